/* The MPI/PETSc example host (issue 21): a contact scene partitioned over
 * the ranks, solved by SNES Newton with a KSP (slide: MUMPS LU; network:
 * GMRES and additive Schwarz) on the host's beam elements and b2b's
 * contacts, the contact models coupled by the ghost-coordinate exchange
 * and the migration protocol of doc/distributed.md.
 *
 *   mpi_host -scene slide|network [-layers L -fibres F -segments S]
 *            [-out FILE] [-verbose] [-verbose_level N] [-scaling]
 *            [-mu MU -eps_t EPS -strain S -steps N -search_margin S]
 *            [-host_mat_type baij|aij] [-jacobian block|coo] [PETSc options]
 *
 * slide:   a slider pressed onto two base beams and dragged along them with
 *          friction across the 2-rank cut; prints the friction force
 *          against mu P.
 * network: L layers of F curved fibres of S segments (default 40 x 50 x 50
 *          = 10^5 segments) compressed in z, with friction.
 * -verbose: Newton's residuals and the step's pair counts; -verbose_level
 *          2: also the Jacobian pattern per rank, 3: the contact counts
 *          per Newton iteration.
 * -out:    the result file (results.h) for compare_results.
 * -scaling: no solve; the ghost layer and exchanged bytes for 2 .. 1024
 *          parts of the scene (scaling.c).
 * Exits non-zero when a step cannot be solved or a check fails. */
#include <math.h>
#include <petscsnes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fe_host.h"
#include "partition.h"
#include "results.h"
#include "scaling.h"
#include "scene.h"

typedef struct {
  step_log log;
  int slip_steps, bad_friction;
  double worst_closed, worst_contacts;
  int max_active;
} report_data;

/* After each converged step: the scene's forces, summed over ranks. */
static int report_step(fe_host *h, int step, Vec U, void *data) {
  (void)step;
  (void)U;
  report_data *rd = data;
  const scene *sc = h->sc;
  int counts[B2B_MODEL_COUNTS_LEN];
  double totals[B2B_MODEL_TOTALS_LEN];
  fe_host_global_counts(h, counts, totals);
  if (counts[B2B_COUNT_ACTIVE] > rd->max_active) rd->max_active = counts[B2B_COUNT_ACTIVE];
  if (sc->kind == SCENE_SLIDE) {
    /* the drag springs' pull on the slider, and the contacts' friction on it */
    double mine[2] = {0, 0}, sum[2];
    for (int l = 0; l < h->pp->n_own_nodes; ++l) {
      const int k = h->pp->local_nodes[l];
      if (h->node_beam[k] != sc->slider) continue;
      double a[3], f[3];
      scene_load(sc, k, h->t, a, f);
      mine[0] += sc->anchor_k[3 * k] * (a[0] - h->x[3 * l]);
    }
    int nc = 0;
    b2b_model_contact_count(h->ch.model, &nc, h->msg, sizeof h->msg);
    for (int k = 0; k < nc; ++k) {
      double info[32];
      b2b_model_get_contact(h->ch.model, k, NULL, NULL, info, NULL, NULL, 24, h->msg, sizeof h->msg);
      const double *T = info + B2B_INFO_TANGENTIAL_FORCE;
      mine[1] += sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]);
    }
    MPI_Allreduce(mine, sum, 2, MPI_DOUBLE, MPI_SUM, h->comm);
    const double N = totals[B2B_TOTAL_NORMAL_FORCE], muP = sc->mu * sc->press;
    const int slipping = h->t > 1.0 && counts[B2B_COUNT_SLIP] == counts[B2B_COUNT_ACTIVE] &&
                         counts[B2B_COUNT_ACTIVE] > 0;
    PetscPrintf(h->comm, "  slide %.4f  drag %.10f  mu P %.4f  mu sum f_N %.10f  sum |T| %.10f%s\n",
                h->t > 1.0 ? sc->slide * (h->t - 1.0) : 0.0, sum[0], muP, sc->mu * N, sum[1],
                slipping ? "  (all slip)" : "");
    if (slipping) {
      rd->slip_steps++;
      rd->worst_closed = fmax(rd->worst_closed, fabs(sum[0] - muP) / muP);
      rd->worst_contacts = fmax(rd->worst_contacts, fabs(sum[1] - sc->mu * N) / (sc->mu * N));
    }
    return step_log_add(&rd->log, h->t, sum[0], N, sum[1]);
  }
  return step_log_add(&rd->log, h->t, totals[B2B_TOTAL_NORMAL_FORCE], totals[B2B_TOTAL_ENERGY],
                      counts[B2B_COUNT_ACTIVE]);
}

int main(int argc, char **argv) {
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  MPI_Comm comm = PETSC_COMM_WORLD;
  int rank, size;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  char scene_name[64] = "slide", out[PETSC_MAX_PATH_LEN] = "";
  PetscInt layers = 40, fibres = 50, segments = 50;
  PetscBool scaling = PETSC_FALSE, verbose = PETSC_FALSE;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-scene", scene_name, sizeof scene_name, NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-out", out, sizeof out, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-layers", &layers, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-fibres", &fibres, NULL));
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-segments", &segments, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-scaling", &scaling, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-verbose", &verbose, NULL));

  scene sc;
  int bad = 0;
  if (strcmp(scene_name, "slide") == 0) bad = scene_slide(&sc);
  else if (strcmp(scene_name, "network") == 0)
    bad = scene_network(&sc, (int)layers, (int)fibres, (int)segments, 12345u);
  else {
    PetscPrintf(comm, "mpi_host: unknown scene '%s' (slide, network)\n", scene_name);
    PetscFinalize();
    return 2;
  }
  if (bad) {
    PetscPrintf(comm, "mpi_host: out of memory building the scene\n");
    PetscFinalize();
    return 1;
  }
  /* overrides of the scene's constants */
  PetscReal value;
  PetscBool set;
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-mu", &value, &set));
  if (set) sc.mu = value;
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-strain", &value, &set));
  if (set) sc.strain = value;
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-eps_t", &value, &set));
  if (set) sc.eps_t = value;
  PetscCall(PetscOptionsGetReal(NULL, NULL, "-search_margin", &value, &set));
  if (set) sc.search_margin = value;
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-steps", &layers, &set));
  if (set) sc.n_steps = (int)layers;
  if (scaling) {
    const int parts[] = {2, 4, 8, 16, 32, 64, 128, 256, 512, 1024};
    if (rank == 0) bad = scaling_study(&sc, parts, (int)(sizeof parts / sizeof parts[0]));
    scene_free(&sc);
    PetscFinalize();
    return bad;
  }
  const double t_start = MPI_Wtime();
  partition pt;
  part pp;
  unsigned char **ghost = malloc(sizeof(unsigned char *) * (size_t)size);
  for (int p = 0; p < size; ++p) ghost[p] = malloc((size_t)sc.n_segments);
  if (partition_rcb(&sc, size, &pt) || ghost_flags(&sc, &pt, partition_reach(&sc), ghost) ||
      part_build(&sc, &pt, rank, ghost[rank], &pp)) {
    fprintf(stderr, "rank %d: partitioning failed (memory)\n", rank);
    MPI_Abort(comm, 1);
  }
  for (int p = 0; p < size; ++p) free(ghost[p]);
  free(ghost);
  PetscPrintf(comm, "scene %s: %d beams, %d segments, %d nodes, %d dofs, %d rank(s)\n", sc.name,
              sc.n_beams, sc.n_segments, sc.n_nodes, 3 * sc.n_nodes, size);
  PetscCall(PetscSynchronizedPrintf(comm, "  rank %d: own segments %d, ghost %d, padding %d, "
            "pieces %d, own nodes %d, ghost nodes %d\n", rank, pp.n_own_segments,
            pp.n_ghost_segments, pp.n_padding_segments, pp.n_pieces, pp.n_own_nodes,
            pp.n_local_nodes - pp.n_own_nodes));
  PetscCall(PetscSynchronizedFlush(comm, PETSC_STDOUT));

  fe_host h;
  if (fe_host_setup(&h, comm, &sc, &pt, &pp)) {
    PetscPrintf(comm, "mpi_host: setup failed\n");
    PetscFinalize();
    return 1;
  }
  h.verbose = verbose;
  PetscInt vlevel = 0;
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-verbose_level", &vlevel, &set));
  if (set) h.verbose = (int)vlevel;
  Vec U;
  PetscCall(VecCreateMPI(comm, 3 * pp.n_own_nodes, 3 * sc.n_nodes, &U));
  report_data rd;
  memset(&rd, 0, sizeof rd);
  const double t_setup = MPI_Wtime() - t_start;
  int fail = fe_host_solve(&h, U, report_step, &rd);
  const double t_solve = MPI_Wtime() - t_start - t_setup;

  /* communication, per rank */
  PetscCall(PetscSynchronizedPrintf(comm,
            "  rank %d: Newton iterations %lld, residuals %lld; bytes sent: ghost coordinates %lld, "
            "residual rows of ghosts %lld, Jacobian blocks of other ranks' rows %lld (of %lld), "
            "migration %lld (%lld contacts, %lld extra updates)\n", rank,
            (long long)h.newton_its, (long long)h.residuals, (long long)h.gx.bytes_sent,
            (long long)(h.res_offproc * (PetscInt)(sizeof(PetscInt) + sizeof(double))),
            (long long)(h.jac_offproc * (PetscInt)(2 * sizeof(PetscInt) + 9 * sizeof(double))),
            (long long)(h.jac_blocks * (PetscInt)(2 * sizeof(PetscInt) + 9 * sizeof(double))),
            (long long)h.ch.migration_bytes_sent, (long long)h.ch.migrations_sent,
            (long long)h.ch.extra_updates));
  PetscCall(PetscSynchronizedPrintf(comm, "  rank %d: time in b2b update + exchange %.2f s, "
            "assembly %.2f s\n", rank, h.time_update, h.time_assembly));
  PetscCall(PetscSynchronizedFlush(comm, PETSC_STDOUT));
  PetscPrintf(comm, "time: setup %.2f s, solve %.2f s (%d rank(s))\n", t_setup, t_solve, size);

  if (!fail && out[0]) fail = results_write(&h, U, &rd.log, out);
  /* the scene's checks */
  if (!fail && sc.kind == SCENE_SLIDE) {
    /* Slipping, each contact's friction is mu f_N (Coulomb); the drag
     * springs balance the friction plus the normal forces' x part, which
     * the base's sag under the slider tilts, either way as the contacts
     * move between its nodes: drag = mu P to that tilt. */
    PetscPrintf(comm, "slide: %d steps with every contact slipping; sum |T| against mu sum f_N: "
                "worst relative difference %.3e (bound 1e-12); drag against mu P %.3e (bound "
                "1e-2)\n", rd.slip_steps, rd.worst_contacts, rd.worst_closed);
    if (rd.slip_steps < 5 || rd.worst_closed > 1e-2 || rd.worst_contacts > 1e-12) fail = 1;
    int64_t mig = 0, mig_all = 0;
    mig = h.ch.migrations_sent;
    MPI_Allreduce(&mig, &mig_all, 1, MPI_INT64_T, MPI_SUM, comm);
    if (size > 1 && mig_all == 0) {
      PetscPrintf(comm, "slide: no contact migrated between the ranks\n");
      fail = 1;
    }
  }
  if (!fail && sc.kind == SCENE_NETWORK) {
    int counts[B2B_MODEL_COUNTS_LEN];
    double totals[B2B_MODEL_TOTALS_LEN];
    fe_host_global_counts(&h, counts, totals);
    PetscPrintf(comm, "network: most active contacts %d; at the end %d active, %d slipping\n",
                rd.max_active, counts[B2B_COUNT_ACTIVE], counts[B2B_COUNT_SLIP]);
    /* a genuine contact scene: many contacts, and with friction some slip */
    if (rd.max_active < 100 || (sc.mu > 0 && counts[B2B_COUNT_SLIP] == 0)) fail = 1;
  }
  PetscPrintf(comm, "%s\n", fail ? "FAILED" : "ok");
  VecDestroy(&U);
  fe_host_free(&h);
  part_free(&pp);
  partition_free(&pt);
  scene_free(&sc);
  free(rd.log.rows);
  PetscFinalize();
  return fail;
}
