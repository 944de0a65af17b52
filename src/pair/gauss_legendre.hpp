// Gauss-Legendre rules on [-1, 1]: the integration points of the line
// element (line_contact.hpp). Exact for polynomials of degree 2n - 1; the
// points are interior, so a segment's joints never carry one.
#pragma once

namespace b2b {
namespace pair {

constexpr int kGaussMaxPoints = 32;  // B2B_LINE_POINTS_MAX

// The n-point rule, 1 <= n <= kGaussMaxPoints: points in increasing order.
// Computed once per n (thread-safe) and read from a table afterwards.
void gauss_legendre(int n, const double** points, const double** weights);

}  // namespace pair
}  // namespace b2b
