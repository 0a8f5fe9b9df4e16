#!/usr/bin/env bash
# cli_sweep_resume.sh: a sweep stopped by SIGTERM after its first case
# finished continues where it stopped when run again (issue 21): every case
# runs to completion exactly once over the two runs (the second run's log
# says which cases it read back), and sweep.csv then equals an
# uninterrupted sweep's (all but the runtime column). A change of the
# cases' inputs (here --end-time) runs every case again.
#
# usage: cli_sweep_resume.sh WALLLOAD SOURCE_DIR
set -u
bin=$1; src=$2
. "$src/tests/sweep_lib.sh"
work=$(mktemp -d)
pid=""
# The clean-up runs in this shell only: a background child signalled
# before it execs is still a copy of this shell, runs the trap, and would
# delete the work directory under the rest of the test (its $$ and even
# $BASHPID read as this shell's then; a new sh's parent does not).
trap 'if [ "$(exec sh -c "echo \$PPID")" = "$$" ]; then [ -n "$pid" ] && kill -9 $pid 2>/dev/null; rm -rf "$work"; fi' EXIT
cd "$work" || exit 1
cp "$src/tests/scenarios/sweep/tiny-sweep.yaml" .
ARGS=(sweep tiny-sweep.yaml --threads 1 --backend cpu)

# the reference: one uninterrupted sweep
"$bin" "${ARGS[@]}" -o whole >/dev/null 2>whole.err || bad "uninterrupted sweep failed: $(cat whole.err)"

# run 1, stopped once the first case has finished (its marker is written last)
"$bin" "${ARGS[@]}" -o sw >run1.out 2>run1.err &
pid=$!
for _ in $(seq 1 1200); do
  ls sw/cases/000_*/sweep-case.txt >/dev/null 2>&1 && break
  sleep 0.05
done
sleep 0.3 # into the second case (about 1.5 s): it stops mid-run and runs again next time
kill -TERM $pid 2>/dev/null
wait $pid; rc1=$?
pid=""
[ $rc1 = 1 ] && grep -q "interrupted by SIGTERM" run1.err \
  && ok "SIGTERM stops the sweep: exit 1, $(grep -o 'interrupted by SIGTERM[^;]*' run1.err | head -1)" \
  || bad "run 1: exit $rc1: $(tail -3 run1.err)"
[ -z "$(find sw -name '*.tmp' -o -name '*.part' -o -name .wallload.lock)" ] \
  && ok "run 1 left no temporary file or lock" || bad "run 1 left $(find sw -name '*.tmp' -o -name '*.part' -o -name .wallload.lock)"
# which cases run 1 finished, from its sweep.csv
done1=$(python3 -c "
import csv,sys
print(' '.join(r['case'] for r in csv.DictReader(open('sw/sweep.csv')) if r['status'] == 'complete'))")
n1=$(wc -w <<<"$done1")
[ "$n1" -ge 1 ] && [ "$n1" -lt 4 ] && ok "run 1 finished cases: $done1" \
  || bad "run 1 finished $n1 cases ('$done1'); expected 1 to 3 (kill too late or too early)"

# run 2 continues
"$bin" "${ARGS[@]}" -o sw >run2.out 2>run2.err; rc2=$?
[ $rc2 = 0 ] && ok "run 2 completes" || bad "run 2: exit $rc2: $(tail -3 run2.err)"
for i in 0 1 2 3; do
  k=$((i+1))
  ran1=$(grep -c "case $k/4 .*: running" run1.err)
  ran2=$(grep -c "case $k/4 .*: running" run2.err)
  reused2=$(grep -c "case $k/4 .*: reused" run2.err)
  if grep -qw "$i" <<<"$done1"; then
    [ "$ran1" = 1 ] && [ "$ran2" = 0 ] && [ "$reused2" = 1 ] \
      && ok "case $i: ran in run 1, read back in run 2" \
      || bad "case $i (done in run 1): run 1 ran it $ran1x, run 2 ran it $ran2x, reused $reused2x"
  else
    [ "$ran2" = 1 ] && [ "$reused2" = 0 ] \
      && ok "case $i: finished in run 2 (started in run 1: $ran1)" \
      || bad "case $i (not done in run 1): run 2 ran it $ran2 x, reused $reused2 x"
  fi
done
# sweep.csv as the uninterrupted sweep's, but for the runtime
if [ "$(sweep_csv_sans_runtime sw/sweep.csv)" = "$(sweep_csv_sans_runtime whole/sweep.csv)" ]; then
  ok "sweep.csv equals the uninterrupted sweep's (runtime aside)"
else
  bad "sweep.csv differs from the uninterrupted sweep's:"; diff <(sweep_csv_sans_runtime sw/sweep.csv) <(sweep_csv_sans_runtime whole/sweep.csv) | head -5
fi
# run 3: nothing left to do; all read back
"$bin" "${ARGS[@]}" -o sw >/dev/null 2>run3.err
[ "$(grep -c ': reused' run3.err)" = 4 ] && ! grep -q ": running" run3.err \
  && ok "run 3 reads back all 4 cases" || bad "run 3: $(grep -c ': reused' run3.err) reused"
# changed inputs (another end time, short: the cases' results are not compared): every case
# runs again
"$bin" "${ARGS[@]}" -o sw --end-time 0.1 >/dev/null 2>run4.err
[ "$(grep -c ': running' run4.err)" = 4 ] && ! grep -q ": reused" run4.err \
  && ok "with other inputs (--end-time) every case runs again" \
  || bad "run 4: $(grep -c ': running' run4.err) run, $(grep -c ': reused' run4.err) reused"
# a second sweep into the same directory while one runs is refused
"$bin" "${ARGS[@]}" -o sw --end-time 0.15 >/dev/null 2>run5.err &
pid=$!
for _ in $(seq 1 200); do [ -e sw/.wallload.lock ] && break; sleep 0.02; done
out=$("$bin" "${ARGS[@]}" -o sw 2>&1); rc=$?
kill -TERM $pid 2>/dev/null; wait $pid; pid=""
[ $rc = 2 ] && grep -q "being written by wallload process" <<<"$out" \
  && ok "a second sweep into the same directory is refused: exit 2" || bad "second sweep: exit $rc: $out"
# a directory that is not a sweep's is refused
mkdir other && echo x >other/notes.txt
out=$("$bin" "${ARGS[@]}" -o other 2>&1); rc=$?
[ $rc = 2 ] && grep -q "not a sweep's" <<<"$out" && ok "a foreign directory is refused: exit 2" \
  || bad "foreign directory: exit $rc: $out"
exit $fail
