/* fema.c: tsunami loads on a wall per metre: FEMA P-646 (2012) Eqs 6-1,
 * 6-3, 6-5, 6-6, 6-7 [FEMA], and the CCH surge force [CCH]. */
#include "internal.h"

static const char CITE_FH[] =
    "FEMA P-646 (2012) Eq 6-1 Fh = rho_s g h_max^2/2, Eq 6-3 h_max = R - z, rho_s = 1.1 rho";
static const char CITE_FD[] =
    "FEMA P-646 (2012) Eq 6-5 Fd = rho_s Cd (h u^2)_max/2 per metre, Eq 6-6 (h u^2)_max; "
    "lever arm h_max/2 assumed";
static const char CITE_FS[] =
    "FEMA P-646 (2012) Eq 6-7 impulsive (bore) force Fs = 1.5 Fd; lever arm h_max/2 assumed";
static const char CITE_CCH[] =
    "CCH (2000) after Dames & Moore (1980): surge Fs = 4.5 rho_s g h^2 at h (UNCONFIRMED; not "
    "in FEMA P-646 2012)";

void wl_design_fema_in_init(struct wl_design_fema_in *in) {
  in->rho = 1000.0;
  in->g = WL_G_STANDARD;
  in->sediment = WL_DESIGN_FEMA_SEDIMENT;
  in->Cd = WL_DESIGN_FEMA_CD;
  in->R = NAN;
  in->z = NAN;
}

enum wl_status wl_design_fema(const struct wl_design_fema_in *in, struct wl_design_fema_out *out,
                              struct wl_error *err) {
  enum wl_status st = check_water(in->rho, in->g, err);
  if (st == WL_OK) st = check_positive("sediment factor rho_s / rho", in->sediment, err);
  if (st == WL_OK) st = check_positive("drag coefficient Cd", in->Cd, err);
  if (st == WL_OK) st = check_positive("design run-up elevation R [m]", in->R, err);
  if (st == WL_OK && !isfinite(in->z))
    st = wl_error_set(err, WL_EINPUT,
                      "design: elevation of the wall's base above SWL z [m]: found %g; must be "
                      "finite",
                      in->z);
  if (st != WL_OK) return st;

  const double g = in->g, R = in->R, z = in->z;
  const double rs = in->sediment * in->rho;
  const double d_w = z < 0.0 ? -z : 0.0;
  const int reached = z < R;
  const double zr = z / R;
  out->rho_s = rs;
  out->h_max = reached ? R - z : 0.0;
  out->hu2_max = reached ? g * R * R * (0.125 - 0.235 * zr + 0.11 * zr * zr) : 0.0;
  const double hm = out->h_max;

  struct wl_design_result *fh = &out->hydrostatic, *fd = &out->hydrodynamic, *fs = &out->impulsive;
  result_start(fh, "fema-hydrostatic", CITE_FH, WL_DESIGN_BASIS_TOTAL);
  result_start(fd, "fema-hydrodynamic", CITE_FD, WL_DESIGN_BASIS_DYNAMIC);
  result_start(fs, "fema-impulsive", CITE_FS, WL_DESIGN_BASIS_DYNAMIC);
  fh->force = rs * g * hm * hm / 2.0;
  fh->moment = fh->force * hm / 3.0;
  fd->force = 0.5 * rs * in->Cd * out->hu2_max;
  fd->moment = fd->force * hm / 2.0;
  fs->force = WL_DESIGN_FEMA_IMPULSIVE * fd->force;
  fs->moment = fs->force * hm / 2.0;
  if (reached) {
    profile_add(&fh->profile, 0.0, rs * g * hm);
    profile_add(&fh->profile, hm, 0.0);
  }
  result_totals(fh, in->rho, g, d_w);
  result_totals(fd, in->rho, g, d_w);
  result_totals(fs, in->rho, g, d_w);

  if (!reached) {
    result_note(fh, 0, "not reached: base z = %.3g m >= run-up R = %.3g m", z, R);
    result_note(fd, 0, "not reached: base z = %.3g m >= run-up R = %.3g m", z, R);
    result_note(fs, 0, "not reached: base z = %.3g m >= run-up R = %.3g m", z, R);
  } else {
    result_note(fh, 1, "hydrostatic at h_max = R - z = %.3g m", hm);
    if (z < 0.0) {
      result_note(fd, 0, "z/R = %.3g < 0: Eq 6-6 is for onshore ground, 0 <= z <= R", zr);
      result_note(fs, 0, "z/R = %.3g < 0: Eq 6-6 is for onshore ground, 0 <= z <= R", zr);
    } else {
      result_note(fd, 1, "0 <= z/R = %.3g <= 1 (Eq 6-6)", zr);
      result_note(fs, 1, "0 <= z/R = %.3g <= 1 (Eq 6-6); bore on a flooded site", zr);
    }
  }
  return WL_OK;
}

enum wl_status wl_design_cch_surge(double rho, double g, double sediment, double h_bore, double z,
                                   struct wl_design_result *out, struct wl_error *err) {
  enum wl_status st = check_water(rho, g, err);
  if (st == WL_OK) st = check_positive("sediment factor rho_s / rho", sediment, err);
  if (st == WL_OK) st = check_positive("bore depth at the wall h [m]", h_bore, err);
  if (st == WL_OK && !isfinite(z))
    st = wl_error_set(err, WL_EINPUT,
                      "design: elevation of the wall's base above SWL z [m]: found %g; must be "
                      "finite",
                      z);
  if (st != WL_OK) return st;

  const double rs = sediment * rho, h3 = 3.0 * h_bore;
  result_start(out, "cch-surge", CITE_CCH, WL_DESIGN_BASIS_TOTAL);
  out->force = WL_DESIGN_CCH_SURGE_COEF * rs * g * h_bore * h_bore;
  out->moment = out->force * h_bore;
  profile_add(&out->profile, 0.0, rs * g * h3);
  profile_add(&out->profile, h3, 0.0);
  result_totals(out, rho, g, z < 0.0 ? -z : 0.0);
  if (z < 0.0)
    result_note(out, 0, "base %.3g m below SWL: the surge force is for a bore on dry ground", -z);
  else
    result_note(out, 1, "bore %.3g m deep on dry ground (no stated limits, UNCONFIRMED)", h_bore);
  return WL_OK;
}
