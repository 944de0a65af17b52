/* Library-wide entry points: status names (b2b_strerror), release and ABI
 * versions, the version macros, and the fixed values of the public enums and
 * constants that the C ABI promises never to change. */
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"

#define N_CODES 12 /* B2B_OK .. B2B_ERR_UNKNOWN_KEY */
#define LAST_CODE B2B_ERR_UNKNOWN_KEY

/* The version macros must also work in the preprocessor. */
#if !B2B_VERSION_GE(0, 0, 0)
#error "B2B_VERSION_GE(0, 0, 0) is false in #if"
#endif
#if !B2B_VERSION_GE(B2B_VERSION_MAJOR, B2B_VERSION_MINOR, B2B_VERSION_PATCH)
#error "B2B_VERSION_GE(current) is false in #if"
#endif
#if B2B_VERSION_GE(B2B_VERSION_MAJOR + 1, 0, 0)
#error "B2B_VERSION_GE(next major) is true in #if"
#endif

/* ---------------------------------------------------------------- strerror */

START_TEST(test_strerror_known_codes) {
  for (int code = B2B_OK; code <= LAST_CODE; ++code) {
    const char *s = b2b_strerror(code);
    ck_assert_msg(s != NULL, "b2b_strerror(%d) is NULL", code);
    ck_assert_msg(s[0] != '\0', "b2b_strerror(%d) is empty", code);
    ck_assert_msg(strlen(s) < B2B_ERRMSG_LEN, "b2b_strerror(%d) is absurdly long", code);
    ck_assert_msg(strstr(s, "unknown status") == NULL,
                  "b2b_strerror(%d) = \"%s\" calls a known code unknown", code, s);
    /* A static string: the same pointer, the same text, every time. */
    ck_assert_ptr_eq(b2b_strerror(code), s);
  }
}
END_TEST

START_TEST(test_strerror_distinct) {
  for (int a = B2B_OK; a <= LAST_CODE; ++a)
    for (int b = a + 1; b <= LAST_CODE; ++b)
      ck_assert_msg(strcmp(b2b_strerror(a), b2b_strerror(b)) != 0,
                    "b2b_strerror(%d) and b2b_strerror(%d) are both \"%s\"", a, b,
                    b2b_strerror(a));
}
END_TEST

/* Each name says what its code means (a word of the documented meaning). */
START_TEST(test_strerror_names_the_problem) {
  static const struct {
    int code;
    const char *word;
  } expect[] = {{B2B_OK, "success"},           {B2B_ERR_NULL, "NULL"},
                {B2B_ERR_SIZE, "short"},       {B2B_ERR_NONFINITE, "infinite"},
                {B2B_ERR_UNKNOWN_KIND, "kind"}, {B2B_ERR_COINCIDENT, "coincide"},
                {B2B_ERR_FOLDED, "folds"},     {B2B_ERR_RANGE, "range"},
                {B2B_ERR_NOMEM, "memory"},     {B2B_ERR_INTERNAL, "internal"},
                {B2B_ERR_STATE, "state"},      {B2B_ERR_UNKNOWN_KEY, "key"}};
  ck_assert_int_eq((int)(sizeof expect / sizeof expect[0]), N_CODES);
  for (int k = 0; k < N_CODES; ++k)
    ck_assert_msg(strstr(b2b_strerror(expect[k].code), expect[k].word) != NULL,
                  "b2b_strerror(%d) = \"%s\" does not contain \"%s\"", expect[k].code,
                  b2b_strerror(expect[k].code), expect[k].word);
}
END_TEST

START_TEST(test_strerror_unknown_codes) {
  const int unknown[] = {99, -1, LAST_CODE + 1, 1000, INT_MAX, INT_MIN};
  for (size_t k = 0; k < sizeof unknown / sizeof unknown[0]; ++k) {
    const char *s = b2b_strerror(unknown[k]);
    ck_assert_msg(s != NULL, "b2b_strerror(%d) is NULL", unknown[k]);
    ck_assert_msg(strstr(s, "unknown status") != NULL,
                  "b2b_strerror(%d) = \"%s\", expected \"unknown status\"", unknown[k], s);
    for (int code = B2B_OK; code <= LAST_CODE; ++code)
      ck_assert_msg(strcmp(s, b2b_strerror(code)) != 0,
                    "b2b_strerror(%d) has the name of the known code %d", unknown[k], code);
  }
}
END_TEST

/* ----------------------------------------------------------------- version */

START_TEST(test_version_matches_headers) {
  int major = -7, minor = -7, patch = -7;
  ck_assert_int_eq(b2b_version(&major, &minor, &patch), B2B_OK);
  ck_assert_int_eq(major, B2B_VERSION_MAJOR);
  ck_assert_int_eq(minor, B2B_VERSION_MINOR);
  ck_assert_int_eq(patch, B2B_VERSION_PATCH);
  ck_assert_int_ge(major, 0);
  ck_assert_int_ge(minor, 0);
  ck_assert_int_ge(patch, 0);
  /* The version string is the same release. */
  char buf[64];
  snprintf(buf, sizeof buf, "%d.%d.%d", major, minor, patch);
  ck_assert_str_eq(buf, B2B_VERSION_STRING);
}
END_TEST

START_TEST(test_version_null_pointers) {
  ck_assert_int_eq(b2b_version(NULL, NULL, NULL), B2B_OK);
  /* Every combination of NULL and non-NULL: the non-NULL ones are filled. */
  for (int mask = 0; mask < 8; ++mask) {
    int v[3] = {-7, -7, -7};
    const int st = b2b_version((mask & 1) ? &v[0] : NULL, (mask & 2) ? &v[1] : NULL,
                               (mask & 4) ? &v[2] : NULL);
    ck_assert_int_eq(st, B2B_OK);
    ck_assert_int_eq(v[0], (mask & 1) ? B2B_VERSION_MAJOR : -7);
    ck_assert_int_eq(v[1], (mask & 2) ? B2B_VERSION_MINOR : -7);
    ck_assert_int_eq(v[2], (mask & 4) ? B2B_VERSION_PATCH : -7);
  }
}
END_TEST

START_TEST(test_abi_version) {
  int abi = -7;
  ck_assert_int_eq(b2b_abi_version(&abi), B2B_OK);
  ck_assert_int_eq(abi, B2B_SOVERSION);
  ck_assert_int_ge(abi, 0);
  ck_assert_int_eq(b2b_abi_version(NULL), B2B_ERR_NULL);
}
END_TEST

START_TEST(test_version_ge_macro) {
  ck_assert(B2B_VERSION_GE(0, 0, 0));
  ck_assert(B2B_VERSION_GE(B2B_VERSION_MAJOR, B2B_VERSION_MINOR, B2B_VERSION_PATCH));
  ck_assert(!B2B_VERSION_GE(B2B_VERSION_MAJOR + 1, 0, 0));
  ck_assert(!B2B_VERSION_GE(B2B_VERSION_MAJOR, B2B_VERSION_MINOR + 1, 0));
  ck_assert(!B2B_VERSION_GE(B2B_VERSION_MAJOR, B2B_VERSION_MINOR, B2B_VERSION_PATCH + 1));
  if (B2B_VERSION_PATCH > 0)
    ck_assert(B2B_VERSION_GE(B2B_VERSION_MAJOR, B2B_VERSION_MINOR, B2B_VERSION_PATCH - 1));
  if (B2B_VERSION_MINOR > 0)
    ck_assert(B2B_VERSION_GE(B2B_VERSION_MAJOR, B2B_VERSION_MINOR - 1, 999));
  if (B2B_VERSION_MAJOR > 0) ck_assert(B2B_VERSION_GE(B2B_VERSION_MAJOR - 1, 999, 999));
  /* Lexicographic order: a later minor/patch does not outweigh an earlier major. */
  ck_assert(B2B_VERSION_GE(B2B_VERSION_MAJOR, 0, 0));
  ck_assert(!B2B_VERSION_GE(B2B_VERSION_MAJOR + 1, B2B_VERSION_MINOR, B2B_VERSION_PATCH));
}
END_TEST

/* ------------------------------------------------------ fixed enum values */

START_TEST(test_status_values) {
  ck_assert_int_eq(B2B_OK, 0);
  ck_assert_int_eq(B2B_ERR_NULL, 1);
  ck_assert_int_eq(B2B_ERR_SIZE, 2);
  ck_assert_int_eq(B2B_ERR_NONFINITE, 3);
  ck_assert_int_eq(B2B_ERR_UNKNOWN_KIND, 4);
  ck_assert_int_eq(B2B_ERR_COINCIDENT, 5);
  ck_assert_int_eq(B2B_ERR_FOLDED, 6);
  ck_assert_int_eq(B2B_ERR_RANGE, 7);
  ck_assert_int_eq(B2B_ERR_NOMEM, 8);
  ck_assert_int_eq(B2B_ERR_INTERNAL, 9);
  ck_assert_int_eq(B2B_ERR_STATE, 10);
  ck_assert_int_eq(B2B_ERR_UNKNOWN_KEY, 11);
}
END_TEST

START_TEST(test_curve_enum_values) {
  ck_assert_int_eq(B2B_CURVE_LINEAR, 0);
  ck_assert_int_eq(B2B_CURVE_HERMITE_MIDPOINT, 1);
  ck_assert_int_eq(B2B_CURVE_HERMITE_NODAL, 2);
  ck_assert_int_eq(B2B_CURVE_HERMITE_NODAL_WEIGHTED, 3);
  ck_assert_int_eq(B2B_END_NEIGHBOUR, 0);
  ck_assert_int_eq(B2B_END_REFLECT, 1);
  ck_assert_int_eq(B2B_END_TANGENT, 2);
  /* Kinds are appended: the count only grows past the last fixed value. */
  ck_assert_int_ge(B2B_CURVE_KIND_COUNT, B2B_CURVE_HERMITE_NODAL_WEIGHTED + 1);
}
END_TEST

START_TEST(test_pair_enum_values) {
  ck_assert_int_eq(B2B_LAW_LINEAR, 0);
  ck_assert_int_eq(B2B_LAW_QUADRATIC, 1);
  /* Laws are appended: the count only grows past the last fixed value. */
  ck_assert_int_ge(B2B_LAW_COUNT, B2B_LAW_QUADRATIC + 1);
  ck_assert_int_eq(B2B_TANGENT_EXACT, 0);
  ck_assert_int_eq(B2B_TANGENT_SYMMETRIC, 1);
  ck_assert_int_eq(B2B_TANGENT_MAIN, 2);
  ck_assert_int_eq(B2B_TANGENT_FD, 3);
}
END_TEST

START_TEST(test_constants) {
  ck_assert_int_eq(B2B_ERRMSG_LEN, 256);
  ck_assert(B2B_COORD_MAX == 1.0e100);
  ck_assert(B2B_LENGTH_MIN == 1.0e-100);
  ck_assert_int_eq(B2B_PATCH_NODES, 4);
  ck_assert_int_eq(B2B_PATCH_LEN, 12);
  ck_assert_int_eq(B2B_POINT_LEN, 9);
  ck_assert_int_eq(B2B_DPOINT_LEN, 72);
  ck_assert_int_eq(B2B_D2POINT_LEN, 864);
  ck_assert_int_eq(B2B_PATCH_LEN, 3 * B2B_PATCH_NODES);
  ck_assert_int_eq(B2B_DPOINT_LEN, 2 * 3 * B2B_PATCH_LEN);
  ck_assert_int_eq(B2B_D2POINT_LEN, 2 * 3 * B2B_PATCH_LEN * B2B_PATCH_LEN);
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("core");
  TCase *tc;

  tc = tcase_create("strerror");
  tcase_add_test(tc, test_strerror_known_codes);
  tcase_add_test(tc, test_strerror_distinct);
  tcase_add_test(tc, test_strerror_names_the_problem);
  tcase_add_test(tc, test_strerror_unknown_codes);
  suite_add_tcase(s, tc);

  tc = tcase_create("version");
  tcase_add_test(tc, test_version_matches_headers);
  tcase_add_test(tc, test_version_null_pointers);
  tcase_add_test(tc, test_abi_version);
  tcase_add_test(tc, test_version_ge_macro);
  suite_add_tcase(s, tc);

  tc = tcase_create("fixed_values");
  tcase_add_test(tc, test_status_values);
  tcase_add_test(tc, test_curve_enum_values);
  tcase_add_test(tc, test_pair_enum_values);
  tcase_add_test(tc, test_constants);
  suite_add_tcase(s, tc);

  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
