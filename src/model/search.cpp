#include "search.hpp"

#include <algorithm>
#include <cmath>

namespace b2b {
namespace model {
namespace {

constexpr int kLeafSize = 4;

// 21 bits of v spread to every third bit of a 63-bit code.
uint64_t spread_bits(uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

void grow(Box& into, const Box& b) {
  for (int i = 0; i < 3; ++i) {
    into.lo[i] = std::min(into.lo[i], b.lo[i]);
    into.hi[i] = std::max(into.hi[i], b.hi[i]);
  }
}

}  // namespace

bool boxes_overlap(const Box& a, const Box& b) {
  return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&
         a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2];
}

double box_distance(const Box& a, const Box& b) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i) d = std::max(d, std::max(a.lo[i] - b.hi[i], b.lo[i] - a.hi[i]));
  return d;
}

void BoxTree::build(const std::vector<Box>& boxes, Backend backend) {
  boxes_ = &boxes;
  nodes_.clear();
  sort_by_morton_code();
  use_rtree_ = false;
#ifdef B2B_HAVE_BOOST_GEOMETRY
  if (backend == Backend::kRTree) {
    use_rtree_ = true;
    std::vector<BValue> values;
    values.reserve(boxes.size());
    for (int k : order_) values.emplace_back(to_bbox(boxes[k]), k);
    rtree_ = decltype(rtree_)(values.begin(), values.end());  // the packing constructor
    return;
  }
  rtree_.clear();
#else
  (void)backend;
#endif
  const int n = static_cast<int>(boxes.size());
  if (n == 0) return;
  nodes_.reserve(2 * (n / kLeafSize + 1));
  build_range(0, n);
}

// order_: the box indices sorted by the Morton code of the box centres,
// taken in the centres' own bounding box (ties by index).
void BoxTree::sort_by_morton_code() {
  const std::vector<Box>& boxes = *boxes_;
  const int n = static_cast<int>(boxes.size());
  double lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    lo[i] = HUGE_VAL;
    hi[i] = -HUGE_VAL;
  }
  for (const Box& b : boxes)
    for (int i = 0; i < 3; ++i) {
      const double c = 0.5 * (b.lo[i] + b.hi[i]);
      lo[i] = std::min(lo[i], c);
      hi[i] = std::max(hi[i], c);
    }
  std::vector<std::pair<uint64_t, int>> keyed(n);
  for (int k = 0; k < n; ++k) {
    uint64_t code = 0;
    for (int i = 0; i < 3; ++i) {
      const double span = hi[i] - lo[i];
      const double c = 0.5 * (boxes[k].lo[i] + boxes[k].hi[i]);
      const double t = span > 0.0 ? (c - lo[i]) / span : 0.0;
      code |= spread_bits(static_cast<uint64_t>(t * 2097151.0)) << i;
    }
    keyed[k] = {code, k};
  }
  std::sort(keyed.begin(), keyed.end());
  order_.resize(n);
  for (int k = 0; k < n; ++k) order_[k] = keyed[k].second;
}

// The partners of each queried box, found in Morton order, are appended in
// the order of the box index: a sorted result, written once and in sequence.
void BoxTree::place(const std::vector<QueryPart>& parts, std::vector<std::pair<int, int>>& out) const {
  const int n = static_cast<int>(order_.size());
  struct Where {
    const int* partners = nullptr;
    int count = 0;
  };
  std::vector<Where> where(static_cast<size_t>(n));
  size_t total = 0;
  for (const QueryPart& part : parts) {
    const int* next = part.partners.data();
    for (size_t g = 0; g < part.box.size(); ++g) {
      where[part.box[g]] = {next, part.count[g]};
      next += part.count[g];
    }
    total += part.partners.size();
  }
  out.reserve(total);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < where[i].count; ++c) out.emplace_back(i, where[i].partners[c]);
}

// A balanced tree over sorted positions: halves of the range (Morton order
// keeps each half spatially compact), leaves of up to kLeafSize boxes.
int BoxTree::build_range(int lo, int hi) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.push_back(Node());
  nodes_[id].lo = lo;
  nodes_[id].hi = hi;
  Box box = (*boxes_)[order_[lo]];
  int max_index = order_[lo];
  if (hi - lo <= kLeafSize) {
    for (int p = lo + 1; p < hi; ++p) {
      grow(box, (*boxes_)[order_[p]]);
      max_index = std::max(max_index, order_[p]);
    }
  } else {
    const int mid = lo + (hi - lo) / 2;
    const int left = build_range(lo, mid);
    const int right = build_range(mid, hi);
    box = nodes_[left].box;
    grow(box, nodes_[right].box);
    max_index = std::max(nodes_[left].max_index, nodes_[right].max_index);
    nodes_[id].left = left;
    nodes_[id].right = right;
  }
  nodes_[id].box = box;
  nodes_[id].max_index = max_index;
  return id;
}

}  // namespace model
}  // namespace b2b
