/* Wrapper of the README's contact-element fragment (section "The contact
 * element"): declares what the fragment uses, with two hermite-nodal
 * segments crossing at 90 degrees and pressed 0.01 into each other, runs it,
 * and checks that it found that contact. Exits non-zero otherwise.
 * The fragment declares p and sets nhist, status, info, residual, tangent. */
#include <stdio.h>

#include <b2b/b2b.h>

int main(void) {
  char msg[B2B_ERRMSG_LEN] = "";
  int nhist = -1;
  int status = -1;
  const int segments[6] = {B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                           B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
  /* A along x, B along y, 0.19 above it: radii 0.1, gap -0.01. */
  const double X[24] = {-1.5, 0.0, 0.0,  -0.5, 0.0, 0.0,  0.5, 0.0, 0.0,  1.5, 0.0, 0.0,
                        0.0, -1.5, 0.19, 0.0, -0.5, 0.19, 0.0, 0.5, 0.19, 0.0, 1.5, 0.19};
  const double *end_tangents = NULL; /* no B2B_END_TANGENT rule in force */
  const double radii[2] = {0.1, 0.1};
  double hist_old[64] = {0.0}; /* a fresh history; the fragment asks for its length */
  double hist_new[64];
  double info[B2B_PAIR_INFO_LEN];
  double residual[B2B_PAIR_NDOF];
  double tangent[B2B_PAIR_NDOF * B2B_PAIR_NDOF];

  /* README SNIPPET */

  b2b_params_destroy(&p);
  if (msg[0] != '\0' || nhist < 1 || nhist > 64 || status != B2B_CONTACT_ACTIVE) {
    fprintf(stderr, "README contact element: history %d, status %d, message '%s'\n", nhist,
            status, msg);
    return 1;
  }
  printf("README contact element: active, gap %g, f_N %g, residual_z(A) %g, K(2,2) %g\n",
         info[B2B_INFO_GAP], info[B2B_INFO_NORMAL_FORCE], residual[2], tangent[2 + 24 * 2]);
  return 0;
}
