// The model's beams as segments: for every segment its beam, its patch of
// host nodes (slots x1..x4, -1 where missing or unused), end rules, kind,
// radius and group; the neighbouring segments along its beam; and the rules
// that exclude a pair before any geometry is looked at (shared host nodes,
// self-contact).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace b2b {
namespace model {

// Host node number -> index among the nodes of beams (-1: no beam's node).
// A table of n_nodes entries when that is not much more than the used nodes
// (the fast case of every real mesh), else a binary search in the sorted
// used nodes: a host's n_nodes alone never costs memory (finalize(INT_MAX)
// with one small beam holds a few ints).
class NodeIndex {
 public:
  void build(const std::vector<int>& sorted_used, int n_nodes);
  int operator[](int node) const {
    if (dense_) return table_[node];
    auto it = std::lower_bound(table_.begin(), table_.end(), node);
    return it != table_.end() && *it == node ? static_cast<int>(it - table_.begin()) : -1;
  }
  // Where a used node's coordinates start in a 3 x n_used array (64 bits).
  size_t offset(int node) const { return 3 * static_cast<size_t>((*this)[node]); }

 private:
  bool dense_ = true;
  std::vector<int> table_;  // dense: per host node; else: the sorted used nodes
};

struct Beam {
  std::vector<int> nodes;  // host node numbers, 0-based
  bool closed = false;
  double radius = 0.0;
  int kind = 0;
  int group = 0;           // the host's group number
  bool self_contact = false;
  double exclusion = -1.0;  // self-contact exclusion length (< 0: default 4 r)
  // set by BeamTable::build
  int first_segment = 0, n_segments = 0;
};

struct SegmentInfo {
  int beam = 0, index = 0;        // beam and segment within it
  int nodes[4] = {-1, -1, -1, -1};  // host nodes of the patch slots
  int start_rule = 0, end_rule = 0;
  int kind = 0;
  int group = 0;                  // dense group index (0 .. n_groups - 1)
  double radius = 0.0;
};

class BeamTable {
 public:
  // Builds the segment table of beams (valid: checked before). groups: the
  // dense index of each beam's group.
  void build(std::vector<Beam>& beams, const std::vector<int>& dense_group);

  int segment_count() const { return static_cast<int>(segs_.size()); }
  const SegmentInfo& segment(int s) const { return segs_[s]; }
  // The segment after (direction +1) or before (-1) s on its beam, across a
  // ring's seam; -1 at an open beam's end.
  int neighbour(int s, int direction) const;
  // Whether two segments' patches share a host node.
  bool share_node(int a, int b) const;
  // Self-contact: the arc spans of the segments of beam b along its chords,
  // from coordinates x of the host nodes (node k at x[3*used(k)]).
  void measure_arcs(const std::vector<Beam>& beams, const double* coords,
                    const NodeIndex& used_index);
  bool arcs_measured() const { return !arc_lo_.empty(); }
  // Arc length between two segments of one beam (0 if they overlap).
  double arc_gap(const Beam& beam, int a, int b) const {
    return arc_gap(beam, a, b, arc_lo_, arc_hi_, arc_total_);
  }
  // The same with given arc spans (a restart buffer's, before it is accepted).
  double arc_gap(const Beam& beam, int a, int b, const std::vector<double>& lo,
                 const std::vector<double>& hi, const std::vector<double>& total) const;
  // The per-segment arc spans, for a restart file (and set_arcs to restore them).
  const std::vector<double>& arc_lo() const { return arc_lo_; }
  const std::vector<double>& arc_hi() const { return arc_hi_; }
  const std::vector<double>& arc_total() const { return arc_total_; }
  void set_arcs(std::vector<double> lo, std::vector<double> hi, std::vector<double> total);

 private:
  std::vector<SegmentInfo> segs_;
  std::vector<int> first_, count_;  // per beam
  std::vector<bool> closed_;
  std::vector<double> arc_lo_, arc_hi_, arc_total_;  // per segment, per beam
};

}  // namespace model
}  // namespace b2b
