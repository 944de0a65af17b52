/* The interpenetration audit (b2b_model_audit): a scene per reason in which
 * two beams overlap with no force and the audit must list the pair with that
 * reason (or, where another part of issue 16 will make the model carry the
 * force, either that or the listing); crossed beams in contact (every curve
 * kind) give an empty audit; the audit against brute force on a network;
 * bad input (NULL, capacity, state, tolerance) gives its documented status,
 * a message, and leaves the outputs as they were. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_support.h"

#define MAXF 64

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

/* A model of beams given as node lists into one coordinate array. */
typedef struct {
  int n;             /* beams */
  const int *nodes[4];
  int count[4], closed[4], kind[4], group[4], self[4];
  double radius[4], exclusion[4];
} scene;

static b2b_model *build(const scene *s, int n_nodes, const b2b_params *p) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_model *m = NULL;
  int beam;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  int groups_used[2] = {0, 0};
  for (int b = 0; b < s->n; ++b) {
    ok(b2b_model_add_beam(m, s->nodes[b], s->count[b], s->closed[b], s->radius[b], s->kind[b],
                          s->group[b], &beam, msg, sizeof msg), msg);
    groups_used[s->group[b]] = 1;
    if (s->self[b]) ok(b2b_model_set_self_contact(m, beam, 1, s->exclusion[b], msg, sizeof msg), msg);
  }
  ok(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg), msg);
  if (groups_used[0]) ok(b2b_model_set_group_pair(m, 0, 0, p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, n_nodes, msg, sizeof msg), msg);
  return m;
}

typedef struct {
  int n, pairs[4 * MAXF], reasons[MAXF];
  double overlap[MAXF];
} findings;

static void run_audit(const b2b_model *m, double tol, findings *f) {
  char msg[B2B_ERRMSG_LEN] = "";
  int count = -1;
  ok(b2b_model_audit(m, tol, &count, NULL, NULL, NULL, 0, msg, sizeof msg), msg);
  ck_assert_int_le(count, MAXF);
  ok(b2b_model_audit(m, tol, &f->n, f->pairs, f->overlap, f->reasons, MAXF, msg, sizeof msg), msg);
  ck_assert_int_eq(f->n, count);  /* the size query counts what the call lists */
  for (int k = 0; k < f->n; ++k) ck_assert(f->overlap[k] > 0.0);
}

static int contacts(const b2b_model *m) {
  char msg[B2B_ERRMSG_LEN] = "";
  int n = -1;
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
  return n;
}

static const char *reason_name(int r) {
  static const char *names[] = {"OTHER", "PARALLEL", "OUTSIDE_BOTH", "NEVER_EVALUATED",
                                "EXCLUDED_SELF", "CROSSED"};
  return r >= 0 && r <= 5 ? names[r] : "?";
}

static void print(const char *what, const findings *f) {
  printf("%s: %d finding(s)", what, f->n);
  for (int k = 0; k < f->n; ++k)
    printf(" [%d.%d-%d.%d %s %.3g]", f->pairs[4 * k], f->pairs[4 * k + 1], f->pairs[4 * k + 2],
           f->pairs[4 * k + 3], reason_name(f->reasons[k]), f->overlap[k]);
  printf("\n");
}

static int all_reasons(const findings *f, int reason) {
  for (int k = 0; k < f->n; ++k)
    if (f->reasons[k] != reason) return 0;
  return 1;
}

/* Whether beam ba segment sa against beam bb segment sb is listed. */
static int listed(const findings *f, int ba, int sa, int bb, int sb) {
  for (int k = 0; k < f->n; ++k) {
    const int *p = f->pairs + 4 * k;
    if ((p[0] == ba && p[1] == sa && p[2] == bb && p[3] == sb) ||
        (p[0] == bb && p[1] == sb && p[2] == ba && p[3] == sa))
      return 1;
  }
  return 0;
}

/* The reason of a listed pair (-1: not listed). */
static int reason_of(const findings *f, int ba, int sa, int bb, int sb) {
  for (int k = 0; k < f->n; ++k) {
    const int *p = f->pairs + 4 * k;
    if ((p[0] == ba && p[1] == sa && p[2] == bb && p[3] == sb) ||
        (p[0] == bb && p[1] == sb && p[2] == ba && p[3] == sa))
      return f->reasons[k];
  }
  return -1;
}

/* Beam 0 along x (nodes 0..4, x = -1 .. 1), beam 1 along y at height z
 * (nodes 5..9), both radius 0.1: they cross at 90 degrees inside segments
 * (the nodes are at +-0.35, +-0.9 ... not at 0). */
static const int cross_a[5] = {0, 1, 2, 3, 4}, cross_b[5] = {5, 6, 7, 8, 9};
static void crossed_coords(double *x, double z) {
  const double t[5] = {-1.0, -0.45, 0.15, 0.6, 1.1};
  for (int k = 0; k < 5; ++k) {
    x[3 * k + 0] = t[k];
    x[3 * k + 1] = 0.0;
    x[3 * k + 2] = 0.0;
    x[3 * (5 + k) + 0] = 0.05;
    x[3 * (5 + k) + 1] = t[k] * 0.9 + 0.02;
    x[3 * (5 + k) + 2] = z;
  }
}

START_TEST(crossed_contact_gives_empty_audit) {
  char msg[B2B_ERRMSG_LEN] = "";
  int total_contacts = 0;
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
      b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
      scene s = {2, {cross_a, cross_b}, {5, 5}, {0, 0}, {ka, kb}, {0, 1}, {0, 0},
                 {0.1, 0.1}, {-1, -1}};
      b2b_model *m = build(&s, 10, p);
      double x[30];
      findings f;
      /* apart, then touching, then pressed in: a host's steps */
      const double z[3] = {0.25, 0.2, 0.19};
      for (int step = 0; step < 3; ++step) {
        crossed_coords(x, z[step]);
        ok(b2b_model_update(m, x, 3, 10, 1, msg, sizeof msg), msg);
        run_audit(m, 0.0, &f);
        if (f.n) print("crossed beams", &f);
        ck_assert_msg(f.n == 0, "%s on %s, step %d: %d findings", tst_kind_name(ka),
                      tst_kind_name(kb), step, f.n);
        ok(b2b_model_commit(m, msg, sizeof msg), msg);
      }
      /* the step pressed in carries force: the audit was not empty for want of an overlap */
      ck_assert_int_eq(contacts(m), 1);
      total_contacts += contacts(m);
      b2b_model_destroy(&m);
      b2b_params_destroy(&p);
    }
  printf("crossed beams in contact, %d kind pairs: audit empty\n", total_contacts);
}
END_TEST

/* Beams whose groups do not touch are never listed, however deep. */
START_TEST(groups_that_do_not_touch_are_not_listed) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  /* both beams in group 1: only (0,1) and (0,0) are set, (1,1) is not */
  scene s = {2, {cross_a, cross_b}, {5, 5}, {0, 0}, {2, 2}, {1, 1}, {0, 0}, {0.1, 0.1}, {-1, -1}};
  b2b_model *m = NULL;
  int beam;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  for (int b = 0; b < 2; ++b)
    ok(b2b_model_add_beam(m, s.nodes[b], 5, 0, 0.1, 2, 1, &beam, msg, sizeof msg), msg);
  ok(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, 10, msg, sizeof msg), msg);
  double x[30];
  crossed_coords(x, 0.1);
  ok(b2b_model_update(m, x, 3, 10, 1, msg, sizeof msg), msg);
  findings f;
  run_audit(m, 0.0, &f);
  ck_assert_int_eq(f.n, 0);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* Two parallel beams (every kind) pressed halfway into each other: below
 * parallel_angle the element carries no force; the audit lists them. */
START_TEST(parallel_beams_are_listed) {
  char msg[B2B_ERRMSG_LEN] = "";
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
    static const int a[6] = {0, 1, 2, 3, 4, 5}, b[6] = {6, 7, 8, 9, 10, 11};
    scene s = {2, {a, b}, {6, 6}, {0, 0}, {kind, kind}, {0, 1}, {0, 0}, {0.1, 0.1}, {-1, -1}};
    b2b_model *m = build(&s, 12, p);
    double x[36];
    for (int k = 0; k < 6; ++k) {
      x[3 * k + 0] = 0.5 * k;
      x[3 * k + 1] = 0.0;
      x[3 * k + 2] = 0.0;
      x[3 * (6 + k) + 0] = 0.5 * k + 0.2;  /* staggered nodes */
      x[3 * (6 + k) + 1] = 0.0;
      x[3 * (6 + k) + 2] = 0.15;           /* overlap 0.05 = r / 2 */
    }
    ok(b2b_model_update(m, x, 3, 12, 1, msg, sizeof msg), msg);
    findings f;
    run_audit(m, 0.01, &f);
    print(tst_kind_name(kind), &f);
    ck_assert_int_eq(contacts(m), 0);  /* line contact is not the element's */
    ck_assert_int_ge(f.n, 4);
    ck_assert(all_reasons(&f, B2B_AUDIT_PARALLEL));
    ck_assert(listed(&f, 0, 2, 1, 2));  /* the middle segments, overlapping along 0.3 */
    for (int k = 0; k < f.n; ++k) ck_assert(fabs(f.overlap[k] - 0.05) < 1e-9);
    /* a tolerance above the overlap (0.05 = 0.5 r) hides them all */
    run_audit(m, 0.51, &f);
    ck_assert_int_eq(f.n, 0);
    b2b_model_destroy(&m);
    b2b_params_destroy(&p);
  }
}
END_TEST

/* A V of straight segments pressed 2 cm onto another beam at its node (the
 * convex joint of issue 16): the element finds the point OUTSIDE on both
 * segments of the V. Either the model carries a contact there (node-to-
 * segment contact) or the audit lists both pairs as OUTSIDE_BOTH. */
START_TEST(convex_joint_is_listed_unless_carried) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  static const int v[3] = {0, 1, 2}, b[4] = {3, 4, 5, 6};
  scene s = {2, {v, b}, {3, 4}, {0, 0}, {B2B_CURVE_LINEAR, B2B_CURVE_LINEAR}, {0, 1}, {0, 0},
             {0.1, 0.1}, {-1, -1}};
  b2b_model *m = build(&s, 7, p);
  const double apex = 0.2 - 0.02;
  double x[21] = {-1.0, 0.0, apex + 0.5, 0.0, 0.0, apex, 1.0, 0.0, apex + 0.5,
                  0.0, -1.0, 0.0, 0.0, -0.3, 0.0, 0.0, 0.4, 0.0, 0.0, 1.0, 0.0};
  ok(b2b_model_update(m, x, 3, 7, 1, msg, sizeof msg), msg);
  findings f;
  run_audit(m, 0.01, &f);
  print("V on a beam", &f);
  if (contacts(m) > 0) {
    ck_assert_int_eq(f.n, 0);
  } else {
    ck_assert_int_eq(f.n, 2);
    ck_assert(all_reasons(&f, B2B_AUDIT_OUTSIDE_BOTH));
    ck_assert(listed(&f, 0, 0, 1, 1) && listed(&f, 0, 1, 1, 1));
    for (int k = 0; k < f.n; ++k) ck_assert(fabs(f.overlap[k] - 0.02) < 1e-9);
  }
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* A hairpin (one beam folded back on itself, its two legs overlapping by
 * half a radius) with self-contact on: with an exclusion length longer than
 * the beam the legs are EXCLUDED_SELF; with the default (4 r) the legs are
 * paired, and, parallel, listed as PARALLEL. Without self-contact nothing. */
START_TEST(self_contact_exclusion_is_listed) {
  char msg[B2B_ERRMSG_LEN] = "";
  static const int hp[11] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  double x[33];
  for (int k = 0; k < 5; ++k) {
    x[3 * k + 0] = 0.5 * k;
    x[3 * k + 1] = 0.0;
    x[3 * (6 + k) + 0] = 2.0 - 0.5 * k;
    x[3 * (6 + k) + 1] = 0.15;
  }
  x[15] = 2.4;
  x[16] = 0.075;
  for (int k = 0; k < 11; ++k) x[3 * k + 2] = 0.0;
  const double exclusion[3] = {100.0, -1.0, -1.0};
  const int self[3] = {1, 1, 0};
  const int expect[3] = {B2B_AUDIT_EXCLUDED_SELF, B2B_AUDIT_PARALLEL, -1};
  for (int c = 0; c < 3; ++c) {
    b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
    scene s = {1, {hp}, {11}, {0}, {B2B_CURVE_LINEAR}, {0}, {self[c]}, {0.1}, {exclusion[c]}};
    b2b_model *m = build(&s, 11, p);
    ok(b2b_model_update(m, x, 3, 11, 1, msg, sizeof msg), msg);
    findings f;
    run_audit(m, 0.01, &f);
    print(c == 0 ? "hairpin, long exclusion" : c == 1 ? "hairpin, default" : "hairpin, no self",
          &f);
    if (expect[c] < 0) {
      ck_assert_int_eq(f.n, 0);
    } else {
      ck_assert_int_ge(f.n, 3);
      /* x in [0.5, 1] against its twin */
      ck_assert_int_eq(reason_of(&f, 0, 1, 0, 8), expect[c]);
      ck_assert_int_eq(reason_of(&f, 0, 0, 0, 9), expect[c]);
      /* with the long exclusion every pair is excluded; by default the
       * segments at the fold meet at a convex joint (OUTSIDE_BOTH) */
      for (int k = 0; k < f.n; ++k)
        ck_assert(f.reasons[k] == expect[c] || (c == 1 && f.reasons[k] == B2B_AUDIT_OUTSIDE_BOTH));
    }
    b2b_model_destroy(&m);
    b2b_params_destroy(&p);
  }
}
END_TEST

/* Two parallel beams, apart at the commit, and at the update beam 1 moved
 * down through beam 0 so that its centreline lies 0.1 below the other's (an
 * overlap of r; below parallel_angle: no force). The audit lists the pairs
 * CROSSED; the same overlap reached from above without passing through is
 * PARALLEL. Every curve kind. */
START_TEST(crossed_since_commit_is_listed) {
  char msg[B2B_ERRMSG_LEN] = "";
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
    for (int through = 0; through < 2; ++through) {
      b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
      static const int a[5] = {0, 1, 2, 3, 4}, b[5] = {5, 6, 7, 8, 9};
      scene s = {2, {a, b}, {5, 5}, {0, 0}, {kind, kind}, {0, 1}, {0, 0}, {0.1, 0.1}, {-1, -1}};
      b2b_model *m = build(&s, 10, p);
      double x[30];
      for (int k = 0; k < 5; ++k) {
        x[3 * k + 0] = 0.5 * k;
        x[3 * (5 + k) + 0] = 0.5 * k + 0.2;
        x[3 * k + 1] = x[3 * (5 + k) + 1] = 0.0;
        x[3 * k + 2] = 0.0;
        x[3 * (5 + k) + 2] = 0.3; /* apart */
      }
      ok(b2b_model_update(m, x, 3, 10, 1, msg, sizeof msg), msg);
      ok(b2b_model_commit(m, msg, sizeof msg), msg);
      for (int k = 0; k < 5; ++k) x[3 * (5 + k) + 2] = through ? -0.1 : 0.1;
      ok(b2b_model_update(m, x, 3, 10, 1, msg, sizeof msg), msg);
      findings f;
      run_audit(m, 0.01, &f);
      printf("%s, %s: ", tst_kind_name(kind), through ? "moved through" : "moved onto");
      print("audit", &f);
      ck_assert_int_eq(contacts(m), 0);
      ck_assert_int_ge(f.n, 4);
      ck_assert(listed(&f, 0, 1, 1, 1));
      ck_assert(all_reasons(&f, through ? B2B_AUDIT_CROSSED : B2B_AUDIT_PARALLEL));
      for (int k = 0; k < f.n; ++k) ck_assert(fabs(f.overlap[k] - 0.1) < 1e-9);
      b2b_model_destroy(&m);
      b2b_params_destroy(&p);
    }
}
END_TEST

/* A pair the last update never evaluated: crossed beams 2 apart at the
 * first update (not candidates: boxes grown by r + 4s/3 with the default
 * margin s = r), then "search_margin" raised to 10 and beam 1 moved 1.85
 * down into beam 0. The move is below half the new margin, so the model
 * keeps its candidate list (issue 16, item 3: an option set after an update
 * does not renew what depends on it). Either the model searches again and
 * carries the contact, or the audit lists the pair NEVER_EVALUATED. */
START_TEST(never_evaluated_is_listed_unless_carried) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  scene s = {2, {cross_a, cross_b}, {5, 5}, {0, 0}, {2, 2}, {0, 1}, {0, 0}, {0.1, 0.1}, {-1, -1}};
  b2b_model *m = build(&s, 10, p);
  double x[30];
  crossed_coords(x, 2.0);
  ok(b2b_model_update(m, x, 3, 10, 1, msg, sizeof msg), msg);
  ok(b2b_model_commit(m, msg, sizeof msg), msg);
  ok(b2b_model_set_real(m, "search_margin", 10.0, msg, sizeof msg), msg);
  crossed_coords(x, 0.15);
  ok(b2b_model_update(m, x, 3, 10, 1, msg, sizeof msg), msg);
  findings f;
  run_audit(m, 0.01, &f);
  printf("stale candidates: %d contact(s); ", contacts(m));
  print("audit", &f);
  if (contacts(m) > 0) {
    ck_assert_int_eq(f.n, 0);
  } else {
    /* the crossing's pair, and its neighbour across the joint nearby */
    ck_assert_int_ge(f.n, 1);
    ck_assert(all_reasons(&f, B2B_AUDIT_NEVER_EVALUATED));
    ck_assert_int_eq(reason_of(&f, 0, 1, 1, 1), B2B_AUDIT_NEVER_EVALUATED);
    ck_assert(fabs(f.overlap[0] - 0.05) < 1e-9);
  }
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* The audit against brute force on a random fibre network (every kind,
 * rings): with "parallel_angle" 89.9 degrees the element leaves (nearly)
 * every pair without force, so the audit must list every overlapping pair.
 * Reference: each segment sampled at 129 points by b2b_segment_eval, the
 * smallest sampled distance of every allowed pair (an upper bound of the
 * true one, within about a sample spacing). Every pair overlapping by more
 * than 0.05 r in the samples is listed (unless a contact touches it), every
 * listed one overlaps in the samples by more than the tolerance less the
 * sampling error, and the audit's overlap is at least the sampled one. */
#define NS 129
START_TEST(random_network_against_brute_force) {
  char msg[B2B_ERRMSG_LEN] = "";
  tst_rng rng;
  tst_rng_seed(&rng, 4242);
  tst_scene sc;
  tst_network(&rng, 40, 9, 0.5, 2.0, 0.1, 0.3, 5, 0, &sc);
  b2b_params *p = NULL;
  ok(b2b_params_create(&p, msg, sizeof msg), msg);
  ok(b2b_params_set_real(p, "penalty", 1e3, msg, sizeof msg), msg);
  ok(b2b_params_set_real(p, "parallel_angle", 89.9, msg, sizeof msg), msg);
  ok(b2b_params_finalize(p, msg, sizeof msg), msg);
  b2b_model *m = tst_model(&sc, p, 1);
  tst_update(m, &sc, 0);
  const double tol = 0.01;
  int n = 0;
  ok(b2b_model_audit(m, tol, &n, NULL, NULL, NULL, 0, msg, sizeof msg), msg);
  int *pairs = malloc(sizeof(int) * 4 * (size_t)(n + 1)), *reasons = malloc(sizeof(int) * (size_t)(n + 1));
  double *overlap = malloc(sizeof(double) * (size_t)(n + 1));
  int listed_n = 0;
  ok(b2b_model_audit(m, tol, &listed_n, pairs, overlap, reasons, n, msg, sizeof msg), msg);
  ck_assert_int_eq(listed_n, n);
  /* segments in contact (and their neighbours) are left out of the coverage check */
  int n_contacts = contacts(m), busy[2 * 64][2];
  ck_assert_int_le(n_contacts, 64);
  for (int k = 0; k < n_contacts; ++k) {
    int pr[4];
    ok(b2b_model_get_contact(m, k, NULL, pr, NULL, NULL, NULL, 0, msg, sizeof msg), msg);
    busy[2 * k][0] = pr[0], busy[2 * k][1] = pr[1];
    busy[2 * k + 1][0] = pr[2], busy[2 * k + 1][1] = pr[3];
  }
  /* samples of every segment, and their bounding box */
  int n_seg = 0, seg_beam[4096], seg_index[4096];
  static double pts[4096][NS][3], lo[4096][3], hi[4096][3];
  for (int b = 0; b < sc.n_beams; ++b) {
    int ns;
    ok(b2b_beam_segment_count(sc.kind[b], sc.count[b], sc.closed[b], &ns, msg, sizeof msg), msg);
    for (int s = 0; s < ns; ++s, ++n_seg) {
      ck_assert_int_lt(n_seg, 4096);
      int local[4], r0, r1;
      ok(b2b_beam_segment_patch(sc.kind[b], sc.count[b], sc.closed[b], s, local, &r0, &r1, msg,
                                sizeof msg), msg);
      double X[12];
      for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 3; ++i)
          X[3 * k + i] = local[k] < 0 ? 0.0 : sc.x[3 * (sc.first[b] + local[k]) + i];
      for (int q = 0; q < NS; ++q) {
        double x[9];
        ok(b2b_segment_eval(sc.kind[b], r0, r1, X, NULL, -1.0 + 2.0 * q / (NS - 1), x, NULL,
                            NULL, msg, sizeof msg), msg);
        memcpy(pts[n_seg][q], x, sizeof(double) * 3);
        for (int i = 0; i < 3; ++i) {
          lo[n_seg][i] = q == 0 ? x[i] : fmin(lo[n_seg][i], x[i]);
          hi[n_seg][i] = q == 0 ? x[i] : fmax(hi[n_seg][i], x[i]);
        }
      }
      seg_beam[n_seg] = b;
      seg_index[n_seg] = s;
    }
  }
  int checked = 0, overlapping = 0;
  for (int i = 0; i < n_seg; ++i)
    for (int j = i + 1; j < n_seg; ++j) {
      const int bi = seg_beam[i], bj = seg_beam[j];
      if (bi == bj) continue; /* no self-contact in this scene */
      const double ra = sc.radius[bi], rb = sc.radius[bj];
      int k = -1;
      for (int f = 0; f < n; ++f) {
        const int *pr = pairs + 4 * f;
        if (pr[0] == bi && pr[1] == seg_index[i] && pr[2] == bj && pr[3] == seg_index[j]) k = f;
      }
      /* An unlisted pair whose sample boxes lie more than ra + rb apart
       * overlaps by less than 0 in the samples (no sample distance is below
       * the boxes'): neither check below can concern it, and the 129 x 129
       * distances (most of this suite's time) are skipped. */
      double gap2 = 0.0;
      for (int a = 0; a < 3; ++a) {
        const double g = fmax(lo[i][a] - hi[j][a], lo[j][a] - hi[i][a]);
        if (g > 0.0) gap2 += g * g;
      }
      if (k < 0 && gap2 > (ra + rb) * (ra + rb)) continue;
      double d2 = HUGE_VAL;
      for (int p1 = 0; p1 < NS; ++p1)
        for (int q = 0; q < NS; ++q) {
          const double dx = pts[i][p1][0] - pts[j][q][0], dy = pts[i][p1][1] - pts[j][q][1],
                       dz = pts[i][p1][2] - pts[j][q][2];
          const double e = dx * dx + dy * dy + dz * dz;
          if (e < d2) d2 = e;
        }
      const double ov = ra + rb - sqrt(d2), rmin = fmin(ra, rb);
      if (k >= 0) {
        /* a sample spacing of 2/128 of a segment of length <= 0.7: error < 0.006 */
        ck_assert_msg(ov > tol * rmin - 0.006, "listed %d.%d-%d.%d overlaps by %g in the samples",
                      bi, seg_index[i], bj, seg_index[j], ov);
        ck_assert_msg(overlap[k] >= ov - 1e-9, "audit overlap %g < sampled %g", overlap[k], ov);
        ++checked;
      }
      if (ov > 0.05 * rmin) {
        ++overlapping;
        int near_contact = 0;
        for (int c = 0; c < 2 * n_contacts; ++c)
          for (int w = 0; w < 2; ++w) {
            const int b = w ? bj : bi, s = w ? seg_index[j] : seg_index[i];
            if (busy[c][0] == b && abs(busy[c][1] - s) <= 1) near_contact = 1;
          }
        ck_assert_msg(k >= 0 || near_contact, "%d.%d-%d.%d overlaps by %g (samples), not listed",
                      bi, seg_index[i], bj, seg_index[j], ov);
      }
    }
  printf("random network: %d segments, %d contacts, %d listed (%d checked), %d overlapping by "
         "> 0.05 r in the samples\n", n_seg, n_contacts, n, checked, overlapping);
  ck_assert_int_eq(checked, n);
  ck_assert_int_ge(overlapping, 10);
  free(pairs);
  free(reasons);
  free(overlap);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
  tst_scene_free(&sc);
}
END_TEST

START_TEST(bad_input) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  static const int a[6] = {0, 1, 2, 3, 4, 5}, b[6] = {6, 7, 8, 9, 10, 11};
  scene s = {2, {a, b}, {6, 6}, {0, 0}, {0, 0}, {0, 1}, {0, 0}, {0.1, 0.1}, {-1, -1}};
  double x[36];
  for (int k = 0; k < 6; ++k) {
    x[3 * k + 0] = x[3 * (6 + k) + 0] = 0.5 * k;
    x[3 * k + 1] = x[3 * (6 + k) + 1] = 0.0;
    x[3 * k + 2] = 0.0;
    x[3 * (6 + k) + 2] = 0.15;
  }
  int n = -7, pairs[8] = {-7, -7, -7, -7, -7, -7, -7, -7}, reasons[2] = {-7, -7};
  double overlap[2] = {-7, -7};
  /* an unfinalized model, then before any update */
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  ck_assert_int_eq(b2b_model_audit(m, 0.0, &n, NULL, NULL, NULL, 0, msg, sizeof msg),
                   B2B_ERR_STATE);
  b2b_model_destroy(&m);
  m = build(&s, 12, p);
  ck_assert_int_eq(b2b_model_audit(m, 0.0, &n, NULL, NULL, NULL, 0, msg, sizeof msg),
                   B2B_ERR_STATE);
  ck_assert_msg(strstr(msg, "b2b_model_update") != NULL, "%s", msg);
  ck_assert_int_eq(b2b_model_audit(NULL, 0.0, &n, NULL, NULL, NULL, 0, msg, sizeof msg),
                   B2B_ERR_NULL);
  ok(b2b_model_update(m, x, 3, 12, 1, msg, sizeof msg), msg);
  int count = 0;
  ok(b2b_model_audit(m, 0.0, &count, NULL, NULL, NULL, 0, msg, sizeof msg), msg);
  ck_assert_int_ge(count, 3);  /* parallel, overlapping by r/2 */
  ck_assert_int_eq(b2b_model_audit(m, 0.0, NULL, pairs, overlap, reasons, 2, msg, sizeof msg),
                   B2B_ERR_NULL);
  ck_assert_msg(strstr(msg, "n_found") != NULL, "%s", msg);
  ck_assert_int_eq(b2b_model_audit(m, 0.0, &n, pairs, NULL, reasons, 2, msg, sizeof msg),
                   B2B_ERR_NULL);
  ck_assert_msg(strstr(msg, "overlap") != NULL, "%s", msg);
  ck_assert_int_eq(b2b_model_audit(m, 0.0, &n, pairs, overlap, NULL, 2, msg, sizeof msg),
                   B2B_ERR_NULL);
  ck_assert_msg(strstr(msg, "reasons") != NULL, "%s", msg);
  /* too small: B2B_ERR_SIZE, the count in the message, nothing written */
  ck_assert_int_eq(b2b_model_audit(m, 0.0, &n, pairs, overlap, reasons, 2, msg, sizeof msg),
                   B2B_ERR_SIZE);
  char want[64];
  snprintf(want, sizeof want, "%d findings", count);
  ck_assert_msg(strstr(msg, want) != NULL, "%s", msg);
  ck_assert_int_eq(b2b_model_audit(m, 0.0, &n, pairs, overlap, reasons, -1, msg, sizeof msg),
                   B2B_ERR_SIZE);
  /* tolerance: negative, NaN, infinite */
  ck_assert_int_eq(b2b_model_audit(m, -0.1, &n, NULL, NULL, NULL, 0, msg, sizeof msg),
                   B2B_ERR_RANGE);
  ck_assert_msg(strstr(msg, "tolerance") != NULL, "%s", msg);
  ck_assert_int_eq(b2b_model_audit(m, NAN, &n, NULL, NULL, NULL, 0, msg, sizeof msg),
                   B2B_ERR_NONFINITE);
  ck_assert_msg(strstr(msg, "tolerance") != NULL, "%s", msg);
  ck_assert_int_eq(b2b_model_audit(m, INFINITY, &n, NULL, NULL, NULL, 0, msg, sizeof msg),
                   B2B_ERR_NONFINITE);
  for (int k = 0; k < 8; ++k) ck_assert_int_eq(pairs[k], -7);
  ck_assert(n == -7 && reasons[0] == -7 && reasons[1] == -7 && overlap[0] == -7 &&
            overlap[1] == -7);
  /* after a revert: no results */
  ok(b2b_model_revert(m, msg, sizeof msg), msg);
  ck_assert_int_eq(b2b_model_audit(m, 0.0, &n, NULL, NULL, NULL, 0, msg, sizeof msg),
                   B2B_ERR_STATE);
  ck_assert_int_eq(n, -7);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_audit");
  TCase *tc = tcase_create("audit");
  tcase_add_test(tc, crossed_contact_gives_empty_audit);
  tcase_add_test(tc, groups_that_do_not_touch_are_not_listed);
  tcase_add_test(tc, parallel_beams_are_listed);
  tcase_add_test(tc, convex_joint_is_listed_unless_carried);
  tcase_add_test(tc, self_contact_exclusion_is_listed);
  tcase_add_test(tc, crossed_since_commit_is_listed);
  tcase_add_test(tc, never_evaluated_is_listed_unless_carried);
  tcase_add_test(tc, random_network_against_brute_force);
  tcase_add_test(tc, bad_input);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
