/* evaluate.c: every formula that applies to a wall on a plain bed, in the
 * order design.h lists, into a caller-owned array. */
#include "internal.h"

void wl_design_scenario_init(struct wl_design_scenario *sc) {
  sc->rho = 1000.0;
  sc->g = WL_G_STANDARD;
  sc->d = 0.0;
  sc->z_toe = 0.0;
  sc->hc = INFINITY;
  sc->H = 0.0;
  sc->T = 0.0;
  sc->L = 0.0;
  sc->eta = 0.0;
  sc->R = 0.0;
  sc->h_bore = 0.0;
}

static enum wl_status check_scenario(const struct wl_design_scenario *sc, struct wl_error *err) {
  enum wl_status st = check_water(sc->rho, sc->g, err);
  if (st == WL_OK) st = check_nonneg("still-water depth at the wall d [m]", sc->d, err);
  if (st == WL_OK) st = check_nonneg("height of a dry toe above SWL z_toe [m]", sc->z_toe, err);
  if (st == WL_OK && sc->d > 0.0 && sc->z_toe > 0.0)
    st = wl_error_set(err, WL_EINPUT,
                      "design: toe: found d = %g m and z_toe = %g m; a toe is either under water "
                      "(d > 0, z_toe = 0) or dry (d = 0)",
                      sc->d, sc->z_toe);
  if (st == WL_OK) st = check_crest(sc->hc, err);
  if (st == WL_OK) st = check_nonneg("design wave height H [m]", sc->H, err);
  if (st == WL_OK) st = check_nonneg("wave period T [s]", sc->T, err);
  if (st == WL_OK) st = check_nonneg("wavelength L [m]", sc->L, err);
  if (st == WL_OK && !isfinite(sc->eta))
    st = wl_error_set(err, WL_EINPUT, "design: water level above SWL eta [m]: found %g; must be "
                                      "finite", sc->eta);
  if (st == WL_OK) st = check_nonneg("run-up elevation R [m]", sc->R, err);
  if (st == WL_OK) st = check_nonneg("bore depth h_bore [m]", sc->h_bore, err);
  return st;
}

enum wl_status wl_design_evaluate(const struct wl_design_scenario *sc,
                                  struct wl_design_result *results, int max_results,
                                  int *n_results, struct wl_error *err) {
  *n_results = 0;
  if (max_results < WL_DESIGN_MAX_RESULTS)
    return wl_error_set(err, WL_EINPUT,
                        "design: results array: found room for %d; needs WL_DESIGN_MAX_RESULTS "
                        "= %d",
                        max_results, WL_DESIGN_MAX_RESULTS);
  enum wl_status st = check_scenario(sc, err);
  int n = 0;

  if (st == WL_OK && sc->d > 0.0) st = wl_design_hydrostatic(sc->rho, sc->g, sc->d, 0.0,
                                                             &results[n++], err);
  if (st == WL_OK && sc->eta != 0.0 && sc->d + sc->eta > 0.0)
    st = wl_design_hydrostatic(sc->rho, sc->g, sc->d, sc->eta, &results[n++], err);

  if (st == WL_OK && sc->d > 0.0 && sc->H > 0.0 && (sc->T > 0.0 || sc->L > 0.0)) {
    struct wl_design_goda_in gi;
    struct wl_design_goda_out go;
    wl_design_goda_in_init(&gi);
    gi.rho = sc->rho;
    gi.g = sc->g;
    gi.h = gi.d = gi.h_prime = sc->d;
    gi.hc = sc->hc;
    gi.Hmax = sc->H;
    gi.T = sc->T;
    gi.L = sc->L;
    for (int imp = 0; imp <= 1 && st == WL_OK; imp++) {
      gi.impulsive = imp;
      st = wl_design_goda(&gi, &go, err);
      if (st == WL_OK) results[n++] = go.result;
    }
    if (st == WL_OK) {
      struct wl_design_sainflou_in si = {sc->rho, sc->g, sc->d, sc->H, sc->T, sc->L, sc->hc};
      struct wl_design_sainflou_out so;
      st = wl_design_sainflou(&si, &so, err);
      if (st == WL_OK) results[n++] = so.result;
    }
  }

  const double z = sc->d > 0.0 ? -sc->d : sc->z_toe;
  if (st == WL_OK && sc->R > 0.0) {
    struct wl_design_fema_in fi;
    struct wl_design_fema_out fo;
    wl_design_fema_in_init(&fi);
    fi.rho = sc->rho;
    fi.g = sc->g;
    fi.R = sc->R;
    fi.z = z;
    st = wl_design_fema(&fi, &fo, err);
    if (st == WL_OK) {
      results[n++] = fo.hydrostatic;
      results[n++] = fo.hydrodynamic;
      results[n++] = fo.impulsive;
    }
  }
  if (st == WL_OK && sc->h_bore > 0.0)
    st = wl_design_cch_surge(sc->rho, sc->g, WL_DESIGN_FEMA_SEDIMENT, sc->h_bore, z, &results[n++],
                             err);

  if (st != WL_OK) {
    wl_error_prefix(err, "scenario: ");
    return st;
  }
  *n_results = n;
  return WL_OK;
}
