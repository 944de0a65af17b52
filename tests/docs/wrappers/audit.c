/* Wrapper of the README's audit fragment in C (section "Interpenetration
 * audit"): a model of two parallel beams of straight segments (radius 0.1)
 * pressed 0.05 into each other, updated once: below parallel_angle the
 * element carries no force, so the audit has findings and the fragment takes
 * its cut-back branch. The wrapper checks that no call wrote a message, that
 * the fragment found the overlaps and reverted (a commit now is
 * B2B_ERR_STATE: nothing to commit). Exits non-zero otherwise. */
#include <stdio.h>
#include <stdlib.h>

#include <b2b/b2b.h>

int main(void) {
  char msg[B2B_ERRMSG_LEN] = "";
  int a[6], b[6], beam, k;
  double x[36];
  b2b_params *params = NULL;
  b2b_model *m = NULL;
  for (k = 0; k < 6; ++k) {
    a[k] = k;
    b[k] = 6 + k;
    x[3 * k] = 0.5 * k;
    x[3 * (6 + k)] = 0.5 * k + 0.2;
    x[3 * k + 1] = x[3 * (6 + k) + 1] = 0.0;
    x[3 * k + 2] = 0.0;
    x[3 * (6 + k) + 2] = 0.15;
  }
  if (b2b_params_create(&params, msg, sizeof msg) || b2b_params_set_real(params, "penalty", 1e3, msg, sizeof msg) ||
      b2b_params_finalize(params, msg, sizeof msg) || b2b_model_create(&m, msg, sizeof msg) ||
      b2b_model_add_beam(m, a, 6, 0, 0.1, B2B_CURVE_LINEAR, 0, &beam, msg, sizeof msg) ||
      b2b_model_add_beam(m, b, 6, 0, 0.1, B2B_CURVE_LINEAR, 1, &beam, msg, sizeof msg) ||
      b2b_model_set_group_pair(m, 0, 1, params, msg, sizeof msg) ||
      b2b_model_finalize(m, 12, msg, sizeof msg) || b2b_model_update(m, x, 3, 12, 1, msg, sizeof msg)) {
    fprintf(stderr, "README audit (C): set-up: %s\n", msg);
    return 1;
  }

  /* README SNIPPET */

  if (msg[0] != '\0' || n_found == 0) {
    fprintf(stderr, "README audit (C): %d findings, message '%s'\n", n_found, msg);
    return 1;
  }
  if (b2b_model_commit(m, msg, sizeof msg) != B2B_ERR_STATE) {
    fprintf(stderr, "README audit (C): the fragment did not cut the step back\n");
    return 1;
  }
  b2b_model_destroy(&m);
  b2b_params_destroy(&params);
  printf("README audit (C): %d pairs overlap with no force, the step was cut back\n", n_found);
  return 0;
}
