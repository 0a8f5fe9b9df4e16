/* sections.c: wl_report_render (results.h5 + template -> PDF), the helpers
 * every section renderer shares, and the text-and-table sections: title
 * page with the summary of findings and the input digest, peaks,
 * convergence, run record (metadata). The figure sections are in
 * sections_scene.c (scene, snapshots), sections_plots.c (gauges, loads)
 * and sections_design.c (design formulae). */
#define _POSIX_C_SOURCE 200809L /* localtime_r */

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sections.h"
#include "wallload/config.h"
#include "wallload/report.h"
#include "wallload/units.h"

#define DEFAULT_DIGITS 3 /* peaks when the template has no peaks section */
#define TIME_DIGITS 3    /* times of peaks in running text */
#define SHARE_DIGITS 2   /* percentages in running text */

/* ---- shared helpers ---------------------------------------------------------------- */

double *wl_report_scratch_alloc(struct wl_report_scratch *s, size_t n) {
  if (s->n >= WL_REPORT_SCRATCH_MAX)
    return NULL;
  double *p = malloc((n ? n : 1) * sizeof *p);
  if (p)
    s->p[s->n++] = p;
  return p;
}

double *wl_report_scratch_scaled(struct wl_report_scratch *s, const double *v, size_t n,
                                 double divisor) {
  if (!v)
    return NULL;
  double *p = wl_report_scratch_alloc(s, n);
  if (p)
    for (size_t i = 0; i < n; i++)
      p[i] = v[i] / divisor;
  return p;
}

void wl_report_scratch_free(struct wl_report_scratch *s) {
  for (int i = 0; i < s->n; i++)
    free(s->p[i]);
  s->n = 0;
}

const char *wl_report_fmt(double v, int sig, char *buf, size_t size) {
  wl_report_format_sig(v, sig, buf, size);
  return buf;
}

const char *wl_report_case_label(int i) {
  return i == WL_RESULTS_CASE_SOLITARY ? "solitary wave" : "explosion wave";
}

enum wl_status wl_report_section_begin(struct wl_report_ctx *c, const struct wl_report_section *s,
                                       struct wl_error *err) {
  enum wl_status st = WL_OK;
  if (s->page_break)
    st = wl_report_break_page(c->doc, err);
  if (!st && s->title[0])
    st = wl_report_add_heading(c->doc, 1, s->title, err);
  if (!st && s->text[0])
    st = wl_report_add_paragraph(c->doc, s->text, err);
  return st;
}

enum wl_status wl_report_paragraphf(struct wl_report_doc *d, struct wl_error *err, const char *fmt,
                                    ...) {
  char buf[4096];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  return wl_report_add_paragraph(d, buf, err);
}

int wl_report_governs(double a, double b) {
  if (isfinite(a) && isfinite(b))
    return a >= b ? WL_RESULTS_CASE_SOLITARY : WL_RESULTS_CASE_EXPLOSION;
  if (isfinite(a))
    return WL_RESULTS_CASE_SOLITARY;
  if (isfinite(b))
    return WL_RESULTS_CASE_EXPLOSION;
  return -1;
}

/* Appending to a fixed buffer. */
struct buf {
  char *s;
  size_t size, len;
};

static void put(struct buf *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static void put(struct buf *b, const char *fmt, ...) {
  if (b->len + 1 >= b->size)
    return;
  va_list ap;
  va_start(ap, fmt);
  int n = vsnprintf(b->s + b->len, b->size - b->len, fmt, ap);
  va_end(ap);
  if (n > 0)
    b->len = b->len + (size_t)n < b->size ? b->len + (size_t)n : b->size - 1;
}

/* Signed percentage "+3.2 %" of (a - b) / b; "n/a" when undefined. */
static const char *share(double a, double b, char *out, size_t size) {
  double r = 100.0 * (a - b) / fabs(b);
  char num[64];
  if (!isfinite(r)) {
    snprintf(out, size, "n/a");
    return out;
  }
  wl_report_format_sig(r, SHARE_DIGITS, num, sizeof num);
  snprintf(out, size, "%s%s %%", r > 0 ? "+" : "", num);
  return out;
}

/* ---- title page -------------------------------------------------------------------- */

static void today(char *out, size_t size) {
  time_t now = time(NULL);
  struct tm tm;
  if (localtime_r(&now, &tm))
    strftime(out, size, "%Y-%m-%d", &tm);
  else
    snprintf(out, size, "unknown");
}

/* The summary of findings, from the peaks the report recomputed. */
static void summary(const struct wl_report_ctx *c, char *out, size_t size) {
  const struct wl_results *r = c->res;
  const struct wl_results_case *cs = r->cases;
  struct buf b = {out, size, 0};
  out[0] = '\0';
  int dg = c->digits;
  char f[2][64], im[2][64], tf[2][64];
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    wl_report_fmt(cs[i].force_peak.value / KILO, dg, f[i], sizeof f[i]);
    wl_report_fmt(cs[i].impulse_positive / KILO, dg, im[i], sizeof im[i]);
    wl_report_fmt(cs[i].force_peak.time, TIME_DIGITS, tf[i], sizeof tf[i]);
  }
  const int S = WL_RESULTS_CASE_SOLITARY, X = WL_RESULTS_CASE_EXPLOSION;
  if (r->n_cases == 0) {
    put(&b, "The results hold no load case: there is nothing to compare. ");
  } else if (r->n_cases == 1) {
    int i = cs[S].present ? S : X;
    put(&b,
        "Only the %s case is in the results (no %s case was run), so the two cases are not "
        "compared. Its peak force is %s kN/m (at t = %s s) and its positive impulse %s kN s/m "
        "per metre of wall. ",
        cs[i].name, cs[1 - i].name, f[i], tf[i], im[i]);
  } else {
    int gf = wl_report_governs(cs[S].force_peak.value, cs[X].force_peak.value);
    int gi = wl_report_governs(cs[S].impulse_positive, cs[X].impulse_positive);
    if (gf < 0) {
      put(&b, "Neither case has a peak force in its record, so none governs. ");
    } else if (gf == gi) {
      put(&b,
          "The %s case governs: its peak force, %s kN/m (at t = %s s), and its positive "
          "impulse, %s kN s/m per metre of wall, exceed the %s case's %s kN/m and %s kN s/m. ",
          cs[gf].name, f[gf], tf[gf], im[gf], cs[1 - gf].name, f[1 - gf], im[1 - gf]);
    } else {
      put(&b,
          "Neither case governs both loads: the %s case has the larger peak force, %s kN/m "
          "(at t = %s s) against %s kN/m",
          cs[gf].name, f[gf], tf[gf], f[1 - gf]);
      if (gi >= 0)
        put(&b, ", the %s case the larger positive impulse, %s kN s/m against %s kN s/m",
            cs[gi].name, im[gi], im[1 - gi]);
      put(&b, " (per metre of wall). ");
    }
  }
  int first = -1;
  for (int i = 0; i < WL_RESULTS_N_CASES; i++)
    if (cs[i].present && cs[i].n) {
      first = i;
      break;
    }
  if (first >= 0) {
    char cut[64], fs[64], fs0[64];
    put(&b,
        "Peak forces are those of the pressure probes on the wall face, %s (cut-off %s Hz); "
        "the positive impulse integrates that force wherever it exceeds the model's force at "
        "rest (%s kN/m, rho g d^2/2 = %s kN/m): the push of every wave together (the impulse "
        "of the peak's positive phase and the net impulse of the whole record are in the peaks "
        "table). ",
        cs[first].filtered ? "low-pass filtered" : "unfiltered (no filtered series stored)",
        wl_report_fmt(cs[first].cutoff, 3, cut, sizeof cut),
        wl_report_fmt(cs[first].rest_force / KILO, dg, fs, sizeof fs),
        wl_report_fmt(cs[first].static_force / KILO, dg, fs0, sizeof fs0));
    put(&b, "Second measurement: the force summed on the wall's boundary particles peaks at");
    int k = 0;
    for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
      if (!cs[i].present || !cs[i].n)
        continue;
      char fb[64], d[64], pc[64];
      put(&b, "%s %s kN/m for the %s case (%s kN/m, %s from the probe value)", k ? " and" : "",
          wl_report_fmt(cs[i].force_b_peak.value / KILO, dg, fb, sizeof fb), cs[i].name,
          wl_report_fmt((cs[i].force_b_peak.value - cs[i].force_peak.value) / KILO, dg, d,
                        sizeof d),
          share(cs[i].force_b_peak.value, cs[i].force_peak.value, pc, sizeof pc));
      k++;
    }
    put(&b, "; the two ways of measuring the wall load differ by about that much. That "
            "difference measures how the wall is discretised, not how far the loads are from "
            "converged: only a convergence ladder estimates the error of the resolution. ");
  }
  /* the convergence ladder's estimate, where one was run */
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_convergence *cv = &r->conv[i];
    if (!cv->present || cv->n_levels < 1)
      continue;
    char ef[64], ed[64], ei[64], dpf[64];
    wl_report_fmt(100.0 * cv->force_error, SHARE_DIGITS, ef, sizeof ef);
    wl_report_fmt(100.0 * cv->dyn_error, SHARE_DIGITS, ed, sizeof ed);
    wl_report_fmt(100.0 * cv->pos_error, SHARE_DIGITS, ei, sizeof ei);
    wl_report_fmt(cv->dp[cv->n_levels - 1], 3, dpf, sizeof dpf);
    if (!isfinite(cv->error_estimate))
      put(&b,
          "The %s case's convergence ladder ran %d level%s (finest dp = %s m): too few complete "
          "levels for an uncertainty. ",
          wl_store_results_case_name(i), cv->n_levels,
          cv->n_levels == 1 ? "" : "s", dpf);
    else
      put(&b,
          "Convergence ladder of the %s case (%d levels, finest dp = %s m): uncertainty of the "
          "resolution +-%s %% of the peak force (%s), +-%s %% of its part above the force at "
          "rest (%s), and +-%s %% of the positive impulse (%s)%s. ",
          wl_store_results_case_name(i), cv->n_levels, dpf, ef, cv->force_basis, ed, cv->dyn_basis,
          ei, cv->pos_basis,
          !isfinite(cv->target)     ? ""
          : cv->target_met > 0      ? ", within the target"
                                    : ", above the target");
  }
  /* the still-water reference (run.still_reference): what it took out */
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_case *ci = &r->cases[i];
    if (!ci->present || !(ci->still_drift_max > 0) || !isfinite(ci->impulse_positive_uncorrected))
      continue;
    char dm[64], rs[64], iu[64];
    wl_report_fmt(ci->still_drift_max / KILO, dg, dm, sizeof dm);
    wl_report_fmt(100.0 * ci->still_drift_max / fabs(ci->rest_force), SHARE_DIGITS, rs, sizeof rs);
    wl_report_fmt(ci->impulse_positive_uncorrected / KILO, dg, iu, sizeof iu);
    put(&b,
        "The %s case's loads are the wave's less the drift of the model's still water at the "
        "wall, read from a run of the same flume without the wave (up to %s kN/m, %s %% of the "
        "force at rest); with it left in, the positive impulse would read %s kN s/m. ",
        wl_store_results_case_name(i), dm, rs, iu);
  }
  /* realisations (resolution.realisations): the finest level's spread */
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_convergence *cv = &r->conv[i];
    if (!cv->present || cv->n_levels < 1)
      continue;
    const int last = cv->n_levels - 1;
    if (!(cv->realisations[last] > 1))
      continue;
    char lo[64], hi[64], sd[64];
    wl_report_fmt(cv->peak_force_min[last] / KILO, dg, lo, sizeof lo);
    wl_report_fmt(cv->peak_force_max[last] / KILO, dg, hi, sizeof hi);
    wl_report_fmt(100.0 * cv->peak_force_sd[last] / fabs(cv->peak_force[last]), SHARE_DIGITS, sd,
                  sizeof sd);
    put(&b,
        "The %s case ran %.0f realisations at each level, its initial wave moved by a fraction "
        "of the particle spacing each time: its flow is chaotic, so one run is one draw, and the "
        "loads quoted are the realisations' mean. At the finest level single runs peaked between "
        "%s and %s kN/m (standard deviation %s %% of the mean). ",
        wl_store_results_case_name(i), cv->realisations[last], lo, hi, sd);
    if (isfinite(cv->force_sampling) && isfinite(cv->pos_sampling)) {
      char sf[64], si[64];
      wl_report_fmt(100.0 * cv->force_sampling, SHARE_DIGITS, sf, sizeof sf);
      wl_report_fmt(100.0 * cv->pos_sampling, SHARE_DIGITS, si, sizeof si);
      put(&b,
          "That mean is itself uncertain by +-%s %% (peak force) and +-%s %% (positive impulse) "
          "at 95 %% (Student's t over the runs), which the uncertainties above include. ",
          sf, si);
    }
  }
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    if (!cs[i].present || !strcmp(cs[i].status, "complete"))
      continue;
    char tr[64], te[64];
    put(&b,
        "The %s case did not complete (%s at t = %s s of %s s%s%s); its values cover the "
        "record up to then and can miss the peak. ",
        cs[i].name, cs[i].status[0] ? cs[i].status : "status not stored",
        wl_report_fmt(cs[i].time_reached, TIME_DIGITS, tr, sizeof tr),
        wl_report_fmt(cs[i].end_time, TIME_DIGITS, te, sizeof te), cs[i].stopped[0] ? ": " : "",
        cs[i].stopped);
    if (cs[i].n == 0)
      put(&b, "It stored no samples at all. ");
  }
  for (int i = 0; i < WL_RESULTS_N_CASES; i++)
    if (cs[i].present && cs[i].caution[0])
      put(&b, "Caution, %s case: %s. ", cs[i].name, cs[i].caution);
}

enum wl_status wl_report_render_title(struct wl_report_ctx *c, const struct wl_report_section *s,
                                      struct wl_error *err) {
  const struct wl_report_template *t = c->tpl;
  const struct wl_results *r = c->res;
  struct wl_report_doc *d = c->doc;
  enum wl_status st = WL_OK;
  if (s->page_break)
    st = wl_report_break_page(d, err);
  if (!st)
    st = wl_report_add_title(d, t->title, t->subtitle[0] ? t->subtitle : NULL, err);
  char date[64];
  if (!strcmp(t->block.date, "auto") || !t->block.date[0])
    today(date, sizeof date);
  else
    snprintf(date, sizeof date, "%s", t->block.date);
  char made[160];
  snprintf(made, sizeof made, "wallload %s, %s",
           r->version[0] ? r->version : "(version not stored)",
           r->created[0] ? r->created : "(time not stored)");
  char by[160];
  snprintf(by, sizeof by, "wallload %s", WL_VERSION);
  struct {
    const char *key, *text;
  } rows[] = {
      {"Project", t->block.project},
      {"Client", t->block.client},
      {"Reference", t->block.reference},
      {"Revision", t->block.revision},
      {"Prepared by", t->block.prepared_by},
      {"Checked by", t->block.checked_by},
      {"Date", date},
      {"Scenario", r->scenario_name[0] ? r->scenario_name : "(not stored)"},
      {"Scenario file", r->scenario_file[0] ? r->scenario_file : "(not stored)"},
      {"Results", r->path},
      {"Results written by", made},
      {"Report rendered by", by},
  };
  struct wl_report_kv kv[sizeof rows / sizeof rows[0]];
  int n = 0;
  for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
    if (!rows[i].text || !rows[i].text[0])
      continue;
    kv[n++] = (struct wl_report_kv){rows[i].key, rows[i].text, 0, NULL, 0};
  }
  if (!st)
    st = wl_report_add_kv_table(d, NULL, kv, n, err);
  if (!st)
    st = wl_report_paragraphf(d, err,
                              "Input digest (SHA-256 of the scenario text stored with the "
                              "results, %zu bytes):\n%s",
                              r->scenario_len, c->digest);
  if (!st && s->text[0])
    st = wl_report_add_paragraph(d, s->text, err);
  if (!st)
    st = wl_report_add_heading(d, 3, "Summary of findings", err);
  char text[4096];
  summary(c, text, sizeof text);
  if (!st)
    st = wl_report_add_paragraph(d, text, err);
  if (!st)
    st = wl_report_break_page(d, err);
  return st;
}

/* ---- peaks -------------------------------------------------------------------------- */

enum wl_status wl_report_render_peaks(struct wl_report_ctx *c, const struct wl_report_section *s,
                                      struct wl_error *err) {
  const struct wl_results *r = c->res;
  const struct wl_results_case *cs = r->cases;
  struct wl_report_doc *d = c->doc;
  enum wl_status st = wl_report_section_begin(c, s, err);
  int dg = s->digits;
  char cut[WL_RESULTS_N_CASES][64];
  for (int i = 0; i < WL_RESULTS_N_CASES; i++)
    wl_report_fmt(cs[i].cutoff, 3, cut[i], sizeof cut[i]);
  if (!st) {
    char cuts[256] = "";
    struct buf b = {cuts, sizeof cuts, 0};
    int k = 0;
    for (int i = 0; i < WL_RESULTS_N_CASES; i++)
      if (cs[i].present)
        put(&b, "%s%s Hz for the %s case", k++ ? ", " : "", cut[i], cs[i].name);
    st = wl_report_paragraphf(
        d, err,
        "Peak force and peak moment are taken from the low-pass filtered series (zero-phase "
        "Butterworth, cut-off c0/(8 d), d the water depth at the wall: %s), not from the raw "
        "ones. The positive impulse, the one to quote, is the time integral of the filtered "
        "force wherever it exceeds the model's force at rest (its mean before the wave reaches "
        "the wall, which differs from rho g d^2/2 by the discretisation at the wall; rho g "
        "d^2/2 itself where the wave is at the wall from the start), over the record from where "
        "peaks are searched: the push of every wave together, which converges with resolution. "
        "The positive phase's impulse integrates the raw force minus the force at rest over "
        "the peak's positive phase only (from the last time before the peak that the filtered "
        "force was at or below the force at rest to the first time after it); where a wave "
        "train brings several crests of nearly equal force, which crest carries the peak, and "
        "so this impulse, changes with resolution. The net impulse integrates the raw force "
        "minus the force at rest to the end of the record; for an oscillating train it nearly "
        "cancels. Run-up is the highest water level at the wall face "
        "above still water. Rise time and duration are those of the filtered force in excess "
        "of the force at rest (10 %% of its peak). All per metre of wall.",
        k ? cuts : "no case in the results");
  }
  static const struct wl_report_column cols0[] = {
      {"case", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"peak force", "kN/m", WL_REPORT_ALIGN_AUTO, 0},
      {"at", "s", WL_REPORT_ALIGN_AUTO, 0},
      {"impulse", "kN s/m", WL_REPORT_ALIGN_AUTO, 0},
      {"pos. phase", "kN s/m", WL_REPORT_ALIGN_AUTO, 0},
      {"net", "kN s/m", WL_REPORT_ALIGN_AUTO, 0},
      {"peak moment", "kN m/m", WL_REPORT_ALIGN_AUTO, 0},
      {"run-up", "m", WL_REPORT_ALIGN_AUTO, 0},
      {"rise time", "s", WL_REPORT_ALIGN_AUTO, 0},
      {"duration", "s", WL_REPORT_ALIGN_AUTO, 0},
  };
  enum { NC = 10 };
  struct wl_report_column cols[NC];
  memcpy(cols, cols0, sizeof cols);
  for (int k = 1; k < NC; k++)
    cols[k].sig = dg;
  struct wl_report_cell cells[(WL_RESULTS_N_CASES + 1) * NC];
  int rows = 0;
  static const struct wl_report_cell blank = {"", 0};
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_case *k = &cs[i];
    struct wl_report_cell *row = &cells[rows * NC];
    row[0] = (struct wl_report_cell){k->name, 0};
    if (!k->present) {
      row[1] = (struct wl_report_cell){"not run", 0};
      for (int j = 2; j < NC; j++)
        row[j] = blank;
    } else {
      row[1] = (struct wl_report_cell){NULL, k->force_peak.value / KILO};
      row[2] = (struct wl_report_cell){NULL, k->force_peak.time};
      row[3] = (struct wl_report_cell){NULL, k->impulse_positive / KILO};
      row[4] = (struct wl_report_cell){NULL, k->impulse_peak / KILO};
      row[5] = (struct wl_report_cell){NULL, k->impulse_total / KILO};
      row[6] = (struct wl_report_cell){NULL, k->moment_peak.value / KILO};
      row[7] = (struct wl_report_cell){NULL, k->runup};
      row[8] = (struct wl_report_cell){NULL, k->force_peak.rise_time};
      row[9] = (struct wl_report_cell){NULL, k->force_peak.duration};
    }
    rows++;
  }
  if (r->n_cases == 2) {
    struct wl_report_cell *row = &cells[rows * NC];
    for (int j = 0; j < NC; j++)
      row[j] = blank;
    row[0].text = "governs";
    int g;
    g = wl_report_governs(cs[0].force_peak.value, cs[1].force_peak.value);
    row[1].text = g < 0 ? "n/a" : cs[g].name;
    g = wl_report_governs(cs[0].impulse_positive, cs[1].impulse_positive);
    row[3].text = g < 0 ? "n/a" : cs[g].name;
    g = wl_report_governs(cs[0].impulse_peak, cs[1].impulse_peak);
    row[4].text = g < 0 ? "n/a" : cs[g].name;
    g = wl_report_governs(cs[0].impulse_total, cs[1].impulse_total);
    row[5].text = g < 0 ? "n/a" : cs[g].name;
    g = wl_report_governs(cs[0].moment_peak.value, cs[1].moment_peak.value);
    row[6].text = g < 0 ? "n/a" : cs[g].name;
    g = wl_report_governs(cs[0].runup, cs[1].runup);
    row[7].text = g < 0 ? "n/a" : cs[g].name;
    rows++;
  }
  struct wl_report_table tab = {
      "Peak loads per metre of wall (peak force and moment from the filtered series; impulse: "
      "the positive impulse; pos. phase: the peak's positive phase; net: the whole record)",
      cols, NC,
      cells, rows};
  if (!st)
    st = wl_report_add_table(d, &tab, err);

  /* The same peaks in US customary units, per foot of wall, when the
   * scenario wrote its lengths in feet or inches (units.h). */
  struct wl_load_units u;
  if (!st && wl_units_load_units(r->length_unit, &u)) {
    const struct wl_report_column ucols[] = {
        {"case", NULL, WL_REPORT_ALIGN_LEFT, 0},
        {"peak force", u.force, WL_REPORT_ALIGN_AUTO, dg},
        {"positive impulse", u.impulse, WL_REPORT_ALIGN_AUTO, dg},
        {"positive phase", u.impulse, WL_REPORT_ALIGN_AUTO, dg},
        {"net impulse", u.impulse, WL_REPORT_ALIGN_AUTO, dg},
        {"peak moment", u.moment, WL_REPORT_ALIGN_AUTO, dg},
        {"run-up", u.length, WL_REPORT_ALIGN_AUTO, dg},
    };
    enum { NU = 7 };
    struct wl_report_cell ucells[WL_RESULTS_N_CASES * NU];
    int urows = 0;
    for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
      const struct wl_results_case *k = &cs[i];
      if (!k->present)
        continue;
      struct wl_report_cell *row = &ucells[urows++ * NU];
      row[0] = (struct wl_report_cell){k->name, 0};
      row[1] = (struct wl_report_cell){NULL, k->force_peak.value * u.force_f};
      row[2] = (struct wl_report_cell){NULL, k->impulse_positive * u.impulse_f};
      row[3] = (struct wl_report_cell){NULL, k->impulse_peak * u.impulse_f};
      row[4] = (struct wl_report_cell){NULL, k->impulse_total * u.impulse_f};
      row[5] = (struct wl_report_cell){NULL, k->moment_peak.value * u.moment_f};
      row[6] = (struct wl_report_cell){NULL, k->runup * u.length_f};
    }
    struct wl_report_table ut = {
        "The same peaks in the scenario's units (US customary, per foot of wall; 1 lbf = "
        "4.4482216 N, 1 ft = 0.3048 m)",
        ucols, NU, ucells, urows};
    st = wl_report_add_table(d, &ut, err);
  }

  /* Probe force against boundary-particle force: the error indicator. */
  static const struct wl_report_column ecols0[] = {
      {"case", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"probes at rest", "kN/m", WL_REPORT_ALIGN_AUTO, 0},
      {"boundary at rest", "kN/m", WL_REPORT_ALIGN_AUTO, 0},
      {"probe peak", "kN/m", WL_REPORT_ALIGN_AUTO, 0},
      {"boundary peak", "kN/m", WL_REPORT_ALIGN_AUTO, 0},
      {"difference", "% of probe", WL_REPORT_ALIGN_AUTO, 0},
      {"boundary impulse", "kN s/m", WL_REPORT_ALIGN_AUTO, 0},
  };
  enum { NE = 7 };
  struct wl_report_column ecols[NE];
  memcpy(ecols, ecols0, sizeof ecols);
  for (int k = 1; k < NE; k++)
    ecols[k].sig = dg;
  ecols[5].sig = 2;
  struct wl_report_cell ecells[WL_RESULTS_N_CASES * NE];
  int erows = 0;
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_case *k = &cs[i];
    if (!k->present)
      continue;
    struct wl_report_cell *row = &ecells[erows * NE];
    row[0] = (struct wl_report_cell){k->name, 0};
    row[1] = (struct wl_report_cell){NULL, k->rest_force / KILO};
    row[2] = (struct wl_report_cell){NULL, k->rest_force_b / KILO};
    row[3] = (struct wl_report_cell){NULL, k->force_peak.value / KILO};
    row[4] = (struct wl_report_cell){NULL, k->force_b_peak.value / KILO};
    row[5] = (struct wl_report_cell){NULL, 100.0 * (k->force_b_peak.value - k->force_peak.value) /
                                               fabs(k->force_peak.value)};
    row[6] = (struct wl_report_cell){NULL, k->impulse_b_total / KILO};
    erows++;
  }
  if (!st && erows) {
    st = wl_report_add_paragraph(
        d,
        "The wall force is measured twice: by the pressure probes on the wall face (the "
        "values above) and by summing the SPH forces on the wall's boundary particles. The "
        "difference between the two measures how the wall is discretised at this resolution; "
        "it is not the error of the resolution itself, which a convergence ladder estimates "
        "(the two can agree within 1 % while the load still moves by several per cent between "
        "resolutions). Each measurement's "
        "force at rest is its own mean before the wave reaches the wall; each impulse "
        "subtracts its own.",
        err);
    struct wl_report_table et = {"Probe and boundary-particle wall force (filtered peaks)", ecols,
                                 NE, ecells, erows};
    if (!st)
      st = wl_report_add_table(d, &et, err);
  }
  for (int i = 0; !st && i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_case *k = &cs[i];
    if (!k->present)
      st = wl_report_paragraphf(d, err,
                                "The %s case is not in the results: the scenario or the "
                                "run had no %s.",
                                k->name, wl_report_case_label(i));
    else if (strcmp(k->status, "complete"))
      st = wl_report_paragraphf(d, err,
                                "The %s case did not complete (%s%s%s): its peaks are those of "
                                "the %zu samples recorded and may not be the peaks of the event.",
                                k->name, k->status[0] ? k->status : "status not stored",
                                k->stopped[0] ? ": " : "", k->stopped, k->n);
  }
  return st;
}

/* ---- convergence ----------------------------------------------------------------------- */

/* Relative change [%] from a to b; NAN when undefined. */
static double change_pct(double b, double a) {
  double r = 100.0 * (b - a) / fabs(a);
  return isfinite(r) ? r : NAN;
}

/* One case's ladder: level by level, with the change between levels. */
static enum wl_status convergence_case_table(struct wl_report_ctx *c, int i, int dg,
                                             struct wl_error *err) {
  const struct wl_results_convergence *cv = &c->res->conv[i];
  static const struct wl_report_column cols0[] = {
      {"level", NULL, WL_REPORT_ALIGN_RIGHT, 0},
      {"dp", "m", WL_REPORT_ALIGN_AUTO, 0},
      {"particles", NULL, WL_REPORT_ALIGN_RIGHT, 0},
      {"runtime", "s", WL_REPORT_ALIGN_AUTO, 0},
      {"peak force", "kN/m", WL_REPORT_ALIGN_AUTO, 0},
      {"change", "%", WL_REPORT_ALIGN_AUTO, 2},
      {"positive impulse", "kN s/m", WL_REPORT_ALIGN_AUTO, 0},
      {"change", "%", WL_REPORT_ALIGN_AUTO, 2},
      {"error", "%", WL_REPORT_ALIGN_AUTO, 2},
      {"status", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"runs' sd", "%", WL_REPORT_ALIGN_AUTO, 2},
  };
  enum { NC_MAX = 11 };
  /* the realisations' columns only where a level ran several
   * (resolution.realisations) */
  double real = 0;
  for (int l = 0; l < cv->n_levels; l++) real = fmax(real, cv->realisations[l] > 1 ? cv->realisations[l] : 0);
  const int nc = real > 1 ? NC_MAX : NC_MAX - 1;
  struct wl_report_column cols[NC_MAX];
  memcpy(cols, cols0, sizeof cols);
  cols[1].sig = cols[3].sig = cols[4].sig = cols[6].sig = dg;
  struct wl_report_cell cells[WL_RESULTS_MAX_LEVELS * NC_MAX];
  char txt[WL_RESULTS_MAX_LEVELS][2][32];
  for (int l = 0; l < cv->n_levels; l++) {
    struct wl_report_cell *row = &cells[l * nc];
    snprintf(txt[l][0], sizeof txt[l][0], "%d", l + 1);
    snprintf(txt[l][1], sizeof txt[l][1], "%.0f", cv->particles[l]);
    row[0] = (struct wl_report_cell){txt[l][0], 0};
    row[1] = (struct wl_report_cell){NULL, cv->dp[l]};
    row[2] = (struct wl_report_cell){txt[l][1], 0};
    row[3] = (struct wl_report_cell){NULL, cv->runtime[l]};
    row[4] = (struct wl_report_cell){NULL, cv->peak_force[l] / KILO};
    row[5] = (struct wl_report_cell){l ? NULL : "", l ? change_pct(cv->peak_force[l], cv->peak_force[l - 1]) : 0};
    row[6] = (struct wl_report_cell){NULL, cv->impulse_pos[l] / KILO};
    row[7] = (struct wl_report_cell){l ? NULL : "",
                                     l ? change_pct(cv->impulse_pos[l], cv->impulse_pos[l - 1]) : 0};
    row[8] = (struct wl_report_cell){NULL, 100.0 * cv->error[l]};
    row[9] = (struct wl_report_cell){cv->status[l] == 0 ? "complete" : "stopped", 0};
    if (real > 1)
      row[10] = cv->realisations[l] > 1 ? (struct wl_report_cell){NULL, 100.0 * cv->peak_force_sd[l] /
                                                                          fabs(cv->peak_force[l])}
                                        : (struct wl_report_cell){"", 0};
  }
  char caption[224], runs[96] = "";
  if (real > 1)
    snprintf(runs, sizeof runs, ", each level the mean of %.0f runs (their sd: runs' sd)", real);
  snprintf(caption, sizeof caption, "Convergence ladder of the %s case (peak force from the "
           "filtered probe force%s; change from the level above; the finest level's error is "
           "its uncertainty)", c->res->cases[i].name[0] ? c->res->cases[i].name : wl_store_results_case_name(i),
           runs);
  struct wl_report_table t = {caption, cols, nc, cells, cv->n_levels};
  return wl_report_add_table(c->doc, &t, err);
}

/* Order, extrapolated value and error estimate of every case: a row per
 * quantity and one for the case's estimate against the target. */
static enum wl_status convergence_summary_table(struct wl_report_ctx *c, int dg,
                                                struct wl_error *err) {
  const struct wl_results *r = c->res;
  static const struct wl_report_column cols0[] = {
      {"case", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"quantity", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"order p", NULL, WL_REPORT_ALIGN_AUTO, 3},
      {"extrapolated", NULL, WL_REPORT_ALIGN_AUTO, 0},
      {"uncertainty", "%", WL_REPORT_ALIGN_AUTO, 2},
      {"from", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"target", "%", WL_REPORT_ALIGN_AUTO, 2},
      {"met", NULL, WL_REPORT_ALIGN_LEFT, 0},
  };
  enum { NC = 8, ROWS = 4 };
  struct wl_report_column cols[NC];
  memcpy(cols, cols0, sizeof cols);
  cols[3].sig = dg;
  struct wl_report_cell cells[WL_RESULTS_N_CASES * ROWS * NC];
  static const struct wl_report_cell blank = {"", 0};
  int rows = 0;
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_convergence *cv = &r->conv[i];
    if (!cv->present)
      continue;
    struct wl_report_cell *a = &cells[rows * NC], *d = a + NC, *b = d + NC, *e = b + NC;
    for (int k = 0; k < ROWS * NC; k++)
      a[k] = blank;
    a[0] = (struct wl_report_cell){wl_store_results_case_name(i), 0};
    a[1] = (struct wl_report_cell){"peak force [kN/m]", 0};
    a[2] = (struct wl_report_cell){NULL, cv->force_order};
    a[3] = (struct wl_report_cell){NULL, cv->force_extrapolated / KILO};
    a[4] = (struct wl_report_cell){NULL, 100.0 * cv->force_error};
    a[5] = (struct wl_report_cell){cv->force_basis[0] ? cv->force_basis : "?", 0};
    /* the wave's part: the peak less the force at rest (the case's estimate takes it) */
    d[1] = (struct wl_report_cell){"peak less force at rest [kN/m]", 0};
    d[2] = (struct wl_report_cell){NULL, cv->dyn_order};
    d[3] = (struct wl_report_cell){NULL, cv->dyn_extrapolated / KILO};
    d[4] = (struct wl_report_cell){NULL, 100.0 * cv->dyn_error};
    d[5] = (struct wl_report_cell){cv->dyn_basis[0] ? cv->dyn_basis : "?", 0};
    b[1] = (struct wl_report_cell){"positive impulse [kN s/m]", 0};
    b[2] = (struct wl_report_cell){NULL, cv->pos_order};
    b[3] = (struct wl_report_cell){NULL, cv->pos_extrapolated / KILO};
    b[4] = (struct wl_report_cell){NULL, 100.0 * cv->pos_error};
    b[5] = (struct wl_report_cell){cv->pos_basis[0] ? cv->pos_basis : "?", 0};
    e[1] = (struct wl_report_cell){"case (the larger)", 0};
    e[4] = (struct wl_report_cell){NULL, 100.0 * cv->error_estimate};
    e[6] = (struct wl_report_cell){NULL, 100.0 * cv->target};
    e[7] = (struct wl_report_cell){!isfinite(cv->error_estimate) ? "n/a"
                                   : cv->target_met > 0          ? "yes"
                                                                 : "no",
                                   0};
    rows += ROWS;
  }
  struct wl_report_table t = {"Observed order, Richardson value and relative uncertainty of "
                              "the finest level run (order and extrapolation n/a where not "
                              "defined or not meaningful)",
                              cols, NC, cells, rows};
  return wl_report_add_table(c->doc, &t, err);
}

/* Estimated error of each level against its runtime, log-log, a line per case. */
static enum wl_status convergence_plot(struct wl_report_ctx *c, struct wl_error *err) {
  const struct wl_results *r = c->res;
  struct wl_report_series ser[WL_RESULTS_N_CASES];
  double x[WL_RESULTS_N_CASES][WL_RESULTS_MAX_LEVELS], y[WL_RESULTS_N_CASES][WL_RESULTS_MAX_LEVELS];
  int n = 0, drawable = 0;
  double target = NAN;
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_convergence *cv = &r->conv[i];
    if (!cv->present)
      continue;
    memset(&ser[n], 0, sizeof ser[n]);
    for (int l = 0; l < cv->n_levels; l++) {
      x[n][l] = cv->runtime[l] > 0 ? cv->runtime[l] : NAN;
      y[n][l] = cv->error[l] > 0 ? 100.0 * cv->error[l] : NAN;
      drawable += isfinite(x[n][l]) && isfinite(y[n][l]);
    }
    ser[n].label = wl_report_case_label(i);
    ser[n].x = x[n];
    ser[n].y = y[n];
    ser[n].n = (size_t)cv->n_levels;
    ser[n].marker = WL_REPORT_MARKER_AUTO;
    ser[n].colour = i + 1;
    if (isfinite(cv->target))
      target = 100.0 * cv->target;
    n++;
  }
  if (!drawable)
    return wl_report_add_paragraph(
        c->doc,
        "No error-against-runtime plot: no level has an error estimate (it needs two complete "
        "levels of a case).",
        err);
  char tl[64];
  snprintf(tl, sizeof tl, "target %.3g %%", target);
  struct wl_report_refline ref = {target, tl, 0};
  struct wl_report_plot p;
  memset(&p, 0, sizeof p);
  p.title = "Estimated error against runtime (each point a ladder level)";
  p.x.label = "runtime of the level";
  p.x.unit = "s";
  p.x.log = 1;
  p.y.label = "estimated relative error";
  p.y.unit = "%";
  p.y.log = 1;
  p.series = ser;
  p.n_series = n;
  p.refs = &ref;
  p.n_refs = isfinite(target) && target > 0 ? 1 : 0;
  p.legend = WL_REPORT_LEGEND_AUTO;
  struct wl_report_rect area;
  enum wl_status st = wl_report_begin_figure(c->doc, 260, &area, err);
  if (!st)
    st = wl_report_draw_plot(c->doc, &p, area, err);
  if (!st)
    st = wl_report_end_figure(
        c->doc,
        "Speed against error: the relative error of each coarser level (the larger of the peak "
        "force's part above the force at rest and the positive impulse, against the Richardson "
        "value where the order is meaningful, else against the finest level) and the finest "
        "level's uncertainty, against the wall-clock runtime of that level, log-log.",
        err);
  return st;
}

enum wl_status wl_report_render_convergence(struct wl_report_ctx *c,
                                            const struct wl_report_section *s,
                                            struct wl_error *err) {
  const struct wl_results *r = c->res;
  enum wl_status st = wl_report_section_begin(c, s, err);
  const char *asked = r->convergence_asked;
  int n_conv = 0;
  for (int i = 0; i < WL_RESULTS_N_CASES; i++)
    n_conv += r->conv[i].present;
  if (n_conv) {
    int dg = s->digits > 0 ? s->digits : DEFAULT_DIGITS;
    if (!st)
      st = wl_report_paragraphf(
          c->doc, err,
          "Each load case was run on a ladder of particle spacings%s%s (dp times each factor, "
          "coarse to fine); the finest level run is the case's result on the other pages. From "
          "the last three levels (spacings h1 > h2 > h3, refinement ratio r) the observed order "
          "is p = ln((f1 - f2)/(f2 - f3)) / ln r and the Richardson value f_ext = f3 + (f3 - f2)/"
          "(r^p - 1). The uncertainty of the finest level is a band meant to hold the converged "
          "value (Roache's grid convergence index, with the order bands of Eca & Hoekstra 2014): "
          "1.25 |f3 - f_ext| where 0.95 <= p < 2.05; for a larger p the same with p = 2 but at "
          "least 1.25 times the range of the three values; for a smaller p the smaller of "
          "1.25 |f3 - f_ext| and 3 times the range; where the values oscillate, 3 times their "
          "range; with two levels 3 |f3 - f2| / (r^2 - 1). It is given relative to f3. A case's "
          "uncertainty is the larger of those of the peak force less the model's force at rest "
          "(the wave's part: the whole peak's relative band is small where the wave adds little "
          "to a large force at rest) and the positive impulse (an oscillating wave train's net "
          "impulse is too small a difference to converge, and which crest carries its peak, "
          "whose positive phase would be integrated, changes with resolution).",
          asked[0] ? " " : "", asked);
    for (int i = 0; !st && i < WL_RESULTS_N_CASES; i++)
      if (r->conv[i].present)
        st = convergence_case_table(c, i, dg, err);
    if (!st)
      st = convergence_summary_table(c, dg, err);
    for (int i = 0; !st && i < WL_RESULTS_N_CASES; i++)
      if (r->conv[i].present && r->conv[i].note[0])
        st = wl_report_paragraphf(c->doc, err, "The %s case: %s.", wl_store_results_case_name(i),
                                  r->conv[i].note);
    if (!st)
      st = convergence_plot(c, err);
    for (int i = 0; !st && i < WL_RESULTS_N_CASES; i++)
      if (r->cases[i].present && !r->conv[i].present)
        st = wl_report_paragraphf(c->doc, err,
                                  "The %s case holds no convergence ladder (it ran at a single "
                                  "resolution, dp = %g m).",
                                  wl_store_results_case_name(i), r->cases[i].dp);
    return st;
  }
  if (!st && r->has_convergence)
    st = wl_report_add_paragraph(c->doc,
                                 "These results hold a /convergence group, but no case in it "
                                 "that this version of the report reads; nothing from it is shown.",
                                 err);
  if (!st && asked[0])
    st = wl_report_paragraphf(
        c->doc, err,
        "The scenario asks for a convergence ladder (resolution.convergence: %s), but these "
        "results hold a single resolution (dp = %g m): they were written by a version of "
        "wallload assess that did not run ladders. No convergence plot is drawn, and the "
        "error of the resolution is not known: the difference between the probe and "
        "boundary-particle wall forces (see the peak loads) measures the wall's "
        "discretisation only.",
        asked, r->dp);
  else if (!st && !r->has_convergence)
    st = wl_report_paragraphf(
        c->doc, err,
        "No convergence ladder was run for these results (a single resolution, dp = %g m), so "
        "no convergence plot is drawn and the error of the resolution is not known: the "
        "difference between the probe and boundary-particle wall forces (see the peak loads) "
        "measures the wall's discretisation only, and the two can agree within 1 %% while the "
        "load still moves by several per cent between resolutions. "
        "To ask for a ladder, add to the scenario\n"
        "    resolution: { convergence: [1, 0.71, 0.5] }\n"
        "(dp, dp/sqrt 2, dp/2) and run wallload assess again: the report then shows peak force, "
        "impulse and runtime at each level with an estimate of the error.",
        r->dp);
  return st;
}

/* ---- metadata (run record) ------------------------------------------------------------- */

/* A stored setting as the table shows it: its value, "(default)" when the
 * scenario did not give it. */
static const char *setting_text(const struct wl_results *r, const char *key, char *out,
                                size_t size) {
  const struct wl_results_setting *v = wl_store_results_setting(r, key);
  snprintf(out, size, "%s%s", v ? v->value : "(not stored)", v && !v->given ? " (default)" : "");
  return out;
}

enum wl_status wl_report_render_metadata(struct wl_report_ctx *c, const struct wl_report_section *s,
                                         struct wl_error *err) {
  const struct wl_results *r = c->res;
  const struct wl_results_case *cs = r->cases;
  struct wl_report_doc *d = c->doc;
  enum wl_status st = wl_report_section_begin(c, s, err);
  char threads[64], by[128], made[128];
  snprintf(by, sizeof by, "wallload %s", WL_VERSION);
  if (isfinite(r->threads))
    snprintf(threads, sizeof threads, "%.0f", r->threads);
  else
    snprintf(threads, sizeof threads, "(not stored)");
  snprintf(made, sizeof made, "wallload %s, %s", r->version[0] ? r->version : "?",
           r->created[0] ? r->created : "time not stored");
  struct wl_report_kv run[] = {
      {"Results file", r->path, 0, NULL, 0},
      {"Written by", made, 0, NULL, 0},
      {"Rendered by", by, 0, NULL, 0},
      {"Template", c->template_source, 0, NULL, 0},
      {"Scenario", r->scenario_name[0] ? r->scenario_name : "(not stored)", 0, NULL, 0},
      {"Scenario file", r->scenario_file[0] ? r->scenario_file : "(not stored)", 0, NULL, 0},
      {"Backend", r->backend[0] ? r->backend : "(not stored)", 0, NULL, 0},
      {"Threads", threads, 0, NULL, 0},
      {"Particle spacing dp", NULL, r->dp, "m", 4},
  };
  if (!st)
    st = wl_report_add_kv_table(d, "Run", run, (int)(sizeof run / sizeof run[0]), err);

  static const struct wl_report_column rc[] = {
      {"case", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"dp", "m", WL_REPORT_ALIGN_AUTO, 4},
      {"h", "m", WL_REPORT_ALIGN_AUTO, 4},
      {"c0", "m/s", WL_REPORT_ALIGN_AUTO, 4},
      {"particles", NULL, WL_REPORT_ALIGN_RIGHT, 0},
      {"fluid", NULL, WL_REPORT_ALIGN_RIGHT, 0},
      {"filter cut-off", "Hz", WL_REPORT_ALIGN_AUTO, 4},
  };
  static const struct wl_report_column tc[] = {
      {"case", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"status", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"steps", NULL, WL_REPORT_ALIGN_RIGHT, 0},
      {"simulated", "s", WL_REPORT_ALIGN_AUTO, 4},
      {"planned", "s", WL_REPORT_ALIGN_AUTO, 4},
      {"runtime", "s", WL_REPORT_ALIGN_AUTO, 4},
      {"particle-steps/s", NULL, WL_REPORT_ALIGN_AUTO, 3},
  };
  struct wl_report_cell rcells[WL_RESULTS_N_CASES * 7], tcells[WL_RESULTS_N_CASES * 7];
  char counts[WL_RESULTS_N_CASES][3][32]; /* whole numbers, printed whole */
  int n = 0;
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_case *k = &cs[i];
    if (!k->present)
      continue;
    struct wl_report_cell *a = &rcells[7 * n], *b = &tcells[7 * n];
    a[0] = b[0] = (struct wl_report_cell){k->name, 0};
    a[1] = (struct wl_report_cell){NULL, k->dp};
    a[2] = (struct wl_report_cell){NULL, k->h};
    a[3] = (struct wl_report_cell){NULL, k->c0};
    snprintf(counts[n][0], sizeof counts[n][0], "%.0f", k->particles);
    snprintf(counts[n][1], sizeof counts[n][1], "%.0f", k->fluid_particles);
    snprintf(counts[n][2], sizeof counts[n][2], "%.0f", k->steps);
    a[4] = (struct wl_report_cell){counts[n][0], 0};
    a[5] = (struct wl_report_cell){counts[n][1], 0};
    a[6] = (struct wl_report_cell){NULL, k->cutoff};
    b[1] = (struct wl_report_cell){k->status[0] ? k->status : "?", 0};
    b[2] = (struct wl_report_cell){counts[n][2], 0};
    b[3] = (struct wl_report_cell){NULL, k->time_reached};
    b[4] = (struct wl_report_cell){NULL, k->end_time};
    b[5] = (struct wl_report_cell){NULL, k->runtime};
    b[6] =
        (struct wl_report_cell){NULL, k->runtime > 0 ? k->particles * k->steps / k->runtime : NAN};
    n++;
  }
  if (!st && n) {
    struct wl_report_table t1 = {"Resolution of each load case", rc, 7, rcells, n};
    struct wl_report_table t2 = {"Run of each load case", tc, 7, tcells, n};
    st = wl_report_add_table(d, &t1, err);
    if (!st)
      st = wl_report_add_table(d, &t2, err);
  } else if (!st) {
    st = wl_report_add_paragraph(d, "The results hold no load case.", err);
  }
  for (int i = 0; !st && i < WL_RESULTS_N_CASES; i++) {
    const struct wl_results_case *k = &cs[i];
    if (!k->present)
      st = wl_report_paragraphf(d, err, "The %s case is not in the results.", k->name);
    else if (strcmp(k->status, "complete"))
      st = wl_report_paragraphf(d, err, "The %s case stopped: %s%s%s.", k->name,
                                k->status[0] ? k->status : "status not stored",
                                k->stopped[0] ? ": " : "", k->stopped);
  }

  if (!st && r->n_settings) {
    /* store's table of the settings: their keys and labels (store.h) */
    enum { N_ROWS = WL_RESULTS_MAX_SETTINGS };
    const int n_rows = wl_store_results_n_settings;
    char v[N_ROWS][200];
    struct wl_report_kv num[N_ROWS];
    for (int i = 0; i < n_rows; i++)
      num[i] = (struct wl_report_kv){wl_store_results_settings[i].label,
                                     setting_text(r, wl_store_results_settings[i].key, v[i],
                                                  sizeof v[i]),
                                     0, NULL, 0};
    st = wl_report_add_kv_table(d, "Numerical settings (from the stored scenario)", num, n_rows,
                                err);
  } else if (!st) {
    st = wl_report_paragraphf(d, err, "Numerical settings are not shown: %s.",
                              WL_REPORT_NO_PLAN);
  }
  if (!st && r->plan.notes[0]) {
    char text[WL_RESULTS_NOTES_MAX + 256];
    struct buf b = {text, sizeof text, 0};
    put(&b, "Notes of the plan (as wallload check prints them):");
    char notes[WL_RESULTS_NOTES_MAX];
    snprintf(notes, sizeof notes, "%s", r->plan.notes);
    char *save = NULL;
    for (char *line = strtok_r(notes, "\n", &save); line; line = strtok_r(NULL, "\n", &save))
      put(&b, "\n- %s", line);
    st = wl_report_add_paragraph(d, text, err);
  }
  if (!st && s->scenario_text) {
    st = wl_report_add_heading(d, 2, "Scenario file as run", err);
    if (!st)
      st = wl_report_paragraphf(d, err, "%s (SHA-256 %s):",
                                r->scenario_file[0] ? r->scenario_file : "scenario", c->digest);
    if (!st)
      st = wl_report_add_preformatted(d, r->scenario_len ? r->scenario_text : "(not stored)", err);
  }
  return st;
}

/* ---- the report ---------------------------------------------------------------------- */

typedef enum wl_status (*renderer)(struct wl_report_ctx *, const struct wl_report_section *,
                                   struct wl_error *);

static const renderer RENDERERS[WL_REPORT_SECTION_COUNT] = {
    wl_report_render_title,  wl_report_render_scene,       wl_report_render_snapshots,
    wl_report_render_gauges, wl_report_render_loads,       wl_report_render_peaks,
    wl_report_render_design, wl_report_render_convergence, wl_report_render_metadata,
};

enum wl_status wl_report_render(const char *results_h5, const char *template_path,
                                const char *pdf_path, struct wl_error *err) {
  struct wl_report_template tpl;
  wl_report_template_init(&tpl);
  struct wl_report_ctx ctx;
  memset(&ctx, 0, sizeof ctx);
  enum wl_status st = WL_OK;
  if (!results_h5 || !*results_h5 || !pdf_path || !*pdf_path)
    return wl_error_set(err, WL_EUSAGE, "report: needs a results file and an output file");
  /* A template named by the caller is checked first: a bad one fails fast. */
  if (template_path) {
    st = wl_report_template_load(template_path, &tpl, err);
    snprintf(ctx.template_source, sizeof ctx.template_source, "%s", template_path);
    if (st)
      return st;
  }
  struct wl_results *res = malloc(sizeof *res);
  if (!res) {
    wl_report_template_clear(&tpl);
    return wl_error_set(err, WL_ENOMEM, "report: no memory for the results");
  }
  st = wl_store_results_read(results_h5, res, err);
  if (!st && !template_path)
    st =
        wl_report_template_resolve(res, &tpl, ctx.template_source, sizeof ctx.template_source, err);
  struct wl_report_doc *doc = NULL;
  if (!st) {
    struct wl_report_doc_info info = {tpl.title, res->scenario_name[0] ? res->scenario_name : NULL,
                                      tpl.company, WL_VERSION};
    st = wl_report_doc_open(pdf_path, &info, &doc, err);
  }
  if (!st) {
    ctx.doc = doc;
    ctx.tpl = &tpl;
    ctx.res = res;
    wl_report_sha256_hex(res->scenario_text, res->scenario_len, ctx.digest);
    ctx.digits = DEFAULT_DIGITS;
    for (int i = 0; i < tpl.n_sections; i++)
      if (tpl.sections[i].type == WL_REPORT_SECTION_PEAKS) {
        ctx.digits = tpl.sections[i].digits;
        break;
      }
    for (int i = 0; !st && i < tpl.n_sections; i++) {
      const struct wl_report_section *s = &tpl.sections[i];
      if ((int)s->type < 0 || s->type >= WL_REPORT_SECTION_COUNT)
        continue;
      st = RENDERERS[s->type](&ctx, s, err);
    }
    if (!st)
      st = wl_report_doc_finish(doc, err);
  }
  wl_report_doc_free(doc);
  wl_store_results_clear(res);
  free(res);
  wl_report_template_clear(&tpl);
  return st;
}
