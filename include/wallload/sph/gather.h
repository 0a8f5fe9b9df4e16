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
 * never visited. Density diffusion acts on fluid particles only, between
 * fluid pairs (and, with the wall condition, fluid-wall pairs: k->ddt_fb).
 * With the wall condition (params.h WL_SPH_BOUND_ADAMI, the default) the
 * backends call this for fluid particles only: the boundary particles'
 * density and pressure come from sph/wall.h's pass before it, and a fluid
 * particle's pairs with them take the wall's volume and pressure rules of
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
#include "wallload/sph/vgrad.h"

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
  /* the fluid's velocity gradients (sph/vgrad.h; dim x dim row-major,
   * dv_a/dx_b in gv[a dim + b]) when the residual viscosity is on (k->rav
   * > 0), filled before the loop; else NULL */
  const wl_real *gv[WL_SPH_DIM_MAX * WL_SPH_DIM_MAX];
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
  wl_real g[WL_SPH_DIM_MAX * WL_SPH_DIM_MAX][WL_SPH_LANES]; /* velocity gradient (residual) */
  wl_real nut[WL_SPH_LANES]; /* its eddy viscosity (sph/vgrad.h), where k->nut_c > 0 */
};

/* The pair of lane l (the particle's r_ij = (dx, dy, dz), v_ij = (ux, uy,
 * uz), density, 1/density and pressure) with a neighbour j (its density,
 * wl_sph_pair_j's 1/rho_j and m_j/rho_j, its pressure) added to lane l's
 * sums. This is the body of every neighbour loop of every backend; they
 * differ only in how they find j and its values (wl_sph_gather_range
 * below; cuda.cu's split loop from staged candidates). The pairs with an
 * acceleration and no density diffusion are exactly those of a fluid i
 * with a boundary j (wl_sph_gather_block), whose p_i is the wall's
 * (interact.h wl_sph_pair_p_wall). dim, laminar, want_ace, with_ddt:
 * compile-time constants; av, lam: see wl_sph_pair_eval. */
WL_HD static WL_INLINE void wl_sph_pair_sum(const int dim, const int laminar, const int want_ace,
                                            const int with_ddt, const struct wl_sph_const *k,
                                            wl_real dx, wl_real dy, wl_real dz, wl_real ux,
                                            wl_real uy, wl_real uz, wl_real rho_i,
                                            wl_real inv_rho_i, wl_real p_i, wl_real rho_j,
                                            wl_real inv_rho_j, wl_real vol_j, wl_real p_j,
                                            wl_real av, wl_real lam, struct wl_sph_acc *acc,
                                            int l) {
  const wl_real r2 = dx * dx + dy * dy + dz * dz;
  const wl_real rv = dx * ux + dy * uy + dz * uz;
  const wl_real p_ip = want_ace && !with_ddt ? wl_sph_pair_p_wall(k, p_i) : p_i;
  const struct wl_sph_pair o = wl_sph_pair_eval(laminar, with_ddt, k, r2, rv, dz, rho_i, inv_rho_i,
                                                p_ip, rho_j, inv_rho_j, vol_j, p_j, av, lam);
  if (want_ace)
    wl_sph_pair_add_ace(dim, laminar, &o, dx, dy, dz, ux, uy, uz, &acc->a[0][l], &acc->a[1][l],
                        &acc->a[2][l]);
  acc->cont[l] += o.cont;
  /* fluid-fluid and fluid-wall pairs (a wall pair's is 0 unless k->ddt_fb) */
  if (want_ace || with_ddt) acc->ddt[l] += o.ddt;
  acc->wsum[l] += o.wq;
  acc->visc[l] = wl_sph_max_nonneg(acc->visc[l], o.visc);
}

/* wl_sph_pair_j for neighbour j of density rho_j, or wl_sph_pair_j_bound
 * when j is a boundary neighbour of a fluid particle (want_ace and not
 * with_ddt, as in wl_sph_pair_sum). */
WL_HD static WL_INLINE void wl_sph_pair_j_of(const int want_ace, const int with_ddt,
                                             const struct wl_sph_const *k, wl_real rho_j,
                                             wl_real *inv_rho_j, wl_real *vol_j) {
  if (want_ace && !with_ddt) wl_sph_pair_j_bound(k, rho_j, inv_rho_j, vol_j);
  else wl_sph_pair_j(k, rho_j, inv_rho_j, vol_j);
}

/* Add the pairs of every lane with neighbours j in [j0, j1), or with their
 * mirror images in the plane y = k->mirror_y[mirror - 1] when mirror is 1
 * (the low plane) or 2 (the high one), 3D.
 * cut (lanes = 1 only): a candidate farther than 2h (r^2 >= k->support2
 * (1 + 1e-4), a margin far above float rounding) is skipped before its
 * values are loaded and its pair evaluated. Such a pair adds exact zeros
 * (W, grad W and the time-step term are 0 beyond the support), so each sum
 * gets the same terms in the same order: the same bits as without cut. The
 * GPU's one-thread-per-particle loop uses it; the CPU's lanes evaluate
 * every candidate (branch-free, vectorised).
 * residual: add the terms of the velocity gradients (sph/vgrad.h) to each
 * pair (want_ace, not a mirror image): the residual viscosity's to a fluid
 * pair (with_ddt) where k->rav > 0, the eddy viscosity's to a fluid or wall
 * pair where k->nut_c > 0; e->gv and in->g must then hold the gradients.
 * dim, laminar, want_ace, with_ddt, lanes, cut, residual: compile-time
 * constants. av, lam: see wl_sph_pair_eval. */
WL_HD static WL_INLINE void wl_sph_gather_range(const int dim, const int laminar,
                                                const int want_ace, const int with_ddt,
                                                const int lanes, const int cut,
                                                const struct wl_sph_const *k,
                                                const struct wl_sph_eval *e,
                                                const struct wl_sph_lanes *in, int j0, int j1,
                                                wl_real av, wl_real lam, const int mirror,
                                                struct wl_sph_acc *acc, const int residual) {
  const int az = dim - 1; /* vertical axis */
  const double *const px = e->pos[0], *const pz = e->pos[az];
  const double *const py = e->pos[dim == 3 ? 1 : 0];
  const double y2 = dim == 3 && mirror ? 2.0 * k->mirror_y[mirror - 1] : 0.0;
  WL_GPU_UNROLL_RANGE
  for (int j = j0; j < j1; j++) {
    const double xj = WL_LDG(px + j), zj = WL_LDG(pz + j);
    const double yj = dim != 3 ? 0.0 : mirror ? y2 - WL_LDG(py + j) : WL_LDG(py + j);
    if (cut) {
      /* position differences in double, narrowed (sph/defs.h) */
      const wl_real dx = (wl_real)(in->x[0][0] - xj);
      const wl_real dy = dim == 3 ? (wl_real)(in->x[1][0] - yj) : WL_R(0.0);
      const wl_real dz = (wl_real)(in->x[az][0] - zj);
      if (!((dx * dx + dy * dy + dz * dz) * WL_R(0.9999) < k->support2)) continue;
    }
    const wl_real uxj = WL_LDG(e->vel[0] + j), uzj = WL_LDG(e->vel[az] + j);
    const wl_real vyj = dim == 3 ? WL_LDG(e->vel[1] + j) : WL_R(0.0);
    const wl_real uyj = mirror ? -vyj : vyj;
    const wl_real rho_j = WL_LDG(e->rho + j), p_j = WL_LDG(e->press + j);
    wl_real inv_rho_j, vol_j;
    wl_sph_pair_j_of(want_ace, with_ddt, k, rho_j, &inv_rho_j, &vol_j);
    for (int l = 0; l < lanes; l++) {
      const wl_real dx = (wl_real)(in->x[0][l] - xj);
      const wl_real dy = dim == 3 ? (wl_real)(in->x[1][l] - yj) : WL_R(0.0);
      const wl_real dz = (wl_real)(in->x[az][l] - zj);
      const wl_real ux = in->v[0][l] - uxj;
      const wl_real uy = dim == 3 ? in->v[1][l] - uyj : WL_R(0.0);
      const wl_real uz = in->v[az][l] - uzj;
      wl_sph_pair_sum(dim, laminar, want_ace, with_ddt, k, dx, dy, dz, ux, uy, uz, in->rho[l],
                      in->inv_rho[l], in->p[l], rho_j, inv_rho_j, vol_j, p_j, av, lam, acc, l);
      if (residual && want_ace && !mirror) {
        /* the terms of the velocity gradients (sph/vgrad.h): the residual
         * viscosity (fluid pairs) and the eddy viscosity (fluid and wall
         * pairs), each where it is on */
        wl_real gi[WL_SPH_DIM_MAX * WL_SPH_DIM_MAX], gj[WL_SPH_DIM_MAX * WL_SPH_DIM_MAX];
        for (int q = 0; q < dim * dim; q++) {
          gi[q] = in->g[q][l];
          gj[q] = with_ddt ? WL_LDG(e->gv[q] + j) : WL_R(0.0);
        }
        if (with_ddt && k->rav > 0) {
          const wl_real c =
              wl_sph_pair_residual(dim, k, dx, dy, dz, ux, uy, uz, gi, gj, in->rho[l] + rho_j);
          acc->a[0][l] += c * dx;
          if (dim == 3) acc->a[1][l] += c * dy;
          acc->a[2][l] += c * dz;
        }
        if (k->nut_c > 0) {
          const wl_real nut_i = in->nut[l];
          const wl_real nut = with_ddt ? WL_R(0.5) * (nut_i + wl_sph_eddy_nu(dim, k, gj)) : nut_i;
          const wl_real c = wl_sph_pair_eddy(k, dx * dx + dy * dy + dz * dz, nut,
                                             in->rho[l] + rho_j);
          acc->a[0][l] += c * ux;
          if (dim == 3) acc->a[1][l] += c * uy;
          acc->a[2][l] += c * uz;
        }
      }
    }
  }
}

/* The mirror planes' passes of particle(s) in cells cell .. cell + span
 * (3D, k->mirror set; none otherwise): the images of the fluid rows beside
 * each plane into f, and for a fluid particle the images of the boundary
 * rows into b (with fluid 0, b is not touched). Each sum gets its terms
 * after the ordinary rows, low plane then high plane: the order of
 * wl_sph_gather_block. dim, laminar, lanes, cut, fluid: compile-time
 * constants where the caller can make them so. */
WL_HD static WL_INLINE void wl_sph_gather_mirrors(const int dim, const int laminar,
                                                  const int lanes, const int cut,
                                                  const struct wl_sph_const *k,
                                                  const struct wl_sph_grid *g,
                                                  const struct wl_sph_eval *e,
                                                  const struct wl_sph_lanes *in, const int fluid,
                                                  int cell, int span, struct wl_sph_acc *f,
                                                  struct wl_sph_acc *b) {
  if (dim != 3 || !k->mirror) return;
  const int *const bf = e->begin + g->n_cells; /* fluid group */
  const int *const bb = e->begin;              /* boundary group */
  int mf[2][6], ml[2][6], nm[2] = {0, 0};
  wl_sph_cell_rows_mirrors(g, k->mirror, cell, span, mf, ml, nm);
  for (int side = 0; side < 2; side++)
    for (int r = 0; r < nm[side]; r++) {
      if (fluid)
        wl_sph_gather_range(dim, laminar, 1, 1, lanes, cut, k, e, in, bf[mf[side][r]],
                            bf[ml[side][r] + 1], k->av_ff, k->lam_ff, side + 1, f, 0);
      else
        wl_sph_gather_range(dim, laminar, 0, 0, lanes, cut, k, e, in, bf[mf[side][r]],
                            bf[ml[side][r] + 1], k->av_fb, k->lam_fb, side + 1, f, 0);
    }
  if (fluid)
    for (int side = 0; side < 2; side++)
      for (int r = 0; r < nm[side]; r++)
        wl_sph_gather_range(dim, laminar, 1, 0, lanes, cut, k, e, in, bb[mf[side][r]],
                            bb[ml[side][r] + 1], k->av_fb, k->lam_fb, side + 1, b, 0);
}

/* The end of particle i's evaluation, from lane l of its sums over fluid
 * neighbours f and, for a fluid particle, over boundary ones b (a boundary
 * particle's call may pass f for b: it is not read). A fluid particle's
 * acceleration adds gravity; its density rate the diffusion over fluid and
 * (k->ddt_fb) wall neighbours, none under DDT2 (not Full) next to a wall;
 * its time-step input takes the larger of
 * the two sums. A boundary particle (DBC) keeps only its continuity
 * equation. Every force loop of every backend ends with this. fluid:
 * compile-time constant where the caller can make it so. */
WL_HD static WL_INLINE void wl_sph_finish(const int dim, const struct wl_sph_const *k,
                                          const struct wl_sph_eval *e, int i, const int fluid,
                                          wl_real rho_i, const struct wl_sph_acc *f,
                                          const struct wl_sph_acc *b, int l) {
  if (fluid) {
    const wl_real ddt =
        (k->ddt == WL_SPH_DDT_FOURTAKAS && b->wsum[l] > 0) ? WL_R(0.0) : f->ddt[l] + b->ddt[l];
    e->ace[0][i] = f->a[0][l] + b->a[0][l] + k->gravity[0];
    if (dim == 3) e->ace[1][i] = f->a[1][l] + b->a[1][l] + k->gravity[1];
    e->ace[dim - 1][i] = f->a[2][l] + b->a[2][l] + k->gravity[dim - 1];
    e->ar[i] = rho_i * (f->cont[l] + b->cont[l]) + ddt;
    e->visc[i] = k->h * wl_sph_max_nonneg(f->visc[l], b->visc[l]);
  } else {
    for (int a = 0; a < dim; a++) e->ace[a][i] = 0;
    e->ar[i] = rho_i * f->cont[l];
    e->visc[i] = k->h * f->visc[l];
  }
}

/* Forces on particles i0 .. i0 + m - 1 (sorted indices, 1 <= m <= lanes) of
 * one group, in cells `span` + 1 consecutive cells of one row (span 0: one
 * cell); writes e->ace, e->ar, e->visc of each. Lanes beyond m repeat the
 * last particle and are discarded. The rows then reach one cell further
 * than a particle needs; those particles are at least 2h away and add exact
 * zeros, so the result does not depend on how particles are grouped into
 * blocks. cut: see wl_sph_gather_range (lanes = 1 only; the same bits).
 * dim, laminar, lanes, cut: compile-time constants. */
WL_HD static WL_INLINE void wl_sph_gather_block(const int dim, const int laminar, const int lanes,
                                                const int cut, const struct wl_sph_const *k,
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
    wl_real gl[WL_SPH_DIM_MAX * WL_SPH_DIM_MAX] = {0};
    if (e->gv[0])
      for (int q = 0; q < dim * dim; q++) in.g[q][l] = gl[q] = e->gv[q][i];
    /* the particle's own eddy viscosity, once for all its pairs */
    in.nut[l] = e->gv[0] && k->nut_c > 0 ? wl_sph_eddy_nu(dim, k, gl) : WL_R(0.0);
  }
  struct wl_sph_acc f; /* fluid neighbours */
  for (int l = 0; l < lanes; l++) {
    for (int a = 0; a < WL_SPH_DIM_MAX; a++) f.a[a][l] = 0;
    f.cont[l] = f.ddt[l] = f.wsum[l] = f.visc[l] = 0;
  }
  if (fluid) {
    struct wl_sph_acc b = f; /* boundary neighbours */
    if (e->gv[0])
      for (int r = 0; r < nr; r++)
        wl_sph_gather_range(dim, laminar, 1, 1, lanes, cut, k, e, &in, bf[first[r]],
                            bf[last[r] + 1], k->av_ff, k->lam_ff, 0, &f, 1);
    else
      for (int r = 0; r < nr; r++)
        wl_sph_gather_range(dim, laminar, 1, 1, lanes, cut, k, e, &in, bf[first[r]],
                            bf[last[r] + 1], k->av_ff, k->lam_ff, 0, &f, 0);
    if (e->gv[0] && k->nut_c > 0) /* the eddy viscosity's wall pairs */
      for (int r = 0; r < nr; r++)
        wl_sph_gather_range(dim, laminar, 1, 0, lanes, cut, k, e, &in, bb[first[r]],
                            bb[last[r] + 1], k->av_fb, k->lam_fb, 0, &b, 1);
    else
      for (int r = 0; r < nr; r++)
        wl_sph_gather_range(dim, laminar, 1, 0, lanes, cut, k, e, &in, bb[first[r]],
                            bb[last[r] + 1], k->av_fb, k->lam_fb, 0, &b, 0);
    wl_sph_gather_mirrors(dim, laminar, lanes, cut, k, g, e, &in, 1, cell, span, &f, &b);
    for (int l = 0; l < m; l++)
      wl_sph_finish(dim, k, e, i0 + l, 1, in.rho[l], &f, &b, l);
  } else {
    for (int r = 0; r < nr; r++)
      wl_sph_gather_range(dim, laminar, 0, 0, lanes, cut, k, e, &in, bf[first[r]],
                          bf[last[r] + 1], k->av_fb, k->lam_fb, 0, &f, 0);
    wl_sph_gather_mirrors(dim, laminar, lanes, cut, k, g, e, &in, 0, cell, span, &f, &f);
    for (int l = 0; l < m; l++) wl_sph_finish(dim, k, e, i0 + l, 0, in.rho[l], &f, &f, l);
  }
}

/* Forces on the single particle i (the per-particle form): the same
 * results as wl_sph_gather_block, bit for bit. The reference loop of the
 * GPU's tests (tests/CMakeLists.txt, test_cuda_backend). */
WL_HD static WL_INLINE void wl_sph_gather(const int dim, const int laminar,
                                          const struct wl_sph_const *k,
                                          const struct wl_sph_grid *g,
                                          const struct wl_sph_eval *e, int n_bound, int i) {
  wl_sph_gather_block(dim, laminar, 1, 0, k, g, e, n_bound, i, 1, 0);
}

/* What the time step (backend.h wl_sph_step_dt) takes from particle i after
 * its force evaluation: its time-step input e->visc[i] in *visc and, for a
 * fluid particle (i >= n_bound), |a|^2 and |v|^2 in *ace2 and *vel2 (as
 * doubles: sums of the float components' squares, each product and sum
 * rounded once, WL_DMUL/WL_DADD); a boundary particle leaves them as they
 * are. Every backend takes the maxima of these. dim: compile-time
 * constant. */
WL_HD static WL_INLINE void wl_sph_eval_dt_input(const int dim, const struct wl_sph_eval *e,
                                                 int i, int n_bound, double *ace2, double *vel2,
                                                 double *visc) {
  *visc = (double)e->visc[i];
  if (i < n_bound) return;
  double a2 = 0, v2 = 0;
  for (int a = 0; a < dim; a++) {
    a2 = WL_DADD(a2, WL_DMUL((double)e->ace[a][i], (double)e->ace[a][i]));
    v2 = WL_DADD(v2, WL_DMUL((double)e->vel[a][i], (double)e->vel[a][i]));
  }
  *ace2 = a2;
  *vel2 = v2;
}

/* The wall load on fluid particle i (sorted index >= n_bound): the force
 * of the boundary particles of body `body` (body_of[j] == body) on it, as
 * its own force evaluation adds them (the fluid-boundary pair term of
 * wl_sph_pair_sum: wl_sph_pair_eval with the wall's p_i, j's volume of
 * wl_sph_pair_j_bound, av_fb and lam_fb, over its boundary rows and their
 * mirror images), taken in double. Out: *fx, the horizontal force of the
 * fluid particle on those boundary particles [N, or N/m in 2D]: minus the
 * particle's acceleration from them times its mass; *my, its moment about
 * the height z_ref [m] (N m, or N m/m), each pair's force acting at the
 * mean height of the two particles, no lever arm below z_ref (what pushes
 * on the foundation). Pairs beyond the support add nothing. The pressures
 * are e->press (the EOS of e->rho for every particle: the state as stored,
 * not the wall pass of sph/wall.h). dim, laminar: compile-time constants. */
WL_HD static WL_INLINE void wl_sph_gather_wall_load(const int dim, const int laminar,
                                                    const struct wl_sph_const *k,
                                                    const struct wl_sph_grid *g,
                                                    const struct wl_sph_eval *e,
                                                    const unsigned char *body_of, int body,
                                                    double z_ref, int i, double *fx,
                                                    double *my) {
  const int nc = g->n_cells, az = dim - 1;
  const int cell = (int)e->key[i] - nc;
  int rf[21], rl[21], rm[21]; /* rows: 9 ordinary (mirror 0), then up to 6 of each plane */
  int nr = wl_sph_cell_rows(dim, g, cell, 0, rf, rl);
  for (int r = 0; r < nr; r++) rm[r] = 0;
  if (dim == 3 && k->mirror) {
    int mf[2][6], ml[2][6], nm[2] = {0, 0};
    wl_sph_cell_rows_mirrors(g, k->mirror, cell, 0, mf, ml, nm);
    for (int side = 0; side < 2; side++)
      for (int r = 0; r < nm[side]; r++, nr++) {
        rf[nr] = mf[side][r];
        rl[nr] = ml[side][r];
        rm[nr] = side + 1;
      }
  }
  const double xi = e->pos[0][i], zi = e->pos[az][i], yi = dim == 3 ? e->pos[1][i] : 0.0;
  const wl_real vxi = e->vel[0][i], vzi = e->vel[az][i];
  const wl_real vyi = dim == 3 ? e->vel[1][i] : WL_R(0.0);
  const wl_real rho_i = e->rho[i], inv_rho_i = wl_sph_rcp(rho_i);
  const wl_real p_i = wl_sph_pair_p_wall(k, e->press[i]);
  double sx = 0.0, sm = 0.0;
  for (int r = 0; r < nr; r++) {
    const int mirror = rm[r];
    for (int j = e->begin[rf[r]]; j < e->begin[rl[r] + 1]; j++) {
      if (body_of[j] != body) continue;
      const double yj = dim != 3 ? 0.0
                        : mirror ? 2.0 * k->mirror_y[mirror - 1] - e->pos[1][j]
                                 : e->pos[1][j];
      const wl_real dx = (wl_real)(xi - e->pos[0][j]);
      const wl_real dy = dim == 3 ? (wl_real)(yi - yj) : WL_R(0.0);
      const wl_real dz = (wl_real)(zi - e->pos[az][j]);
      const wl_real r2 = dx * dx + dy * dy + dz * dz;
      if (r2 >= k->support2) continue;
      const wl_real uyj = dim == 3 ? (mirror ? -e->vel[1][j] : e->vel[1][j]) : WL_R(0.0);
      const wl_real ux = vxi - e->vel[0][j];
      const wl_real uy = dim == 3 ? vyi - uyj : WL_R(0.0);
      const wl_real uz = vzi - e->vel[az][j];
      const wl_real rv = dx * ux + dy * uy + dz * uz;
      wl_real inv_rho_j, vol_j;
      wl_sph_pair_j_bound(k, e->rho[j], &inv_rho_j, &vol_j);
      const struct wl_sph_pair o =
          wl_sph_pair_eval(laminar, 0, k, r2, rv, dz, rho_i, inv_rho_i, p_i, e->rho[j], inv_rho_j,
                           vol_j, e->press[j], k->av_fb, k->lam_fb);
      /* the pair's acceleration of i along x, in double as the sums of
       * the loads are; minus m_i times it is i's push on j */
      const double ax = WL_DADD(WL_DMUL((double)o.c_r, (double)dx),
                                WL_DMUL((double)o.c_v, (double)ux));
      const double fij = -WL_DMUL((double)k->mass, ax);
      const double arm = WL_DADD(WL_DMUL(0.5, WL_DADD(zi, e->pos[az][j])), -z_ref);
      sx = WL_DADD(sx, fij);
      sm = WL_DADD(sm, WL_DMUL(fij, wl_sph_maxd(0.0, arm)));
    }
  }
  *fx = sx;
  *my = sm;
}

#endif
