#include "assembly.hpp"

#include <cstdlib>

#include <b2b/b2b.h>

namespace b2b {
namespace model {

Problem check_equations(const Model& m, const EqMap& map, int kl, int ku) {
  Problem pb;
  int e[24];
  for (const Contact& c : m.contacts()) {
    for (int s = 0; s < 8; ++s)
      for (int i = 0; i < 3 && c.nodes[s] >= 0; ++i) {
        const int64_t v = map.eq[static_cast<size_t>(map.ldeq) * c.nodes[s] + i];
        if (v >= map.base && v - map.base >= map.n_eq) {
          pb.status = B2B_ERR_RANGE;
          pb.what = Problem::What::Equation;
          pb.node = c.nodes[s];
          pb.axis = i;
          pb.value = static_cast<double>(v);
          return pb;
        }
      }
    if (kl < 0) continue;
    dof_equations(c, map, e);
    for (int col = 0; col < 24; ++col)
      for (int row = 0; row < 24 && e[col] >= 0; ++row)
        if (e[row] >= 0 && (static_cast<int64_t>(e[row]) - e[col] > kl ||
                            static_cast<int64_t>(e[col]) - e[row] > ku)) {
          pb.status = B2B_ERR_RANGE;
          pb.what = Problem::What::Band;
          pb.row = e[row] + map.base;
          pb.col = e[col] + map.base;
          return pb;
        }
  }
  return pb;
}

void add_residual(const Model& m, const EqMap& map, double scale, double* f) {
  int e[24];
  for (const Contact& c : m.contacts()) {
    dof_equations(c, map, e);
    for (int k = 0; k < 24; ++k)
      if (e[k] >= 0) f[e[k]] += scale * c.residual()[k];
  }
}

void add_tangent_dense(const Model& m, const EqMap& map, double scale, double* K, int ldk) {
  for_each_entry(m, map, [K, ldk, scale](int r, int c, double v) {
    K[r + static_cast<size_t>(ldk) * c] += scale * v;
  });
}

void add_tangent_banded(const Model& m, const EqMap& map, int kl, int ku, double scale,
                        double* AB, int ldab) {
  for_each_entry(m, map, [=](int r, int c, double v) {
    // within the band (checked): 0 <= kl + ku + r - c < ldab, in 64 bits
    AB[static_cast<int64_t>(kl) + ku + r - c + static_cast<int64_t>(ldab) * c] += scale * v;
  });
}

int64_t coo_count(const Model& m, const EqMap& map) {
  int64_t n = 0;
  for_each_entry(m, map, [&n](int, int, double) { ++n; });
  return n;
}

void coo_fill(const Model& m, const EqMap& map, int* rows, int* cols, double* values) {
  int64_t k = 0;
  for_each_entry(m, map, [&](int r, int c, double v) {
    rows[k] = r + map.base;
    cols[k] = c + map.base;
    values[k] = v;
    ++k;
  });
}

}  // namespace model
}  // namespace b2b
