// The AD reference of the line-contact element (test-only code, not part of
// libb2b): b2b_pair_eval_line as include/b2b/b2b_pair.h ("Line contact")
// and doc/line-contact.md specify it, built on the point element of
// ad_pair.hpp and templated over the scalar like it.
//
//   - The integration points are Gauss-Legendre points, computed here (the
//     roots of P_n by Newton's method in long double from the asymptotic
//     estimate cos(pi (i - 1/4) / (n + 1/2)), weights 2 / ((1 - x^2) P_n'^2)).
//   - Integration point i is ad_pair.hpp's point element with A's parameter
//     held at xi_i (one-sided projection onto B, ownership of eta only, the
//     sign-tracked normal, friction with its own history), with the line
//     penalties in place of the point ones.
//   - Its length element J_i = |x_A,xi(xi_i)| and dJ_i/dX are computed in
//     the scalar type, so the residual as written,
//         R = sum_i (1 - lambda_i) w_i (J_i r_i + pi_i dJ_i/dX) + lambda_P r_P,
//     is differentiated by AD as a whole: the length element's second
//     variation, the projections' motion and the weights' derivatives all
//     come from the dual numbers, none is written out.
//   - The blend (contact_type ALL_ANGLE): lambda(s) = u^2 (3 - 2u),
//     u = (s - s1)/(s2 - s1) clipped to [0, 1], s = sin^2 of the angle
//     between the tangents at the point's parameters (1 - (a.b)^2/(|a|^2
//     |b|^2)), computed in the scalar type from the tangents at the
//     parameters found (whose derivatives the Newton steps carried); the
//     point element on the free closest points (slot 0 of the histories)
//     weighted by lambda_P, the integration points by 1 - lambda_i.
//     Other contact types: the line element alone, slot 0 written fresh.
//   - The potential Pi = sum_i w_i J_i pi(g_i) (line part, no blend) in the
//     scalar type: its AD gradient must equal R without friction.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstring>

#include "ad_pair.hpp"

namespace b2bad {

constexpr int kLinePointsMax = B2B_LINE_POINTS_MAX;
constexpr int kHistMax = 16;

// The line options of a finalized b2b_params.
struct LineSettings {
  int type = B2B_CONTACT_TYPE_POINT;
  double line_penalty = 0.0, line_eps_t = 0.0;
  double s1 = 0.0, s2 = 1.0;  // sin^2 of "line_angle", "point_angle"
};

// The n-point Gauss-Legendre rule on [-1, 1], points increasing.
inline void gauss_legendre(int n, double* x, double* w) {
  const long double pi = 3.141592653589793238462643383279502884L;
  for (int i = 0; i < n; ++i) {
    // i-th root from the top, then stored in increasing order
    long double t = std::cos(pi * (i + 0.75L) / (n + 0.5L));
    long double dp = 1.0L;
    for (int it = 0; it < 100; ++it) {
      long double p0 = 1.0L, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const long double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1.0L;
      // P_n' = n (t P_n - P_{n-1}) / (t^2 - 1); here p1 = P_n, p0 = P_{n-1}
      dp = n * (t * p1 - p0) / (t * t - 1.0L);
      const long double step = p1 / dp;
      t -= step;
      if (std::fabs(step) <= 1e-19L) break;
    }
    {
      long double p0 = 1.0L, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const long double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0L);
    }
    x[n - 1 - i] = static_cast<double>(t);
    w[n - 1 - i] = static_cast<double>(2.0L / ((1.0L - t * t) * dp * dp));
  }
  if (n % 2 == 1) x[n / 2] = 0.0;
  for (int i = 0; i < n / 2; ++i) {  // exactly symmetric
    x[i] = -x[n - 1 - i];
    w[i] = w[n - 1 - i];
  }
}

// The blending weight lambda(s) of the tangents a, b (scalar type), and
// whether it lies strictly inside (0, 1) (where its derivative is not zero).
template <class S>
S blend_weight(const LineSettings& ls, const S* a, const S* b, bool* inside) {
  const S aa = dot3(a, a), bb = dot3(b, b), ab = dot3(a, b);
  const S s = 1.0 - (ab * ab) / (aa * bb);
  const S u = (s - ls.s1) / (ls.s2 - ls.s1);
  *inside = false;
  if (!(val(u) > 0.0)) return S(0.0);
  if (!(val(u) < 1.0)) return S(1.0);
  *inside = true;
  return (u * u) * (3.0 - 2.0 * u);
}

template <class S>
struct LineResult {
  int status = B2B_CONTACT_OUTSIDE;
  double line_info[B2B_LINE_INFO_LEN] = {};
  double point_info[B2B_PAIR_INFO_LEN * kLinePointsMax] = {};
  double hist[(kLinePointsMax + 1) * kHistMax] = {};
  S R[kNdof];
  S potential = 0.0;       // sum_i w_i J_i pi(g_i), the line part
  double K_main[kNdof * kNdof] = {};  // the MAIN tangent (values)
  double scale = 1.0;
  bool active = false;
};

// b2b_pair_eval_line on checked input. pst: the point element's settings,
// lst: the same with the line penalties, ls: the line options; hist_old of
// (n + 1) * pst.hist_len doubles. Returns a B2B_ERR_* status.
template <class S>
int evaluate_line(const Settings& pst, const Settings& lst, const LineSettings& ls,
                  const SegmentSpec* spec, const double* X, const double* radii, int n,
                  const double* hist_old, int flags, LineResult<S>& out) {
  static thread_local Result<S> q;  // large: kept off the stack
  const int hs = pst.hist_len;
  out = LineResult<S>();
  for (int r = 0; r < kNdof; ++r) out.R[r] = 0.0;
  double* li = out.line_info;
  li[B2B_LINE_INFO_POINTS] = n;
  li[B2B_LINE_INFO_MIN_GAP] = DBL_MAX;
  li[B2B_LINE_INFO_SYMMETRIC] = 1.0;
  li[B2B_LINE_INFO_POINT_STATUS] = -1.0;
  const bool blend = ls.type == B2B_CONTACT_TYPE_ALL_ANGLE;
  bool any_force = false, any_owned = false;
  int counts[6] = {0, 0, 0, 0, 0, 0};  // line points per status

  auto add_main = [&](double weight, const Result<S>& r) {
    for (int c = 0; c < kNdof; ++c)
      for (int k = 0; k < kNdof; ++k)
        out.K_main[k + kNdof * c] += weight * (-r.slope) * r.G[k] * r.G[c];
  };

  // The point element (ALL_ANGLE only), slot 0.
  if (blend) {
    if (int e = evaluate(pst, spec, X, radii, hist_old, flags, nullptr, q)) return e;
    std::memcpy(out.hist, q.hist, hs * sizeof(double));
    out.scale = q.scale;
    li[B2B_LINE_INFO_POINT_STATUS] = q.status;
    const bool owned = q.status == B2B_CONTACT_OPEN || q.status == B2B_CONTACT_ACTIVE;
    if (owned) {
      any_owned = true;
      li[B2B_LINE_INFO_MIN_GAP] = std::fmin(li[B2B_LINE_INFO_MIN_GAP], q.info[B2B_INFO_GAP]);
    }
    // lambda_P weights the point element's force: it is reported where there
    // is one (the header's "lambda_P of the point element"; with no force
    // nothing is weighted and the entry stays 0)
    bool inside = false;
    const S lam = q.active ? blend_weight(ls, q.ta, q.tb, &inside) : S(0.0);
    if (q.active && val(lam) > 0.0) {
      li[B2B_LINE_INFO_POINT_WEIGHT] = val(lam);
      any_force = true;
      for (int r = 0; r < kNdof; ++r) out.R[r] += lam * q.R[r];
      const double lv = val(lam);
      li[B2B_LINE_INFO_POINT_FORCE] = lv * q.info[B2B_INFO_NORMAL_FORCE];
      li[B2B_LINE_INFO_POINT_FRICTION_STATE] = q.info[B2B_INFO_FRICTION_STATE];
      li[B2B_LINE_INFO_NORMAL_FORCE] += lv * q.info[B2B_INFO_NORMAL_FORCE];
      li[B2B_LINE_INFO_ENERGY] += lv * q.info[B2B_INFO_ENERGY];
      li[B2B_LINE_INFO_DISSIPATION] += lv * q.info[B2B_INFO_DISSIPATION];
      if (inside || q.info[B2B_INFO_SYMMETRIC] == 0.0) li[B2B_LINE_INFO_SYMMETRIC] = 0.0;
      add_main(lv, q);
    }
  }

  double xg[kLinePointsMax], wg[kLinePointsMax];
  gauss_legendre(n, xg, wg);
  for (int i = 0; i < n; ++i) {
    Hold h;
    h.a = true;
    h.line = true;
    h.ta = xg[i];
    if (int e = evaluate(lst, spec, X, radii, hist_old + (i + 1) * hs, flags, nullptr, q, h))
      return e;
    out.scale = q.scale;
    std::memcpy(out.point_info + B2B_PAIR_INFO_LEN * i, q.info, sizeof q.info);
    std::memcpy(out.hist + (i + 1) * hs, q.hist, hs * sizeof(double));
    if (q.status >= 0 && q.status < 6) ++counts[q.status];
    li[B2B_LINE_INFO_LENGTH] += wg[i] * dval(q.J);
    const bool owned = q.status == B2B_CONTACT_OPEN || q.status == B2B_CONTACT_ACTIVE;
    if (owned) {
      any_owned = true;
      ++li[B2B_LINE_INFO_OWNED_POINTS];
      li[B2B_LINE_INFO_MIN_GAP] = std::fmin(li[B2B_LINE_INFO_MIN_GAP], q.info[B2B_INFO_GAP]);
    }
    out.potential += (wg[i] * q.J) * q.energy;
    if (!q.active) continue;
    bool inside = false;
    const S lam = blend && q.tangents ? blend_weight(ls, q.ta, q.tb, &inside) : S(0.0);
    const S wl = 1.0 - lam;
    if (!(val(wl) > 0.0)) continue;
    any_force = true;
    ++li[B2B_LINE_INFO_ACTIVE_POINTS];
    const int fs = static_cast<int>(q.info[B2B_INFO_FRICTION_STATE]);
    if (fs == B2B_FRICTION_STICK) ++li[B2B_LINE_INFO_STICK_POINTS];
    if (fs == B2B_FRICTION_SLIP) ++li[B2B_LINE_INFO_SLIP_POINTS];
    const S wJ = wg[i] * q.J;
    for (int r = 0; r < kNdof; ++r) {
      S Ri = wJ * q.R[r];
      if (r < 12) Ri += (wg[i] * q.energy) * q.dJ[r];
      out.R[r] += wl * Ri;
    }
    const double wv = dval(wl) * dval(wJ);
    li[B2B_LINE_INFO_NORMAL_FORCE] += wv * q.info[B2B_INFO_NORMAL_FORCE];
    li[B2B_LINE_INFO_ENERGY] += wv * q.info[B2B_INFO_ENERGY];
    li[B2B_LINE_INFO_DISSIPATION] += wv * q.info[B2B_INFO_DISSIPATION];
    if (inside || q.info[B2B_INFO_SYMMETRIC] == 0.0) li[B2B_LINE_INFO_SYMMETRIC] = 0.0;
    add_main(wv, q);
  }
  if (!blend) std::memset(out.hist, 0, hs * sizeof(double));  // slot 0 kept fresh

  // The pair's status (not documented in detail; b2b_pair.h lists the
  // values): ACTIVE where a part carries force, else OPEN where a part is
  // owned, else the line points' common status (OUTSIDE where they differ).
  if (any_force) {
    out.status = B2B_CONTACT_ACTIVE;
    out.active = true;
  } else if (any_owned) {
    out.status = B2B_CONTACT_OPEN;
  } else {
    out.status = B2B_CONTACT_OUTSIDE;
    for (int k = 0; k < 6; ++k)
      if (counts[k] == n) out.status = k;
  }
  return B2B_OK;
}

}  // namespace b2bad
