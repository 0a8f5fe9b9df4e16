/* convergence.c: observed order of convergence, Richardson extrapolation and
 * the uncertainty of the finest value over a resolution ladder (definitions
 * and sources in loads.h: Roache's grid convergence index with Eca &
 * Hoekstra's order bands; Celik et al. 2008 for unequal refinement ratios). */
#include <math.h>

#include "wallload/loads.h"

/* Ratios closer than this are treated as one constant ratio (closed form). */
#define EQUAL_RATIO_TOL 1e-9
/* Bisection bracket for the order with unequal ratios, and its tolerance. */
#define ORDER_BRACKET 20.0
#define ORDER_TOL 1e-12

/* ln of r32^p (r21^p - 1)/(r32^p - 1) = ln((e^{a p} - 1)/(1 - e^{-b p})),
 * a = ln r21, b = ln r32; its limit a/b at p = 0. Increasing in p. */
static double log_ratio_model(double a, double b, double p) {
  if (p == 0.0) return log(a / b);
  return log(expm1(a * p) / -expm1(-b * p));
}

double wl_loads_t95(int dof) {
  static const double t[30] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306,
                               2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120,
                               2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
                               2.060,  2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof < 1) return NAN;
  return dof <= 30 ? t[dof - 1] : 1.96 + 2.4 / dof;
}

double wl_loads_mean_uncertainty(double sd, int m, double mean) {
  if (m < 2 || !isfinite(sd) || !isfinite(mean) || mean == 0.0) return NAN;
  return wl_loads_t95(m - 1) * sd / sqrt((double)m) / fabs(mean);
}

const char *wl_loads_estimate_name(enum wl_loads_estimate e) {
  switch (e) {
  case WL_LOADS_EST_TWO_LEVEL: return "two levels, order 2 assumed";
  case WL_LOADS_EST_GCI: return "GCI";
  case WL_LOADS_EST_GCI_LOW: return "GCI, low order";
  case WL_LOADS_EST_GCI_HIGH: return "GCI, order capped at 2";
  case WL_LOADS_EST_RANGE: return "3 x range";
  case WL_LOADS_EST_SAMPLED: return "GCI, order 2, within sampling";
  default: return "none";
  }
}

/* |f3 - f_ext(p)|: Richardson's estimate of the finest value's error. */
static double richardson_delta(double f2, double f3, double r32, double p) {
  return fabs(f3 - f2) / (pow(r32, p) - 1.0);
}

/* The observed order of three levels whose differences d12 = f1 - f2 and
 * d23 = f2 - f3 have one sign, at ratios r21, r32; +-ORDER_BRACKET where the
 * equation's root lies beyond the bracket. */
static double observed_order(double d12, double d23, double r21, double r32) {
  double lq = log(d12 / d23), a = log(r21), b = log(r32);
  if (fabs(a - b) <= EQUAL_RATIO_TOL * b) return lq / b;
  double lo = -ORDER_BRACKET, hi = ORDER_BRACKET;
  if (lq <= log_ratio_model(a, b, lo)) return lo;
  if (lq >= log_ratio_model(a, b, hi)) return hi;
  while (hi - lo > ORDER_TOL) {
    double mid = 0.5 * (lo + hi);
    if (log_ratio_model(a, b, mid) < lq) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

void wl_loads_convergence(const double *h, const double *f, int n,
                          struct wl_loads_convergence *out) {
  out->n_used = n < 3 ? (n > 0 ? n : 0) : 3;
  out->r21 = out->r32 = out->order = out->extrapolated = out->error = NAN;
  out->order_ok = 0;
  out->basis = WL_LOADS_EST_NONE;
  if (n < 2) return;
  double h2 = h[n - 2], h3 = h[n - 1], f2 = f[n - 2], f3 = f[n - 1];
  if (!isfinite(f2) || !isfinite(f3) || !(h3 > 0) || !(h2 > h3)) return;
  out->r32 = h2 / h3;
  /* two levels: Roache's two-grid GCI with the order assumed */
  out->error = WL_LOADS_SAFETY_ASSUMED * richardson_delta(f2, f3, out->r32, WL_LOADS_ORDER_ASSUMED) /
               fabs(f3);
  out->basis = WL_LOADS_EST_TWO_LEVEL;
  if (n < 3) return;
  double h1 = h[n - 3], f1 = f[n - 3];
  if (!isfinite(f1) || !(h1 > h2)) return;
  out->r21 = h1 / h2;
  const double range = fmax(f1, fmax(f2, f3)) - fmin(f1, fmin(f2, f3));
  double d12 = f1 - f2, d23 = f2 - f3;
  /* oscillating or a zero difference: the data range alone */
  out->error = 3.0 * range / fabs(f3);
  out->basis = WL_LOADS_EST_RANGE;
  if (d12 == 0.0 || d23 == 0.0 || (d12 > 0) != (d23 > 0)) return;
  const double p = observed_order(d12, d23, out->r21, out->r32);
  out->order = p;
  if (p >= WL_LOADS_ORDER_MIN && p <= WL_LOADS_ORDER_MAX) {
    out->order_ok = 1;
    out->extrapolated = f3 + (f3 - f2) / (pow(out->r32, p) - 1.0);
  }
  if (!(p > 0)) return; /* diverging: the range */
  double u;
  if (p < WL_LOADS_ORDER_LOW) {
    u = fmin(WL_LOADS_SAFETY_OBSERVED * richardson_delta(f2, f3, out->r32, p),
             WL_LOADS_SAFETY_ASSUMED * range);
    out->basis = WL_LOADS_EST_GCI_LOW;
  } else if (p < WL_LOADS_ORDER_HIGH) {
    u = WL_LOADS_SAFETY_OBSERVED * richardson_delta(f2, f3, out->r32, p);
    out->basis = WL_LOADS_EST_GCI;
  } else {
    u = fmax(WL_LOADS_SAFETY_OBSERVED * richardson_delta(f2, f3, out->r32, WL_LOADS_ORDER_ASSUMED),
             WL_LOADS_SAFETY_OBSERVED * range);
    out->basis = WL_LOADS_EST_GCI_HIGH;
  }
  out->error = u / fabs(f3);
}

void wl_loads_convergence_sampled(const double *h, const double *f, const double *u, int n,
                                  struct wl_loads_convergence *out) {
  wl_loads_convergence(h, f, n, out);
  if (n < 3 || !u || out->basis != WL_LOADS_EST_RANGE || !isfinite(out->r21)) return;
  const double f2 = f[n - 2], f3 = f[n - 1];
  const double u2 = isfinite(u[n - 2]) ? u[n - 2] : 0.0, u3 = isfinite(u[n - 1]) ? u[n - 1] : 0.0;
  const double noise = sqrt(u2 * u2 + u3 * u3);
  if (!(noise > 0.0) || fabs(f3 - f2) > noise) return;
  const double f1 = f[n - 3];
  const double range = fmax(f1, fmax(f2, f3)) - fmin(f1, fmin(f2, f3));
  const double v = fmax(WL_LOADS_SAFETY_OBSERVED *
                            richardson_delta(f2, f3, out->r32, WL_LOADS_ORDER_ASSUMED),
                        WL_LOADS_SAFETY_OBSERVED * range);
  out->order = out->extrapolated = NAN;
  out->order_ok = 0;
  out->error = v / fabs(f3);
  out->basis = WL_LOADS_EST_SAMPLED;
}
