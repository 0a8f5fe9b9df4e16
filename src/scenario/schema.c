/* schema.c: every scenario key: type, unit dimension, range, choices, default.
 *
 * This table is the schema: the parser, the "did you mean" suggestions, the
 * defaults and `wallload check`'s listing all read it, so a new key is one
 * row here and one member in struct wl_scenario. */
#include "schema.h"
#include "wallload/sph/params.h"

#include <math.h>
#include <stddef.h>

#define OFF(member) offsetof(struct wl_scenario, member)
#define BED(member) offsetof(struct wl_scenario_bed, member)
#define GAUGE(member) offsetof(struct wl_scenario_gauge, member)
#define NONE NAN
#define NO_FLAG ((size_t)-1)

static const char *const theory_choices[] = {"grimshaw", "boussinesq", "exact", NULL};
static const char *const generation_choices[] = {"paddle", "initial", NULL};
static const char *const shape_choices[] = {"quadratic", "quadratic-lip", "quartic-lip", NULL};
static const char *const lip_choices[] = {"auto", "plane", "axisymmetric", NULL};
static const char *const basis_choices[] = {"per-width", "seed-001", NULL};
static const char *const model_choices[] = {"crater", "thrown-mass", NULL};
static const char *const backend_choices[] = {"auto", "cpu", "cuda", NULL};
static const char *const viscosity_choices[] = {"artificial", "laminar", NULL};
static const char *const onoff_choices[] = {"off", "on", NULL};
static const char *const boundary_choices[] = {"adami", "dbc", NULL}; /* wl_boundary_choice */
static const char *const integrator_choices[] = {"symplectic", "verlet", NULL};
static const char *const far_end_choices[] = {"wall", "damping", NULL};
static const char *const symmetry_choices[] = {"auto", "none", "centreline", NULL};
static const char *const side_wall_choices[] = {"free-slip", "particles", NULL};
static const char *const still_reference_choices[] = {"auto", "on", "off", NULL};

/* Ranges are in SI. lo_open/hi_open: the bound itself is excluded. */

static const struct wl_key water_keys[] = {
    {"depth", KT_QTY, WL_DIM_LENGTH, OFF(water.depth), NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG,
     1, "still-water depth at the paddle"},
    {"density", KT_QTY, WL_DIM_DENSITY, OFF(water.density), NULL, 500, 2000, 0, 0, "1000 kg/m^3",
     NULL, NO_FLAG, 0, "water density"},
    {"gravity", KT_QTY, WL_DIM_ACCELERATION, OFF(water.gravity), NULL, 0.1, 100, 0, 0, "9.81 m/s^2",
     NULL, NO_FLAG, 0, "gravitational acceleration"},
    {0}};

static const struct wl_key domain_keys[] = {
    {"dimensions", KT_INT_OR_AUTO, WL_DIM_NONE, OFF(domain.dimensions), NULL, 2, 3, 0, 0, "auto",
     NULL, NO_FLAG, 0,
     "2 (a flume section), 3, or auto (2D unless an explosion's axisymmetric crater, from a "
     "charge or eta0 + r0, is narrower than the flume: 3D)"},
    {"length", KT_QTY, WL_DIM_LENGTH, OFF(domain.length), NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG,
     1, "flume length from the paddle"},
    {"width", KT_QTY, WL_DIM_LENGTH, OFF(domain.width), NULL, 0, NONE, 1, 0, "1 m", NULL, NO_FLAG,
     0, "flume width (3D runs; totals per wall in 2D)"},
    {"far_end", KT_ENUM, WL_DIM_NONE, OFF(domain.far_end), far_end_choices, NONE, NONE, 0, 0,
     "wall", NULL, NO_FLAG, 0,
     "what closes the flume behind the seawall: wall, or damping (overtopping water is brought "
     "to rest over the far half of the land)"},
    {"symmetry", KT_ENUM, WL_DIM_NONE, OFF(domain.symmetry), symmetry_choices, NONE, NONE, 0, 0,
     "auto", NULL, NO_FLAG, 0,
     "3D: centreline (model half the width, a symmetry plane on the flume's centreline; the "
     "width rounds to an even number of rows), none (the whole width), or auto (centreline when "
     "the width is an even number of rows of dp: the flume, its wall and its load cases are "
     "symmetric about it)"},
    {"side_walls", KT_ENUM, WL_DIM_NONE, OFF(domain.side_walls), side_wall_choices, NONE, NONE, 0,
     0, "free-slip", NULL, NO_FLAG, 0,
     "3D: free-slip (mirror planes: a smooth wall, no boundary particles) or particles (boundary "
     "particles under numerics.boundary, which drag on a narrow flume)"},
    {0}};

static const struct wl_key wall_keys[] = {
    {"x", KT_QTY, WL_DIM_LENGTH, OFF(wall.x), NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG, 1,
     "position of the seawall's seaward face, from the paddle"},
    {"height", KT_QTY, WL_DIM_LENGTH, OFF(wall.height), NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG,
     1, "height of the wall above the bed at its toe"},
    {"probes", KT_INT, WL_DIM_NONE, OFF(wall.probes), NULL, 2, 1000, 0, 0, "20", NULL, NO_FLAG, 0,
     "number of pressure probes over the wall face"},
    {0}};

static const struct wl_key solitary_keys[] = {
    {"height", KT_QTY, WL_DIM_LENGTH, OFF(solitary.height), NULL, 0, NONE, 1, 0, NULL, NULL,
     NO_FLAG, 1, "solitary-wave height H above still water"},
    {"theory", KT_ENUM, WL_DIM_NONE, OFF(solitary.theory), theory_choices, NONE, NONE, 0, 0,
     "grimshaw", NULL, NO_FLAG, 0, "profile and velocities (seed 003 eqs 21-24 or first order)"},
    {"generation", KT_ENUM, WL_DIM_NONE, OFF(solitary.generation), generation_choices, NONE, NONE,
     0, 0, "paddle", NULL, NO_FLAG, 0, "piston paddle (Goring 1978) or initial condition"},
    {"at", KT_QTY_OR_AUTO, WL_DIM_LENGTH, OFF(solitary.at), NULL, 0, NONE, 0, 0, "auto", NULL,
     NO_FLAG, 0, "crest position for an initial-condition wave"},
    {0}};

static const struct wl_key explosion_keys[] = {
    {"charge", KT_QTY, WL_DIM_MASS, OFF(explosion.charge), NULL, 0, NONE, 1, 0, NULL, NULL,
     NO_FLAG, 0, "charge weight (TNT)"},
    {"energy", KT_QTY_OR_SAME, WL_DIM_ENERGY, OFF(explosion.energy), NULL, 0, NONE, 1, 0, NULL,
     NULL, NO_FLAG, 0, "crater (wave) energy, or same-as-solitary"},
    {"eta0", KT_QTY, WL_DIM_LENGTH, OFF(explosion.eta0), NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG,
     0, "crater depth (with r0, instead of charge or energy)"},
    {"r0", KT_QTY, WL_DIM_LENGTH, OFF(explosion.r0), NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG, 0,
     "crater radius at the lip (with eta0)"},
    {"at", KT_QTY, WL_DIM_LENGTH, OFF(explosion.at), NULL, 0, NONE, 0, 0, NULL, NULL, NO_FLAG, 1,
     "position of the explosion centre, from the paddle"},
    {"shape", KT_ENUM, WL_DIM_NONE, OFF(explosion.shape), shape_choices, NONE, NONE, 0, 0,
     "quadratic-lip", NULL, NO_FLAG, 0, "initial crater (seed 000 eqs 1-3)"},
    {"lip_form", KT_ENUM, WL_DIM_NONE, OFF(explosion.lip_form), lip_choices, NONE, NONE, 0, 0,
     "auto", NULL, NO_FLAG, 0,
     "auto: the mass-conserving form for the dimension (plane in 2D, axisymmetric in 3D)"},
    {"energy_basis", KT_ENUM, WL_DIM_NONE, OFF(explosion.energy_basis), basis_choices, NONE, NONE,
     0, 0, "per-width", NULL, NO_FLAG, 0,
     "how same-as-solitary matches energies: per metre of crest, or as seed 001 Table 4"},
    {"coefficient", KT_QTY, WL_DIM_NONE, OFF(explosion.coefficient), NULL, 0, NONE, 1, 0, "35",
     NULL, NO_FLAG, 0, "Hmax*r/W^0.54 in ft and lb (Whalin 34, Le Mehaute 36, mean 35)"},
    {"wave_fraction", KT_QTY, WL_DIM_RATIO, OFF(explosion.wave_fraction), NULL, 0, 1, 1, 0, "40 %",
     NULL, NO_FLAG, 0, "share of chemical energy that can make waves (seed 000 eq 9; a ceiling)"},
    {"model", KT_ENUM, WL_DIM_NONE, OFF(explosion.model), model_choices, NONE, NONE, 0, 0, "crater",
     NULL, NO_FLAG, 0, "initial crater, or thrown mass (seed 000)"},
    {"thrown_parts", KT_INT, WL_DIM_NONE, OFF(explosion.thrown_parts), NULL, 1, 5, 0, 0, "3", NULL,
     NO_FLAG, 0, "1, 3 or 5 parts of thrown mass"},
    {0}};

static const struct wl_key loads_keys[] = {
    {"solitary", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, solitary_keys,
     OFF(solitary.present), 0, "a solitary-wave load case"},
    {"explosion", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, explosion_keys,
     OFF(explosion.present), 0, "an explosion-wave load case"},
    {0}};

static const struct wl_key refine_keys[] = {
    {"from", KT_QTY_OR_AUTO, WL_DIM_LENGTH, OFF(resolution.refine.from), NULL, 0, NONE, 1, 0,
     NULL, NULL, NO_FLAG, 1,
     "where the fine level begins, from the paddle, over a flat bed: from here to the wall the "
     "water is at dp, seaward of it at 2 dp; or auto (the plan places it two depths seaward of "
     "the first change of the bed, for the solitary case, where the coarse level holds 4 "
     "particles a wave height; the explosion and GPU runs keep one resolution)"},
    {0}};

static const struct wl_key resolution_keys[] = {
    {"dp", KT_QTY_OR_AUTO, WL_DIM_LENGTH, OFF(resolution.dp), NULL, 0, NONE, 1, 0, "auto", NULL,
     NO_FLAG, 0, "particle spacing, or auto (from particles_per_height)"},
    {"particles_per_height", KT_QTY_OR_AUTO, WL_DIM_NONE, OFF(resolution.particles_per_height),
     NULL, 2, 1000, 0, 0, "10", NULL, NO_FLAG, 0,
     "particles over the smallest wave height when dp is auto, or auto (planned to the machine: "
     "the finest of 2, 2.83, 4, 5.66 whose ladder runs within 20 min)"},
    {"target_error", KT_QTY, WL_DIM_RATIO, OFF(resolution.target_error), NULL, 0, 1, 1, 0, "5 %",
     NULL, NO_FLAG, 0, "relative error at which a convergence ladder stops"},
    {"realisations", KT_INT_OR_AUTO, WL_DIM_NONE, OFF(resolution.realisations), NULL, 1,
     WL_SCENARIO_MAX_REALISATIONS, 0, 0, "auto", NULL, NO_FLAG, 0,
     "explosion runs per convergence level, its crater placed at n offsets within one particle "
     "spacing; the loads quoted are their mean (the explosion's collapse is chaotic: one run is "
     "one realisation), or auto (8 where the ladder runs on a GPU, else 1)"},
    {"convergence", KT_LEVELS, WL_DIM_NONE, 0, NULL, 0, 1, 1, 0, NULL, NULL, NO_FLAG, 0,
     "list of dp factors, e.g. [1, 0.71, 0.5]"},
    {"refine", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, refine_keys,
     OFF(resolution.refine.present), 0,
     "two resolutions in one run (2D; docs/variable-resolution.md): dp at the wall, "
     "2 dp seaward of `from`"},
    {0}};

static const struct wl_key run_keys[] = {
    {"end_time", KT_QTY_OR_AUTO, WL_DIM_TIME, OFF(run.end_time), NULL, 0, 1e5, 1, 0, "auto", NULL,
     NO_FLAG, 0, "simulated time, or auto (wave travel to the wall and load decay)"},
    {"output_interval", KT_QTY, WL_DIM_TIME, OFF(run.output_interval), NULL, 1e-5, NONE, 0, 0,
     "0.01 s", NULL, NO_FLAG, 0, "sampling interval of gauges and wall loads"},
    {"backend", KT_ENUM, WL_DIM_NONE, OFF(run.backend), backend_choices, NONE, NONE, 0, 0, "auto",
     NULL, NO_FLAG, 0, "where the solver runs"},
    {"threads", KT_INT_OR_AUTO, WL_DIM_NONE, OFF(run.threads), NULL, 1, 4096, 0, 0, "auto", NULL,
     NO_FLAG, 0, "CPU threads, or auto (all cores, at most one per 4000 particles)"},
    {"still_reference", KT_ENUM, WL_DIM_NONE, OFF(run.still_reference), still_reference_choices,
     NONE, NONE, 0, 0, "auto", NULL, NO_FLAG, 0,
     "run each case's flume once more with still water and take the wall force's drift in it "
     "out of the impulses (on, off, or auto: the explosion's case, whose load is a small part of "
     "the force at rest over a long record)"},
    {0}};

static const struct wl_key numerics_keys[] = {
    {"coefh", KT_QTY_OR_AUTO, WL_DIM_NONE, OFF(numerics.coefh), NULL, WL_SPH_COEFH_MIN,
     WL_SPH_COEFH_MAX, 0, 0, "auto",
     NULL, NO_FLAG, 0,
     "h = coefh*sqrt(dim)*dp (DualSPHysics convention), or auto: 1.2 in 2D, 1.0 in 3D (h = 1.7 dp)"},
    {"coefsound", KT_QTY, WL_DIM_NONE, OFF(numerics.coefsound), NULL,
     WL_SPH_COEFSOUND_MIN, WL_SPH_COEFSOUND_MAX, 0, 0, "10", NULL,
     NO_FLAG, 0, "c0 = coefsound*sqrt(g*h_max)"},
    {"cfl", KT_QTY, WL_DIM_NONE, OFF(numerics.cfl), NULL, WL_SPH_CFL_MIN_OPEN,
     WL_SPH_CFL_MAX, 1, 0, "0.2", NULL, NO_FLAG, 0,
     "Courant number of the variable time step"},
    {"alpha", KT_QTY, WL_DIM_NONE, OFF(numerics.alpha), NULL, 0, WL_SPH_ALPHA_MAX, 0, 0, "0.01", NULL, NO_FLAG, 0,
     "artificial viscosity coefficient"},
    {"viscosity", KT_ENUM, WL_DIM_NONE, OFF(numerics.viscosity), viscosity_choices, NONE, NONE, 0,
     0, "laminar", NULL, NO_FLAG, 0, "viscosity model"},
    {"nu", KT_QTY, WL_DIM_NONE, OFF(numerics.nu), NULL, 0, WL_SPH_NU_MAX, 0, 0, "1e-6", NULL, NO_FLAG, 0,
     "kinematic viscosity for the laminar model [m^2/s]"},
    {"density_diffusion", KT_QTY, WL_DIM_NONE, OFF(numerics.density_diffusion), NULL, 0,
     WL_SPH_DELTA_MAX, 0, 0,
     "0.1", NULL, NO_FLAG, 0, "delta-SPH coefficient (0 switches it off; wall pressure is noise then)"},
    {"residual_viscosity", KT_QTY, WL_DIM_NONE, OFF(numerics.residual_viscosity), NULL, 0,
     WL_SPH_ALPHA_MAX, 0, 0, "0", NULL, NO_FLAG, 0,
     "alpha of the residual viscosity: artificial viscosity on the velocity's departure from its "
     "linear field (0: off; docs/numerics.md)"},
    {"smagorinsky", KT_QTY, WL_DIM_NONE, OFF(numerics.smagorinsky), NULL, 0,
     WL_SPH_SMAGORINSKY_MAX, 0, 0, "0", NULL, NO_FLAG, 0,
     "Smagorinsky constant C_s of the eddy viscosity (C_s dp)^2 |S| added to nu (0: off; "
     "0.12 as DualSPHysics' Laminar+SPS; docs/numerics.md)"},
    {"shifting", KT_ENUM, WL_DIM_NONE, OFF(numerics.shifting), onoff_choices, NONE, NONE, 0, 0,
     "off", NULL, NO_FLAG, 0, "particle shifting"},
    {"integrator", KT_ENUM, WL_DIM_NONE, OFF(numerics.integrator), integrator_choices, NONE, NONE,
     0, 0, "symplectic", NULL, NO_FLAG, 0,
     "time integrator: symplectic (two force evaluations a step) or verlet (one; about twice as "
     "fast)"},
    {"verlet_steps", KT_INT, WL_DIM_NONE, OFF(numerics.verlet_steps), NULL, 1,
     WL_SPH_VERLET_STEPS_MAX, 0, 0, "40",
     NULL, NO_FLAG, 0, "verlet: an Euler step every this many steps (DualSPHysics VerletSteps)"},
    {"boundary", KT_ENUM, WL_DIM_NONE, OFF(numerics.boundary), boundary_choices, NONE, NONE, 0, 0,
     "adami", NULL, NO_FLAG, 0,
     "wall condition: adami (boundary particles take the fluid's pressure, Adami et al. 2012) or "
     "dbc (dynamic boundary particles, as DualSPHysics' DBC)"},
    {0}};

static const struct wl_key report_keys[] = {
    {"template", KT_STR, WL_DIM_NONE, OFF(report.template_name), NULL, NONE, NONE, 0, 0, "design",
     NULL, NO_FLAG, 0, "report template in report_templates/"},
    {0}};

/* Each parameter's limits are its target key's (loads.explosion.charge,
 * ...); what a value does to the rest of the scenario (a standoff beyond
 * the paddle, a depth that floods the wall) is checked on each case
 * (src/sweep). */
const struct wl_key wl_schema_sweep_keys[] = {
    {"charge", KT_QTY, WL_DIM_MASS, WL_SWEEP_CHARGE, NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG, 0,
     "charge weights (TNT) for loads.explosion.charge"},
    {"energy", KT_QTY, WL_DIM_ENERGY, WL_SWEEP_ENERGY, NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG, 0,
     "crater (wave) energies for loads.explosion.energy"},
    {"standoff", KT_QTY, WL_DIM_LENGTH, WL_SWEEP_STANDOFF, NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG,
     0, "distances of the explosion centre seaward of the wall's face (loads.explosion.at = "
        "wall.x - standoff)"},
    {"depth", KT_QTY, WL_DIM_LENGTH, WL_SWEEP_DEPTH, NULL, 0, NONE, 1, 0, NULL, NULL, NO_FLAG, 0,
     "still-water depths for water.depth"},
    {"solitary_height", KT_QTY, WL_DIM_LENGTH, WL_SWEEP_SOLITARY_HEIGHT, NULL, 0, NONE, 1, 0, NULL,
     NULL, NO_FLAG, 0, "solitary-wave heights for loads.solitary.height"},
    {0}};

static const char *const spacing_choices[] = {"linear", "log", NULL}; /* wl_sweep_spacing */

#define RANGE(member) offsetof(struct wl_sweep_range, member)
const struct wl_key wl_schema_sweep_range_keys[] = {
    {"from", KT_QTY, WL_DIM_NONE, RANGE(from), NULL, NONE, NONE, 0, 0, NULL, NULL, NO_FLAG, 1,
     "first value"},
    {"to", KT_QTY, WL_DIM_NONE, RANGE(to), NULL, NONE, NONE, 0, 0, NULL, NULL, NO_FLAG, 1,
     "last value"},
    {"count", KT_INT, WL_DIM_NONE, RANGE(count), NULL, 1, WL_SCENARIO_MAX_SWEEP_VALUES, 0, 0, NULL,
     NULL, NO_FLAG, 1, "number of values from `from` to `to`, both included"},
    {"spacing", KT_ENUM, WL_DIM_NONE, RANGE(spacing), spacing_choices, NONE, NONE, 0, 0, "linear",
     NULL, NO_FLAG, 0, "linear (equal steps) or log (equal ratios)"},
    {0}};
#undef RANGE

const struct wl_key wl_schema_bed_keys[] = {
    {"from", KT_QTY, WL_DIM_LENGTH, BED(from), NULL, 0, NONE, 0, 0, NULL, NULL, NO_FLAG, 1,
     "where the segment starts, from the paddle"},
    {"slope", KT_QTY, WL_DIM_RATIO, BED(slope), NULL, -1, 1, 0, 0, NULL, NULL, NO_FLAG, 1,
     "rise over run, e.g. 1/5.7 (0 for flat)"},
    {0}};

const struct wl_key wl_schema_gauge_keys[] = {
    {"name", KT_STR, WL_DIM_NONE, GAUGE(name), NULL, NONE, NONE, 0, 0, NULL, NULL, NO_FLAG, 1,
     "gauge name"},
    {"x", KT_QTY, WL_DIM_LENGTH, GAUGE(x), NULL, 0, NONE, 0, 0, NULL, NULL, NO_FLAG, 1,
     "gauge position from the paddle"},
    {0}};

const struct wl_key wl_schema_top[] = {
    {"scenario", KT_STR, WL_DIM_NONE, OFF(name), NULL, NONE, NONE, 0, 0, NULL, NULL, NO_FLAG, 1,
     "the scenario's name"},
    {"description", KT_STR, WL_DIM_NONE, OFF(description), NULL, NONE, NONE, 0, 0, "", NULL,
     NO_FLAG, 0, "free text"},
    {"water", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, water_keys, NO_FLAG, 1,
     "water properties"},
    {"domain", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, domain_keys, NO_FLAG, 1,
     "the flume"},
    {"bathymetry", KT_BED, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, wl_schema_bed_keys,
     NO_FLAG, 0, "list of bed segments {from, slope}; flat bed when absent"},
    {"wall", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, wall_keys, NO_FLAG, 1,
     "the seawall"},
    {"gauges", KT_GAUGES, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, wl_schema_gauge_keys,
     NO_FLAG, 0, "list of wave gauges {name, x}"},
    {"loads", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, loads_keys, NO_FLAG, 1,
     "load cases: solitary and/or explosion"},
    {"resolution", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, resolution_keys, NO_FLAG,
     0, "particle spacing and convergence ladder"},
    {"run", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, run_keys, NO_FLAG, 0,
     "run control"},
    {"numerics", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, numerics_keys, NO_FLAG, 0,
     "SPH settings"},
    {"report", KT_MAP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, report_keys, NO_FLAG, 0,
     "design report"},
    {"sweep", KT_SWEEP, WL_DIM_NONE, 0, NULL, NONE, NONE, 0, 0, NULL, wl_schema_sweep_keys, NO_FLAG,
     0, "parameters to vary for `wallload sweep`: each a list of values or a range {from, to, "
        "count, spacing}"},
    {0}};
