/* params.c: SPH parameter defaults, validation and the derived constants
 * (sph/params.h), and the run configuration helpers. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "wallload/sph.h"

void wl_sph_params_default(struct wl_sph_params *prm, int dim, double dp, double h_max) {
  memset(prm, 0, sizeof *prm);
  prm->dim = dim;
  prm->dp = dp;
  prm->coefh = 1.0;     /* DualSPHysics examples: h = sqrt(dim) dp */
  prm->coefsound = 10;  /* DualSPHysics default; faster flows: expected_speed (the Mach rule) */
  prm->h_max = h_max;
  prm->rho0 = 1000;
  prm->g = 9.81;
  prm->visc = WL_SPH_VISC_ARTIFICIAL;
  prm->alpha = 0.01;    /* DualSPHysics examples, and the seeds' lower bound */
  prm->visc_bound_factor = 1;
  prm->nu = 1e-6;
  prm->ddt = WL_SPH_DDT_FOURTAKAS_FULL;
  prm->delta = 0.1;     /* DualSPHysics DensityDTvalue */
  prm->cfl = 0.2;       /* DualSPHysics CFLnumber */
  prm->integrator = WL_SPH_SYMPLECTIC;
  prm->boundary = WL_SPH_BOUND_ADAMI;
  prm->wall_alpha = 0.0; /* off: 0.01 took 3 % off a reflected solitary wave (docs/boundary.md) */
  prm->wall_limiter = 1;
  prm->tension_max = 1;
  prm->verlet_steps = 40; /* DualSPHysics VerletSteps */
  prm->dt_collapse = 1e-3;
  prm->rho_min_factor = 0.7; /* DualSPHysics RhopOutMin 700 for rho0 1000 */
  prm->rho_max_factor = 1.3; /* RhopOutMax 1300 */
  prm->penetration = 0.5;
}

static enum wl_status bad(struct wl_error *err, const char *name, double v, const char *valid) {
  return wl_error_set(err, WL_EINPUT, "sph parameter %s: %g; %s", name, v, valid);
}

enum wl_status wl_sph_const_make(const struct wl_sph_params *prm, struct wl_sph_const *k,
                                 struct wl_error *err) {
  if (prm->dim != 2 && prm->dim != 3) return bad(err, "dim", prm->dim, "must be 2 or 3");
  if (!(prm->dp > 0) || !isfinite(prm->dp)) return bad(err, "dp", prm->dp, "must be > 0 m");
  char range[64];
  if (!(prm->coefh >= WL_SPH_COEFH_MIN && prm->coefh <= WL_SPH_COEFH_MAX)) {
    snprintf(range, sizeof range, "must be in [%g, %g]", WL_SPH_COEFH_MIN, WL_SPH_COEFH_MAX);
    return bad(err, "coefh", prm->coefh, range);
  }
  if (!(prm->coefsound >= WL_SPH_COEFSOUND_MIN && prm->coefsound <= WL_SPH_COEFSOUND_MAX)) {
    snprintf(range, sizeof range, "must be in [%g, %g]", WL_SPH_COEFSOUND_MIN,
             WL_SPH_COEFSOUND_MAX);
    return bad(err, "coefsound", prm->coefsound, range);
  }
  if (!(prm->expected_speed >= 0) || !isfinite(prm->expected_speed))
    return bad(err, "expected_speed", prm->expected_speed, "must be >= 0 m/s (0: none known)");
  if (!(prm->h_max > 0) || !isfinite(prm->h_max))
    return bad(err, "h_max", prm->h_max, "must be > 0 m (the largest water depth)");
  if (!(prm->rho0 > 0)) return bad(err, "rho0", prm->rho0, "must be > 0 kg/m^3");
  if (!(prm->g > 0)) return bad(err, "g", prm->g, "must be > 0 m/s^2");
  if (prm->visc != WL_SPH_VISC_ARTIFICIAL && prm->visc != WL_SPH_VISC_LAMINAR)
    return bad(err, "visc", prm->visc, "must be 0 (artificial) or 1 (laminar)");
  if (!(prm->alpha >= 0 && prm->alpha <= WL_SPH_ALPHA_MAX)) {
    snprintf(range, sizeof range, "must be in [0, %g]", WL_SPH_ALPHA_MAX);
    return bad(err, "alpha", prm->alpha, range);
  }
  if (!(prm->visc_bound_factor >= 0))
    return bad(err, "visc_bound_factor", prm->visc_bound_factor, "must be >= 0");
  if (!(prm->nu >= 0 && prm->nu <= WL_SPH_NU_MAX)) {
    snprintf(range, sizeof range, "must be in [0, %g] m^2/s", WL_SPH_NU_MAX);
    return bad(err, "nu", prm->nu, range);
  }
  if (prm->ddt != WL_SPH_DDT_NONE && prm->ddt != WL_SPH_DDT_FOURTAKAS &&
      prm->ddt != WL_SPH_DDT_FOURTAKAS_FULL)
    return bad(err, "ddt", prm->ddt, "must be 0 (none), 1 (Fourtakas) or 2 (Fourtakas, full)");
  if (!(prm->delta >= 0 && prm->delta <= WL_SPH_DELTA_MAX)) {
    snprintf(range, sizeof range, "must be in [0, %g]", WL_SPH_DELTA_MAX);
    return bad(err, "delta", prm->delta, range);
  }
  if (!(prm->residual_alpha >= 0 && prm->residual_alpha <= WL_SPH_ALPHA_MAX)) {
    snprintf(range, sizeof range, "must be in [0, %g]", WL_SPH_ALPHA_MAX);
    return bad(err, "residual_alpha", prm->residual_alpha, range);
  }
  if (!(prm->smagorinsky >= 0 && prm->smagorinsky <= WL_SPH_SMAGORINSKY_MAX)) {
    snprintf(range, sizeof range, "must be in [0, %g]", WL_SPH_SMAGORINSKY_MAX);
    return bad(err, "smagorinsky", prm->smagorinsky, range);
  }
  if (prm->smagorinsky > 0 && prm->visc != WL_SPH_VISC_LAMINAR)
    return bad(err, "smagorinsky", prm->smagorinsky,
               "needs the laminar viscosity (the eddy viscosity adds to its nu)");
  if (prm->residual_alpha > 0 && prm->integrator == WL_SPH_VERLET)
    return bad(err, "residual_alpha", prm->residual_alpha,
               "needs the symplectic integrator (the Verlet leapfrog amplifies a velocity-"
               "dependent damping)");
  if (!(prm->cfl > WL_SPH_CFL_MIN_OPEN && prm->cfl <= WL_SPH_CFL_MAX)) {
    snprintf(range, sizeof range, "must be in (%g, %g]", WL_SPH_CFL_MIN_OPEN, WL_SPH_CFL_MAX);
    return bad(err, "cfl", prm->cfl, range);
  }
  if (!(prm->wall_alpha >= 0 && prm->wall_alpha <= 1))
    return bad(err, "wall_alpha", prm->wall_alpha, "must be in [0, 1]");
  if (prm->boundary != WL_SPH_BOUND_DBC && prm->boundary != WL_SPH_BOUND_ADAMI)
    return bad(err, "boundary", prm->boundary, "must be 0 (dbc) or 1 (adami)");
  if (prm->integrator != WL_SPH_SYMPLECTIC && prm->integrator != WL_SPH_VERLET)
    return bad(err, "integrator", prm->integrator, "must be 0 (symplectic) or 1 (Verlet)");
  if (!(prm->verlet_steps >= 1 && prm->verlet_steps <= WL_SPH_VERLET_STEPS_MAX)) {
    snprintf(range, sizeof range, "must be in [1, %d]", WL_SPH_VERLET_STEPS_MAX);
    return bad(err, "verlet_steps", prm->verlet_steps, range);
  }
  if (!(prm->dt_collapse >= 0 && prm->dt_collapse < 1))
    return bad(err, "dt_collapse", prm->dt_collapse, "must be in [0, 1)");
  if (!(prm->rho_min_factor >= 0 && prm->rho_min_factor < 1))
    return bad(err, "rho_min_factor", prm->rho_min_factor, "must be in [0, 1)");
  if (!(prm->rho_max_factor > 1)) return bad(err, "rho_max_factor", prm->rho_max_factor, "must be > 1");
  if (!(prm->penetration > 0)) return bad(err, "penetration", prm->penetration, "must be > 0 (units of dp)");
  if (!(prm->shift_coef >= 0 && prm->shift_coef <= 10))
    return bad(err, "shift_coef", prm->shift_coef, "must be in [0, 10] (0: no shifting; 1-6 usual)");
  if (!(prm->shift_tfs >= 0 && prm->shift_tfs < prm->dim))
    return bad(err, "shift_tfs", prm->shift_tfs, "must be in [0, dim) (0: 1.5 in 2D, 2.75 in 3D)");
  for (int z = 0; z < WL_SPH_DAMP_ZONES; z++) {
    if (!(prm->damp_rate[z] >= 0 && isfinite(prm->damp_rate[z])))
      return bad(err, "damp_rate", prm->damp_rate[z], "must be >= 0 and finite [1/s]");
    if (prm->damp_rate[z] > 0 && !(fabs(prm->damp_x1[z] - prm->damp_x0[z]) > 0))
      return bad(err, "damp_x1", prm->damp_x1[z], "must differ from damp_x0 (the zone's length)");
  }

  if ((prm->mirror_lo || prm->mirror_hi) && prm->dim != 3)
    return bad(err, "mirror_lo/mirror_hi", 1, "mirror planes need dim 3 (they are planes y = const)");

  memset(k, 0, sizeof *k);
  const int dim = prm->dim;
  const double gamma = 7.0;
  const double h = wl_sph_smoothing_length(prm->coefh, dim, prm->dp);
  const double c0 =
      wl_sph_sound_speed(prm->coefsound, prm->g, prm->h_max, prm->expected_speed);
  const double B = c0 * c0 * prm->rho0 / gamma;
  const double aD = wl_sph_kernel_norm(dim, h);
  k->dim = dim;
  k->visc = prm->visc;
  k->ddt = prm->ddt;
  k->boundary = prm->boundary;
  k->wall_limiter = prm->wall_limiter != 0;
  k->h = (wl_real)h;
  k->inv_h = (wl_real)(1.0 / h);
  k->support2 = (wl_real)(4.0 * h * h);
  k->eta2 = (wl_real)(0.01 * h * h);
  k->kw = (wl_real)aD;
  k->kf = (wl_real)(-5.0 * aD / (h * h));
  k->rho0 = (wl_real)prm->rho0;
  k->inv_rho0 = (wl_real)(1.0 / prm->rho0);
  k->B = (wl_real)B;
  k->c0 = (wl_real)c0;
  k->mass = (wl_real)(prm->rho0 * pow(prm->dp, dim));
  const int art = prm->visc == WL_SPH_VISC_ARTIFICIAL;
  k->av_ff = (wl_real)(art ? prm->alpha * c0 * h : 0.0);
  k->av_fb = (wl_real)(art ? prm->alpha * prm->visc_bound_factor * c0 * h : prm->wall_alpha * c0 * h);
  k->lam_ff = (wl_real)(art ? 0.0 : 4.0 * prm->nu);
  k->lam_fb = (wl_real)(art ? 0.0 : 4.0 * prm->nu * prm->visc_bound_factor);
  k->rav = (wl_real)(prm->residual_alpha * c0 * h);
  k->nut_c = (wl_real)(prm->smagorinsky * prm->smagorinsky * prm->dp * prm->dp);
  k->ddt_k = (wl_real)(prm->ddt == WL_SPH_DDT_NONE ? 0.0 : prm->delta * 2.0 * h * c0);
  k->ddt_fb = prm->ddt == WL_SPH_DDT_FOURTAKAS_FULL && prm->boundary == WL_SPH_BOUND_ADAMI
                  ? k->ddt_k
                  : (wl_real)0.0;
  {
    /* sph/eos.h: the series' coefficients 1/7, -3/49, 13/343 times powers of
     * rho0 g / B, in double, so the pair loop multiplies dz alone */
    const double gz = prm->rho0 * prm->g / B;
    k->ddt_h[0] = (wl_real)(prm->rho0 * gz / 7.0);
    k->ddt_h[1] = (wl_real)(prm->rho0 * gz * gz * -3.0 / 49.0);
    k->ddt_h[2] = (wl_real)(prm->rho0 * gz * gz * gz * 13.0 / 343.0);
  }
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) k->gravity[a] = 0;
  k->gravity[dim - 1] = (wl_real)(-prm->g);
  k->dp = prm->dp;
  k->h_d = h;
  k->c0_d = c0;
  k->cfl = prm->cfl;
  k->integrator = prm->integrator;
  k->verlet_steps = prm->verlet_steps;
  k->dt_collapse = prm->dt_collapse;
  k->rho_min = prm->rho_min_factor * prm->rho0;
  k->rho_floor = (wl_real)(prm->tension_max > 0
                               ? wl_sph_eos_rho_of_p(prm->rho0, (double)k->B,
                                                     -prm->tension_max * prm->rho0 * prm->g * prm->h_max)
                               : 0.0);
  /* The floor's contract is a tension of at most tension_max rho0 g h_max,
   * and the pressure the solver and the probes read is the float equation of
   * state's: the double inverse above rounds to a float density whose float
   * pressure can lie a rounding step (0.1 Pa at coefsound 20) beyond it.
   * Raised to the first density whose pressure keeps the contract. */
  if (k->rho_floor > 0) {
    const double cap = -prm->tension_max * prm->rho0 * prm->g * prm->h_max;
    while ((double)wl_sph_eos_p(k, k->rho_floor) < cap)
      k->rho_floor = WL_REAL_DOUBLE ? (wl_real)nextafter(k->rho_floor, INFINITY)
                                    : (wl_real)nextafterf((float)k->rho_floor, INFINITY);
  }
  k->rho_max = prm->rho_max_factor * prm->rho0;
  k->penetration = prm->penetration * prm->dp;
  k->shift_coef = prm->shift_coef;
  k->shift_tfs = prm->shift_tfs > 0 ? prm->shift_tfs : dim == 2 ? 1.5 : 2.75;
  for (int z = 0; z < WL_SPH_DAMP_ZONES; z++)
    if (prm->damp_rate[z] > 0) {
      k->damp_x0[z] = prm->damp_x0[z];
      k->damp_inv_len[z] = 1.0 / (prm->damp_x1[z] - prm->damp_x0[z]);
      k->damp_rate[z] = prm->damp_rate[z];
    }
  k->mirror = (prm->mirror_lo ? 1 : 0) | (prm->mirror_hi ? 2 : 0);
  k->mirror_y[0] = prm->mirror_lo ? prm->mirror_y_lo : 0.0;
  k->mirror_y[1] = prm->mirror_hi ? prm->mirror_y_hi : 0.0;
  return WL_OK;
}

void wl_sph_config_default(struct wl_sph_config *cfg, int dim, double dp, double h_max) {
  memset(cfg, 0, sizeof *cfg);
  wl_sph_params_default(&cfg->prm, dim, dp, h_max);
}

enum wl_status wl_sph_config_add_faces(struct wl_sph_config *cfg, const double *x, const double *z,
                                       int n, double thickness, struct wl_error *err) {
  enum wl_status st = WL_OK;
  for (int i = 0; i + 1 < n && st == WL_OK; i++)
    st = wl_sph_config_add_wall(cfg, x[i], z[i], x[i + 1], z[i + 1], thickness, err);
  if (st != WL_OK || n < 2) return st;
  /* the caps: across the layers' ends, facing out along the polyline, from
   * the face's end point to thickness behind it (the layers lie on the
   * right of the walk) */
  for (int end = 0; end < 2 && st == WL_OK; end++) {
    const int i0 = end ? n - 2 : 0, i1 = end ? n - 1 : 1, v = end ? n - 1 : 0;
    const double tx = x[i1] - x[i0], tz = z[i1] - z[i0], len = sqrt(tx * tx + tz * tz);
    if (!(len > 0)) continue;
    const double rx = tz / len * thickness, rz = -tx / len * thickness; /* right normal */
    st = end ? wl_sph_config_add_wall(cfg, x[v], z[v], x[v] + rx, z[v] + rz, thickness, err)
             : wl_sph_config_add_wall(cfg, x[v] + rx, z[v] + rz, x[v], z[v], thickness, err);
  }
  return st;
}

enum wl_status wl_sph_config_add_wall(struct wl_sph_config *cfg, double ax, double az, double bx,
                                      double bz, double thickness, struct wl_error *err) {
  if (cfg->n_walls >= WL_SPH_WALLS_MAX)
    return wl_error_set(err, WL_EINPUT, "too many wall faces for the penetration guard (at most %d)",
                        (int)WL_SPH_WALLS_MAX);
  if (!(thickness >= 0) || !isfinite(ax + az + bx + bz))
    return wl_error_set(err, WL_EINPUT, "wall face (%g, %g)-(%g, %g), thickness %g: not finite or "
                        "negative thickness", ax, az, bx, bz, thickness);
  cfg->walls[cfg->n_walls++] = wl_sph_wall_make(ax, az, bx, bz, thickness);
  return WL_OK;
}
