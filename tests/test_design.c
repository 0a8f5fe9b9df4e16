/* test_design.c: the design module against references it did not produce:
 * closed-form hydrostatics (REFERENCES.md 1.1), hand calculations written
 * out step by step next to each check (numbers from an independent Python
 * script when this test was written), published or transcribed worked
 * examples (FEMA P-646 (2012) App. C.3; ACES User's Guide Example 4-3; the
 * Goda (2000) p. 140 inputs with the `breakwater` package's outputs; a
 * Deltares toolbox Goda case; Goda's wavelength table as the Deltares tests
 * transcribe it), independent approximations of the dispersion relation
 * (Fenton & McKee 1990, Hunt 1979, written here, not in the library), GSL
 * quadrature of every pressure profile as a second computation of force and
 * moment, validity flags on both sides of each stated limit, and every
 * error path. */
#include "wallload/design.h"
#include "wallload/units.h"

#include "testutil.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <string.h>

#define RHO 1000.0
#define G 9.81
#define TOL_EXACT 1e-12   /* a handful of roundings */
#define TOL_HAND 1e-7     /* hand calculations carried to 8 significant digits */
#define TOL_QUAD 1e-9     /* profile integral vs GSL quadrature, relative */
#define TOL_DISP 1e-13    /* dispersion residual after Newton, relative */
#define TOL_HUNT 1e-4     /* Hunt (1979) Pade: 8.2e-5 worst over the sweep (measured) */
#define TOL_FENTON 0.017  /* Fenton & McKee (1990): 1.66 % worst over the sweep (measured) */
#define TOL_GODA_TABLE 0.005 /* Goda's table is printed to 0.01 m */

static const double DEG = WL_PI / 180.0;

/* ---- helpers ------------------------------------------------------------ */

static double profile_fn(double z, void *p) {
  return wl_design_profile_pressure((const struct wl_design_profile *)p, z);
}

static double profile_z_fn(double z, void *p) {
  return z * wl_design_profile_pressure((const struct wl_design_profile *)p, z);
}

/* int p dz and int p z dz by GSL adaptive quadrature, segment by segment. */
static void quad_profile(const struct wl_design_profile *pr, double *force, double *moment) {
  gsl_integration_workspace *w = gsl_integration_workspace_alloc(200);
  double f = 0.0, m = 0.0;
  for (int i = 1; i < pr->n_points; i++) {
    double r, e;
    gsl_function F = {profile_fn, (void *)pr};
    gsl_function M = {profile_z_fn, (void *)pr};
    /* an interior point keeps each integrand smooth on its interval */
    double a = pr->z[i - 1], b = pr->z[i];
    if (gsl_integration_qags(&F, a, b, 0.0, 1e-12, 200, w, &r, &e) != GSL_SUCCESS) r = NAN;
    f += r;
    if (gsl_integration_qags(&M, a, b, 0.0, 1e-12, 200, w, &r, &e) != GSL_SUCCESS) r = NAN;
    m += r;
  }
  gsl_integration_workspace_free(w);
  *force = f;
  *moment = m;
}

/* Every result's profile integrates to its force and moment (closed forms
 * from the source) and GSL agrees. Only for TOTAL/WAVE results with a
 * profile. */
static void check_profile(const struct wl_design_result *r, const char *ref) {
  if (r->profile.n_points < 2) return;
  double f = NAN, m = NAN, fq = NAN, mq = NAN;
  wl_design_profile_integrate(&r->profile, &f, &m);
  quad_profile(&r->profile, &fq, &mq);
  CHECK_REL(f, r->force, TOL_QUAD, ref);
  CHECK_REL(m, r->moment, TOL_QUAD, ref);
  CHECK_REL(fq, r->force, TOL_QUAD, "GSL qags of the profile vs closed-form force");
  CHECK_REL(mq, r->moment, TOL_QUAD, "GSL qags of z p(z) vs closed-form moment");
}

static double wavelength(double T, double h, double g) {
  double L = NAN;
  struct wl_error err;
  wl_error_clear(&err);
  if (wl_design_wavelength(T, h, g, &L, &err) != WL_OK) return NAN;
  return L;
}

static int expect_einput(enum wl_status st, const struct wl_error *err, const char *needle) {
  return st == WL_EINPUT && err->status == WL_EINPUT && strstr(err->msg, needle) != NULL;
}

/* ---- wavelength [DISP] -------------------------------------------------- */

/* Fenton & McKee (1990) explicit estimate, written here independently. */
static double fenton_mckee(double T, double h, double g) {
  double L0 = g * T * T / (2.0 * WL_PI);
  return L0 * pow(tanh(pow(2.0 * WL_PI / T * sqrt(h / g), 1.5)), 2.0 / 3.0);
}

/* Hunt (1979) Pade series for c^2 = g h / (y + 1/(1 + sum d_n y^n)),
 * y = omega^2 h / g, coefficients as in the ACES 4-3 port (CHESS-QC). */
static double hunt(double T, double h, double g) {
  static const double D[9] = {0.66667, 0.35550, 0.16084, 0.06320, 0.02174,
                              0.00654, 0.00171, 0.00039, 0.00011};
  double w = 2.0 * WL_PI / T, y = w * w * h / g, s = 1.0, yn = 1.0;
  for (int n = 0; n < 9; n++) {
    yn *= y;
    s += D[n] * yn;
  }
  return sqrt(g * h / (y + 1.0 / s)) * T;
}

static void test_wavelength(void) {
  /* The defining identity: omega^2 = g k tanh(k h), over deep to shallow. */
  const double Ts[] = {1.0, 4.0, 8.0, 15.0, 60.0};
  const double hs[] = {0.05, 0.36, 2.0, 10.0, 200.0};
  double worst = 0.0;
  for (int i = 0; i < 5; i++)
    for (int j = 0; j < 5; j++) {
      double L = wavelength(Ts[i], hs[j], G), k = 2.0 * WL_PI / L, w = 2.0 * WL_PI / Ts[i];
      worst = fmax(worst, fabs(G * k * tanh(k * hs[j]) - w * w) / (w * w));
    }
  CHECK_ABS(worst, 0.0, TOL_DISP, "linear dispersion omega^2 = g k tanh(kh), worst of 25 cases");

  /* Deep water: kh = 2 pi 1000 / 39 ~ 161, tanh = 1 exactly: L = g T^2 / 2 pi. */
  CHECK_REL(wavelength(5.0, 1000.0, G), G * 25.0 / (2.0 * WL_PI), TOL_EXACT,
            "deep-water limit L0 = g T^2 / (2 pi)");
  /* Shallow water: kh ~ 2e-3, L = T sqrt(g h)(1 - (kh)^2/6 + ...): 7e-7. */
  CHECK_REL(wavelength(100.0, 0.01, G), 100.0 * sqrt(G * 0.01), 1e-6,
            "shallow-water limit L = T sqrt(g h), (kh)^2/6 = 7e-7");

  /* Goda (2000) wavelength table, g = 9.8, as transcribed by the Deltares
   * coastal-structures-toolbox test (tests/structural/forces_caisson). */
  CHECK_ABS(wavelength(2.0, 0.2, 9.8), 2.71, TOL_GODA_TABLE, "Goda (2000) table: T 2 s, h 0.2 m");
  CHECK_ABS(wavelength(2.0, 1.0, 9.8), 5.21, TOL_GODA_TABLE, "Goda (2000) table: T 2 s, h 1 m");
  CHECK_ABS(wavelength(2.0, 2.0, 9.8), 6.05, TOL_GODA_TABLE, "Goda (2000) table: T 2 s, h 2 m");
  CHECK_ABS(wavelength(2.0, 11.0, 9.8), 6.24, TOL_GODA_TABLE, "Goda (2000) table: T 2 s, h 11 m");
  CHECK_ABS(wavelength(5.0, 6.0, 9.8), 32.17, TOL_GODA_TABLE, "Goda (2000) table: T 5 s, h 6 m");

  /* Two independent approximations over omega^2 h / g from 0.005 to 10. */
  double worst_hunt = 0.0, worst_fm = 0.0;
  for (int i = 1; i <= 2000; i++) {
    double y = 0.005 * i, h = 1.0, T = 2.0 * WL_PI / sqrt(y * G / h);
    double L = wavelength(T, h, G);
    worst_hunt = fmax(worst_hunt, fabs(hunt(T, h, G) / L - 1.0));
    worst_fm = fmax(worst_fm, fabs(fenton_mckee(T, h, G) / L - 1.0));
  }
  CHECK_ABS(worst_hunt, 0.0, TOL_HUNT, "Hunt (1979) Pade series, worst of 2000 depths");
  CHECK_ABS(worst_fm, 0.0, TOL_FENTON, "Fenton & McKee (1990) explicit, worst of 2000 depths");

  struct wl_error err;
  double L = 0.0;
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_wavelength(0.0, 1.0, G, &L, &err), &err, "wave period T"),
             "error: T = 0");
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_wavelength(INFINITY, 1.0, G, &L, &err), &err, "period"),
             "error: T infinite");
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_wavelength(5.0, -1.0, G, &L, &err), &err, "water depth h"),
             "error: h < 0");
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_wavelength(5.0, 1.0, NAN, &L, &err), &err, "gravity g"),
             "error: g NaN");
}

/* ---- profiles ------------------------------------------------------------ */

static void test_profile(void) {
  struct wl_design_profile pr = {3, {0.0, 2.0, 3.0, 0.0}, {10.0, 4.0, 1.0, 0.0}};
  CHECK_ABS(wl_design_profile_pressure(&pr, 1.0), 7.0, TOL_EXACT, "linear between points");
  CHECK_ABS(wl_design_profile_pressure(&pr, 2.5), 2.5, TOL_EXACT, "linear between points");
  CHECK_ABS(wl_design_profile_pressure(&pr, -0.1), 0.0, 0.0, "0 below the first point");
  CHECK_ABS(wl_design_profile_pressure(&pr, 3.1), 0.0, 0.0, "0 above the last point");
  /* int p dz = (10 + 4)/2 * 2 + (4 + 1)/2 * 1 = 16.5;
   * int p z dz = [0,2]: (2/6)(10*2 + 4*4) = 12; [2,3]: (1/6)(4*7 + 1*8) = 6; 18. */
  double f = 0.0, m = 0.0;
  wl_design_profile_integrate(&pr, &f, &m);
  CHECK_ABS(f, 16.5, TOL_EXACT, "hand: trapezoids 14 + 2.5");
  CHECK_ABS(m, 18.0, TOL_EXACT, "hand: 12 + 6");
  CHECK_TRUE(strcmp(wl_design_basis_name(WL_DESIGN_BASIS_WAVE), "wave") == 0, "basis name");
  CHECK_TRUE(strcmp(wl_design_basis_name((enum wl_design_basis)42), "unknown") == 0,
             "invalid basis name");
}

/* ---- hydrostatic [HYD] ---------------------------------------------------- */

static void test_hydrostatic(void) {
  struct wl_design_result r;
  struct wl_error err;
  wl_error_clear(&err);
  CHECK_TRUE(wl_design_hydrostatic(RHO, G, 0.5, 0.0, &r, &err) == WL_OK, "hydrostatic runs");
  CHECK_REL(r.force, 1226.25, TOL_EXACT, "REFERENCES.md 1.1: h = 0.5 m, F = 1226.25 N/m");
  CHECK_REL(r.moment, 9810.0 * 0.125 / 6.0, TOL_EXACT, "M = rho g h^3/6 = 204.375 N m/m");
  CHECK_REL(r.force_total, r.force, 0.0, "TOTAL basis: force_total = force");
  CHECK_TRUE(r.in_range && strcmp(r.name, "hydrostatic") == 0 && r.basis == WL_DESIGN_BASIS_TOTAL,
             "exact, always in range");
  CHECK_TRUE(isnan(r.uplift_p), "no uplift for a wall face");
  check_profile(&r, "hydrostatic profile integral");

  /* Raised level: D = 0.5 + 0.1 = 0.6: F = 9810 * 0.36 / 2 = 1765.8,
   * M = 9810 * 0.216 / 6 = 353.16. Lowered: D = 0.3, F = 9810 * 0.09 / 2. */
  CHECK_TRUE(wl_design_hydrostatic(RHO, G, 0.5, 0.1, &r, &err) == WL_OK, "raised level runs");
  CHECK_REL(r.force, 1765.8, TOL_EXACT, "rho g (d + eta)^2 / 2 = 1765.8 N/m");
  CHECK_REL(r.moment, 353.16, TOL_EXACT, "rho g (d + eta)^3 / 6 = 353.16 N m/m");
  CHECK_TRUE(strcmp(r.name, "hydrostatic-level") == 0, "named for the raised level");
  CHECK_TRUE(wl_design_hydrostatic(RHO, G, 0.5, -0.2, &r, &err) == WL_OK, "lowered level runs");
  CHECK_REL(r.force, 441.45, TOL_EXACT, "rho g 0.3^2 / 2 = 441.45 N/m");
  CHECK_TRUE(wl_design_hydrostatic(RHO, G, 0.0, 0.3, &r, &err) == WL_OK, "dry toe, flooded");
  CHECK_REL(r.force, 441.45, TOL_EXACT, "d = 0, eta = 0.3: same 441.45 N/m");

  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_hydrostatic(RHO, G, -0.1, 0.0, &r, &err), &err,
                           "still-water depth"),
             "error: d < 0");
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_hydrostatic(RHO, G, 0.5, -0.5, &r, &err), &err, "d + eta"),
             "error: d + eta = 0");
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_hydrostatic(0.0, G, 0.5, 0.0, &r, &err), &err, "density"),
             "error: rho = 0");
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_hydrostatic(RHO, G, 0.5, NAN, &r, &err), &err, "eta"),
             "error: eta NaN");
}

/* ---- Goda / Takahashi [GODA] [TAK] ---------------------------------------- */

static enum wl_status goda(const struct wl_design_goda_in *in, struct wl_design_goda_out *out,
                           struct wl_error *err) {
  wl_error_clear(err);
  return wl_design_goda(in, out, err);
}

static void test_goda(void) {
  struct wl_design_goda_in in;
  struct wl_design_goda_out out;
  struct wl_error err;

  /* (a) Hand calculation, wall on a plain bed: h = d = h' = hb = 10 m,
   * hc = 5 m, Hmax = 6 m, L = 100 m (given), beta = 0, rho 1025, g 9.81.
   *   x = 4 pi 10/100 = 1.2566371, sinh x = 1.6144880
   *   alpha1 = 0.6 + 0.5 (1.2566371/1.6144880)^2 = 0.90291450
   *   alpha2 = (hb - d)/(3 hb)(H/d)^2 = 0      (plain bed)
   *   kh = 0.62831853, cosh kh = 1.2039721
   *   alpha3 = 1 - (10/10)(1 - 1/1.2039721) = 0.83058404
   *   eta* = 0.75 * 2 * 6 = 9 m; hc* = min(9, 5) = 5 m; alpha4 = 1 - 5/9
   *   p1 = alpha1 rho g H = 0.90291450 * 1025 * 9.81 * 6 = 54474.186 Pa
   *   p3 = alpha3 p1 = 45245.390 Pa; p4 = (4/9) p1 = 24210.749 Pa
   *   pu = alpha1 alpha3 rho g H = 45245.390 Pa
   *   P = (p1 + p3)/2 * 10 + (p1 + p4)/2 * 5 = 498597.88 + 196712.34 = 695310.22 N/m
   *   Mp = (2 p1 + p3) 100/6 + (p1 + p4)/2 * 10 * 5 + (p1 + 2 p4) 25/6 = 4965751.5 N m/m
   *   Takahashi: delta11 = 0.93(-0.12) + 0.36(-0.6) = -0.3276,
   *   delta22 = -0.36(-0.12) + 0.93(-0.6) = -0.5148, delta1 = -6.552,
   *   delta2 = -2.52252, alpha_I1 = cos(-2.52252)/cosh(-6.552) = -0.0023247618,
   *   alpha_I0 = 6/10, alpha_I = -0.0013948571 < alpha2: no impulsive. */
  wl_design_goda_in_init(&in);
  in.rho = 1025.0;
  in.h = in.d = in.h_prime = 10.0;
  in.hc = 5.0;
  in.Hmax = 6.0;
  in.L = 100.0;
  CHECK_TRUE(goda(&in, &out, &err) == WL_OK, "Goda plain bed runs");
  CHECK_REL(out.alpha1, 0.90291450, TOL_HAND, "hand: alpha1");
  CHECK_ABS(out.alpha2, 0.0, 0.0, "hand: alpha2 = 0 on a plain bed");
  CHECK_REL(out.alpha3, 0.83058404, TOL_HAND, "hand: alpha3");
  CHECK_REL(out.eta_star, 9.0, TOL_EXACT, "hand: eta* = 0.75 (1 + 1) 6");
  CHECK_REL(out.hc_star, 5.0, TOL_EXACT, "hand: hc* = min(eta*, hc)");
  CHECK_REL(out.p1, 54474.186, TOL_HAND, "hand: p1");
  CHECK_REL(out.p3, 45245.390, TOL_HAND, "hand: p3");
  CHECK_REL(out.p4, 24210.749, TOL_HAND, "hand: p4");
  CHECK_REL(out.pu, 45245.390, TOL_HAND, "hand: pu");
  CHECK_REL(out.P, 695310.22, TOL_HAND, "hand: P");
  CHECK_REL(out.Mp, 4965751.5, TOL_HAND, "hand: Mp");
  CHECK_REL(out.delta11, -0.3276, TOL_EXACT, "hand: Takahashi delta11");
  CHECK_REL(out.delta22, -0.5148, TOL_EXACT, "hand: Takahashi delta22");
  CHECK_REL(out.alpha_I1, -0.0023247618, TOL_HAND, "hand: Takahashi alpha_I1");
  CHECK_REL(out.alpha_I, -0.0013948571, TOL_HAND, "hand: Takahashi alpha_I");
  CHECK_TRUE(out.result.in_range, "plain bed: alpha_I < alpha2, in range");
  CHECK_TRUE(out.result.basis == WL_DESIGN_BASIS_WAVE && strcmp(out.result.name, "goda") == 0,
             "Goda gives wave pressure");
  CHECK_REL(out.result.force_total, 695310.22 + 1025.0 * G * 100.0 / 2.0, TOL_HAND,
            "force_total = P + rho g h'^2 / 2");
  CHECK_REL(out.result.moment_total, 4965751.5 + 1025.0 * G * 1000.0 / 6.0, TOL_HAND,
            "moment_total = Mp + rho g h'^3 / 6");
  CHECK_REL(out.result.uplift_p, out.pu, 0.0, "result carries pu");
  CHECK_TRUE(isnan(out.U) && isnan(out.Mu), "no base width, no uplift force");
  check_profile(&out.result, "Goda: profile integral vs closed-form P, Mp");

  /* Uplift force with B = 20 m: U = pu B / 2 = 452453.90, Mu = (2/3) U B. */
  in.B = 20.0;
  CHECK_TRUE(goda(&in, &out, &err) == WL_OK, "Goda with base width runs");
  CHECK_REL(out.U, 452453.90, TOL_HAND, "hand: U = pu B / 2");
  CHECK_REL(out.Mu, 452453.90 * 40.0 / 3.0, TOL_HAND, "hand: Mu = (2/3) U B");
  in.B = 0.0;

  /* Crest above eta*: hc = 20 m, hc* = eta* = 9 m, p4 = 0; the profile ends at 0. */
  in.hc = 20.0;
  CHECK_TRUE(goda(&in, &out, &err) == WL_OK, "Goda high crest runs");
  CHECK_ABS(out.p4, 0.0, 0.0, "alpha4 = 0 when eta* <= hc");
  CHECK_REL(out.P, 0.5 * (54474.186 + 45245.390) * 10.0 + 0.5 * 54474.186 * 9.0, TOL_HAND,
            "hand: P with the full triangle to eta*");
  check_profile(&out.result, "Goda high crest: profile integral");
  in.hc = INFINITY;
  CHECK_TRUE(goda(&in, &out, &err) == WL_OK && out.hc_star == 9.0, "no crest: hc* = eta*");

  /* (b) Goda (2000) p. 140 inputs as in the `breakwater` package's test
   * (test/test_goda.py): h 10.1, d 5.6, h' 7.1, hc 3.4, Hmax 8.05, T 11.4 s,
   * beta 15 deg, hb = 10.1 + 5 * 5.796 / 100 (slope 1/100, H1/3 5.796),
   * BM 8 m, rho 1030; the package applies Takahashi always and asserts to
   * 2 decimals: p1 97644.84, p3 87211.93, p4 69674.10, pu 65739.31 Pa,
   * alpha_I 0.3223 (4 decimals). */
  wl_design_goda_in_init(&in);
  in.rho = 1030.0;
  in.h = 10.1;
  in.d = 5.6;
  in.h_prime = 7.1;
  in.hc = 3.4;
  in.Hmax = 8.05;
  in.T = 11.4;
  in.beta = 15.0 * DEG;
  in.hb = 10.1 + 5.0 * 5.796 / 100.0;
  in.BM = 8.0;
  in.impulsive = 1;
  CHECK_TRUE(goda(&in, &out, &err) == WL_OK, "Goda (2000) p. 140 example runs");
  CHECK_ABS(out.p1, 97644.84, 0.01, "breakwater pkg, Goda (2000) p.140 inputs: p1");
  CHECK_ABS(out.p3, 87211.93, 0.01, "breakwater pkg, Goda (2000) p.140 inputs: p3");
  CHECK_ABS(out.p4, 69674.10, 0.01, "breakwater pkg, Goda (2000) p.140 inputs: p4");
  CHECK_ABS(out.pu, 65739.31, 0.01, "breakwater pkg, Goda (2000) p.140 inputs: pu");
  CHECK_ABS(out.alpha_I, 0.3223, 5e-5, "breakwater pkg: Takahashi alpha_I");
  CHECK_TRUE(out.alpha_star == out.alpha_I && strcmp(out.result.name, "goda-takahashi") == 0,
             "alpha* = alpha_I when it exceeds alpha2");
  check_profile(&out.result, "Goda-Takahashi: profile integral");

  /* Impulsive flag of plain Goda flips where alpha_I crosses alpha2 = 0.3175:
   * BM 8 m gives alpha_I 0.3223 (out: the package warns), BM 7 m gives
   * 0.2758 (in). */
  in.impulsive = 0;
  CHECK_TRUE(goda(&in, &out, &err) == WL_OK, "plain Goda, BM 8 m");
  CHECK_ABS(out.alpha2, 0.31754454, 1e-7, "hand: alpha2 = (hb - d)/(3 hb)(H/d)^2");
  CHECK_TRUE(!out.result.in_range && strstr(out.result.range_note, "impulsive"),
             "BM 8 m: alpha_I 0.3223 > alpha2 0.3175, out of range");
  in.BM = 7.0;
  CHECK_TRUE(goda(&in, &out, &err) == WL_OK, "plain Goda, BM 7 m");
  CHECK_ABS(out.alpha_I, 0.27581991, 1e-7, "hand (Takahashi eqs, BM 7 m): alpha_I");
  CHECK_TRUE(out.result.in_range, "BM 7 m: alpha_I 0.2758 <= alpha2, in range");

  /* (c) Deltares coastal-structures-toolbox test case "C2"
   * (tests/structural/forces_caisson/goda1985_test.py): Hmax 7.88, H1/3 4.35,
   * T 8 s, h 10, d 4, h' 6, Rc 5, beta 0, slope 1/100 (hb = 10 + 5 * 4.35/100),
   * rho 1025: FH 1177.2 kN/m, p1 125.089 kPa (its own dispersion solver:
   * 0.1 % allowed). */
  wl_design_goda_in_init(&in);
  in.rho = 1025.0;
  in.h = 10.0;
  in.d = 4.0;
  in.h_prime = 6.0;
  in.hc = 5.0;
  in.Hmax = 7.88;
  in.T = 8.0;
  in.hb = 10.0 + 5.0 * 4.35 / 100.0;
  CHECK_TRUE(goda(&in, &out, &err) == WL_OK, "Deltares C2 runs");
  CHECK_REL(out.P, 1177.2e3, 1e-3, "Deltares toolbox C2: FH 1177.2 kN/m");
  CHECK_REL(out.p1, 125.089e3, 1e-3, "Deltares toolbox C2: p1 125.089 kPa");

  /* Error paths. */
  struct wl_design_goda_in ok = in;
  in = ok; in.d = 11.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "berm"), "error: d > h");
  in = ok; in.h_prime = 3.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "h'"), "error: h' < d");
  in = ok; in.h_prime = 10.5;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "h'"), "error: h' > h");
  in = ok; in.hb = 3.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "hb"), "error: hb < d");
  in = ok; in.hc = -1.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "crest"), "error: hc < 0");
  in = ok; in.hc = NAN;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "crest"), "error: hc NaN");
  in = ok; in.beta = 2.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "beta"), "error: beta > pi/2");
  in = ok; in.lambda2 = 0.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "lambda2"), "error: lambda2 = 0");
  in = ok; in.BM = -1.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "berm width"), "error: BM < 0");
  in = ok; in.B = -1.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "base width"), "error: B < 0");
  in = ok; in.T = 0.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "wavelength"), "error: no T, no L");
  in = ok; in.L = -5.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "wavelength"), "error: L < 0");
  wl_design_goda_in_init(&in);
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "depth in front"),
             "error: fields left at their NAN defaults");
  in = ok; in.rho = -1.0;
  CHECK_TRUE(expect_einput(goda(&in, &out, &err), &err, "density"), "error: rho < 0");
}

/* ---- Sainflou [SAIN] ------------------------------------------------------ */

static enum wl_status sainflou(const struct wl_design_sainflou_in *in,
                               struct wl_design_sainflou_out *out, struct wl_error *err) {
  wl_error_clear(err);
  return wl_design_sainflou(in, out, err);
}

static void test_sainflou(void) {
  struct wl_design_sainflou_out out;
  struct wl_error err;

  /* (a) Hand calculation: h 10, H 2, L 100 (given), rho 1000, g 9.81.
   *   kh = 0.62831853, tanh kh = 0.55689331, cosh kh = 1.2039721
   *   delta0 = pi 4/100 / 0.55689331 = 0.22565131 m; crest = 2.2256513 m
   *   p2 = 9810 * 2 / 1.2039721 = 16296.059 Pa; p_bed = 98100 + p2 = 114396.06 Pa
   *   p1 = 114396.06 * 2.2256513 / 12.225651 = 20825.536 Pa
   *   F = 114396.06 * 12.225651 / 2 = 699283.16 N/m; M = F * 12.225651 / 3 = 2849730.7 */
  struct wl_design_sainflou_in in = {RHO, G, 10.0, 2.0, 0.0, 100.0, INFINITY};
  CHECK_TRUE(sainflou(&in, &out, &err) == WL_OK, "Sainflou runs");
  CHECK_REL(out.delta0, 0.22565131, TOL_HAND, "hand: delta0 = (pi H^2/L) coth kh");
  CHECK_REL(out.p2, 16296.059, TOL_HAND, "hand: p2 = rho g H / cosh kh");
  CHECK_REL(out.p1, 20825.536, TOL_HAND, "hand: p1 = (p2 + rho g h)(H + d0)/(h + H + d0)");
  CHECK_REL(out.result.force, 699283.16, TOL_HAND, "hand: F");
  CHECK_REL(out.result.moment, 2849730.7, TOL_HAND, "hand: M");
  CHECK_TRUE(out.result.in_range && !out.overtopped, "H/h 0.2, H/L 0.02: in range");
  CHECK_REL(out.result.force_total, out.result.force, 0.0, "TOTAL basis");
  check_profile(&out.result, "Sainflou: profile (p_bed, p1 at SWL, 0 at crest) integral");
  CHECK_REL(wl_design_profile_pressure(&out.result.profile, 10.0), out.p1, TOL_EXACT,
            "profile passes through p1 at SWL");

  /* (b) ACES User's Guide Example 4-3 (values as tabulated by the CHESS-QC
   * port): d 15 ft, H 8 ft, T 10 s, chi 1, 64 lb/ft^3 (rho = 1025.18 with
   * g 9.80665): Sainflou crest force 17724.17 lb/ft, moment 148008.60
   * lb ft/ft. ACES integrates the Lagrangian solution in 90 steps; the
   * straight-line diagram here gives 18014 lb/ft (+1.6 %) and 151739
   * lb ft/ft (+2.5 %): 3 % allowed. */
  const double LBF = 4.4482216152605, FT = 0.3048;
  struct wl_design_sainflou_in aces = {64.0 * LBF / (FT * FT * FT) / 9.80665, 9.80665, 15.0 * FT,
                                       8.0 * FT, 10.0, 0.0, INFINITY};
  CHECK_TRUE(sainflou(&aces, &out, &err) == WL_OK, "ACES 4-3 example runs");
  CHECK_REL(out.result.force / (LBF / FT), 17724.17, 0.03,
            "ACES User's Guide Ex. 4-3: Sainflou crest force 17724 lb/ft (Lagrangian)");
  CHECK_REL(out.result.moment / LBF, 148008.60, 0.03,
            "ACES User's Guide Ex. 4-3: Sainflou crest moment 148009 lb ft/ft (Lagrangian)");

  /* (c) Small waves: F -> rho g h^2 / 2 (+ O(H)). */
  in.H = 1e-7;
  CHECK_TRUE(sainflou(&in, &out, &err) == WL_OK, "tiny wave runs");
  CHECK_REL(out.result.force, RHO * G * 50.0, 1e-6, "H -> 0: hydrostatic rho g h^2/2");

  /* (d) Flags either side of each limit. Breaking at 0.78 h = 7.8 m
   * (Miche at h/L 0.1: 0.142 tanh 0.628 = 0.0791 > 0.0781, not the limit). */
  in.H = 7.79;
  CHECK_TRUE(sainflou(&in, &out, &err) == WL_OK && out.result.in_range, "H 7.79 < 0.78 h: in");
  in.H = 7.81;
  CHECK_TRUE(sainflou(&in, &out, &err) == WL_OK && !out.result.in_range &&
                 strstr(out.result.range_note, "breaking"),
             "H 7.81 > 0.78 h: breaking, out");
  /* Miche at h 20, L 100: 0.142 tanh(1.2566) = 0.120727, H limit 12.07 m (< 0.78 h = 15.6). */
  struct wl_design_sainflou_in deep = {RHO, G, 20.0, 12.0, 0.0, 100.0, INFINITY};
  CHECK_TRUE(sainflou(&deep, &out, &err) == WL_OK && out.result.in_range, "H/L 0.120: in");
  deep.H = 12.1;
  CHECK_TRUE(sainflou(&deep, &out, &err) == WL_OK && !out.result.in_range &&
                 strstr(out.result.range_note, "steep"),
             "H/L 0.121 > Miche 0.1207: too steep, out");
  /* Crest at the clapotis crest 2.2256513 m above SWL. */
  in.H = 2.0;
  in.hc = 2.23;
  CHECK_TRUE(sainflou(&in, &out, &err) == WL_OK && out.result.in_range, "hc 2.23 >= crest: in");
  in.hc = 2.22;
  CHECK_TRUE(sainflou(&in, &out, &err) == WL_OK && !out.result.in_range && out.overtopped,
             "hc 2.22 < crest 2.2257: overtopped, out");
  /* Cut profile, hc 1 m: p(crest) = p1 (1 - 1/2.2256513) = 11468.483 Pa;
   * F = (114396.06 + 20825.536)/2 * 10 + (20825.536 + 11468.483)/2 * 1
   *   = 676107.97 + 16147.010 = 692254.98 N/m. */
  in.hc = 1.0;
  CHECK_TRUE(sainflou(&in, &out, &err) == WL_OK && out.overtopped, "hc 1 m: overtopped");
  CHECK_REL(out.result.force, 692254.98, TOL_HAND, "hand: force of the profile cut at the crest");
  check_profile(&out.result, "Sainflou cut profile: integral");

  struct wl_design_sainflou_in bad = {RHO, G, 10.0, 2.0, 0.0, 100.0, INFINITY};
  bad.H = 0.0;
  CHECK_TRUE(expect_einput(sainflou(&bad, &out, &err), &err, "wave height"), "error: H = 0");
  bad.H = 2.0;
  bad.h = NAN;
  CHECK_TRUE(expect_einput(sainflou(&bad, &out, &err), &err, "depth"), "error: h NaN");
  bad.h = 10.0;
  bad.hc = -0.1;
  CHECK_TRUE(expect_einput(sainflou(&bad, &out, &err), &err, "crest"), "error: hc < 0");
  bad.hc = INFINITY;
  bad.L = 0.0;
  CHECK_TRUE(expect_einput(sainflou(&bad, &out, &err), &err, "wavelength"), "error: no T, no L");
  bad.L = 100.0;
  bad.g = 0.0;
  CHECK_TRUE(expect_einput(sainflou(&bad, &out, &err), &err, "gravity"), "error: g = 0");
}

/* ---- FEMA P-646 / CCH [FEMA] [CCH] ---------------------------------------- */

static enum wl_status fema(const struct wl_design_fema_in *in, struct wl_design_fema_out *out,
                           struct wl_error *err) {
  wl_error_clear(err);
  return wl_design_fema(in, out, err);
}

static void test_fema(void) {
  struct wl_design_fema_in in;
  struct wl_design_fema_out out;
  struct wl_error err;

  /* (a) FEMA P-646 (2012) App. C.3: z 4 m, R 13 m, g 9.81:
   * (h u^2)_max = 105 m^3/s^2 (printed, rounded); Fd = 1155 kN and
   * Fs = 1.5 Fd = 1730 kN for B 10 m, rho_s 1100, Cd 2: 115.5 and 173.0 kN/m.
   * Hand: z/R = 0.30769231; 0.125 - 0.235 (0.30769231) + 0.11 (0.30769231)^2
   * = 0.125 - 0.072307692 + 0.010414201 = 0.063106509; times 9.81 * 169
   * = 104.62365 m^3/s^2; Fd = 0.5 * 1100 * 2 * 104.62365 = 115086.02 N/m. */
  wl_design_fema_in_init(&in);
  in.R = 13.0;
  in.z = 4.0;
  CHECK_TRUE(fema(&in, &out, &err) == WL_OK, "FEMA C.3 runs");
  CHECK_ABS(out.hu2_max, 105.0, 0.5, "FEMA P-646 (2012) App. C.3: (h u^2)_max = 105 m^3/s^2");
  CHECK_REL(out.hu2_max, 104.62365, TOL_HAND, "hand: Eq 6-6");
  CHECK_REL(out.rho_s, 1100.0, TOL_EXACT, "rho_s = 1.1 rho = 1100 kg/m^3 (Eq 6-1)");
  CHECK_REL(out.hydrodynamic.force, 1155e3 / 10.0, 0.005,
            "FEMA P-646 (2012) App. C.3: Fd = 1155 kN over B = 10 m (from the rounded 105)");
  CHECK_REL(out.hydrodynamic.force, 115086.02, TOL_HAND, "hand: Eq 6-5 per metre");
  CHECK_REL(out.impulsive.force, 1730e3 / 10.0, 0.005,
            "FEMA P-646 (2012) App. C.3: Fs = 1.5 Fd = 1730 kN over B = 10 m");
  CHECK_REL(out.impulsive.force, 1.5 * 115086.02, TOL_HAND, "Eq 6-7: 1.5 Fd");
  CHECK_TRUE(out.hydrodynamic.in_range && out.impulsive.in_range, "0 <= z/R <= 1: in range");
  CHECK_TRUE(out.hydrodynamic.basis == WL_DESIGN_BASIS_DYNAMIC, "drag is a dynamic force");
  CHECK_REL(out.hydrodynamic.moment, 115086.02 * 9.0 / 2.0, TOL_HAND,
            "assumed lever arm h_max/2 = 4.5 m");

  /* (b) Eq 6-1 with Eq 6-3: h_max = 13 - 4 = 9 m, Fh = 0.5 * 1100 * 9.81 * 81
   * = 437035.5 N/m at 3 m: M = 1311106.5 N m/m. */
  CHECK_REL(out.h_max, 9.0, TOL_EXACT, "Eq 6-3: h_max = R - z");
  CHECK_REL(out.hydrostatic.force, 437035.5, TOL_EXACT, "hand: Eq 6-1");
  CHECK_REL(out.hydrostatic.moment, 1311106.5, TOL_EXACT, "hand: Fh h_max / 3");
  check_profile(&out.hydrostatic, "FEMA hydrostatic profile integral");

  /* (c) Flags: Eq 6-6 for 0 <= z <= R. It vanishes at z = R
   * (0.125 - 0.235 + 0.11 = 0), so the cut-off at R is continuous. */
  in.z = 0.0;
  CHECK_TRUE(fema(&in, &out, &err) == WL_OK && out.hydrodynamic.in_range, "z = 0: in range");
  CHECK_REL(out.hu2_max, G * 169.0 * 0.125, TOL_EXACT, "z = 0: g R^2 / 8");
  in.z = -0.5;
  CHECK_TRUE(fema(&in, &out, &err) == WL_OK && !out.hydrodynamic.in_range &&
                 !out.impulsive.in_range && out.hydrostatic.in_range,
             "z < 0 (wall in water): Eq 6-6 out of range, hydrostatic still exact");
  CHECK_REL(out.hydrodynamic.force_total,
            out.hydrodynamic.force + RHO * G * 0.25 / 2.0, TOL_EXACT,
            "dynamic basis: force_total adds still water 0.5 m deep");
  in.z = 12.999;
  CHECK_TRUE(fema(&in, &out, &err) == WL_OK && out.hydrodynamic.in_range, "z just below R: in");
  /* slope at z = R: g R^2 (-0.235 + 0.22)/R = -1.91 m^2/s^2 per m: 0.0019 at 1 mm */
  CHECK_ABS(out.hu2_max, 0.0019, 1e-4, "Eq 6-6 -> 0 as z -> R (linear slope, 1 mm below)");
  in.z = 13.0;
  CHECK_TRUE(fema(&in, &out, &err) == WL_OK && !out.hydrostatic.in_range &&
                 out.hydrostatic.force == 0.0 && out.hydrodynamic.force == 0.0,
             "z = R: not reached, zero forces, out of range");

  /* (d) CCH surge: h 2 m, rho_s 1100: Fs = 4.5 * 1100 * 9.81 * 4 = 194238 N/m
   * acting at h: M = 388476 N m/m; its profile is still water 3h = 6 m deep,
   * whose force 0.5 rho_s g 36 is the same 4.5 rho_s g h^2. */
  struct wl_design_result r;
  wl_error_clear(&err);
  CHECK_TRUE(wl_design_cch_surge(RHO, G, 1.1, 2.0, 0.0, &r, &err) == WL_OK, "CCH surge runs");
  CHECK_REL(r.force, 194238.0, TOL_EXACT, "hand: 4.5 rho_s g h^2");
  CHECK_REL(r.moment, 388476.0, TOL_EXACT, "hand: at h above the base");
  CHECK_TRUE(r.in_range, "bore on dry ground: in range");
  check_profile(&r, "CCH surge profile (3h still water) integral");
  CHECK_TRUE(wl_design_cch_surge(RHO, G, 1.1, 2.0, -1.0, &r, &err) == WL_OK && !r.in_range,
             "wall base under water: out of range");

  struct wl_design_fema_in ok = in;
  in = ok; in.R = 0.0;
  CHECK_TRUE(expect_einput(fema(&in, &out, &err), &err, "run-up"), "error: R = 0");
  in = ok; in.z = NAN;
  CHECK_TRUE(expect_einput(fema(&in, &out, &err), &err, "elevation"), "error: z NaN");
  in = ok; in.Cd = 0.0;
  CHECK_TRUE(expect_einput(fema(&in, &out, &err), &err, "drag"), "error: Cd = 0");
  in = ok; in.sediment = -1.0;
  CHECK_TRUE(expect_einput(fema(&in, &out, &err), &err, "sediment"), "error: sediment < 0");
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_cch_surge(RHO, G, 1.1, 0.0, 0.0, &r, &err), &err, "bore"),
             "error: bore depth 0");
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_cch_surge(RHO, G, 1.1, 1.0, INFINITY, &r, &err), &err,
                           "elevation"),
             "error: z infinite");
}

/* ---- every formula for a scenario ----------------------------------------- */

static void test_evaluate(void) {
  struct wl_design_scenario sc;
  struct wl_design_result res[WL_DESIGN_MAX_RESULTS];
  struct wl_error err;
  int n = -1;

  /* The Goda hand case (a) with fresh water, plus a raised level, a
   * tsunami run-up and a bore: all nine rows. */
  wl_design_scenario_init(&sc);
  sc.d = 10.0;
  sc.hc = 5.0;
  sc.H = 6.0;
  sc.L = 100.0;
  sc.eta = 1.0;
  sc.R = 13.0;
  sc.h_bore = 2.0;
  wl_error_clear(&err);
  CHECK_TRUE(wl_design_evaluate(&sc, res, WL_DESIGN_MAX_RESULTS, &n, &err) == WL_OK,
             "evaluate runs");
  static const char *names[] = {"hydrostatic", "hydrostatic-level", "goda", "goda-takahashi",
                                "sainflou", "fema-hydrostatic", "fema-hydrodynamic",
                                "fema-impulsive", "cch-surge"};
  CHECK_TRUE(n == 9, "nine rows apply");
  int names_ok = n == 9;
  for (int i = 0; i < n && names_ok; i++) names_ok = strcmp(res[i].name, names[i]) == 0;
  CHECK_TRUE(names_ok, "rows in the documented order");
  CHECK_REL(res[0].force, RHO * G * 50.0, TOL_EXACT, "row 1: rho g d^2/2");
  CHECK_REL(res[1].force, RHO * G * 60.5, TOL_EXACT, "row 2: rho g (d + eta)^2/2");
  /* Goda hand case scaled to rho 1000: P = 695310.22 * 1000/1025. */
  CHECK_REL(res[2].force, 695310.22 / 1.025, TOL_HAND, "row 3: Goda hand case at rho 1000");
  CHECK_REL(res[2].force_total, 695310.22 / 1.025 + RHO * G * 50.0, TOL_HAND,
            "row 3: force_total adds rho g d^2/2");
  CHECK_REL(res[3].force, res[2].force, TOL_EXACT, "plain bed: alpha_I < 0, Takahashi = Goda");
  CHECK_TRUE(!res[6].in_range && !res[7].in_range && !res[8].in_range,
             "tsunami rows for a wall standing in water are flagged");
  int all_ok = 1;
  for (int i = 0; i < n; i++)
    all_ok = all_ok && res[i].citation && res[i].citation[0] && res[i].range_note[0] &&
             isfinite(res[i].force) && isfinite(res[i].moment) && isfinite(res[i].force_total);
  CHECK_TRUE(all_ok, "every row: citation, range note, finite numbers");
  for (int i = 0; i < n; i++)
    if (res[i].basis != WL_DESIGN_BASIS_DYNAMIC) check_profile(&res[i], res[i].name);

  /* Sainflou row = the hand case of test_sainflou at H 6 instead of 2:
   * recomputed through the single-formula call. */
  struct wl_design_sainflou_in si = {RHO, G, 10.0, 6.0, 0.0, 100.0, 5.0};
  struct wl_design_sainflou_out so;
  wl_error_clear(&err);
  CHECK_TRUE(wl_design_sainflou(&si, &so, &err) == WL_OK &&
                 fabs(so.result.force - res[4].force) <= TOL_EXACT * so.result.force,
             "row 5 equals the Sainflou call");

  /* A dry wall reached by the FEMA C.3 run-up: three FEMA rows only. */
  wl_design_scenario_init(&sc);
  sc.z_toe = 4.0;
  sc.R = 13.0;
  CHECK_TRUE(wl_design_evaluate(&sc, res, WL_DESIGN_MAX_RESULTS, &n, &err) == WL_OK && n == 3,
             "dry wall: three FEMA rows");
  CHECK_REL(res[0].force, 437035.5, TOL_EXACT, "dry wall: Eq 6-1 as in test_fema");
  CHECK_REL(res[1].force, 115086.02, TOL_HAND, "dry wall: Eq 6-5 as in test_fema");

  /* The seawall flume of ARCHITECTURE.md's sketch: 0.36 m deep, crest
   * 0.05 m, a 0.05 m wave of 1.5 s: five finite rows. */
  wl_design_scenario_init(&sc);
  sc.d = 0.36;
  sc.hc = 0.05;
  sc.H = 0.05;
  sc.T = 1.5;
  CHECK_TRUE(wl_design_evaluate(&sc, res, WL_DESIGN_MAX_RESULTS, &n, &err) == WL_OK && n == 4,
             "flume: hydrostatic, goda, goda-takahashi, sainflou");
  all_ok = n == 4;
  for (int i = 0; i < n; i++) all_ok = all_ok && isfinite(res[i].force_total);
  CHECK_TRUE(all_ok, "flume rows finite");

  /* Errors. */
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_evaluate(&sc, res, 3, &n, &err), &err, "results array") &&
                 n == 0,
             "error: results array too small");
  sc.z_toe = 1.0;
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_evaluate(&sc, res, WL_DESIGN_MAX_RESULTS, &n, &err), &err,
                           "scenario: design: toe") &&
                 n == 0,
             "error: toe both wet and dry, prefixed 'scenario: '");
  sc.z_toe = 0.0;
  sc.H = NAN;
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_evaluate(&sc, res, WL_DESIGN_MAX_RESULTS, &n, &err), &err,
                           "wave height"),
             "error: H NaN");
  sc.H = 0.05;
  sc.eta = INFINITY;
  wl_error_clear(&err);
  CHECK_TRUE(expect_einput(wl_design_evaluate(&sc, res, WL_DESIGN_MAX_RESULTS, &n, &err), &err,
                           "eta"),
             "error: eta infinite");
}

int main(void) {
  gsl_set_error_handler_off();
  test_wavelength();
  test_profile();
  test_hydrostatic();
  test_goda();
  test_sainflou();
  test_fema();
  test_evaluate();
  return TEST_RESULT();
}
