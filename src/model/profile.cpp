#include "profile.hpp"

#include <algorithm>
#include <cstdint>

#include <b2b/b2b.h>

namespace b2b {
namespace model {

void tangent_profile(const Model& m, const EqMap& map, int* heights, int* kl, int* ku) {
  int low = 0, up = 0;
  if (heights) std::fill(heights, heights + map.n_eq, 0);
  // An entry (r, c) and its transpose both lie in the profile of column
  // max(r, c) down to row min(r, c): the profile is symmetric in structure.
  for_each_entry(
      m, map,
      [&](int r, int c, double) {
        if (r > c) low = std::max(low, r - c);
        if (c > r) up = std::max(up, c - r);
        if (heights) {
          const int j = std::max(r, c), i = std::min(r, c);
          heights[j] = std::max(heights[j], j - i);
        }
      },
      false);
  if (kl) *kl = low;
  if (ku) *ku = up;
}

Problem check_profile(const Model& m, const EqMap& map, const int* jp) {
  Problem pb;
  // jp first: a height is jp[j] - jp[j - 1], between 0 and j (the rows above
  // the diagonal); 64 bits, so that a corrupt jp cannot overflow the test.
  for (int j = 0; j < map.n_eq; ++j) {
    const int64_t h = j == 0 ? jp[0] : static_cast<int64_t>(jp[j]) - jp[j - 1];
    if (h < 0 || h > j) {
      pb.status = B2B_ERR_RANGE;
      pb.what = Problem::What::ProfilePointer;
      pb.row = j + map.base;
      pb.value = static_cast<double>(jp[j]);
      return pb;
    }
  }
  for_each_entry(
      m, map,
      [&](int r, int c, double) {
        if (pb.status) return;
        const int j = std::max(r, c), i = std::min(r, c);
        const int64_t h = j == 0 ? 0 : static_cast<int64_t>(jp[j]) - jp[j - 1];
        if (j - i > h) {
          pb.status = B2B_ERR_RANGE;
          pb.what = Problem::What::Profile;
          pb.row = r + map.base;
          pb.col = c + map.base;
        }
      },
      false);
  return pb;
}

void add_tangent_profile(const Model& m, const EqMap& map, double scale, const int* jp,
                         double* ad, double* au, double* al) {
  for_each_entry(m, map, [=](int r, int c, double v) {
    if (r == c) {
      ad[r] += scale * v;
    } else if (r < c) {
      au[static_cast<int64_t>(jp[c]) - c + r] += scale * v;
    } else if (al) {
      al[static_cast<int64_t>(jp[r]) - r + c] += scale * v;
    }
  });
}

}  // namespace model
}  // namespace b2b
