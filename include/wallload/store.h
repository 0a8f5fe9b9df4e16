/* store.h: results on disk, written so that nothing half-written is ever
 * left under the final name.
 *
 * Every file is written to "<path>.tmp" and renamed over <path> only when it
 * is complete (rename is atomic on POSIX file systems), so a crash, an
 * interruption or an unstable run leaves either the previous file or the new
 * complete one. Each file is synced to disk before the rename (and the
 * directory after it). A write the system refuses (a full disk, a file-size
 * limit, an I/O error) is WL_EIO with the final file's name and the
 * system's reason ("No space left on device"); the temporary file is then
 * removed and the previous file under the final name, if any, is kept.
 * Closing a file after a failed write cannot fail or crash (store.c says
 * how). HDF5 files hold datasets with a "unit" and a "description"
 * attribute each; particle snapshots come with an XDMF index that ParaView
 * opens (2D runs are written as (x, 0, z)). */
#ifndef WALLLOAD_STORE_H
#define WALLLOAD_STORE_H

#include <stddef.h>

#include "wallload/error.h"
#include "wallload/loads.h"

struct wl_store; /* an HDF5 file being written; opaque */

/* HDF5 as wallload uses it: the library's own error printing off (every
 * status is checked and reported with the file), and no exit handler (a
 * file the library failed to close can then never crash the exit). Called
 * by wl_store_open; readers of HDF5 files call it before their first
 * HDF5 call. Idempotent. */
void wl_store_hdf5_init(void);

/* 1 when the HDF5 library serialises its calls (a thread-safe build), so
 * that files may be written from several threads at once. */
int wl_store_thread_safe(void);

/* fsync the directory holding path, so that a rename in it reaches the
 * disk (best effort: the files themselves are synced before). */
void wl_store_sync_dir_of(const char *path);

/* Files written to their temporary names and moved into place together,
 * only when all of them were written: a failure on any one leaves every
 * previous file as it was. */
enum { WL_STORE_BATCH_MAX = 16 };
struct wl_store_batch {
  int n;
  char path[WL_STORE_BATCH_MAX][1024]; /* final names; each written as path.tmp */
};
void wl_store_batch_init(struct wl_store_batch *b);
/* Add path (its path.tmp written complete earlier, e.g. by a batch that
 * was not committed) to b. WL_EIO (and path.tmp removed) when b is full. */
enum wl_status wl_store_batch_add(struct wl_store_batch *b, const char *path,
                                  struct wl_error *err);
/* Rename every file of the batch into place (in the order added) and sync
 * the directory. WL_EIO when a rename fails (the files after it are
 * dropped). The batch is empty afterwards. */
enum wl_status wl_store_batch_commit(struct wl_store_batch *b, struct wl_error *err);
/* Remove every temporary file of the batch. */
void wl_store_batch_abort(struct wl_store_batch *b);

/* Create "<path>.tmp" for writing. Returns WL_OK and *out; WL_EIO (message
 * names the file and HDF5's reason). */
enum wl_status wl_store_open(const char *path, struct wl_store **out, struct wl_error *err);

/* Finish: close the file and, when `commit` is 1 and every write to it
 * succeeded, sync it and rename it to its final name; otherwise the
 * temporary file is removed (commit 0 returns WL_OK). Safe on NULL.
 * Returns WL_OK or WL_EIO. Always frees *store. */
enum wl_status wl_store_close(struct wl_store *store, int commit, struct wl_error *err);

/* Close a complete file into a batch (moved into place by
 * wl_store_batch_commit). On a failure (this close, or an earlier write)
 * the temporary file is removed and WL_EIO returned. Frees *store. */
enum wl_status wl_store_close_batch(struct wl_store *store, struct wl_store_batch *b,
                                    struct wl_error *err);

/* Push what is written so far to the file, so that a full disk is found
 * now rather than at the close (snapshots are flushed one by one). WL_EIO
 * names the file and the reason; the store is then failed (closing it
 * discards it). */
enum wl_status wl_store_flush(struct wl_store *store, struct wl_error *err);

/* Write a 1D double dataset `path` (groups created as needed, e.g.
 * "cases/solitary/gauges/G1/eta") with attributes unit and description. */
enum wl_status wl_store_write_vector(struct wl_store *store, const char *path, const double *data,
                                     size_t n, const char *unit, const char *description,
                                     struct wl_error *err);

/* Write a 2D row-major double dataset [rows x cols] (e.g. time x probe). */
enum wl_status wl_store_write_matrix(struct wl_store *store, const char *path, const double *data,
                                     size_t rows, size_t cols, const char *unit,
                                     const char *description, struct wl_error *err);

/* Write a 1D float dataset (particle fields). */
enum wl_status wl_store_write_vector_f(struct wl_store *store, const char *path, const float *data,
                                       size_t n, const char *unit, const char *description,
                                       struct wl_error *err);

/* Write a 2D row-major float dataset [rows x cols] (particle vectors). */
enum wl_status wl_store_write_matrix_f(struct wl_store *store, const char *path, const float *data,
                                       size_t rows, size_t cols, const char *unit,
                                       const char *description, struct wl_error *err);

/* Write a 1D int dataset (particle kinds, ids). */
enum wl_status wl_store_write_vector_i(struct wl_store *store, const char *path, const int *data,
                                       size_t n, const char *description, struct wl_error *err);

/* Attach a text attribute `name` to the object (group or dataset) at
 * `path`, creating the group if it does not exist ("" or "/" is the root). */
enum wl_status wl_store_attr_text(struct wl_store *store, const char *path, const char *name,
                                  const char *text, struct wl_error *err);

/* Attach a double attribute with a unit ("<name>" and "<name>_unit"). */
enum wl_status wl_store_attr_double(struct wl_store *store, const char *path, const char *name,
                                    double value, const char *unit, struct wl_error *err);

/* One particle snapshot for the XDMF index. */
struct wl_snapshot_ref {
  double time;   /* [s] */
  size_t n;      /* particles */
  char group[96];/* HDF5 group holding position (n x 3), velocity (n x 3), rho, p, dp, kind */
};

/* Write the XDMF index `xmf_path` (atomically) that refers to the snapshot
 * groups in `h5_name` (a file name relative to the XDMF file). */
enum wl_status wl_store_write_xdmf(const char *xmf_path, const char *h5_name,
                                   const struct wl_snapshot_ref *snaps, size_t n_snaps,
                                   struct wl_error *err);

/* wl_store_write_xdmf into batch b (written to xmf_path.tmp, moved at the
 * batch's commit). */
enum wl_status wl_store_write_xdmf_batch(const char *xmf_path, const char *h5_name,
                                         const struct wl_snapshot_ref *snaps, size_t n_snaps,
                                         struct wl_store_batch *b, struct wl_error *err);

/* A growing text buffer for the text files written below (CSV, JSON):
 * wl_text_put appends printf-style; when an allocation fails, `failed` is
 * set and later puts do nothing (the writer then reports WL_ENOMEM).
 * Zero-initialise; the caller frees s. */
struct wl_text {
  char *s;
  size_t len, cap;
  int failed;
};
void wl_text_put(struct wl_text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Write `text` to `path` atomically (temp file + fsync + rename); for JSON
 * and CSV. */
enum wl_status wl_store_write_text(const char *path, const char *text, size_t len,
                                   struct wl_error *err);

/* Write `text` to path.tmp (synced) and add it to batch b. */
enum wl_status wl_store_write_text_batch(const char *path, const char *text, size_t len,
                                         struct wl_store_batch *b, struct wl_error *err);

/* ---- results.h5: the schema, its writer and its reader ------------------------
 *
 * One table in src/store/results.c names every group, dataset and
 * attribute of results.h5 with its type, unit, description and whether it
 * is required: wl_store_results_write_* write from the structs below
 * through it, wl_store_results_read reads them back through it, so a key
 * has one owner. Layout (docs/outputs.md):
 *   /                      run: scenario name, file and text, version, backend,
 *                          threads, dp, report_template, length_unit,
 *                          convergence_asked
 *   /settings              the scenario's numerical settings as resolved
 *   /plan                  what assess planned: depth, density, gravity, the
 *                          flume drawn (wall, bed corners, gauges), notes
 *   /plan/solitary|explosion  each load case's derived initial conditions and
 *                          its initial free surface
 *   /cases/NAME            each case's series and attributes
 *   /convergence/NAME      each case's convergence ladder, one value a level
 * A struct member that is NAN (numbers) or "" (texts) reads "absent". */

enum {
  WL_RESULTS_CASE_SOLITARY = 0, /* index of each load case in wl_results.cases */
  WL_RESULTS_CASE_EXPLOSION = 1,
  WL_RESULTS_N_CASES = 2,
  WL_RESULTS_MAX_GAUGES = 40,
  WL_RESULTS_TEXT_MAX = 512,   /* bytes of a stored one-line text, with the NUL */
  WL_RESULTS_NOTES_MAX = 4096, /* bytes of the plan's notes, with the NUL */
  WL_RESULTS_MAX_LEVELS = 8,   /* convergence levels read per case */
  WL_RESULTS_MAX_SETTINGS = 32,
  WL_RESULTS_SURFACE_POINTS = 600, /* samples of a stored initial free surface */
  WL_RESULTS_MAX_BED = 34,     /* bed corners: the flume start, each segment, the toe */
};

/* Name of case index i ("solitary", "explosion"; "?" otherwise). */
const char *wl_store_results_case_name(int i);

struct wl_results_gauge {
  char name[64];
  double x;    /* [m]; NAN when not stored */
  double *eta; /* n samples [m] above still water (reader: owned) */
};

/* One load case under /cases/NAME. Series are NULL when not stored (an
 * older or damaged file); every stored series has the length n of `t`.
 * The writer reads the series from the caller's arrays; what the reader
 * allocates, wl_store_results_clear frees. */
struct wl_results_case {
  int present; /* 1: /cases/<name> exists */
  char name[32];
  char status[32];    /* "complete", "unstable", "interrupted", "failed" ("" not stored) */
  char stopped[2048]; /* why it stopped ("" when complete) */
  char caution[1024]; /* a caution about the result (late peak; "" when none) */
  double dp, h, c0, particles, fluid_particles, steps, runtime, end_time, time_reached;
  double cutoff;        /* low-pass cut-off of the filtered series [Hz] */
  double peaks_from;    /* peaks are searched from this time on [s] (assess.h) */
  double static_force;  /* [N/m] */
  double static_moment; /* [N m/m] */
  /* the model's force and moment at rest, measured over [rest_from,
   * rest_to] (assess.h); after reading, rest_force and rest_force_b are the
   * bases of the derived values: the static force where not measured or
   * not stored */
  double rest_force, rest_force_b, rest_moment, rest_from, rest_to;
  double wall_x, wall_toe_z, wall_crest_z, still_water_z; /* the modelled flume [m] */
  double width;                            /* 3D: the flume's width [m] (NAN in 2D) */
  char symmetry[16], side_walls[16];       /* 3D: "centreline"/"none", "free-slip"/"particles" */
  size_t n;                                /* samples */
  double *t;                               /* [s] */
  double *force, *force_f, *force_b, *force_bf; /* probes raw, filtered; boundary raw,
                                                   filtered [N/m] */
  double *impulse, *impulse_b;          /* [N s/m] */
  double *still_drift; /* the still-water reference's force drift [N/m]; NULL: none */
  double *moment, *moment_f, *moment_b; /* [N m/m] */
  double *kinetic, *potential;          /* [J/m] */
  double *momentum;                     /* fluid horizontal momentum [N s/m] */
  size_t n_probes;
  double *probe_z;  /* n_probes [m] above the flume floor */
  double *pressure; /* n x n_probes [Pa] */
  int n_gauges;
  struct wl_results_gauge gauges[WL_RESULTS_MAX_GAUGES]; /* reader: ordered by x */
  /* the loads assess computed (loads.h definitions, summary.json's
   * values), stored as case attributes and read back as they are; NAN when
   * the record is empty. The reader sets wall_gauge, filtered and the
   * peaks' index (the sample at their time). */
  int wall_gauge; /* index of the gauge named "wall" (run-up); -1 if none */
  int filtered;   /* 1: the filtered series are stored (the peaks are of them) */
  struct wl_peak force_peak;             /* of force_f (base: the force at rest) */
  struct wl_peak force_b_peak;           /* of force_bf */
  struct wl_peak moment_peak;            /* of moment_f (base: the moment at rest) */
  double impulse_total, impulse_b_total; /* last samples [N s/m] */
  double impulse_peak;                   /* of the force peak's positive phase [N s/m] */
  double impulse_positive, impulse_positive_b; /* probes, boundary particles (loads.h) [N s/m] */
  double impulse_peak_from, impulse_peak_to;   /* that phase [s] */
  double runup, runup_time; /* max eta of the wall gauge [m], when [s] */
  /* the still-water reference run (assess.h wl_case_loads): its drift's
   * largest magnitude [N/m] and the positive impulse with the drift left
   * in [N s/m]; NaN (not stored) without one */
  double still_drift_max, impulse_positive_uncorrected;
};

/* The convergence ladder of one case under /convergence/NAME (definitions
 * in include/wallload/assess.h), one value a level. Values NAN when absent. */
struct wl_results_convergence {
  int present;  /* 1: the group exists */
  int n_levels; /* levels stored (at most WL_RESULTS_MAX_LEVELS) */
  double factor[WL_RESULTS_MAX_LEVELS], dp[WL_RESULTS_MAX_LEVELS];       /* [-], [m] */
  double particles[WL_RESULTS_MAX_LEVELS], steps[WL_RESULTS_MAX_LEVELS]; /* counts */
  double runtime[WL_RESULTS_MAX_LEVELS], rate[WL_RESULTS_MAX_LEVELS];    /* [s], [1/s] */
  double time_reached[WL_RESULTS_MAX_LEVELS];                            /* [s] */
  double peak_force[WL_RESULTS_MAX_LEVELS], peak_force_b[WL_RESULTS_MAX_LEVELS]; /* [N/m] */
  double rest_force[WL_RESULTS_MAX_LEVELS]; /* the probes' force at rest [N/m] */
  double impulse[WL_RESULTS_MAX_LEVELS];       /* whole record [N s/m] */
  double impulse_phase[WL_RESULTS_MAX_LEVELS]; /* the peak's positive phase [N s/m] */
  double impulse_pos[WL_RESULTS_MAX_LEVELS];   /* the positive impulse [N s/m] */
  double peak_moment[WL_RESULTS_MAX_LEVELS];   /* [N m/m] */
  double runup[WL_RESULTS_MAX_LEVELS];         /* [m] */
  /* resolution.realisations: runs per level whose mean the loads above are,
   * and the spread over them (NaN from one run) */
  double realisations[WL_RESULTS_MAX_LEVELS];
  double peak_force_sd[WL_RESULTS_MAX_LEVELS], peak_force_min[WL_RESULTS_MAX_LEVELS];
  double peak_force_max[WL_RESULTS_MAX_LEVELS], impulse_pos_sd[WL_RESULTS_MAX_LEVELS];
  double error[WL_RESULTS_MAX_LEVELS]; /* estimated relative error of each level [-] */
  int status[WL_RESULTS_MAX_LEVELS];   /* 0 complete, else the run's failure code */
  double levels_planned, levels_run, ratio;
  double force_order, force_order_ok, force_extrapolated, force_error;
  double pos_order, pos_order_ok, pos_extrapolated, pos_error; /* positive impulse */
  /* the peak force less the force at rest (the wave's part) */
  double dyn_order, dyn_order_ok, dyn_extrapolated, dyn_error;
  double error_estimate, target, target_given, target_met, stopped_early;
  /* realisations: the finest mean's sampling uncertainty, relative, already
   * in the error estimates above (NaN, or absent in older files: one run) */
  double force_sampling, dyn_sampling, pos_sampling;
  char force_basis[32], pos_basis[32], dyn_basis[32]; /* wl_loads_estimate_name: "GCI", ... */
  char note[WL_RESULTS_TEXT_MAX];      /* how the ladder ended */
};

/* The level columns of a ladder in the schema's order (the HDF5 dataset
 * names; assess's summary.json and convergence.csv use the same names,
 * units and order): name, unit, description; the value of level l is
 * wl_store_results_level_value(cv, k, l). The last column is the status
 * (unit ""), an int per level. */
struct wl_results_column {
  const char *name, *unit, *description;
};
extern const struct wl_results_column wl_store_results_levels[];
extern const int wl_store_results_n_levels; /* columns in wl_store_results_levels */
double wl_store_results_level_value(const struct wl_results_convergence *cv, int column, int l);
/* Set level l's value of a column (not the status column). */
void wl_store_results_level_set(struct wl_results_convergence *cv, int column, int l, double v);

/* A solitary wave's initial conditions as planned, under /plan/solitary. */
struct wl_results_solitary {
  int present;
  char theory[64];  /* wl_waves_solitary_theory_text(theory, 0) */
  double H;         /* [m] */
  double K;         /* decay rate: eta ~ sech^2(K X) [1/m] */
  double celerity;  /* [m/s] */
  double energy_integrated, energy_first_order, energy_seed001; /* [J/m] */
  int paddle;       /* 1: Goring paddle; 0: initial condition */
  double paddle_stroke, paddle_duration; /* [m], [s] (paddle only) */
  double crest_x0;  /* initial crest [m] (initial condition only) */
  double arrival_time, x_left; /* [s], [m] */
  size_t n_surface; /* the initial free surface drawn: x [m], z above the floor
                       [m] (NAN where the bed is above it); 0 when none */
  double surface_x[WL_RESULTS_SURFACE_POINTS], surface_z[WL_RESULTS_SURFACE_POINTS];
};

/* An explosion's initial conditions as planned, under /plan/explosion. */
struct wl_results_explosion {
  int present;
  char source[64];       /* "charge weight", "crater energy", "energy of the solitary
                            wave", "crater size" */
  int sized_to_solitary; /* 1: the crater holds the solitary wave's energy */
  char basis[32];        /* "seed-001" or "per-width" (sized_to_solitary) */
  double matched_energy; /* [J/m per width in 2D, else J] */
  double charge;         /* TNT [kg] */
  double chain_r0, chain_eta0, hr, whalin_coef; /* Van Dorn / Whalin chain [m, m, m^2, -] */
  double crater_energy, chemical_energy;        /* [J] */
  double chain_wave_fraction, wave_fraction;    /* crater / chemical; its ceiling [-] */
  char shape[64];        /* wl_explosion_shape_name */
  double eta0, r0, x_center, extent; /* as simulated [m] */
  double energy, energy_quad;        /* closed form, quadrature [J/m in 2D, J in 3D] */
  double net_volume;                 /* [m^2/m in 2D, m^3 in 3D] */
  int conserves_mass;
  double arrival_time, x_left; /* [s], [m] */
  size_t n_surface;            /* as the solitary's */
  double surface_x[WL_RESULTS_SURFACE_POINTS], surface_z[WL_RESULTS_SURFACE_POINTS];
};

/* What assess planned, under /plan: what the report draws and quotes
 * besides the runs' records. */
struct wl_results_plan {
  int present; /* 1: /plan exists (results of this wallload on) */
  int dims;
  double depth, rho, g;     /* still water [m], water density [kg/m^3], gravity [m/s^2] */
  double wall_x, wall_toe_z, wall_crest_z; /* the scenario's wall [m] */
  double land_length;       /* land drawn behind the wall [m] */
  size_t n_bed;             /* corners of the bed from x = 0 to the wall's toe */
  double bed_x[WL_RESULTS_MAX_BED], bed_z[WL_RESULTS_MAX_BED];
  int n_gauges;             /* the scenario's gauges, in its order */
  char gauge_name[WL_RESULTS_MAX_GAUGES][64];
  double gauge_x[WL_RESULTS_MAX_GAUGES];
  char notes[WL_RESULTS_NOTES_MAX]; /* the plan's notes, one a line ("" when none) */
  struct wl_results_solitary solitary;
  struct wl_results_explosion explosion;
};

/* The numerical settings results.h5 holds under /settings, in the order
 * assess writes them and the report lists them: the scenario key (as the
 * scenario schema spells it) and the report's label. assess writes each
 * key's resolved value (scenario.h wl_scenario_value_of); the report reads
 * them by key: the names have this one owner. */
struct wl_results_setting_key {
  const char *key, *label;
};
extern const struct wl_results_setting_key wl_store_results_settings[];
extern const int wl_store_results_n_settings; /* rows of wl_store_results_settings */

/* One numerical setting under /settings: the scenario key, its value as
 * resolved, and whether the scenario gave it. */
struct wl_results_setting {
  char key[64];
  char value[160];
  int given;
};

/* results.h5 as a whole. */
struct wl_results {
  char path[1024]; /* reader: results.h5 as given */
  char dir[1024];  /* reader: its directory ("." when none) */
  char scenario_name[WL_RESULTS_TEXT_MAX], scenario_file[WL_RESULTS_TEXT_MAX], version[64],
      created[64], backend[64];
  char *scenario_text; /* "" when not stored (reader: owned) */
  size_t scenario_len;
  double threads, dp;
  char report_template[WL_RESULTS_TEXT_MAX]; /* scenario report.template ("" not given) */
  char length_unit[16];        /* the unit the scenario wrote its water depth in */
  char convergence_asked[256]; /* resolution.convergence as written, "[1, 0.71]"
                                  ("" not given) */
  int n_settings;
  struct wl_results_setting settings[WL_RESULTS_MAX_SETTINGS];
  struct wl_results_plan plan;
  int has_convergence; /* reader: 1 when a /convergence group exists */
  struct wl_results_convergence conv[WL_RESULTS_N_CASES]; /* per case index */
  struct wl_results_case cases[WL_RESULTS_N_CASES];
  int n_cases; /* reader: cases present */
};

/* Zero *r with every number absent (NAN). */
void wl_store_results_init(struct wl_results *r);
void wl_store_results_case_init(struct wl_results_case *c);
void wl_store_results_convergence_init(struct wl_results_convergence *cv);

/* Free what the reader allocated in *r and zero it (wl_store_results_init);
 * safe on an initialised or half-read *r. */
void wl_store_results_clear(struct wl_results *r);

/* The setting `key` of r, or NULL when not stored. */
const struct wl_results_setting *wl_store_results_setting(const struct wl_results *r,
                                                           const char *key);

/* Write r's root attributes, /settings and (when r->plan.present) /plan.
 * Returns WL_OK or WL_EIO / WL_ENOMEM (the store's messages). */
enum wl_status wl_store_results_write_run(struct wl_store *h5, const struct wl_results *r,
                                          struct wl_error *err);
/* Write case c under /cases/<c->name> (its series have c->n samples, the
 * gauges' eta included). */
enum wl_status wl_store_results_write_case(struct wl_store *h5, const struct wl_results_case *c,
                                           struct wl_error *err);
/* Write ladder cv (cv->n_levels levels) under /convergence/<name>. */
enum wl_status wl_store_results_write_convergence(struct wl_store *h5, const char *name,
                                                  const struct wl_results_convergence *cv,
                                                  struct wl_error *err);

/* Read results.h5 `path` into *r (initialised first), the stored loads
 * included. Returns WL_OK; WL_EINPUT (missing, a directory, not HDF5,
 * damaged, not a wallload results file, or a required key missing: the
 * message names the file and the key, and for a load that a file of an
 * earlier wallload lacks, says to run assess again); WL_EIO (a dataset that cannot be read); WL_ENOMEM. On
 * failure *r is left cleared. */
enum wl_status wl_store_results_read(const char *path, struct wl_results *r,
                                     struct wl_error *err);

/* ---- particle snapshots (particles_<case>.h5) --------------------------------- */

struct wl_results_snapshot_ref {
  char group[64]; /* "snapshots/0007" */
  double time;    /* [s] */
};

/* List the snapshots of particle file `path` in time order into *refs
 * (malloc'ed, free it) and *n. Returns WL_OK; WL_EINPUT when the file
 * cannot be opened (missing, truncated, damaged); WL_ENOMEM. On failure
 * *refs is NULL and *n 0. */
enum wl_status wl_store_snapshot_list(const char *path, struct wl_results_snapshot_ref **refs,
                                      size_t *n, struct wl_error *err);

/* Quantities a snapshot can be read as. */
enum wl_results_quantity { WL_RESULTS_Q_PRESSURE, WL_RESULTS_Q_SPEED, WL_RESULTS_Q_DENSITY };

/* Read snapshot `group` of `path`: x, z [m] (the position's first and last
 * columns), the quantity q of each particle, and its kind (0 fluid). The
 * arrays are malloc'ed (free them) with *n entries. Returns WL_OK,
 * WL_EINPUT (incomplete data), WL_EIO or WL_ENOMEM; on failure the arrays
 * are NULL and *n 0. */
enum wl_status wl_store_snapshot_read(const char *path, const char *group,
                                      enum wl_results_quantity q, double **x, double **z,
                                      double **value, int **kind, size_t *n,
                                      struct wl_error *err);

#endif
