// Coulomb friction of an active contact pair (Zavarise and Wriggers 2000,
// Litewka and Wriggers 2002; doc/friction.md sections 2-6; the contract is in
// b2b_pair.h): the slip of the material points that were in contact at the
// committed step, the committed force carried in the frame of beam A's
// tangent, the penalty trial force, the return mapping onto the Coulomb cone,
// and the exact derivative of the friction residual [P_A^T T; -P_B^T T].
#pragma once

#include "../curve/segment.hpp"
#include "linearization.hpp"
#include "params.hpp"

namespace b2b {
namespace pair {

// The current contact, as the friction law needs it.
struct FrictionContact {
  const curve::Segment *sa, *sb;
  double xi, eta;
  const double *ta, *tad;  // x_A,xi and x_A,xixi
  const double* tb;        // x_B,eta
  const double* n;         // unit normal from B to A
  double rho_signed;       // signed axis distance; 0 where the normal is the history's
  double normal_force, normal_slope;  // f_N > 0 and df_N/dg
  // End contact (Kinematics::end_a, end_b): a held parameter's tangent is
  // not normal to n, so the frame is then built from the projection of a
  // tangent onto the tangent plane (frame_tangent); tbd = x_B,etaeta.
  const double* tbd = nullptr;
  int end_a = 0, end_b = 0;
  // Any parameter held (an end contact or a line-contact point): the
  // frame is then projected (see friction.cpp).
  bool held = false;
  // > 0 (B's radius, for a line-contact point): the slip is read at B's
  // surface (doc/line-contact.md section 5): the anchor on B is its
  // committed axis point plus r_B m, m the committed normal made normal to
  // B's current tangent there, so that a point sliding round B's axis slips.
  double surface_b = 0.0;
};

enum FrameSource { kFrameA = 0, kFrameB = 1, kFrameAxis = 2 };

struct FrictionResult {
  bool anchored = false;  // the committed step was in contact (else T = 0: stick from here)
  int state = 0;          // B2B_FRICTION_STICK or _SLIP
  double T[3] = {0, 0, 0};         // force on B by A
  double slip[3] = {0, 0, 0};      // slip increment (zero in stick)
  double dissipation = 0.0;
  double force_e1 = 0.0, force_e2 = 0.0;  // T in the current frame: the new history
  // kept for the tangent
  double e1[3] = {0, 0, 0}, e2[3] = {0, 0, 0}, speed_a = 0.0;
  // the frame's tangent t (friction.cpp): x_A,xi (kFrameA), x_B,eta
  // (kFrameB) or a constant axis (kFrameAxis, node to node along the axes);
  // projected onto the tangent plane for an end contact
  int frame_source = 0;
  bool projected = false;
  double axis[3] = {0, 0, 0};
  double frame_norm = 0.0;  // |(I - n n^T) t| (speed_a where not projected)
  double committed_e1 = 0.0, committed_e2 = 0.0;  // committed force in the frame
  double xi_n = 0.0, eta_n = 0.0;
  double anchor_gap[3] = {0, 0, 0};  // x_A(xi_n) - x_B(eta_n) (- r_B m, surface)
  // the surface anchor (FrictionContact::surface_b): m = p / |p|,
  // p = (I - t t^T) n_n, t the unit tangent of B at eta_n, n_n the
  // committed normal; kept for the tangent
  bool surface = false;
  double surface_m[3] = {0, 0, 0}, surface_t[3] = {0, 0, 0}, surface_nn[3] = {0, 0, 0};
  double surface_speed = 0.0, surface_pn = 0.0, surface_tnn = 0.0;
  double trial[3] = {0, 0, 0}, trial_norm = 0.0;
};

// hist_old: the pair's committed history (friction layout, validated).
FrictionResult friction_force(const Params& p, const FrictionContact& c, const double* hist_old);

// Kc = the tangent on the used columns (m x m, leading dimension kNdof) of
// an anchored contact (fr.anchored), normal and friction parts, except the
// curves' second derivatives in X, which the caller adds with the weights
// T - f_N n (beam A) and its negative (beam B). PAd, PBd: the 3x12
// jacobians of x_A,xi and x_B,eta at the contact (read with the surface
// anchor only; otherwise their rows in lin and the segments serve).
void friction_tangent(const Params& p, const FrictionContact& c, const FrictionResult& fr,
                      const Linearization& lin, const double* PAd, const double* PBd,
                      double* Kc);

}  // namespace pair
}  // namespace b2b
