/* What each curve kind passes through: the nodal kinds through their nodes,
 * the midpoint kind through element midpoints (and the beam's end nodes),
 * the linear kind along its chord; on whole open beams and rings. */
#include <math.h>
#include <string.h>

#include "test_support.h"

#define N_NODES 9

/* A random open chain of nodes (a curved beam). */
static void random_chain(tst_rng *rng, int n, double *coords) {
  double patch[12];
  for (int k = 0; k < n; k += 3) {
    tst_random_patch(rng, 1.0, 0.7, patch);
    /* continue from the previous node so the chain is connected */
    const double *prev = k > 0 ? coords + 3 * (k - 1) : patch;
    for (int j = 0; j < 3 && k + j < n; ++j)
      for (int i = 0; i < 3; ++i)
        coords[3 * (k + j) + i] = prev[i] + patch[3 * (j + 1) + i] - patch[i];
  }
}

static double dist(const double *a, const double *b) {
  return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
              (a[2] - b[2]) * (a[2] - b[2]));
}

/* Round-off bound for points of size about |a|. */
static double roundoff(const double *a) { return 8 * 2.2e-16 * (1.0 + tst_max_abs(a, 3)); }

static void segment_ends(int kind, int n, int closed, int s, const double *coords, double *x0,
                         double *x1) {
  double patch[12], x[9];
  int sr, er;
  tst_gather_patch(kind, n, closed, s, coords, patch, &sr, &er);
  tst_eval(kind, sr, er, patch, NULL, -1.0, x, NULL, NULL);
  memcpy(x0, x, 3 * sizeof(double));
  tst_eval(kind, sr, er, patch, NULL, 1.0, x, NULL, NULL);
  memcpy(x1, x, 3 * sizeof(double));
}

START_TEST(nodal_kinds_pass_through_nodes) {
  tst_rng rng;
  tst_rng_seed(&rng, 11);
  double coords[3 * N_NODES];
  random_chain(&rng, N_NODES, coords);
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    /* A curve centred on a node cuts the corners (the midpoint kind: below). */
    if (tst_kind_family(kind) == TST_CENTRED) continue;
    for (int closed = 0; closed < 2; ++closed) {
      int nseg;
      ck_assert_int_eq(b2b_beam_segment_count(kind, N_NODES, closed, &nseg, NULL, 0), B2B_OK);
      for (int s = 0; s < nseg; ++s) {
        double x0[3], x1[3];
        segment_ends(kind, N_NODES, closed, s, coords, x0, x1);
        const double *a = coords + 3 * s, *b = coords + 3 * ((s + 1) % N_NODES);
        ck_assert_msg(dist(x0, a) <= roundoff(a), "%s segment %d misses its first node by %g",
                      tst_kind_name(kind), s, dist(x0, a));
        ck_assert_msg(dist(x1, b) <= roundoff(b), "%s segment %d misses its last node by %g",
                      tst_kind_name(kind), s, dist(x1, b));
      }
    }
  }
}
END_TEST

START_TEST(midpoint_kind_passes_through_element_midpoints) {
  tst_rng rng;
  tst_rng_seed(&rng, 12);
  double coords[3 * N_NODES];
  random_chain(&rng, N_NODES, coords);
  const int kind = B2B_CURVE_HERMITE_MIDPOINT;
  for (int closed = 0; closed < 2; ++closed) {
    int nseg;
    ck_assert_int_eq(b2b_beam_segment_count(kind, N_NODES, closed, &nseg, NULL, 0), B2B_OK);
    ck_assert_int_eq(nseg, N_NODES);
    for (int s = 0; s < nseg; ++s) {
      double x0[3], x1[3], m_prev[3], m_next[3];
      segment_ends(kind, N_NODES, closed, s, coords, x0, x1);
      const double *c = coords + 3 * s;
      const double *p = coords + 3 * ((s - 1 + N_NODES) % N_NODES);
      const double *q = coords + 3 * ((s + 1) % N_NODES);
      for (int i = 0; i < 3; ++i) {
        m_prev[i] = 0.5 * (p[i] + c[i]);
        m_next[i] = 0.5 * (c[i] + q[i]);
      }
      /* Open beams: the first segment starts at node 0, the last ends at node n-1. */
      const double *want0 = (!closed && s == 0) ? c : m_prev;
      const double *want1 = (!closed && s == nseg - 1) ? c : m_next;
      ck_assert_msg(dist(x0, want0) <= roundoff(want0), "midpoint segment %d start off by %g", s,
                    dist(x0, want0));
      ck_assert_msg(dist(x1, want1) <= roundoff(want1), "midpoint segment %d end off by %g", s,
                    dist(x1, want1));
      /* It cuts the corner: the centre node itself is not on the curve
       * (interior segments of a curved beam). */
      if (closed || (s > 0 && s < nseg - 1)) {
        double x[9];
        double patch[12];
        int sr, er;
        tst_gather_patch(kind, N_NODES, closed, s, coords, patch, &sr, &er);
        tst_eval(kind, sr, er, patch, NULL, 0.0, x, NULL, NULL);
        ck_assert_msg(dist(x, c) > 1e-3, "midpoint segment %d passes through its node", s);
      }
    }
  }
}
END_TEST

START_TEST(linear_kind_is_the_chord) {
  tst_rng rng;
  tst_rng_seed(&rng, 13);
  double patch[12], x[9];
  tst_random_patch(&rng, 1.0, 0.7, patch);
  const double xis[4] = {-1.0, -0.25, 0.5, 2.0};
  for (int q = 0; q < 4; ++q) {
    tst_eval(B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, patch, NULL, xis[q], x, NULL,
             NULL);
    for (int i = 0; i < 3; ++i) {
      const double want = 0.5 * (1 - xis[q]) * patch[3 + i] + 0.5 * (1 + xis[q]) * patch[6 + i];
      ck_assert(fabs(x[i] - want) <= 1e-14 * (1 + fabs(want)));
      ck_assert(fabs(x[3 + i] - 0.5 * (patch[6 + i] - patch[3 + i])) <= 1e-15 * (1 + fabs(x[3 + i])));
      ck_assert(x[6 + i] == 0.0);
    }
  }
}
END_TEST

/* Litewka's end tangents (doc/curves.md section 3.3):
 * dx/dxi(-1) = l23 (x3 - x1) / (2 l13). */
START_TEST(nodal_end_tangents_are_litewkas) {
  tst_rng rng;
  tst_rng_seed(&rng, 14);
  double patch[12], x[9];
  tst_random_patch(&rng, 1.0, 0.7, patch);
  double l13 = 0, l23 = 0, l24 = 0;
  for (int i = 0; i < 3; ++i) {
    l13 += (patch[6 + i] - patch[i]) * (patch[6 + i] - patch[i]);
    l23 += (patch[6 + i] - patch[3 + i]) * (patch[6 + i] - patch[3 + i]);
    l24 += (patch[9 + i] - patch[3 + i]) * (patch[9 + i] - patch[3 + i]);
  }
  l13 = sqrt(l13);
  l23 = sqrt(l23);
  l24 = sqrt(l24);
  tst_eval(B2B_CURVE_HERMITE_NODAL, 0, 0, patch, NULL, -1.0, x, NULL, NULL);
  for (int i = 0; i < 3; ++i)
    ck_assert(fabs(x[3 + i] - l23 * (patch[6 + i] - patch[i]) / (2 * l13)) <= 1e-14);
  tst_eval(B2B_CURVE_HERMITE_NODAL, 0, 0, patch, NULL, 1.0, x, NULL, NULL);
  for (int i = 0; i < 3; ++i)
    ck_assert(fabs(x[3 + i] - l23 * (patch[9 + i] - patch[3 + i]) / (2 * l24)) <= 1e-14);
  /* A reflected ghost gives the chord as end tangent. */
  tst_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_REFLECT, 0, patch, NULL, -1.0, x, NULL, NULL);
  for (int i = 0; i < 3; ++i)
    ck_assert(fabs(x[3 + i] - 0.5 * (patch[6 + i] - patch[3 + i])) <= 1e-14);
  /* A host tangent sets the direction; its length does not matter. */
  const double t[6] = {0.0, 0.0, 5.0, 1.0, 0.0, 0.0};
  tst_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_TANGENT, B2B_END_TANGENT, patch, t, -1.0, x, NULL,
           NULL);
  ck_assert(fabs(x[3]) <= 1e-15 && fabs(x[4]) <= 1e-15 && fabs(x[5] - 0.5 * l23) <= 1e-14);
  tst_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_TANGENT, B2B_END_TANGENT, patch, t, 1.0, x, NULL,
           NULL);
  ck_assert(fabs(x[3] - 0.5 * l23) <= 1e-14 && fabs(x[4]) <= 1e-15 && fabs(x[5]) <= 1e-15);
}
END_TEST

/* With equal neighbouring element lengths the weighted tangent is Litewka's
 * (doc/curves.md section 3.4). */
START_TEST(weighted_equals_nodal_on_uniform_spacing) {
  double coords[3 * 12];
  tst_ring_nodes(12, 2.0, 0, coords);
  for (int s = 0; s < 12; ++s) {
    double patch[12], a[9], b[9];
    int sr, er;
    tst_gather_patch(B2B_CURVE_HERMITE_NODAL, 12, 1, s, coords, patch, &sr, &er);
    for (double xi = -1.0; xi <= 1.0; xi += 0.25) {
      tst_eval(B2B_CURVE_HERMITE_NODAL, sr, er, patch, NULL, xi, a, NULL, NULL);
      tst_eval(B2B_CURVE_HERMITE_NODAL_WEIGHTED, sr, er, patch, NULL, xi, b, NULL, NULL);
      ck_assert_msg(tst_rel_diff(a, b, 9, 1.0) <= 1e-13, "segment %d xi %g differs", s, xi);
    }
  }
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("curve_interpolation");
  TCase *tc = tcase_create("interpolation");
  tcase_add_test(tc, nodal_kinds_pass_through_nodes);
  tcase_add_test(tc, midpoint_kind_passes_through_element_midpoints);
  tcase_add_test(tc, linear_kind_is_the_chord);
  tcase_add_test(tc, nodal_end_tangents_are_litewkas);
  tcase_add_test(tc, weighted_equals_nodal_on_uniform_spacing);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
