/* Partitioning of a scene over ranks and each rank's part: the segments it
 * owns, the ghost layer it needs for contact, and the local beams (pieces of
 * global beams) it hands b2b. Pure host bookkeeping, no MPI. */
#ifndef MPI_PARTITION_H
#define MPI_PARTITION_H

#include "scene.h"

/* Owners of segments and nodes for n_parts parts: recursive coordinate
 * bisection of the segments' reference midpoints, each cut across the
 * longest extent of its part at the count that splits the ranks (so 2
 * parts: one cut along x for both scenes). Node i of a beam belongs to the
 * owner of segment i (the last node to the owner of the last segment). */
typedef struct {
  int n_parts;
  int *seg_owner;  /* scene n_segments */
  int *node_owner; /* scene n_nodes */
} partition;

int partition_rcb(const scene *sc, int n_parts, partition *pt);
void partition_free(partition *pt);

/* The contact reach of the ghost layer: two segments whose boxes (their
 * Hermite patches' nodes, reference configuration) lie within it of each
 * other may come into b2b's narrow phase during the run: r_A + r_B + the
 * regularization gap + b2b's search margin (the scene's, set on every model) + the
 * scene's motion margin. */
double partition_reach(const scene *sc);

/* Calls pair(i, j, data) once for every pair of flat segments i < j whose
 * boxes lie within reach of each other (a uniform grid). Returns 1 on
 * allocation failure. */
int near_pairs(const scene *sc, double reach, void (*pair)(int i, int j, void *data), void *data);

enum { SEG_ABSENT = 0, SEG_OWN = 1, SEG_GHOST = 2, SEG_PADDING = 3 };

/* One local beam: segments [first_segment, first_segment + n_segments) of
 * global beam `beam`, with start/end cut flags (b2b_model_set_beam_global). */
typedef struct {
  int beam, first_segment, n_segments, start_cut, end_cut;
} piece;

/* Part p's view. */
typedef struct {
  int rank;
  unsigned char *seg_state;  /* scene n_segments: SEG_* for this part */
  int n_own_segments, n_ghost_segments, n_padding_segments;
  int n_pieces;
  piece *pieces;
  int n_own_nodes, n_local_nodes; /* local nodes: own first, then the others, each ascending */
  int *local_nodes;               /* global node of each local node */
} part;

/* Marks part p's ghosts from ghost_of (a 0/1 byte per flat segment: within
 * reach of one of p's own segments, owned by another part), fills gaps of
 * at most 2 segments between needed runs of a beam (a padding segment at
 * each end of the gap would meet: cheaper as ghosts), adds a padding
 * segment beyond each cut, and lists the pieces and local nodes. */
int part_build(const scene *sc, const partition *pt, int p, const unsigned char *ghost_of,
               part *out);
void part_free(part *pp);

/* Ghost flags of every part at once: ghost[p][seg] = 1 when seg is
 * within reach of a segment of p and owned by another part. */
int ghost_flags(const scene *sc, const partition *pt, double reach, unsigned char **ghost);

#endif
