/* check.h: argument checks shared by the explosion module's files (private).
 * Each sets the error ("explosion: <what>: found <value>; <what is valid>")
 * and returns its status, so callers chain them with `if (st == WL_OK)`. */
#ifndef WALLLOAD_EXPLOSION_CHECK_H
#define WALLLOAD_EXPLOSION_CHECK_H

#include "wallload/error.h"

#include <math.h>

static inline enum wl_status check_positive(const char *what, double v, struct wl_error *err) {
  if (!(isfinite(v) && v > 0.0))
    return wl_error_set(err, WL_EINPUT, "explosion: %s: found %g; must be positive and finite",
                        what, v);
  return WL_OK;
}

static inline enum wl_status check_nonneg(const char *what, double v, struct wl_error *err) {
  if (!(isfinite(v) && v >= 0.0))
    return wl_error_set(err, WL_EINPUT,
                        "explosion: %s: found %g; must be zero or positive and finite", what, v);
  return WL_OK;
}

static inline enum wl_status check_dims(int dims, struct wl_error *err) {
  if (dims != 2 && dims != 3)
    return wl_error_set(err, WL_EINPUT, "explosion: dimensions: found %d; valid are 2 and 3",
                        dims);
  return WL_OK;
}

static inline enum wl_status check_water(double rho, double g, struct wl_error *err) {
  enum wl_status st = check_positive("water density rho [kg/m^3]", rho, err);
  if (st == WL_OK) st = check_positive("gravity g [m/s^2]", g, err);
  return st;
}

#endif
