/* Shared helpers of the Check suites: a seeded generator, random patches,
 * rings, finite differences' bookkeeping, and the suite runner. */
#ifndef B2B_TEST_SUPPORT_H
#define B2B_TEST_SUPPORT_H

#include <check.h>
#include <stdint.h>

#include <b2b/b2b.h>

/* C linkage for the suites written in C++ (check_box_tree, check_finite). */
#ifdef __cplusplus
extern "C" {
#endif

/* Check's ck_assert_msg (and every ck_assert_* built on it) with its record
 * of a passed assertion made conditional: Check writes each passed
 * assertion's location to its message file (one write(2) each) so that a
 * test that crashes later can be reported "after" the last point it
 * reached. That is worth having when each test runs in a child process
 * (CK_FORK, Check's default: the parent reports the crash), and worth
 * nothing with CK_FORK=no, where a crash ends the whole runner before any
 * report; there the records are skipped (tst_run_suite decides, from the
 * runner's fork status). Under valgrind (scripts/quickstart.sh memcheck,
 * which sets CK_FORK=no) these records were most of the bad-input suites'
 * time: CK_FORK=no check_curve_bad_input made 695 thousand write(2) calls
 * (strace -c -f), 241 without them, and took 56.5 s of CPU under valgrind,
 * 2.0 s without. In fork mode a location is recorded only when it is not
 * the one recorded last (an assertion in a loop passes at one place
 * thousands of times), which leaves Check's report of a crash as it was:
 * check_curve_bad_input then made 49 thousand write(2) calls instead of 354
 * thousand, and took 0.50 s instead of 1.81 s (Release build). A failed
 * assertion is reported exactly as by Check's own macro. */
void tst_mark_point(const char *file, int line);
#undef ck_assert_msg
#define ck_assert_msg(expr, ...)               \
  ((expr) ? tst_mark_point(__FILE__, __LINE__) \
          : _ck_assert_failed(__FILE__, __LINE__, "Assertion '" #expr "' failed", ##__VA_ARGS__))

/* Asserts cond for every i in [lo, hi) with a single Check assertion: the
 * loop runs in plain C and only the first failing i (if any) reaches
 * ck_assert_msg, which then reports it with the message as usual. Check
 * records every passed assertion (a message to its parent process each), so
 * asserting per array element made the bad-input suites spend seconds in
 * system calls. */
#define TST_ASSERT_ALL(type, i, lo, hi, cond, ...)          \
  do {                                                      \
    type i##_first_bad_ = (hi);                             \
    int i##_found_ = 0;                                     \
    for (type i = (lo); i < (hi); ++i)                      \
      if (!(cond)) {                                        \
        i##_first_bad_ = i;                                 \
        i##_found_ = 1;                                     \
        break;                                              \
      }                                                     \
    if (i##_found_) {                                       \
      type i = i##_first_bad_;                              \
      ck_assert_msg(cond, __VA_ARGS__);                     \
    }                                                       \
  } while (0)

/* The curve kinds are 0 .. B2B_CURVE_KIND_COUNT - 1 and the normal laws
 * 0 .. B2B_LAW_COUNT - 1 (b2b_curve.h, b2b_pair.h): the tests loop to these
 * counts, so every loop covers a kind or law the library adds. */

/* Kept for suites that still index it: tst_kinds[k] is kind k (k <
 * B2B_CURVE_KIND_COUNT). New code loops to B2B_CURVE_KIND_COUNT and uses the
 * kind itself. */
#define TST_KINDS_MAX 16
extern const int tst_kinds[TST_KINDS_MAX];

/* The n-th pair of curve kinds (A, B), n = 0, 1, ...: all
 * B2B_CURVE_KIND_COUNT^2 of them, then again. */
#define TST_KIND_A(n) ((n) % B2B_CURVE_KIND_COUNT)
#define TST_KIND_B(n) (((n) / B2B_CURVE_KIND_COUNT) % B2B_CURVE_KIND_COUNT)

/* A short label of a curve kind for messages ("linear", ...); a kind that
 * has none yet reads "an unlabelled kind", any other value "not a kind". */
const char *tst_kind_name(int kind);

/* What the tests expect of a curve kind follows its family, the behaviour
 * b2b_curve.h documents for it: the chord (LINEAR: slots x2, x3, linear in
 * the nodes, no end tangents), a curve centred on a node (HERMITE_MIDPOINT:
 * one segment per node, slots x1..x3), a node-preserving curve
 * (HERMITE_NODAL and _WEIGHTED: slots x1..x4). Tests switch on the family
 * without a default, so -Wswitch names those a new family must join; a kind
 * without a family fails the running test (tst_no_expectation). */
typedef enum { TST_CHORD, TST_CENTRED, TST_NODAL } tst_family;
tst_family tst_kind_family(int kind);

/* Fails the running test: `what` states an expectation per curve kind and
 * has none for `kind` (one the library added later: give it its case). */
void tst_no_expectation(const char *what, int kind);

/* Deterministic generator (splitmix64): every run sees the same numbers. */
typedef struct {
  uint64_t state;
} tst_rng;
void tst_rng_seed(tst_rng *rng, uint64_t seed);
double tst_uniform(tst_rng *rng, double lo, double hi);

/* A curved 4-node patch: element lengths in [0.6 h, 1.4 h], turning angles
 * at the nodes up to max_turn radians, random orientation and position
 * (within 2 h of the origin). */
void tst_random_patch(tst_rng *rng, double h, double max_turn, double patch[12]);

/* b2b_segment_eval that fails the running test (with the library's message)
 * unless it returns B2B_OK. */
void tst_eval(int kind, int start_rule, int end_rule, const double patch[12],
              const double end_tangents[6], double xi, double x[9], double dx[72],
              double d2x[864]);

double tst_max_abs(const double *a, int n);

/* out = Q v, Q a 3x3 rotation, column-major. */
void tst_rotate(const double Q[9], const double v[3], double out[3]);
/* max|a - b| / max(max|a|, max|b|, floor): relative difference of two arrays. */
double tst_rel_diff(const double *a, const double *b, int n, double floor);

/* n nodes on the circle of radius radius (a closed beam): uniform spacing, or
 * elements alternating 1.3 h / 0.7 h (n even). coords is 3 x n. */
void tst_ring_nodes(int n, double radius, int alternating, double *coords);

/* The patch of one beam segment gathered from the beam's coordinates with
 * b2b_beam_segment_patch; slots the kind does not read are filled with NaN so
 * that a test fails if the library ever reads them. */
void tst_gather_patch(int kind, int n_nodes, int closed, int segment, const double *coords,
                      double patch[12], int *start_rule, int *end_rule);

/* Whether the suites run in their quick mode: environment variable
 * B2B_TEST_QUICK set and not "0". Only scripts/quickstart.sh memcheck sets
 * it (valgrind makes the suites' sweeps slow); every other step runs them in
 * full. A quick mode runs the same checks on fewer configurations (a coarser
 * sweep, fewer steps, a sparser scene); every library line its full run
 * reaches, its quick run or another suite memcheck runs must reach
 * (scripts/quickstart.sh coverage checks it for each suite labelled "quick",
 * tests/CMakeLists.txt: B2B_QUICK_SUITES). */
int tst_quick(void);

/* Runs one suite (CK_NORMAL) and returns the process exit status. */
int tst_run_suite(Suite *suite);

/* The same with each test in a process of its own whatever CK_FORK says:
 * for a suite whose tests change their process for the tests after them
 * (check_model_hostile's address-space limits). */
int tst_run_suite_forked(Suite *suite);

#ifdef __cplusplus
}
#endif

#endif
