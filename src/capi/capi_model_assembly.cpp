// C entry points that add the model's contact arrays into a host's global
// residual and tangent (dense, LAPACK band, COO). Argument checks and
// messages only; src/model/assembly does the work.
#include <climits>
#include <cstdint>

#include <b2b/b2b.h>

#include "../model/assembly.hpp"
#include "model_handle.hpp"

using b2b::capi::check_results;
using b2b::capi::check_tangents;
using b2b::capi::guarded;
using b2b::capi::report_model_problem;
using b2b::capi::Reporter;
namespace md = b2b::model;

namespace {

// The common checks: a model with results (and tangents if asked), a valid
// numbering; then every equation number of the contacts within n_eq (and
// within the band when kl >= 0).
int check_assembly(const Reporter& r, const b2b_model* model, const int* eq, int ldeq,
                   int eq_base, int n_eq, bool tangent, md::EqMap& map, int kl = -1,
                   int ku = -1) {
  if (int st = check_results(r, model)) return st;
  if (tangent)
    if (int st = check_tangents(r, model)) return st;
  if (eq == nullptr) return r.fail(B2B_ERR_NULL, "eq is NULL");
  if (ldeq < 3) return r.fail(B2B_ERR_SIZE, "ldeq is %d (>= 3)", ldeq);
  if (n_eq < 0) return r.fail(B2B_ERR_RANGE, "n_eq is %d (>= 0)", n_eq);
  if (eq_base == INT_MIN)
    return r.fail(B2B_ERR_RANGE, "eq_base is %d: no equation number could be below it (a "
                  "constrained dof); eq_base is > INT_MIN (0 for C, 1 for Fortran numbering)",
                  eq_base);
  map = md::EqMap{eq, ldeq, eq_base, n_eq};
  const md::Problem pb = md::check_equations(model->m, map, kl, ku);
  if (pb.status) return report_model_problem(r, model, pb);
  return B2B_OK;
}

}  // namespace

extern "C" {

int b2b_model_add_residual(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                           int n_eq, double* f, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_add_residual", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (f == nullptr) return r.fail(B2B_ERR_NULL, "f is NULL");
    md::EqMap map;
    if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, false, map)) return st;
    md::add_residual(model->m, map, f);
    return B2B_OK;
  });
}

int b2b_model_add_tangent_dense(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                                int n_eq, double* K, int ldk, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_add_tangent_dense", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (K == nullptr) return r.fail(B2B_ERR_NULL, "K is NULL");
    if (ldk < n_eq || ldk < 1)
      return r.fail(B2B_ERR_SIZE, "ldk is %d, K needs at least n_eq = %d rows", ldk, n_eq);
    md::EqMap map;
    if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, true, map)) return st;
    md::add_tangent_dense(model->m, map, K, ldk);
    return B2B_OK;
  });
}

int b2b_model_add_tangent_banded(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                                 int n_eq, int kl, int ku, double* AB, int ldab, char* errmsg,
                                 int errmsg_len) {
  const Reporter r("b2b_model_add_tangent_banded", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (AB == nullptr) return r.fail(B2B_ERR_NULL, "AB is NULL");
    if (kl < 0 || ku < 0) return r.fail(B2B_ERR_RANGE, "kl = %d and ku = %d must be >= 0", kl, ku);
    const int64_t need = 2 * static_cast<int64_t>(kl) + ku + 1;  // 64 bits: no overflow
    if (ldab < need)
      return r.fail(B2B_ERR_SIZE, "ldab is %d, dgbsv's band storage needs 2 kl + ku + 1 = %lld",
                    ldab, static_cast<long long>(need));
    md::EqMap map;
    if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, true, map, kl, ku)) return st;
    md::add_tangent_banded(model->m, map, kl, ku, AB, ldab);
    return B2B_OK;
  });
}

int b2b_model_tangent_coo(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                          int n_eq, int* nnz, int* rows, int* cols, double* values, int capacity,
                          char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_tangent_coo", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (nnz == nullptr) return r.fail(B2B_ERR_NULL, "nnz is NULL");
    md::EqMap map;
    if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, true, map)) return st;
    const int64_t count = md::coo_count(model->m, map);
    if (count > 2147483647)
      return r.fail(B2B_ERR_SIZE, "%lld entries do not fit an int count",
                    static_cast<long long>(count));
    if (rows != nullptr) {
      if (cols == nullptr || values == nullptr)
        return r.fail(B2B_ERR_NULL, "rows is given but %s is NULL", cols ? "values" : "cols");
      if (capacity < count)
        return r.fail(B2B_ERR_SIZE, "capacity is %d, the tangent has %lld entries", capacity,
                      static_cast<long long>(count));
      md::coo_fill(model->m, map, rows, cols, values);
    }
    *nnz = static_cast<int>(count);
    return B2B_OK;
  });
}

}  // extern "C"
