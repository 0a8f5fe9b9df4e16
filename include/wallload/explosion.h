/* explosion.h: initial conditions for waves from underwater explosions.
 *
 * Owns the crater shapes, their volumes and potential energies, the empirical
 * Van Dorn / Whalin / Le Mehaute scaling from charge mass to crater size, the
 * cavity-work energy partition, the chains that tie charge, crater size and
 * crater energy together, and the "thrown mass" initial condition.
 *
 * Sources (seed numbers are files under shared/seeds/):
 *   [S0] Safiyari, Akbarpour Jannat & Banijamali (2019), "Investigation of
 *        physical issues of the initial conditions of free water surface due
 *        to underwater disturbances on the basis of SPH", seed 000:
 *        eqs 1-3 crater shapes, eq 4 potential energy, eqs 5-7 its closed
 *        forms, eq 8 cavity work, eq 9 the 40 % partition, the thrown-mass
 *        method ("New approach to initial free surface condition", Fig. 9).
 *   [S1] seed 001 (SPH of explosion waves on sea walls): eq 1 crater with lip,
 *        eqs 2-3 its energy, eq 4 Van Dorn R0 = 9.6 W^0.3, eq 5
 *        eta0 R0 = 0.81 Hmax r, eq 6 Whalin Hmax r / W^0.54 = 34, eq 7
 *        Le Mehaute 36; section 3.1.3 and Table 4 (energy -> crater chain).
 *   [REF] shared/design/REFERENCES.md section 5.2 (plane crater with lip
 *        eta_c (3x^2/R^2 - 1), E0 = (4/5) rho g eta_c^2 R).
 *   [NIST] NIST SP 811 (2008), App. B.8: ton of TNT (energy equivalent)
 *        = 4.184e9 J, so 1 kg TNT = 4.184e6 J (a definition, not a measured
 *        heat of detonation).
 *
 * Sign convention ([S1] eq 1): eta(r) = eta0 f(r/R) with eta0 > 0 the crater
 * depth, so the crater centre lies at eta = -eta0. [S0] writes its eqs 1-3
 * with the opposite sign (eta0 [1 - u^2] etc., eta0 then negative for a
 * crater); the shapes are the same.
 *
 * Units: SI inside. The empirical formulae are in feet and pounds of TNT
 * and are converted here, at the function boundary, with WL_FT_M and
 * WL_LB_KG (exact). Charges are masses of TNT [kg]. In 2D (dims = 2) every
 * volume is an area per unit crest width [m^2/m = m^2], every energy a J per
 * metre, every mass a kg per metre; in 3D (dims = 3) the shape is
 * axisymmetric about r = 0.
 *
 * Errors: every fallible function returns WL_OK or WL_EINPUT (bad argument,
 * message "explosion: <what>: found <value>; <what is valid>"), and the
 * few noted WL_ENOMEM / WL_ENUMERIC; on failure the out-parameters are left
 * untouched. */
#ifndef WALLLOAD_EXPLOSION_H
#define WALLLOAD_EXPLOSION_H

#include "wallload/error.h"
#include "wallload/units.h"

/* Unit boundary constants (exact; normally from units.h). */
#ifndef WL_FT_M
#define WL_FT_M 0.3048 /* metres per international foot (exact) */
#endif
#ifndef WL_LB_KG
#define WL_LB_KG 0.45359237 /* kilograms per avoirdupois pound (exact) */
#endif
#ifndef WL_TNT_J_PER_KG
#define WL_TNT_J_PER_KG 4.184e6 /* TNT equivalent [J/kg], by definition [NIST] */
#endif

/* Empirical scaling [S1], in feet and pounds of TNT. */
#define WL_VANDORN_COEF 9.6      /* R0 [ft] = 9.6 W[lb]^0.3, [S1] eq 4 */
#define WL_VANDORN_EXP 0.3       /* exponent of W in [S1] eq 4 */
#define WL_WHALIN_COEF 34.0      /* Hmax r [ft^2] / W[lb]^0.54, upper critical depth, [S1] eq 6 */
#define WL_LEMEHAUTE_COEF 36.0   /* the same, Le Mehaute (1980), [S1] eq 7 */
#define WL_WHALIN_MEAN_COEF 35.0 /* mean of eqs 6-7; gives [S1]'s Charlesworth eta0 = 2.07 m */
#define WL_WHALIN_EXP 0.54       /* exponent of W in [S1] eqs 6-7 */
#define WL_ETA0R0_PER_HR 0.81    /* eta0 R0 = 0.81 Hmax r, [S1] eq 5 (dimensionless: m^2/m^2) */

/* Energy partition and cavity work [S0] eqs 8-9. */
#define WL_P_ATM 101325.0 /* standard atmosphere [Pa] */
/* Share of the chemical energy taken as wave-generating by [S0] eq 9 and
 * [S1] section 2.1 (the bubble-pulsation 40 %). A CEILING, not an estimate:
 * the literature reports that only a few percent of the explosive energy
 * reaches surface waves (UNCONFIRMED here), and the seeds' own Charlesworth
 * case (32 lb, R0 = 8.28 m, eta0 = 2.07 m) implies 1.50 MJ of crater energy
 * for 60.7 MJ of chemical energy, i.e. 2.5 % (see
 * wl_explosion_implied_fraction and tests/test_explosion.c). */
#define WL_EXPLOSION_WAVE_SHARE 0.40

/* Crater shapes, eta(r) = eta0 f(u), u = r/R, f = 0 beyond the extent.
 * "Zero volume" means the integral of eta over the plane (3D) or the line
 * (2D) vanishes, so the crater water sits in the lip. */
enum wl_crater_shape {
  /* f = -(1 - u^2), u <= 1; no lip ([S0] eq 1). Conserves no volume:
   * 3D -pi eta0 R^2 / 2, 2D -(4/3) eta0 R. */
  WL_CRATER_SHAPE_QUADRATIC,
  /* f = 2u^2 - 1, u <= 1 ([S0] eq 2, [S1] eq 1); rim at +eta0; zero volume
   * in 3D only (2D: -(2/3) eta0 R). */
  WL_CRATER_SHAPE_QUADRATIC_LIP_AXI,
  /* f = 3u^2 - 1, u <= 1 ([REF] 5.2); rim at +2 eta0; zero area in 2D only
   * (3D: +pi eta0 R^2 / 2). */
  WL_CRATER_SHAPE_QUADRATIC_LIP_PLANE,
  /* f = -(1 - (4/3)u^2 + (1/3)u^4), u <= sqrt 3 ([S0] eq 3); root at u = 1,
   * lip crest +eta0/3 at u = sqrt 2; zero volume in 3D only
   * (2D: -(8 sqrt3 / 15) eta0 R). */
  WL_CRATER_SHAPE_QUARTIC_LIP_AXI,
  /* f = -(1 - (6/5)u^2 + (1/5)u^4), u <= sqrt 5, the 2D analogue of eq 3
   * (derived here: f = -(1 - a u^2 + b u^4) with f(1) = 0 gives a = 1 + b and
   * an outer root u^2 = 1/b; zero area int_0^{1/sqrt b} f du = 0 gives
   * 15b - 5(1 + b) + 3 = 0, b = 1/5; the same steps with u du give b = 1/3,
   * [S0] eq 3). Lip crest +(4/5) eta0 at u = sqrt 3; zero area in 2D only
   * (3D: +(5/3) pi eta0 R^2). */
  WL_CRATER_SHAPE_QUARTIC_LIP_PLANE,
};
enum { WL_CRATER_SHAPE_COUNT = 5 };

/* Name of a shape ("quadratic", "quadratic-lip-axi", ...), "unknown" for an
 * invalid value. Never NULL; static storage. */
const char *wl_explosion_shape_name(enum wl_crater_shape shape);

/* Highest initial surface above still water [m] of a crater of depth eta0
 * (>= 0): its lip crest, eta0 times 0, 1, 2, 1/3 and 4/5 for the shapes
 * above in order (the rim at u = 1 of the quadratic forms, the stationary
 * point of the quartic ones). What decides the flume's c0. */
enum wl_status wl_explosion_rim_height(enum wl_crater_shape shape, double eta0, double *height,
                                       struct wl_error *err);

/* Free-surface elevation eta [m] at distance r [m] (r >= 0; 2D: |x|) from the
 * crater axis, for depth eta0 [m] (>= 0) and radius R [m] (> 0).
 * Returns WL_OK, or WL_EINPUT for an invalid shape, eta0 < 0, R <= 0, r < 0
 * or a non-finite value. */
enum wl_status wl_explosion_eta(enum wl_crater_shape shape, double eta0, double R, double r,
                                double *eta, struct wl_error *err);

/* Outer radius [m] beyond which eta = 0: R for the quadratics, sqrt(3) R and
 * sqrt(5) R for the quartics. WL_EINPUT for an invalid shape or R <= 0. */
enum wl_status wl_explosion_extent(enum wl_crater_shape shape, double R, double *extent,
                                   struct wl_error *err);

/* Radius [m] where the surface crosses still water (the crater's rim at
 * still-water level): R, R/sqrt2, R/sqrt3, R, R for the five shapes in order.
 * WL_EINPUT for an invalid shape or R <= 0. */
enum wl_status wl_explosion_inner_radius(enum wl_crater_shape shape, double R, double *rc,
                                         struct wl_error *err);

/* Net volume of the initial elevation, closed form: dims = 3: int eta dA
 * [m^3]; dims = 2: int eta dx over the whole line [m^2 per m width]. Negative
 * means water missing. WL_EINPUT for an invalid shape, dims not 2 or 3,
 * eta0 < 0 or R <= 0. */
enum wl_status wl_explosion_net_volume(enum wl_crater_shape shape, int dims, double eta0, double R,
                                       double *volume, struct wl_error *err);

/* The same by GSL adaptive quadrature (a second, independent computation).
 * Also WL_ENOMEM (workspace) or WL_ENUMERIC (quadrature failed). */
enum wl_status wl_explosion_net_volume_quad(enum wl_crater_shape shape, int dims, double eta0,
                                            double R, double *volume, struct wl_error *err);

/* 1 when the shape's net volume is exactly zero in `dims` dimensions
 * (QUADRATIC_LIP_AXI and QUARTIC_LIP_AXI in 3D, the two _PLANE shapes in 2D),
 * else 0 (also 0 for an invalid shape or dims). */
int wl_explosion_conserves_mass(enum wl_crater_shape shape, int dims);

/* Initial potential energy, closed form ([S0] eq 4 integrated):
 *   dims 3 [J]:    E = pi rho g eta0^2 R^2 * {1/6, 1/6, 1/2, 1/5, 5/6}
 *   dims 2 [J/m]:  E = rho g eta0^2 R * {8/15, 7/15, 4/5, 32 sqrt3/105,
 *                                        128 sqrt5/315}
 * (shapes in enum order; [S0] eqs 5-7 give the 3D 1/6, 1/6, 1/5; [REF] 5.2
 * gives the 2D 4/5). rho [kg/m^3] > 0, g [m/s^2] > 0, eta0 [m] >= 0,
 * R [m] > 0, else WL_EINPUT. */
enum wl_status wl_explosion_energy(enum wl_crater_shape shape, int dims, double rho, double g,
                                   double eta0, double R, double *energy, struct wl_error *err);

/* The same by GSL quadrature of [S0] eq 4: 3D E = 2 pi rho g int eta^2/2 r dr;
 * 2D E = rho g int eta^2/2 dx over the whole line. Also WL_ENOMEM or
 * WL_ENUMERIC. */
enum wl_status wl_explosion_energy_quad(enum wl_crater_shape shape, int dims, double rho, double g,
                                        double eta0, double R, double *energy,
                                        struct wl_error *err);

/* ---- empirical scaling [S1] eqs 4-7 (SI in, SI out) --------------------- */

/* Van Dorn crater radius at the lip: R0 [m] from charge [kg TNT] (> 0):
 * R0_ft = 9.6 W_lb^0.3. WL_EINPUT for charge <= 0 or non-finite. */
enum wl_status wl_explosion_vandorn_r0(double charge_kg, double *r0, struct wl_error *err);

/* Inverse of wl_explosion_vandorn_r0: charge [kg TNT] from R0 [m] (> 0). */
enum wl_status wl_explosion_vandorn_charge(double r0, double *charge_kg, struct wl_error *err);

/* Whalin / Le Mehaute: Hmax r [m^2] = coef W_lb^0.54 [ft^2], coef > 0
 * (WL_WHALIN_COEF, WL_LEMEHAUTE_COEF or WL_WHALIN_MEAN_COEF). WL_EINPUT for
 * charge <= 0 or coef <= 0. */
enum wl_status wl_explosion_whalin_hr(double charge_kg, double coef, double *hr,
                                      struct wl_error *err);

/* Inverse: charge [kg TNT] from Hmax r [m^2] (> 0) and coef (> 0). */
enum wl_status wl_explosion_whalin_charge(double hr, double coef, double *charge_kg,
                                          struct wl_error *err);

/* Forward crater depth: eta0 [m] = 0.81 Hmax r / R0 ([S1] eqs 4-6). */
enum wl_status wl_explosion_eta0_from_charge(double charge_kg, double coef, double *eta0,
                                             struct wl_error *err);

/* Inverse of [S1] eqs 5-6: charge [kg TNT] from eta0 R0 [m^2] (> 0). */
enum wl_status wl_explosion_charge_from_eta0_r0(double eta0_r0, double coef, double *charge_kg,
                                                struct wl_error *err);

/* ---- energy partition and cavity work [S0] eqs 8-9 ---------------------- */

/* Chemical energy [J] of a charge [kg TNT] (> 0): 4.184e6 J/kg [NIST]. */
enum wl_status wl_explosion_chemical_energy(double charge_kg, double *energy,
                                            struct wl_error *err);

/* [S0] eq 8: work [J] to open a sphere of radius a [m] (>= 0) whose top is at
 * the surface, against hydrostatic plus atmospheric pressure:
 * Wk = 4 pi rho g a^3 (a + z) / 3, z = p_atm / (rho g) [m]. rho, g > 0,
 * p_atm >= 0 [Pa], else WL_EINPUT. */
enum wl_status wl_explosion_cavity_work(double a, double rho, double g, double p_atm,
                                        double *work, struct wl_error *err);

/* Inverse of eq 8: the cavity radius a [m] whose work is `work` [J] (>= 0).
 * a^3 (a + z) is convex and increasing for a > 0; Newton from the upper bound
 * min(K^(1/4), (K/z)^(1/3)), K = 3 Wk / (4 pi rho g), descends monotonically
 * onto the root. WL_EINPUT for bad arguments, WL_ENUMERIC if Newton has not
 * converged in 200 steps (not expected). */
enum wl_status wl_explosion_cavity_radius(double work, double rho, double g, double p_atm,
                                          double *a, struct wl_error *err);

/* Implied wave-energy fraction = wave_energy [J] / chemical energy of
 * charge_kg: how much of the charge a given crater energy represents (to
 * compare with the 0.40 ceiling of [S0] eq 9). WL_EINPUT for
 * wave_energy < 0 or charge <= 0. */
enum wl_status wl_explosion_implied_fraction(double wave_energy, double charge_kg,
                                             double *fraction, struct wl_error *err);

/* ---- chains [S1] eqs 3-7 and section 3.1.3 ------------------------------ */

/* Water and model constants a chain uses. */
struct wl_explosion_params {
  double rho;         /* water density [kg/m^3]; default 1000 (reproduces [S1] Table 4) */
  double g;           /* gravity [m/s^2]; default 9.81 */
  double p_atm;       /* atmospheric pressure [Pa] for eq 8; default WL_P_ATM */
  double whalin_coef; /* Hmax r / W^0.54 [ft^2 lb^-0.54]; default WL_WHALIN_MEAN_COEF */
  double wave_share;  /* eq 9 share of chemical energy doing cavity work; default 0.40 (ceiling) */
};

/* Fill p with the defaults above. p must not be NULL. */
void wl_explosion_params_default(struct wl_explosion_params *p);

/* One explosion seen three ways: charge, crater size, crater energy. The
 * crater energy is always the 3D QUADRATIC_LIP_AXI energy of [S1] eq 3,
 * pi rho g (eta0 R0)^2 / 6, the form [S1] uses to match energies. */
struct wl_explosion_chain {
  double charge_kg;       /* charge [kg TNT] */
  double whalin_coef;     /* coefficient used [ft^2 lb^-0.54] */
  double chemical_energy; /* [J], 4.184 MJ/kg */
  double r0;              /* crater radius at the lip [m], Van Dorn eq 4 */
  double hr;              /* Hmax r [m^2], eq 6/7 */
  double eta0_r0;         /* eta0 R0 [m^2], eq 5 */
  double eta0;            /* crater depth = lip height [m] */
  double crater_energy;   /* potential energy of the crater [J], eq 3 */
  double wave_fraction;   /* crater_energy / chemical_energy (implied share) */
  double cavity_work;     /* wave_share * chemical_energy [J], [S0] eq 9 */
  double cavity_radius;   /* sphere radius with that work [m], [S0] eq 8 */
};

/* Chain from a charge [kg TNT] (> 0): R0 (eq 4), Hmax r (eq 6/7 with
 * p->whalin_coef), eta0 R0 (eq 5), eta0, crater energy (eq 3), the energies
 * and cavity of [S0] eqs 8-9. WL_EINPUT for bad charge or params; *chain
 * untouched on failure. */
enum wl_status wl_explosion_chain_from_charge(const struct wl_explosion_params *p,
                                              double charge_kg, struct wl_explosion_chain *chain,
                                              struct wl_error *err);

/* Chain from a crater energy [J] (> 0), [S1] section 3.1.3:
 * eta0 R0 = sqrt(6E / (pi rho g)) -> Hmax r = eta0 R0 / 0.81 -> W from the
 * coefficient -> R0 from Van Dorn -> eta0 = eta0 R0 / R0; then as above.
 * The result satisfies chain_from_charge(chain.charge_kg) to rounding. */
enum wl_status wl_explosion_chain_from_energy(const struct wl_explosion_params *p,
                                              double crater_energy,
                                              struct wl_explosion_chain *chain,
                                              struct wl_error *err);

/* ---- thrown mass ([S0], "New approach to initial free surface condition")
 *
 * What [S0] says: "the water mass, which could be displaced from crater
 * area, was calculated at the first step, and then the mass of lip and
 * vaporized water should be equilibrated, and finally the remained mass was
 * considered to be thrown upward with an initial upward velocity (Fig. 9)";
 * "waterbody size and its initial velocities are estimated by law of
 * conservation of energy"; "considering the kinetic energy of the thrown mass
 * equal to released energy by explosion"; Fig. 9 / Table 6: one, three and
 * five parts; Figs. 16-17 show both horizontal and vertical particle
 * velocities. Nothing more is given (no formula, no geometry).
 *
 * The rule made explicit here:
 *  1. Mass: M = rho (V_crater - V_lip) - m_vapor = -rho V_net - m_vapor, the
 *     water missing from the initial surface, so the SPH crater plus the
 *     thrown bodies hold exactly the still-water mass (the paper's
 *     conclusion 4: "the mass of these models are conserved"). Zero-volume
 *     shapes leave nothing to throw; use QUADRATIC (M = rho pi eta0 R^2 / 2
 *     in 3D, (4/3) rho eta0 R per metre in 2D) or a shape that does not
 *     conserve volume in the chosen dims.
 *  2. Body: a layer of uniform thickness h = M / (rho A) over the crater's
 *     still-water footprint (|x| <= rc in 2D, A = 2 rc per metre; r <= rc in
 *     3D, A = pi rc^2; rc from wl_explosion_inner_radius), resting on the
 *     still-water level (centre at z = h/2). For QUADRATIC, h is the crater's
 *     mean depth (2/3 eta0 in 2D, eta0/2 in 3D): the crater water lifted out.
 *  3. Parts: n equal-mass pieces, M/n each. 2D: n slabs of width 2 rc / n side
 *     by side across [-rc, rc]. 3D: a central disc and n-1 annuli of equal
 *     area, radii rc sqrt(k/n), k = 0..n (a 3D "part" is a ring, so the
 *     section through the axis shows 2n - 1 pieces).
 *  4. Velocity: every part gets the same speed V = sqrt(2E / M), so the total
 *     kinetic energy is exactly E whatever the directions (equal speed is
 *     what a uniform pressure impulse over equal masses gives). Direction:
 *     vertical for spread = 0 (the paper's "thrown upward"); otherwise part k
 *     leans outward by theta_k from vertical with
 *     tan(theta_k) = (s_k / rc) tan(spread), s_k its centre offset, as if
 *     launched from a point rc / tan(spread) below the crater centre. Mirror
 *     parts (2D) and rings (3D) cancel horizontal momentum.
 *  E is the caller's choice: the crater potential energy (wave-equivalent),
 *  or wave_share * chemical energy ([S0] eq 9, a ceiling). The potential
 *  energy of lifting the body out of the crater is not deducted (the paper
 *  equates kinetic energy to the explosion energy). */

/* One thrown part. 2D values are per metre of crest width. */
struct wl_explosion_part {
  double mass;   /* [kg] (3D) or [kg/m] (2D) */
  double offset; /* centre offset from the crater axis [m]: 2D signed x of the
                    slab centre; 3D radius of the circle halving the ring's
                    area (0 for the central disc) */
  double z;      /* height of the part's centre above still water [m] */
  double s_in;   /* 2D: left edge x [m]; 3D: inner radius [m] */
  double s_out;  /* 2D: right edge x [m]; 3D: outer radius [m] */
  double height; /* vertical thickness [m] */
  double u;      /* launch velocity, horizontal [m/s]: 2D along +x; 3D radially outward */
  double w;      /* launch velocity, vertical (up) [m/s] */
};

enum { WL_EXPLOSION_PARTS_MAX = 64 };

/* Thrown mass M [kg (3D) or kg/m (2D)] of rule 1 for a crater of shape,
 * depth eta0 [m] > 0 and radius R [m] > 0 in density rho [kg/m^3] > 0, less
 * vapor_mass [same unit] >= 0. WL_EINPUT for bad arguments or when nothing is
 * left to throw (M <= 0: the shape holds its crater water in its lip in these
 * dims, or vapor_mass exceeds the missing mass). */
enum wl_status wl_explosion_thrown_mass(enum wl_crater_shape shape, int dims, double rho,
                                        double eta0, double R, double vapor_mass, double *mass,
                                        struct wl_error *err);

/* Split mass M (> 0) carrying kinetic energy E [J or J/m] (>= 0) into n_parts
 * (1..WL_EXPLOSION_PARTS_MAX) by rules 2-4 over a footprint of radius rc [m]
 * (> 0), spread angle [rad] in [0, pi/2). parts must hold n_parts entries,
 * filled left to right (2D) or inside out (3D). WL_EINPUT for bad arguments;
 * parts untouched on failure. Sum of mass = M and of mass (u^2 + w^2)/2 = E to
 * rounding. */
enum wl_status wl_explosion_thrown_split(int dims, double rho, double rc, double mass,
                                         double energy, int n_parts, double spread,
                                         struct wl_explosion_part *parts, struct wl_error *err);

#endif
