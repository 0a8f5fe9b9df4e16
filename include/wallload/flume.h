/* flume.h: one load case of a scenario as particles and a run
 * configuration: the 2D flume (bed and bathymetry, left end or piston
 * paddle, the seawall with land at its crest behind it, an end wall), the
 * initial condition of the case (still water, solitary wave with its
 * velocity field, paddle motion, crater, thrown mass), the wave gauges and
 * the pressure probes on the wall face.
 *
 * Geometry (x from the paddle / left end, z up from the flume floor):
 *   - the bed is the scenario's bathymetry up to the wall's toe x_w;
 *   - the seawall's face is x = x_w from its toe to its crest z_c; behind
 *     it the land stays at crest level to the end of the flume, closed by an
 *     end wall (overtopping water lands there, it is not lost);
 *   - at x = 0: a Goring piston paddle (paddle-generated solitary wave) or a
 *     fixed vertical wall (other cases). The plan's end time keeps the
 *     wave reflected there from reaching the wall within the run.
 * Wall probes sit half a particle spacing seaward of the face, at the
 * centres of n equal strips of the face: there the interpolated pressure is
 * the fluid's (a probe inside the wall reads nothing).
 *
 * 3D (domain.dimensions: 3): the flume is y in [0, width], the width
 * rounded to a whole number of lattice rows (`width` below; the scenario's
 * domain.width within dp/2). The 2D bed / wall / land / end-wall polyline
 * is extruded over the width (and under side walls of particles). The
 * side walls are free-slip mirror planes at y = 0 and y = width (the
 * default, domain.side_walls: free-slip; sph/params.h), or layers of
 * boundary particles at y < 0 and y > width from the bed to the top of
 * the domain (particles). Waves and plane craters are long-crested (the 2D
 * field, v = 0); the axisymmetric craters (and the lip-less quadratic) are
 * centred at y = width/2, eta(r) with r the distance from the axis. Gauges
 * stand at y = width/2; wall probes form a grid of the heights below times
 * n_probe_y positions across (centres of equal strips of the width). The
 * penetration guard covers the extruded faces (bed, ends, seawall, land);
 * a particle that escapes through a side wall is caught by the domain box
 * (its y bounds lie just behind the side walls' layers). The seawall body
 * is the extruded polyline behind the face plane (side walls excluded).
 *
 * Symmetry plane (plan.symmetry, domain.symmetry auto or centreline): the
 * scene is symmetric about the flume's centreline, so only half of it is
 * built: y in [0, width/2], the plane y = 0 being the centreline (the
 * solver mirrors the particles beside it, sph/params.h), one side wall at
 * y = width/2. `width` is then the modelled half; gauges and the axis of
 * an axisymmetric crater stand on the plane; forces per metre are the
 * modelled half's over its width, as before. */
#ifndef WALLLOAD_FLUME_H
#define WALLLOAD_FLUME_H

#include "wallload/error.h"
#include "wallload/plan.h"
#include "wallload/scenario.h"
#include "wallload/sph.h"

enum wl_load_case { WL_CASE_SOLITARY, WL_CASE_EXPLOSION, WL_CASE_STILL };

/* Body number tagging the seawall's boundary particles (fixed), so loads
 * can sum the force on them; the paddle is moving body 1. */
#define WL_FLUME_BODY_PADDLE 1
#define WL_FLUME_BODY_WALL 2

enum { WL_FLUME_MAX_PROBES = 1000, WL_FLUME_PADDLE_SAMPLES = 4001, WL_FLUME_MAX_PROBES_Y = 16 };

struct wl_flume {
  enum wl_load_case load;
  int dims;                        /* 2 or 3 */
  double width;                    /* 3D: modelled flume width [m] (0 in 2D); half the
                                      flume's with a symmetry plane */
  int symmetry;                    /* 3D: symmetry plane at y = 0, the flume's centreline */
  int slip_walls;                  /* 3D: side walls are free-slip mirror planes */
  struct wl_sph_config cfg;        /* parameters, domain box, walls for the guard */
  struct wl_particles particles;   /* initial state (state fields only); owned */
  int has_paddle;
  double paddle_t[WL_FLUME_PADDLE_SAMPLES]; /* Goring motion table [s] */
  double paddle_x[WL_FLUME_PADDLE_SAMPLES]; /* displacement [m] */
  int n_paddle;
  double x_wall, z_toe, z_crest;   /* seawall face and its extent [m] */
  double depth;                    /* still-water level above the floor [m] */
  double x_left;                   /* left end of the modelled flume [m] (plan) */
  double depth_wall;               /* still water depth at the wall's toe [m] */
  double static_force;             /* rho g d_w^2 / 2 at rest [N/m] */
  double static_moment;            /* rho g d_w^3 / 6 about the toe [N m/m] */
  int n_probes;
  double probe_x;                  /* [m] */
  double probe_z[WL_FLUME_MAX_PROBES];
  /* Shepard sum S a probe at each height would read under still water
   * standing above it: the settled lattice in front of the face, down to
   * the toe (wl_sample's wetness rule: a probe is wet where S reaches half
   * of it) [-] */
  double probe_shepard_full[WL_FLUME_MAX_PROBES];
  int n_probe_y;                   /* 3D: probe positions across the width (0 in 2D) */
  double probe_y[WL_FLUME_MAX_PROBES_Y]; /* [m] */
  double gauge_y;                  /* 3D: y of every gauge [m] (width/2) */
  int n_gauges;
  double gauge_x[WL_SCENARIO_MAX_GAUGES + 1]; /* scenario gauges, then one at the wall face */
  double gauge_bed[WL_SCENARIO_MAX_GAUGES + 1]; /* bed height under each gauge [m] */
  char gauge_name[WL_SCENARIO_MAX_GAUGES + 1][64];
  double t_end;                    /* simulated time of this case [s] */
};

/* Build the flume of load case `load` from a validated scenario and its
 * plan. Returns WL_OK; WL_EINPUT (a case the scenario does not have, a
 * geometry the builder refuses), WL_ENOMEM. On failure *f is cleared. */
enum wl_status wl_flume_build(const struct wl_scenario *s, const struct wl_plan *plan,
                              enum wl_load_case load, struct wl_flume *f, struct wl_error *err);

/* Keep of f's particles the fluid with fluid_lo <= x < fluid_hi and the
 * boundary particles within margin of that range [m], ids renumbered in
 * order: one level of a two-resolution run (vres.h), whose flume is built
 * whole at the level's dp and then cut to the water it simulates. WL_EINPUT
 * when no fluid is left; WL_ENOMEM (f unchanged). */
enum wl_status wl_flume_crop(struct wl_flume *f, double fluid_lo, double fluid_hi, double margin,
                             struct wl_error *err);

/* Free what a flume owns; safe on a zeroed flume. */
void wl_flume_clear(struct wl_flume *f);

/* Name of a load case ("solitary", "explosion", "still"). */
const char *wl_flume_case_name(enum wl_load_case load);

#endif
