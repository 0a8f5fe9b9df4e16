/* sections_plots.c: the time-history sections. gauges: free-surface
 * elevation at each gauge, the two load cases overlaid. loads: wall force
 * (probes and boundary particles, raw and filtered), impulse and overturning
 * moment, the cases overlaid; the pressure distribution over the wall's
 * height at the time of each case's peak force; optionally the probe
 * pressure histories and the run-up at the wall face. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sections.h"

#define PLOT_H 170.0      /* one history plot [pt] */
#define PAIR_H 190.0      /* two plots side by side [pt] */
#define CELL_GAP 14.0     /* between plots of one figure [pt] */
#define MAX_PROBE_LINES 6 /* probe pressure histories drawn per case */
#define RHO_DEFAULT 1000.0
#define G_DEFAULT 9.81

/* Palette entries: the solitary case black, the explosion vermillion (Okabe-Ito). */
static int case_colour(int i) { return i == WL_RESULTS_CASE_SOLITARY ? 1 : 5; }

static enum wl_status figure(struct wl_report_doc *d, const struct wl_report_plot *p, double h,
                             const char *caption, struct wl_error *err) {
  struct wl_report_rect area;
  enum wl_status st = wl_report_begin_figure(d, h, &area, err);
  if (!st)
    st = wl_report_draw_plot(d, p, area, err);
  if (!st)
    st = wl_report_end_figure(d, caption, err);
  return st;
}

/* " (no explosion case in the results)" etc. for a caption. */
static void missing_note(const struct wl_results *r, char *out, size_t size) {
  out[0] = '\0';
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_case *k = &r->cases[i];
    size_t used = strlen(out);
    if (!k->present)
      snprintf(out + used, size - used, " No %s case is in the results.",
               k->name[0] ? k->name : wl_store_results_case_name(i));
    else if (k->n == 0)
      snprintf(out + used, size - used, " The %s case recorded no samples.", k->name);
    else if (strcmp(k->status, "complete"))
      snprintf(out + used, size - used, " The %s case stopped early (%s) at t = %.4g s.", k->name,
               k->status[0] ? k->status : "?", k->time_reached);
  }
}

/* ---- gauges ------------------------------------------------------------------------- */

static const struct wl_results_gauge *find_gauge(const struct wl_results_case *k, const char *name) {
  for (int g = 0; g < k->n_gauges; g++)
    if (!strcmp(k->gauges[g].name, name))
      return &k->gauges[g];
  return NULL;
}

enum wl_status wl_report_render_gauges(struct wl_report_ctx *c, const struct wl_report_section *s,
                                       struct wl_error *err) {
  const struct wl_results *r = c->res;
  struct wl_report_doc *d = c->doc;
  enum wl_status st = wl_report_section_begin(c, s, err);
  /* names: the template's, or every gauge of either case (ordered by x) */
  char names[WL_RESULTS_MAX_GAUGES * 2][64];
  double xs[WL_RESULTS_MAX_GAUGES * 2];
  int n = 0;
  char unknown[512] = "";
  if (s->n_gauges > 0) {
    for (int i = 0; i < s->n_gauges; i++) {
      int found = 0;
      double x = NAN;
      for (int ci = 0; ci < WL_RESULTS_N_CASES; ci++) {
        const struct wl_results_gauge *g = find_gauge(&r->cases[ci], s->gauges[i]);
        if (g)
          found = 1, x = g->x;
      }
      if (!found) {
        size_t used = strlen(unknown);
        snprintf(unknown + used, sizeof unknown - used, "%s%s", used ? ", " : "", s->gauges[i]);
        continue;
      }
      snprintf(names[n], sizeof names[n], "%s", s->gauges[i]);
      xs[n++] = x;
    }
  } else {
    for (int ci = 0; ci < WL_RESULTS_N_CASES; ci++)
      for (int g = 0; g < r->cases[ci].n_gauges; g++) {
        const struct wl_results_gauge *ga = &r->cases[ci].gauges[g];
        int dup = 0;
        for (int j = 0; j < n; j++)
          dup |= !strcmp(names[j], ga->name);
        if (dup || n >= WL_RESULTS_MAX_GAUGES * 2)
          continue;
        /* insertion by x keeps the flume's order */
        int at = n;
        while (at > 0 && isfinite(ga->x) && !(xs[at - 1] <= ga->x)) {
          memcpy(names[at], names[at - 1], sizeof names[0]);
          xs[at] = xs[at - 1];
          at--;
        }
        snprintf(names[at], sizeof names[at], "%s", ga->name);
        xs[at] = ga->x;
        n++;
      }
  }
  char missing[512];
  missing_note(r, missing, sizeof missing);
  if (!st && unknown[0])
    st = wl_report_paragraphf(d, err, "Gauges named in the template but not in the results: %s.",
                              unknown);
  if (!st && n == 0)
    st = wl_report_paragraphf(d, err, "The results hold no gauge records.%s", missing);
  for (int i = 0; !st && i < n; i++) {
    struct wl_report_series ser[WL_RESULTS_N_CASES];
    int ns = 0;
    for (int ci = 0; ci < WL_RESULTS_N_CASES; ci++) {
      const struct wl_results_case *k = &r->cases[ci];
      const struct wl_results_gauge *g = k->present ? find_gauge(k, names[i]) : NULL;
      if (!g || !k->n)
        continue;
      ser[ns++] = (struct wl_report_series){
          k->name, k->t, g->eta, k->n, WL_REPORT_LINE_AUTO, WL_REPORT_MARKER_NONE, case_colour(ci)};
    }
    char title[160], cap[1024], where[64];
    int wall = !strcmp(names[i], "wall");
    if (isfinite(xs[i]))
      snprintf(where, sizeof where, " at x = %.4g m", xs[i]);
    else
      where[0] = '\0';
    snprintf(title, sizeof title, "%s%s", wall ? "wall face (run-up)" : names[i], where);
    snprintf(cap, sizeof cap,
             "Free-surface elevation above still water at %s%s%s, the load cases overlaid.%s",
             wall ? "the wall face" : "gauge ", wall ? "" : names[i], where, missing);
    struct wl_report_refline zero = {0.0, NULL, 0};
    struct wl_report_plot p = {
        title, {"time", "s", 0, 0, 0, 0}, {"elevation", "m", 0, 0, 0, 0}, ser, ns, &zero,
        1,     WL_REPORT_LEGEND_AUTO};
    st = figure(d, &p, PLOT_H, cap, err);
  }
  return st;
}

/* ---- loads ---------------------------------------------------------------------------- */

/* Pressure over the wall's height at the peak force of each case, with the
 * hydrostatic pressure at rest. */
static enum wl_status pressure_profile(struct wl_report_ctx *c, struct wl_report_scratch *sc,
                                       const char *missing, struct wl_error *err) {
  const struct wl_results *r = c->res;
  struct wl_report_series ser[WL_RESULTS_N_CASES + 1];
  char labels[WL_RESULTS_N_CASES][96];
  int ns = 0;
  double zmin = INFINITY, zmax = -INFINITY, still = NAN;
  size_t np_max = 0;
  for (int ci = 0; ci < WL_RESULTS_N_CASES; ci++) {
    const struct wl_results_case *k = &r->cases[ci];
    if (!k->present || !k->n || !k->pressure || !k->n_probes || !isfinite(k->force_peak.time))
      continue;
    size_t row = k->force_peak.index < k->n ? k->force_peak.index : k->n - 1;
    double *p = wl_report_scratch_scaled(sc, k->pressure + row * k->n_probes, k->n_probes, KILO);
    if (!p)
      return wl_error_set(err, WL_ENOMEM, "report: no memory for a plot");
    snprintf(labels[ns], sizeof labels[ns], "%s, t = %.3f s", k->name, k->t[row]);
    ser[ns] = (struct wl_report_series){
        labels[ns],     p, k->probe_z, k->n_probes, WL_REPORT_LINE_SOLID, WL_REPORT_MARKER_AUTO,
        case_colour(ci)};
    ns++;
    for (size_t j = 0; j < k->n_probes; j++)
      zmin = fmin(zmin, k->probe_z[j]), zmax = fmax(zmax, k->probe_z[j]);
    if (isfinite(k->wall_toe_z))
      zmin = fmin(zmin, k->wall_toe_z);
    if (isfinite(k->wall_crest_z))
      zmax = fmax(zmax, k->wall_crest_z);
    still = k->still_water_z;
    if (k->n_probes > np_max)
      np_max = k->n_probes;
  }
  if (ns == 0)
    return wl_report_paragraphf(c->doc, err,
                                "No pressure distribution at the peak force: no case stored "
                                "probe pressures with a peak.%s",
                                missing);
  double rho = r->plan.present ? r->plan.rho : RHO_DEFAULT,
         g = r->plan.present ? r->plan.g : G_DEFAULT;
  enum { NH = 64 };
  double *hz = wl_report_scratch_alloc(sc, NH), *hp = wl_report_scratch_alloc(sc, NH);
  if (!hz || !hp)
    return wl_error_set(err, WL_ENOMEM, "report: no memory for a plot");
  int nh = 0;
  if (isfinite(still) && zmax > zmin)
    for (int i = 0; i < NH; i++) {
      hz[i] = zmin + (zmax - zmin) * i / (NH - 1);
      hp[i] = rho * g * fmax(0.0, still - hz[i]) / KILO;
      nh = NH;
    }
  if (nh)
    ser[ns++] = (struct wl_report_series){
        "hydrostatic at rest", hp, hz, (size_t)nh, WL_REPORT_LINE_DOTTED, WL_REPORT_MARKER_NONE, 3};
  struct wl_report_refline swl = {still, "still water", 0};
  struct wl_report_plot p = {"Pressure on the wall face at the peak force",
                             {"pressure", "kPa", 0, 0, 0, 0},
                             {"height above the flume floor z", "m", 0, 0, 0, 0},
                             ser,
                             ns,
                             &swl,
                             isfinite(still) ? 1 : 0,
                             WL_REPORT_LEGEND_BELOW};
  char cap[1024];
  snprintf(cap, sizeof cap,
           "Probe pressures (raw) over the wall's height at the sample of each case's peak "
           "(filtered) force, and the hydrostatic pressure of still water (rho = %g kg/m^3, "
           "g = %g m/s^2).%s",
           rho, g, missing);
  return figure(c->doc, &p, 260.0, cap, err);
}

/* Series of one quantity for each case: `what` picks the array. */
enum which {
  W_FORCE,
  W_FORCE_F,
  W_FORCE_B,
  W_FORCE_BF,
  W_IMPULSE,
  W_IMPULSE_B,
  W_MOMENT,
  W_MOMENT_F,
  W_MOMENT_B
};

static const double *pick(const struct wl_results_case *k, enum which w) {
  switch (w) {
  case W_FORCE: return k->force;
  case W_FORCE_F: return k->force_f;
  case W_FORCE_B: return k->force_b;
  case W_FORCE_BF: return k->force_bf;
  case W_IMPULSE: return k->impulse;
  case W_IMPULSE_B: return k->impulse_b;
  case W_MOMENT: return k->moment;
  case W_MOMENT_F: return k->moment_f;
  case W_MOMENT_B: return k->moment_b;
  }
  return NULL;
}

struct line_spec {
  enum which w;
  const char *suffix; /* legend: "<case>, <suffix>" */
  enum wl_report_line line;
};

/* A plot of the given lines for every present case, in kN units. */
static enum wl_status case_lines(struct wl_report_ctx *c, struct wl_report_scratch *sc,
                                 const struct line_spec *spec, int n_spec, int only_case,
                                 int colour_by_spec, struct wl_report_plot *p,
                                 struct wl_report_series *ser, char (*labels)[96],
                                 struct wl_error *err) {
  const struct wl_results *r = c->res;
  int ns = 0;
  for (int ci = 0; ci < WL_RESULTS_N_CASES; ci++) {
    const struct wl_results_case *k = &r->cases[ci];
    if (!k->present || !k->n || (only_case >= 0 && ci != only_case))
      continue;
    for (int j = 0; j < n_spec; j++) {
      const double *v = pick(k, spec[j].w);
      if (!v)
        continue;
      double *y = wl_report_scratch_scaled(sc, v, k->n, KILO);
      if (!y)
        return wl_error_set(err, WL_ENOMEM, "report: no memory for a plot");
      snprintf(labels[ns], 96, "%s, %s", k->name, spec[j].suffix);
      ser[ns] = (struct wl_report_series){labels[ns],
                                          k->t,
                                          y,
                                          k->n,
                                          spec[j].line,
                                          WL_REPORT_MARKER_NONE,
                                          colour_by_spec ? j + 1 : case_colour(ci)};
      ns++;
    }
  }
  p->series = ser;
  p->n_series = ns;
  return WL_OK;
}

enum wl_status wl_report_render_loads(struct wl_report_ctx *c, const struct wl_report_section *s,
                                      struct wl_error *err) {
  const struct wl_results *r = c->res;
  struct wl_report_doc *d = c->doc;
  enum wl_status st = wl_report_section_begin(c, s, err);
  struct wl_report_scratch sc = {0};
  struct wl_report_series ser[16];
  char labels[16][96];
  char missing[512], cap[1024];
  missing_note(r, missing, sizeof missing);
  int any = 0;
  double fs = NAN, cut = NAN;
  for (int i = 0; i < WL_RESULTS_N_CASES; i++)
    if (r->cases[i].present && r->cases[i].n) {
      any = 1;
      if (!isfinite(fs))
        fs = r->cases[i].rest_force, cut = r->cases[i].cutoff;
    }
  if (!st && !any) {
    st = wl_report_paragraphf(d, err, "No wall-load histories: no case recorded samples.%s",
                              missing);
    return st;
  }
  struct wl_report_refline at_rest = {fs / KILO, "at rest", 0};
  if (!st && (s->loads & WL_REPORT_LOAD_FORCE)) {
    static const struct line_spec both[] = {
        {W_FORCE_F, "probes, filtered", WL_REPORT_LINE_SOLID},
        {W_FORCE_BF, "boundary, filtered", WL_REPORT_LINE_DASHED},
    };
    struct wl_report_plot p = {"Horizontal force on the wall (filtered)",
                               {"time", "s", 0, 0, 0, 0},
                               {"force", "kN/m", 0, 0, 0, 0},
                               NULL,
                               0,
                               &at_rest,
                               isfinite(fs) ? 1 : 0,
                               WL_REPORT_LEGEND_AUTO};
    st = case_lines(c, &sc, both, 2, -1, 0, &p, ser, labels, err);
    snprintf(cap, sizeof cap,
             "Horizontal force per metre of wall, low-pass filtered (cut-off %.3g Hz), from the "
             "pressure probes (solid) and summed on the wall's boundary particles (dashed); the "
             "line marks the probes' force at rest.%s",
             cut, missing);
    if (!st)
      st = figure(d, &p, PLOT_H + 20.0, cap, err);
    /* raw and filtered, one plot per case */
    static const struct line_spec raw[] = {
        {W_FORCE, "probes, raw", WL_REPORT_LINE_SOLID},
        {W_FORCE_F, "probes, filtered", WL_REPORT_LINE_SOLID},
        {W_FORCE_B, "boundary, raw", WL_REPORT_LINE_DOTTED},
        {W_FORCE_BF, "boundary, filtered", WL_REPORT_LINE_DASHED},
    };
    int n_cells = 0, idx[WL_RESULTS_N_CASES];
    for (int i = 0; i < WL_RESULTS_N_CASES; i++)
      if (r->cases[i].present && r->cases[i].n)
        idx[n_cells++] = i;
    struct wl_report_rect area;
    if (!st && n_cells)
      st = wl_report_begin_figure(d, PAIR_H, &area, err);
    for (int j = 0; !st && j < n_cells; j++) {
      char title[96];
      snprintf(title, sizeof title, "%s: raw and filtered", r->cases[idx[j]].name);
      struct wl_report_plot q = {
          title, {"time", "s", 0, 0, 0, 0}, {"force", "kN/m", 0, 0, 0, 0}, NULL, 0, NULL,
          0,     WL_REPORT_LEGEND_BELOW};
      st = case_lines(c, &sc, raw, 4, idx[j], 1, &q, ser, labels, err);
      if (!st)
        st = wl_report_draw_plot(d, &q, wl_report_rect_cell(area, n_cells, 1, j, CELL_GAP), err);
    }
    if (!st && n_cells)
      st = wl_report_end_figure(d,
                                "Raw and filtered force of each case, from the probes and from "
                                "the boundary particles: the raw series carry the acoustic "
                                "ringing of weakly-compressible SPH that the filter removes.",
                                err);
  }
  if (!st && (s->loads & WL_REPORT_LOAD_IMPULSE)) {
    static const struct line_spec imp[] = {
        {W_IMPULSE, "probes", WL_REPORT_LINE_SOLID},
        {W_IMPULSE_B, "boundary", WL_REPORT_LINE_DASHED},
    };
    struct wl_report_refline zero = {0.0, NULL, 0};
    struct wl_report_plot p = {"Impulse on the wall",
                               {"time", "s", 0, 0, 0, 0},
                               {"impulse", "kN s/m", 0, 0, 0, 0},
                               NULL,
                               0,
                               &zero,
                               1,
                               WL_REPORT_LEGEND_AUTO};
    st = case_lines(c, &sc, imp, 2, -1, 0, &p, ser, labels, err);
    snprintf(cap, sizeof cap,
             "Impulse per metre of wall: the time integral of the raw force in excess of the "
             "force at rest, from the probes (solid) and the boundary particles (dashed), each "
             "its own force at rest.%s",
             missing);
    if (!st)
      st = figure(d, &p, PLOT_H, cap, err);
  }
  if (!st && (s->loads & WL_REPORT_LOAD_MOMENT)) {
    static const struct line_spec mom[] = {
        {W_MOMENT_F, "probes, filtered", WL_REPORT_LINE_SOLID},
        {W_MOMENT_B, "boundary, raw", WL_REPORT_LINE_DOTTED},
    };
    struct wl_report_plot p = {"Overturning moment about the wall's toe",
                               {"time", "s", 0, 0, 0, 0},
                               {"moment", "kN m/m", 0, 0, 0, 0},
                               NULL,
                               0,
                               NULL,
                               0,
                               WL_REPORT_LEGEND_AUTO};
    st = case_lines(c, &sc, mom, 2, -1, 0, &p, ser, labels, err);
    snprintf(cap, sizeof cap,
             "Overturning moment per metre of wall about its toe: probes, filtered (solid), and "
             "boundary particles, raw (dotted).%s",
             missing);
    if (!st)
      st = figure(d, &p, PLOT_H, cap, err);
  }
  if (!st && (s->loads & (WL_REPORT_LOAD_FORCE | WL_REPORT_LOAD_PRESSURE)))
    st = pressure_profile(c, &sc, missing, err);
  if (!st && (s->loads & WL_REPORT_LOAD_PRESSURE)) {
    for (int ci = 0; !st && ci < WL_RESULTS_N_CASES; ci++) {
      const struct wl_results_case *k = &r->cases[ci];
      if (!k->present || !k->n || !k->pressure || !k->n_probes)
        continue;
      size_t stride = (k->n_probes + MAX_PROBE_LINES - 1) / MAX_PROBE_LINES;
      if (stride < 1)
        stride = 1;
      int ns = 0;
      for (size_t j = 0; j < k->n_probes && ns < MAX_PROBE_LINES; j += stride) {
        double *y = wl_report_scratch_alloc(&sc, k->n);
        if (!y)
          return wl_error_set(err, WL_ENOMEM, "report: no memory for a plot");
        for (size_t t = 0; t < k->n; t++)
          y[t] = k->pressure[t * k->n_probes + j] / KILO;
        snprintf(labels[ns], 96, "z = %.3g m", k->probe_z[j]);
        ser[ns] = (struct wl_report_series){
            labels[ns], k->t, y, k->n, WL_REPORT_LINE_AUTO, WL_REPORT_MARKER_NONE, ns + 1};
        ns++;
      }
      char title[96];
      snprintf(title, sizeof title, "Probe pressures, %s case", k->name);
      struct wl_report_plot p = {
          title, {"time", "s", 0, 0, 0, 0}, {"pressure", "kPa", 0, 0, 0, 0}, ser, ns, NULL,
          0,     WL_REPORT_LEGEND_BELOW};
      snprintf(cap, sizeof cap, "Raw pressure at %d of the %zu probes on the wall face (%s case).",
               ns, k->n_probes, k->name);
      st = figure(d, &p, PLOT_H + 30.0, cap, err);
    }
  }
  if (!st && (s->loads & WL_REPORT_LOAD_RUNUP)) {
    int ns = 0;
    for (int ci = 0; ci < WL_RESULTS_N_CASES; ci++) {
      const struct wl_results_case *k = &r->cases[ci];
      if (!k->present || !k->n || k->wall_gauge < 0)
        continue;
      ser[ns++] = (struct wl_report_series){k->name,
                                            k->t,
                                            k->gauges[k->wall_gauge].eta,
                                            k->n,
                                            WL_REPORT_LINE_AUTO,
                                            WL_REPORT_MARKER_NONE,
                                            case_colour(ci)};
    }
    struct wl_report_plot p = {"Water level at the wall face",
                               {"time", "s", 0, 0, 0, 0},
                               {"run-up", "m", 0, 0, 0, 0},
                               ser,
                               ns,
                               NULL,
                               0,
                               WL_REPORT_LEGEND_AUTO};
    snprintf(cap, sizeof cap, "Water level at the wall face above still water (run-up).%s",
             missing);
    st = figure(d, &p, PLOT_H, cap, err);
  }
  wl_report_scratch_free(&sc);
  return st;
}
