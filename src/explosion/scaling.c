/* scaling.c: empirical explosion scaling in feet and pounds of TNT ([S1]
 * eqs 4-7: Van Dorn, Whalin, Le Mehaute), the energy partition and cavity
 * work ([S0] eqs 8-9), and the charge <-> crater <-> energy chains ([S1]
 * eq 3 and section 3.1.3). Feet and pounds exist only inside the functions
 * below; everything crossing the interface is SI. */
#include "wallload/explosion.h"

#include "check.h"

#include <float.h>
#include <gsl/gsl_math.h> /* M_PI */
#include <math.h>

/* Newton on a^3 (a + z) = K: iteration cap and stopping step (relative). */
#define CAVITY_MAX_ITER 200
#define CAVITY_REL_STEP (4.0 * DBL_EPSILON)

static const double FT2_M2 = WL_FT_M * WL_FT_M; /* m^2 per ft^2 */

static enum wl_status check_charge(double charge_kg, struct wl_error *err) {
  return check_positive("charge mass [kg TNT]", charge_kg, err);
}

static enum wl_status check_coef(double coef, struct wl_error *err) {
  return check_positive("Hmax r / W^0.54 coefficient [ft^2 lb^-0.54] (Whalin 34, Le Mehaute 36)",
                        coef, err);
}

/* ---- [S1] eqs 4-7 ------------------------------------------------------- */

enum wl_status wl_explosion_vandorn_r0(double charge_kg, double *r0, struct wl_error *err) {
  enum wl_status st = check_charge(charge_kg, err);
  if (st != WL_OK) return st;
  double w_lb = charge_kg / WL_LB_KG;
  double r0_ft = WL_VANDORN_COEF * pow(w_lb, WL_VANDORN_EXP);
  *r0 = r0_ft * WL_FT_M;
  return WL_OK;
}

enum wl_status wl_explosion_vandorn_charge(double r0, double *charge_kg, struct wl_error *err) {
  enum wl_status st = check_positive("crater radius R0 [m]", r0, err);
  if (st != WL_OK) return st;
  double r0_ft = r0 / WL_FT_M;
  double w_lb = pow(r0_ft / WL_VANDORN_COEF, 1.0 / WL_VANDORN_EXP);
  *charge_kg = w_lb * WL_LB_KG;
  return WL_OK;
}

enum wl_status wl_explosion_whalin_hr(double charge_kg, double coef, double *hr,
                                      struct wl_error *err) {
  enum wl_status st = check_charge(charge_kg, err);
  if (st == WL_OK) st = check_coef(coef, err);
  if (st != WL_OK) return st;
  double w_lb = charge_kg / WL_LB_KG;
  double hr_ft2 = coef * pow(w_lb, WL_WHALIN_EXP);
  *hr = hr_ft2 * FT2_M2;
  return WL_OK;
}

enum wl_status wl_explosion_whalin_charge(double hr, double coef, double *charge_kg,
                                          struct wl_error *err) {
  enum wl_status st = check_positive("Hmax r [m^2]", hr, err);
  if (st == WL_OK) st = check_coef(coef, err);
  if (st != WL_OK) return st;
  double hr_ft2 = hr / FT2_M2;
  double w_lb = pow(hr_ft2 / coef, 1.0 / WL_WHALIN_EXP);
  *charge_kg = w_lb * WL_LB_KG;
  return WL_OK;
}

enum wl_status wl_explosion_eta0_from_charge(double charge_kg, double coef, double *eta0,
                                             struct wl_error *err) {
  double r0 = 0.0, hr = 0.0;
  enum wl_status st = wl_explosion_vandorn_r0(charge_kg, &r0, err);
  if (st == WL_OK) st = wl_explosion_whalin_hr(charge_kg, coef, &hr, err);
  if (st != WL_OK) return st;
  *eta0 = WL_ETA0R0_PER_HR * hr / r0;
  return WL_OK;
}

enum wl_status wl_explosion_charge_from_eta0_r0(double eta0_r0, double coef, double *charge_kg,
                                                struct wl_error *err) {
  enum wl_status st = check_positive("eta0 R0 [m^2]", eta0_r0, err);
  if (st != WL_OK) return st;
  return wl_explosion_whalin_charge(eta0_r0 / WL_ETA0R0_PER_HR, coef, charge_kg, err);
}

/* ---- [S0] eqs 8-9 ------------------------------------------------------- */

enum wl_status wl_explosion_chemical_energy(double charge_kg, double *energy,
                                            struct wl_error *err) {
  enum wl_status st = check_charge(charge_kg, err);
  if (st != WL_OK) return st;
  *energy = charge_kg * WL_TNT_J_PER_KG;
  return WL_OK;
}

static enum wl_status check_cavity_water(double rho, double g, double p_atm,
                                         struct wl_error *err) {
  enum wl_status st = check_water(rho, g, err);
  if (st == WL_OK) st = check_nonneg("atmospheric pressure [Pa]", p_atm, err);
  return st;
}

enum wl_status wl_explosion_cavity_work(double a, double rho, double g, double p_atm,
                                        double *work, struct wl_error *err) {
  enum wl_status st = check_nonneg("cavity radius a [m]", a, err);
  if (st == WL_OK) st = check_cavity_water(rho, g, p_atm, err);
  if (st != WL_OK) return st;
  double z = p_atm / (rho * g); /* head of the atmosphere [m] */
  *work = 4.0 * M_PI * rho * g * a * a * a * (a + z) / 3.0;
  return WL_OK;
}

enum wl_status wl_explosion_cavity_radius(double work, double rho, double g, double p_atm,
                                          double *a_out, struct wl_error *err) {
  enum wl_status st = check_nonneg("cavity work [J]", work, err);
  if (st == WL_OK) st = check_cavity_water(rho, g, p_atm, err);
  if (st != WL_OK) return st;
  if (work == 0.0) {
    *a_out = 0.0;
    return WL_OK;
  }
  double z = p_atm / (rho * g);
  double K = 3.0 * work / (4.0 * M_PI * rho * g); /* a^3 (a + z) = K [m^4] */
  /* a^4 <= K and z a^3 <= K bound the root from above. */
  double a = pow(K, 0.25);
  if (z > 0.0) a = fmin(a, cbrt(K / z));
  for (int it = 0; it < CAVITY_MAX_ITER; it++) {
    double phi = a * a * a * (a + z) - K;
    double dphi = a * a * (4.0 * a + 3.0 * z);
    if (phi <= 0.0 || dphi <= 0.0) { /* on the root to rounding */
      *a_out = a;
      return WL_OK;
    }
    double step = phi / dphi;
    a -= step;
    if (step <= CAVITY_REL_STEP * a) {
      *a_out = a;
      return WL_OK;
    }
  }
  return wl_error_set(err, WL_ENUMERIC,
                      "explosion: cavity radius for work %g J did not converge in %d Newton steps",
                      work, CAVITY_MAX_ITER);
}

enum wl_status wl_explosion_implied_fraction(double wave_energy, double charge_kg,
                                             double *fraction, struct wl_error *err) {
  double chem = 0.0;
  enum wl_status st = check_nonneg("wave energy [J]", wave_energy, err);
  if (st == WL_OK) st = wl_explosion_chemical_energy(charge_kg, &chem, err);
  if (st != WL_OK) return st;
  *fraction = wave_energy / chem;
  return WL_OK;
}

/* ---- chains ------------------------------------------------------------- */

void wl_explosion_params_default(struct wl_explosion_params *p) {
  p->rho = 1000.0;
  p->g = 9.81;
  p->p_atm = WL_P_ATM;
  p->whalin_coef = WL_WHALIN_MEAN_COEF;
  p->wave_share = WL_EXPLOSION_WAVE_SHARE;
}

static enum wl_status check_params(const struct wl_explosion_params *p, struct wl_error *err) {
  if (!p) return wl_error_set(err, WL_EINPUT, "explosion: parameters: found NULL; pass a filled "
                                              "struct wl_explosion_params");
  enum wl_status st = check_cavity_water(p->rho, p->g, p->p_atm, err);
  if (st == WL_OK) st = check_coef(p->whalin_coef, err);
  if (st == WL_OK && !(p->wave_share >= 0.0 && p->wave_share <= 1.0))
    st = wl_error_set(err, WL_EINPUT, "explosion: wave share of chemical energy: found %g; "
                                      "valid is 0 to 1 (the seeds use 0.40, a ceiling)",
                      p->wave_share);
  return st;
}

enum wl_status wl_explosion_chain_from_charge(const struct wl_explosion_params *p,
                                              double charge_kg, struct wl_explosion_chain *chain,
                                              struct wl_error *err) {
  enum wl_status st = check_params(p, err);
  if (st != WL_OK) return st;
  struct wl_explosion_chain c = {0};
  c.charge_kg = charge_kg;
  c.whalin_coef = p->whalin_coef;
  st = wl_explosion_chemical_energy(charge_kg, &c.chemical_energy, err);
  if (st == WL_OK) st = wl_explosion_vandorn_r0(charge_kg, &c.r0, err);
  if (st == WL_OK) st = wl_explosion_whalin_hr(charge_kg, p->whalin_coef, &c.hr, err);
  if (st != WL_OK) return st;
  c.eta0_r0 = WL_ETA0R0_PER_HR * c.hr;
  c.eta0 = c.eta0_r0 / c.r0;
  /* [S1] eq 3: the 3D quadratic crater with lip. */
  c.crater_energy = M_PI * p->rho * p->g * c.eta0_r0 * c.eta0_r0 / 6.0;
  c.wave_fraction = c.crater_energy / c.chemical_energy;
  c.cavity_work = p->wave_share * c.chemical_energy;
  st = wl_explosion_cavity_radius(c.cavity_work, p->rho, p->g, p->p_atm, &c.cavity_radius, err);
  if (st != WL_OK) return st;
  *chain = c;
  return WL_OK;
}

enum wl_status wl_explosion_chain_from_energy(const struct wl_explosion_params *p,
                                              double crater_energy,
                                              struct wl_explosion_chain *chain,
                                              struct wl_error *err) {
  enum wl_status st = check_params(p, err);
  if (st == WL_OK) st = check_positive("crater energy [J]", crater_energy, err);
  if (st != WL_OK) return st;
  /* Invert [S1] eq 3 for the product eta0 R0, then eqs 5, 6/7 for W. */
  double eta0_r0 = sqrt(6.0 * crater_energy / (M_PI * p->rho * p->g));
  double charge_kg = 0.0;
  st = wl_explosion_charge_from_eta0_r0(eta0_r0, p->whalin_coef, &charge_kg, err);
  if (st != WL_OK) return st;
  return wl_explosion_chain_from_charge(p, charge_kg, chain, err);
}
