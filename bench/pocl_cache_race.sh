#!/usr/bin/env bash
# bench/pocl_cache_race.sh — many cold processes building the same programs
# into one PoCL cache folder at once, to see PoCL 3.1's rare failure under
# that load ("Device ... failed to build the program", no error named; issue
# 31) and the retry that answers it (host/device/kernel_program.h).
#
#   bench/pocl_cache_race.sh [ROUNDS] [PROCESSES]    (default 8 rounds of 16)
#
# Each round starts PROCESSES renders of the Cornell box (8 pixels wide, 1 spp)
# against a new, empty POCL_CACHE_DIR and program cache, and counts those that
# failed and those that warned of a retried build. On 2 cores, about a minute
# a round. Before the retry: 5 of 352 processes failed (22 rounds of 16);
# with it, none of 160, and 3 retried a build and went on.
set -uo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-8} processes=${2:-16}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0 warned=0
for round in $(seq 1 "$rounds"); do
  cache="$work/cache-$round"
  mkdir -p "$cache"
  for p in $(seq 1 "$processes"); do
    POCL_CACHE_DIR="$cache" build/wavefront render scenes/cornell-box.gltf --spp 1 --width 8 \
      -o "$work/out-$p.exr" --cache-dir "$cache/programs" > "$work/log-$round-$p" 2>&1 &
  done
  for job in $(jobs -p); do
    wait "$job" || failed=$((failed + 1))
  done
  warned=$((warned + $(grep -l "first build failed" "$work"/log-"$round"-* 2>/dev/null | wc -l)))
  grep -h "^error:" "$work"/log-"$round"-* 2>/dev/null | sort | uniq -c
  rm -rf "$cache"
done
echo "$((rounds * processes)) processes: $failed failed, $warned retried a build and went on"
