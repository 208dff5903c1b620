#!/usr/bin/env bash
# scripts/fuzz.sh [SECONDS] — fuzzes the scene loader (tests/fuzz) for SECONDS
# (default 120): builds build-fuzz/ with clang-14 and libFuzzer, seeds it with
# scenes/*.gltf and every .gltf/.glb in ../shared/scenes-real/ (the corpus,
# build-fuzz/corpus/, keeps what the fuzzer adds), and
# exits non-zero when it finds a crash, leak, hang or sanitizer report (the
# input is left as build-fuzz/crash-*). Prints libFuzzer's closing counts and
# a summary, `fuzz: N inputs, M crashes, ...`, also appended to
# build-fuzz/runs.log. Mutations are structure-aware where the input is a glTF
# (tests/fuzz/gltf_mutator.cpp); WF_FUZZ_MUTATOR=bytes leaves them all to
# libFuzzer's byte mutator, for comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-120}"

scripts/install_packages.sh clang-14 libclang-rt-14-dev
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 -DWF_FUZZ=ON >/dev/null
cmake --build build-fuzz --target fuzz_gltf_loader -j"$(nproc)"

# libFuzzer reads whole folders, and the real assets' folders also hold their
# .bin and image files, so the seeds are gathered into build-fuzz/seeds (a
# build output, never in the repository), named by their path.
rm -rf build-fuzz/seeds && mkdir -p build-fuzz/seeds build-fuzz/corpus
seed_roots=(scenes)
[ -d ../shared/scenes-real ] && seed_roots+=(../shared/scenes-real)
while IFS= read -r file; do
  cp "$file" "build-fuzz/seeds/$(echo "${file#../}" | tr / _)"
done < <(find "${seed_roots[@]}" -type f \( -name '*.gltf' -o -name '*.glb' \))
echo "fuzz: $(ls build-fuzz/seeds | wc -l) seeds from ${seed_roots[*]}, ${seconds} s"

# -max_len: every seed but DamagedHelmet.glb (3.8 MB, cut to it: its JSON
# chunk comes first) fits whole. The corpus folder comes first: new inputs are
# written there.
# -seed: the same inputs in the same order on every run, so CI reproduces what
# was run here (FUZZ_SEED=0 picks a random seed, for longer runs by hand).
# -rss_limit_mb also caps a single allocation: a small file that asks for
# gigabytes is reported (oom-*), not absorbed by the loader's bad_alloc catch.
status=0
build-fuzz/fuzz_gltf_loader build-fuzz/corpus build-fuzz/seeds \
  -max_total_time="$seconds" -max_len=2000000 -timeout=10 -rss_limit_mb=4096 \
  -seed="${FUZZ_SEED:-1}" -artifact_prefix=build-fuzz/ -print_final_stats=1 \
  >build-fuzz/fuzz.log 2>&1 || status=$?
grep -E '^(Done [0-9]+ runs|stat::number_of_executed_units|stat::new_units_added|stat::peak_rss_mb|mutator:)|ERROR|SUMMARY|Test unit written' \
  build-fuzz/fuzz.log || true
# libFuzzer stops at the first crash, leak, hang or out-of-memory, so this is
# 0 or 1; its input is the artifact the line names.
inputs=$(grep -oP '^stat::number_of_executed_units: \K[0-9]+' build-fuzz/fuzz.log ||
  grep -oP '^#\K[0-9]+' build-fuzz/fuzz.log | tail -1)
crashes=$(grep -c 'Test unit written to' build-fuzz/fuzz.log || true)
coverage=$(grep -oP '^#[0-9]+\s+(DONE|pulse|NEW|REDUCE|INITED)\s+cov: \K[0-9]+ ft: [0-9]+' build-fuzz/fuzz.log | tail -1 || true)
mutator=$(grep -oP '^mutator: \K.*' build-fuzz/fuzz.log || echo "${WF_FUZZ_MUTATOR:-structure-aware} (no count: the run stopped early)")
summary="fuzz: ${inputs} inputs, ${crashes} crashes, cov ${coverage:-?}, mutator: ${mutator}"
echo "$summary"
echo "$(date -u +%FT%TZ) ${seconds}s seed=${FUZZ_SEED:-1} ${summary#fuzz: }" >>build-fuzz/runs.log
if ((status)); then
  echo "fuzz: FAILED (exit $status); the log is build-fuzz/fuzz.log" >&2
  exit "$status"
fi
echo "fuzz: no crash"
