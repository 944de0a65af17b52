// A model segment's geometry from the host's coordinates: its patch, the
// built curve segment, a box that contains the curve, and the handover of a
// history across one of its joints on the committed configuration.
#pragma once

#include <vector>

#include "../curve/segment.hpp"
#include "beam_table.hpp"
#include "search.hpp"

namespace b2b {
namespace model {

// The 12 patch coordinates (slots without a node: 0, never read).
void gather_patch(const SegmentInfo& s, const double* coords, const NodeIndex& used_index,
                  double X[12]);

// The unit host end tangents the model hands on where a kind's rule would
// read them: none, the model uses no B2B_END_TANGENT rule.
extern const double kNoHostTangents[6];

// Segment s built from its patch X (gather_patch).
curve::Failure build_segment_from_patch(const SegmentInfo& s, const double X[12],
                                        curve::Segment& seg, bool derivatives);

curve::Failure build_segment(const SegmentInfo& s, const double* coords,
                             const NodeIndex& used_index, curve::Segment& seg,
                             bool derivatives);

// A box containing the segment's curve, from its Hermite control polygon
// without building it: on xi in [-1, 1] the cubic lies in the convex hull of
// its Bezier points P0, P0 + 2 T0/3, P1 - 2 T1/3, P1. Linear kind: the chord
// x2 x3. Midpoint kind: inside the box of its patch nodes (its control
// points are m12, x2, m23; at a beam end a straight half element). Nodal
// kinds: |T| = l23/2, so the box of x2, x3 grown by l23/3.
// When every node moves by at most d, this box moves by at most 5d/3 per side
// (the l23/3 term by 2d/3): a box grown at a search by r + g0/2 + 4s/3 still
// holds the current box grown by r + g0/2 + s/2 while no node has moved more
// than s/2, which is what the near test (reach r_A + r_B + g0 + s) needs.
Box segment_box(const SegmentInfo& s, const double* coords, const NodeIndex& used_index);

// Maps a committed history across the joint from segment `from` to its
// neighbour `to` (direction +1 or -1) of beam side 0 (A) or 1 (B), with both
// segments built on coords (the committed configuration, where the history's
// anchors live). False when a segment cannot be built there or the two do not
// share the joint.
bool handover_committed(const BeamTable& table, int from, int to, int side, int direction,
                        const std::vector<double>& coords, const NodeIndex& used_index,
                        double* hist, int len);

}  // namespace model
}  // namespace b2b
