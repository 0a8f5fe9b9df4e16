/* validate.c: `wallload validate [CASE...] [--ladder N] [--quick] [-o DIR]
 * [--threads N] [--integrator NAME] [--backend cpu|cuda|auto] [--reference DIR]`: run the
 * reference cases of reference/
 * on a resolution ladder, print per case and level the particles, steps,
 * runtime and metrics with pass/fail, the observed order and the
 * Richardson-extrapolated error, and write validation.{json,csv,pdf}. */
#define _POSIX_C_SOURCE 200809L /* mkdir */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "wallload/error.h"
#include "wallload/loads.h"
#include "wallload/sph.h"
#include "wallload/validate.h"

#define VALIDATE_USAGE                                                                            \
  "usage: wallload validate [CASE...] [--ladder N] [--quick] [-o DIR] [--threads N] "            \
  "[--integrator symplectic|verlet] [--residual-viscosity A] [--smagorinsky CS] "                \
  "[--backend cpu|cuda|auto] "      \
  "[--reference DIR]"

static void help(void) {
  printf("%s\n\n"
         "Run reference cases (reference/<case>/README.md says what each checks) on a ladder of\n"
         "resolutions dp, dp/sqrt2, dp/2, ...; print error, runtime and the observed order.\n"
         "  CASE...          case names or the group 'solitary' (default: all)\n"
         "  --ladder N       levels per case, 1 to 6 (default 3, the solitary cases 5;\n"
         "                   the order needs 3)\n"
         "  --quick          each case's coarse, short ladder (seconds to a minute per case;\n"
         "                   spheric2, 3D: one level, about 10 minutes on 2 cores)\n"
         "  -o DIR           output directory (default validation-results; created)\n"
         "  --threads N      OpenMP threads per run (default: OpenMP's)\n"
         "  --integrator NAME  symplectic (default) or verlet: the time integrator of every run\n"
         "  --residual-viscosity A  every run with the residual viscosity alpha_r = A (0 to 1;\n"
         "                   default 0, off; docs/numerics.md)\n"
         "  --smagorinsky CS every run with the eddy viscosity (CS dp)^2 |S| (0 to 0.3; default\n"
         "                   0, off; 0.12 as DualSPHysics' Laminar+SPS; docs/numerics.md)\n"
         "  --backend NAME   cpu (default), cuda, or auto (the GPU when there is one), as assess;\n"
         "                   spheric2's full ladder (0.2 to 1.1 M particles) is a GPU run: on\n"
         "                   2 CPU cores its finest level alone would take more than a day\n"
         "  --reference DIR  the reference/ directory (default: the source tree's)\n"
         "  --list           list the cases\n"
         "exit: 0 every case passes, 1 a case misses its tolerance or a run fails, 2 bad input\n\n"
         "cases:\n",
         VALIDATE_USAGE);
  for (int i = 0; i < wl_validate_n_cases(); i++)
    printf("  %-20s %s\n", wl_validate_case_name(i), wl_validate_case_title(i));
}

static void print_metric(const struct wl_validate_metric *m) {
  const char *mark = isnan(m->tol) ? "info" : (m->pass ? "pass" : "FAIL");
  switch (m->kind) {
  case WL_VALIDATE_REL:
    if (isnan(m->tol)) /* reported, not judged */
      printf("      %-34s %12.5g vs %-12.5g %-6s error %+8.2f %%  tol    n/a  %s\n", m->name,
             m->value, m->reference, m->unit, 100 * m->error, mark);
    else
      printf("      %-34s %12.5g vs %-12.5g %-6s error %+8.2f %%  tol %.1f %%  %s\n", m->name,
             m->value, m->reference, m->unit, 100 * m->error, 100 * m->tol, mark);
    break;
  case WL_VALIDATE_RMSE:
  case WL_VALIDATE_RATIO:
    if (isnan(m->tol))
      printf("      %-34s %12.5g / %-12.5g %-6s = %8.2f %%   tol    n/a  %s\n", m->name,
             m->value, m->reference, m->unit, 100 * m->error, mark);
    else
      printf("      %-34s %12.5g / %-12.5g %-6s = %8.2f %%   tol %.1f %%  %s\n", m->name,
             m->value, m->reference, m->unit, 100 * m->error, 100 * m->tol, mark);
    break;
  case WL_VALIDATE_CORR:
    if (isnan(m->tol))
      printf("      %-34s r = %.4f%34s tol      n/a  %s\n", m->name, m->value, "", mark);
    else
      printf("      %-34s r = %.4f%34s tol >= %.3f  %s\n", m->name, m->value, "", m->tol, mark);
    break;
  }
}

/* Progress of a level's run on stderr: a line redrawn on a terminal; in a
 * log, a line a minute, so the short cases print none. */
struct progress_state {
  int tty;
  double last_print;
  const char *name; /* the run last seen */
  int level;
};

static void on_progress(void *user, const char *name, int level,
                        const struct wl_sph_progress *pr) {
  struct progress_state *ps = user;
  if (name != ps->name || level != ps->level) { /* a new run */
    ps->name = name;
    ps->level = level;
    ps->last_print = 0;
  }
  const double frac = pr->t_end > 0 ? pr->t / pr->t_end : 0;
  const double eta = frac > 0 ? pr->wall_s * (1 - frac) / frac : NAN;
  if (ps->tty) {
    fprintf(stderr, "\r  %s level %d: t = %.3f / %.3f s (%3.0f %%), %.0f steps/s, ETA %.0f s   ",
            name, level + 1, pr->t, pr->t_end, 100 * frac, pr->steps_per_s, eta);
    if (pr->t >= pr->t_end) fputc('\n', stderr);
  } else if (pr->wall_s - ps->last_print >= 60.0) {
    fprintf(stderr, "  %s level %d: t = %.3f / %.3f s (%.0f %%), %.0f steps/s, ETA %.0f s\n", name,
            level + 1, pr->t, pr->t_end, 100 * frac, pr->steps_per_s, eta);
    ps->last_print = pr->wall_s;
  }
  fflush(stderr);
}

static void on_level(void *user, const struct wl_validate_result *r, int l) {
  (void)user;
  const struct wl_validate_level *lv = &r->lv[l];
  printf("  level %d: dp = %-9.4g m  %7d particles  %7ld steps  %8.1f s%s%s\n", l + 1, lv->dp,
         lv->n_particles, lv->steps, lv->runtime_s, lv->status ? "  STOPPED: " : "",
         lv->status ? lv->message : "");
  for (int j = 0; j < lv->n_metrics; j++) print_metric(&lv->m[j]);
  fflush(stdout);
}

enum wl_status wl_cli_validate(int argc, char **argv, struct wl_error *err) {
  const int n_cases = wl_validate_n_cases();
  int *sel = calloc((size_t)n_cases, sizeof(int));
  if (!sel) return wl_error_set(err, WL_ENOMEM, "validate: no memory");
  struct wl_validate_opts opts = {0};
  const char *out_dir = "validation-results";
  int any = 0;
  enum wl_status st = WL_OK;
  for (int i = 1; i < argc && !st; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
      help();
      free(sel);
      return WL_OK;
    } else if (!strcmp(a, "--list")) {
      for (int c = 0; c < n_cases; c++)
        printf("%-20s %s\n", wl_validate_case_name(c), wl_validate_case_title(c));
      free(sel);
      return WL_OK;
    } else if (!strcmp(a, "--quick")) {
      opts.quick = 1;
    } else if (!strcmp(a, "-o") || !strcmp(a, "--ladder") || !strcmp(a, "--threads") ||
               !strcmp(a, "--reference") || !strcmp(a, "--integrator") ||
               !strcmp(a, "--residual-viscosity") || !strcmp(a, "--smagorinsky") ||
               !strcmp(a, "--backend")) {
      if (i + 1 >= argc) {
        st = wl_error_set(err, WL_EUSAGE, "validate: %s needs a value\n%s", a, VALIDATE_USAGE);
        break;
      }
      const char *v = argv[++i];
      char *end;
      if (!strcmp(a, "-o")) {
        out_dir = v;
      } else if (!strcmp(a, "--reference")) {
        opts.reference_dir = v;
      } else if (!strcmp(a, "--backend")) {
        if (!strcmp(v, "cpu") || !strcmp(v, "cuda") || !strcmp(v, "auto"))
          opts.backend = v;
        else
          st = wl_error_set(err, WL_EUSAGE,
                            "validate: --backend: found '%s'; valid: cpu, cuda, auto", v);
      } else if (!strcmp(a, "--residual-viscosity")) {
        const double r = strtod(v, &end);
        if (*end || !(r >= 0 && r <= WL_SPH_ALPHA_MAX))
          st = wl_error_set(err, WL_EUSAGE,
                            "validate: --residual-viscosity: found '%s'; expected 0 to %g", v,
                            WL_SPH_ALPHA_MAX);
        opts.residual = r;
      } else if (!strcmp(a, "--smagorinsky")) {
        const double cs = strtod(v, &end);
        if (*end || !(cs >= 0 && cs <= WL_SPH_SMAGORINSKY_MAX))
          st = wl_error_set(err, WL_EUSAGE, "validate: --smagorinsky: found '%s'; expected 0 to %g",
                            v, WL_SPH_SMAGORINSKY_MAX);
        opts.smagorinsky = cs;
      } else if (!strcmp(a, "--integrator")) {
        if (!strcmp(v, "verlet") || !strcmp(v, "symplectic"))
          opts.verlet = !strcmp(v, "verlet");
        else
          st = wl_error_set(err, WL_EUSAGE,
                            "validate: --integrator: found '%s'; valid: symplectic, verlet", v);
      } else if (!strcmp(a, "--ladder")) {
        long n = strtol(v, &end, 10);
        if (*end || n < 1 || n > WL_VALIDATE_MAX_LEVELS)
          st = wl_error_set(err, WL_EUSAGE, "validate: --ladder: found '%s'; expected 1 to %d", v,
                            WL_VALIDATE_MAX_LEVELS);
        opts.n_levels = (int)n;
      } else {
        long n = strtol(v, &end, 10);
        if (*end || n < 1 || n > 4096)
          st = wl_error_set(err, WL_EUSAGE, "validate: --threads: found '%s'; expected 1 to 4096", v);
        opts.threads = (int)n;
      }
    } else if (a[0] == '-') {
      st = wl_error_set(err, WL_EUSAGE,
                        "validate: unknown option '%s'; valid: --ladder N, --quick, -o DIR, "
                        "--threads N, --integrator NAME, --residual-viscosity A, --smagorinsky CS, "
                        "--backend NAME, "
                        "--reference DIR, "
                        "--list\n%s",
                        a, VALIDATE_USAGE);
    } else {
      st = wl_validate_select(a, sel, err);
      any = 1;
    }
  }
  if (st) {
    free(sel);
    return st;
  }
  if (!any)
    for (int i = 0; i < n_cases; i++) sel[i] = 1;
  if (mkdir(out_dir, 0777) != 0 && errno != EEXIST) {
    st = wl_error_set(err, errno == ENOSPC || errno == EIO || errno == EDQUOT ? WL_EIO : WL_EINPUT,
                      "validate: %s: cannot create the output directory (%s)", out_dir,
                      strerror(errno));
    free(sel);
    return st;
  }
  struct wl_validate_result *res = calloc((size_t)n_cases, sizeof *res);
  if (!res) {
    free(sel);
    return wl_error_set(err, WL_ENOMEM, "validate: no memory");
  }
  opts.on_level = on_level;
  struct progress_state ps = {isatty(2), 0.0, NULL, -1};
  opts.progress = on_progress;
  opts.user = &ps;
  int n_done = 0;
  for (int i = 0; i < n_cases && !st; i++) {
    if (!sel[i]) continue;
    printf("%s: %s\n", wl_validate_case_name(i), wl_validate_case_title(i));
    fflush(stdout);
    st = wl_validate_run(i, &opts, &res[n_done], err);
    const struct wl_validate_result *r = &res[n_done];
    if (st) break;
    n_done++;
    if (r->n_levels >= 3 && !isfinite(r->order))
      printf("  order: undefined (equal errors on the last levels)\n");
    else if (r->n_levels >= 3 && r->order_ok)
      printf("  order p = %.2f, Richardson-extrapolated primary error %.4g\n", r->order,
             r->extrapolated);
    else if (r->n_levels >= 3)
      printf("  order p = %.2f (not meaningful: non-monotone or outside [%.1f, %.1f]); no "
             "extrapolation\n",
             r->order, WL_LOADS_ORDER_MIN, WL_LOADS_ORDER_MAX);
    else
      printf("  order: needs 3 levels\n");
    printf("  %s: %s\n\n", r->pass ? "PASS" : "FAIL", r->verdict);
    fflush(stdout);
  }
  if (st) {
    /* a bad reference or option: whatever ran is still worth writing */
    struct wl_error e2;
    wl_error_clear(&e2);
    if (n_done) wl_validate_write(out_dir, res, n_done, &e2);
    free(res);
    free(sel);
    return st;
  }
  st = wl_validate_write(out_dir, res, n_done, err);
  if (!st) {
    printf("%-20s %-6s %s\n", "case", "result", "finest level");
    char failed[1024] = "";
    int n_failed = 0;
    for (int i = 0; i < n_done; i++) {
      printf("%-20s %-6s %s\n", res[i].name, res[i].pass ? "pass" : "FAIL", res[i].verdict);
      if (!res[i].pass) {
        size_t u = strlen(failed);
        snprintf(failed + u, sizeof failed - u, "%s%s", n_failed ? ", " : "", res[i].name);
        n_failed++;
      }
    }
    printf("\nvalidation table and plot in %s/ (validation.json, validation.csv, validation.pdf)\n",
           out_dir);
    if (n_failed)
      st = wl_error_set(err, WL_ENUMERIC, "validate: %d of %d case(s) missed their tolerance: %s",
                        n_failed, n_done, failed);
  }
  free(res);
  free(sel);
  return st;
}
