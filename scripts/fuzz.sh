#!/usr/bin/env bash
# Builds the libFuzzer harnesses (tests/fuzz: every loader of a user's file or a device's words) with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer in ./build-fuzz, and runs each for FUZZ_SECONDS (default 60)
# from its committed corpus. New inputs go to build-fuzz/corpus-work/NAME, inputs that broke a promise or
# crashed to build-fuzz/crashes/. Exits non-zero when any fuzzer found one. Not part of CI (docs/robustness.md, "Fuzzing").
#   bash scripts/fuzz.sh                  # every fuzzer, 60 s each
#   FUZZ_SECONDS=600 bash scripts/fuzz.sh plan_loader marlin_reply
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh" --sanitizers
seconds=${FUZZ_SECONDS:-60}
build="$root/build-fuzz"
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer"
source "$root/scripts/compiler-cache.sh"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMULTIDIR_BUILD_FUZZERS=ON -DMULTIDIR_TCMALLOC=OFF \
  -DMULTIDIR_BUILD_GUI=OFF -DMULTIDIR_BUILD_TESTS=OFF -DMULTIDIR_BUILD_BENCH=OFF \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" "${compiler_cache[@]}" >/dev/null

all=(mesh_loader plan_loader project_loader machine_profile printer_profile marlin_reply printer_reply)
names=("$@")
[ ${#names[@]} -eq 0 ] && names=("${all[@]}")
targets=()
for name in "${names[@]}"; do targets+=("multidir_${name}_fuzzer"); done
cmake --build "$build" -j"${MULTIDIR_JOBS:-$(nproc)}" --target "${targets[@]}"

mkdir -p "$build/crashes"
failed=0
for name in "${names[@]}"; do
  case $name in
    mesh_loader) seeds="$root/tests/fuzz/corpus" ;;
    *) seeds="$root/tests/fuzz/corpus-${name%_loader}" ;;
  esac
  seeds=${seeds/%_profile/}
  work="$build/corpus-work/$name"
  mkdir -p "$work"
  log="$build/$name.log"
  echo "fuzz: $name for ${seconds}s (seeds: ${seeds#$root/})"
  if ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
      "$build/tests/fuzz/multidir_${name}_fuzzer" "$work" "$seeds" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/crashes/$name-" >"$log" 2>&1; then
    echo "fuzz: $name: $(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$') runs, no failure"
  else
    failed=1
    echo "fuzz: $name FAILED: $(ls "$build"/crashes/"$name"-* 2>/dev/null | head -3 | tr '\n' ' ')(log: ${log#$root/})"
  fi
done
exit $failed
