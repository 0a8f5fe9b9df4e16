/* test_sph_tank.c: still water in a 2D tank (REFERENCES.md 1.1).
 *
 * Water H = 0.5 m deep in a tank L = 1 m long, dp = H/25, dynamic boundary
 * particles (3 layers) in the bed and both walls, densities hydrostatic at
 * t = 0, run for 10 s (44 sqrt(H/g); REFERENCES recommends >= 20). Checks,
 * averaged over the outputs of the last second:
 *  - bed pressure: the hydrostatic line p(z) fitted (least squares) through
 *    the pressures of the fluid particles away from the walls, evaluated at
 *    the bed face z = 0, within 2 % of rho0 g h_eff, h_eff = fluid volume /
 *    tank length = (mass / rho0) / L (REFERENCES 1.1: use h_eff);
 *    its slope within 2 % of -rho0 g;
 *  - spurious velocity: max |v| of all fluid particles < 1 % of sqrt(g h);
 *  - no fluid particle behind a wall face (the guard would have stopped
 *    the run; checked again here on the positions);
 *  - gauges: the free surface at x = L/2 (DualSPHysics 0.4 criterion)
 *    within dp/2 of h_eff, and the interpolated velocity there ~ 0. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "testutil.h"
#include "wallload/scene.h"
#include "wallload/sph.h"

#define H 0.5
#define L 1.0
#define N_H 25
#define T_END 10.0
#define T_AVG 1.0     /* averaging window at the end [s] */
#define TOL_P 0.02    /* brief: 2 % */
#define TOL_V 0.01    /* brief: 1 % of sqrt(g h) */

struct acc {
  int n;
  double p_bed, slope, vmax, eta, veta, xmin, xmax, zmin;
  struct wl_sph_probe *probe;
};

static enum wl_status on_output(void *user, struct wl_sph_sim *sim, double t, struct wl_error *err) {
  struct acc *a = user;
  const struct wl_particles *p = wl_sph_sim_particles(sim, err);
  if (!p) return err->status;
  const struct wl_sph_const *k = wl_sph_sim_const(sim);
  double vmax = 0;
  for (int i = p->n_bound; i < p->n; i++) {
    const double v = hypot(p->vel[0][i], p->vel[1][i]);
    vmax = v > vmax ? v : vmax;
    a->xmin = fmin(a->xmin, p->pos[0][i]);
    a->xmax = fmax(a->xmax, p->pos[0][i]);
    a->zmin = fmin(a->zmin, p->pos[1][i]);
  }
  if (t < T_END - T_AVG - 1e-9) return WL_OK;
  /* least-squares line p = c0 + c1 z through interior fluid particles */
  double sz = 0, sp = 0, szz = 0, szp = 0;
  int m = 0;
  for (int i = p->n_bound; i < p->n; i++) {
    const double x = p->pos[0][i], z = p->pos[1][i];
    if (x < 0.2 * L || x > 0.8 * L || z < 2 * k->dp || z > H - 3 * k->dp) continue;
    const double pr = wl_sph_eos_p(k, p->rho[i]);
    sz += z;
    sp += pr;
    szz += z * z;
    szp += z * pr;
    m++;
  }
  const double c1 = (m * szp - sz * sp) / (m * szz - sz * sz), c0 = (sp - c1 * sz) / m;
  if (wl_sph_probe_index(a->probe, p, err) != WL_OK) return err->status;
  const double eta = wl_sph_probe_elevation(a->probe, 0.5 * L, 0, 0, 2 * H, 0);
  double v[2];
  const double pt[2] = {0.5 * L, 0.5 * H};
  wl_sph_probe_velocity(a->probe, pt, v);
  a->p_bed += c0;
  a->slope += c1;
  a->vmax = fmax(a->vmax, vmax);
  a->eta += eta;
  a->veta = fmax(a->veta, hypot(v[0], v[1]));
  a->n++;
  return WL_OK;
}

int main(void) {
  const double dp = H / N_H, g = 9.81;
  const int layers = 3;
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, 2, dp, H);
  /* One thread: thread independence is test_sph_threads' job; on a machine
   * shared with other jobs (CI, parallel ctest) each of the ~10^5 barriers
   * of a multi-threaded run can wait a scheduler time slice for a
   * descheduled partner, which made this test 30x slower there. */
  cfg.n_threads = 1;
  struct wl_sph_const k;
  if (wl_sph_const_make(&cfg.prm, &k, &err) != WL_OK) {
    printf("FAIL %s\n", err.msg);
    return 1;
  }
  cfg.lo[0] = -(layers + 2) * dp;
  cfg.hi[0] = L + (layers + 2) * dp;
  cfg.lo[1] = -(layers + 2) * dp;
  cfg.hi[1] = 2 * H;
  struct wl_scene sc;
  wl_scene_init(&sc, &k, 0, 0);
  const double tx[4] = {0, 0, L, L}, tz[4] = {1.5 * H, 0, 0, 1.5 * H};
  const double lo[2] = {0, 0}, hi[2] = {L, H};
  struct wl_particles init = {0};
  if (wl_scene_boundary_polyline(&sc, tx, tz, 4, layers, WL_KIND_FIXED, 0, &cfg, &err) ||
      wl_scene_fluid_block(&sc, lo, hi, H, &err)) {
    printf("FAIL scene: %s\n", err.msg);
    return 1;
  }
  wl_scene_hydrostatic_boundary(&sc, H);
  if (wl_scene_build(&sc, &init, &err)) {
    printf("FAIL build: %s\n", err.msg);
    return 1;
  }
  wl_scene_clear(&sc);
  const int n_fluid = init.n - init.n_bound;
  const double h_eff = n_fluid * dp * dp / L; /* (mass / rho0) / L */
  printf("tank: %d particles (%d fluid), h_eff = %g m, c0 = %g m/s\n", init.n, n_fluid, h_eff, k.c0_d);

  struct wl_sph_sim *sim;
  if (wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err) != WL_OK) {
    printf("FAIL sim: %s\n", err.msg);
    return 1;
  }
  wl_particles_clear(&init);
  struct acc a;
  memset(&a, 0, sizeof a);
  a.xmin = a.zmin = 1e30;
  a.xmax = -1e30;
  if (wl_sph_probe_alloc(&a.probe, &cfg, &err) != WL_OK) {
    printf("FAIL probe: %s\n", err.msg);
    return 1;
  }
  struct wl_sph_run_opts opts = {0};
  opts.t_end = T_END;
  opts.output_dt = 0.1;
  opts.output = on_output;
  opts.user = &a;
  const time_t w0 = time(NULL);
  const enum wl_status st = wl_sph_sim_run(sim, &opts, &err);
  printf("run: %s%s%s, %ld steps, ~%ld s wall\n", wl_error_status_name(st), st ? ": " : "",
         st ? err.msg : "", wl_sph_sim_steps(sim), (long)(time(NULL) - w0));
  CHECK_TRUE(st == WL_OK, "10 s of still water without a guard fault (no wall crossed)");
  CHECK_TRUE(a.n >= 10, "outputs in the averaging window");
  const double rgh = k.rho0 * g * h_eff;
  CHECK_REL(a.p_bed / a.n, rgh, TOL_P, "bed pressure = rho0 g h_eff (REFERENCES 1.1)");
  CHECK_REL(a.slope / a.n, -k.rho0 * g, TOL_P, "hydrostatic gradient dp/dz = -rho0 g");
  CHECK_ABS(a.vmax, 0, TOL_V * sqrt(g * H), "max spurious fluid velocity < 1 % sqrt(g h)");
  CHECK_TRUE(a.xmin > 0 && a.xmax < L && a.zmin > 0,
             "no fluid particle behind a wall face (x in (0, L), z > 0) at any output");
  CHECK_ABS(a.eta / a.n, h_eff, 0.5 * dp, "gauge: free surface at L/2 (0.4 criterion) = h_eff +- dp/2");
  CHECK_ABS(a.veta, 0, TOL_V * sqrt(g * H), "probe: velocity at mid depth ~ 0");
  wl_sph_probe_free(a.probe);
  wl_sph_sim_free(sim);
  return TEST_RESULT();
}
