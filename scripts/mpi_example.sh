#!/usr/bin/env bash
# The MPI/PETSc example host (examples/mpi): installs the Debian packages it
# needs if any is missing (with sudo when not run as root), configures
# build-mpi/ with -DB2B_ENABLE_MPI_EXAMPLE=ON, builds the host and its
# programs with libb2b, and runs ctest -L mpi (the element's FD test, the
# slide and network scenes on 1 and 2 ranks and their comparisons; the
# network at 4800 and at 10^5 segments).
#   scripts/mpi_example.sh          the mpi label (minutes: the 10^5-segment
#                                   network runs on 1 and on 2 ranks)
#   scripts/mpi_example.sh quick    without the 10^5-segment network (label
#                                   large; seconds)
set -euo pipefail
cd "$(dirname "$0")/.."

exclude=()
case "${1:-}" in
  "") ;;
  quick) exclude=(-LE large) ;;
  *)
    echo "usage: $0 [quick]" >&2
    exit 2
    ;;
esac

packages=(cmake make g++ pkg-config liblapack-dev petsc-dev openmpi-bin libopenmpi-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "mpi_example: installing missing Debian packages: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# The example needs neither Fortran nor the library's own test suites.
cmake -S . -B build-mpi -DCMAKE_BUILD_TYPE=Release -DB2B_ENABLE_MPI_EXAMPLE=ON \
  -DB2B_ENABLE_FORTRAN=OFF
nice -n 5 cmake --build build-mpi -j 2 --target mpi_host mpi_beam_element_fd mpi_compare_results
ctest --test-dir build-mpi -L mpi "${exclude[@]}" --output-on-failure
