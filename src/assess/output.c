/* output.c: results.h5, summary.json and CSV files of an assessment, each
 * written atomically (store module). Layout documented in README.md. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "assess_private.h"
#include "wallload/config.h"
#include "wallload/store.h"

/* A growing text buffer for JSON and CSV. */
struct text {
  char *s;
  size_t len, cap;
  int failed;
};

static void put(struct text *t, const char *fmt, ...) {
  if (t->failed) return;
  for (;;) {
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(t->s ? t->s + t->len : NULL, t->s ? t->cap - t->len : 0, fmt, ap);
    va_end(ap);
    if (n < 0) {
      t->failed = 1;
      return;
    }
    if (t->s && t->len + (size_t)n < t->cap) {
      t->len += (size_t)n;
      return;
    }
    size_t cap = t->cap ? t->cap : 4096;
    while (cap <= t->len + (size_t)n) cap *= 2;
    char *b = realloc(t->s, cap);
    if (!b) {
      t->failed = 1;
      return;
    }
    t->s = b;
    t->cap = cap;
  }
}

/* A JSON number: non-finite values are written as null. */
static void jnum(struct text *t, double v) {
  if (isfinite(v))
    put(t, "%.10g", v);
  else
    put(t, "null");
}

static void jstr(struct text *t, const char *s) {
  put(t, "\"");
  for (; *s; s++) {
    unsigned char ch = (unsigned char)*s;
    if (ch == '"' || ch == '\\')
      put(t, "\\%c", ch);
    else if (ch < 0x20)
      put(t, "\\u%04x", ch);
    else
      put(t, "%c", ch);
  }
  put(t, "\"");
}

static void jval(struct text *t, const char *key, double v, const char *unit, const char *what,
                 int last) {
  put(t, "      ");
  jstr(t, key);
  put(t, ": { \"value\": ");
  jnum(t, v);
  put(t, ", \"unit\": ");
  jstr(t, unit);
  if (what) {
    put(t, ", \"from\": ");
    jstr(t, what);
  }
  put(t, " }%s\n", last ? "" : ",");
}

static const char *status_word(enum wl_status st) {
  switch (st) {
  case WL_OK: return "complete";
  case WL_EUNSTABLE: return "unstable";
  case WL_EINTERRUPTED: return "interrupted";
  default: return "failed";
  }
}

static enum wl_status write_summary(const struct wl_scenario *s, const struct wl_plan *plan,
                                    const struct wl_assess_result *res, struct wl_error *err) {
  struct text t = {0};
  put(&t, "{\n  \"scenario\": ");
  jstr(&t, s->name.text);
  put(&t, ",\n  \"file\": ");
  jstr(&t, s->path);
  put(&t, ",\n  \"wallload_version\": ");
  jstr(&t, WL_VERSION);
  put(&t, ",\n  \"backend\": ");
  jstr(&t, res->backend);
  put(&t, ",\n  \"threads\": %d,\n  \"cases\": {\n", res->threads);
  for (int i = 0; i < res->n_cases; i++) {
    const struct wl_case_result *c = &res->cases[i];
    const struct wl_case_loads *l = &c->loads;
    put(&t, "    ");
    jstr(&t, c->name);
    put(&t, ": {\n      \"status\": ");
    jstr(&t, status_word(c->status));
    if (c->status != WL_OK) {
      put(&t, ",\n      \"stopped\": ");
      jstr(&t, c->message);
    }
    put(&t, ",\n");
    char filt[96];
    snprintf(filt, sizeof filt, "pressure probes, low-pass %.4g Hz", l->cutoff);
    char filt_b[96];
    snprintf(filt_b, sizeof filt_b, "boundary particles, low-pass %.4g Hz", l->cutoff);
    jval(&t, "peak_force", l->force_peak.value, "N/m", filt, 0);
    jval(&t, "peak_force_time", l->force_peak.time, "s", filt, 0);
    jval(&t, "peak_force_dynamic", l->force_peak.value - c->static_force, "N/m",
         "peak_force minus the hydrostatic force at rest", 0);
    jval(&t, "peak_force_boundary", l->force_bound_peak.value, "N/m", filt_b, 0);
    jval(&t, "static_force", c->static_force, "N/m", "rho g d^2/2 at the wall at rest", 0);
    jval(&t, "impulse", l->impulse_total, "N s/m",
         "integral of (force - static force), raw pressure-probe force", 0);
    jval(&t, "impulse_boundary", c->rec.n ? l->impulse_bound[c->rec.n - 1] : NAN, "N s/m",
         "integral of (force - static force), boundary particles", 0);
    jval(&t, "peak_moment", l->moment_peak.value, "N m/m", filt, 0);
    jval(&t, "max_runup", l->runup, "m", "water level at the wall face above still water", 0);
    jval(&t, "rise_time", l->force_peak.rise_time, "s", "10 % of the dynamic peak to the peak", 0);
    jval(&t, "duration", l->force_peak.duration, "s", "dynamic force above 10 % of its peak", 0);
    jval(&t, "filter_cutoff", l->cutoff, "Hz", "c0/(8 d)", 0);
    jval(&t, "dp", c->dp, "m", NULL, 0);
    jval(&t, "smoothing_length", c->h, "m", NULL, 0);
    jval(&t, "c0", c->c0, "m/s", NULL, 0);
    jval(&t, "particles", c->n_particles, "1", NULL, 0);
    jval(&t, "steps", (double)c->steps, "1", NULL, 0);
    jval(&t, "end_time", c->t_end, "s", "planned", 0);
    jval(&t, "time_reached", c->t_reached, "s", NULL, 0);
    jval(&t, "runtime", c->runtime_s, "s", "wall clock", 0);
    jval(&t, "particle_steps_per_second",
         c->runtime_s > 0 ? (double)c->n_particles * (double)c->steps / c->runtime_s : NAN, "1/s",
         NULL, 1);
    put(&t, "    }%s\n", i + 1 < res->n_cases ? "," : "");
  }
  put(&t, "  }");
  if (res->n_cases == 2) {
    const struct wl_case_loads *a = &res->cases[0].loads, *b = &res->cases[1].loads;
    int f = a->force_peak.value >= b->force_peak.value ? 0 : 1;
    int im = a->impulse_total >= b->impulse_total ? 0 : 1;
    put(&t, ",\n  \"comparison\": {\n    \"larger_peak_force\": ");
    jstr(&t, res->cases[f].name);
    put(&t, ",\n    \"peak_force_ratio\": ");
    jnum(&t, res->cases[f].loads.force_peak.value / res->cases[1 - f].loads.force_peak.value);
    put(&t, ",\n    \"larger_impulse\": ");
    jstr(&t, res->cases[im].name);
    put(&t, ",\n    \"impulse_ratio\": ");
    jnum(&t, res->cases[im].loads.impulse_total / res->cases[1 - im].loads.impulse_total);
    put(&t, "\n  }");
  }
  (void)plan;
  put(&t, "\n}\n");
  if (t.failed) {
    free(t.s);
    return wl_error_set(err, WL_ENOMEM, "summary.json: no memory");
  }
  char path[600];
  snprintf(path, sizeof path, "%s/summary.json", res->out_dir);
  enum wl_status st = wl_store_write_text(path, t.s, t.len, err);
  free(t.s);
  return st;
}

static enum wl_status write_csv(const struct wl_assess_result *res, const struct wl_case_result *c,
                                struct wl_error *err) {
  const struct wl_record *r = &c->rec;
  const struct wl_case_loads *l = &c->loads;
  struct text t = {0};
  put(&t, "time_s,force_N_per_m,force_filtered_N_per_m,force_boundary_N_per_m,impulse_Ns_per_m,"
          "moment_Nm_per_m,moment_filtered_Nm_per_m\n");
  for (size_t k = 0; k < r->n; k++)
    put(&t, "%.6f,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", r->t[k], r->force[k], l->force_filtered[k],
        r->force_bound[k], l->impulse[k], r->moment[k], l->moment_filtered[k]);
  char path[700];
  snprintf(path, sizeof path, "%s/%s_wall.csv", res->out_dir, c->name);
  enum wl_status st =
      t.failed ? wl_error_set(err, WL_ENOMEM, "%s: no memory", path)
               : wl_store_write_text(path, t.s, t.len, err);
  t.len = 0;
  if (!st) {
    put(&t, "time_s");
    for (int g = 0; g < r->n_gauges; g++) put(&t, ",eta_%s_m", c->flume.gauge_name[g]);
    put(&t, "\n");
    for (size_t k = 0; k < r->n; k++) {
      put(&t, "%.6f", r->t[k]);
      for (int g = 0; g < r->n_gauges; g++) put(&t, ",%.6g", r->eta[k * (size_t)r->n_gauges + (size_t)g]);
      put(&t, "\n");
    }
    snprintf(path, sizeof path, "%s/%s_gauges.csv", res->out_dir, c->name);
    st = t.failed ? wl_error_set(err, WL_ENOMEM, "%s: no memory", path)
                  : wl_store_write_text(path, t.s, t.len, err);
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
      {"static_force", c->static_force, "N/m"},
      {"static_moment", c->static_moment, "N m/m"},
      {"wall_x", f->x_wall, "m"},
      {"wall_toe_z", f->z_toe, "m"},
      {"wall_crest_z", f->z_crest, "m"},
      {"still_water_z", f->depth, "m"},
  };
  for (size_t i = 0; !st && i < sizeof attrs / sizeof attrs[0]; i++)
    st = wl_store_attr_double(h5, g, attrs[i].name, attrs[i].v, attrs[i].unit, err);
  if (!st) st = wl_store_attr_text(h5, g, "status", status_word(c->status), err);
  if (!st && c->status != WL_OK) st = wl_store_attr_text(h5, g, "stopped", c->message, err);
  return st;
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
  struct wl_error cerr;
  wl_error_clear(&cerr);
  enum wl_status st2 = wl_store_close(h5, st == WL_OK, &cerr);
  if (!st && st2) {
    *err = cerr;
    st = st2;
  }
  for (int i = 0; !st && i < res->n_cases; i++) st = write_csv(res, &res->cases[i], err);
  if (!st) st = write_summary(s, plan, res, err);
  return st;
}
