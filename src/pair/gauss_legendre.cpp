#include "gauss_legendre.hpp"

#include <cmath>

namespace b2b {
namespace pair {
namespace {

struct Rule {
  double x[kGaussMaxPoints], w[kGaussMaxPoints];
};

// The roots of P_n by Newton from Chebyshev-like guesses (Tricomi's
// asymptotic cos(pi (i + 3/4) / (n + 1/2)) is close enough that Newton
// converges to the i-th root), the weights 2 / ((1 - x^2) P_n'(x)^2).
// P_n and P_n' by the three-term recurrence, stable on [-1, 1].
Rule make_rule(int n) {
  Rule r{};
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = n == 1 ? x : p1, pm = n == 1 ? 1.0 : p0;  // P_n, P_{n-1}
      dp = n * (x * pn - pm) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) break;
    }
    // recompute P_n' at the converged root for the weight
    double p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    const double pn = n == 1 ? x : p1, pm = n == 1 ? 1.0 : p0;
    dp = n * (x * pn - pm) / (x * x - 1.0);
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    // x is the i-th largest root: mirror it
    r.x[n - 1 - i] = x;
    r.x[i] = -x;
    r.w[n - 1 - i] = r.w[i] = w;
  }
  if (n % 2 == 1) r.x[n / 2] = 0.0;  // exactly
  return r;
}

struct Table {
  Rule rules[kGaussMaxPoints + 1];
  Table() {
    for (int n = 1; n <= kGaussMaxPoints; ++n) rules[n] = make_rule(n);
  }
};

}  // namespace

void gauss_legendre(int n, const double** points, const double** weights) {
  static const Table table;  // built once, on first use (thread-safe in C++11)
  *points = table.rules[n].x;
  *weights = table.rules[n].w;
}

}  // namespace pair
}  // namespace b2b
