/* test_scene_layout.c: still water laid over a bed holds the water a level
 * surface holds, in deep and in shallow parts alike (wl_scene_fluid_surface).
 *
 * The reference is the closed-form hydrostatic column of the Tait equation of
 * state (gamma = 7, the solver's): with p = g M, M the mass per unit area
 * above a point, and rho = rho0 (1 + p/B)^(1/7), a column of depth D whose
 * surface is level holds
 *   M(D) = (B/g) [(1 + 6 g rho0 D / (7 B))^(7/6) - 1],
 * from dD = dM / rho(g M). Inverting it gives the depth D(M) that a region's
 * particle mass fills. Weakly compressible water is denser at depth, so a
 * deep column holds about g D^2/(2 c0^2) of extra water (1.6 mm in 0.36 m at
 * c0 = 20 m/s) that a shallow one does not: laid as D/dp particles per
 * column, the deep part of seawall.yaml's flume stood 1.6 mm lower than its
 * 0.06 m platform, which then drained into it (history
 * 2026-11-28-slope-current.md, "The level").
 *
 * The flume: a flat bed (0-3 m), a 1:5.7 slope up 0.3 m, a platform
 * (4.71-6 m); still water 0.36 m above the flat bed; dp = 0.01 m. Checked:
 *  - every column of the flat part and of the platform, as the level its
 *    mass (over its width, half-way to its neighbours) fills by D(M),
 *    within 1 % of a spacing of the still-water level; columns a spacing
 *    wide miss it by the compression (the printout gives both: 1.75 and
 *    0.05 mm here);
 *  - every column of a part holds the same number of particles, so the
 *    surface is level (no column a particle higher than its neighbours);
 *  - a solitary wave (H = 6 dp) laid over a flat bed holds the closed-form
 *    column's mass under its surface, integrated along the flume, within
 *    0.3 %: rounding each column's count alone left its tails under dp/2
 *    unlaid, 2.6 % of the wave. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "testutil.h"
#include "wallload/scene.h"
#include "wallload/sph.h"

#define DEPTH 0.36 /* whole rows of DP over both parts */
#define DP 0.01
#define RISE 0.3

static double still_eta(double x, void *user) {
  (void)x;
  (void)user;
  return DEPTH;
}

/* The solitary wave of the last check: H = dp * 6 on DEPTH, its crest
 * mid-flume, sech^2 (K (x - x_c)) with K = sqrt(3 H / (4 D^3)); the flume
 * holds it to 1e-6 of H at either end. */
#define WAVE_H 0.06
#define WAVE_FLUME 16.0

static double wave_eta(double x, void *user) {
  (void)user;
  const double K = sqrt(3.0 * WAVE_H / (4.0 * DEPTH * DEPTH * DEPTH));
  const double s = 1.0 / cosh(K * (x - 0.5 * WAVE_FLUME));
  return DEPTH + WAVE_H * s * s;
}

/* Closed-form mass per unit area of a level column of depth D (header). */
static double mass_of_depth(double D, double rho0, double B, double g) {
  return B / g * (pow(1.0 + 6.0 * g * rho0 * D / (7.0 * B), 7.0 / 6.0) - 1.0);
}

/* Closed-form depth filled by mass M per unit area (header). */
static double depth_of_mass(double M, double rho0, double B, double g) {
  return 7.0 * B / (6.0 * g * rho0) * (pow(1.0 + g * M / B, 6.0 / 7.0) - 1.0);
}

int main(void) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, 2, DP, DEPTH);
  struct wl_sph_const k;
  if (wl_sph_const_make(&cfg.prm, &k, &err) != WL_OK) {
    printf("FAIL %s\n", err.msg);
    return 1;
  }
  const double g = -(double)k.gravity[1], rho0 = (double)k.rho0, B = (double)k.B;
  const double x_toe = 3.0, x_top = x_toe + 5.7 * RISE, x_end = 6.0;
  const double bx[4] = {0.0, x_toe, x_top, x_end}, bz[4] = {0.0, 0.0, RISE, RISE};
  struct wl_scene sc;
  wl_scene_init(&sc, &k, 0, 0);
  if (wl_scene_fluid_surface(&sc, 0.0, x_end, bx, bz, 4, DEPTH, still_eta, NULL, &err)) {
    printf("FAIL scene: %s\n", err.msg);
    return 1;
  }
  const int n = sc.n[1];
  const double *pos = sc.pos[1];
  /* the columns: particles sharing an x, in order of x */
  double *xs = malloc(sizeof(double) * (size_t)n);
  int *count = calloc((size_t)n, sizeof *count);
  if (!xs || !count) return 1;
  int n_col = 0;
  for (int i = 0; i < n; i++) {
    int c = n_col - 1;
    while (c >= 0 && fabs(xs[c] - pos[2 * i]) > 1e-9) c--; /* particles come column by column */
    if (c < 0) xs[c = n_col++] = pos[2 * i];
    count[c]++;
  }
  for (int i = 1; i < n_col; i++) /* insertion sort by x, counts along */
    for (int j = i; j > 0 && xs[j] < xs[j - 1]; j--) {
      const double tx = xs[j]; xs[j] = xs[j - 1]; xs[j - 1] = tx;
      const int tc = count[j]; count[j] = count[j - 1]; count[j - 1] = tc;
    }
  const double m = rho0 * DP * DP; /* a particle's mass per unit width */
  const struct {
    const char *name;
    double x0, x1, bed;
  } part[2] = {{"flat bed", 0.05, x_toe - 0.05, 0.0}, {"platform", x_top + 0.05, x_end - 0.05, RISE}};
  for (int r = 0; r < 2; r++) {
    int cols = 0, same = 1;
    double worst = 0.0;
    for (int c = 1; c + 1 < n_col; c++) {
      if (xs[c] < part[r].x0 || xs[c] > part[r].x1) continue;
      /* the column's width: half-way to its neighbours */
      const double width = 0.5 * (xs[c + 1] - xs[c - 1]);
      const double level = part[r].bed + depth_of_mass(count[c] * m / width, rho0, B, g);
      if (fabs(level - DEPTH) > worst) worst = fabs(level - DEPTH);
      if (cols && count[c] != count[c - 1]) same = 0;
      cols++;
    }
    printf("%s: %d columns, the level their mass fills off still water by at most %.3g m "
           "(laid a spacing wide: %.3g m)\n",
           part[r].name, cols, worst,
           DEPTH - part[r].bed - depth_of_mass((DEPTH - part[r].bed) * rho0, rho0, B, g));
    CHECK_TRUE(cols > 50, "the part has columns");
    CHECK_ABS(worst, 0.0, 0.01 * DP,
              "every column's mass fills the closed-form Tait column to still water's level "
              "(within 1 % of a spacing)");
    CHECK_TRUE(same, "every column of the part holds the same number of particles (a level top)");
  }
  free(xs);
  free(count);
  wl_scene_clear(&sc);

  /* A solitary wave over the flat bed: the water it adds to still water. */
  const double bxf[2] = {0.0, WAVE_FLUME}, bzf[2] = {0.0, 0.0};
  double still_mass = 0, wave_mass = 0;
  for (int pass = 0; pass < 2; pass++) {
    wl_scene_init(&sc, &k, 0, 0);
    if (wl_scene_fluid_surface(&sc, 0.0, WAVE_FLUME, bxf, bzf, 2, DEPTH,
                               pass ? wave_eta : still_eta, NULL, &err)) {
      printf("FAIL scene: %s\n", err.msg);
      return 1;
    }
    (pass ? &wave_mass : &still_mass)[0] = sc.n[1] * m;
    wl_scene_clear(&sc);
  }
  /* the closed form: each metre of flume holds M(D + eta) - M(D) more */
  const int n_quad = 200000;
  double excess = 0;
  for (int i = 0; i < n_quad; i++) {
    const double x = (i + 0.5) * WAVE_FLUME / n_quad;
    excess += (mass_of_depth(wave_eta(x, NULL), rho0, B, g) -
               mass_of_depth(DEPTH, rho0, B, g)) * WAVE_FLUME / n_quad;
  }
  printf("solitary wave H = %g m over %g m, dp = %g m: laid %.6g kg/m over still water, "
         "closed form %.6g kg/m (%+.3f %%); rounding each column alone laid 2.6 %% less\n",
         WAVE_H, DEPTH, DP, wave_mass - still_mass, excess,
         100.0 * ((wave_mass - still_mass) / excess - 1.0));
  CHECK_REL(wave_mass - still_mass, excess, 3e-3,
            "the laid wave holds the closed-form wave's water over still water within 0.3 %");
  return wl_test_failures;
}
