/* A frictional contact sliding along a curved, unevenly meshed beam across
 * many of its nodes (and along the other beam's segments too), in steps that
 * sometimes skip a segment, with the model doing the bookkeeping; for every
 * smoothed kind, on an open arc and across a ring's seam:
 *  - exactly one active contact at every step, none lost;
 *  - after the first step the contact slips with |T| = mu f_N at every step,
 *    so the committed friction history crossed every joint (a fresh history
 *    would stick with T = 0), and T changes across joints no more than on
 *    the steps between them;
 *  - the model's contact is bit for bit what a host gets doing the same
 *    bookkeeping by hand with b2b_pair_eval and b2b_pair_history_handover,
 *    its tangent included (the model keeps a tangent whose triangles hold
 *    the same bits packed, and a slipping contact's, not symmetric, whole:
 *    src/model/contact_result.hpp; both kinds occur here). */
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "model_support.h"

#define PI 3.14159265358979323846
#define NA_MAX 64
#define NB 9

typedef struct {
  int kind, closed, n_a;
  double phi[NA_MAX];  /* node angles of A */
  double R, ra, rb, delta;
  int slide_b;         /* the contact also moves along B */
  double x[3 * (NA_MAX + NB)];
  int n_nodes;
} slide_scene;

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

/* A: arc (or ring) of radius R in the plane z = 0, elements alternating
 * 1.25 h and 0.75 h. B: a straight beam along z of NB nodes 0.15 apart,
 * pressed onto A from outside at angle theta, shifted along z by zoff. */
static void place(slide_scene *s, double theta, double zoff) {
  for (int k = 0; k < s->n_a; ++k) {
    s->x[3 * k] = s->R * cos(s->phi[k]);
    s->x[3 * k + 1] = s->R * sin(s->phi[k]);
    s->x[3 * k + 2] = 0.0;
  }
  const double rho = s->R + s->ra + s->rb - s->delta;
  for (int k = 0; k < NB; ++k) {
    double *p = s->x + 3 * (s->n_a + k);
    p[0] = rho * cos(theta);
    p[1] = rho * sin(theta);
    p[2] = zoff + 0.15 * (k - 4) + 0.0123;
  }
}

static void setup(slide_scene *s, int kind, int closed, int slide_b) {
  memset(s, 0, sizeof *s);
  s->kind = kind;
  s->closed = closed;
  s->slide_b = slide_b;
  s->R = 4.0;
  /* deep enough that the midpoint kind, which cuts the polygon's corners by
   * up to 0.08 here, stays in contact */
  s->ra = s->rb = 0.2;
  s->delta = 0.12;
  s->n_a = closed ? 24 : 21;
  const double h = closed ? 2 * PI / 24 : PI / 20;
  double phi = closed ? 0.0 : 0.0;
  for (int k = 0; k < s->n_a; ++k) {
    s->phi[k] = phi;
    phi += (k % 2 ? 0.75 : 1.25) * h;
  }
  s->n_nodes = s->n_a + NB;
}

static b2b_model *make_model(const slide_scene *s, const b2b_params *p) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_model *m = NULL;
  int nodes[NA_MAX + NB], beam;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  for (int k = 0; k < s->n_a; ++k) nodes[k] = k;
  ok(b2b_model_add_beam(m, nodes, s->n_a, s->closed, s->ra, s->kind, 0, &beam, msg, sizeof msg), msg);
  for (int k = 0; k < NB; ++k) nodes[k] = s->n_a + k;
  ok(b2b_model_add_beam(m, nodes, NB, 0, s->rb, B2B_CURVE_LINEAR, 1, &beam, msg, sizeof msg), msg);
  ok(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, s->n_nodes, msg, sizeof msg), msg);
  return m;
}

/* Segment data of beam 0 (A) or 1 (B) from coordinates x. */
static void seg_patch(const slide_scene *s, int beam, int seg, const double *x, int rules[3],
                      double X[12]) {
  char msg[B2B_ERRMSG_LEN] = "";
  const int kind = beam == 0 ? s->kind : B2B_CURVE_LINEAR;
  const int n = beam == 0 ? s->n_a : NB, closed = beam == 0 ? s->closed : 0;
  const int first = beam == 0 ? 0 : s->n_a;
  int local[4];
  ok(b2b_beam_segment_patch(kind, n, closed, seg, local, &rules[1], &rules[2], msg, sizeof msg), msg);
  rules[0] = kind;
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) X[3 * k + i] = local[k] < 0 ? 0.0 : x[3 * (first + local[k]) + i];
}

static int n_seg(const slide_scene *s, int beam) {
  int n;
  char msg[B2B_ERRMSG_LEN] = "";
  ok(b2b_beam_segment_count(beam == 0 ? s->kind : B2B_CURVE_LINEAR, beam == 0 ? s->n_a : NB,
                            beam == 0 ? s->closed : 0, &n, msg, sizeof msg), msg);
  return n;
}

/* The host's bookkeeping by hand: the contact's pair and committed history. */
typedef struct {
  int seg[2];
  double hist[16];
  double x_committed[3 * (NA_MAX + NB)];
} by_hand;

static int eval_pair(const slide_scene *s, const b2b_params *p, const int seg[2], const double *hist,
                     double *hist_new, double info[32], double res[24], double K[576]) {
  char msg[B2B_ERRMSG_LEN] = "";
  int segs[6], st, nh;
  double X[24];
  seg_patch(s, 0, seg[0], s->x, segs, X);
  seg_patch(s, 1, seg[1], s->x, segs + 3, X + 12);
  const double radii[2] = {s->ra, s->rb};
  ok(b2b_params_history_size(p, &nh, msg, sizeof msg), msg);
  ok(b2b_pair_eval(p, segs, X, NULL, radii, hist, hist_new, nh, &st, info, res, K, 24, msg,
                   sizeof msg), msg);
  return st;
}

static int exit_dir(double t) { return t >= 1.0 - 1e-12 ? 1 : (t < -1.0 ? -1 : 0); }

/* One step by hand; returns the contact status of the owner found. */
static int hand_step(const slide_scene *s, const b2b_params *p, by_hand *h, double info[32],
                     double res[24], double K[576], double hist_new[16], int *hops) {
  char msg[B2B_ERRMSG_LEN] = "";
  int nh;
  ok(b2b_params_history_size(p, &nh, msg, sizeof msg), msg);
  double hist[16];
  memcpy(hist, h->hist, sizeof hist);
  int st = eval_pair(s, p, h->seg, hist, hist_new, info, res, K);
  while (st == B2B_CONTACT_OUTSIDE) {
    const int d[2] = {exit_dir(info[B2B_INFO_XI]), exit_dir(info[B2B_INFO_ETA])};
    ck_assert_msg(d[0] || d[1], "by hand: outside but inside both segments");
    for (int beam = 0; beam < 2; ++beam) {
      if (!d[beam]) continue;
      const int n = n_seg(s, beam), closed = beam == 0 ? s->closed : 0;
      int to = h->seg[beam] + d[beam];
      if (closed) to = (to + n) % n;
      ck_assert_msg(to >= 0 && to < n, "by hand: the contact left beam %d", beam);
      int from_rules[3], to_rules[3];
      double from_X[12], to_X[12];
      seg_patch(s, beam, h->seg[beam], h->x_committed, from_rules, from_X);
      seg_patch(s, beam, to, h->x_committed, to_rules, to_X);
      ok(b2b_pair_history_handover(p, beam, d[beam], from_rules, from_X, NULL, to_rules, to_X,
                                   NULL, hist, hist, nh, msg, sizeof msg), msg);
      h->seg[beam] = to;
      ++*hops;
    }
    st = eval_pair(s, p, h->seg, hist, hist_new, info, res, K);
  }
  return st;
}

static void slide(int kind, int closed, int slide_b) {
  char msg[B2B_ERRMSG_LEN] = "";
  slide_scene s;
  setup(&s, kind, closed, slide_b);
  const double mu = 0.3;
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, mu, 2e3);
  b2b_model *m = make_model(&s, p);
  const double theta0 = closed ? -0.7 : 0.25, theta1 = closed ? 0.7 : 2.85;
  by_hand h;
  memset(&h, 0, sizeof h);
  double theta = theta0, T_prev[3] = {0, 0, 0}, worst_cross = 0.0, worst_between = 0.0;
  int step = 0, hops_model = 0, hops_hand = 0, skips = 0, crossings = 0, seg_prev = -1;
  int symmetric = 0;  /* steps whose tangent is symmetric bit for bit */
  int segb_prev = -1;
  while (theta <= theta1) {
    const double frac = (theta - theta0) / (theta1 - theta0);
    place(&s, theta, slide_b ? 0.5 - 1.0 * frac : 0.0);
    ok(b2b_model_update(m, s.x, 3, s.n_nodes, 1, msg, sizeof msg), msg);
    int n, counts[16], pair[4];
    double info[32], res[24], K[576];
    ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
    ok(b2b_model_stats(m, counts, NULL, msg, sizeof msg), msg);
    ck_assert_msg(n == 1, "%s %s: step %d (theta %.3f): %d active contacts", tst_kind_name(kind),
                  closed ? "ring" : "arc", step, theta, n);
    ck_assert_int_eq(counts[B2B_COUNT_LOST], 0);
    ok(b2b_model_get_contact(m, 0, NULL, pair, info, res, K, 24, msg, sizeof msg), msg);
    hops_model += counts[B2B_COUNT_HANDOVERS];
    /* by hand */
    double hinfo[32], hres[24], hK[576], hnew[16];
    if (step == 0) {
      h.seg[0] = pair[1];  /* the host finds its first contact by its own search */
      h.seg[1] = pair[3];
    }
    const int hst = hand_step(&s, p, &h, hinfo, hres, hK, hnew, &hops_hand);
    ck_assert_int_eq(hst, B2B_CONTACT_ACTIVE);
    ck_assert_msg(pair[1] == h.seg[0] && pair[3] == h.seg[1],
                  "step %d: model pair (%d, %d), by hand (%d, %d)", step, pair[1], pair[3],
                  h.seg[0], h.seg[1]);
    ck_assert_msg(memcmp(info, hinfo, sizeof info) == 0 && memcmp(res, hres, sizeof res) == 0,
                  "step %d: the model's contact differs from the bookkeeping by hand", step);
    ck_assert_msg(memcmp(K, hK, sizeof K) == 0,
                  "step %d: the model's tangent differs from the bookkeeping by hand", step);
    int sym = 1;
    for (int c = 0; c < 24 && sym; ++c)
      for (int r = 0; r < c && sym; ++r) sym = memcmp(&K[r + 24 * c], &K[c + 24 * r], 8) == 0;
    symmetric += sym;
    /* friction */
    const double *T = info + B2B_INFO_TANGENTIAL_FORCE;
    const double fn = info[B2B_INFO_NORMAL_FORCE], tn = sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]);
    if (step > 0) {
      ck_assert_msg(info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_SLIP,
                    "step %d: friction state %g, slip expected", step, info[B2B_INFO_FRICTION_STATE]);
      ck_assert_msg(fabs(tn - mu * fn) <= 1e-9 * mu * fn, "step %d: |T| %.12g, mu f_N %.12g",
                    step, tn, mu * fn);
      const double dT = sqrt((T[0] - T_prev[0]) * (T[0] - T_prev[0]) +
                             (T[1] - T_prev[1]) * (T[1] - T_prev[1]) +
                             (T[2] - T_prev[2]) * (T[2] - T_prev[2]));
      /* T turns with A's tangent: about mu f_N per radian of theta (and less
       * when B slides too); across a joint no more than that. (At step 1 it
       * grows from the new contact's 0 to mu f_N.) */
      const double dtheta = step % 9 == 0 ? 0.3 : 0.03;
      const double ratio = dT / (mu * fn * (dtheta + 0.02));
      const int crossed = pair[1] != seg_prev || pair[3] != segb_prev;
      if (step > 3) {  /* after the onset of slip has settled */
        double *worst = crossed ? &worst_cross : &worst_between;
        if (ratio > *worst) *worst = ratio;
        ck_assert_msg(ratio <= 2.0, "step %d: T jumps by %.3g (mu f_N %.3g, dtheta %.2f)", step,
                      dT, mu * fn, dtheta);
      }
    }
    if (pair[1] != seg_prev && step > 0) ++crossings;
    if (step > 0 && abs(pair[1] - seg_prev) >= 2 && !(closed && abs(pair[1] - seg_prev) > 10)) ++skips;
    seg_prev = pair[1];
    segb_prev = pair[3];
    memcpy(T_prev, T, sizeof T_prev);
    ok(b2b_model_commit(m, msg, sizeof msg), msg);
    int nh;
    ok(b2b_params_history_size(p, &nh, msg, sizeof msg), msg);
    memcpy(h.hist, hnew, sizeof(double) * nh);
    memcpy(h.x_committed, s.x, sizeof s.x);
    ++step;
    theta += step % 9 == 0 ? 0.3 : 0.03;
  }
  printf("%-22s %s%s: %d steps (%d with a symmetric tangent), A's contact segment changed %d "
         "times (%d steps skipped a segment), %d handover hops (by hand %d); |dT| / (mu f_N "
         "dtheta') at most %.2f across joints, %.2f between\n",
         tst_kind_name(kind), closed ? "ring across the seam" : "open arc",
         slide_b ? ", sliding along B too" : "", step, symmetric, crossings, skips, hops_model,
         hops_hand, worst_cross, worst_between);
  ck_assert_msg(symmetric >= 1 && symmetric < step, "%d of %d tangents symmetric: both forms "
                "expected", symmetric, step);
  ck_assert_msg(worst_cross <= 1.5 * worst_between + 0.05,
                "T jumps more across joints (%.3f) than between them (%.3f)", worst_cross,
                worst_between);
  ck_assert_int_eq(hops_model, hops_hand);
  ck_assert_msg(closed || crossings >= 10, "only %d node crossings", crossings);
  ck_assert_msg(closed || skips >= 1, "no step skipped a segment");
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}

START_TEST(arc_every_smoothed_kind) {
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
    if (tst_kind_family(kind) != TST_CHORD) slide(kind, 0, 0);
}
END_TEST

START_TEST(arc_sliding_along_both_beams) {
  slide(B2B_CURVE_HERMITE_NODAL, 0, 1);
  slide(B2B_CURVE_HERMITE_NODAL_WEIGHTED, 0, 1);
}
END_TEST

START_TEST(ring_seam) {
  slide(B2B_CURVE_HERMITE_NODAL, 1, 0);
  slide(B2B_CURVE_HERMITE_MIDPOINT, 1, 1);
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_sliding");
  TCase *tc = tcase_create("handover");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, arc_every_smoothed_kind);
  tcase_add_test(tc, arc_sliding_along_both_beams);
  tcase_add_test(tc, ring_seam);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
