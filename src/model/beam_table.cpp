#include "beam_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <b2b/b2b.h>

#include "../curve/kinds.hpp"
#include "../curve/topology.hpp"

namespace b2b {
namespace model {

void BeamTable::build(std::vector<Beam>& beams, const std::vector<int>& dense_group) {
  segs_.clear();
  first_.clear();
  count_.clear();
  closed_.clear();
  arc_lo_.clear();
  arc_hi_.clear();
  arc_total_.clear();
  for (size_t b = 0; b < beams.size(); ++b) {
    Beam& beam = beams[b];
    const int n = static_cast<int>(beam.nodes.size());
    const int nseg = curve::segment_count(beam.kind, n, beam.closed);
    beam.first_segment = static_cast<int>(segs_.size());
    beam.n_segments = nseg;
    first_.push_back(beam.first_segment);
    count_.push_back(nseg);
    closed_.push_back(beam.closed);
    for (int s = 0; s < nseg; ++s) {
      SegmentInfo info;
      info.beam = static_cast<int>(b);
      info.index = s;
      int local[4];
      curve::segment_patch(beam.kind, n, beam.closed, s, local, &info.start_rule, &info.end_rule);
      for (int k = 0; k < 4; ++k) info.nodes[k] = local[k] < 0 ? -1 : beam.nodes[local[k]];
      info.kind = beam.kind;
      info.group = dense_group[b];
      info.radius = beam.radius;
      segs_.push_back(info);
    }
  }
}

int BeamTable::neighbour(int s, int direction) const {
  const SegmentInfo& info = segs_[s];
  const int b = info.beam, n = count_[b];
  int t = info.index + direction;
  if (t < 0 || t >= n) {
    if (!closed_[b]) return -1;
    t = (t + n) % n;
  }
  return first_[b] + t;
}

bool BeamTable::share_node(int a, int b) const {
  const int *na = segs_[a].nodes, *nb = segs_[b].nodes;
  for (int i = 0; i < 4; ++i) {
    if (na[i] < 0) continue;
    for (int j = 0; j < 4; ++j)
      if (na[i] == nb[j]) return true;
  }
  return false;
}

void BeamTable::measure_arcs(const std::vector<Beam>& beams, const double* coords,
                             const NodeIndex& used_index) {
  arc_lo_.assign(segs_.size(), 0.0);
  arc_hi_.assign(segs_.size(), 0.0);
  arc_total_.assign(beams.size(), 0.0);
  for (size_t b = 0; b < beams.size(); ++b) {
    const Beam& beam = beams[b];
    const int n = static_cast<int>(beam.nodes.size());
    // cum[k]: chord length from node 0 to node k; cum[n]: around the ring.
    std::vector<double> cum(n + 1, 0.0);
    const int last = beam.closed ? n : n - 1;
    for (int k = 0; k < last; ++k) {
      const double* p = coords + used_index.offset(beam.nodes[k]);
      const double* q = coords + used_index.offset(beam.nodes[(k + 1) % n]);
      cum[k + 1] = cum[k] + std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
    }
    if (!beam.closed) cum[n] = cum[n - 1];
    arc_total_[b] = cum[n];
    for (int s = 0; s < beam.n_segments; ++s) {
      const int g = beam.first_segment + s;
      if (curve::kind_info(beam.kind).centred_on_node) {
        // centred on node s, from the middle of the element before to the
        // middle of the element after (the node itself at an open end)
        double before = 0.0;  // the element before node s (none at an open start)
        if (s > 0)
          before = cum[s] - cum[s - 1];
        else if (beam.closed)
          before = cum[n] - cum[n - 1];
        const double after = (s < n - 1 || beam.closed) ? cum[s + 1] - cum[s] : 0.0;
        arc_lo_[g] = cum[s] - 0.5 * before;
        arc_hi_[g] = cum[s] + 0.5 * after;
      } else {
        arc_lo_[g] = cum[s];
        arc_hi_[g] = cum[s + 1];
      }
    }
  }
}

double BeamTable::arc_gap(const Beam& beam, int a, int b, const std::vector<double>& lo,
                          const std::vector<double>& hi, const std::vector<double>& total) const {
  if (lo[a] > lo[b]) std::swap(a, b);
  double gap = std::max(0.0, lo[b] - hi[a]);
  if (beam.closed) gap = std::min(gap, std::max(0.0, lo[a] + total[segs_[a].beam] - hi[b]));
  return gap;
}

void NodeIndex::build(const std::vector<int>& sorted_used, int n_nodes) {
  // dense while the table is at most 4 times the used nodes (plus a little)
  dense_ = static_cast<int64_t>(n_nodes) <= 4 * static_cast<int64_t>(sorted_used.size()) + 4096;
  if (!dense_) {
    table_ = sorted_used;
    return;
  }
  table_.assign(static_cast<size_t>(n_nodes), -1);
  for (size_t k = 0; k < sorted_used.size(); ++k) table_[sorted_used[k]] = static_cast<int>(k);
}

void BeamTable::set_arcs(std::vector<double> lo, std::vector<double> hi,
                         std::vector<double> total) {
  arc_lo_ = std::move(lo);
  arc_hi_ = std::move(hi);
  arc_total_ = std::move(total);
}

}  // namespace model
}  // namespace b2b
