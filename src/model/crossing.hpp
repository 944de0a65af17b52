// Beams that crossed since the last commit (tunnelling). Between two
// converged states a host may move beams by more than their thickness; two
// centrelines can then pass through each other within one step and be
// apart again, on the wrong side, at the next update: the unsigned gap says
// "open" and no contact is ever formed. The element already keeps an active
// contact's side by its committed normal (doc/contact-element.md section 6);
// this gives every other pair the same reference:
//   - the broad phase searches each segment's box swept from its committed
//     to its current position (their union), so a pair that met anywhere on
//     the way is a candidate;
//   - a pair with no committed history whose segments moved, since the
//     commit, by more than their present axis distance (else they cannot
//     have passed through each other: the distance would have had to reach
//     0) gets the normal of its closest points on the committed geometry; if
//     the current closest points lie on the other side of it, the pair is
//     evaluated with that normal as its history: an active contact with its
//     signed gap, below -(r_A + r_B) (b2b_model.h, B2B_COUNT_CROSSED).
#pragma once

#include <vector>

#include "beam_table.hpp"
#include "search.hpp"

namespace b2b {
namespace model {

// Each segment's box on the committed coordinates, and how far its patch
// nodes moved since (the largest displacement of one of them).
struct CommittedMotion {
  std::vector<Box> boxes;
  std::vector<double> moved;
};

// Segment s's entries of out (sized for every segment by the caller; one
// segment per call, so that the update fills them in parallel). coords,
// committed: the used nodes' current and committed coordinates.
void segment_motion(const BeamTable& table, int s, const double* coords, const double* committed,
                    const NodeIndex& used_index, CommittedMotion& out);

// Whether the pair (a, b), with current closest points at axis distance rho,
// can have crossed since the commit: its segments moved by at least rho
// together, and by at least their committed boxes' distance.
bool may_have_crossed(const CommittedMotion& cm, int a, int b, double rho);

// A synthetic committed history for the pair (a, b) (history.hpp's layout,
// hist_len doubles): tag, the unit normal from B to A at the closest points
// of the committed geometry, and their parameters. False (hist untouched)
// where the committed segments cannot be built or their axes meet.
bool committed_history(const SegmentInfo& a, const SegmentInfo& b, const double* committed,
                       const NodeIndex& used_index, int max_iterations, double* hist,
                       int hist_len);

// The same for a line pair of n integration points (pair/line_contact.hpp;
// (n + 1) histories of hl doubles): slot 0 as committed_history (the
// all-angle blend's point element), slot i the normal from B to A at the
// projection of A's integration point i onto B on the committed geometry
// (its eta as the search found it, beyond [-1, 1] where the projection lies
// on B's neighbour). A slot whose axes meet stays fresh. False (hist
// untouched) where the committed segments cannot be built.
bool committed_line_histories(const SegmentInfo& a, const SegmentInfo& b, const double* committed,
                              const NodeIndex& used_index, int max_iterations, int n, int hl,
                              double* hist);

}  // namespace model
}  // namespace b2b
