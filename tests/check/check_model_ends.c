/* End contacts in the contact model (b2b_model.h, doc/contact-element.md
 * section 14): a node that the segments on both sides of it point away
 * from, at a convex joint of straight segments or at a beam's end, is a
 * contact of its own (node-to-segment), owned by one pair, with friction
 * history carried into and out of it as the point slides on; and
 * B2B_TOTAL_MIN_GAP when no pair owns a closest point. Each case failed
 * before the end contact: every pair reported OUTSIDE, the beams passed
 * through each other with no contact and B2B_COUNT_LOST 0. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "test_support.h"

static char msg[B2B_ERRMSG_LEN];

static void ok(int st) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

/* eps_T = 0.2 penalty: a step's slip (1e-3) adds a stick force of the order
 * of mu f_N, so the committed force's direction shows in the next step. */
static b2b_params *params(double penalty, double mu) {
  b2b_params *p = NULL;
  ok(b2b_params_create(&p, msg, sizeof msg));
  ok(b2b_params_set_real(p, "penalty", penalty, msg, sizeof msg));
  if (mu > 0.0) {
    ok(b2b_params_set_real(p, "friction", mu, msg, sizeof msg));
    ok(b2b_params_set_real(p, "tangential_penalty", 0.2 * penalty, msg, sizeof msg));
  }
  ok(b2b_params_finalize(p, msg, sizeof msg));
  return p;
}

/* A model of beam A (nodes 0 .. na-1) and beam B (the next nb nodes), one
 * group each, radius r. */
static b2b_model *two_beams(const b2b_params *p, int na, int kind_a, int nb, int kind_b,
                            double r) {
  b2b_model *m = NULL;
  int nodes[16], beam;
  ok(b2b_model_create(&m, msg, sizeof msg));
  for (int k = 0; k < na; ++k) nodes[k] = k;
  ok(b2b_model_add_beam(m, nodes, na, 0, r, kind_a, 0, &beam, msg, sizeof msg));
  for (int k = 0; k < nb; ++k) nodes[k] = na + k;
  ok(b2b_model_add_beam(m, nodes, nb, 0, r, kind_b, 1, &beam, msg, sizeof msg));
  ok(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg));
  ok(b2b_model_finalize(m, na + nb, msg, sizeof msg));
  return m;
}

/* The V of three nodes, vertex at (0, 0, h), arms rising by slope s to
 * x = -+1, over a straight bar of three nodes along y through (xb, 0, 0). */
static void v_over_bar(double h, double s, double xb, double x[18]) {
  const double v[18] = {-1, 0, h + s, 0, 0, h, 1, 0, h + s,
                        xb, -1, 0, xb, 0.001, 0, xb, 1, 0};
  memcpy(x, v, sizeof v);
}

START_TEST(v_onto_bar_carries_its_load) {
  /* radii 0.05 + 0.05, vertex 0.099 above the bar: penetration 0.001 */
  b2b_params *p = params(1e4, 0.0);
  b2b_model *m = two_beams(p, 3, B2B_CURVE_LINEAR, 3, B2B_CURVE_LINEAR, 0.05);
  double x[18], info[32];
  v_over_bar(0.099, 0.3, 0.0, x);
  ok(b2b_model_update(m, x, 3, 6, 1, msg, sizeof msg));
  int n, counts[16], pair[4], nodes[8];
  double totals[8];
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg));
  ok(b2b_model_stats(m, counts, totals, msg, sizeof msg));
  ck_assert_msg(n == 1, "%d contacts (outside %d, lost %d)", n, counts[B2B_COUNT_OUTSIDE],
                counts[B2B_COUNT_LOST]);
  ok(b2b_model_get_contact(m, 0, nodes, pair, info, NULL, NULL, 24, msg, sizeof msg));
  /* the vertex (A's node 1) holds it: segment 1 of A at its start */
  ck_assert_int_eq(pair[0], 0);
  ck_assert_int_eq(pair[1], 1);
  ck_assert(info[B2B_INFO_END_A] == -1.0 && info[B2B_INFO_END_B] == 0.0);
  ck_assert_msg(fabs(info[B2B_INFO_GAP] + 0.001) < 1e-12, "gap %.17g", info[B2B_INFO_GAP]);
  ck_assert_msg(fabs(info[B2B_INFO_NORMAL_FORCE] - 10.0) < 1e-9, "f_N %.17g",
                info[B2B_INFO_NORMAL_FORCE]);
  ck_assert(totals[B2B_TOTAL_MIN_GAP] == info[B2B_INFO_GAP]);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(beam_end_on_a_beam) {
  /* Beam A (every kind) ends 0.01 into beam B, perpendicular, its last
   * node above B's middle: the end node holds the contact. */
  b2b_params *p = params(100.0, 0.0);
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    b2b_model *m = two_beams(p, 4, kind, 3, B2B_CURVE_LINEAR, 0.1);
    const double x[21] = {0, 0, 1.5, 0, 0, 1.0, 0, 0, 0.5, 0, 0, 0.19,
                          -1, 0.0002, 0, 0, 0.0001, 0, 1, 0, 0};
    ok(b2b_model_update(m, x, 3, 7, 1, msg, sizeof msg));
    int n, nodes[8], pair[4];
    double info[32], res[24];
    ok(b2b_model_contact_count(m, &n, msg, sizeof msg));
    ck_assert_msg(n == 1, "kind %d: %d contacts", kind, n);
    ok(b2b_model_get_contact(m, 0, nodes, pair, info, res, NULL, 24, msg, sizeof msg));
    ck_assert_msg(info[B2B_INFO_END_A] == 1.0, "kind %d: end_a %g", kind, info[B2B_INFO_END_A]);
    ck_assert_msg(fabs(info[B2B_INFO_GAP] + 0.01) < 1e-6, "kind %d: gap %g", kind,
                  info[B2B_INFO_GAP]);
    /* the force acts on the end node (along z) and balances over the pair */
    double sum_z = 0.0;
    for (int k = 0; k < 8; ++k) sum_z += res[3 * k + 2];
    ck_assert_msg(fabs(sum_z) < 1e-9, "kind %d: residual sum %g", kind, sum_z);
    b2b_model_destroy(&m);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* The bar slides along x under the V, through the window |xb| <= s h'
 * where the vertex is the closest point: interior of the left arm, the
 * vertex, interior of the right arm, committed at every step. With
 * friction the anchored force must survive every handover (a lost history
 * restarts at T = 0). */
static void slide(double mu) {
  b2b_params *p = params(1e4, mu);
  b2b_model *m = two_beams(p, 3, B2B_CURVE_LINEAR, 3, B2B_CURVE_LINEAR, 0.05);
  const double h = 0.099, s = 0.05;
  int seen_left = 0, seen_vertex = 0, seen_right = 0;
  for (int step = 0; step <= 40; ++step) {
    const double xb = -0.02 + 0.001 * step;
    double x[18], info[32];
    v_over_bar(h, s, xb, x);
    ok(b2b_model_update(m, x, 3, 6, 1, msg, sizeof msg));
    int n, counts[16], nodes[8], pair[4];
    ok(b2b_model_contact_count(m, &n, msg, sizeof msg));
    ok(b2b_model_stats(m, counts, NULL, msg, sizeof msg));
    ck_assert_msg(n == 1, "mu %g, xb %g: %d contacts", mu, xb, n);
    ck_assert_msg(counts[B2B_COUNT_LOST] == 0, "mu %g, xb %g: lost %d", mu, xb,
                  counts[B2B_COUNT_LOST]);
    ok(b2b_model_get_contact(m, 0, nodes, pair, info, NULL, NULL, 24, msg, sizeof msg));
    if (info[B2B_INFO_END_A] == -1.0) ++seen_vertex;
    else if (pair[1] == 0) ++seen_left;
    else ++seen_right;
    if (mu > 0.0 && step > 0) {
      const double *T = info + B2B_INFO_TANGENTIAL_FORCE;
      const double t = sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]);
      ck_assert_msg(t > 0.5 * mu * info[B2B_INFO_NORMAL_FORCE],
                    "xb %g: |T| %g, mu f_N %g: the friction history was lost", xb, t,
                    mu * info[B2B_INFO_NORMAL_FORCE]);
      /* the bar moves along +x: A holds it back along -x at every step,
       * also across both handovers (a force re-read in another frame turned
       * by the crossing angle, 90 degrees here) */
      ck_assert_msg(T[0] < -0.9 * t, "xb %g: friction force (%g, %g, %g) is not against the "
                    "motion", xb, T[0], T[1], T[2]);
    }
    ok(b2b_model_commit(m, msg, sizeof msg));
  }
  ck_assert_msg(seen_left > 0 && seen_vertex > 0 && seen_right > 0,
                "left %d, vertex %d, right %d", seen_left, seen_vertex, seen_right);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}

START_TEST(slide_across_a_convex_joint) { slide(0.0); }
END_TEST

START_TEST(slide_across_a_convex_joint_with_friction) { slide(0.3); }
END_TEST

START_TEST(min_gap_when_nothing_is_near) {
  /* far apart: no pair owns a closest point; the minimum gap is DBL_MAX,
   * never the 0 that reads as touching */
  b2b_params *p = params(100.0, 0.0);
  b2b_model *m = two_beams(p, 3, B2B_CURVE_LINEAR, 3, B2B_CURVE_LINEAR, 0.05);
  double x[18], totals[8];
  int counts[16];
  v_over_bar(50.0, 0.3, 0.0, x);
  ok(b2b_model_update(m, x, 3, 6, 0, msg, sizeof msg));
  ok(b2b_model_stats(m, counts, totals, msg, sizeof msg));
  ck_assert_int_eq(counts[B2B_COUNT_ACTIVE] + counts[B2B_COUNT_OPEN], 0);
  ck_assert(totals[B2B_TOTAL_MIN_GAP] == DBL_MAX);
  ck_assert(totals[B2B_TOTAL_ENERGY] == 0.0 && totals[B2B_TOTAL_NORMAL_FORCE] == 0.0);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_ends");
  TCase *tc = tcase_create("end_contact");
  tcase_add_test(tc, v_onto_bar_carries_its_load);
  tcase_add_test(tc, beam_end_on_a_beam);
  tcase_add_test(tc, slide_across_a_convex_joint);
  tcase_add_test(tc, slide_across_a_convex_joint_with_friction);
  tcase_add_test(tc, min_gap_when_nothing_is_near);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
