/* internal.h: the validate module's case table and shared helpers (private
 * to src/validate). */
#ifndef WALLLOAD_VALIDATE_INTERNAL_H
#define WALLLOAD_VALIDATE_INTERNAL_H

#include "wallload/validate.h"

/* Where the run of one level gets its settings. */
struct wl_val_ctx {
  const char *ref_dir; /* reference/ */
  int threads;         /* 0: OpenMP's default */
  int quick;
  int verlet;          /* 1: the Verlet integrator (sph/integrate.h) */
};

struct wl_val_case;
typedef enum wl_status (*wl_val_run_fn)(const struct wl_val_case *c, const struct wl_val_ctx *ctx,
                                        double dp, struct wl_validate_level *lv,
                                        struct wl_error *err);

struct wl_val_case {
  const char *name;   /* command-line name */
  const char *dir;    /* reference/<dir> */
  const char *title;
  wl_val_run_fn run;
  double dp0;         /* coarsest spacing of the full ladder [m] */
  double dp0_quick;   /* coarsest spacing of the quick ladder [m] */
  double p[4];        /* case parameters (depth, H/h, ...) */
};

extern const struct wl_val_case wl_val_cases[];
extern const int wl_val_n_cases;

/* ---- helpers (src/validate/util.c) ---------------------------------------- */

/* A two-column numeric table read from a text file: lines starting with '#'
 * or not starting with two numbers (headers) are skipped; separators are
 * commas, spaces or tabs. */
struct wl_val_table {
  int n;
  double *x, *y;
};
enum wl_status wl_val_table_read(const char *path, struct wl_val_table *t, struct wl_error *err);
void wl_val_table_clear(struct wl_val_table *t);

/* Linear interpolation of (x, y), n points, x increasing; clamped ends. */
double wl_val_interp(const double *x, const double *y, int n, double xq);

/* Fill a metric. */
void wl_val_rel(struct wl_validate_metric *m, const char *name, const char *unit, double value,
                double reference, double tol);
void wl_val_rmse(struct wl_validate_metric *m, const char *name, const char *unit, double rmse,
                 double scale, double tol);
void wl_val_ratio(struct wl_validate_metric *m, const char *name, const char *unit, double value,
                  double scale, double tol);
void wl_val_corr(struct wl_validate_metric *m, const char *name, double r, double tol);

/* RMSE (seed 001 eq 16) and correlation coefficient of a model series
 * interpolated at the reference's times: model (tm, ym, nm), reference
 * (te, ye, ne), over reference points with t0 <= te <= t1. *n_used gets the
 * count. */
void wl_val_compare(const double *tm, const double *ym, int nm, const double *te,
                    const double *ye, int ne, double t0, double t1, double *rmse, double *corr,
                    int *n_used);

/* Growable series of (t, y1..yk). */
struct wl_val_series {
  int n, cap, k;
  double *t, *y; /* y: n x k */
};
enum wl_status wl_val_series_push(struct wl_val_series *s, double t, const double *y,
                                  struct wl_error *err);
void wl_val_series_clear(struct wl_val_series *s);

/* Wall-clock seconds (monotonic). */
double wl_val_now(void);

#endif
