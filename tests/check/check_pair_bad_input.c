/* Bad input of the contact element: the b2b_params handle (create, set, get,
 * finalize, history_size, destroy) and b2b_pair_eval.
 *
 * For every documented bad input (see <b2b/b2b.h> "Messages", "Outputs" and
 * the "Bad input" paragraph of <b2b/b2b_pair.h>) each test checks
 *   - the documented status code,
 *   - a NUL-terminated message that names the problem (strstr on the
 *     argument, the beam, the node, the key), written within the buffer,
 *   - that no output was touched (hist_new, contact_status, info, residual
 *     and the tangent, with its leading-dimension padding, pre-filled with a
 *     sentinel and checked entry by entry) and that no input was modified,
 *   - the same code with errmsg = NULL, 0 and with an 8-byte buffer,
 * and, next to it, the closest input that is NOT an error (unused slots, zero
 * radius, zero penalty, aliased histories, extreme scales, near-parallel and
 * intersecting axes), which must succeed with finite outputs and leave the
 * message buffer alone.
 *
 * The base configuration is hand-made and exact: beam A is a gently bent
 * curve in the plane z = 0 running along x, beam B one in the plane
 * z = -DIST running along y; both planar, so the closest points are where
 * their projections cross, the axes are exactly DIST apart and the gap is
 * DIST - 2 RADIUS = -0.05 (an active contact). Beam A is HERMITE_NODAL with
 * neighbours on both sides (all four slots read), beam B
 * HERMITE_NODAL_WEIGHTED ending at its last node with a host TANGENT (slot x4
 * unused, filled with NaN). One thing is broken at a time. */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pair_support.h"

#define SENT 12345.0
#define SENT_INT (-777)
#define GUARD 'Z'
#define HMAX 16      /* room for the history (its length is checked <= HMAX - 4) */
#define LDMAX 30     /* largest leading dimension the tests use */
#define INFO_PAD 4   /* entries after info[32] and residual[24] that must stay untouched */
#define PEN 100.0
#define RADIUS 0.1
#define DIST 0.15 /* axis distance of the base crossing: gap DIST - 2 RADIUS = -0.05 */
#define BEND 0.1

enum { NB = B2B_END_NEIGHBOUR, RF = B2B_END_REFLECT, TG = B2B_END_TANGENT };
enum { LIN = B2B_CURVE_LINEAR, MID = B2B_CURVE_HERMITE_MIDPOINT, NOD = B2B_CURVE_HERMITE_NODAL,
       NDW = B2B_CURVE_HERMITE_NODAL_WEIGHTED };

#define CTX(...) snprintf(ctx, sizeof ctx, __VA_ARGS__)

static const char *const beam_name[2] = {"beam A", "beam B"};
static const int base_seg[6] = {NOD, NB, NB, NDW, NB, TG};

static const char *rule_name(int r) {
  switch (r) {
    case NB: return "NEIGHBOUR";
    case RF: return "REFLECT";
    case TG: return "TANGENT";
    default: return "?";
  }
}

/* ============================================================ geometry */

/* A segment centred on a node (midpoint) cannot be both ends of its beam. */
static int valid_rules(int kind, int sr, int er) {
  return !(tst_kind_family(kind) == TST_CENTRED && sr != NB && er != NB);
}

/* The slots a kind reads, from the table in <b2b/b2b_curve.h> (bit k: x(k+1)). */
static unsigned used_slots(int kind, int sr, int er) {
  switch (tst_kind_family(kind)) {
    case TST_CHORD: return 0x6u;
    case TST_CENTRED: return 0x2u | (sr == NB ? 0x1u : 0u) | (er == NB ? 0x4u : 0u);
    case TST_NODAL: return 0x6u | (sr == NB ? 0x1u : 0u) | (er == NB ? 0x8u : 0u);
  }
  return 0u;
}

static int tangent_in_force(int kind, int sr, int er) {
  return tst_kind_family(kind) != TST_CHORD && (sr == TG || er == TG);
}

typedef struct {
  int seg[6]; /* kind, start_rule, end_rule of A, then of B */
  double X[24];
  double tangents[12];
  double radii[2];
} geometry;

/* One beam: nodes at s = -1.5, -0.5, 0.5, 1.5 along dir, bent by bend s^2
 * along perp (a planar curve), moved so that the segment's point at xi = 0
 * lies at `at`. Slots the kind does not read are NaN. */
static void make_beam(int kind, int sr, int er, const double dir[3], const double perp[3],
                      double bend, const double at[3], const double tang[6], double P[12]) {
  static const double s[4] = {-1.5, -0.5, 0.5, 1.5};
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) P[3 * k + i] = s[k] * dir[i] + bend * s[k] * s[k] * perp[i];
  double x[9];
  tst_eval(kind, sr, er, P, tang, 0.0, x, NULL, NULL);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) P[3 * k + i] += at[i] - x[i];
  const unsigned used = used_slots(kind, sr, er);
  for (int k = 0; k < 4; ++k)
    if (!(used & (1u << k)))
      for (int i = 0; i < 3; ++i) P[3 * k + i] = NAN;
}

/* Beam A along x in z = 0, beam B at angle_deg to it in z = -dist, both bent
 * by `bend` within their planes; host tangents along the beams; radii RADIUS.
 * The projections cross near the origin, at xi, eta near 0. */
static void make_geometry(const int seg[6], double angle_deg, double bend, double dist,
                          geometry *g) {
  const double th = angle_deg * 3.14159265358979323846 / 180.0;
  const double da[3] = {1, 0, 0}, pa[3] = {0, 1, 0};
  const double db[3] = {cos(th), sin(th), 0}, pb[3] = {-sin(th), cos(th), 0};
  const double at_a[3] = {0, 0, 0}, at_b[3] = {0, 0, -dist};
  memcpy(g->seg, seg, sizeof g->seg);
  for (int i = 0; i < 3; ++i) {
    g->tangents[i] = g->tangents[3 + i] = da[i];
    g->tangents[6 + i] = g->tangents[9 + i] = db[i];
  }
  make_beam(seg[0], seg[1], seg[2], da, pa, bend, at_a, g->tangents, g->X);
  make_beam(seg[3], seg[4], seg[5], db, pb, bend, at_b, g->tangents + 6, g->X + 12);
  g->radii[0] = g->radii[1] = RADIUS;
}

/* x -> s x + offset for every coordinate (NaN stays NaN); radii scale too. */
static void scale_geometry(geometry *g, double s, double offset) {
  for (int a = 0; a < 24; ++a) g->X[a] = g->X[a] * s + offset;
  g->radii[0] *= s;
  g->radii[1] *= s;
}

static void copy_node(double *patch, int to, int from) {
  for (int i = 0; i < 3; ++i) patch[3 * to + i] = patch[3 * from + i];
}

/* ============================================================ calls */

/* Arguments that a test may pass as NULL. */
enum {
  A_SEGMENTS = 1 << 0,
  A_X = 1 << 1,
  A_RADII = 1 << 2,
  A_HIST_OLD = 1 << 3,
  A_HIST_NEW = 1 << 4,
  A_STATUS = 1 << 5,
  A_INFO = 1 << 6,
  A_RESIDUAL = 1 << 7,
  A_END_TANGENTS = 1 << 8,
  A_TANGENT = 1 << 9
};

typedef struct {
  const b2b_params *params;
  geometry g;
  double hist_old[HMAX];
  int hist_len, ldk;
  unsigned null_args; /* A_* bits */
  int alias;          /* hist_new is hist_old */
} pair_call;

typedef struct {
  double hist_new[HMAX];
  int status;
  double info[B2B_PAIR_INFO_LEN + INFO_PAD];
  double residual[B2B_PAIR_NDOF + INFO_PAD];
  double tangent[LDMAX * B2B_PAIR_NDOF];
} outputs;

static int history_size(const b2b_params *p) {
  int n = SENT_INT;
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_params_history_size(p, &n, msg, (int)sizeof msg) == B2B_OK,
                "history_size: %s", msg);
  ck_assert_msg(n >= 1 && n <= HMAX - 4, "history size %d outside what the tests expect", n);
  return n;
}

/* The base call: a finalized linear-law parameter set, the base crossing, a
 * fresh history, a tangent with ldk 24. */
static void base_call(pair_call *c, const b2b_params *p) {
  memset(c, 0, sizeof *c);
  c->params = p;
  make_geometry(base_seg, 90.0, BEND, DIST, &c->g);
  c->hist_len = history_size(p);
  c->ldk = B2B_PAIR_NDOF;
}

static void fill_outputs(outputs *o) {
  for (int i = 0; i < HMAX; ++i) o->hist_new[i] = SENT;
  o->status = SENT_INT;
  for (int i = 0; i < B2B_PAIR_INFO_LEN + INFO_PAD; ++i) o->info[i] = SENT;
  for (int i = 0; i < B2B_PAIR_NDOF + INFO_PAD; ++i) o->residual[i] = SENT;
  for (int i = 0; i < LDMAX * B2B_PAIR_NDOF; ++i) o->tangent[i] = SENT;
}

static int run_call(pair_call *c, outputs *o, char *msg, int len) {
  const unsigned z = c->null_args;
  return b2b_pair_eval(c->params, (z & A_SEGMENTS) ? NULL : c->g.seg, (z & A_X) ? NULL : c->g.X,
                       (z & A_END_TANGENTS) ? NULL : c->g.tangents,
                       (z & A_RADII) ? NULL : c->g.radii, (z & A_HIST_OLD) ? NULL : c->hist_old,
                       (z & A_HIST_NEW) ? NULL : c->alias ? c->hist_old : o->hist_new,
                       c->hist_len, (z & A_STATUS) ? NULL : &o->status,
                       (z & A_INFO) ? NULL : o->info, (z & A_RESIDUAL) ? NULL : o->residual,
                       (z & A_TANGENT) ? NULL : o->tangent, c->ldk, msg, len);
}

static void assert_untouched(const outputs *o, const char *ctx) {
  TST_ASSERT_ALL(int, i, 0, HMAX, o->hist_new[i] == SENT,
                 "%s: hist_new[%d] was written (%g) on failure", ctx, i, o->hist_new[i]);
  ck_assert_msg(o->status == SENT_INT, "%s: contact_status was written (%d) on failure", ctx,
                o->status);
  TST_ASSERT_ALL(int, i, 0, B2B_PAIR_INFO_LEN + INFO_PAD, o->info[i] == SENT,
                 "%s: info[%d] was written (%g) on failure", ctx, i, o->info[i]);
  TST_ASSERT_ALL(int, i, 0, B2B_PAIR_NDOF + INFO_PAD, o->residual[i] == SENT,
                 "%s: residual[%d] was written (%g) on failure", ctx, i, o->residual[i]);
  TST_ASSERT_ALL(int, i, 0, LDMAX * B2B_PAIR_NDOF, o->tangent[i] == SENT,
                 "%s: tangent[%d] was written (%g) on failure", ctx, i, o->tangent[i]);
}

/* Checks a failed call's message buffer: NUL within len, nothing written
 * from byte len on (the buffer holds `size` bytes), not empty, each word. */
static void check_message(const char *ctx, const char *msg, int len, size_t size, const char *w1,
                          const char *w2, const char *w3) {
  ck_assert_msg(memchr(msg, '\0', (size_t)len) != NULL, "%s: message not NUL-terminated", ctx);
  TST_ASSERT_ALL(size_t, i, (size_t)len, size, msg[i] == GUARD,
                 "%s: message buffer overrun at byte %zu", ctx, i);
  if (len > 1) ck_assert_msg(msg[0] != '\0', "%s: empty message", ctx);
  const char *w[3] = {w1, w2, w3};
  for (int k = 0; k < 3; ++k)
    if (w[k])
      ck_assert_msg(strstr(msg, w[k]) != NULL, "%s: message \"%s\" does not contain \"%s\"", ctx,
                    msg, w[k]);
}

/* b2b_pair_eval must fail with `want`, a message holding each non-NULL word,
 * no output touched and no input changed; again with errmsg NULL, 0 and with
 * an 8-byte buffer. */
static void expect_fail(const char *ctx, pair_call *c, int want, const char *w1, const char *w2,
                        const char *w3) {
  const pair_call before = *c;
  outputs o;
  fill_outputs(&o);
  char msg[B2B_ERRMSG_LEN + 16];
  memset(msg, GUARD, sizeof msg);
  int st = run_call(c, &o, msg, B2B_ERRMSG_LEN);
  ck_assert_msg(st == want, "%s: status %d (%s), expected %d (%s); message: %.*s", ctx, st,
                b2b_strerror(st), want, b2b_strerror(want), B2B_ERRMSG_LEN, msg);
  check_message(ctx, msg, B2B_ERRMSG_LEN, sizeof msg, w1, w2, w3);
  assert_untouched(&o, ctx);
  ck_assert_msg(memcmp(&before, c, sizeof before) == 0, "%s: an input was modified", ctx);

  st = run_call(c, &o, NULL, 0);
  ck_assert_msg(st == want, "%s (errmsg NULL, 0): status %d, expected %d", ctx, st, want);
  assert_untouched(&o, ctx);
  ck_assert_msg(memcmp(&before, c, sizeof before) == 0, "%s: an input was modified", ctx);

  char tiny[16];
  memset(tiny, GUARD, sizeof tiny);
  st = run_call(c, &o, tiny, 8);
  ck_assert_msg(st == want, "%s (errmsg_len 8): status %d, expected %d", ctx, st, want);
  check_message(ctx, tiny, 8, sizeof tiny, NULL, NULL, NULL);
  ck_assert_msg(strncmp(tiny, msg, 7) == 0, "%s: errmsg_len 8 gave \"%s\", not the start of "
                "\"%s\"", ctx, tiny, msg);
  assert_untouched(&o, ctx);
}

/* b2b_pair_eval must succeed, leave the message buffer alone, write finite
 * outputs within their documented sizes only (the history's n entries, info,
 * residual, the 24 x 24 tangent within ldk) and zero the reserved info
 * entries. Returns the contact status. */
static int expect_ok(const char *ctx, pair_call *c, outputs *o) {
  fill_outputs(o);
  char msg[B2B_ERRMSG_LEN];
  memset(msg, GUARD, sizeof msg);
  const int st = run_call(c, o, msg, (int)sizeof msg);
  ck_assert_msg(st == B2B_OK, "%s: status %d (%s): %.*s", ctx, st, b2b_strerror(st),
                (int)sizeof msg, msg);
  TST_ASSERT_ALL(size_t, i, 0, sizeof msg, msg[i] == GUARD,
                 "%s: a successful call wrote errmsg[%zu]", ctx, i);
  ck_assert_msg(o->status >= B2B_CONTACT_OPEN && o->status <= B2B_CONTACT_NO_NORMAL,
                "%s: contact status %d", ctx, o->status);
  const double *hist = c->alias ? c->hist_old : o->hist_new;
  TST_ASSERT_ALL(int, i, 0, c->hist_len, isfinite(hist[i]) && hist[i] != SENT,
                 "%s: hist_new[%d] = %g", ctx, i, hist[i]);
  TST_ASSERT_ALL(int, i, c->alias ? 0 : c->hist_len, HMAX, o->hist_new[i] == SENT,
                 "%s: hist_new[%d] written beyond hist_len", ctx, i);
  TST_ASSERT_ALL(int, i, 0, B2B_PAIR_INFO_LEN, isfinite(o->info[i]) && o->info[i] != SENT,
                 "%s: info[%d] = %g (status %d)", ctx, i, o->info[i], o->status);
  TST_ASSERT_ALL(int, i, B2B_INFO_SYMMETRIC + 1, B2B_PAIR_INFO_LEN, o->info[i] == 0.0,
                 "%s: reserved info[%d] = %g", ctx, i, o->info[i]);
  TST_ASSERT_ALL(int, i, 0, B2B_PAIR_NDOF, isfinite(o->residual[i]) && o->residual[i] != SENT,
                 "%s: residual[%d] = %g", ctx, i, o->residual[i]);
  TST_ASSERT_ALL(int, i, B2B_PAIR_INFO_LEN, B2B_PAIR_INFO_LEN + INFO_PAD, o->info[i] == SENT,
                 "%s: info[%d] written beyond its length", ctx, i);
  TST_ASSERT_ALL(int, i, B2B_PAIR_NDOF, B2B_PAIR_NDOF + INFO_PAD, o->residual[i] == SENT,
                 "%s: residual[%d] written beyond its length", ctx, i);
  const int with_k = !(c->null_args & A_TANGENT);
  for (int i = 0; i < LDMAX * B2B_PAIR_NDOF; ++i) {
    const int col = with_k ? i / c->ldk : B2B_PAIR_NDOF, row = with_k ? i % c->ldk : 0;
    if (col < B2B_PAIR_NDOF && row < B2B_PAIR_NDOF)
      ck_assert_msg(isfinite(o->tangent[i]) && o->tangent[i] != SENT,
                    "%s: tangent(%d, %d) = %g", ctx, row, col, o->tangent[i]);
    else
      ck_assert_msg(o->tangent[i] == SENT, "%s: tangent[%d] written outside the 24 x 24 matrix",
                    ctx, i);
  }
  return o->status;
}

/* Residual and tangent of a force-free pair are exactly zero. */
static void assert_no_force(const char *ctx, const pair_call *c, const outputs *o) {
  ck_assert_msg(o->info[B2B_INFO_NORMAL_FORCE] == 0.0, "%s: normal force %g", ctx,
                o->info[B2B_INFO_NORMAL_FORCE]);
  TST_ASSERT_ALL(int, i, 0, B2B_PAIR_NDOF, o->residual[i] == 0.0,
                 "%s: residual[%d] = %g without force", ctx, i, o->residual[i]);
  if (!(c->null_args & A_TANGENT))
    for (int col = 0; col < B2B_PAIR_NDOF; ++col)
      TST_ASSERT_ALL(int, row, 0, B2B_PAIR_NDOF, o->tangent[row + c->ldk * col] == 0.0,
                     "%s: tangent(%d, %d) = %g without " "force", ctx, row, col, o->tangent[row + c->ldk * col]);
}

/* ===================================================== params helpers */

static char g_msg[B2B_ERRMSG_LEN + 16];

static char *fresh_msg(void) {
  memset(g_msg, GUARD, sizeof g_msg);
  return g_msg;
}

/* The last call (made with fresh_msg(), B2B_ERRMSG_LEN) failed with `want`. */
static void check_failure(const char *ctx, int st, int want, const char *w1, const char *w2,
                          const char *w3) {
  ck_assert_msg(st == want, "%s: status %d (%s), expected %d (%s); message: %.*s", ctx, st,
                b2b_strerror(st), want, b2b_strerror(want), B2B_ERRMSG_LEN, g_msg);
  check_message(ctx, g_msg, B2B_ERRMSG_LEN, sizeof g_msg, w1, w2, w3);
}

/* The last call (made with fresh_msg()) succeeded and left the buffer alone. */
static void check_success(const char *ctx, int st) {
  ck_assert_msg(st == B2B_OK, "%s: status %d (%s): %.*s", ctx, st, b2b_strerror(st),
                B2B_ERRMSG_LEN, g_msg);
  TST_ASSERT_ALL(size_t, i, 0, sizeof g_msg, g_msg[i] == GUARD,
                 "%s: a successful call wrote errmsg[%zu]", ctx, i);
}

static b2b_params *new_params(void) {
  b2b_params *p = NULL;
  check_success("create", b2b_params_create(&p, fresh_msg(), B2B_ERRMSG_LEN));
  ck_assert_ptr_nonnull(p);
  return p;
}

static void assert_real(const b2b_params *p, const char *key, double want, const char *ctx) {
  double v = SENT;
  ck_assert_int_eq(b2b_params_get_real(p, key, &v, NULL, 0), B2B_OK);
  ck_assert_msg(v == want || (v == 0.0 && want == 0.0), "%s: \"%s\" reads %.17g, expected %.17g",
                ctx, key, v, want);
}

static void assert_int(const b2b_params *p, const char *key, int want, const char *ctx) {
  int v = SENT_INT;
  ck_assert_int_eq(b2b_params_get_int(p, key, &v, NULL, 0), B2B_OK);
  ck_assert_msg(v == want, "%s: \"%s\" reads %d, expected %d", ctx, key, v, want);
}

static const char *const real_keys[3] = {"penalty", "regularization_gap", "parallel_angle"};
static const char *const int_keys[3] = {"law", "warm_start", "max_iterations"};

/* ======================================================= params: NULLs */

START_TEST(test_params_null_handle) {
  char ctx[256];
  double v = SENT;
  int iv = SENT_INT;
  CTX("create(NULL)");
  check_failure(ctx, b2b_params_create(NULL, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_NULL,
                "params", "NULL", NULL);
  ck_assert_int_eq(b2b_params_create(NULL, NULL, 0), B2B_ERR_NULL);
  CTX("set_real(NULL)");
  check_failure(ctx, b2b_params_set_real(NULL, "penalty", 1.0, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_NULL, "params", "NULL", NULL);
  ck_assert_int_eq(b2b_params_set_real(NULL, "penalty", 1.0, NULL, 0), B2B_ERR_NULL);
  CTX("set_int(NULL)");
  check_failure(ctx, b2b_params_set_int(NULL, "law", 0, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_NULL, "params", "NULL", NULL);
  ck_assert_int_eq(b2b_params_set_int(NULL, "law", 0, NULL, 0), B2B_ERR_NULL);
  CTX("get_real(NULL)");
  check_failure(ctx, b2b_params_get_real(NULL, "penalty", &v, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_NULL, "params", "NULL", NULL);
  ck_assert_msg(v == SENT, "get_real(NULL) wrote the value");
  ck_assert_int_eq(b2b_params_get_real(NULL, "penalty", &v, NULL, 0), B2B_ERR_NULL);
  CTX("get_int(NULL)");
  check_failure(ctx, b2b_params_get_int(NULL, "law", &iv, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_NULL, "params", "NULL", NULL);
  ck_assert_msg(iv == SENT_INT, "get_int(NULL) wrote the value");
  ck_assert_int_eq(b2b_params_get_int(NULL, "law", &iv, NULL, 0), B2B_ERR_NULL);
  CTX("finalize(NULL)");
  check_failure(ctx, b2b_params_finalize(NULL, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_NULL,
                "params", "NULL", NULL);
  ck_assert_int_eq(b2b_params_finalize(NULL, NULL, 0), B2B_ERR_NULL);
  CTX("history_size(NULL)");
  check_failure(ctx, b2b_params_history_size(NULL, &iv, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_NULL, "params", "NULL", NULL);
  ck_assert_msg(iv == SENT_INT, "history_size(NULL) wrote n");
  ck_assert_int_eq(b2b_params_history_size(NULL, &iv, NULL, 0), B2B_ERR_NULL);

  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  CTX("history_size(p, NULL)");
  check_failure(ctx, b2b_params_history_size(p, NULL, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_NULL,
                "n is NULL", NULL, NULL);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(test_params_null_key_value) {
  char ctx[256];
  b2b_params *p = new_params();
  double v = SENT;
  int iv = SENT_INT;
  CTX("set_real key NULL");
  check_failure(ctx, b2b_params_set_real(p, NULL, 1.0, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_NULL, "key", "NULL", NULL);
  CTX("set_int key NULL");
  check_failure(ctx, b2b_params_set_int(p, NULL, 0, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_NULL,
                "key", "NULL", NULL);
  CTX("get_real key NULL");
  check_failure(ctx, b2b_params_get_real(p, NULL, &v, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_NULL,
                "key", "NULL", NULL);
  ck_assert(v == SENT);
  CTX("get_int key NULL");
  check_failure(ctx, b2b_params_get_int(p, NULL, &iv, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_NULL,
                "key", "NULL", NULL);
  ck_assert(iv == SENT_INT);
  for (int k = 0; k < 3; ++k) {
    CTX("get_real(\"%s\") value NULL", real_keys[k]);
    check_failure(ctx, b2b_params_get_real(p, real_keys[k], NULL, fresh_msg(), B2B_ERRMSG_LEN),
                  B2B_ERR_NULL, "value", "NULL", NULL);
    ck_assert_int_eq(b2b_params_get_real(p, real_keys[k], NULL, NULL, 0), B2B_ERR_NULL);
    CTX("get_int(\"%s\") value NULL", int_keys[k]);
    check_failure(ctx, b2b_params_get_int(p, int_keys[k], NULL, fresh_msg(), B2B_ERRMSG_LEN),
                  B2B_ERR_NULL, "value", "NULL", NULL);
    ck_assert_int_eq(b2b_params_get_int(p, int_keys[k], NULL, NULL, 0), B2B_ERR_NULL);
  }
  /* Nothing was set: the handle still lacks its penalty. */
  ck_assert_int_eq(b2b_params_finalize(p, NULL, 0), B2B_ERR_STATE);
  b2b_params_destroy(&p);
}
END_TEST

/* =================================================== params: keys */

/* A message for an unknown key names it (in quotes) and lists every key of
 * that type. */
static void check_unknown_key(const char *ctx, int st, const char *key, int real) {
  char quoted[128];
  snprintf(quoted, sizeof quoted, "\"%s\"", key);
  check_failure(ctx, st, B2B_ERR_UNKNOWN_KEY, quoted, NULL, NULL);
  const char *const *known = real ? real_keys : int_keys;
  TST_ASSERT_ALL(int, k, 0, 3, strstr(g_msg, known[k]) != NULL,
                 "%s: message \"%s\" does not list \"%s\"", ctx, g_msg, known[k]);
}

START_TEST(test_params_unknown_key) {
  const char *const bad[] = {"bogus", "", "Penalty", "penalty ", " law", "max_iter", "LAW",
                             "regularisation_gap", "parallel-angle"};
  char ctx[256];
  b2b_params *p = new_params();
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    double v = SENT;
    int iv = SENT_INT;
    CTX("set_real(\"%s\")", bad[k]);
    check_unknown_key(ctx, b2b_params_set_real(p, bad[k], 1.0, fresh_msg(), B2B_ERRMSG_LEN),
                      bad[k], 1);
    ck_assert_int_eq(b2b_params_set_real(p, bad[k], 1.0, NULL, 0), B2B_ERR_UNKNOWN_KEY);
    /* the key is checked before the value */
    ck_assert_int_eq(b2b_params_set_real(p, bad[k], NAN, NULL, 0), B2B_ERR_UNKNOWN_KEY);
    CTX("set_int(\"%s\")", bad[k]);
    check_unknown_key(ctx, b2b_params_set_int(p, bad[k], 1, fresh_msg(), B2B_ERRMSG_LEN), bad[k],
                      0);
    ck_assert_int_eq(b2b_params_set_int(p, bad[k], 1, NULL, 0), B2B_ERR_UNKNOWN_KEY);
    CTX("get_real(\"%s\")", bad[k]);
    check_unknown_key(ctx, b2b_params_get_real(p, bad[k], &v, fresh_msg(), B2B_ERRMSG_LEN),
                      bad[k], 1);
    ck_assert_msg(v == SENT, "%s: value written", ctx);
    CTX("get_int(\"%s\")", bad[k]);
    check_unknown_key(ctx, b2b_params_get_int(p, bad[k], &iv, fresh_msg(), B2B_ERRMSG_LEN),
                      bad[k], 0);
    ck_assert_msg(iv == SENT_INT, "%s: value written", ctx);
  }
  /* The same on a finalized handle for the getters. */
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", PEN, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_finalize(p, NULL, 0), B2B_OK);
  double v = SENT;
  CTX("finalized: get_real(\"bogus\")");
  check_unknown_key(ctx, b2b_params_get_real(p, "bogus", &v, fresh_msg(), B2B_ERRMSG_LEN),
                    "bogus", 1);
  ck_assert(v == SENT);
  b2b_params_destroy(&p);
}
END_TEST

/* A real key through the integer functions (and vice versa) is an unknown
 * key of that type; the value is not touched. */
START_TEST(test_params_key_of_other_type) {
  char ctx[256];
  b2b_params *p = new_params();
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", 7.0, NULL, 0), B2B_OK);
  for (int k = 0; k < 3; ++k) {
    double v = SENT;
    int iv = SENT_INT;
    CTX("set_int(\"%s\")", real_keys[k]);
    check_unknown_key(ctx, b2b_params_set_int(p, real_keys[k], 1, fresh_msg(), B2B_ERRMSG_LEN),
                      real_keys[k], 0);
    CTX("get_int(\"%s\")", real_keys[k]);
    check_unknown_key(ctx, b2b_params_get_int(p, real_keys[k], &iv, fresh_msg(), B2B_ERRMSG_LEN),
                      real_keys[k], 0);
    ck_assert(iv == SENT_INT);
    CTX("set_real(\"%s\")", int_keys[k]);
    check_unknown_key(ctx, b2b_params_set_real(p, int_keys[k], 1.0, fresh_msg(), B2B_ERRMSG_LEN),
                      int_keys[k], 1);
    CTX("get_real(\"%s\")", int_keys[k]);
    check_unknown_key(ctx, b2b_params_get_real(p, int_keys[k], &v, fresh_msg(), B2B_ERRMSG_LEN),
                      int_keys[k], 1);
    ck_assert(v == SENT);
  }
  assert_real(p, "penalty", 7.0, "after the wrong-type calls");
  assert_real(p, "parallel_angle", 0.5, "after the wrong-type calls");
  assert_int(p, "law", B2B_LAW_LINEAR, "after the wrong-type calls");
  assert_int(p, "warm_start", 0, "after the wrong-type calls");
  assert_int(p, "max_iterations", 50, "after the wrong-type calls");
  b2b_params_destroy(&p);
}
END_TEST

/* A key far longer than the message buffer: the message is cut, still
 * NUL-terminated within B2B_ERRMSG_LEN, and nothing beyond is written. */
START_TEST(test_params_long_unknown_key) {
  char key[1000];
  memset(key, 'k', sizeof key - 1);
  key[sizeof key - 1] = '\0';
  b2b_params *p = new_params();
  double v = SENT;
  int iv = SENT_INT;
  /* The key is echoed shortened, so the whole message (up to the list of
   * keys and its closing parenthesis) fits in B2B_ERRMSG_LEN, as b2b.h says. */
  check_failure("set_real(long key)",
                b2b_params_set_real(p, key, 1.0, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_UNKNOWN_KEY, "kkkkkkkk", "\"point_angle\")", NULL);
  check_failure("set_int(long key)", b2b_params_set_int(p, key, 1, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_UNKNOWN_KEY, "kkkkkkkk", "\"line_points\")", NULL);
  check_failure("get_real(long key)",
                b2b_params_get_real(p, key, &v, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_UNKNOWN_KEY, "kkkkkkkk", "\"point_angle\")", NULL);
  check_failure("get_int(long key)", b2b_params_get_int(p, key, &iv, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_UNKNOWN_KEY, "kkkkkkkk", "\"line_points\")", NULL);
  ck_assert(v == SENT && iv == SENT_INT);
  /* A key set after a finalize names a long key the same way. */
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", PEN, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_finalize(p, NULL, 0), B2B_OK);
  check_failure("finalized: set_real(long key)",
                b2b_params_set_real(p, key, 1.0, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_STATE,
                "finalized", NULL, NULL);
  b2b_params_destroy(&p);
}
END_TEST

/* ================================================= params: values */

/* The value a key holds before each bad set (set first, so a change shows). */
static const double real_before[3] = {3.0, 0.25, 1.5};

START_TEST(test_params_nonfinite) {
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  char ctx[256];
  b2b_params *p = new_params();
  for (int k = 0; k < 3; ++k) {
    ck_assert_int_eq(b2b_params_set_real(p, real_keys[k], real_before[k], NULL, 0), B2B_OK);
    for (int v = 0; v < 3; ++v) {
      CTX("set_real(\"%s\", %g)", real_keys[k], bad[v]);
      check_failure(ctx, b2b_params_set_real(p, real_keys[k], bad[v], fresh_msg(),
                                             B2B_ERRMSG_LEN),
                    B2B_ERR_NONFINITE, real_keys[k], "finite", isnan(bad[v]) ? "nan" : "inf");
      ck_assert_int_eq(b2b_params_set_real(p, real_keys[k], bad[v], NULL, 0), B2B_ERR_NONFINITE);
      assert_real(p, real_keys[k], real_before[k], ctx);
    }
  }
  b2b_params_destroy(&p);
}
END_TEST

/* A penalty that failed to set does not count as set. */
START_TEST(test_params_failed_penalty_not_set) {
  const double bad[] = {-1.0, NAN, INFINITY};
  char ctx[256];
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    b2b_params *p = new_params();
    ck_assert_int_ne(b2b_params_set_real(p, "penalty", bad[k], NULL, 0), B2B_OK);
    CTX("finalize after set_real(\"penalty\", %g) failed", bad[k]);
    check_failure(ctx, b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_STATE,
                  "penalty", NULL, NULL);
    int n = SENT_INT;
    ck_assert_int_eq(b2b_params_history_size(p, &n, NULL, 0), B2B_ERR_STATE);
    ck_assert_int_eq(n, SENT_INT);
    b2b_params_destroy(&p);
  }
}
END_TEST

typedef struct {
  const char *key;
  double value;
} real_case;

START_TEST(test_params_real_range) {
  const real_case bad[] = {
      {"penalty", -1.0},
      {"penalty", -1e-300},
      {"penalty", -4.9406564584124654e-324},
      {"penalty", -DBL_MAX},
      {"regularization_gap", 0.0},
      {"regularization_gap", -0.0},
      {"regularization_gap", -1.0},
      {"regularization_gap", -DBL_MIN},
      {"parallel_angle", -1.0},
      {"parallel_angle", -1e-12},
      {"parallel_angle", 90.0},
      {"parallel_angle", 90.0000001},
      {"parallel_angle", 180.0},
      {"parallel_angle", 1e300},
  };
  char ctx[256];
  b2b_params *p = new_params();
  for (int k = 0; k < 3; ++k)
    ck_assert_int_eq(b2b_params_set_real(p, real_keys[k], real_before[k], NULL, 0), B2B_OK);
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    int key = 0;
    while (strcmp(real_keys[key], bad[k].key) != 0) ++key;
    CTX("set_real(\"%s\", %.17g)", bad[k].key, bad[k].value);
    check_failure(ctx, b2b_params_set_real(p, bad[k].key, bad[k].value, fresh_msg(),
                                           B2B_ERRMSG_LEN),
                  B2B_ERR_RANGE, bad[k].key, NULL, NULL);
    ck_assert_int_eq(b2b_params_set_real(p, bad[k].key, bad[k].value, NULL, 0), B2B_ERR_RANGE);
    assert_real(p, bad[k].key, real_before[key], ctx);
  }
  b2b_params_destroy(&p);
}
END_TEST

typedef struct {
  const char *key;
  int value, want;
} int_case;

START_TEST(test_params_int_range) {
  const int_case bad[] = {
      {"warm_start", 2, B2B_ERR_RANGE},        {"warm_start", -1, B2B_ERR_RANGE},
      {"warm_start", INT_MAX, B2B_ERR_RANGE},  {"warm_start", INT_MIN, B2B_ERR_RANGE},
      {"max_iterations", 0, B2B_ERR_RANGE},    {"max_iterations", -1, B2B_ERR_RANGE},
      {"max_iterations", INT_MIN, B2B_ERR_RANGE}, {"max_iterations", INT_MAX, B2B_ERR_RANGE},
      {"max_iterations", 1000000000, B2B_ERR_RANGE},
      {"law", B2B_LAW_COUNT, B2B_ERR_UNKNOWN_KIND}, {"law", -1, B2B_ERR_UNKNOWN_KIND},
      {"law", INT_MAX, B2B_ERR_UNKNOWN_KIND},  {"law", INT_MIN, B2B_ERR_UNKNOWN_KIND},
  };
  char ctx[256], num[32];
  b2b_params *p = new_params();
  ck_assert_int_eq(b2b_params_set_int(p, "warm_start", 1, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "max_iterations", 7, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "law", B2B_LAW_QUADRATIC, NULL, 0), B2B_OK);
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    snprintf(num, sizeof num, "%d", bad[k].value);
    CTX("set_int(\"%s\", %d)", bad[k].key, bad[k].value);
    check_failure(ctx, b2b_params_set_int(p, bad[k].key, bad[k].value, fresh_msg(),
                                          B2B_ERRMSG_LEN),
                  bad[k].want, bad[k].key, num, NULL);
    ck_assert_int_eq(b2b_params_set_int(p, bad[k].key, bad[k].value, NULL, 0), bad[k].want);
    assert_int(p, "warm_start", 1, ctx);
    assert_int(p, "max_iterations", 7, ctx);
    assert_int(p, "law", B2B_LAW_QUADRATIC, ctx);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* The closest values that are valid, and the documented defaults. */
START_TEST(test_params_valid_bounds) {
  char ctx[256];
  b2b_params *p = new_params();
  assert_real(p, "parallel_angle", 0.5, "default");
  assert_int(p, "law", B2B_LAW_LINEAR, "default");
  assert_int(p, "warm_start", 0, "default");
  assert_int(p, "max_iterations", 50, "default");
  const real_case good[] = {
      {"penalty", 0.0},           {"penalty", -0.0},
      {"penalty", DBL_MAX},       {"penalty", 4.9406564584124654e-324},
      {"regularization_gap", DBL_MIN}, {"regularization_gap", 4.9406564584124654e-324},
      {"regularization_gap", 1e300},   {"parallel_angle", 0.0},
      {"parallel_angle", 89.99999999999999}, {"parallel_angle", 45.0},
  };
  for (size_t k = 0; k < sizeof good / sizeof good[0]; ++k) {
    CTX("set_real(\"%s\", %.17g)", good[k].key, good[k].value);
    check_success(ctx, b2b_params_set_real(p, good[k].key, good[k].value, fresh_msg(),
                                           B2B_ERRMSG_LEN));
    assert_real(p, good[k].key, good[k].value, ctx);
  }
  const int_case goodi[] = {{"warm_start", 0, 0},     {"warm_start", 1, 0},
                            {"max_iterations", 1, 0}, {"max_iterations", 1000, 0},
                            {"law", B2B_LAW_QUADRATIC, 0}, {"law", B2B_LAW_LINEAR, 0}};
  for (size_t k = 0; k < sizeof goodi / sizeof goodi[0]; ++k) {
    CTX("set_int(\"%s\", %d)", goodi[k].key, goodi[k].value);
    check_success(ctx, b2b_params_set_int(p, goodi[k].key, goodi[k].value, fresh_msg(),
                                          B2B_ERRMSG_LEN));
    assert_int(p, goodi[k].key, goodi[k].value, ctx);
  }
  check_success("finalize", b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN));
  b2b_params_destroy(&p);
}
END_TEST

/* =============================================== params: state */

START_TEST(test_params_finalize_without_penalty) {
  b2b_params *p = new_params();
  check_failure("finalize without penalty", b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_STATE, "penalty", NULL, NULL);
  ck_assert_int_eq(b2b_params_finalize(p, NULL, 0), B2B_ERR_STATE);
  /* Other keys do not replace it. */
  ck_assert_int_eq(b2b_params_set_real(p, "regularization_gap", 0.1, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "max_iterations", 20, NULL, 0), B2B_OK);
  check_failure("finalize without penalty (other keys set)",
                b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_STATE, "penalty",
                NULL, NULL);
  /* A failed finalize leaves the handle settable; then it finalizes. */
  check_success("set penalty after a failed finalize",
                b2b_params_set_real(p, "penalty", PEN, fresh_msg(), B2B_ERRMSG_LEN));
  check_success("finalize", b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN));
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(test_params_quadratic_without_gap) {
  b2b_params *p = new_params();
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", PEN, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "law", B2B_LAW_QUADRATIC, NULL, 0), B2B_OK);
  check_failure("quadratic law without regularization_gap",
                b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_STATE,
                "regularization_gap", NULL, NULL);
  /* A failed set of the gap does not count either. */
  ck_assert_int_eq(b2b_params_set_real(p, "regularization_gap", 0.0, NULL, 0), B2B_ERR_RANGE);
  check_failure("quadratic law after a failed regularization_gap",
                b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_STATE,
                "regularization_gap", NULL, NULL);
  int n = SENT_INT;
  ck_assert_int_eq(b2b_params_history_size(p, &n, NULL, 0), B2B_ERR_STATE);
  ck_assert_int_eq(n, SENT_INT);
  /* The linear law does not need it. */
  ck_assert_int_eq(b2b_params_set_int(p, "law", B2B_LAW_LINEAR, NULL, 0), B2B_OK);
  check_success("linear law without regularization_gap",
                b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN));
  b2b_params_destroy(&p);
}
END_TEST

/* Every set after finalize is B2B_ERR_STATE naming the key, and the value
 * reads back unchanged; so is a set of an invalid or unknown value. */
START_TEST(test_params_set_after_finalize) {
  char ctx[256];
  b2b_params *p = tst_params(B2B_LAW_QUADRATIC, PEN, 0.02);
  ck_assert_int_eq(b2b_params_finalize(p, NULL, 0), B2B_OK); /* finalizing twice is harmless */
  const double new_real[3] = {5.0, 0.5, 10.0};
  const int new_int[3] = {B2B_LAW_LINEAR, 1, 10};
  const double old_real[3] = {PEN, 0.02, 0.5};
  const int old_int[3] = {B2B_LAW_QUADRATIC, 0, 50};
  for (int k = 0; k < 3; ++k) {
    char quoted[64];
    snprintf(quoted, sizeof quoted, "\"%s\"", real_keys[k]);
    CTX("finalized: set_real(\"%s\", %g)", real_keys[k], new_real[k]);
    check_failure(ctx, b2b_params_set_real(p, real_keys[k], new_real[k], fresh_msg(),
                                           B2B_ERRMSG_LEN),
                  B2B_ERR_STATE, "finalized", quoted, NULL);
    ck_assert_int_eq(b2b_params_set_real(p, real_keys[k], new_real[k], NULL, 0), B2B_ERR_STATE);
    CTX("finalized: set_real(\"%s\", -1)", real_keys[k]);
    ck_assert_int_eq(b2b_params_set_real(p, real_keys[k], -1.0, NULL, 0), B2B_ERR_STATE);
    assert_real(p, real_keys[k], old_real[k], ctx);

    snprintf(quoted, sizeof quoted, "\"%s\"", int_keys[k]);
    CTX("finalized: set_int(\"%s\", %d)", int_keys[k], new_int[k]);
    check_failure(ctx, b2b_params_set_int(p, int_keys[k], new_int[k], fresh_msg(),
                                          B2B_ERRMSG_LEN),
                  B2B_ERR_STATE, "finalized", quoted, NULL);
    ck_assert_int_eq(b2b_params_set_int(p, int_keys[k], new_int[k], NULL, 0), B2B_ERR_STATE);
    ck_assert_int_eq(b2b_params_set_int(p, int_keys[k], -7, NULL, 0), B2B_ERR_STATE);
    assert_int(p, int_keys[k], old_int[k], ctx);
  }
  check_failure("finalized: set_real(\"bogus\")",
                b2b_params_set_real(p, "bogus", 1.0, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_STATE,
                "finalized", NULL, NULL);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(test_params_history_size_before_finalize) {
  b2b_params *p = new_params();
  int n = SENT_INT;
  check_failure("history_size on a new handle",
                b2b_params_history_size(p, &n, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_STATE,
                "finalized", NULL, NULL);
  ck_assert_int_eq(n, SENT_INT);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", PEN, NULL, 0), B2B_OK);
  check_failure("history_size with the penalty set",
                b2b_params_history_size(p, &n, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_STATE,
                "finalized", NULL, NULL);
  ck_assert_int_eq(b2b_params_history_size(p, &n, NULL, 0), B2B_ERR_STATE);
  ck_assert_int_eq(n, SENT_INT);
  ck_assert_int_eq(b2b_params_finalize(p, NULL, 0), B2B_OK);
  check_success("history_size", b2b_params_history_size(p, &n, fresh_msg(), B2B_ERRMSG_LEN));
  ck_assert_int_ge(n, 1);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(test_params_destroy) {
  ck_assert_int_eq(b2b_params_destroy(NULL), B2B_OK);
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_destroy(&p), B2B_OK);
  ck_assert_ptr_null(p);
  p = new_params();
  ck_assert_int_eq(b2b_params_destroy(&p), B2B_OK);
  ck_assert_ptr_null(p);
  ck_assert_int_eq(b2b_params_destroy(&p), B2B_OK); /* twice: the second is a no-op */
  ck_assert_ptr_null(p);
  p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  ck_assert_int_eq(b2b_params_destroy(&p), B2B_OK);
  ck_assert_ptr_null(p);
}
END_TEST

/* ================================================ params: penalties */

/* Zero penalty is valid: the pair is evaluated but carries no force. */
START_TEST(test_zero_penalty) {
  const int law = _i;
  char ctx[256];
  b2b_params *p = new_params();
  check_success("penalty 0", b2b_params_set_real(p, "penalty", 0.0, fresh_msg(), B2B_ERRMSG_LEN));
  ck_assert_int_eq(b2b_params_set_int(p, "law", law, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "regularization_gap", 0.02, NULL, 0), B2B_OK);
  check_success("finalize with penalty 0", b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN));
  pair_call c;
  outputs o;
  base_call(&c, p);
  CTX("law %d, penalty 0", law);
  const int st = expect_ok(ctx, &c, &o);
  ck_assert_msg(st == B2B_CONTACT_OPEN, "%s: contact status %d, expected OPEN", ctx, st);
  assert_no_force(ctx, &c, &o);
  ck_assert_msg(o.info[B2B_INFO_ENERGY] == 0.0, "%s: energy %g", ctx, o.info[B2B_INFO_ENERGY]);
  ck_assert_msg(fabs(o.info[B2B_INFO_GAP] - (DIST - 2 * RADIUS)) < 1e-12, "%s: gap %g", ctx,
                o.info[B2B_INFO_GAP]);
  b2b_params_destroy(&p);
}
END_TEST

/* A huge penalty on the base crossing: finite outputs or a clear status with
 * nothing written; never NaN or Inf with B2B_OK. Loop index: penalty and law. */
START_TEST(test_huge_penalty) {
  const double pens[3] = {1e200, 1e300, DBL_MAX};
  const double pen = pens[_i % 3];
  const int law = _i / 3;
  char ctx[256];
  b2b_params *p = tst_params(law, pen, 0.02);
  pair_call c;
  base_call(&c, p);
  outputs o;
  fill_outputs(&o);
  char msg[B2B_ERRMSG_LEN] = "";
  CTX("law %d, penalty %g", law, pen);
  const int st = run_call(&c, &o, msg, (int)sizeof msg);
  if (st != B2B_OK) {
    ck_assert_msg(st == B2B_ERR_RANGE, "%s: status %d (%s): %s", ctx, st, b2b_strerror(st), msg);
    ck_assert_msg(msg[0] != '\0', "%s: no message", ctx);
    assert_untouched(&o, ctx);
  } else {
    expect_ok(ctx, &c, &o);
    ck_assert_int_eq(o.status, B2B_CONTACT_ACTIVE);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* The same with a deep penetration at a large (valid) coordinate scale:
 * 0.5 eps g^2 overflows. b2b must say so, not return B2B_OK with Inf.
 * Loop index: {penalty 1e300, scale 1e6}, {penalty 1e200, scale 1e60}. */
START_TEST(test_huge_penalty_deep_penetration) {
  const double pen = _i == 0 ? 1e300 : 1e200, scale = _i == 0 ? 1e6 : 1e60;
  char ctx[256];
  b2b_params *p = tst_params(B2B_LAW_LINEAR, pen, 0.0);
  pair_call c;
  base_call(&c, p);
  scale_geometry(&c.g, scale, 0.0);
  outputs o;
  fill_outputs(&o);
  char msg[B2B_ERRMSG_LEN] = "";
  CTX("penalty %g, base crossing scaled by %g (gap %g)", pen, scale,
      (DIST - 2 * RADIUS) * scale);
  const int st = run_call(&c, &o, msg, (int)sizeof msg);
  if (st != B2B_OK) {
    ck_assert_msg(st == B2B_ERR_RANGE, "%s: status %d (%s): %s", ctx, st, b2b_strerror(st), msg);
    assert_untouched(&o, ctx);
  } else {
    expect_ok(ctx, &c, &o);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* ===================================================== pair: state */

START_TEST(test_pair_base_is_active) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  pair_call c;
  outputs o;
  base_call(&c, p);
  ck_assert_int_eq(expect_ok("base", &c, &o), B2B_CONTACT_ACTIVE);
  ck_assert_msg(fabs(o.info[B2B_INFO_GAP] - (DIST - 2 * RADIUS)) < 1e-12, "base: gap %g",
                o.info[B2B_INFO_GAP]);
  ck_assert(fabs(o.info[B2B_INFO_XI]) < 0.5 && fabs(o.info[B2B_INFO_ETA]) < 0.5);
  ck_assert(o.info[B2B_INFO_NORMAL + 2] > 0.999);
  ck_assert(tst_max_abs(o.residual, 24) > 0.0);
  /* Without the tangent, and with a larger leading dimension. */
  c.null_args = A_TANGENT;
  outputs o2;
  ck_assert_int_eq(expect_ok("base without tangent", &c, &o2), B2B_CONTACT_ACTIVE);
  ck_assert(memcmp(o.residual, o2.residual, sizeof o.residual) == 0);
  c.null_args = 0;
  c.ldk = LDMAX;
  ck_assert_int_eq(expect_ok("base with ldk 30", &c, &o2), B2B_CONTACT_ACTIVE);
  for (int col = 0; col < 24; ++col)
    for (int row = 0; row < 24; ++row)
      ck_assert(o2.tangent[row + LDMAX * col] == o.tangent[row + 24 * col]);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(test_pair_params_null) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  pair_call c;
  base_call(&c, p);
  c.params = NULL;
  expect_fail("params NULL", &c, B2B_ERR_NULL, "params", "NULL", NULL);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(test_pair_params_not_finalized) {
  b2b_params *fin = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  b2b_params *p = new_params();
  pair_call c;
  base_call(&c, fin);
  c.params = p;
  expect_fail("params not finalized (new)", &c, B2B_ERR_STATE, "finalized", NULL, NULL);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", PEN, NULL, 0), B2B_OK);
  expect_fail("params not finalized (penalty set)", &c, B2B_ERR_STATE, "finalized", NULL, NULL);
  ck_assert_int_eq(b2b_params_set_int(p, "law", B2B_LAW_QUADRATIC, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_finalize(p, NULL, 0), B2B_ERR_STATE);
  expect_fail("params whose finalize failed", &c, B2B_ERR_STATE, "finalized", NULL, NULL);
  b2b_params_destroy(&p);
  b2b_params_destroy(&fin);
}
END_TEST

/* ===================================================== pair: NULLs */

static const struct {
  unsigned bit;
  const char *name;
} null_args[] = {
    {A_SEGMENTS, "segments"},         {A_X, "X is NULL"},      {A_RADII, "radii"},
    {A_HIST_OLD, "hist_old"},         {A_HIST_NEW, "hist_new"}, {A_STATUS, "contact_status"},
    {A_INFO, "info"},                 {A_RESIDUAL, "residual"},
};
#define N_NULL_ARGS ((int)(sizeof null_args / sizeof null_args[0]))

START_TEST(test_pair_null_argument) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  pair_call c;
  base_call(&c, p);
  char ctx[256];
  c.null_args = null_args[_i].bit;
  CTX("%s NULL", null_args[_i].name);
  expect_fail(ctx, &c, B2B_ERR_NULL, null_args[_i].name, "NULL", NULL);
  /* Also without a tangent, and with hist_new aliasing hist_old. */
  c.null_args |= A_TANGENT;
  expect_fail(ctx, &c, B2B_ERR_NULL, null_args[_i].name, "NULL", NULL);
  c.null_args = null_args[_i].bit;
  c.alias = 1;
  expect_fail(ctx, &c, B2B_ERR_NULL, null_args[_i].name, "NULL", NULL);
  b2b_params_destroy(&p);
}
END_TEST

/* end_tangents NULL is an error exactly when a rule in force is TANGENT
 * (LINEAR ignores its rules). Loop index: the beam under test; the other
 * beam has no TANGENT rule. */
START_TEST(test_pair_null_end_tangents) {
  const int b = _i;
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  int n_fail = 0;
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
    for (int sr = NB; sr <= TG; ++sr)
      for (int er = NB; er <= TG; ++er) {
        if (!valid_rules(kind, sr, er)) continue;
        int seg[6] = {NOD, NB, NB, NDW, NB, RF};
        seg[3 * b] = kind;
        seg[3 * b + 1] = sr;
        seg[3 * b + 2] = er;
        pair_call c;
        outputs o;
        base_call(&c, p);
        make_geometry(seg, 90.0, BEND, DIST, &c.g);
        c.null_args = A_END_TANGENTS;
        CTX("%s %s (%s, %s): end_tangents NULL", beam_name[b], tst_kind_name(kind),
            rule_name(sr), rule_name(er));
        if (tangent_in_force(kind, sr, er)) {
          expect_fail(ctx, &c, B2B_ERR_NULL, beam_name[b], "end_tangents", "TANGENT");
          ++n_fail;
        } else {
          ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
        }
      }
  ck_assert_int_eq(n_fail, 2 + 5 + 5);
  b2b_params_destroy(&p);
}
END_TEST

/* ======================================================= pair: ldk */

START_TEST(test_pair_ldk) {
  const int bad[] = {23, 0, -1, 1, INT_MIN};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256], num[32];
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    pair_call c;
    outputs o;
    base_call(&c, p);
    c.ldk = bad[k];
    snprintf(num, sizeof num, "%d", bad[k]);
    CTX("tangent with ldk %d", bad[k]);
    expect_fail(ctx, &c, B2B_ERR_SIZE, "ldk", num, NULL);
    /* Without a tangent, ldk is not used. */
    c.null_args = A_TANGENT;
    CTX("tangent NULL with ldk %d", bad[k]);
    ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  }
  for (int ldk = 24; ldk <= LDMAX; ++ldk) {
    pair_call c;
    outputs o;
    base_call(&c, p);
    c.ldk = ldk;
    CTX("ldk %d", ldk);
    ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* ================================================ pair: kinds, rules */

START_TEST(test_pair_unknown_kind) {
  const int b = _i;
  const int bad[] = {-1, B2B_CURVE_KIND_COUNT, 1000, INT_MIN, INT_MAX};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256], num[32];
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    pair_call c;
    base_call(&c, p);
    c.g.seg[3 * b] = bad[k];
    snprintf(num, sizeof num, "%d", bad[k]);
    CTX("%s: kind %d", beam_name[b], bad[k]);
    expect_fail(ctx, &c, B2B_ERR_UNKNOWN_KIND, beam_name[b], "kind", num);
  }
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(test_pair_unknown_rule) {
  const int b = _i;
  const int bad[] = {3, -1, 1000, INT_MIN, INT_MAX};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256], num[32];
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k)
    for (int which = 1; which <= 2; ++which) {
      pair_call c;
      base_call(&c, p);
      c.g.seg[3 * b + which] = bad[k];
      snprintf(num, sizeof num, "%d", bad[k]);
      CTX("%s: %s %d", beam_name[b], which == 1 ? "start_rule" : "end_rule", bad[k]);
      expect_fail(ctx, &c, B2B_ERR_UNKNOWN_KIND, beam_name[b],
                  which == 1 ? "start_rule" : "end_rule", num);
      /* LINEAR ignores its rules' meaning, not their validity. */
      c.g.seg[3 * b] = LIN;
      expect_fail(ctx, &c, B2B_ERR_UNKNOWN_KIND, beam_name[b],
                  which == 1 ? "start_rule" : "end_rule", num);
    }
  b2b_params_destroy(&p);
}
END_TEST

/* A midpoint segment that both starts and ends its beam, as for
 * b2b_segment_eval. */
START_TEST(test_pair_midpoint_both_ends) {
  const int b = _i;
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  pair_call c;
  base_call(&c, p);
  c.g.seg[3 * b] = MID;
  c.g.seg[3 * b + 1] = RF;
  c.g.seg[3 * b + 2] = TG;
  char ctx[256];
  CTX("%s: midpoint (REFLECT, TANGENT)", beam_name[b]);
  expect_fail(ctx, &c, B2B_ERR_RANGE, beam_name[b], "B2B_CURVE_HERMITE_MIDPOINT", "centred");
  b2b_params_destroy(&p);
}
END_TEST

/* ================================================ pair: coordinates */

/* Every kind and rule combination of beam b (the other beam as in the base),
 * each bad value in each coordinate of each slot it reads. Returns the number
 * of cases. */
static int bad_coordinate_cases(const b2b_params *p, int b, const double *bad, int n_bad,
                                int want, const char *word) {
  char ctx[256], node[8];
  int n_cases = 0;
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
    for (int sr = NB; sr <= TG; ++sr)
      for (int er = NB; er <= TG; ++er) {
        if (!valid_rules(kind, sr, er)) continue;
        int seg[6];
        memcpy(seg, base_seg, sizeof seg);
        seg[3 * b] = kind;
        seg[3 * b + 1] = sr;
        seg[3 * b + 2] = er;
        pair_call c0;
        outputs o;
        base_call(&c0, p);
        make_geometry(seg, 90.0, BEND, DIST, &c0.g);
        CTX("%s %s (%s, %s): valid", beam_name[b], tst_kind_name(kind), rule_name(sr),
            rule_name(er));
        ck_assert_int_eq(expect_ok(ctx, &c0, &o), B2B_CONTACT_ACTIVE);
        const unsigned used = used_slots(kind, sr, er);
        for (int slot = 0; slot < 4; ++slot) {
          if (!(used & (1u << slot))) continue;
          snprintf(node, sizeof node, "x%d", slot + 1);
          for (int axis = 0; axis < 3; ++axis)
            for (int v = 0; v < n_bad; ++v) {
              pair_call c = c0;
              c.g.X[12 * b + 3 * slot + axis] = bad[v];
              CTX("%s %s (%s, %s): %c of %s = %.17g", beam_name[b], tst_kind_name(kind),
                  rule_name(sr), rule_name(er), "xyz"[axis], node, bad[v]);
              expect_fail(ctx, &c, want, beam_name[b], node, word);
              ++n_cases;
            }
        }
      }
  return n_cases;
}

START_TEST(test_pair_nonfinite_coordinate) {
  const int b = _i;
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  const int n = bad_coordinate_cases(p, b, bad, 3, B2B_ERR_NONFINITE, "finite");
  /* used slots x axes x values: linear 9 x 2, midpoint 3 + 4 x 2, nodal
   * kinds 36 - 6 - 6 each; times 3 axes and 3 values */
  ck_assert_int_eq(n, (18 + 11 + 24 + 24) * 9);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(test_pair_coordinate_beyond_max) {
  const int b = _i;
  const double bad[] = {2e100, -2e100, DBL_MAX, -DBL_MAX, nextafter(B2B_COORD_MAX, INFINITY)};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  ck_assert_int_gt(bad_coordinate_cases(p, b, bad, (int)(sizeof bad / sizeof bad[0]),
                                        B2B_ERR_RANGE, "B2B_COORD_MAX"),
                   0);
  b2b_params_destroy(&p);
}
END_TEST

/* Anything in a slot the kind does not read changes nothing. */
START_TEST(test_pair_unused_slots) {
  const int b = _i;
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  int n_unused = 0;
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
    for (int sr = NB; sr <= TG; ++sr)
      for (int er = NB; er <= TG; ++er) {
        if (!valid_rules(kind, sr, er)) continue;
        int seg[6];
        memcpy(seg, base_seg, sizeof seg);
        seg[3 * b] = kind;
        seg[3 * b + 1] = sr;
        seg[3 * b + 2] = er;
        pair_call c0;
        static outputs ref, o;
        base_call(&c0, p);
        make_geometry(seg, 90.0, BEND, DIST, &c0.g);
        CTX("%s %s (%s, %s): reference", beam_name[b], tst_kind_name(kind), rule_name(sr),
            rule_name(er));
        ck_assert_int_eq(expect_ok(ctx, &c0, &ref), B2B_CONTACT_ACTIVE);
        const unsigned used = used_slots(kind, sr, er);
        for (int slot = 0; slot < 4; ++slot) {
          if (used & (1u << slot)) continue;
          ++n_unused;
          const double junk[5] = {NAN, INFINITY, -INFINITY, 2e100, -DBL_MAX};
          for (int v = 0; v < 6; ++v) {
            pair_call c = c0;
            double *patch = c.g.X + 12 * b;
            if (v < 5)
              for (int i = 0; i < 3; ++i) patch[3 * slot + i] = junk[v];
            else
              copy_node(patch, slot, slot == 0 || slot == 2 ? 1 : 2);
            CTX("%s %s (%s, %s): unused slot x%d = %s", beam_name[b], tst_kind_name(kind),
                rule_name(sr), rule_name(er), slot + 1,
                v == 0 ? "NaN" : v == 1 ? "+Inf" : v == 2 ? "-Inf" : v == 3 ? "2e100"
                               : v == 4 ? "-DBL_MAX" : "a copy of its neighbour");
            expect_ok(ctx, &c, &o);
            ck_assert_msg(memcmp(&o, &ref, sizeof o) == 0, "%s: the outputs changed", ctx);
          }
        }
      }
  ck_assert_int_eq(n_unused, 18 + 9 + 12 + 12);
  b2b_params_destroy(&p);
}
END_TEST

/* =============================================== pair: end tangents */

START_TEST(test_pair_bad_end_tangent) {
  const int b = _i;
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  int seg[6];
  memcpy(seg, base_seg, sizeof seg);
  seg[3 * b] = NOD;
  seg[3 * b + 1] = TG;
  seg[3 * b + 2] = TG;
  pair_call c0;
  outputs o;
  base_call(&c0, p);
  make_geometry(seg, 90.0, BEND, DIST, &c0.g);
  ck_assert_int_eq(expect_ok("both ends TANGENT", &c0, &o), B2B_CONTACT_ACTIVE);
  for (int t = 0; t < 6; ++t)
    for (int v = 0; v < 3; ++v) {
      pair_call c = c0;
      c.g.tangents[6 * b + t] = bad[v];
      CTX("%s: end_tangents[%d] = %g", beam_name[b], 6 * b + t, bad[v]);
      expect_fail(ctx, &c, B2B_ERR_NONFINITE, beam_name[b], "end tangent",
                  t < 3 ? "first" : "last");
    }
  for (int which = 0; which < 2; ++which) {
    pair_call c = c0;
    for (int i = 0; i < 3; ++i) c.g.tangents[6 * b + 3 * which + i] = 0.0;
    CTX("%s: zero end tangent at the %s node", beam_name[b], which ? "last" : "first");
    expect_fail(ctx, &c, B2B_ERR_RANGE, beam_name[b], "zero vector", which ? "last" : "first");
  }
  b2b_params_destroy(&p);
}
END_TEST

/* ===================================================== pair: radii */

START_TEST(test_pair_bad_radius) {
  const int b = _i;
  const double nonfinite[3] = {NAN, INFINITY, -INFINITY};
  const double negative[] = {-1.0, -1e-300, -4.9406564584124654e-324, -DBL_MAX, 2e100, DBL_MAX};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  for (int v = 0; v < 3; ++v) {
    pair_call c;
    base_call(&c, p);
    c.g.radii[b] = nonfinite[v];
    CTX("%s: radius %g", beam_name[b], nonfinite[v]);
    expect_fail(ctx, &c, B2B_ERR_NONFINITE, beam_name[b], "radius", "finite");
  }
  for (size_t v = 0; v < sizeof negative / sizeof negative[0]; ++v) {
    pair_call c;
    base_call(&c, p);
    c.g.radii[b] = negative[v];
    CTX("%s: radius %g", beam_name[b], negative[v]);
    expect_fail(ctx, &c, B2B_ERR_RANGE, beam_name[b], "radius", NULL);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* Zero radius is valid: contact of the axes themselves. */
START_TEST(test_pair_zero_radius) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  pair_call c;
  outputs o;
  base_call(&c, p);
  c.g.radii[0] = c.g.radii[1] = 0.0;
  CTX("radii 0, 0");
  ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_OPEN);
  assert_no_force(ctx, &c, &o);
  ck_assert(fabs(o.info[B2B_INFO_GAP] - DIST) < 1e-12);
  c.g.radii[0] = -0.0;
  c.g.radii[1] = 0.2;
  CTX("radii -0, 0.2");
  ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  ck_assert(fabs(o.info[B2B_INFO_GAP] - (DIST - 0.2)) < 1e-12);
  c.g.radii[0] = 0.2;
  c.g.radii[1] = 0.0;
  CTX("radii 0.2, 0");
  ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  b2b_params_destroy(&p);
}
END_TEST

/* ================================================ pair: degenerate */

START_TEST(test_pair_coincident) {
  const int b = _i;
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  outputs o;
  /* x3 = x2: the segment's own element. */
  pair_call c;
  base_call(&c, p);
  copy_node(c.g.X + 12 * b, 2, 1);
  CTX("%s: x3 == x2", beam_name[b]);
  expect_fail(ctx, &c, B2B_ERR_COINCIDENT, beam_name[b], "x2", "x3");
  expect_fail(ctx, &c, B2B_ERR_COINCIDENT, "coincide", NULL, NULL);
  /* x1 = x2: the element before (both beams have a neighbour there). */
  base_call(&c, p);
  copy_node(c.g.X + 12 * b, 0, 1);
  CTX("%s: x1 == x2", beam_name[b]);
  expect_fail(ctx, &c, B2B_ERR_COINCIDENT, beam_name[b], "x1", "x2");
  /* x4 = x3: the element after; beam B ends at x3 (x4 unused). */
  base_call(&c, p);
  copy_node(c.g.X + 12 * b, 3, 2);
  CTX("%s: x4 == x3", beam_name[b]);
  if (b == 0)
    expect_fail(ctx, &c, B2B_ERR_COINCIDENT, beam_name[b], "x3", "x4");
  else
    ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  /* All nodes at one point, and a linear segment of zero length. */
  base_call(&c, p);
  for (int k = 1; k < 4; ++k) copy_node(c.g.X + 12 * b, k, 0);
  CTX("%s: all nodes equal", beam_name[b]);
  expect_fail(ctx, &c, B2B_ERR_COINCIDENT, beam_name[b], "coincide", NULL);
  base_call(&c, p);
  c.g.seg[3 * b] = LIN;
  copy_node(c.g.X + 12 * b, 2, 1);
  CTX("%s: linear, x3 == x2", beam_name[b]);
  expect_fail(ctx, &c, B2B_ERR_COINCIDENT, beam_name[b], "x2", "x3");
  /* Both beams degenerate: beam A is named. */
  if (b == 1) {
    base_call(&c, p);
    copy_node(c.g.X, 2, 1);
    copy_node(c.g.X + 12, 2, 1);
    expect_fail("both beams: x3 == x2", &c, B2B_ERR_COINCIDENT, "beam A", NULL, NULL);
  }
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(test_pair_folded) {
  const int b = _i;
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  outputs o;
  pair_call c;
  /* x1 = x3: no tangent direction at x2. */
  base_call(&c, p);
  copy_node(c.g.X + 12 * b, 0, 2);
  CTX("%s: x1 == x3", beam_name[b]);
  expect_fail(ctx, &c, B2B_ERR_FOLDED, beam_name[b], "folds", "x2");
  expect_fail(ctx, &c, B2B_ERR_FOLDED, "x1", "x3", NULL);
  /* x4 = x2: no tangent direction at x3; beam B ends at x3 (x4 unused). */
  base_call(&c, p);
  copy_node(c.g.X + 12 * b, 3, 1);
  CTX("%s: x4 == x2", beam_name[b]);
  if (b == 0)
    expect_fail(ctx, &c, B2B_ERR_FOLDED, beam_name[b], "folds", "x3");
  else
    ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  /* At a beam end the ghost node replaces x1: no fold. */
  base_call(&c, p);
  c.g.seg[3 * b + 1] = RF;
  copy_node(c.g.X + 12 * b, 0, 2);
  CTX("%s: x1 == x3 with start_rule REFLECT", beam_name[b]);
  ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  b2b_params_destroy(&p);
}
END_TEST

/* ==================================================== pair: history */

START_TEST(test_pair_hist_len) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  const int n = history_size(p);
  const int bad[] = {0, n - 1, n + 1, -1, 1, 2 * n, INT_MIN, INT_MAX};
  char ctx[256], num[32];
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    if (bad[k] == n) continue;
    pair_call c;
    base_call(&c, p);
    c.hist_len = bad[k];
    snprintf(num, sizeof num, "%d", bad[k]);
    CTX("hist_len %d (history size %d)", bad[k], n);
    expect_fail(ctx, &c, B2B_ERR_SIZE, "hist_len", num, NULL);
    c.alias = 1;
    expect_fail(ctx, &c, B2B_ERR_SIZE, "hist_len", num, NULL);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* A written history of the base crossing. */
static void written_history(const b2b_params *p, double hist[HMAX]) {
  pair_call c;
  outputs o;
  base_call(&c, p);
  ck_assert_int_eq(expect_ok("history source", &c, &o), B2B_CONTACT_ACTIVE);
  for (int i = 0; i < HMAX; ++i) hist[i] = i < c.hist_len ? o.hist_new[i] : 0.0;
}

START_TEST(test_pair_hist_nonfinite) {
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  const int n = history_size(p);
  double written[HMAX];
  written_history(p, written);
  char ctx[256], where[32];
  for (int fresh = 0; fresh <= 1; ++fresh)
    for (int i = 0; i < n; ++i)
      for (int v = 0; v < 3; ++v) {
        pair_call c;
        base_call(&c, p);
        if (!fresh) memcpy(c.hist_old, written, sizeof c.hist_old);
        c.hist_old[i] = bad[v];
        snprintf(where, sizeof where, "hist_old[%d]", i);
        CTX("%s history, hist_old[%d] = %g", fresh ? "fresh" : "written", i, bad[v]);
        expect_fail(ctx, &c, B2B_ERR_NONFINITE, where, "finite", NULL);
        c.alias = 1;
        expect_fail(ctx, &c, B2B_ERR_NONFINITE, where, "finite", NULL);
      }
  b2b_params_destroy(&p);
}
END_TEST

/* Histories b2b never writes: a foreign format tag, a normal that is not a
 * unit vector. */
START_TEST(test_pair_hist_foreign) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  const int n = history_size(p);
  char ctx[256];
  pair_call c;
  outputs o;
  /* Filled with 7.0. */
  base_call(&c, p);
  for (int i = 0; i < n; ++i) c.hist_old[i] = 7.0;
  expect_fail("history filled with 7.0", &c, B2B_ERR_RANGE, "hist_old", "tag", "7");
  c.alias = 1;
  expect_fail("history filled with 7.0 (aliased)", &c, B2B_ERR_RANGE, "hist_old", "tag", "7");
  /* Other foreign tags, in a history that is otherwise written by b2b. */
  double written[HMAX];
  written_history(p, written);
  const double tags[] = {-1.0, 2.0, 0.5, 1e300, -DBL_MAX, nextafter(1.0, 2.0), 1e-300};
  for (size_t k = 0; k < sizeof tags / sizeof tags[0]; ++k) {
    base_call(&c, p);
    memcpy(c.hist_old, written, sizeof c.hist_old);
    c.hist_old[0] = tags[k];
    CTX("history tag %.17g", tags[k]);
    expect_fail(ctx, &c, B2B_ERR_RANGE, "hist_old", "tag", NULL);
  }
  /* A "fresh" history (tag 0) that is not all zeros, and a has-normal flag
   * that is neither 0 nor 1, are not b2b's either. */
  base_call(&c, p);
  memset(c.hist_old, 0, sizeof c.hist_old);
  c.hist_old[n - 1] = 3.0;
  expect_fail("tag 0 with a non-zero entry", &c, B2B_ERR_RANGE, "hist_old", "all zeros", NULL);
  base_call(&c, p);
  memcpy(c.hist_old, written, sizeof c.hist_old);
  c.hist_old[1] = 0.5;
  expect_fail("has-normal flag 0.5", &c, B2B_ERR_RANGE, "hist_old", "flag", NULL);
  /* The written history itself is fine. */
  base_call(&c, p);
  memcpy(c.hist_old, written, sizeof c.hist_old);
  ck_assert_int_eq(expect_ok("written history", &c, &o), B2B_CONTACT_ACTIVE);
  /* A normal that is not a unit vector. The layout is private; the base
   * normal is (0, 0, 1), so scaling every entry of magnitude ~1 after the
   * first two (format tag and has-normal flag in this layout; the closest-
   * point parameters are ~0) scales the normal. */
  const double scales[] = {2.0, 0.0, 0.5};
  for (size_t k = 0; k < sizeof scales / sizeof scales[0]; ++k) {
    base_call(&c, p);
    memcpy(c.hist_old, written, sizeof c.hist_old);
    int changed = 0;
    for (int i = 2; i < n; ++i)
      if (fabs(c.hist_old[i]) > 0.999 && fabs(c.hist_old[i]) <= 1.0) {
        c.hist_old[i] *= scales[k];
        ++changed;
      }
    ck_assert_int_ge(changed, 1);
    CTX("history normal scaled by %g", scales[k]);
    expect_fail(ctx, &c, B2B_ERR_RANGE, "hist_old", "normal", NULL);
  }
  b2b_params_destroy(&p);
}
END_TEST

/* hist_new may be hist_old: the same results, and the array holds the new
 * history afterwards; twice in a row (the second reads the first's). */
START_TEST(test_pair_hist_alias) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  const int n = history_size(p);
  static outputs ref1, ref2, o;
  pair_call c;
  base_call(&c, p);
  ck_assert_int_eq(expect_ok("step 1 (separate)", &c, &ref1), B2B_CONTACT_ACTIVE);
  pair_call a;
  base_call(&a, p);
  a.alias = 1;
  ck_assert_int_eq(expect_ok("step 1 (aliased)", &a, &o), B2B_CONTACT_ACTIVE);
  ck_assert(memcmp(a.hist_old, ref1.hist_new, (size_t)n * sizeof(double)) == 0);
  ck_assert(memcmp(o.info, ref1.info, sizeof o.info) == 0);
  ck_assert(memcmp(o.residual, ref1.residual, sizeof o.residual) == 0);
  ck_assert(memcmp(o.tangent, ref1.tangent, sizeof o.tangent) == 0);
  /* Step 2: the beams move on (A deeper by 0.01). */
  for (int k = 0; k < 4; ++k) {
    c.g.X[3 * k + 2] -= 0.01;
    a.g.X[3 * k + 2] -= 0.01;
  }
  memcpy(c.hist_old, ref1.hist_new, (size_t)n * sizeof(double));
  ck_assert_int_eq(expect_ok("step 2 (separate)", &c, &ref2), B2B_CONTACT_ACTIVE);
  ck_assert_int_eq(expect_ok("step 2 (aliased)", &a, &o), B2B_CONTACT_ACTIVE);
  ck_assert(memcmp(a.hist_old, ref2.hist_new, (size_t)n * sizeof(double)) == 0);
  ck_assert(memcmp(o.residual, ref2.residual, sizeof o.residual) == 0);
  ck_assert(memcmp(o.tangent, ref2.tangent, sizeof o.tangent) == 0);
  /* With warm start too. */
  b2b_params *w = new_params();
  ck_assert_int_eq(b2b_params_set_real(w, "penalty", PEN, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(w, "warm_start", 1, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_finalize(w, NULL, 0), B2B_OK);
  a.params = w;
  memcpy(a.hist_old, ref1.hist_new, (size_t)n * sizeof(double));
  ck_assert_int_eq(expect_ok("step 2 (aliased, warm start)", &a, &o), B2B_CONTACT_ACTIVE);
  ck_assert(fabs(o.info[B2B_INFO_GAP] - ref2.info[B2B_INFO_GAP]) < 1e-12);
  b2b_params_destroy(&w);
  b2b_params_destroy(&p);
}
END_TEST

/* ===================================================== pair: extremes */

/* The base crossing scaled by 1e-6 and 1e6 (radii and distances with it) and
 * translated by 1e6: active, finite, and the same contact in scaled units. */
START_TEST(test_pair_extreme_scales) {
  const double scale = _i == 0 ? 1e-6 : _i == 1 ? 1e6 : 1.0;
  const double offset = _i == 2 ? 1e6 : 0.0;
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  static outputs ref, o;
  pair_call c;
  base_call(&c, p);
  ck_assert_int_eq(expect_ok("unit scale", &c, &ref), B2B_CONTACT_ACTIVE);
  scale_geometry(&c.g, scale, offset);
  CTX("scaled by %g, translated by %g", scale, offset);
  ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  const double tol = offset != 0.0 ? 1e-6 : 1e-9;
  const double gap = o.info[B2B_INFO_GAP] / scale;
  ck_assert_msg(fabs(gap - ref.info[B2B_INFO_GAP]) < tol * DIST, "%s: gap %g, expected %g", ctx,
                gap, ref.info[B2B_INFO_GAP]);
  /* Linear law: force ~ scale, residual ~ scale, tangent scale-free. */
  for (int i = 0; i < 24; ++i) o.residual[i] /= scale;
  ck_assert_msg(tst_rel_diff(o.residual, ref.residual, 24, 0.0) < tol, "%s: residual off by %g",
                ctx, tst_rel_diff(o.residual, ref.residual, 24, 0.0));
  ck_assert_msg(tst_rel_diff(o.tangent, ref.tangent, 576, 0.0) < tol, "%s: tangent off by %g",
                ctx, tst_rel_diff(o.tangent, ref.tangent, 576, 0.0));
  b2b_params_destroy(&p);
}
END_TEST

/* Scales further out, still well inside B2B_COORD_MAX and above
 * B2B_LENGTH_MIN: by <b2b/b2b.h> the crossing is still a crossing (active,
 * 88.6 degrees) and every output of a successful call is finite. */
static const double far_scales[] = {1e-99, 1e-80, 1e-60, 1e60, 1e76, 1e78, 1e80, 1e99};
#define N_FAR_SCALES ((int)(sizeof far_scales / sizeof far_scales[0]))

START_TEST(test_pair_far_scales) {
  const double scale = far_scales[_i];
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1.0, 0.0);
  char ctx[256];
  static outputs o;
  pair_call c;
  base_call(&c, p);
  scale_geometry(&c.g, scale, 0.0);
  CTX("base crossing scaled by %g", scale);
  const int st = expect_ok(ctx, &c, &o);
  ck_assert_msg(st == B2B_CONTACT_ACTIVE,
                "%s: contact status %d (angle %g, xi %g, eta %g, %g iterations), expected ACTIVE",
                ctx, st, o.info[B2B_INFO_ANGLE], o.info[B2B_INFO_XI], o.info[B2B_INFO_ETA],
                o.info[B2B_INFO_ITERATIONS]);
  ck_assert_msg(fabs(o.info[B2B_INFO_GAP] / scale - (DIST - 2 * RADIUS)) < 1e-9, "%s: gap %g",
                ctx, o.info[B2B_INFO_GAP]);
  b2b_params_destroy(&p);
}
END_TEST

/* Near-parallel beams: B2B_CONTACT_PARALLEL, no force, nothing non-finite.
 * Loop index: the curve kind of both beams (straight patches). */
START_TEST(test_pair_near_parallel) {
  const int kind = _i;
  const double angles[] = {0.1, 0.0, 0.4, 0.01};
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  const int seg[6] = {kind, NB, NB, kind, NB, NB};
  for (size_t k = 0; k < sizeof angles / sizeof angles[0]; ++k) {
    pair_call c;
    outputs o;
    base_call(&c, p);
    make_geometry(seg, angles[k], 0.0, DIST, &c.g);
    CTX("%s, crossing at %g degrees", tst_kind_name(kind), angles[k]);
    const int st = expect_ok(ctx, &c, &o);
    ck_assert_msg(st == B2B_CONTACT_PARALLEL, "%s: contact status %d, expected PARALLEL", ctx,
                  st);
    assert_no_force(ctx, &c, &o);
    ck_assert_msg(o.info[B2B_INFO_ANGLE] < 0.5, "%s: angle %g", ctx, o.info[B2B_INFO_ANGLE]);
    /* The same with the parallel angle below the crossing angle: evaluated. */
    if (angles[k] >= 0.1) {
      b2b_params *q = new_params();
      ck_assert_int_eq(b2b_params_set_real(q, "penalty", PEN, NULL, 0), B2B_OK);
      ck_assert_int_eq(b2b_params_set_real(q, "parallel_angle", 0.05, NULL, 0), B2B_OK);
      ck_assert_int_eq(b2b_params_finalize(q, NULL, 0), B2B_OK);
      c.params = q;
      CTX("%s, crossing at %g degrees, parallel_angle 0.05", tst_kind_name(kind), angles[k]);
      ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
      b2b_params_destroy(&q);
    }
  }
  b2b_params_destroy(&p);
}
END_TEST

/* Axes that intersect exactly: no normal with a fresh history; with the
 * history of the approach (normal (0, 0, 1)) that normal is used and the
 * pair is active with gap -r_A - r_B. Loop index: 0 base kinds (bent), 1
 * linear (straight). */
START_TEST(test_pair_intersecting_axes) {
  int seg[6];
  memcpy(seg, base_seg, sizeof seg);
  if (_i == 1) seg[0] = seg[3] = LIN;
  b2b_params *p = tst_params(B2B_LAW_LINEAR, PEN, 0.0);
  char ctx[256];
  pair_call c;
  outputs o;
  /* The approach: the same beams DIST apart. */
  base_call(&c, p);
  make_geometry(seg, 90.0, _i == 1 ? 0.0 : BEND, DIST, &c.g);
  ck_assert_int_eq(expect_ok("approach", &c, &o), B2B_CONTACT_ACTIVE);
  double hist[HMAX];
  memcpy(hist, o.hist_new, sizeof hist);
  ck_assert(o.info[B2B_INFO_NORMAL + 2] > 0.999);

  make_geometry(seg, 90.0, _i == 1 ? 0.0 : BEND, 0.0, &c.g);
  CTX("%s axes intersect, fresh history", _i ? "straight" : "bent");
  ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_NO_NORMAL);
  assert_no_force(ctx, &c, &o);
  TST_ASSERT_ALL(int, i, 0, c.hist_len, o.hist_new[i] == 0.0,
                 "%s: hist_new[%d] = %g (nothing to record)", ctx, i, o.hist_new[i]);

  memcpy(c.hist_old, hist, sizeof hist);
  CTX("%s axes intersect, history with a normal", _i ? "straight" : "bent");
  ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  ck_assert_msg(fabs(o.info[B2B_INFO_GAP] + 2 * RADIUS) < 1e-12, "%s: gap %g", ctx,
                o.info[B2B_INFO_GAP]);
  ck_assert_msg(fabs(o.info[B2B_INFO_NORMAL + 2] - 1.0) < 1e-12, "%s: normal z %g", ctx,
                o.info[B2B_INFO_NORMAL + 2]);
  ck_assert_msg(tst_max_abs(o.residual, 24) > 0.0, "%s: zero residual", ctx);
  ck_assert_msg(fabs(o.info[B2B_INFO_NORMAL_FORCE] - PEN * 2 * RADIUS) < 1e-9, "%s: force %g", ctx,
                o.info[B2B_INFO_NORMAL_FORCE]);
  /* The tangent omits the history normal's rotation and is not symmetric;
   * info says so with and without the tangent (it said 1 without). */
  ck_assert_msg(o.info[B2B_INFO_SYMMETRIC] == 0.0, "%s: symmetric %g with the tangent", ctx,
                o.info[B2B_INFO_SYMMETRIC]);
  c.null_args = A_TANGENT;
  ck_assert_int_eq(expect_ok(ctx, &c, &o), B2B_CONTACT_ACTIVE);
  ck_assert_msg(o.info[B2B_INFO_SYMMETRIC] == 0.0, "%s: symmetric %g without the tangent", ctx,
                o.info[B2B_INFO_SYMMETRIC]);
  b2b_params_destroy(&p);
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("pair_bad_input");
  TCase *tc;
#define TC(name, fn, lo, hi)           \
  tc = tcase_create(name);             \
  tcase_add_loop_test(tc, fn, lo, hi); \
  suite_add_tcase(s, tc)

  /* The b2b_params handle. */
  TC("params_null_handle", test_params_null_handle, 0, 1);
  TC("params_null_key_value", test_params_null_key_value, 0, 1);
  TC("params_unknown_key", test_params_unknown_key, 0, 1);
  TC("params_key_of_other_type", test_params_key_of_other_type, 0, 1);
  TC("params_long_unknown_key", test_params_long_unknown_key, 0, 1);
  TC("params_nonfinite", test_params_nonfinite, 0, 1);
  TC("params_failed_penalty_not_set", test_params_failed_penalty_not_set, 0, 1);
  TC("params_real_range", test_params_real_range, 0, 1);
  TC("params_int_range", test_params_int_range, 0, 1);
  TC("params_valid_bounds", test_params_valid_bounds, 0, 1);
  TC("params_finalize_without_penalty", test_params_finalize_without_penalty, 0, 1);
  TC("params_quadratic_without_gap", test_params_quadratic_without_gap, 0, 1);
  TC("params_set_after_finalize", test_params_set_after_finalize, 0, 1);
  TC("params_history_size_before_finalize", test_params_history_size_before_finalize, 0, 1);
  TC("params_destroy", test_params_destroy, 0, 1);
  /* Loop index: the law. */
  TC("zero_penalty", test_zero_penalty, 0, 2);
  /* Loop index: penalty 1e200, 1e300, DBL_MAX x law. */
  TC("huge_penalty", test_huge_penalty, 0, 6);
  TC("huge_penalty_deep_penetration", test_huge_penalty_deep_penetration, 0, 2);
  /* b2b_pair_eval. Loop index (where 0, 2): the beam, A or B. */
  TC("pair_base_is_active", test_pair_base_is_active, 0, 1);
  TC("pair_params_null", test_pair_params_null, 0, 1);
  TC("pair_params_not_finalized", test_pair_params_not_finalized, 0, 1);
  TC("pair_null_argument", test_pair_null_argument, 0, N_NULL_ARGS);
  TC("pair_null_end_tangents", test_pair_null_end_tangents, 0, 2);
  TC("pair_ldk", test_pair_ldk, 0, 1);
  TC("pair_unknown_kind", test_pair_unknown_kind, 0, 2);
  TC("pair_unknown_rule", test_pair_unknown_rule, 0, 2);
  TC("pair_midpoint_both_ends", test_pair_midpoint_both_ends, 0, 2);
  TC("pair_nonfinite_coordinate", test_pair_nonfinite_coordinate, 0, 2);
  TC("pair_coordinate_beyond_max", test_pair_coordinate_beyond_max, 0, 2);
  TC("pair_unused_slots", test_pair_unused_slots, 0, 2);
  TC("pair_bad_end_tangent", test_pair_bad_end_tangent, 0, 2);
  TC("pair_bad_radius", test_pair_bad_radius, 0, 2);
  TC("pair_zero_radius", test_pair_zero_radius, 0, 1);
  TC("pair_coincident", test_pair_coincident, 0, 2);
  TC("pair_folded", test_pair_folded, 0, 2);
  TC("pair_hist_len", test_pair_hist_len, 0, 1);
  TC("pair_hist_nonfinite", test_pair_hist_nonfinite, 0, 1);
  TC("pair_hist_foreign", test_pair_hist_foreign, 0, 1);
  TC("pair_hist_alias", test_pair_hist_alias, 0, 1);
  /* Loop index: scale 1e-6, scale 1e6, translation 1e6. */
  TC("pair_extreme_scales", test_pair_extreme_scales, 0, 3);
  TC("pair_far_scales", test_pair_far_scales, 0, N_FAR_SCALES);
  /* Loop index: curve kind. */
  TC("pair_near_parallel", test_pair_near_parallel, 0, 4);
  TC("pair_intersecting_axes", test_pair_intersecting_axes, 0, 2);
#undef TC
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
