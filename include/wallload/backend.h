/* backend.h: the interface every SPH backend implements (ggml / SPH-EXA
 * style: a small table of function pointers, each backend in its own
 * directory and library). The driver in src/sph (wl_sph_sim_*) owns the
 * time loop, the motion of paddles, output times and the instability
 * report; a backend owns the particle arrays (host memory or device memory)
 * and runs one symplectic step on them with the shared physics of
 * include/wallload/sph/.
 *
 * Backends: wl_backend_cpu_ops (src/backend_cpu, OpenMP) and
 * wl_backend_cuda_ops (src/backend_cuda) with the same contract. */
#ifndef WALLLOAD_BACKEND_H
#define WALLLOAD_BACKEND_H

#include <math.h>
#include <stddef.h>

#include "wallload/error.h"
#include "wallload/sph/guard.h"
#include "wallload/sph/params.h"
#include "wallload/sph/particles.h"

enum { WL_SPH_WALLS_MAX = 64 };

/* Linear solvers of the ISPH pressure Poisson equation (backend_cpu/isph.c;
 * docs/isph.md says which is chosen and why). */
enum wl_isph_solver {
  WL_ISPH_SOLVER_BICGSTAB = 0, /* BiCGSTAB (van der Vorst 1992) on the Jacobi-scaled CSR: default */
  WL_ISPH_SOLVER_GSL_GMRES = 1 /* GSL's restarted GMRES (gsl_splinalg), same scaled system */
};

/* Options of the incompressible SPH backend (wl_backend_isph_ops); zero
 * means the default of each. The weakly-compressible backends ignore them. */
struct wl_isph_opts {
  enum wl_isph_solver solver;
  double tol;          /* relative residual |b - A p| / |b| of the PPE; 0: 1e-9 */
  int max_iter;        /* 0: 2000 */
  double surface_tfs;  /* div r below which a fluid particle is on the free surface; 0: 1.5 in
                          2D, 2.4 in 3D (Lee et al. 2008) */
  /* The Dirichlet value of a surface particle: 0 puts p = 0 at its centre;
   * 1 (default, -1 to turn off) puts it at the fluid's edge dp/2 outside,
   * p_s = rho0 max(0, -g.n) dp/2 (docs/isph.md, "free surface") */
  int surface_offset;
  /* The density-invariant source (Shao & Lo 2003; Hu & Adams 2007; relaxed
   * as Asai et al. 2012): the PPE's divergence of every interior particle
   * compressed beyond the rest lattice carries -(rho_i/rho_ref - 1)/tau,
   * rho_i its summation density, so a compression relaxes over the time
   * tau [s] whatever the step (0: 4 sqrt(h/g); negative: off).
   * docs/isph.md, "density-invariant correction". */
  double density_tau;
  /* A wall particle with p <= 0 is dry (air to the fluid) unless a fluid
   * particle within its support approaches it faster than this [m/s]
   * (0: 0.1 sqrt(g h); negative: never, stage 1's rule). docs/isph.md. */
  double wet_speed;
  /* Particle shifting (Lind et al. 2012, with the velocity scaling of
   * Skillen et al. 2013, as sph/shift.h): delta r = -A h |u| dt grad C,
   * none at the free surface, ramped in below it; A is this (0 or
   * negative: off, the default: no measured gain yet). docs/isph.md. */
  double shift_coef;
  /* Debug: write the PPE (Matrix Market, rows scaled, and its right-hand
   * side) of step dump_step to dump_path(.mtx, .rhs); NULL: never. */
  const char *dump_path;
  long dump_step;
};

/* What the ISPH backend did in its last step (wl_backend_isph_stats). */
struct wl_isph_stats {
  int iterations;      /* of the PPE solve */
  double residual;     /* its final relative residual */
  long iterations_sum; /* over all steps so far */
  long solves;         /* steps so far */
  int n_surface;       /* fluid particles on the free surface */
  int nnz;             /* nonzeros of the PPE */
  double t_solve, t_total; /* seconds spent in solves and in steps so far */
};

/* Everything a backend needs to set up a run (copied by init). */
struct wl_sph_config {
  struct wl_sph_params prm;            /* physics parameters */
  double lo[WL_SPH_DIM_MAX];           /* domain box, lower corner [m] */
  double hi[WL_SPH_DIM_MAX];           /* domain box, upper corner [m] */
  int n_walls;                         /* wall faces for the penetration guard */
  struct wl_sph_wall walls[WL_SPH_WALLS_MAX];
  int n_threads;                       /* CPU: OpenMP threads, 0 = OpenMP's default */
  struct wl_isph_opts isph;            /* the ISPH backend's options (zero: defaults) */
  int priority;                        /* CUDA: 1 = the run the others beside it wait for
                                          (its stream at the GPU's greatest priority) */
};

/* Input of one step. */
struct wl_sph_step_in {
  double t;   /* time at the step start [s] */
  double dt;  /* step [s] */
  double dt_prev; /* the previous step [s] (0 before the first): the Verlet leapfrog spans
                     dt_prev + dt */
  long step;  /* number of this step (0 = first) */
  /* velocity of each moving body over this step [m/s]; row 0 unused */
  double body_vel[WL_SPH_BODIES_MAX + 1][WL_SPH_DIM_MAX];
  /* acceleration of each moving body at the step start [m/s^2] (the wall
   * condition's inertial term, sph/wall.h); row 0 unused */
  double body_acc[WL_SPH_BODIES_MAX + 1][WL_SPH_DIM_MAX];
};

/* Result of one step (or of the initial force evaluation). */
struct wl_sph_step_out {
  double dt_next;   /* CFL * min(dt_force, dt_cv) [s], for the next step */
  double dt_force;  /* sqrt(h / max|a|) over fluid particles [s] */
  double dt_cv;     /* h / (max(c0, 10 max|v|) + max h|v.r|/(r^2+eta^2)) [s] */
  double ace_max;   /* max |a| of fluid particles, incl. gravity [m/s^2] */
  double vel_max;   /* max |v| of fluid particles [m/s] */
  /* first faulty particle (lowest sorted index) when fault != 0 */
  int fault;        /* enum wl_sph_fault */
  int fault_index;  /* sorted index */
  unsigned int fault_id;
  int fault_kind;
  int fault_wall;   /* for WL_SPH_FAULT_PENETRATION */
  double fault_pos[WL_SPH_DIM_MAX], fault_vel[WL_SPH_DIM_MAX], fault_rho;
  long n_limited;   /* fluid particles the wall limiter moved in this step (sph/guard.h) */
  long n_excluded;  /* fluid particles that left the domain box in this step (sph/guard.h) */
};

/* The next step from the maxima over a step's force evaluations
 * (DualSPHysics DtVariable), for every backend (the CUDA backend's block
 * of steps evaluates it on the device): max |a|^2 and |v|^2 of the fluid
 * particles and max h|v.r|/(r^2 + eta^2) over their pairs; fills dt_next,
 * dt_force, dt_cv, ace_max and vel_max of out. The product stays unfused
 * (WL_DMUL): the host and the device give the same bits. */
WL_HD static inline void wl_sph_step_dt(const struct wl_sph_const *k, double ace2_max,
                                        double vel2_max, double visc_max,
                                        struct wl_sph_step_out *out) {
  const double h = k->h_d, c0 = k->c0_d;
  const double amax = sqrt(ace2_max), vmax = sqrt(vel2_max), v10 = WL_DMUL(10.0, vmax);
  out->ace_max = amax;
  out->vel_max = vmax;
  out->dt_force = amax > 0 ? sqrt(h / amax) : INFINITY;
  out->dt_cv = h / ((c0 > v10 ? c0 : v10) + visc_max);
  out->dt_next = k->cfl * (out->dt_force < out->dt_cv ? out->dt_force : out->dt_cv);
}

/* The driver's rules for the next step, for the host loop (src/sph/sim.c)
 * and a backend that runs a block of steps on its own (run below): */

/* The time-step collapse: the CFL step dt_cfl under dt_collapse of the
 * first one, or not finite. */
WL_HD static inline int wl_sph_dt_collapsed(const struct wl_sph_const *k, double dt_cfl,
                                            double dt_initial) {
  return !(dt_cfl >= k->dt_collapse * dt_initial) || !isfinite(dt_cfl);
}

/* The limit on the step toward an output time `rest` [s] ahead (> 0), with
 * the CFL step dt: the step that lands on it when the rest fits in one
 * (*lands = 1), half the rest when it fits in two (so no step is shorter
 * than half the CFL step), else 0 (no limit). */
WL_HD static inline double wl_sph_dt_toward(double rest, double dt, int *lands) {
  *lands = rest <= dt;
  return rest <= dt ? rest : rest < 2 * dt ? 0.5 * rest : 0.0;
}

/* The step taken: the CFL step dt_cfl, or dt_max when it is shorter (dt_max
 * <= 0: no limit). */
WL_HD static inline double wl_sph_dt_limit(double dt_max, double dt_cfl) {
  return dt_max > 0 && dt_max < dt_cfl ? dt_max : dt_cfl;
}

/* Fluid particles that left the domain box so far (n_excluded of n_fluid):
 * a few splash particles over the walls are DualSPHysics' "excluded"
 * particles; more than WL_SPH_EXCLUDED_MAX of the fluid is a failed run. */
#define WL_SPH_EXCLUDED_MAX 0.01
WL_HD static inline int wl_sph_excluded_too_many(long n_excluded, long n_fluid) {
  return n_excluded > WL_SPH_EXCLUDED_MAX * (double)n_fluid;
}

/* Input of a block of steps (run below): the driver's state at its start. */
struct wl_sph_block_in {
  double t;          /* time now [s] */
  double t_out;      /* the next output time [s], > t: the block stops on it */
  double dt_next;    /* the CFL step from the last force evaluations [s] */
  double dt_last;    /* the last step taken [s] (0 before the first) */
  double dt_initial; /* the first CFL step (the collapse guard's reference) [s] */
  long step;         /* steps taken so far */
  long max_steps;    /* at most this many steps (>= 1) */
  long n_excluded;   /* fluid particles excluded so far (the guard on their share) */
  long n_fluid;      /* fluid particles of the run */
};

/* Why a block stopped. */
enum wl_sph_block_stop {
  WL_SPH_BLOCK_COUNT = 0,    /* max_steps taken */
  WL_SPH_BLOCK_LANDED = 1,   /* its last step landed on t_out (t = t_out exactly) */
  WL_SPH_BLOCK_REACHED = 2,  /* t reached t_out by rounding, without landing */
  WL_SPH_BLOCK_FAULT = 3,    /* the guard found a fault in its last step (last.fault) */
  WL_SPH_BLOCK_COLLAPSE = 4, /* the next step would have collapsed (wl_sph_dt_collapsed) */
  WL_SPH_BLOCK_EXCLUDED = 5  /* too many fluid particles left the box (wl_sph_excluded_too_many) */
};

/* Result of a block: the driver's state after it. */
struct wl_sph_block_out {
  int stop;          /* enum wl_sph_block_stop */
  long steps;        /* steps taken in the block */
  double t;          /* time after the last step [s] (t_out when landed) */
  double dt_next;    /* the CFL step for the next step [s] */
  double dt_last;    /* the last step taken [s] */
  long n_limited;    /* wall-limiter corrections over the block */
  long n_excluded;   /* fluid particles excluded over the block */
  struct wl_sph_step_out last; /* the last step's out (its fault when stop is FAULT) */
};

/* What every backend's init checks of the host particles it is given
 * (backend: its name, for the message): their dimension is the
 * configuration's; boundary particles first, then fluid; kinds fluid,
 * fixed or moving; a moving particle's body 1..WL_SPH_BODIES_MAX; at most
 * WL_SPH_WALLS_MAX wall faces. WL_OK or WL_EINPUT naming the particle. */
static inline enum wl_status wl_sph_check_particles(const char *backend,
                                                    const struct wl_sph_config *cfg,
                                                    const struct wl_particles *host,
                                                    struct wl_error *err) {
  if (host->dim != cfg->prm.dim)
    return wl_error_set(err, WL_EINPUT, "%s backend: particles are %dD, configuration %dD",
                        backend, host->dim, cfg->prm.dim);
  for (int i = 0; i < host->n; i++) {
    const int bound = host->kind[i] != WL_KIND_FLUID;
    if (bound != (i < host->n_bound))
      return wl_error_set(err, WL_EINPUT,
                          "%s backend: particle %d (id %u) is %s but the first %d particles must "
                          "be the boundary ones and the rest fluid",
                          backend, i, host->id[i], bound ? "boundary" : "fluid", host->n_bound);
    if (host->kind[i] > WL_KIND_MOVING)
      return wl_error_set(err, WL_EINPUT, "%s backend: particle %d has kind %d; valid 0, 1, 2",
                          backend, i, host->kind[i]);
    if (host->kind[i] == WL_KIND_MOVING && (host->body[i] < 1 || host->body[i] > WL_SPH_BODIES_MAX))
      return wl_error_set(err, WL_EINPUT, "%s backend: moving particle %d has body %d; valid 1..%d",
                          backend, i, host->body[i], WL_SPH_BODIES_MAX);
  }
  if (cfg->n_walls < 0 || cfg->n_walls > WL_SPH_WALLS_MAX)
    return wl_error_set(err, WL_EINPUT, "%s backend: %d walls; at most %d", backend, cfg->n_walls,
                        WL_SPH_WALLS_MAX);
  return WL_OK;
}

struct wl_backend_ops {
  const char *name; /* "cpu", "cuda" */
  /* Create the backend state from the host particles (boundary first, then
   * fluid; not modified) and evaluate the forces of the initial state, so
   * that out->dt_next is the first step. WL_EINPUT for a configuration the
   * backend rejects, WL_ENOMEM (message names the array), WL_EUNSUPPORTED
   * (e.g. built without CUDA). On failure *ctx is NULL and nothing leaks. */
  enum wl_status (*init)(void **ctx, const struct wl_sph_config *cfg, const struct wl_sph_const *k,
                         const struct wl_particles *host, struct wl_sph_step_out *out,
                         struct wl_error *err);
  /* One symplectic step: rebuild the cell lists (sort), predictor, corrector,
   * guard. No allocation. Returns WL_OK, also when the guard found a fault
   * (out->fault says which; the driver turns it into WL_EUNSTABLE). */
  enum wl_status (*step)(void *ctx, const struct wl_sph_step_in *in, struct wl_sph_step_out *out,
                         struct wl_error *err);
  /* Copy the state fields (WL_FIELD_SORT) into host, which must have been
   * allocated for at least as many particles (wl_particles_alloc). */
  enum wl_status (*download)(void *ctx, struct wl_particles *host, struct wl_error *err);
  /* One line for the run metadata and progress: backend, threads or
   * device, code path ("cpu (OpenMP, 2 threads, avx512 force loop, ...)"). */
  void (*describe)(void *ctx, char *buf, size_t size);
  /* Free everything; NULL is accepted. */
  void (*free)(void *ctx);
  /* The load of the fluid on the boundary particles of body `body` (a
   * fixed structure's tag, particles.h body) in the current state: the
   * horizontal force [N in 3D, N/m in 2D] into *force and its moment about
   * the height z_ref [m] into *moment, summed over every fluid-boundary
   * pair of the solver's momentum equation (sph/gather.h
   * wl_sph_gather_wall_load; the pressures the EOS of the stored
   * densities). Rebuilds the cell lists first (the order the next step
   * would sort into: the run's results are unchanged). Not for a moving
   * body. WL_OK, or the backend's error (outputs 0). */
  enum wl_status (*wall_load)(void *ctx, int body, double z_ref, double *force, double *moment,
                              struct wl_error *err);
  /* Optional (NULL: the driver calls step once a step). Steps with no
   * moving body in motion, chosen, guarded and counted on the backend's
   * side by the driver's rules above exactly as the driver's own loop would
   * (src/sph/sim.c wl_sph_sim_run), from in until one of
   * enum wl_sph_block_stop; the steps stop advancing after the first fault
   * or guard, so out says which step and time. For a backend that would
   * otherwise wait for each step's record (a GPU). WL_OK or the backend's
   * error. */
  enum wl_status (*run)(void *ctx, const struct wl_sph_block_in *in, struct wl_sph_block_out *out,
                        struct wl_error *err);
  /* Optional, all four or none (NULL: the driver's output reads the state
   * between blocks): an output overlapped with the next block. snapshot
   * enqueues, behind the work already queued, the copy of the fields
   * download reads and then the wall loads of n (body, z_ref) pairs (n <=
   * WL_SPH_SNAPSHOT_LOADS, as wall_load), and returns at once; run_start
   * enqueues a block as run would and returns at once; snapshot_wait waits
   * for the snapshot and gives its state (as download) and loads;
   * run_finish waits for the block and gives its out (as run). The
   * snapshot's results are those of download and wall_load at that point,
   * to the last bit. */
  enum wl_status (*snapshot)(void *ctx, int n, const int *body, const double *z_ref,
                             struct wl_error *err);
  enum wl_status (*snapshot_wait)(void *ctx, struct wl_particles *host, double *force,
                                  double *moment, struct wl_error *err);
  enum wl_status (*run_start)(void *ctx, const struct wl_sph_block_in *in, struct wl_error *err);
  enum wl_status (*run_finish)(void *ctx, struct wl_sph_block_out *out, struct wl_error *err);
  /* Optional, both or neither (NULL: the backend's state cannot be edited
   * from the host). For a driver that edits a few particles between steps
   * (vres.h: the buffers' interpolated values, particles parked and
   * revived) without moving the whole state across (a GPU's bus):
   * zone_download copies the state fields (WL_FIELD_SORT) of every particle
   * whose x lies in [x_lo, x_hi], and of the first n_parked fluid particles
   * outside it that are parked (body WL_SPH_BODY_EXCLUDED), into host,
   * compacted in the backend's order (so boundary particles first; host->n
   * and n_bound set; host allocated for the backend's particle count), and
   * each one's place in the backend into idx; zone_upload writes host's
   * particles back to those places, with no step between the two. */
  enum wl_status (*zone_download)(void *ctx, double x_lo, double x_hi, int n_parked,
                                  struct wl_particles *host, int *idx, struct wl_error *err);
  enum wl_status (*zone_upload)(void *ctx, const struct wl_particles *host, const int *idx,
                                struct wl_error *err);
};

/* Most wall loads one snapshot computes (backend.h snapshot). */
enum { WL_SPH_SNAPSHOT_LOADS = 4 };

/* The OpenMP CPU backend (src/backend_cpu). */
extern const struct wl_backend_ops wl_backend_cpu_ops;

/* The incompressible SPH backend (src/backend_cpu/isph.c): a projection
 * method with a pressure Poisson equation (sph/isph.h, docs/isph.md), 2D,
 * on the host. Stage 1 of issue 22: reachable from the tests, not yet from
 * scenarios. */
extern const struct wl_backend_ops wl_backend_isph_ops;

/* The ISPH backend's counters (ctx: the backend state of a simulation that
 * runs wl_backend_isph_ops; sph.h wl_sph_sim_backend gives it). */
void wl_backend_isph_stats(const void *ctx, struct wl_isph_stats *out);

/* The CUDA backend (src/backend_cuda); in a build without CUDA its init
 * returns WL_EUNSUPPORTED ("built without CUDA"). */
extern const struct wl_backend_ops wl_backend_cuda_ops;

#endif
