// Whether an array holds only finite numbers: the guard on outputs that
// would otherwise let an overflow (Inf) or NaN out of the library.
#pragma once

namespace b2b {

// v * 0 is (+-)0 for finite v and NaN otherwise. Two independent sums: the
// compiler may not reorder (nor vectorise) a floating-point sum, and one
// chain of dependent additions costs as much as the rest of a small tangent.
inline bool all_finite(const double* v, int n) {
  double a0 = 0.0, a1 = 0.0;
  int i = 0;
  for (; i + 1 < n; i += 2) {
    a0 += v[i] * 0.0;
    a1 += v[i + 1] * 0.0;
  }
  if (i < n) a0 += v[i] * 0.0;
  return a0 + a1 == 0.0;
}

// Whether the n contiguous entries of v are finite (n a multiple of 4):
// entry * 0 summed in four independent parts, which the compiler packs into
// two vector sums (all_finite's two scalar sums, column by column, cost
// half as much again on the whole of K).
inline bool all_finite4(const double* v, int n) {
  double a0 = 0.0, a1 = 0.0, a2 = 0.0, a3 = 0.0;
  for (int i = 0; i < n; i += 4) {
    a0 += v[i] * 0.0;
    a1 += v[i + 1] * 0.0;
    a2 += v[i + 2] * 0.0;
    a3 += v[i + 3] * 0.0;
  }
  return (a0 + a1) + (a2 + a3) == 0.0;
}

// The same answer at one addition per entry (n a multiple of 8): the plain
// sum of the entries is finite only if every entry is (an Inf or a NaN makes
// every partial sum after it Inf or NaN, opposite infinities NaN), so a
// finite sum settles it. Only a sum that overflows although every entry is
// finite (a tangent near the double range) needs the exact check
// (tests/check/check_finite.cpp holds both ways). Eight independent sums,
// which the compiler packs into four vector sums (with four, as
// all_finite4, the loop costs a quarter more). Not inlined: in
// pair::assemble_tangent it changed the code of the frictionless path
// around it (82 instructions more per nodal evaluation, in
// mirror_upper_checked's loop), which never calls it.
#if defined(__GNUC__)
__attribute__((noinline))
#endif
inline bool all_finite_by_sum(const double* v, int n) {
  double a[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < n; i += 8)
    for (int j = 0; j < 8; ++j) a[j] += v[i + j];
  const double sum = ((a[0] + a[1]) + (a[2] + a[3])) + ((a[4] + a[5]) + (a[6] + a[7]));
  return sum - sum == 0.0 || all_finite4(v, n);
}

}  // namespace b2b
