/* waves.h: solitary-wave theories, their integral properties, the
 * Longuet-Higgins (1974) highest-wave profile and energies, and the Goring
 * (1978) piston-paddle trajectory. Everything is 2D, per unit crest width, SI.
 *
 * What this module owns, and the sources it implements:
 *
 *  - First-order (Boussinesq / KdV) solitary wave [REFERENCES 3.1]:
 *      eta = H sech^2(K X), K = sqrt(3H/(4h^3)), c = sqrt(g(h+H)), X = x - c t.
 *    Velocity: u = c eta/(h+eta), uniform over the depth (the exact mass flux
 *    of a steady wave, int_0^{h+eta} u dz = c eta), and, from continuity
 *    du/dx + dw/dz = 0 with w = 0 at the bed,
 *      w = -z du/dX = -c h z eta_X / (h+eta)^2,
 *    which satisfies the kinematic surface condition w = (u - c) eta_X exactly.
 *
 *  - Third-order solitary wave of Grimshaw (1971), as written in seed 003
 *    (eqs 21-24): surface eta (21), decay alpha (22), celerity C (23),
 *    horizontal u and vertical w velocity (24). REFERENCES 3.2 confirms eq 23
 *    (Clamond & Dutykh) and verified eqs 21-22 against the exact wave
 *    (deviation ~0.18 eps^4 h).
 *    Vertical coordinate: seed 003 defines z only through its Figure 3 (not in
 *    the text). We take z UP FROM THE BED (0 <= z <= h + eta) because the
 *    formulas say so: (a) w in eq 24 carries an overall factor z/h, so w = 0
 *    at z = 0, which is the impermeable bed, not the still-water level;
 *    (b) the eps^2 (z/h)^2 term of u, (z/h)^2 (3/4 s^2 - 9/4 s^2 q^2), is
 *    exactly -z^2/2 d^3phi/dX^3 of the potential expanded about the bed,
 *    phi = f - z^2/2 f'' + ..., with f' = sqrt(gh) eps s^2. This is also
 *    REFERENCES 1.1's convention and the project's (bed at z = 0, gravity
 *    along -z). tests/test_waves.c checks the choice: the Grimshaw field
 *    carries the exact steady-wave mass flux int_0^{h+eta} u dz = C eta to a
 *    relative O(eps^3), which it would not with z from the still-water level.
 *    CORRECTION to seed 003 eq 24: the eps^3 term of w is printed as
 *      eps^3 {-49/640 - 17/20 s^2 - 18/5 s^4 + Z^2(-13/16 - 25/16 s^2 + 15/2 s^4)
 *             + Z^4(-3/40 + 9/8 s^2 - 27/16 s^4)}            (Z = z/h)
 *    but continuity du/dx + dw/dz = 0 applied to eq 24's own u (w = -int_0^z
 *    u_X dz, by hand) gives
 *      eps^3 {-49/640 + 17/20 s^2 + 18/5 s^4 + Z^2(13/16 + 25/16 s^2 - 15/2 s^4)
 *             + Z^4(3/40 - 9/8 s^2 + 27/16 s^4)},
 *    i.e. the print is -eps^3{49/640 - 17/20 s^2 ...} with the minus sign
 *    left on the first term only (the eps and eps^2 terms check out). With
 *    the printed signs, continuity and the kinematic surface condition
 *    w = (u - C) eta_X fail at a relative 2.2-2.5 eps^2; with the corrected
 *    ones both hold to O(eps^3) (tests). We implement the corrected term. The
 *    correction changes Grimshaw's kinetic energy: E(0.3) = 0.2782 rho g h^3
 *    (0.2757 with the printed signs; exact 0.2824).
 *    Accuracy of the integrals against the exact wave (REFERENCES 3.4): M,
 *    I, V, E within 0.2-0.6 eps^3 relative for eps <= 0.3 (E: -0.05 % at
 *    0.1, -1.5 % at 0.3). Above eps ~ 0.5 Grimshaw degrades: E(0.5) = 0.574
 *    vs 0.616 exact, E(0.78) = 0.953 vs 1.007 exact; I(0.78) = 2.20 vs 2.62.
 *
 *  - Longuet-Higgins (1974) as quoted in seed 001 (eqs 17-22): the two-
 *    exponential profile eta/h = A e^{-mu|x/h|} + B e^{-nu|x/h|} with
 *    A = 1.5389, B = -0.7093, mu = 1.0495, nu = 1.4630. Seed 001 writes |x|;
 *    the fit is in units of h (x/h, eta/h). What it represents: the HIGHEST
 *    solitary wave. Its crest height is A + B = 0.8296 h (the limiting wave
 *    has H/h ~ 0.83, Longuet-Higgins & Fenton 1974), and its crest slope
 *    is -(A mu + B nu) = -0.57737 = -tan(30 deg) to 4 digits: the 120 deg
 *    Stokes corner of the limiting wave. Therefore eqs 20-22, T = 0.527,
 *    V = 0.431, E = 0.958 (times rho g h^3, per unit crest width; seed 001
 *    writes them without rho and calls them the energy "of the solitary wave")
 *    are the energies of the highest wave and do NOT depend on H.
 *    Check of eq 21 (wl_waves_lh74_potential, test_waves.c): by quadrature,
 *    V = rho g/2 int eta^2 dx = 0.431312 rho g h^3 (closed form
 *    A^2/(2mu) + 2AB/(mu+nu) + B^2/(2nu), same digits), so eq 21 is reproduced
 *    to its 3 digits. Its mass is 2(A/mu + B/nu) = 1.9630 h^2.
 *    Seed 001 then uses E = 0.958 rho g h^3 as "the energy of the solitary
 *    wave" for equal-energy explosion cases. For its seawall case (h = 0.36 m,
 *    H = 0.05 m, H/h = 0.139) the integrated Grimshaw energy is
 *    E = 0.08474 rho g h^3 = 38.78 J/m (exact Euler wave,
 *    wl_waves_exact_solitary: 0.08485 rho g h^3 = 38.83 J/m), while eq 22
 *    gives 0.958 rho g h^3 = 438.5 J/m: an overestimate by a factor of 11.3
 *    (tests/test_waves.c prints and checks this ratio). Use
 *    wl_waves_solitary_integrals, not eq 22, for a wave of given H.
 *
 *  - Integral properties per unit crest width by GSL quadrature of the
 *    profile and velocity field (double integral over x and z from bed to
 *    surface), and the first-order closed forms (derived here from
 *    int sech^2 = 2/K, int sech^4 = 4/(3K)):
 *      mass       M = rho int eta dx           = rho 4 h^2 sqrt(eps/3)
 *      potential  V = rho g/2 int eta^2 dx     = (4/(3 sqrt 3)) rho g h^3 eps^{3/2}
 *      momentum   I = rho int int u dz dx      = c M (exact for u = c eta/(h+eta))
 *      kinetic    T = rho/2 int int (u^2+w^2)  = V (1 + O(eps))  (equipartition)
 *      energy     E = T + V                    = (8/(3 sqrt 3)) rho g h^3 eps^{3/2} (1 + O(eps))
 *    M and V are exact for the sech^2 profile; T and E are leading order. For
 *    the first-order field T = V (1 + 2 eps/5 + O(eps^2)) (int sech^6 =
 *    16/(15K); eps/5 from u, eps/5 from w), so E = E0 (1 + eps/5 + O(eps^2)).
 *
 *  - Which theory for what: Grimshaw for eps <= 0.5 (within 0.5 % of the exact
 *    energy up to 0.2, 1.5 % at 0.3, 7 % at 0.5); the exact solver
 *    (wl_waves_exact_solitary, ~0.1-1 s) wherever accuracy matters above that.
 *    A Grimshaw wave started in an Euler solver is not steady there: it
 *    sheds a tail and settles to a lower crest (the SPH flume's H/h = 0.6
 *    wave), and its momentum is 1.2 % short of the exact wave's 2I at H/h
 *    0.3; WL_SOLITARY_EXACT gives the flume the exact wave instead.
 *
 *  - The exact wave's field (WL_SOLITARY_EXACT), for initial conditions:
 *    the conformal map of the strip -1 <= sigma <= 0 (zeta = xi + i sigma,
 *    bed sigma = -1) onto the fluid is z(zeta) = zeta + c_0 (zeta + i) +
 *    sum_{k != 0} -i c_k e^{-k} e^{i k zeta} / sinh k, c_k the Fourier
 *    coefficients of the Babenko solution eta(xi) (so Im z = eta on sigma =
 *    0 and -1 on the bed); in the frame of the crest the flow is uniform in
 *    the strip, complex potential -F zeta, so u - c - i w = -F / z'(zeta)
 *    (Dutykh & Clamond 2014, section 2). Each tabulated point is found by
 *    Newton's method on z(zeta) = x + i y.
 *
 *  - Inversion energy -> height on the integrated Grimshaw energy (GSL Brent).
 *    Grimshaw's E(eps) increases monotonically up to eps = 0.78 (0.953 rho g
 *    h^3 there), so the root is unique.
 *
 *  - Goring (1978) piston wavemaker [REFERENCES 3.5]: X_p(t) from
 *      X_p = (H/(K h)) [tanh(K (c t - X_p - lambda)) + tanh(K lambda)],
 *    which is the exact integral of dX_p/dt = c eta/(h + eta) for the
 *    first-order profile, with lambda = arccosh(1/sqrt(eps0))/K.
 *
 *  - Exact (Euler) solitary wave by Petviashvili iteration of the Babenko
 *    equation in conformal variables (Clamond & Dutykh 2013, Dutykh & Clamond
 *    2014; REFERENCES 3.4), with GSL FFTs: the independent reference for F,
 *    M, I, T and V.
 *
 * Units: h, H, x, z [m]; g [m/s^2]; rho [kg/m^3]; t [s]; velocities [m/s];
 * integrals per unit crest width: mass [kg/m], momentum [kg/s] (= kg m/s per
 * m of crest), energies [J/m].
 *
 * Threading: all functions are reentrant; structs are caller-owned and hold
 * no heap memory (no _clear needed). */
#ifndef WALLLOAD_WAVES_H
#define WALLLOAD_WAVES_H

#include "wallload/error.h"

/* Largest H/h accepted by the solitary-wave and Goring constructors. The
 * highest solitary wave has H/h ~ 0.83 (Longuet-Higgins & Fenton 1974);
 * Clamond & Dutykh's exact method works up to 0.79; mass, momentum and
 * energy peak near 0.78 (REFERENCES 3.4), so above it H no longer follows
 * from the energy. */
#define WL_WAVES_EPS_MAX 0.78
/* H/h up to which Grimshaw's third-order theory is accurate (seed 003:
 * "well suited for solitary wave of eps <= 0.5"; REFERENCES 3.4: its F is
 * within 0.2 % of the exact wave there). Accepted above, but less accurate. */
#define WL_WAVES_EPS_GRIMSHAW_ACCURATE 0.5
/* Smallest H/h accepted: a sanity floor (far below any SPH resolution) that
 * also bounds the energy inversion's bracket. */
#define WL_WAVES_EPS_MIN 1e-6

/* Longuet-Higgins (1974) highest-wave profile fit and energies, seed 001
 * eqs 17 and 20-22 (dimensionless: lengths / h, energies / (rho g h^3)). */
#define WL_WAVES_LH74_A 1.5389
#define WL_WAVES_LH74_B (-0.7093)
#define WL_WAVES_LH74_MU 1.0495
#define WL_WAVES_LH74_NU 1.4630
#define WL_WAVES_LH74_T 0.527 /* kinetic energy, eq 20 */
#define WL_WAVES_LH74_V 0.431 /* potential energy, eq 21 */
#define WL_WAVES_LH74_E 0.958 /* total energy, eq 22 */

/* Goring (1978) start/stop threshold: the paddle moves while eta at the
 * paddle exceeds eps0 H (REFERENCES 3.5, "e.g. eps0 = 0.002"). */
#define WL_WAVES_GORING_EPS0_DEFAULT 0.002

enum wl_solitary_theory {
  WL_SOLITARY_BOUSSINESQ, /* first order (KdV): REFERENCES 3.1 */
  WL_SOLITARY_GRIMSHAW,   /* third order: Grimshaw 1971, seed 003 eqs 21-24 */
  WL_SOLITARY_EXACT,      /* the exact (Euler) wave: Clamond & Dutykh 2013, REFERENCES 3.4 */
};

/* Exact (Euler) solitary wave, dimensionless with rho = g = h = 1:
 * lengths / h, speeds / sqrt(gh), mass / h^2, impulse / (rho h^2 sqrt(gh)),
 * energies / (rho g h^3). */
struct wl_solitary_exact {
  double eps;       /* H/h it was computed for [-] */
  double F;         /* Froude number c/sqrt(gh) [-] */
  double mass;      /* M/h^2 [-] */
  double impulse;   /* I/(rho h^2 sqrt(gh)) = F M [-] */
  double kinetic;   /* T/(rho g h^3) [-] */
  double potential; /* V/(rho g h^3) [-] */
  double beta;      /* far-field decay: eta ~ e^{-beta |x|/h}, tan(beta)/beta = F^2 [-] */
  double residual;  /* max |Babenko residual| at the end [-] */
  double tail;      /* max |eta_hat(k)|/eta_hat(0) over the top quarter of |k|: a
                       resolution indicator; ~1e-15 when n_modes resolves the
                       wave, larger means more modes are needed [-] */
  int n_iter;       /* Petviashvili iterations used */
};

/* The exact wave's field is tabulated on WL_WAVES_EXACT_NX abscissae from
 * the crest (X >= 0; the wave is symmetric) out to where eta has fallen
 * below 1e-9 H, and WL_WAVES_EXACT_NZ levels from the bed to the surface;
 * read back by 4-point Lagrange interpolation in both (error ~1e-7 of the
 * crest values, measured in test_waves against the conformal solution). */
enum { WL_WAVES_EXACT_NX = 384, WL_WAVES_EXACT_NZ = 13 };

/* A solitary wave: inputs and derived constants. Filled by
 * wl_waves_solitary_init; read-only afterwards. */
struct wl_solitary {
  enum wl_solitary_theory theory;
  double h;       /* still-water depth [m] */
  double H;       /* wave height above still water [m] */
  double g;       /* gravity [m/s^2] */
  double eps;     /* H/h [-] */
  double K;       /* decay rate [1/m]: argument of sech is K X. Boussinesq
                     sqrt(3H/(4h^3)); Grimshaw alpha/h (eq 22); exact beta/(2h),
                     the far-field decay eta ~ e^{-2 K |X|} */
  double c;       /* celerity [m/s]: Boussinesq sqrt(g(h+H)); Grimshaw eq 23;
                     exact F sqrt(g h) */
  double sqrt_gh; /* sqrt(g h) [m/s] */
  /* WL_SOLITARY_EXACT only (zero otherwise), dimensionless (lengths / h,
   * speeds / sqrt(g h)): the solution's integrals, and its field at X_i =
   * i exact_dX: the surface eta_i, and u (even in X) and w (odd in X) at
   * the heights z = s_j (1 + eta_i) above the bed, s_j = j / (NZ - 1). */
  struct wl_solitary_exact exact;
  double exact_dX;
  double exact_eta[WL_WAVES_EXACT_NX];
  double exact_u[WL_WAVES_EXACT_NX][WL_WAVES_EXACT_NZ];
  double exact_w[WL_WAVES_EXACT_NX][WL_WAVES_EXACT_NZ];
};

/* Integral properties per unit crest width. */
struct wl_wave_integrals {
  double mass;      /* M = rho int eta dx [kg/m] */
  double momentum;  /* I = rho int int u dz dx [kg/s] (kg m/s per m of crest) */
  double kinetic;   /* T = rho/2 int int (u^2 + w^2) dz dx [J/m] */
  double potential; /* V = rho g/2 int eta^2 dx [J/m] */
  double energy;    /* E = T + V [J/m] */
};


/* Goring (1978) piston paddle for a first-order solitary wave. Filled by
 * wl_waves_goring_init; read-only afterwards. */
struct wl_goring {
  double h, H, g;   /* depth [m], wave height [m], gravity [m/s^2] */
  double eps0;      /* start/stop threshold eta/H at the paddle [-] */
  double K;         /* sqrt(3H/(4h^3)) [1/m] */
  double c;         /* sqrt(g(h+H)) [m/s] */
  double lambda;    /* arccosh(1/sqrt(eps0))/K [m]: crest distance at t = 0 */
  double stroke;    /* S = 2H/(K h) = sqrt(16 H h/3) [m]: displacement as t -> inf */
  double x_end;     /* S sqrt(1 - eps0) [m]: displacement when the paddle stops */
  double duration;  /* (2 lambda + x_end)/c [s]: time the paddle moves */
};

/* ---- solitary wave ------------------------------------------------------ */

/* Validate inputs and fill *sw for a solitary wave of height H [m] on depth
 * h [m] under gravity g [m/s^2], in the given theory.
 * Returns WL_OK; WL_EINPUT if h, H or g is not finite and > 0, if theory is
 * unknown, or if eps = H/h is outside [WL_WAVES_EPS_MIN, WL_WAVES_EPS_MAX]
 * (the message gives the value found and the valid range). On failure *sw is
 * zeroed. */
enum wl_status wl_waves_solitary_init(struct wl_solitary *sw, enum wl_solitary_theory theory,
                                      double h, double H, double g, struct wl_error *err);

/* Surface elevation eta above still water [m] at X = x - c t [m]. */
double wl_waves_solitary_eta(const struct wl_solitary *sw, double X);

/* Particle velocity (u horizontal, w vertical) [m/s] at X = x - c t [m] and
 * height z [m] measured up from the bed (0 at the bed, h at still water), in
 * the frame where the water is at rest far from the wave. Defined for
 * 0 <= z <= h + eta(X); outside that range the formulas are extrapolated.
 * u or w may be NULL. */
void wl_waves_solitary_velocity(const struct wl_solitary *sw, double X, double z, double *u,
                                double *w);

/* Celerity c [m/s]. */
double wl_waves_solitary_celerity(const struct wl_solitary *sw);

/* The theory's name ("Grimshaw third order") and, with source = 1, where its
 * profile and celerity come from, for reports; "?" for an unknown value. */
const char *wl_waves_solitary_theory_text(enum wl_solitary_theory theory, int source);

/* Integral properties of *sw per unit crest width for water density rho
 * [kg/m^3], by adaptive GSL quadrature (outer over x on [0, inf) with the
 * symmetry of the wave, inner over z from the bed to the surface), relative
 * accuracy ~1e-11.
 * Returns WL_OK; WL_EINPUT if rho is not finite and > 0; WL_ENOMEM if the
 * quadrature workspace cannot be allocated; WL_ENUMERIC if a quadrature
 * fails. On failure *out is zeroed. */
enum wl_status wl_waves_solitary_integrals(const struct wl_solitary *sw, double rho,
                                           struct wl_wave_integrals *out,
                                           struct wl_error *err);

/* First-order (KdV) closed forms for sw's h, H, g (whatever sw->theory) and
 * density rho [kg/m^3]: mass rho 4 h^2 sqrt(eps/3), momentum c M with
 * c = sqrt(g(h+H)), potential (4/(3 sqrt 3)) rho g h^3 eps^{3/2}, kinetic =
 * potential (leading-order equipartition), energy twice that. mass, momentum
 * and potential are exact for the first-order field; kinetic and energy carry
 * an O(eps) relative error. */
void wl_waves_solitary_closed_form(const struct wl_solitary *sw, double rho,
                                   struct wl_wave_integrals *out);

/* Height H [m] of the Grimshaw solitary wave on depth h [m] (gravity g
 * [m/s^2], density rho [kg/m^3]) whose integrated energy (kinetic +
 * potential, wl_waves_solitary_integrals) per unit crest width is E [J/m];
 * Brent's method on eps in [WL_WAVES_EPS_MIN, WL_WAVES_EPS_MAX], to a relative
 * 1e-12 in eps.
 * Returns WL_OK; WL_EINPUT if an input is not finite and > 0, or if E is
 * above the energy of the eps = WL_WAVES_EPS_MAX wave (the message gives
 * that maximum in J/m) or below that of the WL_WAVES_EPS_MIN wave;
 * WL_ENOMEM; WL_ENUMERIC if quadrature or the root finder fails.
 * On failure *H is 0. */
enum wl_status wl_waves_solitary_height_from_energy(double E, double h, double g, double rho,
                                                    double *H, struct wl_error *err);

/* ---- Longuet-Higgins (1974) highest wave, seed 001 --------------------- */

/* eq 17: surface elevation [m] at distance x [m] from the crest on depth
 * h [m]: h (A e^{-mu|x/h|} + B e^{-nu|x/h|}). */
double wl_waves_lh74_eta(double h, double x);

/* eq 22: total energy 0.958 rho g h^3 [J/m] of the highest solitary wave on
 * depth h [m] (rho [kg/m^3], g [m/s^2]). It does not depend on the wave
 * height: it is NOT the energy of a lower wave (see the file comment). */
double wl_waves_lh74_energy(double rho, double g, double h);

/* Potential energy V = rho g/2 int eta^2 dx [J/m] of the eq-17 profile by
 * GSL quadrature (qagiu), to compare with eq 21 (0.431 rho g h^3).
 * Returns WL_OK; WL_EINPUT if rho, g or h is not finite and > 0; WL_ENOMEM;
 * WL_ENUMERIC. On failure *V is 0. */
enum wl_status wl_waves_lh74_potential(double rho, double g, double h, double *V,
                                       struct wl_error *err);

/* ---- Goring (1978) piston paddle ---------------------------------------- */

/* Validate and fill *gp for a first-order solitary wave of height H [m] on
 * depth h [m], gravity g [m/s^2], start/stop threshold eps0 (use
 * WL_WAVES_GORING_EPS0_DEFAULT).
 * Returns WL_OK; WL_EINPUT if h, H, g are not finite and > 0, if H/h is
 * outside [WL_WAVES_EPS_MIN, WL_WAVES_EPS_MAX], or if eps0 is not in (0, 1).
 * On failure *gp is zeroed. */
enum wl_status wl_waves_goring_init(struct wl_goring *gp, double h, double H, double g,
                                    double eps0, struct wl_error *err);

/* Paddle displacement X_p [m] from its start at time t [s] after the start:
 * 0 for t <= 0, gp->x_end for t >= gp->duration, otherwise the root of the
 * implicit equation (safeguarded Newton with bisection on a bracket that
 * always holds it, to ~1e-15 relative). No allocation. */
double wl_waves_goring_position(const struct wl_goring *gp, double t);

/* Paddle velocity U_p = c eta/(h + eta) [m/s] at time t [s], eta the first-
 * order elevation at the paddle; 0 outside (0, gp->duration). */
double wl_waves_goring_velocity(const struct wl_goring *gp, double t);

/* ---- exact solitary wave ------------------------------------------------ */

/* Exact irrotational solitary wave of amplitude eps = H/h by Petviashvili
 * iteration of the Babenko equation (Clamond & Dutykh 2013) on n_modes
 * Fourier modes (a power of two, 256..1048576). 8192 reproduces REFERENCES
 * 3.4 to all its digits for eps <= 0.3 (~0.1 s); near eps = 0.79 use 65536
 * (256 modes there give F wrong in the 2nd digit); out->tail tells.
 * Allocates and frees its own work arrays.
 * Returns WL_OK; WL_EINPUT if eps is outside [0.001, 0.79] or n_modes is not
 * such a power of two; WL_ENOMEM; WL_ENUMERIC if the iteration does not
 * converge to 1e-13 within 2000 iterations. On failure *out is zeroed. */
enum wl_status wl_waves_exact_solitary(double eps, int n_modes, struct wl_solitary_exact *out,
                                       struct wl_error *err);

/* Dimensional integrals [kg/m, kg/s, J/m] of an exact solution on depth h
 * [m], gravity g [m/s^2], density rho [kg/m^3]. */
void wl_waves_exact_integrals(const struct wl_solitary_exact *ex, double rho, double g, double h,
                              struct wl_wave_integrals *out);

#endif
