/* A small host with the contact model, in C: what a user's code does.
 *
 * Beam A, an arc of radius 3 (16 hermite-nodal elements, unevenly meshed),
 * is fixed. Beam B, a straight beam of 5 nodes across it, is free; each of
 * its nodes hangs on a spring (stiffness k) whose anchor presses B onto A
 * and drags it along the arc, in load steps that carry the contact across
 * A's nodes. Coulomb friction (mu 0.3) acts between them. Every load step
 * is solved by Newton's method: the residual k (x - anchor) + contact and the
 * tangent k I + contact come from b2b_model_add_residual and
 * b2b_model_add_tangent_dense through the host's equation numbers (A's dofs
 * constrained), the system by LAPACK's dgesv (the friction tangent is not
 * symmetric); converged steps are committed.
 *
 * It checks, and exits non-zero otherwise: every step converges; exactly one
 * contact carries the load; Newton's last step squares the residual (see
 * below); the contact crossed at least 8 of A's nodes; the friction force
 * slips at mu f_N. --quick: fewer steps (for ctest). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <b2b/b2b.h>

void dgesv_(const int *n, const int *nrhs, double *a, const int *lda, int *ipiv, double *b,
            const int *ldb, int *info);

enum { NA = 17, NB = 5, NN = NA + NB, NEQ = 3 * NB };

static int fail(const char *what, int status, const char *msg) {
  fprintf(stderr, "model_host: %s failed (%s): %s\n", what, b2b_strerror(status), msg);
  return 1;
}

int main(int argc, char **argv) {
  const int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
  const double R = 3.0, r = 0.1, k_spring = 400.0, mu = 0.3, press = 0.05;
  char msg[B2B_ERRMSG_LEN] = "";
  int st;

  /* The host's nodes: A (0 .. 16) on the arc, angles alternating 1.2h/0.8h. */
  double x[3 * NN], anchor[3 * NB], anchor_prev[3 * NB];
  double phi = 0.0, phis[NA];
  for (int k = 0; k < NA; ++k) {
    phis[k] = phi;
    x[3 * k] = R * cos(phi);
    x[3 * k + 1] = R * sin(phi);
    x[3 * k + 2] = 0.0;
    phi += (k % 2 ? 0.8 : 1.2) * (3.14159265358979 / 16);
  }
  /* B's anchors at angle theta, pressed press into A, B along z */
  double theta = 0.3;
  for (int j = 0; j < NB; ++j)
    for (int i = 0; i < 3; ++i) x[3 * (NA + j) + i] = 0.0;
  /* equation numbers: A fixed (-1), B's 15 dofs 0 .. 14 (C numbering) */
  int eq[3 * NN];
  for (int k = 0; k < NN; ++k)
    for (int i = 0; i < 3; ++i) eq[3 * k + i] = k < NA ? -1 : 3 * (k - NA) + i;

  b2b_params *p = NULL;
  b2b_model *m = NULL;
  if ((st = b2b_params_create(&p, msg, sizeof msg))) return fail("params", st, msg);
  /* The C1 regularized law: contact starts at a gap of 0.02, so a predictor
   * that leaves B just off A still sees stiffness, and Newton does not
   * ping-pong between open and deeply closed (with the linear law it does). */
  b2b_params_set_real(p, "penalty", 2e4, msg, sizeof msg);
  b2b_params_set_int(p, "law", B2B_LAW_QUADRATIC, msg, sizeof msg);
  b2b_params_set_real(p, "regularization_gap", 0.02, msg, sizeof msg);
  b2b_params_set_real(p, "friction", mu, msg, sizeof msg);
  b2b_params_set_real(p, "tangential_penalty", 2e4, msg, sizeof msg);
  if ((st = b2b_params_finalize(p, msg, sizeof msg))) return fail("finalize params", st, msg);

  int nodes_a[NA], nodes_b[NB], beam;
  for (int k = 0; k < NA; ++k) nodes_a[k] = k;
  for (int j = 0; j < NB; ++j) nodes_b[j] = NA + j;
  if ((st = b2b_model_create(&m, msg, sizeof msg)) ||
      (st = b2b_model_add_beam(m, nodes_a, NA, 0, r, B2B_CURVE_HERMITE_NODAL, 0, &beam, msg,
                               sizeof msg)) ||
      (st = b2b_model_add_beam(m, nodes_b, NB, 0, r, B2B_CURVE_HERMITE_NODAL, 1, &beam, msg,
                               sizeof msg)) ||
      (st = b2b_model_set_group_pair(m, 0, 1, p, msg, sizeof msg)) ||
      (st = b2b_model_finalize(m, NN, msg, sizeof msg)))
    return fail("model set-up", st, msg);

  const int steps = quick ? 12 : 40;
  const double dtheta = (phis[NA - 1] - 0.6) / 40;
  int errors = 0, crossings = 0, seg_prev = -1, total_iterations = 0, n_quadratic = 0;
  double worst_C = 0.0, lowest_order = 1e300;
  printf("step  theta  iterations  last residual norms              A's segment  f_N      |T|/(mu f_N)\n");
  for (int step = 0; step < steps; ++step) {
    theta += dtheta;
    const double rho = R + 2 * r - press;
    for (int j = 0; j < NB; ++j) {
      anchor[3 * j] = rho * cos(theta);
      anchor[3 * j + 1] = rho * sin(theta);
      anchor[3 * j + 2] = 0.3 * (j - 2) + 0.05;
    }
    /* predictor: B moves with its anchors (the displacement increment) */
    if (step == 0) memcpy(x + 3 * NA, anchor, sizeof anchor);
    else
      for (int e = 0; e < NEQ; ++e) x[3 * NA + e] += anchor[e] - anchor_prev[e];
    memcpy(anchor_prev, anchor, sizeof anchor);
    double norms[40];
    int active_set[40];
    int it = 0, converged = 0;
    for (; it < 40; ++it) {
      if ((st = b2b_model_update(m, x, 3, NN, 1, msg, sizeof msg))) return fail("update", st, msg);
      double f[NEQ], K[NEQ * NEQ];
      for (int e = 0; e < NEQ; ++e) f[e] = k_spring * (x[3 * NA + e] - anchor[e]);
      memset(K, 0, sizeof K);
      for (int e = 0; e < NEQ; ++e) K[e + NEQ * e] = k_spring;
      if ((st = b2b_model_add_residual(m, eq, 3, 0, NEQ, f, msg, sizeof msg)) ||
          (st = b2b_model_add_tangent_dense(m, eq, 3, 0, NEQ, K, NEQ, msg, sizeof msg)))
        return fail("assembly", st, msg);
      double nf = 0.0;
      for (int e = 0; e < NEQ; ++e) nf += f[e] * f[e];

      norms[it] = sqrt(nf);
      /* the active set of this iterate: which pair holds the contact, and
       * whether it sticks or slips */
      int nc, pr[4] = {-1, -1, -1, -1};
      double inf[32] = {0};
      b2b_model_contact_count(m, &nc, msg, sizeof msg);
      if (nc > 0) b2b_model_get_contact(m, 0, NULL, pr, inf, NULL, NULL, 0, msg, sizeof msg);
      active_set[it] = nc * 100000 + pr[1] * 100 + (int)inf[B2B_INFO_FRICTION_STATE];
      if (norms[it] < 1e-9) {
        converged = 1;
        break;
      }
      int n = NEQ, one = 1, ipiv[NEQ], info;
      dgesv_(&n, &one, K, &n, ipiv, f, &n, &info);
      if (info) {
        fprintf(stderr, "model_host: dgesv info %d\n", info);
        return 1;
      }
      for (int e = 0; e < NEQ; ++e) x[3 * NA + e] -= f[e];
    }
    total_iterations += it;
    int n_contacts, pair[4];
    double info[32];
    b2b_model_contact_count(m, &n_contacts, msg, sizeof msg);
    if (!converged || n_contacts != 1) {
      fprintf(stderr, "model_host: step %d: %s, %d contacts\n", step,
              converged ? "converged" : "NOT converged", n_contacts);
      ++errors;
      break;
    }
    b2b_model_get_contact(m, 0, NULL, pair, info, NULL, NULL, 0, msg, sizeof msg);
    const double *T = info + B2B_INFO_TANGENTIAL_FORCE;
    const double fn = info[B2B_INFO_NORMAL_FORCE];
    const double ratio = sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]) / (mu * fn);
    /* quadratic: the last step clear of round-off (norms > 1e-10) satisfies
     * r_{k+1} <= C r_k^2 with C <= 1 (in units of the forces, which are
     * O(10) here; a linearly converging step with ratio 0.1 at r_k = 1e-3
     * would give C = 100), where the active set (pair, stick or slip) held
     * over those iterations. The order log(r2/r1)/log(r1/r0) of the last
     * three is printed too; from a start far off it reads low even where each
     * step squares the error. */
    int last = it;
    while (last >= 0 && norms[last] <= 1e-10) --last;
    if (last >= 1 && active_set[last] == active_set[last - 1]) {
      const double C = norms[last] / (norms[last - 1] * norms[last - 1]);
      if (C > worst_C) worst_C = C;
      ++n_quadratic;
      if (C > 1.0) {
        fprintf(stderr, "model_host: step %d: r = %.3g after %.3g, not quadratic\n", step,
                norms[last], norms[last - 1]);
        ++errors;
      }
      if (last >= 2 && active_set[last - 1] == active_set[last - 2]) {
        const double order =
            log(norms[last] / norms[last - 1]) / log(norms[last - 1] / norms[last - 2]);
        if (order < lowest_order) lowest_order = order;
      }
    }
    if (step > 1 && fabs(ratio - 1.0) > 1e-6) {
      fprintf(stderr, "model_host: step %d: |T| = %.6f mu f_N, slip expected\n", step, ratio);
      ++errors;
    }
    if (seg_prev >= 0 && pair[1] != seg_prev) ++crossings;
    seg_prev = pair[1];
    printf("%4d  %5.3f  %10d  ", step, theta, it);
    for (int j = it - 3 < 0 ? 0 : it - 3; j <= it; ++j) printf("%9.2e ", norms[j]);
    for (int j = it; j < 3; ++j) printf("          ");
    printf("  %11d  %7.3f  %.6f\n", pair[1] + 1, fn, ratio);
    if ((st = b2b_model_commit(m, msg, sizeof msg))) return fail("commit", st, msg);
  }
  printf("%d steps, %d Newton iterations, the contact crossed %d of A's nodes\n", steps,
         total_iterations, crossings);
  printf("quadratic convergence: r_{k+1} <= %.3g r_k^2 in the last step of all %d steps "
         "checked; order estimate from the last three norms at least %.2f\n", worst_C,
         n_quadratic, lowest_order);
  if (n_quadratic < steps / 2) {
    fprintf(stderr, "model_host: only %d steps kept their active set to the end\n", n_quadratic);
    ++errors;
  }
  if (crossings < (quick ? 2 : 8)) {
    fprintf(stderr, "model_host: only %d node crossings\n", crossings);
    ++errors;
  }
  b2b_model_destroy(&m);
  b2b_params_destroy(&p);
  printf("model_host: %s\n", errors ? "FAILED" : "all checks passed");
  return errors ? 1 : 0;
}
