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

/* Adds the concentration gradient and -div r of the neighbours j in
 * [j0, j1) (or their mirror images in plane `mirror` 1 or 2, 3D) of the
 * particle at xi to gc[3] and divr. */
WL_HD static WL_INLINE void wl_sph_shift_range(const int dim, const struct wl_sph_const *k,
                                               const struct wl_sph_eval *e, const double xi[3],
                                               int j0, int j1, const int mirror, double gc[3],
                                               double *divr) {
  const int az = dim - 1;
  for (int j = j0; j < j1; j++) {
    const double yj = dim != 3 ? 0.0
                      : mirror ? 2.0 * k->mirror_y[mirror - 1] - e->pos[1][j]
                               : e->pos[1][j];
    const wl_real dx = (wl_real)(xi[0] - e->pos[0][j]);
    const wl_real dy = dim == 3 ? (wl_real)(xi[1] - yj) : WL_R(0.0);
    const wl_real dz = (wl_real)(xi[2] - e->pos[az][j]);
    const wl_real r2 = dx * dx + dy * dy + dz * dz;
    if (!(r2 < k->support2)) continue;
    wl_real inv_rho_j, vol_j;
    wl_sph_pair_j(k, e->rho[j], &inv_rho_j, &vol_j);
    const wl_real wq = wl_sph_kernel_wq(k, r2);
    const wl_real vF = vol_j * k->kf * wq * wq * wq; /* V_j grad W = vF r_ij */
    gc[0] += (double)(vF * dx);
    gc[1] += (double)(vF * dy);
    gc[2] += (double)(vF * dz);
    *divr -= (double)(vF * r2);
  }
}

/* The shift of fluid particle i (sorted index, i >= n_bound) for a step of
 * dt at the state e (positions, velocities, densities of the step start):
 * writes shift[a][i], a < dim. Off (zeros) when k->shift_coef is 0. */
WL_HD static WL_INLINE void wl_sph_shift(const int dim, const struct wl_sph_const *k,
                                         const struct wl_sph_grid *g, const struct wl_sph_eval *e,
                                         int n_bound, int i, double dt,
                                         wl_real *const *shift) {
  const int az = dim - 1;
  for (int a = 0; a < dim; a++) shift[a][i] = 0;
  if (!(k->shift_coef > 0) || i < n_bound) return;
  const int nc = g->n_cells;
  const int cell = (int)e->key[i] - nc;
  int first[9], last[9];
  const int nr = wl_sph_cell_rows(dim, g, cell, 0, first, last);
  const double xi[3] = {e->pos[0][i], dim == 3 ? e->pos[1][i] : 0.0, e->pos[az][i]};
  double gc[3] = {0, 0, 0}, divr = 0;
  for (int grp = 1; grp >= 0; grp--) { /* fluid, then boundary neighbours */
    const int *const b = e->begin + (grp ? nc : 0);
    for (int r = 0; r < nr; r++)
      wl_sph_shift_range(dim, k, e, xi, b[first[r]], b[last[r] + 1], 0, gc, &divr);
    for (int side = 0; dim == 3 && side < 2; side++) {
      if (!(k->mirror & (1 << side))) continue;
      int mf[6], ml[6];
      const int nm = wl_sph_cell_rows_mirror(g, cell, 0, side, mf, ml);
      for (int r = 0; r < nm; r++)
        wl_sph_shift_range(dim, k, e, xi, b[mf[r]], b[ml[r] + 1], side + 1, gc, &divr);
    }
  }
  if (divr < k->shift_tfs) return; /* at the free surface */
  double ramp = (divr - k->shift_tfs) / ((double)dim - k->shift_tfs);
  ramp = ramp > 1.0 ? 1.0 : ramp;
  double v2 = 0;
  for (int a = 0; a < dim; a++) v2 += (double)e->vel[a][i] * (double)e->vel[a][i];
  const double scale = -k->shift_coef * k->h_d * sqrt(v2) * dt * ramp;
  const double cap = 0.1 * k->dp;
  const double g3[3] = {gc[0], gc[1], gc[2]};
  for (int a = 0; a < dim; a++) {
    double s = scale * g3[a == az ? 2 : a];
    s = s > cap ? cap : s < -cap ? -cap : s;
    shift[a][i] = (wl_real)s;
  }
}

#endif
