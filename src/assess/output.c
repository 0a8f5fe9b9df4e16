/* output.c: results.h5, summary.json and CSV files of an assessment, each
 * written atomically (store module). Layout documented in README.md. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "assess_private.h"
#include "wallload/config.h"
#include "wallload/store.h"
#include "wallload/units.h"


/* A JSON number: non-finite values are written as null. */
static void jnum(struct wl_text *t, double v) {
  if (isfinite(v))
    wl_text_put(t, "%.10g", v);
  else
    wl_text_put(t, "null");
}

static void jstr(struct wl_text *t, const char *s) {
  wl_text_put(t, "\"");
  for (; *s; s++) {
    unsigned char ch = (unsigned char)*s;
    if (ch == '"' || ch == '\\')
      wl_text_put(t, "\\%c", ch);
    else if (ch < 0x20)
      wl_text_put(t, "\\u%04x", ch);
    else
      wl_text_put(t, "%c", ch);
  }
  wl_text_put(t, "\"");
}

static void jval(struct wl_text *t, const char *key, double v, const char *unit, const char *what,
                 int last) {
  wl_text_put(t, "      ");
  jstr(t, key);
  wl_text_put(t, ": { \"value\": ");
  jnum(t, v);
  wl_text_put(t, ", \"unit\": ");
  jstr(t, unit);
  if (what) {
    wl_text_put(t, ", \"from\": ");
    jstr(t, what);
  }
  wl_text_put(t, " }%s\n", last ? "" : ",");
}

static const char *status_word(enum wl_status st) {
  switch (st) {
  case WL_OK: return "complete";
  case WL_EUNSTABLE: return "unstable";
  case WL_EINTERRUPTED: return "interrupted";
  default: return "failed";
  }
}

/* ---- convergence ladder ------------------------------------------------------ */

/* The per-level quantities of a ladder: name (HDF5 dataset, JSON key, CSV
 * column stem), unit, description, and where the value is. */
struct level_field {
  const char *name, *unit, *desc;
  size_t offset;
  int kind; /* 0 double, 1 int, 2 long, 3 status word */
};
#define LF(m) offsetof(struct wl_assess_level, m)
static const struct level_field LEVEL_FIELDS[] = {
    {"factor", "1", "level's factor of the scenario's dp", LF(factor), 0},
    {"dp", "m", "particle spacing of the level", LF(dp), 0},
    {"particles", "1", "fluid and boundary particles", LF(n_particles), 1},
    {"steps", "1", "time steps", LF(steps), 2},
    {"runtime", "s", "wall-clock time of the level's run", LF(runtime_s), 0},
    {"particle_steps_per_second", "1/s", "particles x steps / runtime", LF(rate), 0},
    {"time_reached", "s", "simulated time reached", LF(t_reached), 0},
    {"peak_force", "N/m", "peak of the filtered pressure-probe force", LF(peak_force), 0},
    {"peak_force_boundary", "N/m", "peak of the filtered boundary-particle force",
     LF(peak_force_bound), 0},
    {"impulse", "N s/m", "integral of (probe force - static force) dt to the end", LF(impulse), 0},
    {"impulse_positive_phase", "N s/m",
     "integral of (probe force - static force) dt over the peak's positive phase",
     LF(impulse_phase), 0},
    {"impulse_positive", "N s/m",
     "integral of max(0, filtered probe force - force at rest) dt: every wave's push",
     LF(impulse_positive), 0},
    {"peak_moment", "N m/m", "peak of the filtered overturning moment about the toe",
     LF(peak_moment), 0},
    {"max_runup", "m", "highest water level at the wall face above still water", LF(runup), 0},
    {"estimated_error", "1",
     "relative error of the level: larger of peak force and positive impulse, against "
     "the Richardson value (or the finest level); the finest level's is the case's "
     "uncertainty (loads.h)",
     LF(error), 0},
    {"status", "", "complete, unstable, interrupted or failed", LF(status), 3},
};
#undef LF
enum { N_LEVEL_FIELDS = sizeof LEVEL_FIELDS / sizeof LEVEL_FIELDS[0] };

static double level_value(const struct wl_assess_level *lv, const struct level_field *f) {
  const char *p = (const char *)lv + f->offset;
  switch (f->kind) {
  case 1: return (double)*(const int *)(const void *)p;
  case 2: return (double)*(const long *)(const void *)p;
  case 3: return (double)*(const enum wl_status *)(const void *)p;
  default: return *(const double *)(const void *)p;
  }
}

static const char *bool_word(int b) { return b ? "true" : "false"; }

static void json_estimate(struct wl_text *t, const char *key, const struct wl_loads_convergence *e,
                          int last) {
  wl_text_put(t, "        ");
  jstr(t, key);
  wl_text_put(t, ": { \"order\": ");
  jnum(t, e->order);
  wl_text_put(t, ", \"order_meaningful\": %s, \"extrapolated\": ", bool_word(e->order_ok));
  jnum(t, e->extrapolated);
  wl_text_put(t, ", \"error_estimate\": ");
  jnum(t, e->error);
  wl_text_put(t, ", \"basis\": ");
  jstr(t, wl_loads_estimate_name(e->basis));
  wl_text_put(t, " }%s\n", last ? "" : ",");
}

static void json_convergence(struct wl_text *t, const struct wl_assess_convergence *cv) {
  wl_text_put(t, "      \"convergence\": {\n        \"units\": {");
  for (int k = 0; k < N_LEVEL_FIELDS; k++) {
    if (LEVEL_FIELDS[k].kind == 3) continue;
    wl_text_put(t, "%s", k ? ", " : " ");
    jstr(t, LEVEL_FIELDS[k].name);
    wl_text_put(t, ": ");
    jstr(t, LEVEL_FIELDS[k].unit);
  }
  wl_text_put(t, " },\n        \"levels\": [\n");
  for (int l = 0; l < cv->n_levels; l++) {
    const struct wl_assess_level *lv = &cv->lv[l];
    wl_text_put(t, "          {");
    for (int k = 0; k < N_LEVEL_FIELDS; k++) {
      const struct level_field *f = &LEVEL_FIELDS[k];
      wl_text_put(t, "%s", k ? ", " : " ");
      jstr(t, f->name);
      wl_text_put(t, ": ");
      if (f->kind == 3)
        jstr(t, status_word(lv->status));
      else
        jnum(t, level_value(lv, f));
    }
    wl_text_put(t, " }%s\n", l + 1 < cv->n_levels ? "," : "");
  }
  wl_text_put(t, "        ],\n        \"levels_planned\": %d,\n", cv->n_planned);
  wl_text_put(t, "        \"ratio\": ");
  jnum(t, cv->force.r32);
  wl_text_put(t, ",\n        \"order\": { \"peak_force\": ");
  jnum(t, cv->force.order);
  wl_text_put(t, ", \"impulse_positive\": ");
  jnum(t, cv->impulse_pos.order);
  wl_text_put(t, " },\n");
  json_estimate(t, "peak_force", &cv->force, 0);
  json_estimate(t, "impulse_positive", &cv->impulse_pos, 0);
  wl_text_put(t, "        \"error_estimate\": ");
  jnum(t, cv->error_estimate);
  wl_text_put(t, ",\n        \"target\": ");
  jnum(t, cv->target);
  wl_text_put(t, ",\n        \"target_given\": %s,\n        \"target_met\": %s,\n"
         "        \"stopped_early\": %s,\n        \"note\": ",
      bool_word(cv->target_given), bool_word(cv->target_met), bool_word(cv->stopped_early));
  jstr(t, cv->note);
  wl_text_put(t, "\n      }\n");
}

static enum wl_status write_convergence_h5(struct wl_store *h5, const struct wl_case_result *c,
                                           const struct wl_assess_convergence *cv,
                                           struct wl_error *err) {
  char g[64], p[160];
  snprintf(g, sizeof g, "convergence/%s", c->name);
  size_t n = (size_t)cv->n_levels;
  double col[WL_ASSESS_MAX_LEVELS];
  enum wl_status st = WL_OK;
  for (int k = 0; !st && k < N_LEVEL_FIELDS; k++) {
    const struct level_field *f = &LEVEL_FIELDS[k];
    snprintf(p, sizeof p, "%s/%s", g, f->name);
    if (f->kind == 3) {
      int code[WL_ASSESS_MAX_LEVELS];
      for (size_t l = 0; l < n; l++) code[l] = (int)cv->lv[l].status;
      st = wl_store_write_vector_i(h5, p, code, n,
                                   "run status per level: 0 complete, else the failure code "
                                   "(enum wl_status: unstable, interrupted, ...)",
                                   err);
      continue;
    }
    for (size_t l = 0; l < n; l++) col[l] = level_value(&cv->lv[l], f);
    st = wl_store_write_vector(h5, p, col, n, f->unit, f->desc, err);
  }
  struct {
    const char *name;
    double v;
    const char *unit;
  } attrs[] = {
      {"levels_planned", cv->n_planned, "1"},
      {"levels_run", cv->n_levels, "1"},
      {"ratio", cv->force.r32, "1"},
      {"peak_force_order", cv->force.order, "1"},
      {"peak_force_order_meaningful", cv->force.order_ok, "1"},
      {"peak_force_extrapolated", cv->force.extrapolated, "N/m"},
      {"peak_force_error_estimate", cv->force.error, "1"},
      {"impulse_positive_order", cv->impulse_pos.order, "1"},
      {"impulse_positive_order_meaningful", cv->impulse_pos.order_ok, "1"},
      {"impulse_positive_extrapolated", cv->impulse_pos.extrapolated, "N s/m"},
      {"impulse_positive_error_estimate", cv->impulse_pos.error, "1"},
      {"error_estimate", cv->error_estimate, "1"},
      {"target", cv->target, "1"},
      {"target_given", cv->target_given, "1"},
      {"target_met", cv->target_met, "1"},
      {"stopped_early", cv->stopped_early, "1"},
  };
  for (size_t i = 0; !st && i < sizeof attrs / sizeof attrs[0]; i++)
    st = wl_store_attr_double(h5, g, attrs[i].name, attrs[i].v, attrs[i].unit, err);
  if (!st)
    st = wl_store_attr_text(h5, g, "peak_force_basis", wl_loads_estimate_name(cv->force.basis), err);
  if (!st)
    st = wl_store_attr_text(h5, g, "impulse_positive_basis",
                            wl_loads_estimate_name(cv->impulse_pos.basis), err);
  if (!st) st = wl_store_attr_text(h5, g, "note", cv->note, err);
  return st;
}

/* convergence.csv: one row per case and level. */
static enum wl_status write_convergence_csv(const struct wl_assess_result *res,
                                            struct wl_store_batch *b, struct wl_error *err) {
  struct wl_text t = {0};
  wl_text_put(&t, "case,level");
  for (int k = 0; k < N_LEVEL_FIELDS; k++) {
    const struct level_field *f = &LEVEL_FIELDS[k];
    if (f->kind == 3 || !strcmp(f->unit, "1")) {
      wl_text_put(&t, ",%s", f->name);
      continue;
    }
    /* units as the other CSV files spell them: N/m -> N_per_m, N s/m -> Ns_per_m */
    wl_text_put(&t, ",%s_", f->name);
    const char *u = f->unit;
    if (!strncmp(u, "1/", 2)) {
      wl_text_put(&t, "per_");
      u += 2;
    }
    for (; *u; u++)
      if (*u == '/')
        wl_text_put(&t, "_per_");
      else if (*u != ' ')
        wl_text_put(&t, "%c", *u);
  }
  wl_text_put(&t, "\n");
  for (int i = 0; i < res->n_cases; i++) {
    const struct wl_assess_convergence *cv = &res->conv[i];
    for (int l = 0; l < cv->n_levels; l++) {
      wl_text_put(&t, "%s,%d", res->cases[i].name, l + 1);
      for (int k = 0; k < N_LEVEL_FIELDS; k++) {
        const struct level_field *f = &LEVEL_FIELDS[k];
        if (f->kind == 3)
          wl_text_put(&t, ",%s", status_word(cv->lv[l].status));
        else
          wl_text_put(&t, ",%.10g", level_value(&cv->lv[l], f));
      }
      wl_text_put(&t, "\n");
    }
  }
  char path[600];
  snprintf(path, sizeof path, "%s/convergence.csv", res->out_dir);
  enum wl_status st = t.failed ? wl_error_set(err, WL_ENOMEM, "%s: no memory", path)
                               : wl_store_write_text_batch(path, t.s, t.len, b, err);
  free(t.s);
  return st;
}

static enum wl_status write_summary(const struct wl_scenario *s, const struct wl_plan *plan,
                                    const struct wl_assess_result *res,
                                    struct wl_store_batch *batch, struct wl_error *err) {
  struct wl_text t = {0};
  wl_text_put(&t, "{\n  \"scenario\": ");
  jstr(&t, s->name.text);
  wl_text_put(&t, ",\n  \"file\": ");
  jstr(&t, s->path);
  wl_text_put(&t, ",\n  \"wallload_version\": ");
  jstr(&t, WL_VERSION);
  wl_text_put(&t, ",\n  \"backend\": ");
  jstr(&t, res->backend);
  wl_text_put(&t, ",\n  \"threads\": %d,\n  \"cases\": {\n", res->threads);
  for (int i = 0; i < res->n_cases; i++) {
    const struct wl_case_result *c = &res->cases[i];
    const struct wl_case_loads *l = &c->loads;
    wl_text_put(&t, "    ");
    jstr(&t, c->name);
    wl_text_put(&t, ": {\n      \"status\": ");
    jstr(&t, status_word(c->status));
    if (c->status != WL_OK) {
      wl_text_put(&t, ",\n      \"stopped\": ");
      jstr(&t, c->message);
    }
    if (c->caution[0]) {
      wl_text_put(&t, ",\n      \"caution\": ");
      jstr(&t, c->caution);
    }
    wl_text_put(&t, ",\n");
    char filt[96];
    snprintf(filt, sizeof filt, "pressure probes, low-pass %.4g Hz", l->cutoff);
    char filt_b[96];
    snprintf(filt_b, sizeof filt_b, "boundary particles, low-pass %.4g Hz", l->cutoff);
    jval(&t, "peak_force", l->force_peak.value, "N/m", filt, 0);
    jval(&t, "peak_force_time", l->force_peak.time, "s", filt, 0);
    jval(&t, "peak_force_dynamic", l->force_peak.value - l->rest_force, "N/m",
         "peak_force minus the force at rest", 0);
    jval(&t, "peak_force_boundary", l->force_bound_peak.value, "N/m", filt_b, 0);
    jval(&t, "static_force", c->static_force, "N/m", "rho g d^2/2 at the wall at rest", 0);
    {
      char rest[160];
      if (l->rest_measured)
        snprintf(rest, sizeof rest, "the model's, mean of the raw force from %.4g to %.4g s, "
                 "before the wave reaches the wall", l->rest_from, l->rest_to);
      else
        snprintf(rest, sizeof rest, "no time at rest before the wave reaches the wall: the "
                 "nominal static_force");
      jval(&t, "rest_force", l->rest_force, "N/m", rest, 0);
      jval(&t, "rest_force_boundary", l->rest_force_bound, "N/m", rest, 0);
      jval(&t, "rest_from", l->rest_from, "s", "start of the rest window (null: none)", 0);
      jval(&t, "rest_to", l->rest_to, "s", "end of the rest window (null: none)", 0);
    }
    jval(&t, "impulse", l->impulse_total, "N s/m",
         "integral of (force - rest_force), raw pressure-probe force", 0);
    jval(&t, "impulse_boundary", c->rec.n ? l->impulse_bound[c->rec.n - 1] : NAN, "N s/m",
         "integral of (force - rest_force_boundary), boundary particles", 0);
    {
      char ph[160];
      snprintf(ph, sizeof ph,
               "integral of (force - rest_force) over the peak's positive phase, %.4g to %.4g s, "
               "raw pressure-probe force",
               l->impulse_peak_from, l->impulse_peak_to);
      jval(&t, "impulse_positive_phase", l->impulse_peak, "N s/m", ph, 0);
    }
    jval(&t, "impulse_positive", l->impulse_positive, "N s/m",
         "integral of max(0, filtered force - rest_force) from peaks_from on: the push of "
         "every wave, pressure probes", 0);
    jval(&t, "impulse_positive_boundary", l->impulse_positive_bound, "N s/m",
         "the same from the boundary particles", 0);
    jval(&t, "peak_moment", l->moment_peak.value, "N m/m", filt, 0);
    jval(&t, "max_runup", l->runup, "m", "water level at the wall face above still water", 0);
    struct wl_load_units u;
    if (wl_scenario_load_units(s, &u)) { /* the same figures per foot of wall */
      wl_text_put(&t, "      \"user_units\": {\n");
      jval(&t, "peak_force", l->force_peak.value * u.force_f, u.force, NULL, 0);
      jval(&t, "peak_force_boundary", l->force_bound_peak.value * u.force_f, u.force, NULL, 0);
      jval(&t, "impulse", l->impulse_total * u.impulse_f, u.impulse, NULL, 0);
      jval(&t, "impulse_positive_phase", l->impulse_peak * u.impulse_f, u.impulse, NULL, 0);
      jval(&t, "impulse_positive", l->impulse_positive * u.impulse_f, u.impulse, NULL, 0);
      jval(&t, "peak_moment", l->moment_peak.value * u.moment_f, u.moment, NULL, 0);
      jval(&t, "max_runup", l->runup * u.length_f, u.length, NULL, 1);
      wl_text_put(&t, "      },\n");
    }
    jval(&t, "rise_time", l->force_peak.rise_time, "s", "10 % of the dynamic peak to the peak", 0);
    jval(&t, "duration", l->force_peak.duration, "s", "dynamic force above 10 % of its peak", 0);
    jval(&t, "filter_cutoff", l->cutoff, "Hz", "c0/(8 d)", 0);
    jval(&t, "peaks_from", c->peak_from, "s",
         "peaks searched from half the wave's estimated arrival at the wall", 0);
    jval(&t, "dp", c->dp, "m", NULL, 0);
    jval(&t, "smoothing_length", c->h, "m", NULL, 0);
    jval(&t, "c0", c->c0, "m/s", NULL, 0);
    {
      const struct wl_sph_params *prm = &c->flume.cfg.prm;
      const int lam = prm->visc == WL_SPH_VISC_LAMINAR;
      jval(&t, "viscosity", lam ? prm->nu : prm->alpha, lam ? "m^2/s" : "1",
           lam ? "laminar, kinematic viscosity nu" : "artificial, alpha", 0);
      jval(&t, "density_diffusion", prm->ddt == WL_SPH_DDT_NONE ? 0.0 : prm->delta, "1",
           "delta-SPH coefficient (0: off)", 0);
      jval(&t, "shifting", prm->shift_coef, "1", "particle shifting coefficient A (0: off)", 0);
      jval(&t, "wall_condition", prm->boundary, "1",
           prm->boundary == WL_SPH_BOUND_DBC ? "0: dynamic boundary particles (DBC)"
                                             : "1: pressure from the fluid (Adami et al. 2012)",
           0);
      jval(&t, "force_evaluations_per_step", prm->integrator == WL_SPH_VERLET ? 1 : 2, "1",
           prm->integrator == WL_SPH_VERLET ? "Verlet integrator" : "symplectic integrator", 0);
    }
    jval(&t, "particles", c->n_particles, "1", NULL, 0);
    jval(&t, "steps", (double)c->steps, "1", NULL, 0);
    jval(&t, "wall_limiter_corrections", (double)c->n_limited, "1",
         "fluid particles put back on a wall face they had passed (particle-steps)", 0);
    jval(&t, "particles_left_domain", (double)c->n_excluded, "1",
         "fluid particles that left the domain box and were taken out of the run", 0);
    jval(&t, "end_time", c->t_end, "s", "planned", 0);
    jval(&t, "time_reached", c->t_reached, "s", NULL, 0);
    jval(&t, "runtime", c->runtime_s, "s", "wall clock", 0);
    jval(&t, "particle_steps_per_second",
         c->runtime_s > 0 ? (double)c->n_particles * (double)c->steps / c->runtime_s : NAN, "1/s",
         NULL, res->conv[i].n_levels == 0);
    if (res->conv[i].n_levels) json_convergence(&t, &res->conv[i]);
    wl_text_put(&t, "    }%s\n", i + 1 < res->n_cases ? "," : "");
  }
  wl_text_put(&t, "  }");
  if (res->n_cases == 2) {
    const struct wl_case_loads *a = &res->cases[0].loads, *b = &res->cases[1].loads;
    int f = a->force_peak.value >= b->force_peak.value ? 0 : 1;
    int im = a->impulse_total >= b->impulse_total ? 0 : 1;
    int ip = a->impulse_peak >= b->impulse_peak ? 0 : 1;
    int ipos = a->impulse_positive >= b->impulse_positive ? 0 : 1;
    wl_text_put(&t, ",\n  \"comparison\": {\n    \"larger_peak_force\": ");
    jstr(&t, res->cases[f].name);
    wl_text_put(&t, ",\n    \"peak_force_ratio\": ");
    jnum(&t, res->cases[f].loads.force_peak.value / res->cases[1 - f].loads.force_peak.value);
    wl_text_put(&t, ",\n    \"larger_impulse\": ");
    jstr(&t, res->cases[im].name);
    wl_text_put(&t, ",\n    \"impulse_ratio\": ");
    jnum(&t, res->cases[im].loads.impulse_total / res->cases[1 - im].loads.impulse_total);
    wl_text_put(&t, ",\n    \"larger_impulse_positive_phase\": ");
    jstr(&t, res->cases[ip].name);
    wl_text_put(&t, ",\n    \"impulse_positive_phase_ratio\": ");
    jnum(&t, res->cases[ip].loads.impulse_peak / res->cases[1 - ip].loads.impulse_peak);
    wl_text_put(&t, ",\n    \"larger_impulse_positive\": ");
    jstr(&t, res->cases[ipos].name);
    wl_text_put(&t, ",\n    \"impulse_positive_ratio\": ");
    jnum(&t, res->cases[ipos].loads.impulse_positive / res->cases[1 - ipos].loads.impulse_positive);
    wl_text_put(&t, "\n  }");
  }
  (void)plan;
  wl_text_put(&t, "\n}\n");
  if (t.failed) {
    free(t.s);
    return wl_error_set(err, WL_ENOMEM, "summary.json: no memory");
  }
  char path[600];
  snprintf(path, sizeof path, "%s/summary.json", res->out_dir);
  enum wl_status st = wl_store_write_text_batch(path, t.s, t.len, batch, err);
  free(t.s);
  return st;
}

static enum wl_status write_csv(const struct wl_assess_result *res, const struct wl_case_result *c,
                                struct wl_store_batch *b, struct wl_error *err) {
  const struct wl_record *r = &c->rec;
  const struct wl_case_loads *l = &c->loads;
  struct wl_text t = {0};
  wl_text_put(&t, "time_s,force_N_per_m,force_filtered_N_per_m,force_boundary_N_per_m,impulse_Ns_per_m,"
          "moment_Nm_per_m,moment_filtered_Nm_per_m\n");
  for (size_t k = 0; k < r->n; k++)
    wl_text_put(&t, "%.6f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", r->t[k], r->force[k], l->force_filtered[k],
        r->force_bound[k], l->impulse[k], r->moment[k], l->moment_filtered[k]);
  char path[700];
  snprintf(path, sizeof path, "%s/%s_wall.csv", res->out_dir, c->name);
  enum wl_status st =
      t.failed ? wl_error_set(err, WL_ENOMEM, "%s: no memory", path)
               : wl_store_write_text_batch(path, t.s, t.len, b, err);
  t.len = 0;
  if (!st) {
    wl_text_put(&t, "time_s");
    for (int g = 0; g < r->n_gauges; g++) wl_text_put(&t, ",eta_%s_m", c->flume.gauge_name[g]);
    wl_text_put(&t, "\n");
    for (size_t k = 0; k < r->n; k++) {
      wl_text_put(&t, "%.6f", r->t[k]);
      for (int g = 0; g < r->n_gauges; g++) wl_text_put(&t, ",%.6g", r->eta[k * (size_t)r->n_gauges + (size_t)g]);
      wl_text_put(&t, "\n");
    }
    snprintf(path, sizeof path, "%s/%s_gauges.csv", res->out_dir, c->name);
    st = t.failed ? wl_error_set(err, WL_ENOMEM, "%s: no memory", path)
                  : wl_store_write_text_batch(path, t.s, t.len, b, err);
  }
  free(t.s);
  return st;
}

static enum wl_status write_case_h5(struct wl_store *h5, const struct wl_case_result *c,
                                    struct wl_error *err) {
  const struct wl_record *r = &c->rec;
  const struct wl_case_loads *l = &c->loads;
  const struct wl_flume *f = &c->flume;
  char g[64], p[160];
  snprintf(g, sizeof g, "cases/%s", c->name);
  enum wl_status st = WL_OK;
#define VEC(name, data, unit, desc)                                                           \
  if (!st) {                                                                                  \
    snprintf(p, sizeof p, "%s/%s", g, name);                                                  \
    st = wl_store_write_vector(h5, p, data, r->n, unit, desc, err);                           \
  }
  VEC("time", r->t, "s", "output times");
  VEC("wall/force", r->force, "N/m", "force per metre from the pressure probes (raw)");
  VEC("wall/force_filtered", l->force_filtered, "N/m", "low-pass filtered force (see cutoff)");
  VEC("wall/force_boundary", r->force_bound, "N/m",
      "force per metre summed on the wall's boundary particles (raw)");
  VEC("wall/force_boundary_filtered", l->force_bound_filtered, "N/m", "low-pass filtered");
  VEC("wall/impulse", l->impulse, "N s/m", "integral of (probe force - static force) dt");
  VEC("wall/impulse_boundary", l->impulse_bound, "N s/m",
      "integral of (boundary force - static force) dt");
  VEC("wall/moment", r->moment, "N m/m", "overturning moment about the toe (raw)");
  VEC("wall/moment_boundary", r->moment_bound, "N m/m",
      "moment about the toe of the boundary-particle force (raw)");
  VEC("wall/moment_filtered", l->moment_filtered, "N m/m", "low-pass filtered");
  VEC("energy/kinetic", r->kinetic, "J/m", "fluid kinetic energy");
  VEC("energy/potential", r->potential, "J/m", "fluid potential energy above the floor");
  VEC("momentum/x", r->momentum, "N s/m",
      "fluid horizontal momentum; its change is the impulse given to all boundaries");
#undef VEC
  if (!st) {
    snprintf(p, sizeof p, "%s/wall/pressure", g);
    st = wl_store_write_matrix(h5, p, r->pressure, r->n, (size_t)r->n_probes, "Pa",
                               "probe pressure, time x probe", err);
  }
  if (!st) {
    snprintf(p, sizeof p, "%s/wall/probe_z", g);
    st = wl_store_write_vector(h5, p, f->probe_z, (size_t)f->n_probes, "m",
                               "probe heights above the flume floor", err);
  }
  double *col = malloc((r->n ? r->n : 1) * sizeof *col);
  if (!col) return wl_error_set(err, WL_ENOMEM, "results: no memory");
  for (int gi = 0; !st && gi < r->n_gauges; gi++) {
    for (size_t k = 0; k < r->n; k++) col[k] = r->eta[k * (size_t)r->n_gauges + (size_t)gi];
    snprintf(p, sizeof p, "%s/gauges/%s/eta", g, f->gauge_name[gi]);
    st = wl_store_write_vector(h5, p, col, r->n, "m", "free-surface elevation above still water",
                               err);
    if (!st) {
      snprintf(p, sizeof p, "%s/gauges/%s", g, f->gauge_name[gi]);
      st = wl_store_attr_double(h5, p, "x", f->gauge_x[gi], "m", err);
    }
  }
  free(col);
  struct {
    const char *name;
    double v;
    const char *unit;
  } attrs[] = {
      {"dp", c->dp, "m"},
      {"smoothing_length", c->h, "m"},
      {"c0", c->c0, "m/s"},
      {"particles", c->n_particles, "1"},
      {"fluid_particles", c->n_fluid, "1"},
      {"steps", (double)c->steps, "1"},
      {"runtime", c->runtime_s, "s"},
      {"end_time", c->t_end, "s"},
      {"time_reached", c->t_reached, "s"},
      {"filter_cutoff", l->cutoff, "Hz"},
      {"peaks_from", c->peak_from, "s"},
      {"static_force", c->static_force, "N/m"},
      {"static_moment", c->static_moment, "N m/m"},
      {"rest_force", l->rest_force, "N/m"},
      {"rest_force_boundary", l->rest_force_bound, "N/m"},
      {"rest_moment", l->rest_moment, "N m/m"},
      {"rest_from", l->rest_from, "s"},
      {"rest_to", l->rest_to, "s"},
      {"wall_x", f->x_wall, "m"},
      {"wall_toe_z", f->z_toe, "m"},
      {"wall_crest_z", f->z_crest, "m"},
      {"still_water_z", f->depth, "m"},
  };
  for (size_t i = 0; !st && i < sizeof attrs / sizeof attrs[0]; i++)
    st = wl_store_attr_double(h5, g, attrs[i].name, attrs[i].v, attrs[i].unit, err);
  /* 3D: the flume width (twice the modelled half with a symmetry plane);
   * the series stay per metre, per wall = per metre x width */
  if (!st && f->dims == 3)
    st = wl_store_attr_double(h5, g, "width", (f->symmetry ? 2 : 1) * f->width, "m", err);
  if (!st && f->dims == 3)
    st = wl_store_attr_text(h5, g, "symmetry", f->symmetry ? "centreline" : "none", err);
  if (!st && f->dims == 3)
    st = wl_store_attr_text(h5, g, "side_walls", f->slip_walls ? "free-slip" : "particles", err);
  if (!st) st = wl_store_attr_text(h5, g, "status", status_word(c->status), err);
  if (!st && c->status != WL_OK) st = wl_store_attr_text(h5, g, "stopped", c->message, err);
  if (!st && c->caution[0]) st = wl_store_attr_text(h5, g, "caution", c->caution, err);
  return st;
}

/* After new results moved into place: remove the result files of the
 * directory that they do not include (a previous run's), so that no file
 * describes another run: report.pdf (rendered again next), the CSV and
 * snapshot files of a case not in res, the snapshot files of a case whose
 * snapshots this run did not write, convergence.csv without a ladder. */
static void remove_stale(const struct wl_assess_result *res, int ladder) {
  char path[700];
  snprintf(path, sizeof path, "%s/report.pdf", res->out_dir);
  remove(path);
  if (!ladder) {
    snprintf(path, sizeof path, "%s/convergence.csv", res->out_dir);
    remove(path);
  }
  static const enum wl_load_case loads[] = {WL_CASE_SOLITARY, WL_CASE_EXPLOSION, WL_CASE_STILL};
  for (size_t l = 0; l < sizeof loads / sizeof loads[0]; l++) {
    const char *name = wl_flume_case_name(loads[l]);
    const struct wl_case_result *c = NULL;
    for (int i = 0; i < res->n_cases; i++)
      if (res->cases[i].load == loads[l]) c = &res->cases[i];
    /* this run's snapshot files: waiting (moved just now) or moved before */
    const int mine = c ? (c->snapshot_files | c->snapshot_files >> 2) & 3 : 0;
    if (!c) {
      snprintf(path, sizeof path, "%s/%s_wall.csv", res->out_dir, name);
      remove(path);
      snprintf(path, sizeof path, "%s/%s_gauges.csv", res->out_dir, name);
      remove(path);
    }
    if (!(mine & 1)) {
      snprintf(path, sizeof path, "%s/particles_%s.h5", res->out_dir, name);
      remove(path);
    }
    if (!(mine & 2)) {
      snprintf(path, sizeof path, "%s/particles_%s.xmf", res->out_dir, name);
      remove(path);
    }
  }
}

enum wl_status write_results(const struct wl_scenario *s, const struct wl_plan *plan,
                             const struct wl_assess_result *res, struct wl_error *err) {
  char path[600];
  snprintf(path, sizeof path, "%s/results.h5", res->out_dir);
  struct wl_store *h5;
  enum wl_status st = wl_store_open(path, &h5, err);
  if (st) return st;
  char when[64];
  time_t now = time(NULL);
  strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
  if (!st) st = wl_store_attr_text(h5, "/", "scenario_name", s->name.text, err);
  if (!st) st = wl_store_attr_text(h5, "/", "scenario_file", s->path, err);
  if (!st) st = wl_store_attr_text(h5, "/", "scenario_text", s->text ? s->text : "", err);
  if (!st) st = wl_store_attr_text(h5, "/", "wallload_version", WL_VERSION, err);
  if (!st) st = wl_store_attr_text(h5, "/", "created", when, err);
  if (!st) st = wl_store_attr_text(h5, "/", "backend", res->backend, err);
  if (!st) st = wl_store_attr_double(h5, "/", "threads", res->threads, "1", err);
  if (!st) st = wl_store_attr_double(h5, "/", "dp", plan->dp, "m", err);
  for (int i = 0; !st && i < res->n_cases; i++) st = write_case_h5(h5, &res->cases[i], err);
  for (int i = 0; !st && i < res->n_cases; i++)
    if (res->conv[i].n_levels) st = write_convergence_h5(h5, &res->cases[i], &res->conv[i], err);
  /* Every file is written to its temporary name first; they move into
   * place together once all are complete (the cases' waiting snapshot
   * files first, summary.json last), so a failure on any of them (a full
   * disk) leaves the previous files as they were. */
  struct wl_store_batch batch;
  wl_store_batch_init(&batch);
  for (int i = 0; i < res->n_cases; i++) {
    static const char *const ext[2] = {"h5", "xmf"};
    for (int k = 0; k < 2; k++) {
      if (!(res->cases[i].snapshot_files & (1 << k))) continue;
      snprintf(path, sizeof path, "%s/particles_%s.%s", res->out_dir, res->cases[i].name, ext[k]);
      enum wl_status sa = wl_store_batch_add(&batch, path, err);
      if (!st) st = sa;
    }
  }
  if (st) {
    wl_store_close(h5, 0, NULL);
  } else {
    st = wl_store_close_batch(h5, &batch, err);
  }
  for (int i = 0; !st && i < res->n_cases; i++) st = write_csv(res, &res->cases[i], &batch, err);
  int ladder = 0;
  for (int i = 0; i < res->n_cases; i++) ladder |= res->conv[i].n_levels > 0;
  if (!st && ladder) st = write_convergence_csv(res, &batch, err);
  if (!st) st = write_summary(s, plan, res, &batch, err);
  if (st) {
    wl_store_batch_abort(&batch);
    return st;
  }
  if ((st = wl_store_batch_commit(&batch, err))) return st;
  remove_stale(res, ladder);
  return WL_OK;
}
