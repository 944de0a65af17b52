#include "segment_distance.hpp"

#include <algorithm>
#include <cmath>

namespace b2b {
namespace model {

namespace {

constexpr int kSamples = 5;       // per segment: xi = -1, -0.5, 0, 0.5, 1
constexpr int kMaxSteps = 24;     // Newton steps
constexpr double kEndTol = 1e-6;  // a parameter this close to +-1 is on the end

double dot(const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

struct Eval {
  double xa[3], ta[3], aa[3], xb[3], tb[3], bb[3], d[3];  // d = xA - xB
  double f;                                               // |d|^2 / 2
};

void evaluate(const Cubic& a, const Cubic& b, double xi, double eta, Eval& e) {
  a.eval(xi, e.xa, e.ta, e.aa);
  b.eval(eta, e.xb, e.tb, e.bb);
  for (int i = 0; i < 3; ++i) e.d[i] = e.xa[i] - e.xb[i];
  e.f = 0.5 * dot(e.d, e.d);
}

double clamp1(double t) { return std::min(1.0, std::max(-1.0, t)); }

}  // namespace

Cubic Cubic::of(const curve::Segment& s) {
  // From x(-1) = P0, x(1) = P1, x'(-1) = T0, x'(1) = T1.
  double p0[3], t0[3], p1[3], t1[3];
  s.point(-1.0, p0, t0, nullptr);
  s.point(1.0, p1, t1, nullptr);
  Cubic q;
  for (int i = 0; i < 3; ++i) {
    q.c[i] = 0.25 * (t1[i] - t0[i]);
    q.d[i] = 0.25 * (t0[i] + t1[i] - (p1[i] - p0[i]));
    q.a[i] = 0.5 * (p0[i] + p1[i]) - q.c[i];
    q.b[i] = 0.5 * (p1[i] - p0[i]) - q.d[i];
    q.p0[i] = p0[i];
    q.p1[i] = p1[i];
  }
  // x(xi) - chord(xi) = c (xi^2 - 1) + d (xi^3 - xi), and on [-1, 1]
  // |xi^2 - 1| <= 1, |xi^3 - xi| <= 2 / (3 sqrt 3) < 0.3850.
  q.bulge = std::sqrt(dot(q.c, q.c)) + 0.3850 * std::sqrt(dot(q.d, q.d));
  return q;
}

double distance_lower_bound(const Cubic& a, const Cubic& b) {
  // Closest points of the chords p = a.p0 + s u, q = b.p0 + t v, s, t in
  // [0, 1]: the unconstrained minimum, clamped in s, t re-solved for s
  // clamped, then s re-solved for that t.
  double u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = a.p1[i] - a.p0[i];
    v[i] = b.p1[i] - b.p0[i];
    w[i] = a.p0[i] - b.p0[i];
  }
  const double uu = dot(u, u), vv = dot(v, v), uv = dot(u, v), uw = dot(u, w), vw = dot(v, w);
  const auto clamp01 = [](double t) { return std::min(1.0, std::max(0.0, t)); };
  double s = 0.0, t = 0.0;
  const double det = uu * vv - uv * uv;
  if (uu > 0.0 && det > 1e-12 * uu * vv) s = clamp01((uv * vw - vv * uw) / det);
  if (vv > 0.0) t = (uv * s + vw) / vv;
  if (t < 0.0 || t > 1.0 || !(vv > 0.0)) {
    t = vv > 0.0 ? clamp01(t) : 0.0;
    s = uu > 0.0 ? clamp01((uv * t - uw) / uu) : 0.0;
  }
  double d[3];
  for (int i = 0; i < 3; ++i) d[i] = w[i] + s * u[i] - t * v[i];
  // Less a slack for a nearly parallel pair (det tiny: s = 0 need not be
  // the chords' closest point, off by at most ~1e-6 of their lengths).
  const double slack = 1e-6 * (std::sqrt(uu) + std::sqrt(vv));
  return std::sqrt(dot(d, d)) - a.bulge - b.bulge - slack;
}

int at_segment_end(double t) {
  if (t >= 1.0 - kEndTol) return 1;
  if (t <= -1.0 + kEndTol) return -1;
  return 0;
}

SegmentClosest closest_between(const Cubic& a, const Cubic& b) {
  // 1. the closest pair of samples
  double pa[kSamples][3], pb[kSamples][3];
  for (int k = 0; k < kSamples; ++k) {
    const double t = -1.0 + 2.0 * k / (kSamples - 1);
    a.eval(t, pa[k], nullptr, nullptr);
    b.eval(t, pb[k], nullptr, nullptr);
  }
  int bi = 0, bj = 0;
  double best = HUGE_VAL;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const double d[3] = {pa[i][0] - pb[j][0], pa[i][1] - pb[j][1], pa[i][2] - pb[j][2]};
      const double d2 = dot(d, d);
      if (d2 < best) best = d2, bi = i, bj = j;
    }
  double x[2] = {-1.0 + 2.0 * bi / (kSamples - 1), -1.0 + 2.0 * bj / (kSamples - 1)};
  Eval e;
  evaluate(a, b, x[0], x[1], e);
  // 2. projected Newton on f(xi, eta) = |xA - xB|^2 / 2 in [-1, 1]^2
  for (int step = 0; step < kMaxSteps; ++step) {
    const double g[2] = {dot(e.d, e.ta), -dot(e.d, e.tb)};
    double H[2][2] = {{dot(e.ta, e.ta) + dot(e.d, e.aa), -dot(e.ta, e.tb)},
                      {-dot(e.ta, e.tb), dot(e.tb, e.tb) - dot(e.d, e.bb)}};
    // Away from a positive definite Hessian (curved segments far apart):
    // Gauss-Newton, whose matrix is semi-definite; a small shift keeps it
    // invertible for parallel segments.
    const double shift = 1e-12 * (H[0][0] + H[1][1] + 1e-300);
    if (!(H[0][0] > 0.0 && H[1][1] > 0.0 && H[0][0] * H[1][1] - H[0][1] * H[1][0] > 0.0)) {
      H[0][0] = dot(e.ta, e.ta);
      H[1][1] = dot(e.tb, e.tb);
    }
    H[0][0] += shift;
    H[1][1] += shift;
    // Active set: a variable on a bound whose gradient pushes it out stays there.
    bool fixed[2];
    for (int k = 0; k < 2; ++k)
      fixed[k] = (x[k] >= 1.0 && g[k] < 0.0) || (x[k] <= -1.0 && g[k] > 0.0);
    double dx[2] = {0.0, 0.0};
    if (!fixed[0] && !fixed[1]) {
      const double det = H[0][0] * H[1][1] - H[0][1] * H[1][0];
      if (det > 0.0) {
        dx[0] = -(H[1][1] * g[0] - H[0][1] * g[1]) / det;
        dx[1] = -(H[0][0] * g[1] - H[1][0] * g[0]) / det;
      } else {
        dx[0] = -g[0] / H[0][0];
        dx[1] = -g[1] / H[1][1];
      }
    } else if (!fixed[0]) {
      dx[0] = -g[0] / H[0][0];
    } else if (!fixed[1]) {
      dx[1] = -g[1] / H[1][1];
    }
    if (!(std::fabs(dx[0]) + std::fabs(dx[1]) > 1e-14)) break;
    // Halve the (projected) step until the distance decreases.
    bool moved = false;
    double s = 1.0;
    for (int halving = 0; halving < 30; ++halving, s *= 0.5) {
      const double y[2] = {clamp1(x[0] + s * dx[0]), clamp1(x[1] + s * dx[1])};
      if (y[0] == x[0] && y[1] == x[1]) break;
      Eval t;
      evaluate(a, b, y[0], y[1], t);
      if (t.f < e.f) {
        const double change = std::fabs(y[0] - x[0]) + std::fabs(y[1] - x[1]);
        x[0] = y[0];
        x[1] = y[1];
        e = t;
        moved = change > 1e-13;
        break;
      }
    }
    if (!moved) break;
  }
  SegmentClosest c;
  c.xi = x[0];
  c.eta = x[1];
  for (int i = 0; i < 3; ++i) {
    c.d[i] = -e.d[i];
    c.ta[i] = e.ta[i];
    c.tb[i] = e.tb[i];
  }
  c.dist = std::sqrt(dot(e.d, e.d));
  return c;
}

}  // namespace model
}  // namespace b2b
