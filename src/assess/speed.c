/* speed.c: how fast this machine runs the CPU backend now, against the
 * rate the plan prices with (plan.h WL_PLAN_CPU_RATE). The same 2-core
 * machine ran the main job's first level at 4.0e6 particle-steps/s one day
 * and 6.4e6 the day before (BENCHMARKS.md, "Sweeps"): a price from one fixed
 * rate cannot hold 20 % across such days, so `check` times a small flume
 * with the run's threads, a few tenths of a second, and scales its estimate
 * by what it finds. The plan itself (particles_per_height: auto, the
 * budget) keeps the fixed rate, so that a scenario plans the same on any
 * day. */
#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "assess_private.h"
#include "wallload/plan.h"
#include "wallload/scene.h"

static double seconds_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The calibration flume: still water 0.3 m deep at dp = 7.5 mm in a tank
 * 1.2 m long (6400 fluid particles: 3200 a thread on the 2 threads
 * WL_PLAN_CPU_SPEED_RATE was measured with), longer with more threads so
 * that each keeps as many (with fewer a thread, the step's barriers
 * dominate, as they would not in the run priced: 16 threads on 6400
 * particles read 0.28 of the rate), the default numerics, the Verlet step;
 * the fastest of a few trials after a few steps to warm the caches. */
#define SPEED_DEPTH 0.3
#define SPEED_LENGTH 1.2
#define SPEED_DP 0.0075
#define SPEED_PARTICLES_PER_THREAD 3200
#define SPEED_WARM_STEPS 5
#define SPEED_STEPS 60
#define SPEED_TRIALS 3 /* the fastest: a trial that another job interrupted reads slow */

double wl_assess_cpu_speed(int threads, struct wl_error *err) {
  const char *env = getenv("WL_CPU_SPEED");
  if (env && atof(env) > 0) return atof(env);
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, 2, SPEED_DP, SPEED_DEPTH);
  wl_plan_default_numerics(&cfg.prm);
  cfg.prm.integrator = WL_SPH_VERLET;
  cfg.n_threads = threads > 0 ? threads : WL_PLAN_CPU_THREADS;
  struct wl_sph_const k;
  enum wl_status st = wl_sph_const_make(&cfg.prm, &k, err);
  if (st) return NAN;
  const double length = fmax(SPEED_LENGTH, (double)SPEED_PARTICLES_PER_THREAD * cfg.n_threads *
                                               SPEED_DP * SPEED_DP / SPEED_DEPTH);
  const double m = 5 * SPEED_DP;
  cfg.lo[0] = -m, cfg.hi[0] = length + m;
  cfg.lo[1] = -m, cfg.hi[1] = 2 * SPEED_DEPTH;
  struct wl_scene sc;
  wl_scene_init(&sc, &k, 0, 0);
  const double tx[4] = {0, 0, length, length}, tz[4] = {1.5 * SPEED_DEPTH, 0, 0, 1.5 * SPEED_DEPTH};
  const double lo[2] = {0, 0}, hi[2] = {length, SPEED_DEPTH};
  struct wl_particles init = {0};
  st = wl_scene_boundary_polyline(&sc, tx, tz, 4, 3, WL_KIND_FIXED, 0, &cfg, err);
  if (!st) st = wl_scene_fluid_block(&sc, lo, hi, SPEED_DEPTH, err);
  if (!st) wl_scene_hydrostatic_boundary(&sc, SPEED_DEPTH);
  if (!st) st = wl_scene_build(&sc, &init, err);
  wl_scene_clear(&sc);
  struct wl_sph_sim *sim = NULL;
  if (!st) st = wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, err);
  const int n = init.n;
  wl_particles_clear(&init);
  double wall = INFINITY;
  for (int i = 0; !st && i < SPEED_WARM_STEPS; i++) st = wl_sph_sim_step(sim, 0.0, err);
  for (int trial = 0; !st && trial < SPEED_TRIALS; trial++) {
    const double t0 = seconds_now();
    for (int i = 0; !st && i < SPEED_STEPS; i++) st = wl_sph_sim_step(sim, 0.0, err);
    wall = fmin(wall, seconds_now() - t0);
  }
  wl_sph_sim_free(sim);
  if (st || !(wall > 0 && isfinite(wall))) return NAN;
  /* this machine's rate against the reference machine's for this flume,
   * per thread as the plan scales it (WL_PLAN_CPU_THREADS) */
  const double rate = (double)n * SPEED_STEPS / wall;
  return rate / (WL_PLAN_CPU_SPEED_RATE * cfg.n_threads / WL_PLAN_CPU_THREADS);
}
