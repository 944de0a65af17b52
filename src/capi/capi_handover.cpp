// C entry point of the history handover across a joint: argument checks,
// then the pair layer. The output is written only on success.
#include <cstring>

#include <b2b/b2b.h>

#include "../pair/handover.hpp"
#include "../pair/history.hpp"
#include "firewall.hpp"
#include "history_checks.hpp"
#include "params_handle.hpp"
#include "segment_checks.hpp"

using b2b::capi::check_finalized;
using b2b::capi::check_history;
using b2b::capi::check_segment;
using b2b::capi::guarded;
using b2b::capi::report_segment_failure;
using b2b::capi::Reporter;
namespace pr = b2b::pair;

extern "C" {

int b2b_pair_history_handover(const b2b_params* params, int beam, int direction,
                              const int* from_segment, const double* from_X,
                              const double* from_end_tangents, const int* to_segment,
                              const double* to_X, const double* to_end_tangents,
                              const double* hist_from, double* hist_to, int hist_len,
                              char* errmsg, int errmsg_len) {
  const Reporter r("b2b_pair_history_handover", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_finalized(r, params)) return st;
    if (beam != 0 && beam != 1)
      return r.fail(B2B_ERR_UNKNOWN_KIND, "beam is %d: 0 (beam A) or 1 (beam B) expected", beam);
    if (direction != 1 && direction != -1)
      return r.fail(B2B_ERR_UNKNOWN_KIND,
                    "direction is %d: +1 (to the next segment) or -1 (to the previous one) "
                    "expected",
                    direction);
    if (from_segment == nullptr) return r.fail(B2B_ERR_NULL, "from_segment is NULL");
    if (from_X == nullptr) return r.fail(B2B_ERR_NULL, "from_X is NULL");
    if (to_segment == nullptr) return r.fail(B2B_ERR_NULL, "to_segment is NULL");
    if (to_X == nullptr) return r.fail(B2B_ERR_NULL, "to_X is NULL");
    if (hist_from == nullptr) return r.fail(B2B_ERR_NULL, "hist_from is NULL");
    if (hist_to == nullptr) return r.fail(B2B_ERR_NULL, "hist_to is NULL");

    const char* const names[2] = {"from segment: ", "to segment: "};
    const int* segs[2] = {from_segment, to_segment};
    const double* Xs[2] = {from_X, to_X};
    const double* tans[2] = {from_end_tangents, to_end_tangents};
    double unit[2][6];
    pr::SegmentInput in[2];
    for (int k = 0; k < 2; ++k) {
      const int* s = segs[k];
      if (int st = check_segment(r, names[k], s[0], s[1], s[2], Xs[k], tans[k], unit[k]))
        return st;
      in[k] = pr::SegmentInput{s[0], s[1], s[2], Xs[k], unit[k], 0.0};
    }
    if (int st = check_history(r, params->p, "hist_from", hist_from, hist_len)) return st;

    double h[pr::kHistoryLengthMax];
    std::memcpy(h, hist_from, hist_len * sizeof(double));
    const pr::HandoverOutcome out = pr::handover(in[0], in[1], beam, direction, h, hist_len);
    if (out.failure.status != B2B_OK)
      return report_segment_failure(r, names[out.failure.beam], out.failure.segment);
    const pr::HandoverResult& res = out.result;
    if (!res.adjacent)
      return r.fail(B2B_ERR_RANGE,
                    "the segments do not share the joint: %s of the from segment and %s of the "
                    "to segment are %g chord lengths apart (direction %+d)",
                    direction > 0 ? "the end" : "the start", direction > 0 ? "the start" : "the end",
                    res.mismatch, direction);
    if (!res.in_range)
      return r.fail(B2B_ERR_RANGE,
                    "the mapped closest-point parameter %g is beyond %g: the segments' speeds "
                    "at the joint differ too much, or the history's parameter was too far off",
                    res.mapped, pr::kHistParamMax);
    std::memcpy(hist_to, h, hist_len * sizeof(double));
    return B2B_OK;
  });
}

}  // extern "C"
