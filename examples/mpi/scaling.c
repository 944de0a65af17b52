/* Ghost layers and exchanged bytes against partition size (scaling.h). */
#include "scaling.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "partition.h"

int scaling_study(const scene *sc, const int *parts, int n_counts) {
  const double reach = partition_reach(sc);
  printf("%s: %d segments, %d nodes, ghost reach %.4g\n", sc->name, sc->n_segments, sc->n_nodes,
         reach);
  printf("| parts | own segments / part | ghost segments / part (mean, max) | padding / part | "
         "ghost / own (mean) | ghost nodes / part (max) | coordinate bytes received / iteration "
         "(max) | residual bytes sent / iteration (max, bound) |\n");
  printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int c = 0; c < n_counts; ++c) {
    const int P = parts[c];
    partition pt;
    if (partition_rcb(sc, P, &pt)) return 1;
    unsigned char **ghost = malloc(sizeof(unsigned char *) * (size_t)P);
    if (!ghost) return 1;
    for (int p = 0; p < P; ++p)
      if (!(ghost[p] = malloc((size_t)sc->n_segments))) return 1;
    if (ghost_flags(sc, &pt, reach, ghost)) return 1;
    double own = 0, gh = 0, pad = 0, ratio = 0;
    int gmax = 0, gnmax = 0;
    for (int p = 0; p < P; ++p) {
      part pp;
      if (part_build(sc, &pt, p, ghost[p], &pp)) return 1;
      own += pp.n_own_segments;
      gh += pp.n_ghost_segments;
      pad += pp.n_padding_segments;
      ratio += (double)pp.n_ghost_segments / pp.n_own_segments;
      if (pp.n_ghost_segments > gmax) gmax = pp.n_ghost_segments;
      const int gn = pp.n_local_nodes - pp.n_own_nodes;
      if (gn > gnmax) gnmax = gn;
      part_free(&pp);
    }
    /* per iteration: 3 doubles per ghost node in; the residual's ghost rows
     * out as (index, value) pairs, at most 3 per ghost node (an int index
     * and a double) */
    printf("| %d | %.0f | %.0f, %d | %.1f | %.4f | %d | %d | %d |\n", P, own / P, gh / P, gmax,
           pad / P, ratio / P, gnmax, 24 * gnmax, 36 * gnmax);
    for (int p = 0; p < P; ++p) free(ghost[p]);
    free(ghost);
    partition_free(&pt);
  }
  return 0;
}
