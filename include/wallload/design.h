/* design.h: design-code wall loads on a vertical wall, per metre of wall, for
 * comparison with the SPH wall loads.
 *
 * Owns the linear-dispersion wavelength, hydrostatic loads, Goda's wave
 * pressure formula with Takahashi's impulsive coefficient, Sainflou's
 * standing-wave pressure, the FEMA P-646 tsunami loads and the CCH surge
 * force, each with its citation, a validity-range flag with a one-line
 * reason (out of range is a flag, not an error: the report shows such rows
 * marked), the horizontal force [N/m], the overturning moment about the
 * wall's base (its toe) [N m/m], the pressure profile p(z) where natural and
 * the uplift pressure where defined; and one call that evaluates every
 * formula that applies to a scenario.
 *
 * Sources, with what each says and how far it was confirmed here (stored
 * public copies searched when this module was written; "UNCONFIRMED" marks
 * what rests on memory or on a secondary source only):
 *
 *   [HYD] Hydrostatics: p = rho g (D - z) for water of depth D over the base,
 *        F = rho g D^2 / 2 acting D/3 above the base, M = rho g D^3 / 6.
 *        Exact; also shared/design/REFERENCES.md 1.1 (h = 0.5 m: 1226.25 N/m).
 *
 *   [GODA] Goda, Y. (2000) "Random Seas and Design of Maritime Structures",
 *        2nd ed., World Scientific, ch. 4 (upright breakwaters); the formula
 *        is Goda (1974) "New wave pressure formulae for composite
 *        breakwaters", Proc. 14th ICCE, as extended with the lambda
 *        modification factors (Takahashi 2002 in the CEM, UNCONFIRMED):
 *          eta* = 0.75 (1 + cos b) lambda1 Hmax
 *          p1 = 0.5 (1 + cos b)(lambda1 alpha1 + lambda2 alpha* cos^2 b) rho g Hmax
 *          p2 = p1 / cosh(2 pi h / L)   (at the sea bed; reported only)
 *          p3 = alpha3 p1               (at the wall's base, h' below SWL)
 *          p4 = alpha4 p1               (at the crest)
 *          alpha1 = 0.6 + 0.5 [(4 pi h/L) / sinh(4 pi h/L)]^2
 *          alpha2 = min{ (hb - d)/(3 hb) (Hmax/d)^2, 2 d / Hmax }
 *          alpha3 = 1 - (h'/h) [1 - 1/cosh(2 pi h/L)]
 *          alpha4 = 1 - hc* / eta*,  hc* = min(eta*, hc)
 *          pu = 0.5 (1 + cos b) alpha1 alpha3 lambda3 rho g Hmax (uplift at the
 *               seaward edge of the base, falling linearly to 0 at the lee edge)
 *          P = (p1 + p3) h'/2 + (p1 + p4) hc* / 2
 *          Mp = (2 p1 + p3) h'^2/6 + (p1 + p4) h' hc* / 2 + (p1 + 2 p4) hc*^2 / 6
 *          U = pu B / 2, Mu = (2/3) U B (about the lee heel)
 *        with alpha* = alpha2 (plain Goda). L is the wavelength at depth h for
 *        the design period (Goda: T_max ~ T_1/3), hb the depth 5 H_1/3
 *        seaward of the wall, b the angle between the wave direction and the
 *        wall's normal, which Goda rotates by up to 15 degrees toward the
 *        normal (left to the caller here). The pressures are WAVE pressures:
 *        the still-water hydrostatic pressure is not in them.
 *        Confirmed: not from the book itself, but from two independent
 *        implementations that cite it and agree term for term with the
 *        above: the `breakwater` Python package (Sander-w/breakwater,
 *        breakwater/core/goda.py, whose test takes its inputs from "Goda
 *        (2000), page 140": h = 10.1 m, d = 5.6 m, h' = 7.1 m, hc = 3.4 m,
 *        Hmax = 8.05 m, T = 11.4 s, b = 15 deg, slope 1/100, rho = 1030;
 *        tests/test_design.c reproduces its p1, p3, p4, pu to 1e-8) and the
 *        Deltares coastal-structures-toolbox (forces_caisson/goda1985.py,
 *        with hb = h + 5 H_1/3 / cot(slope)). The book's own worked numbers
 *        were not read (UNCONFIRMED). Goda's list of geometries prone to
 *        impulsive breaking (as coded by Deltares: b < 20 deg, small berm,
 *        steep sea bed, low steepness, hc/H > 0.3) is not used here;
 *        Takahashi's coefficient is the impulsive flag.
 *
 *   [TAK] Takahashi, S., Tanimoto, K. and Shimosako, K. (1994) "A proposal
 *        of impulsive pressure coefficient for design of composite
 *        breakwaters", Proc. Hydro-Port '94, Yokosuka (citation details and
 *        the CEM table number VI-5-54 from memory: UNCONFIRMED):
 *          alpha_I = alpha_I0 alpha_I1, alpha* = max(alpha2, alpha_I)
 *          alpha_I0 = Hmax/d for Hmax <= 2d, else 2
 *          alpha_I1 = cos(delta2)/cosh(delta1)              for delta22 <= 0
 *                   = 1/(cosh(delta1) cosh(delta2)^(1/2))   for delta22 > 0
 *          delta1 = 20 delta11 (delta11 <= 0), 15 delta11 (delta11 > 0)
 *          delta2 = 4.9 delta22 (delta22 <= 0), 3 delta22 (delta22 > 0)
 *          delta11 = 0.93 (BM/L - 0.12) + 0.36 ((h - d)/h - 0.6)
 *          delta22 = -0.36 (BM/L - 0.12) + 0.93 ((h - d)/h - 0.6)
 *        with BM the berm width in front of the wall. Confirmed from the
 *        `breakwater` package (Goda._impulsive_pressure, which cites
 *        "Takahasi (2002)"); it matches the CEM table as remembered.
 *        Flag here: plain Goda is out of range when alpha_I > alpha2
 *        (impulsive breaking governs, Goda under-predicts); that is the
 *        package's criterion for its impulsive warning.
 *
 *   [SAIN] Sainflou, G. (1928) "Essai sur les digues maritimes verticales",
 *        Annales des Ponts et Chaussees 98(4); the simplified straight-line
 *        pressure diagram of the Shore Protection Manual (1984, sec. 7-3) and
 *        Goda's book, crest of the clapotis at the wall:
 *          delta0 = (pi H^2 / L) coth(2 pi h / L)  (orbit-centre rise)
 *          p2 = rho g H / cosh(2 pi h / L)         (wave pressure at the bed)
 *          p1 = (p2 + rho g h)(H + delta0)/(h + H + delta0)  (at SWL)
 *        i.e. total pressure (hydrostatic included) falling linearly from
 *        rho g h + p2 at the bed through p1 at SWL to 0 at H + delta0 above
 *        SWL; H is the INCIDENT height (the clapotis is 2H high), L the
 *        wavelength at depth h. F = (rho g h + p2)(h + H + delta0)/2,
 *        M = F (h + H + delta0)/3. The SPM/CEM text was not read
 *        (UNCONFIRMED); confirmed: delta0 and p2 are exactly the crest
 *        elevation and bed pressure of the Lagrangian Sainflou solution in
 *        the USACE ACES 4-3 code (MATLAB port, WFVW2: y_c = y0 +
 *        H sinh(k(h+y0))/sinh(kh) + pi H (H/L) ...), and the check against
 *        ACES User's Guide Example 4-3 (d = 15 ft, H = 8 ft, T = 10 s, 64
 *        lb/ft^3: 17 724 lb/ft, 148 009 lb ft/ft, by 90-step Lagrangian
 *        integration) agrees within 1.6 % (force) and 2.5 % (moment).
 *        Validity flags: non-breaking needs H <= 0.78 h (the flat-bed
 *        breaker index ACES 4-3 checks, ERRWAVBRK1(d, 0.78)) and
 *        H/L <= 0.142 tanh(kh) (Miche 1944, from memory: UNCONFIRMED);
 *        full reflection needs the crest at or above H + delta0 (this
 *        module's criterion; the profile is cut at the crest).
 *
 *   [FEMA] FEMA P-646 (2012, 2nd ed.) "Guidelines for Design of Structures
 *        for Vertical Evacuation from Tsunamis", ch. 6 and App. C, confirmed
 *        from a stored copy of the text (an edition that cites 2012
 *        photographs, taken to be the 2012 one): Eq 6-1 Fh = pc Aw =
 *        rho_s g b h_max^2 / 2 with rho_s = 1100 kg/m^3 (sea water with sediment,
 *        1.1 rho here); Eq 6-3 h_max = 1.3 R* - z_w = R - z_w (R the design
 *        run-up elevation, 1.3 times the predicted one); Eq 6-5 Fd =
 *        rho_s Cd B (h u^2)_max / 2, Cd = 2; Eq 6-6 (h u^2)_max = g R^2
 *        (0.125 - 0.235 z/R + 0.11 (z/R)^2) for ground elevation z; Eq 6-7
 *        impulsive (bore) force Fs = 1.5 Fd; App. C.3 example z = 4 m,
 *        R = 13 m: (h u^2)_max = 105 m^3/s^2, Fd = 1155 kN and Fs = 1730 kN
 *        for B = 10 m. The hydrostatic line of action h_max/3 follows from
 *        the triangular pressure; FEMA gives no line of action for Fd, so
 *        this module puts it at h_max/2 (an assumption: UNCONFIRMED). The
 *        2008 edition's equation numbers differ (UNCONFIRMED).
 *   [CCH] The surge force on a wall at the leading edge of a bore,
 *        Fs = 4.5 rho_s g h^2 (h the bore depth), acting h above the base
 *        (a triangular pressure equal to still water 3h deep), is from the
 *        City and County of Honolulu Building Code (2000) after Dames &
 *        Moore (1980), as quoted in FEMA 55 and Nistor et al. (2009). It is
 *        NOT in FEMA P-646 (2012) as read here (its Eq 6-7 is 1.5 Fd); the
 *        whole item is from memory: UNCONFIRMED.
 *   [ASCE7] ASCE/SEI 7-16 chapter 6 "Tsunami Loads and Effects" (continued
 *        in ASCE 7-22, confirmed to exist) is the US consensus standard that
 *        replaced the FEMA P-646 load equations for design; FEMA P-646 (2019,
 *        3rd ed.) defers to it (UNCONFIRMED). Its procedures (inundation
 *        depth and velocity from energy grade line analysis) are not
 *        implemented here.
 *
 *   [DISP] Linear dispersion omega^2 = g k tanh(k h), solved by Newton in kh.
 *        Independent checks in the test: Fenton, J.D. and McKee, W.D. (1990)
 *        "On calculating the lengths of water waves", Coastal Eng. 14:
 *        L ~ L0 tanh((omega^2 h/g)^(3/4))^(2/3) (1.66 % worst error
 *        measured); Hunt (1979) Pade series (coefficients from the ACES
 *        port), 8.2e-5 worst error measured; and Goda (2000) wavelength
 *        table values as transcribed by the Deltares toolbox tests.
 *
 * Geometry: z is elevation above the wall's base (the toe of its seaward
 * face); SWL is still-water level. A wall on a plain bed has h = d = h'.
 * Units SI throughout. Every fallible function returns WL_OK, WL_EINPUT
 * (message "design: <what>: found <value>; <what is valid>") or, for the
 * wavelength, WL_ENUMERIC; on failure the out-parameters are unspecified.
 * Nothing allocates, nothing prints. */
#ifndef WALLLOAD_DESIGN_H
#define WALLLOAD_DESIGN_H

#include "wallload/error.h"

/* Validity limits and code constants, with their sources. */
#define WL_DESIGN_BREAKING_RATIO 0.78  /* H/h at depth-limited breaking, flat bed (ACES 4-3) */
#define WL_DESIGN_MICHE_COEF 0.142     /* (H/L)max = 0.142 tanh(kh), Miche (1944) UNCONFIRMED */
#define WL_DESIGN_FEMA_SEDIMENT 1.1    /* rho_s / rho, FEMA P-646 (2012) Eq 6-1 (1100 kg/m^3) */
#define WL_DESIGN_FEMA_CD 2.0          /* drag coefficient of a wall, FEMA P-646 (2012) Eq 6-5 */
#define WL_DESIGN_FEMA_IMPULSIVE 1.5   /* Fs / Fd, FEMA P-646 (2012) Eq 6-7 */
#define WL_DESIGN_FEMA_RUNUP_FACTOR 1.3 /* R = 1.3 R*, FEMA P-646 (2012) Eq 6-3 (for callers) */
#define WL_DESIGN_CCH_SURGE_COEF 4.5   /* Fs = 4.5 rho_s g h^2, CCH (2000), UNCONFIRMED */

enum { WL_DESIGN_PROFILE_MAX = 4, WL_DESIGN_NOTE_MAX = 200, WL_DESIGN_MAX_RESULTS = 10 };

/* A piecewise-linear pressure profile on the wall. */
struct wl_design_profile {
  int n_points;                     /* 0: the formula gives no profile */
  double z[WL_DESIGN_PROFILE_MAX];  /* elevation above the wall's base [m], strictly increasing */
  double p[WL_DESIGN_PROFILE_MAX];  /* pressure at z[i] [Pa]; linear between points, 0 outside */
};

/* What a result's force contains. */
enum wl_design_basis {
  WL_DESIGN_BASIS_TOTAL,   /* all pressure on the seaward face, still-water hydrostatics included */
  WL_DESIGN_BASIS_WAVE,    /* the excess over still-water hydrostatics (Goda's wave pressure) */
  WL_DESIGN_BASIS_DYNAMIC, /* a flow force alone, added to hydrostatics in design (FEMA Fd, Fs) */
};

/* One formula's answer for one wall. */
struct wl_design_result {
  const char *name;     /* short id ("goda", "sainflou", ...); static storage, never NULL */
  const char *citation; /* author, year, equation or section; static storage, never NULL */
  enum wl_design_basis basis;
  double force;         /* horizontal force as the formula defines it [N/m] */
  double moment;        /* its overturning moment about the wall's base [N m/m] */
  double force_total;   /* force plus, unless basis is TOTAL, the still-water hydrostatic force
                           rho g d_w^2 / 2 on the face (d_w its still-water depth) [N/m]: the
                           number to compare with an integrated SPH wall pressure */
  double moment_total;  /* moment plus, unless TOTAL, rho g d_w^3 / 6 [N m/m] */
  double uplift_p;      /* uplift pressure at the seaward edge of the base [Pa]; NAN if undefined */
  int in_range;         /* 1 inside the formula's validity range, 0 outside (still computed) */
  char range_note[WL_DESIGN_NOTE_MAX]; /* one line: the limit checked and the value found */
  struct wl_design_profile profile;    /* p(z) in the result's basis */
};

/* Name of a basis ("total", "wave", "dynamic"); "unknown" for an invalid
 * value. Never NULL; static storage. */
const char *wl_design_basis_name(enum wl_design_basis basis);

/* ---- linear dispersion [DISP] ----------------------------------------- */

/* Wavelength L [m] of a linear wave of period T [s] in depth h [m] under
 * gravity g [m/s^2]: the root of (2 pi/T)^2 = g k tanh(k h), k = 2 pi/L, by
 * Newton iteration on kh from the Fenton-McKee estimate, to a relative step
 * below 4 DBL_EPSILON. Returns WL_OK; WL_EINPUT for T, h or g not positive
 * and finite; WL_ENUMERIC if Newton does not converge (not observed). */
enum wl_status wl_design_wavelength(double T, double h, double g, double *L, struct wl_error *err);

/* ---- profiles ----------------------------------------------------------- */

/* Pressure [Pa] of profile pr at elevation z [m] above the wall's base:
 * linear interpolation between points, 0 below the first and above the last
 * (and for n_points < 2). pr must not be NULL. */
double wl_design_profile_pressure(const struct wl_design_profile *pr, double z);

/* Exact integrals of a piecewise-linear profile: *force = int p dz [N/m],
 * *moment = int p z dz [N m/m] about the base. Either pointer may be NULL. */
void wl_design_profile_integrate(const struct wl_design_profile *pr, double *force, double *moment);

/* ---- hydrostatic [HYD] ------------------------------------------------- */

/* Still water of depth d + eta over the wall's base: d [m] the still-water
 * depth (>= 0), eta [m] a raised level above SWL (surge, set-up, run-up;
 * may be negative while d + eta > 0); rho [kg/m^3], g [m/s^2] positive.
 * Fills *out (basis TOTAL, in range, name "hydrostatic" for eta == 0 else
 * "hydrostatic-level"; force_total = force since hydrostatics is the whole
 * load). WL_EINPUT for a bad argument or d + eta <= 0. */
enum wl_status wl_design_hydrostatic(double rho, double g, double d, double eta,
                                     struct wl_design_result *out, struct wl_error *err);

/* ---- Goda / Takahashi [GODA] [TAK] ------------------------------------- */

struct wl_design_goda_in {
  double rho;      /* water density [kg/m^3] */
  double g;        /* gravity [m/s^2] */
  double h;        /* still-water depth in front of the wall (at the mound's toe) [m] */
  double d;        /* depth above the berm / armour in front of the wall [m]; = h on a plain bed */
  double h_prime;  /* depth of the wall's base below SWL, h' [m]; d <= h' <= h */
  double hc;       /* crest height above SWL [m] (>= 0; INFINITY: no crest) */
  double hb;       /* depth 5 H_1/3 seaward of the wall [m] (>= d); 0: take h */
  double Hmax;     /* design wave height [m] */
  double T;        /* design period [s], used when L is 0 */
  double L;        /* wavelength at depth h [m]; 0: computed from T */
  double beta;     /* angle between wave direction and the wall's normal [rad], 0..pi/2 */
  double lambda1;  /* modification factors (1 for a plain upright wall) */
  double lambda2;
  double lambda3;
  int impulsive;   /* 1: alpha* = max(alpha2, alpha_I) [TAK]; 0: plain Goda, alpha* = alpha2 */
  double BM;       /* berm width in front of the wall [m] (>= 0), for alpha_I */
  double B;        /* width of the wall's base [m] for the uplift force U; 0: U not computed */
};

struct wl_design_goda_out {
  double L;                           /* wavelength used [m] */
  double eta_star, hc_star;           /* elevation reached by the pressure, loaded crest [m] */
  double alpha1, alpha2, alpha3, alpha4;
  double delta11, delta22, alpha_I0, alpha_I1, alpha_I; /* [TAK], always computed */
  double alpha_star;                  /* the coefficient used in p1 */
  double p1, p2, p3, p4, pu;          /* [Pa] */
  double P, Mp;                       /* wave force [N/m], its moment about the base [N m/m] */
  double U, Mu;                       /* uplift force [N/m], moment about the lee heel [N m/m];
                                         NAN when B == 0 */
  struct wl_design_result result;     /* "goda" or "goda-takahashi", basis WAVE, d_w = h' */
};

/* Defaults: rho 1000, g WL_G_STANDARD (9.81), lambdas 1, beta 0, hb 0,
 * L 0, impulsive 0, BM 0, B 0, hc INFINITY; h, d, h_prime, Hmax and T NAN so
 * that a field left unset is reported as bad input. */
void wl_design_goda_in_init(struct wl_design_goda_in *in);

/* Goda's pressure formula for *in, all intermediate values into *out.
 * Range flag: plain Goda is out of range when alpha_I > alpha2 (impulsive
 * breaking); the Takahashi variant is in range (calibrated for composite
 * breakwaters: a plain bed gives alpha_I <= 0, so both agree there).
 * WL_EINPUT for: rho, g, h, d, Hmax not positive and finite; h' outside
 * [d, h]; d > h; hb given and < d; hc NaN or < 0; beta outside [0, pi/2];
 * lambdas not positive; BM or B negative; neither L nor T positive.
 * WL_ENUMERIC only from the wavelength. */
enum wl_status wl_design_goda(const struct wl_design_goda_in *in, struct wl_design_goda_out *out,
                              struct wl_error *err);

/* ---- Sainflou [SAIN] --------------------------------------------------- */

struct wl_design_sainflou_in {
  double rho, g; /* [kg/m^3], [m/s^2] */
  double h;      /* still-water depth at the wall [m] */
  double H;      /* incident wave height [m] */
  double T;      /* period [s], used when L is 0 */
  double L;      /* wavelength at depth h [m]; 0: computed from T */
  double hc;     /* crest height above SWL [m] (>= 0; INFINITY: no crest) */
};

struct wl_design_sainflou_out {
  double L;       /* wavelength used [m] */
  double delta0;  /* orbit-centre rise [m] */
  double crest;   /* clapotis crest above SWL, H + delta0 [m] */
  double p1;      /* total pressure at SWL [Pa] */
  double p2;      /* wave pressure at the bed [Pa] */
  double p_bed;   /* total pressure at the bed, rho g h + p2 [Pa] */
  int overtopped; /* 1 when hc < H + delta0 (profile cut at the crest) */
  struct wl_design_result result; /* "sainflou", basis TOTAL */
};

/* Sainflou's crest-at-wall pressure for *in into *out. Range flags, first
 * failing reported: H > 0.78 h (breaking), H/L > 0.142 tanh(kh) (too steep),
 * overtopped. WL_EINPUT for rho, g, h, H not positive and finite, hc NaN or
 * negative, neither L nor T positive. WL_ENUMERIC only from the wavelength. */
enum wl_status wl_design_sainflou(const struct wl_design_sainflou_in *in,
                                  struct wl_design_sainflou_out *out, struct wl_error *err);

/* ---- FEMA P-646 tsunami loads [FEMA] [CCH] ----------------------------- */

struct wl_design_fema_in {
  double rho;             /* water density [kg/m^3]; the loads use rho_s = sediment * rho */
  double g;               /* [m/s^2] */
  double sediment;        /* rho_s / rho (WL_DESIGN_FEMA_SEDIMENT) */
  double Cd;              /* drag coefficient (WL_DESIGN_FEMA_CD) */
  double R;               /* design run-up elevation above SWL, 1.3 R* [m] (> 0) */
  double z;               /* elevation of the wall's base above SWL [m]; < 0 stands in water */
};

struct wl_design_fema_out {
  double rho_s;           /* [kg/m^3] */
  double h_max;           /* R - z, water height over the base, Eq 6-3 [m] (0 if z >= R) */
  double hu2_max;         /* (h u^2)_max, Eq 6-6 [m^3/s^2] (0 if z >= R) */
  struct wl_design_result hydrostatic;  /* "fema-hydrostatic", Eq 6-1, TOTAL */
  struct wl_design_result hydrodynamic; /* "fema-hydrodynamic", Eq 6-5/6-6 per metre, DYNAMIC */
  struct wl_design_result impulsive;    /* "fema-impulsive", Eq 6-7, DYNAMIC */
};

/* Defaults: rho 1000, g 9.81, sediment 1.1, Cd 2, R and z NAN. */
void wl_design_fema_in_init(struct wl_design_fema_in *in);

/* The FEMA P-646 (2012) loads per metre of wall for *in. Range flags:
 * Eq 6-6 holds for 0 <= z <= R (onshore, below the run-up); z >= R means
 * the wall is not reached (forces 0, out of range). The still-water depth
 * for force_total is max(0, -z). WL_EINPUT for rho, g, sediment, Cd, R not
 * positive and finite, or z not finite. */
enum wl_status wl_design_fema(const struct wl_design_fema_in *in, struct wl_design_fema_out *out,
                              struct wl_error *err);

/* The CCH surge force on a wall at the leading edge of a bore of depth
 * h_bore [m] (> 0), sea water of density rho [kg/m^3] times sediment
 * (rho_s / rho), gravity g, wall base at z [m] above SWL: Fs = 4.5 rho_s g
 * h_bore^2 acting h_bore above the base, profile rho_s g (3 h_bore - z').
 * Basis TOTAL, name "cch-surge". Range flag: a bore on dry ground, z >= 0.
 * WL_EINPUT for a value not positive and finite (z: not finite). */
enum wl_status wl_design_cch_surge(double rho, double g, double sediment, double h_bore, double z,
                                   struct wl_design_result *out, struct wl_error *err);

/* ---- every formula for a scenario -------------------------------------- */

/* A wall on a plain bed, as the scenario describes it. */
struct wl_design_scenario {
  double rho, g;  /* [kg/m^3], [m/s^2] */
  double d;       /* still-water depth at the wall [m] (>= 0; 0: the toe is dry) */
  double z_toe;   /* height of a dry toe above SWL [m] (>= 0; must be 0 when d > 0) */
  double hc;      /* crest height above SWL [m] (>= 0; INFINITY: no crest) */
  double H;       /* design wave height at the wall [m]: Hmax for Goda, incident H for
                     Sainflou; 0: no wave rows */
  double T;       /* wave period [s], used when L is 0 */
  double L;       /* wavelength at depth d [m]; 0: from T */
  double eta;     /* raised still level above SWL (surge, set-up, run-up) for a second
                     hydrostatic row [m]; 0: none */
  double R;       /* tsunami design run-up elevation above SWL (1.3 R*) [m]; 0: no FEMA rows */
  double h_bore;  /* bore depth at the wall for the CCH surge row [m]; 0: none */
};

/* Defaults: rho 1000, g 9.81, hc INFINITY, everything else 0. */
void wl_design_scenario_init(struct wl_design_scenario *sc);

/* Evaluate every formula that applies to *sc into results[0..*n_results):
 *   hydrostatic             when d > 0
 *   hydrostatic-level       when eta != 0 and d + eta > 0
 *   goda, goda-takahashi,   when d > 0, H > 0 and T or L > 0 (plain bed: h = d = h' = hb,
 *   sainflou                  beta 0, lambdas 1, BM 0)
 *   fema-hydrostatic, fema-hydrodynamic, fema-impulsive   when R > 0 (z = z_toe or -d)
 *   cch-surge               when h_bore > 0
 * in that order. max_results must be at least WL_DESIGN_MAX_RESULTS.
 * Returns WL_OK; WL_EINPUT for a bad scenario value (the failing formula's
 * message, prefixed "scenario: ") or too small an array; WL_ENUMERIC from
 * the wavelength. On failure *n_results is 0. */
enum wl_status wl_design_evaluate(const struct wl_design_scenario *sc,
                                  struct wl_design_result *results, int max_results,
                                  int *n_results, struct wl_error *err);

#endif
