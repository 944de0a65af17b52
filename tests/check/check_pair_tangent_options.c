/* The "tangent" option: each mode against its definition, on active
 * crossings of every pair of kinds, both laws, with and without friction
 * (after a committed step, so that the friction force is not zero):
 *   EXACT      the default, bit for bit
 *   SYMMETRIC  (K + K^T)/2 of the exact one, bit for bit
 *   MAIN       -f' G G^T with G = dg/dX = -residual / f_N (frictionless), to
 *              round-off; with friction the same as without
 *   FD         the exact tangent to 1e-6 (relative, central differences)
 * and in every mode the residual and info are those of EXACT (but for
 * B2B_INFO_SYMMETRIC). Also through the contact model: its FD tangent
 * against its exact one. And the tangent as b2b_pair_eval writes it into
 * the host's array (where both segments are linear in X it is expanded
 * there from the used rows and columns, src/pair/tangent_assembly.hpp):
 * every entry of the 24 x 24 block written, the rows and columns of the
 * slots no segment reads exactly zero, the padding rows of a larger ldk
 * untouched. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "model_support.h"

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

static b2b_params *with_mode(int law, double mu, int mode) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  ok(b2b_params_create(&p, msg, sizeof msg), msg);
  ok(b2b_params_set_real(p, "penalty", 1e3, msg, sizeof msg), msg);
  ok(b2b_params_set_int(p, "law", law, msg, sizeof msg), msg);
  if (law == B2B_LAW_QUADRATIC) ok(b2b_params_set_real(p, "regularization_gap", 0.02, msg, sizeof msg), msg);
  if (mu > 0) {
    ok(b2b_params_set_real(p, "friction", mu, msg, sizeof msg), msg);
    ok(b2b_params_set_real(p, "tangential_penalty", 2e3, msg, sizeof msg), msg);
  }
  ok(b2b_params_set_int(p, "tangent", mode, msg, sizeof msg), msg);
  ok(b2b_params_finalize(p, msg, sizeof msg), msg);
  return p;
}

START_TEST(each_mode_against_its_definition) {
  tst_rng rng;
  tst_rng_seed(&rng, 31337);
  double worst_main = 0, worst_fd = 0;
  int cases = 0;
  for (int law = 0; law < B2B_LAW_COUNT; ++law)
    for (int fr = 0; fr < 2; ++fr) {
      const double mu = fr ? 0.3 : 0.0;
      b2b_params *p[4];
      for (int mode = 0; mode < 4; ++mode) p[mode] = with_mode(law, mu, mode);
      b2b_params *p_default = with_mode(law, mu, B2B_TANGENT_EXACT);
      const int nh = tst_history_len(p[0]);
      for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
        for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb) {
          tst_pair_spec spec = {{ka, kb},
                                {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                                {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                                {0.1, 0.1}};
          double X[24], h0[16] = {0}, h1[16], info[32], r[24], K[576];
          tst_crossing(&rng, &spec, 0.2, tst_uniform(&rng, 30, 90), tst_uniform(&rng, -0.6, 0.6),
                       tst_uniform(&rng, -0.6, 0.6), 0.19, X);
          /* a committed step, then a slid configuration */
          ck_assert_int_eq(tst_pair(p[0], &spec, X, NULL, h1, info, r, NULL), B2B_CONTACT_ACTIVE);
          memcpy(h0, h1, sizeof(double) * nh);
          for (int k = 0; k < 12; k += 3) X[k] += 0.004;
          double Ke[576], re[24], ie[32];
          ck_assert_int_eq(tst_pair(p[0], &spec, X, h0, h1, ie, re, Ke), B2B_CONTACT_ACTIVE);
          /* EXACT is the default */
          ck_assert_int_eq(tst_pair(p_default, &spec, X, h0, h1, info, r, K), B2B_CONTACT_ACTIVE);
          ck_assert(memcmp(K, Ke, sizeof K) == 0);
          for (int mode = 1; mode < 4; ++mode) {
            ck_assert_int_eq(tst_pair(p[mode], &spec, X, h0, h1, info, r, K), B2B_CONTACT_ACTIVE);
            ck_assert(memcmp(r, re, sizeof r) == 0);
            for (int i = 0; i < 32; ++i)
              if (i != B2B_INFO_SYMMETRIC) ck_assert(info[i] == ie[i] || (isnan(info[i]) && isnan(ie[i])));
            if (mode == B2B_TANGENT_SYMMETRIC) {
              for (int c = 0; c < 24; ++c)
                for (int rr = 0; rr < 24; ++rr)
                  ck_assert(K[rr + 24 * c] == 0.5 * (Ke[rr + 24 * c] + Ke[c + 24 * rr]) ||
                            K[rr + 24 * c] == 0.5 * (Ke[c + 24 * rr] + Ke[rr + 24 * c]));
              ck_assert(info[B2B_INFO_SYMMETRIC] == 1.0);
            } else if (mode == B2B_TANGENT_MAIN) {
              /* G = -r / f_N of the frictionless residual; slope -eps for
               * g <= 0 under both laws */
              double rf[24], inf0[32], G[24], scale = 0.0, err = 0.0;
              b2b_params *p0 = with_mode(law, 0.0, B2B_TANGENT_EXACT);
              double hz[16] = {0}, hn[16];
              tst_pair(p0, &spec, X, hz, hn, inf0, rf, NULL);
              b2b_params_destroy(&p0);
              const double fn = inf0[B2B_INFO_NORMAL_FORCE], slope = -1e3;
              for (int i = 0; i < 24; ++i) G[i] = -rf[i] / fn;
              for (int c = 0; c < 24; ++c)
                for (int rr = 0; rr < 24; ++rr) {
                  const double want = -slope * G[rr] * G[c];
                  scale = fmax(scale, fabs(want));
                  err = fmax(err, fabs(K[rr + 24 * c] - want));
                }
              ck_assert_msg(inf0[B2B_INFO_GAP] <= 0.0, "the main-term check needs g <= 0");
              worst_main = fmax(worst_main, err / scale);
              ck_assert_msg(err <= 1e-12 * scale, "MAIN: %g relative", err / scale);
            } else {
              double scale = 0.0, err = 0.0;
              for (int i = 0; i < 576; ++i) {
                scale = fmax(scale, fabs(Ke[i]));
                err = fmax(err, fabs(K[i] - Ke[i]));
              }
              worst_fd = fmax(worst_fd, err / scale);
              ck_assert_msg(err <= 1e-6 * scale, "FD: %g relative", err / scale);
            }
          }
          ++cases;
        }
      for (int mode = 0; mode < 4; ++mode) b2b_params_destroy(&p[mode]);
      b2b_params_destroy(&p_default);
    }
  printf("tangent options: %d active crossings (16 kind pairs x 2 laws x with and without "
         "friction): SYMMETRIC and EXACT bit for bit as defined; MAIN = -f' G G^T to %.1e; "
         "FD against EXACT %.1e\n", cases, worst_main, worst_fd);
}
END_TEST

START_TEST(model_fd_against_exact) {
  char msg[B2B_ERRMSG_LEN] = "";
  tst_rng rng;
  tst_rng_seed(&rng, 99);
  tst_scene sc;
  tst_network(&rng, 30, 8, 0.5, 2.5, 0.1, 0.3, 5, 0, &sc);
  b2b_params *pe = with_mode(B2B_LAW_LINEAR, 0.3, B2B_TANGENT_EXACT);
  b2b_params *pf = with_mode(B2B_LAW_LINEAR, 0.3, B2B_TANGENT_FD);
  b2b_model *me = tst_model(&sc, pe, 1), *mf = tst_model(&sc, pf, 1);
  tst_update(me, &sc, 1);
  tst_update(mf, &sc, 1);
  int n, nf;
  ok(b2b_model_contact_count(me, &n, msg, sizeof msg), msg);
  ok(b2b_model_contact_count(mf, &nf, msg, sizeof msg), msg);
  ck_assert_int_eq(n, nf);
  ck_assert_int_ge(n, 10);
  double worst = 0;
  for (int c = 0; c < n; ++c) {
    double Ke[576], Kf[576], scale = 0, err = 0;
    ok(b2b_model_get_contact(me, c, NULL, NULL, NULL, NULL, Ke, 24, msg, sizeof msg), msg);
    ok(b2b_model_get_contact(mf, c, NULL, NULL, NULL, NULL, Kf, 24, msg, sizeof msg), msg);
    for (int i = 0; i < 576; ++i) {
      scale = fmax(scale, fabs(Ke[i]));
      err = fmax(err, fabs(Kf[i] - Ke[i]));
    }
    worst = fmax(worst, err / scale);
  }
  printf("model: %d contacts, FD tangent against the exact one %.1e\n", n, worst);
  ck_assert(worst <= 1e-6);
  b2b_model_destroy(&me);
  b2b_model_destroy(&mf);
  b2b_params_destroy(&pe);
  b2b_params_destroy(&pf);
  tst_scene_free(&sc);
}
END_TEST

/* b2b_pair_eval's tangent into an array of NaN with leading dimension ldk. */
static int eval_into_nan(const b2b_params *p, const tst_pair_spec *spec, const double X[24],
                         const double *h0, int ldk, double *K) {
  const int segments[6] = {spec->kind[0], spec->start_rule[0], spec->end_rule[0],
                           spec->kind[1], spec->start_rule[1], spec->end_rule[1]};
  double h1[64], info[32], r[24];
  int nh = 0, status = -1;
  char msg[B2B_ERRMSG_LEN] = "";
  ok(b2b_params_history_size(p, &nh, msg, sizeof msg), msg);
  for (int i = 0; i < ldk * 24; ++i) K[i] = NAN;
  ok(b2b_pair_eval(p, segments, X, NULL, spec->radius, h0, h1, nh, &status, info, r, K, ldk, msg,
                   sizeof msg),
     msg);
  return status;
}

START_TEST(written_whole) {
  enum { LD = 27 };
  tst_rng rng;
  tst_rng_seed(&rng, 4711);
  int zero_rows = 0;
  for (int fr = 0; fr < 2; ++fr)
    for (int mode = B2B_TANGENT_EXACT; mode <= B2B_TANGENT_SYMMETRIC; ++mode) {
      const double mu = fr ? 0.3 : 0.0;
      b2b_params *p = with_mode(B2B_LAW_LINEAR, mu, mode);
      b2b_params *pf = with_mode(B2B_LAW_LINEAR, mu, B2B_TANGENT_FD);
      const int nh = tst_history_len(p);
      for (int ka = 0; ka < B2B_CURVE_KIND_COUNT; ++ka)
        for (int kb = 0; kb < B2B_CURVE_KIND_COUNT; ++kb)
          for (int far = 0; far < 2; ++far) {
            tst_pair_spec spec = {{ka, kb},
                                  {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                                  {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                                  {0.1, 0.1}};
            double X[24], h0[16] = {0}, h1[16], info[32], r[24];
            tst_crossing(&rng, &spec, 0.2, tst_uniform(&rng, 30, 90), tst_uniform(&rng, -0.6, 0.6),
                         tst_uniform(&rng, -0.6, 0.6), far ? 0.5 : 0.19, X);
            const int expected = far ? B2B_CONTACT_OPEN : B2B_CONTACT_ACTIVE;
            ck_assert_int_eq(tst_pair(p, &spec, X, NULL, h1, info, r, NULL), expected);
            memcpy(h0, h1, sizeof(double) * nh);
            for (int k = 0; k < 12; k += 3) X[k] += 0.004;  /* a slip for friction */
            double K24[24 * 24], Kld[LD * 24], Kfd[24 * 24];
            ck_assert_int_eq(eval_into_nan(p, &spec, X, h0, 24, K24), expected);
            ck_assert_int_eq(eval_into_nan(p, &spec, X, h0, LD, Kld), expected);
            ck_assert_int_eq(eval_into_nan(pf, &spec, X, h0, 24, Kfd), expected);
            for (int c = 0; c < 24; ++c) {
              for (int rr = 0; rr < 24; ++rr) {
                const double k = K24[rr + 24 * c];
                ck_assert_msg(isfinite(k), "kinds %d %d: K(%d, %d) = %g", ka, kb, rr, c, k);
                ck_assert(memcmp(&k, &Kld[rr + LD * c], sizeof k) == 0);
                if (far) ck_assert_msg(k == 0.0, "open pair: K(%d, %d) = %g", rr, c, k);
              }
              for (int rr = 24; rr < LD; ++rr) ck_assert(isnan(Kld[rr + LD * c]));
            }
            if (far) continue;
            /* A coordinate of a slot neither segment reads: the FD tangent's
             * column is exactly zero (the residual does not move); so must
             * the exact tangent's row and column be. */
            for (int a = 0; a < 24; ++a) {
              int unread = 1;
              for (int rr = 0; rr < 24 && unread; ++rr) unread = Kfd[rr + 24 * a] == 0.0;
              if (!unread) continue;
              ++zero_rows;
              for (int i = 0; i < 24; ++i)
                ck_assert_msg(K24[i + 24 * a] == 0.0 && K24[a + 24 * i] == 0.0,
                              "kinds %d %d: coordinate %d is read by neither segment, but "
                              "K(%d, %d) = %g, K(%d, %d) = %g",
                              ka, kb, a, i, a, K24[i + 24 * a], a, i, K24[a + 24 * i]);
            }
          }
      b2b_params_destroy(&p);
      b2b_params_destroy(&pf);
    }
  /* every kind pair with linear or midpoint on a side has such coordinates */
  printf("written whole: %d coordinates read by neither segment, their rows and columns zero\n",
         zero_rows);
  ck_assert_int_ge(zero_rows, 100);
}
END_TEST

int main(void) {
  Suite *s = suite_create("pair_tangent_options");
  TCase *tc = tcase_create("tangent_options");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, each_mode_against_its_definition);
  tcase_add_test(tc, model_fd_against_exact);
  tcase_add_test(tc, written_whole);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
