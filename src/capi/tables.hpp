// Checks and messages read from the library's tables: enumerated values
// (curve kinds, end rules, normal laws, tangent options: src/common/enumeration.hpp)
// and options set by key. Each handle with options (b2b_params, b2b_model)
// has one table of them, an Option per key (capi_params.cpp,
// capi_model.cpp): its setter, getter, checks and the messages of all of
// them, including the list of keys in "unknown key", come from the entry.
#pragma once

#include <cstddef>
#include <cstring>
#include <limits>

#include <b2b/b2b.h>

#include "../common/enumeration.hpp"
#include "firewall.hpp"

namespace b2b {
namespace capi {

// B2B_ERR_UNKNOWN_KIND unless value is one of the enumeration's; the message
// reads "<prefix>unknown <what> <value> (<first> .. <last> are 0 .. <n-1>)".
int check_enumerated(const Reporter& r, const char* prefix, const char* what, int value,
                     const Enumeration& values);

enum class OptionType { Real, Int };

// The valid values of an option: an enumeration (values.count > 0; any
// other value is B2B_ERR_UNKNOWN_KIND), or lo .. hi with each bound in or
// out (hi = kNone: none; any value outside is B2B_ERR_RANGE). The range
// message is worded from the bounds: ">= 0", "in 1 .. 1000", "0 or 1",
// "in [0, 90) degrees", "> 0 and <= B2B_COORD_MAX" (hi_name).
struct Valid {
  static constexpr double kNone = std::numeric_limits<double>::infinity();

  Enumeration values;
  double lo = 0.0, hi = kNone;
  bool lo_open = false, hi_open = false;
  const char* hi_name = nullptr;  // hi in words, for the message
  const char* unit = nullptr;     // after the range in the message

  static constexpr Valid one_of(Enumeration e) {
    Valid v;
    v.values = e;
    return v;
  }
  static constexpr Valid at_least(double bound) { return interval(bound, false, kNone, false); }
  static constexpr Valid above(double bound) { return interval(bound, true, kNone, false); }
  static constexpr Valid interval(double lower, bool lower_open, double upper, bool upper_open,
                                  const char* upper_name = nullptr, const char* in_unit = nullptr) {
    Valid v;
    v.lo = lower;
    v.lo_open = lower_open;
    v.hi = upper;
    v.hi_open = upper_open;
    v.hi_name = upper_name;
    v.unit = in_unit;
    return v;
  }
  constexpr bool in_range(double x) const {
    return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
  }
};

// One option of a Target (the struct behind a handle): its key, type,
// valid values, and how to set and read it. An Int option's value travels
// as a double (exact for every int).
template <class Target>
struct Option {
  const char* key;
  OptionType type;
  Valid valid;
  void (*set)(Target&, double);  // the value has passed the checks
  double (*get)(const Target&);  // nullptr: the handle has no getter
};

// B2B_ERR_NONFINITE, B2B_ERR_RANGE or B2B_ERR_UNKNOWN_KIND unless value is
// one of the option's valid values (the messages name the key).
int check_option_value(const Reporter& r, const char* key, OptionType type, const Valid& valid,
                       double value);

// B2B_ERR_UNKNOWN_KEY: key (echoed to at most 64 characters, fewer the
// longer the list, so that B2B_ERRMSG_LEN holds the whole message, b2b.h) is
// not one of `keys`, the keys of this type, listed.
int fail_unknown_key(const Reporter& r, const char* key, OptionType type, const char* keys);

// Appends "\"key\"" to a list of keys (", " between them) in list[size].
void append_key(char* list, std::size_t size, const char* key);

// The option of this key and type in the table, or nullptr.
template <class Target, std::size_t N>
const Option<Target>* find_option(const Option<Target> (&table)[N], const char* key,
                                  OptionType type) {
  for (const Option<Target>& o : table)
    if (o.type == type && std::strcmp(o.key, key) == 0) return &o;
  return nullptr;
}

// The option of this key and type, or B2B_ERR_UNKNOWN_KEY with the table's
// keys of that type in the message.
template <class Target, std::size_t N>
int lookup_option(const Reporter& r, const Option<Target> (&table)[N], const char* key,
                  OptionType type, const Option<Target>** option) {
  *option = find_option(table, key, type);
  if (*option) return B2B_OK;
  char keys[B2B_ERRMSG_LEN] = "";
  for (const Option<Target>& o : table)
    if (o.type == type) append_key(keys, sizeof keys, o.key);
  return fail_unknown_key(r, key, type, keys);
}

// Checks the value and sets it.
template <class Target>
int set_option(const Reporter& r, const Option<Target>& o, Target& target, double value) {
  if (int st = check_option_value(r, o.key, o.type, o.valid, value)) return st;
  o.set(target, value);
  return B2B_OK;
}

}  // namespace capi
}  // namespace b2b
