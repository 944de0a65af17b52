/* The contact element at the extremes of its inputs (issue 11, item 2): one
 * table of extreme classes, each row a generator of configurations (every
 * pair of curve kinds, both normal laws, with and without friction where it
 * matters), the outcomes b2b_pair.h documents for that class, and the
 * accuracy criterion of the class. Every configuration must give
 *   - one of the class's documented outcomes: B2B_OK with a contact status,
 *     or an error status;
 *   - on an error: every output untouched (sentinels: contact status, info,
 *     residual, tangent, new history) and a message naming the beam;
 *   - on B2B_OK: every output finite, and residual and tangent zero unless
 *     the pair is ACTIVE;
 *   - on ACTIVE: residual and tangent within the class's criterion of the
 *     forward-mode AD reference (tests/ad/, b2b_ad.h) in long double, which
 *     measures the library's own error: the reference in double rounds like
 *     the library, and its error against the same criterion is printed too
 *     (where both miss a criterion alike, the loss is the inputs' rounding,
 *     or a formulation the two share);
 *   - nothing aborts or hangs (Check's timeout, 120 s per row; the whole
 *     suite takes well under a second).
 * Relative errors are in the max norm: max|K - K_ref| / max|K_ref|. The
 * criteria (formulas in each generator's comment; TOL_K = TOL_R = 1e-12 is
 * check_pair_ad's criterion for well-conditioned crossings):
 *   scale s, penalty eps, offset o of a unit-sized pair: the tangent scales
 *     like eps (not like s), the residual like eps s; the library works in
 *     units of the segments and relative to the patch, so the relative error
 *     stays at TOL_K; a pair translated exactly or scaled by a power of two
 *     must give the untransformed pair's results (see each row);
 *   crossing angle theta: the closest-point Hessian's condition number is
 *     1/sin^2(theta), so rounding of the closest points and of the closed-form
 *     tangent grows like eps / sin^2(theta): TOL (sin 2 deg / sin theta)^2
 *     below 2 degrees, as in check_pair_ad;
 *   axes a distance rho apart (L the segments' length): the residual's
 *     normal tilts by the rounding of d's tangential components, a few
 *     eps L / rho (doc/contact-element.md 4): TOL + 32 eps L / rho; the
 *     tangent's sensitivity to the rounding of the inputs is L / rho times a
 *     factor of the geometry (up to about 50 on these crossings):
 *     TOL_K + 64 eps L / rho.
 * No finite differences are used: at an offset of 1e8 a central difference
 * with step h moves coordinates whose spacing is 1.5e-8, at scale 1e-9 or
 * penalty 1e15 a fixed step is meaningless, and at small angles or axis
 * distances the truncation error grows like the very conditioning the
 * criteria state, so differences could only be checked with tolerances
 * loosened by orders of magnitude; the AD reference has no truncation error.
 * The suite prints a summary table: class, configurations, outcomes seen,
 * criterion, worst error of the library as a fraction of its criterion (and
 * the AD reference's in double, and of the row's transformed-twin check).
 * Each row is one Check test (a loop test over the table), so a failing row
 * does not hide the others; its line of the table is printed before its
 * assertions. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "b2b_ad.h"
#include "pair_support.h"

#define TOL_K 1e-12 /* tangent, relative, max norm (check_pair_ad's) */
#define TOL_R 1e-12 /* residual */
#define EPS DBL_EPSILON
#define HLEN 12
#define SENTINEL (-7.25)
#define MU 0.3

static const double kPi = 3.14159265358979323846;
static const double kDefaultTangents[12] = {1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0};

/* ------------------------------------------------------------ outcomes */

/* An outcome: a contact status (0..5) with B2B_OK, or 16 + an error code. */
#define N_OUTCOMES 32
#define OK_(status) (1u << (status))
#define ERR_(code) (1u << (16 + (code)))
static int outcome_of(int rc, int status) { return rc == B2B_OK ? status : 16 + rc; }
static const char *outcome_name(int o) {
  static const char *const contact[] = {"OPEN", "ACTIVE", "OUTSIDE", "PARALLEL",
                                        "NOT_CONVERGED", "NO_NORMAL"};
  if (o >= 0 && o < 6) return contact[o];
  switch (o - 16) {
    case B2B_ERR_COINCIDENT: return "ERR_COINCIDENT";
    case B2B_ERR_FOLDED: return "ERR_FOLDED";
    case B2B_ERR_RANGE: return "ERR_RANGE";
    default: return "another status";
  }
}

/* ------------------------------------------------------------ a configuration */

typedef struct {
  char what[200];
  /* the parameter set */
  int law;
  double penalty, g0, mu, eps_t, parallel_angle; /* parallel_angle < 0: the default */
  /* the pair */
  tst_pair_spec spec;
  double X[24], tang[12], hist[HLEN]; /* hist: hist_old (zero: fresh) */
  /* the class's expectations */
  unsigned allowed;      /* documented outcomes */
  double tol_k, tol_r;   /* on ACTIVE: criteria against the reference */
  int agree;             /* the reference's contact status must be the library's */
  int at_threshold;      /* at the singular-problem threshold: an ACTIVE library
                            may meet a PARALLEL reference (rounding decides) */
  int intersecting;      /* axes within the tolerance band with a history normal:
                            the library keeps -f' G G^T (doc/contact-element.md 12) */
  const double *k_ref;   /* a reference tangent to use instead of the reference's
                            own at X (NULL: its own) */
  const char *msg_has;   /* on an error: a text the message must contain */
} config;

static void init_config(config *c, int ka, int kb, int law, double penalty, int friction) {
  memset(c, 0, sizeof *c);
  c->law = law;
  c->penalty = penalty;
  c->g0 = 0.1;
  c->mu = friction ? MU : 0.0;
  c->eps_t = friction ? 0.8 * penalty : 0.0;
  c->parallel_angle = -1.0;
  const tst_pair_spec spec = {{ka, kb}, {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                              {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR}, {0.2, 0.15}};
  c->spec = spec;
  memcpy(c->tang, kDefaultTangents, sizeof c->tang);
  c->allowed = OK_(B2B_CONTACT_ACTIVE);
  c->tol_k = TOL_K;
  c->tol_r = TOL_R;
  c->agree = 1;
}

static b2b_params *make_params(const config *c, int tangent_option) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, msg, sizeof msg), B2B_OK);
  int rc = b2b_params_set_real(p, "penalty", c->penalty, msg, sizeof msg);
  rc |= b2b_params_set_int(p, "law", c->law, msg, sizeof msg);
  if (c->law == B2B_LAW_QUADRATIC)
    rc |= b2b_params_set_real(p, "regularization_gap", c->g0, msg, sizeof msg);
  if (c->mu > 0.0) {
    rc |= b2b_params_set_real(p, "friction", c->mu, msg, sizeof msg);
    rc |= b2b_params_set_real(p, "tangential_penalty", c->eps_t, msg, sizeof msg);
  }
  if (c->parallel_angle >= 0.0)
    rc |= b2b_params_set_real(p, "parallel_angle", c->parallel_angle, msg, sizeof msg);
  rc |= b2b_params_set_int(p, "tangent", tangent_option, msg, sizeof msg);
  rc |= b2b_params_finalize(p, msg, sizeof msg);
  ck_assert_msg(rc == B2B_OK, "%s: parameters: %s", c->what, msg);
  return p;
}

static int history_len(const b2b_params *p) {
  int n = 0;
  b2b_params_history_size(p, &n, NULL, 0);
  return n;
}

typedef struct {
  int rc, status;
  double info[32], R[24], K[576], hist[HLEN];
  char msg[B2B_ERRMSG_LEN];
} result;

/* The library, every output preset to a sentinel. */
static void lib_call(const b2b_params *p, const config *c, result *r) {
  const int segments[6] = {c->spec.kind[0], c->spec.start_rule[0], c->spec.end_rule[0],
                           c->spec.kind[1], c->spec.start_rule[1], c->spec.end_rule[1]};
  r->status = -99;
  for (int i = 0; i < 32; ++i) r->info[i] = SENTINEL;
  for (int i = 0; i < 24; ++i) r->R[i] = SENTINEL;
  for (int i = 0; i < 576; ++i) r->K[i] = SENTINEL;
  for (int i = 0; i < HLEN; ++i) r->hist[i] = SENTINEL;
  r->msg[0] = '\0';
  r->rc = b2b_pair_eval(p, segments, c->X, c->tang, c->spec.radius, c->hist, r->hist,
                        history_len(p), &r->status, r->info, r->R, r->K, 24, r->msg,
                        sizeof r->msg);
}

/* The AD reference (flags: 0, or B2B_AD_LONG_DOUBLE). */
static void ref_call(const b2b_params *p, const config *c, int flags, result *r) {
  const int segments[6] = {c->spec.kind[0], c->spec.start_rule[0], c->spec.end_rule[0],
                           c->spec.kind[1], c->spec.start_rule[1], c->spec.end_rule[1]};
  r->msg[0] = '\0';
  r->rc = b2b_ad_pair_eval_ex(p, segments, c->X, c->tang, c->spec.radius, c->hist, r->hist,
                              history_len(p), flags, &r->status, r->info, r->R, r->K, 24, NULL,
                              NULL, NULL, r->msg, sizeof r->msg);
}

/* ------------------------------------------------------------ bookkeeping */

static double max_abs(const double *a, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fabs(a[i]));
  return m;
}

/* max|a - b| / max|b| (max|a - b| if b is zero). */
static double rel_err(const double *a, const double *b, int n) {
  double d = 0.0;
  for (int i = 0; i < n; ++i) d = fmax(d, fabs(a[i] - b[i]));
  const double m = max_abs(b, n);
  return m > 0.0 ? d / m : d;
}

static int all_finite(const double *a, int n) {
  for (int i = 0; i < n; ++i)
    if (!isfinite(a[i])) return 0;
  return 1;
}

static int all_equal(const double *a, int n, double v) {
  for (int i = 0; i < n; ++i)
    if (!(a[i] == v)) return 0;
  return 1;
}

/* The running row's record (each row runs in its own process). Violations of
 * the documented outcomes are counted and the first one kept, so that the
 * row's line of the summary is printed before the row fails. */
typedef struct {
  int n, seen[N_OUTCOMES], disagree, n_active, n_twin;
  double worst, worst_ad, worst_twin; /* errors as fractions of their criteria */
  char worst_what[600], worst_twin_what[600];
  int bad;
  char first_bad[600];
} row_record;
static row_record rec;

/* A configuration, exactly (hexadecimal floats), on stderr: what a
 * reproducer needs. */
static void dump_config(const config *c, const char *why) {
  fprintf(stderr,
          "reproducer (%s) of \"%s\": law %d, penalty %a, g0 %a, friction %a, eps_t %a, "
          "parallel_angle %a\nsegments {%d, %d, %d, %d, %d, %d}, radii {%a, %a}\nX {",
          why, c->what, c->law, c->penalty, c->g0, c->mu, c->eps_t, c->parallel_angle,
          c->spec.kind[0], c->spec.start_rule[0], c->spec.end_rule[0], c->spec.kind[1],
          c->spec.start_rule[1], c->spec.end_rule[1], c->spec.radius[0], c->spec.radius[1]);
  for (int a = 0; a < 24; ++a) fprintf(stderr, "%s%a", a ? ", " : "", c->X[a]);
  fprintf(stderr, "}\nend_tangents {");
  for (int a = 0; a < 12; ++a) fprintf(stderr, "%s%a", a ? ", " : "", c->tang[a]);
  fprintf(stderr, "}\nhist_old {");
  for (int a = 0; a < HLEN; ++a) fprintf(stderr, "%s%a", a ? ", " : "", c->hist[a]);
  fprintf(stderr, "}\n");
}

static const config *current; /* the configuration being judged */
static config worst_config;    /* the worst one of the row */

static void violation(const char *fmt, ...) {
  if (rec.bad++ == 0) {
    if (current) dump_config(current, "the first violation");
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(rec.first_bad, sizeof rec.first_bad, fmt, ap);
    va_end(ap);
  }
}

/* Evaluates c with the library and judges it by the class's expectations;
 * the library's result in *out if out is not NULL. */
static void judge(const config *c, result *out) {
  static result l, ref, ad, mainr;
  current = c;
  b2b_params *p = make_params(c, B2B_TANGENT_EXACT);
  const int nh = history_len(p);
  lib_call(p, c, &l);
  const int o = outcome_of(l.rc, l.status);
  ++rec.n;
  if (o >= 0 && o < N_OUTCOMES) ++rec.seen[o];
  if (!(o >= 0 && o < N_OUTCOMES && (c->allowed & (1u << o))))
    violation("%s: outcome %s, not one documented for this class (iterations %g, xi %.3g, "
              "eta %.3g, angle %.3g deg; %s)",
              c->what, outcome_name(o), l.info[B2B_INFO_ITERATIONS], l.info[B2B_INFO_XI],
              l.info[B2B_INFO_ETA], l.info[B2B_INFO_ANGLE], l.msg);
  if (l.rc != B2B_OK) {
    if (!(l.status == -99 && all_equal(l.info, 32, SENTINEL) && all_equal(l.R, 24, SENTINEL) &&
          all_equal(l.K, 576, SENTINEL) && all_equal(l.hist, HLEN, SENTINEL)))
      violation("%s: %s wrote an output", c->what, outcome_name(o));
    if (strlen(l.msg) == 0 || (c->msg_has && !strstr(l.msg, c->msg_has)))
      violation("%s: %s with the message \"%s\" (expected one naming \"%s\")", c->what,
                outcome_name(o), l.msg, c->msg_has ? c->msg_has : "the problem");
    if (out) *out = l;
    b2b_params_destroy(&p);
    return;
  }
  if (!(all_finite(l.info, 32) && all_finite(l.R, 24) && all_finite(l.K, 576) &&
        all_finite(l.hist, nh)))
    violation("%s: B2B_OK (%s) with a non-finite output", c->what, outcome_name(o));
  if (l.status != B2B_CONTACT_ACTIVE && !(all_equal(l.R, 24, 0.0) && all_equal(l.K, 576, 0.0)))
    violation("%s: %s with a non-zero residual or tangent", c->what, outcome_name(o));
  ref_call(p, c, B2B_AD_LONG_DOUBLE, &ref);
  if (ref.rc != B2B_OK)
    violation("%s: the reference returned %d (%s)", c->what, ref.rc, ref.msg);
  if (ref.status != l.status) {
    ++rec.disagree;
    if (c->agree || (l.status == B2B_CONTACT_ACTIVE && !c->at_threshold))
      violation("%s: contact status %s, the reference's %s", c->what, outcome_name(l.status),
                outcome_name(ref.status));
  }
  if (l.status == B2B_CONTACT_ACTIVE && ref.status == B2B_CONTACT_ACTIVE) {
    static double k_exp[576], k_ad[576];
    const double *kr = c->k_ref ? c->k_ref : ref.K;
    memcpy(k_exp, kr, sizeof k_exp);
    ref_call(p, c, 0, &ad);
    memcpy(k_ad, ad.K, sizeof k_ad);
    if (c->intersecting) { /* + (-f' G G^T): the library's MAIN tangent */
      b2b_params *pm = make_params(c, B2B_TANGENT_MAIN);
      lib_call(pm, c, &mainr);
      b2b_params_destroy(&pm);
      for (int i = 0; i < 576; ++i) {
        k_exp[i] += mainr.K[i];
        k_ad[i] += mainr.K[i];
      }
    }
    const double ek = rel_err(l.K, k_exp, 576), er = rel_err(l.R, ref.R, 24);
    const double ratio = fmax(ek / c->tol_k, er / c->tol_r);
    const double ratio_ad = fmax(rel_err(k_ad, k_exp, 576) / c->tol_k,
                                 rel_err(ad.R, ref.R, 24) / c->tol_r);
    ++rec.n_active;
    if (ratio > rec.worst || rec.n_active == 1) {
      rec.worst = ratio;
      worst_config = *c;
      snprintf(rec.worst_what, sizeof rec.worst_what,
               "%s: tangent %.2e (criterion %.2e), residual %.2e (criterion %.2e); xi, eta "
               "off by %.1e, %.1e",
               c->what, ek, c->tol_k, er, c->tol_r, l.info[B2B_INFO_XI] - ref.info[B2B_INFO_XI],
               l.info[B2B_INFO_ETA] - ref.info[B2B_INFO_ETA]);
    }
    rec.worst_ad = fmax(rec.worst_ad, ratio_ad);
  }
  if (out) *out = l;
  b2b_params_destroy(&p);
  current = NULL;
}

/* A transformed twin b of a, whose residual must be fr times a's and tangent
 * fk times a's, to tol relative (tol 0: bit for bit). */
static void twin(const char *what, const result *a, const result *b, double fr, double fk,
                 double tol) {
  if (a->rc != B2B_OK || b->rc != B2B_OK || a->status != b->status) {
    violation("%s: the twins differ in outcome (%s, %s)", what,
              outcome_name(outcome_of(a->rc, a->status)),
              outcome_name(outcome_of(b->rc, b->status)));
    return;
  }
  double er = 0.0, ek = 0.0, mr = 0.0, mk = 0.0;
  for (int i = 0; i < 24; ++i) {
    er = fmax(er, fabs(b->R[i] - fr * a->R[i]));
    mr = fmax(mr, fabs(fr * a->R[i]));
  }
  for (int i = 0; i < 576; ++i) {
    ek = fmax(ek, fabs(b->K[i] - fk * a->K[i]));
    mk = fmax(mk, fabs(fk * a->K[i]));
  }
  er = mr > 0.0 ? er / mr : er;
  ek = mk > 0.0 ? ek / mk : ek;
  const double e = fmax(er, ek);
  const double ratio = tol > 0.0 ? e / tol : (e > 0.0 ? INFINITY : 0.0);
  ++rec.n_twin;
  if (ratio > rec.worst_twin || rec.n_twin == 1) {
    rec.worst_twin = ratio;
    snprintf(rec.worst_twin_what, sizeof rec.worst_twin_what,
             "%s: residual %.2e, tangent %.2e relative to the expected (criterion %s%.1e)", what,
             er, ek, tol > 0.0 ? "" : "bit for bit, ", tol);
  }
}

/* ------------------------------------------------------------ geometry */

static void cross3(const double *a, const double *b, double *c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
static double norm3(const double *a) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/* The chord lengths of the pair's segments, summed: the length unit L. */
static double pair_length(const config *c) {
  double L = 0.0;
  for (int b = 0; b < 2; ++b) {
    double x0[9], x1[9], d[3];
    tst_eval(c->spec.kind[b], c->spec.start_rule[b], c->spec.end_rule[b], c->X + 12 * b,
             c->tang + 6 * b, -1.0, x0, NULL, NULL);
    tst_eval(c->spec.kind[b], c->spec.start_rule[b], c->spec.end_rule[b], c->X + 12 * b,
             c->tang + 6 * b, 1.0, x1, NULL, NULL);
    for (int i = 0; i < 3; ++i) d[i] = x1[i] - x0[i];
    L += norm3(d);
  }
  return L;
}

/* Moves beam B's patch by v (unused slots stay NaN). */
static void move_b(double *X, const double *v) {
  for (int k = 4; k < 8; ++k)
    for (int i = 0; i < 3; ++i) X[3 * k + i] += v[i];
}

/* A crossing of the spec's kinds (tst_crossing: random curved patches
 * turning up to max_turn per node, tangents crossing at angle_deg at xi*,
 * eta* with the axes dist apart), retried until the library finds it ACTIVE
 * at the origin with c's parameters: a random curved crossing can be a
 * saddle of the distance (doc/contact-element.md 2), another class. */
static void active_crossing(tst_rng *rng, config *c, double max_turn, double angle_deg,
                            double star, double dist) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    tst_crossing(rng, &c->spec, max_turn, angle_deg, tst_uniform(rng, -star, star),
                 tst_uniform(rng, -star, star), dist, c->X);
    static result r;
    b2b_params *p = make_params(c, B2B_TANGENT_EXACT);
    lib_call(p, c, &r);
    b2b_params_destroy(&p);
    if (r.rc == B2B_OK && r.status == B2B_CONTACT_ACTIVE) return;
  }
  ck_abort_msg("%s: no active crossing in 20 attempts", c->what);
}

/* Slides beam A by d along its own axis at its closest point: in the
 * contact's tangent plane, and the crossing point stays where it is even at
 * small angles (the material slides through it). */
static void slide_a(const config *c, const double *info, double d, double *X) {
  double x[9];
  tst_eval(c->spec.kind[0], c->spec.start_rule[0], c->spec.end_rule[0], X, c->tang,
           info[B2B_INFO_XI], x, NULL, NULL);
  const double l = norm3(x + 3);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) X[3 * k + i] += d * x[3 + i] / l;
}

/* A transformation of a configuration's coordinates, X -> s X + o, exact
 * when s is a power of two and o holds integers below 2^27 with X on the
 * grid 2^-26 (snap). */
typedef struct {
  double s, o[3];
  int snap;
} transform;
static const transform kIdentity = {1.0, {0.0, 0.0, 0.0}, 0};

static void apply(const transform *t, const double *X, double *Y) {
  for (int a = 0; a < 24; ++a) Y[a] = X[a] * t->s + t->o[a % 3]; /* NaN stays NaN */
}

static void snap(double *X) {
  for (int a = 0; a < 24; ++a) X[a] = ldexp(nearbyint(ldexp(X[a], 26)), -26);
}

static int active(const result *r) { return r->rc == B2B_OK && r->status == B2B_CONTACT_ACTIVE; }

/* Friction states: 0 fresh (no history), 1 stick, 2 slip. For 1 and 2 the
 * crossing a->X is committed, A slid along its own axis by 0.4 or 1.5 stick
 * lengths mu f_N / eps_T (which keeps the crossing point, even at small
 * angles) and committed again, then slid on by 0.3 or 2.5; the committed
 * histories are the library's. With a twin b (may be NULL), b's coordinates
 * are t applied to a's at every step, and b's histories its own. Returns 0
 * unless every committed step is active. */
static int prepare(config *a, config *b, const transform *t, int state) {
  memset(a->hist, 0, sizeof a->hist);
  if (t->snap) snap(a->X);
  if (b) {
    memset(b->hist, 0, sizeof b->hist);
    apply(t, a->X, b->X);
  }
  if (state == 0 || a->mu == 0.0) return 1;
  static result ra, rb;
  b2b_params *pa = make_params(a, B2B_TANGENT_EXACT);
  b2b_params *pb = b ? make_params(b, B2B_TANGENT_EXACT) : NULL;
  int ok = 1;
  for (int step = 0; step < 2 && ok; ++step) {
    lib_call(pa, a, &ra);
    if (b) lib_call(pb, b, &rb);
    ok = active(&ra) && (!b || active(&rb));
    if (!ok) break;
    memcpy(a->hist, ra.hist, sizeof a->hist);
    if (b) memcpy(b->hist, rb.hist, sizeof b->hist);
    const double slide = state == 1 ? (step ? 0.3 : 0.4) : (step ? 2.5 : 1.5);
    slide_a(a, ra.info, slide * a->mu * ra.info[B2B_INFO_NORMAL_FORCE] / a->eps_t, a->X);
    if (t->snap) snap(a->X);
    if (b) apply(t, a->X, b->X);
  }
  b2b_params_destroy(&pa);
  if (pb) b2b_params_destroy(&pb);
  return ok;
}

/* A configuration whose committed steps were not all active (where the same
 * steps of the untransformed crossing were, unit_crossing_for) is a
 * violation; the generator goes on with the next one. */
static int prepared(int ok, const config *c) {
  if (!ok) violation("%s: a committed step before it is not active", c->what);
  return ok;
}

static const char *const kState[3] = {"fresh", "stick", "slip"};

static void name(config *c, const char *fmt, ...) {
  char head[120];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(head, sizeof head, fmt, ap);
  va_end(ap);
  snprintf(c->what, sizeof c->what, "%s, %s x %s, %s law%s", head, tst_kind_name(c->spec.kind[0]),
           tst_kind_name(c->spec.kind[1]), c->law ? "quadratic" : "linear",
           c->mu > 0.0 ? ", friction" : "");
}

/* ------------------------------------------------------------ the classes */

/* The angle criterion: TOL (sin 2 deg / sin theta)^2 below 2 degrees. */
static double angle_factor(double theta) {
  return fmax(1.0, pow(sin(2.0 * kPi / 180.0) / sin(theta), 2));
}

/* Slender beams crossing at theta (turning below the angle, radii 0.02 and
 * 0.015, axes 0.03 apart, closest points within 0.2 of the middle), as
 * check_pair_ad does down to 1 degree: the crossing is a minimum of the
 * distance while theta^2 exceeds the axis distance times the relative
 * curvature (doc/contact-element.md 2), so the turning is also kept below
 * 0.1 theta^2 / 0.03. */
static void slender_crossing(tst_rng *rng, config *c, double theta) {
  c->spec.radius[0] = 0.02;
  c->spec.radius[1] = 0.015;
  c->g0 = 0.01;
  const double turn = fmin(fmin(0.25 * theta, 0.1 * theta * theta / 0.03), 0.5);
  tst_crossing(rng, &c->spec, turn, theta * 180.0 / kPi, tst_uniform(rng, -0.2, 0.2),
               tst_uniform(rng, -0.2, 0.2), 0.03, c->X);
}

/* Angles 90 .. 0.6 degrees (above the default "parallel_angle", 0.5 deg):
 * ACTIVE, every kind pair, both laws, frictionless and sliding (stick,
 * slip: A slid along its own axis, which keeps the crossing point).
 * Criterion TOL (sin 2 deg / sin theta)^2 for tangent and residual (the
 * closest points' rounding moves the residual's weights as much). */
static void gen_angles(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12001);
  const double deg[] = {90, 30, 5, 2, 1, 0.6};
  for (size_t q = 0; q < sizeof deg / sizeof *deg; ++q)
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int fr = 0; fr < 2; ++fr) {
          const double theta = deg[q] * kPi / 180.0;
          config c;
          init_config(&c, ka, kb, (int)((ka + kb + q) % 2), 1e3, fr);
          const int state = fr ? 1 + (int)((ka + kb + q) % 2) : 0;
          slender_crossing(&rng, &c, theta);
          name(&c, "angle %g deg, %s", deg[q], kState[state]);
          if (!prepared(prepare(&c, NULL, &kIdentity, state), &c)) continue;
          c.tol_k = TOL_K * angle_factor(theta);
          c.tol_r = TOL_R * angle_factor(theta);
          judge(&c, NULL);
        }
}

static const double kSmallAngles[] = {0.4 * 3.14159265358979323846 / 180.0,
                                      0.1 * 3.14159265358979323846 / 180.0,
                                      1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-10};
#define N_SMALL_ANGLES (sizeof kSmallAngles / sizeof *kSmallAngles)

/* Angles 0.4 degrees .. 1e-10 rad with the default "parallel_angle" (0.5
 * degrees): PARALLEL, whatever the search does (b2b_pair.h: "crossing angle
 * below parallel_angle"), no force; with friction the history is forgotten. */
static void gen_angles_below_threshold(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12002);
  for (size_t q = 0; q < N_SMALL_ANGLES; ++q)
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
        config c;
        init_config(&c, ka, kb, (int)((ka + kb + q) % 2), 1e3, (int)((ka + q) % 2));
        slender_crossing(&rng, &c, kSmallAngles[q]);
        c.allowed = OK_(B2B_CONTACT_PARALLEL);
        c.agree = 0; /* the reference has no PARALLEL for a search that stopped */
        name(&c, "angle %.1e rad, default parallel_angle", kSmallAngles[q]);
        judge(&c, NULL);
      }
}

/* The same small angles with "parallel_angle" 0 (a host's choice, within
 * its documented range [0, 90)): the pair is evaluated down to where the
 * closest-point problem is singular. Documented: ACTIVE with the angle
 * criterion TOL (sin 2 deg / sin theta)^2; NOT_CONVERGED ("the search did
 * not converge") or OUTSIDE (a search that did not converge and ran off the
 * segment, doc/contact-element.md 4: the midpoint kind's extension retraces
 * a nearly parallel line); PARALLEL only for "a singular closest-point problem",
 * det H <= 1e-12 |a|^2 |b|^2 (doc/contact-element.md 5), i.e. sin theta
 * below about 1e-6 on these straight-to-rounding crossings (allowed below
 * 2e-6). */
static void gen_angles_host_zero(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12003);
  for (size_t q = 0; q < N_SMALL_ANGLES; ++q)
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
        const double theta = kSmallAngles[q];
        config c;
        init_config(&c, ka, kb, (int)((ka + kb + q) % 2), 1e3, (int)((kb + q) % 2));
        slender_crossing(&rng, &c, theta);
        c.parallel_angle = 0.0;
        c.allowed = OK_(B2B_CONTACT_ACTIVE) | OK_(B2B_CONTACT_NOT_CONVERGED) |
                    OK_(B2B_CONTACT_OUTSIDE) |
                    (sin(theta) < 2e-6 ? OK_(B2B_CONTACT_PARALLEL) : 0u);
        c.agree = 0;
        /* det H <= 1e-12 |a|^2 |b|^2 is sin^2 theta <= 1e-12 here: near
         * 1e-6 rad the library and the reference may fall either side */
        c.at_threshold = sin(theta) < 2e-6;
        c.tol_k = TOL_K * angle_factor(theta);
        c.tol_r = TOL_R * angle_factor(theta);
        name(&c, "angle %.1e rad, parallel_angle 0", theta);
        judge(&c, NULL);
      }
}

/* A crossing of unit elements at angles 20..90 degrees, axes 0.3 apart
 * (radii 0.2, 0.15: gap -0.05), closest points within 0.5 of the middle. */
static void unit_crossing(tst_rng *rng, config *c) {
  active_crossing(rng, c, 0.5, tst_uniform(rng, 20, 90), 0.5, 0.3);
}

/* A unit crossing that stays active through its friction steps (prepare,
 * state) and after them: a slide of a few stick lengths can make a strongly
 * curved random patch's closest point jump to a closer one off the segment
 * (OUTSIDE, rightly), another class; retried. */
static void unit_crossing_for(tst_rng *rng, config *c, int state) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    unit_crossing(rng, c);
    config trial = *c;
    if (!prepare(&trial, NULL, &kIdentity, state)) continue;
    static result r;
    b2b_params *p = make_params(&trial, B2B_TANGENT_EXACT);
    lib_call(p, &trial, &r);
    b2b_params_destroy(&p);
    if (active(&r)) return;
  }
  ck_abort_msg("%s: no crossing that stays active in 20 attempts", c->what);
}

/* Offsets 1e2 .. 1e8 of a pair of unit elements, exact translations (the
 * coordinates on the grid 2^-26, the spacing of doubles at 1e8): the library
 * works relative to the patch (doc/contact-element.md 4), so the translated
 * pair's residual and tangent are the untranslated pair's to rounding
 * (criterion 64 eps: the midpoint kind's end points are node midpoints,
 * whose rounding differs with the translation, so its search starts a few
 * ulps elsewhere), and both are within TOL of the reference. Offsets 1e10
 * and 1e12 cannot be exact (the spacing there is 2e-6 and 1e-4): the
 * rounded coordinates make another pair, judged against the reference on
 * its own inputs, TOL. Every kind pair, both laws, frictionless and in a
 * slipping second step. */
static void gen_offsets(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12004);
  const double offsets[] = {1e2, 1e4, 1e6, 1e8, 1e10, 1e12};
  for (size_t q = 0; q < sizeof offsets / sizeof *offsets; ++q)
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
        const int fr = (int)((ka + kb + q) % 2);
        config a, b;
        init_config(&a, ka, kb, (int)((ka + q) % 2), 1e3, fr);
        unit_crossing_for(&rng, &a, 2 * fr);
        double dir[3];
        for (int i = 0; i < 3; ++i) dir[i] = tst_uniform(&rng, -1, 1);
        const int exact = offsets[q] <= 1e8;
        b = a;
        transform t = {1.0, {0, 0, 0}, exact};
        for (int i = 0; i < 3; ++i)
          t.o[i] = exact ? nearbyint(offsets[q] * dir[i]) : offsets[q] * dir[i];
        name(&a, "offset 0 (twin of %.0e)", offsets[q]);
        name(&b, "offset %.0e%s", offsets[q], exact ? "" : " (rounded)");
        if (!prepared(prepare(&a, &b, &t, 2 * fr), &a)) continue;
        result ra, rb;
        if (exact) judge(&a, &ra);
        judge(&b, &rb);
        if (exact) twin(b.what, &ra, &rb, 1.0, 1.0, 64 * EPS);
      }
}

/* Scales 2^-300 .. 2^300 and 1e-90 .. 1e90 of a unit pair (coordinates,
 * radii and the regularization gap scaled, the penalties not: the tangent
 * is then the unit pair's, the residual s times it). Scaling by a power of
 * two is exact in every operation, so the scaled pair must give the unit
 * pair's tangent and s times its residual bit for bit (an absolute constant
 * anywhere in the algebra would show); a power of ten rounds the inputs:
 * judged against the reference, TOL (the issue asks for 1e-9 .. 1e9; the
 * README promises 1e-99 .. 1e99). */
static void gen_scales(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12005);
  const double scales[] = {0x1p-300, 0x1p-30, 0x1p30, 0x1p300, 1e-90, 1e-9, 1e9, 1e90};
  for (size_t q = 0; q < sizeof scales / sizeof *scales; ++q)
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
        const double s = scales[q];
        const int fr = (int)((ka + kb + q) % 2), pow2 = q < 4;
        config a, b;
        init_config(&a, ka, kb, (int)((kb + q) % 2), 1e3, fr);
        unit_crossing_for(&rng, &a, 2 * fr);
        b = a;
        b.spec.radius[0] *= s;
        b.spec.radius[1] *= s;
        b.g0 *= s;
        const transform t = {s, {0, 0, 0}, 0};
        name(&a, "scale 1 (twin of %.1e)", s);
        name(&b, "scale %.1e", s);
        if (!prepared(prepare(&a, &b, &t, 2 * fr), &a)) continue;
        result ra, rb;
        if (pow2) judge(&a, &ra);
        judge(&b, &rb);
        if (pow2) twin(b.what, &ra, &rb, s, 1.0, 0.0);
      }
}

/* Penalties 1e-6 .. 1e15 and 1e300 (friction with eps_T = 0.8 eps_N): every
 * force is proportional to the penalty, so residual and tangent must be
 * eps / 1e3 times those at 1e3 to rounding (criterion 64 eps of the largest
 * entry: each entry is a sum of up to a dozen terms, each rounded once more
 * or less when the penalty changes, with cancellation between them) and
 * within TOL of the reference. Penalty 0: OPEN (no force), residual and
 * tangent zero. */
static void gen_penalties(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12006);
  const double penalties[] = {0.0, 1e-6, 1e-3, 1.0, 1e9, 1e15, 1e300};
  for (size_t q = 0; q < sizeof penalties / sizeof *penalties; ++q)
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
        const double eps = penalties[q];
        const int fr = eps > 0.0 ? (int)((ka + kb + q) % 2) : 0;
        config a, b;
        init_config(&a, ka, kb, (int)((ka + q) % 2), 1e3, fr);
        unit_crossing_for(&rng, &a, 2 * fr);
        b = a;
        b.penalty = eps;
        b.eps_t = 0.8 * eps;
        if (eps == 0.0) b.allowed = OK_(B2B_CONTACT_OPEN);
        name(&a, "penalty 1e3 (twin of %.0e)", eps);
        name(&b, "penalty %.0e", eps);
        if (!prepared(prepare(&a, &b, &kIdentity, 2 * fr), &a)) continue;
        result ra, rb;
        judge(&a, &ra);
        judge(&b, &rb);
        if (eps > 0.0) twin(b.what, &ra, &rb, eps / 1e3, eps / 1e3, 64 * EPS);
      }
}

/* A force or tangent beyond doubles: penalty 1e308 with a penetration of
 * 0.05 .. 0.3, and the quadratic law with g0 = 1e308 (b2b_pair.h: "a force,
 * energy or tangent that would overflow ... B2B_ERR_RANGE"): ERR_RANGE with
 * the outputs untouched, or, where everything fits, ACTIVE within TOL. */
static void gen_overflow(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12007);
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (int law = 0; law < B2B_LAW_COUNT; ++law) {
        config c;
        init_config(&c, ka, kb, law, 1e3, 0);
        active_crossing(&rng, &c, 0.5, tst_uniform(&rng, 20, 90), 0.5,
                        tst_uniform(&rng, 0.05, 0.3));
        c.penalty = 1e308;
        if (law == B2B_LAW_QUADRATIC && (ka + kb) % 2) c.g0 = 1e308;
        c.allowed = OK_(B2B_CONTACT_ACTIVE) | ERR_(B2B_ERR_RANGE);
        c.msg_has = "overflow";
        name(&c, "penalty 1e308, g0 %g", c.g0);
        judge(&c, NULL);
      }
}

/* Penetration beyond r_A + r_B: slender beams (radii 0.02, 0.015), a
 * committed step with the axes 0.03 apart, then B moved through A along the
 * normal to 0.5, 1, 2 and 5 times r_A + r_B on the other side. The
 * history's normal keeps the side (sign-tracked gap, b2b_pair.h): ACTIVE
 * with g = -rho - r_A - r_B < -(r_A + r_B), within TOL of the reference
 * (which tracks the sign the same way). Frictionless and with friction (the
 * committed step anchors the contact). */
static void gen_penetration(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12008);
  const double depth[] = {0.5, 1.0, 2.0, 5.0};
  for (size_t q = 0; q < sizeof depth / sizeof *depth; ++q)
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
        config c;
        init_config(&c, ka, kb, (int)((ka + kb + q) % 2), 1e3, (int)((ka + q) % 2));
        c.spec.radius[0] = 0.02;
        c.spec.radius[1] = 0.015;
        c.g0 = 0.01;
        active_crossing(&rng, &c, 0.5, tst_uniform(&rng, 20, 90), 0.5, 0.03);
        static result r;
        b2b_params *p = make_params(&c, B2B_TANGENT_EXACT);
        lib_call(p, &c, &r);
        b2b_params_destroy(&p);
        memcpy(c.hist, r.hist, sizeof c.hist);
        const double radii = c.spec.radius[0] + c.spec.radius[1];
        double v[3];
        for (int i = 0; i < 3; ++i) v[i] = (0.03 + depth[q] * radii) * r.info[B2B_INFO_NORMAL + i];
        move_b(c.X, v);
        name(&c, "through by %g (r_A + r_B)", depth[q]);
        result out;
        judge(&c, &out);
        if (out.rc == B2B_OK && !(out.info[B2B_INFO_GAP] < -radii))
          violation("%s: gap %g, not beyond -(r_A + r_B)", c.what, out.info[B2B_INFO_GAP]);
      }
}

/* Axes that intersect: within the tolerance band (a crossing built with
 * distance 0: rho is rounding, below 1e-13 L) for every kind pair, and
 * exactly (straight segments through one point, rho = 0). Without a history
 * NO_NORMAL (no force); with a history normal (from a step with the axes
 * 0.05 apart) ACTIVE on that normal, g = -r_A - r_B, and the library's
 * tangent is the exact derivative of its residual plus -f' G G^T, which it
 * keeps on purpose (doc/contact-element.md 12): TOL against the reference
 * plus that term (the MAIN tangent). */
static void gen_intersection(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12009);
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (int form = 0; form < 2; ++form) {
        config c;
        init_config(&c, ka, kb, (ka + kb + form) % 2, 1e3, 0);
        if (form == 0) {
          unit_crossing(&rng, &c); /* active at 0.3: a well-posed crossing */
          double v[3];
          static result r;
          b2b_params *p = make_params(&c, B2B_TANGENT_EXACT);
          lib_call(p, &c, &r);
          b2b_params_destroy(&p);
          for (int i = 0; i < 3; ++i)
            v[i] = r.info[B2B_INFO_POINT_A + i] - r.info[B2B_INFO_POINT_B + i];
          move_b(c.X, v);
        } else { /* A along x, B along y, both through the origin at xi = eta = 0:
                    nodes at +-0.5, +-1.5 (a midpoint segment centred on the
                    origin: nodes -1, 0, 1), so the origin is x(0) exactly */
          for (int b = 0; b < 2; ++b) {
            const int mid = c.spec.kind[b] == B2B_CURVE_HERMITE_MIDPOINT;
            for (int k = 0; k < 4; ++k)
              for (int i = 0; i < 3; ++i)
                c.X[12 * b + 3 * k + i] = i == b ? (mid ? k - 1.0 : k - 1.5) : 0.0;
            for (int i = 0; i < 3; ++i) {
              if (c.spec.kind[b] == B2B_CURVE_LINEAR) c.X[12 * b + i] = c.X[12 * b + 9 + i] = NAN;
              if (mid) c.X[12 * b + 9 + i] = NAN;
            }
          }
        }
        c.allowed = OK_(B2B_CONTACT_NO_NORMAL);
        name(&c, "axes meet (%s), fresh", form ? "exactly" : "within the band");
        judge(&c, NULL);
        /* the history: a step with B 0.05 below along A x B's normal */
        config h = c;
        static result r;
        double n[3], xa[9], xb[9];
        tst_eval(ka, 0, 0, c.X, NULL, 0.0, xa, NULL, NULL);
        tst_eval(kb, 0, 0, c.X + 12, NULL, 0.0, xb, NULL, NULL);
        cross3(xa + 3, xb + 3, n);
        const double ln = norm3(n);
        for (int i = 0; i < 3; ++i) n[i] *= -0.05 / ln;
        move_b(h.X, n);
        h.allowed = OK_(B2B_CONTACT_ACTIVE);
        b2b_params *p = make_params(&h, B2B_TANGENT_EXACT);
        lib_call(p, &h, &r);
        b2b_params_destroy(&p);
        ck_assert_msg(active(&r), "%s: the step before is not active", c.what);
        memcpy(c.hist, r.hist, sizeof c.hist);
        c.allowed = OK_(B2B_CONTACT_ACTIVE);
        c.intersecting = 1;
        name(&c, "axes meet (%s), history normal", form ? "exactly" : "within the band");
        result out;
        judge(&c, &out);
        if (out.rc == B2B_OK && out.status == B2B_CONTACT_ACTIVE &&
            out.info[B2B_INFO_GAP] != -(c.spec.radius[0] + c.spec.radius[1]))
          violation("%s: gap %.17g, not -(r_A + r_B)", c.what, out.info[B2B_INFO_GAP]);
      }
}

/* Near-intersecting axes, rho = 1e-1 .. 1e-12 L (B moved along the normal
 * from an intersecting crossing), and 1e-14 L, inside the tolerance band
 * (NO_NORMAL). The normal d / rho tilts by the rounding of d's tangential
 * components, a few eps L / rho (doc/contact-element.md 4 measured at most
 * 3.8 eps L / rho): criterion TOL_R + 32 eps L / rho for the residual. The
 * exact tangent is bounded and smooth as rho -> 0 (at the closest points the
 * normal is +-(a x b) / |a x b| whatever rho), but its sensitivity to the
 * inputs' rounding grows like L / rho: criterion TOL_K + 64 eps L / rho.
 * This row found the library's tangent off like eps (L / rho)^2 (relative
 * error 150 at 1e-10 L) while it formed the normal as d / rho; it now takes
 * the tangents' cross product there (src/pair/contact_kinematics.cpp), and
 * the worst is about 50 eps L / rho. The reference forms d / rho, in
 * long double; its tangent is accurate to about 1e-19 (L / rho)^2, enough
 * down to rho = 1e-4 L; below, the reference tangent is the long-double
 * reference's at 1e-4 L and 2e-4 L extrapolated linearly to rho (good to
 * about K'' (1e-4 L)^2, 1e-6 on curved pairs), and the criterion is at
 * least 2e-6. */
/* Whether long double arithmetic really carries more digits than double
 * at run time. Under valgrind (the memcheck step) it is emulated with
 * double's 53 bits, and a long-double reference that forms d / rho is then
 * no better than the library below rho = 1e-2 L. */
static int extended_precision(void) {
  volatile long double one = 1.0L, tiny = 1e-19L;
  return one + tiny != one;
}

static void gen_near_intersection(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12010);
  const double rhos[] = {1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14};
  const int extended = extended_precision();
  if (!extended)
    printf("    (long double is not extended at run time, e.g. under valgrind: the rows "
           "below 1e-2 L check outcomes and finiteness only)\n");
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
      config c0;
      init_config(&c0, ka, kb, (ka + kb) % 2, 1e3, (ka + 2 * kb) % 3 == 0);
      unit_crossing(&rng, &c0);
      /* the intersecting crossing and the unit normal */
      static result r;
      b2b_params *p = make_params(&c0, B2B_TANGENT_EXACT);
      lib_call(p, &c0, &r);
      double d[3], n[3];
      for (int i = 0; i < 3; ++i)
        d[i] = r.info[B2B_INFO_POINT_A + i] - r.info[B2B_INFO_POINT_B + i];
      for (int i = 0; i < 3; ++i) n[i] = r.info[B2B_INFO_NORMAL + i];
      move_b(c0.X, d);
      const double L = pair_length(&c0);
      /* the reference tangent at 1e-4 L and 2e-4 L, long double */
      static double k1[576], k2[576], kx[576];
      static result q1, q2;
      config c1 = c0, c2 = c0;
      double v[3];
      for (int i = 0; i < 3; ++i) v[i] = -1e-4 * L * n[i];
      move_b(c1.X, v);
      for (int i = 0; i < 3; ++i) v[i] = -2e-4 * L * n[i];
      move_b(c2.X, v);
      ref_call(p, &c1, B2B_AD_LONG_DOUBLE, &q1);
      ref_call(p, &c2, B2B_AD_LONG_DOUBLE, &q2);
      b2b_params_destroy(&p);
      memcpy(k1, q1.K, sizeof k1);
      memcpy(k2, q2.K, sizeof k2);
      for (size_t e = 0; e < sizeof rhos / sizeof *rhos; ++e) {
        const double rho = rhos[e];
        config c = c0;
        for (int i = 0; i < 3; ++i) v[i] = -rho * L * n[i];
        move_b(c.X, v);
        c.tol_r = TOL_R + 32 * EPS / rho;
        c.tol_k = TOL_K + 64 * EPS / rho;
        if (rho < 1e-4) {
          const double t = (rho - 1e-4) / 1e-4;
          for (int i = 0; i < 576; ++i) kx[i] = k1[i] + t * (k2[i] - k1[i]);
          c.k_ref = kx;
          /* the extrapolation is good to about K'' (1e-4 L)^2: about 1e-6
           * for the curved weighted x midpoint pairs, where the library
           * differs from it by 1.1e-6 at rho = 1e-6 and 1e-8 L alike (not
           * growing with L / rho, as a rounding error would) */
          c.tol_k = fmax(c.tol_k, 2e-6);
        }
        if (!extended && rho < 1e-2) c.tol_k = c.tol_r = HUGE_VAL;
        c.allowed = rho < 1e-13 ? OK_(B2B_CONTACT_NO_NORMAL) : OK_(B2B_CONTACT_ACTIVE);
        name(&c, "axes %.0e L apart", rho);
        judge(&c, NULL);
      }
    }
}

/* Coincident nodes of both beams at the crossing: two beams of two segments
 * each (plane curves, curvature up to 0.3, elements 0.7 .. 1.3, crossing at
 * 30..90 degrees) whose joints lie on one vertical line: the joint is a node
 * of both beams (linear and nodal kinds; for the midpoint kind the joint is
 * an element midpoint), the axes 0.3 apart there. Of the four segment
 * pairs exactly one owns the point (b2b_pair.h: a joint belongs to the next
 * segment) and is ACTIVE, the other three OUTSIDE; with B lifted onto A
 * (the axes meeting at the joint) all four are NO_NORMAL without a history,
 * and with each pair's history from the step before, one ACTIVE on the
 * history's normal, three OUTSIDE. Criterion TOL (plus -f' G G^T where the axes meet). */
static void beam_patch(int kind, int seg, double nodes[5][3], double patch[12]) {
  for (int s = 0; s < 4; ++s) {
    /* nodal and linear kinds: segment seg (1 or 2) is nodes seg .. seg+1,
     * patch nodes seg-1 .. seg+2; the midpoint kind: centred on node seg */
    const int node = seg - 1 + s;
    const int used = kind == B2B_CURVE_LINEAR ? (s == 1 || s == 2)
                     : kind == B2B_CURVE_HERMITE_MIDPOINT ? s < 3
                                                         : 1;
    for (int i = 0; i < 3; ++i) patch[3 * s + i] = used && node <= 4 ? nodes[node][i] : NAN;
  }
}

static void beam_nodes(tst_rng *rng, int kind, double phi, double z, double nodes[5][3]) {
  if (kind > B2B_CURVE_HERMITE_NODAL_WEIGHTED) tst_no_expectation("beam_nodes", kind);
  const double h = tst_uniform(rng, 0.7, 1.3), kappa = tst_uniform(rng, -0.3, 0.3);
  /* nodal and linear kinds: the joint is node 2 at t = 0; midpoint: the
   * midpoint of nodes 1 and 2 at t = 0 (nodes at t = -1.5h .. 2.5h) */
  const double shift = kind == B2B_CURVE_HERMITE_MIDPOINT ? 1.5 : 2.0;
  const double y0 = kind == B2B_CURVE_HERMITE_MIDPOINT ? 0.125 * kappa * h * h : 0.0;
  for (int j = 0; j < 5; ++j) {
    const double t = (j - shift) * h, y = 0.5 * kappa * t * t - y0;
    nodes[j][0] = cos(phi) * t - sin(phi) * y;
    nodes[j][1] = sin(phi) * t + cos(phi) * y;
    nodes[j][2] = z;
  }
}

static void gen_joints(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12011);
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (int fr = 0; fr < 2; ++fr) {
        double A[5][3], B[5][3];
        beam_nodes(&rng, ka, 0.0, 0.0, A);
        const double phi = tst_uniform(&rng, 30, 90) * kPi / 180.0;
        beam_nodes(&rng, kb, phi, -0.3, B);
        config c[4];
        static result first[4];
        for (int stage = 0; stage < 3; ++stage) { /* 0.3 apart; meet, fresh; meet, history */
          int active = 0, owner = -1;
          for (int q = 0; q < 4; ++q) {
            const int sa = 1 + q / 2, sb = 1 + q % 2;
            if (stage == 0) {
              init_config(&c[q], ka, kb, (ka + kb + fr) % 2, 1e3, fr);
              beam_patch(ka, sa, A, c[q].X);
              beam_patch(kb, sb, B, c[q].X + 12);
              c[q].allowed = OK_(B2B_CONTACT_ACTIVE) | OK_(B2B_CONTACT_OUTSIDE);
            } else {
              for (int k = 4; k < 8; ++k)
                if (!isnan(c[q].X[3 * k + 2])) c[q].X[3 * k + 2] = 0.0;
              memset(c[q].hist, 0, sizeof c[q].hist);
              c[q].allowed = OK_(B2B_CONTACT_NO_NORMAL);
              if (stage == 2) {
                memcpy(c[q].hist, first[q].hist, sizeof c[q].hist);
                c[q].allowed = OK_(B2B_CONTACT_ACTIVE) | OK_(B2B_CONTACT_OUTSIDE);
                c[q].intersecting = 1;
              }
            }
            name(&c[q], "joint of both beams, segments %d/%d, %s", sa, sb,
                 stage == 0 ? "0.3 apart" : stage == 1 ? "meeting, fresh" : "meeting, history");
            result r;
            judge(&c[q], &r);
            if (stage == 0) first[q] = r;
            if (r.rc == B2B_OK && r.status == B2B_CONTACT_ACTIVE) {
              ++active;
              owner = q;
            }
          }
          if (stage != 1 && (active != 1 || owner != 3))
            violation("%s: %d active pairs (the owner: %d), expected one, the pair of the "
                      "segments after the joint",
                      c[0].what, active, owner);
        }
      }
}

/* Exactly folded or degenerate patches, on beam A and on beam B (the other
 * beam a straight crossing): nodal kinds x1 = x3 or x2 = x4 (FOLDED: "no
 * tangent direction at a node"), x1 = x2, x2 = x3, x3 = x4 (COINCIDENT);
 * the midpoint kind x1 = x3 (FOLDED, a hairpin), x1 = x2, x2 = x3
 * (COINCIDENT); the linear kind x2 = x3. The outputs untouched and the
 * message naming the beam. */
static void gen_folded(void) {
  static const struct {
    int family; /* 0 linear, 1 midpoint, 2 nodal */
    int to, from; /* slot `to` := slot `from` */
    int code;
  } cases[] = {{0, 2, 1, B2B_ERR_COINCIDENT}, {1, 2, 0, B2B_ERR_FOLDED},
               {1, 0, 1, B2B_ERR_COINCIDENT}, {1, 2, 1, B2B_ERR_COINCIDENT},
               {2, 0, 2, B2B_ERR_FOLDED},     {2, 3, 1, B2B_ERR_FOLDED},
               {2, 0, 1, B2B_ERR_COINCIDENT}, {2, 2, 1, B2B_ERR_COINCIDENT},
               {2, 3, 2, B2B_ERR_COINCIDENT}};
  static const double good[12] = {-1.3, 0.1, 0, -0.4, 0, 0, 0.5, 0.1, 0.05, 1.4, 0.3, 0};
  static const double other[12] = {0.1, -1.5, 0.3, 0.05, -0.5, 0.3, 0, 0.5, 0.3, -0.1, 1.4, 0.3};
  for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k)
    for (int beam = 0; beam < 2; ++beam)
      for (size_t q = 0; q < sizeof cases / sizeof *cases; ++q) {
        int family = 2;
        switch (k) {
          case B2B_CURVE_LINEAR: family = 0; break;
          case B2B_CURVE_HERMITE_MIDPOINT: family = 1; break;
          case B2B_CURVE_HERMITE_NODAL:
          case B2B_CURVE_HERMITE_NODAL_WEIGHTED: family = 2; break;
          default: tst_no_expectation("gen_folded", k);
        }
        if (cases[q].family != family) continue;
        config c;
        init_config(&c, beam ? B2B_CURVE_LINEAR : k, beam ? k : B2B_CURVE_LINEAR,
                    (int)(q % 2), 1e3, (int)(q % 2));
        double *folded = c.X + 12 * beam, *straight = c.X + 12 * (1 - beam);
        memcpy(folded, good, sizeof good);
        memcpy(straight, other, sizeof other);
        for (int i = 0; i < 3; ++i) folded[3 * cases[q].to + i] = folded[3 * cases[q].from + i];
        c.allowed = ERR_(cases[q].code);
        c.msg_has = beam ? "beam B" : "beam A";
        name(&c, "x%d = x%d on beam %c", cases[q].to + 1, cases[q].from + 1, beam ? 'B' : 'A');
        judge(&c, NULL);
      }
}


/* B crossing a given A: a random patch of B's kind (elements 0.6 .. 1.4,
 * turning up to 0.3 per node), turned so that its tangent at eta* makes
 * angle_deg with A's tangent at xi*, and placed dist from A's point along
 * their common normal. */
static void crossing_on(tst_rng *rng, config *c, double xi_star, double eta_star,
                        double angle_deg, double dist) {
  double B[12], xa[9], xb[9], ta[3], tb[3], u[3], r[3], nn[3];
  tst_random_patch(rng, 1.0, 0.3, B);
  tst_eval(c->spec.kind[0], c->spec.start_rule[0], c->spec.end_rule[0], c->X, c->tang, xi_star,
           xa, NULL, NULL);
  tst_eval(c->spec.kind[1], B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, B, NULL, eta_star, xb, NULL,
           NULL);
  for (int i = 0; i < 3; ++i) {
    ta[i] = xa[3 + i] / norm3(xa + 3);
    tb[i] = xb[3 + i] / norm3(xb + 3);
  }
  do {
    for (int i = 0; i < 3; ++i) r[i] = tst_uniform(rng, -1, 1);
    cross3(ta, r, u);
  } while (norm3(u) < 0.3);
  const double lu = norm3(u);
  for (int i = 0; i < 3; ++i) u[i] /= lu;
  cross3(ta, u, nn); /* unit, normal to ta and to the target direction */
  const double th = angle_deg * kPi / 180.0;
  double target[3], e1[3], e2[3], f2[3];
  for (int i = 0; i < 3; ++i) target[i] = cos(th) * ta[i] + sin(th) * u[i];
  /* the rotation taking the frame (tb, e1, e2) to (target, nn, target x nn) */
  double w[3];
  for (int i = 0; i < 3; ++i) w[i] = tst_uniform(rng, -1, 1);
  cross3(tb, w, e1);
  const double l1 = norm3(e1);
  for (int i = 0; i < 3; ++i) e1[i] /= l1;
  cross3(tb, e1, e2);
  cross3(target, nn, f2);
  for (int k = 0; k < 4; ++k) {
    double y[3], a0 = 0, a1 = 0, a2 = 0;
    for (int i = 0; i < 3; ++i) y[i] = B[3 * k + i] - xb[i];
    for (int i = 0; i < 3; ++i) {
      a0 += tb[i] * y[i];
      a1 += e1[i] * y[i];
      a2 += e2[i] * y[i];
    }
    for (int i = 0; i < 3; ++i)
      c->X[12 + 3 * k + i] = xa[i] - dist * nn[i] + a0 * target[i] + a1 * nn[i] + a2 * f2[i];
  }
  if (c->spec.kind[1] == B2B_CURVE_LINEAR)
    for (int i = 0; i < 3; ++i) c->X[12 + i] = c->X[21 + i] = NAN;
  if (c->spec.kind[1] == B2B_CURVE_HERMITE_MIDPOINT)
    for (int i = 0; i < 3; ++i) c->X[21 + i] = NAN;
}

/* Nearly folded patches: a hairpin at x2, x1 = x3 + delta u (u normal to
 * the element x2 x3, of length 1), delta = 1e-2 .. 1e-12 and 2e-16; for the nodal
 * kinds also at x3 (x4 = x2 + delta u); beam A, every kind of B crossing it
 * at xi = -+0.4. Any contact status is documented here (a hairpin is
 * strongly curved: the crossing may be OUTSIDE); on ACTIVE the criterion is
 * TOL + 4 eps / delta for tangent and residual. Why: the tangent direction
 * at the fold node is that of a vector of length delta formed from the
 * nodes (x3 - x1 for the nodal kind; l23^2 (x2 - x1) + l12^2 (x3 - x2) for
 * the weighted kind, whose component along the element, (l12^2 - l23^2),
 * is delta^2 while l12^2 and l23^2 are 1): a perturbation of the nodes by
 * their own rounding, eps, turns it by eps / delta, and residual and tangent
 * with it. That is the conditioning of the inputs; the weighted kind meets
 * it (2.2 eps / delta at delta = 1e-8, as does the reference in double: its
 * l12^2 rounds the same way), the nodal kind does better (x3 - x1 is exact),
 * and the midpoint kind has no direction to normalize (it is linear in the
 * nodes). Below delta ~ 1e-8, delta^2 is lost in 1 + delta^2 altogether and
 * the direction is the normal u exactly: the error drops again. And
 * delta = 2e-16 at x2, x1 within rounding of x3 = (1, 0, 0) ("below
 * rounding of the coordinates", b2b.h): ERR_FOLDED. */
static void gen_nearly_folded(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12012);
  const double deltas[] = {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 2e-16};
  for (size_t q = 0; q < sizeof deltas / sizeof *deltas; ++q)
    for (int ka = 1; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int end = 0; end < 2; ++end) {
          /* 2e-16 is rounding next to x3 = (1, 0, 0), not next to x2 = 0 */
          if (end && deltas[q] < 4 * EPS) continue;
          config c;
          init_config(&c, ka, kb, (int)((ka + kb + q) % 2), 1e3, (int)((kb + q) % 2));
          const double x2[3] = {0, 0, 0}, x3[3] = {1, 0, 0}, u[3] = {0, 1, 0};
          for (int i = 0; i < 3; ++i) {
            c.X[3 + i] = x2[i];
            c.X[6 + i] = x3[i];
            c.X[i] = x3[i] + deltas[q] * u[i];
            c.X[9 + i] = x2[i] - 0.7 * u[i] + 0.3 * x3[i];
          }
          if (end && ka != B2B_CURVE_HERMITE_MIDPOINT)
            for (int i = 0; i < 3; ++i) {
              c.X[i] = x3[i] - 0.6 * u[i];
              c.X[9 + i] = x2[i] + deltas[q] * u[i];
            }
          if (ka == B2B_CURVE_HERMITE_MIDPOINT)
            for (int i = 0; i < 3; ++i) c.X[9 + i] = NAN;
          if (deltas[q] >= 4 * EPS) {
            crossing_on(&rng, &c, end ? 0.4 : -0.4, tst_uniform(&rng, -0.3, 0.3),
                        tst_uniform(&rng, 40, 90), 0.3);
          } else { /* A has no tangent to cross: a fixed straight B */
            static const double other[12] = {0.1,  -1.5, 0.3, 0.05, -0.5, 0.3,
                                              0, 0.5, 0.3, -0.1, 1.4,  0.3};
            memcpy(c.X + 12, other, sizeof other);
            for (int i = 0; i < 3; ++i) {
              if (kb == B2B_CURVE_LINEAR) c.X[12 + i] = c.X[21 + i] = NAN;
              if (kb == B2B_CURVE_HERMITE_MIDPOINT) c.X[21 + i] = NAN;
            }
          }
          c.allowed = OK_(B2B_CONTACT_ACTIVE) | OK_(B2B_CONTACT_OPEN) |
                      OK_(B2B_CONTACT_OUTSIDE) | OK_(B2B_CONTACT_PARALLEL) |
                      OK_(B2B_CONTACT_NOT_CONVERGED);
          c.agree = 0;
          c.tol_k = c.tol_r = TOL_K + 4 * EPS / deltas[q];
          if (deltas[q] < 4 * EPS) { /* nodes within rounding of each other (b2b.h) */
            c.allowed = ERR_(B2B_ERR_FOLDED);
            c.msg_has = "beam A";
          }
          name(&c, "fold %.0e at %s", deltas[q], end ? "x3" : "x2");
          judge(&c, NULL);
        }
}

/* A cusp: a nodal segment whose host end tangent at x2 points against its
 * chord stops and turns back inside (x' = 0 at xi_c = (1 - sqrt 10) / 3 for
 * the chord (0,0,0)-(1,0,0)). A straight beam crossing it at 90 degrees at
 * xi_c + 0.02 q |q|, q = -8..8, the axes 0.15 apart: PARALLEL where the
 * closest point is the cusp (b2b_pair.h: "a cusp (a centreline whose
 * tangent vanishes at the closest point)"), OUTSIDE beyond the segment,
 * else ACTIVE (or OPEN) within TOL: away from the cusp the crossing is
 * well-conditioned. */
static void gen_cusp(void) {
  tst_rng rng;
  tst_rng_seed(&rng, 12013);
  const double xi_c = (1.0 - sqrt(10.0)) / 3.0;
  for (int k = B2B_CURVE_HERMITE_NODAL; k < B2B_CURVE_KIND_COUNT; ++k)
    for (int q = -8; q <= 8; ++q)
      for (int law = 0; law < B2B_LAW_COUNT; ++law) {
        config c;
        init_config(&c, k, B2B_CURVE_LINEAR, law, 1e3, (q + law) % 2 != 0);
        c.spec.start_rule[0] = B2B_END_TANGENT;
        c.spec.end_rule[0] = B2B_END_REFLECT;
        c.spec.radius[0] = c.spec.radius[1] = 0.1;
        const double tangents[12] = {-1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0};
        memcpy(c.tang, tangents, sizeof tangents);
        const double A[12] = {NAN, NAN, NAN, 0, 0, 0, 1, 0, 0, NAN, NAN, NAN};
        memcpy(c.X, A, sizeof A);
        double xc[9];
        tst_eval(k, B2B_END_TANGENT, B2B_END_REFLECT, c.X, c.tang, xi_c + 0.02 * q * abs(q),
                 xc, NULL, NULL);
        const double B[12] = {NAN, NAN, NAN, xc[0], -1, 0.15, xc[0], 1, 0.15, NAN, NAN, NAN};
        memcpy(c.X + 12, B, sizeof B);
        c.allowed = OK_(B2B_CONTACT_ACTIVE) | OK_(B2B_CONTACT_OPEN) | OK_(B2B_CONTACT_OUTSIDE) |
                    OK_(B2B_CONTACT_PARALLEL);
        c.agree = 0;
        name(&c, "cusp, crossing at xi_c %+.3f", 0.02 * q * abs(q));
        judge(&c, NULL);
      }
  (void)rng;
}

/* ------------------------------------------------------------ the table */

typedef struct {
  const char *name;
  const char *outcomes;  /* the documented outcomes (summary) */
  const char *criterion; /* on ACTIVE (summary; the formulas are in the generators) */
  void (*generate)(void);
} extreme_class;

static const extreme_class kClasses[] = {
    {"angles 90..0.6 deg", "ACTIVE", "TOL (sin 2deg/sin theta)^2", gen_angles},
    {"angles 0.4 deg..1e-10 rad, default parallel_angle", "PARALLEL", "-",
     gen_angles_below_threshold},
    {"angles 0.4 deg..1e-10 rad, parallel_angle 0",
     "ACTIVE, NOT_CONVERGED, OUTSIDE; PARALLEL if sin theta < 2e-6", "TOL (sin 2deg/sin theta)^2",
     gen_angles_host_zero},
    {"offsets 1e2..1e12", "ACTIVE", "TOL; exact translation: = origin's to 64 eps",
     gen_offsets},
    {"scales 2^-300..2^300, 1e-90..1e90", "ACTIVE", "TOL; power of 2: = unit pair's, bit for bit",
     gen_scales},
    {"penalties 0, 1e-6..1e15, 1e300", "ACTIVE (0: OPEN)", "TOL; = (eps/1e3) x at 1e3 to 64 eps",
     gen_penalties},
    {"force beyond doubles (penalty 1e308)", "ERR_RANGE or ACTIVE", "TOL", gen_overflow},
    {"penetration beyond r_A + r_B", "ACTIVE, g < -(r_A + r_B)", "TOL", gen_penetration},
    {"axes intersecting (band, exact)", "fresh NO_NORMAL; history ACTIVE", "TOL + (-f' G G^T)",
     gen_intersection},
    {"axes 1e-1..1e-14 L apart", "ACTIVE; NO_NORMAL in the band",
     "R: TOL + 32 eps L/rho; K: TOL + 64 eps L/rho", gen_near_intersection},
    {"coincident nodes of both beams at the crossing", "one ACTIVE, 3 OUTSIDE; NO_NORMAL",
     "TOL", gen_joints},
    {"folded patches (exact)", "ERR_FOLDED / ERR_COINCIDENT", "-", gen_folded},
    {"nearly folded patches 1e-2..1e-12, 2e-16", "any contact status; 2e-16: ERR_FOLDED",
     "TOL + 4 eps/delta",
     gen_nearly_folded},
    {"cusp (host tangent against the chord)", "any contact status", "TOL", gen_cusp},
};
#define N_CLASSES ((int)(sizeof kClasses / sizeof *kClasses))

static void outcomes_seen(char *buf, size_t len) {
  buf[0] = '\0';
  for (int o = 0; o < N_OUTCOMES; ++o)
    if (rec.seen[o]) {
      const size_t used = strlen(buf);
      snprintf(buf + used, len - used, "%s%s %d", used ? ", " : "", outcome_name(o), rec.seen[o]);
    }
}

static void ratio_text(char *buf, size_t len, double r, int n) {
  if (n == 0) snprintf(buf, len, "-");
  else snprintf(buf, len, "%.2g", r);
}

START_TEST(extreme_class_test) {
  const extreme_class *x = &kClasses[_i];
  memset(&rec, 0, sizeof rec);
  x->generate();
  char seen[300], lib[32], ad[32], tw[32];
  outcomes_seen(seen, sizeof seen);
  ratio_text(lib, sizeof lib, rec.worst, rec.n_active);
  ratio_text(ad, sizeof ad, rec.worst_ad, rec.n_active);
  ratio_text(tw, sizeof tw, rec.worst_twin, rec.n_twin);
  printf("| %s | %d | %s | %s | %s | %s | %s |\n", x->name, rec.n, seen, x->criterion, lib, ad, tw);
  if (rec.n_active) printf("    worst: %s\n", rec.worst_what);
  if (rec.n_twin) printf("    worst twin: %s\n", rec.worst_twin_what);
  if (rec.disagree) printf("    contact status differs from the reference's in %d\n", rec.disagree);
  if (rec.bad) printf("    %d violations, the first: %s\n", rec.bad, rec.first_bad);
  fflush(stdout);
  if (rec.worst > 1.0) dump_config(&worst_config, "the worst error");
  ck_assert_msg(rec.bad == 0, "%s: %d violations of the documented outcomes; the first: %s",
                x->name, rec.bad, rec.first_bad);
  ck_assert_msg(rec.worst <= 1.0, "%s: the worst error is %.3g times its criterion: %s", x->name,
                rec.worst, rec.worst_what);
  ck_assert_msg(rec.worst_twin <= 1.0, "%s: a transformed twin differs by %.3g times its "
                "criterion: %s", x->name, rec.worst_twin, rec.worst_twin_what);
  ck_assert_msg(rec.n > 0, "%s: no configuration", x->name);
}
END_TEST

int main(void) {
  printf("Extremes of the contact element (TOL = %g; errors as fractions of their criterion; "
         "\"AD double\": the AD reference in double against the same criterion; twin: the "
         "transformed pair against the untransformed)\n\n", TOL_K);
  printf("| class | configurations | outcomes seen | criterion | worst library error | AD "
         "double | twin |\n|---|---:|---|---|---:|---:|---:|\n");
  fflush(stdout);
  Suite *s = suite_create("pair_extremes");
  TCase *tc = tcase_create("extremes");
  tcase_set_timeout(tc, 120);
  tcase_add_loop_test(tc, extreme_class_test, 0, N_CLASSES);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
