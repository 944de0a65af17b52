// Fuzz target: sequences of b2b_model_* calls in any order (stateful). The
// input is a program of up to 48 calls on one model, each with valid or
// hostile arguments: beams (bad nodes, kinds, radii, groups), group pairs,
// self-contact, every option key (and unknown ones) with edge values,
// finalize with n_nodes up to INT_MAX, updates of a small scene of crossing
// beams moved, scaled or collapsed onto one point, contacts read, the four
// assembly calls with edge kl, ku, ldab, eq_base and n_eq, commit, revert,
// save, restore of the model's own, an older, or a damaged buffer, stats.
// Asserts b2b_model.h's contract:
//  - every call returns one of the statuses documented for it;
//  - contact_count and stats agree (both B2B_OK or both B2B_ERR_STATE; the
//    active count equal to the contacts) and every total is finite;
//  - a failed update, commit, restore or assembly call leaves what the host
//    reads (contacts, stats, saved state) as it was;
//  - an accepted restore of the model's own buffer saves the same bytes.
#include <climits>
#include <cmath>
#include <cstring>
#include <vector>

#include <b2b/b2b.h>

#include "fuzz_contract.hpp"
#include "fuzz_input.hpp"

using namespace b2b_fuzz;

namespace {

constexpr int kNodes = 40;  // host nodes the beams are made of
constexpr int kCols = 64;   // columns of x and eq (beyond every node)

struct View {
  int rc_count = 0, n = 0, rc_stats = 0;
  int counts[B2B_MODEL_COUNTS_LEN] = {0};
  double totals[B2B_MODEL_TOTALS_LEN] = {0};
  std::vector<unsigned char> saved;
  int rc_save = 0;
};

View view(const b2b_model* m) {
  View v;
  v.rc_count = b2b_model_contact_count(m, &v.n, nullptr, 0);
  if (v.rc_count != B2B_OK) v.n = 0;
  v.rc_stats = b2b_model_stats(m, v.counts, v.totals, nullptr, 0);
  FUZZ_REQUIRE(status_in(v.rc_count, {B2B_OK, B2B_ERR_STATE}), "contact_count %d", v.rc_count);
  FUZZ_REQUIRE(v.rc_stats == v.rc_count, "stats %d but contact_count %d", v.rc_stats, v.rc_count);
  if (v.rc_stats == B2B_OK) {
    FUZZ_REQUIRE(v.counts[B2B_COUNT_ACTIVE] == v.n, "%d active, %d contacts",
                 v.counts[B2B_COUNT_ACTIVE], v.n);
    FUZZ_REQUIRE(all_finite(v.totals, B2B_MODEL_TOTALS_LEN), "a total is not finite");
  }
  int64_t size = 0;
  v.rc_save = b2b_model_save_size(m, &size, nullptr, 0);
  if (v.rc_save == B2B_OK) {
    FUZZ_REQUIRE(size > 0 && size < (1 << 24), "save size %lld", static_cast<long long>(size));
    v.saved.resize(static_cast<size_t>(size));
    FUZZ_REQUIRE(b2b_model_save(m, v.saved.data(), size, nullptr, 0) == B2B_OK, "save");
  }
  return v;
}

bool same(const View& a, const View& b) {
  return a.rc_count == b.rc_count && a.n == b.n && a.rc_stats == b.rc_stats &&
         std::memcmp(a.counts, b.counts, sizeof a.counts) == 0 &&
         same_bits(a.totals, b.totals, sizeof a.totals) && a.rc_save == b.rc_save &&
         a.saved == b.saved;
}

// The scene: beams of consecutive nodes along lines that cross each other.
void place(FuzzInput& in, std::vector<double>& x) {
  const int mode = in.pick(8);
  const double s = mode == 6 ? 1e-3 : 1.0;
  for (int k = 0; k < kCols; ++k) {
    const int line = k / 8, pos = k % 8;
    const double ang = 0.9 * line;
    double* p = &x[3 * static_cast<size_t>(k)];
    p[0] = s * (0.3 * pos - 1.0) * std::cos(ang);
    p[1] = s * (0.3 * pos - 1.0) * std::sin(ang);
    p[2] = s * 0.12 * line;
    if (mode == 7) p[0] = p[1] = p[2] = 0.5;  // every node on one point
  }
  if (mode == 5) x[3 * static_cast<size_t>(in.pick(kCols)) + static_cast<size_t>(in.pick(3))] = in.wild();
  if (mode < 3)
    for (double& v : x) v += 0.02 * in.uniform(-1, 1);
}

int wild_int(FuzzInput& in, int small) {
  switch (in.pick(6)) {
    case 0: return INT_MAX;
    case 1: return INT_MIN;
    case 2: return -1;
    case 3: return in.raw_int();
    default: return in.pick(small + 1);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzInput in(data, size);
  b2b_model* m = nullptr;
  if (b2b_model_create(&m, nullptr, 0) != B2B_OK) return 0;
  b2b_params* sets[2] = {nullptr, nullptr};
  for (int k = 0; k < 2; ++k) {
    b2b_params_create(&sets[k], nullptr, 0);
    b2b_params_set_real(sets[k], "penalty", k ? 1e2 : 1e3, nullptr, 0);
    if (k == 1) {
      b2b_params_set_real(sets[k], "friction", 0.4, nullptr, 0);
      b2b_params_set_real(sets[k], "tangential_penalty", 1e3, nullptr, 0);
    }
    b2b_params_finalize(sets[k], nullptr, 0);
  }
  std::vector<double> x(3 * static_cast<size_t>(kCols) * 4);
  std::vector<int> eq(6 * static_cast<size_t>(kCols));
  for (size_t k = 0; k < eq.size(); ++k) eq[k] = static_cast<int>(k);
  std::vector<unsigned char> old_buffer;
  const int n_calls = 1 + in.pick(48);
  char msg[B2B_ERRMSG_LEN];
  for (int call = 0; call < n_calls && in.remaining() > 0; ++call) {
    const int op = in.pick(16);
    const View before = view(m);
    int rc = B2B_OK;
    bool keeps = false;  // a failure of this call must leave the view as it was
    switch (op) {
      case 0: {  // add_beam
        const int n = 2 + in.pick(7);
        const int first = 8 * in.pick(5);
        std::vector<int> nodes(static_cast<size_t>(n));
        for (int k = 0; k < n; ++k) nodes[k] = first + k;
        // a bad node: negative, repeated or beyond n_nodes, never beyond
        // the columns of x and eq (which the model then reads)
        if (in.chance(24)) nodes[in.pick(n)] = in.flag() ? -1 - in.pick(3) : in.pick(kCols);
        int beam;
        const double r = in.chance(16) ? in.wild() : 0.02 + 0.1 * in.unit();
        // a wrong count, never beyond the array: -3 .. n
        const int n_arg = in.chance(16) ? in.pick(n + 4) - 3 : n;
        rc = b2b_model_add_beam(m, nodes.data(), n_arg,
                                in.chance(32) ? 1 : 0, r, in.chance(8) ? wild_int(in, 9) : in.pick(B2B_CURVE_KIND_COUNT),
                                in.chance(8) ? wild_int(in, 3) : in.pick(3), &beam, msg, sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_SIZE, B2B_ERR_NONFINITE,
                                    B2B_ERR_UNKNOWN_KIND, B2B_ERR_STATE}),
                     "add_beam %d", rc);
        break;
      }
      case 1:
        rc = b2b_model_set_group_pair(m, in.chance(16) ? wild_int(in, 3) : in.pick(3),
                                      in.chance(16) ? wild_int(in, 3) : in.pick(3),
                                      sets[in.pick(2)], msg, sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_STATE, B2B_ERR_SIZE}),
                     "set_group_pair %d", rc);
        break;
      case 2:
        rc = b2b_model_set_self_contact(m, wild_int(in, 4), in.chance(16) ? wild_int(in, 1) : 1,
                                        in.flag() ? -1.0 : in.wild(), msg, sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_STATE, B2B_ERR_NONFINITE}),
                     "set_self_contact %d", rc);
        break;
      case 3: {
        static const char* kKeys[] = {"search_margin", "threads", "max_handover_hops",
                                      "message_base", "max_candidates", "no_such_key", ""};
        const char* key = kKeys[in.pick(7)];
        if (in.flag())
          rc = b2b_model_set_real(m, key, in.flag() ? in.wild() : in.log_uniform(-4, 1), msg,
                                  sizeof msg);
        else
          rc = b2b_model_set_int(m, key, in.flag() ? wild_int(in, 50) : in.pick(1000) + 1, msg,
                                 sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_NONFINITE,
                                    B2B_ERR_UNKNOWN_KEY, B2B_ERR_UNKNOWN_KIND}),
                     "set option %d", rc);
        break;
      }
      case 4:
        rc = b2b_model_finalize(m, in.chance(24) ? wild_int(in, kNodes) : kNodes + in.pick(8), msg,
                                sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_STATE}), "finalize %d", rc);
        break;
      case 5:
      case 6:
      case 7: {  // update
        place(in, x);
        const int ldx = in.chance(16) ? in.pick(5) : 3 + in.pick(2);
        const int n_cols = in.chance(8) ? INT_MAX : in.chance(8) ? in.pick(kCols) : kCols;
        rc = b2b_model_update(m, x.data(), ldx, n_cols, in.flag() ? 1 : 0, msg, sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_NONFINITE, B2B_ERR_COINCIDENT,
                                    B2B_ERR_FOLDED, B2B_ERR_SIZE, B2B_ERR_STATE}),
                     "update %d (%s)", rc, msg);
        keeps = true;
        break;
      }
      case 8: {
        // K holds 24 x 24: a wrong ldk is a smaller one (a larger one would
        // be the harness's lie about K's size)
        int nodes[8], pair[4];
        double info[32], res[24], K[24 * 24];
        rc = b2b_model_get_contact(m, in.chance(32) ? wild_int(in, 4) : in.pick(4), nodes, pair, info,
                                   res, in.flag() ? K : nullptr, in.chance(16) ? in.pick(25) : 24,
                                   msg, sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_STATE, B2B_ERR_SIZE}),
                     "get_contact %d", rc);
        if (rc == B2B_OK) FUZZ_REQUIRE(all_finite(info, 32) && all_finite(res, 24), "contact");
        keeps = true;
        break;
      }
      case 9:
      case 10: {  // assembly
        const int n_eq = in.chance(24) ? wild_int(in, 300) : in.pick(300);
        const int base = in.chance(24) ? wild_int(in, 2) : in.pick(2);
        const int ldeq = in.chance(16) ? in.pick(4) : 3 + in.pick(4);
        // n_eq as passed: at most 300 (the arrays below hold that many);
        // negative ones stay (refused)
        const int neq = n_eq > 300 ? 300 : n_eq;
        const int safe_eq = neq > 0 ? neq : 1;
        switch (in.pick(4)) {
          case 0: {
            std::vector<double> f(static_cast<size_t>(safe_eq));
            rc = b2b_model_add_residual(m, eq.data(), ldeq, base, neq, f.data(),
                                        msg, sizeof msg);
            break;
          }
          case 1: {
            std::vector<double> K(static_cast<size_t>(safe_eq) * safe_eq);
            rc = b2b_model_add_tangent_dense(m, eq.data(), ldeq, base, neq, K.data(), safe_eq, msg,
                                             sizeof msg);
            break;
          }
          case 2: {
            const int ldab = 1 + in.pick(64);
            std::vector<double> AB(static_cast<size_t>(ldab) * safe_eq);
            const int kl = in.chance(48) ? wild_int(in, 20) : in.pick(21);
            const int ku = in.chance(48) ? wild_int(in, 20) : in.pick(21);
            rc = b2b_model_add_tangent_banded(m, eq.data(), ldeq, base, neq,
                                              kl, ku, AB.data(), ldab, msg, sizeof msg);
            break;
          }
          default: {
            int nnz = 0;
            rc = b2b_model_tangent_coo(m, eq.data(), ldeq, base, n_eq, &nnz, nullptr, nullptr,
                                       nullptr, 0, msg, sizeof msg);
            if (rc == B2B_OK && nnz > 0 && nnz < (1 << 20)) {
              std::vector<int> rows(static_cast<size_t>(nnz)), cols(static_cast<size_t>(nnz));
              std::vector<double> vals(static_cast<size_t>(nnz));
              const int cap = in.flag() ? nnz : nnz - 1;
              rc = b2b_model_tangent_coo(m, eq.data(), ldeq, base, n_eq, &nnz, rows.data(),
                                         cols.data(), vals.data(), cap, msg, sizeof msg);
            }
            break;
          }
        }
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_STATE, B2B_ERR_SIZE}),
                     "assembly %d (%s)", rc, msg);
        keeps = true;
        break;
      }
      case 11:
        rc = b2b_model_commit(m, msg, sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_STATE}), "commit %d", rc);
        keeps = true;
        break;
      case 12:
        rc = b2b_model_revert(m, msg, sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_STATE}), "revert %d", rc);
        if (rc == B2B_OK) {
          const View v = view(m);
          FUZZ_REQUIRE(v.rc_count == B2B_ERR_STATE, "results after a revert");
        }
        break;
      case 13:
        if (before.rc_save == B2B_OK) old_buffer = before.saved;
        break;
      case 14: {  // restore: the last saved buffer, damaged or not, or the current one
        std::vector<unsigned char> b = in.flag() || old_buffer.empty() ? before.saved : old_buffer;
        if (!b.empty() && in.chance(96)) b[in.pick(static_cast<int>(b.size()))] ^= 1 + in.pick(255);
        if (!b.empty() && in.chance(32)) b.resize(static_cast<size_t>(in.pick(static_cast<int>(b.size()))));
        rc = b2b_model_restore(m, b.empty() ? static_cast<const void*>(x.data()) : b.data(),
                               in.chance(16) ? -1 : static_cast<int64_t>(b.size()), msg, sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_RANGE, B2B_ERR_STATE, B2B_ERR_SIZE}),
                     "restore %d", rc);
        if (rc == B2B_OK) {
          const View v = view(m);
          FUZZ_REQUIRE(v.saved == b, "an accepted buffer is not what save writes back");
          FUZZ_REQUIRE(v.rc_stats == B2B_ERR_STATE, "stats after restore");
        }
        keeps = true;
        break;
      }
      default: {
        int counts[B2B_MODEL_COUNTS_LEN];
        double totals[B2B_MODEL_TOTALS_LEN];
        rc = b2b_model_stats(m, counts, totals, msg, sizeof msg);
        FUZZ_REQUIRE(status_in(rc, {B2B_OK, B2B_ERR_STATE}), "stats %d", rc);
        break;
      }
    }
    trace("call %d: op %d = %d\n", call, op, rc);
    const View after = view(m);
    if (keeps && rc != B2B_OK)
      FUZZ_REQUIRE(same(before, after), "op %d failed (%d: %s) and changed the model", op, rc, msg);
  }
  b2b_model_destroy(&m);
  b2b_params_destroy(&sets[0]);
  b2b_params_destroy(&sets[1]);
  return 0;
}
