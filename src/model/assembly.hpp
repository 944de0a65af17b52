// Assembly of the active contacts' element arrays into the host's global
// arrays through its equation numbers of the translational dofs. Every
// function visits the contacts in their listed order and, within one, the
// 8 slots x 3 components in order, so the sums are the same every time.
#pragma once

#include <cstdint>

#include "contact_dofs.hpp"
#include "model.hpp"

namespace b2b {
namespace model {

// The first dof of a contact whose equation number is beyond n_eq
// (B2B_ERR_RANGE: node, axis, value) or, with kl >= 0, whose coupling with
// another dof of the same contact lies outside the band (beam = row,
// other_beam = column equations).
Problem check_equations(const Model& m, const EqMap& map, int kl = -1, int ku = -1);

// Each adds scale * (the contacts' entry) into the host's array. scale 1 adds
// the entries themselves (1 * v is v exactly), and scale -1 their negatives,
// exactly -1 times what scale 1 adds (negation is exact and the order of the
// sums is the same).
void add_residual(const Model& m, const EqMap& map, double scale, double* f);
void add_tangent_dense(const Model& m, const EqMap& map, double scale, double* K, int ldk);
// LAPACK general band storage for dgbsv: (r, c) at AB[kl + ku + r - c + ldab*c].
void add_tangent_banded(const Model& m, const EqMap& map, int kl, int ku, double scale,
                        double* AB, int ldab);
// Number of (row, col) entries: every pair of unconstrained dofs of each
// contact, also where the value is 0 (the pattern does not change with values).
int64_t coo_count(const Model& m, const EqMap& map);
void coo_fill(const Model& m, const EqMap& map, int* rows, int* cols, double* values);

}  // namespace model
}  // namespace b2b
