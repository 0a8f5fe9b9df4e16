/* sainflou.c: Sainflou's standing-wave (clapotis) pressure on a vertical
 * wall, crest at the wall, simplified straight-line diagram [SAIN]: total
 * pressure rho g h + p2 at the bed, p1 at SWL, 0 at H + delta0 above SWL,
 * cut at the wall's crest. */
#include "internal.h"

static const char CITE_SAIN[] =
    "Sainflou (1928), simplified diagram as in SPM (1984) 7-3 / Goda (2000): delta0, p1, p2 "
    "(crest at wall)";

enum wl_status wl_design_sainflou(const struct wl_design_sainflou_in *in,
                                  struct wl_design_sainflou_out *out, struct wl_error *err) {
  enum wl_status st = check_water(in->rho, in->g, err);
  if (st == WL_OK) st = check_positive("still-water depth at the wall h [m]", in->h, err);
  if (st == WL_OK) st = check_positive("incident wave height H [m]", in->H, err);
  if (st == WL_OK) st = check_crest(in->hc, err);
  double L = 0.0;
  if (st == WL_OK) st = wavelength_of(in->T, in->L, in->h, in->g, &L, err);
  if (st != WL_OK) return st;

  const double rho = in->rho, g = in->g, h = in->h, H = in->H;
  const double kh = 2.0 * WL_PI * h / L;
  out->L = L;
  out->delta0 = WL_PI * H * H / L / tanh(kh);
  out->crest = H + out->delta0;
  out->p2 = rho * g * H / cosh(kh);
  out->p_bed = rho * g * h + out->p2;
  out->p1 = out->p_bed * out->crest / (h + out->crest);
  out->overtopped = in->hc < out->crest;

  struct wl_design_result *res = &out->result;
  result_start(res, "sainflou", CITE_SAIN, WL_DESIGN_BASIS_TOTAL);
  profile_add(&res->profile, 0.0, out->p_bed);
  if (!out->overtopped) {
    profile_add(&res->profile, h, out->p1);
    profile_add(&res->profile, h + out->crest, 0.0);
  } else if (in->hc > 0.0) {
    profile_add(&res->profile, h, out->p1);
    profile_add(&res->profile, h + in->hc, out->p1 * (1.0 - in->hc / out->crest));
  } else {
    profile_add(&res->profile, h, out->p1);
  }
  if (!out->overtopped) {
    /* one triangle from the bed to the clapotis crest */
    const double top = h + out->crest;
    res->force = out->p_bed * top / 2.0;
    res->moment = res->force * top / 3.0;
  } else {
    wl_design_profile_integrate(&res->profile, &res->force, &res->moment);
  }
  result_totals(res, rho, g, h);

  const double miche = WL_DESIGN_MICHE_COEF * tanh(kh);
  if (H > WL_DESIGN_BREAKING_RATIO * h)
    result_note(res, 0, "breaking: H/h = %.3g > %.2f; Sainflou is for non-breaking waves", H / h,
                WL_DESIGN_BREAKING_RATIO);
  else if (H / L > miche)
    result_note(res, 0, "too steep: H/L = %.3g > Miche limit 0.142 tanh(kh) = %.3g", H / L, miche);
  else if (out->overtopped)
    result_note(res, 0,
                "overtopped: crest %.3g m < clapotis crest H + delta0 = %.3g m above SWL; "
                "full reflection assumed",
                in->hc, out->crest);
  else
    result_note(res, 1, "non-breaking: H/h = %.3g <= %.2f, H/L = %.3g <= Miche %.3g", H / h,
                WL_DESIGN_BREAKING_RATIO, H / L, miche);
  return WL_OK;
}
