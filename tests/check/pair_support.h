/* Helpers of the pair suites: parameter handles and generated crossings. */
#ifndef B2B_PAIR_SUPPORT_H
#define B2B_PAIR_SUPPORT_H

#include "test_support.h"

/* A finalized parameter set (fails the test on error). g0 is used by the
 * quadratic law only. Destroy with b2b_params_destroy. */
b2b_params *tst_params(int law, double penalty, double g0);

typedef struct {
  int kind[2], start_rule[2], end_rule[2];
  double radius[2];
} tst_pair_spec;

/* The 24 coordinates of a crossing: two random curved patches (turning up to
 * max_turn per node), placed so that at parameters xi_star on A and eta_star
 * on B the tangents cross at angle_deg and the axes are dist apart along
 * their common normal. Unused slots are NaN. */
void tst_crossing(tst_rng *rng, const tst_pair_spec *spec, double max_turn, double angle_deg,
                  double xi_star, double eta_star, double dist, double X[24]);

/* b2b_pair_eval with a fresh history unless hist is given; fails the test
 * unless it returns B2B_OK. tangent may be NULL. Returns the contact status. */
int tst_pair(const b2b_params *params, const tst_pair_spec *spec, const double X[24],
             const double *hist_old, double *hist_new, double info[32], double residual[24],
             double *tangent);

/* A finalized parameter set with Coulomb friction: "friction" = mu and, if
 * eps_t > 0, "tangential_penalty" = eps_t (fails the test on error). */
b2b_params *tst_params_friction(int law, double penalty, double g0, double mu, double eps_t);

/* Penalties and friction of a line-contact parameter set: eps_n the point
 * element's penalty, eps_l the line penalty; with mu > 0, Coulomb friction
 * with tangential penalties eps_t (point) and eps_lt (line). */
typedef struct {
  double eps_n, eps_l, mu, eps_t, eps_lt;
} tst_line_spec;

/* A finalized line-contact parameter set (fails the test on error): law
 * (the quadratic law with regularization gap 0.01), "contact_type" type,
 * "tangent" option tangent (< 0: the default), the penalties of spec. */
b2b_params *tst_line_params(int law, int type, int tangent, const tst_line_spec *spec);

/* b2b_params_history_size (fails the test on error). */
int tst_history_len(const b2b_params *params);

/* tst_pair with the host's end tangents (A's two, then B's two; NULL: the
 * defaults tst_pair uses). */
int tst_pair_ext(const b2b_params *params, const tst_pair_spec *spec, const double X[24],
                 const double end_tangents[12], const double *hist_old, double *hist_new,
                 double info[32], double residual[24], double *tangent);

/* Largest |K2 - Q K1 Q^T| over the 3x3 node blocks of two 24x24 tangents
 * (column-major): how far K2 is from K1 turned by the rotation Q. */
/* max |K - K^T| over max |K| of a 24 x 24 tangent (0 for a zero K). */
double tst_asymmetry(const double K[576]);

double tst_tangent_rotation_error(const double Q[9], const double K1[576], const double K2[576]);

#endif
