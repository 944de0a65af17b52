/* Shared helpers of the Check suites: a seeded generator, random patches,
 * rings, finite differences' bookkeeping, and the suite runner. */
#ifndef B2B_TEST_SUPPORT_H
#define B2B_TEST_SUPPORT_H

#include <check.h>
#include <stdint.h>

#include <b2b/b2b.h>

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

/* The four curve kinds, in enum order. */
extern const int tst_kinds[4];
const char *tst_kind_name(int kind);

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

/* Runs one suite (CK_NORMAL) and returns the process exit status. */
int tst_run_suite(Suite *suite);

#endif
