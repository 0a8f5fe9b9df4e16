/* table.c: sweep.csv and sweep.h5, one row (one index) per case, each file
 * written atomically (store.h), so that a kill between two cases leaves the
 * previous complete file. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sweep_private.h"
#include "wallload/config.h"
#include "wallload/store.h"

static const char *const load_name[WL_SWEEP_N_LOADS] = {"solitary", "explosion"};


/* A number to round-trip exactly (%.17g); empty when there is none. */
static void num(struct wl_text *t, double v) {
  if (isfinite(v)) wl_text_put(t, ",%.17g", v);
  else wl_text_put(t, ",");
}

/* A CSV text field, quoted (RFC 4180) when it needs to be. */
static void field(struct wl_text *t, const char *s) {
  wl_text_put(t, ",");
  if (!strpbrk(s, ",\"\n\r")) {
    wl_text_put(t, "%s", s);
    return;
  }
  wl_text_put(t, "\"");
  for (; *s; s++) {
    if (*s == '"') wl_text_put(t, "\"\"");
    else if (*s == '\n' || *s == '\r') wl_text_put(t, " ");
    else wl_text_put(t, "%c", *s);
  }
  wl_text_put(t, "\"");
}

static double load_value(const struct wl_sweep_loads *l, const struct sweep_field *f) {
  return *(const double *)(const void *)((const char *)l + f->off);
}

/* Which load case governs a quantity: "explosion", "solitary", or "" when
 * either is missing. */
static const char *governs(const struct wl_sweep_row *r, size_t off) {
  const double a = *(const double *)(const void *)((const char *)&r->load[0] + off);
  const double b = *(const double *)(const void *)((const char *)&r->load[1] + off);
  if (!isfinite(a) || !isfinite(b)) return "";
  return b > a ? "explosion" : "solitary";
}

static enum wl_status write_csv(const struct wl_sweep *sw, const char *dir, struct wl_error *err) {
  struct wl_text t = {0};
  const int both = sw->has_load[0] && sw->has_load[1];
  wl_text_put(&t, "case,id,status");
  for (int k = 0; k < sw->n_params; k++)
    wl_text_put(&t, ",%s_%s", wl_scenario_sweep_param_name(sw->order[k]), sweep_param_unit(sw->order[k]));
  for (int l = 0; l < WL_SWEEP_N_LOADS; l++) {
    if (!sw->has_load[l]) continue;
    wl_text_put(&t, ",%s_status", load_name[l]);
    for (int f = 0; f < sweep_n_fields; f++)
      wl_text_put(&t, ",%s_%s_%s", load_name[l], sweep_fields[f].name, sweep_fields[f].csv_unit);
  }
  if (both) wl_text_put(&t, ",governs_peak_force,governs_impulse_positive");
  wl_text_put(&t, ",runtime_s,message\n");
  for (int i = 0; i < sw->n_cases; i++) {
    const struct wl_sweep_row *r = &sw->rows[i];
    const int pending = r->state == WL_SWEEP_PENDING;
    wl_text_put(&t, "%d,%s,%s", i, sw->cases[i].id, sweep_status_word(r, r->status));
    for (int k = 0; k < sw->n_params; k++) num(&t, sw->cases[i].value[sw->order[k]]);
    for (int l = 0; l < WL_SWEEP_N_LOADS; l++) {
      if (!sw->has_load[l]) continue;
      const struct wl_sweep_loads *ld = &r->load[l];
      field(&t, pending || !ld->present ? "" : sweep_status_word(NULL, ld->status));
      for (int f = 0; f < sweep_n_fields; f++)
        num(&t, pending || !ld->present ? NAN : load_value(ld, &sweep_fields[f]));
    }
    if (both) {
      field(&t, pending ? "" : governs(r, offsetof(struct wl_sweep_loads, peak_force)));
      field(&t, pending ? "" : governs(r, offsetof(struct wl_sweep_loads, impulse_positive)));
    }
    num(&t, pending ? NAN : r->runtime_s);
    field(&t, pending ? "" : r->message);
    wl_text_put(&t, "\n");
  }
  char path[1200];
  snprintf(path, sizeof path, "%s/sweep.csv", dir);
  enum wl_status st = t.failed ? wl_error_set(err, WL_ENOMEM, "%s: no memory", path)
                               : wl_store_write_text(path, t.s, t.len, err);
  free(t.s);
  return st;
}

/* Status codes of sweep.h5: what a case's (or load case's) status word is. */
static int status_code(const struct wl_sweep_row *r, enum wl_status st) {
  if (r && r->state == WL_SWEEP_PENDING) return -1;
  return st == WL_OK ? 0 : st == WL_EUNSTABLE ? 1 : st == WL_EINTERRUPTED ? 2 : 3;
}
#define STATUS_CODES "-1 pending (not run), 0 complete, 1 unstable, 2 interrupted, 3 failed"

static enum wl_status write_h5(const struct wl_sweep *sw, const char *dir, struct wl_error *err) {
  char path[1200];
  snprintf(path, sizeof path, "%s/sweep.h5", dir);
  const size_t n = (size_t)sw->n_cases;
  double *v = malloc(n * sizeof *v);
  int *code = malloc(n * sizeof *code);
  if (!v || !code) {
    free(v), free(code);
    return wl_error_set(err, WL_ENOMEM, "%s: no memory", path);
  }
  struct wl_store *h5;
  enum wl_status st = wl_store_open(path, &h5, err);
  if (st) {
    free(v), free(code);
    return st;
  }
  char params[256] = "";
  for (int k = 0; k < sw->n_params; k++) {
    size_t u = strlen(params);
    snprintf(params + u, sizeof params - u, "%s%s", k ? "," : "",
             wl_scenario_sweep_param_name(sw->order[k]));
  }
  if (!st) st = wl_store_attr_text(h5, "/", "scenario_name", sw->name, err);
  if (!st) st = wl_store_attr_text(h5, "/", "scenario_file", sw->path, err);
  if (!st) st = wl_store_attr_text(h5, "/", "wallload_version", WL_VERSION, err);
  if (!st) st = wl_store_attr_text(h5, "/", "parameters", params, err);
  if (!st) st = wl_store_attr_double(h5, "/", "cases", (double)n, "1", err);
  for (int k = 0; !st && k < sw->n_params; k++) {
    const enum wl_sweep_param p = sw->order[k];
    char ds[160], desc[200];
    for (size_t i = 0; i < n; i++) v[i] = sw->cases[i].value[p];
    snprintf(ds, sizeof ds, "inputs/%s", wl_scenario_sweep_param_name(p));
    snprintf(desc, sizeof desc, "swept value of %s per case", wl_scenario_sweep_param_name(p));
    st = wl_store_write_vector(h5, ds, v, n, sweep_param_unit(p), desc, err);
  }
  for (size_t i = 0; i < n; i++) code[i] = status_code(&sw->rows[i], sw->rows[i].status);
  if (!st) st = wl_store_write_vector_i(h5, "status", code, n, "case status: " STATUS_CODES, err);
  for (size_t i = 0; i < n; i++)
    v[i] = sw->rows[i].state == WL_SWEEP_PENDING ? NAN : sw->rows[i].runtime_s;
  if (!st) st = wl_store_write_vector(h5, "runtime", v, n, "s", "wall clock of the case's run", err);
  for (int l = 0; !st && l < WL_SWEEP_N_LOADS; l++) {
    if (!sw->has_load[l]) continue;
    char ds[160];
    for (size_t i = 0; i < n; i++)
      code[i] = sw->rows[i].load[l].present ? status_code(&sw->rows[i], sw->rows[i].load[l].status)
                                            : -1;
    snprintf(ds, sizeof ds, "%s/status", load_name[l]);
    st = wl_store_write_vector_i(h5, ds, code, n, "load case status: " STATUS_CODES, err);
    for (int f = 0; !st && f < sweep_n_fields; f++) {
      for (size_t i = 0; i < n; i++) {
        const struct wl_sweep_row *r = &sw->rows[i];
        v[i] = r->state == WL_SWEEP_PENDING || !r->load[l].present
                   ? NAN
                   : load_value(&r->load[l], &sweep_fields[f]);
      }
      snprintf(ds, sizeof ds, "%s/%s", load_name[l], sweep_fields[f].name);
      st = wl_store_write_vector(h5, ds, v, n, sweep_fields[f].unit, sweep_fields[f].desc, err);
    }
  }
  /* each case's identity, scenario and (when it did not complete) why */
  for (size_t i = 0; !st && i < n; i++) {
    char g[200];
    snprintf(g, sizeof g, "cases/%s", sw->cases[i].id);
    st = wl_store_attr_text(h5, g, "scenario_text", sw->cases[i].text, err);
    if (!st)
      st = wl_store_attr_text(h5, g, "status", sweep_status_word(&sw->rows[i], sw->rows[i].status),
                              err);
    if (!st && sw->rows[i].state != WL_SWEEP_PENDING && sw->rows[i].status != WL_OK)
      st = wl_store_attr_text(h5, g, "message", sw->rows[i].message, err);
  }
  free(v), free(code);
  enum wl_status cst = wl_store_close(h5, st == WL_OK, st ? NULL : err);
  return st ? st : cst;
}

enum wl_status sweep_write_tables(const struct wl_sweep *sw, const char *dir,
                                  struct wl_error *err) {
  enum wl_status st = write_csv(sw, dir, err);
  if (st == WL_OK) st = write_h5(sw, dir, err);
  return st;
}
