// The contact model (behind the b2b_model handle): the host's beams, which
// groups touch with which parameters, the broad phase, the narrow phase on
// the pair layer, the active set with handover, commit/revert and restart.
// Arguments are checked at the C boundary; what only the model can know
// (node numbers against n_nodes, segments that fold, histories in a restart
// buffer) it reports as a Problem for the C boundary to word.
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "../pair/contact_element.hpp"
#include "../pair/params.hpp"
#include "beam_table.hpp"
#include "contact_state.hpp"
#include "search.hpp"

namespace b2b {
namespace model {

struct GroupPair {
  int ga, gb;  // host group numbers, ga <= gb
  pair::Params params;
  int hist_len;
};

// What went wrong, for the C boundary to word (status 0: nothing).
struct Problem {
  int status = 0;
  enum class What {
    None, NodeRange, SelfNoGroupPair, NoGroupPair, Coordinate, Segment,
    Overflow, Buffer, Equation, Band
  } what = What::None;
  int beam = -1, segment = -1, node = -1, slot_a = -1, slot_b = -1, axis = -1;
  int other_beam = -1, other_segment = -1;
  int row = -1, col = -1;  // equations of a tangent entry outside a band
  double value = 0.0;
  const char* detail = "";
};

// One active contact of the last update.
struct Contact {
  int a, b;  // segments (oriented)
  int nodes[8];
  double info[pair::kInfoLength];
  double residual[pair::kNdof];
  int64_t tangent = -1;  // offset into Model::tangents_ (-1: none)
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
  double search_margin = -1.0;  // < 0: the default (largest radius)
  int threads = 0;
  int max_hops = 16;

  Problem finalize(int n_nodes);
  bool finalized() const { return finalized_; }
  int n_nodes() const { return n_nodes_; }
  // State for the C boundary's checks.
  bool updated() const { return updated_; }      // an update since the last commit/revert
  bool has_results() const { return has_results_; }

  // --- per iteration ---
  // x: host coordinates (node k at x[ldx*k]), valid size (checked by the caller).
  Problem update(const double* x, int ldx, bool want_tangent);
  const std::vector<Contact>& contacts() const { return contacts_; }
  const double* tangent(const Contact& c) const {
    return c.tangent < 0 ? nullptr : tangents_.data() + c.tangent;
  }
  const int* counts() const { return counts_; }
  const double* totals() const { return totals_; }
  bool has_tangents() const { return want_tangent_; }
  const BeamTable& table() const { return table_; }

  void commit();
  void revert();

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
  std::vector<int> used_index_;   // host node -> index in used_nodes_ (-1: unused)
  std::vector<int> dense_group_;  // per beam
  int n_groups_ = 0;
  std::vector<int> gp_of_groups_;  // n_groups^2: group pair index or -1
  double margin_ = 0.0, g0_max_ = 0.0;
  // broad phase
  std::vector<Box> search_boxes_;
  BoxTree tree_;
  std::vector<std::pair<int, int>> candidates_;
  std::vector<double> build_coords_;  // coordinates at the last build
  int builds_ = 0;
  // states
  ContactState committed_, trial_;
  std::vector<double> committed_coords_;  // used nodes at the last commit (empty: none yet)
  std::vector<double> current_coords_;    // of the last update
  bool updated_ = false, has_results_ = false, want_tangent_ = false;
  std::vector<Contact> contacts_;
  std::vector<double> tangents_;
  int counts_[16] = {0};
  double totals_[8] = {0};

  friend class Updater;
  friend struct RestartCodec;
  int group_pair_index(int seg_a, int seg_b) const {
    return gp_of_groups_[table_.segment(seg_a).group * n_groups_ + table_.segment(seg_b).group];
  }
  bool may_pair(int a, int b) const;
  double effective_margin() const;
  uint64_t fingerprint() const;

 public:
  // --- read by the interpenetration audit (audit.hpp), which keeps its own
  // search and distances and only looks up what the last update recorded ---
  const std::vector<double>& current_coords() const { return current_coords_; }
  const std::vector<double>& committed_coords() const { return committed_coords_; }
  const std::vector<int>& used_index() const { return used_index_; }
  const std::vector<std::pair<int, int>>& candidates() const { return candidates_; }
};

}  // namespace model
}  // namespace b2b
