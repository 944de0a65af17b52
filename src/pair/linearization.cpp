#include "linearization.hpp"

#include "../curve/vec3.hpp"

namespace b2b {
namespace pair {
namespace {

// The used columns of one beam: P, Pd its 3x12 jacobians, sign +1 for A
// (J = [P_A, -P_B]), k the first row of lin to fill. Returns the next;
// clears axial unless every column of P lies along its own axis.
template <bool kOnA>
int linearize_beam(unsigned used, const ContactGeometry& geo, double inv_det, Linearization& lin,
                   int k, bool& axial) {
  const double* P = kOnA ? geo.PA : geo.PB;
  const double* Pd = kOnA ? geo.PAd : geo.PBd;
  const double sign = kOnA ? 1.0 : -1.0;
  // Local copies: lin could alias the geometry as far as the compiler knows.
  const double n[3] = {geo.n[0], geo.n[1], geo.n[2]};
  const double ta[3] = {geo.ta[0], geo.ta[1], geo.ta[2]};
  const double tb[3] = {geo.tb[0], geo.tb[1], geo.tb[2]};
  const double d[3] = {geo.d[0], geo.d[1], geo.d[2]};
  const double h11 = geo.h11, h12 = geo.h12, h22 = geo.h22;
  for (int slot = 0; slot < 4; ++slot) {
    if (!(used & (1u << slot))) continue;
    for (int i = 0; i < 3; ++i, ++k) {
      const int cc = 3 * slot + i;
      const double* p = P + 3 * cc;
      const double* pd = Pd + 3 * cc;
      lin.cols[k] = kOnA ? cc : 12 + cc;
      const double jx = sign * p[0], jy = sign * p[1], jz = sign * p[2];
      lin.Jx[k] = jx;
      lin.Jy[k] = jy;
      lin.Jz[k] = jz;
      double b0, b1;
      const int i1 = i == 2 ? 0 : i + 1, i2 = i == 0 ? 2 : i - 1;
      const bool along_i = p[i1] == 0.0 && p[i2] == 0.0;
      axial = axial && along_i;
      if (along_i && pd[i1] == 0.0 && pd[i2] == 0.0) {
        // A column along axis i (every column of a segment linear in X):
        // the products with the zeros drop out of the dot products.
        const double pi = p[i], qi = pd[i];
        lin.g[k] = n[i] * (sign * pi);
        if (kOnA) {
          b0 = pi * ta[i] + qi * d[i];
          b1 = -(pi * tb[i]);
          lin.av[k] = qi * n[i];
          lin.bv[k] = 0.0;
        } else {
          b0 = -(pi * ta[i]);
          b1 = pi * tb[i] - qi * d[i];
          lin.av[k] = 0.0;
          lin.bv[k] = -(qi * n[i]);
        }
      } else if (kOnA) {
        lin.g[k] = n[0] * jx + n[1] * jy + n[2] * jz;
        b0 = curve::dot3(p, ta) + curve::dot3(pd, d);
        b1 = -curve::dot3(p, tb);
        lin.av[k] = curve::dot3(pd, n);
        lin.bv[k] = 0.0;
      } else {
        lin.g[k] = n[0] * jx + n[1] * jy + n[2] * jz;
        b0 = -curve::dot3(p, ta);
        b1 = curve::dot3(p, tb) - curve::dot3(pd, d);
        lin.av[k] = 0.0;
        lin.bv[k] = -curve::dot3(pd, n);
      }
      lin.B0[k] = b0;
      lin.B1[k] = b1;
      lin.C0[k] = geo.fixed_xi ? 0.0 : (h22 * b0 - h12 * b1) * inv_det;  // H^-1 B
      lin.C1[k] = geo.fixed_eta ? 0.0 : (h11 * b1 - h12 * b0) * inv_det;
    }
  }
  return k;
}

}  // namespace

void linearize(unsigned used_a, unsigned used_b, const ContactGeometry& geo, Linearization& lin) {
  const double inv_det = geo.inv_unit * geo.inv_unit / geo.det;  // H is in units of unit^2
  for (int i = 0; i < 3; ++i) lin.n[i] = geo.n[i];
  bool axial = true;
  const int m = linearize_beam<true>(used_a, geo, inv_det, lin, 0, axial);
  lin.m = linearize_beam<false>(used_b, geo, inv_det, lin, m, axial);
  lin.axial = axial;
}

}  // namespace pair
}  // namespace b2b
