// The contract every fuzz target asserts, in the words of include/b2b/b2b.h:
// a status that the function documents; on success every output finite; on
// failure no output touched, bit for bit; a message on failure and none on
// success. A violation prints what failed and aborts, which libFuzzer
// records as a crash together with the input that caused it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <ctime>
#include <initializer_list>

#include <b2b/b2b.h>

#include "fuzz_input.hpp"

namespace b2b_fuzz {

[[noreturn]] void violated(const char* file, int line, const char* condition, const char* format,
                           ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

#define FUZZ_REQUIRE(cond, ...)                                            \
  do {                                                                     \
    if (!(cond)) ::b2b_fuzz::violated(__FILE__, __LINE__, #cond, __VA_ARGS__); \
  } while (0)

bool all_finite(const double* v, size_t n);
bool same_bits(const void* a, const void* b, size_t n);
// K (n x n, leading dimension ld) equal to its transpose, bit for bit.
bool exactly_symmetric(const double* K, int n, int ld);
// Whether status is one of the codes a function documents. B2B_ERR_INTERNAL
// is never among them: it is b2b's own word for a bug.
bool status_in(int status, std::initializer_list<int> allowed);

// With B2B_FUZZ_PRINT set in the environment, the targets print the
// arguments of their calls (doubles as hexadecimal floats, exact) before
// making them, so that a crash's input can be turned into a reproducer:
//   B2B_FUZZ_PRINT=1 build-fuzz/tests/fuzz/fuzz_pair_eval crash-<hash>
bool printing();
void print_ints(const char* name, const int* v, int n);
void print_doubles(const char* name, const double* v, int n);
void print_params(const b2b_params* p);
// printf to stderr when printing().
void trace(const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

// The message buffer of a call, chosen by the input: NULL, length 0, a few
// bytes (truncation), or the documented B2B_ERRMSG_LEN. Bytes beyond the
// length the call is given are a guard that must stay untouched.
class MessageBuffer {
 public:
  explicit MessageBuffer(FuzzInput& in);
  char* ptr() { return null_ ? nullptr : buf_; }
  int len() const { return len_; }
  // On success nothing written; on failure a NUL-terminated, non-empty
  // message within len (when there is a buffer), nothing beyond it.
  void check(int status, const char* function) const;
  // The message (empty if none was asked for).
  const char* text() const { return null_ || len_ == 0 ? "" : buf_; }

 private:
  static constexpr int kCapacity = B2B_ERRMSG_LEN + 64;
  char buf_[kCapacity];
  char before_[kCapacity];
  int len_ = 0;
  bool null_ = false;
};

// CPU time of the calling thread: unlike the wall clock it does not grow
// when a busy machine takes the core away, so a bound on it cannot flake
// on a shared CI runner.
class CpuClock {
 public:
  CpuClock() : start_(now()) {}
  double seconds() const { return now() - start_; }

 private:
  static double now() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }
  double start_;
};

// The time bound of one call. The work of an evaluation is bounded by its
// closest-point iterations, each a few dozen curve evaluations (at most 40
// line-search trials); one iteration costs about a microsecond, tens under
// the sanitizers. The bound grants each allowed iteration 200 us plus a
// fixed second, so it is far from any honest run (>= 1e3 times) and is only
// exceeded by a call that does not stop when its iteration count says so
// (a loop without a bound, or one that ignores "max_iterations").
double time_budget(double iterations_allowed);

}  // namespace b2b_fuzz
