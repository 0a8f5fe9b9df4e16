/* sim.c: the time-stepping driver (sph.h): owns time, step count, the
 * prescribed motion of moving bodies, output times and the instability
 * report; the backend (backend.h) owns the particles and does the step. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "wallload/sph.h"

struct body_motion {
  enum wl_sph_motion_type type;
  int n;
  double *t, *x; /* owned copies of the table */
  double (*x_of_t)(double t, void *user);
  void *user;
};

/* Most steps in one block of the backend (backend.h run): the progress
 * callback and the host's view of the run come at least this often. */
#define WL_SPH_BLOCK_STEPS 256

struct wl_sph_sim {
  const struct wl_backend_ops *ops;
  void *ctx;
  struct wl_sph_config cfg;
  struct wl_sph_const k;
  struct wl_particles host; /* download target */
  int host_valid;           /* host holds the current state */
  struct wl_particles zone; /* wl_sph_sim_edit_zone's particles (allocated at the first) */
  int *zone_idx;            /* their places in the backend */
  int zone_open;            /* an edit not yet committed */
  double t;
  long steps;
  double dt_next;           /* from the last force evaluations [s] */
  double dt_last;           /* the last step taken [s] (0 before the first) */
  double dt_initial;        /* the first CFL step, reference for the dt-collapse guard */
  struct wl_sph_step_out last;
  long n_limited;           /* wall-limiter corrections since the start (sph/guard.h) */
  long n_excluded;          /* fluid particles that left the domain box (sph/guard.h) */
  long n_fluid;             /* fluid particles of the run */
  struct body_motion motion[WL_SPH_BODIES_MAX + 1];
  /* the wall loads the outputs asked for (wl_sph_sim_wall_load): a
   * snapshot computes them for the next output */
  int n_loads;
  int load_body[WL_SPH_SNAPSHOT_LOADS];
  double load_z[WL_SPH_SNAPSHOT_LOADS];
  /* an output overlapped with the next block (backend.h snapshot): during
   * it the state is the snapshot's; `pending`: that block is started and
   * not yet finished */
  int snap, snap_read, pending;
  double snap_force[WL_SPH_SNAPSHOT_LOADS], snap_moment[WL_SPH_SNAPSHOT_LOADS];
};

static void motion_clear(struct body_motion *m) {
  free(m->t);
  free(m->x);
  memset(m, 0, sizeof *m);
}

static void finish_pending(struct wl_sph_sim *sim) {
  if (!sim->pending) return;
  struct wl_sph_block_out out;
  struct wl_error e;
  wl_error_clear(&e);
  sim->ops->run_finish(sim->ctx, &out, &e); /* a run that stopped: its steps are not taken */
  sim->pending = 0;
}

void wl_sph_sim_free(struct wl_sph_sim *sim) {
  if (!sim) return;
  finish_pending(sim);
  if (sim->ops && sim->ctx) sim->ops->free(sim->ctx);
  wl_particles_clear(&sim->host);
  wl_particles_clear(&sim->zone);
  free(sim->zone_idx);
  for (int b = 0; b <= WL_SPH_BODIES_MAX; b++) motion_clear(&sim->motion[b]);
  free(sim);
}

static const char *fault_name(int fault) {
  switch (fault) {
  case WL_SPH_FAULT_NONFINITE: return "non-finite position, velocity or density";
  case WL_SPH_FAULT_OUTSIDE: return "left the domain box";
  case WL_SPH_FAULT_DENSITY: return "density out of range";
  case WL_SPH_FAULT_PENETRATION: return "crossed a wall";
  case WL_SPH_FAULT_DT: return "time step collapsed";
  }
  return "no fault";
}

static const char *kind_name(int kind) {
  return kind == WL_KIND_FLUID ? "fluid" : kind == WL_KIND_FIXED ? "fixed boundary" : "moving boundary";
}

/* Turn a guard fault into WL_EUNSTABLE with what, where and when. */
static enum wl_status report_fault(const struct wl_sph_sim *sim, const struct wl_sph_step_out *o,
                                   struct wl_error *err) {
  const int dim = sim->cfg.prm.dim;
  char where[256];
  if (dim == 2)
    snprintf(where, sizeof where, "at (x, z) = (%.6g, %.6g) m, velocity (%.4g, %.4g) m/s, density "
             "%.6g kg/m^3", o->fault_pos[0], o->fault_pos[1], o->fault_vel[0], o->fault_vel[1],
             o->fault_rho);
  else
    snprintf(where, sizeof where, "at (%.6g, %.6g, %.6g) m, velocity (%.4g, %.4g, %.4g) m/s, "
             "density %.6g kg/m^3", o->fault_pos[0], o->fault_pos[1], o->fault_pos[2],
             o->fault_vel[0], o->fault_vel[1], o->fault_vel[2], o->fault_rho);
  char detail[256] = "";
  if (o->fault == WL_SPH_FAULT_OUTSIDE) {
    if (dim == 2)
      snprintf(detail, sizeof detail, " (box x [%g, %g], z [%g, %g] m)", sim->cfg.lo[0],
               sim->cfg.hi[0], sim->cfg.lo[1], sim->cfg.hi[1]);
    else
      snprintf(detail, sizeof detail, " (box [%g, %g] x [%g, %g] x [%g, %g] m)", sim->cfg.lo[0],
               sim->cfg.hi[0], sim->cfg.lo[1], sim->cfg.hi[1], sim->cfg.lo[2], sim->cfg.hi[2]);
  } else if (o->fault == WL_SPH_FAULT_DENSITY) {
    snprintf(detail, sizeof detail, " (valid [%g, %g] kg/m^3)", sim->k.rho_min, sim->k.rho_max);
  } else if (o->fault == WL_SPH_FAULT_PENETRATION && o->fault_wall >= 0) {
    const struct wl_sph_wall *w = &sim->cfg.walls[o->fault_wall];
    snprintf(detail, sizeof detail, " (wall %d from (%g, %g) to (%g, %g) m, more than %g m behind "
             "its face)", o->fault_wall, w->a[0], w->a[1], w->a[0] + w->len * w->t[0],
             w->a[1] + w->len * w->t[1], sim->k.penetration);
  }
  return wl_error_set(err, WL_EUNSTABLE,
                      "unstable at t = %.6g s, step %ld: %s particle %d (id %u) %s%s; %s",
                      sim->t, sim->steps, kind_name(o->fault_kind), o->fault_index, o->fault_id,
                      fault_name(o->fault), detail, where);
}

/* The time-step collapse (wl_sph_dt_collapsed of sim->dt_next) as
 * WL_EUNSTABLE, with the last step's maxima. */
static enum wl_status report_collapse(const struct wl_sph_sim *sim, struct wl_error *err) {
  const double dt_cfl = sim->dt_next;
  const struct wl_sph_step_out *o = &sim->last;
  return wl_error_set(err, WL_EUNSTABLE,
                      "unstable at t = %.6g s, step %ld: time step collapsed to %.3g s (%.3g of "
                      "the initial %.3g s; limit %.4g): max |a| = %.4g m/s^2, max |v| = %.4g m/s",
                      sim->t, sim->steps, dt_cfl, dt_cfl / sim->dt_initial, sim->dt_initial,
                      sim->k.dt_collapse, o->ace_max, o->vel_max);
}

/* Too many fluid particles left the box (wl_sph_excluded_too_many) as
 * WL_EUNSTABLE. */
static enum wl_status report_excluded(const struct wl_sph_sim *sim, struct wl_error *err) {
  return wl_error_set(err, WL_EUNSTABLE,
                      "unstable at t = %.6g s, step %ld: %ld of %ld fluid particles (more than "
                      "%.1f %%) have left the domain box [%g, %g] x ... m and were taken out of "
                      "the run", sim->t, sim->steps, sim->n_excluded, sim->n_fluid,
                      100 * WL_SPH_EXCLUDED_MAX, sim->cfg.lo[0], sim->cfg.hi[0]);
}

enum wl_status wl_sph_sim_alloc(struct wl_sph_sim **out, const struct wl_backend_ops *ops,
                                const struct wl_sph_config *cfg, const struct wl_particles *initial,
                                struct wl_error *err) {
  *out = NULL;
  struct wl_sph_sim *sim = calloc(1, sizeof *sim);
  if (!sim) return wl_error_set(err, WL_ENOMEM, "sph: out of memory for the simulation");
  sim->ops = ops;
  sim->cfg = *cfg;
  enum wl_status st = wl_sph_const_make(&cfg->prm, &sim->k, err);
  if (st == WL_OK && cfg->n_walls > WL_SPH_WALLS_MAX)
    st = wl_error_set(err, WL_EINPUT, "sph: %d walls; at most %d", cfg->n_walls, WL_SPH_WALLS_MAX);
  if (st == WL_OK && initial->dim != cfg->prm.dim)
    st = wl_error_set(err, WL_EINPUT, "sph: particles are %dD but the parameters say %dD",
                      initial->dim, cfg->prm.dim);
  if (st == WL_OK && (initial->n <= initial->n_bound))
    st = wl_error_set(err, WL_EINPUT, "sph: no fluid particles (%d particles, %d boundary)",
                      initial->n, initial->n_bound);
  sim->n_fluid = initial->n - initial->n_bound;
  if (st == WL_OK) st = wl_particles_alloc(&sim->host, cfg->prm.dim, initial->n, 0, err);
  if (st == WL_OK) st = ops->init(&sim->ctx, cfg, &sim->k, initial, &sim->last, err);
  if (st != WL_OK) {
    wl_error_prefix(err, "%s backend: ", ops->name);
    wl_sph_sim_free(sim);
    return st;
  }
  if (sim->last.fault) {
    st = report_fault(sim, &sim->last, err);
    wl_error_prefix(err, "initial state: ");
    wl_sph_sim_free(sim);
    return st;
  }
  sim->dt_next = sim->dt_initial = sim->last.dt_next;
  *out = sim;
  return WL_OK;
}

enum wl_status wl_sph_sim_set_motion(struct wl_sph_sim *sim, int body,
                                     const struct wl_sph_motion *m, struct wl_error *err) {
  if (body < 1 || body > WL_SPH_BODIES_MAX)
    return wl_error_set(err, WL_EINPUT, "sph motion: body %d; valid 1..%d", body, WL_SPH_BODIES_MAX);
  struct body_motion nm = {0};
  nm.type = m->type;
  if (m->type == WL_SPH_MOTION_TABLE) {
    if (m->n < 1 || !m->t || !m->x)
      return wl_error_set(err, WL_EINPUT, "sph motion of body %d: table with %d samples; need >= 1",
                          body, m->n);
    for (int i = 1; i < m->n; i++)
      if (!(m->t[i] > m->t[i - 1]))
        return wl_error_set(err, WL_EINPUT, "sph motion of body %d: times not increasing at sample "
                            "%d (%g after %g s)", body, i, m->t[i], m->t[i - 1]);
    nm.n = m->n;
    nm.t = malloc(sizeof(double) * (size_t)m->n);
    nm.x = malloc(sizeof(double) * (size_t)m->n);
    if (!nm.t || !nm.x) {
      motion_clear(&nm);
      return wl_error_set(err, WL_ENOMEM, "sph motion of body %d: out of memory for %d samples",
                          body, m->n);
    }
    memcpy(nm.t, m->t, sizeof(double) * (size_t)m->n);
    memcpy(nm.x, m->x, sizeof(double) * (size_t)m->n);
  } else if (m->type == WL_SPH_MOTION_FUNCTION) {
    if (!m->x_of_t)
      return wl_error_set(err, WL_EINPUT, "sph motion of body %d: no function given", body);
    nm.x_of_t = m->x_of_t;
    nm.user = m->user;
  } else if (m->type != WL_SPH_MOTION_NONE) {
    return wl_error_set(err, WL_EINPUT, "sph motion of body %d: type %d; valid 0, 1, 2", body,
                        (int)m->type);
  }
  motion_clear(&sim->motion[body]);
  sim->motion[body] = nm;
  return WL_OK;
}

/* Displacement X(t) [m] of a body. */
static double motion_x(const struct body_motion *m, double t) {
  switch (m->type) {
  case WL_SPH_MOTION_TABLE: {
    if (t <= m->t[0]) return m->x[0];
    if (t >= m->t[m->n - 1]) return m->x[m->n - 1];
    int lo = 0, hi = m->n - 1; /* bisection: t[lo] <= t < t[hi] */
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      if (m->t[mid] <= t) lo = mid;
      else hi = mid;
    }
    const double s = (t - m->t[lo]) / (m->t[hi] - m->t[lo]);
    return m->x[lo] + s * (m->x[hi] - m->x[lo]);
  }
  case WL_SPH_MOTION_FUNCTION: return m->x_of_t(t, m->user);
  default: return 0;
  }
}

enum wl_status wl_sph_sim_step(struct wl_sph_sim *sim, double dt_max, struct wl_error *err) {
  const double dt_cfl = sim->dt_next;
  if (wl_sph_dt_collapsed(&sim->k, dt_cfl, sim->dt_initial)) return report_collapse(sim, err);
  struct wl_sph_step_in in;
  memset(&in, 0, sizeof in);
  in.t = sim->t;
  in.dt = wl_sph_dt_limit(dt_max, dt_cfl);
  in.dt_prev = sim->dt_last;
  in.step = sim->steps;
  for (int b = 1; b <= WL_SPH_BODIES_MAX; b++)
    if (sim->motion[b].type != WL_SPH_MOTION_NONE) {
      const struct body_motion *m = &sim->motion[b];
      const double x0 = motion_x(m, sim->t), x1 = motion_x(m, sim->t + in.dt);
      in.body_vel[b][0] = (x1 - x0) / in.dt;
      /* central difference at the step start; one-sided at t = 0 (at rest before) */
      const double xm = sim->t > in.dt ? motion_x(m, sim->t - in.dt) : x0;
      in.body_acc[b][0] = (x1 - 2.0 * x0 + xm) / (in.dt * in.dt);
    }
  struct wl_sph_step_out out;
  enum wl_status st = sim->ops->step(sim->ctx, &in, &out, err);
  sim->host_valid = 0;
  if (st != WL_OK) {
    wl_error_prefix(err, "%s backend, t = %.6g s, step %ld: ", sim->ops->name, sim->t, sim->steps);
    return st;
  }
  sim->t += in.dt;
  sim->dt_last = in.dt;
  sim->steps++;
  sim->last = out;
  sim->n_limited += out.n_limited;
  sim->n_excluded += out.n_excluded;
  sim->dt_next = out.dt_next;
  if (out.fault) return report_fault(sim, &out, err);
  if (wl_sph_excluded_too_many(sim->n_excluded, sim->n_fluid)) return report_excluded(sim, err);
  return WL_OK;
}

/* Whether the run's steps may go to the backend in blocks (backend.h run):
 * the backend has them and no body moves (the motion is sampled here, on
 * the host, step by step). */
static int blocks_possible(const struct wl_sph_sim *sim) {
  if (!sim->ops->run) return 0;
  for (int b = 1; b <= WL_SPH_BODIES_MAX; b++)
    if (sim->motion[b].type != WL_SPH_MOTION_NONE) return 0;
  return 1;
}

/* Steps toward t_out in one block of the backend (backend.h run), with the
 * driver's state before and after it and the messages of wl_sph_sim_step;
 * *landed: the last step landed on t_out. */
static void block_in_of(const struct wl_sph_sim *sim, double t_out, long max_steps,
                        struct wl_sph_block_in *in) {
  memset(in, 0, sizeof *in);
  in->t = sim->t;
  in->t_out = t_out;
  in->dt_next = sim->dt_next;
  in->dt_last = sim->dt_last;
  in->dt_initial = sim->dt_initial;
  in->step = sim->steps;
  in->max_steps = max_steps;
  in->n_excluded = sim->n_excluded;
  in->n_fluid = sim->n_fluid;
}

/* The steps of a block toward t_out, rest = t_out - t ahead: about the
 * steps to t_out, and one more for a split rest (a block that ends short
 * of it is followed by another). */
static long block_steps(double rest, double dt) {
  const double est = rest / dt + 2;
  return est < WL_SPH_BLOCK_STEPS ? (long)est : WL_SPH_BLOCK_STEPS;
}

static enum wl_status step_block(struct wl_sph_sim *sim, double t_out, long max_steps,
                                 int *landed, struct wl_error *err) {
  *landed = 0;
  struct wl_sph_block_out out;
  memset(&out, 0, sizeof out);
  enum wl_status st;
  if (sim->pending) { /* started during the last output, with these t_out and max_steps */
    sim->pending = 0;
    st = sim->ops->run_finish(sim->ctx, &out, err);
  } else {
    struct wl_sph_block_in in;
    block_in_of(sim, t_out, max_steps, &in);
    st = sim->ops->run(sim->ctx, &in, &out, err);
  }
  if (out.steps > 0) sim->host_valid = 0;
  if (st != WL_OK) {
    wl_error_prefix(err, "%s backend, t = %.6g s, step %ld: ", sim->ops->name, sim->t, sim->steps);
    return st;
  }
  if (out.steps > 0) {
    sim->t = out.t;
    sim->dt_last = out.dt_last;
    sim->steps += out.steps;
    sim->last = out.last;
    sim->n_limited += out.n_limited;
    sim->n_excluded += out.n_excluded;
    sim->dt_next = out.dt_next;
  }
  switch (out.stop) {
  case WL_SPH_BLOCK_FAULT: return report_fault(sim, &out.last, err);
  case WL_SPH_BLOCK_COLLAPSE: return report_collapse(sim, err);
  case WL_SPH_BLOCK_EXCLUDED: return report_excluded(sim, err);
  case WL_SPH_BLOCK_LANDED: *landed = 1; break;
  default: break;
  }
  return WL_OK;
}

/* A snapshot of the state for the output at the current time, and the
 * next block (toward t_out, max_steps) started behind it (backend.h
 * snapshot, run_start). */
static enum wl_status overlap_start(struct wl_sph_sim *sim, double t_out, long max_steps,
                                    struct wl_error *err) {
  enum wl_status st = sim->ops->snapshot(sim->ctx, sim->n_loads, sim->load_body, sim->load_z, err);
  if (st == WL_OK) {
    struct wl_sph_block_in in;
    block_in_of(sim, t_out, max_steps, &in);
    st = sim->ops->run_start(sim->ctx, &in, err);
    sim->pending = st == WL_OK;
  }
  if (st != WL_OK) {
    wl_error_prefix(err, "%s backend, t = %.6g s, step %ld: ", sim->ops->name, sim->t, sim->steps);
    return st;
  }
  sim->snap = 1;
  sim->snap_read = 0;
  sim->host_valid = 0;
  return WL_OK;
}

/* The snapshot's state and loads, once (the output's first look). */
static enum wl_status snapshot_read(struct wl_sph_sim *sim, struct wl_error *err) {
  if (sim->snap_read) return WL_OK;
  const enum wl_status st =
      sim->ops->snapshot_wait(sim->ctx, &sim->host, sim->snap_force, sim->snap_moment, err);
  if (st) return st;
  sim->snap_read = 1;
  sim->host_valid = 1;
  return WL_OK;
}

static double wall_seconds(void) {
  struct timespec ts;
  timespec_get(&ts, TIME_UTC);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

enum wl_status wl_sph_sim_run(struct wl_sph_sim *sim, const struct wl_sph_run_opts *o,
                              struct wl_error *err) {
  if (!(o->t_end >= sim->t))
    return wl_error_set(err, WL_EINPUT, "sph run: end time %g s is before the current time %g s",
                        o->t_end, sim->t);
  const double t0 = sim->t, wall0 = wall_seconds();
  const double every = o->progress_wall_s > 0 ? o->progress_wall_s : 1.0;
  double wall_next = wall0 + every;
  const long steps0 = sim->steps;
  /* output times t0 + m output_dt; the last one is t_end */
  long m = 0;
  enum wl_status st = WL_OK;
  if (o->output) st = o->output(o->user, sim, sim->t, err);
  m = 1;
  const int blocks = blocks_possible(sim);
  while (st == WL_OK && sim->t < o->t_end) {
    double t_out = o->output_dt > 0 ? t0 + (double)m * o->output_dt : o->t_end;
    if (t_out > o->t_end) t_out = o->t_end;
    /* the step that lands on t_out; two steps split the rest evenly, so no
     * step is shorter than half the CFL step */
    const double rest = t_out - sim->t, dt = sim->dt_next;
    if (!(rest > 0)) { /* already there (rounding) */
      m++;
      continue;
    }
    int lands;
    if (blocks) {
      st = step_block(sim, t_out, block_steps(rest, dt), &lands, err);
    } else {
      const double dt_max = wl_sph_dt_toward(rest, dt, &lands);
      st = wl_sph_sim_step(sim, dt_max, err);
    }
    if (st != WL_OK) break;
    if (lands) {
      sim->t = t_out; /* exact, against rounding of t + dt */
      if (o->output) {
        /* the next block runs on the GPU while the host samples this
         * output from a snapshot: the block the next pass of this loop
         * would start, with the same t_out and step count */
        double t_next = o->output_dt > 0 ? t0 + (double)(m + 1) * o->output_dt : o->t_end;
        if (t_next > o->t_end) t_next = o->t_end;
        if (blocks && sim->ops->snapshot && sim->t < o->t_end && t_next - sim->t > 0)
          st = overlap_start(sim, t_next, block_steps(t_next - sim->t, sim->dt_next), err);
        if (st == WL_OK) st = o->output(o->user, sim, sim->t, err);
        sim->snap = 0;
        sim->host_valid = 0;
        if (st != WL_OK) finish_pending(sim);
      }
      m++;
    }
    if (o->progress) {
      const double now = wall_seconds();
      if (now >= wall_next || sim->t >= o->t_end) {
        struct wl_sph_progress pr;
        pr.t = sim->t;
        pr.t_end = o->t_end;
        pr.step = sim->steps;
        pr.dt = sim->dt_next;
        pr.wall_s = now - wall0;
        pr.steps_per_s = pr.wall_s > 0 ? (double)(sim->steps - steps0) / pr.wall_s : 0;
        pr.n = sim->host.capacity;
        pr.particle_steps_per_s = pr.steps_per_s * pr.n;
        pr.eta_s = sim->t > t0 ? pr.wall_s * (o->t_end - sim->t) / (sim->t - t0) : 0;
        pr.runs = 0, pr.done = 0.0;
        o->progress(o->user, &pr);
        wall_next = now + every;
      }
    }
  }
  return st;
}

const struct wl_particles *wl_sph_sim_particles(struct wl_sph_sim *sim, struct wl_error *err) {
  if (sim->snap) return snapshot_read(sim, err) ? NULL : &sim->host;
  if (!sim->host_valid) {
    if (sim->ops->download(sim->ctx, &sim->host, err) != WL_OK) return NULL;
    sim->host_valid = 1;
  }
  return &sim->host;
}

struct wl_particles *wl_sph_sim_edit_zone(struct wl_sph_sim *sim, double x_lo, double x_hi,
                                          int n_parked, struct wl_error *err) {
  if (!sim->ops->zone_download || !sim->ops->zone_upload) {
    wl_error_set(err, WL_EUNSUPPORTED, "%s backend: its particles cannot be edited between steps",
                 sim->ops->name);
    return NULL;
  }
  if (!sim->zone_idx) {
    const int cap = sim->host.capacity;
    if (wl_particles_alloc(&sim->zone, sim->cfg.prm.dim, cap, 0, err) != WL_OK) return NULL;
    if (!(sim->zone_idx = malloc(sizeof(int) * (size_t)cap))) {
      wl_error_set(err, WL_ENOMEM, "sph: out of memory for the places of %d particles", cap);
      return NULL;
    }
  }
  finish_pending(sim);
  sim->snap = 0;
  if (sim->ops->zone_download(sim->ctx, x_lo, x_hi, n_parked, &sim->zone, sim->zone_idx, err))
    return NULL;
  sim->host_valid = 0; /* the edit changes the state the host copy holds */
  sim->zone_open = 1;
  return &sim->zone;
}

enum wl_status wl_sph_sim_commit_zone(struct wl_sph_sim *sim, struct wl_error *err) {
  if (!sim->zone_open) return wl_error_set(err, WL_EINPUT, "sph: commit without an edit");
  sim->zone_open = 0;
  return sim->ops->zone_upload(sim->ctx, &sim->zone, sim->zone_idx, err);
}

enum wl_status wl_sph_sim_wall_load(struct wl_sph_sim *sim, int body, double z_ref,
                                    double *force, double *moment, struct wl_error *err) {
  *force = *moment = 0.0;
  if (body < 1 || body > WL_SPH_BODY_TAG_MAX)
    return wl_error_set(err, WL_EINPUT, "sph: wall load of body %d; valid 1..%d", body,
                        WL_SPH_BODY_TAG_MAX);
  if (!sim->ops->wall_load)
    return wl_error_set(err, WL_EUNSUPPORTED, "sph: the %s backend has no wall load",
                        sim->ops->name);
  int q = 0;
  while (q < sim->n_loads && !(sim->load_body[q] == body && sim->load_z[q] == z_ref)) q++;
  if (sim->snap) { /* during an overlapped output: the snapshot computed the loads asked before */
    if (q == sim->n_loads)
      return wl_error_set(err, WL_EUNSUPPORTED, "sph: the wall load of body %d about z = %g m was "
                          "not asked for at the first output, so no snapshot has it", body, z_ref);
    const enum wl_status st = snapshot_read(sim, err);
    if (st) return st;
    *force = sim->snap_force[q];
    *moment = sim->snap_moment[q];
    return WL_OK;
  }
  if (q == sim->n_loads && q < WL_SPH_SNAPSHOT_LOADS) {
    sim->load_body[q] = body;
    sim->load_z[q] = z_ref;
    sim->n_loads++;
  }
  const enum wl_status st = sim->ops->wall_load(sim->ctx, body, z_ref, force, moment, err);
  if (st) *force = *moment = 0.0;
  return st;
}

long wl_sph_sim_limited(const struct wl_sph_sim *sim) { return sim->n_limited; }
long wl_sph_sim_excluded(const struct wl_sph_sim *sim) { return sim->n_excluded; }

double wl_sph_sim_time(const struct wl_sph_sim *sim) { return sim->t; }
long wl_sph_sim_steps(const struct wl_sph_sim *sim) { return sim->steps; }
double wl_sph_sim_dt(const struct wl_sph_sim *sim) { return sim->dt_next; }
double wl_sph_sim_dt_initial(const struct wl_sph_sim *sim) { return sim->dt_initial; }
const struct wl_sph_const *wl_sph_sim_const(const struct wl_sph_sim *sim) { return &sim->k; }
const struct wl_sph_config *wl_sph_sim_config(const struct wl_sph_sim *sim) { return &sim->cfg; }
const struct wl_sph_step_out *wl_sph_sim_last(const struct wl_sph_sim *sim) { return &sim->last; }

void wl_sph_sim_describe(const struct wl_sph_sim *sim, char *buf, size_t size) {
  if (size == 0) return;
  if (sim->ops->describe) sim->ops->describe(sim->ctx, buf, size);
  else snprintf(buf, size, "%s", sim->ops->name);
}

const void *wl_sph_sim_backend(const struct wl_sph_sim *sim) { return sim->ctx; }
