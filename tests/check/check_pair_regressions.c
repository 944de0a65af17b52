/* Regression tests for defects found by an adversarial campaign against the
 * contact element, each built from the inputs that exposed it:
 *  - the quadratic law with a huge regularization gap: NaN or Inf reported
 *    with B2B_OK (0 * inf, g0^2 overflowing), or an overflow error where the
 *    true force and energy are finite;
 *  - the handover writing -Inf for a history whose xi was -1e308 (which the
 *    history check let through);
 *  - a pair far from the coordinates' origin (offset 1e8, unit elements):
 *    the search stopped on a tolerance of 64 eps |coordinate| and residual
 *    and tangent were off by 3e-6 relative (nodal and weighted kinds);
 *  - near-intersecting axes: a normal tilted by 6e-14 L / rho;
 *  - a midpoint hairpin (x1 = x3) and a nodal cusp: NaN with B2B_OK;
 *  - near-parallel straight segments: NOT_CONVERGED instead of PARALLEL;
 *  - candidates beyond the search's box: every iteration spent at its edge. */
#include <float.h>
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

/* The same crossing at the origin and translated by about 1e8 (coordinates on
 * a grid of 2^-26, the spacing of doubles at 1e8, so the translation is
 * exact, while a midpoint of two nodes there is not: the midpoint kind formed
 * (x1 + x2) / 2 at 1e8 and was 5e-9 off until positions became offsets to a
 * node of the patch, found against the AD reference): the results of a translated
 * pair must be those of the original up to rounding of the patch's size, for
 * every kind, frictionless and in a second, sliding step with friction. */
START_TEST(far_from_the_origin_as_at_the_origin) {
  const double offset[3] = {1e8, -1e8, 0.5e8};
  tst_rng rng;
  tst_rng_seed(&rng, 4242);
  double worst_r = 0.0, worst_k = 0.0;
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
      tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
      double X[24], Y[24], X2[24], Y2[24];
      tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 20, 90), tst_uniform(&rng, -0.6, 0.6),
                   tst_uniform(&rng, -0.6, 0.6), 0.3, X);
      for (int i = 0; i < 24; ++i) {
        X[i] = ldexp(nearbyint(ldexp(X[i], 26)), -26); /* NaN (unused slots) stays NaN */
        X2[i] = X[i] + (i % 3 == 1 ? 0.015625 : 0.0);  /* the second step slides along y */
        Y[i] = X[i] + offset[i % 3];
        Y2[i] = X2[i] + offset[i % 3];
      }
      for (int fric = 0; fric < 2; ++fric) {
        b2b_params *p = fric ? tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.3, 1e3)
                             : tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
        const int n_hist = tst_history_len(p);
        double h0[64] = {0}, hx[64], hy[64], hx2[64], hy2[64];
        double ix[32], iy[32], rx[24], ry[24], Kx[576], Ky[576];
        ck_assert(n_hist <= 64);
        int sx = tst_pair(p, &spec, X, h0, hx, ix, rx, Kx);
        int sy = tst_pair(p, &spec, Y, h0, hy, iy, ry, Ky);
        if (fric) { /* the second step, from each one's own committed history */
          sx = tst_pair(p, &spec, X2, hx, hx2, ix, rx, Kx);
          sy = tst_pair(p, &spec, Y2, hy, hy2, iy, ry, Ky);
        }
        ck_assert_msg(sx == B2B_CONTACT_ACTIVE && sy == B2B_CONTACT_ACTIVE,
                      "%s x %s, friction %d: status %d at the origin (%g iterations), %d far "
                      "from it (%g iterations, xi %.17g, eta %.17g)",
                      tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), fric, sx,
                      ix[B2B_INFO_ITERATIONS], sy, iy[B2B_INFO_ITERATIONS], iy[B2B_INFO_XI],
                      iy[B2B_INFO_ETA]);
        double rmax = 0.0, kmax = 0.0, dr = 0.0, dk = 0.0;
        for (int i = 0; i < 24; ++i) {
          rmax = fmax(rmax, fabs(rx[i]));
          dr = fmax(dr, fabs(rx[i] - ry[i]));
        }
        for (int i = 0; i < 576; ++i) {
          kmax = fmax(kmax, fabs(Kx[i]));
          dk = fmax(dk, fabs(Kx[i] - Ky[i]));
        }
        worst_r = fmax(worst_r, dr / rmax);
        worst_k = fmax(worst_k, dk / kmax);
        /* 1e-10: far below the 3e-6 of the defect, far above rounding of
         * the patch (the gap's own rounding is about 1e-15 / 0.05) */
        ck_assert_msg(dr <= 1e-10 * rmax && dk <= 1e-10 * kmax,
                      "%s x %s, friction %d: residual %.2e, tangent %.2e relative",
                      tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), fric, dr / rmax,
                      dk / kmax);
        b2b_params_destroy(&p);
      }
    }
  printf("far from the origin (offset 1e8): worst difference to the origin's results: "
         "residual %.2e, tangent %.2e relative\n", worst_r, worst_k);
}
END_TEST

/* Near-intersecting axes: the search stopped on a tangential residual of
 * about 1e-13 L whatever the axis distance rho, so the normal d / rho tilted
 * by about 6e-14 L / rho (0.12 rad at rho = 1e-12 L). Now the residual is
 * relative to rho too: the normal's error must stay at the conditioning of
 * the inputs, a few eps L / rho, against the crossing's construction (which
 * is itself rounded: its own normal is good to about 2 eps L / rho). */
START_TEST(normal_accurate_as_the_axes_meet) {
  tst_rng rng;
  tst_rng_seed(&rng, 777);
  double worst = 0.0; /* tilt * rho / eps */
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (int e = 4; e <= 10; ++e)
        for (int rep = 0; rep < 3; ++rep) {
          const double rho = pow(10.0, -e);
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          const double xs = tst_uniform(&rng, -0.6, 0.6), es = tst_uniform(&rng, -0.6, 0.6);
          double X[24];
          tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 20, 90), xs, es, rho, X);
          double xa[9], xb[9];
          tst_eval(spec.kind[0], 0, 0, X, NULL, xs, xa, NULL, NULL);
          tst_eval(spec.kind[1], 0, 0, X + 12, NULL, es, xb, NULL, NULL);
          double n[3], len = 0.0;
          for (int i = 0; i < 3; ++i) {
            n[i] = xa[i] - xb[i];
            len += n[i] * n[i];
          }
          len = sqrt(len);
          b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
          double info[32], r[24];
          const int st = tst_pair(p, &spec, X, NULL, NULL, info, r, NULL);
          ck_assert_msg(st == B2B_CONTACT_ACTIVE, "status %d", st);
          double c[3];
          const double *m = info + B2B_INFO_NORMAL;
          c[0] = m[1] * n[2] - m[2] * n[1];
          c[1] = m[2] * n[0] - m[0] * n[2];
          c[2] = m[0] * n[1] - m[1] * n[0];
          const double tilt = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / len;
          worst = fmax(worst, tilt * rho / DBL_EPSILON);
          b2b_params_destroy(&p);
        }
  printf("near-intersecting axes (rho = 1e-4 .. 1e-10 L, all kinds): normal tilt at most "
         "%.1f eps L / rho\n", worst);
  ck_assert_msg(worst <= 32.0, "normal tilt %.1f eps L / rho", worst);
}
END_TEST

/* A hairpin: a hermite-midpoint segment with x1 = x3 turns back at x2 (its
 * tangent vanishes at the apex). It returned OK with a NaN angle; the header
 * promises FOLDED, with the outputs untouched. */
START_TEST(midpoint_hairpin_is_folded) {
  const int seg[6] = {B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                      B2B_CURVE_HERMITE_MIDPOINT, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
  const double X[24] = {0, 0, 0, 0.5, -1, 0, 0.5, 1, 0, 0, 0, 0,
                        0, 0, 0, 1, 0, 0, 0, 0, 0, 5, 5, 5};
  const double radii[2] = {0.1, 0.1};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  double h0[8] = {0}, h1[8], info[32], r[24];
  for (int i = 0; i < 32; ++i) info[i] = -7.0;
  for (int i = 0; i < 24; ++i) r[i] = -7.0;
  char msg[B2B_ERRMSG_LEN] = "";
  int st = -1;
  const int rc = b2b_pair_eval(p, seg, X, NULL, radii, h0, h1, 8, &st, info, r, NULL, 24, msg,
                               sizeof msg);
  ck_assert_msg(rc == B2B_ERR_FOLDED, "returned %d: %s", rc, msg);
  ck_assert_msg(strstr(msg, "x1 and x3") != NULL, "%s", msg);
  ck_assert_int_eq(st, -1);
  for (int i = 0; i < 32; ++i) ck_assert(info[i] == -7.0);
  for (int i = 0; i < 24; ++i) ck_assert(r[i] == -7.0);
  b2b_params_destroy(&p);
}
END_TEST

/* A cusp: a nodal segment whose host end tangent points against its chord
 * stops and turns back inside (x' = 0 at xi = (1 - sqrt(10)) / 3). A beam
 * crossing it anywhere near the cusp, at scales 1 and 1e-9, gets B2B_OK with
 * finite outputs (PARALLEL where the closest point is the cusp itself). */
START_TEST(cusp_gives_finite_outputs) {
  const int seg[6] = {B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                      B2B_CURVE_HERMITE_NODAL, B2B_END_TANGENT, B2B_END_REFLECT};
  const double tangents[12] = {1, 0, 0, 1, 0, 0, -1, 0, 0, 1, 0, 0};
  const double xi_c = (1.0 - sqrt(10.0)) / 3.0;
  const double h = 0.25 * (1.0 - xi_c - xi_c * xi_c + xi_c * xi_c * xi_c) * -0.5 +
                   0.25 * (2.0 + 3.0 * xi_c - xi_c * xi_c * xi_c) +
                   0.25 * (-1.0 - xi_c + xi_c * xi_c + xi_c * xi_c * xi_c) * 0.5;
  int parallel = 0, evaluated = 0;
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  for (int sc = 0; sc < 2; ++sc) {
    const double L = sc ? 1e-9 : 1.0;
    for (int k = -20; k <= 20; ++k) {
      const double xa = (h + 1e-3 * k) * L; /* h: x at the cusp, for chord (0,0,0)-(1,0,0) */
      for (int lift = 0; lift < 2; ++lift) {
        const double z = lift ? 0.15 * L : 0.0;
        const double X[24] = {0, 0, 0, xa, -L, z, xa, L, z, 0, 0, 0,
                              0, 0, 0, 0, 0, 0, L, 0, 0, 0, 0, 0};
        const double radii[2] = {0.1 * L, 0.1 * L};
        double h0[8] = {0}, h1[8], info[32], r[24], K[576];
        char msg[B2B_ERRMSG_LEN] = "";
        int st = -1;
        const int rc = b2b_pair_eval(p, seg, X, tangents, radii, h0, h1, 8, &st, info, r, K, 24,
                                     msg, sizeof msg);
        ck_assert_msg(rc == B2B_OK, "scale %g, x %g: returned %d: %s", L, xa, rc, msg);
        ck_assert_msg(all_finite(info, 32) && all_finite(r, 24) && all_finite(K, 576),
                      "scale %g, x %g: status %d with a non-finite output", L, xa, st);
        parallel += st == B2B_CONTACT_PARALLEL;
        ++evaluated;
      }
    }
  }
  printf("cusp: %d crossings near it at scales 1 and 1e-9, all finite (%d PARALLEL)\n", evaluated,
         parallel);
  b2b_params_destroy(&p);
}
END_TEST

/* Straight segments crossing at angles far below "parallel_angle" (default
 * 0.5 degrees): the search cannot converge on the (nearly) singular problem
 * and returned NOT_CONVERGED after every iteration; b2b_pair.h promises
 * PARALLEL for axes within the parallel angle (found with the AD reference). */
START_TEST(near_parallel_is_parallel_not_a_failed_search) {
  const double angles[] = {1e-3, 1e-4, 3e-5, 1e-5, 3e-6, 2e-6, 1.5e-6, 1.1e-6, 9e-7};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  for (size_t q = 0; q < sizeof angles / sizeof angles[0]; ++q) {
    const double c = cos(angles[q]), s = sin(angles[q]);
    const double X[24] = {0, 0, 0, -0.5, 0.1, 0, 0.5, 0.1, 0, 0, 0, 0,
                          0, 0, 0, 0.15 - 0.5 * c, 0.1 - 0.5 * s, 0.3,
                          0.15 + 0.5 * c, 0.1 + 0.5 * s, 0.3, 0, 0, 0};
    const double radii[2] = {0.2, 0.15};
    double h0[8] = {0}, h1[8], info[32], r[24];
    char msg[B2B_ERRMSG_LEN] = "";
    int st = -1;
    ck_assert_int_eq(b2b_pair_eval(p, kLinear, X, NULL, radii, h0, h1, 8, &st, info, r, NULL, 24,
                                   msg, sizeof msg),
                     B2B_OK);
    ck_assert_msg(st == B2B_CONTACT_PARALLEL, "angle %g rad: status %d after %g iterations",
                  angles[q], st, info[B2B_INFO_ITERATIONS]);
    ck_assert(all_finite(info, 32) && info[B2B_INFO_ANGLE] < 0.5);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* Candidates whose closest point lies beyond the search's box (axes crossing
 * at xi = 4.5, every kind of B): OUTSIDE after at most 4 iterations (from the
 * segment's end, two steps to the box's edge, two held there), each without
 * a line search into the wall. The search spent every iteration at the
 * box's edge (50; 22.7 us a call), then up to 40 halvings of a step into the
 * wall per iteration (the cost study's OUTSIDE row: 1.4-3.5x an active
 * residual). */
START_TEST(outside_candidates_stop_at_once) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
    const int seg[6] = {B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                        kb, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
    /* A from (-1,0,0) to (1,0,0); B along y through x = 4.5, 0.2 above */
    const double X[24] = {-3, 0, 0, -1, 0, 0, 1, 0, 0, 3, 0, 0,
                          4.5, -3, 0.2, 4.5, -1, 0.2, 4.5, 1, 0.2, 4.5, 3, 0.2};
    const double radii[2] = {0.1, 0.1};
    double h0[8] = {0}, h1[8], info[32], r[24], K[576];
    char msg[B2B_ERRMSG_LEN] = "";
    int st = -1;
    ck_assert_int_eq(b2b_pair_eval(p, seg, X, NULL, radii, h0, h1, 8, &st, info, r, K, 24, msg,
                                   sizeof msg),
                     B2B_OK);
    ck_assert_msg(st == B2B_CONTACT_OUTSIDE && info[B2B_INFO_ITERATIONS] <= 4.0,
                  "%s: status %d after %g iterations", tst_kind_name(kb), st,
                  info[B2B_INFO_ITERATIONS]);
  }
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
  tcase_add_test(tc, far_from_the_origin_as_at_the_origin);
  tcase_add_test(tc, normal_accurate_as_the_axes_meet);
  tcase_add_test(tc, midpoint_hairpin_is_folded);
  tcase_add_test(tc, cusp_gives_finite_outputs);
  tcase_add_test(tc, near_parallel_is_parallel_not_a_failed_search);
  tcase_add_test(tc, outside_candidates_stop_at_once);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
