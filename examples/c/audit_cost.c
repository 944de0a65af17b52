/* The cost of the interpenetration audit (b2b_model_audit) against the
 * update it audits (issue 16, item 4: at most 20% of an update, so that a
 * host can run it after every converged step).
 *
 *   audit_cost [--quick] [--max N]
 *
 * Scene: a seeded random network of fibres of radius 0.1, 12 segments of
 * length 0.5 each, gently curved, at random positions and orientations in a
 * cube whose volume grows with the count (2 segments per unit volume: a few
 * contacts per fibre), every curve kind in turn. Sizes 10^3 .. 10^5
 * segments (--max N: up to N; --quick: 10^3 only, the ctest smoke test).
 * For each size, on one thread ("threads" 1; the audit runs on one):
 *   update   b2b_model_update with tangents on coordinates moved a little
 *            from the first update's, so that it reuses the candidates (a
 *            Newton iteration of a host), best of 3;
 *   build    the first update (search build and evaluation), best of 3
 *            models;
 *   audit    b2b_model_audit after the update (size query and listing),
 *            best of 3;
 * and prints audit / update and audit / build, and the findings by reason
 * (PARALLEL / OUTSIDE_BOTH / NEVER_EVALUATED / EXCLUDED_SELF / CROSSED /
 * OTHER). Checks (exit 1): every call
 * succeeds, the listing's count equals the size query's; without --quick
 * also audit / update <= 0.20 at every size. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <b2b/b2b.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t rng_state;
static double uniform(double a, double b) {
  rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
  return a + (b - a) * (double)(rng_state >> 11) / 9007199254740992.0;
}

enum { SEG_PER_FIBRE = 12 };

typedef struct {
  int n_fibres, n_nodes;
  double *x, *moved;
} scene;

static void make_scene(int n_seg, scene *s) {
  s->n_fibres = (n_seg + SEG_PER_FIBRE - 1) / SEG_PER_FIBRE;
  s->n_nodes = s->n_fibres * (SEG_PER_FIBRE + 1);
  s->x = malloc(sizeof(double) * 3 * (size_t)s->n_nodes);
  s->moved = malloc(sizeof(double) * 3 * (size_t)s->n_nodes);
  const double side = cbrt(s->n_fibres * SEG_PER_FIBRE / 2.0);
  for (int f = 0; f < s->n_fibres; ++f) {
    double p[3], d[3], n;
    for (int i = 0; i < 3; ++i) p[i] = uniform(0.0, side);
    do {
      for (int i = 0; i < 3; ++i) d[i] = uniform(-1.0, 1.0);
      n = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    } while (n < 0.1 || n > 1.0);
    for (int k = 0; k <= SEG_PER_FIBRE; ++k) {
      double *q = s->x + 3 * (f * (SEG_PER_FIBRE + 1) + k);
      for (int i = 0; i < 3; ++i) q[i] = p[i];
      for (int i = 0; i < 3; ++i) d[i] = d[i] / n + uniform(-0.15, 0.15);
      n = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (int i = 0; i < 3; ++i) p[i] += 0.5 * d[i] / n;
    }
  }
  for (int k = 0; k < 3 * s->n_nodes; ++k) s->moved[k] = s->x[k] + uniform(-0.002, 0.002);
}

static int fail(const char *what, int st, const char *msg) {
  fprintf(stderr, "audit_cost: %s: status %d: %s\n", what, st, msg);
  exit(1);
}
#define OK(call, what)                            \
  do {                                            \
    const int st_ = (call);                       \
    if (st_ != B2B_OK) fail(what, st_, msg);      \
  } while (0)

static b2b_model *make_model(const scene *s, const b2b_params *p) {
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_model *m = NULL;
  int nodes[SEG_PER_FIBRE + 1], beam;
  OK(b2b_model_create(&m, msg, sizeof msg), "create");
  for (int f = 0; f < s->n_fibres; ++f) {
    for (int k = 0; k <= SEG_PER_FIBRE; ++k) nodes[k] = f * (SEG_PER_FIBRE + 1) + k;
    OK(b2b_model_add_beam(m, nodes, SEG_PER_FIBRE + 1, 0, 0.1, f % B2B_CURVE_KIND_COUNT, 0,
                          &beam, msg, sizeof msg), "add_beam");
  }
  OK(b2b_model_set_group_pair(m, 0, 0, p, msg, sizeof msg), "set_group_pair");
  OK(b2b_model_set_int(m, "threads", 1, msg, sizeof msg), "threads");
  OK(b2b_model_finalize(m, s->n_nodes, msg, sizeof msg), "finalize");
  return m;
}

int main(int argc, char **argv) {
  int quick = 0, max = 100000;
  for (int a = 1; a < argc; ++a) {
    if (strcmp(argv[a], "--quick") == 0)
      quick = 1;
    else if (strcmp(argv[a], "--max") == 0 && a + 1 < argc)
      max = atoi(argv[++a]);
    else {
      fprintf(stderr, "usage: audit_cost [--quick] [--max N]\n");
      return 2;
    }
  }
  if (quick) max = 1000;
  char msg[B2B_ERRMSG_LEN] = "";
  b2b_params *p = NULL;
  OK(b2b_params_create(&p, msg, sizeof msg), "params");
  OK(b2b_params_set_real(p, "penalty", 1e3, msg, sizeof msg), "penalty");
  OK(b2b_params_finalize(p, msg, sizeof msg), "finalize params");
  int failed = 0;
  printf("| segments | contacts | findings (P / J / N / S / C / O) | build [ms] | update [ms] | "
         "audit [ms] | audit / update | audit / build |\n|---|---|---|---|---|---|---|---|\n");
  for (int n_seg = 1000; n_seg <= max; n_seg *= 10) {
    rng_state = 12345u + (uint64_t)n_seg;
    scene s;
    make_scene(n_seg, &s);
    double t_build = HUGE_VAL, t_update = HUGE_VAL, t_audit = HUGE_VAL;
    int contacts = 0, found = 0, by_reason[6] = {0};
    for (int rep = 0; rep < 3; ++rep) {
      b2b_model *m = make_model(&s, p);
      double t0 = now();
      OK(b2b_model_update(m, s.x, 3, s.n_nodes, 1, msg, sizeof msg), "first update");
      const double tb = now() - t0;
      if (tb < t_build) t_build = tb;
      t0 = now();
      OK(b2b_model_update(m, s.moved, 3, s.n_nodes, 1, msg, sizeof msg), "update");
      const double tu = now() - t0;
      if (tu < t_update) t_update = tu;
      OK(b2b_model_contact_count(m, &contacts, msg, sizeof msg), "contact_count");
      t0 = now();
      int n = 0;
      OK(b2b_model_audit(m, 0.01, &n, NULL, NULL, NULL, 0, msg, sizeof msg), "audit size");
      int *pairs = malloc(sizeof(int) * 4 * (size_t)(n + 1));
      int *reasons = malloc(sizeof(int) * (size_t)(n + 1));
      double *overlap = malloc(sizeof(double) * (size_t)(n + 1));
      int listed = -1;
      OK(b2b_model_audit(m, 0.01, &listed, pairs, overlap, reasons, n, msg, sizeof msg),
         "audit");
      const double ta = (now() - t0) / 2.0;  /* two audits: the query and the listing */
      if (ta < t_audit) t_audit = ta;
      if (listed != n) {
        fprintf(stderr, "audit_cost: the listing has %d findings, the size query %d\n", listed,
                n);
        failed = 1;
      }
      found = n;
      memset(by_reason, 0, sizeof by_reason);
      for (int k = 0; k < listed; ++k)
        if (reasons[k] >= 0 && reasons[k] < 6) ++by_reason[reasons[k]];
      free(pairs);
      free(reasons);
      free(overlap);
      b2b_model_destroy(&m);
    }
    const double ratio = t_audit / t_update;
    printf("| %d | %d | %d (%d / %d / %d / %d / %d / %d) | %.2f | %.2f | %.2f | %.3f | %.3f |\n",
           s.n_fibres * SEG_PER_FIBRE, contacts, found, by_reason[B2B_AUDIT_PARALLEL],
           by_reason[B2B_AUDIT_OUTSIDE_BOTH], by_reason[B2B_AUDIT_NEVER_EVALUATED],
           by_reason[B2B_AUDIT_EXCLUDED_SELF], by_reason[B2B_AUDIT_CROSSED],
           by_reason[B2B_AUDIT_OTHER], 1e3 * t_build, 1e3 * t_update, 1e3 * t_audit, ratio,
           t_audit / t_build);
    fflush(stdout);
    if (!quick && ratio > 0.20) {
      fprintf(stderr, "audit_cost: audit / update = %.3f > 0.20 at %d segments\n", ratio,
              s.n_fibres * SEG_PER_FIBRE);
      failed = 1;
    }
    free(s.x);
    free(s.moved);
  }
  b2b_params_destroy(&p);
  return failed;
}
