#!/usr/bin/env bash
# Builds everything and runs the whole test suite with ctest.
# Usage: scripts/test.sh [--sanitize] [extra ctest args]
#   --sanitize  build and test under AddressSanitizer + UBSan (build-sanitize/)
set -euo pipefail
cd "$(dirname "$0")/.."
preset=release dir=build
if [ "${1:-}" = "--sanitize" ]; then preset=sanitize dir=build-sanitize; shift; fi
./scripts/build.sh --preset "$preset"
ctest --test-dir "$dir" --output-on-failure -j "$(nproc)" "$@"
