// C entry points of the contact parameters: a handle set by key, validated
// per key and as a whole (finalize), read-only afterwards.
#include <cmath>
#include <cstring>
#include <new>

#include <b2b/b2b.h>

#include "../pair/history.hpp"
#include "firewall.hpp"
#include "params_handle.hpp"

using b2b::capi::check_finalized;
using b2b::capi::guarded;
using b2b::capi::Reporter;

namespace {

bool is(const char* key, const char* name) { return std::strcmp(key, name) == 0; }

// Messages echo at most 64 characters of a caller's key ("%.64s"), so that
// B2B_ERRMSG_LEN always holds the whole message (b2b.h).

const char kRealKeys[] =
    "\"penalty\", \"regularization_gap\", \"parallel_angle\", \"friction\", "
    "\"tangential_penalty\"";
const char kIntKeys[] = "\"law\", \"warm_start\", \"max_iterations\", \"tangent\"";

int check_settable(const Reporter& r, const b2b_params* params, const char* key) {
  if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
  if (key == nullptr) return r.fail(B2B_ERR_NULL, "key is NULL");
  if (params->p.finalized)
    return r.fail(B2B_ERR_STATE, "params is finalized (read-only); cannot set \"%.64s\"", key);
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
  return guarded(r, [&]() -> int {
    if (int st = check_settable(r, params, key)) return st;
    b2b::pair::Params& p = params->p;
    if (!is(key, "penalty") && !is(key, "regularization_gap") && !is(key, "parallel_angle") &&
        !is(key, "friction") && !is(key, "tangential_penalty"))
      return r.fail(B2B_ERR_UNKNOWN_KEY, "unknown real key \"%.64s\" (real keys: %s)", key,
                    kRealKeys);
    if (!std::isfinite(value))
      return r.fail(B2B_ERR_NONFINITE, "\"%.64s\" = %g is not finite", key, value);
    if (is(key, "penalty")) {
      if (value < 0.0) return r.fail(B2B_ERR_RANGE, "\"penalty\" = %g must be >= 0", value);
      p.penalty = value;
      p.penalty_set = true;
    } else if (is(key, "regularization_gap")) {
      if (!(value > 0.0))
        return r.fail(B2B_ERR_RANGE, "\"regularization_gap\" = %g must be > 0", value);
      p.regularization_gap = value;
      p.regularization_gap_set = true;
    } else if (is(key, "friction")) {
      if (value < 0.0) return r.fail(B2B_ERR_RANGE, "\"friction\" = %g must be >= 0", value);
      p.friction = value;
    } else if (is(key, "tangential_penalty")) {
      if (!(value > 0.0))
        return r.fail(B2B_ERR_RANGE, "\"tangential_penalty\" = %g must be > 0", value);
      p.tangential_penalty = value;
      p.tangential_penalty_set = true;
    } else {  // "parallel_angle"
      if (value < 0.0 || value >= 90.0)
        return r.fail(B2B_ERR_RANGE, "\"parallel_angle\" = %g must be in [0, 90) degrees", value);
      p.parallel_angle_deg = value;
    }
    return B2B_OK;
  });
}

int b2b_params_set_int(b2b_params* params, const char* key, int value, char* errmsg,
                       int errmsg_len) {
  const Reporter r("b2b_params_set_int", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_settable(r, params, key)) return st;
    b2b::pair::Params& p = params->p;
    if (is(key, "law")) {
      if (value != B2B_LAW_LINEAR && value != B2B_LAW_QUADRATIC)
        return r.fail(B2B_ERR_UNKNOWN_KIND, "unknown \"law\" %d (B2B_LAW_* are 0 .. 1)", value);
      p.law = value;
    } else if (is(key, "warm_start")) {
      if (value != 0 && value != 1)
        return r.fail(B2B_ERR_RANGE, "\"warm_start\" = %d must be 0 or 1", value);
      p.warm_start = value;
    } else if (is(key, "tangent")) {
      if (value < B2B_TANGENT_EXACT || value > B2B_TANGENT_FD)
        return r.fail(B2B_ERR_UNKNOWN_KIND, "unknown \"tangent\" %d (B2B_TANGENT_* are 0 .. 3)",
                      value);
      p.tangent = value;
    } else if (is(key, "max_iterations")) {
      if (value < 1 || value > 100000)
        return r.fail(B2B_ERR_RANGE, "\"max_iterations\" = %d must be in 1 .. 100000", value);
      p.max_iterations = value;
    } else {
      return r.fail(B2B_ERR_UNKNOWN_KEY, "unknown integer key \"%.64s\" (integer keys: %s)", key,
                    kIntKeys);
    }
    return B2B_OK;
  });
}

int b2b_params_get_real(const b2b_params* params, const char* key, double* value, char* errmsg,
                        int errmsg_len) {
  const Reporter r("b2b_params_get_real", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
    if (key == nullptr) return r.fail(B2B_ERR_NULL, "key is NULL");
    if (value == nullptr) return r.fail(B2B_ERR_NULL, "value is NULL");
    const b2b::pair::Params& p = params->p;
    if (is(key, "penalty"))
      *value = p.penalty;
    else if (is(key, "regularization_gap"))
      *value = p.regularization_gap;
    else if (is(key, "parallel_angle"))
      *value = p.parallel_angle_deg;
    else if (is(key, "friction"))
      *value = p.friction;
    else if (is(key, "tangential_penalty"))
      *value = p.tangential_penalty;
    else
      return r.fail(B2B_ERR_UNKNOWN_KEY, "unknown real key \"%.64s\" (real keys: %s)", key,
                    kRealKeys);
    return B2B_OK;
  });
}

int b2b_params_get_int(const b2b_params* params, const char* key, int* value, char* errmsg,
                       int errmsg_len) {
  const Reporter r("b2b_params_get_int", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
    if (key == nullptr) return r.fail(B2B_ERR_NULL, "key is NULL");
    if (value == nullptr) return r.fail(B2B_ERR_NULL, "value is NULL");
    const b2b::pair::Params& p = params->p;
    if (is(key, "law"))
      *value = p.law;
    else if (is(key, "warm_start"))
      *value = p.warm_start;
    else if (is(key, "max_iterations"))
      *value = p.max_iterations;
    else if (is(key, "tangent"))
      *value = p.tangent;
    else
      return r.fail(B2B_ERR_UNKNOWN_KEY, "unknown integer key \"%.64s\" (integer keys: %s)", key,
                    kIntKeys);
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
        return r.fail(B2B_ERR_STATE,
                      "\"law\" is B2B_LAW_QUADRATIC but \"regularization_gap\" has not been set");
      case b2b::pair::MissingOption::TangentialPenalty:
        return r.fail(B2B_ERR_STATE,
                      "\"friction\" is %g but \"tangential_penalty\" has not been set",
                      p.friction);
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
