// Broad phase: all pairs of overlapping axis-aligned boxes. Two
// implementations, both O(n log n) with no global box or cell size to choose:
//  - Boost.Geometry's R-tree (R* split, 16 entries per node) built by its
//    packing constructor, one intersects query per box: used when the Boost
//    headers are found at build time (B2B_HAVE_BOOST_GEOMETRY), because it
//    measured faster (examples/c/model_scaling.cpp: 0.36 .. 0.93 of the time
//    of the BVH below on the same boxes, the same pairs);
//  - otherwise a bounding-volume hierarchy over the boxes sorted by the
//    Morton code of their centres (taken in the boxes' own bounding box).
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

class BoxTree {
 public:
  // Builds the hierarchy over boxes (kept by reference until the next build).
  void build(const std::vector<Box>& boxes);
  // Every pair (i, j), i < j, of overlapping boxes for which accept(i, j)
  // is true, sorted. threads: as b2b's "threads" option (0: OpenMP's default).
  template <class Accept>
  void overlapping_pairs(Accept accept, int threads, std::vector<std::pair<int, int>>& out) const;

 private:
  struct Node {
    Box box;
    int lo, hi;          // the sorted boxes it covers: positions [lo, hi)
    int left = -1, right = -1;
  };
  const std::vector<Box>* boxes_ = nullptr;
  std::vector<int> order_;  // box index at each sorted position
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
  int build_range(int lo, int hi);
  // Pairs of the box at sorted position p with boxes at positions > p.
  template <class Accept>
  void query(int p, Accept& accept, std::vector<std::pair<int, int>>& out) const;
};

bool boxes_overlap(const Box& a, const Box& b);

template <class Accept>
void BoxTree::query(int p, Accept& accept, std::vector<std::pair<int, int>>& out) const {
#ifdef B2B_HAVE_BOOST_GEOMETRY
  // p is the box index itself; pairs with every later box that intersects it
  std::vector<BValue> hits;
  rtree_.query(boost::geometry::index::intersects(to_bbox((*boxes_)[p])),
               std::back_inserter(hits));
  for (const BValue& v : hits)
    if (v.second > p && accept(p, v.second)) out.emplace_back(p, v.second);
#else
  if (nodes_.empty()) return;
  const int i = order_[p];
  const Box& bi = (*boxes_)[i];
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.hi <= p + 1 || !boxes_overlap(node.box, bi)) continue;
    if (node.left < 0) {
      for (int q = std::max(node.lo, p + 1); q < node.hi; ++q) {
        const int j = order_[q];
        if (!boxes_overlap((*boxes_)[j], bi)) continue;
        const int a = i < j ? i : j, b = i < j ? j : i;
        if (accept(a, b)) out.emplace_back(a, b);
      }
    } else {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
#endif
}

}  // namespace model
}  // namespace b2b

#include "search_query.hpp"
