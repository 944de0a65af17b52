// C entry points of the contact model: set-up, update, contacts, commit,
// revert, restart, stats. Argument checks and messages only; the model layer
// (src/model) does the work.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <b2b/b2b.h>

#include "../curve/topology.hpp"
#include "../pair/history.hpp"
#include "model_handle.hpp"
#include "params_handle.hpp"
#include "segment_checks.hpp"
#include "tables.hpp"

using b2b::capi::check_finalized;
using b2b::capi::check_kind;
using b2b::capi::check_model_finalized;
using b2b::capi::check_results;
using b2b::capi::check_tangents;
using b2b::capi::guarded;
using b2b::capi::Option;
using b2b::capi::OptionType;
using b2b::capi::report_model_problem;
using b2b::capi::Reporter;
using b2b::capi::Valid;
namespace md = b2b::model;

namespace {

// A number the caller gave, as a message shows it (+ message_base): in 64
// bits, so INT_MAX + 1 is not an overflow.
long long shown(int value, int base) { return static_cast<long long>(value) + base; }

}  // namespace

namespace b2b {
namespace capi {

int check_model_finalized(const Reporter& r, const b2b_model* model) {
  if (model == nullptr) return r.fail(B2B_ERR_NULL, "model is NULL");
  if (!model->m.finalized())
    return r.fail(B2B_ERR_STATE, "the model is not finalized (call b2b_model_finalize first)");
  return B2B_OK;
}

int check_results(const Reporter& r, const b2b_model* model) {
  if (int st = check_model_finalized(r, model)) return st;
  if (!model->m.has_results())
    return r.fail(B2B_ERR_STATE, "no update since the model was finalized, reverted or "
                  "restored (call b2b_model_update first)");
  return B2B_OK;
}

int check_tangents(const Reporter& r, const b2b_model* model) {
  if (!model->m.has_tangents())
    return r.fail(B2B_ERR_STATE, "the last update was made without tangents (want_tangent 0)");
  return B2B_OK;
}

int report_model_problem(const Reporter& r, const b2b_model* model, const md::Problem& pb) {
  using W = md::Problem::What;
  const int o = model->message_base;
  const char kAxis[] = "xyz";
  switch (pb.what) {
    case W::NoGroupPair:
      return r.fail(pb.status, "no pair of groups interacts: call b2b_model_set_group_pair first");
    case W::NodeRange:
      return r.fail(pb.status, "beam %d: node %lld (position %d in its list) is out of range: the "
                    "host has nodes %d .. %d", pb.beam + o, shown(pb.node, o), pb.segment + o, o,
                    model->m.n_nodes() - 1 + o);
    case W::SelfNoGroupPair:
      return r.fail(pb.status, "beam %d has self-contact but its group %d is not paired with "
                    "itself: call b2b_model_set_group_pair(%d, %d, ...)", pb.beam + o, pb.node,
                    pb.node, pb.node);
    case W::Coordinate:
      if (pb.status == B2B_ERR_NONFINITE)
        return r.fail(pb.status, "node %d has a non-finite %c coordinate (%g)", pb.node + o,
                      kAxis[pb.axis], pb.value);
      return r.fail(pb.status, "node %d has its %c coordinate (%g) beyond B2B_COORD_MAX",
                    pb.node + o, kAxis[pb.axis], pb.value);
    case W::Segment: {
      const md::SegmentInfo& s =
          model->m.table().segment(model->m.beam(pb.beam).first_segment + pb.segment);
      if (pb.status == B2B_ERR_COINCIDENT)
        return r.fail(pb.status, "beam %d, segment %d: nodes %d and %d coincide (zero-length "
                      "element)", pb.beam + o, pb.segment + o, s.nodes[pb.slot_a] + o,
                      s.nodes[pb.slot_b] + o);
      return r.fail(pb.status, "beam %d, segment %d: the beam folds back on itself at node %d "
                    "(nodes %d and %d on both sides of it coincide), so its tangent has no "
                    "direction", pb.beam + o, pb.segment + o, s.nodes[pb.slot_a + 1] + o,
                    s.nodes[pb.slot_a] + o, s.nodes[pb.slot_b] + o);
    }
    case W::Overflow:
      return r.fail(pb.status, "the contact of beam %d segment %d with beam %d segment %d "
                    "overflows (penalty %g): reduce the penalty or the penetration",
                    pb.beam + o, pb.segment + o, pb.other_beam + o, pb.other_segment + o,
                    pb.value);
    case W::Buffer:
      return r.fail(pb.status, "the restart buffer is not accepted: %s", pb.detail);
    case W::Equation:
      return r.fail(pb.status, "the equation number of node %d, %c (%g) is beyond n_eq",
                    pb.node + o, kAxis[pb.axis], pb.value);
    case W::Candidates:
      return r.fail(pb.status, "the broad phase found more than \"max_candidates\" = %.0f "
                    "pairs of segments that may touch (nodes on top of each other, or a "
                    "search margin far too large?); raise the bound with b2b_model_set_int if "
                    "the scene is meant to be so dense", pb.value);
    case W::Segments:
      return r.fail(pb.status, "the model has %.0f segments, more than the %lld b2b handles in "
                    "one model", pb.value, static_cast<long long>(md::kMaxSegments));
    case W::Band:
      return r.fail(pb.status, "a contact couples equations %d and %d, outside the band (kl, "
                    "ku): widen the band", pb.row, pb.col);
    case W::Displacement:
      return r.fail(pb.status, "node %d has a non-finite %c displacement (%g)", pb.node + o,
                    kAxis[pb.axis], pb.value);
    case W::CurrentCoordinate:
      return r.fail(pb.status, "node %d: its current %c coordinate x + u (%g) is beyond "
                    "B2B_COORD_MAX", pb.node + o, kAxis[pb.axis], pb.value);
    case W::Profile:
      return r.fail(pb.status, "a contact couples equations %d and %d, outside the profile jp: "
                    "raise column %d's height (b2b_model_tangent_profile gives the heights the "
                    "contacts need)", pb.row, pb.col, pb.row > pb.col ? pb.row : pb.col);
    case W::ProfilePointer:
      return r.fail(pb.status, "jp is not a profile pointer array at equation %d (jp there is "
                    "%.0f): jp starts at 0 for the first equation and grows by a column height "
                    "between 0 and the number of equations before it", pb.row, pb.value);
    case W::Increment:
      return r.fail(pb.status, "node %d has a non-finite prescribed %c increment du (%g)",
                    pb.node + o, kAxis[pb.axis], pb.value);
    case W::Partition:  // [partition] worded in capi_partition.cpp
      return report_partition_problem(r, model, pb);
    case W::Migration:
      return r.fail(pb.status, "the packed contact is not accepted: %s", pb.detail);
    case W::None:
      break;
  }
  return r.fail(B2B_ERR_INTERNAL, "unclassified model problem (status %d)", pb.status);
}

}  // namespace capi
}  // namespace b2b

namespace {

int check_setup(const Reporter& r, const b2b_model* model) {
  if (model == nullptr) return r.fail(B2B_ERR_NULL, "model is NULL");
  if (model->m.finalized())
    return r.fail(B2B_ERR_STATE, "the model is finalized: beams and self-contact are set before "
                  "b2b_model_finalize");
  return B2B_OK;
}

// The keys of b2b_model_set_real / _set_int, in the order of b2b_model.h's
// table (the messages list them in this order). A new option is one entry
// here, its member of the model and its line in b2b_model.h.
constexpr Option<b2b_model> kOptions[] = {
    {"search_margin", OptionType::Real,
     Valid::interval(0.0, true, B2B_COORD_MAX, false, "B2B_COORD_MAX"),
     [](b2b_model& h, double v) { h.m.set_search_margin(v); }, nullptr},
    {"threads", OptionType::Int, Valid::at_least(0),
     [](b2b_model& h, double v) { h.m.threads = static_cast<int>(v); }, nullptr},
    {"max_handover_hops", OptionType::Int, Valid::interval(1, false, 1000, false),
     [](b2b_model& h, double v) { h.m.max_hops = static_cast<int>(v); }, nullptr},
    {"message_base", OptionType::Int, Valid::interval(0, false, 1, false),
     [](b2b_model& h, double v) { h.message_base = static_cast<int>(v); }, nullptr},
    {"max_candidates", OptionType::Int, Valid::at_least(1),
     [](b2b_model& h, double v) { h.m.set_max_candidates(static_cast<int>(v)); }, nullptr},
};

int set_by_key(const Reporter& r, b2b_model* model, const char* key, OptionType type,
               double value) {
  if (model == nullptr) return r.fail(B2B_ERR_NULL, "model is NULL");
  if (key == nullptr) return r.fail(B2B_ERR_NULL, "key is NULL");
  const Option<b2b_model>* o = nullptr;
  if (int st = b2b::capi::lookup_option(r, kOptions, key, type, &o)) return st;
  return b2b::capi::set_option(r, *o, *model, value);
}

}  // namespace

extern "C" {

int b2b_model_create(b2b_model** model, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_create", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (model == nullptr) return r.fail(B2B_ERR_NULL, "model is NULL");
    *model = new b2b_model();
    return B2B_OK;
  });
}

int b2b_model_destroy(b2b_model** model) {
  if (model == nullptr) return B2B_OK;
  delete *model;
  *model = nullptr;
  return B2B_OK;
}

int b2b_model_add_beam(b2b_model* model, const int* nodes, int n_nodes, int closed, double radius,
                       int kind, int group, int* beam, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_add_beam", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_setup(r, model)) return st;
    if (nodes == nullptr) return r.fail(B2B_ERR_NULL, "nodes is NULL");
    if (beam == nullptr) return r.fail(B2B_ERR_NULL, "beam is NULL");
    const int o = model->message_base;
    const int b = model->m.beam_count();
    if (closed != 0 && closed != 1)
      return r.fail(B2B_ERR_RANGE, "beam %d: closed is %d (0 open, 1 ring)", b + o, closed);
    char beam_prefix[32];
    std::snprintf(beam_prefix, sizeof beam_prefix, "beam %d: ", b + o);
    if (int st = check_kind(r, kind, beam_prefix)) return st;
    const int min_nodes = b2b::curve::min_nodes(closed);
    if (n_nodes < min_nodes)
      return r.fail(B2B_ERR_SIZE, "beam %d has %d nodes; %s beam needs at least %d", b + o,
                    n_nodes, closed ? "a closed" : "an open", min_nodes);
    if (!std::isfinite(radius))
      return r.fail(B2B_ERR_NONFINITE, "beam %d: the radius is not finite (%g)", b + o, radius);
    if (!(radius > 0.0) || radius > B2B_COORD_MAX)
      return r.fail(B2B_ERR_RANGE, "beam %d: the radius %g must be > 0 (and <= B2B_COORD_MAX)",
                    b + o, radius);
    if (group < 0) return r.fail(B2B_ERR_RANGE, "beam %d: group %d must be >= 0", b + o, group);
    std::vector<std::pair<int, int>> sorted(n_nodes);
    for (int k = 0; k < n_nodes; ++k) {
      if (nodes[k] < 0)
        return r.fail(B2B_ERR_RANGE, "beam %d: node %d at position %d is negative (nodes are "
                      "numbered from %d)", b + o, nodes[k] + o, k + o, o);
      sorted[k] = {nodes[k], k};
    }
    std::sort(sorted.begin(), sorted.end());
    for (int k = 1; k < n_nodes; ++k)
      if (sorted[k].first == sorted[k - 1].first)
        return r.fail(B2B_ERR_RANGE, "beam %d: node %lld appears twice (positions %d and %d)%s",
                      b + o, shown(sorted[k].first, o), sorted[k - 1].second + o, sorted[k].second + o,
                      closed ? "; a closed beam joins its last node to the first by itself" : "");
    md::Beam bm;
    bm.nodes.assign(nodes, nodes + n_nodes);
    bm.closed = closed == 1;
    bm.radius = radius;
    bm.kind = kind;
    bm.group = group;
    *beam = model->m.add_beam(std::move(bm));
    return B2B_OK;
  });
}

int b2b_model_set_group_pair(b2b_model* model, int ga, int gb, const b2b_params* params,
                             char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_set_group_pair", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (model == nullptr) return r.fail(B2B_ERR_NULL, "model is NULL");
    if (int st = check_finalized(r, params)) return st;
    if (ga < 0 || gb < 0)
      return r.fail(B2B_ERR_RANGE, "groups %d and %d: groups are >= 0", ga, gb);
    md::Model& m = model->m;
    if (m.finalized()) {
      const md::GroupPair* g = m.group_pair(ga, gb);
      if (!g)
        return r.fail(B2B_ERR_STATE, "the model is finalized: only a pair of groups set before "
                      "can be given new parameters, and (%d, %d) was not", ga, gb);
      if (m.updated())
        return r.fail(B2B_ERR_STATE, "groups (%d, %d): parameters are replaced between steps "
                      "only (after b2b_model_commit or _revert), not after an update", ga, gb);
      const int len = b2b::pair::history_length(params->p);
      if (len != g->hist_len)
        return r.fail(B2B_ERR_SIZE, "groups (%d, %d): the new parameter set keeps %d doubles "
                      "per pair, the one it replaces %d (friction on one and off in the other?)",
                      ga, gb, len, g->hist_len);
      const bool line = params->p.contact_type != B2B_CONTACT_TYPE_POINT;
      if (line != g->line)
        return r.fail(B2B_ERR_SIZE, "groups (%d, %d): the new parameter set is %s contact, the "
                      "one it replaces %s (their pairs keep different histories)",
                      ga, gb, line ? "line" : "point", g->line ? "line" : "point");
    }
    m.set_group_pair(ga, gb, params->p);
    return B2B_OK;
  });
}

int b2b_model_set_self_contact(b2b_model* model, int beam, int on, double exclusion_length,
                               char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_set_self_contact", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_setup(r, model)) return st;
    const int o = model->message_base;
    if (beam < 0 || beam >= model->m.beam_count())
      return r.fail(B2B_ERR_RANGE, "beam %lld does not exist (beams %d .. %d)", shown(beam, o), o,
                    model->m.beam_count() - 1 + o);
    if (on != 0 && on != 1) return r.fail(B2B_ERR_RANGE, "on is %d (0 or 1)", on);
    if (!std::isfinite(exclusion_length))
      return r.fail(B2B_ERR_NONFINITE, "exclusion_length is not finite (%g)", exclusion_length);
    md::Beam& b = model->m.beam(beam);
    b.self_contact = on == 1;
    b.exclusion = exclusion_length < 0.0 ? -1.0 : exclusion_length;
    return B2B_OK;
  });
}

int b2b_model_set_real(b2b_model* model, const char* key, double value, char* errmsg,
                       int errmsg_len) {
  const Reporter r("b2b_model_set_real", errmsg, errmsg_len);
  return guarded(r, [&]() -> int { return set_by_key(r, model, key, OptionType::Real, value); });
}

int b2b_model_set_int(b2b_model* model, const char* key, int value, char* errmsg,
                      int errmsg_len) {
  const Reporter r("b2b_model_set_int", errmsg, errmsg_len);
  return guarded(r, [&]() -> int { return set_by_key(r, model, key, OptionType::Int, value); });
}

int b2b_model_finalize(b2b_model* model, int n_nodes, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_finalize", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_setup(r, model)) return st;
    if (n_nodes < 1) return r.fail(B2B_ERR_RANGE, "n_nodes is %d (>= 1)", n_nodes);
    if (model->m.beam_count() == 0)
      return r.fail(B2B_ERR_STATE, "the model has no beams (b2b_model_add_beam)");
    const md::Problem pb = model->m.finalize(n_nodes);
    if (pb.status && pb.what == md::Problem::What::NodeRange) {
      // Worded here: the model holds no n_nodes until it is finalized.
      const int o = model->message_base;
      return r.fail(pb.status, "beam %d: node %lld (position %d in its list) is out of range: the "
                    "host has nodes %d .. %d", pb.beam + o, shown(pb.node, o), pb.segment + o, o,
                    n_nodes - 1 + o);
    }
    if (pb.status) return report_model_problem(r, model, pb);
    return B2B_OK;
  });
}

int b2b_model_update(b2b_model* model, const double* x, int ldx, int n_cols, int want_tangent,
                     char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_update", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_model_finalized(r, model)) return st;
    if (x == nullptr) return r.fail(B2B_ERR_NULL, "x is NULL");
    if (ldx < 3) return r.fail(B2B_ERR_SIZE, "ldx is %d (>= 3)", ldx);
    if (n_cols < model->m.n_nodes())
      return r.fail(B2B_ERR_SIZE, "x has %d columns (nodes) but the model has %d nodes", n_cols,
                    model->m.n_nodes());
    if (want_tangent != 0 && want_tangent != 1)
      return r.fail(B2B_ERR_RANGE, "want_tangent is %d (0 or 1)", want_tangent);
    const md::Problem pb = model->m.update(x, ldx, want_tangent == 1);
    if (pb.status) return report_model_problem(r, model, pb);
    return B2B_OK;
  });
}

int b2b_model_update_xu(b2b_model* model, const double* x, int ldx, const double* u, int ldu,
                        int n_cols, int want_tangent, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_update_xu", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_model_finalized(r, model)) return st;
    if (x == nullptr) return r.fail(B2B_ERR_NULL, "x is NULL");
    if (u == nullptr) return r.fail(B2B_ERR_NULL, "u is NULL");
    if (ldx < 3) return r.fail(B2B_ERR_SIZE, "ldx is %d (>= 3)", ldx);
    if (ldu < 3) return r.fail(B2B_ERR_SIZE, "ldu is %d (>= 3)", ldu);
    if (n_cols < model->m.n_nodes())
      return r.fail(B2B_ERR_SIZE, "x and u have %d columns (nodes) but the model has %d nodes",
                    n_cols, model->m.n_nodes());
    if (want_tangent != 0 && want_tangent != 1)
      return r.fail(B2B_ERR_RANGE, "want_tangent is %d (0 or 1)", want_tangent);
    const md::Problem pb = model->m.update(x, ldx, u, ldu, want_tangent == 1);
    if (pb.status) return report_model_problem(r, model, pb);
    return B2B_OK;
  });
}

int b2b_model_contact_count(const b2b_model* model, int* n, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_contact_count", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (n == nullptr) return r.fail(B2B_ERR_NULL, "n is NULL");
    if (int st = check_results(r, model)) return st;
    *n = static_cast<int>(model->m.contacts().size());
    return B2B_OK;
  });
}

int b2b_model_get_contact(const b2b_model* model, int k, int* nodes, int* pair, double* info,
                          double* residual, double* tangent, int ldk, char* errmsg,
                          int errmsg_len) {
  const Reporter r("b2b_model_get_contact", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_results(r, model)) return st;
    const md::Model& m = model->m;
    const int n = static_cast<int>(m.contacts().size());
    const int o = model->message_base;
    if (k < 0 || k >= n)
      return r.fail(B2B_ERR_RANGE, "contact %lld does not exist (%d active contacts%s)", shown(k, o), n,
                    n ? "" : ": none");
    if (tangent != nullptr)
      if (int st = check_tangents(r, model)) return st;
    if (tangent != nullptr && ldk < 24)
      return r.fail(B2B_ERR_SIZE, "ldk is %d, the tangent needs at least 24", ldk);
    const md::Contact& c = m.contacts()[k];
    if (nodes) std::memcpy(nodes, c.nodes, sizeof c.nodes);
    if (pair) {
      const md::SegmentInfo &a = m.table().segment(c.a), &b = m.table().segment(c.b);
      pair[0] = a.beam;
      pair[1] = a.index;
      pair[2] = b.beam;
      pair[3] = b.index;
    }
    if (info) std::memcpy(info, c.info(), sizeof(double) * B2B_PAIR_INFO_LEN);
    if (residual) std::memcpy(residual, c.residual(), sizeof(double) * B2B_PAIR_NDOF);
    if (tangent) {
      double scratch[24 * 24];  // a packed tangent, unpacked
      const double* K = m.tangent(c, scratch);
      for (int col = 0; col < 24; ++col)
        std::memcpy(tangent + static_cast<size_t>(ldk) * col, K + 24 * col, 24 * sizeof(double));
    }
    return B2B_OK;
  });
}

int b2b_model_commit(b2b_model* model, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_commit", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_model_finalized(r, model)) return st;
    if (!model->m.updated())
      return r.fail(B2B_ERR_STATE, "nothing to commit: no update since the last commit, revert "
                    "or restore");
    model->m.commit();
    return B2B_OK;
  });
}

int b2b_model_revert(b2b_model* model, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_revert", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_model_finalized(r, model)) return st;
    model->m.revert();
    return B2B_OK;
  });
}

int b2b_model_save_size(const b2b_model* model, int64_t* size, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_save_size", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (size == nullptr) return r.fail(B2B_ERR_NULL, "size is NULL");
    if (int st = check_model_finalized(r, model)) return st;
    *size = model->m.save_size();
    return B2B_OK;
  });
}

int b2b_model_save(const b2b_model* model, void* buffer, int64_t size, char* errmsg,
                   int errmsg_len) {
  const Reporter r("b2b_model_save", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (buffer == nullptr) return r.fail(B2B_ERR_NULL, "buffer is NULL");
    if (int st = check_model_finalized(r, model)) return st;
    const int64_t need = model->m.save_size();
    if (size < need)
      return r.fail(B2B_ERR_SIZE, "the buffer has %lld bytes, the state needs %lld "
                    "(b2b_model_save_size)", static_cast<long long>(size),
                    static_cast<long long>(need));
    model->m.save(static_cast<unsigned char*>(buffer));
    return B2B_OK;
  });
}

int b2b_model_restore(b2b_model* model, const void* buffer, int64_t size, char* errmsg,
                      int errmsg_len) {
  const Reporter r("b2b_model_restore", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (buffer == nullptr) return r.fail(B2B_ERR_NULL, "buffer is NULL");
    if (int st = check_model_finalized(r, model)) return st;
    if (size < 0) return r.fail(B2B_ERR_SIZE, "size is %lld", static_cast<long long>(size));
    const md::Problem pb =
        model->m.restore(static_cast<const unsigned char*>(buffer), size);
    if (pb.status) return report_model_problem(r, model, pb);
    return B2B_OK;
  });
}

int b2b_model_stats(const b2b_model* model, int* counts, double* totals, char* errmsg,
                    int errmsg_len) {
  const Reporter r("b2b_model_stats", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_results(r, model)) return st;  // none after revert or restore
    if (counts) std::memcpy(counts, model->m.counts(), B2B_MODEL_COUNTS_LEN * sizeof(int));
    if (totals) std::memcpy(totals, model->m.totals(), B2B_MODEL_TOTALS_LEN * sizeof(double));
    return B2B_OK;
  });
}

}  // extern "C"
