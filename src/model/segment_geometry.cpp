#include "segment_geometry.hpp"

#include <algorithm>
#include <cmath>

#include <b2b/b2b.h>

#include "../pair/handover.hpp"

namespace b2b {
namespace model {

void gather_patch(const SegmentInfo& s, const double* coords, const std::vector<int>& used_index,
                  double X[12]) {
  for (int k = 0; k < 4; ++k) {
    const int node = s.nodes[k];
    for (int i = 0; i < 3; ++i) X[3 * k + i] = node < 0 ? 0.0 : coords[3 * used_index[node] + i];
  }
}

curve::Failure build_segment(const SegmentInfo& s, const double* coords,
                             const std::vector<int>& used_index, curve::Segment& seg,
                             bool derivatives) {
  double X[12];
  gather_patch(s, coords, used_index, X);
  static const double kNoTangents[6] = {0, 0, 0, 0, 0, 0};  // the model uses no TANGENT rule
  return seg.build(s.kind, s.start_rule, s.end_rule, X, kNoTangents, derivatives);
}

Box segment_box(const SegmentInfo& s, const double* coords, const std::vector<int>& used_index) {
  Box box;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] = HUGE_VAL;
    box.hi[i] = -HUGE_VAL;
  }
  const bool midpoint = s.kind == B2B_CURVE_HERMITE_MIDPOINT;
  for (int k = 0; k < 4; ++k) {
    const int node = s.nodes[k];
    if (node < 0 || (!midpoint && (k == 0 || k == 3))) continue;
    const double* p = coords + 3 * used_index[node];
    for (int i = 0; i < 3; ++i) {
      box.lo[i] = std::min(box.lo[i], p[i]);
      box.hi[i] = std::max(box.hi[i], p[i]);
    }
  }
  if (s.kind == B2B_CURVE_HERMITE_NODAL || s.kind == B2B_CURVE_HERMITE_NODAL_WEIGHTED) {
    const double* p = coords + 3 * used_index[s.nodes[1]];
    const double* q = coords + 3 * used_index[s.nodes[2]];
    const double grow = std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]) / 3.0;
    for (int i = 0; i < 3; ++i) {
      box.lo[i] -= grow;
      box.hi[i] += grow;
    }
  }
  return box;
}

bool handover_committed(const BeamTable& table, int from, int to, int side, int direction,
                        const std::vector<double>& coords, const std::vector<int>& used_index,
                        double* hist, int len) {
  curve::Segment seg[2];
  const int ids[2] = {from, to};
  for (int k = 0; k < 2; ++k)
    if (build_segment(table.segment(ids[k]), coords.data(), used_index, seg[k], false).status)
      return false;
  const pair::HandoverResult r = pair::handover_history(seg[0], seg[1], side, direction, hist, len);
  return r.adjacent && r.in_range;
}

}  // namespace model
}  // namespace b2b
