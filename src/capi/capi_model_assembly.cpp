// C entry points that add the model's contact arrays into a host's global
// residual and tangent (dense, LAPACK band, FEAP profile, COO; unscaled and
// scaled), the pattern query for sizing the host's structure, and the
// coupling to prescribed dofs. Argument checks and messages only;
// src/model/assembly, profile and constrained_product do the work.
#include <climits>
#include <cmath>
#include <cstdint>

#include <b2b/b2b.h>

#include "../model/assembly.hpp"
#include "../model/constrained_product.hpp"
#include "../model/profile.hpp"
#include "model_handle.hpp"

using b2b::capi::check_model_finalized;
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

int check_scale(const Reporter& r, double scale) {
  if (!std::isfinite(scale)) return r.fail(B2B_ERR_NONFINITE, "scale is not finite (%g)", scale);
  return B2B_OK;
}

int add_residual(const Reporter& r, const b2b_model* model, const int* eq, int ldeq,
                 int eq_base, int n_eq, double scale, double* f) {
  if (f == nullptr) return r.fail(B2B_ERR_NULL, "f is NULL");
  if (int st = check_scale(r, scale)) return st;
  md::EqMap map;
  if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, false, map)) return st;
  md::add_residual(model->m, map, scale, f);
  return B2B_OK;
}

int add_dense(const Reporter& r, const b2b_model* model, const int* eq, int ldeq, int eq_base,
              int n_eq, double scale, double* K, int ldk) {
  if (K == nullptr) return r.fail(B2B_ERR_NULL, "K is NULL");
  if (ldk < n_eq || ldk < 1)
    return r.fail(B2B_ERR_SIZE, "ldk is %d, K needs at least n_eq = %d rows", ldk, n_eq);
  if (int st = check_scale(r, scale)) return st;
  md::EqMap map;
  if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, true, map)) return st;
  md::add_tangent_dense(model->m, map, scale, K, ldk);
  return B2B_OK;
}

int add_banded(const Reporter& r, const b2b_model* model, const int* eq, int ldeq, int eq_base,
               int n_eq, int kl, int ku, double scale, double* AB, int ldab) {
  if (AB == nullptr) return r.fail(B2B_ERR_NULL, "AB is NULL");
  if (kl < 0 || ku < 0) return r.fail(B2B_ERR_RANGE, "kl = %d and ku = %d must be >= 0", kl, ku);
  const int64_t need = 2 * static_cast<int64_t>(kl) + ku + 1;  // 64 bits: no overflow
  if (ldab < need)
    return r.fail(B2B_ERR_SIZE, "ldab is %d, dgbsv's band storage needs 2 kl + ku + 1 = %lld",
                  ldab, static_cast<long long>(need));
  if (int st = check_scale(r, scale)) return st;
  md::EqMap map;
  if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, true, map, kl, ku)) return st;
  md::add_tangent_banded(model->m, map, kl, ku, scale, AB, ldab);
  return B2B_OK;
}

}  // namespace

extern "C" {

int b2b_model_add_residual(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                           int n_eq, double* f, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_add_residual", errmsg, errmsg_len);
  return guarded(r, [&]() -> int { return add_residual(r, model, eq, ldeq, eq_base, n_eq, 1.0, f); });
}

int b2b_model_add_residual_scaled(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                                  int n_eq, double scale, double* f, char* errmsg,
                                  int errmsg_len) {
  const Reporter r("b2b_model_add_residual_scaled", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    return add_residual(r, model, eq, ldeq, eq_base, n_eq, scale, f);
  });
}

int b2b_model_add_tangent_dense(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                                int n_eq, double* K, int ldk, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_add_tangent_dense", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    return add_dense(r, model, eq, ldeq, eq_base, n_eq, 1.0, K, ldk);
  });
}

int b2b_model_add_tangent_dense_scaled(const b2b_model* model, const int* eq, int ldeq,
                                       int eq_base, int n_eq, double scale, double* K, int ldk,
                                       char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_add_tangent_dense_scaled", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    return add_dense(r, model, eq, ldeq, eq_base, n_eq, scale, K, ldk);
  });
}

int b2b_model_add_tangent_banded(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                                 int n_eq, int kl, int ku, double* AB, int ldab, char* errmsg,
                                 int errmsg_len) {
  const Reporter r("b2b_model_add_tangent_banded", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    return add_banded(r, model, eq, ldeq, eq_base, n_eq, kl, ku, 1.0, AB, ldab);
  });
}

int b2b_model_add_tangent_banded_scaled(const b2b_model* model, const int* eq, int ldeq,
                                        int eq_base, int n_eq, int kl, int ku, double scale,
                                        double* AB, int ldab, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_add_tangent_banded_scaled", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    return add_banded(r, model, eq, ldeq, eq_base, n_eq, kl, ku, scale, AB, ldab);
  });
}

int b2b_model_tangent_profile(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                              int n_eq, int* heights, int* kl, int* ku, char* errmsg,
                              int errmsg_len) {
  const Reporter r("b2b_model_tangent_profile", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    md::EqMap map;
    if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, false, map)) return st;
    md::tangent_profile(model->m, map, heights, kl, ku);
    return B2B_OK;
  });
}

int b2b_model_add_tangent_profile(const b2b_model* model, const int* eq, int ldeq, int eq_base,
                                  int n_eq, double scale, const int* jp, double* ad, double* au,
                                  double* al, char* errmsg, int errmsg_len) {
  const Reporter r("b2b_model_add_tangent_profile", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (jp == nullptr) return r.fail(B2B_ERR_NULL, "jp is NULL");
    if (ad == nullptr) return r.fail(B2B_ERR_NULL, "ad is NULL");
    if (au == nullptr) return r.fail(B2B_ERR_NULL, "au is NULL");
    if (int st = check_scale(r, scale)) return st;
    md::EqMap map;
    if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, true, map)) return st;
    const md::Problem pb = md::check_profile(model->m, map, jp);
    if (pb.status) return report_model_problem(r, model, pb);
    md::add_tangent_profile(model->m, map, scale, jp, ad, au, al);
    return B2B_OK;
  });
}

int b2b_model_add_constrained_product(const b2b_model* model, const int* eq, int ldeq,
                                      int eq_base, int n_eq, const double* du, int ldu,
                                      int n_cols, double scale, double* f, char* errmsg,
                                      int errmsg_len) {
  const Reporter r("b2b_model_add_constrained_product", errmsg, errmsg_len);
  return guarded(r, [&]() -> int {
    if (du == nullptr) return r.fail(B2B_ERR_NULL, "du is NULL");
    if (f == nullptr) return r.fail(B2B_ERR_NULL, "f is NULL");
    if (ldu < 3) return r.fail(B2B_ERR_SIZE, "ldu is %d (>= 3)", ldu);
    if (int st = check_model_finalized(r, model)) return st;
    if (n_cols < model->m.n_nodes())
      return r.fail(B2B_ERR_SIZE, "du has %d columns (nodes) but the model has %d nodes", n_cols,
                    model->m.n_nodes());
    if (int st = check_scale(r, scale)) return st;
    md::EqMap map;
    if (int st = check_assembly(r, model, eq, ldeq, eq_base, n_eq, true, map)) return st;
    const md::Problem pb = md::check_increments(model->m, map, du, ldu);
    if (pb.status) return report_model_problem(r, model, pb);
    md::add_constrained_product(model->m, map, du, ldu, scale, f);
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
