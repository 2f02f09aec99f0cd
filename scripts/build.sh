#!/usr/bin/env bash
# Configures and builds the project (installing missing packages first).
# Usage: scripts/build.sh [--preset release|sanitize] [extra cmake --build args, e.g. --target pd]
# The release preset builds into build/, the sanitize preset into build-sanitize/.
set -euo pipefail
cd "$(dirname "$0")/.."
preset=release
if [ "${1:-}" = "--preset" ]; then preset="$2"; shift 2; fi
./scripts/install_deps.sh
dir=$(python3 -c "import json;p={c['name']:c for c in json.load(open('CMakePresets.json'))['configurePresets']};print(p['$preset']['binaryDir'].replace('\${sourceDir}/',''))")
if [ ! -f "$dir/CMakeCache.txt" ]; then
  cmake --preset "$preset" >/dev/null
fi
cmake --build "$dir" -j "$(nproc)" "$@"
