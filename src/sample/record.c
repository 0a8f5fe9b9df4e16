/* record.c: the growable record of a case's sampled series (sample.h). */
#include <stdlib.h>
#include <string.h>

#include "wallload/sample.h"

void wl_sample_record_clear(struct wl_record *r) {
  free(r->t);
  free(r->eta);
  free(r->pressure);
  free(r->force);
  free(r->moment);
  free(r->force_bound);
  free(r->moment_bound);
  free(r->kinetic);
  free(r->potential);
  free(r->momentum);
  memset(r, 0, sizeof *r);
}

static int grow(double **a, size_t cap, size_t width) {
  double *b = realloc(*a, cap * width * sizeof *b);
  if (!b) return 0;
  *a = b;
  return 1;
}

enum wl_status wl_sample_record_push(struct wl_record *r, struct wl_error *err) {
  if (r->n == r->cap) {
    size_t cap = r->cap ? 2 * r->cap : 1024;
    int ok = grow(&r->t, cap, 1) && grow(&r->eta, cap, (size_t)(r->n_gauges ? r->n_gauges : 1)) &&
             grow(&r->pressure, cap, (size_t)(r->n_probes ? r->n_probes : 1)) &&
             grow(&r->force, cap, 1) && grow(&r->moment, cap, 1) &&
             grow(&r->force_bound, cap, 1) && grow(&r->moment_bound, cap, 1) &&
             grow(&r->kinetic, cap, 1) &&
             grow(&r->potential, cap, 1) && grow(&r->momentum, cap, 1);
    if (!ok)
      return wl_error_set(err, WL_ENOMEM, "record: no memory for %zu output samples", cap);
    r->cap = cap;
  }
  r->n++;
  return WL_OK;
}
