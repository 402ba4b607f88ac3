#!/usr/bin/env bash
# The README's second command: install missing Debian packages, configure and build the
# checked Debug build in build-debug/, and run the whole test suite (every CTest test except
# the `bench` label). Ends with CTest's summary; exit status non-zero on any failure.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build-debug" -G Ninja -DCMAKE_BUILD_TYPE=Debug
cmake --build "$root/build-debug"
cd "$root/build-debug"
ctest --output-on-failure -LE bench -j "$(nproc)"
