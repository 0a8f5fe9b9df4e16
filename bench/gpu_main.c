/* gpu_main.c: a bench-only driver (wl_cli_bench, src/cli/bench.c) that
 * bench/gpu.sh builds where the full dependency set of wallload (GSL,
 * libyaml, cairo, HDF5) is missing, as on the device machine:
 *
 *   wl_bench [bench options]      (the options of `wallload bench`) */
#include <stdio.h>

#include "cli.h"

int main(int argc, char **argv) {
  struct wl_error err;
  wl_error_clear(&err);
  const enum wl_status st = wl_cli_bench(argc, argv, &err);
  if (st != WL_OK) fprintf(stderr, "wl_bench: %s\n", err.msg);
  return wl_error_exit_code(st);
}
