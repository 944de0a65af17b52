/* The thread-safety promise of b2b.h for the pair layer: one finalized
 * parameter set shared by 2, 3 and 4 threads that evaluate different pairs
 * at the same time gives, bit for bit, what a serial run gives.
 *
 * The jobs (seeded, built once in the main thread, read-only afterwards):
 * crossings of every pair of curve kinds, each evaluated
 *   - frictionless, with the tangent (both normal laws),
 *   - with Coulomb friction and the tangent, from a committed history of a
 *     previous step (so that the pair sticks or slips),
 *   - as one b2b_segment_eval of A's segment with all derivatives,
 *   - with a NaN coordinate (an error: status and message).
 * Threads take the jobs round-robin, several times over, all starting at a
 * barrier, and write into their own output slots; the main thread compares
 * every output (return code, contact status, info, residual, tangent, new
 * history, message, segment outputs) with memcmp. Check's assertions are not
 * thread-safe, so the threads only record. Built with -DB2B_TSAN=ON this
 * suite is the ThreadSanitizer run of CI. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pair_support.h"

#define N_JOBS 48
#define ROUNDS 3
#define HIST_MAX 64

typedef struct {
  int segments[6];
  double X[24], Xbad[24], radii[2];
  double hist_fric[HIST_MAX]; /* committed friction history (read-only) */
  double patch[12], xi;       /* A's segment for b2b_segment_eval */
  int law;                    /* 0: linear params, 1: quadratic params */
} job_t;

typedef struct {
  int rc[4], status[3];
  double info[3][32], residual[3][24], tangent[3][576], hist_new[3][HIST_MAX];
  double x[9], dx[72], d2x[864];
  char msg[3][B2B_ERRMSG_LEN];
} result_t;

static job_t jobs[N_JOBS];
static const b2b_params *params_law[2], *params_fric;
static int hist_len_plain, hist_len_fric;

/* Every output slot starts from the same bytes in both runs. */
static void clear(result_t *r) { memset(r, 0, sizeof *r); }

static void run_job(const job_t *j, result_t *r) {
  const double zeros[HIST_MAX] = {0};
  const b2b_params *p = params_law[j->law];
  r->rc[0] = b2b_pair_eval(p, j->segments, j->X, NULL, j->radii, zeros, r->hist_new[0],
                           hist_len_plain, &r->status[0], r->info[0], r->residual[0],
                           r->tangent[0], 24, r->msg[0], B2B_ERRMSG_LEN);
  r->rc[1] = b2b_pair_eval(params_fric, j->segments, j->X, NULL, j->radii, j->hist_fric,
                           r->hist_new[1], hist_len_fric, &r->status[1], r->info[1],
                           r->residual[1], r->tangent[1], 24, r->msg[1], B2B_ERRMSG_LEN);
  r->rc[2] = b2b_pair_eval(params_fric, j->segments, j->Xbad, NULL, j->radii, j->hist_fric,
                           r->hist_new[2], hist_len_fric, &r->status[2], r->info[2],
                           r->residual[2], r->tangent[2], 24, r->msg[2], B2B_ERRMSG_LEN);
  r->rc[3] = b2b_segment_eval(j->segments[0], j->segments[1], j->segments[2], j->patch, NULL,
                              j->xi, r->x, r->dx, r->d2x, NULL, 0);
}

static result_t serial[N_JOBS];
static result_t *threaded; /* [ROUNDS][N_JOBS] */

typedef struct {
  int id, n_threads;
  pthread_barrier_t *barrier;
} worker_t;

static void *worker(void *arg) {
  const worker_t *w = arg;
  pthread_barrier_wait(w->barrier);
  for (int round = 0; round < ROUNDS; ++round)
    /* Each round shifts which thread gets which job. */
    for (int j = (w->id + round) % w->n_threads; j < N_JOBS; j += w->n_threads)
      run_job(&jobs[j], &threaded[round * N_JOBS + j]);
  return NULL;
}

static void setup_jobs(void) {
  static b2b_params *owned[3];
  owned[0] = tst_params(B2B_LAW_LINEAR, 1e3, 0.0);
  owned[1] = tst_params(B2B_LAW_QUADRATIC, 1e3, 0.05);
  owned[2] = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.3, 1e3);
  params_law[0] = owned[0];
  params_law[1] = owned[1];
  params_fric = owned[2];
  hist_len_plain = tst_history_len(params_law[0]);
  ck_assert_int_eq(tst_history_len(params_law[1]), hist_len_plain);
  hist_len_fric = tst_history_len(params_fric);
  ck_assert(hist_len_plain <= HIST_MAX && hist_len_fric <= HIST_MAX);

  tst_rng rng;
  tst_rng_seed(&rng, 20240611u);
  for (int n = 0; n < N_JOBS; ++n) {
    job_t *j = &jobs[n];
    const int ka = TST_KIND_A(n), kb = TST_KIND_B(n);
    const tst_pair_spec spec = {{ka, kb}, {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR},
                                {B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR}, {0.2, 0.15}};
    const int segments[6] = {ka, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                             kb, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
    memcpy(j->segments, segments, sizeof segments);
    j->radii[0] = spec.radius[0];
    j->radii[1] = spec.radius[1];
    j->law = (n / 16) % 2;
    const double angle = tst_uniform(&rng, 20.0, 90.0);
    const double xi = tst_uniform(&rng, -0.6, 0.6), eta = tst_uniform(&rng, -0.6, 0.6);
    tst_crossing(&rng, &spec, 0.3, angle, xi, eta, 0.3, j->X);
    /* The committed friction step: A displaced along x by a little. */
    double X0[24], info[32], R[24];
    memcpy(X0, j->X, sizeof X0);
    for (int a = 0; a < 12; a += 3) X0[a] -= tst_uniform(&rng, 0.0, 0.03);
    tst_pair(params_fric, &spec, X0, NULL, j->hist_fric, info, R, NULL);
    memcpy(j->Xbad, j->X, sizeof j->Xbad);
    j->Xbad[4] = NAN; /* node 2 of A, y: read by every kind */
    memcpy(j->patch, j->X, sizeof j->patch);
    j->xi = tst_uniform(&rng, -1.0, 1.0);
  }
}

static void teardown_jobs(void) {
  b2b_params *p[3] = {(b2b_params *)params_law[0], (b2b_params *)params_law[1],
                      (b2b_params *)params_fric};
  for (int i = 0; i < 3; ++i) b2b_params_destroy(&p[i]);
}

/* The serial reference, and what it should look like: most pairs active,
 * some sliding, every bad call an error with a message. */
static void run_serial(void) {
  int active = 0, slip = 0, stick = 0;
  for (int n = 0; n < N_JOBS; ++n) {
    clear(&serial[n]);
    run_job(&jobs[n], &serial[n]);
    const result_t *r = &serial[n];
    ck_assert_msg(r->rc[0] == B2B_OK && r->rc[1] == B2B_OK && r->rc[3] == B2B_OK,
                  "job %d: %d %d %d: %s / %s", n, r->rc[0], r->rc[1], r->rc[3], r->msg[0],
                  r->msg[1]);
    ck_assert_int_eq(r->rc[2], B2B_ERR_NONFINITE);
    ck_assert_msg(strlen(r->msg[2]) > 0, "job %d: no message for the NaN coordinate", n);
    active += r->status[0] == B2B_CONTACT_ACTIVE;
    slip += r->info[1][B2B_INFO_FRICTION_STATE] == B2B_FRICTION_SLIP;
    stick += r->info[1][B2B_INFO_FRICTION_STATE] == B2B_FRICTION_STICK;
  }
  printf("check_pair_threads: %d jobs, %d active, friction: %d stick, %d slip\n", N_JOBS, active,
         stick, slip);
  ck_assert_msg(active >= N_JOBS / 2, "only %d of %d pairs active", active, N_JOBS);
  ck_assert_msg(stick > 0 && slip > 0, "stick %d, slip %d: both states wanted", stick, slip);
}

static void compare(int n_threads) {
  for (int round = 0; round < ROUNDS; ++round)
    for (int n = 0; n < N_JOBS; ++n) {
      const result_t *a = &serial[n], *b = &threaded[round * N_JOBS + n];
      ck_assert_msg(memcmp(a->rc, b->rc, sizeof a->rc) == 0 &&
                        memcmp(a->status, b->status, sizeof a->status) == 0,
                    "%d threads, round %d, job %d: status differs", n_threads, round, n);
      ck_assert_msg(memcmp(a->info, b->info, sizeof a->info) == 0 &&
                        memcmp(a->residual, b->residual, sizeof a->residual) == 0 &&
                        memcmp(a->tangent, b->tangent, sizeof a->tangent) == 0 &&
                        memcmp(a->hist_new, b->hist_new, sizeof a->hist_new) == 0,
                    "%d threads, round %d, job %d: pair outputs differ", n_threads, round, n);
      ck_assert_msg(memcmp(a->msg, b->msg, sizeof a->msg) == 0, "%d threads, job %d: messages",
                    n_threads, n);
      ck_assert_msg(memcmp(a->x, b->x, sizeof a->x) == 0 &&
                        memcmp(a->dx, b->dx, sizeof a->dx) == 0 &&
                        memcmp(a->d2x, b->d2x, sizeof a->d2x) == 0,
                    "%d threads, round %d, job %d: segment outputs differ", n_threads, round, n);
    }
}

START_TEST(threads_match_serial_bitwise) {
  const int n_threads = 2 + _i; /* 2, 3, 4 */
  setup_jobs();
  run_serial();
  threaded = malloc(sizeof(result_t) * ROUNDS * N_JOBS);
  ck_assert_ptr_nonnull(threaded);
  for (int i = 0; i < ROUNDS * N_JOBS; ++i) clear(&threaded[i]);
  pthread_barrier_t barrier;
  ck_assert_int_eq(pthread_barrier_init(&barrier, NULL, (unsigned)n_threads), 0);
  pthread_t tid[4];
  worker_t w[4];
  for (int t = 0; t < n_threads; ++t) {
    w[t] = (worker_t){t, n_threads, &barrier};
    ck_assert_int_eq(pthread_create(&tid[t], NULL, worker, &w[t]), 0);
  }
  for (int t = 0; t < n_threads; ++t) ck_assert_int_eq(pthread_join(tid[t], NULL), 0);
  pthread_barrier_destroy(&barrier);
  compare(n_threads);
  free(threaded);
  threaded = NULL;
  teardown_jobs();
}
END_TEST

int main(void) {
  Suite *s = suite_create("pair_threads");
  TCase *tc = tcase_create("threads");
  tcase_set_timeout(tc, 300);
  tcase_add_loop_test(tc, threads_match_serial_bitwise, 0, 3);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
