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
export OMP_WAIT_POLICY=PASSIVE OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
sed -e "s|count: 80 .*|count: $count|" -e "s|horizon: {ratio: 3.0}|horizon: {ratio: $ratio}|" \
    -e "s|output: {directory: out/crack}|output: {directory: $work/serial}|" "$here/scenes/crack.yaml" > "$work/serial.yaml"
sed -e "s|$work/serial|$work/petsc|" -e "s|^law: silling_plane_strain|law: silling_plane_strain\nsolver: {backend: petsc}|" \
    "$work/serial.yaml" > "$work/petsc.yaml"
cpu_of() {  # GNU time file -> user + system seconds
  awk -F': ' '/User time|System time/ {s += $2} END {printf "%.1f", s}' "$1"
}
report() {  # label, log, time file, CPU text
  local wall rss its err
  wall=$(grep "Elapsed (wall" "$3" | awk '{print $NF}')
  rss=$(grep "Maximum resident" "$3" | awk '{print $NF}')
  # Krylov iterations summed over Newton steps: "N Krylov iterations" (PETSc), "N linear its" (serial).
  its=$( (grep -oE "[0-9]+ (Krylov iterations|linear its)" "$2" || true) | awk '{s += $1} END {print s + 0}')
  err=$( (grep -o "eq. 48): [0-9.e+-]*" "$2" || true) | awk '{print $NF}')
  echo "$1 | wall $wall | CPU $4 s | peak RSS $((rss / 1024)) MB | Krylov $its | field error $err | load $(cut -d' ' -f1 /proc/loadavg)"
}
echo "crack ${count}^2, delta/h = $ratio, $(date -u +%FT%TZ)"
if [ "${SERIAL:-1}" != 0 ]; then
  /usr/bin/time -v -o "$work/t_serial" "$pd" run "$work/serial.yaml" > "$work/serial.log" 2>&1
  report "serial auto" "$work/serial.log" "$work/t_serial" "$(cpu_of "$work/t_serial")"
fi
for n in $(seq "${MIN_RANKS:-1}" "$max_ranks"); do
  # GNU time on mpirun reports mpirun's own RSS: time each rank instead.
  extra=""
  if [ -n "$petsc_options" ]; then extra="--petsc-options='$petsc_options'"; fi
  mpirun -n "$n" --oversubscribe sh -c "/usr/bin/time -v -o $work/t_petsc_${n}_\$OMPI_COMM_WORLD_RANK \
    $pd run $work/petsc.yaml --out $work/petsc_$n $extra" > "$work/petsc_$n.log" 2>&1 || true
  worst=$(for f in "$work"/t_petsc_${n}_*; do grep "Maximum resident" "$f" | awk '{print $NF}'; done | sort -n | tail -1)
  cp "$(ls "$work"/t_petsc_${n}_* | head -1)" "$work/t_petsc_$n"
  sed -i "s/Maximum resident set size (kbytes): .*/Maximum resident set size (kbytes): $worst/" "$work/t_petsc_$n"
  cpus=$(for f in "$work"/t_petsc_${n}_*; do cpu_of "$f"; echo; done)
  cpu="$(echo "$cpus" | awk '{s += $1; if ($1 > m) m = $1} END {printf "%.1f (busiest rank %.1f)", s, m}')"
  report "petsc $n rank(s) $petsc_options" "$work/petsc_$n.log" "$work/t_petsc_$n" "$cpu"
done
echo "logs: $work"
