#!/usr/bin/env bash
# h-refinement at nu = 0.495 on the inclusion problem (scenes/inclusion.yaml with both
# phases at nu = 0.495, inclusion 10x stiffer, delta = 3.5 h as in paper 001), for the
# laws that represent a near-incompressible solid; prints a markdown table of the error
# of eq. (48) and the observed order of the RMS error, 0.5 log2(e(h)/e(h/2)).
# Usage: [NU=0.495] scripts/stability/near_incompressible.sh [OUT_DIR] [COUNTS...]   (default out/nu0495, 20 40 80)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:-out/nu0495}
shift || true
counts=("${@:-20 40 80}")
read -r -a counts <<< "${counts[*]}"
nu=${NU:-0.495}
mkdir -p "$out"
laws=("silling_plane_strain|" "lps_corrected_plane_strain|" "correspondence_silling_plane_strain|stab: 1")
echo "| law | $(printf '%s² | ' "${counts[@]}")orders |"
echo "|---|$(printf -- '---|%.0s' "${counts[@]}")---|"
for entry in "${laws[@]}"; do
  law=${entry%%|*}
  params=${entry#*|}
  extra=""
  if [ -n "$params" ]; then extra=", parameters: {$params}"; fi
  errors=()
  for count in "${counts[@]}"; do
    tag="${law}_${count}"
    inner=$(python3 -c "print(1 - 3.5 * 2 / $count)")
    sed -e "s/^law: .*/law: $law/" -e "s/^  count: .*/  count: $count/" -e "s/ratio: 3.0/ratio: 3.5/" \
        -e "s|^  - {name: matrix.*|  - {name: matrix, E: 1, nu: $nu$extra}|" \
        -e "s|^  - {name: stiff.*|  - {name: stiff, E: 10, nu: $nu$extra}|" \
        -e "s/E_inclusion: 1000, nu_inclusion: 0.25/E_inclusion: 10, nu_inclusion: $nu/g" \
        -e "s/outside: {min: \[-0.85, -0.85\], max: \[0.85, 0.85\]}/outside: {min: [-$inner, -$inner], max: [$inner, $inner]}/" \
        -e "s|^output: .*|output: {directory: $out/$tag, vtu: false, csv: false}|" \
        scenes/inclusion.yaml > "$out/$tag.yaml"
    build/bin/pd run "$out/$tag.yaml" > "$out/$tag.log" 2>&1
    errors+=("$(python3 -c "import json;print(json.load(open('$out/$tag/summary.json'))['field_error_eq48'])")")
  done
  python3 - "$law${params:+ ($params)}" "${errors[@]}" <<'PY'
import math, sys
e = [float(v) for v in sys.argv[2:]]
orders = [0.5 * math.log2(a / b) for a, b in zip(e, e[1:])]
print(f"| {sys.argv[1]} | " + " | ".join(f"{v:.3g}" for v in e) + " | " + ", ".join(f"{o:.2f}" for o in orders) + " |")
PY
done
