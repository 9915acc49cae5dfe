#!/usr/bin/env bash
# Configures and builds MultiDir in ./build (Release with debug info). Extra arguments go to cmake.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=${MULTIDIR_JOBS:-$(nproc)}
source "$root/scripts/compiler-cache.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${compiler_cache[@]}" "$@"
cmake --build "$root/build" -j"$jobs"
