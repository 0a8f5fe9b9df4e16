/* sph/params.h: the SPH run parameters (what a user or the plan chooses) and
 * the derived constants every physics function reads (computed once on the
 * host by wl_sph_const_make, copied as a value to the device).
 *
 * Conventions follow DualSPHysics (Dominguez et al. 2022, Comp. Part. Mech.
 * 9:867) unless a comment says otherwise:
 *  - h = coefh sqrt(dim) dp, so coefh = 1 gives h = 1.414 dp in 2D and
 *    h = 1.732 dp in 3D; kernel support 2h.
 *  - c0 = coefsound sqrt(g h_max), h_max the largest water depth; Tait
 *    B = c0^2 rho0 / gamma with gamma = 7 (Monaghan 1994; seed 000 eqs 15-17).
 *  - particle mass rho0 dp^dim for fluid and boundary particles alike. */
#ifndef WALLLOAD_SPH_PARAMS_H
#define WALLLOAD_SPH_PARAMS_H

#include <math.h>

#include "wallload/sph/defs.h"

/* Viscosity model of the momentum equation. */
enum wl_sph_visc {
  WL_SPH_VISC_ARTIFICIAL = 0, /* Monaghan (1992) artificial viscosity, alpha */
  WL_SPH_VISC_LAMINAR = 1,    /* Lo & Shao (2002) laminar viscosity, nu */
};

/* Density diffusion (delta-SPH) of the continuity equation. */
enum wl_sph_ddt {
  WL_SPH_DDT_NONE = 0,
  /* Molteni & Colagrossi (2009) with the Fourtakas et al. (2019) hydrostatic
   * correction, between fluid pairs, for fluid particles that have no
   * boundary neighbour (DualSPHysics DensityDT=2). */
  WL_SPH_DDT_FOURTAKAS = 1,
  /* The same term for every fluid particle, including those next to a wall
   * (DualSPHysics DensityDT=3, "DDT2Full"). Default: without it the fluid
   * next to a wall keeps its pressure noise, and wall pressure is what
   * wallload is for. With the wall condition (WL_SPH_BOUND_ADAMI) the wall
   * particles are in the sum too (sph/interact.h); with dynamic boundary
   * particles, fluid pairs only, as DualSPHysics. */
  WL_SPH_DDT_FOURTAKAS_FULL = 2,
};

/* Wall boundary condition of the boundary particles. */
enum wl_sph_boundary {
  /* Dynamic boundary particles (Crespo et al. 2007, CMC 5:173): boundary
   * particles integrate their own continuity equation, so a wall pushes
   * back only once the fluid has compressed it (DualSPHysics' DBC; kept
   * for comparison with DualSPHysics runs). */
  WL_SPH_BOUND_DBC = 0,
  /* Boundary particles take their pressure from the fluid next to them:
   * Adami, Hu & Adams (2012) generalized wall condition, sph/wall.h.
   * Default. */
  WL_SPH_BOUND_ADAMI = 1,
};

/* Time integrator (sph/integrate.h). */
enum wl_sph_integrator {
  WL_SPH_SYMPLECTIC = 0, /* symplectic position Verlet: two force evaluations a step (default) */
  WL_SPH_VERLET = 1,     /* Verlet with an Euler step every verlet_steps: one evaluation a step */
};

/* The accepted range of each tunable numerics parameter, closed at both
 * ends unless named _OPEN: one table, read by the solver's validation
 * (wl_sph_const_make) and by the scenario schema's numerics keys, so that a
 * value `check` accepts is one the solver runs. */
#define WL_SPH_COEFH_MIN 0.5
#define WL_SPH_COEFH_MAX 2.0
#define WL_SPH_COEFSOUND_MIN 5.0
#define WL_SPH_COEFSOUND_MAX 100.0
#define WL_SPH_CFL_MIN_OPEN 0.0
#define WL_SPH_CFL_MAX 1.0
#define WL_SPH_ALPHA_MAX 1.0
#define WL_SPH_SMAGORINSKY_MAX 0.3 /* Smagorinsky constants in use: 0.1-0.2 */
#define WL_SPH_NU_MAX 1.0      /* [m^2/s] */
#define WL_SPH_DELTA_MAX 1.0
#define WL_SPH_VERLET_STEPS_MAX 1000

/* Weak compressibility holds density variations to about Ma^2: c0 is kept
 * at least this many times the largest expected flow speed (Ma <= 0.1,
 * Monaghan 1994). For a dam break of height H, whose front runs at
 * 2 sqrt(g H) (Ritter), it gives c0 = 20 sqrt(g H): DualSPHysics'
 * dam-break setting. At coefsound 10 (Ma 0.2 at the front) the dam
 * breaks of `wallload bench` leave the density range at their impacts
 * (docs/boundary.md). */
#define WL_SPH_MACH_FACTOR 10.0

/* The smoothing length h = coefh sqrt(dim) dp [m] (DualSPHysics'
 * convention): the solver's constants and the plan call it. */
static inline double wl_sph_smoothing_length(double coefh, int dim, double dp) {
  return coefh * sqrt((double)dim) * dp;
}

/* The numerical speed of sound [m/s]: coefsound sqrt(g h_max) (h_max the
 * largest water depth, DualSPHysics), raised to WL_SPH_MACH_FACTOR times a
 * known largest flow speed expected_speed (0: none). The one formula: the
 * solver's constants (wl_sph_const_make) and the plan's estimates call it. */
static inline double wl_sph_sound_speed(double coefsound, double g, double h_max,
                                        double expected_speed) {
  const double c_depth = coefsound * sqrt(g * h_max), c_mach = WL_SPH_MACH_FACTOR * expected_speed;
  return c_depth > c_mach ? c_depth : c_mach;
}

/* Run parameters; wl_sph_params_default fills DualSPHysics' defaults. */
struct wl_sph_params {
  int dim;                  /* 2 (x, z) or 3 (x, y, z); gravity along the last axis */
  double dp;                /* initial particle spacing [m] */
  double coefh;             /* h = coefh sqrt(dim) dp [-]; default 1 */
  double coefsound;         /* c0 = coefsound sqrt(g h_max) [-]; default 10 */
  double h_max;             /* largest water depth, for c0 [m] */
  double expected_speed;    /* the largest flow speed the scene is known to reach [m/s]
                               (a dam break's front, 2 sqrt(g H)); c0 is raised to
                               WL_SPH_MACH_FACTOR times it where coefsound's is lower.
                               0: none known */
  double rho0;              /* reference density [kg/m^3]; default 1000 */
  double g;                 /* gravity magnitude [m/s^2]; default 9.81 */
  enum wl_sph_visc visc;    /* default artificial */
  double alpha;             /* artificial viscosity coefficient [-]; default 0.01 */
  double visc_bound_factor; /* alpha (or nu) multiplier for fluid-boundary pairs [-]; 1 */
  double nu;                /* kinematic viscosity for WL_SPH_VISC_LAMINAR [m^2/s]; 1e-6 */
  enum wl_sph_ddt ddt;      /* default WL_SPH_DDT_FOURTAKAS_FULL */
  double delta;             /* density diffusion coefficient [-]; default 0.1 */
  double residual_alpha;    /* residual viscosity alpha_r (sph/vgrad.h) [-]; 0: off (default) */
  double smagorinsky;       /* Smagorinsky constant C_s of the eddy viscosity (sph/vgrad.h) [-];
                               0: off (default); laminar viscosity only */
  double cfl;               /* CFL number [-]; default 0.2 */
  enum wl_sph_integrator integrator; /* default WL_SPH_SYMPLECTIC */
  enum wl_sph_boundary boundary;     /* wall condition; default WL_SPH_BOUND_ADAMI */
  /* Artificial viscosity (Monaghan 1992, approaching pairs only) between
   * fluid and wall particles when the fluid's viscosity is laminar: a
   * wall resists a particle running into it in proportion to its approach
   * speed, as the artificial viscosity does everywhere in DualSPHysics'
   * runs. 0: none. With artificial viscosity the walls get alpha *
   * visc_bound_factor instead. */
  double wall_alpha;                 /* [-] */
  /* Wall limiter (sph/guard.h wl_sph_wall_limit): a fluid particle found
   * behind a wall face after its update is put back on the face and loses
   * its velocity into the wall. 0: off. */
  int wall_limiter;
  /* Tension limit: a fluid particle's density is not integrated below the
   * Tait density of the pressure -tension_max rho0 g h_max, so the fluid
   * sustains at most that tension (in heads of its own depth). A particle
   * that leaves the fluid or a wall (a splash, a jet off the wall's end)
   * loses by the continuity equation the density its kernel's lost
   * neighbours gave it, and would otherwise pull on the fluid with up to
   * the Tait equation's -B (tens of times rho0 g h_max) when it lands.
   * Default 1; <= 0: no limit. */
  double tension_max;       /* [-] */
  int verlet_steps;         /* Verlet: an Euler step every verlet_steps steps; default 40
                               (DualSPHysics VerletSteps) */
  /* Guard (instability detection after every step; see sph/guard.h). */
  double dt_collapse;       /* unstable when dt < dt_collapse * initial dt [-]; 1e-3 */
  double rho_min_factor;    /* fluid density below rho_min_factor rho0 is unstable; 0.7 */
  double rho_max_factor;    /* ... above rho_max_factor rho0 (DualSPHysics RhopOut); 1.3 */
  double penetration;       /* fluid depth behind a wall face that counts as crossing
                               it, in units of dp [-]; default 0.5 */
  /* Particle shifting (sph/shift.h; Lind et al. 2012, Skillen et al. 2013,
   * as DualSPHysics): each step moves a fluid particle by -A h |v| dt
   * grad C, away from where its neighbours crowd. shift_coef is A (0: off,
   * the default; DualSPHysics uses 2, range 1-6); shift_tfs the free-
   * surface threshold on div r below which a particle is not shifted (0:
   * 1.5 in 2D, 2.75 in 3D, DualSPHysics' values; div r = dim inside the
   * fluid). */
  double shift_coef;        /* [-] */
  double shift_tfs;         /* [-] */
  /* Damping zones along x (DualSPHysics "Damping"), up to WL_SPH_DAMP_ZONES
   * (the flume uses zone 0 beyond the seawall, zone 1 at its seaward end):
   * in zone z, fluid velocities are relaxed towards rest at the rate
   * damp_rate[z] w^2, w rising linearly from 0 at x = damp_x0[z] to 1 at
   * x = damp_x1[z] (either order) and 1 beyond. A zone is off when its
   * damp_rate is 0 (the default). */
  double damp_x0[WL_SPH_DAMP_ZONES], damp_x1[WL_SPH_DAMP_ZONES]; /* [m] */
  double damp_rate[WL_SPH_DAMP_ZONES]; /* full-strength relaxation rate [1/s]; 0: none */
  /* Mirror planes (3D only) at the domain box's low and high y faces
   * (cfg->lo[1], cfg->hi[1]): each particle within the kernel support of
   * a plane also sees the mirror images of its neighbours there (y -> 2
   * y_plane - y, v_y -> -v_y), and a fluid particle carried across is
   * reflected back. A plane is a symmetry plane (a scene symmetric about
   * it runs on its half) and, equally, a free-slip wall. Off when 0. */
  int mirror_lo, mirror_hi;
  double mirror_y_lo, mirror_y_hi; /* [m]: must be cfg->lo[1], cfg->hi[1] */
};

/* Derived constants (host computes, both backends read). Float members are
 * what the hot loops use; the double ones serve host-side bookkeeping. */
struct wl_sph_const {
  int dim;
  enum wl_sph_visc visc;
  enum wl_sph_ddt ddt;
  enum wl_sph_boundary boundary;
  int wall_limiter;   /* wl_sph_wall_limit after each update (params.h) */
  wl_real h;          /* smoothing length [m] */
  wl_real inv_h;      /* 1/h [1/m] */
  wl_real support2;   /* (2h)^2 [m^2] */
  wl_real eta2;       /* 0.01 h^2 [m^2], keeps 1/(r^2 + eta2) finite */
  wl_real kw;         /* Wendland C2 normalisation aD: 7/(4 pi h^2) or 21/(16 pi h^3) */
  wl_real kf;         /* gradient factor -5 aD / h^2: grad_i W_ij = kf (1-q/2)^3 r_ij */
  wl_real rho0;       /* [kg/m^3] */
  wl_real inv_rho0;   /* [m^3/kg] */
  wl_real B;          /* Tait coefficient c0^2 rho0 / 7 [Pa] */
  wl_real c0;         /* [m/s] */
  wl_real mass;       /* rho0 dp^dim, fluid and boundary [kg or kg/m in 2D] */
  wl_real av_ff;      /* alpha c0 h: artificial viscosity, fluid-fluid [m^2/s] */
  wl_real av_fb;      /* visc_bound_factor alpha c0 h, fluid-boundary [m^2/s]; with laminar
                         viscosity wall_alpha c0 h */
  wl_real lam_ff;     /* 4 nu (Lo & Shao), fluid-fluid [m^2/s] */
  wl_real lam_fb;     /* 4 nu visc_bound_factor, fluid-boundary [m^2/s] */
  wl_real rav;        /* residual_alpha c0 h (sph/vgrad.h), fluid-fluid [m^2/s]; 0: off */
  wl_real nut_c;      /* (smagorinsky dp)^2, the eddy viscosity's (sph/vgrad.h) [m^2]; 0: off */
  wl_real ddt_k;      /* delta * 2h * c0 (DualSPHysics DDTkh * Cs0) [m^2/s] */
  wl_real ddt_fb;     /* the same for a fluid particle's wall neighbours: ddt_k under the
                         full diffusion with the wall condition, else 0 (sph/interact.h) */
  wl_real ddt_h[3];   /* the series of sph/eos.h in dz: rho0 c_n (rho0 g / B)^n [kg/m^(3+n)]
                         (rho0 g / B is DualSPHysics' DDTgz) */
  wl_real gravity[WL_SPH_DIM_MAX]; /* [m/s^2]; last used component -g */
  double dp;          /* [m] */
  double h_d;         /* h in double [m] */
  double c0_d;        /* c0 in double [m/s] */
  double cfl;         /* [-] */
  enum wl_sph_integrator integrator;
  int verlet_steps;   /* Verlet: an Euler step every verlet_steps steps */
  double dt_collapse, rho_min, rho_max; /* guard thresholds ([-], kg/m^3, kg/m^3) */
  wl_real rho_floor;  /* fluid density floor (tension_max) [kg/m^3]; 0: none */
  double penetration; /* guard: crossing depth [m] */
  double shift_coef;  /* particle shifting A [-] (0: off) */
  double shift_tfs;   /* its free-surface threshold on div r [-] */
  /* damping zones: start [m], 1/(x1 - x0) [1/m] (signed), rate [1/s] (0: none) */
  double damp_x0[WL_SPH_DAMP_ZONES], damp_inv_len[WL_SPH_DAMP_ZONES];
  double damp_rate[WL_SPH_DAMP_ZONES];
  int mirror;         /* mirror planes, 3D: bit 0 the grid's low y face, bit 1 its high */
  double mirror_y[2]; /* their y [m] (the domain box's lo[1] and hi[1]) */
};

#endif
