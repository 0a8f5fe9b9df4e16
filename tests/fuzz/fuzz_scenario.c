/* fuzz_scenario.c: libFuzzer target for the parse-validate-plan path of
 * `wallload check` (issue 18): each input is a scenario file's bytes, read
 * under the name "fuzz.yaml", driven by fuzz_drive.h the way
 * src/cli/check.c takes it (that header says what is in and what is left
 * out). A violated invariant of fuzz_drive.h aborts, as a sanitizer report
 * does: libFuzzer saves the input.
 *
 * Built with -DWL_FUZZ=ON and clang; scripts/fuzz.sh builds and runs it.
 * Findings become regression inputs in tests/fuzz/regress/, replayed in
 * every build by tests/test_fuzz_regress.c. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_drive.h"
#include "wallload/waves.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The exact solitary wave: wl_plan_make computes it for a note whenever
 * H/h > 0.5, with 16384 Fourier modes (0.7 to 2 s in Release, twice that
 * here), and once again for every level of a convergence ladder: a check
 * of 37 s (tests/fuzz/regress/exact_solitary_ladder.yaml). The target
 * links with -Wl,--wrap=wl_waves_exact_solitary: the real solver runs, on
 * 1024 modes (the same code; the note's digits change a little), and the
 * results of the last 64 values of H/h are kept (the ladder's levels share
 * one; the fuzzer's mutations come back to a few). It is a pure function
 * of (eps, n_modes), so nothing else changes; its accuracy is test_waves'
 * business. WL_FUZZ_EXACT_MODES=N sets the modes (16384: what check
 * computes). */
enum wl_status __real_wl_waves_exact_solitary(double eps, int n_modes,
                                              struct wl_solitary_exact *out,
                                              struct wl_error *err);
enum wl_status __wrap_wl_waves_exact_solitary(double eps, int n_modes,
                                              struct wl_solitary_exact *out,
                                              struct wl_error *err);

enum { EXACT_CACHE = 64 };

enum wl_status __wrap_wl_waves_exact_solitary(double eps, int n_modes,
                                              struct wl_solitary_exact *out,
                                              struct wl_error *err) {
  static int modes, n_kept, next;
  static struct {
    double eps;
    enum wl_status st;
    struct wl_solitary_exact ex;
    char msg[WL_ERROR_MSG_MAX];
  } kept[EXACT_CACHE];
  if (!modes) {
    const char *env = getenv("WL_FUZZ_EXACT_MODES");
    modes = env && atoi(env) > 0 ? atoi(env) : 1024;
  }
  (void)n_modes;
  int i = 0;
  while (i < n_kept && memcmp(&kept[i].eps, &eps, sizeof eps) != 0) i++;
  if (i == n_kept) {
    i = n_kept < EXACT_CACHE ? n_kept++ : next;
    next = (i + 1) % EXACT_CACHE;
    struct wl_error e;
    wl_error_clear(&e);
    kept[i].st = __real_wl_waves_exact_solitary(eps, modes, &kept[i].ex, &e);
    kept[i].eps = eps;
    snprintf(kept[i].msg, sizeof kept[i].msg, "%s", e.msg);
  }
  *out = kept[i].ex;
  if (kept[i].st != WL_OK) wl_error_set(err, kept[i].st, "%s", kept[i].msg);
  return kept[i].st;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static FILE *sink;
  if (!sink) sink = fopen("/dev/null", "w");
  if (!sink) abort();
  struct wl_fuzz_result r = wl_fuzz_drive("fuzz.yaml", (const char *)data, size, sink);
  if (r.violation[0]) {
    fprintf(stderr, "fuzz_scenario: %s\n", r.violation);
    abort();
  }
  return 0;
}
