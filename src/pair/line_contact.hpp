// The line-contact element (Meier, Popp and Wall 2016, on the smoothed
// centrelines, with friction per integration point) and its blend with the
// point element over the crossing angle (B2B_CONTACT_TYPE_ALL_ANGLE; Meier,
// Popp and Wall 2017). Each integration point is the point element with
// A's parameter held at a Gauss point (Ends::at_point), weighted by the
// Gauss weight and the current length element |x_A,xi|; the contract is in
// b2b_pair.h ("Line contact"), the derivation in doc/line-contact.md.
#pragma once

#include <b2b/b2b.h>

#include "../common/enumeration.hpp"
#include "contact_element.hpp"

namespace b2b {
namespace pair {

// The values of "contact_type", in value order.
inline constexpr NamedValue kContactTypes[] = {
    {B2B_NAMED(B2B_CONTACT_TYPE_POINT)},
    {B2B_NAMED(B2B_CONTACT_TYPE_LINE)},
    {B2B_NAMED(B2B_CONTACT_TYPE_ALL_ANGLE)},
};
static_assert(in_value_order(kContactTypes), "kContactTypes lists B2B_CONTACT_TYPE_* in order");
inline constexpr Enumeration kContactTypeEnumeration = enumeration_of(kContactTypes);

constexpr int kLineInfoLength = 16;

// b2b_pair_line_points: "line_points" if set, else the default rule.
int line_points(const Params& p, double length, double radius_a, double radius_b);

struct LineResult {
  bool overflow = false;  // an output is not finite (huge penalty x gap)
  int contact_status = 0;
  double info[kLineInfoLength] = {0};  // B2B_LINE_INFO_*
  double residual[kNdof] = {0};
  // ALL_ANGLE: the point element's own info (unweighted; zero otherwise),
  // what a contact model reports where the point part carries the force.
  double point_part[kInfoLength] = {0};
};

// n_points in 1 .. kGaussMaxPoints; hist_old, hist_new: (n_points + 1)
// histories of history_length(params) doubles each (slot 0 the point
// element's), not aliased; point_info: null or kInfoLength * n_points. K:
// 24 x 24, leading dimension 24, or null. params: finalized, with the
// line options (line_contact_missing() is None).
void evaluate_line(const Params& params, const SegmentRef& A, const SegmentRef& B, int n_points,
                   const double* hist_old, double* hist_new, LineResult& out, double* point_info,
                   double* K);

// Builds both segments, then evaluate_line() (the C API's entry; a contact
// model builds each segment once per update and calls evaluate_line).
PairFailure evaluate_line_pair(const Params& params, const SegmentInput& A,
                               const SegmentInput& B, int n_points, const double* hist_old,
                               double* hist_new, LineResult& out, double* point_info, double* K);

}  // namespace pair
}  // namespace b2b
