// C entry points of the contact parameters: a handle set by key, validated
// per key and as a whole (finalize), read-only afterwards.
#include <b2b/b2b.h>

#include "../pair/history.hpp"
#include "../pair/laws.hpp"
#include "../pair/line_contact.hpp"
#include "../pair/tangent_options.hpp"
#include "firewall.hpp"
#include "params_handle.hpp"
#include "tables.hpp"

using b2b::capi::check_finalized;
using b2b::capi::guarded;
using b2b::capi::Option;
using b2b::capi::OptionType;
using b2b::capi::Reporter;
using b2b::capi::Valid;
using b2b::pair::Params;

namespace {

// The keys of b2b_params, in the order of b2b_pair.h's table (the messages
// list them in this order). A new option is one entry here, its member of
// Params and its line in b2b_pair.h.
constexpr Option<Params> kOptions[] = {
    {"penalty", OptionType::Real, Valid::at_least(0.0),
     [](Params& p, double v) {
       p.penalty = v;
       p.penalty_set = true;
     },
     [](const Params& p) { return p.penalty; }},
    {"law", OptionType::Int, Valid::one_of(b2b::pair::kLawEnumeration),
     [](Params& p, double v) { p.law = static_cast<int>(v); },
     [](const Params& p) { return static_cast<double>(p.law); }},
    {"regularization_gap", OptionType::Real, Valid::above(0.0),
     [](Params& p, double v) {
       p.regularization_gap = v;
       p.regularization_gap_set = true;
     },
     [](const Params& p) { return p.regularization_gap; }},
    {"parallel_angle", OptionType::Real,
     Valid::interval(0.0, false, 90.0, true, nullptr, "degrees"),
     [](Params& p, double v) { p.parallel_angle_deg = v; },
     [](const Params& p) { return p.parallel_angle_deg; }},
    {"warm_start", OptionType::Int, Valid::interval(0, false, 1, false),
     [](Params& p, double v) { p.warm_start = static_cast<int>(v); },
     [](const Params& p) { return static_cast<double>(p.warm_start); }},
    {"max_iterations", OptionType::Int, Valid::interval(1, false, 100000, false),
     [](Params& p, double v) { p.max_iterations = static_cast<int>(v); },
     [](const Params& p) { return static_cast<double>(p.max_iterations); }},
    {"friction", OptionType::Real, Valid::at_least(0.0),
     [](Params& p, double v) { p.friction = v; },
     [](const Params& p) { return p.friction; }},
    {"tangential_penalty", OptionType::Real, Valid::above(0.0),
     [](Params& p, double v) {
       p.tangential_penalty = v;
       p.tangential_penalty_set = true;
     },
     [](const Params& p) { return p.tangential_penalty; }},
    {"tangent", OptionType::Int, Valid::one_of(b2b::pair::kTangentModeEnumeration),
     [](Params& p, double v) { p.tangent = static_cast<int>(v); },
     [](const Params& p) { return static_cast<double>(p.tangent); }},
    {"contact_type", OptionType::Int, Valid::one_of(b2b::pair::kContactTypeEnumeration),
     [](Params& p, double v) { p.contact_type = static_cast<int>(v); },
     [](const Params& p) { return static_cast<double>(p.contact_type); }},
    {"line_penalty", OptionType::Real, Valid::at_least(0.0),
     [](Params& p, double v) {
       p.line_penalty = v;
       p.line_penalty_set = true;
     },
     [](const Params& p) { return p.line_penalty; }},
    {"line_tangential_penalty", OptionType::Real, Valid::above(0.0),
     [](Params& p, double v) {
       p.line_tangential_penalty = v;
       p.line_tangential_penalty_set = true;
     },
     [](const Params& p) { return p.line_tangential_penalty; }},
    {"line_points", OptionType::Int, Valid::interval(0, false, B2B_LINE_POINTS_MAX, false),
     [](Params& p, double v) { p.line_points = static_cast<int>(v); },
     [](const Params& p) { return static_cast<double>(p.line_points); }},
    {"line_angle", OptionType::Real,
     Valid::interval(0.0, true, 90.0, true, nullptr, "degrees"),
     [](Params& p, double v) { p.line_angle_deg = v; },
     [](const Params& p) { return p.line_angle_deg; }},
    {"point_angle", OptionType::Real,
     Valid::interval(0.0, true, 90.0, true, nullptr, "degrees"),
     [](Params& p, double v) { p.point_angle_deg = v; },
     [](const Params& p) { return p.point_angle_deg; }},
};

int check_settable(const Reporter& r, const b2b_params* params, const char* key) {
  if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
  if (key == nullptr) return r.fail(B2B_ERR_NULL, "key is NULL");
  if (params->p.finalized)
    return r.fail(B2B_ERR_STATE, "params is finalized (read-only); cannot set \"%.64s\"", key);
  return B2B_OK;
}

int set_by_key(const Reporter& r, b2b_params* params, const char* key, OptionType type,
               double value) {
  if (int st = check_settable(r, params, key)) return st;
  const Option<Params>* o = nullptr;
  if (int st = b2b::capi::lookup_option(r, kOptions, key, type, &o)) return st;
  return b2b::capi::set_option(r, *o, params->p, value);
}

int get_by_key(const Reporter& r, const b2b_params* params, const char* key, OptionType type,
               const void* value, double* got) {
  if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
  if (key == nullptr) return r.fail(B2B_ERR_NULL, "key is NULL");
  if (value == nullptr) return r.fail(B2B_ERR_NULL, "value is NULL");
  const Option<Params>* o = nullptr;
  if (int st = b2b::capi::lookup_option(r, kOptions, key, type, &o)) return st;
  *got = o->get(params->p);
  return B2B_OK;
}

}  // namespace

extern "C" {

int b2b_params_create(b2b_params** params, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_params_create", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
    *params = new b2b_params();
    return B2B_OK;
  });
}

int b2b_params_destroy(b2b_params** params) {
  if (params == nullptr) return B2B_OK;
  delete *params;
  *params = nullptr;
  return B2B_OK;
}

int b2b_params_set_real(b2b_params* params, const char* key, double value, char* errmsg,
                        int errmsg_len) {
  const Reporter r("b2b_params_set_real", errmsg, errmsg_len);
  return guarded(r, [&]() -> int { return set_by_key(r, params, key, OptionType::Real, value); });
}

int b2b_params_set_int(b2b_params* params, const char* key, int value, char* errmsg,
                       int errmsg_len) {
  const Reporter r("b2b_params_set_int", errmsg, errmsg_len);
  return guarded(r, [&]() -> int { return set_by_key(r, params, key, OptionType::Int, value); });
}

int b2b_params_get_real(const b2b_params* params, const char* key, double* value, char* errmsg,
                        int errmsg_len) {
  const Reporter r("b2b_params_get_real", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    double got = 0.0;
    if (int st = get_by_key(r, params, key, OptionType::Real, value, &got)) return st;
    *value = got;
    return B2B_OK;
  });
}

int b2b_params_get_int(const b2b_params* params, const char* key, int* value, char* errmsg,
                       int errmsg_len) {
  const Reporter r("b2b_params_get_int", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    double got = 0.0;
    if (int st = get_by_key(r, params, key, OptionType::Int, value, &got)) return st;
    *value = static_cast<int>(got);
    return B2B_OK;
  });
}

int b2b_params_finalize(b2b_params* params, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_params_finalize", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
    b2b::pair::Params& p = params->p;
    switch (b2b::pair::finalize(p)) {
      case b2b::pair::MissingOption::None:
        return B2B_OK;
      case b2b::pair::MissingOption::Penalty:
        return r.fail(B2B_ERR_STATE, "\"penalty\" has not been set");
      case b2b::pair::MissingOption::RegularizationGap:
        return r.fail(B2B_ERR_STATE, "\"law\" is %s but \"regularization_gap\" has not been set",
                      b2b::pair::law_info(p.law).name);
      case b2b::pair::MissingOption::TangentialPenalty:
        return r.fail(B2B_ERR_STATE,
                      "\"friction\" is %g but \"tangential_penalty\" has not been set",
                      p.friction);
      case b2b::pair::MissingOption::LinePenalty:
        return r.fail(B2B_ERR_STATE,
                      "\"contact_type\" is %s but \"line_penalty\" has not been set",
                      b2b::pair::kContactTypes[p.contact_type].name);
      case b2b::pair::MissingOption::LineTangentialPenalty:
        return r.fail(B2B_ERR_STATE,
                      "\"contact_type\" is %s and \"friction\" is %g but "
                      "\"line_tangential_penalty\" has not been set",
                      b2b::pair::kContactTypes[p.contact_type].name, p.friction);
      case b2b::pair::MissingOption::BlendRange:
        return r.fail(B2B_ERR_RANGE,
                      "\"contact_type\" is B2B_CONTACT_TYPE_ALL_ANGLE, which needs "
                      "\"parallel_angle\" < \"line_angle\" < \"point_angle\" (they are %g, "
                      "%g, %g degrees)",
                      p.parallel_angle_deg, p.line_angle_deg, p.point_angle_deg);
    }
    return r.fail(B2B_ERR_INTERNAL, "unclassified finalize outcome");
  });
}

int b2b_params_history_size(const b2b_params* params, int* n, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_params_history_size", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
    if (n == nullptr) return r.fail(B2B_ERR_NULL, "n is NULL");
    if (int st = check_finalized(r, params)) return st;
    *n = b2b::pair::history_length(params->p);
    return B2B_OK;
  });
}

}  // extern "C"
