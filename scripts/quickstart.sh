#!/usr/bin/env bash
# Builds b2b and runs one of:
#   study      the curve study (the main program for now): accuracy and cost
#              of every curve kind
#   test       the whole test suite through ctest (Release build in build/)
#   sanitize   the whole test suite built with AddressSanitizer and
#              UndefinedBehaviorSanitizer (Debug build in build-sanitize/)
# It first installs the Debian packages it needs if any is missing (with sudo
# when not run as root), so it works as is on a fresh Debian 12 machine.
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-}
case "$mode" in
  study | test | sanitize) ;;
  *)
    echo "usage: $0 study|test|sanitize" >&2
    exit 2
    ;;
esac

packages=(cmake make g++ gfortran pkg-config check liblapack-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "quickstart: installing missing Debian packages: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc)
case "$mode" in
  study)
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
    cmake --build build -j "$jobs" --target curve_study
    ./build/examples/curve_study
    ;;
  test)
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
    cmake --build build -j "$jobs"
    ctest --test-dir build --output-on-failure -j "$jobs"
    ;;
  sanitize)
    cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug -DB2B_SANITIZE=ON
    cmake --build build-sanitize -j "$jobs"
    # Any finding aborts the test that made it (-fno-sanitize-recover), so a
    # green run means zero findings.
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
      UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      ctest --test-dir build-sanitize --output-on-failure -j "$jobs"
    ;;
esac
