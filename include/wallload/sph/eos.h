/* sph/eos.h: Tait equation of state and hydrostatic densities.
 *
 *   p = B ((rho/rho0)^gamma - 1),  B = c0^2 rho0 / gamma,  gamma = 7
 *       (Monaghan 1994; seed 000 eqs. 15-17; DualSPHysics)
 *   rho(p) = rho0 (1 + p/B)^(1/gamma)    (inverse)
 *   hydrostatic: p = rho0 g (H - z), so rho = rho0 (1 + rho0 g (H - z)/B)^(1/7)
 *       (REFERENCES.md 1.1, TNL-SPH init.py)
 *
 * Density diffusion needs the hydrostatic density difference between two
 * particles a height dz = z_i - z_j apart (Fourtakas et al. 2019, Comput.
 * Fluids 190:346, eq. 22; DualSPHysics DDT2):
 *
 *   rho_H_ji = rho0 ((1 + rho0 g dz / B)^(1/7) - 1)
 *
 * DualSPHysics evaluates this with powf per pair. Here x = rho0 g dz / B is
 * below 0.02 for any sane run (|dz| < 2h, B = c0^2 rho0/7 with c0 >= 10
 * sqrt(g h_max) gives x <= 14 h/(100 h_max)), and the binomial series
 *   (1 + x)^(1/7) - 1 = x/7 - 3x^2/49 + 13x^3/343 - 0.0271 x^4 + ...
 * cut after x^3 is off by < 0.19 x^3 relative to the leading term (< 2e-6 at
 * x = 0.02). It is more accurate than powf(1 + x, 1/7) - 1 in float, which
 * loses the digits of x to the rounding of 1 + x (4e-4 relative at x = 1e-3),
 * and it costs two FMAs and a multiplication: the coefficients times powers
 * of rho0 g / B are folded in once (k->ddt_h, sph/params.c), so the series
 * runs in dz itself. */
#ifndef WALLLOAD_SPH_EOS_H
#define WALLLOAD_SPH_EOS_H

#include "wallload/sph/params.h"

/* Tait pressure [Pa] of density rho [kg/m^3]. */
WL_HD static WL_INLINE wl_real wl_sph_eos_p(const struct wl_sph_const *k, wl_real rho) {
  const wl_real x = rho * k->inv_rho0;
  const wl_real x2 = x * x;
  const wl_real x4 = x2 * x2;
  return k->B * (x4 * x2 * x - WL_R(1.0));
}

/* Hydrostatic density difference rho_H(z_j) - rho_H(z_i) [kg/m^3] for
 * dz = z_i - z_j [m] (the deeper particle is the denser). */
WL_HD static WL_INLINE wl_real wl_sph_eos_drho_hydro(const struct wl_sph_const *k, wl_real dz) {
  return dz * (k->ddt_h[0] + dz * (k->ddt_h[1] + dz * k->ddt_h[2]));
}

/* Density [kg/m^3] of pressure p [Pa] (inverse Tait), in double for set-up. */
WL_HD static inline double wl_sph_eos_rho_of_p(double rho0, double B, double p) {
  /* (1 + p/B)^(1/7) by Newton on y^7 = 1 + p/B, from y = 1 + p/(7B); converges
   * in a few steps for |p/B| < 1 (no libm in shared headers). */
  const double a = 1.0 + p / B;
  double y = 1.0 + p / (7.0 * B);
  if (a <= 0) return 0;
  for (int it = 0; it < 40; it++) {
    const double y2 = y * y, y6 = y2 * y2 * y2;
    const double step = (y6 * y - a) / (7.0 * y6);
    y -= step;
    if (step < 1e-16 * y && step > -1e-16 * y) break;
  }
  return rho0 * y;
}

#endif
