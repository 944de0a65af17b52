#include "line_pair.hpp"

#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../curve/vec3.hpp"
#include "../pair/history.hpp"
#include "segment_geometry.hpp"

namespace b2b {
namespace model {
namespace {

// A parameter within this of a joint is on it: the element's ownership
// band (1e-13 segment lengths, b2b_pair.h) in parameter units, with room.
constexpr double kOnJoint = 1e-9;

// Whether a segment owned parameter t at the commit: [-1, 1), a point on
// its start joint (t a rounding below -1) its own, one on its end joint
// the next segment's (ownership, b2b_pair.h).
bool in_segment(double t) { return t >= -1.0 - kOnJoint && t < 1.0 - kOnJoint; }

// The point this slot describes was owned by its pair at the commit: a
// written history whose eta lies in its segment.
bool owned(const double* slot) {
  return slot[pair::kHistTag] == pair::kHistTagV1 && in_segment(slot[pair::kHistEta]);
}

// The point element's slot (0, ALL_ANGLE) was owned at the commit: xi in
// its segment too.
bool point_owned(const double* slot) { return owned(slot) && in_segment(slot[pair::kHistXi]); }

// Slot 0 of (a, b) from the pair of a neighbouring segment of B (side 1) or
// of A (side 0) whose point element owned its point at the commit: the
// point part's history follows its point across one joint, as a point
// contact's does (Updater::handovers for point pairs).
void take_over_point_part(const BeamTable& table, const ContactState& committed,
                          const std::vector<double>& committed_coords,
                          const NodeIndex& used_index, int a, int b, size_t len, int hl,
                          double* hist) {
  if (point_owned(hist)) return;
  for (int side = 1; side >= 0; --side)
    for (int dir = -1; dir <= 1; dir += 2) {
      const int here = side ? b : a;
      const int nb = table.neighbour(here, dir);
      if (nb < 0 || nb == here) continue;
      const int fa = side ? a : nb, fb = side ? nb : b;
      const StoredPair* sp = committed.find(pair_key(fa, fb));
      if (!sp || sp->a != fa || static_cast<size_t>(sp->length) != len) continue;
      const double* from = committed.history(*sp);
      if (!point_owned(from)) continue;
      double moved[pair::kHistoryLengthMax];
      std::memcpy(moved, from, hl * sizeof(double));
      if (handover_committed(table, nb, here, side, -dir, committed_coords, used_index, moved,
                             hl)) {
        std::memcpy(hist, moved, hl * sizeof(double));
        return;
      }
    }
}

}  // namespace

int line_pair_points(const pair::Params& p, const pair::SegmentRef& A, const pair::SegmentRef& B,
                     int committed_length, int hl) {
  if (committed_length > 0) return committed_length / hl - 1;
  double c[3];
  curve::sub3(A.seg->end_point(), A.seg->start_point(), c);
  return pair::line_points(p, curve::norm3(c), A.radius, B.radius);
}

void take_over_points(const BeamTable& table, const ContactState& committed,
                      const std::vector<double>& committed_coords, const NodeIndex& used_index,
                      int a, int b, int n, int hl, double* hist) {
  if (committed_coords.empty()) return;
  const size_t len = static_cast<size_t>(n + 1) * hl;
  take_over_point_part(table, committed, committed_coords, used_index, a, b, len, hl, hist);
  for (int dir = -1; dir <= 1; dir += 2) {
    const int nb = table.neighbour(b, dir);
    if (nb < 0 || nb == b) continue;
    const StoredPair* sp = committed.find(pair_key(a, nb));
    if (!sp || sp->a != a || static_cast<size_t>(sp->length) != len) continue;
    const double* from = committed.history(*sp);
    for (int i = 1; i <= n; ++i) {
      double* slot = hist + static_cast<size_t>(i) * hl;
      if (owned(slot) || !owned(from + static_cast<size_t>(i) * hl)) continue;
      double moved[pair::kHistoryLengthMax];
      std::memcpy(moved, from + static_cast<size_t>(i) * hl, hl * sizeof(double));
      // From nb to b: b follows nb (direction +1) where nb precedes b.
      if (handover_committed(table, nb, b, 1, -dir, committed_coords, used_index, moved, hl))
        std::memcpy(slot, moved, hl * sizeof(double));
    }
  }
}

void summarize_line(const pair::LineResult& lr, const double* point_info, int n,
                    pair::PairResult& res) {
  res = pair::PairResult();
  res.contact_status = lr.contact_status;
  res.overflow = lr.overflow;
  std::memcpy(res.residual, lr.residual, sizeof res.residual);
  double* info = res.info;
  info[B2B_INFO_NORMAL_FORCE] = lr.info[B2B_LINE_INFO_NORMAL_FORCE];
  info[B2B_INFO_ENERGY] = lr.info[B2B_LINE_INFO_ENERGY];
  info[B2B_INFO_DISSIPATION] = lr.info[B2B_LINE_INFO_DISSIPATION];
  info[B2B_INFO_GAP] = lr.info[B2B_LINE_INFO_MIN_GAP];
  info[B2B_INFO_SYMMETRIC] = lr.info[B2B_LINE_INFO_SYMMETRIC];
  info[B2B_INFO_LINE_POINTS] = lr.info[B2B_LINE_INFO_ACTIVE_POINTS];
  const int point_state = static_cast<int>(lr.info[B2B_LINE_INFO_POINT_FRICTION_STATE]);
  info[B2B_INFO_FRICTION_STATE] =
      lr.info[B2B_LINE_INFO_SLIP_POINTS] > 0.0 || point_state == B2B_FRICTION_SLIP ? B2B_FRICTION_SLIP
      : lr.info[B2B_LINE_INFO_STICK_POINTS] > 0.0 || point_state == B2B_FRICTION_STICK
          ? B2B_FRICTION_STICK
          : B2B_FRICTION_NONE;
  int deepest = -1;
  for (int i = 0; i < n; ++i) {
    const double* pi = point_info + pair::kInfoLength * i;
    if (!(pi[B2B_INFO_NORMAL_FORCE] > 0.0)) continue;
    if (deepest < 0 || pi[B2B_INFO_GAP] < point_info[pair::kInfoLength * deepest + B2B_INFO_GAP])
      deepest = i;
  }
  // Where the point element carries at least half the force (ALL_ANGLE at
  // larger angles), its contact point; else the deepest integration point.
  const double lambda = lr.info[B2B_LINE_INFO_POINT_WEIGHT];
  const bool point_part = lambda > 0.0 && (deepest < 0 || lambda >= 0.5);
  if (point_part) {
    const double* pp = lr.point_part;
    for (int k : {B2B_INFO_XI, B2B_INFO_ETA, B2B_INFO_ANGLE}) info[k] = pp[k];
    for (int k = 0; k < 3; ++k) {
      info[B2B_INFO_POINT_A + k] = pp[B2B_INFO_POINT_A + k];
      info[B2B_INFO_POINT_B + k] = pp[B2B_INFO_POINT_B + k];
      info[B2B_INFO_NORMAL + k] = pp[B2B_INFO_NORMAL + k];
      info[B2B_INFO_TANGENTIAL_FORCE + k] = lambda * pp[B2B_INFO_TANGENTIAL_FORCE + k];
      info[B2B_INFO_SLIP + k] = pp[B2B_INFO_SLIP + k];
    }
    return;
  }
  if (deepest < 0) return;
  const double* pd = point_info + pair::kInfoLength * deepest;
  for (int k : {B2B_INFO_XI, B2B_INFO_ETA, B2B_INFO_ANGLE})
    info[k] = pd[k];
  for (int k = 0; k < 3; ++k) {
    info[B2B_INFO_POINT_A + k] = pd[B2B_INFO_POINT_A + k];
    info[B2B_INFO_POINT_B + k] = pd[B2B_INFO_POINT_B + k];
    info[B2B_INFO_NORMAL + k] = pd[B2B_INFO_NORMAL + k];
  }
}

}  // namespace model
}  // namespace b2b
