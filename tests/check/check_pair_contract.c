/* Promises of b2b_pair.h that no other suite exercises:
 *
 *  - B2B_CONTACT_NOT_CONVERGED is reachable and reported. A curved crossing
 *    whose closest-point search needs k >= 2 iterations (default
 *    "max_iterations") is evaluated again with max_iterations = 1 and
 *    k - 1: the call returns B2B_OK with NOT_CONVERGED, info[ITERATIONS]
 *    equal to the limit, no force (residual, tangent, normal and tangential
 *    force zero), and a history the next call accepts; with
 *    max_iterations = k the outputs are those of the default run, bit for bit.
 *  - The tangent after the axes have passed through each other. Step 1: B's
 *    axis 0.3 on one side of A's (committed history, normal n1); step 2: B's
 *    axis moved 0.6 along the normal to 0.3 on the other side. With the step-1
 *    history the sign-tracked gap keeps n1 (gap -0.65, the pair pushed back),
 *    and the analytic tangent, the derivative with the old history held
 *    fixed, must agree with central differences of the residual (and the
 *    residual with those of the potential): every pair of kinds, both normal
 *    laws, curved patches, and with Coulomb friction.
 * Central differences: steps h and h/2 combined by one Richardson step, as in
 * check_pair_tangent; relative tolerance 1e-6. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pair_support.h"

#define TOL 1e-6

static b2b_params *params_with_max_iterations(int max_it, double mu) {
  b2b_params *p = NULL;
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_int_eq(b2b_params_create(&p, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", 1e3, msg, sizeof msg), B2B_OK);
  if (mu > 0) {
    ck_assert_int_eq(b2b_params_set_real(p, "friction", mu, msg, sizeof msg), B2B_OK);
    ck_assert_int_eq(b2b_params_set_real(p, "tangential_penalty", 1e3, msg, sizeof msg), B2B_OK);
  }
  ck_assert_msg(b2b_params_set_int(p, "max_iterations", max_it, msg, sizeof msg) == B2B_OK,
                "max_iterations %d: %s", max_it, msg);
  ck_assert_msg(b2b_params_finalize(p, msg, sizeof msg) == B2B_OK, "finalize: %s", msg);
  return p;
}

/* ----------------------------------------------------------- NOT_CONVERGED */

static int n_limited, n_limited_to_one;

/* One crossing: the default run, then the limits 1, k - 1 and k. */
static void check_iteration_limit(const tst_pair_spec *spec, const double X[24], double mu,
                                  const char *what) {
  static double K0[576], K1[576];
  double info0[32], R0[24], h0[64], info1[32], R1[24], h1[64];
  b2b_params *pdef = params_with_max_iterations(50, mu);
  const int status = tst_pair(pdef, spec, X, NULL, h0, info0, R0, K0);
  ck_assert_msg(status == B2B_CONTACT_ACTIVE, "%s: status %d with the default limit", what,
                status);
  const int k = (int)info0[B2B_INFO_ITERATIONS];
  /* 0: the start (the chords' closest points) is already the solution */
  ck_assert_msg(k >= 0 && k < 50, "%s: %d iterations", what, k);
  if (k >= 2) {
    const int limits[2] = {1, k - 1};
    for (int l = 0; l < 2; ++l) {
      if (l == 1 && k - 1 == 1) break;
      b2b_params *p = params_with_max_iterations(limits[l], mu);
      for (int i = 0; i < 24; ++i) R1[i] = 7.0;
      for (int i = 0; i < 576; ++i) K1[i] = 7.0;
      const int st = tst_pair(p, spec, X, NULL, h1, info1, R1, K1);
      ck_assert_msg(st == B2B_CONTACT_NOT_CONVERGED,
                    "%s: max_iterations %d (default run needs %d): status %d, not "
                    "NOT_CONVERGED",
                    what, limits[l], k, st);
      ck_assert_msg(info1[B2B_INFO_ITERATIONS] == limits[l], "%s: reports %g iterations, limit %d",
                    what, info1[B2B_INFO_ITERATIONS], limits[l]);
      ck_assert_msg(tst_max_abs(R1, 24) == 0.0 && tst_max_abs(K1, 576) == 0.0,
                    "%s: NOT_CONVERGED carries a force", what);
      ck_assert(info1[B2B_INFO_NORMAL_FORCE] == 0.0);
      for (int i = 0; i < 3; ++i) ck_assert(info1[B2B_INFO_TANGENTIAL_FORCE + i] == 0.0);
      ck_assert(info1[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_NONE);
      /* The history it wrote is one the next call accepts (tst_pair fails
       * the test otherwise), and the next step converges from it. */
      double info2[32], R2[24], h2[64];
      ck_assert_int_eq(tst_pair(pdef, spec, X, h1, h2, info2, R2, NULL), B2B_CONTACT_ACTIVE);
      ++n_limited;
      n_limited_to_one += limits[l] == 1;
      b2b_params_destroy(&p);
    }
  }
  /* The limit k itself is enough, and changes nothing. */
  b2b_params *pk = params_with_max_iterations(k > 1 ? k : 1, mu);
  ck_assert_int_eq(tst_pair(pk, spec, X, NULL, h1, info1, R1, K1), B2B_CONTACT_ACTIVE);
  ck_assert_msg(memcmp(info0, info1, sizeof info0) == 0 && memcmp(R0, R1, sizeof R0) == 0 &&
                    memcmp(K0, K1, sizeof K0) == 0,
                "%s: max_iterations %d changes the outputs", what, k);
  b2b_params_destroy(&pk);
  b2b_params_destroy(&pdef);
}

START_TEST(not_converged_is_reachable_and_reported) {
  n_limited = n_limited_to_one = 0;
  tst_rng rng;
  tst_rng_seed(&rng, 7001);
  for (int fric = 0; fric < 2; ++fric)
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int rep = 0; rep < 3; ++rep) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          double X[24];
          const double angle = tst_uniform(&rng, 30, 90);
          tst_crossing(&rng, &spec, 0.5, angle, tst_uniform(&rng, -0.7, 0.7),
                       tst_uniform(&rng, -0.7, 0.7), 0.3, X);
          char what[160];
          snprintf(what, sizeof what, "%s x %s, angle %.1f%s", tst_kind_name(spec.kind[0]),
                   tst_kind_name(spec.kind[1]), angle, fric ? ", friction" : "");
          check_iteration_limit(&spec, X, fric ? 0.3 : 0.0, what);
        }
  printf("check_pair_contract: NOT_CONVERGED reached %d times (%d with max_iterations = 1)\n",
         n_limited, n_limited_to_one);
  /* Curved crossings need more than one Newton step from the chord start. */
  ck_assert_int_ge(n_limited_to_one, 40);
}
END_TEST

/* --------------------------------------------------------- pass-through */

static double worst_tangent, worst_residual;
static int n_checked;

/* Central differences (Richardson) of the residual and the potential of the
 * pair at X with hist_old fixed; compares with the analytic tangent. */
static void check_tangent_with_history(const b2b_params *p, const tst_pair_spec *spec,
                                       const double X[24], const double *hist_old, int friction,
                                       const char *what) {
  static double K[576], Kfd[576];
  double info[32], R[24], Rfd[24], hnew[64];
  const int status = tst_pair(p, spec, X, hist_old, hnew, info, R, K);
  ck_assert_int_eq(status, B2B_CONTACT_ACTIVE);
  const double f = info[B2B_INFO_NORMAL_FORCE];
  const double h = 1e-5;
  memset(Kfd, 0, sizeof Kfd);
  memset(Rfd, 0, sizeof Rfd);
  for (int a = 0; a < 24; ++a) {
    if (isnan(X[a])) continue;
    double dR[2][24], dE[2];
    for (int k = 0; k < 2; ++k) {
      const double step = k ? 0.5 * h : h;
      double Xp[24], Xm[24], ip[32], im[32], Rp[24], Rm[24], hs[64];
      memcpy(Xp, X, sizeof Xp);
      memcpy(Xm, X, sizeof Xm);
      Xp[a] += step;
      Xm[a] -= step;
      const int sp = tst_pair(p, spec, Xp, hist_old, hs, ip, Rp, NULL);
      const int sm = tst_pair(p, spec, Xm, hist_old, hs, im, Rm, NULL);
      ck_assert_msg(sp == status && sm == status, "%s: status changes under a perturbation",
                    what);
      if (friction)
        ck_assert_msg(ip[B2B_INFO_FRICTION_STATE] == info[B2B_INFO_FRICTION_STATE] &&
                          im[B2B_INFO_FRICTION_STATE] == info[B2B_INFO_FRICTION_STATE],
                      "%s: friction state changes under a perturbation", what);
      for (int r = 0; r < 24; ++r) dR[k][r] = (Rp[r] - Rm[r]) / (2 * step);
      dE[k] = (ip[B2B_INFO_ENERGY] - im[B2B_INFO_ENERGY]) / (2 * step);
    }
    for (int r = 0; r < 24; ++r) Kfd[r + 24 * a] = (4 * dR[1][r] - dR[0][r]) / 3;
    Rfd[a] = (4 * dE[1] - dE[0]) / 3;
  }
  const double ek = tst_rel_diff(K, Kfd, 576, 1e-12 * f);
  worst_tangent = fmax(worst_tangent, ek);
  ck_assert_msg(ek <= TOL, "%s: tangent vs FD of the residual, rel. error %.2e", what, ek);
  if (!friction) { /* with friction the residual is not a gradient */
    const double er = tst_rel_diff(R, Rfd, 24, 1e-12 * f);
    worst_residual = fmax(worst_residual, er);
    ck_assert_msg(er <= TOL, "%s: residual vs FD of the potential, rel. error %.2e", what, er);
  }
  ++n_checked;
}

/* Step 1 at distance +d1 (committed), step 2 at -d2 through the other side. */
static void pass_through_case(const b2b_params *p, tst_rng *rng, const tst_pair_spec *spec,
                              double d1, double d2, int friction, const char *what) {
  const tst_rng start = *rng;
  double X1[24], X2[24], info[32], R[24], h1[64], h2[64];
  const double angle = tst_uniform(rng, 30, 90);
  const double xi = tst_uniform(rng, -0.6, 0.6), eta = tst_uniform(rng, -0.6, 0.6);
  tst_crossing(rng, spec, 0.5, angle, xi, eta, d1, X1);
  /* The same patches, B on the other side of A: replay the generator. */
  tst_rng replay = start;
  (void)tst_uniform(&replay, 30, 90);
  (void)tst_uniform(&replay, -0.6, 0.6);
  (void)tst_uniform(&replay, -0.6, 0.6);
  tst_crossing(&replay, spec, 0.5, angle, xi, eta, -d2, X2);

  ck_assert_int_eq(tst_pair(p, spec, X1, NULL, h1, info, R, NULL), B2B_CONTACT_ACTIVE);
  double n1[3];
  memcpy(n1, &info[B2B_INFO_NORMAL], sizeof n1);
  ck_assert_int_eq(tst_pair(p, spec, X2, h1, h2, info, R, NULL), B2B_CONTACT_ACTIVE);
  const double want = -d2 - spec->radius[0] - spec->radius[1];
  ck_assert_msg(fabs(info[B2B_INFO_GAP] - want) <= 1e-9, "%s: sign-tracked gap %.12g, want %g",
                what, info[B2B_INFO_GAP], want);
  const double dot = n1[0] * info[B2B_INFO_NORMAL] + n1[1] * info[B2B_INFO_NORMAL + 1] +
                     n1[2] * info[B2B_INFO_NORMAL + 2];
  ck_assert_msg(dot > 0.999, "%s: the normal flipped (n . n1 = %g)", what, dot);
  check_tangent_with_history(p, spec, X2, h1, friction, what);
}

START_TEST(tangent_after_pass_through) {
  worst_tangent = worst_residual = 0.0;
  n_checked = 0;
  tst_rng rng;
  tst_rng_seed(&rng, 7002);
  for (int law = 0; law < B2B_LAW_COUNT; ++law) {
    b2b_params *p = tst_params(law, 1e3, 0.05);
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int rep = 0; rep < 2; ++rep) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          char what[160];
          /* well through (0.3 beyond), or just through (0.05 beyond) */
          const double d2 = rep ? 0.05 : 0.3;
          snprintf(what, sizeof what, "law %d, %s x %s, %g through", law,
                   tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), d2);
          pass_through_case(p, &rng, &spec, 0.3, d2, 0, what);
        }
    b2b_params_destroy(&p);
  }
  printf("check_pair_contract: pass-through, %d configurations; worst rel. error: tangent "
         "%.2e, residual %.2e\n",
         n_checked, worst_tangent, worst_residual);
  ck_assert_int_eq(n_checked, 64);
}
END_TEST

START_TEST(friction_tangent_after_pass_through) {
  worst_tangent = worst_residual = 0.0;
  n_checked = 0;
  tst_rng rng;
  tst_rng_seed(&rng, 7003);
  /* mu 0.3, eps_T 1e3: the step moves A's and B's material points along
   * the normal only, so the pair sticks (no tangential motion) */
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.3, 1e3);
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
      tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
      char what[160];
      snprintf(what, sizeof what, "friction, %s x %s", tst_kind_name(spec.kind[0]),
               tst_kind_name(spec.kind[1]));
      pass_through_case(p, &rng, &spec, 0.3, 0.3, 1, what);
    }
  b2b_params_destroy(&p);
  printf("check_pair_contract: pass-through with friction, %d configurations; worst rel. error: "
         "tangent %.2e\n",
         n_checked, worst_tangent);
  ck_assert_int_eq(n_checked, 16);
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("pair_contract");
  TCase *tc = tcase_create("contract");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, not_converged_is_reachable_and_reported);
  tcase_add_test(tc, tangent_after_pass_through);
  tcase_add_test(tc, friction_tangent_after_pass_through);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
