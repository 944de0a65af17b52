#!/usr/bin/env bash
# The MPI/PETSc example host (examples/mpi): installs the Debian packages it
# needs if any is missing (with sudo when not run as root), configures a
# build directory with -DB2B_ENABLE_MPI_EXAMPLE=ON, builds the host and its
# programs with libb2b, and runs ctest -L mpi (the element's FD test, the
# slide and network scenes on 1 and 2 ranks and their comparisons; the
# network at 4800 and at 10^5 segments).
#   scripts/mpi_example.sh          the mpi label (minutes: the 10^5-segment
#                                   network runs on 1 and on 2 ranks)
#   scripts/mpi_example.sh quick    without the 10^5-segment network (label
#                                   large; under a minute)
# The build directory is build-mpi/ (Release, no Fortran); MPI_BUILD_DIR=dir
# uses another one, configured as it is plus the example: the CI step passes
# the test step's build/, whose libb2b is then not compiled a second time.
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

packages=(cmake ninja-build make g++ pkg-config liblapack-dev petsc-dev openmpi-bin libopenmpi-dev)
scripts/install_packages.sh mpi_example "${packages[@]}"

dir=${MPI_BUILD_DIR:-build-mpi}
if [ -f "$dir/CMakeCache.txt" ] && [ "$dir" != build-mpi ]; then
  # An existing build: its own options, the example switched on.
  scripts/configure_build.sh "$dir" -DB2B_ENABLE_MPI_EXAMPLE=ON
else
  # The example needs neither Fortran nor the library's own test suites.
  scripts/configure_build.sh "$dir" -DCMAKE_BUILD_TYPE=Release -DB2B_ENABLE_MPI_EXAMPLE=ON \
    -DB2B_ENABLE_FORTRAN=OFF
fi
cmake --build "$dir" -j "${B2B_JOBS:-$(nproc)}" --target mpi_host mpi_beam_element_fd mpi_compare_results
# --no-tests=error: a build that did not register the example fails here.
ctest --test-dir "$dir" -L mpi "${exclude[@]}" --output-on-failure --no-tests=error
