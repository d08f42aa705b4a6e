#!/usr/bin/env bash
# Sets everything up, builds every target (benchmarks included) and runs the test suite.
#   scripts/test.sh              Release build in build/ with SBPACK_WITH_MPI=ON, so that the
#                                MPI tests (mpirun -np 2 and 3) run too (what .ci/run runs)
#   scripts/test.sh --sanitize   AddressSanitizer + UndefinedBehaviorSanitizer build of the whole
#                                suite in build-sanitize/ (CMakePresets.json "sanitize"), then its
#                                tests; docs/reliability.md
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --mpi
if [[ "${1:-}" == "--sanitize" ]]; then
    cmake --preset sanitize >/dev/null
    cmake --build --preset sanitize -j"$(nproc)"
    # The suite without the static checks (clang-tidy reads the release compile commands), the
    # downstream package test (a project built without the sanitizer cannot link it) and the
    # Python module (an instrumented extension cannot load into the uninstrumented python3), and
    # libhdf5's own bad memcpy on a corrupt heap (ASan's interceptor reports it inside libhdf5
    # before it faults, so the read guard's message never comes: the release test shows it).
    ctest --preset sanitize -j"$(nproc)" \
        -E "clang_tidy|clang_format|install_package|downstream_find_package|corrupt_heap_does_not_crash"
    exit
fi
scripts/build.sh -DSBPACK_WITH_MPI=ON
ctest --test-dir build --output-on-failure -j"$(nproc)"
