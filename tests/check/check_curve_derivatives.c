/* Every derivative of the smoothed centreline against central finite
 * differences on seeded random curved patches: d/dxi and d2/dxi2 of the
 * point, first derivatives of the point and of dx/dxi with respect to the 12
 * patch coordinates (FD of the point), and their second derivatives (FD of
 * the analytic first derivatives). All curve kinds, all end rules, xi at the
 * joints (+-1), inside and outside [-1, 1]. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"

#define N_PATCHES 12
#define TOL 1e-6

static const double kXi[] = {-1.0, -0.7, 0.0, 0.4, 1.0, 1.3};
#define N_XI ((int)(sizeof kXi / sizeof kXi[0]))

typedef struct {
  int start_rule, end_rule;
} rules_t;

/* Rule combinations that make sense for a kind (a segment centred on a node,
 * the midpoint kind's, cannot be both the first and the last of its beam). */
static int rule_sets(int kind, rules_t *out) {
  const int n = B2B_END_TANGENT + 1;
  int count = 0;
  for (int s = 0; s < n; ++s)
    for (int e = 0; e < n; ++e) {
      if (tst_kind_family(kind) == TST_CENTRED && s != B2B_END_NEIGHBOUR &&
          e != B2B_END_NEIGHBOUR)
        continue;
      out[count].start_rule = s;
      out[count].end_rule = e;
      ++count;
    }
  return count;
}

/* The patch with the slots this segment does not read set to NaN, so that any
 * read of them shows up as a failure. */
static unsigned mask_unused(int kind, rules_t r, double patch[12]) {
  unsigned used = 0x6u;
  switch (tst_kind_family(kind)) {
    case TST_CHORD:
      break;
    case TST_CENTRED:
      used = 0x2u | (r.start_rule == B2B_END_NEIGHBOUR ? 0x1u : 0u) |
             (r.end_rule == B2B_END_NEIGHBOUR ? 0x4u : 0u);
      break;
    case TST_NODAL:
      used |= (r.start_rule == B2B_END_NEIGHBOUR ? 0x1u : 0u) |
              (r.end_rule == B2B_END_NEIGHBOUR ? 0x8u : 0u);
      break;
  }
  for (int s = 0; s < 4; ++s)
    if (!(used & (1u << s)))
      for (int i = 0; i < 3; ++i) patch[3 * s + i] = NAN;
  return used;
}

/* Worst relative error of the running test, printed at its end as evidence. */
static double worst;
static double note(double e) {
  if (e > worst) worst = e;
  return e;
}

typedef void (*case_fn)(int kind, rules_t r, const double *patch, const double *tangents,
                        unsigned used, double xi);

static void for_all_cases(case_fn fn, uint64_t seed, const char *what) {
  worst = 0.0;
  tst_rng rng;
  tst_rng_seed(&rng, seed);
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    rules_t rs[9];
    const int nr = rule_sets(kind, rs);
    for (int p = 0; p < N_PATCHES; ++p) {
      double base[12], tangents[6];
      tst_random_patch(&rng, 1.0, 0.8, base);
      for (int i = 0; i < 6; ++i) tangents[i] = tst_uniform(&rng, -1.0, 1.0);
      for (int r = 0; r < nr; ++r) {
        double patch[12];
        memcpy(patch, base, sizeof patch);
        const unsigned used = mask_unused(kind, rs[r], patch);
        for (int q = 0; q < N_XI; ++q) fn(kind, rs[r], patch, tangents, used, kXi[q]);
      }
    }
  }
  printf("%s: worst relative error against central differences %.2e (tolerance %.0e)\n", what,
         worst, TOL);
}

static void check_xi(int kind, rules_t r, const double *patch, const double *tangents,
                     unsigned used, double xi) {
  (void)used;
  const double h = 1e-5;
  double x[9], xp[9], xm[9];
  tst_eval(kind, r.start_rule, r.end_rule, patch, tangents, xi, x, NULL, NULL);
  tst_eval(kind, r.start_rule, r.end_rule, patch, tangents, xi + h, xp, NULL, NULL);
  tst_eval(kind, r.start_rule, r.end_rule, patch, tangents, xi - h, xm, NULL, NULL);
  double fd1[3], fd2[3];
  for (int i = 0; i < 3; ++i) {
    fd1[i] = (xp[i] - xm[i]) / (2 * h);
    fd2[i] = (xp[3 + i] - xm[3 + i]) / (2 * h);
  }
  /* Scale floors: dx/dxi is about half an element, d2x/dxi2 about its curvature. */
  const double e1 = note(tst_rel_diff(x + 3, fd1, 3, 0.1));
  const double e2 = note(tst_rel_diff(x + 6, fd2, 3, 0.1));
  ck_assert_msg(e1 <= TOL, "%s rules %d/%d xi %g: dx/dxi rel. error %.2e", tst_kind_name(kind),
                r.start_rule, r.end_rule, xi, e1);
  ck_assert_msg(e2 <= TOL, "%s rules %d/%d xi %g: d2x/dxi2 rel. error %.2e", tst_kind_name(kind),
                r.start_rule, r.end_rule, xi, e2);
}

static void check_first(int kind, rules_t r, const double *patch, const double *tangents,
                        unsigned used, double xi) {
  double dx[72], fd[72];
  tst_eval(kind, r.start_rule, r.end_rule, patch, tangents, xi, NULL, dx, NULL);
  memset(fd, 0, sizeof fd);
  for (int a = 0; a < 12; ++a) {
    if (!(used & (1u << (a / 3)))) continue;
    const double h = 1e-6;
    double pp[12], pm[12], xp[9], xm[9];
    memcpy(pp, patch, sizeof pp);
    memcpy(pm, patch, sizeof pm);
    pp[a] += h;
    pm[a] -= h;
    tst_eval(kind, r.start_rule, r.end_rule, pp, tangents, xi, xp, NULL, NULL);
    tst_eval(kind, r.start_rule, r.end_rule, pm, tangents, xi, xm, NULL, NULL);
    for (int i = 0; i < 3; ++i) {
      fd[i + 3 * a] = (xp[i] - xm[i]) / (2 * h);
      fd[36 + i + 3 * a] = (xp[3 + i] - xm[3 + i]) / (2 * h);
    }
  }
  const double e0 = note(tst_rel_diff(dx, fd, 36, 1.0));
  const double e1 = note(tst_rel_diff(dx + 36, fd + 36, 36, 1.0));
  ck_assert_msg(e0 <= TOL, "%s rules %d/%d xi %g: dx/dX rel. error %.2e", tst_kind_name(kind),
                r.start_rule, r.end_rule, xi, e0);
  ck_assert_msg(e1 <= TOL, "%s rules %d/%d xi %g: d(dx/dxi)/dX rel. error %.2e",
                tst_kind_name(kind), r.start_rule, r.end_rule, xi, e1);
  /* Slots the segment does not read have exactly zero derivatives. */
  for (int a = 0; a < 12; ++a)
    if (!(used & (1u << (a / 3))))
      for (int i = 0; i < 3; ++i)
        ck_assert(dx[i + 3 * a] == 0.0 && dx[36 + i + 3 * a] == 0.0);
}

static void check_second(int kind, rules_t r, const double *patch, const double *tangents,
                         unsigned used, double xi) {
  static double d2x[864], fd[864];
  tst_eval(kind, r.start_rule, r.end_rule, patch, tangents, xi, NULL, NULL, d2x);
  memset(fd, 0, sizeof fd);
  for (int b = 0; b < 12; ++b) {
    if (!(used & (1u << (b / 3)))) continue;
    const double h = 1e-6;
    double pp[12], pm[12], dp[72], dm[72];
    memcpy(pp, patch, sizeof pp);
    memcpy(pm, patch, sizeof pm);
    pp[b] += h;
    pm[b] -= h;
    tst_eval(kind, r.start_rule, r.end_rule, pp, tangents, xi, NULL, dp, NULL);
    tst_eval(kind, r.start_rule, r.end_rule, pm, tangents, xi, NULL, dm, NULL);
    for (int w = 0; w < 2; ++w)
      for (int a = 0; a < 12; ++a)
        for (int i = 0; i < 3; ++i)
          fd[432 * w + i + 3 * (a + 12 * b)] =
              (dp[36 * w + i + 3 * a] - dm[36 * w + i + 3 * a]) / (2 * h);
  }
  /* Second derivatives scale like 1/element length (here about 1). */
  const double e0 = note(tst_rel_diff(d2x, fd, 432, 1.0));
  const double e1 = note(tst_rel_diff(d2x + 432, fd + 432, 432, 1.0));
  ck_assert_msg(e0 <= TOL, "%s rules %d/%d xi %g: d2x/dX2 rel. error %.2e", tst_kind_name(kind),
                r.start_rule, r.end_rule, xi, e0);
  ck_assert_msg(e1 <= TOL, "%s rules %d/%d xi %g: d2(dx/dxi)/dX2 rel. error %.2e",
                tst_kind_name(kind), r.start_rule, r.end_rule, xi, e1);
  /* Exactly symmetric in the two coordinates (as documented). */
  for (int w = 0; w < 2; ++w)
    for (int b = 0; b < 12; ++b)
      for (int a = 0; a < b; ++a)
        for (int i = 0; i < 3; ++i) {
          const double hab = d2x[432 * w + i + 3 * (a + 12 * b)];
          const double hba = d2x[432 * w + i + 3 * (b + 12 * a)];
          ck_assert_msg(hab == hba,
                        "%s: second derivative not symmetric (%d,%d)", tst_kind_name(kind), a, b);
        }
}

START_TEST(xi_derivatives) { for_all_cases(check_xi, 101, "d/dxi, d2/dxi2"); }
END_TEST

START_TEST(nodal_first_derivatives) { for_all_cases(check_first, 202, "first derivatives in X"); }
END_TEST

START_TEST(nodal_second_derivatives) { for_all_cases(check_second, 303, "second derivatives in X"); }
END_TEST

/* The kinds that are linear in the nodes have exactly zero second
 * derivatives; the node-preserving kinds do not (Litewka's point, entry 5 of
 * doc/bibliography.md; doc/curves.md section 8). */
START_TEST(second_derivatives_vanish_only_where_linear) {
  tst_rng rng;
  tst_rng_seed(&rng, 404);
  double patch[12];
  tst_random_patch(&rng, 1.0, 0.6, patch);
  static double d2x[864];
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    tst_eval(kind, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch, NULL, 0.3, NULL, NULL, d2x);
    const double m = tst_max_abs(d2x, 864);
    if (tst_kind_family(kind) != TST_NODAL) /* linear in the nodes */
      ck_assert_msg(m == 0.0, "%s: expected zero second derivatives", tst_kind_name(kind));
    else
      ck_assert_msg(m > 1e-3, "%s: expected non-zero second derivatives, max %g",
                    tst_kind_name(kind), m);
  }
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("curve_derivatives");
  TCase *tc = tcase_create("finite_differences");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, xi_derivatives);
  tcase_add_test(tc, nodal_first_derivatives);
  tcase_add_test(tc, nodal_second_derivatives);
  tcase_add_test(tc, second_derivatives_vanish_only_where_linear);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
