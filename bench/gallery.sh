#!/usr/bin/env bash
# The README's gallery: the glossy teapot, Veach's MIS scene, a glass sphere,
# DamagedHelmet and ToyCar (real assets, lit by a uniform sky; ToyCar has a
# clear coat, sheen and thin-walled glass), each rendered with
# the command printed above its report. Writes bench/results/gallery/*.png and
# their closing reports (*.txt), whose "render" line is the time the README
# quotes. Usage: bench/gallery.sh [extra render flags]
set -euo pipefail
cd "$(dirname "$0")/.."
out=bench/results/gallery
mkdir -p "$out"
render() {
    local name=$1
    shift
    echo "build/wavefront render $* -o $out/$name.png" | tee "$out/$name.txt"
    build/wavefront render "$@" -o "$out/$name.png" | tee -a "$out/$name.txt"
}
render teapot scenes/cornell-teapot.gltf --width 320 --spp 128 "$@"
render veach-mis scenes/veach-mis.gltf --width 384 --spp 128 "$@"
render glass scenes/cornell-glass.gltf --width 320 --spp 128 "$@"
render damaged-helmet ../shared/scenes-real/DamagedHelmet/DamagedHelmet.glb --width 320 --spp 64 --env-uniform 1 "$@"
render toy-car ../shared/scenes-real/ToyCar/ToyCar.gltf --width 320 --spp 128 --env-uniform 1 "$@"
