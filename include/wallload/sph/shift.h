/* sph/shift.h: particle shifting (Lind et al. 2012, J. Comput. Phys.
 * 231:1499; with the velocity scaling of Skillen et al. 2013, Comput.
 * Methods Appl. Mech. Eng. 265:163; as DualSPHysics 4-5), per fluid
 * particle, for host and device. Weakly-compressible SPH lets particles
 * line up along streamlines and open voids where the flow stretches
 * (tensile instability); shifting moves each fluid particle a little away
 * from where its neighbours crowd, towards a uniform spacing:
 *
 *   delta r_i = -A h |v_i| dt grad C_i,   grad C_i = sum_j (m_j/rho_j) grad_i W_ij
 *
 * over fluid and boundary neighbours (the walls count as neighbours, so a
 * particle is not shifted into them), with the mirror images beside a
 * mirror plane. At a free surface grad C points into the fluid for want of
 * neighbours outside, and shifting along it would spread the surface; there
 * the divergence of position
 *
 *   div r_i = -sum_j (m_j/rho_j) r_ij . grad_i W_ij   (= dim in full support)
 *
 * falls below the threshold k->shift_tfs and the particle is not shifted;
 * between the threshold and dim the shift ramps linearly (DualSPHysics'
 * free-surface correction). Each component is capped at 0.1 dp per step.
 *
 * The shift is computed from the step-start state (the cell lists of the
 * step) and added to the position by the corrector (sph/integrate.h), as
 * DualSPHysics applies it in the corrector only. */
#ifndef WALLLOAD_SPH_SHIFT_H
#define WALLLOAD_SPH_SHIFT_H

#include "wallload/sph/cells.h"
#include "wallload/sph/gather.h"

/* Adds, for every lane, the concentration gradient and -div r of the
 * neighbours j in [j0, j1) (or their mirror images in plane `mirror` 1 or
 * 2, 3D). Branch-free: a j outside the support has wq = 0 and adds zeros;
 * the lane loop is what the CPU compiler vectorises, and each lane sums
 * its neighbours in the order of a lone particle (as sph/gather.h). */
WL_HD static WL_INLINE void wl_sph_shift_range(const int dim, const int lanes,
                                               const struct wl_sph_const *k,
                                               const struct wl_sph_eval *e,
                                               const double x[WL_SPH_DIM_MAX][WL_SPH_LANES],
                                               int j0, int j1, const int mirror,
                                               wl_real gc[3][WL_SPH_LANES],
                                               wl_real divr[WL_SPH_LANES]) {
  const int az = dim - 1;
  for (int j = j0; j < j1; j++) {
    const double xj = e->pos[0][j], zj = e->pos[az][j];
    const double yj = dim != 3 ? 0.0
                      : mirror ? 2.0 * k->mirror_y[mirror - 1] - e->pos[1][j]
                               : e->pos[1][j];
    wl_real inv_rho_j, vol_j;
    wl_sph_pair_j(k, e->rho[j], &inv_rho_j, &vol_j);
    const wl_real vkf = vol_j * k->kf;
    for (int l = 0; l < lanes; l++) {
      const wl_real dx = (wl_real)(x[0][l] - xj);
      const wl_real dy = dim == 3 ? (wl_real)(x[1][l] - yj) : WL_R(0.0);
      const wl_real dz = (wl_real)(x[az][l] - zj);
      const wl_real r2 = dx * dx + dy * dy + dz * dz;
      const wl_real wq = wl_sph_kernel_wq(k, r2);
      const wl_real vF = vkf * wq * wq * wq; /* V_j grad W = vF r_ij */
      gc[0][l] += vF * dx;
      gc[1][l] += vF * dy;
      gc[2][l] += vF * dz;
      divr[l] -= vF * r2;
    }
  }
}

/* The shifts of fluid particles i0 .. i0 + m - 1 (sorted indices >=
 * n_bound, 1 <= m <= lanes, in cells `span` + 1 consecutive cells of one
 * row, as wl_sph_gather_block) for a step of dt at the state e (positions,
 * velocities, densities of the step start): writes shift[a][i], a < dim.
 * Zeros when k->shift_coef is 0. dim, lanes: compile-time constants. */
WL_HD static WL_INLINE void wl_sph_shift_block(const int dim, const int lanes,
                                               const struct wl_sph_const *k,
                                               const struct wl_sph_grid *g,
                                               const struct wl_sph_eval *e, int i0, int m,
                                               int span, double dt, wl_real *const *shift) {
  const int az = dim - 1;
  if (!(k->shift_coef > 0)) {
    for (int l = 0; l < m; l++)
      for (int a = 0; a < dim; a++) shift[a][i0 + l] = 0;
    return;
  }
  const int nc = g->n_cells;
  const int cell = (int)e->key[i0] - nc;
  int first[9], last[9];
  const int nr = wl_sph_cell_rows(dim, g, cell, span, first, last);
  int mf[2][6], ml[2][6], nm[2] = {0, 0};
  if (dim == 3) wl_sph_cell_rows_mirrors(g, k->mirror, cell, span, mf, ml, nm);
  double x[WL_SPH_DIM_MAX][WL_SPH_LANES];
  wl_real gc[3][WL_SPH_LANES], divr[WL_SPH_LANES];
  for (int l = 0; l < lanes; l++) {
    const int i = i0 + (l < m ? l : m - 1);
    for (int a = 0; a < dim; a++) x[a][l] = e->pos[a][i];
    gc[0][l] = gc[1][l] = gc[2][l] = divr[l] = 0;
  }
  for (int grp = 1; grp >= 0; grp--) { /* fluid, then boundary neighbours */
    const int *const b = e->begin + (grp ? nc : 0);
    for (int r = 0; r < nr; r++)
      wl_sph_shift_range(dim, lanes, k, e, x, b[first[r]], b[last[r] + 1], 0, gc, divr);
    for (int side = 0; dim == 3 && side < 2; side++)
      for (int r = 0; r < nm[side]; r++)
        wl_sph_shift_range(dim, lanes, k, e, x, b[mf[side][r]], b[ml[side][r] + 1], side + 1, gc,
                           divr);
  }
  const double cap = 0.1 * k->dp;
  for (int l = 0; l < m; l++) {
    const int i = i0 + l;
    double s[3] = {0, 0, 0};
    if (divr[l] >= k->shift_tfs) { /* else at the free surface: no shift */
      double ramp = ((double)divr[l] - k->shift_tfs) / ((double)dim - k->shift_tfs);
      ramp = ramp > 1.0 ? 1.0 : ramp;
      double v2 = 0;
      for (int a = 0; a < dim; a++) v2 += (double)e->vel[a][i] * (double)e->vel[a][i];
      const double scale = -k->shift_coef * k->h_d * sqrt(v2) * dt * ramp;
      for (int a = 0; a < dim; a++) {
        const double sa = scale * (double)gc[a == az ? 2 : a][l];
        s[a] = sa > cap ? cap : sa < -cap ? -cap : sa;
      }
    }
    for (int a = 0; a < dim; a++) shift[a][i] = (wl_real)s[a];
  }
}

/* The shift of the single fluid particle i (one CUDA thread each); the
 * same bits as wl_sph_shift_block. Boundary particles (i < n_bound) get
 * zeros. */
WL_HD static WL_INLINE void wl_sph_shift(const int dim, const struct wl_sph_const *k,
                                         const struct wl_sph_grid *g, const struct wl_sph_eval *e,
                                         int n_bound, int i, double dt,
                                         wl_real *const *shift) {
  if (i < n_bound) {
    for (int a = 0; a < dim; a++) shift[a][i] = 0;
    return;
  }
  wl_sph_shift_block(dim, 1, k, g, e, i, 1, 0, dt, shift);
}

#endif
