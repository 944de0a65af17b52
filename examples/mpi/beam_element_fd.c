/* Central finite-difference check of the host's elements (beam_element.c):
 * gradient against the energy, Hessian against the gradient, at random
 * curved configurations (a stretched, bent, twisted chain). Exits non-zero
 * when a relative error exceeds its bound. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "beam_element.h"

static double urand(unsigned *s) {
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xffffff) / 16777216.0 - 0.5;
}

/* energy and derivatives of either element on n = 2 or 3 nodes */
static double eval(int n, const double *x, double *g, double *H) {
  if (n == 2) return axial_element(x, x + 3, 0.9, 7.0, g, H);
  return bending_element(x, x + 3, x + 6, 2.5, g, H);
}

static int check(int n, unsigned seed, double *worst_g, double *worst_H) {
  const int d = 3 * n;
  double x[9], g[9], H[81], gp[9], gm[9], xp[9];
  unsigned s = seed;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < 3; ++i) x[3 * k + i] = (i == 0 ? k : 0.0) + 0.4 * urand(&s);
  eval(n, x, g, H);
  double gmax = 0.0, Hmax = 0.0, eg = 0.0, eH = 0.0;
  for (int a = 0; a < d; ++a) gmax = fmax(gmax, fabs(g[a]));
  for (int a = 0; a < d * d; ++a) Hmax = fmax(Hmax, fabs(H[a]));
  const double h = 1e-6, he = 3e-6; /* the energy's differences lose more to rounding */
  for (int b = 0; b < d; ++b) {
    for (int a = 0; a < d; ++a) xp[a] = x[a];
    xp[b] = x[b] + he;
    const double Ep = eval(n, xp, NULL, NULL);
    xp[b] = x[b] - he;
    const double Em = eval(n, xp, NULL, NULL);
    eg = fmax(eg, fabs((Ep - Em) / (2 * he) - g[b]) / gmax);
    xp[b] = x[b] + h;
    eval(n, xp, gp, NULL);
    xp[b] = x[b] - h;
    eval(n, xp, gm, NULL);
    for (int a = 0; a < d; ++a) eH = fmax(eH, fabs((gp[a] - gm[a]) / (2 * h) - H[d * a + b]) / Hmax);
  }
  /* the Hessian is symmetric */
  for (int a = 0; a < d; ++a)
    for (int b = 0; b < d; ++b) eH = fmax(eH, fabs(H[d * a + b] - H[d * b + a]) / Hmax);
  *worst_g = fmax(*worst_g, eg);
  *worst_H = fmax(*worst_H, eH);
  return eg < 1e-8 && eH < 1e-7;
}

int main(void) {
  int bad = 0;
  const char *name[2] = {"axial", "bending"};
  for (int n = 2; n <= 3; ++n) {
    double wg = 0.0, wH = 0.0;
    for (unsigned seed = 1; seed <= 200; ++seed) bad += !check(n, seed, &wg, &wH);
    printf("%-8s 200 configurations: gradient vs FD of energy %.2e, Hessian vs FD of gradient %.2e "
           "(relative to the largest entry; bounds 1e-8, 1e-7)\n", name[n - 2], wg, wH);
  }
  if (bad) fprintf(stderr, "beam_element_fd: %d configurations failed\n", bad);
  return bad != 0;
}
