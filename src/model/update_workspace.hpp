// Buffers of the model's update kept from one update to the next: a
// Newton iteration's update reuses the memory of the last one instead of
// allocating, per update, arrays as long as the segments or the candidate
// pairs (issue 20). Nothing in here carries state from one update to the
// next: each update overwrites what it reads.
#pragma once

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

#include <b2b/b2b.h>

#include "contact_state.hpp"
#include "crossing.hpp"
#include "search.hpp"
#include "segment_cache.hpp"

namespace b2b {
namespace model {

// One evaluated pair that a later stage of the update reads: one with a
// record (pair_record.hpp: active, open, or outside with a committed
// history) or whose outputs overflowed. Every other evaluated pair leaves
// only its count.
struct UpdateItem {
  int a, b, gp;
  int8_t status = -1;     // B2B_CONTACT_* of its evaluation
  bool overflow = false;  // an output of the element is not finite
  // Lengths of its committed and of its new history: a line pair
  // (GroupPair::line) has (n + 1) point histories for n integration points.
  int hist_old_len = 0;
  int hist_len = 0;
  const double* hist_old = nullptr;  // committed history, or null (fresh)
  const double* rec = nullptr;       // its record, or null
  const double* tangent = nullptr;   // ACTIVE, with tangents: in a tangent block
  uint64_t key() const { return pair_key(a, b); }
};

// What one chunk of the update's evaluation leaves (filled by the thread
// that evaluates it, so nothing of it depends on the threads).
struct UpdateChunk {
  std::vector<UpdateItem> kept;  // in work-item order
  size_t kept_candidates = 0;    // of them, from candidates (the rest: extras)
  int counts[B2B_MODEL_COUNTS_LEN] = {0};  // B2B_COUNT_*: evaluated, not kept
  int evaluated = 0, near = 0;
  int bad_segment = -1;  // the lowest segment that could not be built (-1: none)
  curve::Failure fail;   // and why
  void reset() {
    kept.clear();
    kept_candidates = 0;
    std::fill(std::begin(counts), std::end(counts), 0);
    evaluated = near = 0;
    bad_segment = -1;
    fail = curve::Failure();
  }
};

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
  // Per chunk of the evaluation: its outputs and its block of records (read
  // until the update ends; the tangent blocks go to the model).
  std::vector<UpdateChunk> chunks;
  std::vector<std::vector<double>> records;
};

}  // namespace model
}  // namespace b2b
