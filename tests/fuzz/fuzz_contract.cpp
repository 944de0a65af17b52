#include "fuzz_contract.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace b2b_fuzz {

void violated(const char* file, int line, const char* condition, const char* format, ...) {
  std::fprintf(stderr, "\nb2b fuzz: CONTRACT VIOLATED at %s:%d: %s\n  ", file, line, condition);
  va_list ap;
  va_start(ap, format);
  std::vfprintf(stderr, format, ap);
  va_end(ap);
  std::fprintf(stderr, "\n");
  std::fflush(stderr);
  std::abort();
}

bool printing() {
  static const bool on = std::getenv("B2B_FUZZ_PRINT") != nullptr;
  return on;
}

void trace(const char* format, ...) {
  if (!printing()) return;
  va_list ap;
  va_start(ap, format);
  std::vfprintf(stderr, format, ap);
  va_end(ap);
}

void print_ints(const char* name, const int* v, int n) {
  if (!printing()) return;
  std::fprintf(stderr, "  int %s[%d] = {", name, n);
  for (int i = 0; i < n; ++i) std::fprintf(stderr, "%s%d", i ? ", " : "", v[i]);
  std::fprintf(stderr, "};\n");
}

void print_doubles(const char* name, const double* v, int n) {
  if (!printing()) return;
  std::fprintf(stderr, "  double %s[%d] = {", name, n);
  for (int i = 0; i < n; ++i) {
    std::fprintf(stderr, "%s%s", i ? "," : "", i % 3 ? " " : "\n    ");
    if (std::isnan(v[i]))
      std::fprintf(stderr, "NAN");
    else if (std::isinf(v[i]))
      std::fprintf(stderr, "%sINFINITY", v[i] < 0 ? "-" : "");
    else
      std::fprintf(stderr, "%a", v[i]);
  }
  std::fprintf(stderr, "};\n");
}

void print_params(const b2b_params* p) {
  if (!printing()) return;
  double penalty = 0, g0 = 0, angle = 0, mu = 0, eps_t = 0;
  int law = 0, warm = 0, max_it = 0, tangent = 0;
  b2b_params_get_real(p, "penalty", &penalty, nullptr, 0);
  b2b_params_get_real(p, "regularization_gap", &g0, nullptr, 0);
  b2b_params_get_real(p, "parallel_angle", &angle, nullptr, 0);
  b2b_params_get_real(p, "friction", &mu, nullptr, 0);
  b2b_params_get_real(p, "tangential_penalty", &eps_t, nullptr, 0);
  b2b_params_get_int(p, "law", &law, nullptr, 0);
  b2b_params_get_int(p, "warm_start", &warm, nullptr, 0);
  b2b_params_get_int(p, "max_iterations", &max_it, nullptr, 0);
  b2b_params_get_int(p, "tangent", &tangent, nullptr, 0);
  std::fprintf(stderr, "  params: penalty %a, law %d, regularization_gap %a, parallel_angle %a, "
               "warm_start %d, max_iterations %d, friction %a, tangential_penalty %a, tangent %d\n",
               penalty, law, g0, angle, warm, max_it, mu, eps_t, tangent);
}

bool all_finite(const double* v, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

bool same_bits(const void* a, const void* b, size_t n) { return std::memcmp(a, b, n) == 0; }

bool exactly_symmetric(const double* K, int n, int ld) {
  for (int c = 0; c < n; ++c)
    for (int r = c + 1; r < n; ++r)
      if (!same_bits(&K[r + static_cast<size_t>(ld) * c], &K[c + static_cast<size_t>(ld) * r],
                     sizeof(double)))
        return false;
  return true;
}

bool status_in(int status, std::initializer_list<int> allowed) {
  for (int a : allowed)
    if (status == a) return true;
  return false;
}

MessageBuffer::MessageBuffer(FuzzInput& in) {
  const int mode = in.pick(8);
  null_ = mode == 0;
  len_ = mode == 1 ? 0 : mode == 2 ? 1 + in.pick(16) : B2B_ERRMSG_LEN;
  std::memset(buf_, 0x5a, sizeof buf_);  // not a NUL: a missing terminator shows
  std::memcpy(before_, buf_, sizeof buf_);
}

void MessageBuffer::check(int status, const char* function) const {
  if (status == B2B_OK || null_ || len_ == 0) {
    FUZZ_REQUIRE(same_bits(buf_, before_, sizeof buf_),
                 "%s: the message buffer was written (status %d, errmsg %s, errmsg_len %d)",
                 function, status, null_ ? "NULL" : "given", len_);
    return;
  }
  const void* nul = std::memchr(buf_, '\0', static_cast<size_t>(len_));
  FUZZ_REQUIRE(nul != nullptr, "%s: no NUL within errmsg_len %d (status %d)", function, len_,
               status);
  FUZZ_REQUIRE(len_ == 1 || buf_[0] != '\0', "%s: empty message for status %d", function,
               status);
  FUZZ_REQUIRE(same_bits(buf_ + len_, before_ + len_, sizeof buf_ - len_),
               "%s: wrote beyond errmsg_len %d (status %d)", function, len_, status);
}

double time_budget(double iterations_allowed) { return 1.0 + 200e-6 * iterations_allowed; }

}  // namespace b2b_fuzz
