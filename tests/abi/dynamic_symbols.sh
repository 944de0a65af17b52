# Sourced by check_exports.sh and check_fortran_exports.sh: the one reading
# of a library's dynamic symbols both checks work on.
#
#   dynamic_symbols NM LIBRARY NODE_REGEX OUT
#
# writes to OUT "TYPE NAME VERSIONED_NAME" for every dynamic symbol LIBRARY
# defines, sorted by name, leaving out the symbol-version nodes themselves
# (type A, names matching the awk regular expression NODE_REGEX), and the
# raw nm output to OUT.raw. GNU nm >= 2.37 prints the versions by default;
# older ones need --with-symbol-versions.
dynamic_symbols() {
  if ! "$1" -D --defined-only --with-symbol-versions "$2" >"$4.raw" 2>/dev/null; then
    "$1" -D --defined-only "$2" >"$4.raw"
  fi
  awk -v node="$3" 'NF >= 2 {
    versioned = $NF
    name = versioned
    sub(/@.*/, "", name)
    if ($(NF-1) == "A" && name ~ node) next
    print $(NF-1), name, versioned
  }' "$4.raw" | sort -k2,2 >"$4"
}
