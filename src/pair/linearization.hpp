// First-order sensitivity of an active contact to the 24 contact
// coordinates, on the columns the two segments actually read ("used
// columns", compacted so that the tangent's loops are short and vectorise):
// J = [P_A, -P_B] at the closest points, the gap gradient g = J^T n, the
// derivative B of the orthogonality conditions and the closest points' motion
// [dxi/dX; deta/dX] = -H^-1 B (doc/contact-element.md section 10). Shared by
// the normal tangent and the friction tangent.
#pragma once

#include "../curve/segment.hpp"

namespace b2b {
namespace pair {

constexpr int kNdof = 24;

struct Linearization {
  int m = 0;          // number of used columns
  int m_a = 0;        // of which A's (the first m_a)
  unsigned used_a = 0, used_b = 0;  // the slots they come from (curve::used_slots)
  int cols[kNdof];    // their indices in 0..23
  double Jx[kNdof], Jy[kNdof], Jz[kNdof];  // rows of J
  double Qx[kNdof], Qy[kNdof], Qz[kNdof];  // rows of [P_A,xi, P_B,eta] (no sign, unlike J)
  double g[kNdof];    // dg/dX = n . J (unsigned distance; the caller's sign is in n)
  double B0[kNdof], B1[kNdof];  // B = d(grad phi)/dX
  double C0[kNdof], C1[kNdof];  // H^-1 B: dxi/dX = -C0, deta/dX = -C1
  double av[kNdof], bv[kNdof];  // n . P_A,xi on A's columns, -n . P_B,eta on B's
  double n[3];                  // the unit normal (g = n . J)
  bool axial = false;           // every used column of J along one axis (cols[k] % 3)
};

// The closest points' state needed by linearize(): the 3x12 jacobians P, Pd
// of both segments at xi and eta, the tangents there, d = x_A - x_B, the unit
// normal n, and the Hessian of phi = |d|^2/2, h11 h12 h22, in units of
// `unit` (so its inverse is (unit^-2 / det) adj(H)).
struct ContactGeometry {
  const double *PA, *PAd, *PB, *PBd;
  const double *ta, *tb;  // x_A,xi and x_B,eta
  const double *d, *n;
  double h11, h12, h22, det, inv_unit;
  // An end contact's held parameters (Kinematics::end_a, end_b): they do
  // not move with X (their row of -H^-1 B is zero), and H is the free
  // parameter's own curvature (h12 = 0, the held diagonal 1).
  bool fixed_xi = false, fixed_eta = false;
};

// used_a, used_b: curve::used_slots of A and B.
void linearize(unsigned used_a, unsigned used_b, const ContactGeometry& geo, Linearization& lin);

}  // namespace pair
}  // namespace b2b
