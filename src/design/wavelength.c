/* wavelength.c: linear dispersion, omega^2 = g k tanh(k h) [DISP], solved
 * for x = k h from x tanh x = y, y = omega^2 h / g, by Newton's method
 * started from the explicit estimate of Fenton & McKee (1990),
 * x0 = y / tanh(y^(3/4))^(2/3), within 2 % of the root everywhere, so that
 * Newton converges in a few steps from deep to shallow water. */
#include "internal.h"

#include <float.h>

#define DISP_MAX_ITER 60                 /* Newton from within 2 % needs < 10 */
#define DISP_REL_STEP (4.0 * DBL_EPSILON) /* stop when |dx| <= this * x */

enum wl_status wl_design_wavelength(double T, double h, double g, double *L, struct wl_error *err) {
  enum wl_status st = check_positive("wave period T [s]", T, err);
  if (st == WL_OK) st = check_positive("water depth h [m]", h, err);
  if (st == WL_OK) st = check_positive("gravity g [m/s^2]", g, err);
  if (st != WL_OK) return st;

  const double omega = 2.0 * WL_PI / T;
  const double y = omega * omega * h / g;
  if (!isfinite(y) || y <= 0.0)
    return wl_error_set(err, WL_EINPUT,
                        "design: omega^2 h / g: found %g for T = %g s, h = %g m; must be "
                        "positive and finite",
                        y, T, h);
  double x = y / pow(tanh(pow(y, 0.75)), 2.0 / 3.0);
  for (int it = 0; it < DISP_MAX_ITER; it++) {
    double t = tanh(x);
    double c = cosh(x);
    /* F = x tanh x - y, F' = tanh x + x / cosh^2 x (cosh overflows to inf
     * in deep water, where the second term is 0 anyway). */
    double dF = t + (isfinite(c) ? x / (c * c) : 0.0);
    double dx = (x * t - y) / dF;
    x -= dx;
    if (fabs(dx) <= DISP_REL_STEP * x) {
      *L = 2.0 * WL_PI * h / x;
      return WL_OK;
    }
  }
  return wl_error_set(err, WL_ENUMERIC,
                      "design: wavelength: Newton did not converge in %d steps for T = %g s, "
                      "h = %g m",
                      DISP_MAX_ITER, T, h);
}
