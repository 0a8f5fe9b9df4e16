/* test_isph_solitary_wall.c: the projection solver (issue 22, docs/isph.md)
 * on the project's solitary wave on a vertical wall, the scene of
 * test_solitary_wall.c (h = 0.2 m, H/h = 0.3, dp = 0.01 m, the exact wave
 * of waves.h as the initial condition, built by the flume as `assess` builds
 * it). References, as test_solitary_wall.c:
 *  - the impulse of the force on the wall's boundary particles above the
 *    force at rest, int (F - F_rest) dt = 2 I (REFERENCES 4.2, exact for
 *    inviscid reflection; I from the exact-wave table, REFERENCES 3.4),
 *    within 5 % (REFERENCES 6), read when the reflected crest is back where
 *    the incident one started;
 *  - the maximum run-up, Su & Mirie (1980), R/h = 2 e + e^2/2 + 3/4 e^3
 *    (REFERENCES 4.1, coefficients marked UNCONFIRMED there), within 5 %:
 *    the highest fluid particle within dp of the face, plus dp/2 (a
 *    particle's volume reaches half a spacing above its centre), above the
 *    still-water level.
 * The weakly-compressible solver's figures on the same scene (validate
 * solitary_wall, reference/RESULTS.md) are printed beside them. Not in the
 * default suite: an accuracy test (scripts/test.sh --accuracy), failing on
 * its impulse (2026-11-26: -46 %, run-up -2.4 %; docs/isph.md). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/backend.h"
#include "wallload/flume.h"
#include "wallload/plan.h"
#include "wallload/sph.h"

struct acc {
  double x_wall, dp, depth; /* the face, the spacing, the still-water level [m] */
  int n;
  double t[4096], force[4096], runup;
};

static enum wl_status on_output(void *user, struct wl_sph_sim *sim, double t, struct wl_error *err) {
  struct acc *a = user;
  if (a->n >= 4096) return WL_OK;
  double f = NAN, mo = NAN;
  enum wl_status st = wl_sph_sim_wall_load(sim, WL_FLUME_BODY_WALL, 0.0, &f, &mo, err);
  if (st) return st;
  const struct wl_particles *p = wl_sph_sim_particles(sim, err);
  if (!p) return err->status;
  for (int i = p->n_bound; i < p->n; i++)
    if (p->pos[0][i] > a->x_wall - a->dp) a->runup = fmax(a->runup, p->pos[1][i] + 0.5 * a->dp - a->depth);
  a->t[a->n] = t;
  a->force[a->n] = f;
  a->n++;
  return WL_OK;
}

int main(void) {
  gsl_set_error_handler_off();
  setvbuf(stdout, NULL, _IOLBF, 0);
  const double h = 0.2, eps = 0.3, H = eps * h, rho = 1000, g = 9.81, dp = 0.01;
  const double I_table = 1.559253; /* REFERENCES 3.4, exact wave at eps 0.3 */
  const double K = sqrt(3 * H / (4 * h * h * h)), length = 6 / K;
  const double c = sqrt(g * h) * sqrt(1 + eps - eps * eps / 20 - 3 * eps * eps * eps / 70);
  const double x0 = 0.55 * length, xw = x0 + 0.75 * length;
  const double t_back = 1.5 * length / c; /* the reflected crest back at x0 */
  char text[1024];
  snprintf(text, sizeof text,
           "scenario: wall\nwater: {depth: %g m}\ndomain: {length: %g m}\n"
           "wall: {x: %g m, height: %g m, probes: 40}\n"
           "loads: {solitary: {height: %g m, theory: exact, generation: initial, at: %g m}}\n"
           "resolution: {dp: %g m}\n",
           h, xw + 0.5, xw, 3 * h, H, x0, dp);
  struct wl_scenario s;
  struct wl_plan plan;
  struct wl_flume f;
  memset(&f, 0, sizeof f);
  struct wl_error err;
  wl_error_clear(&err);
  wl_scenario_init(&s);
  if (wl_scenario_parse("wall.yaml", text, strlen(text), &s, &err) ||
      wl_plan_make(&s, &plan, &err) || wl_flume_build(&s, &plan, WL_CASE_SOLITARY, &f, &err)) {
    printf("FAIL setup: %s\n", err.msg);
    return 1;
  }
  f.cfg.n_threads = 2;
  struct wl_sph_sim *sim = NULL;
  if (wl_sph_sim_alloc(&sim, &wl_backend_isph_ops, &f.cfg, &f.particles, &err) != WL_OK) {
    printf("FAIL the ISPH backend refused the flume: %s\n", err.msg);
    wl_flume_clear(&f);
    return 1;
  }
  static struct acc a;
  a.x_wall = f.x_wall;
  a.dp = dp;
  a.depth = f.depth;
  a.runup = -INFINITY;
  struct wl_sph_run_opts opts = {0};
  opts.t_end = t_back;
  opts.output_dt = 0.005;
  opts.output = on_output;
  opts.user = &a;
  const enum wl_status st = wl_sph_sim_run(sim, &opts, &err);
  CHECK_TRUE(st == WL_OK, "the ISPH reflection runs to the reflected crest's return");
  if (st) printf("  stopped: %s\n", err.msg);
  const long steps = wl_sph_sim_steps(sim);
  wl_sph_sim_free(sim);
  /* the force at rest: its mean before the wave's front raises the water at
   * the wall (the first 0.1 s; the front is at 1e-4 H there) */
  double rest = 0;
  int nr = 0;
  for (int i = 0; i < a.n && a.t[i] <= 0.1; i++) rest += a.force[i], nr++;
  rest = nr ? rest / nr : NAN;
  double imp = 0;
  for (int i = 1; i < a.n; i++)
    imp += 0.5 * (a.force[i] + a.force[i - 1] - 2 * rest) * (a.t[i] - a.t[i - 1]);
  if (getenv("WL_TEST_TRACE"))
    for (int i = 0; i < a.n; i += 20) printf("  t = %.3f s: force %.2f N/m\n", a.t[i], a.force[i]);
  const double I2 = 2 * I_table * rho * h * h * sqrt(g * h);
  const double R_ref = h * (2 * eps + eps * eps / 2 + 0.75 * eps * eps * eps);
  printf("ISPH, eps = %.2f, dp = %g m: %ld steps to t = %.3f s; force at rest %.2f N/m "
         "(rho g h^2/2 = %.2f); boundary impulse %.2f N s/m (2I = %.2f, %+.2f %%); run-up %.4f m "
         "(Su & Mirie %.4f m, %+.2f %%)\n",
         eps, dp, steps, a.n ? a.t[a.n - 1] : NAN, rest, 0.5 * rho * g * h * h, imp, I2,
         100 * (imp / I2 - 1), a.runup, R_ref, 100 * (a.runup / R_ref - 1));
  printf("  (WCSPH on the same scene, validate solitary_wall at dp = 0.01 m: boundary impulse "
         "-2.7 %%, probes -1.7 %%, run-up -1.8 %%; reference/RESULTS.md)\n");
  CHECK_REL(imp, I2, 0.05, "ISPH boundary impulse = 2 I (REFERENCES 4.2 and 3.4)");
  CHECK_REL(a.runup, R_ref, 0.05, "ISPH maximum run-up, Su & Mirie (1980)");
  wl_flume_clear(&f);
  wl_scenario_clear(&s);
  return TEST_RESULT();
}
