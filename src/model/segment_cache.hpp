// The segments one thread of the model's update has built, kept while they
// are reused. An update evaluates its pairs in key order (lower segment
// first): a segment's pairs with its later partners come one after another,
// and the partners of a segment's neighbour along its beam are mostly its
// own partners' neighbours. A small cache therefore serves nearly every
// request, and the update's memory no longer holds every segment near
// contact at once (1.9 kB each: the largest per-segment cost of a network
// before; doc/guide-model.md, "Scaling").
//
// Set-associative with two ways per set (a pair's two segments may map to
// one set, and the first must stay while the second is built); within a
// set the way used longer ago is replaced. A segment is a pure function of
// the coordinates, so a result never depends on which request built it:
// the update is bit for bit the same whatever the threads or the cache.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "../curve/segment.hpp"
#include "beam_table.hpp"
#include "search.hpp"

namespace b2b {
namespace model {

class SegmentCache {
 public:
  struct Entry {
    int segment = -1;  // model segment held (-1: none)
    curve::Segment built;
    double X[12];      // its patch (the finite-difference tangent reads it)
  };

  // Forgets every entry (the coordinates changed) and sets the number of
  // sets (a power of two); keeps the memory when that does not change.
  void reset(int sets);
  // Segment s built with derivatives on coords (used nodes), from the cache
  // or built now; `keep` (may be null) is an entry the caller still uses,
  // never the one replaced. Null when the segment cannot be built: then
  // fail says why (and nothing is cached).
  const Entry* get(int s, const Entry* keep, const SegmentInfo& info, const double* coords,
                   const NodeIndex& used_index, curve::Failure& fail);

  // The number of sets for an update over these candidate pairs (sorted,
  // as the search returns them) of a model of n_segments evaluated on
  // `threads` threads (one cache each). The working set depends on the
  // scene: a fibre network's pairs miss about half the time whatever the
  // size short of holding every segment (a segment's partners lie on
  // random fibres), while a packed bundle's need thousands of entries
  // (each segment's partners lie along rows of neighbouring fibres, and the
  // rows grow with the bundle's width) and miss on nearly every request
  // below that. So: the smallest size whose misses, simulated on sample
  // windows of the candidates in the order the update asks for their
  // segments, are within 25% of those of the largest allowed, which is
  // bounded by memory: all caches together at most about 64 bytes per
  // candidate pair (an entry is about 2 kB), and at least 32 sets.
  static int choose_sets(const PairRows& candidates, int n_segments, int threads);
  static constexpr int kWays = 2;

 private:
  int sets_ = 0;
  std::vector<Entry> entries_;     // sets_ * kWays, allocated at the first get
  std::vector<uint8_t> recent_;    // per set: the way used last
};

}  // namespace model
}  // namespace b2b
