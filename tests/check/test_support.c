#include "test_support.h"

#include "ring_accuracy.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const int tst_kinds[TST_KINDS_MAX] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
typedef char tst_kinds_holds_every_kind[B2B_CURVE_KIND_COUNT <= TST_KINDS_MAX ? 1 : -1];

const char *tst_kind_name(int kind) {
  switch (kind) {
    case B2B_CURVE_LINEAR: return "linear";
    case B2B_CURVE_HERMITE_MIDPOINT: return "hermite-midpoint";
    case B2B_CURVE_HERMITE_NODAL: return "hermite-nodal";
    case B2B_CURVE_HERMITE_NODAL_WEIGHTED: return "hermite-nodal-weighted";
    default: return kind >= 0 && kind < B2B_CURVE_KIND_COUNT ? "an unlabelled kind" : "not a kind";
  }
}

tst_family tst_kind_family(int kind) {
  switch (kind) {
    case B2B_CURVE_LINEAR: return TST_CHORD;
    case B2B_CURVE_HERMITE_MIDPOINT: return TST_CENTRED;
    case B2B_CURVE_HERMITE_NODAL:
    case B2B_CURVE_HERMITE_NODAL_WEIGHTED: return TST_NODAL;
    default: tst_no_expectation("tst_kind_family", kind); return TST_NODAL;
  }
}

void tst_no_expectation(const char *what, int kind) {
  ck_abort_msg("%s: no expectation for curve kind %d; B2B_CURVE_KIND_COUNT is %d (a kind added "
               "to the library needs its case here)",
               what, kind, B2B_CURVE_KIND_COUNT);
}

void tst_rng_seed(tst_rng *rng, uint64_t seed) { rng->state = seed; }

double tst_uniform(tst_rng *rng, double lo, double hi) {
  uint64_t z = (rng->state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return lo + (hi - lo) * (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static void normalize(double *v) {
  const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  v[0] /= n;
  v[1] /= n;
  v[2] /= n;
}

static void random_unit(tst_rng *rng, double *v) {
  do {
    for (int i = 0; i < 3; ++i) v[i] = tst_uniform(rng, -1.0, 1.0);
  } while (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] < 0.05);
  normalize(v);
}

void tst_random_patch(tst_rng *rng, double h, double max_turn, double patch[12]) {
  double dir[3];
  random_unit(rng, dir);
  for (int i = 0; i < 3; ++i) patch[i] = tst_uniform(rng, -2.0 * h, 2.0 * h);
  for (int k = 1; k < 4; ++k) {
    if (k > 1) {  // turn the direction by up to max_turn about a random normal
      double a[3], n[3];
      random_unit(rng, a);
      n[0] = a[1] * dir[2] - a[2] * dir[1];
      n[1] = a[2] * dir[0] - a[0] * dir[2];
      n[2] = a[0] * dir[1] - a[1] * dir[0];
      normalize(n);
      const double t = tst_uniform(rng, 0.0, max_turn);
      for (int i = 0; i < 3; ++i) dir[i] = cos(t) * dir[i] + sin(t) * n[i];
    }
    const double len = h * tst_uniform(rng, 0.6, 1.4);
    for (int i = 0; i < 3; ++i) patch[3 * k + i] = patch[3 * (k - 1) + i] + len * dir[i];
  }
}

void tst_eval(int kind, int start_rule, int end_rule, const double patch[12],
              const double end_tangents[6], double xi, double x[9], double dx[72],
              double d2x[864]) {
  char msg[B2B_ERRMSG_LEN] = "";
  const int st = b2b_segment_eval(kind, start_rule, end_rule, patch, end_tangents, xi, x, dx, d2x,
                                  msg, (int)sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_segment_eval(%s) returned %d: %s", tst_kind_name(kind), st,
                msg);
}

void tst_rotate(const double Q[9], const double v[3], double out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = Q[i] * v[0] + Q[i + 3] * v[1] + Q[i + 6] * v[2];
}

double tst_max_abs(const double *a, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = fmax(m, fabs(a[i]));
  return m;
}

double tst_rel_diff(const double *a, const double *b, int n, double floor) {
  double d = 0.0;
  for (int i = 0; i < n; ++i) d = fmax(d, fabs(a[i] - b[i]));
  const double scale = fmax(floor, fmax(tst_max_abs(a, n), tst_max_abs(b, n)));
  return scale > 0.0 ? d / scale : d;
}

void tst_ring_nodes(int n, double radius, int alternating, double *coords) {
  ring_nodes(n, radius, alternating, coords);
}

void tst_gather_patch(int kind, int n_nodes, int closed, int segment, const double *coords,
                      double patch[12], int *start_rule, int *end_rule) {
  int nodes[4];
  char msg[B2B_ERRMSG_LEN] = "";
  const int st = b2b_beam_segment_patch(kind, n_nodes, closed, segment, nodes, start_rule,
                                        end_rule, msg, (int)sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_beam_segment_patch returned %d: %s", st, msg);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) patch[3 * k + i] = nodes[k] >= 0 ? coords[3 * nodes[k] + i] : NAN;
}

int tst_quick(void) {
  const char *v = getenv("B2B_TEST_QUICK");
  return v != NULL && v[0] != '\0' && strcmp(v, "0") != 0;
}

/* Whether a passed assertion is recorded (test_support.h, ck_assert_msg):
 * yes unless the running suite's runner does not fork. */
static int tst_marks = 1;

/* The location recorded last: an assertion in a loop passes at the same
 * place thousands of times, and Check's report of a crash names only the
 * last location recorded, which recording it again does not change. (In
 * fork mode each test runs in a child process with its own copy of these,
 * starting from none.) */
static const char *tst_marked_file;
static int tst_marked_line = -1;

void tst_mark_point(const char *file, int line) {
  if (!tst_marks || (line == tst_marked_line && file == tst_marked_file)) return;
  tst_marked_file = file;
  tst_marked_line = line;
  _mark_point(file, line);
}

static int run_suite(Suite *suite, int forked) {
  SRunner *runner = srunner_create(suite);
  if (forked) srunner_set_fork_status(runner, CK_FORK);
  if (tst_quick())
    printf("B2B_TEST_QUICK: a suite with a quick mode runs fewer configurations, the same checks\n");
  tst_marks = srunner_fork_status(runner) != CK_NOFORK;
  srunner_run_all(runner, CK_NORMAL);
  const int failed = srunner_ntests_failed(runner);
  srunner_free(runner);
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int tst_run_suite(Suite *suite) { return run_suite(suite, 0); }

int tst_run_suite_forked(Suite *suite) { return run_suite(suite, 1); }
