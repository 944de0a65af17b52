// C entry point of the contact element: argument checks, then the pair
// layer. Outputs are computed into local buffers and copied only on success.
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../pair/contact_element.hpp"
#include "firewall.hpp"
#include "params_handle.hpp"
#include "segment_checks.hpp"

using b2b::capi::check_segment;
using b2b::capi::guarded;
using b2b::capi::report_segment_failure;
using b2b::capi::Reporter;
namespace pr = b2b::pair;

namespace {

const char* const kBeam[2] = {"beam A: ", "beam B: "};

int check_history(const Reporter& r, const double* h, int len) {
  if (len != pr::kHistoryLength)
    return r.fail(B2B_ERR_SIZE,
                  "hist_len is %d but this parameter set keeps %d doubles per pair "
                  "(b2b_params_history_size); a history from another parameter set?",
                  len, pr::kHistoryLength);
  for (int i = 0; i < len; ++i)
    if (!std::isfinite(h[i]))
      return r.fail(B2B_ERR_NONFINITE, "hist_old[%d] is not finite (%g)", i, h[i]);
  const double tag = h[pr::kHistTag];
  if (tag != pr::kHistTagFresh && tag != pr::kHistTagV1)
    return r.fail(B2B_ERR_RANGE,
                  "hist_old was not written by b2b_pair_eval (format tag %g); start from a "
                  "zero-filled history",
                  tag);
  if (tag == pr::kHistTagFresh)
    for (int i = 1; i < len; ++i)
      if (h[i] != 0.0)
        return r.fail(B2B_ERR_RANGE,
                      "hist_old has format tag 0 (fresh) but entry %d is %g: a fresh history is "
                      "all zeros",
                      i, h[i]);
  if (tag == pr::kHistTagV1 && h[pr::kHistHasNormal] != 0.0 && h[pr::kHistHasNormal] != 1.0)
    return r.fail(B2B_ERR_RANGE, "hist_old has a has-normal flag of %g (0 or 1 expected)",
                  h[pr::kHistHasNormal]);
  if (tag == pr::kHistTagV1 && h[pr::kHistHasNormal] == 1.0) {
    const double* n = h + pr::kHistNormal;
    const double len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (std::fabs(len2 - 1.0) > 1e-8)
      return r.fail(B2B_ERR_RANGE, "hist_old holds a normal of length %g, not a unit vector",
                    std::sqrt(len2));
  }
  return B2B_OK;
}

}  // namespace

extern "C" {

int b2b_pair_eval(const b2b_params* params, const int* segments, const double* X,
                  const double* end_tangents, const double* radii, const double* hist_old,
                  double* hist_new, int hist_len, int* contact_status, double* info,
                  double* residual, double* tangent, int ldk, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_pair_eval", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
    if (!params->p.finalized)
      return r.fail(B2B_ERR_STATE, "params is not finalized (call b2b_params_finalize first)");
    if (segments == nullptr) return r.fail(B2B_ERR_NULL, "segments is NULL");
    if (X == nullptr) return r.fail(B2B_ERR_NULL, "X is NULL");
    if (radii == nullptr) return r.fail(B2B_ERR_NULL, "radii is NULL");
    if (hist_old == nullptr) return r.fail(B2B_ERR_NULL, "hist_old is NULL");
    if (hist_new == nullptr) return r.fail(B2B_ERR_NULL, "hist_new is NULL");
    if (contact_status == nullptr) return r.fail(B2B_ERR_NULL, "contact_status is NULL");
    if (info == nullptr) return r.fail(B2B_ERR_NULL, "info is NULL");
    if (residual == nullptr) return r.fail(B2B_ERR_NULL, "residual is NULL");
    if (tangent != nullptr && ldk < pr::kNdof)
      return r.fail(B2B_ERR_SIZE, "ldk is %d, the tangent needs at least %d", ldk, pr::kNdof);

    pr::SegmentInput seg[2];
    double unit[2][6];
    for (int b = 0; b < 2; ++b) {
      const int* s = segments + 3 * b;
      if (int st = check_segment(r, kBeam[b], s[0], s[1], s[2], X + 12 * b,
                                 end_tangents ? end_tangents + 6 * b : nullptr, unit[b]))
        return st;
      if (!std::isfinite(radii[b]))
        return r.fail(B2B_ERR_NONFINITE, "%sradius is not finite (%g)", kBeam[b], radii[b]);
      if (radii[b] < 0.0 || radii[b] > B2B_COORD_MAX)
        return r.fail(B2B_ERR_RANGE, "%sradius %g must be in [0, B2B_COORD_MAX]", kBeam[b],
                      radii[b]);
      seg[b] = pr::SegmentInput{s[0], s[1], s[2], X + 12 * b, unit[b], radii[b]};
    }
    if (int st = check_history(r, hist_old, hist_len)) return st;

    pr::PairResult out;
    double K[pr::kNdof * pr::kNdof];
    const pr::PairFailure f =
        pr::evaluate_pair(params->p, seg[0], seg[1], hist_old, out, tangent ? K : nullptr);
    if (f.status != B2B_OK) return report_segment_failure(r, kBeam[f.beam], f.segment);
    if (out.overflow)
      return r.fail(B2B_ERR_RANGE,
                    "the contact force, energy or tangent overflows (penalty %g, gap %g): "
                    "reduce the penalty or the penetration",
                    params->p.penalty, out.info[B2B_INFO_GAP]);

    std::memcpy(hist_new, out.history, sizeof out.history);
    *contact_status = out.contact_status;
    std::memcpy(info, out.info, sizeof out.info);
    std::memcpy(residual, out.residual, sizeof out.residual);
    if (tangent)
      for (int c = 0; c < pr::kNdof; ++c)
        std::memcpy(tangent + static_cast<size_t>(ldk) * c, K + pr::kNdof * c,
                    pr::kNdof * sizeof(double));
    return B2B_OK;
  });
}

}  // extern "C"
