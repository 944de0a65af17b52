/* One rank's contact model and its update with migration (contact_host.h). */
#include "contact_host.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void contact_host_free(contact_host *ch) {
  b2b_model_destroy(&ch->model);
  b2b_params_destroy(&ch->params);
}

int contact_host_build(contact_host *ch, MPI_Comm comm, const scene *sc, const partition *pt,
                       const part *pp, char *msg, int msg_len) {
  memset(ch, 0, sizeof *ch);
  ch->comm = comm;
  MPI_Comm_rank(comm, &ch->rank);
  MPI_Comm_size(comm, &ch->size);
  ch->sc = sc;
  ch->pt = pt;
  ch->pp = pp;
  ch->n_local_nodes = pp->n_local_nodes;
  int st = 0;
  b2b_params *p = NULL;
  if ((st = b2b_params_create(&p, msg, msg_len))) return st;
  ch->params = p;
  if ((st = b2b_params_set_real(p, "penalty", sc->penalty, msg, msg_len)) ||
      (st = b2b_params_set_int(p, "law", B2B_LAW_QUADRATIC, msg, msg_len)) ||
      (st = b2b_params_set_real(p, "regularization_gap", sc->reg_gap, msg, msg_len)) ||
      (st = b2b_params_set_real(p, "friction", sc->mu, msg, msg_len)) ||
      (st = b2b_params_set_real(p, "tangential_penalty", sc->eps_t, msg, msg_len)) ||
      (st = b2b_params_finalize(p, msg, msg_len)))
    return st;
  if ((st = b2b_model_create(&ch->model, msg, msg_len))) return st;
  /* one thread per rank: the ranks share the machine's cores */
  if ((st = b2b_model_set_int(ch->model, "threads", 1, msg, msg_len))) return st;
  /* the same search margin on every rank (doc/distributed.md, section 3):
   * the default, the largest radius of the model's beams, could differ */
  if ((st = b2b_model_set_real(ch->model, "search_margin", sc->search_margin, msg, msg_len)))
    return st;
  /* global node -> local node */
  int *local = malloc(sizeof(int) * (size_t)sc->n_nodes);
  int *nodes = malloc(sizeof(int) * (size_t)(sc->n_nodes + 1));
  if (!local || !nodes) {
    free(local);
    free(nodes);
    snprintf(msg, (size_t)msg_len, "out of memory");
    return B2B_ERR_NOMEM;
  }
  for (int l = 0; l < pp->n_local_nodes; ++l) local[pp->local_nodes[l]] = l;
  for (int i = 0; i < pp->n_pieces && !st; ++i) {
    const piece *pc = pp->pieces + i;
    const int first = sc->first_node[pc->beam] + pc->first_segment;
    for (int j = 0; j <= pc->n_segments; ++j) nodes[j] = local[first + j];
    int beam = -1;
    st = b2b_model_add_beam(ch->model, nodes, pc->n_segments + 1, 0, sc->radius,
                            B2B_CURVE_HERMITE_NODAL, 0, &beam, msg, msg_len);
    if (!st)
      st = b2b_model_set_beam_global(ch->model, beam, pc->beam, pc->first_segment, pc->start_cut,
                                     pc->end_cut, msg, msg_len);
    /* ghost ranges: the ghosts, and the padding at cuts (owned elsewhere too) */
    const unsigned char *s = pp->seg_state + scene_segment(sc, pc->beam, pc->first_segment);
    for (int j = 0; j < pc->n_segments && !st;) {
      if (s[j] == SEG_OWN) {
        ++j;
        continue;
      }
      int e = j;
      while (e < pc->n_segments && s[e] != SEG_OWN) ++e;
      st = b2b_model_set_ghost_segments(ch->model, beam, j, e - j, msg, msg_len);
      j = e;
    }
  }
  free(local);
  free(nodes);
  if (!st) st = b2b_model_set_group_pair(ch->model, 0, 0, p, msg, msg_len);
  if (!st) st = b2b_model_finalize(ch->model, pp->n_local_nodes, msg, msg_len);
  int bad = st != 0, any = 0;
  MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, comm);
  if (any && !st) {
    snprintf(msg, (size_t)msg_len, "model build failed on another rank");
    st = B2B_ERR_STATE;
  }
  return st;
}

int contact_host_global_pair(const contact_host *ch, int k, int64_t pair[4], char *msg,
                             int msg_len) {
  return b2b_model_get_contact_global(ch->model, k, pair, msg, msg_len);
}

/* The owner of a pair: the rank of its smaller segment (global ids). */
static int pair_owner(const contact_host *ch, const int64_t t[4]) {
  const int a_smaller = t[0] < t[2] || (t[0] == t[2] && t[1] <= t[3]);
  const int64_t b = a_smaller ? t[0] : t[2], s = a_smaller ? t[1] : t[3];
  return ch->pt->seg_owner[scene_segment(ch->sc, (int)b, (int)s)];
}

/* One migration round: every rank sends its migrating contacts to their
 * targets' owners and unpacks what it receives; *changed_any: did any
 * rank's received set change. Collective. */
static int migrate(contact_host *ch, int *changed_any, char *msg, int msg_len) {
  const int P = ch->size;
  int n = 0, st = b2b_model_migration_count(ch->model, &n, msg, msg_len);
  int *dest = malloc(sizeof(int) * (size_t)(n + 1));
  int64_t *size = malloc(sizeof(int64_t) * (size_t)(n + 1));
  int *scount = calloc((size_t)P, sizeof(int)), *rcount = calloc((size_t)P, sizeof(int));
  int *sdispl = calloc((size_t)P + 1, sizeof(int)), *rdispl = calloc((size_t)P + 1, sizeof(int));
  char *sbuf = NULL, *rbuf = NULL;
  if (!dest || !size || !scount || !rcount || !sdispl || !rdispl) st = B2B_ERR_NOMEM;
  for (int k = 0; k < n && !st; ++k) {
    int64_t t[4];
    st = b2b_model_migration_info(ch->model, k, t, &size[k], msg, msg_len);
    if (st) break;
    dest[k] = pair_owner(ch, t);
    if (dest[k] == ch->rank) {
      snprintf(msg, (size_t)msg_len, "migrating contact %d targets pair (%lld,%lld)-(%lld,%lld), "
               "which this rank owns", k, (long long)t[0], (long long)t[1], (long long)t[2],
               (long long)t[3]);
      st = B2B_ERR_STATE;
      break;
    }
    /* framing: the size as 8 bytes, then the packed bytes padded to 8 */
    scount[dest[k]] += 8 + (int)((size[k] + 7) / 8 * 8);
  }
  if (!st) {
    for (int q = 0; q < P; ++q) sdispl[q + 1] = sdispl[q] + scount[q];
    sbuf = calloc((size_t)sdispl[P] + 8, 1);
    if (!sbuf) st = B2B_ERR_NOMEM;
  }
  if (!st) {
    int *fill = calloc((size_t)P, sizeof(int));
    if (!fill) st = B2B_ERR_NOMEM;
    for (int k = 0; k < n && !st; ++k) {
      char *at = sbuf + sdispl[dest[k]] + fill[dest[k]];
      memcpy(at, &size[k], 8);
      st = b2b_model_migration_pack(ch->model, k, at + 8, size[k], msg, msg_len);
      fill[dest[k]] += 8 + (int)((size[k] + 7) / 8 * 8);
    }
    free(fill);
  }
  int bad = st != 0, any = 0;
  MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, ch->comm);
  int changed = 0;
  if (!any) {
    MPI_Alltoall(scount, 1, MPI_INT, rcount, 1, MPI_INT, ch->comm);
    for (int q = 0; q < P; ++q) rdispl[q + 1] = rdispl[q] + rcount[q];
    rbuf = malloc((size_t)rdispl[P] + 8);
    MPI_Alltoallv(sbuf, scount, sdispl, MPI_BYTE, rbuf, rcount, rdispl, MPI_BYTE, ch->comm);
    ch->migrations_sent += n;
    ch->migrations_step += n;
    ch->migration_bytes_sent += sdispl[P];
    ch->migration_bytes_received += rdispl[P];
    for (int off = 0; off < rdispl[P] && !st;) {
      int64_t sz;
      memcpy(&sz, rbuf + off, 8);
      int ch1 = 0;
      st = b2b_model_migration_unpack(ch->model, rbuf + off + 8, sz, &ch1, msg, msg_len);
      changed |= ch1;
      off += 8 + (int)((sz + 7) / 8 * 8);
    }
    /* the end of the round: received contacts no rank sent again are dropped */
    if (!st) {
      int ch1 = 0;
      st = b2b_model_migration_unpack(ch->model, NULL, 0, &ch1, msg, msg_len);
      changed |= ch1;
    }
    bad = st != 0;
    MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, ch->comm);
  }
  if (any && !st) {
    snprintf(msg, (size_t)msg_len, "migration failed on another rank");
    st = B2B_ERR_STATE;
  }
  MPI_Allreduce(&changed, changed_any, 1, MPI_INT, MPI_MAX, ch->comm);
  free(dest);
  free(size);
  free(scount);
  free(rcount);
  free(sdispl);
  free(rdispl);
  free(sbuf);
  free(rbuf);
  return st;
}

int contact_host_update(contact_host *ch, const double *x, int want_tangent, char *msg,
                        int msg_len) {
  for (int round = 0;; ++round) {
    int st = b2b_model_update(ch->model, x, 3, ch->n_local_nodes, want_tangent, msg, msg_len);
    int bad = st != 0, any = 0;
    MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, ch->comm);
    if (any) {
      if (!st) snprintf(msg, (size_t)msg_len, "update failed on another rank");
      return st ? st : B2B_ERR_STATE;
    }
    int changed = 0;
    if ((st = migrate(ch, &changed, msg, msg_len))) return st;
    if (!changed) return 0;
    /* each round carries contacts one partition boundary further */
    if (round >= ch->size + 2) {
      snprintf(msg, (size_t)msg_len, "migration did not settle in %d rounds", round + 1);
      return B2B_ERR_STATE;
    }
    ch->extra_updates++;
  }
}
