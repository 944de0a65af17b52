/* Axial and bending elements of the MPI example host: energies, exact
 * gradients and Hessians (beam_element.h). */
#include "beam_element.h"

#include <math.h>

static double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

double axial_element(const double xa[3], const double xb[3], double L0, double EA, double g[6],
                     double H[36]) {
  double e[3] = {xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]};
  const double l = sqrt(dot3(e, e)), k = EA / L0, s = l - L0;
  double t[3] = {e[0] / l, e[1] / l, e[2] / l};
  if (g)
    for (int i = 0; i < 3; ++i) {
      g[i] = -k * s * t[i];
      g[3 + i] = k * s * t[i];
    }
  if (H) {
    /* d2E/de2 = k (t t^T + (s / l) (I - t t^T)); the nodes carry it as [K -K; -K K]. */
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double Kij = k * (t[i] * t[j] + (s / l) * ((i == j) - t[i] * t[j]));
        H[6 * i + j] = Kij;
        H[6 * (i + 3) + j + 3] = Kij;
        H[6 * i + j + 3] = -Kij;
        H[6 * (i + 3) + j] = -Kij;
      }
  }
  return 0.5 * k * s * s;
}

double bending_element(const double x0[3], const double x1[3], const double x2[3], double kb,
                       double g[9], double H[81]) {
  double e1[3], e2[3], t1[3], t2[3];
  for (int i = 0; i < 3; ++i) {
    e1[i] = x1[i] - x0[i];
    e2[i] = x2[i] - x1[i];
  }
  const double l1 = sqrt(dot3(e1, e1)), l2 = sqrt(dot3(e2, e2));
  for (int i = 0; i < 3; ++i) {
    t1[i] = e1[i] / l1;
    t2[i] = e2[i] / l2;
  }
  const double c = dot3(t1, t2);
  /* c = t1.t2: dc/de1 = P1 t2 / l1, dc/de2 = P2 t1 / l2, P = I - t t^T. */
  double a1[3], a2[3];
  for (int i = 0; i < 3; ++i) {
    a1[i] = (t2[i] - c * t1[i]) / l1;
    a2[i] = (t1[i] - c * t2[i]) / l2;
  }
  /* Edge e_p depends on the nodes with coefficients D[p][node]. */
  static const double D[2][3] = {{-1.0, 1.0, 0.0}, {0.0, -1.0, 1.0}};
  if (g)
    for (int n = 0; n < 3; ++n)
      for (int i = 0; i < 3; ++i) g[3 * n + i] = -kb * (D[0][n] * a1[i] + D[1][n] * a2[i]);
  if (H) {
    /* Second derivatives of c in the edges:
     *   d2c/de1 de1 = -(c P1 + t1 (P1 t2)^T + (P1 t2) t1^T) / l1^2   (and likewise for e2)
     *   d2c/de1 de2 = P1 P2 / (l1 l2). */
    double C[2][2][3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double P1ij = (i == j) - t1[i] * t1[j], P2ij = (i == j) - t2[i] * t2[j];
        C[0][0][i][j] = -(c * P1ij + t1[i] * a1[j] * l1 + a1[i] * l1 * t1[j]) / (l1 * l1);
        C[1][1][i][j] = -(c * P2ij + t2[i] * a2[j] * l2 + a2[i] * l2 * t2[j]) / (l2 * l2);
        double p12 = 0.0;
        for (int m = 0; m < 3; ++m)
          p12 += ((i == m) - t1[i] * t1[m]) * ((m == j) - t2[m] * t2[j]);
        C[0][1][i][j] = p12 / (l1 * l2);
      }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) C[1][0][i][j] = C[0][1][j][i];
    for (int n = 0; n < 3; ++n)
      for (int m = 0; m < 3; ++m)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            double h = 0.0;
            for (int p = 0; p < 2; ++p)
              for (int q = 0; q < 2; ++q) h += D[p][n] * D[q][m] * C[p][q][i][j];
            H[9 * (3 * n + i) + 3 * m + j] = -kb * h;
          }
  }
  return kb * (1.0 - c);
}
