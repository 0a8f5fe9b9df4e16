/* sweep_private.h: pieces of the sweep module shared by its files. */
#ifndef WALLLOAD_SWEEP_PRIVATE_H
#define WALLLOAD_SWEEP_PRIVATE_H

#include <stddef.h>

#include "wallload/sweep.h"

/* One column of a load case's loads: name (CSV column stem, HDF5 dataset,
 * sweep-case.txt key), unit (SI, as written), what it is, where it is. */
struct sweep_field {
  const char *name, *csv_unit, *unit, *desc;
  size_t off; /* of a double in struct wl_sweep_loads */
};
extern const struct sweep_field sweep_fields[];
extern const int sweep_n_fields;

/* "complete", "unstable", "interrupted", "failed"; "pending" for a row not run. */
const char *sweep_status_word(const struct wl_sweep_row *r, enum wl_status st);

/* The SI unit of a swept parameter ("kg", "J", "m"). */
const char *sweep_param_unit(enum wl_sweep_param p);

/* table.c: write DIR/sweep.csv and DIR/sweep.h5 (each atomically) from
 * sw's cases and rows. */
enum wl_status sweep_write_tables(const struct wl_sweep *sw, const char *dir,
                                  struct wl_error *err);

/* plot.c: DIR/sweep.pdf, the envelopes (report.h). */
enum wl_status sweep_write_pdf(const struct wl_sweep *sw, const char *dir, struct wl_error *err);

/* run.c: each case's digest of its inputs (sweep.h: resuming), malloc'd
 * into *digest (free it); *threads (may be NULL) gets the CPU threads a
 * case runs with. */
enum wl_status sweep_digests(const struct wl_sweep *sw, const struct wl_assess_opts *opts,
                             char (**digest)[17], int *threads, struct wl_error *err);

/* run.c: run case i into dir/cases/<id>/ and fill its row (all but
 * rank). Returns the case's status (its row's); WL_EIO or WL_ENOMEM when
 * its files could not be written (the sweep then stops: the next case
 * would fail alike; err says why). */
enum wl_status sweep_run_case(struct wl_sweep *sw, int i, const char *dir, const char *digest,
                              const struct wl_assess_opts *opts, struct wl_error *err);

/* mpi.c: the cases shared among MPI ranks (docs/sweep-mpi.md). Rank 0,
 * the lead, holds the directory's lock, reads back what earlier runs
 * finished, hands out the pending cases one at a time, runs cases itself
 * in between, and writes every table; the other ranks follow. */
struct sweep_lead;

/* Lead: tell the followers whether the directory is had (st; WL_OK: they
 * start), and make *lead. Returns WL_ENOMEM or an MPI failure. */
enum wl_status sweep_lead_start(struct wl_sweep_ranks *r, const struct wl_sweep *sw,
                                enum wl_status st, struct sweep_lead **lead,
                                struct wl_error *err);

/* Lead: run or hand out every pending case (sw->rows' state PENDING),
 * writing the tables as each one ends (threads: this rank's, for
 * ev->rank_ready); *stop gets the signal's number when
 * a stop signal ended the sweep early. As run.c's loop, the sweep stops at
 * a case whose files cannot be written (WL_EIO, WL_ENOMEM). A follower
 * that dies or goes silent makes its case a failed row. */
enum wl_status sweep_lead_cases(struct sweep_lead *lead, struct wl_sweep *sw, const char *dir,
                                const struct wl_assess_opts *opts,
                                const struct wl_sweep_events *ev, char (*digest)[17], int threads,
                                int *stop, struct wl_error *err);

/* Lead: tell every follower still there that the sweep ended with status
 * st (their exit status), and whether a rank was lost (r->lost, on every
 * rank); free lead (may be NULL). */
void sweep_lead_end(struct sweep_lead *lead, enum wl_status st);

/* Follower (rank > 0): run the cases the lead hands out until it says the
 * sweep ended. Returns the lead's status with err's message empty (the
 * lead says why), or this rank's own failure (the lead lost). */
enum wl_status sweep_follow(struct wl_sweep_ranks *r, struct wl_sweep *sw, const char *dir,
                            const struct wl_assess_opts *opts, struct wl_error *err);

#endif
