#include "line_contact.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>
#include <vector>

#include "../common/finite.hpp"
#include "../curve/vec3.hpp"
#include "angle_blend.hpp"
#include "gauss_legendre.hpp"
#include "tangent_options.hpp"

namespace b2b {
namespace pair {
namespace {

using curve::dot3;

constexpr int kNN = kNdof * kNdof;

// What the pair's status is made of (b2b_pair.h: ACTIVE if any part carries
// force, else OPEN if any part's point is owned, else OUTSIDE if any point
// lies on another pair, else the first part's own status).
struct StatusTally {
  bool active = false, owned = false, outside = false;
  int other = -1;
  void add(int status, bool carries_force) {
    if (carries_force) active = true;
    if (status == B2B_CONTACT_ACTIVE || status == B2B_CONTACT_OPEN) owned = true;
    else if (status == B2B_CONTACT_OUTSIDE) outside = true;
    else if (other < 0) other = status;
  }
  int status() const {
    if (active) return B2B_CONTACT_ACTIVE;
    if (owned) return B2B_CONTACT_OPEN;
    if (outside || other < 0) return B2B_CONTACT_OUTSIDE;
    return other;
  }
};

// K += s * r ds^T: a part's residual times the gradient of its weight.
void add_outer(double* K, double s, const double* r, const double* ds) {
  for (int c = 0; c < kNdof; ++c)
    for (int row = 0; row < kNdof; ++row) K[row + kNdof * c] += s * r[row] * ds[c];
}

// The residual, line_info, new histories and (K not null) the tangent the
// "tangent" option asks for, except FD and the final symmetrization
// (evaluate_line). hist_new: (n + 1) histories.
void line_sum(const Params& params, const SegmentRef& A, const SegmentRef& B, int n,
              const double* hist_old, double* hist_new, LineResult& out, double* point_info,
              double* K) {
  out = LineResult();
  double* info = out.info;
  const int hl = history_length(params);
  const bool blend = params.contact_type == B2B_CONTACT_TYPE_ALL_ANGLE;
  const bool main_only = params.tangent == B2B_TANGENT_MAIN;
  // The parts' own tangents: exact (or the main term); FD and SYMMETRIC act
  // on the sum.
  Params pp = params, lp = line_point_params(params);
  pp.tangent = lp.tangent = main_only ? B2B_TANGENT_MAIN : B2B_TANGENT_EXACT;
  if (K) std::memset(K, 0, kNN * sizeof(double));
  info[B2B_LINE_INFO_POINTS] = n;
  info[B2B_LINE_INFO_MIN_GAP] = DBL_MAX;
  info[B2B_LINE_INFO_POINT_STATUS] = -1;
  bool symmetric = true;
  StatusTally tally;
  double Kp[kNN], ds[kNdof];

  // The point element (ALL_ANGLE), weighted by lambda of its angle.
  if (blend) {
    PairResult pr;
    Kinematics kin;
    evaluate_built(pp, A, B, hist_old, pr, K ? Kp : nullptr, Ends(), &kin);
    std::memcpy(hist_new, pr.history, hl * sizeof(double));
    const int st = pr.contact_status;
    info[B2B_LINE_INFO_POINT_STATUS] = st;
    std::memcpy(out.point_part, pr.info, sizeof pr.info);
    if (st == B2B_CONTACT_OPEN || st == B2B_CONTACT_ACTIVE)
      info[B2B_LINE_INFO_MIN_GAP] = std::fmin(info[B2B_LINE_INFO_MIN_GAP], pr.info[B2B_INFO_GAP]);
    BlendWeight w;
    if (st == B2B_CONTACT_ACTIVE) w = point_weight(params, sin2_angle(kin.pa.xd, kin.pb.xd));
    tally.add(st, w.lambda > 0.0);
    if (w.lambda > 0.0) {
      info[B2B_LINE_INFO_POINT_WEIGHT] = w.lambda;
      info[B2B_LINE_INFO_POINT_FRICTION_STATE] = pr.info[B2B_INFO_FRICTION_STATE];
      info[B2B_LINE_INFO_POINT_FORCE] = w.lambda * pr.info[B2B_INFO_NORMAL_FORCE];
      info[B2B_LINE_INFO_NORMAL_FORCE] += w.lambda * pr.info[B2B_INFO_NORMAL_FORCE];
      info[B2B_LINE_INFO_ENERGY] += w.lambda * pr.info[B2B_INFO_ENERGY];
      info[B2B_LINE_INFO_DISSIPATION] += w.lambda * pr.info[B2B_INFO_DISSIPATION];
      for (int r = 0; r < kNdof; ++r) out.residual[r] += w.lambda * pr.residual[r];
      if (pr.info[B2B_INFO_SYMMETRIC] != 1.0) symmetric = false;
      if (K) {
        for (int i = 0; i < kNN; ++i) K[i] += w.lambda * Kp[i];
        if (w.slope != 0.0 && !main_only) {
          sin2_gradient(A, B, kin, ds);
          add_outer(K, w.slope, pr.residual, ds);
        }
      }
      // The weight's derivative makes the exact tangent unsymmetric; the
      // main terms alone stay symmetric.
      if (w.slope != 0.0 && !main_only) symmetric = false;
    }
  } else {
    std::memset(hist_new, 0, hl * sizeof(double));  // kept fresh
  }

  // The integration points, weighted by w_i |x_A,xi(xi_i)| (and 1 - lambda).
  const double *xs, *ws;
  gauss_legendre(n, &xs, &ws);
  double length = 0.0;
  for (int i = 0; i < n; ++i) {
    double t[3];
    A.seg->point(xs[i], nullptr, t, nullptr);
    const double J = curve::norm3(t);
    length += ws[i] * J;
    Ends held;
    held.at_point = true;
    held.xi_a = xs[i];
    PairResult pr;
    Kinematics kin;
    evaluate_built(lp, A, B, hist_old + (i + 1) * hl, pr, K ? Kp : nullptr, held, &kin);
    std::memcpy(hist_new + (i + 1) * hl, pr.history, hl * sizeof(double));
    if (point_info) std::memcpy(point_info + kInfoLength * i, pr.info, sizeof pr.info);
    const int st = pr.contact_status;
    if (st == B2B_CONTACT_OPEN || st == B2B_CONTACT_ACTIVE) {
      info[B2B_LINE_INFO_OWNED_POINTS] += 1.0;
      info[B2B_LINE_INFO_MIN_GAP] = std::fmin(info[B2B_LINE_INFO_MIN_GAP], pr.info[B2B_INFO_GAP]);
    }
    BlendWeight w;
    if (blend && st == B2B_CONTACT_ACTIVE)
      w = point_weight(params, sin2_angle(kin.pa.xd, kin.pb.xd));
    const double keep = 1.0 - w.lambda;  // the line point's weight
    const bool carries = st == B2B_CONTACT_ACTIVE && keep > 0.0;
    tally.add(st, carries);
    if (!carries) continue;
    info[B2B_LINE_INFO_ACTIVE_POINTS] += 1.0;
    const int fs = static_cast<int>(pr.info[B2B_INFO_FRICTION_STATE]);
    if (fs == B2B_FRICTION_STICK) info[B2B_LINE_INFO_STICK_POINTS] += 1.0;
    if (fs == B2B_FRICTION_SLIP) info[B2B_LINE_INFO_SLIP_POINTS] += 1.0;
    if (pr.info[B2B_INFO_SYMMETRIC] != 1.0) symmetric = false;
    if (w.slope != 0.0 && !main_only) symmetric = false;

    // R = w_i (J r + pi dJ/dX), dJ/dX = e . dx_A,xi/dX with e = t / J (A's columns).
    const double wi = ws[i], W = wi * J, pi = pr.info[B2B_INFO_ENERGY];
    const double f = pr.info[B2B_INFO_NORMAL_FORCE];
    double PA[36], PAd[36], e[3] = {t[0] / J, t[1] / J, t[2] / J}, gJ[12];
    A.seg->jacobians(xs[i], PA, PAd);
    for (int c = 0; c < 12; ++c) gJ[c] = dot3(PAd + 3 * c, e);
    double R[kNdof];
    for (int r = 0; r < kNdof; ++r) R[r] = W * pr.residual[r] + (r < 12 ? wi * pi * gJ[r] : 0.0);
    for (int r = 0; r < kNdof; ++r) out.residual[r] += keep * R[r];
    info[B2B_LINE_INFO_NORMAL_FORCE] += keep * W * f;
    info[B2B_LINE_INFO_ENERGY] += keep * W * pi;
    info[B2B_LINE_INFO_DISSIPATION] += keep * W * pr.info[B2B_INFO_DISSIPATION];
    if (!K) continue;
    for (int k = 0; k < kNN; ++k) K[k] += keep * W * Kp[k];
    if (main_only) continue;
    // dR = W K_i + w_i (r gJ^T + gJ rN^T + pi d2J/dX2), rN = -f dg/dX the
    // normal part of r (the gradient of pi), d2J/dX2 = (1/J) Pd^T (I - e e^T) Pd
    // + e . d2(x_A,xi)/dX2.
    const double* n_i = pr.info + B2B_INFO_NORMAL;
    double PB[36], PBd[36], rN[kNdof];
    B.seg->jacobians(kin.eta, PB, PBd);
    for (int c = 0; c < 12; ++c) {
      rN[c] = -f * dot3(PA + 3 * c, n_i);
      rN[12 + c] = f * dot3(PB + 3 * c, n_i);
    }
    const double s = keep * wi;
    for (int c = 0; c < 12; ++c)
      for (int r = 0; r < kNdof; ++r) K[r + kNdof * c] += s * pr.residual[r] * gJ[c];
    for (int c = 0; c < kNdof; ++c)
      for (int r = 0; r < 12; ++r) K[r + kNdof * c] += s * gJ[r] * rN[c];
    if (pi != 0.0) {
      double Hx[144], Hxd[144];
      A.seg->contracted_hessians(xs[i], e, Hx, Hxd);
      for (int c = 0; c < 12; ++c)
        for (int r = 0; r < 12; ++r) {
          const double* pr_ = PAd + 3 * r;
          const double* pc = PAd + 3 * c;
          const double proj = dot3(pr_, pc) - dot3(pr_, e) * dot3(pc, e);
          K[r + kNdof * c] += s * pi * (proj / J + Hxd[r + 12 * c]);
        }
    }
    if (w.slope != 0.0) {
      sin2_gradient(A, B, kin, ds);
      add_outer(K, -w.slope, R, ds);
    }
  }
  info[B2B_LINE_INFO_LENGTH] = length;
  info[B2B_LINE_INFO_SYMMETRIC] = symmetric ? 1.0 : 0.0;
  out.contact_status = tally.status();
  out.overflow = !all_finite(info, kLineInfoLength) || !all_finite(out.residual, kNdof) ||
                 !all_finite(out.point_part, kInfoLength) ||
                 !all_finite(hist_new, (n + 1) * hl) || (K && !all_finite(K, kNN)) ||
                 (point_info && !all_finite(point_info, kInfoLength * n));
  // Symmetric in exact arithmetic (no friction, no weight derivative): the
  // rank-one terms r dJ^T and dJ r_N^T were added in different orders, so
  // make it symmetric to the bit, as the flag promises.
  if (K && symmetric) symmetrize(K);
}

}  // namespace

int line_points(const Params& p, double length, double radius_a, double radius_b) {
  if (p.line_points > 0) return p.line_points;
  const double r = radius_a + radius_b;
  if (!(r > 0.0)) return 16;
  const double n = 3.0 + std::ceil(length / r);
  return n < 4.0 ? 4 : (n > 16.0 ? 16 : static_cast<int>(n));
}

void evaluate_line(const Params& params, const SegmentRef& A, const SegmentRef& B, int n_points,
                   const double* hist_old, double* hist_new, LineResult& out, double* point_info,
                   double* K) {
  const bool fd = K && params.tangent == B2B_TANGENT_FD;
  line_sum(params, A, B, n_points, hist_old, hist_new, out, point_info, fd ? nullptr : K);
  if (!K) return;
  if (fd && out.contact_status != B2B_CONTACT_ACTIVE) {
    // No force, no tangent (b2b_pair.h), whatever differences across the
    // contact's onset would say.
    std::memset(K, 0, kNN * sizeof(double));
    return;
  }
  if (fd) {
    std::vector<double> scratch(static_cast<size_t>(n_points + 1) * history_length(params));
    fd_tangent_of(A, B, K, [&](const SegmentRef& a, const SegmentRef& b, double* r) {
      LineResult moved;
      line_sum(params, a, b, n_points, hist_old, scratch.data(), moved, nullptr, nullptr);
      std::memcpy(r, moved.residual, sizeof moved.residual);
    });
    out.info[B2B_LINE_INFO_SYMMETRIC] = 0.0;
    out.overflow = out.overflow || !all_finite(K, kNN);
    return;
  }
  if (params.tangent == B2B_TANGENT_SYMMETRIC && out.info[B2B_LINE_INFO_SYMMETRIC] != 1.0) {
    symmetrize(K);
    out.info[B2B_LINE_INFO_SYMMETRIC] = 1.0;
  }
}

PairFailure evaluate_line_pair(const Params& params, const SegmentInput& A,
                               const SegmentInput& B, int n_points, const double* hist_old,
                               double* hist_new, LineResult& out, double* point_info, double* K) {
  curve::Segment built[2];
  SegmentRef refs[2];
  const PairFailure fail = build_pair(A, B, built, refs);
  if (!fail.status)
    evaluate_line(params, refs[0], refs[1], n_points, hist_old, hist_new, out, point_info, K);
  return fail;
}

}  // namespace pair
}  // namespace b2b
