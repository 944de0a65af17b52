/*
 * b2b: beam-to-beam contact for finite-element codes.
 *
 * This is the one public header: include <b2b/b2b.h> and nothing else.
 *
 * ---------------------------------------------------------------------------
 * Conventions of the C ABI (kept by every function, now and in later releases)
 * ---------------------------------------------------------------------------
 *
 *  Names      Everything public starts with b2b_ (functions) or B2B_ (macros,
 *             enumerators). Nothing else is exported from libb2b.
 *
 *  Status     Every function returns an int status: B2B_OK (0) on success or
 *             one of the B2B_ERR_* codes below. The values are fixed forever;
 *             new codes are only ever appended. b2b_strerror() names a code.
 *             The one exception is b2b_strerror, which returns a string.
 *
 *  Messages   Functions that can fail on bad input take a trailing
 *             (char *errmsg, int errmsg_len) pair. On failure, when errmsg is
 *             not NULL and errmsg_len > 0, a NUL-terminated message naming the
 *             problem (the argument, the node, the value) is written there,
 *             truncated to errmsg_len - 1 characters; B2B_ERRMSG_LEN bytes are
 *             always enough for the whole message. On success the buffer is
 *             not touched. Passing NULL, 0 is always allowed.
 *
 *  Outputs    On failure no output argument is touched. No function aborts,
 *             exits, prints, or lets a C++ exception escape. On success every
 *             output is finite.
 *
 *  State      The library holds no global mutable state. Every function may
 *             be called from several threads at once on distinct outputs.
 *
 *  Numbers    Real numbers are double. Integers (counts, indices, flags,
 *             enumerated values) are int. Matrices are column-major (Fortran
 *             and LAPACK order); a matrix with a run-time size comes with a
 *             leading dimension, one with a fixed documented size does not.
 *
 *  Nodes      Node and segment numbers are 0-based in C (the Fortran module
 *             makes them 1-based). A missing node is -1 in C (0 in Fortran).
 *
 *  ABI        B2B_SOVERSION is the SONAME's major version. Within one ABI
 *             version functions and enumerators are only added; no signature,
 *             enumerator value or documented meaning changes.
 */
#ifndef B2B_H
#define B2B_H

#include <b2b/b2b_export.h>
#include <b2b/b2b_version.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------
 * Status codes. Values are fixed; new codes are appended, never inserted.
 * ------------------------------------------------------------------------- */
enum {
  B2B_OK = 0,               /* success */
  B2B_ERR_NULL = 1,         /* a required pointer argument is NULL */
  B2B_ERR_SIZE = 2,         /* an array is too short or has the wrong shape */
  B2B_ERR_NONFINITE = 3,    /* an input holds NaN or Inf */
  B2B_ERR_UNKNOWN_KIND = 4, /* unknown curve kind, end rule or other enumerated value */
  B2B_ERR_COINCIDENT = 5,   /* two nodes of one element coincide (zero-length element) */
  B2B_ERR_FOLDED = 6,       /* the patch folds back on itself: no tangent direction at a node */
  B2B_ERR_RANGE = 7,        /* a value lies outside its documented range */
  B2B_ERR_NOMEM = 8,        /* memory could not be allocated */
  B2B_ERR_INTERNAL = 9,     /* a bug in b2b: please report it with the message */
  B2B_ERR_STATE = 10,       /* a handle is not in the state the call needs */
  B2B_ERR_UNKNOWN_KEY = 11  /* an option key the handle does not know */
};

/* Size of a message buffer that always holds a whole message. */
#define B2B_ERRMSG_LEN 256

/* Largest magnitude of a coordinate that b2b accepts. Squares of lengths and
 * the inverse cubes of lengths down to B2B_LENGTH_MIN stay normal doubles in
 * this range, so no derivative overflows. */
#define B2B_COORD_MAX 1.0e100
/* Element lengths below this (or below rounding of the coordinates) count as
 * coincident nodes. */
#define B2B_LENGTH_MIN 1.0e-100

/* A static, never-NULL English name for a status code ("unknown status" for
 * codes this version does not know). Thread-safe. */
B2B_EXPORT const char *b2b_strerror(int status);

/* The run-time release version of the library (which may be newer than the
 * headers a program was compiled with). Any pointer may be NULL. */
B2B_EXPORT int b2b_version(int *major, int *minor, int *patch);

/* The run-time ABI version: the N of libb2b.so.N. */
B2B_EXPORT int b2b_abi_version(int *abi);

#ifdef __cplusplus
}
#endif

#include <b2b/b2b_curve.h>
#include <b2b/b2b_pair.h>
#include <b2b/b2b_model.h>

#endif /* B2B_H */
