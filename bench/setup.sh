#!/usr/bin/env bash
# bench/setup.sh — what the benchmarks need beyond the renderer, then the
# build: Embree 3 (Debian's libembree-dev), so that build/bench/wavefront_ray_bench,
# which measures the traversal kernels against rtcIntersect1 on the same rays,
# is always there for bench/. The test suite never needs it.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_packages.sh libembree-dev
scripts/setup.sh --tests
if [ ! -x build/bench/wavefront_ray_bench ]; then
  echo "bench/setup.sh: Embree is installed but build/bench/wavefront_ray_bench was not built" >&2
  exit 1
fi
