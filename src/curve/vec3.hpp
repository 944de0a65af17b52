// Small fixed-size vector helpers for the curve layer. Header-only so the
// compiler can inline them into the hot loops.
#pragma once

#include <algorithm>
#include <cmath>

namespace b2b {
namespace curve {

inline double dot3(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline void sub3(const double* a, const double* b, double* out) {
  out[0] = a[0] - b[0];
  out[1] = a[1] - b[1];
  out[2] = a[2] - b[2];
}

// Inputs are finite (checked at the C boundary), so std::max needs no NaN care.
inline double max_abs3(const double* a) {
  return std::max(std::fabs(a[0]), std::max(std::fabs(a[1]), std::fabs(a[2])));
}

// Euclidean length. Inputs are bounded by B2B_COORD_MAX (checked at the C
// boundary), so the plain sum of squares cannot overflow.
inline double norm3(const double* a) { return std::sqrt(dot3(a, a)); }

inline void cross3(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace curve
}  // namespace b2b
