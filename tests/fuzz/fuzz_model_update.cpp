// Fuzz target: the contact model's b2b_model_update. Decodes a small model
// (up to 5 beams of up to 9 nodes, open or rings, every kind, shared nodes,
// up to 3 groups with up to 2 parameter sets, self-contact, options), a
// scene of curved beams crossing at random angles, near-parallel fibres,
// coincident nodes, at any scale, and a sequence of up to 6 updates (small
// and large motions, slides across joints for the handover, non-finite or
// huge coordinates, zero-length elements), each followed by a commit, a
// revert or nothing, and now and then a save and restore. A shadow model
// built by the same calls receives every update that succeeds (with clean
// padding and unused columns, and another ldx) and none that fail, and
// every restart buffer. Asserts b2b_model.h's contract:
//  - a documented status for every call;
//  - a failed update leaves the model as it was: its contacts and stats
//    unchanged bit for bit, and (through the shadow) everything it will
//    compute later;
//  - a successful update: the same contacts and stats as the shadow's, bit
//    for bit (so nodes beyond the beams' and the padding of x are not read,
//    and a restored model continues as the original); every output finite;
//    info[B2B_INFO_SYMMETRIC] = 1 ⇒ the tangent symmetric bit for bit;
//    iterations within the group pair's "max_iterations"; rows and columns
//    of missing slots zero; node and beam numbers in range;
//  - bounded time (fuzz_contract.hpp), for the pairs the update evaluated.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <b2b/b2b.h>

#include "fuzz_contract.hpp"
#include "fuzz_scene.hpp"

using namespace b2b_fuzz;

namespace {

constexpr int kMaxBeams = 5;
constexpr int kMaxBeamNodes = 9;
constexpr int kGroups = 3;
constexpr int kSets = 2;

struct Beam {
  std::vector<int> nodes;
  int closed = 0, kind = 0, group = 0;
  double radius = 0;
};

struct Contact {
  int rc;
  int nodes[8], pair[4];
  double info[B2B_PAIR_INFO_LEN], residual[24], tangent[576];
};

// Everything a host can read from a model after an update.
struct Snapshot {
  int rc_count = 0, count = 0, rc_stats = 0;
  int counts[B2B_MODEL_COUNTS_LEN];
  double totals[B2B_MODEL_TOTALS_LEN];
  std::vector<Contact> contacts;
};

Snapshot snapshot(const b2b_model* m) {
  Snapshot s;
  std::memset(s.counts, 0xA7, sizeof s.counts);
  std::memset(s.totals, 0xA7, sizeof s.totals);
  s.rc_count = b2b_model_contact_count(m, &s.count, nullptr, 0);
  if (s.rc_count != B2B_OK) s.count = 0;
  s.rc_stats = b2b_model_stats(m, s.counts, s.totals, nullptr, 0);
  s.contacts.resize(static_cast<size_t>(s.count));
  for (int k = 0; k < s.count; ++k) {
    Contact& c = s.contacts[k];
    std::memset(&c, 0xA7, sizeof c);
    c.rc = b2b_model_get_contact(m, k, c.nodes, c.pair, c.info, c.residual, c.tangent, 24,
                                 nullptr, 0);
    if (c.rc == B2B_ERR_STATE)  // updated without tangents
      c.rc = b2b_model_get_contact(m, k, c.nodes, c.pair, c.info, c.residual, nullptr, 24,
                                   nullptr, 0);
    FUZZ_REQUIRE(c.rc == B2B_OK, "b2b_model_get_contact(%d of %d) returned %d", k, s.count, c.rc);
  }
  return s;
}

// Bit for bit. With `search_too` false the broad phase's own counts are
// left out: a restored model rebuilds its search where the original reuses
// its candidates, which changes no result.
bool same(const Snapshot& a, const Snapshot& b, bool search_too) {
  if (a.rc_count != b.rc_count || a.count != b.count || a.rc_stats != b.rc_stats) return false;
  int ca[B2B_MODEL_COUNTS_LEN], cb[B2B_MODEL_COUNTS_LEN];
  std::memcpy(ca, a.counts, sizeof ca);
  std::memcpy(cb, b.counts, sizeof cb);
  if (!search_too)
    for (int k : {B2B_COUNT_CANDIDATES, B2B_COUNT_FAR, B2B_COUNT_SEARCH_BUILDS}) ca[k] = cb[k] = 0;
  if (!same_bits(ca, cb, sizeof ca) || !same_bits(a.totals, b.totals, sizeof a.totals))
    return false;
  for (size_t k = 0; k < a.contacts.size(); ++k)
    if (!same_bits(&a.contacts[k], &b.contacts[k], sizeof(Contact))) return false;
  return true;
}

// Where two snapshots differ first (for the message of a violation).
void print_difference(const Snapshot& a, const Snapshot& b) {
  std::fprintf(stderr, "  count: %d (rc %d) vs %d (rc %d); stats rc %d vs %d\n", a.count,
               a.rc_count, b.count, b.rc_count, a.rc_stats, b.rc_stats);
  for (int k = 0; k < B2B_MODEL_COUNTS_LEN; ++k)
    if (a.counts[k] != b.counts[k])
      std::fprintf(stderr, "  counts[%d]: %d vs %d\n", k, a.counts[k], b.counts[k]);
  for (int k = 0; k < B2B_MODEL_TOTALS_LEN; ++k)
    if (!same_bits(&a.totals[k], &b.totals[k], sizeof(double)))
      std::fprintf(stderr, "  totals[%d]: %a vs %a\n", k, a.totals[k], b.totals[k]);
  for (size_t k = 0; k < std::min(a.contacts.size(), b.contacts.size()); ++k) {
    const Contact &x = a.contacts[k], &y = b.contacts[k];
    if (same_bits(&x, &y, sizeof x)) continue;
    std::fprintf(stderr, "  contact %zu: beams/segments %d %d %d %d vs %d %d %d %d\n", k,
                 x.pair[0], x.pair[1], x.pair[2], x.pair[3], y.pair[0], y.pair[1], y.pair[2],
                 y.pair[3]);
    for (int i = 0; i < B2B_PAIR_INFO_LEN; ++i)
      if (!same_bits(&x.info[i], &y.info[i], sizeof(double)))
        std::fprintf(stderr, "    info[%d]: %a vs %a\n", i, x.info[i], y.info[i]);
  }
}

struct Models {
  b2b_model* m = nullptr;
  b2b_model* shadow = nullptr;
  b2b_params* sets[kSets] = {nullptr, nullptr};
  ParamsInfo info[kSets];
  int group_set[kGroups][kGroups];
  bool restored = false;  // the shadow was restored from the model's buffer
  ~Models() {
    b2b_model_destroy(&m);
    b2b_model_destroy(&shadow);
    for (b2b_params*& p : sets) b2b_params_destroy(&p);
  }
};

// A set-up call made on both models, with the same outcome.
#define BOTH(call_m, call_s)                                                           \
  [&]() {                                                                              \
    const int rc_m = (call_m), rc_s = (call_s);                                        \
    FUZZ_REQUIRE(rc_m == rc_s, "set-up call differs between twin models: %d, %d", rc_m, \
                 rc_s);                                                                \
    return rc_m;                                                                       \
  }()

void check_contacts(const Snapshot& s, const Models& ms, const std::vector<Beam>& beams,
                    int n_nodes, bool tangents) {
  FUZZ_REQUIRE(s.rc_count == B2B_OK && s.rc_stats == B2B_OK, "after a successful update: count "
               "%d, stats %d", s.rc_count, s.rc_stats);
  FUZZ_REQUIRE(all_finite(s.totals, B2B_MODEL_TOTALS_LEN),
               "stats totals not finite: energy %g, dissipation %g / %g, normal force %g, min gap "
               "%g", s.totals[0], s.totals[1], s.totals[2], s.totals[3], s.totals[4]);
  for (int k = 0; k < B2B_MODEL_COUNTS_LEN; ++k)
    FUZZ_REQUIRE(s.counts[k] >= 0, "counts[%d] = %d", k, s.counts[k]);
  FUZZ_REQUIRE(s.counts[B2B_COUNT_ACTIVE] == s.count, "counts[ACTIVE] %d, %d contacts",
               s.counts[B2B_COUNT_ACTIVE], s.count);
  for (const Contact& c : s.contacts) {
    FUZZ_REQUIRE(all_finite(c.info, B2B_PAIR_INFO_LEN) && all_finite(c.residual, 24),
                 "a contact's info or residual is not finite");
    if (tangents) FUZZ_REQUIRE(all_finite(c.tangent, 576), "a contact's tangent is not finite");
    for (int k = 0; k < 4; k += 2)
      FUZZ_REQUIRE(c.pair[k] >= 0 && c.pair[k] < static_cast<int>(beams.size()) &&
                       c.pair[k + 1] >= 0,
                   "contact on beam %d, segment %d", c.pair[k], c.pair[k + 1]);
    const int ga = beams[c.pair[0]].group, gb = beams[c.pair[2]].group;
    const int set = ms.group_set[std::min(ga, gb)][std::max(ga, gb)];
    FUZZ_REQUIRE(set >= 0, "a contact between groups %d and %d, which do not touch", ga, gb);
    const double it = c.info[B2B_INFO_ITERATIONS];
    FUZZ_REQUIRE(it >= 0 && it <= ms.info[set].max_iterations && it == std::floor(it),
                 "info[B2B_INFO_ITERATIONS] = %g, max_iterations %d", it,
                 ms.info[set].max_iterations);
    FUZZ_REQUIRE(c.info[B2B_INFO_NORMAL_FORCE] > 0, "an active contact with f_N = %g",
                 c.info[B2B_INFO_NORMAL_FORCE]);
    if (tangents && c.info[B2B_INFO_SYMMETRIC] == 1.0)
      FUZZ_REQUIRE(exactly_symmetric(c.tangent, 24, 24),
                   "info says symmetric, the contact's tangent is not");
    for (int slot = 0; slot < 8; ++slot) {
      FUZZ_REQUIRE(c.nodes[slot] >= -1 && c.nodes[slot] < n_nodes, "node %d in slot %d",
                   c.nodes[slot], slot);
      if (c.nodes[slot] != -1) continue;
      for (int i = 3 * slot; i < 3 * slot + 3; ++i) {
        FUZZ_REQUIRE(c.residual[i] == 0.0, "residual of a missing slot %d: %g", slot,
                     c.residual[i]);
        if (tangents)
          for (int j = 0; j < 24; ++j)
            FUZZ_REQUIRE(c.tangent[i + 24 * j] == 0.0 && c.tangent[j + 24 * i] == 0.0,
                         "tangent row or column of a missing slot %d", slot);
      }
    }
  }
}

// Local coordinates of every beam: curved chains or rings through a common
// region, so that they cross at random angles; or a copy of the previous
// beam shifted sideways (near-parallel fibres).
void place_beams(FuzzInput& in, const std::vector<Beam>& beams, std::vector<double>& x) {
  std::vector<double> prev;
  for (const Beam& b : beams) {
    const int n = static_cast<int>(b.nodes.size());
    std::vector<double> loc(3 * static_cast<size_t>(n));
    const int mode = in.pick(6);
    if (mode == 0 && static_cast<int>(prev.size()) >= 3 * n) {
      double R[9], e[3] = {0, 1, 0}, d[3];
      random_rotation(in, R);
      rotate(R, e, d);
      const double off = in.flag() ? 2 * b.radius * (1 + in.uniform(-0.5, 0.5))
                                   : in.log_uniform(-12, 0);
      for (int k = 0; k < n; ++k)
        for (int i = 0; i < 3; ++i) loc[3 * k + i] = prev[3 * k + i] + off * d[i];
    } else {
      if (b.closed) {
        const double rad = n / 6.2832 * in.uniform(0.7, 1.3);
        for (int k = 0; k < n; ++k) {
          const double a = 6.283185307179586 * (k + 0.3 * in.uniform(-1, 1)) / n;
          loc[3 * k] = rad * std::cos(a);
          loc[3 * k + 1] = rad * std::sin(a);
          loc[3 * k + 2] = 0.2 * in.uniform(-1, 1);
        }
      } else {
        decode_chain(in, n, loc.data());
      }
      double R[9], c[3] = {0, 0, 0};
      random_rotation(in, R);
      for (int k = 0; k < n; ++k)
        for (int i = 0; i < 3; ++i) c[i] += loc[3 * k + i] / n;
      const double shift[3] = {in.uniform(-1, 1), in.uniform(-1, 1), in.uniform(-1, 1)};
      for (int k = 0; k < n; ++k) {
        double d[3] = {loc[3 * k] - c[0], loc[3 * k + 1] - c[1], loc[3 * k + 2] - c[2]};
        rotate(R, d, &loc[3 * k]);
        for (int i = 0; i < 3; ++i) loc[3 * k + i] += shift[i];
      }
    }
    if (in.chance(10)) decode_degeneracy(in, loc.data(), n);
    for (int k = 0; k < n; ++k)
      for (int i = 0; i < 3; ++i) x[3 * static_cast<size_t>(b.nodes[k]) + i] = loc[3 * k + i];
    prev = loc;
  }
}

// The motion of one step, in local coordinates.
void move(FuzzInput& in, const std::vector<Beam>& beams, std::vector<double>& x) {
  const Beam& b = beams[in.pick(static_cast<int>(beams.size()))];
  const int n = static_cast<int>(b.nodes.size());
  auto node = [&](int k) { return &x[3 * static_cast<size_t>(b.nodes[k])]; };
  switch (in.pick(7)) {
    case 0: {  // every node a little
      const double s = in.log_uniform(-7, -1);
      for (double& v : x) v += s * in.uniform(-1, 1);
      break;
    }
    case 1: {  // one beam translated
      const double v[3] = {in.uniform(-0.5, 0.5), in.uniform(-0.5, 0.5), in.uniform(-0.5, 0.5)};
      for (int k = 0; k < n; ++k)
        for (int i = 0; i < 3; ++i) node(k)[i] += v[i];
      break;
    }
    case 2: {  // one beam slid along its first chord: contacts cross joints
      double d[3];
      for (int i = 0; i < 3; ++i) d[i] = node(1)[i] - node(0)[i];
      const double s = in.uniform(-1.5, 1.5);
      for (int k = 0; k < n; ++k)
        for (int i = 0; i < 3; ++i) node(k)[i] += s * d[i];
      break;
    }
    case 3: {  // one beam turned about its first node
      double R[9];
      random_rotation(in, R);
      const double c[3] = {node(0)[0], node(0)[1], node(0)[2]};
      for (int k = 0; k < n; ++k) {
        double d[3] = {node(k)[0] - c[0], node(k)[1] - c[1], node(k)[2] - c[2]};
        rotate(R, d, node(k));
        for (int i = 0; i < 3; ++i) node(k)[i] += c[i];
      }
      break;
    }
    case 4: {  // a large jump: the search is rebuilt
      for (double& v : x) v += in.uniform(-1, 1);
      break;
    }
    default: break;  // another Newton iteration at the same point
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzInput in(data, size);
  Models ms;
  if (b2b_model_create(&ms.m, nullptr, 0) != B2B_OK ||
      b2b_model_create(&ms.shadow, nullptr, 0) != B2B_OK)
    return 0;
  const Placement pl = decode_placement(in);
  const double scale = pl.scale;

  // Beams: consecutive host nodes, sometimes reversed or sharing a node
  // with an earlier beam (a frame), sometimes refused.
  std::vector<Beam> beams;
  int next_node = 0;
  const int n_beams = 1 + in.pick(kMaxBeams);
  for (int b = 0; b < n_beams; ++b) {
    Beam bm;
    bm.closed = in.chance(40) ? 1 : 0;
    const int n = (bm.closed ? 3 : 2) + in.pick(kMaxBeamNodes - (bm.closed ? 2 : 1));
    for (int k = 0; k < n; ++k) bm.nodes.push_back(next_node + k);
    if (in.chance(48)) std::reverse(bm.nodes.begin(), bm.nodes.end());
    if (next_node > 0 && in.chance(24)) bm.nodes[in.pick(n)] = in.pick(next_node);
    bm.kind = in.pick(4);
    bm.group = in.pick(kGroups);
    bm.radius = scale * in.uniform(0.02, 0.3);
    int closed_arg = bm.closed, n_arg = n;
    if (in.chance(6)) {  // refused: a bad node, kind, radius, group or size
      switch (in.pick(5)) {
        case 0: bm.nodes[in.pick(n)] = in.flag() ? -1 : in.raw_int(); break;
        case 1: bm.kind = in.raw_int(); break;
        case 2: bm.radius = in.wild(); break;
        case 3: bm.group = -1 - in.pick(3); break;
        default: closed_arg = in.raw_int(); n_arg = in.pick(3); break;
      }
    }
    int id_m = -1, id_s = -1;
    const int rc = BOTH(b2b_model_add_beam(ms.m, bm.nodes.data(), n_arg, closed_arg, bm.radius,
                                           bm.kind, bm.group, &id_m, nullptr, 0),
                        b2b_model_add_beam(ms.shadow, bm.nodes.data(), n_arg, closed_arg,
                                           bm.radius, bm.kind, bm.group, &id_s, nullptr, 0));
    FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_SIZE, B2B_ERR_NONFINITE,
                                B2B_ERR_UNKNOWN_KIND}),
                 "b2b_model_add_beam returned %d", rc);
    trace("b2b_model_add_beam(nodes, %d, %d, %a, %d, %d) = %d\n", n_arg, closed_arg, bm.radius,
          bm.kind, bm.group, rc);
    print_ints("nodes", bm.nodes.data(), n);
    if (rc != B2B_OK) continue;
    FUZZ_REQUIRE(id_m == static_cast<int>(beams.size()), "beam index %d", id_m);
    next_node += n;
    beams.push_back(bm);
  }
  if (beams.empty()) return 0;
  const int n_nodes = next_node + in.pick(3);  // and a few nodes of no beam

  // Groups and their parameters.
  int n_sets = 0;
  for (int k = 0; k < 1 + in.pick(kSets); ++k) {
    ms.sets[n_sets] = decode_params(in, scale, &ms.info[n_sets], 200);
    if (!ms.sets[n_sets]) continue;
    trace("parameter set %d:\n", n_sets);
    print_params(ms.sets[n_sets]);
    ++n_sets;
  }
  if (n_sets == 0) return 0;
  for (auto& row : ms.group_set)
    for (int& v : row) v = -1;
  for (int ga = 0; ga < kGroups; ++ga)
    for (int gb = ga; gb < kGroups; ++gb) {
      if (!in.chance(160)) continue;
      const int set = in.pick(n_sets);
      if (BOTH(b2b_model_set_group_pair(ms.m, ga, gb, ms.sets[set], nullptr, 0),
               b2b_model_set_group_pair(ms.shadow, ga, gb, ms.sets[set], nullptr, 0)) == B2B_OK) {
        ms.group_set[ga][gb] = set;
        trace("b2b_model_set_group_pair(%d, %d, set %d)\n", ga, gb, set);
      }
    }
  for (size_t b = 0; b < beams.size(); ++b)
    if (in.chance(32)) {
      const double excl = in.flag() ? -1.0 : scale * in.uniform(0, 3);
      const int rc = BOTH(b2b_model_set_self_contact(ms.m, static_cast<int>(b), 1, excl, nullptr, 0),
                          b2b_model_set_self_contact(ms.shadow, static_cast<int>(b), 1, excl, nullptr, 0));
      trace("b2b_model_set_self_contact(%zu, 1, %a) = %d\n", b, excl, rc);
    }
  if (in.chance(64)) {
    const double margin = in.flag() ? scale * in.log_uniform(-6, 1) : in.wild();
    const int rc = BOTH(b2b_model_set_real(ms.m, "search_margin", margin, nullptr, 0),
                        b2b_model_set_real(ms.shadow, "search_margin", margin, nullptr, 0));
    trace("b2b_model_set_real(\"search_margin\", %a) = %d\n", margin, rc);
  }
  if (in.chance(64)) {
    const int hops = in.flag() ? 1 + in.pick(20) : in.raw_int();
    const int rc = BOTH(b2b_model_set_int(ms.m, "max_handover_hops", hops, nullptr, 0),
                        b2b_model_set_int(ms.shadow, "max_handover_hops", hops, nullptr, 0));
    trace("b2b_model_set_int(\"max_handover_hops\", %d) = %d\n", hops, rc);
  }
  const int fin = BOTH(b2b_model_finalize(ms.m, n_nodes, nullptr, 0),
                       b2b_model_finalize(ms.shadow, n_nodes, nullptr, 0));
  trace("b2b_model_finalize(%d) = %d\n", n_nodes, fin);
  if (fin != B2B_OK) return 0;

  // Bound of the work of one update: every pair of segments (and as many
  // handover hops), each with the largest iteration limit.
  int n_seg = 0;
  for (const Beam& b : beams) {
    int s = 0;
    if (b2b_beam_segment_count(b.kind, static_cast<int>(b.nodes.size()), b.closed, &s, nullptr,
                               0) == B2B_OK)
      n_seg += s;
  }
  double per_pair = 0;
  for (int k = 0; k < n_sets; ++k)
    per_pair = std::max(per_pair, static_cast<double>(ms.info[k].max_iterations) *
                                      (ms.info[k].tangent == B2B_TANGENT_FD ? 49 : 1));

  std::vector<double> local(3 * static_cast<size_t>(n_nodes), 0.0);
  place_beams(in, beams, local);
  const int steps = 1 + in.pick(6);
  for (int step = 0; step < steps; ++step) {
    move(in, beams, local);
    // The coordinates of this update: placed, and now and then with a bad
    // coordinate or a zero-length element (for this update only; a value
    // the model accepts goes to the twin too). The model's x has garbage in
    // its padding and in the columns of nodes of no beam; the twin's x is
    // clean, with ldx 3.
    const int ldx = 3 + (in.chance(64) ? 1 + in.pick(3) : 0);
    const int n_cols = n_nodes + in.pick(2);
    std::vector<double> x(static_cast<size_t>(ldx) * n_cols), clean(3 * static_cast<size_t>(n_nodes));
    place_points(pl, local.data(), clean.data(), n_nodes);
    if (in.chance(12)) {
      const Beam& b = beams[in.pick(static_cast<int>(beams.size()))];
      const int k = in.pick(static_cast<int>(b.nodes.size()));
      double* p = &clean[3 * static_cast<size_t>(b.nodes[k])];
      if (in.flag()) {
        p[in.pick(3)] = in.wild();
      } else {  // on top of its neighbour
        const int k2 = (k + 1) % static_cast<int>(b.nodes.size());
        std::memcpy(p, &clean[3 * static_cast<size_t>(b.nodes[k2])], 3 * sizeof(double));
      }
    }
    const double garbage = in.chance(128) ? in.wild() : 0.0;
    for (double& v : x) v = garbage;
    std::vector<bool> used(static_cast<size_t>(n_nodes), false);
    for (const Beam& b : beams)
      for (int k : b.nodes) used[k] = true;
    for (int k = 0; k < n_nodes; ++k)
      for (int i = 0; i < 3; ++i) {
        if (used[k])
          x[static_cast<size_t>(ldx) * k + i] = clean[3 * k + i];
        else
          clean[3 * k + i] = 0.0;
      }
    const int want_tangent = in.chance(200) ? 1 : 0;

    const Snapshot before = snapshot(ms.m);
    const CpuClock clock;
    const int rc = b2b_model_update(ms.m, x.data(), ldx, n_cols, want_tangent, nullptr, 0);
    const double t = clock.seconds();
    const Snapshot after = snapshot(ms.m);
    if (printing()) {
      std::fprintf(stderr, "step %d: b2b_model_update(ldx %d, n_cols %d, want_tangent %d) = %d; "
                   "%d contacts, %d builds\n", step, ldx, n_cols, want_tangent, rc, after.count,
                   after.counts[B2B_COUNT_SEARCH_BUILDS]);
      print_doubles("x (used nodes as the twin sees them)", clean.data(), 3 * n_nodes);
    }
    const double pairs = rc == B2B_OK
                             ? after.counts[B2B_COUNT_EVALUATED] + after.counts[B2B_COUNT_HANDOVERS]
                             : 0.5 * n_seg * n_seg + n_seg;
    FUZZ_REQUIRE(t <= time_budget(per_pair * (pairs + 1)),
                 "b2b_model_update took %.3f s of CPU time for %g pairs", t, pairs);
    FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_NONFINITE, B2B_ERR_COINCIDENT,
                                B2B_ERR_FOLDED}),
                 "b2b_model_update returned %d", rc);
    if (rc != B2B_OK) {
      if (!same(before, after, true)) print_difference(before, after);
      FUZZ_REQUIRE(same(before, after, true), "a failed update (%d) changed the model", rc);
      continue;
    }
    const int rc_s =
        b2b_model_update(ms.shadow, clean.data(), 3, n_nodes, want_tangent, nullptr, 0);
    FUZZ_REQUIRE(rc_s == B2B_OK, "the twin model refuses the update (%d) that succeeded", rc_s);
    const Snapshot twin = snapshot(ms.shadow);
    if (printing())
      std::fprintf(stderr, "  twin: %d contacts, %d builds\n", twin.count,
                   twin.counts[B2B_COUNT_SEARCH_BUILDS]);
    if (!same(after, twin, !ms.restored)) print_difference(after, twin);
    FUZZ_REQUIRE(same(after, twin, !ms.restored),
                 "the model and its twin differ after the same update (%zu and %zu contacts; "
                 "restored %d)", after.contacts.size(), twin.contacts.size(), ms.restored);
    check_contacts(after, ms, beams, n_nodes, want_tangent == 1);

    switch (in.pick(4)) {
      case 0: break;  // the next update is another iteration of this step
      case 1:
        trace("b2b_model_revert\n");
        b2b_model_revert(ms.m, nullptr, 0);
        b2b_model_revert(ms.shadow, nullptr, 0);
        break;
      default:
        trace("b2b_model_commit\n");
        b2b_model_commit(ms.m, nullptr, 0);
        b2b_model_commit(ms.shadow, nullptr, 0);
        if (in.chance(32)) {  // restart the twin from the model's buffer
          int64_t n = 0;
          FUZZ_REQUIRE(b2b_model_save_size(ms.m, &n, nullptr, 0) == B2B_OK && n > 0,
                       "b2b_model_save_size");
          std::vector<unsigned char> buf(static_cast<size_t>(n));
          FUZZ_REQUIRE(b2b_model_save(ms.m, buf.data(), n, nullptr, 0) == B2B_OK,
                       "b2b_model_save");
          if (in.flag()) {  // a damaged buffer is refused
            std::vector<unsigned char> bad = buf;
            bad[static_cast<size_t>(in.pick(static_cast<int>(std::min<int64_t>(n, 65536))))] ^=
                static_cast<unsigned char>(1 + in.pick(255));
            const int rc_bad = b2b_model_restore(ms.shadow, bad.data(), n, nullptr, 0);
            FUZZ_REQUIRE(rc_bad == B2B_ERR_RANGE, "a damaged restart buffer: restore returned %d",
                         rc_bad);
          }
          const int rc_r = b2b_model_restore(ms.shadow, buf.data(), n, nullptr, 0);
          FUZZ_REQUIRE(rc_r == B2B_OK, "restoring the model's own buffer returned %d", rc_r);
          ms.restored = true;
          trace("the twin restored from the model's buffer\n");
        }
        break;
    }
  }
  return 0;
}
