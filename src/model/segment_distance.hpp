// The closest points of two segments of smoothed centrelines, computed on
// their own for the interpenetration audit (audit.hpp): the pair layer's
// closest-point iteration is what the audit checks, so it is not used here.
// Each segment is sampled at a few points, the closest sampled pair is
// refined by projected Newton steps on the squared distance in [-1, 1]^2
// (an active-set step at the bounds, halved until the distance decreases),
// so a closest point on a joint or a beam end is found clamped to it.
#pragma once

#include "../curve/segment.hpp"

namespace b2b {
namespace model {

struct SegmentClosest {
  double xi = 0.0, eta = 0.0;  // parameters on A and B, in [-1, 1]
  double dist = 0.0;           // centreline distance |xB(eta) - xA(xi)|
  double d[3] = {0, 0, 0};     // xB(eta) - xA(xi)
  double ta[3] = {0, 0, 0}, tb[3] = {0, 0, 0};  // dx/dxi of A and B there
};

// Segments built by curve::Segment::build (derivatives not needed).
SegmentClosest closest_between(const curve::Segment& a, const curve::Segment& b);

// +1 if t lies at the end of its segment (xi = 1, up to a small tolerance),
// -1 at the start, 0 inside.
int at_segment_end(double t);

}  // namespace model
}  // namespace b2b
