/* sample.h: what a run is sampled as at each output time (module sample,
 * src/sample/), the stage between the solver and the loads
 * (ARCHITECTURE.md). Given the solver's particle state and the flume's
 * gauges and probes (flume.h), one call fills one row of a case's record:
 *
 *  - gauges: the free-surface elevation above still water on each gauge's
 *    vertical line, scanned up from the bed under it (a dry gauge reads the
 *    bed, not the domain's floor), where the fluid's Shepard sum falls
 *    below WL_SPH_SURFACE_SHEPARD (sph/probe.h); the flume's last gauge is
 *    the one at the wall face;
 *  - wall pressure probes: the pressure half a spacing seaward of the face
 *    (a line in height fitted to the fluid's pressures, sph/probe.h
 *    wl_sph_point_pressure) where the probe is wet, 0 where it is dry. A probe
 *    is wet where its Shepard sum reaches half of what still water standing
 *    over it would give (flume.h probe_shepard_full): the gauges' surface
 *    rule at the face, where the wall cuts the kernel, so the water on the
 *    face itself decides (a slam or a film above the run-up gauge's level
 *    counts). 3D: each height's pressure is the mean over the probes across
 *    the width (a dry one 0), so that it integrates to the force per metre;
 *  - the probe force and moment about the toe: the profile of every probe
 *    up to the highest wet one, closed by 0 where the wettest probe across
 *    falls through the half on the way to the next probe (or at the crest),
 *    integrated by loads.h wl_loads_profile; a single wet probe is a
 *    triangle; a dry face is 0;
 *  - the force of the fluid on the wall's boundary particles and its moment
 *    about the toe, computed by the backend with the solver's own pair term
 *    (sph.h wl_sph_sim_wall_load); 3D: per metre of the modelled wall;
 *  - the fluid's kinetic and potential energy (above the floor) and its
 *    horizontal momentum; 3D: per metre of the modelled width.
 *
 * Typical use, from the solver's output callback:
 *
 *   wl_sample_alloc(&smp, &flume, &err);
 *   ... at each output time:
 *   p = wl_sph_sim_particles(sim, &err);
 *   wl_sample_sim(smp, sim, p, t, &record, &err);
 *   ...
 *   wl_sample_free(smp);  wl_sample_record_clear(&record); */
#ifndef WALLLOAD_SAMPLE_H
#define WALLLOAD_SAMPLE_H

#include <stddef.h>

#include "wallload/error.h"
#include "wallload/flume.h"
#include "wallload/sph.h"

/* Time series recorded at every output time of one case. Zero-initialise
 * with n_gauges and n_probes set (the flume's); rows are added by the
 * sample calls below (wl_sample_record_push). */
struct wl_record {
  size_t n, cap;
  int n_gauges, n_probes;
  double *t;            /* [s] */
  double *eta;          /* n x n_gauges, elevation above still water [m] */
  double *pressure;     /* n x n_probes [Pa] */
  double *force;        /* from the probes [N/m] */
  double *moment;       /* from the probes, about the toe [N m/m] */
  double *force_bound;  /* summed on the wall's boundary particles [N/m] */
  double *moment_bound; /* their moment about the toe [N m/m] */
  double *kinetic;      /* fluid kinetic energy [J/m] */
  double *potential;    /* fluid potential energy above the floor [J/m] */
  double *momentum;     /* fluid horizontal momentum, sum of m u over the fluid [N s/m]; its
                           change is the impulse the fluid gave all boundaries (wall, bed, ends) */
};

/* Make room for one more row: n grows by one, the caller fills row n - 1.
 * Returns WL_OK or WL_ENOMEM (the record then keeps its n rows). */
enum wl_status wl_sample_record_push(struct wl_record *r, struct wl_error *err);

/* Free the record's series and zero it; safe on a zeroed record. */
void wl_sample_record_clear(struct wl_record *r);

struct wl_sample; /* opaque: the probe's cell index and the wet profile's workspace */

/* A sampler for flume f's gauges and probes (f is kept by pointer and must
 * outlive the sampler; its cfg sizes the probe's cell grid). Returns WL_OK;
 * WL_ENOMEM or WL_EINPUT (the grid, sph.h wl_sph_probe_alloc). On failure
 * *s is NULL. */
enum wl_status wl_sample_alloc(struct wl_sample **s, const struct wl_flume *f,
                               struct wl_error *err);

/* Free a sampler; NULL is accepted. */
void wl_sample_free(struct wl_sample *s);

/* Sum the energies and momentum over the fluid particles with x_lo <= x <
 * x_hi [m] that take part in the run (neither parked nor in a buffer band,
 * vres.h) only: one level of a two-resolution run, each level counting the
 * water it owns. By default every fluid particle counts. */
void wl_sample_set_range(struct wl_sample *s, double x_lo, double x_hi);

/* Sample particle state p (kernel constants k; p is indexed and kept by
 * pointer until the next call) at time t [s] into a new row of r: gauges,
 * probe pressures, probe force and moment, energies and momentum. Gauges
 * scan up to z_top [m] (the domain's top). The row's boundary force and
 * moment are 0 (wl_sample_sim measures them). Returns WL_OK, WL_ENOMEM
 * (no row added) or WL_EINPUT (p of another dimension than the flume). */
enum wl_status wl_sample_state(struct wl_sample *s, const struct wl_particles *p,
                               const struct wl_sph_const *k, double z_top, double t,
                               struct wl_record *r, struct wl_error *err);

/* The whole row of sim's state p (its wl_sph_sim_particles) at time t [s]:
 * wl_sample_state with sim's constants and domain top, and the wall's
 * boundary-particle force and moment from the backend. Returns WL_OK, the
 * errors of wl_sample_state, or the backend's (the row then stays, with
 * what was sampled). */
enum wl_status wl_sample_sim(struct wl_sample *s, struct wl_sph_sim *sim,
                             const struct wl_particles *p, double t, struct wl_record *r,
                             struct wl_error *err);

#endif
