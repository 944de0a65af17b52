// The contact model (behind the b2b_model handle): the host's beams, which
// groups touch with which parameters, the broad phase, the narrow phase on
// the pair layer, the active set with handover, commit/revert and restart.
// Arguments are checked at the C boundary; what only the model can know
// (node numbers against n_nodes, segments that fold, histories in a restart
// buffer) it reports as a Problem for the C boundary to word.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "../pair/contact_element.hpp"
#include "../pair/params.hpp"
#include "beam_table.hpp"
#include "contact_result.hpp"
#include "contact_state.hpp"
#include "migration.hpp"
#include "page_pool.hpp"
#include "partition.hpp"
#include "search.hpp"
#include "update_workspace.hpp"

namespace b2b {
namespace model {

struct GroupPair {
  int ga, gb;  // host group numbers, ga <= gb
  pair::Params params;
  int hist_len;  // of one point element (a line pair keeps (n + 1) of them)
  // "contact_type" LINE or ALL_ANGLE: its pairs are line pairs
  // (pair/line_contact.hpp), each with its own count of integration points.
  bool line = false;
};

// Thrown by the broad phase when it finds more than "max_candidates" pairs
// (caught by Model::update, which reports it as a Problem).
struct CandidateLimit {};

// Default of the "max_candidates" option: pairs kept by one search (about
// 1.2 GB of candidate lists at the bound).
constexpr int kDefaultMaxCandidates = 100000000;

// The most segments a model may have (finalize: B2B_ERR_SIZE beyond): 2^29,
// so that segment counts, their chunks and twice them stay far inside int.
constexpr int64_t kMaxSegments = int64_t(1) << 29;

// What went wrong, for the C boundary to word (status 0: nothing).
struct Problem {
  int status = 0;
  enum class What {
    None, NodeRange, SelfNoGroupPair, NoGroupPair, Coordinate, Segment,
    Overflow, Buffer, Equation, Band, Candidates, Segments,
    Displacement,      // node, axis, value: a non-finite displacement u
    CurrentCoordinate, // node, axis, value: x + u beyond B2B_COORD_MAX
    Profile,           // row, col: a tangent entry outside the host's profile
    ProfilePointer,    // row (equation), value: an invalid jp entry
    Increment,         // node, axis, value: a non-finite prescribed increment
    Partition,         // code (PartitionIssue), beam, other_beam, segment (partition.hpp)
    Migration          // detail: a packed contact not accepted (migration.hpp)
  } what = What::None;
  int code = 0;
  int beam = -1, segment = -1, node = -1, slot_a = -1, slot_b = -1, axis = -1;
  int other_beam = -1, other_segment = -1;
  int row = -1, col = -1;  // equations of a tangent entry outside a band
  double value = 0.0;
  const char* detail = "";
};

class Model {
 public:
  // --- set-up (before finalize) ---
  int add_beam(Beam beam);  // returns its index
  int beam_count() const { return static_cast<int>(beams_.size()); }
  Beam& beam(int b) { return beams_[b]; }
  const Beam& beam(int b) const { return beams_[b]; }
  // Sets or replaces (same history length, checked by the caller) a pair.
  void set_group_pair(int ga, int gb, const pair::Params& p);
  const GroupPair* group_pair(int ga, int gb) const;
  // Options (b2b_model.h says, per option, what a change after finalize
  // does): the search margin and the candidate bound invalidate the
  // candidates, so the next update searches again; the others are read
  // afresh by every update and leave nothing derived behind.
  void set_search_margin(double s);
  void set_max_candidates(int n);
  double search_margin = -1.0;  // < 0: the default (largest radius)
  int threads = 0;
  int max_hops = 16;
  int max_candidates = kDefaultMaxCandidates;

  Problem finalize(int n_nodes);
  bool finalized() const { return finalized_; }
  int n_nodes() const { return n_nodes_; }
  // State for the C boundary's checks.
  bool updated() const { return updated_; }      // an update since the last commit/revert
  bool has_results() const { return has_results_; }

  // --- per iteration ---
  // x: host coordinates (node k at x[ldx*k]), valid size (checked by the caller).
  Problem update(const double* x, int ldx, bool want_tangent);
  // The same with the current coordinates x + u (node k's displacement at
  // u[ldu*k]): the sum is formed per coordinate as it is read, so the result
  // is update(x + u) bit for bit.
  Problem update(const double* x, int ldx, const double* u, int ldu, bool want_tangent);
  const std::vector<Contact>& contacts() const { return contacts_; }
  // A contact's tangent (kNdof x kNdof, column-major), in place or unpacked
  // into scratch (kNdof * kNdof doubles: contact_result.hpp); null without.
  const double* tangent(const Contact& c, double* scratch) const {
    return result_tangent(c.result, c.form, scratch);
  }
  const int* counts() const { return counts_; }
  const double* totals() const { return totals_; }
  bool has_tangents() const { return want_tangent_; }
  const BeamTable& table() const { return table_; }

  void commit();
  void revert();

  // --- distributed models (partition.hpp, migration.hpp) ---
  Partition& partition() { return partition_; }
  const Partition& partition() const { return partition_; }
  const Migration& migration() const { return migration_; }
  // A received contact's end of round (b2b_model_migration_unpack(NULL, 0)).
  bool end_migration_round() { return migration_.end_round(); }

  // --- restart ---
  int64_t save_size() const;
  void save(unsigned char* buffer) const;
  Problem restore(const unsigned char* buffer, int64_t size);

 private:
  std::vector<Beam> beams_;
  std::vector<GroupPair> group_pairs_;
  bool finalized_ = false;
  int n_nodes_ = 0;
  // finalize
  BeamTable table_;
  std::vector<int> used_nodes_;   // host nodes of beams, sorted
  NodeIndex used_index_;          // host node -> index in used_nodes_ (-1: unused)
  std::vector<int> dense_group_;  // per beam
  int n_groups_ = 0;
  // host (ga, gb), ga <= gb -> index into group_pairs_: one entry per pair set
  std::map<std::pair<int, int>, int> gp_by_host_;
  // (dense ga, dense gb), both orders, sorted -> index into group_pairs_:
  // one or two entries per pair set whose groups have beams (so 10^6 groups
  // cost their beams, not their square)
  std::vector<std::pair<uint64_t, int>> gp_of_groups_;
  double margin_ = 0.0, g0_max_ = 0.0;
  // broad phase: the grown boxes and their index live only while a search
  // runs (update.cpp, broad_phase)
  std::vector<Box> search_boxes_;
  BoxTree tree_;
  PairRows candidates_;  // the pairs (a, b), a < b, in order
  std::vector<double> build_coords_;  // coordinates at the last build
  int builds_ = 0;
  // states
  ContactState committed_, trial_;
  std::vector<double> committed_coords_;  // used nodes at the last commit (empty: none yet)
  std::vector<double> current_coords_;    // of the last update
  bool updated_ = false, has_results_ = false, want_tangent_ = false;
  // The self-contact arc lengths (table_) belong to the committed state once
  // a commit (or a restore) has followed the update that measured them; a
  // revert before that forgets them, so the next update measures again.
  bool arcs_committed_ = false;
  std::vector<Contact> contacts_;
  // The contacts' outputs (info, residual, tangent: contact_result.hpp), in
  // the pages the update's threads wrote them to; the workspace holds the
  // other set, which the next update writes (update_workspace.hpp).
  PagePool<double> results_;
  UpdateWorkspace workspace_;  // the update's buffers, reused (update_workspace.hpp)
  int counts_[16] = {0};
  double totals_[8] = {0};

  // Distributed models: global ids, ghosts and padding (set up before
  // finalize), the migrating and the received contacts.
  Partition partition_;
  Migration migration_;

  friend class Updater;
  friend struct RestartCodec;
  friend struct MigrationCodec;
  // The group pair of two segments' groups (index into group_pairs_), or -1.
  int group_pair_index(int seg_a, int seg_b) const {
    const uint64_t key = dense_key(table_.segment(seg_a).group, table_.segment(seg_b).group);
    auto it = std::lower_bound(gp_of_groups_.begin(), gp_of_groups_.end(),
                               std::pair<uint64_t, int>(key, -1));
    return it != gp_of_groups_.end() && it->first == key ? it->second : -1;
  }
  static uint64_t dense_key(int ga, int gb) {
    return static_cast<uint64_t>(static_cast<uint32_t>(ga)) << 32 | static_cast<uint32_t>(gb);
  }
  void invalidate_search() {
    candidates_.clear();
    build_coords_.clear();
  }
  bool may_pair(int a, int b) const;
  // The O(n) check before the search: B2B_ERR_COINCIDENT for the first
  // element of a beam whose two nodes coincide in coords (used nodes).
  Problem check_elements(const double* coords) const;
  // may_pair with the self-contact arc spans of a restart buffer.
  bool may_pair_with_arcs(int a, int b, const std::vector<double>& lo,
                          const std::vector<double>& hi, const std::vector<double>& total) const;
  double effective_margin() const;
  uint64_t fingerprint() const;

 public:
  // --- read by the interpenetration audit (audit.hpp), which keeps its own
  // search and distances and only looks up what the last update recorded ---
  const std::vector<double>& current_coords() const { return current_coords_; }
  const std::vector<double>& committed_coords() const { return committed_coords_; }
  const NodeIndex& used_index() const { return used_index_; }
  const PairRows& candidates() const { return candidates_; }
};

}  // namespace model
}  // namespace b2b
