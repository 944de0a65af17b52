// Restart: the committed state of a model as bytes, and back.
//
// Layout (native byte order and doubles; a restart file is for the same
// platform): "B2BMODL1", total size, format version, model fingerprint (a
// hash of n_nodes, the beams with their self-contact settings, and every
// group pair with every parameter of its set, so a buffer is only accepted
// by a model built the same way), the committed coordinates of the beams'
// nodes, the self-contact arc spans (once committed), the total dissipation,
// the committed pairs with their histories, and an FNV-1a checksum of
// everything before it.
//
// The checksum only tells damage from chance; a buffer may have been
// crafted, so restore also checks every field against the model: sizes,
// every double finite and in its range (coordinates within B2B_COORD_MAX,
// arc spans ordered along each beam within its length, dissipation >= 0),
// and every pair one this model could have formed (segments in range,
// distinct, of groups that are paired, sharing no node, beyond the
// self-contact exclusion on one beam) with its own group pair, history
// length and a history the element could have written. Anything else is
// B2B_ERR_RANGE with the model unchanged. Everything else a model holds is either
// set up by the host again or recomputed at the next update (the search);
// neither changes the results, so a restored model continues bit for bit.
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../pair/history_check.hpp"
#include "model.hpp"

namespace b2b {
namespace model {
namespace {

constexpr char kMagic[8] = {'B', '2', 'B', 'M', 'O', 'D', 'L', '1'};
// 2: the fingerprint covers the group pairs' parameters (a version 1
// buffer would be refused as foreign; this says why).
constexpr uint64_t kVersion = 2;

uint64_t fnv1a(const unsigned char* p, size_t n, uint64_t h = 1469598103934665603ULL) {
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

class Writer {
 public:
  explicit Writer(unsigned char* out) : out_(out) {}
  void bytes(const void* p, size_t n) {
    if (out_) std::memcpy(out_ + size_, p, n);
    size_ += n;
  }
  void u64(uint64_t v) { bytes(&v, 8); }
  void f64(double v) { bytes(&v, 8); }
  void doubles(const std::vector<double>& v) {
    u64(v.size());
    if (!v.empty()) bytes(v.data(), 8 * v.size());
  }
  size_t size() const { return size_; }

 private:
  unsigned char* out_;
  size_t size_ = 0;
};

class Reader {
 public:
  Reader(const unsigned char* p, size_t n) : p_(p), n_(n) {}
  bool bytes(void* out, size_t n) {
    if (n > n_ - pos_) return false;
    std::memcpy(out, p_ + pos_, n);
    pos_ += n;
    return true;
  }
  bool u64(uint64_t& v) { return bytes(&v, 8); }
  bool f64(double& v) { return bytes(&v, 8); }
  bool doubles(std::vector<double>& v, uint64_t max) {
    uint64_t n;
    if (!u64(n) || n > max || n > (n_ - pos_) / 8) return false;
    v.resize(n);
    return n == 0 || bytes(v.data(), 8 * n);
  }
  size_t left() const { return n_ - pos_; }

 private:
  const unsigned char* p_;
  size_t n_, pos_ = 0;
};

}  // namespace

struct RestartCodec {
  static void write(const Model& m, Writer& w) {
    w.bytes(kMagic, 8);
    w.u64(0);  // total size, patched by the caller
    w.u64(kVersion);
    w.u64(m.fingerprint());
    w.doubles(m.committed_coords_);
    // arc spans of an update not yet committed are not part of the state
    static const std::vector<double> kNone;
    w.doubles(m.arcs_committed_ ? m.table_.arc_lo() : kNone);
    w.doubles(m.arcs_committed_ ? m.table_.arc_hi() : kNone);
    w.doubles(m.arcs_committed_ ? m.table_.arc_total() : kNone);
    w.f64(m.committed_.dissipation);
    w.u64(m.committed_.pairs.size());
    for (const StoredPair& p : m.committed_.pairs) {
      w.u64(p.key);
      w.u64(static_cast<uint64_t>(p.a));
      w.u64(static_cast<uint64_t>(p.b));
      w.u64(static_cast<uint64_t>(p.status));
      w.u64(static_cast<uint64_t>(p.group_pair));
      w.u64(static_cast<uint64_t>(p.length));
      w.bytes(m.committed_.history(p), 8 * static_cast<size_t>(p.length));
    }
  }

  static Problem fail(const char* detail) {
    Problem pb;
    pb.status = B2B_ERR_RANGE;
    pb.what = Problem::What::Buffer;
    pb.detail = detail;
    return pb;
  }

  // Per beam: a length >= 0 and, segment by segment, spans lo <= hi within
  // [-length, length] (a ring's first centred span starts before 0), both
  // non-decreasing along the beam; all finite.
  static bool arcs_valid(const Model& m, const std::vector<double>& lo,
                         const std::vector<double>& hi, const std::vector<double>& total) {
    if (lo.empty()) return true;
    for (size_t b = 0; b < m.beams_.size(); ++b) {
      const Beam& beam = m.beams_[b];
      const double t = total[b];
      if (!std::isfinite(t) || !(t >= 0.0)) return false;
      for (int s = 0; s < beam.n_segments; ++s) {
        const size_t g = static_cast<size_t>(beam.first_segment + s);
        if (!std::isfinite(lo[g]) || !std::isfinite(hi[g]) || !(lo[g] <= hi[g]) ||
            !(lo[g] >= -t) || !(hi[g] <= t))
          return false;
        if (s > 0 && (!(lo[g] >= lo[g - 1]) || !(hi[g] >= hi[g - 1]))) return false;
      }
    }
    return true;
  }

  static Problem read(Model& m, const unsigned char* buf, int64_t size) {
    if (size < 40) return fail("it is truncated (shorter than the header)");
    if (std::memcmp(buf, kMagic, 8) != 0) return fail("it is not a b2b model restart buffer");
    uint64_t total, version, fingerprint;
    std::memcpy(&total, buf + 8, 8);
    std::memcpy(&version, buf + 16, 8);
    std::memcpy(&fingerprint, buf + 24, 8);
    if (version != kVersion) return fail("it has an unknown format version");
    if (static_cast<uint64_t>(size) < total) return fail("it is truncated");
    if (total < 40) return fail("it is corrupted (bad size)");
    uint64_t sum;
    std::memcpy(&sum, buf + total - 8, 8);
    if (fnv1a(buf, total - 8) != sum) return fail("it is corrupted (checksum)");
    if (fingerprint != m.fingerprint())
      return fail("it is from another model (other nodes, beams, self-contact settings, group "
                  "pairs or parameters)");

    Reader r(buf + 32, total - 40);
    const uint64_t n_seg = static_cast<uint64_t>(m.table_.segment_count());
    std::vector<double> coords, lo, hi, arc_total;
    ContactState st;
    uint64_t n_pairs;
    if (!r.doubles(coords, 3 * m.used_nodes_.size()) || !r.doubles(lo, n_seg) ||
        !r.doubles(hi, n_seg) || !r.doubles(arc_total, m.beams_.size()) ||
        !r.f64(st.dissipation) || !r.u64(n_pairs))
      return fail("it is corrupted (inconsistent sizes)");
    if (!coords.empty() && coords.size() != 3 * m.used_nodes_.size())
      return fail("it is corrupted (coordinates)");
    for (double v : coords)
      if (!std::isfinite(v) || std::fabs(v) > B2B_COORD_MAX)
        return fail("it holds a committed coordinate that is not finite or beyond B2B_COORD_MAX");
    if (!(lo.size() == hi.size() && (lo.empty() ? arc_total.empty()
                                                : lo.size() == n_seg &&
                                                      arc_total.size() == m.beams_.size())))
      return fail("it is corrupted (arc lengths)");
    bool self = false;
    for (const Beam& b : m.beams_) self = self || b.self_contact;
    // Arc spans are measured by the first update when a beam has
    // self-contact, and saved once committed: with the coordinates.
    if (lo.empty() != (!self || coords.empty()))
      return fail(self ? "it is corrupted (committed coordinates without arc lengths, or the "
                         "reverse)"
                       : "it holds arc lengths but no beam of this model has self-contact");
    if (!arcs_valid(m, lo, hi, arc_total))
      return fail("it holds self-contact arc lengths that are not finite, negative or out of "
                  "order along their beam");
    if (!std::isfinite(st.dissipation) || !(st.dissipation >= 0.0))
      return fail("it holds a total dissipation that is negative or not finite");
    if (coords.empty() && n_pairs > 0) return fail("it is corrupted (pairs without coordinates)");
    if (n_pairs > r.left() / 48) return fail("it is corrupted (pair count)");
    uint64_t last_key = 0;
    for (uint64_t k = 0; k < n_pairs; ++k) {
      uint64_t key, a, b, status, gp, len;
      if (!r.u64(key) || !r.u64(a) || !r.u64(b) || !r.u64(status) || !r.u64(gp) || !r.u64(len))
        return fail("it is corrupted (pair list)");
      if (a >= n_seg || b >= n_seg || a == b ||
          key != pair_key(static_cast<int>(a), static_cast<int>(b)) ||
          (k > 0 && key <= last_key))
        return fail("it is corrupted (pair keys)");
      last_key = key;
      if (status != B2B_CONTACT_ACTIVE && status != B2B_CONTACT_OPEN)
        return fail("it is corrupted (pair status)");
      const int ia = static_cast<int>(a), ib = static_cast<int>(b);
      if (!m.may_pair_with_arcs(ia, ib, lo, hi, arc_total))
        return fail("it holds a pair of segments this model never pairs (the same segment, "
                    "segments sharing a node, groups not paired, or within the self-contact "
                    "exclusion)");
      const int index = m.group_pair_index(ia, ib);  // >= 0: may_pair
      if (gp != static_cast<uint64_t>(index)) return fail("it is corrupted (group pair)");
      const GroupPair& g = m.group_pairs_[static_cast<size_t>(index)];
      // A point pair keeps one history, a line pair n + 1 (1 <= n <= 32).
      const uint64_t hl = static_cast<uint64_t>(g.hist_len);
      const bool len_ok = g.line ? len % hl == 0 && len / hl >= 2 &&
                                       len / hl <= static_cast<uint64_t>(B2B_LINE_POINTS_MAX) + 1
                                 : len == hl;
      if (!len_ok) return fail("it is corrupted (history length)");
      const size_t offset = st.hist.size();
      if (len > r.left() / 8) return fail("it is corrupted (histories)");
      st.hist.resize(offset + len);
      if (!r.bytes(st.hist.data() + offset, 8 * len)) return fail("it is corrupted (histories)");
      for (uint64_t slot = 0; slot < len; slot += hl)
        if (pair::check_history(g.params, st.hist.data() + offset + slot, g.hist_len).problem !=
            pair::HistoryProblem::None)
          return fail("it holds a pair history b2b could not have written");
      st.pairs.push_back(StoredPair{key, ia, ib, static_cast<int>(status), index, offset,
                                    static_cast<int>(len)});
    }
    if (r.left() != 0) return fail("it is corrupted (bytes after the pair list)");
    // Accepted: replace the committed state; the rest starts afresh.
    m.committed_ = std::move(st);
    m.committed_coords_ = std::move(coords);
    // The search's boxes are swept from the committed coordinates
    // (crossing.hpp): search again.
    m.candidates_.clear();
    m.build_coords_.clear();
    m.arcs_committed_ = !lo.empty();
    m.table_.set_arcs(std::move(lo), std::move(hi), std::move(arc_total));
    m.trial_ = ContactState();
    m.migration_.clear();  // [partition] they belonged to the replaced state
    m.updated_ = false;
    m.has_results_ = false;
    m.contacts_.clear();
    m.results_.clear();
    return Problem();
  }
};

uint64_t Model::fingerprint() const {
  uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](const void* p, size_t n) { h = fnv1a(static_cast<const unsigned char*>(p), n, h); };
  auto mix_int = [&mix](int v) { mix(&v, sizeof v); };
  auto mix_double = [&mix](double v) { mix(&v, sizeof v); };
  mix_int(n_nodes_);
  for (const Beam& b : beams_) {
    const size_t n = b.nodes.size();
    mix(&n, sizeof n);
    mix(b.nodes.data(), n * sizeof(int));
    const int flags[4] = {b.closed, b.kind, b.group, b.self_contact};
    mix(flags, sizeof flags);
    mix(&b.radius, sizeof b.radius);
    mix(&b.exclusion, sizeof b.exclusion);
  }
  // [partition] a rank's model: its global ids, ghosts and padding (none in
  // a serial model, whose fingerprint stays what it was)
  const std::vector<int64_t> sig = partition_.signature();
  if (!sig.empty()) mix(sig.data(), sig.size() * sizeof(int64_t));
  // Every group pair with every parameter of its set (field by field: no
  // padding bytes), in the order of the host's group numbers.
  for (const auto& entry : gp_by_host_) {
    const GroupPair& g = group_pairs_[entry.second];
    const pair::Params& p = g.params;
    for (int v : {g.ga, g.gb, g.hist_len, p.law, p.warm_start, p.max_iterations, p.tangent,
                  int(p.penalty_set), int(p.regularization_gap_set),
                  int(p.tangential_penalty_set)})
      mix_int(v);
    for (double v : {p.penalty, p.regularization_gap, p.parallel_angle_deg, p.friction,
                     p.tangential_penalty})
      mix_double(v);
    // The line-contact options (ABI 1.3) only where one differs from its
    // default: a buffer saved before they existed still restores.
    const pair::Params d;
    if (p.contact_type != d.contact_type || p.line_penalty_set || p.line_tangential_penalty_set ||
        p.line_points != d.line_points || p.line_angle_deg != d.line_angle_deg ||
        p.point_angle_deg != d.point_angle_deg) {
      for (int v : {p.contact_type, p.line_points, int(p.line_penalty_set),
                    int(p.line_tangential_penalty_set)})
        mix_int(v);
      for (double v : {p.line_penalty, p.line_tangential_penalty, p.line_angle_deg,
                       p.point_angle_deg})
        mix_double(v);
    }
  }
  return h;
}

int64_t Model::save_size() const {
  Writer w(nullptr);
  RestartCodec::write(*this, w);
  return static_cast<int64_t>(w.size() + 8);
}

void Model::save(unsigned char* buffer) const {
  Writer w(buffer);
  RestartCodec::write(*this, w);
  const uint64_t total = w.size() + 8;
  std::memcpy(buffer + 8, &total, 8);
  const uint64_t sum = fnv1a(buffer, w.size());
  std::memcpy(buffer + w.size(), &sum, 8);
}

Problem Model::restore(const unsigned char* buffer, int64_t size) {
  return RestartCodec::read(*this, buffer, size);
}

}  // namespace model
}  // namespace b2b
