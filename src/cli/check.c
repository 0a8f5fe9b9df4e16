/* check.c: `wallload check` and `wallload assess`. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "wallload/plan.h"
#include "wallload/scenario.h"

/* Load and plan a scenario; on failure everything is freed. */
static enum wl_status load_and_plan(const char *path, struct wl_scenario *s, struct wl_plan *plan,
                                    struct wl_error *err) {
  wl_scenario_init(s);
  enum wl_status st = wl_scenario_load(path, s, err);
  if (st == WL_OK) st = wl_plan_make(s, plan, err);
  if (st != WL_OK) wl_scenario_clear(s);
  return st;
}

enum wl_status wl_cli_check(int argc, char **argv, struct wl_error *err) {
  if (argc != 2 || argv[1][0] == '-')
    return wl_error_set(err, WL_EUSAGE, "usage: wallload check FILE.yaml");
  struct wl_scenario s;
  struct wl_plan plan;
  enum wl_status st = load_and_plan(argv[1], &s, &plan, err);
  if (st) return st;
  printf("Scenario %s (%s): valid\n\nResolved scenario (SI; the value as written beside it)\n",
         s.name.text, s.path);
  wl_scenario_write_resolved(&s, stdout);
  wl_plan_write(&plan, stdout);
  wl_scenario_clear(&s);
  return WL_OK;
}

enum wl_status wl_cli_assess(int argc, char **argv, struct wl_error *err) {
  const char *path = NULL;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "-o") || !strcmp(a, "--backend") || !strcmp(a, "--threads")) {
      if (i + 1 >= argc) return wl_error_set(err, WL_EUSAGE, "assess: %s needs a value", a);
      i++;
    } else if (!strcmp(a, "--quiet") || !strcmp(a, "--force")) {
    } else if (a[0] == '-') {
      return wl_error_set(err, WL_EUSAGE,
                          "assess: unknown option '%s'; valid: -o DIR, --backend cpu|cuda|auto, "
                          "--threads N, --quiet, --force",
                          a);
    } else if (!path) {
      path = a;
    } else {
      return wl_error_set(err, WL_EUSAGE, "assess: one scenario file at a time ('%s' extra)", a);
    }
  }
  if (!path) return wl_error_set(err, WL_EUSAGE, "usage: wallload assess FILE.yaml [options]");
  struct wl_scenario s;
  struct wl_plan plan;
  enum wl_status st = load_and_plan(path, &s, &plan, err);
  if (st) return st;
  fprintf(stderr,
          "wallload: %s: scenario valid; initial conditions planned (%ld particles at dp = %g m)\n",
          path, plan.n_fluid + plan.n_boundary, plan.dp);
  wl_scenario_clear(&s);
  return wl_error_set(err, WL_EUNSUPPORTED,
                      "assess: stages done: scenario, plan. The next stage, the SPH solver, is "
                      "not built yet, so no loads were computed ('wallload check %s' shows the "
                      "plan)",
                      path);
}
