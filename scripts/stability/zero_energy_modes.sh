#!/usr/bin/env bash
# Zero-energy modes of the correspondence law on the pressurised crack (scenes/crack.yaml):
# for each delta/h, the unstabilised and the two stabilised laws, the oscillation
# |u - smooth(u)| / |u| (linear smoothing, paper 000 eq. 49) and the field error (eq. 48)
# against Westergaard, as a markdown table (docs/stability.md).
# Usage: scripts/stability/zero_energy_modes.sh [COUNT] [OUT_DIR]   (default 120, out/zero_energy)
set -euo pipefail
cd "$(dirname "$0")/../.."
count=${1:-120}
out=${2:-out/zero_energy}
pd=build/bin/pd
mkdir -p "$out"
laws=("silling_plane_strain|" "correspondence_plane_strain|" "correspondence_silling_plane_strain|stab: 1"
      "correspondence_littlewood_plane_strain|hourglass: 10")
echo "| δ/h | law | oscillation | field error (eq. 48) | smoothed field error |"
echo "|---|---|---|---|---|"
for ratio in 1.5 2.0 2.5 3.0 3.5; do
  for entry in "${laws[@]}"; do
    law=${entry%%|*}
    params=${entry#*|}
    tag="${count}_${ratio}_${law}"
    extra=""
    if [ -n "$params" ]; then extra=", parameters: {$params}"; fi
    material="  - {name: rock, E: 60, nu: 0.0, plane: strain$extra}"
    sed -e "s/^law: .*/law: $law/" -e "s/^  count: 80 /  count: $count /" -e "s/ratio: 3.0/ratio: $ratio/" \
        -e "s|^  - {name: rock.*|$material|" \
        -e "s|^output: .*|output: {directory: $out/$tag, vtu: false, csv: false, smoothing: {influence: linear}}|" \
        scenes/crack.yaml > "$out/$tag.yaml"
    "$pd" run "$out/$tag.yaml" > "$out/$tag.log" 2>&1
    python3 - "$out/$tag/summary.json" "$ratio" "$law${params:+ ($params)}" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
s = j["smoothing_eq49"]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {s['oscillation']:.3g} | {j['field_error_eq48']:.3g} | {s['field_error_eq48']:.3g} |")
PY
  done
done
