// The third stage of the contact element: the exact tangent of an active
// pair, K = d(residual)/dX, 24 x 24 (doc/contact-element.md, doc/friction.md):
//   K = -f' G G^T - f sum n.d2x/dX2 - (f/rho)(J^T (I - n n^T) J - B^T H^-1 B)
//       [+ the friction part, not symmetric]
// computed on the columns of the slots the segments read and scattered into
// the full matrix.
#pragma once

#include "contact_kinematics.hpp"
#include "friction.hpp"
#include "linearization.hpp"
#include "normal_law.hpp"

namespace b2b {
namespace pair {

struct TangentResult {
  bool finite = true;     // no entry overflowed
  bool symmetric = true;  // exactly symmetric (no friction, axes apart)
};

// Which rows and columns of K a tangent left compact holds. Where both
// segments are linear in X (linear, hermite-midpoint) and a segment's patch
// has slots it does not read, only m < 24 rows and columns of K can be
// nonzero: a caller that copies K out anyway (the C API, into the host's
// array) takes the m x m matrix of those (leading dimension kNdof, both
// triangles) and writes the whole of K itself with expand_tangent(), instead
// of the element zeroing 576 entries and scattering into them first (that
// was a fifth of the linear kind's residual + tangent, doc/performance.md).
// m == kNdof: K is all of K (cols unused); m == 0: K is zero, not written.
struct TangentColumns {
  int m = kNdof;
  int cols[kNdof];  // the m indices in 0..23, ascending, in whole slots of 3
};

// K: 24 x 24, column-major, leading dimension kNdof; fully written, or, with
// compact not null, possibly only its leading m x m block (compact->m). fc
// and fr: the friction state of the residual (read only when
// params.friction > 0). PA, PAd, PB, PBd: the 3 x 12 jacobians of both
// segments at the closest points.
TangentResult assemble_tangent(const Params& params, const SegmentRef& A, const SegmentRef& B,
                               const Kinematics& k, const LawValue& law,
                               const FrictionContact& fc, const FrictionResult& fr,
                               const double* PA, const double* PAd, const double* PB,
                               const double* PBd, double* K, TangentColumns* compact = nullptr);

// The whole 24 x 24 tangent into dst (column-major, leading dimension ld >=
// 24; rows 24..ld-1 not written) from K as the element left it (used).
void expand_tangent(const double* K, const TangentColumns& used, double* dst, int ld);

}  // namespace pair
}  // namespace b2b
