#include "segment_checks.hpp"

#include <cmath>

#include <b2b/b2b.h>

#include "../curve/kinds.hpp"
#include "tables.hpp"

namespace b2b {
namespace capi {
namespace {

const char kAxis[] = "xyz";

// Unit direction of a host end tangent; scaled first so that any finite
// vector, however large or small, normalises without overflow.
int unit_tangent(const Reporter& r, const char* beam, const double* t, const char* where,
                 double* unit) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(t[i]))
      return r.fail(B2B_ERR_NONFINITE, "%sthe end tangent at the %s node has a non-finite %c (%g)",
                    beam, where, kAxis[i], t[i]);
  const double m = std::fmax(std::fabs(t[0]), std::fmax(std::fabs(t[1]), std::fabs(t[2])));
  if (m == 0.0)
    return r.fail(B2B_ERR_RANGE, "%sthe end tangent at the %s node is the zero vector", beam,
                  where);
  const double s[3] = {t[0] / m, t[1] / m, t[2] / m};
  const double n = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (int i = 0; i < 3; ++i) unit[i] = s[i] / n;
  return B2B_OK;
}

}  // namespace

int check_kind(const Reporter& r, int kind, const char* beam) {
  return check_enumerated(r, beam, "curve kind", kind, curve::kKindEnumeration);
}

int check_segment(const Reporter& r, const char* beam, int kind, int start_rule, int end_rule,
                  const double* patch, const double* end_tangents, double unit_tangents[6]) {
  if (int st = check_kind(r, kind, beam)) return st;
  if (int st = check_enumerated(r, beam, "start_rule", start_rule, curve::kEndRuleEnumeration))
    return st;
  if (int st = check_enumerated(r, beam, "end_rule", end_rule, curve::kEndRuleEnumeration))
    return st;
  const curve::KindInfo& info = curve::kind_info(kind);
  if (info.centred_on_node && start_rule != B2B_END_NEIGHBOUR && end_rule != B2B_END_NEIGHBOUR)
    return r.fail(B2B_ERR_RANGE,
                  "%sa %s segment cannot both start and end its beam (it is centred on a node, "
                  "so such a beam would have one node); start_rule and end_rule are both beam "
                  "ends",
                  beam, info.name);

  const unsigned used = curve::used_slots(kind, start_rule, end_rule);
  for (int slot = 0; slot < 4; ++slot) {
    if (!(used & (1u << slot))) continue;
    for (int i = 0; i < 3; ++i) {
      const double v = patch[3 * slot + i];
      if (!std::isfinite(v))
        return r.fail(B2B_ERR_NONFINITE, "%spatch node x%d has a non-finite %c coordinate (%g)",
                      beam, slot + 1, kAxis[i], v);
      if (std::fabs(v) > B2B_COORD_MAX)
        return r.fail(B2B_ERR_RANGE, "%spatch node x%d has %c = %g, beyond B2B_COORD_MAX (%g)",
                      beam, slot + 1, kAxis[i], v, B2B_COORD_MAX);
    }
  }

  const bool t0 = curve::uses_start_tangent(kind, start_rule);
  const bool t1 = curve::uses_end_tangent(kind, end_rule);
  if ((t0 || t1) && end_tangents == nullptr)
    return r.fail(B2B_ERR_NULL, "%send_tangents is NULL but the %s rule is B2B_END_TANGENT", beam,
                  t0 ? "start" : "end");
  for (int i = 0; i < 6; ++i) unit_tangents[i] = 0.0;
  if (t0)
    if (int st = unit_tangent(r, beam, end_tangents, "first", unit_tangents)) return st;
  if (t1)
    if (int st = unit_tangent(r, beam, end_tangents + 3, "last", unit_tangents + 3)) return st;
  return B2B_OK;
}

int report_segment_failure(const Reporter& r, const char* beam, const curve::Failure& f) {
  if (f.status == B2B_ERR_COINCIDENT)
    return r.fail(f.status, "%spatch nodes x%d and x%d coincide (zero-length element)", beam,
                  f.slot_a + 1, f.slot_b + 1);
  if (f.status == B2B_ERR_FOLDED)
    return r.fail(f.status,
                  "%sthe patch folds back on itself: nodes x%d and x%d (nearly) coincide, so "
                  "the tangent at x%d has no direction",
                  beam, f.slot_a + 1, f.slot_b + 1, f.slot_a + 2);
  return r.fail(B2B_ERR_INTERNAL, "%ssegment build failed (%d)", beam, f.status);
}

}  // namespace capi
}  // namespace b2b
