// The host's equation numbers of the translational dofs (EqMap) and the
// mapping of one contact's 24 coordinates onto them, shared by every
// routine that puts the contacts' arrays into host arrays (assembly.cpp,
// profile.cpp, constrained_product.cpp). The visiting order is fixed -
// contacts as listed, then columns, then rows of the 24 x 24 tangent - so
// that every sum is formed in the same order every time.
#pragma once

#include <cstddef>
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

// The equation (0-based, or -1 if constrained) of each of the 24 dofs of a
// contact, -1 also for slots without a node.
// In 64 bits: v - base of any two ints fits (check_equations has made sure
// that every unconstrained one is below n_eq, so the result fits an int).
inline void dof_equations(const Contact& c, const EqMap& map, int e[24]) {
  for (int s = 0; s < 8; ++s)
    for (int i = 0; i < 3; ++i) {
      const int node = c.nodes[s];
      if (node < 0) {
        e[3 * s + i] = -1;
        continue;
      }
      const int64_t v = map.eq[static_cast<size_t>(map.ldeq) * node + i];
      e[3 * s + i] = v < map.base ? -1 : static_cast<int>(v - map.base);
    }
}

// visit(row, col, K(row, col)) for every pair of unconstrained dofs of
// every contact (0-based equations), also where the value is 0: the pattern
// does not depend on the values. tangent false: values are passed as 0 (a
// pattern query needs no tangent).
template <class Visit>
void for_each_entry(const Model& m, const EqMap& map, Visit visit, bool tangent = true) {
  int e[24];
  double scratch[24 * 24];  // a packed tangent, unpacked
  for (const Contact& c : m.contacts()) {
    dof_equations(c, map, e);
    const double* K = tangent ? m.tangent(c, scratch) : nullptr;
    for (int col = 0; col < 24; ++col) {
      if (e[col] < 0) continue;
      for (int row = 0; row < 24; ++row)
        if (e[row] >= 0) visit(e[row], e[col], K ? K[row + 24 * col] : 0.0);
    }
  }
}

}  // namespace model
}  // namespace b2b
