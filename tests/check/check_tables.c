/* The library's tables against the public headers. The values of each
 * enumeration that runs 0 .. count - 1 (curve kinds, end rules, normal laws,
 * tangent options) and the option keys that b2b_pair.h and b2b_model.h
 * document are exactly those the library accepts; its messages name the
 * header's first and last enumerators and list the documented keys, in the
 * header's order, and hold whole in B2B_ERRMSG_LEN. The headers are read as
 * text, as cmake/B2BFortranConstants.cmake reads them, so that a value or a
 * key added to a header but not to the library's table (or the other way
 * round) fails here. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"

#ifndef B2B_HEADER_DIR
#error "B2B_HEADER_DIR (the directory of the public headers) is set by tests/CMakeLists.txt"
#endif

#define MAX_ITEMS 32
#define NAME_LEN 64

typedef struct {
  char name[NAME_LEN];
  int value;
} enumerator;

typedef struct {
  char key[NAME_LEN];
  int is_real; /* else int */
} documented_key;

/* ------------------------------------------------------- reading headers */

static char *read_header(const char *name) {
  char path[1024];
  snprintf(path, sizeof path, "%s/%s", B2B_HEADER_DIR, name);
  FILE *f = fopen(path, "rb");
  ck_assert_msg(f != NULL, "cannot open %s", path);
  ck_assert_int_eq(fseek(f, 0, SEEK_END), 0);
  const long n = ftell(f);
  ck_assert(n > 0);
  rewind(f);
  char *text = malloc((size_t)n + 1);
  ck_assert(text != NULL);
  ck_assert_msg(fread(text, 1, (size_t)n, f) == (size_t)n, "cannot read %s", path);
  text[n] = '\0';
  fclose(f);
  return text;
}

static int is_ident(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

/* The enumerators "NAME = value" whose NAME starts with prefix, on the
 * header's code lines that start with an enumerator (after "enum {", if
 * any), as the Fortran constants generator takes them; #defines are not
 * enumerators. */
static int parse_enum(const char *text, const char *prefix, enumerator out[MAX_ITEMS]) {
  const size_t plen = strlen(prefix);
  int n = 0;
  const char *line = text;
  while (*line) {
    const char *end = strchr(line, '\n');
    if (!end) end = line + strlen(line);
    const char *p = line;
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    if (end - p >= 4 && strncmp(p, "enum", 4) == 0) {
      p += 4;
      while (p < end && (*p == ' ' || *p == '\t' || *p == '{')) ++p;
    }
    if (end - p >= 4 && strncmp(p, "B2B_", 4) == 0) {
      for (const char *q = p; q < end; ++q) {
        if (q + 1 < end && q[0] == '/' && q[1] == '*') break; /* a comment to the end */
        if ((size_t)(end - q) < plen || strncmp(q, prefix, plen) != 0) continue;
        if (q > p && is_ident(q[-1])) continue;
        const char *r = q;
        while (r < end && is_ident(*r)) ++r;
        const size_t len = (size_t)(r - q);
        while (r < end && *r == ' ') ++r;
        if (r >= end || *r != '=') continue;
        char *after;
        const long v = strtol(r + 1, &after, 10);
        if (after == r + 1) continue;
        ck_assert_msg(n < MAX_ITEMS && len < NAME_LEN, "too many or too long %s*", prefix);
        memcpy(out[n].name, q, len);
        out[n].name[len] = '\0';
        out[n].value = (int)v;
        ++n;
        q = after - 1;
      }
    }
    line = *end ? end + 1 : end;
  }
  return n;
}

/* The option keys of the header's table of options: comment lines
 *  *   "key"   real|int   ...                                              */
static int parse_keys(const char *text, documented_key out[MAX_ITEMS]) {
  int n = 0;
  const char *line = text;
  while (*line) {
    const char *end = strchr(line, '\n');
    if (!end) end = line + strlen(line);
    const char *p = line;
    if (end - p > 3 && p[0] == ' ' && p[1] == '*') {
      p += 2;
      while (p < end && *p == ' ') ++p;
      if (p < end && *p == '"') {
        const char *k = ++p;
        while (p < end && *p != '"') ++p;
        const size_t len = (size_t)(p - k);
        if (p < end) ++p;
        while (p < end && *p == ' ') ++p;
        const int real = end - p > 5 && strncmp(p, "real ", 5) == 0;
        const int integer = end - p > 4 && strncmp(p, "int ", 4) == 0;
        if (len > 0 && (real || integer)) {
          ck_assert_msg(n < MAX_ITEMS && len < NAME_LEN, "too many or too long keys");
          memcpy(out[n].key, k, len);
          out[n].key[len] = '\0';
          out[n].is_real = real;
          ++n;
        }
      }
    }
    line = *end ? end + 1 : end;
  }
  return n;
}

/* "\"a\", \"b\"": the documented keys of one type, in the header's order. */
static void key_list(const documented_key *keys, int n, int is_real, char *list, size_t size) {
  list[0] = '\0';
  for (int k = 0; k < n; ++k) {
    if (keys[k].is_real != is_real) continue;
    const size_t used = strlen(list);
    snprintf(list + used, size - used, "%s\"%.*s\"", used ? ", " : "", NAME_LEN, keys[k].key);
  }
}

/* A message the buffer holds whole ends as the library words it. */
static void assert_whole(const char *msg, const char *ending, const char *what) {
  const size_t n = strlen(msg), e = strlen(ending);
  ck_assert_msg(n < B2B_ERRMSG_LEN - 1 && n >= e && strcmp(msg + n - e, ending) == 0,
                "%s: the message is cut or worded otherwise (%zu characters): %s", what, n, msg);
}

/* ----------------------------------------------------------- enumerations */

/* Tries one value of the enumeration on the library: its status, and its
 * message in msg (B2B_ERRMSG_LEN). */
typedef int (*try_fn)(int value, char *msg);

/* The enumerators of prefix in the header are 0 .. n - 1, n == count (the
 * header's count macro, or -1 where there is none); the library accepts each
 * of them and rejects n, -1 and INT_MIN as B2B_ERR_UNKNOWN_KIND, naming the
 * first and the last enumerator. */
static void check_enumeration(const char *header, const char *prefix, int count, try_fn try_value) {
  char *text = read_header(header);
  enumerator e[MAX_ITEMS];
  const int n = parse_enum(text, prefix, e);
  free(text);
  ck_assert_msg(n >= 2, "%s: %d enumerators %s*", header, n, prefix);
  if (count >= 0)
    ck_assert_msg(n == count, "%s: %d enumerators %s*, but the count macro says %d", header, n,
                  prefix, count);
  const char *first = NULL, *last = NULL;
  for (int v = 0; v < n; ++v) {
    int seen = 0;
    for (int k = 0; k < n; ++k)
      if (e[k].value == v) {
        ++seen;
        if (v == 0) first = e[k].name;
        if (v == n - 1) last = e[k].name;
      }
    ck_assert_msg(seen == 1, "%s: %d enumerators %s* have the value %d (values 0 .. %d)", header,
                  seen, prefix, v, n - 1);
  }
  char msg[B2B_ERRMSG_LEN];
  for (int k = 0; k < n; ++k) {
    msg[0] = '\0';
    const int st = try_value(e[k].value, msg);
    ck_assert_msg(st == B2B_OK, "%s = %d: status %d: %s", e[k].name, e[k].value, st, msg);
  }
  char names[3 * NAME_LEN + 32];
  snprintf(names, sizeof names, "(%.*s .. %.*s are 0 .. %d)", NAME_LEN, first, NAME_LEN, last,
           n - 1);
  const int bad[] = {n, -1, INT_MIN};
  for (size_t b = 0; b < sizeof bad / sizeof bad[0]; ++b) {
    msg[0] = '\0';
    const int st = try_value(bad[b], msg);
    ck_assert_msg(st == B2B_ERR_UNKNOWN_KIND, "%s* value %d: status %d, not B2B_ERR_UNKNOWN_KIND",
                  prefix, bad[b], st);
    ck_assert_msg(strstr(msg, names) != NULL, "%s* value %d: the message does not say %s: %s",
                  prefix, bad[b], names, msg);
    assert_whole(msg, names, prefix);
  }
}

static int try_kind(int kind, char *msg) {
  int n = -1;
  return b2b_beam_segment_count(kind, 5, 0, &n, msg, B2B_ERRMSG_LEN);
}

/* The model checks kinds too, with the beam in its message. */
static int try_model_kind(int kind, char *msg) {
  b2b_model *m = NULL;
  ck_assert_int_eq(b2b_model_create(&m, NULL, 0), B2B_OK);
  const int nodes[5] = {0, 1, 2, 3, 4};
  int beam = -1;
  const int st = b2b_model_add_beam(m, nodes, 5, 0, 0.1, kind, 0, &beam, msg, B2B_ERRMSG_LEN);
  b2b_model_destroy(&m);
  return st;
}

static const double kPatch[12] = {0, 0, 0, 1, 0.1, 0, 2, 0.3, 0.1, 3, 0.2, 0.3};
static const double kTangents[6] = {1, 0, 0, 1, 0.2, 0};

static int try_start_rule(int rule, char *msg) {
  double x[9];
  return b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, rule, B2B_END_NEIGHBOUR, kPatch, kTangents,
                          0.3, x, NULL, NULL, msg, B2B_ERRMSG_LEN);
}

static int try_end_rule(int rule, char *msg) {
  double x[9];
  return b2b_segment_eval(B2B_CURVE_HERMITE_NODAL, B2B_END_NEIGHBOUR, rule, kPatch, kTangents,
                          0.3, x, NULL, NULL, msg, B2B_ERRMSG_LEN);
}

/* An int option of a fresh parameter set: set, read back, finalized. */
static int try_params_int(const char *key, int value, char *msg) {
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "penalty", 1e3, NULL, 0), B2B_OK);
  ck_assert_int_eq(b2b_params_set_real(p, "regularization_gap", 0.02, NULL, 0), B2B_OK);
  int st = b2b_params_set_int(p, key, value, msg, B2B_ERRMSG_LEN);
  if (st == B2B_OK) {
    int got = -1;
    ck_assert_int_eq(b2b_params_get_int(p, key, &got, NULL, 0), B2B_OK);
    ck_assert_int_eq(got, value);
    st = b2b_params_finalize(p, msg, B2B_ERRMSG_LEN);
  }
  b2b_params_destroy(&p);
  return st;
}

static int try_law(int law, char *msg) { return try_params_int("law", law, msg); }
static int try_tangent(int mode, char *msg) { return try_params_int("tangent", mode, msg); }

START_TEST(curve_kinds) {
  check_enumeration("b2b_curve.h", "B2B_CURVE_", B2B_CURVE_KIND_COUNT, try_kind);
  check_enumeration("b2b_curve.h", "B2B_CURVE_", B2B_CURVE_KIND_COUNT, try_model_kind);
}
END_TEST

START_TEST(end_rules) {
  check_enumeration("b2b_curve.h", "B2B_END_", -1, try_start_rule);
  check_enumeration("b2b_curve.h", "B2B_END_", -1, try_end_rule);
}
END_TEST

START_TEST(normal_laws) {
  check_enumeration("b2b_pair.h", "B2B_LAW_", B2B_LAW_COUNT, try_law);
}
END_TEST

START_TEST(tangent_options) {
  check_enumeration("b2b_pair.h", "B2B_TANGENT_", -1, try_tangent);
}
END_TEST

/* ------------------------------------------------------------ option keys */

/* A key far longer than the 64 characters a message echoes. */
static void long_key(char *key, size_t size) {
  memset(key, 'k', size - 1);
  key[size - 1] = '\0';
}

/* The unknown-key message of one setter or getter lists the documented keys
 * of its type; with a long key it still holds whole. */
static void check_unknown_key(int st, const char *msg, const char *type_word, const char *list,
                              const char *what) {
  char want[B2B_ERRMSG_LEN];
  snprintf(want, sizeof want, "(%s keys: %s)", type_word, list);
  ck_assert_msg(st == B2B_ERR_UNKNOWN_KEY, "%s: status %d", what, st);
  ck_assert_msg(strstr(msg, want) != NULL, "%s: the message does not list %s: %s", what, want,
                msg);
  assert_whole(msg, want, what);
}

START_TEST(params_keys) {
  char *text = read_header("b2b_pair.h");
  documented_key keys[MAX_ITEMS];
  const int n = parse_keys(text, keys);
  free(text);
  ck_assert_msg(n >= 2, "b2b_pair.h documents %d keys", n);
  b2b_params *p = NULL;
  ck_assert_int_eq(b2b_params_create(&p, NULL, 0), B2B_OK);
  char msg[B2B_ERRMSG_LEN];
  for (int k = 0; k < n; ++k) {
    const char *key = keys[k].key;
    double r;
    int i;
    if (keys[k].is_real) {
      /* a known key: the value is checked, after the key */
      ck_assert_msg(b2b_params_set_real(p, key, NAN, msg, sizeof msg) == B2B_ERR_NONFINITE,
                    "\"%s\" (real): %s", key, msg);
      ck_assert_msg(b2b_params_get_real(p, key, &r, msg, sizeof msg) == B2B_OK, "\"%s\": %s", key,
                    msg);
      ck_assert_int_eq(b2b_params_set_int(p, key, 0, NULL, 0), B2B_ERR_UNKNOWN_KEY);
      ck_assert_int_eq(b2b_params_get_int(p, key, &i, NULL, 0), B2B_ERR_UNKNOWN_KEY);
    } else {
      const int st = b2b_params_set_int(p, key, INT_MIN, msg, sizeof msg);
      ck_assert_msg(st != B2B_OK && st != B2B_ERR_UNKNOWN_KEY, "\"%s\" (int) = INT_MIN: %d: %s",
                    key, st, msg);
      ck_assert_msg(b2b_params_get_int(p, key, &i, msg, sizeof msg) == B2B_OK, "\"%s\": %s", key,
                    msg);
      ck_assert_int_eq(b2b_params_set_real(p, key, 0.0, NULL, 0), B2B_ERR_UNKNOWN_KEY);
      ck_assert_int_eq(b2b_params_get_real(p, key, &r, NULL, 0), B2B_ERR_UNKNOWN_KEY);
    }
  }
  /* No key but these: the messages list exactly them. */
  char reals[B2B_ERRMSG_LEN], ints[B2B_ERRMSG_LEN], key[200];
  key_list(keys, n, 1, reals, sizeof reals);
  key_list(keys, n, 0, ints, sizeof ints);
  long_key(key, sizeof key);
  double r;
  int i;
  check_unknown_key(b2b_params_set_real(p, key, 1.0, msg, sizeof msg), msg, "real", reals,
                    "b2b_params_set_real");
  check_unknown_key(b2b_params_get_real(p, key, &r, msg, sizeof msg), msg, "real", reals,
                    "b2b_params_get_real");
  check_unknown_key(b2b_params_set_int(p, key, 1, msg, sizeof msg), msg, "integer", ints,
                    "b2b_params_set_int");
  check_unknown_key(b2b_params_get_int(p, key, &i, msg, sizeof msg), msg, "integer", ints,
                    "b2b_params_get_int");
  b2b_params_destroy(&p);
}
END_TEST

START_TEST(model_keys) {
  char *text = read_header("b2b_model.h");
  documented_key keys[MAX_ITEMS];
  const int n = parse_keys(text, keys);
  free(text);
  ck_assert_msg(n >= 2, "b2b_model.h documents %d keys", n);
  b2b_model *m = NULL;
  ck_assert_int_eq(b2b_model_create(&m, NULL, 0), B2B_OK);
  char msg[B2B_ERRMSG_LEN];
  for (int k = 0; k < n; ++k) {
    const char *key = keys[k].key;
    if (keys[k].is_real) {
      ck_assert_msg(b2b_model_set_real(m, key, NAN, msg, sizeof msg) == B2B_ERR_NONFINITE,
                    "\"%s\" (real): %s", key, msg);
      ck_assert_int_eq(b2b_model_set_int(m, key, 0, NULL, 0), B2B_ERR_UNKNOWN_KEY);
    } else {
      const int st = b2b_model_set_int(m, key, INT_MIN, msg, sizeof msg);
      ck_assert_msg(st != B2B_OK && st != B2B_ERR_UNKNOWN_KEY, "\"%s\" (int) = INT_MIN: %d: %s",
                    key, st, msg);
      ck_assert_int_eq(b2b_model_set_real(m, key, 0.0, NULL, 0), B2B_ERR_UNKNOWN_KEY);
    }
  }
  char reals[B2B_ERRMSG_LEN], ints[B2B_ERRMSG_LEN], key[200];
  key_list(keys, n, 1, reals, sizeof reals);
  key_list(keys, n, 0, ints, sizeof ints);
  long_key(key, sizeof key);
  check_unknown_key(b2b_model_set_real(m, key, 1.0, msg, sizeof msg), msg, "real", reals,
                    "b2b_model_set_real");
  check_unknown_key(b2b_model_set_int(m, key, 1, msg, sizeof msg), msg, "integer", ints,
                    "b2b_model_set_int");
  b2b_model_destroy(&m);
}
END_TEST

static Suite *make_suite(void) {
  Suite *s = suite_create("tables");
  TCase *tc = tcase_create("enumerations");
  tcase_add_test(tc, curve_kinds);
  tcase_add_test(tc, end_rules);
  tcase_add_test(tc, normal_laws);
  tcase_add_test(tc, tangent_options);
  suite_add_tcase(s, tc);
  tc = tcase_create("option_keys");
  tcase_add_test(tc, params_keys);
  tcase_add_test(tc, model_keys);
  suite_add_tcase(s, tc);
  return s;
}

int main(void) { return tst_run_suite(make_suite()); }
