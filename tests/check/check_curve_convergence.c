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

/* The orders on a circle, uniform and alternating mesh, for every kind (the
 * README's table). Litewka's node-preserving method (doc/curves.md section
 * 3.3) is fourth order on a uniform mesh only: on non-uniform ones the
 * central chord x3 - x1 is not the tangent (doc/curves.md section 6). */
static void expected_orders(int kind, double *uniform, double *alternating) {
  switch (kind) {
    case B2B_CURVE_LINEAR: *uniform = 2.0, *alternating = 2.0; return;
    case B2B_CURVE_HERMITE_MIDPOINT: *uniform = 2.0, *alternating = 2.0; return;
    case B2B_CURVE_HERMITE_NODAL: *uniform = 4.0, *alternating = 2.0; return;
    case B2B_CURVE_HERMITE_NODAL_WEIGHTED: *uniform = 4.0, *alternating = 4.0; return;
    default: tst_no_expectation("expected_orders", kind); *uniform = *alternating = 0.0;
  }
}

/* Loop index: the curve kind. */
START_TEST(order_on_the_circle) {
  double uniform, alternating;
  expected_orders(_i, &uniform, &alternating);
  expect_order(_i, 0, uniform);
  expect_order(_i, 1, alternating);
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
  tcase_add_loop_test(tc, order_on_the_circle, 0, B2B_CURVE_KIND_COUNT);
  tcase_add_test(tc, linear_error_is_the_sagitta);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
