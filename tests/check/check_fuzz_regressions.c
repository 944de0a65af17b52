/* Regression tests for the defects the fuzz targets (tests/fuzz) found, each
 * from the inputs that exposed it; the fuzzers' own reproducers are in
 * tests/fuzz/corpus/<target>/regress-*.
 *  - "tangent" = B2B_TANGENT_MAIN reported info[B2B_INFO_SYMMETRIC] = 1 for
 *    a tangent that was symmetric only up to rounding: -f' G G^T was
 *    computed as (-f' G_r) G_c, which rounds differently from (-f' G_c) G_r
 *    (fuzz_pair_eval).
 *  - The contact model's stats summed the active contacts' energies into
 *    +Inf, with B2B_OK, when each energy was finite but their sum was not
 *    (fuzz_model_update). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pair_support.h"

static int exactly_symmetric(const double *K) {
  for (int c = 0; c < 24; ++c)
    for (int r = c + 1; r < 24; ++r)
      if (memcmp(&K[r + 24 * c], &K[c + 24 * r], sizeof(double)) != 0) return 0;
  return 1;
}

static b2b_params *main_tangent_params(double penalty) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", penalty, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "tangent", B2B_TANGENT_MAIN, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_finalize(p, msg, sizeof msg), B2B_OK);
  return p;
}

/* The fuzzer's input: a nodal segment against a weighted one starting its
 * beam (B's slot x1 unused, and DBL_MAX). */
START_TEST(main_tangent_symmetric_as_reported_fuzzer_case) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", 0x1.6a80a397c4749p-575, msg, sizeof msg),
                   B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "warm_start", 1, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "tangent", B2B_TANGENT_MAIN, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_finalize(p, msg, sizeof msg), B2B_OK);
  const int segments[6] = {B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                           B2B_CURVE_HERMITE_NODAL_WEIGHTED, B2B_END_REFLECT, B2B_END_NEIGHBOUR};
  const double X[24] = {
      -0x1.76073a0079f5ep-25, -0x1.e29896fb6bd8fp-20, -0x1.e29896fb6bd8fp-20,
      0x1.36a5ccd48a248p-20,  -0x1.e29896fb6bd8fp-20, -0x1.e29896fb6bd8fp-20,
      0x1.3c7de9bc8c0c6p-19,  -0x1.e29896fb6bd8fp-20, -0x1.e29896fb6bd8fp-20,
      0x1.dda8ed0ed3067p-19,  -0x1.e29896fb6bd8fp-20, -0x1.e29896fb6bd8fp-20,
      0x1.fffffffffffffp+1023, 0x1.fffffffffffffp+1023, 0x1.fffffffffffffp+1023,
      0x1.99cbcfc5a9a9fp-21,  -0x1.ef0925786cf2ep-20, -0x1.18b825aed31cp-20,
      0x1.fd909c05c630dp-20,  -0x1.88cda890e9932p-20, -0x1.31c363b9169d5p-20,
      0x1.971da8145bc65p-19,  -0x1.22922ba966336p-20, -0x1.4acea1c35a1eap-20};
  const double radii[2] = {0x1.82baa4ab723adp-22, 0x1.81bf6b33af3b7p-22};
  double h0[8] = {0}, h1[8], info[32], r[24], K[576];
  int status = -1;
  ck_assert_msg(b2b_pair_eval(p, segments, X, NULL, radii, h0, h1, 8, &status, info, r, K, 24, msg,
                              sizeof msg) == B2B_OK,
                "%s", msg);
  ck_assert_int_eq(status, B2B_CONTACT_ACTIVE);
  ck_assert(info[B2B_INFO_SYMMETRIC] == 1.0);
  ck_assert_msg(exactly_symmetric(K), "MAIN tangent reported symmetric but is not, bit for bit");
  b2b_params_destroy(&p);
}
END_TEST

/* The same on random crossings of every pair of kinds: before the fix about
 * a third of them had an entry that differed from its mirror. */
START_TEST(main_tangent_symmetric_as_reported_sweep) {
  b2b_params *p = main_tangent_params(1e3);
  tst_rng rng;
  tst_rng_seed(&rng, 9101);
  int n = 0;
  static double K[576];
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (int rep = 0; rep < 4; ++rep) {
        tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
        double X[24], h[8], info[32], r[24];
        tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 20, 90), tst_uniform(&rng, -0.7, 0.7),
                     tst_uniform(&rng, -0.7, 0.7), 0.3, X);
        /* A strongly curved pair can have a second local minimum of the
         * distance off its segments, where the search may end (OUTSIDE):
         * only the active ones say anything about the tangent. */
        if (tst_pair(p, &spec, X, NULL, h, info, r, K) != B2B_CONTACT_ACTIVE) continue;
        ck_assert(info[B2B_INFO_SYMMETRIC] == 1.0);
        ck_assert_msg(exactly_symmetric(K), "%s x %s, case %d: MAIN tangent not symmetric",
                      tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), rep);
        ++n;
      }
  ck_assert_int_ge(n, 60); /* of 64 */
  printf("check_fuzz_regressions: MAIN tangent exactly symmetric on %d crossings\n", n);
  b2b_params_destroy(&p);
}
END_TEST

/* Beam 0 along x (three linear segments), beams 1..n_cross along y across
 * each of its segments, 0.3 above it; quadratic law with g0 = 2e151, so that
 * every crossing is active with an energy of about 6.7e307 (finite). */
static b2b_model *crossing_model(int n_cross, b2b_params **p_out) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = tst_params(B2B_LAW_QUADRATIC, 1e6, 2e151);
  b2b_model *m = NULL;
  ck_assert_int_eq(b2b_model_create(&m, msg, sizeof msg), B2B_OK);
  int beam, nodes[4] = {0, 1, 2, 3};
  ck_assert_int_eq(b2b_model_add_beam(m, nodes, 4, 0, 0.1, B2B_CURVE_LINEAR, 0, &beam, msg,
                                      sizeof msg),
                   B2B_OK);
  for (int k = 0; k < n_cross; ++k) {
    const int pair[2] = {4 + 2 * k, 5 + 2 * k};
    ck_assert_int_eq(b2b_model_add_beam(m, pair, 2, 0, 0.1, B2B_CURVE_LINEAR, 1, &beam, msg,
                                        sizeof msg),
                     B2B_OK);
  }
  ck_assert_int_eq(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg), B2B_OK);
  ck_assert_msg(b2b_model_finalize(m, 4 + 2 * n_cross, msg, sizeof msg) == B2B_OK, "%s", msg);
  *p_out = p;
  return m;
}

static void crossing_coords(int n_cross, double *x) {
  for (int k = 0; k < 4; ++k) {
    x[3 * k] = k;
    x[3 * k + 1] = x[3 * k + 2] = 0.0;
  }
  for (int k = 0; k < n_cross; ++k)
    for (int e = 0; e < 2; ++e) {
      double *q = x + 3 * (4 + 2 * k + e);
      q[0] = 0.5 + k;
      q[1] = e ? 1.0 : -1.0;
      q[2] = 0.3;
    }
}

START_TEST(model_totals_that_overflow_are_an_error) {
  char msg[B2B_ERRMSG_LEN] = "";
  double x[3 * 10];
  int counts[16], n;
  double totals[8];
  /* Two crossings: the sums are finite, and so are they reported. */
  b2b_params *p = NULL;
  b2b_model *m = crossing_model(2, &p);
  crossing_coords(2, x);
  ck_assert_msg(b2b_model_update(m, x, 3, 8, 1, msg, sizeof msg) == B2B_OK, "%s", msg);
  ck_assert_int_eq(b2b_model_contact_count(m, &n, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(n, 2);
  ck_assert_int_eq(b2b_model_stats(m, counts, totals, msg, sizeof msg), B2B_OK);
  for (int k = 0; k < 8; ++k) ck_assert(isfinite(totals[k]));
  ck_assert(totals[B2B_TOTAL_ENERGY] > 1e308);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);

  /* Three: each energy finite, their sum beyond the doubles. The update is
   * refused, and the model is as it was (no results). */
  m = crossing_model(3, &p);
  crossing_coords(3, x);
  const int rc = b2b_model_update(m, x, 3, 10, 1, msg, sizeof msg);
  ck_assert_msg(rc == B2B_ERR_RANGE, "update returned %d (before the fix: B2B_OK with an "
                "energy total of +Inf)", rc);
  ck_assert_msg(strstr(msg, "overflows") != NULL, "%s", msg);
  ck_assert_int_eq(b2b_model_contact_count(m, &n, NULL, 0), B2B_ERR_STATE);
  printf("check_fuzz_regressions: three contacts of energy ~6.7e307: %s\n", msg);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

int main(void) {
  Suite *s = suite_create("fuzz_regressions");
  TCase *tc = tcase_create("regressions");
  tcase_add_test(tc, main_tangent_symmetric_as_reported_fuzzer_case);
  tcase_add_test(tc, main_tangent_symmetric_as_reported_sweep);
  tcase_add_test(tc, model_totals_that_overflow_are_an_error);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
