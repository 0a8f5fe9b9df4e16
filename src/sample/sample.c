/* sample.c: one row of a case's record at an output time (sample.h):
 * gauges, wall pressure probes and the force they integrate to, the wall's
 * boundary-particle force from the backend, the fluid's energies and
 * momentum. */
#include <math.h>
#include <stdlib.h>

#include "wallload/loads.h"
#include "wallload/sample.h"

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

/* Probe pressures of row `row` (dry at and above z_surface) into r, and
 * the force and moment they integrate to. */
static void sample_probes(struct wl_sample *s, double z_surface, struct wl_record *r, size_t row) {
  const struct wl_flume *f = s->f;
  double *pr = &r->pressure[row * (size_t)r->n_probes];
  int n_wet = 0;
  for (int k = 0; k < f->n_probes; k++) {
    double x[2] = {f->probe_x, f->probe_z[k]}, pk = 0.0;
    if (f->dims == 3) {
      for (int j = 0; j < f->n_probe_y && f->probe_z[k] < z_surface; j++) {
        double x3[3] = {f->probe_x, f->probe_y[j], f->probe_z[k]}, pj = 0.0;
        if (wl_sph_probe_interp(s->probe, x3, NULL, &pj)) pk += pj / f->n_probe_y;
      }
    } else if (f->probe_z[k] >= z_surface || !wl_sph_probe_interp(s->probe, x, NULL, &pk)) {
      pk = 0.0;
    }
    pr[k] = pk;
    if (f->probe_z[k] < z_surface) {
      s->prof_z[n_wet] = f->probe_z[k];
      s->prof_p[n_wet++] = pk;
    }
  }
  if (z_surface <= f->z_toe || n_wet == 0) {
    r->force[row] = r->moment[row] = 0.0;
    return;
  }
  /* the profile ends at (surface, 0), or at the crest when overtopped */
  double top = fmin(z_surface, f->z_crest);
  if (top > s->prof_z[n_wet - 1]) {
    s->prof_z[n_wet] = top;
    s->prof_p[n_wet++] = 0.0;
  }
  if (n_wet == 1) { /* one probe under a thin layer: a triangle */
    s->prof_z[1] = s->prof_z[0];
    s->prof_p[1] = s->prof_p[0];
    n_wet = 2;
  }
  wl_loads_profile(s->prof_z, s->prof_p, (size_t)n_wet, f->z_toe, top, &r->force[row],
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
  /* the water level at the face: the last gauge's */
  const double z_surface =
      f->depth + r->eta[row * (size_t)r->n_gauges + (size_t)(f->n_gauges - 1)];
  sample_probes(s, z_surface, r, row);
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
