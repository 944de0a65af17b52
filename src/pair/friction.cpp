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

// |v|, neither underflowing nor overflowing where v does not (a tiny trial
// force read as zero would stick beyond the Coulomb limit): the plain sum of
// squares where the largest component lies within 1e+-150 (no square can
// overflow, and one that underflows is below the rounding of the largest),
// std::hypot only outside (its three divisions cost more than the rest of
// the return mapping).
double safe_norm3(const double* v) {
  const double a = curve::max_abs3(v);  // (a NaN goes either way, and stays NaN)
  if (a > 1e-150 && a < 1e150) return std::sqrt(dot3(v, v));
  return std::hypot(v[0], v[1], v[2]);
}
}  // namespace

FrictionResult friction_force(const Params& p, const FrictionContact& c, const double* hist_old) {
  FrictionResult fr;
  fr.state = B2B_FRICTION_STICK;
  fr.speed_a = norm3(c.ta);
  fr.frame_norm = fr.speed_a;
  const double inv_speed = 1.0 / fr.speed_a;
  for (int i = 0; i < 3; ++i) fr.e1[i] = c.ta[i] * inv_speed;
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
    const double inv_norm = 1.0 / fr.frame_norm;
    for (int i = 0; i < 3; ++i) fr.e1[i] *= inv_norm;
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
  if (c.surface_b > 0.0) {
    // A point sliding round B's axis keeps its distance to the axis point:
    // read the slip at B's surface, r_B m off the axis (FrictionContact).
    // Where n_n lies along B's tangent (|p| below 1e-8) there is no surface
    // direction to read it at, and the axis point serves.
    double t[3], pv[3];
    c.sb->point(fr.eta_n, nullptr, t, nullptr);
    fr.surface_speed = norm3(t);
    const double* nn = hist_old + kHistNormal;
    for (int i = 0; i < 3; ++i) {
      fr.surface_t[i] = t[i] / fr.surface_speed;
      fr.surface_nn[i] = nn[i];
    }
    fr.surface_tnn = dot3(fr.surface_t, nn);
    for (int i = 0; i < 3; ++i) pv[i] = nn[i] - fr.surface_tnn * fr.surface_t[i];
    fr.surface_pn = norm3(pv);
    fr.surface = fr.surface_pn > 1e-8;
    if (fr.surface)
      for (int i = 0; i < 3; ++i) {
        fr.surface_m[i] = pv[i] / fr.surface_pn;
        fr.anchor_gap[i] -= c.surface_b * fr.surface_m[i];
      }
  }
  // g_T = (I - n n^T)(x_A(xi_n) - x_B(eta_n)); T_trial = T_n + eps_T g_T
  const double nd = dot3(c.n, fr.anchor_gap);
  const double eps = p.tangential_penalty;
  for (int i = 0; i < 3; ++i)
    fr.trial[i] = fr.committed_e1 * fr.e1[i] + fr.committed_e2 * fr.e2[i] +
                  eps * (fr.anchor_gap[i] - nd * c.n[i]);
  fr.trial_norm = safe_norm3(fr.trial);
  const double limit = p.friction * c.normal_force;
  if (fr.trial_norm <= limit) {
    for (int i = 0; i < 3; ++i) fr.T[i] = fr.trial[i];
  } else {
    fr.state = B2B_FRICTION_SLIP;
    const double excess = fr.trial_norm - limit, slip_length = excess / eps;
    const double inv_trial = 1.0 / fr.trial_norm;
    for (int i = 0; i < 3; ++i) {
      const double dir = fr.trial[i] * inv_trial;
      fr.T[i] = limit * dir;
      fr.slip[i] = slip_length * dir;
    }
    fr.dissipation = limit * slip_length;
  }
  fr.force_e1 = dot3(fr.T, fr.e1);
  fr.force_e2 = dot3(fr.T, fr.e2);
  return fr;
}

namespace {

// 3 x 3 matrices, column-major.
void matvec3(const double* A, const double* v, double* y) {  // y = A v
  for (int i = 0; i < 3; ++i) y[i] = A[i] * v[0] + A[i + 3] * v[1] + A[i + 6] * v[2];
}
// a I + u v^T
void rank_one3(double a, const double* u, const double* v, double* M) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) M[i + 3 * j] = (i == j ? a : 0.0) + u[i] * v[j];
}
// a I + b [w]x ([w]x v = w x v)
void cross_matrix3(double a, double b, const double* w, double* M) {
  M[0] = a;
  M[1] = b * w[2];
  M[2] = -b * w[1];
  M[3] = -b * w[2];
  M[4] = a;
  M[5] = b * w[0];
  M[6] = b * w[1];
  M[7] = -b * w[0];
  M[8] = a;
}

// Kc = J^T a + w0 C0^T + w1 C1^T on the m x m used block (the five
// products of friction_tangent; a is 3 x m column-major); restrict: the
// compiler vectorises the rows. kM: m as a constant (0: read m_), which
// spares the loops their run-time set-up where every column is used.
template <int kM>
void five_term_pass(int m_, const double* __restrict Jx, const double* __restrict Jy,
                    const double* __restrict Jz, const double* __restrict w0,
                    const double* __restrict w1, const double* __restrict a,
                    const double* __restrict C0, const double* __restrict C1,
                    double* __restrict Kc) {
  const int m = kM ? kM : m_;
  int c = 0;
  for (; c + 1 < m; c += 2) {  // two columns per pass: each row's values loaded once
    double* __restrict col0 = Kc + kNdof * c;
    double* __restrict col1 = col0 + kNdof;
    const double tx = a[3 * c], ty = a[3 * c + 1], tz = a[3 * c + 2], c0 = C0[c], c1 = C1[c];
    const double ux = a[3 * c + 3], uy = a[3 * c + 4], uz = a[3 * c + 5], d0 = C0[c + 1],
                 d1 = C1[c + 1];
#pragma GCC unroll 4
    for (int r = 0; r < m; ++r) {
      const double jx = Jx[r], jy = Jy[r], jz = Jz[r], v0 = w0[r], v1 = w1[r];
      col0[r] = (jx * tx + jy * ty + jz * tz) + (v0 * c0 + v1 * c1);
      col1[r] = (jx * ux + jy * uy + jz * uz) + (v0 * d0 + v1 * d1);
    }
  }
  if (c < m) {
    double* col = Kc + kNdof * c;
    const double tx = a[3 * c], ty = a[3 * c + 1], tz = a[3 * c + 2], c0 = C0[c], c1 = C1[c];
    for (int r = 0; r < m; ++r)
      col[r] = (Jx[r] * tx + Jy[r] * ty + Jz[r] * tz) + (w0[r] * c0 + w1[r] * c1);
  }
}

void five_term_pass(int m, const Linearization& lin, const double* w0, const double* w1,
                    const double* a, double* Kc) {
  if (m == kNdof)
    five_term_pass<kNdof>(m, lin.Jx, lin.Jy, lin.Jz, w0, w1, a, lin.C0, lin.C1, Kc);
  else
    five_term_pass<0>(m, lin.Jx, lin.Jy, lin.Jz, w0, w1, a, lin.C0, lin.C1, Kc);
}

// The same where every column of J lies along its own axis (both segments
// linear in X; row r along axis r % 3, the used columns come in whole
// slots): the two zero products of J^T a drop out, the sums are unchanged.
// Six rows at a time (two of each axis), so that the rows pair up with the
// column's factors (ax, ay), (az, ax), (ay, az) and vectorise.
void three_term_pass(int m, const Linearization& lin, const double* __restrict w0,
                     const double* __restrict w1, const double* __restrict a,
                     double* __restrict Kc) {
  double jd[kNdof];  // J's entry on its axis, row by row
  for (int r = 0; r < m; r += 3) {
    jd[r] = lin.Jx[r];
    jd[r + 1] = lin.Jy[r + 1];
    jd[r + 2] = lin.Jz[r + 2];
  }
  const double* __restrict C0 = lin.C0;
  const double* __restrict C1 = lin.C1;
  const int m6 = m - m % 6;
  for (int c = 0; c < m; ++c) {
    double* __restrict col = Kc + kNdof * c;
    const double t[3] = {a[3 * c], a[3 * c + 1], a[3 * c + 2]};
    const double c0 = C0[c], c1 = C1[c];
    int r = 0;
    for (; r < m6; r += 6)
      for (int q = 0; q < 6; ++q)
        col[r + q] = jd[r + q] * t[q % 3] + (w0[r + q] * c0 + w1[r + q] * c1);
    for (; r < m; ++r) col[r] = jd[r] * t[r % 3] + (w0[r] * c0 + w1[r] * c1);
  }
}

// The row factors w0, w1 of rows [k0, k1) (one beam's used columns), as the
// general loop of friction_tangent computes them but on the compact rows of
// J and Q = [P_A,xi, P_B,eta] (lin), which vectorise:
//   w0 = b0 - [P_A,xi^T T on A] - J.v_xi,  w1 = b1 + [P_B,eta^T T on B] - J.v_eta,
// with the same sums in the same order.
template <bool kOnA>
void factor_rows(int k0, int k1, const double* T, const double* v_xi, const double* v_eta,
                 const double* b0v, const double* b1v, double sb, const Linearization& lin,
                 double* __restrict w0, double* __restrict w1) {
  const double* __restrict Jx = lin.Jx;
  const double* __restrict Jy = lin.Jy;
  const double* __restrict Jz = lin.Jz;
  const double* __restrict px = lin.Qx;
  const double* __restrict py = lin.Qy;
  const double* __restrict pz = lin.Qz;
  const double* __restrict b0 = b0v;
  const double* __restrict b1 = b1v;
  for (int k = k0; k < k1; ++k) {
    const double J0 = Jx[k], J1 = Jy[k], J2 = Jz[k];
    const double p0 = px[k], p1 = py[k], p2 = pz[k];
    const double conv = p0 * T[0] + p1 * T[1] + p2 * T[2];
    const double jxi = J0 * v_xi[0] + J1 * v_xi[1] + J2 * v_xi[2];
    const double jeta = J0 * v_eta[0] + J1 * v_eta[1] + J2 * v_eta[2];
    w0[k] = kOnA ? (sb * b0[k] - conv) - jxi : sb * b0[k] - jxi;
    w1[k] = kOnA ? sb * b1[k] - jeta : (sb * b1[k] + conv) - jeta;
  }
}

}  // namespace

void friction_tangent(const Params& p, const FrictionContact& c, const FrictionResult& fr,
                      const Linearization& lin, const double* PAd, const double* PBd,
                      double* Kc) {
  const double* n = c.n;
  const double eps = p.tangential_penalty;
  const double nd = dot3(n, fr.anchor_gap);
  const bool slip = fr.state == B2B_FRICTION_SLIP;
  const double limit = p.friction * c.normal_force;
  const double f = c.normal_force, fp = c.normal_slope;
  const bool rotating = c.rho_signed != 0.0;
  const double s = rotating ? f / c.rho_signed : 0.0;

  // dT is linear in what a column moves: J (through dn and, in slip, df_N =
  // f' n.J), dxi, deta, the frame tangent's jacobian column pd and the
  // anchors' jn (doc/friction.md section 6). Its 3 x 3 factors, once:
  //   dn   = Pn (J + x_A,xi dxi - x_B,eta deta) / rho,  Pn = I - n n^T
  //   de1  = E (S dta - Q dn),  E = (I - e1 e1^T) / |t|, dta = pd + t' dxi (deta)
  //          (projected frame: S = Pn, Q = (n.t) I + n t^T; else S = I, Q = 0)
  //   dT_tr = F de1 + G dn + eps Pn jn,  F = c1 I + c2 [n]x,
  //          G = -c2 [e1]x - eps (nd I + n d_n^T)
  //   dT   = R dT_tr + mu f' that (n.J),  R = ratio (I - that that^T) in slip, I in stick
  // so dT = Mdn dn + Mta dta + Mjn jn + tg n^T J with Mta = R F E S,
  // Mdn = R (G - F E Q), Mjn = eps R Pn, tg = mu f' that (slip).
  // Every factor but F and G is the identity plus rank-one terms, so each
  // product with one is a rank-one correction (9 products, not 27):
  //   X Pn = X - (X n) n^T,  X E = (X - (X e1) e1^T) / |t|,
  //   R X = ratio (X - that (that^T X)) in slip.
  double ratio = 1.0, that[3] = {0, 0, 0}, tg[3] = {0, 0, 0};
  if (slip) {
    const double inv_trial = 1.0 / fr.trial_norm;
    for (int i = 0; i < 3; ++i) {
      that[i] = fr.trial[i] * inv_trial;
      tg[i] = p.friction * fp * that[i];
    }
    ratio = limit * inv_trial;
  }
  auto apply_R = [&](double* X) {  // X = R X
    if (!slip) return;
    for (int j = 0; j < 3; ++j) {
      double* x = X + 3 * j;
      const double d = dot3(that, x);
      for (int i = 0; i < 3; ++i) x[i] = ratio * (x[i] - that[i] * d);
    }
  };
  auto times_Pn = [n](const double* X, double scale, double* Y) {  // Y = scale X Pn
    double xn[3];
    matvec3(X, n, xn);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) Y[i + 3 * j] = scale * (X[i + 3 * j] - xn[i] * n[j]);
  };
  double F[9], G[9];
  cross_matrix3(fr.committed_e1, fr.committed_e2, n, F);
  {
    double Ge[9], epsn[3];
    cross_matrix3(0.0, -fr.committed_e2, fr.e1, Ge);
    for (int i = 0; i < 3; ++i) epsn[i] = -eps * n[i];
    rank_one3(-eps * nd, epsn, fr.anchor_gap, G);
    for (int k = 0; k < 9; ++k) G[k] += Ge[k];
  }
  double FE[9], RFE[9], Mta[9], Mdn[9], Mjn[9];
  {
    double fe1[3];
    matvec3(F, fr.e1, fe1);
    const double inv = 1.0 / fr.frame_norm;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) FE[i + 3 * j] = inv * (F[i + 3 * j] - fe1[i] * fr.e1[j]);
  }
  for (int k = 0; k < 9; ++k) {
    RFE[k] = FE[k];
    Mdn[k] = G[k];
  }
  apply_R(RFE);
  if (fr.projected) {  // FE Q = (n.t) FE + (FE n) t^T; Mta = RFE Pn
    const double* t = frame_tangent(fr, c);
    const double nt = dot3(n, t);
    double fen[3];
    matvec3(FE, n, fen);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) Mdn[i + 3 * j] -= nt * FE[i + 3 * j] + fen[i] * t[j];
    times_Pn(RFE, 1.0, Mta);
  } else {
    for (int k = 0; k < 9; ++k) Mta[k] = RFE[k];
  }
  apply_R(Mdn);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) Mjn[i + 3 * j] = (i == j ? 1.0 : 0.0) - n[i] * n[j];
  apply_R(Mjn);
  for (int k = 0; k < 9; ++k) Mjn[k] *= eps;
  // dn's factors: Pn / rho on J, Pn x_A,xi / rho on dxi, -Pn x_B,eta / rho on deta
  // (zero where the normal does not rotate).
  const double inv_rho = rotating ? 1.0 / c.rho_signed : 0.0;
  double dn_xi[3], dn_eta[3];
  {
    const double nta = dot3(n, c.ta), ntb = dot3(n, c.tb);
    for (int i = 0; i < 3; ++i) {
      dn_xi[i] = inv_rho * (c.ta[i] - n[i] * nta);
      dn_eta[i] = inv_rho * (c.tb[i] - n[i] * ntb);
    }
  }
  // The columns' factor a = M J + dT, with the normal part M = -s I + (s -
  // f') n n^T (-f' n n^T at intersecting axes), all on J in one matrix:
  //   A = M + Mdn Pn / rho + tg n^T;
  // the terms in dxi and deta go to the rows (below): v_xi = Mdn dn_xi
  // (+ Mta x_A,xixi, frame A), v_eta = -Mdn dn_eta (+ Mta x_B,etaeta, frame B).
  double A[9], v_xi[3], v_eta[3];
  times_Pn(Mdn, inv_rho, A);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      A[i + 3 * j] += (i == j ? -s : 0.0) + ((s - fp) * n[i] + tg[i]) * n[j];
  matvec3(Mdn, dn_xi, v_xi);
  matvec3(Mdn, dn_eta, v_eta);
  for (int i = 0; i < 3; ++i) v_eta[i] = -v_eta[i];
  const bool pd_on_a = fr.frame_source == kFrameA, pd_on_b = fr.frame_source == kFrameB;
  if (pd_on_a) {
    double y[3];
    matvec3(Mta, c.tad, y);
    for (int i = 0; i < 3; ++i) v_xi[i] += y[i];
  } else if (pd_on_b) {
    double y[3];
    matvec3(Mta, c.tbd, y);
    for (int i = 0; i < 3; ++i) v_eta[i] += y[i];
  }

  // Every entry is a sum of five products, rows times columns:
  //   K = J^T a + w0 C0^T + w1 C1^T,
  // the normal part -s (J^T (I - n n^T) J - B^T H^-1 B) - f' g g^T (at
  // intersecting axes -f' g g^T + f (av C0^T + bv C1^T)) and the friction
  // part J^T dT + [P_A,xi^T T; 0] dxi^T + [0; -P_B,eta^T T] deta^T, with
  // dxi = -C0, deta = -C1: w0 = s B0 (f av) - (J v_xi) - [P_A,xi^T T; 0],
  // w1 = s B1 (f bv) - (J v_eta) + [0; P_B,eta^T T].
  const int m = lin.m;
  double a[3 * kNdof], w0[kNdof], w1[kNdof];  // a: 3 x m, column-major
  const double* b0 = rotating ? lin.B0 : lin.av;
  const double* b1 = rotating ? lin.B1 : lin.bv;
  const double sb = rotating ? s : f;
  if (!fr.surface) {
    // On each beam a = A J + Mjn jn + Mpd pd is one combination of the
    // segment's jacobians at the contact and at the anchor
    // (Segment::combine_jacobians): no jacobian at the anchor, no three 3x3
    // products per column. J = -P_B, jn = -P_B(eta_n) on B: A and Mjn
    // change sign there; pd is P_A,xi or P_B,eta for the beam whose tangent
    // the frame follows (Mpd = Mta), absent on the other.
    double nA[9], nMjn[9];
    for (int e = 0; e < 9; ++e) {
      nA[e] = -A[e];
      nMjn[e] = -Mjn[e];
    }
    using Term = curve::Segment::JacobianTerm;
    const Term terms_a[3] = {{c.xi, false, A}, {fr.xi_n, false, Mjn}, {c.xi, true, Mta}};
    const Term terms_b[3] = {{c.eta, false, nA}, {fr.eta_n, false, nMjn}, {c.eta, true, Mta}};
    // (The used columns are whole slots in slot order: a, A's then B's.)
    c.sa->combine_jacobians(pd_on_a ? 3 : 2, terms_a, lin.used_a, a);
    c.sb->combine_jacobians(pd_on_b ? 3 : 2, terms_b, lin.used_b, a + 3 * lin.m_a);
    factor_rows<true>(0, lin.m_a, fr.T, v_xi, v_eta, b0, b1, sb, lin, w0, w1);
    factor_rows<false>(lin.m_a, m, fr.T, v_xi, v_eta, b0, b1, sb, lin, w0, w1);
    if (lin.axial && c.sa->linear_in_X() && c.sb->linear_in_X())
      three_term_pass(m, lin, w0, w1, a, Kc);
    else
      five_term_pass(m, lin, w0, w1, a, Kc);
    return;
  }
  // The surface anchor (a line-contact point): its - r_B dm moves with B's
  // tangent at eta_n too, column by column with the anchors' jacobians.
  double PAn[36], PBn[36], PBnd[36];
  c.sa->jacobian(fr.xi_n, PAn);
  c.sb->jacobians(fr.eta_n, PBn, PBnd);
  for (int k = 0; k < m; ++k) {
    const int col = lin.cols[k];
    const bool on_a = col < 12;
    const int cc = on_a ? col : col - 12;
    const double J[3] = {lin.Jx[k], lin.Jy[k], lin.Jz[k]};
    double ak[3], y[3];
    const double* pn = on_a ? PAn + 3 * cc : PBn + 3 * cc;
    const double sn = on_a ? 1.0 : -1.0;
    double jn[3] = {sn * pn[0], sn * pn[1], sn * pn[2]};
    if (!on_a) {
      // the surface anchor's - r_B dm: dt = (I - t t^T) dx_B,eta(eta_n) / |x_B,eta|,
      // dp = -(dt (t.n_n) + t (dt.n_n)), dm = (I - m m^T) dp / |p|
      const double* pdn = PBnd + 3 * cc;
      const double* t = fr.surface_t;
      const double tp = dot3(t, pdn);
      double dt[3], dp[3];
      for (int i = 0; i < 3; ++i) dt[i] = (pdn[i] - tp * t[i]) / fr.surface_speed;
      const double dtn = dot3(dt, fr.surface_nn);
      for (int i = 0; i < 3; ++i) dp[i] = -(dt[i] * fr.surface_tnn + t[i] * dtn);
      const double mdp = dot3(fr.surface_m, dp);
      for (int i = 0; i < 3; ++i)
        jn[i] -= c.surface_b * (dp[i] - mdp * fr.surface_m[i]) / fr.surface_pn;
    }
    matvec3(A, J, ak);
    matvec3(Mjn, jn, y);
    for (int i = 0; i < 3; ++i) ak[i] += y[i];
    if ((pd_on_a && on_a) || (pd_on_b && !on_a)) {
      matvec3(Mta, (on_a ? PAd : PBd) + 3 * cc, y);
      for (int i = 0; i < 3; ++i) ak[i] += y[i];
    }
    for (int i = 0; i < 3; ++i) a[3 * k + i] = ak[i];
    const double b0k = sb * b0[k], b1k = sb * b1[k];
    if (on_a) {
      w0[k] = (b0k - dot3(PAd + 3 * cc, fr.T)) - dot3(J, v_xi);
      w1[k] = b1k - dot3(J, v_eta);
    } else {
      w0[k] = b0k - dot3(J, v_xi);
      w1[k] = (b1k + dot3(PBd + 3 * cc, fr.T)) - dot3(J, v_eta);
    }
  }
  five_term_pass(m, lin, w0, w1, a, Kc);
}

}  // namespace pair
}  // namespace b2b
