#include "contact_result.hpp"

#include <cstring>

namespace b2b {
namespace model {

namespace {

constexpr int kN = pair::kNdof;

inline uint64_t bits(double v) {
  uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

}  // namespace

TangentForm tangent_form(const double* K) {
  if (!K) return TangentForm::None;
  for (int c = 1; c < kN; ++c)
    for (int r = 0; r < c; ++r)
      if (bits(K[r + kN * c]) != bits(K[c + kN * r])) return TangentForm::Full;
  return TangentForm::Packed;
}

size_t result_length(TangentForm form) {
  const size_t head = pair::kInfoLength + pair::kNdof;
  switch (form) {
    case TangentForm::Full: return head + kN * kN;
    case TangentForm::Packed: return head + kPackedTangent;
    default: return head;
  }
}

void write_result(const double* info, const double* residual, const double* K, TangentForm form,
                  double* block) {
  std::memcpy(block, info, sizeof(double) * pair::kInfoLength);
  std::memcpy(block + pair::kInfoLength, residual, sizeof(double) * pair::kNdof);
  double* t = block + pair::kInfoLength + pair::kNdof;
  if (form == TangentForm::Full) {
    std::memcpy(t, K, sizeof(double) * kN * kN);
  } else if (form == TangentForm::Packed) {
    for (int c = 0; c < kN; ++c) {
      std::memcpy(t, K + kN * c, sizeof(double) * (c + 1));
      t += c + 1;
    }
  }
}

const double* result_tangent(const double* block, TangentForm form, double* scratch) {
  const double* t = block + pair::kInfoLength + pair::kNdof;
  if (form == TangentForm::Full) return t;
  if (form != TangentForm::Packed) return nullptr;
  // Column c's entries r <= c as stored; the rest mirrored from row c.
  for (int c = 0; c < kN; ++c) {
    const double* col = t + c * (c + 1) / 2;
    std::memcpy(scratch + kN * c, col, sizeof(double) * (c + 1));
    for (int r = c + 1; r < kN; ++r) scratch[r + kN * c] = t[r * (r + 1) / 2 + c];
  }
  return scratch;
}

}  // namespace model
}  // namespace b2b
