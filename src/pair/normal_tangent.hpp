// The dense part of the frictionless tangent on the used columns (the hot
// loop of a tangent evaluation). With f = f_N, fp = df_N/dg, rho the signed
// distance of the axes (doc/contact-element.md section 10 in closed form):
//   K = -fp g g^T - (f/rho) (J^T (I - n n^T) J - B^T H^-1 B),
// symmetric. The curves' second derivatives in X are added by the caller.
#pragma once

#include "linearization.hpp"

namespace b2b {
namespace pair {

// Upper triangle of the m x m compact K (leading dimension kNdof); an even
// column c also gets its entry (c + 1, c) below the diagonal (the rows are
// written in pairs), which the caller mirrors over or does not read.
void normal_tangent_upper(const Linearization& lin, double fp, double f_over_rho, double* Kc);

// Exactly intersecting axes (the normal is the history's and does not
// rotate): K = -fp g g^T + f (a C0^T + b C1^T), full and not symmetric.
void normal_tangent_intersecting(const Linearization& lin, double fp, double f, double* Kc);

}  // namespace pair
}  // namespace b2b
