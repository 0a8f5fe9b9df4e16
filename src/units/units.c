/* units.c: the unit table and the quantity parser. */
#include "wallload/units.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct unit_def {
  enum wl_dim dim;
  const char *symbol;
  double to_si; /* SI value of one unit */
};

/* The first entry of each dimension is its SI unit. */
static const struct unit_def unit_table[] = {
    {WL_DIM_RATIO, "%", 0.01},
    {WL_DIM_LENGTH, "m", 1.0},
    {WL_DIM_LENGTH, "cm", 0.01},
    {WL_DIM_LENGTH, "mm", 0.001},
    {WL_DIM_LENGTH, "km", 1000.0},
    {WL_DIM_LENGTH, "ft", WL_FT_M},
    {WL_DIM_LENGTH, "in", WL_IN_M},
    {WL_DIM_MASS, "kg", 1.0},
    {WL_DIM_MASS, "g", 0.001},
    {WL_DIM_MASS, "t", 1000.0},
    {WL_DIM_MASS, "lb", WL_LB_KG},
    {WL_DIM_TIME, "s", 1.0},
    {WL_DIM_TIME, "ms", 0.001},
    {WL_DIM_TIME, "min", 60.0},
    {WL_DIM_ENERGY, "J", 1.0},
    {WL_DIM_ENERGY, "kJ", 1e3},
    {WL_DIM_ENERGY, "MJ", 1e6},
    {WL_DIM_ENERGY, "GJ", 1e9},
    {WL_DIM_ENERGY_LINEAR, "J/m", 1.0},
    {WL_DIM_ENERGY_LINEAR, "kJ/m", 1e3},
    {WL_DIM_ENERGY_LINEAR, "MJ/m", 1e6},
    {WL_DIM_DENSITY, "kg/m^3", 1.0},
    {WL_DIM_DENSITY, "kg/m3", 1.0},
    {WL_DIM_DENSITY, "g/cm^3", 1000.0},
    {WL_DIM_ACCELERATION, "m/s^2", 1.0},
    {WL_DIM_ACCELERATION, "m/s2", 1.0},
    {WL_DIM_ACCELERATION, "ft/s^2", WL_FT_M},
    {WL_DIM_VELOCITY, "m/s", 1.0},
    {WL_DIM_VELOCITY, "ft/s", WL_FT_M},
    {WL_DIM_VELOCITY, "km/h", 1.0 / 3.6},
};
enum { N_UNITS = sizeof unit_table / sizeof unit_table[0] };

const char *wl_units_valid(enum wl_dim dim) {
  switch (dim) {
  case WL_DIM_NONE: return "a plain number";
  case WL_DIM_RATIO: return "a number, a fraction like 1/5.7, or a percentage like 40 %";
  case WL_DIM_LENGTH: return "a number with a length unit: m, cm, mm, km, ft, in";
  case WL_DIM_MASS: return "a number with a mass unit: kg, g, t, lb";
  case WL_DIM_TIME: return "a number with a time unit: s, ms, min";
  case WL_DIM_ENERGY: return "a number with an energy unit: J, kJ, MJ, GJ";
  case WL_DIM_ENERGY_LINEAR: return "a number with an energy-per-width unit: J/m, kJ/m, MJ/m";
  case WL_DIM_DENSITY: return "a number with a density unit: kg/m^3, g/cm^3";
  case WL_DIM_ACCELERATION: return "a number with an acceleration unit: m/s^2, ft/s^2";
  case WL_DIM_VELOCITY: return "a number with a velocity unit: m/s, ft/s, km/h";
  }
  return "?";
}

int wl_units_load_units(const char *length_unit, struct wl_load_units *u) {
  if (!length_unit || (strcmp(length_unit, "ft") && strcmp(length_unit, "in"))) return 0;
  const double lbf = WL_LB_KG * WL_G_LBF; /* N */
  u->force = "lbf/ft";
  u->impulse = "lbf s/ft";
  u->moment = "lbf ft/ft";
  u->length = "ft";
  u->force_f = WL_FT_M / lbf;   /* N/m -> lbf/ft */
  u->impulse_f = WL_FT_M / lbf; /* N s/m -> lbf s/ft */
  u->moment_f = 1.0 / lbf;      /* N m/m = N -> lbf ft/ft = lbf */
  u->length_f = 1.0 / WL_FT_M;  /* m -> ft */
  return 1;
}

const char *wl_units_si_symbol(enum wl_dim dim) {
  for (int i = 0; i < N_UNITS; i++)
    if (unit_table[i].dim == dim && dim != WL_DIM_RATIO) return unit_table[i].symbol;
  return "";
}

static const struct unit_def *find_unit(enum wl_dim dim, const char *sym) {
  for (int i = 0; i < N_UNITS; i++)
    if (unit_table[i].dim == dim && strcmp(unit_table[i].symbol, sym) == 0) return &unit_table[i];
  return NULL;
}

/* Which dimension a unit symbol belongs to, to say "a mass where a length was
 * expected" instead of only "unknown unit". */
static const struct unit_def *find_any_unit(const char *sym) {
  for (int i = 0; i < N_UNITS; i++)
    if (strcmp(unit_table[i].symbol, sym) == 0) return &unit_table[i];
  return NULL;
}

static const char *dim_name(enum wl_dim dim) {
  switch (dim) {
  case WL_DIM_NONE: return "number";
  case WL_DIM_RATIO: return "ratio";
  case WL_DIM_LENGTH: return "length";
  case WL_DIM_MASS: return "mass";
  case WL_DIM_TIME: return "time";
  case WL_DIM_ENERGY: return "energy";
  case WL_DIM_ENERGY_LINEAR: return "energy per width";
  case WL_DIM_DENSITY: return "density";
  case WL_DIM_ACCELERATION: return "acceleration";
  case WL_DIM_VELOCITY: return "velocity";
  }
  return "?";
}

/* strtod that accepts only a complete finite number prefix. */
static int parse_number(const char *s, double *out, const char **end) {
  errno = 0;
  char *e;
  double v = strtod(s, &e);
  if (e == s || errno == ERANGE || !isfinite(v)) return 0;
  /* strtod accepts "inf", "nan" and hex; a scenario value must be decimal. */
  for (const char *p = s; p < e; p++)
    if (!(isdigit((unsigned char)*p) || *p == '.' || *p == '-' || *p == '+' || *p == 'e' ||
          *p == 'E'))
      return 0;
  *out = v;
  *end = e;
  return 1;
}

enum wl_status wl_units_parse(const char *text, enum wl_dim dim, struct wl_quantity *q,
                              struct wl_error *err) {
  memset(q, 0, sizeof *q);
  q->dim = dim;
  const char *s = text;
  while (isspace((unsigned char)*s)) s++;
  double v;
  const char *rest;
  if (!parse_number(s, &v, &rest))
    return wl_error_set(err, WL_EINPUT, "found '%s', which is not a number; expected %s", text,
                        wl_units_valid(dim));
  while (isspace((unsigned char)*rest)) rest++;

  /* A ratio may be written n/d (the 1/5.7 of a slope). */
  if (dim == WL_DIM_RATIO && *rest == '/') {
    double d;
    const char *r2;
    const char *ds = rest + 1;
    while (isspace((unsigned char)*ds)) ds++;
    if (!parse_number(ds, &d, &r2) || d == 0.0)
      return wl_error_set(err, WL_EINPUT, "found '%s'; expected %s (with a non-zero denominator)",
                          text, wl_units_valid(dim));
    while (isspace((unsigned char)*r2)) r2++;
    if (*r2)
      return wl_error_set(err, WL_EINPUT, "found '%s', with '%s' after the fraction; expected %s",
                          text, r2, wl_units_valid(dim));
    q->value = v / d;
    q->si = v / d;
    return WL_OK;
  }

  size_t n = strlen(rest);
  while (n > 0 && isspace((unsigned char)rest[n - 1])) n--;
  if (n == 0) {
    if (dim == WL_DIM_NONE || dim == WL_DIM_RATIO) {
      q->value = q->si = v;
      return WL_OK;
    }
    return wl_error_set(err, WL_EINPUT, "found '%s' without a unit; expected %s", text,
                        wl_units_valid(dim));
  }
  char sym[sizeof q->unit];
  if (n >= sizeof sym)
    return wl_error_set(err, WL_EINPUT, "found '%s', whose unit is not known; expected %s", text,
                        wl_units_valid(dim));
  memcpy(sym, rest, n);
  sym[n] = '\0';
  if (dim == WL_DIM_NONE)
    return wl_error_set(err, WL_EINPUT, "found '%s'; expected a plain number without a unit",
                        text);
  const struct unit_def *u = find_unit(dim, sym);
  if (!u) {
    const struct unit_def *other = find_any_unit(sym);
    if (other)
      return wl_error_set(err, WL_EINPUT, "found '%s', a %s where a %s is expected; expected %s",
                          text, dim_name(other->dim), dim_name(dim), wl_units_valid(dim));
    return wl_error_set(err, WL_EINPUT, "found '%s', with unknown unit '%s'; expected %s", text,
                        sym, wl_units_valid(dim));
  }
  q->value = v;
  q->si = v * u->to_si;
  memcpy(q->unit, sym, n + 1);
  return WL_OK;
}

enum wl_status wl_units_from_si(double si, enum wl_dim dim, const char *unit, double *out,
                                struct wl_error *err) {
  if ((dim == WL_DIM_RATIO || dim == WL_DIM_NONE) && (!unit || !*unit)) {
    *out = si;
    return WL_OK;
  }
  const struct unit_def *u = find_unit(dim, unit ? unit : "");
  if (!u)
    return wl_error_set(err, WL_EINPUT, "unit '%s' is not a %s unit; expected %s",
                        unit ? unit : "", dim_name(dim), wl_units_valid(dim));
  *out = si / u->to_si;
  return WL_OK;
}
