/* plot.c: DIR/sweep.pdf, the sweep's envelopes, drawn by the report module
 * (report.h wl_report_sweep_render) from the rows and each case's
 * results.h5. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sweep_private.h"
#include "wallload/report.h"

enum { N_ARRAYS = 6 }; /* per load case: the quantities the report draws */

enum wl_status sweep_write_pdf(const struct wl_sweep *sw, const char *dir, struct wl_error *err) {
  const size_t n = (size_t)sw->n_cases;
  struct wl_report_sweep r;
  memset(&r, 0, sizeof r);
  r.scenario = sw->name;
  r.file = sw->path;
  r.n_cases = sw->n_cases;
  r.n_params = sw->n_params;
  double *vals = malloc((size_t)sw->n_params * n * sizeof *vals);
  double *loads = malloc(WL_SWEEP_N_LOADS * N_ARRAYS * n * sizeof *loads);
  const char **ids = malloc(n * sizeof *ids), **status = malloc(n * sizeof *status);
  const char **results = calloc(n, sizeof *results);
  char(*paths)[1200] = malloc(n * sizeof *paths);
  enum wl_status st = WL_OK;
  if (!vals || !loads || !ids || !status || !results || !paths) {
    st = wl_error_set(err, WL_ENOMEM, "%s/sweep.pdf: no memory", dir);
    goto done;
  }
  for (int k = 0; k < sw->n_params; k++) {
    const enum wl_sweep_param p = sw->order[k];
    r.params[k].name = wl_scenario_sweep_param_name(p);
    r.params[k].unit = sweep_param_unit(p);
    r.params[k].value = vals + (size_t)k * n;
    for (size_t i = 0; i < n; i++) vals[(size_t)k * n + i] = sw->cases[i].value[p];
  }
  for (int l = 0; l < WL_SWEEP_N_LOADS; l++) {
    double *a[N_ARRAYS];
    for (int j = 0; j < N_ARRAYS; j++) a[j] = loads + ((size_t)l * N_ARRAYS + (size_t)j) * n;
    struct wl_report_sweep_load *rl = &r.load[l];
    rl->present = sw->has_load[l];
    rl->peak_force = a[0], rl->peak_force_boundary = a[1], rl->impulse_positive = a[2];
    rl->peak_moment = a[3], rl->max_runup = a[4], rl->uncertainty = a[5];
    for (size_t i = 0; i < n; i++) {
      const struct wl_sweep_row *row = &sw->rows[i];
      const struct wl_sweep_loads *ld = &row->load[l];
      const int have = row->state != WL_SWEEP_PENDING && ld->present;
      a[0][i] = have ? ld->peak_force : NAN;
      a[1][i] = have ? ld->peak_force_boundary : NAN;
      a[2][i] = have ? ld->impulse_positive : NAN;
      a[3][i] = have ? ld->peak_moment : NAN;
      a[4][i] = have ? ld->max_runup : NAN;
      a[5][i] = have ? ld->uncertainty : NAN;
    }
  }
  for (size_t i = 0; i < n; i++) {
    ids[i] = sw->cases[i].id;
    status[i] = sweep_status_word(&sw->rows[i], sw->rows[i].status);
    snprintf(paths[i], sizeof paths[i], "%s/cases/%s/results.h5", dir, sw->cases[i].id);
    struct stat sb;
    if (sw->rows[i].state != WL_SWEEP_PENDING && stat(paths[i], &sb) == 0) results[i] = paths[i];
  }
  r.case_id = ids;
  r.status = status;
  r.results = results;
  char pdf[1200];
  snprintf(pdf, sizeof pdf, "%s/sweep.pdf", dir);
  st = wl_report_sweep_render(&r, pdf, err);
done:
  free(vals), free(loads), free(ids), free(status), free(results), free(paths);
  return st;
}
