/* Commit, revert and restart of the contact model, with friction (so the
 * committed histories matter) on a fibre network whose nodes drift so that
 * contacts slide, open and close:
 *  - a step that is tried, reverted (a host's cut-back) and then taken
 *    smaller gives, from there on, bit for bit the results of never having
 *    tried it;
 *  - a model restored from a saved buffer continues bit for bit as the
 *    original, and saves the same bytes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_support.h"

#define CAP (8u << 20)
#define STEPS 10

static void ok(int st, const char *msg) { ck_assert_msg(st == B2B_OK, "status %d: %s", st, msg); }

typedef struct {
  tst_scene sc;
  double *x0, *v;
  b2b_params *p;
} drift;

static void drift_setup(drift *d, uint64_t seed) {
  tst_rng rng;
  tst_rng_seed(&rng, seed);
  /* quick mode: 20 fibres in the same cube (rings and self-contact among
   * them), about a quarter of the pairs */
  tst_network(&rng, tst_quick() ? 20 : 40, 9, 0.5, 2.5, 0.1, 0.3, 6, 2, &d->sc);
  const size_t n = 3 * (size_t)d->sc.n_nodes;
  d->x0 = malloc(n * sizeof(double));
  d->v = malloc(n * sizeof(double));
  memcpy(d->x0, d->sc.x, n * sizeof(double));
  /* each fibre drifts rigidly, plus a little noise per node */
  for (int b = 0; b < d->sc.n_beams; ++b) {
    double w[3];
    for (int i = 0; i < 3; ++i) w[i] = tst_uniform(&rng, -0.03, 0.03);
    for (int k = d->sc.first[b]; k < d->sc.first[b] + d->sc.count[b]; ++k)
      for (int i = 0; i < 3; ++i) d->v[3 * k + i] = w[i] + tst_uniform(&rng, -0.002, 0.002);
  }
  d->p = tst_params_friction(B2B_LAW_QUADRATIC, 1e3, 0.02, 0.3, 1.5e3);
}

static void drift_free(drift *d) {
  free(d->x0);
  free(d->v);
  b2b_params_destroy(&d->p);
  tst_scene_free(&d->sc);
}

/* The scene at load step s (a fraction f of the way to s + 1). */
static void at(drift *d, double s) {
  memcpy(d->sc.x, d->x0, 3 * (size_t)d->sc.n_nodes * sizeof(double));
  tst_scene_move(&d->sc, d->v, s);
}

/* A step as a host's Newton loop makes it: two iterations, the first a bit
 * off the final state, then commit; records the last update. */
static size_t take_step(b2b_model *m, drift *d, double s, unsigned char *rec) {
  char msg[B2B_ERRMSG_LEN] = "";
  at(d, s + 0.1);
  tst_update(m, &d->sc, 1);
  at(d, s);
  tst_update(m, &d->sc, 1);
  const size_t n = tst_model_record(m, 1, rec, CAP);
  ok(b2b_model_commit(m, msg, sizeof msg), msg);
  return n;
}

START_TEST(cut_back_is_as_if_never_tried) {
  char msg[B2B_ERRMSG_LEN] = "";
  drift d;
  drift_setup(&d, 77);
  b2b_model *ref = tst_model(&d.sc, d.p, 1), *cut = tst_model(&d.sc, d.p, 1);
  unsigned char *r1 = malloc(CAP), *r2 = malloc(CAP);
  int contacts = 0, compared = 0;
  for (int step = 1; step <= STEPS; ++step) {
    const size_t n1 = take_step(ref, &d, step, r1);
    if (step == 4 || step == 7) {
      /* a failed attempt: a step four times too long, two iterations, revert */
      at(&d, step + 3.0);
      tst_update(cut, &d.sc, 1);
      at(&d, step + 4.0);
      tst_update(cut, &d.sc, 0);
      ok(b2b_model_revert(cut, msg, sizeof msg), msg);
      int n;
      ck_assert_int_eq(b2b_model_contact_count(cut, &n, msg, sizeof msg), B2B_ERR_STATE);
      ck_assert_int_eq(b2b_model_commit(cut, msg, sizeof msg), B2B_ERR_STATE);
    }
    const size_t n2 = take_step(cut, &d, step, r2);
    ck_assert_msg(n1 == n2 && memcmp(r1, r2, n1) == 0, "step %d differs after a cut-back", step);
    int c;
    ok(b2b_model_contact_count(ref, &c, msg, sizeof msg), msg);
    contacts += c;
    ++compared;
  }
  int counts[16];
  ok(b2b_model_stats(ref, counts, NULL, msg, sizeof msg), msg);
  printf("cut-back: %d steps with %d active contacts in all (slip and stick) compared bit for "
         "bit\n", compared, contacts);
  ck_assert_int_ge(contacts, 30);
  free(r1);
  free(r2);
  b2b_model_destroy(&ref);
  b2b_model_destroy(&cut);
  drift_free(&d);
}
END_TEST

START_TEST(restore_continues_bit_for_bit) {
  char msg[B2B_ERRMSG_LEN] = "";
  drift d;
  drift_setup(&d, 91);
  b2b_model *orig = tst_model(&d.sc, d.p, 1);
  unsigned char *r1 = malloc(CAP), *r2 = malloc(CAP), *saved = NULL, *again = NULL;
  int64_t size = 0, size2 = 0;
  for (int step = 1; step <= 4; ++step) take_step(orig, &d, step, r1);
  ok(b2b_model_save_size(orig, &size, msg, sizeof msg), msg);
  saved = malloc((size_t)size);
  ok(b2b_model_save(orig, saved, size, msg, sizeof msg), msg);
  /* a new run of the host: the same beams and groups, then the restart file */
  b2b_model *restored = tst_model(&d.sc, d.p, 1);
  ok(b2b_model_restore(restored, saved, size, msg, sizeof msg), msg);
  ok(b2b_model_save_size(restored, &size2, msg, sizeof msg), msg);
  ck_assert_int_eq(size, size2);
  again = malloc((size_t)size2);
  ok(b2b_model_save(restored, again, size2, msg, sizeof msg), msg);
  ck_assert_msg(memcmp(saved, again, (size_t)size) == 0, "a restored model saves other bytes");
  int contacts = 0;
  for (int step = 5; step <= STEPS; ++step) {
    const size_t n1 = take_step(orig, &d, step, r1);
    const size_t n2 = take_step(restored, &d, step, r2);
    ck_assert_msg(n1 == n2 && memcmp(r1, r2, n1) == 0, "step %d differs after the restore", step);
    int c;
    ok(b2b_model_contact_count(orig, &c, msg, sizeof msg), msg);
    contacts += c;
  }
  printf("restart: %lld bytes; steps 5..%d with %d active contacts bit for bit\n",
         (long long)size, STEPS, contacts);
  ck_assert_int_ge(contacts, 20);
  free(r1);
  free(r2);
  free(saved);
  free(again);
  b2b_model_destroy(&orig);
  b2b_model_destroy(&restored);
  drift_free(&d);
}
END_TEST

int main(void) {
  Suite *s = suite_create("model_state");
  TCase *tc = tcase_create("commit_revert_restart");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, cut_back_is_as_if_never_tried);
  tcase_add_test(tc, restore_continues_bit_for_bit);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
