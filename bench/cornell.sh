#!/usr/bin/env bash
# The reference measurement of issue 2: the Cornell box at 512x512, 256 spp,
# unlimited depth, on the default device. Writes the image and the closing
# report under bench/results/. Usage: bench/cornell.sh [extra render flags]
set -euo pipefail
cd "$(dirname "$0")/.."
out=bench/results
mkdir -p "$out"
build/wavefront render scenes/cornell-box.gltf --width 512 --height 512 --spp 256 --max-depth unlimited \
    -o "$out/cornell-512-256spp.png" "$@" | tee "$out/cornell-512-256spp.txt"
