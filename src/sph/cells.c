/* cells.c: host side of the cell lists (sph/cells.h): the grid over a
 * domain box and the counting sort by (group, cell). Used by the CPU
 * backend and the probes; a device backend sorts on the device the same
 * way. */
#include <math.h>
#include <string.h>

#include "wallload/sph.h"

enum wl_status wl_sph_grid_make(const struct wl_sph_config *cfg, const struct wl_sph_const *k,
                                struct wl_sph_grid *g, struct wl_error *err) {
  const int dim = cfg->prm.dim;
  memset(g, 0, sizeof *g);
  g->cell = 2.0 * k->h_d;
  g->inv_cell = 1.0 / g->cell;
  double cells = 1;
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    g->n[a] = 1;
    if (a >= dim) continue;
    g->lo[a] = cfg->lo[a];
    const double len = cfg->hi[a] - cfg->lo[a];
    if (!(len > 0) || !isfinite(len))
      return wl_error_set(err, WL_EINPUT, "domain box axis %d is [%g, %g] m; need lo < hi", a,
                          cfg->lo[a], cfg->hi[a]);
    const double na = ceil(len * g->inv_cell);
    g->n[a] = na < 1 ? 1 : na > 1e9 ? 1000000000 : (int)na;
    cells *= g->n[a];
  }
  if (cells > WL_SPH_CELLS_MAX)
    return wl_error_set(err, WL_EINPUT, "the domain box needs %.3g cells of %g m (2h); at most %g: "
                        "shrink the box", cells, g->cell, (double)WL_SPH_CELLS_MAX);
  g->n_cells = (int)cells;
  /* the mirror passes of sph/gather.h visit the first and the last two
   * cell layers in y; a plane's images of the other plane's images are
   * left out: they are 2W from their particle (W the planes' distance), out
   * of reach (2h) when W > 2h, which two cell layers (W > one cell)
   * ensure */
  if (((k->mirror & 1) && k->mirror_y[0] != cfg->lo[1]) ||
      ((k->mirror & 2) && k->mirror_y[1] != cfg->hi[1]))
    return wl_error_set(err, WL_EINPUT, "mirror planes must be the domain box's y faces (y = %g "
                        "and %g m)", cfg->lo[1], cfg->hi[1]);
  if (k->mirror == 3 && g->n[1] < 2)
    return wl_error_set(err, WL_EINPUT, "mirror planes at y = %g and %g m: %g m apart; they must "
                        "be more than one cell (2h = %g m) apart", cfg->lo[1], cfg->hi[1],
                        cfg->hi[1] - cfg->lo[1], g->cell);
  return WL_OK;
}

void wl_sph_cells_sort(const struct wl_sph_grid *g, const unsigned int *key, int n, int *begin,
                       int *cursor, unsigned int *perm) {
  const int nk = 2 * g->n_cells;
  memset(begin, 0, sizeof(int) * (size_t)(nk + 1));
  for (int i = 0; i < n; i++) begin[key[i] + 1]++;
  for (int b = 0; b < nk; b++) begin[b + 1] += begin[b];
  memcpy(cursor, begin, sizeof(int) * (size_t)nk);
  for (int i = 0; i < n; i++) perm[cursor[key[i]]++] = (unsigned)i;
}

size_t wl_sph_memory_bytes(const struct wl_sph_config *cfg, int n) {
  struct wl_sph_const k;
  struct wl_sph_grid g;
  if (wl_sph_const_make(&cfg->prm, &k, NULL) != WL_OK || wl_sph_grid_make(cfg, &k, &g, NULL) != WL_OK)
    return 0;
  const int dim = cfg->prm.dim;
  return wl_particles_bytes(dim, n, 1) + wl_particles_bytes(dim, n, 0) +
         sizeof(unsigned int) * (size_t)n + 2 * sizeof(int) * (2 * (size_t)g.n_cells + 1);
}
