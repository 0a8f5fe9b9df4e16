/* cpu_shared.h: what the CPU backends (cpu.c, isph.c) share: the cell rebuild
 * and the guard's report. Private to src/backend_cpu. */
#ifndef WL_BACKEND_CPU_SHARED_H
#define WL_BACKEND_CPU_SHARED_H

#include <stddef.h>

#include "wallload/backend.h"
#include "wallload/sph.h"
#include "wallload/sph/cells.h"

/* Arrays beyond the state's field table that travel with the particles
 * (Verlet's previous velocities and density): each *src is permuted into
 * *tmp, then the two swap. */
enum { WL_CPU_SORT_EXTRA_MAX = WL_SPH_DIM_MAX + 1 };
struct wl_cpu_sort_extra {
  int n;
  void **src[WL_CPU_SORT_EXTRA_MAX], **tmp[WL_CPU_SORT_EXTRA_MAX];
  size_t size[WL_CPU_SORT_EXTRA_MAX];
};

/* Counting sort of all particles by key = group * n_cells + cell (boundary
 * group 0 first, so boundary particles stay in [0, n_bound)). The sort is
 * stable, so the order within a cell is the previous order: deterministic.
 * Every sorted field of p (the field table) goes into alt's arrays and the
 * two swap; the keys likewise with *key_tmp; begin and cursor are the
 * sort's scratch (wl_sph_cells_sort). One parallel region of `threads`
 * (a step's barriers are what costs when the machine is shared). */
void wl_cpu_rebuild(struct wl_particles *p, struct wl_particles *alt, unsigned int **key_tmp,
                    const struct wl_sph_grid *g, int *begin, int *cursor,
                    const struct wl_cpu_sort_extra *extra, int threads);

/* Particles per chunk of the guard (wl_cpu_guard_chunk). */
enum { WL_CPU_GUARD_CHUNK = 256 };

/* The guard's counts over the chunks of a step. */
struct wl_cpu_guard_counts {
  int first;    /* the lowest faulty index so far (p->n: none) */
  long limited; /* wall-limiter corrections */
  long excluded; /* particles taken out of the run (domain exits) */
};

/* After the particles [i0, i1) (a chunk, in cell order: a compact patch)
 * have been updated: the wall limiter (when `limiter`), the domain exits
 * (when `exits`) and the guard of each, added to *cnt. The limiter tests
 * only the wall faces near the chunk's fluid (sph/guard.h
 * wl_sph_walls_near: its decisions are those over every face), the guard
 * only where the limiter moved a particle (wl_sph_guard_faces). */
void wl_cpu_guard_chunk(const struct wl_sph_const *k, const struct wl_sph_config *cfg,
                        struct wl_particles *p, int i0, int i1, int limiter, int exits,
                        struct wl_cpu_guard_counts *cnt);

/* The guard's report of a step into out: the wall limiter's and the domain
 * exits' counts, and the first particle (lowest index; n: none) that
 * failed the guard, with its state. */
void wl_cpu_guard_report(const struct wl_sph_const *k, const struct wl_particles *p,
                         const struct wl_sph_config *cfg, int first, long limited, long excluded,
                         struct wl_sph_step_out *out);

#endif
