/* particles.c: the particle field table and the allocation of the
 * structure-of-arrays view (sph/particles.h). Every array is allocated by
 * its label (the field name) and failures name it, its size and why. */
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/sph.h"

#define F(member) offsetof(struct wl_particles, member)

static const struct wl_field_desc fields[] = {
    {"pos", "m", WL_FIELD_F64, WL_FIELD_VECTOR | WL_FIELD_SORT | WL_FIELD_OUTPUT, F(pos),
     "position; 2D runs store (x, z)"},
    {"vel", "m/s", WL_FIELD_REAL, WL_FIELD_VECTOR | WL_FIELD_SORT | WL_FIELD_OUTPUT, F(vel),
     "velocity"},
    {"rho", "kg/m^3", WL_FIELD_REAL, WL_FIELD_SORT | WL_FIELD_OUTPUT, F(rho), "density"},
    {"id", "", WL_FIELD_U32, WL_FIELD_SORT | WL_FIELD_OUTPUT, F(id), "particle number at creation"},
    {"kind", "", WL_FIELD_U8, WL_FIELD_SORT | WL_FIELD_OUTPUT, F(kind),
     "0 fluid, 1 fixed boundary, 2 moving boundary"},
    {"body", "", WL_FIELD_U8, WL_FIELD_SORT | WL_FIELD_OUTPUT, F(body),
     "moving body number, 0 for none"},
    {"pos_h", "m", WL_FIELD_F64, WL_FIELD_VECTOR | WL_FIELD_WORK, F(pos_h), "half-step position"},
    {"vel_h", "m/s", WL_FIELD_REAL, WL_FIELD_VECTOR | WL_FIELD_WORK, F(vel_h), "half-step velocity"},
    {"rho_h", "kg/m^3", WL_FIELD_REAL, WL_FIELD_WORK, F(rho_h), "half-step density"},
    {"press", "Pa", WL_FIELD_REAL, WL_FIELD_WORK, F(press), "pressure at the last force evaluation"},
    {"ace", "m/s^2", WL_FIELD_REAL, WL_FIELD_VECTOR | WL_FIELD_WORK, F(ace), "acceleration"},
    {"ar", "kg/m^3/s", WL_FIELD_REAL, WL_FIELD_WORK, F(ar), "density rate"},
    {"visc", "m/s", WL_FIELD_REAL, WL_FIELD_WORK, F(visc), "time-step viscous term"},
    {"shift", "m", WL_FIELD_REAL, WL_FIELD_VECTOR | WL_FIELD_WORK, F(shift),
     "particle shifting displacement of the step"},
    {"key", "", WL_FIELD_U32, WL_FIELD_WORK, F(key), "cell sort key"},
    {"perm", "", WL_FIELD_U32, WL_FIELD_WORK, F(perm), "sort permutation"},
};

#undef F

const struct wl_field_desc *wl_particles_fields(int *n_fields) {
  if (n_fields) *n_fields = (int)(sizeof fields / sizeof fields[0]);
  return fields;
}

int wl_field_components(const struct wl_field_desc *f, int dim) {
  return (f->flags & WL_FIELD_VECTOR) ? dim : 1;
}

size_t wl_field_type_size(enum wl_field_type type) {
  switch (type) {
  case WL_FIELD_F64: return 8;
  case WL_FIELD_REAL: return sizeof(wl_real);
  case WL_FIELD_U32: return 4;
  case WL_FIELD_U8: return 1;
  }
  return 0;
}

/* The pointer member of field f, component c (vector fields are arrays of
 * pointers, so component c is c pointers further). */
static void **slot(const struct wl_particles *p, const struct wl_field_desc *f, int c) {
  return (void **)((char *)p + f->offset) + c;
}

void *wl_field_array(const struct wl_particles *p, const struct wl_field_desc *f, int c) {
  return *slot(p, f, c);
}

size_t wl_particles_bytes(int dim, int capacity, int with_work) {
  size_t total = 0;
  int nf;
  const struct wl_field_desc *fd = wl_particles_fields(&nf);
  for (int i = 0; i < nf; i++) {
    if ((fd[i].flags & WL_FIELD_WORK) && !with_work) continue;
    total += (size_t)wl_field_components(&fd[i], dim) * wl_field_type_size(fd[i].type) *
             (size_t)(capacity > 0 ? capacity : 0);
  }
  return total;
}

enum wl_status wl_particles_alloc(struct wl_particles *p, int dim, int capacity, int with_work,
                                  struct wl_error *err) {
  memset(p, 0, sizeof *p);
  if (dim != 2 && dim != 3)
    return wl_error_set(err, WL_EINPUT, "particles: dimension %d; must be 2 or 3", dim);
  if (capacity < 0)
    return wl_error_set(err, WL_EINPUT, "particles: capacity %d; must be >= 0", capacity);
  p->dim = dim;
  p->capacity = capacity;
  int nf;
  const struct wl_field_desc *fd = wl_particles_fields(&nf);
  for (int i = 0; i < nf; i++) {
    if ((fd[i].flags & WL_FIELD_WORK) && !with_work) continue;
    const size_t es = wl_field_type_size(fd[i].type);
    for (int c = 0; c < wl_field_components(&fd[i], dim); c++) {
      /* at least one element, so that a 0-particle view still has arrays */
      void *a = calloc(capacity > 0 ? (size_t)capacity : 1, es);
      if (!a) {
        const double mb = (double)capacity * (double)es / 1048576.0;
        wl_particles_clear(p);
        return wl_error_set(err, WL_ENOMEM,
                            "particles: cannot allocate array '%s'[%d]: %.1f MiB (%d particles x "
                            "%zu B; %.1f MiB for all fields)",
                            fd[i].name, c, mb, capacity, es,
                            (double)wl_particles_bytes(dim, capacity, with_work) / 1048576.0);
      }
      *slot(p, &fd[i], c) = a;
    }
  }
  return WL_OK;
}

void wl_particles_clear(struct wl_particles *p) {
  if (!p) return;
  int nf;
  const struct wl_field_desc *fd = wl_particles_fields(&nf);
  for (int i = 0; i < nf; i++)
    for (int c = 0; c < ((fd[i].flags & WL_FIELD_VECTOR) ? WL_SPH_DIM_MAX : 1); c++) {
      free(*slot(p, &fd[i], c));
      *slot(p, &fd[i], c) = NULL;
    }
  memset(p, 0, sizeof *p);
}

enum wl_status wl_particles_copy_state(struct wl_particles *dst, const struct wl_particles *src,
                                       struct wl_error *err) {
  if (dst->dim != src->dim)
    return wl_error_set(err, WL_EINPUT, "particles: copy from %dD into %dD", src->dim, dst->dim);
  if (dst->capacity < src->n)
    return wl_error_set(err, WL_EINPUT, "particles: copy of %d particles into room for %d", src->n,
                        dst->capacity);
  int nf;
  const struct wl_field_desc *fd = wl_particles_fields(&nf);
  for (int i = 0; i < nf; i++) {
    if (!(fd[i].flags & WL_FIELD_SORT)) continue;
    const size_t es = wl_field_type_size(fd[i].type);
    for (int c = 0; c < wl_field_components(&fd[i], src->dim); c++)
      if (src->n > 0) memcpy(*slot(dst, &fd[i], c), *slot(src, &fd[i], c), (size_t)src->n * es);
  }
  dst->n = src->n;
  dst->n_bound = src->n_bound;
  return WL_OK;
}

int wl_particles_zone_select(const struct wl_particles *p, double x_lo, double x_hi, int n_parked,
                             int *idx) {
  int m = 0, parked = 0;
  for (int i = 0; i < p->n; i++) {
    const int f = wl_sph_zone_flag(p->pos[0][i], p->kind[i], p->body[i], x_lo, x_hi);
    if (f == 1 || (f == 2 && parked < n_parked)) idx[m++] = i, parked += f == 2;
  }
  return m;
}

/* The state fields between a particle set and its zone: zone particle k
 * is all's particle idx[k] (to_zone: all's into zone; else back). */
static void zone_move(struct wl_particles *zone, struct wl_particles *all, const int *idx, int m,
                      int to_zone) {
  int nf;
  const struct wl_field_desc *fd = wl_particles_fields(&nf);
  for (int f = 0; f < nf; f++) {
    if (!(fd[f].flags & WL_FIELD_SORT)) continue;
    const size_t es = wl_field_type_size(fd[f].type);
    for (int c = 0; c < wl_field_components(&fd[f], all->dim); c++) {
      char *z = *slot(zone, &fd[f], c), *a = *slot(all, &fd[f], c);
      for (int k = 0; k < m; k++) {
        char *zk = z + (size_t)k * es, *ak = a + (size_t)idx[k] * es;
        memcpy(to_zone ? zk : ak, to_zone ? ak : zk, es);
      }
    }
  }
}

void wl_particles_gather(struct wl_particles *dst, const struct wl_particles *src, const int *idx,
                         int m) {
  zone_move(dst, (struct wl_particles *)src, idx, m, 1);
  int nb = 0;
  while (nb < m && idx[nb] < src->n_bound) nb++;
  dst->n = m;
  dst->n_bound = nb;
}

void wl_particles_scatter(struct wl_particles *dst, const struct wl_particles *src, const int *idx) {
  zone_move((struct wl_particles *)src, dst, idx, src->n, 0);
}
