#include "ring_accuracy.h"

#include <math.h>
#include <stdlib.h>

#include <b2b/b2b.h>

void ring_nodes(int n, double radius, int alternating, double *coords) {
  const double h = 2.0 * 3.14159265358979323846 / n;
  double theta = 0.0;
  for (int k = 0; k < n; ++k) {
    coords[3 * k] = radius * cos(theta);
    coords[3 * k + 1] = radius * sin(theta);
    coords[3 * k + 2] = 0.0;
    theta += alternating ? (k % 2 == 0 ? 1.3 * h : 0.7 * h) : h;
  }
}

int ring_max_error(int kind, int n, double radius, int alternating, int samples_per_segment,
                   double *max_error) {
  double *coords = malloc(3 * (size_t)n * sizeof(double));
  if (!coords) return B2B_ERR_NOMEM;
  ring_nodes(n, radius, alternating, coords);
  int nseg = 0;
  int st = b2b_beam_segment_count(kind, n, 1, &nseg, NULL, 0);
  double worst = 0.0;
  for (int s = 0; st == B2B_OK && s < nseg; ++s) {
    int nodes[4], sr, er;
    double patch[12] = {0};
    st = b2b_beam_segment_patch(kind, n, 1, s, nodes, &sr, &er, NULL, 0);
    for (int k = 0; st == B2B_OK && k < 4; ++k)
      for (int i = 0; i < 3 && nodes[k] >= 0; ++i) patch[3 * k + i] = coords[3 * nodes[k] + i];
    for (int q = 0; st == B2B_OK && q <= samples_per_segment; ++q) {
      double x[9];
      const double xi = -1.0 + 2.0 * q / samples_per_segment;
      st = b2b_segment_eval(kind, sr, er, patch, NULL, xi, x, NULL, NULL, NULL, 0);
      const double r = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      if (st == B2B_OK) worst = fmax(worst, fabs(r - radius));
    }
  }
  free(coords);
  if (st == B2B_OK) *max_error = worst;
  return st;
}

double fitted_order(const int *n, const double *err, int count) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < count; ++i) {
    const double x = log((double)n[i]), y = log(err[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return -(count * sxy - sx * sy) / (count * sxx - sx * sx);
}
