/* test_sph_load.c: the wall load the backend computes (backend.h
 * wall_load, sph/gather.h wl_sph_gather_wall_load: the horizontal force of
 * the fluid on the boundary particles of one body and its moment) against
 * a second, independent computation: the host loop over wall-fluid pairs
 * that `assess` ran before the backends computed it (kept here as it was in
 * src/assess/assess.c: the wall particles outside, the fluid particles near
 * the wall inside, the fluid's mirror images for the mirror planes), on the
 * CPU backend's state. Cases: a 2D dam break and a 3D dam break between
 * free-slip side walls (mirror planes), each against the tank's left wall,
 * which holds the water column (a load from the first step), at the start
 * and during the collapse; with the laminar viscosity too.
 *
 * Why not bit for bit. Each pair's term is the same function of the same
 * values in 2D (the same bits); the sums over pairs run in another order
 * (per fluid particle, then over the particles, against per wall particle
 * then over the fluid), which moves the last bits of a double sum: the
 * tolerance is 1e-12 of the sum of |pair forces|. In 3D the gather takes
 * r^2 and v.r as the solver's gather does (x, y, z order), the host loop
 * in (x, z, y) order: float rounding of single pairs, 1e-6 of that sum.
 *
 * And the wall load leaves the run alone: it sorts the particles into the
 * order the next step would, so a run that asks for it at every output
 * ends in the same bits as one that does not. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "dam_tanks.h"
#include "wallload/backend.h"
#include "wallload/scene.h"
#include "wallload/sph.h"
#include "wallload/sph/interact.h"

/* Body tag of the loaded wall in these tests (flume.h uses 2 likewise). */
#define BODY_WALL 2
/* Relative tolerances against the sum of |pair forces| (file header). */
#define TOL_LOAD_2D 1e-12
#define TOL_LOAD_3D 1e-6

struct load_case {
  int dim;
  int laminar;
  long steps;
  const char *name;
};

/* The dam break of test_cuda_backend (2D; 3D between free-slip walls), its
 * left wall (x < 0) tagged BODY_WALL (dam_tanks.h). */
static enum wl_status build(const struct load_case *lc, struct wl_sph_config *cfg,
                            struct wl_particles *p, struct wl_error *err) {
  const int dim = lc->dim;
  const enum dam_tank t = dim == 2 ? DAM_2D : DAM_3D_MIRROR;
  wl_sph_config_default(cfg, dim, dim == 2 ? 0.01 : 0.02, dam_tank_height(t));
  cfg->n_threads = 1;
  if (lc->laminar) cfg->prm.visc = WL_SPH_VISC_LAMINAR;
  if (dim == 3) {
    cfg->prm.mirror_lo = cfg->prm.mirror_hi = 1;
    cfg->prm.mirror_y_lo = 0.0;
    cfg->prm.mirror_y_hi = DAM_W;
  }
  return dam_tank_build(t, cfg, BODY_WALL, p, err);
}

/* The host loop `assess` ran (src/assess/assess.c boundary_force before
 * the backends computed the load), on host particles p: force and moment
 * about z_toe of the fluid on the boundary particles of body `body`, and
 * in *scale the sum of |pair forces|. x_wall, z_toe: the wall's face and
 * toe, for its choice of the fluid particles near the wall. */
static void host_load(const struct wl_particles *p, const struct wl_sph_const *k, int body,
                      double x_wall, double z_toe, double *force, double *moment,
                      double *scale) {
  const double reach = 2.0 * k->h_d;
  const int d3 = p->dim == 3, az = p->dim - 1;
  int *near = malloc(sizeof(int) * (size_t)(p->n > 0 ? p->n : 1));
  size_t n_near = 0;
  for (int i = p->n_bound; i < p->n; i++) {
    const double x = p->pos[0][i], z = p->pos[az][i];
    /* the wall is at x < x_wall here (the old loop's wall was at x >
     * x_wall): the near test mirrored */
    if (x < x_wall + reach && z > z_toe - reach) near[n_near++] = i;
  }
  const int laminar = k->visc == WL_SPH_VISC_LAMINAR;
  size_t n_pass[3] = {n_near, 0, 0};
  for (int m = 1; m < 3; m++)
    if (d3 && (k->mirror & (1 << (m - 1)))) n_pass[m] = n_near;
  double fx = 0.0, my = 0.0, sa = 0.0;
  for (int j = 0; j < p->n_bound; j++) {
    if (p->body[j] != body) continue;
    wl_real rho_j = p->rho[j], p_j = wl_sph_eos_p(k, rho_j);
    for (int mirror = 0; mirror < 3; mirror++)
      for (size_t a = 0; a < n_pass[mirror]; a++) {
        const int i = near[a];
        wl_real dx = (wl_real)(p->pos[0][i] - p->pos[0][j]);
        wl_real dz = (wl_real)(p->pos[az][i] - p->pos[az][j]);
        wl_real r2 = dx * dx + dz * dz, dy = 0;
        if (d3) {
          const double yi = mirror ? 2.0 * k->mirror_y[mirror - 1] - p->pos[1][i] : p->pos[1][i];
          dy = (wl_real)(yi - p->pos[1][j]);
          r2 += dy * dy;
        }
        if (r2 >= k->support2) continue;
        wl_real vx = p->vel[0][i] - p->vel[0][j], vz = p->vel[az][i] - p->vel[az][j];
        wl_real rho_i = p->rho[i], p_i = wl_sph_pair_p_wall(k, wl_sph_eos_p(k, rho_i));
        wl_real rv = dx * vx + dz * vz;
        if (d3) rv += dy * ((mirror ? -p->vel[1][i] : p->vel[1][i]) - p->vel[1][j]);
        wl_real inv_rho_j, vol_j;
        wl_sph_pair_j_bound(k, rho_j, &inv_rho_j, &vol_j);
        struct wl_sph_pair pr =
            laminar ? wl_sph_pair_eval(1, 0, k, r2, rv, dz, rho_i, 1 / rho_i, p_i, rho_j,
                                       inv_rho_j, vol_j, p_j, k->av_fb, k->lam_fb)
                    : wl_sph_pair_eval(0, 0, k, r2, rv, dz, rho_i, 1 / rho_i, p_i, rho_j,
                                       inv_rho_j, vol_j, p_j, k->av_fb, 0);
        double ax = (double)pr.c_r * dx + (double)pr.c_v * vx;
        double fij = -(double)k->mass * ax;
        fx += fij;
        sa += fabs(fij);
        my += fij * fmax(0.0, 0.5 * (p->pos[az][i] + p->pos[az][j]) - z_toe);
      }
  }
  free(near);
  *force = fx;
  *moment = my;
  *scale = sa;
}

static uint64_t hash(uint64_t h, const void *data, size_t n) {
  const unsigned char *c = data;
  for (size_t i = 0; i < n; i++) h = (h ^ c[i]) * 1099511628211ull;
  return h;
}

/* FNV-1a of the state fields of p, in id order. */
static uint64_t state_hash(const struct wl_particles *p) {
  int *at = malloc(sizeof(int) * (size_t)p->n);
  for (int i = 0; i < p->n; i++) at[p->id[i] < (unsigned)p->n ? p->id[i] : 0] = i;
  uint64_t h = 1469598103934665603ull;
  for (int q = 0; q < p->n; q++) {
    const int i = at[q];
    for (int a = 0; a < p->dim; a++) {
      h = hash(h, &p->pos[a][i], sizeof(double));
      h = hash(h, &p->vel[a][i], sizeof(wl_real));
    }
    h = hash(h, &p->rho[i], sizeof(wl_real));
  }
  free(at);
  return h;
}

static void run_case(const struct load_case *lc) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_config cfg;
  struct wl_particles init = {0};
  struct wl_sph_sim *sim = NULL, *plain = NULL;
  enum wl_status st = build(lc, &cfg, &init, &err);
  if (!st) st = wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err);
  if (!st) st = wl_sph_sim_alloc(&plain, &wl_backend_cpu_ops, &cfg, &init, &err);
  wl_particles_clear(&init);
  CHECK_TRUE(st == WL_OK, "two CPU simulations set up");
  if (st) {
    printf("  %s: %s\n", lc->name, err.msg);
    wl_sph_sim_free(sim);
    wl_sph_sim_free(plain);
    return;
  }
  const struct wl_sph_const *k = wl_sph_sim_const(sim);
  const double tol = lc->dim == 2 ? TOL_LOAD_2D : TOL_LOAD_3D;
  double worst_f = 0, worst_m = 0, f_first = 0;
  int n_checked = 0, ok = 1;
  for (long s = 0; s <= lc->steps && ok; s++) {
    if (s > 0 && ((st = wl_sph_sim_step(sim, 0, &err)) || (st = wl_sph_sim_step(plain, 0, &err)))) {
      ok = 0;
      break;
    }
    if (s % 50) continue;
    const struct wl_particles *p = wl_sph_sim_particles(sim, &err);
    double fh, mh, scale, fb, mb;
    if (!p || wl_sph_sim_wall_load(sim, BODY_WALL, 0.0, &fb, &mb, &err)) {
      ok = 0;
      break;
    }
    host_load(p, k, BODY_WALL, 0.0, 0.0, &fh, &mh, &scale);
    if (s == 0) f_first = fh;
    worst_f = fmax(worst_f, fabs(fb - fh) / scale);
    worst_m = fmax(worst_m, fabs(mb - mh) / (scale * 0.6)); /* lever arms below 0.6 m */
    n_checked++;
  }
  CHECK_TRUE(ok, "both runs ran every step, every wall load computed");
  if (!ok) printf("  %s: %s\n", lc->name, err.msg);
  printf("# %s: %d samples, first force %.6g, |force - host|max %.3g and |moment - host|max "
         "%.3g of the sum of |pair forces|\n", lc->name, n_checked, f_first, worst_f, worst_m);
  CHECK_TRUE(f_first < 0, "the water column pushes the left wall towards -x");
  CHECK_ABS(worst_f, 0, tol, "wall force: backend gather against the host loop of assess");
  CHECK_ABS(worst_m, 0, tol, "wall moment: backend gather against the host loop of assess");
  if (ok) {
    const struct wl_particles *a = wl_sph_sim_particles(sim, &err);
    const uint64_t ha = a ? state_hash(a) : 0;
    const struct wl_particles *b = wl_sph_sim_particles(plain, &err);
    const uint64_t hb = b ? state_hash(b) : 1;
    CHECK_TRUE(ha == hb, "the run that asked for the wall load ends in the same bits as the run "
               "that did not");
  }
  wl_sph_sim_free(sim);
  wl_sph_sim_free(plain);
}

int main(void) {
  const struct load_case cases[] = {
      {2, 0, 300, "2D dam break, left wall"},
      {2, 1, 300, "2D dam break, left wall, laminar viscosity"},
      {3, 0, 100, "3D dam break between free-slip walls (mirror planes), left wall"},
      {3, 1, 100, "3D dam break between free-slip walls, left wall, laminar viscosity"},
  };
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) run_case(&cases[c]);
  struct wl_error err;
  wl_error_clear(&err);
  double f, m;
  CHECK_TRUE(wl_sph_sim_wall_load(NULL, 0, 0.0, &f, &m, &err) == WL_EINPUT && f == 0 && m == 0,
             "body 0 (no structure) is refused before the simulation is looked at");
  return TEST_RESULT();
}
