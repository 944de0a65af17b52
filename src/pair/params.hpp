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
  // Line contact (line_contact.hpp): which element the contact model uses
  // (B2B_CONTACT_TYPE_*), the penalties per unit length, the integration
  // points (0: the default rule) and the blending range of the crossing
  // angle (degrees) for B2B_CONTACT_TYPE_ALL_ANGLE.
  int contact_type = 0;
  double line_penalty = 0.0;
  bool line_penalty_set = false;
  double line_tangential_penalty = 0.0;
  bool line_tangential_penalty_set = false;
  int line_points = 0;
  double line_angle_deg = 5.0;
  double point_angle_deg = 15.0;
  bool finalized = false;
  // derived by finalize
  double sin_parallel_angle = 0.0;
  double sin2_line_angle = 0.0, sin2_point_angle = 0.0;
};

// What finalize() found missing (a required option never set) or
// inconsistent (the blending range).
enum class MissingOption {
  None,
  Penalty,
  RegularizationGap,
  TangentialPenalty,
  LinePenalty,
  LineTangentialPenalty,
  BlendRange
};

// Whether the parameters hold what the line-contact element needs: its
// penalty, and its tangential penalty with friction (None if so). For
// b2b_pair_eval_line with a "contact_type" that did not make finalize ask.
MissingOption line_contact_missing(const Params& p);

// The parameter set of the line element's integration points: the point
// element's with the penalties per unit length.
Params line_point_params(const Params& p);

// Checks the options together and derives what evaluation needs; on success
// the set is read-only (finalized). Finalizing twice is harmless.
MissingOption finalize(Params& p);

}  // namespace pair
}  // namespace b2b
