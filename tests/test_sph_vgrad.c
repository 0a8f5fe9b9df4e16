/* test_sph_vgrad.c: the residual and the eddy viscosity (sph/vgrad.h).
 *  - the corrected velocity gradient of a linear field v = v0 + G0 x is G0
 *    at every particle of a jittered 2D block, its edges and corners
 *    included (the first-order correction's contract; reference: G0, the
 *    field's own gradient), to float rounding;
 *  - for that field the residual viscosity's pair term is 0 for every pair
 *    (the linear part is all of v_ij), while the same term on the whole
 *    v_ij (G = 0: an artificial viscosity of Monaghan's form) is not;
 *  - a closed still tank (1 m x 0.5 m, dp = 0.05 m, the default numerics
 *    with residual_alpha 0.5, symplectic, CPU) keeps its largest fluid speed
 *    under 1 % of sqrt(g h) over the last 5 sqrt(h/g) of 20 sqrt(h/g)
 *    (issue 17's still-water bar, REFERENCES 1.1: the fluid at rest).
 *    Without it the same tank reads 3.2 % (`wallload validate hydrostatic`,
 *    reference/RESULTS.md);
 *  - the eddy viscosity (numerics.smagorinsky) of that field against its
 *    closed form (C_s dp)^2 |S|, and its pair term against the laminar
 *    term of sph/interact.h at nu = nu_t. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/plan.h"
#include "wallload/scene.h"
#include "wallload/sph.h"
#include "wallload/sph/interact.h"
#include "wallload/sph/vgrad.h"

enum { NX = 16, NZ = 12, N = NX * NZ };
#define DP 0.01

static double jitter(int i, int axis) { /* deterministic, within +-0.15 dp */
  const unsigned u = (unsigned)(i * 2654435761u + (unsigned)axis * 40503u);
  return 0.15 * DP * (((u >> 8) % 2001) / 1000.0 - 1.0);
}

static void linear_field(void) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, 2, DP, 1.0);
  wl_plan_default_numerics(&cfg.prm);
  cfg.prm.residual_alpha = 0.5;
  cfg.lo[0] = -0.05, cfg.hi[0] = NX * DP + 0.05;
  cfg.lo[1] = -0.05, cfg.hi[1] = NZ * DP + 0.05;
  struct wl_sph_const k;
  struct wl_sph_grid g;
  if (wl_sph_const_make(&cfg.prm, &k, &err) || wl_sph_grid_make(&cfg, &k, &g, &err)) {
    printf("FAIL setup: %s\n", err.msg);
    wl_test_failures++;
    return;
  }
  const double G0[2][2] = {{-0.8, 0.3}, {0.5, 0.8}}, v0[2] = {0.2, -0.1}; /* [1/s], [m/s] */
  static double xs[N], zs[N], x[N], z[N];
  static wl_real vx[N], vz[N], rho[N], gbuf[4][N];
  static unsigned int key_in[N], key[N], perm[N];
  for (int iz = 0; iz < NZ; iz++)
    for (int ix = 0; ix < NX; ix++) {
      const int i = iz * NX + ix;
      xs[i] = (ix + 0.5) * DP + jitter(i, 0);
      zs[i] = (iz + 0.5) * DP + jitter(i, 1);
      const int cx = wl_sph_cell_coord(&g, 0, xs[i]), cz = wl_sph_cell_coord(&g, 1, zs[i]);
      key_in[i] = (unsigned)(g.n_cells + cz * g.n[0] + cx); /* fluid group */
    }
  int *begin = malloc(sizeof(int) * (2 * (size_t)g.n_cells + 1));
  int *cursor = malloc(sizeof(int) * 2 * (size_t)g.n_cells);
  wl_sph_cells_sort(&g, key_in, N, begin, cursor, perm);
  for (int s = 0; s < N; s++) {
    const int i = (int)perm[s];
    x[s] = xs[i], z[s] = zs[i], key[s] = key_in[i];
    vx[s] = (wl_real)(v0[0] + G0[0][0] * x[s] + G0[0][1] * z[s]);
    vz[s] = (wl_real)(v0[1] + G0[1][0] * x[s] + G0[1][1] * z[s]);
    rho[s] = (wl_real)(1000.0 * (1.0 + 0.002 * ((s * 7) % 5))); /* volumes differ a little */
  }
  const double *pos[2] = {x, z};
  const wl_real *vel[2] = {vx, vz};
  wl_real *gp[4] = {gbuf[0], gbuf[1], gbuf[2], gbuf[3]};
  double err_max = 0;
  for (int s = 0; s < N; s++) {
    wl_sph_vgrad(2, &k, &g, pos, vel, rho, key, begin, s, gp);
    for (int q = 0; q < 4; q++) err_max = fmax(err_max, fabs(gbuf[q][s] - G0[q / 2][q % 2]));
  }
  printf("# linear field: largest |G - G0| over %d particles (edges and corners included) %.3g "
         "1/s\n", N, err_max);
  /* float sums of ~30 terms of size |G0| dp / dp: 1e-4 of |G0| leaves room */
  CHECK_ABS(err_max, 0, 1e-4, "corrected velocity gradient of a linear field: G0 everywhere");
  /* the pair terms, over every pair within the support */
  double res_max = 0, mon_max = 0;
  for (int a = 0; a < N; a++)
    for (int b = 0; b < N; b++) {
      if (a == b) continue;
      const wl_real dx = (wl_real)(x[a] - x[b]), dz = (wl_real)(z[a] - z[b]);
      const wl_real r2 = dx * dx + dz * dz;
      if (!(r2 < k.support2)) continue;
      const wl_real ux = vx[a] - vx[b], uz = vz[a] - vz[b];
      const wl_real ga[4] = {gbuf[0][a], gbuf[1][a], gbuf[2][a], gbuf[3][a]};
      const wl_real gb[4] = {gbuf[0][b], gbuf[1][b], gbuf[2][b], gbuf[3][b]};
      const double c = wl_sph_pair_residual(2, &k, dx, 0, dz, ux, 0, uz, ga, gb, rho[a] + rho[b]);
      res_max = fmax(res_max, fabs(c) * sqrt(r2));
      /* the same term on the whole v_ij (G = 0) */
      const wl_real g0[4] = {0, 0, 0, 0};
      const double m = wl_sph_pair_residual(2, &k, dx, 0, dz, ux, 0, uz, g0, g0, rho[a] + rho[b]);
      mon_max = fmax(mon_max, fabs(m) * sqrt(r2));
    }
  printf("# linear field: largest pair acceleration, residual %.3g m/s^2, on the whole v_ij %.3g\n",
         res_max, mon_max);
  CHECK_TRUE(mon_max > 1e-3, "the term on the whole v_ij of the linear field's pairs is not 0");
  CHECK_ABS(res_max / mon_max, 0, 1e-3,
            "residual term on a linear field, relative to the same term on the whole v_ij");
  /* the eddy viscosity (numerics.smagorinsky): nu_t of the linear field
   * from each particle's gradient against the closed form from G0, S =
   * (G0 + G0^T)/2, |S| = sqrt(2 S:S) = sqrt(3.2) 1/s; and its pair term
   * against the laminar term of sph/interact.h with nu = nu_t (the same
   * physics, written separately there) */
  struct wl_sph_params pe = cfg.prm;
  pe.smagorinsky = 0.12;
  struct wl_sph_const ke;
  if (wl_sph_const_make(&pe, &ke, &err)) {
    printf("FAIL eddy setup: %s\n", err.msg);
    wl_test_failures++;
  } else {
    double s2 = 0;
    for (int a = 0; a < 2; a++)
      for (int b = 0; b < 2; b++) s2 += 2 * pow(0.5 * (G0[a][b] + G0[b][a]), 2);
    const double nut0 = pow(0.12 * DP, 2) * sqrt(s2);
    double nut_err = 0, pair_err = 0;
    for (int s = 0; s < N; s++) {
      const wl_real gs[4] = {gbuf[0][s], gbuf[1][s], gbuf[2][s], gbuf[3][s]};
      nut_err = fmax(nut_err, fabs(wl_sph_eddy_nu(2, &ke, gs) / nut0 - 1));
    }
    for (int b = 1; b < N; b++) {
      const wl_real dx = (wl_real)(x[0] - x[b]), dz = (wl_real)(z[0] - z[b]);
      const wl_real r2 = dx * dx + dz * dz;
      if (!(r2 < ke.support2)) continue;
      const struct wl_sph_pair o =
          wl_sph_pair_eval(1, 1, &ke, r2, 0, dz, rho[0], 1 / rho[0], 0, rho[b], 1 / rho[b],
                           ke.mass / rho[b], 0, 0, (wl_real)(4 * nut0));
      const double c = wl_sph_pair_eddy(&ke, r2, (wl_real)nut0, rho[0] + rho[b]);
      pair_err = fmax(pair_err, fabs(c / o.c_v - 1));
    }
    printf("# eddy viscosity: nu_t %.4g m^2/s (closed form), largest relative error %.2g; pair term "
           "against the laminar term's, largest relative difference %.2g\n",
           nut0, nut_err, pair_err);
    /* G within 1e-4 of |G0| (above) moves |S| by about as much */
    CHECK_ABS(nut_err, 0, 1e-3, "eddy viscosity of a linear field: (C_s dp)^2 |S| of its gradient");
    CHECK_ABS(pair_err, 0, 1e-5, "eddy pair term: the laminar term's with nu = nu_t");
  }
  free(begin);
  free(cursor);
}

/* The largest fluid speed from t0 on (the run's output callback). */
struct vmax_acc {
  double t0, vmax;
};
static enum wl_status vmax_out(void *user, struct wl_sph_sim *sim, double t, struct wl_error *err) {
  struct vmax_acc *a = user;
  if (t < a->t0 - 1e-9) return WL_OK;
  const struct wl_particles *p = wl_sph_sim_particles(sim, err);
  if (!p) return err->status;
  for (int i = p->n_bound; i < p->n; i++)
    a->vmax = fmax(a->vmax, hypot(p->vel[0][i], p->vel[1][i]));
  return WL_OK;
}

/* The closed still tank of `validate hydrostatic` at its level 1: fluid
 * 1 m x 0.5 m at rest (hydrostatic), three layers of wall particles 0.75 m
 * high, as src/validate/builders.c builds it. */
static void still_tank(double t_quick) {
  struct wl_error err;
  wl_error_clear(&err);
  const double L = 1.0, h = 0.5, dp = 0.05, g = 9.81, wall_h = 1.5 * h;
  const int layers = 3;
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, 2, dp, h);
  wl_plan_default_numerics(&cfg.prm);
  cfg.prm.residual_alpha = 0.5;
  cfg.n_threads = 1;
  struct wl_sph_const k;
  struct wl_particles init = {0};
  enum wl_status st = wl_sph_const_make(&cfg.prm, &k, &err);
  const double margin = (layers + 2) * dp;
  cfg.lo[0] = -margin, cfg.hi[0] = L + margin;
  cfg.lo[1] = -margin, cfg.hi[1] = wall_h + 2 * margin;
  struct wl_scene sc;
  if (!st) {
    wl_scene_init(&sc, &k, 0, 0);
    const double tx[4] = {0, 0, L, L}, tz[4] = {wall_h, 0, 0, wall_h};
    const double lo[2] = {0, 0}, hi[2] = {L, h};
    st = wl_scene_boundary_polyline(&sc, tx, tz, 4, layers, WL_KIND_FIXED, 0, &cfg, &err);
    if (!st) st = wl_scene_fluid_block(&sc, lo, hi, h, &err);
    if (!st) wl_scene_hydrostatic_boundary(&sc, h);
    if (!st) st = wl_scene_build(&sc, &init, &err);
    wl_scene_clear(&sc);
  }
  struct wl_sph_sim *sim = NULL;
  if (!st) st = wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err);
  const double t_end = t_quick > 0 ? t_quick : 20 * sqrt(h / g);
  struct vmax_acc acc = {t_end - 5 * sqrt(h / g), 0};
  if (!st) {
    struct wl_sph_run_opts o = {0};
    o.t_end = t_end;
    o.output_dt = 0.05;
    o.output = vmax_out;
    o.user = &acc;
    st = wl_sph_sim_run(sim, &o, &err);
  }
  if (st) printf("FAIL still tank: %s\n", err.msg);
  CHECK_TRUE(st == WL_OK, "still tank with the residual viscosity runs to its end");
  if (t_quick > 0) {
    printf("# quick run: %g s of the tank (the speed is judged after 20 sqrt(h/g))\n", t_quick);
    wl_sph_sim_free(sim);
    wl_particles_clear(&init);
    return;
  }
  printf("# still tank: largest speed over the last 5 sqrt(h/g) %.4g m/s = %.3g %% of sqrt(g h)\n",
         acc.vmax, 100 * acc.vmax / sqrt(g * h));
  CHECK_TRUE(acc.vmax < 0.01 * sqrt(g * h), "still tank: largest speed below 1 % of sqrt(g h)");
  wl_sph_sim_free(sim);
  wl_particles_clear(&init);
}

int main(void) {
  linear_field();
  /* the sanitizers' quick run: the tank's first 0.3 s, for memory errors */
  still_tank(getenv("WL_TEST_QUICK") ? 0.3 : 0);
  return TEST_RESULT();
}
