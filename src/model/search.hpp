// Broad phase: all pairs of overlapping axis-aligned boxes. Two backends,
// both O(n log n) with no global box or cell size to choose:
//  - Boost.Geometry's R-tree (R* split, 16 entries per node) built by its
//    packing constructor, when compiled with the Boost headers
//    (B2B_HAVE_BOOST_GEOMETRY): the model's search when b2b is built with
//    them (B2B_USE_BOOST_GEOMETRY, B2B_BROAD_PHASE_RTREE);
//  - a bounding-volume hierarchy built top down by median splits along the
//    longest extent, on a copy of the boxes in its leaf order (a leaf's
//    boxes are contiguous in memory): the model's search otherwise.
// examples/c/model_scaling.cpp times the two on the same boxes: within a few
// per cent of each other in total, the R-tree with the lower worst exponent.
// Either way each box i is queried for its partners j > i, in the order of
// i, in fixed chunks of consecutive boxes: a host's segments follow their
// beams, so consecutive queries walk the same part of the tree, and each
// chunk's pairs come out sorted and are copied once into place. The chunks'
// buffers are kept for the next search, which then writes into memory it
// already holds, unless the caller releases them with the index (release:
// the model does, as its candidates hold the same pairs again and it builds
// a new index for every search); a search after a release reserves each
// chunk's buffer at the size it last had, so that it does not grow it by
// doubling.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace b2b {
namespace model {

struct Box {
  double lo[3], hi[3];
};

// L-infinity distance between two boxes (0 if they overlap).
double box_distance(const Box& a, const Box& b);

inline bool boxes_overlap(const Box& a, const Box& b) {
  return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&
         a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2];
}

// Pairs (a, b), a < b, sorted, kept as each a's list of b in order
// (compressed rows): 4 bytes a pair and 8 a box instead of 8 a pair, which
// matters where there are a hundred pairs a box (the bundle of
// examples/c/model_scaling.cpp finds 150-175 a segment).
struct PairRows {
  std::vector<int64_t> start;  // a's pairs are [start[a], start[a + 1]); empty when cleared
  std::vector<int> partner;    // b of each pair
  size_t size() const { return partner.size(); }
  void clear() {
    start.clear();
    partner.clear();
  }
  // a of pair k (k < size()).
  int row_of(size_t k) const;
  // The index of pair (a, b), a < b, or -1.
  int64_t find(int a, int b) const;
};

class BoxTree {
 public:
  enum class Backend { kBvh, kRTree };
  BoxTree();
  ~BoxTree();  // in search.cpp, where the R-tree's type is complete
  BoxTree(BoxTree&&) noexcept;
  BoxTree& operator=(BoxTree&&) noexcept;
  // The backend an update uses: the R-tree when b2b is built with it.
  static Backend default_backend() {
#ifdef B2B_BROAD_PHASE_RTREE
    return Backend::kRTree;
#else
    return Backend::kBvh;
#endif
  }

  // Builds the index over boxes (kept by reference until the next build).
  // kRTree without the Boost headers builds the BVH.
  void build(const std::vector<Box>& boxes, Backend backend = default_backend());
  // Every pair (i, j), i < j, of overlapping boxes for which accept(i, j)
  // is true, sorted. threads: as b2b's "threads" option (0: OpenMP's default).
  template <class Accept>
  void overlapping_pairs(Accept accept, int threads, std::vector<std::pair<int, int>>& out);
  // The same pairs as rows (out.start has a row for every box).
  template <class Accept>
  void overlapping_pairs(Accept accept, int threads, PairRows& out);
  // Frees the index and the chunks' buffers (half the memory of the pairs
  // found: a box index per pair), keeping the buffers' sizes for the next
  // search; build() must come before the next overlapping_pairs().
  void release();

 private:
  // 64 bytes, one cache line. Nodes are stored depth first, so a node's
  // left child is the next node.
  struct Node {
    Box box;
    int lo, hi;      // the boxes it covers: positions [lo, hi) of order_
    int right = -1;  // the right child (-1: a leaf)
    int max_index;   // the largest box index among them
  };
  // One chunk of consecutive boxes: each one's partners j > i, in order;
  // how many it had when its buffer was released (0: none).
  struct Chunk {
    std::vector<int> count, partners;
    size_t released = 0;
  };
  const std::vector<Box>* boxes_ = nullptr;
  bool use_rtree_ = false;
  std::vector<int> order_;   // BVH: the box index at each position (leaf order)
  std::vector<Box> sorted_;  // BVH: the boxes in that order
  std::vector<Node> nodes_;
  std::vector<Chunk> chunks_;  // kept from search to search
  // Boost.Geometry's R-tree, defined in search.cpp only: its headers cost a
  // second of compile time in every file that included this one (the whole
  // model layer, through model.hpp), in every build configuration.
  struct RTreeIndex;
  std::unique_ptr<RTreeIndex> rtree_;  // null: none built
  // Appends to out every box j > i that overlaps box i, in the R-tree's order.
  void rtree_overlaps(int i, std::vector<int>& out) const;
  struct Centre {
    double c[3];  // twice the box's centre
    int index;
  };
  int split_range(std::vector<Centre>& centres, int lo, int hi);
  // Appends to out the boxes j > i that overlap box i and are accepted.
  template <class Accept>
  void partners(int i, Accept& accept, std::vector<int>& out) const;
  template <class Accept>
  void rtree_partners(int i, Accept& accept, std::vector<int>& out) const;
  static constexpr int kQueryChunk = 4096;  // boxes per chunk of the query
#ifdef B2B_HAVE_OPENMP
  // The threads of a search's parallel loops: as b2b's "threads" option,
  // 0 meaning OpenMP's default (search_query.hpp).
  static int search_threads(int threads);
#endif
  // Every box's accepted partners into chunks_; the number of chunks.
  template <class Accept>
  int query_chunks(Accept& accept, int threads);
  // Where each chunk's pairs start in the gathered pairs; the last entry
  // is their number.
  std::vector<size_t> chunk_offsets(int n_chunks) const;
  // The chunks' pairs, copied in order into out.
  void gather(int n_chunks, int threads, std::vector<std::pair<int, int>>& out) const;
  void gather(int n_chunks, int threads, PairRows& out) const;
};

template <class Accept>
void BoxTree::partners(int i, Accept& accept, std::vector<int>& out) const {
  if (use_rtree_) {
    rtree_partners(i, accept, out);
    return;
  }
  if (nodes_.empty()) return;
  const Box bi = (*boxes_)[i];
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int id = stack[--top];
    const Node& node = nodes_[id];
    if (node.max_index <= i || !boxes_overlap(node.box, bi)) continue;
    if (node.right < 0) {
      for (int q = node.lo; q < node.hi; ++q) {
        if (!boxes_overlap(sorted_[q], bi)) continue;
        const int j = order_[q];
        if (j > i && accept(i, j)) out.push_back(j);
      }
    } else {
      stack[top++] = node.right;
      stack[top++] = id + 1;
    }
  }
}

template <class Accept>
void BoxTree::rtree_partners(int i, Accept& accept, std::vector<int>& out) const {
  const size_t from = out.size();
  rtree_overlaps(i, out);
  size_t kept = from;
  for (size_t k = from; k < out.size(); ++k)
    if (accept(i, out[k])) out[kept++] = out[k];
  out.resize(kept);
}

}  // namespace model
}  // namespace b2b

#include "search_query.hpp"
