/* Coulomb friction of one contact pair under a loading history, driven the
 * way a host drives it: two straight beams crossing at 90 degrees, A pressed
 * onto B, pulled along its axis past the slip limit, pulled back the other
 * way, and lifted off. After each (displacement-controlled) step the host
 * commits the step by copying hist_new into hist_old.
 *
 *   friction_loading [--quick]     (one run; --quick is accepted for ctest)
 *
 * Each step is compared with the one-dimensional Coulomb model it must
 * reproduce here (straight beams, constant normal force): an elastic spring
 * of stiffness eps_T in series with a slider that yields at mu f_N. The
 * program prints the table, the dissipated energy against mu f_N times the
 * total slip, and "Coulomb sequence: as predicted" if every step agrees. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <b2b/b2b.h>

static void check(int st, const char *what, const char *msg) {
  if (st != B2B_OK) {
    fprintf(stderr, "friction_loading: %s failed (%s): %s\n", what, b2b_strerror(st), msg);
    exit(EXIT_FAILURE);
  }
}

/* The 24 coordinates: A along x at height z_a, shifted by u along x; B along
 * y at height 0. Four nodes each, spacing 1, the crossing in the middle
 * element of both patches. */
static void configuration(double u, double z_a, double X[24]) {
  for (int k = 0; k < 4; ++k) {
    const double s = k - 1.5;
    X[3 * k] = s + u;
    X[3 * k + 1] = 0.0;
    X[3 * k + 2] = z_a;
    X[12 + 3 * k] = 0.0;
    X[12 + 3 * k + 1] = s;
    X[12 + 3 * k + 2] = 0.0;
  }
}

int main(void) {
  const double penalty = 1000.0, mu = 0.3, eps_t = 1400.0, radius = 0.25;
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  check(b2b_params_create(&p, msg, sizeof msg), "create", msg);
  check(b2b_params_set_real(p, "penalty", penalty, msg, sizeof msg), "penalty", msg);
  check(b2b_params_set_real(p, "friction", mu, msg, sizeof msg), "friction", msg);
  check(b2b_params_set_real(p, "tangential_penalty", eps_t, msg, sizeof msg), "eps_T", msg);
  check(b2b_params_finalize(p, msg, sizeof msg), "finalize", msg);
  int nhist = 0;
  check(b2b_params_history_size(p, &nhist, msg, sizeof msg), "history size", msg);
  double *hist_old = calloc((size_t)nhist, sizeof(double));
  double *hist_new = calloc((size_t)nhist, sizeof(double));
  if (!hist_old || !hist_new) return EXIT_FAILURE;

  const int segments[6] = {B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                           B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
  const double radii[2] = {radius, radius};
  const double z_pressed = 2.0 * radius - 0.05; /* gap -0.05: f_N = 50 */

  /* The history: 0 (press), up to +0.02 in 10 steps, back to -0.01 in 15
   * steps, then lift off. */
  enum { N_STEPS = 28 };
  double u[N_STEPS], z[N_STEPS];
  int n = 0;
  u[n] = 0.0, z[n++] = z_pressed;
  for (int i = 1; i <= 10; ++i) u[n] = 0.002 * i, z[n++] = z_pressed;
  for (int i = 1; i <= 15; ++i) u[n] = 0.02 - 0.002 * i, z[n++] = z_pressed;
  u[n] = u[n - 1], z[n++] = 2.0 * radius + 0.1;
  u[n] = u[n - 1], z[n++] = z_pressed;

  /* The 1D model: elastic displacement e of the spring, slider at u - e. */
  double e = 0.0, u_prev = 0.0, total_slip = 0.0, total_dissipation = 0.0;
  int in_contact = 0, agree = 1;
  double friction_work = 0.0; /* mu f_N |slip| summed over the steps */
  printf("Coulomb friction of one pair: eps_N %g, mu %g, eps_T %g, hermite-nodal beams\n",
         penalty, mu, eps_t);
  printf("\n| step | u | gap | state | T_x | mu f_N | slip_x | dissipation | model |\n");
  printf("|---:|---:|---:|---|---:|---:|---:|---:|---|\n");
  for (int s = 0; s < n; ++s) {
    double X[24], info[B2B_PAIR_INFO_LEN], residual[24];
    int status = -1;
    configuration(u[s], z[s], X);
    check(b2b_pair_eval(p, segments, X, NULL, radii, hist_old, hist_new, nhist, &status, info,
                        residual, NULL, 0, msg, sizeof msg),
          "b2b_pair_eval", msg);
    const double fn = info[B2B_INFO_NORMAL_FORCE], tx = info[B2B_INFO_TANGENTIAL_FORCE];
    const int state = (int)info[B2B_INFO_FRICTION_STATE];

    /* The model's prediction for this step. */
    int want_state = B2B_FRICTION_NONE;
    double want_t = 0.0, want_slip = 0.0;
    if (status == B2B_CONTACT_ACTIVE) {
      if (!in_contact) e = 0.0; /* a new contact starts unloaded */
      else e += u[s] - u_prev;
      const double limit = mu * fn;
      want_state = B2B_FRICTION_STICK;
      if (fabs(eps_t * e) > limit) {
        want_state = B2B_FRICTION_SLIP;
        const double e_new = copysign(limit / eps_t, e);
        want_slip = e - e_new;
        e = e_new;
      }
      want_t = eps_t * e;
    }
    in_contact = status == B2B_CONTACT_ACTIVE;
    u_prev = u[s];
    const int ok = state == want_state && fabs(tx - want_t) <= 1e-9 * (1.0 + fabs(want_t)) &&
                   fabs(info[B2B_INFO_SLIP] - want_slip) <= 1e-12 &&
                   info[B2B_INFO_DISSIPATION] >= 0.0;
    agree = agree && ok;
    total_slip += fabs(info[B2B_INFO_SLIP]);
    total_dissipation += info[B2B_INFO_DISSIPATION];
    friction_work += mu * fn * fabs(info[B2B_INFO_SLIP]);
    static const char *names[3] = {"-", "stick", "slip"};
    printf("| %d | %+.3f | %+.3f | %s | %+8.3f | %6.3f | %+.4f | %.5f | %s |\n", s, u[s],
           info[B2B_INFO_GAP], status == B2B_CONTACT_ACTIVE ? names[state] : "open", tx,
           mu * fn, info[B2B_INFO_SLIP], info[B2B_INFO_DISSIPATION], ok ? "agrees" : "DIFFERS");
    memcpy(hist_old, hist_new, (size_t)nhist * sizeof(double)); /* commit the step */
  }
  printf("\nTotal slip %.4f, dissipated energy %.6f, mu f_N x slip %.6f\n", total_slip,
         total_dissipation, friction_work);
  const int energy_ok = fabs(total_dissipation - friction_work) <= 1e-12 * friction_work;
  printf("Coulomb sequence: %s\n", agree && energy_ok ? "as predicted" : "NOT as predicted");
  free(hist_old);
  free(hist_new);
  b2b_params_destroy(&p);
  return agree && energy_ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
