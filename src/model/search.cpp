#include "search.hpp"

#ifdef B2B_HAVE_BOOST_GEOMETRY
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>
#endif

#include <algorithm>
#include <cmath>


namespace b2b {
namespace model {
namespace {

// Boxes per leaf. On examples/c/model_scaling.cpp's bundle, 16 visited
// fewer nodes than 4 or 8 for the same pairs and was the fastest.
constexpr int kLeafSize = 16;

void grow(Box& into, const Box& b) {
  for (int i = 0; i < 3; ++i) {
    into.lo[i] = std::min(into.lo[i], b.lo[i]);
    into.hi[i] = std::max(into.hi[i], b.hi[i]);
  }
}

}  // namespace

double box_distance(const Box& a, const Box& b) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i) d = std::max(d, std::max(a.lo[i] - b.hi[i], b.lo[i] - a.hi[i]));
  return d;
}

#ifdef B2B_HAVE_BOOST_GEOMETRY
struct BoxTree::RTreeIndex {
  using Point = boost::geometry::model::point<double, 3, boost::geometry::cs::cartesian>;
  using BBox = boost::geometry::model::box<Point>;
  using Value = std::pair<BBox, int>;
  static BBox to_bbox(const Box& b) {
    return BBox(Point(b.lo[0], b.lo[1], b.lo[2]), Point(b.hi[0], b.hi[1], b.hi[2]));
  }
  boost::geometry::index::rtree<Value, boost::geometry::index::rstar<16>> tree;
};

void BoxTree::rtree_overlaps(int i, std::vector<int>& out) const {
  struct Sink {  // an output iterator that keeps the later boxes
    int i;
    std::vector<int>* out;
    Sink& operator*() { return *this; }
    Sink& operator++() { return *this; }
    Sink& operator++(int) { return *this; }
    Sink& operator=(const RTreeIndex::Value& v) {
      if (v.second > i) out->push_back(v.second);
      return *this;
    }
  };
  rtree_->tree.query(boost::geometry::index::intersects(RTreeIndex::to_bbox((*boxes_)[i])),
                     Sink{i, &out});
}
#else
struct BoxTree::RTreeIndex {};
void BoxTree::rtree_overlaps(int, std::vector<int>&) const {}
#endif

BoxTree::BoxTree() = default;
BoxTree::~BoxTree() = default;
BoxTree::BoxTree(BoxTree&&) noexcept = default;
BoxTree& BoxTree::operator=(BoxTree&&) noexcept = default;

void BoxTree::build(const std::vector<Box>& boxes, Backend backend) {
  boxes_ = &boxes;
  nodes_.clear();
  use_rtree_ = false;
  const int n = static_cast<int>(boxes.size());
#ifdef B2B_HAVE_BOOST_GEOMETRY
  if (backend == Backend::kRTree) {
    use_rtree_ = true;
    rtree_.reset();  // before the new one is packed: one tree in memory at a time
    std::vector<RTreeIndex::Value> values;
    values.reserve(boxes.size());
    for (int k = 0; k < n; ++k) values.emplace_back(RTreeIndex::to_bbox(boxes[k]), k);
    // the packing constructor
    rtree_.reset(new RTreeIndex{decltype(RTreeIndex::tree)(values.begin(), values.end())});
    return;
  }
  rtree_.reset();
#else
  (void)backend;
#endif
  order_.resize(boxes.size());
  sorted_.resize(boxes.size());
  if (n == 0) return;
  // The split works on a compact copy (twice each centre, and the index)
  // that it reorders in place, so it reads memory in sequence.
  std::vector<Centre> centres(boxes.size());
  for (int k = 0; k < n; ++k) {
    for (int a = 0; a < 3; ++a) centres[k].c[a] = boxes[k].lo[a] + boxes[k].hi[a];
    centres[k].index = k;
  }
  nodes_.reserve(2 * (n / kLeafSize + 1));
  split_range(centres, 0, n);
  for (int p = 0; p < n; ++p) order_[p] = centres[p].index;
  for (int p = 0; p < n; ++p) sorted_[p] = boxes[order_[p]];
  // Children come after their parent: one backward pass bounds them all.
  for (int id = static_cast<int>(nodes_.size()) - 1; id >= 0; --id) {
    Node& node = nodes_[id];
    if (node.right < 0) {
      node.box = sorted_[node.lo];
      node.max_index = order_[node.lo];
      for (int p = node.lo + 1; p < node.hi; ++p) {
        grow(node.box, sorted_[p]);
        node.max_index = std::max(node.max_index, order_[p]);
      }
    } else {
      const Node& left = nodes_[id + 1];
      const Node& right = nodes_[node.right];
      node.box = left.box;
      grow(node.box, right.box);
      node.max_index = std::max(left.max_index, right.max_index);
    }
  }
}

// A balanced tree, depth first: each node's boxes (positions [lo, hi) of
// order_) are split at their median along the longest extent of their
// centres, down to leaves of up to kLeafSize boxes. The splits follow the
// scene's shape: halves of the boxes' Morton order (the first version) cut
// the long bundle of examples/c/model_scaling.cpp into nodes that are not,
// and its queries at 10^6 segments took 10.6 s on that tree against 8.4 s
// on this one (one run, same machine).
int BoxTree::split_range(std::vector<Centre>& centres, int lo, int hi) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(Node());
  nodes_[id].lo = lo;
  nodes_[id].hi = hi;
  if (hi - lo <= kLeafSize) return id;
  double clo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, chi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (int p = lo; p < hi; ++p)
    for (int a = 0; a < 3; ++a) {
      clo[a] = std::min(clo[a], centres[p].c[a]);
      chi[a] = std::max(chi[a], centres[p].c[a]);
    }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (chi[a] - clo[a] > chi[axis] - clo[axis]) axis = a;
  const int mid = lo + (hi - lo) / 2;
  std::nth_element(centres.begin() + lo, centres.begin() + mid, centres.begin() + hi,
                   [axis](const Centre& x, const Centre& y) {
                     return x.c[axis] < y.c[axis] || (x.c[axis] == y.c[axis] && x.index < y.index);
                   });
  split_range(centres, lo, mid);  // == id + 1
  nodes_[id].right = split_range(centres, mid, hi);
  return id;
}

void BoxTree::release() {
  for (Chunk& c : chunks_) {
    c.released = c.partners.size();
    std::vector<int>().swap(c.partners);
    std::vector<int>().swap(c.count);
  }
  boxes_ = nullptr;
  std::vector<int>().swap(order_);
  std::vector<Box>().swap(sorted_);
  std::vector<Node>().swap(nodes_);
  rtree_.reset();
}

// Chunk c holds the partners of boxes c * kQueryChunk onwards, each box's
// in order: its pairs go to out after those of the chunks before it.
std::vector<size_t> BoxTree::chunk_offsets(int n_chunks) const {
  std::vector<size_t> offset(static_cast<size_t>(n_chunks) + 1, 0);
  for (int c = 0; c < n_chunks; ++c) offset[c + 1] = offset[c] + chunks_[c].partners.size();
  return offset;
}

void BoxTree::gather(int n_chunks, int threads, std::vector<std::pair<int, int>>& out) const {
  const std::vector<size_t> offset = chunk_offsets(n_chunks);
  out.resize(offset[n_chunks]);
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel for schedule(static) num_threads(search_threads(threads)) if (n_chunks > 1)
#else
  (void)threads;
#endif
  for (int c = 0; c < n_chunks; ++c) {
    const Chunk& chunk = chunks_[c];
    size_t at = offset[c], k = 0;
    for (size_t r = 0; r < chunk.count.size(); ++r) {
      const int i = c * kQueryChunk + static_cast<int>(r);
      for (int e = 0; e < chunk.count[r]; ++e) out[at++] = {i, chunk.partners[k++]};
    }
  }
}

void BoxTree::gather(int n_chunks, int threads, PairRows& out) const {
  const size_t n = boxes_ ? boxes_->size() : 0;
  const std::vector<size_t> offset = chunk_offsets(n_chunks);
  out.start.resize(n + 1);
  out.partner.resize(offset[n_chunks]);
#ifdef B2B_HAVE_OPENMP
#pragma omp parallel for schedule(static) num_threads(search_threads(threads)) if (n_chunks > 1)
#else
  (void)threads;
#endif
  for (int c = 0; c < n_chunks; ++c) {
    const Chunk& chunk = chunks_[c];
    int64_t at = static_cast<int64_t>(offset[c]);
    for (size_t r = 0; r < chunk.count.size(); ++r) {
      out.start[static_cast<size_t>(c) * kQueryChunk + r] = at;
      at += chunk.count[r];
    }
    std::copy(chunk.partners.begin(), chunk.partners.end(),
              out.partner.begin() + static_cast<std::ptrdiff_t>(offset[c]));
  }
  out.start[n] = static_cast<int64_t>(offset[n_chunks]);
}

int PairRows::row_of(size_t k) const {
  // The last row that starts at or before k (rows without pairs start where
  // the next one does).
  const auto it = std::upper_bound(start.begin(), start.end(), static_cast<int64_t>(k));
  return static_cast<int>(it - start.begin()) - 1;
}

int64_t PairRows::find(int a, int b) const {
  if (a < 0 || static_cast<size_t>(a) + 1 >= start.size()) return -1;
  const auto lo = partner.begin() + static_cast<std::ptrdiff_t>(start[a]);
  const auto hi = partner.begin() + static_cast<std::ptrdiff_t>(start[a + 1]);
  const auto it = std::lower_bound(lo, hi, b);
  return it != hi && *it == b ? static_cast<int64_t>(it - partner.begin()) : -1;
}

}  // namespace model
}  // namespace b2b
