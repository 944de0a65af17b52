// Argument checks of a segment description (kind, end rules, patch, host end
// tangents), shared by every entry point that takes segments, so that they
// all accept and reject the same inputs with the same messages.
#pragma once

#include "../curve/segment.hpp"
#include "firewall.hpp"

namespace b2b {
namespace capi {

// B2B_ERR_UNKNOWN_KIND unless kind is a B2B_CURVE_* value; `beam` prefixes
// the message ("" or e.g. "beam A: ").
int check_kind(const Reporter& r, int kind, const char* beam = "");

// Checks a segment as b2b_segment_eval documents it; on success writes the
// unit host tangents (6 doubles) where a rule in force is B2B_END_TANGENT.
// `beam` prefixes the messages ("" or e.g. "beam A: ").
int check_segment(const Reporter& r, const char* beam, int kind, int start_rule, int end_rule,
                  const double* patch, const double* end_tangents, double unit_tangents[6]);

// Words a failed Segment::build.
int report_segment_failure(const Reporter& r, const char* beam, const curve::Failure& f);

}  // namespace capi
}  // namespace b2b
