#include "linearization.hpp"

#include "../curve/vec3.hpp"

namespace b2b {
namespace pair {
namespace {

// The used columns of one beam (P, Pd its 3x12 jacobians; J = [P_A, -P_B]),
// from row k of lin on: their indices, J and Q (the columns of Pd), as
// rows of the compact arrays. Returns the next row; clears axial unless
// every column of P lies along its own axis.
template <bool kOnA>
int gather_beam(unsigned used, const double* P, const double* Pd, Linearization& lin, int k,
                bool& axial) {
  const double sign = kOnA ? 1.0 : -1.0;
  for (int slot = 0; slot < 4; ++slot) {
    if (!(used & (1u << slot))) continue;
    for (int i = 0; i < 3; ++i, ++k) {
      const int cc = 3 * slot + i;
      const double* p = P + 3 * cc;
      const double* pd = Pd + 3 * cc;
      lin.cols[k] = kOnA ? cc : 12 + cc;
      lin.Jx[k] = sign * p[0];
      lin.Jy[k] = sign * p[1];
      lin.Jz[k] = sign * p[2];
      lin.Qx[k] = pd[0];
      lin.Qy[k] = pd[1];
      lin.Qz[k] = pd[2];
      const int i1 = i == 2 ? 0 : i + 1, i2 = i == 0 ? 2 : i - 1;
      axial = axial && p[i1] == 0.0 && p[i2] == 0.0;
    }
  }
  return k;
}

// Rows [k0, k1) of one beam, all products on the compact rows (they
// vectorise): g = n.J, B = d(grad phi)/dX,
//   A: B0 = J.ta + Pd.d, B1 = -J.tb,        av = Pd.n
//   B: B0 = J.ta,        B1 = -J.tb - Pd.d, bv = -Pd.n
// (J = -P_B on B: -P_B.ta is J.ta exactly), and C = H^-1 B.
template <bool kOnA>
void linearize_rows(const ContactGeometry& geo, double inv_det, int k0, int k1,
                    Linearization& lin) {
  const double n0 = geo.n[0], n1 = geo.n[1], n2 = geo.n[2];
  const double ta0 = geo.ta[0], ta1 = geo.ta[1], ta2 = geo.ta[2];
  const double tb0 = geo.tb[0], tb1 = geo.tb[1], tb2 = geo.tb[2];
  const double d0 = geo.d[0], d1 = geo.d[1], d2 = geo.d[2];
  const double h11 = geo.h11, h12 = geo.h12, h22 = geo.h22;
  const double c0 = geo.fixed_xi ? 0.0 : inv_det, c1 = geo.fixed_eta ? 0.0 : inv_det;
  const double* __restrict Jx = lin.Jx;
  const double* __restrict Jy = lin.Jy;
  const double* __restrict Jz = lin.Jz;
  const double* __restrict qx = lin.Qx;
  const double* __restrict qy = lin.Qy;
  const double* __restrict qz = lin.Qz;
  double* __restrict g = lin.g;
  double* __restrict B0 = lin.B0;
  double* __restrict B1 = lin.B1;
  double* __restrict C0 = lin.C0;
  double* __restrict C1 = lin.C1;
  double* __restrict av = lin.av;
  double* __restrict bv = lin.bv;
  for (int k = k0; k < k1; ++k) {
    const double jx = Jx[k], jy = Jy[k], jz = Jz[k];
    const double qd = qx[k] * d0 + qy[k] * d1 + qz[k] * d2;
    const double qn = qx[k] * n0 + qy[k] * n1 + qz[k] * n2;
    g[k] = n0 * jx + n1 * jy + n2 * jz;
    const double jta = jx * ta0 + jy * ta1 + jz * ta2;
    const double jtb = -(jx * tb0 + jy * tb1 + jz * tb2);
    const double b0 = kOnA ? jta + qd : jta;
    const double b1 = kOnA ? jtb : jtb - qd;
    B0[k] = b0;
    B1[k] = b1;
    av[k] = kOnA ? qn : 0.0;
    bv[k] = kOnA ? 0.0 : -qn;
    C0[k] = (h22 * b0 - h12 * b1) * c0;  // H^-1 B; zero for a held parameter
    C1[k] = (h11 * b1 - h12 * b0) * c1;
  }
}

}  // namespace

void linearize(unsigned used_a, unsigned used_b, const ContactGeometry& geo, Linearization& lin) {
  const double inv_det = geo.inv_unit * geo.inv_unit / geo.det;  // H is in units of unit^2
  for (int i = 0; i < 3; ++i) lin.n[i] = geo.n[i];
  bool axial = true;
  const int ma = gather_beam<true>(used_a, geo.PA, geo.PAd, lin, 0, axial);
  lin.m_a = ma;
  lin.used_a = used_a;
  lin.used_b = used_b;
  lin.m = gather_beam<false>(used_b, geo.PB, geo.PBd, lin, ma, axial);
  lin.axial = axial;
  linearize_rows<true>(geo, inv_det, 0, ma, lin);
  linearize_rows<false>(geo, inv_det, ma, lin.m, lin);
}

}  // namespace pair
}  // namespace b2b
