/* cpu.c: the OpenMP CPU backend (backend.h): particle arrays in host
 * memory, one step = cell rebuild by counting sort, then with the
 * symplectic integrator two force evaluations (step start and half step)
 * with the shared gather physics of include/wallload/sph/, predictor,
 * corrector and guard; with Verlet one evaluation, the Verlet update and
 * guard (sph/integrate.h). Every parallel
 * loop writes only to its own particle's outputs and every reduction is a
 * max or min, so the results do not depend on the thread count. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/backend.h"
#include "wallload/config.h"
#include "wallload/sph.h"
#include "wallload/sph/cells.h"
#include "wallload/sph/gather.h"
#include "wallload/sph/shift.h"
#include "wallload/sph/guard.h"
#include "wallload/sph/integrate.h"
#include "wallload/sph/wall.h"
#include "cpu_shared.h"

struct cpu;
struct eval_stats;
typedef void (*block_fn)(const struct cpu *, const struct wl_sph_eval *, int, int,
                         struct eval_stats *);
typedef void (*shift_fn)(const struct cpu *, const struct wl_sph_eval *, int, int, double);

struct cpu {
  struct wl_sph_config cfg;
  struct wl_sph_const k;
  struct wl_sph_grid grid;
  struct wl_particles p;   /* state + work arrays, sorted by cell */
  struct wl_particles alt; /* second copy of the state fields: target of the sort */
  int *begin;              /* 2 n_cells + 1: first sorted index of each key */
  int *cursor;             /* 2 n_cells: scatter positions of the counting sort */
  unsigned int *key_tmp;   /* keys in sorted order */
  /* Verlet: sort targets of the previous step's v and rho (vel_h, rho_h) */
  wl_real *prev_vel_tmp[WL_SPH_DIM_MAX], *prev_rho_tmp;
  block_fn block;          /* force loop for this dimension, viscosity and CPU */
  shift_fn shift;          /* particle shifting loop (sph/shift.h), the same ISA */
  const char *isa;         /* which build of it */
  int n_threads;
  /* the fluid's velocity gradients (sph/vgrad.h), when the residual
   * viscosity is on: recomputed before each force evaluation */
  wl_real *gv[WL_SPH_DIM_MAX * WL_SPH_DIM_MAX];
};

/* Maxima of one force evaluation. */
struct eval_stats {
  double ace2_max, vel2_max, visc_max;
};

/* Particles per thread below which automatic threading uses fewer threads. */
#define WL_CPU_PARTICLES_PER_THREAD 4000

static int threads(const struct cpu *c) {
  return c->n_threads > 0 ? c->n_threads : omp_get_max_threads();
}

/* ---- cell rebuild ------------------------------------------------------------ */

/* The cell rebuild (cpu_shared.h); Verlet's previous velocities and density
 * travel with the particles. */
static void rebuild(struct cpu *c) {
  struct wl_particles *p = &c->p;
  struct wl_cpu_sort_extra extra = {0};
  if (c->k.integrator == WL_SPH_VERLET) {
    for (int a = 0; a < p->dim; a++) {
      extra.src[extra.n] = (void **)&p->vel_h[a];
      extra.tmp[extra.n] = (void **)&c->prev_vel_tmp[a];
      extra.size[extra.n++] = sizeof(wl_real);
    }
    extra.src[extra.n] = (void **)&p->rho_h;
    extra.tmp[extra.n] = (void **)&c->prev_rho_tmp;
    extra.size[extra.n++] = sizeof(wl_real);
  }
  wl_cpu_rebuild(p, &c->alt, &c->key_tmp, &c->grid, c->begin, c->cursor, &extra, threads(c));
}

/* ---- force evaluation ------------------------------------------------------ */

/* The block starting at sorted index i0: up to WL_SPH_LANES consecutive
 * particles in at most two neighbouring cells of one row and group (keys
 * never straddle groups: the boundary keys end at nc), keys below c1.
 * Returns its size m; *span = last key - first key (0 or 1). */
static WL_INLINE int next_block(const struct wl_sph_eval *e, int nc, int nx, int c1, int i0,
                                int i_stop, int *span) {
  const int key0 = (int)e->key[i0];
  const int cell0 = key0 % nc;
  const int key_max = (cell0 % nx) + 1 < nx && key0 + 1 < c1 && key0 + 1 != nc ? key0 + 1 : key0;
  int m = 1;
  while (m < WL_SPH_LANES && i0 + m < i_stop && (int)e->key[i0 + m] <= key_max) m++;
  *span = (int)e->key[i0 + m - 1] - key0;
  return m;
}

/* Particle shifting (sph/shift.h) of the fluid particles of keys [c0, c1)
 * (fluid keys, >= n_cells), WL_SPH_LANES at a time as the force loop. */
static WL_INLINE void shift_generic(const int dim, const struct cpu *c,
                                    const struct wl_sph_eval *e, int c0, int c1, double dt) {
  const int nc = c->grid.n_cells, nx = c->grid.n[0];
  const int i_stop = e->begin[c1];
  for (int i0 = e->begin[c0]; i0 < i_stop;) {
    int span;
    const int m = next_block(e, nc, nx, c1, i0, i_stop, &span);
    wl_sph_shift_block(dim, WL_SPH_LANES, &c->k, &c->grid, e, i0, m, span, dt, c->p.shift);
    i0 += m;
  }
}

/* Forces on the particles of cells (keys) [c0, c1), WL_SPH_LANES at a time,
 * and the maxima the time step needs; dim and laminar are compile-time
 * constants in each instantiation below. Out of line (not inside the
 * OpenMP region), which is where GCC vectorises the lane loops; cloned for
 * AVX2 and AVX-512 (chosen at run time). The lanes do not reassociate any
 * sum, so every clone gives the same bits (ISO C mode: no FMA contraction). */
static WL_INLINE void block_generic(const int dim, const int laminar, const struct cpu *c,
                                    const struct wl_sph_eval *e, int c0, int c1,
                                    struct eval_stats *st) {
  const struct wl_particles *p = &c->p;
  const int nb = p->n_bound;
  double ace2 = st->ace2_max, vel2 = st->vel2_max, visc = st->visc_max;
  const int nc = c->grid.n_cells, nx = c->grid.n[0];
  const int i_stop = e->begin[c1];
  for (int i0 = e->begin[c0]; i0 < i_stop;) {
    int span;
    const int m = next_block(e, nc, nx, c1, i0, i_stop, &span);
    wl_sph_gather_block(dim, laminar, WL_SPH_LANES, 0, &c->k, &c->grid, e, nb, i0, m, span);
    for (int i = i0; i < i0 + m; i++) {
      double a2 = 0, v2 = 0, vi = 0;
      wl_sph_eval_dt_input(dim, e, i, nb, &a2, &v2, &vi);
      visc = visc > vi ? visc : vi;
      ace2 = ace2 > a2 ? ace2 : a2;
      vel2 = vel2 > v2 ? vel2 : v2;
    }
    i0 += m;
  }
  st->ace2_max = ace2;
  st->vel2_max = vel2;
  st->visc_max = visc;
}

/* Each instantiation in three builds on x86-64 (AVX-512 with VL, AVX2,
 * baseline SSE2), picked at run time by select_loops; elsewhere one. The
 * AVX-512 build needs VL: with AVX-512F alone GCC keeps the 8 lanes in
 * masked 512-bit registers and runs at half speed (measured). The
 * sanitizer build has the baseline one only: the three are the same C, the
 * sanitizers check it before vectorisation, and compiling three took this
 * file from 62 to 24 s there. */
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__) && !WL_SANITIZED
#define HAVE_ISA_BUILDS 1
#define ISA_BUILDS(name, params, call)                                                            \
  static __attribute__((noinline, target("avx2,avx512f,avx512vl,avx512bw,avx512dq"))) void       \
      name##_v4 params { call; }                                                                  \
  static __attribute__((noinline, target("avx2"))) void name##_v3 params { call; }                \
  static __attribute__((noinline)) void name##_v1 params { call; }
#else
#define HAVE_ISA_BUILDS 0
#define ISA_BUILDS(name, params, call) static void name##_v1 params { call; }
#endif
#define BLOCK(name, dim, laminar)                                                                 \
  ISA_BUILDS(name,                                                                                \
             (const struct cpu *c, const struct wl_sph_eval *e, int c0, int c1,                   \
              struct eval_stats *st),                                                             \
             block_generic(dim, laminar, c, e, c0, c1, st))
BLOCK(block_2a, 2, 0)
BLOCK(block_2l, 2, 1)
BLOCK(block_3a, 3, 0)
BLOCK(block_3l, 3, 1)
#undef BLOCK
#define SHIFT(name, dim)                                                                          \
  ISA_BUILDS(name, (const struct cpu *c, const struct wl_sph_eval *e, int c0, int c1, double dt), \
             shift_generic(dim, c, e, c0, c1, dt))
SHIFT(shift_2, 2)
SHIFT(shift_3, 3)
#undef SHIFT

/* The widest build this CPU runs: 4 (AVX-512 with VL), 3 (AVX2) or 1
 * (baseline), and its name. */
static int isa_level(const char **isa) {
#if HAVE_ISA_BUILDS
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
      __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq")) {
    *isa = "avx512";
    return 4;
  }
  if (__builtin_cpu_supports("avx2")) {
    *isa = "avx2";
    return 3;
  }
#endif
  *isa = "baseline";
  return 1;
}

/* The force loop for this run's dimension and viscosity, and the shifting
 * loop for its dimension, in the build isa_level chose. */
static void select_loops(int dim, int laminar, block_fn *block, shift_fn *shift, const char **isa) {
  const int lv = isa_level(isa), v = dim * 2 + laminar; /* 4, 5, 6, 7 */
#if HAVE_ISA_BUILDS
  if (lv == 4) {
    *block = v == 4 ? block_2a_v4 : v == 5 ? block_2l_v4 : v == 6 ? block_3a_v4 : block_3l_v4;
    *shift = dim == 2 ? shift_2_v4 : shift_3_v4;
    return;
  }
  if (lv == 3) {
    *block = v == 4 ? block_2a_v3 : v == 5 ? block_2l_v3 : v == 6 ? block_3a_v3 : block_3l_v3;
    *shift = dim == 2 ? shift_2_v3 : shift_3_v3;
    return;
  }
#else
  (void)lv;
#endif
  *block = v == 4 ? block_2a_v1 : v == 5 ? block_2l_v1 : v == 6 ? block_3a_v1 : block_3l_v1;
  *shift = dim == 2 ? shift_2_v1 : shift_3_v1;
}

/* Cells per OpenMP work chunk. */
enum { CELLS_PER_CHUNK = 32 };

/* One force evaluation at state (pos, vel, rho): pressures, then the gather
 * over all cells in chunks; the maxima go into st. With `in` not NULL the
 * predictor (step in->dt) runs first in the same parallel region. */
static void evaluate(struct cpu *c, double *const *pos, wl_real *const *vel, wl_real *rho,
                     const struct wl_sph_step_in *in, struct eval_stats *st) {
  struct wl_particles *p = &c->p;
  const struct wl_sph_const *k = &c->k;
  const int n = p->n, dim = p->dim;
  struct wl_sph_eval e;
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    e.pos[a] = a < dim ? pos[a] : NULL;
    e.vel[a] = a < dim ? vel[a] : NULL;
    e.ace[a] = a < dim ? p->ace[a] : NULL;
  }
  e.rho = rho;
  e.press = p->press;
  e.key = p->key;
  e.begin = c->begin;
  e.ar = p->ar;
  e.visc = p->visc;
  for (int q = 0; q < WL_SPH_DIM_MAX * WL_SPH_DIM_MAX; q++) e.gv[q] = c->gv[q];
  const block_fn block = c->block;
  wl_real *press = p->press;
  const int n_keys = 2 * c->grid.n_cells;
  const int n_chunks = (n_keys + CELLS_PER_CHUNK - 1) / CELLS_PER_CHUNK;
  /* with the wall condition the force loop visits the fluid keys only
   * (key_first = nc .. 2 nc - 1), from the chunk that holds key nc */
  const int wall_bc = k->boundary == WL_SPH_BOUND_ADAMI, nb = p->n_bound;
  const int nb_eos = wall_bc ? nb : 0;
  const int key_first = wall_bc ? c->grid.n_cells : 0, b_first = key_first / CELLS_PER_CHUNK;
#pragma omp parallel num_threads(threads(c))
  {
    if (in) {
#pragma omp for schedule(static)
      for (int i = 0; i < n; i++)
        wl_sph_predict(dim, k, p, in->dt, (const double(*)[WL_SPH_DIM_MAX])in->body_vel, i);
    }
#pragma omp for schedule(static)
    for (int i = nb_eos; i < n; i++) press[i] = wl_sph_eos_p(k, rho[i]);
    if (c->gv[0]) {
      /* the residual viscosity's velocity gradients (sph/vgrad.h) */
#pragma omp for schedule(dynamic, 256)
      for (int i = nb; i < n; i++) {
        if (dim == 2) wl_sph_vgrad(2, k, &c->grid, e.pos, e.vel, e.rho, e.key, e.begin, i, c->gv);
        else wl_sph_vgrad(3, k, &c->grid, e.pos, e.vel, e.rho, e.key, e.begin, i, c->gv);
      }
    }
    if (wall_bc) {
      /* the wall condition (sph/wall.h) from the fluid's pressures: the
       * boundary particles' density and pressure before the fluid reads them */
#pragma omp for schedule(dynamic, 64)
      for (int i = 0; i < nb; i++) {
        const double *aw = p->kind[i] == WL_KIND_MOVING && in ? in->body_acc[p->body[i]] : NULL;
        if (dim == 2) wl_sph_wall_sample(2, k, &c->grid, &e, aw, i, rho, press);
        else wl_sph_wall_sample(3, k, &c->grid, &e, aw, i, rho, press);
      }
    }
    struct eval_stats mine = {0, 0, 0};
#pragma omp for schedule(dynamic, 1)
    for (int b = b_first; b < n_chunks; b++) {
      const int c0 = b * CELLS_PER_CHUNK, c1 = c0 + CELLS_PER_CHUNK < n_keys ? c0 + CELLS_PER_CHUNK : n_keys;
      block(c, &e, c0 > key_first ? c0 : key_first, c1, &mine);
    }
#pragma omp critical
    {
      st->ace2_max = st->ace2_max > mine.ace2_max ? st->ace2_max : mine.ace2_max;
      st->vel2_max = st->vel2_max > mine.vel2_max ? st->vel2_max : mine.vel2_max;
      st->visc_max = st->visc_max > mine.visc_max ? st->visc_max : mine.visc_max;
    }
  }
}

/* Particle shifting of the step (sph/shift.h) from the sorted step-start
 * state, for the corrector to add. */
static void shift(struct cpu *c, double dt) {
  struct wl_particles *p = &c->p;
  const int nc = c->grid.n_cells;
  const struct wl_sph_eval e = wl_sph_eval_inputs(p->dim, p->pos, p->vel, p->rho, p->key, c->begin);
  const shift_fn run = c->shift;
  const int n_chunks = (nc + CELLS_PER_CHUNK - 1) / CELLS_PER_CHUNK;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads(c))
  for (int b = 0; b < n_chunks; b++) { /* the fluid keys nc .. 2 nc - 1 */
    const int c0 = nc + b * CELLS_PER_CHUNK;
    run(c, &e, c0, c0 + CELLS_PER_CHUNK < 2 * nc ? c0 + CELLS_PER_CHUNK : 2 * nc, dt);
  }
}

/* dt from the maxima of the evaluations of a step (backend.h wl_sph_step_dt). */
static void fill_dt(const struct cpu *c, const struct eval_stats *st, struct wl_sph_step_out *out) {
  wl_sph_step_dt(&c->k, st->ace2_max, st->vel2_max, st->visc_max, out);
}

/* ---- guard ------------------------------------------------------------------- */

/* The guard for every particle, after the update (the corrector or the
 * Verlet step) when `in` is not NULL, a chunk at a time: the chunk's
 * updates, then its limiter, exits and guard (cpu_shared.h
 * wl_cpu_guard_chunk; particle i's check reads only what its update
 * wrote). The first faulty particle is the lowest index, whatever the
 * threads. */
static void guard(struct cpu *c, const struct wl_sph_step_in *in, struct wl_sph_step_out *out) {
  struct wl_particles *p = &c->p;
  const int n = p->n, dim = p->dim;
  const int n_chunks = (n + WL_CPU_GUARD_CHUNK - 1) / WL_CPU_GUARD_CHUNK;
  int first = n;
  long limited = 0, excluded = 0;
  const int verlet = c->k.integrator == WL_SPH_VERLET;
  const int euler = in && verlet && wl_sph_verlet_euler(&c->k, in->step);
  const int limiter = in && c->k.wall_limiter;
#pragma omp parallel for schedule(static) num_threads(threads(c)) reduction(min : first) \
    reduction(+ : limited, excluded)
  for (int ch = 0; ch < n_chunks; ch++) {
    const int i0 = ch * WL_CPU_GUARD_CHUNK;
    const int i1 = i0 + WL_CPU_GUARD_CHUNK < n ? i0 + WL_CPU_GUARD_CHUNK : n;
    if (in)
      for (int i = i0; i < i1; i++) {
        if (verlet)
          wl_sph_verlet(dim, &c->k, p, in->dt, in->dt_prev,
                        (const double(*)[WL_SPH_DIM_MAX])in->body_vel, euler, i);
        else
          wl_sph_correct(dim, &c->k, p, in->dt, (const double(*)[WL_SPH_DIM_MAX])in->body_vel, i);
      }
    struct wl_cpu_guard_counts cnt = {n, 0, 0};
    wl_cpu_guard_chunk(&c->k, &c->cfg, p, i0, i1, limiter, in != NULL, &cnt);
    first = cnt.first < first ? cnt.first : first;
    limited += cnt.limited;
    excluded += cnt.excluded;
  }
  wl_cpu_guard_report(&c->k, p, &c->cfg, first, limited, excluded, out);
}

/* ---- the wall load ------------------------------------------------------------ */

/* backend.h wall_load: the cell lists of the current state, every
 * particle's pressure from its stored density, then each fluid particle's
 * share (sph/gather.h wl_sph_gather_wall_load) into pos_h, which holds
 * nothing between steps (the next predictor or Verlet step writes it
 * before reading), summed in index order. */
static enum wl_status cpu_wall_load(void *ctx, int body, double z_ref, double *force,
                                    double *moment, struct wl_error *err) {
  struct cpu *c = ctx;
  struct wl_particles *p = &c->p;
  const struct wl_sph_const *k = &c->k;
  const int n = p->n, nb = p->n_bound, dim = p->dim;
  const int laminar = k->visc == WL_SPH_VISC_LAMINAR;
  (void)err;
  rebuild(c);
  const struct wl_sph_eval e0 = wl_sph_eval_inputs(dim, p->pos, p->vel, p->rho, p->key, c->begin);
  struct wl_sph_eval e = e0;
  e.press = p->press;
  double *fx = p->pos_h[0], *my = p->pos_h[1];
#pragma omp parallel num_threads(threads(c))
  {
#pragma omp for schedule(static)
    for (int i = 0; i < n; i++) p->press[i] = wl_sph_eos_p(k, p->rho[i]);
#pragma omp for schedule(dynamic, 256)
    for (int i = nb; i < n; i++) {
      if (dim == 2 && laminar) wl_sph_gather_wall_load(2, 1, k, &c->grid, &e, p->body, body, z_ref, i, &fx[i], &my[i]);
      else if (dim == 2) wl_sph_gather_wall_load(2, 0, k, &c->grid, &e, p->body, body, z_ref, i, &fx[i], &my[i]);
      else if (laminar) wl_sph_gather_wall_load(3, 1, k, &c->grid, &e, p->body, body, z_ref, i, &fx[i], &my[i]);
      else wl_sph_gather_wall_load(3, 0, k, &c->grid, &e, p->body, body, z_ref, i, &fx[i], &my[i]);
    }
  }
  double sx = 0.0, sm = 0.0;
  for (int i = nb; i < n; i++) {
    sx += fx[i];
    sm += my[i];
  }
  *force = sx;
  *moment = sm;
  return WL_OK;
}

/* ---- the backend operations ------------------------------------------------- */

static void cpu_free(void *ctx) {
  struct cpu *c = ctx;
  if (!c) return;
  wl_particles_clear(&c->p);
  wl_particles_clear(&c->alt);
  free(c->begin);
  free(c->cursor);
  free(c->key_tmp);
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) free(c->prev_vel_tmp[a]);
  free(c->prev_rho_tmp);
  for (int q = 0; q < WL_SPH_DIM_MAX * WL_SPH_DIM_MAX; q++) free(c->gv[q]);
  free(c);
}

static enum wl_status cpu_step(void *ctx, const struct wl_sph_step_in *in,
                               struct wl_sph_step_out *out, struct wl_error *err) {
  struct cpu *c = ctx;
  struct wl_particles *p = &c->p;
  (void)err;
  memset(out, 0, sizeof *out);
  struct eval_stats st = {0, 0, 0};

  /* four parallel regions (five with shifting): sort; (shifts;) forces at
   * the start; predictor and forces at the half step; corrector and guard.
   * Verlet: sort; (shifts;) forces at the start; Verlet update and guard */
  rebuild(c);
  if (in && c->k.shift_coef > 0) shift(c, in->dt);
  evaluate(c, p->pos, p->vel, p->rho, NULL, &st);
  if (c->k.integrator == WL_SPH_SYMPLECTIC) evaluate(c, p->pos_h, p->vel_h, p->rho_h, in, &st);
  guard(c, in, out);
  fill_dt(c, &st, out);
  return WL_OK;
}

static void cpu_describe(void *ctx, char *buf, size_t size) {
  const struct cpu *c = ctx;
  snprintf(buf, size, "cpu (OpenMP, %d threads, %s force loop, %s, %d cells of %.4g m)",
           threads(c), c->isa,
           c->k.integrator == WL_SPH_VERLET ? "Verlet steps" : "symplectic steps",
           c->grid.n_cells, c->grid.cell);
}

static enum wl_status cpu_download(void *ctx, struct wl_particles *host, struct wl_error *err) {
  struct cpu *c = ctx;
  return wl_particles_copy_state(host, &c->p, err);
}

static enum wl_status cpu_zone_download(void *ctx, double x_lo, double x_hi, int n_parked,
                                        struct wl_particles *host, int *idx, struct wl_error *err) {
  struct cpu *c = ctx;
  if (host->dim != c->p.dim || host->capacity < c->p.n)
    return wl_error_set(err, WL_EINPUT, "cpu backend: a zone of up to %d %dD particles into room "
                        "for %d %dD", c->p.n, c->p.dim, host->capacity, host->dim);
  const int m = wl_particles_zone_select(&c->p, x_lo, x_hi, n_parked, idx);
  wl_particles_gather(host, &c->p, idx, m);
  return WL_OK;
}

static enum wl_status cpu_zone_upload(void *ctx, const struct wl_particles *host, const int *idx,
                                      struct wl_error *err) {
  struct cpu *c = ctx;
  (void)err;
  wl_particles_scatter(&c->p, host, idx);
  return WL_OK;
}

static enum wl_status cpu_init(void **ctx, const struct wl_sph_config *cfg,
                               const struct wl_sph_const *k, const struct wl_particles *host,
                               struct wl_sph_step_out *out, struct wl_error *err) {
  *ctx = NULL;
  const int dim = cfg->prm.dim;
  enum wl_status st0 = wl_sph_check_particles("cpu", cfg, host, err);
  if (st0) return st0;
  struct cpu *c = calloc(1, sizeof *c);
  if (!c) return wl_error_set(err, WL_ENOMEM, "cpu backend: out of memory");
  c->cfg = *cfg;
  c->k = *k;
  c->n_threads = cfg->n_threads;
  if (c->n_threads <= 0) {
    /* Automatic: no more threads than the particles keep busy. A step has
     * four parallel regions; below a few thousand particles per thread the
     * barriers cost more than the work they split, and on a machine shared
     * with other jobs each barrier can wait a whole scheduler slice for a
     * descheduled partner (a small still-water run went 70x slower on 2
     * threads than its work needs). */
    const int by_work = host->n / WL_CPU_PARTICLES_PER_THREAD;
    const int most = omp_get_max_threads();
    c->n_threads = by_work < 1 ? 1 : by_work > most ? most : by_work;
  }
  select_loops(dim, k->visc == WL_SPH_VISC_LAMINAR, &c->block, &c->shift, &c->isa);
  /* the grid: cells of side 2h over the domain box */
  struct wl_sph_grid *g = &c->grid;
  const enum wl_status gst = wl_sph_grid_make(cfg, k, g, err);
  if (gst != WL_OK) {
    cpu_free(c);
    return gst;
  }
  enum wl_status st = wl_particles_alloc(&c->p, dim, host->n, 1, err);
  if (st == WL_OK) st = wl_particles_alloc(&c->alt, dim, host->n, 0, err);
  if (st == WL_OK) st = wl_particles_copy_state(&c->p, host, err);
  if (st != WL_OK) {
    cpu_free(c);
    return st;
  }
  c->begin = malloc(sizeof(int) * (size_t)(2 * g->n_cells + 1));
  c->cursor = malloc(sizeof(int) * (size_t)(2 * g->n_cells));
  c->key_tmp = malloc(sizeof(unsigned int) * (size_t)(host->n > 0 ? host->n : 1));
  if (k->integrator == WL_SPH_VERLET) {
    /* the previous step's v and rho start as the initial state (the first
     * step is an Euler step, wl_sph_verlet_euler, which does not read them) */
    const size_t bytes = sizeof(wl_real) * (size_t)(host->n > 0 ? host->n : 1);
    int ok = (c->prev_rho_tmp = malloc(bytes)) != NULL;
    for (int a = 0; a < dim; a++) {
      ok = ok && (c->prev_vel_tmp[a] = malloc(bytes)) != NULL;
      if (ok) memcpy(c->p.vel_h[a], c->p.vel[a], sizeof(wl_real) * (size_t)host->n);
    }
    if (!ok) {
      const int n = host->n;
      cpu_free(c);
      return wl_error_set(err, WL_ENOMEM, "cpu backend: cannot allocate the Verlet sort buffers "
                          "(%d particles x %zu B)", n, (size_t)(dim + 1) * sizeof(wl_real));
    }
    memcpy(c->p.rho_h, c->p.rho, sizeof(wl_real) * (size_t)host->n);
  }
  if (k->rav > 0 || k->nut_c > 0) {
    /* the velocity gradients of the residual and the eddy viscosity (sph/vgrad.h) */
    const size_t bytes = sizeof(wl_real) * (size_t)(c->p.capacity > 0 ? c->p.capacity : 1);
    int ok = 1;
    for (int q = 0; q < dim * dim; q++) ok = ok && (c->gv[q] = malloc(bytes)) != NULL;
    if (!ok) {
      const int n = c->p.capacity;
      cpu_free(c);
      return wl_error_set(err, WL_ENOMEM, "cpu backend: cannot allocate the velocity gradients "
                          "(%d particles x %zu B)", n, (size_t)(dim * dim) * sizeof(wl_real));
    }
  }
  if (!c->begin || !c->cursor || !c->key_tmp) {
    const double mb = (2.0 * g->n_cells + 1) * sizeof(int) / 1048576.0, side = g->cell;
    const int nc = g->n_cells;
    cpu_free(c);
    return wl_error_set(err, WL_ENOMEM, "cpu backend: cannot allocate the cell index: 2 x %.1f MiB "
                        "(%d cells of %g m)", mb, nc, side);
  }
  /* forces of the initial state give the first dt */
  memset(out, 0, sizeof *out);
  struct eval_stats es = {0, 0, 0};
  rebuild(c);
  evaluate(c, c->p.pos, c->p.vel, c->p.rho, NULL, &es);
  fill_dt(c, &es, out);
  guard(c, NULL, out);
  *ctx = c;
  return WL_OK;
}

const struct wl_backend_ops wl_backend_cpu_ops = {
    .name = "cpu",
    .init = cpu_init,
    .step = cpu_step,
    .download = cpu_download,
    .describe = cpu_describe,
    .free = cpu_free,
    .wall_load = cpu_wall_load,
    .zone_download = cpu_zone_download,
    .zone_upload = cpu_zone_upload,
};
