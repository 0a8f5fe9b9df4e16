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
 *    the flume's gauge at the face.
 * Both wall loads are the project's sampler's (sample.h): the pressure
 * probes integrated over the wet face, and the force on the wall's
 * boundary particles (the ISPH backend's wall_load).
 * The weakly-compressible solver's figures on the same scene (validate
 * solitary_wall, reference/RESULTS.md) are printed beside them. Not in the
 * default suite: an accuracy test (scripts/test.sh --accuracy), failing on
 * the boundary particles' impulse (2026-11-26: -46 %; probes +2.1 %, run-up
 * -0.1 %; docs/isph.md) and on the wall force's noise after the reflection
 * (2026-11-27: 97 N/m, the bar 3.9): the probes' whole-record impulse
 * (-0.3 % that day) integrates that noise and passes by chance. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/backend.h"
#include "wallload/flume.h"
#include "wallload/plan.h"
#include "wallload/sample.h"
#include "wallload/sph.h"

struct acc {
  struct wl_sample *smp;
  struct wl_record rec;
};

/* One row of the project's sampler (sample.h): probes, boundary load,
 * gauges (the last one at the wall's face), momentum. */
static enum wl_status on_output(void *user, struct wl_sph_sim *sim, double t, struct wl_error *err) {
  struct acc *a = user;
  const struct wl_particles *p = wl_sph_sim_particles(sim, err);
  if (!p) return err->status;
  return wl_sample_sim(a->smp, sim, p, t, &a->rec, err);
}

/* int (F - F_rest) dt over the record [N s/m], F_rest the mean of the first
 * 0.1 s (the front raises the water at the wall by 1e-4 H there). */
static double impulse(const struct wl_record *r, const double *F, double *rest) {
  double fr = 0, imp = 0;
  int nr = 0;
  for (size_t i = 0; i < r->n && r->t[i] <= 0.1; i++) fr += F[i], nr++;
  fr = nr ? fr / nr : NAN;
  for (size_t i = 1; i < r->n; i++) imp += 0.5 * (F[i] + F[i - 1] - 2 * fr) * (r->t[i] - r->t[i - 1]);
  *rest = fr;
  return imp;
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
  struct acc a;
  memset(&a, 0, sizeof a);
  a.rec.n_gauges = f.n_gauges;
  a.rec.n_probes = f.n_probes;
  if (wl_sample_alloc(&a.smp, &f, &err) != WL_OK) {
    printf("FAIL sampler: %s\n", err.msg);
    return 1;
  }
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
  const struct wl_record *r = &a.rec;
  double rest_p, rest_b, runup = -INFINITY;
  const double imp_p = impulse(r, r->force, &rest_p), imp_b = impulse(r, r->force_bound, &rest_b);
  for (size_t i = 0; i < r->n; i++)
    runup = fmax(runup, r->eta[i * (size_t)r->n_gauges + (size_t)(r->n_gauges - 1)]);
  if (getenv("WL_TEST_TRACE"))
    for (size_t i = 0; i < r->n; i += 20)
      printf("  t = %.3f s: force probes %.2f, boundary %.2f N/m\n", r->t[i], r->force[i],
             r->force_bound[i]);
  const double I2 = 2 * I_table * rho * h * h * sqrt(g * h);
  /* The wall force's noise over the record's last 30 %, after the
   * reflection: the rms of F_i - (F_{i-1} + F_{i+1})/2 at the 5 ms outputs.
   * A force record the wave makes is smooth at that spacing (the first
   * 1.7 s read 1.9 N/m); issue 22 asks for wall pressure quoted without a
   * filter, so the noise is held to 2 % of the force at rest. 2026-11-27:
   * 97 N/m, the projection's pressure degrading after 1.8 s (docs/isph.md). */
  double noise = 0;
  size_t n_noise = 0;
  for (size_t i = (size_t)(0.7 * (double)r->n) + 1; i + 1 < r->n; i++, n_noise++) {
    const double d = r->force[i] - 0.5 * (r->force[i - 1] + r->force[i + 1]);
    noise += d * d;
  }
  noise = n_noise ? sqrt(noise / (double)n_noise) : NAN;
  const double R_ref = h * (2 * eps + eps * eps / 2 + 0.75 * eps * eps * eps);
  printf("ISPH, eps = %.2f, dp = %g m: %ld steps to t = %.3f s; force at rest %.2f (probes), "
         "%.2f (boundary) N/m (rho g h^2/2 = %.2f); impulse probes %.2f, boundary %.2f N s/m "
         "(2I = %.2f: %+.2f %%, %+.2f %%); run-up %.4f m (Su & Mirie %.4f m, %+.2f %%)\n",
         eps, dp, steps, r->n ? r->t[r->n - 1] : NAN, rest_p, rest_b, 0.5 * rho * g * h * h, imp_p,
         imp_b, I2, 100 * (imp_p / I2 - 1), 100 * (imp_b / I2 - 1), runup, R_ref,
         100 * (runup / R_ref - 1));
  printf("  (WCSPH on the same scene, validate solitary_wall at dp = 0.01 m: probes -1.7 %%, "
         "boundary -2.7 %%, run-up -1.8 %%; reference/RESULTS.md)\n");
  printf("  wall force noise over the last 30 %% of the record: %.2f N/m (bar: 2 %% of the force "
         "at rest, %.2f N/m)\n", noise, 0.02 * rest_p);
  CHECK_TRUE(noise < 0.02 * rest_p, "the wall force after the reflection is not noise");
  CHECK_REL(imp_p, I2, 0.05, "ISPH probe impulse = 2 I (REFERENCES 4.2 and 3.4)");
  CHECK_REL(imp_b, I2, 0.05, "ISPH boundary impulse = 2 I (REFERENCES 4.2 and 3.4)");
  CHECK_REL(runup, R_ref, 0.05, "ISPH maximum run-up (the wall gauge), Su & Mirie (1980)");
  wl_sample_record_clear(&a.rec);
  wl_sample_free(a.smp);
  wl_flume_clear(&f);
  wl_scenario_clear(&s);
  return TEST_RESULT();
}
