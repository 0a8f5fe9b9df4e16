/* vres.h: variable particle resolution by coupled subdomains (issue 19,
 * stage A: 2D, CPU backend, levels side by side in x).
 *
 * As DualSPHysics 5.4's VRes (docs/history/2026-11-26-variable-resolution-
 * next.md): every level is a whole uniform simulation (its own dp, h, mass,
 * particles, walls; today's code path, so every pair is a same-h pair). A
 * level owns the fluid of an x range; beyond each of its open ends it
 * keeps a buffer band `buffer_h` of its own h wide, which lies inside the
 * neighbouring level's range. Unlike DualSPHysics, whose buffer particles
 * move with their interpolated velocity (and need shifting to stay
 * ordered), a band here is a fixed lattice of sites of the level's dp
 * (Eulerian): the buffer particles hold their sites, so the band stays as
 * regular as the level's initial lattice (measured: with moving buffer
 * particles the still tank's largest speed grew to 22 % of sqrt(g h) in
 * 20 sqrt(h/g), with fixed sites it stays at the uniform runs' 2-3 %).
 * After each step (one dt for all levels, the least of their CFL steps):
 *  - a level's fluid that left its own range is removed (parked, below);
 *  - every site takes density and velocity from the other level's own
 *    fluid, first-order corrected (sph/vres_fit.h; Shepard's average where
 *    the fit is ill-conditioned). A site whose donor Shepard sum is below
 *    WL_VRES_WET_MIN lies above the other level's free surface: it holds no
 *    particle (its particle is parked, and revived when the water rises);
 *  - inflow creates fluid: points one dp apart on the level's interface
 *    accumulate the mass flux rho (u . n) dp dt there (the other level's
 *    fit; never below zero), and each whole particle mass becomes a new
 *    fluid particle dp/2 inside the interface, once no particle of the
 *    level is within dp/2 of that place.
 * Mass is conserved only to a particle (removal and creation are
 * quantised, the flux Eulerian); the run reports each level's own mass.
 * Parked particles rest (WL_SPH_BODY_EXCLUDED) in slots of a rectangle of
 * the level's domain box that holds no water and no wall; each level gets
 * one per site plus `spare`.
 *
 * Limits of this stage: 2D, two levels, the interface a vertical line, a
 * flat bed under the sites (z_bed), the symplectic integrator, a backend
 * with upload (the CPU backend); no loads, gauges or outputs of its own:
 * the caller reads each level (wl_vres_level) in the range it owns. */
#ifndef WALLLOAD_VRES_H
#define WALLLOAD_VRES_H

#include "wallload/backend.h"
#include "wallload/sph.h"

/* Sites and flux points with a donor Shepard sum below this are out of the
 * water (a full support sums to about 1, the still surface's top row to
 * about 0.6, a site dp above it to about 0.2). */
#define WL_VRES_WET_MIN 0.5
#define WL_VRES_LEVELS_MAX 2

struct wl_vres_level_spec {
  const struct wl_sph_config *cfg;    /* its dp, h, walls and domain box */
  const struct wl_particles *initial; /* boundary, then fluid over its range and buffer bands */
  double own_lo, own_hi;              /* the x range it owns [m]; +-INFINITY: a closed end */
  double park_lo[2], park_hi[2];      /* (x, z) rectangle for parked particles [m] */
  int spare;                          /* parked particles for creation, beyond one a site */
};

struct wl_vres_opts {
  double buffer_h; /* buffer width in h of its level (0: 2, DualSPHysics' default) */
  double z_bed;    /* the flat bed under the sites and flux points [m] */
  double z_top;    /* the highest the water may reach in a band [m] */
};

/* Counts since the start, per level. */
struct wl_vres_counts {
  long created, removed, fitted, shepard, steps;
  double flux_in;  /* mass accumulated at the flux points [kg/m] */
};

struct wl_vres;

enum wl_status wl_vres_alloc(struct wl_vres **out, const struct wl_backend_ops *ops, int n_levels,
                             const struct wl_vres_level_spec *levels,
                             const struct wl_vres_opts *opts, struct wl_error *err);
void wl_vres_free(struct wl_vres *v);

/* One step of every level with the least CFL step (at most dt_max when > 0),
 * then the coupling above. WL_EUNSTABLE from a level's guard, naming it. */
enum wl_status wl_vres_step(struct wl_vres *v, double dt_max, struct wl_error *err);

double wl_vres_time(const struct wl_vres *v);
struct wl_sph_sim *wl_vres_level(struct wl_vres *v, int level);
/* Whether level `level` owns x. */
int wl_vres_owns(const struct wl_vres *v, int level, double x);
/* Mass of the fluid (not buffer, not parked) each level holds in its own
 * range, summed [kg, or kg/m in 2D]. */
double wl_vres_own_mass(struct wl_vres *v, struct wl_error *err);
const struct wl_vres_counts *wl_vres_counts(const struct wl_vres *v, int level);

#endif
