/* sections_design.c: the design_formulae section. For each load case the
 * wall as simulated (depth at the toe, crest above still water) and the
 * wave that reached it (the solitary wave's H from the scenario, the
 * explosion's leading-wave height measured at the gauge nearest the wall;
 * a period estimated from that gauge's record; the simulated run-up) go
 * into wl_design_evaluate (design.h: hydrostatic, Goda / Takahashi,
 * Sainflou, FEMA P-646, CCH surge); each row is printed with its citation
 * and validity flag beside the simulated peak force and moment. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sections.h"
#include "wallload/design.h"
#include "wallload/loads.h"

#define RHO_DEFAULT 1000.0
#define CREST_SHARE 0.5 /* the leading crest is the first maximum above this share of the highest  \
                         */

/* ---- leading wave ------------------------------------------------------------------ */

/* Time at which eta crosses level between samples a and b (linear). */
static double crossing(const double *t, const double *eta, size_t a, size_t b, double level) {
  double d = eta[b] - eta[a];
  if (d == 0 || !isfinite(d))
    return 0.5 * (t[a] + t[b]);
  return t[a] + (level - eta[a]) / d * (t[b] - t[a]);
}

int wl_report_leading_wave(const double *t, const double *eta, size_t n, double *height,
                           double *period, double *t_crest) {
  *height = *period = *t_crest = NAN;
  if (!t || !eta || n < 3)
    return 0;
  double top = -INFINITY;
  for (size_t k = 0; k < n; k++)
    if (isfinite(eta[k]) && eta[k] > top)
      top = eta[k];
  if (!(top > 0))
    return 0;
  size_t kc = 0;
  while (kc < n && !(isfinite(eta[kc]) && eta[kc] >= CREST_SHARE * top))
    kc++;
  while (kc + 1 < n && isfinite(eta[kc + 1]) && eta[kc + 1] > eta[kc])
    kc++;
  double crest = eta[kc];
  double trough = 0.0;
  int below = 0;
  for (size_t k = kc + 1; k < n; k++) {
    if (!isfinite(eta[k]))
      continue;
    if (eta[k] < 0)
      below = 1;
    if (below && eta[k] >= 0)
      break;
    if (eta[k] < trough)
      trough = eta[k];
  }
  *height = crest - trough;
  *t_crest = t[kc];
  double th = WL_LOADS_THRESHOLD * crest;
  size_t up = kc, down = kc;
  while (up > 0 && !(isfinite(eta[up - 1]) && eta[up - 1] < th))
    up--;
  while (down + 1 < n && !(isfinite(eta[down + 1]) && eta[down + 1] < th))
    down++;
  if (up > 0 && down + 1 < n) {
    double t_up = crossing(t, eta, up - 1, up, th), t_down = crossing(t, eta, down, down + 1, th);
    *period = 2.0 * (t_down - t_up);
  }
  return 1;
}

/* ---- the section --------------------------------------------------------------------- */

static unsigned formula_bit(const char *name) {
  if (!strncmp(name, "hydrostatic", 11))
    return WL_REPORT_FORMULA_HYDROSTATIC;
  if (!strncmp(name, "goda", 4) || !strcmp(name, "sainflou"))
    return WL_REPORT_FORMULA_GODA_TAKAHASHI;
  if (!strncmp(name, "fema", 4))
    return WL_REPORT_FORMULA_FEMA_P646;
  if (!strcmp(name, "cch-surge"))
    return WL_REPORT_FORMULA_CROSS;
  return ~0u;
}

/* The gauge nearest the wall other than the wall face itself; -1 if none. */
static int gauge_near_wall(const struct wl_results_case *k) {
  int best = -1;
  for (int g = 0; g < k->n_gauges; g++) {
    if (g == k->wall_gauge || !isfinite(k->gauges[g].x) || !k->gauges[g].eta)
      continue;
    if (best < 0 || fabs(k->gauges[g].x - k->wall_x) < fabs(k->gauges[best].x - k->wall_x))
      best = g;
  }
  return best;
}

int wl_report_design_inputs(const struct wl_results *r, int ci,
                            struct wl_design_scenario *out, char *h_src, char *t_src,
                            size_t src_size) {
  const struct wl_results_case *k = &r->cases[ci];
  if (!isfinite(k->still_water_z) || !isfinite(k->wall_toe_z) || !k->n)
    return 0;
  struct wl_design_scenario ds;
  wl_design_scenario_init(&ds);
  if (r->plan.present)
    ds.rho = r->plan.rho, ds.g = r->plan.g;
  else
    ds.rho = RHO_DEFAULT;
  double still = k->still_water_z;
  ds.d = fmax(0.0, still - k->wall_toe_z);
  ds.z_toe = ds.d > 0 ? 0.0 : k->wall_toe_z - still;
  ds.hc = isfinite(k->wall_crest_z) ? fmax(0.0, k->wall_crest_z - still) : INFINITY;

  /* the wave at the wall */
  h_src[0] = t_src[0] = '\0';
  int gi = gauge_near_wall(k);
  double Hm = NAN, Tm = NAN, tc = NAN;
  if (gi >= 0)
    wl_report_leading_wave(k->t, k->gauges[gi].eta, k->n, &Hm, &Tm, &tc);
  const struct wl_results_solitary *ps = r->plan.present ? &r->plan.solitary : NULL;
  if (ci == WL_RESULTS_CASE_SOLITARY && ps && ps->present) {
    ds.H = ps->H;
    snprintf(h_src, src_size, "the solitary wave's height (scenario)");
  } else if (isfinite(Hm)) {
    ds.H = Hm;
    snprintf(h_src, src_size, "leading wave at %s (x = %.4g m), crest to trough",
             k->gauges[gi].name, k->gauges[gi].x);
  } else {
    snprintf(h_src, src_size, "%s",
             gi < 0 ? "no gauge seaward of the wall" : "no wave crest in the gauge record");
  }
  if (isfinite(Tm) && Tm > 0) {
    ds.T = Tm;
    snprintf(t_src, src_size, "twice the time the crest at %s stays above 10 %% of its height",
             k->gauges[gi].name);
  } else if (ci == WL_RESULTS_CASE_SOLITARY && ps && ps->present && ps->K > 0 &&
             ps->celerity > 0) {
    ds.T = 4.0 * acosh(sqrt(1.0 / WL_LOADS_THRESHOLD)) / (ps->K * ps->celerity);
    snprintf(t_src, src_size,
             "the same measure on the theoretical profile, 4 acosh(sqrt 10)/(K c)");
  } else {
    snprintf(t_src, src_size, "%s",
             gi < 0 ? "no gauge seaward of the wall"
                    : "the leading crest does not pass within the record");
  }
  double runup = k->runup;
  if (isfinite(runup) && runup > 0) {
    ds.eta = runup;
    ds.R = WL_DESIGN_FEMA_RUNUP_FACTOR * runup;
    if (ds.d == 0 && runup > ds.z_toe)
      ds.h_bore = runup - ds.z_toe;
  }
  *out = ds;
  return 1;
}

static enum wl_status design_case(struct wl_report_ctx *c, const struct wl_report_section *s,
                                  int ci, struct wl_error *err) {
  const struct wl_results *r = c->res;
  const struct wl_results_case *k = &r->cases[ci];
  struct wl_report_doc *d = c->doc;
  int dg = s->digits;
  enum wl_status st = wl_report_add_heading(d, 2, wl_report_case_label(ci), err);
  if (st)
    return st;
  if (!isfinite(k->still_water_z) || !isfinite(k->wall_toe_z) || !k->n)
    return wl_report_paragraphf(d, err,
                                "The %s case has no wall geometry or no record in the results: "
                                "no comparison.",
                                k->name);
  struct wl_design_scenario ds;
  char h_src[256], t_src[256];
  wl_report_design_inputs(r, ci, &ds, h_src, t_src, sizeof h_src);
  const double runup = k->runup;
  double L = NAN;
  if (ds.d > 0 && ds.T > 0) {
    struct wl_error e;
    wl_error_clear(&e);
    if (wl_design_wavelength(ds.T, ds.d, ds.g, &L, &e) != WL_OK)
      L = NAN;
  }
  struct wl_report_kv in[] = {
      {"still-water depth at the toe d", NULL, ds.d, "m", dg},
      {"dry toe above still water", NULL, ds.z_toe, "m", dg},
      {"crest above still water hc", NULL, ds.hc, "m", dg},
      {"wave height H", NULL, ds.H > 0 ? ds.H : NAN, "m", dg},
      {"  from", h_src, 0, NULL, 0},
      {"period T", NULL, ds.T > 0 ? ds.T : NAN, "s", dg},
      {"  from", t_src, 0, NULL, 0},
      {"wavelength L at d (linear dispersion)", NULL, L, "m", dg},
      {"simulated run-up at the wall", NULL, runup, "m", dg},
      {"FEMA design run-up R = 1.3 x run-up", NULL, ds.R > 0 ? ds.R : NAN, "m", dg},
      {"water density", NULL, ds.rho, "kg/m^3", 4},
  };
  char cap[160];
  snprintf(cap, sizeof cap, "Formula inputs for the %s case", k->name);
  st = wl_report_add_kv_table(d, cap, in, (int)(sizeof in / sizeof in[0]), err);
  if (st)
    return st;

  struct wl_design_result res[WL_DESIGN_MAX_RESULTS];
  int n = 0;
  struct wl_error e;
  wl_error_clear(&e);
  if (wl_design_evaluate(&ds, res, WL_DESIGN_MAX_RESULTS, &n, &e) != WL_OK)
    return wl_report_paragraphf(d, err, "The design formulae could not be evaluated: %s.", e.msg);

  static const struct wl_report_column cols0[] = {
      {"formula", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"basis", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"force", "kN/m", WL_REPORT_ALIGN_AUTO, 0},
      {"total force", "kN/m", WL_REPORT_ALIGN_AUTO, 0},
      {"total moment", "kN m/m", WL_REPORT_ALIGN_AUTO, 0},
      {"SPH / total", NULL, WL_REPORT_ALIGN_AUTO, 0},
      {"validity", NULL, WL_REPORT_ALIGN_LEFT, 0},
  };
  enum { NC = 7 };
  struct wl_report_column cols[NC];
  memcpy(cols, cols0, sizeof cols);
  for (int j = 2; j < 6; j++)
    cols[j].sig = dg;
  struct wl_report_cell cells[(WL_DESIGN_MAX_RESULTS + 1) * NC];
  char valid[WL_DESIGN_MAX_RESULTS][32];
  char notes[WL_DESIGN_MAX_RESULTS * (WL_DESIGN_NOTE_MAX + 400) + 256];
  size_t used = 0;
  notes[0] = '\0';
  double F = k->force_peak.value, M = k->moment_peak.value;
  struct wl_report_cell *row = cells;
  row[0] = (struct wl_report_cell){"SPH, this run (peak)", 0};
  row[1] = (struct wl_report_cell){"total", 0};
  row[2] = (struct wl_report_cell){NULL, F / KILO};
  row[3] = (struct wl_report_cell){NULL, F / KILO};
  row[4] = (struct wl_report_cell){NULL, M / KILO};
  row[5] = (struct wl_report_cell){NULL, 1.0};
  row[6] = (struct wl_report_cell){k->filtered ? "filtered peaks" : "raw peaks", 0};
  int rows = 1, m = 0;
  for (int i = 0; i < n; i++) {
    const struct wl_design_result *x = &res[i];
    if (!(formula_bit(x->name) & s->formulae))
      continue;
    m++;
    snprintf(valid[i], sizeof valid[i], "%s [%d]", x->in_range ? "in range" : "OUT of range", m);
    row = &cells[rows * NC];
    row[0] = (struct wl_report_cell){x->name, 0};
    row[1] = (struct wl_report_cell){wl_design_basis_name(x->basis), 0};
    row[2] = (struct wl_report_cell){NULL, x->force / KILO};
    row[3] = (struct wl_report_cell){NULL, x->force_total / KILO};
    row[4] = (struct wl_report_cell){NULL, x->moment_total / KILO};
    row[5] = (struct wl_report_cell){NULL, x->force_total != 0 ? F / x->force_total : NAN};
    row[6] = (struct wl_report_cell){valid[i], 0};
    rows++;
    if (used < sizeof notes)
      used += (size_t)snprintf(notes + used, sizeof notes - used, "%s[%d] %s: %s. %s: %s.",
                               m > 1 ? "\n" : "", m, x->name, x->citation,
                               x->in_range ? "Valid" : "Outside its range", x->range_note);
  }
  snprintf(cap, sizeof cap,
           "Design-code wall loads for the %s case beside the simulated peak (per metre of wall)",
           k->name);
  struct wl_report_table tab = {cap, cols, NC, cells, rows};
  st = wl_report_add_table(d, &tab, err);
  if (!st && m == 0)
    st = wl_report_add_paragraph(d,
                                 "No formula of those the template asks for applies to this "
                                 "wall and wave (see the inputs above).",
                                 err);
  if (!st && notes[0])
    st = wl_report_add_paragraph(d, notes, err);
  return st;
}

enum wl_status wl_report_render_design(struct wl_report_ctx *c, const struct wl_report_section *s,
                                       struct wl_error *err) {
  const struct wl_results *r = c->res;
  enum wl_status st = wl_report_section_begin(c, s, err);
  if (!st)
    st = wl_report_add_paragraph(
        c->doc,
        "Each design formula is evaluated for the wall as simulated (still-water depth at its "
        "toe, crest above still water) and for the wave that reached it: the solitary wave's "
        "height, or the explosion's leading-wave height measured at the gauge nearest the wall; "
        "the period is estimated from that gauge's record. 'total' forces include the "
        "hydrostatic force of still water on the face and compare with the SPH peak force, which "
        "includes it too; 'wave' is Goda's wave pressure alone, 'dynamic' a flow force to be "
        "added to hydrostatics. A formula outside its validity range is still printed, marked. "
        "The FEMA P-646 rows take the simulated run-up at the wall, times 1.3, as the design "
        "run-up. Cross (1967) is not implemented; where the template asks for it, the CCH surge "
        "force (a bore on a wall with a dry toe) is printed.",
        err);
  for (int i = 0; !st && i < WL_RESULTS_N_CASES; i++) {
    if (!r->cases[i].present) {
      st = wl_report_paragraphf(c->doc, err,
                                "The %s case is not in the results: no comparison for it.",
                                wl_store_results_case_name(i));
      continue;
    }
    st = design_case(c, s, i, err);
  }
  return st;
}
