#include "pair_checks.hpp"

#include <cmath>

#include <b2b/b2b.h>

#include "segment_checks.hpp"

namespace b2b {
namespace capi {

const char* const kPairBeam[2] = {"beam A: ", "beam B: "};

int check_pair_segments(const Reporter& r, const int* segments, const double* X,
                        const double* end_tangents, const double* radii,
                        pair::SegmentInput seg[2], double unit[2][6]) {
  if (segments == nullptr) return r.fail(B2B_ERR_NULL, "segments is NULL");
  if (X == nullptr) return r.fail(B2B_ERR_NULL, "X is NULL");
  if (radii == nullptr) return r.fail(B2B_ERR_NULL, "radii is NULL");
  for (int b = 0; b < 2; ++b) {
    const int* s = segments + 3 * b;
    if (int st = check_segment(r, kPairBeam[b], s[0], s[1], s[2], X + 12 * b,
                               end_tangents ? end_tangents + 6 * b : nullptr, unit[b]))
      return st;
    if (!std::isfinite(radii[b]))
      return r.fail(B2B_ERR_NONFINITE, "%sradius is not finite (%g)", kPairBeam[b], radii[b]);
    if (radii[b] < 0.0 || radii[b] > B2B_COORD_MAX)
      return r.fail(B2B_ERR_RANGE, "%sradius %g must be in [0, B2B_COORD_MAX]", kPairBeam[b],
                    radii[b]);
    seg[b] = pair::SegmentInput{s[0], s[1], s[2], X + 12 * b, unit[b], radii[b]};
  }
  return B2B_OK;
}

}  // namespace capi
}  // namespace b2b
