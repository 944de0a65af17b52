#include "firewall.hpp"

#include <cstdarg>
#include <cstdio>

namespace b2b {
namespace capi {

int Reporter::fail(int status, const char* format, ...) const {
  if (errmsg_ == nullptr || errmsg_len_ <= 0) return status;
  const int n = std::snprintf(errmsg_, static_cast<size_t>(errmsg_len_), "%s: ", function_);
  if (n >= 0 && n < errmsg_len_) {
    va_list args;
    va_start(args, format);
    std::vsnprintf(errmsg_ + n, static_cast<size_t>(errmsg_len_ - n), format, args);
    va_end(args);
  }
  return status;
}

}  // namespace capi
}  // namespace b2b
