/* probe.c: kernel interpolation at points on the host (sph.h probes): a
 * cell index over a particle snapshot (counting sort of indices, the data
 * stay where they are) and the gauges built on sph/probe.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/sph.h"
#include "wallload/sph/probe.h"

struct wl_sph_probe {
  struct wl_sph_const k;
  struct wl_sph_grid grid;
  int *begin;        /* 2 n_cells + 1 */
  int *cursor;       /* n_cells: counting-sort scratch */
  int capacity;      /* particles the arrays below hold */
  int *order;        /* sorted position -> particle index */
  double *pos[WL_SPH_DIM_MAX]; /* gathered copies in cell order */
  wl_real *vel[WL_SPH_DIM_MAX];
  wl_real *rho, *press;
  int dim;
};

static void arrays_free(struct wl_sph_probe *pr) {
  free(pr->order);
  pr->order = NULL;
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    free(pr->pos[a]);
    free(pr->vel[a]);
    pr->pos[a] = NULL;
    pr->vel[a] = NULL;
  }
  free(pr->rho);
  free(pr->press);
  pr->rho = pr->press = NULL;
  pr->capacity = 0;
}

void wl_sph_probe_free(struct wl_sph_probe *pr) {
  if (!pr) return;
  arrays_free(pr);
  free(pr->begin);
  free(pr->cursor);
  free(pr);
}

enum wl_status wl_sph_probe_alloc(struct wl_sph_probe **out, const struct wl_sph_config *cfg,
                                  struct wl_error *err) {
  *out = NULL;
  struct wl_sph_probe *pr = calloc(1, sizeof *pr);
  if (!pr) return wl_error_set(err, WL_ENOMEM, "probe: out of memory");
  enum wl_status st = wl_sph_const_make(&cfg->prm, &pr->k, err);
  if (st != WL_OK) {
    wl_sph_probe_free(pr);
    return st;
  }
  pr->dim = cfg->prm.dim;
  struct wl_sph_grid *g = &pr->grid;
  st = wl_sph_grid_make(cfg, &pr->k, g, err);
  if (st != WL_OK) {
    wl_sph_probe_free(pr);
    return st;
  }
  pr->begin = calloc((size_t)(2 * g->n_cells + 1), sizeof(int));
  pr->cursor = calloc((size_t)g->n_cells, sizeof(int));
  if (!pr->begin || !pr->cursor) {
    const int nc = g->n_cells;
    wl_sph_probe_free(pr);
    return wl_error_set(err, WL_ENOMEM, "probe: cannot allocate the cell index (%d cells)", nc);
  }
  *out = pr;
  return WL_OK;
}

enum wl_status wl_sph_probe_index(struct wl_sph_probe *pr, const struct wl_particles *p,
                                  struct wl_error *err) {
  const int n = p->n, dim = pr->dim, nc = pr->grid.n_cells;
  if (p->dim != dim)
    return wl_error_set(err, WL_EINPUT, "probe: particles are %dD, probe %dD", p->dim, dim);
  if (n > pr->capacity) {
    arrays_free(pr);
    const size_t m = (size_t)n;
    int ok = (pr->order = malloc(m * sizeof(int))) != NULL;
    for (int a = 0; a < dim; a++) {
      ok = ok && (pr->pos[a] = malloc(m * sizeof(double))) != NULL;
      ok = ok && (pr->vel[a] = malloc(m * sizeof(wl_real))) != NULL;
    }
    ok = ok && (pr->rho = malloc(m * sizeof(wl_real))) != NULL;
    ok = ok && (pr->press = malloc(m * sizeof(wl_real))) != NULL;
    if (!ok) {
      arrays_free(pr);
      return wl_error_set(err, WL_ENOMEM, "probe: cannot allocate the index of %d particles", n);
    }
    pr->capacity = n;
  }
  /* counting sort of the particle indices; only the fluid group is filled,
   * the boundary group stays empty (probes interpolate the fluid) */
  int *begin = pr->begin;
  memset(begin, 0, sizeof(int) * (size_t)(2 * nc + 1));
  for (int i = 0; i < n; i++)
    if (p->kind[i] == WL_KIND_FLUID) begin[nc + wl_sph_cell_of(dim, &pr->grid, p->pos, i) + 1]++;
  for (int b = 0; b < 2 * nc; b++) begin[b + 1] += begin[b];
  int *cursor = pr->cursor;
  memcpy(cursor, begin + nc, sizeof(int) * (size_t)nc);
  for (int i = 0; i < n; i++)
    if (p->kind[i] == WL_KIND_FLUID) pr->order[cursor[wl_sph_cell_of(dim, &pr->grid, p->pos, i)]++] = i;
  const int nf = begin[2 * nc];
  for (int s = 0; s < nf; s++) {
    const int i = pr->order[s];
    for (int a = 0; a < dim; a++) {
      pr->pos[a][s] = p->pos[a][i];
      pr->vel[a][s] = p->vel[a][i];
    }
    pr->rho[s] = p->rho[i];
    pr->press[s] = wl_sph_eos_p(&pr->k, p->rho[i]);
  }
  return WL_OK;
}

static struct wl_sph_point_sums sums(const struct wl_sph_probe *pr, const double *x) {
  return wl_sph_point_sum(pr->dim, &pr->k, &pr->grid, pr->begin, (double *const *)pr->pos,
                          (wl_real *const *)pr->vel, pr->rho, pr->press, x);
}

double wl_sph_probe_shepard(const struct wl_sph_probe *pr, const double *x) { return sums(pr, x).s; }

double wl_sph_probe_pressure(const struct wl_sph_probe *pr, const double *x, double *p) {
  const struct wl_sph_point_sums s = sums(pr, x);
  *p = wl_sph_point_pressure(&s, (double)pr->k.h);
  return s.s;
}

void wl_sph_probe_face_pressure(const struct wl_sph_probe *pr, const double *x, double z_bed,
                                double *p) {
  const double y = pr->dim == 3 ? x[1] : 0.0;
  const double full = wl_sph_face_shepard_full(&pr->k, pr->dim, (double)pr->k.dp, z_bed, y);
  const double s = wl_sph_probe_pressure(pr, x, p);
  if (!(s >= WL_SPH_SURFACE_SHEPARD * full)) *p = 0.0;
}

int wl_sph_probe_velocity(const struct wl_sph_probe *pr, const double *x, double *v) {
  const struct wl_sph_point_sums s = sums(pr, x);
  const int ok = s.s > 0;
  for (int a = 0; a < pr->dim; a++) v[a] = ok ? s.v[a] / s.s : 0;
  return ok;
}

double wl_sph_probe_elevation(const struct wl_sph_probe *pr, double x, double y, double z_lo,
                              double z_hi, double dz) {
  const int dim = pr->dim;
  const double limit = WL_SPH_SURFACE_SHEPARD;
  if (!(dz > 0)) dz = 0.1 * pr->k.dp;
  double pt[WL_SPH_DIM_MAX] = {x, y, 0};
  const int az = dim - 1;
  /* The surface is the top of the highest wet stretch: S can dip below
   * the limit inside the water (a film running up a wall, air entrained
   * under a plunging crest), and the first dip from below is not the
   * surface. */
  int wet = 0;
  double z_prev = z_lo, s_prev = 0, surface = z_lo;
  const long n_pts = (long)ceil((z_hi - z_lo) / dz);
  for (long i = 0; i <= n_pts; i++) {
    const double z = i < n_pts ? z_lo + (double)i * dz : z_hi;
    pt[az] = z;
    const double s = wl_sph_probe_shepard(pr, pt);
    if (s >= limit) {
      wet = 1;
      surface = z_hi; /* wet up to here; lowered when it dries */
    } else if (wet) {
      surface = z_prev + (z - z_prev) * (s_prev - limit) / (s_prev - s);
      wet = 0;
    }
    z_prev = z;
    s_prev = s;
  }
  return surface;
}
