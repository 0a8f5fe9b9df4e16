/* crater.c: crater shapes, their extents, net volumes and potential
 * energies, in closed form and by GSL quadrature ([S0] eqs 1-7, [S1] eqs 1-3,
 * REFERENCES.md 5.2; see include/wallload/explosion.h). */
#include "wallload/explosion.h"

#include "check.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_math.h> /* M_PI, which strict C11 <math.h> lacks */
#include <math.h>

/* Quadrature settings: the integrands are polynomials on one interval, so
 * Gauss-Kronrod 21 is exact to rounding on the first pass; the tolerances
 * only keep GSL from subdividing further. */
#define QUAD_EPSREL 1e-12
#define QUAD_EPSABS_SCALE 1e-14 /* times the problem's natural scale */
#define QUAD_LIMIT 100

/* f(u) = c0 + c1 u^2 + c2 u^4 on 0 <= u <= ext, zero beyond. */
struct profile {
  double c0, c1, c2;
  double ext;  /* outer radius / R */
  double root; /* inner zero (still-water crossing) / R */
  double vol2; /* 2D net area / (eta0 R) */
  double vol3; /* 3D net volume / (pi eta0 R^2) */
  double en2;  /* 2D energy / (rho g eta0^2 R) */
  double en3;  /* 3D energy / (pi rho g eta0^2 R^2) */
};

/* The closed forms. Each fraction is the exact integral of the polynomial
 * (derivation in explosion.h; checked against quadrature in the tests):
 *   vol2 = 2 int_0^ext f du,        vol3 = 2 int_0^ext f u du,
 *   en2  = int_0^ext f^2 du,        en3  = int_0^ext f^2 u du. */
static int get_profile(enum wl_crater_shape shape, struct profile *p) {
  switch (shape) {
  case WL_CRATER_SHAPE_QUADRATIC:
    *p = (struct profile){-1.0, 1.0, 0.0, 1.0, 1.0, -4.0 / 3.0, -0.5, 8.0 / 15.0, 1.0 / 6.0};
    return 1;
  case WL_CRATER_SHAPE_QUADRATIC_LIP_AXI:
    *p = (struct profile){-1.0, 2.0, 0.0, 1.0, sqrt(0.5), -2.0 / 3.0, 0.0, 7.0 / 15.0, 1.0 / 6.0};
    return 1;
  case WL_CRATER_SHAPE_QUADRATIC_LIP_PLANE:
    *p = (struct profile){-1.0, 3.0, 0.0, 1.0, sqrt(1.0 / 3.0), 0.0, 0.5, 4.0 / 5.0, 0.5};
    return 1;
  case WL_CRATER_SHAPE_QUARTIC_LIP_AXI:
    *p = (struct profile){-1.0, 4.0 / 3.0, -1.0 / 3.0, sqrt(3.0), 1.0,
                          -8.0 * sqrt(3.0) / 15.0, 0.0, 32.0 * sqrt(3.0) / 105.0, 1.0 / 5.0};
    return 1;
  case WL_CRATER_SHAPE_QUARTIC_LIP_PLANE:
    *p = (struct profile){-1.0, 6.0 / 5.0, -1.0 / 5.0, sqrt(5.0), 1.0,
                          0.0, 5.0 / 3.0, 128.0 * sqrt(5.0) / 315.0, 5.0 / 6.0};
    return 1;
  }
  return 0;
}

static double profile_f(const struct profile *p, double u) {
  if (u > p->ext) return 0.0;
  double u2 = u * u;
  return p->c0 + u2 * (p->c1 + u2 * p->c2);
}

const char *wl_explosion_shape_name(enum wl_crater_shape shape) {
  switch (shape) {
  case WL_CRATER_SHAPE_QUADRATIC: return "quadratic";
  case WL_CRATER_SHAPE_QUADRATIC_LIP_AXI: return "quadratic-lip-axi";
  case WL_CRATER_SHAPE_QUADRATIC_LIP_PLANE: return "quadratic-lip-plane";
  case WL_CRATER_SHAPE_QUARTIC_LIP_AXI: return "quartic-lip-axi";
  case WL_CRATER_SHAPE_QUARTIC_LIP_PLANE: return "quartic-lip-plane";
  }
  return "unknown";
}

/* ---- argument checks: each sets the error and returns its status ------- */

static enum wl_status check_shape(enum wl_crater_shape shape, struct profile *p,
                                  struct wl_error *err) {
  if (!get_profile(shape, p))
    return wl_error_set(err, WL_EINPUT,
                        "explosion: crater shape: found %d; valid are quadratic, "
                        "quadratic-lip-axi, quadratic-lip-plane, quartic-lip-axi, "
                        "quartic-lip-plane",
                        (int)shape);
  return WL_OK;
}

/* Shape, dims (when dims_needed), eta0 >= 0, R > 0. */
static enum wl_status check_crater(enum wl_crater_shape shape, int dims, int dims_needed,
                                   double eta0, double R, struct profile *p,
                                   struct wl_error *err) {
  enum wl_status st = check_shape(shape, p, err);
  if (st == WL_OK && dims_needed) st = check_dims(dims, err);
  if (st == WL_OK) st = check_nonneg("crater depth eta0 [m]", eta0, err);
  if (st == WL_OK) st = check_positive("crater radius R [m]", R, err);
  return st;
}

/* ---- shape, extent ------------------------------------------------------ */

enum wl_status wl_explosion_eta(enum wl_crater_shape shape, double eta0, double R, double r,
                                double *eta, struct wl_error *err) {
  struct profile p = {0};
  enum wl_status st = check_crater(shape, 0, 0, eta0, R, &p, err);
  if (st == WL_OK) st = check_nonneg("distance from the crater axis r [m]", r, err);
  if (st != WL_OK) return st;
  *eta = eta0 * profile_f(&p, r / R);
  return WL_OK;
}

enum wl_status wl_explosion_rim_height(enum wl_crater_shape shape, double eta0, double *height,
                                       struct wl_error *err) {
  struct profile p = {0};
  enum wl_status st = check_crater(shape, 0, 0, eta0, 1.0, &p, err);
  if (st != WL_OK) return st;
  /* f = c0 + c1 u^2 + c2 u^4 on [0, ext]: largest at an end or where
   * df/d(u^2) = c1 + 2 c2 u^2 = 0 */
  double f = fmax(profile_f(&p, 0.0), profile_f(&p, p.ext));
  if (p.c2 < 0) {
    const double u2 = -p.c1 / (2.0 * p.c2);
    if (u2 > 0 && u2 < p.ext * p.ext) f = fmax(f, profile_f(&p, sqrt(u2)));
  }
  *height = eta0 * fmax(f, 0.0);
  return WL_OK;
}

enum wl_status wl_explosion_extent(enum wl_crater_shape shape, double R, double *extent,
                                   struct wl_error *err) {
  struct profile p = {0};
  enum wl_status st = check_crater(shape, 0, 0, 0.0, R, &p, err);
  if (st != WL_OK) return st;
  *extent = p.ext * R;
  return WL_OK;
}

enum wl_status wl_explosion_inner_radius(enum wl_crater_shape shape, double R, double *rc,
                                         struct wl_error *err) {
  struct profile p = {0};
  enum wl_status st = check_crater(shape, 0, 0, 0.0, R, &p, err);
  if (st != WL_OK) return st;
  *rc = p.root * R;
  return WL_OK;
}

/* ---- closed forms ------------------------------------------------------- */

enum wl_status wl_explosion_net_volume(enum wl_crater_shape shape, int dims, double eta0, double R,
                                       double *volume, struct wl_error *err) {
  struct profile p = {0};
  enum wl_status st = check_crater(shape, dims, 1, eta0, R, &p, err);
  if (st != WL_OK) return st;
  *volume = dims == 2 ? p.vol2 * eta0 * R : p.vol3 * M_PI * eta0 * R * R;
  return WL_OK;
}

int wl_explosion_conserves_mass(enum wl_crater_shape shape, int dims) {
  struct profile p = {0};
  if (!get_profile(shape, &p) || (dims != 2 && dims != 3)) return 0;
  return (dims == 2 ? p.vol2 : p.vol3) == 0.0;
}

enum wl_status wl_explosion_energy(enum wl_crater_shape shape, int dims, double rho, double g,
                                   double eta0, double R, double *energy, struct wl_error *err) {
  struct profile p = {0};
  enum wl_status st = check_crater(shape, dims, 1, eta0, R, &p, err);
  if (st == WL_OK) st = check_water(rho, g, err);
  if (st != WL_OK) return st;
  double base = rho * g * eta0 * eta0 * R;
  *energy = dims == 2 ? p.en2 * base : p.en3 * M_PI * base * R;
  return WL_OK;
}

/* ---- quadrature --------------------------------------------------------- */

struct quad_ctx {
  const struct profile *p;
  double eta0, R;
  int dims;
  int power; /* 1: eta (volume); 2: eta^2 / 2 (energy density) */
};

/* 2D: integrand over x in [-ext R, ext R]; 3D: over r in [0, ext R] with the
 * 2 pi r ring weight. */
static double quad_integrand(double s, void *vctx) {
  const struct quad_ctx *c = vctx;
  double eta = c->eta0 * profile_f(c->p, fabs(s) / c->R);
  double v = c->power == 1 ? eta : 0.5 * eta * eta;
  return c->dims == 2 ? v : 2.0 * M_PI * s * v;
}

/* Integrate over the crater in pieces that do not change sign (crater,
 * lip), so a zero net volume is the sum of two accurately known parts
 * rather than a relative tolerance on zero. */
static enum wl_status integrate(const struct quad_ctx *c, double scale, double *out,
                                struct wl_error *err) {
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(QUAD_LIMIT);
  if (!ws)
    return wl_error_set(err, WL_ENOMEM,
                        "explosion: quadrature workspace of %d intervals could not be allocated",
                        QUAD_LIMIT);
  gsl_function F = {quad_integrand, (void *)c};
  double b = c->p->ext * c->R, r1 = c->p->root * c->R;
  /* breakpoints: 2D -b, -r1, r1, b; 3D 0, r1, b (empty pieces skipped) */
  double pts[4];
  int n_pts = 0;
  if (c->dims == 2) {
    pts[n_pts++] = -b;
    if (r1 < b) pts[n_pts++] = -r1;
  } else {
    pts[n_pts++] = 0.0;
  }
  pts[n_pts++] = r1;
  if (r1 < b) pts[n_pts++] = b;
  double total = 0.0;
  for (int i = 0; i + 1 < n_pts; i++) {
    double result = 0.0, abserr = 0.0;
    int rc = gsl_integration_qag(&F, pts[i], pts[i + 1], QUAD_EPSABS_SCALE * scale, QUAD_EPSREL,
                                 QUAD_LIMIT, GSL_INTEG_GAUSS21, ws, &result, &abserr);
    if (rc != GSL_SUCCESS) {
      gsl_integration_workspace_free(ws);
      return wl_error_set(err, WL_ENUMERIC,
                          "explosion: quadrature over [%g, %g] m failed: %s (estimate %g +- %g)",
                          pts[i], pts[i + 1], gsl_strerror(rc), result, abserr);
    }
    total += result;
  }
  gsl_integration_workspace_free(ws);
  *out = total;
  return WL_OK;
}

enum wl_status wl_explosion_net_volume_quad(enum wl_crater_shape shape, int dims, double eta0,
                                            double R, double *volume, struct wl_error *err) {
  struct profile p = {0};
  enum wl_status st = check_crater(shape, dims, 1, eta0, R, &p, err);
  if (st != WL_OK) return st;
  struct quad_ctx c = {&p, eta0, R, dims, 1};
  double scale = dims == 2 ? eta0 * R : eta0 * R * R;
  return integrate(&c, scale, volume, err);
}

enum wl_status wl_explosion_energy_quad(enum wl_crater_shape shape, int dims, double rho, double g,
                                        double eta0, double R, double *energy,
                                        struct wl_error *err) {
  struct profile p = {0};
  enum wl_status st = check_crater(shape, dims, 1, eta0, R, &p, err);
  if (st == WL_OK) st = check_water(rho, g, err);
  if (st != WL_OK) return st;
  struct quad_ctx c = {&p, eta0, R, dims, 2};
  double scale = dims == 2 ? eta0 * eta0 * R : eta0 * eta0 * R * R;
  double half_eta2 = 0.0;
  st = integrate(&c, scale, &half_eta2, err);
  if (st != WL_OK) return st;
  *energy = rho * g * half_eta2;
  return WL_OK;
}
