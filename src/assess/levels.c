/* levels.c: a load case at two resolutions (resolution.refine; vres.h,
 * docs/variable-resolution.md): the flume built whole at each level's
 * spacing, then each cut to the water it simulates by wl_vres_layout's rule.
 * The fine level holds the wall, its probes and the gauges from the
 * interface on; the coarse level the paddle or the crater and the gauges
 * seaward of it. */
#include "assess_private.h"

#include <math.h>
#include <string.h>

#include "wallload/sph/params.h"

/* Parked particles (vres.h) a level keeps for the water that flows in: a
 * share of its own, the wave's volume twice (it may pile up against the
 * wall before it flows back) and at least a few hundred. A level that runs
 * out stops with an error naming it: the solitary wave H/h = 0.3 of
 * test_solitary_wall (0.05 m^2, a quarter of the fine level's water) ran
 * out of a quarter's share. */
#define LEVELS_SPARE_SHARE 0.25
#define LEVELS_SPARE_MIN 500

/* The water the case's wave holds above still level [m^2]: the solitary
 * wave's integral 2 H / K of H sech^2(K x); a crater's lip about
 * eta0 r0 (its plane section's rim). */
static double wave_volume(const struct wl_plan *plan, enum wl_load_case load) {
  if (load == WL_CASE_SOLITARY && plan->solitary.present && plan->solitary.wave.K > 0)
    return 2.0 * plan->solitary.wave.H / plan->solitary.wave.K;
  if (load == WL_CASE_EXPLOSION && plan->explosion.present)
    return plan->explosion.eta0 * plan->explosion.r0;
  return 0.0;
}

/* Place a band of parking slots above the level's walls (its domain's top
 * raised to hold them) over the level's water in x. */
static void park_band(struct wl_flume *f, double x_lo, double x_hi, int spare,
                      struct wl_vres_level_spec *spec) {
  struct wl_sph_config *cfg = &f->cfg;
  const double h = wl_sph_smoothing_length(cfg->prm.coefh, 2, cfg->prm.dp);
  const double slot = 2.2 * h; /* vres.c: slots out of each other's reach */
  const double lo = fmax(x_lo, cfg->lo[0]) + h, hi = fmin(x_hi, cfg->hi[0]) - h;
  const int nx = (int)fmax(1.0, floor((hi - lo) / slot));
  const int rows = (2 * spare + nx - 1) / nx + 1; /* twice the spares: removed ones park too */
  const double z0 = cfg->hi[1] + 2.0 * h;
  spec->park_lo[0] = lo, spec->park_hi[0] = hi;
  spec->park_lo[1] = z0, spec->park_hi[1] = z0 + rows * slot;
  cfg->hi[1] = spec->park_hi[1] + 2.0 * h;
  spec->spare = spare;
}

enum wl_status levels_build(const struct wl_scenario *s, const struct wl_plan *plan,
                            enum wl_load_case load, struct wl_flume *fine, struct wl_flume *coarse,
                            struct wl_vres_level_spec spec[2], struct wl_vres_opts *vo,
                            struct wl_error *err) {
  struct wl_plan pc = *plan;
  pc.refine = 0;
  pc.dp = plan->dp_coarse;
  pc.h_sml = wl_sph_smoothing_length(plan->coefh, 2, pc.dp);
  enum wl_status st = wl_flume_build(s, &pc, load, coarse, err);
  if (st) return st;
  memset(vo, 0, sizeof *vo);
  struct wl_vres_layout lay;
  wl_plan_refine_layout(plan, plan->refine_from, vo, &lay); /* the layout plan priced */
  struct wl_flume *lv[2] = {coarse, fine};
  const double z_walls = fine->cfg.hi[1]; /* the walls' top, below the parking bands */
  for (int l = 0; l < 2 && !st; l++) {
    const double dp = lv[l]->cfg.prm.dp;
    const double reach = 2.0 * wl_sph_smoothing_length(lv[l]->cfg.prm.coefh, 2, dp) + dp;
    st = wl_flume_crop(lv[l], lay.water_lo[l], lay.water_hi[l], reach, err);
    if (st) {
      wl_error_prefix(err, "resolution.refine: the %s level (dp = %g m): ", l ? "fine" : "coarse",
                      dp);
      break;
    }
    memset(&spec[l], 0, sizeof spec[l]);
    const int fluid = lv[l]->particles.n - lv[l]->particles.n_bound;
    const double spare = LEVELS_SPARE_SHARE * fluid + 2.0 * wave_volume(plan, load) / (dp * dp);
    park_band(lv[l], lay.water_lo[l], lay.water_hi[l], (int)fmax(LEVELS_SPARE_MIN, spare),
              &spec[l]);
    spec[l].cfg = &lv[l]->cfg;
    spec[l].initial = &lv[l]->particles;
    spec[l].own_lo = lay.own_lo[l], spec[l].own_hi = lay.own_hi[l];
  }
  vo->z_bed = wl_scenario_bed_z(s, plan->refine_from);
  vo->z_top = z_walls - 2.0 * plan->dp_coarse;
  return st;
}
