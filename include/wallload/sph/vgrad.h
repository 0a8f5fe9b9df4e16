/* sph/vgrad.h: the residual viscosity, a dissipation of the particle-scale
 * velocity noise that leaves smooth flows alone (numerics.residual_viscosity;
 * docs/numerics.md, "Residual viscosity").
 *
 * Monaghan's (1992) artificial viscosity acts on the pair's velocity
 * difference v_ij = v_i - v_j; here it acts on what the linear field
 * around the pair does not explain:
 *
 *   u_ij = v_ij - G_ij r_ij,   G_ij = (G_i + G_j) / 2,
 *   mu_ij = h u_ij.r_ij / (r_ij^2 + eta^2),
 *   Pi_ij = -alpha_r c0 mu_ij / rho_ij-bar,
 *   dv_i/dt += -sum_j m_j Pi_ij grad_i W_ij        (fluid pairs only),
 *
 * with G_i particle i's velocity gradient, first-order corrected (Bonet &
 * Lok 1999) over its fluid neighbours:
 *
 *   A_i = sum_j V_j (v_j - v_i) (x) grad_i W_ij,
 *   L_i = sum_j V_j (r_j - r_i) (x) grad_i W_ij,   G_i = A_i L_i^-1,
 *
 * which is exact for a linear velocity field even where the kernel is cut
 * by the free surface or a wall. So a smooth flow (a travelling wave, whose
 * velocity is nearly linear over 2h) feels almost nothing, while the
 * particle arrangement's own motion, which no linear field describes, is
 * damped as by Monaghan's term. Unlike Monaghan's it acts on receding
 * residuals too (a viscosity of the residual, not a compression-only bulk
 * viscosity): the pair term then has no branch, so the CPU's lanes stay
 * one vector loop; on the reference suite the two forms measured alike
 * (docs/history/2026-11-26-still-tank-drift.md). The pair force stays
 * antisymmetric (momentum is kept). It is the idea of the reconstructed velocity jumps of
 * Riemann-solver SPH (Zhang, Hu & Adams 2017, J. Comput. Phys. 340:439,
 * where a limiter plays this role) in artificial-viscosity form.
 * Mirror-image pairs (3D symmetry planes) do not take it. */
#ifndef WALLLOAD_SPH_VGRAD_H
#define WALLLOAD_SPH_VGRAD_H

#include "wallload/sph/cells.h"
#include "wallload/sph/kernel.h"

/* A particle whose correction matrix is this close to singular (a lone
 * particle, a thin jet) gets G = 0: the residual is then its whole velocity
 * difference, as with Monaghan's term. L is about -I in the bulk. */
#define WL_SPH_VGRAD_DET_MIN WL_R(0.05)

/* G_i of fluid particle i (sorted index, key in the fluid group) from the
 * fluid particles of its cell rows, into g[a * dim + b][i] = dv_a/dx_b.
 * pos, vel, rho: the evaluated state; key, begin: the cell lists.
 * dim: compile-time constant. */
WL_HD static WL_INLINE void wl_sph_vgrad(const int dim, const struct wl_sph_const *k,
                                         const struct wl_sph_grid *grid, const double *const *pos,
                                         const wl_real *const *vel, const wl_real *rho,
                                         const unsigned int *key, const int *begin, int i,
                                         wl_real *const *g) {
  const int nc = grid->n_cells;
  int first[9], last[9];
  const int nr = wl_sph_cell_rows(dim, grid, (int)key[i] - nc, 0, first, last);
  const int *const bf = begin + nc;
  wl_real A[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  wl_real L[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int r = 0; r < nr; r++)
    for (int j = bf[first[r]]; j < bf[last[r] + 1]; j++) {
      wl_real d[3], r2 = 0;
      for (int a = 0; a < dim; a++) {
        d[a] = (wl_real)(pos[a][i] - pos[a][j]); /* r_ij */
        r2 += d[a] * d[a];
      }
      if (!(r2 < k->support2)) continue;
      const wl_real vF = k->mass / rho[j] * wl_sph_kernel_f(k, r2); /* V_j grad W = vF r_ij */
      for (int a = 0; a < dim; a++) {
        const wl_real dv = vel[a][j] - vel[a][i];
        for (int b = 0; b < dim; b++) {
          A[a][b] += dv * vF * d[b];
          L[a][b] -= d[a] * vF * d[b];
        }
      }
    }
  /* G = A L^-1 from L's adjugate */
  wl_real inv[3][3];
  wl_real det;
  if (dim == 2) {
    det = L[0][0] * L[1][1] - L[0][1] * L[1][0];
    inv[0][0] = L[1][1], inv[0][1] = -L[0][1];
    inv[1][0] = -L[1][0], inv[1][1] = L[0][0];
  } else {
    inv[0][0] = L[1][1] * L[2][2] - L[1][2] * L[2][1];
    inv[0][1] = L[0][2] * L[2][1] - L[0][1] * L[2][2];
    inv[0][2] = L[0][1] * L[1][2] - L[0][2] * L[1][1];
    inv[1][0] = L[1][2] * L[2][0] - L[1][0] * L[2][2];
    inv[1][1] = L[0][0] * L[2][2] - L[0][2] * L[2][0];
    inv[1][2] = L[0][2] * L[1][0] - L[0][0] * L[1][2];
    inv[2][0] = L[1][0] * L[2][1] - L[1][1] * L[2][0];
    inv[2][1] = L[0][1] * L[2][0] - L[0][0] * L[2][1];
    inv[2][2] = L[0][0] * L[1][1] - L[0][1] * L[1][0];
    det = L[0][0] * inv[0][0] + L[0][1] * inv[1][0] + L[0][2] * inv[2][0];
  }
  const int ok = det > WL_SPH_VGRAD_DET_MIN || det < -WL_SPH_VGRAD_DET_MIN;
  const wl_real s = ok ? WL_R(1.0) / det : WL_R(0.0);
  for (int a = 0; a < dim; a++)
    for (int b = 0; b < dim; b++) {
      wl_real v = 0;
      for (int c = 0; c < dim; c++) v += A[a][c] * inv[c][b];
      g[a * dim + b][i] = v * s;
    }
}

/* The residual viscosity's acceleration coefficient of a fluid pair: the
 * pair adds c r_ij to particle i's acceleration. r_ij = (dx, dy, dz),
 * v_ij = (ux, uy, uz) (dy, uy 0 in 2D), gi / gj the two gradients (dim x
 * dim, row-major), rho_sum = rho_i + rho_j. 0 beyond the support. dim:
 * compile-time constant. */
WL_HD static WL_INLINE wl_real wl_sph_pair_residual(const int dim, const struct wl_sph_const *k,
                                                    wl_real dx, wl_real dy, wl_real dz,
                                                    wl_real ux, wl_real uy, wl_real uz,
                                                    const wl_real *gi, const wl_real *gj,
                                                    wl_real rho_sum) {
  const wl_real d[3] = {dx, dim == 3 ? dy : dz, dz};
  const wl_real u[3] = {ux, dim == 3 ? uy : uz, uz};
  wl_real rv = 0, r2 = 0;
  for (int a = 0; a < dim; a++) {
    wl_real lin = 0;
    for (int b = 0; b < dim; b++) lin += WL_R(0.5) * (gi[a * dim + b] + gj[a * dim + b]) * d[b];
    rv += d[a] * (u[a] - lin);
    r2 += d[a] * d[a];
  }
  /* -m Pi F with Pi = -2 rav rv / ((r^2 + eta^2) rho_sum), rav = alpha_r c0 h; F is 0
   * beyond the support. No branch: the CPU's lanes stay one vector loop */
  return WL_R(2.0) * k->mass * k->rav * rv * wl_sph_kernel_f(k, r2) *
         wl_sph_rcp((r2 + k->eta2) * rho_sum);
}

/* The eddy viscosity (numerics.smagorinsky; docs/numerics.md, "Eddy
 * viscosity"): Smagorinsky's (1963) model of the motion below the particle
 * scale, as the sub-particle-scale (SPS) model of Dalrymple & Rogers (2006,
 * Coastal Eng. 53:141) and DualSPHysics' Laminar+SPS viscosity take it,
 * in its eddy-viscosity part: the divergence of 2 nu_t S written as the
 * laminar operator with each pair's nu_t (exact where nu_t is uniform),
 * instead of their SPS stress tensor's own divergence, whose isotropic
 * part the pressure absorbs:
 *
 *   nu_t,i = (C_s dp)^2 |S_i|,   |S| = sqrt(2 S:S),   S = (G + G^T) / 2,
 *
 * with G_i the corrected velocity gradient above. It is large where the
 * flow shears at the particle scale (a surge's front, a plunging jet, an
 * impact: |S| of 100 1/s gives 6e-4 m^2/s at dp = 0.02 m and C_s = 0.12)
 * and about water's own viscosity in a travelling wave (|S| ~ 1 1/s).
 * It adds to nu in the laminar term of sph/interact.h, pair by pair:
 * a fluid pair takes the mean of its two nu_t, a fluid-wall pair the fluid
 * particle's (the wall's friction on a sheared flow, the laminar term's
 * no-slip form). The pair force stays antisymmetric. Mirror-image pairs
 * (3D symmetry planes) do not take it. */

/* nu_t of a particle whose corrected velocity gradient is g[a * dim + b]
 * = dv_a/dx_b [m^2/s]. */
WL_HD static WL_INLINE wl_real wl_sph_eddy_nu(const int dim, const struct wl_sph_const *k,
                                              const wl_real *g) {
  wl_real ss = 0; /* 2 S:S */
  for (int a = 0; a < dim; a++)
    for (int b = 0; b < dim; b++) {
      const wl_real s = WL_R(0.5) * (g[a * dim + b] + g[b * dim + a]);
      ss += WL_R(2.0) * s * s;
    }
  return k->nut_c * wl_sph_sqrt(ss);
}

/* The pair's eddy-viscous term: acceleration += c v_ij with c the laminar
 * term's coefficient (sph/interact.h) for 4 nu_t: m 4 nu_t F r^2 /
 * ((r^2 + eta^2)(rho_i + rho_j)); 0 beyond the support (F is). */
WL_HD static WL_INLINE wl_real wl_sph_pair_eddy(const struct wl_sph_const *k, wl_real r2,
                                                wl_real nut, wl_real rho_sum) {
  return k->mass * WL_R(4.0) * nut * wl_sph_kernel_f(k, r2) * r2 *
         wl_sph_rcp((r2 + k->eta2) * rho_sum);
}

#endif
