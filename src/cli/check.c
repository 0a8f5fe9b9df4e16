/* check.c: `wallload check` and `wallload assess`. */
#define _POSIX_C_SOURCE 200809L /* sigaction, isatty */
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "wallload/assess.h"
#include "cli.h"
#include "wallload/plan.h"
#include "wallload/report.h"
#include "wallload/scenario.h"
#include "wallload/units.h"

/* Load a scenario and find and parse its report template (so that a
 * missing or malformed one is refused now, not after the run); `plan`
 * (may be NULL: a sweep plans its cases) is made too, for the machine
 * `opts` run on within `budget_s` (--budget; <= 0: the default)
 * (resolution.particles_per_height: auto; what it chose, and the machine,
 * to *choice, may be NULL). On failure
 * everything is freed. */
static enum wl_status load_scenario(const char *path, const struct wl_assess_opts *opts,
                                    double budget_s, struct wl_scenario *s, struct wl_plan *plan,
                                    struct wl_plan_choice *choice, struct wl_error *err) {
  wl_scenario_init(s);
  enum wl_status st = wl_scenario_load(path, s, err);
  if (st == WL_OK && plan) {
    struct wl_plan_machine m;
    wl_assess_machine(s, opts, &m);
    if (budget_s > 0) m.budget_seconds = budget_s;
    struct wl_plan_choice c;
    st = wl_plan_choose(s, &m, &c, err);
    if (choice) *choice = c;
  }
  if (st == WL_OK && plan) st = wl_plan_make(s, plan, err);
  if (st == WL_OK) {
    struct wl_report_template t;
    wl_report_template_init(&t);
    char source[1200];
    st = wl_report_template_find(s->report.template_name.text, path, NULL, &t, source,
                                 sizeof source, err);
    wl_report_template_clear(&t);
  }
  if (st != WL_OK) wl_scenario_clear(s);
  return st;
}

/* A scenario for `assess`: one without a sweep section, planned. */
static enum wl_status load_and_plan(const char *path, const struct wl_assess_opts *opts,
                                    double budget_s, struct wl_scenario *s, struct wl_plan *plan,
                                    struct wl_plan_choice *choice, struct wl_error *err) {
  wl_scenario_init(s);
  enum wl_status st = wl_scenario_load(path, s, err);
  if (st == WL_OK && s->sweep.present)
    st = wl_error_set(err, WL_EINPUT,
                      "%s:%d:%d: sweep: the scenario has a sweep section (%d cases), which "
                      "`wallload sweep %s` runs; `assess` runs one scenario: remove the section, "
                      "or assess one case's scenario.yaml from the sweep's cases/ directory",
                      path, s->sweep.line, s->sweep.col, s->sweep.n_cases, path);
  wl_scenario_clear(s);
  if (st) return st;
  return load_scenario(path, opts, budget_s, s, plan, choice, err);
}

enum wl_status wl_cli_load_sweep(const char *path, struct wl_scenario *s, struct wl_sweep *sw,
                                 struct wl_error *err) {
  wl_sweep_init(sw);
  enum wl_status st = load_scenario(path, NULL, 0, s, NULL, NULL, err);
  if (st) return st;
  if ((st = wl_sweep_make(s, sw, err))) {
    wl_sweep_clear(sw);
    wl_scenario_clear(s);
  }
  return st;
}

/* --budget HOURS and --force-large, shared by check and assess: 1 when
 * argv[*i] is one of them (consumed, *i advanced past a value), 0 when it
 * is not, -1 on a bad value (err set). */
int wl_cli_budget_option(const char *cmd, int argc, char **argv, int *i, double *budget_s,
                         int *force_large, struct wl_error *err) {
  const char *a = argv[*i];
  if (!strcmp(a, "--force-large")) {
    *force_large = 1;
    return 1;
  }
  if (strcmp(a, "--budget")) return 0;
  if (*i + 1 >= argc) {
    wl_error_set(err, WL_EUSAGE, "%s: --budget needs a value (hours)", cmd);
    return -1;
  }
  const char *v = argv[++*i];
  char *end;
  const double hours = strtod(v, &end);
  if (*end || !(hours > 0) || hours > 1e6) {
    wl_error_set(err, WL_EUSAGE, "%s: --budget: found '%s'; expected hours above 0 and at most 1e6",
                 cmd, v);
    return -1;
  }
  *budget_s = hours * 3600.0;
  return 1;
}

/* What check and assess both judge once the plan is made (the one
 * function, so that a scenario check passes is one assess starts): every
 * case can run, and the plan (or its ladder) fits the machine the run
 * would take and the budget. The machine's verdict goes to `out` (may be
 * NULL). */
static enum wl_status judge_run(const struct wl_scenario *s, const struct wl_plan *plan,
                                const struct wl_plan_cost *cost,
                                const struct wl_assess_opts *opts, double budget_s,
                                int force_large, FILE *out, struct wl_error *err) {
  enum wl_status st = WL_OK;
  if (plan->solitary.present && (st = wl_plan_solitary_runnable(s, plan, err))) return st;
  struct wl_plan_machine m;
  wl_assess_machine(s, opts, &m);
  if (budget_s > 0) m.budget_seconds = budget_s;
  m.force_large = force_large;
  st = wl_plan_fits(s, cost, &m, err);
  if (out && st == WL_OK) {
    fprintf(out, "\nMachine: %s%s, %.3g GiB of memory; runtime budget %.3g h%s: fits\n",
            m.device_bytes > 0 ? "GPU " : "CPU", m.device_bytes > 0 ? m.device_name : "",
            (m.device_bytes > 0 ? m.device_bytes : m.host_bytes) / 1073741824.0,
            m.budget_seconds / 3600.0, force_large ? " (lifted by --force-large)" : "");
    if (!(m.device_bytes > 0)) {
      /* the estimates above are at the reference machine's rate; this
       * machine's now (src/assess/speed.c) */
      struct wl_error serr;
      wl_error_clear(&serr);
      const double speed = wl_assess_cpu_speed(m.threads, &serr);
      if (speed > 0)
        fprintf(out, "CPU speed now: %.2f of the reference machine's on %d threads (a small "
                     "flume timed just now): about %.4g s here (%.3g h)\n",
                speed, m.threads, wl_plan_machine_seconds(cost, &m) / speed,
                wl_plan_machine_seconds(cost, &m) / speed / 3600.0);
      else
        fprintf(out, "CPU speed now: not measured (%s)\n", serr.msg);
    }
  }
  return st;
}

enum wl_status wl_cli_sweep_price(const struct wl_sweep *sw, const struct wl_assess_opts *opts,
                                  double budget_s, int force_large, FILE *out,
                                  struct wl_error *err) {
  struct wl_scenario *cs = malloc(sizeof *cs), *first = malloc(sizeof *first);
  struct wl_plan *plan = malloc(sizeof *plan), *first_plan = malloc(sizeof *first_plan);
  enum wl_status st = WL_OK;
  if (first) wl_scenario_init(first);
  if (!cs || !first || !plan || !first_plan)
    st = wl_error_set(err, WL_ENOMEM, "%s: no memory to price the sweep", sw->path);
  struct wl_plan_cost total = {0, 0, 0, 0, 0, 0};
  double footprint = 0.0;
  struct wl_plan_cost *case_cost = calloc(sw->n_cases > 0 ? (size_t)sw->n_cases : 1, sizeof *case_cost);
  if (!case_cost && !st) st = wl_error_set(err, WL_ENOMEM, "%s: no memory to price the sweep", sw->path);
  if (!st && out) {
    fprintf(out, "\nSweep: %d cases (", sw->n_cases);
    for (int k = 0; k < sw->n_params; k++)
      fprintf(out, "%s%s", k ? " x " : "", wl_scenario_sweep_param_name(sw->order[k]));
    fprintf(out, "), each priced as `check` prices it alone\n  %4s  %-40s %10s %16s %16s\n",
            "case", "id", "particles", "CPU (est.) [s]", "GPU (est.) [s]");
  }
  for (int i = 0; !st && i < sw->n_cases; i++) {
    struct wl_scenario *c = i == 0 ? first : cs;
    struct wl_plan *p = i == 0 ? first_plan : plan;
    struct wl_error e;
    wl_error_clear(&e);
    st = wl_sweep_case_scenario(sw, i, c, &e);
    if (!st) st = wl_plan_make(c, p, &e);
    if (!st && p->solitary.present) st = wl_plan_solitary_runnable(c, p, &e);
    if (st) {
      char label[512];
      wl_sweep_case_label(sw, i, label, sizeof label);
      wl_error_set(err, st, "%s: sweep case %d (%s): %s", sw->path, i, label, e.msg);
      if (i) wl_scenario_clear(c);
      break;
    }
    struct wl_plan_cost cost;
    struct wl_error ladder_err; /* a level that cannot be planned: the case's own cost */
    wl_error_clear(&ladder_err);
    wl_plan_ladder_cost(c, p, 1, NULL, &cost, &ladder_err);
    total.dims = cost.dims > total.dims ? cost.dims : total.dims;
    total.host_bytes = fmax(total.host_bytes, cost.host_bytes);
    total.device_bytes = fmax(total.device_bytes, cost.device_bytes);
    /* side by side, a case holds all its ladder's levels at once */
    footprint = fmax(footprint, (c->resolution.n_levels > 0 ? c->resolution.n_levels : 1) *
                                    cost.device_bytes);
    total.cpu_seconds += cost.cpu_seconds;
    total.gpu_work_seconds += cost.gpu_work_seconds;
    case_cost[i] = cost;
    if (out)
      fprintf(out, "  %4d  %-40s %10ld %16.6g %16.6g\n", i, sw->cases[i].id,
              p->n_fluid + p->n_boundary, cost.cpu_seconds, cost.gpu_seconds);
    if (i) wl_scenario_clear(c);
  }
  /* on a GPU the cases run side by side (src/sweep/run.c), each counting
   * its ladder's levels' memory */
  int width = 1;
  if (!st) {
    width = wl_plan_gpu_side_by_side_width(footprint, WL_PLAN_GPU_BYTES,
                                           WL_SWEEP_SIDE_BY_SIDE_MAX);
    total.gpu_seconds = wl_plan_gpu_side_by_side(case_cost, sw->n_cases, width);
  }
  if (!st && out)
    fprintf(out,
            "  sweep CPU runtime (estimate) %.6g s (%.3g h), the cases one after the other; "
            "GPU runtime (estimate, an H100) %.6g s, up to %d cases side by side\n",
            total.cpu_seconds, total.cpu_seconds / 3600.0, total.gpu_seconds,
            width < sw->n_cases ? width : sw->n_cases);
  /* the machine and the budget judge the sweep as one run */
  if (!st && (st = judge_run(first, first_plan, &total, opts, budget_s, force_large, out, err)))
    wl_error_prefix(err, "the sweep's %d cases: ", sw->n_cases);
  if (first) wl_scenario_clear(first);
  free(case_cost), free(cs), free(first), free(plan), free(first_plan);
  return st;
}

/* check of a sweep: the resolved scenario, the first case's plan in full,
 * and the price of every case. */
static enum wl_status check_sweep(const char *path, const struct wl_assess_opts *opts,
                                  double budget_s, int force_large, struct wl_error *err) {
  struct wl_scenario s;
  struct wl_sweep sw;
  enum wl_status st = wl_cli_load_sweep(path, &s, &sw, err);
  if (st) return st;
  printf("Scenario %s (%s): valid, a sweep of %d cases\n\nResolved scenario (SI; the value as "
         "written beside it)\n",
         s.name.text, s.path, sw.n_cases);
  wl_scenario_write_resolved(&s, stdout);
  struct wl_scenario *c0 = malloc(sizeof *c0);
  struct wl_plan *p0 = malloc(sizeof *p0);
  if (c0) wl_scenario_init(c0);
  if (!c0 || !p0) st = wl_error_set(err, WL_ENOMEM, "%s: no memory", path);
  if (!st) st = wl_sweep_case_scenario(&sw, 0, c0, err);
  if (!st && (st = wl_plan_make(c0, p0, err)) == WL_OK) {
    char label[512];
    wl_sweep_case_label(&sw, 0, label, sizeof label);
    printf("\nCase 0 (%s), as each case is planned\n", label);
    wl_plan_write(p0, stdout);
  }
  if (c0) wl_scenario_clear(c0);
  free(c0), free(p0);
  if (!st) st = wl_cli_sweep_price(&sw, opts, budget_s, force_large, stdout, err);
  wl_sweep_clear(&sw);
  wl_scenario_clear(&s);
  return st;
}

enum wl_status wl_cli_check(int argc, char **argv, struct wl_error *err) {
  const char *path = NULL;
  struct wl_assess_opts opts = {0};
  double budget_s = 0;
  int force_large = 0;
  for (int i = 1; i < argc; i++) {
    const int used = wl_cli_budget_option("check", argc, argv, &i, &budget_s, &force_large, err);
    if (used < 0) return WL_EUSAGE;
    if (used) continue;
    if (!strcmp(argv[i], "--backend")) {
      const char *v = i + 1 < argc ? argv[++i] : "";
      if (strcmp(v, "cpu") && strcmp(v, "cuda") && strcmp(v, "auto"))
        return wl_error_set(err, WL_EUSAGE, "check: --backend: found '%s'; valid: cpu, cuda, auto", v);
      opts.backend = v;
    } else if (argv[i][0] == '-' || path) {
      return wl_error_set(err, WL_EUSAGE,
                          "usage: wallload check FILE.yaml [--backend cpu|cuda|auto] [--budget "
                          "HOURS] [--force-large] ('%s' not understood)",
                          argv[i]);
    } else {
      path = argv[i];
    }
  }
  if (!path)
    return wl_error_set(err, WL_EUSAGE,
                        "usage: wallload check FILE.yaml [--backend cpu|cuda|auto] [--budget "
                        "HOURS] [--force-large]");
  struct wl_scenario s;
  struct wl_plan plan;
  wl_scenario_init(&s);
  enum wl_status st = wl_scenario_load(path, &s, err);
  const int sweep = st == WL_OK && s.sweep.present;
  wl_scenario_clear(&s);
  if (st) return st;
  if (sweep) return check_sweep(path, &opts, budget_s, force_large, err);
  struct wl_plan_choice choice;
  st = load_scenario(path, &opts, budget_s, &s, &plan, &choice, err);
  if (st) return st;
  printf("Scenario %s (%s): valid\n\nResolved scenario (SI; the value as written beside it)\n",
         s.name.text, s.path);
  wl_scenario_write_resolved(&s, stdout);
  wl_plan_write(&plan, stdout);
  if (choice.is_auto) {
    char line[400];
    wl_plan_choice_describe(&choice, line, sizeof line);
    printf("\n%s\n", line);
  }
  struct wl_plan_cost cost;
  struct wl_error ladder_err; /* printed with the ladder; the plan's own cost then */
  wl_error_clear(&ladder_err);
  wl_plan_ladder_cost(&s, &plan, 0, stdout, &cost, &ladder_err);
  /* printed in full above; a case that cannot run, or a run beyond the
   * machine or the budget, makes the scenario invalid */
  st = judge_run(&s, &plan, &cost, &opts, budget_s, force_large, stdout, err);
  wl_scenario_clear(&s);
  return st;
}

/* Ctrl-C (SIGINT), SIGTERM (a scheduler's or `kill`'s stop) and SIGHUP (a
 * closed terminal) set this to the signal's number; the running case stops
 * at its next output time and everything computed so far is written, with
 * status `interrupted`. (The one piece of process state: a signal handler
 * can reach nothing else.) */
static volatile sig_atomic_t interrupted = 0;

static void on_stop_signal(int sig) { interrupted = sig; }


static void fmt_eta(double s, char *buf, size_t size) {
  if (!isfinite(s) || s < 0)
    snprintf(buf, size, "--");
  else if (s < 60)
    snprintf(buf, size, "%.0fs", s);
  else if (s < 3600)
    snprintf(buf, size, "%dm%02ds", (int)(s / 60), (int)fmod(s, 60));
  else
    snprintf(buf, size, "%dh%02dm", (int)(s / 3600), (int)fmod(s / 60, 60));
}

void wl_cli_show_progress(void *user, const char *name, const struct wl_sph_progress *pr) {
  struct wl_cli_progress *ps = user;
  double frac = pr->t_end > 0 ? pr->t / pr->t_end : 0;
  double eta_s = frac > 0 ? pr->wall_s * (1 - frac) / frac : NAN;
  char eta[32];
  if (pr->runs > 1) { /* runs side by side: the share of their work, and the ETA of all */
    fmt_eta(pr->eta_s, eta, sizeof eta);
    if (ps->tty) {
      fprintf(stderr, "\r%-10s %6.1f %% of the %d runs' work  ETA %-8s", name, 100 * pr->done,
              pr->runs, eta);
      if (pr->done >= 1.0) fputc('\n', stderr);
    } else if (pr->wall_s - ps->last_print >= 30.0 || pr->done >= 1.0) {
      fprintf(stderr, "%s: %.0f %% of the %d runs' work, ETA %s\n", name, 100 * pr->done,
              pr->runs, eta);
      ps->last_print = pr->wall_s;
    }
    return;
  }
  fmt_eta(eta_s, eta, sizeof eta);
  if (ps->tty) {
    fprintf(stderr, "\r%-10s t = %7.3f / %.3f s  %6.1f %%  %8.0f steps/s  %.2e particle-steps/s  ETA %-8s",
            name, pr->t, pr->t_end, 100 * frac, pr->steps_per_s, pr->particle_steps_per_s, eta);
    if (pr->t >= pr->t_end) fputc('\n', stderr);
  } else if (pr->wall_s - ps->last_print >= 30.0 || pr->t >= pr->t_end) {
    /* not a terminal (a log file): a line every 30 s */
    fprintf(stderr, "%s: t = %.3f / %.3f s (%.0f %%), %.0f steps/s, ETA %s\n", name, pr->t,
            pr->t_end, 100 * frac, pr->steps_per_s, eta);
    ps->last_print = pr->wall_s;
  }
}

static void print_case(const struct wl_case_result *c, const struct wl_scenario *s) {
  const struct wl_case_loads *l = &c->loads;
  printf("\n%s case: %s", c->name,
         c->status == WL_OK ? "complete" : c->status == WL_EUNSTABLE ? "UNSTABLE" : "stopped");
  printf(" (t = %.3f of %.3f s, %ld steps, %d particles, %.1f s)\n", c->t_reached, c->t_end,
         c->steps, c->n_particles, c->runtime_s);
  if (c->status != WL_OK) printf("  stopped: %s\n", c->message);
  if (!c->rec.n) return;
  printf("  %-34s %12.5g kN/m  at t = %.3f s (probes, filtered %.3g Hz)\n", "peak force",
         l->force_peak.value / 1e3, l->force_peak.time, l->cutoff);
  printf("  %-34s %12.5g kN/m  (boundary particles, filtered)\n", "peak force",
         l->force_bound_peak.value / 1e3);
  printf("  %-34s %12.5g kN/m  (rho g d^2/2)\n", "static force", c->static_force / 1e3);
  if (l->rest_measured)
    printf("  %-34s %12.5g kN/m  (probes; %.5g boundary particles; %.3g to %.3g s)\n",
           "force at rest, the model's", l->rest_force / 1e3, l->rest_force_bound / 1e3,
           l->rest_from, l->rest_to);
  else
    printf("  %-34s %12s        (the wave is at the wall from the start: rho g d^2/2)\n",
           "force at rest, the model's", "not read");
  printf("  %-34s %12.5g kN s/m (whole record)\n", "impulse (force - at rest)",
         l->impulse_total / 1e3);
  printf("  %-34s %12.5g kN s/m (%.3f to %.3f s)\n", "impulse of the peak's positive phase",
         l->impulse_peak / 1e3, l->impulse_peak_from, l->impulse_peak_to);
  printf("  %-34s %12.5g kN s/m (boundary particles: %.5g; every wave's push)\n",
         "positive impulse", l->impulse_positive / 1e3, l->impulse_positive_bound / 1e3);
  printf("  %-34s %12.5g kN m/m\n", "peak overturning moment", l->moment_peak.value / 1e3);
  printf("  %-34s %12.5g m\n", "max run-up at the wall", l->runup);
  printf("  %-34s %12.5g s\n", "rise time", l->force_peak.rise_time);
  printf("  %-34s %12.5g s\n", "load duration", l->force_peak.duration);
  if (c->n_limited || c->n_excluded)
    printf("  %-34s %ld wall-limiter corrections, %ld fluid particles left the domain\n",
           "kept in bounds", c->n_limited, c->n_excluded);
  if (c->dp_coarse > 0)
    printf("  %-34s dp = %.4g m from x = %.4g m to the wall, %.4g m seaward; the water they "
           "own changed by %+.3g %%\n",
           "two resolutions", c->dp, c->x_interface, c->dp_coarse, 100.0 * c->water_change);
  struct wl_load_units u;
  if (wl_scenario_load_units(s, &u))
    printf("  %-34s %.5g %s, positive impulse %.5g %s (net %.5g, positive phase %.5g), moment "
           "%.5g %s, run-up %.4g %s\n",
           "in the scenario's units", l->force_peak.value * u.force_f, u.force,
           l->impulse_positive * u.impulse_f, u.impulse, l->impulse_total * u.impulse_f,
           l->impulse_peak * u.impulse_f,
           l->moment_peak.value * u.moment_f, u.moment, l->runup * u.length_f, u.length);
  if (c->caution[0]) printf("  caution: %s\n", c->caution);
}

static void print_convergence(const struct wl_case_result *c,
                              const struct wl_assess_convergence *cv) {
  if (!cv->n_levels) return;
  printf("  convergence ladder (%d of %d levels):\n", cv->n_levels, cv->n_planned);
  printf("    %5s %10s %10s %9s %14s %18s %16s %10s\n", "level", "dp [m]", "particles", "runtime",
         "peak F [kN/m]", "I+ [kN s/m]", "pos. phase", "error");
  for (int k = 0; k < cv->n_levels; k++) {
    const struct wl_assess_level *lv = &cv->lv[k];
    printf("    %5d %10.4g %10d %8.1fs %14.5g %18.5g %16.5g %9.3g%%%s\n", k + 1, lv->dp,
           lv->n_particles, lv->runtime_s, lv->peak_force / 1e3, lv->impulse_positive / 1e3,
           lv->impulse_phase / 1e3, 100 * lv->error,
           lv->status == WL_OK ? "" : "  (stopped)");
  }
  const struct wl_assess_level *fin = &cv->lv[cv->n_levels - 1];
  if (fin->realisations > 1)
    printf("    each level the mean of %d realisations (resolution.realisations); at level %d "
           "single runs peaked at %.5g to %.5g kN/m (sd %.2g %%), I+ sd %.2g %%\n",
           fin->realisations, cv->n_levels, fin->peak_force_min / 1e3, fin->peak_force_max / 1e3,
           100 * fin->peak_force_sd / fabs(fin->peak_force),
           100 * fin->impulse_positive_sd / fabs(fin->impulse_positive));
  if (fin->realisations > 1)
    printf("    the mean's sampling uncertainty (95 %%, in the bands below): peak force %.3g %%, "
           "its part above the force at rest %.3g %%, positive impulse %.3g %%\n",
           100 * cv->force_sampling, 100 * cv->dynamic_sampling, 100 * cv->impulse_sampling);
  printf("    observed order: peak force %.3g%s, positive impulse %.3g%s; uncertainty: peak "
         "force %.3g %% (%s), its part above the force at rest %.3g %% (%s), positive impulse "
         "%.3g %% (%s)\n",
         cv->force.order, cv->force.order_ok ? "" : " (not meaningful)", cv->impulse_pos.order,
         cv->impulse_pos.order_ok ? "" : " (not meaningful)", 100 * cv->force.error,
         wl_loads_estimate_name(cv->force.basis), 100 * cv->force_dynamic.error,
         wl_loads_estimate_name(cv->force_dynamic.basis), 100 * cv->impulse_pos.error,
         wl_loads_estimate_name(cv->impulse_pos.basis));
  printf("    %s: %s\n", c->name, cv->note);
}

struct assess_args {
  const char *path;
  struct wl_assess_opts *opts;
  int quiet;
  double budget_s;
  int force_large;
};
static enum wl_status assess_stoppable(void *user, volatile sig_atomic_t *stop,
                                       struct wl_error *err);

enum wl_status wl_cli_assess(int argc, char **argv, struct wl_error *err) {
  const char *path = NULL;
  struct wl_assess_opts opts = {0};
  int quiet = 0, force_large = 0, used;
  double budget_s = 0;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "-o") || !strcmp(a, "--backend") || !strcmp(a, "--threads") ||
        !strcmp(a, "--end-time")) {
      if (i + 1 >= argc) return wl_error_set(err, WL_EUSAGE, "assess: %s needs a value", a);
      const char *v = argv[++i];
      if (!strcmp(a, "-o")) {
        opts.out_dir = v;
      } else if (!strcmp(a, "--threads")) {
        char *end;
        long n = strtol(v, &end, 10);
        if (*end || n < 1 || n > 4096)
          return wl_error_set(err, WL_EUSAGE, "assess: --threads: found '%s'; expected 1 to 4096", v);
        opts.threads = (int)n;
      } else if (!strcmp(a, "--end-time")) {
        char *end;
        double t = strtod(v, &end);
        if (*end || !(t > 0))
          return wl_error_set(err, WL_EUSAGE, "assess: --end-time: found '%s'; expected seconds > 0", v);
        opts.end_time = t;
      } else if (strcmp(v, "cpu") && strcmp(v, "cuda") && strcmp(v, "auto")) {
        return wl_error_set(err, WL_EUSAGE, "assess: --backend: found '%s'; valid: cpu, cuda, auto", v);
      } else {
        opts.backend = v;
      }
    } else if ((used = wl_cli_budget_option("assess", argc, argv, &i, &budget_s, &force_large, err))) {
      if (used < 0) return WL_EUSAGE;
    } else if (!strcmp(a, "--quiet")) {
      quiet = 1;
    } else if (!strcmp(a, "--force")) {
      opts.force = 1;
    } else if (a[0] == '-') {
      return wl_error_set(err, WL_EUSAGE,
                          "assess: unknown option '%s'; valid: -o DIR, --backend cpu|cuda|auto, "
                          "--threads N, --quiet, --force, --end-time SECONDS, --budget HOURS, "
                          "--force-large",
                          a);
    } else if (!path) {
      path = a;
    } else {
      return wl_error_set(err, WL_EUSAGE, "assess: one scenario file at a time ('%s' extra)", a);
    }
  }
  if (!path) return wl_error_set(err, WL_EUSAGE, "usage: wallload assess FILE.yaml [options]");
  struct assess_args a = {path, &opts, quiet, budget_s, force_large};
  enum wl_status st = wl_cli_with_stop_signals(assess_stoppable, &a, err);
  /* A signal that came after the run's last look at the flag (while it
   * freed its memory, or returned) stopped nothing, but it was sent: say
   * so and exit 1, as for any stop after the results were written, rather
   * than swallow it. (Not for `sweep`: under mpirun a rank that has
   * finished can be sent SIGTERM as the job ends.) */
  if (st == WL_OK && interrupted)
    st = wl_error_set(err, WL_EINTERRUPTED,
                      "interrupted by %s after the results were written (they are complete)",
                      wl_assess_stop_signal_name(interrupted));
  return st;
}

enum wl_status wl_cli_with_stop_signals(wl_cli_stoppable_fn fn, void *user, struct wl_error *err) {
  /* The stop signals are caught from here to the last line printed, so
   * that no moment of a run is left to the default action (death with
   * exit 143 and nothing said). */
  static const int stop_signals[3] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction sa, old[3];
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_stop_signal;
  for (int k = 0; k < 3; k++) sigaction(stop_signals[k], &sa, &old[k]);
  const enum wl_status st = fn(user, &interrupted, err);
  for (int k = 0; k < 3; k++) sigaction(stop_signals[k], &old[k], NULL);
  return st;
}

/* wl_cli_assess after its options, with the stop signals caught. */
static enum wl_status assess_stoppable(void *user, volatile sig_atomic_t *stop,
                                       struct wl_error *err) {
  const struct assess_args *a = user;
  const char *path = a->path;
  const int quiet = a->quiet;
  struct wl_assess_opts opts = *a->opts;
  opts.interrupted = stop;
  const double budget_s = a->budget_s;
  const int force_large = a->force_large;
  struct wl_scenario s;
  struct wl_plan plan;
  struct wl_plan_choice choice;
  enum wl_status st = load_and_plan(path, &opts, budget_s, &s, &plan, &choice, err);
  if (st) return st;
  struct wl_plan_cost cost;
  struct wl_error ladder_err; /* a level that cannot be planned: the plan's own cost */
  wl_error_clear(&ladder_err);
  wl_plan_ladder_cost(&s, &plan, 1, NULL, &cost, &ladder_err);
  if ((st = judge_run(&s, &plan, &cost, &opts, budget_s, force_large, NULL, err))) {
    wl_scenario_clear(&s);
    return st;
  }
  if (*stop) {
    wl_scenario_clear(&s);
    return wl_error_set(err, WL_EINTERRUPTED,
                        "interrupted by %s before the run started; nothing written",
                        wl_assess_stop_signal_name(*stop));
  }
  struct wl_cli_progress ps = {isatty(2), 0.0};
  if (!quiet) {
    opts.progress = wl_cli_show_progress;
    opts.user = &ps;
    /* estimates for the machine the run goes to */
    const struct wl_plan_machine m = choice.machine;
    const struct wl_plan_cost own = wl_plan_cost_of(&plan);
    char where_run[160];
    wl_plan_machine_name(&m, where_run, sizeof where_run);
    fprintf(stderr, "wallload: %s: dp = %g m, about %ld particles, est. %.0f s on %s\n", path,
            plan.dp, plan.n_fluid + plan.n_boundary, wl_plan_machine_seconds(&own, &m), where_run);
    if (choice.is_auto) {
      char line[400];
      wl_plan_choice_describe(&choice, line, sizeof line);
      fprintf(stderr, "wallload: %s\n", line);
    }
    if (s.resolution.n_levels) {
      fprintf(stderr, "wallload: convergence ladder of %d levels, dp x", s.resolution.n_levels);
      for (int k = 0; k < s.resolution.n_levels; k++)
        fprintf(stderr, "%s %s", k ? "," : "", s.resolution.levels[k].text);
      fprintf(stderr, "; est. %.0f s on %s in all", wl_plan_machine_seconds(&cost, &m), where_run);
      if (s.resolution.target_error.given)
        fprintf(stderr, "; stops once the estimated error is below %s",
                s.resolution.target_error.text);
      fputc('\n', stderr);
    }
  }
  struct wl_assess_result res;
  st = wl_assess_run(&s, &plan, &opts, &res, err);
  for (int i = 0; i < res.n_cases; i++) {
    print_case(&res.cases[i], &s);
    print_convergence(&res.cases[i], &res.conv[i]);
  }
  if (res.n_cases) printf("\nresults in %s/ (results.h5, summary.json, CSV, particle snapshots)\n", res.out_dir);
  /* a stop after the results were written: wl_cli_assess says so */
  wl_assess_result_clear(&res);
  wl_scenario_clear(&s);
  return st;
}
