#!/usr/bin/env bash
# scripts/sanitize.sh [CTEST ARGS...] — the test suite under AddressSanitizer
# and UndefinedBehaviorSanitizer: builds build-asan/ with -DWF_SANITIZE=ON
# (g++), then runs ctest there. The kernels run on PoCL's CPU device as in the
# normal suite; PoCL and its LLVM are not instrumented, only our host code.
# By default it runs the tests of what reads untrusted input or state: the
# loader, the CLI, the BVH, textures and the program cache, less
# Bvh.RandomSoupAgreesWithBruteForce (10^9 ray-triangle tests of random
# geometry, 6 min under ASan). The whole suite takes far longer than CI's
# share of 2 cores allows; figures in docs/testing.md.
# Arguments replace that filter and go to ctest: `scripts/sanitize.sh -R .`
# runs everything.
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
(($#)) || set -- -R '^(Gltf|Cli\.|Bvh\.|Texture|ProgramCacheTest\.)' -E '^Bvh\.RandomSoup'
ctest --test-dir build-asan --output-on-failure -j2 "$@"
