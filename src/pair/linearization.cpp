#include "linearization.hpp"

#include "../curve/vec3.hpp"

namespace b2b {
namespace pair {
namespace {

// Column c of a 3 x 12 column-major matrix dotted with v.
inline double col_dot(const double* M, int c, const double* v) { return curve::dot3(M + 3 * c, v); }

}  // namespace

void linearize(unsigned used_a, unsigned used_b, const ContactGeometry& geo, Linearization& lin) {
  const unsigned used[2] = {used_a, used_b};
  int m = 0;
  for (int beam = 0; beam < 2; ++beam)
    for (int slot = 0; slot < 4; ++slot)
      if (used[beam] & (1u << slot))
        for (int i = 0; i < 3; ++i) lin.cols[m++] = 12 * beam + 3 * slot + i;
  lin.m = m;

  const double* n = geo.n;
  const double inv_det = geo.inv_unit * geo.inv_unit / geo.det;  // H is in units of unit^2
  for (int k = 0; k < m; ++k) {
    const int c = lin.cols[k];
    const bool on_a = c < 12;
    const int cc = on_a ? c : c - 12;
    const double* P = on_a ? geo.PA : geo.PB;
    const double sign = on_a ? 1.0 : -1.0;
    lin.Jx[k] = sign * P[3 * cc];
    lin.Jy[k] = sign * P[1 + 3 * cc];
    lin.Jz[k] = sign * P[2 + 3 * cc];
    lin.g[k] = n[0] * lin.Jx[k] + n[1] * lin.Jy[k] + n[2] * lin.Jz[k];
    if (on_a) {
      lin.B0[k] = col_dot(geo.PA, cc, geo.ta) + col_dot(geo.PAd, cc, geo.d);
      lin.B1[k] = -col_dot(geo.PA, cc, geo.tb);
      lin.av[k] = col_dot(geo.PAd, cc, n);
      lin.bv[k] = 0.0;
    } else {
      lin.B0[k] = -col_dot(geo.PB, cc, geo.ta);
      lin.B1[k] = col_dot(geo.PB, cc, geo.tb) - col_dot(geo.PBd, cc, geo.d);
      lin.av[k] = 0.0;
      lin.bv[k] = -col_dot(geo.PBd, cc, n);
    }
    lin.C0[k] = (geo.h22 * lin.B0[k] - geo.h12 * lin.B1[k]) * inv_det;  // H^-1 B
    lin.C1[k] = (geo.h11 * lin.B1[k] - geo.h12 * lin.B0[k]) * inv_det;
  }
}

}  // namespace pair
}  // namespace b2b
