#include "tangent_options.hpp"

#include <cstring>

#include "../curve/vec3.hpp"
#include "contact_element.hpp"

namespace b2b {
namespace pair {

void symmetrize(double* K, int n) {
  for (int c = 0; c < n; ++c)
    for (int r = c + 1; r < n; ++r) {
      const double a = K[r + kNdof * c], b = K[c + kNdof * r];
      // Two finite entries above DBL_MAX / 2 of one sign have an infinite
      // sum, and the callers have checked K's finiteness before this: the
      // halves then (both exact there, so the mean is the same rounding of
      // (a + b) / 2). Elsewhere the sum first, which keeps the halves of
      // subnormal entries from losing their last bit.
      const double s = a + b;
      const double m = s - s == 0.0 ? 0.5 * s : 0.5 * a + 0.5 * b;
      K[r + kNdof * c] = K[c + kNdof * r] = m;
    }
}

void main_term(double slope, const double* PA, const double* PB, const double* n, double* K) {
  double G[kNdof];
  for (int c = 0; c < 12; ++c) {
    G[c] = curve::dot3(PA + 3 * c, n);
    G[12 + c] = -curve::dot3(PB + 3 * c, n);
  }
  // G[r] * G[c] first: a product of two factors is the same both ways
  // round, so K is exactly symmetric, as info[B2B_INFO_SYMMETRIC] = 1 says
  // ((-slope * G[r]) * G[c] rounds differently from (-slope * G[c]) * G[r]).
  for (int c = 0; c < kNdof; ++c)
    for (int r = 0; r < kNdof; ++r) K[r + kNdof * c] = -slope * (G[r] * G[c]);
}

void fd_tangent(const Params& params, const SegmentRef& A, const SegmentRef& B,
                const double* hist_old, double* K, Ends ends) {
  fd_tangent_of(A, B, K, [&](const SegmentRef& a, const SegmentRef& b, double* r) {
    PairResult out;
    evaluate_built(params, a, b, hist_old, out, nullptr, ends);
    std::memcpy(r, out.residual, sizeof out.residual);
  });
}

void fd_tangent_of(const SegmentRef& A, const SegmentRef& B, double* K,
                   const PairResidual& residual) {
  const SegmentRef* in[2] = {&A, &B};
  double chord = 0.0, d[3];
  for (const SegmentRef* s : in) {
    curve::sub3(s->seg->end_point(), s->seg->start_point(), d);
    chord += 0.5 * curve::norm3(d);
  }
  const double h = 1e-6 * chord;
  for (int beam = 0; beam < 2; ++beam) {
    const SegmentRef& me = *in[beam];
    const unsigned used = curve::used_slots(me.kind, me.start_rule, me.end_rule);
    for (int c = 0; c < 12; ++c) {
      double* col = K + kNdof * (12 * beam + c);
      if (!(used & (1u << (c / 3)))) {
        std::memset(col, 0, kNdof * sizeof(double));
        continue;
      }
      double r[2][kNdof];
      bool built = true;
      for (int side = 0; side < 2 && built; ++side) {
        double X[12];
        std::memcpy(X, me.X, sizeof X);
        X[c] += side == 0 ? h : -h;
        curve::Segment seg;
        built = seg.build(me.kind, me.start_rule, me.end_rule, X, me.unit_tangents, true).status == 0;
        if (!built) break;
        SegmentRef moved = me;
        moved.seg = &seg;
        moved.X = X;
        residual(beam == 0 ? moved : A, beam == 0 ? B : moved, r[side]);
      }
      if (!built) continue;
      for (int k = 0; k < kNdof; ++k) col[k] = (r[0][k] - r[1][k]) / (2.0 * h);
    }
  }
}

}  // namespace pair
}  // namespace b2b
