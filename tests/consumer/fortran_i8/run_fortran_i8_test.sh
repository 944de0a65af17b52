#!/bin/sh
# consumer_fortran_i8: a legacy Fortran host that compiles the module source
# b2b installs with its own flags, -fdefault-integer-8 -fdefault-real-8, and
# links libb2b only (not libb2b_fortran, whose module it replaces):
#   1. cmake --install the b2b build tree into a scratch prefix;
#   2. compile <prefix>/<datadir>/b2b/fortran/b2b.f90 (which includes
#      b2b_constants.inc from its own directory), then its submodules
#      b2b_curve.f90, b2b_pair.f90, b2b_pair_line.f90, b2b_model.f90, b2b_support.f90, with
#      those flags;
#   3. compile consumer_i8.f90 with them, link it with the module's objects and
#      $(pkg-config --libs b2b) (--static for a static libb2b);
#   4. run it (it exits non-zero on any failure) without LD_LIBRARY_PATH and,
#      for a shared libb2b, check with ldd that libb2b comes from the prefix
#      and libb2b_fortran is not loaded at all.
#
# Options (all --name=value; registered by consumer_fortran_i8.cmake here):
#   --cmake=CMAKE_COMMAND               --build-dir=<b2b build tree>
#   --work-dir=<scratch dir, wiped>     --source-dir=<this directory>
#   --fortran-compiler=<gfortran>       --pkg-config=PKG_CONFIG_EXECUTABLE
#   --libdir=CMAKE_INSTALL_LIBDIR       --datadir=CMAKE_INSTALL_DATADIR
#   --shared=ON|OFF (BUILD_SHARED_LIBS)
#   --built-lib=<built library>  (repeatable; checked to exist before installing)
set -eu

cmake=
build_dir=
work_dir=
source_dir=
fc=
pkg_config=pkg-config
libdir=lib
datadir=share
shared=ON
built_libs=
flags="-fdefault-integer-8 -fdefault-real-8"

for arg in "$@"; do
  case $arg in
    --cmake=*) cmake=${arg#*=} ;;
    --build-dir=*) build_dir=${arg#*=} ;;
    --work-dir=*) work_dir=${arg#*=} ;;
    --source-dir=*) source_dir=${arg#*=} ;;
    --fortran-compiler=*) fc=${arg#*=} ;;
    --pkg-config=*) pkg_config=${arg#*=} ;;
    --libdir=*) libdir=${arg#*=} ;;
    --datadir=*) datadir=${arg#*=} ;;
    --shared=*) shared=${arg#*=} ;;
    --built-lib=*) built_libs="$built_libs ${arg#*=}" ;;
    *) echo "run_fortran_i8_test: unknown argument '$arg'" >&2; exit 2 ;;
  esac
done
for pair in cmake:cmake build_dir:build-dir work_dir:work-dir source_dir:source-dir \
  fc:fortran-compiler; do
  eval "val=\${${pair%%:*}}"
  if [ -z "$val" ]; then
    echo "run_fortran_i8_test: --${pair#*:}=... is required" >&2
    exit 2
  fi
done
case $work_dir in
  /?*) ;;
  *) echo "run_fortran_i8_test: --work-dir must be an absolute path, not '$work_dir'" >&2; exit 2 ;;
esac
case $shared in
  ON | OFF) ;;
  *) echo "run_fortran_i8_test: --shared must be ON or OFF, not '$shared'" >&2; exit 2 ;;
esac
for f in $built_libs; do
  if [ ! -f "$f" ]; then
    echo "run_fortran_i8_test: $f does not exist: build the whole project before running ctest" >&2
    exit 1
  fi
done

# Nothing but the prefix may lead the host to b2b.
unset LD_LIBRARY_PATH LD_RUN_PATH LIBRARY_PATH CPATH PKG_CONFIG_PATH PKG_CONFIG_LIBDIR \
  PKG_CONFIG_SYSROOT_DIR || true

rm -rf "$work_dir"
mkdir -p "$work_dir/logs" "$work_dir/host"
prefix=$work_dir/prefix
logs=$work_dir/logs
host=$work_dir/host

# run LOG CMD...: CMD with its output in $logs/LOG.log, shown on failure.
run() {
  log=$logs/$1.log
  shift
  echo "+ $*"
  if "$@" >"$log" 2>&1; then
    sed 's/^/  | /' "$log"
  else
    rc=$?
    sed 's/^/  | /' "$log"
    echo "FAILED (exit $rc): $*"
    echo "consumer_fortran_i8: FAILED"
    exit 1
  fi
}

echo "== 1. install into $prefix"
run install "$cmake" --install "$build_dir" --prefix "$prefix"
msrc=$prefix/$datadir/b2b/fortran
module_sources="b2b.f90 b2b_curve.f90 b2b_pair.f90 b2b_pair_line.f90 b2b_model.f90 b2b_support.f90"  # module first
for f in $module_sources b2b_constants.inc; do
  if [ ! -f "$msrc/$f" ]; then
    echo "FAILED: the install tree lacks $msrc/$f"
    echo "consumer_fortran_i8: FAILED"
    exit 1
  fi
done
if [ ! -f "$prefix/$libdir/pkgconfig/b2b.pc" ]; then
  echo "FAILED: the install tree lacks $prefix/$libdir/pkgconfig/b2b.pc"
  echo "consumer_fortran_i8: FAILED"
  exit 1
fi

echo "== 2. the module source, compiled by the host with $flags"
module_objects=
for f in $module_sources; do
  o=$host/${f%.f90}.o
  # shellcheck disable=SC2086 # $flags holds several options
  run "module_${f%.f90}" "$fc" $flags -Wall -J "$host" -c "$msrc/$f" -o "$o"
  module_objects="$module_objects $o"
done

echo "== 3. the host program, linked with libb2b through pkg-config"
PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
export PKG_CONFIG_PATH
if [ "$shared" = ON ]; then
  c_libs=$("$pkg_config" --libs b2b)
else
  c_libs=$("$pkg_config" --static --libs b2b)
fi
pc_libdir=$("$pkg_config" --variable=libdir b2b)
pc_libdir=$(cd "$pc_libdir" && pwd -P)
echo "  b2b: $c_libs"
# shellcheck disable=SC2086
run host "$fc" $flags -Wall -I "$host" -o "$host/consumer_i8" "$source_dir/consumer_i8.f90" \
  $module_objects $c_libs "-Wl,-rpath,$pc_libdir"

echo "== 4. run"
run consumer_i8 "$host/consumer_i8"
if [ "$shared" = ON ] && command -v ldd >/dev/null 2>&1; then
  ldd "$host/consumer_i8" >"$logs/ldd.out"
  grep 'libb2b' "$logs/ldd.out" | sed 's/^[[:space:]]*/  ldd: /'
  if grep -q 'libb2b_fortran' "$logs/ldd.out"; then
    echo "FAILED: the host loads libb2b_fortran, but it compiled the module itself"
    echo "consumer_fortran_i8: FAILED"
    exit 1
  fi
  resolved=$(awk '$1 ~ /^libb2b\.so/ { print $3; exit }' "$logs/ldd.out")
  case $resolved in
    "$prefix"/* | "$pc_libdir"/*) ;;
    *)
      echo "FAILED: the host loads libb2b from '$resolved', not from the install prefix $prefix"
      echo "consumer_fortran_i8: FAILED"
      exit 1
      ;;
  esac
fi
echo "consumer_fortran_i8: OK"
