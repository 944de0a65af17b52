/* Wrapper of the README's contact-model fragment in C (section "The contact
 * model"): a host's arrays for one beam of 17 nodes on the x axis, every
 * translational dof free (equations 0..50, eq_base 0), and a finalized
 * parameter set for the group pair. The fragment declares m and runs the
 * life cycle once; the wrapper checks that no call wrote a message (every
 * call succeeded) and frees the handles. Exits non-zero otherwise. */
#include <stdio.h>

#include <b2b/b2b.h>

enum { N_NODES = 17, N_EQ = 3 * N_NODES };

int main(void) {
  char msg[B2B_ERRMSG_LEN] = "";
  int nodes[N_NODES], eq[3 * N_NODES], k;
  const int n = N_NODES, closed = 0, group = 0, n_nodes = N_NODES, ldeq = 3, n_eq = N_EQ;
  const int ldk = N_EQ;
  const double radius = 0.1;
  double x[3 * N_NODES], f[N_EQ] = {0.0};
  static double K[N_EQ * N_EQ];
  int beam = -1;
  b2b_params *params = NULL;

  for (k = 0; k < N_NODES; ++k) {
    nodes[k] = k;
    x[3 * k] = 0.25 * k;
    x[3 * k + 1] = 0.0;
    x[3 * k + 2] = 0.0;
  }
  for (k = 0; k < 3 * N_NODES; ++k) eq[k] = k;
  if (b2b_params_create(&params, msg, sizeof msg) != B2B_OK ||
      b2b_params_set_real(params, "penalty", 1e3, msg, sizeof msg) != B2B_OK ||
      b2b_params_finalize(params, msg, sizeof msg) != B2B_OK) {
    fprintf(stderr, "README model (C): parameter set: %s\n", msg);
    return 1;
  }

  /* README SNIPPET */

  b2b_model_destroy(&m);
  b2b_params_destroy(&params);
  if (msg[0] != '\0' || beam != 0) {
    fprintf(stderr, "README model (C): beam %d, message '%s'\n", beam, msg);
    return 1;
  }
  printf("README model (C): one beam, the life cycle ran without an error\n");
  return 0;
}
