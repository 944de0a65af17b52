// Pair histories kept by the model between updates: the committed state (of
// the last commit) and the trial state (of the last update), each a list of
// pairs sorted by their canonical key with one history each.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace b2b {
namespace model {

// Canonical key of a pair of segments: the smaller index in the high word.
inline uint64_t pair_key(int a, int b) {
  const uint64_t lo = static_cast<uint32_t>(a < b ? a : b), hi = static_cast<uint32_t>(a < b ? b : a);
  return lo << 32 | hi;
}

struct StoredPair {
  uint64_t key;
  int a, b;         // oriented: a is the element's beam A (not always the smaller)
  int status;       // B2B_CONTACT_ACTIVE or _OPEN when stored
  int group_pair;   // index of its parameter set
  size_t offset;    // of its history in ContactState::hist
  int length;       // history length
};

struct ContactState {
  std::vector<StoredPair> pairs;  // sorted by key
  std::vector<double> hist;
  double dissipation = 0.0;       // total dissipation up to this state

  const StoredPair* find(uint64_t key) const {
    auto it = std::lower_bound(pairs.begin(), pairs.end(), key,
                               [](const StoredPair& p, uint64_t k) { return p.key < k; });
    return (it != pairs.end() && it->key == key) ? &*it : nullptr;
  }
  const double* history(const StoredPair& p) const { return hist.data() + p.offset; }
  void clear() {
    pairs.clear();
    hist.clear();
    dissipation = 0.0;
  }
};

}  // namespace model
}  // namespace b2b
