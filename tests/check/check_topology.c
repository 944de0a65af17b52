/* Beam topology: b2b_beam_segment_count and b2b_beam_segment_patch for every
 * curve kind, open beams and rings, from the smallest beam up to 7 nodes,
 * checked against the rules of <b2b/b2b_curve.h>:
 *   counts      LINEAR / nodal: n - 1 open, n closed; MIDPOINT: n both;
 *   slots       nodal: {s-1, s, s+1, s+2}; LINEAR: {-1, s, s+1, -1};
 *               MIDPOINT: {s-1, s, s+1, -1}; -1 outside an open beam,
 *               modulo n on a ring;
 *   rules       REFLECT exactly at the start of the first and the end of the
 *               last segment of an open beam, NEIGHBOUR everywhere else. */
#include <limits.h>
#include <string.h>

#include "test_support.h"

#define N_MAX 7
#define SENTINEL_INT (-777)

static int min_nodes(int closed) { return closed ? 3 : 2; }

/* The patch slots a segment of the kind reads inside a beam (bit k: slot
 * x(k+1)), as the header documents them. */
static unsigned inner_slots(int kind) {
  switch (tst_kind_family(kind)) {
    case TST_CHORD: return 0x6u;
    case TST_CENTRED: return 0x7u;
    case TST_NODAL: return 0xfu;
  }
  return 0u;
}

/* The slots (0-based) of the neighbours before the segment's first node and
 * after its last, which a beam end replaces by its rule; -1: not read. */
static void neighbour_slots(int kind, int *before, int *after) {
  *before = *after = -1;
  switch (tst_kind_family(kind)) {
    case TST_CHORD: break;
    case TST_CENTRED: *before = 0, *after = 2; break;
    case TST_NODAL: *before = 0, *after = 3; break;
  }
}

/* One segment per node, centred on it, rather than one per element. */
static int centred_on_node(int kind) { return tst_kind_family(kind) == TST_CENTRED; }

static int expected_count(int kind, int n, int closed) {
  if (centred_on_node(kind)) return n;
  return closed ? n : n - 1;
}

/* Beam node k (any integer) of an n-node beam: wrapped on a ring, -1 outside
 * an open beam. Written in long long so that it holds for any int n. */
static int beam_node(long long k, int n, int closed) {
  if (closed) return (int)(((k % n) + n) % n);
  return (k < 0 || k >= n) ? -1 : (int)k;
}

static int count_of(int kind, int n, int closed) {
  int count = SENTINEL_INT;
  char msg[B2B_ERRMSG_LEN];
  memset(msg, 'Z', sizeof msg);
  const int st = b2b_beam_segment_count(kind, n, closed, &count, msg, (int)sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_beam_segment_count(%s, n=%d, closed=%d) = %d: %.*s",
                tst_kind_name(kind), n, closed, st, (int)sizeof msg, msg);
  for (size_t i = 0; i < sizeof msg; ++i)
    ck_assert_msg(msg[i] == 'Z', "a successful b2b_beam_segment_count wrote errmsg[%zu]", i);
  return count;
}

static void patch_of(int kind, int n, int closed, int s, int nodes[4], int *sr, int *er) {
  char msg[B2B_ERRMSG_LEN];
  memset(msg, 'Z', sizeof msg);
  for (int k = 0; k < 4; ++k) nodes[k] = SENTINEL_INT;
  *sr = *er = SENTINEL_INT;
  const int st = b2b_beam_segment_patch(kind, n, closed, s, nodes, sr, er, msg, (int)sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_beam_segment_patch(%s, n=%d, closed=%d, segment=%d) = %d: %.*s",
                tst_kind_name(kind), n, closed, s, st, (int)sizeof msg, msg);
  for (size_t i = 0; i < sizeof msg; ++i)
    ck_assert_msg(msg[i] == 'Z', "a successful b2b_beam_segment_patch wrote errmsg[%zu]", i);
}

#define ASSERT_NODES(kind, n, closed, s, got, e0, e1, e2, e3)                                  \
  do {                                                                                         \
    const int want_[4] = {(e0), (e1), (e2), (e3)};                                             \
    for (int k_ = 0; k_ < 4; ++k_)                                                             \
      ck_assert_msg((got)[k_] == want_[k_],                                                    \
                    "%s, n=%d, %s, segment %d: nodes = {%d, %d, %d, %d}, expected {%d, %d, %d, " \
                    "%d}",                                                                     \
                    tst_kind_name(kind), (n), (closed) ? "closed" : "open", (s), (got)[0],    \
                    (got)[1], (got)[2], (got)[3], want_[0], want_[1], want_[2], want_[3]);     \
  } while (0)

/* ------------------------------------------------------------------ counts */

START_TEST(test_counts) {
  const int kind = _i;
  for (int closed = 0; closed <= 1; ++closed)
    for (int n = min_nodes(closed); n <= N_MAX; ++n) {
      const int count = count_of(kind, n, closed);
      ck_assert_msg(count == expected_count(kind, n, closed),
                    "%s, n=%d, %s: %d segments, expected %d", tst_kind_name(kind), n,
                    closed ? "closed" : "open", count, expected_count(kind, n, closed));
    }
}
END_TEST

/* The documented counts, spelled out. */
START_TEST(test_counts_table) {
  ck_assert_int_eq(count_of(B2B_CURVE_LINEAR, 2, 0), 1);
  ck_assert_int_eq(count_of(B2B_CURVE_LINEAR, 5, 0), 4);
  ck_assert_int_eq(count_of(B2B_CURVE_LINEAR, 3, 1), 3);
  ck_assert_int_eq(count_of(B2B_CURVE_HERMITE_NODAL, 2, 0), 1);
  ck_assert_int_eq(count_of(B2B_CURVE_HERMITE_NODAL, 7, 1), 7);
  ck_assert_int_eq(count_of(B2B_CURVE_HERMITE_NODAL_WEIGHTED, 6, 0), 5);
  ck_assert_int_eq(count_of(B2B_CURVE_HERMITE_NODAL_WEIGHTED, 4, 1), 4);
  ck_assert_int_eq(count_of(B2B_CURVE_HERMITE_MIDPOINT, 2, 0), 2);
  ck_assert_int_eq(count_of(B2B_CURVE_HERMITE_MIDPOINT, 6, 0), 6);
  ck_assert_int_eq(count_of(B2B_CURVE_HERMITE_MIDPOINT, 3, 1), 3);
}
END_TEST

/* ------------------------------------------------------------------- slots */

START_TEST(test_patch_slots) {
  const int kind = _i;
  for (int closed = 0; closed <= 1; ++closed)
    for (int n = min_nodes(closed); n <= N_MAX; ++n) {
      const int count = expected_count(kind, n, closed);
      for (int s = 0; s < count; ++s) {
        int nodes[4], sr, er;
        patch_of(kind, n, closed, s, nodes, &sr, &er);
        int want[4];
        for (int k = 0; k < 4; ++k)
          want[k] = (inner_slots(kind) >> k & 1u) ? beam_node((long long)s - 1 + k, n, closed) : -1;
        ASSERT_NODES(kind, n, closed, s, nodes, want[0], want[1], want[2], want[3]);
        /* Every slot is a beam node or -1; slot x2 is always node s. */
        for (int k = 0; k < 4; ++k) ck_assert(nodes[k] >= -1 && nodes[k] < n);
        ck_assert_int_eq(nodes[1], s);
      }
    }
}
END_TEST

START_TEST(test_patch_rules) {
  const int kind = _i;
  for (int closed = 0; closed <= 1; ++closed)
    for (int n = min_nodes(closed); n <= N_MAX; ++n) {
      const int count = expected_count(kind, n, closed);
      for (int s = 0; s < count; ++s) {
        int nodes[4], sr, er;
        patch_of(kind, n, closed, s, nodes, &sr, &er);
        const int want_sr = (!closed && s == 0) ? B2B_END_REFLECT : B2B_END_NEIGHBOUR;
        const int want_er = (!closed && s == count - 1) ? B2B_END_REFLECT : B2B_END_NEIGHBOUR;
        ck_assert_msg(sr == want_sr && er == want_er,
                      "%s, n=%d, %s, segment %d: rules (%d, %d), expected (%d, %d)",
                      tst_kind_name(kind), n, closed ? "closed" : "open", s, sr, er, want_sr,
                      want_er);
        /* The slot that a REFLECT rule replaces is missing, and only then
         * (for the kinds that read it). */
        int before, after;
        neighbour_slots(kind, &before, &after);
        if (before >= 0) ck_assert_int_eq(nodes[before] == -1, sr == B2B_END_REFLECT);
        if (after >= 0) ck_assert_int_eq(nodes[after] == -1, er == B2B_END_REFLECT);
        /* A segment centred on a node never both starts and ends the beam. */
        if (centred_on_node(kind)) ck_assert(!(sr == B2B_END_REFLECT && er == B2B_END_REFLECT));
      }
    }
}
END_TEST

/* Hand-written patches of small beams, straight from the header's rules. */
START_TEST(test_patch_table) {
  int v[4], sr, er;
  const int L = B2B_CURVE_LINEAR, M = B2B_CURVE_HERMITE_MIDPOINT, N = B2B_CURVE_HERMITE_NODAL,
            W = B2B_CURVE_HERMITE_NODAL_WEIGHTED;
  const int R = B2B_END_REFLECT, B = B2B_END_NEIGHBOUR;

  /* Nodal, open, 4 nodes: 3 segments. */
  patch_of(N, 4, 0, 0, v, &sr, &er);
  ASSERT_NODES(N, 4, 0, 0, v, -1, 0, 1, 2);
  ck_assert(sr == R && er == B);
  patch_of(N, 4, 0, 1, v, &sr, &er);
  ASSERT_NODES(N, 4, 0, 1, v, 0, 1, 2, 3);
  ck_assert(sr == B && er == B);
  patch_of(N, 4, 0, 2, v, &sr, &er);
  ASSERT_NODES(N, 4, 0, 2, v, 1, 2, 3, -1);
  ck_assert(sr == B && er == R);

  /* Nodal weighted, open, 2 nodes: one segment that is both ends. */
  patch_of(W, 2, 0, 0, v, &sr, &er);
  ASSERT_NODES(W, 2, 0, 0, v, -1, 0, 1, -1);
  ck_assert(sr == R && er == R);

  /* Nodal, ring of 3. */
  patch_of(N, 3, 1, 0, v, &sr, &er);
  ASSERT_NODES(N, 3, 1, 0, v, 2, 0, 1, 2);
  ck_assert(sr == B && er == B);
  patch_of(W, 3, 1, 2, v, &sr, &er);
  ASSERT_NODES(W, 3, 1, 2, v, 1, 2, 0, 1);
  ck_assert(sr == B && er == B);

  /* Linear. */
  patch_of(L, 3, 0, 0, v, &sr, &er);
  ASSERT_NODES(L, 3, 0, 0, v, -1, 0, 1, -1);
  ck_assert(sr == R && er == B);
  patch_of(L, 3, 0, 1, v, &sr, &er);
  ASSERT_NODES(L, 3, 0, 1, v, -1, 1, 2, -1);
  ck_assert(sr == B && er == R);
  patch_of(L, 4, 1, 3, v, &sr, &er);
  ASSERT_NODES(L, 4, 1, 3, v, -1, 3, 0, -1);
  ck_assert(sr == B && er == B);

  /* Midpoint, open, 3 nodes: 3 segments centred on the nodes. */
  patch_of(M, 3, 0, 0, v, &sr, &er);
  ASSERT_NODES(M, 3, 0, 0, v, -1, 0, 1, -1);
  ck_assert(sr == R && er == B);
  patch_of(M, 3, 0, 1, v, &sr, &er);
  ASSERT_NODES(M, 3, 0, 1, v, 0, 1, 2, -1);
  ck_assert(sr == B && er == B);
  patch_of(M, 3, 0, 2, v, &sr, &er);
  ASSERT_NODES(M, 3, 0, 2, v, 1, 2, -1, -1);
  ck_assert(sr == B && er == R);
  /* Midpoint, open, 2 nodes: two half elements. */
  patch_of(M, 2, 0, 0, v, &sr, &er);
  ASSERT_NODES(M, 2, 0, 0, v, -1, 0, 1, -1);
  ck_assert(sr == R && er == B);
  patch_of(M, 2, 0, 1, v, &sr, &er);
  ASSERT_NODES(M, 2, 0, 1, v, 0, 1, -1, -1);
  ck_assert(sr == B && er == R);
  /* Midpoint ring of 4. */
  patch_of(M, 4, 1, 0, v, &sr, &er);
  ASSERT_NODES(M, 4, 1, 0, v, 3, 0, 1, -1);
  ck_assert(sr == B && er == B);
  patch_of(M, 4, 1, 3, v, &sr, &er);
  ASSERT_NODES(M, 4, 1, 3, v, 2, 3, 0, -1);
  ck_assert(sr == B && er == B);
}
END_TEST

/* Rings: every slot a real node (modulo n), only NEIGHBOUR rules, and every
 * node in slot x2 exactly once. */
START_TEST(test_closed_rings) {
  const int kind = _i;
  for (int n = 3; n <= N_MAX; ++n) {
    int seen[N_MAX] = {0};
    const int count = count_of(kind, n, 1);
    ck_assert_int_eq(count, n);
    for (int s = 0; s < count; ++s) {
      int v[4], sr, er;
      patch_of(kind, n, 1, s, v, &sr, &er);
      ck_assert_int_eq(sr, B2B_END_NEIGHBOUR);
      ck_assert_int_eq(er, B2B_END_NEIGHBOUR);
      ck_assert_int_eq(v[0] >= 0, (inner_slots(kind) & 0x1u) != 0);
      ck_assert(v[1] >= 0 && v[1] < n && v[2] >= 0 && v[2] < n);
      ck_assert_int_eq(v[3] >= 0, (inner_slots(kind) & 0x8u) != 0);
      ck_assert_int_eq(v[2], (v[1] + 1) % n);
      if (v[0] >= 0) ck_assert_int_eq(v[0], (v[1] + n - 1) % n);
      if (v[3] >= 0) ck_assert_int_eq(v[3], (v[1] + 2) % n);
      ++seen[v[1]];
    }
    for (int k = 0; k < n; ++k) ck_assert_msg(seen[k] == 1, "node %d is x2 of %d segments", k, seen[k]);
  }
}
END_TEST

/* ------------------------------------------------------------ consistency */

START_TEST(test_consecutive_segments_share_nodes) {
  const int kind = _i;
  for (int closed = 0; closed <= 1; ++closed)
    for (int n = min_nodes(closed); n <= N_MAX; ++n) {
      const int count = count_of(kind, n, closed);
      for (int s = 0; s + 1 < count + closed; ++s) {
        const int t = (s + 1) % count; /* on a ring the last segment joins the first */
        int a[4], b[4], sra, era, srb, erb;
        patch_of(kind, n, closed, s, a, &sra, &era);
        patch_of(kind, n, closed, t, b, &srb, &erb);
        if (centred_on_node(kind)) {
          ck_assert_int_eq(b[1], t);
          ck_assert_int_eq(a[2], b[1]); /* element x2-x3 of s is element x1-x2 of s + 1 */
          ck_assert_int_eq(a[1], b[0]);
        } else {
          ck_assert_msg(a[2] == b[1], "%s n=%d %s: slot 2 of segment %d (%d) != slot 1 of %d (%d)",
                        tst_kind_name(kind), n, closed ? "closed" : "open", s, a[2], t, b[1]);
          if (inner_slots(kind) == 0xfu) { /* the patches overlap by three nodes */
            ck_assert_int_eq(a[1], b[0]);
            ck_assert_int_eq(a[3], b[2]);
          }
        }
        /* No rule change inside the beam. */
        ck_assert_int_eq(era, B2B_END_NEIGHBOUR);
        ck_assert_int_eq(srb, B2B_END_NEIGHBOUR);
      }
    }
}
END_TEST

/* The segments of an open beam cover it: the first starts at node 0, the
 * last ends at node n - 1 (midpoint: is centred on it). */
START_TEST(test_open_beam_covered) {
  const int kind = _i;
  for (int n = 2; n <= N_MAX; ++n) {
    const int count = count_of(kind, n, 0);
    int v[4], sr, er;
    patch_of(kind, n, 0, 0, v, &sr, &er);
    ck_assert_int_eq(v[1], 0);
    patch_of(kind, n, 0, count - 1, v, &sr, &er);
    if (centred_on_node(kind))
      ck_assert_int_eq(v[1], n - 1);
    else
      ck_assert_int_eq(v[2], n - 1);
  }
}
END_TEST

/* The topology is pure integer arithmetic: it must hold for any valid int
 * n_nodes, not only for small beams. One test per (n_nodes, open/closed). */
static const int big_n[] = {(1 << 30) + 3, INT_MAX - 1, INT_MAX};

START_TEST(test_large_beams) {
  const int n = big_n[_i / 2];
  const int closed = _i % 2;
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    const int count = count_of(kind, n, closed);
    ck_assert_int_eq(count, expected_count(kind, n, closed));
    const int segs[] = {0, 1, count / 2, count - 2, count - 1};
    for (size_t j = 0; j < sizeof segs / sizeof segs[0]; ++j) {
      const int s = segs[j];
      int v[4], sr, er;
      patch_of(kind, n, closed, s, v, &sr, &er);
      int want[4];
      for (int q = 0; q < 4; ++q)
        want[q] = (inner_slots(kind) >> q & 1u) ? beam_node((long long)s - 1 + q, n, closed) : -1;
      ASSERT_NODES(kind, n, closed, s, v, want[0], want[1], want[2], want[3]);
      ck_assert_int_eq(sr, (!closed && s == 0) ? B2B_END_REFLECT : B2B_END_NEIGHBOUR);
      ck_assert_int_eq(er, (!closed && s == count - 1) ? B2B_END_REFLECT : B2B_END_NEIGHBOUR);
    }
  }
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("topology");
  TCase *tc;

  tc = tcase_create("count");
  tcase_add_loop_test(tc, test_counts, 0, B2B_CURVE_KIND_COUNT);
  tcase_add_test(tc, test_counts_table);
  suite_add_tcase(s, tc);

  tc = tcase_create("patch");
  tcase_add_loop_test(tc, test_patch_slots, 0, B2B_CURVE_KIND_COUNT);
  tcase_add_loop_test(tc, test_patch_rules, 0, B2B_CURVE_KIND_COUNT);
  tcase_add_test(tc, test_patch_table);
  tcase_add_loop_test(tc, test_closed_rings, 0, B2B_CURVE_KIND_COUNT);
  suite_add_tcase(s, tc);

  tc = tcase_create("consistency");
  tcase_add_loop_test(tc, test_consecutive_segments_share_nodes, 0, B2B_CURVE_KIND_COUNT);
  tcase_add_loop_test(tc, test_open_beam_covered, 0, B2B_CURVE_KIND_COUNT);
  suite_add_tcase(s, tc);

  tc = tcase_create("large_beams");
  tcase_add_loop_test(tc, test_large_beams, 0, 2 * (int)(sizeof big_n / sizeof big_n[0]));
  suite_add_tcase(s, tc);

  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
