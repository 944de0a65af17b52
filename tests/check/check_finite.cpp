// The library's finiteness guards (src/common/finite.hpp, and the symmetric
// tangent's mirror with its check, src/pair/tangent_mirror.hpp; header-only
// and internal, so compiled in here), each way round: every output the library
// returns with B2B_OK has passed one of them, so a guard that let an Inf or
// a NaN through, or refused finite numbers, would leak or lose results in
// silence. The tangent's guard, all_finite_by_sum, decides from the sum of
// the entries and falls back to the exact check only when that sum
// overflows although every entry is finite (entries near the double
// range that do not cancel): a path no contact scene reaches, tested here.
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "../../src/common/finite.hpp"
#include "../../src/pair/tangent_mirror.hpp"

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

// The mirror of the symmetric tangent (the upper triangle into the lower,
// the whole 24 x 24 or the compact m x m block of a linear-in-X pair) and
// its finiteness check: the lower triangle's old contents (NaN here) never
// count, a non-finite entry anywhere in the upper one does, and a sum that
// overflows over finite entries falls back to the exact check.
namespace {

constexpr int kLd = b2b::pair::kNdof;

// K (24 x 24) with the upper triangle of the m x m block from value(r, c),
// everything else NaN; whether the mirror's answer is `finite` and the
// block symmetric, equal to the upper triangle.
template <class Value>
void expect_mirror(int m, Value value, bool finite, const char* what) {
  std::vector<double> K(kLd * kLd, kNaN);
  for (int c = 0; c < m; ++c)
    for (int r = 0; r <= c; ++r) K[r + kLd * c] = value(r, c);
  const bool answer = m == kLd ? b2b::pair::mirror_upper_checked(K.data())
                               : b2b::pair::mirror_compact_checked(K.data(), m);
  if (answer != finite) ck_abort_msg("%s (m %d): finite %d, expected %d", what, m, answer, finite);
  for (int c = 0; c < m; ++c)
    for (int r = c + 1; r < m; ++r)
      if (std::memcmp(&K[r + kLd * c], &K[c + kLd * r], sizeof(double)) != 0)
        ck_abort_msg("%s (m %d): K(%d, %d) = %g is not K(%d, %d) = %g", what, m, r, c,
                     K[r + kLd * c], c, r, K[c + kLd * r]);
}

}  // namespace

START_TEST(mirror_of_the_symmetric_tangent) {
  for (int m : {12, 18, kLd}) {
    expect_mirror(m, [](int r, int c) { return std::sin(0.3 * r + 0.7 * c) * 1e3; }, true,
                  "ordinary entries");
    expect_mirror(m, [](int, int) { return 0.9 * DBL_MAX; }, true,
                  "entries of 0.9 DBL_MAX (their sum overflows)");
    const double bad[3] = {kInf, -kInf, kNaN};
    for (double x : bad)
      for (int c = 0; c < m; ++c)
        for (int r = 0; r <= c; ++r) {
          const auto one_bad = [&](int i, int j) { return i == r && j == c ? x : 1.0; };
          expect_mirror(m, one_bad, false, "one non-finite entry");
          const auto among_huge = [&](int i, int j) { return i == r && j == c ? x : 0.9 * DBL_MAX; };
          expect_mirror(m, among_huge, false, "one non-finite entry among huge ones");
        }
  }
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
  tcase_add_test(tc, mirror_of_the_symmetric_tangent);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
