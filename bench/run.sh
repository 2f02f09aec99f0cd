#!/usr/bin/env bash
# Runs the benchmark suite in one go and writes docs/performance.md from the medians.
# Usage: bench/run.sh [--quick]   (--quick: 1 repetition, short minimum time)
set -euo pipefail
cd "$(dirname "$0")/.."
reps=7 min_time=0.2
if [ "${1:-}" = "--quick" ]; then reps=1 min_time=0.02; fi
./scripts/build.sh --target kernel_bench --target assembly_bench
mkdir -p build/bench
build/bin/kernel_bench --benchmark_repetitions="$reps" --benchmark_min_time="$min_time" \
  --benchmark_out=build/bench/kernels.json --benchmark_out_format=json >/dev/null
build/bin/assembly_bench --benchmark_repetitions="$reps" --benchmark_min_time="$min_time" \
  --benchmark_out=build/bench/assembly.json --benchmark_out_format=json >/dev/null
python3 bench/report.py build/bench/kernels.json build/bench/assembly.json "bench/run.sh $*" > docs/performance.md
echo "wrote docs/performance.md"
