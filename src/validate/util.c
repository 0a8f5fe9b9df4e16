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
#include "wallload/sph.h"
#include "wallload/sph/probe.h"

void wl_val_table_clear(struct wl_val_table *t) {
  free(t->x);
  free(t->y);
  memset(t, 0, sizeof *t);
}

/* The numbers of one line (separators: commas, semicolons, spaces, tabs),
 * at most max; parsing stops at the first token that is not a number. */
static int parse_numbers(char *line, double *v, int max) {
  int n = 0;
  char *c = line;
  while (n < max) {
    while (*c == ' ' || *c == '\t' || *c == ',' || *c == ';' || *c == '\r' || *c == '\n') c++;
    if (!*c) break;
    char *end;
    const double x = strtod(c, &end);
    if (end == c) break;
    v[n++] = x;
    c = end;
  }
  return n;
}

enum wl_status wl_val_table_read_col(const char *path, int col, struct wl_val_table *t,
                                     struct wl_error *err) {
  memset(t, 0, sizeof *t);
  if (col < 1 || col >= WL_VAL_TABLE_COLS)
    return wl_error_set(err, WL_EINPUT, "%s: column %d out of range 1..%d", path, col,
                        WL_VAL_TABLE_COLS - 1);
  FILE *f = fopen(path, "r");
  if (!f)
    return wl_error_set(err, WL_EINPUT, "%s: cannot open the reference table (is --reference "
                        "pointing at wallload's reference/ directory?)", path);
  char line[2048];
  double v[WL_VAL_TABLE_COLS];
  int cap = 0;
  while (fgets(line, sizeof line, f)) {
    if (line[0] == '#') continue;
    if (parse_numbers(line, v, col + 1) != col + 1) continue; /* a header or a short row */
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
    t->x[t->n] = v[0];
    t->y[t->n] = v[col];
    t->n++;
  }
  fclose(f);
  if (t->n < 2) {
    wl_val_table_clear(t);
    return wl_error_set(err, WL_EINPUT, "%s: fewer than two data rows with %d columns", path,
                        col + 1);
  }
  return WL_OK;
}

enum wl_status wl_val_table_read(const char *path, struct wl_val_table *t, struct wl_error *err) {
  return wl_val_table_read_col(path, 1, t, err);
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

/* ---- time-series helpers ------------------------------------------------------ */

double wl_val_first_above(const double *t, const double *y, int n, int stride, double level) {
  for (int i = 0; i < n; i++)
    if (y[(size_t)i * (size_t)stride] > level) return t[i];
  return NAN;
}

void wl_val_running_mean(const double *t, const double *y, int n, int stride, double width,
                         double *out) {
  double s = 0;
  int lo = 0, hi = 0; /* the window is samples lo .. hi-1 */
  const double half = 0.5 * width, eps = 1e-9 * (width > 0 ? width : 1);
  for (int i = 0; i < n; i++) {
    while (hi < n && t[hi] <= t[i] + half + eps) s += y[(size_t)hi++ * (size_t)stride];
    while (t[lo] < t[i] - half - eps) s -= y[(size_t)lo++ * (size_t)stride];
    out[i] = s / (hi - lo);
  }
}

double wl_val_window_mean(const double *t, const double *y, int n, int stride, double t0,
                          double t1) {
  double s = 0;
  int m = 0;
  for (int i = 0; i < n; i++)
    if (t[i] >= t0 && t[i] <= t1) s += y[(size_t)i * (size_t)stride], m++;
  return m ? s / m : NAN;
}

double wl_val_window_max(const double *t, const double *y, int n, int stride, double t0,
                         double t1) {
  double mx = NAN;
  for (int i = 0; i < n; i++) {
    const double v = y[(size_t)i * (size_t)stride];
    if (t[i] >= t0 && t[i] <= t1 && !(v <= mx)) mx = v;
  }
  return mx;
}

/* The crest of the record y[k * stride], k < n: the contiguous samples
 * [*a, *b] around the highest one where y is at least `level` times it.
 * 0, or -1 where no sample is positive. */
static int crest_window(const double *y, int n, int stride, double level, int *a, int *b) {
  if (n < 1) return -1;
  const size_t st = (size_t)stride;
  int best = 0;
  for (int k = 1; k < n; k++)
    if (y[(size_t)k * st] > y[(size_t)best * st]) best = k;
  const double top = y[(size_t)best * st];
  if (!(top > 0)) return -1;
  *a = *b = best;
  while (*a > 0 && y[(size_t)(*a - 1) * st] >= level * top) (*a)--;
  while (*b + 1 < n && y[(size_t)(*b + 1) * st] >= level * top) (*b)++;
  return 0;
}

double wl_val_crest_fit(const double *t, const double *y, int n, int stride, double *t_crest) {
  if (t_crest) *t_crest = NAN;
  int a, b;
  if (crest_window(y, n, stride, WL_VAL_CREST_FIT_LEVEL, &a, &b) ||
      b - a + 1 < WL_VAL_CREST_FIT_MIN)
    return NAN;
  /* least squares of c0 + c1 u + ... + c4 u^4, u = (t - tm) / w in [-1, 1] */
  const double tm = 0.5 * (t[a] + t[b]), w = 0.5 * (t[b] - t[a]);
  double A[5][6] = {{0}};
  for (int i = a; i <= b; i++) {
    const double u = (t[i] - tm) / w, v = y[(size_t)i * (size_t)stride];
    double pw[9];
    pw[0] = 1;
    for (int k = 1; k < 9; k++) pw[k] = pw[k - 1] * u;
    for (int r = 0; r < 5; r++) {
      for (int c = 0; c < 5; c++) A[r][c] += pw[r + c];
      A[r][5] += pw[r] * v;
    }
  }
  for (int c = 0; c < 5; c++) { /* Gauss-Jordan with partial pivoting */
    int piv = c;
    for (int r = c + 1; r < 5; r++)
      if (fabs(A[r][c]) > fabs(A[piv][c])) piv = r;
    if (!(fabs(A[piv][c]) > 0)) return NAN;
    for (int k = 0; k < 6; k++) {
      const double tmp = A[c][k];
      A[c][k] = A[piv][k];
      A[piv][k] = tmp;
    }
    for (int r = 0; r < 5; r++) {
      if (r == c) continue;
      const double f = A[r][c] / A[c][c];
      for (int k = c; k < 6; k++) A[r][k] -= f * A[c][k];
    }
  }
  double coef[5];
  for (int k = 0; k < 5; k++) coef[k] = A[k][5] / A[k][k];
  /* the fitted curve's highest point on the window, on a fine grid */
  double best_v = -INFINITY, best_u = 0;
  for (int j = 0; j <= 2000; j++) {
    const double u = -1.0 + j / 1000.0;
    const double v = coef[0] + u * (coef[1] + u * (coef[2] + u * (coef[3] + u * coef[4])));
    if (v > best_v) best_v = v, best_u = u;
  }
  if (t_crest) *t_crest = tm + best_u * w;
  return best_v;
}

double wl_val_crest_centroid_time(const double *t, const double *y, int n, int stride) {
  int a, b;
  if (crest_window(y, n, stride, 0.5, &a, &b) || a == 0 || b + 1 == n) return NAN;
  const size_t st = (size_t)stride;
  double se = 0, ste = 0;
  for (int k = a; k <= b; k++) {
    se += y[(size_t)k * st];
    ste += t[k] * y[(size_t)k * st];
  }
  return ste / se;
}

/* ---- simulation helpers ------------------------------------------------------- */

double wl_val_wetted_length(const struct wl_sph_probe *pr, int dim, double x, double y,
                            double z_hi, double dp) {
  const double lim = WL_SPH_SURFACE_SHEPARD, dz = 0.1 * dp; /* sph/probe.h */
  double q[3] = {x, dim == 3 ? y : 0.0, 0.0};
  const int iz = dim - 1;
  double len = 0, z = 0.0;
  for (; z <= 3 * dp; z += dz) {
    q[iz] = z;
    if (wl_sph_probe_shepard(pr, q) >= lim) break;
  }
  if (z <= 3 * dp) len = z;
  for (; z <= z_hi; z += dz) {
    q[iz] = z;
    if (wl_sph_probe_shepard(pr, q) >= lim) len += dz;
  }
  return len;
}

/* The solver's callbacks share one user pointer: the output callback and
 * the level's context travel together. */
struct run_wrap {
  wl_sph_output_fn out;
  void *user;
  const struct wl_val_ctx *ctx;
};

static enum wl_status wrap_out(void *u, struct wl_sph_sim *sim, double t, struct wl_error *err) {
  const struct run_wrap *w = u;
  return w->out ? w->out(w->user, sim, t, err) : WL_OK;
}

static void wrap_progress(void *u, const struct wl_sph_progress *pr) {
  const struct run_wrap *w = u;
  w->ctx->progress(w->ctx->user, w->ctx->name, w->ctx->level, pr);
}

enum wl_status wl_val_run_sim(const struct wl_val_ctx *ctx, const struct wl_sph_config *cfg,
                              const struct wl_particles *init, double t_end, double output_dt,
                              wl_sph_output_fn out, void *user, struct wl_validate_level *lv,
                              struct wl_error *err) {
  struct wl_sph_sim *sim = NULL;
  lv->n_particles = init->n;
  const struct wl_backend_ops *ops = ctx->ops ? ctx->ops : &wl_backend_cpu_ops;
  enum wl_status st = wl_sph_sim_alloc(&sim, ops, cfg, init, err);
  if (st) return st;
  struct wl_sph_run_opts o = {0};
  o.t_end = t_end;
  o.output_dt = output_dt;
  struct run_wrap w = {out, user, ctx};
  o.output = wrap_out;
  o.user = &w;
  if (ctx->progress) o.progress = wrap_progress;
  const double w0 = wl_val_now();
  struct wl_error run_err;
  wl_error_clear(&run_err);
  st = wl_sph_sim_run(sim, &o, &run_err);
  lv->runtime_s = wl_val_now() - w0;
  lv->steps = wl_sph_sim_steps(sim);
  lv->t_reached = wl_sph_sim_time(sim);
  lv->status = st;
  if (st) snprintf(lv->message, sizeof lv->message, "%s", run_err.msg);
  wl_sph_sim_free(sim);
  if (st == WL_EUNSTABLE) return WL_OK;
  if (st) return wl_error_set(err, st, "%s", run_err.msg);
  return WL_OK;
}
