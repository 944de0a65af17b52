/* A C program built against an installed b2b, as a host code would be: it
 * includes <b2b/b2b.h> only and links libb2b. Exits non-zero on any mismatch.
 * Built by tests/consumer/run_consumer_test.sh through CMake (find_package)
 * and through pkg-config. */
#include <stdio.h>
#include <string.h>

#include <b2b/b2b.h>

static int failures = 0;

#define CHECK(cond, ...)                                         \
  do {                                                           \
    if (!(cond)) {                                               \
      fprintf(stderr, "FAIL (%s:%d): ", __FILE__, __LINE__);     \
      fprintf(stderr, __VA_ARGS__);                              \
      fputc('\n', stderr);                                       \
      ++failures;                                                \
    }                                                            \
  } while (0)

static double absdiff(double a, double b) { return a > b ? a - b : b - a; }

int main(void) {
  int major = -1, minor = -1, patch = -1, abi = -1, st, i;
  /* x1, x2, x3, x4: a 3x4 column-major matrix, a non-planar patch. */
  const double nodes[B2B_PATCH_LEN] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                                       2.0, 1.0, 0.0, 3.0, 1.0, 1.0};
  double x[B2B_POINT_LEN];
  char msg[B2B_ERRMSG_LEN];

  /* The run-time library matches the headers this program was built with. */
  st = b2b_version(&major, &minor, &patch);
  CHECK(st == B2B_OK, "b2b_version returned %d", st);
  CHECK(major == B2B_VERSION_MAJOR && minor == B2B_VERSION_MINOR && patch == B2B_VERSION_PATCH,
        "b2b_version gives %d.%d.%d, the headers say %s", major, minor, patch,
        B2B_VERSION_STRING);
  st = b2b_abi_version(&abi);
  CHECK(st == B2B_OK && abi == B2B_SOVERSION, "b2b_abi_version: status %d, abi %d, want %d", st,
        abi, B2B_SOVERSION);
  CHECK(b2b_strerror(B2B_ERR_UNKNOWN_KIND) != NULL, "b2b_strerror returned NULL");

  /* The node-preserving curve starts at x2. */
  for (i = 0; i < B2B_POINT_LEN; ++i) x[i] = -999.0;
  msg[0] = '\0';
  st = b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, nodes,
                        NULL, -1.0, x, NULL, NULL, msg, (int)sizeof msg);
  CHECK(st == B2B_OK, "b2b_segment_eval(HERMITE_NODAL, xi = -1) returned %d: %s", st, msg);
  if (st == B2B_OK)
    for (i = 0; i < 3; ++i)
      CHECK(absdiff(x[i], nodes[3 + i]) <= 1e-14, "x(-1)[%d] = %.17g, want x2[%d] = %.17g", i,
            x[i], i, nodes[3 + i]);

  /* An unknown curve kind is reported, with a message. */
  msg[0] = '\0';
  st = b2b_segment_eval(42, B2B_END_NEIGHBOUR, B2B_END_NEIGHBOUR, nodes, NULL, -1.0, x, NULL,
                        NULL, msg, (int)sizeof msg);
  CHECK(st == B2B_ERR_UNKNOWN_KIND, "b2b_segment_eval(kind 42) returned %d, want %d (%s)", st,
        B2B_ERR_UNKNOWN_KIND, b2b_strerror(B2B_ERR_UNKNOWN_KIND));
  CHECK(msg[0] != '\0', "b2b_segment_eval(kind 42) wrote no message");

  if (failures) {
    fprintf(stderr, "b2b C consumer: %d failure(s)\n", failures);
    return 1;
  }
  printf("b2b C consumer: library %d.%d.%d (ABI %d), headers %s: OK\n", major, minor, patch, abi,
         B2B_VERSION_STRING);
  printf("  kind 42 -> %s: %s\n", b2b_strerror(B2B_ERR_UNKNOWN_KIND), msg);
  return 0;
}
