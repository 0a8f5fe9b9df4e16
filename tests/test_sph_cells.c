/* test_sph_cells.c: the cell-list neighbour search against brute force
 * (SWIFT's test27cells idea), in 2D and 3D, on random particles (boundary
 * and fluid, with clumps and empty regions):
 *  - the counting sort puts every particle in its cell, boundary first,
 *    and is a permutation;
 *  - for every particle, the set of neighbours within 2h reached through
 *    the cell rows equals the O(N^2) set;
 *  - the forces from the gather (per particle, and in blocks of lanes
 *    spanning two cells, as the CPU backend runs it) equal an O(N^2) sum of
 *    the same pair terms over all pairs (to float rounding: the brute force
 *    sums in another order), and the two gather shapes agree bit for bit. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/sph.h"
#include "wallload/sph/gather.h"

static double urand(unsigned long long *s) {
  *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*s >> 11) / 9007199254740992.0;
}

static int run(int dim) {
  const double dp = 0.02;
  const int n_bound = dim == 2 ? 300 : 600, n = dim == 2 ? 3000 : 6000;
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, dim, dp, 0.5);
  for (int a = 0; a < dim; a++) {
    cfg.lo[a] = -0.1;
    cfg.hi[a] = dim == 2 ? 0.9 : 0.35;
  }
  struct wl_sph_const k;
  struct wl_sph_grid g;
  if (wl_sph_const_make(&cfg.prm, &k, &err) || wl_sph_grid_make(&cfg, &k, &g, &err)) {
    printf("FAIL set-up: %s\n", err.msg);
    return 1;
  }
  struct wl_particles p = {0};
  if (wl_particles_alloc(&p, dim, n, 1, &err) != WL_OK) return 1;
  p.n = n;
  p.n_bound = n_bound;
  unsigned long long seed = 12345 + dim;
  for (int i = 0; i < n; i++) {
    /* half uniform, half in a clump; a few exactly on cell faces */
    const int clump = i % 2;
    for (int a = 0; a < dim; a++) {
      double x = cfg.lo[a] + (cfg.hi[a] - cfg.lo[a]) * urand(&seed);
      if (clump) x = 0.2 + 0.15 * urand(&seed);
      if (i % 97 == 0) x = cfg.lo[a] + g.cell * (int)(urand(&seed) * g.n[a]);
      p.pos[a][i] = x;
      p.vel[a][i] = (wl_real)(urand(&seed) - 0.5);
    }
    p.rho[i] = (wl_real)(1000 + 20 * (urand(&seed) - 0.3));
    p.id[i] = (unsigned)i;
    p.kind[i] = i < n_bound ? WL_KIND_FIXED : WL_KIND_FLUID;
  }
  /* keys, sort, permute (as the backend does) */
  for (int i = 0; i < n; i++)
    p.key[i] = (p.kind[i] == WL_KIND_FLUID ? (unsigned)g.n_cells : 0u) +
               (unsigned)wl_sph_cell_of(dim, &g, p.pos, i);
  int *begin = malloc(sizeof(int) * (size_t)(2 * g.n_cells + 1));
  int *cursor = malloc(sizeof(int) * (size_t)(2 * g.n_cells));
  wl_sph_cells_sort(&g, p.key, n, begin, cursor, p.perm);
  struct wl_particles s = {0};
  wl_particles_alloc(&s, dim, n, 1, &err);
  s.n = n;
  s.n_bound = n_bound;
  int is_perm = 1;
  char *seen = calloc((size_t)n, 1);
  for (int i = 0; i < n; i++) {
    const unsigned j = p.perm[i];
    if (j >= (unsigned)n || seen[j]) is_perm = 0;
    else seen[j] = 1;
    if (!is_perm) break;
    for (int a = 0; a < dim; a++) {
      s.pos[a][i] = p.pos[a][j];
      s.vel[a][i] = p.vel[a][j];
    }
    s.rho[i] = p.rho[j];
    s.kind[i] = p.kind[j];
    s.id[i] = p.id[j];
    s.key[i] = p.key[j];
  }
  CHECK_TRUE(is_perm, "counting sort gives a permutation");
  int order_ok = 1, bound_first = 1, begin_ok = 1;
  for (int i = 0; i < n; i++) {
    if (i > 0 && s.key[i] < s.key[i - 1]) order_ok = 0;
    if ((i < n_bound) != (s.kind[i] != WL_KIND_FLUID)) bound_first = 0;
    if (!(begin[s.key[i]] <= i && i < begin[s.key[i] + 1])) begin_ok = 0;
  }
  CHECK_TRUE(order_ok && begin_ok, "sorted by key; begin[key] .. begin[key+1] holds exactly that key");
  CHECK_TRUE(bound_first, "boundary particles first, then fluid");

  /* neighbour sets: cell rows vs brute force */
  const double s2 = 4 * k.h_d * k.h_d;
  int sets_equal = 1;
  long pairs = 0;
  char *mark = calloc((size_t)n, 1);
  for (int i = 0; i < n && sets_equal; i++) {
    const int fluid = s.kind[i] == WL_KIND_FLUID;
    const int cell = (int)s.key[i] - (fluid ? g.n_cells : 0);
    int first[9], last[9];
    const int nr = wl_sph_cell_rows(dim, &g, cell, 0, first, last);
    memset(mark, 0, (size_t)n);
    for (int grp = 0; grp < 2; grp++)
      for (int r = 0; r < nr; r++)
        for (int j = begin[grp * g.n_cells + first[r]]; j < begin[grp * g.n_cells + last[r] + 1]; j++)
          mark[j]++;
    for (int j = 0; j < n; j++) {
      double r2 = 0;
      for (int a = 0; a < dim; a++) r2 += (s.pos[a][i] - s.pos[a][j]) * (s.pos[a][i] - s.pos[a][j]);
      const int near = r2 < s2;
      pairs += near;
      if (mark[j] > 1 || (near && !mark[j])) sets_equal = 0;
    }
  }
  CHECK_TRUE(sets_equal, "every neighbour within 2h is visited exactly once (brute force O(N^2))");
  printf("  %dD: %d particles, %d cells, %ld pairs within 2h\n", dim, n, g.n_cells, pairs);

  /* forces: gather (per particle), gather blocks, brute force */
  struct wl_sph_eval e;
  memset(&e, 0, sizeof e);
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    e.pos[a] = a < dim ? s.pos[a] : NULL;
    e.vel[a] = a < dim ? s.vel[a] : NULL;
    e.ace[a] = a < dim ? s.ace[a] : NULL;
  }
  for (int i = 0; i < n; i++) s.press[i] = wl_sph_eos_p(&k, s.rho[i]);
  e.rho = s.rho;
  e.press = s.press;
  e.key = s.key;
  e.begin = begin;
  e.ar = s.ar;
  e.visc = s.visc;
  for (int i = 0; i < n; i++) wl_sph_gather(dim, 0, &k, &g, &e, n_bound, i);
  double *a1 = malloc(sizeof(double) * (size_t)n * 5);
  for (int i = 0; i < n; i++) {
    for (int a = 0; a < dim; a++) a1[5 * i + a] = s.ace[a][i];
    a1[5 * i + 3] = s.ar[i];
    a1[5 * i + 4] = s.visc[i];
  }
  /* blocks as the backend forms them: up to 8 particles in <= 2 cells of a row */
  for (int i0 = 0; i0 < n;) {
    const int key0 = (int)s.key[i0], cell0 = key0 % g.n_cells;
    const int key_max = (cell0 % g.n[0]) + 1 < g.n[0] && key0 + 1 != g.n_cells ? key0 + 1 : key0;
    int m = 1;
    while (m < WL_SPH_LANES && i0 + m < n && (int)s.key[i0 + m] <= key_max) m++;
    if (dim == 2)
      wl_sph_gather_block(2, 0, WL_SPH_LANES, 0, &k, &g, &e, n_bound, i0, m, (int)s.key[i0 + m - 1] - key0);
    else
      wl_sph_gather_block(3, 0, WL_SPH_LANES, 0, &k, &g, &e, n_bound, i0, m, (int)s.key[i0 + m - 1] - key0);
    i0 += m;
  }
  int identical = 1;
  for (int i = 0; i < n; i++) {
    for (int a = 0; a < dim; a++) identical &= a1[5 * i + a] == s.ace[a][i];
    identical &= a1[5 * i + 3] == s.ar[i] && a1[5 * i + 4] == s.visc[i];
  }
  CHECK_TRUE(identical, "per-particle gather and two-cell lane blocks give the same bits");
  /* the per-particle form with the cut-off skip (the GPU's one-thread loop,
   * sph/gather.h wl_sph_gather_range cut): the skipped pairs add exact
   * zeros, so the same bits again */
  for (int i = 0; i < n; i++) {
    if (dim == 2) wl_sph_gather_block(2, 0, 1, 1, &k, &g, &e, n_bound, i, 1, 0);
    else wl_sph_gather_block(3, 0, 1, 1, &k, &g, &e, n_bound, i, 1, 0);
  }
  identical = 1;
  for (int i = 0; i < n; i++) {
    for (int a = 0; a < dim; a++) identical &= a1[5 * i + a] == s.ace[a][i];
    identical &= a1[5 * i + 3] == s.ar[i] && a1[5 * i + 4] == s.visc[i];
  }
  CHECK_TRUE(identical, "per-particle gather with the cut-off skip gives the same bits");
  /* brute force with the same pair terms, all j in index order */
  double worst_a = 0, worst_r = 0, scale_a = 0, scale_r = 0;
  for (int i = 0; i < n; i++) {
    const int fi = s.kind[i] == WL_KIND_FLUID;
    double acc[3] = {0, 0, 0}, cont = 0, ddt = 0;
    for (int j = 0; j < n; j++) {
      const int fj = s.kind[j] == WL_KIND_FLUID;
      if (!fi && !fj) continue;
      wl_real d[3] = {0, 0, 0}, u[3] = {0, 0, 0}, r2 = 0, rv = 0;
      for (int a = 0; a < dim; a++) {
        d[a] = (wl_real)(s.pos[a][i] - s.pos[a][j]);
        u[a] = s.vel[a][i] - s.vel[a][j];
        r2 += d[a] * d[a];
        rv += d[a] * u[a];
      }
      if (!(r2 < k.support2)) continue;
      /* a fluid particle's pair with a wall particle: the wall's volume
       * and the fluid's pressure as the wall condition takes them
       * (sph/interact.h wl_sph_pair_j_bound, wl_sph_pair_p_wall) */
      wl_real ij, vj;
      const int ff = fi && fj, fb = fi && !fj;
      if (fb) wl_sph_pair_j_bound(&k, s.rho[j], &ij, &vj);
      else wl_sph_pair_j(&k, s.rho[j], &ij, &vj);
      const wl_real p_i = fb ? wl_sph_pair_p_wall(&k, s.press[i]) : s.press[i];
      const struct wl_sph_pair o =
          ff ? wl_sph_pair_eval(0, 1, &k, r2, rv, d[dim - 1], s.rho[i], 1 / s.rho[i], p_i,
                                s.rho[j], ij, vj, s.press[j], k.av_ff, 0)
             : wl_sph_pair_eval(0, 0, &k, r2, rv, d[dim - 1], s.rho[i], 1 / s.rho[i], p_i,
                                s.rho[j], ij, vj, s.press[j], k.av_fb, 0);
      for (int a = 0; a < dim; a++) acc[a] += o.c_r * d[a];
      cont += o.cont;
      if (fi) ddt += o.ddt; /* a boundary particle takes no diffusion */
    }
    const double ar = s.rho[i] * cont + ddt;
    for (int a = 0; a < dim; a++) {
      const double want = fi ? acc[a] + k.gravity[a] : 0;
      worst_a = fmax(worst_a, fabs(a1[5 * i + a] - want));
      scale_a = fmax(scale_a, fabs(want));
    }
    worst_r = fmax(worst_r, fabs(a1[5 * i + 3] - ar));
    scale_r = fmax(scale_r, fabs(ar));
  }
  CHECK_ABS(worst_a / scale_a, 0, 1e-5, "acceleration: cell lists vs O(N^2) sum (relative to max |a|)");
  CHECK_ABS(worst_r / scale_r, 0, 1e-5, "density rate: cell lists vs O(N^2) sum (relative to max)");
  free(a1);
  free(mark);
  free(seen);
  free(begin);
  free(cursor);
  wl_particles_clear(&p);
  wl_particles_clear(&s);
  return 0;
}

int main(void) {
  run(2);
  run(3);
  /* error paths of the grid */
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, 2, 0.01, 1);
  struct wl_sph_const k;
  struct wl_sph_grid g;
  struct wl_error err;
  wl_error_clear(&err);
  wl_sph_const_make(&cfg.prm, &k, &err);
  cfg.lo[0] = 1;
  cfg.hi[0] = 0;
  cfg.hi[1] = 1;
  CHECK_TRUE(wl_sph_grid_make(&cfg, &k, &g, &err) == WL_EINPUT && strstr(err.msg, "axis 0"),
             "inverted domain box rejected, names the axis");
  wl_error_clear(&err);
  cfg.lo[0] = 0;
  cfg.hi[0] = 1e6;
  cfg.hi[1] = 1e6;
  CHECK_TRUE(wl_sph_grid_make(&cfg, &k, &g, &err) == WL_EINPUT && strstr(err.msg, "cells"),
             "too many cells rejected");
  return TEST_RESULT();
}
