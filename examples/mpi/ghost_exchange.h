/* The ghost-coordinate exchange: each rank receives the current
 * displacements of the nodes of its ghost and padding segments from their
 * owners (MPI_Alltoallv; the lists are set up once by asking each owner). */
#ifndef MPI_GHOST_EXCHANGE_H
#define MPI_GHOST_EXCHANGE_H

#include <mpi.h>
#include <stdint.h>

#include "partition.h"

typedef struct {
  MPI_Comm comm;
  int size;
  int *send_counts, *send_displs, *recv_counts, *recv_displs; /* in doubles */
  int *send_local; /* own local nodes to pack, grouped by destination rank */
  int *recv_local; /* ghost local nodes to fill, grouped by source rank */
  int n_send, n_recv; /* nodes */
  double *sendbuf, *recvbuf;
  int64_t bytes_sent, bytes_received, n_exchanges; /* totals since setup */
} ghost_exchange;

/* own_index[k]: global node k's index in its owner's own-node list. */
int ghost_exchange_setup(ghost_exchange *gx, MPI_Comm comm, const part *pp, const partition *pt,
                         const int *own_index);
/* u: 3 * n_local_nodes; fills the entries of the ghost nodes from the owners'. */
int ghost_exchange_run(ghost_exchange *gx, double *u);
void ghost_exchange_free(ghost_exchange *gx);

#endif
