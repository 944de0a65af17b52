#include "params.hpp"

#include <cmath>

#include <b2b/b2b.h>

#include "laws.hpp"

namespace b2b {
namespace pair {

MissingOption finalize(Params& p) {
  if (p.finalized) return MissingOption::None;
  if (!p.penalty_set) return MissingOption::Penalty;
  if (law_info(p.law).regularized && !p.regularization_gap_set)
    return MissingOption::RegularizationGap;
  if (p.friction > 0.0 && !p.tangential_penalty_set) return MissingOption::TangentialPenalty;
  p.sin_parallel_angle = std::sin(p.parallel_angle_deg * 3.14159265358979323846 / 180.0);
  p.finalized = true;
  return MissingOption::None;
}

}  // namespace pair
}  // namespace b2b
