#!/usr/bin/env bash
# The main job on a default example. Installs missing packages, builds into build/,
# lists the generated laws, verifies the first law's exact tangent against finite
# differences, and solves paper 000's pressurised crack (scenes/crack.yaml).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh --target pd
echo
build/bin/pd laws
echo
build/bin/pd check-law silling_plane_strain
echo
build/bin/pd run scenes/crack.yaml --out out/demo
echo
echo "Results: out/demo/ (result.vtu opens in ParaView; summary.json lists the run)."
