/* sweep.h: a parameter sweep of a scenario (`wallload sweep`).
 *
 * A scenario with a `sweep:` section (scenario.h) stands for every
 * combination of its swept values: charge weight or energy, standoff of the
 * explosion from the wall, water depth, solitary-wave height. Each
 * combination is one case: the scenario's own text with the swept keys'
 * values replaced in place (loads.explosion.charge or .energy, .at =
 * wall.x - standoff in m to 12 significant digits, water.depth,
 * loads.solitary.height; a range's values are also written to 12
 * significant digits) and the sweep
 * section commented out, line for line, so that the case's text is a
 * scenario `wallload assess` runs alone with the same results (bit for bit
 * on one backend), and its error messages point at the lines of the sweep's
 * file. Each case runs through wl_assess_run into DIR/cases/<id>/ (no
 * particle snapshots, no report.pdf), and its loads become one row of
 *
 *   DIR/sweep.csv    one row per case: inputs, loads, uncertainty, runtime, status
 *   DIR/sweep.h5     the same as datasets with units, and every case's text
 *   DIR/sweep.pdf    envelopes (report.h wl_report_sweep_render)
 *
 * Resuming. A finished case leaves DIR/cases/<id>/sweep-case.txt (written
 * atomically after its results) with the digest of its inputs (the case's
 * text, the backend, an --end-time override, the wallload version) and its
 * row. A later sweep into DIR reads such a case back instead of running it
 * when the digest matches and its results are there; a case that was
 * interrupted, failed to run, or whose inputs changed runs again. sweep.csv
 * and sweep.h5 are rewritten after every case. */
#ifndef WALLLOAD_SWEEP_H
#define WALLLOAD_SWEEP_H

#include <stddef.h>

#include "wallload/assess.h"
#include "wallload/error.h"
#include "wallload/scenario.h"

enum { WL_SWEEP_N_LOADS = 2 }; /* per case: 0 solitary, 1 explosion */

/* The loads of one load case of one sweep case (summary.json's values). */
struct wl_sweep_loads {
  int present;                      /* the scenario has this load case */
  enum wl_status status;            /* its run's status */
  double peak_force;                /* filtered, pressure probes [N/m] */
  double peak_force_boundary;       /* filtered, boundary particles [N/m] */
  double impulse_positive;          /* the quoted impulse, probes [N s/m] */
  double impulse_positive_boundary; /* the same, boundary particles [N s/m] */
  double impulse;                   /* net, whole record, probes [N s/m] */
  double impulse_positive_phase;    /* the peak's positive phase, probes [N s/m] */
  double peak_moment;               /* filtered, about the toe [N m/m] */
  double max_runup;                 /* [m] */
  double uncertainty;               /* the ladder's error_estimate (assess.h): the larger of
                                       uncertainty_impulse and that of the peak force less the
                                       force at rest [-]; NaN: none */
  double uncertainty_force;         /* of peak_force [-] */
  double uncertainty_impulse;       /* of impulse_positive [-] */
};

enum wl_sweep_state {
  WL_SWEEP_PENDING, /* not run (yet) */
  WL_SWEEP_RAN,     /* run by this sweep */
  WL_SWEEP_REUSED,  /* read back from an earlier sweep's case directory */
};

struct wl_sweep_row {
  enum wl_sweep_state state;
  enum wl_status status;            /* the case's: WL_OK when every load case completed */
  char message[512];                /* why not, when not WL_OK */
  double runtime_s;                 /* wall clock of the case's run [s] */
  int rank;                         /* the MPI rank that ran it (0 without MPI) */
  struct wl_sweep_loads load[WL_SWEEP_N_LOADS];
};

struct wl_sweep_case {
  char id[128];                     /* "NNN_<param><value>...": its directory under DIR/cases */
  char value_text[WL_SWEEP_N_PARAMS][128]; /* as written into the case ("" where not swept) */
  double value[WL_SWEEP_N_PARAMS];  /* SI (standoff: from the wall); NaN where not swept */
  char *text;                       /* the case's scenario text; owned */
  size_t len;
};

/* Cases a sweep runs at once on a GPU (at most; within half its memory). */
#define WL_SWEEP_SIDE_BY_SIDE_MAX 16

struct wl_sweep {
  char path[512];                   /* the sweep's scenario file */
  char name[128];                   /* its scenario name */
  int n_params;
  enum wl_sweep_param order[WL_SWEEP_N_PARAMS]; /* as written; the first varies slowest */
  int has_load[WL_SWEEP_N_LOADS];
  int n_cases;
  struct wl_sweep_case *cases;      /* n_cases; owned */
  struct wl_sweep_row *rows;        /* n_cases; owned; filled by wl_sweep_run */
  int side_by_side;                 /* cases wl_sweep_run runs at once (GPU); 1: one at a time */
};

/* Zero sw (safe to _clear). */
void wl_sweep_init(struct wl_sweep *sw);
/* Free what sw owns and zero it; safe on a zeroed or half-made sweep. */
void wl_sweep_clear(struct wl_sweep *sw);

/* Make every case of s (which must have a sweep section) and check that each
 * one is a valid scenario. A value that makes the scenario invalid on its
 * own is WL_EINPUT at that value ("FILE:LINE:COL: sweep.depth[2]: ... gives
 * an invalid scenario: <why, with its own position>"); a combination that
 * does, at the sweep key. Also WL_ENOMEM; WL_EINPUT when the file is not a
 * block mapping (the text cannot be edited in place). On failure sw is
 * half-made: clear it. */
enum wl_status wl_sweep_make(const struct wl_scenario *s, struct wl_sweep *sw,
                             struct wl_error *err);

/* Parse case i's text into cs (its path the sweep's, so that messages and
 * the report template's lookup are the sweep file's). */
enum wl_status wl_sweep_case_scenario(const struct wl_sweep *sw, int i, struct wl_scenario *cs,
                                      struct wl_error *err);

/* "charge = 0.5 g, standoff = 2 m": case i's values as written. */
void wl_sweep_case_label(const struct wl_sweep *sw, int i, char *buf, size_t size);

/* ---- MPI: `mpirun -np N wallload sweep` (docs/sweep-mpi.md) --------------------- */

/* This process among the sweep's processes. Without MPI (or without an MPI
 * launcher) one process: rank 0 of size 1. */
struct wl_sweep_ranks {
  int rank, size;               /* in the job */
  int local_rank, local_size;   /* among the job's ranks on this host */
  int threads;                  /* CPU threads a rank's case gets by default: this host's
                                   cores divided among its ranks, at most the cores the
                                   rank may run on (its binding) */
  char host[64];                /* this host's name */
  char gpu[64];                 /* the GPU given to this rank (CUDA_VISIBLE_DEVICES as
                                   set for it); "" when none was chosen here */
  double silence_s;             /* rank 0 counts a rank lost after this long without a
                                   word from it (its heartbeat is every 5 s); > 0 */
  int lost;                     /* a rank was lost (set by wl_sweep_run_ranks): MPI is
                                   not finalised, since Open MPI's MPI_Finalize waits for
                                   every rank, the dead one too */
  struct wl_sweep_comm *comm;   /* MPI's; NULL for one process */
};

/* What a rank reports when it starts (wl_sweep_events.rank_ready). */
struct wl_sweep_rank_info {
  int rank;
  long pid;
  int threads;                  /* CPU threads its cases run with */
  char host[64], gpu[64];
};

/* 1 when this build has MPI. */
int wl_sweep_mpi_built(void);

/* Take this process's place among the ranks. Started by an MPI launcher
 * (mpirun sets OMPI_COMM_WORLD_SIZE; MPICH, PMIx and Slurm's PMI set
 * PMI_SIZE or PMIX_RANK), MPI is initialised; otherwise r is one process
 * and nothing else happens. Before any CUDA call (the GPU is chosen
 * through the environment): on a host with several GPUs and several ranks,
 * each rank sees one, by its local rank. WL_EUNSUPPORTED when an MPI
 * launcher started several processes of a build without MPI. */
enum wl_status wl_sweep_ranks_init(struct wl_sweep_ranks *r, struct wl_error *err);

/* MPI finalised, when init started it and no rank was lost (r->lost);
 * r becomes one process. */
void wl_sweep_ranks_finish(struct wl_sweep_ranks *r);

/* Every rank's st (which must be the same call on every rank), agreed:
 * returns rank 0's status when it failed (err's message kept on rank 0,
 * emptied on the others: one message, not N); else, when another rank
 * failed, that rank keeps its message (prefixed "rank K (HOST): ") and
 * rank 0 gets one naming the ranks; WL_OK when all are. One process: st. */
enum wl_status wl_sweep_ranks_agree(const struct wl_sweep_ranks *r, enum wl_status st,
                                    struct wl_error *err);

/* What the sweep tells its caller while it runs (library code prints
 * nothing). Both may be NULL. */
struct wl_sweep_events {
  /* before case i: reused 1 when it is read back instead of run */
  void (*case_begin)(void *user, const struct wl_sweep *sw, int i, int reused);
  /* after case i ran (its row is filled) */
  void (*case_end)(void *user, const struct wl_sweep *sw, int i);
  void *user;
  /* MPI, on rank 0: rank `info->rank` has started (it reports once) */
  void (*rank_ready)(void *user, const struct wl_sweep_rank_info *info);
};

/* Run (or read back) every case into directory dir (created when missing;
 * an existing one must be empty or a sweep's), with opts as wl_assess_run
 * takes them (out_dir, force, no_snapshots and no_report are the sweep's).
 * sw->rows gets one row per case; sweep.csv and sweep.h5 are rewritten
 * after every case, and sweep.pdf rendered at the end. Returns WL_OK when
 * every case completed; WL_EUNSTABLE when a case did not (its row says why;
 * the other cases still ran); WL_EINTERRUPTED after a stop signal
 * (opts->interrupted: the running case stops as assess stops, the others do
 * not start; the message says which cases are done); WL_EINPUT (dir cannot
 * be used, or another process sweeps into it); WL_EIO, WL_ENOMEM. */
enum wl_status wl_sweep_run(struct wl_sweep *sw, const char *dir,
                            const struct wl_assess_opts *opts, const struct wl_sweep_events *ev,
                            struct wl_error *err);

/* wl_sweep_run on every rank of r (NULL or one process: wl_sweep_run).
 * Rank 0 locks dir, reads back finished cases, hands the others out one at
 * a time (and runs cases itself in between), gathers every row and writes
 * the tables and the PDF, as wl_sweep_run does; the events come on rank 0
 * only. dir must be on a filesystem every rank sees. The other ranks run
 * the cases they are given into dir/cases/ and return rank 0's status with
 * an empty message. A rank that dies, or is silent for r->silence_s, while
 * running a case makes that case a failed row; the others go on. */
enum wl_status wl_sweep_run_ranks(struct wl_sweep *sw, const char *dir,
                                  const struct wl_assess_opts *opts,
                                  const struct wl_sweep_events *ev,
                                  struct wl_sweep_ranks *ranks, struct wl_error *err);

#endif
