/* integrals.c: mass, momentum and energies of a solitary wave per unit crest
 * width by GSL quadrature of its profile and velocity field; the first-order
 * closed forms; the Longuet-Higgins (1974) highest-wave profile of seed 001
 * (eqs 17, 21, 22); the energy -> height inversion (GSL Brent).
 *
 * GSL is used only through its status-returning calls; the library never
 * changes GSL's error handler (the CLI turns the abort handler off). */
#include "wallload/waves.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <string.h>

/* Quadrature: relative target for the outer (x) and inner (z) integrals. The
 * inner integrands are polynomials in z of degree <= 10, integrated exactly
 * by one 21-point Gauss-Kronrod rule; the outer ones decay like e^{-2KX}. */
enum { QUAD_LIMIT = 1000 };
static const double QUAD_EPSREL_OUTER = 1e-11;
static const double QUAD_EPSREL_INNER = 1e-13;

/* Energy inversion: relative tolerance on eps and iteration cap. */
static const double ROOT_EPSREL = 1e-12;
enum { ROOT_MAX_ITER = 200 };

enum quantity { Q_MASS, Q_MOMENTUM, Q_KINETIC, Q_POTENTIAL };

struct quad {
  const struct wl_solitary *sw;
  enum quantity what;
  double X;                        /* current abscissa of the inner integral [m] */
  gsl_integration_workspace *wz;   /* inner workspace */
  int status;                      /* first GSL failure of an inner integral */
};

static double inner_integrand(double z, void *p) {
  struct quad *qd = p;
  double u, w;
  wl_waves_solitary_velocity(qd->sw, qd->X, z, &u, &w);
  return qd->what == Q_MOMENTUM ? u : u * u + w * w;
}

/* Integrand in xi = K X >= 0 (the wave is symmetric about its crest). */
static double outer_integrand(double xi, void *p) {
  struct quad *qd = p;
  const struct wl_solitary *sw = qd->sw;
  double X = xi / sw->K;
  double eta = wl_waves_solitary_eta(sw, X);
  switch (qd->what) {
  case Q_MASS: return eta;
  case Q_POTENTIAL: return eta * eta;
  case Q_MOMENTUM:
  case Q_KINETIC: break;
  }
  qd->X = X;
  gsl_function f = {inner_integrand, qd};
  double r = 0, e = 0;
  int st = gsl_integration_qag(&f, 0.0, sw->h + eta, 0.0, QUAD_EPSREL_INNER, QUAD_LIMIT,
                               GSL_INTEG_GAUSS21, qd->wz, &r, &e);
  /* Roundoff-limited results of an exactly integrated polynomial are fine. */
  if (st != GSL_SUCCESS && st != GSL_EROUND && qd->status == GSL_SUCCESS) qd->status = st;
  return r;
}

/* int_{-inf}^{inf} dx (of eta, eta^2, or the inner z integral) [m^2, m^3, ...]. */
static int integrate(struct quad *qd, gsl_integration_workspace *wx, double *out) {
  gsl_function f = {outer_integrand, qd};
  double r = 0, e = 0;
  qd->status = GSL_SUCCESS;
  int st = gsl_integration_qagiu(&f, 0.0, 0.0, QUAD_EPSREL_OUTER, QUAD_LIMIT, wx, &r, &e);
  if (st == GSL_SUCCESS) st = qd->status;
  *out = 2.0 * r / qd->sw->K;
  return st;
}

static const char *quantity_name(enum quantity q) {
  switch (q) {
  case Q_MASS: return "mass";
  case Q_MOMENTUM: return "momentum";
  case Q_KINETIC: return "kinetic energy";
  case Q_POTENTIAL: return "potential energy";
  }
  return "?";
}

/* The integrals with caller-provided workspaces (reused by the inversion). */
static enum wl_status integrals_ws(const struct wl_solitary *sw, double rho,
                                   gsl_integration_workspace *wx,
                                   gsl_integration_workspace *wz, struct wl_wave_integrals *out,
                                   struct wl_error *err) {
  double val[4];
  for (int k = 0; k < 4; k++) {
    struct quad qd = {.sw = sw, .what = (enum quantity)k, .wz = wz};
    int st = integrate(&qd, wx, &val[k]);
    if (st != GSL_SUCCESS)
      return wl_error_set(err, WL_ENUMERIC,
                          "solitary wave (h = %g m, H = %g m): quadrature of the %s failed: %s",
                          sw->h, sw->H, quantity_name((enum quantity)k), gsl_strerror(st));
  }
  out->mass = rho * val[Q_MASS];
  out->momentum = rho * val[Q_MOMENTUM];
  out->kinetic = 0.5 * rho * val[Q_KINETIC];
  out->potential = 0.5 * rho * sw->g * val[Q_POTENTIAL];
  out->energy = out->kinetic + out->potential;
  return WL_OK;
}

enum wl_status wl_waves_solitary_integrals(const struct wl_solitary *sw, double rho,
                                           struct wl_wave_integrals *out,
                                           struct wl_error *err) {
  memset(out, 0, sizeof *out);
  if (!(isfinite(rho) && rho > 0))
    return wl_error_set(err, WL_EINPUT, "solitary wave integrals: density rho = %g kg/m^3; "
                        "valid: finite and > 0", rho);
  if (!(sw->h > 0 && sw->K > 0))
    return wl_error_set(err, WL_EINPUT,
                        "solitary wave integrals: the wave was not initialised "
                        "(call wl_waves_solitary_init first)");
  if (sw->theory == WL_SOLITARY_EXACT) {
    /* the conformal solution's own integrals (exact.c), not a quadrature of
     * its interpolated table; test_waves compares the two */
    wl_waves_exact_integrals(&sw->exact, rho, sw->g, sw->h, out);
    return WL_OK;
  }
  gsl_integration_workspace *wx = gsl_integration_workspace_alloc(QUAD_LIMIT);
  gsl_integration_workspace *wz = gsl_integration_workspace_alloc(QUAD_LIMIT);
  enum wl_status st;
  if (!wx || !wz)
    st = wl_error_set(err, WL_ENOMEM, "solitary wave integrals: cannot allocate two GSL "
                      "quadrature workspaces of %d intervals", QUAD_LIMIT);
  else
    st = integrals_ws(sw, rho, wx, wz, out, err);
  if (wx) gsl_integration_workspace_free(wx);
  if (wz) gsl_integration_workspace_free(wz);
  if (st != WL_OK) memset(out, 0, sizeof *out);
  return st;
}

void wl_waves_solitary_closed_form(const struct wl_solitary *sw, double rho,
                                   struct wl_wave_integrals *out) {
  /* int sech^2(KX) dX = 2/K, int sech^4(KX) dX = 4/(3K), K = sqrt(3H/(4h^3)). */
  double h = sw->h, eps = sw->eps, g = sw->g;
  double c = sqrt(g * (h + sw->H));
  out->mass = rho * 4.0 * h * h * sqrt(eps / 3.0);
  out->momentum = c * out->mass;
  out->potential = 4.0 / (3.0 * sqrt(3.0)) * rho * g * h * h * h * pow(eps, 1.5);
  out->kinetic = out->potential;
  out->energy = 2.0 * out->potential;
}

/* ---- Longuet-Higgins (1974), seed 001 ---------------------------------- */

double wl_waves_lh74_eta(double h, double x) {
  double a = fabs(x / h);
  return h * (WL_WAVES_LH74_A * exp(-WL_WAVES_LH74_MU * a) +
              WL_WAVES_LH74_B * exp(-WL_WAVES_LH74_NU * a));
}

double wl_waves_lh74_energy(double rho, double g, double h) {
  return WL_WAVES_LH74_E * rho * g * h * h * h;
}

static double lh74_eta2(double xi, void *p) {
  (void)p;
  double e = wl_waves_lh74_eta(1.0, xi);
  return e * e;
}

enum wl_status wl_waves_lh74_potential(double rho, double g, double h, double *V,
                                       struct wl_error *err) {
  *V = 0;
  if (!(isfinite(rho) && rho > 0 && isfinite(g) && g > 0 && isfinite(h) && h > 0))
    return wl_error_set(err, WL_EINPUT,
                        "Longuet-Higgins potential energy: rho = %g kg/m^3, g = %g m/s^2, "
                        "h = %g m; valid: all finite and > 0", rho, g, h);
  gsl_integration_workspace *wx = gsl_integration_workspace_alloc(QUAD_LIMIT);
  if (!wx)
    return wl_error_set(err, WL_ENOMEM, "Longuet-Higgins potential energy: cannot allocate a "
                        "GSL quadrature workspace of %d intervals", QUAD_LIMIT);
  gsl_function f = {lh74_eta2, NULL};
  double r = 0, e = 0;
  int st = gsl_integration_qagiu(&f, 0.0, 0.0, QUAD_EPSREL_OUTER, QUAD_LIMIT, wx, &r, &e);
  gsl_integration_workspace_free(wx);
  if (st != GSL_SUCCESS)
    return wl_error_set(err, WL_ENUMERIC, "Longuet-Higgins potential energy: quadrature "
                        "failed: %s", gsl_strerror(st));
  /* eta = h f(x/h): int eta^2 dx = h^3 * 2 int_0^inf f^2 */
  *V = 0.5 * rho * g * h * h * h * 2.0 * r;
  return WL_OK;
}

/* ---- energy -> height --------------------------------------------------- */

struct energy_root {
  double h, g, rho, E;
  gsl_integration_workspace *wx, *wz;
  struct wl_error inner;  /* first failure inside the root function */
};

static double energy_of_eps(struct energy_root *er, double eps) {
  struct wl_solitary sw;
  if (wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, er->h, eps * er->h, er->g, &er->inner) !=
      WL_OK)
    return NAN;
  struct wl_wave_integrals wi;
  if (integrals_ws(&sw, er->rho, er->wx, er->wz, &wi, &er->inner) != WL_OK) return NAN;
  return wi.energy;
}

static double energy_residual(double eps, void *p) {
  struct energy_root *er = p;
  return energy_of_eps(er, eps) - er->E;
}

/* Hand an error met inside the root function on to the caller. */
static enum wl_status pass_inner(const struct energy_root *er, struct wl_error *err) {
  return wl_error_set(err, er->inner.status, "solitary height from energy: %s", er->inner.msg);
}

static enum wl_status height_from_energy_ws(struct energy_root *er, double *H,
                                            struct wl_error *err) {
  double lo = WL_WAVES_EPS_MIN, hi = WL_WAVES_EPS_MAX;
  double E_lo = energy_of_eps(er, lo), E_hi = energy_of_eps(er, hi);
  if (er->inner.status != WL_OK) return pass_inner(er, err);
  if (er->E > E_hi)
    return wl_error_set(err, WL_EINPUT,
                        "solitary height from energy: E = %g J/m on h = %g m; valid: %g <= E "
                        "<= %g J/m (the maximum, %.4g rho g h^3, is the energy of the Grimshaw wave "
                        "of H/h = %g, the highest accepted)",
                        er->E, er->h, E_lo, E_hi, E_hi / (er->rho * er->g * pow(er->h, 3)),
                        WL_WAVES_EPS_MAX);
  if (er->E < E_lo)
    return wl_error_set(err, WL_EINPUT,
                        "solitary height from energy: E = %g J/m on h = %g m; valid: %g <= E "
                        "<= %g J/m (H/h from %g to %g)",
                        er->E, er->h, E_lo, E_hi, WL_WAVES_EPS_MIN, WL_WAVES_EPS_MAX);
  if (er->E == E_hi) {
    *H = hi * er->h;
    return WL_OK;
  }
  if (er->E == E_lo) {
    *H = lo * er->h;
    return WL_OK;
  }

  gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  if (!s)
    return wl_error_set(err, WL_ENOMEM, "solitary height from energy: cannot allocate the "
                        "GSL Brent solver");
  gsl_function f = {energy_residual, er};
  int st = gsl_root_fsolver_set(s, &f, lo, hi);
  int iter = 0;
  while (st == GSL_SUCCESS && iter++ < ROOT_MAX_ITER) {
    st = gsl_root_fsolver_iterate(s);
    if (st != GSL_SUCCESS || er->inner.status != WL_OK) break;
    st = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0,
                                ROOT_EPSREL);
    if (st == GSL_SUCCESS) break;
    if (st == GSL_CONTINUE) st = GSL_SUCCESS;
  }
  double eps = gsl_root_fsolver_root(s);
  gsl_root_fsolver_free(s);
  if (er->inner.status != WL_OK) return pass_inner(er, err);
  if (st != GSL_SUCCESS || iter > ROOT_MAX_ITER)
    return wl_error_set(err, WL_ENUMERIC,
                        "solitary height from energy: Brent's method did not converge for E = "
                        "%g J/m, h = %g m (%s after %d iterations)",
                        er->E, er->h, st != GSL_SUCCESS ? gsl_strerror(st) : "no convergence",
                        iter);
  *H = eps * er->h;
  return WL_OK;
}

enum wl_status wl_waves_solitary_height_from_energy(double E, double h, double g, double rho,
                                                    double *H, struct wl_error *err) {
  *H = 0;
  if (!(isfinite(E) && E > 0 && isfinite(h) && h > 0 && isfinite(g) && g > 0 &&
        isfinite(rho) && rho > 0))
    return wl_error_set(err, WL_EINPUT,
                        "solitary height from energy: E = %g J/m, h = %g m, g = %g m/s^2, "
                        "rho = %g kg/m^3; valid: all finite and > 0", E, h, g, rho);
  struct energy_root er = {.h = h, .g = g, .rho = rho, .E = E};
  wl_error_clear(&er.inner);
  er.wx = gsl_integration_workspace_alloc(QUAD_LIMIT);
  er.wz = gsl_integration_workspace_alloc(QUAD_LIMIT);
  enum wl_status st;
  if (!er.wx || !er.wz)
    st = wl_error_set(err, WL_ENOMEM, "solitary height from energy: cannot allocate two GSL "
                      "quadrature workspaces of %d intervals", QUAD_LIMIT);
  else
    st = height_from_energy_ws(&er, H, err);
  if (er.wx) gsl_integration_workspace_free(er.wx);
  if (er.wz) gsl_integration_workspace_free(er.wz);
  if (st != WL_OK) *H = 0;
  return st;
}
