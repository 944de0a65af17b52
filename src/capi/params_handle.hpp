// The definition behind the opaque b2b_params handle of the C ABI.
#pragma once

#include <b2b/b2b.h>

#include "../pair/params.hpp"

struct b2b_params {
  b2b::pair::Params p;
};
