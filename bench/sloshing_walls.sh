#!/usr/bin/env bash
# sloshing_walls.sh: the first sloshing mode between mirror-plane end walls
# with dynamic-boundary side walls W apart, and between dynamic-boundary
# end walls (see sloshing_walls.c); h/dp = 10. Results go to stdout (README,
# "Known accuracy gaps", quotes them). About 2 minutes on one core.
#
#   usage: bench/sloshing_walls.sh [BUILD_DIR]      (default: build)
#
# BUILD_DIR must hold a Release build of the libraries (cmake --build).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
case $build in /*) ;; *) build=$PWD/$build ;; esac
exe=$(mktemp -d)/sloshing_walls
trap 'rm -rf "$(dirname "$exe")"' EXIT
libs=""
for m in plan scenario explosion waves units scene backend_cpu sph error; do libs="$libs $build/libwl_$m.a"; done
gcc -std=c11 -O3 -fopenmp -I"$root/include" -I"$build/include" "$root/bench/sloshing_walls.c" \
  -Wl,--start-group $libs -Wl,--end-group -lgsl -lgslcblas -lyaml -lm -o "$exe"
echo "# $(lscpu | grep 'Model name' | sed 's/  */ /g'), $(date -u +%Y-%m-%d)"
for w in 0.25 0.5 1 2; do OMP_NUM_THREADS=${THREADS:-1} "$exe" y 10 "$w"; done
OMP_NUM_THREADS=${THREADS:-1} "$exe" x 10 0.25
