/* Bad input of Coulomb friction (b2b_pair.h, "Friction", "Handover" and
 * "Bad input"): the "friction" and "tangential_penalty" options, friction
 * histories (length, non-finite and out-of-range friction slots), extreme
 * penalties and displacements, and b2b_pair_history_handover.
 *
 * Each failing case checks the documented status code, a non-empty,
 * NUL-terminated message that names the problem (strstr on a key word), that
 * no output was touched (pre-filled with a sentinel) and no input modified,
 * and the same code with errmsg = NULL, 0. Next to the failures, the closest
 * valid inputs must succeed.
 *
 * Friction histories are built by taking a valid history written by
 * b2b_pair_eval and altering one entry. The layout is private, but the tests
 * rely on it: [0] tag, [1] has-normal, [2..4] normal, [5] xi, [6] eta,
 * [7] reserved, [8] in-contact, [9], [10] force components, [11] state. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pair_support.h"

#define SENT 12345.0
#define SENT_INT (-777)
#define GUARD 'Z'
#define HMAX 16
#define PAD 4
#define MU 0.3
#define EPS_N 1e3
#define EPS_T 1e3

enum { LIN = B2B_CURVE_LINEAR, NOD = B2B_CURVE_HERMITE_NODAL };

#define CTX(...) snprintf(ctx, sizeof ctx, __VA_ARGS__)

/* ============================================================ messages */

static char g_msg[B2B_ERRMSG_LEN + 16];

static char *fresh_msg(void) {
  memset(g_msg, GUARD, sizeof g_msg);
  return g_msg;
}

/* The last call, made with fresh_msg() and B2B_ERRMSG_LEN, failed with want:
 * NUL within the buffer, nothing written past it, not empty, each word. */
static void check_failure(const char *ctx, int st, int want, const char *w1, const char *w2) {
  ck_assert_msg(st == want, "%s: status %d (%s), expected %d (%s); message: %.*s", ctx, st,
                b2b_strerror(st), want, b2b_strerror(want), B2B_ERRMSG_LEN, g_msg);
  ck_assert_msg(memchr(g_msg, '\0', B2B_ERRMSG_LEN) != NULL, "%s: message not NUL-terminated",
                ctx);
  for (size_t i = B2B_ERRMSG_LEN; i < sizeof g_msg; ++i)
    ck_assert_msg(g_msg[i] == GUARD, "%s: message buffer overrun", ctx);
  ck_assert_msg(g_msg[0] != '\0', "%s: empty message", ctx);
  const char *w[2] = {w1, w2};
  for (int k = 0; k < 2; ++k)
    if (w[k])
      ck_assert_msg(strstr(g_msg, w[k]) != NULL, "%s: message \"%s\" does not contain \"%s\"",
                    ctx, g_msg, w[k]);
}

/* The last call (made with fresh_msg()) succeeded and left the buffer alone. */
static void check_success(const char *ctx, int st) {
  ck_assert_msg(st == B2B_OK, "%s: status %d (%s): %.*s", ctx, st, b2b_strerror(st),
                B2B_ERRMSG_LEN, g_msg);
  for (size_t i = 0; i < sizeof g_msg; ++i)
    ck_assert_msg(g_msg[i] == GUARD, "%s: a successful call wrote errmsg[%zu]", ctx, i);
}

static double get_real(const b2b_params *p, const char *key) {
  double v = SENT;
  ck_assert_int_eq(b2b_params_get_real(p, key, &v, NULL, 0), B2B_OK);
  return v;
}

static b2b_params *new_params(void) {
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", EPS_N, NULL, 0), B2B_OK);
  return p;
}

/* ============================================================ the pair */

/* Two straight HERMITE_NODAL beams crossing at 90 degrees: A along x (moved
 * by shift along x), B along y at height 0.3 (radii 0.2, 0.15: gap -0.05);
 * everything scaled by `scale`. */
typedef struct {
  int seg[6];
  double X[24];
  double radii[2];
} problem;

static void make_problem(double shift, double scale, problem *pb) {
  const int seg[6] = {NOD, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, NOD, B2B_END_NEIGHBOUR,
                      B2B_END_NEIGHBOUR};
  memcpy(pb->seg, seg, sizeof seg);
  for (int k = 0; k < 4; ++k) {
    const double s = k - 1.5;
    pb->X[3 * k] = (s + shift) * scale, pb->X[3 * k + 1] = 0.0, pb->X[3 * k + 2] = 0.0;
    pb->X[12 + 3 * k] = 0.0, pb->X[12 + 3 * k + 1] = s * scale, pb->X[12 + 3 * k + 2] = 0.3 * scale;
  }
  pb->radii[0] = 0.2 * scale;
  pb->radii[1] = 0.15 * scale;
}

typedef struct {
  double hist_new[HMAX];
  int status;
  double info[B2B_PAIR_INFO_LEN + PAD];
  double residual[B2B_PAIR_NDOF + PAD];
  double tangent[B2B_PAIR_NDOF * B2B_PAIR_NDOF + PAD];
} outputs;

static void fill_outputs(outputs *o) {
  for (int i = 0; i < HMAX; ++i) o->hist_new[i] = SENT;
  o->status = SENT_INT;
  for (int i = 0; i < B2B_PAIR_INFO_LEN + PAD; ++i) o->info[i] = SENT;
  for (int i = 0; i < B2B_PAIR_NDOF + PAD; ++i) o->residual[i] = SENT;
  for (int i = 0; i < B2B_PAIR_NDOF * B2B_PAIR_NDOF + PAD; ++i) o->tangent[i] = SENT;
}

static void assert_untouched(const outputs *o, const char *ctx) {
  for (int i = 0; i < HMAX; ++i)
    ck_assert_msg(o->hist_new[i] == SENT, "%s: hist_new[%d] written on failure", ctx, i);
  ck_assert_msg(o->status == SENT_INT, "%s: contact_status written on failure", ctx);
  for (int i = 0; i < B2B_PAIR_INFO_LEN + PAD; ++i)
    ck_assert_msg(o->info[i] == SENT, "%s: info[%d] written on failure", ctx, i);
  for (int i = 0; i < B2B_PAIR_NDOF + PAD; ++i)
    ck_assert_msg(o->residual[i] == SENT, "%s: residual[%d] written on failure", ctx, i);
  for (int i = 0; i < B2B_PAIR_NDOF * B2B_PAIR_NDOF + PAD; ++i)
    ck_assert_msg(o->tangent[i] == SENT, "%s: tangent[%d] written on failure", ctx, i);
}

static int run(const b2b_params *p, const problem *pb, const double *hist_old, int hist_len,
               outputs *o, char *msg, int len) {
  return b2b_pair_eval(p, pb->seg, pb->X, NULL, pb->radii, hist_old, o->hist_new, hist_len,
                       &o->status, o->info, o->residual, o->tangent, B2B_PAIR_NDOF, msg, len);
}

/* b2b_pair_eval fails with want, a message holding w1 and w2, no output
 * touched and hist_old unchanged; again with errmsg NULL, 0. */
static void expect_fail(const char *ctx, const b2b_params *p, const problem *pb,
                        const double *hist_old, int hist_len, int want, const char *w1,
                        const char *w2) {
  double before[HMAX];
  memcpy(before, hist_old, sizeof before);
  outputs o;
  fill_outputs(&o);
  check_failure(ctx, run(p, pb, hist_old, hist_len, &o, fresh_msg(), B2B_ERRMSG_LEN), want, w1,
                w2);
  assert_untouched(&o, ctx);
  ck_assert_msg(memcmp(before, hist_old, sizeof before) == 0, "%s: hist_old modified", ctx);
  ck_assert_msg(run(p, pb, hist_old, hist_len, &o, NULL, 0) == want,
                "%s: another status with errmsg NULL", ctx);
  assert_untouched(&o, ctx);
}

/* b2b_pair_eval succeeds with finite outputs, written within their lengths
 * only, and leaves the message buffer alone. Returns the contact status. */
static int expect_ok(const char *ctx, const b2b_params *p, const problem *pb,
                     const double *hist_old, int hist_len, outputs *o) {
  fill_outputs(o);
  check_success(ctx, run(p, pb, hist_old, hist_len, o, fresh_msg(), B2B_ERRMSG_LEN));
  for (int i = 0; i < HMAX; ++i)
    ck_assert_msg(i < hist_len ? isfinite(o->hist_new[i]) && o->hist_new[i] != SENT
                               : o->hist_new[i] == SENT,
                  "%s: hist_new[%d] = %g", ctx, i, o->hist_new[i]);
  for (int i = 0; i < B2B_PAIR_INFO_LEN + PAD; ++i)
    ck_assert_msg(i < B2B_PAIR_INFO_LEN ? isfinite(o->info[i]) && o->info[i] != SENT
                                        : o->info[i] == SENT,
                  "%s: info[%d] = %g", ctx, i, o->info[i]);
  for (int i = 0; i < B2B_PAIR_NDOF + PAD; ++i)
    ck_assert_msg(i < B2B_PAIR_NDOF ? isfinite(o->residual[i]) : o->residual[i] == SENT,
                  "%s: residual[%d] = %g", ctx, i, o->residual[i]);
  for (int i = 0; i < B2B_PAIR_NDOF * B2B_PAIR_NDOF + PAD; ++i)
    ck_assert_msg(i < B2B_PAIR_NDOF * B2B_PAIR_NDOF ? isfinite(o->tangent[i])
                                                    : o->tangent[i] == SENT,
                  "%s: tangent[%d] = %g", ctx, i, o->tangent[i]);
  return o->status;
}

/* A history of the base crossing after a committed step with A at shift0,
 * then (if shift1 differs) another with A at shift1: in contact, with a
 * force if shift1 != shift0. */
static void written_history(const b2b_params *p, double shift0, double shift1,
                            double hist[HMAX]) {
  problem pb;
  outputs o;
  double h0[HMAX] = {0};
  const int n = tst_history_len(p);
  make_problem(shift0, 1.0, &pb);
  ck_assert_int_eq(expect_ok("history source", p, &pb, h0, n, &o), B2B_CONTACT_ACTIVE);
  memcpy(hist, o.hist_new, HMAX * sizeof(double));
  if (shift1 != shift0) {
    make_problem(shift1, 1.0, &pb);
    memcpy(h0, hist, sizeof h0);
    ck_assert_int_eq(expect_ok("history source", p, &pb, h0, n, &o), B2B_CONTACT_ACTIVE);
    memcpy(hist, o.hist_new, HMAX * sizeof(double));
  }
  for (int i = n; i < HMAX; ++i) hist[i] = 0.0;
}

/* ======================================================= the options */

START_TEST(friction_out_of_range) {
  char ctx[128];
  b2b_params *p = new_params();
  ck_assert_int_eq(b2b_params_set_real(p, "friction", 0.25, NULL, 0), B2B_OK);
  const double bad[] = {-0.1, -1e-300, -1e300};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    CTX("friction = %g", bad[k]);
    check_failure(ctx, b2b_params_set_real(p, "friction", bad[k], fresh_msg(), B2B_ERRMSG_LEN),
                  B2B_ERR_RANGE, "\"friction\"", ">= 0");
    ck_assert_int_eq(b2b_params_set_real(p, "friction", bad[k], NULL, 0), B2B_ERR_RANGE);
    ck_assert_msg(get_real(p, "friction") == 0.25, "%s: the value changed", ctx);
  }
  /* the bounds themselves are fine */
  check_success("friction = 0", b2b_params_set_real(p, "friction", 0.0, fresh_msg(),
                                                    B2B_ERRMSG_LEN));
  check_success("friction = 1e300", b2b_params_set_real(p, "friction", 1e300, fresh_msg(),
                                                        B2B_ERRMSG_LEN));
  ck_assert(get_real(p, "friction") == 1e300);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(tangential_penalty_out_of_range) {
  char ctx[128];
  b2b_params *p = new_params();
  ck_assert_int_eq(b2b_params_set_real(p, "tangential_penalty", 7.5, NULL, 0), B2B_OK);
  const double bad[] = {0.0, -0.0, -1.0, -1e-300, -1e300};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    CTX("tangential_penalty = %g", bad[k]);
    check_failure(ctx,
                  b2b_params_set_real(p, "tangential_penalty", bad[k], fresh_msg(),
                                      B2B_ERRMSG_LEN),
                  B2B_ERR_RANGE, "\"tangential_penalty\"", "> 0");
    ck_assert_int_eq(b2b_params_set_real(p, "tangential_penalty", bad[k], NULL, 0),
                     B2B_ERR_RANGE);
    ck_assert_msg(get_real(p, "tangential_penalty") == 7.5, "%s: the value changed", ctx);
  }
  check_success("tangential_penalty = 1e-300",
                b2b_params_set_real(p, "tangential_penalty", 1e-300, fresh_msg(),
                                    B2B_ERRMSG_LEN));
  ck_assert(get_real(p, "tangential_penalty") == 1e-300);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(friction_options_not_finite) {
  char ctx[128];
  const char *keys[2] = {"friction", "tangential_penalty"};
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  b2b_params *p = new_params();
  ck_assert_int_eq(b2b_params_set_real(p, "friction", 0.5, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "tangential_penalty", 9.0, NULL, 0), B2B_OK);
  for (int k = 0; k < 2; ++k)
    for (int v = 0; v < 3; ++v) {
      CTX("%s = %g", keys[k], bad[v]);
      char quoted[64];
      snprintf(quoted, sizeof quoted, "\"%s\"", keys[k]);
      check_failure(ctx, b2b_params_set_real(p, keys[k], bad[v], fresh_msg(), B2B_ERRMSG_LEN),
                    B2B_ERR_NONFINITE, quoted, "finite");
      ck_assert_int_eq(b2b_params_set_real(p, keys[k], bad[v], NULL, 0), B2B_ERR_NONFINITE);
    }
  ck_assert(get_real(p, "friction") == 0.5);
  ck_assert(get_real(p, "tangential_penalty") == 9.0);
  b2b_params_destroy(&p);
}
END_TEST

/* Defaults, the values set, and the history length each gives. */
START_TEST(friction_options_read_back) {
  b2b_params *p = new_params();
  ck_assert(get_real(p, "friction") == 0.0);           /* default: frictionless */
  ck_assert(get_real(p, "tangential_penalty") == 0.0); /* required: reads 0 until set */
  const double mu = 0.3125, eps = 1234.5678;
  check_success("set friction", b2b_params_set_real(p, "friction", mu, fresh_msg(),
                                                    B2B_ERRMSG_LEN));
  check_success("set tangential_penalty",
                b2b_params_set_real(p, "tangential_penalty", eps, fresh_msg(), B2B_ERRMSG_LEN));
  double v = SENT;
  check_success("get friction", b2b_params_get_real(p, "friction", &v, fresh_msg(),
                                                    B2B_ERRMSG_LEN));
  ck_assert(v == mu);
  check_success("get tangential_penalty",
                b2b_params_get_real(p, "tangential_penalty", &v, fresh_msg(), B2B_ERRMSG_LEN));
  ck_assert(v == eps);
  ck_assert_int_eq(b2b_params_finalize(p, NULL, 0), B2B_OK);
  ck_assert(get_real(p, "friction") == mu && get_real(p, "tangential_penalty") == eps);
  ck_assert_int_eq(tst_history_len(p), 12);
  /* read-only after finalize */
  check_failure("set friction after finalize",
                b2b_params_set_real(p, "friction", 0.1, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_STATE, "finalized", "\"friction\"");
  check_failure("set tangential_penalty after finalize",
                b2b_params_set_real(p, "tangential_penalty", 1.0, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_STATE, "finalized", "\"tangential_penalty\"");
  ck_assert(get_real(p, "friction") == mu && get_real(p, "tangential_penalty") == eps);
  b2b_params_destroy(&p);
  /* no friction, or friction 0 (with or without eps_T): the short history */
  for (int k = 0; k < 3; ++k) {
    b2b_params *q = new_params();
    if (k >= 1) ck_assert_int_eq(b2b_params_set_real(q, "friction", 0.0, NULL, 0), B2B_OK);
    if (k == 2)
      ck_assert_int_eq(b2b_params_set_real(q, "tangential_penalty", 5.0, NULL, 0), B2B_OK);
    check_success("finalize without friction", b2b_params_finalize(q, fresh_msg(),
                                                                   B2B_ERRMSG_LEN));
    ck_assert_int_eq(tst_history_len(q), 8);
    b2b_params_destroy(&q);
  }
}
END_TEST

/* friction > 0 needs tangential_penalty: finalize fails (and the handle
 * stays settable, unfinalized: history_size and b2b_pair_eval refuse it),
 * until it is set. */
START_TEST(friction_without_tangential_penalty) {
  b2b_params *p = new_params();
  ck_assert_int_eq(b2b_params_set_real(p, "friction", 0.4, NULL, 0), B2B_OK);
  check_failure("finalize", b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN), B2B_ERR_STATE,
                "\"tangential_penalty\"", "not been set");
  ck_assert_int_eq(b2b_params_finalize(p, NULL, 0), B2B_ERR_STATE);
  int n = SENT_INT;
  check_failure("history_size", b2b_params_history_size(p, &n, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_STATE, "finalize", NULL);
  ck_assert(n == SENT_INT);
  problem pb;
  make_problem(0.0, 1.0, &pb);
  double h[HMAX] = {0};
  expect_fail("b2b_pair_eval", p, &pb, h, 12, B2B_ERR_STATE, "finalize", NULL);
  /* a tiny coefficient needs it too */
  b2b_params *q = new_params();
  ck_assert_int_eq(b2b_params_set_real(q, "friction", 1e-300, NULL, 0), B2B_OK);
  check_failure("finalize, friction 1e-300", b2b_params_finalize(q, fresh_msg(), B2B_ERRMSG_LEN),
                B2B_ERR_STATE, "\"tangential_penalty\"", NULL);
  b2b_params_destroy(&q);
  /* set it now: fine */
  check_success("set tangential_penalty late",
                b2b_params_set_real(p, "tangential_penalty", EPS_T, fresh_msg(), B2B_ERRMSG_LEN));
  check_success("finalize", b2b_params_finalize(p, fresh_msg(), B2B_ERRMSG_LEN));
  ck_assert_int_eq(tst_history_len(p), 12);
  outputs o;
  ck_assert_int_eq(expect_ok("eval", p, &pb, h, 12, &o), B2B_CONTACT_ACTIVE);
  b2b_params_destroy(&p);
}
END_TEST

/* ======================================================= histories */

START_TEST(history_of_the_wrong_length) {
  char ctx[128];
  b2b_params *fric = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  b2b_params *none = tst_params(B2B_LAW_LINEAR, EPS_N, 0.0);
  problem pb;
  make_problem(0.0, 1.0, &pb);
  double h[HMAX] = {0};
  const int for_fric[] = {8, 11, 13, 0, -12}, for_none[] = {12, 7, 9, 0};
  for (size_t k = 0; k < sizeof for_fric / sizeof for_fric[0]; ++k) {
    CTX("friction set, hist_len %d", for_fric[k]);
    expect_fail(ctx, fric, &pb, h, for_fric[k], B2B_ERR_SIZE, "hist_len", "12");
  }
  for (size_t k = 0; k < sizeof for_none / sizeof for_none[0]; ++k) {
    CTX("frictionless set, hist_len %d", for_none[k]);
    expect_fail(ctx, none, &pb, h, for_none[k], B2B_ERR_SIZE, "hist_len", "keeps 8");
  }
  /* a written friction history given to the frictionless set, and back */
  double hf[HMAX], hn[HMAX];
  written_history(fric, 0.0, 0.004, hf);
  written_history(none, 0.0, 0.004, hn);
  expect_fail("friction history, frictionless set", none, &pb, hf, 12, B2B_ERR_SIZE, "hist_len",
              NULL);
  expect_fail("frictionless history, friction set", fric, &pb, hn, 8, B2B_ERR_SIZE, "hist_len",
              NULL);
  outputs o;
  ck_assert_int_eq(expect_ok("right lengths", fric, &pb, hf, 12, &o), B2B_CONTACT_ACTIVE);
  ck_assert_int_eq(expect_ok("right lengths", none, &pb, hn, 8, &o), B2B_CONTACT_ACTIVE);
  b2b_params_destroy(&fric);
  b2b_params_destroy(&none);
}
END_TEST

START_TEST(history_friction_slots_not_finite) {
  char ctx[128], where[32];
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  problem pb;
  make_problem(0.004, 1.0, &pb);
  double written[HMAX];
  written_history(p, 0.0, 0.004, written);
  ck_assert_msg(written[8] == 1.0 && written[9] != 0.0 && written[11] == B2B_FRICTION_STICK,
                "the stuck history is not what the tests expect");
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  for (int fresh = 0; fresh < 2; ++fresh)
    for (int i = 8; i < 12; ++i)
      for (int v = 0; v < 3; ++v) {
        double h[HMAX];
        if (fresh) memset(h, 0, sizeof h);
        else memcpy(h, written, sizeof h);
        h[i] = bad[v];
        snprintf(where, sizeof where, "hist_old[%d]", i);
        CTX("%s history, %s = %g", fresh ? "fresh" : "written", where, bad[v]);
        expect_fail(ctx, p, &pb, h, 12, B2B_ERR_NONFINITE, where, "not finite");
      }
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(history_friction_slots_out_of_range) {
  char ctx[128];
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  problem pb;
  make_problem(0.004, 1.0, &pb);
  double stuck[HMAX], slipped[HMAX], h[HMAX];
  written_history(p, 0.0, 0.004, stuck);
  written_history(p, 0.0, 0.05, slipped);
  ck_assert(slipped[8] == 1.0 && slipped[11] == B2B_FRICTION_SLIP);
  /* the written histories themselves are fine */
  outputs o;
  ck_assert_int_eq(expect_ok("stuck history", p, &pb, stuck, 12, &o), B2B_CONTACT_ACTIVE);
  ck_assert_int_eq(expect_ok("slipped history", p, &pb, slipped, 12, &o), B2B_CONTACT_ACTIVE);
  /* the in-contact flag is 0 or 1 */
  const double flags[] = {0.5, 2.0, -1.0, 1.0 + 1e-15};
  for (size_t k = 0; k < sizeof flags / sizeof flags[0]; ++k) {
    memcpy(h, stuck, sizeof h);
    h[8] = flags[k];
    CTX("in-contact flag %.17g", flags[k]);
    expect_fail(ctx, p, &pb, h, 12, B2B_ERR_RANGE, "hist_old", "in-contact flag");
  }
  /* in contact: the state is STICK or SLIP */
  const double states[] = {0.0, 3.0, 1.5, -1.0, 2.0 + 4e-16};
  for (size_t k = 0; k < sizeof states / sizeof states[0]; ++k) {
    memcpy(h, slipped, sizeof h);
    h[11] = states[k];
    CTX("in contact, friction state %.17g", states[k]);
    expect_fail(ctx, p, &pb, h, 12, B2B_ERR_RANGE, "hist_old", "friction state");
  }
  /* not in contact: no force and no state */
  for (int i = 9; i < 12; ++i) {
    memcpy(h, stuck, sizeof h);
    h[8] = 0.0;
    for (int j = 9; j < 12; ++j)
      if (j != i) h[j] = 0.0;
    if (h[i] == 0.0) h[i] = 1.0; /* (a stuck history's force may lie along e1 only) */
    CTX("not in contact, entry %d = %g", i, h[i]);
    expect_fail(ctx, p, &pb, h, 12, B2B_ERR_RANGE, "hist_old", "not in contact");
  }
  memcpy(h, stuck, sizeof h);
  h[8] = 0.0;
  expect_fail("not in contact with the stuck force and state", p, &pb, h, 12, B2B_ERR_RANGE,
              "not in contact", NULL);
  /* in contact but no normal */
  memcpy(h, stuck, sizeof h);
  h[1] = 0.0;
  expect_fail("in contact without a normal", p, &pb, h, 12, B2B_ERR_RANGE, "hist_old",
              "no normal");
  /* the closest valid one: not in contact, all friction slots zero */
  memcpy(h, stuck, sizeof h);
  for (int i = 8; i < 12; ++i) h[i] = 0.0;
  ck_assert_int_eq(expect_ok("not in contact, no force", p, &pb, h, 12, &o), B2B_CONTACT_ACTIVE);
  for (int i = 0; i < 3; ++i) ck_assert(o.info[B2B_INFO_TANGENTIAL_FORCE + i] == 0.0);
  b2b_params_destroy(&p);
}
END_TEST

/* ======================================================= extremes */

/* |v| without underflow or overflow of the squares. */
static double vnorm(const double *v) {
  const double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
  if (m == 0.0) return 0.0;
  const double a = v[0] / m, b = v[1] / m, c = v[2] / m;
  return m * sqrt(a * a + b * b + c * c);
}

/* A valid result (checked against the slip law) or B2B_ERR_RANGE with
 * nothing written; returns which (1: valid). */
static int ok_or_range(const char *ctx, const b2b_params *p, const problem *pb,
                       const double *hist_old, double mu, double shift_scaled) {
  outputs o;
  fill_outputs(&o);
  const int st = run(p, pb, hist_old, 12, &o, fresh_msg(), B2B_ERRMSG_LEN);
  if (st == B2B_ERR_RANGE) {
    check_failure(ctx, st, B2B_ERR_RANGE, "overflow", NULL);
    assert_untouched(&o, ctx);
    return 0;
  }
  ck_assert_int_eq(expect_ok(ctx, p, pb, hist_old, 12, &o), B2B_CONTACT_ACTIVE);
  const double L = mu * o.info[B2B_INFO_NORMAL_FORCE];
  const double *T = o.info + B2B_INFO_TANGENTIAL_FORCE;
  ck_assert_msg(o.info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_SLIP, "%s: state %g", ctx,
                o.info[B2B_INFO_FRICTION_STATE]);
  ck_assert_msg(fabs(vnorm(T) - L) <= 1e-12 * L, "%s: |T| = %g, mu f_N = %g", ctx, vnorm(T), L);
  ck_assert_msg(T[0] > 0.999 * L, "%s: T not along the displacement", ctx);
  /* the slip cannot exceed the imposed displacement (up to rounding) */
  ck_assert_msg(o.info[B2B_INFO_SLIP] > 0.0 && o.info[B2B_INFO_SLIP] <= shift_scaled * (1 + 1e-12),
                "%s: slip %.17g, displacement %.17g", ctx, o.info[B2B_INFO_SLIP], shift_scaled);
  ck_assert(o.info[B2B_INFO_DISSIPATION] >= 0.0);
  return 1;
}

START_TEST(huge_tangential_penalty_and_displacement) {
  char ctx[128];
  const double eps_t[] = {1e300, 1e3};
  const double scales[] = {1.0, 1e10, 1e90, 1e-10, 1e-90};
  int valid = 0, range = 0;
  for (int e = 0; e < 2; ++e) {
    b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, eps_t[e]);
    for (int s = 0; s < 5; ++s) {
      problem pb;
      outputs o;
      double h0[HMAX] = {0}, h1[HMAX];
      make_problem(0.0, scales[s], &pb);
      CTX("eps_T %g, scale %g, first step", eps_t[e], scales[s]);
      ck_assert_int_eq(expect_ok(ctx, p, &pb, h0, 12, &o), B2B_CONTACT_ACTIVE);
      memcpy(h1, o.hist_new, sizeof h1);
      make_problem(0.3, scales[s], &pb); /* A moves by 0.3 scale along x */
      CTX("eps_T %g, displacement %g", eps_t[e], 0.3 * scales[s]);
      const int r = ok_or_range(ctx, p, &pb, h1, MU, 0.3 * scales[s]);
      printf("%s: %s\n", ctx, r ? "valid (slip)" : "B2B_ERR_RANGE");
      valid += r;
      range += !r;
    }
    b2b_params_destroy(&p);
  }
  /* every case is one or the other, and both occur: the overflow is reported
   * as B2B_ERR_RANGE, the rest is valid */
  printf("%d valid, %d B2B_ERR_RANGE\n", valid, range);
  ck_assert_int_ge(valid, 1);
  ck_assert_int_eq(valid + range, 10);
}
END_TEST

/* Scale invariance at the extremes: with coordinates and radii scaled by
 * s (penalties fixed), gaps, slips, forces and the residual scale by s and
 * the tangent is unchanged, in stick and in slip, from s = 1e-90 to 1e90. */
START_TEST(friction_scales_with_the_coordinates) {
  const double scales[] = {1e-90, 1e-10, 1e10, 1e90};
  const double shifts[2] = {0.001, 0.3}; /* stick (eps_T 0.001 < mu f_N), slip */
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  for (int k = 0; k < 2; ++k) {
    outputs ref, o;
    problem pb;
    double h0[HMAX] = {0}, h1[HMAX];
    make_problem(0.0, 1.0, &pb);
    expect_ok("scale 1, first step", p, &pb, h0, 12, &ref);
    memcpy(h1, ref.hist_new, sizeof h1);
    make_problem(shifts[k], 1.0, &pb);
    expect_ok("scale 1, moved", p, &pb, h1, 12, &ref);
    ck_assert(ref.info[B2B_INFO_FRICTION_STATE] == (k ? B2B_FRICTION_SLIP : B2B_FRICTION_STICK));
    for (int j = 0; j < 4; ++j) {
      const double sc = scales[j];
      char ctx[96];
      CTX("scale %g, %s", sc, k ? "slip" : "stick");
      make_problem(0.0, sc, &pb);
      expect_ok(ctx, p, &pb, h0, 12, &o);
      memcpy(h1, o.hist_new, sizeof h1);
      make_problem(shifts[k], sc, &pb);
      expect_ok(ctx, p, &pb, h1, 12, &o);
      ck_assert_msg(o.info[B2B_INFO_FRICTION_STATE] == ref.info[B2B_INFO_FRICTION_STATE],
                    "%s: friction state %g", ctx, o.info[B2B_INFO_FRICTION_STATE]);
      const int scaled[] = {B2B_INFO_GAP, B2B_INFO_NORMAL_FORCE, B2B_INFO_TANGENTIAL_FORCE,
                            B2B_INFO_TANGENTIAL_FORCE + 1, B2B_INFO_TANGENTIAL_FORCE + 2,
                            B2B_INFO_SLIP, B2B_INFO_SLIP + 1, B2B_INFO_SLIP + 2};
      for (int i = 0; i < 8; ++i) {
        const double want = ref.info[scaled[i]] * sc, got = o.info[scaled[i]];
        ck_assert_msg(fabs(got - want) <= 1e-11 * fabs(sc) * (1 + fabs(ref.info[scaled[i]])),
                      "%s: info[%d] = %g, want %g", ctx, scaled[i], got, want);
      }
      double rmax = 0.0, kmax = 0.0, rerr = 0.0, kerr = 0.0;
      for (int i = 0; i < 24; ++i) {
        rmax = fmax(rmax, fabs(ref.residual[i]));
        rerr = fmax(rerr, fabs(o.residual[i] / sc - ref.residual[i]));
      }
      for (int i = 0; i < 576; ++i) {
        kmax = fmax(kmax, fabs(ref.tangent[i]));
        kerr = fmax(kerr, fabs(o.tangent[i] - ref.tangent[i]));
      }
      ck_assert_msg(rerr <= 1e-11 * rmax, "%s: residual / s differs by %g (rel.)", ctx,
                    rerr / rmax);
      ck_assert_msg(kerr <= 1e-9 * kmax, "%s: tangent differs by %g (rel.)", ctx, kerr / kmax);
    }
  }
  b2b_params_destroy(&p);
}
END_TEST

/* A tiny stick stiffness: stick with a tiny force; and with a tiny
 * coefficient too, slip at once; finite outputs either way.
 * Also a trial force whose square underflows (|T_trial| ~ 3e-301), which
 * must still slip at the Coulomb limit. */
START_TEST(tiny_tangential_penalty) {
  const double eps = 1e-300;
  problem pb;
  outputs o;
  double h0[HMAX] = {0}, h1[HMAX];
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, eps);
  make_problem(0.0, 1.0, &pb);
  ck_assert_int_eq(expect_ok("tiny eps_T, first step", p, &pb, h0, 12, &o), B2B_CONTACT_ACTIVE);
  memcpy(h1, o.hist_new, sizeof h1);
  make_problem(0.3, 1.0, &pb);
  ck_assert_int_eq(expect_ok("tiny eps_T, moved", p, &pb, h1, 12, &o), B2B_CONTACT_ACTIVE);
  ck_assert(o.info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK);
  ck_assert_msg(fabs(o.info[B2B_INFO_TANGENTIAL_FORCE] - eps * 0.3) <= 1e-10 * eps * 0.3,
                "tiny eps_T: T = %g, eps_T delta = %g", o.info[B2B_INFO_TANGENTIAL_FORCE],
                eps * 0.3);
  ck_assert(vnorm(o.info + B2B_INFO_TANGENTIAL_FORCE) <= MU * o.info[B2B_INFO_NORMAL_FORCE]);
  ck_assert(o.info[B2B_INFO_DISSIPATION] == 0.0);
  b2b_params_destroy(&p);

  /* mu f_N = 5e-159 < eps_T delta = 3e-151: slip */
  const double eps2 = 1e-150, mu = 1e-160;
  p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, mu, eps2);
  make_problem(0.0, 1.0, &pb);
  ck_assert_int_eq(expect_ok("tiny eps_T and mu, first step", p, &pb, h0, 12, &o),
                   B2B_CONTACT_ACTIVE);
  memcpy(h1, o.hist_new, sizeof h1);
  make_problem(0.3, 1.0, &pb);
  ck_assert(ok_or_range("tiny eps_T and mu, moved", p, &pb, h1, mu, 0.3) == 1);
  ck_assert_int_eq(expect_ok("tiny eps_T and mu, moved", p, &pb, h1, 12, &o),
                   B2B_CONTACT_ACTIVE);
  ck_assert(fabs(o.info[B2B_INFO_SLIP] - 0.3) <= 1e-8);
  b2b_params_destroy(&p);

  /* |T_trial| = 3e-301 (its square underflows) against mu f_N = 5e-305: slip
   * at the Coulomb limit (a norm computed as sqrt(T.T) read 0 and stuck). */
  const double eps3 = 1e-300, mu3 = 1e-306;
  p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, mu3, eps3);
  make_problem(0.0, 1.0, &pb);
  ck_assert_int_eq(expect_ok("underflowing trial force, first step", p, &pb, h0, 12, &o),
                   B2B_CONTACT_ACTIVE);
  memcpy(h1, o.hist_new, sizeof h1);
  make_problem(0.3, 1.0, &pb);
  ck_assert_int_eq(expect_ok("underflowing trial force, moved", p, &pb, h1, 12, &o),
                   B2B_CONTACT_ACTIVE);
  const double limit = mu3 * o.info[B2B_INFO_NORMAL_FORCE];
  ck_assert(o.info[B2B_INFO_FRICTION_STATE] == B2B_FRICTION_SLIP);
  ck_assert_msg(fabs(vnorm(o.info + B2B_INFO_TANGENTIAL_FORCE) - limit) <= 1e-10 * limit,
                "underflowing trial force: |T| = %g, mu f_N = %g",
                vnorm(o.info + B2B_INFO_TANGENTIAL_FORCE), limit);
  ck_assert(o.info[B2B_INFO_DISSIPATION] >= 0.0);
  b2b_params_destroy(&p);
}
END_TEST

/* ======================================================= handover */

#define BEAM_N 6

/* A curved open beam of BEAM_N nodes with uneven elements (HERMITE_NODAL),
 * its segments 2 and 3 (sharing node 3), and the history of segment 2's pair
 * with a straight probe crossing it near xi = 0.8 (in contact, with force). */
typedef struct {
  int seg[BEAM_N][3];
  double X[BEAM_N][12];
  double hist[HMAX];
} beam_fixture;

static void beam_nodes(double *c) {
  const double s[BEAM_N] = {0.0, 1.0, 2.3, 3.0, 4.4, 5.0};
  for (int k = 0; k < BEAM_N; ++k) {
    c[3 * k] = s[k];
    c[3 * k + 1] = 0.1 * s[k] * s[k];
    c[3 * k + 2] = 0.0;
  }
}

static void make_fixture(const b2b_params *p, beam_fixture *f) {
  double c[3 * BEAM_N];
  beam_nodes(c);
  for (int s = 0; s < BEAM_N - 1; ++s) {
    f->seg[s][0] = NOD;
    tst_gather_patch(NOD, BEAM_N, 0, s, c, f->X[s], &f->seg[s][1], &f->seg[s][2]);
  }
  /* a probe along z through segment 2's point xi = 0.8, just touching */
  double x[9];
  tst_eval(NOD, f->seg[2][1], f->seg[2][2], f->X[2], NULL, 0.8, x, NULL, NULL);
  double nrm[3] = {-x[4], x[3], 0.0};
  const double l = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1]);
  const tst_pair_spec spec = {{NOD, LIN}, {f->seg[2][1], 0}, {f->seg[2][2], 0}, {0.1, 0.1}};
  double X[24];
  memcpy(X, f->X[2], sizeof f->X[2]);
  for (int i = 0; i < 3; ++i) X[12 + i] = X[21 + i] = NAN;
  for (int step = 0; step < 2; ++step) {
    const double shift = step * 0.004; /* second step: the probe moves along the beam */
    for (int i = 0; i < 2; ++i) {
      const double at = x[i] + 0.15 * nrm[i] / l + shift * x[3 + i] / hypot(x[3], x[4]);
      X[15 + i] = X[18 + i] = at;
    }
    X[17] = -0.5;
    X[20] = 0.5;
    double h[HMAX], info[32], R[24];
    ck_assert_int_eq(tst_pair(p, &spec, X, step ? f->hist : NULL, h, info, R, NULL),
                     B2B_CONTACT_ACTIVE);
    memcpy(f->hist, h, sizeof h);
  }
  for (int i = tst_history_len(p); i < HMAX; ++i) f->hist[i] = 0.0;
}

typedef struct {
  const b2b_params *params;
  int beam, direction;
  int from_seg[3], to_seg[3];
  double from_X[12], to_X[12];
  const double *from_tan, *to_tan;
  double hist_from[HMAX];
  int hist_len;
  unsigned null_args;
} handover_call;

enum { H_FROM_SEG = 1, H_FROM_X = 2, H_TO_SEG = 4, H_TO_X = 8, H_HIST_FROM = 16, H_HIST_TO = 32 };

static void base_handover(const b2b_params *p, const beam_fixture *f, int from, int to,
                          handover_call *c) {
  memset(c, 0, sizeof *c);
  c->params = p;
  c->beam = 0;
  c->direction = to > from ? 1 : -1;
  memcpy(c->from_seg, f->seg[from], sizeof c->from_seg);
  memcpy(c->to_seg, f->seg[to], sizeof c->to_seg);
  memcpy(c->from_X, f->X[from], sizeof c->from_X);
  memcpy(c->to_X, f->X[to], sizeof c->to_X);
  memcpy(c->hist_from, f->hist, sizeof c->hist_from);
  c->hist_len = p ? tst_history_len(p) : 12;
}

static int run_handover(const handover_call *c, double *hist_to, char *msg, int len) {
  const unsigned z = c->null_args;
  return b2b_pair_history_handover(
      c->params, c->beam, c->direction, (z & H_FROM_SEG) ? NULL : c->from_seg,
      (z & H_FROM_X) ? NULL : c->from_X, c->from_tan, (z & H_TO_SEG) ? NULL : c->to_seg,
      (z & H_TO_X) ? NULL : c->to_X, c->to_tan, (z & H_HIST_FROM) ? NULL : c->hist_from,
      (z & H_HIST_TO) ? NULL : hist_to, c->hist_len, msg, len);
}

static void expect_handover_fail(const char *ctx, const handover_call *c, int want,
                                 const char *w1, const char *w2) {
  const handover_call before = *c;
  double to[HMAX];
  for (int i = 0; i < HMAX; ++i) to[i] = SENT;
  check_failure(ctx, run_handover(c, to, fresh_msg(), B2B_ERRMSG_LEN), want, w1, w2);
  for (int i = 0; i < HMAX; ++i)
    ck_assert_msg(to[i] == SENT, "%s: hist_to[%d] written on failure", ctx, i);
  ck_assert_msg(memcmp(&before, c, sizeof before) == 0, "%s: an input was modified", ctx);
  ck_assert_msg(run_handover(c, to, NULL, 0) == want, "%s: another status with errmsg NULL", ctx);
  for (int i = 0; i < HMAX; ++i) ck_assert(to[i] == SENT);
}

static void expect_handover_ok(const char *ctx, const handover_call *c, double to[HMAX]) {
  for (int i = 0; i < HMAX; ++i) to[i] = SENT;
  check_success(ctx, run_handover(c, to, fresh_msg(), B2B_ERRMSG_LEN));
  for (int i = 0; i < HMAX; ++i)
    ck_assert_msg(i < c->hist_len ? isfinite(to[i]) && to[i] != SENT : to[i] == SENT,
                  "%s: hist_to[%d] = %g", ctx, i, to[i]);
}

/* |dx/dxi| of a segment at xi. */
static double speed(const int seg[3], const double X[12], double xi) {
  double x[9];
  tst_eval(seg[0], seg[1], seg[2], X, NULL, xi, x, NULL, NULL);
  return sqrt(x[3] * x[3] + x[4] * x[4] + x[5] * x[5]);
}

START_TEST(handover_null_arguments) {
  char ctx[128];
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  beam_fixture f;
  make_fixture(p, &f);
  handover_call c;
  base_handover(NULL, &f, 2, 3, &c);
  expect_handover_fail("params NULL", &c, B2B_ERR_NULL, "params", "NULL");
  const struct {
    unsigned bit;
    const char *name;
  } args[] = {{H_FROM_SEG, "from_segment"}, {H_FROM_X, "from_X"},       {H_TO_SEG, "to_segment"},
              {H_TO_X, "to_X"},             {H_HIST_FROM, "hist_from"}, {H_HIST_TO, "hist_to"}};
  for (size_t k = 0; k < sizeof args / sizeof args[0]; ++k) {
    base_handover(p, &f, 2, 3, &c);
    c.null_args = args[k].bit;
    CTX("%s NULL", args[k].name);
    expect_handover_fail(ctx, &c, B2B_ERR_NULL, args[k].name, "NULL");
  }
  /* end tangents: NULL is fine unless a rule in force is TANGENT */
  base_handover(p, &f, 0, 1, &c);
  c.from_seg[1] = B2B_END_TANGENT;
  expect_handover_fail("TANGENT rule, end tangents NULL", &c, B2B_ERR_NULL, "from segment",
                       "end_tangents");
  const double tan[6] = {1, 0, 0, 1, 0, 0};
  c.from_tan = tan;
  double to[HMAX];
  expect_handover_ok("TANGENT rule with end tangents", &c, to);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(handover_unknown_beam_or_direction_and_state) {
  char ctx[128];
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  beam_fixture f;
  make_fixture(p, &f);
  handover_call c;
  const int beams[] = {2, -1, 100};
  for (size_t k = 0; k < sizeof beams / sizeof beams[0]; ++k) {
    base_handover(p, &f, 2, 3, &c);
    c.beam = beams[k];
    CTX("beam %d", beams[k]);
    expect_handover_fail(ctx, &c, B2B_ERR_UNKNOWN_KIND, "beam", NULL);
  }
  const int dirs[] = {0, 2, -2};
  for (size_t k = 0; k < sizeof dirs / sizeof dirs[0]; ++k) {
    base_handover(p, &f, 2, 3, &c);
    c.direction = dirs[k];
    CTX("direction %d", dirs[k]);
    expect_handover_fail(ctx, &c, B2B_ERR_UNKNOWN_KIND, "direction", NULL);
  }
  /* unknown kind or rule of a segment */
  base_handover(p, &f, 2, 3, &c);
  c.to_seg[0] = 9;
  expect_handover_fail("to segment kind 9", &c, B2B_ERR_UNKNOWN_KIND, "to segment", NULL);
  base_handover(p, &f, 2, 3, &c);
  c.from_seg[2] = 7;
  expect_handover_fail("from segment rule 7", &c, B2B_ERR_UNKNOWN_KIND, "from segment", NULL);
  base_handover(p, &f, 2, 3, &c);
  c.from_X[4] = NAN;
  expect_handover_fail("from_X NaN", &c, B2B_ERR_NONFINITE, "from segment", NULL);
  /* params not finalized */
  b2b_params *q = new_params();
  ck_assert_int_eq(b2b_params_set_real(q, "friction", MU, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(q, "tangential_penalty", EPS_T, NULL, 0), B2B_OK);
  base_handover(p, &f, 2, 3, &c);
  c.params = q;
  expect_handover_fail("params not finalized", &c, B2B_ERR_STATE, "finalize", NULL);
  b2b_params_destroy(&q);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(handover_segments_not_sharing_the_joint) {
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  beam_fixture f;
  make_fixture(p, &f);
  handover_call c;
  double to[HMAX];
  base_handover(p, &f, 2, 4, &c); /* segment 4 does not follow segment 2 */
  expect_handover_fail("segment 2 -> 4", &c, B2B_ERR_RANGE, "joint", NULL);
  base_handover(p, &f, 2, 3, &c);
  c.direction = -1; /* segment 3 follows segment 2, it does not precede it */
  expect_handover_fail("segment 2 -> 3, direction -1", &c, B2B_ERR_RANGE, "joint", NULL);
  base_handover(p, &f, 3, 2, &c);
  c.direction = 1;
  expect_handover_fail("segment 3 -> 2, direction +1", &c, B2B_ERR_RANGE, "joint", NULL);
  /* the joint moved by 1e-6 of the length: not shared; by 1e-13: shared */
  base_handover(p, &f, 2, 3, &c);
  for (int k = 0; k < 4; ++k) c.to_X[3 * k + 2] += 1e-6;
  expect_handover_fail("joint apart by 1e-6", &c, B2B_ERR_RANGE, "joint", NULL);
  base_handover(p, &f, 2, 3, &c);
  for (int k = 0; k < 4; ++k) c.to_X[3 * k + 2] += 1e-13;
  expect_handover_ok("joint apart by 1e-13", &c, to);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(handover_bad_history) {
  char ctx[128];
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  beam_fixture f;
  make_fixture(p, &f);
  handover_call c;
  const int lens[] = {8, 11, 13, 0};
  for (size_t k = 0; k < sizeof lens / sizeof lens[0]; ++k) {
    base_handover(p, &f, 2, 3, &c);
    c.hist_len = lens[k];
    CTX("hist_len %d", lens[k]);
    expect_handover_fail(ctx, &c, B2B_ERR_SIZE, "hist_len", NULL);
  }
  base_handover(p, &f, 2, 3, &c);
  c.hist_from[9] = NAN;
  expect_handover_fail("hist_from[9] NaN", &c, B2B_ERR_NONFINITE, "hist_from[9]", NULL);
  base_handover(p, &f, 2, 3, &c);
  c.hist_from[0] = 7.0;
  expect_handover_fail("foreign tag", &c, B2B_ERR_RANGE, "hist_from", "tag");
  base_handover(p, &f, 2, 3, &c);
  c.hist_from[8] = 0.5;
  expect_handover_fail("in-contact 0.5", &c, B2B_ERR_RANGE, "hist_from", "in-contact");
  base_handover(p, &f, 2, 3, &c);
  c.hist_from[11] = 0.0;
  expect_handover_fail("in contact, state 0", &c, B2B_ERR_RANGE, "hist_from", "friction state");
  b2b_params_destroy(&p);
}
END_TEST

/* The mapping t' = -1 + (t - 1) s_from / s_to (direction +1) and
 * t' = 1 + (t + 1) s_from / s_to (direction -1), everything else copied. */
START_TEST(handover_maps_the_anchor) {
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, EPS_N, 0.0, MU, EPS_T);
  beam_fixture f;
  make_fixture(p, &f);
  ck_assert(f.hist[8] == 1.0 && f.hist[9] != 0.0 && fabs(f.hist[5] - 0.8) < 0.05);
  handover_call c;
  double fwd[HMAX], back[HMAX];
  const double s2 = speed(f.seg[2], f.X[2], 1.0), s3 = speed(f.seg[3], f.X[3], -1.0);
  ck_assert_msg(fabs(s2 / s3 - 1.0) > 0.1, "the test needs uneven speeds (%g, %g)", s2, s3);
  base_handover(p, &f, 2, 3, &c);
  expect_handover_ok("segment 2 -> 3", &c, fwd);
  const double want = -1.0 + (f.hist[5] - 1.0) * s2 / s3;
  ck_assert_msg(fabs(fwd[5] - want) <= 1e-14, "xi %.17g -> %.17g, expected %.17g", f.hist[5],
                fwd[5], want);
  for (int i = 0; i < 12; ++i)
    if (i != 5) ck_assert_msg(fwd[i] == f.hist[i], "entry %d changed by the handover", i);
  /* and back: the inverse map */
  base_handover(p, &f, 3, 2, &c);
  memcpy(c.hist_from, fwd, sizeof c.hist_from);
  expect_handover_ok("segment 3 -> 2", &c, back);
  ck_assert(fabs(back[5] - (1.0 + (fwd[5] + 1.0) * s3 / s2)) <= 1e-14);
  ck_assert_msg(fabs(back[5] - f.hist[5]) <= 1e-14, "round trip %.17g -> %.17g", f.hist[5],
                back[5]);
  /* beam B: eta is mapped, xi left alone */
  base_handover(p, &f, 2, 3, &c);
  c.beam = 1;
  expect_handover_ok("beam B", &c, fwd);
  ck_assert(fwd[5] == f.hist[5]);
  ck_assert(fabs(fwd[6] - (-1.0 + (f.hist[6] - 1.0) * s2 / s3)) <= 1e-14);
  /* in place */
  base_handover(p, &f, 2, 3, &c);
  check_success("in place", b2b_pair_history_handover(p, 0, 1, c.from_seg, c.from_X, NULL,
                                                      c.to_seg, c.to_X, NULL, c.hist_from,
                                                      c.hist_from, 12, fresh_msg(),
                                                      B2B_ERRMSG_LEN));
  ck_assert(fabs(c.hist_from[5] - want) <= 1e-14);
  /* a fresh history is copied unchanged */
  base_handover(p, &f, 2, 3, &c);
  memset(c.hist_from, 0, sizeof c.hist_from);
  expect_handover_ok("fresh history", &c, fwd);
  for (int i = 0; i < 12; ++i) ck_assert(fwd[i] == 0.0);
  b2b_params_destroy(&p);
  /* a frictionless history: mapped the same way */
  b2b_params *q = tst_params(B2B_LAW_LINEAR, EPS_N, 0.0);
  make_fixture(q, &f);
  base_handover(q, &f, 2, 3, &c);
  ck_assert_int_eq(c.hist_len, 8);
  expect_handover_ok("frictionless history", &c, fwd);
  ck_assert(fabs(fwd[5] - (-1.0 + (f.hist[5] - 1.0) * s2 / s3)) <= 1e-14);
  for (int i = 0; i < 8; ++i)
    if (i != 5) ck_assert(fwd[i] == f.hist[i]);
  c.hist_len = 12;
  expect_handover_fail("frictionless set, hist_len 12", &c, B2B_ERR_SIZE, "hist_len", NULL);
  b2b_params_destroy(&q);
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("pair_friction_bad_input");
  TCase *tp = tcase_create("options");
  tcase_add_test(tp, friction_out_of_range);
  tcase_add_test(tp, tangential_penalty_out_of_range);
  tcase_add_test(tp, friction_options_not_finite);
  tcase_add_test(tp, friction_options_read_back);
  tcase_add_test(tp, friction_without_tangential_penalty);
  suite_add_tcase(s, tp);
  TCase *th = tcase_create("histories");
  tcase_add_test(th, history_of_the_wrong_length);
  tcase_add_test(th, history_friction_slots_not_finite);
  tcase_add_test(th, history_friction_slots_out_of_range);
  tcase_add_test(th, huge_tangential_penalty_and_displacement);
  tcase_add_test(th, tiny_tangential_penalty);
  tcase_add_test(th, friction_scales_with_the_coordinates);
  suite_add_tcase(s, th);
  TCase *tho = tcase_create("handover");
  tcase_add_test(tho, handover_null_arguments);
  tcase_add_test(tho, handover_unknown_beam_or_direction_and_state);
  tcase_add_test(tho, handover_segments_not_sharing_the_joint);
  tcase_add_test(tho, handover_bad_history);
  tcase_add_test(tho, handover_maps_the_anchor);
  suite_add_tcase(s, tho);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
