/* The result file of a run: per committed step a summary line, then the
 * final displacements of every global node and every contact with its
 * global pair, gathered on rank 0 in global order whatever the number of
 * ranks (compare_results.c compares two such files). */
#ifndef MPI_RESULTS_H
#define MPI_RESULTS_H

#include <stdio.h>

#include "fe_host.h"

typedef struct {
  int n_steps, cap;
  double *rows; /* 4 per step: t, and three scene values */
} step_log;

int step_log_add(step_log *lg, double t, double a, double b, double c);

/* Writes the file on rank 0 (collective: gathers U and the contacts). */
int results_write(fe_host *h, Vec U, const step_log *lg, const char *path);

#endif
