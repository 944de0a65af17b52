/* The Jacobian's nonzero pattern in 3 x 3 node blocks, grown only: the
 * host's elements (fixed) and every contact pair that has been active at
 * some Jacobian of the run (its 8 x 8 node blocks, kept, as zeros, after
 * the contact opens). A contact pair that closes again, or stays closed,
 * then finds its entries in place: the matrix is preallocated anew only
 * when a pair comes into contact for the first time, which after the
 * first iterations of a run is rare. Preallocating every time the contact
 * set changed (MatSetPreallocationCOO, which sorts every entry: 1500
 * instructions per entry in PETSc 3.18) cost more than the linear solves.
 *
 * Per rank: a hash set of the pairs in the pattern (global segment ids),
 * a hash set of the node blocks this rank adds, and per local node the
 * number of its row's blocks, inside and outside the row owner's diagonal
 * block; the owners sum the counts of their rows over the ranks (an upper
 * bound where two ranks add the same block) for MatXAIJSetPreallocation. */
#ifndef MPI_JACOBIAN_PATTERN_H
#define MPI_JACOBIAN_PATTERN_H

#include <petscmat.h>
#include <stdint.h>

typedef struct {
  int64_t *keys; /* -1: empty */
  int *vals;
  size_t cap, n;
} key_set;

typedef struct {
  MPI_Comm comm;
  int n_local, n_own;        /* local nodes (own first), own nodes */
  int64_t n_blocks_global;   /* global block rows (nodes) */
  const int *block;          /* local node -> global block row */
  const int *row_lo, *row_hi; /* local node -> its owner's block rows [lo, hi) */
  key_set pairs;             /* contact pairs in the pattern -> index */
  int n_pairs, cap_pairs;
  int *pair_nodes;           /* 8 local nodes (or -1) per pair */
  int n_new;                 /* pairs added since the last preallocation */
  key_set blocks;            /* (row, col) node blocks this rank adds */
  PetscInt *d_count, *o_count; /* per local node */
} jac_pattern;

/* block[l], row_lo[l], row_hi[l] for the n_local local nodes (kept, not copied). */
int jac_pattern_init(jac_pattern *jp, MPI_Comm comm, int n_local, int n_own,
                     int64_t n_blocks_global, const int *block, const int *row_lo,
                     const int *row_hi);
void jac_pattern_free(jac_pattern *jp);

/* An element on local nodes nodes[0 .. n) (n <= 8; -1 entries skipped):
 * all its n x n blocks. Returns 1 on allocation failure. */
int jac_pattern_add_element(jac_pattern *jp, const int *nodes, int n);

/* A contact pair (key: its global segments) with its 8 local nodes (-1:
 * none): *added = 1 if it was not in the pattern yet. Returns 1 on
 * allocation failure. */
int jac_pattern_add_pair(jac_pattern *jp, int64_t key, const int nodes[8], int *added);

/* A new matrix (type `type`, block size 3) preallocated for the pattern
 * (collective: the counts of other ranks' rows go to their owners), with
 * the pairs' blocks set to zero (unassembled: the caller adds its values,
 * the host's elements among them, and assembles; after that first
 * assembly MAT_NEW_NONZERO_LOCATION_ERR makes a location outside the
 * pattern an error). Resets n_new. */
PetscErrorCode jac_pattern_matrix(jac_pattern *jp, MatType type, Mat *J);

#endif
