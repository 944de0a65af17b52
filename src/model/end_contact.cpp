#include "end_contact.hpp"

#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../curve/vec3.hpp"

namespace b2b {
namespace model {
namespace {

using curve::dot3;
using pair::Ends;
using pair::PairResult;

// The node a closest-point parameter t points to, if this segment may hold
// it: -1 (its start), +1 (its end), else 0. "Beyond the end" as the
// handover reads it (update.cpp): the end joint itself belongs there too.
int held_end(double t, const SegmentEnds& e) {
  if (t < -1.0 && e.start_held) return -1;
  if (t >= 1.0 - 1e-12 && e.end_held) return 1;
  return 0;
}

// Whether a held node is the closest point of its beam to the other beam's
// point to first order: d (from that point to the node) does not shrink
// when the point moves into the segment (direction -end x,xi) nor into the
// segment before a start node (direction -prev_tangent).
bool node_is_closest(const curve::Segment& seg, int end, const SegmentEnds& e, const double* d) {
  double t[3];
  seg.point(end, nullptr, t, nullptr);
  if (-end * dot3(d, t) < 0.0) return false;
  return !(end == -1 && e.has_prev && dot3(d, e.prev_tangent) > 0.0);
}

bool owned(int status) { return status == B2B_CONTACT_ACTIVE || status == B2B_CONTACT_OPEN; }

class EndSearch {
 public:
  EndSearch(const pair::Params& p, const pair::SegmentRef& A, const pair::SegmentRef& B,
            const SegmentEnds& ea, const SegmentEnds& eb, const double* hist, bool tangent)
      : p_(p), A_(A), B_(B), ea_(ea), eb_(eb), hist_(hist), tangent_(tangent) {}

  // Evaluates the pair with `ends` held; keeps it if it is an end contact
  // closer than the best so far. Returns the evaluation's status.
  int attempt(Ends ends) {
    pair::evaluate_built(p_, A_, B_, hist_, trial_, tangent_ ? Ktrial_ : nullptr, ends);
    const int st = trial_.contact_status;
    if (!owned(st)) return st;
    double d[3], e[3];
    for (int i = 0; i < 3; ++i) {
      d[i] = trial_.info[B2B_INFO_POINT_A + i] - trial_.info[B2B_INFO_POINT_B + i];
      e[i] = -d[i];
    }
    if (ends.a && !node_is_closest(*A_.seg, ends.a, ea_, d)) return st;
    if (ends.b && !node_is_closest(*B_.seg, ends.b, eb_, e)) return st;
    const double dist = std::sqrt(dot3(d, d));
    if (found_ && !(dist < best_dist_)) return st;
    found_ = true;
    best_dist_ = dist;
    best_ = trial_;
    if (tangent_) std::memcpy(Kbest_, Ktrial_, sizeof Kbest_);
    return st;
  }
  double trial_param(bool on_a) const {
    return trial_.info[on_a ? B2B_INFO_XI : B2B_INFO_ETA];
  }
  bool found() const { return found_; }
  const PairResult& best() const { return best_; }
  const double* best_tangent() const { return Kbest_; }

 private:
  const pair::Params& p_;
  const pair::SegmentRef &A_, &B_;
  const SegmentEnds &ea_, &eb_;
  const double* hist_;
  bool tangent_;
  PairResult trial_, best_;
  double Ktrial_[pair::kNdof * pair::kNdof], Kbest_[pair::kNdof * pair::kNdof];
  bool found_ = false;
  double best_dist_ = 0.0;
};

}  // namespace

bool resolve_end_contact(const pair::Params& params, const pair::SegmentRef& A,
                         const pair::SegmentRef& B, const SegmentEnds& ea, const SegmentEnds& eb,
                         const double* hist_old, PairResult& res, double* K) {
  const int ca = held_end(res.info[B2B_INFO_XI], ea);
  const int cb = held_end(res.info[B2B_INFO_ETA], eb);
  if (!ca && !cb) return false;
  EndSearch search(params, A, B, ea, eb, hist_old, K != nullptr);
  // A node of A against B's segment; if B's point leaves that segment too,
  // towards a node B may hold, the two nodes. Then the same from B's side.
  if (ca && search.attempt(Ends{ca, 0}) == B2B_CONTACT_OUTSIDE)
    if (const int cb2 = held_end(search.trial_param(false), eb)) search.attempt(Ends{ca, cb2});
  if (cb && search.attempt(Ends{0, cb}) == B2B_CONTACT_OUTSIDE)
    if (const int ca2 = held_end(search.trial_param(true), ea)) search.attempt(Ends{ca2, cb});
  if (!search.found()) return false;
  res = search.best();
  if (K) std::memcpy(K, search.best_tangent(), sizeof(double) * pair::kNdof * pair::kNdof);
  return true;
}

}  // namespace model
}  // namespace b2b
