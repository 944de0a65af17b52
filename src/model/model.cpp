#include "model.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../pair/history.hpp"
#include "../curve/segment.hpp"
#include "../curve/topology.hpp"
#include "../pair/laws.hpp"

namespace b2b {
namespace model {

int Model::add_beam(Beam beam) {
  beams_.push_back(std::move(beam));
  return static_cast<int>(beams_.size()) - 1;
}

void Model::set_group_pair(int ga, int gb, const pair::Params& p) {
  if (ga > gb) std::swap(ga, gb);
  auto found = gp_by_host_.find({ga, gb});
  if (found != gp_by_host_.end()) {
    GroupPair& g = group_pairs_[found->second];
    g.params = p;
    g.hist_len = pair::history_length(p);
    g.line = p.contact_type != B2B_CONTACT_TYPE_POINT;
    if (finalized_) {
      g0_max_ = 0.0;
      for (const GroupPair& h : group_pairs_)
        g0_max_ = std::max(g0_max_, pair::contact_start_gap(h.params));
      invalidate_search();  // boxes depend on g0: search again
    }
    return;
  }
  // both insertions or neither: room first (growing geometrically)
  if (group_pairs_.size() == group_pairs_.capacity())
    group_pairs_.reserve(2 * group_pairs_.size() + 1);
  gp_by_host_.emplace(std::make_pair(ga, gb), static_cast<int>(group_pairs_.size()));
  group_pairs_.push_back(GroupPair{ga, gb, p, pair::history_length(p),
                                   p.contact_type != B2B_CONTACT_TYPE_POINT});
}

const GroupPair* Model::group_pair(int ga, int gb) const {
  if (ga > gb) std::swap(ga, gb);
  auto found = gp_by_host_.find({ga, gb});
  return found == gp_by_host_.end() ? nullptr : &group_pairs_[found->second];
}

void Model::set_search_margin(double s) {
  search_margin = s;
  if (finalized_) invalidate_search();  // the skin and the grown boxes change
}

void Model::set_max_candidates(int n) {
  max_candidates = n;
  if (finalized_) invalidate_search();  // the bound applies from the next search on
}

Problem Model::finalize(int n_nodes) {
  Problem pb;
  if (group_pairs_.empty()) {
    pb.status = B2B_ERR_STATE;
    pb.what = Problem::What::NoGroupPair;
    return pb;
  }
  for (size_t b = 0; b < beams_.size(); ++b) {
    const Beam& beam = beams_[b];
    for (size_t k = 0; k < beam.nodes.size(); ++k)
      if (beam.nodes[k] < 0 || beam.nodes[k] >= n_nodes) {
        pb.status = B2B_ERR_RANGE;
        pb.what = Problem::What::NodeRange;
        pb.beam = static_cast<int>(b);
        pb.node = beam.nodes[k];
        pb.segment = static_cast<int>(k);  // position in the beam's node list
        return pb;
      }
    if (beam.self_contact && !group_pair(beam.group, beam.group)) {
      pb.status = B2B_ERR_STATE;
      pb.what = Problem::What::SelfNoGroupPair;
      pb.beam = static_cast<int>(b);
      pb.node = beam.group;
      return pb;
    }
  }
  int64_t n_segments = 0;  // in 64 bits: beams * nodes may exceed int
  for (const Beam& b : beams_)
    n_segments += curve::segment_count(b.kind, static_cast<int>(b.nodes.size()), b.closed);
  if (n_segments > kMaxSegments) {
    pb.status = B2B_ERR_SIZE;
    pb.what = Problem::What::Segments;
    pb.value = static_cast<double>(n_segments);
    return pb;
  }
  // Everything is built in locals first: an allocation failure leaves the
  // model unfinalized and as it was.
  // Dense group numbers and the group pairs between groups that have beams,
  // in proportion to the beams and the pairs set (never groups squared).
  std::vector<int> groups;
  groups.reserve(beams_.size());
  for (const Beam& b : beams_) groups.push_back(b.group);
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  std::vector<int> dense_group;
  dense_group.reserve(beams_.size());
  for (const Beam& b : beams_)
    dense_group.push_back(static_cast<int>(
        std::lower_bound(groups.begin(), groups.end(), b.group) - groups.begin()));
  auto dense = [&groups](int g) {
    auto it = std::lower_bound(groups.begin(), groups.end(), g);
    return it != groups.end() && *it == g ? static_cast<int>(it - groups.begin()) : -1;
  };
  std::vector<std::pair<uint64_t, int>> gp_of_groups;
  for (size_t k = 0; k < group_pairs_.size(); ++k) {
    const int da = dense(group_pairs_[k].ga), db = dense(group_pairs_[k].gb);
    if (da < 0 || db < 0) continue;  // a group without beams
    gp_of_groups.emplace_back(dense_key(da, db), static_cast<int>(k));
    if (da != db) gp_of_groups.emplace_back(dense_key(db, da), static_cast<int>(k));
  }
  std::sort(gp_of_groups.begin(), gp_of_groups.end());
  // The host nodes of beams, sorted, and their index (n_nodes itself costs
  // nothing: NodeIndex).
  std::vector<int> used;
  for (const Beam& b : beams_) used.insert(used.end(), b.nodes.begin(), b.nodes.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  NodeIndex used_index;
  used_index.build(used, n_nodes);
  BeamTable table;
  std::vector<Beam> beams = beams_;
  table.build(beams, dense_group);
  // [partition] global ids, ghosts and padding checked against the beams
  if (Problem ppb = partition_.finalize(beams); ppb.status) return ppb;

  double g0 = 0.0;
  for (const GroupPair& g : group_pairs_) g0 = std::max(g0, pair::contact_start_gap(g.params));
  n_nodes_ = n_nodes;
  n_groups_ = static_cast<int>(groups.size());
  dense_group_.swap(dense_group);
  gp_of_groups_.swap(gp_of_groups);
  used_nodes_.swap(used);
  used_index_ = std::move(used_index);
  beams_.swap(beams);
  table_ = std::move(table);
  g0_max_ = g0;
  finalized_ = true;
  return pb;
}

double Model::effective_margin() const {
  if (search_margin > 0.0) return search_margin;
  double r = 0.0;
  for (const Beam& b : beams_) r = std::max(r, b.radius);
  return r;
}

// Whether segments a and b may ever be in contact (before any geometry).
bool Model::may_pair(int a, int b) const {
  return may_pair_with_arcs(a, b, table_.arc_lo(), table_.arc_hi(), table_.arc_total());
}

Problem Model::check_elements(const double* coords) const {
  Problem pb;
  for (size_t b = 0; b < beams_.size(); ++b) {
    const Beam& beam = beams_[b];
    const int n = static_cast<int>(beam.nodes.size());
    const int elements = beam.closed ? n : n - 1;
    for (int k = 0; k < elements; ++k) {
      const int u = beam.nodes[k], v = beam.nodes[(k + 1) % n];
      if (!curve::points_coincide(coords + used_index_.offset(u), coords + used_index_.offset(v)))
        continue;
      pb.status = B2B_ERR_COINCIDENT;
      pb.what = Problem::What::Segment;
      pb.beam = static_cast<int>(b);
      // the first segment whose patch holds the element (slots j, j + 1)
      for (int s = 0; s < beam.n_segments && pb.slot_a < 0; ++s) {
        const SegmentInfo& info = table_.segment(beam.first_segment + s);
        for (int j = 0; j < 3; ++j)
          if ((info.nodes[j] == u && info.nodes[j + 1] == v) ||
              (info.nodes[j] == v && info.nodes[j + 1] == u)) {
            pb.segment = s;
            pb.slot_a = j;
            pb.slot_b = j + 1;
            break;
          }
      }
      if (pb.slot_a < 0) {  // (every element is in some patch)
        pb.segment = 0;
        pb.slot_a = 1;
        pb.slot_b = 2;
      }
      return pb;
    }
  }
  return pb;
}

// The same with given arc spans (without them, no two segments of one beam).
bool Model::may_pair_with_arcs(int a, int b, const std::vector<double>& lo,
                               const std::vector<double>& hi,
                               const std::vector<double>& total) const {
  if (group_pair_index(a, b) < 0) return false;
  if (table_.share_node(a, b)) return false;
  const SegmentInfo &sa = table_.segment(a), &sb = table_.segment(b);
  // [partition] the ownership rule; pieces of one global beam never pair
  if (!partition_.evaluates(a, b) || partition_.other_piece(sa, sb)) return false;
  if (sa.beam != sb.beam) return true;
  const Beam& beam = beams_[sa.beam];
  if (!beam.self_contact || lo.empty()) return false;
  const double exclusion = beam.exclusion >= 0.0 ? beam.exclusion : 4.0 * beam.radius;
  return table_.arc_gap(beam, a, b, lo, hi, total) > exclusion;
}

void Model::commit() {
  ContactState committed = trial_;  // copies first: a failed one changes nothing
  std::vector<double> coords = current_coords_;
  committed_ = std::move(committed);
  committed_coords_ = std::move(coords);
  if (table_.arcs_measured()) arcs_committed_ = true;
  updated_ = false;
  migration_.clear();  // [partition] received contacts are in the committed state now
}

void Model::revert() {
  // Arc lengths measured by a reverted update (the first after finalize, or
  // after a revert that forgot them) are forgotten with it: they are
  // measured in the configuration of the first update that is committed.
  if (!arcs_committed_) table_.set_arcs({}, {}, {});
  trial_ = ContactState();
  migration_.clear();  // [partition] received and migrating contacts go with the update
  updated_ = false;
  has_results_ = false;
  contacts_.clear();  // their outputs' pages stay, for the next update to reuse
  std::fill(counts_, counts_ + 16, 0);
  std::fill(totals_, totals_ + 8, 0.0);
}

}  // namespace model
}  // namespace b2b
