/* The line-contact element (b2b_pair_eval_line) against its forward-mode AD
 * reference (b2b_ad_pair_eval_line, tests/ad/ad_line.hpp): Gauss points of
 * the reference's own, each the AD point element with A's parameter held,
 * the length element and the blending weights in the dual type, the
 * residual as written differentiated as a whole.
 *
 * On seeded random curved patches of every pair of curve kinds touching
 * nearly parallel (LINE: 0 to 4 degrees) or crossing inside the blending
 * range (ALL_ANGLE: 6 to 14 degrees, where the blend of 5 .. 15 is partial
 * and its weights' derivatives count), both normal laws, frictionless and
 * with friction in stick and in slip (committed histories written by the
 * library, then B slid along A), 2 to 9 integration points, B's end at a
 * beam end (REFLECT) in part of them:
 *   - status, line_info (counts and flags exactly, forces, energies, gap,
 *     length and weights relative to their scales), every point's info (but
 *     the iteration count), every history slot, residual and tangent: the
 *     residual and tangent to 1e-12 relative in the max norm, as
 *     check_pair_ad;
 *   - the reference against itself: dual and double values bit for bit,
 *     and without friction and blend its residual equals the AD gradient of
 *     its potential sum_i w_i J_i pi(g_i);
 *   - the "tangent" options SYMMETRIC, MAIN and FD against the reference's;
 *   - checks of the checks: a tangent perturbed in one entry by twice the
 *     tolerance fails the criterion, and a reference with the projections
 *     frozen in the derivative is rejected by a wide margin.
 * The worst errors are printed per contact type and friction state. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "b2b_ad.h"
#include "pair_support.h"

#define TOL_K 1e-12
#define TOL_R 1e-12
#define TOL_I 1e-12
#define TOL_SELF 1e-12
#define RADIUS 0.1
#define EPS_N 1e3
#define EPS_L 2e3
#define MU 0.3
#define EPS_T 8e2
#define EPS_LT 1.5e3
#define MAXP 32
#define HS 12
#define MAXH ((MAXP + 1) * HS)

enum { ST_NONE = 0, ST_STICK = 1, ST_SLIP = 2, N_STATES = 3 };
static const char *const state_name[N_STATES] = {"frictionless", "stick", "slip"};

/* ------------------------------------------------------------- helpers */

static b2b_params *line_params(int law, int type, int friction, int tangent) {
  const tst_line_spec spec = {EPS_N, EPS_L, friction ? MU : 0.0, EPS_T, EPS_LT};
  return tst_line_params(law, type, tangent, &spec);
}

typedef struct {
  int status;
  double li[16], pinfo[32 * MAXP], hist[MAXH], R[24], K[576], grad[24], mismatch;
} out_t;

static const double kFresh[MAXH];

static void segs(const tst_pair_spec *s, int seg[6]) {
  for (int b = 0; b < 2; ++b) {
    seg[3 * b] = s->kind[b];
    seg[3 * b + 1] = s->start_rule[b];
    seg[3 * b + 2] = s->end_rule[b];
  }
}

static void lib_line(const b2b_params *p, const tst_pair_spec *s, const double X[24], int n,
                     const double *hist_old, out_t *o) {
  int seg[6];
  segs(s, seg);
  char msg[B2B_ERRMSG_LEN] = "";
  const int len = (n + 1) * tst_history_len(p);
  const int st = b2b_pair_eval_line(p, seg, X, NULL, s->radius, n, hist_old ? hist_old : kFresh,
                                    o->hist, len, &o->status, o->li, o->pinfo, o->R, o->K, 24,
                                    msg, sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_pair_eval_line returned %d: %s", st, msg);
}

static void ad_line(const b2b_params *p, const tst_pair_spec *s, const double X[24], int n,
                    const double *hist_old, int flags, out_t *o) {
  int seg[6];
  segs(s, seg);
  char msg[B2B_ERRMSG_LEN] = "";
  const int len = (n + 1) * tst_history_len(p);
  const int st = b2b_ad_pair_eval_line_ex(p, seg, X, NULL, s->radius, n,
                                          hist_old ? hist_old : kFresh, o->hist, len, flags,
                                          &o->status, o->li, o->pinfo, o->R, o->K, 24, o->grad,
                                          &o->mismatch, msg, sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_ad_pair_eval_line returned %d: %s", st, msg);
}

/* max|a - b| / max|b| (max|a - b| if b is zero). */
static double rel_err(const double *a, const double *b, int n) {
  double d = 0.0, m = 0.0;
  for (int i = 0; i < n; ++i) {
    d = fmax(d, fabs(a[i] - b[i]));
    m = fmax(m, fabs(b[i]));
  }
  return m > 0.0 ? d / m : d;
}

static const char *worst_field;
static int worst_slot; /* the point (history slot - 1) of the worst entry; -1: line_info */
static int cur_slot;
static double worst_val; /* the largest entry error of the configuration so far */
static double upd(double e, double v, const char *name) {
  if (v > worst_val) worst_field = name, worst_slot = cur_slot, worst_val = v;
  return v > e ? v : e;
}

/* One point's info, as check_pair_ad: each entry relative to its natural
 * scale, flags exactly. Forces are measured against the larger of the
 * point's force and f_scale, the largest point force of the configuration:
 * the slip measure of a point is a difference of positions, rounded to
 * about eps times the coordinates, so eps_LT times that is the absolute
 * accuracy of a tangential force, however small the point's normal force
 * (a point at the edge of the contact zone). */
static double point_info_error(const double *a, const double *b, double eps_t, double f_scale,
                               int pt, const char *what) {
  const double f = fmax(fmax(b[B2B_INFO_NORMAL_FORCE], f_scale), 1e-300);
  const double slip_unit = MU * f / eps_t;
  double e = 0.0;
  e = upd(e, fabs(a[B2B_INFO_XI] - b[B2B_INFO_XI]), "xi");
  e = upd(e, fabs(a[B2B_INFO_ETA] - b[B2B_INFO_ETA]), "eta");
  for (int i = 0; i < 3; ++i) {
    const double c = 1.0 + fabs(b[B2B_INFO_POINT_A + i]) + fabs(b[B2B_INFO_POINT_B + i]);
    e = upd(e, fabs(a[B2B_INFO_POINT_A + i] - b[B2B_INFO_POINT_A + i]) / c, "point A");
    e = upd(e, fabs(a[B2B_INFO_POINT_B + i] - b[B2B_INFO_POINT_B + i]) / c, "point B");
    e = upd(e, fabs(a[B2B_INFO_NORMAL + i] - b[B2B_INFO_NORMAL + i]), "normal");
    e = upd(e, fabs(a[B2B_INFO_TANGENTIAL_FORCE + i] - b[B2B_INFO_TANGENTIAL_FORCE + i]) / f,
            "tangential force");
    e = upd(e, fabs(a[B2B_INFO_SLIP + i] - b[B2B_INFO_SLIP + i]) / slip_unit, "slip");
  }
  e = upd(e, fabs(a[B2B_INFO_GAP] - b[B2B_INFO_GAP]), "gap");
  e = upd(e, fabs(a[B2B_INFO_NORMAL_FORCE] - b[B2B_INFO_NORMAL_FORCE]) / f, "normal force");
  e = upd(e, fabs(a[B2B_INFO_ENERGY] - b[B2B_INFO_ENERGY]) / f, "energy");
  e = upd(e, fabs(a[B2B_INFO_ANGLE] - b[B2B_INFO_ANGLE]) / 90.0, "angle");
  e = upd(e, fabs(a[B2B_INFO_DISSIPATION] - b[B2B_INFO_DISSIPATION]) / (f * slip_unit),
          "dissipation");
  ck_assert_msg(a[B2B_INFO_SYMMETRIC] == b[B2B_INFO_SYMMETRIC] &&
                    a[B2B_INFO_FRICTION_STATE] == b[B2B_INFO_FRICTION_STATE],
                "%s, point %d: symmetric flag %g / %g, friction state %g / %g "
                "(library / reference)",
                what, pt, a[B2B_INFO_SYMMETRIC], b[B2B_INFO_SYMMETRIC],
                a[B2B_INFO_FRICTION_STATE], b[B2B_INFO_FRICTION_STATE]);
  for (int i = 25; i < 32; ++i)
    ck_assert_msg(a[i] == 0.0 && b[i] == 0.0, "%s, point %d: info[%d] %g / %g", what, pt, i,
                  a[i], b[i]);
  return e;
}

static double hist_error(const double *ha, const double *hb, int nh, double f, int slot,
                         const char *what) {
  double e = 0.0;
  for (int i = 0; i < nh; ++i) {
    double scale = 0.0; /* 0: must be equal */
    if (i >= 2 && i <= 6) scale = 1.0;
    if (i == 9 || i == 10) scale = fmax(f, 1e-300);
    if (scale == 0.0)
      ck_assert_msg(ha[i] == hb[i], "%s: history slot %d [%d] %g / %g (library / reference)",
                    what, slot, i, ha[i], hb[i]);
    else
      e = upd(e, fabs(ha[i] - hb[i]) / scale, "history");
  }
  return e;
}

/* line_info: counts, flags and status exactly; the rest relative to its
 * scale (forces to the integrated force F, energy and dissipation to F
 * times a length, gap and length to the segments' length, order one). */
static double line_info_error(const double *a, const double *b, const char *what) {
  static const int exact[] = {B2B_LINE_INFO_POINTS,       B2B_LINE_INFO_ACTIVE_POINTS,
                              B2B_LINE_INFO_OWNED_POINTS, B2B_LINE_INFO_SYMMETRIC,
                              B2B_LINE_INFO_STICK_POINTS, B2B_LINE_INFO_SLIP_POINTS,
                              B2B_LINE_INFO_POINT_STATUS, 14, 15};
  for (size_t k = 0; k < sizeof exact / sizeof exact[0]; ++k)
    ck_assert_msg(a[exact[k]] == b[exact[k]], "%s: line_info[%d] %g / %g (library / reference)",
                  what, exact[k], a[exact[k]], b[exact[k]]);
  const double F = fmax(b[B2B_LINE_INFO_NORMAL_FORCE], 1e-300);
  double e = 0.0;
  e = upd(e, fabs(a[B2B_LINE_INFO_NORMAL_FORCE] - b[B2B_LINE_INFO_NORMAL_FORCE]) / F, "F");
  e = upd(e, fabs(a[B2B_LINE_INFO_ENERGY] - b[B2B_LINE_INFO_ENERGY]) / F, "line energy");
  e = upd(e, fabs(a[B2B_LINE_INFO_DISSIPATION] - b[B2B_LINE_INFO_DISSIPATION]) / F,
          "line dissipation");
  if (b[B2B_LINE_INFO_MIN_GAP] == DBL_MAX)
    ck_assert_msg(a[B2B_LINE_INFO_MIN_GAP] == DBL_MAX, "%s: min gap %g, reference none", what,
                  a[B2B_LINE_INFO_MIN_GAP]);
  else
    e = upd(e, fabs(a[B2B_LINE_INFO_MIN_GAP] - b[B2B_LINE_INFO_MIN_GAP]), "min gap");
  e = upd(e, fabs(a[B2B_LINE_INFO_LENGTH] - b[B2B_LINE_INFO_LENGTH]) / b[B2B_LINE_INFO_LENGTH],
          "length");
  e = upd(e, fabs(a[B2B_LINE_INFO_POINT_WEIGHT] - b[B2B_LINE_INFO_POINT_WEIGHT]), "lambda_P");
  e = upd(e, fabs(a[B2B_LINE_INFO_POINT_FORCE] - b[B2B_LINE_INFO_POINT_FORCE]) / F,
          "point force");
  return e;
}

/* ------------------------------------------------------------- bookkeeping */

typedef struct {
  double tangent, residual, info, self;
  int n;
} worst_t;
static worst_t worst[2][2][N_STATES]; /* [type LINE, ALL_ANGLE][law][state] */

static void report(void) {
  printf("| type | law | state | configs | tangent | residual | info/history | self |\n");
  printf("|---|---|---|---:|---:|---:|---:|---:|\n");
  for (int t = 0; t < 2; ++t)
    for (int law = 0; law < 2; ++law)
      for (int s = 0; s < N_STATES; ++s) {
        const worst_t *w = &worst[t][law][s];
        if (!w->n) continue;
        printf("| %s | %s | %s | %d | %.2e | %.2e | %.2e | %.2e |\n",
               t ? "all-angle" : "line", law ? "quadratic" : "linear", state_name[s], w->n,
               w->tangent, w->residual, w->info, w->self);
      }
}

typedef struct {
  double tangent, residual, info, self;
  int status;
} cmp_t;

/* Library against the reference on one configuration; asserts the
 * criteria. Returns the errors (status -1: not active). */
static cmp_t compare(const b2b_params *p, const tst_pair_spec *s, const double X[24], int n,
                     const double *hist_old, int type, int law, int state, const char *what) {
  static out_t l, o;
  cmp_t c = {0, 0, 0, 0, -1};
  lib_line(p, s, X, n, hist_old, &l);
  ad_line(p, s, X, n, hist_old, 0, &o);
  ck_assert_msg(l.status == o.status, "%s: status %d, the reference says %d", what, l.status,
                o.status);
  c.status = l.status;
  const int hs = tst_history_len(p);
  double eps_t = EPS_LT;
  cur_slot = -1;
  worst_val = 0.0;
  worst_field = "none";
  double e = line_info_error(l.li, o.li, what);
  double f_scale = 0.0;
  for (int i = 0; i < n; ++i) f_scale = fmax(f_scale, o.pinfo[32 * i + B2B_INFO_NORMAL_FORCE]);
  for (int i = 0; i < n; ++i) {
    cur_slot = i;
    char w2[260];
    snprintf(w2, sizeof w2, "%s, point %d", what, i);
    e = fmax(e, point_info_error(l.pinfo + 32 * i, o.pinfo + 32 * i, eps_t, f_scale, i, what));
    e = fmax(e, hist_error(l.hist + (i + 1) * hs, o.hist + (i + 1) * hs, hs,
                           f_scale, i + 1, w2));
  }
  cur_slot = -2;
  e = fmax(e, hist_error(l.hist, o.hist, hs, o.li[B2B_LINE_INFO_POINT_FORCE] /
                                                 fmax(o.li[B2B_LINE_INFO_POINT_WEIGHT], 1e-300),
                         0, what));
  c.info = e;
  c.residual = rel_err(l.R, o.R, 24);
  c.tangent = rel_err(l.K, o.K, 576);
  ck_assert_msg(o.mismatch == 0.0, "%s: the reference's dual and double values differ by %g",
                what, o.mismatch);
  if (state == ST_NONE && type == B2B_CONTACT_TYPE_LINE) {
    c.self = rel_err(o.grad, o.R, 24);
    ck_assert_msg(c.self <= TOL_SELF,
                  "%s: the reference's residual differs from the AD gradient of its "
                  "potential by %.2e",
                  what, c.self);
  }
  ck_assert_msg(c.info <= TOL_I && c.residual <= TOL_R && c.tangent <= TOL_K,
                "%s: library against the AD reference: tangent %.2e, residual %.2e, "
                "info/history %.2e (%s of point %d; -1 line_info, -2 the point element)",
                what, c.tangent, c.residual, c.info, worst_field, worst_slot);
  if (l.status == B2B_CONTACT_ACTIVE) {
    worst_t *w = &worst[type == B2B_CONTACT_TYPE_ALL_ANGLE][law][state];
    w->tangent = fmax(w->tangent, c.tangent);
    w->residual = fmax(w->residual, c.residual);
    w->info = fmax(w->info, c.info);
    w->self = fmax(w->self, c.self);
    ++w->n;
  }
  return c;
}

/* A configuration of kinds ka, kb: nearly parallel (LINE) or crossing at
 * 6 .. 14 degrees (ALL_ANGLE), penetrating by 5e-3 .. 2e-2; B ends at a
 * beam end (REFLECT) on one side if end_b. */
static void configuration(tst_rng *rng, int type, int ka, int kb, int end_b, tst_pair_spec *s,
                          double X[24]) {
  for (int b = 0; b < 2; ++b) {
    s->kind[b] = b ? kb : ka;
    s->start_rule[b] = s->end_rule[b] = B2B_END_NEIGHBOUR;
    s->radius[b] = RADIUS;
  }
  if (end_b == 1) s->end_rule[1] = B2B_END_REFLECT;
  if (end_b == 2) s->start_rule[1] = B2B_END_REFLECT;
  const double angle =
      type == B2B_CONTACT_TYPE_LINE ? tst_uniform(rng, 0, 4) : tst_uniform(rng, 6, 14);
  tst_crossing(rng, s, 0.06, angle, tst_uniform(rng, -0.3, 0.3), tst_uniform(rng, -0.3, 0.3),
               2 * RADIUS - tst_uniform(rng, 0.005, 0.02), X);
}

/* Commit a first evaluation (the library's histories) and slide B along
 * A's chord by `slide`; 0 unless the first evaluation is active. */
static int prepare_friction(const b2b_params *p, const tst_pair_spec *s, double X[24], int n,
                            double slide, double hist[MAXH]) {
  static out_t o;
  lib_line(p, s, X, n, NULL, &o);
  if (o.status != B2B_CONTACT_ACTIVE) return 0;
  memcpy(hist, o.hist, sizeof o.hist);
  const double ax[3] = {X[6] - X[3], X[7] - X[4], X[8] - X[5]};
  const double l = sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
  for (int k = 12; k < 24; ++k)
    if (!isnan(X[k])) X[k] += slide * ax[k % 3] / l;
  return 1;
}

/* ------------------------------------------------------------- tests */

/* Every pair of kinds, both laws, LINE and ALL_ANGLE, frictionless, stick
 * and slip. */
START_TEST(library_against_reference) {
  tst_rng rng;
  tst_rng_seed(&rng, 31001);
  memset(worst, 0, sizeof worst);
  int count[2][N_STATES] = {{0}};
  int pairs_seen[B2B_CURVE_KIND_COUNT][B2B_CURVE_KIND_COUNT] = {{0}};
  static const int types[2] = {B2B_CONTACT_TYPE_LINE, B2B_CONTACT_TYPE_ALL_ANGLE};
  for (int t = 0; t < 2; ++t)
    for (int law = 0; law < B2B_LAW_COUNT; ++law)
      for (int fr = 0; fr < 2; ++fr) {
        b2b_params *p = line_params(law, types[t], fr, B2B_TANGENT_EXACT);
        for (int c = 0; c < B2B_CURVE_KIND_COUNT * B2B_CURVE_KIND_COUNT; ++c)
          for (int rep = 0; rep < (fr ? 2 : 1); ++rep) {
            const int ka = TST_KIND_A(c), kb = TST_KIND_B(c);
            tst_pair_spec s;
            double X[24], hist[MAXH];
            configuration(&rng, types[t], ka, kb, (c + rep + law) % 3, &s, X);
            const int n = 2 + (c + 3 * rep + law) % 8;
            int state = ST_NONE;
            if (fr) {
              state = rep ? ST_SLIP : ST_STICK;
              if (!prepare_friction(p, &s, X, n, rep ? 2e-2 : 1e-5, hist)) continue;
            }
            char what[200];
            snprintf(what, sizeof what, "%s, law %d, %s x %s, n %d, aimed at %s",
                     t ? "all-angle" : "line", law, tst_kind_name(ka), tst_kind_name(kb), n,
                     state_name[state]);
            if (fr) { /* the state reached, from the library's counts */
              static out_t pre;
              lib_line(p, &s, X, n, hist, &pre);
              state = pre.li[B2B_LINE_INFO_SLIP_POINTS] > 0 ? ST_SLIP : ST_STICK;
            }
            const cmp_t r = compare(p, &s, X, n, fr ? hist : NULL, types[t], law, state, what);
            if (r.status == B2B_CONTACT_ACTIVE) {
              ++count[t][state];
              ++pairs_seen[ka][kb];
            }
          }
        b2b_params_destroy(&p);
      }
  printf("line element against the AD reference:\n");
  report();
  for (int t = 0; t < 2; ++t)
    for (int st = 0; st < N_STATES; ++st)
      ck_assert_msg(count[t][st] >= 8, "type %d, %s: only %d active configurations", t,
                    state_name[st], count[t][st]);
  for (int a = 0; a < B2B_CURVE_KIND_COUNT; ++a)
    for (int b = 0; b < B2B_CURVE_KIND_COUNT; ++b)
      ck_assert_msg(pairs_seen[a][b] >= 4, "%s x %s: only %d active configurations",
                    tst_kind_name(a), tst_kind_name(b), pairs_seen[a][b]);
}
END_TEST

/* The "tangent" options against the reference's (FD at the differences'
 * accuracy). */
START_TEST(tangent_options) {
  tst_rng rng;
  tst_rng_seed(&rng, 31002);
  double worst_opt[4] = {0, 0, 0, 0};
  int checked = 0;
  for (int opt = B2B_TANGENT_SYMMETRIC; opt <= B2B_TANGENT_FD; ++opt)
    for (int t = 0; t < 2; ++t) {
      const int type = t ? B2B_CONTACT_TYPE_ALL_ANGLE : B2B_CONTACT_TYPE_LINE;
      b2b_params *p = line_params(B2B_LAW_LINEAR, type, 1, opt);
      for (int c = 0; c < 6; ++c) {
        tst_pair_spec s;
        double X[24], hist[MAXH];
        configuration(&rng, type, TST_KIND_A(c + 5), TST_KIND_B(c + 5), 0, &s, X);
        if (!prepare_friction(p, &s, X, 5, (c % 2) ? 2e-2 : 1e-5, hist)) continue;
        static out_t l, o;
        lib_line(p, &s, X, 5, hist, &l);
        ad_line(p, &s, X, 5, hist, 0, &o);
        ck_assert_int_eq(l.status, o.status);
        if (l.status != B2B_CONTACT_ACTIVE) continue;
        const double e = rel_err(l.K, o.K, 576);
        ck_assert_msg(l.li[B2B_LINE_INFO_SYMMETRIC] == o.li[B2B_LINE_INFO_SYMMETRIC],
                        "option %d: symmetric flag %g / %g", opt,
                        l.li[B2B_LINE_INFO_SYMMETRIC], o.li[B2B_LINE_INFO_SYMMETRIC]);
        if (opt != B2B_TANGENT_FD)
          ck_assert_msg(tst_asymmetry(l.K) == 0.0, "option %d: tangent not symmetric (%.2e)",
                        opt, tst_asymmetry(l.K));
        const double tol = opt == B2B_TANGENT_FD ? 1e-5 : TOL_K;
        worst_opt[opt] = fmax(worst_opt[opt], e);
        ck_assert_msg(e <= tol, "option %d, type %d: tangent vs reference %.2e", opt, type, e);
        ++checked;
      }
      b2b_params_destroy(&p);
    }
  ck_assert_int_ge(checked, 12);
  printf("tangent options vs reference: SYMMETRIC %.2e, MAIN %.2e, FD %.2e (%d configurations)\n",
         worst_opt[1], worst_opt[2], worst_opt[3], checked);
}
END_TEST

/* The criteria catch what they should: a tangent perturbed in one entry by
 * twice the tolerance, and a reference with frozen projections. */
START_TEST(checks_of_the_checks) {
  tst_rng rng;
  tst_rng_seed(&rng, 31003);
  b2b_params *p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, 0, B2B_TANGENT_EXACT);
  int frozen = 0;
  double least = INFINITY;
  for (int c = 0; c < B2B_CURVE_KIND_COUNT * B2B_CURVE_KIND_COUNT; ++c) {
    tst_pair_spec s;
    double X[24];
    configuration(&rng, B2B_CONTACT_TYPE_ALL_ANGLE, TST_KIND_A(c), TST_KIND_B(c), 0, &s, X);
    static out_t l, o, f;
    lib_line(p, &s, X, 6, NULL, &l);
    if (l.status != B2B_CONTACT_ACTIVE) continue;
    ad_line(p, &s, X, 6, NULL, 0, &o);
    ad_line(p, &s, X, 6, NULL, B2B_AD_FREEZE_CLOSEST_POINTS, &f);
    const double e = rel_err(l.K, o.K, 576);
    ck_assert(e <= TOL_K);
    double K2[576];
    memcpy(K2, l.K, sizeof K2);
    double m = 0.0;
    for (int k = 0; k < 576; ++k) m = fmax(m, fabs(o.K[k]));
    K2[c % 576] = o.K[c % 576] + 2 * TOL_K * m;
    ck_assert_msg(rel_err(K2, o.K, 576) > TOL_K, "a perturbed tangent passes");
    const double ef = rel_err(l.K, f.K, 576);
    least = fmin(least, ef);
    ck_assert_msg(ef > 1e3 * TOL_K, "%s x %s: frozen projections pass (%.2e)",
                  tst_kind_name(s.kind[0]), tst_kind_name(s.kind[1]), ef);
    ++frozen;
  }
  ck_assert_int_ge(frozen, 8);
  printf("frozen projections: the library differs from that reference by %.2e at least\n",
         least);
  b2b_params_destroy(&p);
}
END_TEST

/* Regression (a library bug this campaign found, fixed): with contact_type ALL_ANGLE and the
 * tangent option MAIN, line_info[B2B_LINE_INFO_SYMMETRIC] is 0 inside the
 * blending range although the MAIN tangent (the parts' weighted main terms
 * -f' G G^T, no weight derivatives) is exactly symmetric, as the returned
 * matrix is; b2b_pair_eval's MAIN reports 1. src/pair/line_contact.cpp
 * sets symmetric = false wherever the blend weight's slope is not zero
 * (lines 99 and 139) without asking whether the weight derivative terms
 * are in the tangent (main_only skips them). A host choosing its solver by
 * the flag picks a non-symmetric one needlessly. */
START_TEST(regression_main_flag) {
  b2b_params *p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, 0, B2B_TANGENT_MAIN);
  tst_rng rng;
  tst_rng_seed(&rng, 31004);
  int checked = 0;
  for (int c = 0; c < 8 && checked < 3; ++c) {
    tst_pair_spec s;
    double X[24];
    configuration(&rng, B2B_CONTACT_TYPE_ALL_ANGLE, B2B_CURVE_HERMITE_NODAL,
                  B2B_CURVE_HERMITE_NODAL, 0, &s, X);
    static out_t l;
    lib_line(p, &s, X, 6, NULL, &l);
    if (l.status != B2B_CONTACT_ACTIVE) continue;
    const double lam = l.li[B2B_LINE_INFO_POINT_WEIGHT];
    if (!(lam > 0.0 && lam < 1.0)) continue;
    ck_assert_msg(tst_asymmetry(l.K) == 0.0, "MAIN tangent not symmetric");
    ck_assert_msg(l.li[B2B_LINE_INFO_SYMMETRIC] == 1.0,
                  "ALL_ANGLE with MAIN, lambda_P %.3f: the tangent is symmetric "
                  "but line_info[SYMMETRIC] = %g",
                  lam, l.li[B2B_LINE_INFO_SYMMETRIC]);
    ++checked;
  }
  ck_assert_int_ge(checked, 3);
  b2b_params_destroy(&p);
}
END_TEST

/* Regression (a library bug this campaign found, fixed): the frictionless line element (LINE,
 * tangent EXACT, outside any blend) reports line_info[SYMMETRIC] = 1 for a
 * tangent that is symmetric only to rounding: src/pair/line_contact.cpp
 * (line_sum) adds the length element's terms as s r_i gJ^T (with the
 * point's residual r_i) and s gJ rN^T (with rN = -f P^T n recomputed), two
 * loops that round differently, so K[r][c] and K[c][r] differ in the last
 * bits. b2b_pair_eval's flag means symmetric bit for bit (fuzz_pair_eval
 * asserts it, and check_fuzz_regressions holds the MAIN case that broke
 * it); a host that reads one triangle because of the flag gets a matrix
 * that differs from the returned one. Found by fuzz_pair_line. */
static int bit_symmetric(const double *K) {
  for (int c = 0; c < 24; ++c)
    for (int r = c + 1; r < 24; ++r)
      if (memcmp(&K[r + 24 * c], &K[c + 24 * r], sizeof(double)) != 0) return 0;
  return 1;
}

START_TEST(regression_symmetric_to_rounding) {
  b2b_params *p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, 0, B2B_TANGENT_EXACT);
  tst_rng rng;
  tst_rng_seed(&rng, 31005);
  int flagged = 0, exact = 0;
  double worst = 0.0;
  for (int c = 0; c < B2B_CURVE_KIND_COUNT * B2B_CURVE_KIND_COUNT; ++c) {
    tst_pair_spec s;
    double X[24];
    configuration(&rng, B2B_CONTACT_TYPE_LINE, TST_KIND_A(c), TST_KIND_B(c), 0, &s, X);
    static out_t l;
    lib_line(p, &s, X, 6, NULL, &l);
    if (l.status != B2B_CONTACT_ACTIVE || l.li[B2B_LINE_INFO_SYMMETRIC] != 1.0) continue;
    ++flagged;
    exact += bit_symmetric(l.K);
    worst = fmax(worst, tst_asymmetry(l.K));
  }
  printf("LINE, frictionless, flagged symmetric: %d of %d tangents symmetric bit for bit "
         "(largest asymmetry %.2e relative)\n", exact, flagged, worst);
  ck_assert_int_ge(flagged, 8);
  ck_assert_msg(exact == flagged,
                "line_info[SYMMETRIC] = 1 but only %d of %d tangents are "
                "symmetric bit for bit (asymmetry up to %.2e)",
                exact, flagged, worst);
  b2b_params_destroy(&p);
}
END_TEST

int main(void) {
  Suite *s = suite_create("pair_line_ad");
  TCase *tc = tcase_create("line_ad");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, library_against_reference);
  tcase_add_test(tc, tangent_options);
  tcase_add_test(tc, checks_of_the_checks);
  suite_add_tcase(s, tc);
  TCase *fixed = tcase_create("regressions");
  tcase_add_test(fixed, regression_main_flag);
  tcase_add_test(fixed, regression_symmetric_to_rounding);
  suite_add_tcase(s, fixed);
  return tst_run_suite(s);
}
