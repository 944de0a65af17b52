#include "tangent_term.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>

#include "vec3.hpp"

namespace b2b {
namespace curve {
namespace {

// The helpers below copy their small operands into locals first: H could
// alias them as far as the compiler knows, which would force a reload after
// every store and keep the loops from being unrolled and vectorised.

// H[3*sa + i, 3*sb + j] += B_ij (B column-major 3x3; H leading dimension ld)
inline void add_block(double* H, int ld, int sa, int sb, const double* B) {
  double b[9];
  for (int k = 0; k < 9; ++k) b[k] = B[k];
  double* h = H + 3 * sa + 3 * ld * sb;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) h[i + ld * j] += b[i + 3 * j];
}

// s * [B -B; -B B] on the slot pair (u, v): the second derivative of a
// function of x_v - x_u whose own second derivative is s * B.
inline void add_difference_blocks(double* H, int ld, int u, int v, const double* B, double s) {
  double sb[9], msb[9];
  for (int k = 0; k < 9; ++k) {
    sb[k] = s * B[k];
    msb[k] = -sb[k];
  }
  add_block(H, ld, u, u, sb);
  add_block(H, ld, v, v, sb);
  add_block(H, ld, u, v, msb);
  add_block(H, ld, v, u, msb);
}

// H[3*sa + i, 3*sb + j] += s * delta_ij
inline void add_identity_block(double* H, int ld, int sa, int sb, double s) {
  for (int i = 0; i < 3; ++i) H[(3 * sa + i) + ld * (3 * sb + i)] += s;
}

// Block (sa, sb) += s f g^T and block (sb, sa) += s g f^T (a symmetric pair;
// for sa == sb the block receives both).
inline void add_sym_outer(double* H, int ld, int sa, const double* f, int sb, const double* g,
                          double s) {
  const double sf[3] = {s * f[0], s * f[1], s * f[2]};
  const double gg[3] = {g[0], g[1], g[2]};
  double* hab = H + 3 * sa + 3 * ld * sb;
  double* hba = H + 3 * sb + 3 * ld * sa;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      hab[i + ld * j] += sf[i] * gg[j];
      hba[i + ld * j] += gg[i] * sf[j];
    }
}

// Projector I - e e^T (column-major; symmetric)
inline void projector(const double* e, double* Q) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) Q[i + 3 * j] = (i == j ? 1.0 : 0.0) - e[i] * e[j];
}

// out = A^T v (A column-major 3x3)
inline void mat_t_vec(const double* A, const double* v, double* out) {
  for (int j = 0; j < 3; ++j) out[j] = dot3(A + 3 * j, v);
}

// out = s A^T MB (all 3x3 column-major), MB = M B computed by the caller once
// per B
inline void atmb(const double* A, const double* MB, double s, double* out) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) out[i + 3 * j] = s * dot3(A + 3 * i, MB + 3 * j);
}

// out = M B (3x3 column-major)
inline void matmul3(const double* M, const double* B, double* out) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      out[i + 3 * j] = M[i] * B[3 * j] + M[i + 3] * B[1 + 3 * j] + M[i + 6] * B[2 + 3 * j];
}

}  // namespace

bool TangentTerm::evaluate(const double* X) {
  double d[3];
  sub3(X + 3 * q, X + 3 * p, d);
  L_ = norm3(d);
  for (int i = 0; i < 3; ++i) eL_[i] = d[i] / L_;

  double u[3] = {0, 0, 0};
  switch (dir) {
    case Dir::Constant:
      for (int i = 0; i < 3; ++i) u[i] = given[i];
      k0_ = 1.0;
      break;
    case Dir::Chord:
      sub3(X + 3 * c, X + 3 * a, u);
      k0_ = 1.0;
      break;
    case Dir::Weighted: {
      sub3(X + 3 * b, X + 3 * a, w1_);  // x_b - x_a
      sub3(X + 3 * c, X + 3 * b, w2_);  // x_c - x_b
      s1_ = dot3(w2_, w2_);             // l_bc^2 weighs the a-b difference
      s2_ = dot3(w1_, w1_);             // l_ab^2 weighs the b-c difference
      const double lab = std::sqrt(s2_), lbc = std::sqrt(s1_);
      k0_ = 1.0 / (lab * lbc * (lab + lbc));
      for (int i = 0; i < 3; ++i) u[i] = (k0_ * s1_) * w1_[i] + (k0_ * s2_) * w2_[i];
      break;
    }
  }
  r_ = norm3(u);
  // The segment has already rejected coincident x_a, x_c. What is left to
  // catch is the weighted direction: u~ is the parabola's tangent, of length
  // at most 1, and near zero only when the patch (almost) folds back on
  // itself, where its direction is lost to rounding.
  const double r_min = (dir == Dir::Weighted) ? 64.0 * DBL_EPSILON : 0.0;
  if (!(r_ > r_min)) return false;
  for (int i = 0; i < 3; ++i) {
    uhat_[i] = u[i] / r_;
    value[i] = sigma * L_ * uhat_[i];
  }
  return true;
}

void TangentTerm::jacobian() {
  // d(u~)/dx_s blocks
  switch (dir) {
    case Dir::Constant:
      n_slots_ = 0;
      break;
    case Dir::Chord:
      n_slots_ = 2;
      slot_[0] = a;
      slot_[1] = c;
      for (int k = 0; k < 9; ++k) {
        du_[0][k] = (k % 4 == 0) ? -1.0 : 0.0;
        du_[1][k] = (k % 4 == 0) ? 1.0 : 0.0;
      }
      break;
    case Dir::Weighted:
      // u = s1 w1 + s2 w2, s1 = |w2|^2, s2 = |w1|^2, w1 = x_b - x_a, w2 = x_c - x_b:
      // du/dx_a = -s1 I - 2 w2 w1^T
      // du/dx_b = (s1 - s2) I - 2 w1 w2^T + 2 w2 w1^T
      // du/dx_c = s2 I + 2 w1 w2^T         (all scaled by k0)
      n_slots_ = 3;
      slot_[0] = a;
      slot_[1] = b;
      slot_[2] = c;
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          const double id = (i == j) ? 1.0 : 0.0;
          du_[0][i + 3 * j] = k0_ * (-s1_ * id - 2.0 * w2_[i] * w1_[j]);
          du_[1][i + 3 * j] =
              k0_ * ((s1_ - s2_) * id - 2.0 * w1_[i] * w2_[j] + 2.0 * w2_[i] * w1_[j]);
          du_[2][i + 3 * j] = k0_ * (s2_ * id + 2.0 * w1_[i] * w2_[j]);
        }
      break;
  }
  // dT = sigma (uhat (x) dL + L duhat),  duhat = (I - uhat uhat^T) du / r
  std::memset(jac, 0, sizeof jac);
  const double s = sigma * L_ / r_;
  for (int k = 0; k < n_slots_; ++k) {
    const double* D = du_[k];
    for (int j = 0; j < 3; ++j) {
      const double* v = D + 3 * j;
      const double uv = dot3(uhat_, v);
      for (int i = 0; i < 3; ++i) jac[i + 3 * (3 * slot_[k] + j)] += s * (v[i] - uhat_[i] * uv);
    }
  }
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      jac[i + 3 * (3 * q + j)] += sigma * uhat_[i] * eL_[j];
      jac[i + 3 * (3 * p + j)] -= sigma * uhat_[i] * eL_[j];
    }
}

void TangentTerm::add_contracted_hessian(const double* w, double s, double* H, int ld) const {
  // w . d2T = sigma [ (w.uhat) d2L + dL (x) g + g (x) dL + L w.d2uhat ]
  const double wu = dot3(w, uhat_);

  // d2L = [QL -QL; -QL QL] / L on the slots (p, q).
  double QL[9], B[9];
  projector(eL_, QL);
  add_difference_blocks(H, ld, p, q, QL, s * sigma * wu / L_);
  if (dir == Dir::Constant) return;

  // cw = (I - uhat uhat^T) w / r, so that g = duhat^T w = du^T cw:
  // g on slot s is du_s^T cw; dL is -eL on p, +eL on q.
  const double inv_r = 1.0 / r_;
  double cw[3];
  for (int i = 0; i < 3; ++i) cw[i] = (w[i] - uhat_[i] * wu) * inv_r;
  double mL[3] = {-eL_[0], -eL_[1], -eL_[2]};
  for (int k = 0; k < n_slots_; ++k) {
    double g[3];
    mat_t_vec(du_[k], cw, g);
    add_sym_outer(H, ld, q, eL_, slot_[k], g, s * sigma);
    add_sym_outer(H, ld, p, mL, slot_[k], g, s * sigma);
  }

  // w . d2uhat = du^T M du + cw . d2u~, with
  // M = -[(uhat.w) Q + uhat (Qw)^T + (Qw) uhat^T] / r^2 = -[wu Q / r + uhat cw^T + cw uhat^T] / r
  double M[9], Qu[9];
  projector(uhat_, Qu);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      M[i + 3 * j] = -(wu * inv_r * Qu[i + 3 * j] + uhat_[i] * cw[j] + cw[i] * uhat_[j]) * inv_r;
  const double sLL = s * sigma * L_;
  if (dir == Dir::Chord) {  // u = x_c - x_a: du^T M du = [M -M; -M M] on (a, c)
    add_difference_blocks(H, ld, a, c, M, sLL);
    return;  // the chord is linear in X: d2u = 0
  }
  // du_k^T M du_l = (du_l^T M du_k)^T (M is symmetric): compute k <= l only.
  for (int l = 0; l < n_slots_; ++l) {
    double MD[9];
    matmul3(M, du_[l], MD);
    for (int k = 0; k <= l; ++k) {
      atmb(du_[k], MD, sLL, B);
      add_block(H, ld, slot_[k], slot_[l], B);
      if (k == l) continue;
      double Bt[9];
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) Bt[i + 3 * j] = B[j + 3 * i];
      add_block(H, ld, slot_[l], slot_[k], Bt);
    }
  }

  // cw . d2u, u = s1 w1 + s2 w2 (times k0):
  //   (cw.w1) d2s1 + sym((dw1^T cw) (x) ds1) + (cw.w2) d2s2 + sym((dw2^T cw) (x) ds2)
  // d2s1 = 2 on (b,b), (c,c), -2 on (b,c), (c,b); d2s2 likewise on a, b.
  // dw1^T cw = -cw on a, +cw on b; ds1 = -2 w2 on b, +2 w2 on c;
  // dw2^T cw = -cw on b, +cw on c; ds2 = -2 w1 on a, +2 w1 on b.
  const double t = sLL * k0_;
  const double cw1 = dot3(cw, w1_), cw2 = dot3(cw, w2_);
  add_identity_block(H, ld, b, b, 2.0 * t * (cw1 + cw2));
  add_identity_block(H, ld, c, c, 2.0 * t * cw1);
  add_identity_block(H, ld, b, c, -2.0 * t * cw1);
  add_identity_block(H, ld, c, b, -2.0 * t * cw1);
  add_identity_block(H, ld, a, a, 2.0 * t * cw2);
  add_identity_block(H, ld, a, b, -2.0 * t * cw2);
  add_identity_block(H, ld, b, a, -2.0 * t * cw2);
  double m_cw[3] = {-cw[0], -cw[1], -cw[2]};
  double w1x2[3] = {2.0 * w1_[0], 2.0 * w1_[1], 2.0 * w1_[2]};
  double w2x2[3] = {2.0 * w2_[0], 2.0 * w2_[1], 2.0 * w2_[2]};
  double m_w1x2[3] = {-w1x2[0], -w1x2[1], -w1x2[2]};
  double m_w2x2[3] = {-w2x2[0], -w2x2[1], -w2x2[2]};
  add_sym_outer(H, ld, a, m_cw, b, m_w2x2, t);  // f1 (x) ds1
  add_sym_outer(H, ld, a, m_cw, c, w2x2, t);
  add_sym_outer(H, ld, b, cw, b, m_w2x2, t);
  add_sym_outer(H, ld, b, cw, c, w2x2, t);
  add_sym_outer(H, ld, b, m_cw, a, m_w1x2, t);  // f2 (x) ds2
  add_sym_outer(H, ld, b, m_cw, b, w1x2, t);
  add_sym_outer(H, ld, c, cw, a, m_w1x2, t);
  add_sym_outer(H, ld, c, cw, b, w1x2, t);
}

}  // namespace curve
}  // namespace b2b
