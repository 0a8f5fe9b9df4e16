/* scene.h: geometric primitives that turn a flume into particles (module
 * scene, src/scene/): fluid blocks and fluid under a free surface over a
 * piecewise-linear bed, boundary polylines (bed, walls, slopes) with layers
 * of dynamic boundary particles, and a vertical piston paddle. The lead's
 * scenario mapping (YAML -> scene) is built on these.
 *
 * Geometry conventions (2D uses (x, z); 3D extrudes along y over the
 * scene's width):
 *  - Fluid particles sit on the lattice x = x0 + (i + 1/2) dp, so a block
 *    [x0, x1] x [z0, z1] holds exactly its area (volume) in particles and its
 *    faces are the block's faces.
 *  - A boundary polyline is the wall FACE: the line where the fluid ends.
 *    Walking from its first to its last vertex the fluid is on the left;
 *    boundary layer k (0 .. n_layers-1) lies (k + 1/2) dp to the right,
 *    offset with mitred corners, so the first layer is dp/2 behind the face
 *    and a dp from the nearest fluid row, as on DualSPHysics' single
 *    lattice, and the fluid volume ends at the face. Along each layer the
 *    particles are spaced as close to dp as the segment length allows.
 *  - Fluid at rest is hydrostatic and Tait-consistent (REFERENCES.md 1.1),
 *    rho = rho0 (1 + p/B)^(1/7), with p the weight of the particles above
 *    (and of any water above the block), and each column is stacked with
 *    layer thicknesses dp rho0/rho, so that every particle's volume m/rho
 *    is the space it fills. The column therefore ends a little below the
 *    nominal surface (about p/(14 B) of the depth: 0.5 % at coefsound 10),
 *    and holds exactly the mass of the nominal block. GenCase places a
 *    uniform lattice instead; that overstates the SPH pressure near the bed
 *    by about the compression (1 % at coefsound 10).
 *
 * The builder collects particles; wl_scene_build emits them boundary first,
 * then fluid, with ids in that order. */
#ifndef WALLLOAD_SCENE_H
#define WALLLOAD_SCENE_H

#include "wallload/backend.h"
#include "wallload/error.h"
#include "wallload/sph/params.h"
#include "wallload/sph/particles.h"

/* Tolerance of the lattice tests, relative to dp: a lattice point within
 * WL_SCENE_LATTICE_TOL dp of a face (a row exactly on the free surface, on
 * the bed's half-spacing clearance) is decided the same way whatever the
 * rounding of its coordinates or of a dp written to 7 or more digits
 * (0.008571428571 m is 0.06/7 m: 7 whole rows, not 6). The plan counts
 * rows with it too (wl_plan_modelled_depth). */
#define WL_SCENE_LATTICE_TOL 1e-6

/* Particle lists under construction (caller-owned: _init / _clear). */
struct wl_scene {
  struct wl_sph_const k; /* constants of the run (rho0, B, g, dp) */
  int dim;          /* 2 or 3 */
  double dp;        /* particle spacing [m] */
  double y0, y1;    /* 3D: width of the flume [m] (extrusion range) */
  int n[2], cap[2]; /* [0] boundary, [1] fluid: particles and room */
  double *pos[2];   /* dim per particle, interleaved [m] */
  double *vel[2];   /* dim per particle [m/s] */
  double *rho[2];   /* [kg/m^3] */
  unsigned char *kind[2], *body[2];
};

/* Start an empty scene for the run constants k (wl_sph_const_make: dim,
 * dp, rho0, B, g); y0 < y1 [m] is the flume width in 3D (ignored in 2D). */
void wl_scene_init(struct wl_scene *sc, const struct wl_sph_const *k, double y0, double y1);

/* Free the lists; safe on a zeroed or cleared scene. */
void wl_scene_clear(struct wl_scene *sc);

/* Fluid block lo..hi (x, z in 2D; x, y, z in 3D; [m]) at rest, hydrostatic;
 * eta [m] is the free surface (hi's z for a block open at the top; higher
 * for a block under more water, whose weight is added). WL_EINPUT for an empty or inverted block; WL_ENOMEM. */
enum wl_status wl_scene_fluid_block(struct wl_scene *sc, const double *lo, const double *hi, double eta,
                                    struct wl_error *err);

/* Free-surface elevation eta(x) [m] for wl_scene_fluid_surface. */
typedef double (*wl_scene_eta_fn)(double x, void *user);

/* Fluid at rest from x1 toward x0 between a piecewise-linear bed (vertices
 * bed_x[i], bed_z[i], i < n_bed, bed_x increasing; [m]) and the free surface
 * eta(x), in columns laid from x1: each column's lowest particle dp/2 from
 * the bed (the bed is a wall face: its first boundary layer is dp/2 below;
 * on a slope the column starts dp / (2 cos theta) above it), stacked
 * hydrostatically (see above). Where eta(x) departs from `level` (a wave, a
 * crater) the columns' counts are rounded with each remainder carried to the
 * next column, seaward first, so that the water above or below the level is
 * laid to half a particle in all and each column's top within a spacing of
 * eta. Each column is as wide as makes the particles still water at
 * `level` would give it hold compressed water exactly to that level (a
 * little under dp: the water is denser at depth), so still water is level
 * over beds of every depth; over a bed a whole number of rows below the
 * level the columns end at it exactly, over a slope their tops step by up
 * to dp/2. Whole columns are laid while they fit: less than a column next
 * to x0 stays dry (wl_scene_fluid_columns_edge gives where they end, for
 * a boundary there). WL_EINPUT for bad arrays or x range; WL_ENOMEM. */
enum wl_status wl_scene_fluid_surface(struct wl_scene *sc, double x0, double x1, const double *bed_x, const double *bed_z,
                                      int n_bed, double level, wl_scene_eta_fn eta, void *user,
                                      struct wl_error *err);

/* Where the columns of wl_scene_fluid_surface (the same arguments) end
 * toward x0 [m]: x0 or less than a column's width from it; NAN out of
 * memory. */
double wl_scene_fluid_columns_edge(const struct wl_sph_const *k, double x0, double x1,
                                   const double *bed_x, const double *bed_z, int n_bed,
                                   double level);

/* Boundary particles along the polyline (x[i], z[i]), i < n_vertices [m],
 * fluid on the left, n_layers layers (see above). kind: WL_KIND_FIXED or
 * WL_KIND_MOVING (then body 1..WL_SPH_BODIES_MAX). Density rho0 (use
 * wl_scene_hydrostatic_boundary for still water). When cfg is not NULL and
 * the kind is fixed, each segment's face is added to cfg's penetration
 * guard (wl_sph_config_add_wall). WL_EINPUT (fewer than 2 vertices, a
 * zero-length segment, bad layers, kind or body), WL_ENOMEM. */
enum wl_status wl_scene_boundary_polyline(struct wl_scene *sc, const double *x, const double *z,
                                          int n_vertices, int n_layers, int kind, int body,
                                          struct wl_sph_config *cfg, struct wl_error *err);

/* Vertical piston paddle: its face is x = x_face for z0 <= z <= z1 [m],
 * facing the fluid at x > x_face; n_layers of moving boundary particles of
 * body `body` behind it. Its motion is set on the simulation
 * (wl_sph_sim_set_motion). Errors as wl_scene_boundary_polyline. */
enum wl_status wl_scene_piston(struct wl_scene *sc, double x_face, double z0, double z1,
                               int n_layers, int body, struct wl_error *err);

/* Set the density of boundary particles below the still-water level eta
 * [m] to the hydrostatic value (rho0 above it), so that a still tank starts
 * in equilibrium. */
void wl_scene_hydrostatic_boundary(struct wl_scene *sc, double eta);

/* Initial fluid velocity v(x) [m/s] (e.g. a solitary wave's), written into
 * v[0..dim-1] for the particle at x[0..dim-1] [m]. */
typedef void (*wl_scene_vel_fn)(const double *x, double *v, void *user);

/* Set the velocity of every fluid particle from fn. */
void wl_scene_fluid_velocity(struct wl_scene *sc, wl_scene_vel_fn fn, void *user);

/* Pressure correction dp(x) [Pa] to the stacked (hydrostatic) pressure of a
 * fluid particle at x[0..dim-1] [m]. */
typedef double (*wl_scene_dp_fn)(const double *x, void *user);

/* Add fn's pressure to every fluid particle: rho <- rho(p(rho) + dp(x)) by
 * the Tait equation. For initial conditions whose pressure is not
 * hydrostatic (a solitary wave's, from Bernoulli's equation). */
void wl_scene_fluid_add_pressure(struct wl_scene *sc, wl_scene_dp_fn fn, void *user);

/* Distance [m] from (x, z) to the polyline of n vertices (bx, bz) [m]. */
double wl_scene_polyline_dist(const double *bx, const double *bz, int n, double x, double z);

/* Emit the particles into out (allocated here with wl_particles_alloc, state
 * fields only; clear it with wl_particles_clear): boundary particles first,
 * then fluid, ids 0.. in that order. WL_EINPUT when there is no particle,
 * WL_ENOMEM; on failure out is cleared. */
enum wl_status wl_scene_build(const struct wl_scene *sc, struct wl_particles *out,
                              struct wl_error *err);

/* Hydrostatic Tait density [kg/m^3] at depth d = eta - z [m] (rho0 for
 * d <= 0). */
double wl_scene_rho_hydro(const struct wl_sph_const *k, double depth);

/* ---- 3D boxes (src/scene/box3d.c) ---------------------------------------- */

/* Rectangular tank open at the top (3D only): the inside lo..hi [m] (x, y,
 * z) is where the fluid may be; n_layers of fixed boundary particles lie
 * behind the floor z = lo[2] and the four walls x = lo[0], hi[0], y =
 * lo[1], hi[1], up to z = hi[2], edges and corners filled. Along each axis
 * the particles keep the spacing closest to dp that divides the span (dp
 * where the span is a multiple of it). With cfg not NULL the floor and the
 * two end walls (x = lo[0], hi[0]) are added to the penetration guard.
 * Densities rho0 (wl_scene_hydrostatic_boundary for still water). WL_EINPUT
 * (2D scene, a span below dp, layers outside 1..16), WL_ENOMEM. */
enum wl_status wl_scene_box3d_tank(struct wl_scene *sc, const double *lo, const double *hi,
                                   int n_layers, struct wl_sph_config *cfg, struct wl_error *err);

/* Solid box lo..hi [m] (3D only; e.g. a pillar): fixed boundary particles
 * on the inside lattice of the box, n_layers deep behind its faces (the
 * fluid is outside). floor_below = 1 leaves out the layers behind the
 * bottom face (the box stands on a floor). Errors as wl_scene_box3d_tank. */
enum wl_status wl_scene_box3d_solid(struct wl_scene *sc, const double *lo, const double *hi,
                                    int n_layers, int floor_below, struct wl_error *err);

/* Side walls of a flume extruded along y (3D only): for each of the n
 * points (xz[2i], xz[2i+1]) [m] of the flume's profile, n_layers fixed
 * boundary particles at y = y0 - (k + 1/2) dp (when bit 0 of sides is
 * set) and y = y1 + (k + 1/2) dp (bit 1) (k < n_layers): the walls y = y0
 * and y = y1 are wall FACES. The caller
 * places the points on the fluid lattice of the profile (and the extruded
 * polylines under them fill the edges). Densities rho0. WL_EINPUT (2D
 * scene, layers outside 1..16, y1 <= y0), WL_ENOMEM. */
enum wl_status wl_scene_box3d_sides(struct wl_scene *sc, const double *xz, int n, double y0,
                                    double y1, int sides, int n_layers, struct wl_error *err);

#endif
