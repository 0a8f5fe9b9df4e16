/* bench.c: `wallload bench`: throughput of the SPH step on each backend,
 * on two dam breaks:
 *
 *  dambreak2d  DualSPHysics CaseDambreakVal2D proportions: a water column
 *              1 m wide and 2 m high in a 4 m tank (walls 6 m high and
 *              room above them to 12 m: the jet up the far wall rises
 *              above 6 m);
 *  dambreak3d  DualSPHysics example 01_DamBreak: tank 1.6 x 0.67 x 0.4 m,
 *              water column 0.4 x 0.67 x 0.3 m at x = 0, a 0.12 x 0.12 m
 *              square pillar standing at x = 0.9, y = 0.24 m (as tall as
 *              the tank).
 *
 * Physics (--numerics dualsphysics, the default): Wendland C2, h = coefh
 * sqrt(dim) dp (coefh 1: 1.41 dp in 2D, 1.73 dp in 3D), symmetric pressure
 * term, artificial viscosity 0.01, Fourtakas density diffusion (full) 0.1,
 * coefsound 10, CFL 0.2, symplectic steps (two force evaluations each);
 * --numerics assess: what `assess` runs (wl_plan_default_numerics: coefh
 * 1.2 in 2D, laminar viscosity) and c0 by its Mach rule (sph/params.h:
 * at least 10 times the front speed 2 sqrt(g H), so 20 sqrt(g H)). Walls: --boundary adami (the default, the
 * wall condition of sph/wall.h) or dbc (dynamic boundary particles), in
 * --layers layers (default: ceil(2h/dp), the kernel's full support, as the
 * flume builds them; DualSPHysics' examples use 2). Timing covers the
 * steps only, after a few warm-up steps (set-up, the initial force
 * evaluation and the warm-up excluded). --until T runs to the simulated
 * time T instead of a step count and reports whether the run stayed stable
 * (the guard, sph/guard.h), with the guard's message if not.
 *
 * Per run it prints particles, steps, force evaluations (particles x 2 x
 * steps), seconds, particle-steps/s, force-evaluations/s, kernel, h/dp and
 * bytes per particle: on the GPU the device memory the backend took
 * (cudaMemGetInfo before and after its init), on the CPU what the backend
 * allocates (wl_sph_memory_bytes). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "wallload/backend.h"
#include "wallload/cuda_device.h"
#include "wallload/plan.h"
#include "wallload/scene.h"
#include "wallload/sph.h"

/* Steps run before timing starts (module load, first-touch, caches). */
enum { WARMUP_STEPS = 3 };

struct bench_opts {
  int case2d, case3d;   /* which cases */
  int cpu, cuda;        /* which backends */
  double particles;     /* target total particle count */
  long steps;
  double coefh;         /* 0: default (1) */
  double shift;         /* particle shifting coefficient A (0: off) */
  int threads;
  int boundary;         /* enum wl_sph_boundary */
  int assess_numerics;  /* 1: wl_plan_default_numerics */
  int layers;           /* boundary layers; 0: ceil(2h/dp) */
  double until;         /* > 0: run to this simulated time [s] instead of `steps` */
  double wall_alpha;    /* < 0: the solver's default */
  double coefsound;     /* 0: the default */
  int limiter;          /* < 0: the solver's default */
};

static double now_s(void) {
  struct timespec ts;
  timespec_get(&ts, TIME_UTC);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Build the case at spacing dp into cfg and p. */
static enum wl_status build_case(const struct bench_opts *o, int dim, double dp,
                                 struct wl_sph_config *cfg, struct wl_particles *p,
                                 struct wl_error *err) {
  const double H = dim == 2 ? 2.0 : 0.3; /* water column height [m] */
  wl_sph_config_default(cfg, dim, dp, H);
  if (o->assess_numerics) {
    wl_plan_default_numerics(&cfg->prm);
    cfg->prm.expected_speed = 2.0 * sqrt(cfg->prm.g * H); /* Ritter's front: c0 by the Mach rule */
  }
  if (o->coefh > 0) cfg->prm.coefh = o->coefh;
  cfg->prm.shift_coef = o->shift;
  cfg->prm.boundary = (enum wl_sph_boundary)o->boundary;
  if (o->wall_alpha >= 0) cfg->prm.wall_alpha = o->wall_alpha;
  if (o->coefsound > 0) cfg->prm.coefsound = o->coefsound;
  if (o->limiter >= 0) cfg->prm.wall_limiter = o->limiter;
  cfg->n_threads = o->threads;
  struct wl_sph_const k;
  enum wl_status st = wl_sph_const_make(&cfg->prm, &k, err);
  if (st) return st;
  const int layers = o->layers > 0 ? o->layers : (int)ceil(2.0 * k.h_d / dp - 1e-9);
  const double margin = (layers + 2) * dp;
  struct wl_scene sc;
  if (dim == 2) {
    const double A = 1, L = 4;
    cfg->lo[0] = -margin;
    cfg->hi[0] = L + margin;
    cfg->lo[1] = -margin;
    cfg->hi[1] = 6 * H; /* room above the walls (3 H) for the jet up the far wall */
    wl_scene_init(&sc, &k, 0, 0);
    const double tx[4] = {0, 0, L, L}, tz[4] = {3 * H, 0, 0, 3 * H};
    const double lo[2] = {0, 0}, hi[2] = {A, H};
    st = wl_scene_boundary_polyline(&sc, tx, tz, 4, layers, WL_KIND_FIXED, 0, cfg, err);
    if (!st) st = wl_scene_fluid_block(&sc, lo, hi, H, err);
  } else {
    const double tlo[3] = {0, 0, 0}, thi[3] = {1.6, 0.67, 0.4};
    const double flo[3] = {0, 0, 0}, fhi[3] = {0.4, 0.67, H};
    const double plo[3] = {0.9, 0.24, 0}, phi[3] = {1.02, 0.36, 0.4};
    for (int a = 0; a < 3; a++) {
      cfg->lo[a] = tlo[a] - margin;
      cfg->hi[a] = thi[a] + margin;
    }
    cfg->hi[2] = 1.0; /* room above the tank for splashes */
    wl_scene_init(&sc, &k, tlo[1], thi[1]);
    st = wl_scene_box3d_tank(&sc, tlo, thi, layers, cfg, err);
    if (!st) st = wl_scene_box3d_solid(&sc, plo, phi, layers, 1, err);
    if (!st) st = wl_scene_fluid_block(&sc, flo, fhi, H, err);
  }
  if (!st) st = wl_scene_build(&sc, p, err);
  wl_scene_clear(&sc);
  return st;
}

/* Spacing for about `target` particles: from the fluid volume first, then
 * corrected once by the count of a trial build (boundary particles scale
 * as dp^-(dim-1), fluid as dp^-dim; the correction assumes all scale as the
 * fluid, close enough at these sizes). */
static enum wl_status choose_dp(const struct bench_opts *o, int dim, double target, double *dp,
                                struct wl_error *err) {
  const double vol = dim == 2 ? 1.0 * 2.0 : 0.4 * 0.67 * 0.3;
  double d = pow(vol / target, 1.0 / dim);
  for (int it = 0; it < 2; it++) {
    struct wl_sph_config cfg;
    struct wl_particles p = {0};
    enum wl_status st = build_case(o, dim, d, &cfg, &p, err);
    if (st) return st;
    const double n = p.n;
    wl_particles_clear(&p);
    d *= pow(n / target, 1.0 / dim);
  }
  *dp = d;
  return WL_OK;
}

static enum wl_status run_one(const struct bench_opts *o, int dim, double dp,
                              const struct wl_backend_ops *ops, struct wl_error *err) {
  struct wl_sph_config cfg;
  struct wl_particles init = {0};
  enum wl_status st = build_case(o, dim, dp, &cfg, &init, err);
  if (st) return st;
  const int n = init.n, nb = init.n_bound;
  const int gpu = !strcmp(ops->name, "cuda");
  struct wl_cuda_device d0, d1;
  if (gpu && (st = wl_cuda_device_query(&d0, err))) {
    wl_particles_clear(&init);
    return st;
  }
  struct wl_sph_sim *sim = NULL;
  st = wl_sph_sim_alloc(&sim, ops, &cfg, &init, err);
  wl_particles_clear(&init);
  if (st) return st;
  double bytes = (double)wl_sph_memory_bytes(&cfg, n);
  if (gpu && (st = wl_cuda_device_query(&d1, err)) == WL_OK)
    bytes = (double)d0.memory_free - (double)d1.memory_free;
  char what[512];
  wl_sph_sim_describe(sim, what, sizeof what);
  for (int s = 0; s < WARMUP_STEPS && !st; s++) st = wl_sph_sim_step(sim, 0, err);
  const double t0 = now_s();
  const long step0 = wl_sph_sim_steps(sim);
  struct wl_error run_err;
  wl_error_clear(&run_err);
  enum wl_status run_st = WL_OK;
  if (!st && o->until > 0) {
    while (!run_st && wl_sph_sim_time(sim) < o->until)
      run_st = wl_sph_sim_step(sim, o->until - wl_sph_sim_time(sim), &run_err);
  } else {
    for (long s = 0; s < o->steps && !st; s++) st = wl_sph_sim_step(sim, 0, err);
  }
  const double sec = now_s() - t0;
  const long steps = wl_sph_sim_steps(sim) - step0;
  const long limited = wl_sph_sim_limited(sim), excluded = wl_sph_sim_excluded(sim);
  const double t_sim = wl_sph_sim_time(sim), dt = wl_sph_sim_dt(sim);
  const struct wl_sph_const *k = wl_sph_sim_const(sim);
  const double h_dp = k->h_d / k->dp;
  const int evals = k->integrator == WL_SPH_VERLET ? 1 : 2;
  char k_desc[160];
  snprintf(k_desc, sizeof k_desc, "c0 %.3g m/s, %s viscosity, wall alpha %.3g, limiter %s",
           k->c0_d, k->visc == WL_SPH_VISC_LAMINAR ? "laminar" : "artificial",
           k->visc == WL_SPH_VISC_LAMINAR ? (double)k->av_fb / (k->c0_d * k->h_d) : 0.0,
           k->wall_limiter ? "on" : "off");
  const int dbc = k->boundary == WL_SPH_BOUND_DBC;
  wl_sph_sim_free(sim);
  if (st) return st;
  if (run_st && run_st != WL_EUNSTABLE) return wl_error_set(err, run_st, "%s", run_err.msg);
  const double ps = (double)n * (double)steps / sec;
  printf("%-10s %-5s %10d %6ld %12.4e %9.3f %12.4e %12.4e  Wendland %.2f %8.1f\n",
         dim == 2 ? "dambreak2d" : "dambreak3d", ops->name, n, steps,
         (double)evals * n * (double)steps, sec, ps, evals * ps, h_dp, bytes / n);
  printf("    dp %.5g m, %d boundary + %d fluid, %s walls, simulated %.4g s, dt %.3g s%s; %s\n",
         dp, nb, n - nb, dbc ? "dbc" : "adami", t_sim, dt,
         o->shift > 0 ? ", particle shifting on" : "", what);
  if (o->until > 0)
    printf("    %s; wall limiter: %ld corrections; %ld fluid particles left the domain; %s\n",
           run_st ? run_err.msg : "stable to the end time", limited, excluded, k_desc);
  fflush(stdout);
  return WL_OK;
}

static enum wl_status parse(int argc, char **argv, struct bench_opts *o, struct wl_error *err) {
  memset(o, 0, sizeof *o);
  o->particles = 1e5;
  o->steps = 50;
  o->boundary = WL_SPH_BOUND_ADAMI;
  o->wall_alpha = -1;
  o->limiter = -1;
  const char *cases = "all", *backend = "all";
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "-h") || !strcmp(a, "--help"))
      return wl_error_set(err, WL_EUSAGE,
                          "usage: wallload bench [--case dambreak2d|dambreak3d|all] [--backend "
                          "cpu|cuda|all] [--particles N] [--steps N] [--until T] [--coefh C] "
                          "[--shifting A] [--threads N] [--boundary adami|dbc] [--layers N] "
                          "[--numerics dualsphysics|assess] [--wall-alpha A] [--limiter on|off] "
                          "[--coefsound C]");
    if (i + 1 >= argc) return wl_error_set(err, WL_EUSAGE, "bench: %s needs a value", a);
    const char *v = argv[++i];
    char *end;
    if (!strcmp(a, "--case")) {
      cases = v;
    } else if (!strcmp(a, "--backend")) {
      backend = v;
    } else if (!strcmp(a, "--particles")) {
      o->particles = strtod(v, &end);
      if (*end || !(o->particles >= 100 && o->particles <= 1e9))
        return wl_error_set(err, WL_EUSAGE, "bench: --particles: found '%s'; expected 100 to 1e9", v);
    } else if (!strcmp(a, "--steps")) {
      const double s = strtod(v, &end);
      if (*end || !(s >= 1 && s <= 1e9))
        return wl_error_set(err, WL_EUSAGE, "bench: --steps: found '%s'; expected 1 to 1e9", v);
      o->steps = (long)s;
    } else if (!strcmp(a, "--coefh")) {
      o->coefh = strtod(v, &end);
      if (*end || !(o->coefh >= WL_SPH_COEFH_MIN && o->coefh <= WL_SPH_COEFH_MAX))
        return wl_error_set(err, WL_EUSAGE, "bench: --coefh: found '%s'; expected %g to %g (h = "
                            "coefh sqrt(dim) dp)", v, WL_SPH_COEFH_MIN, WL_SPH_COEFH_MAX);
    } else if (!strcmp(a, "--shifting")) {
      o->shift = strtod(v, &end);
      if (*end || !(o->shift >= 0 && o->shift <= 10))
        return wl_error_set(err, WL_EUSAGE, "bench: --shifting: found '%s'; expected 0 (off) to "
                            "10 (the coefficient A; 2 as DualSPHysics)", v);
    } else if (!strcmp(a, "--threads")) {
      const long t = strtol(v, &end, 10);
      if (*end || t < 1 || t > 4096)
        return wl_error_set(err, WL_EUSAGE, "bench: --threads: found '%s'; expected 1 to 4096", v);
      o->threads = (int)t;
    } else if (!strcmp(a, "--boundary")) {
      if (!strcmp(v, "adami")) o->boundary = WL_SPH_BOUND_ADAMI;
      else if (!strcmp(v, "dbc")) o->boundary = WL_SPH_BOUND_DBC;
      else
        return wl_error_set(err, WL_EUSAGE, "bench: --boundary: found '%s'; valid: adami, dbc", v);
    } else if (!strcmp(a, "--numerics")) {
      if (!strcmp(v, "dualsphysics")) o->assess_numerics = 0;
      else if (!strcmp(v, "assess")) o->assess_numerics = 1;
      else
        return wl_error_set(err, WL_EUSAGE, "bench: --numerics: found '%s'; valid: dualsphysics, "
                            "assess", v);
    } else if (!strcmp(a, "--layers")) {
      const long l = strtol(v, &end, 10);
      if (*end || l < 1 || l > 8)
        return wl_error_set(err, WL_EUSAGE, "bench: --layers: found '%s'; expected 1 to 8", v);
      o->layers = (int)l;
    } else if (!strcmp(a, "--wall-alpha")) {
      o->wall_alpha = strtod(v, &end);
      if (*end || !(o->wall_alpha >= 0 && o->wall_alpha <= 1))
        return wl_error_set(err, WL_EUSAGE, "bench: --wall-alpha: found '%s'; expected 0 to 1", v);
    } else if (!strcmp(a, "--coefsound")) {
      o->coefsound = strtod(v, &end);
      if (*end || !(o->coefsound >= WL_SPH_COEFSOUND_MIN && o->coefsound <= WL_SPH_COEFSOUND_MAX))
        return wl_error_set(err, WL_EUSAGE, "bench: --coefsound: found '%s'; expected %g to %g", v,
                            WL_SPH_COEFSOUND_MIN, WL_SPH_COEFSOUND_MAX);
    } else if (!strcmp(a, "--limiter")) {
      if (!strcmp(v, "on")) o->limiter = 1;
      else if (!strcmp(v, "off")) o->limiter = 0;
      else return wl_error_set(err, WL_EUSAGE, "bench: --limiter: found '%s'; valid: on, off", v);
    } else if (!strcmp(a, "--until")) {
      o->until = strtod(v, &end);
      if (*end || !(o->until > 0 && o->until <= 100))
        return wl_error_set(err, WL_EUSAGE, "bench: --until: found '%s'; expected a simulated "
                            "time in (0, 100] s", v);
    } else {
      return wl_error_set(err, WL_EUSAGE,
                          "bench: unknown option '%s'; valid: --case, --backend, --particles, "
                          "--steps, --until, --coefh, --shifting, --threads, --boundary, "
                          "--layers, --numerics, --wall-alpha, --limiter, --coefsound", a);
    }
  }
  if (!strcmp(cases, "all")) o->case2d = o->case3d = 1;
  else if (!strcmp(cases, "dambreak2d")) o->case2d = 1;
  else if (!strcmp(cases, "dambreak3d")) o->case3d = 1;
  else
    return wl_error_set(err, WL_EUSAGE, "bench: --case: found '%s'; valid: dambreak2d, dambreak3d, all",
                        cases);
  if (!strcmp(backend, "all") || !strcmp(backend, "auto")) {
    o->cpu = 1;
    o->cuda = 2; /* when a GPU is there */
  } else if (!strcmp(backend, "cpu")) {
    o->cpu = 1;
  } else if (!strcmp(backend, "cuda")) {
    o->cuda = 1;
  } else {
    return wl_error_set(err, WL_EUSAGE, "bench: --backend: found '%s'; valid: cpu, cuda, all", backend);
  }
  return WL_OK;
}

enum wl_status wl_cli_bench(int argc, char **argv, struct wl_error *err) {
  struct bench_opts o;
  enum wl_status st = parse(argc, argv, &o, err);
  if (st) return st;
  struct wl_cuda_device dev;
  struct wl_error qerr;
  wl_error_clear(&qerr);
  const int have_gpu = wl_cuda_device_query(&dev, &qerr) == WL_OK;
  if (o.cuda == 1 && !have_gpu) return wl_error_set(err, WL_EUNSUPPORTED, "bench: %s", qerr.msg);
  if (o.cuda == 2 && !have_gpu) printf("# no GPU: %s\n", qerr.msg);
  if (have_gpu)
    printf("# GPU: %s, %.1f GiB, sm_%d%d, %d SMs\n", dev.name, dev.memory_total / 1073741824.0,
           dev.sm_major, dev.sm_minor, dev.n_sm);
  printf("# warm-up %d steps, then %ld timed steps; force evaluations = particles x 2 x steps "
         "(symplectic)\n", WARMUP_STEPS, o.steps);
  printf("%-10s %-5s %10s %6s %12s %9s %12s %12s  %-13s %8s\n", "case", "back", "particles",
         "steps", "force-evals", "seconds", "p-steps/s", "f-evals/s", "kernel h/dp", "B/part");
  for (int dim = 2; dim <= 3; dim++) {
    if ((dim == 2 && !o.case2d) || (dim == 3 && !o.case3d)) continue;
    double dp;
    if ((st = choose_dp(&o, dim, o.particles, &dp, err))) return st;
    if (o.cpu && (st = run_one(&o, dim, dp, &wl_backend_cpu_ops, err))) return st;
    if (o.cuda && have_gpu && (st = run_one(&o, dim, dp, &wl_backend_cuda_ops, err))) return st;
  }
  return WL_OK;
}
