/* test_sph_kernel.c: the shared physics functions of include/wallload/sph/
 * against independent computations: Wendland C2 normalisation by
 * quadrature (2D and 3D) and by a lattice sum, the kernel gradient against
 * a finite difference, the branch-free square root against sqrt, the Tait
 * EOS and hydrostatic densities against pow, and the parameter checks. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "testutil.h"
#include "wallload/scene.h"
#include "wallload/sph.h"
#include "wallload/sph/interact.h"

static const double PI = 3.14159265358979323846;

/* Composite Simpson of W(r) * shell(r) over [0, 2h] (n even). */
static double radial_integral(const struct wl_sph_const *k, int dim, int n) {
  const double R = 2 * k->h_d, dr = R / n;
  double sum = 0;
  for (int i = 0; i <= n; i++) {
    const double r = i * dr;
    const double w = wl_sph_kernel_w(k, (wl_real)(r * r));
    const double shell = dim == 2 ? 2 * PI * r : 4 * PI * r * r;
    const double c = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    sum += c * w * shell;
  }
  return sum * dr / 3;
}

static struct wl_sph_const make(int dim, double dp) {
  struct wl_sph_params prm;
  wl_sph_params_default(&prm, dim, dp, 1.0);
  struct wl_sph_const k;
  struct wl_error err;
  wl_error_clear(&err);
  if (wl_sph_const_make(&prm, &k, &err) != WL_OK) printf("const_make: %s\n", err.msg);
  return k;
}

int main(void) {
  const double dp = 0.01;
  for (int dim = 2; dim <= 3; dim++) {
    const struct wl_sph_const k = make(dim, dp);
    CHECK_REL(k.h_d, sqrt((double)dim) * dp, 1e-12, "h = coefh sqrt(dim) dp (DualSPHysics), coefh 1");
    CHECK_REL(radial_integral(&k, dim, 20000), 1.0, 1e-5,
              dim == 2 ? "int W dA = 1, Simpson quadrature (2D, aD = 7/(4 pi h^2))"
                       : "int W dV = 1, Simpson quadrature (3D, aD = 21/(16 pi h^3))");
    /* lattice sum with a spacing much finer than h: sum W dx^dim -> 1 */
    const double dx = k.h_d / 20;
    const int m = (int)ceil(2 * k.h_d / dx) + 1;
    double sum = 0;
    for (int i = -m; i <= m; i++)
      for (int j = -m; j <= m; j++)
        for (int l = (dim == 3 ? -m : 0); l <= (dim == 3 ? m : 0); l++) {
          const double r2 = dx * dx * ((double)i * i + (double)j * j + (double)l * l);
          sum += wl_sph_kernel_w(&k, (wl_real)r2);
        }
    sum *= pow(dx, dim);
    CHECK_REL(sum, 1.0, 2e-4, "lattice sum of W dx^dim = 1 (midpoint rule, dx = h/20)");
    /* gradient: F r = dW/dr, central difference */
    double worst = 0;
    for (int i = 1; i < 40; i++) {
      const double r = i * 2 * k.h_d / 40, e = 1e-3 * k.h_d;
      const double fd = (wl_sph_kernel_w(&k, (wl_real)((r + e) * (r + e))) -
                         wl_sph_kernel_w(&k, (wl_real)((r - e) * (r - e)))) / (2 * e);
      const double an = wl_sph_kernel_f(&k, (wl_real)(r * r)) * r;
      const double rel = fabs(an - fd) / (fabs(k.kf) * k.h_d); /* scale: max |dW/dr| ~ kf h */
      if (rel > worst) worst = rel;
    }
    CHECK_ABS(worst, 0, 1e-3, "grad W = F r_ij vs central finite difference of W, 0 < r < 2h");
    CHECK_TRUE(wl_sph_kernel_w(&k, (wl_real)(4.0001 * k.h_d * k.h_d)) == 0 &&
                   wl_sph_kernel_f(&k, (wl_real)(4.0001 * k.h_d * k.h_d)) == 0,
               "W and grad W exactly 0 beyond the support 2h");
    CHECK_TRUE(wl_sph_kernel_f(&k, 0) * 0 == 0, "gradient factor finite at r = 0");
  }

  /* branch-free square root: within 4 ulp of sqrt over [1e-12, 1e4] */
  double worst_ulp = 0;
  for (int i = 0; i <= 100000; i++) {
    const float x = (float)pow(10.0, -12.0 + 16.0 * i / 100000.0);
    const double exact = sqrt((double)x);
    const double ulp = nextafterf((float)exact, INFINITY) - (float)exact;
    const double e = fabs((double)wl_sph_sqrt(x) - exact) / ulp;
    if (e > worst_ulp) worst_ulp = e;
  }
  CHECK_ABS(worst_ulp, 0, 4, "wl_sph_sqrt vs double sqrt, in float ulp");
  CHECK_TRUE(wl_sph_sqrt(0) == 0, "wl_sph_sqrt(0) = 0");
  CHECK_TRUE(wl_sph_pos(-3.5f) == 0 && wl_sph_pos(2.25f) == 2.25f && wl_sph_neg(-3.5f) == -3.5f &&
                 wl_sph_neg(2.25f) == 0,
             "max(x,0), min(x,0) exact");
  CHECK_TRUE(wl_sph_max_nonneg(1.5f, 2.5f) == 2.5f && wl_sph_max_nonneg(3.0f, 0.0f) == 3.0f &&
                 wl_sph_nonzero(0.0f) == 0 && wl_sph_nonzero(1e-38f) == 1,
             "integer max of non-negative floats, nonzero indicator");

  /* EOS and hydrostatics */
  const struct wl_sph_const k = make(2, dp);
  double worst_p = 0;
  for (int i = 1; i <= 100; i++) {
    const double depth = i * 0.01; /* h_max = 1 m */
    const double rho = wl_scene_rho_hydro(&k, depth);
    const double p = wl_sph_eos_p(&k, (wl_real)rho);
    const double want = k.rho0 * 9.81 * depth;
    const double e = fabs(p - want) / (k.rho0 * 9.81 * 1.0);
    if (e > worst_p) worst_p = e;
  }
  /* float density: 6e-8 relative of rho times 7 B / rho0 ~ a few Pa */
  CHECK_ABS(worst_p, 0, 2e-4, "Tait p(rho_hydro(d)) = rho0 g d (REFERENCES 1.1), relative to rho0 g h_max");
  CHECK_REL(wl_sph_eos_rho_of_p(1000, k.B, 5000.0), 1000 * pow(1 + 5000.0 / k.B, 1 / 7.0), 1e-12,
            "inverse Tait by Newton vs pow");
  double worst_h = 0;
  for (int i = -100; i <= 100; i++) {
    const double x = 0.02 * i / 100.0; /* rho0 g dz / B */
    const double dz = x / (k.rho0 * 9.81 / k.B); /* x = rho0 g dz / B, make()'s g */
    const double want = k.rho0 * (pow(1 + x, 1 / 7.0) - 1);
    const double got = wl_sph_eos_drho_hydro(&k, (wl_real)dz);
    const double e = fabs(got - want) / (k.rho0 * 0.02 / 7);
    if (e > worst_h) worst_h = e;
  }
  CHECK_ABS(worst_h, 0, 1e-5, "hydrostatic density difference series vs pow, |x| <= 0.02 (Fourtakas 2019 eq 22)");

  /* pair: Newton's third law in the pressure term and zero self-interaction */
  {
    const wl_real r2 = (wl_real)(1.3 * dp * 1.3 * dp);
    wl_real ij, vj, ii, vi;
    wl_sph_pair_j(&k, 1003, &ij, &vj);
    wl_sph_pair_j(&k, 998, &ii, &vi);
    const struct wl_sph_pair a =
        wl_sph_pair_eval(0, 1, &k, r2, 0.3f, 0.01f, 998, 1 / 998.f, 200, 1003, ij, vj, 50, k.av_ff, 0);
    const struct wl_sph_pair b =
        wl_sph_pair_eval(0, 1, &k, r2, 0.3f, -0.01f, 1003, 1 / 1003.f, 50, 998, ii, vi, 200, k.av_ff, 0);
    CHECK_REL(a.c_r, b.c_r, 1e-6, "pair force antisymmetric (c_r r_ij = -c_r r_ji)");
    CHECK_REL(a.ddt * vi, -b.ddt * vj, 1e-3,
              "density diffusion conserves sum V_i drho_i/dt (antisymmetric up to the hydrostatic term's curvature)");
    const struct wl_sph_pair s =
        wl_sph_pair_eval(0, 1, &k, 0, 0, 0, 1000, 1e-3f, 100, 1000, ii, vi, 100, k.av_ff, 0);
    CHECK_TRUE(s.c_r * 0 == 0 && s.cont == 0 && s.ddt == 0 && s.visc == 0,
               "a particle meeting itself adds nothing and nothing non-finite");
  }

  /* the speed of sound: coefsound sqrt(g h_max), raised to 10 times a
   * known largest flow speed (Ma <= 0.1): closed forms */
  {
    struct wl_sph_params prm;
    wl_sph_params_default(&prm, 2, 0.01, 0.3);
    struct wl_sph_const kc;
    CHECK_TRUE(wl_sph_const_make(&prm, &kc, NULL) == WL_OK, "default parameters accepted");
    CHECK_REL(kc.c0_d, 10 * sqrt(9.81 * 0.3), 1e-12, "c0 = coefsound sqrt(g h_max)");
    prm.expected_speed = 2 * sqrt(9.81 * 0.3); /* a dam break's front (Ritter) */
    CHECK_TRUE(wl_sph_const_make(&prm, &kc, NULL) == WL_OK, "expected speed accepted");
    CHECK_REL(kc.c0_d, 20 * sqrt(9.81 * 0.3), 1e-12, "c0 = 10 x the front speed 2 sqrt(g H)");
    prm.expected_speed = 0.1; /* slower than coefsound's: no change */
    CHECK_TRUE(wl_sph_const_make(&prm, &kc, NULL) == WL_OK, "slow expected speed accepted");
    CHECK_REL(kc.c0_d, 10 * sqrt(9.81 * 0.3), 1e-12, "a slow flow keeps coefsound's c0");
  }

  /* parameter checks (every error path of wl_sph_const_make) */
  struct {
    const char *what;
    int field;
    double value;
  } bad[] = {{"dim", 0, 4},          {"dp", 1, -1},          {"coefh", 2, 0.1},
             {"coefsound", 3, 0},    {"h_max", 4, 0},        {"rho0", 5, 0},
             {"g", 6, -9.81},        {"visc", 7, 5},         {"alpha", 8, -1},
             {"visc_bound_factor", 9, -1}, {"nu", 10, -1},   {"ddt", 11, 7},
             {"delta", 12, 2},       {"cfl", 13, 0},         {"dt_collapse", 14, 1},
             {"rho_min_factor", 15, 1}, {"rho_max_factor", 16, 1}, {"penetration", 17, 0},
             {"expected_speed", 18, -1}};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    struct wl_sph_params prm;
    wl_sph_params_default(&prm, 2, dp, 1);
    double v = bad[i].value;
    switch (bad[i].field) {
    case 0: prm.dim = (int)v; break;
    case 1: prm.dp = v; break;
    case 2: prm.coefh = v; break;
    case 3: prm.coefsound = v; break;
    case 4: prm.h_max = v; break;
    case 5: prm.rho0 = v; break;
    case 6: prm.g = v; break;
    case 7: prm.visc = (enum wl_sph_visc)(int)v; break;
    case 8: prm.alpha = v; break;
    case 9: prm.visc_bound_factor = v; break;
    case 10: prm.nu = v; break;
    case 11: prm.ddt = (enum wl_sph_ddt)(int)v; break;
    case 12: prm.delta = v; break;
    case 13: prm.cfl = v; break;
    case 14: prm.dt_collapse = v; break;
    case 15: prm.rho_min_factor = v; break;
    case 16: prm.rho_max_factor = v; break;
    case 17: prm.penetration = v; break;
    case 18: prm.expected_speed = v; break;
    }
    struct wl_sph_const kk;
    struct wl_error err;
    wl_error_clear(&err);
    const enum wl_status st = wl_sph_const_make(&prm, &kk, &err);
    char ref[128];
    snprintf(ref, sizeof ref, "bad %s rejected, message names it", bad[i].what);
    CHECK_TRUE(st == WL_EINPUT && strstr(err.msg, bad[i].what), ref);
  }
  return TEST_RESULT();
}
