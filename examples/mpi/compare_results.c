/* Compares two result files of mpi_host (results.h), e.g. the 1-rank and
 * the 2-rank run of a scene: the same steps, nodes and contacts (the same
 * global pairs, in the same order), and every number within `tol` of the
 * other relative to the largest magnitude of its kind in the first file
 * (each step column; displacements; f_N; gaps; friction forces).
 *   compare_results A B [tol]      (tol default 1e-10)
 * Exits 0 if they agree, 1 if not, 2 on a read error. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { K_STEP = 0, K_NODE = 1, K_CONTACT = 2 };
/* numbers per line kind: integers first, then reals */
static const int n_int[3] = {1, 1, 4}, n_real[3] = {4, 3, 5};
/* a real's category (scale): step columns 0-3, u 4, f_N 5, gap 6, T 7 */
static int category(int kind, int j) {
  if (kind == K_STEP) return j;
  if (kind == K_NODE) return 4;
  return j == 0 ? 5 : j == 1 ? 6 : 7;
}
static const char *cat_name[8] = {"step t", "step column a", "step column b", "step column c",
                                  "displacements", "contact f_N", "contact gap", "contact T"};

typedef struct {
  int n, cap;
  int *kind;
  long long *ints; /* 4 per line */
  double *reals;   /* 5 per line */
} file_data;

static int read_file(const char *path, file_data *fd) {
  FILE *f = fopen(path, "r");
  if (!f) {
    fprintf(stderr, "compare_results: cannot open %s\n", path);
    return 1;
  }
  memset(fd, 0, sizeof *fd);
  char line[1024];
  int ln = 0;
  while (fgets(line, sizeof line, f)) {
    ++ln;
    if (line[0] == '#') continue;
    if (fd->n == fd->cap) {
      fd->cap = fd->cap ? 2 * fd->cap : 1024;
      fd->kind = realloc(fd->kind, sizeof(int) * (size_t)fd->cap);
      fd->ints = realloc(fd->ints, sizeof(long long) * 4 * (size_t)fd->cap);
      fd->reals = realloc(fd->reals, sizeof(double) * 5 * (size_t)fd->cap);
      if (!fd->kind || !fd->ints || !fd->reals) {
        fprintf(stderr, "compare_results: out of memory\n");
        fclose(f);
        return 1;
      }
    }
    char tag[16];
    long long *I = fd->ints + 4 * fd->n;
    double *R = fd->reals + 5 * fd->n;
    int k, got;
    if (sscanf(line, "%15s", tag) != 1) continue;
    if (strcmp(tag, "step") == 0) {
      k = K_STEP;
      got = sscanf(line, "%*s %lld %lf %lf %lf %lf", I, R, R + 1, R + 2, R + 3);
    } else if (strcmp(tag, "node") == 0) {
      k = K_NODE;
      got = sscanf(line, "%*s %lld %lf %lf %lf", I, R, R + 1, R + 2);
    } else if (strcmp(tag, "contact") == 0) {
      k = K_CONTACT;
      got = sscanf(line, "%*s %lld %lld %lld %lld %lf %lf %lf %lf %lf", I, I + 1, I + 2, I + 3, R,
                   R + 1, R + 2, R + 3, R + 4);
    } else {
      fprintf(stderr, "compare_results: %s line %d: unknown line '%s'\n", path, ln, tag);
      fclose(f);
      return 1;
    }
    if (got != n_int[k] + n_real[k]) {
      fprintf(stderr, "compare_results: %s line %d: malformed %s line\n", path, ln, tag);
      fclose(f);
      return 1;
    }
    fd->kind[fd->n++] = k;
  }
  fclose(f);
  return 0;
}

int main(int argc, char **argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: compare_results A B [tol]\n");
    return 2;
  }
  const double tol = argc > 3 ? atof(argv[3]) : 1e-10;
  file_data a, b;
  if (read_file(argv[1], &a) || read_file(argv[2], &b)) return 2;
  int n_kind[3] = {0, 0, 0};
  for (int i = 0; i < a.n; ++i) n_kind[a.kind[i]]++;
  printf("%s: %d steps, %d nodes, %d contacts\n", argv[1], n_kind[0], n_kind[1], n_kind[2]);
  if (a.n != b.n) {
    printf("DIFFER: %d lines against %d\n", a.n, b.n);
    return 1;
  }
  double scale[8] = {0};
  for (int i = 0; i < a.n; ++i)
    for (int j = 0; j < n_real[a.kind[i]]; ++j) {
      const int c = category(a.kind[i], j);
      scale[c] = fmax(scale[c], fabs(a.reals[5 * i + j]));
    }
  double worst[8] = {0};
  int differ = 0;
  for (int i = 0; i < a.n; ++i) {
    const int k = a.kind[i];
    if (b.kind[i] != k || memcmp(a.ints + 4 * i, b.ints + 4 * i, sizeof(long long) * (size_t)n_int[k])) {
      if (differ++ < 10)
        printf("DIFFER at entry %d: %s %lld %lld %lld %lld against %s %lld %lld %lld %lld\n", i,
               k == 0 ? "step" : k == 1 ? "node" : "contact", a.ints[4 * i], a.ints[4 * i + 1],
               a.ints[4 * i + 2], a.ints[4 * i + 3], b.kind[i] == 0 ? "step" : b.kind[i] == 1 ? "node" : "contact",
               b.ints[4 * i], b.ints[4 * i + 1], b.ints[4 * i + 2], b.ints[4 * i + 3]);
      continue;
    }
    for (int j = 0; j < n_real[k]; ++j) {
      const int c = category(k, j);
      const double d = fabs(a.reals[5 * i + j] - b.reals[5 * i + j]);
      const double rel = scale[c] > 0 ? d / scale[c] : d;
      if (!(rel <= tol) && differ++ < 10)
        printf("DIFFER at entry %d (%s): %.17g against %.17g, %.3e relative\n", i, cat_name[c],
               a.reals[5 * i + j], b.reals[5 * i + j], rel);
      if (!(rel <= worst[c])) worst[c] = rel;
    }
  }
  for (int c = 0; c < 8; ++c)
    if (scale[c] > 0)
      printf("  %-14s largest |value| %.6e, largest difference %.3e relative (bound %.0e)\n",
             cat_name[c], scale[c], worst[c], tol);
  printf("%s\n", differ ? "the results DIFFER" : "the same contact list; every value within the bound");
  return differ != 0;
}
