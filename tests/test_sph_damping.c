/* test_sph_damping.c: the damping zone of the corrector (sph/integrate.h)
 * and its wiring from the scenario (domain.far_end: damping).
 *
 * References, written out here independently of the code under test:
 *  - one corrector step multiplies a fluid particle's velocity by
 *    max(0, 1 - dt rate w^2), w = clamp((x - x0)/(x1 - x0), 0, 1)
 *    (DualSPHysics' damping zone), with the acceleration zero so that the
 *    unmodified velocity is known exactly;
 *  - outside the zone (w = 0) the velocity is untouched, bit for bit;
 *  - a zone given as x0 > x1 (damping towards smaller x) mirrors it;
 *  - a scenario with far_end: damping puts the zone on the far half of the
 *    land behind the seawall; far_end: wall puts none. */
#include <gsl/gsl_errno.h>
#include <string.h>

#include "testutil.h"
#include "wallload/flume.h"
#include "wallload/plan.h"
#include "wallload/scenario.h"
#include "wallload/sph.h"
#include "wallload/sph/integrate.h"

#define N 7

static void check_zone(double x0, double x1, double rate) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_params prm;
  wl_sph_params_default(&prm, 2, 0.01, 1.0);
  prm.damp_x0[0] = x0;
  prm.damp_x1[0] = x1;
  prm.damp_rate[0] = rate;
  struct wl_sph_const k;
  if (wl_sph_const_make(&prm, &k, &err) != WL_OK) {
    printf("FAIL const: %s\n", err.msg);
    wl_test_failures++;
    return;
  }
  struct wl_particles p;
  if (wl_particles_alloc(&p, 2, N, 1, &err) != WL_OK) {
    printf("FAIL alloc: %s\n", err.msg);
    wl_test_failures++;
    return;
  }
  p.n = N;
  p.n_bound = 0;
  const double dt = 1e-3, lo = x0 < x1 ? x0 : x1, len = x0 < x1 ? x1 - x0 : x0 - x1;
  /* positions from well before the zone to well beyond it */
  const double xs[N] = {lo - len, x0, lo + 0.25 * len, lo + 0.5 * len, lo + 0.9 * len, x1,
                        lo + 2 * len};
  for (int i = 0; i < N; i++) {
    p.kind[i] = WL_KIND_FLUID;
    p.body[i] = 0;
    p.rho[i] = p.rho_h[i] = 1000.0f;
    p.ar[i] = 0;
    p.pos[0][i] = p.pos_h[0][i] = xs[i];
    p.pos[1][i] = p.pos_h[1][i] = 0.5;
    p.vel[0][i] = 1.5f;
    p.vel[1][i] = -0.5f;
    p.ace[0][i] = p.ace[1][i] = 0.0f;
  }
  const double body_vel[WL_SPH_BODIES_MAX + 1][WL_SPH_DIM_MAX] = {{0}};
  for (int i = 0; i < N; i++) wl_sph_correct(2, &k, &p, dt, body_vel, i);
  for (int i = 0; i < N; i++) {
    /* the new position is pos_h + dt/2 v (v before damping, ace = 0) */
    double w = (xs[i] + 0.5 * dt * 1.5 - x0) / (x1 - x0);
    w = w < 0 ? 0 : w > 1 ? 1 : w;
    double f = 1 - dt * rate * w * w;
    f = f < 0 ? 0 : f;
    char what[160];
    snprintf(what, sizeof what, "x = %.3f m: u, w scaled by max(0, 1 - dt rate w^2) = %.6f",
             xs[i], f);
    CHECK_REL((double)p.vel[0][i], 1.5 * f, 2e-7, what);
    CHECK_REL((double)p.vel[1][i], -0.5 * f, 2e-7, what);
    if (w == 0)
      CHECK_TRUE(p.vel[0][i] == 1.5f && p.vel[1][i] == -0.5f, "outside the zone: untouched");
  }
  wl_particles_clear(&p);
}

static void check_scenario(const char *far_end, int want_zone) {
  char text[1024];
  snprintf(text, sizeof text,
           "scenario: land\nwater: {depth: 0.2 m}\ndomain: {length: 4 m, far_end: %s}\n"
           "wall: {x: 3 m, height: 0.22 m}\n"
           "loads: {solitary: {height: 0.06 m, generation: initial, at: 1.5 m}}\n"
           "resolution: {dp: 0.02 m}\n",
           far_end);
  struct wl_scenario s;
  struct wl_plan plan;
  struct wl_flume f;
  struct wl_error err;
  wl_error_clear(&err);
  wl_scenario_init(&s);
  if (wl_scenario_parse("land.yaml", text, strlen(text), &s, &err) ||
      wl_plan_make(&s, &plan, &err) || wl_flume_build(&s, &plan, WL_CASE_SOLITARY, &f, &err)) {
    printf("FAIL setup (%s): %s\n", far_end, err.msg);
    wl_test_failures++;
    wl_scenario_clear(&s);
    return;
  }
  const struct wl_sph_params *prm = &f.cfg.prm;
  if (want_zone) {
    const double x_end = 3.0 + plan.land_length;
    CHECK_TRUE(prm->damp_rate[0] > 0, "far_end: damping switches the zone on");
    CHECK_REL(prm->damp_x1[0], x_end, 1e-12, "the zone reaches the end of the land");
    CHECK_REL(prm->damp_x0[0], x_end - 0.5 * plan.land_length, 1e-12,
              "the zone covers the far half of the land");
  } else {
    CHECK_TRUE(prm->damp_rate[0] == 0, "far_end: wall has no damping zone");
  }
  wl_flume_clear(&f);
  wl_scenario_clear(&s);
}

int main(void) {
  gsl_set_error_handler_off();
  check_zone(2.0, 3.0, 50.0);   /* damping towards +x */
  check_zone(1.0, 0.2, 1500.0); /* towards -x; dt rate = 1.5 clamps the factor at 0 deep in */
  check_scenario("damping", 1);
  check_scenario("wall", 0);
  return TEST_RESULT();
}
