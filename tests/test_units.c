/* test_units.c: quantity parsing and conversion against exact definitions
 * (1 ft = 0.3048 m, 1 in = 0.0254 m, 1 lb = 0.45359237 kg: the 1959
 * international yard and pound agreement) and seed 001's own conversions. */
#include "testutil.h"
#include "wallload/units.h"

#include <string.h>

static double si(const char *text, enum wl_dim dim) {
  struct wl_quantity q;
  struct wl_error err;
  wl_error_clear(&err);
  if (wl_units_parse(text, dim, &q, &err) != WL_OK) return NAN;
  return q.si;
}

static int rejects(const char *text, enum wl_dim dim, const char *must_say) {
  struct wl_quantity q;
  struct wl_error err;
  wl_error_clear(&err);
  return wl_units_parse(text, dim, &q, &err) == WL_EINPUT && strstr(err.msg, must_say) != NULL;
}

int main(void) {
  CHECK_REL(si("8 ft", WL_DIM_LENGTH), 2.4384, 1e-15, "8 ft = 8 x 0.3048 m exactly");
  /* Seed 001 (Charlesworth 1945 case): 56.5 ft = 17.22 m, 15-18 ft = 4.57-5.49 m. */
  CHECK_ABS(si("56.5 ft", WL_DIM_LENGTH), 17.22, 0.005, "seed 001: 56.5 ft (17.22 m)");
  CHECK_ABS(si("18 ft", WL_DIM_LENGTH), 5.49, 0.005, "seed 001: 18 ft (5.49 m)");
  CHECK_REL(si("32 lb", WL_DIM_MASS), 14.51495584, 1e-12, "32 lb = 32 x 0.45359237 kg exactly");
  CHECK_ABS(si("32 lb", WL_DIM_MASS), 14.5, 0.05, "seed 001: 32-pound (14.5 kg) charge");
  CHECK_REL(si("12 in", WL_DIM_LENGTH), si("1 ft", WL_DIM_LENGTH), 1e-15, "12 in = 1 ft");
  CHECK_REL(si("36 cm", WL_DIM_LENGTH), 0.36, 1e-15, "cm");
  CHECK_REL(si("177 kJ", WL_DIM_ENERGY), 177e3, 1e-15, "kJ");
  CHECK_REL(si("0.44 kJ/m", WL_DIM_ENERGY_LINEAR), 440.0, 1e-15, "kJ/m");
  CHECK_REL(si("1/5.7", WL_DIM_RATIO), 1.0 / 5.7, 1e-15, "slope 1:5.7");
  CHECK_REL(si("40 %", WL_DIM_RATIO), 0.4, 1e-15, "percent");
  CHECK_REL(si("40%", WL_DIM_RATIO), 0.4, 1e-15, "percent without space");
  CHECK_REL(si("1.025 g/cm^3", WL_DIM_DENSITY), 1025.0, 1e-12, "g/cm^3");
  CHECK_REL(si("32.174 ft/s^2", WL_DIM_ACCELERATION), 9.80664, 1e-5, "standard gravity in ft/s^2");
  CHECK_REL(si("2 min", WL_DIM_TIME), 120.0, 1e-15, "minutes");

  double back;
  struct wl_error err;
  wl_error_clear(&err);
  CHECK_TRUE(wl_units_from_si(14.51495584, WL_DIM_MASS, "lb", &back, &err) == WL_OK &&
                 fabs(back - 32.0) < 1e-9,
             "round trip kg -> lb");
  wl_error_clear(&err);
  CHECK_TRUE(wl_units_from_si(2.4384, WL_DIM_LENGTH, "ft", &back, &err) == WL_OK &&
                 fabs(back - 8.0) < 1e-12,
             "round trip m -> ft");

  CHECK_TRUE(rejects("0.5", WL_DIM_LENGTH, "without a unit"), "a length needs a unit");
  CHECK_TRUE(rejects("20 kg", WL_DIM_LENGTH, "a mass where a length"), "wrong dimension named");
  CHECK_TRUE(rejects("3 furlong", WL_DIM_LENGTH, "unknown unit 'furlong'"), "unknown unit");
  CHECK_TRUE(rejects("abc m", WL_DIM_LENGTH, "not a number"), "not a number");
  CHECK_TRUE(rejects("nan m", WL_DIM_LENGTH, "not a number"), "nan is not a value");
  CHECK_TRUE(rejects("inf m", WL_DIM_LENGTH, "not a number"), "inf is not a value");
  CHECK_TRUE(rejects("1/0", WL_DIM_RATIO, "non-zero denominator"), "division by zero");
  CHECK_TRUE(rejects("3 m", WL_DIM_NONE, "plain number"), "a count takes no unit");
  /* Load figures in US customary units, against NIST SP 811 (2008)
   * appendix B.9 factors: 1 lbf/ft = 14.593 90 N/m, 1 lbf = 4.448 222 N
   * (so 1 lbf ft/ft = 4.448 222 N m/m), 1 ft = 0.3048 m. */
  {
    struct wl_load_units u;
    CHECK_TRUE(wl_units_load_units("ft", &u) == 1 && !strcmp(u.force, "lbf/ft"),
               "a scenario in feet gets lbf/ft");
    CHECK_REL(1.0 / u.force_f, 14.59390, 1e-6, "1 lbf/ft = 14.59390 N/m (NIST SP 811)");
    CHECK_REL(1.0 / u.impulse_f, 14.59390, 1e-6, "1 lbf s/ft = 14.59390 N s/m");
    CHECK_REL(1.0 / u.moment_f, 4.448222, 1e-6, "1 lbf ft/ft = 4.448222 N m/m (NIST SP 811)");
    CHECK_REL(u.length_f * 0.3048, 1.0, 1e-15, "m -> ft");
    CHECK_TRUE(wl_units_load_units("in", &u) == 1, "inches: US customary figures too");
    CHECK_TRUE(wl_units_load_units("m", &u) == 0 && wl_units_load_units("", &u) == 0,
               "metres: no second set");
  }
  return TEST_RESULT();
}
