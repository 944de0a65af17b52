/* The cost of line contact (b2b_pair_eval_line), per segment pair and per
 * integration point, against the point element (b2b_pair_eval) on the
 * same curve kind: what a scene pays for modelling nearly parallel beams
 * with lines.
 *
 *   line_cost_study [--quick]
 *
 * Configurations: two arcs (radius 20, element length 1) lying side by
 * side at angles of 0 to 3 degrees, pressed together along their length
 * (every integration point active: the axes 0.30 apart at their closest,
 * radii 0.2 and 0.15), both beams of one kind; for the point element the
 * same arcs crossing at 30 to 90 degrees. Each variant is timed interleaved with the others, best of
 * several trials (--quick: the ctest smoke test, few trials). Columns: the
 * point element's residual + tangent; the line element with 4, 8 and 16
 * points, residual + tangent per pair and per point; the per-point cost
 * over the point element's (what one integration point costs, in point
 * evaluations); the all-angle blend at 10 degrees (point and line part
 * both evaluated) with 8 points.
 * Checks (exit status 1; timings never fail it): every evaluation succeeds
 * and is active, and on each configuration the exact tangent agrees with
 * the library's own finite differences (B2B_TANGENT_FD) to 1e-5. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <b2b/b2b.h>

#define N_KINDS 4
#define N_CONFIGS 8
#define MAX_POINTS 16
static const int kKinds[N_KINDS] = {B2B_CURVE_LINEAR, B2B_CURVE_HERMITE_MIDPOINT,
                                    B2B_CURVE_HERMITE_NODAL, B2B_CURVE_HERMITE_NODAL_WEIGHTED};
static const char *kNames[N_KINDS] = {"linear", "hermite-midpoint", "hermite-nodal",
                                      "hermite-nodal-weighted"};
static const int kPoints[3] = {4, 8, 16};
static const double kPi = 3.14159265358979323846;

static void check(int st, const char *what, const char *msg) {
  if (st != B2B_OK) {
    fprintf(stderr, "line_cost_study: %s failed: %s\n", what, msg);
    exit(EXIT_FAILURE);
  }
}

static double now_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return 1e9 * (double)ts.tv_sec + (double)ts.tv_nsec;
}

/* Two arcs of radius 20 in planes through z, A bulging up, B bulging down
 * below it, B's plane turned by angle_deg about z, the axes gap_mid apart
 * at their closest, a quarter element before the middle of the patch
 * (where the nodal segment x2-x3 and the midpoint segment around x2
 * overlap; within both segments the axes stay within 0.33 of each other,
 * below the radii's 0.35: every integration point is active). */
static void make_arcs(double angle_deg, double gap_mid, double X[24]) {
  const double th = angle_deg * kPi / 180.0;
  for (int k = 0; k < 4; ++k) {
    const double t = (k - 1.25) / 20.0;
    X[3 * k] = 20.0 * sin(t);
    X[3 * k + 1] = 0.0;
    X[3 * k + 2] = 20.0 * (1.0 - cos(t)) + gap_mid;
    const double u = 20.0 * sin(t), w = -20.0 * (1.0 - cos(t));
    X[12 + 3 * k] = u * cos(th);
    X[12 + 3 * k + 1] = u * sin(th);
    X[12 + 3 * k + 2] = w;
  }
}

static b2b_params *params_of(int type, int tangent) {
  b2b_params *p = NULL;
  char msg[B2B_ERRMSG_LEN] = "";
  check(b2b_params_create(&p, msg, sizeof msg), "params_create", msg);
  check(b2b_params_set_real(p, "penalty", 1e3, msg, sizeof msg), "penalty", msg);
  check(b2b_params_set_int(p, "contact_type", type, msg, sizeof msg), "contact_type", msg);
  check(b2b_params_set_real(p, "line_penalty", 1e3, msg, sizeof msg), "line_penalty", msg);
  check(b2b_params_set_int(p, "tangent", tangent, msg, sizeof msg), "tangent", msg);
  check(b2b_params_finalize(p, msg, sizeof msg), "finalize", msg);
  return p;
}

static double sink;

/* One b2b_pair_eval_line; returns its status. */
static int eval_line(const b2b_params *p, const int seg[6], const double X[24], int n, double *R,
                     double *K) {
  static double h0[(MAX_POINTS + 1) * 8], h1[(MAX_POINTS + 1) * 8];
  double li[16];
  const double radii[2] = {0.2, 0.15};
  int status;
  char msg[B2B_ERRMSG_LEN] = "";
  check(b2b_pair_eval_line(p, seg, X, NULL, radii, n, h0, h1, (n + 1) * 8, &status, li, NULL, R,
                           K, 24, msg, sizeof msg),
        "b2b_pair_eval_line", msg);
  sink += R[0];
  return status;
}

static int eval_point(const b2b_params *p, const int seg[6], const double X[24], double *R,
                      double *K) {
  double h0[8] = {0}, h1[8], info[32];
  const double radii[2] = {0.2, 0.15};
  int status;
  char msg[B2B_ERRMSG_LEN] = "";
  check(b2b_pair_eval(p, seg, X, NULL, radii, h0, h1, 8, &status, info, R, K, 24, msg,
                      sizeof msg),
        "b2b_pair_eval", msg);
  sink += R[0];
  return status;
}

int main(int argc, char **argv) {
  const int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
  const int trials = quick ? 2 : 7, reps = quick ? 20 : 400;
  b2b_params *pline = params_of(B2B_CONTACT_TYPE_LINE, B2B_TANGENT_EXACT);
  b2b_params *pfd = params_of(B2B_CONTACT_TYPE_LINE, B2B_TANGENT_FD);
  b2b_params *pall = params_of(B2B_CONTACT_TYPE_ALL_ANGLE, B2B_TANGENT_EXACT);
  b2b_params *ppoint = params_of(B2B_CONTACT_TYPE_POINT, B2B_TANGENT_EXACT);
  double best[N_KINDS][5];
  double worst_fd = 0.0;
  for (int k = 0; k < N_KINDS; ++k) {
    const int seg[6] = {kKinds[k], B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                        kKinds[k], B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
    double Xl[N_CONFIGS][24], Xp[N_CONFIGS][24], Xb[N_CONFIGS][24];
    for (int j = 0; j < N_CONFIGS; ++j) {
      make_arcs(3.0 * j / (N_CONFIGS - 1), 0.30, Xl[j]);
      make_arcs(30.0 + 60.0 * j / (N_CONFIGS - 1), 0.30, Xp[j]);
      make_arcs(10.0, 0.30, Xb[j]);
    }
    /* checks: active, and the exact tangent against the FD option */
    for (int j = 0; j < N_CONFIGS; ++j) {
      double R[24], K[576], Kf[576];
      if (eval_line(pline, seg, Xl[j], 8, R, K) != B2B_CONTACT_ACTIVE ||
          eval_point(ppoint, seg, Xp[j], R, K) != B2B_CONTACT_ACTIVE ||
          eval_line(pall, seg, Xb[j], 8, R, K) != B2B_CONTACT_ACTIVE) {
        fprintf(stderr, "line_cost_study: %s configuration %d is not active\n", kNames[k], j);
        return EXIT_FAILURE;
      }
      eval_line(pline, seg, Xl[j], 8, R, K);
      eval_line(pfd, seg, Xl[j], 8, R, Kf);
      double d = 0.0, m = 0.0;
      for (int i = 0; i < 576; ++i) {
        d = fmax(d, fabs(K[i] - Kf[i]));
        m = fmax(m, fabs(K[i]));
      }
      worst_fd = fmax(worst_fd, d / m);
      if (d > 1e-5 * m) {
        fprintf(stderr, "line_cost_study: %s configuration %d: tangent vs FD %.2e\n", kNames[k],
                j, d / m);
        return EXIT_FAILURE;
      }
    }
    for (int v = 0; v < 5; ++v) best[k][v] = HUGE_VAL;
    for (int t = 0; t < trials; ++t)
      for (int v = 0; v < 5; ++v) {
        double R[24], K[576];
        const double t0 = now_ns();
        for (int r = 0; r < reps; ++r)
          for (int j = 0; j < N_CONFIGS; ++j) {
            if (v == 0) eval_point(ppoint, seg, Xp[j], R, K);
            else if (v <= 3) eval_line(pline, seg, Xl[j], kPoints[v - 1], R, K);
            else eval_line(pall, seg, Xb[j], 8, R, K);
          }
        best[k][v] = fmin(best[k][v], (now_ns() - t0) / (reps * N_CONFIGS));
      }
  }
  printf("Cost of line contact, residual + tangent, %d configurations per kind (best of %d "
         "trials)\n\n",
         N_CONFIGS, trials);
  printf("| kind | point element [ns] | line, 4 points [ns] | 8 points [ns] | 16 points [ns] | "
         "per point, 16 [ns] | per point / point element | all-angle, 8 points [ns] |\n");
  printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int k = 0; k < N_KINDS; ++k)
    printf("| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.2f | %.0f |\n", kNames[k], best[k][0],
           best[k][1], best[k][2], best[k][3], best[k][3] / 16.0,
           best[k][3] / 16.0 / best[k][0], best[k][4]);
  printf("\nexact tangent vs the library's finite differences (8 points): worst %.2e\n",
         worst_fd);
  if (sink == 1.2345) printf(" ");
  b2b_params_destroy(&pline);
  b2b_params_destroy(&pfd);
  b2b_params_destroy(&pall);
  b2b_params_destroy(&ppoint);
  return EXIT_SUCCESS;
}
