/* sph/isph.h: the per-particle terms of incompressible SPH (ISPH), a
 * projection method beside the weakly-compressible equations of
 * sph/interact.h. Gather form as sph/gather.h: each function walks the
 * neighbour rows of particle i (sph/cells.h) and writes only i's outputs.
 * Design and references: docs/isph.md. In short (r_ij = r_i - r_j,
 * grad_i W_ij = F r_ij, sph/kernel.h; V_j = m/rho0, every particle's volume,
 * the fluid being incompressible):
 *
 *  projection (Chorin 1968; Cummins & Rudman 1999, J. Comput. Phys.
 *  152:584; Shao & Lo 2003, Adv. Water Resour. 26:787; seed 003 eqs 6-10):
 *    u* = u^n + dt (g + nu lap u)                        predictor
 *    lap p^{n+1} = rho0/dt div u*                         PPE
 *    u^{n+1} = u* - dt/rho0 grad p^{n+1},  r^{n+1} = r^n + dt u^{n+1}
 *  divergence (seed 003 eq 16):  div u*_i = -sum_j V_j u*_ij . grad_i W_ij
 *  Laplacian (Morris et al. 1997; Cummins & Rudman 1999; seed 003 eq 19,
 *  constant density):  lap p_i = -sum_j c_ij (p_i - p_j),
 *    c_ij = -2 V_j F r^2/(r^2 + eta^2) >= 0
 *  gradient: first-order consistent, with the renormalisation matrix of
 *  Bonet & Lok (1999, CMAME 180:97), as in Xu, Stansby & Laurence (2009,
 *  J. Comput. Phys. 228:6703):
 *    grad p_i = M_i^-1 sum_j V_j (p_j - p_i) grad_i W_ij,
 *    M_i = -sum_j V_j F r_ij (x) r_ij   (= I in a full support)
 *  exact for a linear field, so a hydrostatic pressure balances gravity to
 *  rounding at every particle, at the free surface and beside the walls.
 *  viscosity: the laminar term of Lo & Shao (2002), as sph/interact.h.
 *  free surface: the divergence of position (Lee et al. 2008, J. Comput.
 *  Phys. 227:8417; Lind et al. 2012, J. Comput. Phys. 231:1499)
 *    div r_i = -sum_j V_j r_ij . grad_i W_ij   (= dim inside the fluid)
 *  below a threshold (1.5 in 2D, their value) marks a surface particle,
 *  whose pressure is a Dirichlet value.
 *  walls (the project's condition, sph/wall.h; Adami et al. 2012 eq. 27):
 *  a wall particle's pressure is an unknown of the PPE whose row is the
 *  Shepard extrapolation  p_w = sum_f W_wf (p_f + rho0 (g - a_w).r_wf) /
 *  sum_f W_wf, and its intermediate velocity is the wall's plus dt (g -
 *  a_w): the wall's Neumann condition dp/dn = rho0 (g - a_w).n is then
 *  carried by the extrapolated pressure alone (see docs/isph.md, "walls").
 *
 * Sums are in double: the PPE is solved to a relative residual of 1e-8 or
 * so, and its coefficients and right-hand side should not carry float
 * noise of 1e-7 into the pressure. The kernel is the shared Wendland C2. */
#ifndef WALLLOAD_SPH_ISPH_H
#define WALLLOAD_SPH_ISPH_H

#include "wallload/sph/cells.h"
#include "wallload/sph/gather.h"
#include "wallload/sph/kernel.h"

/* Most nonzeros of one PPE row (the particle and its neighbours within 2h):
 * about 25 in 2D at h = sqrt(2) dp, 100 in 3D at h = sqrt(3) dp; a row
 * beyond this is a compressed, failing run (the backend reports it). */
#define WL_ISPH_ROW_MAX_2D 64
#define WL_ISPH_ROW_MAX_3D 256

/* The arrays the ISPH passes read (inputs) besides the cell lists. */
struct wl_isph_view {
  const double *pos[WL_SPH_DIM_MAX];
  const wl_real *vel[WL_SPH_DIM_MAX];  /* u^n (fluid), wall velocity (boundary) */
  const double *ustar[WL_SPH_DIM_MAX]; /* u* of every particle (after the predictor) */
  const unsigned int *key;
  const int *begin;
  int n_bound;
  /* wall particles the fluid does not see this step (their extrapolated
   * pressure was <= 0 at its start: wall above the free surface, air to
   * the fluid; docs/isph.md "walls"); NULL: all seen */
  const unsigned char *dry;
  /* outward unit normals of the wall particles (3 per particle, x y z;
   * wl_isph_wall_normal); NULL: no impact term */
  const double *wall_n;
};

/* Whether fluid particle i's sums skip neighbour j (a dry wall particle). */
WL_HD static inline int wl_isph_skip(const struct wl_isph_view *v, int j) {
  return v->dry && j < v->n_bound && v->dry[j];
}

/* The neighbour ranges of particle i (its key, fluid or boundary group):
 * rows 0..nr-1 of the fluid group in [f0[r], f1[r]), then of the boundary
 * group in [b0[r], b1[r]). Returns nr. */
WL_HD static inline int wl_isph_ranges(const int dim, const struct wl_sph_grid *g,
                                       const struct wl_isph_view *v, int i, int f0[9], int f1[9],
                                       int b0[9], int b1[9]) {
  const int nc = g->n_cells;
  const int cell = (int)v->key[i] - (i >= v->n_bound ? nc : 0);
  int first[9], last[9];
  const int nr = wl_sph_cell_rows(dim, g, cell, 0, first, last);
  for (int r = 0; r < nr; r++) {
    f0[r] = v->begin[nc + first[r]];
    f1[r] = v->begin[nc + last[r] + 1];
    b0[r] = v->begin[first[r]];
    b1[r] = v->begin[last[r] + 1];
  }
  return nr;
}

/* r_ij [m] in (x, y, z) slots (2D: y = 0) and r^2, in double. */
WL_HD static inline double wl_isph_rij(const int dim, const struct wl_isph_view *v, int i, int j,
                                       double r[3]) {
  r[0] = v->pos[0][i] - v->pos[0][j];
  r[1] = dim == 3 ? v->pos[1][i] - v->pos[1][j] : 0.0;
  r[2] = v->pos[dim - 1][i] - v->pos[dim - 1][j];
  return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
}

/* F(r) of sph/kernel.h in double, from r^2 [m^2]: grad_i W_ij = F r_ij. */
WL_HD static inline double wl_isph_f(const struct wl_sph_const *k, double r2) {
  return (double)wl_sph_kernel_f(k, (wl_real)r2);
}

/* What the geometry pass gives fluid particle i. */
struct wl_isph_geom {
  double div_r;     /* div r [-]: dim inside the fluid */
  double n[3];      /* outward unit normal -grad C/|grad C| (0 if grad C = 0), (x, y, z) */
  double gradc[3];  /* grad C = sum_j V_j grad_i W_ij [1/m] (x, y, z): particle shifting */
  double minv[6];   /* M^-1 (xx, yy, zz, xy, xz, yz), or the identity where M is singular */
  double visc[3];   /* nu lap u [m/s^2] (Lo & Shao), (x, y, z) */
  double wsum;      /* sum_j V_j W_ij over i itself and its neighbours [-]: the summation
                       density over rho0 (a full lattice at dp gives wl_isph_lattice_sum) */
};

/* sum_j V W(r_j) over a full lattice of spacing dp around a particle (j
 * itself included): what wl_isph_geom.wsum reads for fluid at rest density.
 * Not 1: the discrete sum of the kernel on a lattice differs from its
 * integral (about 1e-3 for Wendland C2 at h = sqrt(dim) dp). */
static inline double wl_isph_lattice_sum(const int dim, const struct wl_sph_const *k) {
  const double dp = k->dp, vol = (double)k->mass / (double)k->rho0;
  const int m = (int)ceil(sqrt((double)k->support2) / dp) + 1;
  double s = 0;
  for (int a = -m; a <= m; a++)
    for (int b = -m; b <= m; b++)
      for (int c = (dim == 3 ? -m : 0); c <= (dim == 3 ? m : 0); c++) {
        const double r2 = dp * dp * (double)(a * a + b * b + c * c);
        if (r2 < (double)k->support2) s += vol * (double)wl_sph_kernel_w(k, (wl_real)r2);
      }
  return s;
}

/* The smallest det M (relative to a full support's 1) for which the
 * gradient is renormalised: below it (a particle with a handful of
 * neighbours, a droplet) M^-1 would amplify noise, and the plain sum is
 * used. */
#define WL_ISPH_DET_MIN 0.1

/* Geometry of fluid particle i at the step start: div r, the surface
 * normal, M^-1 and the viscous acceleration from u^n (vel; a wall
 * particle's is its wall velocity). nu4 = 4 nu [m^2/s]. dim: compile-time
 * constant. */
WL_HD static inline void wl_isph_geometry(const int dim, const struct wl_sph_const *k,
                                          const struct wl_sph_grid *g,
                                          const struct wl_isph_view *v, double nu4, int i,
                                          struct wl_isph_geom *o) {
  int f0[9], f1[9], b0[9], b1[9];
  const int nr = wl_isph_ranges(dim, g, v, i, f0, f1, b0, b1);
  const double vol = (double)k->mass / (double)k->rho0, h2e = (double)k->eta2;
  const double sup2 = (double)k->support2;
  double divr = 0, gc[3] = {0, 0, 0}, M[6] = {0, 0, 0, 0, 0, 0}, vs[3] = {0, 0, 0};
  double ws = vol * (double)wl_sph_kernel_w(k, (wl_real)0);
  const double ui[3] = {(double)v->vel[0][i], dim == 3 ? (double)v->vel[1][i] : 0.0,
                        (double)v->vel[dim - 1][i]};
  for (int grp = 0; grp < 2; grp++)
    for (int r = 0; r < nr; r++) {
      const int j0 = grp ? b0[r] : f0[r], j1 = grp ? b1[r] : f1[r];
      for (int j = j0; j < j1; j++) {
        double x[3];
        const double r2 = wl_isph_rij(dim, v, i, j, x);
        if (r2 >= sup2 || j == i || wl_isph_skip(v, j)) continue;
        const double F = wl_isph_f(k, r2), vf = vol * F;
        ws += vol * (double)wl_sph_kernel_w(k, (wl_real)r2);
        divr -= vf * r2;
        for (int a = 0; a < 3; a++) gc[a] += vf * x[a];
        M[0] -= vf * x[0] * x[0];
        M[1] -= vf * x[1] * x[1];
        M[2] -= vf * x[2] * x[2];
        M[3] -= vf * x[0] * x[1];
        M[4] -= vf * x[0] * x[2];
        M[5] -= vf * x[1] * x[2];
        /* Lo & Shao (2002): nu lap u_i = sum_j m_j 4 nu r.gradW / ((rho_i + rho_j)(r^2 + eta^2)) u_ij */
        const double uj[3] = {(double)v->vel[0][j], dim == 3 ? (double)v->vel[1][j] : 0.0,
                              (double)v->vel[dim - 1][j]};
        const double cv = vol * nu4 * F * r2 / (2.0 * (r2 + h2e));
        for (int a = 0; a < 3; a++) vs[a] += cv * (ui[a] - uj[a]);
      }
    }
  o->div_r = divr;
  o->wsum = ws;
  const double gn = sqrt(gc[0] * gc[0] + gc[1] * gc[1] + gc[2] * gc[2]);
  for (int a = 0; a < 3; a++) {
    o->n[a] = gn > 0 ? -gc[a] / gn : 0.0;
    o->gradc[a] = gc[a];
    o->visc[a] = vs[a];
  }
  /* M^-1: 2D uses xx, zz, xz (y row and column the identity) */
  for (int a = 0; a < 6; a++) o->minv[a] = a < 3 ? 1.0 : 0.0;
  if (dim == 2) {
    const double det = M[0] * M[2] - M[4] * M[4];
    if (det > WL_ISPH_DET_MIN) {
      o->minv[0] = M[2] / det;
      o->minv[2] = M[0] / det;
      o->minv[4] = -M[4] / det;
    }
  } else {
    const double a = M[0], b = M[1], c = M[2], d = M[3], e = M[4], f = M[5];
    const double c00 = b * c - f * f, c01 = e * f - d * c, c02 = d * f - b * e;
    const double det = a * c00 + d * c01 + e * c02;
    if (det > WL_ISPH_DET_MIN) {
      o->minv[0] = c00 / det;
      o->minv[1] = (a * c - e * e) / det;
      o->minv[2] = (a * b - d * d) / det;
      o->minv[3] = c01 / det;
      o->minv[4] = c02 / det;
      o->minv[5] = (d * e - a * f) / det;
    }
  }
}

/* div u*_i [1/s] of fluid particle i over fluid and wall neighbours. */
WL_HD static inline double wl_isph_div_ustar(const int dim, const struct wl_sph_const *k,
                                             const struct wl_sph_grid *g,
                                             const struct wl_isph_view *v, int i) {
  int f0[9], f1[9], b0[9], b1[9];
  const int nr = wl_isph_ranges(dim, g, v, i, f0, f1, b0, b1);
  const double vol = (double)k->mass / (double)k->rho0, sup2 = (double)k->support2;
  const int az = dim - 1;
  double div = 0;
  for (int grp = 0; grp < 2; grp++)
    for (int r = 0; r < nr; r++) {
      const int j0 = grp ? b0[r] : f0[r], j1 = grp ? b1[r] : f1[r];
      for (int j = j0; j < j1; j++) {
        double x[3];
        const double r2 = wl_isph_rij(dim, v, i, j, x);
        if (r2 >= sup2 || wl_isph_skip(v, j)) continue;
        double ur = (v->ustar[0][i] - v->ustar[0][j]) * x[0] +
                    (v->ustar[az][i] - v->ustar[az][j]) * x[2];
        if (dim == 3) ur += (v->ustar[1][i] - v->ustar[1][j]) * x[1];
        div -= vol * wl_isph_f(k, r2) * ur;
      }
    }
  return div;
}

/* The outward unit normal of wall particle w (x, y, z slots), from the
 * other boundary particles around it: -grad C_b / |grad C_b|, C_b their
 * kernel sum (at the first layer, out of the wall towards the fluid; at a
 * corner, along its bisector). Zeros when w has no boundary neighbours. */
WL_HD static inline void wl_isph_wall_normal(const int dim, const struct wl_sph_const *k,
                                             const struct wl_sph_grid *g,
                                             const struct wl_isph_view *v, int w, double n[3]) {
  int f0[9], f1[9], b0[9], b1[9];
  const int nr = wl_isph_ranges(dim, g, v, w, f0, f1, b0, b1);
  const double sup2 = (double)k->support2;
  double gc[3] = {0, 0, 0};
  for (int r = 0; r < nr; r++)
    for (int j = b0[r]; j < b1[r]; j++) {
      double x[3];
      const double r2 = wl_isph_rij(dim, v, w, j, x);
      if (r2 >= sup2 || j == w) continue;
      const double F = wl_isph_f(k, r2);
      for (int a = 0; a < 3; a++) gc[a] += F * x[a];
    }
  const double gn = sqrt(gc[0] * gc[0] + gc[1] * gc[1] + gc[2] * gc[2]);
  for (int a = 0; a < 3; a++) n[a] = gn > 0 ? -gc[a] / gn : 0.0;
}

/* The impact term of wall particle w's row for fluid neighbour f (x =
 * r_w - r_f, nw the wall's outward normal): with d = -x.nw > 0 the fluid
 * particle's height over the wall particle and u_n = (u*_w - u*_f).nw its
 * intermediate speed into the wall, of which u_x = u_n - max(0, d - dp)/dt
 * would take it nearer than dp in this step: rho0 u_x d/dt (u_x > 0), the
 * pressure difference over d that takes u_x away (it never pushes a
 * particle that does not approach). This is the wall's Neumann condition
 * dp/dn = rho0 (g - a_w).n + rho0/dt (u* - u*_w).n for the fluid that
 * runs at it: the extrapolation carries the first part, this the second.
 * For every fluid neighbour: a surface particle's pressure is a Dirichlet
 * value the PPE cannot raise, and an interior particle's raised pressure
 * is extrapolated onto the wall too, so neither is stopped otherwise.
 * Sliding along the wall adds nothing. docs/isph.md, "walls". */
WL_HD static inline double wl_isph_wall_impact(const int dim, const struct wl_isph_view *v,
                                               const double *nw, double rho0, double dp, double dt, int w,
                                               int f, const double x[3]) {
  const int az = dim - 1;
  double un = (v->ustar[0][w] - v->ustar[0][f]) * nw[0] + (v->ustar[az][w] - v->ustar[az][f]) * nw[2];
  if (dim == 3) un += (v->ustar[1][w] - v->ustar[1][f]) * nw[1];
  const double d = -(x[0] * nw[0] + x[1] * nw[1] + x[2] * nw[2]);
  /* only the speed that would take f nearer than dp (a fluid particle's
   * distance from the first wall layer at rest) within this step */
  const double gap = d > dp ? (d - dp) / dt : 0.0, ux = un - gap;
  return ux > 0 && d > 0 && dt > 0 ? rho0 / dt * ux * d : 0.0;
}

/* The PPE row of particle i, scaled to a unit diagonal: the column
 * indices col[0..m) and values val[0..m) (col[0] = i, val[0] = 1), its
 * right-hand side *rhs; returns m, or -1 when the row would exceed
 * row_max entries. Unknowns are all particles; a fixed particle (surface,
 * or a wall particle with no interior fluid around it) has the row p_i =
 * p_fix[i] and its value moves to the right-hand side of the rows that
 * see it.
 *  - fixed[i] != 0: p_i = p_fix[i].
 *  - fluid i: sum_j c_ij (p_i - p_j - r_ij.grad p_i) = -rho0/dt div_u: the
 *    Morris Laplacian made exact for a linear field where the support is
 *    cut (free surface, dry wall), as Schwaiger (2008, IJNME 75:647) and
 *    Fatehi & Manzari (2011, Comput. Math. Appl. 61:482), with grad p_i
 *    lagged (gp_prev: last step's pressure at this step's positions; a
 *    deferred correction, exact at equilibrium): without it a hydrostatic
 *    field does not solve the rows beside the surface and the still tank
 *    goes unstable from its corners (docs/isph.md).
 *  - wall i: sum_f W_if (p_i - p_f) = sum_f W_if rho0 ga.r_if (sph/wall.h,
 *    Adami eq. 27), fluid neighbours f only; ga = g - a_w (x, y, z slots). */
WL_HD static inline int wl_isph_ppe_row(const int dim, const struct wl_sph_const *k,
                                        const struct wl_sph_grid *g,
                                        const struct wl_isph_view *v,
                                        const unsigned char *fixed, const double *p_fix,
                                        double div_u, double dt, const double *ga,
                                        const double *gp_prev, int i, int row_max, int *col,
                                        double *val, double *rhs) {
  col[0] = i;
  val[0] = 1.0;
  if (fixed[i]) {
    *rhs = p_fix[i];
    return 1;
  }
  int f0[9], f1[9], b0[9], b1[9];
  const int nr = wl_isph_ranges(dim, g, v, i, f0, f1, b0, b1);
  const double vol = (double)k->mass / (double)k->rho0, h2e = (double)k->eta2;
  const double sup2 = (double)k->support2, rho0 = (double)k->rho0;
  const int wall = i < v->n_bound;
  double diag = 0, b = wall ? 0.0 : -rho0 / dt * div_u;
  int m = 1;
  for (int grp = 0; grp < (wall ? 1 : 2); grp++)
    for (int r = 0; r < nr; r++) {
      const int j0 = grp ? b0[r] : f0[r], j1 = grp ? b1[r] : f1[r];
      for (int j = j0; j < j1; j++) {
        double x[3];
        const double r2 = wl_isph_rij(dim, v, i, j, x);
        if (r2 >= sup2 || j == i || (!wall && wl_isph_skip(v, j))) continue;
        double c;
        if (wall) {
          c = (double)wl_sph_kernel_w(k, (wl_real)r2);
          b += c * rho0 * (ga[0] * x[0] + ga[1] * x[1] + ga[2] * x[2]);
          if (v->wall_n) b += c * wl_isph_wall_impact(dim, v, &v->wall_n[3 * (size_t)i], rho0, (double)k->dp, dt, i, j, x);
        } else {
          c = -2.0 * vol * wl_isph_f(k, r2) * r2 / (r2 + h2e);
          /* the consistent Laplacian's first-order term with the lagged
           * gradient: + c r_ij.grad p_i (see the comment of this function) */
          b += c * (x[0] * gp_prev[0] + x[1] * gp_prev[1] + x[2] * gp_prev[2]);
        }
        if (!(c > 0)) continue;
        diag += c;
        if (fixed[j]) {
          b += c * p_fix[j];
        } else {
          if (m >= row_max) return -1;
          col[m] = j;
          val[m] = -c;
          m++;
        }
      }
    }
  if (!(diag > 0)) { /* nothing around it: pressure 0 */
    *rhs = 0.0;
    return 1;
  }
  const double s = 1.0 / diag;
  for (int q = 1; q < m; q++) val[q] *= s;
  *rhs = b * s;
  return m;
}

/* The wall condition's value for wall particle i from the pressures p of
 * its fluid neighbours (sph/wall.h, Adami eq. 27, without the clamp):
 * sum_f W_if (p_f + rho0 ga.r_if + impact) / sum_f W_if (wl_isph_wall_impact),
 * 0 with no fluid around it.
 * The backend's active set (docs/isph.md, "walls") reads it to release a
 * wall particle held at p = 0 once the fluid would push on it. */
WL_HD static inline double wl_isph_wall_value(const int dim, const struct wl_sph_const *k,
                                              const struct wl_sph_grid *g,
                                              const struct wl_isph_view *v, const double *p,
                                              double dt,
                                              const double *ga, int i) {
  int f0[9], f1[9], b0[9], b1[9];
  const int nr = wl_isph_ranges(dim, g, v, i, f0, f1, b0, b1);
  const double sup2 = (double)k->support2, rho0 = (double)k->rho0;
  double sw = 0, spw = 0;
  for (int r = 0; r < nr; r++)
    for (int j = f0[r]; j < f1[r]; j++) {
      double x[3];
      const double r2 = wl_isph_rij(dim, v, i, j, x);
      if (r2 >= sup2) continue;
      const double w = (double)wl_sph_kernel_w(k, (wl_real)r2);
      sw += w;
      spw += w * (p[j] + rho0 * (ga[0] * x[0] + ga[1] * x[1] + ga[2] * x[2]) +
                  (v->wall_n ? wl_isph_wall_impact(dim, v, &v->wall_n[3 * (size_t)i], rho0, (double)k->dp, dt, i, j, x) : 0.0));
    }
  return sw > 0 ? spw / sw : 0.0;
}

/* Whether fluid wets wall particle i this step although its pressure is
 * not positive (docs/isph.md, "walls"): a fluid neighbour within the
 * support that approaches it, (u_f - u_w).(r_w - r_f)/|r_w - r_f| > u_min
 * [m/s]. A jet running at a dry wall must see it before its extrapolated
 * pressure can turn positive. */
WL_HD static inline int wl_isph_wall_wetted(const int dim, const struct wl_sph_const *k,
                                            const struct wl_sph_grid *g,
                                            const struct wl_isph_view *v, double u_min, int i) {
  int f0[9], f1[9], b0[9], b1[9];
  const int nr = wl_isph_ranges(dim, g, v, i, f0, f1, b0, b1);
  const double sup2 = (double)k->support2;
  const int az = dim - 1;
  for (int r = 0; r < nr; r++)
    for (int j = f0[r]; j < f1[r]; j++) {
      double x[3]; /* r_w - r_f */
      const double r2 = wl_isph_rij(dim, v, i, j, x);
      if (r2 >= sup2 || !(r2 > 0)) continue;
      double ur = ((double)v->vel[0][j] - (double)v->vel[0][i]) * x[0] +
                  ((double)v->vel[az][j] - (double)v->vel[az][i]) * x[2];
      if (dim == 3) ur += ((double)v->vel[1][j] - (double)v->vel[1][i]) * x[1];
      if (ur > u_min * sqrt(r2)) return 1;
    }
  return 0;
}

/* The wall load on fluid particle i (backend.h wall_load; as sph/gather.h
 * wl_sph_gather_wall_load for WCSPH): the horizontal pressure force of i on
 * the boundary particles w of body `body` (body_of[w] == body) within its
 * support, in the symmetric pair form V_i V_w (p_i + p_w) F r_iw. The
 * momentum equation's renormalised difference form (wl_isph_grad_p) is not
 * antisymmetric, so its fluid-fluid pairs do not cancel and its
 * fluid-wall pairs are not the force on the wall (a uniform pressure gives
 * them none); in the symmetric form the fluid-fluid pairs cancel, and the
 * fluid-wall pairs are the wall's share of the pressure force (a
 * hydrostatic tank: rho0 g h^2/2 on an end wall, test_isph). Viscous
 * stresses are left out (laminar nu, negligible at the wall's scale). *fx
 * [N/m in 2D, N in 3D]; *my its moment about z_ref [m], each pair's force
 * at the mean height of the two particles, no lever arm below z_ref.
 * p: every particle's pressure [Pa]. */
WL_HD static inline void wl_isph_wall_load(const int dim, const struct wl_sph_const *k,
                                           const struct wl_sph_grid *g,
                                           const struct wl_isph_view *v, const double *p,
                                           const unsigned char *body_of, int body, double z_ref,
                                           int i, double *fx, double *my) {
  int f0[9], f1[9], b0[9], b1[9];
  const int nr = wl_isph_ranges(dim, g, v, i, f0, f1, b0, b1);
  const double vol = (double)k->mass / (double)k->rho0, sup2 = (double)k->support2;
  const int az = dim - 1;
  double sx = 0, sm = 0;
  for (int r = 0; r < nr; r++)
    for (int j = b0[r]; j < b1[r]; j++) {
      if (body_of[j] != body) continue;
      double x[3];
      const double r2 = wl_isph_rij(dim, v, i, j, x);
      if (r2 >= sup2) continue;
      const double f = vol * vol * (p[i] + p[j]) * wl_isph_f(k, r2) * x[0];
      const double arm = 0.5 * (v->pos[az][i] + v->pos[az][j]) - z_ref;
      sx += f;
      sm += f * (arm > 0 ? arm : 0.0);
    }
  *fx = sx;
  *my = sm;
}

/* grad p_i [Pa/m] of fluid particle i in (x, y, z) slots: M^-1 sum_j V_j
 * (p_j - p_i) grad_i W_ij over fluid and wall neighbours. */
WL_HD static inline void wl_isph_grad_p(const int dim, const struct wl_sph_const *k,
                                        const struct wl_sph_grid *g,
                                        const struct wl_isph_view *v, const double *p,
                                        const double *minv, int i, double gp[3]) {
  int f0[9], f1[9], b0[9], b1[9];
  const int nr = wl_isph_ranges(dim, g, v, i, f0, f1, b0, b1);
  const double vol = (double)k->mass / (double)k->rho0, sup2 = (double)k->support2;
  double s[3] = {0, 0, 0};
  for (int grp = 0; grp < 2; grp++)
    for (int r = 0; r < nr; r++) {
      const int j0 = grp ? b0[r] : f0[r], j1 = grp ? b1[r] : f1[r];
      for (int j = j0; j < j1; j++) {
        double x[3];
        const double r2 = wl_isph_rij(dim, v, i, j, x);
        if (r2 >= sup2 || j == i || wl_isph_skip(v, j)) continue;
        const double c = vol * wl_isph_f(k, r2) * (p[j] - p[i]);
        for (int a = 0; a < 3; a++) s[a] += c * x[a];
      }
    }
  /* minv: xx, yy, zz, xy, xz, yz */
  gp[0] = minv[0] * s[0] + minv[3] * s[1] + minv[4] * s[2];
  gp[1] = minv[3] * s[0] + minv[1] * s[1] + minv[5] * s[2];
  gp[2] = minv[4] * s[0] + minv[5] * s[1] + minv[2] * s[2];
}

#endif
