#!/usr/bin/env bash
# Runs every scene in scenes/ with two pd binaries and compares their summary.json files:
# every number to a relative tolerance (default 1e-12), every string (solver path, linear
# method, its choice sentence, effect list, ...) exactly. Wall-clock seconds, file names, the
# run id, the binary's version and commit (`pd`) and
# the scene path are skipped (they differ between any two runs).
#
#   scripts/compare_runs.sh BEFORE_PD AFTER_PD [SCENE.yaml ...]
#
# Scenes are run from a temporary copy in which `count:` is capped at PD_COMPARE_MAX_COUNT
# (default 40, rounded down to an even number so that crack scenes keep their crack between
# two rows), so that the whole comparison takes well under a minute; PD_COMPARE_MAX_STEPS, when
# set, caps `steps:` too (not by default: for relaxation scenes it is an iteration limit).
# PD_COMPARE_RTOL overrides the tolerance (0: bit for bit). result.csv and energies.csv are
# compared too, every number to the same tolerance.
#
# PD_COMPARE_RANKS=N runs every copy with `solver.backend: petsc` under
# `mpirun -n N --oversubscribe` (both binaries alike), so the distributed paths are compared.
# Exit status: 0 when every scene agrees, 1 otherwise.
set -euo pipefail

if [[ $# -lt 2 ]]; then
    echo "usage: $0 BEFORE_PD AFTER_PD [SCENE.yaml ...]" >&2
    exit 2
fi
before=$(realpath "$1")
after=$(realpath "$2")
shift 2
repo=$(cd "$(dirname "$0")/.." && pwd)
if [[ $# -gt 0 ]]; then scenes=("$@"); else scenes=("$repo"/scenes/*.yaml); fi
max_count=${PD_COMPARE_MAX_COUNT:-40}
max_steps=${PD_COMPARE_MAX_STEPS:-0}
ranks=${PD_COMPARE_RANKS:-0}
launch=()
if [[ $ranks -gt 0 ]]; then
    launch=(mpirun -n "$ranks" --oversubscribe)
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
fi
rtol=${PD_COMPARE_RTOL:-1e-12}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A capped copy of SCENE as $work/NAME.yaml, with EXTRA (YAML lines) appended.
prepare() {
    local name=$1 scene=$2 extra=$3
    awk -v mc="$max_count" -v ms="$max_steps" '
        match($0, /^( *)count: *[0-9]+/) {
            n = substr($0, RSTART, RLENGTH); sub(/.*: */, "", n)
            if (n + 0 > mc) { c = mc - mc % 2; sub(/count: *[0-9]+/, "count: " c) }
        }
        match($0, /^( *)steps: *[0-9]+/) {
            n = substr($0, RSTART, RLENGTH); sub(/.*: */, "", n)
            if (ms > 0 && n + 0 > ms) sub(/steps: *[0-9]+/, "steps: " ms)
        }
        { print }' "$scene" > "$work/$name.yaml"
    [[ -n $extra ]] && printf '%s\n' "$extra" >> "$work/$name.yaml"
    if [[ $ranks -gt 0 ]]; then  # solver.backend: petsc, merged into the scene's own solver section
        /usr/bin/python3 -c '
import sys, yaml
path = sys.argv[1]
scene = yaml.safe_load(open(path))
scene.setdefault("solver", {})["backend"] = "petsc"
yaml.safe_dump(scene, open(path, "w"), sort_keys=False)' "$work/$name.yaml"
    fi
    names+=("$name"); sources+=("$scene")
}
names=(); sources=()
for scene in "${scenes[@]}"; do prepare "$(basename "$scene" .yaml)" "$scene" ""; done
# No scene in scenes/ takes the matrix-free or assembled-Krylov paths, so the crack scene
# (which has no solver section) is also run on each of them: `auto` sent matrix-free by a
# low direct_max_nonzeros (short-horizon preconditioner, then Jacobi), each named, and CG.
if [[ $# -eq 0 && -f $repo/scenes/crack.yaml ]]; then
    crack=$repo/scenes/crack.yaml
    prepare crack+auto_short_horizon "$crack" "solver: {direct_max_nonzeros: 1000}"
    prepare crack+auto_jacobi "$crack" "solver: {direct_max_nonzeros: 1000, preconditioner_max_nonzeros: 1000}"
    prepare crack+matrix_free_diagonal "$crack" "solver: {linear: matrix_free, preconditioner: diagonal}"
    prepare crack+matrix_free_short "$crack" "solver: {linear: matrix_free, preconditioner: short_horizon}"
    prepare crack+cg_ic "$crack" "solver: {linear: cg, preconditioner: ic}"
    prepare crack+bicgstab "$crack" "solver: {linear: bicgstab}"
fi
# No scene in scenes/ has viscous damping or prescribed motion in time (a velocity
# condition, a displacement with a time function): one small explicit scene has all three
# (the top row's condition stops short of the held left corner, which two conditions on
# one component would give: refused since 8586a84).
if [[ $# -eq 0 ]]; then
    cat > "$work/motion_source.yaml" <<'YAML'
dimension: 2
domain: {box: {min: [0, 0], max: [0.2, 0.1]}, spacing: 0.01}
horizon: {ratio: 3.0}
law: silling_plane_strain
influence: const
materials: [{name: m, E: 1.0, nu: 0.25, density: 2.5}]
boundary:
  - region: {side: left}
    fixed: [x, y]
  - region: {side: right}
    velocity: {x: 0.01}
    time_function: {ramp: 0.5}
  - region: {side: top, within: {min: [0.02, 0], max: [0.18, 1]}}
    displacement: {y: 0.001}
    time_function: {sine: {period: 2.0}}
probes:
  - {name: u_mid, region: {box: {min: [0.09, 0.04], max: [0.11, 0.06]}}, component: x}
dynamics: {method: explicit, steps: 300, damping: 0.5, output_every: 50, threads: 1}
YAML
    prepare damped_prescribed_motion "$work/motion_source.yaml" ""
fi

status=0
for i in "${!names[@]}"; do
    name=${names[$i]}
    scene=${sources[$i]}
    copy="$work/$name.yaml"
    declare -A rcs=()
    for side in before after; do
        pd=$before; [[ $side == after ]] && pd=$after
        rc=0
        (cd "$(dirname "$scene")" && "${launch[@]}" "$pd" run "$copy" --out "$work/$name.$side") \
            > "$work/$name.$side.log" 2>&1 || rc=$?
        rcs[$side]=$rc
    done
    if [[ ${rcs[before]} -ne 0 || ${rcs[after]} -ne 0 ]]; then
        # Both refusing the same scene with the same message (e.g. a solver path the PETSc
        # backend does not take) is agreement; anything else is a difference.
        if [[ ${rcs[before]} -eq ${rcs[after]} ]] &&
           [[ "$(grep -v '^pd ' "$work/$name.before.log" | tail -1)" == "$(grep -v '^pd ' "$work/$name.after.log" | tail -1)" ]]; then
            echo "$name: both refused alike (exit status ${rcs[after]}): $(tail -1 "$work/$name.after.log")"
        else
            echo "$name: exit status ${rcs[before]} before, ${rcs[after]} after; logs:"
            tail -n 3 "$work/$name.before.log" "$work/$name.after.log" || true
            status=1
        fi
        continue
    fi
    if ! /usr/bin/python3 - "$work/$name.before/summary.json" "$work/$name.after/summary.json" \
            "$rtol" "$name" <<'EOF'
import json, sys
a = json.load(open(sys.argv[1])); b = json.load(open(sys.argv[2]))
rtol = float(sys.argv[3]); name = sys.argv[4]
SKIP = {"seconds", "files", "scene", "peak_memory_mb", "output_directory", "run_id", "pd"}
diffs = []; count = [0, 0]; worst = [0.0]
def walk(x, y, path):
    if isinstance(x, dict) and isinstance(y, dict):
        for k in sorted(set(x) | set(y)):
            if k in SKIP: continue
            if k not in x or k not in y: diffs.append(f"{path}/{k}: only in {'after' if k in y else 'before'}"); continue
            walk(x[k], y[k], f"{path}/{k}")
    elif isinstance(x, list) and isinstance(y, list):
        if len(x) != len(y): diffs.append(f"{path}: length {len(x)} vs {len(y)}"); return
        for i, (u, v) in enumerate(zip(x, y)): walk(u, v, f"{path}[{i}]")
    elif isinstance(x, bool) or isinstance(y, bool) or isinstance(x, str) or isinstance(y, str) or x is None or y is None:
        count[1] += 1
        if x != y: diffs.append(f"{path}: {x!r} vs {y!r}")
    else:
        count[0] += 1
        scale = max(abs(x), abs(y))
        rel = abs(x - y) / scale if scale > 0 else 0.0
        worst[0] = max(worst[0], rel)
        if rel > rtol: diffs.append(f"{path}: {x!r} vs {y!r} (relative {rel:.2e})")
walk(a, b, "")
# The result files: every number to the same tolerance, every other cell exactly.
import os
for table in ("result.csv", "energies.csv"):
    pa, pb = (os.path.join(os.path.dirname(p), table) for p in sys.argv[1:3])
    if os.path.exists(pa) != os.path.exists(pb):
        diffs.append(f"{table}: written by one run only"); continue
    if not os.path.exists(pa): continue
    la, lb = open(pa).read().splitlines(), open(pb).read().splitlines()
    if len(la) != len(lb): diffs.append(f"{table}: {len(la)} vs {len(lb)} lines"); continue
    for row, (ra, rb) in enumerate(zip(la, lb)):
        for col, (x, y) in enumerate(zip(ra.split(","), rb.split(","))):
            try: walk(float(x), float(y), f"{table}[{row}][{col}]")
            except ValueError: walk(x, y, f"{table}[{row}][{col}]")
path = a.get("linear_solver", {}).get("method", a.get("method", "-"))
if diffs:
    print(f"{name}: DIFFERENT ({len(diffs)} of {count[0]} numbers / {count[1]} strings)")
    for d in diffs[:20]: print("   ", d)
    sys.exit(1)
print(f"{name}: same ({count[0]} numbers, largest relative difference {worst[0]:.1e}; {count[1]} strings equal; solver {path})")
EOF
    then
        status=1
    fi
done
exit $status
