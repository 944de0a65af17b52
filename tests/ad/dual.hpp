// Forward-mode dual numbers for the AD reference of the contact element
// (test-only code, not part of libb2b).
//
// A Dual<N, R> is a value v and N derivative components d[k] = dv/dX_k, in
// the real type R (double; long double for a more precise diagnostic). Every
// operation applies the chain rule to the components. The value part of a
// result is computed by exactly the same operation as the plain code in R
// would use (v = a.v * b.v, sqrt(a.v), ...), so a computation templated over
// the scalar gives bit for bit the same values for R and for Dual<N, R> (the
// build uses -ffp-contract=off, so no fused multiply-add can differ between
// the two); the AD suite asserts this.
#pragma once

#include <cmath>
#include <type_traits>

namespace b2bad {

template <int N, class R = double>
struct Dual {
  R v = 0;
  R d[N] = {};

  Dual() = default;
  Dual(R value) : v(value) {}  // NOLINT: a constant converts implicitly
  // A variable: value and a unit seed in component k.
  static Dual variable(R value, int k) {
    Dual r(value);
    r.d[k] = 1;
    return r;
  }
};

// The real type under a scalar, and the value of a scalar: what branches and
// tests look at.
template <class S>
struct RealOf {
  using type = S;
};
template <int N, class R>
struct RealOf<Dual<N, R>> {
  using type = R;
};
inline double val(double x) { return x; }
inline long double val(long double x) { return x; }
template <int N, class R>
inline R val(const Dual<N, R>& x) {
  return x.v;
}

// Mixed operations take any arithmetic constant (promoted as C++ promotes).
template <class T>
using IfArith = typename std::enable_if<std::is_arithmetic<T>::value, int>::type;

template <int N, class R>
inline Dual<N, R> operator-(const Dual<N, R>& a) {
  Dual<N, R> r;
  r.v = -a.v;
  for (int k = 0; k < N; ++k) r.d[k] = -a.d[k];
  return r;
}

template <int N, class R>
inline Dual<N, R> operator+(const Dual<N, R>& a, const Dual<N, R>& b) {
  Dual<N, R> r;
  r.v = a.v + b.v;
  for (int k = 0; k < N; ++k) r.d[k] = a.d[k] + b.d[k];
  return r;
}
template <int N, class R, class T, IfArith<T> = 0>
inline Dual<N, R> operator+(const Dual<N, R>& a, T b) {
  Dual<N, R> r = a;
  r.v = a.v + b;
  return r;
}
template <int N, class R, class T, IfArith<T> = 0>
inline Dual<N, R> operator+(T a, const Dual<N, R>& b) {
  Dual<N, R> r = b;
  r.v = a + b.v;
  return r;
}

template <int N, class R>
inline Dual<N, R> operator-(const Dual<N, R>& a, const Dual<N, R>& b) {
  Dual<N, R> r;
  r.v = a.v - b.v;
  for (int k = 0; k < N; ++k) r.d[k] = a.d[k] - b.d[k];
  return r;
}
template <int N, class R, class T, IfArith<T> = 0>
inline Dual<N, R> operator-(const Dual<N, R>& a, T b) {
  Dual<N, R> r = a;
  r.v = a.v - b;
  return r;
}
template <int N, class R, class T, IfArith<T> = 0>
inline Dual<N, R> operator-(T a, const Dual<N, R>& b) {
  Dual<N, R> r;
  r.v = a - b.v;
  for (int k = 0; k < N; ++k) r.d[k] = -b.d[k];
  return r;
}

template <int N, class R>
inline Dual<N, R> operator*(const Dual<N, R>& a, const Dual<N, R>& b) {
  Dual<N, R> r;
  r.v = a.v * b.v;
  for (int k = 0; k < N; ++k) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
  return r;
}
template <int N, class R, class T, IfArith<T> = 0>
inline Dual<N, R> operator*(const Dual<N, R>& a, T b) {
  Dual<N, R> r;
  r.v = a.v * b;
  for (int k = 0; k < N; ++k) r.d[k] = a.d[k] * b;
  return r;
}
template <int N, class R, class T, IfArith<T> = 0>
inline Dual<N, R> operator*(T a, const Dual<N, R>& b) {
  Dual<N, R> r;
  r.v = a * b.v;
  for (int k = 0; k < N; ++k) r.d[k] = a * b.d[k];
  return r;
}

// a / b: value a.v / b.v, derivative (a' - (a/b) b') / b.
template <int N, class R>
inline Dual<N, R> operator/(const Dual<N, R>& a, const Dual<N, R>& b) {
  Dual<N, R> r;
  r.v = a.v / b.v;
  for (int k = 0; k < N; ++k) r.d[k] = (a.d[k] - r.v * b.d[k]) / b.v;
  return r;
}
template <int N, class R, class T, IfArith<T> = 0>
inline Dual<N, R> operator/(const Dual<N, R>& a, T b) {
  Dual<N, R> r;
  r.v = a.v / b;
  for (int k = 0; k < N; ++k) r.d[k] = a.d[k] / b;
  return r;
}
template <int N, class R, class T, IfArith<T> = 0>
inline Dual<N, R> operator/(T a, const Dual<N, R>& b) {
  Dual<N, R> r;
  r.v = a / b.v;
  for (int k = 0; k < N; ++k) r.d[k] = -r.v * b.d[k] / b.v;
  return r;
}

template <int N, class R>
inline Dual<N, R>& operator+=(Dual<N, R>& a, const Dual<N, R>& b) {
  a.v += b.v;
  for (int k = 0; k < N; ++k) a.d[k] += b.d[k];
  return a;
}
template <int N, class R>
inline Dual<N, R>& operator-=(Dual<N, R>& a, const Dual<N, R>& b) {
  a.v -= b.v;
  for (int k = 0; k < N; ++k) a.d[k] -= b.d[k];
  return a;
}

// sqrt: derivative a' / (2 sqrt(a)); only used where a > 0.
inline double sqrt_(double a) { return std::sqrt(a); }
inline long double sqrt_(long double a) { return std::sqrt(a); }
template <int N, class R>
inline Dual<N, R> sqrt_(const Dual<N, R>& a) {
  Dual<N, R> r;
  r.v = std::sqrt(a.v);
  const R h = R(0.5) / r.v;
  for (int k = 0; k < N; ++k) r.d[k] = h * a.d[k];
  return r;
}

// |(x, y, z)| without overflow or underflow of the squares (std::hypot), with
// derivative (x x' + y y' + z z') / |.|; only used where the norm is > 0.
inline double hypot3(double x, double y, double z) { return std::hypot(x, y, z); }
inline long double hypot3(long double x, long double y, long double z) {
  return std::hypot(x, y, z);
}
template <int N, class R>
inline Dual<N, R> hypot3(const Dual<N, R>& x, const Dual<N, R>& y, const Dual<N, R>& z) {
  Dual<N, R> r;
  r.v = std::hypot(x.v, y.v, z.v);
  const R ux = x.v / r.v, uy = y.v / r.v, uz = z.v / r.v;
  for (int k = 0; k < N; ++k) r.d[k] = ux * x.d[k] + uy * y.d[k] + uz * z.d[k];
  return r;
}

}  // namespace b2bad
