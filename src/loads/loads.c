/* loads.c: profile integration, time integrals, zero-phase filtering and
 * peak measures; definitions in loads.h. */
#include "wallload/loads.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/units.h"

void wl_loads_profile(const double *z, const double *p, size_t n, double z_toe, double z_top,
                      double *force, double *moment) {
  double f = 0.0, m = 0.0;
  /* Below the first probe and above the last: the end value held. */
  f += p[0] * (z[0] - z_toe);
  m += p[0] * 0.5 * ((z[0] - z_toe) * (z[0] - z_toe));
  for (size_t k = 0; k + 1 < n; k++) {
    double dz = z[k + 1] - z[k];
    f += 0.5 * (p[k] + p[k + 1]) * dz;
    /* exact moment of the linear interpolant over [z_k, z_k+1] about z_toe */
    double a = z[k] - z_toe, b = z[k + 1] - z_toe;
    m += dz * (p[k] * (2 * a + b) + p[k + 1] * (a + 2 * b)) / 6.0;
  }
  double top = z_top - z[n - 1];
  f += p[n - 1] * top;
  m += p[n - 1] * 0.5 * ((z_top - z_toe) * (z_top - z_toe) - (z[n - 1] - z_toe) * (z[n - 1] - z_toe));
  *force = f;
  *moment = m;
}

void wl_loads_cumulative(const double *t, const double *f, size_t n, double *out) {
  if (n == 0) return;
  out[0] = 0.0;
  for (size_t k = 1; k < n; k++) out[k] = out[k - 1] + 0.5 * (f[k] + f[k - 1]) * (t[k] - t[k - 1]);
}

int wl_loads_rest_window(double quiet_until, double depth, double c0, double *t0, double *t1) {
  const double period = 4.0 * depth / c0;
  *t0 = 2.0 * period;
  *t1 = quiet_until;
  return isfinite(period) && period > 0 && isfinite(quiet_until) && *t1 - *t0 >= 2.0 * period;
}

double wl_loads_mean(const double *t, const double *x, size_t n, double t0, double t1) {
  size_t k0 = 0;
  while (k0 < n && t[k0] < t0) k0++;
  size_t k1 = k0;
  while (k1 < n && t[k1] <= t1) k1++;
  if (k1 - k0 < 4) return NAN;
  double s = 0.0;
  for (size_t k = k0 + 1; k < k1; k++) s += 0.5 * (x[k] + x[k - 1]) * (t[k] - t[k - 1]);
  return s / (t[k1 - 1] - t[k0]);
}

double wl_loads_cutoff(double c0, double depth, double dt_sample) {
  double fc = c0 / (8.0 * depth);
  double cap = 0.4 * 0.5 / dt_sample;
  return fc < cap ? fc : cap;
}

/* One pass of a second-order Butterworth low-pass (bilinear transform with
 * prewarping), direct form II transposed, started at rest on x[0]. */
static void butter2(const double *x, size_t n, double dt, double fc, double *y) {
  double K = tan(WL_PI * fc * dt);
  double norm = 1.0 / (1.0 + sqrt(2.0) * K + K * K);
  double b0 = K * K * norm, b1 = 2 * b0, b2 = b0;
  double a1 = 2 * (K * K - 1) * norm, a2 = (1 - sqrt(2.0) * K + K * K) * norm;
  /* steady state for a constant input x[0] */
  double z1 = x[0] - b0 * x[0], z2 = b2 * x[0] - a2 * x[0];
  for (size_t k = 0; k < n; k++) {
    double yk = b0 * x[k] + z1;
    z1 = b1 * x[k] - a1 * yk + z2;
    z2 = b2 * x[k] - a2 * yk;
    y[k] = yk;
  }
}

enum wl_status wl_loads_lowpass(const double *x, size_t n, double dt, double fc, double *out,
                                struct wl_error *err) {
  if (n < 4) return wl_error_set(err, WL_EINPUT, "low-pass filter: %zu samples; need at least 4", n);
  if (!(fc > 0 && fc < 0.5 / dt))
    return wl_error_set(err, WL_EINPUT,
                        "low-pass filter: cut-off %g Hz; valid: above 0 and below the Nyquist "
                        "frequency %g Hz",
                        fc, 0.5 / dt);
  /* Pad both ends by odd reflection (about the end values) over a few
   * filter time constants, so the edges start without a transient. */
  size_t pad = (size_t)ceil(3.0 / (fc * dt));
  if (pad > n - 1) pad = n - 1;
  size_t m = n + 2 * pad;
  double *a = malloc(m * sizeof *a), *b = malloc(m * sizeof *b);
  if (!a || !b) {
    free(a);
    free(b);
    return wl_error_set(err, WL_ENOMEM, "low-pass filter: no memory for %zu samples", m);
  }
  for (size_t k = 0; k < pad; k++) {
    a[pad - 1 - k] = 2 * x[0] - x[k + 1];
    a[pad + n + k] = 2 * x[n - 1] - x[n - 2 - k];
  }
  memcpy(a + pad, x, n * sizeof *x);
  butter2(a, m, dt, fc, b);
  for (size_t k = 0; k < m / 2; k++) { /* reverse */
    double tmp = b[k];
    b[k] = b[m - 1 - k];
    b[m - 1 - k] = tmp;
  }
  butter2(b, m, dt, fc, a);
  for (size_t k = 0; k < n; k++) out[k] = a[m - 1 - pad - k];
  free(a);
  free(b);
  return WL_OK;
}

void wl_loads_positive_phase(const double *x, size_t n, double base, size_t ip, size_t *i0,
                             size_t *i1) {
  size_t a = ip, b = ip;
  if (x[ip] > base) {
    while (a > 0 && x[a] > base) a--;
    while (b + 1 < n && x[b] > base) b++;
  }
  *i0 = a;
  *i1 = b;
}

double wl_loads_positive_phase_impulse(const double *t, const double *xf, const double *I,
                                       size_t n, double base, size_t ip, double *t0, double *t1) {
  size_t a, b;
  wl_loads_positive_phase(xf, n, base, ip, &a, &b);
  *t0 = t[a];
  *t1 = t[b];
  return I[b] - I[a];
}

void wl_loads_peak(const double *t, const double *x, size_t n, double base, struct wl_peak *pk) {
  size_t ip = 0;
  for (size_t k = 1; k < n; k++)
    if (x[k] - base > x[ip] - base) ip = k;
  pk->index = ip;
  pk->value = x[ip];
  pk->time = t[ip];
  double level = WL_LOADS_THRESHOLD * (x[ip] - base);
  pk->rise_time = NAN;
  pk->duration = NAN;
  if (!(level > 0)) return;
  /* rise: back from the peak to the last sample below the threshold,
   * interpolated linearly to the crossing */
  size_t k = ip;
  while (k > 0 && x[k] - base >= level) k--;
  if (x[k] - base < level) {
    double f0 = x[k] - base, f1 = x[k + 1] - base;
    double tc = t[k] + (level - f0) / (f1 - f0) * (t[k + 1] - t[k]);
    pk->rise_time = pk->time - tc;
    /* duration: from that upward crossing to the last downward crossing */
    size_t j = n - 1;
    while (j > ip && x[j] - base < level) j--;
    double t_end = t[j];
    if (j + 1 < n) {
      double g0 = x[j] - base, g1 = x[j + 1] - base;
      t_end = t[j] + (g0 - level) / (g0 - g1) * (t[j + 1] - t[j]);
    }
    pk->duration = t_end - tc;
  }
}

double wl_loads_time_above(const double *t, const double *xf, size_t n, double base) {
  double sum = 0;
  for (size_t k = 0; k + 1 < n; k++) {
    const double a = xf[k] - base, b = xf[k + 1] - base, dt = t[k + 1] - t[k];
    if (a >= 0 && b >= 0)
      sum += dt;
    else if (a > 0)
      sum += dt * a / (a - b);
    else if (b > 0)
      sum += dt * b / (b - a);
  }
  return sum;
}

double wl_loads_halves_spread(const double *t, const double *x, size_t n, double t0, double t1) {
  const double tm = 0.5 * (t0 + t1);
  return 0.5 * fabs(wl_loads_mean(t, x, n, t0, tm) - wl_loads_mean(t, x, n, tm, t1));
}

double wl_loads_positive_impulse(const double *t, const double *xf, size_t n, double base) {
  double sum = 0;
  for (size_t k = 0; k + 1 < n; k++) {
    const double a = xf[k] - base, b = xf[k + 1] - base, dt = t[k + 1] - t[k];
    if (a >= 0 && b >= 0)
      sum += 0.5 * (a + b) * dt;
    else if (a > 0) /* crosses down at dt a/(a - b) */
      sum += 0.5 * a * dt * a / (a - b);
    else if (b > 0) /* crosses up */
      sum += 0.5 * b * dt * b / (b - a);
  }
  return sum;
}
