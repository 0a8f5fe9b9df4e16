#!/usr/bin/env bash
# gpu_step.sh: the CUDA backend's per-step overhead (issue 21) on the device
# machine, two builds side by side in one call: microseconds per step of
# seawall.yaml's solitary case alone at its finest default dp (0.012 m;
# with the default outputs every 0.01 s and with outputs every 0.5 s, so
# that the steps alone show), the whole `wallload assess
# scenarios/seawall.yaml --backend cuda`, whether the two builds' results
# are the same bits, and the GPU tests of the second build.
#
#   bench/gpu_step.sh pack BASE_BUILD NEW_BUILD DIR   here: the two builds'
#       wallload, test_cuda_backend, test_cuda_starts and h5_series_equal into DIR/base and
#       DIR/new, the shared libraries the device machine lacks (ldd) into
#       DIR/lib, fonts for the report (as bench/assess_e2e.sh pack)
#   bench/gpu_step.sh run DIR [ROUNDS]   there (DIR carried): ROUNDS (1)
#       alternations of the timings; then the tests; $OUT/gpu_step.log and
#       $OUT/gpu_step.tgz (summaries). GPU_STEP_ALSO=NAME: a third build
#       DIR/NAME (packed by hand: its wallload) runs the solitary case too,
#       compared bit for bit with the new build's. GPU_STEP_NCU=1: each
#       kernel's duration over a few steps of both builds (Nsight Compute).
#       GPU_STEP_PLAN=1: seawall.yaml at dp = 0.0125 m, one level, Verlet
#       and symplectic (plan.h's step costs), both builds. GPU_STEP_SEA=0:
#       without the whole assess (about a minute a build and round).
#       A build's wallload may be a script (e.g. one that sets WL_CUDA_PDL=0
#       and runs the other build's), to compare settings of one build.
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
case ${1:-} in
pack)
  set -e
  base=$2 new=$3 D=$4
  rm -rf "$D/base" "$D/new" "$D/lib" "$D/fonts"
  mkdir -p "$D/base" "$D/new"
  for b in base new; do
    src=$base; [ $b = new ] && src=$new
    cp "$src/wallload" "$src/tests/test_cuda_backend" "$src/tests/test_cuda_starts" \
      "$src/tests/h5_series_equal" "$D/$b/"
    strip "$D/$b/"*
  done
  . "$here/bench/pack_runtime.sh"
  pack_runtime "$D" "$D"/base/* "$D"/new/*
  du -sh "$D"
  ;;
run)
  D=$(cd "$2" && pwd) rounds=${3:-1}
  out=${OUT:-/tmp}
  R=/tmp/gpu_step
  rm -rf $R && mkdir -p $R
  export LD_LIBRARY_PATH=$D/lib FONTCONFIG_FILE=$D/fonts.conf
  # the solitary case alone at the ladder's finest dp
  sed -e '/^  explosion:$/,/^    at: 12 m$/d' -e 's/^  dp: auto$/  dp: 0.012 m/' \
    -e '/^  particles_per_height:/d' -e '/^  convergence:/d' "$here/scenarios/seawall.yaml" >$R/sol.yaml
  sed 's/^run:$/run:\n  output_interval: 0.5 s/' $R/sol.yaml >$R/sol_few.yaml
  one() { # build name scenario
    local a b rc
    a=$(date +%s.%N)
    timeout 150 "$D/$1/wallload" assess "$3" --backend cuda --quiet --force -o $R/$1_$2 >$R/$1_$2.log 2>&1
    rc=$?
    b=$(date +%s.%N)
    python3 - "$1" "$2" "$rc" "$(awk "BEGIN{print $b - $a}")" "$R/$1_$2/summary.json" <<'PY'
import json, sys
b, n, rc, wall, f = sys.argv[1:6]
line = "%-4s %-9s rc=%s wall %6.2f s" % (b, n, rc, float(wall))
try:
    for name, c in json.load(open(f))["cases"].items():
        steps = c["steps"]["value"]; rt = c["runtime"]["value"]
        line += " | %s %d steps %.2f s %.1f us/step" % (name, steps, rt, 1e6 * rt / steps)
except Exception as e:
    line += " | (%s)" % e
print(line)
PY
  }
  {
    echo "# $(date -u +%FT%TZ) $(nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader 2>&1)"
    echo "# host: $(lscpu | grep 'Model name' | sed 's/  */ /g'), $(nproc) cores"
    for r in $(seq "$rounds"); do
      for b in base new; do
        one $b sol$r $R/sol.yaml
        one $b few$r $R/sol_few.yaml
        [ "${GPU_STEP_SEA:-1}" = 0 ] || one $b sea$r "$here/scenarios/seawall.yaml"
      done
    done
    if [ -n "${GPU_STEP_ALSO:-}" ]; then
      one "$GPU_STEP_ALSO" sol1 $R/sol.yaml
      "$D/new/h5_series_equal" $R/${GPU_STEP_ALSO}_sol1/results.h5 $R/new_sol1/results.h5 \
        /cases/solitary/time /cases/solitary/wall/force /cases/solitary/wall/pressure \
        /cases/solitary/gauges/G1/eta 2>&1 | sed "s/^/$GPU_STEP_ALSO vs new, sol1: /"
    fi
    echo "== base vs new, bit for bit"
    for n in sol1 few1 sea1; do
      for load in solitary explosion; do
        [ -f $R/base_$n/results.h5 ] || continue
        "$D/new/h5_series_equal" $R/base_$n/results.h5 $R/new_$n/results.h5 \
          /cases/$load/time /cases/$load/wall/force /cases/$load/wall/force_boundary \
          /cases/$load/wall/pressure /cases/$load/wall/moment /cases/$load/gauges/G1/eta \
          2>&1 | sed "s/^/$n $load: /" | grep -v 'cannot read it' | head -8
      done
      [ -f $R/base_$n/summary.json ] || continue
      python3 - $R/base_$n/summary.json $R/new_$n/summary.json "$n" <<'PY'
import json, sys
def leaves(x, p=""):
    if isinstance(x, dict):
        for k, v in x.items(): yield from leaves(v, p + "/" + k)
    elif isinstance(x, list):
        for i, v in enumerate(x): yield from leaves(v, p + "/%d" % i)
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        yield p, x
a = dict(leaves(json.load(open(sys.argv[1])))); b = dict(leaves(json.load(open(sys.argv[2]))))
skip = ("runtime", "rate", "wall_s", "seconds")
diff = [(k, a[k], b.get(k)) for k in a if not any(s in k for s in skip) and a[k] != b.get(k)]
print("%s summary.json: %d numbers, %d differ" % (sys.argv[3], len(a), len(diff)))
for k, x, y in diff[:15]: print("   %s: %r vs %r" % (k, x, y))
PY
    done
    echo "== tests (new build)"
    (cd $R && timeout 300 "$D/new/test_cuda_backend" >$R/test_cuda_backend.log 2>&1; echo "test_cuda_backend rc=$?")
    grep -E '^(FAIL|#.*blocks)' $R/test_cuda_backend.log | head -30
    echo "PASS: $(grep -c '^PASS' $R/test_cuda_backend.log) FAIL: $(grep -c '^FAIL' $R/test_cuda_backend.log)"
    (cd $R && timeout 300 "$D/new/test_cuda_starts" >$R/test_cuda_starts.log 2>&1; echo "test_cuda_starts rc=$?")
    grep -E '^(FAIL|# [0-9]+ starts)' $R/test_cuda_starts.log | head
    timeout 300 bash "$here/tests/cli_gpu_assess.sh" "$D/new/wallload" >$R/cli_gpu_assess.log 2>&1
    echo "cli_gpu_assess.sh rc=$?"; grep -E '^(FAIL|SKIP)' $R/cli_gpu_assess.log | head
    (cd $R && WL_H5_SERIES_EQUAL=$D/new/h5_series_equal timeout 300 bash "$here/tests/cli_sweep_run.sh" \
      "$D/new/wallload" "$here" cuda >$R/cli_sweep_run.log 2>&1; echo "cli_sweep_run.sh cuda rc=$?")
    grep -E '^(FAIL|SKIP)' $R/cli_sweep_run.log | head
    (cd $R && WL_H5_SERIES_EQUAL=$D/new/h5_series_equal timeout 300 bash "$here/tests/cli_gpu_cases.sh" \
      "$D/new/wallload" >$R/cli_gpu_cases.log 2>&1; echo "cli_gpu_cases.sh rc=$?")
    grep -E '^(FAIL|SKIP)' $R/cli_gpu_cases.log | head
    if [ -n "${GPU_STEP_PLAN:-}" ]; then
      # plan.h's step costs: seawall.yaml at dp = 0.0125 m, one level (its
      # two cases side by side), Verlet and symplectic, both builds
      sed -e 's/^  dp: auto$/  dp: 0.0125 m/' -e '/^  particles_per_height:/d' -e '/^  convergence:/d' \
        "$here/scenarios/seawall.yaml" >$R/p125.yaml
      sed 's/^  integrator: verlet$/  integrator: symplectic/' $R/p125.yaml >$R/p125s.yaml
      for b in base new; do
        one $b p125 $R/p125.yaml
        one $b p125s $R/p125s.yaml
      done
    fi
    if [ -n "${GPU_STEP_NCU:-}" ] && command -v ncu >/dev/null; then
      # each kernel's duration (Nsight Compute, clocks as found) over a few
      # steps of the solitary case, past its start
      for b in base new; do
        timeout 240 ncu --clock-control none --launch-skip 4000 --launch-count 120 --csv \
          --metrics gpu__time_duration.sum "$D/$b/wallload" assess $R/sol.yaml --backend cuda \
          --quiet --force -o $R/ncu_$b --end-time 0.6 >$R/ncu_$b.csv 2>$R/ncu_$b.err
        python3 - $R/ncu_$b.csv $b <<'PY'
import csv, sys, collections, re
rows = [r for r in csv.reader(open(sys.argv[1])) if len(r) > 10]
if not rows: print("ncu %s: no rows" % sys.argv[2]); sys.exit(0)
h = rows[0]; ki = h.index("Kernel Name"); vi = h.index("Metric Value"); ui = h.index("Metric Unit")
d = collections.OrderedDict()
for r in rows[1:]:
    name = re.sub(r"\(.*", "", r[ki]).replace("void ", "").strip()
    v = float(r[vi].replace(",", "")); v = v / 1000 if r[ui] == "nsecond" else v
    d.setdefault(name, []).append(v)
print("ncu %s: kernel, launches, median us" % sys.argv[2])
for k, v in d.items():
    v.sort(); print("   %-40s %4d %7.2f" % (k[:40], len(v), v[len(v) // 2]))
PY
      done
    fi
  } 2>&1 | tee "$out/gpu_step.log"
  (cd $R && tar czf "$out/gpu_step.tgz" */summary.json *.log 2>/dev/null)
  ;;
*) echo "usage: bench/gpu_step.sh pack BASE_BUILD NEW_BUILD DIR | run DIR [ROUNDS]" >&2; exit 2 ;;
esac
