#!/usr/bin/env bash
# cli_signals.sh: signals at every moment of `wallload assess` (issue 18).
#
# SIGTERM (and SIGHUP, SIGINT) stop a run as documented in assess.h: while
# stepping, the case stops at its next output time and what it computed is
# written (summary.json status `interrupted`); while the results are
# written, or the report rendered, that writing finishes (statuses
# `complete`) and no further case starts; exit 1 with a message naming the
# signal and the phase ("while stepping", "while writing the results",
# "while rendering the report"). Before wallload installs its handlers, or
# after it puts the defaults back, the signal's default action ends the
# process (exit 143 = 128 + SIGTERM): then the output directory holds no
# files, or complete ones. SIGKILL can come at any moment: never a
# half-written final file; its temporary files and lock are cleaned by the
# next run.
#
# Phases are hit two ways: a sweep of delays over the whole run (its length
# measured first), and kills triggered by the run's own files appearing
# (the snapshots' .tmp while stepping, results.h5.tmp while writing,
# report.pdf.part while rendering). Every run's phase, exit code and
# statuses are printed. WL_TEST_QUICK=1 (the sanitizer build) runs a shorter
# case and fewer delays.
#
# usage: cli_signals.sh WALLLOAD SOURCE_DIR
set -u
bin=$1; src=$2
fail=0
ok() { echo "PASS $1"; }
bad() { echo "FAIL $1"; fail=$((fail+1)); }
for tool in python3 pdfinfo pdftotext; do
  command -v "$tool" >/dev/null || { echo "SKIP: $tool not installed"; exit 77; }
done
work=$(mktemp -d)
pids=""
# The clean-up runs in this shell only: a background child signalled
# before it execs is still a copy of this shell, runs the trap, and would
# delete the work directory under the rest of the test (its $$ and even
# $BASHPID read as this shell's then; a new sh's parent does not).
trap 'if [ "$(exec sh -c "echo \$PPID")" = "$$" ]; then for p in $pids; do kill -9 $p 2>/dev/null; done; rm -rf "$work"; fi' EXIT
cd "$work" || exit 1
cp "$src/tests/scenarios/good/tiny.yaml" tiny.yaml
if [ "${WL_TEST_QUICK:-0}" = 1 ]; then
  # the sanitizers' run: the flume at twice the spacing as well (a
  # sanitized run is 13 times slower; the phases are the same)
  sed -i 's/dp: 0.02 m/dp: 0.04 m/' tiny.yaml
  T_END=0.05; N_DELAYS=4; N_KILL=1; KILL_AT="results.h5.tmp report.pdf.part"
else
  T_END=0.2; N_DELAYS=9; N_KILL=3; KILL_AT="results.h5.tmp summary.json.tmp report.pdf.part"
fi
ARGS=(assess tiny.yaml --threads 1 --end-time $T_END)

# check_dir DIR LABEL [--allow-temporary]: every final file complete (and,
# without the flag, no temporary file or lock), results.h5 read back by
# `wallload report`. Prints the cases' statuses.
check_dir() {
  local d=$1 label=$2 flag=${3:-} p
  p=$(python3 "$src/tests/results_dir_check.py" "$d" --statuses $flag 2>&1) || { bad "$label: $p"; return 1; }
  statuses=$p
  if [ -e "$d/results.h5" ]; then
    if ! "$bin" report "$d/results.h5" -o "$work/check.pdf" >/dev/null 2>"$work/check.err"; then
      bad "$label: results.h5 does not read back: $(cat "$work/check.err")"; return 1
    fi
    if pdftotext "$work/check.pdf" - 2>/dev/null | grep -q "(HDF5)"; then
      bad "$label: a particle snapshot file does not open"; return 1
    fi
  fi
  return 0
}

# start OUT: assess into OUT in the background; sets $pid
start() {
  rm -rf "$1"
  "$bin" "${ARGS[@]}" -o "$1" >"$1.out" 2>"$1.err" &
  pid=$!
  pids="$pids $pid"
}

# when_exists PID FILE: wait (busy) until FILE exists or PID is gone
when_exists() {
  while kill -0 "$1" 2>/dev/null && [ ! -e "$2" ]; do :; done
}

declare -A phases=()
# after_report OUT: whether OUT/report.pdf was written before the last
# kill (signal_run's $killed_at).
after_report() {
  [ -e "$1/report.pdf" ] || return 1
  python3 -c "import os, sys; sys.exit(0 if os.stat('$1/report.pdf').st_mtime < $killed_at else 1)"
}

# judge LABEL OUT RC SIG: the exit code and message of a stopped run, and
# its files; records the phase hit.
judge() {
  local label=$1 out=$2 rc=$3 sig=$4 msg phase=""
  msg=$(grep "^wallload: " "$out.err" | grep -v "dp = \|convergence ladder" | tail -1)
  case "$msg" in
    *"interrupted by SIG$sig while stepping"*) phase=stepping ;;
    *"interrupted by SIG$sig while writing the results"*) phase="writing results" ;;
    *"interrupted by SIG$sig while rendering the report"*) phase="rendering the report" ;;
    *"interrupted by SIG$sig after the results were written"*) phase="after the results" ;;
  esac
  if [ $rc = 1 ] && [ -n "$phase" ]; then
    :
  elif [ $rc = $((128 + $(kill -l "$sig"))) ]; then
    # the default action: before the handlers are installed (no results
    # yet) or after they are restored (all written)
    if [ -e "$out/summary.json" ]; then phase="after the run (default action)"; else phase="before the run (default action)"; fi
  elif [ $rc = 0 ] && { [ "$sent" = 0 ] || [ "$maybe_before" = 1 ]; }; then
    phase="after the exit (not sent)"
  elif [ $rc = 0 ] && [ -n "${WL_TEST_QUICK:-}" ] && after_report "$out"; then
    # The sanitizer build only: its leak check runs as the process exits,
    # with every signal blocked (LeakSanitizer stops the world), for a good
    # part of a second; a signal sent then is never delivered and the run
    # ends 0. Accepted only when report.pdf, the last file a run writes,
    # was complete before the kill: the run had nothing left to stop. The
    # Release build has no such window (a signal there ends the run with 1
    # or 128 + SIG, never 0).
    phase="in the sanitizer's exit (not delivered)"
  else
    bad "$label: exit $rc, message: ${msg:-none}: $(tail -2 "$out.err")"
    return
  fi
  phases[$phase]=1
  check_dir "$out" "$label" || return
  case "$phase" in
    stepping)
      grep -q "=interrupted" <<<"$statuses" || { bad "$label: stepping, but no case interrupted: $statuses"; return; } ;;
    "writing results"|"rendering the report"|"after the results"|"in the sanitizer's exit (not delivered)")
      grep -q "=interrupted\|=failed" <<<"$statuses" && { bad "$label: $phase, but statuses $statuses"; return; } ;;
  esac
  ok "$label: exit $rc, $phase${statuses:+ ($statuses)}${msg:+: ${msg#wallload: }}"
}

# signal_run SIG: sends SIG to $pid; sets $sent to 0 where the run had
# already exited. A run that has exited but is not yet reaped (a zombie,
# state Z) still takes a kill without error, and it can exit between any
# look and the kill: so it is looked at before and after. A run that reads
# as a zombie within 30 ms of the kill and then exits 0 had finished, or
# was inside its exit, before the signal came (a handled signal ends a run
# with 1, the default action with 128 + SIG, never 0).
signal_run() {
  sent=1
  # the state read by bash's own `read` (no fork between the look and the
  # kill: an awk there took milliseconds, longer than the results take to
  # write, and the aimed kills missed that phase ten times running)
  local st=""
  { read -r _ _ st _ </proc/$pid/stat; } 2>/dev/null
  [ "$st" = Z ] && sent=0
  killed_at=$EPOCHREALTIME
  [ $sent = 1 ] && { kill -s "$1" $pid 2>/dev/null || sent=0; }
  # after the kill there is time to look: a run caught inside its exit (the
  # kernel no longer delivers signals there) reads Z a moment later
  st=""
  for _ in 1 2 3; do
    { read -r _ _ st _ </proc/$pid/stat; } 2>/dev/null
    [ "$st" = Z ] && break
    sleep 0.01
  done
  [ "$st" = Z ] && maybe_before=1 || maybe_before=0
}

# stop_at LABEL SIG DELAY: a run signalled after DELAY seconds
stop_at() {
  local label=$1 sig=$2 delay=$3 out=run
  start $out
  sleep "$delay"
  # a run that has already exited but is not yet reaped (a zombie, state Z)
  # still takes a kill without error: its signal is not sent
  signal_run "$sig"
  wait $pid; local rc=$?
  judge "$label" $out $rc "$sig"
}

# stop_when LABEL SIG FILE: a run signalled as soon as FILE appears in it
stop_when() {
  local label=$1 sig=$2 file=$3 out=run
  start $out
  when_exists $pid "$out/$file"
  signal_run "$sig"
  wait $pid; local rc=$?
  judge "$label" $out $rc "$sig"
}

# The run's length, undisturbed.
t0=$EPOCHREALTIME
if ! "$bin" "${ARGS[@]}" --quiet -o full >/dev/null 2>full.err; then
  bad "the undisturbed run failed: $(tail -2 full.err)"
  exit 1
fi
t1=$EPOCHREALTIME
dur=$(python3 -c "print('%.3f' % ($t1 - $t0))")
check_dir full "undisturbed run" && ok "undisturbed run: $dur s ($statuses)"

# SIGTERM swept over the run: N_DELAYS delays from 0 to 1.1 times its length
# (a loaded machine runs slower than the measurement).
for k in $(seq 0 $((N_DELAYS - 1))); do
  d=$(python3 -c "print('%.3f' % (1.1 * $dur * $k / ($N_DELAYS - 1)))")
  stop_at "SIGTERM after $d s" TERM "$d"
done

# SIGTERM aimed at each phase by the files the run writes there (up to ten
# tries each, stopping at the first hit: the file may come and go between
# two looks, and on a loaded machine the signal can land after the phase;
# three tries missed the results' writing once in a fresh-Debian run).
for aim in "stepping:particles_solitary.h5.tmp" "writing results:results.h5.tmp" \
           "rendering the report:report.pdf.part"; do
  want=${aim%%:*}; file=${aim#*:}
  [ -n "${phases[$want]:-}" ] && continue # the sweep met it already
  for try in $(seq 10); do
    stop_when "SIGTERM when $file appears (try $try)" TERM "$file"
    [ -n "${phases[$want]:-}" ] && break
  done
done
stop_when "SIGHUP when particles_explosion.h5.tmp appears" HUP particles_explosion.h5.tmp

# Every phase hit, by the sweep or the aimed kills.
for want in stepping "writing results" "rendering the report"; do
  [ -n "${phases[$want]:-}" ] && ok "SIGTERM met while $want" || bad "SIGTERM never met while $want"
done
echo "phases hit: $(printf '%s; ' "${!phases[@]}")"

# SIGKILL: never a half-written final file; the next run cleans the
# temporary files and the lock it left, and completes.
kill9() {
  local label=$1 rc left
  wait $pid 2>/dev/null
  left=$(ls -A run | grep '\.tmp$\|\.part$\|\.wallload\.lock$' | tr '\n' ' ')
  check_dir run "$label" --allow-temporary || return
  if "$bin" "${ARGS[@]}" --quiet --force -o run >/dev/null 2>run.err; then
    check_dir run "$label, the next run" && ok "$label: final files complete (left: ${left:-nothing}); the next run cleans up and completes"
  else
    bad "$label: the next run failed: $(tail -2 run.err)"
  fi
}
for k in $(seq 1 $N_KILL); do
  d=$(python3 -c "print('%.3f' % ($dur * $k / ($N_KILL + 1)))")
  start run; sleep "$d"; kill -9 $pid 2>/dev/null
  kill9 "SIGKILL after $d s"
done
for file in $KILL_AT; do
  start run; when_exists $pid "run/$file"; kill -9 $pid 2>/dev/null
  kill9 "SIGKILL when $file appears"
done

echo "$fail failure(s)"
exit $((fail > 0))
