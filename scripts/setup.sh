#!/usr/bin/env bash
# scripts/setup.sh [--tests] — installs the Debian packages the project needs
# (when missing) and builds the renderer, build/wavefront, first of all, so
# that a first picture needs no more. --tests then builds the test suite too
# (build/wavefront_tests and the tools its tests run). Safe to run again: it
# only installs and rebuilds what changed.
set -euo pipefail
cd "$(dirname "$0")/.."

case "${1:-}" in
  "") tests=0 ;;
  --tests) tests=1 ;;
  *) echo "scripts/setup.sh: unknown argument '$1' (expected nothing or --tests)" >&2; exit 2 ;;
esac

scripts/install_packages.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --target wavefront -j"$(nproc)"
if ((tests)); then cmake --build build -j"$(nproc)"; fi
