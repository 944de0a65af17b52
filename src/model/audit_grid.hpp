// The interpenetration audit's own broad phase (audit.hpp), independent of
// the model's BoxTree: a uniform grid whose cell size is 1.5 times the median
// of the boxes' largest extents, hashed into a table of as many buckets as
// box-cell entries and filled by a counting sort (no ordering, no
// per-cell allocation). A pair of overlapping boxes is reported by the one
// bucket of the cell holding the lower corner of their intersection (both
// boxes cover that cell), so each pair comes out once. A box that spans more
// than kMaxCells cells goes to a short list tested against every box.
#pragma once

#include <utility>
#include <vector>

#include "search.hpp"

namespace b2b {
namespace model {

// Every pair (i, j), i < j, of overlapping boxes (touching counts), once,
// in no particular order.
void grid_overlapping_pairs(const std::vector<Box>& boxes, std::vector<std::pair<int, int>>& out);

}  // namespace model
}  // namespace b2b
