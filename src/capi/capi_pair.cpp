// C entry point of the contact element: argument checks, then the pair
// layer. Outputs are computed into local buffers and copied only on success.
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../pair/contact_element.hpp"
#include "firewall.hpp"
#include "history_checks.hpp"
#include "pair_checks.hpp"
#include "params_handle.hpp"
#include "segment_checks.hpp"

using b2b::capi::check_finalized;
using b2b::capi::check_history;
using b2b::capi::check_pair_segments;
using b2b::capi::kPairBeam;
using b2b::capi::guarded;
using b2b::capi::report_segment_failure;
using b2b::capi::Reporter;
namespace pr = b2b::pair;

namespace {

// b2b_pair_eval and b2b_pair_eval_ends: ends null for the free pair.
int eval_pair(const Reporter& r, const b2b_params* params, const int* segments, const double* X,
              const double* end_tangents, const double* radii, const int* ends,
              const double* hist_old, double* hist_new, int hist_len, int* contact_status,
              double* info, double* residual, double* tangent, int ldk) {
  return guarded(r, [&]() -> int {
    if (int st = check_finalized(r, params)) return st;
    if (hist_old == nullptr) return r.fail(B2B_ERR_NULL, "hist_old is NULL");
    if (hist_new == nullptr) return r.fail(B2B_ERR_NULL, "hist_new is NULL");
    if (contact_status == nullptr) return r.fail(B2B_ERR_NULL, "contact_status is NULL");
    if (info == nullptr) return r.fail(B2B_ERR_NULL, "info is NULL");
    if (residual == nullptr) return r.fail(B2B_ERR_NULL, "residual is NULL");
    if (tangent != nullptr && ldk < pr::kNdof)
      return r.fail(B2B_ERR_SIZE, "ldk is %d, the tangent needs at least %d", ldk, pr::kNdof);
    pr::Ends held;
    if (ends) {
      for (int b = 0; b < 2; ++b)
        if (ends[b] < -1 || ends[b] > 1)
          return r.fail(B2B_ERR_RANGE, "%sends[%d] is %d, must be -1, 0 or +1", kPairBeam[b], b,
                        ends[b]);
      held.a = ends[0];
      held.b = ends[1];
    }

    pr::SegmentInput seg[2];
    double unit[2][6];
    if (int st = check_pair_segments(r, segments, X, end_tangents, radii, seg, unit)) return st;
    if (int st = check_history(r, params->p, "hist_old", hist_old, hist_len)) return st;

    pr::PairResult out;
    double K[pr::kNdof * pr::kNdof];
    pr::TangentColumns used;  // K as the element left it: expand_tangent writes it out
    const pr::PairFailure f = pr::evaluate_pair(params->p, seg[0], seg[1], hist_old, out,
                                                tangent ? K : nullptr, held, &used);
    if (f.status != B2B_OK) return report_segment_failure(r, kPairBeam[f.beam], f.segment);
    if (out.overflow && params->p.friction > 0.0)
      return r.fail(B2B_ERR_RANGE,
                    "the contact force, energy or tangent overflows (penalty %g, "
                    "tangential_penalty %g, gap %g): reduce the penalties, the penetration or "
                    "the slip per step",
                    params->p.penalty, params->p.tangential_penalty, out.info[B2B_INFO_GAP]);
    if (out.overflow)
      return r.fail(B2B_ERR_RANGE,
                    "the contact force, energy or tangent overflows (penalty %g, gap %g): "
                    "reduce the penalty or the penetration",
                    params->p.penalty, out.info[B2B_INFO_GAP]);

    std::memcpy(hist_new, out.history, hist_len * sizeof(double));
    *contact_status = out.contact_status;
    std::memcpy(info, out.info, sizeof out.info);
    std::memcpy(residual, out.residual, sizeof out.residual);
    if (tangent) pr::expand_tangent(K, used, tangent, ldk);
    return B2B_OK;
  });
}

}  // namespace

extern "C" {

int b2b_pair_eval(const b2b_params* params, const int* segments, const double* X,
                  const double* end_tangents, const double* radii, const double* hist_old,
                  double* hist_new, int hist_len, int* contact_status, double* info,
                  double* residual, double* tangent, int ldk, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_pair_eval", errmsg, errmsg_len);
  return eval_pair(r, params, segments, X, end_tangents, radii, nullptr, hist_old, hist_new,
                   hist_len, contact_status, info, residual, tangent, ldk);
}

int b2b_pair_eval_ends(const b2b_params* params, const int* segments, const double* X,
                       const double* end_tangents, const double* radii, const int* ends,
                       const double* hist_old, double* hist_new, int hist_len,
                       int* contact_status, double* info, double* residual, double* tangent,
                       int ldk, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_pair_eval_ends", errmsg, errmsg_len);
  if (ends == nullptr) return r.fail(B2B_ERR_NULL, "ends is NULL");
  return eval_pair(r, params, segments, X, end_tangents, radii, ends, hist_old, hist_new,
                   hist_len, contact_status, info, residual, tangent, ldk);
}

}  // extern "C"
