/* Coulomb friction of the contact element (b2b_pair.h, "Friction" and
 * "Handover"):
 *   - the tangent against central finite differences of the residual with
 *     the committed history held fixed, in a fresh contact, in stick and in
 *     slip with a nonzero committed force (so the transport of the force with
 *     the frame is differentiated too), for every pair of curve kinds, both
 *     normal laws, crossing angles 90 .. 5 degrees, points near segment
 *     joints and at beam ends (REFLECT and TANGENT rules);
 *   - the stick and slip laws in closed form on straight beams;
 *   - a loading history with commits (press, pull past the slip limit,
 *     reverse, pull sideways, release) against a scalar Coulomb model, with
 *     the dissipation;
 *   - objectivity (rigid motion of every step; a rigid motion within a step
 *     is no slip);
 *   - mu = 0 is bit for bit frictionless; a fresh contact with mu > 0 has the
 *     frictionless residual;
 *   - continuity of the friction force when the contact point slides across
 *     a joint of a smoothed beam, with b2b_pair_history_handover (and the
 *     loss of the force without it).
 * (Central differences with one Richardson step, as in check_pair_tangent.) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pair_support.h"

#define TOL 1e-6
#define MU 0.3
#define EPS_N 1e3
#define EPS_T 8e2
#define HLEN 12

enum { ST_FRESH = 0, ST_STICK = 1, ST_SLIP = 2 };

static const double kPi = 3.14159265358979323846;
static const char *const state_name[3] = {"fresh", "stick", "slip"};

/* ----------------------------------------------------------- small algebra */

static double dot3(const double *a, const double *b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double norm3(const double *a) { return sqrt(dot3(a, a)); }

static double dist3(const double *a, const double *b) {
  const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return norm3(d);
}

static void normalize3(double *v) {
  const double n = norm3(v);
  for (int i = 0; i < 3; ++i) v[i] /= n;
}

/* Rotation by th about axis (column-major, Rodrigues). */
static void axis_rotation(const double *axis_in, double th, double Q[9]) {
  double k[3] = {axis_in[0], axis_in[1], axis_in[2]};
  normalize3(k);
  const double c = cos(th), s = sin(th);
  const double K[9] = {0, k[2], -k[1], -k[2], 0, k[0], k[1], -k[0], 0};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      Q[i + 3 * j] = (i == j ? c : 0.0) + (1 - c) * k[i] * k[j] + s * K[i + 3 * j];
}

static void random_rotation(tst_rng *rng, double th_lo, double th_hi, double Q[9]) {
  double axis[3];
  do {
    for (int i = 0; i < 3; ++i) axis[i] = tst_uniform(rng, -1, 1);
  } while (norm3(axis) < 0.2);
  axis_rotation(axis, tst_uniform(rng, th_lo, th_hi), Q);
}

/* Y = Q X + t node by node (NaN slots stay NaN). */
static void rigid_motion(const double Q[9], const double t[3], const double *X, int nodes,
                         double *Y) {
  for (int k = 0; k < nodes; ++k) {
    tst_rotate(Q, X + 3 * k, Y + 3 * k);
    for (int i = 0; i < 3; ++i) Y[3 * k + i] += t[i];
  }
}

/* Sums of the residual over the nodes of A and of B (NaN slots skipped). */
static void nodal_sums(const double X[24], const double R[24], double sa[3], double sb[3]) {
  for (int i = 0; i < 3; ++i) sa[i] = sb[i] = 0.0;
  for (int k = 0; k < 8; ++k) {
    if (isnan(X[3 * k])) continue;
    for (int i = 0; i < 3; ++i) (k < 4 ? sa : sb)[i] += R[3 * k + i];
  }
}

/* The force balance of an active pair: A's residual sums to -f_N n + T, B's
 * to f_N n - T (the curves are translation invariant, so their jacobians sum
 * to the identity over the nodes). */
static void assert_balance(const double X[24], const double info[32], const double R[24],
                           const char *what) {
  double sa[3], sb[3];
  nodal_sums(X, R, sa, sb);
  const double f = info[B2B_INFO_NORMAL_FORCE];
  const double scale = f + norm3(info + B2B_INFO_TANGENTIAL_FORCE);
  for (int i = 0; i < 3; ++i) {
    const double want = -f * info[B2B_INFO_NORMAL + i] + info[B2B_INFO_TANGENTIAL_FORCE + i];
    ck_assert_msg(fabs(sa[i] - want) <= 1e-11 * scale && fabs(sb[i] + want) <= 1e-11 * scale,
                  "%s: nodal forces of A sum to %g, of B to %g, expected %g and %g", what, sa[i],
                  sb[i], want, -want);
  }
}

/* ------------------------------------------------------- configurations */

/* Host end tangents near the chord of the patch's first element whose nodes
 * are both read (x2-x3, or x1-x2 for a midpoint segment ending at x2),
 * slightly tilted. */
static void make_end_tangents(tst_rng *rng, const double X[24], double tang[12]) {
  for (int b = 0; b < 2; ++b) {
    const double *x2 = X + 12 * b + 3, *x3 = X + 12 * b + 6;
    if (isnan(x3[0])) x3 = x2, x2 = X + 12 * b;
    double c[3] = {x3[0] - x2[0], x3[1] - x2[1], x3[2] - x2[2]};
    normalize3(c);
    for (int e = 0; e < 2; ++e)
      for (int i = 0; i < 3; ++i) tang[6 * b + 3 * e + i] = c[i] + tst_uniform(rng, -0.2, 0.2);
  }
}

/* Unit tangent of beam b at parameter t. */
static void unit_tangent(const tst_pair_spec *spec, const double tang[12], const double X[24],
                         int b, double t, double u[3]) {
  double x[9];
  tst_eval(spec->kind[b], spec->start_rule[b], spec->end_rule[b], X + 12 * b, tang + 6 * b, t, x,
           NULL, NULL);
  for (int i = 0; i < 3; ++i) u[i] = x[3 + i];
  normalize3(u);
}

static double random_sign(tst_rng *rng) { return tst_uniform(rng, 0, 1) < 0.5 ? -1.0 : 1.0; }

/* Y = X with A moved by s a t_A and B by s b t_B, t_A, t_B the unit tangents
 * at the closest points xi, eta, such that A moves by d relative to B:
 * |s (a t_A - b t_B)| = d. Moving a beam along its own tangent leaves the
 * crossing point in space (nearly) where it is, even at small angles.
 * mode 0: both beams, 1: only B (A's closest point stays, e.g. near a joint
 * of A), 2: only A. */
static void slide(tst_rng *rng, const tst_pair_spec *spec, const double tang[12],
                  const double X[24], double xi, double eta, double d, int mode, double Y[24]) {
  double ta[3], tb[3], rel[3], a, b;
  unit_tangent(spec, tang, X, 0, xi, ta);
  unit_tangent(spec, tang, X, 1, eta, tb);
  do {
    a = mode == 1 ? 0.0 : random_sign(rng) * tst_uniform(rng, 0.3, 1.0);
    b = mode == 2 ? 0.0 : random_sign(rng) * tst_uniform(rng, 0.3, 1.0);
    for (int i = 0; i < 3; ++i) rel[i] = a * ta[i] - b * tb[i];
  } while (norm3(rel) < 0.2);
  const double s = d / norm3(rel);
  memcpy(Y, X, 24 * sizeof(double));
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) {
      Y[3 * k + i] += s * a * ta[i];
      Y[12 + 3 * k + i] += s * b * tb[i];
    }
}

static void add_noise(tst_rng *rng, double *X, int n, double amp) {
  for (int a = 0; a < n; ++a)
    if (!isnan(X[a])) X[a] += tst_uniform(rng, -amp, amp);
}

/* From the crossing X0: X1, X2 and the committed history hist (of X1) of a
 * state aimed at `target`. Fresh: X1 = X0, X2 near X0 and a fresh history
 * (T = 0, no anchor). Stick and slip: X0 (fresh) is committed, X1 slides by
 * 0.4 (stick) or 0.3 .. 2.5 (slip) times mu f_N / eps_T and is committed
 * (a nonzero committed force, in stick or slip), X2 slides on by 0.3 (stick)
 * or 2 .. 3 (slip) times mu f_N / eps_T in another direction. Returns 0
 * unless X0 and X1 are active. */
static int prepare(tst_rng *rng, const b2b_params *p, const tst_pair_spec *spec,
                   const double tang[12], const double X0[24], int target, int mode,
                   double X1[24], double X2[24], double hist[HLEN]) {
  double info[32], R[24], h1[HLEN];
  memset(hist, 0, HLEN * sizeof(double));
  memcpy(X1, X0, 24 * sizeof(double));
  memcpy(X2, X0, 24 * sizeof(double));
  if (tst_pair_ext(p, spec, X0, tang, NULL, h1, info, R, NULL) != B2B_CONTACT_ACTIVE) return 0;
  if (target == ST_FRESH) {
    add_noise(rng, X2, 24, 1e-4);
    return 1;
  }
  double unit = MU * info[B2B_INFO_NORMAL_FORCE] / EPS_T;
  slide(rng, spec, tang, X0, info[B2B_INFO_XI], info[B2B_INFO_ETA],
        (target == ST_STICK ? 0.4 : tst_uniform(rng, 0.3, 2.5)) * unit, mode, X1);
  if (tst_pair_ext(p, spec, X1, tang, h1, hist, info, R, NULL) != B2B_CONTACT_ACTIVE) return 0;
  unit = MU * info[B2B_INFO_NORMAL_FORCE] / EPS_T;
  slide(rng, spec, tang, X1, info[B2B_INFO_XI], info[B2B_INFO_ETA],
        (target == ST_STICK ? 0.3 : tst_uniform(rng, 2.0, 3.0)) * unit, mode, X2);
  add_noise(rng, X2, 24, 1e-4);
  return 1;
}

/* ------------------------------------------------------ finite differences */

static double worst_tangent, worst_friction_part;
static int n_state[3], n_skipped;

static void reset(void) {
  worst_tangent = worst_friction_part = 0.0;
  n_state[0] = n_state[1] = n_state[2] = n_skipped = 0;
}

static void report(const char *name) {
  printf("%s: checked %d fresh, %d stick, %d slip (%d skipped: state changes under the "
         "smallest step); worst rel. error of the tangent %.2e, of its friction part %.2e\n",
         name, n_state[0], n_state[1], n_state[2], n_skipped, worst_tangent,
         worst_friction_part);
}

/* Tangent of the active pair at X (committed history hist held fixed)
 * against central differences of the residual, steps h and h/2 with one
 * Richardson step. Perturbations must keep the contact status and the
 * friction state; where they do not, the step is shrunk (twice, by 4) and
 * the configuration skipped if that does not help. p0 is the frictionless
 * parameter set of the same law: the friction part of the tangent, K - K0,
 * is checked on its own scale too. Returns the friction state, or -1
 * (not active) or -2 (skipped). */
static int fd_check(const b2b_params *p, const b2b_params *p0, const tst_pair_spec *spec,
                    const double tang[12], const double X[24], const double hist[HLEN], double h,
                    const char *what) {
  static double K[576], Kfd[576], K0[576];
  double info[32], R[24], info0[32], R0[24];
  const int status = tst_pair_ext(p, spec, X, tang, hist, NULL, info, R, K);
  if (status != B2B_CONTACT_ACTIVE) return -1;
  const int state = (int)info[B2B_INFO_FRICTION_STATE];
  ck_assert_msg(state == B2B_FRICTION_STICK || state == B2B_FRICTION_SLIP,
                "%s: friction state %d of an active pair", what, state);
  ck_assert_msg(info[B2B_INFO_SYMMETRIC] == 0.0, "%s: active pair with friction reports a "
                "symmetric tangent", what);
  const int anchored = hist[8] == 1.0;
  for (int a = 0; a < 24; ++a) {
    if (isnan(X[a])) continue;
    int ok = 0;
    double step = h;
    for (int attempt = 0; attempt < 3 && !ok; ++attempt, step *= 0.25) {
      double dR[2][24];
      ok = 1;
      for (int k = 0; k < 2 && ok; ++k) {
        const double s = k ? 0.5 * step : step;
        double Xp[24], Xm[24], ip[32], im[32], Rp[24], Rm[24];
        memcpy(Xp, X, sizeof Xp);
        memcpy(Xm, X, sizeof Xm);
        Xp[a] += s;
        Xm[a] -= s;
        const int sp = tst_pair_ext(p, spec, Xp, tang, hist, NULL, ip, Rp, NULL);
        const int sm = tst_pair_ext(p, spec, Xm, tang, hist, NULL, im, Rm, NULL);
        if (sp != status || sm != status || ip[B2B_INFO_FRICTION_STATE] != state ||
            im[B2B_INFO_FRICTION_STATE] != state) {
          ok = 0;
          break;
        }
        for (int r = 0; r < 24; ++r) dR[k][r] = (Rp[r] - Rm[r]) / (2 * s);
      }
      if (ok)
        for (int r = 0; r < 24; ++r) Kfd[r + 24 * a] = (4 * dR[1][r] - dR[0][r]) / 3;
    }
    if (!ok) {
      ++n_skipped;
      return -2;
    }
  }
  for (int a = 0; a < 24; ++a)
    if (isnan(X[a])) {
      ck_assert(R[a] == 0.0);
      for (int r = 0; r < 24; ++r) {
        ck_assert(K[r + 24 * a] == 0.0 && K[a + 24 * r] == 0.0);
        Kfd[r + 24 * a] = 0.0;
      }
    }
  const double f = info[B2B_INFO_NORMAL_FORCE];
  const double ek = tst_rel_diff(K, Kfd, 576, 1e-12 * f);
  worst_tangent = fmax(worst_tangent, ek);
  ck_assert_msg(ek <= TOL, "%s (%s): tangent vs FD of the residual, rel. error %.2e", what,
                state_name[anchored ? state : 0], ek);
  /* the friction part on its own scale */
  double hist0[HLEN];
  memcpy(hist0, hist, sizeof hist0);
  ck_assert_int_eq(tst_pair_ext(p0, spec, X, tang, hist0, NULL, info0, R0, K0),
                   B2B_CONTACT_ACTIVE);
  if (anchored) {
    double diff = 0.0, part = 0.0;
    for (int i = 0; i < 576; ++i) {
      diff = fmax(diff, fabs(K[i] - Kfd[i]));
      part = fmax(part, fabs(K[i] - K0[i]));
    }
    const double ef = diff / part;
    worst_friction_part = fmax(worst_friction_part, ef);
    ck_assert_msg(ef <= TOL, "%s (%s): tangent vs FD, error %.2e of the friction part",
                  what, state_name[state], ef);
  } else {
    /* T = 0 and no anchor: the frictionless tangent (up to rounding) */
    ck_assert_msg(tst_rel_diff(K, K0, 576, 0.0) <= 1e-12, "%s: fresh contact, tangent differs "
                  "from the frictionless one", what);
  }
  assert_balance(X, info, R, what);
  /* the return mapping's invariants */
  const double L = MU * f, t = norm3(info + B2B_INFO_TANGENTIAL_FORCE);
  if (state == B2B_FRICTION_SLIP)
    ck_assert_msg(fabs(t - L) <= 1e-12 * L, "%s: slip with |T| = %.17g, mu f_N = %.17g", what,
                  t, L);
  else
    ck_assert_msg(t <= L, "%s: stick with |T| = %g > mu f_N = %g", what, t, L);
  ck_assert(info[B2B_INFO_DISSIPATION] >= 0.0);
  ++n_state[anchored ? state : 0];
  return anchored ? state : ST_FRESH;
}

/* Every pair of kinds, both laws, interior segments, angles 20 .. 90. */
START_TEST(fd_all_kinds_both_laws) {
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 3001);
  int count[4][4][3];
  memset(count, 0, sizeof count);
  for (int law = 0; law < B2B_LAW_COUNT; ++law) {
    b2b_params *p = tst_params_friction(law, EPS_N, 0.05, MU, EPS_T);
    b2b_params *p0 = tst_params(law, EPS_N, 0.05);
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int target = 0; target < 3; ++target)
          for (int rep = 0; rep < 2; ++rep) {
            tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
            double X0[24], X1[24], X2[24], hist[HLEN], tang[12];
            const double angle = tst_uniform(&rng, 20, 90);
            const double dist = 0.35 - tst_uniform(&rng, law ? -0.02 : 0.02, 0.1);
            tst_crossing(&rng, &spec, 0.5, angle, tst_uniform(&rng, -0.6, 0.6),
                         tst_uniform(&rng, -0.6, 0.6), dist, X0);
            make_end_tangents(&rng, X0, tang);
            if (!prepare(&rng, p, &spec, tang, X0, target, 0, X1, X2, hist)) continue;
            char what[160];
            snprintf(what, sizeof what, "law %d, %s x %s, angle %.1f, aimed at %s", law,
                     tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), angle,
                     state_name[target]);
            const int st = fd_check(p, p0, &spec, tang, X2, hist, 1e-5, what);
            if (st >= 0) ++count[ka][kb][st];
          }
    b2b_params_destroy(&p);
    b2b_params_destroy(&p0);
  }
  report("all kinds, both laws");
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (int st = 0; st < 3; ++st)
        ck_assert_msg(count[ka][kb][st] > 0, "%s x %s: no %s configuration checked",
                      tst_kind_name(ka), tst_kind_name(kb),
                      state_name[st]);
  ck_assert_int_le(n_skipped, 10);
}
END_TEST

/* Crossing angles from 90 down to 5 degrees, slender beams (as in
 * check_pair_tangent: turning below the angle), stick and slip. */
START_TEST(fd_crossing_angles) {
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 3002);
  const double angles[] = {90, 45, 20, 10, 7, 5};
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  b2b_params *p0 = tst_params(B2B_LAW_LINEAR, EPS_N, 0.0);
  int count[B2B_CURVE_KIND_COUNT][3];
  memset(count, 0, sizeof count);
  for (size_t q = 0; q < sizeof angles / sizeof angles[0]; ++q)
    for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k)
      for (int target = 1; target < 3; ++target)
        for (int rep = 0; rep < 2; ++rep) {
          tst_pair_spec spec = {{k, (k + rep + target) % B2B_CURVE_KIND_COUNT}, {0, 0}, {0, 0},
                                {0.02, 0.015}};
          double X0[24], X1[24], X2[24], hist[HLEN], tang[12];
          const double rad = angles[q] * kPi / 180.0;
          tst_crossing(&rng, &spec, 0.25 * rad, angles[q], tst_uniform(&rng, -0.2, 0.2),
                       tst_uniform(&rng, -0.2, 0.2), 0.03, X0);
          make_end_tangents(&rng, X0, tang);
          char what[160];
          snprintf(what, sizeof what, "angle %g, %s x %s, aimed at %s", angles[q],
                   tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), state_name[target]);
          ck_assert_msg(prepare(&rng, p, &spec, tang, X0, target, 0, X1, X2, hist),
                        "%s: not active", what);
          const int st = fd_check(p, p0, &spec, tang, X2, hist, 1e-5 * sin(rad), what);
          ck_assert_msg(st != -1, "%s: not active", what);
          if (st >= 0) ++count[k][st];
        }
  b2b_params_destroy(&p);
  b2b_params_destroy(&p0);
  report("angles 90 .. 5 degrees");
  for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k)
    ck_assert_msg(count[k][ST_STICK] > 0 && count[k][ST_SLIP] > 0,
                  "%s: %d stick, %d slip configurations", tst_kind_name(k),
                  count[k][ST_STICK], count[k][ST_SLIP]);
  ck_assert_int_le(n_skipped, 4);
}
END_TEST

/* Closest points near segment joints (xi or eta = +-0.99), with the beam
 * ending there (REFLECT or TANGENT) or continuing (NEIGHBOUR); the other beam
 * slides so that the point near the joint stays where it is. */
START_TEST(fd_near_joints_and_beam_ends) {
  reset();
  tst_rng rng;
  tst_rng_seed(&rng, 3003);
  b2b_params *p = tst_params_friction(B2B_LAW_QUADRATIC, 5e2, 0.02, MU, EPS_T);
  b2b_params *p0 = tst_params(B2B_LAW_QUADRATIC, 5e2, 0.02);
  const double stars[] = {-0.99, 0.99};
  const int rules[] = {B2B_END_NEIGHBOUR, B2B_END_REFLECT, B2B_END_TANGENT};
  int count[3][3], near = 0;
  memset(count, 0, sizeof count);
  for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k)
    for (int beam = 0; beam < 2; ++beam)
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 2; ++s)
          for (int target = 1; target < 3; ++target) {
            tst_pair_spec spec = {{k, B2B_CURVE_KIND_COUNT - 1 - k}, {0, 0}, {0, 0},
                                  {0.2, 0.15}};
            /* placed with REFLECT (the same slots are read as with TANGENT;
             * tst_crossing has no host tangents), then the rule in force */
            const int placing = rules[r] == B2B_END_TANGENT ? B2B_END_REFLECT : rules[r];
            if (stars[s] < 0) spec.start_rule[beam] = placing;
            else spec.end_rule[beam] = placing;
            double X0[24], X1[24], X2[24], hist[HLEN], tang[12];
            const double other = tst_uniform(&rng, -0.5, 0.5);
            tst_crossing(&rng, &spec, 0.6, tst_uniform(&rng, 30, 90), beam ? other : stars[s],
                         beam ? stars[s] : other, 0.3, X0);
            if (stars[s] < 0) spec.start_rule[beam] = rules[r];
            else spec.end_rule[beam] = rules[r];
            make_end_tangents(&rng, X0, tang);
            if (!prepare(&rng, p, &spec, tang, X0, target, beam ? 2 : 1, X1, X2, hist))
              continue;
            char what[160];
            snprintf(what, sizeof what, "%s x %s, %s* %g, rule %d, aimed at %s",
                     tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]),
                     beam ? "eta" : "xi", stars[s], rules[r], state_name[target]);
            const int st = fd_check(p, p0, &spec, tang, X2, hist, 1e-5, what);
            if (st < 0) continue;
            ++count[r][st];
            double info[32], R[24];
            tst_pair_ext(p, &spec, X2, tang, hist, NULL, info, R, NULL);
            if (fabs(info[beam ? B2B_INFO_ETA : B2B_INFO_XI]) > 0.97) ++near;
          }
  b2b_params_destroy(&p);
  b2b_params_destroy(&p0);
  report("near joints and beam ends");
  printf("near joints and beam ends: %d checked with the point within 0.03 of the joint\n",
         near);
  for (int r = 0; r < 3; ++r)
    ck_assert_msg(count[r][ST_STICK] > 0 && count[r][ST_SLIP] > 0,
                  "end rule %d: %d stick, %d slip configurations", rules[r], count[r][ST_STICK],
                  count[r][ST_SLIP]);
  ck_assert_int_ge(near, 40);
  ck_assert_int_le(n_skipped, 4);
}
END_TEST

/* ------------------------------------------------------ closed-form laws */

/* Two straight beams: A along x with its point xi = 0 at the origin, B in the
 * plane z = dist at angle_deg to A with eta = 0 above the origin; radii 0.2
 * and 0.15 (gap dist - 0.35). The normal is -z. */
static void straight_pair(int kind_a, int kind_b, double angle_deg, double dist,
                          tst_pair_spec *spec, double X[24]) {
  const tst_pair_spec s = {{kind_a, kind_b}, {0, 0}, {0, 0}, {0.2, 0.15}};
  *spec = s;
  const double th = angle_deg * kPi / 180.0;
  const double dir[2][3] = {{1, 0, 0}, {cos(th), sin(th), 0}};
  const double at[2][3] = {{0, 0, 0}, {0, 0, dist}};
  for (int b = 0; b < 2; ++b) {
    double *P = X + 12 * b, x[9];
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) P[3 * k + i] = (k - 1.5) * dir[b][i];
    tst_eval(spec->kind[b], 0, 0, P, NULL, 0.0, x, NULL, NULL);
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) P[3 * k + i] += at[b][i] - x[i];
  }
}

static void translate(double *X, int first_node, int nodes, const double *d, double s) {
  for (int k = first_node; k < first_node + nodes; ++k)
    for (int i = 0; i < 3; ++i) X[3 * k + i] += s * d[i];
}

/* Press, then move A by a small delta along a direction d of the tangent
 * plane: T = eps_T delta d (the relative displacement of A, whatever the
 * direction), stick, no slip, no dissipation; moving B by -delta d instead
 * gives the same force. */
START_TEST(stick_law) {
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  int checked = 0;
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (int ang = 0; ang < 2; ++ang) {
        tst_pair_spec spec;
        double X0[24], info[32], R[24], h1[HLEN];
        straight_pair(ka, kb, ang ? 60.0 : 90.0, 0.3, &spec, X0);
        ck_assert_int_eq(tst_pair(p, &spec, X0, NULL, h1, info, R, NULL), B2B_CONTACT_ACTIVE);
        const double f = info[B2B_INFO_NORMAL_FORCE], L = MU * f;
        ck_assert(fabs(f - EPS_N * 0.05) <= 1e-9 * f);
        /* a new contact: stick, no force yet */
        ck_assert(info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK);
        for (int i = 0; i < 3; ++i)
          ck_assert(info[B2B_INFO_TANGENTIAL_FORCE + i] == 0.0 && info[B2B_INFO_SLIP + i] == 0.0);
        ck_assert(info[B2B_INFO_DISSIPATION] == 0.0);
        ck_assert(info[B2B_INFO_SYMMETRIC] == 0.0);
        for (int q = 0; q < 6; ++q) {
          const double phi = (10.0 + 60.0 * q) * kPi / 180.0;
          const double d[3] = {cos(phi), sin(phi), 0.0};
          const double delta = (0.3 + 0.1 * q) * L / EPS_T;
          double X1[24], i1[32], R1[24], h2[HLEN];
          memcpy(X1, X0, sizeof X1);
          translate(X1, 0, 4, d, delta);
          ck_assert_int_eq(tst_pair(p, &spec, X1, h1, h2, i1, R1, NULL), B2B_CONTACT_ACTIVE);
          char what[128];
          snprintf(what, sizeof what, "%s x %s at %g deg, direction %g deg",
                   tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), ang ? 60.0 : 90.0,
                   phi * 180 / kPi);
          ck_assert_msg(i1[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK, "%s: state %g", what,
                        i1[B2B_INFO_FRICTION_STATE]);
          ck_assert(fabs(i1[B2B_INFO_NORMAL_FORCE] - f) <= 1e-11 * f);
          const double *T = i1 + B2B_INFO_TANGENTIAL_FORCE;
          const double tn = norm3(T);
          ck_assert_msg(fabs(tn - EPS_T * delta) <= 1e-11 * EPS_T * delta,
                        "%s: |T| = %.17g, eps_T delta = %.17g", what, tn, EPS_T * delta);
          for (int i = 0; i < 3; ++i) {
            ck_assert_msg(fabs(T[i] - EPS_T * delta * d[i]) <= 1e-11 * tn,
                          "%s: T not along the displacement", what);
            ck_assert(i1[B2B_INFO_SLIP + i] == 0.0);
          }
          ck_assert(i1[B2B_INFO_DISSIPATION] == 0.0);
          ck_assert(h2[8] == 1.0 && h2[11] == B2B_FRICTION_STICK);
          assert_balance(X1, i1, R1, what);
          /* the same relative displacement by moving B the other way */
          double X2[24], i2[32], R2[24];
          memcpy(X2, X0, sizeof X2);
          translate(X2, 4, 4, d, -delta);
          ck_assert_int_eq(tst_pair(p, &spec, X2, h1, NULL, i2, R2, NULL), B2B_CONTACT_ACTIVE);
          for (int i = 0; i < 3; ++i)
            ck_assert_msg(fabs(i2[B2B_INFO_TANGENTIAL_FORCE + i] - T[i]) <= 1e-11 * tn,
                          "%s: moving B gives a different force", what);
          ++checked;
        }
      }
  b2b_params_destroy(&p);
  ck_assert_int_eq(checked, 16 * 2 * 6);
}
END_TEST

/* A larger displacement: |T| = mu f_N along the displacement, slip
 * increment (eps_T delta - mu f_N) / eps_T along T, dissipation mu f_N |slip|;
 * the friction force on A (-T) opposes A's slip. */
START_TEST(slip_law) {
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  int checked = 0;
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
      for (int ang = 0; ang < 2; ++ang) {
        tst_pair_spec spec;
        double X0[24], info[32], R[24], h1[HLEN];
        straight_pair(ka, kb, ang ? 60.0 : 90.0, 0.3, &spec, X0);
        ck_assert_int_eq(tst_pair(p, &spec, X0, NULL, h1, info, R, NULL), B2B_CONTACT_ACTIVE);
        const double f = info[B2B_INFO_NORMAL_FORCE], L = MU * f;
        for (int q = 0; q < 6; ++q) {
          const double phi = (25.0 + 60.0 * q) * kPi / 180.0;
          const double d[3] = {cos(phi), sin(phi), 0.0};
          const double delta = (1.5 + 0.5 * q) * L / EPS_T;
          double X1[24], i1[32], R1[24], h2[HLEN];
          memcpy(X1, X0, sizeof X1);
          translate(X1, 0, 4, d, delta);
          ck_assert_int_eq(tst_pair(p, &spec, X1, h1, h2, i1, R1, NULL), B2B_CONTACT_ACTIVE);
          char what[128];
          snprintf(what, sizeof what, "%s x %s at %g deg, direction %g deg",
                   tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), ang ? 60.0 : 90.0,
                   phi * 180 / kPi);
          ck_assert_msg(i1[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_SLIP, "%s: state %g", what,
                        i1[B2B_INFO_FRICTION_STATE]);
          const double *T = i1 + B2B_INFO_TANGENTIAL_FORCE, *slip = i1 + B2B_INFO_SLIP;
          ck_assert_msg(fabs(norm3(T) - L) <= 1e-12 * L, "%s: |T| = %.17g, mu f_N = %.17g",
                        what, norm3(T), L);
          const double want_slip = (EPS_T * delta - L) / EPS_T;
          for (int i = 0; i < 3; ++i) {
            ck_assert_msg(fabs(T[i] - L * d[i]) <= 1e-11 * L, "%s: T not along the slip", what);
            ck_assert_msg(fabs(slip[i] - want_slip * d[i]) <= 1e-11 * want_slip,
                          "%s: slip[%d] = %.17g, expected %.17g", what, i, slip[i],
                          want_slip * d[i]);
          }
          const double D = i1[B2B_INFO_DISSIPATION];
          ck_assert_msg(fabs(D - L * norm3(slip)) <= 1e-12 * L * want_slip,
                        "%s: dissipation %.17g, mu f_N |slip| = %.17g", what, D,
                        L * norm3(slip));
          ck_assert(fabs(D - L * want_slip) <= 1e-11 * L * want_slip);
          /* the tangential force on A (minus its residual) opposes A's motion */
          double sa[3], sb[3];
          nodal_sums(X1, R1, sa, sb);
          const double on_a[3] = {-sa[0], -sa[1], 0.0};
          ck_assert_msg(dot3(on_a, d) < -0.999 * L, "%s: friction on A along its slip", what);
          ck_assert(h2[8] == 1.0 && h2[11] == B2B_FRICTION_SLIP);
          assert_balance(X1, i1, R1, what);
          ++checked;
        }
      }
  b2b_params_destroy(&p);
  ck_assert_int_eq(checked, 16 * 2 * 6);
}
END_TEST

/* ------------------------------------------------------- loading history */

/* One step of the path: A's displacement increment (in the xy-plane) and
 * B's height (the axis distance: 0.3 pressed, 0.4 open). */
typedef struct {
  double du[2];
  double dist;
  int leg; /* 0 press, 1 pull +x, 2 reverse, 3 sideways, 4 release, 5 press again */
} path_step;

START_TEST(loading_history) {
  const double du = 0.0023; /* eps_T du = 1.84: no step lands on the limit */
  path_step path[80];
  int n = 0;
  path[n++] = (path_step){{0, 0}, 0.4, 0}; /* open */
  path[n++] = (path_step){{0, 0}, 0.3, 0}; /* press */
  for (int k = 0; k < 14; ++k) path[n++] = (path_step){{du, 0}, 0.3, 1};
  for (int k = 0; k < 26; ++k) path[n++] = (path_step){{-du, 0}, 0.3, 2};
  for (int k = 0; k < 6; ++k) path[n++] = (path_step){{0, du}, 0.3, 3};
  path[n++] = (path_step){{0, 0}, 0.4, 4};
  path[n++] = (path_step){{0, 0}, 0.3, 5};
  path[n++] = (path_step){{du, 0}, 0.3, 5};
  for (int law = 0; law < B2B_LAW_COUNT; ++law)
    for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k) {
      b2b_params *p = tst_params_friction(law, EPS_N, 0.02, MU, EPS_T);
      tst_pair_spec spec;
      double X[24], hold[HLEN] = {0}, hnew[HLEN], info[32], R[24];
      double ux = 0, uy = 0;
      /* the Coulomb model: committed force (x, y), anchored (in contact) */
      double Tm[2] = {0, 0}, total_D = 0, total_slip = 0, model_slip = 0;
      int anchored = 0, stick_in_leg[6] = {0}, slip_in_leg[6] = {0};
      double L = 0;
      for (int s = 0; s < n; ++s) {
        ux += path[s].du[0];
        uy += path[s].du[1];
        straight_pair(k, k, 90.0, path[s].dist, &spec, X);
        const double u[3] = {ux, uy, 0};
        translate(X, 0, 4, u, 1.0);
        const int st = tst_pair(p, &spec, X, hold, hnew, info, R, NULL);
        char what[128];
        snprintf(what, sizeof what, "law %d, %s, step %d (leg %d)", law,
                 tst_kind_name(k), s, path[s].leg);
        const double D = info[B2B_INFO_DISSIPATION];
        ck_assert_msg(D >= 0.0, "%s: dissipation %g", what, D);
        if (path[s].dist > 0.35 + 0.02 * law) {
          /* open: no force, no friction state, the history forgets */
          ck_assert_msg(st == B2B_CONTACT_OPEN, "%s: status %d", what, st);
          ck_assert(info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_NONE && D == 0.0);
          for (int i = 0; i < 3; ++i) ck_assert(info[B2B_INFO_TANGENTIAL_FORCE + i] == 0.0);
          ck_assert(tst_max_abs(R, 24) == 0.0);
          for (int i = 8; i < HLEN; ++i) ck_assert(hnew[i] == 0.0);
          Tm[0] = Tm[1] = 0;
          anchored = 0;
        } else {
          ck_assert_msg(st == B2B_CONTACT_ACTIVE, "%s: status %d", what, st);
          L = MU * info[B2B_INFO_NORMAL_FORCE];
          int want_state = B2B_FRICTION_STICK;
          double want_slip[2] = {0, 0}, want_D = 0;
          if (anchored) {
            const double tr[2] = {Tm[0] + EPS_T * path[s].du[0], Tm[1] + EPS_T * path[s].du[1]};
            const double trn = hypot(tr[0], tr[1]);
            ck_assert_msg(fabs(trn - L) > 1e-3 * L, "%s: the test's step is ambiguous", what);
            if (trn <= L) {
              Tm[0] = tr[0], Tm[1] = tr[1];
            } else {
              want_state = B2B_FRICTION_SLIP;
              for (int i = 0; i < 2; ++i) {
                want_slip[i] = (trn - L) / EPS_T * tr[i] / trn;
                Tm[i] = L * tr[i] / trn;
              }
              want_D = L * (trn - L) / EPS_T;
            }
          } else {
            Tm[0] = Tm[1] = 0;
          }
          anchored = 1;
          ck_assert_msg(info[B2B_INFO_FRICTION_STATE] == want_state, "%s: state %g, Coulomb: %d",
                        what, info[B2B_INFO_FRICTION_STATE], want_state);
          const double *T = info + B2B_INFO_TANGENTIAL_FORCE, *slip = info + B2B_INFO_SLIP;
          ck_assert_msg(fabs(T[0] - Tm[0]) <= 1e-10 * L && fabs(T[1] - Tm[1]) <= 1e-10 * L &&
                            fabs(T[2]) <= 1e-10 * L,
                        "%s: T = (%g, %g, %g), Coulomb (%g, %g)", what, T[0], T[1], T[2], Tm[0],
                        Tm[1]);
          ck_assert_msg(fabs(slip[0] - want_slip[0]) <= 1e-12 && fabs(slip[1] - want_slip[1]) <= 1e-12,
                        "%s: slip (%g, %g), Coulomb (%g, %g)", what, slip[0], slip[1],
                        want_slip[0], want_slip[1]);
          ck_assert_msg(fabs(D - want_D) <= 1e-10 * L * du, "%s: dissipation %g, Coulomb %g", what,
                        D, want_D);
          if (want_state == B2B_FRICTION_STICK) ++stick_in_leg[path[s].leg];
          else ++slip_in_leg[path[s].leg];
          model_slip += hypot(want_slip[0], want_slip[1]);
          assert_balance(X, info, R, what);
        }
        total_D += D;
        total_slip += norm3(info + B2B_INFO_SLIP);
        memcpy(hold, hnew, sizeof hold); /* commit */
      }
      /* The sequence Coulomb predicts: stick while eps_T |u| < mu f_N; on
       * reversal stick until the force has swung through 2 mu f_N; sideways
       * from the cone's edge: slip at once. */
      const int first = (int)floor(L / (EPS_T * du)), swing = (int)floor(2 * L / (EPS_T * du));
      char what[96];
      snprintf(what, sizeof what, "law %d, %s", law, tst_kind_name(k));
      ck_assert_msg(stick_in_leg[1] == first && slip_in_leg[1] == 14 - first,
                    "%s: pull: %d stick, %d slip steps; expected %d stick", what, stick_in_leg[1],
                    slip_in_leg[1], first);
      ck_assert_msg(stick_in_leg[2] == swing && slip_in_leg[2] == 26 - swing,
                    "%s: reversal: %d stick, %d slip steps; expected %d stick", what,
                    stick_in_leg[2], slip_in_leg[2], swing);
      ck_assert_msg(stick_in_leg[3] == 0 && slip_in_leg[3] == 6, "%s: sideways: %d stick", what,
                    stick_in_leg[3]);
      ck_assert(stick_in_leg[5] == 2); /* pressed again: a new contact, then stick */
      ck_assert(slip_in_leg[1] > 0 && slip_in_leg[2] > 0);
      /* total dissipation = mu f_N times the total plastic slip */
      ck_assert_msg(fabs(total_D - L * total_slip) <= 1e-10 * L * total_slip,
                    "%s: dissipated %.17g, mu f_N sum |slip| = %.17g", what, total_D,
                    L * total_slip);
      ck_assert(fabs(total_slip - model_slip) <= 1e-10 * model_slip);
      if (k == 0)
        printf("loading history (law %d): %d stick then %d slip steps, reversal %d stick then "
               "%d slip, sideways %d slip; dissipated %.6g = mu f_N x %.6g\n",
               law, stick_in_leg[1], slip_in_leg[1], stick_in_leg[2], slip_in_leg[2],
               slip_in_leg[3], total_D, total_slip);
      b2b_params_destroy(&p);
    }
}
END_TEST

/* ------------------------------------------------------------ objectivity */

/* Compares a result with that of the rigidly moved problem. */
static void assert_rotated(const double Q[9], const double X[24], const double i1[32],
                           const double R1[24], const double *K1, const double *h1,
                           const double i2[32], const double R2[24], const double *K2,
                           const double *h2, const char *what) {
  const double f = i1[B2B_INFO_NORMAL_FORCE], L = MU * f;
  ck_assert_msg(fabs(i1[B2B_INFO_XI] - i2[B2B_INFO_XI]) <= 1e-11 &&
                    fabs(i1[B2B_INFO_ETA] - i2[B2B_INFO_ETA]) <= 1e-11,
                "%s: closest points move", what);
  ck_assert(fabs(i1[B2B_INFO_GAP] - i2[B2B_INFO_GAP]) <= 1e-12);
  ck_assert(fabs(f - i2[B2B_INFO_NORMAL_FORCE]) <= 1e-11 * f);
  ck_assert_msg(i1[B2B_INFO_FRICTION_STATE] == i2[B2B_INFO_FRICTION_STATE], "%s: state %g vs %g",
                what, i1[B2B_INFO_FRICTION_STATE], i2[B2B_INFO_FRICTION_STATE]);
  const double t1 = norm3(i1 + B2B_INFO_TANGENTIAL_FORCE);
  ck_assert_msg(fabs(t1 - norm3(i2 + B2B_INFO_TANGENTIAL_FORCE)) <= 1e-10 * L,
                "%s: |T| %.17g vs %.17g", what, t1, norm3(i2 + B2B_INFO_TANGENTIAL_FORCE));
  ck_assert(fabs(i1[B2B_INFO_DISSIPATION] - i2[B2B_INFO_DISSIPATION]) <= 1e-10 * L * L / EPS_T);
  double want[3];
  tst_rotate(Q, i1 + B2B_INFO_TANGENTIAL_FORCE, want);
  ck_assert_msg(dist3(want, i2 + B2B_INFO_TANGENTIAL_FORCE) <= 1e-10 * L, "%s: T does not rotate",
                what);
  tst_rotate(Q, i1 + B2B_INFO_SLIP, want);
  ck_assert(dist3(want, i2 + B2B_INFO_SLIP) <= 1e-10 * L / EPS_T);
  for (int k = 0; k < 8; ++k) {
    if (isnan(X[3 * k])) continue;
    tst_rotate(Q, R1 + 3 * k, want);
    ck_assert_msg(dist3(want, R2 + 3 * k) <= 1e-10 * f, "%s: residual of node %d does not rotate",
                  what, k);
  }
  const double err = tst_tangent_rotation_error(Q, K1, K2);
  ck_assert_msg(err <= 1e-10 * tst_max_abs(K1, 576), "%s: tangent not objective: %g of %g", what,
                err, tst_max_abs(K1, 576));
  /* the history: the same anchors and force components, the normal rotated */
  ck_assert(fabs(h1[5] - h2[5]) <= 1e-11 && fabs(h1[6] - h2[6]) <= 1e-11);
  ck_assert(fabs(h1[9] - h2[9]) <= 1e-10 * L && fabs(h1[10] - h2[10]) <= 1e-10 * L);
  ck_assert(h1[8] == h2[8] && h1[11] == h2[11]);
  tst_rotate(Q, h1 + 2, want);
  ck_assert(dist3(want, h2 + 2) <= 1e-12);
}

/* Every step of a three-step history rigidly moved (each frame with its own
 * history): scalars unchanged, vectors, residual and tangent rotated. */
START_TEST(objectivity_of_every_step) {
  tst_rng rng;
  tst_rng_seed(&rng, 3004);
  b2b_params *p = tst_params_friction(B2B_LAW_QUADRATIC, EPS_N, 0.02, MU, EPS_T);
  int checked[3] = {0, 0, 0};
  for (int rep = 0; rep < 64; ++rep) {
    tst_pair_spec spec = {{TST_KIND_A(rep), TST_KIND_B(rep)}, {0, 0}, {0, 0}, {0.2, 0.15}};
    const int target = 1 + (rep / 16) % 2;
    double X0[24], X1[24], X2[24], hist[HLEN], tang[12];
    tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 20, 90), tst_uniform(&rng, -0.6, 0.6),
                 tst_uniform(&rng, -0.6, 0.6), 0.32, X0);
    make_end_tangents(&rng, X0, tang);
    if (!prepare(&rng, p, &spec, tang, X0, target, 0, X1, X2, hist)) continue;
    double Q[9], t[3], Y0[24], Y1[24], Y2[24], tangY[12];
    random_rotation(&rng, 0.1, 3.0, Q);
    for (int i = 0; i < 3; ++i) t[i] = tst_uniform(&rng, -10, 10);
    rigid_motion(Q, t, X0, 8, Y0);
    rigid_motion(Q, t, X1, 8, Y1);
    rigid_motion(Q, t, X2, 8, Y2);
    const double zero[3] = {0, 0, 0};
    rigid_motion(Q, zero, tang, 4, tangY);
    /* the rotated frame's own history */
    double g1[HLEN], g2[HLEN], i[32], r[24];
    ck_assert_int_eq(tst_pair_ext(p, &spec, Y0, tangY, NULL, g1, i, r, NULL),
                     B2B_CONTACT_ACTIVE);
    ck_assert_int_eq(tst_pair_ext(p, &spec, Y1, tangY, g1, g2, i, r, NULL), B2B_CONTACT_ACTIVE);
    static double K1[576], K2[576];
    double i1[32], i2[32], R1[24], R2[24], h1[HLEN], h2[HLEN];
    const int s1 = tst_pair_ext(p, &spec, X2, tang, hist, h1, i1, R1, K1);
    const int s2 = tst_pair_ext(p, &spec, Y2, tangY, g2, h2, i2, R2, K2);
    ck_assert_int_eq(s1, s2);
    if (s1 != B2B_CONTACT_ACTIVE) continue;
    char what[128];
    snprintf(what, sizeof what, "%s x %s, %s", tst_kind_name(spec.kind[0]),
             tst_kind_name(spec.kind[1]), state_name[(int)i1[B2B_INFO_FRICTION_STATE]]);
    assert_rotated(Q, X2, i1, R1, K1, h1, i2, R2, K2, h2, what);
    ++checked[(int)i1[B2B_INFO_FRICTION_STATE]];
  }
  b2b_params_destroy(&p);
  printf("objectivity: %d stick and %d slip configurations rigidly moved\n", checked[1],
         checked[2]);
  ck_assert_int_ge(checked[1], 15);
  ck_assert_int_ge(checked[2], 15);
}
END_TEST

/* A rigid motion of both beams within a step is no slip: with the committed
 * configuration rotated by 20 degrees and moved, a new contact keeps T = 0
 * and a stuck one keeps its force, turned with the beams. */
START_TEST(rigid_motion_within_a_step_is_no_slip) {
  tst_rng rng;
  tst_rng_seed(&rng, 3005);
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  int checked = 0;
  double worst_fresh = 0, worst_stuck = 0;
  for (int rep = 0; rep < 48; ++rep) {
    tst_pair_spec spec = {{TST_KIND_A(rep), TST_KIND_B(rep)}, {0, 0}, {0, 0}, {0.2, 0.15}};
    double X0[24], Xa[24], tang[12], h1[HLEN], h2[HLEN], info[32], ia[32], R[24];
    tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 30, 90), tst_uniform(&rng, -0.5, 0.5),
                 tst_uniform(&rng, -0.5, 0.5), 0.3, X0);
    make_end_tangents(&rng, X0, tang); /* not in force: NEIGHBOUR rules */
    if (tst_pair_ext(p, &spec, X0, tang, NULL, h1, info, R, NULL) != B2B_CONTACT_ACTIVE) continue;
    const double L = MU * info[B2B_INFO_NORMAL_FORCE];
    double Q[9], c[3], Y[24];
    random_rotation(&rng, 20 * kPi / 180, 20 * kPi / 180, Q);
    for (int i = 0; i < 3; ++i) c[i] = tst_uniform(&rng, -1, 1);
    char what[128];
    snprintf(what, sizeof what, "%s x %s", tst_kind_name(spec.kind[0]),
             tst_kind_name(spec.kind[1]));
    /* the committed configuration itself, moved: no slip, no force */
    rigid_motion(Q, c, X0, 8, Y);
    ck_assert_int_eq(tst_pair_ext(p, &spec, Y, tang, h1, NULL, info, R, NULL),
                     B2B_CONTACT_ACTIVE);
    ck_assert_msg(info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK, "%s: state %g", what,
                  info[B2B_INFO_FRICTION_STATE]);
    const double t0 = norm3(info + B2B_INFO_TANGENTIAL_FORCE);
    worst_fresh = fmax(worst_fresh, t0 / EPS_T);
    ck_assert_msg(t0 <= 1e-12 * EPS_T, "%s: rigid rotation gives |T| = %g (eps_T %g)", what, t0,
                  EPS_T);
    /* a stuck contact with a committed force, then a rigid motion */
    slide(&rng, &spec, tang, X0, info[B2B_INFO_XI], info[B2B_INFO_ETA], 0.6 * L / EPS_T, 0, Xa);
    if (tst_pair_ext(p, &spec, Xa, tang, h1, h2, ia, R, NULL) != B2B_CONTACT_ACTIVE) continue;
    ck_assert(ia[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK);
    const double ta = norm3(ia + B2B_INFO_TANGENTIAL_FORCE);
    ck_assert(ta > 0.4 * L);
    rigid_motion(Q, c, Xa, 8, Y);
    ck_assert_int_eq(tst_pair_ext(p, &spec, Y, tang, h2, NULL, info, R, NULL),
                     B2B_CONTACT_ACTIVE);
    ck_assert_msg(info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK, "%s: state %g", what,
                  info[B2B_INFO_FRICTION_STATE]);
    double want[3];
    tst_rotate(Q, ia + B2B_INFO_TANGENTIAL_FORCE, want);
    const double e = dist3(want, info + B2B_INFO_TANGENTIAL_FORCE);
    worst_stuck = fmax(worst_stuck, e / ta);
    ck_assert_msg(e <= 1e-10 * ta, "%s: stuck force %g changes by %g under a rigid motion", what,
                  ta, e);
    for (int i = 0; i < 3; ++i) ck_assert(info[B2B_INFO_SLIP + i] == 0.0);
    ck_assert(info[B2B_INFO_DISSIPATION] == 0.0);
    ++checked;
  }
  b2b_params_destroy(&p);
  printf("rigid motion within a step (20 deg): %d pairs; |T| / eps_T of a new contact at most "
         "%.2e, change of a stuck force at most %.2e (relative)\n",
         checked, worst_fresh, worst_stuck);
  ck_assert_int_ge(checked, 30);
}
END_TEST

/* -------------------------------------------------- mu = 0 is frictionless */

START_TEST(zero_friction_is_frictionless_bit_for_bit) {
  tst_rng rng;
  tst_rng_seed(&rng, 3006);
  int active = 0;
  for (int law = 0; law < B2B_LAW_COUNT; ++law) {
    b2b_params *none = tst_params(law, EPS_N, 0.05);
    b2b_params *zero[2] = {tst_params_friction(law, EPS_N, 0.05, 0.0, 0.0),
                           tst_params_friction(law, EPS_N, 0.05, 0.0, EPS_T)};
    ck_assert_int_eq(tst_history_len(none), 8);
    ck_assert_int_eq(tst_history_len(zero[0]), 8);
    ck_assert_int_eq(tst_history_len(zero[1]), 8);
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int rep = 0; rep < 2; ++rep) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          double X[2][24], tang[12];
          tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 20, 90), tst_uniform(&rng, -0.6, 0.6),
                       tst_uniform(&rng, -0.6, 0.6), 0.35 - tst_uniform(&rng, -0.02, 0.1),
                       X[0]);
          make_end_tangents(&rng, X[0], tang);
          slide(&rng, &spec, tang, X[0], 0.0, 0.0, 0.01, 0, X[1]);
          double h_ref[8] = {0}, h_z[2][8];
          memset(h_z, 0, sizeof h_z);
          for (int step = 0; step < 2; ++step) {
            static double K_ref[576], K_z[576];
            double i_ref[32], R_ref[24], hn_ref[8];
            const int s_ref = tst_pair_ext(none, &spec, X[step], tang, h_ref, hn_ref, i_ref,
                                           R_ref, K_ref);
            for (int z = 0; z < 2; ++z) {
              double i_z[32], R_z[24], hn_z[8];
              const int s_z =
                  tst_pair_ext(zero[z], &spec, X[step], tang, h_z[z], hn_z, i_z, R_z, K_z);
              char what[128];
              snprintf(what, sizeof what, "law %d, %s x %s, step %d, mu = 0 %s", law,
                       tst_kind_name(spec.kind[0]), tst_kind_name(spec.kind[1]), step,
                       z ? "with eps_T" : "alone");
              ck_assert_msg(s_z == s_ref, "%s: status %d vs %d", what, s_z, s_ref);
              ck_assert_msg(memcmp(i_z, i_ref, sizeof i_z) == 0, "%s: info differs", what);
              ck_assert_msg(memcmp(R_z, R_ref, sizeof R_z) == 0, "%s: residual differs", what);
              ck_assert_msg(memcmp(K_z, K_ref, sizeof K_z) == 0, "%s: tangent differs", what);
              ck_assert_msg(memcmp(hn_z, hn_ref, sizeof hn_z) == 0, "%s: history differs", what);
              memcpy(h_z[z], hn_z, sizeof hn_z);
            }
            if (s_ref == B2B_CONTACT_ACTIVE) ++active;
            memcpy(h_ref, hn_ref, sizeof h_ref);
          }
        }
    b2b_params_destroy(&none);
    b2b_params_destroy(&zero[0]);
    b2b_params_destroy(&zero[1]);
  }
  ck_assert_int_ge(active, 60);
}
END_TEST

/* mu > 0, a contact that was not active in the committed step: T = 0, the
 * frictionless residual (bit for bit; == also equates the signs of zeros),
 * the frictionless tangent up to rounding, the friction slots of info and
 * history as documented. Also an open pair. */
START_TEST(fresh_contact_with_friction_is_frictionless) {
  tst_rng rng;
  tst_rng_seed(&rng, 3007);
  int active = 0, open = 0;
  double worst = 0;
  for (int law = 0; law < B2B_LAW_COUNT; ++law) {
    b2b_params *none = tst_params(law, EPS_N, 0.05);
    b2b_params *fric = tst_params_friction(law, EPS_N, 0.05, MU, EPS_T);
    ck_assert_int_eq(tst_history_len(fric), 12);
    for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
      for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
        for (int rep = 0; rep < 3; ++rep) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          double X[24], tang[12];
          tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 20, 90), tst_uniform(&rng, -0.6, 0.6),
                       tst_uniform(&rng, -0.6, 0.6), 0.35 - tst_uniform(&rng, -0.1, 0.1), X);
          make_end_tangents(&rng, X, tang);
          static double K0[576], K1[576];
          double i0[32], i1[32], R0[24], R1[24], h0[8], h1[HLEN];
          const int s0 = tst_pair_ext(none, &spec, X, tang, NULL, h0, i0, R0, K0);
          const int s1 = tst_pair_ext(fric, &spec, X, tang, NULL, h1, i1, R1, K1);
          char what[128];
          snprintf(what, sizeof what, "law %d, %s x %s", law, tst_kind_name(spec.kind[0]),
                   tst_kind_name(spec.kind[1]));
          ck_assert_int_eq(s0, s1);
          for (int r = 0; r < 24; ++r)
            ck_assert_msg(R1[r] == R0[r], "%s: residual[%d] %.17g vs %.17g", what, r, R1[r],
                          R0[r]);
          ck_assert_msg(memcmp(h1, h0, sizeof h0) == 0, "%s: history[0..7] differs", what);
          for (int i = 0; i < 32; ++i) {
            if (i == B2B_INFO_SYMMETRIC || i == B2B_INFO_FRICTION_STATE) continue;
            ck_assert_msg(i1[i] == i0[i], "%s: info[%d] %.17g vs %.17g", what, i, i1[i], i0[i]);
          }
          if (s1 == B2B_CONTACT_ACTIVE) {
            ++active;
            ck_assert(i1[B2B_INFO_SYMMETRIC] == 0.0 && i0[B2B_INFO_SYMMETRIC] == 1.0);
            ck_assert(i1[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK);
            ck_assert(h1[8] == 1.0 && h1[9] == 0.0 && h1[10] == 0.0 &&
                      h1[11] == B2B_FRICTION_STICK);
            const double e = tst_rel_diff(K1, K0, 576, 0.0);
            worst = fmax(worst, e);
            ck_assert_msg(e <= 1e-13, "%s: tangent differs by %.2e", what, e);
          } else {
            if (s1 == B2B_CONTACT_OPEN) ++open;
            ck_assert(i1[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_NONE);
            ck_assert(memcmp(i1, i0, sizeof i0) == 0);
            ck_assert(memcmp(K1, K0, sizeof K0) == 0);
            for (int i = 8; i < HLEN; ++i) ck_assert(h1[i] == 0.0);
          }
        }
    b2b_params_destroy(&none);
    b2b_params_destroy(&fric);
  }
  printf("fresh contacts with friction: %d active, %d open; tangent differs from the "
         "frictionless one by at most %.2e (relative)\n",
         active, open, worst);
  ck_assert_int_ge(active, 60);
  ck_assert_int_ge(open, 5);
}
END_TEST

/* ------------------------------------------- sliding across a joint: handover */

#define ARC_N 9
#define ARC_R 4.0
/* non-uniform spacing: the parametric speeds differ on the two sides of a
 * joint, so the handover's rescaling matters */
static const double arc_phi[ARC_N] = {0, 0.22, 0.50, 0.72, 1.0, 1.22, 1.50, 1.72, 2.0};

/* The pair of arc segment s and the probe (a straight LINEAR segment along z
 * through polar angle phi, axis distance 4.12 from the arc's centre: radii
 * 0.1 and 0.1, penetration 0.08 on the nodal curves, about 0.04 where the
 * midpoint curve cuts a corner). arc_is_b: the arc is beam B. */
static void arc_pair(int kind, int s, double phi, int arc_is_b, tst_pair_spec *spec,
                     double X[24]) {
  double coords[3 * ARC_N];
  for (int k = 0; k < ARC_N; ++k) {
    coords[3 * k] = ARC_R * cos(arc_phi[k]);
    coords[3 * k + 1] = ARC_R * sin(arc_phi[k]);
    coords[3 * k + 2] = 0.0;
  }
  const int a = arc_is_b ? 1 : 0, b = 1 - a;
  const tst_pair_spec s0 = {{0, 0}, {0, 0}, {0, 0}, {0.1, 0.1}};
  *spec = s0;
  spec->kind[a] = kind;
  spec->kind[b] = B2B_CURVE_LINEAR;
  tst_gather_patch(kind, ARC_N, 0, s, coords, X + 12 * a, &spec->start_rule[a],
                   &spec->end_rule[a]);
  double *P = X + 12 * b;
  const double rho = ARC_R + 0.2 - 0.08;
  for (int i = 0; i < 3; ++i) P[i] = P[9 + i] = NAN;
  P[3] = P[6] = rho * cos(phi);
  P[4] = P[7] = rho * sin(phi);
  P[5] = -0.5;
  P[8] = 0.5;
}

typedef struct {
  int crossings, state_at_crossing, slip_steps;
  double jump, neighbours, force_at_crossing, L;
  double kink, kink_around; /* second differences of T at the joint, and near it */
} sweep_result;

/* Slides the probe over the arc in `steps` committed steps of dphi, starting
 * `before` steps before the joint at joint_phi. Each step evaluates every
 * arc segment: the owner with the committed history, its neighbours with
 * the committed history handed over, the others fresh; exactly one must be
 * active, and it is committed. */
static void slide_over_joint(int kind, int arc_is_b, double eps_t, double joint_phi, double dphi,
                             int before, int steps, sweep_result *res) {
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, eps_t);
  int nseg;
  ck_assert_int_eq(b2b_beam_segment_count(kind, ARC_N, 0, &nseg, NULL, 0), B2B_OK);
  const int beam = arc_is_b ? 1 : 0;
  int owner = -1, cross = -1;
  double hc[HLEN] = {0}, Tprev[3] = {0, 0, 0}, change[400], Ts[400][3];
  ck_assert(steps < 400);
  memset(res, 0, sizeof *res);
  for (int step = 0; step <= steps; ++step) {
    const double phi = joint_phi + (step - before) * dphi;
    int found = -1;
    double T[3], hn[HLEN], info[32];
    for (int s = 0; s < nseg; ++s) {
      tst_pair_spec spec;
      double X[24], hold[HLEN] = {0}, h[HLEN], i[32], R[24];
      arc_pair(kind, s, phi, arc_is_b, &spec, X);
      if (owner >= 0 && s == owner) {
        memcpy(hold, hc, sizeof hold);
      } else if (owner >= 0 && abs(s - owner) == 1) {
        tst_pair_spec from;
        double Xf[24];
        arc_pair(kind, owner, phi, arc_is_b, &from, Xf);
        const int seg_from[3] = {from.kind[beam], from.start_rule[beam], from.end_rule[beam]};
        const int seg_to[3] = {spec.kind[beam], spec.start_rule[beam], spec.end_rule[beam]};
        char msg[B2B_ERRMSG_LEN] = "";
        const int st = b2b_pair_history_handover(p, beam, s - owner, seg_from, Xf + 12 * beam,
                                                 NULL, seg_to, X + 12 * beam, NULL, hc, hold,
                                                 HLEN, msg, sizeof msg);
        ck_assert_msg(st == B2B_OK, "handover %d -> %d: %s", owner, s, msg);
      }
      if (tst_pair(p, &spec, X, hold, h, i, R, NULL) != B2B_CONTACT_ACTIVE) continue;
      ck_assert_msg(found < 0, "%s: segments %d and %d both hold the contact at phi %g",
                    tst_kind_name(kind), found, s, phi);
      found = s;
      memcpy(hn, h, sizeof hn);
      memcpy(info, i, sizeof info);
      memcpy(T, i + B2B_INFO_TANGENTIAL_FORCE, sizeof T);
      if (owner >= 0 && s != owner) {
        /* without the handover the new owner starts afresh: the force drops to 0 */
        double i2[32], R2[24];
        ck_assert_int_eq(tst_pair(p, &spec, X, NULL, NULL, i2, R2, NULL), B2B_CONTACT_ACTIVE);
        for (int c = 0; c < 3; ++c) ck_assert(i2[B2B_INFO_TANGENTIAL_FORCE + c] == 0.0);
      }
    }
    ck_assert_msg(found >= 0, "%s: contact lost at phi %g", tst_kind_name(kind), phi);
    const double L = MU * info[B2B_INFO_NORMAL_FORCE];
    const int state = (int)info[B2B_INFO_FRICTION_STATE];
    if (state == B2B_FRICTION_SLIP) {
      ++res->slip_steps;
      /* the friction force on the arc opposes its motion relative to the
       * probe, i.e. it is along the probe's motion */
      const double v[3] = {-sin(phi) * dphi, cos(phi) * dphi, 0.0};
      const double on_arc = arc_is_b ? dot3(T, v) : -dot3(T, v);
      ck_assert_msg(on_arc > 0.0, "%s: friction on the arc against the probe's motion",
                    tst_kind_name(kind));
    }
    change[step] = step > 0 ? dist3(T, Tprev) : 0.0;
    memcpy(Ts[step], T, sizeof T);
    if (owner >= 0 && found != owner) {
      ++res->crossings;
      cross = step;
      res->state_at_crossing = state;
      res->force_at_crossing = norm3(T);
      res->L = L;
    }
    memcpy(hc, hn, sizeof hc); /* commit */
    owner = found;
    memcpy(Tprev, T, sizeof Tprev);
  }
  ck_assert_msg(cross > 1 && cross < steps, "%s: the contact did not cross a joint",
                tst_kind_name(kind));
  res->jump = change[cross];
  res->neighbours = fmax(change[cross - 1], change[cross + 1]);
  /* second differences |T(k+1) - 2 T(k) + T(k-1)|: at the joint (k = cross or
   * cross - 1), and at the other steps within 10 of it */
  ck_assert(cross >= 12 && cross + 12 <= steps);
  for (int k = cross - 11; k <= cross + 10; ++k) {
    double d2 = 0;
    for (int i = 0; i < 3; ++i) {
      const double v = Ts[k + 1][i] - 2 * Ts[k][i] + Ts[k - 1][i];
      d2 += v * v;
    }
    d2 = sqrt(d2);
    if (k == cross || k == cross - 1) res->kink = fmax(res->kink, d2);
    else res->kink_around = fmax(res->kink_around, d2);
  }
  b2b_params_destroy(&p);
}

START_TEST(sliding_across_a_joint_with_handover) {
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    /* The kinds with a continuous tangent: the chord's kinks at the joint. */
    if (tst_kind_family(kind) == TST_CHORD) continue;
    /* the joint: node 4, or for a kind centred on nodes (midpoint) the middle
     * of element 3-4 (near its polar angle; the crossing is found, not
     * assumed) */
    const double joint =
        tst_kind_family(kind) == TST_CENTRED ? 0.5 * (arc_phi[3] + arc_phi[4]) : arc_phi[4];
    for (int arc_is_b = 0; arc_is_b < 2; ++arc_is_b)
      for (int dir = -1; dir <= 1; dir += 2)
        for (int stick = 0; stick < 2; ++stick) {
          /* slip: eps_T 800, slip after a few steps, the joint after 30;
           * stick: eps_T 40, the joint after 30 steps (|T| = 4.8, mu f_N 12 ..
           * 24), slip before step 200 */
          const double eps_t = stick ? 40.0 : EPS_T, dphi = dir * 1e-3;
          sweep_result r;
          slide_over_joint(kind, arc_is_b, eps_t, joint, dphi, 30, 200, &r);
          char what[128];
          snprintf(what, sizeof what, "%s (arc is beam %c), direction %+d, %s", tst_kind_name(kind),
                   arc_is_b ? 'B' : 'A', dir, stick ? "stick then slip" : "slip");
          printf("%s: joint crossed in %s with |T| = %.3g (mu f_N %.3g): change %.2e, "
                 "neighbouring steps %.2e; second difference %.2e, near the joint %.2e\n",
                 what, state_name[r.state_at_crossing], r.force_at_crossing, r.L, r.jump,
                 r.neighbours, r.kink, r.kink_around);
          ck_assert_msg(r.crossings == 1, "%s: %d crossings", what, r.crossings);
          ck_assert_msg(r.state_at_crossing == (stick ? B2B_FRICTION_STICK : B2B_FRICTION_SLIP),
                        "%s: crossed in state %d", what, r.state_at_crossing);
          ck_assert_msg(r.force_at_crossing > 0.15 * r.L, "%s: |T| %g at the joint", what,
                        r.force_at_crossing);
          ck_assert(r.slip_steps > 0);
          ck_assert_msg(r.neighbours > 0 && r.jump <= 3 * r.neighbours,
                        "%s: the force changes by %g across the joint, %g in the steps around "
                        "it",
                        what, r.jump, r.neighbours);
          /* In stick the force follows the anchor: its rate of change is
           * continuous across the joint (the second difference there below a
           * tenth of the step's change) only if the handover keeps the
           * anchor's arc length to the joint (the s_from / s_to rescaling). */
          if (stick)
            ck_assert_msg(r.kink <= 0.1 * r.neighbours,
                          "%s: second difference of the force %g at the joint, step change %g",
                          what, r.kink, r.neighbours);
        }
  }
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("pair_friction");
  TCase *fd = tcase_create("finite_differences");
  tcase_set_timeout(fd, 300);
  tcase_add_test(fd, fd_all_kinds_both_laws);
  tcase_add_test(fd, fd_crossing_angles);
  tcase_add_test(fd, fd_near_joints_and_beam_ends);
  suite_add_tcase(s, fd);
  TCase *law = tcase_create("coulomb_law");
  tcase_set_timeout(law, 300);
  tcase_add_test(law, stick_law);
  tcase_add_test(law, slip_law);
  tcase_add_test(law, loading_history);
  tcase_add_test(law, objectivity_of_every_step);
  tcase_add_test(law, rigid_motion_within_a_step_is_no_slip);
  tcase_add_test(law, zero_friction_is_frictionless_bit_for_bit);
  tcase_add_test(law, fresh_contact_with_friction_is_frictionless);
  tcase_add_test(law, sliding_across_a_joint_with_handover);
  suite_add_tcase(s, law);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
