/* Convergence on the circle: the largest distance of the smoothed ring from
 * the exact circle, for 8 .. 256 elements, uniform and alternating
 * 1.3h/0.7h meshes; fitted orders asserted within +-0.3 of the expected ones. */
#include <math.h>
#include <stdio.h>

#include "ring_accuracy.h"
#include "test_support.h"

#define N_MESHES 6
static const int kN[N_MESHES] = {8, 16, 32, 64, 128, 256};

static double measured_order(int kind, int alternating) {
  double err[N_MESHES];
  for (int m = 0; m < N_MESHES; ++m) {
    const int st = ring_max_error(kind, kN[m], 1.0, alternating, 200, &err[m]);
    ck_assert_int_eq(st, B2B_OK);
    ck_assert(err[m] > 0.0 && err[m] < 0.2); /* at most the coarsest sagitta */
  }
  /* Errors decrease monotonically with refinement. */
  for (int m = 1; m < N_MESHES; ++m) ck_assert(err[m] < err[m - 1]);
  const double p = fitted_order(kN, err, N_MESHES);
  printf("%-24s %-12s error n=8: %.2e  n=256: %.2e  fitted order %.2f\n", tst_kind_name(kind),
         alternating ? "alternating" : "uniform", err[0], err[N_MESHES - 1], p);
  return p;
}

static void expect_order(int kind, int alternating, double expected) {
  const double p = measured_order(kind, alternating);
  ck_assert_msg(fabs(p - expected) <= 0.3, "%s on a %s mesh: order %.2f, expected %.1f +- 0.3",
                tst_kind_name(kind), alternating ? "alternating" : "uniform", p, expected);
}

START_TEST(linear_second_order) {
  expect_order(B2B_CURVE_LINEAR, 0, 2.0);
  expect_order(B2B_CURVE_LINEAR, 1, 2.0);
}
END_TEST

START_TEST(midpoint_second_order) {
  expect_order(B2B_CURVE_HERMITE_MIDPOINT, 0, 2.0);
  expect_order(B2B_CURVE_HERMITE_MIDPOINT, 1, 2.0);
}
END_TEST

/* Litewka's node-preserving method (doc/curves.md section 3.3) is fourth
 * order on a circle (uniform mesh) only: on non-uniform ones the central
 * chord x3 - x1 is not the tangent (doc/curves.md section 6). */
START_TEST(nodal_fourth_order_uniform_second_order_alternating) {
  expect_order(B2B_CURVE_HERMITE_NODAL, 0, 4.0);
  expect_order(B2B_CURVE_HERMITE_NODAL, 1, 2.0);
}
END_TEST

START_TEST(nodal_weighted_fourth_order_both) {
  expect_order(B2B_CURVE_HERMITE_NODAL_WEIGHTED, 0, 4.0);
  expect_order(B2B_CURVE_HERMITE_NODAL_WEIGHTED, 1, 4.0);
}
END_TEST

/* The fit is not fooled by sampling: the linear kind's error is exactly
 * the sagitta R (1 - cos(pi/n)), which 200 samples per segment resolve. */
START_TEST(linear_error_is_the_sagitta) {
  for (int m = 0; m < N_MESHES; ++m) {
    double err;
    ck_assert_int_eq(ring_max_error(B2B_CURVE_LINEAR, kN[m], 1.0, 0, 200, &err), B2B_OK);
    const double sagitta = 1.0 - cos(3.14159265358979323846 / kN[m]);
    ck_assert_msg(fabs(err - sagitta) <= 1e-12 + 1e-9 * sagitta, "n=%d: %g vs sagitta %g", kN[m],
                  err, sagitta);
  }
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("curve_convergence");
  TCase *tc = tcase_create("circle");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, linear_second_order);
  tcase_add_test(tc, midpoint_second_order);
  tcase_add_test(tc, nodal_fourth_order_uniform_second_order_alternating);
  tcase_add_test(tc, nodal_weighted_fourth_order_both);
  tcase_add_test(tc, linear_error_is_the_sagitta);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
