/* record.c: the post-processing of a case's sampled record (sample.h)
 * into loads (definitions in loads.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "assess_private.h"

void case_loads_clear(struct wl_case_loads *l) {
  free(l->force_filtered);
  free(l->moment_filtered);
  free(l->force_bound_filtered);
  free(l->impulse);
  free(l->impulse_bound);
  free(l->drift);
  free(l->drift_bound);
  free(l->drift_moment);
  memset(l, 0, sizeof *l);
}

/* Filter a series, or copy it where it is too short to filter. */
static enum wl_status filtered(const double *x, size_t n, double dt, double fc, double **out,
                               struct wl_error *err) {
  *out = malloc((n ? n : 1) * sizeof **out);
  if (!*out) return wl_error_set(err, WL_ENOMEM, "loads: no memory for %zu samples", n);
  if (n < 8 || !(fc > 0 && fc < 0.5 / dt)) {
    memcpy(*out, x, n * sizeof *x);
    return WL_OK;
  }
  return wl_loads_lowpass(x, n, dt, fc, *out, err);
}

/* The still-water reference run's drift (plan.h) into c->loads.drift,
 * drift_bound and drift_moment: its filtered series less its own values at
 * rest, at the case's sample times (linear between the reference's
 * samples, which are the case's but for the last: a realisation's crater
 * moves its planned end time by a fraction of a sample). Only a complete
 * reference that reaches within one sample of the case's end serves;
 * otherwise none (the caution says so, case_caution). */
static enum wl_status still_drift(struct wl_case_result *c, struct wl_error *err) {
  const struct wl_case_result *tr = c->still;
  struct wl_case_loads *l = &c->loads;
  const size_t n = c->rec.n, m = tr ? tr->rec.n : 0;
  if (!tr || tr->status != WL_OK || m < 2 || n < 2 || !tr->loads.force_filtered ||
      !tr->loads.force_bound_filtered || !tr->loads.moment_filtered ||
      !isfinite(tr->loads.rest_force) || !isfinite(tr->loads.rest_force_bound) ||
      !isfinite(tr->loads.rest_moment))
    return WL_OK;
  const double *tt = tr->rec.t, *t = c->rec.t;
  const double dt = (t[n - 1] - t[0]) / (double)(n - 1);
  if (tt[0] > t[0] + 1e-9 * dt || tt[m - 1] < t[n - 1] - dt * (1.0 + 1e-9))
    return WL_OK; /* it does not cover the case's record */
  l->drift = malloc(n * sizeof *l->drift);
  l->drift_bound = malloc(n * sizeof *l->drift_bound);
  l->drift_moment = malloc(n * sizeof *l->drift_moment);
  if (!l->drift || !l->drift_bound || !l->drift_moment) {
    free(l->drift), free(l->drift_bound), free(l->drift_moment);
    l->drift = l->drift_bound = l->drift_moment = NULL;
    return wl_error_set(err, WL_ENOMEM, "loads: no memory for %zu samples", n);
  }
  const struct wl_case_loads *rl = &tr->loads;
  size_t j = 0;
  for (size_t k = 0; k < n; k++) {
    while (j + 2 < m && tt[j + 1] < t[k]) j++;
    double w = (t[k] - tt[j]) / (tt[j + 1] - tt[j]);
    w = w < 0.0 ? 0.0 : w > 1.0 ? 1.0 : w; /* held beyond its ends */
    l->drift[k] = (1.0 - w) * rl->force_filtered[j] + w * rl->force_filtered[j + 1] - rl->rest_force;
    l->drift_bound[k] = (1.0 - w) * rl->force_bound_filtered[j] +
                        w * rl->force_bound_filtered[j + 1] - rl->rest_force_bound;
    l->drift_moment[k] = (1.0 - w) * rl->moment_filtered[j] + w * rl->moment_filtered[j + 1] -
                         rl->rest_moment;
  }
  return WL_OK;
}

enum wl_status case_loads_compute(struct wl_case_result *c, struct wl_error *err) {
  const struct wl_record *r = &c->rec;
  struct wl_case_loads *l = &c->loads;
  size_t n = r->n;
  l->realisations = 1;
  l->drift_max = l->impulse_positive_uncorrected = NAN;
  if (n == 0) return WL_OK;
  double dt = n > 1 ? (r->t[n - 1] - r->t[0]) / (double)(n - 1) : 1.0;
  l->cutoff = wl_loads_cutoff(c->c0, c->depth_wall > 0 ? c->depth_wall : c->h, dt);
  enum wl_status st;
  if ((st = filtered(r->force, n, dt, l->cutoff, &l->force_filtered, err)) ||
      (st = filtered(r->moment, n, dt, l->cutoff, &l->moment_filtered, err)) ||
      (st = filtered(r->force_bound, n, dt, l->cutoff, &l->force_bound_filtered, err)))
    return st;
  /* the model's own force at rest (loads.h) */
  const double depth = c->depth_wall > 0 ? c->depth_wall : c->h;
  double w0, w1;
  l->rest_measured = wl_loads_rest_window(c->quiet_until, depth, c->c0, &w0, &w1);
  l->rest_force = l->rest_measured ? wl_loads_mean(r->t, r->force, n, w0, w1) : NAN;
  l->rest_force_bound = l->rest_measured ? wl_loads_mean(r->t, r->force_bound, n, w0, w1) : NAN;
  l->rest_moment = l->rest_measured ? wl_loads_mean(r->t, r->moment, n, w0, w1) : NAN;
  l->rest_measured = l->rest_measured && isfinite(l->rest_force) &&
                     isfinite(l->rest_force_bound) && isfinite(l->rest_moment);
  l->rest_from = l->rest_measured ? w0 : NAN;
  l->rest_to = l->rest_measured ? fmin(w1, r->t[n - 1]) : NAN;
  if (!l->rest_measured) {
    l->rest_force = l->rest_force_bound = c->static_force;
    l->rest_moment = c->static_moment;
  }
  if ((st = still_drift(c, err))) return st;
  /* The filtered series less the still-water reference's drift: the wave's
   * load on a wall whose still water stays still (plan.h). Peaks and
   * impulses are taken from them; the raw series stay as sampled. */
  double *unfiltered_drift = NULL;
  if (l->drift) {
    unfiltered_drift = malloc(n * sizeof *unfiltered_drift);
    if (!unfiltered_drift) return wl_error_set(err, WL_ENOMEM, "loads: no memory for %zu samples", n);
    memcpy(unfiltered_drift, l->force_filtered, n * sizeof *unfiltered_drift);
    for (size_t k = 0; k < n; k++) {
      l->force_filtered[k] -= l->drift[k];
      l->force_bound_filtered[k] -= l->drift_bound[k];
      l->moment_filtered[k] -= l->drift_moment[k];
    }
  }
  l->impulse = malloc(n * sizeof *l->impulse);
  l->impulse_bound = malloc(n * sizeof *l->impulse_bound);
  double *net = malloc(n * sizeof *net);
  if (!l->impulse || !l->impulse_bound || !net) {
    free(net), free(unfiltered_drift);
    return wl_error_set(err, WL_ENOMEM, "loads: no memory for %zu samples", n);
  }
  double *const ff = l->force_filtered, *const fbf = l->force_bound_filtered;
  for (size_t k = 0; k < n; k++) net[k] = r->force[k] - l->rest_force - (l->drift ? l->drift[k] : 0.0);
  wl_loads_cumulative(r->t, net, n, l->impulse);
  for (size_t k = 0; k < n; k++)
    net[k] = r->force_bound[k] - l->rest_force_bound - (l->drift ? l->drift_bound[k] : 0.0);
  wl_loads_cumulative(r->t, net, n, l->impulse_bound);
  free(net);
  l->impulse_total = l->impulse[n - 1];
  size_t k0 = 0; /* peaks from c->peak_from on (assess.h) */
  while (k0 + 1 < n && r->t[k0] < c->peak_from) k0++;
  wl_loads_peak(r->t + k0, l->force_filtered + k0, n - k0, l->rest_force, &l->force_peak);
  wl_loads_peak(r->t + k0, l->moment_filtered + k0, n - k0, l->rest_moment, &l->moment_peak);
  wl_loads_peak(r->t + k0, l->force_bound_filtered + k0, n - k0, l->rest_force_bound,
                &l->force_bound_peak);
  /* indices of the stored series, not of the searched part */
  l->force_peak.index += k0;
  l->moment_peak.index += k0;
  l->force_bound_peak.index += k0;
  l->impulse_peak = wl_loads_positive_phase_impulse(r->t, ff, l->impulse, n, l->rest_force,
                                                    l->force_peak.index, &l->impulse_peak_from,
                                                    &l->impulse_peak_to);
  /* the positive impulse of the whole event, from where peaks are searched */
  l->impulse_positive = wl_loads_positive_impulse(r->t + k0, ff + k0, n - k0, l->rest_force);
  l->impulse_positive_bound =
      wl_loads_positive_impulse(r->t + k0, fbf + k0, n - k0, l->rest_force_bound);
  l->impulse_positive_uncorrected =
      unfiltered_drift ? wl_loads_positive_impulse(r->t + k0, unfiltered_drift + k0, n - k0,
                                                   l->rest_force)
                       : NAN;
  free(unfiltered_drift);
  l->drift_max = NAN;
  if (l->drift) {
    l->drift_max = 0.0;
    for (size_t k = k0; k < n; k++) l->drift_max = fmax(l->drift_max, fabs(l->drift[k]));
  }
  l->rest_force_spread =
      l->rest_measured ? wl_loads_halves_spread(r->t, r->force, n, l->rest_from, l->rest_to) : NAN;
  l->impulse_positive_rest_error =
      l->rest_force_spread * wl_loads_time_above(r->t + k0, ff + k0, n - k0, l->rest_force);
  /* run-up: the last gauge is the one at the wall face */
  int gw = r->n_gauges - 1;
  l->runup = -INFINITY;
  for (size_t k = 0; k < n; k++) {
    double e = r->eta[k * (size_t)r->n_gauges + (size_t)gw];
    if (e > l->runup) l->runup = e, l->runup_time = r->t[k];
  }
  return WL_OK;
}
