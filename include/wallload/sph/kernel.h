/* sph/kernel.h: the Wendland C2 kernel (Wendland 1995), as in seed 000
 * eq. (12) and DualSPHysics:
 *
 *   W(r, h) = aD (1 - q/2)^4 (2q + 1),  q = r/h in [0, 2], 0 beyond;
 *   aD = 7 / (4 pi h^2) in 2D, 21 / (16 pi h^3) in 3D.
 *
 * Its gradient, from dW/dq = -5 q (1 - q/2)^3 aD:
 *
 *   grad_i W_ij = (dW/dr) r_ij / r = -5 aD / h^2 (1 - q/2)^3 r_ij = kf (1-q/2)^3 r_ij
 *
 * with r_ij = r_i - r_j. No division by r: the gradient is finite (zero) at
 * r = 0, so a particle may meet itself in the neighbour loop without a
 * branch. Beyond the support (1 - q/2) is clamped to 0, which makes both W
 * and its gradient exactly 0 there, again without a branch. */
#ifndef WALLLOAD_SPH_KERNEL_H
#define WALLLOAD_SPH_KERNEL_H

#include "wallload/sph/params.h"

/* (1 - q/2) clamped to [0, 1], from r^2 [m^2]. */
WL_HD static WL_INLINE wl_real wl_sph_kernel_wq(const struct wl_sph_const *k, wl_real r2) {
  /* r (inv_h / 2): the same bits as (r inv_h) / 2, and inv_h / 2 is
   * constant over a neighbour loop, so a multiplication a pair less */
  return wl_sph_pos(WL_R(1.0) - wl_sph_sqrt(r2) * (WL_R(0.5) * k->inv_h));
}

/* W(r) [1/m^dim] from r^2 [m^2]. */
WL_HD static WL_INLINE wl_real wl_sph_kernel_w(const struct wl_sph_const *k, wl_real r2) {
  const wl_real q = wl_sph_sqrt(r2) * k->inv_h;
  const wl_real wq = wl_sph_pos(WL_R(1.0) - WL_R(0.5) * q);
  const wl_real wq2 = wq * wq;
  return k->kw * wq2 * wq2 * (WL_R(2.0) * q + WL_R(1.0));
}

/* F(r) [1/m^(dim+2)] such that grad_i W_ij = F r_ij, from r^2 [m^2]. */
WL_HD static WL_INLINE wl_real wl_sph_kernel_f(const struct wl_sph_const *k, wl_real r2) {
  const wl_real wq = wl_sph_kernel_wq(k, r2);
  return k->kf * wq * wq * wq;
}

/* Normalisation aD for dimension dim and smoothing length h [m]. */
WL_HD static inline double wl_sph_kernel_norm(int dim, double h) {
  const double pi = 3.14159265358979323846;
  return dim == 2 ? 7.0 / (4.0 * pi * h * h) : 21.0 / (16.0 * pi * h * h * h);
}

#endif
