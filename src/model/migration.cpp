#include "migration.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <b2b/b2b.h>

#include "../pair/history.hpp"
#include "../pair/history_check.hpp"
#include "model.hpp"

namespace b2b {
namespace model {

namespace {

constexpr char kMagic[8] = {'B', '2', 'B', 'M', 'I', 'G', 'R', '1'};
constexpr uint64_t kVersion = 1;
constexpr size_t kHeader = 128;  // bytes before the history
constexpr int kMaxHops = 1000;   // the largest "max_handover_hops"

uint64_t fnv1a(const unsigned char* p, size_t n, uint64_t h = 1469598103934665603ULL) {
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

// Every parameter of a group pair's set that changes what a history means
// or how it is used (field by field: no padding bytes).
uint64_t params_fingerprint(const GroupPair& g) {
  uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](const void* p, size_t n) { h = fnv1a(static_cast<const unsigned char*>(p), n, h); };
  const pair::Params& p = g.params;
  for (int v : {g.ga, g.gb, g.hist_len, p.law, p.warm_start, p.max_iterations, p.tangent,
                p.contact_type, p.line_points})
    mix(&v, sizeof v);
  for (double v : {p.penalty, p.regularization_gap, p.parallel_angle_deg, p.friction,
                   p.tangential_penalty, p.line_penalty, p.line_tangential_penalty,
                   p.line_angle_deg, p.point_angle_deg})
    mix(&v, sizeof v);
  return h;
}

bool same_ids(const int64_t* x, const int64_t* y) {
  return std::equal(x, x + 4, y);
}

bool same_contact(const Migrant& x, const Migrant& y) {
  return same_ids(x.source, y.source) && same_ids(x.target, y.target) && x.hops == y.hops &&
         x.ga == y.ga && x.gb == y.gb && x.hist.size() == y.hist.size() &&
         (x.hist.empty() ||
          std::memcmp(x.hist.data(), y.hist.data(), x.hist.size() * sizeof(double)) == 0);
}

bool source_less(const int64_t* x, const int64_t* y) {
  return std::lexicographical_compare(x, x + 4, y, y + 4);
}

Problem fail(const char* detail) {
  Problem pb;
  pb.status = B2B_ERR_RANGE;
  pb.what = Problem::What::Migration;
  pb.detail = detail;
  return pb;
}

}  // namespace

bool Migration::receive(Received r) {
  auto it = std::lower_bound(received.begin(), received.end(), r.m.source,
                             [](const Received& x, const int64_t* s) {
                               return source_less(x.m.source, s);
                             });
  if (it != received.end() && same_ids(it->m.source, r.m.source)) {
    const bool changed = !same_contact(it->m, r.m);
    *it = std::move(r);
    return changed;
  }
  received.insert(it, std::move(r));
  return true;
}

bool Migration::end_round() {
  const size_t before = received.size();
  received.erase(std::remove_if(received.begin(), received.end(),
                                [this](const Received& r) { return r.epoch < updates; }),
                 received.end());
  return received.size() != before;
}

Migrant make_migrant(const BeamTable& table, const Partition& part, int sa, int sb,
                     const Migration::Received* from, int a, int b, int hops, int ga, int gb,
                     const double* hist, int hist_len) {
  Migrant mg;
  const int ends[4] = {sa, sb, a, b};
  for (int k = 0; k < 4; ++k) {
    const SegmentInfo& s = table.segment(ends[k]);
    int64_t* ids = k < 2 ? mg.source + 2 * k : mg.target + 2 * (k - 2);
    ids[0] = part.global_beam(s);
    ids[1] = part.global_segment(s);
  }
  if (from) std::copy(from->m.source, from->m.source + 4, mg.source);
  mg.hops = hops;
  mg.ga = ga;
  mg.gb = gb;
  mg.hist.assign(hist, hist + hist_len);
  return mg;
}

const Migration::Received* CommittedView::received(const Migration& mig, uint64_t key) const {
  auto it = std::lower_bound(received_at.begin(), received_at.end(),
                             std::pair<uint64_t, int>(key, -1));
  return it != received_at.end() && it->first == key ? &mig.received[it->second] : nullptr;
}

void build_view(const ContactState& committed, const Migration& mig, CommittedView& view) {
  view.received_at.clear();
  view.conflicts = 0;
  if (mig.received.empty()) {
    view.state = &committed;
    return;
  }
  // The received by target, then source: the first of a target wins.
  std::vector<int> order(mig.received.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&mig](int x, int y) {
    const Migration::Received &p = mig.received[x], &q = mig.received[y];
    return p.key != q.key ? p.key < q.key : source_less(p.m.source, q.m.source);
  });
  ContactState& w = view.with;
  w.pairs.clear();
  w.pairs.reserve(committed.pairs.size() + order.size());
  w.hist = committed.hist;
  w.dissipation = committed.dissipation;
  size_t c = 0;
  for (size_t k = 0; k < order.size(); ++k) {
    const Migration::Received& r = mig.received[order[k]];
    if (k > 0 && mig.received[order[k - 1]].key == r.key) {
      ++view.conflicts;
      continue;
    }
    while (c < committed.pairs.size() && committed.pairs[c].key < r.key)
      w.pairs.push_back(committed.pairs[c++]);
    if (c < committed.pairs.size() && committed.pairs[c].key == r.key) {
      // its own active contact stays (merged); an open one is replaced
      if (committed.pairs[c].status == B2B_CONTACT_ACTIVE) continue;
      ++c;
    }
    w.pairs.push_back(StoredPair{r.key, r.a, r.b, B2B_CONTACT_ACTIVE, r.group_pair, w.hist.size(),
                                 static_cast<int>(r.m.hist.size())});
    w.hist.insert(w.hist.end(), r.m.hist.begin(), r.m.hist.end());
    view.received_at.emplace_back(r.key, order[k]);
  }
  while (c < committed.pairs.size()) w.pairs.push_back(committed.pairs[c++]);
  view.state = &w;
}

int64_t MigrationCodec::packed_size(const Migrant& m) {
  return static_cast<int64_t>(kHeader + 8 * m.hist.size() + 8);
}

void MigrationCodec::pack(const Model& model, const Migrant& m, unsigned char* out) {
  const GroupPair* g = model.group_pair(m.ga, m.gb);
  const uint64_t total = static_cast<uint64_t>(packed_size(m));
  const uint64_t version = kVersion, fp = g ? params_fingerprint(*g) : 0;
  const int64_t head[3] = {m.hops, m.ga, m.gb};
  const uint64_t len = m.hist.size();
  std::memcpy(out, kMagic, 8);
  std::memcpy(out + 8, &total, 8);
  std::memcpy(out + 16, &version, 8);
  std::memcpy(out + 24, m.source, 32);
  std::memcpy(out + 56, m.target, 32);
  std::memcpy(out + 88, head, 24);
  std::memcpy(out + 112, &fp, 8);
  std::memcpy(out + 120, &len, 8);
  if (len) std::memcpy(out + kHeader, m.hist.data(), 8 * len);
  const uint64_t sum = fnv1a(out, total - 8);
  std::memcpy(out + total - 8, &sum, 8);
}

Problem MigrationCodec::unpack(Model& model, const unsigned char* buf, int64_t size,
                               bool* changed) {
  if (size < static_cast<int64_t>(kHeader + 8)) return fail("it is truncated (shorter than its header)");
  if (std::memcmp(buf, kMagic, 8) != 0) return fail("it is not a packed b2b contact");
  uint64_t total, version, len, fp, sum;
  std::memcpy(&total, buf + 8, 8);
  std::memcpy(&version, buf + 16, 8);
  std::memcpy(&len, buf + 120, 8);
  if (version != kVersion) return fail("it has an unknown format version");
  if (total != static_cast<uint64_t>(size))
    return fail("its size does not match the size it records (truncated, or bytes after it)");
  if (len > static_cast<uint64_t>(pair::kHistoryLengthMax) || total != kHeader + 8 * len + 8)
    return fail("it is corrupted (history length)");
  std::memcpy(&sum, buf + total - 8, 8);
  if (fnv1a(buf, total - 8) != sum) return fail("it is corrupted (checksum)");
  Migrant m;
  int64_t head[3];
  std::memcpy(m.source, buf + 24, 32);
  std::memcpy(m.target, buf + 56, 32);
  std::memcpy(head, buf + 88, 24);
  std::memcpy(&fp, buf + 112, 8);
  for (int k = 0; k < 4; ++k)
    if (m.source[k] < 0 || m.target[k] < 0 || m.source[k] > INT32_MAX ||
        m.target[k] > INT32_MAX)
      return fail("it is corrupted (a global id out of range)");
  if (head[0] < 0 || head[0] > kMaxHops) return fail("it is corrupted (hop count)");
  if (head[1] < 0 || head[1] > INT32_MAX || head[2] < 0 || head[2] > INT32_MAX)
    return fail("it is corrupted (groups)");
  m.hops = static_cast<int>(head[0]);
  m.ga = static_cast<int>(head[1]);
  m.gb = static_cast<int>(head[2]);
  const Partition& part = model.partition_;
  const int a = part.local_segment(model.beams_, m.target[0], m.target[1]);
  const int b = part.local_segment(model.beams_, m.target[2], m.target[3]);
  if (a < 0 || b < 0) return fail("its target pair is not held by this model");
  if (a == b) return fail("it is corrupted (its target pairs a segment with itself)");
  if (!part.evaluates(a, b))
    return fail("its target pair is not one this model evaluates (another rank owns its "
                "smaller segment, or the other one is padding here)");
  if (!model.may_pair(a, b))
    return fail("its target pair is one this model never pairs (groups not paired, a shared "
                "node, one global beam)");
  const int index = model.group_pair_index(a, b);
  const GroupPair& g = model.group_pairs_[static_cast<size_t>(index)];
  const int ga = std::min(m.ga, m.gb), gb = std::max(m.ga, m.gb);
  if (ga != g.ga || gb != g.gb) return fail("its groups are not those of its target pair");
  if (g.line) return fail("its target is a line-contact pair (line contacts do not migrate)");
  if (fp != params_fingerprint(g))
    return fail("its group pair's parameters differ from this model's");
  if (len != static_cast<uint64_t>(g.hist_len))
    return fail("its history length does not match the group pair's");
  m.hist.resize(len);
  std::memcpy(m.hist.data(), buf + kHeader, 8 * len);
  if (pair::check_history(g.params, m.hist.data(), g.hist_len).problem !=
      pair::HistoryProblem::None)
    return fail("it holds a history b2b could not have written");
  Migration::Received r;
  r.m = std::move(m);
  r.a = a;
  r.b = b;
  r.group_pair = index;
  r.key = pair_key(a, b);
  r.epoch = model.migration_.updates;
  *changed = model.migration_.receive(std::move(r));
  return Problem();
}

}  // namespace model
}  // namespace b2b
