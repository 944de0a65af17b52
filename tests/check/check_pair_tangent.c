/* The contact element's derivatives against central finite differences:
 * tangent against the residual, residual against the contact potential.
 * Seeded random crossings for every pair of curve kinds, both normal laws,
 * crossing angles from 90 down to 1 degree, points near segment joints and
 * beam ends, curved patches. Also: the frictionless tangent is symmetric.
 * (Central differences with one Richardson step; see check_config.) */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pair_support.h"

#define TOL 1e-6

static double worst_tangent, worst_residual, worst_symmetry;
static int n_active;

/* Checks one configuration with central differences of step h if it is an
 * active contact; returns its contact status. */
static int check_config(const b2b_params *params, const tst_pair_spec *spec, const double X[24],
                        double h, const char *what) {
  static double K[576], Kfd[576];
  double info[32], R[24], Rfd[24];
  const int status = tst_pair(params, spec, X, NULL, NULL, info, R, K);
  if (status != B2B_CONTACT_ACTIVE) return status;
  const double f = info[B2B_INFO_NORMAL_FORCE];
  memset(Kfd, 0, sizeof Kfd);
  memset(Rfd, 0, sizeof Rfd);
  for (int a = 0; a < 24; ++a) {
    if (isnan(X[a])) continue;  // a slot the kinds do not read
    /* Central differences with steps h and h/2, combined by one Richardson
     * step (error O(h^4)): robust where the residual varies fast (small
     * crossing angles) without a step so small that rounding dominates. */
    double dR[2][24], dE[2];
    for (int k = 0; k < 2; ++k) {
      const double step = k ? 0.5 * h : h;
      double Xp[24], Xm[24], ip[32], im[32], Rp[24], Rm[24];
      memcpy(Xp, X, sizeof Xp);
      memcpy(Xm, X, sizeof Xm);
      Xp[a] += step;
      Xm[a] -= step;
      const int sp = tst_pair(params, spec, Xp, NULL, NULL, ip, Rp, NULL);
      const int sm = tst_pair(params, spec, Xm, NULL, NULL, im, Rm, NULL);
      ck_assert_msg(sp == status && sm == status,
                    "%s: status changes under a perturbation of %g", what, step);
      for (int r = 0; r < 24; ++r) dR[k][r] = (Rp[r] - Rm[r]) / (2 * step);
      dE[k] = (ip[B2B_INFO_ENERGY] - im[B2B_INFO_ENERGY]) / (2 * step);
    }
    for (int r = 0; r < 24; ++r) Kfd[r + 24 * a] = (4 * dR[1][r] - dR[0][r]) / 3;
    Rfd[a] = (4 * dE[1] - dE[0]) / 3;
  }
  /* Rows and columns of unused slots are exactly zero. */
  for (int a = 0; a < 24; ++a)
    if (isnan(X[a])) {
      ck_assert(R[a] == 0.0);
      for (int r = 0; r < 24; ++r) ck_assert(K[r + 24 * a] == 0.0 && K[a + 24 * r] == 0.0);
    }
  const double ek = tst_rel_diff(K, Kfd, 576, 1e-12 * f);
  const double er = tst_rel_diff(R, Rfd, 24, 1e-12 * f);
  const double asym = tst_asymmetry(K);
  worst_tangent = fmax(worst_tangent, ek);
  worst_residual = fmax(worst_residual, er);
  worst_symmetry = fmax(worst_symmetry, asym);
  ck_assert_msg(ek <= TOL, "%s: tangent vs FD of the residual, rel. error %.2e", what, ek);
  ck_assert_msg(er <= TOL, "%s: residual vs FD of the potential, rel. error %.2e", what, er);
  ck_assert_msg(asym <= 1e-10, "%s: tangent not symmetric, rel. %.2e", what, asym);
  ++n_active;
  return status;
}

static void reset(void) { worst_tangent = worst_residual = worst_symmetry = 0.0, n_active = 0; }

static void report(const char *name) {
  printf("%s: %d active configurations; worst rel. error: tangent %.2e, residual %.2e; "
         "asymmetry %.2e\n",
         name, n_active, worst_tangent, worst_residual, worst_symmetry);
}

/* Every pair of kinds, both laws, interior segments, moderate angles. */
START_TEST(all_kinds_both_laws) {
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 1001);
  for (int law = 0; law < B2B_LAW_COUNT; ++law) {
    b2b_params *p = tst_params(law, 1e3, 0.05);
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int rep = 0; rep < 4; ++rep) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          double X[24];
          const double angle = tst_uniform(&rng, 20, 90);
          /* penetrating, or (quadratic law) inside the regularisation zone */
          const double dist = 0.35 - tst_uniform(&rng, law ? -0.04 : 0.01, 0.1);
          tst_crossing(&rng, &spec, 0.5, angle, tst_uniform(&rng, -0.7, 0.7),
                       tst_uniform(&rng, -0.7, 0.7), dist, X);
          char what[128];
          snprintf(what, sizeof what, "law %d, %s x %s, angle %.1f", law,
                   tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), angle);
          check_config(p, &spec, X, 1e-5, what);
        }
    b2b_params_destroy(&p);
  }
  report("all kinds, both laws");
  ck_assert_int_ge(n_active, 100);
}
END_TEST

/* Crossing angles from 90 down to 1 degree. */
START_TEST(crossing_angles_down_to_1_degree) {
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 1002);
  const double angles[] = {90, 60, 30, 10, 5, 3, 2, 1};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  for (size_t q = 0; q < sizeof angles / sizeof angles[0]; ++q)
    for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k)
      for (int rep = 0; rep < 3; ++rep) {
        /* Slender beams on curved patches. The closest point at the crossing
         * is a local minimum of the distance only while angle^2 exceeds the
         * axes' distance times their relative curvature; beyond that it runs
         * off along the valley and point-wise contact is undefined (the
         * element reports OUTSIDE, correctly). So: radii small against the
         * element length, and turning below the crossing angle. */
        tst_pair_spec spec = {{k, (k + rep) % B2B_CURVE_KIND_COUNT}, {0, 0}, {0, 0},
                              {0.02, 0.015}};
        double X[24];
        const double rad = angles[q] * 3.14159265358979323846 / 180.0;
        tst_crossing(&rng, &spec, 0.25 * rad, angles[q], tst_uniform(&rng, -0.2, 0.2),
                     tst_uniform(&rng, -0.2, 0.2), 0.03, X);
        char what[128];
        snprintf(what, sizeof what, "angle %g, %s x %s", angles[q], tst_kind_name(spec.kind[0]),
                 tst_kind_name(spec.kind[1]));
        /* The closest points move 1/sin(angle) times faster than the nodes:
         * scale the difference step with sin(angle). */
        const int status = check_config(p, &spec, X, 1e-5 * sin(rad), what);
        ck_assert_msg(status == B2B_CONTACT_ACTIVE, "%s: contact status %d, not active", what,
                      status);
      }
  b2b_params_destroy(&p);
  report("angles 90 .. 1 degree");
}
END_TEST

/* Closest points near segment joints (xi, eta = +-0.99) and on beam-end
 * segments (REFLECT rules), strongly curved patches. */
START_TEST(near_joints_and_beam_ends) {
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 1003);
  b2b_params *p = tst_params(B2B_LAW_QUADRATIC, 5e2, 0.02);
  const double stars[] = {-0.99, 0.99};
  for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k)
    for (int end = 0; end < 2; ++end)
      for (int s = 0; s < 2; ++s)
        for (int rep = 0; rep < 3; ++rep) {
          tst_pair_spec spec = {{k, B2B_CURVE_KIND_COUNT - 1 - k}, {0, 0}, {0, 0},
                                {0.2, 0.15}};
          /* a beam end on the side of the closest point (midpoint segments
           * cannot end on both sides, so only that one) */
          if (end) {
            if (stars[s] < 0) spec.start_rule[0] = B2B_END_REFLECT;
            else spec.end_rule[0] = B2B_END_REFLECT;
          }
          double X[24];
          tst_crossing(&rng, &spec, 0.6, tst_uniform(&rng, 30, 90), stars[s],
                       tst_uniform(&rng, -0.5, 0.5), 0.3, X);
          char what[128];
          snprintf(what, sizeof what, "%s xi* %g%s", tst_kind_name(spec.kind[0]), stars[s],
                   end ? " at a beam end" : "");
          check_config(p, &spec, X, 1e-5, what);
        }
  b2b_params_destroy(&p);
  report("near joints and beam ends");
  ck_assert_int_ge(n_active, 30);
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("pair_tangent");
  TCase *tc = tcase_create("finite_differences");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, all_kinds_both_laws);
  tcase_add_test(tc, crossing_angles_down_to_1_degree);
  tcase_add_test(tc, near_joints_and_beam_ends);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
