/* output.c: results.h5 (through the store module's schema: the cases, their
 * ladders, and what the plan derived for the report), summary.json and CSV
 * files of an assessment, each written atomically. Layout in
 * docs/outputs.md. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "assess_private.h"
#include "wallload/config.h"
#include "wallload/explosion.h"
#include "wallload/store.h"
#include "wallload/units.h"
#include "wallload/waves.h"


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

/* The ladder as results.h5 holds it (the level columns of store.h, which
 * summary.json and convergence.csv follow). */
static void ladder_columns(const struct wl_assess_convergence *cv,
                           struct wl_results_convergence *out) {
  wl_store_results_convergence_init(out);
  out->present = 1;
  out->n_levels = cv->n_levels;
  for (int l = 0; l < cv->n_levels; l++) {
    const struct wl_assess_level *lv = &cv->lv[l];
    out->factor[l] = lv->factor, out->dp[l] = lv->dp;
    out->particles[l] = (double)lv->n_particles, out->steps[l] = (double)lv->steps;
    out->runtime[l] = lv->runtime_s, out->rate[l] = lv->rate;
    out->time_reached[l] = lv->t_reached;
    out->peak_force[l] = lv->peak_force, out->peak_force_b[l] = lv->peak_force_bound;
    out->rest_force[l] = lv->rest_force;
    out->impulse[l] = lv->impulse, out->impulse_phase[l] = lv->impulse_phase;
    out->impulse_pos[l] = lv->impulse_positive, out->peak_moment[l] = lv->peak_moment;
    out->runup[l] = lv->runup, out->error[l] = lv->error;
    out->realisations[l] = lv->realisations > 0 ? lv->realisations : 1;
    out->peak_force_sd[l] = lv->peak_force_sd, out->impulse_pos_sd[l] = lv->impulse_positive_sd;
    out->peak_force_min[l] = lv->peak_force_min, out->peak_force_max[l] = lv->peak_force_max;
    out->status[l] = (int)lv->status;
  }
  out->levels_planned = cv->n_planned, out->levels_run = cv->n_levels;
  out->ratio = cv->force.r32;
  out->force_order = cv->force.order, out->force_order_ok = cv->force.order_ok;
  out->force_extrapolated = cv->force.extrapolated, out->force_error = cv->force.error;
  out->dyn_order = cv->force_dynamic.order, out->dyn_order_ok = cv->force_dynamic.order_ok;
  out->dyn_extrapolated = cv->force_dynamic.extrapolated, out->dyn_error = cv->force_dynamic.error;
  snprintf(out->dyn_basis, sizeof out->dyn_basis, "%s",
           wl_loads_estimate_name(cv->force_dynamic.basis));
  out->pos_order = cv->impulse_pos.order, out->pos_order_ok = cv->impulse_pos.order_ok;
  out->pos_extrapolated = cv->impulse_pos.extrapolated, out->pos_error = cv->impulse_pos.error;
  out->error_estimate = cv->error_estimate, out->target = cv->target;
  out->force_sampling = cv->force_sampling, out->dyn_sampling = cv->dynamic_sampling;
  out->pos_sampling = cv->impulse_sampling;
  out->target_given = cv->target_given, out->target_met = cv->target_met;
  out->stopped_early = cv->stopped_early;
  snprintf(out->force_basis, sizeof out->force_basis, "%s", wl_loads_estimate_name(cv->force.basis));
  snprintf(out->pos_basis, sizeof out->pos_basis, "%s",
           wl_loads_estimate_name(cv->impulse_pos.basis));
  snprintf(out->note, sizeof out->note, "%s", cv->note);
}

static int is_status_column(int k) { return !wl_store_results_levels[k].unit[0]; }

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
  struct wl_results_convergence col;
  ladder_columns(cv, &col);
  wl_text_put(t, "      \"convergence\": {\n        \"units\": {");
  for (int k = 0; k < wl_store_results_n_levels; k++) {
    if (is_status_column(k)) continue;
    wl_text_put(t, "%s", k ? ", " : " ");
    jstr(t, wl_store_results_levels[k].name);
    wl_text_put(t, ": ");
    jstr(t, wl_store_results_levels[k].unit);
  }
  wl_text_put(t, " },\n        \"levels\": [\n");
  for (int l = 0; l < cv->n_levels; l++) {
    wl_text_put(t, "          {");
    for (int k = 0; k < wl_store_results_n_levels; k++) {
      wl_text_put(t, "%s", k ? ", " : " ");
      jstr(t, wl_store_results_levels[k].name);
      wl_text_put(t, ": ");
      if (is_status_column(k))
        jstr(t, status_word((enum wl_status)col.status[l]));
      else
        jnum(t, wl_store_results_level_value(&col, k, l));
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
  json_estimate(t, "peak_force_dynamic", &cv->force_dynamic, 0);
  json_estimate(t, "impulse_positive", &cv->impulse_pos, 0);
  /* realisations: the finest mean's sampling uncertainty, already in the
   * error estimates above (null with one run a level) */
  wl_text_put(t, "        \"sampling_uncertainty\": { \"peak_force\": ");
  jnum(t, cv->force_sampling);
  wl_text_put(t, ", \"peak_force_dynamic\": ");
  jnum(t, cv->dynamic_sampling);
  wl_text_put(t, ", \"impulse_positive\": ");
  jnum(t, cv->impulse_sampling);
  wl_text_put(t, " },\n");
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

/* convergence.csv: one row per case and level. */
static enum wl_status write_convergence_csv(const struct wl_assess_result *res,
                                            struct wl_store_batch *b, struct wl_error *err) {
  struct wl_text t = {0};
  wl_text_put(&t, "case,level");
  for (int k = 0; k < wl_store_results_n_levels; k++) {
    const struct wl_results_column *f = &wl_store_results_levels[k];
    if (is_status_column(k) || !strcmp(f->unit, "1")) {
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
    struct wl_results_convergence col;
    ladder_columns(&res->conv[i], &col);
    for (int l = 0; l < col.n_levels; l++) {
      wl_text_put(&t, "%s,%d", res->cases[i].name, l + 1);
      for (int k = 0; k < wl_store_results_n_levels; k++) {
        if (is_status_column(k))
          wl_text_put(&t, ",%s", status_word((enum wl_status)col.status[l]));
        else
          wl_text_put(&t, ",%.10g", wl_store_results_level_value(&col, k, l));
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
    /* with a still-water reference the filtered series the peaks come
     * from are the case's less the reference's drift (record.c) */
    const char *less = l->drift ? ", less the still water's drift (still_drift)" : "";
    char filt[160];
    snprintf(filt, sizeof filt, "pressure probes, low-pass %.4g Hz%s", l->cutoff, less);
    char filt_b[160];
    snprintf(filt_b, sizeof filt_b, "boundary particles, low-pass %.4g Hz%s", l->cutoff, less);
    jval(&t, "realisations", l->realisations > 1 ? l->realisations : 1, "1",
         l->realisations > 1 ? "runs of the finest level whose mean every scalar load here is "
                               "(resolution.realisations); the series, the peaks' times and the "
                               "force at rest are the first run's"
                             : "one run", 0);
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
    /* the base every impulse subtracts: the force at rest, and the
     * still-water reference's drift where the case has one (plan.h) */
    const char *base = l->drift ? "(rest_force + still_drift)" : "rest_force";
    char d1[200], d2[200];
    snprintf(d1, sizeof d1, "integral of (force - %s), raw pressure-probe force", base);
    snprintf(d2, sizeof d2, "integral of (force - %s), boundary particles",
             l->drift ? "(rest_force_boundary + its still_drift)" : "rest_force_boundary");
    jval(&t, "impulse", l->impulse_total, "N s/m", d1, 0);
    jval(&t, "impulse_boundary", c->rec.n ? l->impulse_bound[c->rec.n - 1] : NAN, "N s/m", d2, 0);
    {
      char ph[200];
      snprintf(ph, sizeof ph,
               "integral of (force - %s) over the peak's positive phase, %.4g to %.4g s, "
               "raw pressure-probe force",
               base, l->impulse_peak_from, l->impulse_peak_to);
      jval(&t, "impulse_positive_phase", l->impulse_peak, "N s/m", ph, 0);
    }
    snprintf(d1, sizeof d1,
             "integral of max(0, filtered force - %s) from peaks_from on: the push of every "
             "wave, pressure probes",
             base);
    jval(&t, "impulse_positive", l->impulse_positive, "N s/m", d1, 0);
    jval(&t, "impulse_positive_boundary", l->impulse_positive_bound, "N s/m",
         "the same from the boundary particles", 0);
    jval(&t, "still_reference", l->drift ? 1 : 0, "1",
         l->drift ? "1: a still-water run of this flume gave the wall force's own drift "
                    "(still_drift in the wall CSV), which the impulses subtract "
                    "(run.still_reference)"
                  : "0: no still-water reference run; the impulses subtract the force at rest "
                    "alone",
         0);
    jval(&t, "still_drift_max", l->drift_max, "N/m",
         "largest magnitude of that drift from peaks_from on (null: none)", 0);
    jval(&t, "impulse_positive_uncorrected", l->impulse_positive_uncorrected, "N s/m",
         "impulse_positive without the drift taken out (null: no reference run)", 0);
    jval(&t, "rest_force_spread", l->rest_force_spread, "N/m",
         "half the difference of the raw force's means over the rest window's two halves: how "
         "well the window fixes the force at rest (null: no rest window)", 0);
    jval(&t, "impulse_positive_rest_uncertainty", l->impulse_positive_rest_error, "N s/m",
         "rest_force_spread times the time the filtered force spends above rest_force: what "
         "that uncertainty does to impulse_positive", 0);
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
      jval(&t, "residual_viscosity", prm->residual_alpha, "1",
           "residual viscosity alpha_r (0: off; sph/vgrad.h)", 0);
      jval(&t, "smagorinsky", prm->smagorinsky, "1",
           "Smagorinsky constant of the eddy viscosity (0: off; sph/vgrad.h)", 0);
      jval(&t, "shifting", prm->shift_coef, "1", "particle shifting coefficient A (0: off)", 0);
      jval(&t, "wall_condition", prm->boundary, "1",
           prm->boundary == WL_SPH_BOUND_DBC ? "0: dynamic boundary particles (DBC)"
                                             : "1: pressure from the fluid (Adami et al. 2012)",
           0);
      jval(&t, "force_evaluations_per_step", prm->integrator == WL_SPH_VERLET ? 1 : 2, "1",
           prm->integrator == WL_SPH_VERLET ? "Verlet integrator" : "symplectic integrator", 0);
    }
    if (c->dp_coarse > 0) {
      jval(&t, "dp_coarse", c->dp_coarse, "m",
           "resolution.refine: the coarse level's spacing, seaward of x_interface", 0);
      jval(&t, "x_interface", c->x_interface, "m", "resolution.refine: the levels' interface", 0);
      jval(&t, "water_change", c->water_change, "1",
           "relative change of the water the two levels own, start to end", 0);
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
  /* still_drift: the still-water reference run's drift (plan.h) that the
   * impulse subtracts with the force at rest; 0 without a reference */
  wl_text_put(&t, "time_s,force_N_per_m,force_filtered_N_per_m,force_boundary_N_per_m,impulse_Ns_per_m,"
          "moment_Nm_per_m,moment_filtered_Nm_per_m,still_drift_N_per_m\n");
  for (size_t k = 0; k < r->n; k++)
    wl_text_put(&t, "%.6f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", r->t[k], r->force[k],
                l->force_filtered[k], r->force_bound[k], l->impulse[k], r->moment[k],
                l->moment_filtered[k], l->drift ? l->drift[k] : 0.0);
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

/* Case c as results.h5 holds it (store.h); the series stay c's, the
 * gauges' columns are copied into eta (n x n_gauges, freed by the caller). */
static enum wl_status case_columns(const struct wl_case_result *c, struct wl_results_case *out,
                                   double **eta, struct wl_error *err) {
  const struct wl_record *r = &c->rec;
  const struct wl_case_loads *l = &c->loads;
  const struct wl_flume *f = &c->flume;
  wl_store_results_case_init(out);
  out->present = 1;
  snprintf(out->name, sizeof out->name, "%s", c->name);
  snprintf(out->status, sizeof out->status, "%s", status_word(c->status));
  if (c->status != WL_OK) snprintf(out->stopped, sizeof out->stopped, "%s", c->message);
  snprintf(out->caution, sizeof out->caution, "%s", c->caution);
  out->dp = c->dp, out->h = c->h, out->c0 = c->c0;
  out->particles = c->n_particles, out->fluid_particles = c->n_fluid;
  out->steps = (double)c->steps, out->runtime = c->runtime_s;
  out->end_time = c->t_end, out->time_reached = c->t_reached;
  out->cutoff = l->cutoff, out->peaks_from = c->peak_from;
  out->static_force = c->static_force, out->static_moment = c->static_moment;
  out->rest_force = l->rest_force, out->rest_force_b = l->rest_force_bound;
  out->rest_moment = l->rest_moment, out->rest_from = l->rest_from, out->rest_to = l->rest_to;
  out->wall_x = f->x_wall, out->wall_toe_z = f->z_toe, out->wall_crest_z = f->z_crest;
  out->still_water_z = f->depth;
  if (r->n) { /* the loads as computed (record.c); absent (NAN) for an empty record */
    out->force_peak = l->force_peak, out->force_b_peak = l->force_bound_peak;
    out->moment_peak = l->moment_peak;
    out->impulse_total = l->impulse_total, out->impulse_b_total = l->impulse_bound[r->n - 1];
    out->impulse_peak = l->impulse_peak;
    out->impulse_peak_from = l->impulse_peak_from, out->impulse_peak_to = l->impulse_peak_to;
    out->impulse_positive = l->impulse_positive;
    out->impulse_positive_b = l->impulse_positive_bound;
    out->still_drift_max = l->drift_max;
    out->impulse_positive_uncorrected = l->impulse_positive_uncorrected;
    if (isfinite(l->runup)) /* a wall gauge that never read water: no run-up */
      out->runup = l->runup, out->runup_time = l->runup_time;
  }
  if (f->dims == 3) {
    out->width = (f->symmetry ? 2 : 1) * f->width;
    snprintf(out->symmetry, sizeof out->symmetry, "%s", f->symmetry ? "centreline" : "none");
    snprintf(out->side_walls, sizeof out->side_walls, "%s",
             f->slip_walls ? "free-slip" : "particles");
  }
  out->n = r->n;
  out->t = r->t;
  out->force = r->force, out->force_f = l->force_filtered;
  out->force_b = r->force_bound, out->force_bf = l->force_bound_filtered;
  out->impulse = l->impulse, out->impulse_b = l->impulse_bound;
  out->still_drift = l->drift;
  out->moment = r->moment, out->moment_f = l->moment_filtered, out->moment_b = r->moment_bound;
  out->kinetic = r->kinetic, out->potential = r->potential, out->momentum = r->momentum;
  out->n_probes = (size_t)r->n_probes;
  out->probe_z = (double *)f->probe_z;
  out->pressure = r->pressure;
  out->n_gauges = r->n_gauges;
  *eta = malloc((r->n ? r->n : 1) * (size_t)(r->n_gauges ? r->n_gauges : 1) * sizeof **eta);
  if (!*eta) return wl_error_set(err, WL_ENOMEM, "results: no memory");
  for (int gi = 0; gi < r->n_gauges; gi++) {
    struct wl_results_gauge *g = &out->gauges[gi];
    snprintf(g->name, sizeof g->name, "%s", f->gauge_name[gi]);
    g->x = f->gauge_x[gi];
    g->eta = *eta + (size_t)gi * r->n;
    for (size_t k = 0; k < r->n; k++) g->eta[k] = r->eta[k * (size_t)r->n_gauges + (size_t)gi];
  }
  return WL_OK;
}

static enum wl_status write_case_h5(struct wl_store *h5, const struct wl_case_result *c,
                                    struct wl_error *err) {
  struct wl_results_case *out = malloc(sizeof *out);
  if (!out) return wl_error_set(err, WL_ENOMEM, "results: no memory");
  double *eta = NULL;
  enum wl_status st = case_columns(c, out, &eta, err);
  if (!st) st = wl_store_results_write_case(h5, out, err);
  free(eta);
  free(out);
  return st;
}

static enum wl_status write_convergence_h5(struct wl_store *h5, const struct wl_case_result *c,
                                           const struct wl_assess_convergence *cv,
                                           struct wl_error *err) {
  struct wl_results_convergence col;
  ladder_columns(cv, &col);
  return wl_store_results_write_convergence(h5, c->name, &col, err);
}

/* ---- what assess planned, for results.h5's /plan and /settings --------------------- */

/* The initial free surface of a case between x0 and x1 [m], as the
 * report draws it: z above the floor, NAN where the bed is above it. */
struct surface_source {
  const struct wl_plan *plan;
  const struct wl_scenario *s;
  double xc; /* the crest or the crater's centre [m] */
};

static double surface_eta(const struct surface_source *src, int explosion, double x) {
  if (!explosion) return wl_waves_solitary_eta(&src->plan->solitary.wave, x - src->xc);
  const struct wl_plan_explosion *px = &src->plan->explosion;
  double eta = 0.0;
  struct wl_error e;
  wl_error_clear(&e);
  if (wl_explosion_eta(px->shape, px->eta0, px->r0, fabs(x - src->xc), &eta, &e)) eta = NAN;
  return eta;
}

static size_t sample_surface(const struct surface_source *src, int explosion, double a, double b,
                             double *x, double *z) {
  if (!(b > a)) return 0;
  const int n = WL_RESULTS_SURFACE_POINTS;
  for (int i = 0; i < n; i++) {
    x[i] = a + (b - a) * i / (n - 1);
    z[i] = src->plan->h + surface_eta(src, explosion, x[i]);
    if (z[i] <= wl_scenario_bed_z(src->s, x[i])) z[i] = NAN;
  }
  return (size_t)n;
}

/* The crater's scenario source, in words. */
static const char *explosion_source_text(enum wl_explosion_source source) {
  static const char *const from[] = {"charge weight", "crater energy",
                                     "energy of the solitary wave", "crater size"};
  return (int)source >= 0 && source <= WL_SOURCE_CRATER ? from[source] : "?";
}

static void plan_solitary(const struct wl_scenario *s, const struct wl_plan *plan,
                          struct wl_results_solitary *out) {
  const struct wl_plan_solitary *ps = &plan->solitary;
  out->present = 1;
  snprintf(out->theory, sizeof out->theory, "%s", wl_waves_solitary_theory_text(ps->wave.theory, 0));
  out->H = ps->wave.H;
  out->K = ps->wave.K;
  out->celerity = wl_waves_solitary_celerity(&ps->wave);
  out->energy_integrated = ps->integrated.energy;
  out->energy_first_order = ps->first_order.energy;
  out->energy_seed001 = ps->energy_seed001;
  out->paddle = ps->paddle;
  if (ps->paddle)
    out->paddle_stroke = ps->goring.stroke, out->paddle_duration = ps->goring.duration;
  else
    out->crest_x0 = ps->crest_x0;
  out->arrival_time = ps->arrival_time;
  out->x_left = ps->x_left;
  if (!ps->paddle && ps->wave.K > 0) {
    /* the wave over +-WL_ASSESS_SOLITARY_HALF/K about its crest, in the flume */
    const struct surface_source src = {plan, s, ps->crest_x0};
    const double half = WL_ASSESS_SOLITARY_HALF / ps->wave.K;
    out->n_surface = sample_surface(&src, 0, fmax(0.0, ps->crest_x0 - half),
                                    fmin(s->wall.x.q.si, ps->crest_x0 + half), out->surface_x,
                                    out->surface_z);
  }
}

static void plan_explosion(const struct wl_scenario *s, const struct wl_plan *plan,
                           struct wl_results_explosion *out) {
  const struct wl_plan_explosion *px = &plan->explosion;
  const struct wl_explosion_chain *ch = &px->chain;
  out->present = 1;
  snprintf(out->source, sizeof out->source, "%s", explosion_source_text(px->source));
  out->sized_to_solitary = px->source == WL_SOURCE_SOLITARY;
  if (out->sized_to_solitary) {
    snprintf(out->basis, sizeof out->basis, "%s",
             px->basis == WL_BASIS_SEED001 ? "seed-001" : "per-width");
    out->matched_energy = px->matched_energy;
  }
  out->charge = ch->charge_kg;
  out->chain_r0 = ch->r0, out->chain_eta0 = ch->eta0, out->hr = ch->hr;
  out->whalin_coef = ch->whalin_coef;
  out->crater_energy = ch->crater_energy, out->chemical_energy = ch->chemical_energy;
  out->chain_wave_fraction = ch->wave_fraction, out->wave_fraction = px->wave_fraction;
  snprintf(out->shape, sizeof out->shape, "%s", wl_explosion_shape_name(px->shape));
  out->eta0 = px->eta0, out->r0 = px->r0, out->x_center = px->x_center, out->extent = px->extent;
  out->energy = px->energy, out->energy_quad = px->energy_quad;
  out->net_volume = px->net_volume;
  out->conserves_mass = px->conserves_mass;
  out->arrival_time = px->arrival_time;
  out->x_left = px->x_left;
  if (px->r0 > 0) {
    const struct surface_source src = {plan, s, px->x_center};
    out->n_surface = sample_surface(&src, 1, fmax(0.0, px->x_center - px->extent),
                                    fmin(s->wall.x.q.si, px->x_center + px->extent),
                                    out->surface_x, out->surface_z);
  }
}

void wl_assess_results_plan(const struct wl_scenario *s, const struct wl_plan *plan,
                            struct wl_results *r) {
  wl_store_results_init(r);
  snprintf(r->scenario_name, sizeof r->scenario_name, "%s", s->name.text);
  snprintf(r->scenario_file, sizeof r->scenario_file, "%s", s->path);
  r->scenario_text = s->text;
  r->dp = plan->dp;
  snprintf(r->report_template, sizeof r->report_template, "%s", s->report.template_name.text);
  snprintf(r->length_unit, sizeof r->length_unit, "%s", s->water.depth.q.unit);
  if (s->resolution.levels_given) {
    size_t used = (size_t)snprintf(r->convergence_asked, sizeof r->convergence_asked, "[");
    for (int i = 0; i < s->resolution.n_levels && used < sizeof r->convergence_asked; i++)
      used += (size_t)snprintf(r->convergence_asked + used, sizeof r->convergence_asked - used,
                               "%s%s", i ? ", " : "", s->resolution.levels[i].text);
    if (used < sizeof r->convergence_asked)
      snprintf(r->convergence_asked + used, sizeof r->convergence_asked - used, "]");
  }
  /* the settings store's table names (store.h), with the scenario's values */
  for (int i = 0; i < wl_store_results_n_settings; i++) {
    const char *key = wl_store_results_settings[i].key;
    const struct wl_scenario_value *v = wl_scenario_value_of(s, key);
    struct wl_results_setting *o = &r->settings[r->n_settings++];
    snprintf(o->key, sizeof o->key, "%s", key);
    snprintf(o->value, sizeof o->value, "%s", !v ? "?" : v->text[0] ? v->text : "none");
    if (v && v->is_auto && !strcmp(key, "resolution.refine.from")) { /* what the plan made of it */
      if (plan->refine)
        snprintf(o->value, sizeof o->value, "auto: %.4g m (the solitary case)", plan->refine_from);
      else
        snprintf(o->value, sizeof o->value, "auto: one resolution (check's notes say why)");
    }
    o->given = v && v->given;
  }

  struct wl_results_plan *pl = &r->plan;
  const double xw = s->wall.x.q.si;
  pl->present = 1;
  pl->dims = plan->dims;
  pl->depth = plan->h, pl->rho = plan->rho, pl->g = plan->g;
  pl->wall_x = xw;
  pl->wall_toe_z = wl_scenario_bed_z(s, xw);
  pl->wall_crest_z = pl->wall_toe_z + s->wall.height.q.si;
  pl->land_length = plan->land_length > 0 ? plan->land_length : s->domain.length.q.si - xw;
  /* the bed's corners: the flume's start, each segment's start before the
   * wall, the wall's toe */
  pl->bed_x[pl->n_bed] = 0.0, pl->bed_z[pl->n_bed++] = wl_scenario_bed_z(s, 0.0);
  for (int i = 0; i < s->n_bed && pl->n_bed + 1 < WL_RESULTS_MAX_BED; i++) {
    const double xb = s->bed[i].from.q.si;
    if (xb > 0.0 && xb < xw) pl->bed_x[pl->n_bed] = xb, pl->bed_z[pl->n_bed++] = wl_scenario_bed_z(s, xb);
  }
  pl->bed_x[pl->n_bed] = xw, pl->bed_z[pl->n_bed++] = pl->wall_toe_z;
  for (int i = 0; i < s->n_gauges && i < WL_RESULTS_MAX_GAUGES; i++) {
    snprintf(pl->gauge_name[i], sizeof pl->gauge_name[i], "%s", s->gauges[i].name.text);
    pl->gauge_x[pl->n_gauges++] = s->gauges[i].x.q.si;
  }
  size_t used = 0;
  for (int i = 0; i < plan->n_notes && used < sizeof pl->notes; i++)
    used += (size_t)snprintf(pl->notes + used, sizeof pl->notes - used, "%s%s", i ? "\n" : "",
                             plan->notes[i]);
  if (plan->solitary.present) plan_solitary(s, plan, &pl->solitary);
  if (plan->explosion.present) plan_explosion(s, plan, &pl->explosion);
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
  struct wl_results *run = malloc(sizeof *run);
  if (!run) st = wl_error_set(err, WL_ENOMEM, "results: no memory");
  if (!st) {
    wl_assess_results_plan(s, plan, run);
    time_t now = time(NULL);
    strftime(run->created, sizeof run->created, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
    snprintf(run->version, sizeof run->version, "%s", WL_VERSION);
    snprintf(run->backend, sizeof run->backend, "%s", res->backend);
    run->threads = res->threads;
    st = wl_store_results_write_run(h5, run, err);
  }
  free(run);
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
