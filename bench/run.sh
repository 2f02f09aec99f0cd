#!/usr/bin/env bash
# Runs the benchmark suite in one go and writes docs/performance.md from the medians.
# Usage: bench/run.sh [--quick] [--profile] [--only STAGES]
#   (default)  kernels: 7 randomly interleaved repetitions of >= 0.1 s each; assembly:
#              100^2, 200^2, 400^2, 1000^2 grids, 5 repetitions of >= 0.2 s (about 7 min here);
#              crack solves (bench/solve_bench.py) with every linear-solver path at delta/h 3.5
#              on 100^2-1000^2 and 1.5 on 100^2-1000^2, points projected past 15 min skipped
#              (about an hour here)
#   --quick    1 repetition of >= 0.02 s, grids 100^2 and 200^2 only, solves on 100^2 (a few minutes)
#   --profile  first re-run bench/profile.sh (perf + cachegrind; rewrites bench/profile.md)
#   --only     comma-separated subset of kernels,assembly,solves to re-run; the report is
#              written from every result in build/bench/, so stages may run at different times
# Results (JSON) go to build/bench/; docs/performance.md embeds bench/profile.md (measured) and
# bench/profile_notes.md (conclusions, by hand).
set -euo pipefail
cd "$(dirname "$0")/.."
command="bench/run.sh${*:+ $*}"
quick=0 profile=0 only="kernels,assembly,solves"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --profile) profile=1 ;;
    --only) only="$2"; shift ;;
    *) echo "usage: bench/run.sh [--quick] [--profile] [--only kernels,assembly,solves]" >&2; exit 2 ;;
  esac
  shift
done
stage() { [[ ",$only," == *",$1,"* ]]; }
if [ "$quick" = 1 ]; then
  kreps=1 kmin=0.02 areps=1 amin=0.02 grids="100 200" solve_grids="100"
else
  kreps=7 kmin=0.1 areps=5 amin=0.2 grids="100 200 400 1000" solve_grids="100 200 400 1000"
fi
start=$(date +%s)
./scripts/build.sh --target kernel_bench --target kernel_bench_native --target assembly_bench --target pd
if [ "$profile" = 1 ]; then bench/profile.sh; fi
out=build/bench
mkdir -p "$out"
if stage kernels; then
  echo "kernel_bench ..."
  build/bin/kernel_bench --benchmark_repetitions="$kreps" --benchmark_min_time="$kmin" \
    --benchmark_enable_random_interleaving=true \
    --benchmark_out="$out/kernels.json" --benchmark_out_format=json >/dev/null
  if [ -x build/bin/kernel_bench_native ]; then  # the same, built with -march=native (PD_BENCH_NATIVE)
    echo "kernel_bench_native ..."
    build/bin/kernel_bench_native --benchmark_repetitions="$kreps" --benchmark_min_time="$kmin" \
      --benchmark_enable_random_interleaving=true \
      --benchmark_out="$out/kernels_native.json" --benchmark_out_format=json >/dev/null
  fi
fi
if stage assembly; then
  rm -f "$out"/assembly_*.json
  # One grid per process, so each peak-memory reading belongs to one grid alone.
  for n in $grids; do
    for r in 15 35; do
      echo "assembly_bench ${n}^2, delta/h = ${r:0:1}.${r:1} ..."
      build/bin/assembly_bench --grids="$n" --benchmark_filter="/$n/$r/" \
        --benchmark_repetitions="$areps" --benchmark_min_time="$amin" \
        --benchmark_out="$out/assembly_${n}_${r}.json" --benchmark_out_format=json >/dev/null
    done
  done
fi
if stage solves; then
  for r in 3.5 1.5; do
    echo "crack solves, delta/h = $r ..."
    python3 bench/solve_bench.py --pd build/bin/pd --scene scenes/crack.yaml --grids $solve_grids --ratio "$r" \
      --solvers "matrix-free + short horizon" "auto" "matrix-free + jacobi" "cg+ic (assembled)" "cholmod" \
      --max-seconds 900 --out "$out/solves_${r/./}.jsonl"
  done
fi
python3 bench/report.py --command "$command" --kernels "$out/kernels.json" --kernels-native "$out/kernels_native.json" --assembly "$out"/assembly_*.json \
  --solves "$out"/solves_*.jsonl --profile bench/profile.md bench/profile_notes.md --build build \
  --seconds "$(( $(date +%s) - start ))" > docs/performance.md.tmp
mv docs/performance.md.tmp docs/performance.md
echo "wrote docs/performance.md ($(( $(date +%s) - start )) s)"
