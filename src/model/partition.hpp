// A model that is one rank's part of a distributed model (b2b_model.h,
// "Distributed models"; doc/distributed.md): each local beam is a piece of a
// global beam, some of its segments are ghosts (owned by another rank) and
// the segment at a cut is padding (it lends its nodes to its neighbour's
// patch and is never paired). From that, the global id of every segment and
// the ownership rule: a pair is evaluated by the rank that owns its smaller
// segment (global order), and only if its other segment is no padding.
//
// Because beams are added in increasing global order (checked at finalize),
// the local segment order is the global order restricted to the model, so
// "smaller" is the smaller local index, and every order-dependent result is
// that of one model holding everything.
//
// A model without any of it (serial) evaluates every pair: global beam =
// local beam, global segment = local segment.
#pragma once

#include <cstdint>
#include <vector>

#include "beam_table.hpp"

namespace b2b {
namespace model {

struct Problem;

// What Partition::finalize found wrong (Problem::code of a What::Partition).
enum class PartitionIssue {
  GhostsWithoutIds = 1,  // beam: ghosts in a model without global ids
  SomeWithoutIds,        // beam: no global id, other_beam: has one
  Order,                 // beam after other_beam in global order
  Overlap,               // beam overlaps other_beam (one global beam)
  Differ,                // pieces beam and other_beam of one global beam differ
  PaddingOwn             // beam, segment: the segment at a cut is not a ghost
};

class Partition {
 public:
  // --- set-up, per local beam (before finalize; checked by the caller) ---
  void set_beam(int beam, int64_t global_beam, int first_segment, bool start_cut, bool end_cut);
  void add_ghosts(int beam, int first, int count);
  bool beam_set(int beam) const {
    return beam < static_cast<int>(setup_.size()) && setup_[beam].set;
  }

  // --- finalize: the beams as BeamTable::build left them (first_segment,
  // n_segments). Checks the set-up (every beam or none, global order, no
  // overlap, pieces of one global beam alike, padding that is a ghost) and
  // builds the per-segment roles; on a problem nothing changes. ---
  Problem finalize(const std::vector<Beam>& beams);

  // --- after finalize ---
  bool partitioned() const { return partitioned_; }
  // Global beam and segment of local segment s.
  int64_t global_beam(const SegmentInfo& s) const {
    return partitioned_ ? global_beam_[s.beam] : s.beam;
  }
  int64_t global_segment(const SegmentInfo& s) const {
    return partitioned_ ? static_cast<int64_t>(first_[s.beam]) + s.index : s.index;
  }
  bool own(int s) const { return !partitioned_ || role_[s] == kOwn; }
  bool padding(int s) const { return partitioned_ && role_[s] == kPadding; }
  // The ownership rule: this model evaluates the pair (a, b).
  bool evaluates(int a, int b) const {
    if (!partitioned_) return true;
    const int lo = a < b ? a : b, hi = a < b ? b : a;
    return role_[lo] == kOwn && role_[hi] != kPadding;
  }
  // Another rank evaluates the pair: its smaller segment is not this
  // model's (a pair whose smaller segment is its own but whose other one is
  // padding is nobody's here: the ghost layer is too thin).
  bool owned_elsewhere(int a, int b) const {
    return partitioned_ && role_[a < b ? a : b] != kOwn;
  }
  // Two segments of one global beam in different local beams (pieces):
  // never paired (no self-contact across pieces).
  bool other_piece(const SegmentInfo& a, const SegmentInfo& b) const {
    return partitioned_ && a.beam != b.beam && global_beam_[a.beam] == global_beam_[b.beam];
  }
  // The local segment of a global id, or -1 if the model does not hold it.
  int local_segment(const std::vector<Beam>& beams, int64_t global_beam,
                    int64_t global_segment) const;
  // For the restart fingerprint: the set-up as numbers (empty: serial).
  std::vector<int64_t> signature() const;

 private:
  struct Setup {
    bool set = false;
    int64_t global_beam = 0;
    int first_segment = 0;
    bool start_cut = false, end_cut = false;
    std::vector<std::pair<int, int>> ghosts;  // [first, first + count)
  };
  enum Role : uint8_t { kOwn = 0, kGhost = 1, kPadding = 2 };
  std::vector<Setup> setup_;  // per local beam (shorter: not set)
  bool partitioned_ = false;
  std::vector<int64_t> global_beam_;  // per local beam
  std::vector<int> first_;            // per local beam
  std::vector<uint8_t> role_;         // per local segment
};

}  // namespace model
}  // namespace b2b
