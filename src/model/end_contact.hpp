// End contacts in the model: node-to-segment and node-to-node contact where
// the closest point of two beams is a node that the segments on both sides
// of it point away from: a convex joint of straight segments (the beam bends
// towards the other one) or a beam's end. There the free element reports
// OUTSIDE on every pair, and without this rule the beams would pass through
// each other in silence (doc/contact-element.md section 14).
//
// The rule, for a pair whose free evaluation is OUTSIDE:
//   - A node of a segment may be held only by the segment that starts at it
//     (as a joint belongs to the next segment), or by the last segment of an
//     open beam at the beam's end: so each node has exactly one owner pair
//     per segment of the other beam, and a node-to-node contact one pair.
//   - A joint inside a beam can be a convex corner only where the tangent
//     turns there, i.e. for the linear kind; the smoothed kinds are G1 at
//     their joints, so their free pairs own every closest point there.
//   - The held node must be the closest point of its beam to first order:
//     the distance grows into the segment and into the segment before it
//     (the Karush-Kuhn-Tucker condition of the distance on the polyline).
//     For straight segments the distance is convex, so such a point is the
//     unique closest point of the two pairs meeting at the node.
//   - The other parameter is free (node-to-segment, owned by the usual
//     [-1, 1) rule), or, where it too leaves its segment towards a held
//     node, held as well (node-to-node).
#pragma once

#include "../pair/contact_element.hpp"

namespace b2b {
namespace model {

// What the rule needs to know about one segment of the model.
struct SegmentEnds {
  bool start_held = false;  // its start node may be held: a beam start, or a linear joint
  bool end_held = false;    // its end node may be held: the end of an open beam
  bool has_prev = false;    // a segment before the start node (then prev_tangent)
  double prev_tangent[3] = {0, 0, 0};  // that segment's dx/dxi at the node
};

// res: the free evaluation of the pair (A, B), OUTSIDE. If the pair owns an
// end contact, res (and K, 24 x 24, if not null) become that contact's, and
// the function returns true; else both are left as they were.
bool resolve_end_contact(const pair::Params& params, const pair::SegmentRef& A,
                         const pair::SegmentRef& B, const SegmentEnds& ea, const SegmentEnds& eb,
                         const double* hist_old, pair::PairResult& res, double* K);

}  // namespace model
}  // namespace b2b
