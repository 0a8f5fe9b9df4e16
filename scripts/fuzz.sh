#!/usr/bin/env bash
# fuzz.sh: build the libFuzzer target of the parse-validate-plan path
# (tests/fuzz/fuzz_scenario.c, clang with ASan+UBSan) in build-fuzz/ and run
# it for a bounded time or number of inputs, one process.
#
#   usage: scripts/fuzz.sh [SECONDS]     run for SECONDS (default 60)
#          scripts/fuzz.sh --runs N      run N inputs
#   environment: FUZZ_JOBS (make -j, default 2), FUZZ_ARGS (more libFuzzer
#          options, e.g. "-seed=1" or "-only_ascii=1")
#
# Seed corpus: scenarios/*.yaml, tests/scenarios/**/*.yaml, reference/**/*.yaml
# and tests/fuzz/regress/*, copied at each run into build-fuzz/corpus/ (new
# inputs the fuzzer finds are kept there between runs); the YAML dictionary
# is tests/fuzz/scenario.dict. A crash, leak, UBSan report, timeout (10 s an
# input) or out-of-memory (2 GiB) writes its input to build-fuzz/artifacts/
# and makes this script exit non-zero. A finding becomes a regression input:
# copy it into tests/fuzz/regress/ (test_fuzz_regress replays them in every
# build).
set -eu
cd "$(dirname "$0")/.."
seconds=60
runs=""
case "${1:-}" in
  "") ;;
  --runs) runs="${2:?--runs needs a number}" ;;
  *[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS | --runs N]" >&2; exit 2 ;;
  *) seconds="$1" ;;
esac
command -v clang >/dev/null || { echo "fuzz.sh: clang not found (scripts/setup.sh installs it)" >&2; exit 1; }

build="build-fuzz"
cmake -S . -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DWL_FUZZ=ON -DWL_CUDA=OFF >/dev/null
cmake --build "$build" -j "${FUZZ_JOBS:-2}" --target fuzz_scenario >/dev/null

corpus="$build/corpus"
artifacts="$build/artifacts"
mkdir -p "$corpus" "$artifacts"
shopt -s nullglob globstar
n=0
for f in scenarios/*.yaml tests/scenarios/**/*.yaml reference/**/*.yaml tests/fuzz/regress/*; do
  [ -f "$f" ] || continue
  cp "$f" "$corpus/seed-$(echo "$f" | tr '/' '_')"
  n=$((n + 1))
done

if [ -n "$runs" ]; then limit="-runs=$runs"; what="$runs inputs"; else
  limit="-max_total_time=$seconds"; what="$seconds s"; fi
echo "fuzz.sh: fuzz_scenario for $what ($n seed files; artifacts in $artifacts/)" >&2
# detect_leaks: LeakSanitizer after every input (libFuzzer's default with
# ASan, made explicit); halt_on_error: a UBSan report is a crash.
# shellcheck disable=SC2086
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$build/tests/fuzz_scenario" "$corpus" -dict=tests/fuzz/scenario.dict \
  -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
  -artifact_prefix="$artifacts/" "$limit" ${FUZZ_ARGS:-}
