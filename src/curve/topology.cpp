#include "topology.hpp"

#include <b2b/b2b.h>

namespace b2b {
namespace curve {

int min_nodes(int closed) { return closed ? 3 : 2; }

int segment_count(int kind, int n_nodes, int closed) {
  if (closed || kind == B2B_CURVE_HERMITE_MIDPOINT) return n_nodes;
  return n_nodes - 1;
}

void segment_patch(int kind, int n_nodes, int closed, int s, int nodes[4], int* start_rule,
                   int* end_rule) {
  // Slot x2 holds node s for every kind: nodal and linear segments run from
  // node s to s + 1 (slots x2, x3), a midpoint segment is centred on node s.
  // 64-bit arithmetic: s + 2 and the wrap-around overflow int for rings of
  // nearly INT_MAX nodes.
  const long long n = n_nodes;
  for (int k = 0; k < 4; ++k) {
    long long node = static_cast<long long>(s) - 1 + k;
    if (closed)
      node = (node + n) % n;
    else if (node < 0 || node >= n)
      node = -1;
    nodes[k] = static_cast<int>(node);
  }
  // Slots the kind never reads.
  if (kind == B2B_CURVE_LINEAR) nodes[0] = nodes[3] = -1;
  if (kind == B2B_CURVE_HERMITE_MIDPOINT) nodes[3] = -1;

  const int last_segment = segment_count(kind, n_nodes, closed) - 1;
  *start_rule = (!closed && s == 0) ? B2B_END_REFLECT : B2B_END_NEIGHBOUR;
  *end_rule = (!closed && s == last_segment) ? B2B_END_REFLECT : B2B_END_NEIGHBOUR;
}

}  // namespace curve
}  // namespace b2b
