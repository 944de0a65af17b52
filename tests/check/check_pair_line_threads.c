/* b2b_pair_eval_line from several threads: one finalized parameter set per
 * option set, shared by 2 and 4 threads evaluating the same jobs at the
 * same time, gives bit for bit what a serial run gives (b2b.h's promise).
 *
 * Jobs (seeded, built in the main thread, read-only afterwards): pairs of
 * every curve kind touching nearly parallel and inside the blending range,
 * evaluated with LINE and ALL_ANGLE, frictionless and with friction from a
 * committed history (stick or slip), n_points over 1 .. 32, the tangent
 * options EXACT and FD, and one with a NaN coordinate (an error: code and
 * message). The threaded runs come before the serial reference (only the
 * friction jobs' first steps are evaluated before them). Threads start at
 * a barrier and take the jobs round-robin, several times over; the main
 * thread compares every output with memcmp. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "pair_support.h"

#define N_JOBS 40
#define ROUNDS 2
#define MAXP 32
#define MAXH ((MAXP + 1) * 12)

enum { P_LINE, P_ALL, P_LINE_FR, P_ALL_FR, P_FD, N_PARAMS };
static b2b_params *params[N_PARAMS];

typedef struct {
  int seg[6], n, which;
  double X[24], radii[2], hist[MAXH];
} job_t;

typedef struct {
  int rc, status;
  double li[16], pinfo[32 * MAXP], hist[MAXH], R[24], K[576];
  char msg[B2B_ERRMSG_LEN];
} result_t;

static job_t jobs[N_JOBS];
static result_t serial[N_JOBS];
static result_t threaded[4][N_JOBS];

static void run_job(const job_t *j, result_t *r) {
  memset(r, 0, sizeof *r);
  const b2b_params *p = params[j->which];
  int hs = 0;
  b2b_params_history_size(p, &hs, NULL, 0);
  r->rc = b2b_pair_eval_line(p, j->seg, j->X, NULL, j->radii, j->n, j->hist, r->hist,
                             (j->n + 1) * hs, &r->status, r->li, r->pinfo, r->R, r->K, 24,
                             r->msg, B2B_ERRMSG_LEN);
}

typedef struct {
  int id, n_threads;
  pthread_barrier_t *barrier;
} arg_t;

static void *worker(void *v) {
  const arg_t *a = v;
  pthread_barrier_wait(a->barrier);
  for (int round = 0; round < ROUNDS; ++round)
    for (int k = a->id; k < N_JOBS; k += a->n_threads) run_job(&jobs[k], &threaded[a->id][k]);
  return NULL;
}

static b2b_params *make(int type, int friction, int tangent) {
  b2b_params *p = NULL;
  char msg[B2B_ERRMSG_LEN];
  ck_assert(b2b_params_create(&p, msg, sizeof msg) == B2B_OK);
  ck_assert(b2b_params_set_real(p, "penalty", 1e3, msg, sizeof msg) == B2B_OK);
  ck_assert(b2b_params_set_int(p, "contact_type", type, msg, sizeof msg) == B2B_OK);
  ck_assert(b2b_params_set_real(p, "line_penalty", 2e3, msg, sizeof msg) == B2B_OK);
  ck_assert(b2b_params_set_int(p, "tangent", tangent, msg, sizeof msg) == B2B_OK);
  if (friction) {
    ck_assert(b2b_params_set_real(p, "friction", 0.3, msg, sizeof msg) == B2B_OK);
    ck_assert(b2b_params_set_real(p, "tangential_penalty", 800, msg, sizeof msg) == B2B_OK);
    ck_assert(b2b_params_set_real(p, "line_tangential_penalty", 1500, msg, sizeof msg) ==
              B2B_OK);
  }
  ck_assert_msg(b2b_params_finalize(p, msg, sizeof msg) == B2B_OK, "%s", msg);
  return p;
}

START_TEST(threads_bit_identical) {
  params[P_LINE] = make(B2B_CONTACT_TYPE_LINE, 0, B2B_TANGENT_EXACT);
  params[P_ALL] = make(B2B_CONTACT_TYPE_ALL_ANGLE, 0, B2B_TANGENT_EXACT);
  params[P_LINE_FR] = make(B2B_CONTACT_TYPE_LINE, 1, B2B_TANGENT_EXACT);
  params[P_ALL_FR] = make(B2B_CONTACT_TYPE_ALL_ANGLE, 1, B2B_TANGENT_EXACT);
  params[P_FD] = make(B2B_CONTACT_TYPE_ALL_ANGLE, 1, B2B_TANGENT_FD);
  tst_rng rng;
  tst_rng_seed(&rng, 51001);
  int active = 0;
  for (int k = 0; k < N_JOBS; ++k) {
    job_t *j = &jobs[k];
    tst_pair_spec s = {{TST_KIND_A(k), TST_KIND_B(k)}, {0, 0}, {0, 0}, {0.1, 0.1}};
    for (int b = 0; b < 2; ++b) {
      j->seg[3 * b] = s.kind[b];
      j->seg[3 * b + 1] = j->seg[3 * b + 2] = B2B_END_NEIGHBOUR;
      j->radii[b] = s.radius[b];
    }
    j->which = k % N_PARAMS;
    j->n = 1 + (k * 13) % MAXP;
    const double angle = (j->which == P_ALL || j->which >= P_ALL_FR) ? tst_uniform(&rng, 6, 14)
                                                                     : tst_uniform(&rng, 0, 3);
    tst_crossing(&rng, &s, 0.05, angle, tst_uniform(&rng, -0.3, 0.3),
                 tst_uniform(&rng, -0.3, 0.3), 0.2 - tst_uniform(&rng, 0.005, 0.02), j->X);
    memset(j->hist, 0, sizeof j->hist);
    if (j->which == P_LINE_FR || j->which >= P_ALL_FR) {
      /* a committed step, then B slid along x (stick or slip) */
      result_t first;
      run_job(j, &first);
      memcpy(j->hist, first.hist, sizeof j->hist);
      for (int a = 12; a < 24; ++a)
        if (!isnan(j->X[a]) && a % 3 == 0) j->X[a] += (k % 2) ? 2e-2 : 1e-5;
    }
    if (k == N_JOBS - 1) j->X[4] = NAN; /* an error */
  }
  static const int counts[2] = {2, 4};
  static result_t runs[2][N_JOBS];
  for (int c = 0; c < 2; ++c) {
    const int nt = counts[c];
    pthread_t th[4];
    arg_t args[4];
    pthread_barrier_t barrier;
    pthread_barrier_init(&barrier, NULL, (unsigned)nt);
    for (int t = 0; t < nt; ++t) {
      args[t].id = t;
      args[t].n_threads = nt;
      args[t].barrier = &barrier;
      ck_assert(pthread_create(&th[t], NULL, worker, &args[t]) == 0);
    }
    for (int t = 0; t < nt; ++t) pthread_join(th[t], NULL);
    pthread_barrier_destroy(&barrier);
    for (int k = 0; k < N_JOBS; ++k) runs[c][k] = threaded[k % nt][k];
  }
  /* the serial reference, after the threads */
  for (int k = 0; k < N_JOBS; ++k) {
    run_job(&jobs[k], &serial[k]);
    if (serial[k].rc == B2B_OK && serial[k].status == B2B_CONTACT_ACTIVE) ++active;
  }
  ck_assert_msg(serial[N_JOBS - 1].rc == B2B_ERR_NONFINITE, "the NaN job returned %d",
                serial[N_JOBS - 1].rc);
  ck_assert_msg(active >= N_JOBS / 2, "only %d of %d jobs active", active, N_JOBS);
  for (int c = 0; c < 2; ++c) {
    int differ = -1;
    for (int k = 0; k < N_JOBS && differ < 0; ++k)
      if (memcmp(&runs[c][k], &serial[k], sizeof(result_t)) != 0) differ = k;
    ck_assert_msg(differ < 0, "%d threads: job %d (n %d, params %d) differs from the serial run",
                  counts[c], differ, differ >= 0 ? jobs[differ].n : 0,
                  differ >= 0 ? jobs[differ].which : 0);
  }
  printf("line element on 2 and 4 threads: %d jobs (%d active), bit-identical to serial\n",
         N_JOBS, active);
  for (int i = 0; i < N_PARAMS; ++i) b2b_params_destroy(&params[i]);
}
END_TEST

int main(void) {
  Suite *s = suite_create("pair_line_threads");
  TCase *tc = tcase_create("threads");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, threads_bit_identical);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
