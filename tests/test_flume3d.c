/* test_flume3d.c: 3D flumes from scenario files (flume.h).
 *  - counts: the 3D flume's fluid is the 2D flume's fluid times the lattice
 *    rows across the width, exactly, and so are the boundary particles of
 *    the extruded bed / wall polyline inside the width (side walls apart);
 *  - the probes' wetness reference sums (flume.h probe_shepard_full)
 *    against the sums of the water the flume lays, 2D and 3D;
 *  - still water against the wall in a 3D flume: force per metre within
 *    1 % of rho g d^2/2 (REFERENCES.md 1.1) from the probe grid and from the
 *    wall's boundary particles (averaged over the last third of the run;
 *    the start-up has settled by then to well under 1 % at this spacing);
 *  - a long-crested solitary wave in 3D against the same case in 2D: the
 *    wall gauge and the wall force per metre histories agree within the
 *    tolerances stated below (coarse, short).
 *  - the symmetry plane: a 3D crater on the centreline, half the width with
 *    the plane against the whole width (symmetry() below);
 * `flume3d counts` runs the first check only; the default run (ctest
 * flume3d) counts and still water (whole width and half); `flume3d
 * symmetry` (ctest flume3d_symmetry, a long test) the symmetry plane; `flume3d solitary` (ctest
 * flume3d_solitary, a long test: minutes on 2 cores) the 3D vs 2D wave. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "still_water_ref.h"
#include "testutil.h"
#include "wallload/assess.h"
#include "wallload/sph.h"

/* 3D vs 2D long-crested solitary wave: peak run-up and forces within the
 * 5 % of issue 4's run-up check (h/dp differs a little: 1.73 in 3D, 1.70
 * in 2D, the plan's defaults; and the 3D flume has a side wall); arrival
 * at the wall within the 2 % of issue 3's celerity check. */
#define SOL_TOL_PEAK 0.05
#define SOL_TOL_ARRIVAL 0.02

static int parse(const char *text, struct wl_scenario *s, struct wl_plan *plan) {
  struct wl_error err;
  wl_error_clear(&err);
  wl_scenario_init(s);
  if (wl_scenario_parse("flume3d.yaml", text, strlen(text), s, &err) ||
      wl_plan_make(s, plan, &err)) {
    printf("FAIL setup: %s\n", err.msg);
    return 1;
  }
  return 0;
}

/* still water: h = 0.3 m, dp = 0.03 m, width 0.3 m (10 rows; 5 with the
 * symmetry plane, domain.symmetry auto) */
static const char *still_text(int dims, const char *symmetry) {
  static char buf[600];
  snprintf(buf, sizeof buf,
           "scenario: still3d\nwater: {depth: 0.3 m}\n"
           "domain: {dimensions: %d, length: 1.5 m, width: 0.3 m, symmetry: %s}\n"
           "wall: {x: 0.9 m, height: 0.5 m, probes: 20}\n"
           /* a solitary case for the particle counts; the 4.6 m wave does not
            * fit this flume, so its crest is placed explicitly */
           "loads: {solitary: {height: 0.06 m, generation: initial, at: 0.45 m}}\n"
           "resolution: {dp: 0.03 m}\nrun: {output_interval: 0.02 s}\n",
           dims, symmetry);
  return buf;
}

/* The probes' wetness reference (flume.h probe_shepard_full, a sum over
 * the lattice the flume is meant to lay) against the Shepard sum the probe
 * module reads from the particles the flume actually laid, at every probe
 * more than a kernel support under the still surface (3D: the mean over the
 * probes across). The laid water is compressed by its hydrostatic (Tait)
 * pressure, so each particle's volume m/rho is smaller than dp^dim by up to
 * rho_bed/rho0 (about 1 % at this depth and sound speed): the laid sum may
 * read up to that much lower, and no higher than the lattice's but for
 * float sums (0.2 %); measured within 0.06 % either way. A reference off by
 * half a spacing at the face reads 18 % off. Returns the worst ratio. */
static double probe_reference(const struct wl_flume *f, int *n_checked) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_sph_probe *pr = NULL;
  struct wl_sph_const k;
  *n_checked = 0;
  if (wl_sph_const_make(&f->cfg.prm, &k, &err) || wl_sph_probe_alloc(&pr, &f->cfg, &err) ||
      wl_sph_probe_index(pr, &f->particles, &err)) {
    printf("FAIL probe index: %s\n", err.msg);
    wl_test_failures++;
    wl_sph_probe_free(pr);
    return NAN;
  }
  const double rho_bed =
      wl_sph_eos_rho_of_p(k.rho0, (double)k.B, k.rho0 * f->cfg.prm.g * f->depth_wall);
  const double lo = k.rho0 / rho_bed - 0.002, hi = 1.002;
  double worst = 1.0;
  int ok = 1;
  for (int i = 0; i < f->n_probes; i++) {
    if (!(f->probe_z[i] < f->z_toe + f->depth_wall - 2.0 * k.h_d)) continue;
    const int ny = f->dims == 3 ? f->n_probe_y : 1;
    double sum = 0.0;
    for (int j = 0; j < ny; j++) {
      double x[3] = {f->probe_x, f->dims == 3 ? f->probe_y[j] : f->probe_z[i], f->probe_z[i]};
      sum += wl_sph_probe_shepard(pr, x);
    }
    const double ratio = sum / ny / f->probe_shepard_full[i];
    ok &= ratio >= lo && ratio <= hi;
    if (fabs(ratio - 1) > fabs(worst - 1)) worst = ratio;
    (*n_checked)++;
  }
  wl_sph_probe_free(pr);
  CHECK_TRUE(*n_checked > 3 && ok,
             "probe reference sums: the laid water's within its compression of the lattice's");
  return worst;
}

static void counts(void) {
  struct wl_scenario s2, s3;
  struct wl_plan p2, p3;
  if (parse(still_text(2, "auto"), &s2, &p2) || parse(still_text(3, "none"), &s3, &p3)) {
    wl_test_failures++;
    return;
  }
  struct wl_error err;
  wl_error_clear(&err);
  const enum wl_load_case cases[2] = {WL_CASE_STILL, WL_CASE_SOLITARY};
  for (int c = 0; c < 2; c++) {
    struct wl_flume f2, f3;
    enum wl_status st = wl_flume_build(&s2, &p2, cases[c], &f2, &err);
    if (!st) st = wl_flume_build(&s3, &p3, cases[c], &f3, &err);
    CHECK_TRUE(st == WL_OK, "2D and 3D flumes build");
    if (st) {
      printf("  %s\n", err.msg);
      return;
    }
    const int rows = (int)floor(f3.width / p3.dp + 0.5);
    const long nf2 = f2.particles.n - f2.particles.n_bound;
    const long nf3 = f3.particles.n - f3.particles.n_bound;
    long nb_in = 0, nb_wall2 = 0, nb_wall3_in = 0;
    for (int i = 0; i < f3.particles.n_bound; i++) {
      const double y = f3.particles.pos[1][i];
      if (y > 0 && y < f3.width) {
        nb_in++;
        nb_wall3_in += f3.particles.body[i] == WL_FLUME_BODY_WALL;
      }
    }
    for (int i = 0; i < f2.particles.n_bound; i++) nb_wall2 += f2.particles.body[i] == WL_FLUME_BODY_WALL;
    printf("%s: width %.3f m = %d rows; fluid 2D %ld, 3D %ld; boundary 2D %d, 3D %d (%ld inside "
           "the width); total 3D %d\n",
           wl_flume_case_name(cases[c]), f3.width, rows, nf2, nf3, f2.particles.n_bound,
           f3.particles.n_bound, nb_in, f3.particles.n);
    CHECK_TRUE(nf3 == nf2 * rows, "3D fluid = 2D fluid x rows across (exact)");
    CHECK_TRUE(nb_in == (long)f2.particles.n_bound * rows,
               "3D boundary inside the width = 2D boundary x rows (exact)");
    CHECK_TRUE(nb_wall3_in == nb_wall2 * rows, "3D seawall body inside the width = 2D x rows");
    CHECK_TRUE(f3.n_probe_y >= 1 && f3.n_probes == f2.n_probes, "3D probe grid over the face");
    if (cases[c] == WL_CASE_STILL) {
      int n2, n3;
      const double w2 = probe_reference(&f2, &n2), w3 = probe_reference(&f3, &n3);
      printf("  probe reference sums, laid / lattice: worst %.4f (2D, %d probes), %.4f (3D, %d)\n",
             w2, n2, w3, n3);
    }
    wl_flume_clear(&f2);
    wl_flume_clear(&f3);
  }
  wl_scenario_clear(&s2);
  wl_scenario_clear(&s3);
}

static void still(int quick, int dims, const char *symmetry) {
  struct wl_scenario s;
  struct wl_plan plan;
  if (parse(still_text(dims, symmetry), &s, &plan)) {
    wl_test_failures++;
    return;
  }
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_assess_opts opts = {0};
  /* the sanitizer build's quick run drives the 3D code for memory errors
   * only (0.05 s, not settled; 14 s there): the Release build checks the
   * forces */
  opts.end_time = quick ? 0.05 : 0.8;
  struct wl_case_result c;
  enum wl_status st = wl_assess_case(&s, &plan, WL_CASE_STILL, &opts, NULL, &c, &err);
  CHECK_TRUE(st == WL_OK, "3D still water runs to the end without a fault");
  if (st) printf("  %s\n", err.msg);
  /* the Tait column at the still level (still_water_ref.h): the probes
   * read 1/kappa of it, the boundary particles' pair sum the column's */
  const double rho = 1000, g = 9.81, d = 0.3;
  const double F0 = still_tait_force(d, rho, g, c.c0), M0 = still_tait_moment(d, rho, g, c.c0);
  const double kappa = still_lattice_gradient_factor(3, c.h / c.dp);
  size_t n = c.rec.n, k0 = 2 * n / 3;
  double F = 0, Fb = 0, M = 0, Mb = 0;
  for (size_t k = k0; k < n; k++)
    F += c.rec.force[k], Fb += c.rec.force_bound[k], M += c.rec.moment[k], Mb += c.rec.moment_bound[k];
  F /= (double)(n - k0), Fb /= (double)(n - k0), M /= (double)(n - k0), Mb /= (double)(n - k0);
  printf("%dD still water, symmetry %s (%d particles, %.2f s in %.1f s): per metre: probes F = "
         "%.2f N/m, boundary F = %.2f N/m, probes M = %.2f, boundary M = %.2f N m/m; reference "
         "%.2f N/m, %.2f N m/m; modelled width %.3f m\n",
         dims, symmetry, c.n_particles, c.t_reached, c.runtime_s, F, Fb, M, Mb, F0, M0,
         c.flume.width);
  if (!quick) {
    printf("  Tait column at c0 = %.2f m/s: F %.2f N/m; lattice factor at h = %.3f dp: %.5f\n",
           c.c0, F0, c.h / c.dp, kappa);
    CHECK_REL(F, F0 / kappa, 0.01, "3D probe force per metre = the Tait column's / kappa");
    CHECK_REL(Fb, F0, 0.01, "3D boundary-particle force per metre = the Tait column's");
  } else {
    CHECK_TRUE(isfinite(F) && isfinite(Fb) && c.rec.n > 3, "3D forces finite (quick run)");
  }
  /* the moments are printed, not checked: at this coarse spacing (10
   * particles over the depth) the probe moment is 4 % high, the probes'
   * profile ending at the wall gauge's surface; the 2D wall test checks
   * the moment at dp = d/25 */
  wl_assess_case_clear(&c);
  wl_scenario_clear(&s);
}

/* Long-crested solitary wave, H/h = 0.3 on h = 0.3 m, dp = 0.03 m, in a
 * flume 0.24 m wide (8 rows; 4 modelled beside the symmetry plane), and the
 * same case in 2D; the geometry of test_solitary_wall scaled to h = 0.3 m
 * (crest 0.55 L from the left end, wall 0.75 L further, L = 6/K = 3.79 m).
 * Until 2026-11-23 this check ran a 2.7 m flume in which the 3.8 m wave
 * did not fit: its crest started 0.3 m from the wall, the wall cut the
 * initial wave and the comparison measured the start-up's acoustic
 * ringing (forces jumping by 2000 N/m between samples). Measured
 * 2026-11-23: with side walls of dynamic boundary particles the 3D wave
 * arrived 10 % early and ran 7.5 % higher (3.4 % and 3.4 % in a 0.6 m
 * flume: the walls' gap and pressure disturb a narrow flume); with the
 * default free-slip side walls (mirror planes): arrival +0.8 %, run-up
 * -2.2 %, peak probe force +3.1 %, peak boundary force +1.0 %. */
static const char *solitary_text(int dims) {
  static char buf[600];
  snprintf(buf, sizeof buf,
           "scenario: sol3d\nwater: {depth: 0.3 m}\n"
           "domain: {dimensions: %d, length: 5.43 m, width: 0.24 m}\n"
           "wall: {x: 4.93 m, height: 0.4 m, probes: 16}\n"
           "loads: {solitary: {height: 0.09 m, generation: initial, at: 2.08 m}}\n"
           "resolution: {dp: 0.03 m}\nrun: {output_interval: 0.01 s}\n",
           dims);
  return buf;
}

static void solitary(int quick) {
  struct wl_scenario s[2];
  struct wl_plan plan[2];
  struct wl_case_result c[2];
  struct wl_error err;
  wl_error_clear(&err);
  for (int d = 0; d < 2; d++) {
    if (parse(solitary_text(d + 2), &s[d], &plan[d])) {
      wl_test_failures++;
      return;
    }
    struct wl_assess_opts opts = {0};
    opts.end_time = plan[d].solitary.arrival_time + (quick ? 0.25 : 0.45);
    enum wl_status st = wl_assess_case(&s[d], &plan[d], WL_CASE_SOLITARY, &opts, NULL, &c[d], &err);
    CHECK_TRUE(st == WL_OK, d ? "3D solitary runs to the end" : "2D solitary runs to the end");
    if (st) printf("  %s\n", err.msg);
    printf("%dD solitary: %d particles, %.2f s simulated in %.1f s (%ld steps)\n", d + 2,
           c[d].n_particles, c[d].t_reached, c[d].runtime_s, (long)c[d].steps);
  }
  /* what the engineer reads: peak force per metre (probes and boundary
   * particles), the wall gauge's largest rise above its level at t = 0
   * (the gauge's rest bias differs by a fraction of dp between 2D and 3D),
   * and when the rise passes H/2 (the wave's arrival) */
  double peak[2][3], arrive[2];
  for (int d = 0; d < 2; d++) {
    const struct wl_record *r = &c[d].rec;
    const int gw = r->n_gauges - 1; /* the wall gauge */
    const double eta_rest = r->eta[gw];
    peak[d][0] = peak[d][1] = peak[d][2] = -INFINITY;
    arrive[d] = NAN;
    for (size_t k = 0; k < r->n; k++) {
      const double rise = r->eta[k * (size_t)r->n_gauges + (size_t)gw] - eta_rest;
      peak[d][0] = fmax(peak[d][0], rise);
      peak[d][1] = fmax(peak[d][1], r->force[k]);
      peak[d][2] = fmax(peak[d][2], r->force_bound[k]);
      if (isnan(arrive[d]) && k > 0 && rise >= 0.5 * 0.09) {
        const double r0 = r->eta[(k - 1) * (size_t)r->n_gauges + (size_t)gw] - eta_rest;
        arrive[d] = r->t[k - 1] + (r->t[k] - r->t[k - 1]) * (0.5 * 0.09 - r0) / (rise - r0);
      }
    }
  }
  printf("3D vs 2D: wall gauge rise %.4f / %.4f m, arrival (rise H/2) %.3f / %.3f s, peak probe "
         "force %.1f / %.1f N/m, peak boundary force %.1f / %.1f N/m\n",
         peak[1][0], peak[0][0], arrive[1], arrive[0], peak[1][1], peak[0][1], peak[1][2],
         peak[0][2]);
  CHECK_REL(peak[1][0], peak[0][0], SOL_TOL_PEAK, "3D wall run-up = 2D");
  CHECK_REL(peak[1][1], peak[0][1], SOL_TOL_PEAK, "3D peak probe force per metre = 2D");
  CHECK_REL(peak[1][2], peak[0][2], SOL_TOL_PEAK, "3D peak boundary force per metre = 2D");
  CHECK_REL(arrive[1], arrive[0], SOL_TOL_ARRIVAL, "3D arrival at the wall = 2D (celerity)");
  for (int d = 0; d < 2; d++) {
    wl_assess_case_clear(&c[d]);
    wl_scenario_clear(&s[d]);
  }
}

/* An axisymmetric crater (lip-less quadratic, eta0 = 0.09 m, R0 = 0.15 m)
 * on the centreline of a 3D flume, h = 0.3 m, 0.6 m wide, dp = 0.03 m:
 * half the width with the symmetry plane against the whole width, the
 * reference. The two are the same discrete problem (the half's lattice
 * and its mirror images are the whole's lattice), summed in another order,
 * so they may differ only by rounding that the flow amplifies. Measured
 * 2026-11-23 over 0.7 s: gauges and boundary force equal to print
 * precision (< 5e-6 m, < 0.005 N/m); the probe force too with the default
 * free-slip side walls, 2.8 % of its largest dynamic value apart with
 * side walls of particles, because the probe grid is not the same (5
 * strips over the half width against 5 over the whole: other sample
 * points of a wave that varies across). With the solver's mirror pass off the gauges
 * differ by more than their signal (fluid falls into the plane); with the
 * boundary force's mirror pass off, that force by 6.9 %. */
#define SYM_TOL_ETA 0.01 /* of the largest |eta| at the gauge */
#define SYM_TOL_FB 0.01  /* boundary force: of its largest dynamic value */
#define SYM_TOL_F 0.05   /* probe force (different probe grids): likewise */

static const char *crater_text(const char *symmetry) {
  static char buf[600];
  snprintf(buf, sizeof buf,
           "scenario: sym3d\nwater: {depth: 0.3 m}\n"
           "domain: {dimensions: 3, length: 1.5 m, width: 0.6 m, symmetry: %s}\n"
           "wall: {x: 1.1 m, height: 0.5 m, probes: 16}\ngauges: [{name: G1, x: 0.75 m}]\n"
           "loads: {explosion: {eta0: 0.09 m, r0: 0.15 m, shape: quadratic, at: 0.4 m}}\n"
           "resolution: {dp: 0.03 m}\nrun: {output_interval: 0.01 s}\n",
           symmetry);
  return buf;
}

static void symmetry(int quick) {
  const char *sym[2] = {"none", "centreline"};
  struct wl_scenario s[2];
  struct wl_plan plan[2];
  struct wl_case_result c[2];
  struct wl_error err;
  wl_error_clear(&err);
  for (int m = 0; m < 2; m++) {
    if (parse(crater_text(sym[m]), &s[m], &plan[m])) {
      wl_test_failures++;
      return;
    }
    struct wl_assess_opts opts = {0};
    opts.end_time = quick ? 0.15 : 0.55; /* the wave meets the wall from 0.41 s */
    enum wl_status st = wl_assess_case(&s[m], &plan[m], WL_CASE_EXPLOSION, &opts, NULL, &c[m], &err);
    CHECK_TRUE(st == WL_OK, m ? "half flume (symmetry plane) runs" : "whole flume runs");
    if (st) printf("  %s\n", err.msg);
    printf("crater, symmetry %s: %d particles (modelled width %.3f m), %.2f s in %.1f s\n", sym[m],
           c[m].n_particles, c[m].flume.width, c[m].t_reached, c[m].runtime_s);
  }
  CHECK_TRUE(plan[0].symmetry == 0 && plan[1].symmetry == 1, "plan: none / centreline");
  CHECK_ABS(c[1].flume.width, 0.5 * c[0].flume.width, 1e-12, "the half's width");
  const long nf0 = c[0].flume.particles.n - c[0].flume.particles.n_bound;
  const long nf1 = c[1].flume.particles.n - c[1].flume.particles.n_bound;
  CHECK_TRUE(nf0 == 2 * nf1, "the whole flume's fluid = 2 x the half's (exact)");
  const size_t n = c[0].rec.n < c[1].rec.n ? c[0].rec.n : c[1].rec.n;
  double deta[2] = {0, 0}, eta_max[2] = {0, 0}, dF = 0, dFb = 0, F_max = 0, Fb_max = 0;
  const double F0 = c[0].static_force;
  const int ng = c[0].rec.n_gauges;
  for (size_t k = 0; k < n; k++) {
    for (int g = 0; g < 2; g++) { /* G1 and the wall gauge */
      const int gi = g ? ng - 1 : 0;
      const double e0 = c[0].rec.eta[k * ng + gi], e1 = c[1].rec.eta[k * ng + gi];
      deta[g] = fmax(deta[g], fabs(e1 - e0));
      eta_max[g] = fmax(eta_max[g], fabs(e0));
    }
    dF = fmax(dF, fabs(c[1].rec.force[k] - c[0].rec.force[k]));
    dFb = fmax(dFb, fabs(c[1].rec.force_bound[k] - c[0].rec.force_bound[k]));
    F_max = fmax(F_max, fabs(c[0].rec.force[k] - F0));
    Fb_max = fmax(Fb_max, fabs(c[0].rec.force_bound[k] - F0));
  }
  printf("half vs whole over %zu samples: G1 max |d eta| = %.5f m (max |eta| %.4f m); wall gauge "
         "%.5f m (%.4f m); probe force per metre max |dF| = %.2f N/m (largest dynamic %.2f N/m); "
         "boundary force %.2f N/m (%.2f N/m)\n",
         n, deta[0], eta_max[0], deta[1], eta_max[1], dF, F_max, dFb, Fb_max);
  CHECK_TRUE(n > 10 && ng == c[1].rec.n_gauges, "both runs sampled, same gauges");
  CHECK_TRUE(deta[0] <= SYM_TOL_ETA * eta_max[0], "gauge G1: half = whole within the tolerance");
  CHECK_TRUE(deta[1] <= SYM_TOL_ETA * eta_max[1], "wall gauge: half = whole within the tolerance");
  CHECK_TRUE(dF <= SYM_TOL_F * F_max, "probe force per metre: half = whole within the tolerance");
  CHECK_TRUE(dFb <= SYM_TOL_FB * Fb_max, "boundary force per metre: half = whole within the tolerance");
  for (int m = 0; m < 2; m++) {
    wl_assess_case_clear(&c[m]);
    wl_scenario_clear(&s[m]);
  }
}

int main(int argc, char **argv) {
  gsl_set_error_handler_off();
  setvbuf(stdout, NULL, _IOLBF, 0); /* progress lines survive a timeout */
  const int quick = getenv("WL_TEST_QUICK") != NULL;
  const char *only = argc > 1 ? argv[1] : "";
  counts();
  if (!strcmp(only, "counts")) return TEST_RESULT();
  if (!strcmp(only, "still2d")) still(quick, 2, "auto"); /* the same flume in 2D */
  if (!*only || !strcmp(only, "still")) {
    /* the sanitizer's quick run: the half width alone, whose mirror passes
     * are the code the whole width does not run */
    if (!quick) still(quick, 3, "none");
    still(quick, 3, "auto"); /* the half width, with the symmetry plane */
  }
  if (!strcmp(only, "symmetry")) symmetry(quick); /* ctest flume3d_symmetry (long) */
  if (!strcmp(only, "solitary")) solitary(quick); /* ctest flume3d_solitary (long) */
  return TEST_RESULT();
}
