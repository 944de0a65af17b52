#!/usr/bin/env bash
# scripts/configure_build.sh DIR [CMAKE ARGUMENT ...]: configures the build
# directory DIR of the repository (cmake -S . -B DIR ARGUMENTS), as the
# other scripts do it: a new directory for Ninja (Debian: ninja-build; the
# scripts install it) unless CMAKE_GENERATOR names another generator or
# ninja is missing, an existing one with the generator it has (CMake does
# not change a build directory's generator). Why Ninja: the whole Release
# build took 142 s of CPU (72 s on 2 cores) with it against 177 s (91 s)
# with Make, most of the difference in the processes that CMake's Makefiles
# start for every target (doc/verification.md, CI).
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:?usage: scripts/configure_build.sh DIR [CMAKE ARGUMENT ...]}
shift
generator=()
if [ ! -f "$dir/CMakeCache.txt" ] && [ -z "${CMAKE_GENERATOR:-}" ] && command -v ninja >/dev/null; then
  generator=(-G Ninja)
fi
exec cmake -S . -B "$dir" "${generator[@]}" "$@"
