/* exact.c: the exact irrotational solitary wave (REFERENCES 3.4), computed by
 * the method of Clamond & Dutykh (2013) Physica D 84 / Dutykh & Clamond
 * (2014) Wave Motion 51: in conformal variables (xi along the surface, depth
 * mapped to a strip of unit height, rho = g = h = 1) the surface eta(xi)
 * solves the Babenko equation
 *   (F^2 C - 1) eta = 1/2 C(eta^2) + eta C(eta),   C = k coth(k) in Fourier space,
 * iterated with Petviashvili's stabilising factor S = (<eta,L eta>/<eta,N(eta)>)^2
 * and renormalised to the crest height eps at each step; F^2 = 1 + 3 PE/M.
 * Integrals (same papers): M = int eta (1 + C eta) dxi, PE = 1/2 int eta^2
 * (1 + C eta) dxi, KE = 1/2 F^2 int eta C eta dxi, I = F M.
 * Domain half-length 17 ln(10)/beta with the far-field decay beta solving
 * tan(beta)/beta = F^2 (F^2 first guessed from Grimshaw's eq 23), so the
 * surface has decayed to ~1e-17 at the ends. FFTs: GSL radix-2, complex. */
#include "wallload/waves.h"
#include "internal.h"

#include <complex.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;
static const double EXACT_EPS_MIN = 0.001, EXACT_EPS_MAX = 0.79;
enum { EXACT_N_MIN = 256, EXACT_N_MAX = 1 << 20, EXACT_MAX_ITER = 2000 };
/* Convergence: max |eta_{n+1} - eta_n| / eps below this. */
static const double EXACT_TOL = 1e-13;
/* Decades of decay of eta over the half domain (Clamond & Dutykh use 17). */
static const double EXACT_DECADES = 17.0;

/* beta in (0, pi/2) with sin(beta)/beta = F2 cos(beta), by bisection. */
static double decay_rate(double F2) {
  double lo = 0.0, hi = 1.5;
  for (int i = 0; i < 200 && hi - lo > 1e-15; i++) {
    double m = 0.5 * (lo + hi);
    double f = sin(m) / m - F2 * cos(m);
    if (f < 0) lo = m;
    else hi = m;
  }
  return 0.5 * (lo + hi);
}

struct work {
  int n;
  double *a, *b, *c; /* packed complex arrays, 2n doubles */
  double *eta, *Ceta, *cop;
};

static void work_free(struct work *w) {
  free(w->a);
  free(w->b);
  free(w->c);
  free(w->eta);
  free(w->Ceta);
  free(w->cop);
}

static void to_complex(double *z, const double *x, int n) {
  for (int i = 0; i < n; i++) {
    z[2 * i] = x[i];
    z[2 * i + 1] = 0.0;
  }
}

/* Ceta = C(eta) from eta_hat already in w->a (w->b is scratch). */
static void apply_C(struct work *w) {
  int n = w->n;
  for (int i = 0; i < n; i++) {
    w->b[2 * i] = w->cop[i] * w->a[2 * i];
    w->b[2 * i + 1] = w->cop[i] * w->a[2 * i + 1];
  }
  gsl_fft_complex_radix2_inverse(w->b, 1, n);
  for (int i = 0; i < n; i++) w->Ceta[i] = w->b[2 * i];
}

/* Solve for eps on n_modes modes (see wl_waves_exact_solitary). When
 * keep_hat is not NULL it receives the converged spectrum FFT(eta) on the
 * grid xi_i = (1 - n/2 + i) dxi (packed complex, 2n doubles, the caller
 * frees it) and *dxi_out the grid spacing. */
static enum wl_status solve(double eps, int n_modes, struct wl_solitary_exact *out,
                            double **keep_hat, double *dxi_out, struct wl_error *err) {
  memset(out, 0, sizeof *out);
  if (!(isfinite(eps) && eps >= EXACT_EPS_MIN && eps <= EXACT_EPS_MAX))
    return wl_error_set(err, WL_EINPUT,
                        "exact solitary wave: H/h = %g; valid: %g <= H/h <= %g (the "
                        "Petviashvili-Babenko method fails near the highest wave, H/h ~ 0.83)",
                        eps, EXACT_EPS_MIN, EXACT_EPS_MAX);
  if (n_modes < EXACT_N_MIN || n_modes > EXACT_N_MAX || (n_modes & (n_modes - 1)) != 0)
    return wl_error_set(err, WL_EINPUT,
                        "exact solitary wave: n_modes = %d; valid: a power of two from %d to %d",
                        n_modes, EXACT_N_MIN, EXACT_N_MAX);
  const int n = n_modes;
  struct work w = {.n = n};
  size_t zc = 2 * (size_t)n * sizeof(double), rc = (size_t)n * sizeof(double);
  w.a = malloc(zc);
  w.b = malloc(zc);
  w.c = malloc(zc);
  w.eta = malloc(rc);
  w.Ceta = malloc(rc);
  w.cop = malloc(rc);
  if (!w.a || !w.b || !w.c || !w.eta || !w.Ceta || !w.cop) {
    work_free(&w);
    return wl_error_set(err, WL_ENOMEM,
                        "exact solitary wave: cannot allocate 6 work arrays of %d modes (%zu "
                        "bytes)", n, 3 * zc + 3 * rc);
  }

  double F2 = 1.0 + eps - eps * eps / 20.0 - 3.0 / 70.0 * eps * eps * eps; /* Grimshaw eq 23 */
  double beta = decay_rate(F2);
  double L = EXACT_DECADES * log(10.0) / beta;
  double dxi = 2.0 * L / n;
  for (int i = 0; i < n; i++) {
    double k = (i < n / 2 ? i : i - n) * PI / L;
    w.cop[i] = i == 0 ? 1.0 : k / tanh(k);
    double xi = (1 - n / 2 + i) * dxi, ch = cosh(0.5 * beta * xi);
    w.eta[i] = eps / (ch * ch); /* KdV first guess */
  }

  double change = INFINITY, residual = INFINITY;
  int iter = 0;
  while (change > EXACT_TOL * eps && iter < EXACT_MAX_ITER) {
    iter++;
    /* a = FFT(eta), Ceta */
    to_complex(w.a, w.eta, n);
    gsl_fft_complex_radix2_forward(w.a, 1, n);
    apply_C(&w);
    double M0 = 0, P0 = 0;
    for (int i = 0; i < n; i++) {
      M0 += w.eta[i] * (1.0 + w.Ceta[i]);
      P0 += 0.5 * w.eta[i] * w.eta[i] * (1.0 + w.Ceta[i]);
    }
    F2 = 1.0 + 3.0 * P0 / M0;
    /* b = FFT(eta^2), c = FFT(eta C eta) */
    for (int i = 0; i < n; i++) {
      w.b[2 * i] = w.eta[i] * w.eta[i];
      w.b[2 * i + 1] = 0.0;
      w.c[2 * i] = w.eta[i] * w.Ceta[i];
      w.c[2 * i + 1] = 0.0;
    }
    gsl_fft_complex_radix2_forward(w.b, 1, n);
    gsl_fft_complex_radix2_forward(w.c, 1, n);
    /* c = N_hat = 1/2 C eta2_hat + FFT(eta C eta); b = L eta_hat - N_hat (residual) */
    double S1 = 0, S2 = 0;
    for (int i = 0; i < n; i++) {
      double lop = F2 * w.cop[i] - 1.0;
      for (int r = 0; r < 2; r++) {
        double nl = 0.5 * w.cop[i] * w.b[2 * i + r] + w.c[2 * i + r];
        double le = lop * w.a[2 * i + r];
        S1 += w.a[2 * i + r] * le;
        S2 += w.a[2 * i + r] * nl;
        w.c[2 * i + r] = nl;
        w.b[2 * i + r] = le - nl;
      }
    }
    gsl_fft_complex_radix2_inverse(w.b, 1, n);
    residual = 0;
    for (int i = 0; i < n; i++) residual = fmax(residual, fabs(w.b[2 * i]));
    double S = (S1 / S2) * (S1 / S2);
    for (int i = 0; i < n; i++) {
      double lop = F2 * w.cop[i] - 1.0;
      w.c[2 * i] *= S / lop;
      w.c[2 * i + 1] *= S / lop;
    }
    gsl_fft_complex_radix2_inverse(w.c, 1, n);
    double top = -INFINITY;
    for (int i = 0; i < n; i++) top = fmax(top, w.c[2 * i]);
    if (!(top > 0) || !isfinite(top)) break;
    change = 0;
    for (int i = 0; i < n; i++) {
      double e1 = eps * w.c[2 * i] / top;
      change = fmax(change, fabs(e1 - w.eta[i]));
      w.eta[i] = e1;
    }
  }
  if (!(change <= EXACT_TOL * eps)) {
    work_free(&w);
    return wl_error_set(err, WL_ENUMERIC,
                        "exact solitary wave: Petviashvili iteration for H/h = %g on %d modes "
                        "did not converge (change %g after %d iterations, wanted %g)",
                        eps, n, change, iter, EXACT_TOL * eps);
  }

  to_complex(w.a, w.eta, n);
  gsl_fft_complex_radix2_forward(w.a, 1, n);
  apply_C(&w);
  double tail = 0;
  for (int i = 3 * n / 8; i <= 5 * n / 8; i++) tail = fmax(tail, hypot(w.a[2 * i], w.a[2 * i + 1]));
  tail /= fabs(w.a[0]);
  double M = 0, P = 0, KC = 0;
  for (int i = 0; i < n; i++) {
    M += w.eta[i] * (1.0 + w.Ceta[i]);
    P += 0.5 * w.eta[i] * w.eta[i] * (1.0 + w.Ceta[i]);
    KC += 0.5 * w.eta[i] * w.Ceta[i];
  }
  M *= dxi;
  P *= dxi;
  KC *= dxi;
  F2 = 1.0 + 3.0 * P / M;
  out->eps = eps;
  out->F = sqrt(F2);
  out->mass = M;
  out->impulse = out->F * M;
  out->kinetic = F2 * KC;
  out->potential = P;
  out->beta = decay_rate(F2);
  out->residual = residual;
  out->tail = tail;
  out->n_iter = iter;
  if (keep_hat) {
    *keep_hat = w.a; /* FFT(eta) of the converged eta (apply_C left it there) */
    *dxi_out = dxi;
    w.a = NULL;
  }
  work_free(&w);
  return WL_OK;
}

enum wl_status wl_waves_exact_solitary(double eps, int n_modes, struct wl_solitary_exact *out,
                                       struct wl_error *err) {
  return solve(eps, n_modes, out, NULL, NULL, err);
}

/* ---- the exact wave's field ------------------------------------------------ */

/* Modes whose coefficient is below this fraction of the mean's are left out
 * of the field sums (the spectrum decays exponentially; the sums cost one
 * term per mode): the field then differs by ~1e-12 of the crest values. */
static const double FIELD_MODE_CUT = 1e-12;
/* Newton's method on the map: converged when the step is below this [h]. */
static const double FIELD_NEWTON_TOL = 1e-13;
enum { FIELD_NEWTON_MAX = 60 };
/* The table reaches out to where eta ~ 4 eps e^{-beta X} is ~1e-9 eps. */
static const double FIELD_X_DECAY = 22.0;

/* The solution as a function of the conformal variable: eta(xi) =
 * c0 + sum_{j=1..m} 2 Re(c_j e^{i j dk xi}). */
struct field {
  int m;
  double dk, c0, F;
  double complex *c; /* c[j], j = 1..m (c[0] unused) */
};

/* z(zeta) and z'(zeta) of the map (waves.h), sigma = Im zeta in [-1, 0].
 * Per mode j (k = j dk) the pair +k, -k gives
 *   z:  -i/sinh k (c A - conj(c) B),  z': k/sinh k (c A + conj(c) B),
 * A = e^{i k (zeta + i)}, B = 1/A; both divided by sinh k in a form that
 * cannot overflow for sigma in [-1, 0]. */
static void field_map(const struct field *f, double complex zeta, double complex *z,
                      double complex *dz) {
  const double xi = creal(zeta), sg = cimag(zeta);
  double complex sz = zeta + f->c0 * (zeta + I), sdz = 1.0 + f->c0;
  const double complex rot = cexp(I * f->dk * xi);
  double complex ph = 1.0;
  for (int j = 1; j <= f->m; j++) {
    ph *= rot; /* e^{i k xi} */
    const double k = j * f->dk, q = exp(-2.0 * k);
    /* A / sinh k = 2 e^{-k (sigma + 2)} / (1 - e^{-2k}) e^{i k xi};
     * B / sinh k = 2 e^{k sigma} / (1 - e^{-2k}) e^{-i k xi} */
    const double a = 2.0 * exp(-k * (sg + 2.0)) / (1.0 - q), b = 2.0 * exp(k * sg) / (1.0 - q);
    const double complex cA = f->c[j] * a * ph, cB = conj(f->c[j]) * b * conj(ph);
    sz += -I * (cA - cB);
    sdz += k * (cA + cB);
  }
  *z = sz;
  *dz = sdz;
}

/* The conformal point that maps to the physical (x, y) (y from still water,
 * bed -1), by Newton's method from zeta0; sigma kept in [-1, 0]. */
static int field_invert(const struct field *f, double x, double y, double complex *zeta) {
  double complex zt = x + I * y, zz = *zeta, z, dz;
  for (int it = 0; it < FIELD_NEWTON_MAX; it++) {
    field_map(f, zz, &z, &dz);
    const double complex step = (zt - z) / dz;
    double sg = cimag(zz + step);
    sg = sg < -1.0 ? -1.0 : sg > 0.0 ? 0.0 : sg;
    zz = creal(zz + step) + I * sg;
    if (cabs(step) < FIELD_NEWTON_TOL) {
      *zeta = zz;
      return 1;
    }
  }
  *zeta = zz;
  return 0;
}

/* The surface point above physical x: xi on sigma = 0 with Re z = x. */
static int field_surface(const struct field *f, double x, double *xi, double *eta) {
  double s = *xi;
  double complex z, dz;
  for (int it = 0; it < FIELD_NEWTON_MAX; it++) {
    field_map(f, s, &z, &dz);
    const double step = (x - creal(z)) / creal(dz);
    s += step;
    if (fabs(step) < FIELD_NEWTON_TOL) {
      field_map(f, s, &z, &dz);
      *xi = s;
      *eta = cimag(z);
      return 1;
    }
  }
  return 0;
}

enum wl_status wl_waves__exact_tabulate(struct wl_solitary *sw, struct wl_error *err) {
  /* Grids whose spectral tail is at round-off (F and I unchanged to 1e-9
   * with twice the modes; measured 2026-11-26 at H/h 0.1, 0.3, 0.6, 0.75) */
  const double eps = sw->eps;
  const int n = eps <= 0.65 ? 4096 : 16384;
  double *hat = NULL, dxi = 0;
  enum wl_status st = solve(eps, n, &sw->exact, &hat, &dxi, err);
  if (st) return st;
  struct field f = {0};
  f.F = sw->exact.F;
  f.dk = 2.0 * PI / (n * dxi);
  f.c0 = hat[0] / n;
  int m = 0;
  for (int j = 1; j < n / 2; j++)
    if (hypot(hat[2 * j], hat[2 * j + 1]) > FIELD_MODE_CUT * fabs(hat[0])) m = j;
  f.m = m;
  f.c = malloc(sizeof(double complex) * (size_t)(m + 1));
  if (!f.c) {
    free(hat);
    return wl_error_set(err, WL_ENOMEM, "exact solitary wave: cannot allocate %d modes", m);
  }
  /* eta(xi) = (1/n) sum_j hat_j e^{i k_j (xi - xi_0)}, xi_0 = (1 - n/2) dxi */
  const double xi0 = (1 - n / 2) * dxi;
  for (int j = 1; j <= m; j++)
    f.c[j] = (hat[2 * j] + I * hat[2 * j + 1]) / n * cexp(-I * j * f.dk * xi0);
  free(hat);

  const double Xmax = FIELD_X_DECAY / sw->exact.beta;
  sw->exact_dX = Xmax / (WL_WAVES_EXACT_NX - 1);
  double xi = 0.0;
  st = WL_OK;
  for (int i = 0; i < WL_WAVES_EXACT_NX && !st; i++) {
    const double X = i * sw->exact_dX;
    double eta;
    if (!field_surface(&f, X, &xi, &eta)) {
      st = wl_error_set(err, WL_ENUMERIC, "exact solitary wave H/h = %g: the surface point at "
                        "X = %g h did not converge", eps, X);
      break;
    }
    sw->exact_eta[i] = eta;
    double complex zeta = xi;
    for (int j = WL_WAVES_EXACT_NZ - 1; j >= 0; j--) { /* surface down: each a start for the next */
      const double s = (double)j / (WL_WAVES_EXACT_NZ - 1), y = -1.0 + s * (1.0 + eta);
      if (!field_invert(&f, X, y, &zeta)) {
        st = wl_error_set(err, WL_ENUMERIC, "exact solitary wave H/h = %g: the point X = %g h, "
                          "z = %g h did not converge", eps, X, 1.0 + y);
        break;
      }
      double complex z, dz;
      field_map(&f, zeta, &z, &dz);
      const double complex W = -f.F / dz; /* u - c - i w in the crest's frame */
      sw->exact_u[i][j] = creal(W) + f.F;
      sw->exact_w[i][j] = -cimag(W);
    }
  }
  free(f.c);
  return st;
}

void wl_waves_exact_integrals(const struct wl_solitary_exact *ex, double rho, double g, double h,
                              struct wl_wave_integrals *out) {
  double sgh = sqrt(g * h);
  out->mass = rho * h * h * ex->mass;
  out->momentum = rho * h * h * sgh * ex->impulse;
  out->kinetic = rho * g * h * h * h * ex->kinetic;
  out->potential = rho * g * h * h * h * ex->potential;
  out->energy = out->kinetic + out->potential;
}
