#!/usr/bin/env bash
# validate_parallel.sh: `wallload validate` cases side by side, each its own
# process with one thread (the cases are small; one thread each fills a
# many-core machine with no barrier overhead), for reference/RESULTS.md.
#   [JOBS=N] [INTEGRATOR=verlet] bench/validate_parallel.sh BIN OUTDIR [LADDER] [CASE...]
# JOBS: processes at once (default: the number of cores); INTEGRATOR: the
# time integrator of every run (validate --integrator; default symplectic);
# LADDER: levels of every case (default, or ''/empty: each case's own, 3 and
# the solitary cases 5);
# REF: the reference/ directory (validate --reference; default: the one the
# binary was built from, which a carried binary does not have). Writes
# OUTDIR/<case>/validation.json|csv|pdf and OUTDIR/<case>.log;
# bench/validate_table.py OUTDIR turns them into RESULTS.md's tables.
# On the device machine: bench/assess_e2e.sh pack here, then run with carry
# [".e2e"] and BIN=.e2e/wallload (LD_LIBRARY_PATH=.e2e/lib).
set -u
bin=$1 out=$2 ladder=${3:-}
shift 3 2>/dev/null || shift $#
mkdir -p "$out"
if [ $# -eq 0 ]; then
  # every case but spheric2: a 3D case of up to 1.1 M particles, a GPU run
  # of its own (validate spheric2 --backend cuda), a day on one CPU thread
  set -- $("$bin" validate --list | awk 'NF && $1 != "spheric2" {print $1}')
fi
one() {
  local a; a=$(date +%s)
  "$bin" validate "$1" ${ladder:+--ladder "$ladder"} --threads 1 \
    ${INTEGRATOR:+--integrator "$INTEGRATOR"} \
    ${REF:+--reference "$REF"} \
    -o "$out/$1" >"$out/$1.log" 2>&1
  echo "== $1 rc=$? wall=$(( $(date +%s) - a )) s"
}
export -f one
export bin out ladder INTEGRATOR REF
printf '%s\n' "$@" | xargs -P "${JOBS:-$(nproc)}" -I{} bash -c 'one {}'
