// Buffers of the model's update kept from one update to the next: a
// Newton iteration's update reuses the memory of the last one instead of
// allocating, per update, arrays as long as the segments or the candidate
// pairs (issue 20). Nothing in here carries state from one update to the
// next: each update overwrites what it reads. In the steady state (an
// update that finds no more pairs than the last) nothing here allocates,
// so the update's resident memory cannot creep (doc/guide-model.md,
// "Scaling").
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

#include <b2b/b2b.h>

#include "contact_result.hpp"
#include "contact_state.hpp"
#include "crossing.hpp"
#include "page_pool.hpp"
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
  TangentForm form = TangentForm::None;  // of its result's tangent
  // The crossing check reads it (no committed history, and it moved far
  // enough since the commit: crossing.hpp); its record has the difference
  // of its closest points.
  bool crossing = false;
  // Lengths of its committed and of its new history: a line pair
  // (GroupPair::line) has (n + 1) point histories for n integration points.
  int hist_old_len = 0;
  int hist_len = 0;
  const double* hist_old = nullptr;  // committed history, or null (fresh)
  const double* rec = nullptr;       // its record, or null
  const double* result = nullptr;    // ACTIVE: its outputs (contact_result.hpp)
  uint64_t key() const { return pair_key(a, b); }
};

// Items share the records' pages (one partial page a thread less): the
// doubles an item takes there.
constexpr size_t kItemDoubles = sizeof(UpdateItem) / sizeof(double);
static_assert(sizeof(UpdateItem) % sizeof(double) == 0 && alignof(UpdateItem) <= alignof(double),
              "an item fills whole doubles of a page");

// Room for n items in the pages of c (constructed by the caller).
inline UpdateItem* take_items(PageCursor<double>& c, size_t n) {
  return reinterpret_cast<UpdateItem*>(c.take(n * kItemDoubles));
}

// What one chunk of the update's evaluation keeps: its kept pairs, in
// work-item order, contiguous in the page of the thread that evaluated it
// (so nothing of it depends on the threads).
struct UpdateChunk {
  UpdateItem* kept = nullptr;
  int n_kept = 0;
  int kept_candidates = 0;  // of them, from candidates (the rest: extras)
};

// What one thread of the evaluation counts: sums and a minimum, the same
// whichever thread evaluated which chunk.
struct UpdateTally {
  int counts[B2B_MODEL_COUNTS_LEN] = {0};  // B2B_COUNT_*: evaluated, not kept
  int evaluated = 0, near = 0;
  int bad_segment = -1;  // the lowest segment that could not be built (-1: none)
  curve::Failure fail;   // and why
};

// Empties v, a buffer whose contents are dead, and makes room in it for n
// elements: a larger one is allocated only after the old one is freed, so
// that the allocator may put it where the old one was (reserve() would
// copy the old contents over and leave the old place as a hole, which
// stays resident when nothing else fills it).
template <class T>
void reserve_afresh(std::vector<T>& v, size_t n) {
  v.clear();
  if (n <= v.capacity()) return;
  std::vector<T>().swap(v);
  v.reserve(n);
}

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
  // Per chunk of the evaluation: where its kept pairs are; per thread: its
  // counts.
  std::vector<UpdateChunk> chunks;
  std::vector<UpdateTally> tallies;
  // The pages the threads write into: the kept pairs and their records
  // (scratch, read until the update ends), and the active contacts'
  // outputs. `results` is the model's next set: an update that succeeds
  // swaps it with the model's (Model::results_), whose pages this one
  // reuses next time.
  PagePool<double> scratch, results;
  // The kept pairs in key order (in the pages of `scratch`).
  std::vector<UpdateItem*> items;
  // The model's next trial state and contacts, swapped in likewise.
  ContactState trial;
  std::vector<Contact> contacts;
};

}  // namespace model
}  // namespace b2b
