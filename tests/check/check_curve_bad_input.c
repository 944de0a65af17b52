/* Bad input of the curve functions: b2b_segment_eval, b2b_beam_segment_count
 * and b2b_beam_segment_patch.
 *
 * For every documented bad input (see <b2b/b2b.h> "Messages", "Outputs" and
 * the "Bad input" paragraph of <b2b/b2b_curve.h>) each test checks
 *   - the documented status code,
 *   - a NUL-terminated message that names the problem (strstr on the node,
 *     the argument or the value), written within the buffer,
 *   - that no output was touched (outputs pre-filled with a sentinel),
 *   - the same code with fewer outputs and with errmsg = NULL, 0,
 * and, next to it, the closest input that is NOT an error (unused slots,
 * finite xi outside [-1, 1], nearly folded patches, extreme scales), which
 * must succeed with finite outputs and leave the message buffer alone. */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"

#define SENT 12345.0
#define SENT_INT (-777)
#define GUARD 'Z'
#define XI0 0.3

enum { NB = B2B_END_NEIGHBOUR, RF = B2B_END_REFLECT, TG = B2B_END_TANGENT };
enum { LIN = B2B_CURVE_LINEAR, MID = B2B_CURVE_HERMITE_MIDPOINT, NOD = B2B_CURVE_HERMITE_NODAL,
       NDW = B2B_CURVE_HERMITE_NODAL_WEIGHTED };

#define CTX(...) snprintf(ctx, sizeof ctx, __VA_ARGS__)

typedef struct {
  double x[9], dx[72], d2x[864];
} outputs;

static const double good_tangents[6] = {0.8, 0.5, -0.2, 0.7, -0.4, 0.3};

static const char *rule_name(int r) {
  switch (r) {
    case NB: return "NEIGHBOUR";
    case RF: return "REFLECT";
    case TG: return "TANGENT";
    default: return "?";
  }
}

static int is_chord(int kind) { return tst_kind_family(kind) == TST_CHORD; }
static int is_centred(int kind) { return tst_kind_family(kind) == TST_CENTRED; }
static int is_nodal(int kind) { return tst_kind_family(kind) == TST_NODAL; }

/* A segment centred on a node (midpoint) cannot be both ends of its beam
 * (documented RANGE). */
static int valid_rules(int kind, int sr, int er) {
  return !(is_centred(kind) && sr != NB && er != NB);
}

/* The slots a kind reads, straight from the table in <b2b/b2b_curve.h>
 * (bit k: slot x(k+1)). */
static unsigned used_slots(int kind, int sr, int er) {
  switch (tst_kind_family(kind)) {
    case TST_CHORD: return 0x6u;
    case TST_CENTRED: return 0x2u | (sr == NB ? 0x1u : 0u) | (er == NB ? 0x4u : 0u);
    case TST_NODAL: return 0x6u | (sr == NB ? 0x1u : 0u) | (er == NB ? 0x8u : 0u);
  }
  return 0u;
}

/* The tangent of the first/last node comes from end_tangents. */
static int start_tangent_in_force(int kind, int sr) { return !is_chord(kind) && sr == TG; }
static int end_tangent_in_force(int kind, int er) { return !is_chord(kind) && er == TG; }

/* A smooth, gently curved patch with elements of length about 1. */
static void base_patch(double p[12]) {
  tst_rng rng;
  tst_rng_seed(&rng, 20240611u);
  tst_random_patch(&rng, 1.0, 0.5, p);
}

static void copy_node(double *p, int to, int from) {
  for (int i = 0; i < 3; ++i) p[3 * to + i] = p[3 * from + i];
}

static double node_dist(const double *p, int a, int b) {
  double s = 0.0;
  for (int i = 0; i < 3; ++i) s += (p[3 * a + i] - p[3 * b + i]) * (p[3 * a + i] - p[3 * b + i]);
  return sqrt(s);
}

static void fill_outputs(outputs *o) {
  for (int i = 0; i < 9; ++i) o->x[i] = SENT;
  for (int i = 0; i < 72; ++i) o->dx[i] = SENT;
  for (int i = 0; i < 864; ++i) o->d2x[i] = SENT;
}

static void assert_untouched(const outputs *o, const char *ctx) {
  TST_ASSERT_ALL(int, i, 0, 9, o->x[i] == SENT,
                 "%s: x[%d] was written (%g) on failure", ctx, i, o->x[i]);
  TST_ASSERT_ALL(int, i, 0, 72, o->dx[i] == SENT,
                 "%s: dx[%d] was written (%g) on failure", ctx, i, o->dx[i]);
  TST_ASSERT_ALL(int, i, 0, 864, o->d2x[i] == SENT,
                 "%s: d2x[%d] was written (%g) on failure", ctx, i, o->d2x[i]);
}

static void assert_finite(const outputs *o, const char *ctx) {
  TST_ASSERT_ALL(int, i, 0, 9, isfinite(o->x[i]) && o->x[i] != SENT,
                 "%s: x[%d] = %g", ctx, i, o->x[i]);
  TST_ASSERT_ALL(int, i, 0, 72, isfinite(o->dx[i]) && o->dx[i] != SENT,
                 "%s: dx[%d] = %g", ctx, i, o->dx[i]);
  TST_ASSERT_ALL(int, i, 0, 864, isfinite(o->d2x[i]) && o->d2x[i] != SENT,
                 "%s: d2x[%d] = %g", ctx, i, o->d2x[i]);
}

static int outputs_equal(const outputs *a, const outputs *b) {
  return memcmp(a, b, sizeof *a) == 0;
}

/* b2b_segment_eval must fail with `want`, a message holding each non-NULL
 * word, and no output touched. It is called again with x only (unless
 * only_full is 1) and with no outputs at all (unless only_full is 1 or 2),
 * both with errmsg NULL, 0: same code. */
static void expect_fail(const char *ctx, int kind, int sr, int er, const double *patch,
                        const double *tang, double xi, int want, int only_full, const char *w1,
                        const char *w2, const char *w3) {
  outputs o;
  fill_outputs(&o);
  char msg[B2B_ERRMSG_LEN + 16];
  memset(msg, GUARD, sizeof msg);
  int st = b2b_segment_eval(kind, sr, er, patch, tang, xi, o.x, o.dx, o.d2x, msg, B2B_ERRMSG_LEN);
  ck_assert_msg(st == want, "%s: status %d (%s), expected %d (%s); message: %.*s", ctx, st,
                b2b_strerror(st), want, b2b_strerror(want), B2B_ERRMSG_LEN, msg);
  ck_assert_msg(memchr(msg, '\0', B2B_ERRMSG_LEN) != NULL, "%s: message not NUL-terminated",
                ctx);
  TST_ASSERT_ALL(size_t, i, B2B_ERRMSG_LEN, sizeof msg, msg[i] == GUARD,
                 "%s: message buffer overrun at byte %zu", ctx, i);
  ck_assert_msg(msg[0] != '\0', "%s: empty message", ctx);
  const char *w[3] = {w1, w2, w3};
  for (int k = 0; k < 3; ++k)
    if (w[k])
      ck_assert_msg(strstr(msg, w[k]) != NULL, "%s: message \"%s\" does not contain \"%s\"", ctx,
                    msg, w[k]);
  assert_untouched(&o, ctx);
  if (only_full == 1) return;
  fill_outputs(&o);
  st = b2b_segment_eval(kind, sr, er, patch, tang, xi, o.x, NULL, NULL, NULL, 0);
  ck_assert_msg(st == want, "%s (x only, errmsg NULL): status %d, expected %d", ctx, st, want);
  assert_untouched(&o, ctx);
  if (only_full == 2) return;
  st = b2b_segment_eval(kind, sr, er, patch, tang, xi, NULL, NULL, NULL, NULL, 0);
  ck_assert_msg(st == want, "%s (no outputs, errmsg NULL): status %d, expected %d", ctx, st,
                want);
}

/* b2b_segment_eval must succeed with every output finite and the message
 * buffer untouched. */
static void expect_ok(const char *ctx, int kind, int sr, int er, const double *patch,
                      const double *tang, double xi, outputs *o) {
  fill_outputs(o);
  char msg[B2B_ERRMSG_LEN];
  memset(msg, GUARD, sizeof msg);
  const int st =
      b2b_segment_eval(kind, sr, er, patch, tang, xi, o->x, o->dx, o->d2x, msg, (int)sizeof msg);
  ck_assert_msg(st == B2B_OK, "%s: status %d (%s): %.*s", ctx, st, b2b_strerror(st),
                (int)sizeof msg, msg);
  TST_ASSERT_ALL(size_t, i, 0, sizeof msg, msg[i] == GUARD,
                 "%s: a successful call wrote errmsg[%zu]", ctx, i);
  assert_finite(o, ctx);
}

/* ======================================================== coordinates */

/* Puts each bad value into each coordinate of each slot the kind reads, for
 * every rule combination, and expects status `want` with a message naming the
 * node and holding `word` (for non-finite values: "nan" or "inf" as well).
 * Returns the number of cases. */
static int bad_coordinate_cases(int kind, const double *bad, int n_bad, int want,
                                const char *word) {
  double p0[12];
  base_patch(p0);
  char ctx[256], node[8];
  int n_cases = 0;
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      const unsigned used = used_slots(kind, sr, er);
      for (int slot = 0; slot < 4; ++slot) {
        if (!(used & (1u << slot))) continue;
        snprintf(node, sizeof node, "x%d", slot + 1);
        for (int axis = 0; axis < 3; ++axis)
          for (int v = 0; v < n_bad; ++v) {
            double p[12];
            memcpy(p, p0, sizeof p);
            p[3 * slot + axis] = bad[v];
            CTX("%s (%s, %s): %c of %s = %.17g", tst_kind_name(kind), rule_name(sr),
                rule_name(er), "xyz"[axis], node, bad[v]);
            const char *value_word = isfinite(bad[v]) ? NULL : isnan(bad[v]) ? "nan" : "inf";
            expect_fail(ctx, kind, sr, er, p, good_tangents, XI0, want, 0, node, word,
                        value_word);
            ++n_cases;
          }
      }
    }
  return n_cases;
}

/* NaN, +Inf, -Inf in each coordinate of each slot the kind reads, for every
 * rule combination. */
START_TEST(test_nonfinite_coordinate) {
  const int kind = _i;
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  const int n_cases = bad_coordinate_cases(kind, bad, 3, B2B_ERR_NONFINITE, "finite");
  ck_assert_int_ge(n_cases, is_chord(kind) ? 9 * 2 * 9 : 9 * 2 * 3);
}
END_TEST

/* Anything in a slot the kind does not read (NaN, Inf, out of range, a copy
 * of a neighbour) is not an error and changes nothing; the derivatives with
 * respect to that slot are zero. */
START_TEST(test_unused_slots_not_read) {
  const int kind = _i;
  double p0[12];
  base_patch(p0);
  char ctx[256];
  int n_unused = 0;
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      const unsigned used = used_slots(kind, sr, er);
      outputs ref, o;
      CTX("%s (%s, %s): reference", tst_kind_name(kind), rule_name(sr), rule_name(er));
      expect_ok(ctx, kind, sr, er, p0, good_tangents, XI0, &ref);
      for (int slot = 0; slot < 4; ++slot) {
        if (used & (1u << slot)) continue;
        ++n_unused;
        for (int a = 3 * slot; a < 3 * slot + 3; ++a)
          for (int i = 0; i < 3; ++i) {
            ck_assert_msg(ref.dx[i + 3 * a] == 0.0 && ref.dx[36 + i + 3 * a] == 0.0,
                          "%s: non-zero derivative with respect to unused slot x%d", ctx,
                          slot + 1);
            for (int b = 0; b < 12; ++b) {
              ck_assert(ref.d2x[i + 3 * (a + 12 * b)] == 0.0);
              ck_assert(ref.d2x[i + 3 * (b + 12 * a)] == 0.0);
              ck_assert(ref.d2x[432 + i + 3 * (a + 12 * b)] == 0.0);
              ck_assert(ref.d2x[432 + i + 3 * (b + 12 * a)] == 0.0);
            }
          }
        const double junk[5] = {NAN, INFINITY, -INFINITY, 2e100, -DBL_MAX};
        for (int v = 0; v < 6; ++v) {
          double p[12];
          memcpy(p, p0, sizeof p);
          if (v < 5)
            for (int i = 0; i < 3; ++i) p[3 * slot + i] = junk[v];
          else
            copy_node(p, slot, slot == 0 || slot == 2 ? 1 : 2); /* coincident with x2 / x3 */
          CTX("%s (%s, %s): unused slot x%d = %s", tst_kind_name(kind), rule_name(sr),
              rule_name(er), slot + 1,
              v == 0 ? "NaN" : v == 1 ? "+Inf" : v == 2 ? "-Inf" : v == 3 ? "2e100"
                             : v == 4 ? "-DBL_MAX" : "a copy of its neighbour");
          expect_ok(ctx, kind, sr, er, p, good_tangents, XI0, &o);
          ck_assert_msg(outputs_equal(&o, &ref), "%s: the outputs changed", ctx);
        }
      }
    }
  /* Linear: x1, x4 in all 9 rule combinations; midpoint: x4 always, plus one
   * of x1/x3 at a beam end; nodal: x1 and/or x4 at beam ends. */
  const int want = is_chord(kind) ? 18 : is_centred(kind) ? 5 + 4 : 12;
  ck_assert_int_eq(n_unused, want);
}
END_TEST

/* A zero-length element of the patch. */
START_TEST(test_coincident_nodes) {
  const int kind = _i;
  double p0[12];
  base_patch(p0);
  char ctx[256];
  outputs o;
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      double p[12];
      /* x3 == x2: the element of every kind (midpoint: unless x3 is unused). */
      memcpy(p, p0, sizeof p);
      copy_node(p, 2, 1);
      CTX("%s (%s, %s): x3 == x2", tst_kind_name(kind), rule_name(sr), rule_name(er));
      if (is_centred(kind) && er != NB)
        expect_ok(ctx, kind, sr, er, p, good_tangents, XI0, &o);
      else
        expect_fail(ctx, kind, sr, er, p, good_tangents, XI0, B2B_ERR_COINCIDENT, 0, "x2", "x3",
                    "coincide");
      /* x1 == x2: element x1-x2 of the nodal and midpoint kinds. */
      memcpy(p, p0, sizeof p);
      copy_node(p, 0, 1);
      CTX("%s (%s, %s): x1 == x2", tst_kind_name(kind), rule_name(sr), rule_name(er));
      if (!is_chord(kind) && sr == NB)
        expect_fail(ctx, kind, sr, er, p, good_tangents, XI0, B2B_ERR_COINCIDENT, 0, "x1", "x2",
                    "coincide");
      else
        expect_ok(ctx, kind, sr, er, p, good_tangents, XI0, &o);
      /* x4 == x3: element x3-x4 of the nodal kinds. */
      memcpy(p, p0, sizeof p);
      copy_node(p, 3, 2);
      CTX("%s (%s, %s): x4 == x3", tst_kind_name(kind), rule_name(sr), rule_name(er));
      if (is_nodal(kind) && er == NB)
        expect_fail(ctx, kind, sr, er, p, good_tangents, XI0, B2B_ERR_COINCIDENT, 0, "x3", "x4",
                    "coincide");
      else
        expect_ok(ctx, kind, sr, er, p, good_tangents, XI0, &o);
      /* All four nodes at one point. */
      for (int k = 1; k < 4; ++k) copy_node(p, k, 0);
      CTX("%s (%s, %s): all nodes equal", tst_kind_name(kind), rule_name(sr), rule_name(er));
      expect_fail(ctx, kind, sr, er, p, good_tangents, XI0, B2B_ERR_COINCIDENT, 0, "coincide",
                  NULL, NULL);
    }
}
END_TEST

/* Nodes that differ only by rounding of their coordinates (~1e6), or by less
 * than B2B_LENGTH_MIN, coincide. */
START_TEST(test_coincident_up_to_rounding) {
  const int kind = _i;
  const int sr = NB, er = NB; /* every slot the kind has is read */
  double p0[12], p[12];
  char ctx[256];
  outputs o;
  base_patch(p0);
  for (int k = 0; k < 12; ++k) p0[k] += 1.0e6;
  CTX("%s: patch at 1e6", tst_kind_name(kind));
  expect_ok(ctx, kind, sr, er, p0, NULL, XI0, &o);

  memcpy(p, p0, sizeof p);
  for (int i = 0; i < 3; ++i) p[6 + i] = p[3 + i] * (1.0 + 1e-17);
  CTX("%s: x3 = x2 (1 + 1e-17) at 1e6", tst_kind_name(kind));
  expect_fail(ctx, kind, sr, er, p, NULL, XI0, B2B_ERR_COINCIDENT, 0, "x2", "x3", "coincide");

  for (int ulps = 1; ulps <= 2; ++ulps) {
    memcpy(p, p0, sizeof p);
    for (int i = 0; i < 3; ++i) {
      p[6 + i] = p[3 + i];
      for (int u = 0; u < ulps; ++u) p[6 + i] = nextafter(p[6 + i], INFINITY);
    }
    CTX("%s: x3 = x2 + %d ulp in each coordinate at 1e6", tst_kind_name(kind), ulps);
    expect_fail(ctx, kind, sr, er, p, NULL, XI0, B2B_ERR_COINCIDENT, 0, "x2", "x3", "coincide");
  }

  if (!is_chord(kind)) {
    memcpy(p, p0, sizeof p);
    for (int i = 0; i < 3; ++i) p[i] = p[3 + i] * (1.0 + 1e-17);
    CTX("%s: x1 = x2 (1 + 1e-17) at 1e6", tst_kind_name(kind));
    expect_fail(ctx, kind, sr, er, p, NULL, XI0, B2B_ERR_COINCIDENT, 0, "x1", "x2", "coincide");
  }
  if (is_nodal(kind)) {
    memcpy(p, p0, sizeof p);
    for (int i = 0; i < 3; ++i) p[9 + i] = nextafter(p[6 + i], -INFINITY);
    CTX("%s: x4 = x3 - 1 ulp at 1e6", tst_kind_name(kind));
    expect_fail(ctx, kind, sr, er, p, NULL, XI0, B2B_ERR_COINCIDENT, 0, "x3", "x4", "coincide");
  }

  /* A short but resolved element at 1e6 is fine (linear: only x2, x3 matter). */
  if (is_chord(kind)) {
    memcpy(p, p0, sizeof p);
    for (int i = 0; i < 3; ++i) p[6 + i] = p[3 + i];
    p[6] += 1.0e-4;
    CTX("linear: x3 = x2 + 1e-4 at 1e6");
    expect_ok(ctx, kind, sr, er, p, NULL, XI0, &o);
  }

  /* Below B2B_LENGTH_MIN: every element of the patch shorter than 1e-100. */
  base_patch(p);
  for (int k = 0; k < 12; ++k) p[k] *= 1.0e-101;
  CTX("%s: patch scaled by 1e-101", tst_kind_name(kind));
  expect_fail(ctx, kind, sr, er, p, NULL, XI0, B2B_ERR_COINCIDENT, 0, "coincide", NULL, NULL);
}
END_TEST

/* ============================================================= folds */

/* x1 == x3 (no tangent direction at x2) or x2 == x4 (none at x3). */
START_TEST(test_folded_patch) {
  const int kind = _i;
  if (!is_nodal(kind)) return; /* their tangent at x2 has the direction of x3 - x1 */
  double p0[12];
  base_patch(p0);
  char ctx[256];
  outputs o;
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      double p[12];
      memcpy(p, p0, sizeof p);
      copy_node(p, 0, 2);
      CTX("%s (%s, %s): x1 == x3", tst_kind_name(kind), rule_name(sr), rule_name(er));
      if (sr == NB)
        expect_fail(ctx, kind, sr, er, p, good_tangents, XI0, B2B_ERR_FOLDED, 0, "folds", "x1",
                    "tangent at x2");
      else
        expect_ok(ctx, kind, sr, er, p, good_tangents, XI0, &o);
      if (sr == NB) { /* and the message names x3 */
        char msg[B2B_ERRMSG_LEN];
        b2b_segment_eval(kind, sr, er, p, good_tangents, XI0, NULL, NULL, NULL, msg,
                         (int)sizeof msg);
        ck_assert_msg(strstr(msg, "x3") != NULL, "%s: \"%s\" does not name x3", ctx, msg);
      }

      memcpy(p, p0, sizeof p);
      copy_node(p, 3, 1);
      CTX("%s (%s, %s): x4 == x2", tst_kind_name(kind), rule_name(sr), rule_name(er));
      if (er == NB)
        expect_fail(ctx, kind, sr, er, p, good_tangents, XI0, B2B_ERR_FOLDED, 0, "folds", "x4",
                    "tangent at x3");
      else
        expect_ok(ctx, kind, sr, er, p, good_tangents, XI0, &o);

      memcpy(p, p0, sizeof p);
      copy_node(p, 0, 2);
      copy_node(p, 3, 1);
      CTX("%s (%s, %s): x1 == x3 and x4 == x2", tst_kind_name(kind), rule_name(sr),
          rule_name(er));
      if (sr == NB || er == NB)
        expect_fail(ctx, kind, sr, er, p, good_tangents, XI0, B2B_ERR_FOLDED, 0, "folds", NULL,
                    NULL);
      else
        expect_ok(ctx, kind, sr, er, p, good_tangents, XI0, &o);
    }
}
END_TEST

/* A fold up to rounding (coordinates ~1e6, x1 one ulp from x3, x4 one ulp
 * from x2) is a fold: the tangent's direction would be rounding noise. */
START_TEST(test_folded_up_to_rounding) {
  const int kind = _i;
  if (!is_nodal(kind)) return; /* as test_folded_patch */
  double p0[12];
  base_patch(p0);
  for (int k = 0; k < 12; ++k) p0[k] += 1.0e6;
  char ctx[256];
  for (int which = 1; which <= 2; ++which) {
    double p[12];
    memcpy(p, p0, sizeof p);
    for (int i = 0; i < 3; ++i) {
      if (which == 1) p[i] = nextafter(p[6 + i], INFINITY);
      if (which == 2) p[9 + i] = nextafter(p[3 + i], -INFINITY);
    }
    CTX("%s: %s at 1e6", tst_kind_name(kind), which == 1 ? "x1 = x3 + 1 ulp" : "x4 = x2 - 1 ulp");
    expect_fail(ctx, kind, NB, NB, p, NULL, XI0, B2B_ERR_FOLDED, 0, "folds",
                which == 1 ? "x1" : "x4", which == 1 ? "tangent at x2" : "tangent at x3");
  }
}
END_TEST

/* Sharply but not fully folded (x1 a thousandth of an element from x3, x4 as
 * near x2): still a valid patch with finite outputs. */
START_TEST(test_nearly_folded_patch) {
  const int kind = _i;
  if (!is_nodal(kind)) return; /* as test_folded_patch */
  double p0[12];
  base_patch(p0);
  const double h = node_dist(p0, 1, 2);
  const double d[3] = {0.36, -0.48, 0.8}; /* a unit vector */
  char ctx[256];
  outputs o;
  for (int which = 1; which <= 3; ++which) {
    double p[12];
    memcpy(p, p0, sizeof p);
    if (which & 1)
      for (int i = 0; i < 3; ++i) p[i] = p[6 + i] + 1e-3 * h * d[i];
    if (which & 2)
      for (int i = 0; i < 3; ++i) p[9 + i] = p[3 + i] - 1e-3 * h * d[i];
    for (int sr = NB; sr <= TG; ++sr)
      for (int er = NB; er <= TG; ++er) {
        CTX("%s (%s, %s): nearly folded (%s)", tst_kind_name(kind), rule_name(sr), rule_name(er),
            which == 1 ? "x1 ~ x3" : which == 2 ? "x4 ~ x2" : "both");
        for (int k = 0; k < 3; ++k) {
          const double xi = k == 0 ? -1.0 : k == 1 ? XI0 : 1.0;
          expect_ok(ctx, kind, sr, er, p, good_tangents, xi, &o);
        }
      }
  }
}
END_TEST

/* ================================================ kinds, rules, NULLs */

START_TEST(test_unknown_kind) {
  const int bad[] = {-1, B2B_CURVE_KIND_COUNT, 1000, INT_MIN, INT_MAX};
  double p[12];
  base_patch(p);
  char ctx[256], num[32];
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k)
    for (int r = 0; r < 3; ++r) {
      const int sr = r == 0 ? NB : r == 1 ? RF : TG, er = r == 0 ? NB : r == 1 ? NB : TG;
      snprintf(num, sizeof num, "%d", bad[k]);
      CTX("kind %d (%s, %s)", bad[k], rule_name(sr), rule_name(er));
      expect_fail(ctx, bad[k], sr, er, p, good_tangents, XI0, B2B_ERR_UNKNOWN_KIND, 0, "kind",
                  num, NULL);
    }
}
END_TEST

START_TEST(test_unknown_rule) {
  const int kind = _i;
  const int bad[] = {3, -1, 1000, INT_MIN};
  double p[12];
  base_patch(p);
  char ctx[256], num[32];
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
    snprintf(num, sizeof num, "%d", bad[k]);
    for (int good = NB; good <= TG; ++good) {
      CTX("%s: start_rule %d, end_rule %s", tst_kind_name(kind), bad[k], rule_name(good));
      expect_fail(ctx, kind, bad[k], good, p, good_tangents, XI0, B2B_ERR_UNKNOWN_KIND, 0,
                  "start_rule", num, NULL);
      CTX("%s: start_rule %s, end_rule %d", tst_kind_name(kind), rule_name(good), bad[k]);
      expect_fail(ctx, kind, good, bad[k], p, good_tangents, XI0, B2B_ERR_UNKNOWN_KIND, 0,
                  "end_rule", num, NULL);
    }
    CTX("%s: both rules %d", tst_kind_name(kind), bad[k]);
    expect_fail(ctx, kind, bad[k], bad[k], p, good_tangents, XI0, B2B_ERR_UNKNOWN_KIND, 0,
                "rule", num, NULL);
  }
}
END_TEST

START_TEST(test_null_patch) {
  const int kind = _i;
  char ctx[256];
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      CTX("%s (%s, %s): patch NULL", tst_kind_name(kind), rule_name(sr), rule_name(er));
      expect_fail(ctx, kind, sr, er, NULL, good_tangents, XI0, B2B_ERR_NULL, 0, "patch", "NULL",
                  NULL);
    }
}
END_TEST

/* TANGENT in force without end_tangents. LINEAR ignores its rules, so there
 * it is not an error. */
START_TEST(test_null_end_tangents) {
  const int kind = _i;
  double p[12];
  base_patch(p);
  char ctx[256];
  outputs o;
  int n_fail = 0;
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      CTX("%s (%s, %s): end_tangents NULL", tst_kind_name(kind), rule_name(sr), rule_name(er));
      if (start_tangent_in_force(kind, sr) || end_tangent_in_force(kind, er)) {
        expect_fail(ctx, kind, sr, er, p, NULL, XI0, B2B_ERR_NULL, 0, "end_tangents", "NULL",
                    "TANGENT");
        ++n_fail;
      } else {
        expect_ok(ctx, kind, sr, er, p, NULL, XI0, &o);
      }
    }
  ck_assert_int_eq(n_fail, is_chord(kind) ? 0 : is_centred(kind) ? 2 : 5);
}
END_TEST

/* ==================================================== end tangents */

START_TEST(test_zero_end_tangent) {
  const int kind = _i;
  double p[12];
  base_patch(p);
  char ctx[256];
  outputs o;
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      for (int which = 0; which < 2; ++which) {
        double t[6];
        memcpy(t, good_tangents, sizeof t);
        t[3 * which] = t[3 * which + 1] = t[3 * which + 2] = 0.0;
        if (which == 1) t[4] = -0.0;
        const int in_force =
            which == 0 ? start_tangent_in_force(kind, sr) : end_tangent_in_force(kind, er);
        CTX("%s (%s, %s): zero tangent at the %s node", tst_kind_name(kind), rule_name(sr),
            rule_name(er), which == 0 ? "first" : "last");
        if (in_force)
          expect_fail(ctx, kind, sr, er, p, t, XI0, B2B_ERR_RANGE, 0, "zero vector",
                      which == 0 ? "first" : "last", NULL);
        else
          expect_ok(ctx, kind, sr, er, p, t, XI0, &o);
      }
    }
}
END_TEST

START_TEST(test_nonfinite_end_tangent) {
  const int kind = _i;
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  double p[12];
  base_patch(p);
  char ctx[256];
  outputs o;
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      for (int c = 0; c < 6; ++c)
        for (int v = 0; v < 3; ++v) {
          double t[6];
          memcpy(t, good_tangents, sizeof t);
          t[c] = bad[v];
          const int in_force =
              c < 3 ? start_tangent_in_force(kind, sr) : end_tangent_in_force(kind, er);
          CTX("%s (%s, %s): end_tangents[%d] = %g", tst_kind_name(kind), rule_name(sr),
              rule_name(er), c, bad[v]);
          if (in_force)
            expect_fail(ctx, kind, sr, er, p, t, XI0, B2B_ERR_NONFINITE, 0, "end tangent",
                        c < 3 ? "first" : "last", isnan(bad[v]) ? "nan" : "inf");
          else
            expect_ok(ctx, kind, sr, er, p, t, XI0, &o);
        }
    }
}
END_TEST

/* Only the direction of a host tangent is used: any non-zero finite length,
 * from the smallest subnormal to DBL_MAX, gives the same segment. */
START_TEST(test_end_tangent_any_length) {
  const int kind = _i;
  if (is_chord(kind)) return; /* the chord reads no host tangent */
  const double scales[] = {4.9406564584124654e-324, 1e-300, 1e-10, 1e10, 1e300, DBL_MAX};
  double p[12];
  base_patch(p);
  char ctx[256];
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er) || (sr != TG && er != TG)) continue;
      const double t1[6] = {1, 1, 0, 0, -1, 1};
      outputs ref, o;
      CTX("%s (%s, %s): tangents of length sqrt 2", tst_kind_name(kind), rule_name(sr),
          rule_name(er));
      expect_ok(ctx, kind, sr, er, p, t1, XI0, &ref);
      for (size_t k = 0; k < sizeof scales / sizeof scales[0]; ++k) {
        double t[6];
        for (int c = 0; c < 6; ++c) t[c] = t1[c] * scales[k];
        CTX("%s (%s, %s): tangents scaled by %g", tst_kind_name(kind), rule_name(sr),
            rule_name(er), scales[k]);
        expect_ok(ctx, kind, sr, er, p, t, XI0, &o);
        ck_assert_msg(tst_rel_diff(o.x, ref.x, 9, 0.0) <= 1e-15 &&
                          tst_rel_diff(o.dx, ref.dx, 72, 0.0) <= 1e-15 &&
                          tst_rel_diff(o.d2x, ref.d2x, 864, 1e-300) <= 1e-15,
                      "%s: the segment depends on the tangent's length", ctx);
      }
    }
}
END_TEST

/* ============================================================= xi */

START_TEST(test_nonfinite_xi) {
  const int kind = _i;
  const double bad[3] = {NAN, INFINITY, -INFINITY};
  double p[12];
  base_patch(p);
  char ctx[256];
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      for (int v = 0; v < 3; ++v) {
        CTX("%s (%s, %s): xi = %g", tst_kind_name(kind), rule_name(sr), rule_name(er), bad[v]);
        expect_fail(ctx, kind, sr, er, p, good_tangents, bad[v], B2B_ERR_NONFINITE, 0, "xi",
                    isnan(bad[v]) ? "nan" : "inf", NULL);
      }
    }
}
END_TEST

/* Lagrange weights of the cubic through xi = -1, -1/3, 1/3, 1 at t. */
static void cubic_weights(double t, double w[4]) {
  const double s[4] = {-1.0, -1.0 / 3.0, 1.0 / 3.0, 1.0};
  for (int k = 0; k < 4; ++k) {
    w[k] = 1.0;
    for (int j = 0; j < 4; ++j)
      if (j != k) w[k] *= (t - s[j]) / (s[k] - s[j]);
  }
}

/* Finite xi outside [-1, 1] is valid: the cubic extends (so every output is
 * the cubic through its values inside the segment). */
START_TEST(test_xi_outside_segment) {
  const int kind = _i;
  const double xis[] = {3.5, -20.0, 100.0, -1.5};
  const double nodes_xi[4] = {-1.0, -1.0 / 3.0, 1.0 / 3.0, 1.0};
  double p[12];
  base_patch(p);
  char ctx[256];
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      static outputs in[4];
      for (int k = 0; k < 4; ++k) {
        CTX("%s (%s, %s): xi = %g", tst_kind_name(kind), rule_name(sr), rule_name(er),
            nodes_xi[k]);
        expect_ok(ctx, kind, sr, er, p, good_tangents, nodes_xi[k], &in[k]);
      }
      for (size_t j = 0; j < sizeof xis / sizeof xis[0]; ++j) {
        outputs o;
        static outputs ex;
        CTX("%s (%s, %s): xi = %g", tst_kind_name(kind), rule_name(sr), rule_name(er), xis[j]);
        expect_ok(ctx, kind, sr, er, p, good_tangents, xis[j], &o);
        double w[4];
        cubic_weights(xis[j], w);
        for (int i = 0; i < 9; ++i) {
          ex.x[i] = 0;
          for (int k = 0; k < 4; ++k) ex.x[i] += w[k] * in[k].x[i];
        }
        for (int i = 0; i < 72; ++i) {
          ex.dx[i] = 0;
          for (int k = 0; k < 4; ++k) ex.dx[i] += w[k] * in[k].dx[i];
        }
        for (int i = 0; i < 864; ++i) {
          ex.d2x[i] = 0;
          for (int k = 0; k < 4; ++k) ex.d2x[i] += w[k] * in[k].d2x[i];
        }
        ck_assert_msg(tst_rel_diff(o.x, ex.x, 9, 1.0) < 1e-9, "%s: x is not the cubic (%g)", ctx,
                      tst_rel_diff(o.x, ex.x, 9, 1.0));
        ck_assert_msg(tst_rel_diff(o.dx, ex.dx, 72, 1.0) < 1e-9, "%s: dx is not the cubic (%g)",
                      ctx, tst_rel_diff(o.dx, ex.dx, 72, 1.0));
        ck_assert_msg(tst_rel_diff(o.d2x, ex.d2x, 864, 1.0) < 1e-9,
                      "%s: d2x is not the cubic (%g)", ctx, tst_rel_diff(o.d2x, ex.d2x, 864, 1.0));
      }
    }
}
END_TEST

/* An absurd finite xi overflows the cubic: B2B_ERR_RANGE, nothing written. */
START_TEST(test_xi_overflow) {
  const int kind = _i;
  const double xis[] = {1e200, -1e200, DBL_MAX, -DBL_MAX};
  double p[12];
  base_patch(p);
  char ctx[256];
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      for (size_t j = 0; j < sizeof xis / sizeof xis[0]; ++j) {
        CTX("%s (%s, %s): xi = %g", tst_kind_name(kind), rule_name(sr), rule_name(er), xis[j]);
        if (is_chord(kind)) {
          /* The chord and its derivatives stay finite at 1e200 (they grow
           * like xi, not xi^3); DBL_MAX is left to the all-or-nothing test. */
          if (fabs(xis[j]) < DBL_MAX) {
            outputs o;
            expect_ok(ctx, kind, sr, er, p, good_tangents, xis[j], &o);
          }
          continue;
        }
        /* Full outputs, and x only; without outputs nothing is computed, so
         * nothing overflows. */
        expect_fail(ctx, kind, sr, er, p, good_tangents, xis[j], B2B_ERR_RANGE, 2, "xi",
                    "overflow", NULL);
      }
    }
}
END_TEST

/* Whatever xi does to the outputs, the result is all or nothing: OK with every
 * requested output finite, or B2B_ERR_RANGE with none touched. */
START_TEST(test_xi_overflow_all_or_nothing) {
  const int kind = _i;
  const double xis[] = {1e100, 1e101, 1e102, 3e102,  5e102,  6.3e102,
                        1e103, 1e150, 1e154, 1e155, 1e200, DBL_MAX};
  double p[12];
  base_patch(p);
  for (int mask = 1; mask < 8; ++mask)
    for (size_t j = 0; j < sizeof xis / sizeof xis[0]; ++j)
      for (int sign = -1; sign <= 1; sign += 2) {
        outputs o;
        fill_outputs(&o);
        char msg[B2B_ERRMSG_LEN] = "";
        const double xi = sign * xis[j];
        const int st = b2b_segment_eval(kind, NB, NB, p, NULL, xi, (mask & 1) ? o.x : NULL,
                                        (mask & 2) ? o.dx : NULL, (mask & 4) ? o.d2x : NULL, msg,
                                        (int)sizeof msg);
        ck_assert_msg(st == B2B_OK || st == B2B_ERR_RANGE, "%s xi=%g: status %d: %s",
                      tst_kind_name(kind), xi, st, msg);
        const int n[3] = {9, 72, 864};
        const double *arr[3] = {o.x, o.dx, o.d2x};
        for (int a = 0; a < 3; ++a)
          for (int i = 0; i < n[a]; ++i) {
            const double v = arr[a][i];
            if (st == B2B_OK && (mask & (1 << a)))
              ck_assert_msg(isfinite(v), "%s xi=%g outputs %d: output %d[%d] = %g on success",
                            tst_kind_name(kind), xi, mask, a, i, v);
            else
              ck_assert_msg(v == SENT, "%s xi=%g outputs %d: output %d[%d] written (st %d)",
                            tst_kind_name(kind), xi, mask, a, i, st);
          }
      }
}
END_TEST

/* ======================================================= magnitudes */

START_TEST(test_coordinate_beyond_max) {
  const int kind = _i;
  const double bad[] = {2e100, -2e100, 1e101, DBL_MAX, -DBL_MAX,
                        nextafter(B2B_COORD_MAX, INFINITY)};
  ck_assert_int_gt(bad_coordinate_cases(kind, bad, (int)(sizeof bad / sizeof bad[0]),
                                        B2B_ERR_RANGE, "B2B_COORD_MAX"),
                   0);
}
END_TEST

/* Coordinates of magnitude exactly B2B_COORD_MAX are accepted (a regular
 * tetrahedron of corners (+-1, +-1, +-1) * 1e100). */
START_TEST(test_coordinate_at_max) {
  const int kind = _i;
  const double M = B2B_COORD_MAX;
  const double p[12] = {-M, M, -M, M, M, M, M, -M, -M, -M, -M, M};
  char ctx[256];
  outputs o;
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      for (int k = 0; k < 3; ++k) {
        const double xi = k == 0 ? -1.0 : k == 1 ? XI0 : 1.0;
        CTX("%s (%s, %s): coordinates +-B2B_COORD_MAX, xi = %g", tst_kind_name(kind),
            rule_name(sr), rule_name(er), xi);
        expect_ok(ctx, kind, sr, er, p, good_tangents, xi, &o);
      }
    }
}
END_TEST

/* Tiny, huge and far-off patches succeed, and the curve scales with them:
 * x ~ s, dx/dX ~ 1, d2x/dX2 ~ 1/s. */
START_TEST(test_extreme_scales) {
  const int kind = _i;
  const double scales[] = {1e-90, 1e90, 1e-99, 1e99};
  char ctx[256];
  tst_rng rng;
  tst_rng_seed(&rng, 77u);
  for (int trial = 0; trial < 4; ++trial) {
    double p0[12];
    tst_random_patch(&rng, 1.0, 0.8, p0);
    for (int sr = NB; sr <= TG; ++sr)
      for (int er = NB; er <= TG; ++er) {
        if (!valid_rules(kind, sr, er)) continue;
        outputs ref, o;
        CTX("%s (%s, %s): unit patch %d", tst_kind_name(kind), rule_name(sr), rule_name(er),
            trial);
        expect_ok(ctx, kind, sr, er, p0, good_tangents, XI0, &ref);
        for (size_t k = 0; k < sizeof scales / sizeof scales[0] + 1; ++k) {
          const int offset = k == sizeof scales / sizeof scales[0];
          const double s = offset ? 1.0 : scales[k];
          double p[12];
          for (int c = 0; c < 12; ++c) p[c] = offset ? p0[c] + 1e8 : p0[c] * s;
          if (offset)
            CTX("%s (%s, %s): patch %d offset by 1e8", tst_kind_name(kind), rule_name(sr),
                rule_name(er), trial);
          else
            CTX("%s (%s, %s): patch %d scaled by %g", tst_kind_name(kind), rule_name(sr),
                rule_name(er), trial, s);
          expect_ok(ctx, kind, sr, er, p, good_tangents, XI0, &o);
          /* Back to the unit patch. */
          for (int i = 0; i < 9; ++i) o.x[i] = (offset && i < 3) ? o.x[i] - 1e8 : o.x[i] / s;
          for (int i = 0; i < 864; ++i) o.d2x[i] *= s;
          const double tol = offset ? 1e-6 : 1e-12;
          ck_assert_msg(tst_rel_diff(o.x, ref.x, 9, 1.0) < tol, "%s: x off by %g", ctx,
                        tst_rel_diff(o.x, ref.x, 9, 1.0));
          ck_assert_msg(tst_rel_diff(o.dx, ref.dx, 72, 1.0) < tol, "%s: dx off by %g", ctx,
                        tst_rel_diff(o.dx, ref.dx, 72, 1.0));
          ck_assert_msg(tst_rel_diff(o.d2x, ref.d2x, 864, 1.0) < tol, "%s: d2x off by %g", ctx,
                        tst_rel_diff(o.d2x, ref.d2x, 864, 1.0));
        }
      }
  }
}
END_TEST

/* ============================================================ ends */

/* A segment centred on a node (midpoint) that both starts and ends its beam
 * does not exist; one segment that is both ends is fine for the other kinds. */
START_TEST(test_midpoint_both_ends) {
  double p[12];
  base_patch(p);
  char ctx[256];
  outputs o;
  for (int sr = RF; sr <= TG; ++sr)
    for (int er = RF; er <= TG; ++er)
      for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
        CTX("%s (%s, %s)", tst_kind_name(kind), rule_name(sr), rule_name(er));
        if (is_centred(kind))
          expect_fail(ctx, kind, sr, er, p, good_tangents, XI0, B2B_ERR_RANGE, 0, "centred",
                      "both", NULL);
        else
          expect_ok(ctx, kind, sr, er, p, good_tangents, XI0, &o);
      }
}
END_TEST

/* ========================================================= messages */

/* A set of failing calls, one per kind of failure. */
typedef struct {
  const char *what;
  int kind, sr, er;
  int patch_null;
  int edit; /* 0 none, 1 NaN in x3, 2 x3 = x2, 3 x1 = x3, 4 x2 = 2e100 */
  int tangents;  /* 0 NULL, 1 good, 2 zero */
  double xi;
  int want;
} bad_call;

static const bad_call bad_calls[] = {
    {"patch NULL", NOD, NB, NB, 1, 0, 1, XI0, B2B_ERR_NULL},
    {"unknown kind", 7, NB, NB, 0, 0, 1, XI0, B2B_ERR_UNKNOWN_KIND},
    {"unknown rule", MID, 3, NB, 0, 0, 1, XI0, B2B_ERR_UNKNOWN_KIND},
    {"NaN coordinate", NDW, NB, NB, 0, 1, 1, XI0, B2B_ERR_NONFINITE},
    {"NaN xi", LIN, NB, NB, 0, 0, 1, NAN, B2B_ERR_NONFINITE},
    {"coincident", LIN, NB, NB, 0, 2, 1, XI0, B2B_ERR_COINCIDENT},
    {"folded", NDW, NB, NB, 0, 3, 1, XI0, B2B_ERR_FOLDED},
    {"coordinate range", MID, NB, NB, 0, 4, 1, XI0, B2B_ERR_RANGE},
    {"end_tangents NULL", NOD, TG, RF, 0, 0, 0, XI0, B2B_ERR_NULL},
    {"zero end tangent", NOD, TG, TG, 0, 0, 2, XI0, B2B_ERR_RANGE},
    {"midpoint both ends", MID, RF, RF, 0, 0, 1, XI0, B2B_ERR_RANGE},
    {"xi overflow", NOD, NB, NB, 0, 0, 1, 1e200, B2B_ERR_RANGE},
};
#define N_BAD_CALLS ((int)(sizeof bad_calls / sizeof bad_calls[0]))

static int run_bad_call(const bad_call *c, outputs *o, char *msg, int len) {
  static const double zero[6] = {0, 0, 0, 0, 0, 0};
  double p[12];
  base_patch(p);
  if (c->edit == 1) p[7] = NAN;
  if (c->edit == 2) copy_node(p, 2, 1);
  if (c->edit == 3) copy_node(p, 0, 2);
  if (c->edit == 4) p[4] = 2e100;
  const double *t = c->tangents == 0 ? NULL : c->tangents == 1 ? good_tangents : zero;
  return b2b_segment_eval(c->kind, c->sr, c->er, c->patch_null ? NULL : p, t, c->xi, o->x, o->dx,
                          o->d2x, msg, len);
}

/* errmsg = NULL, 0 is always allowed and returns the code; so is NULL with a
 * length; a buffer with length 0 or negative is not written. */
START_TEST(test_errmsg_null) {
  const bad_call *c = &bad_calls[_i];
  outputs o;
  fill_outputs(&o);
  ck_assert_msg(run_bad_call(c, &o, NULL, 0) == c->want, "%s: wrong code with NULL, 0", c->what);
  assert_untouched(&o, c->what);
  ck_assert_msg(run_bad_call(c, &o, NULL, B2B_ERRMSG_LEN) == c->want,
                "%s: wrong code with NULL, B2B_ERRMSG_LEN", c->what);
  assert_untouched(&o, c->what);
  for (int len = 0; len >= -1; --len) {
    char msg[B2B_ERRMSG_LEN];
    memset(msg, GUARD, sizeof msg);
    ck_assert_msg(run_bad_call(c, &o, msg, len) == c->want, "%s: wrong code with errmsg_len %d",
                  c->what, len);
    TST_ASSERT_ALL(size_t, i, 0, sizeof msg, msg[i] == GUARD,
                   "%s: errmsg_len %d but errmsg[%zu] written", c->what, len, i);
    assert_untouched(&o, c->what);
  }
}
END_TEST

/* A short buffer gets the start of the message, NUL-terminated within its
 * length, and nothing beyond it is written. */
START_TEST(test_errmsg_truncated) {
  const bad_call *c = &bad_calls[_i];
  outputs o;
  fill_outputs(&o);
  char full[B2B_ERRMSG_LEN];
  ck_assert_int_eq(run_bad_call(c, &o, full, (int)sizeof full), c->want);
  ck_assert_msg(strlen(full) > 20, "%s: message \"%s\" too short to test truncation", c->what,
                full);
  const int lens[] = {1, 2, 8, 19, 20, 40};
  for (size_t k = 0; k < sizeof lens / sizeof lens[0]; ++k) {
    const int len = lens[k];
    char buf[64];
    memset(buf, GUARD, sizeof buf);
    ck_assert_int_eq(run_bad_call(c, &o, buf, len), c->want);
    ck_assert_msg(memchr(buf, '\0', (size_t)len) != NULL,
                  "%s: errmsg_len %d, no NUL within the buffer", c->what, len);
    TST_ASSERT_ALL(size_t, i, (size_t)len, sizeof buf, buf[i] == GUARD,
                   "%s: errmsg_len %d, byte %zu written", c->what, len, i);
    const size_t want = strlen(full) < (size_t)len - 1 ? strlen(full) : (size_t)len - 1;
    ck_assert_msg(strlen(buf) == want && strncmp(buf, full, want) == 0,
                  "%s: errmsg_len %d gave \"%s\", not the first %zu characters of \"%s\"",
                  c->what, len, buf, want, full);
    assert_untouched(&o, c->what);
  }
}
END_TEST

/* Every message fits B2B_ERRMSG_LEN and distinct failures say distinct things. */
START_TEST(test_errmsg_distinct) {
  char msgs[N_BAD_CALLS][B2B_ERRMSG_LEN];
  for (int k = 0; k < N_BAD_CALLS; ++k) {
    outputs o;
    fill_outputs(&o);
    char big[2 * B2B_ERRMSG_LEN];
    memset(big, GUARD, sizeof big);
    ck_assert_int_eq(run_bad_call(&bad_calls[k], &o, big, (int)sizeof big), bad_calls[k].want);
    ck_assert_msg(strlen(big) < B2B_ERRMSG_LEN - 1, "%s: message longer than B2B_ERRMSG_LEN",
                  bad_calls[k].what);
    memcpy(msgs[k], big, B2B_ERRMSG_LEN);
    TST_ASSERT_ALL(int, j, 0, k, strcmp(msgs[j], msgs[k]) != 0,
                   "\"%s\" and \"%s\" give the same message", bad_calls[j].what, bad_calls[k].what);
  }
}
END_TEST

/* A successful call leaves the message buffer alone, whatever its length. */
START_TEST(test_success_leaves_errmsg) {
  const int kind = _i;
  double p[12];
  base_patch(p);
  for (int sr = NB; sr <= TG; ++sr)
    for (int er = NB; er <= TG; ++er) {
      if (!valid_rules(kind, sr, er)) continue;
      const int lens[] = {B2B_ERRMSG_LEN, 8, 1};
      for (size_t k = 0; k < 3; ++k) {
        char msg[B2B_ERRMSG_LEN];
        memset(msg, GUARD, sizeof msg);
        outputs o;
        fill_outputs(&o);
        const int st = b2b_segment_eval(kind, sr, er, p, good_tangents, XI0, o.x, o.dx, o.d2x,
                                        msg, lens[k]);
        ck_assert_int_eq(st, B2B_OK);
        TST_ASSERT_ALL(size_t, i, 0, sizeof msg, msg[i] == GUARD,
                       "%s (%s, %s), errmsg_len %d: errmsg[%zu] written", tst_kind_name(kind), rule_name(sr), rule_name(er), lens[k], i);
        assert_finite(&o, tst_kind_name(kind));
      }
    }
}
END_TEST

/* ================================================ beam topology input */

/* b2b_beam_segment_count must fail with `want` and leave *n_segments alone. */
static void expect_count_fail(const char *ctx, int kind, int n, int closed, int null_out,
                              int want, const char *w1, const char *w2) {
  int count = SENT_INT;
  char msg[B2B_ERRMSG_LEN + 16];
  memset(msg, GUARD, sizeof msg);
  int st = b2b_beam_segment_count(kind, n, closed, null_out ? NULL : &count, msg, B2B_ERRMSG_LEN);
  ck_assert_msg(st == want, "%s: status %d (%s), expected %d; message: %.*s", ctx, st,
                b2b_strerror(st), want, B2B_ERRMSG_LEN, msg);
  ck_assert_msg(memchr(msg, '\0', B2B_ERRMSG_LEN) != NULL, "%s: message not NUL-terminated", ctx);
  for (size_t i = B2B_ERRMSG_LEN; i < sizeof msg; ++i) ck_assert(msg[i] == GUARD);
  if (w1) ck_assert_msg(strstr(msg, w1) != NULL, "%s: \"%s\" lacks \"%s\"", ctx, msg, w1);
  if (w2) ck_assert_msg(strstr(msg, w2) != NULL, "%s: \"%s\" lacks \"%s\"", ctx, msg, w2);
  ck_assert_msg(count == SENT_INT, "%s: n_segments written (%d) on failure", ctx, count);
  st = b2b_beam_segment_count(kind, n, closed, null_out ? NULL : &count, NULL, 0);
  ck_assert_msg(st == want, "%s (errmsg NULL): status %d", ctx, st);
  ck_assert_int_eq(count, SENT_INT);
  char tiny[16];
  memset(tiny, GUARD, sizeof tiny);
  st = b2b_beam_segment_count(kind, n, closed, null_out ? NULL : &count, tiny, 8);
  ck_assert_int_eq(st, want);
  ck_assert(memchr(tiny, '\0', 8) != NULL);
  for (int i = 8; i < 16; ++i) ck_assert(tiny[i] == GUARD);
}

/* b2b_beam_segment_patch must fail with `want` and leave every output alone.
 * null_mask: bit 0 nodes, bit 1 start_rule, bit 2 end_rule passed as NULL. */
static void expect_patch_fail(const char *ctx, int kind, int n, int closed, int seg,
                              int null_mask, int want, const char *w1, const char *w2) {
  int nodes[4] = {SENT_INT, SENT_INT, SENT_INT, SENT_INT}, sr = SENT_INT, er = SENT_INT;
  char msg[B2B_ERRMSG_LEN + 16];
  memset(msg, GUARD, sizeof msg);
  int st = b2b_beam_segment_patch(kind, n, closed, seg, (null_mask & 1) ? NULL : nodes,
                                  (null_mask & 2) ? NULL : &sr, (null_mask & 4) ? NULL : &er, msg,
                                  B2B_ERRMSG_LEN);
  ck_assert_msg(st == want, "%s: status %d (%s), expected %d; message: %.*s", ctx, st,
                b2b_strerror(st), want, B2B_ERRMSG_LEN, msg);
  ck_assert_msg(memchr(msg, '\0', B2B_ERRMSG_LEN) != NULL, "%s: message not NUL-terminated", ctx);
  for (size_t i = B2B_ERRMSG_LEN; i < sizeof msg; ++i) ck_assert(msg[i] == GUARD);
  if (w1) ck_assert_msg(strstr(msg, w1) != NULL, "%s: \"%s\" lacks \"%s\"", ctx, msg, w1);
  if (w2) ck_assert_msg(strstr(msg, w2) != NULL, "%s: \"%s\" lacks \"%s\"", ctx, msg, w2);
  TST_ASSERT_ALL(int, k, 0, 4, nodes[k] == SENT_INT,
                 "%s: nodes[%d] written (%d) on failure", ctx, k, nodes[k]);
  ck_assert_msg(sr == SENT_INT && er == SENT_INT, "%s: rules written on failure", ctx);
  st = b2b_beam_segment_patch(kind, n, closed, seg, (null_mask & 1) ? NULL : nodes,
                              (null_mask & 2) ? NULL : &sr, (null_mask & 4) ? NULL : &er, NULL, 0);
  ck_assert_msg(st == want, "%s (errmsg NULL): status %d", ctx, st);
  for (int k = 0; k < 4; ++k) ck_assert_int_eq(nodes[k], SENT_INT);
  ck_assert(sr == SENT_INT && er == SENT_INT);
  char tiny[16];
  memset(tiny, GUARD, sizeof tiny);
  st = b2b_beam_segment_patch(kind, n, closed, seg, (null_mask & 1) ? NULL : nodes,
                              (null_mask & 2) ? NULL : &sr, (null_mask & 4) ? NULL : &er, tiny, 8);
  ck_assert_int_eq(st, want);
  ck_assert(memchr(tiny, '\0', 8) != NULL);
  for (int i = 8; i < 16; ++i) ck_assert(tiny[i] == GUARD);
}

START_TEST(test_count_bad_input) {
  const int kind = _i;
  char ctx[256], num[32];
  for (int closed = 0; closed <= 1; ++closed) {
    CTX("%s: n_segments NULL", tst_kind_name(kind));
    expect_count_fail(ctx, kind, 5, closed, 1, B2B_ERR_NULL, "n_segments", "NULL");
  }
  const int bad_kinds[] = {-1, B2B_CURVE_KIND_COUNT, 1000};
  for (size_t k = 0; k < 3; ++k) {
    snprintf(num, sizeof num, "%d", bad_kinds[k]);
    CTX("count: kind %d", bad_kinds[k]);
    expect_count_fail(ctx, bad_kinds[k], 5, 0, 0, B2B_ERR_UNKNOWN_KIND, "kind", num);
  }
  const int bad_closed[] = {2, -1, 100};
  for (size_t k = 0; k < 3; ++k) {
    snprintf(num, sizeof num, "%d", bad_closed[k]);
    CTX("%s: closed = %d", tst_kind_name(kind), bad_closed[k]);
    expect_count_fail(ctx, kind, 5, bad_closed[k], 0, B2B_ERR_RANGE, "closed", num);
  }
  const int small_open[] = {1, 0, -1, INT_MIN}, small_closed[] = {2, 1, 0, -3};
  for (size_t k = 0; k < 4; ++k) {
    snprintf(num, sizeof num, "%d", small_open[k]);
    CTX("%s: open beam of %d nodes", tst_kind_name(kind), small_open[k]);
    expect_count_fail(ctx, kind, small_open[k], 0, 0, B2B_ERR_RANGE, "at least 2", num);
    snprintf(num, sizeof num, "%d", small_closed[k]);
    CTX("%s: ring of %d nodes", tst_kind_name(kind), small_closed[k]);
    expect_count_fail(ctx, kind, small_closed[k], 1, 0, B2B_ERR_RANGE, "at least 3", num);
  }
}
END_TEST

START_TEST(test_patch_bad_input) {
  const int kind = _i;
  char ctx[256], num[32];
  for (int mask = 1; mask < 8; ++mask) {
    const char *which = (mask & 1) ? "nodes" : (mask & 2) ? "start_rule" : "end_rule";
    CTX("%s: NULL outputs (mask %d)", tst_kind_name(kind), mask);
    expect_patch_fail(ctx, kind, 5, 0, 1, mask, B2B_ERR_NULL, which, "NULL");
  }
  const int bad_kinds[] = {-1, B2B_CURVE_KIND_COUNT, 1000};
  for (size_t k = 0; k < 3; ++k) {
    snprintf(num, sizeof num, "%d", bad_kinds[k]);
    CTX("patch: kind %d", bad_kinds[k]);
    expect_patch_fail(ctx, bad_kinds[k], 5, 0, 0, 0, B2B_ERR_UNKNOWN_KIND, "kind", num);
  }
  const int bad_closed[] = {2, -1};
  for (size_t k = 0; k < 2; ++k) {
    snprintf(num, sizeof num, "%d", bad_closed[k]);
    CTX("%s: closed = %d", tst_kind_name(kind), bad_closed[k]);
    expect_patch_fail(ctx, kind, 5, bad_closed[k], 0, 0, B2B_ERR_RANGE, "closed", num);
  }
  const int small_open[] = {1, 0, -1}, small_closed[] = {2, 1, 0};
  for (size_t k = 0; k < 3; ++k) {
    CTX("%s: open beam of %d nodes", tst_kind_name(kind), small_open[k]);
    expect_patch_fail(ctx, kind, small_open[k], 0, 0, 0, B2B_ERR_RANGE, "at least 2", NULL);
    CTX("%s: ring of %d nodes", tst_kind_name(kind), small_closed[k]);
    expect_patch_fail(ctx, kind, small_closed[k], 1, 0, 0, B2B_ERR_RANGE, "at least 3", NULL);
  }
  for (int closed = 0; closed <= 1; ++closed)
    for (int n = closed ? 3 : 2; n <= 6; ++n) {
      int count = SENT_INT;
      ck_assert_int_eq(b2b_beam_segment_count(kind, n, closed, &count, NULL, 0), B2B_OK);
      const int segs[] = {-1, count, count + 1, INT_MAX, INT_MIN};
      for (size_t k = 0; k < 5; ++k) {
        snprintf(num, sizeof num, "%d", segs[k]);
        CTX("%s: %s beam of %d nodes, segment %d of %d", tst_kind_name(kind),
            closed ? "closed" : "open", n, segs[k], count);
        expect_patch_fail(ctx, kind, n, closed, segs[k], 0, B2B_ERR_RANGE, "segment", num);
      }
      /* The last valid segment is fine. */
      int nodes[4], sr, er;
      ck_assert_int_eq(
          b2b_beam_segment_patch(kind, n, closed, count - 1, nodes, &sr, &er, NULL, 0), B2B_OK);
    }
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("curve_bad_input");
  TCase *tc;
#define TC(name, fn, lo, hi)           \
  tc = tcase_create(name);             \
  tcase_add_loop_test(tc, fn, lo, hi); \
  suite_add_tcase(s, tc)

  /* b2b_segment_eval: loop index = curve kind. */
  TC("nonfinite_coordinate", test_nonfinite_coordinate, 0, B2B_CURVE_KIND_COUNT);
  TC("unused_slots_not_read", test_unused_slots_not_read, 0, B2B_CURVE_KIND_COUNT);
  TC("coincident_nodes", test_coincident_nodes, 0, B2B_CURVE_KIND_COUNT);
  TC("coincident_up_to_rounding", test_coincident_up_to_rounding, 0, B2B_CURVE_KIND_COUNT);
  TC("folded_patch", test_folded_patch, 0, B2B_CURVE_KIND_COUNT);
  TC("folded_up_to_rounding", test_folded_up_to_rounding, 0, B2B_CURVE_KIND_COUNT);
  TC("nearly_folded_patch", test_nearly_folded_patch, 0, B2B_CURVE_KIND_COUNT);
  TC("unknown_kind", test_unknown_kind, 0, 1);
  TC("unknown_rule", test_unknown_rule, 0, B2B_CURVE_KIND_COUNT);
  TC("null_patch", test_null_patch, 0, B2B_CURVE_KIND_COUNT);
  TC("null_end_tangents", test_null_end_tangents, 0, B2B_CURVE_KIND_COUNT);
  TC("zero_end_tangent", test_zero_end_tangent, 0, B2B_CURVE_KIND_COUNT);
  TC("nonfinite_end_tangent", test_nonfinite_end_tangent, 0, B2B_CURVE_KIND_COUNT);
  TC("end_tangent_any_length", test_end_tangent_any_length, 0, B2B_CURVE_KIND_COUNT);
  TC("nonfinite_xi", test_nonfinite_xi, 0, B2B_CURVE_KIND_COUNT);
  TC("xi_outside_segment", test_xi_outside_segment, 0, B2B_CURVE_KIND_COUNT);
  TC("xi_overflow", test_xi_overflow, 0, B2B_CURVE_KIND_COUNT);
  TC("xi_overflow_all_or_nothing", test_xi_overflow_all_or_nothing, 0, B2B_CURVE_KIND_COUNT);
  TC("coordinate_beyond_max", test_coordinate_beyond_max, 0, B2B_CURVE_KIND_COUNT);
  TC("coordinate_at_max", test_coordinate_at_max, 0, B2B_CURVE_KIND_COUNT);
  TC("extreme_scales", test_extreme_scales, 0, B2B_CURVE_KIND_COUNT);
  TC("midpoint_both_ends", test_midpoint_both_ends, 0, 1);
  /* Messages: loop index = one of bad_calls[]. */
  TC("errmsg_null", test_errmsg_null, 0, N_BAD_CALLS);
  TC("errmsg_truncated", test_errmsg_truncated, 0, N_BAD_CALLS);
  TC("errmsg_distinct", test_errmsg_distinct, 0, 1);
  TC("success_leaves_errmsg", test_success_leaves_errmsg, 0, B2B_CURVE_KIND_COUNT);
  /* Beam topology. */
  TC("count_bad_input", test_count_bad_input, 0, B2B_CURVE_KIND_COUNT);
  TC("patch_bad_input", test_patch_bad_input, 0, B2B_CURVE_KIND_COUNT);
#undef TC
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
