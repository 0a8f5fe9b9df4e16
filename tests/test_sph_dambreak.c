/* test_sph_dambreak.c: 2D dry-bed dam break against Martin & Moyce (1952).
 *
 * A water column a wide and 2a high (n^2 = 2) collapses at t = 0 in a tank
 * 4a long (DualSPHysics' CaseDambreakVal2D proportions) with walls 5H high:
 * the jet that runs up the far wall after the impact rises beyond 3H and is
 * thrown back over the whole tank, so lower walls would let it escape. Reference: the
 * surge-front position Z = z/a against T = t sqrt(2g/a), Martin & Moyce
 * Table 2 as transcribed in validation_data/martin_moyce1952/ (REFERENCES.md
 * 2.3; the data scatter is about 3 %), on the table points with T >= 1.5
 * (the front has formed) and Z < 3.6 (before the far wall at Z = 4 is felt):
 *  - front speed: the least-squares slope dZ/dT within 5 % of the table's;
 *  - front position after the best single time shift dT (|dT| <= 0.35):
 *    within 5 % in Z at every point.
 * The brief's check, the position as is within 5 %, fails today: it is
 * this program with the argument `front` (ctest sph_dambreak_front, an
 * accuracy test run with ctest -L accuracy), which stops at T = 3.4, the
 * end of the data, and checks the unshifted position only.
 * Why the shift: an inviscid model with a free-slip bed runs ahead of
 * Martin & Moyce by a nearly constant 0.2-0.3 in T that builds up for
 * T < 1.2, while the column is released (their gate/diaphragm) and the
 * bed friction acts; after that the speeds agree. Numerical fronts ahead
 * of dam-break experiments are the usual finding (e.g. Jonsson et al.
 * 2015, Engineering 7:248: "a tendency of the wave front to be ahead of
 * the experimental results"). With this engine the unshifted front is
 * 9-15 % ahead for 1.5 <= T <= 2.9 (a/dp = 40); nothing was tuned to close
 * it.
 * The run then goes on through the impact on the far wall to t sqrt(g/H) =
 * 8 with every value finite and no particle through a wall (the guard
 * would stop it with WL_EUNSTABLE).
 *
 * With the argument `shift` (ctest sph_dambreak_shift) the same run and
 * checks with particle shifting on.
 *
 * Resolution a/dp = 40 (3200 fluid particles), coefsound 20 (see below). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "testutil.h"
#include "wallload/scene.h"
#include "wallload/sph.h"

#define A 1.0           /* column width a [m] */
#define N_A 40          /* a / dp */
#define TOL_Z 0.05      /* brief: 5 % in Z (data scatter ~3 %, REFERENCES 2.3) */
#define TOL_SPEED 0.05  /* front speed dZ/dT */
#define DT_SHIFT_MAX 0.35
#define T_FORMED 1.5    /* front formed (brief) */
#define Z_BEFORE_WALL 3.6
#define TAU_END 8.0     /* t sqrt(g/H) */
#define T_END_MM 3.4    /* T = t sqrt(2g/a): the end of the front data (`front` run) */

struct front_log {
  int n, cap;
  double *t, *x;
  double dp;
  int nonfinite;
};

static enum wl_status on_output(void *user, struct wl_sph_sim *sim, double t, struct wl_error *err) {
  struct front_log *lg = user;
  const struct wl_particles *p = wl_sph_sim_particles(sim, err);
  if (!p) return err->status;
  double xmax = -1e30;
  for (int i = p->n_bound; i < p->n; i++) {
    if (!isfinite(p->pos[0][i]) || !isfinite(p->pos[1][i]) || !isfinite(p->rho[i])) lg->nonfinite++;
    if (p->pos[0][i] > xmax) xmax = p->pos[0][i];
  }
  if (lg->n == lg->cap) {
    lg->cap = lg->cap ? 2 * lg->cap : 256;
    lg->t = realloc(lg->t, sizeof(double) * (size_t)lg->cap);
    lg->x = realloc(lg->x, sizeof(double) * (size_t)lg->cap);
    if (!lg->t || !lg->x) return wl_error_set(err, WL_ENOMEM, "test: out of memory");
  }
  lg->t[lg->n] = t;
  lg->x[lg->n] = xmax + 0.5 * lg->dp; /* the fluid's edge, half a spacing beyond the last centre */
  lg->n++;
  return WL_OK;
}

static double interp(const double *x, const double *y, int n, double xq) {
  if (xq <= x[0]) return y[0];
  for (int i = 1; i < n; i++)
    if (xq <= x[i]) return y[i - 1] + (y[i] - y[i - 1]) * (xq - x[i - 1]) / (x[i] - x[i - 1]);
  return y[n - 1];
}

int main(int argc, char **argv) {
  const int front_only = argc > 1 && !strcmp(argv[1], "front");
  /* `shift`: the same run and checks with particle shifting on (sph/shift.h,
   * A = 2; ctest sph_dambreak_shift): the overturning jet and its splash
   * are where shifting works hardest */
  const int shifting = argc > 1 && !strcmp(argv[1], "shift");
  const double dp = A / N_A, H = 2 * A, L = 4 * A, g = 9.81;
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
  /* coefsound 20: with the default 10, the front runs at up to 0.3 c0 and
   * the fluid compresses visibly at the impact (DualSPHysics' dam-break
   * examples use 20 as well) */
  cfg.prm.coefsound = 20;
  if (shifting) cfg.prm.shift_coef = 2.0;
  struct wl_sph_const k;
  if (wl_sph_const_make(&cfg.prm, &k, &err) != WL_OK) {
    printf("FAIL const: %s\n", err.msg);
    return 1;
  }
  const double margin = (layers + 2) * dp;
  cfg.lo[0] = -margin;
  cfg.hi[0] = L + margin;
  cfg.lo[1] = -margin;
  cfg.hi[1] = 6 * H;

  struct wl_scene sc;
  wl_scene_init(&sc, &k, 0, 0);
  const double tank_x[4] = {0, 0, L, L}, tank_z[4] = {5 * H, 0, 0, 5 * H};
  const double lo[2] = {0, 0}, hi[2] = {A, H};
  struct wl_particles init = {0};
  if (wl_scene_boundary_polyline(&sc, tank_x, tank_z, 4, layers, WL_KIND_FIXED, 0, &cfg, &err) ||
      wl_scene_fluid_block(&sc, lo, hi, H, &err) || wl_scene_build(&sc, &init, &err)) {
    printf("FAIL scene: %s\n", err.msg);
    return 1;
  }
  wl_scene_clear(&sc);
  printf("dam break: %d particles (%d boundary), dp = %g m, h = %g m, c0 = %g m/s\n", init.n,
         init.n_bound, dp, k.h_d, k.c0_d);

  struct wl_sph_sim *sim = NULL;
  if (wl_sph_sim_alloc(&sim, &wl_backend_cpu_ops, &cfg, &init, &err) != WL_OK) {
    printf("FAIL sim: %s\n", err.msg);
    return 1;
  }
  wl_particles_clear(&init);

  struct front_log lg = {0};
  lg.dp = dp;
  const double t_scale = sqrt(2 * g / A); /* T = t sqrt(2g/a) */
  struct wl_sph_run_opts opts = {0};
  opts.t_end = front_only ? T_END_MM / t_scale : TAU_END * sqrt(H / g);
  opts.output_dt = 0.02 / t_scale; /* every 0.02 in T */
  opts.output = on_output;
  opts.user = &lg;
  const clock_t c0 = clock();
  const time_t w0 = time(NULL);
  enum wl_status st = wl_sph_sim_run(sim, &opts, &err);
  printf("run: status %s%s%s, t = %g s, %ld steps, cpu %.1f s, wall ~%ld s\n",
         wl_error_status_name(st), st ? ": " : "", st ? err.msg : "", wl_sph_sim_time(sim),
         wl_sph_sim_steps(sim), (double)(clock() - c0) / CLOCKS_PER_SEC, (long)(time(NULL) - w0));
  CHECK_TRUE(st == WL_OK, front_only ? "run through the front phase without a guard fault"
                                     : "run to t sqrt(g/H) = 8 through the wall impact without a "
                                       "guard fault");
  CHECK_TRUE(lg.nonfinite == 0, "all fluid positions and densities finite at every output");
  if (!front_only) CHECK_ABS(wl_sph_sim_time(sim) * sqrt(g / H), TAU_END, 1e-9, "end time reached");

  /* Martin & Moyce Table 2 (n^2 = 2), from the shared validation data */
  char path[1024];
  snprintf(path, sizeof path, "%s/validation_data/martin_moyce1952/"
           "martin_moyce_table2_table6_from_ocellaris.txt", WL_SHARED_DIR);
  FILE *f = fopen(path, "r");
  if (!f) {
    printf("FAIL cannot open %s\n", path);
    return 1;
  }
  char line[256];
  int section = 0, n = 0;
  double te[64], ze[64];
  double *T = malloc(sizeof(double) * (size_t)lg.n), *Z = malloc(sizeof(double) * (size_t)lg.n);
  for (int i = 0; i < lg.n; i++) {
    T[i] = lg.t[i] * t_scale;
    Z[i] = lg.x[i] / A;
  }
  while (fgets(line, sizeof line, f)) {
    if (line[0] == '#') {
      if (strstr(line, "Residual")) section = 2;
      continue;
    }
    double tt, zz;
    if (sscanf(line, "%lf %lf", &tt, &zz) == 2 && section == 0) {
      printf("  T = %.2f  Z_exp = %.2f  Z_sph = %.3f  (%+.1f %%)\n", tt, zz, interp(T, Z, lg.n, tt),
             100 * (interp(T, Z, lg.n, tt) / zz - 1));
      if (tt >= T_FORMED && zz < Z_BEFORE_WALL && n < 64) {
        te[n] = tt;
        ze[n] = zz;
        n++;
      }
    }
  }
  fclose(f);
  CHECK_TRUE(n >= 6, "enough Martin & Moyce points in the checked range");
  /* Koshizuka & Oka (1996), the second reference, printed beside:
   * its only source here is one digitization of a figure (PySPH's
   * db_exp_data.py), and between T = 1.5 and 3.1 its front advances at
   * dZ/dT = 1.08 (least squares), 20 % below Martin & Moyce's 1.35 over the
   * same T for the same n^2 = 2 column, far outside both data sets'
   * scatter (about 3 %). The
   * checks use Martin & Moyce, whose Table 2 two independent transcriptions
   * reproduce within 0.02 (REFERENCES.md 2.3-2.4). */
  snprintf(path, sizeof path, "%s/validation_data/pysph_digitized/ko_data.txt", WL_SHARED_DIR);
  if ((f = fopen(path, "r"))) {
    while (fgets(line, sizeof line, f)) {
      double tt, zz;
      if (line[0] != '#' && sscanf(line, "%lf %lf", &tt, &zz) == 2 && tt >= T_FORMED)
        printf("  Koshizuka & Oka: T = %.3f  Z_exp = %.3f  Z_sph = %.3f  (%+.1f %%)\n", tt, zz,
               interp(T, Z, lg.n, tt), 100 * (interp(T, Z, lg.n, tt) / zz - 1));
    }
    fclose(f);
  } else {
    printf("# Koshizuka & Oka data not found (%s): not printed\n", path);
  }
  if (front_only) {
    for (int i = 0; i < n; i++)
      CHECK_REL(interp(T, Z, lg.n, te[i]), ze[i], TOL_Z,
                "Martin & Moyce (1952) Table 2 surge front, unshifted (brief: 5 % in Z)");
    free(T);
    free(Z);
    free(lg.t);
    free(lg.x);
    wl_sph_sim_free(sim);
    return TEST_RESULT();
  }
  /* front speed: least-squares slopes over the same T points */
  double sT = 0, sze = 0, szs = 0, stt = 0, stze = 0, stzs = 0;
  for (int i = 0; i < n; i++) {
    const double zs = interp(T, Z, lg.n, te[i]);
    sT += te[i];
    sze += ze[i];
    szs += zs;
    stt += te[i] * te[i];
    stze += te[i] * ze[i];
    stzs += te[i] * zs;
  }
  const double den = n * stt - sT * sT;
  const double slope_exp = (n * stze - sT * sze) / den, slope_sph = (n * stzs - sT * szs) / den;
  CHECK_REL(slope_sph, slope_exp, TOL_SPEED, "Martin & Moyce (1952) Table 2: front speed dZ/dT");
  /* best time shift (least squares over a fine grid of shifts) */
  double best = 0, best_err = 1e30;
  for (double sh = -DT_SHIFT_MAX; sh <= DT_SHIFT_MAX + 1e-12; sh += 0.005) {
    double e2 = 0;
    for (int i = 0; i < n; i++) {
      const double d = interp(T, Z, lg.n, te[i] + sh) - ze[i];
      e2 += d * d;
    }
    if (e2 < best_err) {
      best_err = e2;
      best = sh;
    }
  }
  printf("best time shift: SPH at T - %.3f matches the data at T\n", -best);
  CHECK_TRUE(best > -DT_SHIFT_MAX && best < DT_SHIFT_MAX,
             "time shift within the bound (not at the search edge)");
  for (int i = 0; i < n; i++) {
    CHECK_REL(interp(T, Z, lg.n, te[i] + best), ze[i], TOL_Z,
              "Martin & Moyce (1952) Table 2 surge front, after the best time shift");
  }
  free(T);
  free(Z);
  free(lg.t);
  free(lg.x);
  wl_sph_sim_free(sim);
  return TEST_RESULT();
}
