// Validation of a host-owned pair history at the C boundary (shared by
// b2b_pair_eval and b2b_pair_history_handover).
#pragma once

#include "../pair/params.hpp"
#include "firewall.hpp"

namespace b2b {
namespace capi {

// name: the argument's name in messages ("hist_old", "hist_from").
int check_history(const Reporter& r, const pair::Params& p, const char* name, const double* h,
                  int len);

}  // namespace capi
}  // namespace b2b
