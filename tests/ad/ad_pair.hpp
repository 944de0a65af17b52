// The AD reference of the contact element (test-only code, not part of
// libb2b): an independent implementation of what b2b_pair_eval computes,
// written from doc/curves.md, doc/contact-element.md, doc/friction.md and the
// contracts of include/b2b/b2b_curve.h and b2b_pair.h, templated over the
// scalar. Instantiated with double it gives the residual; with Dual<24>
// seeded on the 24 contact coordinates, the residual's exact derivative, the
// tangent, by forward-mode automatic differentiation. It calls nothing of
// libb2b's src/ (only the public b2b_params getters, in ad_pair.cpp).
//
// What is differentiated is the residual as a function of X:
//   R(X) = J(xi(X), eta(X), X)^T (T - f_N n),   J = [P_A, -P_B],
// where P = dx/dX is this file's own first derivative of the curve (a
// vector-Jacobian product, add_PTw), xi and eta solve the orthogonality
// conditions, n = d/rho, f_N = f_N(g) and T the friction force of the return
// mapping with the committed history held constant. The closest points are
// found by a safeguarded Newton iteration in double (doc/contact-element.md
// 3-4: chord start, positive-definite shift, step limit, backtracking, the
// box [-3, 3]); then two plain Newton steps are taken in the scalar type
// from the converged point, which carry the implicit-function derivative
// dxi/dX = -H^-1 dr/dX into the duals and polish the values to rounding (the
// first step's derivative is exact up to a term proportional to the
// converged residual r; the second's to one proportional to its square).
//
// Numerics: the coordinates are moved to a local frame, X' = (X - c)/s with c
// beam A's node x2 and s a power of two near the segments' chord lengths, so
// every quantity is of order one (no overflow or underflow from 1e-100 to
// 1e100, and no loss to a large offset beyond that of rounding X - c once);
// the derivative is taken in X' and divided by s. Lengths that enter the
// force (the gap, the slip) are s times the local ones, exactly.
//
// The real type: double for the reference proper; the same code in long
// double (Dual<24, long double>, 64-bit significand on x86-64) tells, where
// the library and the reference differ, which of the two is off.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "dual.hpp"

namespace b2bad {

constexpr int kNdof = 24;
using D24 = Dual<kNdof>;

// The options of a finalized b2b_params, as read through its getters.
struct Settings {
  int law = B2B_LAW_LINEAR;
  double penalty = 0.0, g0 = 0.0, sin_parallel = 0.0, mu = 0.0, eps_t = 0.0;
  int warm_start = 0, max_iterations = 50, tangent = B2B_TANGENT_EXACT, hist_len = 8;
};

// History slots (doc/friction.md section 7).
enum {
  kTag = 0, kHasNormal = 1, kNormal = 2, kXi = 5, kEta = 6,
  kInContact = 8, kForceE1 = 9, kForceE2 = 10, kFrictionState = 11
};

// ------------------------------------------------------------- algebra

template <class S>
inline S dot3(const S* a, const S* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class S>
inline S norm3(const S* a) {
  return hypot3(a[0], a[1], a[2]);
}
template <class S>
inline void cross3(const S* a, const S* b, S* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

// A coordinate as a scalar: a plain value, or an AD variable seeded in
// component k.
template <class S>
struct Seed;
template <>
struct Seed<double> {
  static double make(double v, int) { return v; }
};
template <>
struct Seed<long double> {
  static long double make(long double v, int) { return v; }
};
template <int N, class R>
struct Seed<Dual<N, R>> {
  static Dual<N, R> make(R v, int k) { return Dual<N, R>::variable(v, k); }
};

// The value of a scalar rounded to double (outputs, decisions).
template <class S>
inline double dval(const S& x) {
  return static_cast<double>(val(x));
}

// x with its value replaced by v (the derivatives kept).
inline double with_value(double, double v) { return v; }
inline long double with_value(long double, double v) { return v; }
template <int N, class R>
inline Dual<N, R> with_value(Dual<N, R> x, double v) {
  x.v = v;
  return x;
}

// ------------------------------------------------------------- the curves

// The four Hermite terms of a segment, x = H1 P0 + H2 T0 + H3 P1 + H4 T1
// (doc/curves.md section 2): each is a fixed combination of the patch slots
// or a nonlinear end tangent T = sigma |x_q - x_p| unit(u).
enum class Dir { Chord, Weighted, Given };
struct TermSpec {
  bool nonlinear = false;
  double coef[4] = {0, 0, 0, 0};  // linear: sum_s coef[s] x_s
  double sigma = 0.0;
  int p = 0, q = 0;               // L = |x_q - x_p|
  Dir dir = Dir::Chord;           // chord u = x_c - x_a; weighted (3.1) with
  int a = 0, b = 0, c = 0;        //   w1 = x_b - x_a, w2 = x_c - x_b
  double given[3] = {0, 0, 0};    // host direction (unit), a constant
};
struct SegmentSpec {
  TermSpec term[4];  // P0, T0, P1, T1
  unsigned used = 0; // bit s: slot s is read
  int kind = 0, start_rule = 0, end_rule = 0;
};

inline void set_linear(TermSpec& t, double c0, double c1, double c2, double c3) {
  t.nonlinear = false;
  t.coef[0] = c0, t.coef[1] = c1, t.coef[2] = c2, t.coef[3] = c3;
}
inline void set_tangent(TermSpec& t, double sigma, int p, int q) {
  t.nonlinear = true;
  t.sigma = sigma, t.p = p, t.q = q;
}
inline void set_given(TermSpec& t, const double* unit_dir) {
  t.dir = Dir::Given;
  for (int i = 0; i < 3; ++i) t.given[i] = unit_dir[i];
}
inline void set_dir(TermSpec& t, int kind, int a, int b, int c) {
  t.dir = kind == B2B_CURVE_HERMITE_NODAL_WEIGHTED ? Dir::Weighted : Dir::Chord;
  t.a = a, t.b = b, t.c = c;
}

// The terms of a kind with its end rules (b2b_curve.h, doc/curves.md 3-4).
// dirs: the host's unit directions at the first and last node (6), read only
// for a TANGENT rule. Returns a B2B_ERR_* status.
inline int make_spec(int kind, int start_rule, int end_rule, const double* dirs,
                     SegmentSpec& sp) {
  sp = SegmentSpec();
  sp.kind = kind, sp.start_rule = start_rule, sp.end_rule = end_rule;
  if (kind < B2B_CURVE_LINEAR || kind > B2B_CURVE_HERMITE_NODAL_WEIGHTED)
    return B2B_ERR_UNKNOWN_KIND;
  if (start_rule < B2B_END_NEIGHBOUR || start_rule > B2B_END_TANGENT ||
      end_rule < B2B_END_NEIGHBOUR || end_rule > B2B_END_TANGENT)
    return B2B_ERR_UNKNOWN_KIND;
  TermSpec* t = sp.term;
  if (kind == B2B_CURVE_LINEAR) {  // the chord x2 -> x3; rules ignored
    set_linear(t[0], 0, 1, 0, 0);
    set_linear(t[1], 0, -0.5, 0.5, 0);
    set_linear(t[2], 0, 0, 1, 0);
    set_linear(t[3], 0, -0.5, 0.5, 0);
    sp.used = 0x6u;
    return B2B_OK;
  }
  if (kind == B2B_CURVE_HERMITE_MIDPOINT) {
    const bool first = start_rule != B2B_END_NEIGHBOUR, last = end_rule != B2B_END_NEIGHBOUR;
    if (first && last) return B2B_ERR_RANGE;
    if (first) {  // half element x2 -> m23
      set_linear(t[0], 0, 1, 0, 0);
      if (start_rule == B2B_END_TANGENT) {
        set_tangent(t[1], 0.25, 1, 2);
        set_given(t[1], dirs);
      } else {
        set_linear(t[1], 0, -0.25, 0.25, 0);
      }
      set_linear(t[2], 0, 0.5, 0.5, 0);
      set_linear(t[3], 0, -0.25, 0.25, 0);
      sp.used = 0x6u;
    } else if (last) {  // half element m12 -> x2
      set_linear(t[0], 0.5, 0.5, 0, 0);
      set_linear(t[1], -0.25, 0.25, 0, 0);
      set_linear(t[2], 0, 1, 0, 0);
      if (end_rule == B2B_END_TANGENT) {
        set_tangent(t[3], 0.25, 0, 1);
        set_given(t[3], dirs + 3);
      } else {
        set_linear(t[3], -0.25, 0.25, 0, 0);
      }
      sp.used = 0x3u;
    } else {  // the parabola m12 -> m23 with control point x2
      set_linear(t[0], 0.5, 0.5, 0, 0);
      set_linear(t[1], -0.5, 0.5, 0, 0);
      set_linear(t[2], 0, 0.5, 0.5, 0);
      set_linear(t[3], 0, -0.5, 0.5, 0);
      sp.used = 0x7u;
    }
    return B2B_OK;
  }
  // The nodal kinds: x2 -> x3, end tangents (l23 / 2) unit(direction).
  set_linear(t[0], 0, 1, 0, 0);
  set_linear(t[2], 0, 0, 1, 0);
  sp.used = 0x6u;
  if (start_rule == B2B_END_REFLECT) {
    set_linear(t[1], 0, -0.5, 0.5, 0);
  } else {
    set_tangent(t[1], 0.5, 1, 2);
    if (start_rule == B2B_END_TANGENT) {
      set_given(t[1], dirs);
    } else {
      set_dir(t[1], kind, 0, 1, 2);
      sp.used |= 0x1u;
    }
  }
  if (end_rule == B2B_END_REFLECT) {
    set_linear(t[3], 0, -0.5, 0.5, 0);
  } else {
    set_tangent(t[3], 0.5, 1, 2);
    if (end_rule == B2B_END_TANGENT) {
      set_given(t[3], dirs + 3);
    } else {
      set_dir(t[3], kind, 1, 2, 3);
      sp.used |= 0x8u;
    }
  }
  return B2B_OK;
}

// A segment on a patch X (12 scalars, only the used slots are read).
template <class S>
struct Segment {
  const SegmentSpec* spec = nullptr;
  S value[4][3];  // P0, T0, P1, T1
  // nonlinear end tangents (terms 1 and 3): what their jacobian needs
  S L[4], e[4][3], uhat[4][3], r[4], w1[4][3], w2[4][3], s1[4], s2[4];
  const S* X = nullptr;
};

// Fills g from the patch; B2B_ERR_COINCIDENT / B2B_ERR_FOLDED where a length
// or a direction is zero.
template <class S>
int build(const SegmentSpec& sp, const S* X, Segment<S>& g) {
  g.spec = &sp;
  g.X = X;
  for (int k = 0; k < 4; ++k) {
    const TermSpec& t = sp.term[k];
    if (!t.nonlinear) {
      for (int i = 0; i < 3; ++i) {
        S v = 0.0;
        for (int s = 0; s < 4; ++s)
          if (t.coef[s] != 0.0) v += t.coef[s] * X[3 * s + i];
        g.value[k][i] = v;
      }
      continue;
    }
    S dx[3], u[3];
    for (int i = 0; i < 3; ++i) dx[i] = X[3 * t.q + i] - X[3 * t.p + i];
    g.L[k] = norm3(dx);
    if (!(val(g.L[k]) > 0.0)) return B2B_ERR_COINCIDENT;
    for (int i = 0; i < 3; ++i) g.e[k][i] = dx[i] / g.L[k];
    if (t.dir == Dir::Chord) {
      for (int i = 0; i < 3; ++i) u[i] = X[3 * t.c + i] - X[3 * t.a + i];
    } else if (t.dir == Dir::Weighted) {
      for (int i = 0; i < 3; ++i) {
        g.w1[k][i] = X[3 * t.b + i] - X[3 * t.a + i];
        g.w2[k][i] = X[3 * t.c + i] - X[3 * t.b + i];
      }
      g.s1[k] = dot3(g.w2[k], g.w2[k]);
      g.s2[k] = dot3(g.w1[k], g.w1[k]);
      if (!(val(g.s1[k]) > 0.0 && val(g.s2[k]) > 0.0)) return B2B_ERR_COINCIDENT;
      for (int i = 0; i < 3; ++i) u[i] = g.s1[k] * g.w1[k][i] + g.s2[k] * g.w2[k][i];
    } else {
      for (int i = 0; i < 3; ++i) u[i] = t.given[i];
    }
    g.r[k] = norm3(u);
    if (!(val(g.r[k]) > 0.0)) return B2B_ERR_FOLDED;
    for (int i = 0; i < 3; ++i) {
      g.uhat[k][i] = u[i] / g.r[k];
      g.value[k][i] = t.sigma * (g.L[k] * g.uhat[k][i]);
    }
  }
  return B2B_OK;
}

// The cubic Hermite basis on [-1, 1] and its first two derivatives.
template <class T>
inline void hermite(const T& t, T h[4], T hd[4], T hdd[4]) {
  const T t2 = t * t, t3 = t2 * t;
  h[0] = 0.25 * (2.0 - 3.0 * t + t3);
  h[1] = 0.25 * (1.0 - t - t2 + t3);
  h[2] = 0.25 * (2.0 + 3.0 * t - t3);
  h[3] = 0.25 * (-1.0 - t + t2 + t3);
  hd[0] = 0.75 * (t2 - 1.0);
  hd[1] = 0.25 * (3.0 * t2 - 2.0 * t - 1.0);
  hd[2] = 0.75 * (1.0 - t2);
  hd[3] = 0.25 * (3.0 * t2 + 2.0 * t - 1.0);
  hdd[0] = 1.5 * t;
  hdd[1] = 0.5 * (3.0 * t - 1.0);
  hdd[2] = -1.5 * t;
  hdd[3] = 0.5 * (3.0 * t + 1.0);
}

// x(t), dx/dt, d2x/dt2 (xd, xdd may be NULL); t a double or a scalar.
template <class S, class T>
void point(const Segment<S>& g, const T& t, S* x, S* xd, S* xdd) {
  T h[4], hd[4], hdd[4];
  hermite(t, h, hd, hdd);
  for (int i = 0; i < 3; ++i) {
    x[i] = h[0] * g.value[0][i] + h[1] * g.value[1][i] + h[2] * g.value[2][i] +
           h[3] * g.value[3][i];
    if (xd)
      xd[i] = hd[0] * g.value[0][i] + hd[1] * g.value[1][i] + hd[2] * g.value[2][i] +
              hd[3] * g.value[3][i];
    if (xdd)
      xdd[i] = hdd[0] * g.value[0][i] + hdd[1] * g.value[1][i] + hdd[2] * g.value[2][i] +
               hdd[3] * g.value[3][i];
  }
}

// out (12) += sign P(t)^T w, P = dx/dX at t: the curve's first derivative in
// the patch coordinates, as a vector-Jacobian product (doc/curves.md 7):
// a linear term adds H_k coef_s w to slot s; a tangent T = sigma L uhat adds
// sigma (w.uhat) dL/dX + F^T c with c = (sigma L / r)(I - uhat uhat^T) w and
// F = du/dX (chord: -I on a, +I on c; weighted: (3.1) differentiated).
// order 1: the same for P_,t = d(x_,t)/dX (the Hermite basis' derivative in
// place of the basis: the terms enter x_,t exactly as they enter x).
template <class S, class T>
void add_PTw(const Segment<S>& g, const T& t, const S* w, double sign, S* out, int order = 0) {
  T hb[4], hd[4], hdd[4];
  hermite(t, hb, hd, hdd);
  const T* h = order == 1 ? hd : hb;
  for (int k = 0; k < 4; ++k) {
    const TermSpec& ts = g.spec->term[k];
    S wk[3];
    for (int i = 0; i < 3; ++i) wk[i] = (sign * h[k]) * w[i];
    if (!ts.nonlinear) {
      for (int s = 0; s < 4; ++s)
        if (ts.coef[s] != 0.0)
          for (int i = 0; i < 3; ++i) out[3 * s + i] += ts.coef[s] * wk[i];
      continue;
    }
    const S uw = dot3(g.uhat[k], wk);
    const S su = ts.sigma * uw;
    for (int i = 0; i < 3; ++i) {
      const S v = su * g.e[k][i];
      out[3 * ts.q + i] += v;
      out[3 * ts.p + i] -= v;
    }
    if (ts.dir == Dir::Given) continue;  // a constant direction
    const S m = (ts.sigma * g.L[k]) / g.r[k];
    S c[3];
    for (int i = 0; i < 3; ++i) c[i] = m * (wk[i] - g.uhat[k][i] * uw);
    if (ts.dir == Dir::Chord) {
      for (int i = 0; i < 3; ++i) {
        out[3 * ts.c + i] += c[i];
        out[3 * ts.a + i] -= c[i];
      }
    } else {
      // u = s1 w1 + s2 w2, s1 = |w2|^2, s2 = |w1|^2:
      // du = (s1 I + 2 w2 w1^T) dw1 + (s2 I + 2 w1 w2^T) dw2
      const S w2c = 2.0 * dot3(g.w2[k], c), w1c = 2.0 * dot3(g.w1[k], c);
      for (int i = 0; i < 3; ++i) {
        const S g1 = g.s1[k] * c[i] + w2c * g.w1[k][i];
        const S g2 = g.s2[k] * c[i] + w1c * g.w2[k][i];
        out[3 * ts.a + i] -= g1;
        out[3 * ts.b + i] += g1 - g2;
        out[3 * ts.c + i] += g2;
      }
    }
  }
}

// ------------------------------------------------------------- closest points

inline double clampd(double v, double lo, double hi) {
  if (!(v == v)) return 0.5 * (lo + hi);
  return v < lo ? lo : (v > hi ? hi : v);
}

// The closest points of the two chords through the segments' end points
// (doc/contact-element.md 3), clamped to [-1, 1]; (0, 0) when parallel.
inline void chord_start(const Segment<double>& A, const Segment<double>& B, double* xi,
                        double* eta) {
  double t1[3], t2[3], c[3];
  for (int i = 0; i < 3; ++i) {
    t1[i] = A.value[2][i] - A.value[0][i];
    t2[i] = B.value[2][i] - B.value[0][i];
    c[i] = (A.value[0][i] - B.value[0][i]) + (A.value[2][i] - B.value[2][i]);
  }
  const double t11 = dot3(t1, t1), t22 = dot3(t2, t2), t12 = dot3(t1, t2);
  const double D = t11 * t22 - t12 * t12;
  if (!(D > 1e-10 * t11 * t22)) {
    *xi = *eta = 0.0;
    return;
  }
  const double ct1 = dot3(c, t1), ct2 = dot3(c, t2);
  *xi = clampd((ct2 * t12 - ct1 * t22) / D, -1.0, 1.0);
  *eta = clampd((t11 * ct2 - t12 * ct1) / D, -1.0, 1.0);
}

struct Closest {
  bool converged = false;
  double xi = 0.0, eta = 0.0;
  int iterations = 0;
};

inline double half_dist2(const Segment<double>& A, const Segment<double>& B, double xi,
                         double eta) {
  double xa[3], xb[3], d[3];
  point(A, xi, xa, (double*)nullptr, (double*)nullptr);
  point(B, eta, xb, (double*)nullptr, (double*)nullptr);
  for (int i = 0; i < 3; ++i) d[i] = xa[i] - xb[i];
  return 0.5 * dot3(d, d);
}

// The safeguarded Newton iteration of doc/contact-element.md 4 on the local
// (order-one) coordinates. Converged when the tangential components of d are
// below min(tol_len, 1e-13 rho) + 4 eps rho (rho = |d|; tol_len the length
// tolerance 1e-13 l + 64 eps e in local units), or after a plain Newton step
// (unshifted, full length) of at most 16 eps in both parameters.
inline Closest newton(const Segment<double>& A, const Segment<double>& B, double xi, double eta,
                      int max_iterations, double tol_len) {
  Closest cp;
  bool at_rounding = false;
  for (int it = 0;; ++it) {
    double xa[3], a[3], a2[3], xb[3], b[3], b2[3], d[3];
    point(A, xi, xa, a, a2);
    point(B, eta, xb, b, b2);
    for (int i = 0; i < 3; ++i) d[i] = xa[i] - xb[i];
    const double g1 = dot3(d, a), g2 = -dot3(d, b);
    const double na = norm3(a), nb = norm3(b), rho = norm3(d);
    const double tol = std::fmin(tol_len, 1e-13 * rho) + 4.0 * DBL_EPSILON * rho;
    if ((std::fabs(g1) <= tol * na && std::fabs(g2) <= tol * nb) || (it > 0 && at_rounding)) {
      cp.converged = true;
      cp.iterations = it;
      break;
    }
    if (it == max_iterations) {
      cp.iterations = it;
      break;
    }
    double h11 = dot3(a, a) + dot3(d, a2), h22 = dot3(b, b) - dot3(d, b2);
    const double h12 = -dot3(a, b);
    const double mean = 0.5 * (h11 + h22);
    const double lmin = mean - std::sqrt(0.25 * (h11 - h22) * (h11 - h22) + h12 * h12);
    const double floor = 1e-13 * (na * na + nb * nb);  // doc/contact-element.md 4.3
    const bool shifted = lmin < floor;
    if (shifted) {  // shift to positive definite: a descent direction
      h11 += floor - lmin;
      h22 += floor - lmin;
    }
    const double det = h11 * h22 - h12 * h12;
    double s1 = -(h22 * g1 - h12 * g2) / det, s2 = -(h11 * g2 - h12 * g1) / det;
    const double m = std::fmax(std::fabs(s1), std::fabs(s2));
    if (m > 1.0) {  // at most half a segment per iteration
      s1 /= m;
      s2 /= m;
    }
    double alpha = 1.0;
    if (m > 1e-3) {  // backtracking (Armijo) while the step is large
      const double phi = 0.5 * dot3(d, d), slope = g1 * s1 + g2 * s2;
      for (int k = 0; k < 40; ++k) {
        const double trial = half_dist2(A, B, clampd(xi + alpha * s1, -3.0, 3.0),
                                        clampd(eta + alpha * s2, -3.0, 3.0));
        if (trial <= phi + 1e-4 * alpha * slope) break;
        alpha *= 0.5;
      }
    }
    at_rounding = !shifted && alpha == 1.0 && m <= 16.0 * DBL_EPSILON;
    xi = clampd(xi + alpha * s1, -3.0, 3.0);
    eta = clampd(eta + alpha * s2, -3.0, 3.0);
  }
  cp.xi = xi;
  cp.eta = eta;
  return cp;
}

// End contact (b2b_pair.h, "End contact"): one parameter is held at a node
// (-1 or +1) and the other minimises the distance alone. A plain 1-D Newton
// on phi(t) = |x_F(t) - p|^2 / 2, p the held node, written here on its own:
// the curvature shifted up to a floor where it is not positive (then a
// descent step), the step limited to half a segment, Armijo backtracking
// while the step is large, the parameter kept in [-3, 3]. Converged when
// |phi'| <= tol |x_F'| (the same length criterion as the 2-D search), or
// after a plain full step below 16 eps. held_a: A's parameter is held (t is
// eta), else B's (t is xi).
inline Closest newton_held(const Segment<double>& A, const Segment<double>& B, double xi,
                           double eta, bool held_a, int max_iterations, double tol_len) {
  Closest cp;
  const Segment<double>& F = held_a ? B : A;
  double p[3];
  point(held_a ? A : B, held_a ? xi : eta, p, (double*)nullptr, (double*)nullptr);
  double t = held_a ? eta : xi;
  auto phi = [&](double u) {
    double x[3], d[3];
    point(F, u, x, (double*)nullptr, (double*)nullptr);
    for (int i = 0; i < 3; ++i) d[i] = x[i] - p[i];
    return 0.5 * dot3(d, d);
  };
  bool at_rounding = false;
  for (int it = 0;; ++it) {
    double x[3], xd[3], xdd[3], d[3];
    point(F, t, x, xd, xdd);
    for (int i = 0; i < 3; ++i) d[i] = x[i] - p[i];
    const double g = dot3(d, xd), speed = norm3(xd), rho = norm3(d);
    const double tol = std::fmin(tol_len, 1e-13 * rho) + 4.0 * DBL_EPSILON * rho;
    if (std::fabs(g) <= tol * speed || (it > 0 && at_rounding)) {
      cp.converged = true;
      cp.iterations = it;
      break;
    }
    if (it == max_iterations) {
      cp.iterations = it;
      break;
    }
    double h = dot3(xd, xd) + dot3(d, xdd);
    const double floor = 1e-13 * speed * speed;
    const bool shifted = h < floor;
    if (shifted) h = floor + std::fabs(h);
    double step = -g / h;
    const double m = std::fabs(step);
    if (m > 1.0) step /= m;
    double alpha = 1.0;
    if (m > 1e-3) {
      const double f0 = 0.5 * dot3(d, d);
      for (int k = 0; k < 40; ++k) {
        if (phi(clampd(t + alpha * step, -3.0, 3.0)) <= f0 + 1e-4 * alpha * g * step) break;
        alpha *= 0.5;
      }
    }
    at_rounding = !shifted && alpha == 1.0 && m <= 16.0 * DBL_EPSILON;
    t = clampd(t + alpha * step, -3.0, 3.0);
  }
  cp.xi = held_a ? xi : t;
  cp.eta = held_a ? t : eta;
  return cp;
}

// ------------------------------------------------------------- the pair

template <class S>
struct Result {
  int status = B2B_CONTACT_OPEN;
  double info[B2B_PAIR_INFO_LEN] = {};
  double hist[16] = {};
  S R[kNdof];
  S energy = 0.0;
  double G[kNdof] = {};  // dg/dX (values, an active pair): the MAIN tangent's vector
  double slope = 0.0;    // df_N/dg
  double scale = 1.0;    // s: X' = (X - c)/s
  bool active = false, friction = false, intersecting = false;
  // For the line element (Hold::line) and the all-angle blend:
  S ta[3], tb[3];        // x_A,xi and x_B,eta at the final parameters (local units)
  bool tangents = false; // ta, tb are set (the closest points converged)
  S f = 0.0;             // the normal force f_N
  S J = 0.0;             // Hold::line: J = |x_A,xi(xi_i)| (original units)
  S dJ[12];              // Hold::line: dJ/dX on A's 12 coordinates
};

// Which parameters are held, and where (b2b_pair_eval_ends: at -1 or +1;
// the line element's integration points: A's at any xi_i). line: an
// integration point of b2b_pair_eval_line, whose info reports no end
// (END_A = 0), whose search starts from the projection onto B's chord
// (doc/line-contact.md 2) and which also returns J and dJ/dX.
struct Hold {
  bool a = false, b = false, line = false;
  double ta = 0.0, tb = 0.0;
};

// flags of evaluate (and b2b_ad_pair_eval_ex)
enum { kFreezeClosestPoints = 1, kLongDouble = 2 };

// The pair as b2b_pair.h specifies it. spec: A's and B's segment specs;
// X the 24 coordinates; hist_old of st.hist_len doubles. Returns a B2B_ERR_*
// status (the input checks are the caller's; only degenerate geometry is
// reported here).
template <class S>
int evaluate(const Settings& st, const SegmentSpec* spec, const double* X, const double* radii,
             const double* hist_old, int flags, const double* at, Result<S>& out,
             const Hold& hold) {
  // An end contact or a line point (hold: A's and/or B's parameter held):
  // the held parameters are constants of the problem, in the search, in the
  // scalar Newton steps (so their derivatives are zero) and in the force.
  const bool ha = hold.a, hb = hold.b;
  const double ta = hold.ta, tb = hold.tb;
  const bool any_held = ha || hb;
  out = Result<S>();
  std::memcpy(out.hist, hist_old, st.hist_len * sizeof(double));
  for (int i = 8; i < st.hist_len; ++i) out.hist[i] = 0.0;  // forgotten unless active
  for (int r = 0; r < kNdof; ++r) out.R[r] = 0.0;
  out.info[B2B_INFO_SYMMETRIC] = 1.0;

  // Local frame: origin A's x2 (read by every kind), unit s a power of two
  // near the sum of the chord lengths.
  const double* c = X + 3;
  double Y[24] = {0}, ends[2][2][3], chord[2];
  for (int b = 0; b < 2; ++b) {
    for (int s = 0; s < 4; ++s)
      if (spec[b].used & (1u << s))
        for (int i = 0; i < 3; ++i) Y[12 * b + 3 * s + i] = X[12 * b + 3 * s + i] - c[i];
    for (int e = 0; e < 2; ++e) {
      const TermSpec& t = spec[b].term[2 * e];
      for (int i = 0; i < 3; ++i) {
        double v = 0.0;
        for (int s = 0; s < 4; ++s)
          if (t.coef[s] != 0.0) v += t.coef[s] * Y[12 * b + 3 * s + i];
        ends[b][e][i] = v;
      }
    }
    const double dv[3] = {ends[b][1][0] - ends[b][0][0], ends[b][1][1] - ends[b][0][1],
                          ends[b][1][2] - ends[b][0][2]};
    chord[b] = norm3(dv);
  }
  // The rounding of d = x_A - x_B scales with the pair's extent about A's
  // start point (the library works relative to it too).
  double extent = 0.0;
  for (int b = 0; b < 2; ++b)
    for (int e = 0; e < 2; ++e)
      for (int i = 0; i < 3; ++i)
        extent = std::fmax(extent, std::fabs(ends[b][e][i] - ends[0][0][i]));
  const double ell = chord[0] + chord[1];
  if (!(ell > 0.0) || !std::isfinite(ell)) return B2B_ERR_COINCIDENT;
  const double s = std::ldexp(1.0, std::ilogb(ell));
  out.scale = s;
  // The length tolerance of doc/contact-element.md 4 (the band of 6), in
  // original units, then local
  const double tol_length = 1e-13 * ell + 64.0 * DBL_EPSILON * extent;
  const double tol_local = tol_length / s;

  // The local coordinates: in double for the search, in the scalar's real
  // type for the reference (X - c rounds only there).
  using Real = typename RealOf<S>::type;
  double Xl[24] = {0};
  S Xs[24];
  for (int b = 0; b < 2; ++b)
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) {
        const int a = 12 * b + 3 * k + i;
        Xl[a] = Y[a] / s;
        const Real y = (spec[b].used & (1u << k)) ? (Real(X[a]) - Real(c[i])) / Real(s) : Real(0);
        Xs[a] = Seed<S>::make(y, a);
      }
  Segment<double> gA, gB;  // for the value-only iteration
  Segment<S> sA, sB;
  if (int e = build(spec[0], Xl, gA)) return e;
  if (int e = build(spec[1], Xl + 12, gB)) return e;
  if (int e = build(spec[0], Xs, sA)) return e;
  if (int e = build(spec[1], Xs + 12, sB)) return e;
  if (hold.line) {
    // the length element of the integration point, J = |x_A,xi(xi_i)| in
    // original units, and dJ/dX = P_A,xi^T e (e = x_A,xi / |x_A,xi|), in the
    // scalar type: its derivative, the length element's second variation,
    // comes from AD
    S xa[3], a[3], e[3];
    point(sA, ta, xa, a, (S*)nullptr);
    const S na = norm3(a);
    out.J = s * na;
    for (int i = 0; i < 3; ++i) e[i] = a[i] / na;
    for (int r = 0; r < 12; ++r) out.dJ[r] = 0.0;
    add_PTw(sA, ta, e, 1.0, out.dJ, 1);
  }

  // Closest points: safeguarded Newton in double to the library's criterion.
  const bool has_history = hist_old[kTag] == 1.0;
  const bool has_normal = has_history && hist_old[kHasNormal] == 1.0;
  double xi0, eta0;
  if (st.warm_start && has_history) {
    xi0 = clampd(hist_old[kXi], -1.0, 1.0);
    eta0 = clampd(hist_old[kEta], -1.0, 1.0);
  } else {
    chord_start(gA, gB, &xi0, &eta0);
  }
  if (ha) xi0 = ta;
  if (hb) eta0 = tb;
  if (hold.line && ha && !hb && !(st.warm_start && has_history)) {
    // doc/line-contact.md 2: from the projection of x_A(xi_i) onto B's
    // chord, clamped to the segment (the chords' closest points are
    // undefined for parallel chords)
    double xa[3], ch[3], dd[3];
    point(gA, ta, xa, (double*)nullptr, (double*)nullptr);
    for (int i = 0; i < 3; ++i) {
      ch[i] = gB.value[2][i] - gB.value[0][i];
      dd[i] = xa[i] - 0.5 * (gB.value[0][i] + gB.value[2][i]);
    }
    const double cc = dot3(ch, ch);
    eta0 = cc > 0.0 ? clampd(2.0 * dot3(dd, ch) / cc, -1.0, 1.0) : 0.0;
  }
  Closest cp;
  if (at) {  // given closest points (a diagnostic): no search
    cp.converged = true;
    cp.xi = ha ? ta : at[0];
    cp.eta = hb ? tb : at[1];
  } else if (ha && hb) {  // node to node: nothing to search
    cp.converged = true;
    cp.xi = ta;
    cp.eta = tb;
  } else if (any_held) {
    cp = newton_held(gA, gB, xi0, eta0, ha, st.max_iterations, tol_local);
  } else {
    cp = newton(gA, gB, xi0, eta0, st.max_iterations, tol_local);
  }
  double* info = out.info;
  info[B2B_INFO_END_A] = hold.line ? 0.0 : (ha ? ta : 0.0);
  info[B2B_INFO_END_B] = hold.line ? 0.0 : (hb ? tb : 0.0);
  info[B2B_INFO_XI] = cp.xi;
  info[B2B_INFO_ETA] = cp.eta;
  info[B2B_INFO_ITERATIONS] = cp.iterations;
  if (!cp.converged) {
    // doc/contact-element.md 4: a search that stopped where the axes are
    // within the parallel angle, or where a centreline almost stops (speed
    // below 1% of its chord's), is PARALLEL; else OUTSIDE if it ran off the
    // segments, else NOT_CONVERGED.
    double xa[3], a[3], a2[3], xb[3], b[3], b2[3], cr[3];
    point(gA, cp.xi, xa, a, a2);
    point(gB, cp.eta, xb, b, b2);
    cross3(a, b, cr);
    const double na = norm3(a), nb = norm3(b);
    const double la = chord[0] / s, lb = chord[1] / s;  // local units, as a, b
    const bool cusp = !(na > 0.005 * la) || !(nb > 0.005 * lb);
    if (cusp || (!any_held && !(norm3(cr) > st.sin_parallel * na * nb)))
      out.status = B2B_CONTACT_PARALLEL;
    else
      out.status = (std::fabs(cp.xi) > 1.0 || std::fabs(cp.eta) > 1.0) ? B2B_CONTACT_OUTSIDE
                                                                        : B2B_CONTACT_NOT_CONVERGED;
    return B2B_OK;
  }

  // Crossing angle and the Hessian's determinant at the converged point
  // (doc/contact-element.md 5): PARALLEL below the threshold.
  {
    double xa[3], a[3], a2[3], xb[3], b[3], b2[3], d[3], cr[3];
    point(gA, cp.xi, xa, a, a2);
    point(gB, cp.eta, xb, b, b2);
    for (int i = 0; i < 3; ++i) d[i] = xa[i] - xb[i];
    for (int i = 0; i < 3; ++i) {
      info[B2B_INFO_POINT_A + i] = c[i] + s * xa[i];
      info[B2B_INFO_POINT_B + i] = c[i] + s * xb[i];
    }
    const double na = norm3(a), nb = norm3(b);
    // a cusp (speed below 1% of the chord's): no crossing angle, no unique
    // normal (doc/contact-element.md 5)
    if (!(na > 0.005 * chord[0] / s) || !(nb > 0.005 * chord[1] / s)) {
      info[B2B_INFO_ANGLE] = 0.0;
      out.status = B2B_CONTACT_PARALLEL;
      return B2B_OK;
    }
    cross3(a, b, cr);
    const double sin_angle = norm3(cr) / (na * nb);
    const double cos_angle = std::fabs(dot3(a, b)) / (na * nb);
    const double h11 = dot3(a, a) + dot3(d, a2), h22 = dot3(b, b) - dot3(d, b2);
    const double h12 = -dot3(a, b);
    const double det = h11 * h22 - h12 * h12;
    info[B2B_INFO_ANGLE] = std::atan2(sin_angle, cos_angle) * 180.0 / 3.14159265358979323846;
    // An end contact has no crossing-angle threshold: PARALLEL only where
    // the free parameter's 1-D problem is singular (its curvature not
    // positive, the 1-D analogue of det > 1e-12 |a|^2 |b|^2).
    const bool singular = any_held ? (ha && hb ? false
                                               : ha ? !(h22 > 1e-12 * nb * nb)
                                                    : !(h11 > 1e-12 * na * na))
                                   : (sin_angle < st.sin_parallel ||
                                      !(det > 1e-12 * na * na * nb * nb));
    if (singular) {
      out.status = B2B_CONTACT_PARALLEL;
      return B2B_OK;
    }
  }

  // Two plain Newton steps in the scalar type from the converged point: the
  // values are polished, and the derivatives become -H^-1 dr/dX.
  S xi = cp.xi, eta = cp.eta;
  for (int step = 0; step < 2 && any_held; ++step) {  // the held ones stay constants
    if (ha && hb) break;
    S xa[3], a[3], a2[3], xb[3], b[3], b2[3], d[3];
    point(sA, xi, xa, a, a2);
    point(sB, eta, xb, b, b2);
    for (int i = 0; i < 3; ++i) d[i] = xa[i] - xb[i];
    if (ha)
      eta = eta - (-dot3(d, b)) / (dot3(b, b) - dot3(d, b2));
    else
      xi = xi - dot3(d, a) / (dot3(a, a) + dot3(d, a2));
  }
  for (int step = 0; step < 2 && !any_held; ++step) {
    S xa[3], a[3], a2[3], xb[3], b[3], b2[3], d[3];
    point(sA, xi, xa, a, a2);
    point(sB, eta, xb, b, b2);
    for (int i = 0; i < 3; ++i) d[i] = xa[i] - xb[i];
    const S r1 = dot3(d, a), r2 = -dot3(d, b);
    const S h11 = dot3(a, a) + dot3(d, a2), h22 = dot3(b, b) - dot3(d, b2);
    const S h12 = -dot3(a, b);
    const S det = h11 * h22 - h12 * h12;
    xi = xi - (h22 * r1 - h12 * r2) / det;
    eta = eta - (h11 * r2 - h12 * r1) / det;
  }
  if (at) {  // keep the given values, with the derivatives of the steps
    if (!ha) xi = with_value(xi, at[0]);
    if (!hb) eta = with_value(eta, at[1]);
  }
  if (flags & kFreezeClosestPoints) {  // a deliberately wrong reference
    xi = S(val(xi));
    eta = S(val(eta));
  }
  S xa[3], a[3], xb[3], b[3], d[3];
  point(sA, xi, xa, a, (S*)nullptr);
  point(sB, eta, xb, b, (S*)nullptr);
  for (int i = 0; i < 3; ++i) d[i] = xa[i] - xb[i];
  for (int i = 0; i < 3; ++i) {
    out.ta[i] = a[i];
    out.tb[i] = b[i];
  }
  out.tangents = true;
  info[B2B_INFO_XI] = val(xi);
  info[B2B_INFO_ETA] = val(eta);
  {
    double av[3] = {dval(a[0]), dval(a[1]), dval(a[2])},
           bv[3] = {dval(b[0]), dval(b[1]), dval(b[2])};
    double cr[3];
    cross3(av, bv, cr);
    const double na = norm3(av), nb = norm3(bv);
    info[B2B_INFO_ANGLE] = std::atan2(norm3(cr) / (na * nb), std::fabs(dot3(av, bv)) / (na * nb)) *
                           180.0 / 3.14159265358979323846;
    for (int i = 0; i < 3; ++i) {
      info[B2B_INFO_POINT_A + i] = c[i] + s * val(xa[i]);
      info[B2B_INFO_POINT_B + i] = c[i] + s * val(xb[i]);
    }
  }

  // Sign-tracked normal and gap (doc/contact-element.md 6).
  const double dv[3] = {dval(d[0]), dval(d[1]), dval(d[2])};
  const double rho0 = s * norm3(dv);
  S n[3], gap;
  if (rho0 <= tol_length) {  // the axes intersect: the history's normal, held fixed
    if (!has_normal) {
      out.status = B2B_CONTACT_NO_NORMAL;
      return B2B_OK;
    }
    for (int i = 0; i < 3; ++i) n[i] = hist_old[kNormal + i];
    gap = -radii[0] - radii[1];
    out.intersecting = true;
  } else {
    const double sign = (has_normal && dot3(dv, hist_old + kNormal) < 0.0) ? -1.0 : 1.0;
    const S rho = sign * norm3(d);  // local units
    for (int i = 0; i < 3; ++i) n[i] = d[i] / rho;
    gap = (s * rho - radii[0]) - radii[1];
  }
  for (int i = 0; i < 3; ++i) info[B2B_INFO_NORMAL + i] = val(n[i]);
  info[B2B_INFO_GAP] = val(gap);
  out.hist[kTag] = 1.0;
  out.hist[kHasNormal] = 1.0;
  for (int i = 0; i < 3; ++i) out.hist[kNormal + i] = val(n[i]);
  out.hist[kXi] = val(xi);
  out.hist[kEta] = val(eta);

  // Ownership (doc/contact-element.md 7): [-1, 1), a joint within 1e-13
  // chord lengths; the end joint stays with the segment at a beam end.
  auto owns = [](double t, double speed, double len, bool beam_ends_here) {
    const double band = 1e-13 * len;
    if (std::fabs(t + 1.0) * speed <= band) return true;
    if (std::fabs(t - 1.0) * speed <= band) return beam_ends_here;
    return t > -1.0 && t < 1.0;
  };
  {
    const double av[3] = {dval(a[0]), dval(a[1]), dval(a[2])};
    const double bv[3] = {dval(b[0]), dval(b[1]), dval(b[2])};
    // a held parameter needs no ownership test (the caller's decision)
    if ((!ha && !owns(dval(xi), norm3(av), chord[0] / s, spec[0].end_rule != B2B_END_NEIGHBOUR)) ||
        (!hb && !owns(dval(eta), norm3(bv), chord[1] / s, spec[1].end_rule != B2B_END_NEIGHBOUR))) {
      out.status = B2B_CONTACT_OUTSIDE;
      return B2B_OK;
    }
  }

  // Normal law (doc/contact-element.md 8).
  S f = 0.0;
  const double eps = st.penalty;
  if (eps != 0.0) {
    if (st.law == B2B_LAW_LINEAR) {
      if (val(gap) < 0.0) {
        f = -eps * gap;
        out.slope = -eps;
        out.energy = 0.5 * eps * (gap * gap);
      }
    } else {
      const double g0 = st.g0;
      if (val(gap) <= 0.0) {
        f = eps * (0.5 * g0 - gap);
        out.slope = -eps;
        out.energy = eps * (g0 * g0 / 6.0 - 0.5 * g0 * gap + 0.5 * (gap * gap));
      } else if (val(gap) < g0) {
        const S h = g0 - gap;
        f = (eps / (2.0 * g0)) * (h * h);
        out.slope = -eps * dval(h) / g0;
        out.energy = (eps / (6.0 * g0)) * (h * h * h);
      }
    }
  }
  out.f = f;
  info[B2B_INFO_NORMAL_FORCE] = val(f);
  info[B2B_INFO_ENERGY] = val(out.energy);
  if (!(val(f) > 0.0)) {
    out.status = B2B_CONTACT_OPEN;
    return B2B_OK;
  }
  out.status = B2B_CONTACT_ACTIVE;
  out.active = true;

  // Friction (doc/friction.md 2-5): the force T on B by A.
  S T[3] = {0.0, 0.0, 0.0};
  if (st.mu > 0.0) {
    out.friction = true;
    info[B2B_INFO_SYMMETRIC] = 0.0;
    S e1[3], e2[3];
    if (!any_held) {
      const S speed = norm3(a);
      for (int i = 0; i < 3; ++i) e1[i] = a[i] / speed;
    } else {
      // an end contact: A's tangent in the tangent plane,
      // (I - n n^T) t / |(I - n n^T) t| (b2b_pair.h, Transport), unless its
      // sin^2 to n is below 1e-2: then B's if that is larger, and where
      // both are below 1e-6 the unit axis of the smallest |n_i| (the first)
      S axis[3] = {0.0, 0.0, 0.0};
      const S* t = a;
      const double ca = dval(dot3(n, a)) / dval(norm3(a));
      const double sa = 1.0 - ca * ca;
      if (sa < 1e-2) {
        const double cb = dval(dot3(n, b)) / dval(norm3(b)), sb = 1.0 - cb * cb;
        if (sb >= sa) t = b;
        if (std::fmax(sa, sb) < 1e-6) {
          int k = 0;
          for (int i = 1; i < 3; ++i)
            if (std::fabs(dval(n[i])) < std::fabs(dval(n[k]))) k = i;
          axis[k] = 1.0;
          t = axis;
        }
      }
      const S tn = dot3(n, t);
      for (int i = 0; i < 3; ++i) e1[i] = t[i] - tn * n[i];
      const S len = norm3(e1);
      for (int i = 0; i < 3; ++i) e1[i] = e1[i] / len;
    }
    cross3(n, e1, e2);
    int state = B2B_FRICTION_STICK;
    const bool anchored =
        has_history && st.hist_len > kFrictionState && hist_old[kInContact] == 1.0;
    if (anchored) {  // else a new contact: stick with T = 0
      const double c1 = hist_old[kForceE1], c2 = hist_old[kForceE2];
      S xan[3], xbn[3], dn[3], tr[3];
      point(sA, hist_old[kXi], xan, (S*)nullptr, (S*)nullptr);
      point(sB, hist_old[kEta], xbn, (S*)nullptr, (S*)nullptr);
      for (int i = 0; i < 3; ++i) dn[i] = xan[i] - xbn[i];
      if (hold.line) {
        // a line point's slip is read at B's surface (doc/line-contact.md 5):
        // the anchor on B is r_B m off its axis point, m the committed normal
        // made normal to B's current tangent at eta_n (unless that is
        // degenerate, |(I - t t^T) n_n| <= 1e-8)
        S xbt[3], tbn[3], pv[3];
        point(sB, hist_old[kEta], xbt, tbn, (S*)nullptr);
        const S tl = norm3(tbn);
        S tn = 0.0;
        for (int i = 0; i < 3; ++i) tn = tn + tbn[i] / tl * hist_old[kNormal + i];
        for (int i = 0; i < 3; ++i) pv[i] = hist_old[kNormal + i] - tn * (tbn[i] / tl);
        const S pl = norm3(pv);
        if (dval(pl) > 1e-8)
          for (int i = 0; i < 3; ++i) dn[i] = dn[i] - (radii[1] / s) * (pv[i] / pl);
      }
      const S nd = dot3(n, dn);
      for (int i = 0; i < 3; ++i) {
        const S gt = s * (dn[i] - nd * n[i]);  // g_T in original units
        tr[i] = (c1 * e1[i] + c2 * e2[i]) + st.eps_t * gt;
      }
      const double tr_norm = dval(hypot3(val(tr[0]), val(tr[1]), val(tr[2])));
      const S limit = st.mu * f;
      if (tr_norm <= dval(limit)) {
        for (int i = 0; i < 3; ++i) T[i] = tr[i];
      } else {
        state = B2B_FRICTION_SLIP;
        const S trn = norm3(tr);
        const double excess = tr_norm - dval(limit);
        for (int i = 0; i < 3; ++i) {
          T[i] = limit * (tr[i] / trn);
          info[B2B_INFO_SLIP + i] = excess / st.eps_t * (dval(tr[i]) / tr_norm);
        }
        info[B2B_INFO_DISSIPATION] = dval(limit) * (excess / st.eps_t);
      }
    }
    for (int i = 0; i < 3; ++i) info[B2B_INFO_TANGENTIAL_FORCE + i] = val(T[i]);
    info[B2B_INFO_FRICTION_STATE] = state;
    out.hist[kInContact] = 1.0;
    out.hist[kForceE1] = val(dot3(T, e1));
    out.hist[kForceE2] = val(dot3(T, e2));
    out.hist[kFrictionState] = state;
  }
  if (out.intersecting) info[B2B_INFO_SYMMETRIC] = 0.0;

  // Residual R = J^T (T - f n), J = [P_A, -P_B] at xi, eta.
  S w[3];
  for (int i = 0; i < 3; ++i) w[i] = T[i] - f * n[i];
  add_PTw(sA, xi, w, 1.0, out.R);
  add_PTw(sB, eta, w, -1.0, out.R + 12);

  // G = dg/dX = J^T n (values): the MAIN tangent's vector.
  {
    const double nv[3] = {dval(n[0]), dval(n[1]), dval(n[2])};
    add_PTw(gA, dval(xi), nv, 1.0, out.G);
    add_PTw(gB, dval(eta), nv, -1.0, out.G + 12);
  }
  return B2B_OK;
}

// The end contact's form: held[2] = A's and B's parameter held at -1 or +1,
// 0 free (NULL: none held).
template <class S>
int evaluate(const Settings& st, const SegmentSpec* spec, const double* X, const double* radii,
             const double* hist_old, int flags, const double* at, Result<S>& out,
             const int* held = nullptr) {
  Hold h;
  if (held) {
    h.a = held[0] != 0, h.b = held[1] != 0;
    h.ta = held[0], h.tb = held[1];
  }
  return evaluate(st, spec, X, radii, hist_old, flags, at, out, h);
}

}  // namespace b2bad
