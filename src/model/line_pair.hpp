// The contact model's line pairs (group pairs of "contact_type" LINE or
// ALL_ANGLE; pair/line_contact.hpp): how many integration points a pair
// has, how a fresh point takes its committed history over from the pair of
// B's neighbouring segment that owned it, and the summary of a line pair in
// the point element's info layout (what b2b_model_get_contact reports).
#pragma once

#include <vector>

#include "../pair/contact_element.hpp"
#include "../pair/line_contact.hpp"
#include "beam_table.hpp"
#include "contact_state.hpp"
#include "search.hpp"

namespace b2b {
namespace model {

// A committed line pair keeps its count ((length / hl) - 1); a new one
// takes line_points() of A's current chord.
int line_pair_points(const pair::Params& p, const pair::SegmentRef& A, const pair::SegmentRef& B,
                     int committed_length, int hl);

// Each point of hist (n + 1 histories of hl doubles; slot 0 the point
// element's) that this pair did not own at the commit (no history, or its
// committed eta outside [-1, 1)) takes the committed history of the pair
// (a, neighbour of b) that owned it, mapped across B's joint
// (handover_committed): its friction force and normal follow the point.
// Slot 0 (ALL_ANGLE's point element) likewise from the pair of a
// neighbouring segment of B or of A (one joint per update).
void take_over_points(const BeamTable& table, const ContactState& committed,
                      const std::vector<double>& committed_coords, const NodeIndex& used_index,
                      int a, int b, int n, int hl, double* hist);

// res: status, overflow and residual of lr; info: the integrated normal
// force, energy and dissipation, the smallest gap, symmetry, the count of
// points carrying force (B2B_INFO_LINE_POINTS), SLIP if a point slips else
// STICK if one sticks (the point part of ALL_ANGLE included), and xi, eta,
// the points, the normal and the angle of the deepest point carrying force
// (point_info of evaluate_line), or of the point part where it carries at
// least half (its weight >= 1/2), with its weighted tangential force.
void summarize_line(const pair::LineResult& lr, const double* point_info, int n,
                    pair::PairResult& res);

}  // namespace model
}  // namespace b2b
