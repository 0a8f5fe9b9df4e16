/* goda.c: Goda's wave pressure on an upright wall [GODA], with the impulsive
 * pressure coefficient of Takahashi, Tanimoto & Shimosako (1994) [TAK].
 * Equations as listed in design.h, in the order they are computed. */
#include "internal.h"

static const char CITE_GODA[] =
    "Goda (2000) Random Seas and Design of Maritime Structures, 2nd ed., ch. 4 (Goda 1974): "
    "eta*, p1, p3, p4, pu, P, Mp";
static const char CITE_TAK[] =
    "Goda (2000) ch. 4 with alpha* = max(alpha2, alpha_I), Takahashi, Tanimoto & Shimosako "
    "(1994) (CEM Table VI-5-54, UNCONFIRMED)";

void wl_design_goda_in_init(struct wl_design_goda_in *in) {
  in->rho = 1000.0;
  in->g = WL_G_STANDARD;
  in->h = in->d = in->h_prime = NAN;
  in->hc = INFINITY;
  in->hb = 0.0;
  in->Hmax = NAN;
  in->T = NAN;
  in->L = 0.0;
  in->beta = 0.0;
  in->lambda1 = in->lambda2 = in->lambda3 = 1.0;
  in->impulsive = 0;
  in->BM = 0.0;
  in->B = 0.0;
}

static enum wl_status check_in(const struct wl_design_goda_in *in, struct wl_error *err) {
  enum wl_status st = check_water(in->rho, in->g, err);
  if (st == WL_OK) st = check_positive("depth in front of the wall h [m]", in->h, err);
  if (st == WL_OK) st = check_positive("depth above the berm d [m]", in->d, err);
  if (st == WL_OK) st = check_positive("design wave height Hmax [m]", in->Hmax, err);
  if (st != WL_OK) return st;
  if (in->d > in->h)
    return wl_error_set(err, WL_EINPUT,
                        "design: depth above the berm d [m]: found %g > h = %g; the berm "
                        "cannot be deeper than the sea bed (d <= h; d = h on a plain bed)",
                        in->d, in->h);
  if (!(in->h_prime >= in->d && in->h_prime <= in->h))
    return wl_error_set(err, WL_EINPUT,
                        "design: depth of the wall's base h' [m]: found %g; must lie in "
                        "[d, h] = [%g, %g]",
                        in->h_prime, in->d, in->h);
  st = check_crest(in->hc, err);
  if (st == WL_OK && in->hb != 0.0 && !(isfinite(in->hb) && in->hb >= in->d))
    st = wl_error_set(err, WL_EINPUT,
                      "design: depth 5 H1/3 seaward hb [m]: found %g; must be >= d = %g, or 0 "
                      "for h",
                      in->hb, in->d);
  if (st == WL_OK && !(in->beta >= 0.0 && in->beta <= WL_PI / 2.0))
    st = wl_error_set(err, WL_EINPUT,
                      "design: wave angle to the wall's normal beta [rad]: found %g; must lie "
                      "in [0, pi/2]",
                      in->beta);
  if (st == WL_OK) st = check_positive("Goda lambda1", in->lambda1, err);
  if (st == WL_OK) st = check_positive("Goda lambda2", in->lambda2, err);
  if (st == WL_OK) st = check_positive("Goda lambda3", in->lambda3, err);
  if (st == WL_OK) st = check_nonneg("berm width BM [m]", in->BM, err);
  if (st == WL_OK) st = check_nonneg("base width B [m]", in->B, err);
  return st;
}

enum wl_status wl_design_goda(const struct wl_design_goda_in *in, struct wl_design_goda_out *out,
                              struct wl_error *err) {
  enum wl_status st = check_in(in, err);
  double L = 0.0;
  if (st == WL_OK) st = wavelength_of(in->T, in->L, in->h, in->g, &L, err);
  if (st != WL_OK) return st;

  const double rho = in->rho, g = in->g, h = in->h, d = in->d, hp = in->h_prime;
  const double H = in->Hmax;
  const double hb = in->hb != 0.0 ? in->hb : h;
  const double cb = cos(in->beta);
  out->L = L;

  out->eta_star = 0.75 * (1.0 + cb) * in->lambda1 * H;
  const double x = 4.0 * WL_PI * h / L; /* sinh overflows to inf for deep water: ratio -> 0 */
  const double r = x / sinh(x);
  out->alpha1 = 0.6 + 0.5 * r * r;
  out->alpha2 = fmin((hb - d) / (3.0 * hb) * (H / d) * (H / d), 2.0 * d / H);
  const double kh = 2.0 * WL_PI * h / L;
  out->alpha3 = 1.0 - hp / h * (1.0 - 1.0 / cosh(kh));

  /* [TAK] */
  const double bm = in->BM / L - 0.12, dh = (h - d) / h - 0.6;
  out->delta11 = 0.93 * bm + 0.36 * dh;
  out->delta22 = -0.36 * bm + 0.93 * dh;
  const double delta1 = out->delta11 <= 0.0 ? 20.0 * out->delta11 : 15.0 * out->delta11;
  const double delta2 = out->delta22 <= 0.0 ? 4.9 * out->delta22 : 3.0 * out->delta22;
  out->alpha_I1 = out->delta22 <= 0.0 ? cos(delta2) / cosh(delta1)
                                      : 1.0 / (cosh(delta1) * sqrt(cosh(delta2)));
  out->alpha_I0 = H <= 2.0 * d ? H / d : 2.0;
  out->alpha_I = out->alpha_I0 * out->alpha_I1;
  out->alpha_star = in->impulsive ? fmax(out->alpha2, out->alpha_I) : out->alpha2;

  const double rgH = rho * g * H;
  const double mix = in->lambda1 * out->alpha1 + in->lambda2 * out->alpha_star * cb * cb;
  out->p1 = 0.5 * (1.0 + cb) * mix * rgH;
  out->p2 = out->p1 / cosh(kh);
  out->p3 = out->alpha3 * out->p1;
  out->hc_star = fmin(out->eta_star, in->hc);
  out->alpha4 = 1.0 - out->hc_star / out->eta_star;
  out->p4 = out->alpha4 * out->p1;
  out->pu = 0.5 * (1.0 + cb) * out->alpha1 * out->alpha3 * in->lambda3 * rgH;

  const double p1 = out->p1, p3 = out->p3, p4 = out->p4, hs = out->hc_star;
  out->P = 0.5 * (p1 + p3) * hp + 0.5 * (p1 + p4) * hs;
  out->Mp = (2.0 * p1 + p3) * hp * hp / 6.0 + 0.5 * (p1 + p4) * hp * hs +
            (p1 + 2.0 * p4) * hs * hs / 6.0;
  if (in->B > 0.0) {
    out->U = 0.5 * out->pu * in->B;
    out->Mu = 2.0 / 3.0 * out->U * in->B;
  } else {
    out->U = out->Mu = NAN;
  }

  struct wl_design_result *res = &out->result;
  result_start(res, in->impulsive ? "goda-takahashi" : "goda", in->impulsive ? CITE_TAK : CITE_GODA,
               WL_DESIGN_BASIS_WAVE);
  res->force = out->P;
  res->moment = out->Mp;
  res->uplift_p = out->pu;
  profile_add(&res->profile, 0.0, p3);
  profile_add(&res->profile, hp, p1);
  if (hs > 0.0) profile_add(&res->profile, hp + hs, p4);
  result_totals(res, rho, g, hp);

  if (in->impulsive)
    result_note(res, 1, "alpha* = max(alpha2 %.3g, alpha_I %.3g): %s governs; h/L = %.3g",
                out->alpha2, out->alpha_I, out->alpha_I > out->alpha2 ? "alpha_I" : "alpha2",
                h / L);
  else if (out->alpha_I > out->alpha2)
    result_note(res, 0,
                "impulsive breaking: Takahashi alpha_I = %.3g > alpha2 = %.3g, plain Goda "
                "under-predicts",
                out->alpha_I, out->alpha2);
  else
    result_note(res, 1, "no impulsive breaking: Takahashi alpha_I = %.3g <= alpha2 = %.3g; "
                        "h/L = %.3g",
                out->alpha_I, out->alpha2, h / L);
  return WL_OK;
}
