/* sample.c: one row of a case's record at an output time (sample.h):
 * gauges, wall pressure probes and the force they integrate to, the wall's
 * boundary-particle force from the backend, the fluid's energies and
 * momentum. */
#include <math.h>
#include <stdlib.h>

#include "wallload/loads.h"
#include "wallload/sample.h"
#include "wallload/sph/probe.h"

struct wl_sample {
  const struct wl_flume *f;
  struct wl_sph_probe *probe;
  /* the wet profile: the wet probes, the surface point and, for a single
   * wet probe, its copy */
  double prof_z[WL_FLUME_MAX_PROBES + 2], prof_p[WL_FLUME_MAX_PROBES + 2];
  int ranged; /* wl_sample_set_range */
  double x_lo, x_hi;
};

void wl_sample_set_range(struct wl_sample *s, double x_lo, double x_hi) {
  s->ranged = 1;
  s->x_lo = x_lo, s->x_hi = x_hi;
}

enum wl_status wl_sample_alloc(struct wl_sample **out, const struct wl_flume *f,
                               struct wl_error *err) {
  *out = NULL;
  struct wl_sample *s = calloc(1, sizeof *s);
  if (!s) return wl_error_set(err, WL_ENOMEM, "sample: no memory");
  s->f = f;
  enum wl_status st = wl_sph_probe_alloc(&s->probe, &f->cfg, err);
  if (st) {
    free(s);
    return st;
  }
  *out = s;
  return WL_OK;
}

void wl_sample_free(struct wl_sample *s) {
  if (!s) return;
  wl_sph_probe_free(s->probe);
  free(s);
}

/* Probe pressures of row `row` into r, and the force and moment they
 * integrate to. A probe is wet where its Shepard sum reaches half of what
 * still water standing over it gives (the flume's probe_shepard_full): the
 * open water's surface rule (WL_SPH_SURFACE_SHEPARD) at the face, where
 * the wall cuts the kernel. The face's own water decides, not the run-up
 * gauge's surface 2h off the face: a slam or a film running up the face
 * wets probes above that surface (seawall.yaml's explosion: the probes read
 * 9 % under the boundary particles when they stopped at it). In 3D a
 * height's pressure is the mean over the probes across, a dry one counting
 * 0. The profile holds every probe up to the highest wet one and ends where
 * the wettest probe across falls through the half between that height and
 * the next, or at the crest. */
static void sample_probes(struct wl_sample *s, struct wl_record *r, size_t row) {
  const struct wl_flume *f = s->f;
  double *pr = &r->pressure[row * (size_t)r->n_probes];
  const int ny = f->dims == 3 ? f->n_probe_y : 1;
  const int az = f->dims - 1;
  double wettest[WL_FLUME_MAX_PROBES];
  int top_k = -1;
  for (int k = 0; k < f->n_probes; k++) {
    double psum = 0.0, rmax = 0.0;
    for (int j = 0; j < ny; j++) {
      double x[3] = {f->probe_x, f->dims == 3 ? f->probe_y[j] : 0.0, 0.0};
      x[az] = f->probe_z[k];
      double pj = 0.0;
      const double ratio = wl_sph_probe_pressure(s->probe, x, &pj) / f->probe_shepard_full[k];
      if (ratio >= WL_SPH_SURFACE_SHEPARD) psum += pj;
      if (ratio > rmax) rmax = ratio;
    }
    pr[k] = psum / ny;
    wettest[k] = rmax;
    if (rmax >= WL_SPH_SURFACE_SHEPARD) top_k = k;
  }
  if (top_k < 0) {
    r->force[row] = r->moment[row] = 0.0;
    return;
  }
  int n = 0;
  for (int k = 0; k <= top_k; k++) {
    s->prof_z[n] = f->probe_z[k];
    s->prof_p[n++] = pr[k];
  }
  double top = f->z_crest;
  if (top_k + 1 < f->n_probes) { /* where the wettest probe across crosses the half */
    const double z0 = f->probe_z[top_k], z1 = f->probe_z[top_k + 1];
    const double r0 = wettest[top_k], r1 = wettest[top_k + 1];
    top = z0 + (z1 - z0) * (r0 - WL_SPH_SURFACE_SHEPARD) / (r0 - r1);
  }
  if (top > s->prof_z[n - 1]) {
    s->prof_z[n] = top;
    s->prof_p[n++] = 0.0;
  }
  if (n == 1) { /* one probe under a thin layer: a triangle */
    s->prof_z[1] = s->prof_z[0];
    s->prof_p[1] = s->prof_p[0];
    n = 2;
  }
  wl_loads_profile(s->prof_z, s->prof_p, (size_t)n, f->z_toe, top, &r->force[row],
                   &r->moment[row]);
}

enum wl_status wl_sample_state(struct wl_sample *s, const struct wl_particles *p,
                               const struct wl_sph_const *k, double z_top, double t,
                               struct wl_record *r, struct wl_error *err) {
  const struct wl_flume *f = s->f;
  enum wl_status st = wl_sph_probe_index(s->probe, p, err);
  if (st) return st;
  if ((st = wl_sample_record_push(r, err))) return st;
  const size_t row = r->n - 1;
  r->t[row] = t;
  for (int g = 0; g < f->n_gauges; g++) {
    /* scan up from the bed: a dry gauge reads the bed, not the domain's floor */
    double z = wl_sph_probe_elevation(s->probe, f->gauge_x[g], f->dims == 3 ? f->gauge_y : 0.0,
                                      f->gauge_bed[g], z_top, 0.0);
    r->eta[row * (size_t)r->n_gauges + (size_t)g] = z - f->depth;
  }
  sample_probes(s, r, row);
  r->force_bound[row] = r->moment_bound[row] = 0.0;
  double kin = 0.0, pot = 0.0, mom = 0.0;
  const int az = p->dim - 1;
  for (int i = p->n_bound; i < p->n; i++) {
    if (s->ranged && (p->body[i] == WL_SPH_BODY_EXCLUDED || p->body[i] == WL_SPH_BODY_BUFFER ||
                      !(p->pos[0][i] >= s->x_lo && p->pos[0][i] < s->x_hi)))
      continue;
    mom += (double)k->mass * p->vel[0][i];
    double v2 = (double)p->vel[0][i] * p->vel[0][i] + (double)p->vel[1][i] * p->vel[1][i];
    if (az == 2) v2 += (double)p->vel[2][i] * p->vel[2][i];
    kin += 0.5 * (double)k->mass * v2;
    pot += (double)k->mass * (-k->gravity[az]) * p->pos[az][i];
  }
  if (az == 2) { /* 3D: per metre of width, as in 2D */
    kin /= f->width;
    pot /= f->width;
    mom /= f->width;
  }
  r->kinetic[row] = kin;
  r->potential[row] = pot;
  r->momentum[row] = mom;
  return WL_OK;
}

enum wl_status wl_sample_sim(struct wl_sample *s, struct wl_sph_sim *sim,
                             const struct wl_particles *p, double t, struct wl_record *r,
                             struct wl_error *err) {
  const struct wl_sph_config *cfg = wl_sph_sim_config(sim);
  enum wl_status st =
      wl_sample_state(s, p, wl_sph_sim_const(sim), cfg->hi[cfg->prm.dim - 1], t, r, err);
  if (st) return st;
  /* every fluid-wall pair of the solver's momentum equation; 3D: the
   * backend's sum is the force on the whole modelled wall [N], per metre
   * of it here, likewise the moment */
  const struct wl_flume *f = s->f;
  const size_t row = r->n - 1;
  double force, moment;
  if ((st = wl_sph_sim_wall_load(sim, WL_FLUME_BODY_WALL, f->z_toe, &force, &moment, err)))
    return st;
  if (f->dims == 3) {
    force /= f->width;
    moment /= f->width;
  }
  r->force_bound[row] = force;
  r->moment_bound[row] = moment;
  return WL_OK;
}
