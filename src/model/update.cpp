// Model::update: one Newton iteration of the host.
//   1. the current coordinates of the beams' nodes (checked)
//   2. the broad phase, rebuilt only when a node has left its skin
//   3. the near pairs among the candidates (boxes within contact reach), plus
//      the contacts of the last commit
//   4. their segments, built once, in parallel
//   5. the contact element on every such pair, in parallel, in fixed chunks
//   6. handover: a committed contact whose point left its pair follows it,
//      hop by hop, with its committed history mapped across each joint
//   7. the active set, sorted by pair, and the trial histories
// Nothing of the model changes unless all of it succeeds.
#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <exception>

#include <b2b/b2b.h>

#ifdef B2B_HAVE_OPENMP
#include <omp.h>
#endif

#include "../pair/handover.hpp"
#include "../pair/history.hpp"
#include "../pair/laws.hpp"
#include "../pair/line_contact.hpp"
#include "crossing.hpp"
#include "end_contact.hpp"
#include "line_pair.hpp"
#include "model.hpp"
#include "pair_record.hpp"
#include "segment_geometry.hpp"

namespace b2b {
namespace model {

namespace {

constexpr int kChunk = 32;  // pairs per parallel work item
// Below these sizes a parallel region costs more than it saves (starting a
// team, and idle threads spinning on a busy machine): run on one thread.
// (Unused without OpenMP.)
[[maybe_unused]] constexpr int kParallelPairs = 1024;
[[maybe_unused]] constexpr int kParallelSegments = 2048;

// Direction in which the contact point left a segment: +1 beyond its end
// (including the end joint, which belongs to the next segment), -1 before
// its start, 0 inside.
int exit_direction(double t) {
  if (t >= 1.0 - 1e-12) return 1;
  if (t < -1.0) return -1;
  return 0;
}

}  // namespace

class Updater {
 public:
  Updater(Model& m, const double* x, int ldx, const double* u, int ldu, bool want_tangent)
      : m_(m), x_(x), u_(u), ldx_(ldx), ldu_(ldu), want_tangent_(want_tangent) {}
  Problem run();

 private:
  // One pair to evaluate, and its outcome. Kept small: a bundle evaluates
  // ~85 pairs a segment and ~1% carry force; what the later stages read of
  // a pair is in its record (pair_record.hpp), which most pairs lack.
  struct Item {
    int a, b, gp;
    int8_t status = -1;     // B2B_CONTACT_* of its evaluation
    bool overflow = false;  // an output of the element is not finite
    // Lengths of its committed and of its new history: a line pair
    // (GroupPair::line) has (n + 1) point histories for n integration points.
    int hist_old_len = 0;
    int hist_len = 0;
    const double* hist_old = nullptr;  // committed history, or null (fresh)
    const double* rec = nullptr;       // its record, or null
    const double* tangent = nullptr;   // ACTIVE, with tangents: in tangent_blocks_
    uint64_t key() const { return pair_key(a, b); }
  };
  Model& m_;
  const double* x_;
  const double* u_;  // displacements added to x_ (nullptr: x_ is current)
  int ldx_, ldu_;
  bool want_tangent_;
  std::vector<double> cur_;
  std::vector<Box> boxes_;
  // Since the last commit (crossing.hpp): committed boxes and motion, and
  // each segment's box swept from its committed to its current position.
  bool has_committed_ = false;
  CommittedMotion motion_;
  std::vector<Box> swept_;
  // Histories made for pairs that crossed (committed normals; for line
  // pairs committed_line_histories): their hist_old.
  std::vector<std::vector<double>> synthetic_;
  std::vector<std::pair<int, int>> new_candidates_;
  bool rebuilt_ = false;
  std::vector<int> slot_;                 // segment -> index into built_ (-1: not built)
  std::vector<curve::Segment> built_;
  std::vector<double> built_X_;           // their patches, 12 each (for the FD tangent)
  std::vector<Item> items_;
  // The items' records and tangents in blocks of exact size at stable
  // addresses: one per chunk of the parallel evaluation, then one per pair
  // evaluated again after it (crossing, handover). No block is copied into
  // another: the tangents go to the model as they are.
  std::vector<std::vector<double>> records_, tangent_blocks_;
  std::vector<double> fresh_;             // zeros: a fresh history
  int hops_ = 0, lost_ = 0, near_ = 0;
  // [partition] the committed state near_pairs and handovers read (the
  // model's, with the contacts received from other ranks: migration.hpp),
  // and the contacts whose walk reached a pair another rank evaluates
  CommittedView view_;
  std::vector<Migrant> migrants_;
  const std::vector<Box>& search_boxes() const { return has_committed_ ? swept_ : boxes_; }

  int nt() const {
#ifdef B2B_HAVE_OPENMP
    return m_.threads > 0 ? m_.threads : omp_get_max_threads();
#else
    return 1;
#endif
  }
  Problem gather();
  void broad_phase();
  void near_pairs();
  Problem build_segments();
  Problem build_one(int s);
  pair::SegmentRef ref(int s) const {
    const SegmentInfo& info = m_.table_.segment(s);
    static const double kNoTangents[6] = {0, 0, 0, 0, 0, 0};
    return pair::SegmentRef{&built_[slot_[s]], info.kind,   info.start_rule,
                            info.end_rule,     info.radius, &built_X_[12 * slot_[s]],
                            kNoTangents};
  }
  SegmentEnds ends_of(int s) const;
  // The element on one pair: res, and a line pair's new histories in
  // line_hist (buffers of the caller, reused from pair to pair).
  void evaluate(const Item& item, pair::PairResult& res, std::vector<double>& line_hist,
                double* K) const;
  void evaluate_line(const Item& item, pair::PairResult& res, std::vector<double>& line_hist,
                     double* K) const;
  int64_t settle(Item& item, const pair::PairResult& res, const std::vector<double>& line_hist,
                 std::vector<double>& recs) const;
  void settle_alone(Item& item, const pair::PairResult& res, const std::vector<double>& line_hist,
                    const double* K);
  Problem evaluate_all();
  Problem crossed_pairs();
  Problem crossed_line_pair(Item& it);
  Problem evaluate_with(Item& it, std::vector<double> hist);
  Problem handovers();
  Problem overflow(const Item& item) const;
  Problem totals_overflow() const;
  void finish();
};

Problem Model::update(const double* x, int ldx, bool want_tangent) {
  Updater u(*this, x, ldx, nullptr, 0, want_tangent);
  return u.run();
}

Problem Model::update(const double* x, int ldx, const double* u, int ldu, bool want_tangent) {
  Updater up(*this, x, ldx, u, ldu, want_tangent);
  return up.run();
}

Problem Updater::run() {
  const bool had_arcs = m_.table_.arcs_measured();
  Problem pb;
  // An exception (std::bad_alloc, from this thread or carried out of a
  // parallel region) leaves the model as it was, like a Problem: the
  // firewall turns it into B2B_ERR_NOMEM.
  try {
    build_view(m_.committed_, m_.migration_, view_);  // [partition]
    lost_ += view_.conflicts;
    pb = gather();
    if (!pb.status) {
      broad_phase();
      near_pairs();
      pb = build_segments();
    }
    if (!pb.status) pb = evaluate_all();
    if (!pb.status) pb = crossed_pairs();
    if (!pb.status) pb = handovers();
    if (!pb.status) pb = totals_overflow();
  } catch (const CandidateLimit&) {
    pb.status = B2B_ERR_SIZE;
    pb.what = Problem::What::Candidates;
    pb.value = m_.max_candidates;
  } catch (...) {
    if (!had_arcs && m_.table_.arcs_measured()) m_.table_.set_arcs({}, {}, {});
    throw;
  }
  if (pb.status) {
    if (!had_arcs && m_.table_.arcs_measured()) m_.table_.set_arcs({}, {}, {});
    return pb;
  }
  finish();
  return pb;
}

Problem Updater::gather() {
  Problem pb;
  const std::vector<int>& used = m_.used_nodes_;
  cur_.resize(3 * used.size());
  for (size_t u = 0; u < used.size(); ++u) {
    const double* p = x_ + static_cast<size_t>(ldx_) * used[u];
    const double* d = u_ ? u_ + static_cast<size_t>(ldu_) * used[u] : nullptr;
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(p[i]) || std::fabs(p[i]) > B2B_COORD_MAX) {
        pb.status = std::isfinite(p[i]) ? B2B_ERR_RANGE : B2B_ERR_NONFINITE;
        pb.what = Problem::What::Coordinate;
        pb.node = used[u];
        pb.axis = i;
        pb.value = p[i];
        return pb;
      }
      double c = p[i];
      if (d) {
        // reference + displacement: the one rounding update(x + u) has too
        if (!std::isfinite(d[i])) {
          pb.status = B2B_ERR_NONFINITE;
          pb.what = Problem::What::Displacement;
          pb.node = used[u];
          pb.axis = i;
          pb.value = d[i];
          return pb;
        }
        c = p[i] + d[i];
        if (!(std::fabs(c) <= B2B_COORD_MAX)) {  // also an overflow to inf
          pb.status = B2B_ERR_RANGE;
          pb.what = Problem::What::CurrentCoordinate;
          pb.node = used[u];
          pb.axis = i;
          pb.value = c;
          return pb;
        }
      }
      cur_[3 * u + i] = c;
    }
  }
  pb = m_.check_elements(cur_.data());  // O(n), before any search
  if (pb.status) return pb;
  bool self = false;
  for (const Beam& b : m_.beams_) self = self || b.self_contact;
  if (self && !m_.table_.arcs_measured())
    m_.table_.measure_arcs(m_.beams_, cur_.data(), m_.used_index_);
  const int n = m_.table_.segment_count();
  boxes_.resize(n);
  for (int s = 0; s < n; ++s)
    boxes_[s] = segment_box(m_.table_.segment(s), cur_.data(), m_.used_index_);
  has_committed_ = !m_.committed_coords_.empty();
  if (has_committed_) {
    committed_motion(m_.table_, cur_.data(), m_.committed_coords_.data(), m_.used_index_,
                     motion_);
    swept_ = boxes_;
    for (int s = 0; s < n; ++s)
      for (int i = 0; i < 3; ++i) {
        swept_[s].lo[i] = std::min(swept_[s].lo[i], motion_.boxes[s].lo[i]);
        swept_[s].hi[i] = std::max(swept_[s].hi[i], motion_.boxes[s].hi[i]);
      }
  }
  return pb;
}

// Verlet skin: the candidates stay valid until a node has moved more than
// half the margin since they were found (segment_geometry.hpp says why the
// boxes are grown by r + g0/2 + 4s/3 for that).
void Updater::broad_phase() {
  const double s = m_.effective_margin();
  bool rebuild = m_.build_coords_.size() != cur_.size();
  for (size_t k = 0; !rebuild && k < cur_.size(); k += 3) {
    const double* p = &cur_[k];
    const double* q = &m_.build_coords_[k];
    const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                      (p[2] - q[2]) * (p[2] - q[2]);
    rebuild = d2 > 0.25 * s * s;
  }
  if (!rebuild) return;
  rebuilt_ = true;
  const int n = static_cast<int>(boxes_.size());
  const std::vector<Box>& swept = search_boxes();
  std::vector<Box>& grown = m_.search_boxes_;
  grown.resize(n);
  for (int k = 0; k < n; ++k) {
    const double g = m_.table_.segment(k).radius + 0.5 * m_.g0_max_ + 4.0 * s / 3.0;
    for (int i = 0; i < 3; ++i) {
      grown[k].lo[i] = swept[k].lo[i] - g;
      grown[k].hi[i] = swept[k].hi[i] + g;
    }
  }
  m_.tree_.build(grown);
  const Model& m = m_;
  // At most "max_candidates" pairs: one over stops the search (the count is
  // the same whatever the threads, so is the outcome).
  std::atomic<int64_t> accepted{0};
  const int64_t limit = m_.max_candidates;
  m_.tree_.overlapping_pairs(
      [&m, &accepted, limit](int a, int b) {
        if (!m.may_pair(a, b)) return false;
        if (accepted.fetch_add(1, std::memory_order_relaxed) >= limit) throw CandidateLimit();
        return true;
      },
      m_.threads, new_candidates_);
}

void Updater::near_pairs() {
  const std::vector<std::pair<int, int>>& cand = rebuilt_ ? new_candidates_ : m_.candidates_;
  const double s = m_.effective_margin();
  const ContactState& committed = *view_.state;  // [partition] with the received contacts
  // The group pair of a candidate within contact reach, or -1.
  const auto near = [this, s](const std::pair<int, int>& c) {
    const int gp = m_.group_pair_index(c.first, c.second);
    const pair::Params& p = m_.group_pairs_[gp].params;
    const double g0 = pair::contact_start_gap(p);
    const double reach = m_.table_.segment(c.first).radius + m_.table_.segment(c.second).radius +
                         g0 + s;
    // Swept boxes once there is a commit: a pair that met anywhere between
    // its committed and its current position is evaluated (crossing.hpp).
    return box_distance(search_boxes()[c.first], search_boxes()[c.second]) > reach ? -1 : gp;
  };
  // Counted first, so that the items are allocated once, at their size (a
  // vector grown by doubling holds up to twice that), with room for the
  // pairs handovers add, at most one per committed contact.
  size_t n_items = 0, n_committed = 0;
  for (const auto& c : cand) n_items += near(c) >= 0;
  for (const StoredPair& sp : committed.pairs) n_committed += sp.status == B2B_CONTACT_ACTIVE;
  items_.clear();
  items_.reserve(n_items + 2 * n_committed);
  for (const auto& c : cand) {
    const int gp = near(c);
    if (gp < 0) continue;
    ++near_;
    Item it;
    it.a = c.first;
    it.b = c.second;
    it.gp = gp;
    items_.push_back(it);
  }
  // The contacts of the last commit are evaluated whatever the boxes say:
  // their pair tells where the point went. Both lists are in key order (the
  // search returns its pairs sorted, a < b), so a merge keeps them so.
  const auto by_key = [](const Item& x, const Item& y) { return x.key() < y.key(); };
  const size_t n_near = items_.size();
  for (const StoredPair& sp : committed.pairs) {
    if (sp.status != B2B_CONTACT_ACTIVE) continue;
    Item it;
    it.a = sp.a;
    it.b = sp.b;
    it.gp = sp.group_pair;
    items_.push_back(it);
  }
  std::inplace_merge(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(n_near),
                     items_.end(), by_key);
  items_.erase(std::unique(items_.begin(), items_.end(),
                           [](const Item& x, const Item& y) { return x.key() == y.key(); }),
               items_.end());
  // A pair with a committed history keeps its orientation and reads it.
  for (Item& it : items_)
    if (const StoredPair* sp = committed.find(it.key())) {
      it.a = sp->a;
      it.b = sp->b;
      it.hist_old = committed.history(*sp);
      it.hist_old_len = sp->length;
    }
}

Problem Updater::build_one(int s) {
  Problem pb;
  slot_[s] = static_cast<int>(built_.size());
  built_.emplace_back();
  built_X_.resize(12 * built_.size());
  gather_patch(m_.table_.segment(s), cur_.data(), m_.used_index_, &built_X_[12 * slot_[s]]);
  const curve::Failure f =
      build_segment(m_.table_.segment(s), cur_.data(), m_.used_index_, built_.back(), true);
  if (f.status) {
    pb.status = f.status;
    pb.what = Problem::What::Segment;
    pb.beam = m_.table_.segment(s).beam;
    pb.segment = m_.table_.segment(s).index;
    pb.slot_a = f.slot_a;
    pb.slot_b = f.slot_b;
  }
  return pb;
}

Problem Updater::build_segments() {
  const int n = m_.table_.segment_count();
  // The segments of the items, in increasing order: marked in slot_ (two
  // per item, sorted, would cost more than the n slots), then numbered.
  slot_.assign(n, -1);
  for (const Item& it : items_) slot_[it.a] = slot_[it.b] = 0;
  int nn = 0;
  for (int s = 0; s < n; ++s) nn += slot_[s] == 0;
  if (nn == 0) return Problem();
  std::vector<int> need;
  need.reserve(nn);
  for (int s = 0; s < n; ++s)
    if (slot_[s] == 0) need.push_back(s);
  // Reserved before they are made (a segment is ~3 kB): a reserve after
  // would copy them all. Handovers add a few.
  built_.reserve(nn + 64);
  built_.assign(nn, curve::Segment());
  built_X_.reserve(12 * static_cast<size_t>(nn + 64));
  built_X_.assign(12 * static_cast<size_t>(nn), 0.0);
  for (int k = 0; k < nn; ++k) {
    slot_[need[k]] = k;
    gather_patch(m_.table_.segment(need[k]), cur_.data(), m_.used_index_, &built_X_[12 * k]);
  }
  std::vector<curve::Failure> fail(nn);
  const SegmentInfo* info = &m_.table_.segment(0);
  const double* cur = cur_.data();
  const NodeIndex& used = m_.used_index_;
  curve::Segment* built = built_.data();
  std::atomic<bool> thrown{false};  // no exception may leave a parallel region
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel for schedule(static) num_threads(nt()) if (nn >= kParallelSegments)
#endif
  for (int k = 0; k < nn; ++k) {
    try {
      fail[k] = build_segment(info[need[k]], cur, used, built[k], true);
    } catch (...) {
      thrown = true;
    }
  }
  if (thrown) throw std::bad_alloc();
  for (int k = 0; k < nn; ++k)
    if (fail[k].status) {
      Problem pb;
      pb.status = fail[k].status;
      pb.what = Problem::What::Segment;
      pb.beam = info[need[k]].beam;
      pb.segment = info[need[k]].index;
      pb.slot_a = fail[k].slot_a;
      pb.slot_b = fail[k].slot_b;
      return pb;
    }
  return Problem();
}

// Which nodes of segment s may hold an end contact (end_contact.hpp): its
// start, if the beam starts there or the straight segments turn there, and
// its end where the beam ends.
SegmentEnds Updater::ends_of(int s) const {
  SegmentEnds e;
  const SegmentInfo& info = m_.table_.segment(s);
  const int prev = m_.table_.neighbour(s, -1);
  e.end_held = m_.table_.neighbour(s, 1) < 0;
  e.has_prev = prev >= 0;
  if (!e.has_prev) {
    e.start_held = true;
  } else if (info.kind == B2B_CURVE_LINEAR && m_.table_.segment(prev).kind == B2B_CURVE_LINEAR) {
    // The chord before the joint (slots x2 -> x3 of the previous segment).
    const SegmentInfo& pi = m_.table_.segment(prev);
    const double* p0 = &cur_[m_.used_index_.offset(pi.nodes[1])];
    const double* p1 = &cur_[m_.used_index_.offset(pi.nodes[2])];
    for (int i = 0; i < 3; ++i) e.prev_tangent[i] = 0.5 * (p1[i] - p0[i]);
    e.start_held = true;
  }
  return e;
}

void Updater::evaluate(const Item& item, pair::PairResult& res, std::vector<double>& line_hist,
                       double* K) const {
  if (m_.group_pairs_[item.gp].line) return evaluate_line(item, res, line_hist, K);
  const double* h = item.hist_old ? item.hist_old : fresh_.data();
  const pair::Params& p = m_.group_pairs_[item.gp].params;
  const pair::SegmentRef A = ref(item.a), B = ref(item.b);
  pair::evaluate_built(p, A, B, h, res, K);
  if (res.contact_status == B2B_CONTACT_OUTSIDE)
    resolve_end_contact(p, A, B, ends_of(item.a), ends_of(item.b), h, res, K);
}

// A line pair (GroupPair::line): its committed histories, points taken over
// from the pairs of B's neighbouring segments, the line element, and its
// summary in the point element's layout (line_pair.hpp).
void Updater::evaluate_line(const Item& item, pair::PairResult& res,
                            std::vector<double>& line_hist, double* K) const {
  const GroupPair& gp = m_.group_pairs_[item.gp];
  const int hl = gp.hist_len;
  const pair::SegmentRef A = ref(item.a), B = ref(item.b);
  const int n = line_pair_points(gp.params, A, B, item.hist_old ? item.hist_old_len : 0, hl);
  const size_t len = static_cast<size_t>(n + 1) * hl;
  std::vector<double> in(len, 0.0);
  if (item.hist_old) std::memcpy(in.data(), item.hist_old, len * sizeof(double));
  take_over_points(m_.table_, m_.committed_, m_.committed_coords_, m_.used_index_, item.a,
                   item.b, n, hl, in.data());
  line_hist.assign(len, 0.0);
  double point_info[pair::kInfoLength * B2B_LINE_POINTS_MAX];
  pair::LineResult lr;
  pair::evaluate_line(gp.params, A, B, n, in.data(), line_hist.data(), lr, point_info, K);
  summarize_line(lr, point_info, n, res);
}

// Takes an evaluation into its item: the status, the overflow, the length
// of the new history, and the record (if the status has one) appended to
// recs. Returns the record's offset in recs, or -1. The item's record and
// tangent are left null for the caller to point into their blocks.
int64_t Updater::settle(Item& item, const pair::PairResult& res,
                        const std::vector<double>& line_hist, std::vector<double>& recs) const {
  const GroupPair& gp = m_.group_pairs_[item.gp];
  item.status = static_cast<int8_t>(res.contact_status);
  item.overflow = res.overflow;
  item.hist_len = gp.line ? static_cast<int>(line_hist.size()) : gp.hist_len;
  item.rec = nullptr;
  item.tangent = nullptr;
  const bool committed = item.hist_old != nullptr;
  const size_t len = record_length(item.status, committed, item.hist_len);
  if (len == 0) return -1;
  const size_t at = recs.size();
  recs.resize(at + len);
  write_record(res, committed, gp.line ? line_hist.data() : res.history, item.hist_len,
               recs.data() + at);
  return static_cast<int64_t>(at);
}

// settle() for a pair evaluated after the parallel stage (rare: crossing,
// handover): its record and tangent K (null: none) in blocks of their own.
void Updater::settle_alone(Item& item, const pair::PairResult& res,
                           const std::vector<double>& line_hist, const double* K) {
  std::vector<double> rec;
  if (settle(item, res, line_hist, rec) >= 0) {
    records_.push_back(std::move(rec));
    item.rec = records_.back().data();
  }
  if (K && item.status == B2B_CONTACT_ACTIVE) {
    tangent_blocks_.emplace_back(K, K + pair::kNdof * pair::kNdof);
    item.tangent = tangent_blocks_.back().data();
  }
}

Problem Updater::overflow(const Item& item) const {
  Problem pb;
  pb.status = B2B_ERR_RANGE;
  pb.what = Problem::What::Overflow;
  const SegmentInfo &a = m_.table_.segment(item.a), &b = m_.table_.segment(item.b);
  pb.beam = a.beam;
  pb.segment = a.index;
  pb.other_beam = b.beam;
  pb.other_segment = b.index;
  pb.value = m_.group_pairs_[item.gp].params.penalty;
  return pb;
}

// The stats sum the active contacts' energies, normal forces and
// dissipations, in finish()'s order. Each is finite (the element checks
// that), but their sum need not be, and on success every output is (b2b.h):
// the contact whose term makes a sum overflow is reported as overflowing.
Problem Updater::totals_overflow() const {
  double energy = 0.0, force = 0.0, dissipation = 0.0;
  for (const Item& it : items_) {
    if (it.status != B2B_CONTACT_ACTIVE) continue;
    const double* info = record_info(it.rec, it.hist_len);
    energy += info[B2B_INFO_ENERGY];
    force += info[B2B_INFO_NORMAL_FORCE];
    dissipation += info[B2B_INFO_DISSIPATION];
    if (!std::isfinite(energy) || !std::isfinite(force) || !std::isfinite(dissipation) ||
        !std::isfinite(m_.committed_.dissipation + dissipation))
      return overflow(it);
  }
  return Problem();
}

Problem Updater::evaluate_all() {
  fresh_.assign(pair::kHistoryLengthMax, 0.0);
  const int n = static_cast<int>(items_.size());
  const int n_chunks = (n + kChunk - 1) / kChunk;
  // One block of records and one of tangents per chunk, each filled by the
  // thread that evaluates the chunk: the layout does not depend on the
  // threads.
  records_.assign(n_chunks, std::vector<double>());
  tangent_blocks_.assign(want_tangent_ ? n_chunks : 0, std::vector<double>());
  Item* items = items_.data();
  std::atomic<bool> thrown{false};  // no exception may leave a parallel region
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel num_threads(nt()) if (n >= kParallelPairs)
#endif
  {
    // A thread's buffers, reused from chunk to chunk; a chunk's records and
    // tangents are copied out of them at their exact size.
    std::vector<double> recs, Ks, line_hist;
    pair::PairResult res;
    double K[pair::kNdof * pair::kNdof];
    int64_t rec_at[kChunk], K_at[kChunk];
#ifdef B2B_HAVE_OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
    for (int c = 0; c < n_chunks; ++c) {
      if (thrown.load(std::memory_order_relaxed)) continue;
      try {
        const int begin = c * kChunk, end = std::min(n, begin + kChunk);
        recs.clear();
        Ks.clear();
        for (int k = begin; k < end; ++k) {
          evaluate(items[k], res, line_hist, want_tangent_ ? K : nullptr);
          rec_at[k - begin] = settle(items[k], res, line_hist, recs);
          K_at[k - begin] = -1;
          if (want_tangent_ && items[k].status == B2B_CONTACT_ACTIVE) {
            K_at[k - begin] = static_cast<int64_t>(Ks.size());
            Ks.insert(Ks.end(), K, K + pair::kNdof * pair::kNdof);
          }
        }
        if (!recs.empty()) records_[c].assign(recs.begin(), recs.end());
        if (!Ks.empty()) tangent_blocks_[c].assign(Ks.begin(), Ks.end());
        for (int k = begin; k < end; ++k) {
          if (rec_at[k - begin] >= 0) items[k].rec = records_[c].data() + rec_at[k - begin];
          if (K_at[k - begin] >= 0) items[k].tangent = tangent_blocks_[c].data() + K_at[k - begin];
        }
      } catch (...) {
        thrown = true;
      }
    }
  }
  if (thrown) throw std::bad_alloc();
  for (const Item& it : items_)
    if (it.overflow) return overflow(it);
  return Problem();
}

// A pair without a committed history that has moved far enough to have
// passed through the other beam since the commit is checked against the
// normal of its committed closest points; on the other side now, it is
// evaluated with that normal as its history, which gives it its signed gap
// (crossing.hpp). In item order after the parallel evaluation, so the
// tangents' layout does not depend on the threads.
Problem Updater::crossed_pairs() {
  if (!has_committed_) return Problem();
  for (Item& it : items_) {
    const int st = it.status;
    if (it.hist_old || (st != B2B_CONTACT_ACTIVE && st != B2B_CONTACT_OPEN)) continue;
    if (m_.group_pairs_[it.gp].line) {
      if (Problem pb = crossed_line_pair(it); pb.status) return pb;
      continue;
    }
    const double* d = it.rec + kRecDiff;
    if (!may_have_crossed(motion_, it.a, it.b, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])))
      continue;
    const GroupPair& gp = m_.group_pairs_[it.gp];
    // Only pairs that moved this far need one (rare within Newton's
    // iterations).
    std::vector<double> h(pair::kHistoryLengthMax, 0.0);
    if (!committed_history(m_.table_.segment(it.a), m_.table_.segment(it.b),
                           m_.committed_coords_.data(), m_.used_index_,
                           gp.params.max_iterations, h.data(), gp.hist_len))
      continue;
    const double* nc = h.data() + pair::kHistNormal;
    if (d[0] * nc[0] + d[1] * nc[1] + d[2] * nc[2] >= 0.0) continue;  // same side
    if (Problem pb = evaluate_with(it, std::move(h)); pb.status) return pb;
  }
  return Problem();
}

// Evaluates a pair again with a synthetic committed history (the crossing
// check's), kept until the update ends, and settles its result.
Problem Updater::evaluate_with(Item& it, std::vector<double> hist) {
  synthetic_.push_back(std::move(hist));
  it.hist_old = synthetic_.back().data();
  it.hist_old_len = static_cast<int>(synthetic_.back().size());
  pair::PairResult res;
  std::vector<double> line_hist;
  double K[pair::kNdof * pair::kNdof];
  evaluate(it, res, line_hist, want_tangent_ ? K : nullptr);
  settle_alone(it, res, line_hist, want_tangent_ ? K : nullptr);
  if (it.overflow) return overflow(it);
  return Problem();
}

// A line pair new since the commit that moved far enough: every integration
// point gets the normal of its projection on the committed geometry as its
// history (committed_line_histories), and the pair is evaluated again; a
// point on the other side now keeps the committed side, with its signed gap
// (sign tracking). The same side: the same result as without it.
Problem Updater::crossed_line_pair(Item& it) {
  const GroupPair& gp = m_.group_pairs_[it.gp];
  const double rho = it.rec[kRecGap] + m_.table_.segment(it.a).radius +
                     m_.table_.segment(it.b).radius;
  if (!may_have_crossed(motion_, it.a, it.b, rho)) return Problem();
  const int hl = gp.hist_len;
  const int n = it.hist_len / hl - 1;
  std::vector<double> h(it.hist_len);
  if (!committed_line_histories(m_.table_.segment(it.a), m_.table_.segment(it.b),
                                m_.committed_coords_.data(), m_.used_index_,
                                gp.params.max_iterations, n, hl, h.data()))
    return Problem();
  return evaluate_with(it, std::move(h));
}

Problem Updater::handovers() {
  const ContactState& committed = *view_.state;  // [partition] with the received contacts
  std::vector<uint64_t> claimed;  // targets a handover has taken in this update
  auto find_item = [this](uint64_t key) -> Item* {
    auto it = std::lower_bound(items_.begin(), items_.end(), key,
                               [](const Item& i, uint64_t k) { return i.key() < k; });
    return (it != items_.end() && it->key() == key) ? &*it : nullptr;
  };
  const size_t n_sorted = items_.size();  // items_[0, n_sorted) stay sorted; new ones follow
  std::vector<Item> added;
  std::vector<double> line_hist;  // unused: line pairs are not handed over
  for (const StoredPair& sp : committed.pairs) {
    if (sp.status != B2B_CONTACT_ACTIVE) continue;
    // A line pair's points are handed over point by point when the pair of
    // B's next segment is evaluated (take_over_points).
    if (m_.group_pairs_[sp.group_pair].line) continue;
    const Item* own = find_item(sp.key);
    if (!own || own->status != B2B_CONTACT_OUTSIDE) continue;
    const GroupPair& gp = m_.group_pairs_[sp.group_pair];
    double hist[pair::kHistoryLengthMax];
    std::memcpy(hist, committed.history(sp), gp.hist_len * sizeof(double));
    int a = sp.a, b = sp.b, hops = 0;
    // [partition] a received contact has walked that far on other ranks
    const Migration::Received* from = view_.received(m_.migration_, sp.key);
    const int hops_before = from ? from->m.hops : 0;
    // (Its record has them: it was evaluated with its committed history.)
    double xi = own->rec[kRecXi], eta = own->rec[kRecEta];
    bool found = false;
    while (true) {
      const int da = exit_direction(xi), db = exit_direction(eta);
      if (da == 0 && db == 0) break;
      bool moved = true;
      for (int side = 0; side < 2 && moved; ++side) {
        const int d = side == 0 ? da : db;
        if (d == 0) continue;
        int& s = side == 0 ? a : b;
        const int next = m_.table_.neighbour(s, d);
        moved = next >= 0 && handover_committed(m_.table_, s, next, side, d, m_.committed_coords_,
                                                m_.used_index_, hist, gp.hist_len);
        if (moved) s = next;
        ++hops;
      }
      if (!moved || hops + hops_before > m_.max_hops) break;
      const uint64_t key = pair_key(a, b);
      // [partition] a pair another rank evaluates: the contact migrates
      // there (migration.hpp), and is not lost; one whose other segment is
      // padding here is (the ghost layer is too thin)
      if (!m_.partition_.evaluates(a, b)) {
        if (m_.partition_.owned_elsewhere(a, b)) {
          migrants_.push_back(make_migrant(m_.table_, m_.partition_, sp.a, sp.b, from, a, b,
                                           hops_before + hops, gp.ga, gp.gb, hist, gp.hist_len));
          found = true;
        }
        break;
      }
      const StoredPair* target = committed.find(key);
      if (target && target->status == B2B_CONTACT_ACTIVE) {  // its own contact: merged
        found = true;
        break;
      }
      if (std::find(claimed.begin(), claimed.end(), key) != claimed.end()) break;
      if (!m_.may_pair(a, b)) break;
      for (int s : {a, b})
        if (slot_[s] < 0)
          if (Problem pb = build_one(s); pb.status) return pb;
      Item trial;
      trial.a = a;
      trial.b = b;
      trial.gp = sp.group_pair;
      trial.hist_old = hist;
      pair::PairResult res;
      double K[pair::kNdof * pair::kNdof];
      evaluate(trial, res, line_hist, want_tangent_ ? K : nullptr);
      if (res.overflow) return overflow(trial);
      const int st = res.contact_status;
      if (st == B2B_CONTACT_ACTIVE || st == B2B_CONTACT_OPEN) {
        trial.hist_old = nullptr;  // the handed-over history lives only here
        settle_alone(trial, res, line_hist, want_tangent_ ? K : nullptr);
        claimed.push_back(key);
        if (Item* existing = find_item(key); existing && existing - items_.data() < static_cast<std::ptrdiff_t>(n_sorted))
          *existing = trial;
        else
          added.push_back(trial);
        found = true;
        break;
      }
      if (st != B2B_CONTACT_OUTSIDE) break;
      xi = res.info[B2B_INFO_XI];
      eta = res.info[B2B_INFO_ETA];
    }
    hops_ += hops;
    if (!found) ++lost_;
  }
  if (!added.empty()) {  // merged in key order (the rest is sorted already)
    const auto by_key = [](const Item& x, const Item& y) { return x.key() < y.key(); };
    std::sort(added.begin(), added.end(), by_key);
    const size_t n_sorted_items = items_.size();
    items_.insert(items_.end(), added.begin(), added.end());
    std::inplace_merge(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(n_sorted_items),
                       items_.end(), by_key);
  }
  return Problem();
}

void Updater::finish() {
  Model& m = m_;
  ContactState trial;
  std::vector<Contact> contacts;
  int counts[16] = {0};
  double totals[8] = {0};
  double min_gap = HUGE_VAL;
  // Sized first: the trial state and the contacts are allocated once, at
  // their size (a vector grown by doubling holds up to twice that).
  size_t n_kept = 0, n_hist = 0, n_active = 0;
  for (const Item& it : items_)
    if (it.status == B2B_CONTACT_ACTIVE || it.status == B2B_CONTACT_OPEN) {
      ++n_kept;
      n_hist += static_cast<size_t>(it.hist_len);
      n_active += it.status == B2B_CONTACT_ACTIVE;
    }
  trial.pairs.reserve(n_kept);
  trial.hist.reserve(n_hist);
  contacts.reserve(n_active);
  for (const Item& it : items_) {
    const int st = it.status;
    switch (st) {
      case B2B_CONTACT_ACTIVE:
        ++counts[B2B_COUNT_ACTIVE];
        // The axes passed through each other (signed gap below -(r_A + r_B)).
        if (it.rec[kRecGap] <
            -(m.table_.segment(it.a).radius + m.table_.segment(it.b).radius))
          ++counts[B2B_COUNT_CROSSED];
        break;
      case B2B_CONTACT_OPEN: ++counts[B2B_COUNT_OPEN]; break;
      case B2B_CONTACT_OUTSIDE: ++counts[B2B_COUNT_OUTSIDE]; break;
      case B2B_CONTACT_PARALLEL: ++counts[B2B_COUNT_PARALLEL]; break;
      case B2B_CONTACT_NOT_CONVERGED: ++counts[B2B_COUNT_NOT_CONVERGED]; break;
      default: ++counts[B2B_COUNT_NO_NORMAL]; break;
    }
    if (st != B2B_CONTACT_ACTIVE && st != B2B_CONTACT_OPEN) continue;
    min_gap = std::min(min_gap, it.rec[kRecGap]);
    const GroupPair& gp = m.group_pairs_[it.gp];
    const double* h = it.rec + kRecHistory;
    const int len = it.hist_len;
    trial.pairs.push_back(StoredPair{it.key(), it.a, it.b, st, it.gp, trial.hist.size(), len});
    trial.hist.insert(trial.hist.end(), h, h + len);
    if (st != B2B_CONTACT_ACTIVE) continue;
    const double* info = record_info(it.rec, len);
    if (gp.line) {
      ++counts[B2B_COUNT_LINE];
      totals[B2B_TOTAL_LINE_POINTS] += info[B2B_INFO_LINE_POINTS];
    }
    Contact c;
    c.a = it.a;
    c.b = it.b;
    std::memcpy(c.nodes, m.table_.segment(it.a).nodes, sizeof(int) * 4);
    std::memcpy(c.nodes + 4, m.table_.segment(it.b).nodes, sizeof(int) * 4);
    std::memcpy(c.info, info, sizeof c.info);
    std::memcpy(c.residual, record_residual(it.rec, len), sizeof c.residual);
    c.tangent = it.tangent;
    contacts.push_back(c);
    totals[B2B_TOTAL_ENERGY] += info[B2B_INFO_ENERGY];
    totals[B2B_TOTAL_DISSIPATION_STEP] += info[B2B_INFO_DISSIPATION];
    totals[B2B_TOTAL_NORMAL_FORCE] += info[B2B_INFO_NORMAL_FORCE];
    const int friction_state = static_cast<int>(info[B2B_INFO_FRICTION_STATE]);
    if (friction_state == B2B_FRICTION_STICK) ++counts[B2B_COUNT_STICK];
    if (friction_state == B2B_FRICTION_SLIP) ++counts[B2B_COUNT_SLIP];
  }
  trial.dissipation = m.committed_.dissipation + totals[B2B_TOTAL_DISSIPATION_STEP];
  totals[B2B_TOTAL_DISSIPATION] = trial.dissipation;
  // No pair owns a closest point: the gap is unbounded, reported finite
  // (b2b_model.h), and never as 0, which would read as touching.
  totals[B2B_TOTAL_MIN_GAP] = min_gap == HUGE_VAL ? DBL_MAX : min_gap;

  std::vector<double> build_coords;  // allocated before the model changes
  if (rebuilt_) build_coords = cur_;
  // The tangent blocks the contacts point into (the empty ones left out).
  std::vector<std::vector<double>> tangents;
  tangents.reserve(static_cast<size_t>(
      std::count_if(tangent_blocks_.begin(), tangent_blocks_.end(),
                    [](const std::vector<double>& b) { return !b.empty(); })));
  for (std::vector<double>& b : tangent_blocks_)
    if (!b.empty()) tangents.push_back(std::move(b));
  if (rebuilt_) {
    m.candidates_.swap(new_candidates_);
    m.build_coords_.swap(build_coords);
    ++m.builds_;
  }
  counts[B2B_COUNT_CANDIDATES] = static_cast<int>(m.candidates_.size());
  counts[B2B_COUNT_EVALUATED] = static_cast<int>(items_.size());
  counts[B2B_COUNT_FAR] = counts[B2B_COUNT_CANDIDATES] - near_;
  counts[B2B_COUNT_SEARCH_BUILDS] = m.builds_;
  counts[B2B_COUNT_HANDOVERS] = hops_;
  counts[B2B_COUNT_LOST] = lost_;
  std::memcpy(m.counts_, counts, sizeof counts);
  std::memcpy(m.totals_, totals, sizeof totals);
  m.trial_ = std::move(trial);
  m.contacts_ = std::move(contacts);
  m.tangents_ = std::move(tangents);
  m.current_coords_ = std::move(cur_);
  m.migration_.outgoing = std::move(migrants_);  // [partition]
  ++m.migration_.updates;
  m.want_tangent_ = want_tangent_;
  m.updated_ = true;
  m.has_results_ = true;
}

}  // namespace model
}  // namespace b2b
