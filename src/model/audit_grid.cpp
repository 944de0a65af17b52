#include "audit_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace b2b {
namespace model {

namespace {

constexpr int64_t kAxisCells = int64_t(1) << 21;  // cell coordinates kept in 21 bits
constexpr int64_t kMaxCells = 512;                // a box over more cells is "large"
// Cell size over the median extent: larger cells, fewer cells per box
// (about (1 + 1/kCellFactor)^3) but more boxes per cell to compare.
constexpr double kCellFactor = 1.5;

struct Cells {
  int64_t lo[3], hi[3];
};

uint64_t bucket_of(const int64_t c[3], uint64_t n_buckets) {
  uint64_t h = static_cast<uint64_t>(c[0]) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<uint64_t>(c[1]) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
  h ^= static_cast<uint64_t>(c[2]) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
  h ^= h >> 29;
  return h % n_buckets;
}

}  // namespace

void grid_overlapping_pairs(const std::vector<Box>& boxes, std::vector<std::pair<int, int>>& out) {
  out.clear();
  const int n = static_cast<int>(boxes.size());
  if (n < 2) return;
  double origin[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
  std::vector<double> extent(n);
  for (int i = 0; i < n; ++i) {
    double e = 0.0;
    for (int k = 0; k < 3; ++k) {
      origin[k] = std::min(origin[k], boxes[i].lo[k]);
      e = std::max(e, boxes[i].hi[k] - boxes[i].lo[k]);
    }
    extent[i] = e;
  }
  std::nth_element(extent.begin(), extent.begin() + n / 2, extent.end());
  double h = kCellFactor * extent[n / 2];
  if (!(h > 0.0)) h = 1.0;  // points only: any size works
  const auto cell = [&](double x, int k) {
    const double c = std::floor((x - origin[k]) / h);
    return static_cast<int64_t>(std::min(std::max(c, 0.0), double(kAxisCells - 1)));
  };
  std::vector<Cells> span(n);
  std::vector<int> large;
  int64_t entries = 0;
  for (int i = 0; i < n; ++i) {
    int64_t count = 1;
    for (int k = 0; k < 3; ++k) {
      span[i].lo[k] = cell(boxes[i].lo[k], k);
      span[i].hi[k] = cell(boxes[i].hi[k], k);
      count *= span[i].hi[k] - span[i].lo[k] + 1;
      count = std::min(count, kMaxCells + 1);
    }
    if (count > kMaxCells)
      large.push_back(i);
    else
      entries += count;
  }
  // Counting sort of the (bucket, box) entries, boxes in increasing order.
  const uint64_t n_buckets = static_cast<uint64_t>(entries + 1);
  std::vector<int> start(n_buckets + 1, 0), fill;
  std::vector<int> members(static_cast<size_t>(entries));
  std::vector<char> is_large(n, 0);
  for (int i : large) is_large[i] = 1;
  const auto for_cells = [&](int i, auto&& f) {
    int64_t c[3];
    for (c[0] = span[i].lo[0]; c[0] <= span[i].hi[0]; ++c[0])
      for (c[1] = span[i].lo[1]; c[1] <= span[i].hi[1]; ++c[1])
        for (c[2] = span[i].lo[2]; c[2] <= span[i].hi[2]; ++c[2]) f(bucket_of(c, n_buckets));
  };
  for (int i = 0; i < n; ++i)
    if (!is_large[i]) for_cells(i, [&](uint64_t b) { ++start[b + 1]; });
  for (uint64_t b = 0; b < n_buckets; ++b) start[b + 1] += start[b];
  fill.assign(start.begin(), start.end() - 1);
  for (int i = 0; i < n; ++i)
    if (!is_large[i]) for_cells(i, [&](uint64_t b) { members[fill[b]++] = i; });
  // Each bucket: its distinct boxes (a box whose cells share a bucket comes
  // twice, in a row), every overlapping pair whose intersection's lower
  // corner lies in a cell of this bucket.
  for (uint64_t b = 0; b < n_buckets; ++b) {
    const int lo = start[b], hi = start[b + 1];
    for (int p = lo; p < hi; ++p) {
      const int i = members[p];
      if (p > lo && members[p - 1] == i) continue;
      for (int q = p + 1; q < hi; ++q) {
        const int j = members[q];
        if (j == members[q - 1] || j == i || !boxes_overlap(boxes[i], boxes[j])) continue;
        int64_t c[3];
        for (int k = 0; k < 3; ++k) c[k] = std::max(span[i].lo[k], span[j].lo[k]);
        if (bucket_of(c, n_buckets) == b) out.emplace_back(std::min(i, j), std::max(i, j));
      }
    }
  }
  for (int i : large)
    for (int j = 0; j < n; ++j)
      if (j != i && (!is_large[j] || j > i) && boxes_overlap(boxes[i], boxes[j]))
        out.emplace_back(std::min(i, j), std::max(i, j));
}

}  // namespace model
}  // namespace b2b
