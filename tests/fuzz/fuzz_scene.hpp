// Structured inputs for the fuzz targets, decoded from the fuzzer's bytes:
// parameter sets, curve kinds and end rules, curved node chains, crossings
// of two segments at any angle and distance, at any scale and offset, with
// coincident or folded nodes, and motions of a crossing from one step to the
// next. Random bytes mostly decode to inputs b2b accepts, so the fuzzer
// spends its time inside the element and not in the argument checks; the
// raw-double path (fuzz_input.hpp, inject_wild) covers those.
#pragma once

#include <b2b/b2b.h>

#include "fuzz_input.hpp"

namespace b2b_fuzz {

struct SegmentSpec {
  int kind, start_rule, end_rule;
};

// A segment's kind and end rules: a valid combination most of the time
// (interior, beam start, beam end or both, by reflection or host tangent),
// an unknown value now and then.
SegmentSpec decode_segment(FuzzInput& in);
bool valid_segment(const SegmentSpec& s);
// Patch slots the segment reads (bit k: slot x(k+1)), as in b2b_curve.h;
// all four for an invalid spec.
unsigned used_slots(const SegmentSpec& s);
// Overwrites the slots the segment does not read with garbage (NaN, Inf,
// huge): b2b_curve.h promises they are never read.
void poison_unused(FuzzInput& in, const SegmentSpec& s, double patch[12]);

// A curved chain of n nodes in local coordinates (3 n doubles): elements of
// length about 1 (uniform, uneven, or one element many decades shorter or
// longer), turning at each node by up to a decoded angle (up to a near fold).
void decode_chain(FuzzInput& in, int n, double* x);
// Makes a chain degenerate: two neighbours coincide (B2B_ERR_COINCIDENT), a
// node's neighbours coincide (B2B_ERR_FOLDED), or nodes a rounding error
// apart.
void decode_degeneracy(FuzzInput& in, double* x, int n);

// Rotation, uniform scale and offset of a scene: scales from 1e-95 to 1e95,
// offsets up to 1e18 times the scale (where coordinates lose their digits).
struct Placement {
  double R[9];  // column-major rotation
  double scale;
  double offset[3];
};
Placement decode_placement(FuzzInput& in);
void place_points(const Placement& p, const double* local, double* out, int n);
void rotate(const double R[9], const double v[3], double out[3]);
void random_rotation(FuzzInput& in, double R[9]);

// Host end tangents for a patch (start, then end): along the end chords,
// tilted, reversed, tiny, huge or zero.
void decode_end_tangents(FuzzInput& in, const double patch[12], double t[6]);

// A finalized parameter set chosen by the input (nullptr if the library
// refused the choice, which is a valid outcome). scale is the scene's
// length scale, so that gaps and penalties are in proportion to it.
struct ParamsInfo {
  int law = 0, max_iterations = 50, tangent = 0, warm_start = 0, hist_len = 8;
  double penalty = 0, regularization_gap = 0, friction = 0, tangential_penalty = 0;
};
b2b_params* decode_params(FuzzInput& in, double scale, ParamsInfo* info, int max_iterations_cap);

// Two segments whose tangents at xi*, eta* cross at a decoded angle (0 to
// 90 degrees, near-parallel down to 1e-12 degrees, exactly parallel), with
// the axes a decoded distance apart along their common normal (penetrating,
// touching, open, exactly intersecting), then placed and possibly
// degenerated. X, tangents and radii are b2b_pair_eval's arguments.
struct Crossing {
  SegmentSpec seg[2];
  double X[24];
  double tangents[12];
  double radii[2];
  double normal[3];  // common normal at the crossing (unit; from B to A before placement)
  double scale;      // the placement's scale (element length)
};
void decode_crossing(FuzzInput& in, Crossing& c);
// The crossing one step later: small random motion of every node, B slid
// along A (across joints), B pushed through A, a rigid rotation of both.
void decode_motion(FuzzInput& in, const Crossing& c, double X[24]);

}  // namespace b2b_fuzz
