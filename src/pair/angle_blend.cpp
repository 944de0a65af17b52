#include "angle_blend.hpp"

#include "../curve/vec3.hpp"
#include "linearization.hpp"

namespace b2b {
namespace pair {

using curve::dot3;

double sin2_angle(const double* ta, const double* tb) {
  const double a = dot3(ta, ta), b = dot3(tb, tb), c = dot3(ta, tb);
  const double s = 1.0 - (c / a) * (c / b);
  return s < 0.0 ? 0.0 : s;
}

BlendWeight point_weight(const Params& p, double s) {
  BlendWeight w;
  const double s1 = p.sin2_line_angle, s2 = p.sin2_point_angle;
  if (s <= s1) return w;
  if (s >= s2) {
    w.lambda = 1.0;
    return w;
  }
  const double u = (s - s1) / (s2 - s1);
  w.lambda = u * u * (3.0 - 2.0 * u);
  w.slope = 6.0 * u * (1.0 - u) / (s2 - s1);
  return w;
}

void sin2_gradient(const SegmentRef& A, const SegmentRef& B, const Kinematics& k, double* ds) {
  double PA[36], PAd[36], PB[36], PBd[36];
  A.seg->jacobians(k.xi, PA, PAd);
  B.seg->jacobians(k.eta, PB, PBd);
  const double *ta = k.pa.xd, *tb = k.pb.xd, *tad = k.pa.xdd, *tbd = k.pb.xdd, *d = k.d;
  // Gradients of phi = |d|^2 / 2 in (xi, eta): g1 = d.t_A, g2 = -d.t_B, and
  // their derivatives in X (d = x_A - x_B moves with [P_A, -P_B]).
  double g1X[kNdof], g2X[kNdof];
  for (int c = 0; c < 12; ++c) {
    const double* p = PA + 3 * c;
    const double* pd = PAd + 3 * c;
    g1X[c] = dot3(ta, p) + dot3(d, pd);
    g2X[c] = -dot3(tb, p);
    const double* q = PB + 3 * c;
    const double* qd = PBd + 3 * c;
    g1X[12 + c] = -dot3(ta, q);
    g2X[12 + c] = dot3(tb, q) - dot3(d, qd);
  }
  const double h11 = dot3(ta, ta) + dot3(d, tad), h22 = dot3(tb, tb) - dot3(d, tbd);
  const double h12 = -dot3(ta, tb);
  double dxi[kNdof], deta[kNdof];
  for (int c = 0; c < kNdof; ++c) {
    if (k.held_a && k.held_b) {
      dxi[c] = deta[c] = 0.0;
    } else if (k.held_a) {
      dxi[c] = 0.0;
      deta[c] = -g2X[c] / h22;
    } else if (k.held_b) {
      dxi[c] = -g1X[c] / h11;
      deta[c] = 0.0;
    } else {
      const double det = h11 * h22 - h12 * h12;
      dxi[c] = -(h22 * g1X[c] - h12 * g2X[c]) / det;
      deta[c] = -(h11 * g2X[c] - h12 * g1X[c]) / det;
    }
  }
  // s = 1 - c^2 / (a b): ds/dt_A = (2c / (ab)) (c t_A / a - t_B), and
  // the same with A and B exchanged.
  const double a = dot3(ta, ta), b = dot3(tb, tb), ab = dot3(ta, tb);
  const double f = 2.0 * ab / (a * b);
  double sa[3], sb[3];
  for (int i = 0; i < 3; ++i) {
    sa[i] = f * (ab * ta[i] / a - tb[i]);
    sb[i] = f * (ab * tb[i] / b - ta[i]);
  }
  // dt_A/dX = [PAd, 0] + t_A,xi dxi/dX; dt_B/dX = [0, PBd] + t_B,eta deta/dX
  const double sa_tad = dot3(sa, tad), sb_tbd = dot3(sb, tbd);
  for (int c = 0; c < 12; ++c) {
    ds[c] = dot3(sa, PAd + 3 * c);
    ds[12 + c] = dot3(sb, PBd + 3 * c);
  }
  for (int c = 0; c < kNdof; ++c) ds[c] += sa_tad * dxi[c] + sb_tbd * deta[c];
}

}  // namespace pair
}  // namespace b2b
