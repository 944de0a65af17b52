#include "history_checks.hpp"

#include <b2b/b2b.h>

#include "../pair/history.hpp"
#include "../pair/history_check.hpp"

namespace b2b {
namespace capi {

namespace pr = b2b::pair;

int check_history(const Reporter& r, const pr::Params& p, const char* name, const double* h,
                  int len) {
  const pr::HistoryCheck c = pr::check_history(p, h, len);
  switch (c.problem) {
    case pr::HistoryProblem::None:
      return B2B_OK;
    case pr::HistoryProblem::Length:
      return r.fail(B2B_ERR_SIZE,
                    "hist_len is %d but this parameter set keeps %d doubles per pair "
                    "(b2b_params_history_size); a history from another parameter set?",
                    len, c.expected);
    case pr::HistoryProblem::NonFinite:
      return r.fail(B2B_ERR_NONFINITE, "%s[%d] is not finite (%g)", name, c.index, c.value);
    case pr::HistoryProblem::Tag:
      return r.fail(B2B_ERR_RANGE,
                    "%s was not written by b2b_pair_eval (format tag %g); start from a "
                    "zero-filled history",
                    name, c.value);
    case pr::HistoryProblem::FreshNotZero:
      return r.fail(B2B_ERR_RANGE,
                    "%s has format tag 0 (fresh) but entry %d is %g: a fresh history is "
                    "all zeros",
                    name, c.index, c.value);
    case pr::HistoryProblem::NormalFlag:
      return r.fail(B2B_ERR_RANGE, "%s has a has-normal flag of %g (0 or 1 expected)", name,
                    c.value);
    case pr::HistoryProblem::NormalLength:
      return r.fail(B2B_ERR_RANGE, "%s holds a normal of length %g, not a unit vector", name,
                    c.value);
    case pr::HistoryProblem::InContactFlag:
      return r.fail(B2B_ERR_RANGE, "%s has an in-contact flag of %g (0 or 1 expected)", name,
                    c.value);
    case pr::HistoryProblem::InContactNoNormal:
      return r.fail(B2B_ERR_RANGE, "%s is in contact but holds no normal", name);
    case pr::HistoryProblem::FrictionState:
      return r.fail(B2B_ERR_RANGE,
                    "%s has friction state %g (B2B_FRICTION_STICK or _SLIP expected)", name,
                    c.value);
    case pr::HistoryProblem::Parameter:
      return r.fail(B2B_ERR_RANGE,
                    "%s holds the closest-point parameter %s = %g, beyond %g: not a history "
                    "b2b wrote",
                    name, c.index == pr::kHistXi ? "xi" : "eta", c.value, pr::kHistParamMax);
    case pr::HistoryProblem::ForceWithoutContact:
      return r.fail(B2B_ERR_RANGE, "%s is not in contact but holds a friction state or force",
                    name);
  }
  return r.fail(B2B_ERR_INTERNAL, "%s: unclassified history problem", name);
}

}  // namespace capi
}  // namespace b2b
