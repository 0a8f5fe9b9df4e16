/* vres.h: variable resolution by coupled subdomains (issue 19, stage A:
 * 2D, CPU backend, levels side by side in x).
 *
 * As DualSPHysics 5.4's VRes (docs/history/2026-11-26-variable-resolution-
 * next.md; measured in docs/history/2026-11-26-variable-resolution-
 * stageA.md): every level is a whole uniform simulation (its own dp, h,
 * mass, particles, walls; today's code path, so every pair is a same-h
 * pair). A level owns the fluid of an x range; beyond each of its open ends
 * it keeps a buffer band `buffer_h` of its own h wide (whole rows of its
 * lattice), which lies inside the neighbouring level's range. After each
 * step (one dt for all levels, the least of their CFL steps):
 *  - each level's fluid is classified by position: its own range: fluid;
 *    a band: buffer (sph/particles.h WL_SPH_BODY_BUFFER: moved with its
 *    velocity, density and velocity not integrated); beyond: removed
 *    (parked, below);
 *  - each buffer particle takes density and velocity from the other
 *    level's own fluid, first-order corrected (sph/vres_fit.h; Shepard's
 *    average where the fit is ill-conditioned); one whose wetness (the
 *    Shepard sum of the other level's fluid, buffer and wall particles) is
 *    below WL_VRES_DRY_MAX is above the other level's water and removed;
 *  - optionally the buffer particles are shifted along the interface
 *    (sph/shift.h's law, coefficient `shift`; the normal component removed
 *    so a band neither gains nor loses particles by it), and with
 *    `shift_across` across it too, less the band's mean displacement across
 *    (spacing the band without a drift of its water through it). A band's
 *    particles move with the donor's velocity and nothing else spaces them
 *    across; unspaced, the symmetric pressure term pushes the fluid beside a
 *    band away from where they crowd: issue 19's pile-up,
 *    docs/history/2026-11-29-vres-band-spacing.md. Spacing them took the
 *    pile-up away but lowered the transmitted wave by about as much, and
 *    which error is left depends on the case (plan.h
 *    WL_PLAN_REFINE_BUFFER_H), so it is measured and off by default;
 *  - inflow refills a band: points one dp apart on its far edge accumulate
 *    the mass flux rho (u . n) dp dt of the other level there (never below
 *    zero; only under its water, wetness WL_VRES_WET_MIN), and each whole
 *    particle mass becomes a new buffer particle dp/2 inside the edge once
 *    no particle is within dp/2 of that place.
 * The two ranges touch or overlap (DualSPHysics 5.4's `overlappingh`;
 * Ricci, Vacondio & Tafuni 2024): in an overlap both levels simulate their
 * own fluid, and each band lies beyond the overlap, so that the donor
 * level's fluid surrounds it and the fit interpolates instead of
 * extrapolating from a cloud on one side. An overlap of at least the
 * coarse level's 2h on either side of the interface completes both fits'
 * supports; at a factor 2 it took the solitary wave's reflection from 3.3
 * to 0.4 % of H (docs/history/2026-11-27-variable-resolution-overlap.md).
 * wl_vres_layout lays two levels out by that rule (one coarse band on
 * either side by default), so that every caller overlaps them alike.
 * Mass is not conserved exactly (the flux points are Eulerian); the run
 * reports each level's own mass, the overlap counted up to its middle by
 * each. Removed particles are parked at rest
 * (WL_SPH_BODY_EXCLUDED) in slots of a rectangle of the level's domain box
 * that holds no water and no wall, and revived for creation; each level is
 * allocated with `spare` of them.
 *
 * Either integrator: buffer particles move with their fitted velocity
 * under both (sph/integrate.h).
 *
 * The coupling runs on the host, on a zone of each level (the particles
 * within its reach of the interface and a flux point's worth of parked
 * ones: backend.h zone_download / zone_upload, sph.h wl_sph_sim_edit_zone),
 * so either backend runs it; on a GPU it costs a round trip and the host's
 * work every step (docs/variable-resolution.md, "On the GPU").
 *
 * Limits of this stage: 2D, two levels, the interface a vertical line, a
 * flat bed under the flux points (z_bed); no loads, gauges or outputs of its
 * own: the caller reads each level (wl_vres_level) in the range it owns. */
#ifndef WALLLOAD_VRES_H
#define WALLLOAD_VRES_H

#include "wallload/backend.h"
#include "wallload/sph.h"

/* Wetness (vres_fit.h's Shepard sum of the donor level's fluid, buffer
 * and wall particles): a full support sums to about 1, the still surface's
 * top row to 0.6-0.7, the surface itself to 0.5, dp above it to 0.1-0.3.
 * Flux points create only under the water; buffer particles are removed
 * only well above it (spray, a falling surface). */
#define WL_VRES_WET_MIN 0.5
#define WL_VRES_DRY_MAX 0.2
#define WL_VRES_LEVELS_MAX 2

struct wl_vres_level_spec {
  const struct wl_sph_config *cfg;    /* its dp, h, walls and domain box */
  const struct wl_particles *initial; /* boundary, then fluid over its range and buffer bands */
  double own_lo, own_hi;              /* the x range it owns [m]; +-INFINITY: no interface there;
                                         the two ranges touch or overlap (above) */
  double park_lo[2], park_hi[2];      /* (x, z) rectangle for parked particles [m] */
  int spare;                          /* parked particles for creation */
};

struct wl_vres_opts {
  double buffer_h; /* buffer width in h of its level (0: 2, DualSPHysics' default) */
  double overlap;  /* wl_vres_layout: the ranges overlap by this many of the coarse level's band
                      widths on either side of the interface (0: 1, the measured choice above;
                      < 0: the ranges touch) */
  double z_bed;    /* the flat bed under the flux points [m] */
  double z_top;    /* the highest the water may reach at a band's far edge [m] */
  double shift;    /* > 0: shift buffer particles along the interface (sph/shift.h's A) */
  int shift_across; /* 1: and across it, less the band's mean (above; measured, not the default) */
};

/* Counts since the start, per level. */
struct wl_vres_counts {
  long created, removed, fitted, shepard, steps;
  double flux_in;  /* mass accumulated at the flux points [kg/m] */
};

struct wl_vres;

/* Where two levels side by side in x, coarse (dp_coarse) on x < x_if and
 * fine beyond, own water, and how far each level's water must be laid for
 * its band (the overlap rule above; each band in whole rows of its level,
 * buffer_h of its h wide). h_over_dp: the levels' common h / dp. Either
 * side may be the fine one: fine_right says which. */
struct wl_vres_layout {
  double own_lo[2], own_hi[2];     /* level 0 coarse, 1 fine: the x range it owns [m] */
  double water_lo[2], water_hi[2]; /* the x range to fill with its water: range and band [m] */
  double band[2];                  /* each level's band width [m] */
  double overlap;                  /* on either side of x_if [m] */
};
void wl_vres_layout(double x_if, double dp_coarse, double dp_fine, double h_over_dp,
                    int fine_right, const struct wl_vres_opts *opts, struct wl_vres_layout *out);

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
 * range, an overlap counted by each level up to its middle, summed [kg, or
 * kg/m in 2D]. */
double wl_vres_own_mass(struct wl_vres *v, struct wl_error *err);
const struct wl_vres_counts *wl_vres_counts(const struct wl_vres *v, int level);

#endif
