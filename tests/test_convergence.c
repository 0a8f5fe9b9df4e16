/* test_convergence.c: the convergence ladder's arithmetic (wl_loads_convergence)
 * and its storage (assess writes, the report reads back).
 *
 * References from outside the code under test:
 *  - synthetic sequences f(h) = f* + C h^p with p, f*, C chosen here, so
 *    the observed order is p, the Richardson value f* and the uncertainty
 *    1.25 |C h3^p| / |f3|, written out below; with the ladder factors 1,
 *    0.71, 0.5 (unequal ratios 1.408, 1.42) and with a constant ratio
 *    sqrt 2;
 *  - the published worked example of Celik et al. (2008), Table 1;
 *  - the other bands by hand (loads.h): an order above 2.05 (capped),
 *    below 0.95, oscillating and diverging values (3 x range), two levels
 *    (Roache's two-grid index), one level (no estimate);
 *  - storage: a tiny assessment with a 3-level ladder, its /convergence
 *    group read back through the report's HDF5 reader (a second code path)
 *    and summary.json's numbers parsed from the text; both must equal what
 *    the driver held in memory. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include "wallload/assess.h"
#include "wallload/loads.h"
#include "wallload/plan.h"
#include "wallload/scenario.h"

#include "wallload/store.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int failures;

static void check(int ok, const char *what) {
  printf("%s %s\n", ok ? "PASS" : "FAIL", what);
  if (!ok) failures++;
}

static int close_rel(double a, double b, double tol) {
  if (isnan(a) && isnan(b)) return 1;
  return fabs(a - b) <= tol * fmax(fabs(a), fabs(b));
}

/* f = fstar + C h^p at the spacings h[0..n) */
static void power_law(const double *h, int n, double fstar, double C, double p, double *f) {
  for (int k = 0; k < n; k++) f[k] = fstar + C * pow(h[k], p);
}

static void test_synthetic(void) {
  char msg[320];
  struct wl_loads_convergence cv;
  const double dp = 0.02;
  /* the ladder of the scenarios: factors 1, 0.71, 0.5 (ratios 1.408, 1.42) */
  double h[3] = {dp, 0.71 * dp, 0.5 * dp}, f[3];
  const double ps[] = {1.0, 2.0};
  for (int i = 0; i < 2; i++) {
    double p = ps[i], fstar = 1234.5, C = -8.0e4;
    power_law(h, 3, fstar, C, p, f);
    wl_loads_convergence(h, f, 3, &cv);
    /* p in [0.95, 2.05): Roache's GCI, 1.25 |f3 - f*| / |f3|, by hand */
    double u = 1.25 * fabs(C * pow(h[2], p)) / fabs(f[2]);
    snprintf(msg, sizeof msg,
             "f = f* + C h^p, p = %.1f, ladder 1/0.71/0.5: order %.12g (%.1f), f_ext %.12g "
             "(f* %.1f), uncertainty %.6g (1.25 |C h3^p|/|f3| = %.6g), GCI",
             p, cv.order, p, cv.extrapolated, fstar, cv.error, u);
    check(cv.order_ok && close_rel(cv.order, p, 1e-9) && close_rel(cv.extrapolated, fstar, 1e-9) &&
              close_rel(cv.error, u, 1e-7) && cv.basis == WL_LOADS_EST_GCI,
          msg);
  }
  /* p = 3.5 >= 2.05: the order is reported and extrapolated, but the band
   * uses order 2 and at least 1.25 x the range (Eca & Hoekstra): by hand */
  {
    double fstar = 1234.5, C = -8.0e4 * 50;
    power_law(h, 3, fstar, C, 3.5, f);
    wl_loads_convergence(h, f, 3, &cv);
    double r32 = h[1] / h[2];
    double d2 = fabs(f[2] - f[1]) / (r32 * r32 - 1), range = fabs(f[2] - f[0]);
    double u = fmax(1.25 * d2, 1.25 * range) / fabs(f[2]);
    snprintf(msg, sizeof msg,
             "p = 3.5: order %.6g, f_ext %.9g = f*, uncertainty %.6g = max(1.25 delta(p=2), 1.25 "
             "range)/|f3| = %.6g, order capped",
             cv.order, cv.extrapolated, cv.error, u);
    check(cv.order_ok && close_rel(cv.order, 3.5, 1e-9) && close_rel(cv.extrapolated, fstar, 1e-9) &&
              close_rel(cv.error, u, 1e-12) && cv.basis == WL_LOADS_EST_GCI_HIGH,
          msg);
  }
  /* constant ratio sqrt 2: the closed form p = ln((f1-f2)/(f2-f3))/ln r */
  double hs[4] = {0.04, 0.04 / sqrt(2.0), 0.02, 0.02 / sqrt(2.0)}, fs[4];
  power_law(hs, 4, 50.0, 3.0e3, 2.0, fs);
  wl_loads_convergence(hs, fs, 4, &cv); /* uses the last three */
  double r = sqrt(2.0);
  double p_hand = log((fs[1] - fs[2]) / (fs[2] - fs[3])) / log(r);
  double ext_hand = fs[3] + (fs[3] - fs[2]) / (pow(r, p_hand) - 1);
  snprintf(msg, sizeof msg,
           "constant ratio sqrt 2, 4 levels (last three used): p %.12g = hand %.12g = 2, f_ext "
           "%.12g = %.12g = 50",
           cv.order, p_hand, cv.extrapolated, ext_hand);
  check(cv.n_used == 3 && close_rel(cv.order, 2.0, 1e-9) && close_rel(cv.order, p_hand, 1e-12) &&
            close_rel(cv.extrapolated, 50.0, 1e-9) && close_rel(cv.extrapolated, ext_hand, 1e-12),
        msg);

  /* The worked example of Celik et al. (2008), J. Fluids Eng. 130, 078001,
   * Table 1, first column: grids of N = 18000, 8000, 4500 cells in 2D
   * (spacings 1/sqrt N), phi = 6.063, 5.972, 5.863 (fine to coarse);
   * published p = 1.53, phi_ext = 6.1685, GCI_fine = 2.2 %. */
  {
    double hc[3] = {1 / sqrt(4500.0), 1 / sqrt(8000.0), 1 / sqrt(18000.0)};
    double fc[3] = {5.863, 5.972, 6.063};
    wl_loads_convergence(hc, fc, 3, &cv);
    snprintf(msg, sizeof msg,
             "Celik et al. 2008 Table 1: p %.4g (1.53), phi_ext %.6g (6.1685), GCI %.4g %% (2.2 %%)",
             cv.order, cv.extrapolated, 100 * cv.error);
    check(fabs(cv.order - 1.53) < 0.005 && fabs(cv.extrapolated - 6.1685) < 0.00005 &&
              fabs(100 * cv.error - 2.2) < 0.05 && cv.basis == WL_LOADS_EST_GCI,
          msg);
  }

  /* oscillating: differences of opposite sign -> no order, 3 x the range */
  double fo[3] = {100.0, 90.0, 95.0};
  wl_loads_convergence(h, fo, 3, &cv);
  snprintf(msg, sizeof msg,
           "oscillating 100, 90, 95: no order (%g), no extrapolation, uncertainty = 3 x 10/95 = "
           "%.6g (%.6g), 3 x range",
           cv.order, 30.0 / 95.0, cv.error);
  check(isnan(cv.order) && !cv.order_ok && isnan(cv.extrapolated) &&
            close_rel(cv.error, 30.0 / 95.0, 1e-12) && cv.basis == WL_LOADS_EST_RANGE,
        msg);

  /* order beyond 4: reported, not extrapolated; still the capped band */
  power_law(h, 3, 10.0, 1.0e9, 6.0, f);
  wl_loads_convergence(h, f, 3, &cv);
  {
    double r32 = h[1] / h[2];
    double u = fmax(1.25 * fabs(f[2] - f[1]) / (r32 * r32 - 1), 1.25 * fabs(f[2] - f[0])) / fabs(f[2]);
    snprintf(msg, sizeof msg,
             "p = 6 > 4: order reported (%.6g), no extrapolation, uncertainty %.6g (%.6g), capped",
             cv.order, cv.error, u);
    check(close_rel(cv.order, 6.0, 1e-9) && !cv.order_ok && isnan(cv.extrapolated) &&
              close_rel(cv.error, u, 1e-12) && cv.basis == WL_LOADS_EST_GCI_HIGH,
          msg);
  }

  /* p = 0.3 < 0.95: slow; the smaller of 1.25 delta_RE and 3 x range */
  power_law(h, 3, 10.0, 5.0, 0.3, f);
  wl_loads_convergence(h, f, 3, &cv);
  {
    double r32 = h[1] / h[2];
    double u = fmin(1.25 * fabs(f[2] - f[1]) / (pow(r32, 0.3) - 1), 3 * fabs(f[2] - f[0])) / fabs(f[2]);
    snprintf(msg, sizeof msg, "p = 0.3 < 0.95: order %.6g, uncertainty %.6g (%.6g), low order",
             cv.order, cv.error, u);
    check(close_rel(cv.order, 0.3, 1e-9) && !cv.order_ok && close_rel(cv.error, u, 1e-9) &&
              cv.basis == WL_LOADS_EST_GCI_LOW,
          msg);
  }
  /* diverging: monotone but growing differences (p < 0): 3 x the range */
  double fd[3] = {100.0, 101.0, 104.0};
  wl_loads_convergence(h, fd, 3, &cv);
  snprintf(msg, sizeof msg, "diverging 100, 101, 104: order %.4g < 0, uncertainty %.6g = 3 x 4/104",
           cv.order, cv.error);
  check(cv.order < 0 && close_rel(cv.error, 12.0 / 104.0, 1e-12) && cv.basis == WL_LOADS_EST_RANGE, msg);

  /* two levels: Roache's two-grid GCI, 3 |f2 - f1| / (r^2 - 1), order 2
   * assumed; one level: nothing */
  double f2[2] = {200.0, 210.0};
  wl_loads_convergence(h, f2, 2, &cv);
  {
    double r01 = h[0] / h[1];
    double u = 3 * 10.0 / (r01 * r01 - 1) / 210.0;
    snprintf(msg, sizeof msg, "two levels 200, 210: uncertainty = 3 x 10/(r^2 - 1)/210 = %.6g (%.6g), no order",
             u, cv.error);
    check(close_rel(cv.error, u, 1e-12) && isnan(cv.order) && cv.basis == WL_LOADS_EST_TWO_LEVEL, msg);
  }
  wl_loads_convergence(h, f2, 1, &cv);
  check(isnan(cv.error) && cv.basis == WL_LOADS_EST_NONE, "one level: no estimate");
  /* converged exactly: zero differences -> no order, uncertainty 0 */
  double fc[3] = {7.0, 7.0, 7.0};
  wl_loads_convergence(h, fc, 3, &cv);
  check(isnan(cv.order) && cv.error == 0.0, "equal values: no order, uncertainty 0 (3 x range)");
}

/* The number after "key": at or after `from` in the JSON text. */
static double json_number(const char *from, const char *key) {
  char pat[96];
  snprintf(pat, sizeof pat, "\"%s\": ", key);
  const char *p = strstr(from, pat);
  if (!p) return NAN;
  p += strlen(pat);
  if (!strncmp(p, "null", 4)) return NAN;
  return strtod(p, NULL);
}

/* A ladder of means (loads.h wl_loads_convergence_sampled): the main job's
 * explosion impulse of 2026-11-28 (21.20, 22.981, 22.976 N s/m at dp =
 * 0.00857, 0.006, 0.00429 m), whose last difference changes sign. Its band
 * by hand: with the finest two equal within their sampling (0.93 N s/m
 * each: sqrt 2 x 0.93 = 1.32 > 0.005), Eca & Hoekstra's band for an order
 * above 2, max(1.25 |f3 - f2| / (r32^2 - 1), 1.25 range) = 1.25 x 1.781 =
 * 2.226 N s/m, 9.69 % of 22.976; as single runs (no sampling), or with
 * sampling too small to hold the difference, 3 x range = 5.343 N s/m. */
static void test_sampled(void) {
  char msg[320];
  struct wl_loads_convergence cv;
  const double h[3] = {0.00857142857, 0.006, 0.00428571429};
  const double f[3] = {21.200, 22.981, 22.976};
  const double u_wide[3] = {0.90, 0.93, 0.93}, u_narrow[3] = {0.002, 0.002, 0.002};
  const double band = 1.25 * (22.981 - 21.200) / 22.976, range3 = 3 * (22.981 - 21.200) / 22.976;
  wl_loads_convergence_sampled(h, f, u_wide, 3, &cv);
  snprintf(msg, sizeof msg, "means equal within sampling: band %.6g (1.25 range / f3 = %.6g), basis %s",
           cv.error, band, wl_loads_estimate_name(cv.basis));
  check(cv.basis == WL_LOADS_EST_SAMPLED && close_rel(cv.error, band, 1e-9) && isnan(cv.order) &&
            !cv.order_ok,
        msg);
  wl_loads_convergence_sampled(h, f, u_narrow, 3, &cv);
  snprintf(msg, sizeof msg, "a difference outside the sampling keeps its sign: %.6g (3 range %.6g)",
           cv.error, range3);
  check(cv.basis == WL_LOADS_EST_RANGE && close_rel(cv.error, range3, 1e-9), msg);
  wl_loads_convergence_sampled(h, f, NULL, 3, &cv);
  check(cv.basis == WL_LOADS_EST_RANGE && close_rel(cv.error, range3, 1e-9),
        "single runs (no sampling): 3 x range");
  /* every basis name fits the results' fixed fields (store.h: char [32]) */
  int fits = 1;
  for (int e = WL_LOADS_EST_NONE; e <= WL_LOADS_EST_SAMPLED; e++)
    fits &= strlen(wl_loads_estimate_name((enum wl_loads_estimate)e)) < 32;
  check(fits, "every basis name is shorter than the results' 32-byte field");
  /* a monotone ladder keeps its GCI band whatever the sampling */
  const double g[3] = {21.200, 22.500, 22.900};
  struct wl_loads_convergence a;
  wl_loads_convergence(h, g, 3, &a);
  wl_loads_convergence_sampled(h, g, u_wide, 3, &cv);
  check(cv.basis == a.basis && cv.error == a.error && cv.order == a.order,
        "monotone means: the band of wl_loads_convergence");
}

static void test_storage(void) {
  char dir[] = "/tmp/wl_convergence_XXXXXX";
  if (!mkdtemp(dir)) {
    check(0, "temporary directory");
    return;
  }
  char yaml[600], out[600];
  snprintf(yaml, sizeof yaml, "%s/ladder.yaml", dir);
  snprintf(out, sizeof out, "%s/out", dir);
  FILE *fp = fopen(yaml, "w");
  if (!fp) {
    check(0, "write the scenario");
    return;
  }
  fputs("scenario: ladder\n"
        "water: {depth: 0.2 m}\n"
        "domain: {length: 3.5 m}\n"
        "wall: {x: 3 m, height: 0.4 m, probes: 10}\n"
        "gauges: [{name: G1, x: 2.5 m}]\n"
        "loads:\n"
        "  solitary: {height: 0.06 m, generation: initial, at: 2.5 m}\n"
        "resolution: {dp: 0.03 m, convergence: [1, 0.71, 0.5]}\n"
        "run: {output_interval: 0.01 s}\n",
        fp);
  fclose(fp);
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_scenario s;
  struct wl_plan plan;
  wl_scenario_init(&s);
  enum wl_status st = wl_scenario_load(yaml, &s, &err);
  if (!st) st = wl_plan_make(&s, &plan, &err);
  struct wl_assess_opts opts = {0};
  opts.out_dir = out;
  opts.threads = 1;
  opts.end_time = 0.15;
  struct wl_assess_result res;
  memset(&res, 0, sizeof res);
  if (!st) st = wl_assess_run(&s, &plan, &opts, &res, &err);
  char msg[300];
  snprintf(msg, sizeof msg, "assess with a 3-level ladder runs (%s)", st ? err.msg : "ok");
  check(st == WL_OK, msg);
  const struct wl_assess_convergence *cv = &res.conv[0];
  snprintf(msg, sizeof msg, "3 levels run, dp %g, %g, %g m", cv->lv[0].dp, cv->lv[1].dp,
           cv->lv[2].dp);
  check(res.n_cases == 1 && cv->n_levels == 3 && close_rel(cv->lv[1].dp, 0.71 * 0.03, 1e-12) &&
            res.cases[0].dp == cv->lv[2].dp,
        msg);

  /* results.h5 through the store's reader (the report's) */
  char h5[700];
  snprintf(h5, sizeof h5, "%s/results.h5", out);
  struct wl_results *rr = malloc(sizeof *rr);
  wl_error_clear(&err);
  st = rr ? wl_store_results_read(h5, rr, &err) : WL_ENOMEM;
  check(st == WL_OK && rr->conv[0].present && rr->conv[0].n_levels == 3,
        "results.h5 holds /convergence/solitary with 3 levels");
  if (st == WL_OK && cv->n_levels == 3) {
    const struct wl_results_convergence *rc = &rr->conv[0];
    int same = 1;
    for (int l = 0; l < 3; l++) {
      const struct wl_assess_level *lv = &cv->lv[l];
      same &= rc->dp[l] == lv->dp && rc->factor[l] == lv->factor &&
              rc->particles[l] == lv->n_particles && rc->steps[l] == (double)lv->steps &&
              rc->runtime[l] == lv->runtime_s && rc->peak_force[l] == lv->peak_force &&
              rc->peak_force_b[l] == lv->peak_force_bound && rc->rest_force[l] == lv->rest_force &&
              rc->impulse[l] == lv->impulse &&
              rc->impulse_phase[l] == lv->impulse_phase && rc->impulse_pos[l] == lv->impulse_positive &&
              rc->peak_moment[l] == lv->peak_moment && rc->runup[l] == lv->runup &&
              close_rel(rc->error[l], lv->error, 0) && rc->status[l] == (int)lv->status;
    }
    check(same, "every level's dp, particles, steps, runtime, peaks, impulse, run-up, error "
                "read back bit for bit");
    snprintf(msg, sizeof msg,
             "attributes read back: force order %g, positive impulse order %g, uncertainty %g, "
             "target %g, target met %g",
             rc->force_order, rc->pos_order, rc->error_estimate, rc->target, rc->target_met);
    check(close_rel(rc->force_order, cv->force.order, 0) &&
              close_rel(rc->pos_order, cv->impulse_pos.order, 0) &&
              close_rel(rc->pos_error, cv->impulse_pos.error, 0) && !strcmp(rc->pos_basis, wl_loads_estimate_name(cv->impulse_pos.basis)) &&
              close_rel(rc->force_extrapolated, cv->force.extrapolated, 0) &&
              close_rel(rc->dyn_error, cv->force_dynamic.error, 0) &&
              close_rel(rc->dyn_order, cv->force_dynamic.order, 0) &&
              !strcmp(rc->dyn_basis, wl_loads_estimate_name(cv->force_dynamic.basis)) &&
              close_rel(rc->error_estimate, cv->error_estimate, 0) && rc->target == cv->target &&
              rc->target_met == cv->target_met && !strcmp(rc->note, cv->note),
          msg);
    /* the stored per-level values give the stored estimate again */
    double h[3], f[3];
    for (int l = 0; l < 3; l++) h[l] = rc->dp[l], f[l] = rc->peak_force[l];
    struct wl_loads_convergence again;
    wl_loads_convergence(h, f, 3, &again);
    check(close_rel(again.error, rc->force_error, 1e-15),
          "the peak-force estimate recomputed from the stored levels equals the stored one");
    /* and the wave's part, the peak less the force at rest, the case's
     * estimate with the positive impulse's */
    for (int l = 0; l < 3; l++) f[l] = rc->peak_force[l] - rc->rest_force[l];
    wl_loads_convergence(h, f, 3, &again);
    check(close_rel(again.error, rc->dyn_error, 1e-15) &&
              close_rel(fmax(again.error, rc->pos_error), rc->error_estimate, 1e-15),
          "the estimate of the peak's part above the force at rest, recomputed from the stored "
          "levels, equals the stored one, and the case's is the larger of it and the positive "
          "impulse's");
  }
  if (rr) {
    wl_store_results_clear(rr);
    free(rr);
  }

  /* summary.json: the same numbers as printed (%.10g) */
  char js[700];
  snprintf(js, sizeof js, "%s/summary.json", out);
  FILE *jf = fopen(js, "r");
  char *text = calloc(1, 1 << 20);
  if (jf && text) {
    size_t n = fread(text, 1, (1 << 20) - 1, jf);
    text[n] = '\0';
  }
  if (jf) fclose(jf);
  const char *conv = text ? strstr(text, "\"convergence\"") : NULL;
  check(conv != NULL, "summary.json has cases.solitary.convergence");
  if (conv && cv->n_levels == 3) {
    const char *p = strstr(conv, "\"levels\": ["); /* after the units object */
    int same = p != NULL;
    for (int l = 0; same && l < 3; l++) {
      p = strstr(p, "{ \"factor\"");
      if (!p) {
        same = 0;
        break;
      }
      same &= close_rel(json_number(p, "dp"), cv->lv[l].dp, 1e-9) &&
              close_rel(json_number(p, "peak_force"), cv->lv[l].peak_force, 1e-9) &&
              close_rel(json_number(p, "impulse"), cv->lv[l].impulse, 1e-9) &&
              close_rel(json_number(p, "impulse_positive_phase"), cv->lv[l].impulse_phase, 1e-9) &&
              close_rel(json_number(p, "impulse_positive"), cv->lv[l].impulse_positive, 1e-9) &&
              close_rel(json_number(p, "estimated_error"), cv->lv[l].error, 1e-9);
      p++;
    }
    const char *tail = strstr(conv, "\"error_estimate\": ");
    /* the case's estimate follows the two per-quantity objects */
    const char *last = NULL;
    for (const char *q = conv; (q = strstr(q, "\"error_estimate\": ")); q++) last = q;
    same &= tail != NULL && last != NULL &&
            close_rel(json_number(last, "error_estimate"), cv->error_estimate, 1e-9) &&
            close_rel(json_number(conv, "target"), cv->target, 1e-9);
    check(same, "summary.json's levels, error estimate and target equal the stored values (to "
                "its 10 digits)");
  }
  free(text);
  wl_assess_result_clear(&res);
  wl_scenario_clear(&s);
  char cmd[700];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  if (system(cmd) != 0) printf("note: could not remove %s\n", dir);
}

int main(void) {
  test_synthetic();
  test_sampled();
  test_storage();
  printf("%s: %d failure(s)\n", failures ? "FAIL" : "PASS", failures);
  return failures ? 1 : 0;
}
