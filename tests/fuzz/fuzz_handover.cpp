// Fuzz target: b2b_pair_history_handover. Decodes a beam (open or a ring,
// any kind, curved, uneven, possibly degenerate, at any scale), a joint of
// it and the two segments on either side, gathered with
// b2b_beam_segment_patch (or made not to share the joint, by a rounding
// error or by far), the beam (A or B) and direction, and a history: fresh,
// written by b2b_pair_eval on a crossing near the joint (with or without
// friction, after up to two steps), or made up, possibly damaged. Asserts
// b2b_pair.h's contract:
//  - a documented status; on error hist_to untouched bit for bit (or, when
//    it is hist_from, hist_from's content);
//  - B2B_OK: hist_to finite, equal to hist_from but for the mapped
//    parameter (all of it for a fresh history), which is within 1e3;
//  - the history it wrote is accepted by b2b_pair_eval on the new segment;
//  - handing it back across the same joint gives the parameter back (the
//    map's inverse, up to rounding);
//  - bounded time (fuzz_contract.hpp).
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "fuzz_contract.hpp"
#include "fuzz_scene.hpp"

using namespace b2b_fuzz;

namespace {

constexpr int kMaxNodes = 8;
constexpr int kHistCap = 32;

struct Params {
  b2b_params* p = nullptr;
  ParamsInfo pi;
  ~Params() { b2b_params_destroy(&p); }
};

struct Side {
  int seg[3];
  double X[12];
  double tangents[6];
};

// Nodes of a ring: n points on a circle of radius 1, unevenly spaced.
void ring(FuzzInput& in, int n, double* x) {
  const double uneven = in.uniform(0, 0.45);
  for (int k = 0; k < n; ++k) {
    const double a = 2 * 3.14159265358979323846 * (k + uneven * in.uniform(-1, 1)) / n;
    x[3 * k] = std::cos(a);
    x[3 * k + 1] = std::sin(a);
    x[3 * k + 2] = in.uniform(-0.1, 0.1);
  }
}

// Segment s of the beam as b2b_beam_segment_patch describes it; NaN in
// missing slots (never read); host tangents at beam ends now and then.
bool gather(FuzzInput& in, int kind, int n, int closed, int s, const double* coords, Side& out) {
  int nodes[4], sr, er;
  if (b2b_beam_segment_patch(kind, n, closed, s, nodes, &sr, &er, nullptr, 0) != B2B_OK)
    return false;
  for (int slot = 0; slot < 4; ++slot)
    for (int i = 0; i < 3; ++i)
      out.X[3 * slot + i] = nodes[slot] >= 0 ? coords[3 * nodes[slot] + i] : NAN;
  decode_end_tangents(in, out.X, out.tangents);
  const bool host = in.chance(64);
  out.seg[0] = kind;
  out.seg[1] = sr == B2B_END_REFLECT && host ? B2B_END_TANGENT : sr;
  out.seg[2] = er == B2B_END_REFLECT && host ? B2B_END_TANGENT : er;
  return true;
}

// A straight partner segment crossing `side` near its parameter t, at a
// right angle tilted by up to 60 degrees, dist apart: X12 and radii.
void partner(FuzzInput& in, const Side& side, double t, double scale, double X12[12]) {
  double x[9] = {0};
  if (b2b_segment_eval(side.seg[0], side.seg[1], side.seg[2], side.X, side.tangents, t, x,
                       nullptr, nullptr, nullptr, 0) != B2B_OK) {
    for (int i = 0; i < 3; ++i) {
      x[i] = side.X[3 + i];
      x[3 + i] = side.X[6 + i] - side.X[3 + i];
    }
  }
  double d[3] = {x[3], x[4], x[5]};
  double dn = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(dn > 0) || !std::isfinite(dn)) {
    d[0] = 1, d[1] = d[2] = 0, dn = 1;
  }
  for (double& v : d) v /= dn;
  double R[9], e[3] = {0.3, 0.9, 0.1}, u[3], nrm[3];
  random_rotation(in, R);
  rotate(R, e, u);
  // u without its component along d, then tilted back towards d a little
  const double ud = u[0] * d[0] + u[1] * d[1] + u[2] * d[2];
  for (int i = 0; i < 3; ++i) u[i] -= ud * d[i];
  const double tilt = in.uniform(-1, 1);
  for (int i = 0; i < 3; ++i) u[i] += tilt * d[i];
  nrm[0] = d[1] * u[2] - d[2] * u[1];
  nrm[1] = d[2] * u[0] - d[0] * u[2];
  nrm[2] = d[0] * u[1] - d[1] * u[0];
  const double nn = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
  const double dist = scale * in.uniform(-0.3, 0.3);
  for (int i = 0; i < 3; ++i) {
    const double c = x[i] + (nn > 0 ? dist * nrm[i] / nn : 0.0);
    X12[i] = X12[9 + i] = NAN;  // linear: x1, x4 never read
    X12[3 + i] = c - scale * u[i];
    X12[6 + i] = c + scale * u[i];
  }
}

// b2b_pair_eval of `side` in the role of beam `beam` against a partner.
int pair_with(const Params& p, int beam, const Side& side, const double partner_X[12],
              const double radii[2], const double* hist_old, double* hist_new, int hist_len,
              char* msg, int msg_len) {
  const int lin[3] = {B2B_CURVE_LINEAR, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
  int segs[6];
  double X[24], T[12] = {0};
  const int a = beam == 0 ? 0 : 1;  // where side goes
  std::memcpy(segs + 3 * a, side.seg, sizeof side.seg);
  std::memcpy(segs + 3 * (1 - a), lin, sizeof lin);
  std::memcpy(X + 12 * a, side.X, sizeof side.X);
  std::memcpy(X + 12 * (1 - a), partner_X, 12 * sizeof(double));
  std::memcpy(T + 6 * a, side.tangents, sizeof side.tangents);
  T[6 * (1 - a)] = T[6 * (1 - a) + 3] = 1.0;
  int status;
  double info[B2B_PAIR_INFO_LEN], residual[B2B_PAIR_NDOF];
  return b2b_pair_eval(p.p, segs, X, T, radii, hist_old, hist_new, hist_len, &status, info,
                       residual, nullptr, 24, msg, msg_len);
}

// A history that looks like b2b's: tag 1, a normal, parameters up to the
// bound, with friction an in-contact flag, a force and a state.
void made_up_history(FuzzInput& in, double* h, int len) {
  std::memset(h, 0, sizeof(double) * static_cast<size_t>(len));
  h[0] = 1;
  h[1] = in.flag();
  double R[9], e[3] = {0, 0, 1};
  random_rotation(in, R);
  rotate(R, e, h + 2);
  for (int k = 5; k < 7; ++k)
    h[k] = in.flag() ? in.uniform(-1.5, 1.5) : in.sign() * in.log_uniform(-3, 3);
  if (len >= 12 && h[1] == 1.0 && in.flag()) {
    h[8] = 1;
    h[9] = in.sign() * in.log_uniform(-300, 300);
    h[10] = in.sign() * in.log_uniform(-300, 300);
    h[11] = 1 + in.pick(2);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzInput in(data, size);
  const int kind = in.pick(4);
  const int closed = in.chance(48) ? 1 : 0;
  const int n = (closed ? 3 : 2) + in.pick(kMaxNodes - (closed ? 2 : 1));
  double local[3 * kMaxNodes], coords[3 * kMaxNodes];
  if (closed)
    ring(in, n, local);
  else
    decode_chain(in, n, local);
  if (in.chance(12)) decode_degeneracy(in, local, n);
  const Placement pl = decode_placement(in);
  place_points(pl, local, coords, n);

  int n_seg = 0;
  if (b2b_beam_segment_count(kind, n, closed, &n_seg, nullptr, 0) != B2B_OK || n_seg < 1) return 0;
  const int from = in.pick(n_seg);
  int direction = in.flag() ? 1 : -1;
  int to = from + direction;
  if (closed) to = (to + n_seg) % n_seg;
  if (to < 0 || to >= n_seg) to = in.pick(n_seg);  // past a beam end: any other segment
  Side s_from, s_to;
  if (!gather(in, kind, n, closed, from, coords, s_from)) return 0;
  if (!gather(in, kind, n, closed, to, coords, s_to)) return 0;
  if (in.chance(16)) {  // the joints a rounding error (or more) apart
    const double eps = in.log_uniform(-16, -6);
    for (int i = 3; i < 9; ++i) s_to.X[i] += eps * pl.scale * in.uniform(-1, 1);
  }
  if (in.chance(8)) inject_wild(in, in.flag() ? s_from.X : s_to.X, 12);
  int beam = in.pick(2);
  if (in.chance(4)) beam = in.raw_int();
  if (in.chance(4)) direction = in.flag() ? in.raw_int() : 0;

  Params p;
  p.p = decode_params(in, pl.scale, &p.pi, 1000);
  if (!p.p) return 0;
  const int len = p.pi.hist_len;
  FUZZ_REQUIRE(len > 0 && len <= kHistCap, "history size %d", len);

  // The history handed over.
  double hist_from[kHistCap] = {0};
  double partner_X[12];
  double radii[2] = {pl.scale * in.uniform(0, 0.3), pl.scale * in.uniform(0, 0.3)};
  const double t_near = direction > 0 ? 1 - in.uniform(0, 0.5) : -1 + in.uniform(0, 0.5);
  partner(in, s_from, t_near, pl.scale, partner_X);
  switch (in.pick(4)) {
    case 0: break;  // fresh
    case 1: made_up_history(in, hist_from, len); break;
    default: {      // written by the element, in one or two steps
      const int steps = 1 + in.pick(2);
      for (int k = 0; k < steps; ++k) {
        double h[kHistCap];
        if (pair_with(p, beam, s_from, partner_X, radii, hist_from, h, len, nullptr, 0) == B2B_OK)
          std::memcpy(hist_from, h, sizeof(double) * len);
        for (int i = 0; i < 12; ++i)
          if (std::isfinite(partner_X[i])) partner_X[i] += pl.scale * 0.05 * in.uniform(-1, 1);
      }
      break;
    }
  }
  if (in.chance(10)) inject_wild(in, hist_from, len);
  int hist_len = len;
  if (in.chance(4)) hist_len = in.pick(kHistCap + 1) - 1;

  const bool alias = in.chance(48);
  double hist_to[kHistCap], filled[kHistCap];
  std::memset(filled, 0xA7, sizeof filled);
  if (alias)
    std::memcpy(hist_to, hist_from, sizeof hist_to);
  else
    std::memcpy(hist_to, filled, sizeof hist_to);
  MessageBuffer msg(in);
  const CpuClock clock;
  const int rc = b2b_pair_history_handover(
      p.p, beam, direction, s_from.seg, s_from.X, s_from.tangents, s_to.seg, s_to.X,
      s_to.tangents, alias ? hist_to : hist_from, hist_to, hist_len, msg.ptr(), msg.len());
  const double t = clock.seconds();
  FUZZ_REQUIRE(t <= time_budget(0), "b2b_pair_history_handover took %.3f s of CPU time", t);
  FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_NULL, B2B_ERR_UNKNOWN_KIND, B2B_ERR_NONFINITE,
                              B2B_ERR_RANGE, B2B_ERR_SIZE, B2B_ERR_COINCIDENT, B2B_ERR_FOLDED}),
               "b2b_pair_history_handover returned %d: %s", rc, msg.text());
  msg.check(rc, "b2b_pair_history_handover");
  if (rc != B2B_OK) {
    FUZZ_REQUIRE(same_bits(hist_to, alias ? hist_from : filled, sizeof hist_to),
                 "b2b_pair_history_handover failed (%d) but wrote hist_to: %s", rc, msg.text());
    return 0;
  }

  FUZZ_REQUIRE(all_finite(hist_to, len), "hist_to not finite");
  FUZZ_REQUIRE(alias || same_bits(hist_to + len, filled + len, sizeof(double) * (kHistCap - len)),
               "hist_to written beyond hist_len");
  const int slot = beam == 0 ? 5 : 6;  // the parameter of the beam that changes segment
  const bool fresh = hist_from[0] == 0.0;
  for (int i = 0; i < len; ++i)
    if (fresh || i != slot)
      FUZZ_REQUIRE(same_bits(&hist_to[i], &hist_from[i], sizeof(double)),
                   "hist_to[%d] = %g changed from %g (fresh %d)", i, hist_to[i], hist_from[i],
                   fresh);
  FUZZ_REQUIRE(std::fabs(hist_to[slot]) <= 1e3, "mapped parameter %g beyond 1e3", hist_to[slot]);

  // The new owner accepts it.
  double h[kHistCap];
  char text[B2B_ERRMSG_LEN] = "";
  double partner_to[12];
  partner(in, s_to, direction > 0 ? -0.5 : 0.5, pl.scale, partner_to);
  const int rc_pair =
      pair_with(p, beam, s_to, partner_to, radii, hist_to, h, len, text, sizeof text);
  FUZZ_REQUIRE(rc_pair == B2B_OK || !std::strstr(text, "hist_old"),
               "the handed-over history is refused by b2b_pair_eval: %s", text);

  // And back across the same joint: the parameter returns.
  double back[kHistCap];
  if (fresh) return 0;
  if (b2b_pair_history_handover(p.p, beam, -direction, s_to.seg, s_to.X, s_to.tangents,
                                s_from.seg, s_from.X, s_from.tangents, hist_to, back, len,
                                nullptr, 0) != B2B_OK)
    return 0;
  const double t0 = hist_from[slot], t1 = hist_to[slot], t2 = back[slot];
  const double j_from = direction > 0 ? 1.0 : -1.0, j_to = -j_from;
  if (std::fabs(t0 - j_from) < 1e-6 || std::fabs(t1 - j_to) < 1e-300) return 0;
  const double ratio = std::fabs(t1 - j_to) / std::fabs(t0 - j_from);  // s_from / s_to
  const double tol = 1e-12 * (2 + std::fabs(t0) + (1 + std::fabs(t1)) / ratio);
  FUZZ_REQUIRE(std::fabs(t2 - t0) <= tol,
               "handover there and back: %.17g -> %.17g -> %.17g (tolerance %.3g)", t0, t1, t2,
               tol);
  return 0;
}
