/* util.c: helpers of the validate module: reference tables, interpolation,
 * the metrics (RMSE as seed 001 eq 16, correlation coefficient as seed 000
 * Table 6), growable series. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "internal.h"

void wl_val_table_clear(struct wl_val_table *t) {
  free(t->x);
  free(t->y);
  memset(t, 0, sizeof *t);
}

enum wl_status wl_val_table_read(const char *path, struct wl_val_table *t, struct wl_error *err) {
  memset(t, 0, sizeof *t);
  FILE *f = fopen(path, "r");
  if (!f)
    return wl_error_set(err, WL_EINPUT, "%s: cannot open the reference table (is --reference "
                        "pointing at wallload's reference/ directory?)", path);
  char line[512];
  int cap = 0;
  while (fgets(line, sizeof line, f)) {
    if (line[0] == '#') continue;
    for (char *c = line; *c; c++)
      if (*c == ',' || *c == ';' || *c == '\t' || *c == '\r') *c = ' ';
    double a, b;
    if (sscanf(line, "%lf %lf", &a, &b) != 2) continue;
    if (t->n == cap) {
      cap = cap ? 2 * cap : 64;
      double *x = realloc(t->x, sizeof(double) * (size_t)cap);
      if (x) t->x = x;
      double *y = realloc(t->y, sizeof(double) * (size_t)cap);
      if (y) t->y = y;
      if (!x || !y) {
        fclose(f);
        wl_val_table_clear(t);
        return wl_error_set(err, WL_ENOMEM, "%s: no memory for the table", path);
      }
    }
    t->x[t->n] = a;
    t->y[t->n] = b;
    t->n++;
  }
  fclose(f);
  if (t->n < 2) {
    wl_val_table_clear(t);
    return wl_error_set(err, WL_EINPUT, "%s: fewer than two data rows", path);
  }
  return WL_OK;
}

double wl_val_interp(const double *x, const double *y, int n, double xq) {
  if (n <= 0) return NAN;
  if (xq <= x[0]) return y[0];
  int lo = 0, hi = n - 1;
  if (xq >= x[hi]) return y[hi];
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (x[mid] <= xq) lo = mid;
    else hi = mid;
  }
  double w = x[hi] > x[lo] ? (xq - x[lo]) / (x[hi] - x[lo]) : 0.0;
  return y[lo] + w * (y[hi] - y[lo]);
}

static void set_common(struct wl_validate_metric *m, const char *name, const char *unit) {
  memset(m, 0, sizeof *m);
  snprintf(m->name, sizeof m->name, "%s", name);
  snprintf(m->unit, sizeof m->unit, "%s", unit ? unit : "");
}

void wl_val_rel(struct wl_validate_metric *m, const char *name, const char *unit, double value,
                double reference, double tol) {
  set_common(m, name, unit);
  m->kind = WL_VALIDATE_REL;
  m->value = value;
  m->reference = reference;
  m->error = value / reference - 1.0;
  m->tol = tol;
  m->pass = isnan(tol) ? 1 : (isfinite(m->error) && fabs(m->error) <= tol);
}

void wl_val_rmse(struct wl_validate_metric *m, const char *name, const char *unit, double rmse,
                 double scale, double tol) {
  set_common(m, name, unit);
  m->kind = WL_VALIDATE_RMSE;
  m->value = rmse;
  m->reference = scale;
  m->error = rmse / scale;
  m->tol = tol;
  m->pass = isnan(tol) ? 1 : (isfinite(m->error) && m->error <= tol);
}

void wl_val_ratio(struct wl_validate_metric *m, const char *name, const char *unit, double value,
                  double scale, double tol) {
  wl_val_rmse(m, name, unit, value, scale, tol);
  m->kind = WL_VALIDATE_RATIO;
}

void wl_val_corr(struct wl_validate_metric *m, const char *name, double r, double tol) {
  set_common(m, name, "");
  m->kind = WL_VALIDATE_CORR;
  m->value = r;
  m->reference = 1.0;
  m->error = r;
  m->tol = tol;
  m->pass = isnan(tol) ? 1 : (isfinite(r) && r >= tol);
}

void wl_val_compare(const double *tm, const double *ym, int nm, const double *te,
                    const double *ye, int ne, double t0, double t1, double *rmse, double *corr,
                    int *n_used) {
  double s2 = 0, sm = 0, se = 0, smm = 0, see = 0, sme = 0;
  int n = 0;
  for (int i = 0; i < ne; i++) {
    if (te[i] < t0 || te[i] > t1 || nm < 2 || te[i] < tm[0] || te[i] > tm[nm - 1]) continue;
    double m = wl_val_interp(tm, ym, nm, te[i]), e = ye[i];
    s2 += (m - e) * (m - e);
    sm += m, se += e, smm += m * m, see += e * e, sme += m * e;
    n++;
  }
  *n_used = n;
  if (n < 2) {
    *rmse = NAN, *corr = NAN;
    return;
  }
  *rmse = sqrt(s2 / n); /* seed 001 eq 16 */
  double cov = sme - sm * se / n, vm = smm - sm * sm / n, ve = see - se * se / n;
  *corr = (vm > 0 && ve > 0) ? cov / sqrt(vm * ve) : NAN; /* Pearson, seed 000 Table 6 */
}

enum wl_status wl_val_series_push(struct wl_val_series *s, double t, const double *y,
                                  struct wl_error *err) {
  if (s->n == s->cap) {
    int cap = s->cap ? 2 * s->cap : 512;
    double *nt = realloc(s->t, sizeof(double) * (size_t)cap);
    if (nt) s->t = nt;
    double *ny = realloc(s->y, sizeof(double) * (size_t)cap * (size_t)(s->k ? s->k : 1));
    if (ny) s->y = ny;
    if (!nt || !ny) return wl_error_set(err, WL_ENOMEM, "validate: no memory for a series");
    s->cap = cap;
  }
  s->t[s->n] = t;
  for (int j = 0; j < s->k; j++) s->y[(size_t)s->n * (size_t)s->k + (size_t)j] = y[j];
  s->n++;
  return WL_OK;
}

void wl_val_series_clear(struct wl_val_series *s) {
  free(s->t);
  free(s->y);
  int k = s->k;
  memset(s, 0, sizeof *s);
  s->k = k;
}

double wl_val_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
