#include "contact_kinematics.hpp"

#include <cfloat>
#include <cmath>

#include <b2b/b2b.h>

#include "../curve/vec3.hpp"
#include "closest_point.hpp"
#include "history.hpp"

namespace b2b {
namespace pair {
namespace {

using curve::cross3;
using curve::dot3;
using curve::max_abs3;
using curve::norm3;
using curve::sub3;

constexpr double kJointBand = 1e-13;  // "on a joint": within this many segment lengths
constexpr double kPi = 3.14159265358979323846;

// Whether a segment owns the closest point at parameter t (see b2b_pair.h):
// [-1, 1), the end joint going to the next segment unless the beam ends there.
bool owns(double t, double speed, double length, bool beam_ends_here) {
  const double band = kJointBand * length;
  if (std::fabs(t + 1.0) * speed <= band) return true;
  if (std::fabs(t - 1.0) * speed <= band) return beam_ends_here;
  return t > -1.0 && t < 1.0;
}

// A centreline (almost) stops: its speed |dx/dxi| below 1% of a straight
// segment's (half its chord length), a cusp (b2b_pair.h, PARALLEL).
bool at_cusp(double speed, double chord_length) { return !(speed > 0.005 * chord_length); }

}  // namespace

int contact_kinematics(const Params& params, const SegmentRef& A, const SegmentRef& B,
                       const double* hist_old, Kinematics& k, double* info, double* history,
                       Ends ends) {
  const curve::Segment &sa = *A.seg, &sb = *B.seg;
  // Length scales: segment chords, and the coordinates' magnitude (rounding).
  const double *a0 = sa.start_point(), *a1 = sa.end_point();
  const double *b0 = sb.start_point(), *b1 = sb.end_point();
  double t[3];
  sub3(a1, a0, t);
  const double len_a = norm3(t);
  sub3(b1, b0, t);
  const double len_b = norm3(t);
  // The algebra works relative to A's base node (Segment::point_from), so
  // rounding scales with the patch's extent, not with the coordinates.
  const double* origin = sa.base();
  double extent = 0.0, rel[3];
  for (const double* p : {a0, a1, b0, b1}) {
    sub3(p, origin, rel);
    extent = std::fmax(extent, max_abs3(rel));
  }
  const double tol_length = 1e-13 * (len_a + len_b) + 64.0 * DBL_EPSILON * extent;
  // The length unit of the closest-point algebra below: products of four
  // lengths (the Hessian's determinant) stay in range for any coordinates.
  const double unit = len_a + len_b;
  const double inv_unit = 1.0 / unit;
  k.inv_unit = inv_unit;

  // Closest points.
  const bool has_history = hist_old[kHistTag] == kHistTagV1;
  const bool has_normal = has_history && hist_old[kHistHasNormal] == 1.0;
  double xi0, eta0;
  if (params.warm_start && has_history) {
    xi0 = std::fmin(1.0, std::fmax(-1.0, hist_old[kHistXi]));
    eta0 = std::fmin(1.0, std::fmax(-1.0, hist_old[kHistEta]));
  } else {
    chord_start(a0, a1, b0, b1, unit, &xi0, &eta0);
    // A line-contact point (Ends::at_point): B's chord parameter of its
    // projection, where the chords' own closest points (undefined for
    // parallel chords) say nothing about it.
    if (ends.at_point) eta0 = chord_projection(sa, ends.xi_a, b0, b1);
  }
  k.end_a = ends.a;
  k.end_b = ends.b;
  k.held_a = ends.held_a();
  k.held_b = ends.held_b();
  info[B2B_INFO_END_A] = ends.a;
  info[B2B_INFO_END_B] = ends.b;
  if (ends.held_a()) xi0 = ends.xi_held();
  if (ends.held_b()) eta0 = ends.b;
  const unsigned fixed = (ends.held_a() ? kFixXi : kFixNone) | (ends.held_b() ? kFixEta : kFixNone);
  const ClosestPoints cp =
      closest_points(sa, sb, xi0, eta0, params.max_iterations, tol_length, unit, fixed);
  k.xi = cp.xi;
  k.eta = cp.eta;
  info[B2B_INFO_XI] = cp.xi;
  info[B2B_INFO_ETA] = cp.eta;
  info[B2B_INFO_ITERATIONS] = cp.iterations;
  if (!cp.converged) {
    // First the (nearly) singular problems, which is why a search does not
    // converge: axes within "parallel_angle" of each other where it stopped,
    // or a centreline that (almost) stops there, a cusp, near which Newton
    // converges only linearly (speed below 1% of the chord's, i.e. of a
    // straight segment's). Both are PARALLEL, as b2b_pair.h says, not a
    // failed search; checked before OUTSIDE, since such a search may also
    // wander off along the axes. Otherwise an iteration that ran off the
    // segment looked for a point that is not this pair's, and else the
    // search failed.
    double da[3], db[3], c[3];
    sa.point(cp.xi, nullptr, da, nullptr);
    sb.point(cp.eta, nullptr, db, nullptr);
    cross3(da, db, c);
    const double sa_speed = norm3(da), sb_speed = norm3(db), speeds = sa_speed * sb_speed;
    const bool cusp = at_cusp(sa_speed, len_a) || at_cusp(sb_speed, len_b);
    if (cusp || (!ends.any() && !(norm3(c) > params.sin_parallel_angle * speeds))) {
      info[B2B_INFO_ANGLE] =
          speeds > 0.0 ? std::asin(std::fmin(1.0, norm3(c) / speeds)) * 180.0 / kPi : 0.0;
      return B2B_CONTACT_PARALLEL;
    }
    const bool ran_off = std::fabs(cp.xi) > 1.0 || std::fabs(cp.eta) > 1.0;
    return ran_off ? B2B_CONTACT_OUTSIDE : B2B_CONTACT_NOT_CONVERGED;
  }
  // Positions (reported) from the coordinates; d and the derivatives from
  // the offsets to A's base node (Segment::point_from), accurate far from the
  // coordinates' origin.
  PointState &pa = k.pa, &pb = k.pb;
  double ra[3], rb[3];
  sa.point_from(origin, k.xi, ra, pa.xd, pa.xdd);
  sb.point_from(origin, k.eta, rb, pb.xd, pb.xdd);
  sa.point(k.xi, pa.x, nullptr, nullptr);
  sb.point(k.eta, pb.x, nullptr, nullptr);
  for (int i = 0; i < 3; ++i) {
    info[B2B_INFO_POINT_A + i] = pa.x[i];
    info[B2B_INFO_POINT_B + i] = pb.x[i];
  }

  // Crossing angle, and the Hessian of phi at the solution, in units of
  // `unit` (h11, h12, h22 scale like length^2, det like length^4).
  double ta[3], tb[3], tad[3], tbd[3], du[3];
  for (int i = 0; i < 3; ++i) {
    ta[i] = pa.xd[i] * inv_unit;
    tb[i] = pb.xd[i] * inv_unit;
    tad[i] = pa.xdd[i] * inv_unit;
    tbd[i] = pb.xdd[i] * inv_unit;
    k.d[i] = ra[i] - rb[i];
    du[i] = k.d[i] * inv_unit;
  }
  const double na = norm3(ta), nb = norm3(tb);
  if (at_cusp(na * unit, len_a) || at_cusp(nb * unit, len_b)) {
    // A cusp: the centreline stops and turns back at (or next to: speed
    // below 1% of its chord's) the closest point, so there is neither a
    // crossing angle nor a unique normal (b2b_pair.h); the point itself is
    // found only to sqrt(eps) there, and the tangent would be meaningless.
    info[B2B_INFO_ANGLE] = 0.0;
    return B2B_CONTACT_PARALLEL;
  }
  double cr[3];
  cross3(ta, tb, cr);
  const double sin_angle = norm3(cr) / (na * nb);
  const double cos_angle = std::fabs(dot3(ta, tb)) / (na * nb);
  info[B2B_INFO_ANGLE] = std::atan2(sin_angle, cos_angle) * 180.0 / kPi;
  k.h11 = dot3(ta, ta) + dot3(du, tad);
  k.h22 = dot3(tb, tb) - dot3(du, tbd);
  k.h12 = -dot3(ta, tb);
  k.det = k.h11 * k.h22 - k.h12 * k.h12;
  if (ends.any()) {
    // An end contact: the held parameters drop out of the problem, and a
    // node's distance to a segment is defined at any angle. What is left
    // must be a minimum: the free parameter's own curvature h > 0 (none
    // for two nodes).
    if (ends.held_a() && ends.held_b()) {
      k.h11 = k.h22 = 1.0;
      k.h12 = 0.0;
    } else if (ends.held_a()) {
      if (!(k.h22 > 1e-12 * nb * nb)) return B2B_CONTACT_PARALLEL;
      k.h11 = 1.0;  // decoupled (linearization.cpp reads only h22)
      k.h12 = 0.0;
    } else {
      if (!(k.h11 > 1e-12 * na * na)) return B2B_CONTACT_PARALLEL;
      k.h22 = 1.0;
      k.h12 = 0.0;
    }
    k.det = k.h11 * k.h22;
  } else if (sin_angle < params.sin_parallel_angle || !(k.det > 1e-12 * na * na * nb * nb)) {
    return B2B_CONTACT_PARALLEL;
  }

  // Sign-tracked normal and gap.
  const double rho = norm3(k.d);
  k.rho_signed = 0.0;  // 0: the normal does not rotate (intersecting axes)
  if (rho <= tol_length) {
    // The axes intersect: the normal is undefined, use the previous one.
    if (!has_normal) return B2B_CONTACT_NO_NORMAL;
    for (int i = 0; i < 3; ++i) k.n[i] = hist_old[kHistNormal + i];
    k.gap = -A.radius - B.radius;
  } else {
    const double sign = (has_normal && dot3(k.d, hist_old + kHistNormal) < 0.0) ? -1.0 : 1.0;
    k.rho_signed = sign * rho;
    // At the closest points d is orthogonal to both tangents, so d / rho is
    // the unit a x b (oriented along d). The two differ in rounding only:
    // d / rho by about eps (patch) / rho, a x b / |a x b| by eps / sin angle.
    // Near intersecting axes the cross product is the accurate one, and the
    // tangent needs it: its (f / rho) (J^T (I - n n^T) J - B^T H^-1 B) is a
    // difference of two O(1) terms that cancel to O(rho), so an error in n
    // came back multiplied by L / rho twice (relative error 150 at 1e-10 L,
    // found by the extremes suite against a long-double reference).
    // (Not for an end contact: d is then normal to the free tangent only.)
    if (!ends.any() && rho < unit * sin_angle) {
      const double c = norm3(cr) * (dot3(k.d, cr) < 0.0 ? -1.0 : 1.0);
      for (int i = 0; i < 3; ++i) k.n[i] = sign * cr[i] / c;
    } else {
      for (int i = 0; i < 3; ++i) k.n[i] = k.d[i] / k.rho_signed;
    }
    k.gap = k.rho_signed - A.radius - B.radius;
  }
  for (int i = 0; i < 3; ++i) info[B2B_INFO_NORMAL + i] = k.n[i];
  info[B2B_INFO_GAP] = k.gap;
  history[kHistTag] = kHistTagV1;
  history[kHistHasNormal] = 1.0;
  for (int i = 0; i < 3; ++i) history[kHistNormal + i] = k.n[i];
  history[kHistXi] = k.xi;
  history[kHistEta] = k.eta;

  if ((!ends.held_a() && !owns(k.xi, na * unit, len_a, A.end_rule != B2B_END_NEIGHBOUR)) ||
      (!ends.held_b() && !owns(k.eta, nb * unit, len_b, B.end_rule != B2B_END_NEIGHBOUR)))
    return B2B_CONTACT_OUTSIDE;
  return B2B_CONTACT_OPEN;
}

}  // namespace pair
}  // namespace b2b
