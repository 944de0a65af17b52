/* Gathering and writing a run's results (results.h). */
#include "results.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int step_log_add(step_log *lg, double t, double a, double b, double c) {
  if (lg->n_steps == lg->cap) {
    const int cap = lg->cap ? 2 * lg->cap : 64;
    double *r = realloc(lg->rows, sizeof(double) * 4 * (size_t)cap);
    if (!r) return 1;
    lg->rows = r;
    lg->cap = cap;
  }
  double *r = lg->rows + 4 * lg->n_steps++;
  r[0] = t;
  r[1] = a;
  r[2] = b;
  r[3] = c;
  return 0;
}

/* a contact: global pair, then f_N, gap, T (3) */
typedef struct {
  int64_t pair[4];
  double v[5];
} contact_row;

static int by_pair(const void *a, const void *b) {
  const contact_row *x = a, *y = b;
  for (int i = 0; i < 4; ++i)
    if (x->pair[i] != y->pair[i]) return x->pair[i] < y->pair[i] ? -1 : 1;
  return 0;
}

int results_write(fe_host *h, Vec U, const step_log *lg, const char *path) {
  const scene *sc = h->sc;
  const int P = h->size, no = h->pp->n_own_nodes;
  /* displacements: own nodes as (global id, u) */
  double *mine = malloc(sizeof(double) * 4 * (size_t)(no + 1));
  const PetscScalar *a;
  VecGetArrayRead(U, &a);
  for (int l = 0; l < no; ++l) {
    mine[4 * l] = h->pp->local_nodes[l];
    for (int d = 0; d < 3; ++d) mine[4 * l + 1 + d] = a[3 * l + d];
  }
  VecRestoreArrayRead(U, &a);
  int *cnt = calloc((size_t)P, sizeof(int)), *dsp = calloc((size_t)P + 1, sizeof(int));
  int n4 = 4 * no;
  MPI_Gather(&n4, 1, MPI_INT, cnt, 1, MPI_INT, 0, h->comm);
  for (int q = 0; q < P; ++q) dsp[q + 1] = dsp[q] + cnt[q];
  double *all = h->rank == 0 ? malloc(sizeof(double) * (size_t)(dsp[P] + 1)) : NULL;
  MPI_Gatherv(mine, n4, MPI_DOUBLE, all, cnt, dsp, MPI_DOUBLE, 0, h->comm);
  double *u = NULL;
  if (h->rank == 0) {
    u = malloc(sizeof(double) * 3 * (size_t)sc->n_nodes);
    for (int i = 0; i < dsp[P] / 4; ++i)
      for (int d = 0; d < 3; ++d) u[3 * (int)all[4 * i] + d] = all[4 * i + 1 + d];
  }
  free(mine);
  free(all);
  /* contacts of this rank's pairs */
  int nc = 0;
  b2b_model_contact_count(h->ch.model, &nc, h->msg, sizeof h->msg);
  contact_row *rows = malloc(sizeof(contact_row) * (size_t)(nc + 1));
  int st = 0;
  for (int k = 0; k < nc && !st; ++k) {
    double info[32];
    st = contact_host_global_pair(&h->ch, k, rows[k].pair, h->msg, sizeof h->msg);
    if (!st)
      st = b2b_model_get_contact(h->ch.model, k, NULL, NULL, info, NULL, NULL, 24, h->msg,
                                 sizeof h->msg);
    rows[k].v[0] = info[B2B_INFO_NORMAL_FORCE];
    rows[k].v[1] = info[B2B_INFO_GAP];
    for (int d = 0; d < 3; ++d) rows[k].v[2 + d] = info[B2B_INFO_TANGENTIAL_FORCE + d];
  }
  if (st) fprintf(stderr, "rank %d: contacts: %s\n", h->rank, h->msg);
  int nb = (int)sizeof(contact_row) * nc;
  MPI_Gather(&nb, 1, MPI_INT, cnt, 1, MPI_INT, 0, h->comm);
  for (int q = 0; q < P; ++q) dsp[q + 1] = dsp[q] + cnt[q];
  contact_row *allc = h->rank == 0 ? malloc((size_t)dsp[P] + sizeof(contact_row)) : NULL;
  MPI_Gatherv(rows, nb, MPI_BYTE, allc, cnt, dsp, MPI_BYTE, 0, h->comm);
  free(rows);
  int fail = st != 0;
  if (h->rank == 0) {
    const int n_all = dsp[P] / (int)sizeof(contact_row);
    qsort(allc, (size_t)n_all, sizeof *allc, by_pair);
    FILE *f = fopen(path, "w");
    if (!f) {
      fprintf(stderr, "cannot write %s\n", path);
      fail = 1;
    } else {
      fprintf(f, "# b2b MPI example: scene %s, %d rank(s); step t a b c; node id u; "
                 "contact beamA segA beamB segB f_N gap T\n", sc->name, P);
      for (int s = 0; s < lg->n_steps; ++s)
        fprintf(f, "step %d %.17g %.17g %.17g %.17g\n", s + 1, lg->rows[4 * s], lg->rows[4 * s + 1],
                lg->rows[4 * s + 2], lg->rows[4 * s + 3]);
      for (int k = 0; k < sc->n_nodes; ++k)
        fprintf(f, "node %d %.17g %.17g %.17g\n", k, u[3 * k], u[3 * k + 1], u[3 * k + 2]);
      for (int k = 0; k < n_all; ++k) {
        const contact_row *c = allc + k;
        fprintf(f, "contact %lld %lld %lld %lld %.17g %.17g %.17g %.17g %.17g\n",
                (long long)c->pair[0], (long long)c->pair[1], (long long)c->pair[2],
                (long long)c->pair[3], c->v[0], c->v[1], c->v[2], c->v[3], c->v[4]);
      }
      fail |= fclose(f) != 0;
    }
  }
  free(allc);
  free(u);
  free(cnt);
  free(dsp);
  int any = 0;
  MPI_Allreduce(&fail, &any, 1, MPI_INT, MPI_MAX, h->comm);
  return any;
}
