/* solitary.c: first-order (Boussinesq/KdV), third-order (Grimshaw 1971,
 * seed 003 eqs 21-24) and exact (tabulated, exact.c) solitary waves:
 * constructor, surface, velocity, celerity. See include/wallload/waves.h for the sources and for why z is
 * measured up from the bed. */
#include "wallload/waves.h"
#include "internal.h"

#include <math.h>
#include <string.h>

/* h, H, g finite and > 0 and WL_WAVES_EPS_MIN <= H/h <= WL_WAVES_EPS_MAX. */
static enum wl_status check_height(double h, double H, double g, const char *what,
                                   struct wl_error *err) {
  if (!(isfinite(h) && h > 0))
    return wl_error_set(err, WL_EINPUT, "%s: depth h = %g m; valid: finite and > 0", what, h);
  if (!(isfinite(H) && H > 0))
    return wl_error_set(err, WL_EINPUT, "%s: wave height H = %g m; valid: finite and > 0", what,
                        H);
  if (!(isfinite(g) && g > 0))
    return wl_error_set(err, WL_EINPUT, "%s: gravity g = %g m/s^2; valid: finite and > 0", what,
                        g);
  double eps = H / h;
  if (eps > WL_WAVES_EPS_MAX)
    return wl_error_set(err, WL_EINPUT,
                        "%s: H/h = %g (H = %g m, h = %g m); valid: %g <= H/h <= %g (the "
                        "highest solitary wave has H/h ~ 0.83, Longuet-Higgins & Fenton 1974; "
                        "mass and energy peak near 0.78; Grimshaw third order is accurate "
                        "for H/h <= %g)",
                        what, eps, H, h, WL_WAVES_EPS_MIN, WL_WAVES_EPS_MAX,
                        WL_WAVES_EPS_GRIMSHAW_ACCURATE);
  if (eps < WL_WAVES_EPS_MIN)
    return wl_error_set(err, WL_EINPUT,
                        "%s: H/h = %g (H = %g m, h = %g m); valid: %g <= H/h <= %g", what, eps, H,
                        h, WL_WAVES_EPS_MIN, WL_WAVES_EPS_MAX);
  return WL_OK;
}

enum wl_status wl_waves_solitary_init(struct wl_solitary *sw, enum wl_solitary_theory theory,
                                      double h, double H, double g, struct wl_error *err) {
  memset(sw, 0, sizeof *sw);
  if (theory != WL_SOLITARY_BOUSSINESQ && theory != WL_SOLITARY_GRIMSHAW &&
      theory != WL_SOLITARY_EXACT)
    return wl_error_set(err, WL_EINPUT,
                        "solitary wave: theory %d; valid: WL_SOLITARY_BOUSSINESQ (first "
                        "order), WL_SOLITARY_GRIMSHAW (third order) or WL_SOLITARY_EXACT",
                        (int)theory);
  enum wl_status st = check_height(h, H, g, "solitary wave", err);
  if (st != WL_OK) return st;

  double eps = H / h;
  sw->theory = theory;
  sw->h = h;
  sw->H = H;
  sw->g = g;
  sw->eps = eps;
  sw->sqrt_gh = sqrt(g * h);
  if (theory == WL_SOLITARY_BOUSSINESQ) {
    sw->K = sqrt(3.0 * H / (4.0 * h * h * h)); /* REFERENCES 3.1 */
    sw->c = sqrt(g * (h + H));
  } else if (theory == WL_SOLITARY_EXACT) {
    st = wl_waves__exact_tabulate(sw, err);
    if (st) {
      memset(sw, 0, sizeof *sw);
      return st;
    }
    sw->K = 0.5 * sw->exact.beta / h;
    sw->c = sw->sqrt_gh * sw->exact.F;
  } else {
    /* seed 003 eq 22: alpha = sqrt(3 eps/4)(1 - 5/8 eps + 71/128 eps^2), argument alpha X/h */
    double alpha = sqrt(0.75 * eps) * (1.0 - 0.625 * eps + (71.0 / 128.0) * eps * eps);
    sw->K = alpha / h;
    /* seed 003 eq 23 */
    sw->c = sw->sqrt_gh * sqrt(1.0 + eps - eps * eps / 20.0 - (3.0 / 70.0) * eps * eps * eps);
  }
  return WL_OK;
}

double wl_waves_solitary_celerity(const struct wl_solitary *sw) { return sw->c; }

const char *wl_waves_solitary_theory_text(enum wl_solitary_theory theory, int source) {
  switch (theory) {
  case WL_SOLITARY_BOUSSINESQ: return source ? "KdV first order, c = sqrt(g (h + H))" : "Boussinesq first order";
  case WL_SOLITARY_GRIMSHAW: return source ? "Grimshaw (1971); seed 003 eqs 21-24" : "Grimshaw third order";
  case WL_SOLITARY_EXACT:
    return source ? "Euler equations, Clamond & Dutykh (2013) conformal solution" : "exact (Euler)";
  }
  return "?";
}

/* sech^2 and tanh of K X, safe for any X (cosh overflows to inf, 1/inf = 0). */
static void sech2_tanh(double KX, double *s2, double *q) {
  double ch = cosh(KX);
  *s2 = 1.0 / (ch * ch);
  *q = tanh(KX);
}

/* 4-point Lagrange weights at fractional position t in [0, 1] between the
 * second and third of four equally spaced nodes. */
static void lagrange4(double t, double *w) {
  w[0] = -t * (t - 1) * (t - 2) / 6;
  w[1] = (t + 1) * (t - 1) * (t - 2) / 2;
  w[2] = -(t + 1) * t * (t - 2) / 2;
  w[3] = (t + 1) * t * (t - 1) / 6;
}

/* The four abscissa nodes of the exact wave's table around |X| (in h) and
 * their weights; nodes before the crest mirror (the table holds X >= 0) and
 * come back with parity[] = -1 where the quantity is odd. Returns 0 beyond
 * the table (the wave has decayed to nothing there). */
static int exact_nodes(const struct wl_solitary *sw, double Xh, int *node, double *wt,
                       double *parity) {
  const double a = fabs(Xh) / sw->exact_dX;
  if (!(a < WL_WAVES_EXACT_NX - 2)) return 0;
  const int i = (int)a;
  lagrange4(a - i, wt);
  for (int r = 0; r < 4; r++) {
    const int k = i - 1 + r;
    node[r] = k < 0 ? -k : k;
    parity[r] = k < 0 ? -1.0 : 1.0;
  }
  return 1;
}

/* Weights of the 4 table levels around s in [0, 1] (clamped), one-sided at
 * the bed and the surface; *j0 the first level. */
static void exact_levels(double s, int *j0, double *wt) {
  const double b = (s < 0 ? 0 : s > 1 ? 1 : s) * (WL_WAVES_EXACT_NZ - 1);
  int j = (int)b - 1;
  if (j < 0) j = 0;
  if (j > WL_WAVES_EXACT_NZ - 4) j = WL_WAVES_EXACT_NZ - 4;
  lagrange4(b - (j + 1), wt);
  *j0 = j;
}

static double exact_eta(const struct wl_solitary *sw, double X) {
  int node[4];
  double wt[4], par[4];
  if (!exact_nodes(sw, X / sw->h, node, wt, par)) return 0.0;
  double e = 0;
  for (int r = 0; r < 4; r++) e += wt[r] * sw->exact_eta[node[r]];
  return sw->h * e;
}

/* u and w of the tabulated exact wave; z above the bed, clamped to the
 * water column (the table holds the bed to the surface). */
static void exact_velocity(const struct wl_solitary *sw, double X, double z, double *u,
                           double *w) {
  int node[4], j0;
  double wt[4], par[4], wz[4];
  *u = *w = 0.0;
  if (!exact_nodes(sw, X / sw->h, node, wt, par)) return;
  const double sign = X < 0 ? -1.0 : 1.0;
  double eta = 0;
  for (int r = 0; r < 4; r++) eta += wt[r] * sw->exact_eta[node[r]];
  exact_levels(z / (sw->h * (1.0 + eta)), &j0, wz);
  double uu = 0, ww = 0;
  for (int r = 0; r < 4; r++)
    for (int q = 0; q < 4; q++) {
      uu += wt[r] * wz[q] * sw->exact_u[node[r]][j0 + q];
      ww += wt[r] * wz[q] * par[r] * sw->exact_w[node[r]][j0 + q];
    }
  *u = sw->sqrt_gh * uu;
  *w = sw->sqrt_gh * sign * ww;
}

double wl_waves_solitary_eta(const struct wl_solitary *sw, double X) {
  if (sw->theory == WL_SOLITARY_EXACT) return exact_eta(sw, X);
  double s2, q;
  sech2_tanh(sw->K * X, &s2, &q);
  if (sw->theory == WL_SOLITARY_BOUSSINESQ) return sw->H * s2;
  /* seed 003 eq 21 */
  double e = sw->eps, q2 = q * q;
  return sw->h * (e * s2 - 0.75 * e * e * s2 * q2 +
                  e * e * e * (0.625 * s2 * q2 - (101.0 / 80.0) * s2 * s2 * q2));
}

void wl_waves_solitary_velocity(const struct wl_solitary *sw, double X, double z, double *u,
                                double *w) {
  if (sw->theory == WL_SOLITARY_EXACT) {
    double uu, ww;
    exact_velocity(sw, X, z, &uu, &ww);
    if (u) *u = uu;
    if (w) *w = ww;
    return;
  }
  double s2, q;
  sech2_tanh(sw->K * X, &s2, &q);
  double uu, ww;
  if (sw->theory == WL_SOLITARY_BOUSSINESQ) {
    double h = sw->h, eta = sw->H * s2;
    double eta_X = -2.0 * sw->K * eta * q;
    double d = h + eta;
    uu = sw->c * eta / d;                 /* exact mass flux c eta, uniform in depth */
    ww = -sw->c * h * z * eta_X / (d * d); /* continuity, w = 0 at the bed */
  } else {
    /* seed 003 eq 24, z up from the bed, with the sign of the eps^3 term of w
     * corrected (see waves.h): the printed brace {-49/640 - 17/20 s^2 ...} is
     * -{49/640 - 17/20 s^2 ...} with the minus sign kept on the first term
     * only. Below, every coefficient of that brace except -49/640 has the
     * opposite sign to the print; this is what continuity du/dX + dw/dz = 0
     * gives from eq 24's u (w = -int_0^z du/dX dz', carried out by hand with
     * d(s^2n)/dxi = -2n s^2n q, s^2 q^2 = s^2 - s^4). */
    double e = sw->eps, e2 = e * e, e3 = e2 * e;
    double Z = z / sw->h, Z2 = Z * Z, Z4 = Z2 * Z2;
    double s4 = s2 * s2, q2 = q * q;
    double u1 = s2;
    double u2 = -0.75 * s2 + s2 * q2 + Z2 * (0.75 * s2 - 2.25 * s2 * q2);
    double u3 = (21.0 / 40.0) * s2 - s2 * q2 - 1.2 * s4 * q2 +
                Z2 * (-2.25 * s2 + 3.75 * s2 * q2 + 7.5 * s4 * q2) +
                Z4 * (0.375 * s2 - (45.0 / 16.0) * s4 * q2);
    uu = sw->sqrt_gh * (e * u1 + e2 * u2 + e3 * u3);
    double w1 = 1.0;
    double w2 = -0.375 - 2.0 * s2 + Z2 * (-0.5 + 1.5 * s2);
    double w3 = -49.0 / 640.0 + 0.85 * s2 + 3.6 * s4 + Z2 * (13.0 / 16.0 + (25.0 / 16.0) * s2 - 7.5 * s4) +
                Z4 * (0.075 - 1.125 * s2 + (27.0 / 16.0) * s4);
    ww = sw->sqrt_gh * sqrt(3.0 * e) * Z * s2 * q * (e * w1 + e2 * w2 + e3 * w3);
  }
  if (u) *u = uu;
  if (w) *w = ww;
}
