/* The line-contact element (b2b_pair_eval_line, b2b_pair.h "Line contact";
 * doc/line-contact.md).
 *
 * Configurations: seeded random curved patches of every pair of curve kinds
 * touching at a small angle (0 to 4 degrees: the axes meet nearly parallel,
 * so part of A's segment penetrates B), and straight beams for the closed
 * forms.
 *   - tangent against central differences of the residual (steps h and h/2,
 *     one Richardson step), relative error <= 1e-6, both normal laws; the
 *     residual against differences of line_info[ENERGY] (it is the gradient
 *     of the potential sum w_i J_i pi(g_i)); frictionless tangent symmetric;
 *     a configuration where a perturbation changes some point's status is
 *     skipped (the integrand has a kink there), and at least 3/4 of them
 *     must be checked;
 *   - with friction in stick and in slip (the committed histories of a
 *     previous evaluation held fixed);
 *   - ALL_ANGLE at crossing angles inside the blending range: the blended
 *     tangent (with the weights' derivatives) against differences;
 *   - the force is continuous in the crossing angle across both ends of the
 *     blending range (a sweep in 0.01 degree steps: no jump larger than the
 *     neighbouring increments allow);
 *   - friction read at B's surface: a rope turned round B's axis slips by
 *     r_B sin(delta); a rigid rotation of both beams slips to second order;
 *   - the "tangent" options: FD equals EXACT to 1e-6, SYMMETRIC is
 *     symmetric, MAIN is the main term (symmetric, differs from EXACT);
 *   - closed forms: parallel straight beams, force eps_L (r_A + r_B - d) L
 *     with every point active; B split at a joint under A (LINEAR and the
 *     smoothed kinds): the two pairs of B's segments own every point once
 *     and sum to the closed form; curved B of every kind: owned counts sum
 *     to n over B's segments;
 *   - Gauss rules, n = 1 .. 32: points are the roots of P_n, weights sum to 2;
 *   - b2b_pair_line_points: the default rule and "line_points";
 *   - bad input: every argument, outputs untouched. */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pair_support.h"

#define TOL 1e-6
#define RADIUS 0.1
#define EPS_N 1e3
#define EPS_L 2e3
#define MU 0.3
#define EPS_T 8e2
#define EPS_LT 1.5e3
#define MAXP 32
#define MAXH ((MAXP + 1) * 12)

static const double kPi = 3.14159265358979323846;

/* ------------------------------------------------------------- helpers */

static b2b_params *line_params(int law, int type, double mu, int tangent) {
  const tst_line_spec spec = {EPS_N, EPS_L, mu, EPS_T, EPS_LT};
  return tst_line_params(law, type, tangent, &spec);
}

typedef struct {
  int status;
  double li[16];
  double R[24];
  double pinfo[32 * MAXP];
} line_out;

/* b2b_pair_eval_line; fails the test unless B2B_OK. hist_old NULL: fresh. */
static int eval_line(const b2b_params *p, const tst_pair_spec *s, const double X[24], int n,
                     const double *hist_old, double *hist_new, line_out *o, double *K) {
  const int seg[6] = {s->kind[0], s->start_rule[0], s->end_rule[0],
                      s->kind[1], s->start_rule[1], s->end_rule[1]};
  static double fresh[MAXH];
  double scratch[MAXH];
  const int len = (n + 1) * tst_history_len(p);
  char msg[B2B_ERRMSG_LEN] = "";
  const int st = b2b_pair_eval_line(p, seg, X, NULL, s->radius, n, hist_old ? hist_old : fresh,
                                    hist_new ? hist_new : scratch, len, &o->status, o->li,
                                    o->pinfo, o->R, K, 24, msg, sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_pair_eval_line returned %d: %s", st, msg);
  return o->status;
}

/* A signature of every point's status and friction state: a perturbation
 * that changes it crosses a kink of the integrand. */
static long signature(const line_out *o, int n) {
  long sig = o->status;
  for (int i = 0; i < n; ++i)
    sig = sig * 7 + (long)o->pinfo[32 * i + B2B_INFO_FRICTION_STATE] * 3 +
          (o->pinfo[32 * i + B2B_INFO_NORMAL_FORCE] > 0);
  return sig;
}

/* Central differences of the residual and of the energy, hist held fixed;
 * 0 if a perturbation changes the signature (the caller skips). */
static int fd_line(const b2b_params *p, const tst_pair_spec *s, const double X[24], int n,
                   const double *hist, long sig, double h, double Kfd[576], double Rfd[24]) {
  memset(Kfd, 0, 576 * sizeof(double));
  memset(Rfd, 0, 24 * sizeof(double));
  for (int a = 0; a < 24; ++a) {
    if (isnan(X[a])) continue;
    double dR[2][24], dE[2];
    for (int k = 0; k < 2; ++k) {
      const double st = k ? 0.5 * h : h;
      double Xp[24], Xm[24];
      static line_out op, om;
      memcpy(Xp, X, sizeof Xp);
      memcpy(Xm, X, sizeof Xm);
      Xp[a] += st;
      Xm[a] -= st;
      eval_line(p, s, Xp, n, hist, NULL, &op, NULL);
      eval_line(p, s, Xm, n, hist, NULL, &om, NULL);
      if (signature(&op, n) != sig || signature(&om, n) != sig) return 0;
      for (int r = 0; r < 24; ++r) dR[k][r] = (op.R[r] - om.R[r]) / (2 * st);
      dE[k] = (op.li[B2B_LINE_INFO_ENERGY] - om.li[B2B_LINE_INFO_ENERGY]) / (2 * st);
    }
    for (int r = 0; r < 24; ++r) Kfd[r + 24 * a] = (4 * dR[1][r] - dR[0][r]) / 3;
    Rfd[a] = (4 * dE[1] - dE[0]) / 3;
  }
  return 1;
}

static void nearly_parallel(tst_rng *rng, tst_pair_spec *s, int kind_a, int kind_b,
                            double max_angle, double X[24]) {
  for (int b = 0; b < 2; ++b) {
    s->kind[b] = b ? kind_b : kind_a;
    s->start_rule[b] = s->end_rule[b] = B2B_END_NEIGHBOUR;
    s->radius[b] = RADIUS;
  }
  const double angle = tst_uniform(rng, 0, max_angle);
  tst_crossing(rng, s, 0.06, angle, tst_uniform(rng, -0.3, 0.3), tst_uniform(rng, -0.3, 0.3),
               2 * RADIUS - tst_uniform(rng, 0.005, 0.02), X);
}

/* ----------------------------------------------------------------- tests */

START_TEST(gauss_rules_exact) {
  /* Through the element: two straight parallel beams of the linear kind, A's
   * length element constant, so the integrated force is eps_L * pen * L and
   * the length L for every n (the weights sum to 2); the points are the
   * roots of the Legendre polynomial P_n. */
  b2b_params *p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, 0, B2B_TANGENT_EXACT);
  tst_pair_spec s = {{B2B_CURVE_LINEAR, B2B_CURVE_LINEAR},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {RADIUS, RADIUS}};
  double X[24];
  for (int k = 0; k < 24; ++k) X[k] = NAN;
  const double L = 1.3, pen = 0.01, d = 2 * RADIUS - pen;
  X[3] = 0, X[4] = 0, X[5] = d, X[6] = L, X[7] = 0, X[8] = d;        /* A */
  X[15] = -1, X[16] = 0, X[17] = 0, X[18] = 3, X[19] = 0, X[20] = 0; /* B, longer */
  double worst = 0.0;
  for (int n = 1; n <= MAXP; ++n) {
    line_out o;
    ck_assert_int_eq(eval_line(p, &s, X, n, NULL, NULL, &o, NULL), B2B_CONTACT_ACTIVE);
    ck_assert_int_eq((int)o.li[B2B_LINE_INFO_ACTIVE_POINTS], n);
    const double F = o.li[B2B_LINE_INFO_NORMAL_FORCE];
    worst = fmax(worst, fabs(F - EPS_L * pen * L) / (EPS_L * pen * L));
    ck_assert_msg(fabs(o.li[B2B_LINE_INFO_LENGTH] - L) <= 1e-13 * L, "n %d: length %.17g", n,
                  o.li[B2B_LINE_INFO_LENGTH]);
    /* the points are the roots of P_n (by the recurrence, here), in
     * increasing order, symmetric about 0 */
    for (int i = 0; i < n; ++i) {
      const double xi = o.pinfo[32 * i + B2B_INFO_XI];
      double p0 = 1.0, p1 = xi;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * xi * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      ck_assert_msg(fabs(p1) <= 1e-13 * n * n, "n %d: P_n(xi_%d = %.17g) = %g", n, i, xi, p1);
      ck_assert(i == 0 || xi > o.pinfo[32 * (i - 1) + B2B_INFO_XI]);
      ck_assert(fabs(xi + o.pinfo[32 * (n - 1 - i) + B2B_INFO_XI]) <= 1e-15);
    }
    /* equal forces: the residual on A's nodes is -F/2 each along z */
    ck_assert_msg(fabs(o.R[5] + 0.5 * F) <= 1e-12 * F && fabs(o.R[8] + 0.5 * F) <= 1e-12 * F,
                  "n %d: A's nodal forces %g %g, F %g", n, o.R[5], o.R[8], F);
  }
  ck_assert_msg(worst <= 1e-13, "integrated force vs eps_L pen L: rel. error %.2e", worst);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(fd_frictionless_all_kinds) {
  tst_rng rng;
  tst_rng_seed(&rng, 18001);
  int checked = 0, tried = 0;
  double worst_k = 0, worst_r = 0, worst_sym = 0;
  for (int law = 0; law < B2B_LAW_COUNT; ++law) {
    b2b_params *p = line_params(law, B2B_CONTACT_TYPE_LINE, 0, B2B_TANGENT_EXACT);
    for (int c = 0; c < 2 * B2B_CURVE_KIND_COUNT * B2B_CURVE_KIND_COUNT; ++c) {
      tst_pair_spec s;
      double X[24];
      nearly_parallel(&rng, &s, TST_KIND_A(c), TST_KIND_B(c), 4.0, X);
      /* quick mode: half of the same configurations, every kind pair once */
      if (tst_quick() && (c + c / 16) % 2) continue;
      const int n = 3 + c % 6;
      static double K[576], Kfd[576];
      line_out o;
      if (eval_line(p, &s, X, n, NULL, NULL, &o, K) != B2B_CONTACT_ACTIVE) continue;
      ++tried;
      ck_assert_msg(o.li[B2B_LINE_INFO_SYMMETRIC] == 1.0, "frictionless not symmetric");
      double Rfd[24];
      if (!fd_line(p, &s, X, n, NULL, signature(&o, n), 1e-6, Kfd, Rfd)) continue;
      ++checked;
      const double F = o.li[B2B_LINE_INFO_NORMAL_FORCE];
      const double ek = tst_rel_diff(K, Kfd, 576, 1e-10 * F);
      const double er = tst_rel_diff(o.R, Rfd, 24, 1e-10 * F);
      const double as = tst_asymmetry(K);
      worst_k = fmax(worst_k, ek);
      worst_r = fmax(worst_r, er);
      worst_sym = fmax(worst_sym, as);
      ck_assert_msg(ek <= TOL, "law %d, %s x %s, n %d: tangent vs FD rel. error %.2e", law,
                    tst_kind_name(s.kind[0]), tst_kind_name(s.kind[1]), n, ek);
      ck_assert_msg(er <= TOL, "law %d, %s x %s: residual vs FD of the energy %.2e", law,
                    tst_kind_name(s.kind[0]), tst_kind_name(s.kind[1]), er);
      ck_assert_msg(as <= 1e-10, "frictionless tangent not symmetric: %.2e", as);
    }
    b2b_params_destroy(&p);
  }
  ck_assert_msg(tried >= 8 && 4 * checked >= 3 * tried, "only %d of %d checked", checked, tried);
  printf("line, frictionless: %d configurations, worst tangent %.2e, residual %.2e, "
         "asymmetry %.2e\n", checked, worst_k, worst_r, worst_sym);
}
END_TEST

/* Friction: commit a first evaluation, move B along A's axis by `slide`
 * (small: stick; larger: slip), FD with the committed histories fixed. */
START_TEST(fd_friction_stick_and_slip) {
  tst_rng rng;
  tst_rng_seed(&rng, 18002);
  int checked[3] = {0, 0, 0};
  double worst = 0;
  b2b_params *p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, MU, B2B_TANGENT_EXACT);
  const int hl = tst_history_len(p);
  ck_assert_int_eq(hl, 12);
  for (int c = 0; c < 4 * B2B_CURVE_KIND_COUNT * B2B_CURVE_KIND_COUNT; ++c) {
    tst_pair_spec s;
    double X[24], hist[MAXH];
    nearly_parallel(&rng, &s, TST_KIND_A(c), TST_KIND_B(c), 3.0, X);
    /* quick mode: half of the same configurations, every kind pair twice */
    if (tst_quick() && (c / 16) % 2) continue;
    const int n = 4 + c % 4;
    line_out o;
    if (eval_line(p, &s, X, n, NULL, hist, &o, NULL) != B2B_CONTACT_ACTIVE) continue;
    /* slide B along A's chord */
    const double slide = (c % 2) ? 1e-5 : 2e-2; /* stick; slip: eps_LT slide > mu f */
    double ax[3] = {X[6] - X[3], X[7] - X[4], X[8] - X[5]};
    const double l = sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
    for (int k = 12; k < 24; ++k)
      if (!isnan(X[k])) X[k] += slide * ax[k % 3] / l;
    static double K[576], Kfd[576];
    if (eval_line(p, &s, X, n, hist, NULL, &o, K) != B2B_CONTACT_ACTIVE) continue;
    const int state = o.li[B2B_LINE_INFO_SLIP_POINTS] > 0 ? 2 : 1;
    ck_assert_msg(o.li[B2B_LINE_INFO_STICK_POINTS] + o.li[B2B_LINE_INFO_SLIP_POINTS] ==
                      o.li[B2B_LINE_INFO_ACTIVE_POINTS],
                  "stick + slip != active points");
    double Rfd[24];
    if (!fd_line(p, &s, X, n, hist, signature(&o, n), 1e-6, Kfd, Rfd)) continue;
    const double F = o.li[B2B_LINE_INFO_NORMAL_FORCE];
    const double ek = tst_rel_diff(K, Kfd, 576, 1e-10 * F);
    worst = fmax(worst, ek);
    ck_assert_msg(ek <= TOL, "%s x %s, %s: tangent vs FD rel. error %.2e",
                  tst_kind_name(s.kind[0]), tst_kind_name(s.kind[1]),
                  state == 2 ? "slip" : "stick", ek);
    if (state == 2)
      ck_assert_msg(o.li[B2B_LINE_INFO_DISSIPATION] > 0, "slip without dissipation");
    ++checked[state];
  }
  ck_assert_msg(checked[1] >= 4 && checked[2] >= 4, "stick %d, slip %d checked", checked[1],
                checked[2]);
  printf("line, friction: stick %d, slip %d configurations, worst tangent %.2e\n", checked[1],
         checked[2], worst);
  b2b_params_destroy(&p);
}
END_TEST

/* Two straight beams of the linear kind crossing at angle_deg (in the xy
 * plane, A above B by d at their middles). */
static void straight_crossing(double angle_deg, double d, double X[24]) {
  for (int k = 0; k < 24; ++k) X[k] = NAN;
  const double th = angle_deg * kPi / 180.0;
  X[3] = -0.6, X[4] = 0, X[5] = d, X[6] = 0.6, X[7] = 0, X[8] = d;
  X[15] = -0.8 * cos(th), X[16] = -0.8 * sin(th), X[17] = 0;
  X[18] = 0.8 * cos(th), X[19] = 0.8 * sin(th), X[20] = 0;
}

START_TEST(blended_fd_in_range) {
  /* curved beams crossing inside the blending range (5 .. 15 degrees) */
  tst_rng rng;
  tst_rng_seed(&rng, 18003);
  int checked = 0, tried = 0;
  double worst = 0;
  for (int fr = 0; fr < 2; ++fr) {
    b2b_params *p =
        line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, fr ? MU : 0, B2B_TANGENT_EXACT);
    for (int c = 0; c < B2B_CURVE_KIND_COUNT * B2B_CURVE_KIND_COUNT * 2; ++c) {
      tst_pair_spec s;
      double X[24];
      for (int b = 0; b < 2; ++b) {
        s.kind[b] = b ? TST_KIND_B(c) : TST_KIND_A(c);
        s.start_rule[b] = s.end_rule[b] = B2B_END_NEIGHBOUR;
        s.radius[b] = RADIUS;
      }
      tst_crossing(&rng, &s, 0.06, tst_uniform(&rng, 6, 14), tst_uniform(&rng, -0.2, 0.2),
                   tst_uniform(&rng, -0.2, 0.2), 2 * RADIUS - 0.01, X);
      /* quick mode: half of the same configurations, every kind pair once */
      if (tst_quick() && (c / 16 + fr) % 2) continue;
      const int n = 6;
      static double K[576], Kfd[576];
      line_out o;
      if (eval_line(p, &s, X, n, NULL, NULL, &o, K) != B2B_CONTACT_ACTIVE) continue;
      ++tried;
      const double lam = o.li[B2B_LINE_INFO_POINT_WEIGHT];
      ck_assert_msg(lam > 0 && lam < 1, "angle in range but point weight %g", lam);
      ck_assert_msg(o.li[B2B_LINE_INFO_SYMMETRIC] == 0.0, "blend reported symmetric");
      double Rfd[24];
      if (!fd_line(p, &s, X, n, NULL, signature(&o, n), 1e-6, Kfd, Rfd)) continue;
      ++checked;
      const double F = o.li[B2B_LINE_INFO_NORMAL_FORCE];
      const double ek = tst_rel_diff(K, Kfd, 576, 1e-10 * F);
      worst = fmax(worst, ek);
      ck_assert_msg(ek <= TOL, "%s x %s, friction %d: blended tangent vs FD %.2e",
                    tst_kind_name(s.kind[0]), tst_kind_name(s.kind[1]), fr, ek);
    }
    b2b_params_destroy(&p);
  }
  ck_assert_msg(tried >= 8 && 4 * checked >= 3 * tried, "only %d of %d checked", checked, tried);
  printf("blended: %d configurations, worst tangent %.2e\n", checked, worst);
}
END_TEST

START_TEST(force_continuous_in_angle) {
  /* straight beams, sweep the crossing angle through both ends of the
   * blending range; the normal force must change smoothly: no step much
   * larger than its neighbours' */
  b2b_params *p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, 0, B2B_TANGENT_EXACT);
  tst_pair_spec s = {{B2B_CURVE_LINEAR, B2B_CURVE_LINEAR},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {RADIUS, RADIUS}};
  const double edges[2] = {5.0, 15.0};
  for (int e = 0; e < 2; ++e) {
    double prev = -1, prev_step = 0, worst_jump = 0;
    for (int k = -50; k <= 50; ++k) {
      double X[24];
      straight_crossing(edges[e] + 0.01 * k, 2 * RADIUS - 0.005, X);
      line_out o;
      ck_assert_int_eq(eval_line(p, &s, X, 8, NULL, NULL, &o, NULL), B2B_CONTACT_ACTIVE);
      const double F = o.li[B2B_LINE_INFO_NORMAL_FORCE];
      if (prev >= 0) {
        const double step = fabs(F - prev);
        if (k > -49) worst_jump = fmax(worst_jump, step - 3 * prev_step);
        prev_step = step;
      }
      prev = F;
    }
    ck_assert_msg(worst_jump <= 1e-3 * prev, "force jumps by %g (force %g) near %g degrees",
                  worst_jump, prev, edges[e]);
  }
  /* at 3 degrees pure line, at 20 pure point */
  double X[24];
  line_out o;
  straight_crossing(3.0, 2 * RADIUS - 0.005, X);
  eval_line(p, &s, X, 8, NULL, NULL, &o, NULL);
  ck_assert(o.li[B2B_LINE_INFO_POINT_WEIGHT] == 0.0 && o.li[B2B_LINE_INFO_POINT_FORCE] == 0.0);
  straight_crossing(20.0, 2 * RADIUS - 0.005, X);
  eval_line(p, &s, X, 8, NULL, NULL, &o, NULL);
  ck_assert(o.li[B2B_LINE_INFO_POINT_WEIGHT] == 1.0);
  ck_assert_int_eq((int)o.li[B2B_LINE_INFO_ACTIVE_POINTS], 0);
  ck_assert_msg(fabs(o.li[B2B_LINE_INFO_NORMAL_FORCE] - EPS_N * 0.005) <= 1e-9,
                "pure point force %g", o.li[B2B_LINE_INFO_NORMAL_FORCE]);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(tangent_options) {
  tst_rng rng;
  tst_rng_seed(&rng, 18004);
  b2b_params *pe = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, MU, B2B_TANGENT_EXACT);
  b2b_params *pf = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, MU, B2B_TANGENT_FD);
  b2b_params *ps =
      line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, MU, B2B_TANGENT_SYMMETRIC);
  b2b_params *pm = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_ALL_ANGLE, MU, B2B_TANGENT_MAIN);
  int checked = 0;
  for (int c = 0; c < 12 && checked < 4; ++c) {
    tst_pair_spec s;
    double X[24];
    for (int b = 0; b < 2; ++b) {
      s.kind[b] = B2B_CURVE_HERMITE_NODAL;
      s.start_rule[b] = s.end_rule[b] = B2B_END_NEIGHBOUR;
      s.radius[b] = RADIUS;
    }
    tst_crossing(&rng, &s, 0.06, tst_uniform(&rng, 0, 12), 0, 0, 2 * RADIUS - 0.01, X);
    static double Ke[576], Kf[576], Ks[576], Km[576];
    line_out oe, of, os, om;
    if (eval_line(pe, &s, X, 6, NULL, NULL, &oe, Ke) != B2B_CONTACT_ACTIVE) continue;
    eval_line(pf, &s, X, 6, NULL, NULL, &of, Kf);
    eval_line(ps, &s, X, 6, NULL, NULL, &os, Ks);
    eval_line(pm, &s, X, 6, NULL, NULL, &om, Km);
    ck_assert(memcmp(oe.R, of.R, sizeof oe.R) == 0 && memcmp(oe.R, os.R, sizeof oe.R) == 0 &&
              memcmp(oe.R, om.R, sizeof oe.R) == 0);
    const double F = oe.li[B2B_LINE_INFO_NORMAL_FORCE];
    ck_assert_msg(tst_rel_diff(Kf, Ke, 576, 1e-10 * F) <= 1e-5, "FD option vs exact %.2e",
                  tst_rel_diff(Kf, Ke, 576, 1e-10 * F));
    ck_assert(tst_asymmetry(Ks) <= 1e-14 && os.li[B2B_LINE_INFO_SYMMETRIC] == 1.0);
    ck_assert_msg(tst_rel_diff(Km, Ke, 576, 1e-10 * F) > 1e-3, "MAIN equals EXACT");
    ++checked;
  }
  ck_assert_int_ge(checked, 4);
  b2b_params_destroy(&pe);
  b2b_params_destroy(&pf);
  b2b_params_destroy(&ps);
  b2b_params_destroy(&pm);
}
END_TEST

/* B along x split into two segments at x = split (a joint under A), A
 * parallel above it from 0 to L: summed over B's two segments, every point
 * is owned once and the forces add to eps_L pen L. */
static void joint_case(b2b_params *p, int kind, double split, int n) {
  const double L = 1.0, pen = 0.008, d = 2 * RADIUS - pen;
  /* B's nodes at -1, split, 2 (and ghosts beyond) */
  const double bx[5] = {-1.0, -0.3, split, 1.7, 2.4};
  tst_pair_spec s = {{kind, kind},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {RADIUS, RADIUS}};
  double ax[4] = {-0.7, 0.0, L, 1.6};
  double owned = 0, force = 0, R[24] = {0};
  for (int segb = 0; segb < 2; ++segb) {
    double X[24];
    for (int k = 0; k < 4; ++k) {
      X[3 * k] = ax[k], X[3 * k + 1] = 0, X[3 * k + 2] = d;
      X[12 + 3 * k] = bx[segb + k > 4 ? 4 : segb + k], X[13 + 3 * k] = 0, X[14 + 3 * k] = 0;
    }
    /* B's patch: nodes segb .. segb+3 of bx (segment between bx[segb+1] and bx[segb+2]) */
    line_out o;
    eval_line(p, &s, X, n, NULL, NULL, &o, NULL);
    owned += o.li[B2B_LINE_INFO_OWNED_POINTS];
    force += o.li[B2B_LINE_INFO_NORMAL_FORCE];
    for (int r = 0; r < 24; ++r) R[r] += o.R[r];
  }
  ck_assert_msg(owned == n, "%s, joint at %g: points owned %g times, n %d", tst_kind_name(kind),
                split, owned, n);
  ck_assert_msg(fabs(force - EPS_L * pen * L) <= 1e-12 * EPS_L * pen * L,
                "%s: force %.17g vs %.17g", tst_kind_name(kind), force, EPS_L * pen * L);
}

START_TEST(joint_of_b_counted_once) {
  b2b_params *p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, 0, B2B_TANGENT_EXACT);
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    if (tst_kind_family(kind) == TST_CENTRED) continue; /* its segments are centred on nodes */
    for (int n = 2; n <= 9; ++n) joint_case(p, kind, 0.37, n);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* The slip is read at B's surface (doc/line-contact.md 5): A an arc round
 * B's axis (a rope on a beam), turned about that axis by delta after a
 * committed evaluation: every point slips by r_B sin(delta) tangentially,
 * so in stick its force per length is eps_LT r_B sin(delta) (the axis slip
 * would give 0); both beams turned rigidly about an axis across B by phi:
 * a slip below r_B phi^2, of second order in phi. */
static void arc_round_z(double rc, double turn, double X[24]) {
  for (int k = 0; k < 4; ++k) {
    const double a = 0.05 * (2 * k - 3) + turn;
    X[3 * k] = rc * cos(a), X[3 * k + 1] = rc * sin(a), X[3 * k + 2] = 0.01 * k;
    X[12 + 3 * k] = 0, X[12 + 3 * k + 1] = 0, X[12 + 3 * k + 2] = -1.0 + 0.6 * k;
  }
}

START_TEST(slip_read_at_surface) {
  b2b_params *p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, MU, B2B_TANGENT_EXACT);
  tst_pair_spec s = {{B2B_CURVE_HERMITE_NODAL, B2B_CURVE_LINEAR},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {RADIUS, 3 * RADIUS}};
  const double rc = 4 * RADIUS - 0.01, delta = 1e-4;
  double X[24], hist[MAXH];
  static line_out o;
  arc_round_z(rc, 0.0, X);
  ck_assert_int_eq(eval_line(p, &s, X, 4, NULL, hist, &o, NULL), B2B_CONTACT_ACTIVE);
  arc_round_z(rc, delta, X);
  ck_assert_int_eq(eval_line(p, &s, X, 4, hist, NULL, &o, NULL), B2B_CONTACT_ACTIVE);
  const double want = EPS_LT * 3 * RADIUS * sin(delta);
  for (int i = 0; i < 4; ++i) {
    const double *q = o.pinfo + 32 * i, *T = q + B2B_INFO_TANGENTIAL_FORCE;
    ck_assert_msg(q[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK, "point %d not in stick", i);
    const double t = sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]);
    ck_assert_msg(fabs(t - want) <= 1e-6 * want, "point %d: |T| %.10g, r_B sin(delta) eps %.10g", i,
                  t, want);
  }
  /* both turned rigidly about x by phi: B's committed tangent is not kept
   * (the history has room for the normal only), so m is the committed
   * normal turned by the smallest rotation that takes the tangent guessed
   * from it to B's current one: right to first order, a slip of second
   * order in the step's rotation remains (doc/line-contact.md 5). */
  double slip[2];
  for (int r = 0; r < 2; ++r) {
    const double phi = r ? 0.01 : 0.02, c = cos(phi), sn = sin(phi);
    arc_round_z(rc, 0.0, X);
    for (int k = 0; k < 8; ++k) {
      double *x = X + 3 * k;
      const double y = x[1], z = x[2];
      x[1] = c * y - sn * z, x[2] = sn * y + c * z;
    }
    ck_assert_int_eq(eval_line(p, &s, X, 4, hist, NULL, &o, NULL), B2B_CONTACT_ACTIVE);
    slip[r] = 0.0;
    for (int i = 0; i < 4; ++i) {
      const double *T = o.pinfo + 32 * i + B2B_INFO_TANGENTIAL_FORCE;
      slip[r] = fmax(slip[r], sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]) / EPS_LT);
    }
    ck_assert_msg(slip[r] <= 3 * RADIUS * phi * phi, "rigid rotation %g: slip %g above r_B phi^2",
                  phi, slip[r]);
  }
  ck_assert_msg(slip[1] <= 0.3 * slip[0], "slip of a rigid rotation not of second order: %g, %g",
                slip[0], slip[1]);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(line_points_rule) {
  b2b_params *p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, 0, B2B_TANGENT_EXACT);
  char msg[B2B_ERRMSG_LEN];
  int n = -1;
  ck_assert(b2b_pair_line_points(p, 1.0, 0.1, 0.1, &n, msg, sizeof msg) == B2B_OK);
  ck_assert_int_eq(n, 8); /* 3 + ceil(1 / 0.2) */
  ck_assert(b2b_pair_line_points(p, 0.0, 0.1, 0.1, &n, msg, sizeof msg) == B2B_OK);
  ck_assert_int_eq(n, 4);
  ck_assert(b2b_pair_line_points(p, 1e6, 0.1, 0.1, &n, msg, sizeof msg) == B2B_OK);
  ck_assert_int_eq(n, 16);
  ck_assert(b2b_pair_line_points(p, 1.0, 0.0, 0.0, &n, msg, sizeof msg) == B2B_OK);
  ck_assert_int_eq(n, 16);
  n = -7;
  ck_assert(b2b_pair_line_points(p, NAN, 0.1, 0.1, &n, msg, sizeof msg) == B2B_ERR_NONFINITE);
  ck_assert(b2b_pair_line_points(p, 1.0, -0.1, 0.1, &n, msg, sizeof msg) == B2B_ERR_RANGE);
  ck_assert_msg(strstr(msg, "radius_a") != NULL, "%s", msg);
  ck_assert(b2b_pair_line_points(p, 1.0, 0.1, 0.1, NULL, msg, sizeof msg) == B2B_ERR_NULL);
  ck_assert_int_eq(n, -7);
  b2b_params_destroy(&p);
  b2b_params_create(&p, msg, sizeof msg);
  b2b_params_set_real(p, "penalty", 1.0, msg, sizeof msg);
  ck_assert(b2b_params_set_int(p, "line_points", 33, msg, sizeof msg) == B2B_ERR_RANGE);
  ck_assert(b2b_params_set_int(p, "line_points", 5, msg, sizeof msg) == B2B_OK);
  b2b_params_finalize(p, msg, sizeof msg);
  ck_assert(b2b_pair_line_points(p, 1.0, 0.1, 0.1, &n, msg, sizeof msg) == B2B_OK);
  ck_assert_int_eq(n, 5);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(bad_input) {
  char msg[B2B_ERRMSG_LEN];
  b2b_params *p = NULL;
  /* finalize: line options required by the type, the blending range */
  b2b_params_create(&p, msg, sizeof msg);
  b2b_params_set_real(p, "penalty", 1.0, msg, sizeof msg);
  ck_assert(b2b_params_set_int(p, "contact_type", 3, msg, sizeof msg) == B2B_ERR_UNKNOWN_KIND ||
            b2b_params_set_int(p, "contact_type", 3, msg, sizeof msg) == B2B_ERR_RANGE);
  ck_assert(b2b_params_set_real(p, "line_penalty", NAN, msg, sizeof msg) == B2B_ERR_NONFINITE);
  ck_assert(b2b_params_set_real(p, "line_penalty", -1, msg, sizeof msg) == B2B_ERR_RANGE);
  b2b_params_set_int(p, "contact_type", B2B_CONTACT_TYPE_LINE, msg, sizeof msg);
  ck_assert(b2b_params_finalize(p, msg, sizeof msg) == B2B_ERR_STATE);
  ck_assert_msg(strstr(msg, "line_penalty") != NULL, "%s", msg);
  b2b_params_set_real(p, "line_penalty", 1.0, msg, sizeof msg);
  b2b_params_set_real(p, "friction", 0.2, msg, sizeof msg);
  b2b_params_set_real(p, "tangential_penalty", 1.0, msg, sizeof msg);
  ck_assert(b2b_params_finalize(p, msg, sizeof msg) == B2B_ERR_STATE);
  ck_assert_msg(strstr(msg, "line_tangential_penalty") != NULL, "%s", msg);
  b2b_params_set_real(p, "line_tangential_penalty", 1.0, msg, sizeof msg);
  b2b_params_set_int(p, "contact_type", B2B_CONTACT_TYPE_ALL_ANGLE, msg, sizeof msg);
  b2b_params_set_real(p, "line_angle", 20.0, msg, sizeof msg);
  ck_assert(b2b_params_finalize(p, msg, sizeof msg) == B2B_ERR_RANGE);
  ck_assert_msg(strstr(msg, "point_angle") != NULL, "%s", msg);
  b2b_params_set_real(p, "line_angle", 5.0, msg, sizeof msg);
  ck_assert(b2b_params_finalize(p, msg, sizeof msg) == B2B_OK);
  b2b_params_destroy(&p);

  /* a point-only set without line_penalty: b2b_pair_eval_line refuses it */
  p = tst_params(B2B_LAW_LINEAR, 1.0, 0.0);
  tst_pair_spec s = {{B2B_CURVE_LINEAR, B2B_CURVE_LINEAR},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                     {RADIUS, RADIUS}};
  const int seg[6] = {0, 0, 0, 0, 0, 0};
  double X[24];
  straight_crossing(2.0, 0.15, X);
  for (int k = 0; k < 24; ++k)
    if (isnan(X[k])) X[k] = 0.0;
  static double ho[MAXH], hn[MAXH], K[576], li[16], pi[32 * MAXP], R[24];
  int status = 77;
  for (int k = 0; k < MAXH; ++k) hn[k] = 5.0;
  li[0] = R[0] = K[0] = pi[0] = 5.0;
  ck_assert(b2b_pair_eval_line(p, seg, X, NULL, s.radius, 4, ho, hn, 5 * 8, &status, li, pi, R,
                               K, 24, msg, sizeof msg) == B2B_ERR_STATE);
  ck_assert_msg(strstr(msg, "line_penalty") != NULL, "%s", msg);
  b2b_params_destroy(&p);
  p = line_params(B2B_LAW_LINEAR, B2B_CONTACT_TYPE_LINE, 0, B2B_TANGENT_EXACT);
  struct {
    int n, len, ldk;
    double *hist_new;
    int expect;
    const char *word;
  } cases[] = {
      {0, 8, 24, hn, B2B_ERR_RANGE, "n_points"},
      {33, 34 * 8, 24, hn, B2B_ERR_RANGE, "n_points"},
      {4, 4 * 8, 24, hn, B2B_ERR_SIZE, "hist_len"},
      {4, 5 * 8, 23, hn, B2B_ERR_SIZE, "ldk"},
      {4, 5 * 8, 24, ho, B2B_ERR_RANGE, "hist_new"},
  };
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
    msg[0] = 0;
    ck_assert_int_eq(b2b_pair_eval_line(p, seg, X, NULL, s.radius, cases[c].n, ho,
                                        cases[c].hist_new, cases[c].len, &status, li, pi, R, K,
                                        cases[c].ldk, msg, sizeof msg),
                     cases[c].expect);
    ck_assert_msg(strstr(msg, cases[c].word) != NULL, "case %zu: %s", c, msg);
  }
  /* a corrupted history slot, a NaN coordinate, a NULL */
  ho[8 * 3 + 0] = 3.0; /* slot 3's tag */
  ck_assert(b2b_pair_eval_line(p, seg, X, NULL, s.radius, 4, ho, hn, 5 * 8, &status, li, pi, R,
                               K, 24, msg, sizeof msg) == B2B_ERR_RANGE);
  ck_assert_msg(strstr(msg, "history 3") != NULL, "%s", msg);
  ho[8 * 3] = 0.0;
  X[4] = NAN;
  ck_assert(b2b_pair_eval_line(p, seg, X, NULL, s.radius, 4, ho, hn, 5 * 8, &status, li, pi, R,
                               K, 24, msg, sizeof msg) == B2B_ERR_NONFINITE);
  X[4] = 0.0;
  ck_assert(b2b_pair_eval_line(p, seg, X, NULL, s.radius, 4, ho, hn, 5 * 8, NULL, li, pi, R, K,
                               24, msg, sizeof msg) == B2B_ERR_NULL);
  /* nothing was written */
  TST_ASSERT_ALL(int, k, 0, MAXH, hn[k] == 5.0, "hist_new[%d] written", k);
  ck_assert(status == 77 && li[0] == 5.0 && R[0] == 5.0 && K[0] == 5.0 && pi[0] == 5.0);
  /* and the good call works */
  ck_assert(b2b_pair_eval_line(p, seg, X, NULL, s.radius, 4, ho, hn, 5 * 8, &status, li, pi, R,
                               K, 24, msg, sizeof msg) == B2B_OK);
  b2b_params_destroy(&p);
}
END_TEST

int main(void) {
  Suite *s = suite_create("pair_line");
  TCase *tc = tcase_create("line");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, gauss_rules_exact);
  tcase_add_test(tc, fd_frictionless_all_kinds);
  tcase_add_test(tc, fd_friction_stick_and_slip);
  tcase_add_test(tc, blended_fd_in_range);
  tcase_add_test(tc, force_continuous_in_angle);
  tcase_add_test(tc, tangent_options);
  tcase_add_test(tc, joint_of_b_counted_once);
  tcase_add_test(tc, slip_read_at_surface);
  tcase_add_test(tc, line_points_rule);
  tcase_add_test(tc, bad_input);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
