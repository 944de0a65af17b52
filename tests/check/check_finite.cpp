// The library's finiteness guards (src/common/finite.hpp, header-only and
// internal, so compiled in here), each way round: every output the library
// returns with B2B_OK has passed one of them, so a guard that let an Inf or
// a NaN through, or refused finite numbers, would leak or lose results in
// silence. The tangent's guard, all_finite_by_sum, decides from the sum of
// the entries and falls back to the exact check only when that sum
// overflows although every entry is finite (entries near the double
// range that do not cancel): a path no contact scene reaches, tested here.
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "../../src/common/finite.hpp"

// Last: Check's macros (fail, ...) would rename members of the C++ library.
#include "test_support.h"

namespace {

constexpr int kN = 576;  // a 24 x 24 tangent
const double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Every guard's answer on v (n a multiple of 8).
struct Answers {
  bool plain, by4, by_sum;
};
Answers answers(const std::vector<double>& v) {
  const int n = static_cast<int>(v.size());
  return {b2b::all_finite(v.data(), n), b2b::all_finite4(v.data(), n),
          b2b::all_finite_by_sum(v.data(), n)};
}

void expect_all(const std::vector<double>& v, bool finite, const char* what) {
  const Answers a = answers(v);
  ck_assert_msg(a.plain == finite && a.by4 == finite && a.by_sum == finite,
                "%s: all_finite %d, all_finite4 %d, all_finite_by_sum %d, expected %d", what,
                a.plain, a.by4, a.by_sum, finite);
}

}  // namespace

START_TEST(ordinary_entries) {
  std::vector<double> v(kN);
  for (int i = 0; i < kN; ++i) v[i] = std::sin(0.37 * i) * 1e3;
  expect_all(v, true, "ordinary entries");
  std::vector<double> zero(kN, 0.0);
  expect_all(zero, true, "zeros");
  std::vector<double> tiny(kN, DBL_TRUE_MIN);
  expect_all(tiny, true, "subnormal entries");
}
END_TEST

// The fallback: each entry finite, the sum (and each of the eight partial
// sums) beyond DBL_MAX. Without the fallback all_finite_by_sum would refuse
// this tangent and the pair would report an overflow that is not there.
START_TEST(finite_entries_whose_sum_overflows) {
  std::vector<double> v(kN, 0.9 * DBL_MAX);
  double sum = 0.0;
  for (double x : v) sum += x;
  ck_assert(std::isinf(sum));
  expect_all(v, true, "576 entries of 0.9 DBL_MAX");
  // Of both signs: four of the eight partial sums overflow, the other four
  // alternate between DBL_MAX and 0.
  for (int i = 0; i < kN; ++i)
    v[i] = i % 8 < 4 ? 0.75 * DBL_MAX : ((i / 8) % 2 ? -DBL_MAX : DBL_MAX);
  expect_all(v, true, "entries of 0.75 DBL_MAX and +-DBL_MAX");
}
END_TEST

// A single non-finite entry at every position, alone and among entries
// whose sum overflows: every guard must refuse it (each of the partial sums
// and the fallback's lanes sees one of the positions).
START_TEST(one_nonfinite_entry_anywhere) {
  const double bad[3] = {kInf, -kInf, kNaN};
  const double base[2] = {1.0, 0.9 * DBL_MAX};
  for (double b : base)
    for (double x : bad)
      for (int at = 0; at < kN; ++at) {
        std::vector<double> v(kN, b);
        v[at] = x;
        const Answers a = answers(v);
        // One Check assertion for a failure only (Check records every
        // passed one, a write(2) each).
        if (a.plain || a.by4 || a.by_sum)
          ck_abort_msg("entries %g, %g at %d: all_finite %d, all_finite4 %d, "
                       "all_finite_by_sum %d",
                       b, x, at, a.plain, a.by4, a.by_sum);
      }
}
END_TEST

// Opposite infinities (their sum is NaN) and infinities among huge finite
// entries of the other sign.
START_TEST(opposite_infinities) {
  std::vector<double> v(kN, 1.0);
  v[3] = kInf;
  v[11] = -kInf;  // the same partial sum as v[3]
  expect_all(v, false, "+Inf and -Inf in one partial sum");
  std::vector<double> w(kN, -0.9 * DBL_MAX);
  w[100] = kInf;
  expect_all(w, false, "+Inf among entries of -0.9 DBL_MAX");
}
END_TEST

// all_finite takes any n, odd included.
START_TEST(odd_lengths) {
  for (int n = 1; n <= 9; ++n) {
    std::vector<double> v(n, 2.0);
    ck_assert(b2b::all_finite(v.data(), n));
    v[n - 1] = kNaN;
    ck_assert_msg(!b2b::all_finite(v.data(), n), "NaN last of %d", n);
  }
  ck_assert(b2b::all_finite(nullptr, 0));
}
END_TEST

int main() {
  Suite* s = suite_create("finite");
  TCase* tc = tcase_create("guards");
  tcase_add_test(tc, ordinary_entries);
  tcase_add_test(tc, finite_entries_whose_sum_overflows);
  tcase_add_test(tc, one_nonfinite_entry_anywhere);
  tcase_add_test(tc, opposite_infinities);
  tcase_add_test(tc, odd_lengths);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
