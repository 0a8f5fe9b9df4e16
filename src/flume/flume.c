/* flume.c: scenario + plan -> particles and run configuration of one load
 * case (geometry in flume.h). */
#include "wallload/flume.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/explosion.h"
#include "wallload/scene.h"
#include "wallload/sph/probe.h"
#include "wallload/units.h"
#include "wallload/waves.h"

/* Free surface of the initial condition, z = depth + eta(x) (3D: eta(x, y)
 * at the lattice row y of the current call). */
struct surface {
  enum wl_load_case load;
  double depth;
  const struct wl_solitary *wave; /* solitary initial condition */
  double crest_x;
  enum wl_crater_shape shape; /* explosion */
  double eta0, r0, xc;
  double rho; /* water density [kg/m^3] */
  int dim;    /* 2 or 3: z is x[dim - 1] */
  int radial; /* 3D axisymmetric crater: r from the axis (xc, yc) */
  double y, yc; /* 3D: the row being filled, the crater's axis [m] */
};

/* The bed under the fluid from x0 to the wall's toe at xw, as a polyline
 * (vertices in bx, bz, at most WL_SCENARIO_MAX_BED + 2); returns the count. */
static int bed_polyline(const struct wl_scenario *s, double x0, double xw, double z_toe, double *bx,
                        double *bz) {
  int nb = 0;
  bx[nb] = x0, bz[nb++] = wl_scenario_bed_z(s, x0);
  for (int i = 0; i < s->n_bed; i++) {
    double xb = s->bed[i].from.q.si;
    if (xb <= x0 || xb >= xw) continue;
    bx[nb] = xb, bz[nb++] = wl_scenario_bed_z(s, xb);
  }
  bx[nb] = xw, bz[nb++] = z_toe;
  return nb;
}

static double surface_z(double x, void *user) {
  const struct surface *s = user;
  double eta = 0.0;
  if (s->wave) {
    eta = wl_waves_solitary_eta(s->wave, x - s->crest_x);
  } else if (s->load == WL_CASE_EXPLOSION) {
    struct wl_error ignore;
    wl_error_clear(&ignore);
    const double r = s->radial ? hypot(x - s->xc, s->y - s->yc) : fabs(x - s->xc);
    wl_explosion_eta(s->shape, s->eta0, s->r0, r, &eta, &ignore);
  }
  return s->depth + eta;
}

/* Velocity of the solitary wave's field; z measured up from the flume
 * floor, which is the wave's bed where it is placed (over the flat part).
 * 3D: long-crested, v = 0. */
static void solitary_velocity(const double *x, double *v, void *user) {
  const struct surface *s = user;
  double u, w;
  wl_waves_solitary_velocity(s->wave, x[0] - s->crest_x, x[s->dim - 1], &u, &w);
  v[0] = u;
  if (s->dim == 3) v[1] = 0.0;
  v[s->dim - 1] = w;
}

/* Non-hydrostatic part of the solitary wave's pressure [Pa]. The flow is
 * steady in the frame moving with the crest at c and irrotational, so
 * Bernoulli's equation holds there with the constant of the still water far
 * ahead (u = 0, p = 0 at z = h): p/rho = g (h - z) + c u - (u^2 + w^2)/2.
 * The particles were stacked with the hydrostatic pressure under the local
 * surface, rho g (h + eta - z); this adds the difference,
 * rho (c u - (u^2 + w^2)/2 - g eta). Under the crest of an H/h = 0.4 wave it
 * is about -1 % of the bed pressure, small enough that leaving it out did not
 * change the wave's measured energy history (H/h = 0.4, dp = h/20); it is
 * kept because it is the wave's pressure, not an approximation of it. */
static double solitary_dynamic_pressure(const double *x, void *user) {
  const struct surface *s = user;
  const double X = x[0] - s->crest_x;
  double u, w;
  wl_waves_solitary_velocity(s->wave, X, x[s->dim - 1], &u, &w);
  const double eta = wl_waves_solitary_eta(s->wave, X);
  return s->rho * (s->wave->c * u - 0.5 * (u * u + w * w) - s->wave->g * eta);
}

const char *wl_flume_case_name(enum wl_load_case load) {
  switch (load) {
  case WL_CASE_SOLITARY: return "solitary";
  case WL_CASE_EXPLOSION: return "explosion";
  case WL_CASE_STILL: return "still";
  }
  return "?";
}

void wl_flume_clear(struct wl_flume *f) {
  if (!f) return;
  wl_particles_clear(&f->particles);
  memset(f, 0, sizeof *f);
}

static void set_params(const struct wl_scenario *s, const struct wl_plan *plan, double h_max,
                       struct wl_sph_config *cfg) {
  wl_sph_config_default(cfg, plan->dims, plan->dp, h_max);
  struct wl_sph_params *prm = &cfg->prm;
  prm->coefh = plan->coefh;
  prm->coefsound = s->numerics.coefsound.q.si;
  prm->cfl = s->numerics.cfl.q.si;
  prm->alpha = s->numerics.alpha.q.si;
  prm->visc = s->numerics.viscosity.choice == WL_VISCOSITY_LAMINAR ? WL_SPH_VISC_LAMINAR
                                                                    : WL_SPH_VISC_ARTIFICIAL;
  prm->nu = s->numerics.nu.q.si;
  prm->delta = s->numerics.density_diffusion.q.si;
  prm->residual_alpha = s->numerics.residual_viscosity.q.si;
  prm->smagorinsky = s->numerics.smagorinsky.q.si;
  if (prm->delta == 0.0) prm->ddt = WL_SPH_DDT_NONE;
  prm->rho0 = plan->rho;
  prm->g = plan->g;
  /* particle shifting (sph/shift.h) with DualSPHysics' coefficient */
  prm->shift_coef = s->numerics.shifting.choice != 0 ? 2.0 : 0.0;
  prm->integrator = s->numerics.integrator.choice == WL_INTEGRATOR_VERLET ? WL_SPH_VERLET
                                                                          : WL_SPH_SYMPLECTIC;
  prm->verlet_steps = (int)s->numerics.verlet_steps.q.si;
  prm->boundary = s->numerics.boundary.choice == WL_BOUNDARY_DBC ? WL_SPH_BOUND_DBC
                                                                 : WL_SPH_BOUND_ADAMI;
  if (!s->run.threads.is_auto) cfg->n_threads = (int)s->run.threads.q.si;
}

/* 3D side walls of boundary particles: the (x, z) lattice points inside
 * the flume's profile (the boundary polyline vx, vz: above the bed,
 * seaward of the wall face or above the land, below z_top, between its end
 * faces) at least dp/2 from the polyline, as layers behind y = 0 (sides
 * bit 0) and y = width (bit 1) (box3d.c). The extruded polyline's layers
 * fill the edges under them. */
static enum wl_status side_walls(struct wl_scene *sc, const double *vx, const double *vz, int nv,
                                 double xw, double z_crest, const struct wl_scenario *s,
                                 double z_top, double width, int sides, int layers,
                                 struct wl_error *err) {
  const double dp = sc->dp, tol = 1e-9 * dp;
  const double x0 = vx[0], x1 = vx[nv - 1];
  double zmin = vz[0];
  for (int i = 1; i < nv; i++) zmin = fmin(zmin, vz[i]);
  const int nx = (int)floor((x1 - x0) / dp + 1e-9), nz = (int)floor((z_top - zmin) / dp + 1e-9);
  double *xz = malloc(sizeof(double) * 2 * (size_t)nx * (size_t)(nz > 0 ? nz : 1));
  if (!xz) return wl_error_set(err, WL_ENOMEM, "flume side walls: out of memory");
  int n = 0;
  for (int i = 0; i < nx; i++) {
    const double x = x0 + (i + 0.5) * dp;
    const double floor_z = x < xw ? wl_scenario_bed_z(s, x) : z_crest;
    for (int j = 0; j < nz; j++) {
      const double z = zmin + (j + 0.5) * dp;
      if (z <= floor_z || wl_scene_polyline_dist(vx, vz, nv, x, z) < 0.5 * dp - tol) continue;
      xz[2 * n] = x;
      xz[2 * n + 1] = z;
      n++;
    }
  }
  enum wl_status st = wl_scene_box3d_sides(sc, xz, n, 0.0, width, sides, layers, err);
  free(xz);
  return st;
}

enum wl_status wl_flume_build(const struct wl_scenario *s, const struct wl_plan *plan,
                              enum wl_load_case load, struct wl_flume *f, struct wl_error *err) {
  memset(f, 0, sizeof *f);
  f->load = load;
  const int dim = plan->dims;
  f->dims = dim;
  if (dim != 2 && dim != 3)
    return wl_error_set(err, WL_EINPUT, "%s: domain.dimensions: %d; valid 2 or 3", s->path, dim);
  if (load == WL_CASE_SOLITARY && !plan->solitary.present)
    return wl_error_set(err, WL_EINPUT, "%s: the scenario has no solitary load case", s->path);
  if (load == WL_CASE_SOLITARY && plan->solitary.present) {
    enum wl_status fst = wl_plan_solitary_runnable(s, plan, err);
    if (fst) return fst;
  }
  if (load == WL_CASE_EXPLOSION && !plan->explosion.present)
    return wl_error_set(err, WL_EINPUT, "%s: the scenario has no explosion load case", s->path);

  const double dp = plan->dp, depth = plan->h;
  const double xw = s->wall.x.q.si;
  /* 3D: the width as a whole number of lattice rows (flume.h) */
  int n_rows = 1;
  f->symmetry = dim == 3 && plan->symmetry;
  if (dim == 3) {
    n_rows = (int)floor(s->domain.width.q.si / (f->symmetry ? 2 : 1) / dp + 0.5);
    if (n_rows < 1) n_rows = 1;
    f->width = n_rows * dp;
  }
  f->depth = depth;
  f->x_wall = xw;
  f->z_toe = wl_scenario_bed_z(s, xw);
  f->z_crest = f->z_toe + s->wall.height.q.si;
  f->depth_wall = depth - f->z_toe;
  f->static_force = 0.5 * plan->rho * plan->g * f->depth_wall * f->depth_wall;
  f->static_moment = plan->rho * plan->g * pow(f->depth_wall, 3) / 6.0;

  /* What rises above still water decides the top of the domain (and, in
   * the plan, c0). */
  double rise = 0.0, top_rise = 0.0, thrown_top = 0.0;
  struct surface surf = {load, depth, NULL, 0, 0, 0, 0, 0, plan->rho, dim, 0, 0, 0};
  const struct wl_plan_solitary *ps = &plan->solitary;
  const struct wl_plan_explosion *px = &plan->explosion;
  double x_left = 0.0; /* where the modelled flume starts (plan) */
  if (load == WL_CASE_SOLITARY) {
    rise = ps->wave.H;
    x_left = ps->paddle ? 0.0 : ps->x_left;
    f->has_paddle = ps->paddle;
    if (!ps->paddle && !plan->still_flume) { /* still_flume: still water (plan.h) */
      surf.wave = &ps->wave;
      surf.crest_x = ps->crest_x0;
    }
    f->t_end = ps->end_time;
  } else if (load == WL_CASE_EXPLOSION) {
    surf.shape = px->model_thrown ? WL_CRATER_SHAPE_QUADRATIC : px->shape;
    surf.eta0 = plan->still_flume ? 0.0 : px->eta0; /* still_flume: no crater */
    surf.r0 = px->r0;
    surf.xc = px->x_center;
    /* 3D: the plane shapes are long-crested, the others axisymmetric */
    surf.radial = dim == 3 && surf.shape != WL_CRATER_SHAPE_QUADRATIC_LIP_PLANE &&
                  surf.shape != WL_CRATER_SHAPE_QUARTIC_LIP_PLANE;
    surf.yc = f->symmetry ? 0.0 : 0.5 * f->width; /* on the centreline */
    rise = px->rise; /* the lip's crest (plan.h) */
    top_rise = 2.0 * px->eta0; /* the domain's top as before: the collapse throws water up */
    x_left = px->x_left;
    f->t_end = px->end_time;
  } else {
    f->t_end = s->run.end_time.is_auto ? 10.0 : s->run.end_time.q.si;
  }
  /* The fluid's lattice is laid from the wall: its last column stands dp/2
   * from the face, as its lowest row stands dp/2 above the bed, so the
   * fluid meets the wall's boundary particles one spacing apart wherever
   * the scenario puts the wall. Laid from the left end instead, that gap
   * was anything from dp/2 to 3dp/2 and the wall loads moved with it: a
   * reflected H/h = 0.3 solitary wave (dp = 0.01 m) gave a boundary-force
   * impulse of 145 to 164 N s/m and a probe impulse of 119 to 155 N s/m for
   * wall positions a few millimetres apart (now 168-169 and 171-172). The
   * lattice starts at x_fluid, less than dp right of the planned left end:
   * the left wall moves there (the plan's end is a cut through the flume,
   * or the flume's own end, either way good to dp), and a paddle's rest
   * position is x_fluid (its motion is a displacement from there). */
  double x_fluid = xw - dp * floor((xw - x_left) / dp + 1e-9);
  if (!f->has_paddle) x_left = x_fluid;

  struct wl_explosion_part parts[WL_EXPLOSION_PARTS_MAX];
  int n_parts = 0;
  if (load == WL_CASE_EXPLOSION && px->model_thrown && dim == 3)
    return wl_error_set(err, WL_EUNSUPPORTED,
                        "%s: loads.explosion: the thrown-mass model is 2D only; use "
                        "domain.dimensions: 2, or a crater shape without thrown mass", s->path);
  if (load == WL_CASE_EXPLOSION && px->model_thrown) {
    double mass, rc;
    enum wl_status st = wl_explosion_thrown_mass(WL_CRATER_SHAPE_QUADRATIC, 2, plan->rho, px->eta0,
                                                 px->r0, 0.0, &mass, err);
    if (!st) st = wl_explosion_inner_radius(WL_CRATER_SHAPE_QUADRATIC, px->r0, &rc, err);
    if (!st)
      st = wl_explosion_thrown_split(2, plan->rho, rc, mass, px->energy, px->thrown_parts, 0.0,
                                     parts, err);
    if (st) {
      wl_error_prefix(err, "%s: loads.explosion (thrown mass): ", s->path);
      return st;
    }
    for (int i = 0; i < px->thrown_parts; i++) {
      double top = parts[i].z + 0.5 * parts[i].height + parts[i].w * parts[i].w / (2 * plan->g);
      if (top > thrown_top) thrown_top = top;
    }
    /* the domain as the case's; still_flume lays no thrown mass */
    n_parts = plan->still_flume ? 0 : px->thrown_parts;
  }

  /* the case's largest depth, which sets c0: the plan's (plan.h) */
  set_params(s, plan,
             load == WL_CASE_SOLITARY    ? ps->h_max
             : load == WL_CASE_EXPLOSION ? px->h_max
                                         : depth,
             &f->cfg);
  {
    /* The still water's columns are a little narrower than dp (scene.h
     * wl_scene_fluid_surface: compressed water is denser at depth), so
     * whole columns from the wall end short of the lattice's x_fluid: the
     * flume (its left wall, or the paddle's rest position) starts where
     * they end, so no strip next to it is left dry. */
    struct wl_sph_const k0;
    enum wl_status st0 = wl_sph_const_make(&f->cfg.prm, &k0, err);
    if (st0) return st0;
    double bx[WL_SCENARIO_MAX_BED + 2], bz[WL_SCENARIO_MAX_BED + 2];
    const int nb = bed_polyline(s, x_fluid, xw, f->z_toe, bx, bz);
    const double edge = wl_scene_fluid_columns_edge(&k0, x_fluid - 0.5 * dp, xw, bx, bz, nb, depth);
    if (!isfinite(edge)) return wl_error_set(err, WL_ENOMEM, "flume: out of memory (columns)");
    x_fluid = edge;
    if (!f->has_paddle) x_left = x_fluid;
  }
  if (load == WL_CASE_EXPLOSION) f->cfg.prm.expected_speed = px->expected_speed; /* plan.h */
  if (s->domain.far_end.choice == WL_FAR_END_DAMPING && plan->land_length > 0) {
    /* over the far half of the land, at a rate that stops water arriving at
     * the long-wave speed within about a tenth of the zone's crossing time */
    const double x_end = s->wall.x.q.si + plan->land_length, zone = 0.5 * plan->land_length;
    f->cfg.prm.damp_x0[0] = x_end - zone;
    f->cfg.prm.damp_x1[0] = x_end;
    f->cfg.prm.damp_rate[0] = 10.0 * sqrt(plan->g * depth) / zone;
  }
  if (load == WL_CASE_EXPLOSION && plan->explosion.absorber > 0) {
    /* the seaward end absorbs the waves running away from the wall
     * (plan.c): the flume ends just behind the crater instead of far
     * enough back for their reflection to arrive after the end time */
    const double zone = plan->explosion.absorber;
    f->cfg.prm.damp_x0[1] = x_left + zone;
    f->cfg.prm.damp_x1[1] = x_left;
    f->cfg.prm.damp_rate[1] = 10.0 * sqrt(plan->g * depth) / zone;
  }
  /* 3D mirror planes (flume.h): y = 0 is the centreline (symmetry) or a
   * free-slip side wall; y = width a free-slip side wall */
  f->slip_walls = dim == 3 && plan->slip_walls;
  f->cfg.prm.mirror_lo = f->symmetry || f->slip_walls;
  f->cfg.prm.mirror_hi = f->slip_walls;
  f->cfg.prm.mirror_y_lo = 0.0;
  f->cfg.prm.mirror_y_hi = f->width;
  struct wl_sph_const k;
  enum wl_status st = wl_sph_const_make(&f->cfg.prm, &k, err);
  if (st) return st;
  int layers = (int)ceil(2.0 * (double)k.h / dp);
  double thick = layers * dp;

  double z_top = fmax(f->z_crest, depth) + fmax(3.0 * fmax(rise, top_rise), 0.5 * depth) + thrown_top;
  f->x_left = x_left;
  f->cfg.lo[0] = x_left - thick - 2 * dp;
  f->cfg.hi[0] = xw + plan->land_length + thick + 2 * dp;
  f->cfg.lo[dim - 1] = -thick - 2 * dp;
  f->cfg.hi[dim - 1] = z_top + thick + 2 * dp;
  const int mirror_lo = f->cfg.prm.mirror_lo, mirror_hi = f->cfg.prm.mirror_hi;
  if (dim == 3) { /* a mirror plane is the box's face; else just behind the
                     side wall's layers (flume.h: guard) */
    f->cfg.lo[1] = mirror_lo ? 0.0 : -thick - 2 * dp;
    f->cfg.hi[1] = mirror_hi ? f->width : f->width + thick + 2 * dp;
  }

  /* 3D: the polyline's extrusion runs on the fluid's y lattice, (j + 1/2)
   * dp, from under one side wall's last layer (or the first fluid row
   * beside a mirror plane) to the other's */
  struct wl_scene sc;
  wl_scene_init(&sc, &k, mirror_lo ? 0.5 * dp : -(layers - 0.5) * dp,
                mirror_hi ? f->width - 0.5 * dp : f->width + (layers - 0.5) * dp);

  /* Fixed boundary: (left wall,) bed with its bathymetry, wall face, land
   * at crest level, end wall; one polyline so its corners are mitred. */
  enum { MAXV = WL_SCENARIO_MAX_BED + 8 };
  double vx[MAXV], vz[MAXV];
  int nv = 0;
  if (!f->has_paddle) {
    vx[nv] = x_left, vz[nv++] = z_top;
    vx[nv] = x_left, vz[nv++] = wl_scenario_bed_z(s, x_left);
  } else {
    vx[nv] = -thick - dp, vz[nv++] = 0.0; /* under the piston's layers */
  }
  for (int i = 0; i < s->n_bed; i++) {
    double xb = s->bed[i].from.q.si;
    if (xb <= vx[nv - 1]) continue;
    vx[nv] = xb, vz[nv++] = wl_scenario_bed_z(s, xb);
  }
  vx[nv] = xw, vz[nv++] = f->z_toe;
  vx[nv] = xw, vz[nv++] = f->z_crest;
  /* Land behind the wall only as far as overtopping water can use it. */
  double x_end = xw + plan->land_length;
  vx[nv] = x_end, vz[nv++] = f->z_crest;
  vx[nv] = x_end, vz[nv++] = z_top;
  st = wl_scene_boundary_polyline(&sc, vx, vz, nv, layers, WL_KIND_FIXED, 0, &f->cfg, err);
  const int n_extruded = sc.n[0]; /* the seawall body is tagged among these */
  const int particle_sides = dim == 3 ? (mirror_lo ? 0 : 1) | (mirror_hi ? 0 : 2) : 0;
  if (!st && particle_sides)
    st = side_walls(&sc, vx, vz, nv, xw, f->z_crest, s, z_top, f->width, particle_sides, layers,
                    err);
  if (!st && f->has_paddle) {
    /* 3D: the piston spans the fluid rows only, inside the side walls */
    sc.y0 = 0.5 * dp;
    sc.y1 = f->width - 0.5 * dp;
    st = wl_scene_piston(&sc, x_fluid, 0.0, z_top, layers, WL_FLUME_BODY_PADDLE, err);
  }

  /* Fluid between the left end and the wall, under the initial surface,
   * on the lattice laid from the wall (x_fluid above). */
  double bx[WL_SCENARIO_MAX_BED + 2], bz[WL_SCENARIO_MAX_BED + 2];
  const int nb = bed_polyline(s, x_left, xw, f->z_toe, bx, bz);
  if (dim == 2) {
    if (!st) st = wl_scene_fluid_surface(&sc, x_fluid, xw, bx, bz, nb, depth, surface_z, &surf, err);
  } else {
    /* one lattice row across at a time, so that eta may depend on y */
    for (int j = 0; !st && j < n_rows; j++) {
      sc.y0 = j * dp;
      sc.y1 = (j + 1) * dp;
      surf.y = (j + 0.5) * dp;
      st = wl_scene_fluid_surface(&sc, x_fluid, xw, bx, bz, nb, depth, surface_z, &surf, err);
    }
  }
  if (!st && surf.wave) {
    wl_scene_fluid_velocity(&sc, solitary_velocity, &surf);
    wl_scene_fluid_add_pressure(&sc, solitary_dynamic_pressure, &surf);
  }
  for (int i = 0; !st && i < n_parts; i++) {
    const struct wl_explosion_part *pt = &parts[i];
    double lo[2] = {px->x_center + pt->s_in, depth + pt->z - 0.5 * pt->height};
    double hi[2] = {px->x_center + pt->s_out, depth + pt->z + 0.5 * pt->height}; /* 2D only */
    int before = sc.n[1];
    st = wl_scene_fluid_block(&sc, lo, hi, hi[1], err);
    for (int j = before; !st && j < sc.n[1]; j++) {
      sc.vel[1][2 * j] = pt->u;
      sc.vel[1][2 * j + 1] = pt->w;
    }
  }
  if (!st) wl_scene_hydrostatic_boundary(&sc, depth);
  /* The structure: every fixed boundary particle behind the face plane,
   * including the bed layers under the toe, since fluid at the toe corner
   * pushes on those too (leaving them out loses a few % of the force). */
  for (int j = 0; !st && j < n_extruded; j++) {
    double x = sc.pos[0][(size_t)dim * j];
    if (sc.kind[0][j] == WL_KIND_FIXED && x > xw) sc.body[0][j] = WL_FLUME_BODY_WALL;
  }
  if (!st) st = wl_scene_build(&sc, &f->particles, err);
  wl_scene_clear(&sc);
  if (st) {
    wl_error_prefix(err, "%s: building the %s case: ", s->path, wl_flume_case_name(load));
    wl_flume_clear(f);
    return st;
  }

  if (f->has_paddle) {
    const struct wl_goring *g = &ps->goring;
    f->n_paddle = WL_FLUME_PADDLE_SAMPLES;
    for (int i = 0; i < f->n_paddle; i++) {
      double t = g->duration * i / (f->n_paddle - 1);
      f->paddle_t[i] = t;
      f->paddle_x[i] = plan->still_flume ? 0.0 : wl_waves_goring_position(g, t);
    }
  }

  int n_probes = (int)s->wall.probes.q.si;
  if (n_probes > WL_FLUME_MAX_PROBES) n_probes = WL_FLUME_MAX_PROBES;
  f->n_probes = n_probes;
  f->probe_x = xw - 0.5 * dp;
  for (int i = 0; i < n_probes; i++)
    f->probe_z[i] = f->z_toe + (i + 0.5) * (f->z_crest - f->z_toe) / n_probes;
  if (dim == 3) {
    /* across: centres of equal strips, at most one per lattice row */
    int ny = n_rows < 5 ? n_rows : 5;
    f->n_probe_y = ny;
    for (int j = 0; j < ny; j++) f->probe_y[j] = (j + 0.5) * f->width / ny;
    f->gauge_y = f->symmetry ? 0.0 : 0.5 * f->width; /* the centreline */
  }
  for (int i = 0; i < n_probes; i++) {
    double sum = 0.0;
    const int ny = dim == 3 ? f->n_probe_y : 1;
    for (int j = 0; j < ny; j++)
      sum += wl_sph_face_shepard_full(&k, dim, dp, f->probe_z[i] - f->z_toe,
                                      dim == 3 ? f->probe_y[j] : 0.0);
    f->probe_shepard_full[i] = sum / ny;
  }
  for (int i = 0; i < s->n_gauges; i++) {
    f->gauge_x[i] = s->gauges[i].x.q.si;
    f->gauge_bed[i] = wl_scenario_bed_z(s, f->gauge_x[i]);
    snprintf(f->gauge_name[i], sizeof f->gauge_name[i], "%s", s->gauges[i].name.text);
  }
  f->n_gauges = s->n_gauges + 1;
  /* The run-up gauge stands one kernel support (2h) from the face, where the
   * kernel is not cut by the wall (S would not reach the surface limit
   * closer in); at maximum run-up the surface there is level with the face. */
  f->gauge_x[s->n_gauges] = xw - 2.0 * (double)k.h;
  f->gauge_bed[s->n_gauges] = f->z_toe;
  snprintf(f->gauge_name[s->n_gauges], sizeof f->gauge_name[0], "wall");
  return WL_OK;
}

/* Whether wl_flume_crop keeps particle i of p. */
static int crop_keeps(const struct wl_particles *p, int i, double lo, double hi, double margin) {
  const double x = p->pos[0][i];
  return p->kind[i] == WL_KIND_FLUID ? x >= lo && x < hi : x >= lo - margin && x < hi + margin;
}

enum wl_status wl_flume_crop(struct wl_flume *f, double fluid_lo, double fluid_hi, double margin,
                             struct wl_error *err) {
  const struct wl_particles *p = &f->particles;
  int n = 0, nb = 0;
  for (int i = 0; i < p->n; i++) {
    const int keep = crop_keeps(p, i, fluid_lo, fluid_hi, margin);
    n += keep;
    nb += keep && i < p->n_bound;
  }
  if (n == nb)
    return wl_error_set(err, WL_EINPUT, "flume: no fluid between x = %g and %g m", fluid_lo,
                        fluid_hi);
  struct wl_particles q;
  enum wl_status st = wl_particles_alloc(&q, p->dim, n, 0, err);
  if (st) return st;
  int k = 0;
  for (int i = 0; i < p->n; i++) {
    if (!crop_keeps(p, i, fluid_lo, fluid_hi, margin)) continue;
    for (int a = 0; a < p->dim; a++) q.pos[a][k] = p->pos[a][i], q.vel[a][k] = p->vel[a][i];
    q.rho[k] = p->rho[i];
    q.id[k] = (unsigned)k;
    q.kind[k] = p->kind[i];
    q.body[k] = p->body[i];
    k++;
  }
  q.n = n;
  q.n_bound = nb;
  wl_particles_clear(&f->particles);
  f->particles = q;
  return WL_OK;
}
