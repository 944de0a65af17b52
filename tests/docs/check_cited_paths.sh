#!/bin/sh
# cited_paths: every repository path cited in the README, the documentation,
# the public headers and the sources exists, so a renamed or deleted file
# cannot leave a dangling reference behind.
#
#   check_cited_paths.sh SOURCE_DIR [BUILD_DIR]
#
# A citation is a word that starts with the name of a top-level directory of
# the repository followed by a slash (doc/curves.md, src/model/, tests/abi/README.md)
# and is not itself part of a longer path (lib/cmake/b2b is not cmake/b2b) or
# of a shell variable's ($work/src/x is not the repository's src/).
# It ends at the first character that cannot be part of a path; trailing dots
# (end of a sentence) are dropped. A citation that runs into a placeholder
# ($, <, { or *: tests/check/check_${suite}.c, include/b2b/<compiler>/) is a
# pattern, and its directory (tests/check/, include/b2b/) must exist. A
# citation exists if it names a file or directory
# relative to SOURCE_DIR or to the citing file's directory, or, when its last
# part has no extension, if a file of that name with an extension exists
# (src/model/assembly: the module of assembly.hpp and assembly.cpp).
# Citations of build/... name build products: they are checked in BUILD_DIR
# (the build tree under test has the layout of the README's build/) when
# BUILD_DIR is given and holds the cited file's directory (build/examples/
# exists only when the examples are built), and are skipped otherwise.
#
# Scanned: README.md, doc/, include/, src/, fortran/, examples/, tests/ and
# cmake/ (text sources only; build trees and .git are never scanned).
#
# A file may mention a path that deliberately does not exist (to say where
# something is not): such a citation is listed, with the reason, in
# cited_paths_exempt.txt next to this script ("file path  # reason").
set -eu

src=${1:?usage: check_cited_paths.sh SOURCE_DIR [BUILD_DIR]}
bin=${2:-}
src=$(cd "$src" && pwd)
[ -z "$bin" ] || bin=$(cd "$bin" && pwd)

# The top-level directories of the repository (build trees excluded).
names=
for d in "$src"/* "$src"/.[!.]*; do
  [ -d "$d" ] || continue
  n=${d##*/}
  case $n in
    .git | build*) continue ;;
  esac
  names="$names${names:+|}$(printf '%s' "$n" | sed 's/\./\\./g')"
done
# and build/, the README's build tree: its citations are checked in
# BUILD_DIR (below).
names="$names|build"

exempt=$(cd "$(dirname "$0")" && pwd)/cited_paths_exempt.txt

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The files to scan, relative to the source directory.
cd "$src"
{
  echo README.md
  for d in doc include src fortran examples tests cmake; do
    [ -d "$d" ] || continue
    find "$d" -type f \( -name '*.md' -o -name '*.h' -o -name '*.h.in' -o -name '*.c' \
      -o -name '*.cpp' -o -name '*.hpp' -o -name '*.f90' -o -name '*.cmake' \
      -o -name 'CMakeLists.txt' -o -name '*.in' -o -name '*.sh' -o -name '*.py' \) -print
  done
} | sort >"$tmp/files"

# Whether cited_paths_exempt.txt lists the citation (file, path). Asked
# only of a citation that names nothing: one grep per citation (thousands of
# them) was most of this script's time.
exempted() {
  [ -f "$exempt" ] && grep -qE "^$1[[:space:]]+$2([[:space:]]|\$)" "$exempt"
}

checked=0
failed=0
# file:line:token for every file in one grep (the files' names hold no
# colon), the token with the character before it (if any) removed: a grep
# and a sed per file were most of this script's time.
tr '\n' '\0' <"$tmp/files" |
  xargs -0 grep -HnoE "(^|[^\$A-Za-z0-9_./-])($names)/[A-Za-z0-9_./-]*[\$<{*]?" |
  sed -E 's/^([^:]*:[0-9]+):[^A-Za-z0-9_.]?/\1:/' >"$tmp/hits" || true
while IFS=: read -r f line path; do
  case $f in
    */*) dir=${f%/*} ;;
    *) dir=. ;;
  esac
  # Drop the dots that end a sentence.
  while :; do
    case $path in
      *.) path=${path%.} ;;
      *) break ;;
    esac
  done
  case $path in
    *[\$\<{*]) path=${path%/*}/ ;; # a pattern: its directory
  esac
  checked=$((checked + 1))
  case $path in
    build/*)
      rest=${path#build/}
      sub=${rest%%/*}
      if [ -n "$bin" ] && [ "$sub" != "$rest" ] && [ -d "$bin/$sub" ]; then
        [ -e "$bin/$rest" ] && continue
        exempted "$f" "$path" && continue
        echo "$f:$line: cited build product '$path' does not exist in $bin"
        failed=$((failed + 1))
      fi
      continue
      ;;
  esac
  [ -e "$path" ] && continue
  [ -e "$dir/$path" ] && continue
  base=${path##*/}
  case $base in
    *.*) ;;
    ?*)
      found=no
      for g in "$path".*; do
        [ -e "$g" ] && found=yes && break
      done
      [ $found = yes ] && continue
      ;;
  esac
  exempted "$f" "$path" && continue
  echo "$f:$line: cited path '$path' does not exist"
  failed=$((failed + 1))
done <"$tmp/hits"

if [ "$failed" -ne 0 ]; then
  echo "cited_paths: $failed of $checked citations name nothing in the repository"
  exit 1
fi
echo "cited_paths: all $checked citations exist"
