/* fuzz_drive.h: one scenario's bytes through the parse-validate-plan path
 * of `wallload check`, shared by the libFuzzer target (fuzz_scenario.c)
 * and the replay of tests/fuzz/regress/ in every build
 * (tests/test_fuzz_regress.c).
 *
 * The path is src/cli/check.c's, in its order: wl_scenario_parse (reader
 * limits, YAML, schema, cross-field rules), wl_plan_make, the listing
 * (wl_scenario_write_resolved, wl_plan_write) into `sink`, the convergence
 * ladder (every level re-planned, as check.c's ladder_cost),
 * wl_plan_solitary_runnable for a solitary case, and wl_plan_fits on a
 * fixed CPU machine and a fixed GPU machine (check measures the machine
 * it runs on; a fixed one keeps the result deterministic), plus
 * wl_scenario_load_units.
 * Left out: wl_report_template_find. It opens the scenario's
 * report.template as a path (relative to the working directory, or any
 * absolute path the input names, /dev/zero included) and looks beside the
 * executable, so a run would depend on the file system.
 *
 * Invariants beyond what the sanitizers see: a failure carries a message
 * that names the file, and is bad input (WL_EINPUT, exit 2) or, from the
 * wave integrals, WL_ENUMERIC/WL_ENOMEM; never another status. Everything
 * is freed before it returns. */
#ifndef WALLLOAD_FUZZ_DRIVE_H
#define WALLLOAD_FUZZ_DRIVE_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/plan.h"
#include "wallload/scenario.h"
#include "wallload/units.h"

struct wl_fuzz_result {
  enum wl_status status;      /* the first failure (WL_OK: check would print "valid") */
  char msg[WL_ERROR_MSG_MAX]; /* its message */
  char violation[2300];       /* "" or which invariant failed, with the message */
};

/* Record a violated invariant (the first one). */
static void wl_fuzz_judge(enum wl_status st, const struct wl_error *err, const char *path,
                          const char *where, struct wl_fuzz_result *r) {
  if (st == WL_OK || r->violation[0]) return;
  if (st != WL_EINPUT && st != WL_ENUMERIC && st != WL_ENOMEM)
    snprintf(r->violation, sizeof r->violation, "%s returned status %d (%s): %s", where, (int)st,
             wl_error_status_name(st), err->msg);
  else if (strncmp(err->msg, path, strlen(path)) != 0 || err->msg[strlen(path)] != ':')
    snprintf(r->violation, sizeof r->violation, "%s failed (%s) without naming the file: '%s'",
             where, wl_error_status_name(st), err->msg);
}

/* check's ladder cost (plan.h wl_plan_ladder_cost), its listing to the
 * sink; a level that cannot be planned is judged as any plan. */
static void wl_fuzz_ladder(const struct wl_scenario *s, const struct wl_plan *plan, FILE *sink,
                           struct wl_plan_cost *cost, struct wl_fuzz_result *r) {
  struct wl_error e;
  wl_error_clear(&e);
  enum wl_status st = wl_plan_ladder_cost(s, plan, 0, sink, cost, &e);
  wl_fuzz_judge(st, &e, s->path, "wl_plan_ladder_cost (a ladder level)", r);
}

/* Drive `size` bytes, read as the file `path`, through check's path;
 * listings go to `sink`. */
static struct wl_fuzz_result wl_fuzz_drive(const char *path, const char *data, size_t size,
                                           FILE *sink) {
  struct wl_fuzz_result r;
  memset(&r, 0, sizeof r);
  struct wl_scenario *s = malloc(sizeof *s);
  struct wl_plan *plan = malloc(sizeof *plan);
  if (!s || !plan) {
    free(s);
    free(plan);
    r.status = WL_ENOMEM;
    return r;
  }
  struct wl_error err;
  wl_error_clear(&err);
  wl_scenario_init(s);
  enum wl_status st = wl_scenario_parse(path, data, size, s, &err);
  wl_fuzz_judge(st, &err, path, "wl_scenario_parse", &r);
  if (st == WL_OK) {
    st = wl_plan_make(s, plan, &err);
    wl_fuzz_judge(st, &err, path, "wl_plan_make", &r);
  }
  if (st == WL_OK) {
    wl_scenario_write_resolved(s, sink);
    wl_plan_write(plan, sink);
    struct wl_plan_cost cost;
    wl_fuzz_ladder(s, plan, sink, &cost, &r);
    if (plan->solitary.present) {
      st = wl_plan_solitary_runnable(s, plan, &err);
      wl_fuzz_judge(st, &err, path, "wl_plan_solitary_runnable", &r);
    }
    if (st == WL_OK) {
      /* the machine check.c would measure, fixed: 2 CPU threads and
       * 16 GiB; then the same with an 80 GiB GPU */
      const double gib = 1073741824.0;
      struct wl_plan_machine cpu = {16 * gib, 0, "", 2, WL_PLAN_BUDGET_DEFAULT_S, 0};
      struct wl_plan_machine gpu = {16 * gib, 80 * gib, "H100", 2, WL_PLAN_BUDGET_DEFAULT_S, 0};
      struct wl_error e;
      wl_error_clear(&e);
      st = wl_plan_fits(s, &cost, &cpu, &e);
      wl_fuzz_judge(st, &e, path, "wl_plan_fits (CPU)", &r);
      wl_error_clear(&e);
      wl_fuzz_judge(wl_plan_fits(s, &cost, &gpu, &e), &e, path, "wl_plan_fits (GPU)", &r);
      if (st != WL_OK) err = e;
    }
    struct wl_load_units u;
    if (wl_scenario_load_units(s, &u)) fprintf(sink, "%s %g\n", u.force, u.force_f);
  }
  r.status = st;
  if (st != WL_OK) snprintf(r.msg, sizeof r.msg, "%s", err.msg);
  wl_scenario_clear(s);
  free(s);
  free(plan);
  return r;
}

#endif
