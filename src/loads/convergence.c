/* convergence.c: observed order of convergence, Richardson extrapolation and
 * relative error estimate over a resolution ladder (definitions in loads.h;
 * Roache 1998, "Verification and Validation in Computational Science and
 * Engineering", ch. 5; Celik et al. 2008, J. Fluids Eng. 130, 078001, for
 * unequal refinement ratios). */
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

const char *wl_loads_estimate_name(enum wl_loads_estimate e) {
  switch (e) {
  case WL_LOADS_EST_LAST_CHANGE: return "last change";
  case WL_LOADS_EST_RICHARDSON: return "Richardson";
  default: return "none";
  }
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
  /* the fallback: the last change, relative to the finest value */
  out->error = fabs(f3 - f2) / fabs(f3);
  out->basis = WL_LOADS_EST_LAST_CHANGE;
  if (n < 3) return;
  double h1 = h[n - 3], f1 = f[n - 3];
  if (!isfinite(f1) || !(h1 > h2)) return;
  out->r21 = h1 / h2;
  double d12 = f1 - f2, d23 = f2 - f3;
  if (d12 == 0.0 || d23 == 0.0 || (d12 > 0) != (d23 > 0)) return; /* no order */
  double q = d12 / d23; /* > 0 */
  double a = log(out->r21), b = log(out->r32);
  if (fabs(a - b) <= EQUAL_RATIO_TOL * b) {
    out->order = log(q) / b;
  } else {
    double lq = log(q), lo = -ORDER_BRACKET, hi = ORDER_BRACKET;
    if (lq < log_ratio_model(a, b, lo) || lq > log_ratio_model(a, b, hi)) return;
    while (hi - lo > ORDER_TOL) {
      double mid = 0.5 * (lo + hi);
      if (log_ratio_model(a, b, mid) < lq) lo = mid;
      else hi = mid;
    }
    out->order = 0.5 * (lo + hi);
  }
  if (!(out->order >= WL_LOADS_ORDER_MIN && out->order <= WL_LOADS_ORDER_MAX)) return;
  out->order_ok = 1;
  out->extrapolated = f3 + (f3 - f2) / (pow(out->r32, out->order) - 1.0);
  out->error = fabs(f3 - out->extrapolated) / fabs(out->extrapolated);
  out->basis = WL_LOADS_EST_RICHARDSON;
}
