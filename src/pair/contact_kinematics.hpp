// Kinematics of a contact pair (the first stage of the contact element):
// closest points of the two smoothed axes, crossing angle and the parallel
// threshold, the sign-tracked normal and gap, and which pair owns the point
// (doc/contact-element.md). No force, no derivative in X.
#pragma once

#include "../curve/segment.hpp"
#include "params.hpp"

namespace b2b {
namespace pair {

// A segment already built (with derivatives) and what the element needs to
// know about it besides its geometry.
struct SegmentRef {
  const curve::Segment* seg;
  int kind, start_rule, end_rule;
  double radius;
  // The patch (12 coordinates) and unit host end tangents it was built from:
  // read only by the finite-difference tangent (B2B_TANGENT_FD).
  const double* X = nullptr;
  const double* unit_tangents = nullptr;
};

struct PointState {
  double x[3], xd[3], xdd[3];  // x, dx/dxi, d2x/dxi2 at the closest point
};

struct Kinematics {
  double xi = 0.0, eta = 0.0;
  PointState pa, pb;
  double d[3];            // x_A - x_B
  double n[3];            // unit normal from B to A (sign-tracked)
  double rho_signed = 0;  // signed axis distance; 0 where the normal is the history's
  double gap = 0.0;
  // Hessian of phi = |d|^2/2 in units of `unit` = chord_A + chord_B
  double h11 = 0, h12 = 0, h22 = 0, det = 0, inv_unit = 0;
  // End contact (doc/contact-element.md section 14): the parameter of A
  // (B) held at this end of its segment, -1 or +1; 0: free.
  int end_a = 0, end_b = 0;
  // Held parameters: an end contact's, or A's at a line-contact
  // integration point (Ends::at_point); they do not move with X.
  bool held_a = false, held_b = false;
};

// Which parameters of a pair are held at an end of their segment: a node of
// A (end_a = -1 or +1, its xi) or of B (end_b, its eta) in contact with the
// other beam; 0: free, the point-wise element of Wriggers and Zavarise.
// A line-contact integration point (line_contact.hpp) holds A's parameter
// at an interior value xi_a instead (at_point; a and b stay 0): the same
// one-sided problem, the point of A projected onto B.
struct Ends {
  int a = 0, b = 0;
  bool at_point = false;
  double xi_a = 0.0;
  bool held_a() const { return a != 0 || at_point; }
  bool held_b() const { return b != 0; }
  bool any() const { return held_a() || held_b(); }
  double xi_held() const { return at_point ? xi_a : a; }
};

// Fills k and the geometric entries of info (B2B_INFO_XI .. _GAP, ANGLE,
// ITERATIONS) and of history (tag, normal, xi, eta: the state a later
// evaluation tracks). Returns B2B_CONTACT_OPEN when the pair owns a closest
// point with a normal (the force is decided by the caller), else the status
// of a pair that carries no force (OUTSIDE, PARALLEL, NOT_CONVERGED,
// NO_NORMAL). hist_old: a valid history. ends: the parameters held at an end
// (an end contact: its free parameter is searched alone; a held one needs no
// ownership test and no crossing angle, since the caller has decided that
// the node is the closest point of its beam).
int contact_kinematics(const Params& params, const SegmentRef& A, const SegmentRef& B,
                       const double* hist_old, Kinematics& k, double* info, double* history,
                       Ends ends = Ends());

}  // namespace pair
}  // namespace b2b
