#include "tangent_term.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>

#include "vec3.hpp"

namespace b2b {
namespace curve {
namespace {

// H[3*sa + i, 3*sb + j] += s * delta_ij  (a scaled identity block)
inline void add_identity_block(double* H, int sa, int sb, double s) {
  for (int i = 0; i < 3; ++i) H[(3 * sa + i) + 12 * (3 * sb + i)] += s;
}

// H[3*sa + i, 3*sb + j] += s * B_ij with B symmetric 3x3 (row-major = col-major)
inline void add_block(double* H, int sa, int sb, const double* B, double s) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) H[(3 * sa + i) + 12 * (3 * sb + j)] += s * B[i + 3 * j];
}

// H += f (x) g + g (x) f for 12-vectors f, g
inline void add_sym_outer(double* H, const double* f, const double* g) {
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) H[i + 12 * j] += f[i] * g[j] + g[i] * f[j];
}

// Projector I - e e^T
inline void projector(const double* e, double* Q) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) Q[i + 3 * j] = (i == j ? 1.0 : 0.0) - e[i] * e[j];
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
  std::memset(du_, 0, sizeof du_);
  switch (dir) {
    case Dir::Constant:
      break;
    case Dir::Chord:
      for (int i = 0; i < 3; ++i) {
        du_[i + 3 * (3 * a + i)] = -1.0;
        du_[i + 3 * (3 * c + i)] = 1.0;
      }
      break;
    case Dir::Weighted:
      // u = s1 w1 + s2 w2, s1 = |w2|^2, s2 = |w1|^2, w1 = x_b - x_a, w2 = x_c - x_b:
      // du/dx_a = -s1 I - 2 w2 w1^T
      // du/dx_b = (s1 - s2) I - 2 w1 w2^T + 2 w2 w1^T
      // du/dx_c = s2 I + 2 w1 w2^T         (all scaled by k0)
      for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
          const double id = (i == j) ? 1.0 : 0.0;
          du_[i + 3 * (3 * a + j)] = k0_ * (-s1_ * id - 2.0 * w2_[i] * w1_[j]);
          du_[i + 3 * (3 * b + j)] =
              k0_ * ((s1_ - s2_) * id - 2.0 * w1_[i] * w2_[j] + 2.0 * w2_[i] * w1_[j]);
          du_[i + 3 * (3 * c + j)] = k0_ * (s2_ * id + 2.0 * w1_[i] * w2_[j]);
        }
      }
      break;
  }
  // dT = sigma (uhat (x) dL + L duhat),  duhat = (I - uhat uhat^T) du / r
  std::memset(jac, 0, sizeof jac);
  for (int col = 0; col < 12; ++col) {
    const double* v = du_ + 3 * col;
    const double uv = dot3(uhat_, v);
    for (int i = 0; i < 3; ++i) jac[i + 3 * col] = sigma * L_ * (v[i] - uhat_[i] * uv) / r_;
  }
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      jac[i + 3 * (3 * q + j)] += sigma * uhat_[i] * eL_[j];
      jac[i + 3 * (3 * p + j)] -= sigma * uhat_[i] * eL_[j];
    }
}

void TangentTerm::accumulate_hessian(const double* w, double* H) const {
  std::memset(H, 0, 144 * sizeof(double));

  // w . d2T = sigma [ (w.uhat) d2L + dL (x) g + g (x) dL + L w.d2uhat ]
  const double wu = dot3(w, uhat_);

  // d2L: +QL/L on the (p,p), (q,q) blocks, -QL/L on (p,q), (q,p).
  double QL[9];
  projector(eL_, QL);
  const double sL = sigma * wu / L_;
  add_block(H, p, p, QL, sL);
  add_block(H, q, q, QL, sL);
  add_block(H, p, q, QL, -sL);
  add_block(H, q, p, QL, -sL);

  if (dir == Dir::Constant) return;

  // cw = (I - uhat uhat^T) w / r, so that g = duhat^T w = du^T cw.
  double cw[3];
  for (int i = 0; i < 3; ++i) cw[i] = (w[i] - uhat_[i] * wu) / r_;
  double g[12], dL[12] = {0};
  for (int col = 0; col < 12; ++col) g[col] = dot3(du_ + 3 * col, cw);
  for (int i = 0; i < 3; ++i) {
    dL[3 * q + i] = eL_[i];
    dL[3 * p + i] = -eL_[i];
  }
  double tmp[144] = {0};
  add_sym_outer(tmp, dL, g);
  for (int k = 0; k < 144; ++k) H[k] += sigma * tmp[k];

  // w . d2uhat = du^T M du + cw . d2u~, with
  // M = -[(uhat.w) Q + uhat (Qw)^T + (Qw) uhat^T] / r^2 = -[wu Q / r + uhat cw^T + cw uhat^T] / r
  double M[9], Qu[9];
  projector(uhat_, Qu);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      M[i + 3 * j] = -(wu * Qu[i + 3 * j] / r_ + uhat_[i] * cw[j] + cw[i] * uhat_[j]) / r_;
  double Mdu[36];
  for (int col = 0; col < 12; ++col)
    for (int i = 0; i < 3; ++i)
      Mdu[i + 3 * col] = M[i] * du_[3 * col] + M[i + 3] * du_[1 + 3 * col] + M[i + 6] * du_[2 + 3 * col];
  const double sLL = sigma * L_;
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) H[i + 12 * j] += sLL * dot3(du_ + 3 * i, Mdu + 3 * j);

  if (dir != Dir::Weighted) return;  // the chord is linear in X: d2u = 0

  // cw . d2u, u = s1 w1 + s2 w2 (times k0):
  //   (cw.w1) d2s1 + sym((dw1^T cw) (x) ds1) + (cw.w2) d2s2 + sym((dw2^T cw) (x) ds2)
  // d2s1 = 2 on (b,b), (c,c), -2 on (b,c), (c,b); d2s2 likewise on a, b.
  const double s = sLL * k0_;
  const double cw1 = dot3(cw, w1_), cw2 = dot3(cw, w2_);
  add_identity_block(H, b, b, 2.0 * s * cw1);
  add_identity_block(H, c, c, 2.0 * s * cw1);
  add_identity_block(H, b, c, -2.0 * s * cw1);
  add_identity_block(H, c, b, -2.0 * s * cw1);
  add_identity_block(H, a, a, 2.0 * s * cw2);
  add_identity_block(H, b, b, 2.0 * s * cw2);
  add_identity_block(H, a, b, -2.0 * s * cw2);
  add_identity_block(H, b, a, -2.0 * s * cw2);
  double f1[12] = {0}, ds1[12] = {0}, f2[12] = {0}, ds2[12] = {0};
  for (int i = 0; i < 3; ++i) {
    f1[3 * a + i] = -cw[i];  // dw1^T cw
    f1[3 * b + i] = cw[i];
    ds1[3 * b + i] = -2.0 * w2_[i];
    ds1[3 * c + i] = 2.0 * w2_[i];
    f2[3 * b + i] = -cw[i];  // dw2^T cw
    f2[3 * c + i] = cw[i];
    ds2[3 * a + i] = -2.0 * w1_[i];
    ds2[3 * b + i] = 2.0 * w1_[i];
  }
  std::memset(tmp, 0, sizeof tmp);
  add_sym_outer(tmp, f1, ds1);
  add_sym_outer(tmp, f2, ds2);
  for (int k = 0; k < 144; ++k) H[k] += s * tmp[k];
}

void TangentTerm::contracted_hessian(const double* w, double* H) const {
  accumulate_hessian(w, H);
  // The terms above are symmetric only up to rounding (du^T M du sums in a
  // different order for (a,b) and (b,a)); make the matrix exactly symmetric,
  // as documented, so hosts may rely on it.
  for (int j = 0; j < 12; ++j)
    for (int i = j + 1; i < 12; ++i) {
      const double m = 0.5 * (H[i + 12 * j] + H[j + 12 * i]);
      H[i + 12 * j] = m;
      H[j + 12 * i] = m;
    }
}

}  // namespace curve
}  // namespace b2b
