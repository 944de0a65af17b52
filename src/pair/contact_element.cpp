#include "contact_element.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../curve/vec3.hpp"
#include "closest_point.hpp"
#include "normal_law.hpp"

namespace b2b {
namespace pair {
namespace {

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
  std::memcpy(out.history, hist_old, sizeof out.history);
  if (K) std::memset(K, 0, kNdof * kNdof * sizeof(double));
  double* info = out.info;
  info[B2B_INFO_SYMMETRIC] = 1.0;

  // Length scales: segment chords, and the coordinates' magnitude (rounding).
  double a0[3], a1[3], b0[3], b1[3], t[3];
  sa.point(-1.0, a0, nullptr, nullptr);
  sa.point(1.0, a1, nullptr, nullptr);
  sb.point(-1.0, b0, nullptr, nullptr);
  sb.point(1.0, b1, nullptr, nullptr);
  sub3(a1, a0, t);
  const double len_a = norm3(t);
  sub3(b1, b0, t);
  const double len_b = norm3(t);
  const double coord = std::fmax(std::fmax(max_abs3(a0), max_abs3(a1)),
                                 std::fmax(max_abs3(b0), max_abs3(b1)));
  const double tol_length = 1e-13 * (len_a + len_b) + 64.0 * DBL_EPSILON * coord;

  // Closest points.
  const bool has_history = hist_old[kHistTag] == kHistTagV1;
  const bool has_normal = has_history && hist_old[kHistHasNormal] == 1.0;
  double xi0, eta0;
  if (params.warm_start && has_history) {
    xi0 = std::fmin(1.0, std::fmax(-1.0, hist_old[kHistXi]));
    eta0 = std::fmin(1.0, std::fmax(-1.0, hist_old[kHistEta]));
  } else {
    chord_start(a0, a1, b0, b1, &xi0, &eta0);
  }
  const ClosestPoints cp = closest_points(sa, sb, xi0, eta0, params.max_iterations, tol_length);
  const double xi = cp.xi, eta = cp.eta;
  info[B2B_INFO_XI] = xi;
  info[B2B_INFO_ETA] = eta;
  info[B2B_INFO_ITERATIONS] = cp.iterations;
  if (!cp.converged) {
    // An iteration that ran off the segment looked for a point that is not
    // this pair's; otherwise the search failed.
    out.contact_status = (std::fabs(xi) > 1.0 || std::fabs(eta) > 1.0) ? B2B_CONTACT_OUTSIDE
                                                                          : B2B_CONTACT_NOT_CONVERGED;
    return fail;
  }
  PointState pa, pb;
  sa.point(xi, pa.x, pa.xd, pa.xdd);
  sb.point(eta, pb.x, pb.xd, pb.xdd);
  for (int i = 0; i < 3; ++i) {
    info[B2B_INFO_POINT_A + i] = pa.x[i];
    info[B2B_INFO_POINT_B + i] = pb.x[i];
  }

  // Crossing angle, and the Hessian of phi at the solution.
  const double na = norm3(pa.xd), nb = norm3(pb.xd);
  double cr[3];
  cr[0] = pa.xd[1] * pb.xd[2] - pa.xd[2] * pb.xd[1];
  cr[1] = pa.xd[2] * pb.xd[0] - pa.xd[0] * pb.xd[2];
  cr[2] = pa.xd[0] * pb.xd[1] - pa.xd[1] * pb.xd[0];
  const double sin_angle = norm3(cr) / (na * nb);
  const double cos_angle = std::fabs(dot3(pa.xd, pb.xd)) / (na * nb);
  info[B2B_INFO_ANGLE] = std::atan2(sin_angle, cos_angle) * 180.0 / kPi;
  double d[3];
  sub3(pa.x, pb.x, d);
  const double h11 = dot3(pa.xd, pa.xd) + dot3(d, pa.xdd);
  const double h22 = dot3(pb.xd, pb.xd) - dot3(d, pb.xdd);
  const double h12 = -dot3(pa.xd, pb.xd);
  const double det = h11 * h22 - h12 * h12;
  if (sin_angle < params.sin_parallel_angle || !(det > 1e-12 * na * na * nb * nb)) {
    out.contact_status = B2B_CONTACT_PARALLEL;
    return fail;
  }

  // Sign-tracked normal and gap.
  const double rho = norm3(d);
  double n[3], rho_signed = 0.0;  // rho_signed = 0: the normal does not rotate (see below)
  double gap;
  if (rho <= tol_length) {
    // The axes intersect: the normal is undefined, use the previous one.
    if (!has_normal) {
      out.contact_status = B2B_CONTACT_NO_NORMAL;
      return fail;
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

  if (!owns(xi, na, len_a, A.end_rule != B2B_END_NEIGHBOUR) ||
      !owns(eta, nb, len_b, B.end_rule != B2B_END_NEIGHBOUR)) {
    out.contact_status = B2B_CONTACT_OUTSIDE;
    return fail;
  }
  const LawValue law = normal_law(params, gap);
  info[B2B_INFO_NORMAL_FORCE] = law.force;
  info[B2B_INFO_ENERGY] = law.energy;
  if (!(law.force > 0.0)) {
    out.contact_status = B2B_CONTACT_OPEN;
    return fail;
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
  if (!K) return fail;

  // Tangent K = -f' G G^T - f dG/dX, where (all total derivatives in X)
  //   dG/dX = blockdiag(n.d2x_A/dX_A^2, -n.d2x_B/dX_B^2) + a dxi^T + b deta^T + J^T dn/dX,
  //   a = [P_A,xi^T n; 0], b = [0; -P_B,eta^T n], J = [P_A, -P_B],
  //   dn/dX = (I - n n^T)/rho_signed (J + x_A,xi dxi^T - x_B,eta deta^T),
  // and [dxi; deta] = -H^-1 dgrad(phi)/dX from the orthogonality conditions.
  double dxi[kNdof], deta[kNdof];
  for (int c = 0; c < 12; ++c) {
    const double bx_a = col_dot(PA, c, pa.xd) + col_dot(PAd, c, d);
    const double bx_b = -col_dot(PB, c, pa.xd);
    const double be_a = -col_dot(PA, c, pb.xd);
    const double be_b = col_dot(PB, c, pb.xd) - col_dot(PBd, c, d);
    dxi[c] = -(h22 * bx_a - h12 * be_a) / det;
    deta[c] = -(h11 * be_a - h12 * bx_a) / det;
    dxi[12 + c] = -(h22 * bx_b - h12 * be_b) / det;
    deta[12 + c] = -(h11 * be_b - h12 * bx_b) / det;
  }
  double av[12], bv[12];
  for (int c = 0; c < 12; ++c) {
    av[c] = col_dot(PAd, c, n);
    bv[c] = -col_dot(PBd, c, n);
  }
  // J (3 x 24) and dn/dX (3 x 24)
  double J[3 * kNdof], N[3 * kNdof];
  for (int c = 0; c < 12; ++c)
    for (int i = 0; i < 3; ++i) {
      J[i + 3 * c] = PA[i + 3 * c];
      J[i + 3 * (12 + c)] = -PB[i + 3 * c];
    }
  if (rho_signed != 0.0) {
    for (int c = 0; c < kNdof; ++c) {
      double v[3];
      for (int i = 0; i < 3; ++i) v[i] = J[i + 3 * c] + pa.xd[i] * dxi[c] - pb.xd[i] * deta[c];
      const double nv = dot3(n, v);
      for (int i = 0; i < 3; ++i) N[i + 3 * c] = (v[i] - n[i] * nv) / rho_signed;
    }
  } else {
    std::memset(N, 0, sizeof N);
  }
  const double f = law.force, fp = law.slope;
  for (int c = 0; c < kNdof; ++c)
    for (int r = 0; r < kNdof; ++r) {
      double dg = dot3(J + 3 * r, N + 3 * c);
      if (r < 12) dg += av[r] * dxi[c];
      else dg += bv[r - 12] * deta[c];
      K[r + kNdof * c] = -fp * G[r] * G[c] - f * dg;
    }
  // Curvature of the smoothed curves in X: only the node-preserving kinds
  // (and host end tangents) are nonlinear in X; the linear kind pays nothing.
  double H[144], Hd[144];
  if (!sa.linear_in_X()) {
    sa.contracted_hessians(xi, n, H, Hd);
    for (int c = 0; c < 12; ++c)
      for (int r = 0; r < 12; ++r) K[r + kNdof * c] -= f * H[r + 12 * c];
  }
  if (!sb.linear_in_X()) {
    sb.contracted_hessians(eta, n, H, Hd);
    for (int c = 0; c < 12; ++c)
      for (int r = 0; r < 12; ++r) K[(12 + r) + kNdof * (12 + c)] += f * H[r + 12 * c];
  }
  return fail;
}

}  // namespace pair
}  // namespace b2b
