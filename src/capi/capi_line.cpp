// C entry points of the line-contact element: argument checks, then the
// pair layer (src/pair/line_contact.hpp). Outputs are computed into local
// buffers and copied only on success.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <b2b/b2b.h>

#include "../pair/line_contact.hpp"
#include "firewall.hpp"
#include "history_checks.hpp"
#include "pair_checks.hpp"
#include "params_handle.hpp"
#include "segment_checks.hpp"

using b2b::capi::check_finalized;
using b2b::capi::check_history;
using b2b::capi::check_pair_segments;
using b2b::capi::guarded;
using b2b::capi::kPairBeam;
using b2b::capi::report_segment_failure;
using b2b::capi::Reporter;
namespace pr = b2b::pair;

namespace {

// The line options b2b_pair_eval_line needs, whatever "contact_type" made
// finalize require.
int check_line_options(const Reporter& r, const pr::Params& p) {
  switch (pr::line_contact_missing(p)) {
    case pr::MissingOption::None:
      return B2B_OK;
    case pr::MissingOption::LineTangentialPenalty:
      return r.fail(B2B_ERR_STATE,
                    "\"friction\" is %g but \"line_tangential_penalty\" has not been set (the "
                    "line element needs it)",
                    p.friction);
    default:
      return r.fail(B2B_ERR_STATE, "\"line_penalty\" has not been set (the line element needs it)");
  }
}

}  // namespace

extern "C" {

int b2b_pair_eval_line(const b2b_params* params, const int* segments, const double* X,
                       const double* end_tangents, const double* radii, int n_points,
                       const double* hist_old, double* hist_new, int hist_len,
                       int* contact_status, double* line_info, double* point_info,
                       double* residual, double* tangent, int ldk, char* errmsg,
                       int errmsg_len) {
  const Reporter r("b2b_pair_eval_line", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_finalized(r, params)) return st;
    const pr::Params& p = params->p;
    if (int st = check_line_options(r, p)) return st;
    if (hist_old == nullptr) return r.fail(B2B_ERR_NULL, "hist_old is NULL");
    if (hist_new == nullptr) return r.fail(B2B_ERR_NULL, "hist_new is NULL");
    if (contact_status == nullptr) return r.fail(B2B_ERR_NULL, "contact_status is NULL");
    if (line_info == nullptr) return r.fail(B2B_ERR_NULL, "line_info is NULL");
    if (residual == nullptr) return r.fail(B2B_ERR_NULL, "residual is NULL");
    if (tangent != nullptr && ldk < pr::kNdof)
      return r.fail(B2B_ERR_SIZE, "ldk is %d, the tangent needs at least %d", ldk, pr::kNdof);
    if (n_points < 1 || n_points > B2B_LINE_POINTS_MAX)
      return r.fail(B2B_ERR_RANGE, "n_points is %d, must be in 1 .. %d (B2B_LINE_POINTS_MAX)",
                    n_points, B2B_LINE_POINTS_MAX);
    const int hl = pr::history_length(p);
    const int len = (n_points + 1) * hl;
    if (hist_len != len)
      return r.fail(B2B_ERR_SIZE,
                    "hist_len is %d, but %d integration points need (%d + 1) x %d = %d doubles",
                    hist_len, n_points, n_points, hl, len);
    if (hist_new == hist_old)
      return r.fail(B2B_ERR_RANGE, "hist_new is hist_old: the line element needs two arrays");

    pr::SegmentInput seg[2];
    double unit[2][6];
    if (int st = check_pair_segments(r, segments, X, end_tangents, radii, seg, unit)) return st;
    for (int slot = 0; slot <= n_points; ++slot) {
      char name[48];
      std::snprintf(name, sizeof name, "hist_old (history %d of %d)", slot, n_points + 1);
      if (int st = check_history(r, p, name, hist_old + slot * hl, hl)) return st;
    }

    std::vector<double> hist(len), pinfo(point_info ? pr::kInfoLength * n_points : 0);
    pr::LineResult out;
    double K[pr::kNdof * pr::kNdof];
    const pr::PairFailure f =
        pr::evaluate_line_pair(p, seg[0], seg[1], n_points, hist_old, hist.data(), out,
                               point_info ? pinfo.data() : nullptr, tangent ? K : nullptr);
    if (f.status != B2B_OK) return report_segment_failure(r, kPairBeam[f.beam], f.segment);
    if (out.overflow)
      return r.fail(B2B_ERR_RANGE,
                    "the contact force, energy or tangent overflows (line_penalty %g, smallest "
                    "gap %g): reduce the penalties, the penetration or the slip per step",
                    p.line_penalty, out.info[B2B_LINE_INFO_MIN_GAP]);

    std::memcpy(hist_new, hist.data(), len * sizeof(double));
    *contact_status = out.contact_status;
    std::memcpy(line_info, out.info, sizeof out.info);
    if (point_info) std::memcpy(point_info, pinfo.data(), pinfo.size() * sizeof(double));
    std::memcpy(residual, out.residual, sizeof out.residual);
    if (tangent)
      for (int c = 0; c < pr::kNdof; ++c)
        std::memcpy(tangent + static_cast<size_t>(ldk) * c, K + pr::kNdof * c,
                    pr::kNdof * sizeof(double));
    return B2B_OK;
  });
}

int b2b_pair_line_points(const b2b_params* params, double length, double radius_a,
                         double radius_b, int* n_points, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_pair_line_points", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_finalized(r, params)) return st;
    if (n_points == nullptr) return r.fail(B2B_ERR_NULL, "n_points is NULL");
    const double v[3] = {length, radius_a, radius_b};
    const char* const name[3] = {"length", "radius_a", "radius_b"};
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(v[i])) return r.fail(B2B_ERR_NONFINITE, "%s is not finite", name[i]);
      if (v[i] < 0.0) return r.fail(B2B_ERR_RANGE, "%s is %g, must be >= 0", name[i], v[i]);
    }
    *n_points = pr::line_points(params->p, length, radius_a, radius_b);
    return B2B_OK;
  });
}

}  // extern "C"
