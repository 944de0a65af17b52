// The definition behind the opaque b2b_params handle of the C ABI.
#pragma once

#include <b2b/b2b.h>

#include "../pair/params.hpp"
#include "firewall.hpp"

struct b2b_params {
  b2b::pair::Params p;
};

namespace b2b {
namespace capi {

// B2B_ERR_NULL for a NULL handle, B2B_ERR_STATE for one not yet finalized:
// what every call that evaluates with a parameter set requires.
inline int check_finalized(const Reporter& r, const b2b_params* params) {
  if (params == nullptr) return r.fail(B2B_ERR_NULL, "params is NULL");
  if (!params->p.finalized)
    return r.fail(B2B_ERR_STATE, "params is not finalized (call b2b_params_finalize first)");
  return B2B_OK;
}

}  // namespace capi
}  // namespace b2b
