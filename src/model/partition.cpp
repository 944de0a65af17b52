#include "partition.hpp"

#include <algorithm>
#include <climits>

#include <b2b/b2b.h>

#include "model.hpp"

namespace b2b {
namespace model {

void Partition::set_beam(int beam, int64_t global_beam, int first_segment, bool start_cut,
                         bool end_cut) {
  if (beam >= static_cast<int>(setup_.size())) setup_.resize(static_cast<size_t>(beam) + 1);
  Setup& s = setup_[beam];
  s.set = true;
  s.global_beam = global_beam;
  s.first_segment = first_segment;
  s.start_cut = start_cut;
  s.end_cut = end_cut;
}

void Partition::add_ghosts(int beam, int first, int count) {
  if (count <= 0) return;
  if (beam >= static_cast<int>(setup_.size())) setup_.resize(static_cast<size_t>(beam) + 1);
  setup_[beam].ghosts.emplace_back(first, count);
}

namespace {

Problem partition_problem(int status, PartitionIssue issue, int beam, int other_beam = -1,
                          int segment = -1) {
  Problem pb;
  pb.status = status;
  pb.what = Problem::What::Partition;
  pb.code = static_cast<int>(issue);
  pb.beam = beam;
  pb.other_beam = other_beam;
  pb.segment = segment;
  return pb;
}

}  // namespace

Problem Partition::finalize(const std::vector<Beam>& beams) {
  const int nb = static_cast<int>(beams.size());
  int first_set = -1, first_unset = -1, first_ghosts = -1;
  for (int b = 0; b < nb; ++b) {
    if (beam_set(b)) {
      if (first_set < 0) first_set = b;
    } else if (first_unset < 0) {
      first_unset = b;
    }
    if (first_ghosts < 0 && b < static_cast<int>(setup_.size()) && !setup_[b].ghosts.empty())
      first_ghosts = b;
  }
  if (first_set < 0) {  // serial
    if (first_ghosts >= 0)
      return partition_problem(B2B_ERR_STATE, PartitionIssue::GhostsWithoutIds, first_ghosts);
    partitioned_ = false;
    global_beam_.clear();
    first_.clear();
    role_.clear();
    return Problem();
  }
  if (first_unset >= 0)
    return partition_problem(B2B_ERR_STATE, PartitionIssue::SomeWithoutIds, first_unset,
                             first_set);
  for (int b = 1; b < nb; ++b) {
    const Setup &p = setup_[b - 1], &q = setup_[b];
    if (q.global_beam < p.global_beam ||
        (q.global_beam == p.global_beam && q.first_segment < p.first_segment))
      return partition_problem(B2B_ERR_RANGE, PartitionIssue::Order, b, b - 1);
    if (q.global_beam != p.global_beam) continue;
    if (static_cast<int64_t>(q.first_segment) <
        static_cast<int64_t>(p.first_segment) + beams[b - 1].n_segments)
      return partition_problem(B2B_ERR_RANGE, PartitionIssue::Overlap, b, b - 1);
    const Beam &x = beams[b - 1], &y = beams[b];
    if (x.kind != y.kind || x.radius != y.radius || x.group != y.group ||
        x.self_contact != y.self_contact || x.exclusion != y.exclusion || x.closed || y.closed)
      return partition_problem(B2B_ERR_RANGE, PartitionIssue::Differ, b, b - 1);
  }
  std::vector<uint8_t> role;
  std::vector<int64_t> global_beam(nb);
  std::vector<int> first(nb);
  for (int b = 0; b < nb; ++b) {
    const Beam& beam = beams[b];
    const Setup& s = setup_[b];
    global_beam[b] = s.global_beam;
    first[b] = s.first_segment;
    role.resize(static_cast<size_t>(beam.first_segment + beam.n_segments), kOwn);
    for (const auto& g : s.ghosts)
      for (int k = g.first; k < g.first + g.second; ++k) role[beam.first_segment + k] = kGhost;
    // The segment at a cut: padding, which must be a ghost (a piece
    // reaches one segment beyond what it owns and needs).
    for (int cut = 0; cut < 2; ++cut) {
      if (!(cut == 0 ? s.start_cut : s.end_cut)) continue;
      const int k = cut == 0 ? 0 : beam.n_segments - 1;
      uint8_t& r = role[beam.first_segment + k];
      if (r == kOwn) return partition_problem(B2B_ERR_RANGE, PartitionIssue::PaddingOwn, b, -1, k);
      r = kPadding;
    }
  }
  role_.swap(role);
  global_beam_.swap(global_beam);
  first_.swap(first);
  partitioned_ = true;
  return Problem();
}

int Partition::local_segment(const std::vector<Beam>& beams, int64_t global_beam,
                             int64_t global_segment) const {
  const int nb = static_cast<int>(beams.size());
  if (!partitioned_) {
    if (global_beam < 0 || global_beam >= nb || global_segment < 0 ||
        global_segment >= beams[global_beam].n_segments)
      return -1;
    return beams[global_beam].first_segment + static_cast<int>(global_segment);
  }
  // The last piece that starts at or before (global_beam, global_segment).
  int lo = 0, hi = nb;  // pieces [0, lo) start at or before it
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    const bool before = global_beam_[mid] < global_beam ||
                        (global_beam_[mid] == global_beam && first_[mid] <= global_segment);
    if (before)
      lo = mid + 1;
    else
      hi = mid;
  }
  if (lo == 0) return -1;
  const int b = lo - 1;
  if (global_beam_[b] != global_beam) return -1;
  const int64_t k = global_segment - first_[b];
  if (k < 0 || k >= beams[b].n_segments) return -1;
  return beams[b].first_segment + static_cast<int>(k);
}

std::vector<int64_t> Partition::signature() const {
  std::vector<int64_t> sig;
  if (!partitioned_) return sig;
  for (size_t b = 0; b < global_beam_.size(); ++b) {
    sig.push_back(global_beam_[b]);
    sig.push_back(first_[b]);
  }
  for (uint8_t r : role_) sig.push_back(r);
  return sig;
}

}  // namespace model
}  // namespace b2b
