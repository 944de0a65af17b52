// Contacts that move from one rank's model to another's (b2b_model.h,
// "Distributed models"; doc/distributed.md).
//
// Outgoing: a committed contact whose handover walk (update.cpp, handovers)
// reaches a pair that another rank evaluates (Partition::owned_elsewhere)
// stops there as a Migrant: the history as mapped so far onto the target
// pair, the hops walked, and its source (the committed contact it comes
// from, which identifies it). The host packs it and sends it to the
// target's owner.
//
// Received: an unpacked Migrant serves as the committed contact of its
// target pair in the following updates (build_view: the committed state an
// update reads is the model's own plus the received), so that the receiving
// model evaluates the target with it and, where the point is not there
// either, walks on, exactly as a single model's handover would. A target
// that holds its own active committed contact keeps it (a single model
// merges the walk there too). Received contacts live until the next commit
// or revert; the packed form's validation is in MigrationCodec
// (migration.cpp).
//
// Packed form (native byte order, 136 + 8 len bytes): "B2BMIGR1", total
// size, format version, source[4], target[4], hops, the groups (ga, gb) of
// its parameter set, a fingerprint of that set, len, the history (len
// doubles), an FNV-1a checksum of everything before it.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "beam_table.hpp"
#include "contact_state.hpp"
#include "partition.hpp"

namespace b2b {
namespace model {

class Model;
struct Problem;

struct Migrant {
  int64_t source[4] = {0, 0, 0, 0};  // global beam, segment of A, then of B
  int64_t target[4] = {0, 0, 0, 0};  // of the target pair, oriented as the element
  int hops = 0;                      // handover hops walked from the source
  int ga = 0, gb = 0;                // host groups of its parameter set
  std::vector<double> hist;          // mapped onto the target pair
};

class Migration {
 public:
  struct Received {
    Migrant m;
    int a = 0, b = 0;   // the target's local segments, oriented
    int group_pair = 0;
    uint64_t key = 0;   // pair_key(a, b)
    uint64_t epoch = 0; // the model's update count when it was unpacked
  };
  // The migrating contacts of the last update (update.cpp's finish).
  std::vector<Migrant> outgoing;
  // The received ones, sorted by source.
  std::vector<Received> received;
  // Updates since finalize (received contacts not unpacked since the last
  // update are dropped at the end of a round).
  uint64_t updates = 0;

  void clear() {
    outgoing.clear();
    received.clear();
  }
  // Adds or replaces (same source) a validated contact; true if the
  // received set changed.
  bool receive(Received r);
  // The end of a round: drops the received contacts not unpacked since the
  // last update; true if there were any.
  bool end_round();
};

// The committed contact on pair (sa, sb) (or the contact received as from,
// whose source it keeps) leaving for the pair (a, b) with hist (hist_len
// doubles) after hops hops; ga, gb the host groups of its parameter set.
Migrant make_migrant(const BeamTable& table, const Partition& part, int sa, int sb,
                     const Migration::Received* from, int a, int b, int hops, int ga, int gb,
                     const double* hist, int hist_len);

// The committed state an update reads (update.cpp: the evaluation's work
// items and the handovers): the model's own, or, with received contacts, a copy with each
// received contact as the active contact of its target pair (unless the
// target holds its own active contact; of two received for one target, the
// one of the smaller source).
struct CommittedView {
  const ContactState* state = nullptr;
  ContactState with;
  std::vector<std::pair<uint64_t, int>> received_at;  // target key -> index in received
  int conflicts = 0;  // received contacts that lost their target to another one
  // The received contact an entry of the view is, or null.
  const Migration::Received* received(const Migration& mig, uint64_t key) const;
};
void build_view(const ContactState& committed, const Migration& mig, CommittedView& view);

// Packing and unpacking, with the model's group pairs and partition.
struct MigrationCodec {
  static int64_t packed_size(const Migrant& m);
  static void pack(const Model& model, const Migrant& m, unsigned char* out);
  // Validates buffer as a contact for model; on success receives it
  // (*changed: whether the received set changed). On a problem nothing
  // changes.
  static Problem unpack(Model& model, const unsigned char* buffer, int64_t size, bool* changed);
};

}  // namespace model
}  // namespace b2b
