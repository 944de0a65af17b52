#include "tables.hpp"

#include <cmath>
#include <cstdio>

namespace b2b {
namespace capi {
namespace {

// A bound as the message shows it: an Int option's as an integer.
// (An unbounded side, kNone, is never converted to an integer.)
void bound_text(double x, OptionType type, char* out, std::size_t size) {
  if (!std::isfinite(x))
    std::snprintf(out, size, "%s", x > 0 ? "inf" : "-inf");
  else if (type == OptionType::Int)
    std::snprintf(out, size, "%lld", static_cast<long long>(x));
  else
    std::snprintf(out, size, "%g", x);
}

// What "must be" is followed by in the range message.
void range_text(const Valid& v, OptionType type, char* out, std::size_t size) {
  char lo[32], hi[32];
  bound_text(v.lo, type, lo, sizeof lo);
  bound_text(v.hi, type, hi, sizeof hi);
  const char* unit = v.unit ? v.unit : "";
  const char* sep = v.unit ? " " : "";
  if (v.hi == Valid::kNone)
    std::snprintf(out, size, "%s %s%s%s", v.lo_open ? ">" : ">=", lo, sep, unit);
  else if (type == OptionType::Int && !v.lo_open && !v.hi_open && v.hi == v.lo + 1.0)
    std::snprintf(out, size, "%s or %s%s%s", lo, hi, sep, unit);
  else if (type == OptionType::Int && !v.lo_open && !v.hi_open)
    std::snprintf(out, size, "in %s .. %s%s%s", lo, hi, sep, unit);
  else if (v.hi_name)
    std::snprintf(out, size, "%s %s and %s %s%s%s", v.lo_open ? ">" : ">=", lo,
                  v.hi_open ? "<" : "<=", v.hi_name, sep, unit);
  else
    std::snprintf(out, size, "in %c%s, %s%c%s%s", v.lo_open ? '(' : '[', lo, hi,
                  v.hi_open ? ')' : ']', sep, unit);
}

}  // namespace

int check_enumerated(const Reporter& r, const char* prefix, const char* what, int value,
                     const Enumeration& values) {
  if (values.contains(value)) return B2B_OK;
  return r.fail(B2B_ERR_UNKNOWN_KIND, "%sunknown %s %d (%s .. %s are 0 .. %d)", prefix, what,
                value, values.first, values.last, values.count - 1);
}

int check_option_value(const Reporter& r, const char* key, OptionType type, const Valid& valid,
                       double value) {
  if (type == OptionType::Real && !std::isfinite(value))
    return r.fail(B2B_ERR_NONFINITE, "\"%s\" = %g is not finite", key, value);
  if (valid.values.count > 0) {
    char what[80];
    std::snprintf(what, sizeof what, "\"%s\"", key);
    return check_enumerated(r, "", what, static_cast<int>(value), valid.values);
  }
  if (valid.in_range(value)) return B2B_OK;
  char must[96];
  range_text(valid, type, must, sizeof must);
  if (type == OptionType::Int)
    return r.fail(B2B_ERR_RANGE, "\"%s\" = %d must be %s", key, static_cast<int>(value), must);
  return r.fail(B2B_ERR_RANGE, "\"%s\" = %g must be %s", key, value, must);
}

int fail_unknown_key(const Reporter& r, const char* key, OptionType type, const char* keys) {
  const char* what = type == OptionType::Real ? "real" : "integer";
  // The list must arrive whole: what is left of B2B_ERRMSG_LEN after it,
  // the text around it and the longest function name (32) is the most of an
  // unknown (possibly huge) key that is echoed, 16 .. 64 characters, "..."
  // marking a cut.
  const int left = B2B_ERRMSG_LEN - 1 - 32 - 40 - static_cast<int>(std::strlen(keys));
  const int room = left < 16 ? 16 : (left > 64 ? 64 : left);
  const bool cut = std::strlen(key) > static_cast<std::size_t>(room);
  return r.fail(B2B_ERR_UNKNOWN_KEY, "unknown %s key \"%.*s%s\" (%s keys: %s)", what, room, key,
                cut ? "..." : "", what, keys);
}

void append_key(char* list, std::size_t size, const char* key) {
  const std::size_t used = std::strlen(list);
  if (used + 1 >= size) return;
  std::snprintf(list + used, size - used, "%s\"%s\"", used ? ", " : "", key);
}

}  // namespace capi
}  // namespace b2b
