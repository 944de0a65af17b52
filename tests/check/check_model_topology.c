/* What the model pairs and what it does not:
 *  - a beam bent into a loop that touches itself: with self-contact on, the
 *    touching is found (one contact per crossing, far apart along the beam)
 *    and no segment is in contact with its neighbours; off, nothing;
 *  - two beams joined at a shared host node (a frame corner): no contact at
 *    the joint, although their axes meet there; a beam that starts near the
 *    corner without sharing its node is a contact;
 *  - two beams crossing exactly at nodes of both (coincident crossing
 *    nodes): one contact, for every pair of kinds. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "model_support.h"

#define PI 3.14159265358979323846

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

/* One beam bent into a loop that crosses itself at right angles: the plane
 * curve (t^2 - 1, t (t^2 - 1)) passes through the origin at t = -1 and at
 * t = 1; z = t (r - 0.01) lifts the two passes 2 r - 0.02 apart there. */
static int loop_contacts(int kind, int self_on, double *arc_sep) {
  char msg[B2B_ERRMSG_LEN] = "";
  enum { N = 65 };
  const double r = 0.05;
  double x[3 * N];
  int nodes[N], beam;
  for (int k = 0; k < N; ++k) {
    const double t = -1.6 + 3.2 * k / (N - 1);
    x[3 * k] = t * t - 1.0;
    x[3 * k + 1] = t * (t * t - 1.0);
    x[3 * k + 2] = t * (r - 0.01);
    nodes[k] = k;
  }
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  ok(b2b_model_add_beam(m, nodes, N, 0, r, kind, 3, &beam, msg, sizeof msg), msg);
  ok(b2b_model_set_self_contact(m, beam, self_on, -1.0, msg, sizeof msg), msg);
  ok(b2b_model_set_group_pair(m, 3, 3, p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, N, msg, sizeof msg), msg);
  ok(b2b_model_update(m, x, 3, N, 0, msg, sizeof msg), msg);
  int n;
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
  *arc_sep = 1e300;
  for (int c = 0; c < n; ++c) {
    int pair[4];
    ok(b2b_model_get_contact(m, c, NULL, pair, NULL, NULL, NULL, 0, msg, sizeof msg), msg);
    ck_assert_int_eq(pair[0], 0);
    ck_assert_int_eq(pair[2], 0);
    const double sep = fabs((double)(pair[3] - pair[1])) * 3.2 / (N - 1);  /* in t */
    if (sep < *arc_sep) *arc_sep = sep;
  }
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
  return n;
}

START_TEST(self_contact_loop) {
  for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k) {
    double sep;
    const int on = loop_contacts(k, 1, &sep);
    const int off = loop_contacts(k, 0, &sep);
    double sep_on;
    loop_contacts(k, 1, &sep_on);
    printf("loop, %-22s: self-contact on: %d contact(s), its segments %.2f apart in t (the "
           "crossing: 2); off: %d\n", tst_kind_name(k), on, sep_on, off);
    ck_assert_msg(on == 1, "the loop touching itself: %d contacts, 1 expected", on);
    ck_assert_msg(sep_on > 1.8, "a contact between segments %.2f apart in t", sep_on);
    ck_assert_int_eq(off, 0);
  }
}
END_TEST

/* An L corner: beam 1 along x ending at the corner node, beam 2 along y
 * starting there (shared = 1), or at a node of its own 0.05 above it. */
static int corner_contacts(int kind, int shared) {
  char msg[B2B_ERRMSG_LEN] = "";
  double x[3 * 12] = {0};
  int a[6], b[6], beam;
  for (int k = 0; k < 6; ++k) {
    a[k] = k; /* x from -1 to 0 */
    x[3 * k] = -1.0 + 0.2 * k;
    b[k] = shared ? 5 + k : 6 + k; /* y from 0 to 1 */
    /* shared: node 5 is the corner, nodes 6 .. 10 follow it (an element of
     * length 0 from the corner to a node on top of it is refused) */
    x[3 * (6 + k) + 1] = shared ? 0.2 * (k + 1) : 0.2 * k;
    x[3 * (6 + k) + 2] = shared ? 0.0 : 0.05;
  }
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  ok(b2b_model_add_beam(m, a, 6, 0, 0.05, kind, 0, &beam, msg, sizeof msg), msg);
  ok(b2b_model_add_beam(m, b, 6, 0, 0.05, kind, 0, &beam, msg, sizeof msg), msg);
  ok(b2b_model_set_group_pair(m, 0, 0, p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, 12, msg, sizeof msg), msg);
  ok(b2b_model_update(m, x, 3, 12, 0, msg, sizeof msg), msg);
  int n;
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
  return n;
}

START_TEST(frame_joint_is_not_contact) {
  for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k) {
    const int shared = corner_contacts(k, 1), apart = corner_contacts(k, 0);
    printf("frame corner, %-22s: shared node %d contacts; a node of its own 0.05 above it %d\n",
           tst_kind_name(k), shared, apart);
    ck_assert_int_eq(shared, 0);
    ck_assert_int_ge(apart, 1);
  }
}
END_TEST

START_TEST(crossing_at_nodes_of_both_counts_once) {
  char msg[B2B_ERRMSG_LEN] = "";
  int total = 0;
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
      double x[3 * 14] = {0};
      int a[7], b[7], beam;
      for (int k = 0; k < 7; ++k) {
        a[k] = k;
        x[3 * k] = -0.6 + 0.2 * k; /* node 3 at the origin */
        b[k] = 7 + k;
        x[3 * (7 + k) + 1] = -0.6 + 0.2 * k; /* node 10 above the origin */
        x[3 * (7 + k) + 2] = 0.19;
      }
      b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
      b2b_model *m = NULL;
      ok(b2b_model_create(&m, msg, sizeof msg), msg);
      ok(b2b_model_add_beam(m, a, 7, 0, 0.1, ka, 0, &beam, msg, sizeof msg), msg);
      ok(b2b_model_add_beam(m, b, 7, 0, 0.1, kb, 1, &beam, msg, sizeof msg), msg);
      ok(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg), msg);
      ok(b2b_model_finalize(m, 14, msg, sizeof msg), msg);
      ok(b2b_model_update(m, x, 3, 14, 1, msg, sizeof msg), msg);
      int n;
      double info[32];
      ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
      ck_assert_msg(n == 1, "%s on %s: %d contacts at the crossing nodes",
                    tst_kind_name(ka), tst_kind_name(kb), n);
      ok(b2b_model_get_contact(m, 0, NULL, NULL, info, NULL, NULL, 0, msg, sizeof msg), msg);
      ck_assert(fabs(info[B2B_INFO_GAP] + 0.01) < 1e-3);
      total += n;
      b2b_model_destroy(&m);
      b2b_params_destroy(&p);
    }
  printf("crossing exactly at nodes of both beams: %d kind pairs, one contact each\n", total);
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_topology");
  TCase *tc = tcase_create("topology");
  tcase_add_test(tc, self_contact_loop);
  tcase_add_test(tc, frame_joint_is_not_contact);
  tcase_add_test(tc, crossing_at_nodes_of_both_counts_once);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
