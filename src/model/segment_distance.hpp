// The closest points of two segments of smoothed centrelines, computed on
// their own for the interpenetration audit (audit.hpp): the pair layer's
// closest-point iteration is what the audit checks, so it is not used here.
// Every curve kind's segment is a cubic in xi (curve/segment.hpp: Hermite
// end points and end tangents), so the audit keeps it as one, in powers of
// xi (96 bytes, evaluated by Horner's rule), read off the built segment's
// end points and end tangents. Each segment is sampled at a few points, the closest sampled pair is
// refined by projected Newton steps on the squared distance in [-1, 1]^2
// (an active-set step at the bounds, halved until the distance decreases),
// so a closest point on a joint or a beam end is found clamped to it.
#pragma once

#include "../curve/segment.hpp"

namespace b2b {
namespace model {

// x(xi) = a + b xi + c xi^2 + d xi^3, xi in [-1, 1].
struct Cubic {
  double a[3], b[3], c[3], d[3];
  double p0[3], p1[3];  // x(-1), x(1): the chord
  double bulge;         // |x(xi) - chord(xi)| <= bulge on [-1, 1]
  // The cubic of a built segment (its end points and end tangents).
  static Cubic of(const curve::Segment& s);
  void eval(double xi, double* x, double* xd, double* xdd) const {
    for (int i = 0; i < 3; ++i) {
      x[i] = a[i] + xi * (b[i] + xi * (c[i] + xi * d[i]));
      if (xd) xd[i] = b[i] + xi * (2.0 * c[i] + 3.0 * xi * d[i]);
      if (xdd) xdd[i] = 2.0 * c[i] + 6.0 * xi * d[i];
    }
  }
};

struct SegmentClosest {
  double xi = 0.0, eta = 0.0;  // parameters on A and B, in [-1, 1]
  double dist = 0.0;           // centreline distance |xB(eta) - xA(xi)|
  double d[3] = {0, 0, 0};     // xB(eta) - xA(xi)
  double ta[3] = {0, 0, 0}, tb[3] = {0, 0, 0};  // dx/dxi of A and B there
};

SegmentClosest closest_between(const Cubic& a, const Cubic& b);

// A lower bound of the distance between the two curves: the distance of
// their chords less both bulges (cheap: it spares most pairs whose boxes
// are near but whose curves are not).
double distance_lower_bound(const Cubic& a, const Cubic& b);

// +1 if t lies at the end of its segment (xi = 1, up to a small tolerance),
// -1 at the start, 0 inside.
int at_segment_end(double t);

}  // namespace model
}  // namespace b2b
