/* test_sph_vres.c: variable resolution by coupled subdomains (vres.h,
 * issue 19 stage A), 2D, CPU backend, default numerics (plan.h
 * wl_plan_default_numerics; Verlet where a mode says).
 *
 * Modes (first argument):
 *  quick (every build): the corrected fit against linear fields; the
 *    layout rule against values worked by hand; the still tank below
 *    through 2 sqrt(h/g) (classification, fit, shifting; a stable run);
 *    a wave entering the bands on 1 and on 2 threads, the same bits.
 *  suite (label long): the fit, and a solitary wave crossing into the fine
 *    level with either integrator (creation runs, own mass within 1 %).
 *  still (label accuracy): a tank L = 1 m, h = 0.5 m, coarse dp = 0.05 m on
 *    x < 0.5 m and fine dp = 0.025 m beyond (the ranges overlapping by
 *    wl_vres_layout's rule), run 20 sqrt(h/g), against issue 19's bars:
 *    hydrostatic pressure (rho0 g depth) continuous across the interface
 *    within 1 % of it (met); the mass each level holds in its own range
 *    conserved to 1e-6, and the largest speed below 1 % of sqrt(g h) (not
 *    met: the same tank at uniform dp 0.05 and 0.025 m, printed beside it,
 *    reads 2.2-2.5 %, reference/RESULTS.md hydrostatic, issue 17).
 *  solitary (label accuracy), refs: below, at "a solitary wave across the
 *    interface and back". */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "testutil.h"
#include "wallload/plan.h"
#include "wallload/scene.h"
#include "wallload/sph/kernel.h"
#include "wallload/sph/vres_fit.h"
#include "wallload/vres.h"
#include "wallload/waves.h"

#define G 9.81
#define RHO0 1000.0
/* Shifting of the buffer particles along the interface (vres.h shift):
 * sph/shift.h's A = 2, DualSPHysics' default coefficient. */
#define VRES_SHIFT 2.0

/* ---- the corrected fit (sph/vres_fit.h) against linear fields ---------------------------------- */

static void field(const double *x, double *f) {
  f[0] = 1000 + 3 * x[0] - 5 * x[1];
  f[1] = 0.2 + 0.7 * x[0] + 0.1 * x[1];
  f[2] = -0.3 * x[0] + 2 * x[1];
}

/* The fit at (px, pz) from donors on a jittered lattice of spacing dp over
 * [0, 0.2] x [0, z_max]; returns wl_vres_fit_solve's code, values in out. */
static int fit_point(const struct wl_sph_const *k, double dp, double z_max, double px, double pz,
                     double *out) {
  struct wl_vres_fit f;
  wl_vres_fit_init(&f, 2, (double)k->h);
  unsigned long seed = 12345;
  for (double x = 0.5 * dp; x < 0.2; x += dp)
    for (double z = 0.5 * dp; z < z_max; z += dp) {
      double xj[2];
      for (int a = 0; a < 2; a++) { /* jitter +-0.2 dp (an LCG, for the same cloud each run) */
        seed = seed * 6364136223846793005ul + 1442695040888963407ul;
        xj[a] = (a ? z : x) + 0.4 * dp * ((double)(seed >> 11) / 9007199254740992.0 - 0.5);
      }
      const double d[2] = {xj[0] - px, xj[1] - pz}, r2 = d[0] * d[0] + d[1] * d[1];
      if (r2 >= (double)k->support2) continue;
      double val[3];
      field(xj, val);
      wl_vres_fit_add(&f, d, (double)wl_sph_kernel_w(k, (wl_real)r2),
                      (double)wl_sph_kernel_f(k, (wl_real)r2), dp * dp, val);
    }
  return wl_vres_fit_solve(&f, out);
}

static int fit(void) {
  const double dp = 0.01;
  struct wl_sph_params prm;
  wl_sph_params_default(&prm, 2, dp, 0.2);
  wl_plan_default_numerics(&prm);
  struct wl_sph_const k;
  struct wl_error err;
  wl_error_clear(&err);
  if (wl_sph_const_make(&prm, &k, &err)) {
    printf("FAIL const: %s\n", err.msg);
    return 1;
  }
  double out[3], want[3];
  const double in[2] = {0.1, 0.1}, cut[2] = {0.1, 0.195};
  field(in, want);
  CHECK_TRUE(fit_point(&k, dp, 0.2, in[0], in[1], out) == 1,
             "inside a full support the corrected fit is used");
  for (int c = 0; c < 3; c++)
    CHECK_ABS(out[c], want[c], 1e-9 * (1 + fabs(want[c])),
              "first-order fit reproduces a linear field exactly (Liu & Liu 2006)");
  field(cut, want);
  CHECK_TRUE(fit_point(&k, dp, 0.2, cut[0], cut[1], out) == 1,
             "at a cut support (a free surface above) the fit is still regular");
  CHECK_ABS(out[0], want[0], 1e-9 * want[0], "linear field exact at a cut support");
  /* a single donor: the moment matrix is singular, Shepard's average is
   * that donor's value */
  struct wl_vres_fit f;
  wl_vres_fit_init(&f, 2, (double)k.h);
  const double d[2] = {0.3 * dp, 0.1 * dp}, val[3] = {1003, 0.5, -0.25};
  const double r2 = d[0] * d[0] + d[1] * d[1];
  wl_vres_fit_add(&f, d, (double)wl_sph_kernel_w(&k, (wl_real)r2), (double)wl_sph_kernel_f(&k, (wl_real)r2),
                  dp * dp, val);
  CHECK_TRUE(wl_vres_fit_solve(&f, out) == 0, "one donor: Shepard's average");
  CHECK_ABS(out[0], 1003, 1e-9, "Shepard's average of one donor is its value");
  wl_vres_fit_init(&f, 2, (double)k.h);
  CHECK_TRUE(wl_vres_fit_solve(&f, out) == -1, "no donor: no value");
  return 0;
}

/* ---- the layout of two levels (vres.h wl_vres_layout) ------------------------------------------ */

/* Against the rule worked by hand: h/dp = 1.2 sqrt 2 = 1.697, so a band of
 * 2h is ceil(3.39) = 4 rows of its level (0.08 m coarse, 0.04 m fine at
 * 0.02 / 0.01 m), the overlap one coarse band on either side. */
static int layout(void) {
  struct wl_vres_opts o = {0};
  struct wl_vres_layout a;
  wl_vres_layout(2.5, 0.02, 0.01, 1.2 * sqrt(2.0), 1, &o, &a);
  CHECK_ABS(a.band[0], 0.08, 1e-12, "coarse band: 4 whole rows of 0.02 m");
  CHECK_ABS(a.band[1], 0.04, 1e-12, "fine band: 4 whole rows of 0.01 m");
  CHECK_ABS(a.own_hi[0], 2.58, 1e-12, "coarse range ends one coarse band past the interface");
  CHECK_ABS(a.own_lo[1], 2.42, 1e-12, "fine range starts one coarse band before it");
  CHECK_TRUE(isinf(a.own_lo[0]) && isinf(a.own_hi[1]), "the outer ends are open");
  CHECK_ABS(a.water_hi[0], 2.66, 1e-12, "coarse water through its band");
  CHECK_ABS(a.water_lo[1], 2.38, 1e-12, "fine water from its band");
  o.overlap = -1;
  wl_vres_layout(2.5, 0.02, 0.01, 1.2 * sqrt(2.0), 0, &o, &a); /* fine on the left, touching */
  CHECK_ABS(a.own_lo[0], 2.5, 1e-12, "touching: the coarse range starts at the interface");
  CHECK_ABS(a.own_hi[1], 2.5, 1e-12, "touching: the fine range ends at it");
  CHECK_ABS(a.water_hi[1], 2.54, 1e-12, "fine water through its band on the right");
  return 0;
}

/* ---- the levels' basins ------------------------------------------------------------------------ */

/* A 2D basin: flat bed at z = 0, walls at x = 0 and `length` of height
 * `wall`, still water `depth` deep; the domain box `top` high. */
struct basin {
  double depth, length, wall, top;
};

#define LAYERS 3 /* boundary particle layers */

struct wave_ic {
  struct wl_solitary sw;
  double depth, crest, rho;
};

static double wave_eta(double x, void *user) {
  const struct wave_ic *w = user;
  return w->depth + wl_waves_solitary_eta(&w->sw, x - w->crest);
}

static void wave_vel(const double *x, double *v, void *user) {
  const struct wave_ic *w = user;
  wl_waves_solitary_velocity(&w->sw, x[0] - w->crest, x[1], &v[0], &v[1]);
}

/* flume.c's non-hydrostatic part of the wave's pressure (Bernoulli in the
 * crest's frame) */
static double wave_dp(const double *x, void *user) {
  const struct wave_ic *w = user;
  double u, ww;
  wl_waves_solitary_velocity(&w->sw, x[0] - w->crest, x[1], &u, &ww);
  return w->rho * (w->sw.c * u - 0.5 * (u * u + ww * ww) -
                   w->sw.g * wl_waves_solitary_eta(&w->sw, x[0] - w->crest));
}

/* CPU threads of each level's run (WL_VRES_THREADS; 1 when unset, so that
 * two runs share the 2-core machine). */
static int g_threads = 0; /* > 0: overrides WL_VRES_THREADS (threads_same) */
static int threads(void) {
  const char *s = getenv("WL_VRES_THREADS");
  return g_threads > 0 ? g_threads : s && atoi(s) > 0 ? atoi(s) : 1;
}

/* The levels' integrator (vres.h: either; buffer particles move with
 * their fitted velocity under both, sph/integrate.h): the default
 * numerics' symplectic one unless a mode sets Verlet, which
 * scenarios/seawall.yaml runs (WL_VRES_VERLET=1 for every mode; the suite
 * crosses with both). */
static int g_verlet = 0;

/* A level of spacing dp of basin b over x in [x0, x1] (a wall where the
 * range reaches the basin's end), water over [fluid_x0, fluid_x1]: still
 * (w NULL) or the solitary wave w; its configuration (wallload's default
 * numerics, one thread) and particles. */
static int basin_level(const struct basin *b, double dp, double x0, double x1, double fluid_x0,
                       double fluid_x1, struct wave_ic *w, struct wl_sph_config *cfg,
                       struct wl_particles *init) {
  struct wl_error err;
  wl_error_clear(&err);
  wl_sph_config_default(cfg, 2, dp, b->depth);
  wl_plan_default_numerics(&cfg->prm);
  if (g_verlet) cfg->prm.integrator = WL_SPH_VERLET;
  cfg->n_threads = threads();
  struct wl_sph_const k;
  if (wl_sph_const_make(&cfg->prm, &k, &err)) {
    printf("FAIL const: %s\n", err.msg);
    return 1;
  }
  const double m = (LAYERS + 2) * dp;
  cfg->lo[0] = x0 - m;
  cfg->hi[0] = x1 + m;
  cfg->lo[1] = -m;
  cfg->hi[1] = b->top;
  struct wl_scene sc;
  wl_scene_init(&sc, &k, 0, 0);
  double tx[4], tz[4];
  int nv = 0;
  if (x0 <= 0) tx[nv] = 0, tz[nv++] = b->wall;
  tx[nv] = x0 <= 0 ? 0 : x0, tz[nv++] = 0;
  tx[nv] = x1 >= b->length ? b->length : x1, tz[nv++] = 0;
  if (x1 >= b->length) tx[nv] = b->length, tz[nv++] = b->wall;
  enum wl_status st = wl_scene_boundary_polyline(&sc, tx, tz, nv, LAYERS, WL_KIND_FIXED, 0, cfg, &err);
  if (!st && !w) {
    const double lo[2] = {fluid_x0, 0}, hi[2] = {fluid_x1, b->depth};
    st = wl_scene_fluid_block(&sc, lo, hi, b->depth, &err);
  } else if (!st) {
    const double bx[2] = {fluid_x0, fluid_x1}, bz[2] = {0, 0};
    w->rho = (double)k.rho0;
    st = wl_scene_fluid_surface(&sc, fluid_x0, fluid_x1, bx, bz, 2, b->depth, wave_eta, w, &err);
    if (!st) {
      wl_scene_fluid_velocity(&sc, wave_vel, w);
      wl_scene_fluid_add_pressure(&sc, wave_dp, w);
    }
  }
  if (!st) wl_scene_hydrostatic_boundary(&sc, b->depth);
  if (!st) st = wl_scene_build(&sc, init, &err);
  wl_scene_clear(&sc);
  if (st) printf("FAIL scene: %s\n", err.msg);
  return st != WL_OK;
}

/* The ranges' overlap on either side of the interface (vres.h
 * wl_vres_layout's opts->overlap: coarse band widths; < 0 touching); the
 * solitary mode's sixth argument. */
static double g_overlap = 1.0;

/* Two levels of basin b, coarse dpc on x < x_if and fine dpf beyond, laid
 * out by wl_vres_layout (overlap g_overlap, bands o->buffer_h), each with
 * `spare` parked particles (parked high in the box, above the walls),
 * coupled (vres.h). */
static int coupled(const struct basin *b, double dpc, double dpf, double x_if, struct wave_ic *w,
                   struct wl_vres_opts *o, int spare, struct wl_vres **v) {
  o->overlap = g_overlap;
  /* WL_VRES_SHIFT_ACROSS=1 (diagnosis): buffers shifted across the interface too (vres.h) */
  if (getenv("WL_VRES_SHIFT_ACROSS")) o->shift_across = atoi(getenv("WL_VRES_SHIFT_ACROSS")) > 0;
  struct wl_vres_layout lay;
  wl_vres_layout(x_if, dpc, dpf, WL_PLAN_COEFH_2D * sqrt(2.0), 1, o, &lay);
  struct wl_sph_config cfg[2];
  struct wl_particles init[2] = {{0}, {0}};
  /* Each level's water holds the columns whose centres lie in its range and
   * band, as `assess` lays them (the flume built whole, then cropped at the
   * band's far edge; src/assess/levels.c). A wave's surface is laid in whole
   * columns back from the range's far end (the wall), so the fine level's
   * wave starts half a spacing seaward of its band's edge: laid from the
   * edge itself, the column straddling it was left out, and the fine level
   * started a column (1 kg/m at dp = 0.005 m) short of what the coupling
   * assumes (2026-11-29). A still block is laid from its near end, whose
   * first column's centre is half a spacing inside it. */
  const double fine_x0 = lay.water_lo[1] - (w ? 0.5 * dpf : 0.0);
  if (basin_level(b, dpc, 0, lay.water_hi[0] + 3 * dpc, 0, lay.water_hi[0], w, &cfg[0], &init[0]) ||
      basin_level(b, dpf, lay.water_lo[1] - 3 * dpf, b->length, fine_x0, b->length, w, &cfg[1],
                  &init[1]))
    return 1;
  struct wl_vres_level_spec s[2];
  memset(s, 0, sizeof s);
  for (int l = 0; l < 2; l++) {
    s[l].cfg = &cfg[l];
    s[l].initial = &init[l];
    s[l].park_lo[0] = cfg[l].lo[0] + 0.05, s[l].park_hi[0] = cfg[l].hi[0] - 0.05;
    s[l].park_lo[1] = 0.64 * b->top, s[l].park_hi[1] = 0.92 * b->top;
    s[l].spare = spare;
  }
  for (int l = 0; l < 2; l++) s[l].own_lo = lay.own_lo[l], s[l].own_hi = lay.own_hi[l];
  struct wl_error err;
  wl_error_clear(&err);
  const enum wl_status st = wl_vres_alloc(v, &wl_backend_cpu_ops, 2, s, o, &err);
  wl_particles_clear(&init[0]);
  wl_particles_clear(&init[1]);
  if (st) printf("FAIL vres: %s\n", err.msg);
  return st != WL_OK;
}

/* ---- still tank -------------------------------------------------------------------------------- */

#define TANK_L 1.0
#define TANK_H 0.5
#define TANK_X_IF 0.5
static const struct basin tank = {TANK_H, TANK_L, 1.5 * TANK_H, 3 * TANK_H};

/* Largest fluid speed over the owned fluid of a particle set (x in
 * [lo, hi], body 0). */
static double vmax_of(const struct wl_particles *p, double lo, double hi) {
  double v2 = 0;
  for (int i = p->n_bound; i < p->n; i++) {
    if (p->body[i] != 0 || p->pos[0][i] < lo || p->pos[0][i] > hi) continue;
    const double s = (double)p->vel[0][i] * p->vel[0][i] + (double)p->vel[1][i] * p->vel[1][i];
    v2 = s > v2 ? s : v2;
  }
  return sqrt(v2);
}

/* Least-squares line p(z) through the pressures of owned fluid in [lo, hi]
 * below z_max, evaluated at z. */
static double p_line(const struct wl_particles *p, const struct wl_sph_const *k, double lo,
                     double hi, double z_max, double z) {
  double n = 0, sz = 0, sp = 0, szz = 0, szp = 0;
  for (int i = p->n_bound; i < p->n; i++) {
    const double x = p->pos[0][i], zi = p->pos[1][i];
    if (p->body[i] != 0 || x < lo || x > hi || zi > z_max) continue;
    const double pr = (double)wl_sph_eos_p(k, p->rho[i]);
    n++, sz += zi, sp += pr, szz += zi * zi, szp += zi * pr;
  }
  const double b = (n * szp - sz * sp) / (n * szz - sz * sz), a = (sp - b * sz) / n;
  return a + b * z;
}

/* The same tank at uniform dp: largest speed after t_end / sqrt(g h). */
static double uniform_tank(double dp, double t_end) {
  struct wl_sph_config cfg;
  struct wl_particles init = {0};
  if (basin_level(&tank, dp, 0, TANK_L, 0, TANK_L, NULL, &cfg, &init)) return NAN;
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_sim *sim;
  if (wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err)) {
    printf("FAIL sim: %s\n", err.msg);
    return NAN;
  }
  wl_particles_clear(&init);
  while (wl_sph_sim_time(sim) < t_end)
    if (wl_sph_sim_step(sim, t_end - wl_sph_sim_time(sim), &err)) {
      printf("FAIL uniform dp %g: %s\n", dp, err.msg);
      wl_sph_sim_free(sim);
      return NAN;
    }
  const double v = vmax_of(wl_sph_sim_particles(sim, &err), -1, 2);
  wl_sph_sim_free(sim);
  return v / sqrt(G * TANK_H);
}

/* The still tank over `periods` sqrt(h/g); strict: against issue 19's bars. */
static int still(double periods, int strict) {
  const double dpc = 0.05, dpf = 0.025, t_end = periods * sqrt(TANK_H / G);
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_vres_opts o = {0};
  o.z_bed = 0;
  o.z_top = TANK_H + 0.1;
  o.shift = VRES_SHIFT;
  struct wl_vres *v;
  if (coupled(&tank, dpc, dpf, TANK_X_IF, NULL, &o, 100, &v)) return 1;
  const double m0 = wl_vres_own_mass(v, &err);
  const time_t w0 = time(NULL);
  enum wl_status st = WL_OK;
  double next = 0.02;
  while (st == WL_OK && wl_vres_time(v) < t_end) {
    st = wl_vres_step(v, t_end - wl_vres_time(v), &err);
    if (st == WL_OK && wl_vres_time(v) >= next) {
      next += next < 0.5 ? 0.04 : 0.5;
      const double vc = vmax_of(wl_sph_sim_particles(wl_vres_level(v, 0), &err), -1, TANK_X_IF);
      const double vf = vmax_of(wl_sph_sim_particles(wl_vres_level(v, 1), &err), TANK_X_IF, 2);
      printf("t = %.2f s: max |v| / sqrt(g h) coarse %.4f, fine %.4f; own mass %+.3e\n",
             wl_vres_time(v), vc / sqrt(G * TANK_H), vf / sqrt(G * TANK_H),
             wl_vres_own_mass(v, &err) / m0 - 1);
    }
  }
  printf("run: %s%s%s, ~%ld s wall\n", wl_error_status_name(st), st ? ": " : "", st ? err.msg : "",
         (long)(time(NULL) - w0));
  CHECK_TRUE(st == WL_OK, "still water across the interface without a guard fault");
  for (int l = 0; l < 2; l++) {
    const struct wl_vres_counts *c = wl_vres_counts(v, l);
    printf("level %d: created %ld, removed %ld, fits %ld corrected / %ld Shepard, flux in %.4g "
           "kg/m\n", l, c->created, c->removed, c->fitted, c->shepard, c->flux_in);
  }
  const struct wl_particles *pc = wl_sph_sim_particles(wl_vres_level(v, 0), &err);
  const double vc = vmax_of(pc, -1, TANK_X_IF) / sqrt(G * TANK_H);
  const struct wl_particles *pf = wl_sph_sim_particles(wl_vres_level(v, 1), &err);
  const double vf = vmax_of(pf, TANK_X_IF, 2) / sqrt(G * TANK_H);
  const double z = 0.1, p_ref = RHO0 * G * (TANK_H - z);
  const double p_c = p_line(pc, wl_sph_sim_const(wl_vres_level(v, 0)), TANK_X_IF - 0.15, TANK_X_IF,
                            TANK_H - 2 * dpc, z);
  const double p_f = p_line(pf, wl_sph_sim_const(wl_vres_level(v, 1)), TANK_X_IF, TANK_X_IF + 0.15,
                            TANK_H - 2 * dpc, z);
  printf("pressure at z = %g m beside the interface: coarse %.1f Pa, fine %.1f Pa, rho0 g depth "
         "%.1f Pa\n", z, p_c, p_f, p_ref);
  const double dm = wl_vres_own_mass(v, &err) / m0 - 1;
  printf("own mass: %+.3e relative; largest speed / sqrt(g h): coarse %.4f, fine %.4f\n", dm, vc,
         vf);
  if (strict) {
    const double uc = uniform_tank(dpc, t_end), uf = uniform_tank(dpf, t_end);
    printf("the same tank at uniform dp %g: %.4f, dp %g: %.4f\n", dpc, uc, dpf, uf);
    CHECK_ABS(p_f - p_c, 0, 0.01 * p_ref, "hydrostatic pressure continuous across the interface "
              "within 1 % of rho0 g depth (issue 19)");
    CHECK_ABS(dm, 0, 1e-6, "own mass conserved to 1e-6 (issue 19)");
    CHECK_ABS(fmax(vc, vf), 0, 0.01, "largest speed below 1 % of sqrt(g h) (issue 19)");
  }
  wl_vres_free(v);
  return 0;
}

/* ---- a solitary wave across the interface and back ----------------------------------------------- */

/* Mode solitary (label accuracy): a Grimshaw solitary wave from the coarse
 * level across the interface into the fine level, onto the far wall and
 * back, against the uniform fine run of the same flume (issue 19's bars:
 * crest at G2 and G3 and back at G1 within 1 % of H, the interface's
 * reflection below 1 % of H, celerity within 1 %). The uniform coarse run
 * is printed beside it: the coupling passes on the coarse level's flow, so
 * the crest in the fine level can be no nearer the uniform fine run's than
 * the coarse level's own wave is at the interface. What it reads, dated,
 * is beside the ctest lines (tests/CMakeLists.txt) and in docs/history
 * (2026-11-27-variable-resolution-overlap.md, 2026-11-29-vres-band-
 * spacing.md). The two-sided bar is kept: issue 19 words it as height
 * lost, and a wave that arrives too high is as wrong a load. */

#define FL_H 0.2     /* still water [m] */
#define FL_L 5.5     /* wall to wall [m] */
#define FL_X_IF 2.5  /* coarse on x < 2.5, fine beyond */
#define FL_CREST 1.0 /* initial crest [m] */
#define FL_T_END 5.2 /* to the reflected crest's return to G1 [s] */
/* The solitary and refs modes' end: FL_T_END, or WL_VRES_T_END seconds
 * (for diagnosis: about 2.1 s holds the incident crest at every gauge;
 * the reflection and return are then not measured). */
static double g_t_end = FL_T_END;
static int g_t_end_given; /* WL_VRES_T_END set */

/* The solitary and refs modes' end: FL_T_END is the H/h = 0.4 wave's
 * return to G1 with its smoothing window; a slower wave (H/h < 0.4) gets
 * the same window stretched by its celerity, sqrt(g (h + H)) (H/h = 0.2:
 * 5.62 s; at 5.2 s its crest came back at the record's last sample). */
static void t_end_for(double eps) {
  if (!g_t_end_given && eps < 0.4) g_t_end = FL_T_END * sqrt((1 + 0.4) / (1 + eps));
}
/* The initial crest's offset from FL_CREST [m]: the solitary mode's
 * realisations (below) start the same wave a fraction of a spacing apart. */
static double g_crest_dx = 0;
#define REALISATIONS_MAX 16

/* The solitary mode's realisations (WL_VRES_REALISATIONS, default 3, at most
 * REALISATIONS_MAX), and realisation k's crest offset at fine spacing dpf. */
static int realisations(void) {
  const char *env = getenv("WL_VRES_REALISATIONS");
  const int n = env && atoi(env) > 0 ? atoi(env) : 3;
  return n < REALISATIONS_MAX ? n : REALISATIONS_MAX;
}
static double realisation_offset(double dpf, int k) { return 0.3 * dpf * k; }
#define FL_GAUGES 8
/* G1 in the coarse level; G2 and G3 in the fine, 1.5 m or more from the
 * wall, whose reflection would otherwise lift their crests. The rest are
 * for diagnosis only (WL_VRES_DUMP): coarse at 2.0, 2.3, 2.45 m, fine at
 * 2.55, 2.7 m. */
static const double fl_gauge_x[FL_GAUGES] = {1.75, 3.2, 4.0, 2.0, 2.3, 2.45, 2.55, 2.7};
static const struct basin flume = {FL_H, FL_L, 2.5 * FL_H, 5 * FL_H};

/* A gauge reads the mean elevation of the vertical lines every
 * GAUGE_LINE_DX over GAUGE_HALF either side of its x: one line reads the
 * crest with spikes of 3-5 mm (a quarter of dp at dp = 0.01 m, 4-6 % of H
 * at H/h 0.4) as particles pass it, and its neighbour lines a few mm away
 * disagree by as much (docs/history/2026-11-27-variable-resolution-
 * overlap.md), which would hide a 1 % bar. The window is fixed in metres,
 * so every run compared reads the same spatial mean (0.1 m, h/2: its smoothing
 * of the crest, some 0.6 % of H at H/h 0.4, is the same for all). */
#define GAUGE_HALF 0.05
#define GAUGE_LINE_DX 0.005

/* Gauge records: eta at fl_gauge_x every 0.01 s. */
struct record {
  int n;
  double t[600], eta[600][FL_GAUGES];
};

/* eta at every gauge from the level that owns it (sims[l], owns x in [lo, hi]). */
static int sample(struct record *r, double t, struct wl_sph_sim **sims, const double *lo,
                  const double *hi, int n_sims) {
  struct wl_error err;
  wl_error_clear(&err);
  if (r->n >= 600) return 0;
  r->t[r->n] = t;
  for (int l = 0; l < n_sims; l++) {
    struct wl_sph_probe *pr;
    if (wl_sph_probe_alloc(&pr, wl_sph_sim_config(sims[l]), &err)) return 1;
    const struct wl_particles *p = wl_sph_sim_particles(sims[l], &err);
    if (!p || wl_sph_probe_index(pr, p, &err)) return 1;
    for (int g = 0; g < FL_GAUGES; g++)
      if (fl_gauge_x[g] >= lo[l] && fl_gauge_x[g] <= hi[l]) {
        const int nl = (int)lround(GAUGE_HALF / GAUGE_LINE_DX);
        double sum = 0;
        for (int q = -nl; q <= nl; q++)
          sum += wl_sph_probe_elevation(pr, fl_gauge_x[g] + q * GAUGE_LINE_DX, 0, 0, 2.5 * FL_H, 0);
        r->eta[r->n][g] = sum / (2 * nl + 1) - FL_H;
      }
    wl_sph_probe_free(pr);
  }
  r->n++;
  return 0;
}

/* A uniform run's record from the directory WL_VRES_REF_DIR when it holds
 * one (written there by an earlier run), so that runs of the coupled flume
 * need not repeat the uniform references (one file per H/h, dp and gauge
 * set). Returns 1 when loaded. */
static int ref_path(char *buf, size_t n, double eps, double dp) {
  const char *dir = getenv("WL_VRES_REF_DIR");
  if (!dir || !*dir) return 0;
  char off[32] = "";
  if (g_crest_dx != 0) snprintf(off, sizeof off, "_c%g", g_crest_dx);
  snprintf(buf, n, "%s/flume_eps%g_dp%g_g%d_w%g_t%g%s%s.bin", dir, eps, dp, FL_GAUGES, GAUGE_HALF,
           g_t_end, g_verlet ? "_verlet" : "", off);
  return 1;
}

static int ref_load(struct record *r, double eps, double dp) {
  char path[512];
  if (!ref_path(path, sizeof path, eps, dp)) return 0;
  FILE *fp = fopen(path, "rb");
  /* WL_VRES_REF_WAIT=s: another process (mode refs) is writing it */
  for (int s = getenv("WL_VRES_REF_WAIT") ? atoi(getenv("WL_VRES_REF_WAIT")) : 0; !fp && s > 0; s -= 5) {
    struct timespec ts = {5, 0};
    nanosleep(&ts, NULL);
    fp = fopen(path, "rb");
  }
  if (!fp) return 0;
  const int ok = fread(r, sizeof *r, 1, fp) == 1;
  fclose(fp);
  if (ok) printf("uniform dp %g: record read from %s\n", dp, path);
  return ok;
}

static void ref_save(const struct record *r, double eps, double dp) {
  char path[512];
  if (!ref_path(path, sizeof path, eps, dp)) return;
  FILE *fp = fopen(path, "wb");
  if (fp) {
    fwrite(r, sizeof *r, 1, fp);
    fclose(fp);
  }
}

/* The gauge records as text into WL_VRES_DUMP.<name> when set: t, then
 * eta at each gauge. */
static void dump(const struct record *r, const char *name) {
  const char *base = getenv("WL_VRES_DUMP");
  if (!base || !*base) return;
  char path[512];
  snprintf(path, sizeof path, "%s.%s", base, name);
  FILE *fp = fopen(path, "w");
  if (!fp) return;
  fprintf(fp, "# t");
  for (int g = 0; g < FL_GAUGES; g++) fprintf(fp, " eta(%.2f)", fl_gauge_x[g]);
  fprintf(fp, "\n");
  for (int k = 0; k < r->n; k++) {
    fprintf(fp, "%.4f", r->t[k]);
    for (int g = 0; g < FL_GAUGES; g++) fprintf(fp, " %.6f", r->eta[k][g]);
    fprintf(fp, "\n");
  }
  fclose(fp);
}

/* Largest eta at gauge g over t in [t0, t1], parabola through the top
 * sample; its time into *tp. */
static double crest_of(const struct record *r, int g, double t0, double t1, double *tp) {
  int best = -1;
  for (int k = 0; k < r->n; k++)
    if (r->t[k] >= t0 && r->t[k] <= t1 && (best < 0 || r->eta[k][g] > r->eta[best][g])) best = k;
  if (best < 0) return NAN;
  double a = r->eta[best][g];
  *tp = r->t[best];
  if (best > 0 && best + 1 < r->n) {
    const double y0 = r->eta[best - 1][g], y1 = a, y2 = r->eta[best + 1][g], den = y0 - 2 * y1 + y2;
    if (den < 0) {
      const double s = 0.5 * (y0 - y2) / den;
      *tp += s * (r->t[best + 1] - r->t[best]);
      a = y1 - 0.25 * (y0 - y2) * s;
    }
  }
  return a;
}

/* The crest at gauge g over [t0, t1], read so that a single sample does
 * not move it: the 3-sample running mean of the record (a single gauge
 * line reads a crest with spikes of 3-5 mm, 4-6 % of H at H/h 0.4, as one
 * particle passes it: docs/history/2026-11-27-variable-resolution-
 * overlap.md), then a least-squares parabola through the mean's samples
 * within CREST_FIT of its largest; its vertex (the largest mean where the
 * vertex falls outside). The same measure reads every run compared. */
#define CREST_FIT 0.06 /* s: +-6 samples, a tenth of the crest's passage at H/h 0.4 */
static double crest_smooth(const struct record *r, int g, double t0, double t1, double *tp) {
  int best = -1;
  double mbest = -INFINITY;
  for (int k = 1; k + 1 < r->n; k++) {
    if (r->t[k] < t0 || r->t[k] > t1) continue;
    const double m = (r->eta[k - 1][g] + r->eta[k][g] + r->eta[k + 1][g]) / 3;
    if (m > mbest) best = k, mbest = m;
  }
  if (best < 0) return NAN;
  double s[5] = {0}, y[3] = {0}; /* sums of tau^0..4 and of m tau^0..2 */
  for (int k = 1; k + 1 < r->n; k++) {
    const double tau = r->t[k] - r->t[best];
    if (fabs(tau) > CREST_FIT + 1e-9) continue;
    const double m = (r->eta[k - 1][g] + r->eta[k][g] + r->eta[k + 1][g]) / 3;
    for (int q = 0; q < 5; q++) s[q] += pow(tau, q);
    for (int q = 0; q < 3; q++) y[q] += m * pow(tau, q);
  }
  /* normal equations of a + b tau + c tau^2, by Cramer's rule */
  const double A[3][3] = {{s[0], s[1], s[2]}, {s[1], s[2], s[3]}, {s[2], s[3], s[4]}};
  const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                     A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                     A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  double c3[3];
  for (int col = 0; col < 3; col++) {
    double M[3][3];
    memcpy(M, A, sizeof M);
    for (int row = 0; row < 3; row++) M[row][col] = y[row];
    c3[col] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
               M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
               M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) / det;
  }
  *tp = r->t[best];
  if (!(c3[2] < 0)) return mbest;
  const double tv = -c3[1] / (2 * c3[2]);
  if (fabs(tv) > CREST_FIT) return mbest;
  *tp += tv;
  return c3[0] - c3[1] * c3[1] / (4 * c3[2]);
}

/* The first time after t0 that eta at gauge g rises through `level` (the
 * front face: steadier than the crest's time, which a crest's changed
 * shape moves), linearly interpolated. */
static double front_time(const struct record *r, int g, double t0, double level) {
  for (int k = 1; k < r->n; k++)
    if (r->t[k - 1] >= t0 && r->eta[k - 1][g] < level && r->eta[k][g] >= level)
      return r->t[k - 1] + (level - r->eta[k - 1][g]) / (r->eta[k][g] - r->eta[k - 1][g]) *
                               (r->t[k] - r->t[k - 1]);
  return NAN;
}

/* Largest |eta| at gauge g over [t0, t1]. */
static double abs_max_of(const struct record *r, int g, double t0, double t1) {
  double m = 0;
  for (int k = 0; k < r->n; k++)
    if (r->t[k] >= t0 && r->t[k] <= t1) m = fmax(m, fabs(r->eta[k][g]));
  return m;
}

static double g_buffer_h = 2.0, g_shift = VRES_SHIFT; /* solitary's optional arguments */
/* The fine level's rows over the still depth (solitary's and refs' argument
 * after the dp ratio): 20, H/dp 8 at H/h 0.4. */
static double g_fine_rows = 20;

/* The run of one flume to t_end: uniform (dpf <= 0) or coarse dpc and fine
 * dpf; the coupled run's own-mass change and created particles into
 * *mass_drift and *created (may be NULL). */
static int flume_run(double eps, double dpc, double dpf, double t_end, struct record *r,
                     double *mass_drift, long *created) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wave_ic w;
  memset(&w, 0, sizeof w);
  w.crest = FL_CREST + g_crest_dx;
  w.depth = FL_H;
  if (wl_waves_solitary_init(&w.sw, WL_SOLITARY_GRIMSHAW, FL_H, eps * FL_H, 9.81, &err)) {
    printf("FAIL wave: %s\n", err.msg);
    return 1;
  }
  if (r) memset(r, 0, sizeof *r);
  const time_t w0 = time(NULL);
  enum wl_status st = WL_OK;
  double next = 0;
  if (dpf <= 0) {
    struct wl_sph_config cfg;
    struct wl_particles init = {0};
    if (basin_level(&flume, dpc, 0, FL_L, 0, FL_L, &w, &cfg, &init)) return 1;
    struct wl_sph_sim *sim;
    if (wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err)) {
      printf("FAIL sim: %s\n", err.msg);
      return 1;
    }
    wl_particles_clear(&init);
    const double lo = -1, hi = 10;
    while (st == WL_OK && wl_sph_sim_time(sim) < t_end - 1e-9) {
      if (wl_sph_sim_time(sim) >= next - 1e-9) {
        if (sample(r, wl_sph_sim_time(sim), &sim, &lo, &hi, 1)) return 1;
        next += 0.01;
      }
      st = wl_sph_sim_step(sim, next - wl_sph_sim_time(sim), &err);
    }
    wl_sph_sim_free(sim);
  } else {
    struct wl_vres_opts o = {0};
    o.z_bed = 0;
    o.z_top = FL_H * (1 + 2 * eps);
    o.shift = g_shift;
    o.buffer_h = g_buffer_h;
    struct wl_vres *v;
    /* parked particles for creation: 1500 at dp 0.01 m (about twice what the wave's crossing
       creates), as many more as the fine level has particles per area */
    const int spare = (int)ceil(1500 * pow(0.01 / dpf, 2));
    if (coupled(&flume, dpc, dpf, FL_X_IF, &w, &o, spare, &v)) return 1;
    const double m0 = wl_vres_own_mass(v, &err);
    struct wl_sph_sim *sims[2] = {wl_vres_level(v, 0), wl_vres_level(v, 1)};
    const double lo[2] = {-1, FL_X_IF}, hi[2] = {FL_X_IF, 10};
    while (st == WL_OK && wl_vres_time(v) < t_end - 1e-9) {
      if (r && wl_vres_time(v) >= next - 1e-9) {
        if (sample(r, wl_vres_time(v), sims, lo, hi, 2)) return 1;
        next += 0.01;
      }
      st = wl_vres_step(v, r ? next - wl_vres_time(v) : t_end - wl_vres_time(v), &err);
    }
    const double drift = wl_vres_own_mass(v, &err) / m0 - 1;
    printf("vres own mass after the run: %+.3e relative\n", drift);
    if (mass_drift) *mass_drift = drift;
    if (created) *created = wl_vres_counts(v, 0)->created + wl_vres_counts(v, 1)->created;
    for (int l = 0; l < 2; l++) {
      const struct wl_vres_counts *c = wl_vres_counts(v, l);
      printf("level %d: created %ld, removed %ld, fits %ld corrected / %ld Shepard\n", l,
             c->created, c->removed, c->fitted, c->shepard);
    }
    wl_vres_free(v);
  }
  printf("flume H/h %g, dp %g%s%g: %s%s%s, %d samples, ~%ld s wall\n", eps, dpc,
         dpf > 0 ? " / " : "", dpf > 0 ? dpf : 0.0, wl_error_status_name(st), st ? ": " : "",
         st ? err.msg : "", r ? r->n : 0, (long)(time(NULL) - w0));
  return st != WL_OK;
}

/* One realisation of the solitary mode: the coupled flume against the
 * uniform fine run started alike; its differences into d[] (m; celerity:
 * relative): G2 and G3 crests, the interface's reflection, celerity, the
 * return into the coarse level (the crest back across at G1). */
enum { SOL_G2, SOL_G3, SOL_REFL, SOL_CEL, SOL_BACK, SOL_N };
static int solitary_once(double eps, double ratio, double d[SOL_N]) {
  const double H = eps * FL_H, dpf = FL_H / g_fine_rows, dpc = ratio * dpf;
  static struct record rv, ru, rc;
  if (flume_run(eps, dpc, dpf, g_t_end, &rv, NULL, NULL)) return 1;
  dump(&rv, "vres");
  if (!ref_load(&ru, eps, dpf)) {
    if (flume_run(eps, dpf, 0, g_t_end, &ru, NULL, NULL)) return 1;
    ref_save(&ru, eps, dpf);
  }
  dump(&ru, "fine");
  if (ratio > 1 && !ref_load(&rc, eps, dpc)) {
    if (flume_run(eps, dpc, 0, g_t_end, &rc, NULL, NULL)) return 1;
    ref_save(&rc, eps, dpc);
  }
  if (ratio > 1) dump(&rc, "coarse");
  const double c = sqrt(9.81 * FL_H * (1 + eps));
  if (ratio > 1)
    for (int g = 0; g < 3; g++) { /* the coarse level's own wave, against the fine one's */
      const double tg = (fl_gauge_x[g] - FL_CREST) / c;
      double tcg, tfg;
      const double a = crest_smooth(&rc, g, tg - 0.4, tg + 0.4, &tcg);
      const double af = crest_smooth(&ru, g, tg - 0.4, tg + 0.4, &tfg);
      printf("G%d uniform coarse: crest (smoothed) %.5f m at %.4f s, %+.2f %% of H from the "
             "uniform fine run's\n", g + 1, a, tcg, 100 * (a - af) / H);
    }
  /* incident crest times at the gauges, the interface's reflection back at
   * G1 before the wall's, the wall's reflection back across at G1 */
  const double t_g1 = (fl_gauge_x[0] - FL_CREST) / c, t_if = (2 * FL_X_IF - FL_CREST - fl_gauge_x[0]) / c;
  const double t_back = (2 * FL_L - FL_CREST - fl_gauge_x[0]) / c;
  double tv[FL_GAUGES], tu[FL_GAUGES], av[FL_GAUGES], au[FL_GAUGES], sv[FL_GAUGES], su[FL_GAUGES];
  for (int g = 0; g < 3; g++) {
    const double tg = (fl_gauge_x[g] - FL_CREST) / c;
    av[g] = crest_of(&rv, g, tg - 0.4, tg + 0.4, &tv[g]);
    au[g] = crest_of(&ru, g, tg - 0.4, tg + 0.4, &tu[g]);
    sv[g] = crest_smooth(&rv, g, tg - 0.4, tg + 0.4, &tv[g]);
    su[g] = crest_smooth(&ru, g, tg - 0.4, tg + 0.4, &tu[g]);
    printf("G%d x = %.2f m: crest (smoothed) vres %.5f m at %.4f s, uniform fine %.5f m at %.4f s "
           "(%+.2f %% of H; top sample %+.2f %%)\n", g + 1, fl_gauge_x[g], sv[g], tv[g], su[g],
           tu[g], 100 * (sv[g] - su[g]) / H, 100 * (av[g] - au[g]) / H);
  }
  /* The interface's reflection: what the coupled run adds at G1 to the
   * level G1 stands in. G1 is in the coarse level, whose own trailing tail
   * (the wave's dispersive tail and the start's waves, at the coarse
   * spacing) reads 1.4-2.3 % of H above the fine run's in this window
   * (2026-11-29: 0.0039-0.0046 m against 0.0028-0.0031 m), more than the
   * bar: so the reference is the uniform run at the coarse spacing, and
   * with one level (ratio 1) the uniform run. */
  const double rv_if = abs_max_of(&rv, 0, t_g1 + 0.6, t_back - 0.5);
  const double ru_if = abs_max_of(&ru, 0, t_g1 + 0.6, t_back - 0.5);
  const double rl_if = ratio > 1 ? abs_max_of(&rc, 0, t_g1 + 0.6, t_back - 0.5) : ru_if;
  printf("G1 between the incident and the wall's reflection (t %.2f-%.2f s, the interface's "
         "reflection at %.2f s): largest |eta| vres %.5f m, uniform at G1's spacing %.5f m "
         "(uniform fine %.5f m)\n", t_g1 + 0.6, t_back - 0.5, t_if, rv_if, rl_if, ru_if);
  double tbv, tbu;
  const double bv = crest_smooth(&rv, 0, t_back - 0.4, g_t_end, &tbv);
  const double bu = crest_smooth(&ru, 0, t_back - 0.4, g_t_end, &tbu);
  printf("G1 reflected crest back across (smoothed): vres %.5f m at %.4f s, uniform fine %.5f m at "
         "%.4f s (%+.2f %% of H)\n", bv, tbv, bu, tbu, 100 * (bv - bu) / H);
  /* celerity from the front face's H/2 crossings at G2 and G3 */
  const double t2 = (fl_gauge_x[1] - FL_CREST) / c - 0.6, t3 = (fl_gauge_x[2] - FL_CREST) / c - 0.6;
  const double cv = (fl_gauge_x[2] - fl_gauge_x[1]) /
                    (front_time(&rv, 2, t3, 0.5 * H) - front_time(&rv, 1, t2, 0.5 * H));
  const double cu = (fl_gauge_x[2] - fl_gauge_x[1]) /
                    (front_time(&ru, 2, t3, 0.5 * H) - front_time(&ru, 1, t2, 0.5 * H));
  printf("celerity G2-G3 (front face at H/2): vres %.4f m/s, uniform fine %.4f m/s, theory "
         "sqrt(g (h + H)) %.4f m/s\n", cv, cu, c);
  d[SOL_G2] = sv[1] - su[1];
  d[SOL_G3] = sv[2] - su[2];
  d[SOL_REFL] = rv_if - rl_if;
  d[SOL_CEL] = cv / cu - 1;
  d[SOL_BACK] = bv - bu;
  return 0;
}

/* Realisations of the solitary mode (realisations() above): the same wave
 * started 0, 0.3, 0.6, ... fine spacings further along, each in
 * the coupled flume and in its own uniform fine run. One pair of runs is
 * one draw of the start's acoustic noise: the uniform fine run's own G2
 * crest moved by 2.5 % of H between starts 3 mm apart (2026-11-29,
 * docs/history/2026-11-29-vres-band-spacing.md), more than issue 19's 1 %
 * bars; the checks read the mean over the realisations of each
 * realisation's difference, and print the spread. */
static int solitary(double eps, double ratio) {
  const double H = eps * FL_H, dpf = FL_H / g_fine_rows;
  const int n = realisations();
  double d[REALISATIONS_MAX][SOL_N], mean[SOL_N] = {0}, sd[SOL_N] = {0};
  for (int r = 0; r < n; r++) {
    g_crest_dx = realisation_offset(dpf, r);
    printf("realisation %d: initial crest at %.4f m\n", r + 1, FL_CREST + g_crest_dx);
    if (solitary_once(eps, ratio, d[r])) return 1;
    for (int k = 0; k < SOL_N; k++) mean[k] += d[r][k] / n;
  }
  g_crest_dx = 0;
  for (int r = 0; r < n; r++)
    for (int k = 0; k < SOL_N; k++) sd[k] += (d[r][k] - mean[k]) * (d[r][k] - mean[k]);
  for (int k = 0; k < SOL_N; k++) sd[k] = n > 1 ? sqrt(sd[k] / (n - 1)) : 0;
  static const char *const name[SOL_N] = {"G2 crest", "G3 crest", "interface's reflection",
                                          "celerity", "return (G1 crest back across)"};
  for (int k = 0; k < SOL_N; k++) {
    const double u = k == SOL_CEL ? 100 : 100 / H; /* % (celerity), % of H (the rest) */
    printf("mean of %d: %s %+.2f %s (standard deviation %.2f; each", n, name[k], mean[k] * u,
           k == SOL_CEL ? "%" : "% of H", sd[k] * u);
    for (int r = 0; r < n; r++) printf(" %+.2f", d[r][k] * u);
    printf(")\n");
  }
  CHECK_ABS(mean[SOL_G2], 0, 0.01 * H, "crest at G2, across coarse to fine, within 1 % of H of "
            "the uniform fine run (issue 19; mean of the realisations)");
  CHECK_ABS(mean[SOL_G3], 0, 0.01 * H, "crest at G3 within 1 % of H of the uniform fine run "
            "(issue 19; mean)");
  CHECK_ABS(mean[SOL_REFL], 0, 0.01 * H, "reflection from the interface below 1 % of H (issue 19; "
            "mean)");
  CHECK_ABS(mean[SOL_CEL], 0, 0.01, "celerity in the fine level within 1 % of the uniform fine "
            "run's (issue 19; mean)");
  CHECK_ABS(mean[SOL_BACK], 0, 0.01 * H, "reflected crest back across fine to coarse within 1 % "
            "of H (issue 19; mean)");
  return 0;
}

/* The suite's crossing: H/h = 0.4 at coarse dp 0.04 / fine 0.02 m (H/dp 2
 * and 4) until its crest is 0.5 m past the interface: the creation path
 * runs (the wave carries its volume, some 150 fine particles, across), the
 * run stays stable, and the levels' own mass stays within 1 % of the start
 * (creation follows the mass flux; a rule that also filled every gap
 * created 2-2.5 % too much, docs/history); with either integrator. */
static int crossing(void) {
  double drift = NAN;
  long created = 0;
  const double t_end = (FL_X_IF + 0.5 - FL_CREST) / sqrt(9.81 * FL_H * 1.4);
  for (g_verlet = 0; g_verlet <= 1; g_verlet++) {
    printf("%s integrator\n", g_verlet ? "Verlet" : "symplectic");
    const int st = flume_run(0.4, 0.04, 0.02, t_end, NULL, &drift, &created);
    CHECK_TRUE(st == 0, "a solitary wave across the interface without a guard fault");
    CHECK_TRUE(created > 50, "the fine level created the water the wave carried in");
    CHECK_ABS(drift, 0, 0.01, "own mass within 1 % (creation follows the mass flux)");
  }
  g_verlet = 0;
  return 0;
}

/* The coupled flume's state after 0.05 s (about 100 steps; the wave's crest
 * 0.3 m from the interface, its front across the bands) on 1 and on 2 threads:
 * the same bits (the fits run side by side, their use in particle order;
 * the CPU backend's steps are thread-count independent, test_sph_threads);
 * with the buffers shifted along the interface, and across it too. */
static int threads_same_with(int across) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wave_ic w;
  memset(&w, 0, sizeof w);
  w.crest = FL_X_IF - 0.3;
  w.depth = FL_H;
  if (wl_waves_solitary_init(&w.sw, WL_SOLITARY_GRIMSHAW, FL_H, 0.4 * FL_H, 9.81, &err)) return 1;
  double *state[2] = {NULL, NULL};
  size_t len[2] = {0, 0};
  for (int run = 0; run < 2; run++) {
    g_threads = run + 1;
    struct wl_vres_opts o = {0};
    o.z_bed = 0;
    o.z_top = FL_H * 1.8;
    o.shift = VRES_SHIFT;
    o.shift_across = across;
    struct wl_vres *v;
    if (coupled(&flume, 0.04, 0.02, FL_X_IF, &w, &o, 600, &v)) return 1;
    enum wl_status st = WL_OK;
    while (st == WL_OK && wl_vres_time(v) < 0.05) st = wl_vres_step(v, 0.05 - wl_vres_time(v), &err);
    CHECK_TRUE(st == WL_OK, "the coupled flume runs on 1 and 2 threads");
    size_t n = 0;
    for (int l = 0; l < 2; l++) n += 5 * (size_t)wl_sph_sim_particles(wl_vres_level(v, l), &err)->n;
    state[run] = malloc(sizeof(double) * n);
    len[run] = n;
    size_t q = 0;
    for (int l = 0; l < 2 && state[run]; l++) {
      const struct wl_particles *p = wl_sph_sim_particles(wl_vres_level(v, l), &err);
      for (int i = 0; i < p->n; i++) {
        state[run][q++] = p->pos[0][i];
        state[run][q++] = p->pos[1][i];
        state[run][q++] = (double)p->vel[0][i];
        state[run][q++] = (double)p->vel[1][i];
        state[run][q++] = (double)p->rho[i];
      }
    }
    wl_vres_free(v);
  }
  g_threads = 0;
  CHECK_TRUE(state[0] && state[1] && len[0] == len[1] &&
                 !memcmp(state[0], state[1], sizeof(double) * len[0]),
             across ? "1 and 2 threads, buffers shifted across too: the same particles, positions, "
                      "velocities and densities, bit for bit"
                    : "1 and 2 threads: the same particles, positions, velocities and densities, "
                      "bit for bit");
  free(state[0]);
  free(state[1]);
  return 0;
}

static int threads_same(void) { return threads_same_with(0) || threads_same_with(1); }

int main(int argc, char **argv) {
  const char *mode = argc > 1 ? argv[1] : "suite";
  g_verlet = getenv("WL_VRES_VERLET") && atoi(getenv("WL_VRES_VERLET")) > 0;
  if (getenv("WL_VRES_T_END") && atof(getenv("WL_VRES_T_END")) > 0) {
    g_t_end = atof(getenv("WL_VRES_T_END"));
    g_t_end_given = 1;
  }
  if (!strcmp(mode, "quick")) {
    if (fit() || layout() || still(2, 0) || threads_same()) return 1;
  } else if (!strcmp(mode, "suite")) {
    if (fit() || layout() || crossing()) return 1;
  } else if (!strcmp(mode, "still")) {
    if (still(20, 1)) return 1;
  } else if (!strcmp(mode, "refs")) { /* the uniform references into WL_VRES_REF_DIR */
    const double eps = argc > 2 ? atof(argv[2]) : 0.4, ratio = argc > 3 ? atof(argv[3]) : 2;
    if (argc > 4) g_fine_rows = atof(argv[4]);
    t_end_for(eps);
    static struct record r;
    const double dps[2] = {FL_H / g_fine_rows, ratio * FL_H / g_fine_rows};
    for (int k = 0; k < realisations(); k++) { /* the solitary mode's realisations' starts */
      g_crest_dx = realisation_offset(dps[0], k);
      for (int q = 0; q < (ratio > 1 ? 2 : 1); q++) {
        if (flume_run(eps, dps[q], 0, g_t_end, &r, NULL, NULL)) return 1;
        ref_save(&r, eps, dps[q]);
      }
    }
    return 0;
  } else if (!strcmp(mode, "solitary")) {
    const double eps = argc > 2 ? atof(argv[2]) : 0.4, ratio = argc > 3 ? atof(argv[3]) : 2;
    if (argc > 4) g_buffer_h = atof(argv[4]);
    if (argc > 5) g_shift = atof(argv[5]);
    if (argc > 6) g_overlap = atof(argv[6]);
    if (argc > 7) g_fine_rows = atof(argv[7]);
    t_end_for(eps);
    if (solitary(eps, ratio)) return 1;
  } else {
    printf("unknown mode %s (quick, suite, still, refs [H/h [dp ratio [fine rows]]], solitary "
           "[H/h [dp ratio [buffer/h [shift A [overlap/band [fine rows]]]]]])\n", mode);
    return 2;
  }
  return TEST_RESULT();
}
