/* assess.h: run every load case of a scenario and keep what the engineer
 * asked for: wave gauges, wall pressure, force (from pressure probes and
 * from the wall's boundary particles), moment, impulse, run-up, with
 * filtered series and peaks (definitions in loads.h), written to
 *
 *   DIR/results.h5            per case: time series with units, metadata
 *   DIR/summary.json          per case: peaks with units; the comparison
 *   DIR/<case>_wall.csv       time, force, impulse, moment (raw and filtered)
 *   DIR/<case>_gauges.csv     time, eta at each gauge
 *   DIR/particles_<case>.h5   particle snapshots, with
 *   DIR/particles_<case>.xmf  their XDMF index for ParaView
 *
 * Every file is written atomically. An unstable or interrupted case keeps
 * its results up to the stop, and its status says where and why it stopped;
 * the other cases still run (after an interruption, none does). After each
 * case the files above move into place together (the snapshots with the
 * results that describe them), and result files of the directory that the
 * new set lacks (a previous run's report.pdf, a case's CSV and snapshot
 * files) are removed, so the directory holds one run's files, never two
 * runs' mixed; report.pdf is then rendered again. A write the disk refuses
 * (WL_EIO: a full disk, a file-size limit) leaves the previous set as it
 * was (or, after an earlier case of the run moved its files into place,
 * that case's files and their report), and no temporary file.
 *
 * Convergence ladder. When the scenario has resolution.convergence (dp
 * factors, decreasing, e.g. [1, 0.71, 0.5]), every load case runs at each
 * level, coarse to fine, with dp_k = dp x factor_k (the scenario re-planned
 * at that spacing). The last level run is the case's main result, written
 * as without a ladder (series, snapshots, CSV, peaks). Per level the driver
 * keeps dp, particles, steps, runtime, particle-steps/s and the scalar loads
 * (peak force from the filtered probe and boundary-particle series, impulse,
 * peak moment, maximum run-up), and after each level estimates the
 * uncertainty of the peak force (probes) and of the positive impulse with
 * wl_loads_convergence (loads.h) from the last three levels run:
 *
 *   observed order p = ln((f1 - f2)/(f2 - f3)) / ln r (r = h1/h2 = h2/h3;
 *     with unequal ratios the general equation of loads.h),
 *   Richardson value f_ext = f3 + (f3 - f2)/(r^p - 1),
 *   uncertainty of the finest level: Roache's grid convergence index
 *     1.25 |f3 - f_ext| where 0.95 <= p < 2.05, with Eca & Hoekstra's
 *     bands outside it (the order capped at 2, or 3 x the range of the
 *     three values when they oscillate), relative to |f3|; with two
 *     levels 3 |f3 - f2| / (r^2 - 1).
 *
 * The case's estimate is the larger of the positive impulse's and that of
 * the peak force less the level's force at rest (force_dynamic). When
 * resolution.target_error is written in the scenario, refining stops once
 * that estimate (available from the second level on) is below the target; the levels not run are listed as skipped. Without it the
 * whole ladder runs and the estimate is compared with the default target
 * (5 %). Stored in results.h5 under /convergence/<case>/, in summary.json
 * (cases.<case>.convergence) and in convergence.csv. */
#ifndef WALLLOAD_ASSESS_H
#define WALLLOAD_ASSESS_H

#include <pthread.h>
#include <signal.h>

#include "wallload/error.h"
#include "wallload/flume.h"
#include "wallload/loads.h"
#include "wallload/plan.h"
#include "wallload/sample.h"
#include "wallload/scenario.h"
#include "wallload/sph.h"
#include "wallload/store.h"

/* Post-processed series and peaks of one case (computed from its record). */
struct wl_case_loads {
  double cutoff;            /* low-pass cut-off [Hz] */
  double *force_filtered;   /* [N/m] */
  double *moment_filtered;  /* [N m/m] */
  double *force_bound_filtered;
  double *impulse;          /* int (F - F_rest) dt from the probes, raw force [N s/m] */
  double *impulse_bound;    /* the same from the boundary particles [N s/m] */
  struct wl_peak force_peak, moment_peak, force_bound_peak; /* of the filtered series */
  /* The model's force (and moment) at rest, the base of every net
   * quantity here (loads.h): the raw series' means over the rest window
   * [rest_from, rest_to]; rest_measured 0 (no rest window) leaves the
   * nominal static_force and static_moment in them. */
  int rest_measured;
  double rest_from, rest_to;                   /* [s]; NaN when not measured */
  double rest_force, rest_force_bound;         /* probes, boundary particles [N/m] */
  double rest_moment;                          /* probes [N m/m] */
  double impulse_total;     /* [N s/m] at the end of the record */
  double impulse_peak;      /* of the peak force's positive phase (loads.h), probes [N s/m] */
  double impulse_positive;  /* int max(0, F_filtered - F_rest) dt from peak_from on, probes
                               (loads.h wl_loads_positive_impulse) [N s/m] */
  double impulse_positive_bound; /* the same from the boundary particles [N s/m] */
  /* How far the force at rest is fixed by its window, and what that does
   * to the positive impulse (loads.h wl_loads_halves_spread, probes; times
   * wl_loads_time_above) [N/m], [N s/m]; NaN without a rest window */
  double rest_force_spread, impulse_positive_rest_error;
  double impulse_peak_from, impulse_peak_to; /* that phase [s] */
  /* The still-water reference run's drift (plan.h), when the case has one:
   * its filtered wall force less its own force at rest, per sample [N/m]
   * (probes; drift_bound: boundary particles; drift_moment: the moment
   * [N m/m]); NULL when none. The filtered series above are the case's
   * less it, and every peak and impulse here is taken from them (the
   * impulses' raw force less the force at rest and the drift): the wave's
   * load on a wall whose still water stays still. drift_max: its largest
   * magnitude from peak_from on; impulse_positive_uncorrected: the
   * positive impulse without it, to show what it took out. NaN when none. */
  double *drift, *drift_bound, *drift_moment;
  double drift_max, impulse_positive_uncorrected;
  double runup;             /* max eta at the wall face [m] */
  double runup_time;        /* [s] */
  /* Runs the scalar loads above are the mean of (resolution.realisations
   * of a ladder's explosion: the finest level's, wl_assess_level), 1 for a
   * single run; the series and the peaks' times stay the first's */
  int realisations;
};

struct wl_case_result {
  enum wl_load_case load;
  /* The case's still-water reference run (plan.h), NULL when none ran;
   * still_owned: this result ran it and clears it */
  struct wl_case_result *still;
  int still_owned;
  int still_run; /* this result is itself a still-water reference run */
  char name[32];
  enum wl_status status;    /* WL_OK, WL_EUNSTABLE, WL_EINTERRUPTED, or a setup error */
  char message[WL_ERROR_MSG_MAX]; /* why it stopped, when not WL_OK */
  double t_end;             /* planned [s] */
  double output_dt;         /* sampling interval [s] */
  double t_reached;         /* [s] */
  long steps;
  long n_limited;           /* wall-limiter corrections (sph/guard.h wl_sph_wall_limit) */
  long n_excluded;          /* fluid particles that left the domain box (wl_sph_exclude) */
  double runtime_s;         /* wall-clock [s] */
  int n_particles, n_fluid;
  double dp, h, c0;
  /* resolution.refine (vres.h): the coarse level's spacing (0: one level),
   * the interface [m], and the relative change of the water the two levels
   * own from the start to the end of the run (the flux points exchange
   * water between them without conserving it exactly) */
  double dp_coarse, x_interface, water_change;
  double static_force, static_moment, depth_wall; /* at rest [N/m], [N m/m], [m] */
  /* Peaks (and their rise time and duration) are searched from peak_from
   * [s] on: half the plan's estimate of when the wave reaches the wall
   * (the solitary crest, the explosion's leading wave). Before then only
   * the start-up's acoustic ringing loads the wall (seawall.yaml's
   * explosion: 30 N/m at t = 0.02 s against a 17.7 N/m static force, with
   * its wave arriving at 5.8 s). The impulse runs over the whole record. */
  double peak_from;
  double quiet_until;       /* the plan's: the wall at rest until then [s] (plan.h) */
  /* Cautions about the result, "; "-separated, empty when there is none
   * (case_caution in assess.c): the peak force came in the last tenth of
   * the record (a larger load may follow); the still-water reference did
   * not join; the force at rest leaves the positive impulse uncertain; an
   * explosion's run-up at the wall is too few particles high. */
  char caution[1024];
  struct wl_flume flume;    /* geometry, probes, gauges */
  struct wl_record rec;      /* the sampled series (sample.h) */
  struct wl_case_loads loads;
  /* wl_assess_run's particle snapshots move into place with the results
   * that describe them: bit 0 (1) particles_<case>.h5.tmp and bit 1 (2)
   * particles_<case>.xmf.tmp are written complete and waiting; bits 2 and 3
   * (4, 8) say the same files were moved into place by this run. */
  int snapshot_files;
};

/* A case's caution names the force at rest when it alone leaves the
 * positive impulse uncertain by more than this share (wl_case_loads
 * impulse_positive_rest_error): a wave that lifts the wall's force by a
 * few per cent of a deep water's force at rest (seawall3d.yaml: 3 %) [-]. */
#define WL_ASSESS_REST_CAUTION 0.10

/* An explosion's caution names the spacing when the run-up its waves raise
 * at the wall is fewer than this many particles high: its short waves then
 * lose height on the way at that spacing, and the ladder can converge
 * smoothly to a wrong value. Each run's own run-up, measured on
 * seawall.yaml's flume (2026-11-28, H200; docs/history/2026-11-28-sensors-
 * and-crests.md): its explosion at dp = 0.012 m raises 1.9 particles (the
 * 2-core ladder's finest level, whose positive impulse read 27 % under the
 * GPU ladder's, outside its band), at 0.0043 m 10.7 (converged); a 0.083 g
 * charge at 3.5 particles still gained 20 % on its last refinement, a
 * 0.664 g charge gained 0.7 % from 3.6 to 6.3. The threshold sits above
 * the worst case seen unconverged, with a margin [-]. */
#define WL_ASSESS_EXPLOSION_RUNUP_PPH_MIN 6.0

enum { WL_ASSESS_MAX_LEVELS = WL_SCENARIO_MAX_LEVELS };

/* One level of a convergence ladder: the run and its scalar loads. */
struct wl_assess_level {
  double factor;            /* of the scenario's dp [-] */
  double dp;                /* [m] */
  enum wl_status status;    /* of the run (WL_OK: complete) */
  int n_particles;          /* fluid and boundary */
  long steps;
  double runtime_s;         /* wall-clock [s] */
  double rate;              /* particle-steps per second [1/s] */
  double t_reached;         /* [s] */
  double peak_force;        /* filtered, pressure probes [N/m] */
  double peak_force_bound;  /* filtered, boundary particles [N/m] */
  double rest_force;        /* the probes' force at rest, the model's [N/m] (assess.h
                               wl_case_loads.rest_force) */
  double impulse;           /* int (F - F_static) dt, probes, whole record [N s/m] */
  double impulse_phase;     /* the same over the peak's positive phase (loads.h) [N s/m] */
  double impulse_positive;  /* int max(0, F_filtered - F_rest) dt, probes (loads.h) [N s/m] */
  double peak_moment;       /* filtered, about the toe [N m/m] */
  double runup;             /* max water level at the wall above still water [m] */
  double impulse_positive_bound; /* as impulse_positive, boundary particles [N s/m] */
  /* resolution.realisations (plan.h): the loads above are the mean of the
   * level's complete realisations, `realisations` of them; the spread of
   * the peak force (probes) and of the positive impulse is their sample
   * standard deviation (NaN from one), and the least and largest peak */
  int realisations;
  double peak_force_sd, peak_force_min, peak_force_max, impulse_positive_sd;
  double impulse_positive_uncorrected; /* the mean of its runs' (wl_case_loads), NaN: none */
  double peak_force_dynamic_sd; /* of peak_force - rest_force over the realisations */
  double error;             /* estimated relative error of this level: the larger of the peak
                               force's part above the force at rest and the positive impulse,
                               |f_k - f_ref|/|f_ref| with f_ref the
                               Richardson value when the order is meaningful, else the
                               finest level run; the finest level gets the case's uncertainty */
};

/* The ladder of one load case. */
struct wl_assess_convergence {
  int n_planned;            /* levels in the scenario (0: no ladder) */
  int n_levels;             /* levels run */
  struct wl_assess_level lv[WL_ASSESS_MAX_LEVELS];
  /* of the peak force (probes) and of the positive impulse: the net impulse
   * of an oscillating wave train is too small a difference to converge, and
   * the peak's positive phase changes crest between resolutions (loads.h
   * wl_loads_positive_impulse) */
  struct wl_loads_convergence force, impulse_pos;
  /* of the peak force less the force at rest, the wave's part: where the
   * wave lifts a large force at rest a little (deep water), the peak force's
   * relative uncertainty is small beside it, and that part is what the
   * resolution decides (docs/convergence.md) */
  struct wl_loads_convergence force_dynamic;
  /* With realisations, the finest complete level's means are uncertain by
   * their sampling (loads.h wl_loads_mean_uncertainty), relative: of the
   * peak force, its part above the force at rest and the positive impulse;
   * each is already added to the band above it (force, force_dynamic,
   * impulse_pos .error). NaN with one run a level. */
  double force_sampling, dynamic_sampling, impulse_sampling;
  double error_estimate;    /* max(force_dynamic.error, impulse_pos.error) [-]; NaN: none */
  double target;            /* resolution.target_error [-] (its default when not given) */
  int target_given;         /* 1: written in the scenario: the ladder may stop early */
  int target_met;           /* error_estimate <= target */
  int stopped_early;        /* 1: target met before the last level */
  char note[320];           /* one sentence: how the ladder ended */
};

struct wl_assess_result {
  int n_cases;
  struct wl_case_result cases[2];
  struct wl_assess_convergence conv[2]; /* per case; n_planned 0 without a ladder */
  char out_dir[512];
  char backend[32];
  int threads;
};

/* Progress of a running case: case_name is the case ("solitary"), or with a
 * ladder the case and its level ("solitary, level 2/3, dp = 0.0141 m"). */
typedef void (*wl_assess_progress_fn)(void *user, const char *case_name,
                                      const struct wl_sph_progress *pr);

struct wl_assess_opts {
  const char *out_dir;       /* NULL: "<scenario name>-results" in the current directory */
  int force;                 /* 1: write into an existing directory */
  int threads;               /* 0: the scenario's run.threads */
  const char *backend;       /* NULL: the scenario's run.backend; else "cpu", "cuda", "auto" */
  double snapshot_interval;  /* [s]; <= 0: a twentieth of each case's end time */
  double end_time;           /* > 0: override every case's end time [s] (tests) */
  volatile sig_atomic_t *interrupted; /* the CLI's stop flag: the signal's number (SIGINT,
                                         SIGTERM, SIGHUP) once one came, else 0; may be NULL */
  wl_assess_progress_fn progress;     /* may be NULL */
  void *user;
  /* For runs that keep only the loads (`wallload sweep`); neither changes
   * what is computed. */
  int no_snapshots;          /* 1: write no particle snapshots */
  int no_report;             /* 1: render no report.pdf (`wallload report DIR/results.h5` can) */
  /* When not NULL, held while the results are written. HDF5 (Debian's
   * build) is not thread-safe: a caller that runs cases in threads (the
   * sweep's cases side by side on a GPU) shares one lock among them and its
   * own HDF5 writing. Needs no_snapshots (snapshots are written while
   * stepping) and no_report. */
  pthread_mutex_t *write_lock;
};

/* Run all load cases and write the outputs. Returns WL_OK when every case
 * completed; WL_EUNSTABLE or WL_EINTERRUPTED when one stopped early (its
 * files are written all the same; err says which case, where and why);
 * WL_EINPUT when the output directory exists and force is 0, or a case
 * cannot be built; WL_EIO, WL_ENOMEM. res holds what was computed; free it
 * with wl_assess_result_clear. */
enum wl_status wl_assess_run(const struct wl_scenario *s, const struct wl_plan *plan,
                             const struct wl_assess_opts *opts, struct wl_assess_result *res,
                             struct wl_error *err);

void wl_assess_result_clear(struct wl_assess_result *res);

/* Take the writer's lock of directory `dir` (which must exist), as
 * wl_assess_run does for its output directory: DIR/.wallload.lock, created
 * exclusively, holds this process's id; `lock` (size bytes) gets its path,
 * to unlink when done. A lock whose process is gone is taken over, and the
 * temporary files its killed writer left in dir (*.tmp, *.part) are
 * removed. Returns WL_OK; WL_EINPUT when a live process holds it (the
 * message names it); WL_EIO. */
enum wl_status wl_assess_lock_dir(const char *dir, char *lock, size_t size, struct wl_error *err);

/* How messages name a stop signal: "SIGTERM", "SIGHUP", "the user (SIGINT)". */
const char *wl_assess_stop_signal_name(int sig);

/* The machine wl_assess_run would run s on with opts: the GPU and its
 * memory when it picks the CUDA backend, the host's physical memory, the
 * CPU threads, and the default runtime budget (WL_PLAN_BUDGET_DEFAULT_S).
 * Backend cuda without a GPU is described as the CPU (the run itself then
 * refuses it, saying why). */
void wl_assess_machine(const struct wl_scenario *s, const struct wl_assess_opts *opts,
                       struct wl_plan_machine *m);

/* Build and run one load case (WL_CASE_STILL included) without writing
 * anything: for tests and the validation suite. `snapshots` (may be NULL)
 * names an HDF5 file for particle snapshots. c is filled as in
 * wl_assess_run (record and loads); free it with wl_assess_case_clear.
 * Returns the run's status (WL_EUNSTABLE keeps the record so far). */
enum wl_status wl_assess_case(const struct wl_scenario *s, const struct wl_plan *plan,
                              enum wl_load_case load, const struct wl_assess_opts *opts,
                              const char *snapshots, struct wl_case_result *c,
                              struct wl_error *err);

void wl_assess_case_clear(struct wl_case_result *c);

/* The part of results.h5 that scenario s and its plan decide (store.h):
 * the scenario's name, file, text (r->scenario_text points at s->text, not
 * owned), dp, report template, length unit and convergence levels as
 * written; /settings (the numerical settings as resolved); /plan (depth,
 * density, gravity, the flume as drawn, the notes, each case's derived
 * initial conditions and initial free surface). *r is initialised first;
 * the run's own keys (version, created, backend, threads) are the caller's. */
void wl_assess_results_plan(const struct wl_scenario *s, const struct wl_plan *plan,
                            struct wl_results *r);

/* A solitary wave's initial free surface is stored over +-this/K about its
 * crest (sech^2(6) ~ 2.5e-5 of its height). */
#define WL_ASSESS_SOLITARY_HALF 6.0

/* This machine's CPU speed now against the reference machine the plan
 * prices with (plan.h WL_PLAN_CPU_SPEED_RATE), timing a small still-water
 * flume on `threads` threads (src/assess/speed.c; about 0.2 s). The
 * environment's WL_CPU_SPEED, when set, is returned instead (tests). NAN
 * when the flume cannot be run (err says why). */
double wl_assess_cpu_speed(int threads, struct wl_error *err);

#endif
