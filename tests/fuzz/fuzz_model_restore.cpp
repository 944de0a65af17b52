// Fuzz target: b2b_model_restore on crafted buffers (structure-aware).
// A short header of the input picks one of a few real scenes (two crossing
// beams with friction and a third group left unpaired; a loop touching
// itself with self-contact; a small network of fibres with rings and a
// second parameter set), and how many steps of it to take and commit; the
// buffer that model saves is the starting point. The rest of the input
// rewrites its fields, knowing the layout (src/model/restart.cpp): counts,
// indices, keys, group-pair indices, history lengths and entries,
// coordinates, arc lengths, the dissipation, with the values at the edges
// (0, -1, 2^64 - 1, n_seg, NaN, +-Inf, 1e308, -1e300, neighbours of the
// real value), pairs duplicated, dropped, or paired with themselves or a
// neighbour; then signs it again with a recomputed checksum (most of the
// time), so that the input reaches the validation behind the checksum.
// Asserts b2b_model.h's contract:
//  - restore returns B2B_OK or B2B_ERR_RANGE;
//  - refused: the model is unchanged (it saves the same bytes as before);
//  - accepted: the buffer is one save could have written (the model saves
//    it back byte for byte), stats are B2B_ERR_STATE until an update, and
//    an update from there returns a documented status with finite outputs.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <b2b/b2b.h>

#include "fuzz_contract.hpp"
#include "fuzz_input.hpp"

using namespace b2b_fuzz;

namespace {

using Bytes = std::vector<unsigned char>;

struct Scene {
  std::vector<std::vector<int>> beams;
  std::vector<int> closed, group, self;
  std::vector<double> radius;
  int kind = B2B_CURVE_LINEAR;
  int n_nodes = 0;
  std::vector<double> x;  // 3 x n_nodes
  std::vector<std::pair<int, int>> pairs;  // group pairs (second set for the odd ones)
  double mu = 0.3;
};

Scene crossing_scene(int kind) {
  Scene s;
  s.kind = kind;
  s.beams = {{0, 1, 2, 3}, {4, 5, 6}, {7, 8}};
  s.closed = {0, 0, 0};
  s.group = {0, 1, 2};
  s.self = {0, 0, 0};
  s.radius = {0.1, 0.1, 0.1};
  s.n_nodes = 9;
  const double p[9][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {0.5, -1, 0.15},
                          {0.6, 0, 0.15}, {0.7, 1, 0.15}, {10, 10, 10}, {11, 10, 10}};
  for (auto& q : p) s.x.insert(s.x.end(), q, q + 3);
  s.pairs = {{0, 1}};
  return s;
}

Scene loop_scene(int kind) {
  Scene s;
  s.kind = kind;
  const int n = 33;
  std::vector<int> nodes(n);
  for (int k = 0; k < n; ++k) {
    nodes[k] = k;
    const double t = -1.6 + 3.2 * k / (n - 1);
    s.x.insert(s.x.end(), {t * t - 1.0, t * (t * t - 1.0), t * 0.04});
  }
  s.beams = {nodes};
  s.closed = {0};
  s.group = {3};
  s.self = {1};
  s.radius = {0.05};
  s.n_nodes = n;
  s.pairs = {{3, 3}};
  return s;
}

Scene network_scene(int kind) {
  Scene s;
  s.kind = kind;
  int next = 0;
  for (int b = 0; b < 6; ++b) {
    const int n = 5;
    std::vector<int> nodes;
    const bool ring = b % 3 == 2;
    for (int k = 0; k < n; ++k) {
      nodes.push_back(next + k);
      const double t = static_cast<double>(k) / (n - 1);
      if (ring) {
        const double a = 2 * M_PI * k / n;
        s.x.insert(s.x.end(), {0.8 * std::cos(a) + 0.2 * b, 0.8 * std::sin(a), 0.05 * b});
      } else {
        const double ang = 0.7 * b;
        s.x.insert(s.x.end(), {2 * (t - 0.5) * std::cos(ang), 2 * (t - 0.5) * std::sin(ang),
                               0.17 * b});
      }
    }
    next += n;
    s.beams.push_back(nodes);
    s.closed.push_back(ring ? 1 : 0);
    s.group.push_back(b % 2);
    s.self.push_back(ring ? 1 : 0);
    s.radius.push_back(0.1);
  }
  s.n_nodes = next;
  s.pairs = {{0, 0}, {0, 1}, {1, 1}};
  return s;
}

b2b_model* build(const Scene& s, b2b_params* const sets[2]) {
  b2b_model* m = nullptr;
  if (b2b_model_create(&m, nullptr, 0) != B2B_OK) return nullptr;
  for (size_t b = 0; b < s.beams.size(); ++b) {
    int id;
    FUZZ_REQUIRE(b2b_model_add_beam(m, s.beams[b].data(), static_cast<int>(s.beams[b].size()),
                                    s.closed[b], s.radius[b], s.kind, s.group[b], &id, nullptr,
                                    0) == B2B_OK,
                 "add_beam");
    if (s.self[b]) b2b_model_set_self_contact(m, id, 1, -1.0, nullptr, 0);
  }
  for (size_t k = 0; k < s.pairs.size(); ++k)
    FUZZ_REQUIRE(b2b_model_set_group_pair(m, s.pairs[k].first, s.pairs[k].second, sets[k % 2],
                                          nullptr, 0) == B2B_OK,
                 "set_group_pair");
  FUZZ_REQUIRE(b2b_model_finalize(m, s.n_nodes, nullptr, 0) == B2B_OK, "finalize");
  return m;
}

Bytes save(const b2b_model* m) {
  int64_t n = 0;
  FUZZ_REQUIRE(b2b_model_save_size(m, &n, nullptr, 0) == B2B_OK && n > 0, "save_size");
  Bytes b(static_cast<size_t>(n));
  FUZZ_REQUIRE(b2b_model_save(m, b.data(), n, nullptr, 0) == B2B_OK, "save");
  return b;
}

uint64_t fnv1a(const unsigned char* p, size_t n) {
  uint64_t h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

uint64_t get(const Bytes& b, size_t at) {
  uint64_t v = 0;
  if (at + 8 <= b.size()) std::memcpy(&v, b.data() + at, 8);
  return v;
}
void put(Bytes& b, size_t at, uint64_t v) {
  if (at + 8 <= b.size()) std::memcpy(b.data() + at, &v, 8);
}
void put_double(Bytes& b, size_t at, double v) {
  uint64_t u;
  std::memcpy(&u, &v, 8);
  put(b, at, u);
}
double get_double(const Bytes& b, size_t at) {
  const uint64_t u = get(b, at);
  double v;
  std::memcpy(&v, &u, 8);
  return v;
}

// Where the fields are (the layout of restart.cpp), for a buffer that
// still has its saved shape.
struct Layout {
  std::vector<size_t> arrays;  // count fields: coordinates, lo, hi, total
  size_t dissipation = 0, n_pairs = 0;
  std::vector<size_t> pairs;   // each pair's first field
  std::vector<size_t> doubles; // every double of the arrays and histories
  bool ok = false;
};

Layout parse(const Bytes& b) {
  Layout l;
  size_t at = 32;
  for (int k = 0; k < 4; ++k) {
    if (at + 8 > b.size()) return l;
    const uint64_t n = get(b, at);
    if (n > b.size() / 8 || at + 16 + 8 * n > b.size()) return l;
    l.arrays.push_back(at);
    for (uint64_t i = 0; i < n; ++i) l.doubles.push_back(at + 8 + 8 * i);
    at += 8 + 8 * n;
  }
  l.dissipation = at;
  l.doubles.push_back(at);
  l.n_pairs = at + 8;
  at += 16;
  if (at + 8 > b.size()) return l;
  const uint64_t np = get(b, l.n_pairs);
  for (uint64_t k = 0; k < np && at + 48 <= b.size(); ++k) {
    l.pairs.push_back(at);
    const uint64_t len = get(b, at + 40);
    if (len > 64 || at + 56 + 8 * len > b.size()) return l;
    for (uint64_t i = 0; i < len; ++i) l.doubles.push_back(at + 48 + 8 * i);
    at += 48 + 8 * len;
  }
  l.ok = true;
  return l;
}

uint64_t key_of(uint64_t a, uint64_t b) {
  const uint64_t lo = static_cast<uint32_t>(a < b ? a : b), hi = static_cast<uint32_t>(a < b ? b : a);
  return lo << 32 | hi;
}

uint64_t edge_u64(FuzzInput& in, uint64_t real, uint64_t n_seg) {
  switch (in.pick(10)) {
    case 0: return 0;
    case 1: return UINT64_MAX;
    case 2: return real + 1;
    case 3: return real - 1;
    case 4: return n_seg;
    case 5: return n_seg - 1;
    case 6: return 1ULL << 32;
    case 7: return static_cast<uint64_t>(in.pick(static_cast<int>(n_seg) + 2));
    case 8: return 1ULL << 63;
    default: return in.u64();
  }
}

double edge_double(FuzzInput& in, double real) {
  switch (in.pick(8)) {
    case 0: return std::nextafter(real, HUGE_VAL);
    case 1: return std::nextafter(real, -HUGE_VAL);
    case 2: return -real;
    case 3: return real * in.uniform(-3, 3);
    case 4: return real + in.uniform(-1, 1);
    case 5: return B2B_COORD_MAX * (in.flag() ? 1.0 : 1.0000001);
    default: return in.wild();
  }
}

// One rewrite of the buffer, chosen by the input.
void mutate(FuzzInput& in, Bytes& b, uint64_t n_seg) {
  const Layout l = parse(b);
  if (!l.ok) {
    if (!b.empty()) b[in.pick(static_cast<int>(b.size()))] ^= static_cast<unsigned char>(1 + in.pick(255));
    return;
  }
  switch (in.pick(9)) {
    case 0: {  // a pair's field (keys kept consistent most of the time)
      if (l.pairs.empty()) break;
      const size_t p = l.pairs[in.pick(static_cast<int>(l.pairs.size()))];
      const int field = in.pick(6);
      put(b, p + 8 * field, edge_u64(in, get(b, p + 8 * field), n_seg));
      if (field == 1 || field == 2)
        if (in.chance(200)) put(b, p, key_of(get(b, p + 8), get(b, p + 16)));
      break;
    }
    case 1: {  // a pair that the model never forms: itself, a neighbour, any
      if (l.pairs.empty()) break;
      const size_t p = l.pairs[in.pick(static_cast<int>(l.pairs.size()))];
      const uint64_t a = get(b, p + 8);
      const uint64_t partner = in.pick(3) == 0 ? a : in.flag() ? a + 1 : a - 1;
      const uint64_t other = in.chance(64) ? static_cast<uint64_t>(in.pick(static_cast<int>(n_seg))) : partner;
      put(b, p + 16, other);
      put(b, p, key_of(a, other));
      break;
    }
    case 2: {  // a double (coordinates, arcs, dissipation, history)
      if (l.doubles.empty()) break;
      const size_t at = l.doubles[in.pick(static_cast<int>(l.doubles.size()))];
      put_double(b, at, edge_double(in, get_double(b, at)));
      break;
    }
    case 3:  // the dissipation
      put_double(b, l.dissipation, edge_double(in, get_double(b, l.dissipation)));
      break;
    case 4: {  // an array's count
      const size_t at = l.arrays[in.pick(static_cast<int>(l.arrays.size()))];
      put(b, at, edge_u64(in, get(b, at), n_seg));
      break;
    }
    case 5:  // the pair count
      put(b, l.n_pairs, edge_u64(in, get(b, l.n_pairs), n_seg));
      break;
    case 6: {  // a pair duplicated (inserted after itself) or dropped
      if (l.pairs.empty()) break;
      const size_t k = static_cast<size_t>(in.pick(static_cast<int>(l.pairs.size())));
      const size_t from = l.pairs[k];
      const size_t to = k + 1 < l.pairs.size() ? l.pairs[k + 1] : b.size() - 8;
      Bytes rec(b.begin() + static_cast<std::ptrdiff_t>(from), b.begin() + static_cast<std::ptrdiff_t>(to));
      if (in.flag()) {
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(to), rec.begin(), rec.end());
        put(b, l.n_pairs, get(b, l.n_pairs) + 1);
      } else {
        b.erase(b.begin() + static_cast<std::ptrdiff_t>(from), b.begin() + static_cast<std::ptrdiff_t>(to));
        put(b, l.n_pairs, get(b, l.n_pairs) - 1);
      }
      put(b, 8, b.size());
      break;
    }
    case 7: {  // an array emptied (count 0, its doubles gone)
      const size_t k = static_cast<size_t>(in.pick(4));
      const size_t at = l.arrays[k];
      const uint64_t n = get(b, at);
      b.erase(b.begin() + static_cast<std::ptrdiff_t>(at + 8),
              b.begin() + static_cast<std::ptrdiff_t>(at + 8 + 8 * n));
      put(b, at, 0);
      put(b, 8, b.size());
      break;
    }
    default: {  // a header field or any byte
      if (in.flag()) {
        const size_t at = 8 * (1 + static_cast<size_t>(in.pick(3)));
        put(b, at, edge_u64(in, get(b, at), b.size()));
      } else {
        b[in.pick(static_cast<int>(b.size()))] ^= static_cast<unsigned char>(1 + in.pick(255));
      }
      break;
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzInput in(data, size);
  const int which = in.pick(3);
  const int kind = in.pick(B2B_CURVE_KIND_COUNT);
  const Scene s = which == 0 ? crossing_scene(kind) : which == 1 ? loop_scene(kind) : network_scene(kind);
  b2b_params* sets[2] = {nullptr, nullptr};
  for (int k = 0; k < 2; ++k) {
    b2b_params_create(&sets[k], nullptr, 0);
    b2b_params_set_real(sets[k], "penalty", k ? 2e3 : 1e3, nullptr, 0);
    b2b_params_set_real(sets[k], "friction", k ? 0.0 : s.mu, nullptr, 0);
    if (k == 0) b2b_params_set_real(sets[k], "tangential_penalty", 1e3, nullptr, 0);
    FUZZ_REQUIRE(b2b_params_finalize(sets[k], nullptr, 0) == B2B_OK, "params_finalize");
  }
  b2b_model* m = build(s, sets);
  b2b_model* twin = build(s, sets);
  // Steps: each moves the beams a little, updates and (mostly) commits.
  std::vector<double> x = s.x;
  const int steps = in.pick(4);
  for (int k = 0; k < steps; ++k) {
    for (size_t i = 0; i < x.size(); ++i) x[i] += 0.01 * ((i * 7 + k * 3) % 5 - 2);
    if (b2b_model_update(m, x.data(), 3, s.n_nodes, 0, nullptr, 0) != B2B_OK) break;
    if (in.pick(4) != 0) b2b_model_commit(m, nullptr, 0);
  }
  b2b_model_revert(m, nullptr, 0);
  const Bytes real = save(m);
  int n_seg = 0;
  for (size_t b = 0; b < s.beams.size(); ++b) {
    int c = 0;
    b2b_beam_segment_count(s.kind, static_cast<int>(s.beams[b].size()), s.closed[b], &c, nullptr, 0);
    n_seg += c;
  }
  // The twin holds the real state; the crafted buffer goes to it.
  FUZZ_REQUIRE(b2b_model_restore(twin, real.data(), static_cast<int64_t>(real.size()), nullptr, 0) ==
                   B2B_OK,
               "the real buffer is refused");
  Bytes crafted = real;
  const int n_mut = 1 + in.pick(4);
  for (int k = 0; k < n_mut && !crafted.empty(); ++k) mutate(in, crafted, static_cast<uint64_t>(n_seg));
  if (crafted.size() >= 40 && in.pick(8) != 0) {  // signed again: the checksum holds
    if (in.pick(4) != 0) put(crafted, 8, crafted.size());
    const uint64_t total = get(crafted, 8);
    if (total >= 16 && total <= crafted.size()) put(crafted, total - 8, fnv1a(crafted.data(), total - 8));
  }
  const Bytes before = save(twin);
  char msg[B2B_ERRMSG_LEN];
  const int rc = b2b_model_restore(twin, crafted.data(), static_cast<int64_t>(crafted.size()), msg,
                                   sizeof msg);
  trace("restore of a crafted buffer (%zu bytes, scene %d, kind %d): %d %s\n", crafted.size(),
        which, kind, rc, rc ? msg : "");
  FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE}), "restore returned %d", rc);
  if (rc != B2B_OK) {
    const Bytes after = save(twin);
    FUZZ_REQUIRE(after == before, "a refused restore (%s) changed the model", msg);
  } else {
    const Bytes back = save(twin);
    const uint64_t total = get(crafted, 8);
    FUZZ_REQUIRE(back.size() == total && std::memcmp(back.data(), crafted.data(), back.size()) == 0,
                 "an accepted buffer is not what save writes back");
    FUZZ_REQUIRE(b2b_model_stats(twin, nullptr, nullptr, nullptr, 0) == B2B_ERR_STATE,
                 "stats after restore");
    const int up = b2b_model_update(twin, x.data(), 3, s.n_nodes, 1, msg, sizeof msg);
    FUZZ_REQUIRE(status_in(up, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_NONFINITE, B2B_ERR_COINCIDENT,
                                B2B_ERR_FOLDED}),
                 "update after an accepted restore returned %d (%s)", up, msg);
    if (up == B2B_OK) {
      int counts[B2B_MODEL_COUNTS_LEN];
      double totals[B2B_MODEL_TOTALS_LEN];
      FUZZ_REQUIRE(b2b_model_stats(twin, counts, totals, nullptr, 0) == B2B_OK, "stats");
      FUZZ_REQUIRE(all_finite(totals, B2B_MODEL_TOTALS_LEN), "non-finite totals after restore");
      FUZZ_REQUIRE(b2b_model_commit(twin, nullptr, 0) == B2B_OK, "commit");
      const Bytes again = save(twin);
      FUZZ_REQUIRE(b2b_model_restore(twin, again.data(), static_cast<int64_t>(again.size()),
                                     nullptr, 0) == B2B_OK,
                   "the model refuses its own buffer");
    }
  }
  b2b_model_destroy(&m);
  b2b_model_destroy(&twin);
  b2b_params_destroy(&sets[0]);
  b2b_params_destroy(&sets[1]);
  return 0;
}
