#include "model.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../pair/history.hpp"
#include "../pair/laws.hpp"

namespace b2b {
namespace model {

int Model::add_beam(Beam beam) {
  beams_.push_back(std::move(beam));
  return static_cast<int>(beams_.size()) - 1;
}

void Model::set_group_pair(int ga, int gb, const pair::Params& p) {
  if (ga > gb) std::swap(ga, gb);
  for (GroupPair& g : group_pairs_)
    if (g.ga == ga && g.gb == gb) {
      g.params = p;
      g.hist_len = pair::history_length(p);
      if (finalized_) {
        g0_max_ = 0.0;
        for (const GroupPair& h : group_pairs_)
          g0_max_ = std::max(g0_max_, pair::contact_start_gap(h.params));
        candidates_.clear();  // boxes depend on g0: search again
        build_coords_.clear();
      }
      return;
    }
  group_pairs_.push_back(GroupPair{ga, gb, p, pair::history_length(p)});
}

const GroupPair* Model::group_pair(int ga, int gb) const {
  if (ga > gb) std::swap(ga, gb);
  for (const GroupPair& g : group_pairs_)
    if (g.ga == ga && g.gb == gb) return &g;
  return nullptr;
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
    std::vector<int> sorted = beam.nodes;
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
  n_nodes_ = n_nodes;
  // Dense group numbers and the table of which group pairs touch.
  std::vector<int> groups;
  for (const Beam& b : beams_) groups.push_back(b.group);
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  n_groups_ = static_cast<int>(groups.size());
  dense_group_.clear();
  for (const Beam& b : beams_)
    dense_group_.push_back(static_cast<int>(
        std::lower_bound(groups.begin(), groups.end(), b.group) - groups.begin()));
  gp_of_groups_.assign(static_cast<size_t>(n_groups_) * n_groups_, -1);
  for (int i = 0; i < n_groups_; ++i)
    for (int j = 0; j < n_groups_; ++j) {
      const GroupPair* g = group_pair(groups[i], groups[j]);
      if (g) gp_of_groups_[i * n_groups_ + j] = static_cast<int>(g - group_pairs_.data());
    }
  g0_max_ = 0.0;
  for (const GroupPair& g : group_pairs_)
    g0_max_ = std::max(g0_max_, pair::contact_start_gap(g.params));
  table_.build(beams_, dense_group_);
  used_index_.assign(n_nodes, -1);
  used_nodes_.clear();
  for (const Beam& b : beams_)
    for (int node : b.nodes) used_index_[node] = 0;
  for (int k = 0; k < n_nodes; ++k)
    if (used_index_[k] == 0) {
      used_index_[k] = static_cast<int>(used_nodes_.size());
      used_nodes_.push_back(k);
    }
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
  if (group_pair_index(a, b) < 0) return false;
  if (table_.share_node(a, b)) return false;
  const SegmentInfo &sa = table_.segment(a), &sb = table_.segment(b);
  if (sa.beam != sb.beam) return true;
  const Beam& beam = beams_[sa.beam];
  if (!beam.self_contact) return false;
  const double exclusion = beam.exclusion >= 0.0 ? beam.exclusion : 4.0 * beam.radius;
  return table_.arc_gap(beam, a, b) > exclusion;
}

void Model::commit() {
  committed_ = trial_;
  committed_coords_ = current_coords_;
  updated_ = false;
}

void Model::revert() {
  trial_ = ContactState();
  updated_ = false;
  has_results_ = false;
  contacts_.clear();
  tangents_.clear();
}

}  // namespace model
}  // namespace b2b
