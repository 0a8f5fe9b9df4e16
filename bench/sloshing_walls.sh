#!/usr/bin/env bash
# sloshing_walls.sh: the first sloshing mode between mirror-plane end walls
# with dynamic-boundary side walls W apart, and between dynamic-boundary
# end walls (see sloshing_walls.c). Results go to stdout
# (docs/history/2026-11-25-walls.md says what they showed). At h/dp = 10
# (the default) about 2 minutes on one core;
# h/dp = 20 runs are NH=20 WIDTHS=2, about 6 minutes a run on 16 cores
# (THREADS=16).
#
#   usage: [NH=h/dp] [WIDTHS="W ..."] [THREADS=N] bench/sloshing_walls.sh [BUILD_DIR]
#          (defaults: NH=10, WIDTHS="0.25 0.5 1 2", THREADS=1, build)
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
nh=${NH:-10}
for w in ${WIDTHS:-0.25 0.5 1 2}; do OMP_NUM_THREADS=${THREADS:-1} "$exe" y "$nh" "$w"; done
OMP_NUM_THREADS=${THREADS:-1} "$exe" x "$nh" 0.25
