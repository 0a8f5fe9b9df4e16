/* units.h: quantities with units, converted to SI at the boundary.
 *
 * A scenario writes `0.36 m`, `8 ft`, `32 lb`, `177 kJ`, `1/5.7`, `40 %`;
 * inside wallload everything is SI (m, kg, s, J). The user's value and unit
 * are kept beside the SI value so `check` and reports can show both.
 *
 * Exact definitions: 1 ft = 0.3048 m, 1 in = 0.0254 m (international yard and
 * pound agreement, 1959); 1 lb = 0.45359237 kg (same agreement). Charge
 * weights in pounds are pounds (mass) of TNT. */
#ifndef WALLLOAD_UNITS_H
#define WALLLOAD_UNITS_H

#include "wallload/error.h"

#define WL_FT_M 0.3048          /* metres per international foot (exact) */
#define WL_IN_M 0.0254          /* metres per inch (exact) */
#define WL_LB_KG 0.45359237     /* kilograms per avoirdupois pound (exact) */
#define WL_G_LBF 9.80665        /* standard gravity of the pound-force (exact, CGPM 1901) */
#define WL_TNT_J_PER_KG 4.184e6 /* TNT equivalent: 1 kg TNT = 4.184 MJ (by definition) */
#define WL_PI 3.14159265358979323846 /* C11 has no M_PI */
#define WL_G_STANDARD 9.81      /* gravity used by the seeds and REFERENCES [m/s^2] */

/* What a quantity measures. */
enum wl_dim {
  WL_DIM_NONE,          /* a plain number, no unit allowed */
  WL_DIM_RATIO,         /* dimensionless: 0.2, 1/5.7, 20 % */
  WL_DIM_LENGTH,        /* m */
  WL_DIM_MASS,          /* kg */
  WL_DIM_TIME,          /* s */
  WL_DIM_ENERGY,        /* J */
  WL_DIM_ENERGY_LINEAR, /* J/m (energy per metre of crest) */
  WL_DIM_DENSITY,       /* kg/m^3 */
  WL_DIM_ACCELERATION,  /* m/s^2 */
  WL_DIM_VELOCITY,      /* m/s */
};

struct wl_quantity {
  double si;         /* value in SI */
  double value;      /* value as written, in the user's unit */
  char unit[16];     /* the user's unit as written ("" when none) */
  enum wl_dim dim;
};

/* Parse `text` ("0.36 m", "1/5.7", "40 %") as a quantity of dimension `dim`.
 * A bare number is accepted for WL_DIM_NONE and WL_DIM_RATIO only; every other
 * dimension needs a unit, so "0.36" for a depth is an error (which unit was
 * meant is not guessed). Returns WL_OK and fills *q, or WL_EINPUT with a
 * message "found '<text>'; <what is valid>" (no position: the caller prefixes
 * file:line:col and key). */
enum wl_status wl_units_parse(const char *text, enum wl_dim dim, struct wl_quantity *q,
                              struct wl_error *err);

/* The units accepted for a dimension, as a comma-separated list for messages. */
const char *wl_units_valid(enum wl_dim dim);

/* The SI unit symbol of a dimension ("m", "J/m", "" for ratios). */
const char *wl_units_si_symbol(enum wl_dim dim);

/* Convert an SI value to `unit` (one accepted for `dim`). Returns WL_EINPUT
 * for a unit not accepted for dim. */
enum wl_status wl_units_from_si(double si, enum wl_dim dim, const char *unit, double *out,
                                struct wl_error *err);

/* The units a design's wall loads are quoted in besides SI. A scenario that
 * writes its lengths in feet or inches gets US customary figures, per foot
 * of wall: force lbf/ft, impulse lbf s/ft, moment lbf ft/ft, run-up ft
 * (1 lbf = 0.45359237 kg x 9.80665 m/s^2 = 4.4482216152605 N, exact);
 * multiply the SI value by the factor. */
struct wl_load_units {
  const char *force, *impulse, *moment, *length;       /* unit symbols */
  double force_f, impulse_f, moment_f, length_f;       /* from N/m, N s/m, N m/m, m */
};

/* 1 and *u filled when length_unit (as the user wrote a length: "ft",
 * "in", "m", ...) is a US customary one; 0 otherwise (the SI figures are
 * the user's). */
int wl_units_load_units(const char *length_unit, struct wl_load_units *u);

#endif
