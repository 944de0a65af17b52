/* The curve study: how accurate each curve kind is, and what it costs.
 *
 *   curve_study [--quick]
 *
 * Part 1: the largest distance from the exact circle of radius R = 1 of the
 * smoothed ring through n nodes, n = 8 .. 256, on a uniform mesh and on a
 * mesh with elements alternating 1.3h / 0.7h, with the fitted order.
 * Part 2: the time of one b2b_segment_eval (point only; point and all first
 * and second derivatives), as ns and as a ratio to the linear kind. All kinds
 * are timed in the same run, interleaved, best of several trials, so that
 * the ratios are robust on a shared machine. --quick shortens part 2 (the
 * ctest smoke test); the accuracy numbers do not change.
 * Output is Markdown, ready for doc/guide-curves.md. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <b2b/b2b.h>

#include "ring_accuracy.h"

#define N_KINDS B2B_CURVE_KIND_COUNT
#define N_MESHES 6
/* Every kind gets a column: one the library adds needs its name here. */
static const int kKinds[] = {B2B_CURVE_LINEAR, B2B_CURVE_HERMITE_MIDPOINT, B2B_CURVE_HERMITE_NODAL,
                             B2B_CURVE_HERMITE_NODAL_WEIGHTED};
static const char *kNames[] = {"linear", "hermite-midpoint", "hermite-nodal",
                               "hermite-nodal-weighted"};
typedef char every_kind_has_a_column[sizeof kKinds / sizeof kKinds[0] == N_KINDS &&
                                             sizeof kNames / sizeof kNames[0] == N_KINDS
                                         ? 1
                                         : -1]; /* C99: no _Static_assert */
static const int kN[N_MESHES] = {8, 16, 32, 64, 128, 256};

static void fail(const char *what, int st) {
  fprintf(stderr, "curve_study: %s failed: %s\n", what, b2b_strerror(st));
  exit(EXIT_FAILURE);
}

static void accuracy_table(int alternating) {
  double err[N_KINDS][N_MESHES];
  for (int k = 0; k < N_KINDS; ++k)
    for (int m = 0; m < N_MESHES; ++m) {
      const int st = ring_max_error(kKinds[k], kN[m], 1.0, alternating, 200, &err[k][m]);
      if (st != B2B_OK) fail("ring_max_error", st);
    }
  printf("\n%s mesh: max |distance from the circle| / R\n\n",
         alternating ? "Alternating 1.3h/0.7h" : "Uniform");
  printf("| elements |");
  for (int k = 0; k < N_KINDS; ++k) printf(" %s |", kNames[k]);
  printf("\n|---:|");
  for (int k = 0; k < N_KINDS; ++k) printf("---:|");
  printf("\n");
  for (int m = 0; m < N_MESHES; ++m) {
    printf("| %d |", kN[m]);
    for (int k = 0; k < N_KINDS; ++k) printf(" %.2e |", err[k][m]);
    printf("\n");
  }
  printf("| fitted order |");
  for (int k = 0; k < N_KINDS; ++k) printf(" %.2f |", fitted_order(kN, err[k], N_MESHES));
  printf("\n");
}

static double now_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return 1e9 * (double)ts.tv_sec + (double)ts.tv_nsec;
}

/* One trial: `count` evaluations on the segments of a 64-node ring at
 * pseudo-random xi; returns ns per evaluation. */
static double time_trial(int kind, int with_derivatives, int count, const double *patches,
                         const int *rules, int nseg) {
  static double x[9], dx[72], d2x[864];
  double sink = 0.0;
  unsigned seed = 12345u;
  const double t0 = now_ns();
  for (int i = 0; i < count; ++i) {
    seed = seed * 1664525u + 1013904223u;
    const int s = (int)(seed >> 8) % nseg;
    const double xi = -1.0 + 2.0 * (double)(seed & 0xffu) / 255.0;
    const int st = b2b_segment_eval(kind, rules[2 * s], rules[2 * s + 1], patches + 12 * s, NULL,
                                    xi, x, with_derivatives ? dx : NULL,
                                    with_derivatives ? d2x : NULL, NULL, 0);
    if (st != B2B_OK) fail("b2b_segment_eval", st);
    sink += x[0] + (with_derivatives ? dx[5] + d2x[100] : 0.0);
  }
  const double t1 = now_ns();
  if (sink == 42.4242) printf(" ");  // keep the results alive
  return (t1 - t0) / count;
}

static void cost_table(int quick) {
  enum { n = 64 };
  double coords[3 * n];
  ring_nodes(n, 1.0, 1, coords);
  const int trials = quick ? 3 : 15;
  const int count[2] = {quick ? 20000 : 200000, quick ? 2000 : 40000};
  double best[N_KINDS][2];
  static double patches[N_KINDS][12 * n];
  static int rules[N_KINDS][2 * n];
  int nseg[N_KINDS];
  for (int k = 0; k < N_KINDS; ++k) {
    int st = b2b_beam_segment_count(kKinds[k], n, 1, &nseg[k], NULL, 0);
    if (st != B2B_OK) fail("b2b_beam_segment_count", st);
    for (int s = 0; s < nseg[k]; ++s) {
      int nodes[4];
      st = b2b_beam_segment_patch(kKinds[k], n, 1, s, nodes, &rules[k][2 * s],
                                  &rules[k][2 * s + 1], NULL, 0);
      if (st != B2B_OK) fail("b2b_beam_segment_patch", st);
      for (int slot = 0; slot < 4; ++slot)
        for (int i = 0; i < 3; ++i)
          patches[k][12 * s + 3 * slot + i] = nodes[slot] >= 0 ? coords[3 * nodes[slot] + i] : 0.0;
    }
    best[k][0] = best[k][1] = 1e300;
  }
  for (int t = 0; t < trials; ++t)
    for (int w = 0; w < 2; ++w)
      for (int k = 0; k < N_KINDS; ++k) {
        const double ns = time_trial(kKinds[k], w, count[w], patches[k], rules[k], nseg[k]);
        if (ns < best[k][w]) best[k][w] = ns;
      }
  printf("\nCost of one b2b_segment_eval (best of %d trials; ratio to the linear kind)\n\n",
         trials);
  printf("| kind | point only [ns] | ratio | point + all derivatives [ns] | ratio |\n");
  printf("|---|---:|---:|---:|---:|\n");
  for (int k = 0; k < N_KINDS; ++k)
    printf("| %s | %.0f | %.2f | %.0f | %.2f |\n", kNames[k], best[k][0], best[k][0] / best[0][0],
           best[k][1], best[k][1] / best[0][1]);
}

static void print_machine(void) {
  char model[256] = "unknown CPU";
  FILE *f = fopen("/proc/cpuinfo", "r");
  if (f) {
    char line[512];
    while (fgets(line, sizeof line, f))
      if (strncmp(line, "model name", 10) == 0) {
        const char *colon = strchr(line, ':');
        if (colon) {
          snprintf(model, sizeof model, "%s", colon + 2);
          model[strcspn(model, "\n")] = '\0';
        }
        break;
      }
    fclose(f);
  }
  int major, minor, patch;
  b2b_version(&major, &minor, &patch);
  printf("b2b %d.%d.%d curve study on %s\n", major, minor, patch, model);
}

int main(int argc, char **argv) {
  const int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
  print_machine();
  accuracy_table(0);
  accuracy_table(1);
  cost_table(quick);
  return EXIT_SUCCESS;
}
