/* assess_private.h: pieces of the assess module shared by its files. */
#ifndef WALLLOAD_ASSESS_PRIVATE_H
#define WALLLOAD_ASSESS_PRIVATE_H

#include "wallload/assess.h"

/* record.c */
void record_clear(struct wl_record *r);
/* Make room for one more sample (n grows by one; the caller fills row n-1). */
enum wl_status record_push(struct wl_record *r, struct wl_error *err);
void case_loads_clear(struct wl_case_loads *l);
/* Filtered series, impulse, peaks and run-up of a case's record. */
enum wl_status case_loads_compute(struct wl_case_result *c, struct wl_error *err);

/* output.c */
/* Write results.h5, summary.json and the CSV files of all cases. */
enum wl_status write_results(const struct wl_scenario *s, const struct wl_plan *plan,
                             const struct wl_assess_result *res, struct wl_error *err);

#endif
