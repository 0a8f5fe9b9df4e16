/* sph/wall.h: the pressure-extrapolating wall condition (params.h
 * WL_SPH_BOUND_ADAMI): every boundary particle takes its pressure from the
 * fluid next to it instead of from its own continuity equation (the
 * dynamic boundary condition, WL_SPH_BOUND_DBC).
 *
 * Generalized wall boundary condition of Adami, Hu & Adams (2012, J.
 * Comput. Phys. 231:7057, eq. 27), for wall particle w and fluid
 * neighbours f within the kernel support:
 *
 *   p_w = ( sum_f p_f W_wf + (g - a_w) . sum_f rho_f r_wf W_wf ) / sum_f W_wf,
 *   r_wf = r_w - r_f,
 *
 * the Shepard mean of the fluid pressure plus the hydrostatic (and, for a
 * moving wall, inertial) pressure difference between the fluid particle
 * and the wall particle, so that a still tank's wall particles carry the
 * hydrostatic pressure of their own depth (first-order exact). The wall
 * particle's density is the Tait density of p_w (Adami eq. 28), so that
 * the fluid's momentum and continuity pair terms (sph/interact.h) read it
 * as they read a fluid neighbour. As DualSPHysics does for its boundary
 * densities, p_w is kept >= 0 (rho_w >= rho0): a wall pushes, it never
 * pulls the fluid onto itself. A wall particle with no fluid within 2h
 * gets p = 0.
 *
 * Why this condition (measured, see docs/boundary.md): it needs no wall
 * normals or ghost nodes, so corners, crests, 3D edges, boxes and the
 * moving paddle are handled by the same sum; the modified dynamic boundary
 * condition of English et al. (2022, Comp. Part. Mech. 9:1), the other
 * candidate, needs a normal and a mirrored ghost node for every boundary
 * particle.
 *
 * The wall particles' velocity stays the wall's own (free of the fluid's:
 * DualSPHysics' mDBC "slip mode 1"); the fluid feels the wall's friction
 * only through the viscous pair term, as with the dynamic condition.
 *
 * Cost: one pass over the boundary particles, each summing its fluid
 * neighbours, before the fluid's force loop; it replaces the boundary
 * particles' continuity evaluation of the dynamic condition. */
#ifndef WALLLOAD_SPH_WALL_H
#define WALLLOAD_SPH_WALL_H

#include "wallload/sph/cells.h"
#include "wallload/sph/gather.h"
#include "wallload/sph/kernel.h"

/* Tait density [kg/m^3] of pressure p >= 0 [Pa]: rho0 (1 + p/B)^(1/7) by
 * four Newton steps on y^7 = 1 + p/B from y = 1 + p/(7B) (relative error
 * below 1e-7 for p <= B: the error squares each step; no libm on the
 * device path). */
WL_HD static WL_INLINE wl_real wl_sph_eos_rho_of_p_fast(const struct wl_sph_const *k, wl_real p) {
  const wl_real a = WL_R(1.0) + p * wl_sph_rcp(k->B);
  wl_real y = WL_R(1.0) + p * wl_sph_rcp(WL_R(7.0) * k->B);
  for (int it = 0; it < 4; it++) {
    const wl_real y2 = y * y, y6 = y2 * y2 * y2;
    y -= (y6 * y - a) * wl_sph_rcp(WL_R(7.0) * y6);
  }
  return k->rho0 * y;
}

/* Running sums of one wall particle. */
struct wl_sph_wall_acc {
  wl_real sw;  /* sum W [1/m^dim] */
  wl_real spw; /* sum (p_f + rho_f (g - a_w).r_wf) W [Pa/m^dim] */
};

/* Add fluid neighbours j in [j0, j1) of the wall particle at xi (mirror
 * images in the plane y = k->mirror_y[mirror - 1] when mirror is 1 or 2,
 * 3D). ga: g - a_w [m/s^2]. dim: compile-time constant. */
WL_HD static WL_INLINE void wl_sph_wall_range(const int dim, const struct wl_sph_const *k,
                                              const struct wl_sph_eval *e, const double *xi,
                                              const wl_real *ga, int j0, int j1, int mirror,
                                              struct wl_sph_wall_acc *acc) {
  const int az = dim - 1;
  for (int j = j0; j < j1; j++) {
    const double yj = dim != 3 ? 0.0
                      : mirror ? 2.0 * k->mirror_y[mirror - 1] - e->pos[1][j]
                               : e->pos[1][j];
    const wl_real dx = (wl_real)(xi[0] - e->pos[0][j]);
    const wl_real dy = dim == 3 ? (wl_real)(xi[1] - yj) : WL_R(0.0);
    const wl_real dz = (wl_real)(xi[2] - e->pos[az][j]);
    const wl_real r2 = dx * dx + dy * dy + dz * dz;
    if (r2 >= k->support2) continue;
    const wl_real w = wl_sph_kernel_w(k, r2);
    const wl_real gr = ga[0] * dx + ga[1] * dy + ga[2] * dz;
    acc->sw += w;
    acc->spw += (e->press[j] + e->rho[j] * gr) * w;
  }
}

/* g - a_w [m/s^2] of a wall particle with acceleration acc_w (NULL: a
 * fixed wall), in the (x, y, z) slots wl_sph_wall_range reads (2D: x, z). */
WL_HD static WL_INLINE void wl_sph_wall_ga(const int dim, const struct wl_sph_const *k,
                                           const double *acc_w, wl_real *ga) {
  const int az = dim - 1;
  ga[0] = ga[1] = ga[2] = 0;
  for (int a = 0; a < dim; a++)
    ga[a == az ? 2 : a] = k->gravity[a] - (acc_w ? (wl_real)acc_w[a] : WL_R(0.0));
}

/* The end of wall particle i's sample from its sums s: its pressure
 * press_out[i] and density rho_out[i]; its ace, ar and visc set to 0. */
WL_HD static WL_INLINE void wl_sph_wall_store(const int dim, const struct wl_sph_const *k,
                                              const struct wl_sph_eval *e,
                                              const struct wl_sph_wall_acc *s, int i,
                                              wl_real *rho_out, wl_real *press_out) {
  wl_real p = s->sw > WL_R(0.0) ? s->spw / s->sw : WL_R(0.0);
  p = p > WL_R(0.0) ? p : WL_R(0.0);
  press_out[i] = p;
  rho_out[i] = wl_sph_eos_rho_of_p_fast(k, p);
  for (int a = 0; a < dim; a++) e->ace[a][i] = 0;
  e->ar[i] = 0;
  e->visc[i] = 0;
}

/* The wall condition for boundary particle i (sorted index, < n_bound):
 * samples the fluid around it and writes its density rho_out[i] and
 * pressure press_out[i]; its ace, ar and visc are set to 0 (it does not
 * integrate density, and the fluid's own pair with it carries the time-step
 * input). acc_w: the particle's acceleration [m/s^2] (a moving body's; NULL
 * for a fixed wall). dim: compile-time constant. (cuda.cu's 2D loop splits
 * each row among several threads and adds their sums.) */
WL_HD static WL_INLINE void wl_sph_wall_sample(const int dim, const struct wl_sph_const *k,
                                               const struct wl_sph_grid *g,
                                               const struct wl_sph_eval *e, const double *acc_w,
                                               int i, wl_real *rho_out, wl_real *press_out) {
  const int nc = g->n_cells, az = dim - 1;
  const int cell = (int)e->key[i];
  int first[9], last[9];
  const int nr = wl_sph_cell_rows(dim, g, cell, 0, first, last);
  const int *const bf = e->begin + nc; /* fluid group */
  double xi[3];
  xi[0] = e->pos[0][i];
  xi[1] = dim == 3 ? e->pos[1][i] : 0.0;
  xi[2] = e->pos[az][i];
  wl_real ga[3];
  wl_sph_wall_ga(dim, k, acc_w, ga);
  struct wl_sph_wall_acc s = {0, 0};
  for (int r = 0; r < nr; r++) wl_sph_wall_range(dim, k, e, xi, ga, bf[first[r]], bf[last[r] + 1], 0, &s);
  if (dim == 3 && k->mirror) {
    int mfirst[2][6], mlast[2][6], nm[2] = {0, 0};
    wl_sph_cell_rows_mirrors(g, k->mirror, cell, 0, mfirst, mlast, nm);
    for (int side = 0; side < 2; side++)
      for (int r = 0; r < nm[side]; r++)
        wl_sph_wall_range(dim, k, e, xi, ga, bf[mfirst[side][r]], bf[mlast[side][r] + 1],
                          side + 1, &s);
  }
  wl_sph_wall_store(dim, k, e, &s, i, rho_out, press_out);
}

#endif
