/* test_hard_cases.c: the stability matrix of the issue, each run to its end
 * at coarse resolution: a near-breaking solitary wave (H/h = 0.6) hitting
 * the wall, the seed 001 Charlesworth crater (32 lb: eta0 = 2.07 m,
 * R0 = 8.28 m in 16.5 ft of water), and a five-part thrown mass (seed 000)
 * falling back. Reference: the solver's own guard (non-finite values,
 * particles leaving the domain, wall crossings, density out of range, dt
 * collapse) must not fire, and every recorded number must be finite; a
 * fault would stop the run with WL_EUNSTABLE and its diagnosis. */
#include <gsl/gsl_errno.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/assess.h"

static int all_finite(const struct wl_record *r) {
  for (size_t k = 0; k < r->n; k++) {
    if (!isfinite(r->t[k]) || !isfinite(r->force[k]) || !isfinite(r->force_bound[k]) ||
        !isfinite(r->moment[k]) || !isfinite(r->kinetic[k]))
      return 0;
    for (int g = 0; g < r->n_gauges; g++)
      if (!isfinite(r->eta[k * (size_t)r->n_gauges + (size_t)g])) return 0;
  }
  return 1;
}

static void run(const char *name, const char *text, enum wl_load_case load, double t_end) {
  struct wl_scenario s;
  struct wl_plan plan;
  struct wl_error err;
  wl_error_clear(&err);
  wl_scenario_init(&s);
  if (wl_scenario_parse(name, text, strlen(text), &s, &err) || wl_plan_make(&s, &plan, &err)) {
    printf("FAIL %s setup: %s\n", name, err.msg);
    wl_test_failures++;
    return;
  }
  struct wl_assess_opts opts = {0};
  opts.end_time = t_end;
  struct wl_case_result c;
  enum wl_status st = wl_assess_case(&s, &plan, load, &opts, NULL, &c, &err);
  printf("%s: %d particles, %ld steps to t = %.3f s in %.1f s; peak force %.4g N/m, run-up %.4g "
         "m\n",
         name, c.n_particles, c.steps, c.t_reached, c.runtime_s, c.loads.force_peak.value,
         c.loads.runup);
  if (st) printf("  stopped: %s\n", err.msg);
  CHECK_TRUE(st == WL_OK, name);
  CHECK_TRUE(c.t_reached >= t_end - 1e-9, "reached the end time");
  CHECK_TRUE(c.rec.n > 10 && all_finite(&c.rec), "every recorded value is finite");
  wl_assess_case_clear(&c);
  wl_scenario_clear(&s);
}

int main(void) {
  gsl_set_error_handler_off();
  setvbuf(stdout, NULL, _IOLBF, 0); /* progress lines survive a timeout */
  const int quick = getenv("WL_TEST_QUICK") != NULL;
  /* H/h = 0.6 on 0.2 m: the crest reaches the wall at about 1.5 s and the
   * plunging run-up and its fall follow. */
  run("near-breaking solitary H/h = 0.6",
      "scenario: breaking\nwater: {depth: 0.2 m}\ndomain: {length: 4.5 m}\n"
      "wall: {x: 4 m, height: 0.6 m}\n"
      "loads: {solitary: {height: 0.12 m, generation: initial, at: 1.5 m}}\n"
      "resolution: {dp: 0.01 m}\nrun: {output_interval: 0.01 s}\n",
      WL_CASE_SOLITARY, quick ? 1.8 : 3.0);
  /* Seed 001 section 3.1.1 A at coarse resolution (eta0/dp = 8). */
  run("Charlesworth crater (seed 001)",
      "scenario: charlesworth\nwater: {depth: 16.5 ft}\ndomain: {length: 45 m}\n"
      "wall: {x: 40 m, height: 10 m}\ngauges: [{name: G, x: 32.22 m}]\n"
      "loads: {explosion: {charge: 32 lb, at: 15 m, lip_form: axisymmetric}}\n"
      "resolution: {dp: 0.25 m}\nrun: {output_interval: 0.05 s}\n",
      WL_CASE_EXPLOSION, quick ? 3.0 : 8.0);
  /* Seed 000's thrown mass in five parts: launched with the crater's
   * energy, it flies and falls back into the crater. */
  run("five-part thrown mass (seed 000)",
      "scenario: thrown\nwater: {depth: 0.5 m}\ndomain: {length: 6 m}\n"
      "wall: {x: 5 m, height: 1 m}\n"
      "loads: {explosion: {eta0: 0.2 m, r0: 0.6 m, shape: quadratic, model: thrown-mass, "
      "thrown_parts: 5, at: 2.5 m}}\n"
      "resolution: {dp: 0.02 m}\nrun: {output_interval: 0.01 s}\n",
      WL_CASE_EXPLOSION, quick ? 1.0 : 2.5);
  return TEST_RESULT();
}
