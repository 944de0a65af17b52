#include "normal_tangent.hpp"

namespace b2b {
namespace pair {

void normal_tangent_upper(const Linearization& lin, double fp, double f_over_rho, double* Kc) {
  const int m = lin.m;
  const double *g = lin.g, *Jx = lin.Jx, *Jy = lin.Jy, *Jz = lin.Jz;
  const double *B0 = lin.B0, *B1 = lin.B1;
  for (int c = 0; c < m; ++c) {
    const double gc = fp * g[c], jx = Jx[c], jy = Jy[c], jz = Jz[c], nc = g[c], c0 = lin.C0[c],
                 c1 = lin.C1[c];
    double* col = Kc + kNdof * c;
    for (int r = 0; r <= c; ++r) {
      const double jqj = Jx[r] * jx + Jy[r] * jy + Jz[r] * jz - g[r] * nc;
      const double bhb = B0[r] * c0 + B1[r] * c1;
      col[r] = -g[r] * gc - f_over_rho * (jqj - bhb);
    }
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
