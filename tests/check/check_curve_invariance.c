/* Invariance: moving a patch rigidly (rotation Q, translation t) and scaling
 * it by s moves the curve with it, x' = s Q x + t, and transforms every
 * derivative accordingly; to round-off relative to the coordinates, also at
 * coordinates offset by 1e6 and at scales 1e-6 and 1e6. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"

/* A random rotation matrix (column-major) from a random unit quaternion. */
static void random_rotation(tst_rng *rng, double Q[9]) {
  double q[4], n = 0;
  for (int i = 0; i < 4; ++i) {
    q[i] = tst_uniform(rng, -1, 1);
    n += q[i] * q[i];
  }
  n = sqrt(n);
  const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
  const double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z),     2 * (x * z - w * y),
                       2 * (x * y - w * z),     1 - 2 * (x * x + z * z), 2 * (y * z + w * x),
                       2 * (x * z + w * y),     2 * (y * z - w * x),     1 - 2 * (x * x + y * y)};
  memcpy(Q, R, sizeof R);
}

typedef struct {
  double scale, offset;
} frame_t;

static double worst;

/* Checks one patch in one frame for one kind and rule set. */
static void check_case(tst_rng *rng, int kind, int sr, int er, frame_t f) {
  double patch[12], tangents[6], Q[9], t[3], moved[12], mtan[6];
  tst_random_patch(rng, 1.0, 0.8, patch);
  for (int i = 0; i < 6; ++i) tangents[i] = tst_uniform(rng, -1, 1);
  random_rotation(rng, Q);
  double dir[3] = {tst_uniform(rng, -1, 1), tst_uniform(rng, -1, 1), tst_uniform(rng, -1, 1)};
  const double nd = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  for (int i = 0; i < 3; ++i) t[i] = f.offset * dir[i] / nd;
  for (int k = 0; k < 4; ++k) {
    tst_rotate(Q, patch + 3 * k, moved + 3 * k);
    for (int i = 0; i < 3; ++i) moved[3 * k + i] = f.scale * moved[3 * k + i] + t[i];
  }
  tst_rotate(Q, tangents, mtan);
  tst_rotate(Q, tangents + 3, mtan + 3);

  /* Round-off of the moved coordinates, relative to the patch size s. */
  const double eps = 2.220446049250313e-16;
  const double rel_tol = 256 * eps * (1.0 + f.offset / f.scale);

  const double xi = tst_uniform(rng, -1.2, 1.2);
  static double x[9], dx[72], d2x[864], y[9], dy[72], d2y[864];
  tst_eval(kind, sr, er, patch, tangents, xi, x, dx, d2x);
  tst_eval(kind, sr, er, moved, mtan, xi, y, dy, d2y);

  /* points: y = s Q x + t; xi-derivatives: s Q x' */
  double want[9];
  for (int c = 0; c < 3; ++c) {
    tst_rotate(Q, x + 3 * c, want + 3 * c);
    for (int i = 0; i < 3; ++i) want[3 * c + i] = f.scale * want[3 * c + i] + (c == 0 ? t[i] : 0);
  }
  double e = 0;
  for (int i = 0; i < 9; ++i) e = fmax(e, fabs(y[i] - want[i]) / f.scale);
  worst = fmax(worst, e / rel_tol);
  ck_assert_msg(e <= rel_tol, "%s frame (s=%g, t=%g): point moved wrongly, rel. error %g",
                tst_kind_name(kind), f.scale, f.offset, e);

  /* first derivatives: each 3x3 block B_k = dx/dx_k becomes Q B_k Q^T (scale-free) */
  double dwant[72];
  for (int w = 0; w < 2; ++w)
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          double v = 0;
          for (int p = 0; p < 3; ++p)
            for (int q = 0; q < 3; ++q)
              v += Q[i + 3 * p] * dx[36 * w + p + 3 * (3 * k + q)] * Q[j + 3 * q];
          dwant[36 * w + i + 3 * (3 * k + j)] = v;
        }
  e = tst_rel_diff(dy, dwant, 72, 1.0);
  worst = fmax(worst, e / rel_tol);
  ck_assert_msg(e <= rel_tol, "%s frame (s=%g, t=%g): dx/dX rotated wrongly, rel. error %g",
                tst_kind_name(kind), f.scale, f.offset, e);

  /* second derivatives: rotate all three indices, scale by 1/s */
  static double d2want[864];
  for (int w = 0; w < 2; ++w)
    for (int b = 0; b < 12; ++b)
      for (int a = 0; a < 12; ++a)
        for (int i = 0; i < 3; ++i) {
          double v = 0;
          const int ka = a / 3, ja = a % 3, kb = b / 3, jb = b % 3;
          for (int p = 0; p < 3; ++p)
            for (int qa = 0; qa < 3; ++qa)
              for (int qb = 0; qb < 3; ++qb)
                v += Q[i + 3 * p] * Q[ja + 3 * qa] * Q[jb + 3 * qb] *
                     d2x[432 * w + p + 3 * ((3 * ka + qa) + 12 * (3 * kb + qb))];
          d2want[432 * w + i + 3 * (a + 12 * b)] = v / f.scale;
        }
  e = tst_rel_diff(d2y, d2want, 864, 1.0 / f.scale);
  worst = fmax(worst, e / rel_tol);
  ck_assert_msg(e <= rel_tol, "%s frame (s=%g, t=%g): d2x/dX2 transformed wrongly, rel. error %g",
                tst_kind_name(kind), f.scale, f.offset, e);
}

static void check_frame(frame_t f, uint64_t seed) {
  tst_rng rng;
  tst_rng_seed(&rng, seed);
  worst = 0;
  const int rules[4][2] = {{B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                           {B2B_END_REFLECT, B2B_END_NEIGHBOUR},
                           {B2B_END_NEIGHBOUR, B2B_END_TANGENT},
                           {B2B_END_TANGENT, B2B_END_NEIGHBOUR}};
  for (int kind = 0; kind < B2B_CURVE_KIND_COUNT; ++kind)
    for (int r = 0; r < 4; ++r)
      for (int rep = 0; rep < 5; ++rep) check_case(&rng, kind, rules[r][0], rules[r][1], f);
  printf("frame scale %g offset %g: worst error %.2f x the round-off tolerance\n", f.scale,
         f.offset, worst);
}

START_TEST(rigid_motion) { check_frame((frame_t){1.0, 3.0}, 51); }
END_TEST

START_TEST(offset_1e6) { check_frame((frame_t){1.0, 1e6}, 52); }
END_TEST

START_TEST(scale_1e_minus_6) { check_frame((frame_t){1e-6, 0.0}, 53); }
END_TEST

START_TEST(scale_1e6) { check_frame((frame_t){1e6, 0.0}, 54); }
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("curve_invariance");
  TCase *tc = tcase_create("frames");
  tcase_add_test(tc, rigid_motion);
  tcase_add_test(tc, offset_1e6);
  tcase_add_test(tc, scale_1e_minus_6);
  tcase_add_test(tc, scale_1e6);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
