#include "crossing.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "../curve/vec3.hpp"
#include "../pair/closest_point.hpp"
#include "../pair/gauss_legendre.hpp"
#include "../pair/history.hpp"
#include "segment_geometry.hpp"

namespace b2b {
namespace model {

void segment_motion(const BeamTable& table, int s, const double* coords, const double* committed,
                    const NodeIndex& used_index, CommittedMotion& out) {
  const SegmentInfo& info = table.segment(s);
  out.boxes[s] = segment_box(info, committed, used_index);
  double moved = 0.0;
  for (int node : info.nodes) {
    if (node < 0) continue;
    const size_t o = used_index.offset(node);
    double d[3];
    curve::sub3(coords + o, committed + o, d);
    moved = std::max(moved, curve::norm3(d));
  }
  out.moved[s] = moved;
}

bool may_have_crossed(const CommittedMotion& cm, int a, int b, double rho) {
  const double moved = cm.moved[a] + cm.moved[b];
  return moved >= rho && moved >= box_distance(cm.boxes[a], cm.boxes[b]);
}

bool committed_history(const SegmentInfo& a, const SegmentInfo& b, const double* committed,
                       const NodeIndex& used_index, int max_iterations, double* hist,
                       int hist_len) {
  curve::Segment sa, sb;
  if (build_segment(a, committed, used_index, sa, false).status ||
      build_segment(b, committed, used_index, sb, false).status)
    return false;
  double t[3];
  curve::sub3(sa.end_point(), sa.start_point(), t);
  const double len_a = curve::norm3(t);
  curve::sub3(sb.end_point(), sb.start_point(), t);
  const double unit = len_a + curve::norm3(t);
  double xi, eta;
  pair::chord_start(sa.start_point(), sa.end_point(), sb.start_point(), sb.end_point(), unit, &xi,
                    &eta);
  // Only the side matters: the closest points of the segments as far as the
  // search gets (clamped to the segments, where a joint's neighbour would
  // own them; the direction between them is what is kept).
  const pair::ClosestPoints cp =
      pair::closest_points(sa, sb, xi, eta, max_iterations, 1e-9 * unit, unit);
  xi = std::clamp(cp.xi, -1.0, 1.0);
  eta = std::clamp(cp.eta, -1.0, 1.0);
  double xa[3], xb[3], d[3];
  const double* origin = sa.base();
  sa.point_from(origin, xi, xa, nullptr, nullptr);
  sb.point_from(origin, eta, xb, nullptr, nullptr);
  curve::sub3(xa, xb, d);
  const double rho = curve::norm3(d);
  if (!(rho > 64.0 * DBL_EPSILON * unit)) return false;
  std::fill(hist, hist + hist_len, 0.0);
  hist[pair::kHistTag] = pair::kHistTagV1;
  hist[pair::kHistHasNormal] = 1.0;
  for (int i = 0; i < 3; ++i) hist[pair::kHistNormal + i] = d[i] / rho;
  hist[pair::kHistXi] = xi;
  hist[pair::kHistEta] = eta;
  return true;
}

bool committed_line_histories(const SegmentInfo& a, const SegmentInfo& b, const double* committed,
                              const NodeIndex& used_index, int max_iterations, int n, int hl,
                              double* hist) {
  curve::Segment sa, sb;
  if (build_segment(a, committed, used_index, sa, false).status ||
      build_segment(b, committed, used_index, sb, false).status)
    return false;
  std::fill(hist, hist + static_cast<size_t>(n + 1) * hl, 0.0);
  committed_history(a, b, committed, used_index, max_iterations, hist, hl);
  double t[3];
  curve::sub3(sa.end_point(), sa.start_point(), t);
  const double len_a = curve::norm3(t);
  curve::sub3(sb.end_point(), sb.start_point(), t);
  const double len_b = curve::norm3(t), unit = len_a + len_b;
  const double *xs, *ws;
  pair::gauss_legendre(n, &xs, &ws);
  const double* origin = sa.base();
  for (int i = 0; i < n; ++i) {
    // B's chord parameter of the point, then the one-sided search
    double xa[3];
    sa.point_from(origin, xs[i], xa, nullptr, nullptr);
    const double eta0 = pair::chord_projection(sa, xs[i], sb.start_point(), sb.end_point());
    const pair::ClosestPoints cp = pair::closest_points(sa, sb, xs[i], eta0, max_iterations,
                                                        1e-9 * unit, unit, pair::kFixXi);
    double xb[3], d[3];
    sb.point_from(origin, cp.eta, xb, nullptr, nullptr);
    curve::sub3(xa, xb, d);
    const double rho = curve::norm3(d);
    if (!(rho > 64.0 * DBL_EPSILON * unit)) continue;
    double* h = hist + static_cast<size_t>(i + 1) * hl;
    h[pair::kHistTag] = pair::kHistTagV1;
    h[pair::kHistHasNormal] = 1.0;
    for (int k = 0; k < 3; ++k) h[pair::kHistNormal + k] = d[k] / rho;
    h[pair::kHistXi] = xs[i];
    h[pair::kHistEta] = cp.eta;
  }
  return true;
}

}  // namespace model
}  // namespace b2b
