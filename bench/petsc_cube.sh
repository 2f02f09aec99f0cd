#!/usr/bin/env bash
# The cube in tension (scenes/cube_tension.yaml) at COUNT^3 particles, delta/h = RATIO and
# law LAW, solved statically by the PETSc backend on RANKS processes: the 3D benchmark of
# docs/performance.md (time and memory per particle; bench/petsc_ranks.sh says what is
# measured). bond_based_constant_3d (nu = 1/4, the scene's) has a one-horizon tangent;
# silling_3d's couples two horizons. The front probe against u_z = T z / E = 5e-4 is printed.
# Usage: bench/petsc_cube.sh [COUNT=40] [RATIO=2.0] [RANKS=2] [LAW=bond_based_constant_3d] [PETSC_OPTIONS...]
set -euo pipefail
count=${1:-40}; ratio=${2:-2.0}; ranks=${3:-2}; law=${4:-bond_based_constant_3d}; shift $(( $# < 4 ? $# : 4 )) || true
petsc_options="$*"
here=$(cd "$(dirname "$0")/.." && pwd)
pd=${PD:-$here/build/bin/pd}
work=$(mktemp -d /tmp/petsc_cube.XXXX)
. "$here/bench/petsc_ranks.sh"
sed -e "s|  count: 8|  count: $count|" -e "s|horizon: {ratio: 2.0}|horizon: {ratio: $ratio}|" -e "s|^law: silling_3d|law: $law|" \
    -e "s|output: {directory: out/cube_tension}|output: {directory: $work/out}\nsolver: {backend: petsc}|" \
    "$here/scenes/cube_tension.yaml" > "$work/cube.yaml"
echo "cube count $count ((count + 1)^3 = $(((count + 1) * (count + 1) * (count + 1))) particles, node placement), delta/h = $ratio, $law, $(date -u +%FT%TZ)"
run_ranks cube "$ranks" "$work/cube.yaml" "$work" "$petsc_options"
grep -E "front_uz|Newton|SNES|converged" "$work/cube_$ranks.log" | head -5 || true
echo "logs: $work"
