/* cli.h: the subcommands (each parses its own arguments; argv[0] is the
 * command name). They print results to stdout and return a status; main()
 * prints the error. */
#ifndef WALLLOAD_CLI_H
#define WALLLOAD_CLI_H

#include <signal.h>
#include <stdio.h>

#include "wallload/assess.h"
#include "wallload/error.h"
#include "wallload/sweep.h"

enum wl_status wl_cli_check(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_convert(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_assess(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_report(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_validate(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_bench(int argc, char **argv, struct wl_error *err);
/* ranks: this process among mpirun's, started here; main() finishes it
 * (wl_sweep_ranks_finish) after printing, so that no rank exits, and
 * mpirun ends the job, before rank 0 has said why. */
enum wl_status wl_cli_sweep(int argc, char **argv, struct wl_sweep_ranks *ranks,
                            struct wl_error *err);

/* Shared by assess and sweep (check.c). */

/* The progress line of a running case (a wl_assess_progress_fn); user is a
 * struct wl_cli_progress. */
struct wl_cli_progress {
  int tty;           /* stderr is a terminal: one line rewritten in place */
  double last_print; /* [s] of the run, for a log file's line every 30 s */
};
void wl_cli_show_progress(void *user, const char *name, const struct wl_sph_progress *pr);

/* Run fn with SIGINT, SIGTERM and SIGHUP caught into the stop flag it gets
 * (the signal's number once one came), the previous actions put back after. */
typedef enum wl_status (*wl_cli_stoppable_fn)(void *user, volatile sig_atomic_t *stop,
                                              struct wl_error *err);
enum wl_status wl_cli_with_stop_signals(wl_cli_stoppable_fn fn, void *user, struct wl_error *err);

/* Load the sweep scenario `path` into s (its report template found and
 * read) and make its cases into sw. On failure both are cleared. */
enum wl_status wl_cli_load_sweep(const char *path, struct wl_scenario *s, struct wl_sweep *sw,
                                 struct wl_error *err);

/* Price a sweep: each case's cost as `check` prices it alone (plan.h; the
 * ladder's levels summed), printed one line a case to out (NULL: nothing),
 * then the total, judged against the machine and the budget as one run
 * (memory: the largest case's; time: the sum). */
enum wl_status wl_cli_sweep_price(const struct wl_sweep *sw, const struct wl_assess_opts *opts,
                                  double budget_s, int force_large, FILE *out,
                                  struct wl_error *err);

/* --budget HOURS and --force-large: 1 when argv[*i] is one of them
 * (consumed), 0 when not, -1 on a bad value (err set). */
int wl_cli_budget_option(const char *cmd, int argc, char **argv, int *i, double *budget_s,
                         int *force_large, struct wl_error *err);

#endif
