#!/usr/bin/env bash
# validate_parallel.sh: every `wallload validate` case at once, each its own
# process with one thread (the cases are small; one thread each fills a
# many-core machine with no barrier overhead), for reference/RESULTS.md.
#   bench/validate_parallel.sh BIN OUTDIR [LADDER] [CASE...]
# Writes OUTDIR/<case>/validation.json|csv|pdf and OUTDIR/<case>.log;
# bench/validate_table.py OUTDIR turns them into RESULTS.md's tables.
# On the device machine: bench/assess_e2e.sh pack here, then run with carry
# [".e2e"] and BIN=.e2e/wallload (LD_LIBRARY_PATH=.e2e/lib).
set -u
bin=$1 out=$2 ladder=${3:-3}
shift 3 2>/dev/null || shift $#
mkdir -p "$out"
if [ $# -eq 0 ]; then
  set -- $("$bin" validate --list | awk 'NF {print $1}')
fi
for c in "$@"; do
  ( a=$(date +%s)
    "$bin" validate "$c" --ladder "$ladder" --threads 1 -o "$out/$c" >"$out/$c.log" 2>&1
    echo "== $c rc=$? wall=$(( $(date +%s) - a )) s" ) &
done
wait
