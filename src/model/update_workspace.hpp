// Buffers of the model's update kept from one update to the next: a
// Newton iteration's update reuses the memory of the last one instead of
// allocating, per update, arrays as long as the segments or the candidate
// pairs (issue 20). Nothing in here carries state from one update to the
// next: each update overwrites what it reads.
#pragma once

#include <cstdint>
#include <vector>

#include "crossing.hpp"
#include "search.hpp"
#include "segment_cache.hpp"

namespace b2b {
namespace model {

struct UpdateWorkspace {
  // Per segment: its box on the current coordinates, and (after a commit)
  // that box swept from the committed one; the committed boxes and motion.
  std::vector<Box> boxes, swept;
  CommittedMotion motion;
  // The current coordinates' buffer for the next update (the model keeps
  // the last update's; the one before is recycled here).
  std::vector<double> coords;
  // One cache of built segments per thread of the evaluation, and its
  // number of sets (SegmentCache::choose_sets; 0: not chosen yet).
  std::vector<SegmentCache> caches;
  int cache_sets = 0;
};

}  // namespace model
}  // namespace b2b
