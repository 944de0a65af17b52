#include "history_check.hpp"

#include <cmath>
#include <initializer_list>

#include <b2b/b2b.h>

#include "history.hpp"

namespace b2b {
namespace pair {
namespace {

HistoryCheck problem(HistoryProblem what, int index = 0, double value = 0.0) {
  HistoryCheck c;
  c.problem = what;
  c.index = index;
  c.value = value;
  return c;
}

}  // namespace

HistoryCheck check_history(const Params& p, const double* h, int len) {
  const int expected = history_length(p);
  if (len != expected) {
    HistoryCheck c = problem(HistoryProblem::Length, 0, len);
    c.expected = expected;
    return c;
  }
  for (int i = 0; i < len; ++i)
    if (!std::isfinite(h[i])) return problem(HistoryProblem::NonFinite, i, h[i]);
  const double tag = h[kHistTag];
  if (tag != kHistTagFresh && tag != kHistTagV1) return problem(HistoryProblem::Tag, 0, tag);
  if (tag == kHistTagFresh) {
    for (int i = 1; i < len; ++i)
      if (h[i] != 0.0) return problem(HistoryProblem::FreshNotZero, i, h[i]);
    return HistoryCheck();
  }
  for (int slot : {static_cast<int>(kHistXi), static_cast<int>(kHistEta)})
    if (std::fabs(h[slot]) > kHistParamMax) return problem(HistoryProblem::Parameter, slot, h[slot]);
  const double has_normal = h[kHistHasNormal];
  if (has_normal != 0.0 && has_normal != 1.0)
    return problem(HistoryProblem::NormalFlag, kHistHasNormal, has_normal);
  if (has_normal == 1.0) {
    const double* n = h + kHistNormal;
    const double len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (std::fabs(len2 - 1.0) > 1e-8)
      return problem(HistoryProblem::NormalLength, kHistNormal, std::sqrt(len2));
  }
  if (len == kHistoryLengthFriction) {
    const double in_contact = h[kHistInContact], state = h[kHistFrictionState];
    if (in_contact != 0.0 && in_contact != 1.0)
      return problem(HistoryProblem::InContactFlag, kHistInContact, in_contact);
    if (in_contact == 1.0 && has_normal != 1.0) return problem(HistoryProblem::InContactNoNormal);
    constexpr double kStick = B2B_FRICTION_STICK, kSlip = B2B_FRICTION_SLIP;
    if (in_contact == 1.0 && state != kStick && state != kSlip)
      return problem(HistoryProblem::FrictionState, kHistFrictionState, state);
    if (in_contact == 0.0 &&
        (state != 0.0 || h[kHistForceE1] != 0.0 || h[kHistForceE2] != 0.0))
      return problem(HistoryProblem::ForceWithoutContact);
  }
  return HistoryCheck();
}

}  // namespace pair
}  // namespace b2b
