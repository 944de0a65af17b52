#include "segment_cache.hpp"

#include <algorithm>

#include "segment_geometry.hpp"

namespace b2b {
namespace model {

namespace {

// The cache's tags alone: how many requests of a sequence would miss.
class CacheSimulation {
 public:
  explicit CacheSimulation(int sets) : sets_(sets), tag_(2 * sets, -1), recent_(sets, 0) {}
  // Requests segment s (keep: the way the caller holds, or -1); returns the
  // way that holds it now.
  int request(int s, int keep, int64_t& misses) {
    const int set = static_cast<int>(static_cast<unsigned>(s) & static_cast<unsigned>(sets_ - 1));
    for (int w = 0; w < 2; ++w)
      if (tag_[2 * set + w] == s) {
        recent_[set] = static_cast<uint8_t>(w);
        return 2 * set + w;
      }
    ++misses;
    int victim = recent_[set] == 0 ? 1 : 0;
    if (2 * set + victim == keep) victim = 1 - victim;
    tag_[2 * set + victim] = s;
    recent_[set] = static_cast<uint8_t>(victim);
    return 2 * set + victim;
  }

 private:
  int sets_;
  std::vector<int> tag_;
  std::vector<uint8_t> recent_;
};

}  // namespace

int SegmentCache::choose_sets(const PairRows& candidates, int n_segments, int threads) {
  constexpr int kMinSets = 32;
  // The memory bound: all threads' caches together at most about 64 bytes
  // per candidate pair (an entry is about 2 kB), and no more entries than
  // segments.
  const int64_t max_entries =
      std::min<int64_t>(n_segments, static_cast<int64_t>(candidates.size()) /
                                        (32 * static_cast<int64_t>(std::max(threads, 1))));
  int max_sets = kMinSets;
  while (2 * (2 * static_cast<int64_t>(max_sets)) <= max_entries) max_sets *= 2;
  if (max_sets == kMinSets) return kMinSets;
  // Eight windows of 16384 consecutive candidates, spread over the list
  // (one, the whole list, when it is shorter): long enough for a window's
  // first misses to matter little, short enough that a cache holding every
  // segment of a small model does not look better than it would on a
  // large one.
  constexpr size_t kWindow = 16384, kWindows = 8;
  const size_t n = candidates.size();
  const size_t windows = n <= kWindow ? 1 : kWindows;
  std::vector<int> sizes;
  std::vector<int64_t> misses;
  for (int sets = kMinSets; sets <= max_sets; sets *= 2) {
    int64_t m = 0;
    for (size_t w = 0; w < windows; ++w) {
      const size_t begin = windows == 1 ? 0 : w * ((n - kWindow) / (kWindows - 1));
      const size_t end = std::min(n, begin + kWindow);
      CacheSimulation sim(sets);
      const int64_t* start = candidates.start.data();
      const int* partner = candidates.partner.data();
      int a = begin < n ? candidates.row_of(begin) : 0;
      for (size_t k = begin; k < end; ++k) {
        while (static_cast<size_t>(start[a + 1]) <= k) ++a;
        const int held = sim.request(a, -1, m);
        sim.request(partner[k], held, m);
      }
    }
    sizes.push_back(sets);
    misses.push_back(m);
  }
  const int64_t best = misses.back();
  for (size_t i = 0; i < sizes.size(); ++i)
    if (misses[i] <= best + best / 4) return sizes[i];
  return sizes.back();
}

void SegmentCache::reset(int sets) {
  if (sets != sets_) {
    entries_.clear();
    entries_.shrink_to_fit();
    sets_ = sets;
  }
  for (Entry& e : entries_) e.segment = -1;
}

const SegmentCache::Entry* SegmentCache::get(int s, const Entry* keep, const SegmentInfo& info,
                                             const double* coords, const NodeIndex& used_index,
                                             curve::Failure& fail) {
  if (entries_.empty()) {
    entries_.resize(static_cast<size_t>(sets_) * kWays);
    recent_.assign(sets_, 0);
  }
  const int set = static_cast<int>(static_cast<unsigned>(s) & static_cast<unsigned>(sets_ - 1));
  Entry* way = &entries_[kWays * set];
  for (int w = 0; w < kWays; ++w)
    if (way[w].segment == s) {
      recent_[set] = static_cast<uint8_t>(w);
      return &way[w];
    }
  // The way not used last, unless the caller holds it.
  int victim = recent_[set] == 0 ? 1 : 0;
  if (&way[victim] == keep) victim = 1 - victim;
  Entry& e = way[victim];
  e.segment = -1;
  gather_patch(info, coords, used_index, e.X);
  fail = build_segment_from_patch(info, e.X, e.built, true);
  if (fail.status) return nullptr;
  e.segment = s;
  recent_[set] = static_cast<uint8_t>(victim);
  return &e;
}

}  // namespace model
}  // namespace b2b
