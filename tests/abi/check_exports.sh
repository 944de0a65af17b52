#!/bin/sh
# Checks that the shared library libb2b exports exactly the C ABI.
#
#   check_exports.sh LIBRARY SYMBOLS_TXT VERSION_H [NM [READELF]]
#
#   LIBRARY      the built libb2b.so ($<TARGET_FILE:b2b>)
#   SYMBOLS_TXT  the exported ABI functions, one name per line, sorted
#                (tests/abi/symbols.txt)
#   VERSION_H    the configured b2b_version.h (defines B2B_SOVERSION)
#   NM, READELF  the binutils to use (default: nm, readelf)
#
# Asserts that
#   1. every dynamic symbol the library defines starts with b2b_ (the version
#      node symbols of type A, e.g. B2B_1.0, excepted);
#   2. the set of exported names equals SYMBOLS_TXT, and each is a function;
#   3. each of them carries a default symbol version, name@@B2B_<x>.<y> with
#      x >= 1 (the nodes of cmake/b2b.map);
#   4. the SONAME is libb2b.so.<B2B_SOVERSION>.
# Prints every violation (a diff for the symbol set) and exits 1 if any.
set -eu
LC_ALL=C
export LC_ALL

if [ "$#" -lt 3 ] || [ "$#" -gt 5 ]; then
  echo "usage: $0 LIBRARY SYMBOLS_TXT VERSION_H [NM [READELF]]" >&2
  exit 2
fi
lib=$1
list=$2
version_h=$3
nm=${4:-nm}
readelf=${5:-readelf}

for f in "$lib" "$list" "$version_h"; do
  if [ ! -r "$f" ]; then
    echo "check_exports: cannot read $f" >&2
    exit 2
  fi
done

tmp=$(mktemp -d "${TMPDIR:-/tmp}/b2b-abi.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

failed=0
fail() {
  echo "FAIL: $*"
  failed=1
}

echo "library: $lib"

# --- the dynamic symbols, version nodes (B2B_1.0, ...) left out: they are
# not part of the ABI surface. "TYPE NAME VERSIONED_NAME" each.
. "$(dirname "$0")/dynamic_symbols.sh"
dynamic_symbols "$nm" "$lib" '^B2B_[0-9]+[.][0-9]+$' "$tmp/exported"
if [ ! -s "$tmp/exported" ]; then
  echo "FAIL: $nm -D --defined-only lists no symbols in $lib"
  exit 1
fi

# --- 1. nothing but b2b_* -------------------------------------------------
awk '$2 !~ /^b2b_/' "$tmp/exported" >"$tmp/leaked"
if [ -s "$tmp/leaked" ]; then
  fail "symbols exported without the b2b_ prefix (leaked; hide them or fix cmake/b2b.map):"
  awk '{ printf "    %s  (type %s)\n", $3, $1 }' "$tmp/leaked"
fi

# --- 2. exactly the listed functions --------------------------------------
# symbols.txt: one name per line; blank lines and # comments are ignored.
sed -e 's/#.*//' -e 's/[[:space:]]//g' "$list" | awk 'NF' >"$tmp/expected.asis"
sort -u "$tmp/expected.asis" >"$tmp/expected"
if ! cmp -s "$tmp/expected.asis" "$tmp/expected"; then
  fail "$list is not sorted (LC_ALL=C sort) or has duplicate names"
fi
awk '{ print $2 }' "$tmp/exported" | sort -u >"$tmp/actual"

comm -13 "$tmp/expected" "$tmp/actual" >"$tmp/extra"
comm -23 "$tmp/expected" "$tmp/actual" >"$tmp/missing"
if [ -s "$tmp/extra" ] || [ -s "$tmp/missing" ]; then
  fail "exported symbols differ from $list"
  echo "  --- $list (expected)"
  echo "  +++ dynamic symbols of $(basename "$lib") (actual)"
  while read -r s; do
    t=$(awk -v s="$s" '$2 == s { print $1; exit }' "$tmp/exported")
    echo "  + $s    [extra, type $t: a leaked symbol, or a new ABI function missing from symbols.txt]"
  done <"$tmp/extra"
  while read -r s; do
    echo "  - $s    [missing: a lost ABI function]"
  done <"$tmp/missing"
fi

# Listed symbols must be functions (T text, W weak, i indirect), not data.
while read -r s; do
  t=$(awk -v s="$s" '$2 == s { print $1; exit }' "$tmp/exported")
  case $t in
    '' | T | W | i) ;;
    *) fail "$s is exported as a symbol of type $t, not as a function" ;;
  esac
done <"$tmp/expected"

# --- 3. symbol versions ---------------------------------------------------
while read -r s; do
  v=$(awk -v s="$s" '$2 == s { print $3; exit }' "$tmp/exported")
  [ -n "$v" ] || continue # already reported as missing
  node=${v#"$s"}
  if printf '%s\n' "$node" | grep -Eq '^@@B2B_[1-9][0-9]*\.[0-9]+$'; then
    continue
  fi
  case $node in
    '') fail "$s carries no symbol version (want ${s}@@B2B_1.0 or a later B2B_x.y node)" ;;
    @[!@]*) fail "$s has only the non-default version '$v' (want ${s}@@B2B_<x>.<y>)" ;;
    *) fail "$s has the unexpected version '$v' (want ${s}@@B2B_1.0 or a later B2B_x.y node)" ;;
  esac
done <"$tmp/expected"

# --- 4. SONAME -----------------------------------------------------------
sov=$(sed -n 's/^[[:space:]]*#[[:space:]]*define[[:space:]][[:space:]]*B2B_SOVERSION[[:space:]][[:space:]]*\([0-9][0-9]*\).*/\1/p' "$version_h")
if [ -z "$sov" ]; then
  fail "no '#define B2B_SOVERSION <N>' in $version_h"
else
  soname=$("$readelf" -d "$lib" | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
  if [ "$soname" != "libb2b.so.$sov" ]; then
    fail "SONAME is '${soname:-<none>}', want 'libb2b.so.$sov' (B2B_SOVERSION in $version_h)"
  else
    echo "SONAME: $soname (B2B_SOVERSION $sov)"
  fi
fi

if [ "$failed" -ne 0 ]; then
  echo "abi_exports: FAILED"
  exit 1
fi
echo "exported ($(wc -l <"$tmp/actual" | tr -d ' ') functions, all versioned):"
awk '{ printf "    %s\n", $3 }' "$tmp/exported"
echo "abi_exports: OK"
