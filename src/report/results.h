/* results.h: what the report reads back from an assessment (private to
 * src/report): results.h5 (layout in src/assess/output.c and README.md),
 * the particle snapshots particles_<case>.h5 beside it, the scenario stored
 * in it re-parsed and re-planned, and the peaks recomputed from the stored
 * series with the definitions of loads.h (so the report needs nothing but
 * results.h5). Also the SHA-256 of the scenario text (FIPS 180-4), the
 * report's input digest.
 *
 * HDF5 is read with its automatic error printing off; nothing prints. */
#ifndef WALLLOAD_REPORT_RESULTS_H
#define WALLLOAD_REPORT_RESULTS_H

#include <stddef.h>
#include <stdint.h>

#include "wallload/error.h"
#include "wallload/loads.h"
#include "wallload/plan.h"
#include "wallload/scenario.h"

enum {
  WL_REPORT_CASE_SOLITARY = 0, /* index of each load case in wl_report_results.cases */
  WL_REPORT_CASE_EXPLOSION = 1,
  WL_REPORT_N_CASES = 2,
  WL_REPORT_MAX_GAUGES = 40,
  WL_REPORT_ATTR_MAX = 512, /* bytes of a stored one-line text, with the NUL */
};

/* Name of case index i ("solitary", "explosion"). */
const char *wl_report_case_name(int i);

struct wl_report_gauge {
  char name[64];
  double x;    /* [m]; NAN when not stored */
  double *eta; /* n samples [m] above still water; owned */
};

/* One load case as stored, and what the report derives from it. Series are
 * NULL when not stored (an older or damaged file); every stored series has
 * the length n of `time`. */
struct wl_report_case {
  int present; /* 1: /cases/<name> exists */
  char name[32];
  char status[32];    /* "complete", "unstable", "interrupted", "failed" ("" not stored) */
  char stopped[2048]; /* why it stopped ("" when complete) */
  char caution[512];  /* a caution about the result (late peak; "" when none) */
  /* scalar attributes (NAN when absent) */
  double dp, h, c0, particles, fluid_particles, steps, runtime, end_time, time_reached;
  double cutoff;        /* low-pass cut-off of the filtered series [Hz] */
  double peaks_from;    /* peaks are searched from this time on [s] (assess.h; 0 when absent) */
  double static_force;  /* [N/m] */
  double static_moment; /* [N m/m] */
  /* the model's force and moment at rest, measured over [rest_from,
   * rest_to] (assess.h); rest_force and rest_force_b are the bases of the
   * derived values: the static force where not measured or not stored
   * (rest_from NAN then) */
  double rest_force, rest_force_b, rest_moment, rest_from, rest_to;
  double wall_x, wall_toe_z, wall_crest_z, still_water_z; /* [m] */
  size_t n;                                               /* samples */
  double *t;                                              /* [s] */
  double *force, *force_f, *force_b,
      *force_bf;                        /* probes raw, filtered; boundary raw, filtered [N/m] */
  double *impulse, *impulse_b;          /* [N s/m] */
  double *moment, *moment_f, *moment_b; /* [N m/m] */
  double *kinetic, *potential;          /* [J/m] */
  size_t n_probes;
  double *probe_z;  /* n_probes [m] above the flume floor */
  double *pressure; /* n x n_probes [Pa] */
  int n_gauges;
  struct wl_report_gauge gauges[WL_REPORT_MAX_GAUGES];
  int wall_gauge; /* index of the gauge named "wall" (run-up); -1 if none */
  /* derived (loads.h definitions; NAN / index 0 when the record is empty) */
  int filtered; /* 1: peaks from the stored filtered series; 0: from raw (no filtered) */
  struct wl_peak force_peak;             /* of force_f (base: the force at rest) */
  struct wl_peak force_b_peak;           /* of force_bf */
  struct wl_peak moment_peak;            /* of moment_f (base: the moment at rest) */
  double impulse_total, impulse_b_total; /* last samples [N s/m] */
  double impulse_peak;                   /* of the force peak's positive phase [N s/m] */
  double impulse_positive, impulse_positive_b; /* probes, boundary particles (loads.h) [N s/m] */
  double impulse_peak_from, impulse_peak_to; /* that phase [s] */
  double runup, runup_time;              /* max eta of the wall gauge [m], when [s] */
};

enum { WL_REPORT_MAX_LEVELS = 8 }; /* convergence levels read per case */

/* The convergence ladder of one case as stored under /convergence/<case>/
 * (definitions in include/wallload/assess.h). Values NAN when absent. */
struct wl_report_convergence {
  int present;  /* 1: the group exists */
  int n_levels; /* levels stored (at most WL_REPORT_MAX_LEVELS) */
  double factor[WL_REPORT_MAX_LEVELS], dp[WL_REPORT_MAX_LEVELS];         /* [-], [m] */
  double particles[WL_REPORT_MAX_LEVELS], steps[WL_REPORT_MAX_LEVELS];   /* counts */
  double runtime[WL_REPORT_MAX_LEVELS], rate[WL_REPORT_MAX_LEVELS];      /* [s], [1/s] */
  double peak_force[WL_REPORT_MAX_LEVELS], peak_force_b[WL_REPORT_MAX_LEVELS]; /* [N/m] */
  double impulse[WL_REPORT_MAX_LEVELS];       /* whole record [N s/m] */
  double impulse_phase[WL_REPORT_MAX_LEVELS]; /* the peak's positive phase [N s/m] */
  double impulse_pos[WL_REPORT_MAX_LEVELS];   /* the positive impulse [N s/m] */
  double peak_moment[WL_REPORT_MAX_LEVELS];                              /* [N m/m] */
  double runup[WL_REPORT_MAX_LEVELS];                                    /* [m] */
  double error[WL_REPORT_MAX_LEVELS];   /* estimated relative error of each level [-] */
  int status[WL_REPORT_MAX_LEVELS];     /* 0 complete, else the run's failure code */
  /* attributes */
  double levels_planned, ratio;
  double force_order, force_order_ok, force_extrapolated, force_error;
  double pos_order, pos_order_ok, pos_extrapolated, pos_error; /* positive impulse */
  double error_estimate, target, target_given, target_met, stopped_early;
  char force_basis[32], pos_basis[32]; /* wl_loads_estimate_name: "GCI", "3 x range", ... */
  char note[WL_REPORT_ATTR_MAX];           /* how the ladder ended */
};

/* Everything the report reads. */
struct wl_report_results {
  char path[1024]; /* results.h5 as given */
  char dir[1024];  /* its directory ("." when none) */
  char scenario_name[WL_REPORT_ATTR_MAX], scenario_file[WL_REPORT_ATTR_MAX], version[64],
      created[64], backend[64];
  char *scenario_text; /* owned; "" when not stored */
  size_t scenario_len;
  char digest[65];     /* SHA-256 of scenario_text, lower-case hex */
  double threads, dp;  /* root attributes (NAN when absent) */
  int has_convergence; /* 1: a /convergence group exists */
  struct wl_report_convergence conv[WL_REPORT_N_CASES]; /* per case index */
  struct wl_report_case cases[WL_REPORT_N_CASES];
  int n_cases; /* cases present */
  /* the stored scenario, re-parsed and re-planned */
  int have_scenario, have_plan;
  struct wl_scenario scenario;          /* valid when have_scenario */
  struct wl_plan plan;                  /* valid when have_plan */
  char scenario_note[WL_ERROR_MSG_MAX]; /* why they are missing ("" when present) */
};

/* Zero *r (safe to clear afterwards). */
void wl_report_results_init(struct wl_report_results *r);

/* Free what *r owns and zero it; safe on a zeroed or half-loaded *r. */
void wl_report_results_clear(struct wl_report_results *r);

/* Read results.h5 `path` into *r (cleared first), re-parse and re-plan the
 * stored scenario (failure there is a note, not an error), and derive the
 * peaks. Returns WL_OK; WL_EIO (cannot open or read: the message names the
 * file and object); WL_EINPUT (not a wallload results file: no
 * scenario_name attribute and no /cases group); WL_ENOMEM. On failure *r is
 * left cleared. */
enum wl_status wl_report_results_load(const char *path, struct wl_report_results *r,
                                      struct wl_error *err);

/* ---- particle snapshots --------------------------------------------------- */

struct wl_report_snapshot_ref {
  char group[64]; /* "snapshots/0007" */
  double time;    /* [s] */
};

/* List the snapshots of particle file `path` in time order into *refs
 * (malloc'ed, free it) and *n. Returns WL_OK; WL_EIO when the file cannot
 * be opened or read (a missing file is WL_EIO with "cannot open");
 * WL_ENOMEM. On failure *refs is NULL and *n 0. */
enum wl_status wl_report_snapshot_list(const char *path, struct wl_report_snapshot_ref **refs,
                                       size_t *n, struct wl_error *err);

/* Quantities a snapshot can be coloured by. */
enum wl_report_quantity { WL_REPORT_Q_PRESSURE, WL_REPORT_Q_SPEED, WL_REPORT_Q_DENSITY };

/* Read snapshot `group` of `path`: x, z [m] (the position's first and last
 * columns), the quantity q of each particle, and its kind (0 fluid). The
 * arrays are malloc'ed (free them) with *n entries. Returns WL_OK, WL_EIO or
 * WL_ENOMEM; on failure the arrays are NULL and *n 0. */
enum wl_status wl_report_snapshot_read(const char *path, const char *group,
                                       enum wl_report_quantity q, double **x, double **z,
                                       double **value, int **kind, size_t *n, struct wl_error *err);

/* ---- SHA-256 (FIPS 180-4) -------------------------------------------------- */

/* Digest of len bytes at data into out[32]. */
void wl_report_sha256(const void *data, size_t len, uint8_t out[32]);

/* The same as 64 lower-case hex digits and a NUL into hex[65]. */
void wl_report_sha256_hex(const void *data, size_t len, char hex[65]);

#endif
