#!/bin/sh
# The ABI gate: compares a built shared library with its stored abidw baseline
# (libabigail), or writes that baseline.
#
#   abi_gate.sh check BASELINE LIBRARY [HEADERS_DIR ...]
#   abi_gate.sh dump  LIBRARY  BASELINE [HEADERS_DIR ...]
#
#   BASELINE     tests/abi/<soname>.abi, the abidw dump of the committed ABI
#   LIBRARY      the built library (libb2b.so.1, libb2b_fortran.so.1), with
#                debug info (a RelWithDebInfo or Debug build)
#   HEADERS_DIR  directories of the public headers (include/b2b and the
#                generated <build>/include/b2b); types defined elsewhere, such
#                as the layout behind the opaque b2b_params, are private and
#                not part of the ABI. None for the Fortran library.
#
# check: runs abidiff --no-added-syms, so that added functions pass and
# everything else it reports fails: a removed or renamed function, a changed
# parameter or return type, a changed public type, a changed symbol version.
# Exits 0 if abidiff finds nothing, 1 otherwise (abidiff's own exit code,
# a bit set of 1 error, 2 usage error, 4 ABI change, 8 incompatible ABI
# change, is printed).
# dump: writes BASELINE with the options the baseline in the repository was
# made with (see tests/abi/README.md for when and how to update it).
#
# Environment: ABIDW, ABIDIFF (default: abidw, abidiff from PATH), and
# ABI_SUPPRESSIONS, an optional libabigail suppression file for check.
set -eu
LC_ALL=C
export LC_ALL

usage() {
  echo "usage: $0 check BASELINE LIBRARY [HEADERS_DIR ...]" >&2
  echo "       $0 dump LIBRARY BASELINE [HEADERS_DIR ...]" >&2
  exit 2
}
[ "$#" -ge 3 ] || usage
mode=$1
shift
abidw=${ABIDW:-abidw}
abidiff=${ABIDIFF:-abidiff}

# A library without DWARF would be compared by its symbol table only.
require_debug_info() {
  if ! readelf -S "$1" 2>/dev/null | grep -q '\.debug_info'; then
    echo "abi_gate: $1 has no debug info; build with -g (RelWithDebInfo)" >&2
    exit 2
  fi
}

case $mode in
  check)
    baseline=$1
    lib=$2
    shift 2
    for f in "$baseline" "$lib"; do
      [ -r "$f" ] || { echo "abi_gate: cannot read $f" >&2; exit 2; }
    done
    require_debug_info "$lib"
    set -- --no-added-syms --fail-no-debug-info --no-default-suppression "$@"
    # abidiff FILE1 FILE2 [options]: the header directories belong to FILE2,
    # the baseline already holds only public types. The arguments are
    # rebuilt in place (POSIX sh has no arrays).
    n=$#
    i=0
    while [ "$i" -lt "$n" ]; do
      a=$1
      shift
      case $a in
        --*) set -- "$@" "$a" ;;
        *) set -- "$@" --hd2 "$a" --drop-private-types ;;
      esac
      i=$((i + 1))
    done
    if [ -n "${ABI_SUPPRESSIONS:-}" ]; then
      set -- "$@" --suppressions "$ABI_SUPPRESSIONS"
    fi
    echo "abi_gate: $abidiff $* $baseline $lib"
    rc=0
    "$abidiff" "$@" "$baseline" "$lib" || rc=$?
    if [ "$rc" -ne 0 ]; then
      echo "abi_gate: FAILED: abidiff exit code $rc (bits: 1 error, 2 usage, 4 ABI change, 8 incompatible change)"
      echo "abi_gate: $(basename "$lib") differs from $baseline in more than added functions."
      echo "abi_gate: an incompatible change needs a new ABI major (README, ABI policy); see tests/abi/README.md."
      exit 1
    fi
    echo "abi_gate: $(basename "$lib") keeps the ABI of $(basename "$baseline") (additions allowed)"
    ;;
  dump)
    lib=$1
    out=$2
    shift 2
    [ -r "$lib" ] || { echo "abi_gate: cannot read $lib" >&2; exit 2; }
    require_debug_info "$lib"
    set -- --no-corpus-path --no-comp-dir-path --no-show-locs --exported-interfaces-only "$@"
    n=$#
    i=0
    while [ "$i" -lt "$n" ]; do
      a=$1
      shift
      case $a in
        --*) set -- "$@" "$a" ;;
        *) set -- "$@" --headers-dir "$a" --drop-private-types ;;
      esac
      i=$((i + 1))
    done
    "$abidw" "$@" --out-file "$out" "$lib"
    echo "abi_gate: wrote $out from $lib"
    ;;
  *) usage ;;
esac
