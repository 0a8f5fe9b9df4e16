/* assess_private.h: pieces of the assess module shared by its files. */
#ifndef WALLLOAD_ASSESS_PRIVATE_H
#define WALLLOAD_ASSESS_PRIVATE_H

#include "wallload/assess.h"
#include "wallload/vres.h"

/* record.c */
void case_loads_clear(struct wl_case_loads *l);
/* Filtered series, impulse, peaks and run-up of a case's record. */
enum wl_status case_loads_compute(struct wl_case_result *c, struct wl_error *err);

/* assess.c */
/* wl_assess_case; `how`: ASSESS_DEFER leaves the snapshot files complete
 * under their temporary names (c->snapshot_files), for write_results to
 * move into place with the results; ASSESS_URGENT marks the run that runs
 * beside others on a GPU and that they all wait for (the finest level of
 * the last case: its stream gets the GPU's greatest priority, so that the
 * runs beside it fill the GPU around it instead of slowing it). */
/* ASSESS_NO_STILL: run no still-water reference (plan.h) for this case;
 * the caller attaches one later (assess_attach_still) or none.
 * ASSESS_STILL_RUN: this run is a still-water reference (its plan's
 * still_flume is set; its progress is named so). */
enum { ASSESS_DEFER = 1, ASSESS_URGENT = 2, ASSESS_NO_STILL = 4, ASSESS_STILL_RUN = 8 };
enum wl_status assess_case(const struct wl_scenario *s, const struct wl_plan *plan,
                           enum wl_load_case load, const struct wl_assess_opts *opts,
                           const char *snapshots, int how, struct wl_case_result *c,
                           struct wl_error *err);

/* Give c the still-water reference `still` (not owned; it must outlive c's
 * use of it) and compute its loads again with the reference's drift: a
 * realisation of a ladder's level shares its first run's reference. */
enum wl_status assess_attach_still(struct wl_case_result *c, struct wl_case_result *still,
                                   struct wl_error *err);

/* The GPU's memory [bytes] when this scenario's run goes to the CUDA backend
 * (opts->backend, else run.backend; auto: a GPU found), else 0. */
double assess_gpu_memory(const struct wl_scenario *s, const struct wl_assess_opts *opts);

/* levels.c */
/* The two levels of a case under resolution.refine (plan->refine): fine is
 * the case's flume built at plan->dp, cut here to the fine level's water;
 * coarse is built at plan->dp_coarse and cut likewise; spec and vo are what
 * wl_vres_alloc takes (spec[0] coarse, spec[1] fine, pointing into the two
 * flumes, whose domains grow a band of parking slots above their walls).
 * On failure coarse may hold a flume for the caller to clear. */
enum wl_status levels_build(const struct wl_scenario *s, const struct wl_plan *plan,
                            enum wl_load_case load, struct wl_flume *fine, struct wl_flume *coarse,
                            struct wl_vres_level_spec spec[2], struct wl_vres_opts *vo,
                            struct wl_error *err);

/* ladder.c */
/* Run load case `load` on the scenario's convergence ladder into c (the last
 * level run, as wl_assess_case fills it) and cv (every level, the estimate
 * and how the ladder ended; urgent: its finest level's run is ASSESS_URGENT).
 * Returns the last level's status (a level that
 * cannot be planned or built returns its error, c keeping the level before
 * when there was one). */
enum wl_status ladder_run(const struct wl_scenario *s, const struct wl_plan *plan,
                          enum wl_load_case load, const struct wl_assess_opts *opts,
                          const char *snapshots, int urgent, struct wl_case_result *c,
                          struct wl_assess_convergence *cv, struct wl_error *err);
/* Order, extrapolation and error estimates of the levels run so far. */
void ladder_estimate(struct wl_assess_convergence *cv);

/* output.c */
/* Write results.h5, summary.json and the CSV files of all cases, and move
 * them into place together with the cases' waiting snapshot files
 * (snapshot_files bits 0-1); nothing moves when any of them fails (the
 * waiting files are then removed). After the move, the directory's result
 * files that the new set does not have are removed (report.pdf, which is
 * rendered again; a case's files the run did not write), so that the
 * directory never mixes two runs. */
enum wl_status write_results(const struct wl_scenario *s, const struct wl_plan *plan,
                             const struct wl_assess_result *res, struct wl_error *err);

#endif
