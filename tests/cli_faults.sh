#!/usr/bin/env bash
# cli_faults.sh: `wallload assess` and `wallload report` on a disk that
# refuses writes (issue 18). Whatever the point of failure, the run exits 1
# (never 0, never a crash such as 139 or 134), stderr names the file and the
# system's reason, every final file left is complete (results.h5 opens,
# JSON parses, CSV rows are whole, the XDMF index parses, the PDF passes
# pdfinfo), no temporary file (*.tmp, *.part) or lock is left by the failed
# run itself, and a directory's previous complete results survive a new run
# that fails.
#
#  1. RLIMIT_FSIZE (ulimit -f, SIGXFSZ ignored): needs nothing, always runs.
#     "File too large" for the particle snapshots, results.h5 and the PDF.
#  2. standard output on /dev/full.
#  3. A full file system: a small tmpfs mounted in a private mount namespace
#     (unshare -m as root, else unshare -rm in a user namespace), the run
#     aimed at each of its files in turn by pre-filling the tmpfs so that the
#     free space runs out there (the points computed from a calibration run's
#     file sizes). Where no tmpfs can be mounted, parts 1 and 2 still run and
#     the test exits 77 (skipped) when they pass.
#
# usage: cli_faults.sh WALLLOAD SOURCE_DIR   (ctest; WL_TEST_QUICK=1 under ASan)
set -u
bin=$1; src=$2
self=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
fail=0
ok() { echo "PASS $1"; }
bad() { echo "FAIL $1"; fail=$((fail+1)); }
for tool in python3 pdfinfo pdftotext; do
  command -v "$tool" >/dev/null || { echo "SKIP: $tool not installed"; exit 77; }
done

if [ "${3:-}" = --tmpfs ]; then
  work=$4 # inside the mount namespace: part 3 only (the helpers below are shared)
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
cd "$work" || exit 1

# The scenarios: tiny.yaml as in cli_assess.sh (two cases), one.yaml its
# solitary case alone, many.yaml sampled so often that results.h5 outgrows
# the particle snapshots (so a file-size limit can stop results.h5 first).
cp "$src/tests/scenarios/good/tiny.yaml" tiny.yaml
sed '/explosion:/d; s/scenario: tiny/scenario: one/' tiny.yaml > one.yaml
sed '/explosion:/d; s/scenario: tiny/scenario: many/; s/dp: 0.02 m/dp: 0.05 m/;
     s/output_interval: 0.02 s/output_interval: 0.00005 s/' tiny.yaml > many.yaml
T_END=0.05 # seconds of flume time: a few snapshots, a fraction of a second in Release

# check_dir DIR LABEL: tests/results_dir_check.py (every final file
# complete, no temporary file or lock left, one run's files), and results.h5 read back by `wallload
# report` (HDF5 opens it; a particle file that does not open shows in the
# rendered text as "(HDF5)"); h5dump -H on every HDF5 file where installed.
check_dir() {
  local d=$1 label=$2 p f
  p=$(python3 "$src/tests/results_dir_check.py" "$d" 2>&1) || { bad "$label: $p"; return 1; }
  if [ -e "$d/results.h5" ]; then
    if ! "$bin" report "$d/results.h5" -o "$work/check.pdf" >/dev/null 2>"$work/check.err"; then
      bad "$label: results.h5 does not read back: $(cat "$work/check.err")"; return 1
    fi
    if pdftotext "$work/check.pdf" - 2>/dev/null | grep -q "(HDF5)"; then
      bad "$label: a particle snapshot file does not open"; return 1
    fi
  fi
  if command -v h5dump >/dev/null; then
    for f in "$d"/*.h5; do
      [ -e "$f" ] || continue
      h5dump -H "$f" >/dev/null 2>&1 || { bad "$label: h5dump -H $(basename "$f") fails"; return 1; }
    done
  fi
  return 0
}

# crash RC: 1 when RC is a signal's death or an abort (>= 128), else 0.
crash() { [ "$1" -ge 128 ]; }

# sums DIR: the checksums of DIR's files (the previous results).
sums() { (cd "$1" && md5sum -- * 2>/dev/null | sort); }

if [ "${3:-}" != --tmpfs ]; then
  # ---- 1. RLIMIT_FSIZE ------------------------------------------------------------
  # run_limited KB OUT ARGS...: wallload ARGS with files limited to KB
  # kilobytes and SIGXFSZ ignored (a write past the limit then fails with
  # EFBIG, "File too large").
  run_limited() {
    local kb=$1; shift
    (ulimit -f "$kb"; trap '' XFSZ; exec "$bin" "$@")
  }
  # the previous complete results of tiny.yaml
  "$bin" assess tiny.yaml --quiet --end-time $T_END -o fs >/dev/null 2>&1 || bad "fsize: the first run failed"
  before=$(sums fs)
  # particle snapshots (about 480 KB a case) over a 64 KB limit
  msg=$(run_limited 64 assess tiny.yaml --quiet --force --end-time $T_END -o fs 2>&1 >/dev/null); rc=$?
  if [ $rc = 1 ] && grep -q "fs/particles_solitary.h5: .*File too large" <<<"$msg"; then
    ok "fsize 64 KB: exit 1, names the snapshot file and the reason: $msg"
  else
    bad "fsize 64 KB: exit $rc: $msg"
  fi
  check_dir fs "fsize 64 KB" && ok "fsize 64 KB: every file complete, nothing temporary left"
  [ "$(sums fs)" = "$before" ] && ok "fsize 64 KB: the previous complete results are unchanged" \
    || bad "fsize 64 KB: the previous results changed"
  # results.h5 (1.2 MB; snapshots 0.7 MB) over a 1000 KB limit
  "$bin" assess many.yaml --quiet --end-time 0.3 -o fsm >/dev/null 2>&1 || bad "fsize: many.yaml failed"
  before=$(sums fsm)
  msg=$(run_limited 1000 assess many.yaml --quiet --force --end-time 0.3 -o fsm 2>&1 >/dev/null); rc=$?
  if [ $rc = 1 ] && grep -q "fsm/results.h5: .*File too large" <<<"$msg"; then
    ok "fsize 1000 KB: exit 1, names results.h5 and the reason: $msg"
  else
    bad "fsize 1000 KB: exit $rc: $msg"
  fi
  check_dir fsm "fsize 1000 KB" && ok "fsize 1000 KB: every file complete, nothing temporary left"
  [ "$(sums fsm)" = "$before" ] && ok "fsize 1000 KB: the previous complete results are unchanged" \
    || bad "fsize 1000 KB: the previous results changed"
  # the PDF (over 100 KB) of `wallload report` over a 32 KB limit: no file,
  # then the previous one kept
  msg=$(run_limited 32 report fs/results.h5 -o new.pdf 2>&1 >/dev/null); rc=$?
  [ $rc = 1 ] && grep -q "new.pdf: .*File too large" <<<"$msg" && [ ! -e new.pdf ] && [ ! -e new.pdf.part ] \
    && ok "fsize 32 KB: report exits 1 naming the PDF and the reason, leaves no file: $msg" \
    || bad "fsize 32 KB: report exit $rc, files: $(ls new.pdf* 2>/dev/null): $msg"
  cp fs/report.pdf old.pdf
  sum=$(md5sum < old.pdf)
  msg=$(run_limited 32 report fs/results.h5 -o old.pdf 2>&1 >/dev/null); rc=$?
  [ $rc = 1 ] && [ "$(md5sum < old.pdf)" = "$sum" ] && [ ! -e old.pdf.part ] \
    && ok "fsize 32 KB: the previous PDF is kept" || bad "fsize 32 KB: previous PDF: exit $rc: $msg"

  # ---- 2. standard output on /dev/full ---------------------------------------------
  rm -rf full
  "$bin" assess one.yaml --end-time $T_END --threads 1 -o full >/dev/full 2>full.err; rc=$?
  if crash $rc; then
    bad "stdout on /dev/full: crashed (exit $rc): $(tail -3 full.err)"
  else
    check_dir full "stdout on /dev/full" && ok "stdout on /dev/full: no crash (exit $rc), the files complete"
    if [ $rc = 1 ] && grep -qi "standard output\|stdout" full.err; then
      ok "stdout on /dev/full: exit 1, says so: $(tail -1 full.err)"
    else
      bad "stdout on /dev/full: exit $rc, the lost case summary not reported: $(tail -1 full.err)"
    fi
  fi

  # ---- 3. a full file system (tmpfs) ------------------------------------------------------
  if [ "$(id -u)" = 0 ] && unshare -m true 2>/dev/null; then
    ns="unshare -m"
  elif unshare -rm true 2>/dev/null; then
    ns="unshare -rm"
  else
    ns=""
  fi
  tmpfs_rc=77
  if [ -n "$ns" ]; then
    echo "full file system: a tmpfs in a private mount namespace ($ns)"
    $ns bash "$self" "$bin" "$src" --tmpfs "$work"; tmpfs_rc=$?
  fi
  if [ $tmpfs_rc = 77 ]; then
    echo "SKIP full file system: no private mount namespace with a tmpfs here (not root, no user namespaces)"
    [ $fail = 0 ] && exit 77
  elif [ $tmpfs_rc != 0 ]; then
    fail=$((fail + tmpfs_rc))
  fi
  echo "$fail failure(s)"
  exit $((fail > 0))
fi

# ---- 3. inside the mount namespace: a full tmpfs ------------------------------------------
mnt=$work/mnt
mkdir -p "$mnt"
SIZE_KB=4096
mount -t tmpfs -o size=${SIZE_KB}k tmpfs "$mnt" 2>/dev/null || { echo "SKIP: cannot mount a tmpfs: $(mount -t tmpfs -o size=${SIZE_KB}k tmpfs "$mnt" 2>&1)"; exit 77; }
echo "tmpfs of $SIZE_KB KB at $mnt"

# alloc FILE: kilobytes the file takes on the tmpfs (whole pages)
alloc() { [ -e "$1" ] && echo $(( $(stat -c '%b*%B' "$1") / 1024 )) || echo 0; }

# fill FREE_KB: fill the tmpfs so that FREE_KB kilobytes stay free
fill() {
  rm -f "$mnt/filler"
  local used free
  free=$(df -k --output=avail "$mnt" | tail -1)
  [ "$1" -lt "$free" ] && head -c $(( (free - $1) * 1024 )) /dev/zero > "$mnt/filler" 2>/dev/null
  return 0
}

# run_full LABEL FREE_KB SCENARIO OUT [--force]: assess into $mnt/OUT with
# FREE_KB free; exit 1 wanted, with the reason and a file of the output
# directory in the message; then every file left complete. Sets $named to
# the file the message names first.
named=""
run_full() {
  local label=$1 free=$2 scen=$3 out=$4 force=${5:-} rc msg
  fill "$free"
  msg=$("$bin" assess "$scen" --quiet --threads 1 --end-time $T_END $force -o "$mnt/$out" 2>&1 >/dev/null); rc=$?
  rm -f "$mnt/filler"
  named=$(grep -o "$mnt/$out/[A-Za-z0-9_.]*" <<<"$msg" | head -1); named=${named##*/}
  if crash $rc; then
    bad "$label ($free KB free): crashed, exit $rc: $msg"
  elif [ $rc != 1 ]; then
    bad "$label ($free KB free): exit $rc, wanted 1: $msg"
  elif ! grep -q "No space left on device" <<<"$msg" || [ -z "$named" ]; then
    bad "$label ($free KB free): the message lacks the file or the reason: $msg"
  else
    ok "$label ($free KB free): exit 1, names $named: ${msg#wallload: }"
  fi
  check_dir "$mnt/$out" "$label" && ok "$label: every file left complete, nothing temporary left ($(ls "$mnt/$out" 2>/dev/null | tr '\n' ' '))"
}

# Calibration: one.yaml with room to spare; each file's pages. The run
# writes, in order: the lock (a page), the snapshots, their XDMF index, then
# results.h5, the two CSV files and summary.json (moved into place
# together), then report.pdf.
rm -rf "$mnt/cal"
"$bin" assess one.yaml --quiet --threads 1 --end-time $T_END -o "$mnt/cal" >/dev/null 2>&1 || bad "calibration run failed"
L=4
S=$(alloc "$mnt/cal/particles_solitary.h5")
X=$(alloc "$mnt/cal/particles_solitary.xmf")
R=$(alloc "$mnt/cal/results.h5")
C1=$(alloc "$mnt/cal/solitary_wall.csv"); C2=$(alloc "$mnt/cal/solitary_gauges.csv")
J=$(alloc "$mnt/cal/summary.json"); P=$(alloc "$mnt/cal/report.pdf")
rm -rf "$mnt/cal"
B=$((L + S + X))
T=$((B + R + C1 + C2 + J + P))
echo "calibration (KB): lock $L, snapshots $S, index $X, results.h5 $R, CSV $C1 + $C2, summary.json $J, report.pdf $P; $T in all"
[ "$T" -gt 100 ] && [ "$T" -lt $((SIZE_KB - 200)) ] || { bad "calibration: total $T KB"; echo "$fail failure(s)"; exit 1; }

# The sweep: free space just short of each file in turn.
declare -A hit=()
points=(
  "lock:0"
  "snapshots:$(( (S / 2) / 4 * 4 ))"
  "snapshot index:$((B - 4))"
  "results.h5:$((B + R - 4))"
  "first CSV:$((B + R))"
  "second CSV:$((B + R + C1))"
  "summary.json:$((B + R + C1 + C2))"
  "report.pdf at once:$((B + R + C1 + C2 + J))"
  "report.pdf at its end:$((T - 4))"
)
for pt in "${points[@]}"; do
  label=${pt%%:*}; free=${pt##*:}
  rm -rf "$mnt/out"
  run_full "aimed at $label" "$free" one.yaml out
  [ -n "$named" ] && hit[$named]=1
  # the next run into the directory, with room: complete, nothing stray
  # (under WL_TEST_QUICK, the sanitizer build, after the first point only)
  [ "${WL_TEST_QUICK:-0}" = 1 ] && [ "$label" != lock ] && continue
  if msg=$("$bin" assess one.yaml --quiet --threads 1 --end-time $T_END --force -o "$mnt/out" 2>&1 >/dev/null); then
    check_dir "$mnt/out" "aimed at $label, the next run with room" && ok "aimed at $label: the next run with room completes"
  else
    bad "aimed at $label: the next run with room failed: $msg"
  fi
done
rm -rf "$mnt/out"
fill $((T + 16))
"$bin" assess one.yaml --quiet --threads 1 --end-time $T_END -o "$mnt/out" >/dev/null 2>"$work/fit.err"; rc=$?
rm -f "$mnt/filler"
[ $rc = 0 ] && check_dir "$mnt/out" "room for all" && ok "$((T + 16)) KB free: exit 0, every file complete" \
  || bad "$((T + 16)) KB free: exit $rc: $(cat "$work/fit.err")"
echo "files the failures named: ${!hit[*]}"
for want in .wallload.lock particles_solitary.h5 particles_solitary.xmf results.h5 summary.json report.pdf; do
  [ -n "${hit[$want]:-}" ] && ok "a full disk was met while writing $want" || bad "no point of the sweep failed on $want"
done
[ -n "${hit[solitary_wall.csv]:-}${hit[solitary_gauges.csv]:-}" ] && ok "a full disk was met while writing a CSV file" \
  || bad "no point of the sweep failed on a CSV file"

# Previous complete results (tiny.yaml, both cases) and a new run into them
# that fails: before anything of the new run is moved into place every
# previous file is unchanged; after its first case is, the directory holds
# the new run's files alone.
rm -rf "$mnt/prev"
"$bin" assess tiny.yaml --quiet --threads 1 --end-time $T_END -o "$mnt/prev" >/dev/null 2>&1 || bad "previous run failed"
before=$(sums "$mnt/prev")
S1=$(alloc "$mnt/prev/particles_solitary.h5"); X1=$(alloc "$mnt/prev/particles_solitary.xmf")
for pt in "its snapshots:$(( (S1 / 2) / 4 * 4 ))" "its results.h5:$((L + S1 + X1 + 4))"; do
  label=${pt%%:*}; free=${pt##*:}
  run_full "previous results, new run stopped in $label" "$free" tiny.yaml prev --force
  [ "$(sums "$mnt/prev")" = "$before" ] && ok "previous results, new run stopped in $label: every previous file unchanged" \
    || bad "previous results, new run stopped in $label: previous files changed"
done
# A fresh directory, two cases, the disk full in the second case's
# snapshots: the first case's files stay, with a report of them.
rm -rf "$mnt/two"
S2=$(alloc "$mnt/prev/particles_explosion.h5")
rm -rf "$mnt/prev"
run_full "two cases, the second one's snapshots" $((L + S1 + X1 + R + C1 + C2 + J + S2 / 2 / 4 * 4)) tiny.yaml two
[ -s "$mnt/two/results.h5" ] && [ -s "$mnt/two/report.pdf" ] && ! [ -e "$mnt/two/explosion_wall.csv" ] \
  && ok "two cases, the second one's snapshots: the first case's results and their report stay" \
  || bad "two cases, the second one's snapshots: left $(ls "$mnt/two" | tr '\n' ' ')"
echo "$fail failure(s) on the tmpfs"
exit $fail
