// Cubic Hermite basis on xi in [-1, 1] and its first two xi-derivatives.
// Weight k multiplies, in order: the start point, the start tangent, the end
// point, the end tangent (the tangents are dx/dxi at xi = -1 and xi = +1).
#pragma once

namespace b2b {
namespace curve {

struct HermiteBasis {
  double h[4];    // H1..H4
  double dh[4];   // dH/dxi
  double ddh[4];  // d2H/dxi2

  explicit HermiteBasis(double xi) {
    const double xi2 = xi * xi, xi3 = xi2 * xi;
    h[0] = 0.25 * (2.0 - 3.0 * xi + xi3);
    h[1] = 0.25 * (1.0 - xi - xi2 + xi3);
    h[2] = 0.25 * (2.0 + 3.0 * xi - xi3);
    h[3] = 0.25 * (-1.0 - xi + xi2 + xi3);
    dh[0] = 0.75 * (xi2 - 1.0);
    dh[1] = 0.25 * (-1.0 - 2.0 * xi + 3.0 * xi2);
    dh[2] = 0.75 * (1.0 - xi2);
    dh[3] = 0.25 * (-1.0 + 2.0 * xi + 3.0 * xi2);
    ddh[0] = 1.5 * xi;
    ddh[1] = 0.25 * (-2.0 + 6.0 * xi);
    ddh[2] = -1.5 * xi;
    ddh[3] = 0.25 * (2.0 + 6.0 * xi);
  }
};

}  // namespace curve
}  // namespace b2b
