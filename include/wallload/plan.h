/* plan.h: from a validated scenario to what will be simulated.
 *
 * The plan turns the scenario's load cases into initial conditions with the
 * wave and explosion formulae (solitary wave of height H; explosion from a
 * charge, a crater, an energy, or the energy of the solitary wave), and
 * chooses what the scene needs: dimension, particle spacing, end time, and
 * the cost (particles, memory, steps, runtime) that `wallload check` prints
 * before anything runs.
 *
 * Equal energy (loads.explosion.energy: same-as-solitary), two bases:
 *  - per-width (default): the solitary wave's energy per metre of crest,
 *    integrated from its profile and velocity field, equals the potential
 *    energy per metre of the crater simulated in the 2D flume; charge weight,
 *    R0 and eta0 then follow from Van Dorn (R0 = 9.6 W^0.3) and Whalin /
 *    Le Mehaute (eta0 R0 = 0.81 C W^0.54) in feet and pounds. Since the 2D
 *    crater energy scales as eta0^2 R0 ~ W^0.78, W follows in closed form.
 *    In 3D the solitary energy times the flume width equals the crater's.
 *  - seed-001: as seed 001 section 3.1.3 and Table 4: the solitary energy is
 *    Longuet-Higgins' E = 0.958 rho g h^3 (the energy of the HIGHEST solitary
 *    wave on depth h, whatever H is), in J/m, equated to the 3D crater
 *    energy pi rho g eta0^2 R0^2 / 6 in J. It reproduces the paper's craters
 *    (eta0 = 0.23 m, R0 = 1.3 m for Yu Yao's flume), but it compares a
 *    per-metre energy with a total one and overstates the 0.05 m wave's
 *    energy about elevenfold; `check` prints both numbers. */
#ifndef WALLLOAD_PLAN_H
#define WALLLOAD_PLAN_H

#include <stdio.h>

#include "wallload/error.h"
#include "wallload/explosion.h"
#include "wallload/scenario.h"
#include "wallload/sph/params.h"
#include "wallload/waves.h"

enum wl_explosion_source { WL_SOURCE_CHARGE, WL_SOURCE_ENERGY, WL_SOURCE_SOLITARY, WL_SOURCE_CRATER };

struct wl_plan_solitary {
  int present;
  struct wl_solitary wave;             /* theory, h, H, celerity */
  struct wl_wave_integrals integrated; /* quadrature of the theory's field, per metre */
  struct wl_wave_integrals first_order;/* first-order closed forms, per metre */
  double energy_seed001;               /* 0.958 rho g h^3 [J/m], seed 001 eq 22 */
  int paddle;                          /* 1: Goring paddle; 0: initial condition */
  struct wl_goring goring;             /* the paddle motion when paddle = 1 */
  double crest_x0;                     /* initial crest position [m] (initial condition) */
  int fits;                            /* 1: the crest starts seaward of the wall */
  double arrival_time;                 /* crest at the wall, estimated [s] */
  double quiet_until;                  /* the wall's force at rest until then [s] (below) */
  double h_max;                        /* still water plus the wave: sets c0 [m] */
  double c0, dt;                       /* speed of sound [m/s]; CFL time step at rest [s]: what
                                          the flume gives the solver */
  double end_time;                     /* simulated time of this case [s] */
  double x_left;                       /* the modelled flume starts here [m] */
  int refine;                          /* runs at two resolutions (resolution.refine) */
  int still_reference;                 /* 1: the still-water reference run too (below) */
  long n_fluid, n_boundary;            /* estimated particles */
  double particle_steps;               /* estimated to end_time, one run */
};

struct wl_plan_explosion {
  int present;
  enum wl_explosion_source source;
  enum wl_energy_basis_choice basis;
  double matched_energy;            /* energy the crater was sized to [J/m (2D per-width) or J] */
  struct wl_explosion_chain chain;  /* charge <-> R0, eta0 <-> 3D crater energy */
  enum wl_crater_shape shape;       /* the shape simulated (lip form resolved) */
  int conserves_mass;               /* the shape's net volume is zero in these dims */
  double eta0, r0;                  /* simulated crater depth and radius [m] */
  double extent;                    /* outer radius of the disturbance [m] */
  double rise;                      /* highest initial water above still water, which sets c0
                                       with the depth: the crater's lip crest
                                       (wl_explosion_rim_height), 2 eta0 for the thrown mass [m] */
  double absorber;                  /* length of the absorbing zone at the flume's seaward
                                       end, x_left .. x_left + absorber [m] (0: none) */
  double net_volume;                /* [m^2 per metre (2D) or m^3] */
  double energy;                    /* potential energy of the simulated crater, closed form
                                       [J/m in 2D, J in 3D] */
  double energy_quad;               /* the same by quadrature of seed 000 eq 4 */
  double x_center;                  /* [m] */
  double wave_fraction;             /* scenario's share of chemical energy (a ceiling) */
  double fraction_energy;           /* wave_fraction x chemical energy [J] */
  int model_thrown;                 /* 1: thrown mass (seed 000) */
  int thrown_parts;
  double arrival_time;              /* leading wave at the wall, estimated [s] */
  double quiet_until;               /* the wall's force at rest until then [s] (below) */
  double h_max;                     /* still water plus the lip's crest: sets c0 [m] */
  double collapse_speed;            /* sqrt(2 g (rise + eta0)): water falling from the lip's
                                       crest to the crater's floor [m/s] */
  double expected_speed;            /* the largest flow speed the flume tells the solver
                                       (sph/params.h; c0 is at least WL_SPH_MACH_FACTOR
                                       times it): collapse_speed in 3D, 0 in 2D
                                       (docs/numerics.md, the Mach rule) */
  double c0, dt;                    /* as the solitary case's */
  double end_time;                  /* simulated time of this case [s] */
  double x_left;                    /* the modelled flume starts here [m] */
  int refine;                          /* runs at two resolutions (resolution.refine) */
  int still_reference;              /* 1: the still-water reference run too (below) */
  long n_fluid, n_boundary;         /* estimated particles */
  double particle_steps;            /* estimated to end_time, one run */
};

/* The still-water reference run (run.still_reference; docs/outputs.md):
 * the case's flume as planned (its crop, absorbing zone, spacing, c0, end
 * time and numerics) with still water and no wave, run to the case's end
 * time. The model's still water is not still at the wall: its start-up
 * moves the water level there by a few per cent of a thin depth (the main
 * job's platform, 0.06 m: +2 mm at dp = 0.0086 m from t = 3 s on, -1 mm
 * at 0.0043 m), which lifts or lowers the wall's force by up to 10 % of
 * its force at rest long after the rest window, and an impulse integrated
 * over a 15 s record takes it in: the explosion's positive impulse moved
 * by 12 % over the ladder's two finest levels for it. The loads' impulses
 * subtract that drift (the reference run's filtered force less its own
 * force at rest) as well as the force at rest (loads.h). auto: the
 * explosion's case; on: both cases; off: neither. A ladder runs it once a
 * level, beside the first realisation (its crater's flume). */

/* quiet_until (both load cases): the last time the wave leaves the wall's
 * force at rest alone, so that assess can read the model's own force at
 * rest before it (loads.h, the rest window). The solitary wave: when its
 * front, H sech^2(K s) at the distance s from its crest (Grimshaw's K as
 * the plan's wave length), raises the water at the wall by
 * WL_PLAN_QUIET_RISE of the depth there, about twice that share of the
 * force at rest; the crest's travel as arrival_time's. The explosion: half
 * the leading wave's arrival, which travels at the long-wave speed
 * sqrt(g d), the fastest a gravity wave goes. */
#define WL_PLAN_QUIET_RISE 1e-3

enum { WL_PLAN_MAX_NOTES = 12 };

struct wl_plan {
  int dims;
  double h, rho, g;                 /* still-water depth [m], density, gravity */
  struct wl_plan_solitary solitary;
  struct wl_plan_explosion explosion;
  double dp;                        /* particle spacing [m] */
  double dp_target;                 /* the spacing asked for (particles_per_height, or
                                       resolution.dp), before wl_plan_whole_rows_dp [m] */
  double depth_model, depth_wall, depth_wall_model; /* still water offshore (modelled; the
                                       nominal is h) and at the wall (nominal, modelled) as
                                       whole particle rows [m] */
  double coefh;                     /* resolved numerics.coefh [-] (auto: WL_PLAN_COEFH_2D/3D) */
  int evals_per_step;               /* force evaluations a time step: 2 symplectic, 1 Verlet */
  char dims_reason[160];            /* why dims: given, or auto's reason */
  int slip_walls;                   /* 3D: side walls as free-slip mirror planes */
  int symmetry;                     /* 3D: half the width modelled, a symmetry plane on the
                                       centreline (domain.symmetry auto or centreline) */
  double h_sml;                     /* smoothing length h = coefh sqrt(dim) dp [m] */
  double c0;                        /* numerical speed of sound, the largest of the cases' [m/s] */
  double dt;                        /* CFL time step at rest, the smallest of the cases' [s] */
  double fluid_area;                /* wetted flume section up to the wall [m^2] (2D) */
  double land_length;               /* land modelled behind the seawall [m] */
  long n_fluid, n_boundary;         /* estimated particles of the largest case */
  double memory_bytes;              /* estimated host memory of a run (either backend) */
  double gpu_memory_bytes;          /* estimated GPU memory of a CUDA run */
  double particle_steps;            /* estimated for all cases */
  double cpu_seconds;               /* estimated on the reference CPU rate */
  double gpu_seconds;               /* estimated for the CUDA backend on an H100 */
  double gpu_work_seconds;          /* its force loops alone at WL_PLAN_GPU_RATE(_3D): the
                                       bound when runs share the GPU */
  int n_cases;                      /* the load cases the plan runs (1 or 2) */
  /* resolution.realisations resolved: the explosion's runs at each level of
   * its convergence ladder, the r-th with the crater's centre moved
   * landward by r dp / realisations (wl_plan_realisation_x); 1
   * without a ladder or an explosion. The collapse of a crater is chaotic:
   * runs whose crater energies differ by 1e-7 part by 3-11 % at the wall
   * (docs/convergence.md, "Realisations"), so one run's peak is one draw */
  int realisations;
  /* Build the flumes with still water (flume.c): the plan of a still-water
   * reference run, a copy of the case's plan (assess) */
  int still_flume;
  double gpu_case_seconds[2];       /* each case alone on the GPU; gpu_seconds is
                                       the cases side by side, as assess runs them */
  double gpu_case_work_seconds[2];
  int gpu_case_still[2];            /* 1: that case's still-water reference runs beside it */
  /* resolution.refine (vres.h): two levels, dp from refine_from to the
   * wall, dp_coarse = 2 dp seaward of it, laid out by wl_vres_layout, for
   * the cases whose `refine` is set (from: auto refines the solitary case
   * alone) */
  int refine;                       /* some case runs at two resolutions */
  int refine_auto;                  /* refine_from placed by the plan (from: auto) */
  double refine_from;               /* the interface [m] */
  double dp_coarse;                 /* the coarse level's spacing [m] */
  double refine_overlap, refine_band[2]; /* wl_vres_layout's overlap and bands (coarse, fine) [m] */
  double uniform_particle_steps;    /* all cases at dp everywhere, for the saving `check` prints */
  int n_notes;
  char notes[WL_PLAN_MAX_NOTES][320]; /* warnings and assumptions worth reading */
};

/* Default coefh (numerics.coefh: auto), chosen so that h is about 1.7 dp in
 * both dimensions. In 2D, DualSPHysics' coefh 1 (h = 1.41 dp) lets a
 * travelling solitary wave feed particle noise that the viscosity then
 * dissipates: H/h = 0.4 on h = 0.2 m at dp = 0.01 m lost 22 % of its energy
 * in 2 s with coefh 1 and artificial viscosity, 12.5 % with coefh 1 and
 * laminar viscosity, 2.5 % with coefh 1.2 and laminar viscosity
 * (docs/numerics.md). 3D's coefh 1 already gives
 * h = 1.73 dp. */
/* Most particles (fluid and boundary) one case may have: the backends
 * index particles with int, and 2^30 particles need about 160 GiB on the
 * CPU and 120 GiB on a GPU, beyond the machines wallload runs on. */
#define WL_PLAN_PARTICLES_MAX (1L << 30)

/* Most output times (samples of gauges, probes and wall force) one case may
 * have (run.output_interval against its end time). */
#define WL_PLAN_OUTPUTS_MAX 1e6

/* resolution.refine: the two levels overlap by this many of the coarse
 * level's band widths on either side of the interface (vres.h
 * wl_vres_opts.overlap). Three, not the module's one: with the coarse level
 * at 4-4.5 particles a wave height the wall's run-up came within 1.1-1.5 %
 * of the uniform fine run's (one band: 3-4.4 % low) and the peaks and
 * impulses within the same spread, for 4 % more runtime
 * (docs/variable-resolution.md, "In a scenario"). */
#define WL_PLAN_REFINE_OVERLAP_BANDS 3.0
/* resolution.refine: each level's band (its buffer) is this many of its h
 * wide, unshifted. Against the uniform fine run (means of two or three
 * starts; docs/variable-resolution.md, "The band's width"): 2h bands read
 * solitary_wall's h/40 positive impulse +3.6 % (the fluid beside a crowded
 * band runs ahead and piles water into the fine level), 3h bands +1.1 %,
 * and seawall.yaml's at dp = 0.006 m +0.7 %, peaks and run-up within 1.5 %.
 * Spacing the bands across the interface (vres.h shift_across) moved the
 * impulse by -4 to -5 % in both: within 0.7 % at solitary_wall, -3.5 % at
 * seawall.yaml, so it stays off. */
#define WL_PLAN_REFINE_BUFFER_H 3.0
/* Below this many particles over the wave height the coarse level does not
 * carry the wave to the fine level within 2 % (measured, as above); `check`
 * says so. */
#define WL_PLAN_REFINE_COARSE_PPH_MIN 4.0
/* Particles over the smallest wave height below which the plan notes that
 * an explosion's loads at the wall may lie outside the ladder's band: at 4
 * (dp = 0.012 m, the 2-core ladder) seawall.yaml's explosion read its
 * positive impulse 16.8 N s/m +-14 % against the 23.0 of the GPU's ladder,
 * whose finest level has 11.7; its short waves reach the wall undamped from
 * about 8 (dp <= 0.006 m; docs/history/2026-11-28-level-true.md). */
#define WL_PLAN_EXPLOSION_PPH_MIN 8.0
/* resolution.refine.from: auto places the interface this many still-water
 * depths seaward of the bed's first change (the slope's toe: a long wave
 * starts to feel a slope about a depth or two ahead of it; seawall.yaml's
 * measured interface stood 0.8 m, 2.3 depths, off its toe), and declines
 * to refine where the coarse level would keep less than this share of the
 * modelled flume. */
#define WL_PLAN_REFINE_TOE_DEPTHS 2.0
#define WL_PLAN_REFINE_COARSE_SHARE_MIN 0.2
#define WL_PLAN_REFINE_INITIAL_ETA_MAX 0.1

#define WL_PLAN_COEFH_2D 1.2
#define WL_PLAN_COEFH_3D 1.0

/* wallload's default numerics, as a scenario without a numerics block runs
 * them (coefh auto, laminar viscosity with water's nu 1e-6 m^2/s; the rest
 * as wl_sph_params_default), applied to prm for its prm->dim. For runs
 * built without a scenario (the tanks and dam breaks of `wallload
 * validate`), so that they measure what `assess` runs; test_plan checks
 * it against the scenario path. wl_sph_params_default itself keeps
 * DualSPHysics' settings, the benchmarks' common ground. */
static inline void wl_plan_default_numerics(struct wl_sph_params *prm) {
  /* inline: `wallload bench` uses it where only the solver's modules are
   * built (bench/gpu.sh on a GPU host without GSL or libyaml) */
  prm->coefh = prm->dim == 3 ? WL_PLAN_COEFH_3D : WL_PLAN_COEFH_2D;
  prm->visc = WL_SPH_VISC_LAMINAR;
  prm->nu = 1e-6; /* water at 20 C */
}

/* Reference throughput used for runtime estimates [force evaluations/s per
 * particle; a symplectic step has two, a Verlet step one]: scenarios/
 * seawall.yaml's ladder on the 2-core development machine, 2 threads, the
 * wall condition of docs/boundary.md: 5.9e6-6.8e6 over its six runs, 6.4e6
 * in all (BENCHMARKS.md, "The main job on this machine"; test_plan checks
 * check's estimate against that run). */
#define WL_PLAN_CPU_RATE 6.4e6
/* The same in 3D (about 100 neighbours per particle instead of 20, and a
 * flume's side walls): test_flume3d's still-water flume (16k particles)
 * ran at about 3e5 symplectic particle-steps/s on the 2-core development
 * machine. */
#define WL_PLAN_CPU_RATE_3D 6.0e5
/* The CUDA backend on an H100 (BENCHMARKS.md, "CUDA backend: the cost of a
 * step"): a small flume's step costs a fixed time whatever its size (seven
 * latency-bound kernels, the outputs overlapped with the next steps); large
 * runs go at the force loop's rate (the 2D dam break of 0.89M particles).
 * A run alone takes the larger of the two times; runs side by side (a
 * scenario's cases, a ladder's levels, a sweep's cases) are priced by
 * wl_plan_gpu_side_by_side. The Verlet step is seawall.yaml's solitary
 * case alone at dp = 0.012 m (2026-11-27, 28af3ea: 38.4-38.9 us on one
 * H100, 41.1-41.3 us on another); the symplectic step that times the ratio
 * of the two integrators' steps measured beside each other at dp = 0.0125 m
 * (1.61). */
#define WL_PLAN_GPU_STEP_S 6.4e-5
#define WL_PLAN_GPU_STEP_S_VERLET 4.0e-5
#define WL_PLAN_GPU_RATE 2.70e9
/* 3D: scenarios/seawall3d.yaml's (99 584 particles, a third of them wall,
 * a symmetry plane, outputs every 0.01 s): its planned 9.15e8 particle-
 * steps (Verlet) over the 3.9 s its case took on the H100, 2026-11-27; the
 * 1.03M-particle dam break's 7.67e8 had priced it at 1.2 s. Larger 3D runs
 * fill the GPU better (5.8e8 at 205 k particles without outputs, 7.7e8 at
 * 1 M), so the estimate is conservative there. */
#define WL_PLAN_GPU_RATE_3D 2.3e8

/* Whole rows of still water. The scene lays fluid rows at z_min + (j +
 * 1/2) dp (scene.c: z_min the lowest bed point up to the wall), every row
 * at least dp/2 above the bed and below the still-water level h; the water
 * a row stands for is dp deep, so a depth that is not a whole number of dp
 * is modelled shallower or deeper by up to dp/2: 0.06 m on seawall.yaml's
 * platform was 0.05 or 0.0625 m (-17 or +4 %, and the wall's force at rest
 * -31 or +9 %). wl_plan_whole_rows_dp returns the spacing within
 * [WL_PLAN_DP_FINER, WL_PLAN_DP_COARSER] x dp_target that models the
 * offshore depth and the depth at the wall best (the largest relative
 * error of the two least; among equal, the spacing nearest dp_target):
 * both exactly where the depths are commensurate, as 0.36 and 0.06 m are
 * at dp = 0.06/n. *worst gets that largest relative depth error (NULL: not
 * wanted). With resolution.dp: auto the plan and every level of a
 * convergence ladder use it; a dp the scenario gives is kept as given. */
#define WL_PLAN_DP_FINER 0.8
#define WL_PLAN_DP_COARSER 1.1
double wl_plan_whole_rows_dp(const struct wl_scenario *s, double dp_target, double *worst);

/* The spacing of a convergence ladder's level with the given factor: with
 * resolution.dp: auto, wl_plan_whole_rows_dp of dp_target x factor (so
 * every level models the still water in whole rows, and the levels'
 * ratios stay near the factors'); a dp the scenario gives times factor. */
double wl_plan_level_dp(const struct wl_scenario *s, const struct wl_plan *p, double factor);

/* The still-water depth the scene models over a bed at height z_bed [m]
 * at spacing dp (above); z_min the lowest bed point. */
double wl_plan_modelled_depth(double h, double z_min, double z_bed, double dp);

/* The lowest bed point from the flume's start to the wall [m]. */
double wl_plan_bed_min(const struct wl_scenario *s);

/* Build the plan of a validated scenario. Returns WL_OK; WL_EINPUT when a
 * formula's validity is exceeded (message names the scenario key);
 * WL_ENUMERIC or WL_ENOMEM from the wave integrals. */
enum wl_status wl_plan_make(const struct wl_scenario *s, struct wl_plan *plan,
                            struct wl_error *err);

/* Print the plan: derived initial conditions with their sources, and cost. */
void wl_plan_write(const struct wl_plan *plan, FILE *out);

/* What a run (or a convergence ladder: the sum of its levels' times, the
 * largest level's memory) will take. */
struct wl_plan_cost {
  int dims;
  double host_bytes, device_bytes; /* the largest case or level */
  double cpu_seconds;              /* at the reference rate, WL_PLAN_CPU_THREADS threads */
  double gpu_seconds;              /* on an H100 */
  double gpu_work_seconds;         /* the force loops' part of it (struct wl_plan) */
};

/* What one plan costs (one resolution). */
struct wl_plan_cost wl_plan_cost_of(const struct wl_plan *p);

/* The cost of the convergence ladder, as assess runs it: each level
 * re-planned at its dp (wl_plan_level_dp). Prints one line per level and
 * the total to `out` (only the total when `brief`; out may be NULL).
 * *cost gets the sum of the levels' CPU times, their GPU time side by side
 * (one after the other when a target error may stop the ladder early, or
 * when they do not fit the GPU together) and the largest level's memory;
 * without a ladder the plan's own cost. A level that cannot be planned
 * leaves *cost the plan's own and returns its status and error (the
 * listing names the level). */
enum wl_status wl_plan_ladder_cost(const struct wl_scenario *s, const struct wl_plan *plan,
                                   int brief, FILE *out, struct wl_plan_cost *cost,
                                   struct wl_error *err);

/* Runs side by side on one GPU: a ladder's levels (src/assess/ladder.c) and
 * a sweep's cases (src/sweep/run.c), together within this share of its
 * memory. */
#define WL_PLAN_GPU_SIDE_BY_SIDE_MEMORY 0.5
/* The GPU `check` prices runs for: the H100's memory [bytes]. */
#define WL_PLAN_GPU_BYTES 80.0e9
/* A small flume's step is a few latency-bound kernels that leave the GPU
 * mostly idle, so runs share it well: with k runs on it each advances at
 * 1 / (1 + WL_PLAN_GPU_SHARE_COST (k - 1)) of its speed alone (processor
 * sharing), and a waiting run starts as one ends. But k small runs together
 * reach only wl_plan_gpu_shared_efficiency(k) = WL_PLAN_GPU_SHARED_RATE k /
 * (k + WL_PLAN_GPU_SHARED_HALF) of the force loop's rate on one large run
 * (each runs its own sort and small kernels, and more of them fill more of
 * the GPU), which bounds the time from below; a large run counts its work
 * at WL_PLAN_GPU_SHARED_RATE of the force loop's rate, what a full GPU
 * reaches (a step is more than its force loop: seawall.yaml's finest
 * explosion alone, 151 000 particles, runs at 1.3e9 particle-steps/s; its
 * GPU ladder with 4 explosion realisations a level, 15 runs, took 170.5 s
 * where the full rate priced 128 s; now priced 159 s, and with 8, 27 runs,
 * 291 s against 321.7 s measured, 2026-11-28). Fitted on the H100
 * (BENCHMARKS.md, "Sweeps" and "The main job on this machine"): the cost to
 * the main job's finest explosion level of its ladder's five other runs
 * beside it (2026-11-26); the share that seawall-sweep.yaml's cases reach
 * one alone (0.135, a whole `assess` each) and 16 side by side (0.54; its
 * 64 cases 16 at a time, 0.57), 2026-11-27 with the 2D wall condition at
 * 16 threads. test_plan holds the model to these runs. */
#define WL_PLAN_GPU_SHARE_COST 0.064
#define WL_PLAN_GPU_SHARED_RATE 0.68
#define WL_PLAN_GPU_SHARED_HALF 4.0

/* The share of the force loop's rate on one large run that `width`
 * latency-bound runs side by side reach together (above). */
double wl_plan_gpu_shared_efficiency(int width);

/* The GPU time of n runs (each costed alone in runs[i]) run at most
 * `width` at a time on one GPU, in order, a new one starting as one ends. */
double wl_plan_gpu_side_by_side(const struct wl_plan_cost *runs, int n, int width);

/* How many runs of `device_bytes` each fit side by side on a GPU of
 * `gpu_bytes` (WL_PLAN_GPU_SIDE_BY_SIDE_MEMORY of it), between 1 and
 * `max_width`. */
int wl_plan_gpu_side_by_side_width(double device_bytes, double gpu_bytes, int max_width);

/* The machine a run is planned for and the budget it is held to. */
struct wl_plan_machine {
  double host_bytes;     /* physical memory [bytes]; 0: unknown, not checked */
  double device_bytes;   /* > 0: the run goes to this GPU, of this much memory */
  char device_name[128];
  int threads;           /* CPU threads of a CPU run */
  double budget_seconds; /* estimated runtime allowed; <= 0: no budget */
  int force_large;       /* 1: past the runtime budget anyway (never past memory) */
};

/* The calibration flume of `check` (src/assess/speed.c) on a machine that
 * runs WL_PLAN_CPU_RATE [particle-steps/s]: its rate times WL_PLAN_CPU_RATE
 * over the rate of a flume the plan prices, measured back to back
 * (seawall-sweep.yaml's first case, 14 k particles; BENCHMARKS.md,
 * "Sweeps", 2026-11-27): 6.43e6 on the 2-core machine at 2 threads, 6.95e6
 * and 6.18e6 on the H100 host's Xeon at 2 and 4; their mean. */
#define WL_PLAN_CPU_SPEED_RATE 6.5e6
/* The CPU thread count WL_PLAN_CPU_RATE was measured with. */
#define WL_PLAN_CPU_THREADS 2
/* A run may plan at most this fraction of the host's physical memory. */
#define WL_PLAN_MEMORY_FRACTION 0.8
/* The default runtime budget of `check` and `assess` [s] (--budget). */
#define WL_PLAN_BUDGET_DEFAULT_S (24.0 * 3600.0)

/* WL_OK when `cost` fits machine `m`: memory (host, and the GPU's when the
 * run goes to one) always, the estimated runtime unless m->force_large.
 * WL_EINPUT otherwise, naming the resolution key, what the run would take
 * and how to reduce it. */
enum wl_status wl_plan_fits(const struct wl_scenario *s, const struct wl_plan_cost *cost,
                            const struct wl_plan_machine *m, struct wl_error *err);

/* The runtime [s] `cost` would take on machine `m`: the GPU's side-by-side
 * time when the run goes to a GPU, else the CPU time scaled from
 * WL_PLAN_CPU_THREADS to m->threads. */
double wl_plan_machine_seconds(const struct wl_plan_cost *cost, const struct wl_plan_machine *m);

/* resolution.particles_per_height: auto, planned to the machine. The
 * candidates are a sqrt(2) series; auto takes the finest whose whole plan
 * (its convergence ladder, as wl_plan_ladder_cost prices it) the machine
 * runs within WL_PLAN_AUTO_SECONDS (or the machine's budget, --budget,
 * where that is less) and holds in memory, and the coarsest
 * when none does (wl_plan_fits then says why the run cannot go). The
 * finest candidate is where the main job's ladder converged on the H100
 * (seawall.yaml at dp = 0.0086, 0.006, 0.0043 m: the two finest levels'
 * peak forces within 0.6 % (solitary) and 0.1 % (explosion), probes and
 * boundary particles within 0.4 %; BENCHMARKS.md, "Speed against
 * error"): finer costs without a measured gain. The budget is what
 * the main job's coarsest ladder takes on 2 CPU cores, so a small machine
 * runs what it ran before and a GPU the converged ladder. A plan made
 * without wl_plan_choose (a sweep's cases) takes the coarsest. */
#define WL_PLAN_AUTO_PPH_N 4
#define WL_PLAN_AUTO_SECONDS (20.0 * 60.0)
extern const double wl_plan_auto_pph[WL_PLAN_AUTO_PPH_N];

/* What wl_plan_choose chose, for check and assess to print. */
struct wl_plan_choice {
  int is_auto;         /* 1: particles_per_height was auto and is now resolved */
  double ppH;          /* the particles per height chosen */
  double seconds;      /* its estimated runtime on the machine [s] */
  double next_seconds; /* the next finer candidate's [s]; 0: none (the finest chosen) */
  int next_too_large;  /* 1: the next finer did not fit the machine's memory */
  double limit;        /* the runtime auto planned within [s]: WL_PLAN_AUTO_SECONDS, or
                          the machine's budget (--budget) where that is less */
  struct wl_plan_machine machine; /* the machine it was planned for (also when not auto) */
};

/* resolution.realisations: auto runs this many explosion realisations a
 * level where the ladder goes to a GPU (wl_plan_choose), one elsewhere.
 * seawall.yaml's explosion on the H100 (2026-11-28, docs/convergence.md,
 * "Realisations of a chaotic case"): single runs at dp = 0.0043 m read
 * 32.4-38.0 N/m; with 4 a level the means' scatter (about 2.6 %) made the
 * ladder's band on the peak +-22 %, with 8 +-6.4 to +-14.5 % (means 33.1-
 * 34.8 N/m), the whole main job 322 s against 171 s. */
#define WL_PLAN_AUTO_REALISATIONS 8

/* The crater centre [m] of realisation r (0-based) of n at spacing dp:
 * x_center + r dp / n, within one spacing of the scenario's, so every
 * realisation is the same explosion on a lattice shifted against it. */
double wl_plan_realisation_x(double x_center, double dp, int r, int n);

/* resolution.refine's two levels laid out at x_if for plan p (vres.h
 * wl_vres_layout, the fine level landward, WL_PLAN_REFINE_OVERLAP_BANDS of
 * overlap and WL_PLAN_REFINE_BUFFER_H bands set in *vo; vo may be NULL):
 * the layout the plan checks and prices and the run builds. */
struct wl_vres_opts;
struct wl_vres_layout;
void wl_plan_refine_layout(const struct wl_plan *p, double x_if, struct wl_vres_opts *vo,
                           struct wl_vres_layout *lay);

/* resolution.refine in s for machine m: from: auto runs one resolution
 * where the run takes the GPU (m->device_bytes > 0; the coupling edits
 * particles on the host between steps, slower there than one resolution),
 * s->resolution.refine.gpu; a given `from` runs and the plan notes the cost,
 * s->resolution.refine.gpu_given. wl_plan_choose
 * calls it; a sweep, which plans its cases without wl_plan_choose, for
 * each case. */
void wl_plan_refine_machine(struct wl_scenario *s, const struct wl_plan_machine *m);

/* Resolves resolution.particles_per_height: auto in s for machine m (the
 * value goes to s->resolution.particles_per_height.q.si; is_auto stays, so
 * the listing still says auto), and resolution.refine.from: auto
 * (wl_plan_refine_machine). Leaves a written value alone (c->is_auto 0).
 * WL_OK, or the status of a plan that cannot be made. */
enum wl_status wl_plan_choose(struct wl_scenario *s, const struct wl_plan_machine *m,
                              struct wl_plan_choice *c, struct wl_error *err);

/* The machine's name for messages: the GPU's, or "N CPU threads". */
void wl_plan_machine_name(const struct wl_plan_machine *m, char *buf, size_t size);

/* One line saying what auto chose and why ("" when nothing was auto). */
void wl_plan_choice_describe(const struct wl_plan_choice *c, char *buf, size_t size);

/* WL_OK when the plan's solitary case can run; WL_EINPUT, naming
 * loads.solitary and the wall, when its automatic initial crest falls at
 * or behind the wall (a flume shorter than the wave). */
enum wl_status wl_plan_solitary_runnable(const struct wl_scenario *s, const struct wl_plan *p,
                                         struct wl_error *err);

#endif
