#include "tangent_term.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>

#include "vec3.hpp"

namespace b2b {
namespace curve {

namespace {

// A[i + 3 j] = v(i, j) for a symmetric 3x3 A: the upper triangle computed,
// the lower one copied (exactly symmetric, a third fewer products).
template <typename V>
inline void fill_symmetric(double* A, V v) {
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i <= j; ++i) A[i + 3 * j] = v(i, j);
  A[1] = A[3];
  A[2] = A[6];
  A[5] = A[7];
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
  if (dir == Dir::Chord) {
    // u = x_c - x_a: duhat = (I - uhat uhat^T) (dx_c - dx_a) / r, so with
    // S = sigma L (I - uhat uhat^T) / r and E = sigma uhat eL^T the block of
    // slot k is [k = c] S - [k = a] S + [k = q] E - [k = p] E, written once
    // (the same sums as the general path below, without clearing jac and
    // adding to it block by block).
    const double s = sigma * L_ / r_;
    double S[9], E[9];
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        S[i + 3 * j] = s * ((i == j ? 1.0 : 0.0) - uhat_[i] * uhat_[j]);
        E[i + 3 * j] = sigma * uhat_[i] * eL_[j];
      }
    for (int k = 0; k < 4; ++k) {
      double* J = jac + 9 * k;
      const bool on_s = (k == a || k == c), on_e = (k == p || k == q);
      const double ss = k == c ? 1.0 : -1.0, se = k == q ? 1.0 : -1.0;
      for (int m = 0; m < 9; ++m) {
        double v = 0.0;
        if (on_s) v = ss * S[m];
        if (on_e) v = on_s ? v + se * E[m] : se * E[m];
        J[m] = v;
      }
    }
    return;
  }
  // d(u~)/dx_s blocks
  switch (dir) {
    case Dir::Constant:
      n_slots_ = 0;
      break;
    case Dir::Chord:  // written above
      return;
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

void TangentTerm::add_product(const double* N, double* const Y[4]) const {
  if (dir == Dir::Weighted) {
    // The direction's blocks are general 3x3 matrices: N jac on the slots
    // a, b, c (p and q are among them on every segment that has this rule).
    for (int slot = 0; slot < 4; ++slot) {
      if (slot != a && slot != b && slot != c && slot != p && slot != q) continue;
      const double* J = jac + 9 * slot;
      double* y = Y[slot];
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
          y[i + 3 * j] += N[i] * J[3 * j] + N[i + 3] * J[3 * j + 1] + N[i + 6] * J[3 * j + 2];
    }
    return;
  }
  // N E = sigma (N uhat) eL^T on the slots q (+) and p (-), as in jacobian().
  double nu[3];
  for (int i = 0; i < 3; ++i)
    nu[i] = sigma * (N[i] * uhat_[0] + N[i + 3] * uhat_[1] + N[i + 6] * uhat_[2]);
  // (Each block through a local copy: the compiler cannot know that the
  // slots' blocks of Y do not overlap.)
  auto add_to = [Y](int slot, const double* v, bool minus) {
    double* y = Y[slot];
    for (int k = 0; k < 9; ++k) y[k] = minus ? y[k] - v[k] : y[k] + v[k];
  };
  double v[9];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) v[i + 3 * j] = nu[i] * eL_[j];
  add_to(q, v, false);
  add_to(p, v, true);
  if (dir == Dir::Constant) return;
  // Chord: N S = s (N - (N uhat) uhat^T) = s N - (L / r) nu uhat^T on the
  // slots c (+) and a (-).
  const double sc = sigma * L_ / r_, lr = L_ / r_;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) v[i + 3 * j] = sc * N[i + 3 * j] - lr * nu[i] * uhat_[j];
  add_to(c, v, false);
  add_to(a, v, true);
}

void TangentTerm::contraction(const double* w, double s, Contraction& out) const {
  // T = sigma L(d) uhat(u~), d = z_q, u~ = k0 u a function of (z_b, z_c):
  //   w . d2T = sigma [ (w.uhat) d2L + dL (x) g + g (x) dL + L w.d2uhat ],
  // g = duhat^T w. All of it lives on the blocks of z_b and z_c (q is one of
  // them), a symmetric 6x6 matrix with blocks (b, b), (b, c), (c, c):
  //   F^T M F + [the dL and d2L terms on q's row and column] (+ cw . d2u~),
  // F = [Fb, Fc] = du~/d(z_b, z_c), M = w . d2uhat/du~2 times sigma L, and
  // with e = eL, G_x = sigma Fx^T cw the dL terms are e G_x^T on (q, x) and
  // G_x e^T on (x, q), and sigma (w.uhat) d2L = cL (I - e e^T) on (q, q).
  const double wu = dot3(w, uhat_);
  const double t0 = s * sigma;
  out.cL = t0 * wu / L_;  // d2L = (I - eL eL^T) / L on (q, q)
  for (int i = 0; i < 3; ++i) out.e[i] = eL_[i];
  const double inv_r = 1.0 / r_;
  const double uh[3] = {uhat_[0], uhat_[1], uhat_[2]};
  double cw[3];  // (I - uhat uhat^T) w / r: duhat^T w = du~^T cw
  for (int i = 0; i < 3; ++i) cw[i] = (w[i] - uh[i] * wu) * inv_r;

  // M = -[wu (I - uhat uhat^T) / r + uhat cw^T + cw uhat^T] / r, times t0 L
  const double tL = t0 * L_;
  const double mI = -tL * wu * inv_r * inv_r, mu = tL * wu * inv_r * inv_r, mc = -tL * inv_r;
  double* M = (dir == Dir::Chord) ? out.Nbb : out.Nbc;  // the weighted blocks are multiples of it
  fill_symmetric(M, [&](int i, int j) {
    return (i == j ? mI : 0.0) + mu * uh[i] * uh[j] + mc * (uh[i] * cw[j] + cw[i] * uh[j]);
  });

  if (dir == Dir::Chord) {  // u = z_b + z_c: Fb = Fc = I, all three blocks M
    for (int i = 0; i < 3; ++i) out.Gb[i] = out.Gc[i] = t0 * cw[i];
    return;
  }
  // Fb = fa I + 2 y2 y1^T, Fc = fb I + 2 y1 y2^T with fa = k0 s1, fb = k0 s2,
  // y = sqrt(k0) w (u = s1 w1 + s2 w2, s1 = |w2|^2, s2 = |w1|^2, w1 = z_b,
  // w2 = z_c; the factors keep every product in range, as u~ = k0 u is
  // O(1)), so with n1 = M y1, n2 = M y2:
  //   Fb^T M Fb = fa^2 M + 2 fa (y1 n2^T + n2 y1^T) + 4 (y2.n2) y1 y1^T,
  //   Fc^T M Fc = fb^2 M + 2 fb (y2 n1^T + n1 y2^T) + 4 (y1.n1) y2 y2^T,
  //   Fb^T M Fc = fa fb M + 2 fa n1 y2^T + 2 fb y1 n2^T + 4 (y2.n1) y1 y2^T,
  // and cw . d2u~ = k0 [2 (cw.w2) I, 2 (cw w2^T + w1 cw^T); . , 2 (cw.w1) I]
  // (times sigma L): a multiple of M plus symmetric rank-two terms per block.
  const double rk = std::sqrt(k0_);
  const double fa = k0_ * s1_, fb = k0_ * s2_;
  double y1[3], y2[3], n1[3], n2[3];
  for (int i = 0; i < 3; ++i) {
    y1[i] = rk * w1_[i];
    y2[i] = rk * w2_[i];
  }
  for (int i = 0; i < 3; ++i) {
    n1[i] = M[i] * y1[0] + M[i + 3] * y1[1] + M[i + 6] * y1[2];
    n2[i] = M[i] * y2[0] + M[i + 3] * y2[1] + M[i + 6] * y2[2];
  }
  const double mu11 = dot3(y1, n1), mu22 = dot3(y2, n2), mu12 = dot3(y2, n1);
  const double cy1 = dot3(cw, y1), cy2 = dot3(cw, y2);
  const double tau = 2.0 * tL * rk;  // the factor of cw . d2u~ in y
  const double dbb = tau * cy2, dcc = tau * cy1;
  double pb[3], pc[3], u[3], v[3];
  for (int i = 0; i < 3; ++i) {
    pb[i] = 2.0 * (fa * n2[i] + mu22 * y1[i]);
    pc[i] = 2.0 * (fb * n1[i] + mu11 * y2[i]);
    u[i] = 2.0 * fa * n1[i] + tau * cw[i];
    v[i] = 2.0 * (fb * n2[i] + 2.0 * mu12 * y2[i]) + tau * cw[i];
    out.Gb[i] = t0 * (fa * cw[i] + 2.0 * cy2 * y1[i]);  // sigma Fb^T cw
    out.Gc[i] = t0 * (fb * cw[i] + 2.0 * cy1 * y2[i]);
  }
  const double abb = fa * fa, acc = fb * fb, abc = fa * fb;
  fill_symmetric(out.Nbb, [&](int i, int j) {
    return abb * M[i + 3 * j] + (y1[i] * pb[j] + pb[i] * y1[j]) + (i == j ? dbb : 0.0);
  });
  fill_symmetric(out.Ncc, [&](int i, int j) {
    return acc * M[i + 3 * j] + (y2[i] * pc[j] + pc[i] * y2[j]) + (i == j ? dcc : 0.0);
  });
  for (int k = 0; k < 9; ++k) {  // M itself is read no more: Nbc overwrites it
    const int i = k % 3, j = k / 3;
    out.Nbc[k] = abc * M[k] + (u[i] * y2[j] + y1[i] * v[j]);
  }
}

void TangentTerm::add_contracted_hessian_z(const double* w, double s, double* Z, int ldz) const {
  // The parts of contraction(), summed on the blocks of z_b and z_c.
  auto add_upper = [ldz](double* z, const double* A) {  // upper triangle of a diagonal block
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i <= j; ++i) z[i + ldz * j] += A[i + 3 * j];
  };
  auto length_q = [](double cL, const double* e, double* Q) {  // cL (I - e e^T)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) Q[i + 3 * j] = cL * ((i == j ? 1.0 : 0.0) - e[i] * e[j]);
  };
  double Q[9];
  if (dir == Dir::Constant) {  // only L varies
    const double e[3] = {eL_[0], eL_[1], eL_[2]};
    length_q(s * sigma * dot3(w, uhat_) / L_, e, Q);
    add_upper(Z + 3 * (q - 1) + ldz * 3 * (q - 1), Q);
    return;
  }
  Contraction parts;
  contraction(w, s, parts);
  length_q(parts.cL, parts.e, Q);
  const double* e = parts.e;
  double Bbb[9], Bbc[9], Bcc[9];
  const bool chord = dir == Dir::Chord;
  for (int k = 0; k < 9; ++k) {
    Bbb[k] = parts.Nbb[k];
    Bbc[k] = chord ? parts.Nbb[k] : parts.Nbc[k];
    Bcc[k] = chord ? parts.Nbb[k] : parts.Ncc[k];
  }
  const double* Gb = parts.Gb;
  const double* Gc = chord ? parts.Gb : parts.Gc;
  // The dL and d2L terms on q's row and column.
  if (q == b) {
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        Bbb[i + 3 * j] += (e[i] * Gb[j] + Gb[i] * e[j]) + Q[i + 3 * j];
        Bbc[i + 3 * j] += e[i] * Gc[j];
      }
  } else {
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        Bcc[i + 3 * j] += (e[i] * Gc[j] + Gc[i] * e[j]) + Q[i + 3 * j];
        Bbc[i + 3 * j] += Gb[i] * e[j];
      }
  }
  double* zbb = Z + 3 * (b - 1) + ldz * 3 * (b - 1);
  add_upper(zbb, Bbb);
  add_upper(zbb + 3 + 3 * ldz, Bcc);
  double* zbc = zbb + 3 * ldz;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) zbc[i + ldz * j] += Bbc[i + 3 * j];
}

}  // namespace curve
}  // namespace b2b
