#include "tangent_assembly.hpp"

#include <cstring>

#include "../common/finite.hpp"
#include "normal_tangent.hpp"

namespace b2b {
namespace pair {
namespace {

// K[r][c] = K[c][r] below the diagonal: the lower triangle becomes a copy of
// the upper one.
void mirror_upper(double* K, int n, int ld) {
  for (int c = 0; c < n; ++c)
    for (int r = c + 1; r < n; ++r) K[r + ld * c] = K[c + ld * r];
}

// The lower triangle of K (kNdof x kNdof) becomes a copy of the upper one,
// and whether the upper one (and so all of K) is finite: entry * 0 is 0 for
// a finite entry and NaN otherwise, summed as the entries are read. Two
// columns at a time, so that each pair read from the upper triangle is
// contiguous (K[c, r], K[c + 1, r]); one loop over the triangle instead of
// a mirror and a finiteness check each reading all of it.
bool mirror_upper_checked(double* K) {
  static_assert(kNdof % 2 == 0, "columns in pairs");
  double z0 = 0.0, z1 = 0.0;
  for (int c = 0; c < kNdof; c += 2) {
    double* k0 = K + kNdof * c;  // columns c and c + 1
    double* k1 = k0 + kNdof;
    const double u = k1[c];  // (c, c + 1)
    z0 += k0[c] * 0.0 + u * 0.0;
    z1 += k1[c + 1] * 0.0;
    k0[c + 1] = u;
    for (int r = c + 2; r < kNdof; r += 2) {  // an even count of rows: two at a time
      const double* s0 = K + kNdof * r + c;  // (c, r) and (c + 1, r)
      const double* s1 = s0 + kNdof;         // (c, r + 1) and (c + 1, r + 1)
      const double x0 = s0[0], x1 = s0[1], y0 = s1[0], y1 = s1[1];
      k0[r] = x0;
      k0[r + 1] = y0;
      k1[r] = x1;
      k1[r + 1] = y1;
      z0 += x0 * 0.0 + y0 * 0.0;
      z1 += x1 * 0.0 + y1 * 0.0;
    }
  }
  return z0 + z1 == 0.0;
}

// K (zeroed) at the used rows and columns from the upper triangle of the
// compact Kc, both triangles written; whether those entries are finite.
bool scatter_symmetric(const double* Kc, int m, const int* cols, double* K) {
  bool finite = true;
  for (int c = 0; c < m; ++c) {
    const double* src = Kc + kNdof * c;
    finite = finite && all_finite(src, c + 1);
    double* dst = K + kNdof * cols[c];
    double* row = K + cols[c];
    for (int r = 0; r <= c; ++r) {
      const double v = src[r];
      dst[cols[r]] = v;
      row[kNdof * cols[r]] = v;
    }
  }
  return finite;
}

}  // namespace

TangentResult assemble_tangent(const Params& params, const SegmentRef& A, const SegmentRef& B,
                               const Kinematics& k, const LawValue& law,
                               const FrictionContact& fc, const FrictionResult& fr,
                               const double* PA, const double* PAd, const double* PB,
                               const double* PBd, double* K) {
  TangentResult res;
  // dG/dX = blockdiag(n.d2x_A/dX_A^2, -n.d2x_B/dX_B^2)
  //       + [P_A,xi^T n; 0] dxi^T + [0; -P_B,eta^T n] deta^T + J^T dn/dX,
  // J = [P_A, -P_B], dn/dX = (I - n n^T)/rho (J + x_A,xi dxi^T - x_B,eta deta^T),
  // [dxi; deta] = -H^-1 B, B = d grad(phi)/dX (the orthogonality conditions).
  // Since n is normal to both tangents at the closest points, the xi and eta
  // terms fold into B^T H^-1 B / rho, which makes the normal part symmetric.
  Linearization lin;
  const ContactGeometry geo{PA,    PAd,   PB,    PBd,   k.pa.xd,    k.pb.xd,
                            k.d,   k.n,   k.h11, k.h12, k.h22,      k.det,
                            k.inv_unit, k.held_a,     k.held_b};
  linearize(curve::used_slots(A.kind, A.start_rule, A.end_rule),
            curve::used_slots(B.kind, B.start_rule, B.end_rule), geo, lin);
  const int m = lin.m;
  const int* cols = lin.cols;
  const double f = law.force, fp = law.slope;
  const bool friction = params.friction > 0.0;
  const bool normal_symmetric = k.rho_signed != 0.0;
  res.symmetric = normal_symmetric && !friction;
  const bool curved = !A.seg->linear_in_X() || !B.seg->linear_in_X();

  // The compact m x m matrix (leading dimension kNdof), K itself when every
  // column is used; otherwise the unused rows and columns of K stay zero.
  double Kbuf[kNdof * kNdof];
  double* Kc = (m == kNdof) ? K : Kbuf;
  if (m < kNdof) std::memset(K, 0, kNdof * kNdof * sizeof(double));

  if (res.symmetric) {
    // The upper triangle only, the curve Hessians on it too, then one mirror.
    normal_tangent_upper(lin, fp, f / k.rho_signed, Kc);
    if (!curved && Kc != K) {
      // Both segments linear in X (linear, midpoint): the compact triangle
      // is all there is; written to both triangles of K at once.
      res.finite = scatter_symmetric(Kc, m, cols, K);
      return res;
    }
    if (Kc != K)
      for (int c = 0; c < m; ++c) {
        double* dst = K + kNdof * cols[c];
        const double* src = Kc + kNdof * c;
        for (int r = 0; r <= c; ++r) dst[cols[r]] = src[r];
      }
    if (curved) {
      A.seg->add_contracted_hessian_upper(k.xi, k.n, -f, K, kNdof);
      B.seg->add_contracted_hessian_upper(k.eta, k.n, f, K + 12 + 12 * kNdof, kNdof);
    }
    res.finite = mirror_upper_checked(K);
    return res;
  }

  if (friction && fr.anchored) {
    // Normal and friction parts in one pass (friction.cpp).
    friction_tangent(params, fc, fr, lin, PAd, PBd, Kc);
  } else if (normal_symmetric) {
    // (Friction without an anchor: T = 0 near this configuration.)
    normal_tangent_upper(lin, fp, f / k.rho_signed, Kc);
    mirror_upper(Kc, m, kNdof);
  } else {
    // Intersecting axes: the normal is the previous one and does not rotate;
    // what is left of the closest points' motion is not symmetric.
    normal_tangent_intersecting(lin, fp, f, Kc);
  }
  // Without the curves' second derivatives the compact matrix is all of K:
  // its finiteness is K's.
  bool finite_known = false;
  if (!curved && Kc != K) {
    for (int c = 0; c < m && res.finite; ++c) res.finite = all_finite(Kc + kNdof * c, m);
    finite_known = true;
  }
  if (Kc != K)  // the used columns come in whole slots: three rows at a time
    for (int c = 0; c < m; ++c) {
      double* dst = K + kNdof * cols[c];
      const double* src = Kc + kNdof * c;
      for (int r = 0; r < m; r += 3) {
        double* d3 = dst + cols[r];
        d3[0] = src[r];
        d3[1] = src[r + 1];
        d3[2] = src[r + 2];
      }
    }
  // Curvature of the smoothed curves in X: only the node-preserving kinds
  // (and host end tangents) are nonlinear in X; the linear kind pays nothing.
  if (curved) {
    if (friction) {  // weights -f n + T on A, f n - T on B
      double wa[3], wb[3];
      for (int i = 0; i < 3; ++i) {
        wa[i] = fr.T[i] - f * k.n[i];
        wb[i] = -wa[i];
      }
      A.seg->add_contracted_hessian(k.xi, wa, 1.0, K, kNdof);
      B.seg->add_contracted_hessian(k.eta, wb, 1.0, K + 12 + 12 * kNdof, kNdof);
    } else {
      A.seg->add_contracted_hessian(k.xi, k.n, -f, K, kNdof);
      B.seg->add_contracted_hessian(k.eta, k.n, f, K + 12 + 12 * kNdof, kNdof);
    }
  }
  static_assert(kNdof * kNdof % 8 == 0, "K in eights");
  if (!finite_known) res.finite = all_finite_by_sum(K, kNdof * kNdof);
  return res;
}

}  // namespace pair
}  // namespace b2b
