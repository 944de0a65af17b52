/* The scaling benchmark of the contact model (issue 8, item 6): how the broad
 * phase and the update grow with the number of segments, on two seeded
 * scenes of hermite-nodal fibres of radius r = 0.1:
 *   network  random fibres of 10..20 segments of length 1, gently curved,
 *            at random positions and orientations in a periodic cube whose
 *            size grows with the count (constant density, 0.5 segments per
 *            unit volume, O(1) candidates a segment);
 *   bundle   a tightly packed bundle of nearly parallel fibres (hexagonal
 *            section, spacing 0.99 x 2r, random tilts up to 1 degree, a
 *            twist of 2 degrees at the rim, staggered nodes), 16 segments
 *            of length 0.5: the hard case for point-wise contact and search.
 *
 *   model_scaling [--quick] [--search-only] [--max N] [--scene network|bundle]
 *                 [--trace-memory]
 *
 * Sizes 10^3 .. 10^6 segments (--quick: 10^3 and 10^4, the ctest smoke test,
 * one repetition, the bundle's model updates at 10^3 only; --max N: sizes up
 * to N; --search-only: the search table alone, no model updates). The
 * searches are timed 3 times up to 10^4 segments and twice above (the
 * second reuses the search's buffers, as the model's rebuilds do), the
 * reusing updates 5 times on each thread count up to 10^5 segments and 3
 * times above (1 and 2 threads in turn, run_model says why), and the best
 * of each is kept. The model's updates are skipped at a size where the memory per
 * segment measured at the size before, times the segments, exceeds 80% of
 * MemAvailable (the table says so). For each scene and size it measures
 *   - the search build on the model's own boxes (this program compiles
 *     src/model/search.cpp in and calls the internal BoxTree) with each of
 *     its backends: the BVH, and Boost.Geometry's packed R-tree (when the
 *     Boost headers were found at configure time); the index build plus the
 *     query for all overlapping pairs, one thread;
 *   - a brute-force search (all box pairs) up to 10^4 segments;
 *   - through the public API: the first b2b_model_update (search build and
 *     evaluation), an update on slightly moved coordinates that reuses the
 *     candidates (B2B_COUNT_SEARCH_BUILDS must not grow) with "threads" 1
 *     and 2 in turn, the active contacts, and the peak memory of creating the model
 *     and its first update (VmHWM after minus VmRSS before, from
 *     /proc/self/status, the peak reset through /proc/self/clear_refs).
 * --trace-memory prints a line after each model update of a row (its
 * threads, its coordinates, its active contacts): the peak and the current
 * resident memory since the row's model was created, and the allocator's
 * bytes in use and free in its heaps (glibc's mallinfo2), each per segment:
 * where the peak over all updates comes from (doc/guide-model.md,
 * "Scaling").
 * It prints the two tables in Markdown, the fitted exponent of the search
 * build time against the segment count (least squares on log-log; goal
 * <= 1.15; also against the candidate pairs, which grow a little with the
 * size as the scenes' boundaries matter less) and which search is faster.
 *
 * Checks (exit status 1 on failure; timings never fail it): the BVH pair set
 * equals the brute-force set and Boost's set exactly; the model's candidate
 * count equals the BVH's on the same boxes; every b2b call succeeds; the
 * reusing updates do not rebuild; 1 and 2 threads give the same counts and
 * bitwise the same totals on the same coordinates, in every repetition. */
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <b2b/b2b.h>

#include "model/search.hpp"

#ifdef B2B_HAVE_BOOST_GEOMETRY
#include <boost/version.hpp>
#endif

namespace {

using b2b::model::Box;
using Pairs = std::vector<std::pair<int, int>>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 0.1;

int g_failures = 0;

void fail(const char* what) {
  std::fprintf(stderr, "model_scaling: FAILED: %s\n", what);
  ++g_failures;
}

void check(int status, const char* what, const char* msg) {
  if (status != B2B_OK) {
    std::fprintf(stderr, "model_scaling: %s failed: %s (%s)\n", what, b2b_strerror(status), msg);
    std::exit(EXIT_FAILURE);
  }
}

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// ---------------------------------------------------------------- random

// splitmix64: the same numbers on every platform (std's distributions are not).
struct Rng {
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed) {}
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  void unit_vector(double v[3]) {
    double n2;
    do {
      for (int i = 0; i < 3; ++i) v[i] = uniform(-1.0, 1.0);
      n2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    } while (n2 > 1.0 || n2 < 1e-6);
    const double n = std::sqrt(n2);
    for (int i = 0; i < 3; ++i) v[i] /= n;
  }
};

// ---------------------------------------------------------------- scenes

// Open fibres of consecutive host nodes; segment s of the whole scene runs
// from node seg_node[s] to seg_node[s] + 1 (the model's numbering: beam by
// beam, segment by segment).
struct Scene {
  std::vector<double> x;       // 3 x n_nodes
  std::vector<int> beam_size;  // nodes per fibre
  std::vector<int> seg_node, seg_beam;
  int n_nodes() const { return static_cast<int>(x.size() / 3); }
  int n_segments() const { return static_cast<int>(seg_node.size()); }
  void add_fibre(const std::vector<double>& pts) {
    const int first = n_nodes(), n = static_cast<int>(pts.size() / 3);
    const int beam = static_cast<int>(beam_size.size());
    x.insert(x.end(), pts.begin(), pts.end());
    beam_size.push_back(n);
    for (int k = 0; k + 1 < n; ++k) {
      seg_node.push_back(first + k);
      seg_beam.push_back(beam);
    }
  }
};

// Fibres of 10..20 unit segments in a cube of n / density volume; each a
// planar arc turning by up to 0.05 rad a segment (gently curved). The cube
// is periodic: a fibre that leaves it goes on from the opposite face as a
// new fibre, so the density is the same everywhere at every size.
Scene network(int n_seg, uint64_t seed) {
  constexpr double kDensity = 0.5;  // segments per unit volume
  Rng rng(seed);
  Scene sc;
  const double side = std::cbrt(n_seg / kDensity);
  while (sc.n_segments() < n_seg) {
    const int m = std::min(10 + static_cast<int>(rng.next() % 11), n_seg - sc.n_segments());
    double p[3], t[3], n[3], a[3];
    for (double& c : p) c = rng.uniform(0.0, side);
    rng.unit_vector(t);
    rng.unit_vector(a);  // a direction off t: n = normalised (a - (a.t) t)
    const double at = a[0] * t[0] + a[1] * t[1] + a[2] * t[2];
    double nn = 0.0;
    for (int i = 0; i < 3; ++i) {
      n[i] = a[i] - at * t[i];
      nn += n[i] * n[i];
    }
    nn = std::sqrt(nn);
    for (double& c : n) c /= nn;
    const double kappa = rng.uniform(0.0, 0.05);
    const double ck = std::cos(kappa), sk = std::sin(kappa);
    std::vector<double> pts(p, p + 3);
    for (int k = 0; k < m; ++k) {
      double q[3], shift[3];
      bool out = false;
      for (int i = 0; i < 3; ++i) {
        q[i] = p[i] + t[i];
        shift[i] = side * std::floor(q[i] / side);
        out = out || shift[i] != 0.0;
      }
      if (out) {  // periodic: the fibre goes on from the opposite face as a new one
        if (pts.size() >= 6) sc.add_fibre(pts);
        for (int i = 0; i < 3; ++i) {
          p[i] -= shift[i];
          q[i] -= shift[i];
        }
        pts.assign(p, p + 3);
      }
      for (int i = 0; i < 3; ++i) p[i] = q[i];
      pts.insert(pts.end(), p, p + 3);
      for (int i = 0; i < 3; ++i) {  // turn t and n by kappa in their plane
        const double ti = ck * t[i] + sk * n[i], ni = ck * n[i] - sk * t[i];
        t[i] = ti;
        n[i] = ni;
      }
    }
    sc.add_fibre(pts);
  }
  return sc;
}

// A bundle along z: fibres on a hexagonal lattice (the sites nearest the
// axis), spacing 0.99 x 2r (neighbours touch), each tilted by up to 1 degree
// in a random direction, the whole turned about z by a twist that tilts the
// rim fibres by 2 degrees, nodes staggered by a random shift along z.
Scene bundle(int n_seg, uint64_t seed) {
  constexpr int kSegs = 16;
  constexpr double kLength = 0.5, kSpacing = 0.99 * 2.0 * kRadius;
  const double tilt_max = 1.0 * kPi / 180.0, rim_angle = 2.0 * kPi / 180.0;
  Rng rng(seed);
  const int n_fibres = (n_seg + kSegs - 1) / kSegs;
  struct Site {
    double x, y, d2;
    int i, j;
  };
  std::vector<Site> sites;
  const int K = static_cast<int>(std::sqrt(static_cast<double>(n_fibres))) + 2;
  for (int j = -K; j <= K; ++j)
    for (int i = -K; i <= K; ++i) {
      const double x = kSpacing * (i + 0.5 * j), y = kSpacing * std::sqrt(3.0) / 2.0 * j;
      sites.push_back({x, y, x * x + y * y, i, j});
    }
  std::sort(sites.begin(), sites.end(), [](const Site& a, const Site& b) {
    if (a.d2 != b.d2) return a.d2 < b.d2;
    return a.j != b.j ? a.j < b.j : a.i < b.i;
  });
  sites.resize(n_fibres);
  const double rim = std::max(kSpacing, std::sqrt(sites.back().d2));
  const double twist = std::tan(rim_angle) / rim;  // rad per unit length
  Scene sc;
  for (int f = 0; f < n_fibres; ++f) {
    const int m = std::min(kSegs, n_seg - sc.n_segments());
    const double theta = tilt_max * rng.uniform(), phi = 2.0 * kPi * rng.uniform();
    const double sx = std::tan(theta) * std::cos(phi), sy = std::tan(theta) * std::sin(phi);
    const double shift = kLength * rng.uniform();
    std::vector<double> pts;
    for (int k = 0; k <= m; ++k) {
      const double z = (k - 0.5 * kSegs) * kLength + shift;
      const double px = sites[f].x + sx * z, py = sites[f].y + sy * z;
      const double c = std::cos(twist * z), s = std::sin(twist * z);
      pts.push_back(c * px - s * py);
      pts.push_back(s * px + c * py);
      pts.push_back(z);
    }
    sc.add_fibre(pts);
  }
  return sc;
}

// ---------------------------------------------------------------- boxes

// The model's search boxes (src/model: segment_box of the hermite-nodal kind,
// then grown in broad_phase by r + g0/2 + 4s/3 with g0 = 0 and the default
// margin s = r), computed the same way so that they are bitwise the same.
std::vector<Box> search_boxes(const Scene& sc) {
  const int n = sc.n_segments();
  const double s = kRadius, g = kRadius + 0.5 * 0.0 + 4.0 * s / 3.0;
  std::vector<Box> boxes(n);
  for (int k = 0; k < n; ++k) {
    const double* p = &sc.x[3 * sc.seg_node[k]];
    const double* q = p + 3;
    const double grow = std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]) / 3.0;
    for (int i = 0; i < 3; ++i) {
      boxes[k].lo[i] = std::min(p[i], q[i]) - grow - g;
      boxes[k].hi[i] = std::max(p[i], q[i]) + grow + g;
    }
  }
  return boxes;
}

// ---------------------------------------------------------------- searches

struct Accept {  // the model's rule for these scenes: different fibres
  const int* beam;
  bool operator()(int a, int b) const { return beam[a] != beam[b]; }
};

Pairs brute_force(const std::vector<Box>& boxes, Accept accept) {
  Pairs out;
  const int n = static_cast<int>(boxes.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (b2b::model::boxes_overlap(boxes[i], boxes[j]) && accept(i, j)) out.emplace_back(i, j);
  return out;
}

// The library's own search (src/model/search.cpp, compiled in) with the
// given backend: the best of reps runs, its build and query times.
void time_search(const std::vector<Box>& boxes, b2b::model::BoxTree::Backend backend, Accept accept,
                 int reps, Pairs& out, double& t_build, double& t_query) {
  b2b::model::BoxTree tree;
  double best = HUGE_VAL;
  for (int k = 0; k < reps; ++k) {
    const double t0 = now_s();
    tree.build(boxes, backend);
    const double t1 = now_s();
    tree.overlapping_pairs(accept, 1, out);
    const double t2 = now_s();
    if (t2 - t0 < best) {
      best = t2 - t0;
      t_build = t1 - t0;
      t_query = t2 - t1;
    }
  }
}

// ---------------------------------------------------------------- memory

long status_kb(const char* key) {  // a "VmXXX:" line of /proc/self/status, kB (-1: none)
  FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  long v = -1;
  const size_t len = std::strlen(key);
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, key, len) == 0) {
      v = std::strtol(line + len, nullptr, 10);
      break;
    }
  std::fclose(f);
  return v;
}

bool reset_peak() {  // Linux >= 4.0: "5" resets VmHWM to the current RSS
  FILE* f = std::fopen("/proc/self/clear_refs", "w");
  if (!f) return false;
  const bool ok = std::fputs("5", f) >= 0;
  return std::fclose(f) == 0 && ok;
}

// --trace-memory: one line after a model update (threads 0: the default;
// rss0: resident kB before the model was created, heap0: the allocator's
// bytes in use then).
bool g_trace_memory = false;
double heap_in_use() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 33)
  const struct mallinfo2 mi = mallinfo2();  // all arenas, and the mmapped blocks
  return static_cast<double>(mi.uordblks + mi.hblkhd);
#else
  return -1;
#endif
}
void trace_memory(const char* scene, int n, int update, int threads, const char* coords,
                  b2b_model* m, long rss0, double heap0) {
  if (!g_trace_memory) return;
  char msg[256];
  int counts[16];
  check(b2b_model_stats(m, counts, nullptr, msg, sizeof msg), "b2b_model_stats", msg);
  const double per = 1024.0 / n;
  char thr[32] = "default threads";
  if (threads > 0) std::snprintf(thr, sizeof thr, "%d thread%s", threads, threads == 1 ? "" : "s");
  std::printf("memory trace: %s %d, update %d (%s, %s coordinates): %d active; "
              "B/seg: peak %.0f, resident %.0f",
              scene, n, update, thr, coords,
              counts[B2B_COUNT_ACTIVE], per * (status_kb("VmHWM:") - rss0),
              per * (status_kb("VmRSS:") - rss0));
#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 33)
  const struct mallinfo2 mi = mallinfo2();
  std::printf(", heap in use %.0f, free in the heap %.0f", (heap_in_use() - heap0) / n,
              static_cast<double>(mi.fordblks) / n);
#else
  (void)heap0;
#endif
  std::printf("\n");
  std::fflush(stdout);
}

long mem_available_kb() {  // /proc/meminfo MemAvailable (a huge value if unknown)
  FILE* f = std::fopen("/proc/meminfo", "r");
  long v = -1;
  if (f) {
    char line[256];
    while (std::fgets(line, sizeof line, f))
      if (std::strncmp(line, "MemAvailable:", 13) == 0) v = std::strtol(line + 13, nullptr, 10);
    std::fclose(f);
  }
  return v > 0 ? v : 1L << 40;
}

std::string load_average() {  // the first three fields of /proc/loadavg
  FILE* f = std::fopen("/proc/loadavg", "r");
  double a[3] = {0, 0, 0};
  if (!f) return "unknown";
  const int got = std::fscanf(f, "%lf %lf %lf", &a[0], &a[1], &a[2]);
  std::fclose(f);
  if (got != 3) return "unknown";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f %.2f %.2f", a[0], a[1], a[2]);
  return buf;
}

// ---------------------------------------------------------------- the model

struct ModelRun {
  double t_first = 0, t_reuse[2] = {0, 0};  // seconds
  int candidates = 0, near = 0, active = 0, parallel = 0;
  double mem_bytes = -1;       // peak delta: set-up and first update
  double mem_all_bytes = -1;   // peak delta: set-up and all updates
  double pair_s = -1;  // one b2b_pair_eval (residual + tangent) on an active contact, seconds
};

// The cost of one pair as pair_cost_study measures it (b2b_pair_eval with
// the tangent, on active contacts, best of several rounds), on the scene's
// own active contacts at coordinates x: up to 256 of those between interior
// segments (their patches have four nodes), fresh histories. The reusing
// update is compared with evaluated pairs x this (item 3 of issue 20): most
// evaluated pairs are not active and cost less, so a ratio near 1 leaves
// the update's own bookkeeping little room.
double active_pair_cost(b2b_model* m, const b2b_params* params, const double* x) {
  char msg[256];
  int n = 0;
  check(b2b_model_contact_count(m, &n, msg, sizeof msg), "contact_count", msg);
  std::vector<std::vector<double>> patches;
  for (int k = 0; k < n && patches.size() < 256; ++k) {
    int nodes[8], pair[4];
    double info[32], residual[24];
    check(b2b_model_get_contact(m, k, nodes, pair, info, residual, nullptr, 0, msg, sizeof msg),
          "get_contact", msg);
    if (*std::min_element(nodes, nodes + 8) < 0) continue;
    std::vector<double> X(24);
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 3; ++i) X[3 * j + i] = x[3 * nodes[j] + i];
    patches.push_back(X);
  }
  if (patches.empty()) return -1;
  const int segments[6] = {B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR,
                           B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR};
  const double radii[2] = {kRadius, kRadius};
  double fresh[16] = {0}, hist_new[16], info[32], R[24], K[576];
  int hist_len = 0, status = 0;
  check(b2b_params_history_size(params, &hist_len, msg, sizeof msg), "history_size", msg);
  double best = HUGE_VAL;
  for (int round = 0; round < 5; ++round) {
    const double t0 = now_s();
    for (const std::vector<double>& X : patches)
      check(b2b_pair_eval(params, segments, X.data(), nullptr, radii, fresh, hist_new, hist_len,
                          &status, info, R, K, 24, msg, sizeof msg),
            "b2b_pair_eval", msg);
    best = std::min(best, (now_s() - t0) / static_cast<double>(patches.size()));
  }
  return best;
}

ModelRun run_model(const Scene& sc, const b2b_params* params, int reps, bool peak_ok,
                   const char* scene = nullptr) {
  char msg[256];
  ModelRun r;
  const int n_nodes = sc.n_nodes();
  // Two sets of moved coordinates, each within 0.2 r * sqrt(3) < s/2 of the
  // first: the candidates stay valid.
  std::vector<double> moved[2] = {sc.x, sc.x};
  Rng rng(12345);
  for (size_t k = 0; k < sc.x.size(); ++k) {
    moved[0][k] += 0.2 * kRadius * rng.uniform(-1.0, 1.0);
    moved[1][k] -= 0.1 * kRadius * rng.uniform(-1.0, 1.0);
  }
  std::vector<int> nodes;

  malloc_trim(0);
  if (peak_ok) peak_ok = reset_peak();
  const long rss0 = status_kb("VmRSS:");
  const double heap0 = heap_in_use();
  b2b_model* m = nullptr;
  check(b2b_model_create(&m, msg, sizeof msg), "b2b_model_create", msg);
  int first = 0;
  for (size_t b = 0; b < sc.beam_size.size(); ++b) {
    nodes.resize(sc.beam_size[b]);
    for (int k = 0; k < sc.beam_size[b]; ++k) nodes[k] = first + k;
    first += sc.beam_size[b];
    int id;
    check(b2b_model_add_beam(m, nodes.data(), sc.beam_size[b], 0, kRadius,
                             B2B_CURVE_HERMITE_NODAL, 0, &id, msg, sizeof msg),
          "b2b_model_add_beam", msg);
  }
  check(b2b_model_set_group_pair(m, 0, 0, params, msg, sizeof msg), "set_group_pair", msg);
  // The bundle finds about 170 candidate pairs a segment: at 10^6 segments
  // more than the default bound of "max_candidates" (10^8), which is there
  // for scenes that are wrong, not for this one.
  check(b2b_model_set_int(m, "max_candidates", 2000000000, msg, sizeof msg),
        "set_int max_candidates", msg);
  check(b2b_model_finalize(m, n_nodes, msg, sizeof msg), "b2b_model_finalize", msg);
  double t0 = now_s();
  check(b2b_model_update(m, sc.x.data(), 3, n_nodes, 1, msg, sizeof msg), "b2b_model_update",
        msg);
  r.t_first = now_s() - t0;
  int update = 0;
  if (scene) trace_memory(scene, sc.n_segments(), update++, 0, "the scene's", m, rss0, heap0);
  const long hwm_first = status_kb("VmHWM:");
  if (peak_ok && rss0 > 0 && hwm_first > 0)
    r.mem_bytes = 1024.0 * static_cast<double>(hwm_first - rss0);
  int counts[16], builds;
  double totals[8];
  check(b2b_model_stats(m, counts, totals, msg, sizeof msg), "b2b_model_stats", msg);
  r.candidates = counts[B2B_COUNT_CANDIDATES];
  builds = counts[B2B_COUNT_SEARCH_BUILDS];

  // Updates reusing the candidates: in repetition k, 1 thread and then 2
  // on the same coordinates (moved[k % 2]), each timed, the best of the
  // repetitions kept per thread count. In turn, so that a load that comes
  // and goes on a shared machine falls on both alike: timed one thread
  // count after the other, the speed-up of the network at 10^5 segments
  // printed 1.31, 1.67 and 1.96 in three runs. After each pair of updates
  // their counts and totals must agree bit for bit.
  int pair_counts[2][16];
  double pair_totals[2][8];
  r.t_reuse[0] = r.t_reuse[1] = HUGE_VAL;
  for (int k = 0; k < reps; ++k) {
    const std::vector<double>& xk = moved[k % 2];
    for (int t = 0; t < 2; ++t) {
      check(b2b_model_set_int(m, "threads", t + 1, msg, sizeof msg), "set_int threads", msg);
      t0 = now_s();
      check(b2b_model_update(m, xk.data(), 3, n_nodes, 1, msg, sizeof msg), "b2b_model_update",
            msg);
      r.t_reuse[t] = std::min(r.t_reuse[t], now_s() - t0);
      if (scene)
        trace_memory(scene, sc.n_segments(), update++, t + 1, k % 2 ? "moved (2)" : "moved (1)",
                     m, rss0, heap0);
      check(b2b_model_stats(m, pair_counts[t], pair_totals[t], msg, sizeof msg),
            "b2b_model_stats", msg);
      if (pair_counts[t][B2B_COUNT_SEARCH_BUILDS] != builds)
        fail("an update on moved coordinates rebuilt the search");
    }
    if (std::memcmp(pair_counts[0], pair_counts[1], sizeof pair_counts[0]) != 0 ||
        std::memcmp(pair_totals[0], pair_totals[1], sizeof pair_totals[0]) != 0)
      fail("1 and 2 threads give different counts or totals");
  }
  // The peak over the model's set-up, its first update and the reusing
  // ones on 1 and 2 threads (each holds the last update's results while it
  // makes its own).
  const long hwm = status_kb("VmHWM:");
  if (peak_ok && rss0 > 0 && hwm > 0)
    r.mem_all_bytes = 1024.0 * static_cast<double>(hwm - rss0);
  r.pair_s = active_pair_cost(m, params, moved[(reps - 1) % 2].data());
  r.near = pair_counts[0][B2B_COUNT_EVALUATED];
  r.active = pair_counts[0][B2B_COUNT_ACTIVE];
  r.parallel = pair_counts[0][B2B_COUNT_PARALLEL];
  int n_contacts = -1;
  check(b2b_model_contact_count(m, &n_contacts, msg, sizeof msg), "contact_count", msg);
  if (n_contacts != r.active) fail("contact_count differs from B2B_COUNT_ACTIVE");
  b2b_model_destroy(&m);
  return r;
}

// ---------------------------------------------------------------- report

struct Row {
  const char* scene;
  int n = 0;
  long pairs = 0;
  double t_tree = 0, t_query = 0;  // BVH, one thread
  double t_brute = -1;
  double t_boost_build = -1, t_boost_query = -1;
  ModelRun model;
  const char* model_skip = nullptr;  // why the model was not run
  char skip_buf[128] = "";
};

double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const size_t n = x.size();
  double mx = 0, my = 0;
  for (size_t k = 0; k < n; ++k) {
    mx += x[k] / n;
    my += y[k] / n;
  }
  double sxy = 0, sxx = 0;
  for (size_t k = 0; k < n; ++k) {
    sxy += (x[k] - mx) * (y[k] - my);
    sxx += (x[k] - mx) * (x[k] - mx);
  }
  return sxx > 0 ? sxy / sxx : NAN;
}

std::string cpu_name() {
  FILE* f = std::fopen("/proc/cpuinfo", "r");
  std::string name = "unknown CPU";
  if (!f) return name;
  char line[512];
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, "model name", 10) == 0) {
      const char* c = std::strchr(line, ':');
      if (c) {
        name = c + 1;
        while (!name.empty() && (name[0] == ' ' || name[0] == '\t')) name.erase(0, 1);
        while (!name.empty() && (name.back() == '\n' || name.back() == ' ')) name.pop_back();
      }
      break;
    }
  std::fclose(f);
  return name;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, search_only = false;
  long max_n = 1000000;
  int scene_mask = 3;  // 1: network, 2: bundle
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--quick") == 0) {
      quick = true;
    } else if (std::strcmp(argv[k], "--search-only") == 0) {
      search_only = true;
    } else if (std::strcmp(argv[k], "--trace-memory") == 0) {
      g_trace_memory = true;
    } else if (std::strcmp(argv[k], "--max") == 0 && k + 1 < argc) {
      max_n = std::strtol(argv[++k], nullptr, 10);
    } else if (std::strcmp(argv[k], "--scene") == 0 && k + 1 < argc) {
      ++k;
      scene_mask = std::strcmp(argv[k], "network") == 0 ? 1 : std::strcmp(argv[k], "bundle") == 0 ? 2 : 0;
      if (!scene_mask) {
        std::fprintf(stderr, "model_scaling: unknown scene '%s'\n", argv[k]);
        return 2;
      }
    } else {
      std::fprintf(stderr, "usage: %s [--quick] [--search-only] [--max N] [--scene network|bundle] "
                   "[--trace-memory]\n", argv[0]);
      return 2;
    }
  }
  if (quick) max_n = std::min(max_n, 10000L);
  std::vector<int> sizes;
  for (int n = 1000; n <= max_n && n <= 1000000; n *= 10) sizes.push_back(n);
  if (sizes.empty()) {
    std::fprintf(stderr, "model_scaling: --max below 1000\n");
    return 2;
  }
  constexpr int kBruteMax = 10000;

  char msg[256];
  b2b_params* params = nullptr;
  check(b2b_params_create(&params, msg, sizeof msg), "b2b_params_create", msg);
  check(b2b_params_set_real(params, "penalty", 1000.0, msg, sizeof msg), "penalty", msg);
  check(b2b_params_finalize(params, msg, sizeof msg), "b2b_params_finalize", msg);

  const bool peak_ok = reset_peak() && status_kb("VmHWM:") > 0;
  int major = 0, minor = 0, patch = 0;
  b2b_version(&major, &minor, &patch);
  std::printf("b2b %d.%d.%d model scaling on %s (%ld cores)%s%s\n", major, minor, patch,
              cpu_name().c_str(), sysconf(_SC_NPROCESSORS_ONLN), quick ? ", --quick" : "",
#ifdef NDEBUG
              ""
#else
              ", assertions ON (not a Release build)"
#endif
  );
  std::printf("hermite-nodal fibres, r = %g, linear law, frictionless, margin s = r; "
              "times: best of %s; load average at start %s\n",
              kRadius,
              quick ? "1"
                    : "3 searches (10^3, 10^4) and 2 above; 5 reusing updates on each thread "
                      "count (up to 10^5, 1 and 2 threads in turn) and 3 above",
              load_average().c_str());
#ifdef B2B_HAVE_BOOST_GEOMETRY
  std::printf("Boost.Geometry %d.%d: bgi::rtree<box, rstar<16>> by its packing constructor, "
              "one intersects query per box\n",
              BOOST_VERSION / 100000, BOOST_VERSION / 100 % 1000);
#else
  std::printf("Boost.Geometry: not found at configure time (libboost-dev); "
              "the Boost column is left out\n");
#endif
  if (!peak_ok) std::printf("memory: /proc/self/clear_refs or VmHWM unavailable, not measured\n");
  std::printf("\n");

  std::vector<Row> rows;
  double last_mem_per_seg[2] = {-1, -1};
  // A warm-up model run, not reported: it loads the library's code and
  // starts the threads, whose pages would otherwise count as the first
  // model's memory.
  if (!search_only) run_model(network(1000, 999), params, 1, false);
  for (int sc_id = 0; sc_id < 2; ++sc_id)
    for (int n : sizes) {
      if (!(scene_mask & (1 << sc_id))) continue;
      Row row;
      row.scene = sc_id == 0 ? "network" : "bundle";
      row.n = n;
      // Above 10^4 a search is timed twice: the second run reuses the tree's
      // buffers, as the model's rebuilds do.
      const int search_reps = quick ? 1 : n <= 10000 ? 3 : 2;
      // The reusing updates: 5 pairs (1 and 2 threads) up to 10^5 segments,
      // where a noisy machine needs them (one update there takes about a
      // second), 3 above.
      const int model_reps = quick ? 1 : n <= 100000 ? 5 : 3;
      const Scene sc = sc_id == 0 ? network(n, 1000 + n) : bundle(n, 2000 + n);
      const std::vector<Box> boxes = search_boxes(sc);
      const Accept accept{sc.seg_beam.data()};

      // BVH: build + all pairs, one thread, best of search_reps.
      Pairs bvh;
      time_search(boxes, b2b::model::BoxTree::Backend::kBvh, accept, search_reps, bvh, row.t_tree,
                  row.t_query);
      row.pairs = static_cast<long>(bvh.size());
      if (n <= kBruteMax) {
        const double t0 = now_s();
        const Pairs brute = brute_force(boxes, accept);
        row.t_brute = now_s() - t0;
        if (brute != bvh) fail("BVH pairs differ from brute force");
      }
#ifdef B2B_HAVE_BOOST_GEOMETRY
      {
        Pairs bp;
        time_search(boxes, b2b::model::BoxTree::Backend::kRTree, accept, search_reps, bp,
                    row.t_boost_build, row.t_boost_query);
        if (bp != bvh) fail("Boost R-tree pairs differ from the BVH's");
      }
#endif
      // The model: skipped where it cannot run here (see the header comment).
      if (search_only) {
        row.model_skip = "left out (--search-only)";
      } else if (quick && sc_id == 1 && n > 1000) {
        row.model_skip = "left out in --quick";
      } else if (last_mem_per_seg[sc_id] > 0 &&
                 last_mem_per_seg[sc_id] * n > 0.8 * 1024.0 * mem_available_kb()) {
        std::snprintf(row.skip_buf, sizeof row.skip_buf,
                      "skipped: %.0f B/seg (measured) x %d = %.0f GB > 80%% of MemAvailable",
                      last_mem_per_seg[sc_id], n, last_mem_per_seg[sc_id] * n / 1e9);
        row.model_skip = row.skip_buf;
      } else {
        row.model = run_model(sc, params, model_reps, peak_ok, row.scene);
        if (row.model.candidates != row.pairs)
          fail("model candidates differ from the BVH on the same boxes");
        if (row.model.mem_all_bytes > 0) last_mem_per_seg[sc_id] = row.model.mem_all_bytes / n;
      }
      rows.push_back(row);
      std::fflush(stdout);
    }

  std::printf("load average at the end: %s\n\n", load_average().c_str());
  // Table 1: the search on the same boxes.
  std::printf("Search on the model's boxes (all overlapping pairs of different fibres), one thread\n\n");
  std::printf("| scene | segments | cand/seg | BVH build [ms] | BVH query [ms] | BVH total [ms] "
              "| brute force [ms] | Boost build [ms] | Boost query [ms] | Boost total [ms] "
              "| Boost / BVH |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Row& r : rows) {
    char brute[32] = "-", bb[32] = "-", bq[32] = "-", bt[32] = "-", ratio[32] = "-";
    if (r.t_brute >= 0) std::snprintf(brute, sizeof brute, "%.1f", 1e3 * r.t_brute);
    if (r.t_boost_build >= 0) {
      const double tb = r.t_boost_build + r.t_boost_query;
      std::snprintf(bb, sizeof bb, "%.1f", 1e3 * r.t_boost_build);
      std::snprintf(bq, sizeof bq, "%.1f", 1e3 * r.t_boost_query);
      std::snprintf(bt, sizeof bt, "%.1f", 1e3 * tb);
      std::snprintf(ratio, sizeof ratio, "%.2f", tb / (r.t_tree + r.t_query));
    }
    std::printf("| %s | %d | %.2f | %.1f | %.1f | %.1f | %s | %s | %s | %s | %s |\n", r.scene,
                r.n, static_cast<double>(r.pairs) / r.n, 1e3 * r.t_tree, 1e3 * r.t_query,
                1e3 * (r.t_tree + r.t_query), brute, bb, bq, bt, ratio);
  }

  // Table 2: the model through the public API.
  std::printf("\nb2b_model_update (with tangents): the first (search build + evaluation, "
              "default threads), then reusing the candidates on moved coordinates\n\n");
  std::printf("| scene | segments | evaluated/seg | active | parallel | first update [ms] "
              "| reuse, 1 thread [ms] | reuse, 2 threads [ms] | speed-up | memory [B/seg] "
              "| memory, all updates [B/seg] | active pair [ns] | throughput ratio, 1 thread | throughput ratio, 2 threads |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Row& r : rows) {
    if (r.model_skip) {
      std::printf("| %s | %d | %s | | | | | | | | | | | |\n", r.scene, r.n, r.model_skip);
      continue;
    }
    char mem[32] = "-", mem_all[32] = "-", pair_ns[32] = "-", ratio1[32] = "-", ratio2[32] = "-";
    if (r.model.mem_bytes >= 0) std::snprintf(mem, sizeof mem, "%.0f", r.model.mem_bytes / r.n);
    if (r.model.mem_all_bytes >= 0)
      std::snprintf(mem_all, sizeof mem_all, "%.0f", r.model.mem_all_bytes / r.n);
    if (r.model.pair_s > 0) {
      // The reusing update against evaluated pairs x the active pair's cost
      // / threads (it searches nothing).
      const double pairs = static_cast<double>(r.model.near) * r.model.pair_s;
      std::snprintf(pair_ns, sizeof pair_ns, "%.0f", 1e9 * r.model.pair_s);
      std::snprintf(ratio1, sizeof ratio1, "%.2f", r.model.t_reuse[0] / pairs);
      std::snprintf(ratio2, sizeof ratio2, "%.2f", r.model.t_reuse[1] / (pairs / 2));
    }
    std::printf("| %s | %d | %.2f | %d | %d | %.1f | %.1f | %.1f | %.2f | %s | %s | %s | %s | %s |\n",
                r.scene, r.n, static_cast<double>(r.model.near) / r.n, r.model.active,
                r.model.parallel, 1e3 * r.model.t_first, 1e3 * r.model.t_reuse[0],
                1e3 * r.model.t_reuse[1], r.model.t_reuse[0] / r.model.t_reuse[1], mem, mem_all,
                pair_ns, ratio1, ratio2);
  }

  // Exponents: log-log least squares over the sizes run.
  std::printf("\nFitted exponent p of time ~ segments^p (sizes %d .. %d):\n", sizes.front(),
              sizes.back());
  double worst = 0;
#ifdef B2B_HAVE_BOOST_GEOMETRY
  double worst_boost = 0;
#endif
  for (const char* scene : {"network", "bundle"}) {
    std::vector<double> lx, lp, l_bvh, l_boost, lxm, l_upd;
    for (const Row& r : rows)
      if (std::strcmp(r.scene, scene) == 0) {
        lx.push_back(std::log(static_cast<double>(r.n)));
        lp.push_back(std::log(static_cast<double>(r.pairs)));
        l_bvh.push_back(std::log(r.t_tree + r.t_query));
        l_boost.push_back(std::log(r.t_boost_build + r.t_boost_query));
        if (!r.model_skip) {
          lxm.push_back(lx.back());
          l_upd.push_back(std::log(r.model.t_reuse[0]));
        }
      }
    if (lx.size() < 2) {
      if (!lx.empty()) std::printf("  %-8s one size only: no exponent\n", scene);
      continue;
    }
    const double p = slope(lx, l_bvh);
    worst = std::max(worst, p);
    std::printf("  %-8s search build (BVH) %.3f%s", scene, p,
                p <= 1.15 ? " (goal <= 1.15: met)" : " (goal <= 1.15: NOT met)");
#ifdef B2B_HAVE_BOOST_GEOMETRY
    const double pb = slope(lx, l_boost);
    worst_boost = std::max(worst_boost, pb);
    std::printf(", Boost %.3f%s", pb, pb <= 1.15 ? " (met)" : " (NOT met)");
#endif
    std::printf("; against candidate pairs: BVH %.3f", slope(lp, l_bvh));
    if (lxm.size() >= 2)
      std::printf(", reusing update (1 thread) %.3f (sizes %.0f .. %.0f)", slope(lxm, l_upd),
                  std::exp(lxm.front()), std::exp(lxm.back()));
    std::printf("\n");
  }
  std::printf("search build exponent (worst scene): BVH %.3f", worst);
#ifdef B2B_HAVE_BOOST_GEOMETRY
  std::printf(", Boost %.3f", worst_boost);
#endif
  std::printf("\n");

#ifdef B2B_HAVE_BOOST_GEOMETRY
  double sum_ours = 0, sum_boost = 0;
  int boost_wins = 0;
  for (const Row& r : rows) {
    sum_ours += r.t_tree + r.t_query;
    sum_boost += r.t_boost_build + r.t_boost_query;
    if (r.t_boost_build + r.t_boost_query < r.t_tree + r.t_query) ++boost_wins;
  }
  std::printf("Faster search: %s (total over all rows: BVH %.1f ms, Boost %.1f ms, "
              "Boost / BVH = %.2f; Boost faster in %d of %zu rows)\n",
              sum_ours <= sum_boost ? "b2b's BVH" : "Boost.Geometry's packed R-tree",
              1e3 * sum_ours, 1e3 * sum_boost, sum_boost / sum_ours, boost_wins, rows.size());
#else
  std::printf("Faster search: not compared (built without Boost.Geometry)\n");
#endif

  b2b_params_destroy(&params);
  if (g_failures) {
    std::printf("model_scaling: %d check(s) FAILED\n", g_failures);
    return EXIT_FAILURE;
  }
  std::printf("checks: BVH = brute force (up to %d segments)%s, model candidates = BVH, "
              "updates reuse the search, 1 and 2 threads agree: all passed\n",
              kBruteMax,
#ifdef B2B_HAVE_BOOST_GEOMETRY
              ", Boost = BVH"
#else
              ""
#endif
  );
  return EXIT_SUCCESS;
}
