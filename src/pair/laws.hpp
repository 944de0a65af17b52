// The normal laws (B2B_LAW_*): one table, an entry per value in value
// order. The C API's checks and messages ("law" in src/capi/capi_params.cpp),
// finalize (params.cpp) and the model's search reach (src/model/) read its
// properties; the mathematics (normal_law.hpp) switches on Law, with no
// default, so that -Wswitch names every switch a new law must join.
//
// A new law: its B2B_LAW_* value in b2b_pair.h (appended, and B2B_LAW_COUNT
// one more), its Law, its entry below and its case in normal_law(). The
// tests loop to B2B_LAW_COUNT.
#pragma once

#include <b2b/b2b.h>

#include "../common/enumeration.hpp"
#include "params.hpp"

namespace b2b {
namespace pair {

enum class Law { Linear = B2B_LAW_LINEAR, Quadratic = B2B_LAW_QUADRATIC };

struct LawInfo {
  Law id;
  int value;         // the B2B_LAW_* value, = id
  const char* name;  // its name, for messages
  // Regularised: the force starts at the gap g0 = "regularization_gap" > 0,
  // which finalize requires; otherwise at g = 0, and g0 is not read.
  bool regularized;
};

inline constexpr LawInfo kLaws[] = {
    {Law::Linear, B2B_NAMED(B2B_LAW_LINEAR), false},
    {Law::Quadratic, B2B_NAMED(B2B_LAW_QUADRATIC), true},
};

static_assert(in_value_order(kLaws) && ids_match_values(kLaws),
              "kLaws lists B2B_LAW_* in value order, each with its Law");
static_assert(sizeof kLaws / sizeof kLaws[0] == B2B_LAW_COUNT,
              "kLaws has one entry per normal law (B2B_LAW_COUNT)");

inline constexpr Enumeration kLawEnumeration = enumeration_of(kLaws);

// The entry of a valid law (checked when "law" is set).
inline const LawInfo& law_info(int law) { return kLaws[law]; }
inline Law law_of(int law) { return kLaws[law].id; }

// The gap at which the force of this parameter set starts: g0 for a
// regularised law, else 0 (what the model's search must reach).
inline double contact_start_gap(const Params& p) {
  return law_info(p.law).regularized ? p.regularization_gap : 0.0;
}

}  // namespace pair
}  // namespace b2b
