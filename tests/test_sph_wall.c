/* test_sph_wall.c: the pressure-extrapolating wall condition (sph/wall.h,
 * Adami, Hu & Adams 2012) against closed forms.
 *
 *  1. The wall particles' Tait density of a pressure, against libm's
 *     pow(1 + p/B, 1/7) (an independent computation of the inverse EOS).
 *  2. A still tank (2D, h = 0.5 m, L = 1 m, dp = h/20), after the initial
 *     force evaluation: each boundary particle below the surface and more
 *     than 2h under it carries the hydrostatic pressure of its own depth,
 *     rho0 g (h - z) (REFERENCES.md 1.1: the condition is first-order exact
 *     for a linear pressure field, so what is left is the fluid's own
 *     departure from hydrostatics); the horizontal force of the fluid on
 *     the left wall's boundary particles, summed pair by pair with the
 *     solver's own momentum term (as assess's boundary force does), is
 *     rho0 g h^2 / 2 within 0.5 % (issue 17); the bed carries rho0 g h over
 *     the tank's length within 0.5 %.
 *  3. The same with the 3D solver (a tank 0.3 m deep, dp = h/10): the wall
 *     pressures of the floor.
 * The dynamic boundary condition is run beside it and its numbers are
 * printed, not judged (it misses the force by several per cent: the gap
 * it opens between fluid and wall). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/plan.h"
#include "wallload/scene.h"
#include "wallload/sph.h"
#include "wallload/sph/interact.h"
#include "wallload/sph/wall.h"

#define G 9.81

static void check_inverse_eos(void) {
  struct wl_sph_params prm;
  wl_sph_params_default(&prm, 2, 0.01, 0.5);
  struct wl_sph_const k;
  struct wl_error err;
  wl_error_clear(&err);
  if (wl_sph_const_make(&prm, &k, &err)) {
    printf("FAIL constants: %s\n", err.msg);
    wl_test_failures++;
    return;
  }
  double worst = 0;
  for (int i = 0; i <= 200; i++) {
    const double p = (double)k.B * i / 100.0; /* 0 .. 2 B: impacts of 2 B are extreme */
    const double want = (double)k.rho0 * pow(1.0 + p / (double)k.B, 1.0 / 7.0);
    const double got = wl_sph_eos_rho_of_p_fast(&k, (wl_real)p);
    worst = fmax(worst, fabs(got - want) / want);
  }
  CHECK_ABS(worst, 0.0, 2e-6, "inverse Tait EOS vs pow(1 + p/B, 1/7) for 0 <= p <= 2B");
}

/* Horizontal force [N/m or N] of the fluid on the boundary particles with
 * x < x_wall (the left wall) and the vertical force on those with z < 0
 * (the bed; 2D: z is axis 1), pair by pair with the solver's momentum term. */
static void wall_forces(const struct wl_particles *p, const struct wl_sph_const *k, double *fx_left,
                        double *fz_bed) {
  const int az = p->dim - 1;
  const int laminar = k->visc == WL_SPH_VISC_LAMINAR;
  double fx = 0, fz = 0;
  for (int j = 0; j < p->n_bound; j++) {
    const int left = p->pos[0][j] < 0, bed = p->pos[az][j] < 0;
    if (!left && !bed) continue;
    const wl_real rho_j = p->rho[j], p_j = wl_sph_eos_p(k, rho_j);
    wl_real inv_rho_j, vol_j;
    wl_sph_pair_j_bound(k, rho_j, &inv_rho_j, &vol_j);
    for (int i = p->n_bound; i < p->n; i++) {
      wl_real d[3] = {0, 0, 0}, r2 = 0;
      for (int a = 0; a < p->dim; a++) {
        d[a] = (wl_real)(p->pos[a][i] - p->pos[a][j]);
        r2 += d[a] * d[a];
      }
      if (r2 >= k->support2) continue;
      const wl_real rho_i = p->rho[i], p_i = wl_sph_pair_p_wall(k, wl_sph_eos_p(k, rho_i));
      const struct wl_sph_pair o =
          laminar ? wl_sph_pair_eval(1, 0, k, r2, 0, d[az], rho_i, 1 / rho_i, p_i, rho_j,
                                     inv_rho_j, vol_j, p_j, 0, k->lam_fb)
                  : wl_sph_pair_eval(0, 0, k, r2, 0, d[az], rho_i, 1 / rho_i, p_i, rho_j,
                                     inv_rho_j, vol_j, p_j, k->av_fb, 0);
      /* at rest: the pair force on the fluid is m c_r r_ij; the wall gets minus it */
      if (left) fx -= (double)k->mass * o.c_r * d[0];
      if (bed) fz -= (double)k->mass * o.c_r * d[az];
    }
  }
  *fx_left = fx;
  *fz_bed = fz;
}

/* Pressure [Pa] at height z [m] above the bed of a still Tait column whose
 * mass is rho0 h_eff per unit area (the scene stacks the fluid so, sph.h):
 * dp/dz = -rho(p) g with rho = rho0 (1 + p/B)^(1/7) integrates to
 * (1 + p/B)^(6/7) = (1 + p_bed/B)^(6/7) - 6 rho0 g z / (7 B), p_bed =
 * rho0 g h_eff. The column is shorter than h_eff by its compression (2.5 mm
 * for h = 0.5 m at coefsound 10), so rho0 g (h_eff - z) would overstate the
 * pressure near the surface by about rho0 g times that. */
static double tait_column_p(const struct wl_sph_const *k, double h_eff, double z) {
  const double B = k->c0_d * k->c0_d * k->rho0 / 7.0, rho0 = k->rho0;
  const double top = pow(1.0 + rho0 * G * h_eff / B, 6.0 / 7.0) - 6.0 * rho0 * G * z / (7.0 * B);
  return top > 1.0 ? B * (pow(top, 7.0 / 6.0) - 1.0) : 0.0;
}

/* A still tank L x h (2D) or L x W x h (3D) at dp, wall condition `bc`;
 * after the initial evaluation: the largest relative error of the deep wall
 * particles' pressures, the left wall's force and the bed's. */
static int still_tank(int dim, int bc, double L, double h, double dp, double *p_err,
                      double *f_left, double *f_bed, double *f_left_ref, double *f_bed_ref) {
  struct wl_sph_config cfg;
  struct wl_error err;
  wl_error_clear(&err);
  wl_sph_config_default(&cfg, dim, dp, h);
  wl_plan_default_numerics(&cfg.prm);
  cfg.prm.boundary = bc;
  struct wl_sph_const k;
  if (wl_sph_const_make(&cfg.prm, &k, &err)) return printf("FAIL %s\n", err.msg), 1;
  const double W = 4 * dp, m = 5 * dp;
  const int az = dim - 1;
  cfg.lo[0] = -m, cfg.hi[0] = L + m;
  cfg.lo[az] = -m, cfg.hi[az] = 1.5 * h + 2 * m;
  if (dim == 3) cfg.lo[1] = -m, cfg.hi[1] = W + m;
  struct wl_scene sc;
  wl_scene_init(&sc, &k, 0, W);
  enum wl_status st;
  if (dim == 2) {
    const double tx[4] = {0, 0, L, L}, tz[4] = {1.5 * h, 0, 0, 1.5 * h};
    st = wl_scene_boundary_polyline(&sc, tx, tz, 4, 3, WL_KIND_FIXED, 0, &cfg, &err);
  } else {
    const double lo[3] = {0, 0, 0}, hi[3] = {L, W, 1.5 * h};
    st = wl_scene_box3d_tank(&sc, lo, hi, 3, &cfg, &err);
  }
  const double lo[3] = {0, 0, 0}, hi2[2] = {L, h}, hi3[3] = {L, W, h};
  if (!st) st = wl_scene_fluid_block(&sc, lo, dim == 2 ? hi2 : hi3, h, &err);
  if (!st) wl_scene_hydrostatic_boundary(&sc, h);
  struct wl_particles init = {0};
  if (!st) st = wl_scene_build(&sc, &init, &err);
  wl_scene_clear(&sc);
  struct wl_sph_sim *sim = NULL;
  if (!st) st = wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err);
  if (st) {
    printf("FAIL set-up: %s\n", err.msg);
    wl_particles_clear(&init);
    return 1;
  }
  /* the fluid's mass gives the effective depth: h_eff = (m / rho0) / area */
  const double area = dim == 2 ? L : L * W;
  const double h_eff = (init.n - init.n_bound) * pow(dp, dim) / area;
  const struct wl_particles *p = wl_sph_sim_particles(sim, &err);
  const struct wl_sph_const *kk = wl_sph_sim_const(sim);
  double worst = 0;
  for (int j = 0; p && j < p->n_bound; j++) {
    const double z = p->pos[az][j], depth = h_eff - z;
    if (depth < 2 * kk->h_d + 0.5 * dp) continue; /* the surface's kernel truncation */
    int wet = 0; /* a fluid particle within 2h: else the wall particle is not sampled */
    for (int i = p->n_bound; i < p->n && !wet; i++) {
      double r2 = 0;
      for (int a = 0; a < dim; a++) r2 += (p->pos[a][i] - p->pos[a][j]) * (p->pos[a][i] - p->pos[a][j]);
      wet = r2 < 4 * kk->h_d * kk->h_d;
    }
    if (!wet) continue;
    if (dim == 3 && (p->pos[1][j] < 0 || p->pos[1][j] > W)) continue; /* side walls' edges */
    const double want = tait_column_p(kk, h_eff, z);
    const double got = wl_sph_eos_p(kk, p->rho[j]);
    if (fabs(got - want) / want > worst && getenv("WL_TEST_VERBOSE"))
      printf("  wall particle at (%g, %g): p = %g Pa, want %g\n", p->pos[0][j], z, got, want);
    worst = fmax(worst, fabs(got - want) / want);
  }
  *p_err = worst;
  double fx, fz;
  wall_forces(p, kk, &fx, &fz);
  *f_left = -fx; /* the force on the left wall points to -x */
  *f_bed = -fz;
  const double width = dim == 2 ? 1.0 : W;
  /* the end wall carries the integral of the column's pressure (a little
   * below rho0 g h_eff^2 / 2: the column is compressed), by the midpoint
   * rule on 4000 strips */
  double fl_ref = 0;
  for (int s = 0; s < 4000; s++) fl_ref += tait_column_p(kk, h_eff, (s + 0.5) * h_eff / 4000);
  *f_left_ref = fl_ref * h_eff / 4000 * width;
  *f_bed_ref = kk->rho0 * G * h_eff * area;
  wl_sph_sim_free(sim);
  wl_particles_clear(&init);
  return 0;
}

/* The SPH pair force between two half-spaces of a square (cubic) lattice
 * of spacing dp under a uniform pressure p, per unit face area, divided by
 * p: 1 in the continuum (the double integral of grad W across a plane is
 * 1/2, times p_i + p_j = 2p); on the lattice, the kernel's quadrature error
 * at this h/dp (-0.62 % in 2D at h = 1.2 sqrt(2) dp, -0.25 % in 3D at h =
 * sqrt(3) dp). Summed here directly from the Wendland C2 kernel in double,
 * independently of the solver: it is what a wall that continues the fluid's
 * lattice perfectly would give. */
static double lattice_face_factor(int dim, double h_over_dp) {
  const double pi = 3.14159265358979323846, h = h_over_dp;
  const double aD = dim == 2 ? 7.0 / (4.0 * pi * h * h) : 21.0 / (16.0 * pi * h * h * h);
  const int R = (int)ceil(2 * h) + 1;
  double s = 0;
  for (int m = 0; m < R; m++)   /* fluid rows at (m + 1/2) dp above the face */
    for (int w = 0; w < R; w++) /* wall rows at (w + 1/2) dp below it */
      for (int ix = -R; ix <= R; ix++)
        for (int iy = (dim == 3 ? -R : 0); iy <= (dim == 3 ? R : 0); iy++) {
          const double dz = m + w + 1.0, r = sqrt(ix * ix + iy * iy + dz * dz), q = r / h;
          if (q < 2) s += aD * 5.0 * q * pow(1 - q / 2, 3) / h * dz / r;
        }
  return 2.0 * s;
}

int main(void) {
  check_inverse_eos();
  double pe, fl, fb, flr, fbr, fl2, fb2;
  struct wl_sph_params prm;
  wl_sph_params_default(&prm, 2, 1, 1);
  wl_plan_default_numerics(&prm);
  const double lat2 = lattice_face_factor(2, prm.coefh * sqrt(2.0));
  prm.dim = 3;
  wl_plan_default_numerics(&prm);
  const double lat3 = lattice_face_factor(3, prm.coefh * sqrt(3.0));
  printf("INFO lattice face factor: 2D %.5f, 3D %.5f\n", lat2, lat3);
  if (!still_tank(2, WL_SPH_BOUND_ADAMI, 1.0, 0.5, 0.025, &pe, &fl, &fb, &flr, &fbr) &&
      !still_tank(2, WL_SPH_BOUND_ADAMI, 1.0, 0.5, 0.0125, &pe, &fl2, &fb2, &flr, &fbr)) {
    CHECK_ABS(pe, 0.0, 0.001, "2D: wall particles' pressure = the Tait column's (0.1 %)");
    /* the bed carries the weight as a perfect continuation of the lattice
     * would: what is left is the kernel's quadrature, not the wall */
    CHECK_REL(fb2, fbr * lat2, 0.001, "2D: bed force = weight x lattice face factor (0.1 %)");
    /* the end wall: an error at the free surface and the corner that
     * vanishes with dp (beside the lattice factor: -1.6 % at h/dp = 20,
     * -0.5 % at 40); at h/dp = 40 it is within issue 17's 0.5 % */
    const double e1 = fl / (flr * lat2) - 1, e2 = fl2 / (flr * lat2) - 1;
    CHECK_TRUE(fabs(e2) < 0.6 * fabs(e1), "2D: end-wall force error falls with dp (order >= 0.7)");
    CHECK_REL(fl2, flr * lat2, 0.005,
              "2D: end-wall force at h/dp = 40 = integral of p dz x lattice factor (0.5 %)");
    printf("INFO 2D end-wall force %+.2f %% (h/dp = 20), %+.2f %% (40) of the integral of p dz; "
           "bed %+.2f %%, %+.2f %% of the weight\n", 100 * (fl / flr - 1), 100 * (fl2 / flr - 1),
           100 * (fb / fbr - 1), 100 * (fb2 / fbr - 1));
  } else {
    wl_test_failures++;
  }
  if (!still_tank(2, WL_SPH_BOUND_DBC, 1.0, 0.5, 0.025, &pe, &fl, &fb, &flr, &fbr))
    printf("INFO dynamic boundary, 2D: wall pressure error %.2f %%, end-wall force %+.2f %%, bed "
           "%+.2f %% (not judged)\n", 100 * pe, 100 * (fl / flr - 1), 100 * (fb / fbr - 1));
  if (!still_tank(3, WL_SPH_BOUND_ADAMI, 0.3, 0.3, 0.03, &pe, &fl, &fb, &flr, &fbr)) {
    CHECK_ABS(pe, 0.0, 0.001, "3D: wall particles' pressure = the Tait column's (0.1 %)");
    CHECK_REL(fb, fbr * lat3, 0.001, "3D: floor force = weight x lattice face factor (0.1 %)");
    CHECK_REL(fb, fbr, 0.005, "3D: floor force = weight (issue 17: 0.5 %)");
    printf("INFO 3D end-wall force %+.2f %% of the integral of p dz\n", 100 * (fl / flr - 1));
  } else {
    wl_test_failures++;
  }
  return TEST_RESULT();
}
