/* test_sph_integrate.c: both time integrators (sph/integrate.h) against
 * the closed form of ballistic flight. Three fluid particles far apart
 * (no neighbour within 2h, so the only force is gravity and the density
 * stays rho0) are thrown in a box: r(t) = r0 + v0 t + g t^2/2,
 * v(t) = v0 + g t. Both schemes integrate a constant acceleration exactly
 * (symplectic: the half-step kick; Verlet: the leapfrog v^{n+1} = v^{n-1}
 * + (dt' + dt) a and its Euler steps), also when the step changes: each
 * run is made twice, with the CFL step (constant here: c0 exceeds 10 |v|
 * throughout) and with steps cut short to land on output times every
 * 0.01 s, as wl_sph_sim_run does. A leapfrog spanning 2 dt instead of
 * dt' + dt (DualSPHysics' form) is 8e-3 m/s off after 0.5 s that way.
 * So positions and velocities must match the closed form to rounding: the
 * velocities are single precision, and each step's kick can round by one
 * unit in the last place of |v| < 8 m/s (4 FLT_EPSILON), so after n steps
 * |dv| <= 4 n FLT_EPSILON and |dr| <= t times that (6e3 steps: 3e-3 m/s,
 * 1.5e-3 m; measured 2e-4 m/s and 4e-5 m).
 *
 * The particles are launched so that two of them change places in the
 * cell order (one falls past the other's row): Verlet keeps the previous
 * step's velocity and density per particle, and the cell sort must carry
 * them along; a particle that got its neighbour's old velocity would be
 * metres per second off. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/sph.h"

#define N 3
#define T_END 0.5 /* [s] */

static void flight(enum wl_sph_integrator integrator, double output_interval, const char *name) {
  const double g = 9.81;
  /* x0, z0, vx0, vz0: B starts below A and overtakes it at t = 0.8/3 s */
  const double r0[N][4] = {{0.1, 1.0, 0.3, 0.0}, {0.9, 0.2, -0.2, 3.0}, {1.6, 0.5, 0.0, 1.0}};
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  /* h_max 5 m: c0 = 10 sqrt(5 g) = 70 m/s > 10 |v| (|v| <= 4.9 m/s) */
  wl_sph_config_default(&cfg, 2, 0.02, 5.0);
  cfg.prm.integrator = integrator;
  cfg.lo[0] = -1;
  cfg.hi[0] = 3;
  cfg.lo[1] = -3;
  cfg.hi[1] = 3;
  struct wl_particles init = {0};
  if (wl_particles_alloc(&init, 2, N, 0, &err)) {
    CHECK_TRUE(0, "allocate the particles");
    return;
  }
  init.n = N;
  init.n_bound = 0;
  for (int i = 0; i < N; i++) {
    init.pos[0][i] = r0[i][0];
    init.pos[1][i] = r0[i][1];
    init.vel[0][i] = (wl_real)r0[i][2];
    init.vel[1][i] = (wl_real)r0[i][3];
    init.rho[i] = 1000;
    init.id[i] = (unsigned)i;
    init.kind[i] = WL_KIND_FLUID;
  }
  struct wl_sph_sim *sim = NULL;
  if (wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err)) {
    printf("sim: %s\n", err.msg);
    CHECK_TRUE(0, "set up the run");
    wl_particles_clear(&init);
    return;
  }
  long steps = 0;
  int order_changed = 0, first = -1;
  double t_out = output_interval;
  while (wl_sph_sim_time(sim) < T_END) {
    /* with outputs, steps are cut short to land on them, as wl_sph_sim_run does */
    const double t_now = wl_sph_sim_time(sim);
    while (output_interval > 0 && t_out <= t_now + 1e-12) t_out += output_interval;
    if (wl_sph_sim_step(sim, output_interval > 0 ? t_out - t_now : 0, &err) != WL_OK) {
      printf("step: %s\n", err.msg);
      CHECK_TRUE(0, "a step failed");
      break;
    }
    steps++;
    const struct wl_particles *p = wl_sph_sim_particles(sim, &err);
    if (p && first < 0) first = (int)p->id[0];
    if (p && (int)p->id[0] != first) order_changed = 1;
  }
  const double t = wl_sph_sim_time(sim);
  const struct wl_particles *p = wl_sph_sim_particles(sim, &err);
  double dr = 0, dv = 0, drho = 0;
  for (int i = 0; p && i < p->n; i++) {
    const unsigned q = p->id[i];
    const double x = r0[q][0] + r0[q][2] * t, z = r0[q][1] + r0[q][3] * t - 0.5 * g * t * t;
    const double vx = r0[q][2], vz = r0[q][3] - g * t;
    dr = fmax(dr, fmax(fabs(p->pos[0][i] - x), fabs(p->pos[1][i] - z)));
    dv = fmax(dv, fmax(fabs(p->vel[0][i] - vx), fabs(p->vel[1][i] - vz)));
    drho = fmax(drho, fabs(p->rho[i] - 1000.0));
  }
  printf("%s: %ld steps to t = %.6g s; largest error: position %.3g m, velocity %.3g m/s, "
         "density %.3g kg/m^3; memory order changed: %s\n",
         name, steps, t, dr, dv, drho, order_changed ? "yes" : "no");
  char what[160];
  snprintf(what, sizeof what, "%s: the particles changed places in memory (the sort carried them)",
           name);
  CHECK_TRUE(order_changed, what);
  snprintf(what, sizeof what, "%s: positions = r0 + v0 t + g t^2/2 [m]", name);
  const double tol_v = 4.0 * FLT_EPSILON * (double)steps;
  CHECK_ABS(dr, 0, t * tol_v, what);
  snprintf(what, sizeof what, "%s: velocities = v0 + g t (single precision) [m/s]", name);
  CHECK_ABS(dv, 0, tol_v, what);
  snprintf(what, sizeof what, "%s: density stays rho0 (no neighbours) [kg/m^3]", name);
  CHECK_ABS(drho, 0, 0, what);
  wl_sph_sim_free(sim);
  wl_particles_clear(&init);
}

int main(void) {
  flight(WL_SPH_SYMPLECTIC, 0, "symplectic");
  flight(WL_SPH_VERLET, 0, "Verlet");
  /* steps cut short every 0.01 s to land on output times: dt varies */
  flight(WL_SPH_SYMPLECTIC, 0.01, "symplectic, outputs every 0.01 s");
  flight(WL_SPH_VERLET, 0.01, "Verlet, outputs every 0.01 s");
  return TEST_RESULT();
}
