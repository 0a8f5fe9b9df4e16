/* sweep.c: the envelope PDF of a sweep (report.h wl_report_sweep_render).
 *
 * For each swept parameter: every case's loads against it, and each load
 * case's envelope, the largest value over the other parameters at each of
 * its values (an engineer designs for the worst combination). The design
 * formulae are those of the design_formulae section, evaluated on each
 * case's stored results with the same inputs (wl_report_design_inputs). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sections.h"
#include "wallload/config.h"
#include "wallload/design.h"

enum { N_LOADS = 2, N_QTY = 4, MAX_FORMULAE = WL_DESIGN_MAX_RESULTS };

/* The quantities plotted against each parameter. */
struct qty {
  const char *label, *unit;
  double scale; /* SI -> the page's unit */
};
static const struct qty QTY[N_QTY] = {
    {"peak force (probes, filtered)", "kN/m", KILO},
    {"positive impulse", "kN s/m", KILO},
    {"peak overturning moment", "kN m/m", KILO},
    {"maximum run-up at the wall", "m", 1.0},
};

static const double *qty_data(const struct wl_report_sweep_load *l, int q) {
  return q == 0 ? l->peak_force : q == 1 ? l->impulse_positive : q == 2 ? l->peak_moment
                                                                         : l->max_runup;
}

/* Palette entries: the solitary wave and the explosion keep their colours on every plot. */
static const int LOAD_COLOUR[N_LOADS] = {2, 6};

/* The distinct values of parameter p over the cases, increasing; returns how many. */
static int distinct(const struct wl_report_sweep *sw, int p, double *out) {
  int n = 0;
  for (int i = 0; i < sw->n_cases; i++) {
    const double v = sw->params[p].value[i];
    int seen = 0;
    for (int j = 0; j < n && !seen; j++) seen = out[j] == v;
    if (!seen) out[n++] = v;
  }
  for (int i = 1; i < n; i++) /* insertion sort: a handful of values */
    for (int j = i; j > 0 && out[j] < out[j - 1]; j--) {
      const double t = out[j];
      out[j] = out[j - 1], out[j - 1] = t;
    }
  return n;
}

/* env[k]: the largest finite y (scaled) over the cases at the k-th distinct value. */
static void envelope(const struct wl_report_sweep *sw, int p, const double *xs, int nx,
                     const double *y, double scale, double *env) {
  for (int k = 0; k < nx; k++) {
    env[k] = NAN;
    for (int i = 0; i < sw->n_cases; i++)
      if (sw->params[p].value[i] == xs[k] && isfinite(y[i]) && !(env[k] >= y[i] / scale))
        env[k] = y[i] / scale;
  }
}

/* A log axis where a parameter spans a decade or more (charges, energies). */
static int log_axis(const double *xs, int nx) {
  return nx > 1 && xs[0] > 0 && xs[nx - 1] / xs[0] >= 10.0;
}

/* Where the governing load case changes along the envelopes: vertical
 * lines half-way between the values it changes between, with a note. */
static int governing_changes(const double *xs, int nx, const double *env_s, const double *env_e,
                             struct wl_report_refline *refs, char labels[][64], int max_refs) {
  int n = 0, prev = -1;
  for (int k = 0; k < nx; k++) {
    const int g = wl_report_governs(env_s[k], env_e[k]);
    if (g < 0) continue;
    if (prev >= 0 && g != prev && n < max_refs) {
      int kp = k - 1;
      while (kp > 0 && wl_report_governs(env_s[kp], env_e[kp]) < 0) kp--;
      snprintf(labels[n], 64, "%s governs", g == WL_RESULTS_CASE_EXPLOSION ? "explosion" : "solitary");
      refs[n].at = 0.5 * (xs[kp] + xs[k]);
      refs[n].vertical = 1;
      refs[n].label = labels[n];
      n++;
    }
    prev = g;
  }
  return n;
}

/* One figure per parameter: the four quantities against it. */
static enum wl_status loads_figure(struct wl_report_doc *d, const struct wl_report_sweep *sw,
                                   int p, struct wl_report_scratch *sc, struct wl_error *err) {
  const struct wl_report_sweep_param *par = &sw->params[p];
  double *xs = wl_report_scratch_alloc(sc, (size_t)sw->n_cases);
  if (!xs) return wl_error_set(err, WL_ENOMEM, "sweep report: no memory");
  const int nx = distinct(sw, p, xs);
  struct wl_report_rect area;
  enum wl_status st = wl_report_begin_figure(d, 430, &area, err);
  for (int q = 0; !st && q < N_QTY; q++) {
    struct wl_report_series series[2 * N_LOADS];
    int ns = 0;
    double *env[N_LOADS] = {NULL, NULL};
    for (int l = 0; l < N_LOADS; l++) {
      const struct wl_report_sweep_load *ld = &sw->load[l];
      if (!ld->present) continue;
      double *y = wl_report_scratch_scaled(sc, qty_data(ld, q), (size_t)sw->n_cases, QTY[q].scale);
      env[l] = wl_report_scratch_alloc(sc, (size_t)nx);
      if (!y || !env[l]) return wl_error_set(err, WL_ENOMEM, "sweep report: no memory");
      envelope(sw, p, xs, nx, qty_data(ld, q), QTY[q].scale, env[l]);
      const char *who = l == 0 ? "solitary" : "explosion";
      series[ns++] = (struct wl_report_series){who, xs, env[l], (size_t)nx, WL_REPORT_LINE_SOLID,
                                               WL_REPORT_MARKER_NONE, LOAD_COLOUR[l]};
      series[ns++] = (struct wl_report_series){NULL, par->value, y, (size_t)sw->n_cases,
                                               WL_REPORT_LINE_NONE,
                                               l == 0 ? WL_REPORT_MARKER_CIRCLE
                                                      : WL_REPORT_MARKER_SQUARE,
                                               LOAD_COLOUR[l]};
    }
    struct wl_report_refline refs[8];
    char labels[8][64];
    int nr = 0;
    if (env[0] && env[1] && q < 2) nr = governing_changes(xs, nx, env[0], env[1], refs, labels, 8);
    struct wl_report_plot plot = {QTY[q].label,
                                  {par->name, par->unit, log_axis(xs, nx), 0, 0, 0},
                                  {QTY[q].label, QTY[q].unit, 0, 0, 0, 0},
                                  series,
                                  ns,
                                  refs,
                                  nr,
                                  WL_REPORT_LEGEND_AUTO};
    st = wl_report_draw_plot(d, &plot, wl_report_rect_cell(area, 2, 2, q, 14), err);
  }
  char cap[400];
  snprintf(cap, sizeof cap,
           "Loads against %s [%s], per metre of wall: every case (markers: circles the solitary "
           "wave, squares the explosion) and each load case's envelope (lines: the largest over "
           "the other parameters). A vertical line marks where the governing load case changes "
           "along the envelopes.",
           par->name, par->unit);
  if (!st) st = wl_report_end_figure(d, cap, err);
  return st;
}

/* The design formulae's total forces per case and load case: value[l][f][i]. */
struct design_table {
  int n_formulae;
  char name[MAX_FORMULAE][32];
  int out_of_range[MAX_FORMULAE]; /* at some case */
  double *value[N_LOADS][MAX_FORMULAE];
};

static int formula_index(struct design_table *t, const char *name) {
  for (int f = 0; f < t->n_formulae; f++)
    if (!strcmp(t->name[f], name)) return f;
  if (t->n_formulae == MAX_FORMULAE) return -1;
  snprintf(t->name[t->n_formulae], sizeof t->name[0], "%s", name);
  return t->n_formulae++;
}

/* Evaluate the formulae on every case's results (a case whose results do
 * not read is left out: its row says why elsewhere). */
static enum wl_status design_values(const struct wl_report_sweep *sw, struct design_table *t,
                                    struct wl_report_scratch *sc, int *n_read,
                                    struct wl_error *err) {
  memset(t, 0, sizeof *t);
  *n_read = 0;
  for (int l = 0; l < N_LOADS; l++)
    for (int f = 0; f < MAX_FORMULAE; f++) {
      t->value[l][f] = wl_report_scratch_alloc(sc, (size_t)sw->n_cases);
      if (!t->value[l][f]) return wl_error_set(err, WL_ENOMEM, "sweep report: no memory");
      for (int i = 0; i < sw->n_cases; i++) t->value[l][f][i] = NAN;
    }
  struct wl_results *r = malloc(sizeof *r);
  if (!r) return wl_error_set(err, WL_ENOMEM, "sweep report: no memory");
  wl_store_results_init(r);
  for (int i = 0; i < sw->n_cases; i++) {
    if (!sw->results[i]) continue;
    struct wl_error e;
    wl_error_clear(&e);
    if (wl_store_results_read(sw->results[i], r, &e) != WL_OK) continue;
    (*n_read)++;
    for (int l = 0; l < N_LOADS; l++) {
      struct wl_design_scenario ds;
      char hs[256], ts[256];
      if (!r->cases[l].present || !wl_report_design_inputs(r, l, &ds, hs, ts, sizeof hs)) continue;
      struct wl_design_result res[WL_DESIGN_MAX_RESULTS];
      int n = 0;
      wl_error_clear(&e);
      if (wl_design_evaluate(&ds, res, WL_DESIGN_MAX_RESULTS, &n, &e) != WL_OK) continue;
      for (int k = 0; k < n; k++) {
        const int f = formula_index(t, res[k].name);
        if (f < 0) continue;
        t->value[l][f][i] = res[k].force_total;
        if (!res[k].in_range) t->out_of_range[f] = 1;
      }
    }
    wl_store_results_clear(r);
  }
  free(r);
  return WL_OK;
}

/* The simulated peak force's envelope beside the formulae's, per load case. */
static enum wl_status design_figure(struct wl_report_doc *d, const struct wl_report_sweep *sw,
                                    int p, const struct design_table *t,
                                    struct wl_report_scratch *sc, struct wl_error *err) {
  const struct wl_report_sweep_param *par = &sw->params[p];
  double *xs = wl_report_scratch_alloc(sc, (size_t)sw->n_cases);
  if (!xs) return wl_error_set(err, WL_ENOMEM, "sweep report: no memory");
  const int nx = distinct(sw, p, xs);
  int n_plots = 0;
  for (int l = 0; l < N_LOADS; l++) n_plots += sw->load[l].present;
  struct wl_report_rect area;
  enum wl_status st = wl_report_begin_figure(d, 230, &area, err);
  int cell = 0;
  for (int l = 0; !st && l < N_LOADS; l++) {
    if (!sw->load[l].present) continue;
    struct wl_report_series series[MAX_FORMULAE + 1];
    char labels[MAX_FORMULAE][64];
    int ns = 0;
    double *env = wl_report_scratch_alloc(sc, (size_t)nx);
    if (!env) return wl_error_set(err, WL_ENOMEM, "sweep report: no memory");
    envelope(sw, p, xs, nx, sw->load[l].peak_force, KILO, env);
    series[ns++] = (struct wl_report_series){"SPH peak force", xs, env, (size_t)nx,
                                             WL_REPORT_LINE_SOLID, WL_REPORT_MARKER_CIRCLE,
                                             LOAD_COLOUR[l]};
    for (int f = 0; f < t->n_formulae; f++) {
      double *fe = wl_report_scratch_alloc(sc, (size_t)nx);
      if (!fe) return wl_error_set(err, WL_ENOMEM, "sweep report: no memory");
      envelope(sw, p, xs, nx, t->value[l][f], KILO, fe);
      int any = 0;
      for (int k = 0; k < nx; k++) any |= isfinite(fe[k]);
      if (!any) continue;
      snprintf(labels[f], sizeof labels[f], "%s%s", t->name[f],
               t->out_of_range[f] ? " (out of range somewhere)" : "");
      series[ns++] = (struct wl_report_series){labels[f], xs, fe, (size_t)nx,
                                               WL_REPORT_LINE_DASHED, WL_REPORT_MARKER_NONE, 0};
    }
    char title[96];
    snprintf(title, sizeof title, "%s: peak force", wl_report_case_label(l));
    struct wl_report_plot plot = {title,
                                  {par->name, par->unit, log_axis(xs, nx), 0, 0, 0},
                                  {"total force", "kN/m", 0, 0, 0, 0},
                                  series,
                                  ns,
                                  NULL,
                                  0,
                                  WL_REPORT_LEGEND_BELOW};
    st = wl_report_draw_plot(d, &plot, wl_report_rect_cell(area, n_plots, 1, cell++, 14), err);
  }
  char cap[400];
  snprintf(cap, sizeof cap,
           "The simulated peak force (envelope over the other parameters) beside the design "
           "formulae's total forces (hydrostatic part included; each formula's envelope) "
           "against %s [%s], per metre of wall.",
           par->name, par->unit);
  if (!st) st = wl_report_end_figure(d, cap, err);
  return st;
}

/* A sentence per parameter and quantity: which load case governs where. */
static enum wl_status governing_text(struct wl_report_doc *d, const struct wl_report_sweep *sw,
                                     struct wl_report_scratch *sc, struct wl_error *err) {
  char text[4096];
  size_t u = 0;
  text[0] = '\0';
  for (int p = 0; p < sw->n_params; p++) {
    const struct wl_report_sweep_param *par = &sw->params[p];
    double *xs = wl_report_scratch_alloc(sc, (size_t)sw->n_cases);
    double *es = wl_report_scratch_alloc(sc, (size_t)sw->n_cases);
    double *ee = wl_report_scratch_alloc(sc, (size_t)sw->n_cases);
    if (!xs || !es || !ee) return wl_error_set(err, WL_ENOMEM, "sweep report: no memory");
    const int nx = distinct(sw, p, xs);
    for (int q = 0; q < 2; q++) {
      envelope(sw, p, xs, nx, qty_data(&sw->load[0], q), QTY[q].scale, es);
      envelope(sw, p, xs, nx, qty_data(&sw->load[1], q), QTY[q].scale, ee);
      if (u < sizeof text)
        u += (size_t)snprintf(text + u, sizeof text - u, "%s%s against %s:", u ? "\n" : "",
                              q == 0 ? "Peak force" : "Positive impulse", par->name);
      int prev = -2;
      for (int k = 0; k < nx && u < sizeof text; k++) {
        const int g = wl_report_governs(es[k], ee[k]);
        if (g == prev) continue;
        char v[32];
        wl_report_fmt(xs[k], 4, v, sizeof v);
        u += (size_t)snprintf(text + u, sizeof text - u, "%s %s from %s %s", prev == -2 ? "" : ";",
                              g < 0                           ? "no result"
                              : g == WL_RESULTS_CASE_EXPLOSION ? "the explosion governs"
                                                              : "the solitary wave governs",
                              v, par->unit);
        prev = g;
      }
      if (u < sizeof text) u += (size_t)snprintf(text + u, sizeof text - u, ".");
    }
  }
  return wl_report_add_paragraph(d, text, err);
}

/* The cases: inputs, status and the two loads to quote. */
static enum wl_status cases_table(struct wl_report_doc *d, const struct wl_report_sweep *sw,
                                  struct wl_error *err) {
  struct wl_report_column cols[WL_REPORT_TABLE_MAX_COLS];
  char heads[WL_REPORT_TABLE_MAX_COLS][48];
  int nc = 0;
  cols[nc++] = (struct wl_report_column){"case", NULL, WL_REPORT_ALIGN_LEFT, 0};
  for (int p = 0; p < sw->n_params; p++)
    cols[nc++] = (struct wl_report_column){sw->params[p].name, sw->params[p].unit,
                                           WL_REPORT_ALIGN_AUTO, 4};
  cols[nc++] = (struct wl_report_column){"status", NULL, WL_REPORT_ALIGN_LEFT, 0};
  for (int l = 0; l < N_LOADS; l++) {
    if (!sw->load[l].present) continue;
    snprintf(heads[nc], sizeof heads[0], "%s F", l == 0 ? "solitary" : "explosion");
    cols[nc] = (struct wl_report_column){heads[nc], "kN/m", WL_REPORT_ALIGN_AUTO, 3};
    nc++;
    snprintf(heads[nc], sizeof heads[0], "%s I+", l == 0 ? "solitary" : "explosion");
    cols[nc] = (struct wl_report_column){heads[nc], "kN s/m", WL_REPORT_ALIGN_AUTO, 3};
    nc++;
  }
  const int both = sw->load[0].present && sw->load[1].present;
  if (both) cols[nc++] = (struct wl_report_column){"governs F", NULL, WL_REPORT_ALIGN_LEFT, 0};
  struct wl_report_cell *cells = calloc((size_t)sw->n_cases * (size_t)nc, sizeof *cells);
  if (!cells) return wl_error_set(err, WL_ENOMEM, "sweep report: no memory");
  for (int i = 0; i < sw->n_cases; i++) {
    struct wl_report_cell *row = &cells[(size_t)i * (size_t)nc];
    int c = 0;
    row[c++].text = sw->case_id[i];
    for (int p = 0; p < sw->n_params; p++) row[c++].value = sw->params[p].value[i];
    row[c++].text = sw->status[i];
    for (int l = 0; l < N_LOADS; l++) {
      if (!sw->load[l].present) continue;
      row[c++].value = sw->load[l].peak_force[i] / KILO;
      row[c++].value = sw->load[l].impulse_positive[i] / KILO;
    }
    if (both) {
      const int g = wl_report_governs(sw->load[0].peak_force[i], sw->load[1].peak_force[i]);
      row[c++].text = g < 0 ? "-" : g == WL_RESULTS_CASE_EXPLOSION ? "explosion" : "solitary";
    }
  }
  struct wl_report_table t = {"The cases: swept values (SI), status, and the loads to quote "
                              "(peak force from the pressure probes, filtered; positive impulse)",
                              cols, nc, cells, sw->n_cases};
  enum wl_status st = wl_report_add_table(d, &t, err);
  free(cells);
  return st;
}

enum wl_status wl_report_sweep_render(const struct wl_report_sweep *sw, const char *pdf_path,
                                      struct wl_error *err) {
  struct wl_report_doc_info info = {"Wave loads over a sweep", sw->scenario, NULL, NULL};
  struct wl_report_doc *d = NULL;
  enum wl_status st = wl_report_doc_open(pdf_path, &info, &d, err);
  if (st) return st;
  struct wl_report_scratch sc = {{0}, 0};
  char sub[512], params[256] = "";
  for (int p = 0; p < sw->n_params; p++) {
    size_t u = strlen(params);
    snprintf(params + u, sizeof params - u, "%s%s", p ? " x " : "", sw->params[p].name);
  }
  int n_ok = 0;
  for (int i = 0; i < sw->n_cases; i++) n_ok += sw->results[i] != NULL;
  snprintf(sub, sizeof sub, "%s: %d cases (%s); %d with results", sw->scenario, sw->n_cases,
           params, n_ok);
  st = wl_report_add_title(d, "Wave loads over a sweep", sub, err);
  if (!st)
    st = wl_report_paragraphf(
        d, err,
        "Each case is the scenario %s with the swept values in place, run as `wallload assess` "
        "runs one scenario (its results in the sweep's cases/ directory). Quote the peak force "
        "from the pressure probes, filtered, and the positive impulse, each with the "
        "convergence ladder's uncertainty where the scenario runs one (sweep.csv's uncertainty "
        "columns); see README.md, Reading the report.",
        sw->file);
  if (!st) st = cases_table(d, sw, err);
  if (!st && sw->load[0].present && sw->load[1].present) {
    st = wl_report_add_heading(d, 1, "Where the governing load case changes", err);
    struct wl_report_scratch gs = {{0}, 0};
    if (!st) st = governing_text(d, sw, &gs, err);
    wl_report_scratch_free(&gs);
  }
  for (int p = 0; !st && p < sw->n_params; p++) {
    char h[128];
    snprintf(h, sizeof h, "Loads against %s", sw->params[p].name);
    st = wl_report_break_page(d, err);
    if (!st) st = wl_report_add_heading(d, 1, h, err);
    struct wl_report_scratch fs = {{0}, 0}; /* each figure its own: the slots are few */
    if (!st) st = loads_figure(d, sw, p, &fs, err);
    wl_report_scratch_free(&fs);
  }
  struct design_table t;
  int n_read = 0;
  if (!st) st = design_values(sw, &t, &sc, &n_read, err);
  if (!st) st = wl_report_break_page(d, err);
  if (!st) st = wl_report_add_heading(d, 1, "Design formulae", err);
  if (!st)
    st = wl_report_paragraphf(
        d, err,
        "The design formulae of the report's design_formulae section, evaluated for each case "
        "on its stored results (the wall as simulated; the solitary wave's height, or the "
        "explosion's leading wave at the gauge nearest the wall; the period from that gauge), "
        "%d of %d cases read. A formula outside its validity range is drawn all the same; each "
        "case's report (wallload report cases/<id>/results.h5) says where and why.",
        n_read, sw->n_cases);
  for (int p = 0; !st && p < sw->n_params; p++) {
    struct wl_report_scratch fs = {{0}, 0};
    st = design_figure(d, sw, p, &t, &fs, err);
    wl_report_scratch_free(&fs);
  }
  if (!st) st = wl_report_doc_finish(d, err);
  wl_report_doc_free(d);
  wl_report_scratch_free(&sc);
  return st;
}
