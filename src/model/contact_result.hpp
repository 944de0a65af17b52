// The outputs of one active contact as the model keeps them from an update
// to the next: a block of doubles holding its info (pair::kInfoLength), its
// residual (pair::kNdof) and its tangent, written once by the thread that
// evaluates the pair into the model's next set of results (page_pool.hpp)
// and read in place by the assembly, the COO pattern and
// b2b_model_get_contact.
//
// The tangent (24 x 24, column-major) takes 4.6 kB, most of a contact's
// memory, and the model holds two sets of them while an update runs (the
// last update's, kept in case this one fails, and its own). A frictionless
// contact's tangent is symmetric: the element writes one triangle and
// mirrors it (pair/tangent_assembly.cpp), so both triangles hold the same
// bits. Such a tangent is kept as its upper triangle, packed (300 doubles),
// and mirrored back where it is read: the host sees the very same bits. The
// test is on the bits, not on what the element says, so a tangent that is
// symmetric only up to rounding is kept whole.
#pragma once

#include <cstddef>
#include <cstdint>

#include "../pair/contact_element.hpp"
#include "../pair/linearization.hpp"

namespace b2b {
namespace model {

enum class TangentForm : uint8_t {
  None,    // no tangent (an update without tangents)
  Full,    // kNdof * kNdof, column-major
  Packed   // upper triangle, column by column: (r, c), r <= c, at c (c + 1) / 2 + r
};

constexpr size_t kPackedTangent = pair::kNdof * (pair::kNdof + 1) / 2;

// The form K (null: none) is kept in: Packed if it is symmetric bit for bit.
TangentForm tangent_form(const double* K);

// Doubles of a block holding a tangent of that form.
size_t result_length(TangentForm form);

// Writes info, residual and K (in form; K unread for None) to block
// (result_length(form) doubles).
void write_result(const double* info, const double* residual, const double* K, TangentForm form,
                  double* block);

inline const double* result_info(const double* block) { return block; }
inline const double* result_residual(const double* block) { return block + pair::kInfoLength; }

// The tangent of a block, kNdof * kNdof column-major: in place (Full), or
// unpacked into scratch (Packed, kNdof * kNdof doubles); null for None.
const double* result_tangent(const double* block, TangentForm form, double* scratch);

// One active contact of the last update.
struct Contact {
  int a, b;  // segments (oriented)
  int nodes[8];
  const double* result = nullptr;  // its block, in Model::results_
  TangentForm form = TangentForm::None;
  const double* info() const { return result_info(result); }
  const double* residual() const { return result_residual(result); }
};

}  // namespace model
}  // namespace b2b
