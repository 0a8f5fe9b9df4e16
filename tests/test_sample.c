/* test_sample.c: the sample stage (sample.h) on a hydrostatic particle
 * column, 2D and 3D, against closed forms (REFERENCES.md 1.1 for the wall
 * load of still water):
 *  - the gauge at the face reads the still-water level h (the height the
 *    particles' volume fills, n_rows dp), i.e. eta = 0;
 *  - probes deeper than one kernel support below the surface read
 *    rho0 g (h - z); probes at and above the surface read 0 (dry face:
 *    their Shepard sum under half of what the same lattice gives them with
 *    water standing over them);
 *  - the probe profile integrates to rho0 g h^2/2 and its moment about the
 *    toe to rho0 g h^3/6;
 *  - the fluid's potential energy above the floor is rho0 g L h^2/2 per
 *    metre (the lattice's rows at (k + 1/2) dp sum to it exactly), its
 *    kinetic energy rho0 L h u^2/2 and its momentum rho0 L h u at a uniform
 *    velocity u;
 *  - with the toe above the water the face is dry: force and moment 0;
 *  - against a face: the still-water Shepard sum of the wetness rule in
 *    closed form equals the particles' sum, and validate's sensors read
 *    rho0 g (h - z) under water and 0 above it.
 * The densities are the Tait equation's hydrostatic ones (eos.h inverse),
 * so the pressure each particle carries is rho0 g (h - z_j) exactly. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"
#include "wallload/sample.h"
#include "wallload/sph/eos.h"
#include "wallload/sph/probe.h"

#define RHO0 1000.0
#define G 9.81
#define DP 0.01
#define N_ROWS 30 /* h = 0.3 m */
#define N_ROWS_DEEP 55 /* water over every probe, by more than a kernel support */
#define U 0.125   /* uniform horizontal velocity [m/s], exact in float */

/* The gauge reads where the Shepard sum crosses 0.5 (sph/probe.h): on a
 * settled lattice within 0.002 dp of where the volume ends (h = 1.7 dp),
 * sampled every dp/10 and interpolated; 0.05 dp allows for the kernel's
 * shorter h = 1.41 dp here. */
#define GAUGE_TOL (0.05 * DP)
/* Interior probes: the Shepard interpolation of a linear field on a
 * symmetric lattice is exact inside the fluid; float densities leave
 * ~0.02 Pa. */
#define PROBE_TOL 1e-3
/* The force and moment: the profile's trapezoid rule and the one-sided
 * interpolation within a kernel support of the surface and of the floor
 * (no boundary particles here) stay within the 1 % of test_wall_still. */
#define LOAD_TOL 0.01
/* Energies and momentum: exact sums, but the particle mass rho0 dp^dim is
 * a float (sph/params.h wl_real), 1e-7 relative. */
#define SUM_TOL 1e-6

/* Fill p with a hydrostatic fluid lattice of nx x ny x rows particles
 * (ny 1 in 2D) from x = 0, y = 0, z = 0, moving at U along x. */
static int column(struct wl_particles *p, int dim, int nx, int ny, int rows,
                  const struct wl_sph_const *k) {
  struct wl_error err;
  wl_error_clear(&err);
  const int n = nx * ny * rows;
  if (wl_particles_alloc(p, dim, n, 0, &err)) {
    printf("FAIL particles: %s\n", err.msg);
    return 0;
  }
  const double h = rows * DP;
  int i = 0;
  for (int a = 0; a < nx; a++)
    for (int b = 0; b < ny; b++)
      for (int c = 0; c < rows; c++, i++) {
        const double z = (c + 0.5) * DP;
        p->pos[0][i] = (a + 0.5) * DP;
        if (dim == 3) p->pos[1][i] = (b + 0.5) * DP;
        p->pos[dim - 1][i] = z;
        for (int d = 0; d < dim; d++) p->vel[d][i] = 0;
        p->vel[0][i] = (wl_real)U;
        p->rho[i] = (wl_real)wl_sph_eos_rho_of_p(k->rho0, k->B, RHO0 * G * (h - z));
        p->id[i] = (unsigned)i;
        p->kind[i] = WL_KIND_FLUID;
        p->body[i] = 0;
      }
  p->n = n;
  p->n_bound = 0;
  return 1;
}

/* The face's still-water Shepard sum (sph/probe.h wl_sph_face_shepard_full,
 * a closed lattice sum) against the probe module's sum over real
 * particles, and validate's sensor reading (sph.h
 * wl_sph_probe_face_pressure): the water of the column's left half
 * stands against a face at x = L/2; sensors half a spacing off it read
 * rho0 g (h - z) under the surface (the fit is exact for a pressure linear
 * in height whatever cuts the kernel) and 0 above it (dry). */
static void face(int dim, const struct wl_flume *f, const struct wl_sph_const *k, int nx, int ny) {
  const int half = nx / 2;
  const double xw = half * DP, x_sensor = xw - 0.5 * DP, y = dim == 3 ? 0.5 * ny * DP : 0.0;
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_particles p;
  memset(&p, 0, sizeof p);
  struct wl_sph_probe *pr = NULL;
  for (int pass = 0; pass < 2; pass++) {
    const int rows = pass == 0 ? N_ROWS_DEEP : N_ROWS;
    const double h = rows * DP;
    if (!column(&p, dim, half, ny, rows, k) || wl_sph_probe_alloc(&pr, &f->cfg, &err) ||
        wl_sph_probe_index(pr, &p, &err)) {
      printf("FAIL the face column: %s\n", err.msg);
      wl_test_failures++;
      break;
    }
    if (pass == 0) { /* the closed sum's volumes are dp^dim: uncompressed water */
      for (int i = 0; i < p.n; i++) p.rho[i] = (wl_real)RHO0;
      if (wl_sph_probe_index(pr, &p, &err)) wl_test_failures++;
    }
    double worst = 0.0;
    int n = 0, ok = 0, dry = 0, dry_ok = 0;
    for (int i = 0; i < 90; i++) { /* every dp/2 from the floor to above the water */
      const double z = (i + 0.5) * 0.5 * DP;
      double x[3] = {x_sensor, dim == 3 ? y : z, z};
      if (pass == 0) {
        if (z > 0.5 * N_ROWS_DEEP * DP) continue;
        const double want = wl_sph_face_shepard_full(k, dim, DP, z, y);
        const double e = fabs(wl_sph_probe_shepard(pr, x) - want) / want;
        worst = e > worst ? e : worst;
        n++;
        ok += e <= 1e-5;
        continue;
      }
      double pz = -1.0;
      wl_sph_probe_face_pressure(pr, x, z, &pz);
      if (z >= h) {
        dry++;
        dry_ok += pz == 0.0;
      } else if (z > 2.0 * k->h_d && z < h - 2.0 * k->h_d) {
        const double want = RHO0 * G * (h - z), e = fabs(pz - want) / want;
        worst = e > worst ? e : worst;
        n++;
        ok += e <= PROBE_TOL;
      }
    }
    if (pass == 0) {
      printf("  face: still-water Shepard sums at %d heights, worst %.1e\n", n, worst);
      CHECK_TRUE(n > 10 && ok == n,
                 "the face's closed lattice sum is the particles' Shepard sum (1e-5, float kernel)");
    } else {
      printf("  face sensors: %d under water, worst %.1e; %d dry\n", n, worst, dry);
      CHECK_TRUE(n > 10 && ok == n, "sensors off the face read rho0 g (h - z) within 1e-3");
      CHECK_TRUE(dry > 10 && dry_ok == dry, "sensors above the water read 0 (dry)");
    }
    wl_sph_probe_free(pr);
    pr = NULL;
    wl_particles_clear(&p);
  }
  wl_sph_probe_free(pr);
  wl_particles_clear(&p);
}

static void run(int dim) {
  const int nx = dim == 2 ? 100 : 40, ny = dim == 2 ? 1 : 12;
  const double h = N_ROWS * DP, L = nx * DP, W = ny * DP;
  struct wl_flume *f = calloc(1, sizeof *f);
  struct wl_error err;
  wl_error_clear(&err);
  wl_sph_config_default(&f->cfg, dim, DP, h);
  f->cfg.prm.rho0 = RHO0;
  f->cfg.prm.g = G;
  f->cfg.lo[0] = -0.1, f->cfg.hi[0] = L + 0.1;
  f->cfg.lo[1] = -0.1, f->cfg.hi[1] = (dim == 2 ? 0.6 : W + 0.1);
  if (dim == 3) f->cfg.lo[2] = -0.1, f->cfg.hi[2] = 0.6;
  struct wl_sph_const k;
  if (wl_sph_const_make(&f->cfg.prm, &k, &err)) {
    printf("FAIL constants: %s\n", err.msg);
    wl_test_failures++;
    free(f);
    return;
  }
  /* a face at the middle of the column: probes on its line every dp/2
   * from the floor to above the water, the gauge on it */
  f->dims = dim;
  f->width = dim == 3 ? W : 0.0;
  f->depth = h;
  f->z_toe = 0.0, f->z_crest = 0.5;
  f->probe_x = 0.5 * L;
  f->n_probes = 90;
  for (int i = 0; i < f->n_probes; i++) f->probe_z[i] = (i + 0.5) * 0.5 * DP;
  if (dim == 3) {
    f->n_probe_y = 2;
    f->probe_y[0] = 0.4 * W, f->probe_y[1] = 0.6 * W;
    f->gauge_y = 0.5 * W;
  }
  f->n_gauges = 1;
  f->gauge_x[0] = 0.5 * L;
  f->gauge_bed[0] = 0.0;
  struct wl_particles p;
  memset(&p, 0, sizeof p);
  /* The wetness rule's reference (flume.h probe_shepard_full): the Shepard
   * sum each probe reads with still water standing over it, here from the
   * same lattice 55 rows deep, summed by the probe module directly. */
  struct wl_sph_probe *deep_probe = NULL;
  if (!column(&p, dim, nx, ny, N_ROWS_DEEP, &k) ||
      wl_sph_probe_alloc(&deep_probe, &f->cfg, &err) ||
      wl_sph_probe_index(deep_probe, &p, &err)) {
    printf("FAIL the deep column: %s\n", err.msg);
    wl_test_failures++;
  }
  for (int i = 0; deep_probe && i < f->n_probes; i++) {
    double sum = 0.0;
    const int n_y = dim == 3 ? f->n_probe_y : 1;
    for (int j = 0; j < n_y; j++) {
      double x[3] = {f->probe_x, dim == 3 ? f->probe_y[j] : f->probe_z[i], f->probe_z[i]};
      sum += wl_sph_probe_shepard(deep_probe, x);
    }
    f->probe_shepard_full[i] = sum / n_y;
  }
  wl_sph_probe_free(deep_probe);
  wl_particles_clear(&p);
  struct wl_sample *s = NULL;
  struct wl_record r;
  memset(&r, 0, sizeof r);
  r.n_gauges = f->n_gauges, r.n_probes = f->n_probes;
  if (!column(&p, dim, nx, ny, N_ROWS, &k) || wl_sample_alloc(&s, f, &err) ||
      wl_sample_state(s, &p, &k, f->cfg.hi[dim - 1], 0.25, &r, &err)) {
    printf("FAIL sampling the %dD column: %s\n", dim, err.msg);
    wl_test_failures++;
  } else {
    printf("%dD column: %d particles, h = %g m, kernel h = %g m\n", dim, p.n, h, (double)k.h_d);
    CHECK_TRUE(r.n == 1 && r.t[0] == 0.25, "one row at the time given");
    CHECK_ABS(r.eta[0], 0.0, GAUGE_TOL, "gauge reads the still-water level h (sph/probe.h)");
    const double support = 2.0 * k.h_d;
    int interior = 0, interior_ok = 0, dry = 0, dry_ok = 0;
    double worst = 0.0;
    for (int i = 0; i < f->n_probes; i++) {
      const double z = f->probe_z[i], pr = r.pressure[i];
      if (z >= h) {
        dry++;
        dry_ok += pr == 0.0;
      } else if (z > support && z < h - support) {
        const double want = RHO0 * G * (h - z), e = fabs(pr - want) / want;
        interior++;
        interior_ok += e <= PROBE_TOL;
        if (e > worst) worst = e;
      }
    }
    printf("  interior probes: %d, worst relative error %.2e\n", interior, worst);
    CHECK_TRUE(interior > 10 && interior_ok == interior,
               "interior probes read rho0 g (h - z) within 1e-3 (hydrostatics)");
    CHECK_TRUE(dry > 10 && dry_ok == dry, "probes at and above the surface read 0 (dry face)");
    CHECK_REL(r.force[0], RHO0 * G * h * h / 2, LOAD_TOL, "probe force rho0 g h^2/2");
    CHECK_REL(r.moment[0], RHO0 * G * h * h * h / 6, LOAD_TOL,
              "probe moment about the toe rho0 g h^3/6");
    CHECK_TRUE(r.force_bound[0] == 0.0 && r.moment_bound[0] == 0.0,
               "wl_sample_state leaves the boundary force to wl_sample_sim");
    /* per metre of width in 3D: L x W x h of water, per W */
    CHECK_REL(r.potential[0], RHO0 * G * L * h * h / 2, SUM_TOL,
              "potential energy rho0 g L h^2/2 (rows at (k + 1/2) dp)");
    CHECK_REL(r.kinetic[0], 0.5 * RHO0 * L * h * U * U, SUM_TOL, "kinetic energy rho0 L h u^2/2");
    CHECK_REL(r.momentum[0], RHO0 * L * h * U, SUM_TOL, "momentum rho0 L h u");
    /* the toe above the water, the probes on the face above it: nothing
     * loads the face */
    f->z_toe = h + DP;
    for (int i = 0; i < f->n_probes; i++)
      f->probe_z[i] = f->z_toe + (i + 0.5) * (f->z_crest - f->z_toe) / f->n_probes;
    if (wl_sample_state(s, &p, &k, f->cfg.hi[dim - 1], 0.5, &r, &err)) {
      printf("FAIL second row: %s\n", err.msg);
      wl_test_failures++;
    } else {
      CHECK_TRUE(r.n == 2 && r.force[1] == 0.0 && r.moment[1] == 0.0,
                 "a face above the water carries no load");
      CHECK_TRUE(r.eta[1] == r.eta[0], "the same state samples the same gauge reading");
    }
  }
  wl_sample_free(s);
  wl_sample_record_clear(&r);
  wl_particles_clear(&p);
  face(dim, f, &k, nx, ny);
  free(f);
}

int main(void) {
  run(2);
  run(3);
  /* a record grows past its first allocation and keeps every row */
  struct wl_record r;
  memset(&r, 0, sizeof r);
  r.n_gauges = 2, r.n_probes = 3;
  struct wl_error err;
  wl_error_clear(&err);
  int ok = 1;
  for (int i = 0; i < 3000 && ok; i++) {
    ok = wl_sample_record_push(&r, &err) == WL_OK;
    if (ok) r.t[i] = i, r.pressure[3 * (size_t)i + 2] = -i;
  }
  int kept = ok;
  for (int i = 0; kept && i < 3000; i++) kept = r.t[i] == i && r.pressure[3 * (size_t)i + 2] == -i;
  CHECK_TRUE(ok && r.n == 3000 && kept, "a record keeps 3000 rows through its growth");
  wl_sample_record_clear(&r);
  CHECK_TRUE(r.n == 0 && r.t == NULL, "a cleared record is empty");
  wl_sample_free(NULL);
  return TEST_RESULT();
}
