#!/usr/bin/env bash
# The main job on a default example. Installs missing packages, builds into build/,
# then: lists the generated laws with their kernels' operation counts, and verifies
# the first law's exact tangent against finite differences on random families.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh --target pd
echo
build/bin/pd laws -v
echo
build/bin/pd check-law silling_plane_strain
echo
echo "Generated kernels: build/generated/ (committed snapshot: generated/silling.cpp)"
