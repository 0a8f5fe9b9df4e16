/* test_sph_guard.c: the instability guard and every error path of the
 * sph, backend and scene interfaces, provoked one by one; the paddle's
 * prescribed trajectory; output and progress callbacks.
 * References: the contracts in sph.h, backend.h, scene.h and sph/guard.h,
 * and for the paddle the prescribed X(t) itself. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "testutil.h"
#include "wallload/scene.h"
#include "wallload/sph.h"
#include "wallload/sph/guard.h"

#define DP 0.02
#define H 0.4
#define L 0.8

/* A small tank (fixed walls registered with the guard) with a fluid block,
 * optionally a piston paddle (body 1) at x = 0; one extra fluid particle
 * can be appended at (xe, ze) with density rhoe. */
static enum wl_status make(struct wl_sph_config *cfg, struct wl_particles *p, int paddle,
                           int extra, double xe, double ze, double rhoe, struct wl_error *err) {
  wl_sph_config_default(cfg, 2, DP, H);
  struct wl_sph_const k;
  enum wl_status st = wl_sph_const_make(&cfg->prm, &k, err);
  if (st) return st;
  cfg->lo[0] = -0.2;
  cfg->hi[0] = L + 0.2;
  cfg->lo[1] = -0.2;
  cfg->hi[1] = 3 * H;
  struct wl_scene sc;
  wl_scene_init(&sc, &k, 0, 0);
  const double tx[4] = {0, 0, L, L}, tz[4] = {2 * H, 0, 0, 2 * H};
  const double px[3] = {-0.15, L, L}, pz[3] = {0, 0, 2 * H};
  const double lo[2] = {paddle ? 0.1 : 0, 0}, hi[2] = {0.3, H};
  if (paddle) {
    st = wl_scene_boundary_polyline(&sc, px, pz, 3, 3, WL_KIND_FIXED, 0, cfg, err);
    if (!st) st = wl_scene_piston(&sc, 0.05, 0, 1.5 * H, 3, 1, err);
  } else {
    st = wl_scene_boundary_polyline(&sc, tx, tz, 4, 3, WL_KIND_FIXED, 0, cfg, err);
  }
  if (!st) st = wl_scene_fluid_block(&sc, lo, hi, H, err);
  if (!st && extra) {
    const double lo2[2] = {xe - 0.5 * DP, ze - 0.5 * DP}, hi2[2] = {xe + 0.5 * DP, ze + 0.5 * DP};
    st = wl_scene_fluid_block(&sc, lo2, hi2, ze, err);
    if (!st) sc.rho[1][sc.n[1] - 1] = rhoe;
  }
  if (!st) st = wl_scene_build(&sc, p, err);
  wl_scene_clear(&sc);
  return st;
}

static enum wl_status alloc_with(double xe, double ze, double rhoe, struct wl_error *err) {
  struct wl_sph_config cfg;
  struct wl_particles p = {0};
  enum wl_status st = make(&cfg, &p, 0, 1, xe, ze, rhoe, err);
  if (st) return st;
  struct wl_sph_sim *sim = NULL;
  st = wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &p, err);
  wl_sph_sim_free(sim);
  wl_particles_clear(&p);
  return st;
}

static double paddle_x(double t, void *user) {
  (void)user;
  return 0.05 * sin(10 * t); /* [m] */
}

static int n_out, n_prog;
static enum wl_status out_fail(void *user, struct wl_sph_sim *sim, double t, struct wl_error *err) {
  (void)user;
  (void)sim;
  n_out++;
  if (t > 0.005) return wl_error_set(err, WL_EIO, "test output failure at t = %g", t);
  return WL_OK;
}
static void prog(void *user, const struct wl_sph_progress *pr) {
  (void)user;
  if (pr->t >= 0 && pr->n > 0) n_prog++;
}

/* One 2D fluid particle at rest density, and the constants the guard and
 * limiter read (penetration 0.01 m); 1 (a failure counted) if the
 * allocation fails. */
static int one_fluid_particle(struct wl_particles *p, struct wl_sph_const *k) {
  struct wl_error err;
  if (wl_particles_alloc(p, 2, 1, 1, &err)) {
    printf("FAIL alloc: %s\n", err.msg);
    wl_test_failures++;
    return 1;
  }
  p->n = 1;
  p->kind[0] = WL_KIND_FLUID;
  p->rho[0] = 1000;
  memset(k, 0, sizeof *k);
  k->rho_min = 700;
  k->rho_max = 1300;
  k->penetration = 0.01;
  return 0;
}

/* The guard's depth rule and the wall limiter (sph/guard.h) on one fluid
 * particle against hand-made faces: a seawall block (vertical face x = 1
 * up to its crest z = 0.45, crest face on top), layers 0.1 m deep, and a
 * thin wall (layers 0.05 m) for the back-side rule. Reference: the
 * geometry itself (distances by hand). */
static void depth_rules(void) {
  struct wl_particles p = {0};
  struct wl_sph_const k;
  if (one_fluid_particle(&p, &k)) return;
  const double lo[2] = {-10, -10}, hi[2] = {10, 10};
  struct wl_sph_wall w[2] = {wl_sph_wall_make(1, 0, 1, 0.45, 0.1),
                             wl_sph_wall_make(1, 0.45, 2, 0.45, 0.1)};
  int wall = -1;
  p.pos[0][0] = 1.04, p.pos[1][0] = 0.4499;
  CHECK_TRUE(wl_sph_guard(2, &k, &p, lo, hi, w, 2, 0, &wall) == WL_SPH_FAULT_NONE,
             "0.1 mm under the crest, 40 mm behind the vertical face: not a crossed wall");
  p.vel[0][0] = 0.5, p.vel[1][0] = -0.2;
  CHECK_TRUE(wl_sph_wall_limit(2, &p, w, 2, 0.01, 0) == 1 && fabs(p.pos[1][0] - 0.45) < 1e-12 &&
                 fabs(p.pos[0][0] - 1.04) < 1e-12 && p.vel[1][0] == 0 && p.vel[0][0] == 0.5f,
             "the limiter lifts it onto the crest and keeps its velocity along it");
  p.pos[0][0] = 1.04, p.pos[1][0] = 0.43;
  CHECK_TRUE(wl_sph_guard(2, &k, &p, lo, hi, w, 2, 0, &wall) == WL_SPH_FAULT_PENETRATION && wall == 1,
             "20 mm under the crest, 40 mm behind the face: crossed, the crest the nearest way out");
  struct wl_sph_wall thin = wl_sph_wall_make(1, 0, 1, 1, 0.05);
  p.pos[0][0] = 1.048, p.pos[1][0] = 0.5;
  p.vel[0][0] = -0.3, p.vel[1][0] = -1;
  CHECK_TRUE(wl_sph_guard(2, &k, &p, lo, hi, &thin, 1, 0, &wall) == WL_SPH_FAULT_NONE,
             "2 mm into the back of a wall's layers (water running down its outside): not crossed");
  CHECK_TRUE(wl_sph_wall_limit(2, &p, &thin, 1, 0.01, 0) == 1 && fabs(p.pos[0][0] - 1.05) < 1e-12 &&
                 p.vel[0][0] == 0 && p.vel[1][0] == -1,
             "the limiter puts it out at the back, its velocity into the wall removed");
  p.pos[0][0] = 1.025;
  CHECK_TRUE(wl_sph_guard(2, &k, &p, lo, hi, &thin, 1, 0, &wall) == WL_SPH_FAULT_PENETRATION,
             "in the middle of the layers (25 mm from face and back): crossed");
  p.pos[0][0] = 1.02, p.pos[1][0] = 0.995;
  CHECK_TRUE(wl_sph_guard(2, &k, &p, lo, hi, &thin, 1, 0, &wall) == WL_SPH_FAULT_NONE,
             "within `penetration` of the face's open end: passing over the top, not crossed");
  p.pos[0][0] = 20, p.pos[1][0] = 0.5;
  CHECK_TRUE(wl_sph_exclude(2, &p, lo, hi, 0) == 1 && p.body[0] == WL_SPH_BODY_EXCLUDED &&
                 p.pos[0][0] < hi[0] && p.pos[0][0] > hi[0] - 1e-6 && p.vel[1][0] == 0 &&
                 wl_sph_guard(2, &k, &p, lo, hi, &thin, 1, 0, &wall) == WL_SPH_FAULT_NONE,
             "out of the domain box: taken out of the run at rest on the box's face, no fault");
  wl_particles_clear(&p);
}

/* The guard after the limiter tests the wall faces only for the particles
 * the limiter moved (sph/guard.h wl_sph_guard_faces), and the limiter only
 * the faces near the particles' box (wl_sph_walls_near). Reference: the
 * limiter and guard over every face, a second computation of the same
 * decisions, on 20 000
 * particles scattered with random velocities around a convex crest (the
 * seawall's), a concave corner (bed and end wall), a thin wall and a slope
 * meeting a platform. Every verdict and crossed wall must agree, and the
 * sample must contain particles the limiter moved and faults the guard
 * finds after it, so that both branches are exercised. */
static void guard_after_limiter(void) {
  struct wl_particles p = {0};
  struct wl_sph_const k;
  if (one_fluid_particle(&p, &k)) return;
  const double lo[2] = {-10, -10}, hi[2] = {10, 10};
  const struct wl_sph_wall w[] = {
      wl_sph_wall_make(1, 0, 1, 0.45, 0.1),   /* seawall face, fluid at x < 1 */
      wl_sph_wall_make(1, 0.45, 2, 0.45, 0.1), /* its crest */
      wl_sph_wall_make(-1, 0, 1, 0, 0.1),     /* bed in front of it */
      wl_sph_wall_make(-1, 1, -1, 0, 0.1),    /* end wall at x = -1, fluid at x > -1 */
      wl_sph_wall_make(-0.5, 0.6, -0.5, 0.9, 0.03), /* a thin plate */
      wl_sph_wall_make(0.2, 0.7, 0.6, 0.8, 0.1),    /* a slope meeting a platform */
      wl_sph_wall_make(0.6, 0.8, 0.9, 0.8, 0.1)};
  const int nw = (int)(sizeof w / sizeof w[0]);
  unsigned long seed = 20261127;
  int differ = 0, moved_n = 0, faults_after_move = 0, near_differ = 0, culled = 0;
  for (int it = 0; it < 20000; it++) {
    double u[4];
    for (int a = 0; a < 4; a++) {
      seed = seed * 6364136223846793005ul + 1442695040888963407ul;
      u[a] = (double)(seed >> 11) / 9007199254740992.0;
    }
    p.pos[0][0] = -1.15 + 3.3 * u[0];
    p.pos[1][0] = -0.15 + 1.1 * u[1];
    p.vel[0][0] = (float)(2 * u[2] - 1);
    p.vel[1][0] = (float)(2 * u[3] - 1);
    p.body[0] = 0;
    /* the limiter over the faces near a box around the particle (random
     * half-widths up to 0.3 m) against the limiter over all of them */
    const double x0 = p.pos[0][0], z0 = p.pos[1][0];
    const float u0 = p.vel[0][0], w0 = p.vel[1][0];
    double box[4];
    for (int a = 0; a < 4; a++) {
      seed = seed * 6364136223846793005ul + 1442695040888963407ul;
      const double half = 0.3 * (double)(seed >> 11) / 9007199254740992.0;
      box[a] = (a < 2 ? x0 : z0) + (a % 2 ? half : -half);
    }
    struct wl_sph_wall near[WL_SPH_WALLS_MAX];
    const int n_near = wl_sph_walls_near(w, nw, box, near);
    culled += n_near < nw;
    const int moved_near = wl_sph_wall_limit(2, &p, near, n_near, k.penetration, 0);
    const double xn = p.pos[0][0], zn = p.pos[1][0];
    const float un = p.vel[0][0], wn = p.vel[1][0];
    p.pos[0][0] = x0, p.pos[1][0] = z0, p.vel[0][0] = u0, p.vel[1][0] = w0;
    const int moved = wl_sph_wall_limit(2, &p, w, nw, k.penetration, 0);
    near_differ += moved != moved_near || xn != p.pos[0][0] || zn != p.pos[1][0] ||
                   un != p.vel[0][0] || wn != p.vel[1][0];
    int w_all = -1, w_fast = -1;
    const int f_all = wl_sph_guard(2, &k, &p, lo, hi, w, nw, 0, &w_all);
    const int f_fast = wl_sph_guard(2, &k, &p, lo, hi, w, wl_sph_guard_faces(1, moved, nw), 0, &w_fast);
    differ += f_all != f_fast || w_all != w_fast;
    moved_n += moved;
    faults_after_move += moved && f_all != WL_SPH_FAULT_NONE;
  }
  printf("  %d of 20000 moved by the limiter, %d of those still crossed after it\n", moved_n,
         faults_after_move);
  CHECK_TRUE(differ == 0, "the guard after the limiter: the same verdict and wall over the moved "
                          "particles' faces alone as over every face");
  CHECK_TRUE(near_differ == 0 && culled > 10000,
             "the limiter over the faces near a box around the particle (wl_sph_walls_near) moves "
             "it as over every face, with faces left out in most draws");
  CHECK_TRUE(moved_n > 1000 && faults_after_move > 0,
             "the sample exercises both: particles the limiter moved, and faults left after it");
  CHECK_TRUE(wl_sph_guard_faces(1, 0, 7) == 0 && wl_sph_guard_faces(1, 1, 7) == 7 &&
                 wl_sph_guard_faces(0, 0, 7) == 7,
             "no faces where the limiter left the particle; all where it moved it or did not run");
  wl_particles_clear(&p);
}

/* The tension floor's contract (sph/params.h tension_max): a density at
 * the floor reads a pressure of at most tension_max rho0 g h_max of
 * tension in the solver's own (float) equation of state, and no more than
 * four of that equation's rounding steps near rho0 (7 B FLT_EPSILON each:
 * dp/drho = 7 B / rho0 at rho0, times rho0's float spacing) inside it. At
 * coefsound 10 and 20 and several depths (the double inverse's rounding
 * to float falls either way). */
static void tension_floor(void) {
  const double depths[4] = {0.3, 0.55, 0.6, 1.7}, sounds[2] = {10, 20};
  int kept = 0, tight = 0, n = 0;
  for (int a = 0; a < 4; a++)
    for (int b = 0; b < 2; b++) {
      struct wl_sph_config cfg;
      wl_sph_config_default(&cfg, 2, DP, depths[a]);
      cfg.prm.coefsound = sounds[b];
      struct wl_sph_const k;
      struct wl_error err;
      wl_error_clear(&err);
      if (wl_sph_const_make(&cfg.prm, &k, &err)) {
        printf("FAIL constants: %s\n", err.msg);
        wl_test_failures++;
        return;
      }
      const double limit = -cfg.prm.tension_max * cfg.prm.rho0 * cfg.prm.g * cfg.prm.h_max;
      const double p_floor = (double)wl_sph_eos_p(&k, k.rho_floor);
      n++;
      kept += p_floor >= limit;
      tight += p_floor - limit <= 4 * 7 * (double)k.B * FLT_EPSILON;
    }
  CHECK_TRUE(kept == n, "the floor's pressure keeps the tension limit (float equation of state)");
  CHECK_TRUE(tight == n, "and lies within four rounding steps of it");
}

int main(void) {
  struct wl_error err;
  tension_floor();
  depth_rules();
  guard_after_limiter();

  /* ---- guard faults, found in the initial state ---- */
  wl_error_clear(&err);
  CHECK_TRUE(alloc_with(0.5, 5 * H, 1000, &err) == WL_EUNSTABLE && strstr(err.msg, "left the domain box") &&
                 strstr(err.msg, "id ") && strstr(err.msg, "t = 0"),
             "particle outside the domain box: WL_EUNSTABLE naming id, position, time");
  printf("  message: %s\n", err.msg);
  wl_error_clear(&err);
  CHECK_TRUE(alloc_with(0.5, 0.2, NAN, &err) == WL_EUNSTABLE && strstr(err.msg, "non-finite"),
             "non-finite density: WL_EUNSTABLE");
  wl_error_clear(&err);
  CHECK_TRUE(alloc_with(0.5, 0.2, 1500, &err) == WL_EUNSTABLE && strstr(err.msg, "density out of range"),
             "fluid density 1500 kg/m^3 (> 1.3 rho0): WL_EUNSTABLE");
  wl_error_clear(&err);
  CHECK_TRUE(alloc_with(0.5, -1.5 * DP, 1000, &err) == WL_EUNSTABLE && strstr(err.msg, "crossed a wall") &&
                 strstr(err.msg, "wall 1"),
             "fluid particle 1.5 dp behind the bed face: WL_EUNSTABLE naming the wall");
  printf("  message: %s\n", err.msg);
  wl_error_clear(&err);
  CHECK_TRUE(alloc_with(0.5, -0.2 * DP, 1000, &err) == WL_OK,
             "0.2 dp behind the face is within the dp/2 tolerance");
  wl_error_clear(&err);
  CHECK_TRUE(alloc_with(-0.15, 0.2, 1000, &err) == WL_OK,
             "fluid beyond the back of the wall layers is not a crossing (overtopping)");

  /* ---- dt collapse ---- */
  {
    struct wl_sph_config cfg;
    struct wl_particles p = {0};
    wl_error_clear(&err);
    make(&cfg, &p, 0, 0, 0, 0, 0, &err);
    cfg.prm.dt_collapse = 0.9999;
    struct wl_sph_sim *sim;
    enum wl_status st = wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &p, &err);
    for (int s = 0; s < 2000 && st == WL_OK; s++) st = wl_sph_sim_step(sim, 0, &err);
    CHECK_TRUE(st == WL_EUNSTABLE && strstr(err.msg, "time step collapsed") && strstr(err.msg, "step "),
               "dt below dt_collapse x initial dt: WL_EUNSTABLE with time and step");
    printf("  message: %s\n", err.msg);
    wl_sph_sim_free(sim);
    wl_particles_clear(&p);
  }

  /* ---- configuration and API errors ---- */
  {
    struct wl_sph_config cfg;
    struct wl_particles p = {0};
    wl_error_clear(&err);
    make(&cfg, &p, 1, 0, 0, 0, 0, &err);
    struct wl_sph_sim *sim = NULL;
    /* boundary particles must come first */
    const unsigned char k0 = p.kind[0];
    p.kind[0] = WL_KIND_FLUID;
    CHECK_TRUE(wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &p, &err) == WL_EINPUT && !sim &&
                   strstr(err.msg, "boundary"),
               "fluid particle among the boundary ones: WL_EINPUT, no simulation");
    p.kind[0] = k0;
    wl_error_clear(&err);
    struct wl_sph_config bad = cfg;
    bad.hi[0] = bad.lo[0];
    CHECK_TRUE(wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &bad, &p, &err) == WL_EINPUT,
               "empty domain box: WL_EINPUT");
    wl_error_clear(&err);
    bad = cfg;
    bad.prm.dim = 3;
    CHECK_TRUE(wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &bad, &p, &err) == WL_EINPUT,
               "2D particles with 3D parameters: WL_EINPUT");
    wl_error_clear(&err);
    CHECK_TRUE(wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &p, &err) == WL_OK, "valid set-up");
    const double t_bad[2] = {0, 0}, x2[2] = {0, 1};
    struct wl_sph_motion m = {WL_SPH_MOTION_TABLE, 2, t_bad, x2, NULL, NULL};
    CHECK_TRUE(wl_sph_sim_set_motion(sim, 1, &m, &err) == WL_EINPUT && strstr(err.msg, "not increasing"),
               "motion table with repeated time: WL_EINPUT");
    wl_error_clear(&err);
    CHECK_TRUE(wl_sph_sim_set_motion(sim, 0, &m, &err) == WL_EINPUT, "motion of body 0: WL_EINPUT");
    wl_error_clear(&err);
    m.type = WL_SPH_MOTION_FUNCTION;
    m.x_of_t = NULL;
    CHECK_TRUE(wl_sph_sim_set_motion(sim, 1, &m, &err) == WL_EINPUT, "function motion without function");
    wl_error_clear(&err);
    /* paddle trajectory: particles follow X(t) exactly */
    m.x_of_t = paddle_x;
    CHECK_TRUE(wl_sph_sim_set_motion(sim, 1, &m, &err) == WL_OK, "function motion accepted");
    double x_before = 0;
    unsigned pid = 0;
    for (int i = 0; i < p.n; i++)
      if (p.kind[i] == WL_KIND_MOVING) {
        x_before = p.pos[0][i];
        pid = p.id[i];
        break;
      }
    struct wl_sph_run_opts o = {0};
    o.t_end = 0.1;
    o.output_dt = 0.01;
    o.progress = prog;
    o.progress_wall_s = 1e-9;
    const enum wl_status st = wl_sph_sim_run(sim, &o, &err);
    CHECK_TRUE(st == WL_OK, "paddle run to 0.1 s");
    const struct wl_particles *q = wl_sph_sim_particles(sim, &err);
    double x_after = NAN;
    for (int i = 0; i < q->n; i++)
      if (q->id[i] == pid) x_after = q->pos[0][i];
    CHECK_ABS(x_after - x_before, paddle_x(0.1, NULL), 1e-12, "paddle displacement = prescribed X(t)");
    CHECK_TRUE(n_prog > 0, "progress callback called");
    o.t_end = 0.05;
    CHECK_TRUE(wl_sph_sim_run(sim, &o, &err) == WL_EINPUT, "end time before the current time: WL_EINPUT");
    wl_error_clear(&err);
    o.t_end = 0.2;
    o.output = out_fail;
    CHECK_TRUE(wl_sph_sim_run(sim, &o, &err) == WL_EIO && strstr(err.msg, "test output failure"),
               "an output callback error stops the run with its status");
    CHECK_TRUE(n_out == 1, "output callback called at the start (and the run stopped there)");
    wl_sph_sim_free(sim);
    wl_particles_clear(&p);
  }

  /* ---- particles and scene ---- */
  {
    struct wl_particles p = {0}, q = {0};
    wl_error_clear(&err);
    CHECK_TRUE(wl_particles_alloc(&p, 4, 10, 0, &err) == WL_EINPUT, "4D particles rejected");
    wl_error_clear(&err);
    wl_particles_alloc(&p, 2, 10, 0, &err);
    wl_particles_alloc(&q, 2, 5, 0, &err);
    p.n = 10;
    CHECK_TRUE(wl_particles_copy_state(&q, &p, &err) == WL_EINPUT, "copy into too small a view");
    wl_particles_clear(&p);
    wl_particles_clear(&p); /* safe twice */
    wl_particles_clear(&q);
    CHECK_TRUE(wl_particles_bytes(2, 1000, 1) > wl_particles_bytes(2, 1000, 0),
               "memory estimate counts the work arrays");
    struct wl_sph_params prm;
    wl_sph_params_default(&prm, 2, DP, H);
    struct wl_sph_const k;
    wl_sph_const_make(&prm, &k, &err);
    struct wl_scene sc;
    wl_scene_init(&sc, &k, 0, 0);
    const double x[2] = {0, 0}, z[2] = {1, 1};
    wl_error_clear(&err);
    CHECK_TRUE(wl_scene_boundary_polyline(&sc, x, z, 2, 2, WL_KIND_FIXED, 0, NULL, &err) == WL_EINPUT &&
                   strstr(err.msg, "zero length"),
               "zero-length wall segment rejected");
    wl_error_clear(&err);
    CHECK_TRUE(wl_scene_boundary_polyline(&sc, x, z, 1, 2, WL_KIND_FIXED, 0, NULL, &err) == WL_EINPUT,
               "one-vertex polyline rejected");
    wl_error_clear(&err);
    const double x2[2] = {0, 1};
    CHECK_TRUE(wl_scene_boundary_polyline(&sc, x2, z, 2, 2, WL_KIND_MOVING, 0, NULL, &err) == WL_EINPUT,
               "moving boundary without a body rejected");
    wl_error_clear(&err);
    const double lo[2] = {0, 0}, hi[2] = {0.5 * DP, 1};
    CHECK_TRUE(wl_scene_fluid_block(&sc, lo, hi, 1, &err) == WL_EINPUT, "block thinner than dp rejected");
    wl_error_clear(&err);
    CHECK_TRUE(wl_scene_build(&sc, &p, &err) == WL_EINPUT && strstr(err.msg, "no fluid"),
               "scene without fluid rejected");
    wl_scene_clear(&sc);
    wl_scene_clear(&sc);
  }
  return TEST_RESULT();
}
