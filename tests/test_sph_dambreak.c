/* test_sph_dambreak.c: 2D dry-bed dam break against Koshizuka & Oka (1996)
 * and Martin & Moyce (1952).
 *
 * A water column a wide and 2a high (n^2 = 2) collapses at t = 0 in a tank
 * 4a long (Koshizuka & Oka's proportions, and DualSPHysics'
 * CaseDambreakVal2D) with walls 5H high: the jet that runs up the far wall
 * after the impact rises beyond 3H and is thrown back over the whole tank,
 * so lower walls would let it escape. The surge front Z = z/a is compared
 * against T = t sqrt(2g/a):
 *  - position: Koshizuka & Oka's (1996) MPS computation of this column in
 *    this tank (their figure of the front; two independent digitizations,
 *    PySPH's and OpenMPS's, agree within 1.2 %), within 5 % in Z (the brief's
 *    band) at every point from the first movement (T >= 0.3) until the far
 *    wall is felt (Z < 3.6);
 *  - speed: the least-squares slope dZ/dT over Martin & Moyce's Table 2
 *    points with T >= 1.5 (the front has formed) within 5 % of the table's;
 *  - the same points after the best single time shift dT (|dT| <= 0.35):
 *    within 5 % in Z.
 * Why the experiments' positions are not checked unshifted. The brief asks
 * for 5 % against Martin & Moyce and against Koshizuka & Oka's experiment,
 * but the two experiments disagree with each other by more than that (K&O's
 * front advances at dZ/dT = 1.08 over 1.5 <= T <= 3.1, M&M's at 1.31), and
 * both lag the two computations of the ideal release here by a
 * delay that builds up for T < 1.2, while their columns were being released:
 * K&O's own MPS runs 10-17 % ahead of M&M's table and 11-22 % ahead of their
 * own experiment over 1.5 <= T <= 2.9, and this engine 9-15 % and 9-20 %
 * (the test prints all three side by side). Numerical fronts ahead of
 * dam-break experiments are the usual finding (e.g. Jonsson et al. 2015,
 * Engineering 7:248). Neither the gate's motion nor the bed's friction in
 * those experiments is documented well enough to model, so the position is
 * checked against the computation of the ideal problem, and the experiments
 * through the front's speed and its shape in time; nothing was tuned to
 * either.
 * The run then goes on through the impact on the far wall to t sqrt(g/H) =
 * 8 with every value finite and no particle through a wall (the guard
 * would stop it with WL_EUNSTABLE).
 *
 * With the argument `shift` (ctest sph_dambreak_shift) the same run and
 * checks with particle shifting on.
 *
 * Resolution a/dp = 32 (2048 fluid particles), coefsound 20 (see below). At
 * a/dp = 40 (until 2026-11-27) the run took twice as long and read the same
 * front within 0.6 % of Z (2.3 % at most from K&O's MPS against 2.9 % here;
 * front speed 1.308 against 1.290, Martin & Moyce 1.308). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "dambreak_front.h"
#include "testutil.h"
#include "wallload/scene.h"
#include "wallload/sph.h"

#define A 1.0           /* column width a [m] */
#define N_A 32          /* a / dp */
#define TAU_END 8.0     /* t sqrt(g/H) */

int main(int argc, char **argv) {
  /* `shift`: the same run and checks with particle shifting on (sph/shift.h,
   * A = 2; ctest sph_dambreak_shift): the overturning jet and its splash
   * are where shifting works hardest */
  const int shifting = argc > 1 && !strcmp(argv[1], "shift");
  const double dp = A / N_A, H = 2 * A;
  const int layers = 3;

  struct wl_sph_config cfg;
  wl_sph_config_default(&cfg, 2, dp, H);
  /* One thread: thread independence is test_sph_threads' job; on a machine
   * shared with other jobs (CI, parallel ctest) each of the ~10^5 barriers
   * of a multi-threaded run can wait a scheduler time slice for a
   * descheduled partner, which made this test 30x slower there. */
  cfg.n_threads = 1;
  /* coefsound 20: with the default 10, the front runs at up to 0.3 c0 and
   * the fluid compresses visibly at the impact (DualSPHysics' dam-break
   * examples use 20 as well) */
  cfg.prm.coefsound = 20;
  if (shifting) cfg.prm.shift_coef = 2.0;
  struct front_log lg = {0};
  struct wl_sph_sim *sim = dambreak_run(&cfg, &wl_backend_cpu_ops, A, dp, layers, TAU_END, &lg);
  if (sim) dambreak_front_check(lg.t, lg.x, lg.n, sqrt(2 * 9.81 / A), A);
  free(lg.t);
  free(lg.x);
  wl_sph_sim_free(sim);
  return TEST_RESULT();
}
