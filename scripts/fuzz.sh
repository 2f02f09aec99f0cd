#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (+ ASan/UBSan) into build-fuzz/ and fuzzes the
# scene reader. Usage: scripts/fuzz.sh [seconds]   (default 20; a longer run: 3600)
# The tracked corpus tests/fuzz/corpus/scene/ is read, never written: new inputs that reach
# new code go to build-fuzz/corpus-new/scene/ (commit minimised ones deliberately, e.g. with
# -merge=1 into the tracked directory); any crash input is written to build-fuzz/ and fails
# the run.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
./scripts/install_deps.sh
if [ ! -f build-fuzz/CMakeCache.txt ]; then cmake --preset fuzz >/dev/null; fi
cmake --build build-fuzz -j "$(nproc)" --target fuzz_scene
cd build-fuzz
mkdir -p corpus-new/scene
./bin/fuzz_scene -max_total_time="$seconds" -max_len=4096 -timeout=10 corpus-new/scene ../tests/fuzz/corpus/scene
