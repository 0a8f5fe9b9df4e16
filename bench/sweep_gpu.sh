#!/usr/bin/env bash
# sweep_gpu.sh: sweeps on one GPU (issue 21): scenarios/seawall-sweep.yaml's
# 16 explosion cases each alone, one after the other, then the same 16 as
# `wallload sweep` runs them (side by side), and a 64-case version (8
# charges x 8 standoffs over the same ranges); what `check` estimated for
# each, from the same binary.
#
#   bench/sweep_gpu.sh pack BUILD DIR   here: BUILD's wallload into DIR/bin,
#       the shared libraries and fonts the device machine lacks (as
#       bench/gpu_step.sh pack)
#   bench/sweep_gpu.sh run DIR          there (DIR carried): $OUT/sweep_gpu.log
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
case ${1:-} in
pack)
  set -e
  build=$2 D=$3
  rm -rf "$D/bin" "$D/lib" "$D/fonts"
  mkdir -p "$D/bin"
  cp "$build/wallload" "$D/bin/"
  strip "$D/bin/wallload"
  . "$here/bench/pack_runtime.sh"
  pack_runtime "$D" "$D/bin/wallload"
  du -sh "$D"
  ;;
run)
  D=$(cd "$2" && pwd)
  out=${OUT:-/tmp}
  R=/tmp/sweep_gpu
  rm -rf $R && mkdir -p $R
  export LD_LIBRARY_PATH=$D/lib FONTCONFIG_FILE=$D/fonts.conf
  wl=$D/bin/wallload
  cp "$here/scenarios/seawall-sweep.yaml" $R/s16.yaml
  sed -e 's/^  charge: .*/  charge: {from: 0.083 g, to: 0.664 g, count: 8, spacing: log}/' \
    -e 's/^  standoff: .*/  standoff: {from: 7.2 m, to: 10.2 m, count: 8}/' \
    -e 's/^scenario: .*/scenario: seawall-sweep64/' $R/s16.yaml >$R/s64.yaml
  secs() { python3 -c "import sys; print('%.2f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$@"; }
  {
    echo "# $(date -u +%FT%TZ) $(nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader 2>&1)"
    echo "# host: $(lscpu | grep 'Model name' | sed 's/  */ /g'), $(nproc) cores"
    for n in 16 64; do
      echo "check s$n: $("$wl" check $R/s$n.yaml --backend cuda 2>&1 | grep 'sweep CPU runtime')"
    done
    a=$(date +%s.%N)
    "$wl" sweep $R/s16.yaml --backend cuda --quiet -o $R/sw16 >$R/sw16.log 2>&1
    echo "sweep of 16 cases side by side: rc=$? $(secs "$a" "$(date +%s.%N)") s"
    total=0
    for c in $R/sw16/cases/*/; do
      a=$(date +%s.%N)
      "$wl" assess "$c/scenario.yaml" --backend cuda --quiet --force -o $R/alone_$(basename "$c") \
        >$R/alone.log 2>&1
      rc=$?
      t=$(secs "$a" "$(date +%s.%N)")
      total=$(python3 -c "print('%.2f' % ($total + $t))")
      echo "  alone $(basename "$c"): rc=$rc $t s"
    done
    echo "the 16 cases alone, one after the other: $total s (mean $(python3 -c "print('%.2f' % ($total / 16))") s)"
    a=$(date +%s.%N)
    "$wl" sweep $R/s64.yaml --backend cuda --quiet -o $R/sw64 >$R/sw64.log 2>&1
    echo "sweep of 64 cases side by side: rc=$? $(secs "$a" "$(date +%s.%N)") s"
    tail -3 $R/sw64.log
    # a case alone gives the same results as in the sweep (bit for bit)
    for c in $R/sw16/cases/*/; do
      cmp -s "$c/explosion_wall.csv" "$R/alone_$(basename "$c")/explosion_wall.csv" ||
        echo "  $(basename "$c"): explosion_wall.csv differs alone and in the sweep"
    done
    echo "bit-for-bit check done"
  } 2>&1 | tee "$out/sweep_gpu.log"
  ;;
*) echo "usage: bench/sweep_gpu.sh pack BUILD DIR | run DIR" >&2; exit 2 ;;
esac
