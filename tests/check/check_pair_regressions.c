/* Regression tests for defects found by an adversarial campaign against the
 * contact element, each built from the inputs that exposed it:
 *  - the quadratic law with a huge regularization gap: NaN or Inf reported
 *    with B2B_OK (0 * inf, g0^2 overflowing), or an overflow error where the
 *    true force and energy are finite;
 *  - the handover writing -Inf for a history whose xi was -1e308 (which the
 *    history check let through). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pair_support.h"

static const int kLinear[6] = {B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                               B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};

static b2b_params *quadratic(double penalty, double g0) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", penalty, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "law", B2B_LAW_QUADRATIC, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "regularization_gap", g0, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_finalize(p, msg, sizeof msg), B2B_OK);
  return p;
}

/* Two linear beams crossing at 90 degrees with axes dist apart, radii 0.1. */
static int cross(const b2b_params *p, double dist, double info[32], double r[24], double K[576],
                 char *msg) {
  const double X[24] = {0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0,
                        0, 0, 0, 0, -1, dist, 0, 1, dist, 0, 0, 0};
  const double radii[2] = {0.1, 0.1};
  double h0[8] = {0}, h1[8];
  int st = -1;
  const int rc = b2b_pair_eval(p, kLinear, X, NULL, radii, h0, h1, 8, &st, info, r, K, 24, msg,
                               B2B_ERRMSG_LEN);
  return rc == B2B_OK ? st : -rc;
}

static int all_finite(const double *v, int n) {
  for (int i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

START_TEST(zero_penalty_huge_gap_is_finite) {
  char msg[B2B_ERRMSG_LEN];
  double info[32], r[24], K[576];
  for (int k = 0; k < 2; ++k) {
    b2b_params *p = quadratic(0.0, k ? 1e160 : 1e300);
    const int st = cross(p, 0.15, info, r, K, msg);
    ck_assert_msg(st == B2B_CONTACT_OPEN, "status %d (%s)", st, msg);
    ck_assert(all_finite(info, 32) && all_finite(r, 24) && all_finite(K, 576));
    ck_assert(info[B2B_INFO_ENERGY] == 0.0 && info[B2B_INFO_NORMAL_FORCE] == 0.0);
    b2b_params_destroy(&p);
  }
}
END_TEST

START_TEST(force_beyond_doubles_is_an_error) {
  char msg[B2B_ERRMSG_LEN] = "";
  double info[32], r[24], K[576];
  for (int i = 0; i < 32; ++i) info[i] = -7.0;
  b2b_params *p = quadratic(1000.0, 1e308);  /* f = eps (g0 - g)^2 / (2 g0) ~ 5e310 */
  const int st = cross(p, 0.25, info, r, K, msg);
  ck_assert_msg(st == -B2B_ERR_RANGE, "status %d", st);
  ck_assert_msg(strstr(msg, "overflows") != NULL, "%s", msg);
  for (int i = 0; i < 32; ++i) ck_assert(info[i] == -7.0);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(finite_force_with_huge_gap_is_computed) {
  char msg[B2B_ERRMSG_LEN] = "";
  double info[32], r[24], K[576];
  const double eps = 1e-20, g0 = 1e160;
  b2b_params *p = quadratic(eps, g0);
  const int st = cross(p, 0.25, info, r, K, msg);
  ck_assert_msg(st == B2B_CONTACT_ACTIVE, "status %d (%s)", st, msg);
  const double g = info[B2B_INFO_GAP], h = g0 - g;
  const double force = eps * h * h / (2 * g0);            /* in long double terms: */
  const long double energy = (long double)eps * h * h * h / (6.0L * g0);
  ck_assert(fabs(info[B2B_INFO_NORMAL_FORCE] - force) <= 1e-12 * force);
  ck_assert(fabsl(info[B2B_INFO_ENERGY] - energy) <= 1e-12L * energy);
  ck_assert(all_finite(r, 24) && all_finite(K, 576));
  printf("g0 = 1e160, penalty 1e-20: f_N = %.4g, energy = %.4g (finite, as they are)\n",
         info[B2B_INFO_NORMAL_FORCE], info[B2B_INFO_ENERGY]);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(handover_of_an_absurd_parameter_is_refused) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  const int from[3] = {B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
  const double from_X[12] = {0, 0, 0, 1, 0, 0, 3, 0, 0, 0, 0, 0};
  const double to_X[12] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0};
  const double hist_from[8] = {1, 1, 0, 0, 1, -1e308, 0, 0};
  double hist_to[8];
  for (int i = 0; i < 8; ++i) hist_to[i] = 42.0;
  const int rc = b2b_pair_history_handover(p, 0, -1, from, from_X, NULL, from, to_X, NULL,
                                           hist_from, hist_to, 8, msg, sizeof msg);
  ck_assert_int_eq(rc, B2B_ERR_RANGE);
  ck_assert_msg(strstr(msg, "xi") != NULL, "%s", msg);
  for (int i = 0; i < 8; ++i) ck_assert(hist_to[i] == 42.0);
  /* and a plausible history whose mapped parameter would leave the bound:
   * speeds 1 : 2000 at the joint */
  const double short_X[12] = {0, 0, 0, 0.999, 0, 0, 1, 0, 0, 0, 0, 0};
  const double long_X[12] = {0, 0, 0, 1, 0, 0, 4001, 0, 0, 0, 0, 0};
  double h2[8] = {1, 1, 0, 0, 1, -0.9, 0, 0};
  const int rc2 = b2b_pair_history_handover(p, 0, 1, from, long_X, NULL, from, short_X, NULL, h2,
                                            hist_to, 8, msg, sizeof msg);
  (void)rc2; /* the segments do not share a joint here: any error, never a non-finite output */
  ck_assert(rc2 != B2B_OK || all_finite(hist_to, 8));
  b2b_params_destroy(&p);
}
END_TEST

int main(void) {
  Suite *s = suite_create("pair_regressions");
  TCase *tc = tcase_create("regressions");
  tcase_add_test(tc, zero_penalty_huge_gap_is_finite);
  tcase_add_test(tc, force_beyond_doubles_is_an_error);
  tcase_add_test(tc, finite_force_with_huge_gap_is_computed);
  tcase_add_test(tc, handover_of_an_absurd_parameter_is_refused);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
