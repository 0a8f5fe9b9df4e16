/* sloshing_walls.c: which walls make the first sloshing mode fast
 * (docs/history/2026-11-25-walls.md). A 3D tank L = 1 m long, h = 0.5 m deep,
 * W wide, the linear mode eta = a cos(k s) sin(omega t), k = pi/L, started
 * from a flat surface with its potential-flow velocity (as `wallload
 * validate sloshing`), a = 0.01 m, assess's default numerics, CPU backend:
 *  - mode y: the mode runs along y between the domain's two mirror planes
 *    (exact free-slip end walls); walls of dynamic boundary particles at
 *    x = 0 and x = W run along it;
 *  - mode x: the mode runs along x between dynamic-boundary end walls;
 *    mirror planes at y = 0 and y = W.
 * The period is the mean interval between the extremes of the fluid's
 * centre of mass along the mode (parabolic peaks, outputs every T1/40),
 * against T1 = 2 pi / sqrt(g k tanh(k h)).
 *   usage: sloshing_walls x|y H_OVER_DP W_METRES
 * Built and run by bench/sloshing_walls.sh. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "wallload/plan.h"
#include "wallload/scene.h"
#include "wallload/sph.h"

#define TANK_L 1.0
#define DEPTH 0.5
#define AMP 0.01
#define LAYERS 3
#define PI 3.14159265358979323846
#define MAX_OUT 4096

struct mode {
  int along_y;
  double omega;
  int n;
  double t[MAX_OUT], s[MAX_OUT]; /* time, centre of mass along the mode */
};

static void mode_vel(const double *x, double *v, void *user) {
  const struct mode *m = user;
  const double k = PI / TANK_L, f = AMP * m->omega / sinh(k * DEPTH);
  const double s = m->along_y ? x[1] : x[0];
  const double u = -f * sin(k * s) * cosh(k * x[2]);
  v[0] = m->along_y ? 0 : u;
  v[1] = m->along_y ? u : 0;
  v[2] = f * cos(k * s) * sinh(k * x[2]);
}

static enum wl_status on_output(void *user, struct wl_sph_sim *sim, double t, struct wl_error *err) {
  struct mode *m = user;
  const struct wl_particles *p = wl_sph_sim_particles(sim, err);
  if (!p) return err->status;
  double sum = 0;
  for (int i = p->n_bound; i < p->n; i++) sum += p->pos[m->along_y ? 1 : 0][i];
  if (m->n < MAX_OUT) {
    m->t[m->n] = t;
    m->s[m->n] = sum / (p->n - p->n_bound);
    m->n++;
  }
  return WL_OK;
}

int main(int argc, char **argv) {
  if (argc != 4 || (argv[1][0] != 'x' && argv[1][0] != 'y')) {
    fprintf(stderr, "usage: sloshing_walls x|y H_OVER_DP W_METRES\n");
    return 2;
  }
  static struct mode m;
  m.along_y = argv[1][0] == 'y';
  const double dp = DEPTH / atof(argv[2]), width = atof(argv[3]);
  const double k = PI / TANK_L;
  m.omega = sqrt(9.81 * k * tanh(k * DEPTH));
  const double T1 = 2 * PI / m.omega;
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, 3, dp, DEPTH + AMP);
  wl_plan_default_numerics(&cfg.prm);
  const double lx = m.along_y ? width : TANK_L, ly = m.along_y ? TANK_L : width;
  const double margin = (LAYERS + 2) * dp;
  cfg.lo[0] = -margin;
  cfg.hi[0] = lx + margin;
  cfg.lo[1] = 0;
  cfg.hi[1] = ly;
  cfg.lo[2] = -margin;
  cfg.hi[2] = 2 * DEPTH;
  cfg.prm.mirror_lo = cfg.prm.mirror_hi = 1;
  cfg.prm.mirror_y_lo = 0;
  cfg.prm.mirror_y_hi = ly;
  struct wl_sph_const kc;
  struct wl_scene sc;
  struct wl_particles init = {0};
  const double wx[4] = {0, 0, lx, lx}, wz[4] = {1.6 * DEPTH, 0, 0, 1.6 * DEPTH};
  const double lo[3] = {0, 0, 0}, hi[3] = {lx, ly, DEPTH};
  if (wl_sph_const_make(&cfg.prm, &kc, &err)) goto fail;
  wl_scene_init(&sc, &kc, 0, ly);
  if (wl_scene_boundary_polyline(&sc, wx, wz, 4, LAYERS, WL_KIND_FIXED, 0, &cfg, &err) ||
      wl_scene_fluid_block(&sc, lo, hi, DEPTH, &err))
    goto fail;
  wl_scene_fluid_velocity(&sc, mode_vel, &m);
  wl_scene_hydrostatic_boundary(&sc, DEPTH);
  if (wl_scene_build(&sc, &init, &err)) goto fail;
  wl_scene_clear(&sc);
  struct wl_sph_sim *sim;
  if (wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err)) goto fail;
  struct wl_sph_run_opts o = {0};
  o.t_end = 2.2 * T1;
  o.output_dt = T1 / 40;
  o.output = on_output;
  o.user = &m;
  if (wl_sph_sim_run(sim, &o, &err)) goto fail;
  /* extremes of the centre of mass, each refined by a parabola */
  double first = NAN, last = NAN;
  int n_ext = 0;
  for (int i = 1; i + 1 < m.n; i++) {
    const double y0 = m.s[i - 1], y1 = m.s[i], y2 = m.s[i + 1];
    if ((y1 - y0) * (y2 - y1) >= 0) continue;
    const double den = y0 - 2 * y1 + y2, shift = den != 0 ? 0.5 * (y0 - y2) / den : 0;
    const double te = m.t[i] + shift * (m.t[i + 1] - m.t[i]);
    if (n_ext == 0) first = te;
    last = te;
    n_ext++;
  }
  const double period = n_ext > 1 ? 2 * (last - first) / (n_ext - 1) : NAN;
  printf("mode %c  h/dp %-4g W %-5g m  %6d particles  period %.4f s  T1 %.4f s  %+.1f %%\n",
         argv[1][0], DEPTH / dp, width, init.n, period, T1, 100 * (period / T1 - 1));
  wl_particles_clear(&init);
  wl_sph_sim_free(sim);
  return 0;
fail:
  fprintf(stderr, "sloshing_walls: %s\n", err.msg);
  return 1;
}
