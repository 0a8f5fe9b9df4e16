/* sph/vres_fit.h: the first-order corrected SPH interpolation at a point
 * from scattered donor particles, which fills the buffer particles of a
 * variable-resolution run from the other resolution's fluid (vres.h).
 *
 * The moment equations of Liu & Liu (2006, Appl. Numer. Math. 56, 19-36;
 * the corrected interpolation of Tafuni et al. 2018's open boundaries and
 * DualSPHysics 5.4's VRes buffers): expand the field f about the point x_b,
 * f_j = f_b + (x_j - x_b) . grad f_b, multiply by the kernel W_j = W(x_b -
 * x_j) and by its gradient G_j = grad_b W(x_b - x_j), and sum over donors
 * with their volumes V_j = m_j / rho_j:
 *
 *   [ sum V W      sum V W (x_j - x_b)^T   ] [ f_b      ]   [ sum V f W ]
 *   [ sum V G      sum V G (x_j - x_b)^T   ] [ grad f_b ] = [ sum V f G ]
 *
 * exact for a linear field wherever the (1 + dim)-square matrix is regular.
 * Where it is nearly singular (a donor cloud cut by the free surface or a
 * wall) the zeroth-order Shepard average sum V f W / sum V W is used. The
 * gradient rows and columns are scaled by h so the matrix is dimensionless
 * (close to the identity inside a full support); the threshold is on its
 * determinant. Host and device code (WL_HD). */
#ifndef WALLLOAD_SPH_VRES_FIT_H
#define WALLLOAD_SPH_VRES_FIT_H

#include "wallload/sph/defs.h"

/* Fields interpolated: density and the dim velocity components. */
#define WL_VRES_FIELDS 4
/* Below this determinant of the scaled moment matrix the fit falls back to
 * Shepard's average (a full support gives about 1). */
#define WL_VRES_DET_MIN 0.05

struct wl_vres_fit {
  int dim;
  double h;                                 /* the donors' smoothing length [m] */
  double a[4][4];                           /* moment matrix (scaled) */
  double b[4][WL_VRES_FIELDS];              /* right-hand sides */
  double shepard;                           /* sum V W (the kernel's partition of unity) */
};

WL_HD static inline void wl_vres_fit_init(struct wl_vres_fit *f, int dim, double h) {
  f->dim = dim;
  f->h = h;
  f->shepard = 0;
  for (int r = 0; r < 4; r++)
    for (int c = 0; c < 4; c++) f->a[r][c] = 0;
  for (int r = 0; r < 4; r++)
    for (int c = 0; c < WL_VRES_FIELDS; c++) f->b[r][c] = 0;
}

/* One donor: d = x_j - x_b [m] (dim components), w = W(|d|), F such that
 * grad_b W = -F d (sph/kernel.h wl_sph_kernel_f of r_bj = -d), vol = m_j /
 * rho_j, val[0..dim] its density and velocity. */
WL_HD static inline void wl_vres_fit_add(struct wl_vres_fit *f, const double *d, double w,
                                         double F, double vol, const double *val) {
  const int n = 1 + f->dim;
  double test[4], mono[4];
  test[0] = vol * w;
  mono[0] = 1.0;
  for (int a = 0; a < f->dim; a++) {
    test[1 + a] = vol * (-F * d[a]) * f->h; /* G scaled by h */
    mono[1 + a] = d[a] / f->h;              /* (x_j - x_b) / h */
  }
  for (int r = 0; r < n; r++) {
    for (int c = 0; c < n; c++) f->a[r][c] += test[r] * mono[c];
    for (int c = 0; c < n; c++) f->b[r][c] += test[r] * val[c];
  }
  f->shepard += test[0];
}

/* The values at the point into out[0..dim] (density, velocity). Returns 1
 * for the corrected fit, 0 for Shepard's average, -1 with no donor weight
 * (out untouched). */
WL_HD static inline int wl_vres_fit_solve(const struct wl_vres_fit *f, double *out) {
  const int n = 1 + f->dim;
  if (!(f->shepard > 0)) return -1;
  double m[4][4 + WL_VRES_FIELDS];
  for (int r = 0; r < n; r++) {
    for (int c = 0; c < n; c++) m[r][c] = f->a[r][c];
    for (int c = 0; c < n; c++) m[r][n + c] = f->b[r][c];
  }
  double det = 1.0;
  int ok = 1;
  for (int col = 0; col < n && ok; col++) { /* Gauss-Jordan, partial pivoting */
    int piv = col;
    for (int r = col + 1; r < n; r++)
      if ((m[r][col] < 0 ? -m[r][col] : m[r][col]) > (m[piv][col] < 0 ? -m[piv][col] : m[piv][col]))
        piv = r;
    if (piv != col) {
      for (int c = 0; c < 2 * n; c++) {
        const double t = m[col][c];
        m[col][c] = m[piv][c];
        m[piv][c] = t;
      }
      det = -det;
    }
    det *= m[col][col];
    if (m[col][col] == 0.0) {
      ok = 0;
      break;
    }
    const double inv = 1.0 / m[col][col];
    for (int c = 0; c < 2 * n; c++) m[col][c] *= inv;
    for (int r = 0; r < n; r++)
      if (r != col) {
        const double s = m[r][col];
        for (int c = 0; c < 2 * n; c++) m[r][c] -= s * m[col][c];
      }
  }
  if (ok && (det < 0 ? -det : det) >= WL_VRES_DET_MIN) {
    for (int c = 0; c < n; c++) out[c] = m[0][n + c];
    return 1;
  }
  for (int c = 0; c < n; c++) out[c] = f->b[0][c] / f->shepard;
  return 0;
}

#endif
