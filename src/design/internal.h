/* internal.h: helpers shared by the design module's files (private).
 * The checks set the error ("design: <what>: found <value>; <what is
 * valid>") and return its status, so callers chain them with
 * `if (st == WL_OK)`. */
#ifndef WALLLOAD_DESIGN_INTERNAL_H
#define WALLLOAD_DESIGN_INTERNAL_H

#include "wallload/design.h"
#include "wallload/units.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

static inline enum wl_status check_positive(const char *what, double v, struct wl_error *err) {
  if (!(isfinite(v) && v > 0.0))
    return wl_error_set(err, WL_EINPUT, "design: %s: found %g; must be positive and finite",
                        what, v);
  return WL_OK;
}

static inline enum wl_status check_nonneg(const char *what, double v, struct wl_error *err) {
  if (!(isfinite(v) && v >= 0.0))
    return wl_error_set(err, WL_EINPUT,
                        "design: %s: found %g; must be zero or positive and finite", what, v);
  return WL_OK;
}

/* A crest height: >= 0, +INFINITY allowed (no crest). */
static inline enum wl_status check_crest(double hc, struct wl_error *err) {
  if (!(hc >= 0.0))
    return wl_error_set(err, WL_EINPUT,
                        "design: crest height above SWL hc [m]: found %g; must be zero or "
                        "positive (INFINITY for no crest); submerged walls are outside every "
                        "formula here",
                        hc);
  return WL_OK;
}

static inline enum wl_status check_water(double rho, double g, struct wl_error *err) {
  enum wl_status st = check_positive("water density rho [kg/m^3]", rho, err);
  if (st == WL_OK) st = check_positive("gravity g [m/s^2]", g, err);
  return st;
}

/* Wavelength from L when L > 0, else from T at depth h. */
static inline enum wl_status wavelength_of(double T, double L_in, double h, double g, double *L,
                                           struct wl_error *err) {
  if (isfinite(L_in) && L_in > 0.0) {
    *L = L_in;
    return WL_OK;
  }
  if (!(L_in == 0.0) || !(isfinite(T) && T > 0.0))
    return wl_error_set(err, WL_EINPUT,
                        "design: wave period T [s] / wavelength L [m]: found T = %g, L = %g; "
                        "give L > 0, or L = 0 and T > 0",
                        T, L_in);
  return wl_design_wavelength(T, h, g, L, err);
}

/* Start a result: everything zero or NAN except what is given. */
static inline void result_start(struct wl_design_result *r, const char *name, const char *cite,
                                enum wl_design_basis basis) {
  r->name = name;
  r->citation = cite;
  r->basis = basis;
  r->force = r->moment = 0.0;
  r->force_total = r->moment_total = 0.0;
  r->uplift_p = NAN;
  r->in_range = 1;
  r->range_note[0] = '\0';
  r->profile.n_points = 0;
  for (int i = 0; i < WL_DESIGN_PROFILE_MAX; i++) r->profile.z[i] = r->profile.p[i] = 0.0;
}

/* Add the still-water hydrostatics of depth d_w unless the basis is TOTAL. */
static inline void result_totals(struct wl_design_result *r, double rho, double g, double d_w) {
  r->force_total = r->force;
  r->moment_total = r->moment;
  if (r->basis != WL_DESIGN_BASIS_TOTAL && d_w > 0.0) {
    r->force_total += rho * g * d_w * d_w / 2.0;
    r->moment_total += rho * g * d_w * d_w * d_w / 6.0;
  }
}

static inline void result_note(struct wl_design_result *r, int in_range, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static inline void result_note(struct wl_design_result *r, int in_range, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(r->range_note, sizeof r->range_note, fmt, ap);
  va_end(ap);
  r->in_range = in_range;
}

/* Append a point to a profile (caller keeps z increasing, n < MAX). */
static inline void profile_add(struct wl_design_profile *pr, double z, double p) {
  pr->z[pr->n_points] = z;
  pr->p[pr->n_points] = p;
  pr->n_points++;
}

#endif
