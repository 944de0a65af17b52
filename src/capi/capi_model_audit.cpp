// C entry point of the interpenetration audit (b2b_model_audit). Argument
// checks and messages only; src/model/audit does the work.
#include <cmath>
#include <vector>

#include <b2b/b2b.h>

#include "../model/audit.hpp"
#include "model_handle.hpp"

using b2b::capi::check_results;
using b2b::capi::guarded;
using b2b::capi::Reporter;
namespace md = b2b::model;

extern "C" {

int b2b_model_audit(const b2b_model* model, double tolerance, int* n_found, int* pairs,
                    double* overlap, int* reasons, int capacity, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_audit", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (n_found == nullptr) return r.fail(B2B_ERR_NULL, "n_found is NULL");
    const bool query = pairs == nullptr && overlap == nullptr && reasons == nullptr;
    if (!query && (pairs == nullptr || overlap == nullptr || reasons == nullptr))
      return r.fail(B2B_ERR_NULL, "%s is NULL: give pairs, overlap and reasons together (or "
                    "none of them for the size query)",
                    pairs == nullptr ? "pairs" : overlap == nullptr ? "overlap" : "reasons");
    if (!std::isfinite(tolerance))
      return r.fail(B2B_ERR_NONFINITE, "tolerance is not finite (%g)", tolerance);
    if (tolerance < 0.0)
      return r.fail(B2B_ERR_RANGE, "tolerance is %g (>= 0: a fraction of the smaller radius)",
                    tolerance);
    if (!query && capacity < 0) return r.fail(B2B_ERR_SIZE, "capacity is %d (>= 0)", capacity);
    if (int st = check_results(r, model)) return st;
    const std::vector<md::AuditFinding> found = md::audit(model->m, tolerance);
    const int count = static_cast<int>(found.size());
    if (!query) {
      if (capacity < count)
        return r.fail(B2B_ERR_SIZE, "capacity is %d, the audit has %d findings", capacity, count);
      const md::BeamTable& t = model->m.table();
      for (int k = 0; k < count; ++k) {
        const md::SegmentInfo &a = t.segment(found[k].a), &b = t.segment(found[k].b);
        pairs[4 * k + 0] = a.beam;
        pairs[4 * k + 1] = a.index;
        pairs[4 * k + 2] = b.beam;
        pairs[4 * k + 3] = b.index;
        overlap[k] = found[k].overlap;
        reasons[k] = found[k].reason;
      }
    }
    *n_found = count;
    return B2B_OK;
  });
}

}  // extern "C"
