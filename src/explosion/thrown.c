/* thrown.c: the "thrown mass" initial condition of [S0] (section "New
 * approach to initial free surface condition", Fig. 9, Table 6): the water
 * missing from the crater, cut into 1, 3 or 5 (any n) equal-mass parts
 * launched with the kinetic energy of the explosion. The paper gives no
 * formula; the rule implemented here (mass, body, parts, velocity) is stated
 * in full in include/wallload/explosion.h. */
#include "wallload/explosion.h"

#include "check.h"

#include <gsl/gsl_math.h> /* M_PI, M_PI_2 */
#include <math.h>

enum wl_status wl_explosion_thrown_mass(enum wl_crater_shape shape, int dims, double rho,
                                        double eta0, double R, double vapor_mass, double *mass,
                                        struct wl_error *err) {
  double v_net = 0.0;
  enum wl_status st = wl_explosion_net_volume(shape, dims, eta0, R, &v_net, err);
  if (st == WL_OK) st = check_positive("crater depth eta0 [m]", eta0, err);
  if (st == WL_OK) st = check_positive("water density rho [kg/m^3]", rho, err);
  if (st == WL_OK) st = check_nonneg("vaporised water mass [kg or kg/m]", vapor_mass, err);
  if (st != WL_OK) return st;
  /* Water missing from the initial surface: crater volume less lip volume. */
  double missing = -rho * v_net;
  double m = missing - vapor_mass;
  if (!(m > 0.0))
    return wl_error_set(err, WL_EINPUT,
                        "explosion: thrown mass: the %s crater in %dD misses %g %s of water "
                        "and %g are vaporised, leaving nothing to throw; use the quadratic "
                        "crater (no lip) or a shape whose lip does not hold the crater water in "
                        "%dD, and a vaporised mass below the missing mass",
                        wl_explosion_shape_name(shape), dims, missing, dims == 2 ? "kg/m" : "kg",
                        vapor_mass, dims);
  *mass = m;
  return WL_OK;
}

enum wl_status wl_explosion_thrown_split(int dims, double rho, double rc, double mass,
                                         double energy, int n_parts, double spread,
                                         struct wl_explosion_part *parts, struct wl_error *err) {
  enum wl_status st = check_dims(dims, err);
  if (st == WL_OK) st = check_positive("water density rho [kg/m^3]", rho, err);
  if (st == WL_OK) st = check_positive("footprint radius rc [m]", rc, err);
  if (st == WL_OK) st = check_positive("thrown mass [kg or kg/m]", mass, err);
  if (st == WL_OK) st = check_nonneg("thrown kinetic energy [J or J/m]", energy, err);
  if (st == WL_OK && (n_parts < 1 || n_parts > WL_EXPLOSION_PARTS_MAX))
    st = wl_error_set(err, WL_EINPUT,
                      "explosion: number of thrown parts: found %d; valid is 1 to %d (the paper "
                      "uses 1, 3 and 5)",
                      n_parts, WL_EXPLOSION_PARTS_MAX);
  if (st == WL_OK && !(spread >= 0.0 && spread < M_PI_2))
    st = wl_error_set(err, WL_EINPUT,
                      "explosion: thrown spread angle: found %g rad; valid is 0 (all vertical) "
                      "up to, not including, pi/2",
                      spread);
  if (st == WL_OK && !parts)
    st = wl_error_set(err, WL_EINPUT,
                      "explosion: thrown parts: found NULL; pass an array of n_parts entries");
  if (st != WL_OK) return st;

  double speed = sqrt(2.0 * energy / mass); /* equal speed: sum m V^2/2 = E */
  double tan_spread = tan(spread);
  double area = dims == 2 ? 2.0 * rc : M_PI * rc * rc; /* footprint [m or m^2] */
  double height = mass / (rho * area);
  double n = (double)n_parts;
  for (int k = 0; k < n_parts; k++) {
    struct wl_explosion_part q;
    q.mass = mass / n;
    q.height = height;
    q.z = 0.5 * height;
    if (dims == 2) {
      double width = 2.0 * rc / n;
      q.s_in = -rc + k * width;
      q.s_out = k == n_parts - 1 ? rc : q.s_in + width;
      q.offset = 0.5 * (q.s_in + q.s_out);
    } else {
      /* equal areas: r_k = rc sqrt(k/n); a ring's offset halves its area */
      q.s_in = rc * sqrt(k / n);
      q.s_out = rc * sqrt((k + 1) / n);
      q.offset = k == 0 ? 0.0 : rc * sqrt((k + 0.5) / n);
    }
    /* lean outward: tan(theta) = (offset / rc) tan(spread) */
    double t = q.offset / rc * tan_spread;
    double c = 1.0 / sqrt(1.0 + t * t);
    q.u = speed * t * c;
    q.w = speed * c;
    parts[k] = q;
  }
  return WL_OK;
}
