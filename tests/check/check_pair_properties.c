/* Physical properties of the contact element: objectivity and equilibrium,
 * continuity when the contact point slides across a node, ownership of
 * points on joints, pass-through with the sign-tracked gap, the parallel
 * threshold, closest points from any start, intersecting axes, and the C1
 * regularised law. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "pair_support.h"

static const double kPi = 3.14159265358979323846;

/* ------------------------------------------------------------ objectivity */

START_TEST(objectivity_and_equilibrium) {
  tst_rng rng;
  tst_rng_seed(&rng, 2001);
  b2b_params *p = tst_params(B2B_LAW_QUADRATIC, 1e3, 0.02);
  int checked = 0;
  for (int rep = 0; rep < 24; ++rep) {
    tst_pair_spec spec = {{TST_KIND_A(rep), TST_KIND_B(rep)}, {0, 0}, {0, 0}, {0.2, 0.15}};
    double X[24], Y[24], Q[9], t[3];
    tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 20, 90), tst_uniform(&rng, -0.6, 0.6),
                 tst_uniform(&rng, -0.6, 0.6), 0.32, X);
    /* a rotation about a random axis, and a translation */
    double axis[3] = {tst_uniform(&rng, -1, 1), tst_uniform(&rng, -1, 1), 0.5};
    const double an = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    for (int i = 0; i < 3; ++i) axis[i] /= an;
    const double th = tst_uniform(&rng, 0.1, 3.0), c = cos(th), s = sin(th);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const double K[9] = {0, axis[2], -axis[1], -axis[2], 0, axis[0], axis[1], -axis[0], 0};
        Q[i + 3 * j] = (i == j ? c : 0.0) + (1 - c) * axis[i] * axis[j] + s * K[i + 3 * j];
      }
    for (int i = 0; i < 3; ++i) t[i] = tst_uniform(&rng, -10, 10);
    for (int k = 0; k < 8; ++k) {
      tst_rotate(Q, X + 3 * k, Y + 3 * k);
      for (int i = 0; i < 3; ++i) Y[3 * k + i] += t[i];
    }
    static double K1[576], K2[576];
    double i1[32], i2[32], R1[24], R2[24];
    const int s1 = tst_pair(p, &spec, X, NULL, NULL, i1, R1, K1);
    const int s2 = tst_pair(p, &spec, Y, NULL, NULL, i2, R2, K2);
    ck_assert_int_eq(s1, s2);
    if (s1 != B2B_CONTACT_ACTIVE) continue;
    ++checked;
    const double f = i1[B2B_INFO_NORMAL_FORCE];
    ck_assert(fabs(i1[B2B_INFO_XI] - i2[B2B_INFO_XI]) <= 1e-11);
    ck_assert(fabs(i1[B2B_INFO_ETA] - i2[B2B_INFO_ETA]) <= 1e-11);
    ck_assert(fabs(i1[B2B_INFO_GAP] - i2[B2B_INFO_GAP]) <= 1e-12);
    ck_assert(fabs(f - i2[B2B_INFO_NORMAL_FORCE]) <= 1e-11 * f);
    /* residual: each node's force rotates; tangent: each 3x3 block Q B Q^T */
    for (int k = 0; k < 8; ++k) {
      double want[3];
      tst_rotate(Q, R1 + 3 * k, want);
      for (int i = 0; i < 3; ++i) ck_assert(fabs(R2[3 * k + i] - want[i]) <= 1e-10 * f);
    }
    const double Kmax = tst_max_abs(K1, 576), err = tst_tangent_rotation_error(Q, K1, K2);
    ck_assert_msg(err <= 1e-10 * Kmax, "tangent not objective: %g of %g", err, Kmax);
    /* equilibrium: the potential is invariant under rigid motion, so the
     * nodal forces sum to zero and have no net moment */
    double F[3] = {0, 0, 0}, M[3] = {0, 0, 0};
    for (int k = 0; k < 8; ++k) {
      if (isnan(X[3 * k])) continue;
      const double *x = X + 3 * k, *r = R1 + 3 * k;
      for (int i = 0; i < 3; ++i) F[i] += r[i];
      M[0] += x[1] * r[2] - x[2] * r[1];
      M[1] += x[2] * r[0] - x[0] * r[2];
      M[2] += x[0] * r[1] - x[1] * r[0];
    }
    for (int i = 0; i < 3; ++i) {
      ck_assert_msg(fabs(F[i]) <= 1e-11 * f, "net force %g", F[i]);
      ck_assert_msg(fabs(M[i]) <= 1e-10 * f * (1 + tst_max_abs(t, 3)), "net moment %g", M[i]);
    }
  }
  b2b_params_destroy(&p);
  ck_assert_int_ge(checked, 15);
}
END_TEST

/* ----------------------------------------- sliding across nodes: continuity */

#define ARC_NODES 7
#define ARC_R 4.0
#define ARC_STEP 0.25 /* radians between nodes */

/* A probe (a short straight linear segment along z) pressed onto an arc of
 * ARC_NODES nodes in the xy-plane at polar angle phi. Evaluates every segment
 * of the arc against it; returns how many pairs are active, and the active
 * one's normal, gap and the force on every arc node (3 x ARC_NODES). */
static int probe_arc(const b2b_params *p, int kind, double phi, double *n, double *gap,
                     double *force) {
  double coords[3 * ARC_NODES];
  for (int k = 0; k < ARC_NODES; ++k) {
    coords[3 * k] = ARC_R * cos(k * ARC_STEP);
    coords[3 * k + 1] = ARC_R * sin(k * ARC_STEP);
    coords[3 * k + 2] = 0.0;
  }
  /* radii 0.1, 0.1; a penetration of 0.05, more than the sagitta (0.031) by
   * which the polygon and the midpoint curve cut the arc's corners */
  const double rho = ARC_R + 0.1 + 0.1 - 0.05;
  int nseg, active = 0;
  ck_assert_int_eq(b2b_beam_segment_count(kind, ARC_NODES, 0, &nseg, NULL, 0), B2B_OK);
  memset(force, 0, 3 * ARC_NODES * sizeof(double));
  for (int s = 0; s < nseg; ++s) {
    tst_pair_spec spec = {{kind, B2B_CURVE_LINEAR}, {0, 0}, {0, 0}, {0.1, 0.1}};
    int nodes[4];
    double X[24];
    ck_assert_int_eq(b2b_beam_segment_patch(kind, ARC_NODES, 0, s, nodes, &spec.start_rule[0],
                                            &spec.end_rule[0], NULL, 0),
                     B2B_OK);
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) X[3 * k + i] = nodes[k] >= 0 ? coords[3 * nodes[k] + i] : NAN;
    for (int i = 0; i < 3; ++i) X[12 + i] = X[21 + i] = NAN;
    X[15] = X[18] = rho * cos(phi);
    X[16] = X[19] = rho * sin(phi);
    X[17] = -0.5;
    X[20] = 0.5;
    double info[32], R[24];
    if (tst_pair(p, &spec, X, NULL, NULL, info, R, NULL) != B2B_CONTACT_ACTIVE) continue;
    ++active;
    for (int i = 0; i < 3; ++i) n[i] = info[B2B_INFO_NORMAL + i];
    *gap = info[B2B_INFO_GAP];
    for (int k = 0; k < 4; ++k)
      if (nodes[k] >= 0)
        for (int i = 0; i < 3; ++i) force[3 * nodes[k] + i] += R[3 * k + i];
  }
  return active;
}

/* Largest change of normal, gap and nodal forces between active probe
 * positions dphi apart, over a sweep across the interior nodes; *lost counts
 * the positions where no pair held the contact. */
static void sweep(int kind, double dphi, double *jump_n, double *jump_g, double *jump_f,
                  int *lost) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  double n0[3], g0, f0[3 * ARC_NODES];
  *jump_n = *jump_g = *jump_f = 0.0;
  *lost = 0;
  int have_previous = 0;
  for (double phi = 1.5 * ARC_STEP; phi <= 4.5 * ARC_STEP; phi += dphi) {
    double n[3], g, f[3 * ARC_NODES];
    const int active = probe_arc(p, kind, phi, n, &g, f);
    ck_assert_msg(active <= 1, "%s: at phi %.6f %d pairs hold one contact", tst_kind_name(kind),
                  phi, active);
    if (active == 0) {
      ++*lost;
      continue;
    }
    if (have_previous) {
      double dn = 0, df = 0;
      for (int i = 0; i < 3; ++i) dn = fmax(dn, fabs(n[i] - n0[i]));
      for (int i = 0; i < 3 * ARC_NODES; ++i) df = fmax(df, fabs(f[i] - f0[i]));
      *jump_n = fmax(*jump_n, dn);
      *jump_g = fmax(*jump_g, fabs(g - g0));
      *jump_f = fmax(*jump_f, df / tst_max_abs(f, 3 * ARC_NODES));
    }
    have_previous = 1;
    memcpy(n0, n, sizeof n0);
    g0 = g;
    memcpy(f0, f, sizeof f0);
  }
  b2b_params_destroy(&p);
}

START_TEST(sliding_across_nodes) {
  const double dphi = 2e-3;
  for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k) {
    double jn, jg, jf, jn2, jg2, jf2;
    int lost, lost2;
    sweep(k, dphi, &jn, &jg, &jf, &lost);
    sweep(k, 0.5 * dphi, &jn2, &jg2, &jf2, &lost2);
    printf("%-24s sliding step %.0e rad: largest change of normal %.2e, gap %.2e, nodal "
           "forces %.2e (relative); contact lost at %d positions\n",
           tst_kind_name(k), dphi, jn, jg, jf, lost);
    if (tst_kind_family(k) == TST_CHORD) {
      /* The polygon's normal turns by the whole element angle at a node, and
       * outside a convex corner the closest point of each chord lies beyond
       * its segment: no pair holds the contact there. */
      ck_assert_msg(jn > 0.5 * ARC_STEP && lost > 0,
                    "linear kind: expected a jump of the normal and lost contacts, got %g, %d",
                    jn, lost);
      /* a jump: it does not shrink with the step */
      ck_assert_msg(jn2 > 0.9 * jn, "linear kind: normal change %g -> %g with half the step", jn,
                    jn2);
    } else {
      /* Smoothed: never lost, and everything moves in proportion to the
       * step (the normal turns with the probe, about dphi per step). */
      ck_assert_msg(lost == 0, "%s: contact lost at %d positions", tst_kind_name(k),
                    lost);
      ck_assert_msg(jn <= 3 * dphi, "%s: normal jumps by %g", tst_kind_name(k), jn);
      ck_assert_msg(jg <= 10 * dphi * 0.05, "%s: gap jumps by %g", tst_kind_name(k),
                    jg);
      ck_assert_msg(jf <= 0.1, "%s: nodal forces jump by %g", tst_kind_name(k), jf);
      /* continuous: the largest change halves with the step */
      ck_assert_msg(jn2 < 0.7 * jn && jg2 < 0.7 * jg && jf2 < 0.7 * jf,
                    "%s: changes do not shrink with the step (normal %g -> %g, gap %g -> %g, "
                    "forces %g -> %g)",
                    tst_kind_name(k), jn, jn2, jg, jg2, jf, jf2);
    }
  }
}
END_TEST

/* ---------------------------------------------------------------- ownership */

/* A probe exactly on a joint of the smoothed arc (a node; for the midpoint
 * kind also an element midpoint): one pair, not two and not none. (The
 * polygon loses such a contact, see sliding_across_nodes.) */
START_TEST(contact_on_a_joint_counted_once) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  for (int k = 0; k < B2B_CURVE_KIND_COUNT; ++k) {
    if (tst_kind_family(k) == TST_CHORD) continue; /* the polygon loses it */
    for (int joint = 2; joint < 2 * (ARC_NODES - 1) - 1; ++joint) {
      double n[3], g, f[3 * ARC_NODES];
      const int active = probe_arc(p, k, 0.5 * joint * ARC_STEP, n, &g, f);
      ck_assert_msg(active == 1, "%s: probe at phi = %g steps found by %d pairs",
                    tst_kind_name(k), 0.5 * joint, active);
    }
  }
  b2b_params_destroy(&p);
}
END_TEST

/* Two straight beams crossing at 90 degrees where a node of each coincides
 * (beamme-py PR 222): 16 segment pairs, one contact. */
START_TEST(crossing_at_coincident_nodes_counted_once) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  enum { n = 5 };
  for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
    for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
      double A[3 * n], B[3 * n];
      for (int k = 0; k < n; ++k) {
        A[3 * k] = k - 2.0, A[3 * k + 1] = 0.0, A[3 * k + 2] = 0.0;
        B[3 * k] = 0.0, B[3 * k + 1] = k - 2.0, B[3 * k + 2] = 0.3;
      }
      int na, nb, active = 0;
      double total = 0;
      b2b_beam_segment_count(ka, n, 0, &na, NULL, 0);
      b2b_beam_segment_count(kb, n, 0, &nb, NULL, 0);
      for (int sa = 0; sa < na; ++sa)
        for (int sb = 0; sb < nb; ++sb) {
          tst_pair_spec spec = {{ka, kb}, {0, 0}, {0, 0}, {0.2, 0.15}};
          double X[24];
          tst_gather_patch(ka, n, 0, sa, A, X, &spec.start_rule[0], &spec.end_rule[0]);
          tst_gather_patch(kb, n, 0, sb, B, X + 12, &spec.start_rule[1],
                           &spec.end_rule[1]);
          double info[32], R[24];
          if (tst_pair(p, &spec, X, NULL, NULL, info, R, NULL) == B2B_CONTACT_ACTIVE) {
            ++active;
            total += info[B2B_INFO_NORMAL_FORCE];
          }
        }
      ck_assert_msg(active == 1, "%s x %s: %d active pairs at coincident nodes",
                    tst_kind_name(ka), tst_kind_name(kb), active);
      ck_assert(fabs(total - 1e3 * 0.05) <= 1e-9);
    }
  b2b_params_destroy(&p);
}
END_TEST

/* ------------------------------------------------------------- pass-through */

START_TEST(pass_through_keeps_a_negative_gap) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  tst_pair_spec spec = {{B2B_CURVE_HERMITE_NODAL, B2B_CURVE_HERMITE_NODAL}, {0, 0}, {0, 0},
                        {0.2, 0.15}};
  double X[24];
  for (int k = 0; k < 4; ++k) {
    X[3 * k] = k - 1.5, X[3 * k + 1] = 0.0, X[3 * k + 2] = 0.0;            /* A along x */
    X[12 + 3 * k] = 0.0, X[12 + 3 * k + 1] = k - 1.5, X[12 + 3 * k + 2] = 0.3; /* B above */
  }
  double h0[8] = {0}, h1[8], info[32], R[24];
  ck_assert_int_eq(tst_pair(p, &spec, X, h0, h1, info, R, NULL), B2B_CONTACT_ACTIVE);
  ck_assert(fabs(info[B2B_INFO_GAP] + 0.05) <= 1e-12);
  ck_assert(info[B2B_INFO_NORMAL + 2] < -0.999); /* from B (above) to A */
  /* One step moves B's axis through A's, to 0.3 below it. */
  for (int k = 0; k < 4; ++k) X[12 + 3 * k + 2] = -0.3;
  double h2[8];
  ck_assert_int_eq(tst_pair(p, &spec, X, h1, h2, info, R, NULL), B2B_CONTACT_ACTIVE);
  ck_assert_msg(fabs(info[B2B_INFO_GAP] + 0.65) <= 1e-12, "sign-tracked gap %g, expected -0.65",
                info[B2B_INFO_GAP]);
  ck_assert(info[B2B_INFO_NORMAL + 2] < -0.999); /* still the old side */
  /* The contact force on B (minus its residual) pushes it back up. */
  double fz = 0;
  for (int k = 0; k < 4; ++k) fz -= R[12 + 3 * k + 2];
  ck_assert_msg(fz > 600.0, "force on B %g, expected +650", fz);
  /* Without the history the same configuration reads as a shallow contact
   * from the other side: the axes would be pulled through. */
  ck_assert_int_eq(tst_pair(p, &spec, X, h0, h2, info, R, NULL), B2B_CONTACT_ACTIVE);
  ck_assert(fabs(info[B2B_INFO_GAP] + 0.05) <= 1e-12);
  ck_assert(info[B2B_INFO_NORMAL + 2] > 0.999);
  b2b_params_destroy(&p);
}
END_TEST

/* Axes that intersect exactly: the previous normal, or NO_NORMAL. */
START_TEST(intersecting_axes) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  tst_pair_spec spec = {{B2B_CURVE_HERMITE_NODAL, B2B_CURVE_LINEAR}, {0, 0}, {0, 0}, {0.2, 0.15}};
  double X[24];
  for (int k = 0; k < 4; ++k) {
    X[3 * k] = k - 1.5, X[3 * k + 1] = 0.0, X[3 * k + 2] = 0.0;
    X[12 + 3 * k] = 0.0, X[12 + 3 * k + 1] = k - 1.5, X[12 + 3 * k + 2] = 0.0;
  }
  double fresh[8] = {0}, h[8], info[32], R[24];
  ck_assert_int_eq(tst_pair(p, &spec, X, fresh, h, info, R, NULL), B2B_CONTACT_NO_NORMAL);
  ck_assert(tst_max_abs(R, 24) == 0.0);
  const double with_normal[8] = {1, 1, 0, 0, 1, 0, 0, 0};
  static double K[576];
  ck_assert_int_eq(tst_pair(p, &spec, X, with_normal, h, info, R, K), B2B_CONTACT_ACTIVE);
  ck_assert(fabs(info[B2B_INFO_GAP] + 0.35) <= 1e-12);
  ck_assert(info[B2B_INFO_NORMAL + 2] == 1.0);
  for (int i = 0; i < 24; ++i) ck_assert(isfinite(R[i]));
  for (int i = 0; i < 576; ++i) ck_assert(isfinite(K[i]));
  b2b_params_destroy(&p);
}
END_TEST

/* ------------------------------------------------------ parallel threshold */

static int at_angle(const b2b_params *p, double angle_deg) {
  tst_pair_spec spec = {{B2B_CURVE_LINEAR, B2B_CURVE_LINEAR}, {0, 0}, {0, 0}, {0.02, 0.015}};
  double X[24];
  const double a = angle_deg * kPi / 180.0;
  for (int k = 0; k < 4; ++k) {
    const double s = k - 1.5;
    X[3 * k] = s, X[3 * k + 1] = 0.0, X[3 * k + 2] = 0.0;
    X[12 + 3 * k] = s * cos(a), X[12 + 3 * k + 1] = s * sin(a), X[12 + 3 * k + 2] = 0.03;
  }
  double info[32], R[24];
  const int st = tst_pair(p, &spec, X, NULL, NULL, info, R, NULL);
  if (st == B2B_CONTACT_PARALLEL) ck_assert(tst_max_abs(R, 24) == 0.0);
  return st;
}

START_TEST(parallel_threshold_is_an_option) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  ck_assert_int_eq(at_angle(p, 1.0), B2B_CONTACT_ACTIVE);
  ck_assert_int_eq(at_angle(p, 0.6), B2B_CONTACT_ACTIVE);
  ck_assert_int_eq(at_angle(p, 0.4), B2B_CONTACT_PARALLEL); /* default threshold 0.5 degree */
  ck_assert_int_eq(at_angle(p, 0.0), B2B_CONTACT_PARALLEL);
  b2b_params_destroy(&p);
  b2b_params *q = NULL;
  ck_assert_int_eq(b2b_params_create(&q, NULL, 0), B2B_OK);
  b2b_params_set_real(q, "penalty", 1e3, NULL, 0);
  ck_assert_int_eq(b2b_params_set_real(q, "parallel_angle", 5.0, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_finalize(q, NULL, 0), B2B_OK);
  ck_assert_int_eq(at_angle(q, 4.0), B2B_CONTACT_PARALLEL);
  ck_assert_int_eq(at_angle(q, 6.0), B2B_CONTACT_ACTIVE);
  b2b_params_destroy(&q);
}
END_TEST

/* ------------------------------------------------- closest points, any start */

START_TEST(closest_points_from_any_start) {
  tst_rng rng;
  tst_rng_seed(&rng, 2002);
  b2b_params *cold = tst_params(B2B_LAW_LINEAR, 1e3, 0.0), *warm = NULL;
  ck_assert_int_eq(b2b_params_create(&warm, NULL, 0), B2B_OK);
  b2b_params_set_real(warm, "penalty", 1e3, NULL, 0);
  ck_assert_int_eq(b2b_params_set_int(warm, "warm_start", 1, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_finalize(warm, NULL, 0), B2B_OK);
  int max_iter = 0;
  for (int rep = 0; rep < 16; ++rep) {
    tst_pair_spec spec = {{rep % B2B_CURVE_KIND_COUNT, (rep + 1) % B2B_CURVE_KIND_COUNT},
                          {0, 0}, {0, 0}, {0.2, 0.15}};
    double X[24], ref[32], R[24];
    tst_crossing(&rng, &spec, 0.5, tst_uniform(&rng, 30, 90), tst_uniform(&rng, -0.5, 0.5),
                 tst_uniform(&rng, -0.5, 0.5), 0.3, X);
    const int st = tst_pair(cold, &spec, X, NULL, NULL, ref, R, NULL);
    if (st != B2B_CONTACT_ACTIVE) continue;
    for (int s = 0; s < 10; ++s) {
      double h[8] = {1, 0, 0, 0, 0, tst_uniform(&rng, -1, 1), tst_uniform(&rng, -1, 1), 0};
      double info[32];
      ck_assert_int_eq(tst_pair(warm, &spec, X, h, NULL, info, R, NULL), st);
      ck_assert_msg(fabs(info[B2B_INFO_XI] - ref[B2B_INFO_XI]) <= 1e-10 &&
                        fabs(info[B2B_INFO_ETA] - ref[B2B_INFO_ETA]) <= 1e-10,
                    "from (%g, %g): (%g, %g) instead of (%g, %g)", h[5], h[6], info[B2B_INFO_XI],
                    info[B2B_INFO_ETA], ref[B2B_INFO_XI], ref[B2B_INFO_ETA]);
      max_iter = (int)fmax(max_iter, info[B2B_INFO_ITERATIONS]);
    }
  }
  printf("closest points from random starts in the patch: at most %d iterations\n", max_iter);
  ck_assert_int_le(max_iter, 20);
  b2b_params_destroy(&cold);
  b2b_params_destroy(&warm);
}
END_TEST

/* ------------------------------------------------------- the C1 normal law */

/* Two straight segments whose axes cross far beyond both (xi about 4.5):
 * the search is held at the edge of its box by steps that point out of it,
 * and must give up there (OUTSIDE) within a few iterations, not spend all of
 * them; most candidate pairs of a contact model are of this kind. */
START_TEST(pinned_search_returns_outside_early) {
  b2b_params *p = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  char msg[B2B_ERRMSG_LEN];
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", 1e3, msg, sizeof msg), B2B_ERR_STATE);
  const int segs[6] = {B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                       B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
  /* A along x from 0 to 1, B along y through x = 2.75 (xi = 4.5), 0.1 above */
  const double X[24] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0,
                        0, 0, 0, 2.75, -0.5, 0.1, 2.75, 0.5, 0.1, 0, 0, 0};
  const double radii[2] = {0.1, 0.1};
  double h0[8] = {0}, h1[8], info[32], r[24];
  int st;
  ck_assert_int_eq(b2b_pair_eval(p, segs, X, NULL, radii, h0, h1, 8, &st, info, r, NULL, 24, msg,
                                 sizeof msg), B2B_OK);
  ck_assert_int_eq(st, B2B_CONTACT_OUTSIDE);
  ck_assert_msg(info[B2B_INFO_ITERATIONS] <= 6, "%g iterations", info[B2B_INFO_ITERATIONS]);
  ck_assert(info[B2B_INFO_XI] > 1.0);
  printf("pinned search: OUTSIDE after %g iterations at xi = %g\n", info[B2B_INFO_ITERATIONS],
         info[B2B_INFO_XI]);
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(quadratic_law_is_c1) {
  const double eps = 1e3, g0 = 0.02;
  b2b_params *p = tst_params(B2B_LAW_QUADRATIC, eps, g0);
  tst_pair_spec spec = {{B2B_CURVE_LINEAR, B2B_CURVE_LINEAR}, {0, 0}, {0, 0}, {0.2, 0.15}};
  double f[3], e[3];
  const double gaps[] = {0.0, g0, 0.5 * g0, -0.01};
  for (size_t q = 0; q < sizeof gaps / sizeof gaps[0]; ++q) {
    for (int side = -1; side <= 1; ++side) {
      const double g = gaps[q] + side * 1e-9;
      double X[24], info[32], R[24];
      for (int k = 0; k < 4; ++k) {
        X[3 * k] = k - 1.5, X[3 * k + 1] = 0.0, X[3 * k + 2] = 0.0;
        X[12 + 3 * k] = 0.0, X[12 + 3 * k + 1] = k - 1.5, X[12 + 3 * k + 2] = 0.35 + g;
      }
      tst_pair(p, &spec, X, NULL, NULL, info, R, NULL);
      f[side + 1] = info[B2B_INFO_NORMAL_FORCE];
      e[side + 1] = info[B2B_INFO_ENERGY];
    }
    /* closed forms */
    const double g = gaps[q];
    const double want = g <= 0 ? eps * (0.5 * g0 - g) : g < g0 ? eps * (g0 - g) * (g0 - g) / (2 * g0) : 0;
    ck_assert_msg(fabs(f[1] - want) <= 1e-6 * eps * g0, "f(%g) = %g, expected %g", g, f[1], want);
    /* continuous force and slope: the one-sided differences agree */
    const double left = (f[1] - f[0]) / 1e-9, right = (f[2] - f[1]) / 1e-9;
    ck_assert_msg(fabs(left - right) <= 1e-3 * eps, "slope jumps at g = %g: %g vs %g", g, left,
                  right);
    /* and dPi/dg = -f */
    ck_assert(fabs(-(e[2] - e[0]) / 2e-9 - f[1]) <= 1e-4 * eps * g0);
  }
  b2b_params_destroy(&p);
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("pair_properties");
  TCase *tc = tcase_create("properties");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, objectivity_and_equilibrium);
  tcase_add_test(tc, sliding_across_nodes);
  tcase_add_test(tc, contact_on_a_joint_counted_once);
  tcase_add_test(tc, crossing_at_coincident_nodes_counted_once);
  tcase_add_test(tc, pass_through_keeps_a_negative_gap);
  tcase_add_test(tc, intersecting_axes);
  tcase_add_test(tc, parallel_threshold_is_an_option);
  tcase_add_test(tc, closest_points_from_any_start);
  tcase_add_test(tc, quadratic_law_is_c1);
  tcase_add_test(tc, pinned_search_returns_outside_early);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
