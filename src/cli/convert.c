/* convert.c: `wallload convert`, the scenario front-end alone: charge weight
 * <-> crater <-> energy <-> equal-energy solitary wave, as a table with
 * units (SI, with feet and pounds beside the empirical formulae's inputs). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "wallload/explosion.h"
#include "wallload/units.h"
#include "wallload/waves.h"

static const char convert_usage[] =
    "usage: wallload convert SOURCE [--water-depth D] [OPTIONS]\n"
    "SOURCE (exactly one):\n"
    "  --charge W             charge weight of TNT (e.g. 32 lb, 14.5 kg)\n"
    "  --energy E             crater energy (e.g. 177 kJ; seed 001 eq 3)\n"
    "  --crater ETA0 R0       crater depth and radius (e.g. 2.07 m 8.28 m)\n"
    "  --solitary-height H    solitary wave height (needs --water-depth)\n"
    "OPTIONS:\n"
    "  --water-depth D        still-water depth (e.g. 8 ft); needed for the solitary wave\n"
    "  --coefficient C        Hmax r / W^0.54 in ft, lb (34 Whalin, 36 Le Mehaute; default 35)\n"
    "  --wave-fraction F      share of chemical energy making waves (default 40 %, a ceiling)\n"
    "  --density RHO          water density (default 1000 kg/m^3)\n";

struct convert_args {
  int n_sources;
  struct wl_quantity charge, energy, eta0, r0, height, depth, coef, fraction, density;
  int has_charge, has_energy, has_crater, has_height, has_depth;
};

static enum wl_status take(int argc, char **argv, int *i, int n, enum wl_dim dim,
                           struct wl_quantity *q, struct wl_error *err) {
  const char *opt = argv[*i];
  if (*i + n >= argc)
    return wl_error_set(err, WL_EUSAGE, "convert: %s needs a value (%s)\n%s", opt,
                        wl_units_valid(dim), convert_usage);
  /* "32 lb" may come as one argument or as two ("32" "lb"). */
  char text[128];
  const char *v = argv[++*i];
  if (dim != WL_DIM_NONE && dim != WL_DIM_RATIO && !strchr(v, ' ') && *i + 1 < argc &&
      argv[*i + 1][0] != '-') {
    struct wl_quantity probe;
    struct wl_error perr;
    wl_error_clear(&perr);
    if (wl_units_parse(v, dim, &probe, &perr) != WL_OK) {
      snprintf(text, sizeof text, "%s %s", v, argv[*i + 1]);
      ++*i;
      v = text;
    }
  }
  if (dim == WL_DIM_RATIO && *i + 1 < argc && !strcmp(argv[*i + 1], "%")) {
    snprintf(text, sizeof text, "%s %%", v);
    ++*i;
    v = text;
  }
  enum wl_status st = wl_units_parse(v, dim, q, err);
  if (st) wl_error_prefix(err, "convert: %s: ", opt);
  return st ? WL_EUSAGE : WL_OK;
}

static enum wl_status parse_args(int argc, char **argv, struct convert_args *a,
                                 struct wl_error *err) {
  memset(a, 0, sizeof *a);
  struct wl_error ignore;
  wl_error_clear(&ignore);
  wl_units_parse("35", WL_DIM_NONE, &a->coef, &ignore);
  wl_units_parse("40 %", WL_DIM_RATIO, &a->fraction, &ignore);
  wl_units_parse("1000 kg/m^3", WL_DIM_DENSITY, &a->density, &ignore);
  for (int i = 1; i < argc; i++) {
    const char *o = argv[i];
    enum wl_status st = WL_OK;
    if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
      fputs(convert_usage, stdout);
      return WL_EUSAGE + 100; /* handled: no error */
    } else if (!strcmp(o, "--charge")) {
      st = take(argc, argv, &i, 1, WL_DIM_MASS, &a->charge, err);
      a->has_charge = 1;
    } else if (!strcmp(o, "--energy")) {
      st = take(argc, argv, &i, 1, WL_DIM_ENERGY, &a->energy, err);
      a->has_energy = 1;
    } else if (!strcmp(o, "--crater")) {
      st = take(argc, argv, &i, 1, WL_DIM_LENGTH, &a->eta0, err);
      if (!st) st = take(argc, argv, &i, 1, WL_DIM_LENGTH, &a->r0, err);
      a->has_crater = 1;
    } else if (!strcmp(o, "--solitary-height")) {
      st = take(argc, argv, &i, 1, WL_DIM_LENGTH, &a->height, err);
      a->has_height = 1;
    } else if (!strcmp(o, "--water-depth")) {
      st = take(argc, argv, &i, 1, WL_DIM_LENGTH, &a->depth, err);
      a->has_depth = 1;
    } else if (!strcmp(o, "--coefficient")) {
      st = take(argc, argv, &i, 1, WL_DIM_NONE, &a->coef, err);
    } else if (!strcmp(o, "--wave-fraction")) {
      st = take(argc, argv, &i, 1, WL_DIM_RATIO, &a->fraction, err);
    } else if (!strcmp(o, "--density")) {
      st = take(argc, argv, &i, 1, WL_DIM_DENSITY, &a->density, err);
    } else {
      return wl_error_set(err, WL_EUSAGE, "convert: unknown option '%s'\n%s", o, convert_usage);
    }
    if (st) return st;
  }
  a->n_sources = a->has_charge + a->has_energy + a->has_crater + a->has_height;
  if (a->n_sources != 1)
    return wl_error_set(err, WL_EUSAGE, "convert: give exactly one source (found %d)\n%s",
                        a->n_sources, convert_usage);
  if (a->has_height && !a->has_depth)
    return wl_error_set(err, WL_EUSAGE, "convert: --solitary-height needs --water-depth");
  return WL_OK;
}

static void row(const char *what, double si, const char *unit, const char *beside,
                const char *source) {
  printf("  %-38s %13.6g %-6s %-18s %s\n", what, si, unit, beside, source);
}

static void print_chain(const struct wl_explosion_chain *ch, double fraction) {
  char b[64];
  printf("\nExplosion (crater with lip, seed 001 eq 1)\n");
  snprintf(b, sizeof b, "(%.5g lb)", ch->charge_kg / WL_LB_KG);
  row("charge weight W (TNT)", ch->charge_kg, "kg", b, "");
  snprintf(b, sizeof b, "(%.5g ft)", ch->r0 / WL_FT_M);
  row("crater radius R0", ch->r0, "m", b, "Van Dorn: R0 = 9.6 W^0.3 [ft, lb] (seed 001 eq 4)");
  snprintf(b, sizeof b, "(%.5g ft^2)", ch->hr / (WL_FT_M * WL_FT_M));
  char src[96];
  snprintf(src, sizeof src, "Hmax r / W^0.54 = %g [ft, lb] (seed 001 eqs 6-7)", ch->whalin_coef);
  row("Hmax r", ch->hr, "m^2", b, src);
  row("eta0 R0", ch->eta0_r0, "m^2", "", "eta0 R0 = 0.81 Hmax r (seed 001 eq 5)");
  snprintf(b, sizeof b, "(%.5g ft)", ch->eta0 / WL_FT_M);
  row("crater depth eta0", ch->eta0, "m", b, "");
  row("crater energy (axisymmetric)", ch->crater_energy, "J", "",
      "pi rho g eta0^2 R0^2 / 6 (seed 001 eq 3)");
  row("chemical energy", ch->chemical_energy, "J", "", "4.184 MJ per kg TNT");
  row("crater / chemical energy", 100 * ch->wave_fraction, "%", "", "implied wave share");
  snprintf(src, sizeof src, "%.0f %% of chemical energy (seed 000 eq 9; a ceiling)", 100 * fraction);
  row("cavity work", ch->cavity_work, "J", "", src);
  row("cavity radius", ch->cavity_radius, "m", "", "4 pi rho g a^3 (a + z)/3 (seed 000 eq 8)");
}

/* The 2D crater (plane lip, the mass-conserving form) of a chain, per metre. */
static double plane_energy(const struct wl_explosion_chain *ch, double rho, double g) {
  double e = NAN;
  struct wl_error ignore;
  wl_error_clear(&ignore);
  wl_explosion_energy(WL_CRATER_SHAPE_QUADRATIC_LIP_PLANE, 2, rho, g, ch->eta0, ch->r0, &e,
                      &ignore);
  return e;
}

static enum wl_status print_solitary(double H, double h, double rho, double g,
                                     struct wl_error *err) {
  struct wl_solitary sw;
  struct wl_wave_integrals wi, fo;
  enum wl_status st = wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, h, H, g, err);
  if (!st) st = wl_waves_solitary_integrals(&sw, rho, &wi, err);
  if (st) return st;
  wl_waves_solitary_closed_form(&sw, rho, &fo);
  char b[64];
  printf("\nSolitary wave (Grimshaw third order, seed 003 eqs 21-24), per metre of crest\n");
  snprintf(b, sizeof b, "(H/h = %.4g)", H / h);
  row("height H", H, "m", b, "");
  row("celerity c", wl_waves_solitary_celerity(&sw), "m/s", "", "seed 003 eq 23");
  snprintf(b, sizeof b, "(1st order %.5g)", fo.mass);
  row("mass", wi.mass, "kg/m", b, "integrated profile");
  snprintf(b, sizeof b, "(1st order %.5g)", fo.momentum);
  row("momentum", wi.momentum, "kg/s", b, "integrated velocity field");
  snprintf(b, sizeof b, "(1st order %.5g)", fo.energy);
  row("energy", wi.energy, "J/m", b, "integrated kinetic + potential");
  row("energy 0.958 rho g h^3", wl_waves_lh74_energy(rho, g, h), "J/m", "",
      "seed 001 eq 22: the HIGHEST wave on h, not this one");
  return WL_OK;
}

enum wl_status wl_cli_convert(int argc, char **argv, struct wl_error *err) {
  struct convert_args a;
  enum wl_status st = parse_args(argc, argv, &a, err);
  if (st == WL_EUSAGE + 100) return WL_OK;
  if (st) return st;
  const double g = WL_G_STANDARD, rho = a.density.si;
  struct wl_explosion_params ep;
  wl_explosion_params_default(&ep);
  ep.rho = rho;
  ep.g = g;
  ep.whalin_coef = a.coef.si;
  ep.wave_share = a.fraction.si;
  struct wl_explosion_chain ch;
  if (a.has_charge)
    st = wl_explosion_chain_from_charge(&ep, a.charge.si, &ch, err);
  else if (a.has_energy)
    st = wl_explosion_chain_from_energy(&ep, a.energy.si, &ch, err);
  else if (a.has_crater)
    st = wl_explosion_chain_from_energy(&ep, WL_PI * rho * g * pow(a.eta0.si * a.r0.si, 2) / 6.0,
                                        &ch, err);
  if (st) return st;

  printf("wallload convert (rho = %g kg/m^3, g = %g m/s^2)\n", rho, g);
  if (a.has_height) {
    st = print_solitary(a.height.si, a.depth.si, rho, g, err);
    if (st) return st;
    struct wl_solitary sw;
    struct wl_wave_integrals wi;
    wl_waves_solitary_init(&sw, WL_SOLITARY_GRIMSHAW, a.depth.si, a.height.si, g, err);
    wl_waves_solitary_integrals(&sw, rho, &wi, err);
    /* per-width: the 2D crater of equal energy per metre (W ~ E^(1/0.78)) */
    struct wl_explosion_chain unit;
    wl_explosion_chain_from_charge(&ep, WL_LB_KG, &unit, err);
    double w = WL_LB_KG * pow(wi.energy / plane_energy(&unit, rho, g),
                              1.0 / (2.0 * WL_WHALIN_EXP - WL_VANDORN_EXP));
    st = wl_explosion_chain_from_charge(&ep, w, &ch, err);
    if (st) return st;
    printf("\nEqual energy, per metre of crest (2D crater eta0 (3(x/R0)^2 - 1), mass-conserving):\n"
           "  %.6g J/m of the solitary wave = (4/5) rho g eta0^2 R0 of the crater\n",
           wi.energy);
    print_chain(&ch, a.fraction.si);
    struct wl_explosion_chain seed;
    st = wl_explosion_chain_from_energy(&ep, wl_waves_lh74_energy(rho, g, a.depth.si), &seed, err);
    if (st) return st;
    printf("\nEqual energy as seed 001 Table 4 (0.958 rho g h^3 taken as the 3D crater energy):\n");
    print_chain(&seed, a.fraction.si);
    return WL_OK;
  }
  print_chain(&ch, a.fraction.si);
  if (a.has_depth) {
    double e2 = plane_energy(&ch, rho, g);
    printf("\nCrater in a 2D flume (plane lip, mass-conserving)\n");
    row("energy per metre of crest", e2, "J/m", "", "(4/5) rho g eta0^2 R0");
    if (ch.eta0 >= a.depth.si)
      printf("  note: the crater (eta0 = %.4g m) is deeper than the water (%.4g m)\n", ch.eta0,
             a.depth.si);
    double H;
    struct wl_error herr;
    wl_error_clear(&herr);
    if (wl_waves_solitary_height_from_energy(e2, a.depth.si, g, rho, &H, &herr) == WL_OK) {
      printf("\nSolitary wave of equal energy per metre on %.4g m of water:\n", a.depth.si);
      st = print_solitary(H, a.depth.si, rho, g, err);
      if (st) return st;
    } else {
      printf("\nNo solitary wave on %.4g m of water carries %.5g J/m: %s\n", a.depth.si, e2,
             herr.msg);
    }
  }
  return WL_OK;
}
