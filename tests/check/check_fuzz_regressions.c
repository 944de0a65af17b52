/* Regression tests for the defects the fuzz targets (tests/fuzz) found, each
 * from the inputs that exposed it; the fuzzers' own reproducers are in
 * tests/fuzz/corpus/<target>/regress-*.
 *  - "tangent" = B2B_TANGENT_MAIN reported info[B2B_INFO_SYMMETRIC] = 1 for
 *    a tangent that was symmetric only up to rounding: -f' G G^T was
 *    computed as (-f' G_r) G_c, which rounds differently from (-f' G_c) G_r
 *    (fuzz_pair_eval).
 *  - The contact model's stats summed the active contacts' energies into
 *    +Inf, with B2B_OK, when each energy was finite but their sum was not
 *    (fuzz_model_update).
 *  - A tangent made symmetric after its finiteness was checked (the
 *    "tangent" option SYMMETRIC on an unsymmetric tangent, and the line
 *    element's MAIN tangent, symmetric up to rounding) was returned with
 *    B2B_OK and entries of +-Inf: the mean (a + b) / 2 of two finite entries
 *    above DBL_MAX / 2 of one sign overflowed in the sum (fuzz_pair_line,
 *    in CI). */
#include <float.h>
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

static int all_finite(const double *v, int n) {
  for (int i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

static b2b_params *friction_params(double penalty, int tangent) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", penalty, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "friction", 0.3, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "tangential_penalty", 1.0, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "tangent", tangent, msg, sizeof msg), B2B_OK);
  ck_assert_msg(b2b_params_finalize(p, msg, sizeof msg) == B2B_OK, "%s", msg);
  return p;
}

/* The point element: two linear segments crossing near A's first node and
 * B's first node (xi = eta = -0.8, gap -0.1), friction sticking after B
 * moved along x; penalty 0.7 DBL_MAX, so that the exact tangent's largest
 * entries (about 0.8 of the penalty) are finite, and the mean of one pair
 * of them, both about -1.0e308, is too. The SYMMETRIC tangent must be
 * finite and, bit for bit, the mean of the exact one's mirror pairs. */
START_TEST(symmetric_tangent_near_the_double_range) {
  char msg[B2B_ERRMSG_LEN] = "";
  const int segments[6] = {B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                           B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
  double X[24] = {-3, 0, 0, -1, 0, 0, 1, 0, 0, 3, 0, 0,
                  -0.8, -2.2, 0.9, -0.8, -0.2, 0.9, -0.8, 1.8, 0.9, -0.8, 3.8, 0.9};
  const double radii[2] = {0.5, 0.5};
  b2b_params *unit = friction_params(1.0, B2B_TANGENT_EXACT);
  b2b_params *exact = friction_params(0.7 * DBL_MAX, B2B_TANGENT_EXACT);
  b2b_params *sym = friction_params(0.7 * DBL_MAX, B2B_TANGENT_SYMMETRIC);
  int nh = 0, status = -1;
  ck_assert_int_eq(b2b_params_history_size(unit, &nh, msg, sizeof msg), B2B_OK);
  ck_assert_int_le(nh, 16);
  double h0[16] = {0}, h1[16], h2[16], info[32], r[24];
  static double Ke[576], Ks[576];
  /* The friction history of a first step at unit penalty, then B moved. */
  ck_assert_msg(b2b_pair_eval(unit, segments, X, NULL, radii, h0, h1, nh, &status, info, r, Ke,
                              24, msg, sizeof msg) == B2B_OK, "%s", msg);
  for (int k = 4; k < 8; ++k) X[3 * k] += 0.01;
  ck_assert_msg(b2b_pair_eval(exact, segments, X, NULL, radii, h1, h2, nh, &status, info, r, Ke,
                              24, msg, sizeof msg) == B2B_OK, "exact: %s", msg);
  ck_assert_int_eq(status, B2B_CONTACT_ACTIVE);
  ck_assert(info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK);
  ck_assert(info[B2B_INFO_SYMMETRIC] == 0.0);
  ck_assert(all_finite(Ke, 576));
  /* The case: a mirror pair of one sign whose sum overflows. */
  int overflowing = 0;
  for (int c = 0; c < 24; ++c)
    for (int q = c + 1; q < 24; ++q) overflowing += !isfinite(Ke[q + 24 * c] + Ke[c + 24 * q]);
  ck_assert_int_gt(overflowing, 0);
  const int rc = b2b_pair_eval(sym, segments, X, NULL, radii, h1, h2, nh, &status, info, r, Ks,
                               24, msg, sizeof msg);
  ck_assert_msg(rc == B2B_OK, "SYMMETRIC: %d %s", rc, msg);
  ck_assert(info[B2B_INFO_SYMMETRIC] == 1.0);
  ck_assert_msg(all_finite(Ks, 576), "SYMMETRIC tangent not finite with B2B_OK (before the fix: "
                "+-Inf where a mirror pair's sum overflowed)");
  for (int c = 0; c < 24; ++c)
    for (int q = 0; q < 24; ++q) {
      const double mean = q == c ? Ke[q + 24 * c] : 0.5 * Ke[q + 24 * c] + 0.5 * Ke[c + 24 * q];
      ck_assert_msg(memcmp(&mean, &Ks[q + 24 * c], sizeof mean) == 0,
                    "SYMMETRIC tangent (%d, %d) = %a, the mean of the exact one's pair %a", q, c,
                    Ks[q + 24 * c], mean);
    }
  printf("check_fuzz_regressions: SYMMETRIC tangent finite with %d mirror pairs whose sum "
         "overflows\n", overflowing);
  b2b_params_destroy(&unit);
  b2b_params_destroy(&exact);
  b2b_params_destroy(&sym);
}
END_TEST

/* The line element's case as fuzz_pair_line found it (regress-line-main-
 * tangent-overflow): coordinates up to 2^996, line_penalty DBL_MAX, the
 * MAIN tangent, one point, the history of an earlier call. */
START_TEST(line_main_tangent_near_the_double_range_fuzzer_case) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", 0x1.387e57ad717e8p+783, msg, sizeof msg),
                   B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "parallel_angle", 0x1p-1, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "max_iterations", 1000, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "friction", 0x1.a369a369a369ap-3, msg, sizeof msg),
                   B2B_OK);
  ck_assert_int_eq(
      b2b_params_set_real(p, "tangential_penalty", 0x1.ddfdb6e75e437p+301, msg, sizeof msg),
      B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "tangent", B2B_TANGENT_MAIN, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(
      b2b_params_set_int(p, "contact_type", B2B_CONTACT_TYPE_LINE, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "line_penalty", DBL_MAX, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(
      b2b_params_set_real(p, "line_tangential_penalty", 0x1.2558f5411fa9bp+133, msg, sizeof msg),
      B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "line_angle", 5.0, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "point_angle", 15.0, msg, sizeof msg), B2B_OK);
  ck_assert_msg(b2b_params_finalize(p, msg, sizeof msg) == B2B_OK, "%s", msg);
  int nh = 0;
  ck_assert_int_eq(b2b_params_history_size(p, &nh, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(nh, 12);
  const int segments[6] = {0, 0, 0, 0, 0, 0};
  const double X[24] = {
      0x1.689fa637d6452p+996,  -0x1.0c5c12e58339fp+994, -0x1.ae5d8e1936666p+994,
      -0x1.2f4a4a350aa0bp+2,   -0x1.49e9074017d4ap+2,   -0x1.047368aa314b3p+2,
      -0x1.204f9a186f7d6p+2,   -0x1.e87a8bad73d22p+1,   -0x1.28173279dfa4dp+2,
      -0x1.de946578f0216p+309, -0x1.b1bed05155dc8p+309, -0x1.4d6865c50266ap+311,
      0x1.27c6f284c1a16p+6,    0x1.d4247aaacdd96p+9,    -0x1.58393201fec7dp+8,
      -0x1.2119c118eb4e8p+2,   -0x1.30856b8445f95p+2,   -0x1.b398dd63bc03ap+1,
      -0x1.34cc41b1c6edep+2,   -0x1.25beef64fbadbp+2,   -0x1.15bb29c5bffe2p+2,
      0x1.689fa637d6452p+996,  -0x1.0c5c12e58339fp+994, -0x1.ae5d8e1936666p+994};
  const double radii[2] = {0x1.1e33ad8fd685ap-2, 0x1.8f98ebc1e1846p-3};
  const double h0[24] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                         1, 1, -0x1.d1af9b335a48p-6, 0x1.c876c8ab6fbdbp-2,
                         -0x1.ca15e6c89236p-1, 0, -0x1.53ffc3bbd6fc4p-1, 0, 0, 0, 0, 0};
  double h1[24], line_info[B2B_LINE_INFO_LEN], point_info[B2B_PAIR_INFO_LEN], r[24];
  static double K[576];
  int status = -1;
  const int rc = b2b_pair_eval_line(p, segments, X, NULL, radii, 1, h0, h1, 24, &status,
                                    line_info, point_info, r, K, 24, msg, sizeof msg);
  ck_assert_msg(rc == B2B_OK, "%d %s", rc, msg);
  ck_assert_int_eq(status, B2B_CONTACT_ACTIVE);
  ck_assert(line_info[B2B_LINE_INFO_SYMMETRIC] == 1.0);
  ck_assert_msg(all_finite(K, 576), "MAIN line tangent not finite with B2B_OK (before the fix: "
                "+-Inf in columns 3, 6, 18 and 19)");
  ck_assert_msg(exactly_symmetric(K), "MAIN line tangent reported symmetric but is not");
  b2b_params_destroy(&p);
}
END_TEST

int main(void) {
  Suite *s = suite_create("fuzz_regressions");
  TCase *tc = tcase_create("regressions");
  tcase_add_test(tc, main_tangent_symmetric_as_reported_fuzzer_case);
  tcase_add_test(tc, main_tangent_symmetric_as_reported_sweep);
  tcase_add_test(tc, model_totals_that_overflow_are_an_error);
  tcase_add_test(tc, symmetric_tangent_near_the_double_range);
  tcase_add_test(tc, line_main_tangent_near_the_double_range_fuzzer_case);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
