#include "normal_tangent.hpp"

#include <cmath>

#include "../curve/vec3.hpp"

namespace b2b {
namespace pair {

namespace {

// Rows 0..c of column c, rounded up to an even count (at most m): the
// vectorised loop then needs no scalar remainder, and the one entry below
// the diagonal it writes is overwritten by the caller's mirror (or not read).
inline int upper_rows(int c, int m) {
  const int r = (c + 2) & ~1;
  return r < m ? r : m;
}

// col[r] = sum of the rank-one terms' row vectors times their factors, r < rows.
void upper_column(int rows, const double* __restrict v0, const double* __restrict v1,
                  const double* __restrict v2, const double* __restrict v3, double a0,
                  double a1, double a2, double a3, double* __restrict col) {
  for (int r = 0; r < rows; ++r) col[r] = v0[r] * a0 + v1[r] * a1 + v2[r] * a2 + v3[r] * a3;
}
void upper_column(int rows, const double* __restrict v0, const double* __restrict v1,
                  const double* __restrict v2, const double* __restrict v3,
                  const double* __restrict v4, double a0, double a1, double a2, double a3,
                  double a4, double* __restrict col) {
  for (int r = 0; r < rows; ++r)
    col[r] = v0[r] * a0 + v1[r] * a1 + v2[r] * a2 + v3[r] * a3 + v4[r] * a4;
}

// Two columns at once (c even and c + 1 share their rows 0..c+1): each
// row's five values are loaded once for both columns. The row loop unrolled
// twice: half its loop overhead (four times: more set-up than it saves on
// the short columns).
void upper_columns2(int rows, const double* __restrict v0, const double* __restrict v1,
                    const double* __restrict v2, const double* __restrict v3,
                    const double* __restrict v4, const double* a, const double* b,
                    double* __restrict col0, double* __restrict col1) {
  const double a0 = a[0], a1 = a[1], a2 = a[2], a3 = a[3], a4 = a[4];
  const double b0 = b[0], b1 = b[1], b2 = b[2], b3 = b[3], b4 = b[4];
#pragma GCC unroll 2
  for (int r = 0; r < rows; ++r) {
    const double x0 = v0[r], x1 = v1[r], x2 = v2[r], x3 = v3[r], x4 = v4[r];
    col0[r] = x0 * a0 + x1 * a1 + x2 * a2 + x3 * a3 + x4 * a4;
    col1[r] = x0 * b0 + x1 * b1 + x2 * b2 + x3 * b3 + x4 * b4;
  }
}

}  // namespace

void normal_tangent_upper(const Linearization& lin, double fp, double f_over_rho, double* Kc) {
  // K = -fp g g^T - s J^T (I - n n^T) J + s B^T H^-1 B, s = f/rho, as a sum of
  // rank-one terms, rows times columns, with B^T H^-1 B = B0 C0^T + B1 C1^T.
  // The loop over the upper triangle is bound by its floating-point
  // operations (the direct form J^T J - g g^T took fourteen per entry):
  //  - every column of J along one axis (both segments linear in X): column c
  //    of J^T J is J_i J_ic with i = cols[c] % 3, and J^T (I - n n^T) J =
  //    J^T J - g g^T: four terms, seven operations;
  //  - otherwise I - n n^T = (e e^T + e' e'^T) / |e|^2 with e = n x (the axis
  //    along which n is smallest), e' = n x e (|e'| = |e|, |e|^2 >= 2/3):
  //    J^T (I - n n^T) J = (p1 p1^T + p2 p2^T) / |e|^2, p1 = J^T e,
  //    p2 = J^T e': five terms, nine operations.
  const int m = lin.m;
  const double s = f_over_rho;
  const double *g = lin.g, *Jx = lin.Jx, *Jy = lin.Jy, *Jz = lin.Jz, *B0 = lin.B0, *B1 = lin.B1;
  if (lin.axial) {
    const double* Jrow[3] = {Jx, Jy, Jz};
    const double sg = s - fp;
    for (int c = 0; c < m; ++c) {
      const double* Ji = Jrow[lin.cols[c] % 3];
      const double a0 = sg * g[c], a1 = -s * Ji[c], a2 = s * lin.C0[c], a3 = s * lin.C1[c];
      upper_column(upper_rows(c, m), g, Ji, B0, B1, a0, a1, a2, a3, Kc + kNdof * c);
    }
    return;
  }
  const double* n = lin.n;
  const double ax = std::fabs(n[0]), ay = std::fabs(n[1]), az = std::fabs(n[2]);
  double e[3];
  if (ax <= ay && ax <= az) {  // n x e_x
    e[0] = 0.0;
    e[1] = n[2];
    e[2] = -n[1];
  } else if (ay <= az) {  // n x e_y
    e[0] = -n[2];
    e[1] = 0.0;
    e[2] = n[0];
  } else {  // n x e_z
    e[0] = n[1];
    e[1] = -n[0];
    e[2] = 0.0;
  }
  double f[3];
  curve::cross3(n, e, f);
  const double sq = -s / (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  double p1[kNdof], p2[kNdof];
  for (int k = 0; k < m; ++k) {
    p1[k] = e[0] * Jx[k] + e[1] * Jy[k] + e[2] * Jz[k];
    p2[k] = f[0] * Jx[k] + f[1] * Jy[k] + f[2] * Jz[k];
  }
  int c = 0;
  for (; c + 1 < m; c += 2) {
    const double a[5] = {-fp * g[c], sq * p1[c], sq * p2[c], s * lin.C0[c], s * lin.C1[c]};
    const double b[5] = {-fp * g[c + 1], sq * p1[c + 1], sq * p2[c + 1], s * lin.C0[c + 1],
                         s * lin.C1[c + 1]};
    upper_columns2(c + 2, g, p1, p2, B0, B1, a, b, Kc + kNdof * c, Kc + kNdof * (c + 1));
  }
  if (c < m) {
    const double a0 = -fp * g[c], a1 = sq * p1[c], a2 = sq * p2[c], a3 = s * lin.C0[c],
                 a4 = s * lin.C1[c];
    upper_column(upper_rows(c, m), g, p1, p2, B0, B1, a0, a1, a2, a3, a4, Kc + kNdof * c);
  }
}

void normal_tangent_intersecting(const Linearization& lin, double fp, double f, double* Kc) {
  const int m = lin.m;
  for (int c = 0; c < m; ++c)
    for (int r = 0; r < m; ++r)
      Kc[r + kNdof * c] = -fp * lin.g[r] * lin.g[c] + f * (lin.av[r] * lin.C0[c] + lin.bv[r] * lin.C1[c]);
}

}  // namespace pair
}  // namespace b2b
