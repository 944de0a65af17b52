/* A host's Newton loop with the frictional contact element: why the tangent
 * must be exact, and why the host's solver must accept a non-symmetric one.
 *
 * Beam A (one hermite-nodal segment, its four patch nodes free) hangs on
 * springs of stiffness k whose anchors are pressed down onto beam B (fixed)
 * and then dragged along A's axis in load steps; friction first holds A
 * (stick), then lets it slide (slip). Each load step is solved by Newton's
 * method on the 12 free coordinates,
 *     R(x) = k (x - anchors) + residual_A(x) = 0,   (k I + K_AA) dx = -R,
 * with LAPACK's dgesv (LU: the tangent is not symmetric). The step is
 * committed (hist_new -> hist_old) when it has converged.
 *
 *   friction_newton [--quick]      (--quick is accepted for ctest)
 *
 * Prints the residual norms of every iteration and the convergence order
 * estimated from the last three norms clear of round-off; then solves the
 * same history with the symmetric part of the tangent (what a host with a
 * symmetric solver would do) and counts its iterations. "Newton: quadratic"
 * if every step converged with order >= 1.5 and in fewer iterations in all
 * than with the symmetric part. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <b2b/b2b.h>

extern void dgesv_(const int *n, const int *nrhs, double *a, const int *lda, int *ipiv, double *b,
                   const int *ldb, int *info);

static void check(int st, const char *what, const char *msg) {
  if (st != B2B_OK) {
    fprintf(stderr, "friction_newton: %s failed (%s): %s\n", what, b2b_strerror(st), msg);
    exit(EXIT_FAILURE);
  }
}

/* Runs the loading history; symmetrize = 1 replaces the tangent by its
 * symmetric part (what a host with a symmetric solver would use). Returns
 * the total number of iterations; *ok = 0 if a step did not converge within
 * MAX_IT or (exact tangent) converged slower than order 1.5. */
enum { N_LOAD = 9, MAX_IT = 40 };

static int run(b2b_params *p, int symmetrize, int print, int *ok) {
  char msg[B2B_ERRMSG_LEN] = "";
  int nhist = 0;
  check(b2b_params_history_size(p, &nhist, msg, sizeof msg), "history size", msg);
  double hist_old[64] = {0}, hist_new[64] = {0};
  const int segments[6] = {B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                           B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
  const double radius = 0.25, k_spring = 200.0;
  const double radii[2] = {radius, radius};
  /* B: a curved beam along y (fixed); A: along x, slightly skewed, free. */
  double X[24];
  for (int k = 0; k < 4; ++k) {
    const double s = k - 1.5;
    X[3 * k] = s;
    X[3 * k + 1] = 0.1 * s;
    X[3 * k + 2] = 2.0 * radius + 0.01 + 0.02 * s * s;
    X[12 + 3 * k] = 0.05 * s * s;
    X[12 + 3 * k + 1] = s;
    X[12 + 3 * k + 2] = -0.03 * s * s;
  }
  double rest[12];
  memcpy(rest, X, sizeof rest);
  int total = 0;
  *ok = 1;
  if (print) printf("\n| step | drag | state | iterations: |R| | order |\n|---:|---:|---|---|---:|\n");
  for (int step = 0; step < N_LOAD; ++step) {
    /* Anchors: pressed 0.04 below the rest position, dragged along x. */
    const double drag = 0.01 * step;
    double anchors[12];
    for (int k = 0; k < 4; ++k) {
      anchors[3 * k] = rest[3 * k] + drag;
      anchors[3 * k + 1] = rest[3 * k + 1];
      anchors[3 * k + 2] = rest[3 * k + 2] - 0.04;
    }
    double norms[MAX_IT + 1];
    int it = 0, status = -1;
    double info[B2B_PAIR_INFO_LEN];
    for (;; ++it) {
      double res[24], K[24 * 24], A[144], R[12];
      check(b2b_pair_eval(p, segments, X, NULL, radii, hist_old, hist_new, nhist, &status, info,
                          res, K, 24, msg, sizeof msg),
            "b2b_pair_eval", msg);
      double norm = 0.0;
      for (int i = 0; i < 12; ++i) {
        R[i] = k_spring * (X[i] - anchors[i]) + res[i];
        norm += R[i] * R[i];
      }
      norms[it] = sqrt(norm);
      if (norms[it] < 1e-11 || it == MAX_IT) break;
      for (int c = 0; c < 12; ++c)
        for (int r = 0; r < 12; ++r) {
          const double kk = symmetrize ? 0.5 * (K[r + 24 * c] + K[c + 24 * r]) : K[r + 24 * c];
          A[r + 12 * c] = kk + (r == c ? k_spring : 0.0);
        }
      for (int i = 0; i < 12; ++i) R[i] = -R[i];
      int n = 12, nrhs = 1, ipiv[12], lapack_info = 0;
      dgesv_(&n, &nrhs, A, &n, ipiv, R, &n, &lapack_info);
      if (lapack_info != 0) {
        fprintf(stderr, "friction_newton: dgesv failed (%d)\n", lapack_info);
        exit(EXIT_FAILURE);
      }
      for (int i = 0; i < 12; ++i) X[i] += R[i];
    }
    total += it;
    /* Convergence order log(r2/r1) / log(r1/r0) of the last three norms
     * clear of round-off (> 1e-11; the floor is about 1e-13). */
    double order = NAN;
    int last = it;
    while (last >= 0 && norms[last] <= 1e-11) --last;
    if (last >= 2)
      order = log(norms[last] / norms[last - 1]) / log(norms[last - 1] / norms[last - 2]);
    const int converged = norms[it] < 1e-11;
    if (!converged || (!symmetrize && !isnan(order) && !(order >= 1.5))) *ok = 0;
    if (print) {
      const int state = (int)info[B2B_INFO_FRICTION_STATE];
      static const char *names[3] = {"-", "stick", "slip"};
      printf("| %d | %.2f | %s |", step, drag,
             status == B2B_CONTACT_ACTIVE ? names[state] : "open");
      for (int j = 0; j <= it; ++j) printf(" %.1e", norms[j]);
      printf(" | %.2f |\n", order);
    }
    memcpy(hist_old, hist_new, sizeof hist_old); /* commit */
  }
  return total;
}

int main(void) {
  const double penalty = 2000.0, mu = 0.3, eps_t = 1000.0;
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  check(b2b_params_create(&p, msg, sizeof msg), "create", msg);
  check(b2b_params_set_real(p, "penalty", penalty, msg, sizeof msg), "penalty", msg);
  check(b2b_params_set_real(p, "friction", mu, msg, sizeof msg), "friction", msg);
  check(b2b_params_set_real(p, "tangential_penalty", eps_t, msg, sizeof msg), "eps_T", msg);
  check(b2b_params_finalize(p, msg, sizeof msg), "finalize", msg);
  printf("Newton on A's 12 coordinates: springs k = 200, eps_N %g, mu %g, eps_T %g\n", penalty,
         mu, eps_t);
  int ok_exact = 0, ok_sym = 0;
  const int it_exact = run(p, 0, 1, &ok_exact);
  const int it_sym = run(p, 1, 0, &ok_sym);
  printf("\nIterations over the %d load steps: exact tangent %d; its symmetric part %d%s\n",
         N_LOAD, it_exact, it_sym, ok_sym ? "" : " (some steps did not converge in 40)");
  const int quadratic = ok_exact && it_exact < it_sym;
  printf("Newton: %s\n", quadratic ? "quadratic" : "NOT quadratic");
  b2b_params_destroy(&p);
  return quadratic ? EXIT_SUCCESS : EXIT_FAILURE;
}
