#!/usr/bin/env bash
# Checks that the project's C++ sources are as clang-format formats them (.clang-format:
# Google style, 110 columns). generated/ is the generator's output and is not checked.
# Usage: scripts/check_format.sh [SOURCE_DIR]   (exit 1 naming each file that differs;
#        `clang-format -i FILE` fixes one)
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"
if ! command -v clang-format > /dev/null; then
    echo "clang-format not found: scripts/install_deps.sh installs it" >&2
    exit 1
fi
mapfile -t files < <(find runtime tests generator laws studies bench -type f \( -name '*.cpp' -o -name '*.hpp' \) | sort)
bad=0
for f in "${files[@]}"; do
    if ! clang-format --dry-run --Werror "$f" > /dev/null 2>&1; then
        echo "not clang-formatted: $f ($(clang-format "$f" | diff "$f" - | grep -c '^[<>]') lines differ)"
        bad=1
    fi
done
echo "$(clang-format --version | head -1): ${#files[@]} files checked"
exit $bad
