#!/bin/sh
# readme_snippets: every C and Fortran snippet of the README compiles against
# the installed library and runs (exit code 0), so a snippet cannot rot.
#   1. extract the README's blocks (extract_snippets.sh; a code block without
#      its marker fails the test);
#   2. install the build tree into a scratch prefix;
#   3. build the snippets as one CMake project (find_package(b2b)): a program
#      as it stands, a fragment inside its wrapper (wrappers/); C with
#      -Wall -Wextra -Werror, Fortran with -Wall -Werror -std=f2018;
#   4. run each one.
# The consumer blocks (cmake files, sh commands) are run by consumer_install.
#
# Options (all --name=value; registered by tests/docs/CMakeLists.txt):
#   --cmake=CMAKE_COMMAND           --generator=CMAKE_GENERATOR
#   --build-dir=<b2b build tree>    --make-program=CMAKE_MAKE_PROGRAM (optional)
#   --readme=<README.md>            --config=<build configuration> (optional)
#   --work-dir=<scratch dir, wiped> --c-compiler=CMAKE_C_COMPILER
#   --fortran-compiler=CMAKE_Fortran_COMPILER (empty: b2b built without
#                                   Fortran, the Fortran snippets are skipped)
set -eu

cmake=
build_dir=
readme=
work_dir=
generator=
make_program=
config=
cc=
fc=
for arg in "$@"; do
  case $arg in
    --cmake=*) cmake=${arg#*=} ;;
    --build-dir=*) build_dir=${arg#*=} ;;
    --readme=*) readme=${arg#*=} ;;
    --work-dir=*) work_dir=${arg#*=} ;;
    --generator=*) generator=${arg#*=} ;;
    --make-program=*) make_program=${arg#*=} ;;
    --config=*) config=${arg#*=} ;;
    --c-compiler=*) cc=${arg#*=} ;;
    --fortran-compiler=*) fc=${arg#*=} ;;
    *) echo "run_readme_snippets: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done
for v in cmake build_dir readme work_dir generator cc; do
  eval "val=\${$v}"
  if [ -z "$val" ]; then
    echo "run_readme_snippets: --$(echo $v | tr _ -)=... is required" >&2
    exit 2
  fi
done
case $work_dir in
  /?*) ;;
  *) echo "run_readme_snippets: --work-dir must be an absolute path" >&2; exit 2 ;;
esac
here=$(cd "$(dirname "$0")" && pwd)
readme=$(cd "$(dirname "$readme")" && pwd)/$(basename "$readme")

unset LD_LIBRARY_PATH CPATH C_INCLUDE_PATH LIBRARY_PATH CMAKE_PREFIX_PATH b2b_DIR b2b_ROOT || true
rm -rf "$work_dir"
mkdir -p "$work_dir/project" "$work_dir/logs"
snippets=$work_dir/snippets
project=$work_dir/project
logs=$work_dir/logs

# run LOG CMD...: CMD with its output in $logs/LOG.log, shown on failure.
run() {
  log=$logs/$1.log
  shift
  if "$@" >"$log" 2>&1; then
    return 0
  fi
  sed 's/^/  | /' "$log"
  echo "FAILED: $*"
  echo "readme_snippets: FAILED"
  exit 1
}

echo "== 1. extract the snippets of $readme"
if ! sh "$here/extract_snippets.sh" "$readme" "$snippets"; then
  echo "readme_snippets: FAILED (mark every code block, see extract_snippets.sh)"
  exit 1
fi

echo "== 2. install the build tree into $work_dir/prefix"
run install "$cmake" --install "$build_dir" --prefix "$work_dir/prefix" ${config:+--config "$config"}

echo "== 3. build the snippets"
langs=C
components=C
[ -z "$fc" ] || { langs="C Fortran"; components="C Fortran"; }
{
  echo "cmake_minimum_required(VERSION 3.20)"
  echo "project(b2b_readme_snippets LANGUAGES $langs)"
  echo "find_package(b2b REQUIRED COMPONENTS $components)"
  echo "set(CMAKE_C_STANDARD 99)"
  echo "set(CMAKE_C_EXTENSIONS OFF)"
} >"$project/CMakeLists.txt"
: >"$work_dir/programs"
while read -r line lang role arg; do
  case $role in
    program | fragment) ;;
    *) continue ;;
  esac
  name=readme_$line
  case $lang in
    c)
      src=$project/$name.c
      if [ "$role" = program ]; then
        { echo "#line $((line + 1)) \"$readme\""; cat "$snippets/$line.c"; } >"$src"
      else
        wrapper=$here/wrappers/$arg
        [ -f "$wrapper" ] || { echo "$readme:$line: no wrapper $wrapper"; exit 1; }
        awk -v snip="$snippets/$line.c" -v first=$((line + 1)) -v rd="$readme" -v wr="$wrapper" '
          /README SNIPPET/ {
            printf "#line %d \"%s\"\n", first, rd
            while ((getline l < snip) > 0) print l
            printf "#line %d \"%s\"\n", NR + 1, wr
            next
          }
          { print }' "$wrapper" >"$src"
      fi
      echo "add_executable($name $name.c)" >>"$project/CMakeLists.txt"
      echo "target_link_libraries($name PRIVATE b2b::b2b)" >>"$project/CMakeLists.txt"
      echo "target_compile_options($name PRIVATE \$<\$<C_COMPILER_ID:GNU,Clang>:-Wall;-Wextra;-Werror>)" \
        >>"$project/CMakeLists.txt"
      ;;
    fortran)
      if [ -z "$fc" ]; then
        echo "  $readme:$line ($role): skipped, b2b is built without Fortran"
        continue
      fi
      src=$project/$name.f90
      if [ "$role" = program ]; then
        cp "$snippets/$line.f90" "$src"
      else
        wrapper=$here/wrappers/$arg
        [ -f "$wrapper" ] || { echo "$readme:$line: no wrapper $wrapper"; exit 1; }
        awk -v snip="$snippets/$line.f90" '
          /README SNIPPET/ { while ((getline l < snip) > 0) print l; next }
          { print }' "$wrapper" >"$src"
      fi
      echo "add_executable($name $name.f90)" >>"$project/CMakeLists.txt"
      echo "target_link_libraries($name PRIVATE b2b::fortran)" >>"$project/CMakeLists.txt"
      echo "target_compile_options($name PRIVATE \$<\$<Fortran_COMPILER_ID:GNU>:-Wall;-Werror;-std=f2018>)" \
        >>"$project/CMakeLists.txt"
      ;;
    *)
      echo "$readme:$line: a $role of language $lang cannot be built"
      exit 1
      ;;
  esac
  echo "$line $role $name" >>"$work_dir/programs"
done <"$snippets/manifest"
if [ ! -s "$work_dir/programs" ]; then
  echo "readme_snippets: FAILED, the README has no C or Fortran snippet to build"
  exit 1
fi
run configure "$cmake" -S "$project" -B "$project/build" -G "$generator" \
  "-DCMAKE_C_COMPILER=$cc" ${fc:+"-DCMAKE_Fortran_COMPILER=$fc"} \
  ${config:+"-DCMAKE_BUILD_TYPE=$config"} "-DCMAKE_PREFIX_PATH=$work_dir/prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF ${make_program:+"-DCMAKE_MAKE_PROGRAM=$make_program"}
run build "$cmake" --build "$project/build" ${config:+--config "$config"}

echo "== 4. run them"
failed=0
while read -r line role name; do
  exe=$project/build/$name
  [ -x "$exe" ] || exe=$project/build/$config/$name # multi-configuration generators
  if "$exe" >"$logs/$name.out" 2>&1; then
    echo "  $readme:$line ($role): OK"
    sed 's/^/  | /' "$logs/$name.out"
  else
    rc=$?
    echo "  $readme:$line ($role): FAILED (exit $rc)"
    sed 's/^/  | /' "$logs/$name.out"
    failed=$((failed + 1))
  fi
done <"$work_dir/programs"
if [ "$failed" -ne 0 ]; then
  echo "readme_snippets: FAILED ($failed snippets)"
  exit 1
fi
echo "readme_snippets: OK"
