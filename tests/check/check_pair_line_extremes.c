/* The line-contact element (b2b_pair_eval_line) at the extremes of its
 * inputs. Every evaluation goes through one wrapper that fills every output
 * with a sentinel first and asserts the contract: on an error every output
 * untouched (status, line_info, point_info, new histories, residual,
 * tangent); on B2B_OK every output finite (line_info's MIN_GAP may be
 * DBL_MAX, "none"), residual and tangent zero unless the pair is ACTIVE.
 * The cases:
 *   - crossing angles 0 (exactly parallel), 1e-8, 1e-4, 1e-2, 1 degree and
 *     on through the blending range to 20: straight beams against the
 *     closed form (each point's gap sqrt(d^2 + x^2 sin^2 theta) - r_A - r_B,
 *     the force sum w_i J f_i to 1e-12), curved beams of every kind against
 *     the AD reference (tests/ad) to 1e-12: the line element's projection is
 *     a one-dimensional problem, well conditioned at any angle, so no
 *     criterion widens towards 0 (the point element's would);
 *   - coincident axes: every point at distance 0; with a fresh history the
 *     normal is undefined: NO_NORMAL, no force, no NaN; with a history
 *     holding the previous normals, that normal is used: ACTIVE, the gap
 *     -r_A - r_B at every point, the force eps_L (r_A + r_B) L; axes that
 *     intersect at one integration point (n odd, xi = 0): that point has no
 *     normal and no force, the others carry theirs, nothing is NaN;
 *   - radii ratios 1e-3 .. 1e3 (parallel straight beams: force eps_L pen L
 *     to 1e-12, every point active);
 *   - sizes 1e-6 and 1e6 and coordinates offset by 1e8: the force scales as
 *     eps_L pen L (to 1e-12), an exactly representable translation by 1e8
 *     reproduces the untranslated residual and tangent to 1e-12 relative,
 *     and a curved pair scaled by s gives s^2 the residual and s the tangent
 *     to 1e-12 (the relative accuracy is kept);
 *   - line_penalty 0: touching, every point owned, no force: OPEN, residual
 *     and tangent zero;
 *   - huge penalties: a force or tangent that would overflow is
 *     B2B_ERR_RANGE with every output untouched, never a NaN or an Inf; one
 *     that does not (1e250) is finite and proportional to the penalty;
 *   - NaN and Inf in coordinates, radii, end tangents and histories:
 *     B2B_ERR_NONFINITE, outputs untouched; a NaN in a slot the kind does
 *     not read is ignored;
 *   - n_points 1 (the midpoint rule: force 2 J f(0)) and 32 (against the
 *     closed form and the AD reference). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "b2b_ad.h"
#include "pair_support.h"

#define RADIUS 0.1
#define EPS_N 1e3
#define EPS_L 2e3
#define MU 0.3
#define EPS_T 8e2
#define EPS_LT 1.5e3
#define MAXP 32
#define MAXH ((MAXP + 1) * 12)
#define SENTINEL -12345.678

static const double kPi = 3.14159265358979323846;

static b2b_params *make_params(int law, int type, int friction, double eps_l, double eps_n) {
  const tst_line_spec spec = {eps_n, eps_l, friction ? MU : 0.0, EPS_T, EPS_LT};
  return tst_line_params(law, type, -1, &spec);
}

typedef struct {
  int rc, status;
  double li[16], pinfo[32 * MAXP], hist[MAXH], R[24], K[576];
  char msg[B2B_ERRMSG_LEN];
} res_t;

static int all_equal(const double *a, int n, double v) {
  for (int i = 0; i < n; ++i)
    if (!(a[i] == v)) return 0;
  return 1;
}
static int all_finite(const double *a, int n) {
  for (int i = 0; i < n; ++i)
    if (!isfinite(a[i])) return 0;
  return 1;
}
static int all_zero(const double *a, int n) { return all_equal(a, n, 0.0); }

static const double kFresh[MAXH];

/* b2b_pair_eval_line with sentinels and the contract's checks. */
static void run(const b2b_params *p, const int seg[6], const double X[24], const double *tang,
                const double radii[2], int n, const double *hist_old, res_t *r,
                const char *what) {
  const int hs = tst_history_len(p), len = (n + 1) * hs;
  r->status = -77;
  for (int i = 0; i < 16; ++i) r->li[i] = SENTINEL;
  for (int i = 0; i < 32 * MAXP; ++i) r->pinfo[i] = SENTINEL;
  for (int i = 0; i < MAXH; ++i) r->hist[i] = SENTINEL;
  for (int i = 0; i < 24; ++i) r->R[i] = SENTINEL;
  for (int i = 0; i < 576; ++i) r->K[i] = SENTINEL;
  r->msg[0] = 0;
  r->rc = b2b_pair_eval_line(p, seg, X, tang, radii, n, hist_old ? hist_old : kFresh, r->hist,
                             len, &r->status, r->li, r->pinfo, r->R, r->K, 24, r->msg,
                             sizeof r->msg);
  if (r->rc != B2B_OK) {
    ck_assert_msg(r->status == -77 && all_equal(r->li, 16, SENTINEL) &&
                      all_equal(r->pinfo, 32 * MAXP, SENTINEL) &&
                      all_equal(r->hist, MAXH, SENTINEL) && all_equal(r->R, 24, SENTINEL) &&
                      all_equal(r->K, 576, SENTINEL),
                  "%s: error %d (%s) but an output was written", what, r->rc, r->msg);
    ck_assert_msg(r->msg[0] != 0, "%s: error %d without a message", what, r->rc);
    return;
  }
  ck_assert_msg(all_finite(r->li, 16) && all_finite(r->pinfo, 32 * n) &&
                    all_finite(r->hist, len) && all_finite(r->R, 24) && all_finite(r->K, 576),
                "%s: B2B_OK with a non-finite output", what);
  ck_assert_msg(all_equal(r->pinfo + 32 * n, 32 * (MAXP - n), SENTINEL) &&
                    all_equal(r->hist + len, MAXH - len, SENTINEL),
                "%s: written beyond n_points", what);
  ck_assert_msg(r->status >= B2B_CONTACT_OPEN && r->status <= B2B_CONTACT_NO_NORMAL,
                "%s: status %d", what, r->status);
  if (r->status != B2B_CONTACT_ACTIVE)
    ck_assert_msg(all_zero(r->R, 24) && all_zero(r->K, 576),
                  "%s: status %d with a residual or tangent", what, r->status);
}

static void run_ok(const b2b_params *p, const int seg[6], const double X[24],
                   const double radii[2], int n, const double *hist_old, res_t *r,
                   const char *what) {
  run(p, seg, X, NULL, radii, n, hist_old, r, what);
  ck_assert_msg(r->rc == B2B_OK, "%s: returned %d: %s", what, r->rc, r->msg);
}

static double rel_err(const double *a, const double *b, int n) {
  double d = 0.0, m = 0.0;
  for (int i = 0; i < n; ++i) {
    d = fmax(d, fabs(a[i] - b[i]));
    m = fmax(m, fabs(b[i]));
  }
  return m > 0.0 ? d / m : d;
}

/* The Gauss-Legendre weight of the root x of P_n. */
static double gl_weight(int n, double x) {
  double p0 = 1.0, p1 = x;
  for (int k = 2; k <= n; ++k) {
    const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
    p0 = p1;
    p1 = p2;
  }
  const double dp = n * (x * p1 - p0) / (x * x - 1.0);
  return 2.0 / ((1.0 - x * x) * dp * dp);
}

static const int kLinearSeg[6] = {B2B_CURVE_LINEAR, 0, 0, B2B_CURVE_LINEAR, 0, 0};

/* Straight beams: A from (o - L/2, o, o + d) to (o + L/2, o, o + d), B
 * through (o, o, o) along (cos theta, sin theta, 0), 3 L long, all times
 * scale. Unread slots NaN. */
static void straight(double L, double d, double theta_deg, double scale, double offset,
                     double X[24]) {
  for (int k = 0; k < 24; ++k) X[k] = NAN;
  const double th = theta_deg * kPi / 180.0;
  X[3] = offset + scale * (-0.5 * L), X[4] = offset, X[5] = offset + scale * d;
  X[6] = offset + scale * (0.5 * L), X[7] = offset, X[8] = offset + scale * d;
  X[15] = offset + scale * (-1.5 * L * cos(th)), X[16] = offset + scale * (-1.5 * L * sin(th));
  X[17] = offset;
  X[18] = offset + scale * (1.5 * L * cos(th)), X[19] = offset + scale * (1.5 * L * sin(th));
  X[20] = offset;
}

/* The closed form of the straight configuration's line force (linear law):
 * sum_i w_i (L/2) eps_L max(0, r - sqrt(d^2 + x_i^2 sin^2 theta)), with the
 * points from the library's point info. */
static double closed_form(const res_t *r, int n, double L, double d, double theta_deg,
                          double rsum, double eps_l) {
  const double s = sin(theta_deg * kPi / 180.0);
  double F = 0.0;
  for (int i = 0; i < n; ++i) {
    const double xi = r->pinfo[32 * i + B2B_INFO_XI];
    const double x = 0.5 * L * xi;
    const double gap = hypot(d, x * s) - rsum;
    if (gap < 0) F += gl_weight(n, xi) * 0.5 * L * eps_l * (-gap);
  }
  return F;
}

/* The AD reference (double) of the same call; its residual and tangent
 * against the library's. */
static void against_ad(const b2b_params *p, const int seg[6], const double X[24],
                       const double radii[2], int n, const double *hist_old, const res_t *r,
                       double *ek, double *er) {
  static res_t o;
  const int len = (n + 1) * tst_history_len(p);
  const int rc = b2b_ad_pair_eval_line(p, seg, X, NULL, radii, n, hist_old ? hist_old : kFresh,
                                       o.hist, len, &o.status, o.li, o.pinfo, o.R, o.K, 24,
                                       o.msg, sizeof o.msg);
  ck_assert_msg(rc == B2B_OK, "reference: %d %s", rc, o.msg);
  ck_assert_msg(o.status == r->status, "status %d, the reference says %d", r->status, o.status);
  *ek = rel_err(r->K, o.K, 576);
  *er = rel_err(r->R, o.R, 24);
}

/* ------------------------------------------------------------- tests */

START_TEST(angles_from_parallel) {
  static const double angles[] = {0.0, 1e-8, 1e-4, 1e-2, 0.5, 1, 3, 5, 7, 10, 14, 15, 20};
  const int na = sizeof angles / sizeof angles[0];
  const double L = 1.2, pen = 0.01, d = 2 * RADIUS - pen, radii[2] = {RADIUS, RADIUS};
  double worst_cf = 0, worst_k = 0, worst_r = 0;
  for (int t = 0; t < 2; ++t) {
    const int type = t ? B2B_CONTACT_TYPE_ALL_ANGLE : B2B_CONTACT_TYPE_LINE;
    b2b_params *p = make_params(B2B_LAW_LINEAR, type, 0, EPS_L, EPS_N);
    double F0 = 0;
    for (int a = 0; a < na; ++a) {
      char what[120];
      snprintf(what, sizeof what, "type %d, straight, angle %g", type, angles[a]);
      double X[24];
      static res_t r;
      straight(L, d, angles[a], 1.0, 0.0, X);
      run_ok(p, kLinearSeg, X, radii, 8, NULL, &r, what);
      ck_assert_msg(r.status == B2B_CONTACT_ACTIVE, "%s: status %d", what, r.status);
      if (a == 0) F0 = r.li[B2B_LINE_INFO_NORMAL_FORCE];
      const double lam = r.li[B2B_LINE_INFO_POINT_WEIGHT];
      if (type == B2B_CONTACT_TYPE_LINE || angles[a] <= 5.0) {
        /* pure line: the closed form (at exactly line_angle the weight is
         * zero to the rounding of sin^2: 3e-29 seen) */
        ck_assert_msg(angles[a] < 5.0 ? lam == 0.0 : lam <= 1e-20, "%s: point weight %g", what,
                      lam);
        const double F = closed_form(&r, 8, L, d, angles[a], 2 * RADIUS, EPS_L);
        const double e = fabs(r.li[B2B_LINE_INFO_NORMAL_FORCE] - F) / F;
        worst_cf = fmax(worst_cf, e);
        ck_assert_msg(e <= 1e-12, "%s: force %.17g, closed form %.17g", what,
                      r.li[B2B_LINE_INFO_NORMAL_FORCE], F);
        if (angles[a] < 5.0)
          ck_assert_msg(r.li[B2B_LINE_INFO_SYMMETRIC] == 1.0 && tst_asymmetry(r.K) <= 1e-13,
                        "%s: frictionless line tangent not symmetric", what);
      } else if (angles[a] < 15.0) {
        ck_assert_msg(lam > 0.0 && lam < 1.0, "%s: point weight %g", what, lam);
      } else {
        ck_assert_msg(lam == 1.0 && r.li[B2B_LINE_INFO_ACTIVE_POINTS] == 0, "%s", what);
      }
      /* the limit theta -> 0 is continuous */
      if (angles[a] > 0 && angles[a] <= 1e-4)
        ck_assert_msg(fabs(r.li[B2B_LINE_INFO_NORMAL_FORCE] - F0) <= 1e-9 * F0,
                      "%s: force %.17g, at 0: %.17g", what, r.li[B2B_LINE_INFO_NORMAL_FORCE], F0);
      double ek, er;
      against_ad(p, kLinearSeg, X, radii, 8, NULL, &r, &ek, &er);
      worst_k = fmax(worst_k, ek);
      worst_r = fmax(worst_r, er);
      ck_assert_msg(ek <= 1e-12 && er <= 1e-12, "%s: against the reference: K %.2e, R %.2e",
                    what, ek, er);
    }
    /* curved beams of every kind pair at the same angles; quick mode: each
     * kind pair at every third angle (each angle with a third of the pairs) */
    tst_rng rng;
    tst_rng_seed(&rng, 41001 + t);
    for (int c = 0; c < B2B_CURVE_KIND_COUNT * B2B_CURVE_KIND_COUNT; ++c)
      for (int a = 0; a < na; ++a) {
        if (type == B2B_CONTACT_TYPE_LINE && angles[a] > 5) continue;
        if (tst_quick() && (a + c) % 3 != 0) continue;
        tst_pair_spec s = {{TST_KIND_A(c), TST_KIND_B(c)}, {0, 0}, {0, 0}, {RADIUS, RADIUS}};
        double X[24];
        tst_crossing(&rng, &s, 0.04, angles[a], tst_uniform(&rng, -0.2, 0.2),
                     tst_uniform(&rng, -0.2, 0.2), 2 * RADIUS - 0.01, X);
        const int seg[6] = {s.kind[0], 0, 0, s.kind[1], 0, 0};
        char what[120];
        snprintf(what, sizeof what, "type %d, %s x %s, angle %g", type, tst_kind_name(s.kind[0]),
                 tst_kind_name(s.kind[1]), angles[a]);
        static res_t r;
        run_ok(p, seg, X, s.radius, 6, NULL, &r, what);
        double ek, er;
        against_ad(p, seg, X, s.radius, 6, NULL, &r, &ek, &er);
        worst_k = fmax(worst_k, ek);
        worst_r = fmax(worst_r, er);
        ck_assert_msg(ek <= 1e-12 && er <= 1e-12, "%s: against the reference: K %.2e, R %.2e",
                      what, ek, er);
      }
    b2b_params_destroy(&p);
  }
  printf("angles 0 .. 20 degrees: closed form %.2e, against the reference: tangent %.2e, "
         "residual %.2e\n",
         worst_cf, worst_k, worst_r);
}
END_TEST

START_TEST(coincident_axes) {
  const double L = 1.2, radii[2] = {RADIUS, RADIUS};
  for (int fr = 0; fr < 2; ++fr) {
    b2b_params *p = make_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, fr, EPS_L, EPS_N);
    double X[24];
    static res_t r, r0;
    /* fresh: no normal anywhere */
    straight(L, 0.0, 0.0, 1.0, 0.0, X);
    run_ok(p, kLinearSeg, X, radii, 5, NULL, &r, "coincident, fresh");
    ck_assert_msg(r.status == B2B_CONTACT_NO_NORMAL, "coincident, fresh: status %d", r.status);
    ck_assert(r.li[B2B_LINE_INFO_ACTIVE_POINTS] == 0 && r.li[B2B_LINE_INFO_NORMAL_FORCE] == 0);
    for (int i = 0; i < 5; ++i)
      ck_assert(r.pinfo[32 * i + B2B_INFO_NORMAL_FORCE] == 0.0);
    /* with the normals of a committed step 0.15 apart: used, gap -2r */
    straight(L, 0.15, 0.0, 1.0, 0.0, X);
    run_ok(p, kLinearSeg, X, radii, 5, NULL, &r0, "0.15 apart");
    ck_assert_int_eq(r0.status, B2B_CONTACT_ACTIVE);
    straight(L, 0.0, 0.0, 1.0, 0.0, X);
    run_ok(p, kLinearSeg, X, radii, 5, r0.hist, &r, "coincident, with history");
    ck_assert_msg(r.status == B2B_CONTACT_ACTIVE, "coincident with history: status %d",
                  r.status);
    const double F = EPS_L * 2 * RADIUS * L;
    ck_assert_msg(fabs(r.li[B2B_LINE_INFO_NORMAL_FORCE] - F) <= 1e-12 * F,
                  "coincident with history: force %.17g, expected %.17g",
                  r.li[B2B_LINE_INFO_NORMAL_FORCE], F);
    for (int i = 0; i < 5; ++i) {
      const double *pi = r.pinfo + 32 * i;
      ck_assert(fabs(pi[B2B_INFO_GAP] + 2 * RADIUS) <= 1e-15);
      ck_assert(pi[B2B_INFO_NORMAL + 2] == 1.0); /* the committed normal, +z */
    }
    ck_assert(r.li[B2B_LINE_INFO_SYMMETRIC] == 0.0); /* the history's normal: see b2b_pair.h */
    /* axes crossing at 2 degrees through A's midpoint: the middle point of
     * an odd rule has no normal, the others carry force */
    for (int k = 0; k < 24; ++k) X[k] = NAN;
    straight(L, 0.0, 2.0, 1.0, 0.0, X);
    run_ok(p, kLinearSeg, X, radii, 5, NULL, &r, "intersecting at the midpoint");
    ck_assert_msg(r.status == B2B_CONTACT_ACTIVE, "intersecting: status %d", r.status);
    ck_assert_msg(r.pinfo[32 * 2 + B2B_INFO_NORMAL_FORCE] == 0.0 &&
                      r.li[B2B_LINE_INFO_ACTIVE_POINTS] == 4 &&
                      r.li[B2B_LINE_INFO_OWNED_POINTS] == 4,
                  "intersecting: middle force %g, active %g, owned %g",
                  r.pinfo[32 * 2 + B2B_INFO_NORMAL_FORCE], r.li[B2B_LINE_INFO_ACTIVE_POINTS],
                  r.li[B2B_LINE_INFO_OWNED_POINTS]);
    b2b_params_destroy(&p);
  }
}
END_TEST

START_TEST(radii_ratios) {
  b2b_params *p = make_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, 0, EPS_L, EPS_N);
  static const double ratios[] = {1e-3, 1e-2, 1.0, 1e2, 1e3};
  double worst = 0;
  for (size_t q = 0; q < sizeof ratios / sizeof ratios[0]; ++q) {
    /* r_A / r_B = ratio, r_A + r_B = 0.2 */
    const double rb = 0.2 / (1 + ratios[q]), ra = 0.2 - rb, radii[2] = {ra, rb};
    const double L = 1.2, pen = 1e-3 * (ra + rb), d = ra + rb - pen;
    double X[24];
    static res_t r;
    straight(L, d, 0.0, 1.0, 0.0, X);
    char what[80];
    snprintf(what, sizeof what, "radii ratio %g", ratios[q]);
    run_ok(p, kLinearSeg, X, radii, 8, NULL, &r, what);
    ck_assert_int_eq(r.status, B2B_CONTACT_ACTIVE);
    ck_assert_int_eq((int)r.li[B2B_LINE_INFO_ACTIVE_POINTS], 8);
    const double F = EPS_L * pen * L, e = fabs(r.li[B2B_LINE_INFO_NORMAL_FORCE] - F) / F;
    worst = fmax(worst, e);
    ck_assert_msg(e <= 1e-12, "%s: force %.17g vs %.17g", what, r.li[B2B_LINE_INFO_NORMAL_FORCE],
                  F);
  }
  /* curved, against the reference */
  tst_rng rng;
  tst_rng_seed(&rng, 41003);
  for (size_t q = 0; q < sizeof ratios / sizeof ratios[0]; ++q)
    for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
      const double rb = 0.2 / (1 + ratios[q]), ra = 0.2 - rb;
      tst_pair_spec s = {{kind, kind}, {0, 0}, {0, 0}, {ra, rb}};
      double X[24];
      tst_crossing(&rng, &s, 0.04, 1.0, 0, 0, 0.2 - 0.005, X);
      const int seg[6] = {kind, 0, 0, kind, 0, 0};
      static res_t r;
      run_ok(p, seg, X, s.radius, 6, NULL, &r, "curved radii ratio");
      double ek, er;
      against_ad(p, seg, X, s.radius, 6, NULL, &r, &ek, &er);
      ck_assert_msg(ek <= 1e-12 && er <= 1e-12, "ratio %g, %s: K %.2e R %.2e", ratios[q],
                    tst_kind_name(kind), ek, er);
    }
  printf("radii ratios 1e-3 .. 1e3: force against eps_L pen L %.2e\n", worst);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(sizes_and_offsets) {
  b2b_params *p = make_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, 0, EPS_L, EPS_N);
  static const double scales[] = {1e-6, 1.0, 1e6};
  double worst = 0;
  /* straight: the force is eps_L (pen s)(L s) */
  for (int q = 0; q < 3; ++q)
    for (int off = 0; off < 2; ++off) {
      const double s = scales[q], L = 1.25, pen = 0.0125, rr = 0.1;
      const double radii[2] = {rr * s, rr * s};
      const double offset = off ? 1e8 : 0.0;
      if (off && s < 1.0) continue; /* a 1e-6 pair at 1e8: 15 bits left, not a test of b2b */
      double X[24];
      static res_t r;
      straight(L, 2 * rr - pen, 0.0, s, offset, X);
      char what[80];
      snprintf(what, sizeof what, "scale %g, offset %g", s, offset);
      run_ok(p, kLinearSeg, X, radii, 8, NULL, &r, what);
      ck_assert_msg(r.status == B2B_CONTACT_ACTIVE, "%s: status %d", what, r.status);
      /* the penetration as the coordinates hold it */
      const double pen_x = 2 * rr * s - (X[5] - X[17]);
      const double F = EPS_L * pen_x * (X[6] - X[3]);
      const double e = fabs(r.li[B2B_LINE_INFO_NORMAL_FORCE] - F) / F;
      worst = fmax(worst, e);
      ck_assert_msg(e <= 1e-12, "%s: force %.17g vs %.17g", what,
                    r.li[B2B_LINE_INFO_NORMAL_FORCE], F);
      ck_assert_msg(fabs(r.li[B2B_LINE_INFO_LENGTH] - L * s) <= 1e-13 * L * s, "%s: length %g",
                    what, r.li[B2B_LINE_INFO_LENGTH]);
    }
  /* curved pairs: translation by 1e8 (exact on these dyadic coordinates)
   * and scaling by s */
  tst_rng rng;
  tst_rng_seed(&rng, 41004);
  double worst_t = 0, worst_s = 0;
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    tst_pair_spec sp = {{kind, kind}, {0, 0}, {0, 0}, {RADIUS, RADIUS}};
    double X[24];
    tst_crossing(&rng, &sp, 0.04, 1.0, 0.1, -0.1, 2 * RADIUS - 0.01, X);
    for (int a = 0; a < 24; ++a)
      if (!isnan(X[a])) X[a] = ldexp(round(ldexp(X[a], 20)), -20); /* 21 bits at most */
    const int seg[6] = {kind, 0, 0, kind, 0, 0};
    static res_t r1, rt, rs;
    run_ok(p, seg, X, sp.radius, 6, NULL, &r1, "curved");
    ck_assert_int_eq(r1.status, B2B_CONTACT_ACTIVE);
    double Xt[24];
    for (int a = 0; a < 24; ++a) Xt[a] = X[a] + 1e8;
    run_ok(p, seg, Xt, sp.radius, 6, NULL, &rt, "curved, offset 1e8");
    const double et = fmax(rel_err(rt.R, r1.R, 24), rel_err(rt.K, r1.K, 576));
    worst_t = fmax(worst_t, et);
    ck_assert_msg(et <= 1e-12, "%s: offset 1e8 changes residual/tangent by %.2e",
                  tst_kind_name(kind), et);
    for (int q = 0; q < 3; q += 2) {
      const double s = scales[q];
      double Xs[24], radii[2] = {RADIUS * s, RADIUS * s}, Rs[24], Ks[576];
      for (int a = 0; a < 24; ++a) Xs[a] = X[a] * s;
      run_ok(p, seg, Xs, radii, 6, NULL, &rs, "curved, scaled");
      ck_assert_int_eq(rs.status, B2B_CONTACT_ACTIVE);
      for (int a = 0; a < 24; ++a) Rs[a] = rs.R[a] / (s * s);
      for (int a = 0; a < 576; ++a) Ks[a] = rs.K[a] / s;
      const double es = fmax(rel_err(Rs, r1.R, 24), rel_err(Ks, r1.K, 576));
      worst_s = fmax(worst_s, es);
      ck_assert_msg(es <= 1e-12, "%s, scale %g: residual / s^2, tangent / s differ by %.2e",
                    tst_kind_name(kind), s, es);
    }
  }
  printf("sizes 1e-6 .. 1e6, offset 1e8: force %.2e, curved offset %.2e, curved scaled %.2e\n",
         worst, worst_t, worst_s);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(zero_line_penalty) {
  for (int law = 0; law < B2B_LAW_COUNT; ++law)
    for (int fr = 0; fr < 2; ++fr) {
      b2b_params *p = make_params(law, B2B_CONTACT_TYPE_LINE, fr, 0.0, EPS_N);
      double X[24];
      static res_t r;
      const double radii[2] = {RADIUS, RADIUS};
      straight(1.2, 2 * RADIUS - 0.01, 0.0, 1.0, 0.0, X);
      run_ok(p, kLinearSeg, X, radii, 6, NULL, &r, "line_penalty 0");
      ck_assert_msg(r.status == B2B_CONTACT_OPEN, "line_penalty 0: status %d", r.status);
      ck_assert(r.li[B2B_LINE_INFO_OWNED_POINTS] == 6 && r.li[B2B_LINE_INFO_ACTIVE_POINTS] == 0);
      ck_assert(r.li[B2B_LINE_INFO_NORMAL_FORCE] == 0.0 && r.li[B2B_LINE_INFO_ENERGY] == 0.0);
      ck_assert(fabs(r.li[B2B_LINE_INFO_MIN_GAP] + 0.01) <= 1e-15);
      b2b_params_destroy(&p);
    }
}
END_TEST

START_TEST(huge_penalties) {
  const double radii[2] = {RADIUS, RADIUS};
  double X[24];
  static res_t r, r1;
  /* 1e250: finite, proportional */
  b2b_params *p1 = make_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, 0, 1.0, EPS_N);
  b2b_params *p = make_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, 0, 1e250, EPS_N);
  straight(1.2, 2 * RADIUS - 0.01, 1.0, 1.0, 0.0, X);
  run_ok(p1, kLinearSeg, X, radii, 6, NULL, &r1, "penalty 1");
  run_ok(p, kLinearSeg, X, radii, 6, NULL, &r, "penalty 1e250");
  ck_assert_int_eq(r.status, B2B_CONTACT_ACTIVE);
  for (int a = 0; a < 24; ++a) r.R[a] /= 1e250;
  for (int a = 0; a < 576; ++a) r.K[a] /= 1e250;
  ck_assert_msg(rel_err(r.R, r1.R, 24) <= 1e-13 && rel_err(r.K, r1.K, 576) <= 1e-13,
                "penalty 1e250 not proportional: %.2e %.2e", rel_err(r.R, r1.R, 24),
                rel_err(r.K, r1.K, 576));
  b2b_params_destroy(&p);
  b2b_params_destroy(&p1);
  /* overflow: DBL_MAX/4 times a penetration of 9.5 (radii 5), line and
   * point penalties, both laws, with and without friction */
  const double big_radii[2] = {5.0, 5.0};
  for (int law = 0; law < B2B_LAW_COUNT; ++law)
    for (int t = 0; t < 2; ++t)
      for (int fr = 0; fr < 2; ++fr) {
        const int type = t ? B2B_CONTACT_TYPE_ALL_ANGLE : B2B_CONTACT_TYPE_LINE;
        p = make_params(law, type, fr, DBL_MAX / 4, DBL_MAX / 4);
        for (int ang = 0; ang < 3; ++ang) {
          const double angle = ang == 0 ? 0.0 : (ang == 1 ? 10.0 : 30.0);
          straight(1.2, 0.5, angle, 1.0, 0.0, X);
          char what[80];
          snprintf(what, sizeof what, "law %d, type %d, friction %d, angle %g, DBL_MAX/4", law,
                   type, fr, angle);
          run(p, kLinearSeg, X, NULL, big_radii, 6, NULL, &r, what);
          ck_assert_msg(r.rc == B2B_ERR_RANGE, "%s: returned %d (status %d)", what, r.rc,
                        r.status);
        }
        b2b_params_destroy(&p);
      }
}
END_TEST

START_TEST(non_finite_inputs) {
  b2b_params *p = make_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, 1, EPS_L, EPS_N);
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  const int nodal[6] = {B2B_CURVE_HERMITE_NODAL, 0, 0, B2B_CURVE_HERMITE_NODAL, 0, 0};
  const int nodal_tangent[6] = {B2B_CURVE_HERMITE_NODAL, B2B_END_TANGENT, 0,
                                B2B_CURVE_HERMITE_NODAL, 0, 0};
  double X[24], tang[12];
  static res_t r;
  const double radii[2] = {RADIUS, RADIUS};
  for (int v = 0; v < 3; ++v) {
    /* every read coordinate */
    for (int a = 0; a < 24; ++a) {
      straight(1.2, 2 * RADIUS - 0.01, 2.0, 1.0, 0.0, X);
      for (int k = 0; k < 24; ++k)
        if (isnan(X[k])) X[k] = 0.5 * k; /* nodal: every slot read */
      X[a] = bad[v];
      for (int k = 0; k < 12; ++k) tang[k] = (k % 3 == 0) ? 1.0 : 0.0;
      run(p, nodal, X, tang, radii, 4, NULL, &r, "bad coordinate");
      ck_assert_msg(r.rc == B2B_ERR_NONFINITE, "X[%d] = %g: returned %d", a, bad[v], r.rc);
    }
    /* an end tangent in force, a radius, a history entry */
    straight(1.2, 2 * RADIUS - 0.01, 2.0, 1.0, 0.0, X);
    for (int k = 0; k < 24; ++k)
      if (isnan(X[k])) X[k] = 0.5 * k;
    for (int k = 0; k < 12; ++k) tang[k] = (k % 3 == 0) ? 1.0 : 0.0;
    tang[1] = bad[v];
    run(p, nodal_tangent, X, tang, radii, 4, NULL, &r, "bad end tangent");
    ck_assert_msg(r.rc == B2B_ERR_NONFINITE, "end tangent %g: returned %d", bad[v], r.rc);
    tang[1] = 0.0;
    for (int b = 0; b < 2; ++b) {
      double rb[2] = {RADIUS, RADIUS};
      rb[b] = bad[v];
      run(p, nodal, X, tang, rb, 4, NULL, &r, "bad radius");
      ck_assert_msg(r.rc == B2B_ERR_NONFINITE, "radius %d = %g: returned %d", b, bad[v], r.rc);
    }
    static double h[MAXH];
    const int len = 5 * tst_history_len(p);
    for (int k = 0; k < len; k += 7) {
      memset(h, 0, sizeof h);
      h[k] = bad[v];
      run(p, nodal, X, tang, radii, 4, h, &r, "bad history");
      ck_assert_msg(r.rc == B2B_ERR_NONFINITE, "hist_old[%d] = %g: returned %d", k, bad[v],
                    r.rc);
    }
    /* a NaN in a slot the linear kind does not read: ignored */
    straight(1.2, 2 * RADIUS - 0.01, 2.0, 1.0, 0.0, X);
    X[0] = X[10] = X[12] = X[23] = bad[v];
    run(p, kLinearSeg, X, NULL, radii, 4, NULL, &r, "unread slots");
    ck_assert_msg(r.rc == B2B_OK && r.status == B2B_CONTACT_ACTIVE, "unread slots: %d %d", r.rc,
                  r.status);
  }
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(one_and_32_points) {
  const double L = 1.2, pen = 0.01, d = 2 * RADIUS - pen, radii[2] = {RADIUS, RADIUS};
  for (int fr = 0; fr < 2; ++fr) {
    b2b_params *p = make_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, fr, EPS_L, EPS_N);
    double X[24];
    static res_t r;
    /* n = 1: the midpoint rule, weight 2: 2 (L/2) f(0) */
    straight(L, d, 3.0, 1.0, 0.0, X);
    run_ok(p, kLinearSeg, X, radii, 1, NULL, &r, "n 1");
    ck_assert(r.pinfo[B2B_INFO_XI] == 0.0);
    ck_assert_msg(fabs(r.li[B2B_LINE_INFO_NORMAL_FORCE] - EPS_L * pen * L) <= 1e-12 * EPS_L * pen * L,
                  "n 1: force %.17g", r.li[B2B_LINE_INFO_NORMAL_FORCE]);
    /* n = 32: closed form and the reference */
    run_ok(p, kLinearSeg, X, radii, 32, NULL, &r, "n 32");
    const double F = closed_form(&r, 32, L, d, 3.0, 2 * RADIUS, EPS_L);
    ck_assert_msg(fabs(r.li[B2B_LINE_INFO_NORMAL_FORCE] - F) <= 1e-12 * F,
                  "n 32: force %.17g vs %.17g", r.li[B2B_LINE_INFO_NORMAL_FORCE], F);
    ck_assert_msg(fabs(r.li[B2B_LINE_INFO_LENGTH] - L) <= 1e-13 * L, "n 32: length %.17g",
                  r.li[B2B_LINE_INFO_LENGTH]);
    tst_rng rng;
    tst_rng_seed(&rng, 41007);
    for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
      for (int q = 0; q < 2; ++q) {
        const int n = q ? 32 : 1;
        tst_pair_spec s = {{kind, kind}, {0, 0}, {0, 0}, {RADIUS, RADIUS}};
        tst_crossing(&rng, &s, 0.04, 2.0, 0, 0, 2 * RADIUS - 0.01, X);
        const int seg[6] = {kind, 0, 0, kind, 0, 0};
        static double hist[MAXH];
        run_ok(p, seg, X, s.radius, n, NULL, &r, "curved");
        memcpy(hist, r.hist, sizeof hist);
        for (int a = 12; a < 24; ++a) X[a] += (a % 3 == 0) ? 4e-3 : 0.0; /* slide B along x */
        run_ok(p, seg, X, s.radius, n, fr ? hist : NULL, &r, "curved, slid");
        ck_assert_int_eq(r.status, B2B_CONTACT_ACTIVE);
        double ek, er;
        against_ad(p, seg, X, s.radius, n, fr ? hist : NULL, &r, &ek, &er);
        ck_assert_msg(ek <= 1e-12 && er <= 1e-12, "%s, n %d, friction %d: K %.2e R %.2e",
                      tst_kind_name(kind), n, fr, ek, er);
      }
    b2b_params_destroy(&p);
  }
}
END_TEST

/* Regression (a library bug this campaign found, fixed): ALL_ANGLE above point_angle with a
 * line penalty whose force overflows. The integration points have weight
 * 1 - lambda = 0, so their (infinite) forces reach neither line_info nor
 * the residual, but each point's point_info (NORMAL_FORCE, ENERGY) is inf
 * and the call returns B2B_OK. b2b_pair.h: a force or energy that would
 * overflow is B2B_ERR_RANGE "whatever the contact status", and a
 * successful call has finite outputs. src/pair/line_contact.cpp, end of
 * line_sum: out.overflow tests line_info, residual, hist_new and K, never
 * point_info (nor the unweighted per-point values). At 2 degrees (weight
 * 1) the same penalty is B2B_ERR_RANGE, as it should be. */
START_TEST(regression_point_info_overflow) {
  b2b_params *p = make_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, 0, DBL_MAX / 4, EPS_N);
  const double big_radii[2] = {5.0, 5.0};
  double X[24];
  static res_t r;
  straight(1.2, 0.5, 2.0, 1.0, 0.0, X);
  run(p, kLinearSeg, X, NULL, big_radii, 6, NULL, &r, "huge line penalty at 2 degrees");
  ck_assert_int_eq(r.rc, B2B_ERR_RANGE);
  straight(1.2, 0.5, 30.0, 1.0, 0.0, X);
  /* run() asserts finite outputs on B2B_OK: this is where it fails */
  run(p, kLinearSeg, X, NULL, big_radii, 6, NULL, &r,
      "huge line penalty at 30 degrees (line weight 0), point_info");
  ck_assert_msg(r.rc == B2B_ERR_RANGE, "returned %d", r.rc);
  b2b_params_destroy(&p);
}
END_TEST

/* Regression (a library bug fuzz_pair_line found, fixed): with the
 * tangent option FD, a pair that carries no force (status OPEN: the beams
 * touch within 1e-9) returns a non-zero tangent, the differences of
 * residuals at perturbed configurations that do penetrate.
 * b2b_pair.h: "Where the pair carries no force both are zero" (and
 * b2b_pair_eval's FD tangent is zero there). src/pair/line_contact.cpp,
 * evaluate_line: the FD branch fills K whatever out.contact_status is. */
START_TEST(regression_fd_tangent_not_active) {
  b2b_params *p = NULL;
  char msg[B2B_ERRMSG_LEN];
  ck_assert(b2b_params_create(&p, msg, sizeof msg) == B2B_OK);
  b2b_params_set_real(p, "penalty", EPS_N, msg, sizeof msg);
  b2b_params_set_int(p, "contact_type", B2B_CONTACT_TYPE_LINE, msg, sizeof msg);
  b2b_params_set_real(p, "line_penalty", EPS_L, msg, sizeof msg);
  b2b_params_set_int(p, "tangent", B2B_TANGENT_FD, msg, sizeof msg);
  ck_assert(b2b_params_finalize(p, msg, sizeof msg) == B2B_OK);
  const double radii[2] = {RADIUS, RADIUS};
  double X[24];
  static res_t r;
  straight(1.2, 2 * RADIUS + 1e-9, 0.0, 1.0, 0.0, X);
  r.rc = b2b_pair_eval_line(p, kLinearSeg, X, NULL, radii, 4, kFresh, r.hist,
                            5 * tst_history_len(p), &r.status, r.li, r.pinfo, r.R, r.K, 24, r.msg,
                            sizeof r.msg);
  ck_assert_int_eq(r.rc, B2B_OK);
  ck_assert_int_eq(r.status, B2B_CONTACT_OPEN);
  ck_assert_msg(all_zero(r.R, 24), "OPEN with a residual");
  double m = 0.0;
  for (int k = 0; k < 576; ++k) m = fmax(m, fabs(r.K[k]));
  ck_assert_msg(m == 0.0, "status OPEN, tangent option FD: max |K| = %g", m);
  b2b_params_destroy(&p);
}
END_TEST

int main(void) {
  Suite *s = suite_create("pair_line_extremes");
  TCase *tc = tcase_create("extremes");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, angles_from_parallel);
  tcase_add_test(tc, coincident_axes);
  tcase_add_test(tc, radii_ratios);
  tcase_add_test(tc, sizes_and_offsets);
  tcase_add_test(tc, zero_line_penalty);
  tcase_add_test(tc, huge_penalties);
  tcase_add_test(tc, non_finite_inputs);
  tcase_add_test(tc, one_and_32_points);
  suite_add_tcase(s, tc);
  TCase *fixed = tcase_create("regressions");
  tcase_add_test(fixed, regression_point_info_overflow);
  tcase_add_test(fixed, regression_fd_tangent_not_active);
  suite_add_tcase(s, fixed);
  return tst_run_suite(s);
}
