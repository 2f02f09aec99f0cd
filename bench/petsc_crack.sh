#!/usr/bin/env bash
# The pressurised crack (scenes/crack.yaml) at COUNT^2 particles and delta/h = RATIO, solved
# by the serial `auto` path and by the PETSc backend (GAMG by default) on 1..MAX_RANKS
# processes, one after the other: wall time, CPU time (user + system, summed over the
# ranks, and the busiest rank's), peak RSS per process (GNU time, the largest rank's),
# Krylov iterations and the field error, for docs/performance.md and docs/scaling.md. On a
# shared machine compare CPU times: wall time measures the other users' load.
# Usage: bench/petsc_crack.sh [COUNT=200] [RATIO=3.5] [MAX_RANKS=2] [PETSC_OPTIONS...]
# Environment: SERIAL=0 skips the serial run, MIN_RANKS=n starts at n processes (the
# 1000^2 crack: the serial run needs 13.1 GB, more than a shared machine may spare).
set -euo pipefail
count=${1:-200}; ratio=${2:-3.5}; max_ranks=${3:-2}; shift $(( $# < 3 ? $# : 3 )) || true
petsc_options="$*"
here=$(cd "$(dirname "$0")/.." && pwd)
pd=${PD:-$here/build/bin/pd}
work=$(mktemp -d /tmp/petsc_crack.XXXX)
. "$here/bench/petsc_ranks.sh"
sed -e "s|count: 80 .*|count: $count|" -e "s|horizon: {ratio: 3.0}|horizon: {ratio: $ratio}|" \
    -e "s|output: {directory: out/crack}|output: {directory: $work/serial}|" "$here/scenes/crack.yaml" > "$work/serial.yaml"
sed -e "s|$work/serial|$work/petsc|" -e "s|^law: silling_plane_strain|law: silling_plane_strain\nsolver: {backend: petsc}|" \
    "$work/serial.yaml" > "$work/petsc.yaml"
echo "crack ${count}^2, delta/h = $ratio, $(date -u +%FT%TZ)"
if [ "${SERIAL:-1}" != 0 ]; then
  /usr/bin/time -v -o "$work/t_serial" "$pd" run "$work/serial.yaml" > "$work/serial.log" 2>&1
  report "serial auto" "$work/serial.log" "$work/t_serial" "$(cpu_of "$work/t_serial")"
fi
for n in $(seq "${MIN_RANKS:-1}" "$max_ranks"); do
  run_ranks petsc "$n" "$work/petsc.yaml" "$work" "$petsc_options"
done
echo "logs: $work"
