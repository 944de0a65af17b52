// Fuzz target: b2b_model_migration_unpack on crafted buffers (structure-aware).
// Two rank models of one scene (tests/fortran/ftest_model_partition.f90's:
// a Hermite beam cut between segments 5 and 6, a straight beam pressed onto
// it and slid across the cut with friction): the sender's migrating contact,
// packed, is the starting point. The input chooses the buffer: its own bytes
// as they are; the real buffer with fields rewritten (ids, hops, groups, the
// parameters' fingerprint, the history length and entries, with edge values:
// 0, -1, 2^63 - 1, neighbours of the real value, NaN, +-Inf, 1e308), signed
// again with a right checksum most of the time, so that the input reaches
// the validation behind it; or the real buffer with bytes flipped, cut
// short or grown. Asserts b2b_model.h's contract:
//  - unpack returns B2B_OK or B2B_ERR_RANGE (B2B_ERR_SIZE for a size < 0);
//  - refused: changed untouched, and the receiver's next update is the one
//    it makes without any contact received, bit for bit;
//  - accepted: changed is 0 or 1, and the next update returns a documented
//    status with every contact's outputs finite.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <b2b/b2b.h>

#include "fuzz_contract.hpp"
#include "fuzz_input.hpp"

using namespace b2b_fuzz;

namespace {

using Bytes = std::vector<unsigned char>;
constexpr int kNodes = 16;
constexpr double kR = 0.1;

void place(double xb, double* x) {
  for (int j = 0; j < 11; ++j) {
    x[3 * j] = 0.5 * j;
    x[3 * j + 1] = x[3 * j + 2] = 0.0;
  }
  for (int j = 0; j < 5; ++j) {
    x[3 * (11 + j)] = xb;
    x[3 * (11 + j) + 1] = 0.5 * (j - 2) + 0.13;
    x[3 * (11 + j) + 2] = 0.19;
  }
}

void must(int st) { FUZZ_REQUIRE(st == B2B_OK, "set-up failed with status %d", st); }

// Rank 0 owns global segments 0..4 of beam 0 and beam 1; rank 1 owns 5..9.
b2b_model* rank_model(int rank, const b2b_params* p) {
  b2b_model* m = nullptr;
  must(b2b_model_create(&m, nullptr, 0));
  int nodes[8], beam;
  for (int j = 0; j < 8; ++j) nodes[j] = (rank == 0 ? 0 : 3) + j;
  must(b2b_model_add_beam(m, nodes, 8, 0, kR, B2B_CURVE_HERMITE_NODAL, 0, &beam, nullptr, 0));
  must(b2b_model_set_beam_global(m, beam, 0, rank == 0 ? 0 : 3, rank, 1 - rank, nullptr, 0));
  must(b2b_model_set_ghost_segments(m, beam, rank == 0 ? 5 : 0, 2, nullptr, 0));
  for (int j = 0; j < 5; ++j) nodes[j] = 11 + j;
  must(b2b_model_add_beam(m, nodes, 5, 0, kR, B2B_CURVE_LINEAR, 1, &beam, nullptr, 0));
  must(b2b_model_set_beam_global(m, beam, 1, 0, 0, 0, nullptr, 0));
  if (rank == 1) must(b2b_model_set_ghost_segments(m, beam, 0, 4, nullptr, 0));
  must(b2b_model_set_group_pair(m, 0, 1, p, nullptr, 0));
  must(b2b_model_finalize(m, kNodes, nullptr, 0));
  return m;
}

// What a host reads of an update: the contacts' infos and residuals.
Bytes outputs(const b2b_model* m) {
  Bytes out;
  int n = 0;
  must(b2b_model_contact_count(m, &n, nullptr, 0));
  for (int k = 0; k < n; ++k) {
    double info[32], res[24];
    must(b2b_model_get_contact(m, k, nullptr, nullptr, info, res, nullptr, 0, nullptr, 0));
    FUZZ_REQUIRE(all_finite(info, 32) && all_finite(res, 24), "contact %d not finite", k);
    const unsigned char* a = reinterpret_cast<const unsigned char*>(info);
    const unsigned char* b = reinterpret_cast<const unsigned char*>(res);
    out.insert(out.end(), a, a + sizeof info);
    out.insert(out.end(), b, b + sizeof res);
  }
  return out;
}

struct Setup {
  b2b_params* p = nullptr;
  double x[3 * kNodes];
  Bytes packed;          // the sender's migrating contact
  Bytes receiver_state;  // the receiver's committed state (restart buffer)
  Bytes without;         // the receiver's update without the contact
  Setup() {
    must(b2b_params_create(&p, nullptr, 0));
    must(b2b_params_set_real(p, "penalty", 1e3, nullptr, 0));
    must(b2b_params_set_real(p, "friction", 0.3, nullptr, 0));
    must(b2b_params_set_real(p, "tangential_penalty", 2e3, nullptr, 0));
    must(b2b_params_finalize(p, nullptr, 0));
    b2b_model* m[2] = {rank_model(0, p), rank_model(1, p)};
    const double xb[3] = {2.3, 2.4, 2.6};
    for (int step = 0; step < 3; ++step) {
      place(xb[step], x);
      for (b2b_model* r : m) must(b2b_model_update(r, x, 3, kNodes, 1, nullptr, 0));
      if (step < 2)
        for (b2b_model* r : m) must(b2b_model_commit(r, nullptr, 0));
    }
    int n = 0;
    must(b2b_model_migration_count(m[0], &n, nullptr, 0));
    FUZZ_REQUIRE(n == 1, "the scene has %d migrating contacts, not 1", n);
    int64_t size = 0;
    must(b2b_model_migration_info(m[0], 0, nullptr, &size, nullptr, 0));
    packed.resize(static_cast<size_t>(size));
    must(b2b_model_migration_pack(m[0], 0, packed.data(), size, nullptr, 0));
    without = outputs(m[1]);
    must(b2b_model_save_size(m[1], &size, nullptr, 0));
    receiver_state.resize(static_cast<size_t>(size));
    must(b2b_model_save(m[1], receiver_state.data(), size, nullptr, 0));
    for (b2b_model*& r : m) b2b_model_destroy(&r);
  }
};

uint64_t fnv1a(const unsigned char* q, size_t n) {
  uint64_t h = 1469598103934665603ULL;
  for (size_t i = 0; i < n; ++i) {
    h ^= q[i];
    h *= 1099511628211ULL;
  }
  return h;
}

int64_t edge_value(FuzzInput& in, int64_t real) {
  switch (in.pick(8)) {
    case 0: return 0;
    case 1: return -1;
    case 2: return INT64_MAX;
    case 3: return INT64_MIN;
    case 4: return static_cast<int64_t>(static_cast<uint64_t>(real) + 1);  // (wraps)
    case 5: return static_cast<int64_t>(static_cast<uint64_t>(real) - 1);
    case 6: return static_cast<int64_t>(in.u32());
    default: return static_cast<int64_t>(in.u64());
  }
}

double edge_double(FuzzInput& in, double real) {
  switch (in.pick(8)) {
    case 0: return std::nan("");
    case 1: return HUGE_VAL;
    case 2: return -HUGE_VAL;
    case 3: return 1e308;
    case 4: return 0.0;
    case 5: return std::nextafter(real, HUGE_VAL);
    case 6: return -real;
    default: return in.uniform(-4.0, 4.0);
  }
}

Bytes choose_buffer(FuzzInput& in, const Setup& s) {
  const int mode = in.pick(3);
  if (mode == 0) {  // the input's own bytes
    Bytes b(in.pick(256));
    for (auto& c : b) c = in.byte();
    return b;
  }
  Bytes b = s.packed;
  if (mode == 1) {  // fields rewritten, signed again
    const int n = 1 + in.pick(3);
    for (int k = 0; k < n; ++k) {
      const size_t field = 2 + in.pick(static_cast<int>(b.size() / 8) - 3);  // not magic, size, sum
      const size_t at = 8 * field;
      if (at >= 128) {  // a history entry
        double v;
        std::memcpy(&v, &b[at], 8);
        v = edge_double(in, v);
        std::memcpy(&b[at], &v, 8);
      } else {
        int64_t v;
        std::memcpy(&v, &b[at], 8);
        v = edge_value(in, v);
        std::memcpy(&b[at], &v, 8);
      }
    }
    if (in.chance(224)) {
      const uint64_t sum = fnv1a(b.data(), b.size() - 8);
      std::memcpy(&b[b.size() - 8], &sum, 8);
    }
    return b;
  }
  switch (in.pick(3)) {  // damaged
    case 0: {
      const int n = 1 + in.pick(4);
      for (int k = 0; k < n; ++k) b[in.pick(static_cast<int>(b.size()))] ^= in.byte() | 1;
      break;
    }
    case 1: b.resize(in.pick(static_cast<int>(b.size()))); break;
    default: b.resize(b.size() + 1 + in.pick(16), in.byte()); break;
  }
  return b;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const Setup s;
  FuzzInput in(data, size);
  b2b_model* m = rank_model(1, s.p);
  must(b2b_model_restore(m, s.receiver_state.data(), static_cast<int64_t>(s.receiver_state.size()),
                         nullptr, 0));
  const Bytes b = choose_buffer(in, s);
  const bool end_round = in.chance(32);
  int changed = 77;
  char msg[B2B_ERRMSG_LEN];
  msg[0] = '\0';
  const int st = b2b_model_migration_unpack(m, b.empty() ? nullptr : b.data(),
                                            static_cast<int64_t>(b.size()), &changed, msg,
                                            sizeof msg);
  if (b.empty()) {  // NULL with size 0: the end of a round
    FUZZ_REQUIRE(st == B2B_OK && changed == 0, "end of round: status %d, changed %d", st, changed);
  } else {
    FUZZ_REQUIRE(status_in(st, {B2B_OK, B2B_ERR_RANGE}), "unpack: status %d (%s)", st, msg);
    if (st != B2B_OK) {
      FUZZ_REQUIRE(changed == 77, "refused, but changed was set to %d", changed);
      FUZZ_REQUIRE(msg[0] != '\0', "refused without a message");
    } else {
      FUZZ_REQUIRE(changed == 0 || changed == 1, "changed is %d", changed);
    }
  }
  if (end_round) {
    int ch = 77;
    FUZZ_REQUIRE(b2b_model_migration_unpack(m, nullptr, 0, &ch, nullptr, 0) == B2B_OK &&
                     (ch == 0 || ch == 1), "end of round: changed %d", ch);
  }
  const int su = b2b_model_update(m, s.x, 3, kNodes, 1, msg, sizeof msg);
  if (st != B2B_OK) {
    FUZZ_REQUIRE(su == B2B_OK, "update after a refused buffer: status %d (%s)", su, msg);
    FUZZ_REQUIRE(outputs(m) == s.without, "a refused buffer changed the receiver");
  } else {
    FUZZ_REQUIRE(status_in(su, {B2B_OK, B2B_ERR_RANGE}), "update: status %d (%s)", su, msg);
    if (su == B2B_OK) outputs(m);  // finite (asserted there)
  }
  b2b_model_destroy(&m);
  return 0;
}
