#!/usr/bin/env bash
# cli_gpu_cases.sh: on a GPU `wallload assess` runs a scenario's load
# cases side by side, each in its own thread and CUDA stream (issue 21);
# each case must give what it gives run one after the other, bit for bit.
# The reference: a sweep of two cases, which runs its cases side by side
# and so each case's loads one after the other (an assessment inside a
# side-by-side sweep does); then each case's scenario.yaml through
# `assess`, its loads side by side, with a 3-level ladder (every case's
# levels beside each other too) and snapshots (two threads then write
# HDF5). Checked: every series of results.h5 (h5_series_equal), the step
# counts and loads of summary.json, both cases' snapshot files.
#
# usage: cli_gpu_cases.sh WALLLOAD [SOURCE_DIR] [WL_H5_SERIES_EQUAL=path of h5_series_equal]
# Skips (77) without a CUDA build, a GPU, python3 or h5_series_equal.
set -u
bin=$1
cmp_h5=${WL_H5_SERIES_EQUAL:-$(dirname "$bin")/tests/h5_series_equal}
fail=0
ok() { echo "PASS $1"; }
bad() { echo "FAIL $1"; fail=$((fail+1)); }
"$bin" --version 2>/dev/null | grep -q 'CUDA backend: built' ||
  { echo "SKIP: wallload built without the CUDA backend"; exit 77; }
command -v python3 >/dev/null || { echo "SKIP: no python3"; exit 77; }
command -v nvidia-smi >/dev/null && nvidia-smi -L >/dev/null 2>&1 ||
  { echo "SKIP: no NVIDIA GPU (nvidia-smi -L)"; exit 77; }
[ -x "$cmp_h5" ] || { echo "SKIP: $cmp_h5 not built"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cat >sw.yaml <<'YAML'
scenario: gpucases
water: {depth: 0.2 m}
domain: {length: 4 m}
wall: {x: 3 m, height: 0.4 m, probes: 10}
gauges: [{name: G1, x: 2 m}]
loads:
  solitary: {height: 0.06 m, generation: initial, at: 1.6 m}
  explosion: {charge: 0.05 g, at: 1.5 m}
resolution: {dp: 0.028 m, convergence: [1, 0.85, 0.71]}
run: {output_interval: 0.02 s, end_time: 0.4 s}
sweep:
  standoff: [1.4 m, 1.5 m]
YAML
msg=$("$bin" sweep sw.yaml -o sw --backend cuda 2>&1); rc=$?
if [ $rc != 0 ] && grep -q "no usable GPU" <<<"$msg"; then echo "SKIP: $msg"; exit 77; fi
[ $rc = 0 ] && ok "sweep --backend cuda (exit 0)" || bad "sweep: exit $rc: $msg"
for d in sw/cases/*/; do
  id=$(basename "$d")
  msg=$("$bin" assess "$d/scenario.yaml" --backend cuda -o "a_$id" 2>&1); rc=$?
  [ $rc = 0 ] && ok "$id: assess --backend cuda (exit 0)" || { bad "$id: exit $rc: $msg"; continue; }
  for load in solitary explosion; do
    out=$("$cmp_h5" "$d/results.h5" "a_$id/results.h5" \
      /cases/$load/time /cases/$load/wall/force /cases/$load/wall/force_boundary \
      /cases/$load/wall/pressure /cases/$load/wall/moment /cases/$load/gauges/G1/eta \
      /cases/$load/energy/kinetic 2>&1) \
      && ok "$id $load: series bit-identical beside the other load and one after the other" \
      || bad "$id $load: $out"
    for f in h5 xmf; do
      [ -s "a_$id/particles_$load.$f" ] && ok "$id $load: particles_$load.$f written" \
        || bad "$id $load: particles_$load.$f missing"
    done
  done
  ls a_$id/*.tmp a_$id/*.part 2>/dev/null && bad "$id: temporary files left" || ok "$id: no temporary file left"
  python3 - "$d/summary.json" "a_$id/summary.json" "$id" <<'PY' || fail=$((fail+1))
import json, sys
a = json.load(open(sys.argv[1]))["cases"]; b = json.load(open(sys.argv[2]))["cases"]
def leaves(x, p=""):
    if isinstance(x, dict):
        for k, v in x.items(): yield from leaves(v, p + "/" + k)
    elif isinstance(x, list):
        for i, v in enumerate(x): yield from leaves(v, p + "/%d" % i)
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        yield p, x
skip = ("runtime", "rate", "per_second", "wall_s", "seconds")
x = dict(leaves(a)); y = dict(leaves(b))
diff = [k for k in x if not any(s in k for s in skip) and x[k] != y.get(k)]
levels = [k for k in x if "/convergence/levels/2/steps" in k]
if diff:
    print("FAIL %s summary: %d of %d numbers differ: %s" % (sys.argv[3], len(diff), len(x), ", ".join(diff[:6])))
    sys.exit(1)
print("PASS %s summary: %d numbers the same (%d ladders of 3 levels)" % (sys.argv[3], len(x), len(levels)))
PY
done
[ $fail = 0 ] && echo "all passed" || { echo "$fail failed"; exit 1; }
