/* sph/interact.h: one particle pair i-j of the weakly-compressible SPH
 * equations, the body of every neighbour loop (gather form: only particle
 * i's sums change). Forms and constants as DualSPHysics 5 (Dominguez et al.
 * 2022, Comp. Part. Mech. 9:867, eqs. 4-13), with r_ij = r_i - r_j,
 * v_ij = v_i - v_j, grad_i W_ij = F r_ij (sph/kernel.h):
 *
 * momentum (symmetric pressure term, seed 000 eq. 13 in DualSPHysics form):
 *   dv_i/dt = -sum_j m_j ((p_i + p_j)/(rho_i rho_j) + Pi_ij) grad_i W_ij + g
 * artificial viscosity (Monaghan 1992; seed 000 eq. 14):
 *   Pi_ij = -alpha c0 mu_ij / rho_ij-bar for v_ij.r_ij < 0, else 0;
 *   mu_ij = h v_ij.r_ij / (r^2 + eta^2), eta^2 = 0.01 h^2, rho-bar = mean density
 * laminar viscosity (Lo & Shao 2002), instead of Pi_ij:
 *   + sum_j m_j 4 nu r_ij.grad_i W_ij / ((rho_i + rho_j)(r^2 + eta^2)) v_ij
 * continuity (DualSPHysics 5 volume form):
 *   drho_i/dt = rho_i sum_j (m_j/rho_j) v_ij.grad_i W_ij + D_i
 * density diffusion (Molteni & Colagrossi 2009 with the hydrostatic
 * correction of Fourtakas et al. 2019, eq. 22; DualSPHysics DDT2):
 *   D_i = -delta 2h c0 sum_j ((rho_j - rho_i) - rho_H_ji) r_ij.grad_i W_ij / (r^2 + eta^2) m_j/rho_j
 *   (r_ij.grad W < 0, so a denser neighbour raises rho_i); rho_H_ji in sph/eos.h.
 *   The sum runs over fluid neighbours and, under the wall condition with the
 *   full diffusion (k->ddt_fb), over wall neighbours, whose density is the
 *   Tait density of their hydrostatically extrapolated pressure (sph/wall.h):
 *   a fluid particle next to a wall then has the whole stencil. With fluid
 *   neighbours alone the stencil is cut at the wall, and a one-sided sum
 *   of the hydrostatic remainder keeps adding density next to the bed: a
 *   still 0.5 m tank's bottom rows compressed by 1.3 % of their pressure
 *   and lifted the column 1.1 mm in 4.5 s, the bed pressure reading +0.9 %
 *   (docs/history/2026-11-26-still-tank-drift.md).
 * time-step input (DualSPHysics ViscDtMax, taken over pairs in the support):
 *   max_j |v_ij.r_ij| / (r^2 + eta^2)
 *
 * Everything is branch-free so that the CPU loop vectorises; particle i may
 * meet itself (r = 0: every term is 0). */
#ifndef WALLLOAD_SPH_INTERACT_H
#define WALLLOAD_SPH_INTERACT_H

#include "wallload/sph/eos.h"
#include "wallload/sph/kernel.h"

/* What one pair adds to particle i. */
struct wl_sph_pair {
  wl_real c_r;  /* acceleration += c_r r_ij [1/s^2] */
  wl_real c_v;  /* acceleration += c_v v_ij [1/s] (laminar viscosity only) */
  wl_real cont; /* (m_j/rho_j) v_ij.grad_i W_ij [1/s] (times rho_i later) */
  wl_real ddt;  /* density diffusion term [kg/m^3/s] */
  wl_real wq;   /* (1 - q/2) clamped, > 0 iff j is inside the support */
  wl_real visc; /* |v_ij.r_ij| / (r^2 + eta^2), 0 outside the support [1/s] */
};

/* One pair. r2 = |r_ij|^2 [m^2], rv = r_ij.v_ij [m^2/s], dz = z_i - z_j [m];
 * densities [kg/m^3], pressures [Pa]; inv_rho_i = 1/rho_i, inv_rho_j =
 * 1/rho_j and vol_j = m_j/rho_j (wl_sph_pair_j: computed once per j). av: alpha c0 h of
 * this pair kind (0 with laminar viscosity); lam: 4 nu (0 without);
 * with_ddt: a fluid-fluid pair (its diffusion coefficient k->ddt_k; other
 * pairs get k->ddt_fb, read only for a fluid particle's wall neighbour,
 * sph/gather.h). `laminar` and `with_ddt` must be compile-time constants at
 * the call site. */
WL_HD static WL_INLINE struct wl_sph_pair
wl_sph_pair_eval(const int laminar, const int with_ddt, const struct wl_sph_const *k, wl_real r2,
                 wl_real rv, wl_real dz, wl_real rho_i, wl_real inv_rho_i, wl_real p_i,
                 wl_real rho_j, wl_real inv_rho_j, wl_real vol_j, wl_real p_j, wl_real av,
                 wl_real lam) {
  struct wl_sph_pair o;
  const wl_real wq = wl_sph_kernel_wq(k, r2);
  const wl_real F = k->kf * wq * wq * wq;
  /* One correctly rounded division for both 1/(r^2 + eta^2) and
   * 1/(rho_i + rho_j): the viscous terms only need their product, and
   * 1/(r^2 + eta^2) alone is that product times (rho_i + rho_j). One
   * division fewer a pair (a vector division on the CPU, three
   * instructions on the GPU, sph/defs.h wl_sph_rcp) for one
   * multiplication; the quotients move by an ulp. The product is ~1e-4 m^2 x 2e3 kg/m^3: far from float's limits. */
  const wl_real rho_sum = rho_i + rho_j;
  const wl_real inv_r2e_rho_sum = wl_sph_rcp((r2 + k->eta2) * rho_sum);
  const wl_real inv_r2e = inv_r2e_rho_sum * rho_sum;
  const wl_real prs = (p_i + p_j) * inv_rho_i * inv_rho_j;
  if (laminar) {
    o.c_r = -k->mass * prs * F;
    o.c_v = k->mass * lam * F * r2 * inv_r2e_rho_sum;
    /* the pairs without density diffusion (fluid-wall) also get the
     * approach-only artificial viscosity av (params.h wall_alpha) */
    if (!with_ddt) o.c_r += k->mass * av * (rv - wl_sph_abs(rv)) * inv_r2e_rho_sum * F;
  } else {
    /* m_j Pi_ij = -m_j av (rv)^- / ((r^2 + eta^2) rho-bar), rho-bar = (rho_i + rho_j)/2;
     * 2 (rv)^- = rv - |rv| (sph/defs.h wl_sph_neg), with the same bits */
    const wl_real m_pi = -k->mass * av * (rv - wl_sph_abs(rv)) * inv_r2e_rho_sum;
    o.c_r = -(k->mass * prs + m_pi) * F;
    o.c_v = 0;
  }
  o.cont = vol_j * F * rv;
  o.ddt = -(with_ddt ? k->ddt_k : k->ddt_fb) * ((rho_j - rho_i) - wl_sph_eos_drho_hydro(k, dz)) *
          F * r2 * inv_r2e * vol_j;
  o.wq = wq;
  o.visc = wl_sph_abs(rv) * inv_r2e * wl_sph_nonzero(wq);
  return o;
}

/* Add pair o's acceleration to (*ax, *ay, *az) (*ay in 3D only); r_ij =
 * (dx, dy, dz), v_ij = (ux, uy, uz). Without laminar viscosity there is
 * no c_v term at all: adding c_v u = +0 would cost an add per axis, which
 * IEEE arithmetic may not drop (x + 0 is not x when x = -0), and keeps the
 * GPU from fusing the multiply into the sum. dim, laminar: compile-time
 * constants. */
WL_HD static WL_INLINE void wl_sph_pair_add_ace(const int dim, const int laminar,
                                                const struct wl_sph_pair *o, wl_real dx,
                                                wl_real dy, wl_real dz, wl_real ux, wl_real uy,
                                                wl_real uz, wl_real *ax, wl_real *ay,
                                                wl_real *az) {
  if (laminar) {
    *ax += o->c_r * dx + o->c_v * ux;
    if (dim == 3) *ay += o->c_r * dy + o->c_v * uy;
    *az += o->c_r * dz + o->c_v * uz;
  } else {
    *ax += o->c_r * dx;
    if (dim == 3) *ay += o->c_r * dy;
    *az += o->c_r * dz;
  }
}

/* 1/rho_j and m_j/rho_j, once per neighbour j. */
WL_HD static WL_INLINE void wl_sph_pair_j(const struct wl_sph_const *k, wl_real rho_j,
                                          wl_real *inv_rho_j, wl_real *vol_j) {
  *inv_rho_j = wl_sph_rcp(rho_j);
  *vol_j = k->mass * *inv_rho_j;
}

/* The pressure of fluid particle i in its pairs with wall particles: with
 * the wall condition (sph/wall.h) not below 0, as the wall's own: a wall
 * pushes the fluid off, it never pulls it on. A splash particle in tension
 * (density below rho0) would otherwise be drawn into the wall it runs
 * along, where nothing pushes back (the wall's pressure is the fluid's,
 * 0 at the surface). With the dynamic condition, p_i as it is. */
WL_HD static WL_INLINE wl_real wl_sph_pair_p_wall(const struct wl_sph_const *k, wl_real p_i) {
  return k->boundary == WL_SPH_BOUND_ADAMI && p_i < WL_R(0.0) ? WL_R(0.0) : p_i;
}

/* The same for a boundary neighbour j. With the wall condition (sph/wall.h)
 * a wall particle's volume is its lattice cell, m/rho0, whatever the
 * pressure it carries: a wall does not compress (Adami et al. 2012 keep
 * the wall particles' volumes fixed likewise). Were its volume m/rho_w, a
 * wall under the pressure p would push a fraction p/(7B) too weakly (1 %
 * at the bed of a still tank at coefsound 10: test_sph_wall). With the
 * dynamic condition the boundary particle's density gives both, as a fluid
 * particle's. */
WL_HD static WL_INLINE void wl_sph_pair_j_bound(const struct wl_sph_const *k, wl_real rho_j,
                                                wl_real *inv_rho_j, wl_real *vol_j) {
  if (k->boundary == WL_SPH_BOUND_ADAMI) {
    *inv_rho_j = k->inv_rho0;
    *vol_j = k->mass * k->inv_rho0;
  } else {
    wl_sph_pair_j(k, rho_j, inv_rho_j, vol_j);
  }
}

#endif
