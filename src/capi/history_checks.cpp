#include "history_checks.hpp"

#include <cmath>

#include <b2b/b2b.h>

#include "../pair/history.hpp"

namespace b2b {
namespace capi {

namespace pr = b2b::pair;

int check_history(const Reporter& r, const pr::Params& p, const char* name, const double* h,
                  int len) {
  const int expected = pr::history_length(p);
  if (len != expected)
    return r.fail(B2B_ERR_SIZE,
                  "hist_len is %d but this parameter set keeps %d doubles per pair "
                  "(b2b_params_history_size); a history from another parameter set?",
                  len, expected);
  for (int i = 0; i < len; ++i)
    if (!std::isfinite(h[i]))
      return r.fail(B2B_ERR_NONFINITE, "%s[%d] is not finite (%g)", name, i, h[i]);
  const double tag = h[pr::kHistTag];
  if (tag != pr::kHistTagFresh && tag != pr::kHistTagV1)
    return r.fail(B2B_ERR_RANGE,
                  "%s was not written by b2b_pair_eval (format tag %g); start from a "
                  "zero-filled history",
                  name, tag);
  if (tag == pr::kHistTagFresh) {
    for (int i = 1; i < len; ++i)
      if (h[i] != 0.0)
        return r.fail(B2B_ERR_RANGE,
                      "%s has format tag 0 (fresh) but entry %d is %g: a fresh history is "
                      "all zeros",
                      name, i, h[i]);
    return B2B_OK;
  }
  if (h[pr::kHistHasNormal] != 0.0 && h[pr::kHistHasNormal] != 1.0)
    return r.fail(B2B_ERR_RANGE, "%s has a has-normal flag of %g (0 or 1 expected)", name,
                  h[pr::kHistHasNormal]);
  if (h[pr::kHistHasNormal] == 1.0) {
    const double* n = h + pr::kHistNormal;
    const double len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (std::fabs(len2 - 1.0) > 1e-8)
      return r.fail(B2B_ERR_RANGE, "%s holds a normal of length %g, not a unit vector", name,
                    std::sqrt(len2));
  }
  if (len == pr::kHistoryLengthFriction) {
    const double in_contact = h[pr::kHistInContact], state = h[pr::kHistFrictionState];
    if (in_contact != 0.0 && in_contact != 1.0)
      return r.fail(B2B_ERR_RANGE, "%s has an in-contact flag of %g (0 or 1 expected)", name,
                    in_contact);
    if (in_contact == 1.0 && h[pr::kHistHasNormal] != 1.0)
      return r.fail(B2B_ERR_RANGE, "%s is in contact but holds no normal", name);
    if (in_contact == 1.0 && state != B2B_FRICTION_STICK && state != B2B_FRICTION_SLIP)
      return r.fail(B2B_ERR_RANGE,
                    "%s has friction state %g (B2B_FRICTION_STICK or _SLIP expected)", name,
                    state);
    if (in_contact == 0.0 && (state != 0.0 || h[pr::kHistForceE1] != 0.0 ||
                              h[pr::kHistForceE2] != 0.0))
      return r.fail(B2B_ERR_RANGE, "%s is not in contact but holds a friction state or force",
                    name);
  }
  return B2B_OK;
}

}  // namespace capi
}  // namespace b2b
