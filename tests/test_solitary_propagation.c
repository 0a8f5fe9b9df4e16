/* test_solitary_propagation.c: a Grimshaw solitary wave (seed 003 eqs
 * 21-24) placed as an initial condition on h = 0.2 m, H/h = 0.2 and 0.4,
 * runs over a flat bed. References: its celerity, seed 003 eq 23 (and the
 * exact solitary wave of REFERENCES 3.4 beside it); the amplitude loss
 * after the run is reported and compared with seed 003's ISPH (10 % after
 * 5 s), which wallload must beat. Crest arrival times at gauges 0.5 m apart
 * (parabolic peak interpolation), fitted by least squares, give the speed.
 * Measured 2026-11-23 (h = 1.70 dp, laminar viscosity): H/h = 0.4, speed
 * -1.2 %, height loss 2.4 % in 4.7 s; H/h = 0.2 (H/dp = 4), speed -0.65 %,
 * the gauges read 4-10 % above H (a quarter of dp: the gauge's resolution
 * at H/dp = 4), so its loss check is weak there and H/h = 0.4 is the one
 * that matters. */
#include <gsl/gsl_errno.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/assess.h"

/* Celerity tolerance of the issue: 2 % of seed 003 eq 23. */
#define CELERITY_TOL 0.02
/* Seed 003's ISPH amplitude loss after 5 s, the figure to beat. */
#define ISPH_LOSS 0.10

static void crest(const struct wl_record *r, int g, double *t_peak, double *a_peak) {
  size_t best = 0;
  for (size_t k = 0; k < r->n; k++)
    if (r->eta[k * (size_t)r->n_gauges + (size_t)g] > r->eta[best * (size_t)r->n_gauges + (size_t)g])
      best = k;
  double tp = r->t[best], ap = r->eta[best * (size_t)r->n_gauges + (size_t)g];
  if (best > 0 && best + 1 < r->n) { /* parabola through the three samples */
    double y0 = r->eta[(best - 1) * (size_t)r->n_gauges + (size_t)g], y1 = ap,
           y2 = r->eta[(best + 1) * (size_t)r->n_gauges + (size_t)g];
    double den = y0 - 2 * y1 + y2, dt = r->t[best + 1] - r->t[best];
    if (den < 0) {
      double s = 0.5 * (y0 - y2) / den;
      tp += s * dt;
      ap = y1 - 0.25 * (y0 - y2) * s;
    }
  }
  *t_peak = tp;
  *a_peak = ap;
}

static void run(double eps, double t_run, double dp) {
  const double h = 0.2, H = eps * h, x0 = 2.0;
  double c_ref = sqrt(9.81 * h) * sqrt(1 + eps - eps * eps / 20 - 3 * eps * eps * eps / 70);
  double x_end = x0 + c_ref * t_run;
  const double spacing = 0.5; /* gauges every 0.5 m from x0 + 0.25 m */
  int n_g = (int)floor((x_end - x0 - 0.25) / spacing);
  char text[2048], gauges[1024] = "";
  for (int g = 0; g < n_g; g++) {
    size_t u = strlen(gauges);
    snprintf(gauges + u, sizeof gauges - u, "%s{name: G%d, x: %.3f m}", g ? ", " : "", g,
             x0 + 0.25 + spacing * g);
  }
  snprintf(text, sizeof text,
           "scenario: prop\nwater: {depth: %g m}\ndomain: {length: %g m}\n"
           "wall: {x: %g m, height: 0.6 m}\ngauges: [%s]\n"
           "loads: {solitary: {height: %g m, generation: initial, at: %g m}}\n"
           "resolution: {dp: %g m}\nrun: {output_interval: 0.01 s}\n",
           h, x_end + 3.0, x_end + 2.0, gauges, H, x0, dp);
  struct wl_scenario s;
  struct wl_plan plan;
  struct wl_error err;
  wl_error_clear(&err);
  wl_scenario_init(&s);
  if (wl_scenario_parse("prop.yaml", text, strlen(text), &s, &err) ||
      wl_plan_make(&s, &plan, &err)) {
    printf("FAIL setup: %s\n", err.msg);
    wl_test_failures++;
    return;
  }
  struct wl_assess_opts opts = {0};
  opts.end_time = t_run;
  struct wl_case_result c;
  enum wl_status st = wl_assess_case(&s, &plan, WL_CASE_SOLITARY, &opts, NULL, &c, &err);
  CHECK_TRUE(st == WL_OK, "the solitary wave runs without a fault");
  if (st) printf("  %s\n", err.msg);
  /* least-squares speed from crest arrivals at the gauges the crest passed */
  double sx = 0, st_ = 0, sxx = 0, sxt = 0, a_first = 0, a_last = 0, t_last = 0;
  int m = 0;
  for (int g = 0; g < n_g; g++) {
    double tp, ap;
    crest(&c.rec, g, &tp, &ap);
    if (tp <= c.rec.t[0] + 0.05 || tp >= c.rec.t[c.rec.n - 1] - 0.05) continue;
    double xg = x0 + 0.25 + spacing * g;
    sx += tp, st_ += xg, sxx += tp * tp, sxt += tp * xg;
    if (m == 0) a_first = ap;
    a_last = ap, t_last = tp;
    m++;
  }
  double speed = m > 1 ? (m * sxt - sx * st_) / (m * sxx - sx * sx) : NAN;
  printf("eps = %.2f, dp = %g m (H/dp = %.1f), %d particles, %ld steps, %.1f s: speed %.4f m/s "
         "(eq 23: %.4f), amplitude %.4f m at the first gauge, %.4f m at t = %.2f s: loss %.1f %% "
         "of H (seed 003 ISPH: %.0f %% after 5 s)\n",
         eps, dp, H / dp, c.n_particles, c.steps, c.runtime_s, speed, c_ref, a_first, a_last,
         t_last, 100 * (H - a_last) / H, 100 * ISPH_LOSS);
  CHECK_TRUE(m >= 2, "the crest passed at least two gauges");
  CHECK_REL(speed, c_ref, CELERITY_TOL, "celerity, seed 003 eq 23");
  /* The ISPH of seed 003 lost 10 % over 5 s; scale that loss to this run's
   * duration and require no worse. */
  CHECK_TRUE((H - a_last) / H < ISPH_LOSS * fmax(t_last, 1.0) / 5.0 + 0.02,
             "amplitude loss below seed 003's ISPH (10 % per 5 s, +2 % gauge resolution)");
  wl_assess_case_clear(&c);
  wl_scenario_clear(&s);
}

/* Run lengths [s]: the default suite propagates the H/h = 0.4 wave for
 * 2.5 s (CI's time budget; H/h = 0.2's loss check is weak at H/dp = 4, see
 * above, and the validate cases judge that wave); `test_solitary_propagation
 * full` (ctest solitary_propagation_full, label extended) runs both waves for
 * the 5 s of seed 003's comparison; the sanitizer's quick run H/h = 0.4 for
 * 1.5 s. */
#define T_DEFAULT 2.5
#define T_FULL 5.0
#define T_QUICK 1.5

int main(int argc, char **argv) {
  gsl_set_error_handler_off();
  setvbuf(stdout, NULL, _IOLBF, 0); /* progress lines survive a timeout */
  const int quick = getenv("WL_TEST_QUICK") != NULL;
  const int full = argc > 1 && !strcmp(argv[1], "full");
  const double t = quick ? T_QUICK : full ? T_FULL : T_DEFAULT;
  run(0.4, t, 0.01);
  if (full) run(0.2, t, 0.01);
  return TEST_RESULT();
}
