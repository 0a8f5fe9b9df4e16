/* test_cuda_starts.c: a run started on a busy GPU holds the state it was
 * given (the CUDA backend's start, src/backend_cuda/cuda.cu init_mode).
 *
 * The bug this guards against (fixed in faaa09a): the start copied the
 * particles in with plain cudaMemcpy, which goes to CUDA's legacy stream
 * and, from pageable host memory, returns once the data is staged, before
 * its DMA lands. The run's own stream is non-blocking and does not wait for
 * the legacy stream, so when the copy engines were busy the first sort
 * read arrays not yet written; a 64-case sweep gave some cases' wall
 * particles no body (boundary force 0) on one run and not the next.
 *
 * How it loads the start:
 *  - the legacy stream kept busy: threads copy 64 MiB blocks from pinned
 *    host memory to the device in stream 0 for as long as the starts go
 *    on, and others start, step and read back larger runs;
 *  - each start's arrays different from the run before it: the starters
 *    alternate two states of the same tank (the second with reversed ids,
 *    other velocities and densities, other body tags), so memory the
 *    driver hands back from the previous run does not already hold the
 *    right values (with one state started again and again, stale memory
 *    held the same numbers and the race went unseen);
 *  - the checks: every particle read back right after the start, found by
 *    id, against the state given (position, velocity, fluid density, kind,
 *    body: the input of the code under test, not its output); and after
 *    one step, against the CPU backend's step from the same state (float
 *    rounding apart). The CPU backend passes both checks first, which
 *    shows the checks themselves hold; they run without a GPU too.
 * What it does not do (H100, 2026-11-27): fail with the code before
 * faaa09a. Built from faaa09a's parent, this test passed as the fixed code
 * did: 2 of 2 runs as it stands (1.5 s a run), 3 of 3 with the copies in
 * their own non-blocking streams, 1 of 1 with pageable cudaMemcpy copies
 * in the legacy stream (280 s, every start waiting behind them). The race
 * showed in a 64-case sweep, its 16 runs starting and writing outputs
 * together; so this checks the start's contract under load, and is not a
 * reproduction of that bug. Skipped (77) without a
 * CUDA build or a GPU (after the CPU part). */
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "dam_tanks.h"
#include "testutil.h"
#include "wallload/backend.h"
#include "wallload/config.h"
#include "wallload/cuda_device.h"
#include "wallload/sph.h"
#if WL_HAVE_CUDA
#include <cuda_runtime_api.h>
#endif

enum {
  THREADS_COPY = 4,   /* host-to-device copies in the legacy stream */
  THREADS_BUSY = 4,   /* larger runs started, stepped and read back */
  THREADS_START = 8,  /* the runs under test */
  ROUNDS = 8,         /* starts per starter, alternating the two states */
  BODY_WALL = 2       /* the tank's left wall (dam_tanks.h) */
};
#define COPY_BYTES ((size_t)64 << 20)

/* The second state: the same tank and positions, ids reversed, other
 * velocities, densities within 0.1 % of the first's, and the wall's body
 * tag swapped with the other boundary particles'. */
static int make_second(const struct wl_particles *a, struct wl_particles *b,
                       struct wl_error *err) {
  if (wl_particles_alloc(b, a->dim, a->n, 0, err) != WL_OK ||
      wl_particles_copy_state(b, a, err) != WL_OK)
    return 1;
  for (int i = 0; i < b->n; i++) {
    b->id[i] = (unsigned)(b->n - 1 - (int)a->id[i]);
    for (int d = 0; d < b->dim; d++) b->vel[d][i] = (wl_real)(0.01 * (d + 1) * (i % 13));
    b->rho[i] = (wl_real)(a->rho[i] * (1.0 + 1e-4 * (i % 7)));
    if (b->kind[i] != WL_KIND_FLUID) b->body[i] = (unsigned char)(a->body[i] == BODY_WALL ? 1 : BODY_WALL);
  }
  return 0;
}

/* where[id] = index of the particle with that id in p. */
static int *index_by_id(const struct wl_particles *p) {
  int *where = malloc(sizeof(int) * (size_t)p->n);
  if (!where) return NULL;
  for (int i = 0; i < p->n; i++) where[i] = -1;
  for (int i = 0; i < p->n; i++)
    if (p->id[i] < (unsigned)p->n) where[p->id[i]] = i;
  return where;
}

/* Particles of got that differ from the state given (by id): position,
 * velocity, kind, body, and a fluid particle's density (a wall particle's
 * is the start's own: it takes its density from the fluid next to it,
 * docs/boundary.md). */
static long differ(const struct wl_particles *got, const struct wl_particles *given,
                   const int *where) {
  long bad = 0;
  for (int j = 0; j < got->n; j++) {
    const unsigned id = got->id[j];
    const int i = id < (unsigned)given->n ? where[id] : -1;
    int same = i >= 0 && got->kind[j] == given->kind[i] && got->body[j] == given->body[i] &&
               (got->kind[j] != WL_KIND_FLUID || got->rho[j] == given->rho[i]);
    for (int d = 0; same && d < got->dim; d++)
      same = got->pos[d][j] == given->pos[d][i] && got->vel[d][j] == given->vel[d][i];
    bad += !same;
  }
  return bad;
}

/* The first step's reference: one step of the CPU backend from a state,
 * with the step dt (half the first CFL step, as test_cuda_backend): the
 * forces of the start's first evaluation, from the state given. */
struct first_step {
  double dt, vmax;             /* the step [s]; the largest fluid speed after it [m/s] */
  struct wl_particles after;   /* the CPU's state after the step */
  int *where;                  /* index in `after` by id */
};

/* Tolerances of the GPU's first step against the CPU's (float rounding;
 * test_cuda_backend's TOL_STEP1_VEL and TOL_STEP1_RHO): a start from stale
 * memory is off by the other state's velocities (0 to 0.12 m/s). */
#define TOL_STEP1_VEL 1e-4
#define TOL_STEP1_RHO 1e-6

/* The checks themselves, on the CPU backend (no streams, no race): both
 * states read back as given; and each state's first step, the GPU's
 * reference. */
static int check_on_cpu(const struct wl_sph_config *cfg, const struct wl_particles *init,
                        int *const *where, struct first_step *ref) {
  for (int w = 0; w < 2; w++) {
    struct wl_error e;
    wl_error_clear(&e);
    struct wl_sph_sim *sim = NULL;
    const struct wl_particles *p = NULL;
    long bad = -1;
    if (wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, cfg, &init[w], &e) == WL_OK &&
        (p = wl_sph_sim_particles(sim, &e)) && p->n == init[w].n)
      bad = differ(p, &init[w], where[w]);
    printf("# CPU backend, state %d: %ld particles differ\n", w + 1, bad);
    CHECK_TRUE(bad == 0, "the check holds on the CPU backend: both states read back as given");
    ref[w].dt = sim ? 0.5 * wl_sph_sim_dt_initial(sim) : 0;
    if (bad || wl_sph_sim_step(sim, ref[w].dt, &e) != WL_OK || !(p = wl_sph_sim_particles(sim, &e)) ||
        wl_particles_alloc(&ref[w].after, p->dim, p->n, 0, &e) != WL_OK ||
        wl_particles_copy_state(&ref[w].after, p, &e) != WL_OK ||
        !(ref[w].where = index_by_id(&ref[w].after))) {
      printf("FAIL the CPU's first step from state %d: %s\n", w + 1, e.msg);
      wl_test_failures++;
      wl_sph_sim_free(sim);
      return 1;
    }
    ref[w].vmax = 0;
    for (int i = p->n_bound; i < p->n; i++)
      for (int d = 0; d < p->dim; d++) ref[w].vmax = fmax(ref[w].vmax, fabs((double)p->vel[d][i]));
    printf("# CPU backend, state %d: first step %.3g s, largest fluid velocity after it %.3g m/s\n",
           w + 1, ref[w].dt, ref[w].vmax);
    wl_sph_sim_free(sim);
  }
  return 0;
}

static enum wl_status tank(double dp, struct wl_sph_config *cfg, struct wl_particles *p,
                           struct wl_error *err) {
  wl_sph_config_default(cfg, 2, dp, dam_tank_height(DAM_2D));
  cfg->n_threads = 1;
  return dam_tank_build(DAM_2D, cfg, BODY_WALL, p, err);
}

#if WL_HAVE_CUDA
/* Fluid particles of got whose velocity or density is off the reference
 * step's beyond the tolerances. */
static long differ_step(const struct wl_particles *got, const struct first_step *ref) {
  long bad = 0;
  for (int j = 0; j < got->n; j++) {
    const unsigned id = got->id[j];
    const int i = id < (unsigned)ref->after.n ? ref->where[id] : -1;
    if (i < 0) {
      bad++;
      continue;
    }
    if (got->kind[j] != WL_KIND_FLUID) continue;
    int same = fabs((double)got->rho[j] - ref->after.rho[i]) <= TOL_STEP1_RHO * 1000.0;
    for (int d = 0; same && d < got->dim; d++)
      same = fabs((double)got->vel[d][j] - ref->after.vel[d][i]) <= TOL_STEP1_VEL * ref->vmax;
    bad += !same;
  }
  return bad;
}

/* The starts on the GPU beside busy runs and copies. */
static void starts_on_busy_gpu(const struct wl_sph_config *cfg, const struct wl_particles *init,
                               int *const *where, const struct first_step *ref,
                               struct wl_error *err) {
  struct wl_sph_config cfg_busy;
  struct wl_particles init_busy = {0};
  if (tank(0.0008, &cfg_busy, &init_busy, err) != WL_OK) {
    printf("FAIL build: %s\n", err->msg);
    wl_test_failures++;
    return;
  }
  printf("# runs under test: %d particles, two states alternating; busy runs: %d particles; "
         "%d threads copying %zu MiB blocks\n",
         init[0].n, init_busy.n, THREADS_COPY, COPY_BYTES >> 20);
  long bad = 0, bad_step = 0, fails = 0, starts = 0, busy_steps = 0, copies = 0, copy_fails = 0;
  int starters_left = THREADS_START;
#pragma omp parallel num_threads(THREADS_COPY + THREADS_BUSY + THREADS_START) \
    reduction(+ : bad, bad_step, fails, starts, busy_steps, copies, copy_fails)
  {
    const int t = omp_get_thread_num();
    struct wl_error e;
    wl_error_clear(&e);
    int left = 1;
    if (t < THREADS_COPY) {
      /* in the legacy stream (0), where the old start's copies went */
      void *host = NULL, *dev_buf = NULL;
      if (cudaMallocHost(&host, COPY_BYTES) != cudaSuccess ||
          cudaMalloc(&dev_buf, COPY_BYTES) != cudaSuccess) {
        copy_fails++;
      } else {
        memset(host, t, COPY_BYTES);
        while (left > 0) {
          if (cudaMemcpyAsync(dev_buf, host, COPY_BYTES, cudaMemcpyHostToDevice, 0) != cudaSuccess ||
              cudaStreamSynchronize(0) != cudaSuccess) {
            copy_fails++;
            break;
          }
          copies++;
#pragma omp atomic read
          left = starters_left;
        }
      }
      cudaFree(dev_buf);
      cudaFreeHost(host);
    } else if (t < THREADS_COPY + THREADS_BUSY) {
      while (left > 0) {
        struct wl_sph_sim *sim = NULL;
        if (wl_sph_sim_alloc(&sim, &wl_backend_cuda_ops, &cfg_busy, &init_busy, &e) != WL_OK) {
          fails++;
          break;
        }
        for (int k = 0; k < 4 && wl_sph_sim_step(sim, 1.0, &e) == WL_OK; k++) busy_steps++;
        if (!wl_sph_sim_particles(sim, &e)) fails++;
        wl_sph_sim_free(sim);
#pragma omp atomic read
        left = starters_left;
      }
    } else {
      for (int r = 0; r < ROUNDS; r++) {
        const int w = (t + r) % 2;
        struct wl_sph_sim *sim = NULL;
        const struct wl_particles *p = NULL;
        starts++;
        if (wl_sph_sim_alloc(&sim, &wl_backend_cuda_ops, cfg, &init[w], &e) != WL_OK ||
            !(p = wl_sph_sim_particles(sim, &e)) || p->n != init[w].n) {
          fails++;
        } else {
          bad += differ(p, &init[w], where[w]);
          if (wl_sph_sim_step(sim, ref[w].dt, &e) != WL_OK || !(p = wl_sph_sim_particles(sim, &e)))
            fails++;
          else
            bad_step += differ_step(p, &ref[w]);
        }
        wl_sph_sim_free(sim);
      }
#pragma omp atomic
      starters_left--;
    }
  }
  printf("# %ld starts beside %ld busy-run steps and %ld copies of %zu MiB: %ld did not start, "
         "step or read back; %ld particles differ from the state given, %ld from the CPU's first "
         "step\n",
         starts, busy_steps, copies, COPY_BYTES >> 20, fails, bad, bad_step);
  CHECK_TRUE(copy_fails == 0 && copies > 0, "the copy threads kept the copy engines busy");
  CHECK_TRUE(starts == THREADS_START * ROUNDS && fails == 0,
             "runs start and read back beside busy runs and copies");
  CHECK_TRUE(bad == 0, "every started run holds the state it was given (position, velocity, "
                       "fluid density, kind, body, by id)");
  CHECK_TRUE(bad_step == 0, "every started run's first step matches the CPU's from the same "
                            "state (velocity and density by id, float rounding)");
  wl_particles_clear(&init_busy);
}
#endif

int main(void) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  struct wl_particles init[2] = {{0}, {0}};
  if (tank(0.0025, &cfg, &init[0], &err) != WL_OK || make_second(&init[0], &init[1], &err)) {
    printf("FAIL build: %s\n", err.msg);
    return 1;
  }
  int *where[2] = {index_by_id(&init[0]), index_by_id(&init[1])};
  struct first_step ref[2];
  memset(ref, 0, sizeof ref);
  const int cpu_ok = check_on_cpu(&cfg, init, where, ref) == 0;
  int gpu_ran = 0;
#if WL_HAVE_CUDA
  struct wl_cuda_device dev;
  if (cpu_ok && wl_cuda_device_query(&dev, &err) == WL_OK) {
    printf("# GPU: %s\n", dev.name);
    starts_on_busy_gpu(&cfg, init, where, ref, &err);
    gpu_ran = 1;
  } else if (cpu_ok) {
    printf("SKIP (GPU part): %s\n", err.msg);
  }
#else
  if (cpu_ok) printf("SKIP (GPU part): built without CUDA\n");
#endif
  for (int w = 0; w < 2; w++) {
    free(where[w]);
    free(ref[w].where);
    wl_particles_clear(&ref[w].after);
  }
  wl_particles_clear(&init[0]);
  wl_particles_clear(&init[1]);
  return wl_test_failures ? TEST_RESULT() : gpu_ran ? 0 : 77;
}
