// Fuzz target: b2b_segment_eval. Decodes a kind, end rules, a curved patch
// at any scale and offset (possibly degenerate), host end tangents, xi and
// which outputs to ask for, then asserts b2b_curve.h's contract:
//  - the status is one the function documents;
//  - B2B_OK: every requested output finite, d2x symmetric in (a, b) bit for
//    bit; an output does not depend on which others were asked for (asking
//    for more may only fail with B2B_ERR_RANGE, an overflow of the extra
//    output far outside [-1, 1]);
//  - an error: every output and the rest of the message buffer untouched;
//  - slots the segment does not read: other garbage there changes nothing;
//  - bounded time (fuzz_contract.hpp).
#include <cstring>

#include <b2b/b2b.h>

#include "fuzz_contract.hpp"
#include "fuzz_scene.hpp"

using namespace b2b_fuzz;

namespace {

struct Outputs {
  double x[B2B_POINT_LEN], dx[B2B_DPOINT_LEN], d2x[B2B_D2POINT_LEN];
  Outputs() { std::memset(this, 0xA7, sizeof *this); }  // a pattern no output has
};

struct Call {
  SegmentSpec s;
  const double* patch;
  const double* tangents;
  double xi;
};

int eval(const Call& c, unsigned want, Outputs& o, char* msg, int msg_len) {
  return b2b_segment_eval(c.s.kind, c.s.start_rule, c.s.end_rule, c.patch, c.tangents, c.xi,
                          (want & 1) ? o.x : nullptr, (want & 2) ? o.dx : nullptr,
                          (want & 4) ? o.d2x : nullptr, msg, msg_len);
}

double decode_xi(FuzzInput& in) {
  switch (in.pick(8)) {
    case 0: return in.sign();
    case 1: return in.sign() * in.log_uniform(0, 200);  // far outside: overflow
    case 2: return in.wild();
    case 3: return in.uniform(-3, 3);
    default: return in.uniform(-1, 1);
  }
}

// Whether the requested parts of two output sets are equal bit for bit.
bool same_requested(const Outputs& a, const Outputs& b, unsigned want) {
  return (!(want & 1) || same_bits(a.x, b.x, sizeof a.x)) &&
         (!(want & 2) || same_bits(a.dx, b.dx, sizeof a.dx)) &&
         (!(want & 4) || same_bits(a.d2x, b.d2x, sizeof a.d2x));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzInput in(data, size);
  Call c;
  c.s = decode_segment(in);
  double local[12], patch[12], tangents[6];
  decode_chain(in, 4, local);
  if (in.chance(24)) decode_degeneracy(in, local, 4);
  const Placement pl = decode_placement(in);
  place_points(pl, local, patch, 4);
  decode_end_tangents(in, patch, tangents);
  if (in.chance(160)) poison_unused(in, c.s, patch);
  if (in.chance(16)) inject_wild(in, patch, 12);
  c.patch = patch;
  c.tangents = in.chance(12) ? nullptr : tangents;
  c.xi = decode_xi(in);
  const unsigned want = static_cast<unsigned>(in.pick(8));
  MessageBuffer msg(in);

  Outputs o;
  const Outputs untouched;
  const CpuClock clock;
  const int rc = eval(c, want, o, msg.ptr(), msg.len());
  const double t = clock.seconds();
  FUZZ_REQUIRE(t <= time_budget(0), "b2b_segment_eval took %.3f s of CPU time", t);
  FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_NULL, B2B_ERR_NONFINITE, B2B_ERR_UNKNOWN_KIND,
                              B2B_ERR_RANGE, B2B_ERR_COINCIDENT, B2B_ERR_FOLDED}),
               "b2b_segment_eval returned %d: %s", rc, msg.text());
  msg.check(rc, "b2b_segment_eval");
  // Outputs not asked for are NULL in the call, so their buffers stay as
  // they were whatever the status; the asked-for ones on failure too.
  FUZZ_REQUIRE(same_requested(o, untouched, rc == B2B_OK ? ~want & 7u : 7u),
               "b2b_segment_eval: an output was written (status %d, outputs %u): %s", rc, want,
               msg.text());
  if (rc != B2B_OK) return 0;

  FUZZ_REQUIRE(!(want & 1) || all_finite(o.x, B2B_POINT_LEN), "x not finite, xi = %g", c.xi);
  FUZZ_REQUIRE(!(want & 2) || all_finite(o.dx, B2B_DPOINT_LEN), "dx not finite, xi = %g", c.xi);
  FUZZ_REQUIRE(!(want & 4) || all_finite(o.d2x, B2B_D2POINT_LEN), "d2x not finite, xi = %g",
               c.xi);
  if (want & 4)
    for (int half = 0; half < 2; ++half)
      for (int a = 0; a < 12; ++a)
        for (int b = a + 1; b < 12; ++b)
          for (int i = 0; i < 3; ++i)
            FUZZ_REQUIRE(same_bits(&o.d2x[432 * half + i + 3 * (a + 12 * b)],
                                   &o.d2x[432 * half + i + 3 * (b + 12 * a)], sizeof(double)),
                         "d2x not symmetric in (a, b) = (%d, %d), component %d, half %d", a, b,
                         i, half);

  // Everything asked for at once: the same values, or an overflow of what
  // this call did not ask for.
  Outputs all;
  const int rc_all = eval(c, 7u, all, nullptr, 0);
  FUZZ_REQUIRE(rc_all == B2B_OK || (rc_all == B2B_ERR_RANGE && want != 7u),
               "asking for all outputs returns %d where outputs %u returned B2B_OK", rc_all, want);
  if (rc_all == B2B_OK)
    FUZZ_REQUIRE(same_requested(o, all, want),
                 "an output changes with the other outputs asked for (outputs %u)", want);

  // Slots the segment does not read may hold anything.
  if (valid_segment(c.s)) {
    double other[12];
    std::memcpy(other, patch, sizeof other);
    const unsigned used = used_slots(c.s);
    for (int slot = 0; slot < 4; ++slot)
      if (!(used & (1u << slot)))
        for (int i = 0; i < 3; ++i) other[3 * slot + i] = other[3 * slot + i] == 0.0 ? -1e308 : 0.0;
    Call c2 = c;
    c2.patch = other;
    Outputs o2;
    const int rc2 = eval(c2, want, o2, nullptr, 0);
    FUZZ_REQUIRE(rc2 == rc && same_requested(o, o2, want),
                 "the value of an unused patch slot changes the outputs (status %d -> %d)", rc,
                 rc2);
  }
  return 0;
}
