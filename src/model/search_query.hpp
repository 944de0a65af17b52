// BoxTree::overlapping_pairs: the parallel self-join. Fixed chunks of
// consecutive boxes, each with its own output, copied in order into place:
// the result does not depend on the thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>

#ifdef B2B_HAVE_OPENMP
#include <omp.h>
#endif

namespace b2b {
namespace model {

#ifdef B2B_HAVE_OPENMP
inline int BoxTree::search_threads(int threads) {
  return threads > 0 ? threads : omp_get_max_threads();
}
#endif

template <class Accept>
int BoxTree::query_chunks(Accept& accept, int threads) {
  const int n = boxes_ ? static_cast<int>(boxes_->size()) : 0;
  const int n_chunks = (n + kQueryChunk - 1) / kQueryChunk;
  if (static_cast<int>(chunks_.size()) < n_chunks) chunks_.resize(n_chunks);
  // No exception may leave a parallel region (std::terminate): a chunk that
  // throws (std::bad_alloc, or accept's own) keeps its exception, the others
  // stop early, and the exception of the first such chunk is rethrown here.
  std::vector<std::exception_ptr> thrown(static_cast<size_t>(n_chunks));
  std::atomic<bool> stop{false};
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel for schedule(dynamic, 1) num_threads(search_threads(threads)) if (n_chunks > 1)
#else
  (void)threads;
#endif
  for (int c = 0; c < n_chunks; ++c) {
    if (stop.load(std::memory_order_relaxed)) continue;
    try {
      Accept local = accept;
      Chunk& chunk = chunks_[c];
      chunk.count.clear();
      chunk.partners.clear();
      if (chunk.partners.capacity() < chunk.released) chunk.partners.reserve(chunk.released);
      const int end = std::min(n, (c + 1) * kQueryChunk);
      for (int i = c * kQueryChunk; i < end && !stop.load(std::memory_order_relaxed); ++i) {
        const size_t start = chunk.partners.size();
        partners(i, local, chunk.partners);
        std::sort(chunk.partners.begin() + static_cast<std::ptrdiff_t>(start),
                  chunk.partners.end());
        chunk.count.push_back(static_cast<int>(chunk.partners.size() - start));
      }
    } catch (...) {
      thrown[c] = std::current_exception();
      stop = true;
    }
  }
  for (const std::exception_ptr& e : thrown)
    if (e) std::rethrow_exception(e);
  return n_chunks;
}

template <class Accept>
void BoxTree::overlapping_pairs(Accept accept, int threads,
                                std::vector<std::pair<int, int>>& out) {
  out.clear();
  gather(query_chunks(accept, threads), threads, out);
}

template <class Accept>
void BoxTree::overlapping_pairs(Accept accept, int threads, PairRows& out) {
  out.clear();
  gather(query_chunks(accept, threads), threads, out);
}

}  // namespace model
}  // namespace b2b
