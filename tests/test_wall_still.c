/* test_wall_still.c: still water against the seawall. Reference
 * (REFERENCES.md 1.1, with the model's own compression): the force and the
 * moment about the toe of a Tait column of depth d, d the still level at
 * the wall (the scene lays the water to it), from the pressure probes and
 * from the force summed on the wall's boundary particles, after the
 * start-up has settled (averaged over the last third of the run). The
 * probes read the discrete equilibrium's pressure, 1/kappa of the
 * column's (still_water_ref.h: the SPH gradient's lattice factor); the
 * boundary particles' pair sum reads the column's force. */
#include <gsl/gsl_errno.h>
#include <stdlib.h>
#include <string.h>

#include "still_water_ref.h"
#include "testutil.h"
#include "wallload/assess.h"

/* Issue 17's bar for still water's wall force (0.5 %); the moment keeps
 * 1 %: it weighs the top probe, half a spacing under the level, whose
 * kernel holds only the water below it (the linear fit of sph/probe.h
 * brings it within about 0.2 % of the moment, not to 0). */
#define STILL_TOL_FORCE 0.005
#define STILL_TOL_MOMENT 0.01


int main(void) {
  gsl_set_error_handler_off();
  setvbuf(stdout, NULL, _IOLBF, 0); /* progress lines survive a timeout */
  const int quick = getenv("WL_TEST_QUICK") != NULL;
  const char *text = "scenario: still\nwater: {depth: 0.5 m}\ndomain: {length: 2.5 m}\n"
                     "wall: {x: 2 m, height: 0.8 m, probes: 40}\n"
                     "loads: {solitary: {height: 0.05 m, generation: initial}}\n"
                     "resolution: {dp: 0.02 m}\nrun: {output_interval: 0.02 s}\n";
  struct wl_scenario s;
  struct wl_plan plan;
  struct wl_error err;
  wl_error_clear(&err);
  wl_scenario_init(&s);
  if (wl_scenario_parse("still.yaml", text, strlen(text), &s, &err) ||
      wl_plan_make(&s, &plan, &err)) {
    printf("FAIL setup: %s\n", err.msg);
    return 1;
  }
  struct wl_assess_opts opts = {0};
  opts.end_time = quick ? 0.6 : 1.5;
  struct wl_case_result c;
  enum wl_status st = wl_assess_case(&s, &plan, WL_CASE_STILL, &opts, NULL, &c, &err);
  CHECK_TRUE(st == WL_OK, "still water runs to the end without a fault");
  if (st) printf("  %s\n", err.msg);
  const double rho = 1000, g = 9.81, d = 0.5;
  const double F0 = still_tait_force(d, rho, g, c.c0), M0 = still_tait_moment(d, rho, g, c.c0);
  const double kappa = still_lattice_gradient_factor(2, c.h / c.dp);
  printf("Tait column at c0 = %.2f m/s: F %.2f N/m (incompressible %.2f), M %.2f N m/m "
         "(%.2f); lattice factor at h = %.3f dp: %.5f\n", c.c0, F0, rho * g * d * d / 2, M0,
         rho * g * d * d * d / 6, c.h / c.dp, kappa);
  size_t n = c.rec.n, k0 = 2 * n / 3;
  double F = 0, Fb = 0, M = 0, Mb = 0;
  for (size_t k = k0; k < n; k++)
    F += c.rec.force[k], Fb += c.rec.force_bound[k], M += c.rec.moment[k], Mb += c.rec.moment_bound[k];
  F /= (double)(n - k0), Fb /= (double)(n - k0), M /= (double)(n - k0), Mb /= (double)(n - k0);
  printf("boundary moment %.2f N m/m\n", Mb);
  /* the references' own checks: the lattice sum tends to the continuum's 1
   * on a fine lattice, and the closed forms to their first-order expansions */
  CHECK_REL(still_lattice_gradient_factor(2, 8.0), 1.0, 2e-4, "lattice factor -> 1 as h/dp grows");
  CHECK_REL(still_lattice_gradient_factor(3, 6.0), 1.0, 2e-4, "3D lattice factor -> 1 as h/dp grows");
  CHECK_REL(F0, rho * g * d * d / 2 * (1 + g * d / (3 * c.c0 * c.c0)), 1e-4,
            "Tait force = rho g d^2/2 (1 + g d/(3 c0^2)) to first order");
  CHECK_REL(M0, rho * g * d * d * d / 6 * (1 + g * d / (4 * c.c0 * c.c0)), 1e-4,
            "Tait moment = rho g d^3/6 (1 + g d/(4 c0^2)) to first order");
  printf("still water: probes F = %.2f N/m, boundary F = %.2f N/m, M = %.2f N m/m\n", F, Fb, M);
  CHECK_REL(F, F0 / kappa, STILL_TOL_FORCE, "probe force = the Tait column's / kappa");
  CHECK_REL(M, M0 / kappa, STILL_TOL_MOMENT, "probe moment = the Tait column's / kappa");
  CHECK_REL(Fb, F0, STILL_TOL_FORCE, "boundary-particle force = the Tait column's");
  /* The sanitizer's quick run (0.6 s) has not settled yet: the moment is
   * checked on the full run only. */
  if (!quick) CHECK_REL(Mb, M0, STILL_TOL_MOMENT, "boundary-particle moment = the Tait column's");
  /* impulse is the integral of the stored force series (an independent
   * trapezoid sum here) */
  double I = 0;
  for (size_t k = 1; k < n; k++)
    I += 0.5 * (c.rec.force[k] + c.rec.force[k - 1] - 2 * c.static_force) * (c.rec.t[k] - c.rec.t[k - 1]);
  CHECK_ABS(c.loads.impulse_total, I, 1e-9 * fabs(F0), "impulse = integral of the stored force");
  wl_assess_case_clear(&c);
  wl_scenario_clear(&s);
  return TEST_RESULT();
}
