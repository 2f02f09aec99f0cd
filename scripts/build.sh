#!/usr/bin/env bash
# Configures and builds the project into build/ (installing missing packages first).
# Usage: scripts/build.sh [extra cmake --build args, e.g. --target pd]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build build -j "$(nproc)" "$@"
