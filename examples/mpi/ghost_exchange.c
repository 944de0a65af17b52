/* The ghost-coordinate exchange (ghost_exchange.h). */
#include "ghost_exchange.h"

#include <stdlib.h>
#include <string.h>

void ghost_exchange_free(ghost_exchange *gx) {
  free(gx->send_counts);
  free(gx->send_displs);
  free(gx->recv_counts);
  free(gx->recv_displs);
  free(gx->send_local);
  free(gx->recv_local);
  free(gx->sendbuf);
  free(gx->recvbuf);
  memset(gx, 0, sizeof *gx);
}

int ghost_exchange_setup(ghost_exchange *gx, MPI_Comm comm, const part *pp, const partition *pt,
                         const int *own_index) {
  memset(gx, 0, sizeof *gx);
  gx->comm = comm;
  MPI_Comm_size(comm, &gx->size);
  const int P = gx->size, n_ghost = pp->n_local_nodes - pp->n_own_nodes;
  gx->send_counts = calloc((size_t)P, sizeof(int));
  gx->send_displs = calloc((size_t)P + 1, sizeof(int));
  gx->recv_counts = calloc((size_t)P, sizeof(int));
  gx->recv_displs = calloc((size_t)P + 1, sizeof(int));
  gx->recv_local = malloc(sizeof(int) * (size_t)(n_ghost + 1));
  int *ask = malloc(sizeof(int) * (size_t)(n_ghost + 1)); /* global ids asked of each owner */
  int *nask = calloc((size_t)P, sizeof(int)), *nasked = calloc((size_t)P, sizeof(int));
  int *askd = calloc((size_t)P + 1, sizeof(int)), *askedd = calloc((size_t)P + 1, sizeof(int));
  int ok = gx->send_counts && gx->send_displs && gx->recv_counts && gx->recv_displs &&
           gx->recv_local && ask && nask && nasked && askd && askedd;
  int *asked = NULL;
  if (ok) {
    for (int l = pp->n_own_nodes; l < pp->n_local_nodes; ++l) nask[pt->node_owner[pp->local_nodes[l]]]++;
    for (int q = 0; q < P; ++q) askd[q + 1] = askd[q] + nask[q];
    int *fill = calloc((size_t)P, sizeof(int));
    ok = fill != NULL;
    if (ok) {
      /* ghosts ascend by global id, so each owner's list does too */
      for (int l = pp->n_own_nodes; l < pp->n_local_nodes; ++l) {
        const int k = pp->local_nodes[l], q = pt->node_owner[k], at = askd[q] + fill[q]++;
        ask[at] = k;
        gx->recv_local[at] = l;
      }
      free(fill);
      MPI_Alltoall(nask, 1, MPI_INT, nasked, 1, MPI_INT, comm);
      for (int q = 0; q < P; ++q) askedd[q + 1] = askedd[q] + nasked[q];
      asked = malloc(sizeof(int) * (size_t)(askedd[P] + 1));
      ok = asked != NULL;
    }
  }
  /* every rank takes part in the collectives even when short of memory */
  int all_ok = 0;
  MPI_Allreduce(&ok, &all_ok, 1, MPI_INT, MPI_MIN, comm);
  if (all_ok) {
    MPI_Alltoallv(ask, nask, askd, MPI_INT, asked, nasked, askedd, MPI_INT, comm);
    gx->n_recv = n_ghost;
    gx->n_send = askedd[P];
    gx->send_local = malloc(sizeof(int) * (size_t)(gx->n_send + 1));
    gx->sendbuf = malloc(sizeof(double) * 3 * (size_t)(gx->n_send + 1));
    gx->recvbuf = malloc(sizeof(double) * 3 * (size_t)(gx->n_recv + 1));
    ok = gx->send_local && gx->sendbuf && gx->recvbuf;
    if (ok)
      for (int i = 0; i < gx->n_send; ++i) gx->send_local[i] = own_index[asked[i]];
    for (int q = 0; q < P; ++q) {
      gx->send_counts[q] = 3 * nasked[q];
      gx->send_displs[q] = 3 * askedd[q];
      gx->recv_counts[q] = 3 * nask[q];
      gx->recv_displs[q] = 3 * askd[q];
    }
    MPI_Allreduce(&ok, &all_ok, 1, MPI_INT, MPI_MIN, comm);
  }
  free(ask);
  free(asked);
  free(nask);
  free(nasked);
  free(askd);
  free(askedd);
  return !all_ok;
}

int ghost_exchange_run(ghost_exchange *gx, double *u) {
  for (int i = 0; i < gx->n_send; ++i)
    memcpy(gx->sendbuf + 3 * i, u + 3 * gx->send_local[i], 3 * sizeof(double));
  const int rc = MPI_Alltoallv(gx->sendbuf, gx->send_counts, gx->send_displs, MPI_DOUBLE,
                               gx->recvbuf, gx->recv_counts, gx->recv_displs, MPI_DOUBLE, gx->comm);
  for (int i = 0; i < gx->n_recv; ++i)
    memcpy(u + 3 * gx->recv_local[i], gx->recvbuf + 3 * i, 3 * sizeof(double));
  gx->bytes_sent += (int64_t)sizeof(double) * 3 * gx->n_send;
  gx->bytes_received += (int64_t)sizeof(double) * 3 * gx->n_recv;
  gx->n_exchanges++;
  return rc != MPI_SUCCESS;
}
