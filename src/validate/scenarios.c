/* scenarios.c: the reference cases that are scenario files (reference/<case>/
 * *.yaml), run as a load case of the production pipeline (wl_assess_case:
 * flume, solver, gauges, wall probes, loads) with dp set per ladder level.
 *
 *  solitary-h*-e*  the exact solitary wave over a flat bed (a steady wave
 *                  of the Euler equations, waves.h): celerity (the exact
 *                  F sqrt(g h), REFERENCES 3.4) from crest arrivals at
 *                  gauges every 2h, amplitude after 20h against seed 003's
 *                  ISPH loss (10 % in 5 s, scaled to the travel time). A
 *                  Grimshaw wave (seed 003 eqs 21-24) is not steady in an
 *                  Euler solver: at H/h 0.6 it sheds a tail and settles
 *                  lower, which the old cases counted as the solver's loss
 *  solitary_wall   reflection at a vertical wall: maximum run-up (Su &
 *                  Mirie 1980, REFERENCES 4.1) and impulse 2I (REFERENCES
 *                  4.2 with I from the exact-wave table of 3.4)
 *  charlesworth    seed 001's crater from 32 lb at 8 ft (eta0 = 2.07 m,
 *                  R0 = 8.28 m), the wave at 17.22 m against a two-phase
 *                  Navier-Stokes (VOF) solution of the same initial value
 *                  problem (reference/charlesworth/vof_gauge.csv, made by
 *                  reference/charlesworth/vof/), RMSE and correlation
 *                  judged by seed 001's own figures (RMSE <= 11.4 %, r >=
 *                  0.93); the linear Cauchy-Poisson solution of the same
 *                  surface (REFERENCES 5.1, plane form, the wall as an
 *                  image) reported beside it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "wallload/assess.h"

#define G 9.81
#define VAL_PI 3.14159265358979323846

static enum wl_status load_scenario(const char *path, double dp, const struct wl_val_ctx *ctx,
                                    struct wl_scenario *s, struct wl_plan *plan,
                                    struct wl_validate_level *lv, struct wl_error *err) {
  wl_scenario_init(s);
  enum wl_status st = wl_scenario_load(path, s, err);
  if (st) {
    if (st == WL_EIO) st = WL_EINPUT; /* a missing reference file is bad input */
    wl_error_prefix(err, "validate: reference scenario: ");
    err->status = st;
    return st;
  }
  /* the ladder sets the spacing, moved as assess moves dp: auto to the
   * nearest that models the still water in whole particle rows (plan.h);
   * the level reports the spacing run */
  s->resolution.dp.is_auto = 0;
  s->resolution.dp.given = 1;
  s->resolution.dp.q.si = lv->dp = wl_plan_whole_rows_dp(s, dp, NULL);
  if (ctx->residual > 0) { /* validate --residual-viscosity */
    s->numerics.residual_viscosity.q.si = ctx->residual;
    s->numerics.residual_viscosity.given = 1;
  }
  if (ctx->smagorinsky > 0) { /* validate --smagorinsky */
    s->numerics.smagorinsky.q.si = ctx->smagorinsky;
    s->numerics.smagorinsky.given = 1;
  }
  if (ctx->verlet) { /* validate --integrator verlet */
    s->numerics.integrator.choice = WL_INTEGRATOR_VERLET;
    s->numerics.integrator.given = 1;
  }
  return wl_plan_make(s, plan, err);
}

static void case_progress(void *user, const char *case_name, const struct wl_sph_progress *pr) {
  (void)case_name;
  const struct wl_val_ctx *ctx = user;
  ctx->progress(ctx->user, ctx->name, ctx->level, pr);
}

static enum wl_status run_case(const struct wl_scenario *s, const struct wl_plan *plan,
                               enum wl_load_case load, const struct wl_val_ctx *ctx, double t_end,
                               struct wl_case_result *c, struct wl_validate_level *lv,
                               struct wl_error *err) {
  struct wl_assess_opts opts = {0};
  opts.threads = ctx->threads;
  opts.backend = ctx->backend; /* validate --backend */
  if (ctx->progress) {
    opts.progress = case_progress;
    opts.user = (void *)ctx;
  }
  opts.end_time = t_end;
  struct wl_error run_err;
  wl_error_clear(&run_err);
  enum wl_status st = wl_assess_case(s, plan, load, &opts, NULL, c, &run_err);
  lv->n_particles = c->n_particles;
  lv->steps = c->steps;
  lv->runtime_s = c->runtime_s;
  lv->t_reached = c->t_reached;
  lv->status = st;
  if (st) snprintf(lv->message, sizeof lv->message, "%s", run_err.msg);
  if (st == WL_OK || st == WL_EUNSTABLE) return WL_OK;
  return wl_error_set(err, st, "%s", run_err.msg);
}

/* Crest time and height of gauge g (parabola through the highest sample
 * and its neighbours). */
static void crest(const struct wl_record *r, int g, double *t_peak, double *a_peak) {
  const size_t ng = (size_t)r->n_gauges;
  size_t best = 0;
  for (size_t k = 0; k < r->n; k++)
    if (r->eta[k * ng + (size_t)g] > r->eta[best * ng + (size_t)g]) best = k;
  double tp = r->n ? r->t[best] : NAN, ap = r->n ? r->eta[best * ng + (size_t)g] : NAN;
  if (best > 0 && best + 1 < r->n) {
    double y0 = r->eta[(best - 1) * ng + (size_t)g], y1 = ap, y2 = r->eta[(best + 1) * ng + (size_t)g];
    double den = y0 - 2 * y1 + y2, dt = r->t[best + 1] - r->t[best];
    if (den < 0) {
      double sh = 0.5 * (y0 - y2) / den;
      tp += sh * dt;
      ap = y1 - 0.25 * (y0 - y2) * sh;
    }
  }
  *t_peak = tp;
  *a_peak = ap;
}

/* ---- solitary propagation ------------------------------------------------------------------ */

/* Half the wave's width at half its height [m]: X > 0 where eta(X) = H / 2,
 * by bisection (eta falls monotonically from the crest at X = 0). */
static double half_width(const struct wl_solitary *sw) {
  double lo = 0, hi = 1.0 / sw->K;
  while (wl_waves_solitary_eta(sw, hi) > 0.5 * sw->H) hi *= 2;
  for (int it = 0; it < 60; it++) {
    const double mid = 0.5 * (lo + hi);
    if (wl_waves_solitary_eta(sw, mid) > 0.5 * sw->H) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

#define SOL_TOL_C 0.02    /* issue 3: celerity within 2 % of seed 003 eq 23 */
#define SOL_ISPH_LOSS 0.10 /* seed 003: ISPH loses 10 % of the height in 5 s */
#define SOL_ISPH_TIME 5.0


enum wl_status wl_val_run_solitary(const struct wl_val_case *c, const struct wl_val_ctx *ctx,
                                   double dp, struct wl_validate_level *lv, struct wl_error *err) {
  const double h = c->p[0], eps = c->p[1], D = c->p[2] * h, H = eps * h;
  char path[1024];
  snprintf(path, sizeof path, "%s/%s/h%.1f-e%.1f.yaml", ctx->ref_dir, c->dir, h, eps);
  struct wl_scenario s;
  struct wl_plan plan;
  enum wl_status st = load_scenario(path, dp, ctx, &s, &plan, lv, err);
  if (st) {
    wl_scenario_clear(&s);
    return st;
  }
  /* the exact wave's celerity (exact.c, checked against REFERENCES 3.4's
   * table in test_waves) */
  const double x0 = plan.solitary.crest_x0, c_ref = wl_waves_solitary_celerity(&plan.solitary.wave);
  /* the crest passes the last gauge (x0 + D) at D / c; then two more
   * depths of travel, or two half-widths at half height if longer (H/h =
   * 0.1: 0.97 m against 2 h = 0.6 m), so that the gauge sees the whole of
   * the crest that the celerity's centroid and the height's fit read */
  const double x_half = half_width(&plan.solitary.wave);
  const double t_end = (D + fmax(2 * h, 2 * x_half)) / c_ref;
  struct wl_case_result cr;
  memset(&cr, 0, sizeof cr);
  st = run_case(&s, &plan, WL_CASE_SOLITARY, ctx, t_end, &cr, lv, err);
  if (!st) {
    /* speed: least squares of the crests' passage times at the scenario's
     * gauges (wl_val_crest_centroid_time) */
    double sx = 0, stt = 0, sxx = 0, sxt = 0, a_last = NAN, a_fit = NAN, x_last = NAN;
    int m = 0;
    for (int g = 0; g < s.n_gauges; g++) {
      const double xg = s.gauges[g].x.q.si;
      double tp, ap;
      crest(&cr.rec, g, &tp, &ap);
      if (!(tp > cr.rec.t[0] + 0.02) || !(tp < cr.rec.t[cr.rec.n - 1] - 0.02)) continue;
      if (fabs(xg - (x0 + D)) < 0.25 * h) {
        a_last = ap, x_last = xg;
        a_fit = wl_val_crest_fit(cr.rec.t, cr.rec.eta + g, (int)cr.rec.n, cr.rec.n_gauges, NULL);
      }
      tp = wl_val_crest_centroid_time(cr.rec.t, cr.rec.eta + g, (int)cr.rec.n, cr.rec.n_gauges);
      if (!isfinite(tp)) continue;
      sx += tp, stt += xg, sxx += tp * tp, sxt += tp * xg;
      m++;
    }
    const double speed = m > 1 ? (m * sxt - sx * stt) / (m * sxx - sx * sx) : NAN;
    /* seed 003's ISPH loss, scaled to this travel time, is the bar */
    const double travel = D / c_ref;
    const double tol_a = SOL_ISPH_LOSS * travel / SOL_ISPH_TIME;
    /* the crest fitted over the top of the record (wl_val_crest_fit), not
     * the highest sample, whose particle-scale noise reads high on waves a
     * few particles tall; the highest sample is reported beside it */
    wl_val_rel(&lv->m[0], "crest height after 20 h", "m", isfinite(x_last) ? a_fit : NAN, H, tol_a);
    wl_val_rel(&lv->m[1], "celerity", "m/s", speed, c_ref, SOL_TOL_C);
    wl_val_rel(&lv->m[2], "highest sample at 20 h", "m", isfinite(x_last) ? a_last : NAN, H, NAN);
    lv->n_metrics = 3;
  }
  wl_assess_case_clear(&cr);
  wl_scenario_clear(&s);
  return st;
}

/* ---- solitary wave on a wall ------------------------------------------------------------------ */

#define WALL_TOL_R 0.05 /* REFERENCES 6: run-up vs Su & Mirie (eps <= 0.3) <= 5 % */
#define WALL_TOL_I 0.05 /* REFERENCES 6: wall impulse vs 2I <= 5 % */

enum wl_status wl_val_run_solitary_wall(const struct wl_val_case *c, const struct wl_val_ctx *ctx,
                                        double dp, struct wl_validate_level *lv,
                                        struct wl_error *err) {
  const double h = c->p[0], eps = c->p[1], I_table = c->p[2], rho = 1000;
  char path[1024];
  snprintf(path, sizeof path, "%s/%s/scenario.yaml", ctx->ref_dir, c->dir);
  struct wl_scenario s;
  struct wl_plan plan;
  enum wl_status st = load_scenario(path, dp, ctx, &s, &plan, lv, err);
  if (st) {
    wl_scenario_clear(&s);
    return st;
  }
  /* until the reflected crest is back where it started: 2 (x_w - x0) / c,
   * plus 0.3 s for the impulse to settle */
  const double x0 = plan.solitary.crest_x0, xw = s.wall.x.q.si;
  const double cg = wl_waves_solitary_celerity(&plan.solitary.wave);
  const double t_end = 2 * (xw - x0) / cg + 0.3;
  struct wl_case_result cr;
  memset(&cr, 0, sizeof cr);
  st = run_case(&s, &plan, WL_CASE_SOLITARY, ctx, t_end, &cr, lv, err);
  if (!st) {
    const double R_ref = h * (2 * eps + eps * eps / 2 + 0.75 * eps * eps * eps);
    const double I2 = 2 * I_table * rho * h * h * sqrt(G * h);
    const size_t n = cr.rec.n;
    wl_val_rel(&lv->m[0], "max run-up (Su & Mirie)", "m", cr.loads.runup, R_ref, WALL_TOL_R);
    /* 2I is the impulse of the reflection: the fluid's momentum has gone
     * from +I to -I when the wall's force in excess of the force at rest
     * first falls back to zero after the peak (on dp = 0.02 m: +86.01 at the
     * start, -86.09 N s/m then). After it the water at the wall sets down
     * behind the departing wave and the wall pulls the fluid back (-1.7 N s/m
     * in the next 0.5 s), which the 2I argument leaves out: the impulse to
     * the record's end depends on where the record stops and is reported,
     * not judged. Both measurements over their own peak's positive phase
     * (loads.h), each less its own force at rest. */
    const struct wl_case_loads *l = &cr.loads;
    double tb0 = NAN, tb1 = NAN;
    const double imp_b = n ? wl_loads_positive_phase_impulse(cr.rec.t, l->force_bound_filtered,
                                                             l->impulse_bound, n, l->rest_force_bound,
                                                             l->force_bound_peak.index, &tb0, &tb1)
                           : NAN;
    wl_val_rel(&lv->m[1], "impulse of the reflection, probes (2I)", "N s/m", l->impulse_peak, I2,
               WALL_TOL_I);
    wl_val_rel(&lv->m[2], "impulse of the reflection, boundary force (2I)", "N s/m", imp_b, I2, NAN);
    wl_val_rel(&lv->m[3], "impulse to the record's end, probes", "N s/m", l->impulse_total, I2, NAN);
    /* A third measurement that reads no wall: the fluid's own momentum
     * change over the probes' positive phase. The end wall behind the
     * wave and the bed also push the fluid, so it is not the wall's load
     * exactly; where the probes and the boundary particles part, it says
     * which one the fluid agrees with (docs/boundary.md, "The toe
     * corner"). */
    double dmom = NAN;
    if (n && isfinite(l->impulse_peak_from) && isfinite(l->impulse_peak_to)) {
      size_t i0 = 0, i1 = 0;
      for (size_t k = 0; k < n; k++) {
        if (fabs(cr.rec.t[k] - l->impulse_peak_from) < fabs(cr.rec.t[i0] - l->impulse_peak_from))
          i0 = k;
        if (fabs(cr.rec.t[k] - l->impulse_peak_to) < fabs(cr.rec.t[i1] - l->impulse_peak_to))
          i1 = k;
      }
      dmom = cr.rec.momentum[i0] - cr.rec.momentum[i1];
    }
    wl_val_rel(&lv->m[4], "fluid momentum change (2I)", "N s/m", dmom, I2, NAN);
    lv->n_metrics = 5;
  }
  wl_assess_case_clear(&cr);
  wl_scenario_clear(&s);
  return st;
}

/* ---- Charlesworth crater (seed 001) --------------------------------------------------------------- */

#define CRATER_TOL_RMSE 0.114 /* seed 001 3.1.1: largest RMSE of its SPH, 11.4 % */
#define CRATER_TOL_R 0.93     /* seed 001 3.1.1: smallest correlation of its SPH */
#define CRATER_N_X 4000       /* quadrature points over the crater (transform) */
#define CRATER_N_K 6000       /* wavenumber samples */

/* Initial surface of seed 001 eq 1 (seed 000 eq 2): eta0 (2 u^2 - 1), u = r/R <= 1. */
static double crater_eta0(double eta0, double R, double r) {
  const double u = fabs(r) / R;
  return u <= 1 ? eta0 * (2 * u * u - 1) : 0.0;
}

/* Linear plane Cauchy-Poisson solution (REFERENCES 5.1):
 *   eta(x, t) = (1/pi) int_0^inf F(k) cos(k x) cos(omega t) dk,
 *   F(k) = 2 int_0^R eta0(x) cos(k x) dx,  omega^2 = g k tanh(k h),
 * with a Gaussian filter exp(-(k delta)^2) (REFERENCES 5.2's advice for the
 * rim's jump); F by Simpson quadrature, the k integral by the trapezoid
 * rule on a uniform grid. */
struct cauchy {
  int nk;
  double dk, *k, *F, *omega;
};

static enum wl_status cauchy_make(struct cauchy *cp, double eta0, double R, double h, double delta,
                                  struct wl_error *err) {
  cp->nk = CRATER_N_K;
  const double kmax = 5.0 / delta;
  cp->dk = kmax / (cp->nk - 1);
  cp->k = malloc(sizeof(double) * (size_t)cp->nk);
  cp->F = malloc(sizeof(double) * (size_t)cp->nk);
  cp->omega = malloc(sizeof(double) * (size_t)cp->nk);
  if (!cp->k || !cp->F || !cp->omega) return wl_error_set(err, WL_ENOMEM, "validate: no memory");
  for (int j = 0; j < cp->nk; j++) {
    const double k = j * cp->dk;
    double sum = 0;
    const double hx = R / CRATER_N_X;
    for (int i = 0; i <= CRATER_N_X; i++) {
      const double x = i * hx, w = (i == 0 || i == CRATER_N_X) ? 1 : (i % 2 ? 4 : 2);
      /* just inside the rim: the shape is eta0 (2u^2 - 1) up to u = 1 */
      sum += w * crater_eta0(eta0, R, i == CRATER_N_X ? R * (1 - 1e-12) : x) * cos(k * x);
    }
    cp->k[j] = k;
    cp->F[j] = 2 * sum * hx / 3 * exp(-(k * delta) * (k * delta));
    cp->omega[j] = sqrt(G * k * tanh(k * h));
  }
  return WL_OK;
}

static double cauchy_eta(const struct cauchy *cp, double x, double t) {
  double s = 0;
  for (int j = 0; j < cp->nk; j++) {
    const double w = (j == 0 || j == cp->nk - 1) ? 0.5 : 1.0;
    s += w * cp->F[j] * cos(cp->k[j] * x) * cos(cp->omega[j] * t);
  }
  return s * cp->dk / VAL_PI;
}

static void cauchy_clear(struct cauchy *cp) {
  free(cp->k);
  free(cp->F);
  free(cp->omega);
  memset(cp, 0, sizeof *cp);
}

/* Seed 001's measures of a modelled series mod against a reference ref (n
 * samples): RMSE (its eq 16), the Pearson correlation, the reference's and
 * the model's largest |eta|. */
struct crater_fit {
  double rmse, r, ref_max, mod_max;
};

static struct crater_fit crater_measures(const double *mod, const double *ref, size_t n) {
  double sm = 0, se = 0, smm = 0, see = 0, sme = 0, s2 = 0;
  struct crater_fit f = {NAN, NAN, 0, 0};
  for (size_t k = 0; k < n; k++) {
    s2 += (mod[k] - ref[k]) * (mod[k] - ref[k]);
    sm += mod[k], se += ref[k], smm += mod[k] * mod[k], see += ref[k] * ref[k];
    sme += mod[k] * ref[k];
    f.ref_max = fmax(f.ref_max, fabs(ref[k]));
    f.mod_max = fmax(f.mod_max, fabs(mod[k]));
  }
  const double dn = (double)n;
  f.rmse = n ? sqrt(s2 / dn) : NAN;
  const double cov = sme - sm * se / dn, vm = smm - sm * sm / dn, ve = see - se * se / dn;
  f.r = (n > 1 && vm > 0 && ve > 0) ? cov / sqrt(vm * ve) : NAN;
  return f;
}

/* Why the Navier-Stokes solution is the judged reference, not the linear
 * one: linear theory assumes eta0/h << 1, and here eta0/h = 0.41 with a
 * rim that stands 2.07 m above still water and drops to it in a jump; the
 * crater's collapse and the steepening of its waves are outside it. At
 * the gauge the linear wave reads 20 % RMSE from the VOF solution, its
 * largest |eta| 18 % high, where this solver reads 6.5-8.3 % from it
 * (reference/charlesworth/README.md), so seed 001's RMSE bar, set for SPH against Charlesworth's record (not
 * available as data), can only be held against a solution of the same
 * nonlinear problem. The VOF series is a second, independent computation
 * (finite volumes, interFoam, two grids; its own grid difference is in the
 * README) of exactly this 2D initial value problem. */
enum wl_status wl_val_run_crater(const struct wl_val_case *c, const struct wl_val_ctx *ctx,
                                 double dp, struct wl_validate_level *lv, struct wl_error *err) {
  const double t_end = ctx->quick ? c->p[1] : c->p[0];
  char path[1024];
  snprintf(path, sizeof path, "%s/%s/scenario.yaml", ctx->ref_dir, c->dir);
  struct wl_scenario s;
  struct wl_plan plan;
  struct wl_val_table vof;
  memset(&vof, 0, sizeof vof);
  enum wl_status st = load_scenario(path, dp, ctx, &s, &plan, lv, err);
  if (!st) {
    snprintf(path, sizeof path, "%s/%s/vof_gauge.csv", ctx->ref_dir, c->dir);
    st = wl_val_table_read(path, &vof, err);
  }
  if (st) {
    wl_scenario_clear(&s);
    return st;
  }
  const struct wl_plan_explosion *px = &plan.explosion;
  struct wl_case_result cr;
  memset(&cr, 0, sizeof cr);
  st = run_case(&s, &plan, WL_CASE_EXPLOSION, ctx, t_end, &cr, lv, err);
  struct cauchy cp;
  memset(&cp, 0, sizeof cp);
  /* a fixed filter width, the same at every level: R0 / 20 */
  if (!st) st = cauchy_make(&cp, px->eta0, px->r0, plan.h, px->r0 / 20, err);
  if (!st && s.n_gauges > 0) {
    const double xg = s.gauges[0].x.q.si, xc = px->x_center, xw = s.wall.x.q.si;
    const double xl = cr.flume.x_left;
    const size_t ng = (size_t)cr.rec.n_gauges;
    size_t n = 0; /* the samples the VOF record covers */
    while (n < cr.rec.n && cr.rec.t[n] <= vof.x[vof.n - 1] + 1e-9) n++;
    double *lin = malloc(sizeof(double) * (n + 1)), *ns = malloc(sizeof(double) * (n + 1)),
           *mod = malloc(sizeof(double) * (n + 1));
    if (!lin || !ns || !mod) {
      st = wl_error_set(err, WL_ENOMEM, "validate: no memory");
    } else {
      for (size_t k = 0; k < n; k++) {
        const double t = cr.rec.t[k];
        /* the wave and its images in the seawall and the left end (both
         * reflect as vertical walls in linear theory) */
        lin[k] = cauchy_eta(&cp, xg - xc, t) + cauchy_eta(&cp, 2 * xw - xg - xc, t) +
                 cauchy_eta(&cp, xg + xc - 2 * xl, t);
        ns[k] = wl_val_interp(vof.x, vof.y, vof.n, t);
        mod[k] = cr.rec.eta[k * ng];
      }
      const struct crater_fit fn = crater_measures(mod, ns, n), fl = crater_measures(mod, lin, n);
      wl_val_rmse(&lv->m[0], "eta RMSE / max|eta_ref| (VOF)", "m", fn.rmse,
                  fn.ref_max, CRATER_TOL_RMSE);
      wl_val_corr(&lv->m[1], "eta correlation (VOF)", fn.r, CRATER_TOL_R);
      /* the 2D section of the axisymmetric lip holds -(2/3) eta0 R0 of
       * water less than the still level, so the leading wave at the gauge
       * can be a trough: the largest |eta| is compared */
      wl_val_rel(&lv->m[2], "largest |eta| at the gauge (VOF)", "m", fn.mod_max,
                 fn.ref_max, NAN);
      wl_val_rmse(&lv->m[3], "eta RMSE / max|eta_ref| (linear)", "m", fl.rmse,
                  fl.ref_max, NAN);
      wl_val_corr(&lv->m[4], "eta correlation (linear)", fl.r, NAN);
      wl_val_rel(&lv->m[5], "largest |eta| at the gauge (linear)", "m", fl.mod_max,
                 fl.ref_max, NAN);
      lv->n_metrics = 6;
    }
    free(lin);
    free(ns);
    free(mod);
  } else if (!st) {
    st = wl_error_set(err, WL_EINPUT, "%s: the reference scenario needs a gauge", path);
  }
  cauchy_clear(&cp);
  wl_val_table_clear(&vof);
  wl_assess_case_clear(&cr);
  wl_scenario_clear(&s);
  return st;
}
