#include "pair_support.h"

#include <math.h>
#include <string.h>

/* A parameter set with the normal law, not yet finalized. */
static b2b_params *normal_params(int law, double penalty, double g0) {
  b2b_params *p = NULL;
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_int_eq(b2b_params_create(&p, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", penalty, msg, sizeof msg), B2B_OK);
  ck_assert_int_eq(b2b_params_set_int(p, "law", law, msg, sizeof msg), B2B_OK);
  if (law == B2B_LAW_QUADRATIC)
    ck_assert_int_eq(b2b_params_set_real(p, "regularization_gap", g0, msg, sizeof msg), B2B_OK);
  return p;
}

static b2b_params *finalized(b2b_params *p) {
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_params_finalize(p, msg, sizeof msg) == B2B_OK, "finalize: %s", msg);
  return p;
}

b2b_params *tst_params(int law, double penalty, double g0) {
  return finalized(normal_params(law, penalty, g0));
}

static void cross(const double *a, const double *b, double *c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

static void unit(double *v) {
  const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int i = 0; i < 3; ++i) v[i] /= n;
}

/* Rotation (column-major) taking unit vector a to unit vector b (Rodrigues). */
static void rotation_between(const double *a, const double *b, double R[9]) {
  double k[3];
  cross(a, b, k);
  const double s = sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
  const double c = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) R[i + 3 * j] = (i == j) ? 1.0 : 0.0;
  if (s < 1e-14) {
    if (c < 0)  // half turn about any axis normal to a
      for (int j = 0; j < 9; ++j) R[j] = (j % 4 == 0) ? -1.0 : 0.0;
    return;
  }
  for (int i = 0; i < 3; ++i) k[i] /= s;
  const double K[9] = {0, k[2], -k[1], -k[2], 0, k[0], k[1], -k[0], 0};
  double K2[9];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      K2[i + 3 * j] = 0;
      for (int m = 0; m < 3; ++m) K2[i + 3 * j] += K[i + 3 * m] * K[m + 3 * j];
    }
  for (int j = 0; j < 9; ++j) R[j] += s * K[j] + (1 - c) * K2[j];
}

static void mask_unused(int kind, int sr, int er, double *patch) {
  unsigned used = 0x6u;
  switch (tst_kind_family(kind)) {
    case TST_CHORD:
      break;
    case TST_CENTRED:
      used = 0x2u | (sr == B2B_END_NEIGHBOUR ? 0x1u : 0u) | (er == B2B_END_NEIGHBOUR ? 0x4u : 0u);
      break;
    case TST_NODAL:
      used |= (sr == B2B_END_NEIGHBOUR ? 0x1u : 0u) | (er == B2B_END_NEIGHBOUR ? 0x8u : 0u);
      break;
  }
  for (int s = 0; s < 4; ++s)
    if (!(used & (1u << s)))
      for (int i = 0; i < 3; ++i) patch[3 * s + i] = NAN;
}

void tst_crossing(tst_rng *rng, const tst_pair_spec *spec, double max_turn, double angle_deg,
                  double xi_star, double eta_star, double dist, double X[24]) {
  double A[12], B[12], xa[9], xb[9];
  tst_random_patch(rng, 1.0, max_turn, A);
  tst_random_patch(rng, 1.0, max_turn, B);
  tst_eval(spec->kind[0], spec->start_rule[0], spec->end_rule[0], A, NULL, xi_star, xa, NULL,
           NULL);
  tst_eval(spec->kind[1], spec->start_rule[1], spec->end_rule[1], B, NULL, eta_star, xb, NULL,
           NULL);
  double ta[3] = {xa[3], xa[4], xa[5]}, tb[3] = {xb[3], xb[4], xb[5]}, u[3], r[3], n[3];
  unit(ta);
  unit(tb);
  do {  // u: a random unit vector normal to ta
    for (int i = 0; i < 3; ++i) r[i] = tst_uniform(rng, -1, 1);
    cross(ta, r, u);
  } while (u[0] * u[0] + u[1] * u[1] + u[2] * u[2] < 0.05);
  unit(u);
  const double th = angle_deg * 3.14159265358979323846 / 180.0;
  double target[3];
  for (int i = 0; i < 3; ++i) target[i] = cos(th) * ta[i] + sin(th) * u[i];
  cross(ta, u, n);  // normal to both ta and target
  double R[9];
  rotation_between(tb, target, R);
  memcpy(X, A, sizeof A);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i) {
      double v = 0;
      for (int j = 0; j < 3; ++j) v += R[i + 3 * j] * (B[3 * k + j] - xb[j]);
      X[12 + 3 * k + i] = v + xa[i] - dist * n[i];
    }
  mask_unused(spec->kind[0], spec->start_rule[0], spec->end_rule[0], X);
  mask_unused(spec->kind[1], spec->start_rule[1], spec->end_rule[1], X + 12);
}

int tst_pair(const b2b_params *params, const tst_pair_spec *spec, const double X[24],
             const double *hist_old, double *hist_new, double info[32], double residual[24],
             double *tangent) {
  const int segments[6] = {spec->kind[0], spec->start_rule[0], spec->end_rule[0],
                           spec->kind[1], spec->start_rule[1], spec->end_rule[1]};
  const double tangents[12] = {1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0};
  double fresh[64] = {0}, scratch[64];
  int n = 0, status = -1;
  ck_assert_int_eq(b2b_params_history_size(params, &n, NULL, 0), B2B_OK);
  char msg[B2B_ERRMSG_LEN] = "";
  const int st = b2b_pair_eval(params, segments, X, tangents, spec->radius,
                               hist_old ? hist_old : fresh, hist_new ? hist_new : scratch, n,
                               &status, info, residual, tangent, 24, msg, sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_pair_eval returned %d: %s", st, msg);
  return status;
}

b2b_params *tst_params_friction(int law, double penalty, double g0, double mu, double eps_t) {
  b2b_params *p = normal_params(law, penalty, g0);
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_params_set_real(p, "friction", mu, msg, sizeof msg) == B2B_OK, "friction: %s",
                msg);
  if (eps_t > 0)
    ck_assert_msg(b2b_params_set_real(p, "tangential_penalty", eps_t, msg, sizeof msg) == B2B_OK,
                  "tangential_penalty: %s", msg);
  return finalized(p);
}

b2b_params *tst_line_params(int law, int type, int tangent, const tst_line_spec *spec) {
  b2b_params *p = normal_params(law, spec->eps_n, 0.01);
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_params_set_int(p, "contact_type", type, msg, sizeof msg) == B2B_OK,
                "contact_type: %s", msg);
  ck_assert_msg(b2b_params_set_real(p, "line_penalty", spec->eps_l, msg, sizeof msg) == B2B_OK,
                "line_penalty: %s", msg);
  if (tangent >= 0)
    ck_assert_msg(b2b_params_set_int(p, "tangent", tangent, msg, sizeof msg) == B2B_OK,
                  "tangent: %s", msg);
  if (spec->mu > 0) {
    ck_assert_msg(b2b_params_set_real(p, "friction", spec->mu, msg, sizeof msg) == B2B_OK,
                  "friction: %s", msg);
    ck_assert_msg(b2b_params_set_real(p, "tangential_penalty", spec->eps_t, msg, sizeof msg) ==
                      B2B_OK,
                  "tangential_penalty: %s", msg);
    ck_assert_msg(
        b2b_params_set_real(p, "line_tangential_penalty", spec->eps_lt, msg, sizeof msg) == B2B_OK,
        "line_tangential_penalty: %s", msg);
  }
  return finalized(p);
}

int tst_history_len(const b2b_params *params) {
  int n = -1;
  char msg[B2B_ERRMSG_LEN] = "";
  ck_assert_msg(b2b_params_history_size(params, &n, msg, sizeof msg) == B2B_OK,
                "history_size: %s", msg);
  return n;
}

int tst_pair_ext(const b2b_params *params, const tst_pair_spec *spec, const double X[24],
                 const double end_tangents[12], const double *hist_old, double *hist_new,
                 double info[32], double residual[24], double *tangent) {
  const int segments[6] = {spec->kind[0], spec->start_rule[0], spec->end_rule[0],
                           spec->kind[1], spec->start_rule[1], spec->end_rule[1]};
  const double defaults[12] = {1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0};
  double fresh[64] = {0}, scratch[64];
  int n = tst_history_len(params), status = -1;
  char msg[B2B_ERRMSG_LEN] = "";
  const int st = b2b_pair_eval(params, segments, X, end_tangents ? end_tangents : defaults,
                               spec->radius, hist_old ? hist_old : fresh,
                               hist_new ? hist_new : scratch, n, &status, info, residual, tangent,
                               24, msg, sizeof msg);
  ck_assert_msg(st == B2B_OK, "b2b_pair_eval returned %d: %s", st, msg);
  return status;
}

double tst_tangent_rotation_error(const double Q[9], const double K1[576], const double K2[576]) {
  double err = 0;
  for (int bc = 0; bc < 8; ++bc)
    for (int br = 0; br < 8; ++br)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          double v = 0;
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
              v += Q[i + 3 * a] * K1[(3 * br + a) + 24 * (3 * bc + b)] * Q[j + 3 * b];
          err = fmax(err, fabs(K2[(3 * br + i) + 24 * (3 * bc + j)] - v));
        }
  return err;
}

double tst_asymmetry(const double K[576]) {
  double asym = 0.0;
  for (int c = 0; c < 24; ++c)
    for (int r = 0; r < c; ++r) asym = fmax(asym, fabs(K[r + 24 * c] - K[c + 24 * r]));
  return asym / fmax(tst_max_abs(K, 576), 1e-300);
}
