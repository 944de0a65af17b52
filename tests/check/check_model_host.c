/* The host-integration entry points of b2b_model.h (issue 19), on a fibre
 * network with friction whose second step makes the contact tangent
 * non-symmetric:
 *   update_xu          = update(x + u) bit for bit (u with 6 rows whose
 *                        rows 4..6 hold NaN: never read); a NaN u, a sum
 *                        beyond B2B_COORD_MAX, bad sizes: their codes, the
 *                        model's results unchanged
 *   *_scaled           scale 1 = unscaled and scale -1 = -(unscaled), bit
 *                        for bit; a NaN scale: B2B_ERR_NONFINITE, nothing added
 *   tangent_profile    heights, kl, ku = what the dense tangent's nonzeros
 *                        (and the COO pattern) imply
 *   add_tangent_profile ad, au, al = the dense tangent entry by entry in
 *                        FEAP's layout (C and Fortran numbering, a profile
 *                        with room to spare); one height too small, a bad jp:
 *                        B2B_ERR_RANGE with nothing added
 *   add_constrained_product = K_all(free, constrained) du_c from the dense
 *                        tangent of the same model with every dof free; NaN
 *                        in du's free entries is not read; a NaN constrained
 *                        entry: B2B_ERR_NONFINITE, f untouched */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_support.h"

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

/* The scene: a network with friction, updated, committed, moved a little
 * and updated again (sticking contacts: a non-symmetric tangent). */
typedef struct {
  tst_scene sc;
  b2b_params *p;
  b2b_model *m;
} host_scene;

static void scene_open(host_scene *h) {
  char msg[B2B_ERRMSG_LEN] = "";
  tst_rng rng;
  tst_rng_seed(&rng, 4242);
  tst_network(&rng, 16, 7, 0.5, 1.6, 0.1, 0.3, 5, 0, &h->sc);
  h->p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.2, 1e3);
  h->m = tst_model(&h->sc, h->p, 1);
  tst_update(h->m, &h->sc, 1);
  ok(b2b_model_commit(h->m, msg, sizeof msg), msg);
  double *v = malloc(sizeof(double) * 3 * h->sc.n_nodes);
  for (int k = 0; k < 3 * h->sc.n_nodes; ++k) v[k] = sin(0.7 * k);
  tst_scene_move(&h->sc, v, 2e-3);
  free(v);
  tst_update(h->m, &h->sc, 1);
}

static void scene_close(host_scene *h) {
  b2b_model_destroy(&h->m);
  b2b_params_destroy(&h->p);
  tst_scene_free(&h->sc);
}

/* eq(ld, n_nodes) of a 6-dof host, numbered from base; every
 * constrained_every-th translational dof constrained (0: none). */
static int *numbering(int n_nodes, int ld, int base, int constrained_every, int *n_eq) {
  int *eq = malloc(sizeof(int) * ld * n_nodes);
  *n_eq = 0;
  for (int k = 0; k < n_nodes; ++k)
    for (int i = 0; i < ld; ++i)
      eq[ld * k + i] = (i < 3 && constrained_every && (3 * k + i) % constrained_every == 3)
                           ? base - 1
                           : base + (*n_eq)++;
  return eq;
}

static double *dense(const b2b_model *m, const int *eq, int ld, int base, int n_eq) {
  char msg[B2B_ERRMSG_LEN] = "";
  double *K = calloc((size_t)n_eq * n_eq, sizeof(double));
  ok(b2b_model_add_tangent_dense(m, eq, ld, base, n_eq, K, n_eq, msg, sizeof msg), msg);
  return K;
}

START_TEST(update_xu) {
  char msg[B2B_ERRMSG_LEN] = "";
  host_scene h;
  scene_open(&h);
  const int n = h.sc.n_nodes, ldu = 6;
  /* reference x_ref = x - d, u = d with FEAP's u(6, numnp) (rotations NaN) */
  double *xr = malloc(sizeof(double) * 3 * n), *u = malloc(sizeof(double) * ldu * n),
         *xc = malloc(sizeof(double) * 3 * n);
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < ldu; ++i) {
      if (i >= 3) {
        u[ldu * k + i] = NAN;
        continue;
      }
      const double d = 0.37 * cos(1.3 * k + i);
      xr[3 * k + i] = h.sc.x[3 * k + i] - d;
      u[ldu * k + i] = d;
      xc[3 * k + i] = xr[3 * k + i] + u[ldu * k + i];
    }
  b2b_model *a = tst_model(&h.sc, h.p, 1), *b = tst_model(&h.sc, h.p, 1);
  ok(b2b_model_update(a, xc, 3, n, 1, msg, sizeof msg), msg);
  ok(b2b_model_update_xu(b, xr, 3, u, ldu, n, 1, msg, sizeof msg), msg);
  const size_t cap = 1 << 22;
  unsigned char *ra = malloc(cap), *rb = malloc(cap);
  const size_t na = tst_model_record(a, 1, ra, cap), nb = tst_model_record(b, 1, rb, cap);
  int count = 0;
  ok(b2b_model_contact_count(b, &count, msg, sizeof msg), msg);
  ck_assert_int_ge(count, 5);
  ck_assert_msg(na == nb && memcmp(ra, rb, na) == 0, "update_xu differs from update(x + u)");
  /* bad inputs: each its code and message, the results of b unchanged */
  int node = -1;
  int first_nodes[8];
  ok(b2b_model_get_contact(b, 0, first_nodes, NULL, NULL, NULL, NULL, 24, msg, sizeof msg), msg);
  node = first_nodes[1];
  const double keep = u[ldu * node + 1];
  u[ldu * node + 1] = NAN;
  ck_assert_int_eq(b2b_model_update_xu(b, xr, 3, u, ldu, n, 1, msg, sizeof msg),
                   B2B_ERR_NONFINITE);
  char want[64];
  snprintf(want, sizeof want, "node %d has a non-finite y displacement", node);
  ck_assert_msg(strstr(msg, want) != NULL, "%s", msg);
  u[ldu * node + 1] = 2 * B2B_COORD_MAX;
  ck_assert_int_eq(b2b_model_update_xu(b, xr, 3, u, ldu, n, 1, msg, sizeof msg), B2B_ERR_RANGE);
  ck_assert_msg(strstr(msg, "x + u") != NULL, "%s", msg);
  u[ldu * node + 1] = keep;
  ck_assert_int_eq(b2b_model_update_xu(b, xr, 3, u, 2, n, 1, msg, sizeof msg), B2B_ERR_SIZE);
  ck_assert_msg(strstr(msg, "ldu") != NULL, "%s", msg);
  ck_assert_int_eq(b2b_model_update_xu(b, xr, 3, u, ldu, n - 1, 1, msg, sizeof msg),
                   B2B_ERR_SIZE);
  ck_assert_int_eq(b2b_model_update_xu(b, xr, 3, NULL, ldu, n, 1, msg, sizeof msg), B2B_ERR_NULL);
  const size_t nb2 = tst_model_record(b, 1, rb, cap);
  ck_assert_msg(nb2 == na && memcmp(ra, rb, na) == 0, "a failed update_xu changed the model");
  printf("update_xu: %d contacts, results equal to update(x + u) bit for bit (%zu bytes); NaN "
         "u at node %d, x + u beyond B2B_COORD_MAX, ldu 2, n_cols short, u NULL refused, "
         "model unchanged\n", count, na, node);
  free(ra);
  free(rb);
  b2b_model_destroy(&a);
  b2b_model_destroy(&b);
  free(xr);
  free(u);
  free(xc);
  scene_close(&h);
}
END_TEST

static void check_scaled(int base) {
  char msg[B2B_ERRMSG_LEN] = "";
  host_scene h;
  scene_open(&h);
  int n_eq;
  const int ld = 6;
  int *eq = numbering(h.sc.n_nodes, ld, base, 7, &n_eq);
  double *f = calloc(n_eq, sizeof(double)), *f1 = calloc(n_eq, sizeof(double)),
         *fm = calloc(n_eq, sizeof(double));
  ok(b2b_model_add_residual(h.m, eq, ld, base, n_eq, f, msg, sizeof msg), msg);
  ok(b2b_model_add_residual_scaled(h.m, eq, ld, base, n_eq, 1.0, f1, msg, sizeof msg), msg);
  ok(b2b_model_add_residual_scaled(h.m, eq, ld, base, n_eq, -1.0, fm, msg, sizeof msg), msg);
  int nonzero = 0;
  TST_ASSERT_ALL(int, k, 0, n_eq,
                 f1[k] == f[k] && fm[k] == -f[k] && memcmp(&f1[k], &f[k], sizeof(double)) == 0,
                 "residual entry %d", k);
  for (int k = 0; k < n_eq; ++k) nonzero += f[k] != 0.0;
  ck_assert_int_gt(nonzero, 0);
  /* a NaN scale: refused, f untouched */
  memcpy(fm, f, sizeof(double) * n_eq);
  ck_assert_int_eq(b2b_model_add_residual_scaled(h.m, eq, ld, base, n_eq, NAN, fm, msg,
                                                 sizeof msg), B2B_ERR_NONFINITE);
  ck_assert_msg(strstr(msg, "scale") != NULL, "%s", msg);
  ck_assert(memcmp(fm, f, sizeof(double) * n_eq) == 0);
  /* dense */
  const size_t nn = (size_t)n_eq * n_eq;
  double *K = dense(h.m, eq, ld, base, n_eq), *Km = calloc(nn, sizeof(double));
  ok(b2b_model_add_tangent_dense_scaled(h.m, eq, ld, base, n_eq, -1.0, Km, n_eq, msg,
                                        sizeof msg), msg);
  TST_ASSERT_ALL(size_t, k, 0, nn, Km[k] == -K[k], "entry %d", (int)k);
  memset(Km, 0, sizeof(double) * nn);
  ok(b2b_model_add_tangent_dense_scaled(h.m, eq, ld, base, n_eq, 1.0, Km, n_eq, msg,
                                        sizeof msg), msg);
  ck_assert(memcmp(Km, K, sizeof(double) * nn) == 0);
  memset(Km, 0, sizeof(double) * nn);
  ck_assert_int_eq(b2b_model_add_tangent_dense_scaled(h.m, eq, ld, base, n_eq, INFINITY, Km,
                                                      n_eq, msg, sizeof msg), B2B_ERR_NONFINITE);
  TST_ASSERT_ALL(size_t, k, 0, nn, Km[k] == 0.0, "entry %d", (int)k);
  /* banded */
  int kl, ku;
  ok(b2b_model_tangent_profile(h.m, eq, ld, base, n_eq, NULL, &kl, &ku, msg, sizeof msg), msg);
  const int ldab = 2 * kl + ku + 1;
  double *AB = calloc((size_t)ldab * n_eq, sizeof(double)),
         *ABm = calloc((size_t)ldab * n_eq, sizeof(double));
  ok(b2b_model_add_tangent_banded(h.m, eq, ld, base, n_eq, kl, ku, AB, ldab, msg, sizeof msg),
     msg);
  ok(b2b_model_add_tangent_banded_scaled(h.m, eq, ld, base, n_eq, kl, ku, -1.0, ABm, ldab, msg,
                                         sizeof msg), msg);
  TST_ASSERT_ALL(size_t, k, 0, (size_t)ldab * n_eq, ABm[k] == -AB[k], "entry %d", (int)k);
  ck_assert_int_eq(b2b_model_add_tangent_banded_scaled(h.m, eq, ld, base, n_eq, kl, ku, NAN,
                                                       ABm, ldab, msg, sizeof msg),
                   B2B_ERR_NONFINITE);
  TST_ASSERT_ALL(size_t, k, 0, (size_t)ldab * n_eq, ABm[k] == -AB[k], "entry %d", (int)k);
  printf("scaled assembly (eq_base %d): %d equations, %d nonzero residual entries; residual, "
         "dense and band (kl %d, ku %d) with scale 1 = unscaled, scale -1 = -unscaled, bit "
         "for bit; NaN/inf scale refused, nothing added\n", base, n_eq, nonzero, kl, ku);
  free(AB);
  free(ABm);
  free(K);
  free(Km);
  free(f);
  free(f1);
  free(fm);
  free(eq);
  scene_close(&h);
}

START_TEST(scaled_c) { check_scaled(0); }
END_TEST
START_TEST(scaled_fortran) { check_scaled(1); }
END_TEST

static void check_profile(int base) {
  char msg[B2B_ERRMSG_LEN] = "";
  host_scene h;
  scene_open(&h);
  int n_eq;
  const int ld = 6;
  int *eq = numbering(h.sc.n_nodes, ld, base, 7, &n_eq);
  double *K = dense(h.m, eq, ld, base, n_eq);
  /* the tangent is not symmetric (friction): al matters */
  double asym = 0.0;
  for (int j = 0; j < n_eq; ++j)
    for (int i = 0; i < j; ++i)
      asym = fmax(asym, fabs(K[i + (size_t)n_eq * j] - K[j + (size_t)n_eq * i]));
  ck_assert_msg(asym > 0.0, "the scene's tangent is symmetric: the test needs friction");
  /* the pattern the dense tangent's nonzeros imply */
  int *hd = calloc(n_eq, sizeof(int)), kld = 0, kud = 0;
  for (int j = 0; j < n_eq; ++j)
    for (int i = 0; i < n_eq; ++i)
      if (K[i + (size_t)n_eq * j] != 0.0) {
        if (i - j > kld) kld = i - j;
        if (j - i > kud) kud = j - i;
        const int c = i > j ? i : j, r = i > j ? j : i;
        if (c - r > hd[c]) hd[c] = c - r;
      }
  int *hq = malloc(sizeof(int) * n_eq), kl = -1, ku = -1;
  for (int j = 0; j < n_eq; ++j) hq[j] = -7;
  ok(b2b_model_tangent_profile(h.m, eq, ld, base, n_eq, hq, &kl, &ku, msg, sizeof msg), msg);
  ck_assert_int_eq(kl, kld);
  ck_assert_int_eq(ku, kud);
  long stored = 0;
  TST_ASSERT_ALL(int, j, 0, n_eq, hq[j] == hd[j], "height of column %d: %d, the dense tangent "
                 "says %d", j, hq[j], hd[j]);
  for (int j = 0; j < n_eq; ++j) stored += hq[j];
  /* FEAP's pointers from the heights, with 2 rows to spare in every 5th column */
  int *jp = malloc(sizeof(int) * n_eq);
  for (int j = 0; j < n_eq; ++j) {
    int hj = hq[j] + (j % 5 == 2 ? 2 : 0);
    if (hj > j) hj = j;
    jp[j] = (j ? jp[j - 1] : 0) + hj;
  }
  const int nau = jp[n_eq - 1];
  double *ad = calloc(n_eq, sizeof(double)), *au = calloc(nau + 1, sizeof(double)),
         *al = calloc(nau + 1, sizeof(double));
  ok(b2b_model_add_tangent_profile(h.m, eq, ld, base, n_eq, 1.0, jp, ad, au, al, msg,
                                   sizeof msg), msg);
  int bad_i = -1, bad_j = -1; /* the first entry that differs, in plain C */
  for (int j = 0; j < n_eq && bad_j < 0; ++j) {
    const int hj = jp[j] - (j ? jp[j - 1] : 0);
    if (ad[j] != K[j + (size_t)n_eq * j]) bad_i = bad_j = j;
    for (int i = 0; i < j && bad_j < 0; ++i) {
      const double up = K[i + (size_t)n_eq * j], low = K[j + (size_t)n_eq * i];
      const int in = j - i <= hj;
      if (in ? (au[jp[j] - j + i] != up || al[jp[j] - j + i] != low) : (up != 0.0 || low != 0.0)) {
        bad_i = i;
        bad_j = j;
      }
    }
  }
  ck_assert_msg(bad_j < 0, "profile entry (%d, %d) differs from the dense tangent", bad_i, bad_j);
  /* scale -1, al NULL: the upper triangle only, negated */
  double *ad2 = calloc(n_eq, sizeof(double)), *au2 = calloc(nau + 1, sizeof(double));
  ok(b2b_model_add_tangent_profile(h.m, eq, ld, base, n_eq, -1.0, jp, ad2, au2, NULL, msg,
                                   sizeof msg), msg);
  TST_ASSERT_ALL(int, j, 0, n_eq, ad2[j] == -ad[j], "entry %d", (int)j);
  TST_ASSERT_ALL(int, k, 0, nau, au2[k] == -au[k], "entry %d", (int)k);
  /* one height too small: refused, nothing added */
  int jn = -1;
  for (int j = 0; j < n_eq && jn < 0; ++j)
    if (hq[j] > 0 && j % 5 != 2) jn = j;
  ck_assert_int_ge(jn, 0);
  for (int j = jn; j < n_eq; ++j) jp[j] -= 1;
  memset(ad2, 0, sizeof(double) * n_eq);
  memset(au2, 0, sizeof(double) * (nau + 1));
  double *al2 = calloc(nau + 1, sizeof(double));
  ck_assert_int_eq(b2b_model_add_tangent_profile(h.m, eq, ld, base, n_eq, 1.0, jp, ad2, au2, al2,
                                                 msg, sizeof msg), B2B_ERR_RANGE);
  ck_assert_msg(strstr(msg, "outside the profile") != NULL, "%s", msg);
  char want[48];
  snprintf(want, sizeof want, "column %d's height", jn + base);
  ck_assert_msg(strstr(msg, want) != NULL, "%s (want %s)", msg, want);
  /* a bad pointer array: jp[0] != 0 */
  for (int j = 0; j < n_eq; ++j) jp[j] += 2;
  ck_assert_int_eq(b2b_model_add_tangent_profile(h.m, eq, ld, base, n_eq, 1.0, jp, ad2, au2, al2,
                                                 msg, sizeof msg), B2B_ERR_RANGE);
  ck_assert_msg(strstr(msg, "jp") != NULL, "%s", msg);
  TST_ASSERT_ALL(int, j, 0, n_eq, ad2[j] == 0.0, "entry %d", (int)j);
  TST_ASSERT_ALL(int, k, 0, (nau) + 1, au2[k] == 0.0 && al2[k] == 0.0, "entry %d", (int)k);
  ck_assert_int_eq(b2b_model_add_tangent_profile(h.m, eq, ld, base, n_eq, NAN, jp, ad2, au2, al2,
                                                 msg, sizeof msg), B2B_ERR_NONFINITE);
  printf("profile (eq_base %d): %d equations, contacts' heights sum %ld, kl %d, ku %d, as the "
         "dense tangent's nonzeros imply; ad/au/al in FEAP's layout equal the dense tangent "
         "entry by entry (max |K - K^T| %.3g); height of column %d one short and jp[0] = 2 "
         "refused, nothing added\n", base, n_eq, stored, kl, ku, asym, jn + base);
  free(ad);
  free(au);
  free(al);
  free(ad2);
  free(au2);
  free(al2);
  free(jp);
  free(hq);
  free(hd);
  free(K);
  free(eq);
  scene_close(&h);
}

START_TEST(profile_c) { check_profile(0); }
END_TEST
START_TEST(profile_fortran) { check_profile(1); }
END_TEST

static void check_constrained(int base) {
  char msg[B2B_ERRMSG_LEN] = "";
  host_scene h;
  scene_open(&h);
  const int nn = h.sc.n_nodes, ld = 6;
  int n_all, n_eq;
  int *eq_all = numbering(nn, ld, base, 0, &n_all);
  int *eq = numbering(nn, ld, base, 5, &n_eq);
  double *K = dense(h.m, eq_all, ld, base, n_all);
  /* du: prescribed increments on the constrained dofs, NaN on the free ones
   * (the library must not read them) */
  double *du = malloc(sizeof(double) * 4 * nn);
  int n_con = 0;
  for (int k = 0; k < nn; ++k)
    for (int i = 0; i < 4; ++i) {
      const int c = i < 3 && eq[ld * k + i] < base;
      du[4 * k + i] = c ? 1e-3 * cos(0.9 * k + 2.1 * i) : NAN;
      n_con += c;
    }
  double *f = calloc(n_eq, sizeof(double)), *want = calloc(n_eq, sizeof(double));
  ok(b2b_model_add_constrained_product(h.m, eq, ld, base, n_eq, du, 4, nn, 1.0, f, msg,
                                       sizeof msg), msg);
  /* K_all(free, constrained) du_c from the dense tangent with every dof free */
  double scale = 0.0, err = 0.0;
  for (int ka = 0; ka < nn; ++ka)
    for (int ia = 0; ia < 3; ++ia) {
      const int e = eq[ld * ka + ia];
      if (e < base) continue;
      const int ra = eq_all[ld * ka + ia] - base;
      for (int kb = 0; kb < nn; ++kb)
        for (int ib = 0; ib < 3; ++ib) {
          if (eq[ld * kb + ib] >= base) continue;
          const double t = K[ra + (size_t)n_all * (eq_all[ld * kb + ib] - base)] * du[4 * kb + ib];
          want[e - base] += t;
          scale = fmax(scale, fabs(t));
        }
    }
  int nonzero = 0;
  for (int e = 0; e < n_eq; ++e) {
    err = fmax(err, fabs(f[e] - want[e]));
    nonzero += want[e] != 0.0;
  }
  ck_assert_int_gt(nonzero, 0);
  ck_assert_msg(err <= 1e-13 * scale, "max error %g (terms up to %g)", err, scale);
  /* scale -1: exactly the negative */
  double *fm = calloc(n_eq, sizeof(double));
  ok(b2b_model_add_constrained_product(h.m, eq, ld, base, n_eq, du, 4, nn, -1.0, fm, msg,
                                       sizeof msg), msg);
  TST_ASSERT_ALL(int, e, 0, n_eq, fm[e] == -f[e], "entry %d", (int)e);
  /* a NaN in a constrained entry of a contact's node: refused, f untouched */
  int nodes[8], bad = -1, axis = -1;
  int count;
  ok(b2b_model_contact_count(h.m, &count, msg, sizeof msg), msg);
  for (int c = 0; c < count && bad < 0; ++c) {
    ok(b2b_model_get_contact(h.m, c, nodes, NULL, NULL, NULL, NULL, 24, msg, sizeof msg), msg);
    for (int s = 0; s < 8 && bad < 0; ++s)
      for (int i = 0; i < 3 && bad < 0 && nodes[s] >= 0; ++i)
        if (eq[ld * nodes[s] + i] < base) {
          bad = nodes[s];
          axis = i;
        }
  }
  ck_assert_int_ge(bad, 0);
  du[4 * bad + axis] = NAN;
  memcpy(fm, f, sizeof(double) * n_eq);
  ck_assert_int_eq(b2b_model_add_constrained_product(h.m, eq, ld, base, n_eq, du, 4, nn, 1.0, fm,
                                                     msg, sizeof msg), B2B_ERR_NONFINITE);
  char want_msg[64];
  snprintf(want_msg, sizeof want_msg, "node %d has a non-finite prescribed %c", bad,
           "xyz"[axis]);
  ck_assert_msg(strstr(msg, want_msg) != NULL, "%s", msg);
  ck_assert(memcmp(fm, f, sizeof(double) * n_eq) == 0);
  ck_assert_int_eq(b2b_model_add_constrained_product(h.m, eq, ld, base, n_eq, du, 2, nn, 1.0, fm,
                                                     msg, sizeof msg), B2B_ERR_SIZE);
  ck_assert_int_eq(b2b_model_add_constrained_product(h.m, eq, ld, base, n_eq, du, 4, nn, NAN, fm,
                                                     msg, sizeof msg), B2B_ERR_NONFINITE);
  ck_assert(memcmp(fm, f, sizeof(double) * n_eq) == 0);
  printf("constrained product (eq_base %d): %d equations, %d constrained dofs, %d rows "
         "coupled; equals K_all(free, constrained) du_c of the all-free dense tangent to %.2g "
         "(terms up to %.3g); NaN du refused naming node %d\n", base, n_eq, n_con, nonzero, err,
         scale, bad);
  free(fm);
  free(f);
  free(want);
  free(du);
  free(K);
  free(eq);
  free(eq_all);
  scene_close(&h);
}

START_TEST(constrained_c) { check_constrained(0); }
END_TEST
START_TEST(constrained_fortran) { check_constrained(1); }
END_TEST

int main(void) {
  Suite *s = suite_create("model_host");
  TCase *tc = tcase_create("host");
  tcase_add_test(tc, update_xu);
  tcase_add_test(tc, scaled_c);
  tcase_add_test(tc, scaled_fortran);
  tcase_add_test(tc, profile_c);
  tcase_add_test(tc, profile_fortran);
  tcase_add_test(tc, constrained_c);
  tcase_add_test(tc, constrained_fortran);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
