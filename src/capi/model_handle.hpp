// The definition behind the opaque b2b_model handle of the C ABI, and the
// wording of the model layer's problems.
#pragma once

#include <b2b/b2b.h>

#include "../model/model.hpp"
#include "firewall.hpp"

struct b2b_model {
  b2b::model::Model m;
  int message_base = 0;  // numbers in messages: 0-based (C) or 1-based (Fortran)
};

namespace b2b {
namespace capi {

// B2B_ERR_NULL for a NULL handle, B2B_ERR_STATE unless finalized.
int check_model_finalized(const Reporter& r, const b2b_model* model);

// The above, and B2B_ERR_STATE unless an update has results (none since
// finalize, revert or restore): what reading contacts or assembling needs.
int check_results(const Reporter& r, const b2b_model* model);

// B2B_ERR_STATE unless the last update computed tangents.
int check_tangents(const Reporter& r, const b2b_model* model);

// Words a model::Problem (status != 0) for the caller.
int report_model_problem(const Reporter& r, const b2b_model* model, const model::Problem& pb);

// [partition] The same for a Problem::What::Partition (capi_partition.cpp).
int report_partition_problem(const Reporter& r, const b2b_model* model, const model::Problem& pb);

}  // namespace capi
}  // namespace b2b
