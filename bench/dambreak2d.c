/* dambreak2d.c: throughput of the CPU backend on the 2D dam break of
 * DualSPHysics' CaseDambreakVal2D proportions: a water column 1 m wide and
 * 2 m high in a 4 m tank; Wendland kernel, h = sqrt(2) dp = 1.41 dp,
 * symmetric pressure term, artificial viscosity 0.01, Fourtakas density
 * diffusion 0.1, symplectic integration (two force evaluations per step).
 *
 *   usage: dambreak2d DP STEPS THREADS
 *
 * Prints one line: particles, steps, seconds, particle-steps/s and force
 * evaluations/s (= 2 x particle-steps/s: the symplectic step evaluates the
 * forces twice). Timing covers the steps only (set-up and the initial force
 * evaluation excluded). Built and run by bench/dambreak2d.sh. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "wallload/scene.h"
#include "wallload/sph.h"

static double now(void) {
  struct timespec ts;
  timespec_get(&ts, TIME_UTC);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: %s DP STEPS THREADS\n", argv[0]);
    return 2;
  }
  const double dp = atof(argv[1]);
  const long steps = atol(argv[2]);
  const int threads = atoi(argv[3]);
  const double A = 1, H = 2, L = 4;
  const int layers = 2;
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, 2, dp, H);
  cfg.n_threads = threads;
  struct wl_sph_const k;
  if (wl_sph_const_make(&cfg.prm, &k, &err) != WL_OK) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  const double margin = (layers + 2) * dp;
  cfg.lo[0] = -margin;
  cfg.hi[0] = L + margin;
  cfg.lo[1] = -margin;
  cfg.hi[1] = 2 * H;
  struct wl_scene sc;
  wl_scene_init(&sc, &k, 0, 0);
  const double tx[4] = {0, 0, L, L}, tz[4] = {1.5 * H, 0, 0, 1.5 * H};
  const double lo[2] = {0, 0}, hi[2] = {A, H};
  struct wl_particles init = {0};
  if (wl_scene_boundary_polyline(&sc, tx, tz, 4, layers, WL_KIND_FIXED, 0, &cfg, &err) ||
      wl_scene_fluid_block(&sc, lo, hi, H, &err) || wl_scene_build(&sc, &init, &err)) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  wl_scene_clear(&sc);
  struct wl_sph_sim *sim;
  if (wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err) != WL_OK) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  const int n = init.n;
  wl_particles_clear(&init);
  char what[256];
  wl_sph_sim_describe(sim, what, sizeof what);
  const double t0 = now();
  for (long s = 0; s < steps; s++)
    if (wl_sph_sim_step(sim, 0, &err) != WL_OK) {
      fprintf(stderr, "%s\n", err.msg);
      return 1;
    }
  const double sec = now() - t0;
  const double ps = (double)n * (double)steps / sec;
  printf("particles %d  steps %ld  threads %d  seconds %.3f  particle-steps/s %.3e  "
         "force-evaluations/s %.3e  (t = %.4f s; %s)\n",
         n, steps, threads, sec, ps, 2 * ps, wl_sph_sim_time(sim), what);
  wl_sph_sim_free(sim);
  return 0;
}
