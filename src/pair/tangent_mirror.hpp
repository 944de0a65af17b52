// The symmetric tangent's lower triangle from its upper one, with the
// finiteness check that must pass before a tangent leaves the library. In
// a header of their own so that tests/check/check_finite.cpp can hold the
// check both ways round, its fallback for a sum that overflows included.
#pragma once

#include "../common/finite.hpp"
#include "linearization.hpp"

namespace b2b {
namespace pair {

// K[r][c] = K[c][r] below the diagonal: the lower triangle becomes a copy of
// the upper one.
inline void mirror_upper(double* K, int n, int ld) {
  for (int c = 0; c < n; ++c)
    for (int r = c + 1; r < n; ++r) K[r + ld * c] = K[c + ld * r];
}

// The lower triangle of K (kNdof x kNdof) becomes a copy of the upper one,
// and whether the upper one (and so all of K) is finite: the entries are
// summed as they are read, and a finite sum settles it (all_finite_by_sum's
// argument); a sum that is not finite needs the exact check (it may have
// overflowed over finite entries). Two columns at a time, so that each pair
// read from the upper triangle is contiguous (K[c, r], K[c + 1, r]); one
// loop over the triangle instead of a mirror and a finiteness check each
// reading all of it.
inline bool mirror_upper_checked(double* K) {
  static_assert(kNdof % 2 == 0, "columns in pairs");
  double z0 = 0.0, z1 = 0.0;
  for (int c = 0; c < kNdof; c += 2) {
    double* k0 = K + kNdof * c;  // columns c and c + 1
    double* k1 = k0 + kNdof;
    const double u = k1[c];  // (c, c + 1)
    z0 += k0[c] + u;
    z1 += k1[c + 1];
    k0[c + 1] = u;
    for (int r = c + 2; r < kNdof; r += 2) {  // an even count of rows: two at a time
      const double* s0 = K + kNdof * r + c;  // (c, r) and (c + 1, r)
      const double* s1 = s0 + kNdof;         // (c, r + 1) and (c + 1, r + 1)
      const double x0 = s0[0], x1 = s0[1], y0 = s1[0], y1 = s1[1];
      k0[r] = x0;
      k0[r + 1] = y0;
      k1[r] = x1;
      k1[r + 1] = y1;
      z0 += x0 + y0;
      z1 += x1 + y1;
    }
  }
  const double sum = z0 + z1;
  return sum - sum == 0.0 || all_finite4(K, kNdof * kNdof);
}

// The compact upper triangle (m x m, leading dimension kNdof) mirrored into
// its lower one; whether it is finite.
inline bool mirror_compact_checked(double* Kc, int m) {
  bool finite = true;
  for (int c = 0; c < m; ++c) finite = finite && all_finite(Kc + kNdof * c, c + 1);
  mirror_upper(Kc, m, kNdof);
  return finite;
}

}  // namespace pair
}  // namespace b2b
