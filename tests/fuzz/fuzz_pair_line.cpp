// Fuzz target: b2b_pair_eval_line, the line-contact element. Decodes a pair
// of segments (fuzz_scene.hpp's crossing: any angle down to exactly
// parallel, any scale and offset, touching, penetrating, intersecting,
// degenerate), a parameter set of its own (every contact type, both laws,
// friction, the line penalties over 600 decades, zero and non-finite ones,
// the blending angles, every tangent option), n_points (1 .. 32, and out of
// range), a history that is fresh or written by up to three earlier steps
// (committed or cut back, possibly damaged, or of the wrong length), and the
// output layout (ldk, point_info or NULL, no tangent, hist_new aliasing
// hist_old). Every call is held to b2b_pair.h ("Line contact"):
//  - a documented status; on error every output untouched, bit for bit;
//  - B2B_OK: a contact status, every output finite, nothing written beyond
//    n_points, hist_len or the tangent's 24 rows; line_info's counts
//    consistent (POINTS = n, ACTIVE <= OWNED <= n, stick + slip = active
//    with friction), reserved entries zero, forces, energy and dissipation
//    >= 0, the weight in [0, 1], the point element's status -1 unless
//    ALL_ANGLE; each point's info as b2b_pair_eval's (|T| <= mu f_N);
//    SYMMETRIC = 1 => the tangent symmetric bit for bit; no force => zero
//    residual and tangent;
//  - the histories it wrote are accepted by the next call;
//  - bounded time.
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>

#include <b2b/b2b.h>

#include "fuzz_contract.hpp"
#include "fuzz_scene.hpp"

using namespace b2b_fuzz;

namespace {

constexpr int kMaxP = B2B_LINE_POINTS_MAX;
constexpr int kHistCap = (kMaxP + 1) * 16;
constexpr int kLdkMax = 27;

struct LineParams {
  b2b_params* params = nullptr;
  int type = 0, tangent = 0, max_iterations = 50, hist_size = 8;
  double friction = 0.0;
  ~LineParams() { b2b_params_destroy(&params); }
};

double decode_penalty(FuzzInput& in, double scale) {
  switch (in.pick(6)) {
    case 0: return in.log_uniform(-300, 300);
    case 1: return 0.0;
    case 2: return in.wild();
    default: return in.log_uniform(-2, 6) / (scale * scale);
  }
}

// A parameter set for the line element: nullptr if finalize refuses it.
bool decode_line_params(FuzzInput& in, double scale, LineParams& lp) {
  b2b_params* p = nullptr;
  if (b2b_params_create(&p, nullptr, 0) != B2B_OK) return false;
  lp.params = p;
  b2b_params_set_real(p, "penalty", decode_penalty(in, 1.0 / scale), nullptr, 0);
  const int law = in.chance(8) ? in.raw_int() : in.pick(2);
  b2b_params_set_int(p, "law", law, nullptr, 0);
  if (law == B2B_LAW_QUADRATIC || in.chance(16))
    b2b_params_set_real(p, "regularization_gap",
                        in.chance(4) ? in.wild() : scale * in.log_uniform(-4, 0.5), nullptr, 0);
  int type = in.pick(3);
  if (in.chance(16)) type = in.raw_int();
  b2b_params_set_int(p, "contact_type", type, nullptr, 0);
  if (!in.chance(16)) b2b_params_set_real(p, "line_penalty", decode_penalty(in, scale), nullptr, 0);
  if (in.chance(8)) b2b_params_set_int(p, "line_points", in.pick(40) - 4, nullptr, 0);
  if (in.chance(4)) {
    const double la = in.flag() ? in.uniform(0, 90) : in.special();
    b2b_params_set_real(p, "line_angle", la, nullptr, 0);
    b2b_params_set_real(p, "point_angle", in.flag() ? la + in.uniform(0, 30) : in.uniform(0, 90),
                        nullptr, 0);
  }
  if (in.chance(32))
    b2b_params_set_real(p, "parallel_angle", in.flag() ? in.uniform(0, 10) : in.special(),
                        nullptr, 0);
  static const int kIter[] = {50, 50, 50, 1, 2, 5, 20, 1000};
  b2b_params_set_int(p, "max_iterations", kIter[in.pick(8)], nullptr, 0);
  b2b_params_set_int(p, "warm_start", in.chance(8) ? 1 : 0, nullptr, 0);
  if (in.flag()) {
    b2b_params_set_real(p, "friction", in.chance(8) ? in.wild() : in.uniform(0, 1), nullptr, 0);
    if (!in.chance(8))
      b2b_params_set_real(p, "tangential_penalty", decode_penalty(in, 1.0 / scale), nullptr, 0);
    if (!in.chance(8))
      b2b_params_set_real(p, "line_tangential_penalty", decode_penalty(in, scale), nullptr, 0);
  }
  int tangent = in.chance(4) ? B2B_TANGENT_EXACT : in.pick(4);
  if (in.chance(32)) tangent = in.raw_int();
  b2b_params_set_int(p, "tangent", tangent, nullptr, 0);
  if (b2b_params_finalize(p, nullptr, 0) != B2B_OK) return false;
  b2b_params_get_int(p, "contact_type", &lp.type, nullptr, 0);
  b2b_params_get_int(p, "tangent", &lp.tangent, nullptr, 0);
  b2b_params_get_int(p, "max_iterations", &lp.max_iterations, nullptr, 0);
  b2b_params_get_real(p, "friction", &lp.friction, nullptr, 0);
  b2b_params_history_size(p, &lp.hist_size, nullptr, 0);
  return true;
}

struct Pair {
  LineParams lp;
  int segments[6];
  const double* tangents;
  double radii[2];
};

struct Layout {
  bool want_tangent = true, want_point_info = true, alias = false;
  int ldk = 24;
};

struct Result {
  int rc, status;
  double line_info[B2B_LINE_INFO_LEN];
  double point_info[B2B_PAIR_INFO_LEN * kMaxP];
  double residual[B2B_PAIR_NDOF];
  double tangent[kLdkMax * B2B_PAIR_NDOF];
  double hist_new[kHistCap];
  char message[B2B_ERRMSG_LEN];
};

// max |K - K^T| over max |K|, differences below 1e-290 (subnormal entries,
// from a subnormal penalty: regress-symmetric-subnormal) not counted.
double asymmetry(const double* K, int ld) {
  double m = 0.0, d = 0.0;
  for (int c = 0; c < 24; ++c)
    for (int r = 0; r < 24; ++r) {
      m = std::fmax(m, std::fabs(K[r + ld * c]));
      const double e = std::fabs(K[r + ld * c] - K[c + ld * r]);
      if (e > 1e-290) d = std::fmax(d, e);
    }
  return m > 0.0 ? d / m : d;
}

void run(const Pair& p, const double X[24], int n, const double* hist_old, int hist_len,
         const Layout& lay, MessageBuffer* msg, Result& r) {
  static Result untouched;
  static bool made = false;
  if (!made) {
    std::memset(&untouched, 0xA7, sizeof untouched);
    made = true;
  }
  std::memcpy(&r, &untouched, sizeof r);
  static double work[kHistCap];
  std::memcpy(work, hist_old, sizeof work);
  double* const out_hist = lay.alias ? work : r.hist_new;
  const double* const in_hist = lay.alias ? work : hist_old;
  double* const K = lay.want_tangent ? r.tangent : nullptr;
  double* const PI = lay.want_point_info ? r.point_info : nullptr;
  char* mptr = msg ? msg->ptr() : r.message;
  const int mlen = msg ? msg->len() : static_cast<int>(sizeof r.message);
  if (printing()) {
    std::fprintf(stderr, "b2b_pair_eval_line: n %d, hist_len %d, tangent %s, ldk %d, "
                 "point_info %s, hist_new %s\n", n, hist_len, lay.want_tangent ? "yes" : "NULL",
                 lay.ldk, lay.want_point_info ? "yes" : "NULL",
                 lay.alias ? "is hist_old" : "separate");
    print_params(p.lp.params);
    {  // the line options print_params does not know
      double lp = 0, lt = 0, la = 0, pa = 0;
      int ct = 0, np = 0;
      b2b_params_get_int(p.lp.params, "contact_type", &ct, nullptr, 0);
      b2b_params_get_int(p.lp.params, "line_points", &np, nullptr, 0);
      b2b_params_get_real(p.lp.params, "line_penalty", &lp, nullptr, 0);
      b2b_params_get_real(p.lp.params, "line_tangential_penalty", &lt, nullptr, 0);
      b2b_params_get_real(p.lp.params, "line_angle", &la, nullptr, 0);
      b2b_params_get_real(p.lp.params, "point_angle", &pa, nullptr, 0);
      std::fprintf(stderr, "  line: contact_type %d, line_penalty %a, line_tangential_penalty "
                   "%a, line_angle %a, point_angle %a, line_points %d\n", ct, lp, lt, la, pa, np);
    }
    print_ints("segments", p.segments, 6);
    print_doubles("X", X, 24);
    if (p.tangents) print_doubles("end_tangents", p.tangents, 12);
    print_doubles("radii", p.radii, 2);
    print_doubles("hist_old", hist_old, hist_len > 0 && hist_len <= kHistCap ? hist_len : 0);
  }
  const CpuClock clock;
  r.rc = b2b_pair_eval_line(p.lp.params, p.segments, X, p.tangents, p.radii, n, in_hist,
                            out_hist, hist_len, &r.status, r.line_info, PI, r.residual, K,
                            lay.ldk, mptr, mlen);
  const double t = clock.seconds();
  // each point (and the point element) a search, FD 49 residuals of them
  const int pts = (n >= 1 && n <= kMaxP) ? n + 1 : 1;
  const double work_bound = static_cast<double>(p.lp.max_iterations) * pts *
                            (p.lp.tangent == B2B_TANGENT_FD ? 49 : 1);
  FUZZ_REQUIRE(t <= time_budget(work_bound), "b2b_pair_eval_line took %.3f s of CPU time "
               "(n %d, max_iterations %d, tangent option %d)", t, n, p.lp.max_iterations,
               p.lp.tangent);
  const char* text = msg ? msg->text() : r.message;
  FUZZ_REQUIRE(status_in(r.rc, {B2B_OK, B2B_ERR_NULL, B2B_ERR_STATE, B2B_ERR_UNKNOWN_KIND,
                                B2B_ERR_NONFINITE, B2B_ERR_RANGE, B2B_ERR_SIZE,
                                B2B_ERR_COINCIDENT, B2B_ERR_FOLDED}),
               "b2b_pair_eval_line returned %d: %s", r.rc, text);
  if (msg) msg->check(r.rc, "b2b_pair_eval_line");
  if (lay.alias) {
    // hist_new may not be hist_old here: refused, nothing written
    FUZZ_REQUIRE(r.rc != B2B_OK, "hist_new aliasing hist_old accepted");
    FUZZ_REQUIRE(same_bits(work, hist_old, sizeof work), "aliased history written");
  }
  if (r.rc != B2B_OK) {
    FUZZ_REQUIRE(same_bits(&r.status, &untouched.status, sizeof r.status) &&
                     same_bits(r.line_info, untouched.line_info, sizeof r.line_info) &&
                     same_bits(r.point_info, untouched.point_info, sizeof r.point_info) &&
                     same_bits(r.residual, untouched.residual, sizeof r.residual) &&
                     same_bits(r.tangent, untouched.tangent, sizeof r.tangent) &&
                     same_bits(r.hist_new, untouched.hist_new, sizeof r.hist_new),
                 "b2b_pair_eval_line failed (%d) but wrote an output: %s", r.rc, text);
    return;
  }
  const double* li = r.line_info;
  FUZZ_REQUIRE(r.status >= B2B_CONTACT_OPEN && r.status <= B2B_CONTACT_NO_NORMAL,
               "contact status %d", r.status);
  FUZZ_REQUIRE(n >= 1 && n <= kMaxP && hist_len == (n + 1) * p.lp.hist_size,
               "accepted n %d, hist_len %d", n, hist_len);
  FUZZ_REQUIRE(all_finite(li, B2B_LINE_INFO_LEN), "line_info not finite (status %d)", r.status);
  FUZZ_REQUIRE(all_finite(r.residual, 24), "residual not finite (status %d)", r.status);
  FUZZ_REQUIRE(all_finite(r.hist_new, hist_len), "hist_new not finite (status %d)", r.status);
  FUZZ_REQUIRE(same_bits(r.hist_new + hist_len, untouched.hist_new + hist_len,
                         sizeof(double) * (kHistCap - hist_len)),
               "hist_new written beyond hist_len %d", hist_len);
  // point_info is finite on success (a point of weight 0 in the blend
  // whose force overflows is B2B_ERR_RANGE: regress-point-info-overflow).
  if (lay.want_point_info)
    FUZZ_REQUIRE(all_finite(r.point_info, B2B_PAIR_INFO_LEN * n),
                 "point_info not finite (status %d, contact type %d)", r.status, p.lp.type);
  if (lay.want_point_info) {
    FUZZ_REQUIRE(same_bits(r.point_info + 32 * n, untouched.point_info + 32 * n,
                           sizeof(double) * 32 * (kMaxP - n)),
                 "point_info written beyond n %d", n);
  } else {
    FUZZ_REQUIRE(same_bits(r.point_info, untouched.point_info, sizeof r.point_info),
                 "point_info written though NULL");
  }
  const int ldk = lay.ldk;
  if (lay.want_tangent)
    for (int c = 0; c < 24; ++c) {
      FUZZ_REQUIRE(all_finite(r.tangent + ldk * c, 24), "tangent column %d not finite", c);
      FUZZ_REQUIRE(same_bits(r.tangent + ldk * c + 24, untouched.tangent + ldk * c + 24,
                             sizeof(double) * (ldk - 24)),
                   "tangent padding of column %d written (ldk %d)", c, ldk);
    }
  // line_info
  auto is_count = [&](double v) { return v >= 0 && v <= n && v == std::floor(v); };
  const double act = li[B2B_LINE_INFO_ACTIVE_POINTS], own = li[B2B_LINE_INFO_OWNED_POINTS];
  FUZZ_REQUIRE(li[B2B_LINE_INFO_POINTS] == n, "line_info POINTS %g, n %d",
               li[B2B_LINE_INFO_POINTS], n);
  FUZZ_REQUIRE(is_count(act) && is_count(own) && act <= own, "active %g, owned %g of %d", act,
               own, n);
  const double stick = li[B2B_LINE_INFO_STICK_POINTS], slip = li[B2B_LINE_INFO_SLIP_POINTS];
  FUZZ_REQUIRE(is_count(stick) && is_count(slip), "stick %g, slip %g", stick, slip);
  if (p.lp.friction > 0.0)
    FUZZ_REQUIRE(stick + slip == act, "stick %g + slip %g != active %g", stick, slip, act);
  else
    FUZZ_REQUIRE(stick == 0 && slip == 0, "stick/slip points without friction");
  FUZZ_REQUIRE(li[15] == 0.0, "reserved line_info %g", li[15]);
  {
    const double pfs = li[B2B_LINE_INFO_POINT_FRICTION_STATE];
    FUZZ_REQUIRE(pfs == 0.0 || (p.lp.friction > 0.0 && li[B2B_LINE_INFO_POINT_WEIGHT] > 0.0 &&
                                (pfs == double(B2B_FRICTION_STICK) ||
                                 pfs == double(B2B_FRICTION_SLIP))),
                 "point friction state %g (weight %g, friction %g)", pfs,
                 li[B2B_LINE_INFO_POINT_WEIGHT], p.lp.friction);
  }
  FUZZ_REQUIRE(li[B2B_LINE_INFO_NORMAL_FORCE] >= 0 && li[B2B_LINE_INFO_ENERGY] >= 0 &&
                   li[B2B_LINE_INFO_DISSIPATION] >= 0 && li[B2B_LINE_INFO_POINT_FORCE] >= 0,
               "negative force %g, energy %g, dissipation %g or point force %g",
               li[B2B_LINE_INFO_NORMAL_FORCE], li[B2B_LINE_INFO_ENERGY],
               li[B2B_LINE_INFO_DISSIPATION], li[B2B_LINE_INFO_POINT_FORCE]);
  FUZZ_REQUIRE(li[B2B_LINE_INFO_LENGTH] >= 0, "length %g", li[B2B_LINE_INFO_LENGTH]);
  const double lam = li[B2B_LINE_INFO_POINT_WEIGHT];
  FUZZ_REQUIRE(lam >= 0.0 && lam <= 1.0, "point weight %g", lam);
  const double ps = li[B2B_LINE_INFO_POINT_STATUS];
  if (p.lp.type == B2B_CONTACT_TYPE_ALL_ANGLE)
    FUZZ_REQUIRE(ps >= double(B2B_CONTACT_OPEN) && ps <= double(B2B_CONTACT_NO_NORMAL),
                 "point status %g", ps);
  else
    FUZZ_REQUIRE(ps == -1.0 && lam == 0.0 && li[B2B_LINE_INFO_POINT_FORCE] == 0.0,
                 "contact type %d with a point part (status %g, weight %g)", p.lp.type, ps, lam);
  const double sym = li[B2B_LINE_INFO_SYMMETRIC];
  FUZZ_REQUIRE(sym == 0.0 || sym == 1.0, "line_info SYMMETRIC %g", sym);
  // The contract is bit-for-bit symmetry (as fuzz_pair_eval asserts;
  // regress-symmetric-to-rounding).
  if (sym == 1.0 && lay.want_tangent)
    FUZZ_REQUIRE(asymmetry(r.tangent, ldk) == 0.0,
                 "line_info says symmetric, the tangent is not (asymmetry %.2e of the largest "
                 "entry; status %d, type %d, friction %g, option %d, min gap %g)",
                 asymmetry(r.tangent, ldk), r.status, p.lp.type, p.lp.friction, p.lp.tangent,
                 li[B2B_LINE_INFO_MIN_GAP]);
  if (r.status == B2B_CONTACT_ACTIVE)
    FUZZ_REQUIRE(act > 0 || li[B2B_LINE_INFO_POINT_WEIGHT] > 0,
                 "ACTIVE without a part carrying force");
  else {
    for (int i = 0; i < 24; ++i)
      FUZZ_REQUIRE(r.residual[i] == 0.0, "status %d with residual[%d] = %g", r.status, i,
                   r.residual[i]);
    // No force, no tangent, with the FD option too (regress-fd-tangent-open:
    // its perturbed configurations touched).
    if (lay.want_tangent)
      for (int c = 0; c < 24; ++c)
        for (int i = 0; i < 24; ++i)
          FUZZ_REQUIRE(r.tangent[i + ldk * c] == 0.0,
                       "status %d with tangent[%d][%d] = %g (line_info: active %g, weight %g, "
                       "point status %g, force %g)", r.status, i, c, r.tangent[i + ldk * c],
                       act, lam, ps, li[B2B_LINE_INFO_NORMAL_FORCE]);
    FUZZ_REQUIRE(act == 0, "status %d with %g active points", r.status, act);
  }
  if (lay.want_point_info)
    for (int i = 0; i < n; ++i) {
      const double* q = r.point_info + 32 * i;
      for (int k = B2B_INFO_LINE_POINTS; k < B2B_PAIR_INFO_LEN; ++k)
        FUZZ_REQUIRE(q[k] == 0.0, "point %d: info[%d] = %g", i, k, q[k]);
      FUZZ_REQUIRE(!(q[B2B_INFO_NORMAL_FORCE] < 0) && !(q[B2B_INFO_DISSIPATION] < 0),
                   "point %d: force %g, dissipation %g", i, q[B2B_INFO_NORMAL_FORCE],
                   q[B2B_INFO_DISSIPATION]);
      FUZZ_REQUIRE(q[B2B_INFO_ANGLE] >= 0 && q[B2B_INFO_ANGLE] <= 90, "point %d: angle %g", i,
                   q[B2B_INFO_ANGLE]);
      const double* T = q + B2B_INFO_TANGENTIAL_FORCE;
      const double tm = std::hypot(T[0], std::hypot(T[1], T[2]));
      // (mu f_N only with friction: 0 times an infinite f_N would be NaN)
      FUZZ_REQUIRE(p.lp.friction > 0.0
                       ? tm <= p.lp.friction * q[B2B_INFO_NORMAL_FORCE] * (1 + 1e-12) + 1e-300
                       : tm == 0.0,
                   "point %d: |T| %.17g beyond mu f_N (mu %g, f_N %g)", i, tm, p.lp.friction,
                   q[B2B_INFO_NORMAL_FORCE]);
    }
}

Layout decode_layout(FuzzInput& in) {
  Layout lay;
  lay.want_tangent = !in.chance(32);
  lay.want_point_info = !in.chance(8);
  switch (in.pick(8)) {
    case 0: lay.ldk = 25 + in.pick(kLdkMax - 24); break;
    case 1: lay.ldk = in.chance(64) ? 23 : in.raw_int(); break;
    default: lay.ldk = 24; break;
  }
  if (lay.ldk > kLdkMax) lay.ldk = kLdkMax;
  lay.alias = in.chance(64);
  return lay;
}

int decode_n(FuzzInput& in) {
  if (in.chance(32)) return in.chance(2) ? in.pick(3) - 1 : in.raw_int();  // out of range
  static const int kCommon[] = {1, 2, 3, 4, 5, 6, 8, 16, 32};
  return in.flag() ? kCommon[in.pick(9)] : 1 + in.pick(kMaxP);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzInput in(data, size);
  Crossing c;
  decode_crossing(in, c);
  Pair p;
  if (!decode_line_params(in, c.scale, p.lp)) return 0;
  for (int b = 0; b < 2; ++b) {
    p.segments[3 * b] = c.seg[b].kind;
    p.segments[3 * b + 1] = c.seg[b].start_rule;
    p.segments[3 * b + 2] = c.seg[b].end_rule;
  }
  p.tangents = in.chance(8) ? nullptr : c.tangents;
  std::memcpy(p.radii, c.radii, sizeof p.radii);
  if (in.chance(8)) inject_wild(in, p.radii, 2);

  int n = decode_n(in);
  const bool n_ok = n >= 1 && n <= kMaxP;
  static double hist[kHistCap];
  std::memset(hist, 0, sizeof hist);
  int hist_len = n_ok ? (n + 1) * p.lp.hist_size : 8;
  const int steps = in.pick(4);
  for (int s = 0; s < steps; ++s) {
    double X[24];
    decode_motion(in, c, X);
    Layout lay = decode_layout(in);
    Result r;
    MessageBuffer msg(in);
    run(p, X, n, hist, hist_len, lay, &msg, r);
    if (r.rc == B2B_OK && !in.chance(48)) std::memcpy(hist, r.hist_new, sizeof(double) * hist_len);
  }
  if (in.chance(10) && n_ok) {
    if (in.flag())
      inject_wild(in, hist, hist_len);
    else
      hist[in.pick(hist_len)] = static_cast<double>(in.pick(5)) - 1.0;
  }
  if (in.chance(16)) hist_len = in.pick(kHistCap + 1);
  double X[24];
  if (in.flag())
    decode_motion(in, c, X);
  else
    std::memcpy(X, c.X, sizeof X);
  if (in.chance(12)) inject_wild(in, X, 24);
  const Layout lay = decode_layout(in);
  MessageBuffer msg(in);
  static Result r;
  run(p, X, n, hist, hist_len, lay, &msg, r);
  if (r.rc != B2B_OK) return 0;
  // the histories it wrote are accepted (an overflow of the force aside)
  static Result again;
  Layout plain;
  plain.want_tangent = false;
  run(p, X, n, r.hist_new, hist_len, plain, nullptr, again);
  FUZZ_REQUIRE(again.rc == B2B_OK ||
                   (again.rc == B2B_ERR_RANGE && std::strstr(again.message, "overflow")),
               "the histories b2b_pair_eval_line wrote are refused by the next call (%d): %s",
               again.rc, again.message);
  return 0;
}
