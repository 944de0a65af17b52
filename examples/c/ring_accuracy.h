/* Geometric accuracy of a smoothed closed beam whose nodes lie on a circle:
 * shared by the curve study (which prints it) and the convergence test
 * (which asserts on it), so both speak of the same numbers. */
#ifndef B2B_RING_ACCURACY_H
#define B2B_RING_ACCURACY_H

/* n nodes on the circle of radius radius in the xy-plane, counter-clockwise
 * from (radius, 0, 0): equally spaced, or (alternating != 0, n even) with
 * elements alternating 1.3 h and 0.7 h, h = 2 pi / n. coords is 3 x n. */
void ring_nodes(int n, double radius, int alternating, double *coords);

/* Largest distance from the circle of the smoothed ring of curve kind `kind`
 * through such nodes, sampled at samples_per_segment + 1 points per segment.
 * Returns a b2b status (B2B_OK on success). */
int ring_max_error(int kind, int n, double radius, int alternating, int samples_per_segment,
                   double *max_error);

/* Convergence order p of err ~ C n^-p fitted by least squares to
 * log(err) against log(n). */
double fitted_order(const int *n, const double *err, int count);

#endif
