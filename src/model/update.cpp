// Model::update: one Newton iteration of the host.
//   1. the current coordinates of the beams' nodes (checked)
//   2. the broad phase, rebuilt only when a node has left its skin
//   3. the element on every candidate within contact reach and on the
//      contacts of the last commit, in parallel, in fixed chunks of the
//      candidate list, on segments built by each thread's small cache
//      (segment_cache.hpp) as the pairs ask for them; what a pair leaves is
//      streamed into its chunk: its status is counted, and only a pair that
//      a later stage reads (one with a record, pair_record.hpp) is kept; an
//      active contact's outputs go straight to the model's next set of
//      results (contact_result.hpp), all of it in pages that the next
//      update reuses (page_pool.hpp)
//   4. the crossing check (crossing.hpp) on the kept pairs
//   5. handover: a committed contact whose point left its pair follows it,
//      hop by hop, with its committed history mapped across each joint
//   6. the active set, sorted by pair, and the trial histories
// Nothing of the model changes unless all of it succeeds.
#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <exception>
#include <memory>
#include <new>

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
#include "segment_cache.hpp"
#include "segment_geometry.hpp"

namespace b2b {
namespace model {

namespace {

// Work items (candidates, then committed contacts that are not candidates)
// per chunk of the parallel evaluation.
constexpr int kChunk = 64;
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

// The entry of counts[] (B2B_COUNT_*) of a pair status.
int count_slot(int status) {
  switch (status) {
    case B2B_CONTACT_ACTIVE: return B2B_COUNT_ACTIVE;
    case B2B_CONTACT_OPEN: return B2B_COUNT_OPEN;
    case B2B_CONTACT_OUTSIDE: return B2B_COUNT_OUTSIDE;
    case B2B_CONTACT_PARALLEL: return B2B_COUNT_PARALLEL;
    case B2B_CONTACT_NOT_CONVERGED: return B2B_COUNT_NOT_CONVERGED;
    default: return B2B_COUNT_NO_NORMAL;
  }
}

}  // namespace

class Updater {
 public:
  Updater(Model& m, const double* x, int ldx, const double* u, int ldu, bool want_tangent)
      : m_(m), ws_(m.workspace_), x_(x), u_(u), ldx_(ldx), ldu_(ldu),
        want_tangent_(want_tangent), margin_(m.effective_margin()), items_(ws_.items),
        serial_scratch_(ws_.scratch), serial_results_(ws_.results) {}
  Problem run();

 private:
  using Item = UpdateItem;
  Model& m_;
  UpdateWorkspace& ws_;
  const double* x_;
  const double* u_;  // displacements added to x_ (nullptr: x_ is current)
  int ldx_, ldu_;
  bool want_tangent_;
  double margin_;  // the search margin (Model::effective_margin(), O(segments))
  std::vector<double> cur_;
  // Since the last commit (crossing.hpp): committed boxes and motion
  // (ws_.motion), and each segment's box swept from its committed to its
  // current position (ws_.swept).
  bool has_committed_ = false;
  // Histories made for pairs that crossed (committed normals; for line
  // pairs committed_line_histories): their hist_old.
  std::vector<std::vector<double>> synthetic_;
  PairRows new_candidates_;
  bool rebuilt_ = false;
  // Committed active contacts that are not candidates (evaluated whatever
  // the boxes say), in key order.
  std::vector<const StoredPair*> extras_;
  std::vector<Item*>& items_;  // the kept pairs, sorted by key (ws_.items)
  // Pairs evaluated and not kept, by B2B_COUNT_* of their status; all
  // evaluated pairs; candidates within contact reach.
  int unkept_[B2B_MODEL_COUNTS_LEN] = {0};
  int evaluated_ = 0, near_ = 0;
  // The items, records and results of the pairs evaluated after the
  // parallel stage (crossing, handover), in the same pages as the threads'.
  PageCursor<double> serial_scratch_, serial_results_;
  std::vector<double> fresh_;             // zeros: a fresh history
  int hops_ = 0, lost_ = 0;
  // [partition] the committed state the evaluation and the handovers read
  // (the model's, with the contacts received from other ranks:
  // migration.hpp), and the contacts whose walk reached a pair another rank
  // evaluates
  CommittedView view_;
  std::vector<Migrant> migrants_;
  const std::vector<Box>& search_boxes() const { return has_committed_ ? ws_.swept : ws_.boxes; }
  const PairRows& candidates() const { return rebuilt_ ? new_candidates_ : m_.candidates_; }

  int nt() const {
#ifdef B2B_HAVE_OPENMP
    return m_.threads > 0 ? m_.threads : omp_get_max_threads();
#else
    return 1;
#endif
  }
  Problem gather();
  Problem gather_node(size_t u);
  void sweep_boxes();
  void broad_phase();
  bool near(int a, int b, int gp) const;
  // Work item k of the evaluation (a candidate, (a, b), then an extra) as
  // an item to evaluate: false if it is not evaluated (apart and no
  // committed contact); *is_near: a candidate within contact reach.
  bool work_item(size_t k, int a, int b, Item& it, bool* is_near) const;
  // The element on one pair: res, and a line pair's new histories in
  // line_hist (buffers of the caller, reused from pair to pair). Its
  // segments come from cache; false (fail, *bad: the segment) when one
  // cannot be built: both are asked for, so the lower failing segment of
  // the pair is the one reported.
  bool evaluate(const Item& item, SegmentCache& cache, pair::PairResult& res,
                std::vector<double>& line_hist, double* K, curve::Failure& fail,
                int* bad) const;
  void evaluate_line(const Item& item, const pair::SegmentRef& A, const pair::SegmentRef& B,
                     pair::PairResult& res, std::vector<double>& line_hist, double* K) const;
  pair::SegmentRef ref(int s, const SegmentCache::Entry& e) const;
  SegmentEnds ends_of(int s) const;
  bool settle(Item& item, const pair::PairResult& res, const std::vector<double>& line_hist,
              const double* K, PageCursor<double>& recs, PageCursor<double>& results) const;
  void settle_alone(Item& item, const pair::PairResult& res, const std::vector<double>& line_hist,
                    const double* K);
  // A pair evaluated after the parallel stage, on the serial cache; a
  // segment that cannot be built is the Problem.
  Problem evaluate_serial(const Item& item, pair::PairResult& res,
                          std::vector<double>& line_hist, double* K);
  Problem segment_problem(int s, const curve::Failure& f) const;
  Problem evaluate_all();
  // The pages one thread of the evaluation writes to.
  struct Cursors {
    PageCursor<double> scratch, results;
  };
  void evaluate_chunk(int c, size_t n_work, SegmentCache& cache, UpdateTally& tally,
                      Cursors& pages, std::vector<double>& line_hist, pair::PairResult& res,
                      double* K);
  Problem crossed_pairs();
  Problem crossed_line_pair(Item& it);
  Problem evaluate_with(Item& it, std::vector<double> hist);
  // The status the evaluation gave pair (a, b), which it did not keep, or
  // -1 if it did not evaluate it (for a handover onto it).
  Problem unkept_status(int a, int b, int* status);
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
      pb = evaluate_all();
    }
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

// Used node u's current coordinates into cur_, or the Problem with them.
Problem Updater::gather_node(size_t u) {
  Problem pb;
  const int node = m_.used_nodes_[u];
  const double* p = x_ + static_cast<size_t>(ldx_) * node;
  const double* d = u_ ? u_ + static_cast<size_t>(ldu_) * node : nullptr;
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(p[i]) || std::fabs(p[i]) > B2B_COORD_MAX) {
      pb.status = std::isfinite(p[i]) ? B2B_ERR_RANGE : B2B_ERR_NONFINITE;
      pb.what = Problem::What::Coordinate;
      pb.node = node;
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
        pb.node = node;
        pb.axis = i;
        pb.value = d[i];
        return pb;
      }
      c = p[i] + d[i];
      if (!(std::fabs(c) <= B2B_COORD_MAX)) {  // also an overflow to inf
        pb.status = B2B_ERR_RANGE;
        pb.what = Problem::What::CurrentCoordinate;
        pb.node = node;
        pb.axis = i;
        pb.value = c;
        return pb;
      }
    }
    cur_[3 * u + i] = c;
  }
  return pb;
}

Problem Updater::gather() {
  const int n_used = static_cast<int>(m_.used_nodes_.size());
  // The buffer of the update before last (the model keeps the last one's).
  cur_.swap(ws_.coords);
  cur_.resize(3 * static_cast<size_t>(n_used));
  // In parallel; the first bad node in node order is the one reported (a
  // second pass, on the error path only, finds it).
  std::atomic<bool> bad{false};
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel for schedule(static) num_threads(nt()) if (n_used >= kParallelSegments)
#endif
  for (int u = 0; u < n_used; ++u)
    if (gather_node(static_cast<size_t>(u)).status) bad.store(true, std::memory_order_relaxed);
  if (bad)
    for (int u = 0; u < n_used; ++u)
      if (Problem pb = gather_node(static_cast<size_t>(u)); pb.status) return pb;
  Problem pb = m_.check_elements(cur_.data());  // O(n), before any search
  if (pb.status) return pb;
  bool self = false;
  for (const Beam& b : m_.beams_) self = self || b.self_contact;
  if (self && !m_.table_.arcs_measured())
    m_.table_.measure_arcs(m_.beams_, cur_.data(), m_.used_index_);
  sweep_boxes();
  return pb;
}

// Each segment's box; after a commit also its committed box, how far its
// nodes moved since, and the union of the two.
void Updater::sweep_boxes() {
  const int n = m_.table_.segment_count();
  std::vector<Box>& boxes = ws_.boxes;
  boxes.resize(n);
  has_committed_ = !m_.committed_coords_.empty();
  if (has_committed_) {
    ws_.motion.boxes.resize(n);
    ws_.motion.moved.resize(n);
    ws_.swept.resize(n);
  }
  const BeamTable& table = m_.table_;
  const double* cur = cur_.data();
  const double* committed = m_.committed_coords_.data();
  const NodeIndex& used = m_.used_index_;
  const bool has_committed = has_committed_;
  CommittedMotion& motion = ws_.motion;
  std::vector<Box>& swept = ws_.swept;
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel for schedule(static) num_threads(nt()) if (n >= kParallelSegments)
#endif
  for (int s = 0; s < n; ++s) {
    boxes[s] = segment_box(table.segment(s), cur, used);
    if (!has_committed) continue;
    segment_motion(table, s, cur, committed, used, motion);
    for (int i = 0; i < 3; ++i) {
      swept[s].lo[i] = std::min(boxes[s].lo[i], motion.boxes[s].lo[i]);
      swept[s].hi[i] = std::max(boxes[s].hi[i], motion.boxes[s].hi[i]);
    }
  }
}

// Verlet skin: the candidates stay valid until a node has moved more than
// half the margin since they were found (segment_geometry.hpp says why the
// boxes are grown by r + g0/2 + 4s/3 for that).
void Updater::broad_phase() {
  const double s = margin_;
  bool rebuild = m_.build_coords_.size() != cur_.size();
  if (!rebuild) {
    const int n_used = static_cast<int>(cur_.size() / 3);
    const double* cur = cur_.data();
    const double* built = m_.build_coords_.data();
    int moved = 0;
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel for schedule(static) num_threads(nt()) reduction(| : moved) \
    if (n_used >= kParallelSegments)
#endif
    for (int u = 0; u < n_used; ++u) {
      const double* p = cur + 3 * static_cast<size_t>(u);
      const double* q = built + 3 * static_cast<size_t>(u);
      const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                        (p[2] - q[2]) * (p[2] - q[2]);
      moved |= d2 > 0.25 * s * s;
    }
    rebuild = moved != 0;
  }
  if (!rebuild) return;
  rebuilt_ = true;
  const int n = static_cast<int>(ws_.boxes.size());
  const std::vector<Box>& swept = search_boxes();
  std::vector<Box>& grown = m_.search_boxes_;
  grown.resize(n);
  const BeamTable& table = m_.table_;
  const double g0_half = 0.5 * m_.g0_max_;
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel for schedule(static) num_threads(nt()) if (n >= kParallelSegments)
#endif
  for (int k = 0; k < n; ++k) {
    const double g = table.segment(k).radius + g0_half + 4.0 * s / 3.0;
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
  // The candidates hold the pairs now: the search's index, its own copy of
  // the pairs and the grown boxes go before the evaluation allocates (issue
  // 20: 1 kB per segment of the bundle, held from update to update before).
  m_.tree_.release();
  std::vector<Box>().swap(grown);
}

// Whether the candidate (a, b) of group pair gp is within contact reach.
// Swept boxes once there is a commit: a pair that met anywhere between its
// committed and its current position is evaluated (crossing.hpp).
bool Updater::near(int a, int b, int gp) const {
  const pair::Params& p = m_.group_pairs_[gp].params;
  const double reach = m_.table_.segment(a).radius + m_.table_.segment(b).radius +
                       pair::contact_start_gap(p) + margin_;
  return box_distance(search_boxes()[a], search_boxes()[b]) <= reach;
}

bool Updater::work_item(size_t k, int a, int b, Item& it, bool* is_near) const {
  const size_t n_cand = candidates().size();
  *is_near = false;
  const StoredPair* sp;
  if (k < n_cand) {
    const int gp = m_.group_pair_index(a, b);
    *is_near = near(a, b, gp);
    sp = view_.state->find(pair_key(a, b));
    // The contacts of the last commit are evaluated whatever the boxes say:
    // their pair tells where the point went.
    if (!*is_near && !(sp && sp->status == B2B_CONTACT_ACTIVE)) return false;
    it.a = a;
    it.b = b;
    it.gp = gp;
  } else {
    sp = extras_[k - n_cand];
    it.gp = sp->group_pair;
  }
  // A pair with a committed history keeps its orientation and reads it.
  if (sp) {
    it.a = sp->a;
    it.b = sp->b;
    it.hist_old = view_.state->history(*sp);
    it.hist_old_len = sp->length;
  }
  return true;
}

pair::SegmentRef Updater::ref(int s, const SegmentCache::Entry& e) const {
  const SegmentInfo& info = m_.table_.segment(s);
  return pair::SegmentRef{&e.built, info.kind, info.start_rule, info.end_rule, info.radius,
                          e.X,      kNoHostTangents};
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

bool Updater::evaluate(const Item& item, SegmentCache& cache, pair::PairResult& res,
                       std::vector<double>& line_hist, double* K, curve::Failure& fail,
                       int* bad) const {
  const double* cur = cur_.data();
  const SegmentCache::Entry* ea =
      cache.get(item.a, nullptr, m_.table_.segment(item.a), cur, m_.used_index_, fail);
  curve::Failure fail_b;
  const SegmentCache::Entry* eb =
      cache.get(item.b, ea, m_.table_.segment(item.b), cur, m_.used_index_, fail_b);
  if (!ea || !eb) {
    // The lower of the pair's failing segments.
    if (!ea && (eb || item.a < item.b)) {
      *bad = item.a;
    } else {
      *bad = item.b;
      fail = fail_b;
    }
    return false;
  }
  const pair::SegmentRef A = ref(item.a, *ea), B = ref(item.b, *eb);
  if (m_.group_pairs_[item.gp].line) {
    evaluate_line(item, A, B, res, line_hist, K);
    return true;
  }
  const double* h = item.hist_old ? item.hist_old : fresh_.data();
  const pair::Params& p = m_.group_pairs_[item.gp].params;
  pair::evaluate_built(p, A, B, h, res, K);
  if (res.contact_status == B2B_CONTACT_OUTSIDE)
    resolve_end_contact(p, A, B, ends_of(item.a), ends_of(item.b), h, res, K);
  return true;
}

// A line pair (GroupPair::line): its committed histories, points taken over
// from the pairs of B's neighbouring segments, the line element, and its
// summary in the point element's layout (line_pair.hpp).
void Updater::evaluate_line(const Item& item, const pair::SegmentRef& A,
                            const pair::SegmentRef& B, pair::PairResult& res,
                            std::vector<double>& line_hist, double* K) const {
  const GroupPair& gp = m_.group_pairs_[item.gp];
  const int hl = gp.hist_len;
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
// of the new history, the record (if the status has one) cut from recs,
// and an active contact's outputs, with its tangent K (null: none), cut
// from results. Returns whether a later stage reads the item (it has a
// record, or it overflowed).
bool Updater::settle(Item& item, const pair::PairResult& res,
                     const std::vector<double>& line_hist, const double* K,
                     PageCursor<double>& recs, PageCursor<double>& results) const {
  const GroupPair& gp = m_.group_pairs_[item.gp];
  item.status = static_cast<int8_t>(res.contact_status);
  item.overflow = res.overflow;
  item.hist_len = gp.line ? static_cast<int>(line_hist.size()) : gp.hist_len;
  item.rec = nullptr;
  item.result = nullptr;
  item.form = TangentForm::None;
  const bool committed = item.hist_old != nullptr;
  // The crossing check's first test (crossed_pairs), on the axis distance
  // of the closest points, as it would make it from the record.
  item.crossing = false;
  if (has_committed_ && !committed &&
      (item.status == B2B_CONTACT_ACTIVE || item.status == B2B_CONTACT_OPEN)) {
    double rho;
    if (gp.line) {
      rho = res.info[B2B_INFO_GAP] + m_.table_.segment(item.a).radius +
            m_.table_.segment(item.b).radius;
    } else {
      double d[3];
      for (int i = 0; i < 3; ++i) d[i] = res.info[B2B_INFO_POINT_A + i] - res.info[B2B_INFO_POINT_B + i];
      rho = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    item.crossing = may_have_crossed(ws_.motion, item.a, item.b, rho);
  }
  const bool with_diff = item.crossing && !gp.line;
  const size_t len = record_length(item.status, committed, item.hist_len, with_diff);
  if (len > 0) {
    double* rec = recs.take(len);
    write_record(res, committed, gp.line ? line_hist.data() : res.history, item.hist_len,
                 with_diff, rec);
    item.rec = rec;
  }
  if (item.status == B2B_CONTACT_ACTIVE) {
    item.form = tangent_form(K);
    double* block = results.take(result_length(item.form));
    write_result(res.info, res.residual, K, item.form, block);
    item.result = block;
  }
  return len > 0 || item.overflow;
}

// settle() for a pair evaluated after the parallel stage (rare: crossing,
// handover).
void Updater::settle_alone(Item& item, const pair::PairResult& res,
                           const std::vector<double>& line_hist, const double* K) {
  settle(item, res, line_hist, K, serial_scratch_, serial_results_);
}

Problem Updater::segment_problem(int s, const curve::Failure& f) const {
  Problem pb;
  pb.status = f.status;
  pb.what = Problem::What::Segment;
  pb.beam = m_.table_.segment(s).beam;
  pb.segment = m_.table_.segment(s).index;
  pb.slot_a = f.slot_a;
  pb.slot_b = f.slot_b;
  return pb;
}

Problem Updater::evaluate_serial(const Item& item, pair::PairResult& res,
                                 std::vector<double>& line_hist, double* K) {
  curve::Failure fail;
  int bad = -1;
  if (!evaluate(item, ws_.caches[0], res, line_hist, K, fail, &bad))
    return segment_problem(bad, fail);
  return Problem();
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
  for (const Item* p : items_) {
    const Item& it = *p;
    if (it.status != B2B_CONTACT_ACTIVE) continue;
    const double* info = result_info(it.result);
    energy += info[B2B_INFO_ENERGY];
    force += info[B2B_INFO_NORMAL_FORCE];
    dissipation += info[B2B_INFO_DISSIPATION];
    if (!std::isfinite(energy) || !std::isfinite(force) || !std::isfinite(dissipation) ||
        !std::isfinite(m_.committed_.dissipation + dissipation))
      return overflow(it);
  }
  return Problem();
}

// One chunk of work items [c kChunk, (c + 1) kChunk): each evaluated on
// the thread's cache, its status counted in the thread's tally, and the
// pair kept if a later stage reads it: its item, record and (active) outputs
// written to the thread's pages, the chunk's items contiguous.
// line_hist, res, K: the thread's buffers.
void Updater::evaluate_chunk(int c, size_t n_work, SegmentCache& cache, UpdateTally& tally,
                             Cursors& pages, std::vector<double>& line_hist,
                             pair::PairResult& res, double* K) {
  const size_t begin = static_cast<size_t>(c) * kChunk;
  const size_t end = std::min(n_work, begin + kChunk);
  const PairRows& cand = candidates();
  const size_t n_cand = cand.size();
  // The chunk's kept items, copied to its thread's page at the end (its
  // records are cut from the same page meanwhile).
  Item kept[kChunk];
  int n_kept = 0, kept_candidates = 0;
  // The rows walked with pointers of their own: writes through kept and
  // tally could otherwise alias the vectors' and force their reload.
  const int64_t* start = cand.start.data();
  const int* partner = cand.partner.data();
  int a = begin < n_cand ? cand.row_of(begin) : -1;  // the row of candidate k
  for (size_t k = begin; k < end; ++k) {
    int b = -1;
    if (k < n_cand) {
      while (static_cast<size_t>(start[a + 1]) <= k) ++a;
      b = partner[k];
    }
    Item it;
    bool is_near;
    if (!work_item(k, a, b, it, &is_near)) continue;
    tally.near += is_near;
    ++tally.evaluated;
    curve::Failure fail;
    int bad = -1;
    if (!evaluate(it, cache, res, line_hist, want_tangent_ ? K : nullptr, fail, &bad)) {
      if (tally.bad_segment < 0 || bad < tally.bad_segment) {
        tally.bad_segment = bad;
        tally.fail = fail;
      }
      continue;
    }
    if (!settle(it, res, line_hist, want_tangent_ ? K : nullptr, pages.scratch, pages.results)) {
      ++tally.counts[count_slot(it.status)];
      continue;
    }
    kept[n_kept++] = it;
    kept_candidates += k < n_cand;
  }
  Item* to = n_kept ? take_items(pages.scratch, static_cast<size_t>(n_kept)) : nullptr;
  std::uninitialized_copy(kept, kept + n_kept, to);
  ws_.chunks[c] = UpdateChunk{to, n_kept, kept_candidates};
}

Problem Updater::evaluate_all() {
  fresh_.assign(pair::kHistoryLengthMax, 0.0);
  // The committed contacts that the candidates do not hold (both lists are
  // in key order: the search returns its pairs sorted, a < b).
  const PairRows& cand = candidates();
  extras_.clear();
  for (const StoredPair& sp : view_.state->pairs) {
    if (sp.status != B2B_CONTACT_ACTIVE) continue;
    if (cand.find(std::min(sp.a, sp.b), std::max(sp.a, sp.b)) < 0) extras_.push_back(&sp);
  }
  const size_t n_work = cand.size() + extras_.size();
  const int n_chunks = static_cast<int>((n_work + kChunk - 1) / kChunk);
  const int threads = std::max(nt(), 1);
  if (ws_.caches.size() < static_cast<size_t>(threads)) ws_.caches.resize(threads);
  // The cache's size goes with the candidates: chosen again when they are.
  if (rebuilt_ || ws_.cache_sets == 0)
    ws_.cache_sets = SegmentCache::choose_sets(cand, m_.table_.segment_count(), threads);
  for (SegmentCache& cache : ws_.caches) cache.reset(ws_.cache_sets);
  // The workspace's pages, written again from their start; the results'
  // are not the model's (it holds the other set until this update ends).
  ws_.scratch.rewind();
  ws_.results.rewind();
  reserve_afresh(ws_.chunks, static_cast<size_t>(n_chunks));
  ws_.chunks.resize(n_chunks);
  ws_.tallies.assign(threads, UpdateTally());
  std::atomic<bool> thrown{false};  // no exception may leave a parallel region
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel num_threads(threads) if (n_work >= static_cast<size_t>(kParallelPairs))
#endif
  {
#ifdef B2B_HAVE_OPENMP
    const int t = omp_get_thread_num();
#else
    const int t = 0;
#endif
    SegmentCache& cache = ws_.caches[t];
    UpdateTally& tally = ws_.tallies[t];
    // A thread's pages and buffers, reused from chunk to chunk.
    Cursors pages{PageCursor<double>(ws_.scratch), PageCursor<double>(ws_.results)};
    std::vector<double> line_hist;
    pair::PairResult res;
    double K[pair::kNdof * pair::kNdof];
#ifdef B2B_HAVE_OPENMP
#pragma omp for schedule(dynamic, 1)
#endif
    for (int c = 0; c < n_chunks; ++c) {
      if (thrown.load(std::memory_order_relaxed)) continue;
      try {
        evaluate_chunk(c, n_work, cache, tally, pages, line_hist, res, K);
      } catch (...) {
        thrown = true;
      }
    }
  }
  if (thrown) throw std::bad_alloc();
  // The lowest segment that could not be built, as if all were built first.
  int bad = -1;
  const UpdateTally* bad_tally = nullptr;
  for (const UpdateTally& t : ws_.tallies) {
    if (t.bad_segment >= 0 && (bad < 0 || t.bad_segment < bad)) {
      bad = t.bad_segment;
      bad_tally = &t;
    }
    for (int i = 0; i < B2B_MODEL_COUNTS_LEN; ++i) unkept_[i] += t.counts[i];
    evaluated_ += t.evaluated;
    near_ += t.near;
  }
  if (bad_tally) return segment_problem(bad, bad_tally->fail);
  size_t n_kept = 0;
  for (int c = 0; c < n_chunks; ++c) n_kept += static_cast<size_t>(ws_.chunks[c].n_kept);
  // The kept pairs in key order: the candidates' in their order, then the
  // extras' (rare) merged in.
  reserve_afresh(items_, n_kept + 2 * extras_.size());
  size_t from_candidates = 0;
  for (int c = 0; c < n_chunks; ++c) {
    const UpdateChunk& o = ws_.chunks[c];
    for (int j = 0; j < o.n_kept; ++j) items_.push_back(o.kept + j);
    from_candidates += static_cast<size_t>(o.kept_candidates);
  }
  const auto by_key = [](const Item* x, const Item* y) { return x->key() < y->key(); };
  std::inplace_merge(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(from_candidates),
                     items_.end(), by_key);
  for (const Item* it : items_)
    if (it->overflow) return overflow(*it);
  return Problem();
}

// A pair without a committed history that has moved far enough to have
// passed through the other beam since the commit is checked against the
// normal of its committed closest points; on the other side now, it is
// evaluated with that normal as its history, which gives it its signed gap
// (crossing.hpp). In item order after the parallel evaluation, so the
// tangents' layout does not depend on the threads. (Every such pair is
// kept: active and open pairs have records.)
Problem Updater::crossed_pairs() {
  if (!has_committed_) return Problem();
  for (Item* p : items_) {
    Item& it = *p;
    // Active or open, no committed history, and moved far enough (settle()
    // made the first test on its closest points).
    if (!it.crossing) continue;
    if (m_.group_pairs_[it.gp].line) {
      if (Problem pb = crossed_line_pair(it); pb.status) return pb;
      continue;
    }
    const double* d = record_diff(it.rec, it.hist_len);
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
  if (Problem pb = evaluate_serial(it, res, line_hist, want_tangent_ ? K : nullptr); pb.status)
    return pb;
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
  const int hl = gp.hist_len;
  const int n = it.hist_len / hl - 1;
  std::vector<double> h(it.hist_len);
  if (!committed_line_histories(m_.table_.segment(it.a), m_.table_.segment(it.b),
                                m_.committed_coords_.data(), m_.used_index_,
                                gp.params.max_iterations, n, hl, h.data()))
    return Problem();
  return evaluate_with(it, std::move(h));
}

// The evaluation kept only the pairs a later stage reads; a handover onto
// another pair must know whether that pair was evaluated, and with what
// status, to count it once. The evaluation is a pure function of the
// coordinates and the committed state, so evaluating it again here gives
// exactly that status (handovers are rare: a contact crossing a joint).
Problem Updater::unkept_status(int a, int b, int* status) {
  *status = -1;
  const int lo = std::min(a, b), hi = std::max(a, b);
  const int64_t at = candidates().find(lo, hi);
  Item it;
  bool is_near = false;
  if (at >= 0) {
    if (!work_item(static_cast<size_t>(at), lo, hi, it, &is_near)) return Problem();
  } else {
    const auto ex = std::find_if(extras_.begin(), extras_.end(), [lo, hi](const StoredPair* sp) {
      return pair_key(sp->a, sp->b) == pair_key(lo, hi);
    });
    if (ex == extras_.end()) return Problem();
    work_item(candidates().size() + static_cast<size_t>(ex - extras_.begin()), -1, -1, it,
              &is_near);
  }
  pair::PairResult res;
  std::vector<double> line_hist;
  if (Problem pb = evaluate_serial(it, res, line_hist, nullptr); pb.status) return pb;
  *status = res.contact_status;
  return Problem();
}

Problem Updater::handovers() {
  const ContactState& committed = *view_.state;  // [partition] with the received contacts
  std::vector<uint64_t> claimed;  // targets a handover has taken in this update
  auto find_item = [this](uint64_t key) -> Item* {
    auto it = std::lower_bound(items_.begin(), items_.end(), key,
                               [](const Item* i, uint64_t k) { return i->key() < k; });
    return (it != items_.end() && (*it)->key() == key) ? *it : nullptr;
  };
  std::vector<Item*> added;  // in the kept pages, merged into items_ at the end
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
      Item trial;
      trial.a = a;
      trial.b = b;
      trial.gp = sp.group_pair;
      trial.hist_old = hist;
      pair::PairResult res;
      double K[pair::kNdof * pair::kNdof];
      if (Problem pb = evaluate_serial(trial, res, line_hist, want_tangent_ ? K : nullptr);
          pb.status)
        return pb;
      if (res.overflow) return overflow(trial);
      const int st = res.contact_status;
      if (st == B2B_CONTACT_ACTIVE || st == B2B_CONTACT_OPEN) {
        trial.hist_old = nullptr;  // the handed-over history lives only here
        settle_alone(trial, res, line_hist, want_tangent_ ? K : nullptr);
        claimed.push_back(key);
        if (Item* existing = find_item(key)) {
          *existing = trial;
        } else {
          // Evaluated and not kept (counted by its status there), or new.
          int old = -1;
          if (Problem pb = unkept_status(a, b, &old); pb.status) return pb;
          if (old >= 0)
            --unkept_[count_slot(old)];
          else
            ++evaluated_;
          Item* slot = take_items(serial_scratch_, 1);
          new (slot) Item(trial);
          added.push_back(slot);
        }
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
    const auto by_key = [](const Item* x, const Item* y) { return x->key() < y->key(); };
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
  // The trial state and the contacts are written into the workspace's set,
  // which the model's is swapped with at the end: at their size, reusing
  // the memory of the update before last (no vector grown by doubling).
  ContactState& trial = ws_.trial;
  std::vector<Contact>& contacts = ws_.contacts;
  // The pairs evaluated and not kept are counted already; the kept ones here.
  int counts[B2B_MODEL_COUNTS_LEN];
  std::memcpy(counts, unkept_, sizeof counts);
  double totals[8] = {0};
  double min_gap = HUGE_VAL;
  size_t n_kept = 0, n_hist = 0, n_active = 0;
  for (const Item* p : items_)
    if (p->status == B2B_CONTACT_ACTIVE || p->status == B2B_CONTACT_OPEN) {
      const Item& it = *p;
      ++n_kept;
      n_hist += static_cast<size_t>(it.hist_len);
      n_active += it.status == B2B_CONTACT_ACTIVE;
    }
  reserve_afresh(trial.pairs, n_kept);
  reserve_afresh(trial.hist, n_hist);
  reserve_afresh(contacts, n_active);
  for (const Item* p : items_) {
    const Item& it = *p;
    const int st = it.status;
    ++counts[count_slot(st)];
    // The axes passed through each other (signed gap below -(r_A + r_B)).
    if (st == B2B_CONTACT_ACTIVE &&
        it.rec[kRecGap] < -(m.table_.segment(it.a).radius + m.table_.segment(it.b).radius))
      ++counts[B2B_COUNT_CROSSED];
    if (st != B2B_CONTACT_ACTIVE && st != B2B_CONTACT_OPEN) continue;
    min_gap = std::min(min_gap, it.rec[kRecGap]);
    const GroupPair& gp = m.group_pairs_[it.gp];
    const double* h = it.rec + kRecHistory;
    const int len = it.hist_len;
    trial.pairs.push_back(StoredPair{it.key(), it.a, it.b, st, it.gp, trial.hist.size(), len});
    trial.hist.insert(trial.hist.end(), h, h + len);
    if (st != B2B_CONTACT_ACTIVE) continue;
    const double* info = result_info(it.result);
    if (gp.line) {
      ++counts[B2B_COUNT_LINE];
      totals[B2B_TOTAL_LINE_POINTS] += info[B2B_INFO_LINE_POINTS];
    }
    Contact c;
    c.a = it.a;
    c.b = it.b;
    std::memcpy(c.nodes, m.table_.segment(it.a).nodes, sizeof(int) * 4);
    std::memcpy(c.nodes + 4, m.table_.segment(it.b).nodes, sizeof(int) * 4);
    c.result = it.result;
    c.form = it.form;
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
  // Nothing below allocates: the model changes all at once. The pages this
  // update did not use are freed: the workspace holds what the last update
  // needed, not the most any update did.
  ws_.scratch.release_unused();
  ws_.results.release_unused();
  if (rebuilt_) {
    std::swap(m.candidates_, new_candidates_);
    m.build_coords_.swap(build_coords);
    ++m.builds_;
  }
  counts[B2B_COUNT_CANDIDATES] = static_cast<int>(m.candidates_.size());
  counts[B2B_COUNT_EVALUATED] = evaluated_;
  counts[B2B_COUNT_FAR] = counts[B2B_COUNT_CANDIDATES] - near_;
  counts[B2B_COUNT_SEARCH_BUILDS] = m.builds_;
  counts[B2B_COUNT_HANDOVERS] = hops_;
  counts[B2B_COUNT_LOST] = lost_;
  std::memcpy(m.counts_, counts, sizeof counts);
  std::memcpy(m.totals_, totals, sizeof totals);
  // The model's last trial state, contacts and results go to the workspace,
  // for the next update to write over.
  std::swap(m.trial_, trial);
  m.contacts_.swap(contacts);
  m.results_.swap(ws_.results);
  // The model keeps these coordinates; the buffer of the last update's
  // goes to the next update.
  m.current_coords_.swap(cur_);
  ws_.coords.swap(cur_);
  m.migration_.outgoing = std::move(migrants_);  // [partition]
  ++m.migration_.updates;
  m.want_tangent_ = want_tangent_;
  m.updated_ = true;
  m.has_results_ = true;
}

}  // namespace model
}  // namespace b2b
