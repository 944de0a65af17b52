// Closest points of two smoothed segments: minimise phi = |x_A(xi) - x_B(eta)|^2 / 2
// by Newton's method on its gradient (the two orthogonality conditions),
// safeguarded so that it converges from any start in the patch: the Hessian
// is shifted to positive definite where it is not, steps are limited to one
// segment half-length, and far from the solution a backtracking line search
// enforces descent of phi.
#pragma once

#include "../curve/segment.hpp"

namespace b2b {
namespace pair {

struct ClosestPoints {
  double xi = 0.0, eta = 0.0;
  int iterations = 0;
  bool converged = false;
};

// Parameters of the closest points of the straight chords between the end
// points a0-a1 and b0-b1 of both segments (Wriggers and Zavarise 1997),
// clamped to [-1, 1]; (0, 0) when the chords are (nearly) parallel. scale: a
// length of the segments' size (the computation is done in units of it).
void chord_start(const double* a0, const double* a1, const double* b0, const double* b1,
                 double scale, double* xi, double* eta);

// The parameter of B's chord b0-b1 nearest to x_A(xi), clamped to [-1, 1]
// (0 for a chord of no length): where a one-sided search for the
// projection of A's point xi onto B starts (a line-contact point), since
// the chords' own closest points are undefined for parallel chords.
double chord_projection(const curve::Segment& A, double xi, const double* b0, const double* b1);

// Which parameters closest_points holds at their start value (an end contact:
// a node of A or of B, doc/contact-element.md section 14).
enum FixedParameter : unsigned { kFixNone = 0, kFixXi = 1, kFixEta = 2 };

// Newton from (xi, eta); the parameters in `fixed` keep their start values
// (the search is then one-dimensional, or none). tol_length: the converged gradient, in length
// units (the components of x_A - x_B along both tangents), must be below it.
// scale: a length of the segments' size; all products are formed in units of
// it, so that nothing overflows or underflows for any supported coordinates.
ClosestPoints closest_points(const curve::Segment& A, const curve::Segment& B, double xi,
                             double eta, int max_iterations, double tol_length, double scale,
                             unsigned fixed = kFixNone);

}  // namespace pair
}  // namespace b2b
