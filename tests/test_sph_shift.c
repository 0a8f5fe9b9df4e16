/* test_sph_shift.c: particle shifting (sph/shift.h) on a 2D block of
 * fluid on a square lattice, against a brute-force computation written out
 * here from the formulae (not the solver's kernel code):
 *  - Wendland C2 in 2D: W(q) = 7/(4 pi h^2) (1 - q/2)^4 (2q + 1), q = r/h,
 *    dW/dr = -(35/(4 pi h^3)) q (1 - q/2)^3 (Wendland 1995; Dehnen & Aly
 *    2012 table 1 with support 2h);
 *  - grad C_i = sum_j V_j grad_i W_ij, div r_i = -sum_j V_j r_ij . grad_i W_ij;
 *  - delta r = -A h |v| dt grad C, ramped by (div r - TFS)/(dim - TFS) and
 *    zero below TFS, each component capped at 0.1 dp (DualSPHysics 4-5).
 * Closed-form expectations as well: on a uniform lattice grad C vanishes
 * at an interior particle by symmetry, and div r is the dimension (the
 * identity int r . grad W dV = -dim for a normalised kernel) to the
 * lattice's quadrature error. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/sph.h"
#include "wallload/sph/shift.h"

enum { NX = 21, NZ = 21, N = NX * NZ };
#define DP 0.01
#define PI 3.14159265358979323846

struct block {
  struct wl_sph_config cfg;
  struct wl_sph_const k;
  struct wl_sph_grid g;
  double x[N], z[N];
  wl_real vx[N], vz[N], rho[N], sx[N], sz[N];
  unsigned int key[N], perm[N];
  int *begin, *cursor;
  int order[N]; /* sorted position -> lattice index */
};

/* The block with particle `moved` displaced by (ddx, ddz), all moving at
 * (u, 0), sorted by cell; shifts computed for dt. */
static int run(struct block *b, int moved, double ddx, double ddz, double u, double dt) {
  struct wl_error err;
  wl_error_clear(&err);
  wl_sph_config_default(&b->cfg, 2, DP, 1.0);
  b->cfg.prm.shift_coef = 2.0;
  b->cfg.lo[0] = -0.05, b->cfg.hi[0] = NX * DP + 0.05;
  b->cfg.lo[1] = -0.05, b->cfg.hi[1] = NZ * DP + 0.05;
  if (wl_sph_const_make(&b->cfg.prm, &b->k, &err) || wl_sph_grid_make(&b->cfg, &b->k, &b->g, &err)) {
    printf("FAIL setup: %s\n", err.msg);
    return 0;
  }
  double x[N], z[N];
  unsigned int key[N];
  for (int iz = 0; iz < NZ; iz++)
    for (int ix = 0; ix < NX; ix++) {
      const int i = iz * NX + ix;
      x[i] = (ix + 0.5) * DP + (i == moved ? ddx : 0.0);
      z[i] = (iz + 0.5) * DP + (i == moved ? ddz : 0.0);
      const int cx = wl_sph_cell_coord(&b->g, 0, x[i]), cz = wl_sph_cell_coord(&b->g, 1, z[i]);
      key[i] = (unsigned)(b->g.n_cells + cz * b->g.n[0] + cx); /* fluid group */
    }
  b->begin = malloc(sizeof(int) * (2 * (size_t)b->g.n_cells + 1));
  b->cursor = malloc(sizeof(int) * 2 * (size_t)b->g.n_cells);
  wl_sph_cells_sort(&b->g, key, N, b->begin, b->cursor, b->perm);
  for (int s = 0; s < N; s++) {
    const int i = (int)b->perm[s];
    b->order[s] = i;
    b->x[s] = x[i], b->z[s] = z[i], b->key[s] = key[i];
    b->vx[s] = (wl_real)u, b->vz[s] = 0, b->rho[s] = b->k.rho0;
  }
  struct wl_sph_eval e;
  memset(&e, 0, sizeof e);
  e.pos[0] = b->x, e.pos[1] = b->z;
  e.vel[0] = b->vx, e.vel[1] = b->vz;
  e.rho = b->rho, e.key = b->key, e.begin = b->begin;
  wl_real *sh[WL_SPH_DIM_MAX] = {b->sx, b->sz, NULL};
  for (int s = 0; s < N; s++) wl_sph_shift(2, &b->k, &b->g, &e, 0, s, dt, sh);
  return 1;
}

/* Brute force at lattice particle `li`: grad C, div r and the shift. */
static void brute(const struct block *b, int li, double u, double dt, double out[2],
                  double *divr_out) {
  const double h = b->k.h_d, vol = DP * DP; /* m_j / rho_j at rho0 */
  int si = 0;
  for (int s = 0; s < N; s++)
    if (b->order[s] == li) si = s;
  double gx = 0, gz = 0, divr = 0;
  for (int s = 0; s < N; s++) {
    const double rx = b->x[si] - b->x[s], rz = b->z[si] - b->z[s], r = hypot(rx, rz);
    const double q = r / h;
    if (r == 0 || q >= 2) continue;
    const double dwdr = -(35.0 / (4 * PI * h * h * h)) * q * pow(1 - q / 2, 3);
    gx += vol * dwdr * rx / r;
    gz += vol * dwdr * rz / r;
    divr -= vol * dwdr * r;
  }
  *divr_out = divr;
  const double tfs = 1.5, ramp = divr < tfs ? 0.0 : fmin(1.0, (divr - tfs) / (2 - tfs));
  const double sc = -2.0 * h * fabs(u) * dt * ramp, cap = 0.1 * DP;
  out[0] = fmax(-cap, fmin(cap, sc * gx));
  out[1] = fmax(-cap, fmin(cap, sc * gz));
}

static double got(const struct block *b, int li, int comp) {
  for (int s = 0; s < N; s++)
    if (b->order[s] == li) return comp ? b->sz[s] : b->sx[s];
  return NAN;
}

int main(void) {
  static struct block b;
  const int centre = (NZ / 2) * NX + NX / 2, top = (NZ - 1) * NX + NX / 2;
  const double u = 0.5, dt = 1e-4;
  /* 1. uniform lattice */
  if (!run(&b, -1, 0, 0, u, dt)) return 1;
  double ref[2], divr;
  brute(&b, centre, u, dt, ref, &divr);
  printf("# uniform lattice, interior particle: div r = %.6f, shift (%.3g, %.3g) m\n", divr,
         got(&b, centre, 0), got(&b, centre, 1));
  CHECK_REL(divr, 2.0, 0.01, "div r = dim inside the fluid (quadrature of int r.grad W dV = -dim)");
  CHECK_ABS(got(&b, centre, 0) / DP, 0.0, 1e-6, "uniform lattice: no shift (symmetry)");
  CHECK_ABS(got(&b, centre, 1) / DP, 0.0, 1e-6, "uniform lattice: no shift (symmetry)");
  brute(&b, top, u, dt, ref, &divr);
  printf("# top row (free surface): div r = %.4f\n", divr);
  CHECK_TRUE(divr < 1.5 && got(&b, top, 0) == 0 && got(&b, top, 1) == 0,
             "free surface (div r below TFS = 1.5): not shifted");
  free(b.begin), free(b.cursor);

  /* 2. one interior particle 0.2 dp to the right of its site: pushed back */
  if (!run(&b, centre, 0.2 * DP, 0.05 * DP, u, dt)) return 1;
  brute(&b, centre, u, dt, ref, &divr);
  printf("# displaced particle: div r = %.5f, shift (%.4g, %.4g) m, brute force (%.4g, %.4g) m\n",
         divr, got(&b, centre, 0), got(&b, centre, 1), ref[0], ref[1]);
  CHECK_TRUE(got(&b, centre, 0) < 0 && got(&b, centre, 1) < 0,
             "a displaced particle is shifted back towards its site (away from the crowd)");
  CHECK_REL(got(&b, centre, 0), ref[0], 1e-4, "shift x vs brute force (float sums)");
  CHECK_REL(got(&b, centre, 1), ref[1], 1e-4, "shift z vs brute force (float sums)");
  /* its neighbour on the right is pushed the other way */
  CHECK_TRUE(got(&b, centre + 1, 0) > 0, "the crowded neighbour is shifted away");
  /* the CPU's blocked form (WL_SPH_LANES particles of a cell at once, the
   * lane loop vectorised) gives the per-particle form's bits */
  {
    struct wl_sph_eval e;
    memset(&e, 0, sizeof e);
    e.pos[0] = b.x, e.pos[1] = b.z, e.vel[0] = b.vx, e.vel[1] = b.vz;
    e.rho = b.rho, e.key = b.key, e.begin = b.begin;
    static wl_real bx[N], bz[N];
    wl_real *sh[WL_SPH_DIM_MAX] = {bx, bz, NULL};
    for (int s0 = 0; s0 < N;) {
      int m = 1;
      while (m < WL_SPH_LANES && s0 + m < N && b.key[s0 + m] == b.key[s0]) m++;
      wl_sph_shift_block(2, WL_SPH_LANES, &b.k, &b.g, &e, s0, m, 0, dt, sh);
      s0 += m;
    }
    int same = 1;
    for (int s1 = 0; s1 < N; s1++) same &= bx[s1] == b.sx[s1] && bz[s1] == b.sz[s1];
    CHECK_TRUE(same, "blocked (8 lanes) and per-particle shifts bit-identical");
  }
  free(b.begin), free(b.cursor);

  /* 3. fast and long step: the 0.1 dp cap */
  if (!run(&b, centre, 0.2 * DP, 0.0, 50.0, 1e-2)) return 1;
  CHECK_ABS(got(&b, centre, 0), -0.1 * DP, 1e-9, "each component capped at 0.1 dp");
  free(b.begin), free(b.cursor);

  /* 4. off: zeros */
  if (!run(&b, centre, 0.2 * DP, 0.0, u, dt)) return 1;
  {
    struct wl_sph_const k0 = b.k;
    k0.shift_coef = 0;
    struct wl_sph_eval e;
    memset(&e, 0, sizeof e);
    e.pos[0] = b.x, e.pos[1] = b.z, e.vel[0] = b.vx, e.vel[1] = b.vz;
    e.rho = b.rho, e.key = b.key, e.begin = b.begin;
    wl_real *sh[WL_SPH_DIM_MAX] = {b.sx, b.sz, NULL};
    double m = 0;
    for (int s = 0; s < N; s++) {
      wl_sph_shift(2, &k0, &b.g, &e, 0, s, dt, sh);
      m = fmax(m, fabs(b.sx[s]) + fabs(b.sz[s]));
    }
    CHECK_TRUE(m == 0, "shift_coef 0: no shift anywhere");
  }
  free(b.begin), free(b.cursor);
  return TEST_RESULT();
}
