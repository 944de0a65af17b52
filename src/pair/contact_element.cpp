#include "contact_element.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../common/finite.hpp"
#include "../curve/vec3.hpp"
#include "closest_point.hpp"
#include "friction.hpp"
#include "normal_law.hpp"
#include "normal_tangent.hpp"

namespace b2b {
namespace pair {
namespace {

using curve::cross3;
using curve::dot3;
using curve::max_abs3;
using curve::norm3;
using curve::sub3;

constexpr double kJointBand = 1e-13;  // "on a joint": within this many segment lengths
constexpr double kPi = 3.14159265358979323846;

// Whether a segment owns the closest point at parameter t (see b2b_pair.h):
// [-1, 1), the end joint going to the next segment unless the beam ends there.
bool owns(double t, double speed, double length, bool beam_ends_here) {
  const double band = kJointBand * length;
  if (std::fabs(t + 1.0) * speed <= band) return true;
  if (std::fabs(t - 1.0) * speed <= band) return beam_ends_here;
  return t > -1.0 && t < 1.0;
}

// Column c of a 3 x 12 column-major matrix dotted with v.
inline double col_dot(const double* M, int c, const double* v) { return dot3(M + 3 * c, v); }

struct PointState {
  double x[3], xd[3], xdd[3];
};

}  // namespace

PairFailure evaluate_pair(const Params& params, const SegmentInput& A, const SegmentInput& B,
                          const double* hist_old, PairResult& out, double* K) {
  PairFailure fail;
  curve::Segment sa, sb;
  fail.segment = sa.build(A.kind, A.start_rule, A.end_rule, A.X, A.unit_tangents, true);
  if (fail.segment.status) {
    fail.status = fail.segment.status;
    fail.beam = 0;
    return fail;
  }
  fail.segment = sb.build(B.kind, B.start_rule, B.end_rule, B.X, B.unit_tangents, true);
  if (fail.segment.status) {
    fail.status = fail.segment.status;
    fail.beam = 1;
    return fail;
  }

  out = PairResult();
  const int hist_len = history_length(params);
  std::memcpy(out.history, hist_old, hist_len * sizeof(double));
  // Friction history is that of the committed step only if this pair is
  // active now (set below); a pair without force forgets it.
  for (int i = kHistoryLength; i < hist_len; ++i) out.history[i] = 0.0;
  // K is zero unless the pair is active; an active pair with all 24 columns
  // in use overwrites all of it, so zero it only where that is not so.
  auto zero_K = [K]() {
    if (K) std::memset(K, 0, kNdof * kNdof * sizeof(double));
  };
  // A pair that carries no force: its status, zero residual (already) and K.
  auto no_force = [&](int status) {
    out.contact_status = status;
    zero_K();
    return fail;
  };
  double* info = out.info;
  info[B2B_INFO_SYMMETRIC] = 1.0;

  // Length scales: segment chords, and the coordinates' magnitude (rounding).
  const double *a0 = sa.start_point(), *a1 = sa.end_point();
  const double *b0 = sb.start_point(), *b1 = sb.end_point();
  double t[3];
  sub3(a1, a0, t);
  const double len_a = norm3(t);
  sub3(b1, b0, t);
  const double len_b = norm3(t);
  const double coord = std::fmax(std::fmax(max_abs3(a0), max_abs3(a1)),
                                 std::fmax(max_abs3(b0), max_abs3(b1)));
  const double tol_length = 1e-13 * (len_a + len_b) + 64.0 * DBL_EPSILON * coord;
  // The length unit of the closest-point algebra below: products of four
  // lengths (the Hessian's determinant) stay in range for any coordinates.
  const double unit = len_a + len_b;
  const double inv_unit = 1.0 / unit;

  // Closest points.
  const bool has_history = hist_old[kHistTag] == kHistTagV1;
  const bool has_normal = has_history && hist_old[kHistHasNormal] == 1.0;
  double xi0, eta0;
  if (params.warm_start && has_history) {
    xi0 = std::fmin(1.0, std::fmax(-1.0, hist_old[kHistXi]));
    eta0 = std::fmin(1.0, std::fmax(-1.0, hist_old[kHistEta]));
  } else {
    chord_start(a0, a1, b0, b1, unit, &xi0, &eta0);
  }
  const ClosestPoints cp =
      closest_points(sa, sb, xi0, eta0, params.max_iterations, tol_length, unit);
  const double xi = cp.xi, eta = cp.eta;
  info[B2B_INFO_XI] = xi;
  info[B2B_INFO_ETA] = eta;
  info[B2B_INFO_ITERATIONS] = cp.iterations;
  if (!cp.converged) {
    // An iteration that ran off the segment looked for a point that is not
    // this pair's; otherwise the search failed.
    const bool ran_off = std::fabs(xi) > 1.0 || std::fabs(eta) > 1.0;
    return no_force(ran_off ? B2B_CONTACT_OUTSIDE : B2B_CONTACT_NOT_CONVERGED);
  }
  PointState pa, pb;
  sa.point(xi, pa.x, pa.xd, pa.xdd);
  sb.point(eta, pb.x, pb.xd, pb.xdd);
  for (int i = 0; i < 3; ++i) {
    info[B2B_INFO_POINT_A + i] = pa.x[i];
    info[B2B_INFO_POINT_B + i] = pb.x[i];
  }

  // Crossing angle, and the Hessian of phi at the solution, in units of
  // `unit` (h11, h12, h22 scale like length^2, det like length^4).
  double ta[3], tb[3], tad[3], tbd[3], d[3], du[3];
  for (int i = 0; i < 3; ++i) {
    ta[i] = pa.xd[i] * inv_unit;
    tb[i] = pb.xd[i] * inv_unit;
    tad[i] = pa.xdd[i] * inv_unit;
    tbd[i] = pb.xdd[i] * inv_unit;
    d[i] = pa.x[i] - pb.x[i];
    du[i] = d[i] * inv_unit;
  }
  const double na = norm3(ta), nb = norm3(tb);
  double cr[3];
  cross3(ta, tb, cr);
  const double sin_angle = norm3(cr) / (na * nb);
  const double cos_angle = std::fabs(dot3(ta, tb)) / (na * nb);
  info[B2B_INFO_ANGLE] = std::atan2(sin_angle, cos_angle) * 180.0 / kPi;
  const double h11 = dot3(ta, ta) + dot3(du, tad);
  const double h22 = dot3(tb, tb) - dot3(du, tbd);
  const double h12 = -dot3(ta, tb);
  const double det = h11 * h22 - h12 * h12;
  if (sin_angle < params.sin_parallel_angle || !(det > 1e-12 * na * na * nb * nb)) {
    return no_force(B2B_CONTACT_PARALLEL);
  }

  // Sign-tracked normal and gap.
  const double rho = norm3(d);
  double n[3], rho_signed = 0.0;  // rho_signed = 0: the normal does not rotate (see below)
  double gap;
  if (rho <= tol_length) {
    // The axes intersect: the normal is undefined, use the previous one.
    if (!has_normal) {
      return no_force(B2B_CONTACT_NO_NORMAL);
    }
    for (int i = 0; i < 3; ++i) n[i] = hist_old[kHistNormal + i];
    gap = -A.radius - B.radius;
  } else {
    const double sign = (has_normal && dot3(d, hist_old + kHistNormal) < 0.0) ? -1.0 : 1.0;
    rho_signed = sign * rho;
    for (int i = 0; i < 3; ++i) n[i] = d[i] / rho_signed;
    gap = rho_signed - A.radius - B.radius;
  }
  for (int i = 0; i < 3; ++i) info[B2B_INFO_NORMAL + i] = n[i];
  info[B2B_INFO_GAP] = gap;
  out.history[kHistTag] = kHistTagV1;
  out.history[kHistHasNormal] = 1.0;
  for (int i = 0; i < 3; ++i) out.history[kHistNormal + i] = n[i];
  out.history[kHistXi] = xi;
  out.history[kHistEta] = eta;

  if (!owns(xi, na * unit, len_a, A.end_rule != B2B_END_NEIGHBOUR) ||
      !owns(eta, nb * unit, len_b, B.end_rule != B2B_END_NEIGHBOUR)) {
    return no_force(B2B_CONTACT_OUTSIDE);
  }
  const LawValue law = normal_law(params, gap);
  info[B2B_INFO_NORMAL_FORCE] = law.force;
  info[B2B_INFO_ENERGY] = law.energy;
  if (!(law.force > 0.0)) {
    return no_force(B2B_CONTACT_OPEN);
  }
  out.contact_status = B2B_CONTACT_ACTIVE;

  // Residual: -f_N dg/dX with dg/dX = G = [P_A^T n; -P_B^T n] (the xi, eta
  // terms vanish by orthogonality).
  double PA[36], PAd[36], PB[36], PBd[36], G[kNdof];
  sa.jacobians(xi, PA, PAd);
  sb.jacobians(eta, PB, PBd);
  for (int c = 0; c < 12; ++c) {
    G[c] = col_dot(PA, c, n);
    G[12 + c] = -col_dot(PB, c, n);
  }
  for (int c = 0; c < kNdof; ++c) out.residual[c] = -law.force * G[c];

  // Friction: + [P_A^T T; -P_B^T T]. mu = 0 skips all of it.
  const bool friction = params.friction > 0.0;
  FrictionContact fc{&sa, &sb, xi, eta, pa.xd, pa.xdd, pb.xd, n, rho_signed, law.force, law.slope};
  FrictionResult fr;
  if (friction) {
    fr = friction_force(params, fc, hist_old);
    for (int c = 0; c < 12; ++c) {
      out.residual[c] += col_dot(PA, c, fr.T);
      out.residual[12 + c] -= col_dot(PB, c, fr.T);
    }
    for (int i = 0; i < 3; ++i) {
      info[B2B_INFO_TANGENTIAL_FORCE + i] = fr.T[i];
      info[B2B_INFO_SLIP + i] = fr.slip[i];
    }
    info[B2B_INFO_FRICTION_STATE] = fr.state;
    info[B2B_INFO_DISSIPATION] = fr.dissipation;
    info[B2B_INFO_SYMMETRIC] = 0.0;
    out.history[kHistInContact] = 1.0;
    out.history[kHistForceE1] = fr.force_e1;
    out.history[kHistForceE2] = fr.force_e2;
    out.history[kHistFrictionState] = fr.state;
  }
  // A huge penalty times a deep penetration can exceed the double range (the
  // energy grows like penalty * gap^2); the caller reports it.
  out.overflow = !all_finite(out.info, kInfoLength) || !all_finite(out.residual, kNdof) ||
                 !all_finite(out.history, hist_len);
  if (!K) return fail;

  // Tangent K = -f' G G^T - f dG/dX with (all total derivatives in X)
  //   dG/dX = blockdiag(n.d2x_A/dX_A^2, -n.d2x_B/dX_B^2)
  //         + [P_A,xi^T n; 0] dxi^T + [0; -P_B,eta^T n] deta^T + J^T dn/dX,
  //   J = [P_A, -P_B], dn/dX = (I - n n^T)/rho (J + x_A,xi dxi^T - x_B,eta deta^T),
  //   [dxi; deta] = -H^-1 B, B = d grad(phi)/dX (the orthogonality conditions).
  // Since n is normal to both tangents at the closest points, the xi and eta
  // terms fold into B^T/rho, and
  //   K = -f' G G^T - f blockdiag(...) - (f/rho) (J^T (I - n n^T) J - B^T H^-1 B),
  // symmetric: computed on one triangle, over the columns of used slots only.
  // Friction adds its own, non-symmetric, part (friction.hpp).
  Linearization lin;
  const ContactGeometry geo{PA, PAd, PB, PBd, pa.xd, pb.xd, d, n, h11, h12, h22, det, inv_unit};
  linearize(curve::used_slots(A.kind, A.start_rule, A.end_rule),
            curve::used_slots(B.kind, B.start_rule, B.end_rule), geo, lin);
  const int m = lin.m;
  const int* cols = lin.cols;
  const double f = law.force, fp = law.slope;
  // compact m x m, leading dimension kNdof; K itself when all columns are used
  double Kbuf[kNdof * kNdof];
  double* Kc = (m == kNdof) ? K : Kbuf;
  if (m < kNdof) zero_K();  // the unused rows and columns stay zero
  const bool normal_symmetric = rho_signed != 0.0;
  const bool curved = !sa.linear_in_X() || !sb.linear_in_X();
  if (normal_symmetric) {  // the upper triangle; mirrored below
    normal_tangent_upper(lin, fp, f / rho_signed, Kc);
  } else {
    // Intersecting axes: the normal is the previous one and does not rotate;
    // what is left of the closest points' motion is not symmetric.
    info[B2B_INFO_SYMMETRIC] = 0.0;
    normal_tangent_intersecting(lin, fp, f, Kc);
  }
  // Exactly symmetric: the lower triangle is a copy of the upper one. Where
  // curve Hessians are added below (symmetric only up to rounding), the copy
  // is made after them, on the whole matrix; with friction it is made now,
  // before the non-symmetric friction part.
  const bool mirror_now = normal_symmetric && (!curved || friction);
  if (mirror_now)
    for (int c = 0; c < m; ++c)
      for (int r = c + 1; r < m; ++r) Kc[r + kNdof * c] = Kc[c + kNdof * r];
  if (friction) add_friction_tangent(params, fc, fr, lin, PAd, PBd, Kc);
  const bool symmetric = normal_symmetric && !friction;
  // When symmetric the upper triangle is all there is (the lower one is or
  // will be its copy).
  bool finite = true;
  for (int c = 0; c < m && finite; ++c) finite = all_finite(Kc + kNdof * c, symmetric ? c + 1 : m);
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
        wa[i] = fr.T[i] - f * n[i];
        wb[i] = -wa[i];
      }
      sa.add_contracted_hessian(xi, wa, 1.0, K, kNdof);
      sb.add_contracted_hessian(eta, wb, 1.0, K + 12 + 12 * kNdof, kNdof);
    } else if (symmetric) {  // the upper triangle; mirrored below
      sa.add_contracted_hessian_upper(xi, n, -f, K, kNdof);
      sb.add_contracted_hessian_upper(eta, n, f, K + 12 + 12 * kNdof, kNdof);
    } else {
      sa.add_contracted_hessian(xi, n, -f, K, kNdof);
      sb.add_contracted_hessian(eta, n, f, K + 12 + 12 * kNdof, kNdof);
    }
    if (symmetric)
      for (int c = 0; c < kNdof; ++c)
        for (int r = c + 1; r < kNdof; ++r) K[r + kNdof * c] = K[c + kNdof * r];
    for (int c = 0; c < kNdof && finite; ++c)
      finite = all_finite(K + kNdof * c, symmetric ? c + 1 : kNdof);
  }
  out.overflow = out.overflow || !finite;
  return fail;
}

}  // namespace pair
}  // namespace b2b
