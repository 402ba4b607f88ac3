#!/usr/bin/env bash
# The README's first command: install missing Debian packages, configure and build the
# optimized (Release) build in build/, then run parasol with no deck (the bundled SSNL130
# model A deck, whose TEST_RESU table is printed on the terminal).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build"
mkdir -p "$root/build/run"
cd "$root/build/run"
"$root/build/parasol"
