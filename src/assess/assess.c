/* assess.c: run the load cases of a scenario: build each flume, step the
 * SPH solver, have the sample stage (sample.h) record gauges, wall probes
 * and the wall's boundary force at every output time, then post-process
 * (record.c) and write (output.c). */
#define _POSIX_C_SOURCE 200809L /* mkdir, stat */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <omp.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "assess_private.h"
#include "wallload/backend.h"
#include "wallload/config.h"
#include "wallload/cuda_device.h"
#include "wallload/report.h"
#include "wallload/sample.h"
#include "wallload/store.h"


/* The stop signal, as messages name it. */
const char *wl_assess_stop_signal_name(int sig) {
  return sig == SIGTERM ? "SIGTERM" : sig == SIGHUP ? "SIGHUP" : "the user (SIGINT)";
}

/* The stop signal's number once one came (opts->interrupted), else 0. */
static int stop_signal(const struct wl_assess_opts *opts) {
  return opts->interrupted ? (int)*opts->interrupted : 0;
}

/* State of one running case, seen by the output callback. */
/* The coarse level of a two-resolution case and what wl_vres_alloc takes
 * (levels.c); the fine level is the case's flume. */
struct case_levels {
  struct wl_flume coarse;
  struct wl_vres_level_spec spec[2];
  struct wl_vres_opts vo;
};

struct run_ctx {
  struct wl_case_result *c;
  const struct wl_assess_opts *opts;
  struct wl_sample *sample;        /* gauges, probes, wall forces (sample.h) */
  struct wl_store *snaps;          /* particle snapshots file */
  struct wl_snapshot_ref *refs;
  size_t n_refs, cap_refs;
  double next_snapshot, snapshot_interval;
  /* two resolutions (levels.c): the coarse level's sampler, and a scratch
   * record for its row; the fine level's is `sample` */
  struct wl_sample *sample_coarse;
  struct wl_record row_coarse;
  double x_interface;
};

static double now_s(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* A snapshot of p at time t; dp_of: each particle's spacing [m], or NULL
 * for k's. */
static enum wl_status write_snapshot(struct run_ctx *rc, const struct wl_particles *p,
                                    const struct wl_sph_const *k, const float *dp_of, double t,
                                    struct wl_error *err) {
  if (rc->n_refs == rc->cap_refs) {
    size_t cap = rc->cap_refs ? 2 * rc->cap_refs : 32;
    struct wl_snapshot_ref *b = realloc(rc->refs, cap * sizeof *b);
    if (!b) return wl_error_set(err, WL_ENOMEM, "snapshots: no memory");
    rc->refs = b;
    rc->cap_refs = cap;
  }
  struct wl_snapshot_ref *r = &rc->refs[rc->n_refs];
  r->time = t;
  r->n = (size_t)p->n;
  snprintf(r->group, sizeof r->group, "snapshots/%04zu", rc->n_refs);
  size_t n = (size_t)p->n;
  double *pos = malloc(3 * n * sizeof *pos);
  float *vel = malloc(3 * n * sizeof *vel), *rho = malloc(n * sizeof *rho),
        *prs = malloc(n * sizeof *prs), *dps = malloc(n * sizeof *dps);
  int *kind = malloc(n * sizeof *kind);
  enum wl_status st = WL_OK;
  if (!pos || !vel || !rho || !prs || !dps || !kind) {
    st = wl_error_set(err, WL_ENOMEM, "snapshots: no memory for %zu particles", n);
  } else {
    for (size_t i = 0; i < n; i++) {
      /* 2D (x, z) is written as (x, 0, z) for ParaView */
      if (p->dim == 3) {
        for (int a = 0; a < 3; a++) {
          pos[3 * i + a] = p->pos[a][i];
          vel[3 * i + a] = (float)p->vel[a][i];
        }
      } else {
        pos[3 * i] = p->pos[0][i], pos[3 * i + 1] = 0.0, pos[3 * i + 2] = p->pos[1][i];
        vel[3 * i] = (float)p->vel[0][i], vel[3 * i + 1] = 0.0f, vel[3 * i + 2] = (float)p->vel[1][i];
      }
      rho[i] = (float)p->rho[i];
      prs[i] = (float)wl_sph_eos_p(k, p->rho[i]);
      dps[i] = dp_of ? dp_of[i] : (float)k->dp;
      kind[i] = p->kind[i];
    }
    char path[160];
    snprintf(path, sizeof path, "%s/position", r->group);
    st = wl_store_write_matrix(rc->snaps, path, pos, n, 3, "m", "particle position (x, y, z)", err);
    if (!st) {
      snprintf(path, sizeof path, "%s/velocity", r->group);
      st = wl_store_write_matrix_f(rc->snaps, path, vel, n, 3, "m/s", "particle velocity (u, v, w)",
                                   err);
    }
    if (!st) {
      snprintf(path, sizeof path, "%s/rho", r->group);
      st = wl_store_write_vector_f(rc->snaps, path, rho, n, "kg/m^3", "density", err);
    }
    if (!st) {
      snprintf(path, sizeof path, "%s/p", r->group);
      st = wl_store_write_vector_f(rc->snaps, path, prs, n, "Pa", "pressure (Tait EOS)", err);
    }
    if (!st) {
      snprintf(path, sizeof path, "%s/dp", r->group);
      st = wl_store_write_vector_f(rc->snaps, path, dps, n, "m", "particle spacing of its level",
                                   err);
    }
    if (!st) {
      snprintf(path, sizeof path, "%s/kind", r->group);
      st = wl_store_write_vector_i(rc->snaps, path, kind, n, "0 fluid, 1 fixed, 2 moving", err);
    }
    if (!st) {
      snprintf(path, sizeof path, "%s", r->group);
      st = wl_store_attr_double(rc->snaps, path, "time", t, "s", err);
    }
    /* to the disk now: a full disk stops the run here, not at its end */
    if (!st) st = wl_store_flush(rc->snaps, err);
  }
  free(pos), free(vel), free(rho), free(prs), free(dps), free(kind);
  if (!st) rc->n_refs++;
  return st;
}

static enum wl_status on_output(void *user, struct wl_sph_sim *sim, double t,
                                struct wl_error *err) {
  struct run_ctx *rc = user;
  if (rc->opts->interrupted && *rc->opts->interrupted)
    return wl_error_set(err, WL_EINTERRUPTED, "interrupted by %s while stepping, at t = %.4f s",
                        wl_assess_stop_signal_name((int)*rc->opts->interrupted), t);
  const struct wl_particles *p = wl_sph_sim_particles(sim, err);
  if (!p) return err->status ? err->status : WL_EIO;
  enum wl_status st = wl_sample_sim(rc->sample, sim, p, t, &rc->c->rec, err);
  if (st) return st;
  if (rc->snaps && t >= rc->next_snapshot - 1e-12) {
    if ((st = write_snapshot(rc, p, wl_sph_sim_const(sim), NULL, t, err))) return st;
    rc->next_snapshot += rc->snapshot_interval;
  }
  return WL_OK;
}

/* Both levels' particles that take part in the run (not parked), each
 * with its level's dp, as one snapshot. */
static enum wl_status levels_snapshot(struct run_ctx *rc, struct wl_vres *v, double t,
                                      struct wl_error *err) {
  const struct wl_particles *p[2];
  int n = 0;
  for (int l = 0; l < 2; l++) {
    if (!(p[l] = wl_sph_sim_particles(wl_vres_level(v, l), err))) return err->status;
    for (int i = 0; i < p[l]->n; i++) n += p[l]->body[i] != WL_SPH_BODY_EXCLUDED;
  }
  struct wl_particles m;
  enum wl_status st = wl_particles_alloc(&m, 2, n, 0, err);
  float *dp_of = malloc((size_t)(n > 0 ? n : 1) * sizeof *dp_of);
  if (!st && !dp_of) st = wl_error_set(err, WL_ENOMEM, "snapshots: no memory");
  if (!st) {
    int k = 0;
    for (int l = 0; l < 2; l++) {
      const float dp = (float)wl_sph_sim_const(wl_vres_level(v, l))->dp;
      for (int i = 0; i < p[l]->n; i++) {
        if (p[l]->body[i] == WL_SPH_BODY_EXCLUDED) continue;
        for (int a = 0; a < 2; a++) m.pos[a][k] = p[l]->pos[a][i], m.vel[a][k] = p[l]->vel[a][i];
        m.rho[k] = p[l]->rho[i];
        m.kind[k] = p[l]->kind[i];
        m.body[k] = p[l]->body[i];
        dp_of[k++] = dp;
      }
    }
    m.n = n;
    st = write_snapshot(rc, &m, wl_sph_sim_const(wl_vres_level(v, 1)), dp_of, t, err);
  }
  free(dp_of);
  wl_particles_clear(&m);
  return st;
}

/* One output of a two-resolution run: the fine level's row (wall, probes,
 * the gauges it owns), the coarse level's gauges seaward of the interface,
 * and the energies and momentum of the water each level owns. */
static enum wl_status levels_output(struct run_ctx *rc, struct wl_vres *v, double t,
                                    struct wl_error *err) {
  if (rc->opts->interrupted && *rc->opts->interrupted)
    return wl_error_set(err, WL_EINTERRUPTED, "interrupted by %s while stepping, at t = %.4f s",
                        wl_assess_stop_signal_name((int)*rc->opts->interrupted), t);
  struct wl_sph_sim *fine = wl_vres_level(v, 1), *coarse = wl_vres_level(v, 0);
  const struct wl_particles *pf = wl_sph_sim_particles(fine, err);
  if (!pf) return err->status ? err->status : WL_EIO;
  struct wl_record *r = &rc->c->rec;
  enum wl_status st = wl_sample_sim(rc->sample, fine, pf, t, r, err);
  if (st) return st;
  const struct wl_particles *pc = wl_sph_sim_particles(coarse, err);
  if (!pc) return err->status ? err->status : WL_EIO;
  struct wl_record *rq = &rc->row_coarse;
  rq->n = 0;
  const struct wl_sph_config *cc = wl_sph_sim_config(coarse);
  if ((st = wl_sample_state(rc->sample_coarse, pc, wl_sph_sim_const(coarse), cc->hi[1], t, rq,
                            err)))
    return st;
  const size_t row = r->n - 1;
  const struct wl_flume *f = &rc->c->flume;
  for (int g = 0; g < f->n_gauges; g++)
    if (f->gauge_x[g] < rc->x_interface)
      r->eta[row * (size_t)r->n_gauges + (size_t)g] = rq->eta[g];
  r->kinetic[row] += rq->kinetic[0];
  r->potential[row] += rq->potential[0];
  r->momentum[row] += rq->momentum[0];
  if (rc->snaps && t >= rc->next_snapshot - 1e-12) {
    if ((st = levels_snapshot(rc, v, t, err))) return st;
    rc->next_snapshot += rc->snapshot_interval;
  }
  return WL_OK;
}

/* Step the two levels of a case (levels.c) to its end, sampling every
 * output_dt, as wl_sph_sim_run does for one. */
static enum wl_status run_levels(struct run_ctx *rc, const struct wl_backend_ops *ops,
                                 const struct wl_vres_level_spec spec[2],
                                 const struct wl_vres_opts *vo, const struct wl_flume *coarse,
                                 struct wl_error *err) {
  struct wl_case_result *c = rc->c;
  struct wl_vres *v = NULL;
  rc->x_interface = 0.5 * (spec[0].own_hi + spec[1].own_lo);
  c->x_interface = rc->x_interface;
  c->dp_coarse = coarse->cfg.prm.dp;
  rc->row_coarse.n_gauges = coarse->n_gauges;
  rc->row_coarse.n_probes = coarse->n_probes;
  enum wl_status st = wl_vres_alloc(&v, ops, 2, spec, vo, err);
  if (!st && coarse->has_paddle) {
    struct wl_sph_motion m = {0};
    m.type = WL_SPH_MOTION_TABLE;
    m.n = coarse->n_paddle;
    m.t = coarse->paddle_t;
    m.x = coarse->paddle_x;
    st = wl_sph_sim_set_motion(wl_vres_level(v, 0), WL_FLUME_BODY_PADDLE, &m, err);
  }
  if (!st) st = wl_sample_alloc(&rc->sample, &c->flume, err);
  if (!st) st = wl_sample_alloc(&rc->sample_coarse, coarse, err);
  if (st) {
    wl_vres_free(v);
    return st;
  }
  wl_sample_set_range(rc->sample, rc->x_interface, INFINITY);
  wl_sample_set_range(rc->sample_coarse, -INFINITY, rc->x_interface);
  const struct wl_sph_const *k = wl_sph_sim_const(wl_vres_level(v, 1));
  c->h = k->h_d;
  c->c0 = k->c0_d;
  rc->snapshot_interval = rc->opts->snapshot_interval > 0 ? rc->opts->snapshot_interval
                                                           : c->t_end / 20.0;
  const double output_dt = c->flume.cfg.prm.dp > 0 ? c->output_dt : 0.01;
  const double mass0 = wl_vres_own_mass(v, err);
  const double wall0 = now_s();
  double wall_next = wall0 + 0.5;
  long m = 1;
  st = levels_output(rc, v, 0.0, err);
  while (st == WL_OK && wl_vres_time(v) < c->t_end) {
    double t_out = output_dt > 0 ? (double)m * output_dt : c->t_end;
    if (t_out > c->t_end) t_out = c->t_end;
    const double rest = t_out - wl_vres_time(v);
    if (!(rest > 1e-12 * t_out)) {
      m++;
      continue;
    }
    const double dt = fmin(wl_sph_sim_dt(wl_vres_level(v, 0)), wl_sph_sim_dt(wl_vres_level(v, 1)));
    int lands;
    const double dt_max = wl_sph_dt_toward(rest, dt, &lands);
    if ((st = wl_vres_step(v, dt_max, err))) break;
    if (fabs(wl_vres_time(v) - t_out) <= 1e-9 * fmax(t_out, 1.0)) {
      st = levels_output(rc, v, t_out, err);
      m++;
    }
    const double now = now_s();
    if (rc->opts->progress && (now >= wall_next || wl_vres_time(v) >= c->t_end)) {
      struct wl_sph_progress pr;
      pr.t = wl_vres_time(v);
      pr.t_end = c->t_end;
      pr.step = wl_sph_sim_steps(wl_vres_level(v, 1));
      pr.dt = dt;
      pr.wall_s = now - wall0;
      pr.steps_per_s = pr.wall_s > 0 ? (double)pr.step / pr.wall_s : 0;
      pr.n = c->n_particles;
      pr.particle_steps_per_s = pr.steps_per_s * pr.n;
      pr.eta_s = pr.t > 0 ? pr.wall_s * (c->t_end - pr.t) / pr.t : 0;
      pr.runs = 0, pr.done = 0.0;
      rc->opts->progress(rc->opts->user, c->name, &pr);
      wall_next = now + 0.5;
    }
  }
  c->t_reached = wl_vres_time(v);
  c->steps = wl_sph_sim_steps(wl_vres_level(v, 1));
  {
    struct wl_error merr;
    wl_error_clear(&merr);
    c->water_change = wl_vres_own_mass(v, &merr) / mass0 - 1.0;
  }
  c->n_limited = c->n_excluded = 0;
  for (int l = 0; l < 2; l++) {
    c->n_limited += wl_sph_sim_limited(wl_vres_level(v, l));
    c->n_excluded += wl_sph_sim_excluded(wl_vres_level(v, l));
  }
  wl_vres_free(v);
  return st;
}

static void on_progress(void *user, const struct wl_sph_progress *pr) {
  struct run_ctx *rc = user;
  if (rc->opts->progress) rc->opts->progress(rc->opts->user, rc->c->name, pr);
}

/* The backend of a run: opts->backend when set, else the scenario's
 * run.backend; "auto" takes the GPU when wl_cuda_device_query finds one, else
 * the CPU. WL_EUNSUPPORTED for cuda without a usable GPU (or CUDA build). */
static enum wl_status pick_backend(const struct wl_scenario *s, const struct wl_assess_opts *opts,
                                   const struct wl_backend_ops **ops, struct wl_error *err) {
  enum wl_backend_choice choice = s->run.backend.choice;
  if (opts->backend && !strcmp(opts->backend, "cpu")) choice = WL_BACKEND_CPU;
  else if (opts->backend && !strcmp(opts->backend, "cuda")) choice = WL_BACKEND_CUDA;
  else if (opts->backend && !strcmp(opts->backend, "auto")) choice = WL_BACKEND_AUTO;
  *ops = &wl_backend_cpu_ops;
  if (choice == WL_BACKEND_CPU) return WL_OK;
  struct wl_cuda_device dev;
  struct wl_error qerr;
  wl_error_clear(&qerr);
  if (wl_cuda_device_query(&dev, &qerr) == WL_OK) *ops = &wl_backend_cuda_ops;
  else if (choice == WL_BACKEND_CUDA)
    return wl_error_set(err, WL_EUNSUPPORTED, "%s: backend cuda: %s", s->path, qerr.msg);
  return WL_OK;
}

/* 1 with the GPU in *dev when the scenario's run goes to the CUDA backend. */
static int run_device(const struct wl_scenario *s, const struct wl_assess_opts *opts,
                      struct wl_cuda_device *dev) {
  const struct wl_backend_ops *ops;
  struct wl_error perr;
  wl_error_clear(&perr);
  if (pick_backend(s, opts, &ops, &perr) != WL_OK || ops != &wl_backend_cuda_ops) return 0;
  wl_error_clear(&perr);
  return wl_cuda_device_query(dev, &perr) == WL_OK;
}

double assess_gpu_memory(const struct wl_scenario *s, const struct wl_assess_opts *opts) {
  struct wl_cuda_device dev;
  return run_device(s, opts, &dev) ? (double)dev.memory_total : 0.0;
}

void wl_assess_machine(const struct wl_scenario *s, const struct wl_assess_opts *opts,
                       struct wl_plan_machine *m) {
  memset(m, 0, sizeof *m);
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) m->host_bytes = (double)pages * (double)page;
  struct wl_cuda_device dev; /* a backend that cannot be had: the run says why */
  if (run_device(s, opts, &dev)) {
    m->device_bytes = (double)dev.memory_total;
    snprintf(m->device_name, sizeof m->device_name, "%s", dev.name);
  }
  m->threads = opts->threads > 0                 ? opts->threads
               : s->run.threads.is_auto          ? omp_get_max_threads()
                                                 : (int)s->run.threads.q.si;
  m->budget_seconds = WL_PLAN_BUDGET_DEFAULT_S;
}

/* Run one case into c (its flume already built). Returns the run's status;
 * the record holds what was sampled before any stop. */
static enum wl_status run_case(const struct wl_assess_opts *opts,
                               const struct wl_backend_ops *ops, const char *snap_path, int defer,
                               struct case_levels *lv, struct wl_case_result *c,
                               struct wl_error *err) {
  struct run_ctx rc;
  memset(&rc, 0, sizeof rc);
  rc.c = c;
  rc.opts = opts;
  struct wl_sph_sim *sim = NULL;
  double start = now_s();
  enum wl_status st = WL_OK;
  if (!lv) st = wl_sph_sim_alloc(&sim, ops, &c->flume.cfg, &c->flume.particles, err);
  if (!st && !lv && c->flume.has_paddle) {
    struct wl_sph_motion m = {0};
    m.type = WL_SPH_MOTION_TABLE;
    m.n = c->flume.n_paddle;
    m.t = c->flume.paddle_t;
    m.x = c->flume.paddle_x;
    st = wl_sph_sim_set_motion(sim, WL_FLUME_BODY_PADDLE, &m, err);
  }
  if (!st && !lv) st = wl_sample_alloc(&rc.sample, &c->flume, err);
  char xmf[1100] = "";
  if (snap_path) {
    snprintf(xmf, sizeof xmf, "%.*s.xmf", (int)(strlen(snap_path) - 3), snap_path);
    if (defer) { /* an earlier level's index, never to be moved into place */
      char old[1110];
      snprintf(old, sizeof old, "%s.tmp", xmf);
      remove(old);
    }
  }
  if (!st && snap_path) st = wl_store_open(snap_path, &rc.snaps, err);
  if (!st && lv) {
    st = run_levels(&rc, ops, lv->spec, &lv->vo, &lv->coarse, err);
  } else if (!st) {
    const struct wl_sph_const *k = wl_sph_sim_const(sim);
    c->h = k->h_d;
    c->c0 = k->c0_d;
    rc.snapshot_interval =
        opts->snapshot_interval > 0 ? opts->snapshot_interval : c->t_end / 20.0;
    struct wl_sph_run_opts ro = {0};
    ro.t_end = c->t_end;
    ro.output_dt = c->flume.cfg.prm.dp > 0 ? c->output_dt : 0.01;
    ro.output = on_output;
    ro.progress = on_progress;
    ro.progress_wall_s = 0.5;
    ro.user = &rc;
    st = wl_sph_sim_run(sim, &ro, err);
  }
  if (sim) {
    c->t_reached = wl_sph_sim_time(sim);
    c->steps = wl_sph_sim_steps(sim);
    c->n_limited = wl_sph_sim_limited(sim);
    c->n_excluded = wl_sph_sim_excluded(sim);
  }
  c->runtime_s = now_s() - start;
  if (rc.snaps) {
    /* the snapshots so far (a stopped run's too), unless writing them failed */
    struct wl_error serr;
    wl_error_clear(&serr);
    const char *base = strrchr(snap_path, '/');
    base = base ? base + 1 : snap_path;
    enum wl_status s2;
    if (defer) {
      struct wl_store_batch b;
      wl_store_batch_init(&b);
      s2 = wl_store_close_batch(rc.snaps, &b, &serr);
      if (!s2) c->snapshot_files |= 1;
      if (!s2 && rc.n_refs) s2 = wl_store_write_xdmf_batch(xmf, base, rc.refs, rc.n_refs, &b, &serr);
      if (!s2 && rc.n_refs) c->snapshot_files |= 2;
      /* not committed here: write_results moves them with the results */
    } else {
      s2 = wl_store_close(rc.snaps, 1, &serr);
      if (!s2 && rc.n_refs) s2 = wl_store_write_xdmf(xmf, base, rc.refs, rc.n_refs, &serr);
    }
    if (s2 && !st) {
      *err = serr;
      st = s2;
    }
  }
  wl_sample_free(rc.sample);
  wl_sample_free(rc.sample_coarse);
  wl_sample_record_clear(&rc.row_coarse);
  wl_sph_sim_free(sim);
  free(rc.refs);
  return st;
}

void wl_assess_case_clear(struct wl_case_result *c) {
  if (!c) return;
  if (c->still_owned && c->still) {
    wl_assess_case_clear(c->still);
    free(c->still);
  }
  wl_sample_record_clear(&c->rec);
  case_loads_clear(&c->loads);
  wl_flume_clear(&c->flume);
  memset(c, 0, sizeof *c);
}

void wl_assess_result_clear(struct wl_assess_result *res) {
  if (!res) return;
  for (int i = 0; i < res->n_cases; i++) wl_assess_case_clear(&res->cases[i]);
  memset(res, 0, sizeof *res);
}

/* Late peak: the planned end time is an estimate (plan.c: the solitary
 * wave's passage, the explosion train's travel at 2/3 of sqrt(g h)); when
 * the filtered peak force falls in the last tenth of the searched record
 * the load may still be rising (seawall.yaml's explosion at 8 m peaked
 * 0.5 s before its end), and the result says so rather than passing the
 * record's last maximum off as the peak. A positive impulse that the
 * force at rest's own uncertainty moves by more than WL_ASSESS_REST_CAUTION
 * is named too. */
static void case_caution(struct wl_case_result *c) {
  c->caution[0] = '\0';
  const double t0 = c->peak_from, t1 = c->t_reached, tp = c->loads.force_peak.time;
  if (c->status != WL_OK || !c->rec.n || !(t1 > t0) || !isfinite(tp)) return;
  if (tp >= t1 - 0.1 * (t1 - t0))
    snprintf(c->caution, sizeof c->caution,
             "the peak force comes at t = %.3g s, in the last tenth of the record (%.3g to %.3g "
             "s): a larger load may follow; run longer (run.end_time)",
             tp, t0, t1);
  const struct wl_case_loads *l = &c->loads;
  if (c->still && !l->drift) {
    const size_t used = strlen(c->caution);
    snprintf(c->caution + used, sizeof c->caution - used,
             "%sthe still-water reference run %s: the impulses keep the flume's own drift at the "
             "wall (run.still_reference)",
             used ? "; " : "",
             c->still->status == WL_OK ? "did not sample the case's times" : "did not complete");
  }
  const double share = l->impulse_positive_rest_error / l->impulse_positive;
  if (share > WL_ASSESS_REST_CAUTION) {
    const size_t used = strlen(c->caution);
    snprintf(c->caution + used, sizeof c->caution - used,
             "%sthe positive impulse is uncertain by %.2g %% from the force at rest alone: "
             "that force is known to about +-%.2g N/m (the halves of its window differ by twice "
             "that) and the wave lifts the force by %.0f %% of it",
             used ? "; " : "", 100.0 * share, l->rest_force_spread,
             100.0 * (l->force_peak.value - l->rest_force) / l->rest_force);
  }
  /* the explosion's waves at the wall, in particles (once the record runs
   * past their planned arrival, twice peak_from) */
  const double pph = l->runup / c->dp;
  if (c->load == WL_CASE_EXPLOSION && !c->still_run && t1 >= 2.0 * t0 &&
      pph < WL_ASSESS_EXPLOSION_RUNUP_PPH_MIN) {
    const size_t used = strlen(c->caution);
    snprintf(c->caution + used, sizeof c->caution - used,
             "%sthe run-up at the wall (%.3g m) is %.1f particles high at dp = %.3g m: under "
             "%.0f the explosion's short waves lose height before the wall and its loads may lie "
             "outside the ladder's band (seawall.yaml's at 1.9: its positive impulse 27 %% under "
             "a finer ladder's); quote them from a finer spacing",
             used ? "; " : "", l->runup, pph, c->dp, WL_ASSESS_EXPLOSION_RUNUP_PPH_MIN);
  }
}

enum wl_status wl_assess_case(const struct wl_scenario *s, const struct wl_plan *plan,
                              enum wl_load_case load, const struct wl_assess_opts *opts,
                              const char *snapshots, struct wl_case_result *c,
                              struct wl_error *err) {
  return assess_case(s, plan, load, opts, snapshots, 0, c, err);
}

enum wl_status assess_attach_still(struct wl_case_result *c, struct wl_case_result *still,
                                   struct wl_error *err) {
  if (c->still_owned && c->still) {
    wl_assess_case_clear(c->still);
    free(c->still);
  }
  c->still = still;
  c->still_owned = 0;
  case_loads_clear(&c->loads);
  enum wl_status st = case_loads_compute(c, err);
  if (!st) case_caution(c);
  return st;
}

/* The still-water reference run of case `load` (plan.h) into *t: the case's
 * plan with still_flume set, no snapshots, its own progress label. */
static enum wl_status run_still(const struct wl_scenario *s, const struct wl_plan *plan,
                                enum wl_load_case load, const struct wl_assess_opts *opts,
                                int how, struct wl_case_result *t, struct wl_error *err) {
  struct wl_plan *ps = malloc(sizeof *ps);
  if (!ps) return wl_error_set(err, WL_ENOMEM, "no memory for the still-water reference run");
  *ps = *plan;
  ps->still_flume = 1;
  enum wl_status st = assess_case(s, ps, load, opts, NULL,
                                  (how & ASSESS_URGENT) | ASSESS_NO_STILL | ASSESS_STILL_RUN, t,
                                  err);
  free(ps);
  return st;
}

/* One run of a case (assess_case without its still-water reference). */
static enum wl_status assess_one(const struct wl_scenario *s, const struct wl_plan *plan,
                                 enum wl_load_case load, const struct wl_assess_opts *opts,
                                 const char *snapshots, int how, struct wl_case_result *c,
                                 struct wl_error *err) {
  memset(c, 0, sizeof *c);
  c->load = load;
  snprintf(c->name, sizeof c->name, "%s%s", wl_flume_case_name(load),
           how & ASSESS_STILL_RUN ? ", still water" : "");
  c->still_run = (how & ASSESS_STILL_RUN) != 0;
  enum wl_status st = wl_flume_build(s, plan, load, &c->flume, err);
  if (st) return st;
  const struct wl_backend_ops *ops = NULL;
  if ((st = pick_backend(s, opts, &ops, err))) return st;
  struct case_levels *lv = NULL;
  if (load == WL_CASE_SOLITARY ? plan->solitary.refine : plan->explosion.refine) {
    /* from: auto in a plan made without the machine (wl_plan_refine_machine) */
    if (s->resolution.refine.from.is_auto && ops != &wl_backend_cpu_ops)
      return wl_error_set(err, WL_EUSAGE,
                          "%s: resolution.refine.from: auto was planned for the CPU backend, and "
                          "this run takes the %s backend; use --backend cpu, or let `wallload "
                          "assess` plan it for this machine",
                          s->path, ops->name);
    if (!(lv = calloc(1, sizeof *lv))) return wl_error_set(err, WL_ENOMEM, "no memory");
    if ((st = levels_build(s, plan, load, &c->flume, &lv->coarse, lv->spec, &lv->vo, err))) {
      wl_flume_clear(&lv->coarse);
      free(lv);
      return st;
    }
    if (opts->threads > 0) lv->coarse.cfg.n_threads = opts->threads;
  }
  if (opts->threads > 0) c->flume.cfg.n_threads = opts->threads;
  if (how & ASSESS_URGENT) c->flume.cfg.priority = 1;
  c->t_end = opts->end_time > 0 ? opts->end_time : c->flume.t_end;
  c->output_dt = s->run.output_interval.q.si;
  c->dp = plan->dp;
  c->n_particles = c->flume.particles.n;
  c->n_fluid = c->flume.particles.n - c->flume.particles.n_bound;
  if (lv) {
    c->n_particles += lv->coarse.particles.n;
    c->n_fluid += lv->coarse.particles.n - lv->coarse.particles.n_bound;
  }
  c->static_force = c->flume.static_force;
  c->static_moment = c->flume.static_moment;
  c->depth_wall = c->flume.depth_wall;
  c->peak_from = load == WL_CASE_SOLITARY    ? 0.5 * plan->solitary.arrival_time
                 : load == WL_CASE_EXPLOSION ? 0.5 * plan->explosion.arrival_time
                                             : 0.0;
  if (!(c->peak_from > 0) || c->peak_from > 0.5 * c->t_end) c->peak_from = 0.0;
  c->quiet_until = load == WL_CASE_SOLITARY    ? plan->solitary.quiet_until
                   : load == WL_CASE_EXPLOSION ? plan->explosion.quiet_until
                                               : 0.0;
  c->rec.n_gauges = c->flume.n_gauges;
  c->rec.n_probes = c->flume.n_probes;
  c->status = run_case(opts, ops, snapshots, (how & ASSESS_DEFER) != 0, lv, c, err);
  if (lv) wl_flume_clear(&lv->coarse);
  free(lv);
  if (c->status != WL_OK) snprintf(c->message, sizeof c->message, "%s", err->msg);
  struct wl_error lerr;
  wl_error_clear(&lerr);
  if ((st = case_loads_compute(c, &lerr))) {
    if (c->status == WL_OK) *err = lerr;
    return c->status ? c->status : st;
  }
  case_caution(c);
  return c->status;
}

struct still_job {
  const struct wl_scenario *s;
  const struct wl_plan *plan;
  enum wl_load_case load;
  struct wl_assess_opts opts;
  int how;
  struct wl_case_result *t;
  struct wl_error err;
  enum wl_status st;
};

static void *still_thread(void *arg) {
  struct still_job *j = arg;
  j->st = run_still(j->s, j->plan, j->load, &j->opts, j->how, j->t, &j->err);
  return NULL;
}

enum wl_status assess_case(const struct wl_scenario *s, const struct wl_plan *plan,
                           enum wl_load_case load, const struct wl_assess_opts *opts,
                           const char *snapshots, int how, struct wl_case_result *c,
                           struct wl_error *err) {
  const int want_still = !(how & ASSESS_NO_STILL) &&
                         (load == WL_CASE_SOLITARY    ? plan->solitary.still_reference
                          : load == WL_CASE_EXPLOSION ? plan->explosion.still_reference
                                                      : 0);
  const struct wl_backend_ops *ops = NULL;
  struct wl_error berr;
  wl_error_clear(&berr);
  struct wl_case_result *t = want_still ? calloc(1, sizeof *t) : NULL;
  if (!want_still || !t || pick_backend(s, opts, &ops, &berr) != WL_OK) {
    free(t); /* no reference (or no memory, or no backend: the case says why) */
    return assess_one(s, plan, load, opts, snapshots, how, c, err);
  }
  /* The still-water reference (plan.h): beside the case on a GPU (its own
   * thread and stream, without progress), before it on the CPU, whose
   * threads the case needs; an interrupted reference stops the case. */
  struct still_job j = {s, plan, load, *opts, how, t, {0}, WL_OK};
  wl_error_clear(&j.err);
  pthread_t tid;
  int threaded = 0;
  if (ops != &wl_backend_cpu_ops) {
    j.opts.progress = NULL;
    threaded = pthread_create(&tid, NULL, still_thread, &j) == 0;
  }
  if (!threaded) still_thread(&j);
  enum wl_status st;
  if (!threaded && j.st == WL_EINTERRUPTED) {
    memset(c, 0, sizeof *c);
    c->load = load;
    snprintf(c->name, sizeof c->name, "%s", wl_flume_case_name(load));
    *err = j.err;
    wl_error_prefix(err, "the still-water reference run: ");
    c->status = st = j.st;
    snprintf(c->message, sizeof c->message, "%s", err->msg);
  } else {
    st = assess_one(s, plan, load, opts, snapshots, how, c, err);
  }
  if (threaded) pthread_join(tid, NULL);
  c->still = t;
  c->still_owned = 1;
  if (c->rec.n > 0) { /* the loads again, with the reference's drift */
    struct wl_error lerr;
    wl_error_clear(&lerr);
    case_loads_clear(&c->loads);
    enum wl_status lst = case_loads_compute(c, &lerr);
    if (lst && st == WL_OK) *err = lerr, st = lst;
    if (!lst) case_caution(c);
  }
  if (st == WL_OK && j.st == WL_EINTERRUPTED) { /* the reference stopped, the case did not */
    *err = j.err;
    wl_error_prefix(err, "the still-water reference run: ");
    c->status = st = WL_EINTERRUPTED;
    snprintf(c->message, sizeof c->message, "%s", err->msg);
  }
  return st;
}

static enum wl_status prepare_dir(const char *dir, int force, struct wl_error *err) {
  struct stat sb;
  if (stat(dir, &sb) == 0) {
    if (!S_ISDIR(sb.st_mode))
      return wl_error_set(err, WL_EINPUT, "%s: exists and is not a directory; choose another with -o",
                          dir);
    if (!force)
      return wl_error_set(err, WL_EINPUT,
                          "%s: the output directory exists; use --force to write into it, or -o "
                          "to choose another",
                          dir);
    return WL_OK;
  }
  if (mkdir(dir, 0777) != 0)
    /* a path the user chose that cannot be one (missing parent, a file in
     * the way, no permission) is bad input; a full or failing disk is not */
    return wl_error_set(err, errno == ENOSPC || errno == EIO || errno == EDQUOT ? WL_EIO : WL_EINPUT,
                        "%s: cannot create the output directory (%s)", dir,
                        strerror(errno));
  return WL_OK;
}

/* The output directory's lock: DIR/.wallload.lock holds the writer's pid,
 * created exclusively, so a second `assess` into the same directory is
 * refused with the first one's pid instead of both writing (or one failing
 * inside HDF5's own lock). A lock whose process is gone is stale: taken
 * over, and the temporary files the killed run left (*.tmp, *.part: the
 * atomic writes' halves) are removed. */
enum wl_status wl_assess_lock_dir(const char *dir, char *lock, size_t size, struct wl_error *err) {
  snprintf(lock, size, "%s/.wallload.lock", dir);
  for (int attempt = 0; attempt < 2; attempt++) {
    const int fd = open(lock, O_CREAT | O_EXCL | O_WRONLY, 0644);
    if (fd >= 0) {
      char pid[32];
      const int len = snprintf(pid, sizeof pid, "%ld\n", (long)getpid());
      const ssize_t w = write(fd, pid, (size_t)len);
      int e = w == len ? 0 : w < 0 ? errno : ENOSPC; /* a short write: the disk is full */
      if (close(fd) != 0 && !e) e = errno;
      if (e) {
        unlink(lock);
        return wl_error_set(err, WL_EIO, "%s: cannot write the lock file: %s", lock, strerror(e));
      }
      break;
    }
    if (errno != EEXIST)
      return wl_error_set(err, WL_EIO, "%s: cannot create the lock file (%s)", lock,
                          strerror(errno));
    long other = 0;
    FILE *f = fopen(lock, "r");
    if (f) {
      if (fscanf(f, "%ld", &other) != 1) other = 0;
      fclose(f);
    }
    if (other > 0 && kill((pid_t)other, 0) == 0)
      return wl_error_set(err, WL_EINPUT,
                          "%s: being written by wallload process %ld (%s); wait for it to end, or "
                          "choose another directory with -o",
                          dir, other, lock);
    if (attempt == 1 || unlink(lock) != 0)
      return wl_error_set(err, WL_EIO, "%s: a stale lock file cannot be removed", lock);
  }
  DIR *d = opendir(dir);
  if (d) {
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
      const size_t n = strlen(e->d_name);
      if ((n > 4 && !strcmp(e->d_name + n - 4, ".tmp")) ||
          (n > 5 && !strcmp(e->d_name + n - 5, ".part"))) {
        char path[1200];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        unlink(path);
      }
    }
    closedir(d);
  }
  return WL_OK;
}

static enum wl_status assess_locked(const struct wl_scenario *s, const struct wl_plan *plan,
                                    const struct wl_assess_opts *opts,
                                    struct wl_assess_result *res, struct wl_error *err);

enum wl_status wl_assess_run(const struct wl_scenario *s, const struct wl_plan *plan,
                             const struct wl_assess_opts *opts, struct wl_assess_result *res,
                             struct wl_error *err) {
  memset(res, 0, sizeof *res);
  if (opts->out_dir)
    snprintf(res->out_dir, sizeof res->out_dir, "%s", opts->out_dir);
  else
    snprintf(res->out_dir, sizeof res->out_dir, "%s-results", s->name.text);
  const struct wl_backend_ops *ops;
  enum wl_status st = pick_backend(s, opts, &ops, err);
  if (st) return st;
  snprintf(res->backend, sizeof res->backend, "%s", ops->name);
  if (opts->write_lock && !(opts->no_snapshots && opts->no_report))
    return wl_error_set(err, WL_EINPUT, "assess: a write lock needs no_snapshots and no_report "
                        "(snapshots and the report write HDF5 outside it)");
  /* input the plan found unusable is refused before anything is written */
  if (plan->solitary.present && (st = wl_plan_solitary_runnable(s, plan, err))) return st;
  if ((st = prepare_dir(res->out_dir, opts->force, err))) return st;
  char lock[1100];
  if ((st = wl_assess_lock_dir(res->out_dir, lock, sizeof lock, err))) return st;
  st = assess_locked(s, plan, opts, res, err);
  unlink(lock);
  return st;
}

/* Add a second failure to a reported one ("...; then ..."), so that a
 * write failure after a stopped case (or a report failure after either)
 * hides neither. */
static void add_failure(struct wl_error *err, const char *what, const char *msg) {
  char buf[WL_ERROR_MSG_MAX];
  snprintf(buf, sizeof buf, "%s; %s: %s", err->msg, what, msg);
  snprintf(err->msg, sizeof err->msg, "%s", buf);
}

/* Remove a case's snapshot files still waiting under their temporary
 * names (snapshot_files bits 0-1). */
static void discard_snapshots(const char *dir, struct wl_case_result *c) {
  static const char *const ext[2] = {"h5", "xmf"};
  for (int k = 0; k < 2; k++)
    if (c->snapshot_files & (1 << k)) {
      char tmp[1200];
      snprintf(tmp, sizeof tmp, "%s/particles_%s.%s.tmp", dir, c->name, ext[k]);
      remove(tmp);
    }
  c->snapshot_files &= ~3;
}

/* The load cases side by side on one GPU (issue 21): a small flume's step
 * leaves most of the GPU idle, so the cases run at once, each in its own
 * thread and CUDA stream, as a ladder's levels do (ladder.c) and a sweep's
 * cases (src/sweep/run.c); each case's results are those it gives alone
 * (every run is deterministic on its own stream). On the GPU only (the CPU
 * backend's threads are the cores'), not inside a sweep that already runs
 * its assessments side by side (opts->write_lock), with snapshots only
 * where HDF5 may be written from two threads, and when every case's runs
 * (its ladder's levels side by side) fit CASES_GPU_MEMORY_SHARE of the
 * GPU's memory together (the plan's estimate). */
#define CASES_GPU_MEMORY_SHARE 0.5

static int cases_side_by_side(const struct wl_scenario *s, const struct wl_plan *plan,
                              const struct wl_assess_opts *opts, int n) {
  if (n < 2 || opts->write_lock) return 0;
  if (!opts->no_snapshots && !wl_store_thread_safe()) return 0;
  const double gpu = assess_gpu_memory(s, opts);
  if (!(gpu > 0)) return 0;
  const int levels = s->resolution.n_levels > 0 ? s->resolution.n_levels : 1;
  return n * levels * plan->gpu_memory_bytes <= CASES_GPU_MEMORY_SHARE * gpu;
}

/* A case run beside the others (cases_side_by_side). */
struct case_job {
  const struct wl_scenario *s;
  const struct wl_plan *plan;
  enum wl_load_case load;
  struct wl_assess_opts opts; /* no progress: the case in the caller's thread reports */
  char snap[1100];
  const char *snaps;
  struct wl_case_result *c;
  struct wl_assess_convergence *cv;
  struct wl_error err;
  enum wl_status st;
  pthread_t tid;
  int started, ran;
  int urgent; /* the case in the caller's thread: the others finish before it */
};

static void *case_thread(void *arg) {
  struct case_job *j = arg;
  j->st = j->s->resolution.n_levels > 0
              ? ladder_run(j->s, j->plan, j->load, &j->opts, j->snaps, j->urgent, j->c, j->cv,
                           &j->err)
              : assess_case(j->s, j->plan, j->load, &j->opts, j->snaps,
                            ASSESS_DEFER | (j->urgent ? ASSESS_URGENT : 0), j->c, &j->err);
  return NULL;
}

/* A stop signal (SIGINT, SIGTERM, SIGHUP: opts->interrupted) stops the
 * stepping at the next output time (on_output); what was computed is then
 * written, and the report rendered, as after any stop. One that comes after
 * a case's last step (while its results are written) lets that writing and
 * the report finish, and no further case starts; one that comes while the
 * report is rendered lets it finish. Every file written is complete; the
 * run returns WL_EINTERRUPTED, its message naming the signal and the phase
 * ("while stepping", "while writing the results", "while rendering the
 * report").
 *
 * A write the disk refuses (WL_EIO: a full disk) is not followed by more
 * writing of that case: the files of the previous run (or of this run's
 * earlier cases) stay as they were, and the report is rendered only when
 * this run moved results into place. */
/* The cases from `from` on that ran beside the others but were not taken
 * into res (a failure ended the writing first): their waiting snapshot
 * files removed and their results freed. */
static void drop_unwritten(struct wl_assess_result *res, struct case_job *jobs, int from, int n) {
  for (int k = from; k < n; k++)
    if (jobs[k].ran && k >= res->n_cases) {
      discard_snapshots(res->out_dir, &res->cases[k]);
      wl_assess_case_clear(&res->cases[k]);
      jobs[k].ran = 0;
    }
}

static enum wl_status assess_locked(const struct wl_scenario *s, const struct wl_plan *plan,
                                    const struct wl_assess_opts *opts,
                                    struct wl_assess_result *res, struct wl_error *err) {
  enum wl_status st;
  enum wl_load_case todo[2];
  int n = 0;
  if (plan->solitary.present) todo[n++] = WL_CASE_SOLITARY;
  if (plan->explosion.present) todo[n++] = WL_CASE_EXPLOSION;
  enum wl_status overall = WL_OK;
  struct wl_error first;
  wl_error_clear(&first);
  int committed = 0; /* results moved into place by this run */
  /* side by side: every case but the last in its own thread, the last (the
   * longest: the explosion's train travels further) here with the progress;
   * their results are then written in order as if run one after the other */
  struct case_job jobs[2];
  memset(jobs, 0, sizeof jobs);
  if (cases_side_by_side(s, plan, opts, n)) {
    for (int i = 0; i < n; i++) {
      struct case_job *j = &jobs[i];
      j->s = s, j->plan = plan, j->load = todo[i];
      j->opts = *opts;
      if (i + 1 < n) j->opts.progress = NULL;
      snprintf(j->snap, sizeof j->snap, "%s/particles_%s.h5", res->out_dir,
               wl_flume_case_name(todo[i]));
      j->snaps = opts->no_snapshots ? NULL : j->snap;
      j->c = &res->cases[i];
      j->cv = &res->conv[i];
      wl_error_clear(&j->err);
      j->ran = 1;
      j->urgent = i + 1 == n;
      if (i + 1 < n) j->started = pthread_create(&j->tid, NULL, case_thread, j) == 0;
    }
    case_thread(&jobs[n - 1]);
    for (int i = 0; i + 1 < n; i++) {
      if (jobs[i].started) pthread_join(jobs[i].tid, NULL);
      else case_thread(&jobs[i]); /* no thread to be had: here, after the others */
    }
  }
  int i = 0;
  for (; i < n; i++) {
    struct wl_case_result *c = &res->cases[res->n_cases++];
    char snap[1100];
    snprintf(snap, sizeof snap, "%s/particles_%s.h5", res->out_dir, wl_flume_case_name(todo[i]));
    struct wl_error cerr;
    wl_error_clear(&cerr);
    const char *snaps = opts->no_snapshots ? NULL : snap;
    enum wl_status cst;
    if (jobs[i].ran) {
      cst = jobs[i].st;
      cerr = jobs[i].err;
    } else {
      cst = s->resolution.n_levels > 0
                ? ladder_run(s, plan, todo[i], opts, snaps, 1, c, &res->conv[i], &cerr)
                : assess_case(s, plan, todo[i], opts, snaps, ASSESS_DEFER | ASSESS_URGENT, c,
                              &cerr);
    }
    /* the next case already ran beside this one: its results are written
     * too, whatever stopped this one */
    const int next_ran = i + 1 < n && jobs[i + 1].ran;
    res->threads = c->flume.cfg.n_threads > 0 ? c->flume.cfg.n_threads : omp_get_max_threads();
    if (cst != WL_OK && cst != WL_EUNSTABLE && cst != WL_EINTERRUPTED &&
        (c->rec.n == 0 || cst == WL_EIO)) {
      discard_snapshots(res->out_dir, c);
      if (cst == WL_EIO && committed) { /* this run's earlier cases stay, with their report */
        if (overall == WL_OK) overall = cst;
        wl_error_set(&first, cst, "case %s stopped at t = %.4g s of %.4g s: %s", c->name,
                     c->t_reached, c->t_end, cerr.msg);
        break;
      }
      *err = cerr; /* the case could not even start, or the disk refused its files */
      if (cst == WL_EIO && c->rec.n)
        wl_error_prefix(err, "case %s stopped at t = %.4g s of %.4g s: ", c->name, c->t_reached,
                        c->t_end);
      drop_unwritten(res, jobs, i + 1, n);
      return cst;
    }
    if (cst != WL_OK && overall == WL_OK) {
      overall = cst;
      wl_error_set(&first, cst, "case %s stopped at t = %.4g s of %.4g s: %s", c->name,
                   c->t_reached, c->t_end, cerr.msg);
    }
    /* Write after every case, so a later failure keeps this one. */
    if (opts->write_lock) pthread_mutex_lock(opts->write_lock);
    st = write_results(s, plan, res, err);
    if (opts->write_lock) pthread_mutex_unlock(opts->write_lock);
    for (int k = 0; k < res->n_cases; k++) { /* moved into place, or removed */
      struct wl_case_result *ck = &res->cases[k];
      ck->snapshot_files = st ? ck->snapshot_files & ~3
                              : (ck->snapshot_files & ~3) | (ck->snapshot_files & 3) << 2;
    }
    if (st) {
      if (overall != WL_OK) add_failure(err, "before that", first.msg);
      drop_unwritten(res, jobs, i + 1, n);
      return st;
    }
    committed = 1;
    if (next_ran) continue;
    if (c->status == WL_EINTERRUPTED) break;
    if (c->status != WL_OK && c->status != WL_EUNSTABLE) break;
    const int sig = stop_signal(opts);
    if (sig) { /* came after the case's last step */
      if (overall == WL_OK) {
        overall = WL_EINTERRUPTED;
        wl_error_set(&first, WL_EINTERRUPTED,
                     "interrupted by %s while writing the results of case %s (they are "
                     "complete)%s%s%s",
                     wl_assess_stop_signal_name(sig), c->name, i + 1 < n ? "; case " : "",
                     i + 1 < n ? wl_flume_case_name(todo[i + 1]) : "", i + 1 < n ? " not run" : "");
      }
      break;
    }
  }
  drop_unwritten(res, jobs, i + 1, n);
  if (opts->no_report) {
    if (overall != WL_OK) *err = first;
    return overall;
  }
  /* The design report, from the stored results alone (as `wallload
   * report` would); a report failure never hides a run failure. */
  char res_h5[600], pdf[600];
  snprintf(res_h5, sizeof res_h5, "%s/results.h5", res->out_dir);
  snprintf(pdf, sizeof pdf, "%s/report.pdf", res->out_dir);
  const int sig_before = stop_signal(opts);
  struct wl_error rerr;
  wl_error_clear(&rerr);
  enum wl_status rst = wl_report_render(res_h5, NULL, pdf, &rerr);
  if (rst && overall == WL_OK) {
    *err = rerr;
    return rst;
  }
  if (rst) add_failure(&first, "the report was not written either", rerr.msg);
  const int sig = stop_signal(opts);
  if (overall == WL_OK && sig) {
    overall = WL_EINTERRUPTED;
    wl_error_set(&first, WL_EINTERRUPTED,
                 "interrupted by %s %s (the results and %s are complete)", wl_assess_stop_signal_name(sig),
                 sig_before ? "after the results were written" : "while rendering the report",
                 pdf);
  }
  if (overall != WL_OK) {
    *err = first;
    return overall;
  }
  return WL_OK;
}
