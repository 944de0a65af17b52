#!/bin/sh
# consumer_install: a host project built against the INSTALL tree of b2b works
# through every route a host may take:
#   1. cmake --install the b2b build tree into a fresh prefix;
#   2. CMake:      find_package(b2b 0.1 REQUIRED COMPONENTS ...), the C program
#                  (c/, b2b::b2b) and the Fortran program (fortran/, b2b::fortran);
#   3. pkg-config: the same programs compiled and linked with
#                  $(pkg-config --cflags --libs b2b) and ... b2b-fortran.
# Every program runs without LD_LIBRARY_PATH: the CMake route relies on CMake's
# build RPATH, the pkg-config route on -Wl,-rpath,<libdir>, and libb2b_fortran
# finds libb2b through its install RPATH $ORIGIN. Each program must resolve
# libb2b from the prefix, not from the build tree.
#
# Options (all --name=value; registered by tests/consumer/CMakeLists.txt):
#   --cmake=CMAKE_COMMAND             --generator=CMAKE_GENERATOR
#   --build-dir=<b2b build tree>      --make-program=CMAKE_MAKE_PROGRAM (optional)
#   --work-dir=<scratch dir, wiped>   --config=<build configuration> (optional)
#   --source-dir=<tests/consumer>     --c-compiler=CMAKE_C_COMPILER
#   --libdir=CMAKE_INSTALL_LIBDIR     --fortran-compiler=CMAKE_Fortran_COMPILER
#   --pkg-config=PKG_CONFIG_EXECUTABLE
#   --built-lib=<built libb2b>  (repeatable; checked to exist before installing)
set -eu

cmake=
build_dir=
work_dir=
source_dir=
libdir=lib
generator=
make_program=
config=
cc=
fc=
pkg_config=pkg-config
built_libs=

usage() {
  sed -n '2,/^set -eu/p' "$0" | sed '$d' >&2
  exit 2
}

for arg in "$@"; do
  case $arg in
    --cmake=*) cmake=${arg#*=} ;;
    --build-dir=*) build_dir=${arg#*=} ;;
    --work-dir=*) work_dir=${arg#*=} ;;
    --source-dir=*) source_dir=${arg#*=} ;;
    --libdir=*) libdir=${arg#*=} ;;
    --generator=*) generator=${arg#*=} ;;
    --make-program=*) make_program=${arg#*=} ;;
    --config=*) config=${arg#*=} ;;
    --c-compiler=*) cc=${arg#*=} ;;
    --fortran-compiler=*) fc=${arg#*=} ;;
    --pkg-config=*) pkg_config=${arg#*=} ;;
    --built-lib=*) built_libs="$built_libs ${arg#*=}" ;;
    *) echo "run_consumer_test: unknown argument '$arg'" >&2; usage ;;
  esac
done
for pair in cmake:cmake build_dir:build-dir work_dir:work-dir source_dir:source-dir \
  generator:generator cc:c-compiler fc:fortran-compiler; do
  eval "val=\${${pair%%:*}}"
  if [ -z "$val" ]; then
    echo "run_consumer_test: --${pair#*:}=... is required" >&2
    usage
  fi
done
case $work_dir in
  /?*) ;;
  *) echo "run_consumer_test: --work-dir must be an absolute path, not '$work_dir'" >&2; exit 2 ;;
esac

# The install step installs what the build produced: it must be complete.
for f in $built_libs; do
  if [ ! -f "$f" ]; then
    echo "run_consumer_test: $f does not exist: build the whole project before running ctest" >&2
    exit 1
  fi
done

# A consumer's environment: nothing that would let it find b2b other than the
# install prefix given below.
unset LD_LIBRARY_PATH LD_RUN_PATH DYLD_LIBRARY_PATH LIBRARY_PATH CPATH C_INCLUDE_PATH \
  PKG_CONFIG_LIBDIR PKG_CONFIG_SYSROOT_DIR b2b_DIR b2b_ROOT B2B_ROOT CMAKE_PREFIX_PATH || true

rm -rf "$work_dir"
mkdir -p "$work_dir/logs"
prefix=$work_dir/prefix
logs=$work_dir/logs

# run LOG CMD...: runs CMD with its output in $logs/LOG.log, shown on failure.
run() {
  log=$logs/$1.log
  shift
  echo "+ $*"
  if "$@" >"$log" 2>&1; then
    return 0
  else
    rc=$?
    sed 's/^/  | /' "$log"
    echo "FAILED (exit $rc): $*"
    echo "consumer_install: FAILED"
    exit 1
  fi
}

# check_runtime EXE: runs EXE and checks that it loaded libb2b from the prefix.
check_runtime() {
  exe=$1
  echo "+ $exe"
  if "$exe"; then :; else
    rc=$?
    echo "FAILED (exit $rc): $exe"
    echo "consumer_install: FAILED"
    exit 1
  fi
  if command -v ldd >/dev/null 2>&1; then
    ldd "$exe" | grep 'libb2b' >"$logs/ldd.out" || true
    sed 's/^[[:space:]]*/  ldd: /' "$logs/ldd.out"
    if [ ! -s "$logs/ldd.out" ] || grep -v -e "=> $prefix/" -e "=> $prefix_real/" "$logs/ldd.out" >/dev/null; then
      echo "FAILED: $exe does not load libb2b from the install prefix $prefix"
      echo "consumer_install: FAILED"
      exit 1
    fi
  fi
}

echo "== 1. install into $prefix"
run install "$cmake" --install "$build_dir" --prefix "$prefix" ${config:+--config "$config"}
prefix_real=$(cd "$prefix" && pwd -P)
package_dir=$prefix/$libdir/cmake/b2b
pc_dir=$prefix/$libdir/pkgconfig
for f in "$package_dir/b2bConfig.cmake" "$package_dir/b2bConfigVersion.cmake" \
  "$pc_dir/b2b.pc" "$pc_dir/b2b-fortran.pc"; do
  if [ ! -f "$f" ]; then
    echo "FAILED: the install tree lacks $f"
    exit 1
  fi
done

echo "== 2. CMake: find_package(b2b) from the install prefix"
for lang in c fortran; do
  bdir=$work_dir/cmake-$lang
  run "cmake-$lang-configure" "$cmake" -S "$source_dir/$lang" -B "$bdir" -G "$generator" \
    "-DCMAKE_C_COMPILER=$cc" "-DCMAKE_Fortran_COMPILER=$fc" "-DCMAKE_BUILD_TYPE=$config" \
    "-DCMAKE_PREFIX_PATH=$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
    ${make_program:+"-DCMAKE_MAKE_PROGRAM=$make_program"}
  found=$(sed -n 's/^b2b_DIR:[A-Z]*=//p' "$bdir/CMakeCache.txt")
  echo "  b2b_DIR = $found"
  if [ "$found" != "$package_dir" ]; then
    echo "FAILED: find_package(b2b) found '$found', not the install tree $package_dir"
    exit 1
  fi
  run "cmake-$lang-build" "$cmake" --build "$bdir" ${config:+--config "$config"}
  exe=$bdir/b2b_consumer_$lang
  [ -x "$exe" ] || exe=$bdir/$config/b2b_consumer_$lang # multi-configuration generators
  check_runtime "$exe"
done

echo "== 3. pkg-config: PKG_CONFIG_PATH=$pc_dir"
PKG_CONFIG_PATH=$pc_dir
export PKG_CONFIG_PATH
run pkg-config-exists "$pkg_config" --print-errors --exists "b2b >= 0.1" "b2b-fortran >= 0.1"
pc_libdir=$("$pkg_config" --variable=libdir b2b)
pc_libdir=$(cd "$pc_libdir" && pwd -P)
c_flags=$("$pkg_config" --cflags --libs b2b)
f_flags=$("$pkg_config" --cflags --libs b2b-fortran)
echo "  b2b $("$pkg_config" --modversion b2b), libdir $pc_libdir"
echo "  b2b:         $c_flags"
echo "  b2b-fortran: $f_flags"
mkdir -p "$work_dir/pkg-config"
# shellcheck disable=SC2086 # the pkg-config flags are meant to be split
run pkg-config-c "$cc" -o "$work_dir/pkg-config/b2b_consumer_c" "$source_dir/c/consumer.c" \
  $c_flags "-Wl,-rpath,$pc_libdir"
check_runtime "$work_dir/pkg-config/b2b_consumer_c"
# shellcheck disable=SC2086
run pkg-config-fortran "$fc" -o "$work_dir/pkg-config/b2b_consumer_fortran" \
  "$source_dir/fortran/consumer.f90" $f_flags "-Wl,-rpath,$pc_libdir"
check_runtime "$work_dir/pkg-config/b2b_consumer_fortran"

echo "consumer_install: OK"
