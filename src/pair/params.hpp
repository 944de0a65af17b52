// Contact parameters of the pair layer: what b2b_params holds. Validated key
// by key when set and together when finalized; read-only afterwards.
#pragma once

namespace b2b {
namespace pair {

struct Params {
  double penalty = 0.0;
  bool penalty_set = false;
  int law = 0;  // B2B_LAW_*
  double regularization_gap = 0.0;
  bool regularization_gap_set = false;
  double parallel_angle_deg = 0.5;
  int warm_start = 0;
  int max_iterations = 50;
  double friction = 0.0;  // Coulomb coefficient mu
  double tangential_penalty = 0.0;
  bool tangential_penalty_set = false;
  int tangent = 0;  // B2B_TANGENT_*
  bool finalized = false;
  // derived by finalize
  double sin_parallel_angle = 0.0;
};

// What finalize() found missing (a required option never set).
enum class MissingOption { None, Penalty, RegularizationGap, TangentialPenalty };

// Checks the options together and derives what evaluation needs; on success
// the set is read-only (finalized). Finalizing twice is harmless.
MissingOption finalize(Params& p);

}  // namespace pair
}  // namespace b2b
