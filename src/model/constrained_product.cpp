#include "constrained_product.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <b2b/b2b.h>

namespace b2b {
namespace model {
namespace {

// Whether slot dof k (3 s + i) of a contact is a constrained dof of a node.
bool constrained(const Contact& c, const EqMap& map, int k) {
  const int node = c.nodes[k / 3];
  return node >= 0 && map.eq[static_cast<size_t>(map.ldeq) * node + k % 3] < map.base;
}

double increment(const Contact& c, const double* du, int ldu, int k) {
  return du[static_cast<size_t>(ldu) * c.nodes[k / 3] + k % 3];
}

}  // namespace

Problem check_increments(const Model& m, const EqMap& map, const double* du, int ldu) {
  Problem pb;
  for (const Contact& c : m.contacts())
    for (int k = 0; k < 24; ++k)
      if (constrained(c, map, k) && !std::isfinite(increment(c, du, ldu, k))) {
        pb.status = B2B_ERR_NONFINITE;
        pb.what = Problem::What::Increment;
        pb.node = c.nodes[k / 3];
        pb.axis = k % 3;
        pb.value = increment(c, du, ldu, k);
        return pb;
      }
  return pb;
}

void add_constrained_product(const Model& m, const EqMap& map, const double* du, int ldu,
                             double scale, double* f) {
  int e[24];
  double scratch[24 * 24];  // a packed tangent, unpacked
  for (const Contact& c : m.contacts()) {
    dof_equations(c, map, e);
    const double* K = m.tangent(c, scratch);
    for (int col = 0; col < 24; ++col) {
      if (!constrained(c, map, col)) continue;
      const double d = increment(c, du, ldu, col);
      for (int row = 0; row < 24; ++row)
        if (e[row] >= 0) f[e[row]] += scale * (K[row + 24 * col] * d);
    }
  }
}

}  // namespace model
}  // namespace b2b
