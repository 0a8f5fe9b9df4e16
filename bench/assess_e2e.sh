#!/usr/bin/env bash
# assess_e2e.sh: `wallload assess` end to end on the device machine, CPU and
# CUDA backends, for BENCHMARKS.md ("assess end to end, CPU vs CUDA").
# The device machine has CUDA but no GSL, libyaml, HDF5 or cairo/pango, so
# the full build is made here and carried with the shared libraries it needs.
#
#   bench/assess_e2e.sh pack   here: build build-e2e (-DWL_CUDA=ON) and fill
#                              .e2e/ (binary, non-glibc libraries from ldd,
#                              DejaVu fonts, fonts.conf, the wall scenario);
#                              add /.e2e/ to .git/info/exclude; ~42 MiB
#   bench/assess_e2e.sh run    there (device `run` with carry [".e2e"]):
#                              both scenarios on both backends, one after the
#                              other; $OUT/e2e.log, $OUT/e2e.tgz (summary.json
#                              and CSV of each run), the GPU seawall report
#   bench/assess_e2e.sh walls  there (carry [".e2e"]): issue 17's wall-condition
#                              set: the CPU/GPU test, the bench cost of the
#                              wall condition against DBC, 3D and 2D dam
#                              breaks to the end with assess's numerics, and
#                              seawall.yaml with each wall condition on the
#                              GPU; $OUT/walls.log, $OUT/walls.tgz
#   bench/assess_e2e.sh ladder there (carry [".e2e"]): issue 19's convergence
#                              measurement, seawall.yaml on the GPU with a
#                              4-level ladder (1, 0.71, 0.5, 0.35): dp auto
#                              (whole rows of still water) and dp = 0.0125 m
#                              as given (the spacings before whole rows);
#                              $OUT/ladder.log, $OUT/ladder.tgz
#   python3 bench/assess_compare.py DIR   here, on the unpacked e2e.tgz
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
E=$root/.e2e
case ${1:-} in
pack)
  set -e
  cd "$root"
  cmake -S . -B build-e2e -DWL_CUDA=ON -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build-e2e -j2 --target wallload >/dev/null
  ex=$(git rev-parse --git-path info/exclude) && mkdir -p "$(dirname "$ex")"
  grep -qx '/.e2e/' "$ex" 2>/dev/null || echo /.e2e/ >>"$ex"
  rm -rf "$E" && mkdir -p "$E/lib" "$E/fonts"
  cmake --build build-e2e -j2 --target test_cuda_backend >/dev/null
  cp build-e2e/wallload build-e2e/tests/test_cuda_backend "$E/"
  . "$root/bench/pack_runtime.sh"
  pack_runtime "$E" build-e2e/wallload
  # solitary wave on a vertical wall, h = 0.2 m, H/h = 0.3, dp = 0.01 m
  # (tests/test_solitary_wall.c: crest x0 = 0.55 L, wall x0 + 0.75 L, L = 6/K)
  cat >"$E/solwall.yaml" <<'YAML'
scenario: solwall
water: {depth: 0.2 m}
domain: {length: 3.787 m}
wall: {x: 3.287 m, height: 0.6 m, probes: 40}
gauges: [{name: G1, x: 2.5 m}, {name: G2, x: 3.2 m}]
loads:
  solitary: {height: 0.06 m, generation: initial, at: 1.392 m}
resolution: {dp: 0.01 m}
run: {output_interval: 0.005 s}
YAML
  du -sh "$E"
  ;;
run)
  t0=$(date +%s)
  R=/tmp/e2e; mkdir -p $R; out=${OUT:-/tmp}
  export FONTCONFIG_FILE=$E/fonts.conf
  one() { # name time-limit assess-arguments...; SIGINT at the limit keeps what was done
    local n=$1 to=$2; shift 2
    local a; a=$(date +%s.%N)
    timeout -s INT -k 20 "$to" env LD_LIBRARY_PATH="$E/lib" "$E/wallload" assess "$@" --quiet \
      -o $R/$n >$R/$n.log 2>&1
    local rc=$? b; b=$(date +%s.%N)
    echo "== $n rc=$rc wall=$(awk "BEGIN{print $b - $a}") s"; tail -40 $R/$n.log
  }
  {
    echo "# $(date -u +%FT%TZ) $(nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader 2>&1)"
    echo "# host: $(lscpu | grep 'Model name' | sed 's/  */ /g'), $(nproc) cores"
    env LD_LIBRARY_PATH="$E/lib" "$E/wallload" --version
    one sol_cuda 120 "$E/solwall.yaml" --backend cuda
    one sol_cpu 150 "$E/solwall.yaml" --backend cpu --threads 16
    one sea_cuda 200 "$root/scenarios/seawall.yaml" --backend cuda
    one sea_cpu $((470 - ($(date +%s) - t0))) "$root/scenarios/seawall.yaml" --backend cpu --threads 16
  } 2>&1 | tee "$out/e2e.log"
  (cd $R && tar czf "$out/e2e.tgz" */summary.json */*.csv *.log)
  cp $R/sea_cuda/report.pdf "$out/sea_cuda_report.pdf" 2>/dev/null
  ;;
walls)
  R=/tmp/walls; mkdir -p $R; out=${OUT:-/tmp}
  export FONTCONFIG_FILE=$E/fonts.conf LD_LIBRARY_PATH=$E/lib
  W=$E/wallload
  # the same scenario with the dynamic boundary condition (its numerics block
  # is in block style: the key goes in under it)
  sed 's/^numerics:$/numerics:\n  boundary: dbc/' "$root/scenarios/seawall.yaml" >$R/seawall-dbc.yaml
  {
    echo "# $(date -u +%FT%TZ) $(nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader 2>&1)"
    "$W" --version
    echo "== CPU/GPU agreement"; timeout 240 "$E/test_cuda_backend" 2>&1 | grep -E '^(FAIL|INFO)|passed|failed' | grep -v '^PASS' | tail -25
    if [ -z "${WALLS_NO_COST:-}" ]; then
      echo "== cost: wall condition vs DBC (DualSPHysics numerics, equal layers)"
      for b in adami dbc; do "$W" bench --backend cuda --case dambreak3d --particles 1.04e6 --steps 100 --boundary $b | tail -2; done
      "$W" bench --backend cuda --case dambreak3d --particles 1.04e6 --steps 100 --boundary dbc --layers 2 | tail -2
      for b in adami dbc; do "$W" bench --backend cuda --case dambreak2d --particles 8.9e5 --steps 100 --boundary $b | tail -2; done
    fi
    echo "== stability: dam breaks to the end with assess's numerics (default walls)"
    for v in ${WALLS_VARIANTS:---boundary_adami}; do  # variants: options joined by _
      echo "-- ${v//_/ }"
      timeout ${WALLS_T3D:-150} "$W" bench --backend cuda --case dambreak3d --particles 1.04e6 --until 1.6 --numerics assess ${v//_/ } | tail -3
      timeout ${WALLS_T2D:-60} "$W" bench --backend cuda --case dambreak2d --particles 1e5 --until 3 --numerics assess ${v//_/ } | tail -3
    done
    [ -n "${WALLS_NO_SEAWALL:-}" ] && exit 0
    echo "== seawall.yaml on the GPU"
    timeout 120 "$W" assess "$root/scenarios/seawall.yaml" --backend cuda --quiet -o $R/sea_adami >$R/sea_adami.log 2>&1; echo "rc=$?"; tail -30 $R/sea_adami.log
    timeout 120 "$W" assess $R/seawall-dbc.yaml --backend cuda --quiet -o $R/sea_dbc >$R/sea_dbc.log 2>&1; echo "rc=$?"; tail -30 $R/sea_dbc.log
  } 2>&1 | tee "$out/walls.log"
  (cd $R && tar czf "$out/walls.tgz" */summary.json */*.csv *.log *.yaml)
  ;;
ladder)
  R=/tmp/ladder; mkdir -p $R; out=${OUT:-/tmp}
  export FONTCONFIG_FILE=$E/fonts.conf LD_LIBRARY_PATH=$E/lib
  W=$E/wallload
  # seawall.yaml's resolution block with 4 particles per wave height (its
  # finest level) as the first of four levels
  lad='  convergence: [1, 0.7071, 0.5, 0.3536]'
  sed "s|^  particles_per_height: 2\$|  particles_per_height: 4|; s|^  convergence: .*|$lad|" \
    "$root/scenarios/seawall.yaml" >$R/whole.yaml
  sed "s|^  dp: auto\$|  dp: 0.0125 m|; /^  particles_per_height: 2\$/d; s|^  convergence: .*|$lad|" \
    "$root/scenarios/seawall.yaml" >$R/given.yaml
  {
    echo "# $(date -u +%FT%TZ) $(nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader 2>&1)"
    "$W" --version
    for n in whole given; do
      echo "== $n"; grep -E '^  (dp|particles_per|convergence)' $R/$n.yaml
      timeout ${LADDER_T:-280} "$W" assess $R/$n.yaml --backend cuda --quiet -o $R/$n >$R/$n.log 2>&1
      echo "rc=$?"; tail -45 $R/$n.log
      cat $R/$n/convergence.csv 2>/dev/null
    done
  } 2>&1 | tee "$out/ladder.log"
  (cd $R && tar czf "$out/ladder.tgz" */summary.json */*.csv *.log *.yaml)
  ;;
*) echo "usage: bench/assess_e2e.sh pack|run|walls|ladder" >&2; exit 2 ;;
esac
