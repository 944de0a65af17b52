/* The host's finite-element side on one rank: its dofs in PETSc's global
 * numbering, the SNES residual and Jacobian callbacks (its own elements
 * plus b2b's contacts), and the load steps with commit and cut-back. */
#ifndef MPI_FE_HOST_H
#define MPI_FE_HOST_H

#include <petscsnes.h>
#include <stdint.h>

#include "contact_host.h"
#include "ghost_exchange.h"
#include "jacobian_pattern.h"

typedef struct {
  MPI_Comm comm;
  int rank, size;
  const scene *sc;
  const partition *pt;
  const part *pp;
  contact_host ch;
  ghost_exchange gx;
  int *local_of;     /* global node -> local node, -1 if not local */
  int *own_index;    /* global node -> its index among its owner's own nodes */
  int *node_beam;    /* global node -> its global beam */
  int *node_offset;  /* size + 1: each rank's first equation / 3 */
  PetscInt *gdof;    /* 3 * n_local: global equation of each local dof */
  int *eq_local, *eq_global; /* the same for b2b: local and global numbering */
  double *u, *x, *f; /* 3 * n_local: displacements, current coordinates, residual */
  double t;          /* load parameter of the step being solved */
  double ftol;       /* convergence: ||F|| <= ftol */
  int max_it, verbose;
  double *u_at;      /* own dofs of the last update, to know the Jacobian's point */
  int have_update, domain_error;
  char msg[B2B_ERRMSG_LEN];
  /* measurements, totals since setup */
  int64_t residuals, jacobians, newton_its;
  int64_t res_offproc;             /* residual entries sent to other ranks in assembly */
  int64_t jac_offproc, jac_blocks; /* Jacobian 3 x 3 blocks: in other ranks' rows, all */
  double time_update, time_assembly, time_solve;
  int64_t preallocations;
  /* the Jacobian: its grown-only pattern (jacobian_pattern.h) */
  jac_pattern jp;
  int *block, *row_lo, *row_hi; /* local node: global block row, its owner's rows */
  char mat_type[64];            /* -host_mat_type: baij (default) or aij */
  int fresh;                    /* the matrix has not been assembled yet */
  /* -jacobian coo: the Jacobian as COO entries (the host's elements and
   * b2b_model_tangent_coo), through MatSetPreallocationCOO/MatSetValuesCOO;
   * the last preallocated pattern */
  int use_coo;
  PetscInt *coo_i, *coo_j;
  PetscCount coo_n;
} fe_host;

/* Builds everything for part pp: maps, the ghost exchange, b2b's model. Collective. */
int fe_host_setup(fe_host *h, MPI_Comm comm, const scene *sc, const partition *pt, const part *pp);
void fe_host_free(fe_host *h);

/* Called after each committed step (rank-local data; collective calls allowed). */
typedef int (*step_report)(fe_host *h, int step, Vec U, void *data);

/* Solves the load path t = 0 .. sc->t_end in sc->n_steps steps, halving a
 * step on failure (Newton not converged, a b2b error, crossed or lost
 * contacts), committing each converged one. U: the displacements at the
 * end. Returns 0, or 1 when a step could not be solved. Collective. */
int fe_host_solve(fe_host *h, Vec U, step_report report, void *data);

/* Summed over ranks. */
void fe_host_global_counts(fe_host *h, int counts[B2B_MODEL_COUNTS_LEN],
                           double totals[B2B_MODEL_TOTALS_LEN]);

#endif
