/* sph/cells.h: the cell grid of the neighbour search (Dominguez et al. 2011,
 * "Neighbour lists in smoothed particle hydrodynamics", Int. J. Numer. Meth.
 * Fluids 67:2026; DualSPHysics cell-linked lists).
 *
 * Cells are cubes of side >= 2h (the kernel support) covering the domain box,
 * numbered c = ix + nx (iy + ny iz) in 3D and c = ix + nx iz in 2D, so the
 * three cells ix-1..ix+1 of a row are consecutive numbers. Particles are
 * counting-sorted by key = group * n_cells + c, group 0 = boundary, 1 =
 * fluid; begin[key] is the first sorted index of a key and begin[key + 1]
 * its end, so a row of three cells of one group is ONE contiguous index range
 * [begin[g nc + c - 1], begin[g nc + c + 2]). A particle's neighbours are in
 * 3 rows (2D) or 9 rows (3D). */
#ifndef WALLLOAD_SPH_CELLS_H
#define WALLLOAD_SPH_CELLS_H

#include "wallload/sph/defs.h"

struct wl_sph_grid {
  double lo[WL_SPH_DIM_MAX]; /* lower corner of the grid (domain box) [m] */
  double cell;               /* cell side [m], >= 2h */
  double inv_cell;           /* 1/cell [1/m] */
  int n[WL_SPH_DIM_MAX];     /* cells per axis; unused axes 1 */
  int n_cells;               /* product of n */
};

/* Cell coordinate along axis a of position x [m], clamped into the grid
 * (a particle outside the grid is sorted into the nearest border cell; the
 * guard reports it as having left the domain). */
WL_HD static WL_INLINE int wl_sph_cell_coord(const struct wl_sph_grid *g, int a, double x) {
  const double s = (x - g->lo[a]) * g->inv_cell;
  if (!(s >= 0)) return 0; /* also catches NaN */
  const int c = s < (double)g->n[a] ? (int)s : g->n[a] - 1;
  return c;
}

/* Cell number of a particle at pos[.][i]. */
WL_HD static WL_INLINE int wl_sph_cell_of(const int dim, const struct wl_sph_grid *g,
                                       double *const *pos, int i) {
  int c = 0;
  for (int a = dim - 1; a >= 0; a--) c = c * g->n[a] + wl_sph_cell_coord(g, a, pos[a][i]);
  return c;
}

/* The rows of neighbour cells around cells c .. c + span of one row (span
 * 0: cell c alone): for each row, the first and last cell number (first <=
 * last, same row). Returns the number of rows (<= 3 in 2D, <= 9 in 3D). */
WL_HD static WL_INLINE int wl_sph_cell_rows(const int dim, const struct wl_sph_grid *g, int c,
                                            int span, int first[9], int last[9]) {
  const int ix = c % g->n[0];
  const int rest = c / g->n[0]; /* iy + ny iz (3D) or iz (2D) */
  const int x0 = wl_sph_maxi(ix - 1, 0) - ix, x1 = wl_sph_mini(ix + span + 1, g->n[0] - 1) - ix;
  int nr = 0;
  if (dim == 2) {
    for (int dz = -1; dz <= 1; dz++) {
      const int iz = rest + dz;
      if (iz < 0 || iz >= g->n[1]) continue;
      const int base = iz * g->n[0] + ix;
      first[nr] = base + x0;
      last[nr] = base + x1;
      nr++;
    }
  } else {
    const int iy = rest % g->n[1], iz = rest / g->n[1];
    for (int dz = -1; dz <= 1; dz++) {
      const int jz = iz + dz;
      if (jz < 0 || jz >= g->n[2]) continue;
      for (int dy = -1; dy <= 1; dy++) {
        const int jy = iy + dy;
        if (jy < 0 || jy >= g->n[1]) continue;
        const int base = (jz * g->n[1] + jy) * g->n[0] + ix;
        first[nr] = base + x0;
        last[nr] = base + x1;
        nr++;
      }
    }
  }
  return nr;
}

/* The rows a mirror plane adds (sph/gather.h's mirror passes), 3D, for
 * cells c .. c + span: side 0, the plane at the grid's low y face: for the
 * first cell layer (iy = 0) the rows iy = 0, iz - 1 .. iz + 1, where lie
 * the particles within 2h of the plane whose images can be neighbours;
 * none for iy >= 1 (a cell, >= 2h, from the plane). Side 1, the plane at
 * the domain box's high y face, which lies in the last layer (or at its
 * top): that layer may be thinner than a cell, so the last two layers
 * (iy >= n - 2) are near the plane and their rows are visited. Rows
 * farther than 2h add exact zeros. Returns the number of rows (<= 6). */
WL_HD static WL_INLINE int wl_sph_cell_rows_mirror(const struct wl_sph_grid *g, int c, int span,
                                                   int side, int first[6], int last[6]) {
  const int ix = c % g->n[0];
  const int rest = c / g->n[0];
  const int iy = rest % g->n[1], iz = rest / g->n[1];
  const int y_first = side ? wl_sph_maxi(g->n[1] - 2, 0) : 0, y_last = side ? g->n[1] - 1 : 0;
  if (iy < y_first || iy > y_last) return 0;
  const int x0 = wl_sph_maxi(ix - 1, 0) - ix, x1 = wl_sph_mini(ix + span + 1, g->n[0] - 1) - ix;
  int nr = 0;
  for (int dz = -1; dz <= 1; dz++) {
    const int jz = iz + dz;
    if (jz < 0 || jz >= g->n[2]) continue;
    for (int jy = y_first; jy <= y_last; jy++) {
      const int base = (jz * g->n[1] + jy) * g->n[0] + ix;
      first[nr] = base + x0;
      last[nr] = base + x1;
      nr++;
    }
  }
  return nr;
}

/* Both planes' mirror rows for cells c .. c + span (3D): side s's rows in
 * first[s], last[s] and their count in n[s]; 0 rows for a plane not in
 * mask (bit 0 the low plane, bit 1 the high one; sph/params.h's mirror). */
WL_HD static WL_INLINE void wl_sph_cell_rows_mirrors(const struct wl_sph_grid *g, int mask, int c,
                                                     int span, int first[2][6], int last[2][6],
                                                     int n[2]) {
  for (int side = 0; side < 2; side++)
    n[side] = (mask & (1 << side))
                  ? wl_sph_cell_rows_mirror(g, c, span, side, first[side], last[side])
                  : 0;
}

#endif
