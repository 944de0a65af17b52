// Fuzz target: b2b_pair_eval. Decodes a crossing (fuzz_scene.hpp: any
// angle down to parallel, any scale and offset, coincident or folded nodes,
// unused slots poisoned), a parameter set (both laws, friction, every
// tangent option, warm start, iteration limits), a history that is fresh or
// written by up to three earlier steps (committed or cut back, possibly
// damaged), and the output layout (ldk, aliasing of hist_new and hist_old,
// no tangent). Every call, the earlier steps' too, is held to b2b_pair.h:
//  - a documented status; on error every output (and the padding of the
//    tangent, and hist_new beyond hist_len) untouched, bit for bit;
//  - B2B_OK: every output finite, a contact status, reserved info zero,
//    iterations an integer within "max_iterations", f_N and dissipation
//    >= 0, the angle in [0, 90], |T| <= mu f_N, no force ⇒ zero residual and
//    tangent; info[B2B_INFO_SYMMETRIC] = 1 ⇒ the tangent symmetric bit for
//    bit (and it is 1 without friction, unless the tangent is FD);
//  - the history it wrote is one the next call accepts;
//  - the same residual and history without a tangent, and with hist_new
//    being hist_old;
//  - bounded time (fuzz_contract.hpp).
#include <cmath>
#include <cstdio>
#include <cstring>

#include <b2b/b2b.h>

#include "fuzz_contract.hpp"
#include "fuzz_scene.hpp"

using namespace b2b_fuzz;

namespace {

constexpr int kHistCap = 64;   // room for any hist_len the input asks for
constexpr int kLdkMax = 31;

struct Pair {
  b2b_params* params = nullptr;
  ParamsInfo pi;
  int segments[6];
  const double* tangents;
  double radii[2];
  ~Pair() { b2b_params_destroy(&params); }
};

struct Layout {
  bool want_tangent = true;
  int ldk = 24;
  bool alias = false;  // hist_new is hist_old
};

struct Result {
  int rc;
  int status;
  double info[B2B_PAIR_INFO_LEN];
  double residual[B2B_PAIR_NDOF];
  double tangent[kLdkMax * B2B_PAIR_NDOF];
  double hist_new[kHistCap];
  char message[B2B_ERRMSG_LEN];
};

// One call, checked against the contract; r holds its outputs.
void run(const Pair& p, const double X[24], const double* hist_old, int hist_len,
         const Layout& lay, MessageBuffer* msg, Result& r) {
  static Result untouched;  // the fill pattern, made once
  static bool made = false;
  if (!made) {
    std::memset(&untouched, 0xA7, sizeof untouched);
    made = true;
  }
  std::memcpy(&r, &untouched, sizeof r);
  double work[kHistCap];  // the aliased array: hist_old in, hist_new out
  std::memcpy(work, hist_old, sizeof work);
  double* const out_hist = lay.alias ? work : r.hist_new;
  const double* const in_hist = lay.alias ? work : hist_old;
  double* const K = lay.want_tangent ? r.tangent : nullptr;
  char* mptr = msg ? msg->ptr() : r.message;
  const int mlen = msg ? msg->len() : static_cast<int>(sizeof r.message);

  if (printing()) {
    std::fprintf(stderr, "b2b_pair_eval: hist_len %d, tangent %s, ldk %d, hist_new %s\n",
                 hist_len, lay.want_tangent ? "yes" : "NULL", lay.ldk,
                 lay.alias ? "is hist_old" : "separate");
    print_params(p.params);
    print_ints("segments", p.segments, 6);
    print_doubles("X", X, 24);
    if (p.tangents) print_doubles("end_tangents", p.tangents, 12);
    print_doubles("radii", p.radii, 2);
    print_doubles("hist_old", hist_old, hist_len > 0 && hist_len <= kHistCap ? hist_len : 0);
  }
  const CpuClock clock;
  r.rc = b2b_pair_eval(p.params, p.segments, X, p.tangents, p.radii, in_hist, out_hist, hist_len,
                       &r.status, r.info, r.residual, K, lay.ldk, mptr, mlen);
  const double t = clock.seconds();
  const double work_bound =
      static_cast<double>(p.pi.max_iterations) * (p.pi.tangent == B2B_TANGENT_FD ? 49 : 1);
  FUZZ_REQUIRE(t <= time_budget(work_bound), "b2b_pair_eval took %.3f s of CPU time "
               "(max_iterations %d, tangent option %d)", t, p.pi.max_iterations, p.pi.tangent);
  const char* text = msg ? msg->text() : r.message;
  FUZZ_REQUIRE(status_in(r.rc, {B2B_OK, B2B_ERR_NULL, B2B_ERR_UNKNOWN_KIND, B2B_ERR_NONFINITE,
                                B2B_ERR_RANGE, B2B_ERR_SIZE, B2B_ERR_COINCIDENT, B2B_ERR_FOLDED}),
               "b2b_pair_eval returned %d: %s", r.rc, text);
  if (msg) msg->check(r.rc, "b2b_pair_eval");
  if (lay.alias) std::memcpy(r.hist_new, work, sizeof work);

  const int ldk = lay.ldk;
  if (r.rc != B2B_OK) {
    FUZZ_REQUIRE(same_bits(&r.status, &untouched.status, sizeof r.status) &&
                     same_bits(r.info, untouched.info, sizeof r.info) &&
                     same_bits(r.residual, untouched.residual, sizeof r.residual) &&
                     same_bits(r.tangent, untouched.tangent, sizeof r.tangent),
                 "b2b_pair_eval failed (%d) but wrote an output: %s", r.rc, text);
    FUZZ_REQUIRE(lay.alias ? same_bits(r.hist_new, hist_old, sizeof r.hist_new)
                           : same_bits(r.hist_new, untouched.hist_new, sizeof r.hist_new),
                 "b2b_pair_eval failed (%d) but wrote hist_new: %s", r.rc, text);
    return;
  }

  const double* info = r.info;
  FUZZ_REQUIRE(r.status >= B2B_CONTACT_OPEN && r.status <= B2B_CONTACT_NO_NORMAL,
               "contact status %d", r.status);
  FUZZ_REQUIRE(all_finite(info, B2B_PAIR_INFO_LEN), "info not finite (status %d)", r.status);
  FUZZ_REQUIRE(all_finite(r.residual, B2B_PAIR_NDOF), "residual not finite (status %d)",
               r.status);
  FUZZ_REQUIRE(all_finite(r.hist_new, hist_len), "hist_new not finite (status %d)", r.status);
  FUZZ_REQUIRE(lay.alias || same_bits(r.hist_new + hist_len, untouched.hist_new + hist_len,
                                      sizeof(double) * (kHistCap - hist_len)),
               "hist_new written beyond hist_len %d", hist_len);
  if (lay.want_tangent) {
    for (int c = 0; c < 24; ++c) {
      FUZZ_REQUIRE(all_finite(r.tangent + ldk * c, 24), "tangent column %d not finite", c);
      FUZZ_REQUIRE(same_bits(r.tangent + ldk * c + 24, untouched.tangent + ldk * c + 24,
                             sizeof(double) * (ldk - 24)),
                   "tangent padding of column %d written (ldk %d)", c, ldk);
    }
  }
  for (int i = B2B_INFO_DISSIPATION + 1; i < B2B_PAIR_INFO_LEN; ++i)
    FUZZ_REQUIRE(info[i] == 0.0, "reserved info[%d] = %g", i, info[i]);
  const double it = info[B2B_INFO_ITERATIONS];
  FUZZ_REQUIRE(it >= 0 && it <= p.pi.max_iterations && it == std::floor(it),
               "info[B2B_INFO_ITERATIONS] = %g with max_iterations %d", it, p.pi.max_iterations);
  const double sym = info[B2B_INFO_SYMMETRIC];
  FUZZ_REQUIRE(sym == 0.0 || sym == 1.0, "info[B2B_INFO_SYMMETRIC] = %g", sym);
  if (sym == 1.0 && lay.want_tangent)
    FUZZ_REQUIRE(exactly_symmetric(r.tangent, 24, ldk),
                 "info says symmetric, the tangent is not (status %d, friction %g, tangent "
                 "option %d)", r.status, p.pi.friction, p.pi.tangent);
  // Without friction the tangent is symmetric, but for the FD option and
  // where the axes intersect (to rounding: the previous normal is used
  // then, the gap is -r_A - r_B, and the tangent leaves out the normal's
  // rotation: b2b_pair.h).
  const bool intersecting = info[B2B_INFO_GAP] == -p.radii[0] - p.radii[1];
  if (p.pi.friction == 0.0 && p.pi.tangent != B2B_TANGENT_FD && !intersecting)
    FUZZ_REQUIRE(sym == 1.0, "frictionless tangent reported non-symmetric (option %d)",
                 p.pi.tangent);
  const double fn = info[B2B_INFO_NORMAL_FORCE];
  FUZZ_REQUIRE(fn >= 0.0, "normal force %g", fn);
  FUZZ_REQUIRE(info[B2B_INFO_DISSIPATION] >= 0.0, "dissipation %g", info[B2B_INFO_DISSIPATION]);
  FUZZ_REQUIRE(info[B2B_INFO_ANGLE] >= 0.0 && info[B2B_INFO_ANGLE] <= 90.0, "angle %g",
               info[B2B_INFO_ANGLE]);
  const double fs = info[B2B_INFO_FRICTION_STATE];
  FUZZ_REQUIRE(fs == B2B_FRICTION_NONE || fs == B2B_FRICTION_STICK || fs == B2B_FRICTION_SLIP,
               "friction state %g", fs);
  const double* T = info + B2B_INFO_TANGENTIAL_FORCE;
  const double tmag = std::hypot(T[0], std::hypot(T[1], T[2]));
  FUZZ_REQUIRE(tmag <= p.pi.friction * fn * (1 + 1e-12) + 1e-300,
               "|T| = %.17g beyond mu f_N = %.17g", tmag, p.pi.friction * fn);
  if (r.status != B2B_CONTACT_ACTIVE) {
    for (int i = 0; i < 24; ++i)
      FUZZ_REQUIRE(r.residual[i] == 0.0, "status %d with residual[%d] = %g", r.status, i,
                   r.residual[i]);
    if (lay.want_tangent)
      for (int c = 0; c < 24; ++c)
        for (int i = 0; i < 24; ++i)
          FUZZ_REQUIRE(r.tangent[i + ldk * c] == 0.0, "status %d with a tangent entry %g",
                       r.status, r.tangent[i + ldk * c]);
    FUZZ_REQUIRE(tmag == 0.0 && fs == B2B_FRICTION_NONE,
                 "status %d with a tangential force or friction state", r.status);
  }
}

// The history a successful call wrote is one b2b accepts: the same call with
// it as hist_old fails, if at all, only by an overflow of the force.
void check_history_accepted(const Pair& p, const double X[24], const Result& r, int hist_len) {
  Result again;
  Layout plain;
  plain.want_tangent = false;
  run(p, X, r.hist_new, hist_len, plain, nullptr, again);
  FUZZ_REQUIRE(again.rc == B2B_OK ||
                   (again.rc == B2B_ERR_RANGE && std::strstr(again.message, "overflows")),
               "the history b2b_pair_eval wrote is refused by the next call (%d): %s", again.rc,
               again.message);
}

// Without a tangent, and with hist_new the same array as hist_old, the call
// gives the same status, residual, info (but the symmetry flag, which
// describes the tangent) and history.
void check_layout_independent(const Pair& p, const double X[24], const double* hist_old,
                              int hist_len, const Layout& lay, const Result& r) {
  Layout other;
  other.want_tangent = !lay.want_tangent;
  other.alias = !lay.alias;
  Result r2;
  run(p, X, hist_old, hist_len, other, nullptr, r2);
  FUZZ_REQUIRE(r2.rc == B2B_OK || (r2.rc == B2B_ERR_RANGE && other.want_tangent),
               "the status depends on the output layout: %d, then %d without/with the tangent "
               "or aliasing", r.rc, r2.rc);
  if (r2.rc != B2B_OK) return;
  double i1[B2B_PAIR_INFO_LEN], i2[B2B_PAIR_INFO_LEN];
  std::memcpy(i1, r.info, sizeof i1);
  std::memcpy(i2, r2.info, sizeof i2);
  i1[B2B_INFO_SYMMETRIC] = i2[B2B_INFO_SYMMETRIC] = 0.0;
  FUZZ_REQUIRE(r.status == r2.status && same_bits(i1, i2, sizeof i1) &&
                   same_bits(r.residual, r2.residual, sizeof r.residual) &&
                   same_bits(r.hist_new, r2.hist_new, sizeof(double) * hist_len),
               "the outputs depend on whether a tangent is asked for or hist_new is hist_old");
}

Layout decode_layout(FuzzInput& in) {
  Layout lay;
  lay.want_tangent = !in.chance(48);
  switch (in.pick(8)) {
    case 0: lay.ldk = 24 + 1 + in.pick(kLdkMax - 24); break;
    case 1: lay.ldk = in.chance(128) ? 23 : in.raw_int(); break;  // too small (if it matters)
    default: lay.ldk = 24; break;
  }
  if (lay.ldk > kLdkMax) lay.ldk = kLdkMax;  // the buffer's size; larger says nothing new
  lay.alias = in.chance(48);
  return lay;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzInput in(data, size);
  Crossing c;
  decode_crossing(in, c);
  Pair p;
  p.params = decode_params(in, c.scale, &p.pi, 100000);
  if (!p.params) return 0;
  for (int b = 0; b < 2; ++b) {
    p.segments[3 * b] = c.seg[b].kind;
    p.segments[3 * b + 1] = c.seg[b].start_rule;
    p.segments[3 * b + 2] = c.seg[b].end_rule;
  }
  p.tangents = in.chance(8) ? nullptr : c.tangents;
  std::memcpy(p.radii, c.radii, sizeof p.radii);
  if (in.chance(8)) inject_wild(in, p.radii, 2);

  // The history: fresh, or written by earlier steps (each committed or cut
  // back), every one of them checked like the last.
  double hist[kHistCap] = {0};
  int hist_len = p.pi.hist_len;
  const int steps = in.pick(4);
  for (int s = 0; s < steps; ++s) {
    double X[24];
    decode_motion(in, c, X);
    Layout lay = decode_layout(in);
    Result r;
    MessageBuffer msg(in);
    run(p, X, hist, hist_len, lay, &msg, r);
    if (r.rc == B2B_OK && !in.chance(48)) std::memcpy(hist, r.hist_new, sizeof(double) * hist_len);
  }
  // A damaged or foreign history, or one of the wrong length.
  if (in.chance(10)) {
    if (in.flag()) {
      inject_wild(in, hist, p.pi.hist_len);
    } else {
      hist[in.pick(p.pi.hist_len)] = static_cast<double>(in.pick(5)) - 1.0;  // flags, tags
    }
  }
  if (in.chance(4)) hist_len = in.flag() ? in.pick(kHistCap + 1) : in.raw_int() % (kHistCap + 1);

  double X[24];
  if (in.flag())
    decode_motion(in, c, X);
  else
    std::memcpy(X, c.X, sizeof X);
  if (in.chance(12)) inject_wild(in, X, 24);
  const Layout lay = decode_layout(in);
  MessageBuffer msg(in);
  Result r;
  run(p, X, hist, hist_len, lay, &msg, r);
  if (r.rc != B2B_OK) return 0;
  check_history_accepted(p, X, r, hist_len);
  if (in.chance(64)) check_layout_independent(p, X, hist, hist_len, lay, r);
  return 0;
}
