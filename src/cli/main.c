/* main.c: the wallload command line. The only place that prints errors and
 * picks exit codes (0 ok, 1 run failure, 2 bad input or usage). */
#define _POSIX_C_SOURCE 200809L /* setenv */

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>

#include "cli.h"
#include "wallload/config.h"
#include "wallload/error.h"

static void usage(FILE *out) {
  fprintf(out,
          "usage: wallload COMMAND [ARGS]\n"
          "\n"
          "commands:\n"
          "  assess FILE.yaml [-o DIR] [--backend cpu|cuda|auto] [--threads N] [--quiet] [--force]\n"
          "                [--end-time SECONDS] [--budget HOURS] [--force-large]\n"
          "                      the whole pipeline for every load case of the scenario\n"
          "  check FILE.yaml [--backend cpu|cuda|auto] [--budget HOURS] [--force-large]\n"
          "                      validate; print the resolved scenario, the derived initial\n"
          "                      conditions and what a run would cost; a run beyond this\n"
          "                      machine's memory, or beyond the runtime budget (24 h unless\n"
          "                      --budget; --force-large lifts it), is refused\n"
          "  sweep FILE.yaml [-o DIR] [--backend cpu|cuda|auto] [--threads N] [--quiet]\n"
          "                [--end-time SECONDS] [--budget HOURS] [--force-large]\n"
          "                      every case of the scenario's sweep section, each as assess\n"
          "                      runs it; sweep.csv, sweep.h5, sweep.pdf (envelopes) in DIR\n"
          "                      (default <scenario>-sweep); a killed sweep continues where it\n"
          "                      stopped when run again; under mpirun -np N the ranks share\n"
          "                      the cases ([--rank-timeout SECONDS]; docs/sweep-mpi.md)\n"
          "  convert OPTIONS     charge weight <-> crater <-> energy <-> equal-energy solitary\n"
          "                      wave (wallload convert --help)\n"
          "  report RESULTS.h5 [-o FILE.pdf] [--template FILE]\n"
          "                      re-render the design report from stored results\n"
          "  validate [CASE...] [--ladder N] [--quick] [-o DIR] [--threads N] [OPTIONS]\n"
          "                      reference cases (reference/) on a resolution ladder: error\n"
          "                      against runtime, observed order (validate --help)\n"
          "  bench [--case dambreak2d|dambreak3d|all] [--backend cpu|cuda|all]\n"
          "        [--particles N] [--steps N | --until T] [--numerics dualsphysics|assess]\n"
          "        [OPTIONS]       dam-break throughput per backend (force evaluations/s), or\n"
          "                      stability to a simulated time (bench --help)\n"
          "  --version           print the version\n"
          "\n"
          "exit codes: 0 success, 1 run failure, 2 bad input or usage\n");
}

/* OpenMP threads that wait at a barrier sleep instead of spinning, unless
 * the user chose otherwise: on a machine other jobs share, spinning threads
 * fight them for the cores. On the 2-core development machine beside one
 * busy process a run took 50.7 s spinning and 25.8 s sleeping (19.1 s
 * either way on the idle machine; BENCHMARKS.md "OpenMP on a shared
 * machine"). The runtime reads the policy once, when it loads, before
 * main: so the process sets it and runs itself again (same process id,
 * arguments and environment otherwise). If that fails it goes on as it
 * is. */
static void wait_passively(char **argv) {
  if (getenv("OMP_WAIT_POLICY")) return;
  if (setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0) return;
  execv("/proc/self/exe", argv);
}

/* The GPU runs the streams of cases side by side (a sweep's up to 16, a
 * ladder's levels) on hardware work queues, 8 by default: streams beyond
 * that share a queue and their kernels wait behind each other's. 32 (the
 * most) queues, unless the user chose: a 64-case sweep took 63.4 s instead
 * of 69.8 (H100, BENCHMARKS.md "Sweeps"). Read when the CUDA context is
 * made, long after this. */
static void gpu_queues_apart(void) {
  if (!getenv("CUDA_DEVICE_MAX_CONNECTIONS")) setenv("CUDA_DEVICE_MAX_CONNECTIONS", "32", 1);
}

int main(int argc, char **argv) {
  gpu_queues_apart();
  wait_passively(argv);
  /* GSL must report errors as status codes; the library checks every one. */
  gsl_set_error_handler_off();
  /* a file-size limit is a refused write ("File too large", exit 1), not a
   * death by SIGXFSZ */
  signal(SIGXFSZ, SIG_IGN);
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sweep_ranks ranks; /* one process, unless sweep runs under mpirun */
  memset(&ranks, 0, sizeof ranks);
  if (argc < 2) {
    usage(stderr);
    return 2;
  }
  const char *cmd = argv[1];
  enum wl_status st;
  if (!strcmp(cmd, "-h") || !strcmp(cmd, "--help") || !strcmp(cmd, "help")) {
    usage(stdout);
    return 0;
  } else if (!strcmp(cmd, "--version")) {
    printf("wallload %s (CUDA backend: %s; MPI: %s)\n", WL_VERSION,
           WL_HAVE_CUDA ? "built" : "not built", WL_HAVE_MPI ? "built" : "not built");
    return 0;
  } else if (!strcmp(cmd, "check")) {
    st = wl_cli_check(argc - 1, argv + 1, &err);
  } else if (!strcmp(cmd, "convert")) {
    st = wl_cli_convert(argc - 1, argv + 1, &err);
  } else if (!strcmp(cmd, "assess")) {
    st = wl_cli_assess(argc - 1, argv + 1, &err);
  } else if (!strcmp(cmd, "sweep")) {
    st = wl_cli_sweep(argc - 1, argv + 1, &ranks, &err);
  } else if (!strcmp(cmd, "report")) {
    st = wl_cli_report(argc - 1, argv + 1, &err);
  } else if (!strcmp(cmd, "bench")) {
    st = wl_cli_bench(argc - 1, argv + 1, &err);
  } else if (!strcmp(cmd, "validate")) {
    st = wl_cli_validate(argc - 1, argv + 1, &err);
  } else {
    fprintf(stderr, "wallload: unknown command '%s'\n\n", cmd);
    usage(stderr);
    return 2;
  }
  /* an empty message: another process says why (the other ranks of an
   * MPI sweep leave it to rank 0) */
  if (st != WL_OK && err.msg[0]) fprintf(stderr, "wallload: %s\n", err.msg);
  int code = wl_error_exit_code(st);
  /* what was printed (a case summary, check's listing) must have arrived */
  if (fflush(stdout) != 0 || ferror(stdout)) {
    fprintf(stderr, "wallload: standard output: %s\n", strerror(errno));
    if (code == 0) code = 1;
  }
  /* MPI finalised last: a rank cannot exit (mpirun then ends the job)
   * before rank 0 has printed */
  fflush(stderr);
  wl_sweep_ranks_finish(&ranks);
  return code;
}
