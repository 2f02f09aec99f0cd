#!/usr/bin/env bash
# Profiles the two hottest paths and rewrites bench/profile.md (embedded in docs/performance.md):
#   1. the stiffness assembly, FamilyAssembler::assemble with K: Silling plane strain, 200^2 grid,
#      delta/h = 3.5, 1 thread (perf), and 100^2 at delta/h = 3.5 (cachegrind: it runs ~50x slower);
#   2. the generated dense tangent at 28 bonds (tangent kernel + form_local_matrix), Silling and
#      correspondence, and the Silling tangent kernel alone (instruction-level, for divisions).
# perf samples cpu-clock (this VM exposes no hardware counters, so no cycles or cache-miss events);
# cachegrind counts instructions, loads, stores and simulated misses (D1 = 48 KiB, LL = the 1 MiB L2).
# Installs linux-perf and valgrind if missing (scripts/install_deps.sh --profile). Builds build-prof/: the release flags plus -g -fno-omit-frame-pointer.
# Usage: bench/profile.sh   (about 2 minutes after the build)
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh --profile
prof=build-prof
if [ ! -f "$prof/CMakeCache.txt" ]; then
  cmake -S . -B "$prof" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS="-g -fno-omit-frame-pointer" \
    -DPD_BUILD_TESTS=OFF >/dev/null
fi
cmake --build "$prof" -j2 --target assembly_bench kernel_bench
out=build/bench/profile
rm -rf "$out"
mkdir -p "$out"
report() {  # perf data -> "overhead@symbol@srcline" lines
  perf report -i "$1" --stdio --no-children --sort sym,srcline -t '@' --percent-limit 0 2>/dev/null | grep -v '^#' > "$2"
}

echo "stiffness assembly 200^2, delta/h = 3.5, 1 thread: timing, then perf ..."
"$prof/bin/assembly_bench" --grids=200 --benchmark_filter='^stiffness/200/35/1/' --benchmark_min_time=2 \
  --benchmark_out="$out/stiffness_clean.json" --benchmark_out_format=json >/dev/null 2>&1
perf record -q -e cpu-clock -F 999 -o "$out/stiffness.perf" -- \
  "$prof/bin/assembly_bench" --grids=200 --benchmark_filter='^stiffness/200/35/1/' --benchmark_min_time=6 \
  --benchmark_out="$out/stiffness.json" --benchmark_out_format=json >/dev/null 2>&1
report "$out/stiffness.perf" "$out/stiffness.lines"

for law in silling_plane_strain correspondence_plane_strain; do
  echo "perf: dense tangent, $law, 28 bonds ..."
  perf record -q -e cpu-clock -F 2999 -o "$out/dense_$law.perf" -- \
    "$prof/bin/kernel_bench" --benchmark_filter="^generated_tangent_dense/$law/3\$" --benchmark_min_time=3 \
    --benchmark_out="$out/dense_$law.json" --benchmark_out_format=json >/dev/null 2>&1
  report "$out/dense_$law.perf" "$out/dense_$law.lines"
done

echo "perf: Silling tangent kernel, 28 bonds, by instruction ..."
perf record -q -e cpu-clock -F 4999 -o "$out/factors.perf" -- \
  "$prof/bin/kernel_bench" --benchmark_filter='^generated_tangent_factors/silling_plane_strain/3$' --benchmark_min_time=3 \
  >/dev/null 2>&1
perf annotate -i "$out/factors.perf" --stdio -s pd::generated::silling_plane_strain_intact_tangent 2>/dev/null \
  | grep -E '^\s+[0-9]+\.[0-9]+ :' > "$out/factors.annotate"

echo "cachegrind: stiffness assembly 100^2, delta/h = 3.5, 1 thread ..."
valgrind --tool=cachegrind --cache-sim=yes --D1=49152,12,64 --LL=1048576,8,64 \
  --cachegrind-out-file="$out/stiffness.cg" -- \
  "$prof/bin/assembly_bench" --grids=100 --benchmark_filter='^stiffness/100/35/1/' --benchmark_min_time=0.001 \
  --benchmark_out="$out/stiffness_cg.json" --benchmark_out_format=json >/dev/null 2>"$out/cachegrind.log"

python3 bench/profile_report.py "$out" > bench/profile.md.tmp
mv bench/profile.md.tmp bench/profile.md
echo "wrote bench/profile.md"
