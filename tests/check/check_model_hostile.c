/* The contact model under hostile input (issue 17) and the model state
 * owned in one place (issue 16, item 3). Each test names the finding it
 * guards and fails on the code before the fix:
 *  - restart buffers crafted behind a valid checksum (the test rewrites a
 *    real buffer's fields and signs it again): a pair whose groups are not
 *    paired with a group-pair index of 2^64 - 1 (read before the group-pair
 *    vector), non-finite or huge dissipation and coordinates, NaN arc
 *    lengths, a segment paired with itself or with its neighbour; a buffer
 *    from a model with another friction coefficient;
 *  - sizes: kl = 1e9, ku = 2e8 in the band assembly, eq_base = INT_MIN,
 *    finalize(INT_MAX) with one small beam, 10^5 groups;
 *  - memory: an update that runs out of memory inside the broad phase's
 *    parallel region (address-space limit) is B2B_ERR_NOMEM with the model
 *    unchanged, and so is one that runs out while it writes its results
 *    over the spare set of the update before last (issue 20: the update
 *    reuses that memory): the last update's contacts, tangents and stats
 *    stay, bit for bit; the "max_candidates" bound; all nodes on one point
 *    refused in O(n) before the search;
 *  - the "threads" range message; stats after revert and restore;
 *  - every option changed between updates acts as if set from the start;
 *    reverting the very first update forgets the self-contact arc lengths
 *    measured in it. */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "model_support.h"

#if defined(__SANITIZE_ADDRESS__)
#define UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_ASAN 1
#endif
#endif
#ifndef UNDER_ASAN
#define UNDER_ASAN 0
#endif

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

/* call (which writes into msg) returns want, and msg holds w1 (and w2 if
 * not NULL). */
#define EXPECT_FAIL(want, w1, w2, w3, call)                                                 \
  do {                                                                                      \
    msg[0] = '\0';                                                                          \
    const int st_ = (call);                                                                 \
    const char *w2_ = (w2);                                                                 \
    (void)(w3);                                                                             \
    ck_assert_msg(st_ == (want), "%s: status %d, expected %d (%s)", #call, st_, (want), msg); \
    ck_assert_msg(strstr(msg, (w1)) != NULL, "%s: no \"%s\" in: %s", #call, (w1), msg);      \
    ck_assert_msg(w2_ == NULL || strstr(msg, w2_) != NULL, "%s: no \"%s\" in: %s", #call,   \
                  w2_ ? w2_ : "", msg);                                                     \
  } while (0)

static double cpu_seconds(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* ------------------------------------------------------- restart buffers */

/* The restart layout of src/model/restart.cpp: header (32 bytes), then
 * coordinates, arc lo, arc hi, arc totals (each a u64 count and doubles),
 * the dissipation, the pair count, the pairs (6 u64 and a history each),
 * and the FNV-1a checksum of everything before it. */
typedef struct {
  size_t coords, lo, hi, total, dissipation, n_pairs, pair0;
} layout;

static uint64_t get_u64(const unsigned char *b, size_t at) {
  uint64_t v;
  memcpy(&v, b + at, 8);
  return v;
}
static void put_u64(unsigned char *b, size_t at, uint64_t v) { memcpy(b + at, &v, 8); }
static void put_f64(unsigned char *b, size_t at, double v) { memcpy(b + at, &v, 8); }

static layout parse(const unsigned char *b) {
  layout l;
  size_t at = 32;
  l.coords = at;
  at += 8 + 8 * get_u64(b, at);
  l.lo = at;
  at += 8 + 8 * get_u64(b, at);
  l.hi = at;
  at += 8 + 8 * get_u64(b, at);
  l.total = at;
  at += 8 + 8 * get_u64(b, at);
  l.dissipation = at;
  l.n_pairs = at + 8;
  l.pair0 = at + 16;
  return l;
}

/* Signs a rewritten buffer again, as a forger would. */
static void resign(unsigned char *b, int64_t size) {
  uint64_t h = 1469598103934665603ULL;
  for (int64_t i = 0; i < size - 8; ++i) {
    h ^= b[i];
    h *= 1099511628211ULL;
  }
  put_u64(b, (size_t)size - 8, h);
}

static uint64_t key_of(uint64_t a, uint64_t b) { return a < b ? (a << 32 | b) : (b << 32 | a); }

/* The committed state of m as bytes (*size of them; malloc'ed). */
static unsigned char *saved(const b2b_model *m, int64_t *size) {
  char msg[B2B_ERRMSG_LEN] = "";
  ok(b2b_model_save_size(m, size, msg, sizeof msg), msg);
  unsigned char *b = malloc((size_t)*size);
  ok(b2b_model_save(m, b, *size, msg, sizeof msg), msg);
  return b;
}

/* restore refuses the buffer with B2B_ERR_RANGE, a message naming the
 * reason (want), and the model saves the same bytes as before. */
static void refused(b2b_model *m, unsigned char *bad, int64_t size, const char *want,
                    const char *what) {
  char msg[B2B_ERRMSG_LEN] = "";
  int64_t n0;
  unsigned char *before = saved(m, &n0);
  const int st = b2b_model_restore(m, bad, size, msg, sizeof msg);
  ck_assert_msg(st == B2B_ERR_RANGE, "%s: restore returned %d (%s)", what, st, msg);
  ck_assert_msg(strstr(msg, want) != NULL, "%s: the message does not say \"%s\": %s", what, want,
                msg);
  int64_t n1;
  unsigned char *after = saved(m, &n1);
  ck_assert_msg(n0 == n1 && memcmp(before, after, (size_t)n0) == 0,
                "%s: a refused restore changed the model", what);
  printf("check_model_hostile: %s: %s\n", what, msg);
  free(before);
  free(after);
}

/* Beam A (4 nodes, group 0) along x, beam B (group 1) crossing it 0.15
 * above at x = 0.5 (radii 0.1: penetrating), beam C (group 2) far away.
 * Groups (0, 1) touch with friction mu. Segments: A 0..2, B 3, C 4. */
static b2b_model *crossing(double mu, b2b_params **p) {
  char msg[B2B_ERRMSG_LEN] = "";
  *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, mu, 1e3);
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  int beam, a[4] = {0, 1, 2, 3}, b[2] = {4, 5}, c[2] = {6, 7};
  ok(b2b_model_add_beam(m, a, 4, 0, 0.1, B2B_CURVE_LINEAR, 0, &beam, msg, sizeof msg), msg);
  ok(b2b_model_add_beam(m, b, 2, 0, 0.1, B2B_CURVE_LINEAR, 1, &beam, msg, sizeof msg), msg);
  ok(b2b_model_add_beam(m, c, 2, 0, 0.1, B2B_CURVE_LINEAR, 2, &beam, msg, sizeof msg), msg);
  ok(b2b_model_set_group_pair(m, 0, 1, *p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, 8, msg, sizeof msg), msg);
  return m;
}

static void crossing_x(double *x, double dy) {
  const double pts[8][3] = {{0, 0, 0},      {1, 0, 0},       {2, 0, 0},       {3, 0, 0},
                            {0.5, -1, 0.15}, {0.5, 1, 0.15},  {10, 10, 10},    {11, 10, 10}};
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) x[3 * k + i] = pts[k][i] + (k >= 4 && k < 6 && i == 0 ? dy : 0);
}

/* The crossing model with one committed contact, and its buffer. */
static b2b_model *committed_crossing(double mu, b2b_params **p, unsigned char **buf,
                                     int64_t *size) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_model *m = crossing(mu, p);
  double x[24];
  crossing_x(x, 0.0);
  ok(b2b_model_update(m, x, 3, 8, 1, msg, sizeof msg), msg);
  int n;
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
  ck_assert_int_eq(n, 1);
  ok(b2b_model_commit(m, msg, sizeof msg), msg);
  *buf = saved(m, size);
  return m;
}

START_TEST(restore_pair_of_unpaired_groups_with_huge_index) {
  /* finding 1: before the fix, group_pair_index gave -1 for the unpaired
   * groups, equal to the buffer's 2^64 - 1, and restore read the group
   * pair at that index (UBSan: out of bounds; release: heap memory). */
  b2b_params *p;
  unsigned char *buf;
  int64_t size;
  b2b_model *m = committed_crossing(0.3, &p, &buf, &size);
  const layout l = parse(buf);
  ck_assert_int_eq(get_u64(buf, l.n_pairs), 1);
  const uint64_t a = get_u64(buf, l.pair0 + 8);
  put_u64(buf, l.pair0 + 16, 4);  /* segment 4: beam C, group 2, not paired with 0 */
  put_u64(buf, l.pair0, key_of(a, 4));
  put_u64(buf, l.pair0 + 32, UINT64_MAX);
  resign(buf, size);
  refused(m, buf, size, "never pairs", "a pair of unpaired groups, group pair 2^64-1");
  free(buf);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(restore_nonfinite_or_huge_doubles) {
  /* finding 2: NaN, +Inf, -1e300 dissipation and NaN, 1e308 committed
   * coordinates were accepted. */
  b2b_params *p;
  unsigned char *buf;
  int64_t size;
  b2b_model *m = committed_crossing(0.3, &p, &buf, &size);
  const layout l = parse(buf);
  unsigned char *bad = malloc((size_t)size);
  const double dissipations[3] = {NAN, INFINITY, -1e300};
  for (int k = 0; k < 3; ++k) {
    memcpy(bad, buf, (size_t)size);
    put_f64(bad, l.dissipation, dissipations[k]);
    resign(bad, size);
    char what[64];
    snprintf(what, sizeof what, "dissipation %g", dissipations[k]);
    refused(m, bad, size, "dissipation", what);
  }
  const double coords[2] = {NAN, 1e308};
  for (int k = 0; k < 2; ++k) {
    memcpy(bad, buf, (size_t)size);
    put_f64(bad, l.coords + 8 + 8 * 13, coords[k]);  /* node 4 (beam B), y */
    resign(bad, size);
    char what[64];
    snprintf(what, sizeof what, "a committed coordinate %g", coords[k]);
    refused(m, bad, size, "coordinate", what);
  }
  /* the untouched buffer is accepted, and the stats then wait for an update */
  char msg[B2B_ERRMSG_LEN] = "";
  ok(b2b_model_restore(m, buf, size, msg, sizeof msg), msg);
  free(bad);
  free(buf);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(restore_foreign_friction) {
  /* finding 3: the fingerprint did not cover the parameters, so a buffer
   * of a model with friction 0.3 restored into one with 0.9. */
  b2b_params *p, *q, *q2;
  unsigned char *buf;
  int64_t size;
  b2b_model *m = committed_crossing(0.3, &p, &buf, &size);
  b2b_model *other = crossing(0.9, &q);
  refused(other, buf, size, "another model", "a buffer of friction 0.3 into a model of 0.9");
  /* the same parameters: accepted */
  b2b_model *same = crossing(0.3, &q2);
  char msg[B2B_ERRMSG_LEN] = "";
  ok(b2b_model_restore(same, buf, size, msg, sizeof msg), msg);
  free(buf);
  b2b_model_destroy(&m);
  b2b_model_destroy(&other);
  b2b_model_destroy(&same);
  b2b_params_destroy(&p);
  b2b_params_destroy(&q);
  b2b_params_destroy(&q2);
}
END_TEST

/* ------------------------------------------------- a loop touching itself */

/* One beam bent into a loop that crosses itself (as check_model_topology's):
 * the plane curve (t^2 - 1, t (t^2 - 1)) passes the origin at t = -1 and 1;
 * z = t (r - 0.01) lifts the passes 2 r - 0.02 apart. scale shrinks the
 * loop about the origin. */
enum { LOOP_N = 65 };
static void loop_x(double *x, double scale) {
  const double r = 0.05;
  for (int k = 0; k < LOOP_N; ++k) {
    const double t = -1.6 + 3.2 * k / (LOOP_N - 1);
    x[3 * k] = scale * (t * t - 1.0);
    x[3 * k + 1] = scale * t * (t * t - 1.0);
    x[3 * k + 2] = scale * t * (r - 0.01);
  }
}

static b2b_model *loop_model(b2b_params **p) {
  char msg[B2B_ERRMSG_LEN] = "";
  int nodes[LOOP_N], beam;
  for (int k = 0; k < LOOP_N; ++k) nodes[k] = k;
  *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  ok(b2b_model_add_beam(m, nodes, LOOP_N, 0, 0.05, B2B_CURVE_HERMITE_NODAL, 3, &beam, msg,
                        sizeof msg), msg);
  ok(b2b_model_set_self_contact(m, beam, 1, -1.0, msg, sizeof msg), msg);
  ok(b2b_model_set_group_pair(m, 3, 3, *p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, LOOP_N, msg, sizeof msg), msg);
  return m;
}

static int count_contacts(const b2b_model *m) {
  char msg[B2B_ERRMSG_LEN] = "";
  int n;
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
  return n;
}

START_TEST(restore_self_contact_lies) {
  /* finding 2: NaN arc lengths silently switched self-contact off; a
   * segment paired with itself or with a neighbour sharing a node was
   * accepted. */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p;
  b2b_model *m = loop_model(&p);
  double x[3 * LOOP_N];
  loop_x(x, 1.0);
  ok(b2b_model_update(m, x, 3, LOOP_N, 0, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), 1);
  ok(b2b_model_commit(m, msg, sizeof msg), msg);
  int64_t size;
  unsigned char *buf = saved(m, &size);
  const layout l = parse(buf);
  ck_assert_msg(get_u64(buf, l.lo) > 0, "no arc lengths in the buffer");
  ck_assert_msg(get_u64(buf, l.n_pairs) >= 1, "no committed pair");
  unsigned char *bad = malloc((size_t)size);

  memcpy(bad, buf, (size_t)size);
  put_f64(bad, l.lo + 8 + 8 * 10, NAN);
  resign(bad, size);
  refused(m, bad, size, "arc lengths", "a NaN arc length");

  memcpy(bad, buf, (size_t)size);
  put_f64(bad, l.total + 8, -1.0);
  resign(bad, size);
  refused(m, bad, size, "arc lengths", "a negative beam length");

  const uint64_t a = get_u64(buf, l.pair0 + 8);
  const uint64_t partners[2] = {a, a + 1};
  const char *whats[2] = {"a segment paired with itself", "a segment paired with its neighbour"};
  for (int k = 0; k < 2; ++k) {
    memcpy(bad, buf, (size_t)size);
    put_u64(bad, l.pair0 + 16, partners[k]);
    put_u64(bad, l.pair0, key_of(a, partners[k]));
    resign(bad, size);
    refused(m, bad, size, k == 0 ? "corrupted (pair keys)" : "never pairs", whats[k]);
  }
  ok(b2b_model_restore(m, buf, size, msg, sizeof msg), msg);
  ok(b2b_model_update(m, x, 3, LOOP_N, 0, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), 1);
  free(bad);
  free(buf);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(revert_of_the_first_update_forgets_its_arc_lengths) {
  /* issue 16, item 3: the arc lengths were measured in the first update's
   * configuration and kept after it was reverted. A first iteration in a
   * configuration shrunk 100 times (arcs shorter than the exclusion
   * length everywhere) excluded every pair for good: 0 contacts after the
   * revert where the loop has 1. */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p;
  b2b_model *m = loop_model(&p);
  double x[3 * LOOP_N], shrunk[3 * LOOP_N];
  loop_x(x, 1.0);
  loop_x(shrunk, 0.01);
  ok(b2b_model_update(m, x, 3, LOOP_N, 0, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), 1);  /* before the revert */
  ok(b2b_model_revert(m, msg, sizeof msg), msg);
  ok(b2b_model_update(m, x, 3, LOOP_N, 0, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), 1);  /* the same update after the revert */
  ok(b2b_model_revert(m, msg, sizeof msg), msg);

  ok(b2b_model_update(m, shrunk, 3, LOOP_N, 0, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), 0);
  ok(b2b_model_revert(m, msg, sizeof msg), msg);
  ok(b2b_model_update(m, x, 3, LOOP_N, 0, msg, sizeof msg), msg);
  const int n = count_contacts(m);
  ck_assert_msg(n == 1, "after reverting a first update in another configuration: %d contacts "
                "(the arc lengths of the reverted update are kept)", n);
  /* once committed, the arcs stay: a revert after the commit keeps them */
  ok(b2b_model_commit(m, msg, sizeof msg), msg);
  ok(b2b_model_update(m, shrunk, 3, LOOP_N, 0, msg, sizeof msg), msg);
  ok(b2b_model_revert(m, msg, sizeof msg), msg);
  ok(b2b_model_update(m, x, 3, LOOP_N, 0, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), 1);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* ------------------------------------------------------------------ sizes */

START_TEST(band_whose_size_overflows_int) {
  /* finding 4: 2 kl + ku + 1 overflowed int, the ldab check passed, and
   * the band index overflowed (segfault). */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p;
  b2b_model *m = crossing(0.0, &p);
  double x[24];
  crossing_x(x, 0.0);
  ok(b2b_model_update(m, x, 3, 8, 1, msg, sizeof msg), msg);
  int eq[24];
  for (int k = 0; k < 24; ++k) eq[k] = k;
  double AB[5 * 24] = {0};
  const int st = b2b_model_add_tangent_banded(m, eq, 3, 0, 24, 1000000000, 200000000, AB, 5,
                                              msg, sizeof msg);
  ck_assert_msg(st == B2B_ERR_SIZE, "kl = 1e9, ku = 2e8, ldab = 5: status %d (%s)", st, msg);
  ck_assert_msg(strstr(msg, "2200000001") != NULL, "%s", msg);
  for (int k = 0; k < 5 * 24; ++k) ck_assert(AB[k] == 0.0);
  printf("check_model_hostile: %s\n", msg);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(eq_base_int_min) {
  /* finding 7: eq_base - 1 overflowed (the "constrained" marker). */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p;
  b2b_model *m = crossing(0.0, &p);
  double x[24];
  crossing_x(x, 0.0);
  ok(b2b_model_update(m, x, 3, 8, 1, msg, sizeof msg), msg);
  int eq[24];
  for (int k = 0; k < 24; ++k) eq[k] = k;
  double f[24] = {0};
  const int st = b2b_model_add_residual(m, eq, 3, INT_MIN, 24, f, msg, sizeof msg);
  ck_assert_msg(st == B2B_ERR_RANGE, "eq_base = INT_MIN: status %d (%s)", st, msg);
  ck_assert_msg(strstr(msg, "eq_base") != NULL, "%s", msg);
  for (int k = 0; k < 24; ++k) ck_assert(f[k] == 0.0);
  /* INT_MIN + 1 with every equation far above it: beyond n_eq in 64 bits */
  const int st2 = b2b_model_add_residual(m, eq, 3, INT_MIN + 1, 24, f, msg, sizeof msg);
  ck_assert_msg(st2 == B2B_ERR_RANGE, "eq_base = INT_MIN + 1: status %d (%s)", st2, msg);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* An address-space limit some megabytes above what the process holds now
 * (not under AddressSanitizer, which reserves terabytes of it). Check runs
 * each test in its own process, so the limit ends with the test. */
static int limit_memory(size_t extra_mb) {
  if (UNDER_ASAN) return 0;
  FILE *f = fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long pages = 0;
  const int got = fscanf(f, "%lu", &pages);
  fclose(f);
  if (got != 1) return 0;
  struct rlimit rl;
  getrlimit(RLIMIT_AS, &rl);
  rl.rlim_cur = (rlim_t)pages * 4096u + (rlim_t)extra_mb * 1024u * 1024u;
  return setrlimit(RLIMIT_AS, &rl) == 0;
}

/* The address-space limit of limit_memory lifted again (to the hard limit),
 * for a test that goes on after its out-of-memory part. */
static int lift_memory_limit(void) {
  struct rlimit rl;
  getrlimit(RLIMIT_AS, &rl);
  rl.rlim_cur = rl.rlim_max;
  return setrlimit(RLIMIT_AS, &rl) == 0;
}

START_TEST(finalize_int_max_nodes) {
  /* finding 7: finalize(INT_MAX) with one 3-node beam allocated an
   * n_nodes-long table (8.4 GB, 15 s). Now: a few ints. */
  char msg[B2B_ERRMSG_LEN] = "";
  limit_memory(512);
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  int nodes[3] = {0, 1, INT_MAX - 1}, beam;
  ok(b2b_model_add_beam(m, nodes, 3, 0, 0.1, B2B_CURVE_HERMITE_NODAL, 0, &beam, msg, sizeof msg),
     msg);
  ok(b2b_model_set_group_pair(m, 0, 0, p, msg, sizeof msg), msg);
  const double t0 = cpu_seconds();
  const int st = b2b_model_finalize(m, INT_MAX, msg, sizeof msg);
  const double t = cpu_seconds() - t0;
  ck_assert_msg(st == B2B_OK, "finalize(INT_MAX): status %d (%s)", st, msg);
  ck_assert_msg(t < 1.0, "finalize(INT_MAX) took %.2f s", t);
  /* an update reads nodes 0, 1 and INT_MAX - 1 only: a 2-column x with
   * ldx = (INT_MAX - 1) * 3 would do; here a 3-column array with a large
   * ldx stands for it */
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(many_groups) {
  /* finding 6: an n_groups x n_groups table (47,000 groups: segfault; 20,000:
   * 1.6 GB, 6 s). 10^5 beams in groups of their own, each group paired with
   * the next: the pairs cost their number. */
  enum { NB = 100000 };
  char msg[B2B_ERRMSG_LEN] = "";
  limit_memory(1024);
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  const double t0 = cpu_seconds();
  for (int b = 0; b < NB; ++b) {
    int nodes[2] = {2 * b, 2 * b + 1}, beam;
    ok(b2b_model_add_beam(m, nodes, 2, 0, 0.1, B2B_CURVE_LINEAR, b, &beam, msg, sizeof msg),
       msg);
  }
  for (int g = 0; g + 1 < NB; ++g) ok(b2b_model_set_group_pair(m, g, g + 1, p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, 2 * NB, msg, sizeof msg), msg);
  /* beams side by side along y, 0.15 apart (radii 0.1: each touches its
   * neighbours); every other pair crosses at 90 degrees */
  double *x = malloc(6 * (size_t)NB * sizeof(double));
  for (int b = 0; b < NB; ++b) {
    double *q = x + 6 * (size_t)b;
    const int row = b / 2;
    if (b % 2 == 0) {
      q[0] = 0; q[1] = 3.0 * row; q[2] = 0;
      q[3] = 1; q[4] = 3.0 * row; q[5] = 0;
    } else {
      q[0] = 0.5; q[1] = 3.0 * row - 0.5; q[2] = 0.15;
      q[3] = 0.5; q[4] = 3.0 * row + 0.5; q[5] = 0.15;
    }
  }
  ok(b2b_model_update(m, x, 3, 2 * NB, 0, msg, sizeof msg), msg);
  const double t = cpu_seconds() - t0;
  const int n = count_contacts(m);
  printf("check_model_hostile: %d beams in %d groups: %d contacts, %.2f s CPU\n", NB, NB, n, t);
  ck_assert_int_eq(n, NB / 2);
  ck_assert_msg(t < 30.0, "10^5 groups took %.1f s", t);
  free(x);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* ----------------------------------------------------------------- memory */

/* n beams of 2 nodes, all on the same two points (distinct host nodes), in
 * group 0 paired with itself: every pair of them is a candidate. */
static b2b_model *stack_model(int n, double **x, b2b_params **p) {
  char msg[B2B_ERRMSG_LEN] = "";
  *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  *x = malloc(6 * (size_t)n * sizeof(double));
  for (int b = 0; b < n; ++b) {
    int nodes[2] = {2 * b, 2 * b + 1}, beam;
    ok(b2b_model_add_beam(m, nodes, 2, 0, 0.1, B2B_CURVE_LINEAR, 0, &beam, msg, sizeof msg), msg);
    const double q[6] = {0, 0, 0, 1, 0, 0};
    memcpy(*x + 6 * (size_t)b, q, sizeof q);
  }
  ok(b2b_model_set_group_pair(m, 0, 0, *p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, 2 * n, msg, sizeof msg), msg);
  return m;
}

START_TEST(out_of_memory_in_the_broad_phase) {
  /* finding 5: std::bad_alloc thrown inside the OpenMP broad phase reached
   * std::terminate (SIGABRT). 20,000 stacked segments want 2e8 candidates
   * (over a GB) under a limit of 96 MB more than the process holds. */
  if (UNDER_ASAN) {
    printf("check_model_hostile: out_of_memory_in_the_broad_phase skipped under ASan\n");
    return;
  }
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p;
  double *x;
  b2b_model *m = stack_model(20000, &x, &p);  /* default bound 1e8: memory runs out first */
  ok(b2b_model_set_int(m, "threads", 2, msg, sizeof msg), msg);
  ck_assert(limit_memory(96));
  const int st = b2b_model_update(m, x, 3, 40000, 0, msg, sizeof msg);
  ck_assert_msg(st == B2B_ERR_NOMEM, "update under a memory limit: status %d (%s)", st, msg);
  int n;
  ck_assert_int_eq(b2b_model_contact_count(m, &n, NULL, 0), B2B_ERR_STATE);
  ck_assert_int_eq(b2b_model_stats(m, NULL, NULL, NULL, 0), B2B_ERR_STATE);
  printf("check_model_hostile: %s\n", msg);
  free(x);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(out_of_memory_in_the_narrow_phase) {
  /* finding 5, the parallel narrow phase: a grid of 320 x 320 crossing
   * beams (2-node, one segment each), every crossing active: 102,400
   * tangents of 4.6 kB each are kept in the parallel region of the
   * evaluation, under a limit of 250 MB more than the process holds. */
  if (UNDER_ASAN) {
    printf("check_model_hostile: out_of_memory_in_the_narrow_phase skipped under ASan\n");
    return;
  }
  enum { N = 320 };
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  double *x = malloc(12 * (size_t)N * sizeof(double));
  const double d = 0.5, len = N * d + 1.0;
  for (int b = 0; b < 2 * N; ++b) {
    int nodes[2] = {2 * b, 2 * b + 1}, beam;
    ok(b2b_model_add_beam(m, nodes, 2, 0, 0.1, B2B_CURVE_LINEAR, b < N ? 0 : 1, &beam, msg,
                          sizeof msg), msg);
    double *q = x + 6 * (size_t)b;
    const int i = b % N;
    if (b < N) { /* along x at y = i d */
      q[0] = -1; q[1] = i * d; q[2] = 0; q[3] = len; q[4] = i * d; q[5] = 0;
    } else { /* along y at x = (i + 1/2) d, 0.15 above */
      q[0] = (i + 0.5) * d; q[1] = -1; q[2] = 0.15;
      q[3] = (i + 0.5) * d; q[4] = len; q[5] = 0.15;
    }
  }
  ok(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, 4 * N, msg, sizeof msg), msg);
  ok(b2b_model_set_int(m, "threads", 2, msg, sizeof msg), msg);
  ck_assert(limit_memory(250));
  const int st = b2b_model_update(m, x, 3, 4 * N, 1, msg, sizeof msg);
  ck_assert_msg(st == B2B_ERR_NOMEM, "update under a memory limit: status %d (%s)", st, msg);
  int n;
  ck_assert_int_eq(b2b_model_contact_count(m, &n, NULL, 0), B2B_ERR_STATE);
  printf("check_model_hostile: narrow phase: %s\n", msg);
  /* the limit lifted, the same update goes through: all N^2 crossings */
  ck_assert(lift_memory_limit());
  ok(b2b_model_update(m, x, 3, 4 * N, 1, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), N * N);
  free(x);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* The grid of out_of_memory_in_the_narrow_phase: beams 0 .. N-1 along x in
 * the plane z = 0, beams N .. 2N-1 along y at height z over it (0.15: every
 * crossing active, radius 0.1); only the first `pressed` of the y beams at
 * 0.15, the others 3 above. */
static void grid_x(double *x, int n, int pressed) {
  const double d = 0.5, len = n * d + 1.0;
  for (int b = 0; b < 2 * n; ++b) {
    double *q = x + 6 * (size_t)b;
    const int i = b % n;
    if (b < n) {
      q[0] = -1; q[1] = i * d; q[2] = 0; q[3] = len; q[4] = i * d; q[5] = 0;
    } else {
      const double z = i < pressed ? 0.15 : 3.0;
      q[0] = (i + 0.5) * d; q[1] = -1; q[2] = z;
      q[3] = (i + 0.5) * d; q[4] = len; q[5] = z;
    }
  }
}

START_TEST(out_of_memory_after_an_update) {
  /* issue 20: a reusing update writes its contacts' results over the pages
   * of the update before last while the model keeps the last one's. The
   * first update here finds 8 N contacts and succeeds; the second, with
   * every crossing pressed, wants the results of all N^2 = 102,400 (2.8 kB
   * each) under a limit of 150 MB more than the process holds, runs out in
   * the parallel evaluation, and must leave every contact of the first
   * (nodes, info, residual, tangent) and its stats as they were. */
  if (UNDER_ASAN) {
    printf("check_model_hostile: out_of_memory_after_an_update skipped under ASan\n");
    return;
  }
  enum { N = 320, PRESSED = 8, NC = N * PRESSED, KK = B2B_PAIR_NDOF * B2B_PAIR_NDOF };
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  double *x = malloc(12 * (size_t)N * sizeof(double));
  for (int b = 0; b < 2 * N; ++b) {
    int nodes[2] = {2 * b, 2 * b + 1}, beam;
    ok(b2b_model_add_beam(m, nodes, 2, 0, 0.1, B2B_CURVE_LINEAR, b < N ? 0 : 1, &beam, msg,
                          sizeof msg), msg);
  }
  ok(b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg), msg);
  ok(b2b_model_finalize(m, 4 * N, msg, sizeof msg), msg);
  ok(b2b_model_set_int(m, "threads", 2, msg, sizeof msg), msg);
  grid_x(x, N, PRESSED);
  ok(b2b_model_update(m, x, 3, 4 * N, 1, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), NC);
  /* what the model reports now, kept before the limit */
  int counts[2][B2B_MODEL_COUNTS_LEN];
  double totals[2][B2B_MODEL_TOTALS_LEN];
  int *nodes = malloc(2 * 8 * (size_t)NC * sizeof(int));
  double *info = malloc(2 * B2B_PAIR_INFO_LEN * (size_t)NC * sizeof(double));
  double *res = malloc(2 * B2B_PAIR_NDOF * (size_t)NC * sizeof(double));
  double *K = malloc(2 * (size_t)KK * NC * sizeof(double));
  for (int s = 0; s < 2; ++s) {
    if (s == 1) { /* the update that runs out of memory */
      grid_x(x, N, N);
      ck_assert(limit_memory(150));
      const int st = b2b_model_update(m, x, 3, 4 * N, 1, msg, sizeof msg);
      ck_assert_msg(st == B2B_ERR_NOMEM, "update under a memory limit: status %d (%s)", st, msg);
      printf("check_model_hostile: after an update: %s\n", msg);
      ck_assert_int_eq(count_contacts(m), NC);
    }
    ok(b2b_model_stats(m, counts[s], totals[s], msg, sizeof msg), msg);
    for (int k = 0; k < NC; ++k) {
      const size_t at = (size_t)s * NC + k;
      ok(b2b_model_get_contact(m, k, nodes + 8 * at, NULL, info + B2B_PAIR_INFO_LEN * at,
                               res + B2B_PAIR_NDOF * at, K + (size_t)KK * at, B2B_PAIR_NDOF, msg,
                               sizeof msg), msg);
    }
  }
  ck_assert_msg(memcmp(counts[0], counts[1], sizeof counts[0]) == 0, "stats counts changed");
  ck_assert_msg(memcmp(totals[0], totals[1], sizeof totals[0]) == 0, "stats totals changed");
  ck_assert_msg(memcmp(nodes, nodes + 8 * (size_t)NC, 8 * (size_t)NC * sizeof(int)) == 0,
                "contact nodes changed");
  ck_assert_msg(memcmp(info, info + B2B_PAIR_INFO_LEN * (size_t)NC,
                       B2B_PAIR_INFO_LEN * (size_t)NC * sizeof(double)) == 0, "contact info changed");
  ck_assert_msg(memcmp(res, res + B2B_PAIR_NDOF * (size_t)NC,
                       B2B_PAIR_NDOF * (size_t)NC * sizeof(double)) == 0, "residuals changed");
  ck_assert_msg(memcmp(K, K + (size_t)KK * NC, (size_t)KK * NC * sizeof(double)) == 0,
                "tangents changed");
  /* the limit lifted, the same update goes through: all N^2 crossings */
  ck_assert(lift_memory_limit());
  ok(b2b_model_update(m, x, 3, 4 * N, 1, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), N * N);
  free(K);
  free(res);
  free(info);
  free(nodes);
  free(x);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(candidate_bound) {
  /* finding 5: no bound on the candidates of an update. 300 stacked
   * segments: 44,850 candidates. */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p;
  double *x;
  b2b_model *m = stack_model(300, &x, &p);
  ok(b2b_model_set_int(m, "max_candidates", 1000, msg, sizeof msg), msg);
  int st = b2b_model_update(m, x, 3, 600, 0, msg, sizeof msg);
  ck_assert_msg(st == B2B_ERR_SIZE, "1000 candidates at most: status %d (%s)", st, msg);
  ck_assert_msg(strstr(msg, "max_candidates") != NULL, "%s", msg);
  printf("check_model_hostile: %s\n", msg);
  int n;
  ck_assert_int_eq(b2b_model_contact_count(m, &n, NULL, 0), B2B_ERR_STATE);
  EXPECT_FAIL(B2B_ERR_RANGE, "max_candidates", ">= 1", NULL,
              b2b_model_set_int(m, "max_candidates", 0, msg, sizeof msg));
  ok(b2b_model_set_int(m, "max_candidates", 44850, msg, sizeof msg), msg);
  ok(b2b_model_update(m, x, 3, 600, 0, msg, sizeof msg), msg);
  int counts[16];
  ok(b2b_model_stats(m, counts, NULL, msg, sizeof msg), msg);
  ck_assert_int_eq(counts[B2B_COUNT_CANDIDATES], 44850);
  /* lowered after an update: the next update searches again under it */
  ok(b2b_model_set_int(m, "max_candidates", 44849, msg, sizeof msg), msg);
  st = b2b_model_update(m, x, 3, 600, 0, msg, sizeof msg);
  ck_assert_msg(st == B2B_ERR_SIZE, "lowered bound: status %d (%s)", st, msg);
  ok(b2b_model_stats(m, counts, NULL, msg, sizeof msg), msg);  /* the last good update's */
  ck_assert_int_eq(counts[B2B_COUNT_CANDIDATES], 44850);
  free(x);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(all_nodes_on_one_point) {
  /* finding 5: with every node on one point the O(n^2) search ran before
   * the O(n) coincident-node check. 20,000 beams: 2e8 pairs to search
   * before; now B2B_ERR_COINCIDENT at once, naming the first element. */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p;
  double *x;
  b2b_model *m = stack_model(20000, &x, &p);
  for (int k = 0; k < 6 * 20000; ++k) x[k] = 0.25;
  const double t0 = cpu_seconds();
  const int st = b2b_model_update(m, x, 3, 40000, 0, msg, sizeof msg);
  const double t = cpu_seconds() - t0;
  ck_assert_msg(st == B2B_ERR_COINCIDENT, "all nodes on one point: status %d (%s)", st, msg);
  ck_assert_msg(strstr(msg, "beam 0, segment 0: nodes 0 and 1 coincide") != NULL, "%s", msg);
  ck_assert_msg(t < 0.5, "the refusal took %.2f s of CPU time", t);
  printf("check_model_hostile: all nodes on one point: %s (%.3f s)\n", msg, t);
  free(x);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* ------------------------------------------------------ messages and stats */

START_TEST(threads_message) {
  /* finding 7: the message of set_int("threads", -1) converted the
   * unbounded upper side (infinity) to long long (UB). */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  EXPECT_FAIL(B2B_ERR_RANGE, "\"threads\" = -1 must be >= 0", NULL, NULL,
              b2b_model_set_int(m, "threads", -1, msg, sizeof msg));
  b2b_model_destroy(&m);
}
END_TEST

START_TEST(numbers_in_messages_at_int_max) {
  /* found by fuzz_model_calls: with "message_base" 1 a caller's number of
   * INT_MAX was shown as INT_MAX + 1 in int (signed overflow, UBSan). */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_model *m = NULL;
  ok(b2b_model_create(&m, msg, sizeof msg), msg);
  ok(b2b_model_set_int(m, "message_base", 1, msg, sizeof msg), msg);
  int nodes[2] = {INT_MAX, INT_MAX}, beam;
  EXPECT_FAIL(B2B_ERR_RANGE, "node 2147483648 appears twice", NULL, NULL,
              b2b_model_add_beam(m, nodes, 2, 0, 0.1, B2B_CURVE_LINEAR, 0, &beam, msg, sizeof msg));
  EXPECT_FAIL(B2B_ERR_RANGE, "beam 2147483648 does not exist", NULL, NULL,
              b2b_model_set_self_contact(m, INT_MAX, 1, -1.0, msg, sizeof msg));
  nodes[0] = 0;
  ok(b2b_model_add_beam(m, nodes, 2, 0, 0.1, B2B_CURVE_LINEAR, 0, &beam, msg, sizeof msg), msg);
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  ok(b2b_model_set_group_pair(m, 0, 0, p, msg, sizeof msg), msg);
  EXPECT_FAIL(B2B_ERR_RANGE, "node 2147483648 (position 2", NULL, NULL,
              b2b_model_finalize(m, 5, msg, sizeof msg));
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(stats_after_revert_and_restore) {
  /* finding 8: stats returned the reverted update's counts with B2B_OK. */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p;
  unsigned char *buf;
  int64_t size;
  b2b_model *m = committed_crossing(0.3, &p, &buf, &size);
  int counts[16];
  double totals[8];
  ok(b2b_model_stats(m, counts, totals, msg, sizeof msg), msg);  /* committed update's */
  ck_assert_int_eq(counts[B2B_COUNT_ACTIVE], 1);
  double x[24];
  crossing_x(x, 0.01);
  ok(b2b_model_update(m, x, 3, 8, 0, msg, sizeof msg), msg);
  ok(b2b_model_revert(m, msg, sizeof msg), msg);
  for (int k = 0; k < 16; ++k) counts[k] = -7;
  EXPECT_FAIL(B2B_ERR_STATE, "no update", NULL, NULL,
              b2b_model_stats(m, counts, totals, msg, sizeof msg));
  for (int k = 0; k < 16; ++k) ck_assert_int_eq(counts[k], -7);
  ok(b2b_model_update(m, x, 3, 8, 0, msg, sizeof msg), msg);
  ok(b2b_model_stats(m, counts, totals, msg, sizeof msg), msg);
  ok(b2b_model_restore(m, buf, size, msg, sizeof msg), msg);
  EXPECT_FAIL(B2B_ERR_STATE, "no update", NULL, NULL,
              b2b_model_stats(m, counts, totals, msg, sizeof msg));
  free(buf);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* -------------------------------------------- options changed between updates */

START_TEST(search_margin_raised_after_an_update) {
  /* issue 16, item 3: the new margin did not invalidate the candidates.
   * Beam B starts 1.0 above A (margin 0.01: no candidate), the margin is
   * raised to 5, and B comes down to 0.15 (penetrating) without leaving the
   * old skin test's half margin: before the fix, 0 candidates, 0 contacts. */
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p;
  b2b_model *m = crossing(0.0, &p);
  ok(b2b_model_set_real(m, "search_margin", 0.01, msg, sizeof msg), msg);
  double x[24];
  crossing_x(x, 0.0);
  x[3 * 4 + 2] = x[3 * 5 + 2] = 1.0;
  ok(b2b_model_update(m, x, 3, 8, 0, msg, sizeof msg), msg);
  ck_assert_int_eq(count_contacts(m), 0);
  ok(b2b_model_commit(m, msg, sizeof msg), msg);
  ok(b2b_model_set_real(m, "search_margin", 5.0, msg, sizeof msg), msg);
  x[3 * 4 + 2] = x[3 * 5 + 2] = 0.15;
  ok(b2b_model_update(m, x, 3, 8, 0, msg, sizeof msg), msg);
  const int n = count_contacts(m);
  ck_assert_msg(n == 1, "after raising search_margin: %d contacts (1 expected)", n);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
}
END_TEST

/* Every option set after the first committed step: the contacts of the
 * steps after it are those of a twin that had it from the start. */
static void same_as_from_the_start(const char *key, int is_real, double value) {
  char msg[B2B_ERRMSG_LEN] = "";
  tst_rng rng;
  tst_rng_seed(&rng, 1717);
  tst_scene sc;
  tst_network(&rng, 30, 9, 0.5, 2.0, 0.1, 0.3, 5, 2, &sc);
  const size_t nx = 3 * (size_t)sc.n_nodes;
  double *x0 = malloc(nx * sizeof(double)), *v = malloc(nx * sizeof(double));
  memcpy(x0, sc.x, nx * sizeof(double));
  for (size_t k = 0; k < nx; ++k) v[k] = tst_uniform(&rng, -0.04, 0.04);
  b2b_params *p = tst_params_friction(B2B_LAW_QUADRATIC, 1e3, 0.02, 0.3, 1.5e3);
  b2b_model *late = tst_model(&sc, p, 1), *early = tst_model(&sc, p, 1);
  /* "early" gets the option now: before finalize is not possible any more
   * (tst_model finalizes), so right after, before any update */
  if (is_real)
    ok(b2b_model_set_real(early, key, value, msg, sizeof msg), msg);
  else
    ok(b2b_model_set_int(early, key, (int)value, msg, sizeof msg), msg);
  enum { MAXC = 4096 };
  tst_contact *c1 = malloc(MAXC * sizeof *c1), *c2 = malloc(MAXC * sizeof *c2);
  int compared = 0;
  for (int step = 0; step < 6; ++step) {
    memcpy(sc.x, x0, nx * sizeof(double));
    tst_scene_move(&sc, v, step);
    tst_update(late, &sc, 1);
    if (step > 0) {
      tst_update(early, &sc, 1);
      const int n1 = tst_model_contacts(late, c1, MAXC), n2 = tst_model_contacts(early, c2, MAXC);
      ck_assert_msg(n1 == n2 && memcmp(c1, c2, (size_t)n1 * sizeof *c1) == 0,
                    "\"%s\" set after step 0: step %d gives %d contacts, %d from the start", key,
                    step, n1, n2);
      compared += n1;
      ok(b2b_model_commit(early, msg, sizeof msg), msg);
    }
    ok(b2b_model_commit(late, msg, sizeof msg), msg);
    if (step == 0) {
      /* the twin takes the committed state of step 0 */
      int64_t size;
      unsigned char *buf = saved(late, &size);
      ok(b2b_model_restore(early, buf, size, msg, sizeof msg), msg);
      free(buf);
      if (is_real)
        ok(b2b_model_set_real(late, key, value, msg, sizeof msg), msg);
      else
        ok(b2b_model_set_int(late, key, (int)value, msg, sizeof msg), msg);
    }
  }
  printf("check_model_hostile: \"%s\" = %g set between steps: %d contacts compared\n", key, value,
         compared);
  ck_assert_msg(compared > 0, "no contacts compared");
  free(c1);
  free(c2);
  free(x0);
  free(v);
  b2b_model_destroy(&late);
  b2b_model_destroy(&early);
  b2b_params_destroy(&p);
  tst_scene_free(&sc);
}

START_TEST(each_option_changed_between_updates) {
  same_as_from_the_start("search_margin", 1, 0.02);
  same_as_from_the_start("search_margin", 1, 0.8);
  same_as_from_the_start("threads", 0, 1);
  same_as_from_the_start("max_handover_hops", 0, 1);
  same_as_from_the_start("message_base", 0, 1);
  same_as_from_the_start("max_candidates", 0, 1000000);
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_hostile");
  TCase *restart = tcase_create("restart");
  tcase_add_test(restart, restore_pair_of_unpaired_groups_with_huge_index);
  tcase_add_test(restart, restore_nonfinite_or_huge_doubles);
  tcase_add_test(restart, restore_foreign_friction);
  tcase_add_test(restart, restore_self_contact_lies);
  suite_add_tcase(s, restart);
  TCase *state = tcase_create("state");
  tcase_add_test(state, revert_of_the_first_update_forgets_its_arc_lengths);
  tcase_add_test(state, stats_after_revert_and_restore);
  tcase_add_test(state, search_margin_raised_after_an_update);
  tcase_add_test(state, each_option_changed_between_updates);
  tcase_add_test(state, threads_message);
  tcase_add_test(state, numbers_in_messages_at_int_max);
  suite_add_tcase(s, state);
  TCase *sizes = tcase_create("sizes");
  tcase_add_test(sizes, band_whose_size_overflows_int);
  tcase_add_test(sizes, eq_base_int_min);
  tcase_add_test(sizes, finalize_int_max_nodes);
  tcase_add_test(sizes, many_groups);
  tcase_add_test(sizes, out_of_memory_in_the_broad_phase);
  tcase_add_test(sizes, out_of_memory_in_the_narrow_phase);
  tcase_add_test(sizes, out_of_memory_after_an_update);
  tcase_add_test(sizes, candidate_bound);
  tcase_add_test(sizes, all_nodes_on_one_point);
  suite_add_tcase(s, sizes);
  /* limit_memory's limits end with their test only in a process of its
   * own (CI sets CK_FORK=no for the other suites). */
  return tst_run_suite_forked(s);
}
