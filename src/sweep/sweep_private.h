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

#endif
