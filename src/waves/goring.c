/* goring.c: Goring (1978) piston-paddle trajectory for a first-order
 * solitary wave (REFERENCES 3.5):
 *   X_p(t) = (H/(K h)) [tanh(K (c t - X_p - lambda)) + tanh(K lambda)],
 * the exact integral of dX_p/dt = c eta/(h + eta) with eta = H sech^2(K(ct -
 * X_p - lambda)). lambda = arccosh(1/sqrt(eps0))/K puts the crest where
 * eta(paddle) = eps0 H at t = 0. The paddle stops when eta(paddle) has fallen
 * back to eps0 H, i.e. when c t - X_p - lambda = lambda; then
 * X_p = S tanh(K lambda) = S sqrt(1 - eps0) =: x_end and
 * t = (2 lambda + x_end)/c (the usual "~ 2 lambda/c" without the paddle's own
 * displacement). No allocation. */
#include "wallload/waves.h"

#include <math.h>
#include <string.h>

/* Newton/bisection: stop when the bracket or step is below this relative size. */
static const double ROOT_EPSREL = 4e-16;
enum { ROOT_MAX_ITER = 200 };

enum wl_status wl_waves_goring_init(struct wl_goring *gp, double h, double H, double g,
                                    double eps0, struct wl_error *err) {
  memset(gp, 0, sizeof *gp);
  struct wl_solitary sw;
  enum wl_status st = wl_waves_solitary_init(&sw, WL_SOLITARY_BOUSSINESQ, h, H, g, err);
  if (st != WL_OK) {
    wl_error_prefix(err, "Goring paddle: ");
    return st;
  }
  if (!(isfinite(eps0) && eps0 > 0 && eps0 < 1))
    return wl_error_set(err, WL_EINPUT,
                        "Goring paddle: start threshold eps0 = %g; valid: 0 < eps0 < 1 "
                        "(default %g, Goring 1978)",
                        eps0, WL_WAVES_GORING_EPS0_DEFAULT);
  gp->h = h;
  gp->H = H;
  gp->g = g;
  gp->eps0 = eps0;
  gp->K = sw.K;
  gp->c = sw.c;
  gp->lambda = acosh(1.0 / sqrt(eps0)) / sw.K;
  gp->stroke = 2.0 * H / (sw.K * h);
  gp->x_end = gp->stroke * sqrt(1.0 - eps0);
  gp->duration = (2.0 * gp->lambda + gp->x_end) / gp->c;
  return WL_OK;
}

double wl_waves_goring_position(const struct wl_goring *gp, double t) {
  if (!(t > 0)) return 0.0;
  if (t >= gp->duration) return gp->x_end;
  /* F(X) = X - a [tanh(K(ct - X - lambda)) + tanh(K lambda)], a = S/2, is
   * strictly increasing (F' = 1 + a K sech^2 >= 1), and F(lo) <= 0 <= F(hi)
   * on [a(tanh(K lambda) - 1), a(tanh(K lambda) + 1)] since tanh is in (-1, 1). */
  const double a = 0.5 * gp->stroke, K = gp->K, tl = tanh(K * gp->lambda);
  const double ct_l = gp->c * t - gp->lambda;
  double lo = a * (tl - 1.0), hi = a * (tl + 1.0);
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < ROOT_MAX_ITER; it++) {
    double th = tanh(K * (ct_l - x));
    double F = x - a * (th + tl);
    if (F == 0.0) return x;
    if (F < 0) lo = x;
    else hi = x;
    double dF = 1.0 + a * K * (1.0 - th * th);
    double xn = x - F / dF;
    if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi); /* Newton left the bracket: bisect */
    double tol = ROOT_EPSREL * fmax(fabs(xn), a);
    if (fabs(xn - x) <= tol || hi - lo <= tol) return xn;
    x = xn;
  }
  return x;
}

double wl_waves_goring_velocity(const struct wl_goring *gp, double t) {
  if (!(t > 0) || t >= gp->duration) return 0.0;
  double X = wl_waves_goring_position(gp, t);
  double ch = cosh(gp->K * (gp->c * t - X - gp->lambda));
  double eta = gp->H / (ch * ch);
  return gp->c * eta / (gp->h + eta);
}
