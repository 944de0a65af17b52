/* The host's SNES callbacks and load steps (fe_host.h). */
#include "fe_host.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "beam_element.h"

int fe_host_setup(fe_host *h, MPI_Comm comm, const scene *sc, const partition *pt, const part *pp) {
  memset(h, 0, sizeof *h);
  h->comm = comm;
  MPI_Comm_rank(comm, &h->rank);
  MPI_Comm_size(comm, &h->size);
  h->sc = sc;
  h->pt = pt;
  h->pp = pp;
  h->max_it = 25;
  const int N = sc->n_nodes, nl = pp->n_local_nodes;
  h->local_of = malloc(sizeof(int) * (size_t)N);
  h->own_index = malloc(sizeof(int) * (size_t)N);
  h->node_beam = malloc(sizeof(int) * (size_t)N);
  h->node_offset = calloc((size_t)h->size + 1, sizeof(int));
  int *count = calloc((size_t)h->size, sizeof(int));
  h->gdof = malloc(sizeof(PetscInt) * 3 * (size_t)nl);
  h->eq_local = malloc(sizeof(int) * 3 * (size_t)nl);
  h->eq_global = malloc(sizeof(int) * 3 * (size_t)nl);
  h->u = calloc(3 * (size_t)nl, sizeof(double));
  h->x = calloc(3 * (size_t)nl, sizeof(double));
  h->f = calloc(3 * (size_t)nl, sizeof(double));
  h->u_at = calloc(3 * (size_t)pp->n_own_nodes + 1, sizeof(double));
  if (!h->local_of || !h->own_index || !h->node_beam || !h->node_offset || !count || !h->gdof ||
      !h->eq_local || !h->eq_global || !h->u || !h->x || !h->f || !h->u_at) {
    free(count);
    return 1;
  }
  for (int b = 0; b < sc->n_beams; ++b)
    for (int k = sc->first_node[b]; k < sc->first_node[b + 1]; ++k) h->node_beam[k] = b;
  for (int k = 0; k < N; ++k) {
    h->local_of[k] = -1;
    h->own_index[k] = count[pt->node_owner[k]]++;
  }
  for (int q = 0; q < h->size; ++q) h->node_offset[q + 1] = h->node_offset[q] + count[q];
  free(count);
  for (int l = 0; l < nl; ++l) {
    const int k = pp->local_nodes[l];
    h->local_of[k] = l;
    const int e = 3 * (h->node_offset[pt->node_owner[k]] + h->own_index[k]);
    for (int d = 0; d < 3; ++d) {
      h->gdof[3 * l + d] = e + d;
      h->eq_global[3 * l + d] = e + d;
      h->eq_local[3 * l + d] = 3 * l + d;
    }
  }
  h->block = malloc(sizeof(int) * ((size_t)nl + 1));
  h->row_lo = malloc(sizeof(int) * ((size_t)nl + 1));
  h->row_hi = malloc(sizeof(int) * ((size_t)nl + 1));
  if (!h->block || !h->row_lo || !h->row_hi) return 1;
  for (int l = 0; l < nl; ++l) {
    const int q = pt->node_owner[pp->local_nodes[l]];
    h->block[l] = (int)(h->gdof[3 * l] / 3);
    h->row_lo[l] = h->node_offset[q];
    h->row_hi[l] = h->node_offset[q + 1];
  }
  if (jac_pattern_init(&h->jp, comm, nl, pp->n_own_nodes, N, h->block, h->row_lo, h->row_hi))
    return 1;
  if (ghost_exchange_setup(&h->gx, comm, pp, pt, h->own_index)) return 1;
  if (contact_host_build(&h->ch, comm, sc, pt, pp, h->msg, sizeof h->msg)) {
    fprintf(stderr, "rank %d: %s\n", h->rank, h->msg);
    return 1;
  }
  return 0;
}

void fe_host_free(fe_host *h) {
  contact_host_free(&h->ch);
  ghost_exchange_free(&h->gx);
  jac_pattern_free(&h->jp);
  PetscFree2(h->coo_i, h->coo_j);
  free(h->block);
  free(h->row_lo);
  free(h->row_hi);
  free(h->local_of);
  free(h->own_index);
  free(h->node_beam);
  free(h->node_offset);
  free(h->gdof);
  free(h->eq_local);
  free(h->eq_global);
  free(h->u);
  free(h->x);
  free(h->f);
  free(h->u_at);
}

/* u and x of every local node from the own dofs of U and the ghost exchange. */
static int local_state(fe_host *h, Vec U) {
  const PetscScalar *a;
  const int no = h->pp->n_own_nodes, nl = h->pp->n_local_nodes;
  VecGetArrayRead(U, &a);
  for (int i = 0; i < 3 * no; ++i) h->u[i] = a[i];
  VecRestoreArrayRead(U, &a);
  if (ghost_exchange_run(&h->gx, h->u)) return 1;
  for (int l = 0; l < nl; ++l)
    for (int d = 0; d < 3; ++d) h->x[3 * l + d] = h->sc->X[3 * h->pp->local_nodes[l] + d] + h->u[3 * l + d];
  return 0;
}

/* Calls emit(local nodes, n, g, H) for each of this rank's own elements at
 * the current x: axial springs of own segments, bending at own interior
 * nodes (less its reference forces with balance_reference), anchors of own
 * nodes (their Hessian diagonal in H, the rest zero). */
typedef void (*emit_fn)(fe_host *h, const int *nodes, int n, const double *g, const double *H,
                        void *data);

static void host_elements(fe_host *h, emit_fn emit, void *data, int want_H) {
  const scene *sc = h->sc;
  const part *pp = h->pp;
  double g[9], g0[9], H[81];
  for (int i = 0; i < pp->n_pieces; ++i) {
    const piece *pc = pp->pieces + i;
    for (int s = pc->first_segment; s < pc->first_segment + pc->n_segments; ++s) {
      if (pp->seg_state[scene_segment(sc, pc->beam, s)] != SEG_OWN) continue;
      const int ka = sc->first_node[pc->beam] + s;
      const int nodes[2] = {h->local_of[ka], h->local_of[ka + 1]};
      const double *Xa = sc->X + 3 * ka;
      double L0 = 0.0;
      for (int d = 0; d < 3; ++d) L0 += (Xa[3 + d] - Xa[d]) * (Xa[3 + d] - Xa[d]);
      axial_element(h->x + 3 * nodes[0], h->x + 3 * nodes[1], sqrt(L0), sc->EA, g,
                    want_H ? H : NULL);
      emit(h, nodes, 2, g, want_H ? H : NULL, data);
    }
  }
  for (int l = 0; l < pp->n_own_nodes; ++l) {
    const int k = pp->local_nodes[l], b = h->node_beam[k];
    double a[3], fx[3];
    scene_load(sc, k, h->t, a, fx);
    double ga[3], Ha[9] = {0};
    for (int d = 0; d < 3; ++d) {
      ga[d] = sc->anchor_k[3 * k + d] * (h->x[3 * l + d] - a[d]) - fx[d];
      Ha[4 * d] = sc->anchor_k[3 * k + d];
    }
    emit(h, &l, 1, ga, want_H ? Ha : NULL, data);
    if (k == sc->first_node[b] || k == sc->first_node[b + 1] - 1) continue;
    const int nodes[3] = {h->local_of[k - 1], l, h->local_of[k + 1]};
    bending_element(h->x + 3 * nodes[0], h->x + 3 * nodes[1], h->x + 3 * nodes[2], sc->kb, g,
                    want_H ? H : NULL);
    if (sc->balance_reference) {
      bending_element(sc->X + 3 * (k - 1), sc->X + 3 * k, sc->X + 3 * (k + 1), sc->kb, g0, NULL);
      for (int i = 0; i < 9; ++i) g[i] -= g0[i];
    }
    emit(h, nodes, 3, g, want_H ? H : NULL, data);
  }
}

static void emit_residual(fe_host *h, const int *nodes, int n, const double *g, const double *H,
                          void *data) {
  (void)H;
  (void)data;
  for (int a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d) h->f[3 * nodes[a] + d] += g[3 * a + d];
}

static PetscErrorCode form_residual(SNES snes, Vec U, Vec F, void *ctx) {
  fe_host *h = ctx;
  const int nl = h->pp->n_local_nodes;
  double t0 = MPI_Wtime();
  if (local_state(h, U)) SETERRQ(h->comm, PETSC_ERR_LIB, "ghost exchange failed");
  const int st = contact_host_update(&h->ch, h->x, 1, h->msg, sizeof h->msg);
  double t1 = MPI_Wtime();
  h->time_update += t1 - t0;
  h->residuals++;
  PetscCall(VecSet(F, 0.0));
  if (st) {
    /* every rank knows (contact_host_update agrees on failure): a cut-back */
    if (h->verbose) PetscCall(PetscPrintf(h->comm, "  update failed: %s\n", h->msg));
    h->domain_error = 1;
    h->have_update = 0;
    PetscCall(SNESSetFunctionDomainError(snes));
    return 0;
  }
  h->have_update = 1;
  for (int i = 0; i < 3 * h->pp->n_own_nodes; ++i) h->u_at[i] = h->u[i];
  memset(h->f, 0, sizeof(double) * 3 * (size_t)nl);
  host_elements(h, emit_residual, NULL, 0);
  if (b2b_model_add_residual(h->ch.model, h->eq_local, 3, 0, 3 * nl, h->f, h->msg, sizeof h->msg))
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "b2b_model_add_residual: %s", h->msg);
  /* own entries, and the nonzero ones of ghost nodes (their owners' rows) */
  const int no = h->pp->n_own_nodes;
  PetscCall(VecSetValues(F, 3 * no, h->gdof, h->f, ADD_VALUES));
  for (int i = 3 * no; i < 3 * nl; ++i)
    if (h->f[i] != 0.0) {
      PetscCall(VecSetValues(F, 1, h->gdof + i, h->f + i, ADD_VALUES));
      h->res_offproc++;
    }
  PetscCall(VecAssemblyBegin(F));
  PetscCall(VecAssemblyEnd(F));
  h->time_assembly += MPI_Wtime() - t1;
  return 0;
}

/* Adds an element's Hessian (n nodes, row-major 3n x 3n; anchors: n = 1,
 * diagonal) to the matrix as n x n node blocks. */
typedef struct {
  Mat J;
  PetscErrorCode err;
} mat_add;

static void count_blocks(fe_host *h, const int *nodes, int n) {
  int nv = 0, ng = 0;
  for (int a = 0; a < n; ++a)
    if (nodes[a] >= 0) {
      ++nv;
      ng += nodes[a] >= h->pp->n_own_nodes;
    }
  h->jac_blocks += (int64_t)nv * nv;
  h->jac_offproc += (int64_t)ng * nv;
}

static void emit_jacobian(fe_host *h, const int *nodes, int n, const double *g, const double *H,
                          void *data) {
  (void)g;
  mat_add *m = data;
  if (m->err) return;
  PetscInt idx[3];
  for (int a = 0; a < n; ++a) idx[a] = h->block[nodes[a]];
  count_blocks(h, nodes, n);
  m->err = MatSetValuesBlocked(m->J, n, idx, n, idx, H, ADD_VALUES);
}

static void emit_pattern(fe_host *h, const int *nodes, int n, const double *g, const double *H,
                         void *data) {
  (void)g;
  (void)H;
  int *bad = data;
  *bad |= jac_pattern_add_element(&h->jp, nodes, n);
}

/* Contact k's 8 local nodes (-1: none) and its pair's key (global segments). */
static int contact_key(fe_host *h, int k, int nodes[8], int64_t *key) {
  int64_t g[4];
  if (b2b_model_get_contact(h->ch.model, k, nodes, NULL, NULL, NULL, NULL, 24, h->msg,
                            sizeof h->msg) ||
      b2b_model_get_contact_global(h->ch.model, k, g, h->msg, sizeof h->msg))
    return 1;
  const scene *sc = h->sc;
  *key = (int64_t)scene_segment(sc, (int)g[0], (int)g[1]) * sc->n_segments +
         scene_segment(sc, (int)g[2], (int)g[3]);
  return 0;
}

/* The Jacobian: the host's elements and each contact's 24 x 24 tangent
 * (b2b_model_get_contact) as 8 x 8 node blocks, into a matrix whose pattern
 * holds every contact pair active at some Jacobian of the run
 * (jacobian_pattern.h): a new matrix only when a pair closes for the first
 * time on some rank, else the same pattern zeroed and filled again. */
/* After a new matrix pattern: the next solve sets its preconditioner up
 * afresh (a factorization would reuse its old symbolic setup). */
static PetscErrorCode reset_preconditioner(SNES snes) {
  KSP ksp;
  PC pc;
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCReset(pc));
  return 0;
}

/* The Jacobian is wanted at the last residual's point (basic line search);
 * if not, update there first (collectively). */
static PetscErrorCode update_at(SNES snes, Vec U, fe_host *h) {
  const PetscScalar *a;
  int same = h->have_update;
  PetscCall(VecGetArrayRead(U, &a));
  for (int i = 0; i < 3 * h->pp->n_own_nodes && same; ++i) same = a[i] == h->u_at[i];
  PetscCall(VecRestoreArrayRead(U, &a));
  int all_same = 0;
  MPI_Allreduce(&same, &all_same, 1, MPI_INT, MPI_MIN, h->comm);
  if (!all_same) {
    Vec F;
    PetscCall(VecDuplicate(U, &F));
    PetscCall(form_residual(snes, U, F, h));
    PetscCall(VecDestroy(&F));
    if (!h->have_update) SETERRQ(h->comm, PETSC_ERR_LIB, "update failed at the Jacobian's point");
  }
  return 0;
}

static PetscErrorCode form_jacobian(SNES snes, Vec U, Mat J, Mat Pmat, void *ctx) {
  fe_host *h = ctx;
  (void)J;
  PetscCall(update_at(snes, U, h));
  const double t0 = MPI_Wtime();
  int nc = 0;
  if (b2b_model_contact_count(h->ch.model, &nc, h->msg, sizeof h->msg))
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "b2b_model_contact_count: %s", h->msg);
  /* the contacts' pairs into the pattern */
  for (int k = 0; k < nc; ++k) {
    int nodes[8], added = 0;
    int64_t key;
    if (contact_key(h, k, nodes, &key))
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "b2b_model_get_contact: %s", h->msg);
    if (jac_pattern_add_pair(&h->jp, key, nodes, &added))
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_MEM, "out of memory (Jacobian pattern)");
  }
  int any_new = 0;
  MPI_Allreduce(&h->jp.n_new, &any_new, 1, MPI_INT, MPI_MAX, h->comm);
  if (h->verbose > 1)
    fprintf(stderr, "rank %d: %d contacts, %d pairs in the pattern, %d new\n", h->rank, nc,
            h->jp.n_pairs, h->jp.n_new);
  if (any_new) {
    Mat Jnew;
    PetscCall(jac_pattern_matrix(&h->jp, h->mat_type, &Jnew));
    PetscCall(MatHeaderReplace(Pmat, &Jnew));
    /* a new pattern: the preconditioner's factorization is set up afresh */
    PetscCall(reset_preconditioner(snes));
    h->preallocations++;
    h->fresh = 1;
  } else if (!h->fresh) {
    PetscCall(MatZeroEntries(Pmat));
  }
  mat_add m = {Pmat, 0};
  host_elements(h, emit_jacobian, &m, 1);
  PetscCall(m.err);
  double K[576], Kt[576];
  for (int k = 0; k < nc; ++k) {
    int nodes[8];
    if (b2b_model_get_contact(h->ch.model, k, nodes, NULL, NULL, NULL, K, 24, h->msg,
                              sizeof h->msg))
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "b2b_model_get_contact: %s", h->msg);
    PetscInt idx[8];
    for (int s = 0; s < 8; ++s) idx[s] = nodes[s] < 0 ? -1 : h->block[nodes[s]];
    /* b2b's tangent is column-major, MatSetValuesBlocked reads rows */
    for (int r = 0; r < 24; ++r)
      for (int c = 0; c < 24; ++c) Kt[24 * r + c] = K[r + 24 * c];
    count_blocks(h, nodes, 8);
    PetscCall(MatSetValuesBlocked(Pmat, 8, idx, 8, idx, Kt, ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(Pmat, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(Pmat, MAT_FINAL_ASSEMBLY));
  if (h->fresh) {
    /* the pattern is complete: a location outside it would be a bug */
    PetscCall(MatSetOption(Pmat, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE));
    h->fresh = 0;
  }
  h->jacobians++;
  h->time_assembly += MPI_Wtime() - t0;
  return 0;
}

/* -jacobian coo: the Jacobian as COO entries, the host's elements' and b2b's
 * (b2b_model_tangent_coo, in the host's global equation numbers), given to
 * PETSc by MatSetPreallocationCOO / MatSetValuesCOO; repeated entries sum.
 * The pattern changes as contacts close, open and slide: a new
 * preallocation when it did on some rank (PETSc then sorts all entries
 * again, the cost that made the block pattern the default at 10^5
 * segments; examples/mpi/README.md), else only the values. */
typedef struct {
  PetscInt *i, *j;
  PetscScalar *v;
  PetscCount n;
} coo_entries;

static void emit_coo(fe_host *h, const int *nodes, int n, const double *g, const double *H,
                     void *data) {
  (void)g;
  coo_entries *c = data;
  const int m = 3 * n;
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) {
      if (n == 1 && a != b) continue;
      c->i[c->n] = h->gdof[3 * nodes[a / 3] + a % 3];
      c->j[c->n] = h->gdof[3 * nodes[b / 3] + b % 3];
      c->v[c->n] = H[m * a + b];
      c->n++;
    }
  count_blocks(h, nodes, n);
}

static PetscErrorCode form_jacobian_coo(SNES snes, Vec U, Mat J, Mat Pmat, void *ctx) {
  fe_host *h = ctx;
  (void)J;
  PetscCall(update_at(snes, U, h));
  const double t0 = MPI_Wtime();
  const int N3 = 3 * h->sc->n_nodes;
  /* at most: 36 entries an own segment's axial spring, 81 an own node's
   * bending element and 3 its anchor */
  const PetscCount n_host =
      (PetscCount)36 * h->pp->n_own_segments + (PetscCount)84 * h->pp->n_own_nodes;
  int nnz_b2b = 0;
  if (b2b_model_tangent_coo(h->ch.model, h->eq_global, 3, 0, N3, &nnz_b2b, NULL, NULL, NULL, 0,
                            h->msg, sizeof h->msg))
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "b2b_model_tangent_coo: %s", h->msg);
  const PetscCount cap = n_host + nnz_b2b;
  coo_entries c = {NULL, NULL, NULL, 0};
  PetscCall(PetscMalloc3(cap, &c.i, cap, &c.j, cap, &c.v));
  host_elements(h, emit_coo, &c, 1);
  int *ri = malloc(sizeof(int) * (size_t)(nnz_b2b + 1));
  int *ci = malloc(sizeof(int) * (size_t)(nnz_b2b + 1));
  if (!ri || !ci) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_MEM, "out of memory");
  int got = 0;
  if (b2b_model_tangent_coo(h->ch.model, h->eq_global, 3, 0, N3, &got, ri, ci, c.v + c.n,
                            nnz_b2b, h->msg, sizeof h->msg))
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "b2b_model_tangent_coo: %s", h->msg);
  for (int e = 0; e < got; ++e) {
    c.i[c.n + e] = ri[e];
    c.j[c.n + e] = ci[e];
  }
  c.n += got;
  free(ri);
  free(ci);
  const int same = h->coo_i && h->coo_n == c.n &&
                   memcmp(h->coo_i, c.i, sizeof(PetscInt) * (size_t)c.n) == 0 &&
                   memcmp(h->coo_j, c.j, sizeof(PetscInt) * (size_t)c.n) == 0;
  int all_same = 0;
  MPI_Allreduce(&same, &all_same, 1, MPI_INT, MPI_MIN, h->comm);
  if (!all_same) {
    PetscCall(PetscFree2(h->coo_i, h->coo_j));
    PetscCall(PetscMalloc2(c.n, &h->coo_i, c.n, &h->coo_j));
    PetscCall(PetscArraycpy(h->coo_i, c.i, c.n));
    PetscCall(PetscArraycpy(h->coo_j, c.j, c.n));
    h->coo_n = c.n;
    PetscCall(MatSetPreallocationCOO(Pmat, c.n, c.i, c.j));
    /* PETSc 3.18 does not see a new COO preallocation as a new pattern: a
     * factorization would reuse its old symbolic setup. */
    PetscCall(reset_preconditioner(snes));
    h->preallocations++;
  }
  PetscCall(MatSetValuesCOO(Pmat, c.v, INSERT_VALUES));
  PetscCall(PetscFree3(c.i, c.j, c.v));
  h->jacobians++;
  h->time_assembly += MPI_Wtime() - t0;
  return 0;
}

static PetscErrorCode converged_test(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                     PetscReal fnorm, SNESConvergedReason *reason, void *ctx) {
  fe_host *h = ctx;
  (void)snes;
  if (h->verbose) PetscCall(PetscPrintf(h->comm, "    it %2d  |F| %.3e  |du| %.3e\n", (int)it, (double)fnorm, (double)snorm));
  if (h->verbose > 2) {
    int c[B2B_MODEL_COUNTS_LEN];
    double tt[B2B_MODEL_TOTALS_LEN];
    fe_host_global_counts(h, c, tt);
    PetscCall(PetscPrintf(h->comm, "           active %d  stick %d  slip %d  handovers %d  "
                          "f_N sum %.9e\n", c[B2B_COUNT_ACTIVE], c[B2B_COUNT_STICK],
                          c[B2B_COUNT_SLIP], c[B2B_COUNT_HANDOVERS],
                          tt[B2B_TOTAL_NORMAL_FORCE]));
  }
  *reason = SNES_CONVERGED_ITERATING;
  if (!(fnorm == fnorm)) *reason = SNES_DIVERGED_FNORM_NAN;
  else if (it > 0 && fnorm <= h->ftol && snorm <= 1e-12 * (xnorm + h->sc->radius))
    *reason = SNES_CONVERGED_SNORM_RELATIVE;
  else if (it >= h->max_it) *reason = SNES_DIVERGED_MAX_IT;
  return 0;
}

void fe_host_global_counts(fe_host *h, int counts[B2B_MODEL_COUNTS_LEN],
                           double totals[B2B_MODEL_TOTALS_LEN]) {
  int c[B2B_MODEL_COUNTS_LEN] = {0};
  double t[B2B_MODEL_TOTALS_LEN] = {0};
  b2b_model_stats(h->ch.model, c, t, h->msg, sizeof h->msg);
  MPI_Allreduce(c, counts, B2B_MODEL_COUNTS_LEN, MPI_INT, MPI_SUM, h->comm);
  MPI_Allreduce(t, totals, B2B_MODEL_TOTALS_LEN, MPI_DOUBLE, MPI_SUM, h->comm);
  double mg = t[B2B_TOTAL_MIN_GAP];
  MPI_Allreduce(&mg, &totals[B2B_TOTAL_MIN_GAP], 1, MPI_DOUBLE, MPI_MIN, h->comm);
}

int fe_host_solve(fe_host *h, Vec U, step_report report, void *data) {
  const scene *sc = h->sc;
  SNES snes;
  KSP ksp;
  PC pc;
  SNESLineSearch ls;
  Vec F, Uc;
  Mat J;
  /* Converged: |F| below ftol and Newton's last correction at the level of
   * rounding (|du| <= 1e-12 (|u| + r)): the state is then the solution to
   * rounding, whatever path Newton took to it. So two runs whose paths part
   * (rounding on either side of a stick/slip switch, or another order of
   * sums) stop at states that agree far below the comparison's 1e-10, not
   * at two points somewhere within a residual tolerance. The residual's
   * bound is 1e-9 of the force scale per dof in the root mean square
   * (|F| <= 1e-9 f sqrt(n_dofs)): the rounding floor of |F| (each
   * contact's stiffness times the rounding of its gap) grows as the square
   * root of the scene's size, and an absolute bound that sat above it at
   * 4800 segments sat below it at 24500 (|F| stuck at 1.35e-11 against
   * 1.26e-11 with |du| at 1e-14: every step ran to max_it and was cut
   * back). */
  h->ftol = 1e-9 * sc->force_scale * sqrt(3.0 * sc->n_nodes);
  VecDuplicate(U, &F);
  VecDuplicate(U, &Uc);
  /* the Jacobian's pattern: the host's elements (evaluated once at the
   * reference, for their nodes); contacts join as they close */
  for (int l = 0; l < h->pp->n_local_nodes; ++l)
    for (int d = 0; d < 3; ++d) h->x[3 * l + d] = sc->X[3 * h->pp->local_nodes[l] + d];
  int bad = 0;
  host_elements(h, emit_pattern, &bad, 0);
  if (bad) {
    PetscPrintf(h->comm, "out of memory (Jacobian pattern)\n");
    return 1;
  }
  PetscStrncpy(h->mat_type, MATBAIJ, sizeof h->mat_type);
  PetscOptionsGetString(NULL, NULL, "-host_mat_type", h->mat_type, sizeof h->mat_type, NULL);
  char jacobian[16] = "block";
  PetscOptionsGetString(NULL, NULL, "-jacobian", jacobian, sizeof jacobian, NULL);
  h->use_coo = strcmp(jacobian, "coo") == 0;
  if (!h->use_coo && strcmp(jacobian, "block") != 0) {
    PetscPrintf(h->comm, "-jacobian %s: expected block or coo\n", jacobian);
    return 1;
  }
  if (h->use_coo) {
    const PetscInt n_own = 3 * (PetscInt)(h->node_offset[h->rank + 1] - h->node_offset[h->rank]);
    MatCreate(h->comm, &J);
    MatSetSizes(J, n_own, n_own, 3 * (PetscInt)sc->n_nodes, 3 * (PetscInt)sc->n_nodes);
    MatSetType(J, MATAIJ);
  } else if (jac_pattern_matrix(&h->jp, h->mat_type, &J)) {
    return 1;
  }
  h->fresh = 1;
  SNESCreate(h->comm, &snes);
  SNESSetType(snes, SNESNEWTONLS);
  SNESGetLineSearch(snes, &ls);
  SNESLineSearchSetType(ls, SNESLINESEARCHBASIC);
  SNESSetFunction(snes, F, form_residual, h);
  SNESSetJacobian(snes, J, J, h->use_coo ? form_jacobian_coo : form_jacobian, h);
  SNESSetConvergenceTest(snes, converged_test, h, NULL);
  SNESSetTolerances(snes, 0.0, 0.0, 0.0, h->max_it + 1, 1000000);
  SNESGetKSP(snes, &ksp);
  KSPGetPC(ksp, &pc);
  if (sc->direct_solver) {
    /* MUMPS LU: the same solution on any number of ranks to rounding */
    KSPSetType(ksp, KSPPREONLY);
    PCSetType(pc, PCLU);
    PCFactorSetMatSolverType(pc, MATSOLVERMUMPS);
  } else {
    /* the network's 3-D contact graph fills an LU badly (MUMPS on
     * Debian's reference BLAS: seconds per factorization at 5000
     * segments); GMRES with additive Schwarz, overlap 1, ILU(0) on each
     * rank's block (on one rank: ILU(0)), solved far enough (1e-10) that
     * Newton's convergence test decides alone. Block Jacobi (no overlap)
     * took 44 iterations per solve on 2 ranks against 22 on one (4800
     * segments); the overlap brings it to 26. A solve that has not
     * converged in 400 iterations fails the Newton step (a cut-back). */
    KSPSetType(ksp, KSPGMRES);
    KSPGMRESSetRestart(ksp, 200);
    KSPSetTolerances(ksp, 1e-10, 0.0, PETSC_DEFAULT, 400);
    PCSetType(pc, PCASM);
    PCASMSetOverlap(pc, 1);
  }
  SNESSetFromOptions(snes);

  /* the initial configuration, committed: the crossing check's reference */
  VecSet(U, 0.0);
  h->t = 0.0;
  int fail = 0;
  if (local_state(h, U) || contact_host_update(&h->ch, h->x, 0, h->msg, sizeof h->msg) ||
      b2b_model_commit(h->ch.model, h->msg, sizeof h->msg)) {
    PetscPrintf(h->comm, "initial update failed: %s\n", h->msg);
    fail = 1;
  }
  const double nominal = sc->t_end / sc->n_steps, dt_min = nominal / 64;
  double t = 0.0, dt = nominal;
  int step = 0, good = 0;
  VecCopy(U, Uc);
  while (!fail && t < sc->t_end * (1 - 1e-12)) {
    const double t_new = fmin(t + dt, sc->t_end);
    h->t = t_new;
    h->domain_error = 0;
    h->ch.migrations_step = 0;
    const double t0 = MPI_Wtime();
    SNESSolve(snes, NULL, U);
    const double t_step = MPI_Wtime() - t0;
    SNESConvergedReason reason;
    PetscInt its;
    SNESGetConvergedReason(snes, &reason);
    SNESGetIterationNumber(snes, &its);
    h->newton_its += its;
    int counts[B2B_MODEL_COUNTS_LEN] = {0};
    double totals[B2B_MODEL_TOTALS_LEN] = {0};
    int ok = reason > 0 && h->have_update;
    if (ok) {
      fe_host_global_counts(h, counts, totals);
      ok = counts[B2B_COUNT_CROSSED] == 0 && counts[B2B_COUNT_LOST] == 0;
    }
    if (ok) {
      ++step;
      t = t_new;
      VecCopy(U, Uc);
      int64_t mig = h->ch.migrations_step, mig_all = 0;
      MPI_Allreduce(&mig, &mig_all, 1, MPI_INT64_T, MPI_SUM, h->comm);
      PetscPrintf(h->comm, "step %2d  t %.5f  Newton %2d  active %6d  slip %6d  handovers %4d  "
                  "migrated %lld  f_N sum %.6e  min gap %.3e  %.2f s\n",
                  step, t, (int)its, counts[B2B_COUNT_ACTIVE], counts[B2B_COUNT_SLIP],
                  counts[B2B_COUNT_HANDOVERS], (long long)mig_all,
                  totals[B2B_TOTAL_NORMAL_FORCE], totals[B2B_TOTAL_MIN_GAP], t_step);
      if (h->verbose)
        PetscPrintf(h->comm, "  pairs: candidates %d, evaluated %d, open %d, outside %d, far %d; "
                    "searches since setup %d (summed over ranks)\n",
                    counts[B2B_COUNT_CANDIDATES], counts[B2B_COUNT_EVALUATED],
                    counts[B2B_COUNT_OPEN], counts[B2B_COUNT_OUTSIDE], counts[B2B_COUNT_FAR],
                    counts[B2B_COUNT_SEARCH_BUILDS]);
      /* the converged state is reported, then committed */
      if (report && report(h, step, U, data)) fail = 1;
      if (b2b_model_commit(h->ch.model, h->msg, sizeof h->msg)) {
        fprintf(stderr, "rank %d: commit: %s\n", h->rank, h->msg);
        fail = 1;
      }
      if (++good >= 2 && dt < nominal) {
        dt = fmin(2 * dt, nominal); /* back towards the nominal step after two that went well */
        good = 0;
      }
    } else {
      PetscPrintf(h->comm, "step at t %.5f cut back (Newton %s after %d, crossed %d, lost %d)\n",
                  t_new, SNESConvergedReasons[reason], (int)its, counts[B2B_COUNT_CROSSED],
                  counts[B2B_COUNT_LOST]);
      if (b2b_model_revert(h->ch.model, h->msg, sizeof h->msg)) {
        fprintf(stderr, "rank %d: revert: %s\n", h->rank, h->msg);
        fail = 1;
        break;
      }
      VecCopy(Uc, U);
      dt *= 0.5;
      good = 0;
      if (dt < dt_min) {
        PetscPrintf(h->comm, "step below %g: giving up\n", dt_min);
        fail = 1;
      }
    }
  }
  SNESDestroy(&snes);
  MatDestroy(&J);
  VecDestroy(&F);
  VecDestroy(&Uc);
  return fail;
}
