/* hydrostatic.c: still-water load on the wall [HYD]: p = rho g (D - z),
 * F = rho g D^2 / 2, M = rho g D^3 / 6 about the base, D = d + eta. */
#include "internal.h"

static const char CITE_HYD[] = "hydrostatics: F = rho g D^2/2 at D/3, M = rho g D^3/6 (exact)";

enum wl_status wl_design_hydrostatic(double rho, double g, double d, double eta,
                                     struct wl_design_result *out, struct wl_error *err) {
  enum wl_status st = check_water(rho, g, err);
  if (st == WL_OK) st = check_nonneg("still-water depth at the wall d [m]", d, err);
  if (st == WL_OK && !isfinite(eta))
    st = wl_error_set(err, WL_EINPUT, "design: water level above SWL eta [m]: found %g; must be "
                                      "finite", eta);
  if (st != WL_OK) return st;
  const double D = d + eta;
  if (!(D > 0.0))
    return wl_error_set(err, WL_EINPUT,
                        "design: water depth over the base d + eta [m]: found %g (d = %g, "
                        "eta = %g); must be positive",
                        D, d, eta);

  result_start(out, eta == 0.0 ? "hydrostatic" : "hydrostatic-level", CITE_HYD,
               WL_DESIGN_BASIS_TOTAL);
  out->force = rho * g * D * D / 2.0;
  out->moment = rho * g * D * D * D / 6.0;
  profile_add(&out->profile, 0.0, rho * g * D);
  profile_add(&out->profile, D, 0.0);
  result_totals(out, rho, g, d);
  result_note(out, 1, "exact: still water %.4g m deep over the base", D);
  return WL_OK;
}
