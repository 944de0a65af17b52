#include "segment_geometry.hpp"

#include <algorithm>
#include <cmath>

#include <b2b/b2b.h>

#include "../curve/kinds.hpp"
#include "../pair/handover.hpp"

namespace b2b {
namespace model {

void gather_patch(const SegmentInfo& s, const double* coords, const NodeIndex& used_index,
                  double X[12]) {
  for (int k = 0; k < 4; ++k) {
    const int node = s.nodes[k];
    for (int i = 0; i < 3; ++i) X[3 * k + i] = node < 0 ? 0.0 : coords[used_index.offset(node) + i];
  }
}

const double kNoHostTangents[6] = {0, 0, 0, 0, 0, 0};

curve::Failure build_segment_from_patch(const SegmentInfo& s, const double X[12],
                                        curve::Segment& seg, bool derivatives) {
  return seg.build(s.kind, s.start_rule, s.end_rule, X, kNoHostTangents, derivatives);
}

curve::Failure build_segment(const SegmentInfo& s, const double* coords,
                             const NodeIndex& used_index, curve::Segment& seg,
                             bool derivatives) {
  double X[12];
  gather_patch(s, coords, used_index, X);
  return build_segment_from_patch(s, X, seg, derivatives);
}

Box segment_box(const SegmentInfo& s, const double* coords, const NodeIndex& used_index) {
  Box box;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] = HUGE_VAL;
    box.hi[i] = -HUGE_VAL;
  }
  // A box around the segment's Hermite control polygon (b2b_model.h): the
  // box of the nodes it reads (all_slots) or of x2 and x3 only, grown by
  // l23/3 where the control points x2 + T0/3, x3 - T1/3 may leave it.
  bool all_slots = false, grow_by_third = false;
  switch (curve::kind_of(s.kind)) {
    case curve::Kind::Linear:  // the chord x2 -> x3
      break;
    case curve::Kind::HermiteMidpoint:  // m12, x2, m23: within the box of x1, x2, x3
      all_slots = true;
      break;
    case curve::Kind::HermiteNodal:
    case curve::Kind::HermiteNodalWeighted:  // |T0|, |T1| = l23/2
      grow_by_third = true;
      break;
  }
  for (int k = 0; k < 4; ++k) {
    const int node = s.nodes[k];
    if (node < 0 || (!all_slots && (k == 0 || k == 3))) continue;
    const double* p = coords + used_index.offset(node);
    for (int i = 0; i < 3; ++i) {
      box.lo[i] = std::min(box.lo[i], p[i]);
      box.hi[i] = std::max(box.hi[i], p[i]);
    }
  }
  if (grow_by_third) {
    const double* p = coords + used_index.offset(s.nodes[1]);
    const double* q = coords + used_index.offset(s.nodes[2]);
    const double grow = std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]) / 3.0;
    for (int i = 0; i < 3; ++i) {
      box.lo[i] -= grow;
      box.hi[i] += grow;
    }
  }
  return box;
}

bool handover_committed(const BeamTable& table, int from, int to, int side, int direction,
                        const std::vector<double>& coords, const NodeIndex& used_index,
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
