#include "tangent_assembly.hpp"

#include <cstring>

#include "../common/finite.hpp"
#include "normal_tangent.hpp"
#include "tangent_mirror.hpp"

namespace b2b {
namespace pair {
namespace {

// The compact m x m Kc (leading dimension kNdof) into the rows and columns
// cols of dst (leading dimension ld), which are not otherwise written. The
// used columns come in whole slots: three rows at a time.
void scatter_compact(const double* Kc, int m, const int* cols, double* dst, int ld) {
  for (int c = 0; c < m; ++c) {
    double* col = dst + static_cast<size_t>(ld) * cols[c];
    const double* src = Kc + kNdof * c;
    for (int r = 0; r < m; r += 3) {
      double* d3 = col + cols[r];
      d3[0] = src[r];
      d3[1] = src[r + 1];
      d3[2] = src[r + 2];
    }
  }
}

}  // namespace

void expand_tangent(const double* K, const TangentColumns& used, double* dst, int ld) {
  if (used.m == kNdof && ld == kNdof) {
    std::memcpy(dst, K, kNdof * kNdof * sizeof(double));
    return;
  }
  if (used.m == kNdof) {
    for (int c = 0; c < kNdof; ++c)
      std::memcpy(dst + static_cast<size_t>(ld) * c, K + kNdof * c, kNdof * sizeof(double));
    return;
  }
  if (ld == kNdof)
    std::memset(dst, 0, kNdof * kNdof * sizeof(double));
  else
    for (int c = 0; c < kNdof; ++c)
      std::memset(dst + static_cast<size_t>(ld) * c, 0, kNdof * sizeof(double));
  scatter_compact(K, used.m, used.cols, dst, ld);
}

TangentResult assemble_tangent(const Params& params, const SegmentRef& A, const SegmentRef& B,
                               const Kinematics& k, const LawValue& law,
                               const FrictionContact& fc, const FrictionResult& fr,
                               const double* PA, const double* PAd, const double* PB,
                               const double* PBd, double* K, TangentColumns* compact) {
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

  // The compact m x m matrix (leading dimension kNdof): K itself when every
  // column is used or when the caller takes it compact (TangentColumns),
  // otherwise a buffer scattered into K, whose unused rows and columns stay
  // zero.
  const bool keep_compact = compact != nullptr && !curved && m < kNdof;
  if (compact) {
    compact->m = keep_compact ? m : kNdof;
    if (keep_compact) std::memcpy(compact->cols, cols, m * sizeof(int));
  }
  double Kbuf[kNdof * kNdof];
  double* Kc = (m == kNdof || keep_compact) ? K : Kbuf;
  if (Kc != K) std::memset(K, 0, kNdof * kNdof * sizeof(double));

  if (res.symmetric) {
    // The upper triangle only, the curve Hessians on it too, then one mirror.
    normal_tangent_upper(lin, fp, f / k.rho_signed, Kc);
    if (!curved && m < kNdof) {
      // Both segments linear in X (linear, midpoint): the compact matrix is
      // all there is, left compact or scattered into K.
      res.finite = mirror_compact_checked(Kc, m);
      if (!keep_compact) scatter_compact(Kc, m, cols, K, kNdof);
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
  if (!curved && m < kNdof) {
    for (int c = 0; c < m && res.finite; ++c) res.finite = all_finite(Kc + kNdof * c, m);
    if (keep_compact) return res;
    finite_known = true;
  }
  if (Kc != K) scatter_compact(Kc, m, cols, K, kNdof);
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
