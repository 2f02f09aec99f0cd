#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (+ ASan/UBSan) into build-fuzz/ and fuzzes each
# reader of outside input (the scene, the particle CSV, the particle .vtu, the checkpoint)
# and the law generator on random laws. Usage: scripts/fuzz.sh [seconds per target]   (default 20; a longer run: 3600)
# The tracked corpora tests/fuzz/corpus/<target>/ are read, never written: new inputs that
# reach new code go to build-fuzz/corpus-new/<target>/ (commit minimised ones deliberately,
# e.g. with -merge=1 into the tracked directory); any crash input is written to
# build-fuzz/ and fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
targets=(scene particle_csv particle_vtu checkpoint pdgen)
./scripts/install_deps.sh
if [ ! -f build-fuzz/CMakeCache.txt ]; then cmake --preset fuzz >/dev/null; fi
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
cd build-fuzz
for t in "${targets[@]}"; do
  echo "== fuzz_$t: $seconds s"
  mkdir -p "corpus-new/$t"
  ./bin/fuzz_"$t" -max_total_time="$seconds" -max_len=4096 -timeout=10 "corpus-new/$t" "../tests/fuzz/corpus/$t"
done
