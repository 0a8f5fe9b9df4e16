/* validate.h: the reference suite (module validate, src/validate/; cases
 * documented in reference/).
 *
 * Each reference case is a scene (a scenario file in reference/<case>/ run
 * as a load case through wl_assess_case, or a documented builder on the
 * scene module), an independent reference (closed form, or a published
 * data table copied into reference/<case>/ with its citation), metrics and
 * tolerances with their justification (reference/<case>/README.md). A case
 * runs on a ladder of resolutions dp0, dp0/sqrt2, dp0/2, ...; per level it
 * records particles, steps, runtime and its metrics. Over three levels the
 * observed convergence order of the primary metric and a Richardson-
 * extrapolated error are estimated where the order is meaningful.
 *
 * Metrics (all dimensionless):
 *  - relative error of a scalar (period, bed pressure, run-up, celerity,
 *    peak value): value / reference - 1 (signed; |.| is judged);
 *  - RMSE of a series (seed 001 eq 16: sqrt(sum (Xm - Xe)^2 / n)), divided
 *    by a stated scale (the reference's peak, the column height, ...);
 *  - correlation coefficient (seed 000 Table 6; seed 001 section 3.1.1),
 *    judged from below;
 *  - a bounded ratio (spurious velocity / sqrt(g h), ...), judged from above.
 * A case passes when every metric that has a tolerance meets it at the
 * finest level of the ladder. Tolerances are never tuned to the solver. */
#ifndef WALLLOAD_VALIDATE_H
#define WALLLOAD_VALIDATE_H

#include <stddef.h>

#include "wallload/error.h"

enum {
  WL_VALIDATE_MAX_LEVELS = 6,
  WL_VALIDATE_MAX_METRICS = 20,
  WL_VALIDATE_NAME_MAX = 48,
};

enum wl_validate_kind {
  WL_VALIDATE_REL,  /* signed relative error value/reference - 1; |error| <= tol passes */
  WL_VALIDATE_RMSE, /* RMSE / scale (>= 0); error <= tol passes */
  WL_VALIDATE_CORR, /* correlation coefficient r; r >= tol passes */
  WL_VALIDATE_RATIO,/* a bound: value / scale (>= 0); error <= tol passes */
};

struct wl_validate_metric {
  char name[WL_VALIDATE_NAME_MAX]; /* "bed pressure", "H1 RMSE/H", ... */
  enum wl_validate_kind kind;
  double value;     /* measured quantity (REL: in `unit`; RMSE: in `unit`, before scaling;
                       CORR: r) */
  double reference; /* REL: the reference value; RMSE: the scale it is divided by; CORR: 1 */
  char unit[16];    /* of value and reference ("" when dimensionless) */
  double error;     /* REL: value/reference - 1; RMSE: value/reference; CORR: r */
  double tol;       /* NaN: reported only, not judged */
  int pass;         /* 1 when judged and met (or not judged), 0 when missed */
};

struct wl_validate_level {
  double dp;          /* particle spacing [m] */
  int n_particles;    /* fluid + boundary */
  long steps;
  double runtime_s;   /* wall-clock of the simulation [s] */
  double t_reached;   /* simulated time [s] */
  int status;         /* enum wl_status of the run (WL_OK, WL_EUNSTABLE, ...) */
  char message[512];  /* why it stopped, when status != WL_OK */
  int n_metrics;
  struct wl_validate_metric m[WL_VALIDATE_MAX_METRICS];
};

struct wl_validate_result {
  char name[WL_VALIDATE_NAME_MAX]; /* case name */
  char title[160];                 /* one line: what and against what */
  int n_levels;
  struct wl_validate_level lv[WL_VALIDATE_MAX_LEVELS];
  /* convergence of the primary metric (m[0]) over the last three levels */
  double ratio;       /* refinement ratio between levels (sqrt 2) */
  double order;       /* observed order p; NaN when fewer than 3 levels */
  int order_ok;       /* 1: p in [WL_LOADS_ORDER_MIN, WL_LOADS_ORDER_MAX] and
                         the differences keep their sign (monotone); the
                         arithmetic is wl_loads_convergence's, as assess's */
  double extrapolated;/* Richardson-extrapolated primary error (NaN unless order_ok) */
  int pass;           /* every judged metric met at the finest level, every level ran */
  char verdict[512];  /* "pass", or which metric missed by how much */
  char integrator[16]; /* time integrator of the runs: "symplectic" or "verlet" */
  double residual;     /* residual viscosity alpha_r of the runs (0: off) */
  double smagorinsky;  /* the eddy viscosity's Smagorinsky constant of the runs (0: off) */
  char backend[16];    /* backend of the runs: "cpu" or "cuda" */
};


/* Progress after each level (the CLI prints it; the library never does). */
typedef void (*wl_validate_level_fn)(void *user, const struct wl_validate_result *r, int level);

/* Progress within a level's run (simulated time, steps/s, ETA; sph.h), about
 * once a second of wall-clock time. */
struct wl_sph_progress;
typedef void (*wl_validate_progress_fn)(void *user, const char *case_name, int level,
                                        const struct wl_sph_progress *pr);

struct wl_validate_opts {
  int n_levels;              /* ladder length (default 3 when 0), 1..WL_VALIDATE_MAX_LEVELS */
  int quick;                 /* 1: each case's quick (coarse, short) ladder */
  int threads;               /* 0: OpenMP's default */
  int verlet;                /* 1: the Verlet integrator instead of the symplectic default */
  double residual;           /* residual viscosity alpha_r of every run (0: the default, off) */
  double smagorinsky;        /* the eddy viscosity's Smagorinsky constant of every run (0: the
                                default, off) */
  const char *backend;       /* NULL or "cpu": the CPU; "cuda": the GPU (WL_EUNSUPPORTED
                                without one); "auto": the GPU when there is one */
  const char *reference_dir; /* NULL: WL_VALIDATE_REFERENCE_DIR (the source tree's reference/) */
  wl_validate_level_fn on_level; /* may be NULL */
  wl_validate_progress_fn progress; /* may be NULL */
  void *user;
};

/* Number of cases, and case i's name and one-line title (NULL out of
 * range). */
int wl_validate_n_cases(void);
const char *wl_validate_case_name(int i);
const char *wl_validate_case_title(int i);

/* Select cases by name: an exact case name, or a group prefix ending the
 * name at '-' ("solitary" selects solitary-h0.2-e0.4 and the others, not
 * solitary_wall). Marks sel[i] = 1 for every case matched (sel has
 * wl_validate_n_cases() entries). Returns WL_OK, or WL_EINPUT naming the
 * unknown name and listing the valid ones. */
enum wl_status wl_validate_select(const char *name, int *sel, struct wl_error *err);

/* Run case i on its ladder. r is filled level by level (also on failure:
 * levels that ran stay). Returns WL_OK when every level ran (the case may
 * still miss its tolerance: see r->pass); WL_EINPUT for a bad option or a
 * missing/bad reference file; WL_EUNSUPPORTED for backend "cuda" without a
 * usable GPU; WL_EIO, WL_ENOMEM. A level whose simulation
 * goes unstable is recorded (status, message), the case fails, and the
 * status returned is still WL_OK so the suite continues. */
enum wl_status wl_validate_run(int i, const struct wl_validate_opts *opts,
                               struct wl_validate_result *r, struct wl_error *err);

/* Write DIR/validation.json, DIR/validation.csv and DIR/validation.pdf
 * (error of the primary metric against runtime, log-log, one line per case,
 * and the tables), each written to a temporary name and renamed. DIR must
 * exist. Returns WL_OK, WL_EIO, WL_ENOMEM. */
enum wl_status wl_validate_write(const char *dir, const struct wl_validate_result *r, int n,
                                 struct wl_error *err);

#endif
