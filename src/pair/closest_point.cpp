#include "closest_point.hpp"

#include <cfloat>
#include <cmath>

#include "../curve/vec3.hpp"

namespace b2b {
namespace pair {
namespace {

using curve::dot3;
using curve::norm3;

constexpr double kBox = 3.0;       // iterates stay in [-3, 3]: the cubics extend, but not forever
constexpr double kMaxStep = 1.0;   // at most half a segment per iteration
constexpr double kArmijo = 1e-4;
constexpr double kRelTol = 1e-13;  // tangential residual relative to the axis distance
// A Newton step this small (in the parameters, which run over [-1, 1]) is
// rounding: 16 ulps of 1.
constexpr double kStepAtRounding = 16.0 * DBL_EPSILON;
// The final Newton step after convergence is a correction; anything larger
// than this (in the parameters) is not, and is not taken.
constexpr double kPolishMax = 1e-6;

// NaN goes to the middle of the range rather than through.
double clamp(double v, double lo, double hi) {
  if (!(v == v)) return 0.5 * (lo + hi);
  return v < lo ? lo : (v > hi ? hi : v);
}

// phi in units of scale^2
double half_distance_squared(const curve::Segment& A, const curve::Segment& B, double xi,
                             double eta, double inv_scale) {
  double xa[3], xb[3], d[3];
  const double* origin = A.base();
  A.point_from(origin, xi, xa, nullptr, nullptr);
  B.point_from(origin, eta, xb, nullptr, nullptr);
  for (int i = 0; i < 3; ++i) d[i] = (xa[i] - xb[i]) * inv_scale;
  return 0.5 * dot3(d, d);
}

void scale3(double* v, double s) {
  v[0] *= s;
  v[1] *= s;
  v[2] *= s;
}

}  // namespace

void chord_start(const double* a0, const double* a1, const double* b0, const double* b1,
                 double scale, double* xi, double* eta) {
  // Chord: x = (p0 + p1)/2 + s (p1 - p0)/2, s in [-1, 1]; in units of scale
  // (the products below are of four lengths).
  const double inv = 1.0 / scale;
  double t1[3], t2[3], c[3];
  for (int i = 0; i < 3; ++i) {
    t1[i] = (a1[i] - a0[i]) * inv;
    t2[i] = (b1[i] - b0[i]) * inv;
    c[i] = ((a0[i] - b0[i]) + (a1[i] - b1[i])) * inv;
  }
  const double t11 = dot3(t1, t1), t22 = dot3(t2, t2), t12 = dot3(t1, t2);
  const double D = t11 * t22 - t12 * t12;
  if (!(D > 1e-10 * t11 * t22)) {  // sin^2 of the angle below 1e-10: no unique answer
    *xi = *eta = 0.0;
    return;
  }
  const double ct1 = dot3(c, t1), ct2 = dot3(c, t2);
  // Clamped to the segments: the cubics' extensions may have closest
  // points of their own, which a start beyond [-1, 1] could find instead of
  // the segments' one.
  *xi = clamp((ct2 * t12 - ct1 * t22) / D, -1.0, 1.0);
  *eta = clamp((t11 * ct2 - t12 * ct1) / D, -1.0, 1.0);
}

ClosestPoints closest_points(const curve::Segment& A, const curve::Segment& B, double xi,
                             double eta, int max_iterations, double tol_length, double scale,
                             unsigned fixed) {
  ClosestPoints r;
  const double inv_scale = 1.0 / scale;
  bool newton_at_rounding = false;
  int pinned = 0;  // consecutive iterations held at the box by a step that points out of it
  // Points relative to A's base node: d keeps the inputs' accuracy far from the
  // coordinates' origin (see Segment::point_from).
  const double* origin = A.base();
  for (int it = 0;; ++it) {
    double xa[3], xad[3], xadd[3], xb[3], xbd[3], xbdd[3], d[3];
    A.point_from(origin, xi, xa, xad, xadd);
    B.point_from(origin, eta, xb, xbd, xbdd);
    // Everything below in units of scale (phi, its gradient and Hessian are
    // then O(1) whatever the size of the segments).
    for (int i = 0; i < 3; ++i) d[i] = (xa[i] - xb[i]) * inv_scale;
    scale3(xad, inv_scale);
    scale3(xadd, inv_scale);
    scale3(xbd, inv_scale);
    scale3(xbdd, inv_scale);
    // Gradient of phi; in length units after dividing by the speeds.
    // A fixed parameter has no gradient component: its condition is not
    // one of the problem's (the point is held at a node).
    const double g1 = (fixed & kFixXi) ? 0.0 : dot3(d, xad);
    const double g2 = (fixed & kFixEta) ? 0.0 : -dot3(d, xbd);
    const double na = norm3(xad), nb = norm3(xbd);
    // The tangential residual, relative to the axis distance rho = |d| as
    // well as to the segments: the normal d / rho tilts by about |g| / rho,
    // so near-intersecting axes need a residual that shrinks with rho (the
    // step test below stops the iteration where rounding takes over).
    const double rho = norm3(d);
    const double tol = std::fmin(tol_length * inv_scale, kRelTol * rho) + 4.0 * DBL_EPSILON * rho;
    const bool polish = std::fabs(g1) <= tol * na && std::fabs(g2) <= tol * nb;
    if (polish) {  // converged; one more Newton step below
      r.converged = true;
      r.iterations = it;
    } else if (it > 0 && newton_at_rounding) {
      // The last step was a plain Newton step (no shift, no line search)
      // of a few ulps of the parameters: the gradient is rounding noise,
      // the iterate as good as the inputs allow.
      r.converged = true;
      r.iterations = it;
      break;
    } else if (it == max_iterations) {
      r.iterations = it;
      break;
    }
    // Hessian of phi, shifted to positive definite where it is not (far from
    // the solution, or a curvature term d.x'' that dominates).
    const double hscale = na * na + nb * nb;
    // A fixed parameter's row and column are decoupled (any positive
    // diagonal): its step is then zero, the other's the 1-D Newton step.
    double h11 = (fixed & kFixXi) ? hscale : dot3(xad, xad) + dot3(d, xadd);
    double h22 = (fixed & kFixEta) ? hscale : dot3(xbd, xbd) - dot3(d, xbdd);
    const double h12 = fixed ? 0.0 : -dot3(xad, xbd);
    const double mean = 0.5 * (h11 + h22);
    const double radius = std::sqrt(0.25 * (h11 - h22) * (h11 - h22) + h12 * h12);
    const double lambda_min = mean - radius;
    // The shift's floor: small enough that the Hessian of two nearly
    // parallel segments, whose smallest eigenvalue is about
    // (1 - cos angle) |a||b|, is not shifted down to 1e-3 rad (1e-6 shifted
    // every step below 0.1 degree, so a host with "parallel_angle" 0 got
    // linear convergence and NOT_CONVERGED).
    const double floor = 1e-13 * hscale;
    const bool shifted = lambda_min < floor;
    if (shifted) {
      h11 += floor - lambda_min;
      h22 += floor - lambda_min;
    }
    const double det = h11 * h22 - h12 * h12;
    double s1 = -(h22 * g1 - h12 * g2) / det;
    double s2 = -(h11 * g2 - h12 * g1) / det;
    if (polish) {
      // The test bounds the tangential residual, not the parameters, whose
      // error grows like 1 / sin^2 of the crossing angle (3e-11 at 1 degree,
      // found against the AD reference): one more plain Newton step, at
      // quadratic convergence, takes it to rounding. Not counted.
      if (!shifted && std::fabs(s1) <= kPolishMax && std::fabs(s2) <= kPolishMax) {
        xi += s1;
        eta += s2;
      }
      break;
    }
    // At the box's edge with phi still decreasing outwards, a parameter is
    // held there and the other takes its own Newton step (a projected
    // Newton step; h11, h22 > 0 after the shift): a step into the wall would
    // make the line search halve it for nothing, up to 40 times.
    const bool wall1 = (xi >= kBox && g1 < 0.0) || (xi <= -kBox && g1 > 0.0);
    const bool wall2 = (eta >= kBox && g2 < 0.0) || (eta <= -kBox && g2 > 0.0);
    if (wall1 || wall2) {
      s1 = wall1 ? 0.0 : -g1 / h11;
      s2 = wall2 ? 0.0 : -g2 / h22;
    }
    const double m = std::fmax(std::fabs(s1), std::fabs(s2));
    if (m > kMaxStep) {
      s1 *= kMaxStep / m;
      s2 *= kMaxStep / m;
    }
    // Far from the solution, backtrack until phi decreases enough; close to
    // it, the full Newton step converges quadratically and phi differences
    // would be lost in rounding.
    double alpha = 1.0;
    if (m > 1e-3) {
      const double phi = 0.5 * dot3(d, d);
      const double slope = g1 * s1 + g2 * s2;  // < 0: a descent direction
      for (int k = 0; k < 40; ++k) {
        const double trial = half_distance_squared(A, B, clamp(xi + alpha * s1, -kBox, kBox),
                                                   clamp(eta + alpha * s2, -kBox, kBox),
                                                   inv_scale);
        if (trial <= phi + kArmijo * alpha * slope) break;
        alpha *= 0.5;
      }
    }
    newton_at_rounding = !shifted && !wall1 && !wall2 && alpha == 1.0 && m <= kStepAtRounding;
    const double xi_free = xi + alpha * s1, eta_free = eta + alpha * s2;
    xi = clamp(xi_free, -kBox, kBox);
    eta = clamp(eta_free, -kBox, kBox);
    // An iterate the box holds back (or holds at its edge) twice in a row,
    // both times with phi still decreasing outwards, is after a closest
    // point beyond the box, well off this pair's segments: the search stops
    // there (the caller reports OUTSIDE) instead of spending every iteration
    // at the wall.
    pinned = (wall1 || wall2 || xi != xi_free || eta != eta_free) ? pinned + 1 : 0;
    if (pinned >= 2) {
      r.iterations = it + 1;
      break;
    }
  }
  r.xi = xi;
  r.eta = eta;
  return r;
}

double chord_projection(const curve::Segment& A, double xi, const double* b0, const double* b1) {
  double p[3], c[3];
  A.point_from(b0, xi, p, nullptr, nullptr);  // x_A(xi) - b0
  curve::sub3(b1, b0, c);
  const double cc = curve::dot3(c, c);
  if (!(cc > 0.0)) return 0.0;
  const double t = 2.0 * curve::dot3(p, c) / cc - 1.0;
  return std::fmin(1.0, std::fmax(-1.0, t));
}

}  // namespace pair
}  // namespace b2b
