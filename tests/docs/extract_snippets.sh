#!/bin/sh
# Extracts the code blocks of a Markdown file (the README) by their markers,
# and checks that every code block has one, so that no snippet escapes the
# tests that compile and run them (run_readme_snippets.sh, consumer_install).
#
#   extract_snippets.sh README OUTDIR
#
# The convention (documented in README.md, "Tests"): a fenced block whose
# info string names a language (```c, ```fortran, ```cmake, ```sh, ...) is a
# code block, and the line right above its opening fence must be a marker
#   <!-- snippet: ROLE ARGUMENT -->
# (an HTML comment: invisible once rendered). Roles:
#   program              c or fortran: a complete program, compiled against
#                        the library and run; it must exit with 0
#   fragment WRAPPER     c or fortran: statements compiled and run inside
#                        tests/docs/wrappers/<WRAPPER>, at its README SNIPPET line
#   file PATH            the file PATH of the README's host project, written
#                        by consumer_install before it runs the commands
#   consumer PART        sh: commands consumer_install runs as they stand,
#                        PART install (always), c (always), fortran (when b2b
#                        is built with Fortran)
#   exempt REASON        not run (REASON says why, and must be given)
# Fences without an info string (or ```text) hold prose, tables or layouts,
# not code, and need no marker.
#
# Writes OUTDIR/<line>.<ext> for each marked block (<line>: the line of its
# opening fence; ext c, f90, cmake, sh or txt) and OUTDIR/manifest with one
# line per block: "<line> <lang> <role> <argument>". Prints every violation
# as README:line: message and exits with 1 if there is any.
set -eu
readme=${1:?usage: extract_snippets.sh README OUTDIR}
out=${2:?usage: extract_snippets.sh README OUTDIR}
mkdir -p "$out"
rm -f "$out"/manifest "$out"/*.c "$out"/*.f90 "$out"/*.cmake "$out"/*.sh "$out"/*.txt
: >"$out/manifest"

awk -v out="$out" -v name="$readme" '
function fail(l, msg) { printf "%s:%d: %s\n", name, l, msg; errors++ }
function ext(lang) {
  if (lang == "c") return "c"
  if (lang == "fortran") return "f90"
  if (lang == "cmake") return "cmake"
  if (lang == "sh") return "sh"
  return "txt"
}
BEGIN { inblock = 0; errors = 0; marker = ""; marker_line = 0 }
{
  line = $0
  if (inblock) {
    if (line ~ /^(   |  | )?```[ \t]*$/) {
      inblock = 0
      if (file != "") close(file)
    } else if (file != "") {
      print line > file
    }
    next
  }
  if (line ~ /^(   |  | )?```/) {
    lang = line
    sub(/^ *```[ \t]*/, "", lang)
    sub(/[ \t].*$/, "", lang)
    inblock = 1
    start = NR
    file = ""
    if (lang == "" || lang == "text") {
      if (marker != "" && marker_line == NR - 1)
        fail(marker_line, "a marker above a block that is not code (no language)")
      marker = ""
      next
    }
    if (marker == "" || marker_line != NR - 1) {
      fail(NR, "```" lang " block without a <!-- snippet: ROLE ARGUMENT --> marker on the line above")
      marker = ""
      next
    }
    n = split(marker, w, " ")
    role = w[1]
    arg = ""
    for (i = 2; i <= n; i++) arg = arg (i > 2 ? " " : "") w[i]
    ok = 1
    if (role == "program") {
      if (lang != "c" && lang != "fortran") { fail(marker_line, "program: only for c or fortran blocks"); ok = 0 }
      if (arg != "") { fail(marker_line, "program takes no argument"); ok = 0 }
    } else if (role == "fragment") {
      if (lang != "c" && lang != "fortran") { fail(marker_line, "fragment: only for c or fortran blocks"); ok = 0 }
      if (arg == "" || arg ~ / /) { fail(marker_line, "fragment needs one argument, the wrapper file"); ok = 0 }
    } else if (role == "file") {
      if (arg == "" || arg ~ / / || arg ~ /^\// || arg ~ /\.\./) { fail(marker_line, "file needs one relative path without .."); ok = 0 }
    } else if (role == "consumer") {
      if (lang != "sh") { fail(marker_line, "consumer: only for sh blocks"); ok = 0 }
      if (arg != "install" && arg != "c" && arg != "fortran") { fail(marker_line, "consumer needs install, c or fortran"); ok = 0 }
    } else if (role == "exempt") {
      if (arg == "") { fail(marker_line, "exempt needs a reason"); ok = 0 }
    } else {
      fail(marker_line, "unknown snippet role \"" role "\" (program, fragment, file, consumer, exempt)")
      ok = 0
    }
    marker = ""
    if (!ok) next
    file = out "/" start "." ext(lang)
    printf "" > file
    printf "%d %s %s %s\n", start, lang, role, arg >> (out "/manifest")
    next
  }
  if (marker != "" && marker_line == NR - 1)
    fail(marker_line, "a snippet marker must stand on the line right above the block'"'"'s opening fence")
  if (line ~ /^<!-- snippet:/) {
    if (line !~ /^<!-- snippet: [^ ].* -->[ \t]*$/) {
      fail(NR, "malformed marker: <!-- snippet: ROLE ARGUMENT -->")
    } else {
      marker = line
      sub(/^<!-- snippet: /, "", marker)
      sub(/ -->[ \t]*$/, "", marker)
      marker_line = NR
    }
  }
}
END {
  if (inblock) fail(start, "the block opened here is never closed")
  if (marker != "" && marker_line == NR) fail(marker_line, "a marker at the end of the file")
  exit errors ? 1 : 0
}' "$readme"
