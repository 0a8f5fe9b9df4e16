/* test_waves.c: the waves module against references it did not produce:
 * REFERENCES.md 3.4 (exact solitary-wave table, Grimshaw F column) and 3.5
 * (Goring stroke and example), seed 001 eqs 17/21/22, closed forms derived
 * from int sech^2 = 2/K, int sech^4 = 4/(3K), int sech^6 = 16/(15K), exact
 * identities of steady irrotational waves (mass flux c eta, continuity,
 * kinematic surface condition), finite differences, and an RK4 integration of
 * the paddle ODE written here. The exact wave's tabulated field
 * (WL_SOLITARY_EXACT) is checked against the table's integrals by a
 * quadrature written here, and against the conditions that define a steady
 * irrotational wave (mass flux, both surface conditions, bed, curl). */
#include "wallload/waves.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "testutil.h"

static const double G = 9.81, RHO = 1000.0;

/* REFERENCES 3.4, exact Euler solitary wave (rho = g = h = 1), and the
 * Grimshaw-3 F column. */
struct table_row {
  double eps, F_exact, F_grimshaw, M, I, KE, PE, E;
};
static const struct table_row TABLE[] = {
    {0.05, 1.02463136, 1.024631, 0.525711, 0.538660, 0.00890874, 0.00873897, 0.017648},
    {0.10, 1.04854822, 1.048550, 0.755552, 0.792232, 0.02599375, 0.02504739, 0.051041},
    {0.20, 1.09434450, 1.094375, 1.097656, 1.201214, 0.07747760, 0.07229525, 0.149773},
    {0.30, 1.13752302, 1.137692, 1.370744, 1.559253, 0.14806832, 0.13431404, 0.282382},
};
enum { N_TABLE = sizeof TABLE / sizeof TABLE[0] };

/* Tolerances, each with its source. */
/* Table entries are rounded to 6 decimals (F exact to 8): half a unit. */
static const double TABLE_HALF_ULP6 = 5e-7, TABLE_HALF_ULP8 = 5e-9;
/* Third-order theory: the profile is off by O(eps^4) h over a width
 * O(eps^-1/2) h, so integrals (~eps^1/2 for M, ~eps^3/2 for E) carry a
 * relative error O(eps^3). Allowed coefficient 1 (observed at eps 0.05-0.3:
 * mass 0.24-0.27, momentum 0.39-0.44, potential 0.2, energy 0.45-0.55). */
static const double GRIMSHAW_EPS3_COEF = 1.0;
/* Exact identities satisfied by the third-order field to O(eps^3) relative:
 * allowed coefficient 1 for the depth-integrated flux and for continuity
 * (observed 0.2 to 0.45), 4 for the kinematic condition, a pointwise check at
 * the surface where the truncated (z/h)^4 terms are largest (observed 2.2 to
 * 2.8). With seed 003's printed eps^3 term of w, continuity and kinematic
 * errors are 2.2 to 2.5 eps^2 and fail these bounds. */
static const double IDENTITY_EPS3_COEF = 1.0, KINEMATIC_EPS3_COEF = 4.0;
/* Quadrature accuracy of the module (relative 1e-11 requested). */
static const double QUAD_REL = 1e-6;

static int expect_status(enum wl_status got, enum wl_status want, const struct wl_error *err,
                         const char *must_contain) {
  return got == want && err->status == want &&
         (!must_contain || strstr(err->msg, must_contain) != NULL);
}

/* ---- inputs -------------------------------------------------------------- */
static void test_bad_inputs(void) {
  struct wl_error err;
  struct wl_solitary sw;
  enum wl_status st;

  wl_error_clear(&err);
  st = wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, 1.0, 0.0, G, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "H = 0"), "input: H = 0 rejected");
  printf("  message: %s\n", err.msg);
  wl_error_clear(&err);
  st = wl_waves_solitary_init(&sw, WL_SOLITARY_BOUSSINESQ, 1.0, -0.1, G, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, NULL), "input: H < 0 rejected");
  wl_error_clear(&err);
  st = wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, 1.0, 0.9, G, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "0.78"), "input: eps = 0.9 rejected, 0.78 named");
  printf("  message: %s\n", err.msg);
  CHECK_TRUE(sw.h == 0 && sw.c == 0, "input: struct zeroed on failure");
  wl_error_clear(&err);
  st = wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, 0.0, 0.1, G, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "depth"), "input: h = 0 rejected");
  wl_error_clear(&err);
  st = wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, 1.0, 0.1, NAN, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "gravity"), "input: g = NaN rejected");
  wl_error_clear(&err);
  st = wl_waves_solitary_init(&sw, (enum wl_solitary_theory)7, 1.0, 0.1, G, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "theory"), "input: unknown theory rejected");
  wl_error_clear(&err);
  st = wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, 1.0, 0.78, G, &err);
  CHECK_TRUE(st == WL_OK, "input: eps = 0.78 accepted (the documented maximum)");

  struct wl_wave_integrals wi;
  wl_error_clear(&err);
  st = wl_waves_solitary_integrals(&sw, -1.0, &wi, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "rho"), "input: integrals rho < 0 rejected");

  double H = 1;
  wl_error_clear(&err);
  st = wl_waves_solitary_height_from_energy(0.0, 1.0, G, RHO, &H, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, NULL) && H == 0,
             "input: energy 0 rejected, H = 0");
  wl_error_clear(&err);
  /* The eps = 0.78 Grimshaw wave carries 1.22 rho g h^3; ask for 1.5. */
  st = wl_waves_solitary_height_from_energy(1.5 * RHO * G, 1.0, G, RHO, &H, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "J/m"), "input: energy above maximum rejected");
  printf("  message: %s\n", err.msg);

  struct wl_goring gp;
  wl_error_clear(&err);
  st = wl_waves_goring_init(&gp, 0.5, 0.15, G, 0.0, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "eps0"), "input: Goring eps0 = 0 rejected");
  wl_error_clear(&err);
  st = wl_waves_goring_init(&gp, 0.5, 0.45, G, WL_WAVES_GORING_EPS0_DEFAULT, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "Goring paddle: "),
             "input: Goring eps = 0.9 rejected with context");

  double V = 1;
  wl_error_clear(&err);
  st = wl_waves_lh74_potential(RHO, G, -1.0, &V, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, NULL) && V == 0, "input: LH74 h < 0 rejected");

  struct wl_solitary_exact ex;
  wl_error_clear(&err);
  st = wl_waves_exact_solitary(0.85, 4096, &ex, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "0.79"), "input: exact eps = 0.85 rejected");
  wl_error_clear(&err);
  st = wl_waves_exact_solitary(0.1, 5000, &ex, &err);
  CHECK_TRUE(expect_status(st, WL_EINPUT, &err, "power of two"),
             "input: exact n_modes = 5000 rejected");
}

/* ---- Grimshaw surface and celerity ---------------------------------------- */
static void test_grimshaw_point_values(void) {
  struct wl_error err;
  wl_error_clear(&err);
  for (int i = 0; i < N_TABLE; i++) {
    struct wl_solitary sw;
    double h = 0.36;
    wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, h, TABLE[i].eps * h, G, &err);
    CHECK_ABS(wl_waves_solitary_celerity(&sw) / sqrt(G * h), TABLE[i].F_grimshaw, TABLE_HALF_ULP6,
              "REFERENCES 3.4 table, column F Grimshaw-3");
    /* F Grimshaw vs exact: third order, O(eps^4) */
    CHECK_ABS(wl_waves_solitary_celerity(&sw) / sqrt(G * h), TABLE[i].F_exact,
              0.05 * pow(TABLE[i].eps, 4) + TABLE_HALF_ULP8,
              "REFERENCES 3.4 F exact, third-order truncation 0.05 eps^4");
    CHECK_REL(wl_waves_solitary_eta(&sw, 0.0), sw.H, 1e-15,
              "seed 003 eq 21 at the crest: eta(0) = H (s = 1, q = 0)");
  }

  /* eps -> 0: Grimshaw -> Boussinesq. eta differs by O(eps^2) h (the eps^2
   * term, coefficient <= 3/16, and alpha's -5/8 eps shift, coefficient
   * <= 0.6): bound eps^2 h. c differs by eps^2/40 relative. */
  const double eps = 1e-3, h = 1.0;
  struct wl_solitary gr, bo;
  wl_waves_solitary_init(&gr, WL_SOLITARY_GRIMSHAW, h, eps * h, G, &err);
  wl_waves_solitary_init(&bo, WL_SOLITARY_BOUSSINESQ, h, eps * h, G, &err);
  double max_eta = 0, max_u = 0, max_w = 0, max_w_B = 0;
  for (int k = -400; k <= 400; k++) {
    double X = k * 0.02 / bo.K;
    max_eta = fmax(max_eta, fabs(wl_waves_solitary_eta(&gr, X) - wl_waves_solitary_eta(&bo, X)));
    for (int j = 0; j <= 4; j++) {
      double z = 0.25 * j * h, ug, wg, ub, wb;
      wl_waves_solitary_velocity(&gr, X, z, &ug, &wg);
      wl_waves_solitary_velocity(&bo, X, z, &ub, &wb);
      max_u = fmax(max_u, fabs(ug - ub));
      max_w = fmax(max_w, fabs(wg - wb));
      max_w_B = fmax(max_w_B, fabs(wb));
    }
  }
  CHECK_TRUE(err.status == WL_OK, "init ok");
  CHECK_ABS(max_eta / h, 0.0, eps * eps, "Grimshaw -> Boussinesq at eps = 1e-3: |d eta| <= eps^2 h");
  CHECK_ABS(max_u / sqrt(G * h), 0.0, 2 * eps * eps,
            "Grimshaw -> Boussinesq at eps = 1e-3: |d u| <= 2 eps^2 sqrt(gh)");
  CHECK_ABS(max_w / max_w_B, 0.0, 2 * eps,
            "Grimshaw -> Boussinesq at eps = 1e-3: relative |d w| <= 2 eps");
  CHECK_REL(gr.c / bo.c, 1.0 - eps * eps / 40.0, 1e-9,
            "eq 23 vs sqrt(g(h+H)): ratio 1 - eps^2/40 + O(eps^3)");
}

/* ---- exact identities of a steady wave, applied to the Grimshaw field ------ */
/* Returns max over X of the relative violation of: mass flux int_0^{h+eta} u
 * dz = c eta; continuity du/dX + dw/dz = 0; kinematic surface condition
 * w = (u - c) eta_X at z = h + eta. */
static void identity_errors(double eps, double *flux, double *cont, double *kin) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_solitary sw;
  const double h = 1.0;
  wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, h, eps * h, G, &err);
  *flux = *cont = *kin = 0;
  double ref_cont = 0, ref_kin = 0;
  double dcont[64], dkin[64];
  int n = 0;
  for (int k = 1; k <= 12; k++) {
    double X = 0.25 * k / sw.K;
    double eta = wl_waves_solitary_eta(&sw, X), d = h + eta;
    /* flux by 6-point Gauss-Legendre on [0, d]: exact for degree <= 11 */
    static const double gx[3] = {0.2386191860831969, 0.6612093864662645, 0.9324695142031521};
    static const double gw[3] = {0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
    double q = 0;
    for (int j = 0; j < 3; j++)
      for (int sgn = -1; sgn <= 1; sgn += 2) {
        double u;
        wl_waves_solitary_velocity(&sw, X, 0.5 * d * (1 + sgn * gx[j]), &u, NULL);
        q += 0.5 * d * gw[j] * u;
      }
    *flux = fmax(*flux, fabs(q - sw.c * eta) / (sw.c * eta));
    /* continuity at mid-depth, central differences */
    double dX = 1e-4 / sw.K, dz = 1e-4 * h, z = 0.5 * h, up, um, wp, wm;
    wl_waves_solitary_velocity(&sw, X + dX, z, &up, NULL);
    wl_waves_solitary_velocity(&sw, X - dX, z, &um, NULL);
    wl_waves_solitary_velocity(&sw, X, z + dz, NULL, &wp);
    wl_waves_solitary_velocity(&sw, X, z - dz, NULL, &wm);
    double ux = (up - um) / (2 * dX), wz = (wp - wm) / (2 * dz);
    dcont[n] = ux + wz;
    ref_cont = fmax(ref_cont, fabs(wz));
    /* kinematic condition at the surface */
    double eta_X =
        (wl_waves_solitary_eta(&sw, X + dX) - wl_waves_solitary_eta(&sw, X - dX)) / (2 * dX);
    double us, ws;
    wl_waves_solitary_velocity(&sw, X, d, &us, &ws);
    dkin[n] = ws - (us - sw.c) * eta_X;
    ref_kin = fmax(ref_kin, fabs(ws));
    n++;
  }
  for (int i = 0; i < n; i++) {
    *cont = fmax(*cont, fabs(dcont[i]) / ref_cont);
    *kin = fmax(*kin, fabs(dkin[i]) / ref_kin);
  }
}

static void test_grimshaw_identities(void) {
  /* Third-order field: identities hold to O(eps^3) relative. Had z been taken
   * from the still-water level, the flux would be off at O(eps) already. */
  const double epss[] = {0.01, 0.05, 0.1};
  double f[3], c[3], k[3];
  for (int i = 0; i < 3; i++) {
    identity_errors(epss[i], &f[i], &c[i], &k[i]);
    double e3 = pow(epss[i], 3);
    printf("  eps %.2f: flux %.3g, continuity %.3g, kinematic %.3g (relative; eps^3 = %.3g)\n",
           epss[i], f[i], c[i], k[i], e3);
    CHECK_ABS(f[i], 0.0, IDENTITY_EPS3_COEF * e3,
              "steady-wave mass flux int_0^{h+eta} u dz = C eta (z from bed), O(eps^3)");
    CHECK_ABS(c[i], 0.0, IDENTITY_EPS3_COEF * e3, "continuity du/dx + dw/dz = 0, O(eps^3)");
    CHECK_ABS(k[i], 0.0, KINEMATIC_EPS3_COEF * e3,
              "kinematic surface condition w = (u - C) eta_x, O(eps^3)");
  }
  /* observed order between eps = 0.05 and 0.1: 3 expected (> 2.5); 2 would
   * mean a wrong eps^3 coefficient */
  CHECK_TRUE(log(f[2] / f[1]) / log(2.0) > 2.5, "mass-flux error converges at order >= 2.5");
  CHECK_TRUE(log(c[2] / c[1]) / log(2.0) > 2.5, "continuity error converges at order >= 2.5");
  CHECK_TRUE(log(k[2] / k[1]) / log(2.0) > 2.5, "kinematic error converges at order >= 2.5");
}

/* ---- integrals ------------------------------------------------------------ */
static void test_boussinesq_closed_forms(void) {
  struct wl_error err;
  wl_error_clear(&err);
  const double epss[] = {1e-3, 0.1, 0.3};
  for (int i = 0; i < 3; i++) {
    double h = 0.36, eps = epss[i];
    struct wl_solitary sw;
    struct wl_wave_integrals num, cf;
    wl_waves_solitary_init(&sw, WL_SOLITARY_BOUSSINESQ, h, eps * h, G, &err);
    enum wl_status st = wl_waves_solitary_integrals(&sw, RHO, &num, &err);
    CHECK_TRUE(st == WL_OK, "Boussinesq integrals: status ok");
    wl_waves_solitary_closed_form(&sw, RHO, &cf);
    /* references written out here, independent of the module's closed form */
    double V_ref = 4.0 / (3.0 * sqrt(3.0)) * RHO * G * pow(h, 3) * pow(eps, 1.5);
    double M_ref = RHO * 4.0 * h * h * sqrt(eps / 3.0);
    CHECK_REL(num.mass, M_ref, QUAD_REL, "M = rho 4 h^2 sqrt(eps/3) (int sech^2 = 2/K)");
    CHECK_REL(num.potential, V_ref, QUAD_REL,
              "V = 4/(3 sqrt3) rho g h^3 eps^1.5 (int sech^4 = 4/(3K))");
    CHECK_REL(num.momentum, sqrt(G * (h + eps * h)) * M_ref, QUAD_REL,
              "I = c M (int_0^{h+eta} u dz = c eta exactly)");
    CHECK_REL(cf.mass, M_ref, 1e-14, "closed form mass");
    CHECK_REL(cf.potential, V_ref, 1e-14, "closed form potential");
    CHECK_REL(cf.energy, 8.0 / (3.0 * sqrt(3.0)) * RHO * G * pow(h, 3) * pow(eps, 1.5), 1e-14,
              "closed form E = 8/(3 sqrt3) rho g h^3 eps^1.5");
    /* T = V (1 + 2 eps/5 + O(eps^2)): horizontal part int eta^2 g(h+H)/(h+eta)
     * gives 1 + eps - (16/15)/(4/3) eps = 1 + eps/5 (int sech^6 = 16/(15K));
     * vertical part c^2 h/3 int eta_x^2 = V (4/15) K^2 h^2 = V eps/5. */
    CHECK_ABS(num.kinetic / num.potential - 1.0, 0.4 * eps, eps * eps,
              "T/V = 1 + 2eps/5 + O(eps^2), derived (equipartition at leading order)");
    CHECK_REL(num.energy, cf.energy, 0.2 * eps + eps * eps,
              "E vs leading-order closed form: E/E0 = 1 + eps/5 + O(eps^2)");
  }
}

static void test_grimshaw_integrals_vs_exact(void) {
  struct wl_error err;
  wl_error_clear(&err);
  for (int i = 0; i < N_TABLE; i++) {
    const struct table_row *r = &TABLE[i];
    double h = 2.0, eps = r->eps; /* any depth: check the scaling too */
    struct wl_solitary sw;
    struct wl_wave_integrals wi;
    wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, h, eps * h, G, &err);
    enum wl_status st = wl_waves_solitary_integrals(&sw, RHO, &wi, &err);
    CHECK_TRUE(st == WL_OK, "Grimshaw integrals: status ok");
    /* eps^3 truncation plus the table's rounding to 6 decimals */
    double tol = GRIMSHAW_EPS3_COEF * pow(eps, 3);
    printf("  eps %.2f: tolerance %.3g relative (eps^3, plus 5e-7 absolute rounding)\n", eps,
           tol);
    CHECK_REL(wi.mass / (RHO * h * h), r->M, tol + TABLE_HALF_ULP6 / r->M,
              "REFERENCES 3.4 M/h^2 (exact wave)");
    CHECK_REL(wi.momentum / (RHO * h * h * sqrt(G * h)), r->I, tol + TABLE_HALF_ULP6 / r->I,
              "REFERENCES 3.4 I/(rho h^2 sqrt(gh)) (exact wave)");
    CHECK_REL(wi.energy / (RHO * G * pow(h, 3)), r->E, tol + TABLE_HALF_ULP6 / r->E,
              "REFERENCES 3.4 E/(rho g h^3) (exact wave)");
    CHECK_REL(wi.potential / (RHO * G * pow(h, 3)), r->PE, tol + TABLE_HALF_ULP8 / r->PE,
              "REFERENCES 3.4 PE/(rho g h^3) (exact wave)");
  }
}

static void test_exact_solver(void) {
  struct wl_error err;
  wl_error_clear(&err);
  for (int i = 0; i < N_TABLE; i++) {
    const struct table_row *r = &TABLE[i];
    struct wl_solitary_exact ex;
    enum wl_status st = wl_waves_exact_solitary(r->eps, 8192, &ex, &err);
    CHECK_TRUE(st == WL_OK, "exact solver: status ok");
    printf("  eps %.2f: %d iterations, residual %.2g, spectral tail %.2g\n", r->eps, ex.n_iter,
           ex.residual, ex.tail);
    CHECK_TRUE(ex.tail < 1e-12, "exact solver: 8192 modes resolve the wave (spectral tail)");
    CHECK_ABS(ex.F, r->F_exact, TABLE_HALF_ULP8 + 1e-10, "REFERENCES 3.4 F exact (8 decimals)");
    CHECK_ABS(ex.mass, r->M, TABLE_HALF_ULP6 + 1e-10, "REFERENCES 3.4 M/h^2");
    CHECK_ABS(ex.impulse, r->I, TABLE_HALF_ULP6 + 1e-10, "REFERENCES 3.4 I/(rho h^2 sqrt(gh))");
    CHECK_ABS(ex.kinetic, r->KE, TABLE_HALF_ULP8 + 1e-10, "REFERENCES 3.4 KE/(rho g h^3)");
    CHECK_ABS(ex.potential, r->PE, TABLE_HALF_ULP8 + 1e-10, "REFERENCES 3.4 PE/(rho g h^3)");
    /* decay rate vs Grimshaw 2 alpha (seed 003: 2 alpha = beta h), O(eps^3.5) */
    struct wl_solitary sw;
    wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, 1.0, r->eps, 1.0, &err);
    CHECK_REL(ex.beta, 2.0 * sw.K, pow(r->eps, 3), "seed 003 eq 25: beta h = 2 alpha, O(eps^3)");
  }
  struct wl_solitary_exact ex;
  struct wl_wave_integrals wi;
  wl_waves_exact_solitary(0.1, 8192, &ex, &err);
  wl_waves_exact_integrals(&ex, RHO, G, 0.5, &wi);
  CHECK_REL(wi.energy, TABLE[1].E * RHO * G * 0.125, 1e-5,
            "REFERENCES 3.4 E at eps 0.1, dimensional on h = 0.5 m");
}

/* ---- the exact wave's tabulated field ---------------------------------------- */

/* Integrals of the tabulated field by composite Simpson quadrature written
 * here: X over [-40 h, 40 h] in steps of h/200, z over the local depth with
 * 40 intervals. Returns M, I, KE, PE dimensionless (rho = g = h = 1). */
static void field_integrals(const struct wl_solitary *sw, double *M, double *I, double *KE,
                            double *PE) {
  const double h = sw->h, g = sw->g, dX = h / 200;
  const int NX = 16000, NZ = 40;
  double m = 0, im = 0, ke = 0, pe = 0;
  for (int i = 0; i <= NX; i++) {
    const double X = -40 * h + i * dX, wx = (i == 0 || i == NX) ? 1 : (i % 2 ? 4 : 2);
    const double eta = wl_waves_solitary_eta(sw, X), d = h + eta;
    double su = 0, sk = 0;
    for (int j = 0; j <= NZ; j++) {
      double u, w;
      wl_waves_solitary_velocity(sw, X, d * j / NZ, &u, &w);
      const double wz = (j == 0 || j == NZ) ? 1 : (j % 2 ? 4 : 2);
      su += wz * u;
      sk += wz * (u * u + w * w);
    }
    m += wx * eta;
    pe += wx * 0.5 * g * eta * eta;
    im += wx * su * d / (3 * NZ);
    ke += wx * 0.5 * sk * d / (3 * NZ);
  }
  const double f = dX / 3, sgh = sqrt(g * h);
  *M = m * f / (h * h);
  *I = im * f / (h * h * sgh);
  *KE = ke * f / (g * h * h * h);
  *PE = pe * f / (g * h * h * h);
}

static void test_exact_field(void) {
  struct wl_error err;
  wl_error_clear(&err);
  const double h = 0.4;
  const double epss[] = {0.1, 0.3, 0.6};
  for (int e = 0; e < 3; e++) {
    const double eps = epss[e];
    struct wl_solitary sw;
    enum wl_status st = wl_waves_solitary_init(&sw, WL_SOLITARY_EXACT, h, eps * h, G, &err);
    CHECK_TRUE(st == WL_OK, "exact field: the wave tabulates");
    if (st) {
      printf("  %s\n", err.msg);
      continue;
    }
    const double c = wl_waves_solitary_celerity(&sw), H = sw.H;
    CHECK_REL(wl_waves_solitary_eta(&sw, 0.0), H, 1e-10, "exact field: crest height H (Newton to 1e-13 h)");
    /* the integrals: REFERENCES 3.4's table at 0.1 and 0.3 (6 decimals),
     * the conformal solution's own (exact.c) at 0.6 */
    double M, I, KE, PE;
    field_integrals(&sw, &M, &I, &KE, &PE);
    printf("  exact field eps %.1f: M %.7f I %.7f KE %.8f PE %.8f\n", eps, M, I, KE, PE);
    const struct table_row *r = e == 0 ? &TABLE[1] : e == 1 ? &TABLE[3] : NULL;
    if (r) {
      CHECK_ABS(c / sqrt(G * h), r->F_exact, TABLE_HALF_ULP8 + 1e-10, "exact field: celerity F");
      CHECK_ABS(M, r->M, TABLE_HALF_ULP6 + 2e-7, "exact field: quadrature of eta, REFERENCES 3.4 M");
      CHECK_ABS(I, r->I, TABLE_HALF_ULP6 + 2e-7, "exact field: quadrature of u, REFERENCES 3.4 I");
      CHECK_ABS(KE, r->KE, TABLE_HALF_ULP8 + 2e-7, "exact field: quadrature of u^2 + w^2, KE");
      CHECK_ABS(PE, r->PE, TABLE_HALF_ULP8 + 2e-7, "exact field: quadrature of eta^2, PE");
    } else {
      CHECK_REL(M, sw.exact.mass, 1e-6, "exact field H/h 0.6: M against the conformal solution");
      CHECK_REL(I, sw.exact.impulse, 1e-5, "exact field H/h 0.6: I against the conformal solution");
      CHECK_REL(KE, sw.exact.kinetic, 1e-5, "exact field H/h 0.6: KE against the conformal solution");
    }
    /* a steady irrotational wave, pointwise over the wave: mass flux c eta
     * through every section, Bernoulli (p = 0) and the kinematic condition
     * at the surface, w = 0 at the bed, no curl inside */
    double flux = 0, bern = 0, kin = 0, bed = 0, curl = 0, slope_max = 0;
    for (int i = -200; i <= 200; i++) {
      const double X = i * 0.015 * h, eta = wl_waves_solitary_eta(&sw, X), d = h + eta;
      double s = 0, u, w;
      for (int j = 0; j <= 200; j++) {
        wl_waves_solitary_velocity(&sw, X, d * j / 200, &u, &w);
        s += (j == 0 || j == 200 ? 1 : (j % 2 ? 4 : 2)) * u;
      }
      flux = fmax(flux, fabs(s * d / 600 - c * eta) / (c * H));
      wl_waves_solitary_velocity(&sw, X, d, &u, &w);
      bern = fmax(bern, fabs(0.5 * ((u - c) * (u - c) + w * w) + G * eta - 0.5 * c * c) / (c * c));
      const double dx = 1e-4 * h;
      const double eta_x = (wl_waves_solitary_eta(&sw, X + dx) - wl_waves_solitary_eta(&sw, X - dx)) / (2 * dx);
      slope_max = fmax(slope_max, fabs(eta_x));
      kin = fmax(kin, fabs(w - (u - c) * eta_x) / c);
      wl_waves_solitary_velocity(&sw, X, 0.0, &u, &w);
      bed = fmax(bed, fabs(w) / c);
      double u1, u2, w1, w2, t;
      wl_waves_solitary_velocity(&sw, X, 0.5 * d + dx, &u1, &t);
      wl_waves_solitary_velocity(&sw, X, 0.5 * d - dx, &u2, &t);
      wl_waves_solitary_velocity(&sw, X + dx, 0.5 * d, &t, &w1);
      wl_waves_solitary_velocity(&sw, X - dx, 0.5 * d, &t, &w2);
      curl = fmax(curl, fabs((u1 - u2) - (w1 - w2)) / (2 * dx) / (c / h));
    }
    printf("  exact field eps %.1f: flux %.1e, Bernoulli %.1e, kinematic %.1e of c max|eta_x| "
           "%.1e, bed %.1e, curl %.1e\n", eps, flux, bern, kin / slope_max, slope_max, bed, curl);
    /* bounds: the table's interpolation error, measured 2e-6 (flux), 2e-7
     * (Bernoulli), 1.5e-5 (curl) at H/h 0.6 and less below; allowed 10x */
    CHECK_TRUE(flux < 2e-5, "exact field: mass flux int u dz = c eta");
    CHECK_TRUE(bern < 2e-6, "exact field: Bernoulli at the surface (p = 0)");
    CHECK_TRUE(kin < 1e-3 * slope_max, "exact field: kinematic surface condition");
    CHECK_TRUE(bed < 1e-12, "exact field: w = 0 at the bed");
    CHECK_TRUE(curl < 2e-4, "exact field: irrotational");
    /* Grimshaw's third order within O(eps^4) h of the exact profile
     * (REFERENCES 3.2: ~0.18 eps^4 h) */
    struct wl_solitary gr;
    wl_waves_solitary_init(&gr, WL_SOLITARY_GRIMSHAW, h, eps * h, G, &err);
    double dev = 0;
    for (int i = 0; i <= 100; i++) {
      const double X = i * 0.05 * h;
      dev = fmax(dev, fabs(wl_waves_solitary_eta(&sw, X) - wl_waves_solitary_eta(&gr, X)));
    }
    printf("  exact vs Grimshaw eps %.1f: max |eta difference| = %.3f eps^4 h\n", eps,
           dev / (h * pow(eps, 4)));
    CHECK_TRUE(dev < 0.5 * pow(eps, 4) * h, "exact field: Grimshaw's profile within O(eps^4) h");
  }
}

/* ---- Longuet-Higgins (1974), seed 001 -------------------------------------- */
static void test_lh74_and_seawall(void) {
  struct wl_error err;
  wl_error_clear(&err);
  double A = 1.5389, B = -0.7093, mu = 1.0495, nu = 1.4630; /* seed 001 eq 17 */
  double h = 0.36, V = 0;
  enum wl_status st = wl_waves_lh74_potential(RHO, G, h, &V, &err);
  CHECK_TRUE(st == WL_OK, "LH74 potential: status ok");
  double rgh3 = RHO * G * h * h * h;
  CHECK_REL(V / rgh3, 0.431, 1.5e-3, "seed 001 eq 21: V = 0.431 rho g h^3 (3 digits)");
  CHECK_REL(V / rgh3, A * A / (2 * mu) + 2 * A * B / (mu + nu) + B * B / (2 * nu), 1e-10,
            "closed form of int (A e^-mu x + B e^-nu x)^2");
  CHECK_REL(wl_waves_lh74_eta(h, 0.0) / h, 0.8296, 1e-12,
            "eq 17 crest A + B = 0.8296: the highest wave (H/h ~ 0.83)");
  double dx = 1e-7 * h;
  double slope = (wl_waves_lh74_eta(h, dx) - wl_waves_lh74_eta(h, 0.0)) / dx;
  CHECK_ABS(slope, -1.0 / sqrt(3.0), 2e-4,
            "eq 17 crest slope = -tan 30 deg: Stokes 120 deg corner of the highest wave");
  CHECK_REL(wl_waves_lh74_energy(RHO, G, h), 0.958 * rgh3, 1e-15, "seed 001 eq 22");

  /* seed 001's seawall: h = 0.36 m, H = 0.05 m. */
  struct wl_solitary sw;
  struct wl_wave_integrals wi;
  wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, h, 0.05, G, &err);
  wl_waves_solitary_integrals(&sw, RHO, &wi, &err);
  struct wl_solitary_exact ex;
  st = wl_waves_exact_solitary(0.05 / h, 8192, &ex, &err);
  CHECK_TRUE(st == WL_OK, "exact solver at eps = 0.139: status ok");
  double E_exact = (ex.kinetic + ex.potential) * rgh3;
  CHECK_REL(wi.energy, E_exact, GRIMSHAW_EPS3_COEF * pow(sw.eps, 3),
            "seawall Grimshaw E vs exact solver (third order)");
  double ratio = wl_waves_lh74_energy(RHO, G, h) / wi.energy;
  printf("  seawall h = 0.36 m, H = 0.05 m: E = %.6f rho g h^3 = %.3f J/m (Grimshaw), "
         "%.6f rho g h^3 (exact); seed 001 eq 22 gives %.3f J/m, %.2f times more\n",
         wi.energy / rgh3, wi.energy, E_exact / rgh3, wl_waves_lh74_energy(RHO, G, h), ratio);
  CHECK_TRUE(ratio > 10.0 && ratio < 12.0,
             "seed 001 eq 22 (0.958 rho g h^3) overestimates the seawall wave ~11x");
}

/* ---- inversion -------------------------------------------------------------- */
static void test_energy_inversion(void) {
  struct wl_error err;
  /* uniqueness of the root: Grimshaw E(eps) increasing on a grid to 0.78 */
  double E_prev = 0;
  int increasing = 1;
  wl_error_clear(&err);
  for (int i = 1; i <= 39; i++) {
    struct wl_solitary sw;
    struct wl_wave_integrals wi;
    wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, 1.0, 0.02 * i, G, &err);
    wl_waves_solitary_integrals(&sw, RHO, &wi, &err);
    if (!(wi.energy > E_prev)) increasing = 0;
    E_prev = wi.energy;
  }
  CHECK_TRUE(increasing && err.status == WL_OK,
             "Grimshaw E(eps) increasing for eps = 0.02..0.78 (unique inversion)");
  printf("  Grimshaw E(0.78) = %.6f rho g h^3 (REFERENCES 3.4 exact E(0.75) = 0.995633)\n",
         E_prev / (RHO * G));

  const double h = 0.36, epss[] = {0.01, 0.05, 0.05 / 0.36, 0.3, 0.7};
  for (int i = 0; i < 5; i++) {
    wl_error_clear(&err);
    struct wl_solitary sw;
    struct wl_wave_integrals wi, wi2;
    wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, h, epss[i] * h, G, &err);
    wl_waves_solitary_integrals(&sw, RHO, &wi, &err);
    double H = 0;
    enum wl_status st = wl_waves_solitary_height_from_energy(wi.energy, h, G, RHO, &H, &err);
    CHECK_TRUE(st == WL_OK, "height from energy: status ok");
    if (st != WL_OK) printf("  %s\n", err.msg);
    CHECK_REL(H, epss[i] * h, 1e-9, "round trip height -> energy -> height");
    struct wl_solitary sw2;
    wl_waves_solitary_init(&sw2, WL_SOLITARY_GRIMSHAW, h, H, G, &err);
    wl_waves_solitary_integrals(&sw2, RHO, &wi2, &err);
    CHECK_REL(wi2.energy, wi.energy, 1e-9, "round trip energy -> height -> energy");
  }
}

/* ---- Goring paddle ------------------------------------------------------------ */
struct paddle_ode {
  double h, H, K, c, lambda;
};
/* dX/dt = c eta/(h + eta), eta = H sech^2(K(c t - X - lambda)): REFERENCES 3.5 */
static double paddle_rhs(const struct paddle_ode *p, double t, double X) {
  double ch = cosh(p->K * (p->c * t - X - p->lambda));
  double eta = p->H / (ch * ch);
  return p->c * eta / (p->h + eta);
}

static void test_goring(void) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_goring gp;
  const double h = 0.5, H = 0.15, eps0 = WL_WAVES_GORING_EPS0_DEFAULT; /* REFERENCES 3.5 example */
  enum wl_status st = wl_waves_goring_init(&gp, h, H, G, eps0, &err);
  CHECK_TRUE(st == WL_OK, "Goring init: status ok");
  CHECK_REL(gp.stroke, sqrt(16.0 * H * h / 3.0), 1e-14, "REFERENCES 3.5: S = sqrt(16 H h/3)");
  CHECK_ABS(gp.stroke, 0.632456, 5e-7, "REFERENCES 3.5 example: stroke 0.632456 m");
  /* duration = (2 lambda + x_end)/c: the stroke adds x_end/(2 lambda) =
   * eps/arccosh(1/sqrt(eps0)) sqrt(1-eps0) <= 0.21 to REFERENCES' 2 lambda/c */
  CHECK_REL(gp.duration, 2 * gp.lambda / gp.c, 0.25,
            "REFERENCES 3.5: duration ~ 2 lambda/c (plus the stroke's own travel)");
  CHECK_ABS(wl_waves_goring_position(&gp, 0.0), 0.0, 1e-15, "X_p(0) = 0");
  CHECK_ABS(wl_waves_goring_position(&gp, gp.duration), gp.stroke, eps0 * gp.stroke,
            "X_p(duration) ~ stroke, within eps0 S");
  CHECK_REL(wl_waves_goring_position(&gp, gp.duration), gp.stroke * sqrt(1 - eps0), 1e-12,
            "X_p(duration) = S sqrt(1 - eps0) (eta at paddle back to eps0 H)");
  CHECK_ABS(wl_waves_goring_position(&gp, 3 * gp.duration), gp.x_end, 0.0,
            "clamped after the motion");
  CHECK_ABS(wl_waves_goring_position(&gp, -1.0), 0.0, 0.0, "clamped before the motion");
  CHECK_ABS(wl_waves_goring_velocity(&gp, 2 * gp.duration), 0.0, 0.0, "U_p = 0 after");

  /* implicit equation, monotonicity, velocity vs finite difference */
  double a = gp.stroke / 2, max_res = 0, max_dv = 0, prev = -1, vmax = 0;
  int monotone = 1;
  const int n = 2000;
  for (int i = 0; i <= n; i++) {
    double t = gp.duration * i / n;
    double X = wl_waves_goring_position(&gp, t);
    if (i < n) {
      double res = X - a * (tanh(gp.K * (gp.c * t - X - gp.lambda)) + tanh(gp.K * gp.lambda));
      max_res = fmax(max_res, fabs(res));
    }
    if (X < prev) monotone = 0;
    prev = X;
    if (i > 0 && i < n) {
      double dt = 1e-5 * gp.duration;
      double fd = (wl_waves_goring_position(&gp, t + dt) - wl_waves_goring_position(&gp, t - dt)) /
                  (2 * dt);
      double v = wl_waves_goring_velocity(&gp, t);
      max_dv = fmax(max_dv, fabs(fd - v));
      vmax = fmax(vmax, v);
    }
  }
  CHECK_ABS(max_res, 0.0, 1e-14 * gp.stroke, "X_p satisfies Goring's implicit equation");
  CHECK_TRUE(monotone, "X_p nondecreasing on [0, duration]");
  CHECK_ABS(max_dv / vmax, 0.0, 1e-6, "U_p = central finite difference of X_p");
  /* peak velocity c H/(h + H) at the crest passage */
  CHECK_REL(vmax, gp.c * H / (h + H), 1e-4, "max U_p = c H/(h + H)");

  /* independent RK4 of the ODE */
  struct paddle_ode p = {h, H, sqrt(3 * H / (4 * h * h * h)), sqrt(G * (h + H)), 0};
  p.lambda = acosh(1.0 / sqrt(eps0)) / p.K;
  const int steps = 20000;
  double dt = gp.duration / steps, X = 0, max_d = 0;
  for (int i = 0; i < steps; i++) {
    double t = i * dt;
    double k1 = paddle_rhs(&p, t, X);
    double k2 = paddle_rhs(&p, t + dt / 2, X + dt / 2 * k1);
    double k3 = paddle_rhs(&p, t + dt / 2, X + dt / 2 * k2);
    double k4 = paddle_rhs(&p, t + dt, X + dt * k3);
    X += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    max_d = fmax(max_d, fabs(X - wl_waves_goring_position(&gp, t + dt)));
  }
  CHECK_ABS(max_d, 0.0, 1e-9, "X_p vs RK4 of dX/dt = c eta/(h+eta) (20000 steps) [m]");

  /* robustness: a steep wave and a tiny one */
  const double Hs[] = {0.78 * h, 1e-4 * h};
  for (int k = 0; k < 2; k++) {
    struct wl_goring g2;
    wl_waves_goring_init(&g2, h, Hs[k], G, eps0, &err);
    double worst = 0;
    for (int i = 0; i <= 1000; i++) {
      double t = g2.duration * i / 1000.0, Xp = wl_waves_goring_position(&g2, t);
      if (i < 1000)
        worst = fmax(worst, fabs(Xp - g2.stroke / 2 *
                                         (tanh(g2.K * (g2.c * t - Xp - g2.lambda)) +
                                          tanh(g2.K * g2.lambda))));
    }
    CHECK_ABS(worst, 0.0, 1e-14 * g2.stroke, "implicit equation at H/h = 0.78 and 1e-4");
  }
}

int main(void) {
  gsl_set_error_handler_off();
  test_bad_inputs();
  test_grimshaw_point_values();
  test_grimshaw_identities();
  test_boussinesq_closed_forms();
  test_grimshaw_integrals_vs_exact();
  test_exact_solver();
  test_exact_field();
  test_lh74_and_seawall();
  test_energy_inversion();
  test_goring();
  return TEST_RESULT();
}
