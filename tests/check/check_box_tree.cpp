/* The broad phase's box tree (src/model/search.cpp, compiled in) against
 * brute force, for each backend built in (b2b's BVH; Boost.Geometry's R-tree
 * when its headers were found): empty and single sets, leaf-size boundaries,
 * coincident boxes (every median split a tie), boxes touching face to face,
 * boxes in a plane and on a line (degenerate extents), huge and tiny
 * coordinates, boxes spanning all the others, an accept filter, a tree
 * rebuilt on fewer boxes than before, and 1 and 2 threads (the same pairs in
 * the same order). Every case also takes the pairs as rows (PairRows, the
 * model's candidates) from a tree released and built again: the same pairs,
 * row_of and find agreeing with them. The model's own search tests
 * (check_model_search) reach
 * the tree through the public API; this suite reaches the cases a scene of
 * fibres does not. */
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

#include "model/search.hpp"

// Last: Check's macros (fail, ...) would rename members of the C++ library.
#include "test_support.h"

namespace {

using b2b::model::Box;
using b2b::model::BoxTree;
using Pairs = std::vector<std::pair<int, int>>;

struct AcceptAll {
  bool operator()(int, int) const { return true; }
};
struct AcceptSome {  // rejects a third of the pairs, by their indices
  bool operator()(int a, int b) const { return (a + 2 * b) % 3 != 0; }
};

uint64_t g_state = 88172645463325252ULL;
double uniform() {  // xorshift64*, [0, 1)
  g_state ^= g_state >> 12;
  g_state ^= g_state << 25;
  g_state ^= g_state >> 27;
  return static_cast<double>((g_state * 2685821657736338717ULL) >> 11) * 0x1.0p-53;
}

Box box_at(const double c[3], const double half[3]) {
  Box b;
  for (int i = 0; i < 3; ++i) {
    b.lo[i] = c[i] - half[i];
    b.hi[i] = c[i] + half[i];
  }
  return b;
}

// n boxes with centres in [0, span)^3 * scale + offset, half-sizes up to
// size * scale.
std::vector<Box> random_boxes(int n, double span, double size, double scale, double offset) {
  std::vector<Box> boxes(n);
  for (Box& b : boxes) {
    double c[3], h[3];
    for (int i = 0; i < 3; ++i) {
      c[i] = offset + scale * span * uniform();
      h[i] = scale * size * uniform();
    }
    b = box_at(c, h);
  }
  return boxes;
}

// Every pair (i, j), i < j, whose boxes overlap and that accept takes, in
// order of i, then j. Brute force, but for the pairs whose x-extents are
// apart: with the boxes in order of lo[0], each is tested against those that
// follow it until one starts beyond its hi[0] (every box has lo <= hi, so
// none after that one can meet it on x). Testing all n^2 / 2 pairs was most
// of this suite's time (12000 boxes in rebuild_smaller: 72 million pairs,
// minutes under valgrind); the touching test checks this reference against
// the grid's count.
template <class Accept>
Pairs brute_force(const std::vector<Box>& boxes, Accept accept) {
  const int n = static_cast<int>(boxes.size());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&boxes](int a, int b) {
    return boxes[a].lo[0] < boxes[b].lo[0] || (boxes[a].lo[0] == boxes[b].lo[0] && a < b);
  });
  Pairs out;
  for (int p = 0; p < n; ++p)
    for (int q = p + 1; q < n && boxes[order[q]].lo[0] <= boxes[order[p]].hi[0]; ++q) {
      const int i = std::min(order[p], order[q]), j = std::max(order[p], order[q]);
      if (b2b::model::boxes_overlap(boxes[i], boxes[j]) && accept(i, j)) out.emplace_back(i, j);
    }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<BoxTree::Backend> backends() {
  std::vector<BoxTree::Backend> b{BoxTree::Backend::kBvh};
#ifdef B2B_HAVE_BOOST_GEOMETRY
  b.push_back(BoxTree::Backend::kRTree);
#endif
  return b;
}

const char* name(BoxTree::Backend b) { return b == BoxTree::Backend::kBvh ? "BVH" : "R-tree"; }

// rows holds exactly ref (n boxes), and its lookups agree.
void check_rows(const b2b::model::PairRows& rows, const Pairs& ref, size_t n, const char* what,
                const char* backend, int threads) {
  ck_assert_msg(rows.start.size() == n + 1 && rows.size() == ref.size(),
                "%s, %s, %d thread(s), rows: %zu starts for %zu boxes, %zu pairs, brute force %zu",
                what, backend, threads, rows.start.size(), n, rows.size(), ref.size());
  // Each pair is checked in plain C++ and only the first that fails reaches
  // Check, whose record of every passed assertion (a write(2) each) made
  // this suite take 81 s under valgrind.
  auto stored = [&](size_t k) {
    const int a = ref[k].first, b = ref[k].second;
    return rows.row_of(k) == a && rows.partner[k] == b &&
           rows.find(a, b) == static_cast<int64_t>(k);
  };
  // No box pairs with itself, and the pair reversed is not stored.
  auto not_reversed = [&](size_t k) {
    const int a = ref[k].first, b = ref[k].second;
    return rows.find(a, a) < 0 && rows.find(b, a) < 0;
  };
  size_t k = 0;
  while (k < ref.size() && stored(k) && not_reversed(k)) ++k;
  if (k < ref.size()) {
    const int a = ref[k].first, b = ref[k].second;
    ck_assert_msg(stored(k),
                  "%s, %s, %d thread(s), rows: pair %zu is (%d, %d) found at %lld, brute force "
                  "(%d, %d)",
                  what, backend, threads, k, rows.row_of(k), rows.partner[k],
                  static_cast<long long>(rows.find(a, b)), a, b);
    ck_assert_msg(not_reversed(k), "%s, %s: (%d, %d) found reversed", what, backend, a, b);
  }
  const int m = static_cast<int>(n);
  ck_assert_msg(rows.find(-1, 0) < 0 && rows.find(m, m + 1) < 0 && rows.find(m - 1, m) < 0,
                "%s, %s: a pair outside the boxes found", what, backend);
}

// Every backend, with 1 and 2 threads, on a fresh tree: exactly brute force,
// as pairs and as rows.
template <class Accept = AcceptAll>
void check_set(const std::vector<Box>& boxes, const char* what, Accept accept = Accept()) {
  const Pairs ref = brute_force(boxes, accept);
  for (BoxTree::Backend backend : backends())
    for (int threads = 1; threads <= 2; ++threads) {
      BoxTree tree;
      tree.build(boxes, backend);
      Pairs out{{-1, -1}};  // overwritten, not appended to
      tree.overlapping_pairs(accept, threads, out);
      ck_assert_msg(out.size() == ref.size(), "%s, %s, %d thread(s): %zu pairs, brute force %zu",
                    what, name(backend), threads, out.size(), ref.size());
      size_t k = 0;
      while (k < ref.size() && out[k] == ref[k]) ++k;
      ck_assert_msg(k == ref.size(), "%s, %s, %d thread(s): pair %zu is (%d, %d), brute force (%d, %d)",
                    what, name(backend), threads, k, out[k].first, out[k].second, ref[k].first,
                    ref[k].second);
      // Released (index and buffers freed), built again, and asked for rows.
      tree.release();
      tree.build(boxes, backend);
      b2b::model::PairRows rows;
      rows.start.assign(5, -7);  // overwritten, not appended to
      rows.partner.assign(3, -1);
      tree.overlapping_pairs(accept, threads, rows);
      check_rows(rows, ref, boxes.size(), what, name(backend), threads);
    }
}

}  // namespace

START_TEST(empty_and_single) {
  check_set({}, "no boxes");
  const double c[3] = {1, 2, 3}, h[3] = {0.5, 0.5, 0.5};
  check_set({box_at(c, h)}, "one box");
  check_set({box_at(c, h), box_at(c, h)}, "two equal boxes");
}
END_TEST

// Counts around the leaf size (16) and its multiples.
START_TEST(leaf_boundaries) {
  for (int n : {2, 3, 15, 16, 17, 31, 32, 33, 47, 48, 49, 100}) {
    char what[64];
    std::snprintf(what, sizeof what, "%d random boxes", n);
    check_set(random_boxes(n, 1.0, 0.2, 1.0, 0.0), what);
  }
}
END_TEST

// All centres equal: every median split is a tie, broken by index.
START_TEST(coincident) {
  const double c[3] = {0, 0, 0};
  std::vector<Box> boxes;
  for (int k = 0; k < 200; ++k) {
    const double h[3] = {1e-3 * (k % 7 + 1), 1e-3 * (k % 5 + 1), 1e-3 * (k % 3 + 1)};
    boxes.push_back(box_at(c, h));
  }
  check_set(boxes, "200 boxes with one centre");
}
END_TEST

// Unit cubes on a 3D grid: neighbours share a face, edge or corner exactly
// (overlap is inclusive), so each box meets 26 others inside the grid.
START_TEST(touching) {
  std::vector<Box> boxes;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      for (int k = 0; k < 12; ++k) {
        const double c[3] = {i + 0.5, j + 0.5, k + 0.5}, h[3] = {0.5, 0.5, 0.5};
        boxes.push_back(box_at(c, h));
      }
  check_set(boxes, "cubes touching on a grid");
  const Pairs ref = brute_force(boxes, AcceptAll());
  // 12^3 cubes: pairs at offsets in {-1,0,1}^3 \ 0, counted once.
  const long expected = (3L * 11 * 12 * 12 + 6L * 11 * 11 * 12 + 4L * 11 * 11 * 11);
  ck_assert_msg(static_cast<long>(ref.size()) == expected, "brute force found %zu pairs, expected %ld",
                ref.size(), expected);
}
END_TEST

// Centres in a plane and on a line: the split axis has no extent in the
// others.
START_TEST(degenerate_extents) {
  std::vector<Box> plane, line;
  for (int k = 0; k < 3000; ++k) {
    const double cp[3] = {10 * uniform(), 10 * uniform(), 0.0};
    const double cl[3] = {0.0, 50 * uniform(), 0.0};
    const double h[3] = {0.1 * uniform(), 0.1 * uniform(), 0.1 * uniform()};
    plane.push_back(box_at(cp, h));
    line.push_back(box_at(cl, h));
  }
  check_set(plane, "centres in a plane");
  check_set(line, "centres on a line");
}
END_TEST

// The same layout at 1e-12 and at 1e12 (offset 1e15): the tree has no
// length scale of its own.
START_TEST(extreme_scales) {
  g_state = 12345;
  check_set(random_boxes(2000, 10.0, 0.3, 1e-12, 0.0), "boxes of size 1e-12");
  g_state = 12345;
  check_set(random_boxes(2000, 10.0, 0.3, 1e12, 1e15), "boxes of size 1e12 at 1e15");
}
END_TEST

// A few boxes spanning everything, among many small ones; with an accept
// filter.
START_TEST(large_boxes_and_filter) {
  std::vector<Box> boxes = random_boxes(6000, 20.0, 0.4, 1.0, 0.0);
  for (int k = 0; k < 5; ++k) {
    const double c[3] = {10, 10, 10}, h[3] = {11.0 + k, 3.0, 11.0};
    boxes.insert(boxes.begin() + 1000 * k, box_at(c, h));
  }
  check_set(boxes, "boxes spanning the others", AcceptAll());
  check_set(boxes, "boxes spanning the others, filtered", AcceptSome());
}
END_TEST

// One tree rebuilt on fewer boxes than before: nothing of the larger set's
// search is left in the result.
START_TEST(rebuild_smaller) {
  const std::vector<Box> big = random_boxes(12000, 20.0, 0.5, 1.0, 0.0);
  const std::vector<Box> small = random_boxes(500, 5.0, 0.5, 1.0, 0.0);
  for (BoxTree::Backend backend : backends()) {
    BoxTree tree;
    Pairs out;
    tree.build(big, backend);
    tree.overlapping_pairs(AcceptAll(), 2, out);
    ck_assert_msg(out == brute_force(big, AcceptAll()), "%s: the larger set", name(backend));
    tree.build(small, backend);
    tree.overlapping_pairs(AcceptAll(), 2, out);
    ck_assert_msg(out == brute_force(small, AcceptAll()), "%s: the smaller set after the larger",
                  name(backend));
    const std::vector<Box> none;
    tree.build(none, backend);
    tree.overlapping_pairs(AcceptAll(), 1, out);
    ck_assert_msg(out.empty(), "%s: no boxes after some: %zu pairs", name(backend), out.size());
  }
}
END_TEST

int main(void) {
  Suite* s = suite_create("box_tree");
  TCase* tc = tcase_create("brute_force");
  tcase_set_timeout(tc, 300);
  tcase_add_test(tc, empty_and_single);
  tcase_add_test(tc, leaf_boundaries);
  tcase_add_test(tc, coincident);
  tcase_add_test(tc, touching);
  tcase_add_test(tc, degenerate_extents);
  tcase_add_test(tc, extreme_scales);
  tcase_add_test(tc, large_boxes_and_filter);
  tcase_add_test(tc, rebuild_smaller);
  suite_add_tcase(s, tc);
  return tst_run_suite(s);
}
