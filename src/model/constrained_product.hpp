// The contact tangent's coupling of free to constrained (prescribed) dofs,
// applied to the prescribed increments: what a host subtracts from its
// right-hand side when it prescribes a displacement increment, since the
// assembly helpers skip the constrained columns (and rows) altogether.
#pragma once

#include "contact_dofs.hpp"
#include "model.hpp"

namespace b2b {
namespace model {

// du: per host node like the coordinates, node k's increments at
// du[ldu*k + 0..2]; only the entries of constrained dofs of the contacts'
// nodes are read. The first such entry that is not finite (Increment: node,
// axis, value), else none.
Problem check_increments(const Model& m, const EqMap& map, const double* du, int ldu);

// f[r] += scale * K(r, c) * du_c for every free row r and constrained column
// c of every contact, in the contacts' order (columns, then rows).
void add_constrained_product(const Model& m, const EqMap& map, const double* du, int ldu,
                             double scale, double* f);

}  // namespace model
}  // namespace b2b
