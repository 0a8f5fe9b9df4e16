#!/usr/bin/env bash
# cli_sweep_price.sh: `wallload check` prices a sweep on the CPU as the sum
# of its cases, each priced as `check` prices that case's scenario alone
# (issue 21), and on a GPU as the cases run there, side by side: with k on
# the GPU each advances at 1 / (1 + 0.064 (k - 1)) of its speed alone
# (processor sharing, plan.h WL_PLAN_GPU_SHARE_COST; the tiny cases' force
# loops are far from the bound of their work), computed here from the cases
# priced alone. The scenarios alone are written by tests/sweep_alone.py,
# independently of wallload's sweep code; the sum is taken here. The budget
# judges the sum: a budget that each case fits but the sweep does not is
# refused, by check and by sweep (exit 2, nothing run).
#
# usage: cli_sweep_price.sh WALLLOAD SOURCE_DIR
set -u
bin=$1; src=$2
. "$src/tests/sweep_lib.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$src/tests/scenarios/sweep/tiny-sweep.yaml" .
mkdir alone
python3 "$src/tests/sweep_alone.py" tiny-sweep.yaml alone >/dev/null || bad "sweep_alone.py failed"

"$bin" check tiny-sweep.yaml --backend cpu >sweep.txt 2>&1 || bad "check of the sweep failed: $(tail -2 sweep.txt)"
total_cpu=$(sed -n 's/.*sweep CPU runtime (estimate) \([0-9.e+-]*\) s.*/\1/p' sweep.txt)
total_gpu=$(sed -n 's/.*GPU runtime (estimate, an H100) \([0-9.e+-]*\) s, up to \([0-9]*\) cases side by side$/\1/p' sweep.txt)
width=$(sed -n 's/.*GPU runtime (estimate, an H100) \([0-9.e+-]*\) s, up to \([0-9]*\) cases side by side$/\2/p' sweep.txt)
sum_cpu=0; sum_gpu=0; max_case=0; gpus="" 
for i in 0 1 2 3; do
  "$bin" check "alone/case_$i.yaml" --backend cpu >case.txt 2>&1 || bad "check of case $i alone failed"
  c=$(sed -n 's/^  CPU runtime (estimate) *\([0-9.e+-]*\) s.*/\1/p' case.txt)
  g=$(sed -n 's/^  GPU runtime (estimate) *\([0-9.e+-]*\) s.*/\1/p' case.txt)
  sum_cpu=$(python3 -c "print($sum_cpu + $c)"); sum_gpu=$(python3 -c "print($sum_gpu + $g)")
  max_case=$(python3 -c "print(max($max_case, $c))"); gpus="$gpus $g"
done
# check prints 4 significant digits a case alone and 6 for the sweep
if python3 -c "import sys; sys.exit(0 if abs($total_cpu - $sum_cpu) <= 1e-3 * $sum_cpu else 1)"; then
  ok "sweep CPU price $total_cpu s = sum of the cases alone $sum_cpu s"
else bad "sweep CPU price '$total_cpu' s, sum of the cases alone $sum_cpu s"; fi
[ "$width" = 4 ] && ok "the 4 cases side by side on a GPU" || bad "side by side: '$width', expected 4"
want_gpu=$(python3 - $gpus <<'PY'
import sys
left, t = [float(x) for x in sys.argv[1:]], 0.0
while left:  # all four on the GPU until the shortest ends, and so on
    m = min(left)
    t += m * (1 + 0.064 * (len(left) - 1))
    left = [x - m for x in left if x - m > 0]
print(t)
PY
)
if python3 -c "import sys; sys.exit(0 if abs($total_gpu - $want_gpu) <= 1e-3 * $want_gpu else 1)"; then
  ok "sweep GPU price $total_gpu s = the cases alone ($sum_gpu s) 4 side by side, $want_gpu s"
else bad "sweep GPU price '$total_gpu' s, expected $want_gpu s (the cases alone: $sum_gpu s)"; fi

# a budget between the dearest case and the whole sweep
hours=$(python3 -c "print(($max_case + $sum_cpu) / 2 / 3600)")
out=$("$bin" check "alone/case_0.yaml" --backend cpu --budget "$hours" 2>&1) \
  && ok "a case alone fits a budget of $hours h" || bad "case 0 alone refused at $hours h: $out"
out=$("$bin" check tiny-sweep.yaml --backend cpu --budget "$hours" 2>&1 >/dev/null); rc=$?
[ $rc = 2 ] && grep -qi "budget" <<<"$out" && ok "check refuses the sweep beyond the budget: $out" \
  || bad "check of the sweep at $hours h: exit $rc: $out"
out=$("$bin" sweep tiny-sweep.yaml --backend cpu --budget "$hours" -o sw 2>&1 >/dev/null); rc=$?
[ $rc = 2 ] && [ ! -e sw ] && ok "sweep refuses it too, before writing anything" \
  || bad "sweep at $hours h: exit $rc: $out"
exit $fail
