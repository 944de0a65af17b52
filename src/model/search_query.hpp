// BoxTree::overlapping_pairs: the parallel self-join. Fixed chunks of Morton
// positions, each with its own output, then every query's partners put in
// place by box index: the result does not depend on the thread count.
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
  std::vector<QueryPart> parts(n_chunks);
#ifdef B2B_HAVE_OPENMP
  const int nt = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(nt) if (n_chunks > 1)
#else
  (void)threads;
#endif
  for (int c = 0; c < n_chunks; ++c) {
    Accept local = accept;
    QueryPart& part = parts[c];
    const int end = std::min(n, (c + 1) * kChunk);
    for (int q = c * kChunk; q < end; ++q) {
      const int i = order_[q];
      const size_t start = part.partners.size();
      partners(i, local, part.partners);
      if (part.partners.size() == start) continue;
      std::sort(part.partners.begin() + static_cast<std::ptrdiff_t>(start), part.partners.end());
      part.box.push_back(i);
      part.count.push_back(static_cast<int>(part.partners.size() - start));
    }
  }
  place(parts, out);
}

}  // namespace model
}  // namespace b2b
