#include "friction.hpp"

#include <cmath>

#include <b2b/b2b.h>

#include "../curve/vec3.hpp"
#include "history.hpp"

namespace b2b {
namespace pair {
using curve::cross3;
using curve::dot3;
using curve::norm3;

namespace {
// An end contact's frame follows A's tangent unless that lies within this
// sin^2 of n (about 6 degrees; b2b_pair.h, Transport).
constexpr double kFrameMinSin2 = 1e-2;

// The tangent the frame is built from (FrictionResult::frame_source).
const double* frame_tangent(const FrictionResult& fr, const FrictionContact& c) {
  return fr.frame_source == kFrameA ? c.ta : (fr.frame_source == kFrameB ? c.tb : fr.axis);
}
}  // namespace

FrictionResult friction_force(const Params& p, const FrictionContact& c, const double* hist_old) {
  FrictionResult fr;
  fr.state = B2B_FRICTION_STICK;
  fr.speed_a = norm3(c.ta);
  fr.frame_norm = fr.speed_a;
  for (int i = 0; i < 3; ++i) fr.e1[i] = c.ta[i] / fr.speed_a;
  if (c.held) {
    // An end contact: the held beam's tangent is not normal to n (the node's
    // distance is minimised along the other beam only), and x_A,xi/|x_A,xi|
    // with n x e1 was then no orthonormal frame of the tangent plane: the
    // committed force came back changed where nothing had moved, with a
    // normal part (found by check_pair_ends, committed_friction_force_is_kept).
    // e1 is A's tangent projected onto the tangent plane, as in the free
    // element (where the projection only removes rounding), so that a
    // committed force handed from a free pair to an end contact keeps its
    // direction (B's tangent turned it by the crossing angle). Where A's
    // tangent lies within about 6 degrees of n (a tip pushed on end-on,
    // sin^2 below 1e-2) B's; where both lie within 1e-3 rad of n (tip to
    // tip) the coordinate axis least aligned with n: a node-to-node contact
    // has no tangential slip, so its frame only carries a committed force
    // over, and it must not be 0/0 (NaN in the new history).
    fr.projected = true;
    auto rel_proj = [&](const double* t) {
      const double tn = dot3(c.n, t) / norm3(t);
      return 1.0 - tn * tn;  // |(I - n n^T) unit(t)|^2
    };
    const double pa = rel_proj(c.ta);
    fr.frame_source = kFrameA;
    if (pa < kFrameMinSin2) {
      const double pb = rel_proj(c.tb);
      fr.frame_source = pb >= pa ? kFrameB : kFrameA;
      if (std::fmax(pa, pb) < 1e-6) {
        fr.frame_source = kFrameAxis;
        int k = 0;
        for (int i = 1; i < 3; ++i)
          if (std::fabs(c.n[i]) < std::fabs(c.n[k])) k = i;
        fr.axis[k] = 1.0;
      }
    }
    const double* t = frame_tangent(fr, c);
    const double tn = dot3(c.n, t);
    for (int i = 0; i < 3; ++i) fr.e1[i] = t[i] - tn * c.n[i];
    fr.frame_norm = norm3(fr.e1);
    for (int i = 0; i < 3; ++i) fr.e1[i] /= fr.frame_norm;
  }
  cross3(c.n, fr.e1, fr.e2);
  fr.anchored = hist_old[kHistTag] == kHistTagV1 && hist_old[kHistInContact] == 1.0;
  if (!fr.anchored) return fr;  // a new contact: stick, no force yet

  fr.committed_e1 = hist_old[kHistForceE1];
  fr.committed_e2 = hist_old[kHistForceE2];
  fr.xi_n = hist_old[kHistXi];
  fr.eta_n = hist_old[kHistEta];
  double xa[3], xb[3];  // relative to A's base node: accurate far from the origin
  const double* origin = c.sa->base();
  c.sa->point_from(origin, fr.xi_n, xa, nullptr, nullptr);
  c.sb->point_from(origin, fr.eta_n, xb, nullptr, nullptr);
  for (int i = 0; i < 3; ++i) fr.anchor_gap[i] = xa[i] - xb[i];
  // g_T = (I - n n^T)(x_A(xi_n) - x_B(eta_n)); T_trial = T_n + eps_T g_T
  const double nd = dot3(c.n, fr.anchor_gap);
  const double eps = p.tangential_penalty;
  for (int i = 0; i < 3; ++i)
    fr.trial[i] = fr.committed_e1 * fr.e1[i] + fr.committed_e2 * fr.e2[i] +
                  eps * (fr.anchor_gap[i] - nd * c.n[i]);
  // hypot: |T_trial| neither underflows nor overflows where T_trial does not
  // (a tiny trial force read as zero would stick beyond the Coulomb limit).
  fr.trial_norm = std::hypot(fr.trial[0], fr.trial[1], fr.trial[2]);
  const double limit = p.friction * c.normal_force;
  if (fr.trial_norm <= limit) {
    for (int i = 0; i < 3; ++i) fr.T[i] = fr.trial[i];
  } else {
    fr.state = B2B_FRICTION_SLIP;
    const double excess = fr.trial_norm - limit;
    for (int i = 0; i < 3; ++i) {
      const double dir = fr.trial[i] / fr.trial_norm;
      fr.T[i] = limit * dir;
      fr.slip[i] = excess / eps * dir;
    }
    fr.dissipation = limit * (excess / eps);
  }
  fr.force_e1 = dot3(fr.T, fr.e1);
  fr.force_e2 = dot3(fr.T, fr.e2);
  return fr;
}

void friction_tangent(const Params& p, const FrictionContact& c, const FrictionResult& fr,
                      const Linearization& lin, const double* PAd, const double* PBd,
                      double* Kc) {
  double PAn[36], PBn[36];
  c.sa->jacobian(fr.xi_n, PAn);
  c.sb->jacobian(fr.eta_n, PBn);
  const double* n = c.n;
  const double eps = p.tangential_penalty;
  const double nd = dot3(n, fr.anchor_gap);
  const bool slip = fr.state == B2B_FRICTION_SLIP;
  const double limit = p.friction * c.normal_force;
  double that[3] = {0, 0, 0};
  if (slip)
    for (int i = 0; i < 3; ++i) that[i] = fr.trial[i] / fr.trial_norm;
  const double ratio = slip ? limit / fr.trial_norm : 1.0;
  const double f = c.normal_force, fp = c.normal_slope;
  const bool rotating = c.rho_signed != 0.0;
  const double s = rotating ? f / c.rho_signed : 0.0;

  // Every entry is a sum of five products, rows times columns:
  //   K = J^T a + w0 C0^T + w1 C1^T,  a = M J + dT  (3 x m),
  // with the normal part -f' g g^T - s (J^T (I - n n^T) J - B^T H^-1 B)
  // (s = f / rho; at intersecting axes -f' g g^T + f (av C0^T + bv C1^T))
  // as M = -s I + (s - f') n n^T (M = -f' n n^T), w0 = s B0 (f av), w1 = s B1
  // (f bv), and the friction part J^T dT + [P_A,xi^T T; 0] dxi^T +
  // [0; -P_B,eta^T T] deta^T with dxi = -C0, deta = -C1 in w0 and w1.
  const int m = lin.m;
  double ax[kNdof], ay[kNdof], az[kNdof], w0[kNdof], w1[kNdof];
  for (int k = 0; k < m; ++k) {
    const int col = lin.cols[k];
    const bool on_a = col < 12;
    const int cc = on_a ? col : col - 12;
    const double dxi = -lin.C0[k], deta = -lin.C1[k];
    const double J[3] = {lin.Jx[k], lin.Jy[k], lin.Jz[k]};
    // dn = (I - n n^T)(J + x_A,xi dxi - x_B,eta deta) / rho
    double dn[3] = {0, 0, 0};
    if (rotating) {
      double v[3];
      for (int i = 0; i < 3; ++i) v[i] = J[i] + c.ta[i] * dxi - c.tb[i] * deta;
      const double nv = dot3(n, v);
      for (int i = 0; i < 3; ++i) dn[i] = (v[i] - nv * n[i]) / c.rho_signed;
    }
    // de1 = (I - e1 e1^T) d(x_A,xi) / |x_A,xi|, d(x_A,xi) = P_A,xi + x_A,xixi dxi
    double dta[3], de1[3], de2[3], t1[3], t2[3];
    if (fr.frame_source == kFrameB)  // d(x_B,eta) = P_B,eta + x_B,etaeta deta
      for (int i = 0; i < 3; ++i) dta[i] = (on_a ? 0.0 : PBd[3 * cc + i]) + c.tbd[i] * deta;
    else if (fr.frame_source == kFrameA)
      for (int i = 0; i < 3; ++i) dta[i] = (on_a ? PAd[3 * cc + i] : 0.0) + c.tad[i] * dxi;
    else  // a constant axis
      for (int i = 0; i < 3; ++i) dta[i] = 0.0;
    if (fr.projected) {  // p = (I - n n^T) t: dp = (I - n n^T) dt - (n.t) dn - n (dn.t)
      const double* t = frame_tangent(fr, c);
      const double tn = dot3(n, t), ndt = dot3(n, dta), dnt = dot3(dn, t);
      for (int i = 0; i < 3; ++i) dta[i] -= ndt * n[i] + tn * dn[i] + dnt * n[i];
    }
    const double e1dta = dot3(fr.e1, dta);
    for (int i = 0; i < 3; ++i) de1[i] = (dta[i] - e1dta * fr.e1[i]) / fr.frame_norm;
    cross3(dn, fr.e1, t1);  // de2 = dn x e1 + n x de1
    cross3(n, de1, t2);
    for (int i = 0; i < 3; ++i) de2[i] = t1[i] + t2[i];
    // dg_T = (I - n n^T) J_n - (n . d_n) dn - n (d_n . dn), J_n = [P_A(xi_n), -P_B(eta_n)]
    double jn[3], dgt[3];
    for (int i = 0; i < 3; ++i) jn[i] = on_a ? PAn[3 * cc + i] : -PBn[3 * cc + i];
    const double njn = dot3(n, jn), ddn = dot3(fr.anchor_gap, dn);
    for (int i = 0; i < 3; ++i) dgt[i] = jn[i] - njn * n[i] - nd * dn[i] - ddn * n[i];
    double dtr[3];
    for (int i = 0; i < 3; ++i)
      dtr[i] = fr.committed_e1 * de1[i] + fr.committed_e2 * de2[i] + eps * dgt[i];
    // slip: T = mu f_N that, dT = mu that df_N + (mu f_N/|T_tr|)(I - that that^T) dT_tr
    double dT[3];
    const double g = lin.g[k];
    if (slip) {
      const double tdt = dot3(that, dtr);
      const double dfn = p.friction * fp * g;
      for (int i = 0; i < 3; ++i) dT[i] = that[i] * dfn + ratio * (dtr[i] - tdt * that[i]);
    } else {
      for (int i = 0; i < 3; ++i) dT[i] = dtr[i];
    }
    // the columns' factors: a = M J + dT
    if (rotating) {
      const double sn = (s - fp) * g;
      ax[k] = (sn * n[0] - s * J[0]) + dT[0];
      ay[k] = (sn * n[1] - s * J[1]) + dT[1];
      az[k] = (sn * n[2] - s * J[2]) + dT[2];
    } else {
      ax[k] = -fp * g * n[0] + dT[0];
      ay[k] = -fp * g * n[1] + dT[1];
      az[k] = -fp * g * n[2] + dT[2];
    }
    // the rows' factors of C0 and C1, with the convective terms ( P_A,xi^T T | -P_B,eta^T T )
    const double b0 = rotating ? s * lin.B0[k] : f * lin.av[k];
    const double b1 = rotating ? s * lin.B1[k] : f * lin.bv[k];
    if (on_a) {
      w0[k] = b0 - dot3(PAd + 3 * cc, fr.T);
      w1[k] = b1;
    } else {
      w0[k] = b0;
      w1[k] = b1 + dot3(PBd + 3 * cc, fr.T);
    }
  }
  const double *Jx = lin.Jx, *Jy = lin.Jy, *Jz = lin.Jz, *C0 = lin.C0, *C1 = lin.C1;
  for (int cidx = 0; cidx < m; ++cidx) {
    double* colp = Kc + kNdof * cidx;
    const double tx = ax[cidx], ty = ay[cidx], tz = az[cidx], c0 = C0[cidx], c1 = C1[cidx];
    for (int r = 0; r < m; ++r)
      colp[r] = (Jx[r] * tx + Jy[r] * ty + Jz[r] * tz) + (w0[r] * c0 + w1[r] * c1);
  }
}

}  // namespace pair
}  // namespace b2b
