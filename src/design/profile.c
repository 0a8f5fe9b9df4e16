/* profile.c: piecewise-linear pressure profiles on the wall: evaluation and
 * exact integrals (force and moment about the base), and basis names. */
#include "internal.h"

const char *wl_design_basis_name(enum wl_design_basis basis) {
  switch (basis) {
  case WL_DESIGN_BASIS_TOTAL: return "total";
  case WL_DESIGN_BASIS_WAVE: return "wave";
  case WL_DESIGN_BASIS_DYNAMIC: return "dynamic";
  }
  return "unknown";
}

double wl_design_profile_pressure(const struct wl_design_profile *pr, double z) {
  int n = pr->n_points;
  if (n < 2 || !(z >= pr->z[0]) || z > pr->z[n - 1]) return 0.0;
  for (int i = 1; i < n; i++) {
    if (z <= pr->z[i]) {
      double dz = pr->z[i] - pr->z[i - 1];
      double s = dz > 0.0 ? (z - pr->z[i - 1]) / dz : 1.0;
      return pr->p[i - 1] + s * (pr->p[i] - pr->p[i - 1]);
    }
  }
  return 0.0;
}

void wl_design_profile_integrate(const struct wl_design_profile *pr, double *force,
                                 double *moment) {
  double f = 0.0, m = 0.0;
  for (int i = 1; i < pr->n_points; i++) {
    double z0 = pr->z[i - 1], z1 = pr->z[i], p0 = pr->p[i - 1], p1 = pr->p[i];
    double dz = z1 - z0;
    /* int over [z0, z1] of the linear p: trapezoid for p, and for p z the
     * exact (dz/6)[p0 (2 z0 + z1) + p1 (z0 + 2 z1)]. */
    f += dz * (p0 + p1) / 2.0;
    m += dz * (p0 * (2.0 * z0 + z1) + p1 * (z0 + 2.0 * z1)) / 6.0;
  }
  if (force) *force = f;
  if (moment) *moment = m;
}
