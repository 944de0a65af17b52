/* Line contact in the contact model (b2b_model.h "Line contact"; group
 * pairs of "contact_type" LINE or ALL_ANGLE).
 *   - two parallel straight beams pressed together, every curve kind: the
 *     integrated normal force is eps_L * penetration * overlap length, the
 *     residuals balance, every integration point of A is counted once
 *     (totals[B2B_TOTAL_LINE_POINTS] = segments of A under B x points),
 *     counts[B2B_COUNT_LINE] = ACTIVE, and without line contact (POINT) the
 *     same scene is PARALLEL, held only by A's end nodes (end contact) with
 *     a fraction of the force (what line contact is for); the
 *     interpenetration audit finds nothing uncarried with line contact;
 *   - the model's contact equals b2b_pair_eval_line on the same segments
 *     (residual, tangent, force: bit for bit);
 *   - friction: B slid along A across several of B's joints in small
 *     committed steps: after the first steps every point slips, the
 *     friction force stays mu times the normal force to 1e-9 and keeps its
 *     direction across the joints (the points' histories are taken over
 *     by the pair of B's next segment), nothing is lost;
 *   - commit / revert / save / restore: a restored model continues bit for
 *     bit; a revert reproduces the update after it;
 *   - threads: 1 and 2 threads give the same bytes;
 *   - ALL_ANGLE: A turned over B from 90 to 0 degrees at a fixed
 *     penetration, the total normal force continuous in the angle;
 *   - ALL_ANGLE at 90 degrees (the point element): its friction history
 *     follows the point across joints of B and of A;
 *   - tunnelling: A moved through B in one step comes back active on its
 *     committed side, every contact counted crossed (LINE and ALL_ANGLE);
 *   - a line set may replace a line set, not a point set (B2B_ERR_SIZE). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_support.h"

#define R 0.05
#define EPS_L 4e3
#define EPS_N 2e2
#define MU 0.25
#define EPS_LT 3e3
#define NSEG 8

static b2b_params *params_of(int type, double mu) {
  b2b_params *p = NULL;
  char msg[B2B_ERRMSG_LEN];
  ck_assert(b2b_params_create(&p, msg, sizeof msg) == B2B_OK);
  b2b_params_set_real(p, "penalty", EPS_N, msg, sizeof msg);
  ck_assert(b2b_params_set_int(p, "contact_type", type, msg, sizeof msg) == B2B_OK);
  b2b_params_set_real(p, "line_penalty", EPS_L, msg, sizeof msg);
  b2b_params_set_int(p, "line_points", 6, msg, sizeof msg);
  if (mu > 0) {
    b2b_params_set_real(p, "friction", mu, msg, sizeof msg);
    b2b_params_set_real(p, "tangential_penalty", 1e3, msg, sizeof msg);
    b2b_params_set_real(p, "line_tangential_penalty", EPS_LT, msg, sizeof msg);
  }
  ck_assert_msg(b2b_params_finalize(p, msg, sizeof msg) == B2B_OK, "%s", msg);
  return p;
}

/* Beam A: nodes 0 .. NSEG along x from 0 to 1 at height d; beam B: nodes
 * NSEG+1 .. 2 NSEG+1 along x from x0 to x0 + len at height 0, of nb
 * elements. */
typedef struct {
  double x[3 * 64];
  int nodes_a[NSEG + 1], nodes_b[40], nb;
} scene2;

static void place(scene2 *s, double d, double x0, double len, int nb, double angle_deg) {
  const double th = angle_deg * 3.14159265358979323846 / 180.0;
  s->nb = nb;
  for (int k = 0; k <= NSEG; ++k) {
    s->nodes_a[k] = k;
    const double t = (double)k / NSEG - 0.5;
    s->x[3 * k] = 0.5 + t * cos(th);
    s->x[3 * k + 1] = t * sin(th);
    s->x[3 * k + 2] = d;
  }
  for (int k = 0; k <= nb; ++k) {
    const int node = NSEG + 1 + k;
    s->nodes_b[k] = node;
    s->x[3 * node] = x0 + len * k / nb;
    s->x[3 * node + 1] = 0;
    s->x[3 * node + 2] = 0;
  }
}

static b2b_model *model_of(const scene2 *s, const b2b_params *p, int kind) {
  b2b_model *m = NULL;
  char msg[B2B_ERRMSG_LEN];
  int beam;
  ck_assert(b2b_model_create(&m, msg, sizeof msg) == B2B_OK);
  ck_assert_msg(b2b_model_add_beam(m, s->nodes_a, NSEG + 1, 0, R, kind, 0, &beam, msg,
                                   sizeof msg) == B2B_OK, "%s", msg);
  ck_assert(b2b_model_add_beam(m, s->nodes_b, s->nb + 1, 0, R, kind, 1, &beam, msg,
                               sizeof msg) == B2B_OK);
  ck_assert(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg) == B2B_OK);
  ck_assert(b2b_model_finalize(m, NSEG + 2 + s->nb, msg, sizeof msg) == B2B_OK);
  return m;
}

static void update(b2b_model *m, const scene2 *s, int want_tangent) {
  char msg[B2B_ERRMSG_LEN];
  ck_assert_msg(b2b_model_update(m, s->x, 3, NSEG + 2 + s->nb, want_tangent, msg, sizeof msg) ==
                    B2B_OK, "%s", msg);
}

static void stats(const b2b_model *m, int counts[16], double totals[8]) {
  char msg[B2B_ERRMSG_LEN];
  ck_assert(b2b_model_stats(m, counts, totals, msg, sizeof msg) == B2B_OK);
}

/* The sum of the contacts' residuals per host node, 3 x n_nodes. */
static void nodal_forces(const b2b_model *m, int n_nodes, double *f) {
  char msg[B2B_ERRMSG_LEN];
  int n = 0;
  memset(f, 0, 3 * (size_t)n_nodes * sizeof(double));
  b2b_model_contact_count(m, &n, msg, sizeof msg);
  for (int c = 0; c < n; ++c) {
    int nodes[8], pair[4];
    double info[32], res[24];
    ck_assert(b2b_model_get_contact(m, c, nodes, pair, info, res, NULL, 24, msg, sizeof msg) ==
              B2B_OK);
    for (int k = 0; k < 8; ++k)
      if (nodes[k] >= 0)
        for (int i = 0; i < 3; ++i) f[3 * nodes[k] + i] += res[3 * k + i];
  }
}

/* A's integration points: its segments (b2b_beam_segment_count) x 6. */
static int a_points(const scene2 *s, int kind) {
  (void)s;
  int n = 0;
  char msg[B2B_ERRMSG_LEN];
  ck_assert(b2b_beam_segment_count(kind, NSEG + 1, 0, &n, msg, sizeof msg) == B2B_OK);
  return 6 * n;
}

START_TEST(parallel_beams_closed_form) {
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    b2b_params *p = params_of(B2B_CONTACT_TYPE_LINE, 0);
    scene2 s;
    const double pen = 0.004;
    place(&s, 2 * R - pen, -0.5, 2.0, 12, 0.0); /* B longer than A on both sides */
    b2b_model *m = model_of(&s, p, kind);
    update(m, &s, 1);
    int counts[16];
    double totals[8];
    stats(m, counts, totals);
    const double F = EPS_L * pen * 1.0;
    ck_assert_msg(fabs(totals[B2B_TOTAL_NORMAL_FORCE] - F) <= 1e-9 * F,
                  "%s: total force %.15g, closed form %.15g", tst_kind_name(kind),
                  totals[B2B_TOTAL_NORMAL_FORCE], F);
    ck_assert_msg(totals[B2B_TOTAL_LINE_POINTS] == a_points(&s, kind),
                  "%s: %g points carry force, want %d", tst_kind_name(kind),
                  totals[B2B_TOTAL_LINE_POINTS], a_points(&s, kind));
    ck_assert_int_eq(counts[B2B_COUNT_LINE], counts[B2B_COUNT_ACTIVE]);
    ck_assert_int_ge(counts[B2B_COUNT_ACTIVE], NSEG);
    ck_assert_msg(fabs(totals[B2B_TOTAL_MIN_GAP] + pen) <= 1e-12, "min gap %g",
                  totals[B2B_TOTAL_MIN_GAP]);
    /* balance: forces on A and on B opposite; A's push up by F */
    double f[3 * 64], fa[3] = {0, 0, 0}, fb[3] = {0, 0, 0};
    nodal_forces(m, NSEG + 2 + s.nb, f);
    for (int k = 0; k <= NSEG; ++k)
      for (int i = 0; i < 3; ++i) fa[i] += f[3 * k + i];
    for (int k = NSEG + 1; k < NSEG + 2 + s.nb; ++k)
      for (int i = 0; i < 3; ++i) fb[i] += f[3 * k + i];
    ck_assert_msg(fabs(fa[2] + F) <= 1e-9 * F && fabs(fb[2] - F) <= 1e-9 * F,
                  "%s: resultants %g on A, %g on B, want %g", tst_kind_name(kind), fa[2], fb[2],
                  -F);
    for (int i = 0; i < 3; ++i) ck_assert(fabs(fa[i] + fb[i]) <= 1e-10 * F);
    /* the interpenetration audit sees the overlap carried */
    int n_found = -1;
    char msg[B2B_ERRMSG_LEN];
    ck_assert(b2b_model_audit(m, 0.01, &n_found, NULL, NULL, NULL, 0, msg, sizeof msg) == B2B_OK);
    ck_assert_msg(n_found == 0, "%s: the audit finds %d overlaps without force", tst_kind_name(kind),
                  n_found);
    b2b_model_destroy(&m);
    b2b_params_destroy(&p);
    /* point contact only: PARALLEL, no force */
    p = params_of(B2B_CONTACT_TYPE_POINT, 0);
    m = model_of(&s, p, kind);
    update(m, &s, 0);
    stats(m, counts, totals);
    if (kind == B2B_CURVE_LINEAR) {
      ck_assert_int_gt(counts[B2B_COUNT_PARALLEL], 0);
      ck_assert_msg(totals[B2B_TOTAL_NORMAL_FORCE] < 0.5 * F,
                    "point contact carried %g of %g on parallel beams",
                    totals[B2B_TOTAL_NORMAL_FORCE], F);
    }
    ck_assert_int_eq(counts[B2B_COUNT_LINE], 0);
    b2b_model_destroy(&m);
    b2b_params_destroy(&p);
  }
}
END_TEST

START_TEST(model_equals_pair_element) {
  b2b_params *p = params_of(B2B_CONTACT_TYPE_LINE, MU);
  scene2 s;
  place(&s, 2 * R - 0.003, -0.4, 1.9, 9, 1.0);
  b2b_model *m = model_of(&s, p, B2B_CURVE_HERMITE_NODAL);
  update(m, &s, 1);
  char msg[B2B_ERRMSG_LEN];
  int n = 0;
  b2b_model_contact_count(m, &n, msg, sizeof msg);
  ck_assert_int_ge(n, 4);
  for (int c = 0; c < n; ++c) {
    int nodes[8], pair[4], status;
    double info[32], res[24], K[576], X[24], li[16], res2[24], K2[576];
    static double ho[7 * 12], hn[7 * 12];
    b2b_model_get_contact(m, c, nodes, pair, info, res, K, 24, msg, sizeof msg);
    int segs[6];
    for (int b = 0; b < 2; ++b) {
      /* the patch of the model's segment: its beam's nodes, slots the rules
       * do not read at 0 */
      const int nn = b ? s.nb + 1 : NSEG + 1, seg = pair[2 * b + 1];
      const int *beam_nodes = b ? s.nodes_b : s.nodes_a;
      int local[4], sr, er;
      ck_assert(b2b_beam_segment_patch(B2B_CURVE_HERMITE_NODAL, nn, 0, seg, local, &sr, &er, msg,
                                       sizeof msg) == B2B_OK);
      segs[3 * b] = B2B_CURVE_HERMITE_NODAL;
      segs[3 * b + 1] = sr;
      segs[3 * b + 2] = er;
      for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 3; ++i)
          X[12 * b + 3 * k + i] = local[k] >= 0 ? s.x[3 * beam_nodes[local[k]] + i] : 0.0;
    }
    const double radii[2] = {R, R};
    ck_assert_msg(b2b_pair_eval_line(p, segs, X, NULL, radii, 6, ho, hn, 7 * 12, &status, li,
                                     NULL, res2, K2, 24, msg, sizeof msg) == B2B_OK, "%s", msg);
    ck_assert_int_eq(status, B2B_CONTACT_ACTIVE);
    ck_assert(info[B2B_INFO_NORMAL_FORCE] == li[B2B_LINE_INFO_NORMAL_FORCE]);
    ck_assert(info[B2B_INFO_LINE_POINTS] == li[B2B_LINE_INFO_ACTIVE_POINTS]);
    TST_ASSERT_ALL(int, r, 0, 24, res[r] == res2[r], "contact %d: residual[%d] %.17g vs %.17g", c,
                   r, res[r], res2[r]);
    TST_ASSERT_ALL(int, r, 0, 576, K[r] == K2[r], "contact %d: tangent[%d]", c, r);
  }
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(friction_slides_across_joints) {
  b2b_params *p = params_of(B2B_CONTACT_TYPE_LINE, MU);
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    scene2 s;
    place(&s, 2 * R - 0.003, -0.5, 2.0, 10, 0.0);
    b2b_model *m = model_of(&s, p, kind);
    char msg[B2B_ERRMSG_LEN];
    update(m, &s, 0);
    ck_assert(b2b_model_commit(m, msg, sizeof msg) == B2B_OK);
    /* slide B by 0.45 (over two of its joints; B still covers A) in 45 steps */
    int slipping_steps = 0;
    for (int step = 1; step <= 45; ++step) {
      for (int k = 0; k <= s.nb; ++k) s.x[3 * (NSEG + 1 + k)] += 0.01;
      update(m, &s, 0);
      int counts[16];
      double totals[8];
      stats(m, counts, totals);
      ck_assert_msg(counts[B2B_COUNT_LOST] == 0, "step %d: lost %d", step, counts[B2B_COUNT_LOST]);
      ck_assert_msg(totals[B2B_TOTAL_LINE_POINTS] == a_points(&s, kind), "%s, step %d: %g points",
                    tst_kind_name(kind), step, totals[B2B_TOTAL_LINE_POINTS]);
      /* friction on A: sum of x residuals over A's nodes (A feels -T) */
      double f[3 * 64], fx = 0;
      nodal_forces(m, NSEG + 2 + s.nb, f);
      for (int k = 0; k <= NSEG; ++k) fx += f[3 * k];
      const double limit = MU * totals[B2B_TOTAL_NORMAL_FORCE];
      if (step > 3) {
        ++slipping_steps;
        ck_assert_msg(counts[B2B_COUNT_SLIP] == counts[B2B_COUNT_ACTIVE],
                      "%s, step %d: %d of %d slipping", tst_kind_name(kind), step,
                      counts[B2B_COUNT_SLIP], counts[B2B_COUNT_ACTIVE]);
        /* B moves +x: A is dragged along +x, its residual (internal force)
         * -T has the sign of... the friction force on A points +x, so the
         * residual on A is -(+) : negative */
        ck_assert_msg(fabs(fabs(fx) - limit) <= 1e-9 * limit,
                      "%s, step %d: friction %.15g, mu f_N %.15g", tst_kind_name(kind), step, fx,
                      limit);
        ck_assert_msg(fx < 0, "%s, step %d: friction force on A turned (%g)", tst_kind_name(kind),
                      step, fx);
      }
      ck_assert(b2b_model_commit(m, msg, sizeof msg) == B2B_OK);
    }
    ck_assert_int_eq(slipping_steps, 42);
    b2b_model_destroy(&m);
  }
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(commit_revert_restore_threads) {
  b2b_params *p = params_of(B2B_CONTACT_TYPE_LINE, MU);
  scene2 s;
  place(&s, 2 * R - 0.003, -0.5, 2.0, 10, 0.5);
  b2b_model *m = model_of(&s, p, B2B_CURVE_HERMITE_NODAL);
  char msg[B2B_ERRMSG_LEN];
  update(m, &s, 1);
  b2b_model_commit(m, msg, sizeof msg);
  for (int k = 0; k <= s.nb; ++k) s.x[3 * (NSEG + 1 + k)] += 0.013;
  update(m, &s, 1);
  b2b_model_commit(m, msg, sizeof msg);
  int64_t size = 0;
  ck_assert(b2b_model_save_size(m, &size, msg, sizeof msg) == B2B_OK);
  unsigned char *buf = malloc((size_t)size);
  ck_assert(b2b_model_save(m, buf, size, msg, sizeof msg) == B2B_OK);
  for (int k = 0; k <= s.nb; ++k) s.x[3 * (NSEG + 1 + k)] += 0.021;
  static unsigned char r1[1 << 20], r2[1 << 20], r3[1 << 20], r4[1 << 20];
  update(m, &s, 1);
  const size_t n1 = tst_model_record(m, 1, r1, sizeof r1);
  /* revert, again: the same bytes */
  b2b_model_revert(m, msg, sizeof msg);
  update(m, &s, 1);
  const size_t n2 = tst_model_record(m, 1, r2, sizeof r2);
  ck_assert(n1 == n2 && memcmp(r1, r2, n1) == 0);
  /* restored into a new model */
  b2b_model *m2 = model_of(&s, p, B2B_CURVE_HERMITE_NODAL);
  ck_assert_msg(b2b_model_restore(m2, buf, size, msg, sizeof msg) == B2B_OK, "%s", msg);
  update(m2, &s, 1);
  const size_t n3 = tst_model_record(m2, 1, r3, sizeof r3);
  ck_assert(n1 == n3 && memcmp(r1, r3, n1) == 0);
  /* one thread */
  b2b_model_set_int(m2, "threads", 1, msg, sizeof msg);
  b2b_model_revert(m2, msg, sizeof msg);
  update(m2, &s, 1);
  const size_t n4 = tst_model_record(m2, 1, r4, sizeof r4);
  ck_assert(n1 == n4 && memcmp(r1, r4, n1) == 0);
  /* a corrupted line history is refused */
  buf[size - 9] ^= 0x40;
  b2b_model *m3 = model_of(&s, p, B2B_CURVE_HERMITE_NODAL);
  ck_assert(b2b_model_restore(m3, buf, size, msg, sizeof msg) == B2B_ERR_RANGE);
  free(buf);
  b2b_model_destroy(&m);
  b2b_model_destroy(&m2);
  b2b_model_destroy(&m3);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(all_angle_turn_continuous) {
  b2b_params *p = params_of(B2B_CONTACT_TYPE_ALL_ANGLE, 0);
  double prev = -1, prev_step = -1, worst = 0, fmax_ = 0;
  int active_everywhere = 1;
  /* 90 .. 0 degrees in steps of 0.1; quick mode: of 0.3 (the force is
   * constant above 15 degrees and turns there: the first step below is
   * 0.0052 in steps of 0.3, 0.014 in steps of 0.5, over the criterion 0.012) */
  const int stride = tst_quick() ? 3 : 1;
  for (int k = 900; k >= 0; k -= stride) {
    scene2 s;
    place(&s, 2 * R - 0.003, -0.5, 2.0, 10, 0.1 * k);
    b2b_model *m = model_of(&s, p, B2B_CURVE_HERMITE_NODAL);
    update(m, &s, 0);
    int counts[16];
    double totals[8];
    stats(m, counts, totals);
    active_everywhere = active_everywhere && counts[B2B_COUNT_ACTIVE] > 0;
    const double F = totals[B2B_TOTAL_NORMAL_FORCE];
    fmax_ = fmax(fmax_, F);
    if (prev >= 0) {
      const double step = fabs(F - prev);
      if (prev_step >= 0) worst = fmax(worst, step - 4 * prev_step - 1e-9 * F);
      prev_step = step;
    }
    prev = F;
    b2b_model_destroy(&m);
  }
  ck_assert(active_everywhere);
  ck_assert_msg(worst <= 1e-3 * fmax_, "the force jumps by %g (largest force %g)", worst, fmax_);
  b2b_params_destroy(&p);
}
END_TEST

/* ALL_ANGLE at 90 degrees is the point element (weight 1): its history must
 * follow the contact point across joints like a point contact's. B slid
 * along its axis over two of its joints, then A along its own over two of
 * its joints, in committed steps: the friction force stays mu f_N in every
 * slipping step (it would restart from zero at each joint without the
 * point part's handover), nothing lost. */
START_TEST(all_angle_point_part_hands_over) {
  b2b_params *p = params_of(B2B_CONTACT_TYPE_ALL_ANGLE, MU);
  scene2 s;
  place(&s, 2 * R - 0.003, -0.5, 2.0, 10, 90.0);
  for (int k = 0; k <= s.nb; ++k) s.x[3 * (NSEG + 1 + k) + 1] = 0.03; /* off A's middle node */
  b2b_model *m = model_of(&s, p, B2B_CURVE_HERMITE_NODAL);
  char msg[B2B_ERRMSG_LEN];
  update(m, &s, 0);
  ck_assert(b2b_model_commit(m, msg, sizeof msg) == B2B_OK);
  int slipping = 0;
  for (int step = 1; step <= 70; ++step) {
    const int phase = step <= 45 ? 0 : 1; /* B along x, then A along y */
    if (phase == 0)
      for (int k = 0; k <= s.nb; ++k) s.x[3 * (NSEG + 1 + k)] += 0.01;
    else
      for (int k = 0; k <= NSEG; ++k) s.x[3 * k + 1] += 0.01;
    update(m, &s, 0);
    int counts[16];
    double totals[8];
    stats(m, counts, totals);
    ck_assert_msg(counts[B2B_COUNT_ACTIVE] == 1 && counts[B2B_COUNT_LOST] == 0,
                  "step %d: %d active, %d lost", step, counts[B2B_COUNT_ACTIVE],
                  counts[B2B_COUNT_LOST]);
    double f[3 * 64], ft[3] = {0, 0, 0};
    nodal_forces(m, NSEG + 2 + s.nb, f);
    for (int k = 0; k <= NSEG; ++k)
      for (int i = 0; i < 2; ++i) ft[i] += f[3 * k + i];
    const double limit = MU * totals[B2B_TOTAL_NORMAL_FORCE];
    const double t = hypot(ft[0], ft[1]);
    if (step != 1 && step != 46) { /* the first step of each phase turns the force */
      ++slipping;
      ck_assert_msg(counts[B2B_COUNT_SLIP] == 1, "step %d: not slipping", step);
      ck_assert_msg(fabs(t - limit) <= 1e-9 * limit, "step %d: friction %.15g, mu f_N %.15g",
                    step, t, limit);
    }
    ck_assert(b2b_model_commit(m, msg, sizeof msg) == B2B_OK);
  }
  ck_assert_int_eq(slipping, 68);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(tunnelling_parallel_beams_are_caught) {
  /* A committed above B with an open gap, then moved through B to below it
   * in one step: line pairs new since the commit, on the other side now.
   * They must come back active with the committed side (signed gap below
   * -(r_A + r_B)) and counted as crossed, never open. */
  for (int type = B2B_CONTACT_TYPE_LINE; type <= B2B_CONTACT_TYPE_ALL_ANGLE; ++type) {
    b2b_params *p = params_of(type, 0);
    scene2 s;
    place(&s, 2 * R + 0.25, -0.5, 2.0, 10, 0.0); /* beyond the near reach: no history */
    b2b_model *m = model_of(&s, p, B2B_CURVE_HERMITE_NODAL);
    char msg[B2B_ERRMSG_LEN];
    update(m, &s, 0);
    int counts[16];
    double totals[8];
    stats(m, counts, totals);
    ck_assert_int_eq(counts[B2B_COUNT_ACTIVE], 0);
    ck_assert(b2b_model_commit(m, msg, sizeof msg) == B2B_OK);
    for (int k = 0; k <= NSEG; ++k) s.x[3 * k + 2] = -(2 * R + 0.01);
    update(m, &s, 0);
    stats(m, counts, totals);
    ck_assert_msg(counts[B2B_COUNT_ACTIVE] > 0 && counts[B2B_COUNT_CROSSED] == counts[B2B_COUNT_ACTIVE],
                  "type %d: %d active, %d crossed", type, counts[B2B_COUNT_ACTIVE],
                  counts[B2B_COUNT_CROSSED]);
    ck_assert_msg(totals[B2B_TOTAL_MIN_GAP] < -2 * R, "min gap %g", totals[B2B_TOTAL_MIN_GAP]);
    /* the force pushes A back up: A's resultant residual (internal force)
     * is negative in z, as when it penetrates from above */
    double f[3 * 64], fz = 0;
    nodal_forces(m, NSEG + 2 + s.nb, f);
    for (int k = 0; k <= NSEG; ++k) fz += f[3 * k + 2];
    ck_assert_msg(fz < 0, "type %d: A's contact residual %g (pulls it through)", type, fz);
    b2b_model_destroy(&m);
    b2b_params_destroy(&p);
  }
}
END_TEST

START_TEST(replacement_keeps_the_contact_type) {
  b2b_params *pl = params_of(B2B_CONTACT_TYPE_LINE, 0), *pp = params_of(B2B_CONTACT_TYPE_POINT, 0);
  b2b_params *pl2 = params_of(B2B_CONTACT_TYPE_ALL_ANGLE, 0);
  scene2 s;
  place(&s, 2 * R - 0.003, -0.5, 2.0, 10, 0.0);
  b2b_model *m = model_of(&s, pl, B2B_CURVE_HERMITE_NODAL);
  char msg[B2B_ERRMSG_LEN];
  ck_assert(b2b_model_set_group_pair(m, 0, 1, pp, msg, sizeof msg) == B2B_ERR_SIZE);
  ck_assert_msg(strstr(msg, "line") != NULL, "%s", msg);
  ck_assert(b2b_model_set_group_pair(m, 0, 1, pl2, msg, sizeof msg) == B2B_OK);
  b2b_model_destroy(&m);
  b2b_params_destroy(&pl);
  b2b_params_destroy(&pl2);
  b2b_params_destroy(&pp);
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_line");
  TCase *tc = tcase_create("line");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, parallel_beams_closed_form);
  tcase_add_test(tc, model_equals_pair_element);
  tcase_add_test(tc, friction_slides_across_joints);
  tcase_add_test(tc, commit_revert_restore_threads);
  tcase_add_test(tc, all_angle_turn_continuous);
  tcase_add_test(tc, all_angle_point_part_hands_over);
  tcase_add_test(tc, tunnelling_parallel_beams_are_caught);
  tcase_add_test(tc, replacement_keeps_the_contact_type);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
