/* Bad input of the contact model (b2b_model_*, <b2b/b2b_model.h>).
 *
 * For every documented bad input each test checks
 *   - the documented status code,
 *   - a NUL-terminated message, within the buffer, that names the problem
 *     (strstr on the beam, node, group, key or argument),
 *   - the same code with errmsg = NULL, 0 and with an 8-byte buffer (whose
 *     text is the start of the full message),
 *   - that no output was touched (pre-filled with a sentinel, compared
 *     bitwise, with padding after each array),
 *   - that the model is unchanged: what it reports after the failure is bit
 *     for bit what it reported before (contacts, tangents, stats), and it
 *     goes on exactly like a twin model that never saw the bad call (the
 *     same updates and commits on both give bit-identical contacts, stats and
 *     restart bytes).
 * Next to the errors sit the closest inputs that are NOT errors (an unused
 * node column holding NaN, Inf or a huge value, ldx > 3, a wide enough band,
 * coordinates scaled by 1e-90 and 1e90, a penalty of 0, near-parallel beams),
 * which must succeed with finite outputs.
 *
 * The scene (host nodes 0 .. 15, node 10 used by no beam):
 *   beam 0  nodes 0..4, HERMITE_NODAL, along x in z = 0, bent in y (0.05 x^2),
 *           group 0
 *   beam 1  nodes 5..9, HERMITE_NODAL_WEIGHTED, along y at x = 0.3, z = -0.15,
 *           group 0
 *   beam 2  nodes 11..15, LINEAR, along y at x = -0.7, z = +0.15, group 1
 * all of radius 0.1, so beam 0 touches beam 1 (segments 2 and 1) and beam 2
 * (segments 1 and 1) with gap -0.05. Group pairs: (0, 0) frictionless,
 * penalty 100; (0, 1) with friction 0.3, tangential penalty 50. */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pair_support.h"

#define NN 16       /* host nodes */
#define UNUSED 10   /* the host node no beam uses */
#define NB 3        /* beams */
#define RADIUS 0.1
#define DIST 0.15   /* axis distance of both crossings */
#define PEN 100.0
#define MU 0.3
#define EPS_T 50.0
#define MAXC 8      /* room for contacts in a snapshot */
#define LDMAX 30
#define PAD 4
#define SENT 12345.0
#define SENT_INT (-777)
#define GUARD 'Z'
#define NEQ (3 * NN)

enum { LIN = B2B_CURVE_LINEAR, NOD = B2B_CURVE_HERMITE_NODAL,
       NDW = B2B_CURVE_HERMITE_NODAL_WEIGHTED };

static const int beam_nodes[NB][5] = {{0, 1, 2, 3, 4}, {5, 6, 7, 8, 9}, {11, 12, 13, 14, 15}};
static const int beam_kind[NB] = {NOD, NDW, LIN};
static const int beam_group[NB] = {0, 0, 1};

#define CTX(...) snprintf(ctx, sizeof ctx, __VA_ARGS__)

/* ============================================================ messages */

static char g_msg[B2B_ERRMSG_LEN + 16];
static char g_tiny[16];
/* The message arguments of the call under test (set by EXPECT_FAIL). */
static char *g_cur;
static int g_len;
#define MSG g_cur, g_len

static char *fresh_msg(void) {
  memset(g_msg, GUARD, sizeof g_msg);
  return g_msg;
}

static void check_message(const char *ctx, const char *msg, int len, size_t size, const char *w1,
                          const char *w2, const char *w3) {
  ck_assert_msg(memchr(msg, '\0', (size_t)len) != NULL, "%s: message not NUL-terminated", ctx);
  for (size_t i = (size_t)len; i < size; ++i)
    ck_assert_msg(msg[i] == GUARD, "%s: message buffer overrun at byte %zu", ctx, i);
  ck_assert_msg(msg[0] != '\0', "%s: empty message", ctx);
  const char *w[3] = {w1, w2, w3};
  for (int k = 0; k < 3; ++k)
    if (w[k])
      ck_assert_msg(strstr(msg, w[k]) != NULL, "%s: message \"%s\" does not contain \"%s\"", ctx,
                    msg, w[k]);
}

/* The call made with fresh_msg(), B2B_ERRMSG_LEN failed with want. */
static void check_failure(const char *ctx, int st, int want, const char *w1, const char *w2,
                          const char *w3) {
  ck_assert_msg(st == want, "%s: status %d (%s), expected %d (%s); message: %.*s", ctx, st,
                b2b_strerror(st), want, b2b_strerror(want), B2B_ERRMSG_LEN, g_msg);
  check_message(ctx, g_msg, B2B_ERRMSG_LEN, sizeof g_msg, w1, w2, w3);
  if (getenv("B2B_TEST_VERBOSE")) printf("%-50s -> %s\n", ctx, g_msg);
}

static void check_tiny(const char *ctx, int st, int want) {
  ck_assert_msg(st == want, "%s (errmsg_len 8): status %d, expected %d", ctx, st, want);
  check_message(ctx, g_tiny, 8, sizeof g_tiny, NULL, NULL, NULL);
  ck_assert_msg(strncmp(g_tiny, g_msg, 7) == 0, "%s: errmsg_len 8 gave \"%s\", not the start of "
                "\"%s\"", ctx, g_tiny, g_msg);
}

/* The call (whose message arguments are MSG) fails with want and a message
 * holding the words, with a full buffer, with NULL, 0 and with 8 bytes. The
 * full message stays in g_msg. Needs `ctx` in scope. */
#define EXPECT_FAIL(want, w1, w2, w3, call)                                              \
  do {                                                                                   \
    g_cur = fresh_msg();                                                                 \
    g_len = B2B_ERRMSG_LEN;                                                              \
    check_failure(ctx, (call), (want), (w1), (w2), (w3));                                \
    char saved_[B2B_ERRMSG_LEN];                                                         \
    memcpy(saved_, g_msg, sizeof saved_);                                                \
    g_cur = NULL;                                                                        \
    g_len = 0;                                                                           \
    const int st0_ = (call);                                                             \
    ck_assert_msg(st0_ == (want), "%s (errmsg NULL, 0): status %d, expected %d", ctx, st0_, \
                  (want));                                                               \
    memset(g_tiny, GUARD, sizeof g_tiny);                                                \
    g_cur = g_tiny;                                                                      \
    g_len = 8;                                                                           \
    memcpy(g_msg, saved_, sizeof saved_);                                                \
    check_tiny(ctx, (call), (want));                                                     \
  } while (0)

/* The call succeeds and leaves the message buffer alone. */
#define EXPECT_OK(call)                                                                  \
  do {                                                                                   \
    g_cur = fresh_msg();                                                                 \
    g_len = B2B_ERRMSG_LEN;                                                              \
    const int st_ = (call);                                                              \
    ck_assert_msg(st_ == B2B_OK, "%s: status %d (%s): %.*s", ctx, st_, b2b_strerror(st_), \
                  B2B_ERRMSG_LEN, g_msg);                                                \
    for (size_t i_ = 0; i_ < sizeof g_msg; ++i_)                                         \
      ck_assert_msg(g_msg[i_] == GUARD, "%s: a successful call wrote errmsg[%zu]", ctx, i_); \
  } while (0)

/* ============================================================ the scene */

/* Host coordinates (3 x NN, ldx 3): beam 0 moved by `step` times
 * (0.02, 0.005, 0); beam 1 at z = -dist1. */
static void scene_x_at(double *x, int step, double dist1) {
  for (int i = 0; i < 3 * NN; ++i) x[i] = 0.0;
  for (int k = 0; k < 5; ++k) {
    const double s = -2.0 + k;
    double *p = x + 3 * beam_nodes[0][k];
    p[0] = s + 0.02 * step;
    p[1] = 0.05 * s * s + 0.005 * step;
    p[2] = 0.0;
    p = x + 3 * beam_nodes[1][k];
    p[0] = 0.3;
    p[1] = -1.8 + k;
    p[2] = -dist1;
    p = x + 3 * beam_nodes[2][k];
    p[0] = -0.7;
    p[1] = -1.7 + k;
    p[2] = DIST;
  }
  x[3 * UNUSED] = x[3 * UNUSED + 1] = x[3 * UNUSED + 2] = 5.0;
}

static void scene_x(double *x, int step) { scene_x_at(x, step, DIST); }

static void scale_x(double *x, double s) {
  for (int i = 0; i < 3 * NN; ++i) x[i] *= s;
}

typedef struct {
  double pen00, pen01; /* penalties of the two group pairs */
  double radius;
  int friction01;      /* (0, 1) with friction */
} scene_opts;

static const scene_opts base_opts = {PEN, PEN, RADIUS, 1};

static b2b_model *new_model(void) {
  b2b_model *m = NULL;
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_model_create(&m, msg, sizeof msg) == B2B_OK, "create: %s", msg);
  ck_assert_ptr_nonnull(m);
  return m;
}

static void add_beam_ok(b2b_model *m, int b, double radius) {
  char msg[B2B_ERRMSG_LEN] = "";
  int idx = SENT_INT;
  ck_assert_msg(b2b_model_add_beam(m, beam_nodes[b], 5, 0, radius, beam_kind[b], beam_group[b],
                                   &idx, msg, sizeof msg) == B2B_OK, "add_beam %d: %s", b, msg);
  ck_assert_int_eq(idx, b);
}

static void add_beams(b2b_model *m, int from, int to, double radius) {
  for (int b = from; b < to; ++b) add_beam_ok(m, b, radius);
}

static void set_pairs(b2b_model *m, const scene_opts *o) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p00 = tst_params(B2B_LAW_LINEAR, o->pen00, 0.0);
  b2b_params *p01 = o->friction01 ? tst_params_friction(B2B_LAW_LINEAR, o->pen01, 0.0, MU, EPS_T)
                                  : tst_params(B2B_LAW_LINEAR, o->pen01, 0.0);
  ck_assert_msg(b2b_model_set_group_pair(m, 0, 0, p00, msg, sizeof msg) == B2B_OK, "pair: %s",
                msg);
  ck_assert_msg(b2b_model_set_group_pair(m, 1, 0, p01, msg, sizeof msg) == B2B_OK, "pair: %s",
                msg);
  /* the model keeps copies */
  b2b_params_destroy(&p00);
  b2b_params_destroy(&p01);
}

static void finalize_ok(b2b_model *m) {
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_model_finalize(m, NN, msg, sizeof msg) == B2B_OK, "finalize: %s", msg);
}

/* The whole scene with options o, finalized. */
static b2b_model *scene_model_opts(const scene_opts *o) {
  b2b_model *m = new_model();
  add_beams(m, 0, NB, o->radius);
  set_pairs(m, o);
  finalize_ok(m);
  return m;
}

static b2b_model *scene_model(void) { return scene_model_opts(&base_opts); }

static void update_ok(b2b_model *m, const double *x, int want_tangent) {
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_model_update(m, x, 3, NN, want_tangent, msg, sizeof msg) == B2B_OK,
                "update: %s", msg);
}

static void update_step(b2b_model *m, int step) {
  double x[3 * NN];
  scene_x(x, step);
  update_ok(m, x, 1);
}

static void commit_ok(b2b_model *m) {
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_model_commit(m, msg, sizeof msg) == B2B_OK, "commit: %s", msg);
}

/* A finalized scene after update(step 0) and a commit, then update(step 1):
 * two active contacts, one with friction history, an uncommitted update. */
static b2b_model *stepped_model(void) {
  b2b_model *m = scene_model();
  update_step(m, 0);
  commit_ok(m);
  update_step(m, 1);
  return m;
}

/* ============================================================ snapshots */

typedef struct {
  int status;  /* of contact_count: B2B_OK or the error (no results) */
  int n;
  int nodes[MAXC][8], pair[MAXC][4];
  double info[MAXC][B2B_PAIR_INFO_LEN], residual[MAXC][B2B_PAIR_NDOF];
  double tangent[MAXC][B2B_PAIR_NDOF * B2B_PAIR_NDOF];
  int tangent_status[MAXC];
  int stats_status;
  int counts[B2B_MODEL_COUNTS_LEN];
  double totals[B2B_MODEL_TOTALS_LEN];
  int64_t save_size;
  unsigned char save[4096];
} snapshot;

/* Everything the model reports now. */
static void take(const b2b_model *m, snapshot *s) {
  memset(s, 0, sizeof *s);
  s->status = b2b_model_contact_count(m, &s->n, NULL, 0);
  if (s->status == B2B_OK) {
    ck_assert_msg(s->n <= MAXC, "%d contacts: more than the tests expect", s->n);
    for (int k = 0; k < s->n; ++k) {
      ck_assert_int_eq(b2b_model_get_contact(m, k, s->nodes[k], s->pair[k], s->info[k],
                                             s->residual[k], NULL, 24, NULL, 0), B2B_OK);
      s->tangent_status[k] =
          b2b_model_get_contact(m, k, NULL, NULL, NULL, NULL, s->tangent[k], 24, NULL, 0);
    }
  }
  s->stats_status = b2b_model_stats(m, s->counts, s->totals, NULL, 0);
  if (b2b_model_save_size(m, &s->save_size, NULL, 0) == B2B_OK) {
    ck_assert_msg(s->save_size > 0 && s->save_size <= (int64_t)sizeof s->save,
                  "save size %lld", (long long)s->save_size);
    ck_assert_int_eq(b2b_model_save(m, s->save, s->save_size, NULL, 0), B2B_OK);
  }
}

static void assert_same(const snapshot *a, const snapshot *b, const char *ctx) {
  ck_assert_msg(a->status == b->status, "%s: contact_count status %d, was %d", ctx, b->status,
                a->status);
  ck_assert_msg(a->n == b->n, "%s: %d contacts, was %d", ctx, b->n, a->n);
  for (int k = 0; k < a->n; ++k) {
    ck_assert_msg(memcmp(a->nodes[k], b->nodes[k], sizeof a->nodes[k]) == 0, "%s: contact %d: "
                  "nodes differ", ctx, k);
    ck_assert_msg(memcmp(a->pair[k], b->pair[k], sizeof a->pair[k]) == 0, "%s: contact %d: "
                  "pair differs", ctx, k);
    ck_assert_msg(memcmp(a->info[k], b->info[k], sizeof a->info[k]) == 0, "%s: contact %d: "
                  "info differs", ctx, k);
    ck_assert_msg(memcmp(a->residual[k], b->residual[k], sizeof a->residual[k]) == 0,
                  "%s: contact %d: residual differs", ctx, k);
    ck_assert_msg(a->tangent_status[k] == b->tangent_status[k], "%s: contact %d: tangent status",
                  ctx, k);
    ck_assert_msg(memcmp(a->tangent[k], b->tangent[k], sizeof a->tangent[k]) == 0,
                  "%s: contact %d: tangent differs", ctx, k);
  }
  ck_assert_msg(a->stats_status == b->stats_status, "%s: stats status", ctx);
  ck_assert_msg(memcmp(a->counts, b->counts, sizeof a->counts) == 0, "%s: stats counts differ",
                ctx);
  ck_assert_msg(memcmp(a->totals, b->totals, sizeof a->totals) == 0, "%s: stats totals differ",
                ctx);
  ck_assert_msg(a->save_size == b->save_size, "%s: save size %lld, was %lld", ctx,
                (long long)b->save_size, (long long)a->save_size);
  ck_assert_msg(memcmp(a->save, b->save, (size_t)a->save_size) == 0, "%s: restart bytes differ",
                ctx);
}

/* Every reported number is finite. */
static void assert_finite(const snapshot *s, const char *ctx) {
  for (int k = 0; k < s->n; ++k) {
    for (int i = 0; i < B2B_PAIR_INFO_LEN; ++i)
      ck_assert_msg(isfinite(s->info[k][i]), "%s: contact %d info[%d] = %g", ctx, k, i,
                    s->info[k][i]);
    for (int i = 0; i < B2B_PAIR_NDOF; ++i)
      ck_assert_msg(isfinite(s->residual[k][i]), "%s: contact %d residual[%d] = %g", ctx, k, i,
                    s->residual[k][i]);
    if (s->tangent_status[k] == B2B_OK)
      for (int i = 0; i < B2B_PAIR_NDOF * B2B_PAIR_NDOF; ++i)
        ck_assert_msg(isfinite(s->tangent[k][i]), "%s: contact %d tangent[%d] = %g", ctx, k, i,
                      s->tangent[k][i]);
  }
  for (int i = 0; i < B2B_MODEL_TOTALS_LEN; ++i)
    ck_assert_msg(isfinite(s->totals[i]), "%s: totals[%d] = %g", ctx, i, s->totals[i]);
}

/* The model reports exactly what it did before (snapshot `before`). */
static void assert_unchanged(const b2b_model *m, const snapshot *before, const char *ctx) {
  snapshot *now = malloc(sizeof *now);
  take(m, now);
  assert_same(before, now, ctx);
  free(now);
}

/* m and twin (which saw the same successful calls, but not the failed ones)
 * go on alike: updates at steps 2 and 3 with a commit between, a revert, and
 * again, compared bit for bit after each. Both must be finalized. */
static void assert_twins(b2b_model *m, b2b_model *twin, const char *ctx) {
  snapshot *a = malloc(sizeof *a), *b = malloc(sizeof *b);
  char c2[300];
  for (int step = 2; step <= 4; ++step) {
    update_step(m, step);
    update_step(twin, step);
    take(m, a);
    take(twin, b);
    snprintf(c2, sizeof c2, "%s (then: step %d)", ctx, step);
    assert_same(b, a, c2);
    ck_assert_msg(a->n == 2, "%s: %d contacts, expected 2", c2, a->n);
    if (step == 3) {
      ck_assert_int_eq(b2b_model_revert(m, NULL, 0), B2B_OK);
      ck_assert_int_eq(b2b_model_revert(twin, NULL, 0), B2B_OK);
    } else {
      commit_ok(m);
      commit_ok(twin);
    }
    take(m, a);
    take(twin, b);
    assert_same(b, a, c2);
  }
  free(a);
  free(b);
}

/* ============================================================ NULL handles */

START_TEST(test_null_model) {
  char ctx[256];
  double x[3 * NN], f[NEQ], K[NEQ * NEQ], AB[10 * NEQ], vals[4], totals[8];
  int eq[NEQ], n = SENT_INT, beam = SENT_INT, nnz = SENT_INT, rows[4], cols[4], counts[16];
  int64_t size = -5;
  unsigned char buf[64];
  const int nodes[5] = {0, 1, 2, 3, 4};
  scene_x(x, 0);
  for (int i = 0; i < NEQ; ++i) eq[i] = i;
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);

  CTX("create(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_create(NULL, MSG));
  /* destroy: NULL and a NULL handle are no-ops */
  ck_assert_int_eq(b2b_model_destroy(NULL), B2B_OK);
  b2b_model *none = NULL;
  ck_assert_int_eq(b2b_model_destroy(&none), B2B_OK);
  ck_assert_ptr_null(none);

  CTX("add_beam(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL,
              b2b_model_add_beam(NULL, nodes, 5, 0, RADIUS, NOD, 0, &beam, MSG));
  ck_assert_int_eq(beam, SENT_INT);
  CTX("set_group_pair(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_set_group_pair(NULL, 0, 0, p, MSG));
  CTX("set_self_contact(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL,
              b2b_model_set_self_contact(NULL, 0, 1, -1.0, MSG));
  CTX("set_real(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL,
              b2b_model_set_real(NULL, "search_margin", 0.1, MSG));
  CTX("set_int(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_set_int(NULL, "threads", 1, MSG));
  CTX("finalize(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_finalize(NULL, NN, MSG));
  CTX("update(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_update(NULL, x, 3, NN, 1, MSG));
  CTX("contact_count(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_contact_count(NULL, &n, MSG));
  ck_assert_int_eq(n, SENT_INT);
  CTX("get_contact(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL,
              b2b_model_get_contact(NULL, 0, NULL, NULL, NULL, NULL, NULL, 24, MSG));
  for (int i = 0; i < NEQ; ++i) f[i] = SENT;
  CTX("add_residual(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL,
              b2b_model_add_residual(NULL, eq, 3, 0, NEQ, f, MSG));
  for (int i = 0; i < NEQ; ++i) ck_assert(f[i] == SENT);
  CTX("add_tangent_dense(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL,
              b2b_model_add_tangent_dense(NULL, eq, 3, 0, NEQ, K, NEQ, MSG));
  CTX("add_tangent_banded(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL,
              b2b_model_add_tangent_banded(NULL, eq, 3, 0, NEQ, 3, 3, AB, 10, MSG));
  CTX("tangent_coo(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL,
              b2b_model_tangent_coo(NULL, eq, 3, 0, NEQ, &nnz, rows, cols, vals, 4, MSG));
  ck_assert_int_eq(nnz, SENT_INT);
  CTX("commit(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_commit(NULL, MSG));
  CTX("revert(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_revert(NULL, MSG));
  CTX("save_size(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_save_size(NULL, &size, MSG));
  ck_assert(size == -5);
  memset(buf, 0xA5, sizeof buf);
  CTX("save(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_save(NULL, buf, sizeof buf, MSG));
  for (size_t i = 0; i < sizeof buf; ++i) ck_assert(buf[i] == 0xA5);
  CTX("restore(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_restore(NULL, buf, sizeof buf, MSG));
  for (int i = 0; i < 16; ++i) counts[i] = SENT_INT;
  for (int i = 0; i < 8; ++i) totals[i] = SENT;
  CTX("stats(NULL)");
  EXPECT_FAIL(B2B_ERR_NULL, "model", "NULL", NULL, b2b_model_stats(NULL, counts, totals, MSG));
  for (int i = 0; i < 16; ++i) ck_assert(counts[i] == SENT_INT);
  for (int i = 0; i < 8; ++i) ck_assert(totals[i] == SENT);
  b2b_params_destroy(&p);
}
END_TEST

/* NULL arguments other than the handle. Loop index 0: set-up calls (then the
 * model must build like its twin), 1: calls on an updated model. */
START_TEST(test_null_arguments) {
  char ctx[256];
  b2b_model *m = new_model(), *twin = new_model();
  int beam = SENT_INT;
  if (_i == 0) {
    CTX("add_beam nodes NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "nodes", "NULL", NULL,
                b2b_model_add_beam(m, NULL, 5, 0, RADIUS, NOD, 0, &beam, MSG));
    ck_assert_int_eq(beam, SENT_INT);
    CTX("add_beam beam NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "beam", "NULL", NULL,
                b2b_model_add_beam(m, beam_nodes[0], 5, 0, RADIUS, NOD, 0, NULL, MSG));
    CTX("set_group_pair params NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "params", "NULL", NULL,
                b2b_model_set_group_pair(m, 0, 0, NULL, MSG));
    CTX("set_real key NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "key", "NULL", NULL, b2b_model_set_real(m, NULL, 0.1, MSG));
    CTX("set_int key NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "key", "NULL", NULL, b2b_model_set_int(m, NULL, 1, MSG));
    /* nothing was added: beam 0 is still the first, no group pair was set */
    CTX("finalize after the failures");
    add_beams(m, 0, NB, RADIUS);
    EXPECT_FAIL(B2B_ERR_STATE, "group", NULL, NULL, b2b_model_finalize(m, NN, MSG));
    set_pairs(m, &base_opts);
    finalize_ok(m);
    b2b_model_destroy(&twin);
    twin = scene_model();
    update_step(m, 1);
    update_step(twin, 1);
    assert_twins(m, twin, "null set-up arguments");
  } else {
    b2b_model_destroy(&m);
    b2b_model_destroy(&twin);
    m = stepped_model();
    twin = stepped_model();
    snapshot *before = malloc(sizeof *before);
    take(m, before);
    int n = SENT_INT, nnz = SENT_INT;
    int eq[NEQ];
    for (int i = 0; i < NEQ; ++i) eq[i] = i;
    int64_t size = -5;
    unsigned char buf[8];
    CTX("update x NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "x", "NULL", NULL, b2b_model_update(m, NULL, 3, NN, 1, MSG));
    CTX("contact_count n NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "n", "NULL", NULL, b2b_model_contact_count(m, NULL, MSG));
    CTX("add_residual eq NULL");
    double f[NEQ];
    for (int i = 0; i < NEQ; ++i) f[i] = SENT;
    EXPECT_FAIL(B2B_ERR_NULL, "eq", "NULL", NULL,
                b2b_model_add_residual(m, NULL, 3, 0, NEQ, f, MSG));
    for (int i = 0; i < NEQ; ++i) ck_assert(f[i] == SENT);
    CTX("add_residual f NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "f", "NULL", NULL,
                b2b_model_add_residual(m, eq, 3, 0, NEQ, NULL, MSG));
    CTX("add_tangent_dense K NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "K", "NULL", NULL,
                b2b_model_add_tangent_dense(m, eq, 3, 0, NEQ, NULL, NEQ, MSG));
    CTX("add_tangent_dense eq NULL");
    double *K = malloc(sizeof(double) * NEQ * NEQ);
    for (int i = 0; i < NEQ * NEQ; ++i) K[i] = SENT;
    EXPECT_FAIL(B2B_ERR_NULL, "eq", "NULL", NULL,
                b2b_model_add_tangent_dense(m, NULL, 3, 0, NEQ, K, NEQ, MSG));
    for (int i = 0; i < NEQ * NEQ; ++i) ck_assert(K[i] == SENT);
    free(K);
    CTX("add_tangent_banded AB NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "AB", "NULL", NULL,
                b2b_model_add_tangent_banded(m, eq, 3, 0, NEQ, 47, 47, NULL, 142, MSG));
    CTX("tangent_coo nnz NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "nnz", "NULL", NULL,
                b2b_model_tangent_coo(m, eq, 3, 0, NEQ, NULL, NULL, NULL, NULL, 0, MSG));
    CTX("tangent_coo eq NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "eq", "NULL", NULL,
                b2b_model_tangent_coo(m, NULL, 3, 0, NEQ, &nnz, NULL, NULL, NULL, 0, MSG));
    ck_assert_int_eq(nnz, SENT_INT);
    CTX("save_size size NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "size", "NULL", NULL, b2b_model_save_size(m, NULL, MSG));
    CTX("save buffer NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "buffer", "NULL", NULL, b2b_model_save(m, NULL, 4096, MSG));
    CTX("restore buffer NULL");
    EXPECT_FAIL(B2B_ERR_NULL, "buffer", "NULL", NULL, b2b_model_restore(m, NULL, 4096, MSG));
    (void)size;
    (void)buf;
    (void)n;
    /* NULL outputs where the contract allows them: not errors */
    EXPECT_OK(b2b_model_stats(m, NULL, NULL, MSG));
    EXPECT_OK(b2b_model_get_contact(m, 0, NULL, NULL, NULL, NULL, NULL, 0, MSG));
    assert_unchanged(m, before, ctx);
    assert_twins(m, twin, "null arguments");
    free(before);
  }
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* ============================================================ add_beam */

/* One bad add_beam (loop index: the case) on a model that already has beam 0;
 * beam untouched; then the scene builds like its twin. */
START_TEST(test_add_beam_bad) {
  char ctx[256];
  b2b_model *m = new_model();
  add_beams(m, 0, 1, RADIUS);
  int beam = SENT_INT;
  int nodes[5];
  memcpy(nodes, beam_nodes[1], sizeof nodes);
  switch (_i) {
    case 0:
      nodes[2] = -1;
      CTX("negative node");
      EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "node -1", "position 2",
                  b2b_model_add_beam(m, nodes, 5, 0, RADIUS, NDW, 0, &beam, MSG));
      break;
    case 1:
      nodes[3] = nodes[1];
      CTX("node repeated");
      EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "node 6", "twice",
                  b2b_model_add_beam(m, nodes, 5, 0, RADIUS, NDW, 0, &beam, MSG));
      break;
    case 2:
      nodes[4] = nodes[0];
      CTX("ring with its first node repeated");
      EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "node 5", "twice",
                  b2b_model_add_beam(m, nodes, 5, 1, RADIUS, NDW, 0, &beam, MSG));
      break;
    case 3:
      CTX("open beam of 1 node");
      EXPECT_FAIL(B2B_ERR_SIZE, "beam 1", "1 node", "an open beam needs at least 2",
                  b2b_model_add_beam(m, nodes, 1, 0, RADIUS, NDW, 0, &beam, MSG));
      break;
    case 4:
      CTX("closed beam of 2 nodes");
      EXPECT_FAIL(B2B_ERR_SIZE, "beam 1", "a closed beam", "at least 3",
                  b2b_model_add_beam(m, nodes, 2, 1, RADIUS, NDW, 0, &beam, MSG));
      break;
    case 5:
      CTX("beam of 0 nodes");
      EXPECT_FAIL(B2B_ERR_SIZE, "beam 1", "0 nodes", NULL,
                  b2b_model_add_beam(m, nodes, 0, 0, RADIUS, NDW, 0, &beam, MSG));
      break;
    case 6:
      CTX("beam of -3 nodes");
      EXPECT_FAIL(B2B_ERR_SIZE, "beam 1", "-3", NULL,
                  b2b_model_add_beam(m, nodes, -3, 0, RADIUS, NDW, 0, &beam, MSG));
      break;
    case 7:
      CTX("closed = 2");
      EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "closed", "2",
                  b2b_model_add_beam(m, nodes, 5, 2, RADIUS, NDW, 0, &beam, MSG));
      break;
    case 8:
      CTX("closed = -1");
      EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "closed", "-1",
                  b2b_model_add_beam(m, nodes, 5, -1, RADIUS, NDW, 0, &beam, MSG));
      break;
    case 9:
      CTX("radius 0");
      EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "radius", NULL,
                  b2b_model_add_beam(m, nodes, 5, 0, 0.0, NDW, 0, &beam, MSG));
      break;
    case 10:
      CTX("radius -0.1");
      EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "radius", NULL,
                  b2b_model_add_beam(m, nodes, 5, 0, -0.1, NDW, 0, &beam, MSG));
      break;
    case 11:
      CTX("radius beyond B2B_COORD_MAX");
      EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "radius", "B2B_COORD_MAX",
                  b2b_model_add_beam(m, nodes, 5, 0, 2 * B2B_COORD_MAX, NDW, 0, &beam, MSG));
      break;
    case 12:
      CTX("radius NaN");
      EXPECT_FAIL(B2B_ERR_NONFINITE, "beam 1", "radius", NULL,
                  b2b_model_add_beam(m, nodes, 5, 0, NAN, NDW, 0, &beam, MSG));
      break;
    case 13:
      CTX("radius Inf");
      EXPECT_FAIL(B2B_ERR_NONFINITE, "beam 1", "radius", NULL,
                  b2b_model_add_beam(m, nodes, 5, 0, INFINITY, NDW, 0, &beam, MSG));
      break;
    case 14:
      CTX("radius -Inf");
      EXPECT_FAIL(B2B_ERR_NONFINITE, "beam 1", "radius", NULL,
                  b2b_model_add_beam(m, nodes, 5, 0, -INFINITY, NDW, 0, &beam, MSG));
      break;
    case 15: { /* the first value past the last kind */
      char kind_word[32];
      snprintf(kind_word, sizeof kind_word, "kind %d", B2B_CURVE_KIND_COUNT);
      CTX("%s", kind_word);
      EXPECT_FAIL(B2B_ERR_UNKNOWN_KIND, "beam 1", kind_word, NULL,
                  b2b_model_add_beam(m, nodes, 5, 0, RADIUS, B2B_CURVE_KIND_COUNT, 0, &beam, MSG));
      break;
    }
    case 16:
      CTX("kind -1");
      EXPECT_FAIL(B2B_ERR_UNKNOWN_KIND, "beam 1", "kind -1", NULL,
                  b2b_model_add_beam(m, nodes, 5, 0, RADIUS, -1, 0, &beam, MSG));
      break;
    case 17:
      CTX("group -1");
      EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "group -1", NULL,
                  b2b_model_add_beam(m, nodes, 5, 0, RADIUS, NDW, -1, &beam, MSG));
      break;
    default:
      ck_abort_msg("no case %d", _i);
  }
  ck_assert_msg(beam == SENT_INT, "%s: beam written (%d) on failure", ctx, beam);
  /* nothing was added: the next beam is beam 1, and the model is the scene */
  add_beams(m, 1, NB, RADIUS);
  set_pairs(m, &base_opts);
  finalize_ok(m);
  b2b_model *twin = scene_model();
  update_step(m, 1);
  update_step(twin, 1);
  assert_twins(m, twin, ctx);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST
#define N_ADD_BEAM_CASES 18

/* The closest valid inputs: a tiny radius, a 2-node open beam, a 3-node ring,
 * a large group number. */
START_TEST(test_add_beam_valid_limits) {
  char ctx[256];
  b2b_model *m = new_model();
  int beam = SENT_INT;
  const int ring[3] = {20, 21, 22}, two[2] = {30, 31};
  CTX("2-node open beam, radius 1e-300");
  EXPECT_OK(b2b_model_add_beam(m, two, 2, 0, 1e-300, NOD, INT_MAX, &beam, MSG));
  ck_assert_int_eq(beam, 0);
  CTX("3-node ring, radius B2B_COORD_MAX");
  EXPECT_OK(b2b_model_add_beam(m, ring, 3, 1, B2B_COORD_MAX, NDW, 0, &beam, MSG));
  ck_assert_int_eq(beam, 1);
  b2b_model_destroy(&m);
}
END_TEST

/* ============================================================ group pairs */

START_TEST(test_group_pair_bad) {
  char ctx[256];
  b2b_model *m = new_model();
  add_beams(m, 0, NB, RADIUS);
  b2b_params *ok = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  b2b_params *raw = NULL;
  ck_assert_int_eq(b2b_params_create(&raw, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(raw, "penalty", PEN, NULL, 0), B2B_OK);
  CTX("unfinalized params");
  EXPECT_FAIL(B2B_ERR_STATE, "params", "finalize", NULL,
              b2b_model_set_group_pair(m, 0, 0, raw, MSG));
  CTX("group -1 (first)");
  EXPECT_FAIL(B2B_ERR_RANGE, "-1", "group", NULL, b2b_model_set_group_pair(m, -1, 0, ok, MSG));
  CTX("group -2 (second)");
  EXPECT_FAIL(B2B_ERR_RANGE, "-2", "group", NULL, b2b_model_set_group_pair(m, 0, -2, ok, MSG));
  CTX("group INT_MIN");
  EXPECT_FAIL(B2B_ERR_RANGE, "group", NULL, NULL,
              b2b_model_set_group_pair(m, INT_MIN, 1, ok, MSG));
  /* none of them set a pair */
  CTX("finalize without a group pair");
  EXPECT_FAIL(B2B_ERR_STATE, "pair of groups", "b2b_model_set_group_pair", NULL,
              b2b_model_finalize(m, NN, MSG));
  set_pairs(m, &base_opts);
  finalize_ok(m);
  b2b_model *twin = scene_model();
  update_step(m, 1);
  update_step(twin, 1);
  assert_twins(m, twin, "group pairs");
  b2b_params_destroy(&ok);
  b2b_params_destroy(&raw);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* Replacing a pair's parameters after finalize. Loop index 0: before the
 * first update; 1: after a commit; 2: after a revert. */
START_TEST(test_group_pair_replace) {
  char ctx[256];
  b2b_model *m = scene_model(), *twin = scene_model();
  if (_i >= 1) {
    update_step(m, 0);
    update_step(twin, 0);
    commit_ok(m);
    commit_ok(twin);
  }
  if (_i == 2) {
    update_step(m, 1);
    update_step(twin, 1);
    ck_assert_int_eq(b2b_model_revert(m, NULL, 0), B2B_OK);
    ck_assert_int_eq(b2b_model_revert(twin, NULL, 0), B2B_OK);
  }
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  b2b_params *plain = tst_params(B2B_LAW_LINEAR, 2 * PEN, 0.0);
  b2b_params *fric = tst_params_friction(B2B_LAW_LINEAR, 2 * PEN, 0.0, MU, EPS_T);
  b2b_params *raw = NULL;
  ck_assert_int_eq(b2b_params_create(&raw, NULL, 0), B2B_OK);
  CTX("friction off replaces friction on (groups 0, 1)");
  EXPECT_FAIL(B2B_ERR_SIZE, "(0, 1)", "friction", NULL,
              b2b_model_set_group_pair(m, 0, 1, plain, MSG));
  CTX("friction on replaces friction off (groups 0, 0)");
  EXPECT_FAIL(B2B_ERR_SIZE, "(0, 0)", "friction", NULL,
              b2b_model_set_group_pair(m, 0, 0, fric, MSG));
  CTX("a pair never set (1, 1)");
  EXPECT_FAIL(B2B_ERR_STATE, "(1, 1)", "finalized", NULL,
              b2b_model_set_group_pair(m, 1, 1, plain, MSG));
  CTX("a pair never set (0, 7)");
  EXPECT_FAIL(B2B_ERR_STATE, "(0, 7)", NULL, NULL, b2b_model_set_group_pair(m, 0, 7, plain, MSG));
  CTX("unfinalized replacement");
  EXPECT_FAIL(B2B_ERR_STATE, "params", "finalize", NULL,
              b2b_model_set_group_pair(m, 0, 0, raw, MSG));
  CTX("NULL replacement");
  EXPECT_FAIL(B2B_ERR_NULL, "params", NULL, NULL, b2b_model_set_group_pair(m, 0, 0, NULL, MSG));
  assert_unchanged(m, before, ctx);
  assert_twins(m, twin, ctx);

  /* While an update is uncommitted: STATE, even for a valid replacement. */
  update_step(m, 5);
  update_step(twin, 5);
  take(m, before);
  CTX("replacement while an update is uncommitted");
  EXPECT_FAIL(B2B_ERR_STATE, "(0, 0)", "commit", NULL,
              b2b_model_set_group_pair(m, 0, 0, plain, MSG));
  CTX("replacement (1, 0) while an update is uncommitted");
  EXPECT_FAIL(B2B_ERR_STATE, "(1, 0)", NULL, NULL, b2b_model_set_group_pair(m, 1, 0, fric, MSG));
  assert_unchanged(m, before, ctx);
  assert_twins(m, twin, "after the uncommitted replacement");

  /* The valid case (same history length, between steps) is accepted, by
   * both orders of the groups, and changes the force. */
  CTX("valid replacement");
  EXPECT_OK(b2b_model_set_group_pair(m, 0, 0, plain, MSG));
  EXPECT_OK(b2b_model_set_group_pair(m, 1, 0, fric, MSG));
  update_step(m, 4);
  update_step(twin, 4);
  snapshot *a = malloc(sizeof *a);
  take(m, a);
  take(twin, before);
  ck_assert_int_eq(a->n, before->n);
  ck_assert_msg(a->totals[B2B_TOTAL_NORMAL_FORCE] > 1.5 * before->totals[B2B_TOTAL_NORMAL_FORCE],
                "doubled penalty: normal force %g, was %g", a->totals[B2B_TOTAL_NORMAL_FORCE],
                before->totals[B2B_TOTAL_NORMAL_FORCE]);
  free(a);
  free(before);
  b2b_params_destroy(&plain);
  b2b_params_destroy(&fric);
  b2b_params_destroy(&raw);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* ============================================================ self-contact */

START_TEST(test_self_contact_bad) {
  char ctx[256];
  b2b_model *m = new_model();
  add_beams(m, 0, NB, RADIUS);
  set_pairs(m, &base_opts);
  CTX("beam -1");
  EXPECT_FAIL(B2B_ERR_RANGE, "beam -1", "does not exist", NULL,
              b2b_model_set_self_contact(m, -1, 1, -1.0, MSG));
  CTX("beam 3 of 3");
  EXPECT_FAIL(B2B_ERR_RANGE, "beam 3", "does not exist", "0 .. 2",
              b2b_model_set_self_contact(m, 3, 1, -1.0, MSG));
  CTX("on = 2");
  EXPECT_FAIL(B2B_ERR_RANGE, "on", "2", NULL, b2b_model_set_self_contact(m, 0, 2, -1.0, MSG));
  CTX("exclusion NaN");
  EXPECT_FAIL(B2B_ERR_NONFINITE, "exclusion_length", NULL, NULL,
              b2b_model_set_self_contact(m, 0, 1, NAN, MSG));
  CTX("exclusion Inf");
  EXPECT_FAIL(B2B_ERR_NONFINITE, "exclusion_length", NULL, NULL,
              b2b_model_set_self_contact(m, 0, 1, INFINITY, MSG));
  /* self-contact of beam 2 (group 1), whose group is not paired with itself */
  CTX("self-contact without the (1, 1) pair");
  EXPECT_OK(b2b_model_set_self_contact(m, 2, 1, -1.0, MSG));
  EXPECT_FAIL(B2B_ERR_STATE, "beam 2", "group 1", "(1, 1",
              b2b_model_finalize(m, NN, MSG));
  /* switched off again, the model finalizes and is the scene */
  EXPECT_OK(b2b_model_set_self_contact(m, 2, 0, -1.0, MSG));
  finalize_ok(m);
  CTX("set_self_contact after finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL,
              b2b_model_set_self_contact(m, 0, 1, -1.0, MSG));
  b2b_model *twin = scene_model();
  update_step(m, 1);
  update_step(twin, 1);
  assert_twins(m, twin, "self-contact");
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* ============================================================ finalize */

START_TEST(test_finalize_bad) {
  char ctx[256];
  b2b_model *m = new_model();
  int beam = SENT_INT;
  set_pairs(m, &base_opts);
  CTX("finalize without beams");
  EXPECT_FAIL(B2B_ERR_STATE, "no beams", NULL, NULL, b2b_model_finalize(m, NN, MSG));
  add_beams(m, 0, NB, RADIUS);
  CTX("n_nodes 0");
  EXPECT_FAIL(B2B_ERR_RANGE, "n_nodes", "0", NULL, b2b_model_finalize(m, 0, MSG));
  CTX("n_nodes -4");
  EXPECT_FAIL(B2B_ERR_RANGE, "n_nodes", "-4", NULL, b2b_model_finalize(m, -4, MSG));
  CTX("node 15 of beam 2 >= n_nodes 15");
  EXPECT_FAIL(B2B_ERR_RANGE, "beam 2", "node 15", "0 .. 14", b2b_model_finalize(m, NN - 1, MSG));
  CTX("node 9 of beam 1 >= n_nodes 9");
  EXPECT_FAIL(B2B_ERR_RANGE, "beam 1", "node 9", "0 .. 8", b2b_model_finalize(m, 9, MSG));
  CTX("node 4 of beam 0 >= n_nodes 4");
  EXPECT_FAIL(B2B_ERR_RANGE, "beam 0", "node 4", "position 4", b2b_model_finalize(m, 4, MSG));
  /* an update or option query before finalize */
  double x[3 * NN];
  scene_x(x, 0);
  CTX("update before finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL, b2b_model_update(m, x, 3, NN, 1, MSG));
  finalize_ok(m);
  CTX("finalize twice");
  EXPECT_FAIL(B2B_ERR_STATE, "finalized", NULL, NULL, b2b_model_finalize(m, NN, MSG));
  CTX("add_beam after finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalized", NULL, NULL,
              b2b_model_add_beam(m, beam_nodes[0], 5, 0, RADIUS, NOD, 0, &beam, MSG));
  ck_assert_int_eq(beam, SENT_INT);
  b2b_model *twin = scene_model();
  update_step(m, 1);
  update_step(twin, 1);
  assert_twins(m, twin, "finalize");
  /* again on an updated model */
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  CTX("finalize twice (updated)");
  EXPECT_FAIL(B2B_ERR_STATE, "finalized", NULL, NULL, b2b_model_finalize(m, NN, MSG));
  CTX("add_beam after finalize (updated)");
  EXPECT_FAIL(B2B_ERR_STATE, "finalized", NULL, NULL,
              b2b_model_add_beam(m, beam_nodes[0], 5, 0, RADIUS, NOD, 0, &beam, MSG));
  assert_unchanged(m, before, ctx);
  free(before);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* A model with beams but no pair for their groups: the only pair is (5, 5). */
START_TEST(test_finalize_no_pair_of_beams) {
  char ctx[256];
  b2b_model *m = new_model();
  add_beams(m, 0, NB, RADIUS);
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  ck_assert_int_eq(b2b_model_set_group_pair(m, 5, 5, p, NULL, 0), B2B_OK);
  /* allowed: pairs that can never touch are never searched */
  CTX("finalize with an unused pair");
  EXPECT_OK(b2b_model_finalize(m, NN, MSG));
  double x[3 * NN];
  scene_x(x, 0);
  update_ok(m, x, 1);
  int n = SENT_INT;
  ck_assert_int_eq(b2b_model_contact_count(m, &n, NULL, 0), B2B_OK);
  ck_assert_int_eq(n, 0);
  b2b_params_destroy(&p);
  b2b_model_destroy(&m);
}
END_TEST

/* ============================================================ options */

START_TEST(test_options_bad) {
  char ctx[256];
  b2b_model *m = scene_model(), *twin = scene_model();
  if (_i == 1) {
    update_step(m, 1);
    update_step(twin, 1);
  }
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  const char *const bad[] = {"bogus", "", "Search_margin", "search_margin ", "thread",
                             "max_handover_hop", "THREADS"};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    char quoted[64];
    snprintf(quoted, sizeof quoted, "\"%s\"", bad[k]);
    CTX("set_real(\"%s\")", bad[k]);
    EXPECT_FAIL(B2B_ERR_UNKNOWN_KEY, quoted, "\"search_margin\"", NULL,
                b2b_model_set_real(m, bad[k], 0.1, MSG));
    /* the key is checked before the value */
    ck_assert_int_eq(b2b_model_set_real(m, bad[k], NAN, NULL, 0), B2B_ERR_UNKNOWN_KEY);
    CTX("set_int(\"%s\")", bad[k]);
    EXPECT_FAIL(B2B_ERR_UNKNOWN_KEY, quoted, "\"threads\"", "\"max_handover_hops\"",
                b2b_model_set_int(m, bad[k], 1, MSG));
  }
  CTX("set_int(\"search_margin\")");
  EXPECT_FAIL(B2B_ERR_UNKNOWN_KEY, "\"search_margin\"", "integer", NULL,
              b2b_model_set_int(m, "search_margin", 1, MSG));
  CTX("set_real(\"threads\")");
  EXPECT_FAIL(B2B_ERR_UNKNOWN_KEY, "\"threads\"", "real", NULL,
              b2b_model_set_real(m, "threads", 1.0, MSG));
  const double bad_margin[] = {0.0, -0.1, -INFINITY, 2 * B2B_COORD_MAX};
  const int bad_margin_st[] = {B2B_ERR_RANGE, B2B_ERR_RANGE, B2B_ERR_NONFINITE, B2B_ERR_RANGE};
  for (int k = 0; k < 4; ++k) {
    CTX("search_margin %g", bad_margin[k]);
    EXPECT_FAIL(bad_margin_st[k], "search_margin", bad_margin_st[k] == B2B_ERR_RANGE ? "> 0" : NULL,
                bad_margin[k] > 1.0 ? "B2B_COORD_MAX" : NULL,
                b2b_model_set_real(m, "search_margin", bad_margin[k], MSG));
  }
  CTX("search_margin NaN");
  EXPECT_FAIL(B2B_ERR_NONFINITE, "search_margin", "finite", NULL,
              b2b_model_set_real(m, "search_margin", NAN, MSG));
  CTX("search_margin Inf");
  EXPECT_FAIL(B2B_ERR_NONFINITE, "search_margin", "finite", NULL,
              b2b_model_set_real(m, "search_margin", INFINITY, MSG));
  CTX("threads -1");
  EXPECT_FAIL(B2B_ERR_RANGE, "threads", "-1", NULL, b2b_model_set_int(m, "threads", -1, MSG));
  CTX("threads INT_MIN");
  EXPECT_FAIL(B2B_ERR_RANGE, "threads", NULL, NULL, b2b_model_set_int(m, "threads", INT_MIN, MSG));
  CTX("max_handover_hops 0");
  EXPECT_FAIL(B2B_ERR_RANGE, "max_handover_hops", "1 .. 1000", NULL,
              b2b_model_set_int(m, "max_handover_hops", 0, MSG));
  CTX("max_handover_hops 1001");
  EXPECT_FAIL(B2B_ERR_RANGE, "max_handover_hops", "1001", NULL,
              b2b_model_set_int(m, "max_handover_hops", 1001, MSG));
  assert_unchanged(m, before, ctx);
  if (_i == 0) {
    update_step(m, 1);
    update_step(twin, 1);
  }
  assert_twins(m, twin, "options");
  /* the valid bounds */
  CTX("valid options");
  EXPECT_OK(b2b_model_set_int(m, "max_handover_hops", 1000, MSG));
  EXPECT_OK(b2b_model_set_int(m, "max_handover_hops", 1, MSG));
  EXPECT_OK(b2b_model_set_int(m, "threads", 0, MSG));
  EXPECT_OK(b2b_model_set_real(m, "search_margin", B2B_COORD_MAX, MSG));
  EXPECT_OK(b2b_model_set_real(m, "search_margin", 1e-300, MSG));
  free(before);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* A key of 300 characters: the message still fits B2B_ERRMSG_LEN whole (it
 * ends with the list of keys). */
START_TEST(test_options_long_key) {
  char ctx[256];
  char key[301];
  memset(key, 'k', 300);
  key[300] = '\0';
  memcpy(key, "search_margin", 13);
  b2b_model *m = new_model();
  CTX("set_real(300-character key)");
  EXPECT_FAIL(B2B_ERR_UNKNOWN_KEY, "\"search_margin", "(real keys: \"search_margin\")", NULL,
              b2b_model_set_real(m, key, 1.0, MSG));
  ck_assert_msg(strlen(g_msg) < B2B_ERRMSG_LEN - 1, "%s: message of %zu characters (truncated?)",
                ctx, strlen(g_msg));
  CTX("set_int(300-character key)");
  EXPECT_FAIL(B2B_ERR_UNKNOWN_KEY, "\"search_margin", "\"max_handover_hops\"", NULL,
              b2b_model_set_int(m, key, 1, MSG));
  ck_assert_msg(strlen(g_msg) < B2B_ERRMSG_LEN - 1, "%s: message of %zu characters (truncated?)",
                ctx, strlen(g_msg));
  ck_assert_msg(g_msg[strlen(g_msg) - 1] == ')', "%s: message \"%s\" is cut short", ctx, g_msg);
  b2b_model_destroy(&m);
}
END_TEST

/* ============================================================ update */

/* Bad arguments of update on a model with results: the previous contacts stay
 * readable and identical, and the model goes on like its twin. */
START_TEST(test_update_bad_arguments) {
  char ctx[256];
  b2b_model *m = stepped_model(), *twin = stepped_model();
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  double x[4 * NN];
  scene_x(x, 1);
  CTX("ldx 2");
  EXPECT_FAIL(B2B_ERR_SIZE, "ldx", "2", NULL, b2b_model_update(m, x, 2, NN, 1, MSG));
  CTX("ldx 0");
  EXPECT_FAIL(B2B_ERR_SIZE, "ldx", "0", NULL, b2b_model_update(m, x, 0, NN, 1, MSG));
  CTX("ldx -3");
  EXPECT_FAIL(B2B_ERR_SIZE, "ldx", "-3", NULL, b2b_model_update(m, x, -3, NN, 1, MSG));
  CTX("n_cols 15 < n_nodes 16");
  EXPECT_FAIL(B2B_ERR_SIZE, "15", "16", "columns", b2b_model_update(m, x, 3, NN - 1, 1, MSG));
  CTX("n_cols 0");
  EXPECT_FAIL(B2B_ERR_SIZE, "columns", NULL, NULL, b2b_model_update(m, x, 3, 0, 1, MSG));
  CTX("want_tangent 2");
  EXPECT_FAIL(B2B_ERR_RANGE, "want_tangent", "2", NULL, b2b_model_update(m, x, 3, NN, 2, MSG));
  CTX("want_tangent -1");
  EXPECT_FAIL(B2B_ERR_RANGE, "want_tangent", "-1", NULL, b2b_model_update(m, x, 3, NN, -1, MSG));
  assert_unchanged(m, before, ctx);
  /* the same update as before gives the same contacts */
  update_ok(m, x, 1);
  assert_unchanged(m, before, "the same update again");
  assert_twins(m, twin, "update arguments");
  free(before);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* The closest valid layouts: ldx 4 with NaN padding, more columns than nodes;
 * identical results. */
START_TEST(test_update_valid_layouts) {
  char ctx[256];
  b2b_model *m = stepped_model();
  snapshot *ref = malloc(sizeof *ref);
  take(m, ref);
  double x3[3 * NN], x4[4 * (NN + 2)];
  scene_x(x3, 1);
  for (int i = 0; i < 4 * (NN + 2); ++i) x4[i] = NAN;
  for (int k = 0; k < NN; ++k)
    for (int i = 0; i < 3; ++i) x4[4 * k + i] = x3[3 * k + i];
  CTX("ldx 4, NaN padding, 18 columns");
  EXPECT_OK(b2b_model_update(m, x4, 4, NN + 2, 1, MSG));
  assert_unchanged(m, ref, ctx);
  free(ref);
  b2b_model_destroy(&m);
}
END_TEST

/* A bad coordinate of a used node. Loop index: node (of the contacts or not)
 * x axis x kind of value. */
static const int bad_nodes[3] = {2, 7, 15};
static const double bad_values[4] = {NAN, INFINITY, -INFINITY, -2.0 * B2B_COORD_MAX};
START_TEST(test_update_bad_coordinate) {
  const int node = bad_nodes[_i / 12], axis = (_i / 4) % 3, kind = _i % 4;
  const double v = bad_values[kind];
  const int want = kind == 3 ? B2B_ERR_RANGE : B2B_ERR_NONFINITE;
  char ctx[256], wnode[32], waxis[16];
  b2b_model *m = stepped_model(), *twin = stepped_model();
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  double x[3 * NN];
  scene_x(x, 1);
  x[3 * node + axis] = v;
  snprintf(wnode, sizeof wnode, "node %d ", node);
  snprintf(waxis, sizeof waxis, " %c coordinate", "xyz"[axis]);
  CTX("node %d, axis %d = %g", node, axis, v);
  EXPECT_FAIL(want, wnode, waxis, kind == 3 ? "B2B_COORD_MAX" : "finite",
              b2b_model_update(m, x, 3, NN, 1, MSG));
  assert_unchanged(m, before, ctx);
  scene_x(x, 1);
  update_ok(m, x, 1);
  assert_unchanged(m, before, "the same update again");
  assert_twins(m, twin, ctx);
  free(before);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* The same values in the column of node 10, which no beam uses: accepted,
 * bit for bit the results without them. */
START_TEST(test_update_unused_node) {
  const double values[4] = {NAN, INFINITY, -INFINITY, 1e300};
  char ctx[256];
  b2b_model *m = stepped_model();
  snapshot *ref = malloc(sizeof *ref);
  take(m, ref);
  double x[3 * NN];
  scene_x(x, 1);
  for (int axis = 0; axis < 3; ++axis) x[3 * UNUSED + axis] = values[_i];
  CTX("unused node 10 = %g", values[_i]);
  EXPECT_OK(b2b_model_update(m, x, 3, NN, 1, MSG));
  assert_unchanged(m, ref, ctx);
  free(ref);
  b2b_model_destroy(&m);
}
END_TEST

/* A segment with coincident nodes (0) or folding back (1): the status names
 * beam and segment; the model keeps its results. */
START_TEST(test_update_degenerate_segment) {
  char ctx[256];
  b2b_model *m = stepped_model(), *twin = stepped_model();
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  double x[3 * NN];
  scene_x(x, 1);
  if (_i == 0) {
    /* beam 0's node 2 on node 1: element 1 - 2 has no length */
    memcpy(x + 3 * 2, x + 3 * 1, 3 * sizeof(double));
    CTX("coincident nodes 1 and 2 of beam 0");
    /* the first segment whose patch holds element 1 - 2 is segment 0 */
    EXPECT_FAIL(B2B_ERR_COINCIDENT, "beam 0", "segment 0", "nodes 1 and 2",
                b2b_model_update(m, x, 3, NN, 1, MSG));
  } else {
    /* beam 0's node 3 on node 1: the beam turns back at node 2 */
    memcpy(x + 3 * 3, x + 3 * 1, 3 * sizeof(double));
    CTX("beam 0 folds back at node 2");
    EXPECT_FAIL(B2B_ERR_FOLDED, "beam 0", "segment", "node 2",
                b2b_model_update(m, x, 3, NN, 1, MSG));
  }
  assert_unchanged(m, before, ctx);
  scene_x(x, 1);
  update_ok(m, x, 1);
  assert_unchanged(m, before, "the same update again");
  assert_twins(m, twin, ctx);
  free(before);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* ============================================================ state */

START_TEST(test_wrong_state) {
  char ctx[256];
  b2b_model *m = new_model();
  double x[3 * NN], f[NEQ], totals[8];
  int eq[NEQ], n = SENT_INT, counts[16];
  int64_t size = -5;
  unsigned char buf[64];
  for (int i = 0; i < NEQ; ++i) eq[i] = i;
  for (int i = 0; i < NEQ; ++i) f[i] = SENT;
  scene_x(x, 0);
  /* before finalize */
  CTX("update before finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL, b2b_model_update(m, x, 3, NN, 1, MSG));
  CTX("commit before finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL, b2b_model_commit(m, MSG));
  CTX("revert before finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL, b2b_model_revert(m, MSG));
  CTX("contact_count before finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL, b2b_model_contact_count(m, &n, MSG));
  CTX("save_size before finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL, b2b_model_save_size(m, &size, MSG));
  CTX("save before finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL, b2b_model_save(m, buf, sizeof buf, MSG));
  CTX("restore before finalize");
  memset(buf, 0, sizeof buf);
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL, b2b_model_restore(m, buf, sizeof buf, MSG));
  for (int i = 0; i < 16; ++i) counts[i] = SENT_INT;
  for (int i = 0; i < 8; ++i) totals[i] = SENT;
  CTX("stats before finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL, b2b_model_stats(m, counts, totals, MSG));
  for (int i = 0; i < 16; ++i) ck_assert(counts[i] == SENT_INT);
  for (int i = 0; i < 8; ++i) ck_assert(totals[i] == SENT);
  CTX("add_residual before finalize");
  EXPECT_FAIL(B2B_ERR_STATE, "finalize", NULL, NULL,
              b2b_model_add_residual(m, eq, 3, 0, NEQ, f, MSG));
  ck_assert(size == -5 && n == SENT_INT);
  b2b_model_destroy(&m);

  /* finalized, no update: no results, nothing to commit */
  m = scene_model();
  b2b_model *twin = scene_model();
  for (int phase = 0; phase < 3; ++phase) {
    /* phase 0: after finalize; 1: after update + revert; 2: after a commit
     * and a revert (nothing to commit either) */
    if (phase == 1) {
      update_step(m, 0);
      update_step(twin, 0);
      ck_assert_int_eq(b2b_model_revert(m, NULL, 0), B2B_OK);
      ck_assert_int_eq(b2b_model_revert(twin, NULL, 0), B2B_OK);
    }
    if (phase == 2) {
      update_step(m, 0);
      update_step(twin, 0);
      commit_ok(m);
      commit_ok(twin);
      CTX("commit twice");
      EXPECT_FAIL(B2B_ERR_STATE, "nothing to commit", NULL, NULL, b2b_model_commit(m, MSG));
      ck_assert_int_eq(b2b_model_revert(m, NULL, 0), B2B_OK);
      ck_assert_int_eq(b2b_model_revert(twin, NULL, 0), B2B_OK);
    }
    snapshot *before = malloc(sizeof *before);
    take(m, before);
    CTX("phase %d: commit", phase);
    EXPECT_FAIL(B2B_ERR_STATE, "nothing to commit", NULL, NULL, b2b_model_commit(m, MSG));
    CTX("phase %d: contact_count", phase);
    EXPECT_FAIL(B2B_ERR_STATE, "b2b_model_update", NULL, NULL,
                b2b_model_contact_count(m, &n, MSG));
    ck_assert_int_eq(n, SENT_INT);
    int nodes[8];
    for (int i = 0; i < 8; ++i) nodes[i] = SENT_INT;
    CTX("phase %d: get_contact", phase);
    EXPECT_FAIL(B2B_ERR_STATE, "b2b_model_update", NULL, NULL,
                b2b_model_get_contact(m, 0, nodes, NULL, NULL, NULL, NULL, 24, MSG));
    for (int i = 0; i < 8; ++i) ck_assert(nodes[i] == SENT_INT);
    CTX("phase %d: add_residual", phase);
    EXPECT_FAIL(B2B_ERR_STATE, "b2b_model_update", NULL, NULL,
                b2b_model_add_residual(m, eq, 3, 0, NEQ, f, MSG));
    for (int i = 0; i < NEQ; ++i) ck_assert(f[i] == SENT);
    double *K = malloc(sizeof(double) * NEQ * NEQ);
    for (int i = 0; i < NEQ * NEQ; ++i) K[i] = SENT;
    CTX("phase %d: add_tangent_dense", phase);
    EXPECT_FAIL(B2B_ERR_STATE, "b2b_model_update", NULL, NULL,
                b2b_model_add_tangent_dense(m, eq, 3, 0, NEQ, K, NEQ, MSG));
    CTX("phase %d: add_tangent_banded", phase);
    EXPECT_FAIL(B2B_ERR_STATE, "b2b_model_update", NULL, NULL,
                b2b_model_add_tangent_banded(m, eq, 3, 0, NEQ, 5, 5, K, 16, MSG));
    for (int i = 0; i < NEQ * NEQ; ++i) ck_assert(K[i] == SENT);
    free(K);
    int nnz = SENT_INT;
    CTX("phase %d: tangent_coo", phase);
    EXPECT_FAIL(B2B_ERR_STATE, "b2b_model_update", NULL, NULL,
                b2b_model_tangent_coo(m, eq, 3, 0, NEQ, &nnz, NULL, NULL, NULL, 0, MSG));
    ck_assert_int_eq(nnz, SENT_INT);
    assert_unchanged(m, before, ctx);
    free(before);
  }
  assert_twins(m, twin, "wrong state");
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* ============================================================ get_contact */

START_TEST(test_get_contact_bad) {
  char ctx[256];
  b2b_model *m = stepped_model(), *twin = stepped_model();
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  ck_assert_int_eq(before->n, 2);
  int nodes[8 + PAD], pair[4 + PAD];
  double info[B2B_PAIR_INFO_LEN + PAD], res[B2B_PAIR_NDOF + PAD], K[LDMAX * B2B_PAIR_NDOF];
#define FILL_OUT()                                                          \
  do {                                                                      \
    for (int i = 0; i < 8 + PAD; ++i) nodes[i] = SENT_INT;                  \
    for (int i = 0; i < 4 + PAD; ++i) pair[i] = SENT_INT;                   \
    for (int i = 0; i < B2B_PAIR_INFO_LEN + PAD; ++i) info[i] = SENT;       \
    for (int i = 0; i < B2B_PAIR_NDOF + PAD; ++i) res[i] = SENT;            \
    for (int i = 0; i < LDMAX * B2B_PAIR_NDOF; ++i) K[i] = SENT;            \
  } while (0)
#define CHECK_OUT()                                                                          \
  do {                                                                                       \
    for (int i = 0; i < 8 + PAD; ++i) ck_assert_msg(nodes[i] == SENT_INT, "%s: nodes", ctx); \
    for (int i = 0; i < 4 + PAD; ++i) ck_assert_msg(pair[i] == SENT_INT, "%s: pair", ctx);   \
    for (int i = 0; i < B2B_PAIR_INFO_LEN + PAD; ++i)                                        \
      ck_assert_msg(info[i] == SENT, "%s: info", ctx);                                       \
    for (int i = 0; i < B2B_PAIR_NDOF + PAD; ++i) ck_assert_msg(res[i] == SENT, "%s: res", ctx); \
    for (int i = 0; i < LDMAX * B2B_PAIR_NDOF; ++i)                                          \
      ck_assert_msg(K[i] == SENT, "%s: tangent", ctx);                                       \
  } while (0)
  const int bad_k[4] = {-1, 2, 3, INT_MAX};
  for (int j = 0; j < 4; ++j) {
    FILL_OUT();
    char w[32];
    snprintf(w, sizeof w, "contact %d ", bad_k[j]);
    CTX("k = %d of 2", bad_k[j]);
    EXPECT_FAIL(B2B_ERR_RANGE, w, "2 active", NULL,
                b2b_model_get_contact(m, bad_k[j], nodes, pair, info, res, K, 24, MSG));
    CHECK_OUT();
  }
  const int bad_ldk[3] = {23, 0, -24};
  for (int j = 0; j < 3; ++j) {
    FILL_OUT();
    CTX("ldk %d", bad_ldk[j]);
    EXPECT_FAIL(B2B_ERR_SIZE, "ldk", "24", NULL,
                b2b_model_get_contact(m, 1, nodes, pair, info, res, K, bad_ldk[j], MSG));
    CHECK_OUT();
  }
  /* the closest valid: ldk 30 writes the 24 x 24 block only, the same numbers */
  FILL_OUT();
  CTX("ldk 30");
  EXPECT_OK(b2b_model_get_contact(m, 1, nodes, pair, info, res, K, LDMAX, MSG));
  for (int col = 0; col < 24; ++col)
    for (int row = 0; row < LDMAX; ++row) {
      if (row < 24)
        ck_assert(memcmp(&K[row + LDMAX * col], &before->tangent[1][row + 24 * col],
                         sizeof(double)) == 0);
      else
        ck_assert_msg(K[row + LDMAX * col] == SENT, "ldk 30: padding (%d, %d) written", row, col);
    }
  for (int i = 8; i < 8 + PAD; ++i) ck_assert(nodes[i] == SENT_INT);
  for (int i = 4; i < 4 + PAD; ++i) ck_assert(pair[i] == SENT_INT);
  for (int i = B2B_PAIR_INFO_LEN; i < B2B_PAIR_INFO_LEN + PAD; ++i) ck_assert(info[i] == SENT);
  for (int i = B2B_PAIR_NDOF; i < B2B_PAIR_NDOF + PAD; ++i) ck_assert(res[i] == SENT);
  /* ldk is not looked at without a tangent */
  CTX("ldk -5 without tangent");
  EXPECT_OK(b2b_model_get_contact(m, 0, nodes, pair, info, res, NULL, -5, MSG));
  assert_unchanged(m, before, ctx);

  /* an update without tangents: the tangent is not there to give */
  double x[3 * NN];
  scene_x(x, 1);
  update_ok(m, x, 0);
  update_ok(twin, x, 0);
  FILL_OUT();
  CTX("tangent after want_tangent 0");
  EXPECT_FAIL(B2B_ERR_STATE, "want_tangent 0", NULL, NULL,
              b2b_model_get_contact(m, 0, nodes, pair, info, res, K, 24, MSG));
  CHECK_OUT();
  /* the rest is there, the same as with tangents */
  CTX("no tangent after want_tangent 0");
  EXPECT_OK(b2b_model_get_contact(m, 0, nodes, pair, info, res, NULL, 24, MSG));
  ck_assert(memcmp(res, before->residual[0], sizeof before->residual[0]) == 0);
  ck_assert(memcmp(info, before->info[0], sizeof before->info[0]) == 0);
  assert_twins(m, twin, "get_contact");
#undef FILL_OUT
#undef CHECK_OUT
  free(before);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* ============================================================ assembly */

/* eq[3 k + i] = 3 k + i: every dof free, n_eq = 48. */
static void plain_eq(int *eq) {
  for (int i = 0; i < NEQ; ++i) eq[i] = i;
}

/* The smallest band (kl = ku) that holds the contacts' couplings with plain_eq. */
static int needed_band(const snapshot *s) {
  int band = 0;
  for (int k = 0; k < s->n; ++k)
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b)
        if (s->nodes[k][a] >= 0 && s->nodes[k][b] >= 0) {
          const int d = abs(3 * s->nodes[k][a] - 3 * s->nodes[k][b]) + 2;
          if (d > band) band = d;
        }
  return band;
}

START_TEST(test_assembly_bad) {
  char ctx[256];
  b2b_model *m = stepped_model(), *twin = stepped_model();
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  int eq[4 * NN];
  plain_eq(eq);
  double f[NEQ + PAD];
  double *K = malloc(sizeof(double) * (NEQ + 2) * NEQ);
  const int band = needed_band(before);
  ck_assert_msg(band > 6 && band < NEQ - 1, "band %d", band);
  const int ldab_ok = 3 * band + 1;
  double *AB = malloc(sizeof(double) * ldab_ok * NEQ);
  int rows[2000], cols[2000], nnz = SENT_INT;
  double vals[2000];
#define FILL_ALL()                                                       \
  do {                                                                   \
    for (int i = 0; i < NEQ + PAD; ++i) f[i] = SENT;                     \
    for (int i = 0; i < (NEQ + 2) * NEQ; ++i) K[i] = SENT;               \
    for (int i = 0; i < ldab_ok * NEQ; ++i) AB[i] = SENT;                \
    for (int i = 0; i < 2000; ++i) rows[i] = cols[i] = SENT_INT;         \
    for (int i = 0; i < 2000; ++i) vals[i] = SENT;                       \
    nnz = SENT_INT;                                                      \
  } while (0)
#define CHECK_ALL()                                                                          \
  do {                                                                                       \
    for (int i = 0; i < NEQ + PAD; ++i) ck_assert_msg(f[i] == SENT, "%s: f[%d] written", ctx, i); \
    for (int i = 0; i < (NEQ + 2) * NEQ; ++i)                                                \
      ck_assert_msg(K[i] == SENT, "%s: K[%d] written", ctx, i);                              \
    for (int i = 0; i < ldab_ok * NEQ; ++i)                                                  \
      ck_assert_msg(AB[i] == SENT, "%s: AB[%d] written", ctx, i);                            \
    for (int i = 0; i < 2000; ++i)                                                           \
      ck_assert_msg(rows[i] == SENT_INT && cols[i] == SENT_INT && vals[i] == SENT,           \
                    "%s: COO entry %d written", ctx, i);                                     \
    ck_assert_msg(nnz == SENT_INT, "%s: nnz written", ctx);                                  \
  } while (0)

  /* ldeq < 3 */
  FILL_ALL();
  CTX("ldeq 2");
  EXPECT_FAIL(B2B_ERR_SIZE, "ldeq", "2", NULL, b2b_model_add_residual(m, eq, 2, 0, NEQ, f, MSG));
  EXPECT_FAIL(B2B_ERR_SIZE, "ldeq", "2", NULL,
              b2b_model_add_tangent_dense(m, eq, 2, 0, NEQ, K, NEQ, MSG));
  EXPECT_FAIL(B2B_ERR_SIZE, "ldeq", "2", NULL,
              b2b_model_add_tangent_banded(m, eq, 2, 0, NEQ, band, band, AB, ldab_ok, MSG));
  EXPECT_FAIL(B2B_ERR_SIZE, "ldeq", "2", NULL,
              b2b_model_tangent_coo(m, eq, 2, 0, NEQ, &nnz, rows, cols, vals, 2000, MSG));
  CHECK_ALL();
  /* n_eq < 0 */
  CTX("n_eq -1");
  EXPECT_FAIL(B2B_ERR_RANGE, "n_eq", "-1", NULL, b2b_model_add_residual(m, eq, 3, 0, -1, f, MSG));
  EXPECT_FAIL(B2B_ERR_RANGE, "n_eq", "-1", NULL,
              b2b_model_tangent_coo(m, eq, 3, 0, -1, &nnz, NULL, NULL, NULL, 0, MSG));
  CHECK_ALL();
  /* an equation number >= n_eq at node 2 (in both contacts), y */
  {
    int eq2[NEQ];
    plain_eq(eq2);
    eq2[3 * 2 + 1] = NEQ;
    CTX("equation 48 of node 2, y, n_eq 48");
    EXPECT_FAIL(B2B_ERR_RANGE, "node 2", "y", "48",
                b2b_model_add_residual(m, eq2, 3, 0, NEQ, f, MSG));
    EXPECT_FAIL(B2B_ERR_RANGE, "node 2", "y", "n_eq",
                b2b_model_add_tangent_dense(m, eq2, 3, 0, NEQ, K, NEQ, MSG));
    EXPECT_FAIL(B2B_ERR_RANGE, "node 2", "y", NULL,
                b2b_model_add_tangent_banded(m, eq2, 3, 0, NEQ, band, band, AB, ldab_ok, MSG));
    EXPECT_FAIL(B2B_ERR_RANGE, "node 2", "y", NULL,
                b2b_model_tangent_coo(m, eq2, 3, 0, NEQ, &nnz, rows, cols, vals, 2000, MSG));
    CHECK_ALL();
    /* Fortran style: base 1, numbers 1 .. 48; 49 is beyond */
    for (int i = 0; i < NEQ; ++i) eq2[i] = i + 1;
    eq2[3 * 2 + 1] = NEQ + 1;
    CTX("equation 49 of node 2, base 1");
    EXPECT_FAIL(B2B_ERR_RANGE, "node 2", "y", "49",
                b2b_model_add_residual(m, eq2, 3, 1, NEQ, f, MSG));
    CHECK_ALL();
    /* all dofs of node 2 constrained, only one number too large: node 5 z,
     * which no contact uses, is not looked at */
    plain_eq(eq2);
    eq2[3 * UNUSED + 2] = 1000;
    CTX("equation 1000 at the unused node 10");
    EXPECT_OK(b2b_model_add_residual(m, eq2, 3, 0, NEQ, f, MSG));
    FILL_ALL();
    /* an n_eq that is too small for the plain numbering: the node named is
     * one the contacts use */
    CTX("n_eq 20");
    EXPECT_FAIL(B2B_ERR_RANGE, "node", "n_eq", NULL, b2b_model_add_residual(m, eq, 3, 0, 20, f, MSG));
    CHECK_ALL();
  }
  /* the band */
  CTX("band %d - 1", band);
  EXPECT_FAIL(B2B_ERR_RANGE, "band", "equations", NULL,
              b2b_model_add_tangent_banded(m, eq, 3, 0, NEQ, band - 1, band - 1, AB,
                                           3 * (band - 1) + 1, MSG));
  CHECK_ALL();
  CTX("band kl 0");
  EXPECT_FAIL(B2B_ERR_RANGE, "band", NULL, NULL,
              b2b_model_add_tangent_banded(m, eq, 3, 0, NEQ, 0, band, AB, band + 1, MSG));
  CHECK_ALL();
  CTX("kl -1");
  EXPECT_FAIL(B2B_ERR_RANGE, "kl", "-1", NULL,
              b2b_model_add_tangent_banded(m, eq, 3, 0, NEQ, -1, band, AB, ldab_ok, MSG));
  CTX("ku -1");
  EXPECT_FAIL(B2B_ERR_RANGE, "ku", "-1", NULL,
              b2b_model_add_tangent_banded(m, eq, 3, 0, NEQ, band, -1, AB, ldab_ok, MSG));
  CTX("ldab 2 kl + ku");
  EXPECT_FAIL(B2B_ERR_SIZE, "ldab", "2 kl + ku + 1", NULL,
              b2b_model_add_tangent_banded(m, eq, 3, 0, NEQ, band, band, AB, ldab_ok - 1, MSG));
  CHECK_ALL();
  /* dense ldk */
  CTX("dense ldk 47 < n_eq 48");
  EXPECT_FAIL(B2B_ERR_SIZE, "ldk", "48", NULL,
              b2b_model_add_tangent_dense(m, eq, 3, 0, NEQ, K, NEQ - 1, MSG));
  CTX("dense ldk 0");
  EXPECT_FAIL(B2B_ERR_SIZE, "ldk", NULL, NULL,
              b2b_model_add_tangent_dense(m, eq, 3, 0, NEQ, K, 0, MSG));
  CHECK_ALL();
  /* COO */
  int count = SENT_INT;
  CTX("COO size query");
  EXPECT_OK(b2b_model_tangent_coo(m, eq, 3, 0, NEQ, &count, NULL, NULL, NULL, 0, MSG));
  ck_assert_msg(count > 0 && count <= 2000, "COO count %d", count);
  CTX("COO capacity count - 1");
  EXPECT_FAIL(B2B_ERR_SIZE, "capacity", "entries", NULL,
              b2b_model_tangent_coo(m, eq, 3, 0, NEQ, &nnz, rows, cols, vals, count - 1, MSG));
  CTX("COO capacity 0");
  EXPECT_FAIL(B2B_ERR_SIZE, "capacity", NULL, NULL,
              b2b_model_tangent_coo(m, eq, 3, 0, NEQ, &nnz, rows, cols, vals, 0, MSG));
  CTX("COO capacity -1");
  EXPECT_FAIL(B2B_ERR_SIZE, "capacity", NULL, NULL,
              b2b_model_tangent_coo(m, eq, 3, 0, NEQ, &nnz, rows, cols, vals, -1, MSG));
  CTX("COO rows without cols");
  EXPECT_FAIL(B2B_ERR_NULL, "cols", "NULL", NULL,
              b2b_model_tangent_coo(m, eq, 3, 0, NEQ, &nnz, rows, NULL, vals, 2000, MSG));
  CTX("COO rows without values");
  EXPECT_FAIL(B2B_ERR_NULL, "values", "NULL", NULL,
              b2b_model_tangent_coo(m, eq, 3, 0, NEQ, &nnz, rows, cols, NULL, 2000, MSG));
  CHECK_ALL();

  /* positive controls: each helper works after all that */
  CTX("band %d", band);
  EXPECT_OK(b2b_model_add_tangent_banded(m, eq, 3, 0, NEQ, band, band, AB, ldab_ok, MSG));
  CTX("COO with capacity count");
  EXPECT_OK(b2b_model_tangent_coo(m, eq, 3, 0, NEQ, &nnz, rows, cols, vals, count, MSG));
  ck_assert_int_eq(nnz, count);
  ck_assert(rows[count] == SENT_INT && cols[count] == SENT_INT && vals[count] == SENT);
  CTX("dense");
  EXPECT_OK(b2b_model_add_tangent_dense(m, eq, 3, 0, NEQ, K, NEQ + 2, MSG));
  CTX("residual");
  EXPECT_OK(b2b_model_add_residual(m, eq, 3, 0, NEQ, f, MSG));
  for (int i = NEQ; i < NEQ + PAD; ++i) ck_assert(f[i] == SENT);

  /* the tangent helpers after an update without tangents: STATE; the
   * residual helper works */
  double x[3 * NN];
  scene_x(x, 1);
  update_ok(m, x, 0);
  update_ok(twin, x, 0);
  FILL_ALL();
  CTX("dense after want_tangent 0");
  EXPECT_FAIL(B2B_ERR_STATE, "want_tangent 0", NULL, NULL,
              b2b_model_add_tangent_dense(m, eq, 3, 0, NEQ, K, NEQ, MSG));
  CTX("banded after want_tangent 0");
  EXPECT_FAIL(B2B_ERR_STATE, "want_tangent 0", NULL, NULL,
              b2b_model_add_tangent_banded(m, eq, 3, 0, NEQ, band, band, AB, ldab_ok, MSG));
  CTX("COO after want_tangent 0");
  EXPECT_FAIL(B2B_ERR_STATE, "want_tangent 0", NULL, NULL,
              b2b_model_tangent_coo(m, eq, 3, 0, NEQ, &nnz, NULL, NULL, NULL, 0, MSG));
  CHECK_ALL();
  CTX("residual after want_tangent 0");
  EXPECT_OK(b2b_model_add_residual(m, eq, 3, 0, NEQ, f, MSG));
  assert_twins(m, twin, "assembly");
#undef FILL_ALL
#undef CHECK_ALL
  free(K);
  free(AB);
  free(before);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* ============================================================ restart */

START_TEST(test_restore_bad) {
  char ctx[256];
  /* m: committed at step 0, updated at step 1 (uncommitted). twin the same. */
  b2b_model *m = stepped_model(), *twin = stepped_model();
  /* a buffer of this model's committed state, after committing step 1 of a third model */
  b2b_model *src = stepped_model();
  commit_ok(src);
  int64_t size = -5;
  ck_assert_int_eq(b2b_model_save_size(src, &size, NULL, 0), B2B_OK);
  ck_assert(size > 40);
  unsigned char *buf = malloc((size_t)size + 16), *copy = malloc((size_t)size + 16);
  ck_assert_int_eq(b2b_model_save(src, buf, size, NULL, 0), B2B_OK);
  snapshot *before = malloc(sizeof *before);
  take(m, before);

  CTX("size -1");
  EXPECT_FAIL(B2B_ERR_SIZE, "size", "-1", NULL, b2b_model_restore(m, buf, -1, MSG));
  const int64_t cut[4] = {0, 8, 39, 0};
  for (int j = 0; j < 4; ++j) {
    const int64_t n = j < 3 ? cut[j] : size - 1;
    CTX("truncated to %lld of %lld bytes", (long long)n, (long long)size);
    EXPECT_FAIL(B2B_ERR_RANGE, "restart buffer", "truncated", NULL,
                b2b_model_restore(m, buf, n, MSG));
  }
  /* one byte flipped, at several places (the middle among them) */
  const int64_t at[5] = {size / 2, 0, 20, 45, size - 1};
  for (int j = 0; j < 5; ++j) {
    memcpy(copy, buf, (size_t)size);
    copy[at[j]] ^= 0x10;
    CTX("byte %lld of %lld flipped", (long long)at[j], (long long)size);
    g_cur = fresh_msg();
    g_len = B2B_ERRMSG_LEN;
    check_failure(ctx, b2b_model_restore(m, copy, size, MSG), B2B_ERR_RANGE, "restart buffer",
                  NULL, NULL);
    ck_assert_msg(strstr(g_msg, "corrupted") || strstr(g_msg, "truncated") ||
                      strstr(g_msg, "not a b2b") || strstr(g_msg, "version"),
                  "%s: message \"%s\" does not say what is wrong", ctx, g_msg);
    if (j == 0)
      EXPECT_FAIL(B2B_ERR_RANGE, "restart buffer", "corrupted", NULL,
                  b2b_model_restore(m, copy, size, MSG));
    ck_assert_msg(memcmp(copy + at[j] + 1, buf + at[j] + 1, (size_t)(size - at[j] - 1)) == 0 &&
                      memcmp(copy, buf, (size_t)at[j]) == 0,
                  "%s: restore modified the buffer", ctx);
  }
  /* garbage of the right size */
  for (int64_t i = 0; i < size; ++i) copy[i] = (unsigned char)(i * 37 + 11);
  CTX("garbage");
  EXPECT_FAIL(B2B_ERR_RANGE, "restart buffer", NULL, NULL, b2b_model_restore(m, copy, size, MSG));
  /* from another model: beam 2 of radius 0.11; a model of two beams */
  for (int j = 0; j < 3; ++j) {
    b2b_model *other = new_model();
    scene_opts o = base_opts;
    if (j == 0) {
      add_beams(other, 0, NB - 1, RADIUS);
      add_beam_ok(other, NB - 1, 0.11);
    } else {
      add_beams(other, 0, j == 1 ? NB - 1 : NB, RADIUS);
    }
    set_pairs(other, &o);
    if (j == 2) {
      /* same beams, n_nodes 17 */
      char msg[B2B_ERRMSG_LEN];
      ck_assert_int_eq(b2b_model_finalize(other, NN + 1, msg, sizeof msg), B2B_OK);
    } else {
      finalize_ok(other);
    }
    double x[3 * (NN + 1)];
    scene_x(x, 0);
    x[3 * NN] = x[3 * NN + 1] = x[3 * NN + 2] = 0.0;
    ck_assert_int_eq(b2b_model_update(other, x, 3, NN + (j == 2), 1, NULL, 0), B2B_OK);
    commit_ok(other);
    int64_t osize = 0;
    ck_assert_int_eq(b2b_model_save_size(other, &osize, NULL, 0), B2B_OK);
    unsigned char *obuf = malloc((size_t)osize);
    ck_assert_int_eq(b2b_model_save(other, obuf, osize, NULL, 0), B2B_OK);
    CTX("buffer of another model (%s)", j == 0 ? "beam 2 radius 0.11"
                                                : j == 1 ? "two beams" : "17 nodes");
    EXPECT_FAIL(B2B_ERR_RANGE, "restart buffer", "another model", NULL,
                b2b_model_restore(m, obuf, osize, MSG));
    free(obuf);
    b2b_model_destroy(&other);
  }
  /* a friction-off variant of (0, 1): other history lengths */
  {
    scene_opts o = base_opts;
    o.friction01 = 0;
    b2b_model *other = scene_model_opts(&o);
    update_step(other, 0);
    commit_ok(other);
    int64_t osize = 0;
    ck_assert_int_eq(b2b_model_save_size(other, &osize, NULL, 0), B2B_OK);
    unsigned char *obuf = malloc((size_t)osize);
    ck_assert_int_eq(b2b_model_save(other, obuf, osize, NULL, 0), B2B_OK);
    CTX("buffer of a model without friction");
    EXPECT_FAIL(B2B_ERR_RANGE, "restart buffer", "another model", NULL,
                b2b_model_restore(m, obuf, osize, MSG));
    free(obuf);
    b2b_model_destroy(&other);
  }
  assert_unchanged(m, before, ctx);
  /* the committed state is the one of step 0: continuing gives the twin's numbers */
  assert_twins(m, twin, "restore");

  /* the closest valid: the real buffer with 16 extra bytes after it */
  memcpy(copy, buf, (size_t)size);
  memset(copy + size, 0xEE, 16);
  CTX("valid buffer with 16 spare bytes");
  EXPECT_OK(b2b_model_restore(m, copy, size + 16, MSG));
  /* after a restore there are no results */
  int n = SENT_INT;
  CTX("contact_count after restore");
  EXPECT_FAIL(B2B_ERR_STATE, "b2b_model_update", NULL, NULL, b2b_model_contact_count(m, &n, MSG));
  /* and it continues as src does */
  update_step(m, 2);
  update_step(src, 2);
  snapshot *a = malloc(sizeof *a), *b = malloc(sizeof *b);
  take(m, a);
  take(src, b);
  /* the search is a cache of each model: its counts may differ */
  a->counts[B2B_COUNT_SEARCH_BUILDS] = b->counts[B2B_COUNT_SEARCH_BUILDS];
  a->counts[B2B_COUNT_CANDIDATES] = b->counts[B2B_COUNT_CANDIDATES];
  a->counts[B2B_COUNT_FAR] = b->counts[B2B_COUNT_FAR];
  assert_same(b, a, "restored vs. source");
  free(a);
  free(b);
  free(before);
  free(buf);
  free(copy);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
  b2b_model_destroy(&src);
}
END_TEST

START_TEST(test_save_bad) {
  char ctx[256];
  b2b_model *m = stepped_model(), *twin = stepped_model();
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  int64_t size = 0;
  ck_assert_int_eq(b2b_model_save_size(m, &size, NULL, 0), B2B_OK);
  unsigned char *buf = malloc((size_t)size + 8);
  const int64_t small[4] = {0, 1, -1, 0};
  for (int j = 0; j < 4; ++j) {
    const int64_t n = j < 3 ? small[j] : size - 1;
    memset(buf, 0xA5, (size_t)size + 8);
    char w[32];
    snprintf(w, sizeof w, "%lld", (long long)size);
    CTX("save into %lld of %lld bytes", (long long)n, (long long)size);
    EXPECT_FAIL(B2B_ERR_SIZE, "buffer", w, "b2b_model_save_size", b2b_model_save(m, buf, n, MSG));
    for (int64_t i = 0; i < size + 8; ++i)
      ck_assert_msg(buf[i] == 0xA5, "%s: byte %lld written", ctx, (long long)i);
  }
  assert_unchanged(m, before, ctx);
  assert_twins(m, twin, "save");
  free(buf);
  free(before);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* ============================================================ extremes */

/* The scene with coordinates and radii scaled by s (loop: 1e-90, 1e90):
 * the same contacts, finite forces, the same parameters xi, eta. */
START_TEST(test_extreme_scales) {
  const double s = _i == 0 ? 1e-90 : 1e90;
  char ctx[256];
  b2b_model *ref = scene_model();
  scene_opts o = base_opts;
  o.radius = RADIUS * s;
  b2b_model *m = scene_model_opts(&o);
  double x[3 * NN];
  scene_x(x, 0);
  update_ok(ref, x, 1);
  scale_x(x, s);
  CTX("scale %g", s);
  EXPECT_OK(b2b_model_update(m, x, 3, NN, 1, MSG));
  snapshot *a = malloc(sizeof *a), *b = malloc(sizeof *b);
  take(m, a);
  take(ref, b);
  assert_finite(a, ctx);
  ck_assert_msg(a->n == 2 && b->n == 2, "%s: %d contacts (unscaled %d)", ctx, a->n, b->n);
  for (int k = 0; k < 2; ++k) {
    ck_assert(memcmp(a->pair[k], b->pair[k], sizeof a->pair[k]) == 0);
    ck_assert(memcmp(a->nodes[k], b->nodes[k], sizeof a->nodes[k]) == 0);
    ck_assert_msg(fabs(a->info[k][B2B_INFO_XI] - b->info[k][B2B_INFO_XI]) < 1e-9 &&
                      fabs(a->info[k][B2B_INFO_ETA] - b->info[k][B2B_INFO_ETA]) < 1e-9,
                  "%s: contact %d at (%g, %g), unscaled (%g, %g)", ctx, k,
                  a->info[k][B2B_INFO_XI], a->info[k][B2B_INFO_ETA], b->info[k][B2B_INFO_XI],
                  b->info[k][B2B_INFO_ETA]);
    ck_assert_msg(a->info[k][B2B_INFO_NORMAL_FORCE] > 0.0, "%s: contact %d: no force", ctx, k);
    ck_assert_msg(fabs(a->info[k][B2B_INFO_GAP] / s - b->info[k][B2B_INFO_GAP]) < 1e-9,
                  "%s: gap %g", ctx, a->info[k][B2B_INFO_GAP]);
  }
  /* it goes on: commit, a step, assembly */
  commit_ok(m);
  scene_x(x, 1);
  scale_x(x, s);
  update_ok(m, x, 1);
  take(m, a);
  assert_finite(a, ctx);
  ck_assert_int_eq(a->n, 2);
  int eq[NEQ];
  plain_eq(eq);
  double f[NEQ] = {0};
  EXPECT_OK(b2b_model_add_residual(m, eq, 3, 0, NEQ, f, MSG));
  for (int i = 0; i < NEQ; ++i) ck_assert_msg(isfinite(f[i]), "%s: f[%d] = %g", ctx, i, f[i]);
  free(a);
  free(b);
  b2b_model_destroy(&m);
  b2b_model_destroy(&ref);
}
END_TEST

/* Penalty 0: the pairs are evaluated, no force, every output finite. */
START_TEST(test_zero_penalty) {
  char ctx[256];
  scene_opts o = base_opts;
  o.pen00 = 0.0;
  o.pen01 = 0.0;
  b2b_model *m = scene_model_opts(&o);
  double x[3 * NN];
  scene_x_at(x, 0, 0.02); /* beam 1 deep in beam 0 */
  CTX("penalty 0");
  EXPECT_OK(b2b_model_update(m, x, 3, NN, 1, MSG));
  snapshot *a = malloc(sizeof *a);
  take(m, a);
  assert_finite(a, ctx);
  for (int k = 0; k < a->n; ++k) {
    ck_assert(a->info[k][B2B_INFO_NORMAL_FORCE] == 0.0);
    for (int i = 0; i < 24; ++i) ck_assert(a->residual[k][i] == 0.0);
  }
  ck_assert_msg(a->counts[B2B_COUNT_EVALUATED] >= 2, "%s: %d pairs evaluated", ctx,
                a->counts[B2B_COUNT_EVALUATED]);
  ck_assert(a->totals[B2B_TOTAL_NORMAL_FORCE] == 0.0 && a->totals[B2B_TOTAL_ENERGY] == 0.0);
  ck_assert_msg(a->totals[B2B_TOTAL_MIN_GAP] < -0.1, "%s: min gap %g", ctx,
                a->totals[B2B_TOTAL_MIN_GAP]);
  commit_ok(m);
  free(a);
  b2b_model_destroy(&m);
}
END_TEST

/* Penalty 1e300 on (0, 0) with a deep penetration at scale 1e6: the energy
 * 0.5 eps g^2 overflows. B2B_ERR_RANGE naming the pair, the model unchanged. */
START_TEST(test_overflow) {
  char ctx[256];
  const double s = 1e6;
  scene_opts o = base_opts;
  o.pen00 = 1e300;
  o.radius = RADIUS * s;
  b2b_model *m = scene_model_opts(&o), *twin = scene_model_opts(&o);
  /* first: beam 1 far below (no (0, 0) contact), beam 2 on beam 0 */
  double x[3 * NN];
  scene_x_at(x, 0, 1.0);
  scale_x(x, s);
  update_ok(m, x, 1);
  update_ok(twin, x, 1);
  commit_ok(m);
  commit_ok(twin);
  update_ok(m, x, 1);
  update_ok(twin, x, 1);
  snapshot *before = malloc(sizeof *before);
  take(m, before);
  ck_assert_int_eq(before->n, 1);
  double deep[3 * NN];
  scene_x_at(deep, 0, 0.01);
  scale_x(deep, s);
  CTX("penalty 1e300, gap -0.19e6");
  EXPECT_FAIL(B2B_ERR_RANGE, "overflow", "beam 0 segment", "beam 1 segment",
              b2b_model_update(m, deep, 3, NN, 1, MSG));
  ck_assert_msg(strstr(g_msg, "penalty") != NULL, "%s: message \"%s\" does not name the penalty",
                ctx, g_msg);
  assert_unchanged(m, before, ctx);
  update_ok(m, x, 1);
  assert_unchanged(m, before, "the same update again");
  /* and a commit goes on like the twin */
  commit_ok(m);
  commit_ok(twin);
  scene_x_at(x, 1, 1.0);
  scale_x(x, s);
  update_ok(m, x, 1);
  update_ok(twin, x, 1);
  snapshot *a = malloc(sizeof *a);
  take(m, a);
  take(twin, before);
  assert_same(before, a, "after the overflow");
  assert_finite(a, ctx);
  free(a);
  free(before);
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
}
END_TEST

/* Beam 1 turned to within angle (loop: 0, 1e-12, 1e-7, 1e-3 rad) of beam 0's
 * direction at the crossing, both straight, pressed together: whatever the
 * status, every output finite. */
START_TEST(test_near_parallel) {
  const double angles[4] = {0.0, 1e-12, 1e-7, 1e-3};
  const double th = angles[_i];
  char ctx[256];
  b2b_model *m = scene_model();
  double x[3 * NN];
  scene_x(x, 0);
  for (int k = 0; k < 5; ++k) {
    const double t = -2.0 + k;
    double *p = x + 3 * beam_nodes[0][k];
    p[0] = t;
    p[1] = 0.0;
    p[2] = 0.0;
    p = x + 3 * beam_nodes[1][k];
    p[0] = 0.3 + (t + 0.2) * cos(th);
    p[1] = (t + 0.2) * sin(th);
    p[2] = -DIST;
  }
  CTX("angle %g", th);
  EXPECT_OK(b2b_model_update(m, x, 3, NN, 1, MSG));
  snapshot *a = malloc(sizeof *a);
  take(m, a);
  assert_finite(a, ctx);
  int eq[NEQ];
  plain_eq(eq);
  double f[NEQ] = {0};
  EXPECT_OK(b2b_model_add_residual(m, eq, 3, 0, NEQ, f, MSG));
  for (int i = 0; i < NEQ; ++i) ck_assert_msg(isfinite(f[i]), "%s: f[%d] = %g", ctx, i, f[i]);
  double *K = calloc(NEQ * NEQ, sizeof(double));
  EXPECT_OK(b2b_model_add_tangent_dense(m, eq, 3, 0, NEQ, K, NEQ, MSG));
  for (int i = 0; i < NEQ * NEQ; ++i) ck_assert_msg(isfinite(K[i]), "%s: K[%d] = %g", ctx, i, K[i]);
  free(K);
  commit_ok(m);
  /* slide along: still finite */
  for (int k = 0; k < 5; ++k) x[3 * beam_nodes[0][k]] += 0.3;
  EXPECT_OK(b2b_model_update(m, x, 3, NN, 1, MSG));
  take(m, a);
  assert_finite(a, ctx);
  free(a);
  b2b_model_destroy(&m);
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("model_bad_input");
  TCase *tc;
#define TC(name, fn, lo, hi)           \
  tc = tcase_create(name);             \
  tcase_add_loop_test(tc, fn, lo, hi); \
  suite_add_tcase(s, tc)

  TC("null_model", test_null_model, 0, 1);
  /* Loop index: 0 set-up calls, 1 calls on an updated model. */
  TC("null_arguments", test_null_arguments, 0, 2);
  /* Loop index: the case (nodes, sizes, closed, radius, kind, group). */
  TC("add_beam_bad", test_add_beam_bad, 0, N_ADD_BEAM_CASES);
  TC("add_beam_valid_limits", test_add_beam_valid_limits, 0, 1);
  TC("group_pair_bad", test_group_pair_bad, 0, 1);
  /* Loop index: before the first update, after a commit, after a revert. */
  TC("group_pair_replace", test_group_pair_replace, 0, 3);
  TC("self_contact_bad", test_self_contact_bad, 0, 1);
  TC("finalize_bad", test_finalize_bad, 0, 1);
  TC("finalize_no_pair_of_beams", test_finalize_no_pair_of_beams, 0, 1);
  /* Loop index: before / after an update. */
  TC("options_bad", test_options_bad, 0, 2);
  TC("options_long_key", test_options_long_key, 0, 1);
  TC("update_bad_arguments", test_update_bad_arguments, 0, 1);
  TC("update_valid_layouts", test_update_valid_layouts, 0, 1);
  /* Loop index: node (2, 7, 15) x axis x value (NaN, Inf, -Inf, -2e100). */
  TC("update_bad_coordinate", test_update_bad_coordinate, 0, 36);
  /* Loop index: NaN, Inf, -Inf, 1e300 in the unused node. */
  TC("update_unused_node", test_update_unused_node, 0, 4);
  /* Loop index: coincident, folded. */
  TC("update_degenerate_segment", test_update_degenerate_segment, 0, 2);
  TC("wrong_state", test_wrong_state, 0, 1);
  TC("get_contact_bad", test_get_contact_bad, 0, 1);
  TC("assembly_bad", test_assembly_bad, 0, 1);
  TC("restore_bad", test_restore_bad, 0, 1);
  TC("save_bad", test_save_bad, 0, 1);
  /* Loop index: scale 1e-90, 1e90. */
  TC("extreme_scales", test_extreme_scales, 0, 2);
  TC("zero_penalty", test_zero_penalty, 0, 1);
  TC("overflow", test_overflow, 0, 1);
  /* Loop index: angle 0, 1e-12, 1e-7, 1e-3. */
  TC("near_parallel", test_near_parallel, 0, 4);
#undef TC
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
