#!/usr/bin/env bash
# scripts/sanitize.sh [CTEST ARGS...] — the test suite under AddressSanitizer
# and UndefinedBehaviorSanitizer: builds build-asan/ with -DWF_SANITIZE=ON
# (g++), then runs ctest there. The kernels run on PoCL's CPU device as in the
# normal suite; PoCL and its LLVM are not instrumented, only our host code.
# Extra arguments go to ctest (e.g. -R GltfLoader).
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install_packages.sh
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWF_SANITIZE=ON >/dev/null
cmake --build build-asan -j"$(nproc)"

# detect_leaks=0: PoCL and the LLVM inside it allocate at start and keep it
# until exit, which LeakSanitizer would report as leaks of ours.
# halt_on_error: the first UB report fails its test.
export ASAN_OPTIONS=detect_leaks=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan --output-on-failure -j2 "$@"
