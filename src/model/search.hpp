// Broad phase: all pairs of overlapping axis-aligned boxes. Two backends,
// both O(n log n) with no global box or cell size to choose:
//  - Boost.Geometry's R-tree (R* split, 16 entries per node) built by its
//    packing constructor, one intersects query per box: the default when the
//    Boost headers are found at build time (B2B_HAVE_BOOST_GEOMETRY), because
//    it measured faster (examples/c/model_scaling.cpp compares the two on the
//    same boxes);
//  - a bounding-volume hierarchy over the boxes sorted by the Morton code of
//    their centres (taken in the boxes' own bounding box): the fallback.
// Either way the boxes are queried in Morton order, so consecutive queries
// walk the same part of the tree, and each query's partners are appended in
// the order of the lower box index: the result comes out sorted without a
// global sort of all pairs (175 million at 10^6 bundle segments; the bundle
// search at that size went from 31.9 to 20.2 s with the BVH, 15.4 to 13.8 s
// with the R-tree, examples/c/model_scaling.cpp).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#ifdef B2B_HAVE_BOOST_GEOMETRY
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>
#endif

namespace b2b {
namespace model {

struct Box {
  double lo[3], hi[3];
};

// L-infinity distance between two boxes (0 if they overlap).
double box_distance(const Box& a, const Box& b);

bool boxes_overlap(const Box& a, const Box& b);

class BoxTree {
 public:
  enum class Backend { kBvh, kRTree };
  // The backend an update uses: the R-tree when it is built in.
  static Backend default_backend() {
#ifdef B2B_HAVE_BOOST_GEOMETRY
    return Backend::kRTree;
#else
    return Backend::kBvh;
#endif
  }
  static bool has_rtree() { return default_backend() == Backend::kRTree; }

  // Builds the index over boxes (kept by reference until the next build).
  // kRTree without the Boost headers builds the BVH.
  void build(const std::vector<Box>& boxes, Backend backend = default_backend());
  // Every pair (i, j), i < j, of overlapping boxes for which accept(i, j)
  // is true, sorted. threads: as b2b's "threads" option (0: OpenMP's default).
  template <class Accept>
  void overlapping_pairs(Accept accept, int threads, std::vector<std::pair<int, int>>& out) const;

 private:
  struct Node {
    Box box;
    int lo, hi;          // the sorted boxes it covers: positions [lo, hi)
    int max_index;       // the largest box index among them
    int left = -1, right = -1;
  };
  // One chunk of queries: for each queried box, its partners j > i.
  struct QueryPart {
    std::vector<int> box, count, partners;
  };
  const std::vector<Box>* boxes_ = nullptr;
  bool use_rtree_ = false;
  std::vector<int> order_;  // box index at each Morton position
  std::vector<Node> nodes_;
#ifdef B2B_HAVE_BOOST_GEOMETRY
  using BPoint = boost::geometry::model::point<double, 3, boost::geometry::cs::cartesian>;
  using BBox = boost::geometry::model::box<BPoint>;
  using BValue = std::pair<BBox, int>;
  boost::geometry::index::rtree<BValue, boost::geometry::index::rstar<16>> rtree_;
  static BBox to_bbox(const Box& b) {
    return BBox(BPoint(b.lo[0], b.lo[1], b.lo[2]), BPoint(b.hi[0], b.hi[1], b.hi[2]));
  }
#endif
  void sort_by_morton_code();
  int build_range(int lo, int hi);
  // Appends to out the boxes j > i that overlap box i and are accepted.
  template <class Accept>
  void partners(int i, Accept& accept, std::vector<int>& out) const;
  void place(const std::vector<QueryPart>& parts, std::vector<std::pair<int, int>>& out) const;
};

template <class Accept>
void BoxTree::partners(int i, Accept& accept, std::vector<int>& out) const {
  const Box& bi = (*boxes_)[i];
#ifdef B2B_HAVE_BOOST_GEOMETRY
  if (use_rtree_) {
    struct Sink {  // an output iterator that keeps the accepted later boxes
      int i;
      Accept* accept;
      std::vector<int>* out;
      Sink& operator*() { return *this; }
      Sink& operator++() { return *this; }
      Sink& operator++(int) { return *this; }
      Sink& operator=(const BValue& v) {
        if (v.second > i && (*accept)(i, v.second)) out->push_back(v.second);
        return *this;
      }
    };
    rtree_.query(boost::geometry::index::intersects(to_bbox(bi)), Sink{i, &accept, &out});
    return;
  }
#endif
  if (nodes_.empty()) return;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.max_index <= i || !boxes_overlap(node.box, bi)) continue;
    if (node.left < 0) {
      for (int q = node.lo; q < node.hi; ++q) {
        const int j = order_[q];
        if (j > i && boxes_overlap((*boxes_)[j], bi) && accept(i, j)) out.push_back(j);
      }
    } else {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
}

}  // namespace model
}  // namespace b2b

#include "search_query.hpp"
