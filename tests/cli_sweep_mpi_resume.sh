#!/usr/bin/env bash
# cli_sweep_mpi_resume.sh: a 2-rank sweep whose mpirun is killed (SIGTERM:
# Open MPI passes it on, then kills the ranks) after its first case
# finished, run again, finishes every case exactly once over the two runs
# (issue 21): the cases whose marker (sweep-case.txt, written last) the
# first run left are read back, the others run once, and sweep.csv then
# has every case complete.
#
# usage: cli_sweep_mpi_resume.sh WALLLOAD SOURCE_DIR
set -u
bin=$1; src=$2
. "$src/tests/sweep_lib.sh"
sweep_mpi_setup
work=$(mktemp -d)
pid=""
# The clean-up runs in this shell only: a background child signalled
# before it execs is still a copy of this shell, runs the trap, and would
# delete the work directory under the rest of the test (its $$ and even
# $BASHPID read as this shell's then; a new sh's parent does not).
trap 'if [ "$(exec sh -c "echo \$PPID")" = "$$" ]; then [ -n "$pid" ] && kill -9 $pid 2>/dev/null; rm -rf "$work"; fi' EXIT
cd "$work" || exit 1
cp "$src/tests/scenarios/sweep/tiny-sweep.yaml" .
ARGS=(sweep tiny-sweep.yaml --threads 1 --backend cpu -o sw)
# the sanitizers' build (WL_TEST_QUICK) runs a third of the cases' time: a
# case still takes seconds there, longer than the kill's 0.3 s
[ -n "${WL_TEST_QUICK:-}" ] && ARGS+=(--end-time 0.1)

# run 1, its mpirun killed once a case has finished
"${mpi[@]}" "$bin" "${ARGS[@]}" >run1.out 2>run1.err &
pid=$!
for _ in $(seq 1 1200); do
  ls sw/cases/*/sweep-case.txt >/dev/null 2>&1 && break
  sleep 0.05
done
sleep 0.3
kill -TERM $pid 2>/dev/null
wait $pid; rc1=$?
pid=""
[ $rc1 != 0 ] && ok "run 1 stopped: mpirun exit $rc1" || bad "run 1 was not stopped (exit 0): kill too late"
# what run 1 finished: the cases with a marker
done1=""
for i in 0 1 2 3; do ls sw/cases/00${i}_*/sweep-case.txt >/dev/null 2>&1 && done1="$done1 $i"; done
n1=$(wc -w <<<"$done1")
[ "$n1" -ge 1 ] && [ "$n1" -lt 4 ] && ok "run 1 finished cases:$done1" \
  || bad "run 1 finished $n1 cases ('$done1'); expected 1 to 3"

# run 2 continues
"${mpi[@]}" "$bin" "${ARGS[@]}" >run2.out 2>run2.err; rc2=$?
[ $rc2 = 0 ] && ok "run 2 completes" || bad "run 2: exit $rc2: $(tail -5 run2.err)"
for i in 0 1 2 3; do
  k=$((i+1))
  ran2=$(grep -c "case $k/4 .*: running on rank" run2.err)
  reused2=$(grep -c "case $k/4 .*: reused" run2.err)
  if grep -qw "$i" <<<"$done1"; then
    [ "$ran2" = 0 ] && [ "$reused2" = 1 ] && ok "case $i: finished in run 1, read back in run 2" \
      || bad "case $i (finished in run 1): run 2 ran it $ran2 times, read it back $reused2 times"
  else
    [ "$ran2" = 1 ] && [ "$reused2" = 0 ] && ok "case $i: run once, in run 2" \
      || bad "case $i (not finished in run 1): run 2 ran it $ran2 times, read it back $reused2 times"
  fi
done
python3 - sw/sweep.csv <<'PY' || fail=$((fail+1))
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
st = [r["status"] for r in rows]
if st == ["complete"] * 4:
    print("PASS sweep.csv: all 4 cases complete")
else:
    print("FAIL sweep.csv statuses: %s" % st); sys.exit(1)
PY
[ -s sw/sweep.pdf ] && ok "sweep.pdf drawn" || bad "sw/sweep.pdf missing"
[ ! -e sw/.wallload.lock ] && ok "no lock left" || bad "the lock was left"
exit $fail
