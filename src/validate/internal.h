/* internal.h: the validate module's case table and shared helpers (private
 * to src/validate). */
#ifndef WALLLOAD_VALIDATE_INTERNAL_H
#define WALLLOAD_VALIDATE_INTERNAL_H

#include "wallload/backend.h"
#include "wallload/sph.h"
#include "wallload/validate.h"

/* Where the run of one level gets its settings. */
struct wl_val_ctx {
  const char *ref_dir; /* reference/ */
  int threads;         /* 0: OpenMP's default */
  int quick;
  int verlet;          /* 1: the Verlet integrator (sph/integrate.h) */
  double residual;     /* residual viscosity alpha_r (sph/vgrad.h); 0: off */
  double smagorinsky;  /* the eddy viscosity's Smagorinsky constant (sph/vgrad.h); 0: off */
  const struct wl_backend_ops *ops; /* the builders' backend (NULL: the CPU's) */
  const char *backend; /* the scenario cases' (wl_assess_opts.backend): "cpu" or "cuda" */
  const char *name;    /* the case's, for progress */
  int level;           /* 0-based level, for progress */
  wl_validate_progress_fn progress; /* may be NULL */
  void *user;
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
  int quick_levels;   /* levels of the quick ladder when --ladder is not given (0: 3) */
  int levels;         /* levels of the full ladder when --ladder is not given (0: 3) */
};

extern const struct wl_val_case wl_val_cases[];
extern const int wl_val_n_cases;

/* ---- helpers (src/validate/util.c) ---------------------------------------- */

/* A two-column numeric table read from a text file: lines starting with '#'
 * or not starting with two numbers (headers) are skipped; separators are
 * commas, semicolons, spaces or tabs. */
struct wl_val_table {
  int n;
  double *x, *y;
};
enum wl_status wl_val_table_read(const char *path, struct wl_val_table *t, struct wl_error *err);

/* The same from a many-column table: x from column 0, y from column col
 * (1 .. WL_VAL_TABLE_COLS - 1); rows with fewer than col + 1 numbers are
 * skipped. WL_EINPUT for a missing file, fewer than two rows or a bad col. */
enum { WL_VAL_TABLE_COLS = 32 };
enum wl_status wl_val_table_read_col(const char *path, int col, struct wl_val_table *t,
                                     struct wl_error *err);
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

/* ---- time series (sample i of a series is y[i * stride]) ---------------------------- */

/* The first t[i] where y exceeds level; NaN if none. */
double wl_val_first_above(const double *t, const double *y, int n, int stride, double level);

/* Centred running mean over a time window: out[i] is the mean of the
 * samples j with |t[j] - t[i]| <= width / 2 (t increasing; out has n
 * entries, stride 1). */
void wl_val_running_mean(const double *t, const double *y, int n, int stride, double width,
                         double *out);

/* The crest of a passing wave in a gauge's record: the highest point of a
 * quartic fitted by least squares to the contiguous samples around the
 * highest one that reach WL_VAL_CREST_FIT_LEVEL of it. The highest sample
 * of a surface that carries particle-scale noise reads the crest plus the
 * noise's largest excursion (2-3 mm on a wave of 2-4 particles' height:
 * 5-10 % of H/h = 0.1's 30 mm); the fit averages the noise over the top of
 * the crest. Its own bias on a smooth crest (the omitted sixth-order term
 * over the fitted window): -0.04 % of the height for sech^2, -0.04 to
 * -0.15 % for the exact solitary waves H/h = 0.1 to 0.6 sampled every
 * 0.01 s (tests/test_validate.c). NaN with
 * fewer than WL_VAL_CREST_FIT_MIN samples in the window or no positive
 * sample; *t_crest (may be NULL) gets the crest's time. */
#define WL_VAL_CREST_FIT_LEVEL 0.7
#define WL_VAL_CREST_FIT_MIN 9
double wl_val_crest_fit(const double *t, const double *y, int n, int stride, double *t_crest);

/* Passage time of a crest in the record y[k * stride], k < n, at times t:
 * the centroid of y over the contiguous samples around the highest one
 * where y is at least half of it. A solitary wave's profile is symmetric
 * about its crest, so this is the crest's time; unlike the highest sample it
 * averages the surface's particle noise, which for a wave 2-4 dp high moves
 * the highest sample by several outputs (celerity +6 % at H/h = 0.1,
 * 2026-11-26). NaN where that window reaches the record's first or last
 * sample: a window cut by the record's end, or by the initial wave already
 * over the gauge at t = 0, has its centroid pulled towards the cut (the
 * long H/h = 0.1 wave's celerity moved by up to 4 % between levels,
 * 2026-11-28), or where no sample is positive. */
double wl_val_crest_centroid_time(const double *t, const double *y, int n, int stride);

/* Mean and largest value of the samples with t0 <= t <= t1; NaN if none. */
double wl_val_window_mean(const double *t, const double *y, int n, int stride, double t0,
                          double t1);
double wl_val_window_max(const double *t, const double *y, int n, int stride, double t0,
                         double t1);

/* ---- simulation helpers (src/validate/util.c) ----------------------------------------- */

/* Water height at (x, y) (y ignored in 2D) as a wire gauge reads it: the
 * wetted length of the vertical line up to z_hi, the sum of the stretches
 * where the Shepard sum is at least the DualSPHysics gauge criterion (0.4
 * in 2D, 0.5 in 3D: sph/probe.h, REFERENCES.md 6), sampled every dp/10.
 * The kernel sum is truncated by the bed, so the line counts as wet from
 * the bed up to the first wet sample when that lies within 3 dp of it. The
 * top of the highest wet stretch (wl_sph_probe_elevation) would read an
 * overturning jet passing above the gauge as the water level, and the top
 * of the stretch from the bed would drop at an air pocket under a plunging
 * bore; the wetted length does neither. */
double wl_val_wetted_length(const struct wl_sph_probe *pr, int dim, double x, double y,
                            double z_hi, double dp);

/* Run a built case to t_end on ctx's backend with the output callback;
 * fills the level's counters. An unstable run is recorded in lv and returns
 * WL_OK (metrics then come from the outputs so far). */
enum wl_status wl_val_run_sim(const struct wl_val_ctx *ctx, const struct wl_sph_config *cfg,
                              const struct wl_particles *init, double t_end, double output_dt,
                              wl_sph_output_fn out, void *user, struct wl_validate_level *lv,
                              struct wl_error *err);

/* ---- SPHERIC Test 2 (src/validate/spheric2.c; reference/spheric2/README.md) --------- */

enum { WL_VAL_S2_NP = 4, WL_VAL_S2_NH = 4 };

/* The case's layout at spacing dp [m]: tank inside, the water as built
 * (whole rows of dp against the far wall, centred in y), the box, the
 * points where P1-P4 are sampled (half a spacing off the box's face) and
 * the (x, y) of the gauges H1-H4; depth H = 0.55 m; z_top the domain's top. */
struct wl_val_s2_geom {
  double tank_lo[3], tank_hi[3];
  double water_lo[3], water_hi[3];
  double box_lo[3], box_hi[3];
  double probe[WL_VAL_S2_NP][3];
  double gauge[WL_VAL_S2_NH][2];
  int gauge_col[WL_VAL_S2_NH]; /* the data's column (1..4: H1..H4) read at each gauge */
  double depth, z_top;
};
void wl_val_spheric2_geometry(double dp, struct wl_val_s2_geom *g);

/* Build the case at dp with the default numerics (ctx may be NULL: the
 * CPU's defaults, symplectic). WL_EINPUT, WL_ENOMEM. */
enum wl_status wl_val_spheric2_build(double dp, const struct wl_val_ctx *ctx,
                                     struct wl_sph_config *cfg, struct wl_particles *init,
                                     struct wl_error *err);

/* The fluid particles of p within `support` [m] of a sensor (P1-P4's strip,
 * the gauges' lines) copied into near (grown with wl_particles_alloc as
 * needed; wl_particles_clear it): what the probe needs to index. */
enum wl_status wl_val_spheric2_near(double dp, const struct wl_particles *p, double support,
                                    struct wl_particles *near, struct wl_error *err);

/* The sensors on an indexed probe: p[WL_VAL_S2_NP] [Pa], h[WL_VAL_S2_NH] [m]. */
void wl_val_spheric2_sample(const struct wl_sph_probe *pr, double dp, double *p, double *h);

/* The experiment (dir/kleefsman2005_exp.dat) with each sensor's pre-impact
 * offset subtracted (its mean before the water arrives: t < 0.35 s for the
 * pressures, t < 0.15 s for H1-H3; H4 stands in the reservoir and keeps
 * its reading); the offsets are kept. h[i] is the data column read at
 * gauge i (geom.gauge_col). */
struct wl_val_s2_data {
  struct wl_val_table p[WL_VAL_S2_NP], h[WL_VAL_S2_NH];
  double p_offset[WL_VAL_S2_NP], h_offset[WL_VAL_S2_NH];
};
enum wl_status wl_val_spheric2_data(const char *dir, struct wl_val_s2_data *d,
                                    struct wl_error *err);
void wl_val_spheric2_data_clear(struct wl_val_s2_data *d);

/* A pressure record's metrics (reference/spheric2/README.md): arrival (the
 * 5 ms running mean first above rho g H / 4), plateau (the mean from 0.5
 * to 1 s after t_arrival_ref, or after its own arrival when that is NaN),
 * peak of the 5 ms running mean and its time, the smallest raw sample. */
struct wl_val_s2_pmetrics {
  double arrival, plateau, peak, t_peak, min;
};
void wl_val_spheric2_pressure_metrics(const double *t, const double *p, int n, int stride,
                                      double rgh, double t_arrival_ref,
                                      struct wl_val_s2_pmetrics *m);

enum wl_status wl_val_run_spheric2(const struct wl_val_case *c, const struct wl_val_ctx *ctx,
                                   double dp, struct wl_validate_level *lv,
                                   struct wl_error *err);

#endif
