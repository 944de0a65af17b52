#!/bin/sh
# Checks that the shared library libb2b_fortran exports exactly the module
# procedures listed, each in its symbol-version node, under its own SONAME.
#
#   check_fortran_exports.sh LIBRARY SYMBOLS_TXT SONAME [NM [READELF]]
#
#   LIBRARY      the built libb2b_fortran.so ($<TARGET_FILE:b2b_fortran>), made
#                by gfortran with cmake/b2b_fortran.map
#   SYMBOLS_TXT  "NAME NODE" per line, sorted (tests/abi/fortran_symbols.txt);
#                # comments and blank lines are ignored
#   SONAME       the expected SONAME, libb2b_fortran.so.<B2B_FORTRAN_ABI_MAJOR>
#   NM, READELF  the binutils to use (default: nm, readelf)
#
# Asserts that
#   1. every dynamic symbol the library defines is gfortran's name for an
#      entity of module b2b (__b2b_MOD_*), the version node symbols (type A,
#      B2B_FORTRAN_x.y) excepted: no private helper, no runtime symbol leaks;
#   2. the exported names are exactly those of SYMBOLS_TXT;
#   3. each carries the default version of its listed node, NAME@@NODE;
#   4. the SONAME is SONAME (libb2b_fortran's own ABI version, not libb2b's).
# Prints every violation and exits 1 if any.
set -eu
LC_ALL=C
export LC_ALL

if [ "$#" -lt 3 ] || [ "$#" -gt 5 ]; then
  echo "usage: $0 LIBRARY SYMBOLS_TXT SONAME [NM [READELF]]" >&2
  exit 2
fi
lib=$1
list=$2
want_soname=$3
nm=${4:-nm}
readelf=${5:-readelf}
for f in "$lib" "$list"; do
  if [ ! -r "$f" ]; then
    echo "check_fortran_exports: cannot read $f" >&2
    exit 2
  fi
done

tmp=$(mktemp -d "${TMPDIR:-/tmp}/b2b-fabi.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

failed=0
fail() {
  echo "FAIL: $*"
  failed=1
}

echo "library: $lib"

# "TYPE NAME VERSIONED_NAME" for each defined dynamic symbol, the version
# nodes (B2B_FORTRAN_1.0, ...) left out.
. "$(dirname "$0")/dynamic_symbols.sh"
dynamic_symbols "$nm" "$lib" '^B2B_FORTRAN_[0-9]+[.][0-9]+$' "$tmp/exported"
if [ ! -s "$tmp/exported" ]; then
  fail "$nm -D --defined-only lists no symbols in $lib"
fi

# --- 1. only module b2b ---------------------------------------------------
awk '$2 !~ /^__b2b_MOD_/' "$tmp/exported" >"$tmp/leaked"
if [ -s "$tmp/leaked" ]; then
  fail "symbols exported that are not module b2b's (fix cmake/b2b_fortran.map):"
  awk '{ printf "    %s  (type %s)\n", $3, $1 }' "$tmp/leaked"
fi

# --- 2. exactly the listed names -------------------------------------------
sed -e 's/#.*//' "$list" | awk 'NF { print $1, $2 }' >"$tmp/expected.asis"
sort -u "$tmp/expected.asis" >"$tmp/expected"
if ! cmp -s "$tmp/expected.asis" "$tmp/expected"; then
  fail "$list is not sorted (LC_ALL=C sort) or has duplicate lines"
fi
awk '{ print $1 }' "$tmp/expected" | sort -u >"$tmp/expected.names"
awk '{ print $2 }' "$tmp/exported" | sort -u >"$tmp/actual.names"
comm -13 "$tmp/expected.names" "$tmp/actual.names" >"$tmp/extra"
comm -23 "$tmp/expected.names" "$tmp/actual.names" >"$tmp/missing"
if [ -s "$tmp/extra" ] || [ -s "$tmp/missing" ]; then
  fail "exported symbols differ from $list"
  sed 's/^/  + [extra: a new procedure missing from the list, or a leak] /' "$tmp/extra"
  sed 's/^/  - [missing: a lost procedure, or one the map does not export] /' "$tmp/missing"
fi

# --- 3. each in its node -----------------------------------------------------
while read -r name node; do
  v=$(awk -v s="$name" '$2 == s { print $3; exit }' "$tmp/exported")
  [ -n "$v" ] || continue # reported as missing
  if [ "$v" = "$name" ]; then
    fail "$name carries no symbol version, want $name@@$node (cmake/b2b_fortran.map)"
  elif [ "$v" != "$name@@$node" ]; then
    fail "$name has the version '${v#"$name"}', want @@$node (cmake/b2b_fortran.map)"
  fi
done <"$tmp/expected"

# --- 4. SONAME -------------------------------------------------------------
soname=$("$readelf" -d "$lib" | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
if [ "$soname" != "$want_soname" ]; then
  fail "SONAME is '${soname:-<none>}', want '$want_soname' (B2B_FORTRAN_ABI_MAJOR)"
else
  echo "SONAME: $soname"
fi

if [ "$failed" -ne 0 ]; then
  echo "abi_fortran_exports: FAILED"
  exit 1
fi
echo "exported ($(wc -l <"$tmp/actual.names" | tr -d ' ') symbols, all versioned):"
awk '{ printf "    %s\n", $3 }' "$tmp/exported"
echo "abi_fortran_exports: OK"
