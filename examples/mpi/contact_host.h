/* One rank's b2b contact model: its pieces of the global beams (own, ghost
 * and padding segments, with their global ids), and the update of a Newton
 * iteration with the migration protocol of doc/distributed.md. */
#ifndef MPI_CONTACT_HOST_H
#define MPI_CONTACT_HOST_H

#include <mpi.h>
#include <stdint.h>

#include <b2b/b2b.h>

#include "partition.h"

typedef struct {
  b2b_model *model;
  b2b_params *params;
  MPI_Comm comm;
  int rank, size;
  const scene *sc;
  const partition *pt;
  const part *pp;
  int n_local_nodes;
  /* migration, totals since build */
  int64_t migrations_sent, migration_bytes_sent, migration_bytes_received, extra_updates;
  int64_t migrations_step; /* contacts sent in the updates since the last commit */
} contact_host;

/* Builds and finalizes part pp's model: one local beam per piece (local
 * nodes: pp->local_nodes' order), global ids, cuts and ghost ranges.
 * Collective. */
int contact_host_build(contact_host *ch, MPI_Comm comm, const scene *sc, const partition *pt,
                       const part *pp, char *msg, int msg_len);
/* x: 3 * n_local_nodes current coordinates. b2b_model_update on every rank,
 * then migration rounds until no rank's received set changes. Collective;
 * a failure on any rank is a failure on all (status != 0; msg set where it
 * failed, "failed on another rank" elsewhere). */
int contact_host_update(contact_host *ch, const double *x, int want_tangent, char *msg,
                        int msg_len);
/* Contact k's global pair (beam A, segment A, beam B, segment B). */
int contact_host_global_pair(const contact_host *ch, int k, int64_t pair[4], char *msg,
                             int msg_len);
void contact_host_free(contact_host *ch);

#endif
