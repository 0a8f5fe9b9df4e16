# sweep_lib.sh: what the sweep's command-line tests share (sourced, after
# `set -u` and bin=..., src=...): PASS/FAIL counting, the skips, the MPI
# launcher, and sweep.csv without its runtime column.
fail=0
ok() { echo "PASS $1"; }
bad() { echo "FAIL $1"; fail=$((fail+1)); }
command -v python3 >/dev/null || { echo "SKIP: python3 not installed"; exit 77; }

# The rows of sweep.csv $1 without the runtime column (the last but one).
sweep_csv_sans_runtime() {
  python3 -c "
import csv,sys
for r in csv.reader(open(sys.argv[1])):
    print(','.join(v for j, v in enumerate(r) if j != len(r) - 2))" "$1"
}

# mpirun for 2 ranks in ${mpi[@]}; skips (77) without an MPI build or mpirun.
sweep_mpi_setup() {
  "$bin" --version | grep -q 'MPI: built' || { echo "SKIP: wallload built without MPI"; exit 77; }
  command -v mpirun >/dev/null || { echo "SKIP: mpirun not installed (Debian: openmpi-bin)"; exit 77; }
  # CI runs as root in a container: root must be allowed, and the container
  # may forbid the cross-process memory copy Open MPI's shared-memory
  # transport tries
  mpi=(mpirun --allow-run-as-root --oversubscribe --mca btl_vader_single_copy_mechanism none -np 2)
  # Under the sanitizer build (scripts/test.sh sets ASAN_OPTIONS) the ranks
  # do not check for leaks: Open MPI leaves allocations at exit from plugins
  # it has unloaded, which LeakSanitizer cannot name (so tests/lsan.supp
  # cannot match them). ASan's and UBSan's other checks stay on; the
  # one-process sweep tests check wallload's own leaks.
  if [ -n "${ASAN_OPTIONS:-}" ]; then export ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0"; fi
}
