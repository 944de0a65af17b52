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

}  // namespace b2b
