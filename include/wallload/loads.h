/* loads.h: wall pressure -> force, moment, impulse, filtered series, peaks.
 *
 * Definitions used everywhere in wallload (docs/outputs.md, README, report,
 * summary.json):
 *  - force F(t) [N/m]: horizontal force per metre of wall, the integral of
 *    the face pressure over the wall's height (2D), or the wall's total /
 *    its width (3D).
 *  - moment M(t) [N m/m]: overturning moment about the wall's toe,
 *    integral of p(z) (z - z_toe) dz.
 *  - force at rest F_rest [N/m]: the model's own force on the wall before
 *    the wave reaches it, the mean of the raw force over the rest window
 *    (wl_loads_rest_window), each measurement (probes, boundary particles)
 *    its own. It differs from the nominal rho g d^2/2 by the model's
 *    discretisation at the wall (1-2 % at h/dp = 20); subtracting the
 *    nominal value instead would add that error times the record's length
 *    to the impulse. Without a rest window (the wave at the wall from the
 *    start) the nominal value is the base, and the results say so.
 *  - impulse I(t) [N s/m]: time integral of F - F_rest from the start of
 *    the record (trapezoid rule on the stored samples).
 *  - filtered series: zero-phase low-pass (second-order Butterworth run
 *    forward and backward, so the response is fourth order with no time
 *    shift) at cut-off f_c. WCSPH's artificial compressibility makes the
 *    water column ring at its acoustic frequency c0/(4 d) (d the water depth
 *    at the wall); f_c = c0/(8 d) keeps everything slower than half of it.
 *    The cut-off is stored with every filtered series. Peaks are taken from
 *    the filtered series and say so.
 *  - rise time: from the last time before the peak the net force
 *    F - F_rest was below 10 % of its peak, to the peak.
 *  - duration: the time the net force stays above 10 % of its peak, from
 *    its first upward crossing to its last downward crossing.
 *  - positive-phase impulse [N s/m]: the integral of F - F_rest over the
 *    positive phase of the peak, from the last time before the peak that
 *    the filtered net force was at or below zero to the first time after
 *    it. It is the impulse that acts with the peak force. The net impulse
 *    of a whole record can be far smaller: an explosion's oscillating wave
 *    train pushes and pulls in turn, and its net impulse is a small
 *    difference of large numbers whose sign changes with the resolution.
 *  - run-up: the highest water level at the wall face above still water. */
#ifndef WALLLOAD_LOADS_H
#define WALLLOAD_LOADS_H

#include <stddef.h>

#include "wallload/error.h"

/* Threshold of the rise-time and duration definitions, share of the peak. */
#define WL_LOADS_THRESHOLD 0.10

/* Integrate a pressure profile p[k] [Pa] sampled at heights z[k] [m]
 * (increasing, n >= 2) over the wall from z_toe to z_top: trapezoid rule
 * between probes, with the pressure held at the end probes' values out to
 * z_toe and z_top (probes sit half a spacing inside the face's ends).
 * Gives the force per metre [N/m] and the moment about (z_toe) [N m/m]. */
void wl_loads_profile(const double *z, const double *p, size_t n, double z_toe, double z_top,
                      double *force, double *moment);

/* The window [*t0, *t1] [s] in which the wall's force at rest is read:
 * from two acoustic periods of the water at the wall (4 d / c0 each: the
 * start's settling rings at it) to quiet_until, the plan's estimate of the
 * last time the wave leaves the wall's force alone (plan.h). Returns 1
 * when the window holds at least two acoustic periods, else 0 (no rest
 * window: the wave is at the wall from the start). */
int wl_loads_rest_window(double quiet_until, double depth, double c0, double *t0, double *t1);

/* The time mean of x over [t0, t1] (trapezoid rule over the samples inside
 * it); NaN when fewer than 4 samples lie inside. */
double wl_loads_mean(const double *t, const double *x, size_t n, double t0, double t1);

/* Cumulative trapezoid integral out[k] = int_{t0}^{t_k} f dt (out[0] = 0).
 * out may alias nothing. */
void wl_loads_cumulative(const double *t, const double *f, size_t n, double *out);

/* Zero-phase low-pass filter of x sampled at uniform interval dt [s] with
 * cut-off fc [Hz] (second-order Butterworth forward and backward, edges
 * padded by reflection). Returns WL_OK; WL_EINPUT if fc is not in
 * (0, 0.5/dt) (the message says the valid range) or n < 4. */
enum wl_status wl_loads_lowpass(const double *x, size_t n, double dt, double fc, double *out,
                                struct wl_error *err);

/* The cut-off of the documented filter, c0/(8 d) [Hz], capped at 0.4 of the
 * sampling Nyquist frequency so the filter remains well defined. */
double wl_loads_cutoff(double c0, double depth, double dt_sample);

struct wl_peak {
  double value;  /* peak value (of the series given) */
  double time;   /* when [s] */
  size_t index;
  double rise_time; /* [s]; NaN if the series never drops below the threshold before the peak */
  double duration;  /* [s] above the threshold */
};

/* Peak of (x - base) over the record and its rise time and duration with
 * WL_LOADS_THRESHOLD; value is the peak of x itself. n >= 1. */
void wl_loads_peak(const double *t, const double *x, size_t n, double base, struct wl_peak *pk);

/* The positive phase of the peak at index ip of x - base (a filtered
 * force): *i0 is the last sample at or before ip where x <= base (0 when
 * there is none), *i1 the first at or after ip where x <= base (n - 1 when
 * there is none). A peak at or below base gives *i0 = *i1 = ip. The
 * phase's impulse is I[*i1] - I[*i0] of a cumulative integral I of
 * x - base (wl_loads_cumulative). n >= 1, ip < n. */
void wl_loads_positive_phase(const double *x, size_t n, double base, size_t ip, size_t *i0,
                             size_t *i1);

/* The positive-phase impulse of the peak at index ip of the filtered force
 * xf (base: the force at rest), from the cumulative impulse I of the raw
 * force (wl_loads_cumulative of F - base): I[i1] - I[i0] over the phase of
 * wl_loads_positive_phase, whose times go to *t0 and *t1. */
double wl_loads_positive_phase_impulse(const double *t, const double *xf, const double *I,
                                       size_t n, double base, size_t ip, double *t0, double *t1);

/* The positive impulse of the filtered force xf over the base (the force at
 * rest): the integral of max(0, xf - base) dt over the whole series, each
 * interval integrated exactly for the linear interpolant (an interval that
 * crosses the base contributes its positive triangle). It is the push of
 * every wave of a train together, and the load's impulse that converges
 * with resolution where the peak's positive phase does not: an explosion's
 * train brings several crests of nearly equal force, and which of them
 * carries the peak (and so whose phase is integrated) changes between
 * resolutions (docs/outputs.md). The filtered force, because the positive
 * part of the raw force would rectify the acoustic ringing into a bias. */
double wl_loads_positive_impulse(const double *t, const double *xf, size_t n, double base);

/* The time [s] the filtered force xf spends above base, each interval
 * exact for the linear interpolant as in wl_loads_positive_impulse: minus
 * the derivative of the positive impulse with respect to its base, so an
 * error dF in the force at rest moves the positive impulse by this times
 * dF. */
double wl_loads_time_above(const double *t, const double *xf, size_t n, double base);

/* How well the window [t0, t1] fixes the mean of x: half the difference
 * between the means of its two halves (wl_loads_mean of each). The rest
 * window holds a few acoustic periods of ringing, and in a scene whose
 * wave lifts the wall's force by a few per cent the uncertainty of the
 * force at rest decides the positive impulse (wl_loads_time_above). NaN
 * when a half holds fewer than 4 samples. */
double wl_loads_halves_spread(const double *t, const double *x, size_t n, double t0, double t1);

/* ---- convergence over a resolution ladder --------------------------------- */

/* Meaningful observed orders: outside [MIN, MAX] the three levels are not in
 * the asymptotic range (or the quantity is noise-dominated) and no
 * Richardson value is reported. */
#define WL_LOADS_ORDER_MIN 0.5
#define WL_LOADS_ORDER_MAX 4.0

/* The order bands of the uncertainty (Eca & Hoekstra 2014, J. Comput. Phys.
 * 262, 104-130, section 4, for a method of formal order 2: the Wendland
 * kernel's SPH is at best second order), the order assumed where the
 * observed one cannot be used, and the factors of safety: 1.25 with an
 * observed order, 3 with an assumed one or with only the data range (Roache
 * 1998, "Verification and Validation in Computational Science and
 * Engineering", ch. 5; ASME V&V 20-2009, section 5). */
#define WL_LOADS_ORDER_LOW 0.95
#define WL_LOADS_ORDER_HIGH 2.05
#define WL_LOADS_ORDER_ASSUMED 2.0
#define WL_LOADS_SAFETY_OBSERVED 1.25
#define WL_LOADS_SAFETY_ASSUMED 3.0

/* How the uncertainty of a ladder's finest value was obtained. */
enum wl_loads_estimate {
  WL_LOADS_EST_NONE,      /* fewer than two levels (or non-finite values): none */
  WL_LOADS_EST_TWO_LEVEL, /* two levels: 3 |f3 - f2| / (r32^2 - 1), the order assumed 2 */
  WL_LOADS_EST_GCI,       /* monotone, 0.95 <= p < 2.05: 1.25 |f3 - f_ext| */
  WL_LOADS_EST_GCI_LOW,   /* monotone, 0 < p < 0.95: min(1.25 |f3 - f_ext|, 3 range) */
  WL_LOADS_EST_GCI_HIGH,  /* monotone, p >= 2.05: max(1.25 |f3 - f_ext(p = 2)|, 1.25 range) */
  WL_LOADS_EST_RANGE,     /* oscillating, a zero difference or diverging: 3 range */
  WL_LOADS_EST_SAMPLED,   /* means whose finest two agree within their sampling:
                             max(1.25 |f3 - f_ext(p = 2)|, 1.25 range) */
};

/* Observed order, Richardson extrapolation and uncertainty of a quantity f
 * computed at spacings h (any length unit), from the LAST three levels
 * (1 coarsest, 3 finest of those three; h1 > h2 > h3):
 *
 *   r21 = h1/h2, r32 = h2/h3 (refinement ratios)
 *   with f = f* + C h^p:  (f1 - f2)/(f2 - f3) = r32^p (r21^p - 1)/(r32^p - 1),
 *   which for a constant ratio r is r^p, so p = ln((f1 - f2)/(f2 - f3)) / ln r;
 *   for unequal ratios (whole rows of still water make them so) the
 *   equation is solved for p by bisection (its right side increases with p);
 *   Celik et al. 2008, J. Fluids Eng. 130, 078001, eqs 3-4.
 *   f_ext(p) = f3 + (f3 - f2)/(r32^p - 1)               (Richardson)
 *   range = max(f1, f2, f3) - min(f1, f2, f3)
 *
 * The uncertainty U of the finest value f3 (a band meant to hold the
 * converged value with about 95 % confidence, not a best guess of the
 * error) follows Eca & Hoekstra's bands for three levels, without their
 * least-squares fit (the ladder has three levels at most in use):
 *   monotone (both differences of one sign) and 0.95 <= p < 2.05:
 *       U = 1.25 |f3 - f_ext(p)|                    (Roache's GCI)
 *   monotone and 0 < p < 0.95:  U = min(1.25 |f3 - f_ext(p)|, 3 range)
 *   monotone and p >= 2.05:     U = max(1.25 |f3 - f_ext(2)|, 1.25 range)
 *   otherwise (oscillating, a zero difference, p <= 0): U = 3 range
 *   two levels:  U = 3 |f3 - f2| / (r32^2 - 1)       (Roache's two-grid GCI)
 * error = U / |f3|. The order is "meaningful" (order_ok; the Richardson
 * value f_ext is then given) when monotone with WL_LOADS_ORDER_MIN <= p <=
 * WL_LOADS_ORDER_MAX; the order is reported whenever it is defined (NaN
 * when the differences change sign or one is zero). Pure function; never
 * fails. */
struct wl_loads_convergence {
  int n_used;            /* levels used: min(n, 3) */
  double r21, r32;       /* refinement ratios of the last three levels (NaN when absent) */
  double order;          /* observed order p (NaN when undefined) */
  int order_ok;          /* 1: monotone and p in [WL_LOADS_ORDER_MIN, WL_LOADS_ORDER_MAX] */
  double extrapolated;   /* f_ext (NaN unless order_ok) */
  double error;          /* uncertainty of the finest value, relative: U / |f3| (NaN: none) */
  enum wl_loads_estimate basis;
};

void wl_loads_convergence(const double *h, const double *f, int n,
                          struct wl_loads_convergence *out);

/* The same for a ladder of means of several realisations (assess.h
 * resolution.realisations), u[k] the 95 % sampling uncertainty of f[k]
 * (absolute, as wl_loads_mean_uncertainty times |f[k]|; 0 or NaN for a
 * single run). Where the finest two means differ by no more than their
 * combined sampling uncertainty, sqrt(u2^2 + u3^2), the sign of that
 * difference is not known from the data, so the test for oscillation
 * cannot use it: where that sign alone made the ladder oscillate (3 x
 * range), the finest two are read as equal, the ladder as
 * converged beyond the order of the method, and the band is Eca &
 * Hoekstra's for an order above 2, max(1.25 |f3 - f_ext(2)|, 1.25 range)
 * (WL_LOADS_EST_SAMPLED; the order is then not reported), instead of 3 x
 * range, which a difference inside the scatter would otherwise trigger by
 * its sign alone (seawall.yaml's explosion, 2026-11-28: 21.20, 22.981,
 * 22.976 N s/m with a sampling uncertainty of 0.93 N s/m read 27 % by
 * 3 x range). Otherwise as wl_loads_convergence. The sampling uncertainty
 * itself is not in the band: the caller adds the finest level's. */
void wl_loads_convergence_sampled(const double *h, const double *f, const double *u, int n,
                                  struct wl_loads_convergence *out);

/* Student's t for a two-sided 95 % interval with `dof` degrees of freedom
 * (dof >= 1; the table of any statistics text to 3 decimals for 1-30, then
 * 1.96 + 2.4/dof, within 0.003 of the exact value beyond): the coverage
 * factor of a mean of dof + 1 runs. */
double wl_loads_t95(int dof);

/* The sampling uncertainty of a mean of m runs whose sample standard
 * deviation is sd: t95(m - 1) sd / sqrt(m), relative to |mean| (NaN for
 * m < 2 or a non-finite sd). A ladder of such means (assess.h
 * resolution.realisations) adds it to the band wl_loads_convergence
 * gives on the means, as Eca & Hoekstra (2014, section 4) add the data's
 * scatter to the discretisation band: the finest mean is itself uncertain
 * by this much, whatever the levels above it say. */
double wl_loads_mean_uncertainty(double sd, int m, double mean);

/* A short name of the basis ("GCI", "3 x range", ...; "none"). */
const char *wl_loads_estimate_name(enum wl_loads_estimate e);

#endif
