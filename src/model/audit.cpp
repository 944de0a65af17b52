#include "audit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <b2b/b2b.h>

#include "audit_grid.hpp"
#include "contact_state.hpp"
#include "segment_distance.hpp"
#include "segment_geometry.hpp"

namespace b2b {
namespace model {

namespace {

double dot(const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

// Euclidean distance between two boxes (0 if they overlap).
double box_gap(const Box& p, const Box& q) {
  double s = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double d = std::max({0.0, p.lo[k] - q.hi[k], q.lo[k] - p.hi[k]});
    s += d * d;
  }
  return std::sqrt(s);
}

// Segments built on one configuration on demand (once each), kept as cubics.
class Built {
 public:
  Built(const Model& m, const std::vector<double>& coords) : m_(m), coords_(coords) {}
  const Cubic* get(int s) {
    if (state_.empty()) {
      state_.assign(m_.table().segment_count(), 0);
      cubic_.resize(m_.table().segment_count());
    }
    if (state_[s] == 0) {
      const curve::Failure f =
          build_segment(m_.table().segment(s), coords_.data(), m_.used_index(), scratch_, false);
      if (!f.status) cubic_[s] = Cubic::of(scratch_);
      state_[s] = f.status ? 2 : 1;
    }
    return state_[s] == 1 ? &cubic_[s] : nullptr;
  }

 private:
  const Model& m_;
  const std::vector<double>& coords_;
  curve::Segment scratch_;
  std::vector<Cubic> cubic_;
  std::vector<char> state_;  // 0 not built, 1 built, 2 cannot be built
};

class Auditor {
 public:
  Auditor(const Model& m, double tolerance)
      : m_(m), table_(m.table()), tol_(tolerance), current_(m, m.current_coords()),
        committed_(m, m.committed_coords()) {}
  std::vector<AuditFinding> run();

 private:
  const Model& m_;
  const BeamTable& table_;
  double tol_;
  Built current_, committed_;
  std::vector<uint64_t> forced_;  // keys of the pairs with an active contact, sorted

  bool may_touch(int a, int b) const;
  bool carried(int a, int b, const SegmentClosest& c) const;
  int reason(int a, int b, const SegmentClosest& c);
  bool has_force(int a, int b) const {
    return std::binary_search(forced_.begin(), forced_.end(), pair_key(a, b));
  }
};

// The rules that decide before any geometry whether two segments may touch,
// from the model's set-up: a group pair, no shared host node, and on one beam
// self-contact (its exclusion length is a reason, not a filter).
bool Auditor::may_touch(int a, int b) const {
  const SegmentInfo &sa = table_.segment(a), &sb = table_.segment(b);
  const Beam &ba = m_.beam(sa.beam), &bb = m_.beam(sb.beam);
  if (!m_.group_pair(ba.group, bb.group)) return false;
  if (table_.share_node(a, b)) return false;
  // [partition] a rank's model audits the pairs it evaluates (each pair on
  // one rank); pieces of one global beam never pair
  const Partition& part = m_.partition();
  if (!part.evaluates(a, b) || part.other_piece(sa, sb)) return false;
  return sa.beam != sb.beam || ba.self_contact;
}

// Whether the overlap is resisted by an active contact: on this pair, or, if
// the closest point lies on a joint, on the pair across it (the element puts
// a point on a joint on one of the pairs that share it).
bool Auditor::carried(int a, int b, const SegmentClosest& c) const {
  if (has_force(a, b)) return true;
  const int ea = at_segment_end(c.xi), eb = at_segment_end(c.eta);
  const int na = ea ? table_.neighbour(a, ea) : -1, nb = eb ? table_.neighbour(b, eb) : -1;
  for (int x : {a, na})
    for (int y : {b, nb})
      if (x >= 0 && y >= 0 && x != y && has_force(x, y)) return true;
  return false;
}

int Auditor::reason(int a, int b, const SegmentClosest& c) {
  const SegmentInfo &sa = table_.segment(a), &sb = table_.segment(b);
  // 1. the self-contact exclusion length
  if (sa.beam == sb.beam && table_.arcs_measured()) {
    const Beam& beam = m_.beam(sa.beam);
    const double exclusion = beam.exclusion >= 0.0 ? beam.exclusion : 4.0 * beam.radius;
    if (table_.arc_gap(beam, a, b) <= exclusion) return B2B_AUDIT_EXCLUDED_SELF;
  }
  // 2. not among the last update's candidates
  if (m_.candidates().find(a, b) < 0) return B2B_AUDIT_NEVER_EVALUATED;
  // 3. the centrelines passed through each other since the commit: the
  //    separation now points against the committed one
  if (!m_.committed_coords().empty()) {
    const Cubic *pa = committed_.get(a), *pb = committed_.get(b);
    if (pa && pb) {
      const SegmentClosest k = closest_between(*pa, *pb);
      if (k.dist > 0.0 && dot(k.d, c.d) < 0.0) return B2B_AUDIT_CROSSED;
    }
  }
  // 4. crossing angle below the group pair's parallel_angle
  const GroupPair* gp = m_.group_pair(m_.beam(sa.beam).group, m_.beam(sb.beam).group);
  const double cx[3] = {c.ta[1] * c.tb[2] - c.ta[2] * c.tb[1],
                        c.ta[2] * c.tb[0] - c.ta[0] * c.tb[2],
                        c.ta[0] * c.tb[1] - c.ta[1] * c.tb[0]};
  const double speeds = std::sqrt(dot(c.ta, c.ta) * dot(c.tb, c.tb));
  if (std::sqrt(dot(cx, cx)) < gp->params.sin_parallel_angle * speeds)
    return B2B_AUDIT_PARALLEL;
  // 5. closest point on a joint or beam end with no force on either side
  if (at_segment_end(c.xi) || at_segment_end(c.eta)) {
    // [partition] ... that this model can see: a pair across the joint is
    // another rank's, whose contact may carry the overlap
    const int ea = at_segment_end(c.xi), eb = at_segment_end(c.eta);
    const int na = ea ? table_.neighbour(a, ea) : -1, nb = eb ? table_.neighbour(b, eb) : -1;
    for (int x : {a, na})
      for (int y : {b, nb})
        if (x >= 0 && y >= 0 && x != y && m_.partition().owned_elsewhere(x, y))
          return B2B_AUDIT_OTHER_RANK;
    return B2B_AUDIT_OUTSIDE_BOTH;
  }
  return B2B_AUDIT_OTHER;
}

std::vector<AuditFinding> Auditor::run() {
  std::vector<AuditFinding> found;
  const int n = table_.segment_count();
  const std::vector<double>& x = m_.current_coords();
  // The boxes around each segment's curve, grown by its radius: surfaces
  // can only overlap where these do.
  std::vector<Box> boxes(n), grown(n);
  for (int s = 0; s < n; ++s) {
    boxes[s] = segment_box(table_.segment(s), x.data(), m_.used_index());
    const double r = table_.segment(s).radius;
    for (int k = 0; k < 3; ++k) {
      grown[s].lo[k] = boxes[s].lo[k] - r;
      grown[s].hi[k] = boxes[s].hi[k] + r;
    }
  }
  std::vector<std::pair<int, int>> pairs;
  grid_overlapping_pairs(grown, pairs);
  for (const Contact& c : m_.contacts()) forced_.push_back(pair_key(c.a, c.b));
  std::sort(forced_.begin(), forced_.end());
  for (const auto& p : pairs) {
    const int a = p.first, b = p.second;
    const double ra = table_.segment(a).radius, rb = table_.segment(b).radius;
    if (!may_touch(a, b) || box_gap(boxes[a], boxes[b]) >= ra + rb) continue;
    const Cubic *sa = current_.get(a), *sb = current_.get(b);
    if (!sa || !sb) continue;  // cannot happen after a successful update
    if (distance_lower_bound(*sa, *sb) >= ra + rb) continue;
    const SegmentClosest c = closest_between(*sa, *sb);
    const double overlap = ra + rb - c.dist;
    if (!(overlap > tol_ * std::min(ra, rb))) continue;
    if (carried(a, b, c)) continue;
    found.push_back(AuditFinding{a, b, overlap, reason(a, b, c)});
  }
  std::sort(found.begin(), found.end(), [](const AuditFinding& p, const AuditFinding& q) {
    return p.a != q.a ? p.a < q.a : p.b < q.b;
  });
  return found;
}

}  // namespace

std::vector<AuditFinding> audit(const Model& m, double tolerance) {
  return Auditor(m, tolerance).run();
}

}  // namespace model
}  // namespace b2b
