// The tangents other than the exact one ("tangent" option, B2B_TANGENT_*):
// its symmetric part, the main term alone, and central finite differences of
// the residual. The exact one is tangent_assembly.hpp's.
#pragma once

#include <functional>

#include <b2b/b2b.h>

#include "../common/enumeration.hpp"
#include "contact_kinematics.hpp"
#include "linearization.hpp"
#include "params.hpp"

namespace b2b {
namespace pair {

// The values of the "tangent" option, in value order (what its check and
// message read, src/capi/capi_params.cpp).
inline constexpr NamedValue kTangentModes[] = {
    {B2B_NAMED(B2B_TANGENT_EXACT)},
    {B2B_NAMED(B2B_TANGENT_SYMMETRIC)},
    {B2B_NAMED(B2B_TANGENT_MAIN)},
    {B2B_NAMED(B2B_TANGENT_FD)},
};
static_assert(in_value_order(kTangentModes), "kTangentModes lists B2B_TANGENT_* in value order");

inline constexpr Enumeration kTangentModeEnumeration = enumeration_of(kTangentModes);

// K = (K + K^T) / 2 on its leading n x n block (leading dimension 24; n 24
// for all of K, less for a compact tangent, TangentColumns); finite entries
// give finite ones (no overflow in the sum).
void symmetrize(double* K, int n = kNdof);

// K = -slope G G^T with G = [P_A^T n; -P_B^T n] (the main term).
void main_term(double slope, const double* PA, const double* PB, const double* n, double* K);

// K(:, c) = (r(X + h e_c) - r(X - h e_c)) / (2 h) on the columns of slots the
// segments read (the rest zero), h = 1e-6 of the mean chord, hist_old held
// fixed. Needs the segments' patches (SegmentRef::X); a column whose
// perturbed patch cannot be built keeps what K held.
void fd_tangent(const Params& params, const SegmentRef& A, const SegmentRef& B,
                const double* hist_old, double* K, Ends ends = Ends());

// The same differences of any residual of the pair: residual(A', B', r)
// writes the 24 entries r on the segments A', B' (one of them perturbed).
// The line element's B2B_TANGENT_FD.
using PairResidual = std::function<void(const SegmentRef&, const SegmentRef&, double*)>;
void fd_tangent_of(const SegmentRef& A, const SegmentRef& B, double* K,
                   const PairResidual& residual);

}  // namespace pair
}  // namespace b2b
