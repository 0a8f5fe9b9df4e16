#!/usr/bin/env bash
# cli_sweep_mpi.sh: `mpirun -np 2 wallload sweep` (issue 21) gives the same
# sweep.csv as one process, runtime aside (the cases are bit-identical
# whichever process runs them), every case run once, on both ranks; a bad
# option is one message and exit 2, not one per rank; a rank killed while it
# runs a case makes that case a failed row and the other cases still finish
# (mpirun --enable-recovery: without it, Open MPI ends the whole job when a
# rank dies; docs/sweep-mpi.md).
#
# The sweep is tests/scenarios/sweep/tiny-sweep.yaml (4 cases, about 1.5 s
# each on one core). Skipped (77) when wallload was built without MPI or
# mpirun is not installed.
#
# usage: cli_sweep_mpi.sh WALLLOAD SOURCE_DIR
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
# under the sanitizers (WL_TEST_QUICK) at twice the spacing: a sanitized
# run is 13 times slower, and the ranks' sharing is what is tested here
[ -n "${WL_TEST_QUICK:-}" ] && sed -i 's/dp: 0.02 m/dp: 0.04 m/' tiny-sweep.yaml
ARGS=(sweep tiny-sweep.yaml --threads 1 --backend cpu)

# one process: the reference (a shorter end time: the comparison holds at
# any, and the test's time on CI's 2 cores, or under the sanitizers'
# WL_TEST_QUICK, stays short)
tend=0.15; [ -n "${WL_TEST_QUICK:-}" ] && tend=0.05
"$bin" "${ARGS[@]}" --end-time $tend -o one >/dev/null 2>one.err \
  || bad "one-process sweep failed: $(tail -3 one.err)"

# two ranks
"${mpi[@]}" "$bin" "${ARGS[@]}" --end-time $tend -o two >two.out 2>two.err; rc=$?
[ $rc = 0 ] && ok "2 ranks: exit 0" || bad "2 ranks: exit $rc: $(tail -5 two.err)"
for f in sweep.csv sweep.h5 sweep.pdf; do
  [ -s "two/$f" ] && ok "two/$f written" || bad "two/$f missing"
done
[ -z "$(find two -name '*.tmp' -o -name '*.part' -o -name .wallload.lock)" ] \
  && ok "no temporary file or lock left" || bad "left: $(find two -name '*.tmp' -o -name '*.part' -o -name .wallload.lock)"
grep -q "shared among 2 MPI ranks" two.err && ok "the log says 2 ranks" || bad "no 'shared among 2 MPI ranks' in the log"
for k in 1 2 3 4; do
  n=$(grep -c "case $k/4 .*: running on rank [01]$" two.err)
  [ "$n" = 1 ] && ok "case $k ran once: $(grep -o "case $k/4 .*: running on rank [01]" two.err)" \
    || bad "case $k ran $n times"
done
grep -q "running on rank 0" two.err && grep -q "running on rank 1" two.err \
  && ok "both ranks ran cases" || bad "one rank ran every case: $(grep running two.err)"
[ "$(grep -c '^ *[0-3]  0' two.out)" = 4 ] && ok "rank 0 alone prints the table (4 rows)" \
  || bad "stdout has $(grep -c '^ *[0-3]  0' two.out) table rows, expected 4"
if [ "$(sweep_csv_sans_runtime two/sweep.csv)" = "$(sweep_csv_sans_runtime one/sweep.csv)" ]; then
  ok "sweep.csv of 2 ranks equals one process's (runtime aside)"
else
  bad "sweep.csv of 2 ranks differs from one process's:"; diff <(sweep_csv_sans_runtime two/sweep.csv) <(sweep_csv_sans_runtime one/sweep.csv) | head -6
fi

# a bad option: every rank refuses it, one message, exit 2
"${mpi[@]}" "$bin" sweep tiny-sweep.yaml --bogus >/dev/null 2>bad.err; rc=$?
[ $rc = 2 ] && [ "$(grep -c "unknown option '--bogus'" bad.err)" = 1 ] \
  && ok "a bad option under mpirun: exit 2, said once" \
  || bad "bad option: exit $rc, said $(grep -c "unknown option" bad.err) times"

# a rank killed mid-case: its case is a failed row, the others finish
# The cases run to their full 0.3 s here (a case must still be running when
# its rank is killed). The sanitizer build's quick run leaves this to the
# Release build: it is Open MPI's recovery and the failed row that rank 0
# writes (the same store code as above), and under the sanitizers it took
# half of this test's 80 s, with both of CI's cores held.
if [ -n "${WL_TEST_QUICK:-}" ]; then
  echo "lost rank: left to the Release build (WL_TEST_QUICK)"
  exit $fail
fi
"${mpi[@]}" --enable-recovery "$bin" "${ARGS[@]}" -o lost >lost.out 2>lost.err &
pid=$!
victim=""
for _ in $(seq 1 600); do
  grep -q "running on rank 1$" lost.err 2>/dev/null && victim=$(sed -n 's/^wallload: rank 1: pid \([0-9]*\) .*/\1/p' lost.err)
  [ -n "$victim" ] && break
  sleep 0.05
done
case_lost=$(sed -n 's|^wallload: case \([0-9]*\)/4 .*: running on rank 1$|\1|p' lost.err | head -1)
[ -n "$victim" ] && kill -9 "$victim" 2>/dev/null
wait $pid
pid=""
python3 - lost/sweep.csv "${case_lost:-0}" <<'PY' || fail=$((fail+1))
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
lost = int(sys.argv[2]) - 1
bad = 0
for i, r in enumerate(rows):
    want = "failed" if i == lost else "complete"
    if r["status"] != want:
        print("FAIL lost rank: case %d is %s, expected %s (%s)" % (i, r["status"], want, r["message"])); bad += 1
if not bad:
    print("PASS lost rank: case %d failed (%s), the other 3 complete" % (lost, rows[lost]["message"]))
sys.exit(1 if bad else 0)
PY
grep -q "rank 1 (pid $victim on .*) died while running this case" lost.err \
  && ok "the log names the lost rank" || bad "no 'rank 1 ... died' in the log: $(tail -4 lost.err)"
[ -s lost/sweep.pdf ] && ok "the envelopes are drawn without the lost case" || bad "lost/sweep.pdf missing"
exit $fail
