/* cpu_shared.c: what the CPU backends share (cpu_shared.h). */
#include "cpu_shared.h"

#include <math.h>
#include <omp.h>

#include "wallload/sph/guard.h"

/* d[i] = s[perm[i]] for elements of es bytes; called inside a parallel
 * region (orphaned worksharing loop, no barrier at its end). */
static void permute(void *d, const void *s, size_t es, const unsigned *perm, int n) {
  if (es == 8) {
    const double *src = s;
    double *dst = d;
#pragma omp for schedule(static) nowait
    for (int i = 0; i < n; i++) dst[i] = src[perm[i]];
  } else if (es == 4) {
    const unsigned int *src = s;
    unsigned int *dst = d;
#pragma omp for schedule(static) nowait
    for (int i = 0; i < n; i++) dst[i] = src[perm[i]];
  } else {
    const unsigned char *src = s;
    unsigned char *dst = d;
#pragma omp for schedule(static) nowait
    for (int i = 0; i < n; i++) dst[i] = src[perm[i]];
  }
}

static void swap_ptr(void **a, void **b) {
  void *t = *a;
  *a = *b;
  *b = t;
}

void wl_cpu_rebuild(struct wl_particles *p, struct wl_particles *alt, unsigned int **key_tmp,
                    const struct wl_sph_grid *g, int *begin, int *cursor,
                    const struct wl_cpu_sort_extra *extra, int threads) {
  const int n = p->n, nc = g->n_cells, dim = p->dim;
  int nf;
  const struct wl_field_desc *fd = wl_particles_fields(&nf);
  const unsigned *perm = p->perm;
#pragma omp parallel num_threads(threads)
  {
#pragma omp for schedule(static)
    for (int i = 0; i < n; i++) {
      const unsigned group = p->kind[i] == WL_KIND_FLUID ? 1u : 0u;
      p->key[i] = group * (unsigned)nc + (unsigned)wl_sph_cell_of(dim, g, p->pos, i);
    }
#pragma omp single
    wl_sph_cells_sort(g, p->key, n, begin, cursor, p->perm);
    /* every state field (field table) into alt, the keys into key_tmp */
    for (int f = 0; f < nf; f++) {
      if (!(fd[f].flags & WL_FIELD_SORT)) continue;
      for (int comp = 0; comp < wl_field_components(&fd[f], dim); comp++)
        permute(*((void **)((char *)alt + fd[f].offset) + comp),
                *((void **)((char *)p + fd[f].offset) + comp), wl_field_type_size(fd[f].type),
                perm, n);
    }
    permute(*key_tmp, p->key, sizeof(unsigned int), perm, n);
    for (int e = 0; extra && e < extra->n; e++)
      permute(*extra->tmp[e], *extra->src[e], extra->size[e], perm, n);
  }
  for (int e = 0; extra && e < extra->n; e++) swap_ptr(extra->src[e], extra->tmp[e]);
  /* the sorted copies become the state */
  for (int f = 0; f < nf; f++) {
    if (!(fd[f].flags & WL_FIELD_SORT)) continue;
    for (int comp = 0; comp < wl_field_components(&fd[f], dim); comp++)
      swap_ptr((void **)((char *)p + fd[f].offset) + comp,
               (void **)((char *)alt + fd[f].offset) + comp);
  }
  unsigned int *tmp = p->key;
  p->key = *key_tmp;
  *key_tmp = tmp;
}

void wl_cpu_guard_chunk(const struct wl_sph_const *k, const struct wl_sph_config *cfg,
                        struct wl_particles *p, int i0, int i1, int limiter, int exits,
                        struct wl_cpu_guard_counts *cnt) {
  const int dim = p->dim;
  struct wl_sph_wall near[WL_SPH_WALLS_MAX];
  int n_near = 0;
  if (limiter) {
    double box[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (int i = i0; i < i1; i++) {
      if (p->kind[i] != WL_KIND_FLUID) continue;
      const double x = p->pos[0][i], z = p->pos[dim - 1][i];
      box[0] = fmin(box[0], x), box[1] = fmax(box[1], x);
      box[2] = fmin(box[2], z), box[3] = fmax(box[3], z);
    }
    n_near = wl_sph_walls_near(cfg->walls, cfg->n_walls, box, near);
  }
  for (int i = i0; i < i1; i++) {
    const int moved = limiter && wl_sph_wall_limit(dim, p, near, n_near, k->penetration, i);
    cnt->limited += moved;
    if (exits) cnt->excluded += wl_sph_exclude(dim, p, cfg->lo, cfg->hi, i);
    int w = -1;
    if (wl_sph_guard(dim, k, p, cfg->lo, cfg->hi, cfg->walls,
                     wl_sph_guard_faces(limiter, moved, cfg->n_walls), i, &w) &&
        i < cnt->first)
      cnt->first = i;
  }
}

void wl_cpu_guard_report(const struct wl_sph_const *k, const struct wl_particles *p,
                         const struct wl_sph_config *cfg, int first, long limited, long excluded,
                         struct wl_sph_step_out *out) {
  const int dim = p->dim;
  out->fault = WL_SPH_FAULT_NONE;
  out->n_limited = limited;
  out->n_excluded = excluded;
  if (first == p->n) return;
  int w = -1;
  out->fault = wl_sph_guard(dim, k, p, cfg->lo, cfg->hi, cfg->walls, cfg->n_walls, first, &w);
  out->fault_index = first;
  out->fault_id = p->id[first];
  out->fault_kind = p->kind[first];
  out->fault_wall = w;
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    out->fault_pos[a] = a < dim ? p->pos[a][first] : 0;
    out->fault_vel[a] = a < dim ? p->vel[a][first] : 0;
  }
  out->fault_rho = p->rho[first];
}
