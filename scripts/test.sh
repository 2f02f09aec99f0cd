#!/usr/bin/env bash
# Builds everything and runs the whole test suite with ctest.
# Usage: scripts/test.sh [--sanitize] [extra ctest args]
#   --sanitize  build and test under AddressSanitizer + UBSan (build-sanitize/)
set -euo pipefail
cd "$(dirname "$0")/.."
preset=release dir=build
if [ "${1:-}" = "--sanitize" ]; then preset=sanitize dir=build-sanitize; shift; fi
./scripts/build.sh --preset "$preset"
# ctest runs two test processes at once on this 2-core machine; OpenMP threads that spin
# at barriers would then steal each other's cores (the coloured assembly slowed 30x).
export OMP_WAIT_POLICY=PASSIVE
ctest --test-dir "$dir" --output-on-failure -j "$(nproc)" "$@"
