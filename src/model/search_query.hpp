// BoxTree::overlapping_pairs: the parallel self-join over the hierarchy.
// Fixed chunks of sorted positions, each with its own output, concatenated in
// chunk order and sorted: the result does not depend on the thread count.
#pragma once

#include <algorithm>

#ifdef B2B_HAVE_OPENMP
#include <omp.h>
#endif

namespace b2b {
namespace model {

template <class Accept>
void BoxTree::overlapping_pairs(Accept accept, int threads,
                                std::vector<std::pair<int, int>>& out) const {
  out.clear();
  const int n = static_cast<int>(order_.size());
  constexpr int kChunk = 4096;
  const int n_chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::vector<std::pair<int, int>>> parts(n_chunks);
#ifdef B2B_HAVE_OPENMP
  const int nt = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(nt) if (n_chunks > 1)
#else
  (void)threads;
#endif
  for (int c = 0; c < n_chunks; ++c) {
    Accept local = accept;
    const int end = std::min(n, (c + 1) * kChunk);
    for (int p = c * kChunk; p < end; ++p) query(p, local, parts[c]);
  }
  size_t total = 0;
  for (const auto& part : parts) total += part.size();
  out.reserve(total);
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  std::sort(out.begin(), out.end());
}

}  // namespace model
}  // namespace b2b
