/* sph/gather.h: one force evaluation for particle i, in gather form (SPH-
 * EXA, SWIFT): particle i walks the 3 (2D) or 9 (3D) rows of cells around
 * its own, each row one contiguous index range per group (sph/cells.h),
 * sums the pair terms of sph/interact.h and writes only its own outputs.
 * No atomics; the result does not depend on how particles are spread over
 * threads (CPU) or blocks (GPU).
 *
 * One body, two shapes. wl_sph_gather_block handles `lanes` particles of
 * one cell at once: for each neighbour j it updates every lane, so the lane
 * loop (a compile-time count) is what the CPU compiler vectorises, and each
 * particle still sums its neighbours in exactly the order of a lone
 * particle: rows in order, j increasing, fluid then boundary. Results are
 * therefore bit-identical whatever the lane count or the vector ISA (no
 * reassociated sums); lanes = 1 is the per-particle form (one CUDA thread
 * per particle).
 *
 * Pairs (as DualSPHysics with the dynamic boundary condition, Crespo et al.
 * 2007, CMC 5:173): fluid i sums fluid and boundary neighbours; boundary i
 * sums fluid neighbours only, and only the continuity equation (its density
 * then gives the pressure that keeps fluid out). Boundary-boundary pairs are
 * never visited. Density diffusion acts between fluid pairs only. With the
 * wall condition (params.h WL_SPH_BOUND_ADAMI, the default) the backends
 * call this for fluid particles only: the boundary particles' density and
 * pressure come from sph/wall.h's pass before it, and a fluid particle's
 * pairs with them take the wall's volume and pressure rules of
 * sph/interact.h (wl_sph_pair_j_bound, wl_sph_pair_p_wall).
 *
 * Mirror planes (k->mirror, 3D; sph/params.h), at the grid's low and high
 * y faces: a particle in the cell layers beside a plane also sums, after
 * each group's ordinary rows, the mirror images of that group's particles
 * in those layers (cells.h wl_sph_cell_rows_mirror) as if they were
 * neighbours: the images of a symmetric scene's other half, so its half
 * runs alone; or a free-slip wall. */
#ifndef WALLLOAD_SPH_GATHER_H
#define WALLLOAD_SPH_GATHER_H

#include <string.h>

#include "wallload/sph/cells.h"
#include "wallload/sph/interact.h"
#include "wallload/sph/particles.h"

/* Most particles one wl_sph_gather_block call handles. */
#define WL_SPH_LANES 8

/* The arrays one force evaluation reads and writes. Inputs are the state at
 * which forces are evaluated (the step start or the predictor's half step). */
struct wl_sph_eval {
  const double *pos[WL_SPH_DIM_MAX];
  const wl_real *vel[WL_SPH_DIM_MAX];
  const wl_real *rho;
  const wl_real *press;          /* EOS of rho, filled before the loop */
  const unsigned int *key;       /* sorted keys: group * n_cells + cell */
  const int *begin;              /* 2 n_cells + 1 range starts, by key */
  wl_real *ace[WL_SPH_DIM_MAX];  /* out: acceleration incl. gravity [m/s^2] */
  wl_real *ar;                   /* out: drho/dt [kg/m^3/s] */
  wl_real *visc;                 /* out: h max_j |v_ij.r_ij|/(r^2+eta^2) [m/s] */
};

/* An evaluation's inputs (outputs NULL): the state at which a neighbour
 * loop runs and the cell lists it walks. */
static inline struct wl_sph_eval wl_sph_eval_inputs(int dim, double *const *pos,
                                                    wl_real *const *vel, const wl_real *rho,
                                                    const unsigned int *key, const int *begin) {
  struct wl_sph_eval e;
  memset(&e, 0, sizeof e);
  for (int a = 0; a < dim; a++) {
    e.pos[a] = pos[a];
    e.vel[a] = vel[a];
  }
  e.rho = rho;
  e.key = key;
  e.begin = begin;
  return e;
}

/* Running sums of the lanes (one particle each). */
struct wl_sph_acc {
  wl_real a[WL_SPH_DIM_MAX][WL_SPH_LANES];
  wl_real cont[WL_SPH_LANES], ddt[WL_SPH_LANES], wsum[WL_SPH_LANES], visc[WL_SPH_LANES];
};

/* The particles of the lanes. */
struct wl_sph_lanes {
  double x[WL_SPH_DIM_MAX][WL_SPH_LANES];
  wl_real v[WL_SPH_DIM_MAX][WL_SPH_LANES];
  wl_real rho[WL_SPH_LANES], inv_rho[WL_SPH_LANES], p[WL_SPH_LANES];
};

/* Add the pairs of every lane with neighbours j in [j0, j1), or with their
 * mirror images in the plane y = k->mirror_y[mirror - 1] when mirror is 1
 * (the low plane) or 2 (the high one), 3D.
 * dim, laminar, want_ace, with_ddt, lanes: compile-time constants. av, lam:
 * see wl_sph_pair_eval. */
WL_HD static WL_INLINE void wl_sph_gather_range(const int dim, const int laminar,
                                                const int want_ace, const int with_ddt,
                                                const int lanes, const struct wl_sph_const *k,
                                                const struct wl_sph_eval *e,
                                                const struct wl_sph_lanes *in, int j0, int j1,
                                                wl_real av, wl_real lam, const int mirror,
                                                struct wl_sph_acc *acc) {
  const int az = dim - 1; /* vertical axis */
  for (int j = j0; j < j1; j++) {
    const double xj = e->pos[0][j], zj = e->pos[az][j];
    const double yj = dim != 3 ? 0.0
                      : mirror ? 2.0 * k->mirror_y[mirror - 1] - e->pos[1][j]
                               : e->pos[1][j];
    const wl_real uxj = e->vel[0][j], uzj = e->vel[az][j];
    const wl_real uyj = dim != 3 ? WL_R(0.0) : mirror ? -e->vel[1][j] : e->vel[1][j];
    const wl_real rho_j = e->rho[j], p_j = e->press[j];
    wl_real inv_rho_j, vol_j;
    /* the pairs with an acceleration and no density diffusion are exactly
     * those of a fluid i with a boundary j (wl_sph_gather_block) */
    if (want_ace && !with_ddt) wl_sph_pair_j_bound(k, rho_j, &inv_rho_j, &vol_j);
    else wl_sph_pair_j(k, rho_j, &inv_rho_j, &vol_j);
    for (int l = 0; l < lanes; l++) {
      /* position differences in double, narrowed (sph/defs.h) */
      const wl_real dx = (wl_real)(in->x[0][l] - xj);
      const wl_real dy = dim == 3 ? (wl_real)(in->x[1][l] - yj) : WL_R(0.0);
      const wl_real dz = (wl_real)(in->x[az][l] - zj);
      const wl_real ux = in->v[0][l] - uxj;
      const wl_real uy = dim == 3 ? in->v[1][l] - uyj : WL_R(0.0);
      const wl_real uz = in->v[az][l] - uzj;
      const wl_real r2 = dx * dx + dy * dy + dz * dz;
      const wl_real rv = dx * ux + dy * uy + dz * uz;
      const wl_real p_i = want_ace && !with_ddt ? wl_sph_pair_p_wall(k, in->p[l]) : in->p[l];
      const struct wl_sph_pair o =
          wl_sph_pair_eval(laminar, with_ddt, k, r2, rv, dz, in->rho[l], in->inv_rho[l], p_i,
                           rho_j, inv_rho_j, vol_j, p_j, av, lam);
      if (want_ace)
        wl_sph_pair_add_ace(dim, laminar, &o, dx, dy, dz, ux, uy, uz, &acc->a[0][l],
                            &acc->a[1][l], &acc->a[2][l]);
      acc->cont[l] += o.cont;
      acc->ddt[l] += o.ddt;
      acc->wsum[l] += o.wq;
      acc->visc[l] = wl_sph_max_nonneg(acc->visc[l], o.visc);
    }
  }
}

/* The end of particle i's evaluation, from its sums over fluid neighbours
 * (fa, fcont, fddt, fvisc) and, for a fluid particle, over boundary ones
 * (ba, bcont, bwsum, bvisc); fa and ba hold the horizontal, transverse
 * (3D) and vertical components at 0, 1 and 2. A fluid particle's
 * acceleration adds gravity; its density rate the diffusion, except under
 * DDT2 (not Full) next to a wall; its time-step input takes the larger of
 * the two sums. A boundary particle (DBC) keeps only its continuity
 * equation. Every force loop of every backend ends with this. */
WL_HD static WL_INLINE void wl_sph_finish(const int dim, const struct wl_sph_const *k,
                                          const struct wl_sph_eval *e, int i, int fluid,
                                          wl_real rho_i, const wl_real *fa, wl_real fcont,
                                          wl_real fddt, wl_real fvisc, const wl_real *ba,
                                          wl_real bcont, wl_real bwsum, wl_real bvisc) {
  if (fluid) {
    const wl_real ddt = (k->ddt == WL_SPH_DDT_FOURTAKAS && bwsum > 0) ? WL_R(0.0) : fddt;
    e->ace[0][i] = fa[0] + ba[0] + k->gravity[0];
    if (dim == 3) e->ace[1][i] = fa[1] + ba[1] + k->gravity[1];
    e->ace[dim - 1][i] = fa[2] + ba[2] + k->gravity[dim - 1];
    e->ar[i] = rho_i * (fcont + bcont) + ddt;
    e->visc[i] = k->h * wl_sph_max_nonneg(fvisc, bvisc);
  } else {
    for (int a = 0; a < dim; a++) e->ace[a][i] = 0;
    e->ar[i] = rho_i * fcont;
    e->visc[i] = k->h * fvisc;
  }
}

/* Forces on particles i0 .. i0 + m - 1 (sorted indices, 1 <= m <= lanes) of
 * one group, in cells `span` + 1 consecutive cells of one row (span 0: one
 * cell); writes e->ace, e->ar, e->visc of each. Lanes beyond m repeat the
 * last particle and are discarded. The rows then reach one cell further
 * than a particle needs; those particles are at least 2h away and add exact
 * zeros, so the result does not depend on how particles are grouped into
 * blocks. dim, laminar, lanes: compile-time constants. */
WL_HD static WL_INLINE void wl_sph_gather_block(const int dim, const int laminar, const int lanes,
                                                const struct wl_sph_const *k,
                                                const struct wl_sph_grid *g,
                                                const struct wl_sph_eval *e, int n_bound, int i0,
                                                int m, int span) {
  const int nc = g->n_cells;
  const int fluid = i0 >= n_bound;
  const int cell = (int)e->key[i0] - (fluid ? nc : 0);
  int first[9], last[9];
  const int nr = wl_sph_cell_rows(dim, g, cell, span, first, last);
  const int *const bf = e->begin + nc; /* fluid group */
  const int *const bb = e->begin;      /* boundary group */
  struct wl_sph_lanes in;
  for (int l = 0; l < lanes; l++) {
    const int i = i0 + (l < m ? l : m - 1);
    for (int a = 0; a < dim; a++) {
      in.x[a][l] = e->pos[a][i];
      in.v[a][l] = e->vel[a][i];
    }
    in.rho[l] = e->rho[i];
    in.inv_rho[l] = wl_sph_rcp(e->rho[i]);
    in.p[l] = e->press[i];
  }
  struct wl_sph_acc f; /* fluid neighbours */
  for (int l = 0; l < lanes; l++) {
    for (int a = 0; a < WL_SPH_DIM_MAX; a++) f.a[a][l] = 0;
    f.cont[l] = f.ddt[l] = f.wsum[l] = f.visc[l] = 0;
  }
  /* mirror rows: only next to a mirror plane (3D); side s in rows
   * mfirst[s]..., mirror pass s + 1 */
  int mfirst[2][6], mlast[2][6], nm[2] = {0, 0};
  if (dim == 3) wl_sph_cell_rows_mirrors(g, k->mirror, cell, span, mfirst, mlast, nm);
  if (fluid) {
    struct wl_sph_acc b = f; /* boundary neighbours */
    for (int r = 0; r < nr; r++)
      wl_sph_gather_range(dim, laminar, 1, 1, lanes, k, e, &in, bf[first[r]], bf[last[r] + 1],
                          k->av_ff, k->lam_ff, 0, &f);
    for (int side = 0; dim == 3 && side < 2; side++)
      for (int r = 0; r < nm[side]; r++)
        wl_sph_gather_range(dim, laminar, 1, 1, lanes, k, e, &in, bf[mfirst[side][r]],
                            bf[mlast[side][r] + 1], k->av_ff, k->lam_ff, side + 1, &f);
    for (int r = 0; r < nr; r++)
      wl_sph_gather_range(dim, laminar, 1, 0, lanes, k, e, &in, bb[first[r]], bb[last[r] + 1],
                          k->av_fb, k->lam_fb, 0, &b);
    for (int side = 0; dim == 3 && side < 2; side++)
      for (int r = 0; r < nm[side]; r++)
        wl_sph_gather_range(dim, laminar, 1, 0, lanes, k, e, &in, bb[mfirst[side][r]],
                            bb[mlast[side][r] + 1], k->av_fb, k->lam_fb, side + 1, &b);
    for (int l = 0; l < m; l++) {
      const wl_real fa[3] = {f.a[0][l], f.a[1][l], f.a[2][l]};
      const wl_real ba[3] = {b.a[0][l], b.a[1][l], b.a[2][l]};
      wl_sph_finish(dim, k, e, i0 + l, 1, in.rho[l], fa, f.cont[l], f.ddt[l], f.visc[l], ba,
                    b.cont[l], b.wsum[l], b.visc[l]);
    }
  } else {
    for (int r = 0; r < nr; r++)
      wl_sph_gather_range(dim, laminar, 0, 0, lanes, k, e, &in, bf[first[r]], bf[last[r] + 1],
                          k->av_fb, k->lam_fb, 0, &f);
    for (int side = 0; dim == 3 && side < 2; side++)
      for (int r = 0; r < nm[side]; r++)
        wl_sph_gather_range(dim, laminar, 0, 0, lanes, k, e, &in, bf[mfirst[side][r]],
                            bf[mlast[side][r] + 1], k->av_fb, k->lam_fb, side + 1, &f);
    for (int l = 0; l < m; l++)
      wl_sph_finish(dim, k, e, i0 + l, 0, in.rho[l], NULL, f.cont[l], 0, f.visc[l], NULL, 0, 0,
                    0);
  }
}

/* Forces on the single particle i (the per-particle form, one CUDA thread
 * each); the same results as wl_sph_gather_block, bit for bit. */
WL_HD static WL_INLINE void wl_sph_gather(const int dim, const int laminar,
                                          const struct wl_sph_const *k,
                                          const struct wl_sph_grid *g,
                                          const struct wl_sph_eval *e, int n_bound, int i) {
  wl_sph_gather_block(dim, laminar, 1, k, g, e, n_bound, i, 1, 0);
}

#endif
