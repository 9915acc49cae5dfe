#!/usr/bin/env bash
# Configures and builds MultiDir in ./build (Release with debug info). Extra arguments go to cmake.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=${MULTIDIR_JOBS:-$(nproc)}
launcher=()
# A compiler cache, when the machine has one, makes rebuilds of other checkouts quick; nothing needs it.
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" "$@"
cmake --build "$root/build" -j"$jobs"
