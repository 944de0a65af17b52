/* Continuity across segment joints, on open beams and rings (including the
 * seam of a ring): position for every kind; unit tangent for the smooth
 * kinds (the linear kind kinks, by design, and the test says by how much);
 * and the nodal force distribution dx/dX, mapped to beam nodes. */
#include <math.h>
#include <string.h>

#include "test_support.h"

#define N_NODES 8

static void random_chain(tst_rng *rng, int n, double *coords) {
  double dir[3] = {1, 0, 0}, pos[3] = {0, 0, 0};
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) coords[3 * k + i] = pos[i];
    /* turn by up to ~0.6 rad about a random axis, step 0.6 .. 1.4 */
    for (int i = 0; i < 3; ++i) dir[i] += tst_uniform(rng, -0.35, 0.35);
    const double nd = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    const double len = tst_uniform(rng, 0.6, 1.4);
    for (int i = 0; i < 3; ++i) {
      dir[i] /= nd;
      pos[i] += len * dir[i];
    }
  }
}

static void unit(const double *v, double *u) {
  const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int i = 0; i < 3; ++i) u[i] = v[i] / n;
}

/* Value and beam-node Jacobian (3 x 3n) of one segment end. */
static void end_state(int kind, int n, int closed, int s, const double *coords, double xi,
                      double *x, double *J) {
  double patch[12], dx[72];
  int nodes[4], sr, er;
  ck_assert_int_eq(b2b_beam_segment_patch(kind, n, closed, s, nodes, &sr, &er, NULL, 0), B2B_OK);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) patch[3 * k + i] = nodes[k] >= 0 ? coords[3 * nodes[k] + i] : NAN;
  tst_eval(kind, sr, er, patch, NULL, xi, x, dx, NULL);
  memset(J, 0, 9 * n * sizeof(double));
  for (int k = 0; k < 4; ++k) {
    if (nodes[k] < 0) continue;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) J[i + 3 * (3 * nodes[k] + j)] += dx[i + 3 * (3 * k + j)];
  }
}

static void check_joints(int kind, int closed, uint64_t seed) {
  tst_rng rng;
  tst_rng_seed(&rng, seed);
  double coords[3 * N_NODES];
  if (closed)
    tst_ring_nodes(N_NODES, 1.5, 1, coords);
  else
    random_chain(&rng, N_NODES, coords);
  int nseg;
  ck_assert_int_eq(b2b_beam_segment_count(kind, N_NODES, closed, &nseg, NULL, 0), B2B_OK);
  const int joints = closed ? nseg : nseg - 1;
  double worst_kink = 0.0;
  for (int s = 0; s < joints; ++s) {
    const int t = (s + 1) % nseg;
    double xa[9], xb[9], Ja[9 * N_NODES], Jb[9 * N_NODES], ua[3], ub[3];
    end_state(kind, N_NODES, closed, s, coords, 1.0, xa, Ja);
    end_state(kind, N_NODES, closed, t, coords, -1.0, xb, Jb);
    const double pos = tst_rel_diff(xa, xb, 3, 1.0);
    ck_assert_msg(pos <= 1e-15, "%s %s joint %d: position jumps by %g", tst_kind_name(kind),
                  closed ? "ring" : "open", s, pos);
    unit(xa + 3, ua);
    unit(xb + 3, ub);
    const double kink = tst_rel_diff(ua, ub, 3, 1.0);
    worst_kink = fmax(worst_kink, kink);
    if (tst_kind_family(kind) != TST_CHORD) /* C1 */
      ck_assert_msg(kink <= 1e-14, "%s %s joint %d: unit tangent jumps by %g",
                    tst_kind_name(kind), closed ? "ring" : "open", s, kink);
    /* How the point moves with the nodes is continuous too: the nodal forces
     * of a contact at the joint do not depend on which segment holds it. */
    const double jac = tst_rel_diff(Ja, Jb, 9 * N_NODES, 1.0);
    ck_assert_msg(jac <= 1e-15, "%s %s joint %d: dx/dX jumps by %g", tst_kind_name(kind),
                  closed ? "ring" : "open", s, jac);
  }
  /* The chord polygon kinks at every joint of a curved beam (C0 only). */
  if (tst_kind_family(kind) == TST_CHORD)
    ck_assert_msg(worst_kink > 0.05, "linear kind: expected kinks, largest %g", worst_kink);
}

START_TEST(joints_open_beams) {
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
    check_joints(kind, 0, 21 + (uint64_t)kind);
}
END_TEST

START_TEST(joints_rings_and_seam) {
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
    check_joints(kind, 1, 31 + (uint64_t)kind);
}
END_TEST

/* Within a segment the curve is smooth: sampled tangents change little
 * between close parameters (no hidden kink inside a segment). */
START_TEST(smooth_inside_segments) {
  double coords[3 * N_NODES];
  tst_ring_nodes(N_NODES, 1.0, 1, coords);
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind) {
    double patch[12];
    int sr, er;
    tst_gather_patch(kind, N_NODES, 1, 2, coords, patch, &sr, &er);
    double prev[9];
    tst_eval(kind, sr, er, patch, NULL, -1.0, prev, NULL, NULL);
    for (int q = 1; q <= 200; ++q) {
      double x[9], ua[3], ub[3];
      tst_eval(kind, sr, er, patch, NULL, -1.0 + q * 0.01, x, NULL, NULL);
      unit(prev + 3, ua);
      unit(x + 3, ub);
      ck_assert(tst_rel_diff(ua, ub, 3, 1.0) < 0.02);
      memcpy(prev, x, sizeof prev);
    }
  }
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("curve_continuity");
  TCase *tc = tcase_create("continuity");
  tcase_add_test(tc, joints_open_beams);
  tcase_add_test(tc, joints_rings_and_seam);
  tcase_add_test(tc, smooth_inside_segments);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
