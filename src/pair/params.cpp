#include "params.hpp"

#include <cmath>

#include <b2b/b2b.h>

#include "laws.hpp"

namespace b2b {
namespace pair {

namespace {
constexpr double kDegree = 3.14159265358979323846 / 180.0;
double sin2_deg(double deg) {
  const double s = std::sin(deg * kDegree);
  return s * s;
}
}  // namespace

MissingOption line_contact_missing(const Params& p) {
  if (!p.line_penalty_set) return MissingOption::LinePenalty;
  if (p.friction > 0.0 && !p.line_tangential_penalty_set)
    return MissingOption::LineTangentialPenalty;
  return MissingOption::None;
}

Params line_point_params(const Params& p) {
  Params q = p;
  q.penalty = p.line_penalty;
  q.tangential_penalty = p.line_tangential_penalty;
  return q;
}

MissingOption finalize(Params& p) {
  if (p.finalized) return MissingOption::None;
  if (!p.penalty_set) return MissingOption::Penalty;
  if (law_info(p.law).regularized && !p.regularization_gap_set)
    return MissingOption::RegularizationGap;
  if (p.friction > 0.0 && !p.tangential_penalty_set) return MissingOption::TangentialPenalty;
  if (p.contact_type != B2B_CONTACT_TYPE_POINT) {
    const MissingOption line = line_contact_missing(p);
    if (line != MissingOption::None) return line;
  }
  // The blend needs the point element defined where it has weight, and a
  // range to blend over.
  if (p.contact_type == B2B_CONTACT_TYPE_ALL_ANGLE &&
      !(p.parallel_angle_deg < p.line_angle_deg && p.line_angle_deg < p.point_angle_deg))
    return MissingOption::BlendRange;
  p.sin_parallel_angle = std::sin(p.parallel_angle_deg * kDegree);
  p.sin2_line_angle = sin2_deg(p.line_angle_deg);
  p.sin2_point_angle = sin2_deg(p.point_angle_deg);
  p.finalized = true;
  return MissingOption::None;
}

}  // namespace pair
}  // namespace b2b
