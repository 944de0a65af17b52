// Assembly of the active contacts' element arrays into the host's global
// arrays through its equation numbers of the translational dofs. Every
// function visits the contacts in their listed order and, within one, the
// 8 slots x 3 components in order, so the sums are the same every time.
#pragma once

#include <cstdint>

#include "model.hpp"

namespace b2b {
namespace model {

// The host's numbering: eq[ldeq*node + i], numbered from base; below base:
// constrained. n_eq equations.
struct EqMap {
  const int* eq;
  int ldeq, base, n_eq;
};

// The first dof of a contact whose equation number is beyond n_eq
// (B2B_ERR_RANGE: node, axis, value) or, with kl >= 0, whose coupling with
// another dof of the same contact lies outside the band (beam = row,
// other_beam = column equations).
Problem check_equations(const Model& m, const EqMap& map, int kl = -1, int ku = -1);

void add_residual(const Model& m, const EqMap& map, double* f);
void add_tangent_dense(const Model& m, const EqMap& map, double* K, int ldk);
// LAPACK general band storage for dgbsv: (r, c) at AB[kl + ku + r - c + ldab*c].
void add_tangent_banded(const Model& m, const EqMap& map, int kl, int ku, double* AB, int ldab);
// Number of (row, col) entries: every pair of unconstrained dofs of each
// contact, also where the value is 0 (the pattern does not change with values).
int64_t coo_count(const Model& m, const EqMap& map);
void coo_fill(const Model& m, const EqMap& map, int* rows, int* cols, double* values);

}  // namespace model
}  // namespace b2b
