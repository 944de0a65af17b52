// The curve kinds (B2B_CURVE_*) and end rules (B2B_END_*): one table each,
// an entry per value in value order. What tells the kinds apart outside
// their mathematics is a property here, and the code reads the property,
// not the kind: the C API's checks and messages (src/capi/segment_checks.cpp),
// which slots a segment reads (segment.cpp), the patch topology
// (topology.cpp) and the model's arc lengths (src/model/beam_table.cpp).
// The mathematics (segment.cpp, the model's boxes) switches on Kind, with no
// default, so that -Wswitch names every switch a new kind must join.
//
// A new kind: its B2B_CURVE_* value in b2b_curve.h (appended, and
// B2B_CURVE_KIND_COUNT one more), its Kind, its entry below, and its case in
// each switch on Kind. The tests loop to B2B_CURVE_KIND_COUNT.
#pragma once

#include <b2b/b2b.h>

#include "../common/enumeration.hpp"

namespace b2b {
namespace curve {

enum class Kind {
  Linear = B2B_CURVE_LINEAR,
  HermiteMidpoint = B2B_CURVE_HERMITE_MIDPOINT,
  HermiteNodal = B2B_CURVE_HERMITE_NODAL,
  HermiteNodalWeighted = B2B_CURVE_HERMITE_NODAL_WEIGHTED
};

struct KindInfo {
  Kind id;
  int value;         // the B2B_CURVE_* value, = id
  const char* name;  // its name, for messages
  // Patch slots the segment reads (bit k: slot x(k+1)): always; and, where
  // the start (end) rule is B2B_END_NEIGHBOUR, the neighbour before the
  // first (after the last) node. Slots read under no rule are never read.
  unsigned slots;
  unsigned start_neighbour_slots;
  unsigned end_neighbour_slots;
  // One segment per node, centred on it (slot x2), reaching half an element
  // to either side: a beam of n nodes has n segments, open or closed, and a
  // segment that starts and ends its beam would be a beam of one node. Else
  // one segment per element, from slot x2 to slot x3.
  bool centred_on_node;
  // A B2B_END_TANGENT rule reads the host's end tangent (the chord of the
  // linear kind needs no direction from anyone).
  bool host_tangents;
};

inline constexpr KindInfo kKinds[] = {
    {Kind::Linear, B2B_NAMED(B2B_CURVE_LINEAR), 0x6u, 0x0u, 0x0u, false, false},
    {Kind::HermiteMidpoint, B2B_NAMED(B2B_CURVE_HERMITE_MIDPOINT), 0x2u, 0x1u, 0x4u, true, true},
    {Kind::HermiteNodal, B2B_NAMED(B2B_CURVE_HERMITE_NODAL), 0x6u, 0x1u, 0x8u, false, true},
    {Kind::HermiteNodalWeighted, B2B_NAMED(B2B_CURVE_HERMITE_NODAL_WEIGHTED), 0x6u, 0x1u, 0x8u,
     false, true},
};

static_assert(in_value_order(kKinds) && ids_match_values(kKinds),
              "kKinds lists B2B_CURVE_* in value order, each with its Kind");
static_assert(sizeof kKinds / sizeof kKinds[0] == B2B_CURVE_KIND_COUNT,
              "kKinds has one entry per curve kind (B2B_CURVE_KIND_COUNT)");

inline constexpr Enumeration kKindEnumeration = enumeration_of(kKinds);

// The entry of a valid kind (checked by the caller: kKindEnumeration).
inline const KindInfo& kind_info(int kind) { return kKinds[kind]; }
inline Kind kind_of(int kind) { return kKinds[kind].id; }

// The end rules: names only (their meaning is in segment.cpp's build).
inline constexpr NamedValue kEndRules[] = {
    {B2B_NAMED(B2B_END_NEIGHBOUR)},
    {B2B_NAMED(B2B_END_REFLECT)},
    {B2B_NAMED(B2B_END_TANGENT)},
};
static_assert(in_value_order(kEndRules), "kEndRules lists B2B_END_* in value order");

inline constexpr Enumeration kEndRuleEnumeration = enumeration_of(kEndRules);

}  // namespace curve
}  // namespace b2b
