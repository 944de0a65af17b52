// The all-angle blend of point and line contact (B2B_CONTACT_TYPE_ALL_ANGLE,
// doc/line-contact.md section 5): the point element's weight lambda(s), a
// C1 step in s = sin^2 of the crossing angle between "line_angle" and
// "point_angle", and the gradient of s in the 24 contact coordinates at a
// pair's contact points, with the points' own motion (what makes the
// blended tangent exact).
#pragma once

#include "contact_kinematics.hpp"
#include "params.hpp"

namespace b2b {
namespace pair {

struct BlendWeight {
  double lambda = 0.0;  // weight of the point element; a line point's is 1 - lambda
  double slope = 0.0;   // dlambda/ds (0 outside the blending range)
};

// s = sin^2 of the angle between the tangents t_A, t_B.
double sin2_angle(const double* ta, const double* tb);

BlendWeight point_weight(const Params& p, double s);

// ds/dX (24 entries) at the contact points of k (an active pair's
// kinematics): the tangents move with the patch and with the closest
// points, d(xi, eta)/dX from the orthogonality conditions (a held
// parameter does not move).
void sin2_gradient(const SegmentRef& A, const SegmentRef& B, const Kinematics& k, double* ds);

}  // namespace pair
}  // namespace b2b
