#!/usr/bin/env bash
# completion_test.bash — the ctest Cli.CompletionOffersCommandsFlagsAndChoices:
# scripts/wavefront-completion.bash asked as bash asks it (COMP_WORDS and
# COMP_CWORD set, _wavefront called), for the commands, a subcommand's own
# flags, a flag's choices and --device's indices.
# Usage: completion_test.bash SOURCE_DIR WAVEFRONT_BINARY
set -uo pipefail
source "$1/scripts/wavefront-completion.bash"
binary=$2 failed=0

# Completes the words (the last one is being typed) and checks that the
# offers include every word of `expected` and none of `absent`.
expect() {
  local expected=$1 absent=$2; shift 2
  COMP_WORDS=("$binary" "$@") COMP_CWORD=$#
  COMPREPLY=()
  _wavefront
  local offer=" ${COMPREPLY[*]} " word
  for word in $expected; do
    [[ $offer == *" $word "* ]] || { echo "FAIL: '$*' should offer $word; offered:$offer"; failed=1; }
  done
  for word in $absent; do
    [[ $offer != *" $word "* ]] || { echo "FAIL: '$*' should not offer $word; offered:$offer"; failed=1; }
  done
}

expect "render devices cache" "" ""
expect "warm clear" "render" cache ""
expect "--device --cache-dir" "--spp" cache warm --
expect "refill passes fullest group auto" "--spp" render scene.gltf --schedule ""
expect "megakernel" "wavefront" render scene.gltf --integrator m
expect "0 1 8 16" "" render scene.gltf --lane-width ""
expect "0 1 2" "" render scene.gltf --trace-width ""
expect "albedo,depth albedo,normal" "depth" render scene.gltf --aov albedo,
expect "0 cpu gpu all" "" render scene.gltf --device ""
expect "--schedule --spp --max-depth" "--frobnicate" render scene.gltf --
((failed == 0)) && echo "completion: all checks passed"
exit $failed
