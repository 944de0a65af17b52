/* The model's assembly helpers against assembling its element arrays by
 * hand (b2b_model_get_contact's nodes, residual, tangent) through a 6-dof
 * host's equation numbers with constrained dofs, in C (eq_base 0) and
 * Fortran (eq_base 1) numbering: add_residual, add_tangent_dense,
 * add_tangent_banded (dgbsv layout) and tangent_coo give the same numbers
 * (bit for bit: the same sums in the same order), constrained dofs are
 * skipped, and a band too narrow is refused with nothing added. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_support.h"

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

static void check_numbering(int base) {
  char msg[B2B_ERRMSG_LEN] = "";
  tst_rng rng;
  tst_rng_seed(&rng, 4242);
  tst_scene sc;
  tst_network(&rng, 16, 7, 0.5, 1.6, 0.1, 0.3, 5, 0, &sc);
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.2, 1e3);
  b2b_model *m = tst_model(&sc, p, 1);
  tst_update(m, &sc, 1);
  /* a 6-dof host: eq[6 k + i]; every 7th translational dof constrained */
  const int nn = sc.n_nodes, ld = 6;
  int *eq = malloc(sizeof(int) * ld * nn), n_eq = 0, constrained = 0;
  for (int k = 0; k < nn; ++k)
    for (int i = 0; i < ld; ++i) {
      if (i < 3 && (3 * k + i) % 7 == 3) {
        eq[ld * k + i] = base - 1;
        ++constrained;
      } else {
        eq[ld * k + i] = base + n_eq++;
      }
    }
  /* by hand */
  double *f = calloc((size_t)n_eq, sizeof(double)), *K = calloc((size_t)n_eq * n_eq, sizeof(double));
  int n, kl = 0, ku = 0;
  ok(b2b_model_contact_count(m, &n, msg, sizeof msg), msg);
  ck_assert_int_ge(n, 5);
  for (int c = 0; c < n; ++c) {
    int nodes[8];
    double r[24], T[576];
    ok(b2b_model_get_contact(m, c, nodes, NULL, NULL, r, T, 24, msg, sizeof msg), msg);
    int e[24];
    for (int s = 0; s < 8; ++s)
      for (int i = 0; i < 3; ++i) {
        const int v = nodes[s] < 0 ? base - 1 : eq[ld * nodes[s] + i];
        e[3 * s + i] = v < base ? -1 : v - base;
      }
    for (int a = 0; a < 24; ++a)
      if (e[a] >= 0) f[e[a]] += r[a];
    for (int col = 0; col < 24; ++col)
      for (int row = 0; row < 24; ++row)
        if (e[row] >= 0 && e[col] >= 0) {
          K[e[row] + (size_t)n_eq * e[col]] += T[row + 24 * col];
          if (e[row] - e[col] > kl) kl = e[row] - e[col];
          if (e[col] - e[row] > ku) ku = e[col] - e[row];
        }
  }
  /* residual */
  double *f2 = calloc((size_t)n_eq, sizeof(double));
  ok(b2b_model_add_residual(m, eq, ld, base, n_eq, f2, msg, sizeof msg), msg);
  ck_assert_msg(memcmp(f, f2, sizeof(double) * n_eq) == 0, "add_residual differs");
  /* dense, with ldk > n_eq */
  const int ldk = n_eq + 3;
  double *K2 = calloc((size_t)ldk * n_eq, sizeof(double));
  ok(b2b_model_add_tangent_dense(m, eq, ld, base, n_eq, K2, ldk, msg, sizeof msg), msg);
  for (int col = 0; col < n_eq; ++col)
    ck_assert_msg(memcmp(K + (size_t)n_eq * col, K2 + (size_t)ldk * col, sizeof(double) * n_eq) == 0,
                  "add_tangent_dense differs in column %d", col);
  /* banded */
  const int ldab = 2 * kl + ku + 1;
  double *AB = calloc((size_t)ldab * n_eq, sizeof(double));
  ok(b2b_model_add_tangent_banded(m, eq, ld, base, n_eq, kl, ku, AB, ldab, msg, sizeof msg), msg);
  for (int col = 0; col < n_eq; ++col)
    for (int row = 0; row < n_eq; ++row) {
      const double want = K[row + (size_t)n_eq * col];
      if (row - col > kl || col - row > ku) {
        ck_assert(want == 0.0);
        continue;
      }
      ck_assert_msg(AB[kl + ku + row - col + (size_t)ldab * col] == want, "band (%d, %d)", row, col);
    }
  /* a band one too narrow: refused, nothing added */
  if (kl > 0) {
    double *AB2 = calloc((size_t)ldab * n_eq, sizeof(double));
    ck_assert_int_eq(b2b_model_add_tangent_banded(m, eq, ld, base, n_eq, kl - 1, ku, AB2, ldab,
                                                  msg, sizeof msg), B2B_ERR_RANGE);
    ck_assert_msg(strstr(msg, "band") != NULL, "%s", msg);
    for (size_t k = 0; k < (size_t)ldab * n_eq; ++k) ck_assert(AB2[k] == 0.0);
    free(AB2);
  }
  /* COO: size query, fill, sum */
  int nnz = -1;
  ok(b2b_model_tangent_coo(m, eq, ld, base, n_eq, &nnz, NULL, NULL, NULL, 0, msg, sizeof msg), msg);
  int *rows = malloc(sizeof(int) * nnz), *cols = malloc(sizeof(int) * nnz);
  double *vals = malloc(sizeof(double) * nnz), *K3 = calloc((size_t)n_eq * n_eq, sizeof(double));
  ok(b2b_model_tangent_coo(m, eq, ld, base, n_eq, &nnz, rows, cols, vals, nnz, msg, sizeof msg), msg);
  for (int k = 0; k < nnz; ++k) {
    ck_assert(rows[k] >= base && rows[k] < base + n_eq && cols[k] >= base && cols[k] < base + n_eq);
    K3[(rows[k] - base) + (size_t)n_eq * (cols[k] - base)] += vals[k];
  }
  ck_assert_msg(memcmp(K, K3, sizeof(double) * n_eq * n_eq) == 0, "COO sums differ");
  double fmax = 0;
  for (int k = 0; k < n_eq; ++k) fmax = fmax > fabs(f[k]) ? fmax : fabs(f[k]);
  printf("assembly (eq_base %d): %d contacts, %d equations (%d dofs constrained), band kl %d ku "
         "%d, %d COO entries; residual, dense, band and COO equal to assembling by hand "
         "(max |f| %.3g)\n", base, n, n_eq, constrained, kl, ku, nnz, fmax);
  ck_assert(fmax > 0);
  free(rows);
  free(cols);
  free(vals);
  free(K3);
  free(AB);
  free(K2);
  free(f2);
  free(K);
  free(f);
  free(eq);
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
  tst_scene_free(&sc);
}

START_TEST(c_numbering) { check_numbering(0); }
END_TEST

START_TEST(fortran_numbering) { check_numbering(1); }
END_TEST

int main(void) {
  Suite *s = suite_create("model_assembly");
  TCase *tc = tcase_create("assembly");
  tcase_add_test(tc, c_numbering);
  tcase_add_test(tc, fortran_numbering);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
