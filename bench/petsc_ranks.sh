# Sourced by bench/petsc_*.sh: a scene on the PETSc backend over N processes, each rank under
# GNU time (time on mpirun would report mpirun's own RSS), reported as one line: wall time,
# CPU time (user + system, summed over the ranks, and the busiest rank's), the largest
# rank's peak RSS, Krylov iterations summed over the Newton steps, the field error when
# the scene has one, the load average. On a shared machine compare CPU times.
export OMP_WAIT_POLICY=PASSIVE OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
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
  echo "$1 | wall $wall | CPU $4 s | peak RSS $((rss / 1024)) MB | Krylov $its | field error ${err:--} | load $(cut -d' ' -f1 /proc/loadavg)"
}
# run_ranks LABEL N SCENE WORK [PETSC_OPTIONS]: runs, then reports (the logs stay in WORK).
run_ranks() {
  local label=$1 n=$2 scene=$3 work=$4 options=${5:-} extra="" worst cpus cpu
  if [ -n "$options" ]; then extra="--petsc-options='$options'"; fi
  mpirun -n "$n" --oversubscribe sh -c "/usr/bin/time -v -o $work/t_${label}_${n}_\$OMPI_COMM_WORLD_RANK \
    $pd run $scene --out $work/out_${label}_$n $extra" > "$work/${label}_$n.log" 2>&1 || true
  worst=$(for f in "$work"/t_${label}_${n}_*; do grep "Maximum resident" "$f" | awk '{print $NF}'; done | sort -n | tail -1)
  cp "$(ls "$work"/t_${label}_${n}_* | head -1)" "$work/t_${label}_$n"
  sed -i "s/Maximum resident set size (kbytes): .*/Maximum resident set size (kbytes): $worst/" "$work/t_${label}_$n"
  cpus=$(for f in "$work"/t_${label}_${n}_*; do cpu_of "$f"; echo; done)
  cpu="$(echo "$cpus" | awk '{s += $1; if ($1 > m) m = $1} END {printf "%.1f (busiest rank %.1f)", s, m}')"
  report "$label $n rank(s) $options" "$work/${label}_$n.log" "$work/t_${label}_$n" "$cpu"
}
