// C entry points of distributed models (b2b_model.h, "Distributed models"):
// global ids, ghosts, contacts in global ids, and the migration of contacts
// between ranks. Argument checks and messages only; src/model/partition and
// src/model/migration do the work.
#include <climits>
#include <cstdint>
#include <cstring>

#include <b2b/b2b.h>

#include "../curve/topology.hpp"
#include "../model/migration.hpp"
#include "model_handle.hpp"

using b2b::capi::check_model_finalized;
using b2b::capi::check_results;
using b2b::capi::guarded;
using b2b::capi::report_model_problem;
using b2b::capi::Reporter;
namespace md = b2b::model;

namespace {

long long shown(int value, int base) { return static_cast<long long>(value) + base; }

// B2B_ERR_NULL / _STATE (finalized) / _RANGE (no such beam) for the set-up calls.
int check_beam(const Reporter& r, const b2b_model* model, int beam) {
  if (model == nullptr) return r.fail(B2B_ERR_NULL, "model is NULL");
  if (model->m.finalized())
    return r.fail(B2B_ERR_STATE, "the model is finalized: global ids and ghosts are set before "
                  "b2b_model_finalize");
  const int o = model->message_base;
  if (beam < 0 || beam >= model->m.beam_count())
    return r.fail(B2B_ERR_RANGE, "beam %lld does not exist (beams %d .. %d)", shown(beam, o), o,
                  model->m.beam_count() - 1 + o);
  return B2B_OK;
}

int segments_of(const md::Beam& b) {
  return b2b::curve::segment_count(b.kind, static_cast<int>(b.nodes.size()), b.closed);
}

// Migrating contact k of the last update: B2B_ERR_STATE / _RANGE.
int check_migrant(const Reporter& r, const b2b_model* model, int k) {
  if (int st = check_results(r, model)) return st;
  const int n = static_cast<int>(model->m.migration().outgoing.size());
  const int o = model->message_base;
  if (k < 0 || k >= n)
    return r.fail(B2B_ERR_RANGE, "migrating contact %lld does not exist (%d migrating contacts%s)",
                  shown(k, o), n, n ? "" : ": none");
  return B2B_OK;
}

}  // namespace

namespace b2b {
namespace capi {

int report_partition_problem(const Reporter& r, const b2b_model* model, const md::Problem& pb) {
  using I = md::PartitionIssue;
  const int o = model->message_base;
  switch (static_cast<I>(pb.code)) {
    case I::GhostsWithoutIds:
      return r.fail(pb.status, "beam %d has ghost segments but no beam has a global id: a model "
                    "with ghosts gives every beam one (b2b_model_set_beam_global)", pb.beam + o);
    case I::SomeWithoutIds:
      return r.fail(pb.status, "beam %d has no global id but beam %d has one: either every beam "
                    "of a model gets b2b_model_set_beam_global or none", pb.beam + o,
                    pb.other_beam + o);
    case I::Order:
      return r.fail(pb.status, "beam %d comes before beam %d in global order (global beam, "
                    "first segment): add beams in increasing global order", pb.beam + o,
                    pb.other_beam + o);
    case I::Overlap:
      return r.fail(pb.status, "beam %d overlaps beam %d: pieces of one global beam may not "
                    "share segments (the first segment of the later piece is within the "
                    "earlier one)", pb.beam + o, pb.other_beam + o);
    case I::Differ:
      return r.fail(pb.status, "beams %d and %d are pieces of one global beam but differ in "
                    "kind, radius, group, self-contact or are closed", pb.other_beam + o,
                    pb.beam + o);
    case I::PaddingOwn:
      return r.fail(pb.status, "beam %d, segment %d is at a cut, so it is padding, but it is "
                    "not a ghost: a piece reaches one ghost segment beyond the segments it "
                    "owns (b2b_model_set_ghost_segments)", pb.beam + o, pb.segment + o);
  }
  return r.fail(B2B_ERR_INTERNAL, "unclassified partition problem (%d)", pb.code);
}

}  // namespace capi
}  // namespace b2b

extern "C" {

int b2b_model_set_beam_global(b2b_model* model, int beam, int64_t global_beam, int first_segment,
                              int start_cut, int end_cut, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_set_beam_global", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_beam(r, model, beam)) return st;
    const int o = model->message_base;
    const md::Beam& b = model->m.beam(beam);
    if (global_beam < 0)
      return r.fail(B2B_ERR_RANGE, "beam %d: global_beam is %lld (>= %d)", beam + o,
                    static_cast<long long>(global_beam) + o, o);
    if (first_segment < 0)
      return r.fail(B2B_ERR_RANGE, "beam %d: first_segment is %lld (>= %d)", beam + o,
                    shown(first_segment, o), o);
    if (start_cut != 0 && start_cut != 1)
      return r.fail(B2B_ERR_RANGE, "beam %d: start_cut is %d (0 or 1)", beam + o, start_cut);
    if (end_cut != 0 && end_cut != 1)
      return r.fail(B2B_ERR_RANGE, "beam %d: end_cut is %d (0 or 1)", beam + o, end_cut);
    if (b.closed && (start_cut || end_cut))
      return r.fail(B2B_ERR_RANGE, "beam %d is closed: a closed beam cannot be cut", beam + o);
    if (b.closed && first_segment != 0)
      return r.fail(B2B_ERR_RANGE, "beam %d is closed, so it is whole: first_segment is %lld, "
                    "not %d", beam + o, shown(first_segment, o), o);
    if (start_cut && first_segment == 0)
      return r.fail(B2B_ERR_RANGE, "beam %d: a cut at its start, but its first segment is the "
                    "global beam's first (first_segment %d): nothing lies before it", beam + o,
                    o);
    const int n = segments_of(b);
    if (static_cast<int64_t>(first_segment) + n > INT_MAX)
      return r.fail(B2B_ERR_RANGE, "beam %d: first_segment %lld + its %d segments is beyond "
                    "INT_MAX", beam + o, shown(first_segment, o), n);
    model->m.partition().set_beam(beam, global_beam, first_segment, start_cut == 1,
                                  end_cut == 1);
    return B2B_OK;
  });
}

int b2b_model_set_ghost_segments(b2b_model* model, int beam, int first, int count, char* errmsg,
                                 int errmsg_len) {
  const Reporter r("b2b_model_set_ghost_segments", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_beam(r, model, beam)) return st;
    const int o = model->message_base;
    const int n = segments_of(model->m.beam(beam));
    if (count < 0)
      return r.fail(B2B_ERR_RANGE, "beam %d: count is %d (>= 0)", beam + o, count);
    if (first < 0 || first >= n || count > n - first)
      return r.fail(B2B_ERR_RANGE, "beam %d: ghost segments %lld .. %lld are beyond its "
                    "segments %d .. %d", beam + o, shown(first, o),
                    static_cast<long long>(first) + count - 1 + o, o, n - 1 + o);
    model->m.partition().add_ghosts(beam, first, count);
    return B2B_OK;
  });
}

int b2b_model_get_contact_global(const b2b_model* model, int k, int64_t* pair, char* errmsg,
                                 int errmsg_len) {
  const Reporter r("b2b_model_get_contact_global", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (pair == nullptr) return r.fail(B2B_ERR_NULL, "pair is NULL");
    if (int st = check_results(r, model)) return st;
    const md::Model& m = model->m;
    const int n = static_cast<int>(m.contacts().size());
    const int o = model->message_base;
    if (k < 0 || k >= n)
      return r.fail(B2B_ERR_RANGE, "contact %lld does not exist (%d active contacts%s)",
                    shown(k, o), n, n ? "" : ": none");
    const md::Contact& c = m.contacts()[k];
    const md::SegmentInfo &a = m.table().segment(c.a), &b = m.table().segment(c.b);
    const md::Partition& part = m.partition();
    pair[0] = part.global_beam(a);
    pair[1] = part.global_segment(a);
    pair[2] = part.global_beam(b);
    pair[3] = part.global_segment(b);
    return B2B_OK;
  });
}

int b2b_model_migration_count(const b2b_model* model, int* n, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_migration_count", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (n == nullptr) return r.fail(B2B_ERR_NULL, "n is NULL");
    if (int st = check_results(r, model)) return st;
    *n = static_cast<int>(model->m.migration().outgoing.size());
    return B2B_OK;
  });
}

int b2b_model_migration_info(const b2b_model* model, int k, int64_t* target, int64_t* size,
                             char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_migration_info", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (int st = check_migrant(r, model, k)) return st;
    const md::Migrant& mg = model->m.migration().outgoing[k];
    if (target) std::memcpy(target, mg.target, sizeof mg.target);
    if (size) *size = md::MigrationCodec::packed_size(mg);
    return B2B_OK;
  });
}

int b2b_model_migration_pack(const b2b_model* model, int k, void* buffer, int64_t size,
                             char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_migration_pack", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (buffer == nullptr) return r.fail(B2B_ERR_NULL, "buffer is NULL");
    if (int st = check_migrant(r, model, k)) return st;
    const md::Migrant& mg = model->m.migration().outgoing[k];
    const int64_t need = md::MigrationCodec::packed_size(mg);
    if (size < need)
      return r.fail(B2B_ERR_SIZE, "the buffer has %lld bytes, the packed contact needs %lld "
                    "(b2b_model_migration_info)", static_cast<long long>(size),
                    static_cast<long long>(need));
    md::MigrationCodec::pack(model->m, mg, static_cast<unsigned char*>(buffer));
    return B2B_OK;
  });
}

int b2b_model_migration_unpack(b2b_model* model, const void* buffer, int64_t size, int* changed,
                               char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_migration_unpack", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (changed == nullptr) return r.fail(B2B_ERR_NULL, "changed is NULL");
    if (int st = check_model_finalized(r, model)) return st;
    if (buffer == nullptr && size == 0) {  // the end of a round
      *changed = model->m.end_migration_round() ? 1 : 0;
      return B2B_OK;
    }
    if (buffer == nullptr)
      return r.fail(B2B_ERR_NULL, "buffer is NULL (with size %lld; NULL with size 0 ends a "
                    "round)", static_cast<long long>(size));
    if (size < 0) return r.fail(B2B_ERR_SIZE, "size is %lld", static_cast<long long>(size));
    bool ch = false;
    const md::Problem pb = md::MigrationCodec::unpack(
        model->m, static_cast<const unsigned char*>(buffer), size, &ch);
    if (pb.status) return report_model_problem(r, model, pb);
    *changed = ch ? 1 : 0;
    return B2B_OK;
  });
}

}  // extern "C"
