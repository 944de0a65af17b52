// C entry points of the smoothed centreline: argument checks, then the curve
// layer. Outputs are computed into local buffers and copied only on success.
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../common/finite.hpp"
#include "../curve/segment.hpp"
#include "../curve/topology.hpp"
#include "firewall.hpp"
#include "segment_checks.hpp"

using b2b::all_finite;
using b2b::capi::check_kind;
using b2b::capi::check_segment;
using b2b::capi::guarded;
using b2b::capi::report_segment_failure;
using b2b::capi::Reporter;

namespace {

int check_beam(const Reporter& r, int kind, int n_nodes, int closed) {
  if (int st = check_kind(r, kind)) return st;
  if (closed != 0 && closed != 1)
    return r.fail(B2B_ERR_RANGE, "closed must be 0 (open beam) or 1 (ring), not %d", closed);
  if (n_nodes < b2b::curve::min_nodes(closed))
    return r.fail(B2B_ERR_RANGE, "%s beam needs at least %d nodes, got %d",
                  closed ? "a closed" : "an open", b2b::curve::min_nodes(closed), n_nodes);
  return B2B_OK;
}

}  // namespace

extern "C" {

int b2b_segment_eval(int kind, int start_rule, int end_rule, const double* patch,
                     const double* end_tangents, double xi, double* x, double* dx, double* d2x,
                     char* errmsg, int errmsg_len) {
  const Reporter r("b2b_segment_eval", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (patch == nullptr) return r.fail(B2B_ERR_NULL, "patch is NULL");
    double unit[6];
    if (int st = check_segment(r, "", kind, start_rule, end_rule, patch, end_tangents, unit))
      return st;
    if (!std::isfinite(xi)) return r.fail(B2B_ERR_NONFINITE, "xi is not finite (%g)", xi);

    b2b::curve::Segment seg;
    const b2b::curve::Failure f =
        seg.build(kind, start_rule, end_rule, patch, unit, dx != nullptr || d2x != nullptr);
    if (f.status != B2B_OK) return report_segment_failure(r, "", f);

    double lx[9], ldx[72], ld2x[864];
    if (x) seg.point(xi, lx, lx + 3, lx + 6);
    if (dx) seg.jacobians(xi, ldx, ldx + 36);
    if (d2x) {
      if (seg.linear_in_X()) {
        std::memset(ld2x, 0, sizeof ld2x);
      } else {
        double Hx[144], Hxd[144];
        for (int i = 0; i < 3; ++i) {
          const double w[3] = {i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0};
          seg.contracted_hessians(xi, w, Hx, Hxd);
          for (int m = 0; m < 144; ++m) {
            ld2x[i + 3 * m] = Hx[m];
            ld2x[432 + i + 3 * m] = Hxd[m];
          }
        }
      }
    }
    // A finite xi far outside [-1, 1] can overflow the cubic; never let that out.
    if ((x && !all_finite(lx, 9)) || (dx && !all_finite(ldx, 72)) ||
        (d2x && !all_finite(ld2x, 864)))
      return r.fail(B2B_ERR_RANGE, "the curve overflows at xi = %g (far outside [-1, 1])", xi);
    if (x) std::memcpy(x, lx, sizeof lx);
    if (dx) std::memcpy(dx, ldx, sizeof ldx);
    if (d2x) std::memcpy(d2x, ld2x, sizeof ld2x);
    return B2B_OK;
  });
}

int b2b_beam_segment_count(int kind, int n_nodes, int closed, int* n_segments, char* errmsg,
                           int errmsg_len) {
  const Reporter r("b2b_beam_segment_count", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (n_segments == nullptr) return r.fail(B2B_ERR_NULL, "n_segments is NULL");
    if (int st = check_beam(r, kind, n_nodes, closed)) return st;
    *n_segments = b2b::curve::segment_count(kind, n_nodes, closed);
    return B2B_OK;
  });
}

int b2b_beam_segment_patch(int kind, int n_nodes, int closed, int segment, int* nodes,
                           int* start_rule, int* end_rule, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_beam_segment_patch", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (nodes == nullptr) return r.fail(B2B_ERR_NULL, "nodes is NULL");
    if (start_rule == nullptr) return r.fail(B2B_ERR_NULL, "start_rule is NULL");
    if (end_rule == nullptr) return r.fail(B2B_ERR_NULL, "end_rule is NULL");
    if (int st = check_beam(r, kind, n_nodes, closed)) return st;
    const int n_seg = b2b::curve::segment_count(kind, n_nodes, closed);
    if (segment < 0 || segment >= n_seg)
      return r.fail(B2B_ERR_RANGE, "segment %d is out of range: this beam has segments 0 .. %d",
                    segment, n_seg - 1);
    b2b::curve::segment_patch(kind, n_nodes, closed, segment, nodes, start_rule, end_rule);
    return B2B_OK;
  });
}

}  // extern "C"
