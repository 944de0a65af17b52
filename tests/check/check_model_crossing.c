/* Beams that pass through each other between two commits (b2b_model.h,
 * B2B_COUNT_CROSSED; src/model/crossing.hpp): a beam moved in one step from
 * one side of another to the other, by a little or by many radii, is an
 * active contact with its signed gap below -(r_A + r_B) and counted as
 * crossed, for every curve kind, never the "open" pair it looked like
 * before (no contact at all: the unsigned gap read as separation, and a
 * pair moved beyond the search's reach was not even evaluated). A beam
 * moved the same way without passing through is not. */
#include <math.h>
#include <string.h>

#include "test_support.h"

static char msg[B2B_ERRMSG_LEN];

static void ok(int st) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

/* A along x at z = 0 (5 nodes), B along y (5 nodes) at height zb. */
static void scene(double zb, double x[30]) {
  for (int k = 0; k < 5; ++k) {
    const double t = -1.0 + 0.5 * k;
    double *a = x + 3 * k, *b = x + 15 + 3 * k;
    a[0] = t + 0.013;
    a[1] = 0.002;
    a[2] = 0.0;
    b[0] = 0.001;
    b[1] = t + 0.021;
    b[2] = zb;
  }
}

static b2b_model *two_beams(int kind, double r, const b2b_params *p) {
  b2b_model *m = NULL;
  int nodes[5], beam;
  ok(b2b_model_create(&m, msg, sizeof msg));
  for (int k = 0; k < 5; ++k) nodes[k] = k;
  ok(b2b_model_add_beam(m, nodes, 5, 0, r, kind, 0, &beam, msg, sizeof msg));
  for (int k = 0; k < 5; ++k) nodes[k] = 5 + k;
  ok(b2b_model_add_beam(m, nodes, 5, 0, r, kind, 1, &beam, msg, sizeof msg));
  ok(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg));
  ok(b2b_model_finalize(m, 10, msg, sizeof msg));
  return m;
}

/* Commit B at z0, update at z1: the active contacts, crossed count and the
 * smallest gap of the active ones. */
static void step(int kind, double z0, double z1, int *active, int *crossed, double *gap) {
  const double r = 0.01;
  b2b_params *p = NULL;
  ok(b2b_params_create(&p, msg, sizeof msg));
  ok(b2b_params_set_real(p, "penalty", 100.0, msg, sizeof msg));
  ok(b2b_params_finalize(p, msg, sizeof msg));
  b2b_model *m = two_beams(kind, r, p);
  double x[30];
  scene(z0, x);
  ok(b2b_model_update(m, x, 3, 10, 1, msg, sizeof msg));
  ok(b2b_model_commit(m, msg, sizeof msg));
  scene(z1, x);
  ok(b2b_model_update(m, x, 3, 10, 1, msg, sizeof msg));
  int counts[16], n;
  ok(b2b_model_stats(m, counts, NULL, msg, sizeof msg));
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg));
  *active = counts[B2B_COUNT_ACTIVE];
  *crossed = counts[B2B_COUNT_CROSSED];
  *gap = 1.0;
  for (int k = 0; k < n; ++k) {
    int nodes[8], pair[4];
    double info[32];
    ok(b2b_model_get_contact(m, k, nodes, pair, info, NULL, NULL, 24, msg, sizeof msg));
    if (info[B2B_INFO_GAP] < *gap) *gap = info[B2B_INFO_GAP];
  }
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}

START_TEST(moved_through_is_crossed) {
  /* from 0.1 above (gap 0.08: beyond the narrow phase's reach r_A + r_B +
   * s = 0.03, so the commit stores no normal for the pair) to 0.03 below,
   * and to 0.5 below (25 radii: beyond the reach at the update too) */
  const double below[2] = {-0.03, -0.5};
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
    for (int c = 0; c < 2; ++c) {
      int active, crossed;
      double gap;
      step(kind, 0.1, below[c], &active, &crossed, &gap);
      ck_assert_msg(active == 1 && crossed == 1, "kind %d, to z %g: active %d, crossed %d", kind,
                    below[c], active, crossed);
      /* the signed gap: axis distance on the other side, minus the radii */
      ck_assert_msg(fabs(gap - (below[c] - 0.02)) < 1e-9, "kind %d, to z %g: gap %.17g", kind,
                    below[c], gap);
    }
}
END_TEST

START_TEST(moved_without_passing_is_not) {
  /* from above to farther above, and from beyond the reach to pressed in
   * a little (the motion exceeds the axis distance, the side is kept): no
   * crossing */
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    int active, crossed;
    double gap;
    step(kind, 0.1, 0.6, &active, &crossed, &gap);
    ck_assert_msg(active == 0 && crossed == 0, "kind %d: active %d, crossed %d", kind, active,
                  crossed);
    step(kind, 0.1, 0.015, &active, &crossed, &gap);
    ck_assert_msg(active == 1 && crossed == 0, "kind %d: active %d, crossed %d", kind, active,
                  crossed);
    ck_assert_msg(fabs(gap + 0.005) < 1e-9, "kind %d: gap %g", kind, gap);
  }
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_crossing");
  TCase *tc = tcase_create("crossing");
  tcase_add_test(tc, moved_through_is_crossed);
  tcase_add_test(tc, moved_without_passing_is_not);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
