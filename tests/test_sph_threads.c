/* test_sph_threads.c: results independent of the thread count. The same
 * short run (a dam break pushed by a moving piston paddle, so fluid, fixed
 * and moving boundary particles all take part) on 1 and on 2 OpenMP
 * threads must give identical states, bit for bit: the gather form writes
 * only each particle's own outputs and every reduction is a max or a min
 * (STYLE.md: "1 thread vs N threads"). A second 2-thread run checks that
 * the result is repeatable. The same comparison runs with laminar
 * viscosity, and in 3D (a slab of the flume, extruded along y), so every
 * instantiation of the force loop is exercised, and with the Verlet
 * integrator (120 steps: three of them Euler steps). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/scene.h"
#include "wallload/sph.h"

#define STEPS 120

static int run(int threads, int dim, int laminar, int verlet, int steps, struct wl_particles *out,
               double *t_out) {
  const double dp = dim == 2 ? 0.02 : 0.04, A = 0.4, H = 0.8, L = 1.6;
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, dim, dp, H);
  cfg.n_threads = threads;
  if (laminar) cfg.prm.visc = WL_SPH_VISC_LAMINAR;
  if (verlet) cfg.prm.integrator = WL_SPH_VERLET;
  struct wl_sph_const k;
  if (wl_sph_const_make(&cfg.prm, &k, &err)) return 1;
  cfg.lo[0] = -0.3;
  cfg.hi[0] = L + 0.2;
  cfg.lo[1] = -0.2;
  cfg.hi[1] = 3 * H;
  if (dim == 3) {
    cfg.lo[1] = -1; /* y: no side walls in this slab, room to spread */
    cfg.hi[1] = 1.2;
    cfg.lo[2] = -0.2;
    cfg.hi[2] = 3 * H;
  }
  struct wl_scene sc;
  wl_scene_init(&sc, &k, 0, 0.2);
  const double tx[3] = {0, L, L}, tz[3] = {0, 0, 2 * H};
  const double bx[2] = {-0.2, 0}, bz[2] = {0, 0};
  const double lo[3] = {0, 0, 0}, hi[3] = {A, dim == 3 ? 0.2 : H, H};
  struct wl_particles init = {0};
  if (wl_scene_boundary_polyline(&sc, tx, tz, 3, 3, WL_KIND_FIXED, 0, &cfg, &err) ||
      wl_scene_boundary_polyline(&sc, bx, bz, 2, 3, WL_KIND_FIXED, 0, NULL, &err) ||
      wl_scene_piston(&sc, 0, 0, 1.5 * H, 3, 1, &err) || wl_scene_fluid_block(&sc, lo, hi, H, &err) ||
      wl_scene_build(&sc, &init, &err)) {
    printf("scene: %s\n", err.msg);
    return 1;
  }
  wl_scene_clear(&sc);
  struct wl_sph_sim *sim;
  if (wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err)) {
    printf("sim: %s\n", err.msg);
    return 1;
  }
  const double tt[3] = {0, 0.05, 1}, xx[3] = {0, 0.01, 0.1};
  struct wl_sph_motion m = {WL_SPH_MOTION_TABLE, 3, tt, xx, NULL, NULL};
  if (wl_sph_sim_set_motion(sim, 1, &m, &err)) return 1;
  for (int s = 0; s < steps; s++)
    if (wl_sph_sim_step(sim, 0, &err) != WL_OK) {
      printf("step: %s\n", err.msg);
      return 1;
    }
  const struct wl_particles *p = wl_sph_sim_particles(sim, &err);
  if (!p || wl_particles_alloc(out, dim, p->n, 0, &err) || wl_particles_copy_state(out, p, &err)) return 1;
  *t_out = wl_sph_sim_time(sim);
  wl_particles_clear(&init);
  wl_sph_sim_free(sim);
  return 0;
}

/* Same particles (by id), same bits in every state field. */
static int identical(const struct wl_particles *a, const struct wl_particles *b, double *max_diff) {
  if (a->n != b->n) return 0;
  unsigned *where = malloc(sizeof(unsigned) * (size_t)a->n);
  for (int i = 0; i < b->n; i++) where[b->id[i]] = (unsigned)i;
  int same = 1;
  *max_diff = 0;
  for (int i = 0; i < a->n; i++) {
    const unsigned j = where[a->id[i]];
    for (int d = 0; d < a->dim; d++) {
      same &= a->pos[d][i] == b->pos[d][j] && a->vel[d][i] == b->vel[d][j];
      *max_diff = fmax(*max_diff, fabs(a->pos[d][i] - b->pos[d][j]));
    }
    same &= a->rho[i] == b->rho[j] && a->kind[i] == b->kind[j];
  }
  free(where);
  return same;
}

static void compare(int dim, int laminar, int verlet, int steps) {
  struct wl_particles p1 = {0}, p2 = {0}, p2b = {0};
  double t1 = 0, t2 = 0, t2b = 0, diff;
  char ref[160];
  if (run(1, dim, laminar, verlet, steps, &p1, &t1) ||
      run(2, dim, laminar, verlet, steps, &p2, &t2) ||
      run(2, dim, laminar, verlet, steps, &p2b, &t2b)) {
    CHECK_TRUE(0, "a run failed");
    return;
  }
  const char *visc = laminar ? "laminar" : "artificial", *step = verlet ? "Verlet" : "symplectic";
  printf("%dD %s, %s: %d particles, %d steps, t = %.6g s\n", dim, visc, step, p1.n, steps, t1);
  snprintf(ref, sizeof ref, "%dD %s viscosity, %s: same time steps on 1 and 2 threads", dim, visc,
           step);
  CHECK_TRUE(t1 == t2, ref);
  snprintf(ref, sizeof ref, "%dD %s viscosity, %s: 1 vs 2 threads identical positions, "
           "velocities, densities", dim, visc, step);
  CHECK_TRUE(identical(&p1, &p2, &diff), ref);
  CHECK_ABS(diff, 0, 0, "largest position difference 1 vs 2 threads [m]");
  CHECK_TRUE(identical(&p2, &p2b, &diff) && t2 == t2b, "2 threads twice: identical");
  int moved = 0;
  for (int i = 0; i < p1.n; i++) moved |= p1.kind[i] == WL_KIND_FLUID && fabs(p1.vel[dim - 1][i]) > 0.02;
  CHECK_TRUE(moved, "the run did something (fluid moving)");
  wl_particles_clear(&p1);
  wl_particles_clear(&p2);
  wl_particles_clear(&p2b);
}

int main(void) {
  compare(2, 0, 0, STEPS);
  compare(2, 1, 0, STEPS / 3);
  compare(3, 0, 0, STEPS / 3);
  compare(2, 0, 1, STEPS);
  return TEST_RESULT();
}
