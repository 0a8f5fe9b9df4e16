/* sph/probe.h: kernel interpolation at an arbitrary point from the fluid
 * particles (host now, device later), for gauges and probes.
 *
 *   S(x) = sum_j V_j W(x - x_j),  V_j = m_j / rho_j   (Shepard sum, ~1 inside)
 *   f(x) = sum_j V_j f_j W(x - x_j) / S(x)           (Shepard-normalised field)
 *
 * Free surface: along a vertical line the surface is where S(x) falls
 * below WL_SPH_SURFACE_SHEPARD = 0.5, in 2D and 3D. A settled half-space
 * lattice gives S = 0.5 at the height where the fluid's volume ends (to
 * 0.002 dp at h = 1.7 dp, computed for the square lattice), so a gauge
 * reads the depth the fluid's mass fills. DualSPHysics' gauges use 0.4 in
 * 2D (its coefmasslimit, REFERENCES.md section 6, an empirical match of 2D
 * to 3D runs): at h = 1.7 dp that reads a flat surface 0.22 dp high, which
 * made validate's solitary crests (H = 2-4 dp) read 6-40 % high. */
#ifndef WALLLOAD_SPH_PROBE_H
#define WALLLOAD_SPH_PROBE_H

#include <math.h>

#include "wallload/sph/cells.h"
#include "wallload/sph/kernel.h"

/* The Shepard sum at which a vertical line leaves the fluid (above). */
#define WL_SPH_SURFACE_SHEPARD 0.5

struct wl_sph_point_sums {
  double s;                 /* sum V_j W [-] */
  double v[WL_SPH_DIM_MAX]; /* sum V_j W v_j [m/s] */
  double p;                 /* sum V_j W p_j [Pa] */
  /* with dz_j the height of particle j above the point: sum V_j W dz_j
   * [m], sum V_j W dz_j^2 [m^2], sum V_j W p_j dz_j [Pa m] (press given),
   * for the pressure linear in height (wl_sph_point_pressure) */
  double s_z, s_zz, p_z;
};

/* Add the fluid particles of sorted range [j0, j1) to o, or their mirror
 * images in the low (mirror 1) or high (mirror 2) mirror plane, 3D. */
WL_HD static inline void wl_sph_point_add(const int dim, const struct wl_sph_const *k,
                                          double *const *pos, wl_real *const *vel,
                                          const wl_real *rho, const wl_real *press,
                                          const double *x, int j0, int j1, int mirror,
                                          struct wl_sph_point_sums *o) {
  for (int j = j0; j < j1; j++) {
    wl_real r2 = 0;
    for (int a = 0; a < dim; a++) {
      const double xj = a == 1 && mirror ? 2.0 * k->mirror_y[mirror - 1] - pos[a][j] : pos[a][j];
      const wl_real d = (wl_real)(x[a] - xj);
      r2 += d * d;
    }
    if (!(r2 < k->support2)) continue;
    const double vw = (double)(k->mass / rho[j] * wl_sph_kernel_w(k, r2));
    o->s += vw;
    for (int a = 0; a < dim; a++) o->v[a] += vw * (a == 1 && mirror ? -vel[a][j] : vel[a][j]);
    if (press) {
      const double dz = pos[dim - 1][j] - x[dim - 1];
      o->p += vw * press[j];
      o->s_z += vw * dz;
      o->s_zz += vw * dz * dz;
      o->p_z += vw * press[j] * dz;
    }
  }
}

/* Sums at point x [m] over the fluid particles, using the sorted cell
 * ranges begin (2 n_cells + 1; the fluid group starts at n_cells), and over
 * their mirror images beside mirror planes (k->mirror). press may be NULL
 * (then p is 0). The cell of x is clamped into the grid. */
WL_HD static inline struct wl_sph_point_sums
wl_sph_point_sum(const int dim, const struct wl_sph_const *k, const struct wl_sph_grid *g,
                 const int *begin, double *const *pos, wl_real *const *vel, const wl_real *rho,
                 const wl_real *press, const double *x) {
  struct wl_sph_point_sums o = {0, {0, 0, 0}, 0, 0, 0, 0};
  int c = 0;
  for (int a = dim - 1; a >= 0; a--) c = c * g->n[a] + wl_sph_cell_coord(g, a, x[a]);
  int first[9], last[9];
  const int nr = wl_sph_cell_rows(dim, g, c, 0, first, last);
  const int *const bf = begin + g->n_cells;
  for (int r = 0; r < nr; r++)
    wl_sph_point_add(dim, k, pos, vel, rho, press, x, bf[first[r]], bf[last[r] + 1], 0, &o);
  for (int side = 0; dim == 3 && side < 2; side++) {
    if (!(k->mirror & (1 << side))) continue;
    const int nm = wl_sph_cell_rows_mirror(g, c, 0, side, first, last);
    for (int r = 0; r < nm; r++)
      wl_sph_point_add(dim, k, pos, vel, rho, press, x, bf[first[r]], bf[last[r] + 1], side + 1,
                       &o);
  }
  return o;
}

/* The pressure at the point from sums o (press given): the value at the
 * point of the line p = a + b dz fitted to the particles by kernel-weighted
 * least squares in height, the first-order correction along the vertical
 * of Shepard's average sum V p W / sum V W. Within a kernel of the free
 * surface only the water below is summed, and Shepard's average of a
 * pressure that falls with height reads high there (a hydrostatic profile:
 * 2.4 times the pressure half a spacing under the surface, h = 1.7 dp); the
 * fit reproduces a pressure linear in height whatever cuts the kernel (the
 * wall beside the point, the surface above it, the bed below). Shepard's
 * average where the particles hardly spread in height (a film about one
 * particle thick: the scaled determinant below WL_SPH_PROBE_FIT_MIN). */
#define WL_SPH_PROBE_FIT_MIN 1e-3
WL_HD static inline double wl_sph_point_pressure(const struct wl_sph_point_sums *o, double h) {
  if (!(o->s > 0)) return 0.0;
  const double det = o->s * o->s_zz - o->s_z * o->s_z;
  if (!(det > WL_SPH_PROBE_FIT_MIN * o->s * o->s * h * h)) return o->p / o->s;
  return (o->s_zz * o->p - o->s_z * o->p_z) / det;
}

/* The Shepard sum that a point half a spacing off a vertical face reads
 * with still water standing over it, at height z_bed [m] above the foot of
 * the face (the bed) and across position y [m] (3D; 0 in 2D): the settled
 * lattice of spacing dp in front of the face (columns dp/2, 3 dp/2, ... from
 * it; rows from the bed, centres at dp/2, 3 dp/2, ...; across, centres at
 * dp/2, 3 dp/2, ... from y = 0). Unlike the open water's 1, it is cut by the
 * face (about 0.6-0.7 at h = 1.7 dp) and by the bed near the foot. A wall
 * probe or pressure sensor is wet where its Shepard sum reaches
 * WL_SPH_SURFACE_SHEPARD of this: the gauges' surface rule at the face. */
static inline double wl_sph_face_shepard_full(const struct wl_sph_const *k, int dim, double dp,
                                              double z_bed, double y) {
  const double reach = 2.0 * (double)k->h;
  const int n = (int)ceil(reach / dp) + 1;
  const double vol = dim == 3 ? dp * dp * dp : dp * dp;
  double sum = 0.0;
  const int j_lo = (int)floor((z_bed - reach) / dp) - 1;
  for (int i = 0; i <= n; i++) {
    const double dx = (double)i * dp;
    for (int j = j_lo > 0 ? j_lo : 0; j <= j_lo + 2 * n + 2; j++) {
      const double dz = z_bed - (j + 0.5) * dp;
      if (dim == 2) {
        sum += vol * (double)wl_sph_kernel_w(k, (wl_real)(dx * dx + dz * dz));
        continue;
      }
      const int l0 = (int)floor((y - reach) / dp) - 1;
      for (int l = l0; l <= l0 + 2 * n + 2; l++) {
        const double dy = y - (l + 0.5) * dp;
        sum += vol * (double)wl_sph_kernel_w(k, (wl_real)(dx * dx + dy * dy + dz * dz));
      }
    }
  }
  return sum;
}

#endif
