// Handover of a pair history across a joint of one beam: the committed
// history of the pair that owned the contact point, re-expressed in the
// parameter of the neighbouring segment that owns it now (the contract is in
// b2b_pair.h, b2b_pair_history_handover).
#pragma once

#include "../curve/segment.hpp"
#include "contact_element.hpp"

namespace b2b {
namespace pair {

// Distance of the two segments' joint points, relative to their chords:
// above kJointMismatch they do not share the joint.
constexpr double kJointMismatch = 1e-10;

struct HandoverResult {
  bool adjacent = true;
  bool in_range = true;   // the mapped parameter within kHistParamMax (else nothing written)
  double mapped = 0.0;    // the mapped parameter
  double mismatch = 0.0;  // |x_from(joint) - x_to(joint)| / (chord_from + chord_to)
};

// hist: a validated history of len doubles, rewritten in place. beam: 0 or 1;
// direction: +1 (to follows from) or -1.
HandoverResult handover_history(const curve::Segment& from, const curve::Segment& to, int beam,
                                int direction, double* hist, int len);

// The same on segments not yet built (inputs valid): builds both, then
// hands over. failure.beam says which segment was refused (0 from, 1 to).
struct HandoverOutcome {
  PairFailure failure;
  HandoverResult result;
};
HandoverOutcome handover(const SegmentInput& from, const SegmentInput& to, int beam,
                         int direction, double* hist, int len);

}  // namespace pair
}  // namespace b2b
