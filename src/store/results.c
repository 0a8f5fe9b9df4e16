/* results.c: the schema of results.h5 (one table per group: every dataset
 * and attribute with its type, unit, description and whether a reader
 * requires it), the writer and the reader that both go through it, and the
 * particle snapshots particles_<case>.h5 read back. The loads (peaks,
 * impulses, run-up) are stored as assess computed them, never derived
 * again on reading. Layout in store.h and docs/outputs.md.
 *
 * HDF5 is read with its automatic error printing off; nothing prints. */
#define _POSIX_C_SOURCE 200809L /* strdup */

#include "wallload/store.h"

#include <errno.h>
#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

const char *wl_store_results_case_name(int i) {
  return i == WL_RESULTS_CASE_SOLITARY    ? "solitary"
         : i == WL_RESULTS_CASE_EXPLOSION ? "explosion"
                                          : "?";
}

/* ---- the schema ----------------------------------------------------------------- */

enum key_type {
  KEY_DOUBLE, /* double attribute with a "<name>_unit" attribute */
  KEY_INT,    /* int member, stored as a double attribute */
  KEY_TEXT,   /* text attribute from a char array member */
};

enum {
  KEY_REQUIRED = 1, /* the reader refuses a group without it */
  KEY_WHEN_SET = 2, /* written only when set (finite, non-empty); else always */
  KEY_LOADS = 4,    /* required: a load assess computed (results.h5 of before it was stored
                       lacks it, and the reader says to run assess again) */
};

/* One attribute of a group: name, type, unit (numbers), flags, and where
 * its value is in the group's struct (size: of a text member). */
struct key {
  const char *name;
  enum key_type type;
  const char *unit;
  int flags;
  size_t offset, size;
};
#define KD(st, m, name, unit, flags) {name, KEY_DOUBLE, unit, flags, offsetof(struct st, m), 0}
#define KI(st, m, name, flags) {name, KEY_INT, "1", flags, offsetof(struct st, m), 0}
#define KT(st, m, name, flags)                                                                \
  {name, KEY_TEXT, NULL, flags, offsetof(struct st, m), sizeof(((struct st *)0)->m)}

/* / (scenario_text is a heap string: written and read beside the table) */
static const struct key ROOT_KEYS[] = {
    KT(wl_results, scenario_name, "scenario_name", KEY_REQUIRED),
    KT(wl_results, scenario_file, "scenario_file", 0),
    KT(wl_results, version, "wallload_version", 0),
    KT(wl_results, created, "created", 0),
    KT(wl_results, backend, "backend", 0),
    KD(wl_results, threads, "threads", "1", 0),
    KD(wl_results, dp, "dp", "m", 0),
    KT(wl_results, report_template, "report_template", KEY_WHEN_SET),
    KT(wl_results, length_unit, "length_unit", KEY_WHEN_SET),
    KT(wl_results, convergence_asked, "convergence_asked", KEY_WHEN_SET),
};

/* /cases/NAME (stopped: written when the case did not complete) */
static const struct key CASE_KEYS[] = {
    KD(wl_results_case, dp, "dp", "m", 0),
    KD(wl_results_case, h, "smoothing_length", "m", 0),
    KD(wl_results_case, c0, "c0", "m/s", 0),
    KD(wl_results_case, particles, "particles", "1", 0),
    KD(wl_results_case, fluid_particles, "fluid_particles", "1", 0),
    KD(wl_results_case, steps, "steps", "1", 0),
    KD(wl_results_case, runtime, "runtime", "s", 0),
    KD(wl_results_case, end_time, "end_time", "s", 0),
    KD(wl_results_case, time_reached, "time_reached", "s", 0),
    KD(wl_results_case, cutoff, "filter_cutoff", "Hz", 0),
    KD(wl_results_case, peaks_from, "peaks_from", "s", 0),
    KD(wl_results_case, static_force, "static_force", "N/m", 0),
    KD(wl_results_case, static_moment, "static_moment", "N m/m", 0),
    KD(wl_results_case, rest_force, "rest_force", "N/m", 0),
    KD(wl_results_case, rest_force_b, "rest_force_boundary", "N/m", 0),
    KD(wl_results_case, rest_moment, "rest_moment", "N m/m", 0),
    KD(wl_results_case, rest_from, "rest_from", "s", 0),
    KD(wl_results_case, rest_to, "rest_to", "s", 0),
    KD(wl_results_case, wall_x, "wall_x", "m", 0),
    KD(wl_results_case, wall_toe_z, "wall_toe_z", "m", 0),
    KD(wl_results_case, wall_crest_z, "wall_crest_z", "m", 0),
    KD(wl_results_case, still_water_z, "still_water_z", "m", 0),
    /* 3D: the flume width (twice the modelled half with a symmetry plane);
     * the series stay per metre, per wall = per metre x width */
    KD(wl_results_case, width, "width", "m", KEY_WHEN_SET),
    KT(wl_results_case, symmetry, "symmetry", KEY_WHEN_SET),
    KT(wl_results_case, side_walls, "side_walls", KEY_WHEN_SET),
    /* the loads assess computed from the series (loads.h definitions;
     * summary.json's names and values), stored so that no reader derives
     * them again; NaN where the record is empty */
    KD(wl_results_case, force_peak.value, "peak_force", "N/m", KEY_LOADS),
    KD(wl_results_case, force_peak.time, "peak_force_time", "s", KEY_LOADS),
    KD(wl_results_case, force_peak.rise_time, "rise_time", "s", KEY_LOADS),
    KD(wl_results_case, force_peak.duration, "duration", "s", KEY_LOADS),
    KD(wl_results_case, force_b_peak.value, "peak_force_boundary", "N/m", KEY_LOADS),
    KD(wl_results_case, force_b_peak.time, "peak_force_boundary_time", "s", KEY_LOADS),
    KD(wl_results_case, moment_peak.value, "peak_moment", "N m/m", KEY_LOADS),
    KD(wl_results_case, moment_peak.time, "peak_moment_time", "s", KEY_LOADS),
    KD(wl_results_case, impulse_total, "impulse", "N s/m", KEY_LOADS),
    KD(wl_results_case, impulse_b_total, "impulse_boundary", "N s/m", KEY_LOADS),
    KD(wl_results_case, impulse_peak, "impulse_positive_phase", "N s/m", KEY_LOADS),
    KD(wl_results_case, impulse_peak_from, "impulse_positive_phase_from", "s", KEY_LOADS),
    KD(wl_results_case, impulse_peak_to, "impulse_positive_phase_to", "s", KEY_LOADS),
    KD(wl_results_case, impulse_positive, "impulse_positive", "N s/m", KEY_LOADS),
    KD(wl_results_case, impulse_positive_b, "impulse_positive_boundary", "N s/m", KEY_LOADS),
    KD(wl_results_case, runup, "max_runup", "m", KEY_LOADS),
    KD(wl_results_case, runup_time, "max_runup_time", "s", KEY_LOADS),
    KD(wl_results_case, still_drift_max, "still_drift_max", "N/m", KEY_WHEN_SET),
    KD(wl_results_case, impulse_positive_uncorrected, "impulse_positive_uncorrected", "N s/m",
       KEY_WHEN_SET),
    KT(wl_results_case, status, "status", KEY_REQUIRED),
    KT(wl_results_case, caution, "caution", KEY_WHEN_SET),
};

/* A series of /cases/NAME: path below the case, unit, description, member. */
struct series {
  const char *name, *unit, *description;
  size_t offset;
};
#define SER(m, name, unit, desc) {name, unit, desc, offsetof(struct wl_results_case, m)}
static const struct series CASE_SERIES[] = {
    SER(force, "wall/force", "N/m", "force per metre from the pressure probes (raw)"),
    SER(force_f, "wall/force_filtered", "N/m",
        "low-pass filtered force (see cutoff), less the still-water drift where there is one"),
    SER(force_b, "wall/force_boundary", "N/m",
        "force per metre summed on the wall's boundary particles (raw)"),
    SER(force_bf, "wall/force_boundary_filtered", "N/m", "low-pass filtered"),
    SER(impulse, "wall/impulse", "N s/m", "integral of (probe force - static force) dt"),
    SER(impulse_b, "wall/impulse_boundary", "N s/m",
        "integral of (boundary force - static force) dt"),
    SER(still_drift, "wall/still_drift", "N/m",
        "the still-water reference run's filtered force less its force at rest, which "
        "force_filtered and the impulses have had taken out (absent: no reference run)"),
    SER(moment, "wall/moment", "N m/m", "overturning moment about the toe (raw)"),
    SER(moment_b, "wall/moment_boundary", "N m/m",
        "moment about the toe of the boundary-particle force (raw)"),
    SER(moment_f, "wall/moment_filtered", "N m/m", "low-pass filtered"),
    SER(kinetic, "energy/kinetic", "J/m", "fluid kinetic energy"),
    SER(potential, "energy/potential", "J/m", "fluid potential energy above the floor"),
    SER(momentum, "momentum/x", "N s/m",
        "fluid horizontal momentum; its change is the impulse given to all boundaries"),
};
enum { N_CASE_SERIES = sizeof CASE_SERIES / sizeof CASE_SERIES[0] };
#undef SER
static const struct series TIME = {"time", "s", "output times", 0};
static const struct series PRESSURE = {"wall/pressure", "Pa", "probe pressure, time x probe", 0};
static const struct series PROBE_Z = {"wall/probe_z", "m", "probe heights above the flume floor",
                                      0};
static const struct series ETA = {"eta", "m", "free-surface elevation above still water", 0};

/* /convergence/NAME: one dataset a level column, then the attributes */
#define LC(m, name, unit, desc) {name, unit, desc}
const struct wl_results_column wl_store_results_levels[] = {
    LC(factor, "factor", "1", "level's factor of the scenario's dp"),
    LC(dp, "dp", "m", "particle spacing of the level"),
    LC(particles, "particles", "1", "fluid and boundary particles"),
    LC(steps, "steps", "1", "time steps"),
    LC(runtime, "runtime", "s",
       "wall-clock time of the level's run (with realisations, the first one's)"),
    LC(rate, "particle_steps_per_second", "1/s", "particles x steps / runtime"),
    LC(time_reached, "time_reached", "s", "simulated time reached"),
    LC(peak_force, "peak_force", "N/m", "peak of the filtered pressure-probe force"),
    LC(peak_force_b, "peak_force_boundary", "N/m", "peak of the filtered boundary-particle force"),
    LC(rest_force, "rest_force", "N/m",
       "the probes' force at rest, the model's (peak_force less it is the wave's part)"),
    LC(impulse, "impulse", "N s/m", "integral of (probe force - static force) dt to the end"),
    LC(impulse_phase, "impulse_positive_phase", "N s/m",
       "integral of (probe force - static force) dt over the peak's positive phase"),
    LC(impulse_pos, "impulse_positive", "N s/m",
       "integral of max(0, filtered probe force - force at rest) dt: every wave's push"),
    LC(peak_moment, "peak_moment", "N m/m", "peak of the filtered overturning moment about the toe"),
    LC(runup, "max_runup", "m", "highest water level at the wall face above still water"),
    LC(realisations, "realisations", "1",
       "runs of the level whose mean the loads are (resolution.realisations: the explosion's "
       "crater moved by a fraction of dp each time)"),
    LC(peak_force_sd, "peak_force_sd", "N/m",
       "standard deviation of the realisations' peak force (probes); NaN from one run"),
    LC(peak_force_min, "peak_force_min", "N/m", "least peak force of the realisations (probes)"),
    LC(peak_force_max, "peak_force_max", "N/m", "largest peak force of the realisations (probes)"),
    LC(impulse_pos_sd, "impulse_positive_sd", "N s/m",
       "standard deviation of the realisations' positive impulse; NaN from one run"),
    LC(error, "estimated_error", "1",
       "relative error of the level: larger of the peak force's part above the force at rest "
       "and the positive impulse, against "
       "the Richardson value (or the finest level); the finest level's is the case's "
       "uncertainty (loads.h)"),
    LC(status, "status", "",
       "run status per level: 0 complete, else the failure code "
       "(enum wl_status: unstable, interrupted, ...)"),
};
#undef LC
const int wl_store_results_n_levels =
    (int)(sizeof wl_store_results_levels / sizeof wl_store_results_levels[0]);
enum { STATUS_COLUMN = sizeof wl_store_results_levels / sizeof wl_store_results_levels[0] - 1 };

/* Where column k's values are (the status column's are int). */
#define LM(m) offsetof(struct wl_results_convergence, m)
static const size_t LEVEL_OFFSET[] = {
    LM(factor),     LM(dp),           LM(particles),     LM(steps),
    LM(runtime),    LM(rate),         LM(time_reached),  LM(peak_force),
    LM(peak_force_b), LM(rest_force), LM(impulse),    LM(impulse_phase), LM(impulse_pos),
    LM(peak_moment), LM(runup),       LM(realisations),  LM(peak_force_sd),
    LM(peak_force_min), LM(peak_force_max), LM(impulse_pos_sd), LM(error), LM(status),
};
#undef LM
_Static_assert(sizeof LEVEL_OFFSET / sizeof LEVEL_OFFSET[0] ==
                   sizeof wl_store_results_levels / sizeof wl_store_results_levels[0],
               "one offset per level column");

double wl_store_results_level_value(const struct wl_results_convergence *cv, int column, int l) {
  const char *p = (const char *)cv + LEVEL_OFFSET[column];
  if (column == STATUS_COLUMN)
    return (double)((const int *)(const void *)p)[l];
  return ((const double *)(const void *)p)[l];
}

void wl_store_results_level_set(struct wl_results_convergence *cv, int column, int l, double v) {
  if (column != STATUS_COLUMN)
    ((double *)(void *)((char *)cv + LEVEL_OFFSET[column]))[l] = v;
}

static const struct key CONV_KEYS[] = {
    KD(wl_results_convergence, levels_planned, "levels_planned", "1", 0),
    KD(wl_results_convergence, levels_run, "levels_run", "1", 0),
    KD(wl_results_convergence, ratio, "ratio", "1", 0),
    KD(wl_results_convergence, force_order, "peak_force_order", "1", 0),
    KD(wl_results_convergence, force_order_ok, "peak_force_order_meaningful", "1", 0),
    KD(wl_results_convergence, force_extrapolated, "peak_force_extrapolated", "N/m", 0),
    KD(wl_results_convergence, force_error, "peak_force_error_estimate", "1", 0),
    KD(wl_results_convergence, pos_order, "impulse_positive_order", "1", 0),
    KD(wl_results_convergence, pos_order_ok, "impulse_positive_order_meaningful", "1", 0),
    KD(wl_results_convergence, pos_extrapolated, "impulse_positive_extrapolated", "N s/m", 0),
    KD(wl_results_convergence, pos_error, "impulse_positive_error_estimate", "1", 0),
    KD(wl_results_convergence, dyn_order, "peak_force_dynamic_order", "1", 0),
    KD(wl_results_convergence, dyn_order_ok, "peak_force_dynamic_order_meaningful", "1", 0),
    KD(wl_results_convergence, dyn_extrapolated, "peak_force_dynamic_extrapolated", "N/m", 0),
    KD(wl_results_convergence, dyn_error, "peak_force_dynamic_error_estimate", "1", 0),
    KD(wl_results_convergence, error_estimate, "error_estimate", "1", 0),
    KD(wl_results_convergence, force_sampling, "peak_force_sampling_uncertainty", "1", 0),
    KD(wl_results_convergence, dyn_sampling, "peak_force_dynamic_sampling_uncertainty", "1", 0),
    KD(wl_results_convergence, pos_sampling, "impulse_positive_sampling_uncertainty", "1", 0),
    KD(wl_results_convergence, target, "target", "1", 0),
    KD(wl_results_convergence, target_given, "target_given", "1", 0),
    KD(wl_results_convergence, target_met, "target_met", "1", 0),
    KD(wl_results_convergence, stopped_early, "stopped_early", "1", 0),
    KT(wl_results_convergence, force_basis, "peak_force_basis", 0),
    KT(wl_results_convergence, pos_basis, "impulse_positive_basis", 0),
    KT(wl_results_convergence, dyn_basis, "peak_force_dynamic_basis", 0),
    KT(wl_results_convergence, note, "note", 0),
};

/* /plan (gauge names: one text attribute, a name a line, beside the
 * gauge_x dataset) */
static const struct key PLAN_KEYS[] = {
    KI(wl_results_plan, dims, "dimensions", KEY_REQUIRED),
    KD(wl_results_plan, depth, "still_water_depth", "m", KEY_REQUIRED),
    KD(wl_results_plan, rho, "water_density", "kg/m^3", KEY_REQUIRED),
    KD(wl_results_plan, g, "gravity", "m/s^2", KEY_REQUIRED),
    KD(wl_results_plan, wall_x, "wall_x", "m", KEY_REQUIRED),
    KD(wl_results_plan, wall_toe_z, "wall_toe_z", "m", KEY_REQUIRED),
    KD(wl_results_plan, wall_crest_z, "wall_crest_z", "m", KEY_REQUIRED),
    KD(wl_results_plan, land_length, "land_length", "m", KEY_REQUIRED),
    KT(wl_results_plan, notes, "notes", KEY_WHEN_SET),
};

static const struct key SOLITARY_KEYS[] = {
    KT(wl_results_solitary, theory, "theory", KEY_REQUIRED),
    KD(wl_results_solitary, H, "height", "m", KEY_REQUIRED),
    KD(wl_results_solitary, K, "decay_rate", "1/m", KEY_REQUIRED),
    KD(wl_results_solitary, celerity, "celerity", "m/s", KEY_REQUIRED),
    KD(wl_results_solitary, energy_integrated, "energy_integrated", "J/m", KEY_REQUIRED),
    KD(wl_results_solitary, energy_first_order, "energy_first_order", "J/m", KEY_REQUIRED),
    KD(wl_results_solitary, energy_seed001, "energy_seed001", "J/m", KEY_REQUIRED),
    KI(wl_results_solitary, paddle, "paddle", KEY_REQUIRED),
    KD(wl_results_solitary, paddle_stroke, "paddle_stroke", "m", KEY_WHEN_SET),
    KD(wl_results_solitary, paddle_duration, "paddle_duration", "s", KEY_WHEN_SET),
    KD(wl_results_solitary, crest_x0, "crest_x0", "m", KEY_WHEN_SET),
    KD(wl_results_solitary, arrival_time, "arrival_time", "s", KEY_REQUIRED),
    KD(wl_results_solitary, x_left, "x_left", "m", KEY_REQUIRED),
};

static const struct key EXPLOSION_KEYS[] = {
    KT(wl_results_explosion, source, "source", KEY_REQUIRED),
    KI(wl_results_explosion, sized_to_solitary, "sized_to_solitary", KEY_REQUIRED),
    KT(wl_results_explosion, basis, "energy_basis", KEY_WHEN_SET),
    KD(wl_results_explosion, matched_energy, "matched_energy", "J or J/m", KEY_WHEN_SET),
    KD(wl_results_explosion, charge, "charge", "kg", KEY_REQUIRED),
    KD(wl_results_explosion, chain_r0, "chain_r0", "m", KEY_REQUIRED),
    KD(wl_results_explosion, chain_eta0, "chain_eta0", "m", KEY_REQUIRED),
    KD(wl_results_explosion, hr, "hmax_r", "m^2", KEY_REQUIRED),
    KD(wl_results_explosion, whalin_coef, "whalin_coefficient", "1", KEY_REQUIRED),
    KD(wl_results_explosion, crater_energy, "crater_energy", "J", KEY_REQUIRED),
    KD(wl_results_explosion, chemical_energy, "chemical_energy", "J", KEY_REQUIRED),
    KD(wl_results_explosion, chain_wave_fraction, "chain_wave_fraction", "1", KEY_REQUIRED),
    KD(wl_results_explosion, wave_fraction, "wave_fraction", "1", KEY_REQUIRED),
    KT(wl_results_explosion, shape, "shape", KEY_REQUIRED),
    KD(wl_results_explosion, eta0, "eta0", "m", KEY_REQUIRED),
    KD(wl_results_explosion, r0, "r0", "m", KEY_REQUIRED),
    KD(wl_results_explosion, x_center, "x_center", "m", KEY_REQUIRED),
    KD(wl_results_explosion, extent, "extent", "m", KEY_REQUIRED),
    KD(wl_results_explosion, energy, "energy", "J/m in 2D, J in 3D", KEY_REQUIRED),
    KD(wl_results_explosion, energy_quad, "energy_quadrature", "J/m in 2D, J in 3D",
       KEY_REQUIRED),
    KD(wl_results_explosion, net_volume, "net_volume", "m^2/m in 2D, m^3 in 3D", KEY_REQUIRED),
    KI(wl_results_explosion, conserves_mass, "conserves_mass", KEY_REQUIRED),
    KD(wl_results_explosion, arrival_time, "arrival_time", "s", KEY_REQUIRED),
    KD(wl_results_explosion, x_left, "x_left", "m", KEY_REQUIRED),
};
#undef KD
#undef KI
#undef KT
#define N_OF(t) (sizeof t / sizeof t[0])

/* /settings: one text attribute a key, with "<key>_origin" */
const struct wl_results_setting_key wl_store_results_settings[] = {
    {"numerics.coefh", "coefh (h = coefh sqrt(dim) dp)"},
    {"numerics.coefsound", "coefsound (c0 = coefsound sqrt(g h_max))"},
    {"numerics.cfl", "CFL number"},
    {"numerics.alpha", "artificial viscosity alpha"},
    {"numerics.viscosity", "viscosity"},
    {"numerics.nu", "laminar viscosity nu"},
    {"numerics.density_diffusion", "density diffusion"},
    {"numerics.residual_viscosity", "residual viscosity alpha_r"},
    {"numerics.shifting", "shifting"},
    {"numerics.integrator", "time integrator"},
    {"numerics.verlet_steps", "Euler step every (Verlet)"},
    {"numerics.boundary", "wall condition"},
    {"resolution.refine.from", "fine level (dp) from, 2 dp seaward of it"},
    {"run.output_interval", "output interval"},
    {"run.end_time", "end time"},
};
const int wl_store_results_n_settings = (int)N_OF(wl_store_results_settings);
_Static_assert(N_OF(wl_store_results_settings) <= WL_RESULTS_MAX_SETTINGS,
               "every stored setting fits struct wl_results");

static const char *const GAUGE_NAMES = "gauge_names";
static const char *const SETTING_ORIGIN = "_origin"; /* "<key>_origin": scenario or default */

/* ---- initialisation ------------------------------------------------------------- */

static void keys_absent(const struct key *keys, size_t n, void *base) {
  for (size_t i = 0; i < n; i++)
    if (keys[i].type == KEY_DOUBLE)
      *(double *)(void *)((char *)base + keys[i].offset) = NAN;
}

void wl_store_results_case_init(struct wl_results_case *c) {
  memset(c, 0, sizeof *c);
  keys_absent(CASE_KEYS, N_OF(CASE_KEYS), c);
  c->wall_gauge = -1;
}

void wl_store_results_convergence_init(struct wl_results_convergence *cv) {
  memset(cv, 0, sizeof *cv);
  keys_absent(CONV_KEYS, N_OF(CONV_KEYS), cv);
  for (int k = 0; k < STATUS_COLUMN; k++)
    for (int l = 0; l < WL_RESULTS_MAX_LEVELS; l++)
      wl_store_results_level_set(cv, k, l, NAN);
}

void wl_store_results_init(struct wl_results *r) {
  memset(r, 0, sizeof *r);
  keys_absent(ROOT_KEYS, N_OF(ROOT_KEYS), r);
  keys_absent(PLAN_KEYS, N_OF(PLAN_KEYS), &r->plan);
  keys_absent(SOLITARY_KEYS, N_OF(SOLITARY_KEYS), &r->plan.solitary);
  keys_absent(EXPLOSION_KEYS, N_OF(EXPLOSION_KEYS), &r->plan.explosion);
  for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
    wl_store_results_case_init(&r->cases[i]);
    wl_store_results_convergence_init(&r->conv[i]);
  }
}

static void case_free(struct wl_results_case *c) {
  free(c->t), free(c->probe_z), free(c->pressure);
  for (size_t i = 0; i < N_CASE_SERIES; i++)
    free(*(double **)(void *)((char *)c + CASE_SERIES[i].offset));
  for (int g = 0; g < WL_RESULTS_MAX_GAUGES; g++)
    free(c->gauges[g].eta);
}

void wl_store_results_clear(struct wl_results *r) {
  if (!r)
    return;
  for (int i = 0; i < WL_RESULTS_N_CASES; i++)
    case_free(&r->cases[i]);
  free(r->scenario_text);
  wl_store_results_init(r);
}

const struct wl_results_setting *wl_store_results_setting(const struct wl_results *r,
                                                           const char *key) {
  for (int i = 0; i < r->n_settings; i++)
    if (!strcmp(r->settings[i].key, key))
      return &r->settings[i];
  return NULL;
}

/* ---- writing -------------------------------------------------------------------- */

static enum wl_status write_keys(struct wl_store *h5, const char *group, const struct key *keys,
                                 size_t n, const void *base, struct wl_error *err) {
  enum wl_status st = WL_OK;
  for (size_t i = 0; !st && i < n; i++) {
    const struct key *k = &keys[i];
    const char *p = (const char *)base + k->offset;
    const int when_set = k->flags & KEY_WHEN_SET;
    if (k->type == KEY_TEXT) {
      if (!when_set || *p)
        st = wl_store_attr_text(h5, group, k->name, p, err);
    } else {
      double v = k->type == KEY_INT ? (double)*(const int *)(const void *)p
                                    : *(const double *)(const void *)p;
      if (!when_set || isfinite(v))
        st = wl_store_attr_double(h5, group, k->name, v, k->unit, err);
    }
  }
  return st;
}

static enum wl_status write_series(struct wl_store *h5, const char *group,
                                   const struct series *s, const double *data, size_t n,
                                   struct wl_error *err) {
  char p[256];
  snprintf(p, sizeof p, "%s/%s", group, s->name);
  return wl_store_write_vector(h5, p, data, n, s->unit, s->description, err);
}

/* A load case's group under /plan: its keys and its initial free surface. */
struct load_plan {
  const char *group;
  const struct key *keys;
  size_t n_keys;
};
static const struct load_plan SOLITARY_PLAN = {"plan/solitary", SOLITARY_KEYS,
                                               N_OF(SOLITARY_KEYS)};
static const struct load_plan EXPLOSION_PLAN = {"plan/explosion", EXPLOSION_KEYS,
                                                N_OF(EXPLOSION_KEYS)};
static const struct series SURFACE_X = {"surface_x", "m", "initial free surface: x", 0};
static const struct series SURFACE_Z = {
    "surface_z", "m", "initial free surface above the flume floor (NaN: below the bed)", 0};

static enum wl_status write_load_plan(struct wl_store *h5, const struct load_plan *lp,
                                      const void *base, const double *x, const double *z,
                                      size_t n, struct wl_error *err) {
  enum wl_status st = write_keys(h5, lp->group, lp->keys, lp->n_keys, base, err);
  if (!st && n)
    st = write_series(h5, lp->group, &SURFACE_X, x, n, err);
  if (!st && n)
    st = write_series(h5, lp->group, &SURFACE_Z, z, n, err);
  return st;
}

enum wl_status wl_store_results_write_run(struct wl_store *h5, const struct wl_results *r,
                                          struct wl_error *err) {
  /* scenario_text third, as results.h5 always held it */
  enum wl_status st = write_keys(h5, "/", ROOT_KEYS, 2, r, err);
  if (!st)
    st = wl_store_attr_text(h5, "/", "scenario_text", r->scenario_text ? r->scenario_text : "",
                            err);
  if (!st)
    st = write_keys(h5, "/", ROOT_KEYS + 2, N_OF(ROOT_KEYS) - 2, r, err);
  char name[96];
  for (int i = 0; !st && i < r->n_settings; i++) {
    const struct wl_results_setting *s = &r->settings[i];
    st = wl_store_attr_text(h5, "settings", s->key, s->value, err);
    snprintf(name, sizeof name, "%s%s", s->key, SETTING_ORIGIN);
    if (!st)
      st = wl_store_attr_text(h5, "settings", name, s->given ? "scenario" : "default", err);
  }
  const struct wl_results_plan *pl = &r->plan;
  if (st || !pl->present)
    return st;
  st = write_keys(h5, "plan", PLAN_KEYS, N_OF(PLAN_KEYS), pl, err);
  if (!st)
    st = wl_store_write_vector(h5, "plan/bed_x", pl->bed_x, pl->n_bed, "m",
                               "corners of the bed from x = 0 to the wall's toe: x", err);
  if (!st)
    st = wl_store_write_vector(h5, "plan/bed_z", pl->bed_z, pl->n_bed, "m",
                               "corners of the bed: height above the flume floor", err);
  if (!st && pl->n_gauges) {
    char names[WL_RESULTS_MAX_GAUGES * 65] = "";
    size_t used = 0;
    for (int g = 0; g < pl->n_gauges && used < sizeof names; g++)
      used += (size_t)snprintf(names + used, sizeof names - used, "%s%s", g ? "\n" : "",
                               pl->gauge_name[g]);
    st = wl_store_write_vector(h5, "plan/gauge_x", pl->gauge_x, (size_t)pl->n_gauges, "m",
                               "the scenario's gauges, in its order (names: gauge_names)", err);
    if (!st)
      st = wl_store_attr_text(h5, "plan/gauge_x", GAUGE_NAMES, names, err);
  }
  const struct wl_results_solitary *ps = &pl->solitary;
  if (!st && ps->present)
    st = write_load_plan(h5, &SOLITARY_PLAN, ps, ps->surface_x, ps->surface_z, ps->n_surface, err);
  const struct wl_results_explosion *px = &pl->explosion;
  if (!st && px->present)
    st = write_load_plan(h5, &EXPLOSION_PLAN, px, px->surface_x, px->surface_z, px->n_surface,
                         err);
  return st;
}

enum wl_status wl_store_results_write_case(struct wl_store *h5, const struct wl_results_case *c,
                                           struct wl_error *err) {
  char g[96], p[256];
  snprintf(g, sizeof g, "cases/%s", c->name);
  enum wl_status st = write_series(h5, g, &TIME, c->t, c->n, err);
  for (size_t i = 0; !st && i < N_CASE_SERIES; i++) {
    const double *data = *(double *const *)(const void *)((const char *)c + CASE_SERIES[i].offset);
    if (data) /* a series the case does not have (still_drift) is absent */
      st = write_series(h5, g, &CASE_SERIES[i], data, c->n, err);
  }
  if (!st) {
    snprintf(p, sizeof p, "%s/%s", g, PRESSURE.name);
    st = wl_store_write_matrix(h5, p, c->pressure, c->n, c->n_probes, PRESSURE.unit,
                               PRESSURE.description, err);
  }
  if (!st)
    st = write_series(h5, g, &PROBE_Z, c->probe_z, c->n_probes, err);
  for (int gi = 0; !st && gi < c->n_gauges; gi++) {
    snprintf(p, sizeof p, "%s/gauges/%s", g, c->gauges[gi].name);
    st = write_series(h5, p, &ETA, c->gauges[gi].eta, c->n, err);
    if (!st)
      st = wl_store_attr_double(h5, p, "x", c->gauges[gi].x, "m", err);
  }
  if (!st)
    st = write_keys(h5, g, CASE_KEYS, N_OF(CASE_KEYS) - 1, c, err);
  if (!st && strcmp(c->status, "complete"))
    st = wl_store_attr_text(h5, g, "stopped", c->stopped, err);
  if (!st) /* the caution last, as results.h5 always held it */
    st = write_keys(h5, g, CASE_KEYS + N_OF(CASE_KEYS) - 1, 1, c, err);
  return st;
}

enum wl_status wl_store_results_write_convergence(struct wl_store *h5, const char *name,
                                                  const struct wl_results_convergence *cv,
                                                  struct wl_error *err) {
  char g[96], p[256];
  snprintf(g, sizeof g, "convergence/%s", name);
  size_t n = (size_t)cv->n_levels;
  double col[WL_RESULTS_MAX_LEVELS];
  enum wl_status st = WL_OK;
  for (int k = 0; !st && k < wl_store_results_n_levels; k++) {
    const struct wl_results_column *f = &wl_store_results_levels[k];
    snprintf(p, sizeof p, "%s/%s", g, f->name);
    if (k == STATUS_COLUMN) {
      st = wl_store_write_vector_i(h5, p, cv->status, n, f->description, err);
      continue;
    }
    for (size_t l = 0; l < n; l++)
      col[l] = wl_store_results_level_value(cv, k, (int)l);
    st = wl_store_write_vector(h5, p, col, n, f->unit, f->description, err);
  }
  if (!st)
    st = write_keys(h5, g, CONV_KEYS, N_OF(CONV_KEYS), cv, err);
  return st;
}

/* ---- HDF5 reading helpers ------------------------------------------------------- */

/* 1 when every component of `path` (relative to loc) exists. */
static int exists(hid_t loc, const char *path) {
  char buf[512];
  size_t len = strlen(path);
  if (len >= sizeof buf)
    return 0;
  memcpy(buf, path, len + 1);
  for (char *s = buf; *s; s++) {
    if (*s != '/')
      continue;
    *s = '\0';
    if (*buf && H5Lexists(loc, buf, H5P_DEFAULT) <= 0)
      return 0;
    *s = '/';
  }
  return H5Lexists(loc, buf, H5P_DEFAULT) > 0;
}

/* A string attribute of obj, malloc'ed; NULL when absent or not a string. */
static char *attr_text_alloc(hid_t obj, const char *name) {
  if (H5Aexists(obj, name) <= 0)
    return NULL;
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  if (a < 0)
    return NULL;
  char *out = NULL;
  hid_t ft = H5Aget_type(a);
  if (ft >= 0 && H5Tget_class(ft) == H5T_STRING) {
    hid_t mt = H5Tcopy(H5T_C_S1);
    if (H5Tis_variable_str(ft) > 0) {
      char *p = NULL;
      if (mt >= 0 && H5Tset_size(mt, H5T_VARIABLE) >= 0 && H5Aread(a, mt, &p) >= 0 && p) {
        out = strdup(p);
        H5free_memory(p);
      }
    } else {
      size_t size = H5Tget_size(ft);
      out = malloc(size + 1);
      if (out && (mt < 0 || H5Tset_size(mt, size) < 0 || H5Aread(a, mt, out) < 0)) {
        free(out);
        out = NULL;
      }
      if (out)
        out[size] = '\0';
    }
    if (mt >= 0)
      H5Tclose(mt);
  }
  if (ft >= 0)
    H5Tclose(ft);
  H5Aclose(a);
  return out;
}

static void attr_text(hid_t obj, const char *name, char *buf, size_t size) {
  char *s = attr_text_alloc(obj, name);
  snprintf(buf, size, "%s", s ? s : "");
  free(s);
}

static double attr_double(hid_t obj, const char *name) {
  double v = NAN;
  if (H5Aexists(obj, name) <= 0)
    return NAN;
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  if (a < 0)
    return NAN;
  if (H5Aread(a, H5T_NATIVE_DOUBLE, &v) < 0)
    v = NAN;
  H5Aclose(a);
  return v;
}

/* The keys of the group at `group` (open as obj) into base. A required key
 * that is missing is WL_EINPUT naming the file, the group and the key. */
static enum wl_status read_keys(hid_t obj, const char *file_name, const char *group,
                                const struct key *keys, size_t n, void *base,
                                struct wl_error *err) {
  /* a group that is not what assess writes is said before a file of an
   * earlier wallload */
  for (size_t i = 0; i < n; i++)
    if ((keys[i].flags & KEY_REQUIRED) && H5Aexists(obj, keys[i].name) <= 0)
      return wl_error_set(err, WL_EINPUT,
                          "%s: /%s: found no attribute '%s'; expected the results.h5 that "
                          "`wallload assess` writes",
                          file_name, group, keys[i].name);
  for (size_t i = 0; i < n; i++) {
    const struct key *k = &keys[i];
    char *p = (char *)base + k->offset;
    if ((k->flags & KEY_LOADS) && H5Aexists(obj, k->name) <= 0)
      return wl_error_set(err, WL_EINPUT,
                          "%s: /%s: found no attribute '%s' (the results of an earlier "
                          "wallload, which did not store the loads); run `wallload assess` on "
                          "the scenario again to write them",
                          file_name, group, k->name);
    if (k->type == KEY_TEXT) {
      attr_text(obj, k->name, p, k->size);
    } else {
      double v = attr_double(obj, k->name);
      if (k->type == KEY_INT)
        *(int *)(void *)p = isfinite(v) ? (int)v : 0;
      else
        *(double *)(void *)p = v;
    }
  }
  return WL_OK;
}

/* Read dataset `path` (rank 1 or 2) as mem_type into a malloc'ed array.
 * Returns WL_OK with *data NULL when it does not exist; WL_EINPUT when it
 * is not what wallload writes (a damaged results file: the user's input);
 * WL_EIO when it cannot be read; WL_ENOMEM. */
static enum wl_status read_dataset(hid_t file, const char *file_name, const char *path,
                                   hid_t mem_type, size_t elem, void **data, size_t *rows,
                                   size_t *cols, struct wl_error *err) {
  *data = NULL, *rows = 0, *cols = 1;
  if (!exists(file, path))
    return WL_OK;
  hid_t d = H5Dopen2(file, path, H5P_DEFAULT);
  if (d < 0)
    return wl_error_set(err, WL_EINPUT, "%s: %s: cannot open the dataset (a damaged results file)",
                        file_name, path);
  hid_t sp = H5Dget_space(d);
  hsize_t dims[2] = {0, 1};
  int rank = sp >= 0 ? H5Sget_simple_extent_ndims(sp) : -1;
  enum wl_status st = WL_OK;
  if (rank < 1 || rank > 2 || H5Sget_simple_extent_dims(sp, dims, NULL) < 0) {
    st = wl_error_set(err, WL_EINPUT, "%s: %s: found a dataset of rank %d; expected 1 or 2",
                      file_name, path, rank);
  } else {
    size_t count = (size_t)dims[0] * (size_t)(rank == 2 ? dims[1] : 1);
    void *buf = malloc((count ? count : 1) * elem);
    if (!buf) {
      st = wl_error_set(err, WL_ENOMEM, "%s: %s: no memory for %zu values", file_name, path, count);
    } else if (count && H5Dread(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0) {
      free(buf);
      st = wl_error_set(err, WL_EIO, "%s: %s: cannot read the dataset", file_name, path);
    } else {
      *data = buf;
      *rows = (size_t)dims[0];
      *cols = rank == 2 ? (size_t)dims[1] : 1;
    }
  }
  if (sp >= 0)
    H5Sclose(sp);
  H5Dclose(d);
  return st;
}

/* A vector of n doubles at `path`; NULL (no error) when absent or of another
 * length, so one damaged series does not hide the rest. */
static enum wl_status read_series(hid_t file, const char *file_name, const char *path, size_t n,
                                  double **out, struct wl_error *err) {
  void *data;
  size_t rows, cols;
  *out = NULL;
  enum wl_status st = read_dataset(file, file_name, path, H5T_NATIVE_DOUBLE, sizeof(double), &data,
                                   &rows, &cols, err);
  if (st)
    return st;
  if (data && (rows != n || cols != 1)) {
    free(data);
    return WL_OK;
  }
  *out = data;
  return WL_OK;
}

/* Up to max doubles of the vector at `path` into out; *n the count read
 * (0 when absent). */
static enum wl_status read_fixed(hid_t file, const char *file_name, const char *path, double *out,
                                 size_t max, size_t *n, struct wl_error *err) {
  void *data;
  size_t rows, cols;
  *n = 0;
  enum wl_status st = read_dataset(file, file_name, path, H5T_NATIVE_DOUBLE, sizeof(double), &data,
                                   &rows, &cols, err);
  if (!st && data) {
    *n = rows < max ? rows : max;
    memcpy(out, data, *n * sizeof(double));
  }
  free(data);
  return st;
}

/* Open group `path` for its attributes: -1 when absent; WL_EINPUT when it
 * exists and cannot be opened. */
static enum wl_status open_group(hid_t file, const char *file_name, const char *path, hid_t *grp,
                                 struct wl_error *err) {
  *grp = -1;
  if (!exists(file, path))
    return WL_OK;
  *grp = H5Oopen(file, path, H5P_DEFAULT);
  if (*grp < 0)
    return wl_error_set(err, WL_EINPUT, "%s: /%s: cannot open the group (a damaged results file)",
                        file_name, path);
  return WL_OK;
}

/* Names of the links in group `path`, at most max, into names[][64]. */
static int link_names(hid_t file, const char *path, char (*names)[64], int max) {
  if (!exists(file, path))
    return 0;
  hid_t g = H5Gopen2(file, path, H5P_DEFAULT);
  if (g < 0)
    return 0;
  H5G_info_t info;
  int n = 0;
  if (H5Gget_info(g, &info) >= 0)
    for (hsize_t i = 0; i < info.nlinks && n < max; i++)
      if (H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, names[n], 64, H5P_DEFAULT) > 0)
        n++;
  H5Gclose(g);
  return n;
}

/* ---- reading -------------------------------------------------------------------- */

static int by_x(const void *a, const void *b) {
  const struct wl_results_gauge *ga = a, *gb = b;
  double xa = isfinite(ga->x) ? ga->x : INFINITY, xb = isfinite(gb->x) ? gb->x : INFINITY;
  return xa < xb ? -1 : xa > xb ? 1 : strcmp(ga->name, gb->name);
}

/* The sample of the stored series at time t (a peak's stored time), 0
 * when none: the stored peaks name their time, the report draws the
 * profile at that sample. */
static size_t sample_at(const struct wl_results_case *c, double t) {
  for (size_t k = 0; c->t && k < c->n; k++)
    if (c->t[k] == t)
      return k;
  return 0;
}

/* What the reader adds to a case's stored values: the wall gauge, the
 * bases of the net loads for files that lack them, the peaks' samples. */
static void case_finish(struct wl_results_case *c) {
  c->wall_gauge = -1;
  for (int g = 0; g < c->n_gauges; g++)
    if (!strcmp(c->gauges[g].name, "wall"))
      c->wall_gauge = g;
  /* the bases assess used: the model's force at rest where it measured it */
  const double fs0 = isfinite(c->static_force) ? c->static_force : 0.0;
  c->rest_force = isfinite(c->rest_force) ? c->rest_force : fs0;
  c->rest_force_b = isfinite(c->rest_force_b) ? c->rest_force_b : fs0;
  c->filtered = c->force_f != NULL;
  c->force_peak.index = sample_at(c, c->force_peak.time);
  c->force_b_peak.index = sample_at(c, c->force_b_peak.time);
  c->moment_peak.index = sample_at(c, c->moment_peak.time);
}

static enum wl_status read_case(hid_t file, const char *file_name, int index,
                                struct wl_results_case *c, struct wl_error *err) {
  char g[96], p[256];
  snprintf(c->name, sizeof c->name, "%s", wl_store_results_case_name(index));
  snprintf(g, sizeof g, "cases/%s", c->name);
  hid_t grp;
  enum wl_status st = open_group(file, file_name, g, &grp, err);
  if (st || grp < 0)
    return st;
  c->present = 1;
  st = read_keys(grp, file_name, g, CASE_KEYS, N_OF(CASE_KEYS), c, err);
  attr_text(grp, "stopped", c->stopped, sizeof c->stopped);
  H5Oclose(grp);
  if (st)
    return st;

  void *data;
  size_t rows, cols;
  snprintf(p, sizeof p, "%s/%s", g, TIME.name);
  st = read_dataset(file, file_name, p, H5T_NATIVE_DOUBLE, sizeof(double), &data, &rows, &cols,
                    err);
  if (st)
    return st;
  c->t = data;
  c->n = data ? rows : 0;
  for (size_t i = 0; !st && c->n && i < N_CASE_SERIES; i++) {
    snprintf(p, sizeof p, "%s/%s", g, CASE_SERIES[i].name);
    st = read_series(file, file_name, p, c->n,
                     (double **)(void *)((char *)c + CASE_SERIES[i].offset), err);
  }
  if (!st) {
    snprintf(p, sizeof p, "%s/%s", g, PROBE_Z.name);
    st = read_dataset(file, file_name, p, H5T_NATIVE_DOUBLE, sizeof(double), &data, &rows, &cols,
                      err);
    c->probe_z = data;
    c->n_probes = data ? rows : 0;
  }
  if (!st && c->n_probes) {
    snprintf(p, sizeof p, "%s/%s", g, PRESSURE.name);
    st = read_dataset(file, file_name, p, H5T_NATIVE_DOUBLE, sizeof(double), &data, &rows, &cols,
                      err);
    if (!st && data && rows == c->n && cols == c->n_probes)
      c->pressure = data;
    else
      free(data);
  }
  if (!st) {
    char names[WL_RESULTS_MAX_GAUGES][64];
    snprintf(p, sizeof p, "%s/gauges", g);
    int n_names = link_names(file, p, names, WL_RESULTS_MAX_GAUGES);
    for (int k = 0; !st && k < n_names; k++) {
      struct wl_results_gauge *ga = &c->gauges[c->n_gauges];
      snprintf(ga->name, sizeof ga->name, "%s", names[k]);
      snprintf(p, sizeof p, "%s/gauges/%s", g, names[k]);
      ga->x = NAN;
      hid_t gg = H5Oopen(file, p, H5P_DEFAULT);
      if (gg >= 0) {
        ga->x = attr_double(gg, "x");
        H5Oclose(gg);
      }
      snprintf(p, sizeof p, "%s/gauges/%s/%s", g, names[k], ETA.name);
      st = read_series(file, file_name, p, c->n, &ga->eta, err);
      if (!st && ga->eta)
        c->n_gauges++;
    }
    qsort(c->gauges, (size_t)c->n_gauges, sizeof c->gauges[0], by_x);
  }
  if (!st)
    case_finish(c);
  return st;
}

/* /convergence/<case>/ of case index i into *cv (left absent when the group
 * is not there). */
static enum wl_status read_convergence(hid_t file, const char *file_name, int i,
                                       struct wl_results_convergence *cv, struct wl_error *err) {
  char g[64], p[160];
  snprintf(g, sizeof g, "convergence/%s", wl_store_results_case_name(i));
  hid_t grp;
  enum wl_status st = open_group(file, file_name, g, &grp, err);
  if (st || grp < 0)
    return st;
  cv->present = 1;
  st = read_keys(grp, file_name, g, CONV_KEYS, N_OF(CONV_KEYS), cv, err);
  H5Oclose(grp);
  for (int k = 0; !st && k < wl_store_results_n_levels; k++) {
    void *data;
    size_t rows, cols;
    snprintf(p, sizeof p, "%s/%s", g, wl_store_results_levels[k].name);
    const int status = k == STATUS_COLUMN;
    st = read_dataset(file, file_name, p, status ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE,
                      status ? sizeof(int) : sizeof(double), &data, &rows, &cols, err);
    if (st || !data)
      continue;
    if (rows > WL_RESULTS_MAX_LEVELS)
      rows = WL_RESULTS_MAX_LEVELS;
    if (status) {
      memcpy(cv->status, data, rows * sizeof(int));
    } else {
      for (size_t l = 0; l < rows; l++)
        wl_store_results_level_set(cv, k, (int)l, ((const double *)data)[l]);
      if (k == 0 || (int)rows < cv->n_levels)
        cv->n_levels = (int)rows; /* the levels every dataset has */
    }
    free(data);
  }
  return st;
}

/* /settings: each "<key>" with its "<key>_origin". */
static void read_settings(hid_t file, struct wl_results *r) {
  hid_t grp = exists(file, "settings") ? H5Oopen(file, "settings", H5P_DEFAULT) : -1;
  if (grp < 0)
    return;
  H5O_info_t info;
  const size_t suffix = strlen(SETTING_ORIGIN);
  if (H5Oget_info(grp, &info) >= 0)
    for (hsize_t i = 0; i < info.num_attrs && r->n_settings < WL_RESULTS_MAX_SETTINGS; i++) {
      char name[64], origin[96], how[32];
      if (H5Aget_name_by_idx(grp, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name,
                             H5P_DEFAULT) <= 0)
        continue;
      size_t len = strlen(name);
      if (len >= suffix && !strcmp(name + len - suffix, SETTING_ORIGIN))
        continue;
      struct wl_results_setting *s = &r->settings[r->n_settings++];
      snprintf(s->key, sizeof s->key, "%s", name);
      attr_text(grp, name, s->value, sizeof s->value);
      snprintf(origin, sizeof origin, "%s%s", name, SETTING_ORIGIN);
      attr_text(grp, origin, how, sizeof how);
      s->given = !strcmp(how, "scenario");
    }
  H5Oclose(grp);
}

/* A load case's group under /plan, when stored (*present 1 then). */
static enum wl_status read_load_plan(hid_t file, const char *file_name, const struct load_plan *lp,
                                     void *base, int *present, double *x, double *z, size_t *n,
                                     struct wl_error *err) {
  hid_t grp;
  enum wl_status st = open_group(file, file_name, lp->group, &grp, err);
  if (st || grp < 0)
    return st;
  *present = 1;
  st = read_keys(grp, file_name, lp->group, lp->keys, lp->n_keys, base, err);
  H5Oclose(grp);
  char p[160];
  size_t nz = 0;
  snprintf(p, sizeof p, "%s/%s", lp->group, SURFACE_X.name);
  if (!st)
    st = read_fixed(file, file_name, p, x, WL_RESULTS_SURFACE_POINTS, n, err);
  snprintf(p, sizeof p, "%s/%s", lp->group, SURFACE_Z.name);
  if (!st)
    st = read_fixed(file, file_name, p, z, WL_RESULTS_SURFACE_POINTS, &nz, err);
  if (!st && nz != *n)
    *n = 0; /* a damaged drawing is not drawn */
  return st;
}

/* /plan and its load cases, when stored. */
static enum wl_status read_plan(hid_t file, const char *file_name, struct wl_results_plan *pl,
                                struct wl_error *err) {
  hid_t grp;
  enum wl_status st = open_group(file, file_name, "plan", &grp, err);
  if (st || grp < 0)
    return st;
  pl->present = 1;
  st = read_keys(grp, file_name, "plan", PLAN_KEYS, N_OF(PLAN_KEYS), pl, err);
  H5Oclose(grp);
  if (!st)
    st = read_fixed(file, file_name, "plan/bed_x", pl->bed_x, WL_RESULTS_MAX_BED, &pl->n_bed, err);
  size_t nz = 0;
  if (!st)
    st = read_fixed(file, file_name, "plan/bed_z", pl->bed_z, WL_RESULTS_MAX_BED, &nz, err);
  if (!st && nz != pl->n_bed)
    st = wl_error_set(err, WL_EINPUT,
                      "%s: /plan/bed_z: found %zu values; expected one a bed_x value (%zu)",
                      file_name, nz, pl->n_bed);
  size_t ng = 0;
  if (!st)
    st = read_fixed(file, file_name, "plan/gauge_x", pl->gauge_x, WL_RESULTS_MAX_GAUGES, &ng, err);
  if (!st && ng) {
    hid_t d = H5Oopen(file, "plan/gauge_x", H5P_DEFAULT);
    char *names = d >= 0 ? attr_text_alloc(d, GAUGE_NAMES) : NULL;
    if (d >= 0)
      H5Oclose(d);
    char *save = NULL, *tok = names ? strtok_r(names, "\n", &save) : NULL;
    for (; tok && pl->n_gauges < (int)ng; tok = strtok_r(NULL, "\n", &save))
      snprintf(pl->gauge_name[pl->n_gauges++], sizeof pl->gauge_name[0], "%s", tok);
    free(names);
    if (pl->n_gauges != (int)ng)
      st = wl_error_set(err, WL_EINPUT,
                        "%s: /plan/gauge_x: found %d names in '%s'; expected one a gauge (%zu)",
                        file_name, pl->n_gauges, GAUGE_NAMES, ng);
  }
  struct wl_results_solitary *ps = &pl->solitary;
  if (!st)
    st = read_load_plan(file, file_name, &SOLITARY_PLAN, ps, &ps->present, ps->surface_x,
                        ps->surface_z, &ps->n_surface, err);
  struct wl_results_explosion *px = &pl->explosion;
  if (!st)
    st = read_load_plan(file, file_name, &EXPLOSION_PLAN, px, &px->present, px->surface_x,
                        px->surface_z, &px->n_surface, err);
  return st;
}

/* The path a user gave: missing, a directory, not HDF5 or damaged is their
 * input (WL_EINPUT naming the file); *file open on WL_OK. */
static enum wl_status open_results(const char *path, hid_t *file, struct wl_error *err) {
  struct stat sb;
  if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode))
    return wl_error_set(err, WL_EINPUT,
                        "%s: is a directory; expected the results.h5 that `wallload assess` writes",
                        path);
  FILE *probe = fopen(path, "rb");
  if (!probe)
    return wl_error_set(err, WL_EINPUT, "%s: cannot open the results file: %s", path,
                        strerror(errno));
  fclose(probe);
  if (H5Fis_hdf5(path) <= 0)
    return wl_error_set(err, WL_EINPUT,
                        "%s: found a file that is not HDF5; expected the "
                        "results.h5 that `wallload assess` writes",
                        path);
  *file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (*file < 0)
    return wl_error_set(err, WL_EINPUT,
                        "%s: an HDF5 file that cannot be opened (truncated or damaged); expected "
                        "the results.h5 that `wallload assess` writes",
                        path);
  return WL_OK;
}

enum wl_status wl_store_results_read(const char *path, struct wl_results *r,
                                     struct wl_error *err) {
  wl_store_results_init(r);
  wl_store_hdf5_init(); /* wallload reports its own errors */
  if (!path || !*path)
    return wl_error_set(err, WL_EINPUT, "report: no results file given");
  if (strlen(path) >= sizeof r->path)
    return wl_error_set(err, WL_EINPUT, "%s: path longer than %zu bytes", path, sizeof r->path - 1);
  snprintf(r->path, sizeof r->path, "%s", path);
  snprintf(r->dir, sizeof r->dir, "%s", path);
  char *slash = strrchr(r->dir, '/');
  if (slash == r->dir)
    r->dir[1] = '\0';
  else if (slash)
    *slash = '\0';
  else
    snprintf(r->dir, sizeof r->dir, ".");
  hid_t file = -1;
  enum wl_status st = open_results(path, &file, err);
  if (st)
    return st;
  hid_t root = H5Gopen2(file, "/", H5P_DEFAULT);
  int has_name = root >= 0 && H5Aexists(root, "scenario_name") > 0;
  if (!has_name && !exists(file, "cases")) {
    st = wl_error_set(err, WL_EINPUT,
                      "%s: found no scenario_name attribute and no /cases group; expected the "
                      "results.h5 that `wallload assess` writes",
                      path);
  } else if (root >= 0) {
    st = read_keys(root, path, "", ROOT_KEYS, N_OF(ROOT_KEYS), r, err);
    r->scenario_text = attr_text_alloc(root, "scenario_text");
    if (!r->scenario_text)
      r->scenario_text = strdup("");
    if (!r->scenario_text && !st)
      st = wl_error_set(err, WL_ENOMEM, "%s: no memory", path);
  }
  if (root >= 0)
    H5Gclose(root);
  if (!st) {
    r->scenario_len = strlen(r->scenario_text);
    r->has_convergence = exists(file, "convergence");
    read_settings(file, r);
    st = read_plan(file, path, &r->plan, err);
  }
  for (int i = 0; !st && i < WL_RESULTS_N_CASES; i++) {
    st = read_case(file, path, i, &r->cases[i], err);
    if (r->cases[i].present)
      r->n_cases++;
  }
  for (int i = 0; !st && r->has_convergence && i < WL_RESULTS_N_CASES; i++)
    st = read_convergence(file, path, i, &r->conv[i], err);
  H5Fclose(file);
  if (st)
    wl_store_results_clear(r);
  return st;
}

/* ---- particle snapshots --------------------------------------------------------- */

static int by_time(const void *a, const void *b) {
  const struct wl_results_snapshot_ref *ra = a, *rb = b;
  return ra->time < rb->time ? -1 : ra->time > rb->time ? 1 : strcmp(ra->group, rb->group);
}

enum wl_status wl_store_snapshot_list(const char *path, struct wl_results_snapshot_ref **refs,
                                      size_t *n, struct wl_error *err) {
  *refs = NULL, *n = 0;
  wl_store_hdf5_init();
  FILE *probe = fopen(path, "rb");
  if (!probe) /* named by the results file: a results set missing a file */
    return wl_error_set(err, WL_EINPUT, "%s: cannot open the particle snapshots: %s", path,
                        strerror(errno));
  fclose(probe);
  hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0)
    return wl_error_set(err, WL_EINPUT,
                        "%s: cannot open the particle snapshots (HDF5: truncated or damaged)", path);
  enum wl_status st = WL_OK;
  hid_t g = exists(file, "snapshots") ? H5Gopen2(file, "snapshots", H5P_DEFAULT) : -1;
  H5G_info_t info;
  if (g >= 0 && H5Gget_info(g, &info) >= 0 && info.nlinks > 0) {
    struct wl_results_snapshot_ref *out = malloc((size_t)info.nlinks * sizeof *out);
    if (!out)
      st = wl_error_set(err, WL_ENOMEM, "%s: no memory for the snapshot list", path);
    size_t k = 0;
    for (hsize_t i = 0; out && i < info.nlinks; i++) {
      char name[32];
      if (H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name,
                             H5P_DEFAULT) <= 0)
        continue;
      hid_t s = H5Gopen2(g, name, H5P_DEFAULT);
      if (s < 0)
        continue;
      double t = attr_double(s, "time");
      H5Gclose(s);
      if (!isfinite(t))
        continue;
      snprintf(out[k].group, sizeof out[k].group, "snapshots/%s", name);
      out[k++].time = t;
    }
    if (out) {
      qsort(out, k, sizeof *out, by_time);
      *refs = out, *n = k;
    }
  }
  if (g >= 0)
    H5Gclose(g);
  H5Fclose(file);
  return st;
}

enum wl_status wl_store_snapshot_read(const char *path, const char *group,
                                      enum wl_results_quantity q, double **x, double **z,
                                      double **value, int **kind, size_t *n,
                                      struct wl_error *err) {
  *x = *z = *value = NULL, *kind = NULL, *n = 0;
  wl_store_hdf5_init();
  hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0)
    return wl_error_set(err, WL_EINPUT,
                        "%s: cannot open the particle snapshots (HDF5: missing, truncated or damaged)",
                        path);
  char p[160];
  void *pos = NULL, *vq = NULL, *kd = NULL;
  size_t rows = 0, cols = 0, rq = 0, cq = 0, rk = 0, ck = 0;
  snprintf(p, sizeof p, "%s/position", group);
  enum wl_status st =
      read_dataset(file, path, p, H5T_NATIVE_DOUBLE, sizeof(double), &pos, &rows, &cols, err);
  const char *qname = q == WL_RESULTS_Q_PRESSURE ? "p" : q == WL_RESULTS_Q_SPEED ? "velocity" : "rho";
  if (!st) {
    snprintf(p, sizeof p, "%s/%s", group, qname);
    st = read_dataset(file, path, p, H5T_NATIVE_DOUBLE, sizeof(double), &vq, &rq, &cq, err);
  }
  if (!st) {
    snprintf(p, sizeof p, "%s/kind", group);
    st = read_dataset(file, path, p, H5T_NATIVE_INT, sizeof(int), &kd, &rk, &ck, err);
  }
  H5Fclose(file);
  if (!st && (!pos || cols < 2 || !vq || rq != rows || !kd || rk != rows))
    st = wl_error_set(err, WL_EINPUT,
                      "%s: %s: found incomplete particle data; expected position (n x 3), %s and "
                      "kind of equal length",
                      path, group, qname);
  double *ox = NULL, *oz = NULL, *ov = NULL;
  if (!st) {
    ox = malloc((rows ? rows : 1) * sizeof *ox);
    oz = malloc((rows ? rows : 1) * sizeof *oz);
    ov = malloc((rows ? rows : 1) * sizeof *ov);
    if (!ox || !oz || !ov)
      st = wl_error_set(err, WL_ENOMEM, "%s: no memory for %zu particles", path, rows);
  }
  if (!st) {
    const double *ps = pos, *vs = vq;
    for (size_t i = 0; i < rows; i++) {
      ox[i] = ps[i * cols];
      oz[i] = ps[i * cols + cols - 1];
      if (q == WL_RESULTS_Q_SPEED) {
        double s2 = 0;
        for (size_t c = 0; c < cq; c++)
          s2 += vs[i * cq + c] * vs[i * cq + c];
        ov[i] = sqrt(s2);
      } else {
        ov[i] = vs[i * cq];
      }
    }
    *x = ox, *z = oz, *value = ov, *kind = kd, *n = rows;
    kd = NULL;
  } else {
    free(ox), free(oz), free(ov);
  }
  free(pos), free(vq), free(kd);
  return st;
}
