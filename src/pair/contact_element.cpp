#include "contact_element.hpp"

#include <cstring>

#include <b2b/b2b.h>

#include "../common/finite.hpp"
#include "../curve/vec3.hpp"
#include "friction.hpp"
#include "normal_law.hpp"
#include "tangent_assembly.hpp"
#include "tangent_options.hpp"

namespace b2b {
namespace pair {
namespace {

// Column c of a 3 x 12 column-major matrix dotted with v.
inline double col_dot(const double* M, int c, const double* v) { return curve::dot3(M + 3 * c, v); }

}  // namespace

PairFailure build_pair(const SegmentInput& A, const SegmentInput& B, curve::Segment built[2],
                       SegmentRef refs[2]) {
  PairFailure fail;
  const SegmentInput* in[2] = {&A, &B};
  for (int b = 0; b < 2; ++b) {
    const SegmentInput& s = *in[b];
    fail.segment = built[b].build(s.kind, s.start_rule, s.end_rule, s.X, s.unit_tangents, true);
    if (fail.segment.status) {
      fail.status = fail.segment.status;
      fail.beam = b;
      return fail;
    }
    refs[b] = SegmentRef{&built[b], s.kind, s.start_rule, s.end_rule, s.radius, s.X, s.unit_tangents};
  }
  return fail;
}

PairFailure evaluate_pair(const Params& params, const SegmentInput& A, const SegmentInput& B,
                          const double* hist_old, PairResult& out, double* K, Ends ends,
                          TangentColumns* compact) {
  curve::Segment built[2];
  SegmentRef refs[2];
  const PairFailure fail = build_pair(A, B, built, refs);
  if (!fail.status)
    evaluate_built(params, refs[0], refs[1], hist_old, out, K, ends, nullptr, compact);
  return fail;
}

void evaluate_built(const Params& params, const SegmentRef& A, const SegmentRef& B,
                    const double* hist_old, PairResult& out, double* K, Ends ends,
                    Kinematics* kin, TangentColumns* compact) {
  out = PairResult();
  const int hist_len = history_length(params);
  std::memcpy(out.history, hist_old, hist_len * sizeof(double));
  // Friction history is that of the committed step only if this pair is
  // active now (set below); a pair without force forgets it.
  for (int i = kHistoryLength; i < hist_len; ++i) out.history[i] = 0.0;
  double* info = out.info;
  info[B2B_INFO_SYMMETRIC] = 1.0;

  // Stage 1: kinematics. A pair that carries no force: its status, zero
  // residual (already) and tangent.
  Kinematics k;
  const int geometric = contact_kinematics(params, A, B, hist_old, k, info, out.history, ends);
  // (Every status passes the finiteness guard: an OPEN pair's energy can
  // overflow too, with a huge regularization gap.)
  auto no_force = [&](int status) {
    out.contact_status = status;
    if (K && compact)
      compact->m = 0;
    else if (K)
      std::memset(K, 0, kNdof * kNdof * sizeof(double));
    out.overflow = !all_finite(out.info, kInfoLength) || !all_finite(out.history, hist_len);
  };
  if (kin) *kin = k;
  if (geometric != B2B_CONTACT_OPEN) return no_force(geometric);
  const LawValue law = normal_law(params, k.gap);
  info[B2B_INFO_NORMAL_FORCE] = law.force;
  info[B2B_INFO_ENERGY] = law.energy;
  if (!(law.force > 0.0)) return no_force(B2B_CONTACT_OPEN);
  out.contact_status = B2B_CONTACT_ACTIVE;
  // With intersecting axes the normal is the history's and the exact tangent
  // omits its rotation, which leaves it unsymmetric (tangent_assembly.cpp):
  // said here, so that info is the same with and without a tangent.
  if (k.rho_signed == 0.0) info[B2B_INFO_SYMMETRIC] = 0.0;

  // Stage 2: force response. Residual -f_N dg/dX with dg/dX = G = [P_A^T n;
  // -P_B^T n] (the xi, eta terms vanish by orthogonality).
  const curve::Segment &sa = *A.seg, &sb = *B.seg;
  double PA[36], PAd[36], PB[36], PBd[36];
  sa.jacobians(k.xi, PA, PAd);
  sb.jacobians(k.eta, PB, PBd);
  // Friction: + [P_A^T T; -P_B^T T]. mu = 0 skips all of it.
  const bool friction = params.friction > 0.0;
  const FrictionContact fc{&sa,       &sb,      k.xi,     k.eta,        k.pa.xd,
                           k.pa.xdd,  k.pb.xd,  k.n,      k.rho_signed, law.force,
                           law.slope, k.pb.xdd, k.end_a,  k.end_b,
                           k.held_a || k.held_b, ends.at_point ? B.radius : 0.0};
  // (Built in place: friction_force's result is not copied.)
  const FrictionResult fr = friction ? friction_force(params, fc, hist_old) : FrictionResult();
  if (!fr.anchored) {  // (also a fresh contact with friction: T = 0, bit for bit)
    for (int c = 0; c < 12; ++c) {
      out.residual[c] = -law.force * col_dot(PA, c, k.n);
      out.residual[12 + c] = law.force * col_dot(PB, c, k.n);
    }
  } else {
    // Normal and friction force in one: [P_A^T w; -P_B^T w], w = T - f_N n.
    double w[3];
    for (int i = 0; i < 3; ++i) w[i] = fr.T[i] - law.force * k.n[i];
    for (int c = 0; c < 12; ++c) {
      out.residual[c] = col_dot(PA, c, w);
      out.residual[12 + c] = -col_dot(PB, c, w);
    }
  }
  if (friction) {
    for (int i = 0; i < 3; ++i) {
      info[B2B_INFO_TANGENTIAL_FORCE + i] = fr.T[i];
      info[B2B_INFO_SLIP + i] = fr.slip[i];
    }
    info[B2B_INFO_FRICTION_STATE] = fr.state;
    info[B2B_INFO_DISSIPATION] = fr.dissipation;
    info[B2B_INFO_SYMMETRIC] = 0.0;
    out.history[kHistInContact] = 1.0;
    out.history[kHistForceE1] = fr.force_e1;
    out.history[kHistForceE2] = fr.force_e2;
    out.history[kHistFrictionState] = fr.state;
  }
  // A huge penalty times a deep penetration can exceed the double range (the
  // energy grows like penalty * gap^2); the caller reports it.
  out.overflow = !all_finite(out.info, kInfoLength) || !all_finite(out.residual, kNdof) ||
                 !all_finite(out.history, hist_len);
  if (!K) return;

  // Stage 3: the tangent, as the "tangent" option asks.
  if (compact) compact->m = kNdof;  // (assemble_tangent may make it compact)
  if (params.tangent == B2B_TANGENT_MAIN) {
    main_term(law.slope, PA, PB, k.n, K);
    info[B2B_INFO_SYMMETRIC] = 1.0;
    out.overflow = out.overflow || !all_finite(K, kNdof * kNdof);
    return;
  }
  if (params.tangent == B2B_TANGENT_FD && A.X && B.X) {
    fd_tangent(params, A, B, hist_old, K, ends);
    info[B2B_INFO_SYMMETRIC] = 0.0;
    out.overflow = out.overflow || !all_finite(K, kNdof * kNdof);
    return;
  }
  const TangentResult t =
      assemble_tangent(params, A, B, k, law, fc, fr, PA, PAd, PB, PBd, K, compact);
  if (!t.symmetric) info[B2B_INFO_SYMMETRIC] = 0.0;
  if (params.tangent == B2B_TANGENT_SYMMETRIC && !t.symmetric) {
    symmetrize(K, compact ? compact->m : kNdof);
    info[B2B_INFO_SYMMETRIC] = 1.0;
  }
  out.overflow = out.overflow || !t.finite;
}

}  // namespace pair
}  // namespace b2b
