/* The ghost layer and the bytes exchanged per Newton iteration against the
 * partition size, for n_parts parts of a scene, computed from the
 * partition alone (no MPI: each part as the rank it would be). */
#ifndef MPI_SCALING_H
#define MPI_SCALING_H

#include "scene.h"

/* Prints one table row per part count in parts[0 .. n_counts). Returns 1 on
 * allocation failure. */
int scaling_study(const scene *sc, const int *parts, int n_counts);

#endif
