/* scenario.h: the scenario file (YAML) as typed, validated values.
 *
 * The schema is a table in src/scenario/schema.c: every key, its type, unit
 * dimension, valid range or choices and default. Parsing walks the YAML node
 * tree against that table, so an unknown key, a wrong type, a bad unit or an
 * out-of-range value is reported with file:line:column, the key's path, what
 * was found and what is valid. Cross-field rules (the slope must start before
 * the wall, a solitary wave cannot be higher than 0.78 h, ...) are checked
 * after all keys are read, before any computation.
 *
 * Every value remembers where it came from (line/column, or "default"), so
 * `wallload check` can print the resolved scenario with each default made
 * explicit and the user's units beside the SI value. */
#ifndef WALLLOAD_SCENARIO_H
#define WALLLOAD_SCENARIO_H

#include <stdio.h>

#include "wallload/error.h"
#include "wallload/units.h"

enum {
  WL_SCENARIO_MAX_BED = 16,
  WL_SCENARIO_MAX_GAUGES = 32,
  WL_SCENARIO_MAX_LEVELS = 8,
  WL_SCENARIO_MAX_REALISATIONS = 16, /* resolution.realisations */
  /* Reader limits (wl_scenario_parse): a scenario is a few kilobytes and
   * nests its collections 3 deep (loads.solitary; a list of maps under
   * bathymetry or gauges; resolution.convergence). libyaml has no limits of
   * its own, and its cost grows with the square of the flow nesting ('['
   * '{': 7 s for 50000 levels) and of the anchors of a document (&name:
   * 22 s for 95000 in 0.9 MiB). */
  WL_SCENARIO_MAX_BYTES = 1 << 20,
  WL_SCENARIO_MAX_DEPTH = 64,
  WL_SCENARIO_MAX_ANCHORS = 256,
  /* A sweep (the `sweep:` section): values per swept parameter, and cases in
   * all (their product). 32 values span a parameter finely enough for an
   * envelope; 4096 cases are days of GPU time. */
  WL_SCENARIO_MAX_SWEEP_VALUES = 32,
  WL_SCENARIO_MAX_SWEEP_CASES = 4096,
};

/* One scalar of the scenario: number with unit, enumeration choice or text. */
struct wl_scenario_value {
  int given;            /* 1: written in the file; 0: the default */
  int line, col;        /* 1-based position in the file; 0 for defaults */
  int is_auto;          /* the value is the word "auto" (resolved by plan) */
  int choice;           /* enumerations: index into the key's choices */
  struct wl_quantity q; /* numbers: SI value and the value/unit as written */
  char text[128];       /* the scalar as written (or the default's text) */
};

/* Choices of the enumerated keys; the order matches the schema's names. */
enum wl_solitary_theory_choice { WL_THEORY_GRIMSHAW, WL_THEORY_BOUSSINESQ, WL_THEORY_EXACT };
enum wl_generation_choice { WL_GENERATION_PADDLE, WL_GENERATION_INITIAL };
enum wl_shape_choice { WL_SHAPE_QUADRATIC, WL_SHAPE_QUADRATIC_LIP, WL_SHAPE_QUARTIC_LIP };
enum wl_lip_form_choice { WL_LIP_AUTO, WL_LIP_PLANE, WL_LIP_AXISYMMETRIC };
enum wl_energy_basis_choice { WL_BASIS_PER_WIDTH, WL_BASIS_SEED001 };
enum wl_explosion_model_choice { WL_MODEL_CRATER, WL_MODEL_THROWN_MASS };
enum wl_backend_choice { WL_BACKEND_AUTO, WL_BACKEND_CPU, WL_BACKEND_CUDA };
enum wl_viscosity_choice { WL_VISCOSITY_ARTIFICIAL, WL_VISCOSITY_LAMINAR };
enum wl_integrator_choice { WL_INTEGRATOR_SYMPLECTIC, WL_INTEGRATOR_VERLET };
enum wl_boundary_choice { WL_BOUNDARY_ADAMI, WL_BOUNDARY_DBC };
/* What closes the flume behind the seawall: a wall, or a damping zone over
 * the far half of the land that brings overtopping water to rest. */
enum wl_far_end_choice { WL_FAR_END_WALL, WL_FAR_END_DAMPING };
/* run.still_reference (plan.h: the still-water reference run) */
enum wl_still_reference_choice { WL_STILL_REF_AUTO, WL_STILL_REF_ON, WL_STILL_REF_OFF };
/* 3D: whether half the width is modelled, with a symmetry plane on the
 * centreline (auto: when the width is an even number of rows of dp; every
 * flume scene is symmetric about the centreline). */
enum wl_symmetry_choice { WL_SYMMETRY_AUTO, WL_SYMMETRY_NONE, WL_SYMMETRY_CENTRELINE };
/* 3D: the flume's side walls as mirror planes (free slip) or as layers of
 * dynamic boundary particles. */
enum wl_side_wall_choice { WL_SIDE_WALLS_FREE_SLIP, WL_SIDE_WALLS_PARTICLES };

struct wl_scenario_bed {
  struct wl_scenario_value from;  /* x where this segment starts [m] */
  struct wl_scenario_value slope; /* rise over run of the bed from `from` on */
};

struct wl_scenario_gauge {
  struct wl_scenario_value name;
  struct wl_scenario_value x; /* [m] from the paddle */
};

/* The parameters a sweep can vary, in the order of the schema's sweep keys. */
enum wl_sweep_param {
  WL_SWEEP_CHARGE,          /* loads.explosion.charge [kg] */
  WL_SWEEP_ENERGY,          /* loads.explosion.energy [J/m or J] */
  WL_SWEEP_STANDOFF,        /* wall.x - loads.explosion.at: the explosion's distance from the
                               wall's face [m] */
  WL_SWEEP_DEPTH,           /* water.depth [m] */
  WL_SWEEP_SOLITARY_HEIGHT, /* loads.solitary.height [m] */
  WL_SWEEP_N_PARAMS
};

/* One swept parameter: its values as written in a list, or generated from
 * a range ({from, to, count, spacing}); each value's text is what a case's
 * scenario gets, and its q what that text parses to. */
struct wl_scenario_sweep_axis {
  int present;
  int line, col; /* of the parameter's key in the file */
  int is_range;  /* 1: generated from {from, to, count, spacing} */
  int n_values;
  struct wl_scenario_value values[WL_SCENARIO_MAX_SWEEP_VALUES];
};

struct wl_scenario {
  char path[512];   /* the file, as given */
  char *text;       /* the whole file (stored with the results); owned */
  size_t text_len;

  struct wl_scenario_value name, description;
  struct {
    struct wl_scenario_value depth, density, gravity;
  } water;
  struct {
    struct wl_scenario_value dimensions, length, width, far_end, symmetry, side_walls;
  } domain;
  int n_bed;
  struct wl_scenario_bed bed[WL_SCENARIO_MAX_BED];
  int bed_given;
  struct {
    struct wl_scenario_value x, height, probes;
  } wall;
  int n_gauges;
  struct wl_scenario_gauge gauges[WL_SCENARIO_MAX_GAUGES];
  struct {
    int present;
    struct wl_scenario_value height, theory, generation, at;
  } solitary;
  struct {
    int present;
    /* exactly one source: charge, energy (a number or "same-as-solitary") or
     * crater (eta0 and r0) */
    struct wl_scenario_value charge, energy, eta0, r0;
    struct wl_scenario_value at, shape, lip_form, energy_basis, coefficient, wave_fraction,
        model, thrown_parts;
  } explosion;
  struct {
    struct wl_scenario_value dp, particles_per_height, target_error;
    /* explosion runs per ladder level, the crater moved by r dp / n for the
     * r-th (plan.h wl_plan.realisations); auto: resolved by wl_plan_choose */
    struct wl_scenario_value realisations;
    int n_levels;
    struct wl_scenario_value levels[WL_SCENARIO_MAX_LEVELS];
    int levels_given;
    struct {
      int present;
      struct wl_scenario_value from; /* the fine level's seaward end [m] (vres.h), or auto
                                        (plan.c plan_refine places it from the scene) */
      int gpu; /* from: auto on a machine whose run takes the GPU (wl_plan_choose): the
                  CUDA backend runs one resolution */
      int gpu_given; /* a given `from` on such a machine: it runs, slower than one
                        resolution there (plan.c's note) */
    } refine;
  } resolution;
  struct {
    struct wl_scenario_value end_time, output_interval, backend, threads, still_reference;
  } run;
  struct {
    struct wl_scenario_value coefh, coefsound, cfl, alpha, viscosity, nu, density_diffusion,
        residual_viscosity, smagorinsky, shifting, integrator, verlet_steps, boundary;
  } numerics;
  struct {
    struct wl_scenario_value template_name;
  } report;
  /* `wallload sweep`: every combination of the swept values is one case,
   * the scenario with those values (src/sweep). The first parameter written
   * varies slowest: order[0..n_params) lists them as written. */
  struct {
    int present;
    int line, col; /* of the `sweep` key */
    int n_params;
    enum wl_sweep_param order[WL_SWEEP_N_PARAMS];
    struct wl_scenario_sweep_axis axis[WL_SWEEP_N_PARAMS];
    int n_cases; /* product of the axes' n_values (0 without a sweep) */
  } sweep;
};

/* The schema name of a swept parameter ("charge", "standoff", ...). */
const char *wl_scenario_sweep_param_name(enum wl_sweep_param p);

/* Highest solitary-wave height that wallload accepts, H/h. The highest
 * solitary wave has H/h ~ 0.833 (Longuet-Higgins & Fenton 1974); third-order
 * theory is used up to 0.78, where mass and energy still rise with H. */
#define WL_SCENARIO_MAX_EPS 0.78

/* The shortest decimal text that reads back as v, to 12 significant
 * digits (a generated value's last bits, 19.999999999999996 from a log
 * spacing, are noise): how the sweep writes values into a case's scenario.
 * Plain notation from 1e-4 to 1e15. */
void wl_scenario_number_text(double v, char *buf, size_t size);

/* Zero a scenario so wl_scenario_clear is safe on it. */
void wl_scenario_init(struct wl_scenario *s);

/* Free what a scenario owns. Safe on a zeroed or half-loaded scenario. */
void wl_scenario_clear(struct wl_scenario *s);

/* Read, parse and validate a scenario file. On success every value is set
 * (defaults filled in). Returns WL_OK; WL_EIO if the file cannot be read;
 * WL_EINPUT for malformed YAML, unknown keys, wrong types, bad units,
 * out-of-range values or inconsistent values, with "file:line:col: key: ...".
 * On failure *s may be half-filled; call wl_scenario_clear. */
enum wl_status wl_scenario_load(const char *path, struct wl_scenario *s, struct wl_error *err);

/* Same, from text in memory (`path` is used in messages only). Text of
 * more than WL_SCENARIO_MAX_BYTES, YAML nested deeper than
 * WL_SCENARIO_MAX_DEPTH collections or with more than
 * WL_SCENARIO_MAX_ANCHORS anchors in a document is refused with WL_EINPUT
 * at its line and column, before the document is built. */
enum wl_status wl_scenario_parse(const char *path, const char *text, size_t len,
                                 struct wl_scenario *s, struct wl_error *err);

/* Write the resolved scenario, every key with its SI value, the user's value
 * and unit beside it, and "default" where it was not given. */
void wl_scenario_write_resolved(const struct wl_scenario *s, FILE *out);

/* The value of scalar key `key` as the schema spells it, dotted from the
 * top ("numerics.coefh", "run.end_time"), or NULL when the schema has no
 * such scalar (a map, a list or an unknown name). */
const struct wl_scenario_value *wl_scenario_value_of(const struct wl_scenario *s,
                                                     const char *key);

/* Bed elevation above the flume floor at x [m], from the bathymetry segments. */
double wl_scenario_bed_z(const struct wl_scenario *s, double x);

/* The units the scenario's wall loads are also quoted in (units.h): US
 * customary when its water depth, the one length every scenario writes, is
 * in ft or in. 1 and *u filled then; 0 when SI is the user's system. */
int wl_scenario_load_units(const struct wl_scenario *s, struct wl_load_units *u);

#endif
