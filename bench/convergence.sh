#!/usr/bin/env bash
# convergence.sh -- the equal-time study of the sampling techniques, on the
# Cornell box and on its variant with a small bright light
# (scenes/make_cornell_box.py --small-light). For each scene it
#   1. renders two references with the best technique (mis, cosine, sobol) from
#      different seeds, reusing any already in RESULTS/references/, and checks
#      that the pair agrees within its own noise (B is rendered against A);
#   2. renders each of the 12 combinations of --light-sampling {bsdf,nee,mis} x
#      --hemisphere {uniform,cosine} x --sampler {independent,sobol} for the
#      same time, measuring the error against reference A at each doubling of
#      spp: RESULTS/convergence/<scene>-<light>-<hemisphere>-<sampler>.csv,
#      with the image (.png) and the render's table and report (.txt);
#   3. plots all 12 relMSE curves against time (RESULTS/convergence-<scene>.png)
#      and writes RESULTS/convergence.md (bench/convergence_report.py).
# The command lines it ran are in RESULTS/convergence/commands.txt.
#
# Usage: [RENDER_SECONDS=10] [REF_SPP=4096] [SIZE=128] [RESULTS=bench/results] bench/convergence.sh
#   RENDER_SECONDS  time budget of each of the 24 study renders (default 10)
#   REF_SPP         samples per pixel of each of the 4 references (default 4096)
#   SIZE            width and height in pixels of every image (default 128)
#   RESULTS         output directory, relative to the repository root (default bench/results)
#   PYTHON          interpreter with matplotlib (default /usr/bin/python3, Debian's)
# Run it on an otherwise idle machine: equal time means nothing under load.
# Dry run: RENDER_SECONDS=1 REF_SPP=64 SIZE=32 RESULTS=/tmp/conv-dry bench/convergence.sh
set -euo pipefail

# Bash keeps its own clock in SECONDS, counting up from any value it is given,
# so the budget has another name; catch the natural slip.
if ((SECONDS > 0)); then
    echo "convergence.sh: set RENDER_SECONDS, not SECONDS (bash's own clock)" >&2
    exit 2
fi
load_at_start=$(cut -d' ' -f1-3 /proc/loadavg)
cd "$(dirname "$0")/.."

RENDER_SECONDS=${RENDER_SECONDS:-10}
REF_SPP=${REF_SPP:-4096}
SIZE=${SIZE:-128}
RESULTS=${RESULTS:-bench/results}
PYTHON=${PYTHON:-/usr/bin/python3}

scenes=(cornell-box cornell-box-small-light)
# The references' seeds differ from each other and from the study's: a render
# sharing its reference's seed and sampler would replay the reference's first
# samples and look better than it is.
ref_seeds=(1 2)
study_seed=0

refs=$RESULTS/references
out=$RESULTS/convergence
mkdir -p "$refs" "$out"
commands=$out/commands.txt
: > "$commands"

# Appends the command line to commands.txt; `run` also runs it, with its
# checkpoint table and closing report going to LOG.
log_command() {
    local line
    printf -v line '%q ' "$@"
    echo "${line% }" >> "$commands"
}
run() {  # LOG COMMAND [ARG ...]
    local log=$1
    shift
    log_command "$@"
    "$@" > "$log"
}

report_args=()
for scene in "${scenes[@]}"; do
    common=(scenes/"$scene".gltf --width "$SIZE" --height "$SIZE")

    ref=()
    for i in 0 1; do
        ref+=("$refs/$scene-${SIZE}px-${REF_SPP}spp-seed${ref_seeds[i]}")
        command=(build/wavefront render "${common[@]}" --spp "$REF_SPP" --seed "${ref_seeds[i]}"
                 --light-sampling mis --hemisphere cosine --sampler sobol
                 -o "${ref[i]}.exr" --report "${ref[i]}.csv")
        # B's report is its error against A, so a newer A makes it stale.
        ((i == 0)) || command+=(--reference "${ref[0]}.exr")
        if [[ -f ${ref[i]}.exr && -f ${ref[i]}.csv && ($i -eq 0 || ${ref[i]}.csv -nt ${ref[0]}.exr) ]]; then
            echo "# reused, already there:" >> "$commands"
            log_command "${command[@]}"
        else
            echo "$scene: reference ${ref_seeds[i]}, $REF_SPP spp" >&2
            run "${ref[i]}.txt" "${command[@]}"
        fi
    done

    # The reference's technique first, so the plot's slope -1 line starts on its
    # curve; the sampler innermost, so each technique's two samplers share a hue.
    csvs=()
    labels=()
    for light in mis nee bsdf; do
        for hemisphere in cosine uniform; do
            for sampler in sobol independent; do
                name=$scene-$light-$hemisphere-$sampler
                echo "$scene: $light $hemisphere $sampler, $RENDER_SECONDS s" >&2
                run "$out/$name.txt" build/wavefront render "${common[@]}" --time "$RENDER_SECONDS" \
                    --seed "$study_seed" --light-sampling "$light" --hemisphere "$hemisphere" --sampler "$sampler" \
                    --reference "${ref[0]}.exr" -o "$out/$name.png" --report "$out/$name.csv"
                csvs+=("$out/$name.csv")
                labels+=("$light $hemisphere $sampler")
            done
        done
    done

    plot=$RESULTS/convergence-$scene.png
    "$PYTHON" bench/plot_convergence.py "$plot" "${csvs[@]}" --labels "${labels[@]}" \
        --title "$scene, ${SIZE}x$SIZE: relMSE against reference A"
    report_args+=(--scene "$scene" "$plot" "${ref[0]}.csv" "${ref[1]}.csv" "${csvs[@]}")
done

"$PYTHON" bench/convergence_report.py "$RESULTS/convergence.md" --commands "$commands" \
    --render-seconds "$RENDER_SECONDS" --size "$SIZE" --ref-seeds "${ref_seeds[@]}" --seed "$study_seed" \
    --load-at-start "$load_at_start" "${report_args[@]}"
echo "wrote $RESULTS/convergence.md" >&2
