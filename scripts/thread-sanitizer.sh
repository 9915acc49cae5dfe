#!/usr/bin/env bash
# Builds the device links, simulators and print-run sequencer with clang's ThreadSanitizer in
# ./build-tsan and runs their tests (the ctest label `hardware`, and the printer-link tests among them) there.
# A data race fails the test that ran into it (TSAN_OPTIONS halt_on_error). Not part of the default run
# (docs/robustness.md, "Data races"); about 15 minutes on 2 cores from scratch.
#   bash scripts/thread-sanitizer.sh                 # every hardware test
#   bash scripts/thread-sanitizer.sh -R MarlinLink   # extra arguments go to ctest
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh" --sanitizers
build="$root/build-tsan"
flags="-fsanitize=thread -fno-omit-frame-pointer"
source "$root/scripts/compiler-cache.sh"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMULTIDIR_BUILD_GUI=OFF -DMULTIDIR_TCMALLOC=OFF \
  -DMULTIDIR_BUILD_BENCH=OFF -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" "${compiler_cache[@]}" >/dev/null
cmake --build "$build" -j"${MULTIDIR_JOBS:-$(nproc)}" --target multidir_hardware_tests multidir
cd "$build"
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 history_size=4" \
  ctest -L hardware --output-on-failure -j"${MULTIDIR_JOBS:-$(nproc)}" --timeout 900 "$@"
