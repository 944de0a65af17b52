#!/bin/sh
# consumer_install: the README's section "Installing and using the library"
# followed as it stands. Its install command and its host projects' commands
# (the blocks marked "consumer" and "file" in README.md) run unchanged, so
# the README cannot drift from what works:
#   1. the install block: cmake --install build --prefix "$HOME/.local";
#   2. the C blocks: the host project my_host/ (its CMakeLists.txt from the
#      README, my_host.c = c/consumer.c here) built with find_package(b2b),
#      and my_host.c built with pkg-config; each program run;
#   3. the Fortran blocks likewise (my_fortran_host/, fortran/consumer.f90),
#      when b2b is built with Fortran.
# The commands run with sh -eu in a scratch directory in which build is the
# b2b build tree under test and HOME a scratch home, with cmake, pkg-config
# and the compilers b2b was built with first on PATH as cmake, pkg-config,
# cc and gfortran (and as CC and FC for CMake). No LD_LIBRARY_PATH: every
# program must find libb2b in the prefix by itself (CMake's RPATH, or the
# -Wl,-rpath of the pkg-config commands), which ldd then confirms.
#
# Options (all --name=value; registered by tests/consumer/CMakeLists.txt, and
# run by scripts/quickstart.sh conly for the C-only build):
#   --cmake=CMAKE_COMMAND             --generator=CMAKE_GENERATOR
#   --build-dir=<b2b build tree>      --readme=<README.md>
#   --work-dir=<scratch dir, wiped>   --source-dir=<tests/consumer>
#   --libdir=CMAKE_INSTALL_LIBDIR     --c-compiler=CMAKE_C_COMPILER
#   --shared=ON|OFF (BUILD_SHARED_LIBS)
#   --fortran-compiler=CMAKE_Fortran_COMPILER (empty or absent: b2b is built
#                                      without Fortran; its blocks are skipped
#                                      and its files must not be installed)
#   --pkg-config=PKG_CONFIG_EXECUTABLE
#   --built-lib=<built library>  (repeatable; checked to exist before installing)
set -eu

cmake=
build_dir=
readme=
work_dir=
source_dir=
libdir=lib
generator=
cc=
fc=
shared=ON
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
    --readme=*) readme=${arg#*=} ;;
    --work-dir=*) work_dir=${arg#*=} ;;
    --source-dir=*) source_dir=${arg#*=} ;;
    --libdir=*) libdir=${arg#*=} ;;
    --generator=*) generator=${arg#*=} ;;
    --c-compiler=*) cc=${arg#*=} ;;
    --fortran-compiler=*) fc=${arg#*=} ;;
    --shared=*) shared=${arg#*=} ;;
    --pkg-config=*) pkg_config=${arg#*=} ;;
    --built-lib=*) built_libs="$built_libs ${arg#*=}" ;;
    *) echo "run_consumer_test: unknown argument '$arg'" >&2; usage ;;
  esac
done
for pair in cmake:cmake build_dir:build-dir readme:readme work_dir:work-dir \
  source_dir:source-dir generator:generator cc:c-compiler; do
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
case $shared in
  ON | OFF) ;;
  *) echo "run_consumer_test: --shared must be ON or OFF, not '$shared'" >&2; exit 2 ;;
esac
build_dir=$(cd "$build_dir" && pwd)
source_dir=$(cd "$source_dir" && pwd)
readme=$(cd "$(dirname "$readme")" && pwd)/$(basename "$readme")
extract=$source_dir/../docs/extract_snippets.sh

# The install step installs what the build produced: it must be complete.
for f in $built_libs; do
  if [ ! -f "$f" ]; then
    echo "run_consumer_test: $f does not exist: build the whole project before running ctest" >&2
    exit 1
  fi
done

# A consumer's environment: nothing that would let it find b2b other than
# the install prefix the README's commands name.
unset LD_LIBRARY_PATH LD_RUN_PATH DYLD_LIBRARY_PATH LIBRARY_PATH CPATH C_INCLUDE_PATH \
  PKG_CONFIG_PATH PKG_CONFIG_LIBDIR PKG_CONFIG_SYSROOT_DIR b2b_DIR b2b_ROOT B2B_ROOT \
  CMAKE_PREFIX_PATH CMAKE_GENERATOR CC CXX FC || true

rm -rf "$work_dir"
mkdir -p "$work_dir/logs" "$work_dir/home" "$work_dir/bin" "$work_dir/src"
logs=$work_dir/logs
snippets=$work_dir/snippets
src=$work_dir/src
HOME=$work_dir/home
prefix=$HOME/.local
export HOME

# The tools b2b was built with, under the names the README uses.
ln -s "$cmake" "$work_dir/bin/cmake"
ln -s "$(command -v "$pkg_config")" "$work_dir/bin/pkg-config"
ln -s "$cc" "$work_dir/bin/cc"
CC=$cc
export CC
if [ -n "$fc" ]; then
  ln -s "$fc" "$work_dir/bin/gfortran"
  FC=$fc
  export FC
fi
PATH=$work_dir/bin:$PATH
export PATH
# The host projects use the generator of the build under test (single-
# configuration generators; others keep CMake's default).
case $generator in
  *Multi-Config* | Visual* | Xcode) ;;
  *) CMAKE_GENERATOR=$generator && export CMAKE_GENERATOR ;;
esac
ln -s "$build_dir" "$src/build"

fail() {
  echo "FAILED: $*"
  echo "consumer_install: FAILED"
  exit 1
}

echo "== README blocks ($readme)"
sh "$extract" "$readme" "$snippets" || fail "the README's blocks could not be extracted"
# The host projects' files: from the README, and the programs from here.
mkdir -p "$src/my_host" "$src/my_fortran_host"
cp "$source_dir/c/consumer.c" "$src/my_host/my_host.c"
cp "$source_dir/fortran/consumer.f90" "$src/my_fortran_host/my_fortran_host.f90"
while read -r line lang role arg; do
  if [ "$role" = file ]; then
    mkdir -p "$(dirname "$src/$arg")"
    cp "$snippets/$line".* "$src/$arg"
    echo "  README.md:$line: $arg"
  fi
done <"$snippets/manifest"

# The README writes the library directory as lib and says that it stands for
# CMAKE_INSTALL_LIBDIR; a build with another one (lib/x86_64-linux-gnu when
# configured for the prefix /usr) reads the README's $HOME/.local/lib so.
if [ "$libdir" != lib ]; then
  echo "== CMAKE_INSTALL_LIBDIR is $libdir: the README's \$HOME/.local/lib is read as \$HOME/.local/$libdir"
  for f in "$snippets"/*.sh; do
    sed "s|\.local/lib\([/\"]\)|.local/$libdir\1|g" "$f" >"$f.libdir" && mv "$f.libdir" "$f"
  done
fi

# run_block LINE PART: the README's block at LINE, with its output in a log.
blocks=0
run_block() {
  blocks=$((blocks + 1))
  echo "== README.md:$1 (consumer $2)"
  sed 's/^/  $ /' "$snippets/$1.sh"
  if (cd "$src" && sh -eu "$snippets/$1.sh") >"$logs/block_$1.log" 2>&1; then
    sed 's/^/  | /' "$logs/block_$1.log" | tail -n 20
  else
    rc=$?
    sed 's/^/  | /' "$logs/block_$1.log"
    fail "README.md:$1 exited with $rc"
  fi
}

for part in install c fortran; do
  if [ "$part" = fortran ] && [ -z "$fc" ]; then
    echo "== consumer fortran: skipped, b2b is built without Fortran"
    continue
  fi
  while read -r line lang role arg; do
    [ "$role" = consumer ] && [ "$arg" = "$part" ] && run_block "$line" "$part"
  done <"$snippets/manifest"
  if [ "$part" = install ]; then
    # What the install must hold for this build.
    pc_dir=$prefix/$libdir/pkgconfig
    package_dir=$prefix/$libdir/cmake/b2b
    for f in "$package_dir/b2bConfig.cmake" "$package_dir/b2bConfigVersion.cmake" \
      "$pc_dir/b2b.pc" "$prefix/include/b2b/b2b.h"; do
      [ -f "$f" ] || fail "the install tree lacks $f"
    done
    if [ "$shared" = ON ]; then
      ls "$prefix/$libdir"/libb2b.so.* >/dev/null 2>&1 || fail "no libb2b.so.* in $prefix/$libdir"
    else
      [ -f "$prefix/$libdir/libb2b.a" ] || fail "no libb2b.a in $prefix/$libdir"
    fi
    if [ -n "$fc" ]; then
      [ -f "$pc_dir/b2b-fortran.pc" ] || fail "the install tree lacks $pc_dir/b2b-fortran.pc"
      [ -f "$package_dir/b2bTargets-Fortran.cmake" ] || fail "the install tree lacks the Fortran targets"
    else
      for f in "$pc_dir/b2b-fortran.pc" "$package_dir/b2bTargets-Fortran.cmake"; do
        [ ! -e "$f" ] || fail "b2b is built without Fortran, but $f is installed"
      done
    fi
  fi
done
[ "$blocks" -gt 0 ] || fail "the README has no consumer blocks"

echo "== find_package found the install tree"
for cache in "$src"/*/build/CMakeCache.txt; do
  [ -f "$cache" ] || continue
  found=$(sed -n 's/^b2b_DIR:[A-Z]*=//p' "$cache")
  echo "  $(dirname "$(dirname "$cache")" | sed "s|^$src/||"): b2b_DIR = $found"
  [ "$found" = "$package_dir" ] || fail "find_package(b2b) found '$found', not $package_dir"
done

echo "== the programs load libb2b from the prefix"
prefix_real=$(cd "$prefix" && pwd -P)
find "$src" -path "$src/build" -prune -o -name CMakeFiles -prune -o -type f -perm -u+x -print \
  >"$work_dir/programs"
[ -s "$work_dir/programs" ] || fail "the README's commands built no program"
if command -v ldd >/dev/null 2>&1; then
  while read -r exe; do
    ldd "$exe" | grep 'libb2b' >"$logs/ldd.out" || true
    echo "  ${exe#"$src"/}:"
    sed 's/^[[:space:]]*/    /' "$logs/ldd.out"
    if grep -v -e "=> $prefix/" -e "=> $prefix_real/" "$logs/ldd.out" >/dev/null; then
      fail "$exe loads a libb2b from outside the install prefix $prefix"
    fi
    if [ "$shared" = ON ] && [ ! -s "$logs/ldd.out" ]; then
      fail "$exe does not load libb2b from the install prefix $prefix"
    fi
  done <"$work_dir/programs"
fi

echo "consumer_install: OK"
