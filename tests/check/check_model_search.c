/* The contact model's search and active set against brute force: on seeded
 * random fibre networks (straight and curved, open and closed beams, with and
 * without self-contact) the model finds exactly the active contacts that
 * evaluating every allowed pair of segments finds, with bit-identical
 * outputs; also after the nodes move within the search skin (the candidate
 * list is reused) and beyond it (rebuilt). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_support.h"

#define MAXC 4096

static int cmp_contact(const void *pa, const void *pb) {
  const tst_contact *a = pa, *b = pb;
  for (int i = 0; i < 4; ++i)
    if (a->pair[i] != b->pair[i]) return a->pair[i] < b->pair[i] ? -1 : 1;
  return 0;
}

/* Fails unless the model's contacts are the brute-force ones, bit for bit. */
static int compare(const b2b_model *m, const tst_scene *sc, const b2b_params *p) {
  static tst_contact mine[MAXC], ref[MAXC];
  const int n = tst_model_contacts(m, mine, MAXC);
  const int nr = tst_brute_force(sc, p, 0, ref, MAXC);
  qsort(ref, nr, sizeof ref[0], cmp_contact);
  ck_assert_msg(n == nr, "model finds %d active contacts, brute force %d", n, nr);
  for (int k = 0; k < n; ++k) {
    ck_assert_msg(memcmp(mine[k].pair, ref[k].pair, sizeof mine[k].pair) == 0,
                  "contact %d: model pair (%d %d, %d %d), brute force (%d %d, %d %d)", k,
                  mine[k].pair[0], mine[k].pair[1], mine[k].pair[2], mine[k].pair[3],
                  ref[k].pair[0], ref[k].pair[1], ref[k].pair[2], ref[k].pair[3]);
    ck_assert_msg(memcmp(mine[k].residual, ref[k].residual, sizeof mine[k].residual) == 0,
                  "contact %d: residual differs", k);
    ck_assert_msg(memcmp(mine[k].info, ref[k].info, sizeof mine[k].info) == 0,
                  "contact %d: info differs", k);
  }
  return n;
}

static void move_all(tst_scene *sc, tst_rng *rng, double amount) {
  for (int k = 0; k < 3 * sc->n_nodes; ++k) sc->x[k] += amount * tst_uniform(rng, -1, 1);
}

static void run_networks(double max_turn, int closed_every, int self_every, int law) {
  int total = 0, builds_reused = 0, builds_new = 0;
  for (int seed = 1; seed <= 6; ++seed) {
    tst_rng rng;
    tst_rng_seed(&rng, 1000 + seed);
    tst_scene sc;
    tst_network(&rng, 40, 9, 0.5, 3.0, 0.09, max_turn, closed_every, self_every, &sc);
    b2b_params *p = tst_params(law, 1e3, 0.02);
    b2b_model *m = tst_model(&sc, p, 0);
    char msg[B2B_ERRMSG_LEN];
    ck_assert_int_eq(b2b_model_set_real(m, "search_margin", 0.05, msg, sizeof msg), B2B_OK);
    int counts[16];
    tst_update(m, &sc, 0);
    total += compare(m, &sc, p);
    /* within the skin: the candidates are reused */
    move_all(&sc, &rng, 0.01);
    tst_update(m, &sc, 0);
    total += compare(m, &sc, p);
    ck_assert_int_eq(b2b_model_stats(m, counts, NULL, msg, sizeof msg), B2B_OK);
    builds_reused += counts[B2B_COUNT_SEARCH_BUILDS] == 1;
    /* beyond it: a new search */
    move_all(&sc, &rng, 0.08);
    tst_update(m, &sc, 0);
    total += compare(m, &sc, p);
    ck_assert_int_eq(b2b_model_stats(m, counts, NULL, msg, sizeof msg), B2B_OK);
    builds_new += counts[B2B_COUNT_SEARCH_BUILDS] == 2;
    b2b_model_destroy(&m);
    b2b_params_destroy(&p);
    tst_scene_free(&sc);
  }
  printf("networks (turn %.2f, rings every %d, self every %d, law %d): %d active contacts "
         "found as by brute force; %d/6 reused the candidates, %d/6 searched again\n",
         max_turn, closed_every, self_every, law, total, builds_reused, builds_new);
  ck_assert_msg(total >= 30, "too few contacts (%d) to test anything", total);
  ck_assert_int_eq(builds_reused, 6);
  ck_assert_int_eq(builds_new, 6);
}

START_TEST(straight_open) { run_networks(0.0, 0, 0, B2B_LAW_LINEAR); }
END_TEST

START_TEST(curved_open_and_closed) { run_networks(0.35, 5, 0, B2B_LAW_LINEAR); }
END_TEST

START_TEST(curved_self_contact) { run_networks(0.6, 7, 2, B2B_LAW_LINEAR); }
END_TEST

START_TEST(quadratic_law_reach) { run_networks(0.35, 5, 2, B2B_LAW_QUADRATIC); }
END_TEST

int main(void) {
  Suite *s = suite_create("model_search");
  TCase *tc = tcase_create("brute_force");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, straight_open);
  tcase_add_test(tc, curved_open_and_closed);
  tcase_add_test(tc, curved_self_contact);
  tcase_add_test(tc, quadratic_law_reach);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
