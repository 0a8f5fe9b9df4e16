/* test_plan.c: the plan's equal-energy conversions and derived values, each
 * checked by a round trip through an independent path or against the seeds'
 * and REFERENCES' numbers. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

#include "testutil.h"
#include "wallload/flume.h"
#include "wallload/plan.h"
#include "wallload/sph.h"

static int make(const char *text, struct wl_scenario *s, struct wl_plan *p) {
  struct wl_error err;
  wl_error_clear(&err);
  wl_scenario_init(s);
  if (wl_scenario_parse("test.yaml", text, strlen(text), s, &err) != WL_OK ||
      wl_plan_make(s, p, &err) != WL_OK) {
    printf("FAIL: %s\n", err.msg);
    wl_test_failures++;
    return 0;
  }
  return 1;
}

/* scenarios/seawall.yaml planned, at dp [m] when dp > 0, else as it is
 * (dp auto). Returns 1 when it loaded and planned; else prints the reason,
 * counts a failure and returns 0. *sw is to be cleared either way. */
static int plan_seawall(double dp, struct wl_scenario *sw, struct wl_plan *pw) {
  char path[1024];
  snprintf(path, sizeof path, "%s/scenarios/seawall.yaml", WL_SOURCE_DIR);
  struct wl_error err;
  wl_error_clear(&err);
  wl_scenario_init(sw);
  int ok = wl_scenario_load(path, sw, &err) == WL_OK;
  if (ok && dp > 0) {
    sw->resolution.dp.is_auto = 0, sw->resolution.dp.given = 1;
    sw->resolution.dp.q.si = dp;
  }
  ok = ok && wl_plan_make(sw, pw, &err) == WL_OK;
  if (!ok) printf("FAIL seawall.yaml: %s\n", err.msg), wl_test_failures++;
  return ok;
}

/* The same as the runs of BENCHMARKS.md measured it: before the
 * still-water reference run (plan.h; run.still_reference: off). */
static int plan_seawall_as_measured(double dp, struct wl_scenario *sw, struct wl_plan *pw) {
  if (!plan_seawall(dp, sw, pw)) return 0;
  sw->run.still_reference.choice = WL_STILL_REF_OFF;
  struct wl_error err;
  wl_error_clear(&err);
  if (wl_plan_make(sw, pw, &err) == WL_OK) return 1;
  printf("FAIL seawall.yaml: %s\n", err.msg), wl_test_failures++;
  return 0;
}

/* 1 when some note of the plan contains `what`. */
static int has_note(const struct wl_plan *p, const char *what) {
  for (int i = 0; i < p->n_notes; i++)
    if (strstr(p->notes[i], what)) return 1;
  return 0;
}

/* The Mach rule of a 3D crater's collapse (plan.h collapse_speed,
 * docs/numerics.md): a cavity eta0 = 0.45 m deep with no lip (shape
 * quadratic: its rim is the still level) in 0.5 m of water. Written out by
 * hand: the depth's c0 is 10 sqrt(9.81 x 0.5) = 22.147 m/s; water falling
 * from the rim to the floor reaches sqrt(2 x 9.81 x 0.45) = 2.9714 m/s, so
 * in 3D c0 = 29.714 m/s; in 2D the depth's. The solver's c0 is the plan's
 * (the flume hands it the speed). */
static void crater_mach(void) {
  for (int dims = 2; dims <= 3; dims++) {
    char text[600];
    snprintf(text, sizeof text,
             "scenario: mach\nwater: {depth: 0.5 m}\n"
             "domain: {dimensions: %d, length: 6 m, width: 2 m}\n"
             "wall: {x: 5 m, height: 1.5 m}\n"
             "loads: {explosion: {eta0: 0.45 m, r0: 1.0 m, shape: quadratic, at: 2.5 m}}\n"
             "resolution: {dp: 0.1 m}\n",
             dims);
    struct wl_scenario s;
    struct wl_plan p;
    if (!make(text, &s, &p)) continue;
    const double want = dims == 3 ? 29.714 : 22.147;
    CHECK_REL(p.explosion.collapse_speed, 2.9714, 1e-4, "the crater's collapse speed, by hand");
    CHECK_REL(p.explosion.c0, want,  1e-4,
              dims == 3 ? "3D crater: c0 = 10 x its collapse speed" : "2D crater: the depth's c0");
    struct wl_flume f;
    struct wl_sph_const k;
    struct wl_error err;
    wl_error_clear(&err);
    memset(&f, 0, sizeof f);
    const int ok = wl_flume_build(&s, &p, WL_CASE_EXPLOSION, &f, &err) == WL_OK &&
                   wl_sph_const_make(&f.cfg.prm, &k, &err) == WL_OK;
    CHECK_TRUE(ok && k.c0_d == p.explosion.c0, "the crater flume's c0 is the plan's, bit for bit");
    if (!ok) printf("  %s\n", err.msg);
    wl_flume_clear(&f);
    wl_scenario_clear(&s);
  }
}

/* resolution.refine.from: auto, against the rule written out by hand
 * (plan.h): the interface 2 still-water depths seaward of the bed's first
 * change (on a flat bed, the solitary wave's half-length to 1 % of H,
 * acosh(10) / k, k = sqrt(3 H / (4 d^3)), if longer), less the coarse
 * level's reach beyond it: three bands of overlap, its band and 2 h_c. A
 * band is whole rows of at least 3 h: h = 1.2 sqrt(2) dp = 1.697 dp, so
 * 5.09, 6 dp_c; the reach is 18 + 6 + 2 x 1.697 = 27.394 dp_c. */
static void refine_auto(void) {
  struct wl_scenario s;
  struct wl_plan p;
  const double beyond = 18.0 + 6.0 + 2.0 * 1.2 * sqrt(2.0); /* in coarse spacings */
  char text[1024];
  const char *slope = "scenario: t\nwater: {depth: 0.5 m}\ndomain: {length: 20 m}\n"
                      "bathymetry: [{from: 10 m, slope: 1/10}, {from: 13 m, slope: 0}]\n"
                      "wall: {x: 15 m, height: 0.5 m}\nloads: {solitary: {height: %g m}%s}\n"
                      "resolution: {dp: 0.0125 m, refine: {from: auto}}\n%s";
  /* coarse level 0.025 m: 4.8 particles over 0.12 m */
  snprintf(text, sizeof text, slope, 0.12, "", "");
  if (make(text, &s, &p)) {
    CHECK_TRUE(p.refine && p.refine_auto && p.solitary.refine, "from: auto refines the solitary case");
    CHECK_REL(p.dp_coarse, 0.025, 1e-12, "the coarse level at 2 dp");
    CHECK_TRUE(has_note(&p, "positive impulse about 1 % high"),
               "check says how far two levels read the solitary impulse");
    CHECK_REL(p.refine_from, 10.0 - 2 * 0.5 - beyond * 0.025, 1e-9,
              "the interface: two depths and the coarse level's reach seaward of the toe (by hand)");
  }
  wl_scenario_clear(&s);
  /* a machine whose run takes the GPU: one resolution (the coupling runs
   * on the host) */
  snprintf(text, sizeof text, slope, 0.12, "", "");
  if (make(text, &s, &p)) {
    struct wl_plan_machine gpu = {0};
    struct wl_plan_choice ch;
    struct wl_error err;
    wl_error_clear(&err);
    gpu.device_bytes = 80e9, gpu.threads = 16, gpu.budget_seconds = 3600;
    CHECK_TRUE(wl_plan_choose(&s, &gpu, &ch, &err) == WL_OK && wl_plan_make(&s, &p, &err) == WL_OK &&
                   !p.refine && has_note(&p, "GPU"),
               "from: auto on a GPU machine: one resolution, said");
  }
  wl_scenario_clear(&s);
  /* 3.2 particles over 0.08 m in the coarse level: one resolution, said */
  snprintf(text, sizeof text, slope, 0.08, "", "");
  if (make(text, &s, &p)) {
    CHECK_TRUE(!p.refine && !p.solitary.refine, "from: auto keeps one resolution under 4 a height");
    CHECK_TRUE(!has_note(&p, "positive impulse about 1 % high"), "and no two-level caveat");
    CHECK_TRUE(has_note(&p, "from: auto: one resolution"), "and check says why");
  }
  wl_scenario_clear(&s);
  /* an explosion beside it runs at dp everywhere */
  snprintf(text, sizeof text, slope, 0.12, ", explosion: {energy: same-as-solitary, at: 4 m}", "");
  if (make(text, &s, &p)) {
    CHECK_TRUE(p.solitary.refine && !p.explosion.refine,
               "from: auto: the solitary case refines, the explosion does not");
    CHECK_TRUE(has_note(&p, "the explosion runs at dp everywhere"), "and check says so");
  }
  wl_scenario_clear(&s);
  /* 3D: one resolution, said (an interface the scenario gives is refused) */
  snprintf(text, sizeof text, slope, 0.12, "", "");
  char *dims = strstr(text, "domain: {length: 20 m}");
  if (dims) {
    char t3[1100];
    snprintf(t3, sizeof t3, "%.*sdomain: {length: 20 m, width: 0.3 m, dimensions: 3}%s",
             (int)(dims - text), text, dims + strlen("domain: {length: 20 m}"));
    if (make(t3, &s, &p))
      CHECK_TRUE(!p.refine && has_note(&p, "2D only"), "from: auto in 3D: one resolution, said");
    wl_scenario_clear(&s);
  }
  /* a flat bed: the solitary_wall flume (H/h = 0.3 on 0.2 m), fine over the
   * wave's half-length before the wall */
  const char *flat = "scenario: t\nwater: {depth: 0.2 m}\ndomain: {length: 7 m}\n"
                     "wall: {x: 6 m, height: 0.4 m}\nloads: {solitary: {height: 0.06 m}}\n"
                     "resolution: {dp: 0.005 m, refine: {from: auto}}\n";
  if (make(flat, &s, &p)) {
    const double k = sqrt(3.0 * 0.06 / (4.0 * 0.2 * 0.2 * 0.2));
    CHECK_TRUE(p.solitary.refine, "from: auto on a flat bed refines");
    CHECK_REL(p.refine_from, 6.0 - acosh(10.0) / k - beyond * 0.01, 1e-9,
              "the interface a half-length of the wave and the reach before the wall (by hand)");
  }
  wl_scenario_clear(&s);
  /* test_solitary_wall's flume: the crest starts 0.75 L = 1.90 m before
   * the wall, and the interface by the rule above (1.77 m from the paddle)
   * would stand where the initial wave is half its height (over 10 %
   * up to 1.39 + acosh(sqrt 10) / k = 2.16 m): one resolution, said */
  const char *near = "scenario: t\nwater: {depth: 0.2 m}\ndomain: {length: 3.79 m}\n"
                     "wall: {x: 3.289 m, height: 0.6 m}\n"
                     "loads: {solitary: {height: 0.06 m, generation: initial, at: 1.392 m}}\n"
                     "resolution: {dp: 0.0066667 m, refine: {from: auto}}\n";
  if (make(near, &s, &p))
    CHECK_TRUE(!p.refine && has_note(&p, "under the initial wave"),
               "from: auto keeps an initial wave out of the interface: one resolution, said");
  wl_scenario_clear(&s);
}

/* The note on an explosion's ladder that is too coarse at its finest level
 * (plan.h WL_PLAN_EXPLOSION_PPH_MIN): seawall.yaml as 2 CPU cores plan it
 * (particles_per_height 2: the finest of dp = 0.02, 0.015, 0.012 m puts
 * 0.05 / 0.012 = 4.2 particles over the 0.05 m solitary wave, the smallest
 * height) notes it; as a GPU plans it (5.66: 0.05 / 0.00429 = 11.7) not. */
static void explosion_resolution_note(void) {
  struct wl_scenario sw;
  struct wl_plan pw;
  if (plan_seawall(0, &sw, &pw)) {
    CHECK_TRUE(has_note(&pw, "4.2 particles over the smallest wave height"),
               "particles_per_height 2: the explosion's coarse finest level is noted");
    sw.resolution.particles_per_height.q.si = 5.66;
    struct wl_error err;
    wl_error_clear(&err);
    CHECK_TRUE(wl_plan_make(&sw, &pw, &err) == WL_OK &&
                   !has_note(&pw, "particles over the smallest wave height"),
               "particles_per_height 5.66: no such note");
  }
  wl_scenario_clear(&sw);
}

int main(void) {
  gsl_set_error_handler_off();
  refine_auto();
  explosion_resolution_note();
  crater_mach();
  struct wl_scenario s;
  struct wl_plan p;
  const char *per_width = "scenario: t\nwater: {depth: 0.36 m}\ndomain: {length: 36 m}\n"
                          "wall: {x: 19.2 m, height: 0.5 m}\n"
                          "loads:\n  solitary: {height: 0.05 m}\n"
                          "  explosion: {energy: same-as-solitary, at: 8 m}\n";
  if (make(per_width, &s, &p)) {
    /* The simulated 2D crater's energy (quadrature of seed 000 eq 4) equals
     * the solitary wave's integrated energy: the closed-form W of the plan
     * inverted the Van Dorn / Whalin chain correctly. */
    CHECK_REL(p.explosion.energy_quad, p.solitary.integrated.energy, 1e-9,
              "per-width equal energy: crater quadrature = solitary integral");
    CHECK_TRUE(p.explosion.conserves_mass && p.explosion.shape == WL_CRATER_SHAPE_QUADRATIC_LIP_PLANE,
               "lip_form auto in 2D is the mass-conserving plane lip (REFERENCES 5.2)");
    /* REFERENCES 3.4 exact table: E/(rho g h^3) = 0.051041 at eps 0.10 and
     * 0.095634 at 0.15; eps = 0.1389 lies between. */
    double e_nd = p.solitary.integrated.energy / (1000 * 9.81 * 0.36 * 0.36 * 0.36);
    CHECK_TRUE(e_nd > 0.051041 && e_nd < 0.095634, "solitary energy within the exact-table bracket");
    CHECK_REL(p.solitary.energy_seed001, 438.47, 1e-3, "seed 001 Yu Yao: E = 0.44 kJ (0.958 rho g h^3)");
    CHECK_REL(p.dp, 0.05 / 10.0, 1e-12, "dp auto = smallest wave height / particles_per_height");
    /* The fluid section up to the wall of a flat flume is h x_wall. */
    CHECK_REL(p.fluid_area, 0.36 * 19.2, 1e-12, "flat flume wetted area");
  }
  wl_scenario_clear(&s);

  const char *seed = "scenario: t\nwater: {depth: 2.66 m}\ndomain: {length: 83 m}\n"
                     "wall: {x: 70 m, height: 4.57 m}\n"
                     "loads:\n  solitary: {height: 1.064 m}\n"
                     "  explosion: {energy: same-as-solitary, energy_basis: seed-001, at: 30 m}\n";
  if (make(seed, &s, &p)) {
    /* seed 001 Table 4, Robertson: E = 177 kJ, eta0 R0 = 5.9 m^2, Hmax r = 7.25 m^2 */
    CHECK_REL(p.explosion.matched_energy, 177e3, 0.005, "seed 001 Table 4: 177 kJ");
    CHECK_REL(p.explosion.chain.eta0_r0, 5.9, 0.01, "seed 001 Table 4: eta0 R0 = 5.9 m^2");
    CHECK_REL(p.explosion.chain.hr, 7.25, 0.005, "seed 001 Table 4: Hmax r = 7.25 m^2");
  }
  wl_scenario_clear(&s);

  /* Sloped bed: area by hand. Slope 1/10 from 10 m to 13 m (rise 0.3 m),
   * then flat to the wall at 15 m, depth 0.5 m:
   * 0.5*10 + (0.5 + 0.2)/2*3 + 0.2*2 = 5 + 1.05 + 0.4 = 6.45 m^2. */
  const char *slope = "scenario: t\nwater: {depth: 0.5 m}\ndomain: {length: 20 m}\n"
                      "bathymetry: [{from: 10 m, slope: 1/10}, {from: 13 m, slope: 0}]\n"
                      "wall: {x: 15 m, height: 0.5 m}\nloads: {solitary: {height: 0.05 m}}\n";
  if (make(slope, &s, &p)) {
    CHECK_REL(p.fluid_area, 6.45, 1e-12, "trapezoid area of a sloped flume by hand");
    CHECK_REL(wl_scenario_bed_z(&s, 11.5), 0.15, 1e-12, "bed height on the slope by hand");
    CHECK_REL(wl_scenario_bed_z(&s, 14.0), 0.3, 1e-12, "bed height on the platform by hand");
  }
  wl_scenario_clear(&s);

  /* Charge in pounds: seed 001, 32 lb -> R0 8.28 m, eta0 2.07 m. */
  const char *charge = "scenario: t\nwater: {depth: 16.5 ft}\ndomain: {length: 45 m}\n"
                       "wall: {x: 40 m, height: 10 m}\n"
                       "loads: {explosion: {charge: 32 lb, at: 15 m}}\n";
  if (make(charge, &s, &p)) {
    CHECK_ABS(p.explosion.r0, 8.28, 0.005, "seed 001: 32 lb gives R0 = 8.28 m");
    CHECK_ABS(p.explosion.eta0, 2.07, 0.005, "seed 001: 32 lb gives eta0 = 2.07 m (coef 35)");
    CHECK_REL(p.h, 16.5 * 0.3048, 1e-15, "16.5 ft depth converted exactly");
  }
  wl_scenario_clear(&s);
  /* The GPU runtime estimate of `check` against what scenarios/seawall.yaml
   * (Verlet integrator) took on the H100 (BENCHMARKS.md "CUDA backend: the
   * cost of a step", 2026-11-27, 28af3ea: its two cases side by side, the
   * solitary's 1.72-1.76 s within the explosion's 3.87-3.89 s): a
   * measurement, not this code's output. Within 25 %: an estimate, not a
   * prediction to the second. */
  {
    struct wl_scenario sw;
    struct wl_plan pw;
    /* at the spacing those runs had (dp auto now picks 0.012 m, below) */
    if (plan_seawall_as_measured(0.0125, &sw, &pw)) {
      CHECK_REL(pw.gpu_seconds, 3.88, 0.25,
                "GPU runtime estimate of seawall.yaml vs its H100 run (BENCHMARKS.md)");
    }
    wl_scenario_clear(&sw);
    /* and the CPU estimate against the ladder's finest level on the 2-core
     * development machine (BENCHMARKS.md "The main job on this machine",
     * 2026-11-26: 135.0 s + 342.8 s for the two cases at dp = 0.012 m, 2
     * threads, the wall condition) */
    if (plan_seawall_as_measured(0.012, &sw, &pw))
      CHECK_REL(pw.cpu_seconds, 135.0 + 342.8, 0.25,
                "CPU runtime estimate of seawall.yaml at 0.012 m vs its 2-core run (BENCHMARKS.md)");
    wl_scenario_clear(&sw);
  }
  /* resolution.particles_per_height: auto, planned to the machine
   * (wl_plan_choose): on the 2-core machine the coarsest candidate, on an
   * H100 the finest; each choice's estimated ladder against the whole
   * `assess` measured on that machine (BENCHMARKS.md "The main job on this
   * machine": 849.6 s on 2 cores for dp = 0.02, 0.015, 0.012 m; 361 s on
   * the H100, 2026-11-28, for dp = 0.0086, 0.006, 0.0043 m with the
   * explosion's 8 realisations a level that auto plans on a GPU and its
   * still-water reference), within 25 %. */
  {
    struct wl_scenario sw;
    struct wl_plan pw;
    struct wl_error err;
    wl_error_clear(&err);
    struct wl_plan_machine cpu = {0}, gpu = {0};
    cpu.threads = 2;
    gpu.device_bytes = WL_PLAN_GPU_BYTES;
    snprintf(gpu.device_name, sizeof gpu.device_name, "H100");
    const struct wl_plan_machine *machines[2] = {&cpu, &gpu};
    /* the H100's run had the explosion's still-water reference run once a
     * level (2026-11-28T04:16Z, 361 s); the 2-core run predates it */
    const double want_pph[2] = {2.0, 5.66}, measured_s[2] = {849.6, 361.0};
    for (int k = 0; k < 2; k++) {
      if (!(k ? plan_seawall(0, &sw, &pw) : plan_seawall_as_measured(0, &sw, &pw))) continue;
      struct wl_plan_choice c;
      struct wl_plan_cost cost;
      CHECK_TRUE(sw.resolution.particles_per_height.is_auto &&
                     wl_plan_choose(&sw, machines[k], &c, &err) == WL_OK && c.is_auto,
                 "seawall.yaml's particles_per_height auto resolves");
      CHECK_REL(c.ppH, want_pph[k], 1e-12, k ? "auto on an H100: 5.66" : "auto on 2 cores: 2");
      /* resolution.realisations: auto: 8 explosion runs a level on a GPU, 1 on the CPU */
      CHECK_TRUE(sw.resolution.realisations.is_auto &&
                     sw.resolution.realisations.q.si == (k ? WL_PLAN_AUTO_REALISATIONS : 1),
                 k ? "realisations auto on an H100: 8" : "realisations auto on 2 cores: 1");
      CHECK_TRUE(wl_plan_make(&sw, &pw, &err) == WL_OK &&
                     wl_plan_ladder_cost(&sw, &pw, 1, NULL, &cost, &err) == WL_OK,
                 "the chosen ladder plans");
      CHECK_TRUE(pw.realisations == (k ? 8 : 1), "the plan runs the realisations chosen");
      if (k) { /* the realisations' price: 7 more explosions at each level, by hand */
        struct wl_plan_cost one;
        double extra = 0.0;
        sw.resolution.realisations.q.si = 1;
        for (int l = 0; l < sw.resolution.n_levels; l++) {
          struct wl_scenario sl = sw;
          struct wl_plan pl;
          sl.resolution.dp.is_auto = 0, sl.resolution.dp.given = 1;
          sl.resolution.dp.q.si = wl_plan_level_dp(&sw, &pw, sw.resolution.levels[l].q.si);
          if (wl_plan_make(&sl, &pl, &err) == WL_OK) extra += 7 * pl.explosion.particle_steps;
        }
        CHECK_TRUE(wl_plan_make(&sw, &pw, &err) == WL_OK && pw.realisations == 1 &&
                       wl_plan_ladder_cost(&sw, &pw, 1, NULL, &one, &err) == WL_OK,
                   "the same ladder with one realisation plans");
        CHECK_REL(cost.cpu_seconds - one.cpu_seconds,
                  extra * pw.evals_per_step / WL_PLAN_CPU_RATE, 1e-9,
                  "8 realisations cost 7 more explosion runs a level (CPU price)");
      }
      CHECK_REL(wl_plan_machine_seconds(&cost, machines[k]), measured_s[k], 0.25,
                k ? "auto's ladder estimate vs its H100 run" : "auto's ladder estimate vs its 2-core run");
      CHECK_TRUE(c.seconds <= WL_PLAN_AUTO_SECONDS && (k == 1 || c.next_seconds > WL_PLAN_AUTO_SECONDS),
                 "auto takes the finest candidate within its budget");
      wl_scenario_clear(&sw);
    }
    /* --budget below auto's 20 min bounds what auto plans */
    if (plan_seawall(0, &sw, &pw)) {
      struct wl_plan_choice c;
      struct wl_plan_machine tight = gpu;
      tight.budget_seconds = 20.0;
      CHECK_TRUE(wl_plan_choose(&sw, &tight, &c, &err) == WL_OK && c.limit == 20.0 &&
                     c.ppH < 5.66 && (c.seconds <= 20.0 || c.ppH == 2.0) && c.next_seconds > 20.0,
                 "a 20 s budget on an H100: auto plans a coarser ladder within it");
    }
    wl_scenario_clear(&sw);
    /* a written value is the user's */
    if (plan_seawall(0, &sw, &pw)) {
      struct wl_plan_choice c;
      sw.resolution.particles_per_height.is_auto = 0;
      sw.resolution.particles_per_height.q.si = 3.0;
      CHECK_TRUE(wl_plan_choose(&sw, &gpu, &c, &err) == WL_OK && !c.is_auto &&
                     sw.resolution.particles_per_height.q.si == 3.0,
                 "a written particles_per_height is left alone");
    }
    wl_scenario_clear(&sw);
  }
  /* The still-water reference run (plan.h): one more run of a case, once a
   * level of a ladder (not once a realisation); its price by hand. */
  {
    struct wl_scenario sw;
    struct wl_plan on, off;
    struct wl_error err;
    wl_error_clear(&err);
    if (plan_seawall(0.012, &sw, &on)) {
      CHECK_TRUE(on.explosion.still_reference && !on.solitary.still_reference,
                 "auto: the explosion's case has a still-water reference, the solitary's none");
      sw.run.still_reference.choice = WL_STILL_REF_OFF;
      CHECK_TRUE(wl_plan_make(&sw, &off, &err) == WL_OK && !off.explosion.still_reference,
                 "off: no reference");
      CHECK_REL(on.particle_steps - off.particle_steps, off.explosion.particle_steps, 1e-12,
                "the reference costs one more explosion run");
      CHECK_REL(on.gpu_work_seconds - off.gpu_work_seconds, off.gpu_case_work_seconds[1], 1e-12,
                "and on a GPU the same work, beside the case");
      sw.run.still_reference.choice = WL_STILL_REF_ON;
      CHECK_TRUE(wl_plan_make(&sw, &on, &err) == WL_OK && on.solitary.still_reference &&
                     on.explosion.still_reference,
                 "on: both cases have one");
    }
    wl_scenario_clear(&sw);
    if (plan_seawall(0, &sw, &on)) { /* the ladder, 4 realisations a level */
      struct wl_plan_cost c_on, c_off;
      sw.resolution.realisations.is_auto = 0, sw.resolution.realisations.q.si = 4;
      double by_hand = 0.0;
      int ok = wl_plan_make(&sw, &on, &err) == WL_OK &&
               wl_plan_ladder_cost(&sw, &on, 1, NULL, &c_on, &err) == WL_OK;
      for (int l = 0; ok && l < sw.resolution.n_levels; l++) {
        struct wl_scenario sl = sw;
        struct wl_plan pl;
        sl.resolution.dp.is_auto = 0, sl.resolution.dp.given = 1;
        sl.resolution.dp.q.si = wl_plan_level_dp(&sw, &on, sw.resolution.levels[l].q.si);
        ok = wl_plan_make(&sl, &pl, &err) == WL_OK;
        if (ok) by_hand += pl.explosion.particle_steps;
      }
      sw.run.still_reference.choice = WL_STILL_REF_OFF;
      ok = ok && wl_plan_make(&sw, &off, &err) == WL_OK &&
           wl_plan_ladder_cost(&sw, &off, 1, NULL, &c_off, &err) == WL_OK;
      CHECK_TRUE(ok, "the ladder plans with and without the reference");
      if (ok)
        CHECK_REL(c_on.cpu_seconds - c_off.cpu_seconds,
                  by_hand * on.evals_per_step / WL_PLAN_CPU_RATE, 1e-9,
                  "a ladder's references: one explosion run a level (CPU price)");
    }
    wl_scenario_clear(&sw);
  }
  /* The plan owns h, c0 and the time step's estimate; each case's flume
   * hands the solver the plan's coefficients and depths, so the solver's
   * constants are the plan's to the last bit (issue 20: check printed a
   * time step from an h and c0 the run did not use). */
  {
    struct wl_scenario sw;
    struct wl_plan pw;
    if (plan_seawall(0.0, &sw, &pw)) {
      const enum wl_load_case load[2] = {WL_CASE_SOLITARY, WL_CASE_EXPLOSION};
      const double c0_plan[2] = {pw.solitary.c0, pw.explosion.c0};
      for (int i = 0; i < 2; i++) {
        struct wl_flume f;
        struct wl_sph_const k;
        struct wl_error err;
        wl_error_clear(&err);
        memset(&f, 0, sizeof f);
        int ok = wl_flume_build(&sw, &pw, load[i], &f, &err) == WL_OK &&
                 wl_sph_const_make(&f.cfg.prm, &k, &err) == WL_OK;
        CHECK_TRUE(ok, "seawall.yaml's flume and the solver's constants");
        if (!ok) printf("  %s\n", err.msg);
        if (ok) {
          CHECK_TRUE(k.h_d == pw.h_sml, "the solver's h is the plan's, bit for bit");
          CHECK_TRUE(k.c0_d == c0_plan[i], "the solver's c0 is the plan's case's, bit for bit");
        }
        wl_flume_clear(&f);
      }
    }
    wl_scenario_clear(&sw);
  }
  /* Runs side by side on one GPU (plan.h wl_plan_gpu_side_by_side) against
   * the measured sweep of seawall-sweep.yaml (BENCHMARKS.md, "Sweeps", H100,
   * 2026-11-27T17:28Z, code 28af3ea's GPU loops): its 16 cases alone took
   * these times one after the other (70.56 s) and 17.54 s side by side. The
   * force loops' work of the 16 at the full rate (9.51 s, their plans') is
   * the model's input; within 10 % of the measured sweep. plan.h's shared
   * efficiency was fitted to these 16 (alone and side by side), so this
   * check holds the fit; the 64-case sweep below and seawall.yaml's pair
   * above are runs the fit did not use. */
  {
    static const double alone[16] = {4.03, 4.50, 5.00, 5.41, 3.91, 4.23, 4.86, 5.23,
                                     3.64, 4.01, 4.38, 4.82, 3.61, 3.99, 4.29, 4.65};
    struct wl_plan_cost runs[16];
    for (int i = 0; i < 16; i++) {
      memset(&runs[i], 0, sizeof runs[i]);
      runs[i].gpu_seconds = alone[i];
      runs[i].gpu_work_seconds = 9.51 / 16;
    }
    CHECK_REL(wl_plan_gpu_side_by_side(runs, 16, 1), 70.56, 1e-12,
              "one at a time: the cases' times added");
    CHECK_REL(wl_plan_gpu_side_by_side(runs, 16, 16), 17.54, 0.10,
              "16 side by side vs the measured sweep (BENCHMARKS.md, Sweeps)");
    /* processor sharing by hand (cost 0.064 a run beside): runs of 1 s and
     * 3 s alone share the GPU for 1 s of the first's (1.064 s), then the
     * second runs alone for its remaining 2 s; two equal runs of 2 s take
     * 2 x 1.064 s together */
    struct wl_plan_cost two[2];
    memset(two, 0, sizeof two);
    two[0].gpu_seconds = 1.0, two[1].gpu_seconds = 3.0;
    CHECK_REL(wl_plan_gpu_side_by_side(two, 2, 2), 1.064 + 2.0, 1e-12,
              "1 s beside 3 s: 1.064 s shared, then 2 s alone");
    two[0].gpu_seconds = two[1].gpu_seconds = 2.0;
    CHECK_REL(wl_plan_gpu_side_by_side(two, 2, 2), 2.128, 1e-12, "two equal runs of 2 s");
    CHECK_REL(wl_plan_gpu_side_by_side(two, 2, 1), 4.0, 1e-12, "one at a time: 4 s");
    /* the 64-case sweep of the same call: 66.00 s, 16 at a time; its force
     * loops' work 37.9 s (the plans'); each case alone taken as the 16's
     * mean, 4.41 s (the 64 were not run alone) */
    {
      struct wl_plan_cost r64[64];
      for (int i = 0; i < 64; i++) {
        memset(&r64[i], 0, sizeof r64[i]);
        r64[i].gpu_seconds = 4.41;
        r64[i].gpu_work_seconds = 37.9 / 64;
      }
      CHECK_REL(wl_plan_gpu_side_by_side(r64, 64, 16), 66.00, 0.10,
                "64 cases 16 at a time vs the measured sweep (BENCHMARKS.md, Sweeps)");
    }
    /* never below the force loops' work: small (latency-bound) runs at
     * 0.68 k / (k + 4) of the full rate together (k = 16 here), large runs
     * at 0.68 of it (a whole step is more than its force loop) */
    for (int i = 0; i < 16; i++) runs[i].gpu_seconds = 10.0, runs[i].gpu_work_seconds = 9.0;
    CHECK_REL(wl_plan_gpu_side_by_side(runs, 16, 16), 16 * 9.0 / (0.68 * 16 / (16 + 4.0)), 1e-12,
              "latency-bound runs: their work at the shared efficiency");
    for (int i = 0; i < 16; i++) runs[i].gpu_seconds = runs[i].gpu_work_seconds = 9.0;
    CHECK_REL(wl_plan_gpu_side_by_side(runs, 16, 16), 16 * 9.0 / 0.68, 1e-12,
              "rate-bound runs: their work added, at the full GPU's share");
    /* how many fit: half of the GPU's memory */
    CHECK_TRUE(wl_plan_gpu_side_by_side_width(10e9, 80e9, 16) == 4, "4 runs of 10 GB in half of 80 GB");
    CHECK_TRUE(wl_plan_gpu_side_by_side_width(1e6, 80e9, 16) == 16, "at most the given width");
    CHECK_TRUE(wl_plan_gpu_side_by_side_width(60e9, 80e9, 16) == 1, "at least one");
  }
  /* resolution.realisations: the crater moved by r dp / n (by hand), and
   * never more than a ladder runs */
  CHECK_REL(wl_plan_realisation_x(12.0, 0.004, 1, 4), 12.001, 1e-15, "realisation 2 of 4: + dp/4");
  CHECK_REL(wl_plan_realisation_x(12.0, 0.004, 3, 4), 12.003, 1e-15, "realisation 4 of 4: + 3 dp/4");
  CHECK_TRUE(wl_plan_realisation_x(12.0, 0.004, 0, 4) == 12.0 &&
                 wl_plan_realisation_x(12.0, 0.004, 0, 1) == 12.0,
             "the first realisation is the scenario's crater");
  /* Whole rows of still water (plan.h wl_plan_whole_rows_dp). seawall.yaml:
   * h = 0.36 m, a platform at z = 0.30 m (0.06 m of water at the wall), a
   * ladder from 0.025 m asked for (2 particles over the 0.05 m solitary
   * wave) x 1, 0.71, 0.5. By hand: the nearest spacing within -20/+10 % of
   * the asked one at which both depths are whole rows is 0.06/3 = 0.02 m
   * (18 and 3 rows) for 0.025 m, 0.06/4 = 0.015 m (24, 4) for 0.01775 m
   * and 0.06/5 = 0.012 m (30, 5) for 0.0125 m. At 0.0125 m as asked, the
   * rows (j + 1/2) 0.0125 < 0.36 are j = 0..28 and those on the platform
   * start at j = 24: 5 rows, 0.0625 m (+4 %, issue 19's number). The
   * flume the scene builder lays (an independent count: its fluid
   * particles in the column next to the wall) must hold the plan's rows. */
  {
    struct wl_scenario sw;
    struct wl_plan pw;
    struct wl_error err;
    wl_error_clear(&err);
    if (plan_seawall(0.0, &sw, &pw)) {
      CHECK_ABS(pw.dp, 0.02, 1e-12, "dp auto: 0.06/3 m, whole rows at the wall and offshore");
      CHECK_ABS(pw.depth_wall_model, 0.06, 1e-12, "0.06 m at the wall modelled exactly (3 rows)");
      CHECK_ABS(pw.depth_model, 0.36, 1e-12, "0.36 m offshore modelled exactly (18 rows)");
      CHECK_ABS(wl_plan_modelled_depth(0.36, 0.0, 0.30, 0.0125), 0.0625, 1e-12,
                "0.0125 m: 5 rows on the platform, 0.0625 m (by hand)");
      CHECK_ABS(wl_plan_modelled_depth(0.36, 0.0, 0.0, 0.0125), 0.3625, 1e-12,
                "0.0125 m: 29 rows offshore, 0.3625 m (by hand)");
      /* 0.06/7 m written to 12 digits (0.008571428571, 3e-11 m short of it)
       * is 7 rows on the platform, as the user meant, not 6 */
      CHECK_ABS(wl_plan_modelled_depth(0.36, 0.0, 0.30, 0.008571428571), 7 * 0.008571428571, 1e-12,
                "0.008571428571 m: 7 rows on the platform");
      /* the ladder's levels: 0.025 x 0.71 = 0.01775 m asked, 0.015 m (4
       * rows); 0.025 x 0.5 = 0.0125 m asked, 0.012 m (5 rows) */
      CHECK_ABS(wl_plan_level_dp(&sw, &pw, 0.71), 0.015, 1e-12, "ladder level x 0.71: 0.06/4 m");
      CHECK_ABS(wl_plan_level_dp(&sw, &pw, 0.5), 0.012, 1e-12, "ladder level x 0.5: 0.06/5 m");
      struct wl_flume f;
      memset(&f, 0, sizeof f);
      if (wl_flume_build(&sw, &pw, WL_CASE_EXPLOSION, &f, &err) == WL_OK) {
        const struct wl_particles *q = &f.particles;
        int rows = 0;
        for (int i = q->n_bound; i < q->n; i++)
          if (q->pos[0][i] > f.x_wall - pw.dp && q->pos[0][i] < f.x_wall) rows++;
        CHECK_ABS(rows * pw.dp, pw.depth_wall_model, 1e-12,
                  "the flume's fluid column at the wall holds the plan's rows");
      } else {
        printf("FAIL seawall.yaml flume: %s\n", err.msg), wl_test_failures++;
      }
      wl_flume_clear(&f);
    }
    wl_scenario_clear(&sw);
  }
  /* The explosion's end time: the train's waves of the crater's diameter
   * (lambda = 2 r0) must have reached the wall at their group velocity.
   * A small crater in deep water (r0 = 0.25 m, h = 5 m: k h = 63) has the
   * deep-water group velocity c_g = sqrt(g / k) / 2, k = 2 pi / lambda
   * (Lamb, Hydrodynamics, section 236), from the crater's outer edge
   * (x = 15 m - extent) to the wall (40 m); the leading edge's 1.5 x
   * travel at sqrt(g h) is far shorter. A crater wide against the depth
   * (r0 = 2 m in 0.5 m) is not dispersive: 1.5 x its long-wave travel from
   * 2 extents behind the centre. The seaward end absorbs over four extents
   * (or two depths), from two extents behind the centre. */
  {
    const char *text =
        "scenario: t\nwater: {depth: 5 m}\ndomain: {length: 45 m}\n"
        "wall: {x: 40 m, height: 10 m}\nloads: {explosion: {eta0: 0.1 m, r0: 0.25 m, at: 15 m}}\n"
        "resolution: {dp: 0.05 m}\n";
    if (make(text, &s, &p)) {
      const double g = 9.81, k = 2 * 3.14159265358979 / 0.5, e = p.explosion.extent;
      CHECK_REL(p.explosion.end_time, (40.0 - (15.0 - e)) / (0.5 * sqrt(g / k)), 1e-3,
                "explosion end time: deep-water group velocity of lambda = 2 r0 (Lamb 236)");
      CHECK_REL(p.explosion.absorber, fmax(4 * e, 10.0), 1e-12, "absorbing zone: 2 depths");
      CHECK_REL(p.explosion.x_left, 15.0 - 2 * e - 10.0, 1e-12,
                "the flume starts an absorbing zone behind the crater");
    }
    wl_scenario_clear(&s);
    text = "scenario: t\nwater: {depth: 0.5 m}\ndomain: {length: 45 m}\n"
           "wall: {x: 40 m, height: 2 m}\nloads: {explosion: {eta0: 0.1 m, r0: 2 m, at: 15 m}}\n"
           "resolution: {dp: 0.05 m}\n";
    if (make(text, &s, &p)) {
      const double e = p.explosion.extent;
      CHECK_REL(p.explosion.end_time, 1.5 * (40.0 - (15.0 - 2 * e)) / sqrt(9.81 * 0.5), 1e-3,
                "explosion end time, crater wide against the depth: 1.5 x long-wave travel");
      CHECK_REL(p.explosion.absorber, 4 * e, 1e-12, "absorbing zone: 4 extents");
    }
    wl_scenario_clear(&s);
  }
  /* domain.dimensions auto (plan_dims): 2D unless an axisymmetric crater
   * is narrower than the flume. Seed 001: 32 lb gives R0 = 8.28 m (Van
   * Dorn, 2 R0 = 16.56 m), so a 16 m flume is spanned by the crater (2D)
   * and a 17 m one is not (3D); a plane lip or a solitary wave is 2D. */
  {
    struct {
      const char *domain, *load;
      int dims, symmetry;
      const char *why;
    } cases[] = {
        {"{length: 45 m, width: 17 m}", "explosion: {charge: 32 lb, at: 15 m}", 3, 1,
         "32 lb in a 17 m flume: 3D (2 R0 = 16.56 m < 17 m), 34 rows: symmetry plane"},
        {"{length: 45 m, width: 16 m}", "explosion: {charge: 32 lb, at: 15 m}", 2, 0,
         "32 lb in a 16 m flume: 2D (the crater spans it)"},
        {"{length: 45 m, width: 17 m}", "explosion: {charge: 32 lb, at: 15 m, lip_form: plane}", 2,
         0, "a plane crater (line source): 2D"},
        {"{length: 45 m, width: 17 m}", "solitary: {height: 0.5 m}", 2, 0, "a solitary wave: 2D"},
        {"{length: 45 m, width: 17 m}", "explosion: {charge: 32 lb, at: 15 m, model: thrown-mass}",
         2, 0, "the thrown-mass model (2D only): 2D"},
        {"{length: 45 m, width: 4 m}", "explosion: {eta0: 0.5 m, r0: 1 m, at: 15 m}", 3, 1,
         "eta0 + r0 (2 r0 = 2 m) in a 4 m flume: 3D, 4 m = 8 rows of dp = 0.5 m: symmetry plane"},
        /* the half between the symmetry plane and a free-slip wall must be
         * more than 2h = 2 x 1.0 sqrt(3) x 0.5 m = 1.732 m (3D, coefh 1.0) */
        {"{length: 45 m, width: 3 m}", "explosion: {eta0: 0.5 m, r0: 1 m, at: 15 m}", 3, 0,
         "... a 3 m flume = 6 rows: its half, 1.5 m, is within 2h = 1.73 m: no symmetry plane"},
        {"{length: 45 m, width: 3 m, side_walls: particles}",
         "explosion: {eta0: 0.5 m, r0: 1 m, at: 15 m}", 3, 1,
         "... with particle side walls it has one mirror plane: symmetry plane"},
        {"{length: 45 m, width: 3.5 m}", "explosion: {eta0: 0.5 m, r0: 1 m, at: 15 m}", 3, 0,
         "... a 3.5 m flume = 7 rows: no symmetry plane (auto)"},
        {"{length: 45 m, width: 3.5 m, symmetry: centreline}",
         "explosion: {eta0: 0.5 m, r0: 1 m, at: 15 m}", 3, 1, "... unless centreline is asked for"},
        {"{length: 45 m, width: 3 m, dimensions: 2}", "explosion: {eta0: 0.5 m, r0: 1 m, at: 15 m}",
         2, 0, "dimensions given: as given"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
      char text[512];
      snprintf(text, sizeof text,
               "scenario: t\nwater: {depth: 5 m}\ndomain: %s\nwall: {x: 40 m, height: 10 m}\n"
               "loads: {%s}\nresolution: {dp: 0.5 m}\n",
               cases[i].domain, cases[i].load);
      if (make(text, &s, &p)) {
        printf("  %s: %dD (%s), symmetry %d\n", cases[i].why, p.dims, p.dims_reason, p.symmetry);
        CHECK_TRUE(p.dims == cases[i].dims && p.symmetry == cases[i].symmetry, cases[i].why);
      }
      wl_scenario_clear(&s);
    }
  }

  /* wl_plan_default_numerics (what validate's scenario-less runs use) is
   * what a scenario without a numerics block gives the solver: the flume
   * built from the scenario path, field by field. */
  const char *plain = "scenario: t\nwater: {depth: 0.2 m}\ndomain: {length: 2 m}\n"
                      "wall: {x: 1.5 m, height: 0.4 m}\nloads: {solitary: {height: 0.04 m}}\n"
                      "resolution: {dp: 0.02 m}\n";
  if (make(plain, &s, &p)) {
    struct wl_flume f = {0};
    struct wl_error err;
    wl_error_clear(&err);
    if (wl_flume_build(&s, &p, WL_CASE_SOLITARY, &f, &err) == WL_OK) {
      const struct wl_sph_params *a = &f.cfg.prm;
      struct wl_sph_params b;
      wl_sph_params_default(&b, 2, a->dp, a->h_max);
      wl_plan_default_numerics(&b);
      CHECK_ABS(b.coefh, a->coefh, 0, "default numerics: coefh as the scenario's auto");
      CHECK_TRUE(b.visc == a->visc && b.nu == a->nu && b.alpha == a->alpha,
                 "default numerics: viscosity model, nu and alpha as the scenario's");
      CHECK_TRUE(b.coefsound == a->coefsound && b.cfl == a->cfl && b.delta == a->delta &&
                     b.ddt == a->ddt && b.visc_bound_factor == a->visc_bound_factor,
                 "default numerics: coefsound, CFL, density diffusion as the scenario's");
    } else {
      printf("FAIL flume: %s\n", err.msg);
      wl_test_failures++;
    }
    wl_flume_clear(&f);
  }
  wl_scenario_clear(&s);
  return TEST_RESULT();
}
