/* test_cuda_backend.c: the CUDA backend against the CPU backend (reference:
 * the CPU backend, itself tested against brute force and closed forms) on a
 * small 2D dam break, a small 3D dam break with a pillar, and the same 3D
 * dam break between free-slip side walls (the solver's mirror planes), the
 * 2D and the free-slip 3D dam breaks with particle shifting, and
 * the 2D and the free-slip 3D dam breaks with the Verlet integrator, with
 * the residual viscosity and with the eddy viscosity (sph/vgrad.h; the eddy
 * cases added 2026-11-28 without a GPU to run them: their first run is the
 * next session's), the
 * 2D dam break with the split and the fast force loops and the free-slip
 * 3D one with the fast loop (the loops that are not their dimension's
 * default; fast is 2D's above WL_LANES_MAX_PARTICLES), and each run's GPU
 * force loop (by default lanes in 2D, split in 3D) against the reference
 * loop (the shared wl_sph_gather, one thread per particle). Then the 2D
 * dam break on the GPU through the backend's blocks of steps (backend.h
 * run) against step by step: the same bits, also where a guard stops it
 * (blocks_vs_steps). The
 * product builds only its own loop per dimension; the others come from the
 * tests' build of cuda.cu (WL_CUDA_TEST_LOOPS, tests/CMakeLists.txt), one
 * backend table per loop. A build of this program without that library
 * (bench/gpu.sh builds it by hand) checks the product against the CPU
 * only. Each run also compares the wall load (backend.h wall_load: the
 * force of the fluid on the tank's left wall, which holds the water column,
 * and its moment) of the GPU with the CPU's. Skipped (77) without a GPU; in
 * a build without CUDA it checks that the backend says so.
 *
 * The GPU's square root and reciprocal of the pair loops (sph/defs.h) are
 * first checked against its correctly rounded sqrtf and 1/x on every float
 * of their ranges (bit for bit).
 *
 * Why the backends are not bit-identical. They evaluate the same shared
 * functions on the same sorted order (both sorts are stable by the same
 * keys), but
 *  - the square root differs: the CPU uses a Newton iteration (sph/defs.h,
 *    within a few ulp), the GPU a correctly rounded one;
 *  - nvcc contracts a*b + c into fused multiply-adds (one rounding instead
 *    of two); the CPU build is ISO C without contraction.
 * Both are float rounding (relative 6e-8 per operation). A force is a sum
 * of 20 (2D) to 150 (3D) pair terms and the Tait pressure raises density
 * differences to the 7th power, so a force evaluation differs by about
 * 1e-6 relative; a dam break is chaotic (free surface, impacts), so the
 * differences grow step by step. The tolerances below are therefore tight
 * after one step and looser after a few hundred, each stated with the
 * scale it is relative to. Both runs use the same fixed step (half the
 * first CFL step), so they reach the same times. Measured on an H100
 * (2026-11-23): after 300 (2D) and 100 (3D) steps max |dx| 3e-6 and 9e-7
 * dp, rms |dv| 3e-6 and 1e-6 of max |v|, max |drho| 3e-7 rho0, kinetic
 * energy 1e-6 relative; the tolerances leave a factor of about 100 for
 * other compilers and GPUs. With the mirror planes (2026-11-23, H100) the
 * GPU against the CPU is as close (|dx|max 9e-7 dp, KE 9e-7). The 3D
 * default loop (split, 2026-11-24) sums each particle's terms in runs and
 * takes positions as float offsets (cuda.cu), so against the reference
 * loop it differs by rounding, as the CPU does: after 100 steps |dx|max
 * 1.3e-6 dp, KE 1e-7. The 2D default (lanes, 2026-11-26: four threads
 * per particle, each a share of every row, their sums added) likewise:
 * 5e-6 dp, KE 1.3e-6 after 300 steps on an H200. With
 * particle shifting (same day) GPU against CPU: 2D |dx|max 3.6e-6 dp,
 * kinetic energy 2.1e-6; 3D between free-slip walls 6.6e-7 dp, 8.8e-7. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dam_tanks.h"
#include "testutil.h"
#include "wallload/backend.h"
#include "wallload/config.h"
#include "wallload/cuda_device.h"
#include "wallload/scene.h"
#include "wallload/sph.h"

#ifndef WL_TEST_CUDA_LOOPS
#define WL_TEST_CUDA_LOOPS 0
#endif
#if WL_TEST_CUDA_LOOPS
/* The tests' build of cuda.cu: one backend per force loop. */
extern const struct wl_backend_ops wl_backend_cuda_ref_ops, wl_backend_cuda_fast_ops,
    wl_backend_cuda_split_ops;
#endif

/* Body tag of the tanks' left wall, whose load the backends compare. */
#define BODY_WALL 2

/* After one step: velocity differences relative to the largest velocity,
 * density differences relative to rho0 (a few float roundings). */
#define TOL_STEP1_VEL 1e-4
#define TOL_STEP1_RHO 1e-6
/* After the run: positions in units of dp, velocities relative to the
 * largest velocity (RMS over particles), densities relative to rho0 (max),
 * kinetic energy relative (at every sample). */
#define TOL_RUN_POS 1e-3
#define TOL_RUN_VEL_RMS 1e-4
#define TOL_RUN_RHO 1e-5
#define TOL_RUN_KE 1e-4
/* The wall load (force and moment on the left wall), relative: on the
 * initial state the same pair terms summed in another order with fused
 * multiply-adds (float rounding of each pair); after the run it follows
 * the pressures at the wall, whose densities may differ by TOL_RUN_RHO
 * rho0, i.e. by c0^2 TOL_RUN_RHO rho0 in pressure, against the column's
 * mean hydrostatic pressure rho0 g H / 2; with c0 = 10 sqrt(g H)
 * (coefsound 10) that is 200 TOL_RUN_RHO. Measured on an H100
 * (2026-11-26): 2e-7 to 8e-7 initially, at most 6.5e-4 over a run (the
 * 2D Verlet case). */
#define TOL_LOAD_INITIAL 1e-5
#define TOL_RUN_LOAD (200 * TOL_RUN_RHO)

struct scene_case {
  int dim;
  double dp;
  long steps;
  const char *name;
  int mirror; /* 3D: free-slip side walls as mirror planes (both y faces) */
  int shift;  /* particle shifting on (sph/shift.h, A = 2) */
  int verlet; /* the Verlet integrator (sph/integrate.h) instead of the symplectic one */
  const char *loop; /* the GPU force loop, "split" or "fast"; NULL: the product's */
  double residual;  /* residual viscosity alpha_r (sph/vgrad.h); 0: off */
  double smagorinsky; /* the eddy viscosity's C_s (sph/vgrad.h), with laminar viscosity; 0: off */
};

static enum wl_status build(const struct scene_case *sc_, struct wl_sph_config *cfg,
                            struct wl_particles *p, struct wl_error *err) {
  const enum dam_tank t = sc_->dim == 2 ? DAM_2D : sc_->mirror ? DAM_3D_MIRROR_PILLAR : DAM_3D_BOX_PILLAR;
  wl_sph_config_default(cfg, sc_->dim, sc_->dp, dam_tank_height(t));
  cfg->n_threads = 1;
  if (sc_->shift) cfg->prm.shift_coef = 2.0;
  if (sc_->verlet) cfg->prm.integrator = WL_SPH_VERLET;
  cfg->prm.residual_alpha = sc_->residual;
  if (sc_->smagorinsky > 0) { /* the eddy viscosity adds to the laminar viscosity's nu */
    cfg->prm.visc = WL_SPH_VISC_LAMINAR;
    cfg->prm.nu = 1e-6;
    cfg->prm.smagorinsky = sc_->smagorinsky;
  }
  if (sc_->mirror) {
    cfg->prm.mirror_lo = cfg->prm.mirror_hi = 1;
    cfg->prm.mirror_y_lo = 0.0;
    cfg->prm.mirror_y_hi = DAM_W;
  }
  return dam_tank_build(t, cfg, BODY_WALL, p, err);
}

/* The wall load of sim into f[0] (force) and f[1] (moment about z = 0). */
static enum wl_status load(struct wl_sph_sim *sim, double *f, struct wl_error *err) {
  return wl_sph_sim_wall_load(sim, BODY_WALL, 0.0, &f[0], &f[1], err);
}

/* |a - b| / |b| of the force and the moment, the larger. */
static double load_diff(const double *a, const double *b) {
  return fmax(fabs(a[0] - b[0]) / fabs(b[0]), fabs(a[1] - b[1]) / fabs(b[1]));
}

/* Kinetic energy of the fluid [J or J/m]. */
static double kinetic(const struct wl_particles *p, double mass) {
  double e = 0;
  for (int i = p->n_bound; i < p->n; i++) {
    double v2 = 0;
    for (int a = 0; a < p->dim; a++) v2 += (double)p->vel[a][i] * p->vel[a][i];
    e += 0.5 * mass * v2;
  }
  return e;
}

/* Differences between two states matched by id. */
struct diff {
  int n_missing;   /* ids of a not found in b, or duplicated */
  double pos_max;  /* max |dx| [m] */
  double vel_rms;  /* rms |dv| over fluid [m/s] */
  double vel_max;  /* max |dv| [m/s] */
  double vmax;     /* max |v| of a's fluid [m/s] */
  double rho_max;  /* max |drho| [kg/m^3] */
};

static struct diff compare(const struct wl_particles *a, const struct wl_particles *b) {
  struct diff d = {0, 0, 0, 0, 0, 0};
  const int n = a->n;
  int *where = malloc(sizeof(int) * (size_t)n);
  for (int i = 0; i < n; i++) where[i] = -1;
  for (int i = 0; i < b->n; i++) {
    const unsigned id = b->id[i];
    if (id < (unsigned)n && where[id] < 0) where[id] = i;
    else d.n_missing++;
  }
  double s2 = 0;
  int nf = 0;
  for (int i = 0; i < n; i++) {
    const unsigned id = a->id[i];
    const int j = id < (unsigned)n ? where[id] : -1;
    if (j < 0) {
      d.n_missing++;
      continue;
    }
    double dx2 = 0, dv2 = 0, v2 = 0;
    for (int c = 0; c < a->dim; c++) {
      const double dx = a->pos[c][i] - b->pos[c][j], dv = (double)a->vel[c][i] - b->vel[c][j];
      dx2 += dx * dx;
      dv2 += dv * dv;
      v2 += (double)a->vel[c][i] * a->vel[c][i];
    }
    d.pos_max = fmax(d.pos_max, sqrt(dx2));
    d.rho_max = fmax(d.rho_max, fabs((double)a->rho[i] - b->rho[j]));
    if (a->kind[i] == WL_KIND_FLUID) {
      s2 += dv2;
      nf++;
      d.vel_max = fmax(d.vel_max, sqrt(dv2));
      d.vmax = fmax(d.vmax, sqrt(v2));
    }
  }
  d.vel_rms = nf ? sqrt(s2 / nf) : 0;
  free(where);
  return d;
}

/* Run the case on the CPU and on the GPU (both force loops) in lockstep. */
static void run_case(const struct scene_case *c) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  struct wl_particles init = {0};
  if (build(c, &cfg, &init, &err) != WL_OK) {
    printf("FAIL %s: build: %s\n", c->name, err.msg);
    wl_test_failures++;
    return;
  }
  printf("# %s: %d particles (%d boundary), dp %g m, %ld steps\n", c->name, init.n, init.n_bound,
         c->dp, c->steps);
  struct wl_sph_sim *cpu = NULL, *gpu = NULL, *ref = NULL;
  const struct wl_backend_ops *ops = &wl_backend_cuda_ops, *ref_ops = NULL;
#if WL_TEST_CUDA_LOOPS
  if (c->loop) ops = !strcmp(c->loop, "split") ? &wl_backend_cuda_split_ops : &wl_backend_cuda_fast_ops;
  ref_ops = &wl_backend_cuda_ref_ops;
#else
  if (c->loop) {
    printf("SKIP %s: the %s loop is built in the tests' build of cuda.cu only\n", c->name, c->loop);
    wl_particles_clear(&init);
    return;
  }
#endif
  enum wl_status st = wl_sph_sim_alloc(&cpu, &wl_backend_cpu_ops, &cfg, &init, &err);
  if (!st) st = wl_sph_sim_alloc(&gpu, ops, &cfg, &init, &err);
  if (!st && ref_ops) st = wl_sph_sim_alloc(&ref, ref_ops, &cfg, &init, &err);
  const int n = init.n;
  const double mass = wl_sph_sim_const(cpu ? cpu : gpu)->mass;
  wl_particles_clear(&init);
  CHECK_TRUE(st == WL_OK, ref_ops ? "three simulations set up (cpu, cuda force loop under test, "
                                     "cuda reference loop)"
                                   : "two simulations set up (cpu, cuda)");
  if (st) {
    printf("  %s\n", err.msg);
    wl_sph_sim_free(cpu);
    wl_sph_sim_free(gpu);
    wl_sph_sim_free(ref);
    return;
  }
  char what[512];
  wl_sph_sim_describe(gpu, what, sizeof what);
  printf("# %s\n", what);
  /* initial force evaluation: max |a| and the first dt */
  const struct wl_sph_step_out *oc = wl_sph_sim_last(cpu), *og = wl_sph_sim_last(gpu),
                               *orf = ref ? wl_sph_sim_last(ref) : NULL;
  CHECK_REL(og->ace_max, oc->ace_max, 1e-4, "initial max |a|: GPU vs CPU (float rounding)");
  if (ref) CHECK_REL(orf->ace_max, oc->ace_max, 1e-4, "initial max |a|: GPU reference loop vs CPU");
  CHECK_REL(wl_sph_sim_dt_initial(gpu), wl_sph_sim_dt_initial(cpu), 1e-4, "first CFL step");
  {
    double lc[2], lg[2];
    st = load(cpu, lc, &err);
    if (!st) st = load(gpu, lg, &err);
    CHECK_TRUE(st == WL_OK && lc[0] < 0, "initial wall load computed on both backends (the column "
               "pushes the left wall towards -x)");
    if (!st) {
      printf("# initial wall load: CPU %.9g N(/m), %.9g N m(/m); GPU - CPU %.3g relative\n", lc[0],
             lc[1], load_diff(lg, lc));
      CHECK_ABS(load_diff(lg, lc), 0, TOL_LOAD_INITIAL,
                "initial wall force and moment: GPU vs CPU (float rounding)");
    }
  }
  const double dt = 0.5 * wl_sph_sim_dt_initial(cpu);
  double ke_err = 0, ke_ref_err = 0, ke_last = 0, load_err = 0;
  int failed = 0;
  for (long s = 0; s < c->steps && !failed; s++) {
    if ((st = wl_sph_sim_step(cpu, dt, &err)) || (st = wl_sph_sim_step(gpu, dt, &err)) ||
        (ref && (st = wl_sph_sim_step(ref, dt, &err)))) {
      failed = 1;
      break;
    }
    if (s == 0 || s % 10 == 9 || s == c->steps - 1) {
      const struct wl_particles *pc = wl_sph_sim_particles(cpu, &err);
      const struct wl_particles *pg = wl_sph_sim_particles(gpu, &err);
      const struct wl_particles *pr = ref ? wl_sph_sim_particles(ref, &err) : pg;
      if (!pc || !pg || !pr) {
        failed = 1;
        break;
      }
      const double kc = kinetic(pc, mass), kg = kinetic(pg, mass), kr = kinetic(pr, mass);
      /* the wall load after the downloads (it re-sorts the backend's
       * particles; the host copies stay valid) */
      double lc[2], lg[2];
      if (load(cpu, lc, &err) || load(gpu, lg, &err)) {
        failed = 1;
        break;
      }
      load_err = fmax(load_err, load_diff(lg, lc));
      if (kc > 0) {
        ke_err = fmax(ke_err, fabs(kg - kc) / kc);
        ke_ref_err = fmax(ke_ref_err, fabs(kr - kg) / kc);
      }
      ke_last = kc;
      if (s == 0) {
        const struct diff d = compare(pc, pg);
        printf("# after 1 step: |dv|max %.3g m/s of |v|max %.3g, |drho|max %.3g kg/m^3, |dx|max "
               "%.3g m\n", d.vel_max, d.vmax, d.rho_max, d.pos_max);
        CHECK_TRUE(d.n_missing == 0, "step 1: every particle id once on both backends");
        CHECK_ABS(d.vel_max / d.vmax, 0, TOL_STEP1_VEL, "step 1: max |dv| / max |v|, GPU vs CPU");
        CHECK_ABS(d.rho_max / 1000.0, 0, TOL_STEP1_RHO, "step 1: max |drho| / rho0, GPU vs CPU");
      }
    }
  }
  CHECK_TRUE(!failed, "both backends ran every step (no instability, no error)");
  if (failed) printf("  %s\n", err.msg);
  if (!failed) {
    const struct wl_particles *pc = wl_sph_sim_particles(cpu, &err);
    const struct wl_particles *pg = wl_sph_sim_particles(gpu, &err);
    const struct wl_particles *pr = ref ? wl_sph_sim_particles(ref, &err) : pg;
    const struct diff d = compare(pc, pg), dr = compare(pg, pr);
    printf("# after %ld steps (t = %.4g s): |dx|max %.3g dp, |dv|rms %.3g and max %.3g m/s of "
           "|v|max %.3g, |drho|max %.3g kg/m^3, KE %.6g (rel. diff max %.3g; GPU loop vs reference "
           "loop %.3g)\n", c->steps, wl_sph_sim_time(cpu), d.pos_max / c->dp, d.vel_rms,
           d.vel_max, d.vmax, d.rho_max, ke_last, ke_err, ke_ref_err);
    printf("# GPU loop vs reference loop: |dx|max %.3g dp, |dv|max %.3g m/s, |drho|max %.3g\n",
           dr.pos_max / c->dp, dr.vel_max, dr.rho_max);
    CHECK_TRUE(pc->n == n && pg->n == n && pr->n == n, "same particle count on every backend");
    CHECK_TRUE(d.n_missing == 0 && dr.n_missing == 0, "no lost or duplicated particle ids");
    CHECK_ABS(d.pos_max / c->dp, 0, TOL_RUN_POS, "max |dx| / dp, GPU vs CPU");
    CHECK_ABS(d.vel_rms / d.vmax, 0, TOL_RUN_VEL_RMS, "rms |dv| / max |v|, GPU vs CPU");
    CHECK_ABS(d.rho_max / 1000.0, 0, TOL_RUN_RHO, "max |drho| / rho0, GPU vs CPU");
    CHECK_ABS(ke_err, 0, TOL_RUN_KE, "kinetic energy history, max relative difference GPU vs CPU");
    printf("# wall load history: max relative difference GPU vs CPU %.3g\n", load_err);
    CHECK_ABS(load_err, 0, TOL_RUN_LOAD, "wall force and moment history, max relative difference "
              "GPU vs CPU");
    if (ref) {
      CHECK_ABS(dr.pos_max / c->dp, 0, TOL_RUN_POS, "max |dx| / dp, GPU loop vs reference loop");
      CHECK_ABS(ke_ref_err, 0, TOL_RUN_KE, "kinetic energy history, GPU loop vs reference loop");
    }
  }
  wl_sph_sim_free(cpu);
  wl_sph_sim_free(gpu);
  wl_sph_sim_free(ref);
}

/* What a run's outputs saw (blocks against steps). */
struct outs {
  int n;
  double t[256], force[256];
  long steps[256];
  double state[256]; /* the downloaded state, summed in its order */
};

/* The host's state at an output (the blocks' runs read it from a snapshot
 * taken while the next block runs, backend.h snapshot), then the wall load,
 * as assess's output does. */
static enum wl_status on_out(void *user, struct wl_sph_sim *sim, double t, struct wl_error *err) {
  struct outs *o = user;
  if (o->n >= 256) return WL_OK;
  const struct wl_particles *p = wl_sph_sim_particles(sim, err);
  if (!p) return err->status ? err->status : WL_EIO;
  double sum = 0;
  for (int i = 0; i < p->n; i++)
    sum = sum * 0.5 + p->pos[0][i] + p->pos[1][i] + p->vel[0][i] + p->rho[i] + p->id[i] + p->body[i];
  o->state[o->n] = sum;
  double f[2];
  const enum wl_status st = load(sim, f, err);
  if (st) return st;
  o->t[o->n] = t;
  o->force[o->n] = f[0];
  o->steps[o->n++] = wl_sph_sim_steps(sim);
  return WL_OK;
}

/* The same run through the backend's blocks of steps (backend.h run: the
 * steps chosen, counted and guarded on the device, one record a block)
 * and step by step (run = NULL: the host's loop), to the same end: the
 * same steps, output times, states and wall loads at the outputs (the
 * blocks' from snapshots beside the next block) and final state, bit for
 * bit, and for a run that stops (guard: a density range it leaves; dt collapse:
 * a floor it falls under) the same message, naming the same step, time
 * and particle. */
static void blocks_vs_steps(const char *name, int verlet, double rho_max_factor,
                            double dt_collapse) {
  struct wl_error err, e1, e2;
  wl_error_clear(&err);
  wl_error_clear(&e1);
  wl_error_clear(&e2);
  const struct scene_case c = {2, 0.01, 0, name, 0, 0, verlet, NULL, 0, 0};
  struct wl_sph_config cfg;
  struct wl_particles init = {0};
  if (build(&c, &cfg, &init, &err) != WL_OK) {
    printf("FAIL %s: build: %s\n", name, err.msg);
    wl_test_failures++;
    return;
  }
  if (rho_max_factor > 0) cfg.prm.rho_max_factor = rho_max_factor;
  if (dt_collapse > 0) cfg.prm.dt_collapse = dt_collapse;
  struct wl_backend_ops steps_ops = wl_backend_cuda_ops;
  steps_ops.run = NULL;
  struct wl_sph_sim *a = NULL, *b = NULL;
  enum wl_status st = wl_sph_sim_alloc(&a, &wl_backend_cuda_ops, &cfg, &init, &err);
  if (!st) st = wl_sph_sim_alloc(&b, &steps_ops, &cfg, &init, &err);
  wl_particles_clear(&init);
  CHECK_TRUE(st == WL_OK && wl_backend_cuda_ops.run, "blocks vs steps: two simulations set up");
  if (st || !wl_backend_cuda_ops.run) {
    printf("  %s\n", err.msg);
    wl_sph_sim_free(a);
    wl_sph_sim_free(b);
    return;
  }
  static struct outs oa, ob;
  memset(&oa, 0, sizeof oa);
  memset(&ob, 0, sizeof ob);
  struct wl_sph_run_opts ro = {0};
  ro.t_end = rho_max_factor > 0 ? 0.6 : 0.3; /* the density guard: after the front's impact */
  ro.output_dt = 0.0123; /* not a multiple of the steps: split rests */
  ro.output = on_out;
  ro.user = &oa;
  const enum wl_status sa = wl_sph_sim_run(a, &ro, &e1);
  ro.user = &ob;
  const enum wl_status sb = wl_sph_sim_run(b, &ro, &e2);
  printf("# %s: blocks %ld steps to t = %.9g s (%s), steps %ld to t = %.9g s (%s)\n", name,
         wl_sph_sim_steps(a), wl_sph_sim_time(a), sa ? e1.msg : "ok", wl_sph_sim_steps(b),
         wl_sph_sim_time(b), sb ? e2.msg : "ok");
  char what[160];
  snprintf(what, sizeof what, "%s: the run %s", name,
           rho_max_factor > 0 || dt_collapse > 0 ? "stops as unstable" : "completes");
  CHECK_TRUE(sa == sb && (sa == WL_EUNSTABLE) == (rho_max_factor > 0 || dt_collapse > 0), what);
  snprintf(what, sizeof what, "%s: same status and message, blocks vs steps", name);
  CHECK_TRUE(sa == sb && !strcmp(e1.msg, e2.msg), what);
  snprintf(what, sizeof what, "%s: same steps and time, bit for bit", name);
  CHECK_TRUE(wl_sph_sim_steps(a) == wl_sph_sim_steps(b) &&
             wl_sph_sim_time(a) == wl_sph_sim_time(b) && wl_sph_sim_dt(a) == wl_sph_sim_dt(b) &&
             wl_sph_sim_excluded(a) == wl_sph_sim_excluded(b) &&
             wl_sph_sim_limited(a) == wl_sph_sim_limited(b), what);
  snprintf(what, sizeof what, "%s: same outputs (times, steps, state, wall force), bit for bit",
           name);
  CHECK_TRUE(oa.n == ob.n && oa.n > 0 && !memcmp(oa.t, ob.t, sizeof oa.t) &&
             !memcmp(oa.steps, ob.steps, sizeof oa.steps) &&
             !memcmp(oa.state, ob.state, sizeof oa.state) &&
             !memcmp(oa.force, ob.force, sizeof oa.force), what);
  const struct wl_particles *pa = wl_sph_sim_particles(a, &err);
  const struct wl_particles *pb = pa ? wl_sph_sim_particles(b, &err) : NULL;
  int same = pa && pb && pa->n == pb->n;
  for (int d = 0; same && d < 2; d++)
    same = !memcmp(pa->pos[d], pb->pos[d], sizeof(double) * (size_t)pa->n) &&
           !memcmp(pa->vel[d], pb->vel[d], sizeof(wl_real) * (size_t)pa->n);
  same = same && !memcmp(pa->rho, pb->rho, sizeof(wl_real) * (size_t)pa->n) &&
         !memcmp(pa->id, pb->id, sizeof(unsigned int) * (size_t)pa->n);
  snprintf(what, sizeof what, "%s: same final state (order, positions, velocities, densities), "
           "bit for bit", name);
  CHECK_TRUE(same, what);
  wl_sph_sim_free(a);
  wl_sph_sim_free(b);
}

int main(void) {
  struct wl_cuda_device dev;
  struct wl_error err;
  wl_error_clear(&err);
  if (!wl_cuda_built()) {
    /* the stub must say so */
    void *ctx = (void *)1;
    struct wl_sph_config cfg;
    wl_sph_config_default(&cfg, 2, 0.01, 1);
    struct wl_sph_step_out out;
    const enum wl_status st = wl_backend_cuda_ops.init(&ctx, &cfg, NULL, NULL, &out, &err);
    CHECK_TRUE(st == WL_EUNSUPPORTED && strstr(err.msg, "without CUDA") && ctx == NULL,
               "a build without CUDA answers 'built without CUDA'");
    printf("SKIP: built without CUDA\n");
    return wl_test_failures ? 1 : 77;
  }
  if (wl_cuda_device_query(&dev, &err) != WL_OK) {
    printf("SKIP: %s\n", err.msg);
    return 77;
  }
  printf("# GPU: %s\n", dev.name);
  {
    /* the GPU's square root and reciprocal (sph/defs.h) against its own
     * correctly rounded sqrtf and 1/x, every float of their ranges: they
     * must be the same bits, which is what lets them replace the library
     * calls in the pair loops without changing a result */
    unsigned long long n_sqrt, bad_sqrt, n_rcp, bad_rcp;
    const enum wl_status st = wl_cuda_math_check(&n_sqrt, &bad_sqrt, &n_rcp, &bad_rcp, &err);
    CHECK_TRUE(st == WL_OK, "wl_cuda_math_check runs");
    CHECK_TRUE(n_sqrt > 1800000000ull && n_rcp > 4000000000ull,
               "math check: every float from 2^-100 (sqrt) and every normal float below 2^126 "
               "(reciprocal) tried");
    CHECK_ABS((double)bad_sqrt, 0, 0, "wl_sph_sqrt: floats whose bits differ from sqrtf");
    CHECK_ABS((double)bad_rcp, 0, 0, "wl_sph_rcp: floats whose bits differ from 1/x");
  }
  const struct scene_case c2 = {2, 0.01, 300, "2D dam break", 0, 0, 0, NULL, 0, 0};
  const struct scene_case c3 = {3, 0.01, 100, "3D dam break with pillar", 0, 0, 0, NULL, 0, 0};
  const struct scene_case c3m = {3, 0.01, 100, "3D dam break with pillar, free-slip side walls "
                                 "(mirror planes)", 1, 0, 0, NULL, 0, 0};
  const struct scene_case c2s = {2, 0.01, 300, "2D dam break with particle shifting", 0, 1, 0,
                                 NULL, 0, 0};
  const struct scene_case c3s = {3, 0.01, 100, "3D dam break with pillar between free-slip walls, "
                                 "particle shifting", 1, 1, 0, NULL, 0, 0};
  /* Verlet: 600 steps (15 of them Euler steps), as many force evaluations
   * as the symplectic 2D case's 300 */
  const struct scene_case c2v = {2, 0.01, 600, "2D dam break, Verlet integrator", 0, 0, 1, NULL, 0, 0};
  const struct scene_case c3v = {3, 0.01, 200, "3D dam break with pillar between free-slip walls, "
                                 "Verlet integrator", 1, 0, 1, NULL, 0, 0};
  run_case(&c2);
  run_case(&c3);
  run_case(&c3m);
  run_case(&c2s);
  run_case(&c3s);
  run_case(&c2v);
  run_case(&c3v);
  /* the loops that are not the default of their dimension (the tests'
   * build of cuda.cu) */
  const struct scene_case c2x = {2, 0.01, 300, "2D dam break, split force loop", 0, 0, 0,
                                 "split", 0, 0};
  const struct scene_case c3x = {3, 0.01, 100, "3D dam break with pillar between free-slip walls, "
                                 "fast force loop", 1, 0, 0, "fast", 0, 0};
  /* the 2D loop of runs of WL_LANES_MAX_PARTICLES (cuda.cu) and more */
  const struct scene_case c2f = {2, 0.01, 300, "2D dam break, fast force loop", 0, 0, 0, "fast", 0, 0};
  /* the residual viscosity (sph/vgrad.h): the product picks the fast loop */
  const struct scene_case c2r = {2, 0.01, 300, "2D dam break with the residual viscosity", 0, 0, 0,
                                 NULL, 0.5, 0};
  const struct scene_case c3r = {3, 0.01, 100, "3D dam break with pillar between free-slip walls, "
                                 "residual viscosity", 1, 0, 0, NULL, 0.5, 0};
  run_case(&c2r);
  run_case(&c3r);
  /* the eddy viscosity (sph/vgrad.h): the same gradient pass and loop */
  const struct scene_case c2e = {2, 0.01, 300, "2D dam break with the eddy viscosity", 0, 0, 0,
                                 NULL, 0, 0.12};
  const struct scene_case c3e = {3, 0.01, 100, "3D dam break with pillar between free-slip walls, "
                                 "eddy viscosity", 1, 0, 0, NULL, 0, 0.12};
  run_case(&c2e);
  run_case(&c3e);
  run_case(&c2x);
  run_case(&c3x);
  run_case(&c2f);
  blocks_vs_steps("2D dam break, Verlet, blocks vs steps", 1, 0, 0);
  blocks_vs_steps("2D dam break, symplectic, blocks vs steps", 0, 0, 0);
  blocks_vs_steps("2D dam break, Verlet, density guard", 1, 1.02, 0);
  blocks_vs_steps("2D dam break, Verlet, dt collapse", 1, 0, 0.8);
  return TEST_RESULT();
}
