// The C boundary: every extern "C" entry point runs its body through
// guarded(), so no C++ exception ever reaches the caller, and reports bad
// input through a Reporter, which words the message into the caller's buffer.
#pragma once

#include <exception>
#include <new>

#include <b2b/b2b.h>

namespace b2b {
namespace capi {

// Writes "<function>: <message>" into the caller's errmsg buffer, if any.
class Reporter {
 public:
  Reporter(const char* function, char* errmsg, int errmsg_len)
      : function_(function), errmsg_(errmsg), errmsg_len_(errmsg_len) {}

  // Records the message and returns status, so callers can write
  // `return r.fail(B2B_ERR_..., "...", ...);`.
  int fail(int status, const char* format, ...) const
#if defined(__GNUC__)
      __attribute__((format(printf, 3, 4)))
#endif
      ;

 private:
  const char* function_;
  char* errmsg_;
  int errmsg_len_;
};

template <class Body>
int guarded(const Reporter& r, Body&& body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return r.fail(B2B_ERR_NOMEM, "out of memory");
  } catch (const std::exception& e) {
    return r.fail(B2B_ERR_INTERNAL, "internal error: %s", e.what());
  } catch (...) {
    return r.fail(B2B_ERR_INTERNAL, "internal error: unknown exception");
  }
}

}  // namespace capi
}  // namespace b2b
