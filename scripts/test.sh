#!/usr/bin/env bash
# test.sh: build and run the whole test suite twice: a Release build, then a
# build with AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/), then a
# half a minute of fuzzing of the scenario reader (scripts/fuzz.sh 30, build-fuzz/;
# longer campaigns: scripts/fuzz.sh SECONDS).
# GPU tests report "skipped" where no GPU is present.
#   scripts/test.sh --accuracy   runs only the accuracy tests (label "accuracy"),
#                                the validation cases the solver does not meet yet.
#   scripts/test.sh --extended   runs only the extended tests (label "extended"):
#                                passing checks too long for the default suite.
set -eu
cd "$(dirname "$0")/.."
jobs=$(nproc)
if [ "${1:-}" = "--accuracy" ] || [ "${1:-}" = "--extended" ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build -j "$jobs"
  exec ctest --test-dir build --output-on-failure -L "${1#--}"
fi
t0=$SECONDS
echo "== Release build and tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs" -LE "accuracy|extended"
echo "== Release: $((SECONDS - t0)) s"
echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
# Without the CUDA backend: the sanitizers instrument host code, the GPU
# tests skip without a GPU, and the Release build above already proves the
# CUDA code compiles; nvcc's builds of cuda.cu were a third of this build.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWL_SANITIZE=ON -DWL_CUDA=OFF >/dev/null
cmake --build build-asan -j "$jobs"
# The sanitized run is slower: tests that scale their work read WL_TEST_QUICK,
# and the long physics runs (label "long") are left to the Release build.
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions="$PWD/tests/lsan.supp" \
  WL_TEST_QUICK=1 ctest --test-dir build-asan --output-on-failure -j "$jobs" -LE "accuracy|extended|long"
echo "== Release and sanitizers: $((SECONDS - t0)) s"
echo "== Fuzzing the parse-validate-plan path (libFuzzer, ASan+UBSan), 30 s"
scripts/fuzz.sh 30
echo "== the whole suite: $((SECONDS - t0)) s (CI's budget: 15 minutes on 2 cores)"
