/* The model's update on 1 and 2 threads (option "threads"): on a network
 * large enough that the narrow phase, the segment builds and the search run
 * in parallel, every output is bit for bit the same, over several committed
 * steps with friction, and so is the order of the contacts. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_support.h"

#define CAP (64u << 20)

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

START_TEST(one_and_two_threads_agree) {
  char msg[B2B_ERRMSG_LEN] = "";
  tst_rng rng;
  tst_rng_seed(&rng, 2024);
  tst_scene sc;
  /* Quick mode (valgrind, where the threads run one after the other anyway):
   * the same 500 fibres in a cube of side 12 instead of 5, so about a ninth
   * of the pairs (6680 evaluated per update instead of 61237); still over
   * 4096 segments (the search's two chunks), over 2048 (the parallel segment
   * loops) and, asserted below, over 1024 evaluated pairs (the parallel
   * narrow phase). */
  tst_network(&rng, 500, 10, 0.3, tst_quick() ? 12.0 : 5.0, 0.08, 0.3, 9, 4, &sc);
  b2b_params *p = tst_params_friction(B2B_LAW_LINEAR, 1e3, 0.0, 0.3, 1e3);
  b2b_model *m[2] = {tst_model(&sc, p, 1), tst_model(&sc, p, 1)};
  ok(b2b_model_set_int(m[0], "threads", 1, msg, sizeof msg), msg);
  ok(b2b_model_set_int(m[1], "threads", 2, msg, sizeof msg), msg);
  unsigned char *r[2] = {malloc(CAP), malloc(CAP)};
  double *v = malloc(sizeof(double) * 3 * sc.n_nodes);
  for (int k = 0; k < 3 * sc.n_nodes; ++k) v[k] = tst_uniform(&rng, -0.01, 0.01);
  int contacts = 0, evaluated = 0;
  for (int step = 0; step < 4; ++step) {
    size_t n[2];
    for (int t = 0; t < 2; ++t) {
      tst_update(m[t], &sc, 1);
      n[t] = tst_model_record(m[t], 1, r[t], CAP);
      ok(b2b_model_commit(m[t], msg, sizeof msg), msg);
    }
    ck_assert_msg(n[0] == n[1] && memcmp(r[0], r[1], n[0]) == 0,
                  "step %d: 1 and 2 threads differ", step);
    int counts[16];
    ok(b2b_model_stats(m[1], counts, NULL, msg, sizeof msg), msg);
    contacts += counts[B2B_COUNT_ACTIVE];
    if (counts[B2B_COUNT_EVALUATED] > evaluated) evaluated = counts[B2B_COUNT_EVALUATED];
    tst_scene_move(&sc, v, 1.0);
  }
  printf("threads: 4 steps, %d segments, up to %d pairs evaluated per update, %d active "
         "contacts in all: 1 and 2 threads bit for bit equal\n", 9 * 500, evaluated, contacts);
  /* enough pairs that the narrow phase really ran in parallel (see update.cpp) */
  ck_assert_int_ge(evaluated, 1024);
  free(r[0]);
  free(r[1]);
  free(v);
  b2b_model_destroy(&m[0]);
  b2b_model_destroy(&m[1]);
  b2b_params_destroy(&p);
  tst_scene_free(&sc);
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_threads");
  TCase *tc = tcase_create("threads");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, one_and_two_threads_agree);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
