#include "handover.hpp"

#include <cmath>

#include "../curve/vec3.hpp"
#include "history.hpp"

namespace b2b {
namespace pair {

HandoverResult handover_history(const curve::Segment& from, const curve::Segment& to, int beam,
                                int direction, double* hist, int /*len*/) {
  HandoverResult res;
  // The joint: from's end and to's start (direction +1), or the reverse.
  const double t_from = direction > 0 ? 1.0 : -1.0, t_to = -t_from;
  double xf[3], df[3], xt[3], dt[3], chord[3], gap[3];
  // Relative to from's base node: far from the coordinates' origin the joint's
  // mismatch is then the inputs' rounding of the segments, not of 1e8.
  const double* origin = from.base();
  from.point_from(origin, t_from, xf, df, nullptr);
  to.point_from(origin, t_to, xt, dt, nullptr);
  curve::sub3(xf, xt, gap);
  curve::sub3(from.end_point(), from.start_point(), chord);
  double scale = curve::norm3(chord);
  curve::sub3(to.end_point(), to.start_point(), chord);
  scale += curve::norm3(chord);
  res.mismatch = curve::norm3(gap) / scale;
  res.adjacent = res.mismatch <= kJointMismatch;
  if (!res.adjacent || hist[kHistTag] != kHistTagV1) return res;
  // Same arc length from the joint, to first order: (t - t_from) s_from = (t' - t_to) s_to.
  const double ratio = curve::norm3(df) / curve::norm3(dt);
  double& t = hist[beam == 0 ? kHistXi : kHistEta];
  res.mapped = t_to + (t - t_from) * ratio;
  res.in_range = std::fabs(res.mapped) <= kHistParamMax;  // (false for NaN too)
  if (res.in_range) t = res.mapped;
  return res;
}

HandoverOutcome handover(const SegmentInput& from, const SegmentInput& to, int beam,
                         int direction, double* hist, int len) {
  HandoverOutcome out;
  const SegmentInput* in[2] = {&from, &to};
  curve::Segment seg[2];
  for (int k = 0; k < 2; ++k) {
    const SegmentInput& s = *in[k];
    const curve::Failure f = seg[k].build(s.kind, s.start_rule, s.end_rule, s.X, s.unit_tangents,
                                          false);
    if (f.status) {
      out.failure.status = f.status;
      out.failure.beam = k;
      out.failure.segment = f;
      return out;
    }
  }
  out.result = handover_history(seg[0], seg[1], beam, direction, hist, len);
  return out;
}

}  // namespace pair
}  // namespace b2b
