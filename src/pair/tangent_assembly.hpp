// The third stage of the contact element: the exact tangent of an active
// pair, K = d(residual)/dX, 24 x 24 (doc/contact-element.md, doc/friction.md):
//   K = -f' G G^T - f sum n.d2x/dX2 - (f/rho)(J^T (I - n n^T) J - B^T H^-1 B)
//       [+ the friction part, not symmetric]
// computed on the columns of the slots the segments read and scattered into
// the full matrix.
#pragma once

#include "contact_kinematics.hpp"
#include "friction.hpp"
#include "normal_law.hpp"

namespace b2b {
namespace pair {

struct TangentResult {
  bool finite = true;     // no entry overflowed
  bool symmetric = true;  // exactly symmetric (no friction, axes apart)
};

// K: 24 x 24, column-major, leading dimension kNdof; fully written. fc and
// fr: the friction state of the residual (read only when params.friction > 0).
// PA, PAd, PB, PBd: the 3 x 12 jacobians of both segments at the closest points.
TangentResult assemble_tangent(const Params& params, const SegmentRef& A, const SegmentRef& B,
                               const Kinematics& k, const LawValue& law,
                               const FrictionContact& fc, const FrictionResult& fr,
                               const double* PA, const double* PAd, const double* PB,
                               const double* PBd, double* K);

}  // namespace pair
}  // namespace b2b
