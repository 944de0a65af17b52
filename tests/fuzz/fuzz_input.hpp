// The fuzzer's bytes read as a stream of choices. Every decoder in
// tests/fuzz draws from one FuzzInput, so a mutation of one byte changes one
// choice (an angle, a curve kind, whether a history is fresh) and libFuzzer
// can climb towards inputs that reach new code. An exhausted input reads as
// zeros, which choose the common case of every choice: every prefix of an
// input is an input, and a short seed already selects a structured case.
#pragma once

#include <cfloat>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

namespace b2b_fuzz {

class FuzzInput {
 public:
  FuzzInput(const uint8_t* data, size_t size) : p_(data), n_(size) {}

  uint8_t byte() { return pos_ < n_ ? p_[pos_++] : 0; }
  uint16_t u16() {
    const uint16_t lo = byte();
    return static_cast<uint16_t>(lo | (byte() << 8));
  }
  uint32_t u32() {
    const uint32_t lo = u16();
    return lo | (static_cast<uint32_t>(u16()) << 16);
  }
  uint64_t u64() {
    const uint64_t lo = u32();
    return lo | (static_cast<uint64_t>(u32()) << 32);
  }
  int raw_int() { return static_cast<int>(u32()); }
  bool flag() { return (byte() & 1) != 0; }

  // True with probability k/256. A zero byte (the exhausted input) takes
  // the likelier side: false for k < 128, true otherwise.
  bool chance(int k) {
    const int b = byte();
    return k >= 128 ? b < k : b >= 256 - k;
  }
  // One of 0 .. n-1 (one byte for n <= 256, two up to 65536).
  int pick(int n) {
    if (n <= 1) return 0;
    return n <= 256 ? byte() % n : u16() % n;
  }

  // [0, 1] in 65536 steps, including both ends exactly.
  double unit() { return u16() / 65535.0; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // 10^u, u uniform in [lo_exp, hi_exp]: scales over many decades.
  double log_uniform(double lo_exp, double hi_exp) {
    return std::pow(10.0, uniform(lo_exp, hi_exp));
  }
  double sign() { return flag() ? -1.0 : 1.0; }

  // Any bit pattern: NaNs with payloads, subnormals, infinities.
  double raw_double() {
    const uint64_t b = u64();
    double d;
    std::memcpy(&d, &b, sizeof d);
    return d;
  }

  // The values at the edges of what b2b accepts or computes with: the
  // documented limits (B2B_COORD_MAX, B2B_LENGTH_MIN, the history's parameter
  // bound 1e3, the search box 3, the joint tolerance 1e-13) and their
  // neighbours, the limits of double, and the non-finite values.
  double special() {
    static const double kSpecial[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 3.0, -3.0,
        std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        DBL_MAX, -DBL_MAX, DBL_MIN, -DBL_MIN, std::numeric_limits<double>::denorm_min(),
        1e100, -1e100, 1.0000000000000002e100, 1e-100, 0.99999999999999e-100,
        1e300, 1e-300, 1e154, 1e155, 1e-154, 1e50, 1e-50,
        1e3, -1e3, 1000.0000000000001, 1 + DBL_EPSILON, 1 - DBL_EPSILON / 2,
        1 - 1e-13, -1 - 1e-13, 1e-13, 1e-10, 1e-8, 2147483648.0, 90.0, 89.99999999999999};
    return kSpecial[pick(sizeof kSpecial / sizeof kSpecial[0])];
  }
  // A special value most of the time, any bit pattern otherwise.
  double wild() { return chance(200) ? special() : raw_double(); }

  size_t consumed() const { return pos_; }
  size_t remaining() const { return pos_ < n_ ? n_ - pos_ : 0; }

 private:
  const uint8_t* p_;
  size_t n_;
  size_t pos_ = 0;
};

// Overwrites 1 to 3 entries of v (chosen by the input) with wild values:
// the raw-double path, by which NaN, Inf and huge values reach any argument.
inline void inject_wild(FuzzInput& in, double* v, int n) {
  const int k = 1 + in.pick(3);
  for (int i = 0; i < k; ++i) v[in.pick(n)] = in.wild();
}

}  // namespace b2b_fuzz
