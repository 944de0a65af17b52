// C entry points of the smoothed centreline: argument checks, then the curve
// layer. Outputs are computed into local buffers and copied only on success.
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../curve/segment.hpp"
#include "../curve/topology.hpp"
#include "firewall.hpp"

using b2b::capi::guarded;
using b2b::capi::Reporter;

namespace {

bool known_kind(int kind) {
  return kind >= B2B_CURVE_LINEAR && kind <= B2B_CURVE_HERMITE_NODAL_WEIGHTED;
}

bool known_rule(int rule) { return rule >= B2B_END_NEIGHBOUR && rule <= B2B_END_TANGENT; }

int check_kind(const Reporter& r, int kind) {
  if (!known_kind(kind))
    return r.fail(B2B_ERR_UNKNOWN_KIND,
                  "unknown curve kind %d (B2B_CURVE_LINEAR .. B2B_CURVE_HERMITE_NODAL_WEIGHTED "
                  "are 0 .. 3)",
                  kind);
  return B2B_OK;
}

const char kAxis[] = "xyz";

// Unit direction of a host end tangent; scaled first so that any finite
// vector, however large or small, normalises without overflow.
int unit_tangent(const Reporter& r, const double* t, const char* where, double* unit) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(t[i]))
      return r.fail(B2B_ERR_NONFINITE, "the end tangent at the %s node has a non-finite %c (%g)",
                    where, kAxis[i], t[i]);
  const double m = std::fmax(std::fabs(t[0]), std::fmax(std::fabs(t[1]), std::fabs(t[2])));
  if (m == 0.0)
    return r.fail(B2B_ERR_RANGE, "the end tangent at the %s node is the zero vector", where);
  double s[3] = {t[0] / m, t[1] / m, t[2] / m};
  const double n = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (int i = 0; i < 3; ++i) unit[i] = s[i] / n;
  return B2B_OK;
}

bool all_finite(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

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
    if (int st = check_kind(r, kind)) return st;
    if (!known_rule(start_rule))
      return r.fail(B2B_ERR_UNKNOWN_KIND, "unknown start_rule %d (B2B_END_* are 0 .. 2)",
                    start_rule);
    if (!known_rule(end_rule))
      return r.fail(B2B_ERR_UNKNOWN_KIND, "unknown end_rule %d (B2B_END_* are 0 .. 2)", end_rule);
    if (kind == B2B_CURVE_HERMITE_MIDPOINT && start_rule != B2B_END_NEIGHBOUR &&
        end_rule != B2B_END_NEIGHBOUR)
      return r.fail(B2B_ERR_RANGE,
                    "a midpoint segment cannot both start and end its beam (such a beam would "
                    "have one node); start_rule and end_rule are both beam ends");
    if (!std::isfinite(xi)) return r.fail(B2B_ERR_NONFINITE, "xi is not finite (%g)", xi);

    const unsigned used = b2b::curve::used_slots(kind, start_rule, end_rule);
    for (int slot = 0; slot < 4; ++slot) {
      if (!(used & (1u << slot))) continue;
      for (int i = 0; i < 3; ++i) {
        const double v = patch[3 * slot + i];
        if (!std::isfinite(v))
          return r.fail(B2B_ERR_NONFINITE, "patch node x%d has a non-finite %c coordinate (%g)",
                        slot + 1, kAxis[i], v);
        if (std::fabs(v) > B2B_COORD_MAX)
          return r.fail(B2B_ERR_RANGE,
                        "patch node x%d has %c = %g, beyond B2B_COORD_MAX (%g)", slot + 1,
                        kAxis[i], v, B2B_COORD_MAX);
      }
    }

    double unit[6] = {0, 0, 0, 0, 0, 0};
    const bool t0 = b2b::curve::uses_start_tangent(kind, start_rule);
    const bool t1 = b2b::curve::uses_end_tangent(kind, end_rule);
    if ((t0 || t1) && end_tangents == nullptr)
      return r.fail(B2B_ERR_NULL, "end_tangents is NULL but the %s rule is B2B_END_TANGENT",
                    t0 ? "start" : "end");
    if (t0)
      if (int st = unit_tangent(r, end_tangents, "first", unit)) return st;
    if (t1)
      if (int st = unit_tangent(r, end_tangents + 3, "last", unit + 3)) return st;

    b2b::curve::Segment seg;
    const b2b::curve::Failure f =
        seg.build(kind, start_rule, end_rule, patch, unit, dx != nullptr || d2x != nullptr);
    if (f.status == B2B_ERR_COINCIDENT)
      return r.fail(f.status, "patch nodes x%d and x%d coincide (zero-length element)",
                    f.slot_a + 1, f.slot_b + 1);
    if (f.status == B2B_ERR_FOLDED)
      return r.fail(f.status,
                    "the patch folds back on itself: nodes x%d and x%d (nearly) coincide, so "
                    "the tangent at x%d has no direction",
                    f.slot_a + 1, f.slot_b + 1, f.slot_a + 2);
    if (f.status != B2B_OK) return r.fail(B2B_ERR_INTERNAL, "segment build failed (%d)", f.status);

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
