/* sweep.c: `wallload sweep FILE.yaml`: every case of the scenario's sweep
 * section, run as `assess` runs one scenario (sweep.h). */
#define _POSIX_C_SOURCE 200809L /* isatty */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "wallload/sweep.h"

#define SWEEP_USAGE                                                                               \
  "usage: wallload sweep FILE.yaml [-o DIR] [--backend cpu|cuda|auto] [--threads N] [--quiet]\n" \
  "                      [--end-time SECONDS] [--budget HOURS] [--force-large]\n"                \
  "                      [--rank-timeout SECONDS]   (under mpirun: docs/sweep-mpi.md)"

struct sweep_args {
  const char *path, *out_dir;
  struct wl_assess_opts opts;
  int quiet, force_large;
  double budget_s;
  struct wl_sweep_ranks *ranks; /* this process among mpirun's (one process without it) */
};

/* What the terminal shows: which case of how many, then assess's own
 * progress line for the running case. */
struct sweep_view {
  const struct sweep_args *a;
  struct wl_cli_progress progress;
  int current, n_cases;
};

static void case_progress(void *user, const char *name, const struct wl_sph_progress *pr) {
  struct sweep_view *v = user;
  char label[160];
  snprintf(label, sizeof label, "[%d/%d] %s", v->current + 1, v->n_cases, name);
  wl_cli_show_progress(&v->progress, label, pr);
}

static void case_begin(void *user, const struct wl_sweep *sw, int i, int reused) {
  struct sweep_view *v = user;
  v->current = i;
  v->progress.last_print = 0.0;
  if (v->a->quiet) return;
  char label[512];
  wl_sweep_case_label(sw, i, label, sizeof label);
  if (reused)
    fprintf(stderr, "wallload: case %d/%d (%s): reused: finished by an earlier run with the same "
            "inputs\n", i + 1, sw->n_cases, label);
  else if (v->a->ranks->size > 1)
    fprintf(stderr, "wallload: case %d/%d (%s): running on rank %d\n", i + 1, sw->n_cases, label,
            sw->rows[i].rank);
  else if (sw->side_by_side > 1)
    fprintf(stderr, "wallload: case %d/%d (%s): started (up to %d cases side by side on the GPU)\n",
            i + 1, sw->n_cases, label, sw->side_by_side);
  else
    fprintf(stderr, "wallload: case %d/%d (%s): running\n", i + 1, sw->n_cases, label);
}

static void case_end(void *user, const struct wl_sweep *sw, int i) {
  struct sweep_view *v = user;
  const struct wl_sweep_row *r = &sw->rows[i];
  if (v->a->quiet) return;
  if (r->status != WL_OK)
    fprintf(stderr, "wallload: case %d/%d: %s\n", i + 1, sw->n_cases, r->message);
  else if (v->a->ranks->size > 1) /* the cases of several ranks end out of order */
    fprintf(stderr, "wallload: case %d/%d: complete on rank %d (%.1f s)\n", i + 1, sw->n_cases,
            r->rank, r->runtime_s);
  else if (sw->side_by_side > 1) /* so do cases side by side */
    fprintf(stderr, "wallload: case %d/%d: complete (%.1f s)\n", i + 1, sw->n_cases, r->runtime_s);
}

/* Under mpirun, what each rank runs with, once, from rank 0. */
static void rank_ready(void *user, const struct wl_sweep_rank_info *ri) {
  const struct sweep_view *v = user;
  if (v->a->quiet) return;
  fprintf(stderr, "wallload: rank %d: pid %ld on %s, %d thread%s%s%s\n", ri->rank, ri->pid,
          ri->host, ri->threads, ri->threads == 1 ? "" : "s", ri->gpu[0] ? ", " : "", ri->gpu);
}

/* One line per case on stdout: the loads to quote (kN/m, kN s/m). */
static void print_rows(const struct wl_sweep *sw, const char *dir, int pdf) {
  static const char *const load_name[WL_SWEEP_N_LOADS] = {"solitary", "explosion"};
  printf("\n%4s  %-36s %-11s", "case", "id", "status");
  for (int l = 0; l < WL_SWEEP_N_LOADS; l++)
    if (sw->has_load[l]) printf(" %9.9s F [kN/m] %9.9s I+ [kN s/m]", load_name[l], load_name[l]);
  printf("  %9s\n", "runtime");
  for (int i = 0; i < sw->n_cases; i++) {
    const struct wl_sweep_row *r = &sw->rows[i];
    const char *status = r->state == WL_SWEEP_PENDING ? "not run"
                         : r->status == WL_OK         ? "complete"
                         : r->status == WL_EUNSTABLE  ? "unstable"
                         : r->status == WL_EINTERRUPTED ? "interrupted"
                                                        : "failed";
    printf("%4d  %-36s %-11s", i, sw->cases[i].id, status);
    for (int l = 0; l < WL_SWEEP_N_LOADS; l++) {
      if (!sw->has_load[l]) continue;
      const struct wl_sweep_loads *ld = &r->load[l];
      const int have = r->state != WL_SWEEP_PENDING && ld->present;
      printf(" %18.5g %22.5g", have ? ld->peak_force / 1e3 : NAN,
             have ? ld->impulse_positive / 1e3 : NAN);
    }
    if (r->state == WL_SWEEP_PENDING)
      printf("  %9s\n", "-");
    else
      printf("  %8.1fs%s\n", r->runtime_s, r->state == WL_SWEEP_REUSED ? " (reused)" : "");
  }
  printf("\nresults in %s/ (sweep.csv, sweep.h5%s; each case's results in cases/)\n", dir,
         pdf ? ", sweep.pdf" : "; sweep.pdf once every case has run");
}

static enum wl_status sweep_stoppable(void *user, volatile sig_atomic_t *stop,
                                      struct wl_error *err) {
  struct sweep_args *a = user;
  struct wl_sweep_ranks *ranks = a->ranks;
  const int lead = ranks->rank == 0, shared = ranks->size > 1;
  struct wl_scenario s;
  struct wl_sweep sw;
  /* every rank reads the file (it must see it) and prices the sweep; each
   * failure is agreed on, so that all stop and one says why */
  const enum wl_status loaded = wl_cli_load_sweep(a->path, &s, &sw, err);
  enum wl_status st = wl_sweep_ranks_agree(ranks, loaded, err);
  if (st) {
    if (loaded == WL_OK) { /* this rank loaded; another did not */
      wl_sweep_clear(&sw);
      wl_scenario_clear(&s);
    }
    return st;
  }
  char dir[600];
  if (a->out_dir) snprintf(dir, sizeof dir, "%s", a->out_dir);
  else snprintf(dir, sizeof dir, "%s-sweep", s.name.text);
  struct wl_assess_opts opts = a->opts;
  /* under mpirun, ranks that share a host share its cores, unless the
   * command, the scenario or OMP_NUM_THREADS says how many */
  if (shared && !opts.threads && s.run.threads.is_auto && !getenv("OMP_NUM_THREADS"))
    opts.threads = ranks->threads;
  /* the whole sweep priced and judged before anything runs, as check does */
  st = wl_cli_sweep_price(&sw, &opts, a->budget_s, a->force_large, NULL, err);
  if (st == WL_OK && *stop)
    st = wl_error_set(err, WL_EINTERRUPTED,
                      "interrupted by %s before the sweep started; nothing written",
                      wl_assess_stop_signal_name(*stop));
  st = wl_sweep_ranks_agree(ranks, st, err);
  if (st == WL_OK) {
    struct sweep_view view = {a, {isatty(2), 0.0}, 0, sw.n_cases};
    opts.interrupted = stop;
    /* under mpirun the log says which case starts and ends where; no
     * progress line (the ranks' output interleaves) */
    if (!a->quiet && lead) {
      if (!shared) {
        opts.progress = case_progress;
        opts.user = &view;
      }
      fprintf(stderr, "wallload: %s: a sweep of %d cases into %s/", a->path, sw.n_cases, dir);
      if (shared) fprintf(stderr, ", shared among %d MPI ranks", ranks->size);
      fputc('\n', stderr);
    }
    struct wl_sweep_events ev = {case_begin, case_end, &view, rank_ready};
    st = wl_sweep_run_ranks(&sw, dir, &opts, &ev, ranks, err);
    if (lead && st != WL_EINPUT && sw.rows) print_rows(&sw, dir, st != WL_EINTERRUPTED);
  }
  wl_sweep_clear(&sw);
  wl_scenario_clear(&s);
  return st;
}

/* The options into a; WL_EUSAGE when one is wrong. */
static enum wl_status parse_args(struct sweep_args *a, int argc, char **argv,
                                 struct wl_error *err) {
  int used;
  for (int i = 1; i < argc; i++) {
    const char *o = argv[i];
    if (!strcmp(o, "-o") || !strcmp(o, "--backend") || !strcmp(o, "--threads") ||
        !strcmp(o, "--end-time") || !strcmp(o, "--rank-timeout")) {
      if (i + 1 >= argc) return wl_error_set(err, WL_EUSAGE, "sweep: %s needs a value", o);
      const char *v = argv[++i];
      char *end;
      if (!strcmp(o, "-o")) {
        a->out_dir = v;
      } else if (!strcmp(o, "--threads")) {
        const long n = strtol(v, &end, 10);
        if (*end || n < 1 || n > 4096)
          return wl_error_set(err, WL_EUSAGE, "sweep: --threads: found '%s'; expected 1 to 4096", v);
        a->opts.threads = (int)n;
      } else if (!strcmp(o, "--end-time")) {
        const double t = strtod(v, &end);
        if (*end || !(t > 0))
          return wl_error_set(err, WL_EUSAGE, "sweep: --end-time: found '%s'; expected seconds > 0",
                              v);
        a->opts.end_time = t;
      } else if (!strcmp(o, "--rank-timeout")) {
        const double t = strtod(v, &end);
        if (*end || !(t >= 10 && t <= 1e7))
          return wl_error_set(err, WL_EUSAGE,
                              "sweep: --rank-timeout: found '%s'; expected seconds, 10 to 1e7", v);
        a->ranks->silence_s = t;
      } else if (strcmp(v, "cpu") && strcmp(v, "cuda") && strcmp(v, "auto")) {
        return wl_error_set(err, WL_EUSAGE, "sweep: --backend: found '%s'; valid: cpu, cuda, auto", v);
      } else {
        a->opts.backend = v;
      }
    } else if ((used = wl_cli_budget_option("sweep", argc, argv, &i, &a->budget_s, &a->force_large,
                                            err))) {
      if (used < 0) return WL_EUSAGE;
    } else if (!strcmp(o, "--quiet")) {
      a->quiet = 1;
    } else if (o[0] == '-') {
      return wl_error_set(err, WL_EUSAGE,
                          "sweep: unknown option '%s'; valid: -o DIR, --backend cpu|cuda|auto, "
                          "--threads N, --quiet, --end-time SECONDS, --budget HOURS, --force-large, "
                          "--rank-timeout SECONDS",
                          o);
    } else if (!a->path) {
      a->path = o;
    } else {
      return wl_error_set(err, WL_EUSAGE, "sweep: one scenario file at a time ('%s' extra)", o);
    }
  }
  if (!a->path) return wl_error_set(err, WL_EUSAGE, SWEEP_USAGE);
  return WL_OK;
}

enum wl_status wl_cli_sweep(int argc, char **argv, struct wl_sweep_ranks *ranks,
                            struct wl_error *err) {
  struct sweep_args a;
  memset(&a, 0, sizeof a);
  /* first, before anything could start CUDA: under mpirun each rank's GPU
   * is chosen through the environment (sweep.h) */
  enum wl_status st = wl_sweep_ranks_init(ranks, err);
  if (st) return st;
  a.ranks = ranks;
  st = wl_sweep_ranks_agree(ranks, parse_args(&a, argc, argv, err), err);
  if (st == WL_OK) st = wl_cli_with_stop_signals(sweep_stoppable, &a, err);
  return st;
}
