#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/fuzz_scene.cpp: scene XML, OBJ and PLY readers;
# fuzz/fuzz_cache_file.cpp: the --cache-load reader) with clang, ASan and UBSan into build-fuzz/,
# and fuzzes each for SECONDS (default 20; the cache reader gets half) starting from the committed
# corpora tests/fuzz/corpus (+ the shipped scenes) and tests/fuzz/corpus_cache. New inputs go to a scratch folder
# (the committed corpus is only read); a crash, a sanitizer report or an input running past 5 s
# makes libFuzzer exit non-zero and leaves the input in build-fuzz/artifacts/.
# CTest runs this as the `fuzz` label (tests/fuzz); to grow the committed corpus:
#   build-fuzz/fuzz_scene -merge=1 tests/fuzz/corpus NEW_INPUTS_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
secs=${1:-20}
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DRC_FUZZ=ON -DRC_BUILD_TESTS=OFF -DRC_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzz_scene fuzz_cache_file >/dev/null
mkdir -p build-fuzz/artifacts
scratch=$(mktemp -d)
scratch2=$(mktemp -d)
trap 'rm -rf "$scratch" "$scratch2"' EXIT
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
build-fuzz/fuzz_scene -max_len=8192 -timeout=5 -rss_limit_mb=2048 -max_total_time="$secs" -print_final_stats=1 \
  -artifact_prefix=build-fuzz/artifacts/ "$scratch" tests/fuzz/corpus scenes scenes/stress tests/cli/data 2>&1 | sed '/^"/d' | tail -25
build-fuzz/fuzz_cache_file -max_len=65536 -timeout=5 -rss_limit_mb=2048 -max_total_time="$((secs / 2))" \
  -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ "$scratch2" tests/fuzz/corpus_cache 2>&1 | sed '/^"/d' | tail -25
