/* The contact element against its forward-mode AD reference (tests/ad/,
 * b2b_ad.h): an independent implementation of b2b_pair_eval's residual,
 * templated over the scalar and differentiated with dual numbers.
 *
 * On seeded random active crossings of every pair of curve kinds (the kinds
 * are counted by asking the library, not hard-coded), both normal laws,
 * without friction and with friction in a fresh contact, in stick and in
 * slip (committed histories written by the library), interior segments and
 * both end rules (REFLECT, TANGENT), crossing angles 90 .. 1 degree, points
 * near joints and beam ends, a sign-tracked normal, each configuration is
 * evaluated by the library and by the reference, and:
 *   - status, info (but the iteration count) and new history agree;
 *   - residual: max|R_lib - R_ad| <= TOL_R max|R_ad|;
 *   - tangent: max_ij |K_lib - K_ad| <= TOL_K max_ij |K_ad| (the largest
 *     absolute entry of the difference over that of the AD tangent: the
 *     relative error in the max norm of the 576 entries), TOL_K = 1e-12;
 *   - the reference agrees with itself: its residual (from the curves'
 *     first derivatives) equals the AD gradient of its contact potential,
 *     and its dual instantiation's values equal its double instantiation's
 *     bit for bit.
 * Also the "tangent" options SYMMETRIC and MAIN against the reference's
 * (FD against the AD tangent at the differences' accuracy), and intersecting
 * axes with a previous normal, where the library keeps -f' G G^T on purpose
 * (doc/contact-element.md 12): there K_lib - K_ad is exactly that term.
 * Checks of the checks: a tangent or residual perturbed by twice the
 * tolerance in one entry fails the criterion, and a reference with the
 * closest points frozen in the derivative is rejected by a wide margin on
 * every kind.
 * Each test prints its worst errors per kind, law and friction state.
 *
 * The tangent's criterion scales with the conditioning below 2 degrees:
 * TOL_K (sin 2 deg / sin angle)^2, since the rounding of the library's
 * closed-form tangent grows like eps / sin^2(angle) (the closest-point
 * Hessian's condition number): 1.3e-12 at 1 degree with exact closest
 * points, where the AD reference in double keeps about 1e-13. Residual, info
 * and history keep their criteria at every angle.
 *
 * Beyond a criterion the long-double instantiation of the reference
 * (B2B_AD_LONG_DOUBLE) says which side is off, and the library is evaluated
 * once more with its search started ("warm_start") at accurate closest
 * points; both go into the failure message. This suite found the library's
 * closest points converged only to a tolerance on the tangential residual,
 * which left xi, eta off by up to 3e-11 at 1 degree (the error grows like
 * 1/sin^2 of the angle) and its residual, info and tangent with them; the
 * search now ends with one more Newton step (src/pair/closest_point.cpp),
 * and the test closest_point_accuracy_regressions holds the two
 * configurations that showed it. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "b2b_ad.h"
#include "pair_support.h"

#define TOL_K 1e-12 /* tangent, relative, max norm */
#define TOL_R 1e-12 /* residual, relative, max norm */
#define TOL_I 1e-12 /* info and history entries, relative to their scales */
#define TOL_SELF 1e-12
#define MAX_KINDS 16
#define HLEN 12
#define EPS_N 1e3
#define MU 0.3
#define EPS_T 8e2

enum { ST_NONE = 0, ST_FRESH = 1, ST_STICK = 2, ST_SLIP = 3, N_STATES = 4 };
static const char *const state_name[N_STATES] = {"frictionless", "fresh", "stick", "slip"};
static const double kPi = 3.14159265358979323846;

/* ------------------------------------------------------------ the kinds */

/* The curve kinds the library knows: kinds are numbered from 0 and appended
 * (b2b_curve.h), so count them until the library says B2B_ERR_UNKNOWN_KIND.
 * The reference must know every one of them. */
static int n_kinds;
static void count_kinds(void) {
  const double patch[12] = {-1, 0, 0, 0, 0.1, 0, 1, 0, 0.1, 2, 0.3, 0};
  n_kinds = 0;
  while (n_kinds < MAX_KINDS &&
         b2b_segment_eval(n_kinds, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch, NULL, 0.0, NULL,
                          NULL, NULL, NULL, 0) != B2B_ERR_UNKNOWN_KIND)
    ++n_kinds;
  ck_assert_int_ge(n_kinds, B2B_CURVE_HERMITE_NODAL_WEIGHTED + 1);
  ck_assert_msg(b2b_ad_curve_kind_count() == n_kinds,
                "the library has %d curve kinds, the AD reference implements %d", n_kinds,
                b2b_ad_curve_kind_count());
}

/* ------------------------------------------------------------ bookkeeping */

typedef struct {
  double tangent, residual, info, self;
  int n;
} worst_t;
static worst_t worst[MAX_KINDS][2][N_STATES];
static worst_t overall;
/* Configurations below 2 degrees, judged at the scaled tangent criterion,
 * and their largest tangent error as a fraction of it. */
static int n_angle;
static double worst_angle;

/* The tangent's criterion at this crossing angle (see the header comment). */
static double tangent_tolerance(double angle_deg) {
  const double s = sin(angle_deg * kPi / 180.0);
  return TOL_K * fmax(1.0, pow(sin(2.0 * kPi / 180.0) / s, 2));
}

static void reset(void) {
  n_angle = 0;
  worst_angle = 0.0;
  memset(worst, 0, sizeof worst);
  memset(&overall, 0, sizeof overall);
}

static void note(worst_t *w, double ek, double er, double ei, double es) {
  w->tangent = fmax(w->tangent, ek);
  w->residual = fmax(w->residual, er);
  w->info = fmax(w->info, ei);
  w->self = fmax(w->self, es);
  ++w->n;
}

/* The worst errors per kind (a configuration counts for the kinds of both
 * beams), law and friction state. */
static void report(const char *name) {
  printf("%s: %d active configurations; worst: tangent %.2e, residual %.2e, info/history "
         "%.2e, reference self-check %.2e\n",
         name, overall.n, overall.tangent, overall.residual, overall.info, overall.self);
  if (n_angle)
    printf("%d configurations below 2 degrees, judged at the scaled tangent criterion: "
           "largest error %.2f of it\n", n_angle, worst_angle);
  printf("| kind | law | state | configs | tangent | residual | info/history |\n");
  printf("|---|---|---|---:|---:|---:|---:|\n");
  for (int k = 0; k < n_kinds; ++k)
    for (int law = 0; law < 2; ++law)
      for (int s = 0; s < N_STATES; ++s) {
        const worst_t *w = &worst[k][law][s];
        if (w->n == 0) continue;
        printf("| %s | %s | %s | %d | %.2e | %.2e | %.2e |\n", tst_kind_name(k),
               law ? "quadratic" : "linear", state_name[s], w->n, w->tangent, w->residual,
               w->info);
      }
}

/* max|a - b| / max|b| (max|a - b| if b is zero): the relative error in the
 * max norm. */
static double rel_err(const double *a, const double *b, int n) {
  double d = 0.0, m = 0.0;
  for (int i = 0; i < n; ++i) {
    d = fmax(d, fabs(a[i] - b[i]));
    m = fmax(m, fabs(b[i]));
  }
  return m > 0.0 ? d / m : d;
}

static double max_abs(const double *a, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fabs(a[i]));
  return m;
}

static double norm3(const double *a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* ------------------------------------------------------------ evaluation */

static const double kDefaultTangents[12] = {1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0};

typedef struct {
  int status;
  double info[32], hist[16], R[24], K[576], grad[24], mismatch;
} ad_out;

/* The reference (fails the test unless it returns B2B_OK). */
static void ad_eval_at(const b2b_params *p, const tst_pair_spec *spec, const double X[24],
                       const double tang[12], const double *hist_old, int flags,
                       const double *at, ad_out *o) {
  const int segments[6] = {spec->kind[0], spec->start_rule[0], spec->end_rule[0],
                           spec->kind[1], spec->start_rule[1], spec->end_rule[1]};
  double fresh[16] = {0};
  char msg[B2B_ERRMSG_LEN] = "";
  const int st = b2b_ad_pair_eval_ex(p, segments, X, tang ? tang : kDefaultTangents,
                                     spec->radius, hist_old ? hist_old : fresh, o->hist,
                                     tst_history_len(p), flags, &o->status, o->info, o->R, o->K,
                                     24, o->grad, &o->mismatch, at, msg, sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_ad_pair_eval returned %d: %s", st, msg);
}

static void ad_eval(const b2b_params *p, const tst_pair_spec *spec, const double X[24],
                    const double tang[12], const double *hist_old, int flags, ad_out *o) {
  ad_eval_at(p, spec, X, tang, hist_old, flags, NULL, o);
}

/* Relative errors of one configuration. */
typedef struct {
  double tangent, residual, info, self;
  int status, state;
} cmp_t;

/* Info entries and history of the library (a) against the reference (b),
 * each relative to its natural scale: lengths to the segments' (order one
 * here), forces to f_N, energies to f_N times a length, slips to the stick
 * length mu f_N / eps_T. Flags and states must be equal. */
static const char *worst_field;
static double upd(double e, double v, const char *name) {
  if (v > e) worst_field = name;
  return v > e ? v : e;
}
static double info_error(const b2b_params *p, const double *a, const double *b,
                         const double *ha, const double *hb, int nh, const char *what) {
  double mu = 0.0, eps_t = 0.0;
  b2b_params_get_real(p, "friction", &mu, NULL, 0);
  b2b_params_get_real(p, "tangential_penalty", &eps_t, NULL, 0);
  const double f = fmax(b[B2B_INFO_NORMAL_FORCE], 1e-300);
  const double slip_unit = mu > 0 ? mu * f / eps_t : 1.0;
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
                "%s: symmetric flag %g / %g, friction state %g / %g (library / reference)", what,
                a[B2B_INFO_SYMMETRIC], b[B2B_INFO_SYMMETRIC], a[B2B_INFO_FRICTION_STATE],
                b[B2B_INFO_FRICTION_STATE]);
  for (int i = 25; i < 32; ++i) ck_assert(a[i] == 0.0 && b[i] == 0.0);
  /* history: tag, flags and state exactly; normal, xi, eta; force components */
  for (int i = 0; i < nh; ++i) {
    double scale = 0.0; /* 0: must be equal */
    if ((i >= 2 && i <= 6)) scale = 1.0;
    if (i == 9 || i == 10) scale = f;
    if (scale == 0.0)
      ck_assert_msg(ha[i] == hb[i], "%s: history[%d] %g / %g (library / reference)", what, i,
                    ha[i], hb[i]);
    else
      e = upd(e, fabs(ha[i] - hb[i]) / scale, "history");
  }
  return e;
}

/* The library's outputs of one configuration. */
typedef struct {
  int status;
  double info[32], hist[16], R[24], K[576];
} lib_out;

static void lib_eval(const b2b_params *p, const tst_pair_spec *spec, const double X[24],
                     const double tang[12], const double *hist_old, lib_out *l) {
  l->status = tst_pair_ext(p, spec, X, tang, hist_old, l->hist, l->info, l->R, l->K);
}

/* Errors of the library against a reference: tangent, residual, info and
 * history (relative, as the criteria above). */
typedef struct {
  double tangent, residual, info;
  const char *field; /* the worst info or history entry */
} errs_t;

static errs_t errors(const b2b_params *p, const lib_out *l, const ad_out *o, const char *what) {
  errs_t e;
  e.tangent = rel_err(l->K, o->K, 576);
  e.residual = rel_err(l->R, o->R, 24);
  e.info = info_error(p, l->info, o->info, l->hist, o->hist, tst_history_len(p), what);
  e.field = worst_field;
  return e;
}

static int within(errs_t e, double tol_k, double tol_r, double tol_i) {
  return e.tangent <= tol_k && e.residual <= tol_r && e.info <= tol_i;
}

/* A copy of p with "warm_start" on. */
static b2b_params *warm_copy(const b2b_params *p) {
  static const char *const reals[] = {"penalty", "regularization_gap", "parallel_angle",
                                      "friction", "tangential_penalty"};
  static const char *const ints[] = {"law", "max_iterations", "tangent"};
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *w = NULL;
  ck_assert_int_eq(b2b_params_create(&w, msg, sizeof msg), B2B_OK);
  for (int i = 0; i < 5; ++i) {
    double v = 0.0;
    ck_assert_int_eq(b2b_params_get_real(p, reals[i], &v, msg, sizeof msg), B2B_OK);
    if (v != 0.0 || i == 2)
      ck_assert_int_eq(b2b_params_set_real(w, reals[i], v, msg, sizeof msg), B2B_OK);
  }
  for (int i = 0; i < 3; ++i) {
    int v = 0;
    ck_assert_int_eq(b2b_params_get_int(p, ints[i], &v, msg, sizeof msg), B2B_OK);
    ck_assert_int_eq(b2b_params_set_int(w, ints[i], v, msg, sizeof msg), B2B_OK);
  }
  ck_assert_int_eq(b2b_params_set_int(w, "warm_start", 1, msg, sizeof msg), B2B_OK);
  ck_assert_msg(b2b_params_finalize(w, msg, sizeof msg) == B2B_OK, "finalize: %s", msg);
  return w;
}

/* The library and the long-double reference with the search started at the
 * long-double reference's closest points (ol; "warm_start"): the errors of
 * the library's element where its closest points are accurate. The history
 * is the given one (a fresh one gets the reference's normal) with xi, eta
 * replaced, for both (with friction they are the anchors, too). */
static errs_t errors_at_accurate_points(const b2b_params *p, const tst_pair_spec *spec,
                                        const double X[24], const double tang[12],
                                        const double *hist_old, const ad_out *ol,
                                        const char *what) {
  static lib_out lw;
  static ad_out ow;
  double h[16] = {0};
  const int nh = tst_history_len(p);
  if (hist_old) memcpy(h, hist_old, nh * sizeof(double));
  if (h[0] != 1.0 || h[1] != 1.0) memcpy(h, ol->hist, 8 * sizeof(double));
  h[5] = ol->info[B2B_INFO_XI];
  h[6] = ol->info[B2B_INFO_ETA];
  b2b_params *w = warm_copy(p);
  lib_eval(w, spec, X, tang, h, &lw);
  ad_eval(w, spec, X, tang, h, B2B_AD_LONG_DOUBLE, &ow);
  ck_assert_msg(lw.status == ow.status && lw.status == B2B_CONTACT_ACTIVE,
                "%s: status %d (library), %d (reference) at the accurate closest points", what,
                lw.status, ow.status);
  const errs_t e = errors(w, &lw, &ow, what);
  b2b_params_destroy(&w);
  return e;
}

/* A failing configuration, exactly (hexadecimal floats), on stderr: what a
 * reproducer needs. */
static void dump_config(const tst_pair_spec *spec, const double X[24], const double tang[12],
                        const double *hist_old, int nh, const char *what) {
  fprintf(stderr, "reproducer of \"%s\": segments {%d, %d, %d, %d, %d, %d}, radii {%a, %a}\nX {",
          what, spec->kind[0], spec->start_rule[0], spec->end_rule[0], spec->kind[1],
          spec->start_rule[1], spec->end_rule[1], spec->radius[0], spec->radius[1]);
  for (int a = 0; a < 24; ++a) fprintf(stderr, "%s%a", a ? ", " : "", X[a]);
  fprintf(stderr, "}\nend_tangents {");
  for (int a = 0; a < 12; ++a)
    fprintf(stderr, "%s%a", a ? ", " : "", tang ? tang[a] : kDefaultTangents[a]);
  fprintf(stderr, "}\nhist_old {");
  for (int a = 0; a < nh; ++a) fprintf(stderr, "%s%a", a ? ", " : "", hist_old ? hist_old[a] : 0.0);
  fprintf(stderr, "}\n");
}

/* Evaluates X with the library and the reference and compares everything;
 * records the errors under both kinds, the law and the friction state.
 * Beyond a criterion, the long-double reference and the library started at
 * accurate closest points say which side is off and why (in the message).
 * Returns the comparison (status -1 if the pair is not active). */
static cmp_t compare(const b2b_params *p, const tst_pair_spec *spec, const double X[24],
                     const double tang[12], const double *hist_old, const char *what) {
  static lib_out l;
  static ad_out o, ol;
  cmp_t c = {0, 0, 0, 0, -1, ST_NONE};
  const int nh = tst_history_len(p);
  lib_eval(p, spec, X, tang, hist_old, &l);
  ad_eval(p, spec, X, tang, hist_old, 0, &o);
  ck_assert_msg(o.status == l.status, "%s: contact status %d, the reference says %d", what,
                l.status, o.status);
  c.status = l.status;
  if (l.status != B2B_CONTACT_ACTIVE) return c;
  double mu = 0.0;
  b2b_params_get_real(p, "friction", &mu, NULL, 0);
  const int anchored = hist_old && hist_old[0] == 1.0 && nh > 8 && hist_old[8] == 1.0;
  c.state = mu == 0.0 ? ST_NONE
                      : (!anchored ? ST_FRESH
                                   : (l.info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_SLIP
                                          ? ST_SLIP
                                          : ST_STICK));
  const errs_t e = errors(p, &l, &o, what);
  c.tangent = e.tangent;
  c.residual = e.residual;
  c.info = e.info;
  /* the reference against itself */
  c.self = c.state == ST_NONE ? rel_err(o.grad, o.R, 24) : 0.0;
  ck_assert_msg(o.mismatch == 0.0, "%s: the reference's dual and double values differ by %g",
                what, o.mismatch);
  ck_assert_msg(c.self <= TOL_SELF, "%s: the reference's residual differs from the AD gradient "
                "of its potential by %.2e", what, c.self);
  /* rows and columns of unread slots are zero in both */
  for (int a = 0; a < 24; ++a)
    if (isnan(X[a])) {
      ck_assert(l.R[a] == 0.0 && o.R[a] == 0.0);
      for (int r = 0; r < 24; ++r)
        ck_assert(l.K[r + 24 * a] == 0.0 && l.K[a + 24 * r] == 0.0 && o.K[r + 24 * a] == 0.0 &&
                  o.K[a + 24 * r] == 0.0);
    }
  int law = 0;
  b2b_params_get_int(p, "law", &law, NULL, 0);
  note(&worst[spec->kind[0]][law][c.state], c.tangent, c.residual, c.info, c.self);
  if (spec->kind[1] != spec->kind[0])
    note(&worst[spec->kind[1]][law][c.state], c.tangent, c.residual, c.info, c.self);
  note(&overall, c.tangent, c.residual, c.info, c.self);
  const double tol_k = tangent_tolerance(l.info[B2B_INFO_ANGLE]);
  if (tol_k > TOL_K) {
    ++n_angle;
    worst_angle = fmax(worst_angle, e.tangent / tol_k);
  }
  if (within(e, tol_k, TOL_R, TOL_I)) return c;

  ad_eval(p, spec, X, tang, hist_old, B2B_AD_LONG_DOUBLE, &ol);
  const errs_t eld = errors(p, &l, &ol, what);
  const errs_t ew = errors_at_accurate_points(p, spec, X, tang, hist_old, &ol, what);
  const double dxi = l.info[B2B_INFO_XI] - ol.info[B2B_INFO_XI];
  const double deta = l.info[B2B_INFO_ETA] - ol.info[B2B_INFO_ETA];
  dump_config(spec, X, tang, hist_old, nh, what);
  ck_assert_msg(0,
                "%s (%s): library against the AD reference: tangent %.2e, residual %.2e, "
                "info/history %.2e (%s); against the long-double reference %.2e, %.2e, %.2e, "
                "its xi, eta off by %.2e, %.2e; started at the accurate closest points %.2e, "
                "%.2e, %.2e",
                what, state_name[c.state], e.tangent, e.residual, e.info, e.field,
                eld.tangent, eld.residual, eld.info, dxi, deta, ew.tangent, ew.residual,
                ew.info);
  return c;
}

/* ------------------------------------------------------------ configurations */

/* Rule variants of a pair: interior; each beam ending at one side (REFLECT
 * or a host TANGENT). A midpoint segment cannot end on both sides, so each
 * beam gets at most one end. */
#define N_VARIANTS 5
static void apply_variant(int v, tst_pair_spec *spec) {
  for (int b = 0; b < 2; ++b) spec->start_rule[b] = spec->end_rule[b] = B2B_END_NEIGHBOUR;
  const int rule = (v == 1 || v == 2) ? B2B_END_REFLECT : B2B_END_TANGENT;
  if (v == 1 || v == 3) {
    spec->start_rule[0] = rule;
    spec->end_rule[1] = rule;
  } else if (v == 2 || v == 4) {
    spec->end_rule[0] = rule;
    spec->start_rule[1] = rule;
  }
}

/* A crossing for spec (tst_crossing, which cannot take host tangents: it is
 * generated with REFLECT where spec has TANGENT, the same slots unread) and
 * host end tangents near the end elements' chords, slightly tilted. */
static void crossing(tst_rng *rng, const tst_pair_spec *spec, double max_turn, double angle,
                     double xi_star, double eta_star, double dist, double X[24],
                     double tang[12]) {
  tst_pair_spec gen = *spec;
  for (int b = 0; b < 2; ++b) {
    if (gen.start_rule[b] == B2B_END_TANGENT) gen.start_rule[b] = B2B_END_REFLECT;
    if (gen.end_rule[b] == B2B_END_TANGENT) gen.end_rule[b] = B2B_END_REFLECT;
  }
  tst_crossing(rng, &gen, max_turn, angle, xi_star, eta_star, dist, X);
  for (int b = 0; b < 2; ++b) {
    const double *x2 = X + 12 * b + 3, *x3 = X + 12 * b + 6;
    if (isnan(x3[0])) x3 = x2, x2 = X + 12 * b; /* a midpoint segment ending at x2 */
    double ch[3] = {x3[0] - x2[0], x3[1] - x2[1], x3[2] - x2[2]};
    const double l = norm3(ch);
    for (int e = 0; e < 2; ++e)
      for (int i = 0; i < 3; ++i)
        tang[6 * b + 3 * e + i] = ch[i] / l + tst_uniform(rng, -0.15, 0.15);
  }
}

static void add_noise(tst_rng *rng, double *X, double amp) {
  for (int a = 0; a < 24; ++a)
    if (!isnan(X[a])) X[a] += tst_uniform(rng, -amp, amp);
}

/* A translation of A by d in the tangent plane of the contact: in a random
 * direction, or (along) along A's own axis at its closest point, which keeps
 * the crossing point where it is even at small angles (the material slides
 * through it). */
static void slide_a(tst_rng *rng, const tst_pair_spec *spec, const double tang[12],
                    const double info[32], int along, double d, double X[24]) {
  const double *n = info + B2B_INFO_NORMAL;
  double t[3];
  if (along) {
    double x[9];
    tst_eval(spec->kind[0], spec->start_rule[0], spec->end_rule[0], X,
             tang ? tang : kDefaultTangents, info[B2B_INFO_XI], x, NULL, NULL);
    const double sign = tst_uniform(rng, 0, 1) < 0.5 ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i) t[i] = sign * x[3 + i];
  } else {
    double r[3];
    do {
      for (int i = 0; i < 3; ++i) r[i] = tst_uniform(rng, -1, 1);
      const double rn = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
      for (int i = 0; i < 3; ++i) t[i] = r[i] - rn * n[i];
    } while (norm3(t) < 0.2);
  }
  const double l = norm3(t);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) X[3 * k + i] += d * t[i] / l;
}

/* From the crossing X0, the configuration X and committed history hist of a
 * friction state aimed at: fresh (hist zero), stick or slip (X0 committed,
 * A slid by 0.4 or 1.5 stick lengths mu f_N / eps_T and committed, a force
 * in the history; then slid on by 0.3 or 2.5 in another direction; along:
 * both slides along A's axis). The committed histories are the library's.
 * Returns 0 unless every step is active. */
static int prepare(tst_rng *rng, const b2b_params *p, const tst_pair_spec *spec,
                   const double tang[12], const double X0[24], int target, int along,
                   double X[24], double hist[HLEN]) {
  double info[32], R[24], h1[HLEN];
  memset(hist, 0, HLEN * sizeof(double));
  memcpy(X, X0, 24 * sizeof(double));
  if (tst_pair_ext(p, spec, X0, tang, NULL, h1, info, R, NULL) != B2B_CONTACT_ACTIVE) return 0;
  if (target == ST_FRESH) {
    add_noise(rng, X, 1e-4);
    return 1;
  }
  double unit = MU * info[B2B_INFO_NORMAL_FORCE] / EPS_T;
  slide_a(rng, spec, tang, info, along, (target == ST_STICK ? 0.4 : 1.5) * unit, X);
  if (tst_pair_ext(p, spec, X, tang, h1, hist, info, R, NULL) != B2B_CONTACT_ACTIVE) return 0;
  unit = MU * info[B2B_INFO_NORMAL_FORCE] / EPS_T;
  slide_a(rng, spec, tang, info, along, (target == ST_STICK ? 0.3 : 2.5) * unit, X);
  add_noise(rng, X, along ? 1e-6 : 1e-4);
  return 1;
}

static b2b_params *params_for(int law, int friction, int tangent_option) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", EPS_N, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "law", law, msg, sizeof msg), B2B_OK);
  if (law == B2B_LAW_QUADRATIC)
    ck_assert_int_eq(b2b_params_set_real(p, "regularization_gap", 0.05, msg, sizeof msg),
                     B2B_OK);
  if (friction) {
    ck_assert_int_eq(b2b_params_set_real(p, "friction", MU, msg, sizeof msg), B2B_OK);
    ck_assert_int_eq(b2b_params_set_real(p, "tangential_penalty", EPS_T, msg, sizeof msg),
                     B2B_OK);
  }
  ck_assert_int_eq(b2b_params_set_int(p, "tangent", tangent_option, msg, sizeof msg), B2B_OK);
  ck_assert_msg(b2b_params_finalize(p, msg, sizeof msg) == B2B_OK, "finalize: %s", msg);
  return p;
}

/* ------------------------------------------------------------ tests */

/* Every pair of kinds, both laws, every rule variant, without friction. */
START_TEST(frictionless_all_kinds) {
  count_kinds();
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 11001);
  int count[MAX_KINDS][N_VARIANTS] = {{0}};
  for (int law = 0; law < 2; ++law) {
    b2b_params *p = params_for(law, 0, B2B_TANGENT_EXACT);
    for (int ka = 0; ka < n_kinds; ++ka)
      for (int kb = 0; kb < n_kinds; ++kb)
        for (int v = 0; v < N_VARIANTS; ++v)
          for (int rep = 0; rep < 3; ++rep) {
            tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
            apply_variant(v, &spec);
            double X[24], tang[12];
            const double angle = tst_uniform(&rng, 20, 90);
            const double dist = 0.35 - tst_uniform(&rng, law ? -0.04 : 0.01, 0.1);
            crossing(&rng, &spec, 0.5, angle, tst_uniform(&rng, -0.8, 0.8),
                     tst_uniform(&rng, -0.8, 0.8), dist, X, tang);
            char what[160];
            snprintf(what, sizeof what, "law %d, %s x %s, variant %d, angle %.1f", law,
                     tst_kind_name(ka), tst_kind_name(kb), v, angle);
            if (compare(p, &spec, X, tang, NULL, what).status == B2B_CONTACT_ACTIVE) {
              ++count[ka][v];
              ++count[kb][v];
            }
          }
    b2b_params_destroy(&p);
  }
  report("frictionless, every kind pair, both laws, end rules");
  for (int k = 0; k < n_kinds; ++k)
    for (int v = 0; v < N_VARIANTS; ++v)
      ck_assert_msg(count[k][v] >= 4, "%s, variant %d: only %d active configurations",
                    tst_kind_name(k), v, count[k][v]);
}
END_TEST

/* Friction: fresh, stick and slip for every pair of kinds, both laws,
 * interior segments and the end-rule variants. */
START_TEST(friction_all_kinds) {
  count_kinds();
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 11002);
  int count[MAX_KINDS][N_STATES] = {{0}};
  for (int law = 0; law < 2; ++law) {
    b2b_params *p = params_for(law, 1, B2B_TANGENT_EXACT);
    for (int ka = 0; ka < n_kinds; ++ka)
      for (int kb = 0; kb < n_kinds; ++kb)
        for (int target = ST_FRESH; target <= ST_SLIP; ++target)
          for (int rep = 0; rep < 3; ++rep) {
            tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
            apply_variant(rep == 0 ? 0 : 1 + (int)tst_uniform(&rng, 0, 4), &spec);
            double X0[24], X[24], tang[12], hist[HLEN];
            const double angle = tst_uniform(&rng, 20, 90);
            const double dist = 0.35 - tst_uniform(&rng, law ? -0.02 : 0.02, 0.1);
            crossing(&rng, &spec, 0.5, angle, tst_uniform(&rng, -0.6, 0.6),
                     tst_uniform(&rng, -0.6, 0.6), dist, X0, tang);
            if (!prepare(&rng, p, &spec, tang, X0, target, 0, X, hist)) continue;
            char what[160];
            snprintf(what, sizeof what, "law %d, %s x %s, angle %.1f, aimed at %s", law,
                     tst_kind_name(ka), tst_kind_name(kb), angle, state_name[target]);
            const cmp_t c = compare(p, &spec, X, tang, hist, what);
            if (c.status == B2B_CONTACT_ACTIVE) {
              ++count[ka][c.state];
              ++count[kb][c.state];
            }
          }
    b2b_params_destroy(&p);
  }
  report("friction, every kind pair, both laws");
  for (int k = 0; k < n_kinds; ++k)
    for (int s = ST_FRESH; s <= ST_SLIP; ++s)
      ck_assert_msg(count[k][s] >= 4, "%s: only %d %s configurations", tst_kind_name(k),
                    count[k][s], state_name[s]);
}
END_TEST

/* Crossing angles 90 down to 1 degree on slender beams (as in
 * check_pair_tangent: turning below the angle, so that the crossing is a
 * minimum of the distance), frictionless and sliding. */
START_TEST(crossing_angles_down_to_1_degree) {
  count_kinds();
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 11003);
  const double angles[] = {90, 60, 30, 10, 5, 3, 2, 1};
  int n = 0;
  for (int fr = 0; fr < 2; ++fr) {
    b2b_params *p = params_for(B2B_LAW_LINEAR, fr, B2B_TANGENT_EXACT);
    for (size_t q = 0; q < sizeof angles / sizeof angles[0]; ++q)
      for (int k = 0; k < n_kinds; ++k)
        for (int rep = 0; rep < 2; ++rep) {
          tst_pair_spec spec = {{k, (k + rep + fr) % n_kinds}, {0, 0}, {0, 0}, {0.02, 0.015}};
          double X0[24], X[24], tang[12], hist[HLEN];
          const double rad = angles[q] * kPi / 180.0;
          crossing(&rng, &spec, 0.25 * rad, angles[q], tst_uniform(&rng, -0.2, 0.2),
                   tst_uniform(&rng, -0.2, 0.2), 0.03, X0, tang);
          char what[160];
          snprintf(what, sizeof what, "angle %g, %s x %s%s", angles[q], tst_kind_name(k),
                   tst_kind_name(spec.kind[1]), fr ? ", sliding" : "");
          const double *h = NULL;
          memcpy(X, X0, sizeof X);
          if (fr) {
            ck_assert_msg(prepare(&rng, p, &spec, tang, X0, rep ? ST_SLIP : ST_STICK, 1, X, hist),
                          "%s: not active", what);
            h = hist;
          }
          const cmp_t c = compare(p, &spec, X, tang, h, what);
          ck_assert_msg(c.status == B2B_CONTACT_ACTIVE, "%s: status %d", what, c.status);
          ++n;
        }
    b2b_params_destroy(&p);
  }
  report("angles 90 .. 1 degree");
  ck_assert_int_eq(n, 2 * 8 * 2 * n_kinds);
}
END_TEST

/* Closest points near joints (xi = +-0.99) and at beam ends (REFLECT,
 * TANGENT), strongly curved patches, quadratic law, with and without
 * friction. */
START_TEST(near_joints_and_beam_ends) {
  count_kinds();
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 11004);
  const double stars[] = {-0.99, 0.99};
  const int rules[] = {B2B_END_NEIGHBOUR, B2B_END_REFLECT, B2B_END_TANGENT};
  int n = 0;
  for (int fr = 0; fr < 2; ++fr) {
    b2b_params *p = params_for(B2B_LAW_QUADRATIC, fr, B2B_TANGENT_EXACT);
    for (int k = 0; k < n_kinds; ++k)
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 2; ++s)
          for (int rep = 0; rep < 2; ++rep) {
            tst_pair_spec spec = {{k, n_kinds - 1 - k}, {0, 0}, {0, 0}, {0.2, 0.15}};
            if (stars[s] < 0) spec.start_rule[0] = rules[r];
            else spec.end_rule[0] = rules[r];
            double X0[24], X[24], tang[12], hist[HLEN];
            crossing(&rng, &spec, 0.6, tst_uniform(&rng, 30, 90), stars[s],
                     tst_uniform(&rng, -0.5, 0.5), 0.3, X0, tang);
            char what[160];
            snprintf(what, sizeof what, "%s xi* %g, rule %d%s", tst_kind_name(k), stars[s],
                     rules[r], fr ? ", friction" : "");
            const double *h = NULL;
            memcpy(X, X0, sizeof X);
            if (fr) {
              if (!prepare(&rng, p, &spec, tang, X0, rep ? ST_SLIP : ST_STICK, 0, X, hist))
                continue;
              h = hist;
            }
            if (compare(p, &spec, X, tang, h, what).status == B2B_CONTACT_ACTIVE) ++n;
          }
    b2b_params_destroy(&p);
  }
  report("near joints and beam ends");
  ck_assert_int_ge(n, 2 * n_kinds * 3 * 2);
}
END_TEST

/* A history whose normal is opposite to d: the axes passed through each
 * other, the normal is kept on the old side (sign-tracked gap, a deep
 * penetration). */
START_TEST(sign_tracked_normal) {
  count_kinds();
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 11005);
  int n = 0;
  for (int fr = 0; fr < 2; ++fr)
    for (int law = 0; law < 2; ++law) {
      b2b_params *p = params_for(law, fr, B2B_TANGENT_EXACT);
      for (int ka = 0; ka < n_kinds; ++ka)
        for (int kb = 0; kb < n_kinds; ++kb) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          double X[24], tang[12], hist[HLEN] = {0}, info[32], R[24];
          crossing(&rng, &spec, 0.4, tst_uniform(&rng, 30, 90), tst_uniform(&rng, -0.5, 0.5),
                   tst_uniform(&rng, -0.5, 0.5), 0.1, X, tang);
          /* the committed step: B's axis on the other side of A's */
          double Xc[24];
          memcpy(Xc, X, sizeof Xc);
          ck_assert_int_eq(tst_pair_ext(p, &spec, X, tang, NULL, hist, info, R, NULL),
                           B2B_CONTACT_ACTIVE);
          for (int k = 4; k < 8; ++k)
            for (int i = 0; i < 3; ++i) Xc[3 * k + i] += 0.2 * info[B2B_INFO_NORMAL + i];
          ck_assert_int_eq(tst_pair_ext(p, &spec, Xc, tang, NULL, hist, info, R, NULL),
                           B2B_CONTACT_ACTIVE);
          char what[160];
          snprintf(what, sizeof what, "passed through, law %d, %s x %s%s", law,
                   tst_kind_name(ka), tst_kind_name(kb), fr ? ", friction" : "");
          double li[32], lr[24];
          ck_assert_int_eq(tst_pair_ext(p, &spec, X, tang, hist, NULL, li, lr, NULL),
                           B2B_CONTACT_ACTIVE);
          ck_assert_msg(li[B2B_INFO_GAP] < -0.35, "%s: gap %g, not sign-tracked", what,
                        li[B2B_INFO_GAP]);
          compare(p, &spec, X, tang, hist, what);
          ++n;
        }
      b2b_params_destroy(&p);
    }
  report("sign-tracked normal");
  ck_assert_int_eq(n, 4 * n_kinds * n_kinds);
}
END_TEST

/* The "tangent" options against the reference's: SYMMETRIC (with friction
 * the symmetric part, else the exact tangent) and MAIN (-f' G G^T) to
 * TOL_K; FD, the library's differences, against the AD tangent to 1e-6. */
START_TEST(tangent_options) {
  count_kinds();
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 11006);
  const int options[] = {B2B_TANGENT_SYMMETRIC, B2B_TANGENT_MAIN, B2B_TANGENT_FD};
  double worst_opt[3] = {0, 0, 0};
  int n = 0;
  for (int o = 0; o < 3; ++o)
    for (int law = 0; law < 2; ++law)
      for (int fr = 0; fr < 2; ++fr) {
        b2b_params *p = params_for(law, fr, options[o]);
        for (int ka = 0; ka < n_kinds; ++ka)
          for (int kb = 0; kb < n_kinds; ++kb) {
            tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
            double X0[24], X[24], tang[12], hist[HLEN];
            crossing(&rng, &spec, 0.4, tst_uniform(&rng, 30, 90), tst_uniform(&rng, -0.5, 0.5),
                     tst_uniform(&rng, -0.5, 0.5), 0.28, X0, tang);
            const double *h = NULL;
            memcpy(X, X0, sizeof X);
            if (fr) {
              ck_assert(prepare(&rng, p, &spec, tang, X0, (ka + kb) % 2 ? ST_SLIP : ST_STICK, 0,
                                X, hist));
              h = hist;
            }
            static double K[576];
            static ad_out ad;
            double info[32], R[24];
            ck_assert_int_eq(tst_pair_ext(p, &spec, X, tang, h, NULL, info, R, K),
                             B2B_CONTACT_ACTIVE);
            ad_eval(p, &spec, X, tang, h, 0, &ad);
            ck_assert_int_eq(ad.status, B2B_CONTACT_ACTIVE);
            ck_assert(info[B2B_INFO_SYMMETRIC] == ad.info[B2B_INFO_SYMMETRIC]);
            const double e = rel_err(K, ad.K, 576);
            worst_opt[o] = fmax(worst_opt[o], e);
            ck_assert_msg(e <= (options[o] == B2B_TANGENT_FD ? 1e-6 : TOL_K),
                          "option %d, law %d, %s x %s%s: tangent differs from the reference's "
                          "by %.2e",
                          options[o], law, tst_kind_name(ka), tst_kind_name(kb),
                          fr ? ", friction" : "", e);
            ck_assert(rel_err(R, ad.R, 24) <= TOL_R);
            ++n;
          }
        b2b_params_destroy(&p);
      }
  printf("tangent options (%d configurations each): worst rel. error SYMMETRIC %.2e, MAIN "
         "%.2e, FD (library differences against AD) %.2e\n",
         n / 3, worst_opt[0], worst_opt[1], worst_opt[2]);
}
END_TEST

/* Axes that intersect (within the tolerance band) with a previous normal in
 * the history: the normal is the history's, the gap -r_A - r_B, and the
 * library's tangent keeps -f' G G^T (doc/contact-element.md 12), which the
 * exact derivative of that residual has not: K_lib - K_ad = -f' G G^T,
 * which is the MAIN tangent. */
START_TEST(intersecting_axes_keep_the_main_term) {
  count_kinds();
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 11007);
  double worst_i = 0.0, worst_r = 0.0;
  int n = 0;
  for (int law = 0; law < 2; ++law) {
    b2b_params *p = params_for(law, 0, B2B_TANGENT_EXACT);
    b2b_params *pm = params_for(law, 0, B2B_TANGENT_MAIN);
    for (int ka = 0; ka < n_kinds; ++ka)
      for (int kb = 0; kb < n_kinds; ++kb) {
        tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
        double X[24], Xh[24], tang[12], hist[HLEN] = {0}, info[32], R[24];
        crossing(&rng, &spec, 0.4, tst_uniform(&rng, 30, 90), tst_uniform(&rng, -0.5, 0.5),
                 tst_uniform(&rng, -0.5, 0.5), 0.0, X, tang);
        /* a history normal from a configuration just above */
        memcpy(Xh, X, sizeof Xh);
        ck_assert_int_eq(tst_pair_ext(p, &spec, X, tang, NULL, NULL, info, R, NULL),
                         B2B_CONTACT_NO_NORMAL);
        for (int k = 0; k < 4; ++k) Xh[3 * k + 2] += 0.05;
        tst_pair_ext(p, &spec, Xh, tang, NULL, hist, info, R, NULL);
        ck_assert(hist[1] == 1.0);
        static double K[576], Km[576];
        static ad_out ad;
        double li[32], lr[24], mi[32], mr[24];
        ck_assert_int_eq(tst_pair_ext(p, &spec, X, tang, hist, NULL, li, lr, K),
                         B2B_CONTACT_ACTIVE);
        ck_assert_int_eq(tst_pair_ext(pm, &spec, X, tang, hist, NULL, mi, mr, Km),
                         B2B_CONTACT_ACTIVE);
        ad_eval(p, &spec, X, tang, hist, 0, &ad);
        ck_assert_int_eq(ad.status, B2B_CONTACT_ACTIVE);
        ck_assert(li[B2B_INFO_GAP] == ad.info[B2B_INFO_GAP]);
        double diff[576];
        for (int i = 0; i < 576; ++i) diff[i] = K[i] - ad.K[i];
        const double e = rel_err(diff, Km, 576) * max_abs(Km, 576) / max_abs(K, 576);
        worst_i = fmax(worst_i, e);
        worst_r = fmax(worst_r, rel_err(lr, ad.R, 24));
        ck_assert_msg(e <= TOL_K, "law %d, %s x %s: K_lib - K_ad differs from -f' G G^T by "
                      "%.2e of max|K|", law, tst_kind_name(ka), tst_kind_name(kb), e);
        ck_assert(rel_err(lr, ad.R, 24) <= TOL_R);
        ck_assert(li[B2B_INFO_SYMMETRIC] == 0.0 && ad.info[B2B_INFO_SYMMETRIC] == 0.0);
        ++n;
      }
    b2b_params_destroy(&p);
    b2b_params_destroy(&pm);
  }
  printf("intersecting axes with a history normal (%d): worst |K_lib - K_ad - (-f' G G^T)| / "
         "max|K_lib| %.2e, residual %.2e\n", n, worst_i, worst_r);
}
END_TEST

/* Checks of the checks: the criteria reject a tangent or a residual
 * perturbed by twice the tolerance in a single entry, and a reference whose
 * derivative ignores the motion of the closest points is rejected by far,
 * on every kind. */
START_TEST(the_checks_can_fail) {
  count_kinds();
  tst_rng rng;
  tst_rng_seed(&rng, 11008);
  b2b_params *p = params_for(B2B_LAW_LINEAR, 1, B2B_TANGENT_EXACT);
  double least_frozen = INFINITY;
  for (int k = 0; k < n_kinds; ++k) {
    tst_pair_spec spec = {{k, k}, {0, 0}, {0, 0}, {0.2, 0.15}};
    double X0[24], X[24], tang[12], hist[HLEN], info[32], R[24];
    static double K[576];
    static ad_out ad, frozen;
    crossing(&rng, &spec, 0.4, 60.0, 0.2, -0.1, 0.28, X0, tang);
    ck_assert(prepare(&rng, p, &spec, tang, X0, ST_SLIP, 0, X, hist));
    ck_assert_int_eq(tst_pair_ext(p, &spec, X, tang, hist, NULL, info, R, K),
                     B2B_CONTACT_ACTIVE);
    ad_eval(p, &spec, X, tang, hist, 0, &ad);
    const double e = rel_err(K, ad.K, 576);
    ck_assert(e <= TOL_K);
    /* one entry off by twice the tolerance */
    int at = (int)tst_uniform(&rng, 0, 576);
    while (K[at] == 0.0) at = (at + 1) % 576;
    const double keep = K[at];
    K[at] += 2.0 * TOL_K * max_abs(ad.K, 576);
    const double e_bad = rel_err(K, ad.K, 576);
    K[at] = keep;
    ck_assert_msg(e_bad > TOL_K, "%s: a perturbed tangent passes (%.2e)", tst_kind_name(k),
                  e_bad);
    /* the same for the residual */
    int ar = (int)tst_uniform(&rng, 0, 24);
    while (R[ar] == 0.0) ar = (ar + 1) % 24;
    const double keep_r = R[ar];
    R[ar] += 2.0 * TOL_R * max_abs(ad.R, 24);
    const double er_bad = rel_err(R, ad.R, 24);
    R[ar] = keep_r;
    ck_assert_msg(er_bad > TOL_R && rel_err(R, ad.R, 24) <= TOL_R,
                  "%s: the residual criterion does not see a perturbation (%.2e)",
                  tst_kind_name(k), er_bad);
    /* the frozen-closest-point reference */
    ad_eval(p, &spec, X, tang, hist, B2B_AD_FREEZE_CLOSEST_POINTS, &frozen);
    const double e_frozen = rel_err(K, frozen.K, 576);
    least_frozen = fmin(least_frozen, e_frozen);
    ck_assert_msg(e_frozen > 1e-3, "%s: a reference without the closest points' motion "
                  "agrees to %.2e", tst_kind_name(k), e_frozen);
    /* same residual: the motion only enters the derivative */
    ck_assert(rel_err(R, frozen.R, 24) <= TOL_R);
    printf("check of the check, %s: tangent error %.2e; one entry perturbed by 2 TOL_K: "
           "%.2e; closest points frozen: %.2e\n",
           tst_kind_name(k), e, e_bad, e_frozen);
  }
  b2b_params_destroy(&p);
  ck_assert(least_frozen > 1e-3);
}
END_TEST

/* The two configurations where the library missed the criteria through its
 * closest-point tolerance alone (found by the sweeps above, xi, eta off by
 * 1.4e-11 .. 2.9e-11, the tangent by 1.4e-12 .. 1.9e-11): against the
 * long-double reference it must now meet them as computed, and started at
 * the accurate closest points too. */
START_TEST(closest_point_accuracy_regressions) {
  count_kinds();
  static const struct {
    const char *what;
    tst_pair_spec spec;
    double X[24];
  } cases[2] = {
      {"linear x hermite-nodal, 20.4 degrees, closest-point Hessian's condition number 825",
       {{0, 2}, {0, 0}, {0, 0}, {0x1.999999999999ap-3, 0x1.3333333333333p-3}},
       {NAN, NAN, NAN, 0x1.79635231c74dep+0, -0x1.5cdbf2de87cb2p+0, -0x1.43b9432b0bb5ep+0,
        0x1.e57eb2d0ea4bdp-1, -0x1.e3d0a7587ce04p+0, -0x1.f7213eb9cc564p-1, NAN, NAN, NAN,
        0x1.eb620db4b5ecep+0, -0x1.e15e6563e8f1ap-1, -0x1.496dc757d74d9p+0,
        0x1.3f6c93accbebcp+0, -0x1.3c4b775848c61p+0, -0x1.15ab8cf83e49cp+0,
        0x1.0654e318a85ebp-1, -0x1.e98e7e53378ap+0, -0x1.0a57b10101cc1p+0,
        0x1.5c3d3615941fp-3, -0x1.2e86cb0531059p+1, -0x1.8209ce55e160cp-1}},
      {"hermite-nodal-weighted x linear, 1 degree",
       {{3, 0}, {0, 0}, {0, 0}, {0x1.47ae147ae147bp-6, 0x1.eb851eb851eb8p-7}},
       {0x1.d928b746da8a8p+0, 0x1.eeb9c175de0dcp+0, -0x1.448244bc0768cp-1,
        0x1.4fb17c6567711p+0, 0x1.48ca1ae65987p+0, -0x1.c15ef43d06d92p-2,
        0x1.1e2ce46f75d54p-1, 0x1.7c20908b0b9bep-2, -0x1.4ddcff498fbcap-3,
        -0x1.325bc79bf5aecp-2, -0x1.5a367a759035bp-1, 0x1.32d3d64bd3102p-3, NAN, NAN, NAN,
        0x1.0997c4d0bb707p+0, 0x1.ef292d0d246cap-1, -0x1.7be54884dab85p-2,
        0x1.55dae18f5274bp-1, 0x1.00c28a3e65292p-1, -0x1.dead14b2a2a9p-3, NAN, NAN, NAN}}};
  b2b_params *p = params_for(B2B_LAW_LINEAR, 0, B2B_TANGENT_EXACT);
  for (int c = 0; c < 2; ++c) {
    static lib_out l;
    static ad_out ol;
    lib_eval(p, &cases[c].spec, cases[c].X, NULL, NULL, &l);
    ad_eval(p, &cases[c].spec, cases[c].X, NULL, NULL, B2B_AD_LONG_DOUBLE, &ol);
    ck_assert_int_eq(l.status, B2B_CONTACT_ACTIVE);
    ck_assert_int_eq(ol.status, B2B_CONTACT_ACTIVE);
    const errs_t e = errors(p, &l, &ol, cases[c].what);
    const errs_t ew = errors_at_accurate_points(p, &cases[c].spec, cases[c].X, NULL, NULL, &ol,
                                                cases[c].what);
    printf("%s: library against the long-double reference: tangent %.2e, residual %.2e, info "
           "%.2e (%s), xi, eta off by %.1e, %.1e after %g iterations; started at the accurate "
           "closest points: %.2e, %.2e, %.2e\n",
           cases[c].what, e.tangent, e.residual, e.info, e.field,
           l.info[B2B_INFO_XI] - ol.info[B2B_INFO_XI], l.info[B2B_INFO_ETA] - ol.info[B2B_INFO_ETA],
           l.info[B2B_INFO_ITERATIONS], ew.tangent, ew.residual, ew.info);
    const double tol_k = tangent_tolerance(l.info[B2B_INFO_ANGLE]);
    ck_assert(within(ew, tol_k, TOL_R, TOL_I));
    ck_assert(within(e, tol_k, TOL_R, TOL_I));
  }
  b2b_params_destroy(&p);
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("pair_ad");
  TCase *tc = tcase_create("ad_reference");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, frictionless_all_kinds);
  tcase_add_test(tc, friction_all_kinds);
  tcase_add_test(tc, crossing_angles_down_to_1_degree);
  tcase_add_test(tc, near_joints_and_beam_ends);
  tcase_add_test(tc, sign_tracked_normal);
  tcase_add_test(tc, tangent_options);
  tcase_add_test(tc, intersecting_axes_keep_the_main_term);
  tcase_add_test(tc, the_checks_can_fail);
  tcase_add_test(tc, closest_point_accuracy_regressions);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
