#include "topology.hpp"

#include <b2b/b2b.h>

#include "kinds.hpp"

namespace b2b {
namespace curve {

int min_nodes(int closed) { return closed ? 3 : 2; }

int segment_count(int kind, int n_nodes, int closed) {
  if (closed || kind_info(kind).centred_on_node) return n_nodes;
  return n_nodes - 1;
}

void segment_patch(int kind, int n_nodes, int closed, int s, int nodes[4], int* start_rule,
                   int* end_rule) {
  // Slot x2 holds node s for every kind: a segment per element runs from
  // node s to s + 1 (slots x2, x3), one centred on a node is centred on
  // node s (KindInfo::centred_on_node).
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
  // Slots the kind never reads, under any rule.
  const KindInfo& info = kind_info(kind);
  const unsigned readable = info.slots | info.start_neighbour_slots | info.end_neighbour_slots;
  for (int slot = 0; slot < 4; ++slot)
    if (!(readable & (1u << slot))) nodes[slot] = -1;

  const int last_segment = segment_count(kind, n_nodes, closed) - 1;
  *start_rule = (!closed && s == 0) ? B2B_END_REFLECT : B2B_END_NEIGHBOUR;
  *end_rule = (!closed && s == last_segment) ? B2B_END_REFLECT : B2B_END_NEIGHBOUR;
}

}  // namespace curve
}  // namespace b2b
