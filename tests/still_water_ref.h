/* still_water_ref.h: closed-form references for water at rest in the
 * weakly compressible model, written here from the equations, not taken
 * from the code under test.
 *
 * 1. Tait water (p = B [(rho/rho0)^7 - 1], B = rho0 c0^2 / 7) at rest under
 *    gravity: dp/ds = rho g with s the depth below the level gives
 *      p(s) = B [(1 + a s)^(7/6) - 1],  a = 6 g rho0 / (7 B) = 6 g / c0^2,
 *    so the force on a wall, F = int_0^d p ds, and the moment about its
 *    toe, M = int_0^d p (d - s) ds, are rho0 g d^2/2 (1 + g d/(3 c0^2))
 *    and rho0 g d^3/6 (1 + g d/(4 c0^2)) to first order: 0.3 % over the
 *    incompressible values in 0.5 m of water at c0 = 22 m/s. The scene lays
 *    still water to its true level (scene.h), so d is that level.
 *
 * 2. The SPH gradient's lattice factor: on the square (cubic) lattice of
 *    spacing dp, sum_j dp^D (x_j - x_i) (x) grad_i W_ij is kappa times the
 *    identity, kappa slightly below 1 (0.9938 in 2D and 0.9976 in 3D for
 *    the Wendland C2 kernel at h = 1.7 dp); the continuum integral is
 *    exactly 1. At rest the pressure force must carry the weight, so the
 *    discrete equilibrium's pressure gradient is rho g / kappa: the fluid's
 *    pressure (what the probes interpolate) reads 1/kappa of the Tait
 *    column's, while the force summed on the wall's boundary particles,
 *    a pair sum with the same factor, reads the Tait column's. Measured on
 *    wall_still's tank (2026-11-28): probes and boundary particles parted
 *    by 0.62 %, kappa's deficit to two digits. */
#ifndef WL_TESTS_STILL_WATER_REF_H
#define WL_TESTS_STILL_WATER_REF_H

#include <math.h>

/* Tait pressure at depth s below the still level [Pa] */
static inline double still_tait_pressure(double s, double rho0, double g, double c0) {
  const double B = rho0 * c0 * c0 / 7, a = 6 * g / (c0 * c0);
  return B * (pow(1 + a * s, 7.0 / 6.0) - 1);
}

/* Force per unit width on a vertical wall in depth d [N/m], in closed form:
 * int_0^d (1 + a s)^(7/6) ds = 6/(13 a) [(1 + a d)^(13/6) - 1]. */
static inline double still_tait_force(double d, double rho0, double g, double c0) {
  const double B = rho0 * c0 * c0 / 7, a = 6 * g / (c0 * c0);
  return B * (6 / (13 * a) * (pow(1 + a * d, 13.0 / 6.0) - 1) - d);
}

/* Moment about the wall's toe per unit width [N m/m]: int_0^d p(s) (d - s) ds
 * = d F - int_0^d s p(s) ds, the last by parts in closed form. */
static inline double still_tait_moment(double d, double rho0, double g, double c0) {
  const double B = rho0 * c0 * c0 / 7, a = 6 * g / (c0 * c0);
  const double u = 1 + a * d;
  /* int_0^d s (1 + a s)^(7/6) ds with t = 1 + a s: (1/a^2) int_1^u (t - 1) t^(7/6) dt */
  const double s_p = (6 / 19.0 * (pow(u, 19.0 / 6.0) - 1) - 6 / 13.0 * (pow(u, 13.0 / 6.0) - 1)) /
                     (a * a);
  return d * still_tait_force(d, rho0, g, c0) - B * (s_p - d * d / 2);
}

/* kappa of the Wendland C2 kernel (W = alpha (1 - q/2)^4 (2 q + 1), q = r/h,
 * alpha = 7/(4 pi h^2) in 2D, 21/(16 pi h^3) in 3D; dW/dr = -5 alpha q
 * (1 - q/2)^3 / h) on the lattice of unit spacing with h = h_over_dp:
 * -sum_j x_j^2 / r_j dW/dr (the xx entry; the lattice's symmetry makes the
 * tensor kappa times the identity). */
static inline double still_lattice_gradient_factor(int dims, double h_over_dp) {
  const double pi = 3.14159265358979323846, h = h_over_dp;
  const double alpha = dims == 2 ? 7 / (4 * pi * h * h) : 21 / (16 * pi * h * h * h);
  const int n = (int)ceil(2 * h) + 1;
  double sum = 0;
  for (int i = -n; i <= n; i++)
    for (int j = -n; j <= n; j++)
      for (int k = (dims == 3 ? -n : 0); k <= (dims == 3 ? n : 0); k++) {
        const double r = sqrt((double)(i * i + j * j + k * k)), q = r / h;
        if (r == 0 || q >= 2) continue;
        const double dWdr = -5 * alpha * q * pow(1 - q / 2, 3) / h;
        sum -= (double)(i * i) / r * dWdr;
      }
  return sum;
}

#endif
