// Which beam nodes make up the patch of each segment of a beam, for every
// curve kind, on open beams (with end rules) and rings (wrap-around).
#pragma once

namespace b2b {
namespace curve {

// Smallest node count of a beam of this kind (open or closed).
int min_nodes(int closed);

// Number of segments; the caller has checked n_nodes >= min_nodes(closed).
int segment_count(int kind, int n_nodes, int closed);

// Patch slots (0-based beam nodes, -1 where missing or unused) and the end
// rules of segment s; the caller has checked 0 <= s < segment_count().
void segment_patch(int kind, int n_nodes, int closed, int s, int nodes[4], int* start_rule,
                   int* end_rule);

}  // namespace curve
}  // namespace b2b
