#!/usr/bin/env bash
# bench/gpu.sh — the prepared GPU run (issue 29): correctness, throughput and
# rays on the machine's OpenCL GPU in a few minutes; bench/gpu.py says what it
# measures and takes the options (--out, --bin, --real, --budget, ...).
exec python3 "$(dirname "$0")/gpu.py" "$@"
