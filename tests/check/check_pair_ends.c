/* The end contact (b2b_pair_eval_ends, b2b_pair.h "End contact"): the
 * point-wise element with the parameter of A and/or B held at -1 or +1
 * (node-to-segment, node-to-node).
 *
 * Configurations: seeded random curved patches of every pair of curve kinds,
 * the held node placed at a given axis distance from the other beam's point
 * at a random parameter, then each held beam turned about its node by 10 to
 * 40 degrees (so its tangent is not normal to the contact normal, the case
 * the free element never sees); the held beam's end rule at that node cycles
 * through NEIGHBOUR, REFLECT and TANGENT. Held: A at -1 and +1, B at -1 and
 * +1, both (four sign combinations).
 *   - tangent against central differences of the residual (steps h and h/2,
 *     one Richardson step, as check_pair_tangent), relative error <= 1e-6,
 *     both normal laws, frictionless; the residual against differences of
 *     info[B2B_INFO_ENERGY] (the residual is the gradient of the potential);
 *     the frictionless tangent symmetric to 1e-10;
 *   - with friction in stick and in slip, the committed history of a
 *     previous evaluation held fixed (as check_pair_friction: the tangent and
 *     its friction part K - K_0 on its own scale, both <= 1e-6);
 *   - the library against the AD reference of tests/ad extended by the held
 *     ends (b2b_ad_pair_eval_ends): status, info, history, residual and
 *     tangent to 1e-12 (the tolerances of check_pair_ad), with and without
 *     friction (fresh, stick, slip);
 *   - the committed friction force is reproduced where nothing moved, and
 *     it is tangential;
 *   - ends = {0, 0} is b2b_pair_eval bit for bit (every output);
 *   - a node above a segment at any crossing angle, 0 included (a node above
 *     a parallel segment): ACTIVE with the gap of the closed form;
 *   - node to node: gap = |x_A - x_B| - r_A - r_B, points and normal; with
 *     friction tip to tip (both tangents along n): a finite history, T = 0;
 *   - bad input: ends NULL, out of range (2, -2, INT_MIN, INT_MAX) with a
 *     message naming ends and every output untouched, and spot checks of
 *     b2b_pair_eval's bad input through b2b_pair_eval_ends. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "b2b_ad.h"
#include "pair_support.h"

#define TOL 1e-6    /* finite differences (check_pair_tangent, check_pair_friction) */
#define TOL_K 1e-12 /* AD reference: tangent, relative, max norm (check_pair_ad) */
#define TOL_R 1e-12 /* AD reference: residual */
#define TOL_I 1e-12 /* AD reference: info and history entries */
#define EPS_N 1e3
#define MU 0.3
#define EPS_T 8e2
#define HLEN 12

static const double kPi = 3.14159265358979323846;

/* The held ends: A at -1, +1; B at -1, +1; both. */
#define N_ENDS 8
static const int ends_list[N_ENDS][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1},
                                         {-1, -1}, {1, 1}, {-1, 1}, {1, -1}};
enum { ST_NONE = 0, ST_STICK = 1, ST_SLIP = 2 };
static const char *const state_name[3] = {"frictionless", "stick", "slip"};

/* ------------------------------------------------------------- helpers */

static double dot3(const double *a, const double *b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static double norm3(const double *a) { return sqrt(dot3(a, a)); }

/* Rotation by th about the unit axis u (column-major). */
static void axis_rotation(const double u[3], double th, double Q[9]) {
  const double c = cos(th), s = sin(th);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) Q[i + 3 * j] = (i == j ? c : 0.0) + (1 - c) * u[i] * u[j];
  Q[1] += s * u[2], Q[2] -= s * u[1];  // column 0
  Q[3] -= s * u[2], Q[5] += s * u[0];  // column 1
  Q[6] += s * u[1], Q[7] -= s * u[0];  // column 2
}

/* Turns the four nodes of beam b (NaN slots stay NaN) about the point p. */
static void turn_beam(double *X, int b, const double Q[9], const double p[3]) {
  for (int k = 0; k < 4; ++k) {
    double *x = X + 12 * b + 3 * k, v[3], w[3];
    for (int i = 0; i < 3; ++i) v[i] = x[i] - p[i];
    tst_rotate(Q, v, w);
    for (int i = 0; i < 3; ++i) x[i] = p[i] + w[i];
  }
}

/* Host end tangents: each beam's chord through its two middle read slots,
 * tilted a little. */
static void make_end_tangents(tst_rng *rng, const double X[24], double tang[12]) {
  for (int b = 0; b < 2; ++b) {
    const double *x2 = X + 12 * b + 3, *x3 = X + 12 * b + 6;
    if (isnan(x3[0])) x3 = x2, x2 = X + 12 * b;
    double c[3] = {x3[0] - x2[0], x3[1] - x2[1], x3[2] - x2[2]};
    const double l = norm3(c);
    for (int e = 0; e < 2; ++e)
      for (int i = 0; i < 3; ++i) tang[6 * b + 3 * e + i] = c[i] / l + tst_uniform(rng, -0.2, 0.2);
  }
}

/* b2b_pair_eval_ends; fails the test unless B2B_OK. Returns the status. */
static int eval_ends(const b2b_params *p, const tst_pair_spec *spec, const double X[24],
                     const double tang[12], const int ends[2], const double *hist_old,
                     double *hist_new, double info[32], double R[24], double *K) {
  const int seg[6] = {spec->kind[0], spec->start_rule[0], spec->end_rule[0],
                      spec->kind[1], spec->start_rule[1], spec->end_rule[1]};
  double fresh[HLEN] = {0}, scratch[HLEN];
  int status = -1;
  char msg[B2B_ERRMSG_LEN] = "";
  const int st = b2b_pair_eval_ends(p, seg, X, tang, spec->radius, ends,
                                    hist_old ? hist_old : fresh, hist_new ? hist_new : scratch,
                                    tst_history_len(p), &status, info, R, K, 24, msg, sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_pair_eval_ends returned %d: %s", st, msg);
  ck_assert(info[B2B_INFO_END_A] == ends[0] && info[B2B_INFO_END_B] == ends[1]);
  return status;
}

/* A random end contact of the kinds of spec: the held parameters at their
 * ends, the free ones at random interior points, axis distance dist along
 * the common normal of the tangents there, then each held beam turned about
 * its node by 10 .. 40 degrees about a random axis. The held beam's rule at
 * the held node cycles with `rule` through NEIGHBOUR, REFLECT, TANGENT
 * (a midpoint segment keeps NEIGHBOUR at the other end). */
static void make_end_config(tst_rng *rng, tst_pair_spec *spec, const int ends[2], int rule,
                            double dist, double X[24], double tang[12]) {
  /* placed with REFLECT where the rule will be TANGENT (tst_crossing has no
   * host tangents; the node moves little, if at all) */
  for (int b = 0; b < 2; ++b) {
    spec->start_rule[b] = spec->end_rule[b] = B2B_END_NEIGHBOUR;
    if (ends[b] < 0) spec->start_rule[b] = rule % 3 ? B2B_END_REFLECT : B2B_END_NEIGHBOUR;
    if (ends[b] > 0) spec->end_rule[b] = rule % 3 ? B2B_END_REFLECT : B2B_END_NEIGHBOUR;
  }
  const double xi = ends[0] ? ends[0] : tst_uniform(rng, -0.5, 0.5);
  const double eta = ends[1] ? ends[1] : tst_uniform(rng, -0.5, 0.5);
  tst_crossing(rng, spec, 0.4, tst_uniform(rng, 20, 90), xi, eta, dist, X);
  make_end_tangents(rng, X, tang);
  if (rule % 3 == 2)
    for (int b = 0; b < 2; ++b) {
      if (ends[b] < 0) spec->start_rule[b] = B2B_END_TANGENT;
      if (ends[b] > 0) spec->end_rule[b] = B2B_END_TANGENT;
    }
  for (int b = 0; b < 2; ++b) {
    if (!ends[b]) continue;
    double x[9], u[3], Q[9];
    tst_eval(spec->kind[b], spec->start_rule[b], spec->end_rule[b], X + 12 * b, tang + 6 * b,
             ends[b], x, NULL, NULL);
    do {
      for (int i = 0; i < 3; ++i) u[i] = tst_uniform(rng, -1, 1);
    } while (norm3(u) < 0.3 || norm3(u) > 1);
    const double l = norm3(u);
    for (int i = 0; i < 3; ++i) u[i] /= l;
    const double th = tst_uniform(rng, 10, 40) * kPi / 180.0;
    axis_rotation(u, th, Q);
    turn_beam(X, b, Q, x);
    double t[6];  // the host tangents turn with the beam
    tst_rotate(Q, tang + 6 * b, t);
    tst_rotate(Q, tang + 6 * b + 3, t + 3);
    memcpy(tang + 6 * b, t, sizeof t);
  }
}

static void describe(char *buf, size_t n, const char *what, const tst_pair_spec *spec,
                     const int ends[2], int law) {
  snprintf(buf, n, "%s: law %d, %s x %s, ends {%d, %d}, rules A %d %d B %d %d", what, law,
           tst_kind_name(spec->kind[0]), tst_kind_name(spec->kind[1]), ends[0], ends[1],
           spec->start_rule[0], spec->end_rule[0], spec->start_rule[1], spec->end_rule[1]);
}

/* ------------------------------------------- finite differences, frictionless */

static double worst_k, worst_r, worst_sym, worst_kf, worst_ff;
static int n_checked[3], n_skipped;

/* Central differences of the residual (and energy) at X, the committed
 * history hist (NULL: fresh) held fixed, steps h and h/2 and one Richardson
 * step; each perturbation must keep the status and friction state (else the
 * step shrinks by 4, twice, then the configuration is skipped: returns 0). */
static int fd_tangent(const b2b_params *p, const tst_pair_spec *spec, const double X[24],
                      const double tang[12], const int ends[2], const double *hist, int status,
                      double state, double h, double Kfd[576], double Rfd[24]) {
  memset(Kfd, 0, 576 * sizeof(double));
  memset(Rfd, 0, 24 * sizeof(double));
  for (int a = 0; a < 24; ++a) {
    if (isnan(X[a])) continue;
    int ok = 0;
    double step = h;
    for (int attempt = 0; attempt < 3 && !ok; ++attempt, step *= 0.25) {
      double dR[2][24], dE[2];
      ok = 1;
      for (int k = 0; k < 2 && ok; ++k) {
        const double s = k ? 0.5 * step : step;
        double Xp[24], Xm[24], ip[32], im[32], Rp[24], Rm[24];
        memcpy(Xp, X, sizeof Xp);
        memcpy(Xm, X, sizeof Xm);
        Xp[a] += s;
        Xm[a] -= s;
        const int sp = eval_ends(p, spec, Xp, tang, ends, hist, NULL, ip, Rp, NULL);
        const int sm = eval_ends(p, spec, Xm, tang, ends, hist, NULL, im, Rm, NULL);
        if (sp != status || sm != status || ip[B2B_INFO_FRICTION_STATE] != state ||
            im[B2B_INFO_FRICTION_STATE] != state) {
          ok = 0;
          break;
        }
        for (int r = 0; r < 24; ++r) dR[k][r] = (Rp[r] - Rm[r]) / (2 * s);
        dE[k] = (ip[B2B_INFO_ENERGY] - im[B2B_INFO_ENERGY]) / (2 * s);
      }
      if (ok) {
        for (int r = 0; r < 24; ++r) Kfd[r + 24 * a] = (4 * dR[1][r] - dR[0][r]) / 3;
        Rfd[a] = (4 * dE[1] - dE[0]) / 3;
      }
    }
    if (!ok) return 0;
  }
  return 1;
}

/* Frictionless: tangent vs FD, residual vs FD of the energy, symmetry.
 * Returns 1 if checked (the configuration is active). */
static int check_frictionless(const b2b_params *p, const tst_pair_spec *spec, const double X[24],
                              const double tang[12], const int ends[2], const char *what) {
  static double K[576], Kfd[576];
  double info[32], R[24], Rfd[24];
  if (eval_ends(p, spec, X, tang, ends, NULL, NULL, info, R, K) != B2B_CONTACT_ACTIVE) return 0;
  ck_assert_msg(info[B2B_INFO_SYMMETRIC] == 1.0, "%s: frictionless, not reported symmetric",
                what);
  if (!fd_tangent(p, spec, X, tang, ends, NULL, B2B_CONTACT_ACTIVE, 0.0, 1e-5, Kfd, Rfd)) {
    ++n_skipped;
    return 0;
  }
  for (int a = 0; a < 24; ++a)
    if (isnan(X[a])) {
      ck_assert_msg(R[a] == 0.0, "%s: residual in an unused slot", what);
      for (int r = 0; r < 24; ++r)
        ck_assert_msg(K[r + 24 * a] == 0.0 && K[a + 24 * r] == 0.0, "%s: tangent in an unused "
                      "slot", what);
    }
  const double f = info[B2B_INFO_NORMAL_FORCE];
  const double ek = tst_rel_diff(K, Kfd, 576, 1e-12 * f);
  const double er = tst_rel_diff(R, Rfd, 24, 1e-12 * f);
  const double asym = tst_asymmetry(K);
  worst_k = fmax(worst_k, ek);
  worst_r = fmax(worst_r, er);
  worst_sym = fmax(worst_sym, asym);
  ck_assert_msg(ek <= TOL, "%s: tangent vs FD of the residual, rel. error %.2e", what, ek);
  ck_assert_msg(er <= TOL, "%s: residual vs FD of the energy, rel. error %.2e", what, er);
  ck_assert_msg(asym <= 1e-10, "%s: frictionless tangent not symmetric, rel. %.2e", what, asym);
  ++n_checked[ST_NONE];
  return 1;
}

static void reset(void) {
  worst_k = worst_r = worst_sym = worst_kf = worst_ff = 0.0;
  n_checked[0] = n_checked[1] = n_checked[2] = n_skipped = 0;
}

START_TEST(fd_frictionless_all_kinds_all_ends) {
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 16001);
  int count[B2B_CURVE_KIND_COUNT][N_ENDS];
  memset(count, 0, sizeof count);
  for (int law = 0; law < B2B_LAW_COUNT; ++law) {
    b2b_params *p = tst_params(law, EPS_N, 0.05);
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int e = 0; e < N_ENDS; ++e) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          double X[24], tang[12];
          const double dist = 0.35 - tst_uniform(&rng, law ? -0.03 : 0.02, 0.1);
          make_end_config(&rng, &spec, ends_list[e], ka + kb + e + law, dist, X, tang);
          /* quick mode: half of the same configurations */
          if (tst_quick() && (ka + kb + e + law) % 2) continue;
          char what[200];
          describe(what, sizeof what, "frictionless", &spec, ends_list[e], law);
          if (check_frictionless(p, &spec, X, tang, ends_list[e], what)) {
            ++count[ka][e];
            ++count[kb][e];
          }
        }
    b2b_params_destroy(&p);
  }
  printf("end contact, frictionless: %d active configurations (%d skipped); worst rel. error: "
         "tangent %.2e, residual vs energy %.2e; asymmetry %.2e\n",
         n_checked[ST_NONE], n_skipped, worst_k, worst_r, worst_sym);
  for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k)
    for (int e = 0; e < N_ENDS; ++e)
      ck_assert_msg(count[k][e] >= 2, "%s, ends {%d, %d}: only %d configurations checked",
                    tst_kind_name(k), ends_list[e][0], ends_list[e][1], count[k][e]);
  ck_assert_int_le(n_skipped, 8);
}
END_TEST

/* ------------------------------------------------ finite differences, friction */

/* Moves beam b rigidly by v (NaN slots stay NaN). */
static void translate_beam(double *X, int b, const double v[3]) {
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) X[12 * b + 3 * k + i] += v[i];
}

/* A random direction normal to n, of length len. */
static void tangential(tst_rng *rng, const double n[3], double len, double v[3]) {
  double r[3], l;
  do {
    for (int i = 0; i < 3; ++i) r[i] = tst_uniform(rng, -1, 1);
    const double rn = dot3(r, n);
    for (int i = 0; i < 3; ++i) r[i] -= rn * n[i];
    l = norm3(r);
  } while (l < 0.2);
  for (int i = 0; i < 3; ++i) v[i] = len * r[i] / l;
}

/* From an active end contact X0: commit it (h1), slide B tangentially by
 * `first` mu f_N / eps_T and commit again (hist, a nonzero committed force),
 * then slide by `second` mu f_N / eps_T in another direction: X2. Returns 0
 * unless X0 and X1 are active. */
static int prepare_friction(tst_rng *rng, const b2b_params *p, const tst_pair_spec *spec,
                            const double tang[12], const int ends[2], const double X0[24],
                            double first, double second, double X1[24], double X2[24],
                            double hist[HLEN]) {
  double info[32], R[24], h1[HLEN], v[3];
  if (eval_ends(p, spec, X0, tang, ends, NULL, h1, info, R, NULL) != B2B_CONTACT_ACTIVE) return 0;
  memcpy(X1, X0, 24 * sizeof(double));
  tangential(rng, info + B2B_INFO_NORMAL, first * MU * info[B2B_INFO_NORMAL_FORCE] / EPS_T, v);
  translate_beam(X1, 1, v);
  if (eval_ends(p, spec, X1, tang, ends, h1, hist, info, R, NULL) != B2B_CONTACT_ACTIVE) return 0;
  memcpy(X2, X1, 24 * sizeof(double));
  tangential(rng, info + B2B_INFO_NORMAL, second * MU * info[B2B_INFO_NORMAL_FORCE] / EPS_T, v);
  translate_beam(X2, 1, v);
  return 1;
}

/* With friction: the tangent (committed history held fixed) against FD, as a
 * whole and its friction part K - K_0 on its own scale. Returns the friction
 * state checked, or -1 (not active or skipped). */
static int check_friction(const b2b_params *p, const b2b_params *p0, const tst_pair_spec *spec,
                          const double X[24], const double tang[12], const int ends[2],
                          const double hist[HLEN], const char *what) {
  static double K[576], Kfd[576], K0[576];
  double info[32], R[24], Rfd[24], i0[32], R0[24];
  if (eval_ends(p, spec, X, tang, ends, hist, NULL, info, R, K) != B2B_CONTACT_ACTIVE) return -1;
  const double state = info[B2B_INFO_FRICTION_STATE];
  ck_assert_msg(state == B2B_FRICTION_STICK || state == B2B_FRICTION_SLIP,
                "%s: friction state %g of an active pair", what, state);
  ck_assert(info[B2B_INFO_SYMMETRIC] == 0.0);
  if (!fd_tangent(p, spec, X, tang, ends, hist, B2B_CONTACT_ACTIVE, state, 1e-5, Kfd, Rfd)) {
    ++n_skipped;
    return -1;
  }
  const double f = info[B2B_INFO_NORMAL_FORCE];
  const double ek = tst_rel_diff(K, Kfd, 576, 1e-12 * f);
  worst_kf = fmax(worst_kf, ek);
  ck_assert_msg(ek <= TOL, "%s (%s): tangent vs FD, rel. error %.2e", what,
                state_name[(int)state], ek);
  if (ends[0] && ends[1]) {
    /* Node to node: the anchors are the nodes themselves, so the tangential
     * relative displacement (I - n n^T)(x_A(xi_n) - x_B(eta_n)) is zero
     * whatever moves (two spheres slide on each other only by turning,
     * which the axis-based element does not model): no friction force. */
    ck_assert_msg(norm3(info + B2B_INFO_TANGENTIAL_FORCE) <= 1e-12 * MU * f,
                  "%s: node to node with a tangential force", what);
    ck_assert(state == B2B_FRICTION_STICK);
    ++n_checked[(int)state];
    return (int)state;
  }
  ck_assert_int_eq(eval_ends(p0, spec, X, tang, ends, hist, NULL, i0, R0, K0),
                   B2B_CONTACT_ACTIVE);
  double diff = 0.0, part = 0.0;
  for (int i = 0; i < 576; ++i) {
    diff = fmax(diff, fabs(K[i] - Kfd[i]));
    part = fmax(part, fabs(K[i] - K0[i]));
  }
  const double ef = diff / part;
  worst_ff = fmax(worst_ff, ef);
  ck_assert_msg(ef <= TOL, "%s (%s): tangent vs FD, error %.2e of the friction part", what,
                state_name[(int)state], ef);
  const double L = MU * f, t = norm3(info + B2B_INFO_TANGENTIAL_FORCE);
  if (state == B2B_FRICTION_SLIP)
    ck_assert_msg(fabs(t - L) <= 1e-12 * L, "%s: slip with |T| %.17g, mu f_N %.17g", what, t, L);
  else
    ck_assert_msg(t <= L, "%s: stick with |T| %g > mu f_N %g", what, t, L);
  ++n_checked[(int)state];
  return (int)state;
}

START_TEST(fd_friction_stick_and_slip) {
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 16002);
  int count[N_ENDS][3];
  memset(count, 0, sizeof count);
  for (int law = 0; law < B2B_LAW_COUNT; ++law) {
    b2b_params *p = tst_params_friction(law, EPS_N, 0.05, MU, EPS_T);
    b2b_params *p0 = tst_params(law, EPS_N, 0.05);
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int e = 0; e < N_ENDS; ++e)
          for (int target = ST_STICK; target <= ST_SLIP; ++target) {
            tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
            double X0[24], X1[24], X2[24], tang[12], hist[HLEN];
            const double dist = 0.35 - tst_uniform(&rng, law ? -0.02 : 0.03, 0.1);
            make_end_config(&rng, &spec, ends_list[e], ka + 2 * kb + e, dist, X0, tang);
            const double first = target == ST_STICK ? 0.4 : tst_uniform(&rng, 1.5, 2.5);
            const double second = target == ST_STICK ? 0.3 : tst_uniform(&rng, 2.0, 3.0);
            if (!prepare_friction(&rng, p, &spec, tang, ends_list[e], X0, first, second, X1, X2,
                                  hist))
              continue;
            /* quick mode: half of the same configurations */
            if (tst_quick() && (ka + kb + e + law) % 2) continue;
            char what[200];
            describe(what, sizeof what, "friction", &spec, ends_list[e], law);
            const int st = check_friction(p, p0, &spec, X2, tang, ends_list[e], hist, what);
            if (st > 0) ++count[e][st];
          }
    b2b_params_destroy(&p);
    b2b_params_destroy(&p0);
  }
  printf("end contact, friction: %d stick, %d slip (%d skipped); worst rel. error of the "
         "tangent %.2e, of its friction part %.2e\n",
         n_checked[ST_STICK], n_checked[ST_SLIP], n_skipped, worst_kf, worst_ff);
  for (int e = 0; e < N_ENDS; ++e)
    for (int s = ST_STICK; s <= (ends_list[e][0] && ends_list[e][1] ? ST_STICK : ST_SLIP); ++s)
      ck_assert_msg(count[e][s] >= 4, "ends {%d, %d}: only %d %s configurations checked",
                    ends_list[e][0], ends_list[e][1], count[e][s], state_name[s]);
  ck_assert_int_le(n_skipped, 16);
}
END_TEST

/* The committed force is rebuilt where nothing moved (the anchors are the
 * contact points, g_T = 0: T = T_committed), and it is tangential. */
START_TEST(committed_friction_force_is_kept) {
  tst_rng rng;
  tst_rng_seed(&rng, 16003);
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  double worst = 0.0, worst_normal = 0.0;
  int n = 0;
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int e = 0; e < 4; ++e)  // one end held (node to node has no force: above)
      for (int rep = 0; rep < 3; ++rep) {
        tst_pair_spec spec = {{ka, (ka + rep + e) % B2B_CURVE_KIND_COUNT}, {0, 0}, {0, 0},
                              {0.2, 0.15}};
        double X0[24], X1[24], X2[24], tang[12], hist[HLEN], h3[HLEN], i1[32], i2[32], R[24];
        make_end_config(&rng, &spec, ends_list[e], rep, 0.27, X0, tang);
        if (!prepare_friction(&rng, p, &spec, tang, ends_list[e], X0, 0.5, 0.0, X1, X2, hist))
          continue;
        /* hist: committed at X1 (stick). Evaluate at X1 again. */
        char what[200];
        describe(what, sizeof what, "committed force", &spec, ends_list[e], 0);
        double h0[HLEN];
        ck_assert_int_eq(eval_ends(p, &spec, X0, tang, ends_list[e], NULL, h0, i1, R, NULL),
                         B2B_CONTACT_ACTIVE);
        ck_assert_int_eq(eval_ends(p, &spec, X1, tang, ends_list[e], h0, NULL, i1, R, NULL),
                         B2B_CONTACT_ACTIVE);
        ck_assert_int_eq(eval_ends(p, &spec, X1, tang, ends_list[e], hist, h3, i2, R, NULL),
                         B2B_CONTACT_ACTIVE);
        const double *t1 = i1 + B2B_INFO_TANGENTIAL_FORCE, *t2 = i2 + B2B_INFO_TANGENTIAL_FORCE;
        const double d[3] = {t2[0] - t1[0], t2[1] - t1[1], t2[2] - t1[2]};
        const double err = norm3(d) / norm3(t1);
        const double tn = fabs(dot3(t2, i2 + B2B_INFO_NORMAL)) / norm3(t2);
        worst = fmax(worst, err);
        worst_normal = fmax(worst_normal, tn);
        ck_assert_msg(i1[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK, "%s: not stick", what);
        ck_assert_msg(err <= 1e-11, "%s: committed force T = (%g %g %g) rebuilt as (%g %g %g), "
                      "rel. error %.2e", what, t1[0], t1[1], t1[2], t2[0], t2[1], t2[2], err);
        ck_assert_msg(tn <= 1e-11, "%s: friction force not tangential, |T.n|/|T| = %.2e", what,
                      tn);
        ++n;
      }
  printf("committed friction force of %d end contacts: worst rel. change %.2e, worst normal "
         "part %.2e\n", n, worst, worst_normal);
  ck_assert_int_ge(n, 40);
  b2b_params_destroy(&p);
}
END_TEST


/* ------------------------------------------------------- the AD reference */

static double rel_err(const double *a, const double *b, int n) {
  double d = 0.0, m = 0.0;
  for (int i = 0; i < n; ++i) {
    d = fmax(d, fabs(a[i] - b[i]));
    m = fmax(m, fabs(b[i]));
  }
  return m > 0.0 ? d / m : d;
}

/* Largest |a - b| / (1 + |b|) over the entries (info: but the iterations). */
static double entry_err(const double *a, const double *b, int n, int skip) {
  double e = 0.0;
  for (int i = 0; i < n; ++i)
    if (i != skip) e = fmax(e, fabs(a[i] - b[i]) / (1.0 + fabs(b[i])));
  return e;
}

static double worst_ad_k[3], worst_ad_r[3], worst_ad_i[3];
static int n_ad[3];

static void compare_ad(const b2b_params *p, const tst_pair_spec *spec, const double X[24],
                       const double tang[12], const int ends[2], const double *hist, int state,
                       const char *what) {
  static double K[576], Kad[576];
  const int seg[6] = {spec->kind[0], spec->start_rule[0], spec->end_rule[0],
                      spec->kind[1], spec->start_rule[1], spec->end_rule[1]};
  double info[32], iad[32], R[24], Rad[24], hn[HLEN], hnad[HLEN], fresh[HLEN] = {0}, grad[24];
  const int nh = tst_history_len(p);
  const int sl = eval_ends(p, spec, X, tang, ends, hist ? hist : fresh, hn, info, R, K);
  int sad = -1;
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_ad_pair_eval_ends(p, seg, X, tang, spec->radius, ends, hist ? hist : fresh,
                                      hnad, nh, 0, &sad, iad, Rad, Kad, 24, grad, msg,
                                      sizeof msg) == B2B_OK,
                "%s: the reference failed: %s", what, msg);
  ck_assert_msg(sl == sad, "%s: status %d, the reference says %d", what, sl, sad);
  if (sl != B2B_CONTACT_ACTIVE) return;
  const double ek = rel_err(K, Kad, 576), er = rel_err(R, Rad, 24);
  const double ei = fmax(entry_err(info, iad, 32, B2B_INFO_ITERATIONS),
                         entry_err(hn, hnad, nh, -1));
  worst_ad_k[state] = fmax(worst_ad_k[state], ek);
  worst_ad_r[state] = fmax(worst_ad_r[state], er);
  worst_ad_i[state] = fmax(worst_ad_i[state], ei);
  ck_assert_msg(ek <= TOL_K, "%s (%s): tangent against the AD reference, rel. error %.2e", what,
                state_name[state], ek);
  ck_assert_msg(er <= TOL_R, "%s (%s): residual against the AD reference, rel. error %.2e",
                what, state_name[state], er);
  ck_assert_msg(ei <= TOL_I, "%s (%s): info or history against the AD reference, %.2e", what,
                state_name[state], ei);
  if (state == ST_NONE)  // the reference's residual is its AD energy gradient
    ck_assert_msg(rel_err(grad, Rad, 24) <= TOL_R, "%s: the reference's residual is not its "
                  "energy gradient", what);
  ++n_ad[state];
}

START_TEST(against_the_ad_reference) {
  tst_rng rng;
  tst_rng_seed(&rng, 16004);
  memset(n_ad, 0, sizeof n_ad);
  ck_assert_int_ge(b2b_ad_curve_kind_count(), B2B_CURVE_KIND_COUNT);
  for (int law = 0; law < B2B_LAW_COUNT; ++law) {
    b2b_params *p0 = tst_params(law, EPS_N, 0.05);
    b2b_params *pf = tst_params_friction(law, EPS_N, 0.05, MU, EPS_T);
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int e = 0; e < N_ENDS; ++e) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          double X0[24], X1[24], X2[24], tang[12], hist[HLEN];
          make_end_config(&rng, &spec, ends_list[e], ka + kb + e + law, 0.27, X0, tang);
          char what[200];
          describe(what, sizeof what, "AD", &spec, ends_list[e], law);
          compare_ad(p0, &spec, X0, tang, ends_list[e], NULL, ST_NONE, what);
          compare_ad(pf, &spec, X0, tang, ends_list[e], NULL, ST_STICK, what);  // fresh
          for (int target = ST_STICK; target <= ST_SLIP; ++target)
            if (prepare_friction(&rng, pf, &spec, tang, ends_list[e], X0,
                                 target == ST_STICK ? 0.4 : 2.0,
                                 target == ST_STICK ? 0.3 : 2.5, X1, X2, hist)) {
              double info[32], R[24];
              const int st = eval_ends(pf, &spec, X2, tang, ends_list[e], hist, NULL, info, R,
                                       NULL);
              const int fs = st == B2B_CONTACT_ACTIVE ? (int)info[B2B_INFO_FRICTION_STATE]
                                                      : ST_STICK;
              compare_ad(pf, &spec, X2, tang, ends_list[e], hist, fs, what);
            }
        }
    b2b_params_destroy(&p0);
    b2b_params_destroy(&pf);
  }
  for (int s = 0; s < 3; ++s)
    printf("end contact against the AD reference, %s: %d active; worst rel. error tangent "
           "%.2e, residual %.2e, info/history %.2e\n",
           state_name[s], n_ad[s], worst_ad_k[s], worst_ad_r[s], worst_ad_i[s]);
  ck_assert_int_ge(n_ad[ST_NONE], 200);
  ck_assert_int_ge(n_ad[ST_STICK], 200);
  ck_assert_int_ge(n_ad[ST_SLIP], 50);
}
END_TEST

/* ------------------------------------------------------------ closed forms */

/* ends = {0, 0} is b2b_pair_eval, every output bit for bit. */
START_TEST(no_end_is_the_free_pair) {
  tst_rng rng;
  tst_rng_seed(&rng, 16005);
  static double K1[576], K2[576];
  const int free_ends[2] = {0, 0};
  int n_active = 0;
  for (int fric = 0; fric < 2; ++fric) {
    b2b_params *p = fric ? tst_params_friction(B2B_LAW_QUADRATIC, EPS_N, 0.05, MU, EPS_T)
                         : tst_params(B2B_LAW_LINEAR, EPS_N, 0.0);
    for (int n = 0; n < 3 * B2B_CURVE_KIND_COUNT * B2B_CURVE_KIND_COUNT; ++n) {
      tst_pair_spec spec = {{TST_KIND_A(n), TST_KIND_B(n)}, {0, 0}, {0, 0}, {0.2, 0.15}};
      double X[24], i1[32], i2[32], R1[24], R2[24], h0[HLEN], h1[HLEN], h2[HLEN], hc[HLEN];
      /* some active, some open, some outside */
      tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 5, 90), tst_uniform(&rng, -1.3, 1.3),
                   tst_uniform(&rng, -1.3, 1.3), tst_uniform(&rng, 0.2, 0.4), X);
      memset(h0, 0, sizeof h0);
      tst_pair(p, &spec, X, h0, hc, i1, R1, NULL);  // a committed history to start from
      for (int a = 0; a < 24; ++a)
        if (!isnan(X[a])) X[a] += tst_uniform(&rng, -0.02, 0.02);
      memset(i1, 0x5a, sizeof i1), memset(i2, 0x5a, sizeof i2);
      memset(K1, 0x5a, sizeof K1), memset(K2, 0x5a, sizeof K2);
      memset(h1, 0x5a, sizeof h1), memset(h2, 0x5a, sizeof h2);
      const int s1 = tst_pair(p, &spec, X, hc, h1, i1, R1, K1);
      const double tang[12] = {1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0};  // tst_pair's defaults
      const int s2 = eval_ends(p, &spec, X, tang, free_ends, hc, h2, i2, R2, K2);
      ck_assert_int_eq(s1, s2);
      ck_assert(memcmp(i1, i2, sizeof i1) == 0);
      ck_assert(memcmp(R1, R2, sizeof R1) == 0);
      ck_assert(memcmp(K1, K2, sizeof K1) == 0);
      ck_assert(memcmp(h1, h2, (size_t)tst_history_len(p) * sizeof(double)) == 0);
      n_active += s1 == B2B_CONTACT_ACTIVE;
    }
    b2b_params_destroy(&p);
  }
  ck_assert_int_ge(n_active, 20);
}
END_TEST

/* A straight patch of kind `kind` through x2 = base along dir, elements of
 * length len (slots the kind does not read: NaN). */
static void straight_patch(int kind, const double base[3], const double dir[3], double len,
                           double *patch) {
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) patch[3 * k + i] = base[i] + (k - 1) * len * dir[i];
  if (tst_kind_family(kind) == TST_CHORD) {
    for (int i = 0; i < 3; ++i) patch[i] = patch[9 + i] = NAN;
  } else if (tst_kind_family(kind) == TST_CENTRED) {
    for (int i = 0; i < 3; ++i) patch[9 + i] = NAN;
  }
}

/* A tip pushed on end-on, with friction: straight A tilted 1 degree off the
 * vertical, its held end (either) pressed 0.01 into B (along x, bent),
 * every kind pair, stick and slip, the tangent against finite differences
 * as in fd_friction_stick_and_slip (the linear law: the slides go with the
 * force, and the quadratic law's would turn the normal too far). A's tangent
 * lies within about 6 degrees of the normal, so the friction frame is built
 * from B's tangent (src/pair/friction.cpp, friction_force): the one case of
 * the frame whose tangent terms no other test reached but by chance (a
 * random network of check_model_threads). */
START_TEST(fd_friction_tip_end_on) {
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 16005);
  /* radii large against the slides (at most 0.017 in all): the normal turns
   * by at most 2 degrees */
  const double rA = 0.3, rB = 0.2, tilt = 1.0 * kPi / 180.0;
  int count[3] = {0, 0, 0};
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  b2b_params *p0 = tst_params(B2B_LAW_LINEAR, EPS_N, 0.0);
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (int end = -1; end <= 1; end += 2)
        for (int target = ST_STICK; target <= ST_SLIP; ++target) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {rA, rB}};
          /* A leaves its held end upwards: from its start (end -1) along
           * +dir, or into its end (end +1) along -dir */
          const double phi = tst_uniform(&rng, 0.0, 2.0 * kPi);
          const double up[3] = {sin(tilt) * cos(phi), sin(tilt) * sin(phi), cos(tilt)};
          double dir_a[3], base_a[3], X0[24], X1[24], X2[24], x[9];
          /* B along x, bent in the horizontal plane (y = 0.3 x^2 at its
           * nodes: the frame's tangent terms carry B's second derivative);
           * A's held node above B's point at eta = 0.1 (x = 0.05) */
          const double dir_b[3] = {1, 0, 0},
                       base_b[3] = {tst_kind_family(kb) == TST_CENTRED ? 0.0 : -0.5, 0, 0};
          straight_patch(kb, base_b, dir_b, 1.0, X0 + 12);
          for (int k = 0; k < 4; ++k) X0[12 + 3 * k + 1] += 0.3 * X0[12 + 3 * k] * X0[12 + 3 * k];
          tst_eval(kb, 0, 0, X0 + 12, NULL, 0.1, x, NULL, NULL);
          for (int i = 0; i < 3; ++i) {
            dir_a[i] = end < 0 ? up[i] : -up[i];
            base_a[i] = i < 2 ? x[i] : 0.0;
            if (end > 0) base_a[i] -= 0.1 * dir_a[i];
          }
          straight_patch(ka, base_a, dir_a, 0.1, X0);
          /* A's end point (a midpoint segment's is off the node) 0.01 deep */
          tst_eval(ka, 0, 0, X0, NULL, end, x, NULL, NULL);
          for (int k = 0; k < 4; ++k) X0[3 * k + 2] += rA + rB - 0.01 - x[2];
          const double tang[12] = {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0};
          const int ends[2] = {end, 0};
          double hist[HLEN], info[32], R[24];
          if (!prepare_friction(&rng, p, &spec, tang, ends, X0,
                                target == ST_STICK ? 0.4 : 2.0,
                                target == ST_STICK ? 0.3 : 2.5, X1, X2, hist))
            continue;
          char what[200];
          describe(what, sizeof what, "friction, tip end-on", &spec, ends, B2B_LAW_LINEAR);
          /* the premise: A's tangent within 6 degrees of the normal */
          ck_assert_int_eq(eval_ends(p, &spec, X2, tang, ends, hist, NULL, info, R, NULL),
                           B2B_CONTACT_ACTIVE);
          tst_eval(ka, 0, 0, X2, NULL, end, x, NULL, NULL);
          const double tn = dot3(info + B2B_INFO_NORMAL, x + 3) / norm3(x + 3);
          ck_assert_msg(1.0 - tn * tn < 1e-2, "%s: A's tangent %g degrees off the normal",
                        what, acos(fabs(tn)) * 180.0 / kPi);
          const int st = check_friction(p, p0, &spec, X2, tang, ends, hist, what);
          if (st > 0) ++count[st];
        }
  b2b_params_destroy(&p);
  b2b_params_destroy(&p0);
  printf("tip end-on, friction: %d stick, %d slip (%d skipped); worst rel. error of the "
         "tangent %.2e, of its friction part %.2e\n",
         count[ST_STICK], count[ST_SLIP], n_skipped, worst_kf, worst_ff);
  ck_assert_msg(count[ST_STICK] >= 16 && count[ST_SLIP] >= 16, "only %d stick, %d slip checked",
                count[ST_STICK], count[ST_SLIP]);
}
END_TEST

/* A node of straight A at height h above straight B (along x), A crossing
 * B's direction at any angle, 0 included: ACTIVE, gap h - r_A - r_B, the
 * foot of the node on B, the normal +z. The free pair is PARALLEL at 0. */
START_TEST(node_above_a_segment_at_any_angle) {
  const double angles[] = {0.0, 1e-6, 0.01, 0.5, 5, 30, 60, 90};
  const double h = 0.1, rA = 0.1, rB = 0.05;  // gap -0.05 (more off a node)
  b2b_params *p = tst_params(B2B_LAW_LINEAR, EPS_N, 0.0);
  double worst = 0.0;
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (size_t q = 0; q < sizeof angles / sizeof angles[0]; ++q)
        for (int end = -1; end <= 1; end += 2) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {rA, rB}};
          const double th = angles[q] * kPi / 180.0;
          const double dir_b[3] = {1, 0, 0}, dir_a[3] = {cos(th), sin(th), 0};
          /* B covers x in [-0.5, 0.5] (a midpoint segment spans the
           * midpoints of its elements about x2) */
          const double base_b[3] = {tst_kind_family(kb) == TST_CENTRED ? 0.0 : -0.5, 0, 0};
          double X[24], x[9];
          /* A's x2 (end -1) or x3 (end +1) at x = 0.05 above B; its end
           * point x_A(end) is that node or (midpoint) 0.05 from it */
          const double node[3] = {0.05, 0.0, h};
          double base_a[3];
          for (int i = 0; i < 3; ++i) base_a[i] = node[i] - (end > 0 ? 0.1 * dir_a[i] : 0.0);
          straight_patch(ka, base_a, dir_a, 0.1, X);
          straight_patch(kb, base_b, dir_b, 1.0, X + 12);
          tst_eval(ka, 0, 0, X, NULL, end, x, NULL, NULL);
          const int ends[2] = {end, 0};
          double info[32], R[24];
          const double tang[12] = {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0};
          char what[160];
          snprintf(what, sizeof what, "%s node %+d above %s at %g degrees", tst_kind_name(ka),
                   end, tst_kind_name(kb), angles[q]);
          const int st = eval_ends(p, &spec, X, tang, ends, NULL, NULL, info, R, NULL);
          ck_assert_msg(st == B2B_CONTACT_ACTIVE, "%s: status %d, not active", what, st);
          /* the end point of A (off the node, and so off y = 0, for a
           * midpoint segment) over its foot (x, 0, 0) on B */
          const double rho = hypot(x[1], x[2]), gap = rho - rA - rB;
          const double e = fmax(fmax(fabs(info[B2B_INFO_GAP] - gap),
                                     fabs(info[B2B_INFO_NORMAL + 1] - x[1] / rho)),
                                fmax(fabs(info[B2B_INFO_POINT_B] - x[0]),
                                     fmax(fabs(info[B2B_INFO_POINT_B + 1]),
                                          fabs(info[B2B_INFO_NORMAL + 2] - x[2] / rho))));
          worst = fmax(worst, e);
          ck_assert_msg(e <= 1e-14, "%s: gap %.17g (want %.17g), foot (%g, %g), normal z %.17g",
                        what, info[B2B_INFO_GAP], gap, info[B2B_INFO_POINT_B],
                        info[B2B_INFO_POINT_B + 1], info[B2B_INFO_NORMAL + 2]);
          ck_assert(fabs(info[B2B_INFO_NORMAL_FORCE] - EPS_N * (rA + rB - rho)) <=
                    1e-12 * EPS_N);
          if (angles[q] == 0.0) {  // the free element cannot do this
            const int st0 = tst_pair(p, &spec, X, NULL, NULL, info, R, NULL);
            ck_assert_msg(st0 != B2B_CONTACT_ACTIVE, "%s: the free pair is active", what);
          }
        }
  printf("node above a segment, angles 0 .. 90: worst error of gap, foot, normal %.2e\n", worst);
  b2b_params_destroy(&p);
}
END_TEST

/* Node to node: gap |x_A - x_B| - r_A - r_B, the nodes as the points, the
 * normal along x_A - x_B. */
START_TEST(node_to_node_gap) {
  tst_rng rng;
  tst_rng_seed(&rng, 16006);
  b2b_params *p = tst_params(B2B_LAW_LINEAR, EPS_N, 0.0);
  double worst = 0.0;
  for (int n = 0; n < 4 * B2B_CURVE_KIND_COUNT * B2B_CURVE_KIND_COUNT; ++n) {
    tst_pair_spec spec = {{TST_KIND_A(n), TST_KIND_B(n)}, {0, 0}, {0, 0}, {0.2, 0.15}};
    const int ends[2] = {n % 2 ? 1 : -1, (n / 2) % 2 ? 1 : -1};
    double X[24], tang[12], xa[9], xb[9], info[32], R[24];
    make_end_config(&rng, &spec, ends, n / 4, tst_uniform(&rng, 0.2, 0.5), X, tang);
    tst_eval(spec.kind[0], spec.start_rule[0], spec.end_rule[0], X, tang, ends[0], xa, NULL,
             NULL);
    tst_eval(spec.kind[1], spec.start_rule[1], spec.end_rule[1], X + 12, tang + 6, ends[1], xb,
             NULL, NULL);
    const int st = eval_ends(p, &spec, X, tang, ends, NULL, NULL, info, R, NULL);
    ck_assert(st == B2B_CONTACT_ACTIVE || st == B2B_CONTACT_OPEN);
    const double d[3] = {xa[0] - xb[0], xa[1] - xb[1], xa[2] - xb[2]};
    const double rho = norm3(d);
    double e = fabs(info[B2B_INFO_GAP] - (rho - 0.2 - 0.15));
    for (int i = 0; i < 3; ++i) {
      e = fmax(e, fabs(info[B2B_INFO_POINT_A + i] - xa[i]));
      e = fmax(e, fabs(info[B2B_INFO_POINT_B + i] - xb[i]));
      e = fmax(e, fabs(info[B2B_INFO_NORMAL + i] - d[i] / rho));
    }
    ck_assert(info[B2B_INFO_XI] == ends[0] && info[B2B_INFO_ETA] == ends[1]);
    worst = fmax(worst, e);
    ck_assert_msg(e <= 1e-14, "%s x %s, ends {%d, %d}: gap %.17g, want %.17g (error %.2e)",
                  tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), ends[0], ends[1],
                  info[B2B_INFO_GAP], rho - 0.35, e);
  }
  printf("node to node: worst error of gap, points, normal %.2e\n", worst);
  b2b_params_destroy(&p);
}
END_TEST


/* Node to node with friction where both tangents lie along the normal (two
 * beams tip to tip, collinear or nearly): the frame of the friction force
 * must still be defined. ACTIVE, T = 0 (no slip node to node), a finite
 * history that the next step accepts, and the tangent against differences.
 * (An e1 = (I - n n^T) x_A,xi / |...| frame gave 0/0 here: a NaN in the new
 * history, B2B_ERR_NONFINITE on the next call.) */
START_TEST(node_to_node_tip_to_tip_with_friction) {
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  b2b_params *p0 = tst_params(B2B_LAW_LINEAR, EPS_N, 0.0);
  const double tilts[] = {0.0, 1e-9, 1e-4, 1e-2};
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (size_t q = 0; q < sizeof tilts / sizeof tilts[0]; ++q) {
        tst_pair_spec spec = {{ka, kb}, {0, B2B_END_REFLECT}, {B2B_END_REFLECT, 0}, {0.03, 0.03}};
        /* A along d ending at its node x3 = 0 (end +1, a beam end), B along
         * d starting at its x2 = 0.05 d (end -1), d tilted off x a little */
        double d[3] = {cos(tilts[q]), sin(tilts[q]), 0.5 * sin(tilts[q])};
        const double dl = norm3(d);
        for (int i = 0; i < 3; ++i) d[i] /= dl;
        double X[24], x[9], tang[12];
        for (int k = 0; k < 4; ++k)
          for (int i = 0; i < 3; ++i) {
            X[3 * k + i] = (k - 2) * d[i];
            X[12 + 3 * k + i] = (k - 1 + 0.05) * d[i];
          }
        for (int e = 0; e < 4; ++e)
          for (int i = 0; i < 3; ++i) tang[3 * e + i] = d[i];
        /* unread slots (none for these rules but the chord's): NaN */
        if (tst_kind_family(ka) == TST_CHORD)
          for (int i = 0; i < 3; ++i) X[i] = X[9 + i] = NAN;
        if (tst_kind_family(kb) == TST_CHORD)
          for (int i = 0; i < 3; ++i) X[12 + i] = X[21 + i] = NAN;
        if (tst_kind_family(ka) == TST_CENTRED || tst_kind_family(kb) == TST_CENTRED)
          continue;  // a midpoint segment's end is not its node: not tip to tip
        tst_eval(ka, spec.start_rule[0], spec.end_rule[0], X, tang, 1, x, NULL, NULL);
        const int ends[2] = {1, -1};
        double info[32], R[24], h1[HLEN], h2[HLEN];
        char what[160];
        snprintf(what, sizeof what, "%s tip to %s tip, tilt %g", tst_kind_name(ka),
                 tst_kind_name(kb), tilts[q]);
        ck_assert_msg(eval_ends(p, &spec, X, tang, ends, NULL, h1, info, R, NULL) ==
                          B2B_CONTACT_ACTIVE, "%s: not active", what);
        ck_assert_msg(fabs(info[B2B_INFO_GAP] + 0.01) <= 1e-14, "%s: gap %.17g", what,
                      info[B2B_INFO_GAP]);
        TST_ASSERT_ALL(int, i, 0, HLEN, isfinite(h1[i]), "%s: hist_new[%d] = %g", what, i, h1[i]);
        /* the next step, with that history */
        X[12] += 1e-3, X[15] += 1e-3, X[18] += 1e-3;  // B's x1 .. x3 move a little
        if (tst_kind_family(kb) == TST_CHORD) X[12] = NAN;
        ck_assert_msg(eval_ends(p, &spec, X, tang, ends, h1, h2, info, R, NULL) ==
                          B2B_CONTACT_ACTIVE, "%s: second step not active", what);
        TST_ASSERT_ALL(int, i, 0, HLEN, isfinite(h2[i]), "%s: hist_new[%d] = %g", what, i, h2[i]);
        ck_assert_msg(norm3(info + B2B_INFO_TANGENTIAL_FORCE) <= 1e-12 * MU * info[B2B_INFO_NORMAL_FORCE], "%s: T != 0", what);
        check_friction(p, p0, &spec, X, tang, ends, h1, what);
      }
  b2b_params_destroy(&p);
  b2b_params_destroy(&p0);
}
END_TEST

/* ------------------------------------------------------------- bad input */

#define SENT 12345.0

/* Calls b2b_pair_eval_ends on a valid active end contact with one thing
 * changed; checks the code, a message naming `word`, untouched outputs. */
static void expect_bad(const b2b_params *p, const int ends[2], int hist_len, double xnan,
                       int ldk, int want, const char *word) {
  tst_pair_spec spec = {{B2B_CURVE_HERMITE_NODAL, B2B_CURVE_LINEAR}, {0, 0}, {0, 0}, {0.2, 0.15}};
  const int seg[6] = {spec.kind[0], 0, 0, spec.kind[1], 0, 0};
  double X[24], tang[12], hold[HLEN] = {0}, hnew[HLEN], info[32], R[24], K[576];
  int status = -777;
  tst_rng rng;
  tst_rng_seed(&rng, 16007);
  const int good[2] = {-1, 0};
  make_end_config(&rng, &spec, good, 0, 0.27, X, tang);
  X[4] += xnan;
  for (int i = 0; i < HLEN; ++i) hnew[i] = SENT;
  for (int i = 0; i < 32; ++i) info[i] = SENT;
  for (int i = 0; i < 24; ++i) R[i] = SENT;
  for (int i = 0; i < 576; ++i) K[i] = SENT;
  char msg[B2B_ERRMSG_LEN] = "";
  const int st = b2b_pair_eval_ends(p, seg, X, tang, spec.radius, ends, hold, hnew, hist_len,
                                    &status, info, R, K, ldk, msg, sizeof msg);
  ck_assert_msg(st == want, "%s: returned %d (%s), want %d", word, st, msg, want);
  if (want == B2B_OK) {
    ck_assert_int_eq(status, B2B_CONTACT_ACTIVE);
    return;
  }
  ck_assert_msg(strstr(msg, word) != NULL, "the message \"%s\" does not name %s", msg, word);
  ck_assert_msg(strstr(msg, "b2b_pair_eval_ends") != NULL, "message \"%s\"", msg);
  ck_assert_int_eq(status, -777);
  TST_ASSERT_ALL(int, i, 0, HLEN, hnew[i] == SENT, "hist_new[%d] touched", i);
  TST_ASSERT_ALL(int, i, 0, 32, info[i] == SENT, "info[%d] touched", i);
  TST_ASSERT_ALL(int, i, 0, 24, R[i] == SENT, "residual[%d] touched", i);
  TST_ASSERT_ALL(int, i, 0, 576, K[i] == SENT, "tangent[%d] touched", i);
  /* the same without a message buffer */
  ck_assert_int_eq(b2b_pair_eval_ends(p, seg, X, tang, spec.radius, ends, hold, hnew, hist_len,
                                      &status, info, R, K, ldk, NULL, 0),
                   want);
}

START_TEST(bad_input) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, EPS_N, 0.0);
  const int n = tst_history_len(p);
  const int ok[2] = {-1, 0};
  const int bad[][2] = {{2, 0}, {0, 2}, {-2, 0}, {0, -2}, {INT_MIN, 0}, {0, INT_MIN},
                        {INT_MAX, 1}, {1, INT_MAX}};
  expect_bad(p, NULL, n, 0.0, 24, B2B_ERR_NULL, "ends");
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k)
    expect_bad(p, bad[k], n, 0.0, 24, B2B_ERR_RANGE, "ends");
  /* b2b_pair_eval's checks apply too */
  expect_bad(p, ok, n - 1, 0.0, 24, B2B_ERR_SIZE, "hist_len");
  expect_bad(p, ok, n, 0.0, 23, B2B_ERR_SIZE, "ldk");
  expect_bad(p, ok, n, NAN, 24, B2B_ERR_NONFINITE, "beam A");
  /* the valid call succeeds */
  expect_bad(p, ok, n, 0.0, 24, B2B_OK, "");
  b2b_params_destroy(&p);
  /* an unfinalized parameter set, NULL params */
  b2b_params *q = NULL;
  ck_assert_int_eq(b2b_params_create(&q, NULL, 0), B2B_OK);
  expect_bad(q, ok, 8, 0.0, 24, B2B_ERR_STATE, "final");
  b2b_params_destroy(&q);
  expect_bad(NULL, ok, 8, 0.0, 24, B2B_ERR_NULL, "params");
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("pair_ends");
  TCase *fd = tcase_create("finite_differences");
  tcase_set_timeout(fd, 300);
  tcase_add_test(fd, fd_frictionless_all_kinds_all_ends);
  tcase_add_test(fd, fd_friction_stick_and_slip);
  tcase_add_test(fd, committed_friction_force_is_kept);
  tcase_add_test(fd, fd_friction_tip_end_on);
  suite_add_tcase(s, fd);
  TCase *ad = tcase_create("ad_reference");
  tcase_set_timeout(ad, 300);
  tcase_add_test(ad, against_the_ad_reference);
  suite_add_tcase(s, ad);
  TCase *cf = tcase_create("closed_forms");
  tcase_add_test(cf, no_end_is_the_free_pair);
  tcase_add_test(cf, node_above_a_segment_at_any_angle);
  tcase_add_test(cf, node_to_node_gap);
  tcase_add_test(cf, node_to_node_tip_to_tip_with_friction);
  tcase_add_test(cf, bad_input);
  suite_add_tcase(s, cf);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
