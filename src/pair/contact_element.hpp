// The point-wise beam-to-beam contact element (Wriggers and Zavarise 1997) on
// smoothed centrelines, in three stages: kinematics (contact_kinematics.hpp:
// closest points, ownership, sign-tracked normal and gap), force response
// (here: normal law, Coulomb friction, residual) and the exact tangent
// (tangent_assembly.hpp). doc/contact-element.md derives it.
// A pure function of its inputs: no state, no allocation.
#pragma once

#include "../curve/segment.hpp"
#include "contact_kinematics.hpp"
#include "history.hpp"
#include "linearization.hpp"
#include "params.hpp"
#include "tangent_assembly.hpp"

namespace b2b {
namespace pair {

constexpr int kInfoLength = 32;

// A segment as the C API describes it, not yet built.
struct SegmentInput {
  int kind, start_rule, end_rule;
  const double* X;              // 12 patch coordinates
  const double* unit_tangents;  // 6: unit host end tangents (read where a rule is TANGENT)
  double radius;
};

struct PairResult {
  bool overflow = false;             // an output is not finite (huge penalty x gap)
  int contact_status = 0;            // B2B_CONTACT_*
  double info[kInfoLength] = {0};    // B2B_INFO_*
  double residual[kNdof] = {0};
  double history[kHistoryLengthMax] = {0};  // history_length(params) used
};

// A refused pair: the status (B2B_ERR_COINCIDENT or _FOLDED) and which beam
// (0 = A, 1 = B) and patch slots.
struct PairFailure {
  int status = 0;
  int beam = -1;
  curve::Failure segment;
};

// Builds both segments of a pair (with derivatives) into built and their
// references into refs; a refused one is the failure (its status, beam and
// slots). Inputs are valid (checked at the C boundary).
PairFailure build_pair(const SegmentInput& A, const SegmentInput& B, curve::Segment built[2],
                       SegmentRef refs[2]);

// Builds both segments, then evaluate_built(). Inputs are valid (checked at
// the C boundary).
// ends: an end contact (a node of A or B held, Ends); default the free pair.
PairFailure evaluate_pair(const Params& params, const SegmentInput& A, const SegmentInput& B,
                          const double* hist_old, PairResult& out, double* K,
                          Ends ends = Ends(), TangentColumns* compact = nullptr);

// The element on segments built with derivatives (a contact model builds each
// segment once per update and evaluates every candidate pair on them).
// hist_old: a valid history of history_length(params) doubles. K: 24 x 24,
// column-major, leading dimension 24, or null for no tangent; zero when the
// pair is not active. kin: if not null, receives the kinematics (valid where
// the pair is active; the line element's blending differentiates them).
// compact: if not null (and K not null), K may be left compact, as compact
// says (tangent_assembly.hpp; expand_tangent() writes all of it).
void evaluate_built(const Params& params, const SegmentRef& A, const SegmentRef& B,
                    const double* hist_old, PairResult& out, double* K, Ends ends = Ends(),
                    Kinematics* kin = nullptr, TangentColumns* compact = nullptr);

}  // namespace pair
}  // namespace b2b
