#!/usr/bin/env bash
# Two resolutions in one run (resolution.refine, docs/variable-resolution.md)
# through `check` and `assess`: the plan prints both levels and what they
# save, the run completes with the wall in the fine level, its force at
# rest is rho g d^2/2 (closed form, within the 1.5 % the uniform flume's
# lattice reads), snapshots carry each particle's dp, and the CUDA backend
# is refused by name. The accuracy against a uniform run is
# test_solitary_wall's (label accuracy).
set -u
bin=$1; src=$2
fail=0
ok() { echo "PASS $1"; }
bad() { echo "FAIL $1"; fail=$((fail+1)); }
work=$(mktemp -d)
trap 'if [ "$(exec sh -c "echo \$PPID")" = "$$" ]; then rm -rf "$work"; fi' EXIT
cd "$work" || exit 1
dp=0.02; t_end=0.6; xf=2.3
# under the sanitizers (WL_TEST_QUICK): the pipeline at a coarser spacing
# (its wider overlap and bands need the interface further from the wall)
[ -n "${WL_TEST_QUICK:-}" ] && dp=0.03 && t_end=0.3 && xf=2.0
cat >refine.yaml <<YAML
scenario: refine
water: { depth: 0.24 m }
domain: { dimensions: 2, length: 3.8 m }
wall: { x: 3.3 m, height: 0.6 m, probes: 20 }
loads: { solitary: { height: 0.06 m, theory: exact, generation: initial, at: 1.4 m } }
resolution: { dp: $dp m, refine: { from: $xf m } }
run: { backend: auto }
YAML
out=$("$bin" check refine.yaml 2>&1); rc=$?
[ $rc = 0 ] && ok "check accepts refine" || bad "check exit $rc: $out"
grep -q "coarse level's spacing" <<<"$out" && grep -q "times fewer particle-steps" <<<"$out" &&
  ok "check prints the coarse level and the saving" || bad "check output: $out"
# `check` times its calibration flume when WL_CPU_SPEED does not set the
# speed (src/assess/speed.c): a positive speed and an estimate for here
out=$(env -u WL_CPU_SPEED "$bin" check refine.yaml 2>&1 | grep "CPU speed now")
grep -qE "CPU speed now: [0-9]+\.[0-9]+ of the reference.*about [0-9.e+]+ s here" <<<"$out" &&
  ok "check times this machine: $out" || bad "no CPU speed in check's output: $out"
out=$("$bin" assess refine.yaml --quiet --end-time $t_end --threads 2 2>&1); rc=$?
[ $rc = 0 ] && ok "assess with two levels (exit 0)" || bad "assess exit $rc: $out"
grep -q 'Name="dp"' refine-results/particles_solitary.xmf && ok "snapshots carry dp" ||
  bad "no dp in particles_solitary.xmf"
python3 - refine-results/solitary_wall.csv refine-results/summary.json <<'PY' && ok "the wall's force at rest is rho g d^2/2 within 1.5 %" || bad "force at rest"
import csv, json, sys
assert json.load(open(sys.argv[2]))["cases"]["solitary"]["status"] == "complete"
# the raw probe force before the wave's long front reaches the wall (from
# 0.1 s on it adds 1.3 % at dp = 0.02 m with one level or two) and after the
# start's first acoustic ringing; a uniform flume reads +0.74 % here
f = [float(r["force_N_per_m"]) for r in csv.DictReader(open(sys.argv[1]))
     if 0.02 <= float(r["time_s"]) <= 0.1]
rest, static = sum(f) / len(f), 0.5 * 1000 * 9.81 * 0.24 ** 2
print("force at rest", rest, "closed form", static, "samples", len(f))
sys.exit(0 if len(f) > 5 and abs(rest / static - 1) < 0.015 else 1)
PY
out=$("$bin" assess refine.yaml --quiet --end-time 0.01 --backend cuda -o cuda-try 2>&1); rc=$?
[ $rc = 2 ] && grep -q "resolution.refine" <<<"$out" && ok "the CUDA backend refused by name (exit 2)" ||
  bad "backend cuda: exit $rc: $out"
# from: auto: the plan places the interface (test_plan checks the rule by
# hand) and says so; an explosion beside it keeps one resolution, said
# (dp = 0.0075 m: the coarse level at 4 particles a wave height; check only)
sed -e "s/refine: { from: $xf m }/refine: { from: auto }/" -e "s/dp: $dp m/dp: 0.0075 m/" \
  -e 's/^loads: .*$/loads: { solitary: { height: 0.06 m, generation: initial, at: 0.9 m } }/' \
  -e 's/length: 3.8 m/length: 5.8 m/' -e 's/x: 3.3 m/x: 5.3 m/' refine.yaml >auto.yaml
out=$(env WL_CPU_SPEED=1 "$bin" check auto.yaml 2>&1); rc=$?
[ $rc = 0 ] && grep -q "placed by the plan" <<<"$out" && ok "check places the interface (from: auto)" ||
  bad "from: auto: exit $rc: $out"
exit $fail
