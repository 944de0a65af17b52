// Validation of a pair history that comes from outside the element (a host's
// array, a restart buffer): its length and whether its contents could have
// been written by the element. The pair layer decides; callers word it.
#pragma once

#include "params.hpp"

namespace b2b {
namespace pair {

enum class HistoryProblem {
  None,
  Length,               // length differs from history_length(params): `expected`
  NonFinite,            // entry `index` is `value`
  Tag,                  // unknown format tag `value`
  FreshNotZero,         // tag 0 (fresh) but entry `index` is `value`
  NormalFlag,           // has-normal flag `value` is not 0 or 1
  NormalLength,         // the normal has length `value`
  InContactFlag,        // in-contact flag `value` is not 0 or 1
  InContactNoNormal,    // in contact without a normal
  FrictionState,        // in contact with friction state `value`
  ForceWithoutContact,  // not in contact but a friction state or force
  Parameter,            // |xi| or |eta| (entry `index`) is `value`, beyond kHistParamMax
};

struct HistoryCheck {
  HistoryProblem problem = HistoryProblem::None;
  int index = 0;
  double value = 0.0;
  int expected = 0;
};

HistoryCheck check_history(const Params& p, const double* h, int len);

}  // namespace pair
}  // namespace b2b
