// Normal contact laws: force f_N(g) >= 0 (compressive), its slope df_N/dg and
// the potential Pi(g) = integral from g to infinity of f_N, so that
// dPi/dg = -f_N (doc/contact-element.md section 8).
#pragma once

#include <b2b/b2b.h>

#include "laws.hpp"
#include "params.hpp"

namespace b2b {
namespace pair {

struct LawValue {
  double force = 0.0;   // f_N
  double slope = 0.0;   // df_N/dg
  double energy = 0.0;  // Pi
};

inline LawValue normal_law(const Params& p, double g) {
  LawValue v;
  const double eps = p.penalty;
  if (eps == 0.0) return v;  // no force: nothing to multiply by an overflowing g0^2
  switch (law_of(p.law)) {
    case Law::Linear:
      if (g < 0.0) {
        v.force = -eps * g;
        v.slope = -eps;
        v.energy = 0.5 * eps * g * g;
      }
      return v;
    case Law::Quadratic: {
      // LinPosQuadPen: linear for g <= 0, quadratic up to g0. Products are
      // ordered so that no intermediate overflows where the result does not
      // (g0 may be as large as a double allows: h/g0 <= 1).
      const double g0 = p.regularization_gap;
      if (g <= 0.0) {
        v.force = eps * (0.5 * g0 - g);
        v.slope = -eps;
        v.energy = eps * g0 * (g0 / 6.0 - 0.5 * g) + 0.5 * eps * g * g;
      } else if (g < g0) {
        const double h = g0 - g, r = h / g0;
        v.force = eps * h * (0.5 * r);
        v.slope = -eps * r;
        v.energy = eps * h * r * (h / 6.0);
      }
      return v;
    }
  }
  return v;  // not reached: "law" holds a B2B_LAW_* value, each a case above
}

}  // namespace pair
}  // namespace b2b
