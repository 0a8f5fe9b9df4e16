/* plan.c: load cases -> initial conditions, resolution, end time and cost.
 * See plan.h for the two equal-energy bases. */
#include "wallload/plan.h"
#include "wallload/vres.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <stdarg.h>
#include <string.h>

#include "wallload/scene.h"
#include "wallload/units.h"

/* Wave lengths (at the celerity offshore) that must pass the wall after the
 * crest for the load to have decayed: the rear half of the wave (its tail
 * at 1 % of H) passes in half a length, the other half covers run-down and
 * overtopping water coming to rest. A wave keeps its duration while it
 * shoals, so the offshore celerity is the right one here. (Two lengths
 * spent a third of seawall.yaml's solitary case on still water.) */
#define LOAD_PASSES 1.0
/* Effective solitary wavelength: the distance over which eta > 1 % of H is
 * 2 arccosh(10)/K (first order), about 6/K. */
#define SOLITARY_LENGTH_FACTOR 6.0
/* Time for the explosion's wave train to pass the wall, as a multiple of the
 * shallow-water travel time of its leading edge. */
#define EXPLOSION_TRAIN_FACTOR 1.5
/* Land modelled behind the seawall, closed by an end wall: at least
 * LAND_MIN [m], or LAND_PER_HEIGHT wall heights (overtopping jets land
 * within a few crest heights), never beyond the scenario's flume. */
#define LAND_MIN 0.5
#define LAND_PER_HEIGHT 5.0
/* Distance kept between a gauge and a truncated left end of the flume [m]. */
#define GAUGE_CLEARANCE 0.5
/* Memory of a run: a fixed part (libraries, the result record) and bytes
 * per particle. Host: the peak resident size of `assess` on the CPU backend
 * (state, the sort's second copy, cell index, snapshot buffers), measured
 * at 22k-317k particles in 2D (307 B) and 98k in 3D (430 B) and rounded
 * up. GPU: the CUDA backend's arrays (bytes_per_particle in cuda.cu with
 * the Verlet copies, 112 B in 2D and 148 B in 3D) plus its sort scratch and
 * cell index. */
#define HOST_BYTES_FIXED (32.0 * 1048576.0)
#define HOST_BYTES_PER_PARTICLE_2D 320.0
#define HOST_BYTES_PER_PARTICLE_3D 440.0
#define GPU_BYTES_FIXED (320.0 * 1048576.0) /* CUDA context and the backend's margin */
#define GPU_BYTES_PER_PARTICLE_2D 140.0
#define GPU_BYTES_PER_PARTICLE_3D 180.0

static void note(struct wl_plan *p, const char *fmt, ...) {
  if (p->n_notes >= WL_PLAN_MAX_NOTES) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(p->notes[p->n_notes++], sizeof p->notes[0], fmt, ap);
  va_end(ap);
}

static enum wl_crater_shape sim_shape(const struct wl_scenario *s, int dims) {
  int lip = s->explosion.lip_form.choice;
  int plane = lip == WL_LIP_PLANE || (lip == WL_LIP_AUTO && dims == 2);
  switch (s->explosion.shape.choice) {
  case WL_SHAPE_QUADRATIC: return WL_CRATER_SHAPE_QUADRATIC;
  case WL_SHAPE_QUARTIC_LIP:
    return plane ? WL_CRATER_SHAPE_QUARTIC_LIP_PLANE : WL_CRATER_SHAPE_QUARTIC_LIP_AXI;
  default: return plane ? WL_CRATER_SHAPE_QUADRATIC_LIP_PLANE : WL_CRATER_SHAPE_QUADRATIC_LIP_AXI;
  }
}

/* domain.dimensions: as given, or auto: 2D unless the geometry needs the
 * width. Solitary waves are long-crested and a plane crater (lip_form:
 * plane, or an energy given per metre) is a line source: a flume section
 * holds them. A point source, the crater of a charge or of eta0 + r0 with
 * an axisymmetric form, narrower than the flume spreads its wave radially
 * (amplitude falling as 1/sqrt(r) before the side walls confine it), which
 * a section cannot: 3D. */
static enum wl_status plan_dims(const struct wl_scenario *s, struct wl_plan *p,
                                struct wl_error *err) {
  if (!s->domain.dimensions.is_auto) {
    p->dims = (int)s->domain.dimensions.q.si;
    snprintf(p->dims_reason, sizeof p->dims_reason, "domain.dimensions");
    return WL_OK;
  }
  p->dims = 2;
  snprintf(p->dims_reason, sizeof p->dims_reason,
           "auto: long-crested waves and plane craters need no width");
  if (!s->explosion.present || s->explosion.lip_form.choice == WL_LIP_PLANE) return WL_OK;
  if (s->explosion.model.choice == WL_MODEL_THROWN_MASS) { /* flume.c: 2D only */
    snprintf(p->dims_reason, sizeof p->dims_reason, "auto: the thrown-mass model is 2D only");
    return WL_OK;
  }
  double r0 = NAN;
  if (s->explosion.charge.given) {
    enum wl_status st = wl_explosion_vandorn_r0(s->explosion.charge.q.si, &r0, err);
    if (st) return st;
  } else if (s->explosion.eta0.given) {
    r0 = s->explosion.r0.q.si;
  }
  const double width = s->domain.width.q.si;
  if (isfinite(r0) && 2.0 * r0 < width) {
    p->dims = 3;
    snprintf(p->dims_reason, sizeof p->dims_reason,
             "auto: the crater (2 R0 = %.3g m) is narrower than the flume (%.3g m), its wave "
             "spreads radially", 2.0 * r0, width);
  } else if (isfinite(r0)) {
    snprintf(p->dims_reason, sizeof p->dims_reason,
             "auto: the crater (2 R0 = %.3g m) spans the flume (%.3g m)", 2.0 * r0, width);
  }
  return WL_OK;
}

/* Time [s] a long wave takes from x0 to x1 > x0 over the scenario's bed:
 * the integral of dx / c(x), with c(x) = c_flat sqrt((d(x) + a) / (h + a))
 * (shallow-water scaling of the celerity c_flat it has on the flat depth
 * h; d(x) the still depth, a the wave's amplitude, 0 for a linear wave).
 * Shoaling slows a wave: seawall.yaml's wave reaches its 0.06 m deep toe
 * at half its offshore speed. The depth is floored at a tenth of h + a (a
 * dry toe: the wave runs up a beach to reach the wall). */
static double travel_time(const struct wl_scenario *s, double h, double a, double c_flat,
                          double x0, double x1) {
  enum { STEPS = 400 };
  if (!(x1 > x0)) return 0.0;
  const double dx = (x1 - x0) / STEPS;
  double t = 0.0;
  for (int i = 0; i < STEPS; i++) {
    const double x = x0 + (i + 0.5) * dx;
    const double depth = fmax(h - wl_scenario_bed_z(s, x) + a, 0.1 * (h + a));
    t += dx / (c_flat * sqrt(depth / (h + a)));
  }
  return t;
}

/* Wavenumber k [1/m] of the linear dispersion relation omega^2 = g k
 * tanh(k d) at depth d > 0: Newton from the larger of the two lower bounds
 * omega^2/g (tanh <= 1) and omega/sqrt(g d) (tanh x <= x); checked to a
 * relative residual below 1e-9 for wavelengths 0.01-1000 m on depths
 * 0.001-50 m. */
static double dispersion_k(double omega, double g, double d) {
  double k = fmax(omega * omega / g, omega / sqrt(g * d));
  for (int it = 0; it < 60; it++) {
    const double t = tanh(k * d), f = g * k * t - omega * omega;
    const double df = g * t + g * k * d * (1.0 - t * t);
    const double dk = f / df;
    k -= dk;
    if (fabs(dk) < 1e-12 * k) break;
  }
  return k;
}

/* Time [s] the energy of waves of length `lambda` on the flat depth h takes
 * from x0 to x1 > x0 over the scenario's bed: the integral of dx / c_g(x),
 * the linear group velocity at the local depth for the wave's period (a
 * period is kept while a wave shoals). The depth is floored as in
 * travel_time. */
static double group_travel_time(const struct wl_scenario *s, double h, double g, double lambda,
                                double x0, double x1) {
  enum { STEPS = 400 };
  if (!(x1 > x0) || !(lambda > 0)) return 0.0;
  const double k0 = 2.0 * WL_PI / lambda, omega = sqrt(g * k0 * tanh(k0 * h));
  const double dx = (x1 - x0) / STEPS;
  double t = 0.0;
  for (int i = 0; i < STEPS; i++) {
    const double x = x0 + (i + 0.5) * dx;
    const double d = fmax(h - wl_scenario_bed_z(s, x), 0.1 * h);
    const double k = dispersion_k(omega, g, d), kd2 = 2.0 * k * d;
    const double cg = 0.5 * (omega / k) * (1.0 + (kd2 < 700 ? kd2 / sinh(kd2) : 0.0));
    t += dx / cg;
  }
  return t;
}

static enum wl_status plan_solitary(const struct wl_scenario *s, struct wl_plan *p,
                                    struct wl_error *err) {
  struct wl_plan_solitary *ps = &p->solitary;
  ps->present = 1;
  const enum wl_solitary_theory theory =
      s->solitary.theory.choice == WL_THEORY_BOUSSINESQ ? WL_SOLITARY_BOUSSINESQ
      : s->solitary.theory.choice == WL_THEORY_EXACT    ? WL_SOLITARY_EXACT
                                                        : WL_SOLITARY_GRIMSHAW;
  enum wl_status st =
      wl_waves_solitary_init(&ps->wave, theory, p->h, s->solitary.height.q.si, p->g, err);
  if (st) return st;
  st = wl_waves_solitary_integrals(&ps->wave, p->rho, &ps->integrated, err);
  if (st) return st;
  wl_waves_solitary_closed_form(&ps->wave, p->rho, &ps->first_order);
  ps->energy_seed001 = wl_waves_lh74_energy(p->rho, p->g, p->h);

  double H = s->solitary.height.q.si, c = wl_waves_solitary_celerity(&ps->wave);
  double K = sqrt(3.0 * H / (4.0 * p->h * p->h * p->h));
  double length = SOLITARY_LENGTH_FACTOR / K;
  double xw = s->wall.x.q.si;
  ps->paddle = s->solitary.generation.choice == WL_GENERATION_PADDLE;
  if (ps->paddle) {
    st = wl_waves_goring_init(&ps->goring, p->h, H, p->g, 0.002, err);
    if (st) return st;
    /* The crest leaves the paddle about lambda/c after the start. */
    ps->arrival_time = ps->goring.lambda / c + travel_time(s, p->h, H, c, 0.0, xw);
    ps->fits = 1;
  } else {
    /* auto: the wave's front (1 % of H) just reaches the first slope's toe
     * (or the wall), so the simulation starts where the wave meets the
     * structure; seed 001 also starts its wave as an initial condition. */
    double x_toe = xw;
    for (int i = 0; i < s->n_bed; i++)
      if (s->bed[i].slope.q.si != 0.0) {
        x_toe = s->bed[i].from.q.si;
        break;
      }
    ps->crest_x0 = s->solitary.at.is_auto ? fmax(x_toe - 0.5 * length, 0.5 * length)
                                          : s->solitary.at.q.si;
    if (!s->solitary.at.is_auto && ps->crest_x0 < 0.5 * length)
      note(p, "loads.solitary.at = %.3g m puts the crest within half a wave length (%.3g m) of "
              "the left end: the wave's tail is cut there",
           ps->crest_x0, 0.5 * length);
    /* An automatic crest position can land at or behind the wall when the
     * flume is shorter than the wave: the solitary case cannot run then
     * (wl_flume_build refuses it); scenarios that only need the flume's
     * still water (tests) may still plan. */
    ps->fits = ps->crest_x0 < xw;
    if (!ps->fits)
      note(p, "the %.3g m solitary wave is %.3g m long (2 x 3/K) and does not fit seaward of the "
              "wall at x = %g m: its case cannot run (wall.x >= %.3g m needed)",
           H, length, xw, length);
    ps->arrival_time = travel_time(s, p->h, H, c, ps->crest_x0, xw);
    /* Model only what the wave needs: the flume starts behind its tail. */
    ps->x_left = fmax(0.0, ps->crest_x0 - 0.5 * length);
  }
  ps->end_time = ps->arrival_time + LOAD_PASSES * length / c;
  {
    /* the front's distance from the crest when it raises the water at the
     * wall by WL_PLAN_QUIET_RISE of the depth there (plan.h) */
    const double d_wall = fmax(p->h - wl_scenario_bed_z(s, xw), 0.0);
    const double rise = WL_PLAN_QUIET_RISE * d_wall;
    const double s_front = H > rise && rise > 0 ? acosh(sqrt(H / rise)) / K : 0.0;
    const double x_front = xw - s_front;
    if (ps->paddle)
      ps->quiet_until = x_front > 0 ? ps->goring.lambda / c + travel_time(s, p->h, H, c, 0.0, x_front) : 0.0;
    else
      ps->quiet_until = x_front > ps->crest_x0 ? travel_time(s, p->h, H, c, ps->crest_x0, x_front) : 0.0;
    ps->quiet_until = fmin(ps->quiet_until, ps->arrival_time);
  }
  if (ps->wave.eps > WL_WAVES_EPS_GRIMSHAW_ACCURATE && theory != WL_SOLITARY_EXACT) {
    /* Beyond its accurate range, say by how much the third-order energy
     * misses the exact solitary wave's (Clamond & Dutykh method). */
    struct wl_solitary_exact ex;
    struct wl_wave_integrals exi;
    struct wl_error xerr;
    wl_error_clear(&xerr);
    /* 4096 modes: the energy within 1.5e-6 of 16384's at H/h 0.55-0.78, in
     * an eighth of the time (a ladder plans this once a level) */
    if (wl_waves_exact_solitary(ps->wave.eps, 4096, &ex, &xerr) == WL_OK) {
      wl_waves_exact_integrals(&ex, p->rho, p->g, p->h, &exi);
      note(p, "H/h = %.3g is beyond Grimshaw's accurate range (0.5): its energy %.4g J/m is "
              "%.1f %% off the exact solitary wave's %.4g J/m (loads.solitary.theory: exact "
              "starts the exact wave)",
           ps->wave.eps, ps->integrated.energy,
           100.0 * (ps->integrated.energy - exi.energy) / exi.energy, exi.energy);
    }
  }
  double ratio = ps->energy_seed001 / ps->integrated.energy;
  note(p, "seed 001's solitary energy 0.958 rho g h^3 = %.4g J/m is the energy of the highest "
          "wave on h = %g m; the %g m wave carries %.4g J/m (integrated), %.1f times less",
       ps->energy_seed001, p->h, H, ps->integrated.energy, ratio);
  return WL_OK;
}

/* The 2D crater energy per metre scales as W^0.78 (eta0^2 R0 with eta0 R0 ~
 * W^0.54 and R0 ~ W^0.3), so the charge of a given energy is closed form. */
static enum wl_status charge_for_energy_2d(const struct wl_explosion_params *ep,
                                           enum wl_crater_shape shape, double energy,
                                           double *charge_kg, struct wl_error *err) {
  struct wl_explosion_chain unit;
  const double w_ref = WL_LB_KG; /* one pound: the formulae's own unit */
  enum wl_status st = wl_explosion_chain_from_charge(ep, w_ref, &unit, err);
  if (st) return st;
  double e_ref;
  st = wl_explosion_energy(shape, 2, ep->rho, ep->g, unit.eta0, unit.r0, &e_ref, err);
  if (st) return st;
  double exponent = 2.0 * WL_WHALIN_EXP - WL_VANDORN_EXP;
  *charge_kg = w_ref * pow(energy / e_ref, 1.0 / exponent);
  return WL_OK;
}

static enum wl_status plan_explosion(const struct wl_scenario *s, struct wl_plan *p,
                                     struct wl_error *err) {
  struct wl_plan_explosion *px = &p->explosion;
  px->present = 1;
  struct wl_explosion_params ep;
  wl_explosion_params_default(&ep);
  ep.rho = p->rho;
  ep.g = p->g;
  ep.whalin_coef = s->explosion.coefficient.q.si;
  ep.wave_share = s->explosion.wave_fraction.q.si;
  px->shape = sim_shape(s, p->dims);
  px->basis = s->explosion.energy_basis.choice;
  enum wl_status st = WL_OK;
  if (s->explosion.charge.given) {
    px->source = WL_SOURCE_CHARGE;
    st = wl_explosion_chain_from_charge(&ep, s->explosion.charge.q.si, &px->chain, err);
  } else if (s->explosion.eta0.given) {
    px->source = WL_SOURCE_CRATER;
    st = wl_explosion_chain_from_energy(
        &ep, WL_PI * p->rho * p->g * pow(s->explosion.eta0.q.si * s->explosion.r0.q.si, 2) / 6.0,
        &px->chain, err);
  } else if (!s->explosion.energy.is_auto) {
    px->source = WL_SOURCE_ENERGY;
    px->matched_energy = s->explosion.energy.q.si;
    st = wl_explosion_chain_from_energy(&ep, px->matched_energy, &px->chain, err);
  } else {
    px->source = WL_SOURCE_SOLITARY;
    if (px->basis == WL_BASIS_SEED001) {
      px->matched_energy = p->solitary.energy_seed001;
      st = wl_explosion_chain_from_energy(&ep, px->matched_energy, &px->chain, err);
    } else if (p->dims == 2) {
      px->matched_energy = p->solitary.integrated.energy;
      double w;
      st = charge_for_energy_2d(&ep, px->shape, px->matched_energy, &w, err);
      if (!st) st = wl_explosion_chain_from_charge(&ep, w, &px->chain, err);
    } else {
      px->matched_energy = p->solitary.integrated.energy * s->domain.width.q.si;
      st = wl_explosion_chain_from_energy(&ep, px->matched_energy, &px->chain, err);
    }
  }
  if (st) {
    wl_error_prefix(err, "loads.explosion: ");
    return st;
  }
  if (px->source == WL_SOURCE_CRATER) {
    px->eta0 = s->explosion.eta0.q.si;
    px->r0 = s->explosion.r0.q.si;
  } else {
    px->eta0 = px->chain.eta0;
    px->r0 = px->chain.r0;
  }
  px->conserves_mass = wl_explosion_conserves_mass(px->shape, p->dims);
  if ((st = wl_explosion_extent(px->shape, px->r0, &px->extent, err)) ||
      (st = wl_explosion_net_volume(px->shape, p->dims, px->eta0, px->r0, &px->net_volume, err)) ||
      (st = wl_explosion_energy(px->shape, p->dims, p->rho, p->g, px->eta0, px->r0, &px->energy,
                                err)) ||
      (st = wl_explosion_energy_quad(px->shape, p->dims, p->rho, p->g, px->eta0, px->r0,
                                     &px->energy_quad, err))) {
    wl_error_prefix(err, "loads.explosion: ");
    return st;
  }
  px->x_center = s->explosion.at.q.si;
  px->wave_fraction = ep.wave_share;
  px->fraction_energy = ep.wave_share * px->chain.chemical_energy;
  px->model_thrown = s->explosion.model.choice == WL_MODEL_THROWN_MASS;
  px->thrown_parts = (int)s->explosion.thrown_parts.q.si;
  /* the thrown mass keeps the bound it always had: its launched parts are
   * not a surface profile */
  if (px->model_thrown)
    px->rise = 2.0 * px->eta0;
  else if ((st = wl_explosion_rim_height(px->shape, px->eta0, &px->rise, err)))
    return st;

  double xw = s->wall.x.q.si;
  if (px->x_center - px->extent < 0 || px->x_center + px->extent > xw)
    return wl_error_set(err, WL_EINPUT,
                        "%s: loads.explosion.at: the crater (centre %g m, outer radius %.3g m) "
                        "does not fit between the paddle and the wall (%g m); expected a centre "
                        "between %.3g m and %.3g m",
                        s->path, px->x_center, px->extent, xw, px->extent, xw - px->extent);
  if (px->eta0 >= p->h)
    note(p, "the crater is deeper (eta0 = %.3g m) than the water (%g m): the bed is exposed at "
            "the start; the empirical crater formulae do not cover this",
         px->eta0, p->h);
  double c_lin = sqrt(p->g * p->h);
  px->arrival_time = travel_time(s, p->h, 0.0, c_lin, px->x_center + px->extent, xw);
  px->quiet_until = 0.5 * px->arrival_time; /* plan.h */
  /* The explosion's wave train is dispersive: shorter waves travel slower
   * than sqrt(g h). Run until the slowest part that matters (the train
   * behind the leading wave) has reached the wall. */
  /* Where the crater is small against the depth the train is dispersive
   * and its largest waves, about the crater's diameter long, come with
   * their group velocity, well behind the leading edge: seawall.yaml's
   * explosion (R0 = 0.27 m in 0.36 m of water, 7.2 m from the wall) loads
   * the wall most between 9 and 13 s, peak at 11.8 s, while its leading
   * wave arrives at 5 s and 1.5 times that ended the run at 8.1 s with a
   * dynamic peak a quarter of the real one (an H100 run to 16 s).
   * So the run lasts until waves of length 2 R0 have arrived, travelling
   * at their group velocity over the bed (15.5 s there; the H100 run to
   * that end with the absorbing zone below peaked at 10.3 s, 28.8 N/m). */
  const double t_long =
      EXPLOSION_TRAIN_FACTOR * travel_time(s, p->h, 0.0, c_lin, px->x_center - 2.0 * px->extent, xw);
  const double t_group =
      group_travel_time(s, p->h, p->g, 2.0 * px->r0, px->x_center - px->extent, xw);
  px->end_time = fmax(t_long, t_group);
  /* The waves running seaward leave the modelled flume through an
   * absorbing zone (flume.c) of four crater radii or two depths, the
   * longer, just behind the crater's extent. */
  px->absorber = fmax(4.0 * px->extent, 2.0 * p->h);
  px->x_left = px->x_center - 2.0 * px->extent - px->absorber;
  if (px->x_left < 0.0) { /* the flume's own end is near: a shorter zone */
    px->absorber = fmax(0.0, px->absorber + px->x_left);
    px->x_left = 0.0;
  }
  if (!px->conserves_mass)
    note(p, "crater shape %s does not conserve mass in %dD (net %+.4g %s): the water level "
            "after the waves settle differs from the scenario's depth",
         wl_explosion_shape_name(px->shape), p->dims, px->net_volume,
         p->dims == 2 ? "m^2 per metre" : "m^3");
  if (px->chain.charge_kg < 1.0)
    note(p, "charge %.3g g TNT: the Van Dorn and Whalin fits come from charges of pounds to "
            "tons; sub-kilogram charges are an extrapolation",
         px->chain.charge_kg * 1e3);
  note(p, "the explosion's wave-energy share: the crater holds %.2g %% of the chemical energy; "
          "wave_fraction %.0f %% (seed 000 eq 9) is a ceiling, %.4g J",
       100.0 * px->chain.wave_fraction, 100.0 * px->wave_fraction, px->fraction_energy);
  return WL_OK;
}

/* Time of one CUDA step of a small flume on the H100 (plan.h): launches and
 * the per-step synchronisation, fewer with Verlet's single evaluation. */
static double gpu_step_seconds(const struct wl_plan *p) {
  return p->evals_per_step == 1 ? WL_PLAN_GPU_STEP_S_VERLET : WL_PLAN_GPU_STEP_S;
}

/* Wetted section between x0 and the wall [m^2], by the trapezoid rule on
 * the bed's corners (exact for a piecewise-linear bed). */
static double wet_area(const struct wl_scenario *s, double h, double x0) {
  double xw = s->wall.x.q.si, area = 0.0, x_prev = x0;
  double d_prev = h - wl_scenario_bed_z(s, x0);
  for (int i = 0; i <= s->n_bed; i++) {
    double x = i < s->n_bed ? s->bed[i].from.q.si : xw;
    if (x <= x0) continue;
    double d = h - wl_scenario_bed_z(s, x);
    area += 0.5 * (d + d_prev) * (x - x_prev);
    x_prev = x;
    d_prev = d;
  }
  return area;
}

/* x as a count, without the undefined conversion of a value beyond long's
 * range (a dp of 1e-10 m): clamped to LONG_MAX / 4, so that sums of a few
 * counts stay representable; the plan then refuses it (WL_PLAN_PARTICLES_MAX). */
static long count_of(double x) {
  const double most = (double)(LONG_MAX / 4);
  return !(x > 0) ? 0 : x >= most ? LONG_MAX / 4 : (long)x;
}

/* Particles of one case whose flume starts at x_left, and its
 * particle-steps to t_end at its time step dt; two_levels: as
 * resolution.refine lays it out (p->refine's layout), else dp everywhere. */
static void case_cost(const struct wl_scenario *s, struct wl_plan *p, int two_levels,
                      double x_left, double t_end,
                      double rise, double dt, long *n_fluid, long *n_boundary,
                      double *particle_steps) {
  double xw = s->wall.x.q.si;
  double area = wet_area(s, p->h, x_left);
  double wall_top = wl_scenario_bed_z(s, xw) + s->wall.height.q.si;
  /* flume.c's polyline: the left end (or the piston) from the domain's top
   * to the bed, the bed and land to the end of the flume, the seawall's
   * face, the end wall up to the top; ceil(2h / dp) layers behind it */
  const double z_top = fmax(wall_top, p->h) + fmax(3.0 * rise, 0.5 * p->h);
  const double layers = ceil(2.0 * p->h_sml / p->dp);
  double perimeter = (z_top - wl_scenario_bed_z(s, x_left)) + (xw + p->land_length - x_left) +
                     s->wall.height.q.si + (z_top - wall_top);
  double across = p->dims == 3 ? s->domain.width.q.si / (p->symmetry ? 2 : 1) / p->dp : 1.0;
  *n_fluid = count_of(area / (p->dp * p->dp) * across);
  *n_boundary = count_of(layers * perimeter / p->dp * across);
  if (two_levels && p->refine_from > x_left) {
    /* each level over its own range and into the other's by the overlap
     * and its band (vres.h); both step at the fine level's dt */
    const double xf = p->refine_from, d_if = p->h - wl_scenario_bed_z(s, xf);
    const double a_fine = wet_area(s, p->h, xf), a_coarse = area - a_fine;
    const double dpc = p->dp_coarse, ov = p->refine_overlap;
    const double a_c = a_coarse + d_if * (ov + p->refine_band[0]);
    const double a_f = a_fine + d_if * (ov + p->refine_band[1]);
    const double left = z_top - wl_scenario_bed_z(s, x_left);
    const double per_c = left + (xf - x_left) + ov + p->refine_band[0];
    const double per_f = perimeter - left - (xf - x_left) + ov + p->refine_band[1];
    *n_fluid = count_of(a_c / (dpc * dpc) + a_f / (p->dp * p->dp));
    /* the same number of layers: each level's h / dp is the fine level's */
    *n_boundary = count_of(layers * (per_c / dpc + per_f / p->dp));
  }
  if (p->dims == 3) {
    /* flume.c: the polyline extruded under the side walls too, and the
     * side walls over the flume's profile up to the domain's top */
    const double x_end = xw + p->land_length;
    double profile = (x_end - x_left) * z_top - p->land_length * wall_top -
                     ((xw - x_left) * p->h - area);
    if (profile < 0) profile = 0;
    /* side walls of boundary particles (none where a mirror plane is) */
    const double sides = p->slip_walls ? 0.0 : p->symmetry ? 1.0 : 2.0;
    *n_boundary = count_of(layers * perimeter / p->dp * (across + sides * layers) +
                           sides * layers * profile / (p->dp * p->dp));
  }
  *particle_steps = (double)(*n_fluid + *n_boundary) * t_end / dt;
}

/* "line" of a value for an error message, or "default". */
/* ":LINE" of a value written in the file, "" for a default (the message
 * then names the key alone). */
static const char *where(const struct wl_scenario_value *v, char buf[32]) {
  if (!v->line) return "";
  snprintf(buf, 32, ":%d", v->line);
  return buf;
}

/* Rows of dp across the modelled width (flume.c rounds it the same way). */
static long modelled_rows(const struct wl_scenario *s, const struct wl_plan *p, int half) {
  const long rows = lround(s->domain.width.q.si / (half ? 2 : 1) / p->dp);
  return rows < 1 ? 1 : rows;
}

/* Whether two mirror planes `rows` rows of dp apart are far enough apart
 * for the solver: more than one cell of the neighbour search (2h; cells.c
 * checks the same on the grid it builds). */
static int planes_apart(const struct wl_plan *p, long rows) {
  return ceil((double)rows * p->dp / (2.0 * p->h_sml)) >= 2;
}

/* 3D: the side walls and the symmetry plane on the centreline (every flume
 * scene is symmetric about it). auto takes the plane when the width is an
 * even number of lattice rows, so that the half is whole rows and the
 * modelled flume is the one the full width would give, and when the half
 * is wide enough for its two planes (with free-slip side walls);
 * centreline takes it always (the width then rounds to an even number of
 * rows). A flume between free-slip walls narrower than the solver's
 * mirror planes allow is refused. */
static enum wl_status plan_sides(const struct wl_scenario *s, struct wl_plan *p,
                                 struct wl_error *err) {
  p->slip_walls = p->dims == 3 && s->domain.side_walls.choice == WL_SIDE_WALLS_FREE_SLIP;
  p->symmetry = 0;
  if (p->dims != 3) return WL_OK;
  const struct wl_scenario_value *w = &s->domain.width;
  char wbuf[32];
  if (p->slip_walls && !planes_apart(p, modelled_rows(s, p, 0)))
    return wl_error_set(err, WL_EINPUT,
                        "%s%s: domain.width: free-slip side walls %g m apart; they must be more "
                        "than 2h = %.3g m (one cell of the neighbour search) apart; expected a "
                        "wider flume, a smaller dp, or domain.side_walls: particles",
                        s->path, where(w, wbuf), w->q.si, 2.0 * p->h_sml);
  if (s->domain.symmetry.choice == WL_SYMMETRY_CENTRELINE) {
    p->symmetry = 1;
    if (p->slip_walls && !planes_apart(p, modelled_rows(s, p, 1)))
      return wl_error_set(err, WL_EINPUT,
                          "%s%s: domain.symmetry: centreline: the half width, %g m, between the "
                          "symmetry plane and a free-slip side wall is not more than 2h = %.3g m; "
                          "expected domain.symmetry: none or auto, a wider flume or a smaller dp",
                          s->path, where(&s->domain.symmetry, wbuf), modelled_rows(s, p, 1) * p->dp,
                          2.0 * p->h_sml);
  } else if (s->domain.symmetry.choice == WL_SYMMETRY_AUTO) {
    const long rows = lround(w->q.si / p->dp);
    p->symmetry = rows >= 2 && rows % 2 == 0 && (!p->slip_walls || planes_apart(p, rows / 2));
  }
  return WL_OK;
}

double wl_plan_bed_min(const struct wl_scenario *s) {
  double z = fmin(0.0, wl_scenario_bed_z(s, s->wall.x.q.si));
  for (int i = 0; i < s->n_bed; i++)
    if (s->bed[i].from.q.si < s->wall.x.q.si) z = fmin(z, wl_scenario_bed_z(s, s->bed[i].from.q.si));
  return z;
}

double wl_plan_modelled_depth(double h, double z_min, double z_bed, double dp) {
  /* rows j >= 0 with z_min + (j + 1/2) dp < h, and from the first at least
   * dp/2 above z_bed, as the scene lays them (scene.c, its tolerance) */
  const double top = ceil((h - z_min) / dp - 0.5 - WL_SCENE_LATTICE_TOL);
  const double first = ceil((z_bed - z_min) / dp - WL_SCENE_LATTICE_TOL);
  return fmax(top - first, 0.0) * dp;
}

double wl_plan_whole_rows_dp(const struct wl_scenario *s, double dp_target, double *worst) {
  const double h = s->water.depth.q.si, z_min = wl_plan_bed_min(s);
  const double z_wall = wl_scenario_bed_z(s, s->wall.x.q.si);
  const double depths[3] = {h - z_min, h - z_wall, z_wall - z_min};
  double best = dp_target, best_err = INFINITY, best_dist = INFINITY;
  for (int d = 0; d < 3; d++) {
    if (!(depths[d] > 0)) continue;
    const long n0 = (long)floor(depths[d] / (WL_PLAN_DP_COARSER * dp_target));
    const long n1 = (long)ceil(depths[d] / (WL_PLAN_DP_FINER * dp_target));
    for (long n = n0 > 1 ? n0 : 1; n <= n1 + 1; n++) {
      const double dp = n == n1 + 1 ? dp_target : depths[d] / (double)n; /* and the target */
      if (dp < WL_PLAN_DP_FINER * dp_target * (1 - 1e-12) ||
          dp > WL_PLAN_DP_COARSER * dp_target * (1 + 1e-12))
        continue;
      double e = 0.0;
      for (int m = 0; m < 2; m++) {
        const double zb = m == 0 ? z_min : z_wall;
        if (h - zb > 0)
          e = fmax(e, fabs(wl_plan_modelled_depth(h, z_min, zb, dp) - (h - zb)) / (h - zb));
      }
      if (s->resolution.refine.present && !s->resolution.refine.gpu) {
        /* the coarse level's rows at the interface (from: auto puts it on
         * the offshore bed) */
        const struct wl_scenario_value *rf = &s->resolution.refine.from;
        const double zf = rf->is_auto ? z_min : wl_scenario_bed_z(s, rf->q.si);
        if (h - zf > 0)
          e = fmax(e, fabs(wl_plan_modelled_depth(h, z_min, zf, 2.0 * dp) - (h - zf)) / (h - zf));
      }
      const double dist = fabs(log(dp / dp_target));
      /* errors below 1e-9 are exact: then the nearest spacing wins */
      const double ek = e < 1e-9 ? 0.0 : e, bk = best_err < 1e-9 ? 0.0 : best_err;
      if (ek < bk || (ek == bk && dist < best_dist)) best = dp, best_err = e, best_dist = dist;
    }
  }
  if (worst) *worst = best_err;
  return best;
}

double wl_plan_level_dp(const struct wl_scenario *s, const struct wl_plan *p, double factor) {
  return s->resolution.dp.is_auto ? wl_plan_whole_rows_dp(s, p->dp_target * factor, NULL)
                                  : p->dp * factor;
}

/* plan.h */
void wl_plan_refine_layout(const struct wl_plan *p, double x_if, struct wl_vres_opts *vo,
                           struct wl_vres_layout *lay) {
  struct wl_vres_opts own = {0};
  if (!vo) vo = &own;
  vo->overlap = WL_PLAN_REFINE_OVERLAP_BANDS;
  vo->buffer_h = WL_PLAN_REFINE_BUFFER_H;
  wl_vres_layout(x_if, p->dp_coarse, p->dp, p->h_sml / p->dp, 1, vo, lay);
}

/* The first x seaward of the wall where the bed departs from the bed at
 * x0 (a slope begins or a step): the toe of the structure's fore slope;
 * the wall's x for a flat bed. */
static double first_bed_change(const struct wl_scenario *s, double x0) {
  const double xw = s->wall.x.q.si, z0 = wl_scenario_bed_z(s, x0);
  double x_change = xw;
  for (int i = 0; i < s->n_bed; i++) {
    const double xb = s->bed[i].from.q.si;
    if (xb > x0 && xb < x_change && (fabs(wl_scenario_bed_z(s, xb + 1e-6) - z0) > 1e-12 ||
                                     fabs(wl_scenario_bed_z(s, xb) - z0) > 1e-12))
      x_change = xb;
  }
  return x_change;
}

/* What rules an interface at xf out (NULL: none; else `why`, the reason
 * and what to change, n bytes at most): room for both levels' water seaward
 * and landward (lo..hi, the layout's reach), a flat bed there (the flux
 * points stand on it), the still water in whole rows of both spacings (so
 * that the two free surfaces meet), the explosion's crater clear of the
 * fine level's band when the explosion refines. */
static const char *refine_problem(const struct wl_scenario *s, const struct wl_plan *p, double xf,
                                  int explosion_refines, char *why, size_t n) {
  struct wl_vres_layout lay;
  wl_plan_refine_layout(p, xf, NULL, &lay);
  const double reach = 2.0 * wl_sph_smoothing_length(p->coefh, 2, p->dp_coarse);
  const double lo = lay.water_lo[1] - reach, hi = lay.water_hi[0] + reach;
  const double z_if = wl_scenario_bed_z(s, xf);
  const double x_left = fmin(p->solitary.present ? p->solitary.x_left : INFINITY,
                             p->explosion.present && explosion_refines ? p->explosion.x_left
                                                                        : INFINITY);
  if (lo <= x_left || hi >= s->wall.x.q.si) {
    snprintf(why, n,
             "%g m leaves no room for the two levels' overlap and bands (%.3g to %.3g m at dp = "
             "%.3g m); expected a position between %.3g and %.3g m",
             xf, lo, hi, p->dp, x_left + (xf - lo), s->wall.x.q.si - (hi - xf));
    return why;
  }
  for (int i = 0; i < s->n_bed; i++) {
    const double xb = s->bed[i].from.q.si;
    if (xb > lo && xb < hi && fabs(wl_scenario_bed_z(s, xb + 1e-9) - z_if) +
                                      fabs(wl_scenario_bed_z(s, hi) - z_if) +
                                      fabs(wl_scenario_bed_z(s, lo) - z_if) > 1e-9) {
      snprintf(why, n,
               "the bed changes at %g m (bathymetry[%d]), within the two levels' overlap and "
               "bands (%.3g to %.3g m); the interface needs a flat bed there: expected `from` at "
               "least %.3g m from every change of slope",
               xb, i, lo, hi, fmax(xf - lo, hi - xf));
      return why;
    }
  }
  if (p->explosion.present && explosion_refines) {
    const double rim = p->explosion.x_center + 2.0 * p->explosion.r0; /* the lip within 2 r0 */
    if (rim > lo) {
      snprintf(why, n,
               "the explosion's crater and lip reach %.3g m, into the fine level's band (from "
               "%.3g m); expected `from` beyond %.3g m",
               rim, lo, rim + (xf - lo));
      return why;
    }
  }
  const double z_min = wl_plan_bed_min(s);
  const double dc = wl_plan_modelled_depth(p->h, z_min, z_if, p->dp_coarse);
  const double df = wl_plan_modelled_depth(p->h, z_min, z_if, p->dp);
  if (fabs(dc - df) > 1e-9 * p->h) {
    snprintf(why, n,
             "at dp = %g m the still water at the interface is %.4g m in the fine level and "
             "%.4g m in the coarse one (2 dp): the two free surfaces would not meet; expected %s "
             "a dp that divides the depth %.4g m into an even number of rows",
             p->dp, df, dc,
             s->resolution.dp.is_auto
                 ? "(no spacing near the one particles_per_height asks models both) "
                 : "dp: auto (it picks a spacing that models both) or",
             p->h - z_if);
    return why;
  }
  return NULL;
}

/* An experimental numerics option (docs/numerics.md) at value v: off at 0;
 * refused where `refuse` (the key, its line and why); else a plan note
 * that it is experimental and what it costs. */
static enum wl_status experimental_option(const struct wl_scenario *s, struct wl_plan *p,
                                          const struct wl_scenario_value *v, const char *key,
                                          int refuse, const char *refusal, const char *caution,
                                          struct wl_error *err) {
  if (!(v->q.si > 0)) return WL_OK;
  if (refuse) {
    char rbuf[32];
    return wl_error_set(err, WL_EINPUT, "%s%s: %s: %g %s", s->path, where(v, rbuf), key, v->q.si,
                        refusal);
  }
  note(p, "%s = %g is experimental (docs/numerics.md): %s", key, v->q.si, caution);
  return WL_OK;
}

/* Why two levels do not pay on a GPU, as `check` says it (measured:
 * docs/variable-resolution.md, "On the GPU"). */
#define REFINE_GPU_COST                                                                        \
  "the two levels' coupling runs on the host every step, so the run takes longer than dp "    \
  "everywhere would (seawall.yaml's solitary case at dp = 0.006 m: 84 s against 5.5 s; "       \
  "docs/variable-resolution.md)"

/* resolution.refine: the two levels' layout (vres.h wl_vres_layout) and
 * which cases run it. An interface the scenario gives must pass
 * refine_problem (else the error names the key); `from: auto` places one
 * for the solitary case, WL_PLAN_REFINE_TOE_DEPTHS still-water depths
 * seaward of the first change of the bed (the slope's toe, where shoaling
 * begins; the wall on a flat bed, less the wave's half-length there so that
 * it reflects whole in the fine level) and the layout's reach, and keeps one
 * resolution, with a note saying why, where the coupling would not carry
 * the wave (3D, the GPU, a coarse level under WL_PLAN_REFINE_COARSE_PPH_MIN
 * particles a wave height, no flat bed, too short a coarse stretch). The
 * explosion keeps one resolution under auto: its short waves lose a quarter
 * of their impulse crossing the coarse level (docs/variable-resolution.md). */
static enum wl_status plan_refine(const struct wl_scenario *s, struct wl_plan *p,
                                  struct wl_error *err) {
  p->refine = p->refine_auto = 0;
  p->solitary.refine = p->explosion.refine = 0;
  if (!s->resolution.refine.present) return WL_OK;
  const struct wl_scenario_value *rf = &s->resolution.refine.from;
  const int is_auto = rf->is_auto;
  char rbuf[32], why[400];
  p->dp_coarse = 2.0 * p->dp;
  if (!is_auto) {
    if (p->dims != 2)
      return wl_error_set(err, WL_EINPUT,
                          "%s%s: resolution.refine.from: two resolutions run in 2D only, and this "
                          "scenario plans 3D (%s); expected domain.dimensions: 2 or no "
                          "resolution.refine",
                          s->path, where(rf, rbuf), p->dims_reason);
    if (refine_problem(s, p, rf->q.si, 1, why, sizeof why))
      return wl_error_set(err, WL_EINPUT, "%s%s: resolution.refine.from: %s", s->path,
                          where(rf, rbuf), why);
    p->refine_from = rf->q.si;
    p->solitary.refine = p->solitary.present;
    p->explosion.refine = p->explosion.present;
  } else {
    const char *none = NULL;
    double xf = 0.0;
    if (!p->solitary.present) none = "the scenario has no solitary case";
    else if (p->dims != 2) none = "two resolutions run in 2D only and this scenario plans 3D";
    else if (s->resolution.refine.gpu)
      none = "this run takes the GPU, where " REFINE_GPU_COST;
    else if (p->solitary.wave.H / p->dp_coarse < WL_PLAN_REFINE_COARSE_PPH_MIN) {
      snprintf(why, sizeof why,
               "the coarse level (dp = %.4g m) would hold %.1f particles over the solitary wave's "
               "height, under the %g that carry it within 2 %%",
               p->dp_coarse, p->solitary.wave.H / p->dp_coarse, WL_PLAN_REFINE_COARSE_PPH_MIN);
      none = why;
    } else {
      const double x_left = p->solitary.x_left, xw = s->wall.x.q.si;
      const double x_change = first_bed_change(s, x_left);
      /* the wave's first-order profile H sech^2(k x) on the offshore depth */
      const double d0 = p->h - wl_scenario_bed_z(s, x_left);
      const double k0 = sqrt(3.0 * p->solitary.wave.H / (4.0 * d0 * d0 * d0));
      double margin = WL_PLAN_REFINE_TOE_DEPTHS * d0;
      if (x_change >= xw) /* a flat bed to the wall: the wave's half-length (to 1 % of H) */
        margin = fmax(margin, acosh(10.0) / k0);
      struct wl_vres_layout lay;
      wl_plan_refine_layout(p, 0.0, NULL, &lay);
      const double beyond =
          lay.water_hi[0] + 2.0 * wl_sph_smoothing_length(p->coefh, 2, p->dp_coarse);
      xf = x_change - margin - beyond;
      /* an initial wave starts in the coarse level: at the interface it
       * stands at most WL_PLAN_REFINE_INITIAL_ETA_MAX of H; seawall.yaml's
       * interface at 15.5 m (4 %) and test_solitary_wall's 0.95 m from its
       * wall (4 %) gave the uniform run's peaks within 1.7 %, one at half
       * the crest's height 2-4 % low */
      const double front = p->solitary.paddle
                               ? -INFINITY
                               : p->solitary.crest_x0 +
                                     acosh(1.0 / sqrt(WL_PLAN_REFINE_INITIAL_ETA_MAX)) / k0;
      if (xf < front) {
        snprintf(why, sizeof why,
                 "the interface would stand at %.3g m, under the initial wave (above %.0f %% of "
                 "its height up to %.3g m): start the wave further seaward (loads.solitary.at) or "
                 "give resolution.refine.from",
                 xf, 100.0 * WL_PLAN_REFINE_INITIAL_ETA_MAX, front);
        none = why;
      } else if (xf - x_left < WL_PLAN_REFINE_COARSE_SHARE_MIN * (xw - x_left)) {
        snprintf(why, sizeof why,
                 "the interface would stand at %.3g m, leaving the coarse level %.2g m of the "
                 "%.3g m modelled: too little to save time",
                 xf, fmax(0.0, xf - x_left), xw - x_left);
        none = why;
      } else if (refine_problem(s, p, xf, 0, why, sizeof why)) {
        none = why;
      }
    }
    if (none) {
      note(p, "resolution.refine.from: auto: one resolution: %s", none);
      return WL_OK;
    }
    p->refine_from = xf;
    p->refine_auto = 1;
    p->solitary.refine = 1;
    if (p->explosion.present)
      note(p, "resolution.refine.from: auto: the explosion runs at dp everywhere (its short waves "
              "lose height crossing a coarse level: docs/variable-resolution.md)");
  }
  p->refine = 1;
  struct wl_vres_layout lay;
  wl_plan_refine_layout(p, p->refine_from, NULL, &lay);
  p->refine_overlap = lay.overlap;
  p->refine_band[0] = lay.band[0], p->refine_band[1] = lay.band[1];
  if (p->solitary.refine && p->solitary.wave.H / p->dp_coarse < WL_PLAN_REFINE_COARSE_PPH_MIN)
    note(p, "resolution.refine: the coarse level (dp = %.4g m) holds %.1f particles over the "
            "solitary wave's height; below %g the wave it hands to the fine level is off by more "
            "than 2 %% (docs/variable-resolution.md): a smaller dp, or no refine",
         p->dp_coarse, p->solitary.wave.H / p->dp_coarse, WL_PLAN_REFINE_COARSE_PPH_MIN);
  if (p->solitary.refine)
    note(p, "resolution.refine: the coupling reads the solitary case's positive impulse about 1 %% "
            "high against dp everywhere (solitary_wall at h/40 +1.1 %%, seawall.yaml at dp = "
            "0.006 m +0.7 %%; peaks within 0.4 %%, run-up within 1.5 %%; means of two or three "
            "starts, one run scatters by 1-3 %% in run-up; docs/variable-resolution.md)");
  if (s->resolution.refine.gpu_given)
    note(p, "resolution.refine on a GPU: " REFINE_GPU_COST "; the cost above counts "
            "particle-steps, not that");
  if (p->explosion.refine)
    note(p, "resolution.refine: the explosion's short waves cross the coarse level and lose "
            "height there (seawall.yaml: a quarter of the positive impulse at the wall; "
            "docs/variable-resolution.md); for design loads run the explosion at dp everywhere");
  return WL_OK;
}

static enum wl_status plan_resolution(const struct wl_scenario *s, struct wl_plan *p,
                                      struct wl_error *err) {
  p->fluid_area = wet_area(s, p->h, 0.0);
  p->land_length = fmin(s->domain.length.q.si - s->wall.x.q.si,
                        fmax(LAND_MIN, LAND_PER_HEIGHT * s->wall.height.q.si));
  double smallest = INFINITY;
  if (p->solitary.present) smallest = fmin(smallest, p->solitary.wave.H);
  if (p->explosion.present) smallest = fmin(smallest, p->explosion.eta0);
  {
    /* auto not resolved for a machine (wl_plan_choose): one */
    const struct wl_scenario_value *rv = &s->resolution.realisations;
    const int n_real = rv->q.si >= 1 ? (int)rv->q.si : 1;
    if (rv->given && !rv->is_auto && n_real > 1 && s->resolution.n_levels == 0) {
      char buf[32];
      return wl_error_set(err, WL_EINPUT,
                          "%s%s: resolution.realisations: %d, without resolution.convergence; "
                          "expected a convergence ladder (realisations run at each of its "
                          "levels), or realisations: 1",
                          s->path, where(rv, buf), n_real);
    }
    p->realisations = p->explosion.present && s->resolution.n_levels > 0 ? n_real : 1;
  }
  /* auto not resolved for a machine (wl_plan_choose): the coarsest */
  const struct wl_scenario_value *ppv = &s->resolution.particles_per_height;
  const double ppH = ppv->is_auto && !(ppv->q.si > 0) ? wl_plan_auto_pph[0] : ppv->q.si;
  p->dp_target = s->resolution.dp.is_auto ? smallest / ppH : s->resolution.dp.q.si;
  double depth_err = 0.0;
  p->dp = s->resolution.dp.is_auto ? wl_plan_whole_rows_dp(s, p->dp_target, &depth_err)
                                   : p->dp_target;
  if (!s->resolution.dp.is_auto && smallest / p->dp < 4)
    note(p, "dp = %g m gives only %.1f particles over the smallest wave height (%.3g m)", p->dp,
         smallest / p->dp, smallest);
  if (p->explosion.present && isfinite(smallest)) { /* the finest spacing run */
    double fine = p->dp;
    for (int k = 0; k < s->resolution.n_levels; k++)
      fine = fmin(fine, wl_plan_level_dp(s, p, s->resolution.levels[k].q.si));
    if (smallest / fine < WL_PLAN_EXPLOSION_PPH_MIN)
      note(p, "the finest spacing (%.3g m) puts %.1f particles over the smallest wave height: "
              "below %.0f, an explosion's short waves lose height before the wall and its "
              "impulse may lie outside the ladder's band (seawall.yaml at 4: 27 %% under); "
              "quote it from a finer ladder", fine, smallest / fine, WL_PLAN_EXPLOSION_PPH_MIN);
  }
  {
    const double z_min = wl_plan_bed_min(s), z_wall = wl_scenario_bed_z(s, s->wall.x.q.si);
    p->depth_model = wl_plan_modelled_depth(p->h, z_min, z_min, p->dp);
    p->depth_wall = p->h - z_wall;
    p->depth_wall_model = wl_plan_modelled_depth(p->h, z_min, z_wall, p->dp);
    const double e0 = fabs(p->depth_model / (p->h - z_min) - 1.0);
    const double ew = p->depth_wall > 0 ? fabs(p->depth_wall_model / p->depth_wall - 1.0) : 0.0;
    if (fmax(e0, ew) > 0.01)
      note(p, "at dp = %.4g m the still water is modelled as whole particle rows: %.4g m offshore "
              "(%.4g m), %.4g m at the wall (%.4g m); %s",
           p->dp, p->depth_model, p->h - z_min, p->depth_wall_model, p->depth_wall,
           s->resolution.dp.is_auto ? "no spacing near the target models both depths within 1 %"
                                    : "resolution.dp: auto picks a spacing that models them");
  }
  p->coefh = s->numerics.coefh.is_auto ? (p->dims == 2 ? WL_PLAN_COEFH_2D : WL_PLAN_COEFH_3D)
                                        : s->numerics.coefh.q.si;
  p->h_sml = wl_sph_smoothing_length(p->coefh, p->dims, p->dp);
  {
    enum wl_status rs = plan_refine(s, p, err);
    if (rs) return rs;
  }
  p->evals_per_step = s->numerics.integrator.choice == WL_INTEGRATOR_VERLET ? 1 : 2;
  enum wl_status xs = experimental_option(
      s, p, &s->numerics.residual_viscosity, "numerics.residual_viscosity",
      p->evals_per_step == 1,
      "needs numerics.integrator: symplectic; the Verlet leapfrog amplifies a velocity-dependent "
      "damping (its odd-even mode grows each step between the Euler steps), and "
      "scenarios/seawall.yaml's explosion load diverged with it; expected 0 or integrator: "
      "symplectic",
      "it keeps still water still, but makes solitary waves about 2.5 % fast and costs coarse "
      "levels up to 17 % of scenarios/seawall.yaml's explosion peak; do not quote its loads in a "
      "design",
      err);
  if (!xs)
    xs = experimental_option(
        s, p, &s->numerics.smagorinsky, "numerics.smagorinsky",
        s->numerics.viscosity.choice != WL_VISCOSITY_LAMINAR,
        "adds an eddy viscosity to the laminar viscosity's nu; expected 0 or numerics.viscosity: "
        "laminar",
        "an eddy viscosity where the flow shears at the particle scale; measured on the reference "
        "cases, not yet on the main job's loads",
        err);
  if (xs) return xs;
  enum wl_status st = plan_sides(s, p, err);
  if (st) return st;
  /* each case's speed of sound from its own largest depth, as its flume
   * gives the solver (flume.c); the CFL step at rest, h/c0 (the solver's
   * step is no larger) */
  const double coefsound = s->numerics.coefsound.q.si, cfl = s->numerics.cfl.q.si;
  p->c0 = 0.0;
  p->dt = INFINITY;
  if (p->solitary.present) {
    struct wl_plan_solitary *ps = &p->solitary;
    ps->h_max = p->h + ps->wave.H;
    ps->c0 = wl_sph_sound_speed(coefsound, p->g, ps->h_max, 0.0);
    ps->dt = cfl * p->h_sml / ps->c0;
    p->c0 = fmax(p->c0, ps->c0), p->dt = fmin(p->dt, ps->dt);
  }
  if (p->explosion.present) {
    struct wl_plan_explosion *px = &p->explosion;
    px->h_max = p->h + px->rise;
    /* the Mach rule for a 3D crater's collapse (docs/numerics.md, "the
     * Mach rule"): its cavity converges on the axis, where the inflow from
     * every side collides; at the depth's c0 a deep crater's collision
     * compressed water past the guard's 1300 kg/m^3. A plane (2D) crater's
     * two fronts meet without that focusing, and the depth's c0 holds them
     * (measured up to 4 times the stability matrix's resolution) */
    px->collapse_speed = sqrt(2.0 * p->g * (px->rise + px->eta0));
    px->expected_speed = p->dims == 3 ? px->collapse_speed : 0.0;
    px->c0 = wl_sph_sound_speed(coefsound, p->g, px->h_max, px->expected_speed);
    px->dt = cfl * p->h_sml / px->c0;
    p->c0 = fmax(p->c0, px->c0), p->dt = fmin(p->dt, px->dt);
  }
  if (!(p->c0 > 0)) { /* neither case: still water */
    p->c0 = wl_sph_sound_speed(coefsound, p->g, p->h, 0.0);
    p->dt = cfl * p->h_sml / p->c0;
  }
  long n_max = 0;
  /* the still-water reference runs (plan.h): a case's cost once more */
  const enum wl_still_reference_choice still = s->run.still_reference.choice;
  p->solitary.still_reference = p->solitary.present && still == WL_STILL_REF_ON;
  p->explosion.still_reference = p->explosion.present && still != WL_STILL_REF_OFF;
  if (p->solitary.present) {
    struct wl_plan_solitary *ps = &p->solitary;
    if (!s->run.end_time.is_auto) ps->end_time = s->run.end_time.q.si;
    case_cost(s, p, ps->refine, ps->x_left, ps->end_time, ps->wave.H, ps->dt, &ps->n_fluid, &ps->n_boundary,
              &ps->particle_steps);
    p->particle_steps += ps->particle_steps * (1 + ps->still_reference);
    if (ps->n_fluid + ps->n_boundary > n_max) n_max = ps->n_fluid + ps->n_boundary;
    p->n_fluid = ps->n_fluid, p->n_boundary = ps->n_boundary;
  }
  if (p->explosion.present) {
    struct wl_plan_explosion *px = &p->explosion;
    if (!s->run.end_time.is_auto) px->end_time = s->run.end_time.q.si;
    case_cost(s, p, px->refine, px->x_left, px->end_time, 2.0 * px->eta0, px->dt, &px->n_fluid,
              &px->n_boundary, &px->particle_steps);
    p->particle_steps += px->particle_steps * (1 + px->still_reference);
    if (px->n_fluid + px->n_boundary > n_max)
      n_max = px->n_fluid + px->n_boundary, p->n_fluid = px->n_fluid, p->n_boundary = px->n_boundary;
  }
  p->memory_bytes = HOST_BYTES_FIXED + (double)n_max * (p->dims == 3 ? HOST_BYTES_PER_PARTICLE_3D
                                                                      : HOST_BYTES_PER_PARTICLE_2D);
  p->gpu_memory_bytes = GPU_BYTES_FIXED + (double)n_max * (p->dims == 3 ? GPU_BYTES_PER_PARTICLE_3D
                                                                        : GPU_BYTES_PER_PARTICLE_2D);
  {
    /* each output samples gauges, probes and the wall force and may write
     * a snapshot: a million of them is a run that never ends, whatever
     * its particles */
    const double t_last = fmax(p->solitary.present ? p->solitary.end_time : 0.0,
                               p->explosion.present ? p->explosion.end_time : 0.0);
    const double outputs = t_last / s->run.output_interval.q.si;
    if (outputs > WL_PLAN_OUTPUTS_MAX) {
      char obuf[32];
      return wl_error_set(err, WL_EINPUT,
                          "%s%s: run.output_interval: %g s over %g s of simulated time is %.3g "
                          "outputs, more than %.0f; expected an interval of at least %.3g s",
                          s->path, where(&s->run.output_interval, obuf),
                          s->run.output_interval.q.si, t_last, outputs, WL_PLAN_OUTPUTS_MAX,
                          t_last / WL_PLAN_OUTPUTS_MAX);
    }
  }
  if (n_max > WL_PLAN_PARTICLES_MAX) {
    const struct wl_scenario_value *r =
        s->resolution.dp.is_auto ? &s->resolution.particles_per_height : &s->resolution.dp;
    char rbuf[32];
    return wl_error_set(err, WL_EINPUT,
                        "%s%s: resolution.%s: dp = %g m needs about %.3g particles (%.3g GiB), "
                        "more than the %.3g a run can hold; expected a larger dp or fewer "
                        "particles per wave height",
                        s->path, where(r, rbuf), s->resolution.dp.is_auto ? "particles_per_height" : "dp",
                        p->dp, (double)n_max, p->memory_bytes / 1073741824.0,
                        (double)WL_PLAN_PARTICLES_MAX);
  }
  if (p->refine) { /* the same cases at dp everywhere, for the saving `check` prints */
    long nf, nb;
    double ps;
    p->uniform_particle_steps = 0;
    if (p->solitary.present) {
      case_cost(s, p, 0, p->solitary.x_left, p->solitary.end_time, p->solitary.wave.H,
                p->solitary.dt, &nf, &nb, &ps);
      p->uniform_particle_steps += ps;
    }
    if (p->explosion.present) {
      case_cost(s, p, 0, p->explosion.x_left, p->explosion.end_time, 2.0 * p->explosion.eta0,
                p->explosion.dt, &nf, &nb, &ps);
      p->uniform_particle_steps += ps;
    }
  }
  p->cpu_seconds = p->particle_steps * p->evals_per_step /
                   (p->dims == 3 ? WL_PLAN_CPU_RATE_3D : WL_PLAN_CPU_RATE);
  const double gpu_rate = p->dims == 3 ? WL_PLAN_GPU_RATE_3D : WL_PLAN_GPU_RATE;
  const double gpu_step = gpu_step_seconds(p);
  /* each case alone, then side by side as assess runs them on a GPU */
  struct wl_plan_cost cases[2];
  p->n_cases = 0;
  p->gpu_work_seconds = 0;
  if (p->solitary.present) {
    const double work = p->solitary.particle_steps * p->evals_per_step / gpu_rate;
    p->gpu_case_still[p->n_cases] = p->solitary.still_reference;
    cases[p->n_cases++] = (struct wl_plan_cost){
        .gpu_seconds = fmax(p->solitary.end_time / p->solitary.dt * gpu_step, work),
        .gpu_work_seconds = work};
  }
  if (p->explosion.present) {
    const double work = p->explosion.particle_steps * p->evals_per_step / gpu_rate;
    p->gpu_case_still[p->n_cases] = p->explosion.still_reference;
    cases[p->n_cases++] = (struct wl_plan_cost){
        .gpu_seconds = fmax(p->explosion.end_time / p->explosion.dt * gpu_step, work),
        .gpu_work_seconds = work};
  }
  /* a case's still-water reference runs beside it on a GPU: one run more */
  struct wl_plan_cost runs[4];
  int n_runs = 0;
  for (int i = 0; i < p->n_cases; i++) {
    p->gpu_case_seconds[i] = cases[i].gpu_seconds;
    p->gpu_case_work_seconds[i] = cases[i].gpu_work_seconds;
    for (int r = 0; r <= p->gpu_case_still[i]; r++) {
      runs[n_runs++] = cases[i];
      p->gpu_work_seconds += cases[i].gpu_work_seconds;
    }
  }
  p->gpu_seconds = wl_plan_gpu_side_by_side(runs, n_runs, n_runs);
  return WL_OK;
}

struct wl_plan_cost wl_plan_cost_of(const struct wl_plan *p) {
  struct wl_plan_cost c = {p->dims, p->memory_bytes, p->gpu_memory_bytes, p->cpu_seconds,
                           p->gpu_seconds, p->gpu_work_seconds};
  return c;
}

/* plan.h */
enum wl_status wl_plan_ladder_cost(const struct wl_scenario *s, const struct wl_plan *plan,
                                   int brief, FILE *out, struct wl_plan_cost *cost,
                                   struct wl_error *err) {
  *cost = wl_plan_cost_of(plan);
  int n = s->resolution.n_levels;
  if (n == 0) return WL_OK;
  struct wl_scenario *sl = malloc(sizeof *sl);
  struct wl_plan *pl = malloc(sizeof *pl);
  struct wl_plan_cost sum = {plan->dims, 0, 0, 0, 0, 0},
                     run[(3 + WL_SCENARIO_MAX_REALISATIONS) * WL_SCENARIO_MAX_LEVELS];
  int n_runs = 0;
  double steps = 0.0, device_total = 0.0;
  enum wl_status st = sl && pl ? WL_OK : wl_error_set(err, WL_ENOMEM, "no memory to plan the ladder");
  int ok = st == WL_OK;
  if (!brief && out) fprintf(out, "\nConvergence ladder (resolution.convergence), coarse to fine\n");
  for (int k = 0; ok && k < n; k++) {
    *sl = *s; /* shallow copy: only read by the plan */
    sl->resolution.dp.is_auto = 0;
    sl->resolution.dp.given = 1;
    sl->resolution.dp.q.si = wl_plan_level_dp(s, plan, s->resolution.levels[k].q.si);
    if ((st = wl_plan_make(sl, pl, err)) != WL_OK) {
      if (!brief && out) fprintf(out, "  level %d: cannot be planned: %s\n", k + 1, err->msg);
      ok = 0;
      break;
    }
    /* a level's cases, each a run; the explosion (the last case) once per
     * realisation, its still-water reference with the first */
    const int n_real = pl->explosion.present ? pl->realisations : 1;
    for (int c = 0; c < pl->n_cases; c++)
      for (int r = 0; r < (c == pl->n_cases - 1 ? n_real : 1) + pl->gpu_case_still[c]; r++)
        run[n_runs++] = (struct wl_plan_cost){.gpu_seconds = pl->gpu_case_seconds[c],
                                              .gpu_work_seconds = pl->gpu_case_work_seconds[c]};
    const double extra = pl->particle_steps > 0 && n_real > 1
                             ? (n_real - 1) * pl->explosion.particle_steps / pl->particle_steps
                             : 0.0; /* the further realisations' share of the level's work */
    device_total += pl->gpu_memory_bytes * (1.0 + extra);
    sum.cpu_seconds += pl->cpu_seconds * (1.0 + extra);
    sum.gpu_work_seconds += pl->gpu_work_seconds * (1.0 + extra);
    sum.host_bytes = fmax(sum.host_bytes, pl->memory_bytes);
    sum.device_bytes = fmax(sum.device_bytes, pl->gpu_memory_bytes);
    steps += pl->particle_steps * (1.0 + extra);
    if (!brief && out) {
      char dps[32];
      snprintf(dps, sizeof dps, "%.4g m", pl->dp);
      fprintf(out, "  level %d  x %-5s dp = %-10s %8ld particles  %10.3e particle-steps  %6.0f s\n",
              k + 1, s->resolution.levels[k].text, dps, pl->n_fluid + pl->n_boundary,
              pl->particle_steps * (1.0 + extra), pl->cpu_seconds * (1.0 + extra));
    }
  }
  free(sl);
  free(pl);
  if (!ok) return st;
  const int side_by_side = !s->resolution.target_error.given &&
                           device_total <= WL_PLAN_GPU_SIDE_BY_SIDE_MEMORY * WL_PLAN_GPU_BYTES;
  /* side by side: every level of every case at once; else the levels one
   * after the other, each level's cases side by side */
  if (side_by_side) {
    sum.gpu_seconds = wl_plan_gpu_side_by_side(run, n_runs, n_runs);
  } else {
    const int per_level = n_runs / n;
    sum.gpu_seconds = 0.0;
    for (int k = 0; k < n; k++)
      sum.gpu_seconds += wl_plan_gpu_side_by_side(run + k * per_level, per_level, per_level);
  }
  if (!brief && out && plan->realisations > 1)
    fprintf(out,
            "  the explosion %d times a level (resolution.realisations), its crater moved by "
            "dp / %d each time; the steps and times above count them all\n",
            plan->realisations, plan->realisations);
  if (!brief && out)
    fprintf(out,
            "  all levels: %.3e particle-steps, about %.0f s on the CPU%s; %.0f s on an H100 "
            "(%s)\n",
            steps, sum.cpu_seconds,
            s->resolution.target_error.given ? " (less when target_error stops the ladder early)"
                                             : "",
            sum.gpu_seconds, side_by_side ? "every level of every case side by side" : "the levels one after the other");
  *cost = sum;
  return WL_OK;
}

double wl_plan_gpu_shared_efficiency(int width) {
  const double k = width < 1 ? 1.0 : (double)width;
  return WL_PLAN_GPU_SHARED_RATE * k / (k + WL_PLAN_GPU_SHARED_HALF);
}

double wl_plan_gpu_side_by_side(const struct wl_plan_cost *runs, int n, int width) {
  /* the throughput bound: runs whose step is latency-bound alone reach
   * together only a share of the force loop's rate, the larger the more of
   * them run (plan.h); a large run, at that rate alone, keeps it */
  if (width > n) width = n;
  const double shared = wl_plan_gpu_shared_efficiency(width);
  double sum = 0.0, work = 0.0;
  for (int i = 0; i < n; i++) {
    sum += runs[i].gpu_seconds;
    work += runs[i].gpu_work_seconds /
            (runs[i].gpu_seconds > runs[i].gpu_work_seconds ? shared : WL_PLAN_GPU_SHARED_RATE);
  }
  double *left = width > 1 ? malloc((size_t)width * sizeof *left) : NULL;
  if (!left) return sum; /* one at a time (or no memory: the dearer answer) */
  /* processor sharing: the k runs on the GPU each advance by 1 / (1 + cost
   * (k - 1)) of a second alone per second, until the first of them ends;
   * the next run in order takes its place */
  double t = 0.0;
  int k = 0, next = 0;
  while (next < n && k < width) left[k++] = runs[next++].gpu_seconds;
  while (k > 0) {
    double m = left[0];
    for (int i = 1; i < k; i++) m = fmin(m, left[i]);
    t += m * (1.0 + WL_PLAN_GPU_SHARE_COST * (k - 1));
    int still = 0;
    for (int i = 0; i < k; i++)
      if (left[i] - m > 0.0) left[still++] = left[i] - m;
    k = still;
    while (next < n && k < width) left[k++] = runs[next++].gpu_seconds;
  }
  free(left);
  return fmax(t, work);
}

int wl_plan_gpu_side_by_side_width(double device_bytes, double gpu_bytes, int max_width) {
  if (!(device_bytes > 0)) return max_width;
  const double fit = floor(WL_PLAN_GPU_SIDE_BY_SIDE_MEMORY * gpu_bytes / device_bytes);
  return fit < 1 ? 1 : fit > max_width ? max_width : (int)fit;
}

enum wl_status wl_plan_make(const struct wl_scenario *s, struct wl_plan *p,
                            struct wl_error *err) {
  memset(p, 0, sizeof *p);
  p->h = s->water.depth.q.si;
  p->rho = s->water.density.q.si;
  p->g = s->water.gravity.q.si;
  enum wl_status st;
  if ((st = plan_dims(s, p, err))) {
    wl_error_prefix(err, "%s: domain.dimensions: ", s->path);
    return st;
  }
  if (s->solitary.present && (st = plan_solitary(s, p, err))) {
    wl_error_prefix(err, "%s: loads.solitary: ", s->path);
    return st;
  }
  if (s->explosion.present && (st = plan_explosion(s, p, err))) return st;
  /* Gauges stay in the water of every case. */
  for (int i = 0; i < s->n_gauges; i++) {
    double xg = s->gauges[i].x.q.si - GAUGE_CLEARANCE;
    if (p->solitary.present && xg < p->solitary.x_left) p->solitary.x_left = fmax(0.0, xg);
    /* the explosion's gauges also stay out of its absorbing zone */
    struct wl_plan_explosion *px = &p->explosion;
    if (px->present && xg < px->x_left + px->absorber) {
      px->x_left = xg - px->absorber;
      if (px->x_left < 0.0) px->absorber = fmax(0.0, xg), px->x_left = 0.0;
    }
  }
  return plan_resolution(s, p, err);
}

void wl_plan_write(const struct wl_plan *p, FILE *out) {
  fprintf(out, "\nDerived initial conditions\n");
  if (p->solitary.present) {
    const struct wl_plan_solitary *ps = &p->solitary;
    const struct wl_wave_integrals *wi = &ps->integrated, *fo = &ps->first_order;
    fprintf(out, "  solitary wave (%s: %s)\n", wl_waves_solitary_theory_text(ps->wave.theory, 0),
            wl_waves_solitary_theory_text(ps->wave.theory, 1));
    fprintf(out, "    %-34s %12.5g m      (H/h = %.4g)\n", "height H", ps->wave.H,
            ps->wave.H / p->h);
    fprintf(out, "    %-34s %12.5g m/s    (sqrt(g h) = %.4g m/s)\n", "celerity c",
            wl_waves_solitary_celerity(&ps->wave), sqrt(p->g * p->h));
    fprintf(out, "    %-34s %12.5g kg/m   (first order %.5g)\n", "mass (integrated)", wi->mass,
            fo->mass);
    fprintf(out, "    %-34s %12.5g kg/s   (first order %.5g)\n", "momentum (integrated)",
            wi->momentum, fo->momentum);
    fprintf(out, "    %-34s %12.5g J/m    (first order %.5g)\n", "kinetic energy", wi->kinetic,
            fo->kinetic);
    fprintf(out, "    %-34s %12.5g J/m    (first order %.5g)\n", "potential energy",
            wi->potential, fo->potential);
    fprintf(out, "    %-34s %12.5g J/m    (first order %.5g)\n", "energy (integrated)",
            wi->energy, fo->energy);
    fprintf(out, "    %-34s %12.5g J/m    (highest wave on h; seed 001 eq 22)\n",
            "energy 0.958 rho g h^3", ps->energy_seed001);
    if (ps->paddle)
      fprintf(out, "    %-34s %12.5g m      (Goring 1978; moves for %.3g s)\n", "paddle stroke",
              ps->goring.stroke, ps->goring.duration);
    else
      fprintf(out, "    %-34s %12.5g m\n", "initial crest position", ps->crest_x0);
    fprintf(out, "    %-34s %12.5g s\n", "arrival at the wall", ps->arrival_time);
    fprintf(out, "    %-34s %12.5g s\n", "wall's force at rest read until", ps->quiet_until);
    fprintf(out, "    %-34s %12.5g m/s    (time step at rest %.4g s)\n", "speed of sound c0", ps->c0,
            ps->dt);
    fprintf(out, "    %-34s %12.5g s\n", "end time", ps->end_time);
    fprintf(out, "    %-34s %12.5g m      (%ld fluid + %ld boundary particles, %.3g particle-steps)\n",
            "flume modelled from x", ps->x_left, ps->n_fluid, ps->n_boundary, ps->particle_steps);
    if (ps->still_reference)
      fprintf(out, "    %-34s %s\n", "still-water reference run",
              "yes: the flume again without the wave, to take its wall force's drift out of "
              "the impulses (run.still_reference)");
  }
  if (p->explosion.present) {
    const struct wl_plan_explosion *px = &p->explosion;
    const struct wl_explosion_chain *ch = &px->chain;
    static const char *const src[] = {"charge weight", "crater energy", "energy of the solitary wave",
                                      "crater size"};
    fprintf(out, "  explosion (from the %s", src[px->source]);
    if (px->source == WL_SOURCE_SOLITARY)
      fprintf(out, ", %s basis: %.5g %s", px->basis == WL_BASIS_SEED001 ? "seed-001" : "per-width",
              px->matched_energy,
              px->basis == WL_BASIS_PER_WIDTH && p->dims == 2 ? "J/m" : "J");
    fprintf(out, ")\n");
    fprintf(out, "    %-34s %12.5g kg     (%.5g lb TNT)\n", "charge W", ch->charge_kg,
            ch->charge_kg / WL_LB_KG);
    fprintf(out, "    %-34s %12.5g m      (%.5g ft; Van Dorn R0 = 9.6 W^0.3)\n", "crater radius R0",
            ch->r0, ch->r0 / WL_FT_M);
    fprintf(out, "    %-34s %12.5g m^2    (Whalin/Le Mehaute C = %g)\n", "Hmax r", ch->hr,
            ch->whalin_coef);
    fprintf(out, "    %-34s %12.5g m      (eta0 R0 = 0.81 Hmax r)\n", "crater depth eta0", ch->eta0);
    fprintf(out, "    %-34s %12.5g J      (pi rho g eta0^2 R0^2/6, seed 001 eq 3)\n",
            "crater energy, 3D", ch->crater_energy);
    fprintf(out, "    %-34s %12.5g J      (4.184 MJ/kg TNT)\n", "chemical energy",
            ch->chemical_energy);
    fprintf(out, "    %-34s %12.3g %%      (ceiling %.0f %%: %.4g J, seed 000 eq 9)\n",
            "crater / chemical energy", 100 * ch->wave_fraction, 100 * px->wave_fraction,
            px->fraction_energy);
    fprintf(out, "    %-34s %12.5g m      (seed 000 eq 8 with the %.0f %% share)\n",
            "cavity radius", ch->cavity_radius, 100 * px->wave_fraction);
    fprintf(out, "    simulated: %s, eta0 = %.5g m, R0 = %.5g m, centre %.5g m, extent %.4g m\n",
            wl_explosion_shape_name(px->shape), px->eta0, px->r0, px->x_center, px->extent);
    fprintf(out, "    %-34s %12.5g %s (quadrature of seed 000 eq 4: %.8g)\n",
            "crater energy as simulated", px->energy, p->dims == 2 ? "J/m " : "J   ",
            px->energy_quad);
    fprintf(out, "    %-34s %12s        (net %+.4g %s)\n", "conserves mass",
            px->conserves_mass ? "yes" : "NO", px->net_volume, p->dims == 2 ? "m^2/m" : "m^3");
    if (px->model_thrown)
      fprintf(out, "    model: thrown mass in %d parts (seed 000)\n", px->thrown_parts);
    fprintf(out, "    %-34s %12.5g s\n", "leading wave at the wall", px->arrival_time);
    fprintf(out, "    %-34s %12.5g s\n", "wall's force at rest read until", px->quiet_until);
    fprintf(out, "    %-34s %12.5g m/s    (time step at rest %.4g s)\n", "speed of sound c0", px->c0,
            px->dt);
    if (px->expected_speed > 0 && px->c0 <= WL_SPH_MACH_FACTOR * px->expected_speed * (1 + 1e-12))
      fprintf(out, "    %-34s %12.5g m/s    (c0 is %g times it: the cavity collapses on its "
                   "axis)\n",
              "crater's collapse speed", px->collapse_speed, WL_SPH_MACH_FACTOR);
    if (px->absorber > 0)
      fprintf(out, "    %-34s %12.5g m      (x = %.4g to %.4g m: the seaward end absorbs)\n",
              "absorbing zone", px->absorber, px->x_left, px->x_left + px->absorber);
    fprintf(out, "    %-34s %12.5g s\n", "end time", px->end_time);
    fprintf(out, "    %-34s %12.5g m      (%ld fluid + %ld boundary particles, %.3g particle-steps)\n",
            "flume modelled from x", px->x_left, px->n_fluid, px->n_boundary, px->particle_steps);
    if (px->still_reference)
      fprintf(out, "    %-34s %s\n", "still-water reference run",
              "yes: the flume again without the wave, to take its wall force's drift out of "
              "the impulses (run.still_reference)");
  }
  fprintf(out, "\nResolution and cost\n");
  fprintf(out, "  %-36s %dD          (%s)\n", "dimension", p->dims, p->dims_reason);
  if (p->dims == 3)
    fprintf(out, "  %-36s %s\n", "symmetry plane",
            p->symmetry ? "centreline (half the width modelled)" : "none (the whole width)");
  if (p->dims == 3)
    fprintf(out, "  %-36s %s\n", "side walls",
            p->slip_walls ? "free-slip (mirror planes)" : "dynamic boundary particles");
  if (p->dp != p->dp_target) /* dp auto moved it (a given dp stays) */
    fprintf(out, "  %-36s %12.5g m      (asked for %.4g m: whole rows of still water)\n",
            "particle spacing dp", p->dp, p->dp_target);
  else
    fprintf(out, "  %-36s %12.5g m\n", "particle spacing dp", p->dp);
  fprintf(out, "  %-36s %12.5g m      (%.4g rows; %.4g m at the wall, %.4g rows)\n",
          "still water modelled", p->depth_model, p->depth_model / p->dp, p->depth_wall_model,
          p->depth_wall_model / p->dp);
  fprintf(out, "  %-36s %12.5g m      (h/dp = %.3g)\n", "smoothing length h", p->h_sml,
          p->h_sml / p->dp);
  fprintf(out, "  %-36s %12.5g m/s    (the largest case's; each case's above)\n",
          "speed of sound c0", p->c0);
  fprintf(out, "  %-36s %12.5g s      (the smallest case's)\n", "time step (CFL, at rest)", p->dt);
  fprintf(out, "  %-36s %12ld        (+ %ld boundary; the largest case)\n", "fluid particles",
          p->n_fluid, p->n_boundary);
  fprintf(out, "  %-36s %12.4g MiB    (%.4g MiB on a GPU)\n", "memory (estimate)",
          p->memory_bytes / 1048576.0, p->gpu_memory_bytes / 1048576.0);
  fprintf(out, "  %-36s %12.4g\n", "particle-steps, all cases", p->particle_steps);
  if (p->refine) {
    fprintf(out, "  %-36s %12.5g m      (seaward of x = %.4g m%s; dp from there to the wall%s)\n",
            "coarse level's spacing", p->dp_coarse, p->refine_from,
            p->refine_auto ? ", placed by the plan" : "",
            p->explosion.present && !p->explosion.refine ? "; the solitary case only" : "");
    fprintf(out, "  %-36s %12.4g m      (either side of the interface; bands %.3g m coarse, "
                 "%.3g m fine)\n",
            "levels' overlap", p->refine_overlap, p->refine_band[0], p->refine_band[1]);
    fprintf(out, "  %-36s %12.4g        (%.2f times fewer particle-steps than dp everywhere, "
                 "%.4g)\n",
            "two levels' particle-steps", p->particle_steps,
            p->particle_steps > 0 ? p->uniform_particle_steps / p->particle_steps : 0.0,
            p->uniform_particle_steps);
  }
  fprintf(out, "  %-36s %12.4g s      (at %.2g force evaluations/s, %d a step: %s)\n",
          "CPU runtime (estimate)", p->cpu_seconds,
          p->dims == 3 ? WL_PLAN_CPU_RATE_3D : WL_PLAN_CPU_RATE, p->evals_per_step,
          p->evals_per_step == 1 ? "Verlet" : "symplectic");
  fprintf(out, "  %-36s %12.4g s      (CUDA backend on an H100: %.2g s a step or %.2g "
               "force evaluations/s, the slower)\n",
          "GPU runtime (estimate)", p->gpu_seconds, gpu_step_seconds(p),
          p->dims == 3 ? WL_PLAN_GPU_RATE_3D : WL_PLAN_GPU_RATE);
  if (p->n_notes) fprintf(out, "\nNotes\n");
  for (int i = 0; i < p->n_notes; i++) fprintf(out, "  - %s\n", p->notes[i]);
}

enum wl_status wl_plan_solitary_runnable(const struct wl_scenario *s, const struct wl_plan *p,
                                         struct wl_error *err) {
  const struct wl_plan_solitary *ps = &p->solitary;
  if (ps->paddle || ps->fits) return WL_OK;
  return wl_error_set(err, WL_EINPUT,
                      "%s: loads.solitary: the wave does not fit seaward of the wall at x = %g m "
                      "(initial crest at %.3g m); expected a longer flume (wall.x, "
                      "domain.length) or a smaller wave",
                      s->path, s->wall.x.q.si, ps->crest_x0);
}

static void fmt_duration(double s, char *buf, size_t size) {
  if (s < 120)
    snprintf(buf, size, "%.0f s", s);
  else if (s < 7200)
    snprintf(buf, size, "%.0f min", s / 60);
  else if (s < 3 * 86400)
    snprintf(buf, size, "%.1f h", s / 3600);
  else
    snprintf(buf, size, "%.0f days", s / 86400);
}

double wl_plan_machine_seconds(const struct wl_plan_cost *cost, const struct wl_plan_machine *m) {
  return m->device_bytes > 0
             ? cost->gpu_seconds
             : cost->cpu_seconds * WL_PLAN_CPU_THREADS / (m->threads > 0 ? m->threads : 1);
}

double wl_plan_realisation_x(double x_center, double dp, int r, int n) {
  return n > 1 ? x_center + dp * (double)r / (double)n : x_center;
}

const double wl_plan_auto_pph[WL_PLAN_AUTO_PPH_N] = {2.0, 2.83, 4.0, 5.66};

/* Whether `cost` fits machine m's memory (as wl_plan_fits judges it). */
static int fits_memory(const struct wl_plan_cost *cost, const struct wl_plan_machine *m) {
  if (m->host_bytes > 0 && cost->host_bytes > WL_PLAN_MEMORY_FRACTION * m->host_bytes) return 0;
  return !(m->device_bytes > 0 && cost->device_bytes > m->device_bytes);
}

void wl_plan_refine_machine(struct wl_scenario *s, const struct wl_plan_machine *m) {
  const int on_gpu = s->resolution.refine.present && m->device_bytes > 0;
  s->resolution.refine.gpu = on_gpu && s->resolution.refine.from.is_auto;
  s->resolution.refine.gpu_given = on_gpu && !s->resolution.refine.from.is_auto;
}

enum wl_status wl_plan_choose(struct wl_scenario *s, const struct wl_plan_machine *m,
                              struct wl_plan_choice *c, struct wl_error *err) {
  memset(c, 0, sizeof *c);
  c->machine = *m;
  wl_plan_refine_machine(s, m);
  {
    struct wl_scenario_value *rv = &s->resolution.realisations;
    if (rv->is_auto)
      rv->q.si = m->device_bytes > 0 && s->resolution.n_levels > 0 ? WL_PLAN_AUTO_REALISATIONS : 1;
  }
  struct wl_scenario_value *v = &s->resolution.particles_per_height;
  if (!v->is_auto || !s->resolution.dp.is_auto) return WL_OK;
  c->is_auto = 1;
  c->limit = m->budget_seconds > 0 ? fmin(WL_PLAN_AUTO_SECONDS, m->budget_seconds)
                                   : WL_PLAN_AUTO_SECONDS;
  struct wl_plan *p = malloc(sizeof *p);
  if (!p) return wl_error_set(err, WL_ENOMEM, "planning particles_per_height: auto: out of memory");
  enum wl_status st = WL_OK;
  int chosen = 0;
  for (int k = 0; k < WL_PLAN_AUTO_PPH_N; k++) {
    v->q.si = wl_plan_auto_pph[k];
    struct wl_plan_cost cost;
    struct wl_error e;
    wl_error_clear(&e);
    /* the coarsest must plan (its error is the scenario's); a finer one
     * that cannot (a limit on particles) ends the search */
    if (wl_plan_make(s, p, k == 0 ? err : &e) != WL_OK) {
      if (k == 0) st = err->status;
      break;
    }
    if (wl_plan_ladder_cost(s, p, 1, NULL, &cost, &e) != WL_OK) break; /* a level unplannable */
    const double secs = wl_plan_machine_seconds(&cost, m);
    if (k == 0) c->seconds = secs;
    if (k > 0 && (secs > c->limit || !fits_memory(&cost, m))) {
      c->next_seconds = secs;
      c->next_too_large = !fits_memory(&cost, m);
      break;
    }
    chosen = k;
    c->seconds = secs;
  }
  free(p);
  v->q.si = c->ppH = wl_plan_auto_pph[chosen];
  return st;
}

void wl_plan_machine_name(const struct wl_plan_machine *m, char *buf, size_t size) {
  if (m->device_bytes > 0)
    snprintf(buf, size, "%s", m->device_name);
  else
    snprintf(buf, size, "%d CPU thread%s", m->threads > 0 ? m->threads : 1,
             m->threads > 1 ? "s" : "");
}

void wl_plan_choice_describe(const struct wl_plan_choice *c, char *buf, size_t size) {
  if (!c->is_auto) {
    if (size) buf[0] = '\0';
    return;
  }
  char where_run[160], took[32], next[32], budget[32];
  wl_plan_machine_name(&c->machine, where_run, sizeof where_run);
  fmt_duration(c->seconds, took, sizeof took);
  fmt_duration(c->limit, budget, sizeof budget);
  if (c->next_too_large) {
    snprintf(buf, size,
             "particles_per_height auto: %.3g on %s (est. %s; the next finer, x 1.41, would not "
             "fit its memory)",
             c->ppH, where_run, took);
  } else if (c->next_seconds > 0) {
    fmt_duration(c->next_seconds, next, sizeof next);
    snprintf(buf, size,
             "particles_per_height auto: %.3g on %s (est. %s; the next finer, x 1.41, would take "
             "%s, beyond auto's %s)",
             c->ppH, where_run, took, next, budget);
  } else {
    snprintf(buf, size,
             "particles_per_height auto: %.3g on %s (est. %s; the finest auto plans: the main "
             "job's ladder converged there)",
             c->ppH, where_run, took);
  }
}

enum wl_status wl_plan_fits(const struct wl_scenario *s, const struct wl_plan_cost *cost,
                            const struct wl_plan_machine *m, struct wl_error *err) {
  const int gpu = m->device_bytes > 0;
  const struct wl_scenario_value *r =
      s->resolution.dp.is_auto ? &s->resolution.particles_per_height : &s->resolution.dp;
  char where_buf[32];
  const char *key = s->resolution.dp.is_auto ? "particles_per_height" : "dp";
  const char *at = where(r, where_buf);
  if (m->host_bytes > 0 && cost->host_bytes > WL_PLAN_MEMORY_FRACTION * m->host_bytes)
    return wl_error_set(err, WL_EINPUT,
                        "%s%s: resolution.%s: the run needs about %.3g GiB of memory, more than "
                        "%.0f %% of this machine's %.3g GiB; expected a larger dp (memory grows "
                        "with 1/dp^%d), fewer particles per wave height, or a shorter flume",
                        s->path, at, key, cost->host_bytes / 1073741824.0,
                        100 * WL_PLAN_MEMORY_FRACTION, m->host_bytes / 1073741824.0,
                        cost->dims);
  if (gpu && cost->device_bytes > m->device_bytes)
    return wl_error_set(err, WL_EINPUT,
                        "%s%s: resolution.%s: the run needs about %.3g GiB of GPU memory, more "
                        "than the %.3g GiB of %s; expected a larger dp, or the CPU backend "
                        "(--backend cpu, %.3g GiB of host memory)",
                        s->path, at, key, cost->device_bytes / 1073741824.0,
                        m->device_bytes / 1073741824.0, m->device_name, cost->host_bytes / 1073741824.0);
  const double seconds = wl_plan_machine_seconds(cost, m);
  if (m->budget_seconds > 0 && seconds > m->budget_seconds && !m->force_large) {
    char need[32], budget[32], where_run[160];
    wl_plan_machine_name(m, where_run, sizeof where_run);
    fmt_duration(seconds, need, sizeof need);
    fmt_duration(m->budget_seconds, budget, sizeof budget);
    return wl_error_set(err, WL_EINPUT,
                        "%s%s: resolution.%s: the run would take about %s on %s, beyond the "
                        "budget of %s; expected a larger dp, a shorter run.end_time%s, or "
                        "--budget HOURS / --force-large to run it anyway",
                        s->path, at, key, need, where_run, budget,
                        gpu ? "" : ", a GPU (--backend cuda)");
  }
  return WL_OK;
}
