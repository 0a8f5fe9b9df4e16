/* test_validate.c: the validate module's arithmetic, against closed forms
 * (no simulation; the runs themselves are tests/cli_validate.sh):
 *  - observed order and Richardson extrapolation (Roache 1998) on
 *    manufactured sequences q_k = q_inf + C (r^-k dp)^p: p and q_inf exact;
 *    non-monotone and out-of-range orders refused;
 *  - case selection: exact names, the 'solitary' group (not solitary_wall),
 *    an unknown name is WL_EINPUT naming the valid cases;
 *  - the running mean and first-crossing helpers on closed forms;
 *  - the crest estimator (wl_val_crest_fit) on a sech^2 crest: within its
 *    small bias (-0.04 % by the omitted term, 0.1 % allowed) without noise,
 *    and on the exact solitary waves H/h = 0.1 and 0.6 within 0.2 %; with a particle-scale noise of
 *    +-4 % of the height it stays within 1 % where the highest sample
 *    reads the noise's excursion high;
 *  - the celerity's crest time (wl_val_crest_centroid_time): the sech^2
 *    crest's time within dt/20, NaN where the record cuts its window;
 *  - spheric2 (SPHERIC Test 2, reference/spheric2/README.md) without its 4 s
 *    of 3D: the layout against the shared data README's numbers (tank,
 *    water, box, P1-P4 half a spacing off the box face, H1-H4); the built
 *    case at dp = 0.05 m (particle counts, nothing inside the box or behind
 *    a wall, the Mach rule's c0 = 20 sqrt(g H), h = sqrt(3) dp, the wall
 *    condition), its sensors at t = 0 (dry box face, H4 = 0.55 m, the
 *    reservoir's pressure rho g (H - z), REFERENCES 1.1); the experiment's
 *    table read with its pre-impact offsets and its metrics (arrival,
 *    plateau, 5 ms running-mean peak) against an independent computation
 *    from the shared file (Python, 2026-11-25). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../src/validate/internal.h" /* spheric2's layout, builder, data and metrics */
#include "testutil.h"
#include "wallload/loads.h"
#include "wallload/sph.h"
#include "wallload/validate.h"
#include "wallload/waves.h"

#define G 9.81

/* The running mean and the crossing on closed forms. */
static void series_helpers(void) {
  enum { N = 101 };
  double t[N], y[N], out[N];
  for (int i = 0; i < N; i++) t[i] = 0.001 * i, y[i] = 3.0 + 2.0 * t[i];
  wl_val_running_mean(t, y, N, 1, 0.005, out);
  CHECK_ABS(out[50], y[50], 1e-12, "running mean of a line = the line (interior)");
  CHECK_ABS(out[0], 3.0 + 2.0 * 0.001, 1e-12, "running mean at the start: samples 0..2");
  for (int i = 0; i < N; i++) y[i] = i >= 50 ? 1.0 : 0.0; /* a step at t = 0.05 s */
  wl_val_running_mean(t, y, N, 1, 0.005, out);
  CHECK_ABS(out[49], 2.0 / 5.0, 1e-12, "5 ms running mean of a step, 1 ms before it: 2 of 5");
  CHECK_ABS(out[50], 3.0 / 5.0, 1e-12, "... at the step: 3 of 5");
  CHECK_ABS(wl_val_first_above(t, out, N, 1, 0.5), 0.050, 1e-12, "first crossing of 1/2");
  CHECK_TRUE(isnan(wl_val_first_above(t, out, N, 1, 2.0)), "no crossing: NaN");
  CHECK_ABS(wl_val_window_mean(t, y, N, 1, 0.0495, 0.0595), 1.0, 1e-12, "window mean");
}

/* spheric2's layout (shared/validation_data/README.md, spheric_test2_kleefsman). */
/* A solitary crest passing a gauge, eta = H sech^2((t - t0) / T), sampled
 * every dt = T / 16 (validate's 0.01 s on H/h = 0.6's T = 0.17 s; H/h 0.1's
 * T = 0.61 s gives 60 samples a T), plus a deterministic noise of +-noise H
 * (a linear congruential sequence, uniform). */
static void crest_fit(void) {
  enum { N = 400 };
  const double H = 0.03, T = 0.61, t0 = 2.0037, dt = T / 16;
  double t[N], y[N], yn[N];
  unsigned int seed = 12345u;
  double top = -1;
  for (int i = 0; i < N; i++) {
    t[i] = i * dt;
    const double c = cosh((t[i] - t0) / T);
    y[i] = H / (c * c);
    seed = seed * 1103515245u + 12345u;
    const double u = (double)((seed >> 8) & 0xffffu) / 65535.0 * 2.0 - 1.0; /* [-1, 1] */
    yn[i] = y[i] + 0.04 * H * u;
    top = yn[i] > top ? yn[i] : top;
  }
  double tc = 0;
  const double a = wl_val_crest_fit(t, y, N, 1, &tc);
  /* the omitted sixth-order term of sech^2 = 1 - x^2 + (2/3) x^4 - (17/45) x^6
   * over |x| <= asech(sqrt 0.7) = 0.60, projected on the continuous window:
   * -(17/45)(5/231) 0.60^6 = -0.04 % */
  CHECK_REL(a, H, 0.001, "crest fit of a clean sech^2: H within its small bias (0.1 %)");
  CHECK_TRUE(a < H, "... and below it (the omitted term's sign)");
  CHECK_ABS(tc, t0, 0.01 * T, "crest fit's time: the crest's");
  const double an = wl_val_crest_fit(t, yn, N, 1, NULL);
  printf("noisy crest: fit %.5f, highest sample %.5f, H %.5f\n", an, top, H);
  CHECK_REL(an, H, 0.01, "crest fit with +-4 % noise: within 1 % of H");
  CHECK_TRUE(top > 1.02 * H, "the highest noisy sample reads more than 2 % high (what the fit removes)");
  CHECK_TRUE(isnan(wl_val_crest_fit(t, y, 5, 1, NULL)), "fewer than 9 samples over the crest: NaN");
  /* the half-height centroid: the crest's time on the symmetric crest; NaN
   * where the window is cut by the record's start (the wave already over
   * the gauge at t = 0) or its end */
  /* its own error: the window starts and ends on samples, which need not
   * straddle the crest evenly; one edge sample (y = H/2 at most) out of
   * about 21 in the window (y ~ 0.75 H) moves the centroid by up to dt/30 */
  CHECK_ABS(wl_val_crest_centroid_time(t, y, N, 1), t0, dt / 20,
            "half-height centroid of a clean sech^2: the crest's time within dt/20");
  const int k_cut = (int)((t0 - 0.5 * T) / dt); /* inside the half-height window */
  CHECK_TRUE(isnan(wl_val_crest_centroid_time(t + k_cut, y + k_cut, N - k_cut, 1)),
             "half-height window cut by the record's start: NaN");
  CHECK_TRUE(isnan(wl_val_crest_centroid_time(t, y, (int)((t0 + 0.5 * T) / dt), 1)),
             "half-height window cut by the record's end: NaN");
  /* the exact (Euler) solitary waves that validate starts (waves.h, checked
   * against REFERENCES 3.4 in test_waves), passing a gauge sampled every
   * 0.01 s as validate samples them: the steepest, H/h = 0.6, has the
   * sharpest crest for its width */
  const double eps[2] = {0.1, 0.6}, hs[2] = {0.3, 0.2};
  for (int e = 0; e < 2; e++) {
    struct wl_solitary sw;
    struct wl_error err;
    wl_error_clear(&err);
    if (wl_waves_solitary_init(&sw, WL_SOLITARY_EXACT, hs[e], eps[e] * hs[e], G, &err)) {
      printf("FAIL exact wave: %s\n", err.msg);
      wl_test_failures++;
      continue;
    }
    const double c = wl_waves_solitary_celerity(&sw);
    for (int i = 0; i < N; i++) {
      t[i] = 0.01 * i;
      y[i] = wl_waves_solitary_eta(&sw, -c * (t[i] - 2.0025));
    }
    CHECK_REL(wl_val_crest_fit(t, y, N, 1, NULL), eps[e] * hs[e], 0.002,
              "crest fit of the exact solitary wave (H/h 0.1, 0.6): H within 0.2 %");
  }
}

static void spheric2_layout(double dp) {
  struct wl_val_s2_geom g;
  wl_val_spheric2_geometry(dp, &g);
  printf("spheric2 layout at dp = %g m\n", dp);
  CHECK_ABS(g.tank_hi[0] - g.tank_lo[0], 3.22, 1e-12, "tank 3.22 m long");
  CHECK_ABS(g.tank_hi[1] - g.tank_lo[1], 1.0, 1e-12, "tank 1 m wide");
  CHECK_ABS(g.tank_hi[2] - g.tank_lo[2], 1.0, 1e-12, "tank 1 m high");
  CHECK_ABS(g.water_hi[0], 3.22, 1e-12, "water against the far end wall");
  CHECK_ABS(g.water_hi[0] - g.water_lo[0], 1.228, 0.5 * dp + 1e-12, "water 1.228 m long (whole rows)");
  CHECK_ABS(g.water_hi[1] - g.water_lo[1], 1.0, 0.5 * dp + 1e-12, "water across the tank");
  CHECK_ABS(0.5 * (g.water_lo[1] + g.water_hi[1]), 0.5, 1e-12, "water centred in y");
  CHECK_ABS(g.water_hi[2], 0.55, 0.5 * dp + 1e-12, "water 0.55 m deep (whole rows)");
  CHECK_ABS(g.box_lo[0], 0.6635, 1e-12, "box from x = 0.6635 m");
  CHECK_ABS(g.box_hi[0], 0.8245, 1e-12, "box to x = 0.8245 m");
  CHECK_ABS(g.box_hi[1] - g.box_lo[1], 0.403, 1e-12, "box 0.403 m wide");
  CHECK_ABS(0.5 * (g.box_lo[1] + g.box_hi[1]), 0.5, 1e-12, "box centred in y");
  CHECK_ABS(g.box_hi[2] - g.box_lo[2], 0.161, 1e-12, "box 0.161 m high, on the floor");
  /* the gauge between the gate and the box at 1.488 m, not the shared
   * README's 1.638 m: src/validate/spheric2.c says why */
  const double pz[4] = {0.021, 0.061, 0.101, 0.141}, hx[4] = {0.496, 0.992, 1.488, 2.638};
  for (int i = 0; i < 4; i++) {
    CHECK_ABS(g.probe[i][0], 0.8245 + 0.5 * dp, 1e-12, "P on the face towards the water, dp/2 off");
    CHECK_ABS(g.probe[i][1], 0.5, 1e-12, "P at the box's centre line (assumed)");
    CHECK_ABS(g.probe[i][2], pz[i], 1e-12, "P1-P4 at z = 0.021, 0.061, 0.101, 0.141 m");
    CHECK_ABS(g.gauge[i][0], hx[i], 1e-12, "gauges at x = 0.496, 0.992, 1.488, 2.638 m");
    CHECK_ABS(g.gauge[i][1], 0.5, 1e-12, "H at the centre line");
    CHECK_TRUE(g.gauge_col[i] == (i == 0 ? 3 : i == 2 ? 1 : i + 1), "data columns H3, H2, H1, H4");
  }
}

/* The case built at dp = 0.05 m, its sensors read at t = 0. */
static void spheric2_built(void) {
  const double dp = 0.05;
  struct wl_sph_config cfg;
  struct wl_particles p = {0};
  struct wl_error err;
  wl_error_clear(&err);
  enum wl_status st = wl_val_spheric2_build(dp, NULL, &cfg, &p, &err);
  CHECK_TRUE(st == WL_OK, "spheric2 builds at dp = 0.05 m");
  if (st) {
    printf("%s\n", err.msg);
    return;
  }
  struct wl_sph_const k;
  CHECK_TRUE(wl_sph_const_make(&cfg.prm, &k, &err) == WL_OK, "constants");
  CHECK_REL(k.c0_d, 20 * sqrt(G * 0.55), 1e-6, "Mach rule: c0 = 10 x 2 sqrt(g H) (sph/params.h)");
  CHECK_REL(k.h_d, sqrt(3.0) * dp, 1e-6, "default numerics in 3D: h = sqrt(3) dp (plan.h)");
  CHECK_TRUE(cfg.prm.boundary == WL_SPH_BOUND_ADAMI, "the wall condition (the default)");
  CHECK_TRUE(cfg.prm.visc == WL_SPH_VISC_LAMINAR, "laminar viscosity (assess's default)");
  struct wl_val_s2_geom g;
  wl_val_spheric2_geometry(dp, &g);
  const int n_fluid = p.n - p.n_bound;
  CHECK_TRUE(n_fluid == 25 * 20 * 11, "fluid: 25 x 20 x 11 particles (1.25 x 1 x 0.55 m)");
  int in_box = 0, outside = 0, bound_box = 0, fluid_out = 0;
  for (int i = 0; i < p.n; i++) {
    const double x = p.pos[0][i], y = p.pos[1][i], z = p.pos[2][i];
    const int inside_box = x > g.box_lo[0] && x < g.box_hi[0] && y > g.box_lo[1] &&
                           y < g.box_hi[1] && z < g.box_hi[2];
    const int inside_tank = x > 0 && x < 3.22 && y > 0 && y < 1 && z > 0;
    if (i >= p.n_bound) {
      in_box += inside_box;
      outside += !inside_tank;
      fluid_out += x < g.water_lo[0] || z > 0.55 + 0.5 * dp;
    } else {
      bound_box += inside_box;
    }
  }
  CHECK_TRUE(in_box == 0 && outside == 0 && fluid_out == 0,
             "every fluid particle in the water block, none in the box or behind a wall");
  CHECK_TRUE(bound_box >= 3 * 8 * 3, "the box is solid boundary particles (3 x 8 x 3 at dp)");
  struct wl_sph_probe *pr = NULL;
  CHECK_TRUE(wl_sph_probe_alloc(&pr, &cfg, &err) == WL_OK, "probe");
  if (pr && wl_sph_probe_index(pr, &p, &err) == WL_OK) {
    double ps[4], hs[4];
    wl_val_spheric2_sample(pr, dp, ps, hs);
    for (int i = 0; i < 4; i++) CHECK_ABS(ps[i], 0.0, 0.0, "P1-P4 dry at t = 0");
    for (int i = 0; i < 3; i++) CHECK_ABS(hs[i], 0.0, 0.0, "H1-H3 dry at t = 0");
    CHECK_ABS(hs[3], 0.55, 0.5 * dp, "H4 in the reservoir reads its depth, 0.55 m");
    const double q[3] = {2.6, 0.5, 0.2};
    double pq = 0;
    wl_sph_probe_pressure(pr, q, &pq);
    CHECK_REL(pq, 1000 * G * (0.55 - 0.2), 0.01,
              "the sensors' pressure in the reservoir: rho g (H - z) (REFERENCES 1.1)");
  }
  /* the sensors from the particles near them = from all of them: the water
   * moved against the box's face (from x = 1.992 m to 0.8245 m), so P1-P4
   * stand in it (wet) and the gauges all see it */
  for (int i = p.n_bound; i < p.n; i++) p.pos[0][i] -= 1.992 - 0.8245;
  struct wl_particles near = {0};
  struct wl_sph_probe *pr2 = NULL;
  if (pr && wl_sph_probe_alloc(&pr2, &cfg, &err) == WL_OK && wl_sph_probe_index(pr, &p, &err) == WL_OK &&
      wl_val_spheric2_near(dp, &p, 2 * k.h_d, &near, &err) == WL_OK &&
      wl_sph_probe_index(pr2, &near, &err) == WL_OK) {
    double pa[4], ha[4], pb[4], hb[4];
    wl_val_spheric2_sample(pr, dp, pa, ha);
    wl_val_spheric2_sample(pr2, dp, pb, hb);
    int same = 1, wet = 0;
    for (int i = 0; i < 4; i++) {
      same = same && pa[i] == pb[i] && ha[i] == hb[i];
      wet += pa[i] > 0;
    }
    printf("moved water: P1-P4 %g %g %g %g Pa from %d of %d fluid particles\n", pa[0], pa[1], pa[2],
           pa[3], near.n, p.n - p.n_bound);
    CHECK_TRUE(wet == 4 && near.n < (p.n - p.n_bound) / 2,
               "moved water: P1-P4 wet, read from fewer than half the particles");
    CHECK_TRUE(same, "the sensors from the particles near them equal those from all (bitwise)");
  } else {
    CHECK_TRUE(0, "near-particle index");
  }
  wl_sph_probe_free(pr2);
  wl_particles_clear(&near);
  wl_sph_probe_free(pr);
  wl_particles_clear(&p);
}

/* The case's run end to end, cut to 0.01 s at dp = 0.1 m (a few seconds):
 * every metric is filled, the run reaches its end, the water has not
 * reached the box (no arrival: the judged P1 metrics fail), the reservoir
 * gauge reads its depth. */
static void spheric2_short_run(void) {
  int i_s2 = -1;
  for (int i = 0; i < wl_val_n_cases; i++)
    if (!strcmp(wl_val_cases[i].name, "spheric2")) i_s2 = i;
  if (i_s2 < 0) return;
  struct wl_val_case c = wl_val_cases[i_s2];
  c.p[0] = c.p[1] = 0.01;
  struct wl_val_ctx ctx;
  memset(&ctx, 0, sizeof ctx);
  ctx.ref_dir = WL_SOURCE_DIR "/reference";
  ctx.threads = 1;
  ctx.ops = &wl_backend_cpu_ops;
  ctx.backend = "cpu";
  ctx.name = c.name;
  struct wl_validate_level lv;
  memset(&lv, 0, sizeof lv);
  struct wl_error err;
  wl_error_clear(&err);
  enum wl_status st = c.run(&c, &ctx, 0.1, &lv, &err);
  CHECK_TRUE(st == WL_OK && lv.status == WL_OK, "spheric2 runs 0.01 s at dp = 0.1 m");
  if (st) printf("%s\n", err.msg);
  CHECK_ABS(lv.t_reached, 0.01, 1e-9, "to its end time");
  CHECK_TRUE(lv.n_metrics == 19,
             "19 metrics: P1 4 and its wall particles' plateau, P2-P4 6, heights 7, the height "
             "in front of the box over P1's plateau window");
  CHECK_TRUE(lv.n_metrics == 19 && !strcmp(lv.m[18].name, "H x 0.992 (data H2) over P1's plateau window") &&
                 isnan(lv.m[18].tol) && isnan(lv.m[18].value),
             "the height in front of the box over P1's plateau window: reported, NaN after 0.01 s");
  if (lv.n_metrics == 19) {
    /* its reference recomputed from the data file by hand: column H2 (file
     * column 6: t, P1-P4, H1-H4), less its mean before 0.15 s (the dry
     * gauge's offset, reference/spheric2/README.md), averaged over the
     * samples from 0.5 to 1.0 s after P1's arrival (the experiment's 0.3940 s,
     * checked above) */
    FILE *f = fopen(WL_SOURCE_DIR "/reference/spheric2/kleefsman2005_exp.dat", "r");
    double off = 0, sum = 0;
    int n_off = 0, n_win = 0;
    char line[512];
    const double ta = 0.3940334357;
    while (f && fgets(line, sizeof line, f)) {
      double col[9];
      if (line[0] == '#' || sscanf(line, "%lf %lf %lf %lf %lf %lf %lf %lf %lf", &col[0], &col[1],
                                   &col[2], &col[3], &col[4], &col[5], &col[6], &col[7],
                                   &col[8]) != 9)
        continue;
      if (col[0] < 0.15) off += col[6], n_off++;
      if (col[0] >= ta + 0.5 && col[0] <= ta + 1.0) sum += col[6], n_win++;
    }
    if (f) fclose(f);
    const double want = n_off && n_win ? sum / n_win - off / n_off : NAN;
    printf("experiment's H2 over P1's plateau window: %.5f m (by hand %.5f m, %d samples)\n",
           lv.m[18].reference, want, n_win);
    CHECK_ABS(lv.m[18].reference, want, 1e-9,
              "the height's reference: the data's H2 over P1's plateau window, recomputed");
  }
  CHECK_TRUE(lv.n_metrics > 4 && !strcmp(lv.m[4].name, "P1 plateau, wall particles' pressure") &&
                 isnan(lv.m[4].tol),
             "P1's plateau from the wall particles: reported, not judged");
  CHECK_TRUE(lv.n_metrics > 3 && !strcmp(lv.m[0].name, "P1 plateau (0.5-1 s after arrival)") &&
                 lv.m[0].tol == 0.15 && lv.m[1].tol == 0.05 && lv.m[2].tol == 0.30 &&
                 lv.m[3].tol == 1.0,
             "judged: P1 plateau 15 %, arrival 5 %, peak 30 %, tension at most rho g H");
  CHECK_TRUE(lv.n_metrics > 3 && isnan(lv.m[1].value) && !lv.m[1].pass && lv.m[3].pass,
             "no arrival within 0.01 s: P1 arrival NaN and failed; no tension");
  CHECK_REL(lv.m[1].reference, 0.3940334357, 1e-9, "P1 arrival's reference: the experiment's");
}

/* The experiment's table and metrics against an independent computation
 * (Python over ../shared/validation_data/spheric_test2_kleefsman/
 * test_case_2_exp_data.dat: offsets the means before t = 0.35 s (P) and
 * 0.15 s (H1-H3); arrival the centred 5 ms running mean first above rho g
 * H / 4; plateau the raw mean from 0.5 to 1 s after it; peak the running
 * mean's largest before t = 4 s). */
static void spheric2_data(void) {
  struct wl_val_s2_data d;
  struct wl_error err;
  wl_error_clear(&err);
  enum wl_status st = wl_val_spheric2_data(WL_SOURCE_DIR "/reference/spheric2", &d, &err);
  CHECK_TRUE(st == WL_OK, "reference/spheric2/kleefsman2005_exp.dat reads");
  if (st) {
    printf("%s\n", err.msg);
    return;
  }
  CHECK_TRUE(d.p[0].n == 7395 && d.h[3].n == 7395, "7395 rows (the shared file's)");
  const double off[4] = {-27.287619, -7.084952, -50.377333, -22.558286};
  const double arr[4] = {0.3940334357, 0.4110229227, 0.4250173025, 0.4340284437};
  const double pk[4] = {10646.434286, 7884.511619, 6550.897333, 7157.131619};
  const double pl[4] = {2955.325752, 2356.166819, 2751.179600, 2470.558019};
  const double rgh = 1000 * G * 0.55;
  for (int i = 0; i < 4; i++) {
    CHECK_ABS(d.p_offset[i], off[i], 1e-5, "pre-impact offset of P1-P4 (mean before 0.35 s)");
    const double raw0[4] = {-45.9333333333, -29.4, -69.8666666667, -54.6666666667};
    CHECK_ABS(d.p[i].y[0] + d.p_offset[i], raw0[i], 1e-9, "the first sample less its offset");
    int ne = 0;
    while (ne < d.p[i].n && d.p[i].x[ne] <= 4.0) ne++;
    struct wl_val_s2_pmetrics m;
    wl_val_spheric2_pressure_metrics(d.p[i].x, d.p[i].y, ne, 1, rgh, NAN, &m);
    CHECK_ABS(m.arrival, arr[i], 1e-9, "arrival: 5 ms running mean first above rho g H / 4");
    CHECK_ABS(m.peak, pk[i], 1e-3, "peak of the 5 ms running mean");
    CHECK_ABS(m.plateau, pl[i], 1e-3, "plateau: mean 0.5 to 1 s after the arrival");
  }
  /* the gauges at x = 0.496, 0.992, 1.638, 2.638 m read the data's
   * columns H3, H2, H1, H4 (src/validate/spheric2.c says why) */
  const double hoff[4] = {0.00040311, 0.00050356, 0.00018933, 0.0};
  for (int i = 0; i < 4; i++)
    CHECK_ABS(d.h_offset[i], hoff[i], 1e-8, "dry offsets (before 0.15 s) of H3, H2, H1; H4 none");
  CHECK_ABS(wl_val_first_above(d.h[0].x, d.h[0].y, d.h[0].n, 1, 0.055), 0.9380326765, 1e-9,
            "the gauge behind the box (data H3) first above H/10 at 0.938 s");
  CHECK_ABS(wl_val_first_above(d.h[2].x, d.h[2].y, d.h[2].n, 1, 0.055), 0.2600282119, 1e-9,
            "the gauge at 1.488 m (data H1) first above H/10 at 0.260 s, before P1's 0.394 s");
  CHECK_ABS(d.h[3].y[0], 0.5466666667, 1e-10, "H4 keeps its reading (the reservoir's depth)");
  wl_val_spheric2_data_clear(&d);
}

/* validate's order arithmetic is wl_loads_convergence (shared with assess's
 * ladder) at a constant ratio r: levels dp, dp/r, dp/r^2. */
static int order3(double q1, double q2, double q3, double r, double *p, double *q_inf) {
  const double h[3] = {1.0, 1.0 / r, 1.0 / (r * r)}, f[3] = {q1, q2, q3};
  struct wl_loads_convergence c;
  wl_loads_convergence(h, f, 3, &c);
  *p = c.order;
  *q_inf = c.extrapolated;
  return c.order_ok;
}

static void manufactured(double p_true, double q_inf, double C) {
  const double r = sqrt(2.0), dp = 0.02;
  double q[3];
  for (int k = 0; k < 3; k++) q[k] = q_inf + C * pow(dp / pow(r, k), p_true);
  double p, qi;
  int ok = order3(q[0], q[1], q[2], r, &p, &qi);
  CHECK_TRUE(ok == 1, "manufactured sequence: order is meaningful");
  CHECK_ABS(p, p_true, 1e-9, "observed order = the manufactured order (Roache 1998)");
  CHECK_ABS(qi, q_inf, 1e-12, "Richardson extrapolation = the manufactured limit");
}

int main(void) {
  crest_fit();
  manufactured(2.0, 0.0123, 3.0);
  manufactured(1.0, -0.05, -0.8);
  manufactured(0.6, 0.2, 1.5);
  double p, qi;
  CHECK_TRUE(order3(0.10, 0.05, 0.08, sqrt(2.0), &p, &qi) == 0 && isnan(qi),
             "non-monotone differences: no extrapolation");
  CHECK_TRUE(order3(0.10, 0.0999, 0.0998, sqrt(2.0), &p, &qi) == 0 && fabs(p) < 1e-6,
             "order 0 (stagnant error): outside [0.5, 4], no extrapolation");
  CHECK_TRUE(order3(0.1, 0.1, 0.1, sqrt(2.0), &p, &qi) == 0 && isnan(p),
             "equal values: order undefined");

  const int n = wl_validate_n_cases();
  CHECK_TRUE(n >= 7, "at least the seven reference cases of the issue");
  int *sel = calloc((size_t)n, sizeof(int));
  struct wl_error err;
  wl_error_clear(&err);
  CHECK_TRUE(wl_validate_select("solitary", sel, &err) == WL_OK, "the 'solitary' group selects");
  int n_sol = 0, wall = 0;
  for (int i = 0; i < n; i++) {
    if (sel[i] && !strncmp(wl_validate_case_name(i), "solitary-", 9)) n_sol++;
    if (sel[i] && !strcmp(wl_validate_case_name(i), "solitary_wall")) wall = 1;
  }
  CHECK_TRUE(n_sol >= 5 && !wall, "group: the five propagation cases, not solitary_wall");
  memset(sel, 0, sizeof(int) * (size_t)n);
  CHECK_TRUE(wl_validate_select("zhou1999", sel, &err) == WL_OK, "exact name selects");
  CHECK_TRUE(wl_validate_select("nosuch", sel, &err) == WL_EINPUT, "unknown name: WL_EINPUT");
  CHECK_TRUE(strstr(err.msg, "hydrostatic") && strstr(err.msg, "charlesworth"),
             "unknown name: the message lists the valid cases");
  memset(sel, 0, sizeof(int) * (size_t)n);
  CHECK_TRUE(wl_validate_select("spheric2", sel, &err) == WL_OK, "spheric2 is a case");
  int i_s2 = -1;
  for (int i = 0; i < n; i++)
    if (sel[i]) i_s2 = i;
  CHECK_TRUE(i_s2 >= 0 && wl_val_cases[i_s2].quick_levels == 1 && wl_val_cases[i_s2].p[0] == 4.0 &&
                 wl_val_cases[i_s2].p[1] == 4.0,
             "spheric2 runs to 4 s (quick too), its quick ladder one level");
  /* a bad backend is refused before anything runs */
  struct wl_validate_opts o = {0};
  o.backend = "gpu";
  struct wl_validate_result *res = calloc(1, sizeof *res);
  wl_error_clear(&err);
  CHECK_TRUE(res && wl_validate_run(0, &o, res, &err) == WL_EINPUT && strstr(err.msg, "cpu, cuda, auto"),
             "backend 'gpu': WL_EINPUT naming the valid ones");
  free(res);
  free(sel);
  series_helpers();
  spheric2_layout(0.05);
  spheric2_layout(0.55 / 27);
  spheric2_layout(0.55 / 54);
  spheric2_built();
  spheric2_data();
  spheric2_short_run();
  return TEST_RESULT();
}
