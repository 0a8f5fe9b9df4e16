#!/usr/bin/env bash
# dambreak2d.sh: CPU backend throughput on the 2D dam break (see dambreak2d.c)
# at ~52k and ~500k particles on 1 and 2 threads. Results go to stdout; copy
# them into BENCHMARKS.md with the machine and date.
#
#   usage: bench/dambreak2d.sh [BUILD_DIR]      (default: build)
#
# BUILD_DIR must hold a Release build of the libraries (cmake --build).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
case $build in /*) ;; *) build=$PWD/$build ;; esac
exe=$(mktemp -d)/dambreak2d
trap 'rm -rf "$(dirname "$exe")"' EXIT
libs=""
for m in scene backend_cpu sph error; do libs="$libs $build/libwl_$m.a"; done
gcc -std=c11 -O3 -fopenmp -I"$root/include" -I"$build/include" "$root/bench/dambreak2d.c" \
  $libs -lm -o "$exe"
echo "# $(lscpu | grep 'Model name' | sed 's/  */ /g'), $(nproc) cores, $(date -u +%Y-%m-%d)"
# dp 0.0063 m: 50.4k fluid + boundary = ~53k; dp 0.002 m: 500k fluid + boundary = ~510k
for threads in 1 2; do
  "$exe" 0.0063 ${STEPS_SMALL:-400} "$threads"
  "$exe" 0.002 ${STEPS_LARGE:-40} "$threads"
done
