/* sph.h: the SPH engine's public interface (module sph, src/sph/).
 *
 * Weakly-compressible SPH as DualSPHysics 5 (Dominguez et al. 2022, Comp.
 * Part. Mech. 9:867): Wendland C2 kernel, Tait equation of state, symmetric
 * pressure term with Monaghan artificial or laminar viscosity, delta-SPH
 * density diffusion with the Fourtakas et al. (2019) hydrostatic correction,
 * walls whose particles take the fluid's pressure (Adami et al. 2012,
 * sph/wall.h; or DualSPHysics' dynamic boundary particles), symplectic
 * position-Verlet integration with a
 * variable step. The physics is in the headers include/wallload/sph/ (shared with the
 * backends); this header holds the host-side pieces:
 *
 *   parameters   wl_sph_params_default, wl_sph_const_make
 *   particles    wl_particles_alloc / _clear, the field table
 *   simulation   wl_sph_sim_alloc / _step / _run / _free on a backend
 *   probes       free-surface elevation, velocity, pressure at points
 *
 * Typical use (the scene module builds the particles):
 *
 *   struct wl_sph_config cfg;  wl_sph_config_default(&cfg, 2, dp, depth);
 *   ... cfg.lo, cfg.hi, walls ...
 *   wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &particles, &err);
 *   wl_sph_sim_run(sim, &opts, &err);      (output callback samples gauges)
 *   wl_sph_sim_free(sim); */
#ifndef WALLLOAD_SPH_H
#define WALLLOAD_SPH_H

#include <stddef.h>

#include "wallload/backend.h"
#include "wallload/error.h"
#include "wallload/sph/cells.h"
#include "wallload/sph/eos.h"
#include "wallload/sph/kernel.h"
#include "wallload/sph/params.h"
#include "wallload/sph/particles.h"

/* ---- parameters ------------------------------------------------------- */

/* Fill prm with DualSPHysics' defaults (what the benchmarks against it and
 * the engine's own tests use; a scenario's defaults differ, see
 * WL_PLAN_COEFH_2D and docs/numerics.md): coefh 1,
 * coefsound 10, rho0 1000, g 9.81, artificial viscosity alpha 0.01,
 * Fourtakas diffusion (full) delta 0.1, CFL 0.2, guard thresholds. dim: 2 or
 * 3; dp: spacing [m]; h_max: largest water depth [m] (for c0). */
void wl_sph_params_default(struct wl_sph_params *prm, int dim, double dp, double h_max);

/* Check prm and derive the constants. Returns WL_OK, or WL_EINPUT naming the
 * parameter, its value and the valid range (k is then unspecified). */
enum wl_status wl_sph_const_make(const struct wl_sph_params *prm, struct wl_sph_const *k,
                                 struct wl_error *err);

/* Defaults for a run configuration: parameters as wl_sph_params_default,
 * no domain box (caller sets lo, hi), no walls, OpenMP's thread count. */
void wl_sph_config_default(struct wl_sph_config *cfg, int dim, double dp, double h_max);

/* Append a wall face (a -> b in (x, z) [m], fluid on the left; boundary
 * layers `thickness` [m] deep) to the penetration guard. WL_EINPUT when
 * WL_SPH_WALLS_MAX walls are already there. */
enum wl_status wl_sph_config_add_wall(struct wl_sph_config *cfg, double ax, double az, double bx,
                                      double bz, double thickness, struct wl_error *err);

/* The faces of a boundary polyline (x[i], z[i]), i < n [m], fluid on the
 * left, layers `thickness` [m] deep, with a cap across the layers at each
 * end (so that water passing over a wall's open top is above a face, not
 * deep behind the wall's). Errors as wl_sph_config_add_wall. */
enum wl_status wl_sph_config_add_faces(struct wl_sph_config *cfg, const double *x, const double *z,
                                       int n, double thickness, struct wl_error *err);

/* ---- cell lists (host side; the physics side is sph/cells.h) ----------- */

/* Most cells a domain box may have (2 int arrays of twice this size). */
#define WL_SPH_CELLS_MAX 200000000

/* The grid of cells of side 2h over cfg's domain box. WL_EINPUT for an
 * empty or non-finite box or more than WL_SPH_CELLS_MAX cells. */
enum wl_status wl_sph_grid_make(const struct wl_sph_config *cfg, const struct wl_sph_const *k,
                                struct wl_sph_grid *g, struct wl_error *err);

/* Stable counting sort of n particles by key (group * n_cells + cell, see
 * sph/cells.h; key[i] < 2 n_cells): begin (2 n_cells + 1 entries) gets the
 * first sorted index of every key, perm[s] the particle at sorted position
 * s. cursor: scratch of 2 n_cells entries. No allocation. */
void wl_sph_cells_sort(const struct wl_sph_grid *g, const unsigned int *key, int n, int *begin,
                       int *cursor, unsigned int *perm);

/* ---- particles --------------------------------------------------------- */

/* The field table (name, unit, type, flags) and its length. */
const struct wl_field_desc *wl_particles_fields(int *n_fields);

/* Number of arrays of field f (dim for vector fields, else 1). */
int wl_field_components(const struct wl_field_desc *f, int dim);

/* Address of component c of field f's array in p (NULL if not allocated). */
void *wl_field_array(const struct wl_particles *p, const struct wl_field_desc *f, int c);

/* Bytes of one element of a field type. */
size_t wl_field_type_size(enum wl_field_type type);

/* Bytes wl_particles_alloc takes for `capacity` particles in `dim`
 * dimensions; with_work: also the per-step arrays (backends need them,
 * a host copy of the state does not). For `wallload check`. */
size_t wl_particles_bytes(int dim, int capacity, int with_work);

/* Bytes a CPU run of n particles in cfg's domain needs: the particle
 * arrays with work fields, the second state copy the sort fills, the
 * sorted keys and the two cell index arrays (2 n_cells + 1 ints each). For
 * `wallload check` and the run metadata; 0 if cfg's box or parameters are
 * invalid. */
size_t wl_sph_memory_bytes(const struct wl_sph_config *cfg, int n);

/* Allocate the arrays of p for `capacity` particles (zeroed), state fields
 * always, work fields if with_work. n = n_bound = 0. Returns WL_OK;
 * WL_EINPUT for dim not 2 or 3 or capacity < 0; WL_ENOMEM naming the array,
 * its size and the particle count. On failure p is cleared. */
enum wl_status wl_particles_alloc(struct wl_particles *p, int dim, int capacity, int with_work,
                                  struct wl_error *err);

/* Free the arrays of p and zero it; safe on a zeroed or half-built p. */
void wl_particles_clear(struct wl_particles *p);

/* Copy the state fields of particles [0, src->n) from src to dst (capacity
 * checked) and set dst's n and n_bound. WL_EINPUT if dst is too small or the
 * dimensions differ. */
enum wl_status wl_particles_copy_state(struct wl_particles *dst, const struct wl_particles *src,
                                       struct wl_error *err);

/* The places of a zone (backend.h zone_download) in p, in p's order, into
 * idx (room for p->n): every particle whose x lies in [x_lo, x_hi], and the
 * first n_parked fluid particles outside it that are parked (body
 * WL_SPH_BODY_EXCLUDED). Returns their number. */
int wl_particles_zone_select(const struct wl_particles *p, double x_lo, double x_hi, int n_parked,
                             int *idx);

/* The state fields of src's particles idx[0..m) into dst's [0, m) (room
 * for m), dst's n = m and n_bound the number of them below src's n_bound
 * (idx ascending); and back: dst's particles idx[k] from src's k < src->n. */
void wl_particles_gather(struct wl_particles *dst, const struct wl_particles *src, const int *idx,
                         int m);
void wl_particles_scatter(struct wl_particles *dst, const struct wl_particles *src, const int *idx);

/* ---- simulation ----------------------------------------------------------- */

/* Prescribed horizontal motion X(t) of a moving body (piston paddle),
 * displacement from the particles' initial position [m] along x. */
enum wl_sph_motion_type {
  WL_SPH_MOTION_NONE = 0,     /* at rest */
  WL_SPH_MOTION_TABLE = 1,    /* piecewise-linear samples (t_k, x_k), held beyond the ends */
  WL_SPH_MOTION_FUNCTION = 2, /* x_of_t(t, user), host function */
};

struct wl_sph_motion {
  enum wl_sph_motion_type type;
  int n;           /* table: number of samples (>= 1) */
  const double *t; /* table: times [s], increasing (copied) */
  const double *x; /* table: displacements [m] (copied) */
  double (*x_of_t)(double t, void *user); /* function: displacement [m] at t [s] */
  void *user;
};

/* Progress report (the CLI prints it; the library never does). */
struct wl_sph_progress {
  double t, t_end;   /* simulated time and end [s] */
  long step;         /* steps done */
  double dt;         /* last step [s] */
  double wall_s;     /* wall-clock time since the run started [s] */
  double steps_per_s;
  double particle_steps_per_s;
  double eta_s;      /* estimated wall-clock seconds to t_end at the rate so far */
  int n;             /* particles */
  /* Where the caller's task is more than this run (runs side by side, a
   * convergence ladder's levels and realisations): `runs` of them, `done`
   * the share of their planned work done, and eta_s then the whole task's
   * (src/assess/ladder.c). runs 0 (the solver's own reports): one run. */
  int runs;
  double done;
};

struct wl_sph_sim; /* opaque */

/* Output callback: called at the start, then whenever the simulated time
 * reaches a multiple of output_dt (steps are shortened to land on it).
 * Return WL_OK to go on, anything else stops the run with that status (set
 * err). */
typedef enum wl_status (*wl_sph_output_fn)(void *user, struct wl_sph_sim *sim, double t,
                                           struct wl_error *err);
typedef void (*wl_sph_progress_fn)(void *user, const struct wl_sph_progress *pr);

struct wl_sph_run_opts {
  double t_end;                /* end time [s] */
  double output_dt;            /* output interval [s]; <= 0: output at start and end only */
  wl_sph_output_fn output;     /* may be NULL */
  wl_sph_progress_fn progress; /* may be NULL */
  double progress_wall_s;      /* wall-clock seconds between progress calls; <= 0: 1 */
  void *user;
};

/* Create a simulation: validate cfg, derive the constants, hand the initial
 * particles (boundary particles first, state fields; not modified, not kept)
 * to the backend and evaluate the initial forces. Returns WL_OK; WL_EINPUT
 * for a bad configuration (message names what), WL_ENOMEM, or the backend's
 * error. On failure *sim is NULL. */
enum wl_status wl_sph_sim_alloc(struct wl_sph_sim **sim, const struct wl_backend_ops *ops,
                                const struct wl_sph_config *cfg, const struct wl_particles *initial,
                                struct wl_error *err);

/* Free a simulation and its backend state; NULL is accepted. */
void wl_sph_sim_free(struct wl_sph_sim *sim);

/* Prescribe the motion of moving body `body` (1..WL_SPH_BODIES_MAX); the
 * table is copied. WL_EINPUT for a bad body number or table (not
 * increasing, n < 1); WL_ENOMEM. */
enum wl_status wl_sph_sim_set_motion(struct wl_sph_sim *sim, int body,
                                     const struct wl_sph_motion *motion, struct wl_error *err);

/* Advance by one step of at most dt_max [s] (<= 0: no limit). Returns WL_OK;
 * WL_EUNSTABLE when the guard found a fault (the message names the particle
 * index and id, its position, velocity and density, the time, the step and
 * what went wrong; the state is the faulty one), or the backend's error. */
enum wl_status wl_sph_sim_step(struct wl_sph_sim *sim, double dt_max, struct wl_error *err);

/* Run until opts->t_end, calling the output and progress callbacks. Returns
 * WL_OK, WL_EUNSTABLE (see wl_sph_sim_step; outputs already made are the
 * results so far), or the callback's or backend's error. */
enum wl_status wl_sph_sim_run(struct wl_sph_sim *sim, const struct wl_sph_run_opts *opts,
                              struct wl_error *err);

/* The current state on the host (downloaded from the backend on demand; the
 * arrays are the simulation's and stay valid until the next step). The
 * order is the backend's sorted order; use the id field to follow a
 * particle. NULL on failure (err set). */
const struct wl_particles *wl_sph_sim_particles(struct wl_sph_sim *sim, struct wl_error *err);

/* A zone of the state for editing between steps (src/sph/vres.c: buffer
 * values, particles parked and revived): the particles whose x lies in
 * [x_lo, x_hi] and the first n_parked parked fluid particles outside it
 * (backend.h zone_download), boundary particles first, in the backend's
 * order; wl_sph_sim_commit_zone writes them back before the next step. The
 * arrays are the simulation's and valid until the commit. Only for a backend
 * with zone_download (WL_EUNSUPPORTED otherwise) and outside a run. */
struct wl_particles *wl_sph_sim_edit_zone(struct wl_sph_sim *sim, double x_lo, double x_hi,
                                          int n_parked, struct wl_error *err);
enum wl_status wl_sph_sim_commit_zone(struct wl_sph_sim *sim, struct wl_error *err);

/* The load of the fluid on the boundary particles tagged `body` (1 ..
 * WL_SPH_BODY_TAG_MAX; the flume tags its seawall WL_FLUME_BODY_WALL) in
 * the current state, computed by the backend with the solver's own pair
 * term (backend.h wall_load): the horizontal force [N in 3D, N/m in 2D]
 * and its moment about the height z_ref [m] (N m, N m/m), no lever arm
 * below z_ref. The host copy of wl_sph_sim_particles stays valid. WL_OK;
 * WL_EINPUT for a bad body; the backend's error (outputs 0). */
enum wl_status wl_sph_sim_wall_load(struct wl_sph_sim *sim, int body, double z_ref,
                                    double *force, double *moment, struct wl_error *err);
#define WL_SPH_BODY_TAG_MAX 254

/* The backend's one-line description (backend, threads, code path) into
 * buf of size bytes. */
void wl_sph_sim_describe(const struct wl_sph_sim *sim, char *buf, size_t size);

/* The backend's state of sim (for a backend's own inspection functions,
 * such as backend.h wl_backend_isph_stats); owned by sim. */
const void *wl_sph_sim_backend(const struct wl_sph_sim *sim);

double wl_sph_sim_time(const struct wl_sph_sim *sim);          /* [s] */
long wl_sph_sim_limited(const struct wl_sph_sim *sim);         /* wall-limiter corrections so far */
/* Fluid particles that left the domain box so far (taken out of the run at
 * rest where they left it, sph/guard.h wl_sph_exclude); a run stops as
 * unstable when they exceed WL_SPH_EXCLUDED_MAX of the fluid. */
long wl_sph_sim_excluded(const struct wl_sph_sim *sim);
/* WL_SPH_EXCLUDED_MAX: backend.h (wl_sph_excluded_too_many) */
long wl_sph_sim_steps(const struct wl_sph_sim *sim);           /* steps done */
double wl_sph_sim_dt(const struct wl_sph_sim *sim);            /* next step [s] */
double wl_sph_sim_dt_initial(const struct wl_sph_sim *sim);    /* first step [s] */
const struct wl_sph_const *wl_sph_sim_const(const struct wl_sph_sim *sim);
const struct wl_sph_config *wl_sph_sim_config(const struct wl_sph_sim *sim);
const struct wl_sph_step_out *wl_sph_sim_last(const struct wl_sph_sim *sim); /* last step's out */

/* ---- probes ---------------------------------------------------------------- */

struct wl_sph_probe; /* opaque: a cell index over a host particle snapshot */

/* Create a probe workspace for the domain of cfg. WL_ENOMEM, WL_EINPUT. */
enum wl_status wl_sph_probe_alloc(struct wl_sph_probe **pr, const struct wl_sph_config *cfg,
                                  struct wl_error *err);
void wl_sph_probe_free(struct wl_sph_probe *pr);

/* Index particles p (any order; kept by pointer until the next call, so p
 * must not change meanwhile). Also computes their pressure from the EOS.
 * Allocates when p has more particles than before. WL_OK, WL_ENOMEM. */
enum wl_status wl_sph_probe_index(struct wl_sph_probe *pr, const struct wl_particles *p,
                                  struct wl_error *err);

/* Shepard sum S(x) = sum_j V_j W(x - x_j) over fluid particles at x [m]. */
double wl_sph_probe_shepard(const struct wl_sph_probe *pr, const double *x);

/* Shepard sum S(x) [-], and into *p the pressure [Pa] at x [m] (0 where
 * no fluid particle is within 2h): the line in height fitted to the
 * particles' pressures (sph/probe.h wl_sph_point_pressure), the reading
 * of every wall probe and pressure sensor. One pass for both. */
double wl_sph_probe_pressure(const struct wl_sph_probe *pr, const double *x, double *p);

/* The pressure [Pa] a sensor half a spacing off a vertical face reads at x
 * [m], z_bed [m] above the face's foot (sph/probe.h
 * wl_sph_face_shepard_full), into *p: wl_sph_probe_pressure's where the
 * point is wet (its Shepard sum at least WL_SPH_SURFACE_SHEPARD of what
 * still water over it gives), 0 where it is dry. The reading of
 * validate's pressure sensors; assess's wall probes apply the same rule
 * with the still-water sums their flume keeps (sample.h). */
void wl_sph_probe_face_pressure(const struct wl_sph_probe *pr, const double *x, double z_bed,
                                double *p);

/* Shepard-normalised velocity [m/s] at x [m] into v (dim components).
 * Returns 1, or 0 (v zero) where no fluid particle is within 2h. */
int wl_sph_probe_velocity(const struct wl_sph_probe *pr, const double *x, double *v);

/* Free-surface elevation [m] on the vertical line at (x, y) (y ignored in
 * 2D), scanning z upward from z_lo to z_hi in steps of dz [m] (<= 0:
 * dp/10, DualSPHysics' default): the top of the highest stretch where S is
 * at least WL_SPH_SURFACE_SHEPARD (0.5, see sph/probe.h), linearly
 * interpolated between samples. z_lo when the line is dry (S never above
 * the limit); z_hi when still wet there. */
double wl_sph_probe_elevation(const struct wl_sph_probe *pr, double x, double y, double z_lo,
                              double z_hi, double dz);

#endif
