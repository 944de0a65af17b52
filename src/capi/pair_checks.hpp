// The arguments every pair entry point shares (b2b_pair_eval, _ends,
// _line): the two segments, their patches, end tangents and radii, checked
// and turned into the pair layer's SegmentInput.
#pragma once

#include "../pair/contact_element.hpp"
#include "firewall.hpp"

namespace b2b {
namespace capi {

extern const char* const kPairBeam[2];  // "beam A: ", "beam B: " (message prefixes)

// seg[b] points into X, end_tangents (as unit[b], which receives the unit
// host tangents) and radii; B2B_OK or the first problem's status.
int check_pair_segments(const Reporter& r, const int* segments, const double* X,
                        const double* end_tangents, const double* radii,
                        pair::SegmentInput seg[2], double unit[2][6]);

}  // namespace capi
}  // namespace b2b
