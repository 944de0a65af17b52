// Library-wide entry points: status names and versions.
#include <b2b/b2b.h>

extern "C" {

const char* b2b_strerror(int status) {
  switch (status) {
    case B2B_OK: return "success";
    case B2B_ERR_NULL: return "a required pointer argument is NULL";
    case B2B_ERR_SIZE: return "an array is too short or has the wrong shape";
    case B2B_ERR_NONFINITE: return "an input is NaN or infinite";
    case B2B_ERR_UNKNOWN_KIND: return "unknown curve kind, end rule or other enumerated value";
    case B2B_ERR_COINCIDENT: return "two nodes of one element coincide (zero-length element)";
    case B2B_ERR_FOLDED: return "the patch folds back on itself (no tangent direction at a node)";
    case B2B_ERR_RANGE: return "a value lies outside its documented range";
    case B2B_ERR_NOMEM: return "out of memory";
    case B2B_ERR_INTERNAL: return "internal error in b2b";
    case B2B_ERR_STATE: return "the handle is not in the state this call needs";
    case B2B_ERR_UNKNOWN_KEY: return "unknown option key";
    default: return "unknown status";
  }
}

int b2b_version(int* major, int* minor, int* patch) {
  if (major) *major = B2B_VERSION_MAJOR;
  if (minor) *minor = B2B_VERSION_MINOR;
  if (patch) *patch = B2B_VERSION_PATCH;
  return B2B_OK;
}

int b2b_abi_version(int* abi) {
  if (abi == nullptr) return B2B_ERR_NULL;
  *abi = B2B_SOVERSION;
  return B2B_OK;
}

}  // extern "C"
