#!/usr/bin/env bash
# cli_sweep_run.sh: a 2 x 2 sweep gives, case for case, what `wallload
# assess` gives on the same scenario alone (issue 21: bit-identical on one
# backend), and writes its files.
#
# The sweep is tests/scenarios/sweep/tiny-sweep.yaml; the scenarios alone
# are written by tests/sweep_alone.py from the sweep's file by text
# substitution, independently of wallload's sweep code. Checked: every row
# of sweep.csv (17 digits) against the alone run's summary.json (10 digits,
# as it is written); the wall-load and gauge series of each case's
# results.h5 against the alone run's, bit for bit (h5_series_equal); the
# step counts; sweep.h5 and sweep.pdf exist and read.
#
# On a GPU (BACKEND cuda: ctest's cli_sweep_run_gpu) the sweep runs its
# cases side by side, each in its own thread and stream: the same checks
# then say that a case beside others gives what it gives alone.
#
# usage: cli_sweep_run.sh WALLLOAD SOURCE_DIR [BACKEND]   (cpu, the default, or cuda)
#        [WL_H5_SERIES_EQUAL=path of h5_series_equal]
set -u
bin=$1; src=$2
backend=${3:-${WL_TEST_BACKEND:-cpu}}
cmp_h5=${WL_H5_SERIES_EQUAL:-$(dirname "$bin")/tests/h5_series_equal}
. "$src/tests/sweep_lib.sh"
if [ "$backend" = cuda ]; then
  "$bin" --version 2>/dev/null | grep -q 'CUDA backend: built' ||
    { echo "SKIP: wallload built without the CUDA backend"; exit 77; }
  command -v nvidia-smi >/dev/null && nvidia-smi -L >/dev/null 2>&1 ||
    { echo "SKIP: no NVIDIA GPU (nvidia-smi -L)"; exit 77; }
fi
[ -x "$cmp_h5" ] || { echo "SKIP: $cmp_h5 not built"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$src/tests/scenarios/sweep/tiny-sweep.yaml" .

"$bin" sweep tiny-sweep.yaml -o sw --threads 1 --backend "$backend" >out.txt 2>err.txt; rc=$?
[ $rc = 0 ] && ok "sweep exits 0" || bad "sweep exit $rc: $(cat err.txt)"
for f in sweep.csv sweep.h5 sweep.pdf; do
  [ -s "sw/$f" ] && ok "sw/$f written" || bad "sw/$f missing"
done
ls sw/*.tmp sw/*.part 2>/dev/null && bad "temporary files left" || ok "no temporary file left"
if command -v pdfinfo >/dev/null; then
  pages=$(pdfinfo sw/sweep.pdf 2>/dev/null | sed -n 's/^Pages: *//p')
  [ "${pages:-0}" -ge 3 ] && ok "sweep.pdf opens: $pages pages" || bad "sweep.pdf does not open"
fi
grep -Eq "case 4/4 \(energy = 25 J, standoff = 1.5 m\): (running|started)" err.txt \
  && ok "progress names the case and how many" || bad "no 'case 4/4' progress line: $(head -5 err.txt)"

mkdir alone
python3 "$src/tests/sweep_alone.py" tiny-sweep.yaml alone >cases.txt || bad "sweep_alone.py failed"
for i in 0 1 2 3; do
  "$bin" assess "alone/case_$i.yaml" -o "alone/out_$i" --threads 1 --backend "$backend" --quiet >/dev/null 2>&1 \
    || bad "assess alone case $i failed"
done

# sweep.csv's rows against summary.json of the cases alone
python3 - sw/sweep.csv alone <<'PY' || fail=$((fail+1))
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
fields = {"peak_force": "N_per_m", "peak_force_boundary": "N_per_m",
          "impulse_positive": "Ns_per_m", "impulse_positive_boundary": "Ns_per_m",
          "impulse": "Ns_per_m", "impulse_positive_phase": "Ns_per_m",
          "peak_moment": "Nm_per_m", "max_runup": "m"}
bad = 0
if len(rows) != 4:
    print("FAIL sweep.csv has %d rows, expected 4" % len(rows)); sys.exit(1)
for i, r in enumerate(rows):
    alone = json.load(open("%s/out_%d/summary.json" % (sys.argv[2], i)))["cases"]
    if r["status"] != "complete":
        print("FAIL case %d: status %s" % (i, r["status"])); bad += 1
    n = 0
    for load in ("solitary", "explosion"):
        for f, unit in fields.items():
            v = float(r["%s_%s_%s" % (load, f, unit)])
            want = alone[load][f]["value"]
            # summary.json holds 10 significant digits: the same double rounds to them
            if float("%.10g" % v) != want:
                print("FAIL case %d %s.%s: sweep %.17g, alone %r" % (i, load, f, v, want)); bad += 1
            n += 1
    print("PASS case %d: %d loads equal to the case run alone" % (i, n))
sys.exit(1 if bad else 0)
PY

# every series of each case's results.h5, bit for bit
for i in 0 1 2 3; do
  d=$(ls -d sw/cases/00${i}_*)
  for load in solitary explosion; do
    out=$("$cmp_h5" "$d/results.h5" "alone/out_$i/results.h5" \
      /cases/$load/time /cases/$load/wall/force /cases/$load/wall/force_boundary \
      /cases/$load/wall/pressure /cases/$load/wall/moment /cases/$load/gauges/G1/eta \
      /cases/$load/energy/kinetic 2>&1) \
      && ok "case $i $load: series bit-identical to the case alone" \
      || bad "case $i $load: $out"
  done
  s1=$(python3 -c "import json,sys; c=json.load(open(sys.argv[1]))['cases']; print(c['solitary']['steps']['value'], c['explosion']['steps']['value'])" "$d/summary.json")
  s2=$(python3 -c "import json,sys; c=json.load(open(sys.argv[1]))['cases']; print(c['solitary']['steps']['value'], c['explosion']['steps']['value'])" "alone/out_$i/summary.json")
  [ -n "$s1" ] && [ "$s1" = "$s2" ] && ok "case $i: steps $s1 as alone" || bad "case $i: steps $s1, alone $s2"
done

# the case's own scenario.yaml runs alone too (what the README offers)
d=$(ls -d sw/cases/003_*)
"$bin" check "$d/scenario.yaml" >/dev/null 2>&1 && ok "a case's scenario.yaml checks alone" \
  || bad "$d/scenario.yaml does not check"
# assess refuses the sweep's file (one scenario at a time), exit 2, naming the sweep key
out=$("$bin" assess tiny-sweep.yaml -o x 2>&1); rc=$?
[ $rc = 2 ] && grep -q "tiny-sweep.yaml:14:1: sweep:" <<<"$out" && [ ! -e x ] \
  && ok "assess refuses a sweep: $out" || bad "assess on a sweep: exit $rc: $out"
exit $fail
