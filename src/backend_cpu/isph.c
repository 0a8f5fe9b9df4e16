/* isph.c: the incompressible SPH backend (backend.h wl_backend_isph_ops), a
 * projection method on the host (OpenMP), 2D. One step:
 *
 *   1. cell rebuild (counting sort, as cpu.c);
 *   2. per fluid particle: div r (free surface), M^-1 (renormalised
 *      gradient), viscous acceleration; predictor u* = u + dt (g + visc);
 *      wall particles u* = u_w + dt (g - a_w) (sph/isph.h, "walls");
 *   3. div u*; the PPE rows of every particle (sph/isph.h
 *      wl_isph_ppe_row), scaled to a unit diagonal, compacted to CSR;
 *   4. the solve (BiCGSTAB or GSL's GMRES), warm-started from the last
 *      step's pressure;
 *   5. u^{n+1} = u* - dt/rho0 grad p, r^{n+1} = r^n + dt u^{n+1}; guard.
 *
 * The stored density of every particle is the Tait density of its ISPH
 * pressure (sph/wall.h wl_sph_eos_rho_of_p_fast), so every consumer that
 * reads pressure through the equation of state (probes, wall loads, HDF5
 * output, the guard) reads the projection's pressure without a change; the
 * Tait constants are then only a storage convention (docs/isph.md).
 *
 * Every parallel loop writes only its own particle's outputs; the dot
 * products of the solver are summed in fixed chunks in a fixed order, so the
 * results do not depend on the thread count. Everything is allocated at
 * init; the step allocates nothing (GSL's GMRES workspace included). */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_spmatrix.h>
#include <gsl/gsl_splinalg.h>
#include <gsl/gsl_vector.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "wallload/backend.h"
#include "wallload/sph.h"
#include "wallload/sph/cells.h"
#include "wallload/sph/guard.h"
#include "wallload/sph/isph.h"
#include "wallload/sph/wall.h"
#include "cpu_shared.h"

/* Dot products are summed over chunks of this many entries, each chunk in
 * index order, then the chunks in order: the same bits on any thread count. */
#define DOT_CHUNK 2048
/* GMRES restart length (GSL's Krylov dimension). */
#define GMRES_M 50

struct isph {
  struct wl_sph_config cfg;
  struct wl_sph_const k;
  struct wl_sph_grid grid;
  struct wl_isph_opts o; /* with the defaults filled in */
  struct wl_particles p, alt;
  int *begin, *cursor;
  unsigned int *key_tmp;
  int row_max;
  /* per particle */
  double *ustar[WL_SPH_DIM_MAX], *minv, *pfix, *press, *divu, *rhs, *fmax2;
  double *derr; /* relative compression beyond the rest lattice (>= 0), per particle */
  double wsum_ref; /* wl_isph_lattice_sum */
  double shift_a;  /* shifting coefficient A (0: off) */
  double u_wet;    /* approach speed that wets a dry wall [m/s] (wl_isph_wall_wetted) */
  unsigned char *fixed, *dry;
  double *gprev; /* lagged grad p (x, y, z) per particle */
  double *wall_n; /* outward unit normals of the wall particles (x, y, z) */
  double *gradc;  /* grad C (x, y, z) and the shift ramp (4 per particle) */
  /* the PPE: rows of row_max slots (assembly), then CSR */
  int *row_len, *slot_col, *rowptr, *col;
  double *slot_val, *val;
  /* BiCGSTAB vectors and the dot products' chunk sums */
  double *kv[6], *chunk;
  /* GSL */
  gsl_spmatrix *A;
  gsl_splinalg_itersolve *gmres;
  struct wl_isph_stats stats;
  int n_threads;
  double tfs;
};

static int threads(const struct isph *c) {
  return c->n_threads > 0 ? c->n_threads : omp_get_max_threads();
}

static double now_s(void) {
  struct timespec ts;
  timespec_get(&ts, TIME_UTC);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- cell rebuild (as cpu.c rebuild: state fields by the field table) --- */

static void rebuild(struct isph *c) {
  wl_cpu_rebuild(&c->p, &c->alt, &c->key_tmp, &c->grid, c->begin, c->cursor, NULL, threads(c));
}

/* ---- linear algebra on the CSR (rows scaled to a unit diagonal) -------- */

static void matvec(const struct isph *c, int n, const double *x, double *y) {
#pragma omp parallel for schedule(static) num_threads(threads(c))
  for (int i = 0; i < n; i++) {
    double s = 0;
    for (int q = c->rowptr[i]; q < c->rowptr[i + 1]; q++) s += c->val[q] * x[c->col[q]];
    y[i] = s;
  }
}

static double dot(const struct isph *c, int n, const double *a, const double *b) {
  const int nch = (n + DOT_CHUNK - 1) / DOT_CHUNK;
#pragma omp parallel for schedule(static) num_threads(threads(c))
  for (int ch = 0; ch < nch; ch++) {
    const int i1 = (ch + 1) * DOT_CHUNK < n ? (ch + 1) * DOT_CHUNK : n;
    double s = 0;
    for (int i = ch * DOT_CHUNK; i < i1; i++) s += a[i] * b[i];
    c->chunk[ch] = s;
  }
  double s = 0;
  for (int ch = 0; ch < nch; ch++) s += c->chunk[ch];
  return s;
}

/* BiCGSTAB (van der Vorst 1992, SIAM J. Sci. Stat. Comput. 13:631) on A x =
 * b, x the initial guess on entry. The rows carry a unit diagonal, so this
 * is Jacobi-preconditioned BiCGSTAB on the unscaled system. Returns the
 * iterations; *res the final |b - Ax|/|b|. */
static int bicgstab(struct isph *c, int n, const double *b, double *x, double tol, int max_iter,
                    double *res) {
  double *r = c->kv[0], *r0 = c->kv[1], *pv = c->kv[2], *v = c->kv[3], *s = c->kv[4],
         *t = c->kv[5];
  const double bn = sqrt(dot(c, n, b, b));
  if (!(bn > 0)) {
    memset(x, 0, sizeof(double) * (size_t)n);
    *res = 0;
    return 0;
  }
  matvec(c, n, x, r);
  for (int i = 0; i < n; i++) {
    r[i] = b[i] - r[i];
    r0[i] = r[i];
    pv[i] = v[i] = 0;
  }
  double rho = 1, alpha = 1, omega = 1, rn = sqrt(dot(c, n, r, r));
  int it = 0;
  while (rn > tol * bn && it < max_iter) {
    const double rho1 = dot(c, n, r0, r);
    if (rho1 == 0) break; /* breakdown: restart from here */
    const double beta = rho1 / rho * alpha / omega;
    for (int i = 0; i < n; i++) pv[i] = r[i] + beta * (pv[i] - omega * v[i]);
    matvec(c, n, pv, v);
    const double r0v = dot(c, n, r0, v);
    if (r0v == 0) break;
    alpha = rho1 / r0v;
    for (int i = 0; i < n; i++) s[i] = r[i] - alpha * v[i];
    it++;
    const double sn = sqrt(dot(c, n, s, s));
    if (sn <= tol * bn) {
      for (int i = 0; i < n; i++) x[i] += alpha * pv[i];
      rn = sn;
      break;
    }
    matvec(c, n, s, t);
    const double tt = dot(c, n, t, t);
    omega = tt > 0 ? dot(c, n, t, s) / tt : 0;
    for (int i = 0; i < n; i++) {
      x[i] += alpha * pv[i] + omega * s[i];
      r[i] = s[i] - omega * t[i];
    }
    rn = sqrt(dot(c, n, r, r));
    rho = rho1;
    if (omega == 0) break;
  }
  *res = rn / bn;
  return it;
}

/* GSL's restarted GMRES on the same CSR (gsl_splinalg_itersolve_gmres, m =
 * GMRES_M): each call of iterate is one restart cycle of up to m steps. */
static int gsl_gmres(struct isph *c, int n, const double *b, double *x, double tol, int max_iter,
                     double *res) {
  gsl_spmatrix *A = c->A;
  A->size1 = A->size2 = (size_t)n;
  memcpy(A->p, c->rowptr, sizeof(int) * (size_t)(n + 1));
  memcpy(A->i, c->col, sizeof(int) * (size_t)c->rowptr[n]);
  memcpy(A->data, c->val, sizeof(double) * (size_t)c->rowptr[n]);
  A->nz = (size_t)c->rowptr[n];
  gsl_vector_const_view bv = gsl_vector_const_view_array(b, (size_t)n);
  gsl_vector_view xv = gsl_vector_view_array(x, (size_t)n);
  int cycles = 0, status = GSL_CONTINUE;
  while (status == GSL_CONTINUE && cycles * GMRES_M < max_iter) {
    status = gsl_splinalg_itersolve_iterate(A, &bv.vector, tol, &xv.vector, c->gmres);
    cycles++;
  }
  const double bn = sqrt(dot(c, n, b, b));
  *res = bn > 0 ? gsl_splinalg_itersolve_normr(c->gmres) / bn : 0;
  return cycles * GMRES_M; /* GSL does not say how many steps the last cycle took */
}

/* ---- the step ------------------------------------------------------------ */

static void dump(const struct isph *c, int n) {
  char path[1024];
  snprintf(path, sizeof path, "%s.mtx", c->o.dump_path);
  FILE *f = fopen(path, "w");
  if (f) {
    fprintf(f, "%%%%MatrixMarket matrix coordinate real general\n%d %d %d\n", n, n, c->rowptr[n]);
    for (int i = 0; i < n; i++)
      for (int q = c->rowptr[i]; q < c->rowptr[i + 1]; q++)
        fprintf(f, "%d %d %.17g\n", i + 1, c->col[q] + 1, c->val[q]);
    fclose(f);
  }
  snprintf(path, sizeof path, "%s.rhs", c->o.dump_path);
  f = fopen(path, "w");
  if (f) {
    for (int i = 0; i < n; i++) fprintf(f, "%.17g %.17g\n", c->rhs[i], c->press[i]);
    fclose(f);
  }
}

static struct wl_isph_view view(const struct isph *c) {
  struct wl_isph_view v;
  memset(&v, 0, sizeof v);
  for (int a = 0; a < c->p.dim; a++) {
    v.pos[a] = c->p.pos[a];
    v.vel[a] = c->p.vel[a];
    v.ustar[a] = c->ustar[a];
  }
  v.key = c->p.key;
  v.begin = c->begin;
  v.n_bound = c->p.n_bound;
  v.dry = c->dry;
  v.wall_n = c->wall_n;
  return v;
}

/* g - a_w of boundary particle i (x, y, z slots) with the body
 * accelerations of in (NULL: at rest). */
static void wall_ga(const struct isph *c, const struct wl_sph_step_in *in, int i, double ga[3]) {
  const int dim = c->p.dim, az = dim - 1;
  const double *aw = in && c->p.kind[i] == WL_KIND_MOVING ? in->body_acc[c->p.body[i]] : NULL;
  ga[0] = ga[1] = ga[2] = 0;
  for (int a = 0; a < dim; a++)
    ga[a == az ? 2 : a] = (double)c->k.gravity[a] - (aw ? aw[a] : 0.0);
}

/* The guard of cpu.c (limiter, exclusion, faults: cpu_shared.h
 * wl_cpu_guard_chunk), after the update when `moved`. */
static void guard(struct isph *c, int moved, struct wl_sph_step_out *out) {
  struct wl_particles *p = &c->p;
  const int n = p->n, n_chunks = (n + WL_CPU_GUARD_CHUNK - 1) / WL_CPU_GUARD_CHUNK;
  int first = n;
  long limited = 0, excluded = 0;
  const int limiter = moved && c->k.wall_limiter;
#pragma omp parallel for schedule(static) num_threads(threads(c)) reduction(min : first) \
    reduction(+ : limited, excluded)
  for (int ch = 0; ch < n_chunks; ch++) {
    const int i0 = ch * WL_CPU_GUARD_CHUNK;
    const int i1 = i0 + WL_CPU_GUARD_CHUNK < n ? i0 + WL_CPU_GUARD_CHUNK : n;
    struct wl_cpu_guard_counts cnt = {n, 0, 0};
    wl_cpu_guard_chunk(&c->k, &c->cfg, p, i0, i1, limiter, moved, &cnt);
    first = cnt.first < first ? cnt.first : first;
    limited += cnt.limited;
    excluded += cnt.excluded;
  }
  wl_cpu_guard_report(&c->k, p, &c->cfg, first, limited, excluded, out);
}

/* The next step (Shao & Lo 2003; seed 003 eq. 20): cfl times the least of
 * h/max|u| (flow-speed CFL), sqrt(h/max|f|) (f the predictor's body and
 * viscous force per unit mass) and h^2/(8 nu) (viscous, Morris et al.
 * 1997: 0.125 h^2/nu with cfl folded in as cfl/0.2 * 0.125 <= 0.125). */
static void next_dt(const struct isph *c, double v2max, double f2max, struct wl_sph_step_out *out) {
  const double h = c->k.h_d, nu = c->cfg.prm.nu;
  const double vmax = sqrt(v2max), fmax = sqrt(f2max);
  out->vel_max = vmax;
  out->ace_max = fmax;
  out->dt_force = fmax > 0 ? sqrt(h / fmax) : INFINITY;
  out->dt_cv = vmax > 0 ? h / vmax : INFINITY;
  double dt = out->dt_force < out->dt_cv ? out->dt_force : out->dt_cv;
  if (c->k.visc == WL_SPH_VISC_LAMINAR && nu > 0 && 0.125 * h * h / nu < c->k.cfl * dt)
    dt = 0.125 * h * h / nu / c->k.cfl;
  out->dt_next = c->k.cfl * dt;
}

/* The lagged gradient of the consistent Laplacian is capped at this many
 * rho0 |g| (project). */
#define LAG_CAP 1.2
/* Restarts of BiCGSTAB after a breakdown, per solve. */
#define BICGSTAB_RESTARTS 4
/* Rounds of the walls' active set per step (project). */
#define ACTIVE_SET_ROUNDS 4

/* The PPE rows of every particle into CSR and the right-hand side, from
 * the fixed set; warm: the initial guess is last step's pressure (else the
 * pressure of the previous round, with the fixed values set). */
static enum wl_status assemble(struct isph *c, const struct wl_isph_view *v,
                               const struct wl_sph_step_in *in, double dt, int warm,
                               struct wl_error *err) {
  struct wl_particles *p = &c->p;
  const struct wl_sph_const *k = &c->k;
  const int n = p->n, nb = p->n_bound, dim = p->dim, rm = c->row_max;
  int overflow = -1;
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads(c)) reduction(max : overflow)
  for (int i = 0; i < n; i++) {
    double ga[3] = {0, 0, 0};
    if (i < nb) wall_ga(c, in, i, ga);
    if (i < nb && c->fixed[i]) c->pfix[i] = 0;
    const int m = wl_isph_ppe_row(dim, k, &c->grid, v, c->fixed, c->pfix, c->divu[i], dt, ga,
                                  &c->gprev[3 * (size_t)i], i,
                                  rm, &c->slot_col[(size_t)i * rm], &c->slot_val[(size_t)i * rm],
                                  &c->rhs[i]);
    c->row_len[i] = m;
    if (m < 0 && i > overflow) overflow = i;
  }
  if (overflow >= 0)
    return wl_error_set(err, WL_EUNSTABLE, "isph: particle %d (id %u) has more than %d "
                        "neighbours in the pressure equation (compressed far beyond a lattice)",
                        overflow, p->id[overflow], rm - 1);
  c->rowptr[0] = 0;
  for (int i = 0; i < n; i++) c->rowptr[i + 1] = c->rowptr[i] + c->row_len[i];
#pragma omp parallel for schedule(static) num_threads(threads(c))
  for (int i = 0; i < n; i++) {
    memcpy(&c->col[c->rowptr[i]], &c->slot_col[(size_t)i * rm], sizeof(int) * (size_t)c->row_len[i]);
    memcpy(&c->val[c->rowptr[i]], &c->slot_val[(size_t)i * rm],
           sizeof(double) * (size_t)c->row_len[i]);
    /* warm start: the last step's pressure, carried through the sort as
     * the Tait density (see the top of this file) */
    if (c->fixed[i]) c->press[i] = c->pfix[i];
    else if (warm) c->press[i] = (double)wl_sph_eos_p(k, p->rho[i]);
  }
  c->stats.nnz = c->rowptr[n];
  return WL_OK;
}

/* One projection step of length dt (in: body motions; NULL at init, where
 * only the pressure of the initial state is solved for with dt_probe and
 * nothing moves). */
static enum wl_status project(struct isph *c, const struct wl_sph_step_in *in, double dt,
                              struct wl_sph_step_out *out, struct wl_error *err) {
  const double t0 = now_s();
  struct wl_particles *p = &c->p;
  const struct wl_sph_const *k = &c->k;
  const int n = p->n, nb = p->n_bound, dim = p->dim, az = dim - 1;
  rebuild(c);
  /* the walls the fluid sees this step, and the pressure to start from
   * (last step's, carried as the Tait density) */
#pragma omp parallel for schedule(static) num_threads(threads(c))
  for (int i = 0; i < n; i++) c->press[i] = (double)wl_sph_eos_p(k, p->rho[i]);
  const struct wl_isph_view v = view(c);
  const struct wl_sph_grid *g = &c->grid;
  /* the walls' normals (moving bodies turn nothing: recomputed for the
   * sorted order each step) */
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads(c))
  for (int i = 0; i < nb; i++) wl_isph_wall_normal(dim, k, g, &v, i, &c->wall_n[3 * (size_t)i]);
  /* dry walls: not positive pressure and no fluid approaching within reach
   * (wl_isph_wall_wetted) */
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads(c))
  for (int i = 0; i < nb; i++)
    c->dry[i] = c->press[i] <= 0 &&
                (isinf(c->u_wet) || !wl_isph_wall_wetted(dim, k, g, &v, c->u_wet, i));
  const double nu4 = k->visc == WL_SPH_VISC_LAMINAR ? 4.0 * c->cfg.prm.nu : 0.0;
  const double rho0 = (double)k->rho0, half_dp = 0.5 * k->dp;
  const int offset = c->o.surface_offset > 0;
  int n_surface = 0;
  /* 1. geometry, surface, predictor */
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads(c)) reduction(+ : n_surface)
  for (int i = 0; i < n; i++) {
    if (i < nb) {
      double ga[3];
      wall_ga(c, in, i, ga);
      const double *bv = in && p->kind[i] == WL_KIND_MOVING ? in->body_vel[p->body[i]] : NULL;
      for (int a = 0; a < dim; a++)
        c->ustar[a][i] = (bv ? bv[a] : 0.0) + dt * ga[a == az ? 2 : a];
      c->fixed[i] = 0;
      c->pfix[i] = 0;
      c->fmax2[i] = 0;
      c->derr[i] = 0;
      continue;
    }
    if (p->body[i] == WL_SPH_BODY_EXCLUDED) {
      c->derr[i] = 0;
      for (int a = 0; a < dim; a++) c->ustar[a][i] = 0;
      c->fixed[i] = 1;
      c->pfix[i] = 0;
      c->fmax2[i] = 0;
      for (int a = 0; a < 6; a++) c->minv[6 * (size_t)i + a] = a < 3;
      continue;
    }
    struct wl_isph_geom geo;
    wl_isph_geometry(dim, k, g, &v, nu4, i, &geo);
    memcpy(&c->minv[6 * (size_t)i], geo.minv, sizeof geo.minv);
    const int surf = geo.div_r < c->tfs;
    /* the density-invariant source: compression only (a particle near the
     * free surface has a cut support and a low sum, which is no expansion) */
    const double e = geo.wsum / c->wsum_ref - 1.0;
    /* shifting: none on the surface, ramped in over tfs < div r < dim */
    double *gcv = &c->gradc[4 * (size_t)i];
    for (int a = 0; a < 3; a++) gcv[a] = geo.gradc[a];
    const double ramp = (geo.div_r - c->tfs) / ((double)dim - c->tfs);
    gcv[3] = surf ? 0.0 : ramp < 0 ? 0.0 : ramp > 1 ? 1.0 : ramp;
    c->derr[i] = !surf && e > 0 ? e : 0.0;
    c->fixed[i] = (unsigned char)surf;
    n_surface += surf;
    /* p_s: the hydrostatic pressure dp/2 under the fluid's edge along -n */
    double gn = 0;
    for (int a = 0; a < dim; a++) gn += (double)k->gravity[a] * geo.n[a == az ? 2 : a];
    c->pfix[i] = surf && offset && gn < 0 ? -rho0 * gn * half_dp : 0.0;
    double f2 = 0;
    for (int a = 0; a < dim; a++) {
      const double f = (double)k->gravity[a] + geo.visc[a == az ? 2 : a];
      c->ustar[a][i] = (double)p->vel[a][i] + dt * f;
      f2 += f * f;
    }
    c->fmax2[i] = f2;
  }
  c->stats.n_surface = n_surface;
  /* the density-invariant source enters as a divergence: lap p = rho0/dt
   * (div u* - (rho_i/rho_ref - 1)/tau) asks u^{n+1} to expand the
   * particle's neighbourhood at the rate that relaxes its compression over
   * tau; never more than half of it in one step */
  const double rate = c->o.density_tau > 0 ? fmin(1.0 / c->o.density_tau, 0.5 / dt) : 0.0;
  /* 2. div u* (once), then rounds of: the rows, the solve, the walls'
   * active set (a wall particle pulls on no fluid: one whose pressure
   * comes out negative is held at p = 0, and released when the fluid's
   * extrapolation would push on it again; docs/isph.md, "walls"). The
   * first round starts from last step's set and pressure. */
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads(c))
  for (int i = nb; i < n; i++)
    c->divu[i] = !c->fixed[i] ? wl_isph_div_ustar(dim, k, g, &v, i) - rate * c->derr[i]
                              : 0.0;
  for (int i = 0; i < nb; i++) c->fixed[i] = c->dry[i];
  /* the lagged gradient of the consistent Laplacian (wl_isph_ppe_row) */
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads(c))
  for (int i = 0; i < n; i++) {
    double *gp = &c->gprev[3 * (size_t)i];
    gp[0] = gp[1] = gp[2] = 0;
    if (i >= nb && !c->fixed[i]) wl_isph_grad_p(dim, k, g, &v, c->press, &c->minv[6 * (size_t)i], i, gp);
    /* at most LAG_CAP rho0 |g|: the term is exact for a hydrostatic field
     * (|grad p| = rho0 |g|), and last step's impact pressures fed back
     * through it unbounded made the dam break unstable (docs/isph.md) */
    const double gm = sqrt(gp[0] * gp[0] + gp[1] * gp[1] + gp[2] * gp[2]), cap = LAG_CAP * rho0 * c->cfg.prm.g;
    if (gm > cap)
      for (int a = 0; a < 3; a++) gp[a] *= cap / gm;
  }
  double res = 0;
  int it = 0;
  for (int round = 0; round < ACTIVE_SET_ROUNDS; round++) {
    const enum wl_status st = assemble(c, &v, in, dt, round == 0, err);
    if (st != WL_OK) return st;
    if (in && c->o.dump_path && in->step == c->o.dump_step && round == 0) dump(c, n);
    const double ts = now_s();
    int its = c->o.solver == WL_ISPH_SOLVER_GSL_GMRES
                  ? gsl_gmres(c, n, c->rhs, c->press, c->o.tol, c->o.max_iter, &res)
                  : bicgstab(c, n, c->rhs, c->press, c->o.tol, c->o.max_iter, &res);
    /* BiCGSTAB stops at a breakdown (rho or omega 0) short of the
     * tolerance: restart it from where it stopped, a new shadow residual */
    for (int rs = 0; rs < BICGSTAB_RESTARTS && c->o.solver != WL_ISPH_SOLVER_GSL_GMRES &&
                     res > c->o.tol && its < c->o.max_iter; rs++)
      its += bicgstab(c, n, c->rhs, c->press, c->o.tol, c->o.max_iter - its, &res);
    c->stats.t_solve += now_s() - ts;
    it += its;
    if (!(res <= 1e3 * c->o.tol))
      return wl_error_set(err, WL_EUNSTABLE, "isph: the pressure equation did not converge: "
                          "relative residual %.3g after %d iterations (tolerance %.3g)", res, its,
                          c->o.tol);
    int changed = 0;
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads(c)) reduction(+ : changed)
    for (int i = 0; i < nb; i++) {
      if (!c->fixed[i] && c->press[i] < 0) {
        c->fixed[i] = 1;
        c->press[i] = 0;
        changed++;
      } else if (c->fixed[i]) {
        double ga[3];
        wall_ga(c, in, i, ga);
        if (wl_isph_wall_value(dim, k, g, &v, c->press, dt, ga, i) > 0) {
          c->fixed[i] = 0;
          changed++;
        }
      }
    }
    if (!changed) break;
  }
  c->stats.iterations = it;
  c->stats.residual = res;
  c->stats.iterations_sum += it;
  c->stats.solves++;
  /* no tension: the fluid's pressure is held at p >= 0 (the walls' active
   * set already holds theirs; what is left of a wall's negative value after
   * the last round goes too). docs/isph.md, "free surface" */
  for (int i = 0; i < n; i++) c->press[i] = c->press[i] > 0 ? c->press[i] : 0.0;
  /* 4. correction (velocities from the step-start positions), then move */
  double v2max = 0, f2max = 0;
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads(c)) reduction(max : v2max, f2max)
  for (int i = nb; i < n; i++) {
    if (p->body[i] == WL_SPH_BODY_EXCLUDED) continue;
    double gp[3];
    wl_isph_grad_p(dim, k, g, &v, c->press, &c->minv[6 * (size_t)i], i, gp);
    double v2 = 0;
    for (int a = 0; a < dim; a++) {
      const double u = c->ustar[a][i] - dt / rho0 * gp[a == az ? 2 : a];
      /* at init (in == NULL) nothing moves: the state keeps its velocity */
      if (in) p->vel_h[a][i] = (wl_real)u;
      v2 += in ? u * u : (double)p->vel[a][i] * (double)p->vel[a][i];
    }
    v2max = v2 > v2max ? v2 : v2max;
    f2max = c->fmax2[i] > f2max ? c->fmax2[i] : f2max;
  }
#pragma omp parallel for schedule(static) num_threads(threads(c))
  for (int i = 0; i < n; i++) {
    const double pr = c->press[i];
    p->press[i] = (wl_real)pr;
    p->rho[i] = wl_sph_eos_rho_of_p_fast(k, (wl_real)pr);
    if (!in) continue;
    if (i < nb) {
      if (p->kind[i] == WL_KIND_MOVING)
        for (int a = 0; a < dim; a++) {
          p->vel[a][i] = (wl_real)in->body_vel[p->body[i]][a];
          p->pos[a][i] += dt * in->body_vel[p->body[i]][a];
        }
      continue;
    }
    if (p->body[i] == WL_SPH_BODY_EXCLUDED) continue;
    double u2 = 0;
    for (int a = 0; a < dim; a++) u2 += (double)p->vel_h[a][i] * (double)p->vel_h[a][i];
    const double *gcv = &c->gradc[4 * (size_t)i];
    const double sh = -c->shift_a * k->h_d * sqrt(u2) * dt * gcv[3], cap = 0.1 * k->dp;
    for (int a = 0; a < dim; a++) {
      p->vel[a][i] = p->vel_h[a][i];
      double d = sh * gcv[a == az ? 2 : a];
      d = d > cap ? cap : d < -cap ? -cap : d;
      p->pos[a][i] += dt * (double)p->vel[a][i] + d;
    }
  }
  memset(out, 0, sizeof *out);
  guard(c, in != NULL, out);
  next_dt(c, v2max, f2max, out);
  c->stats.t_total += now_s() - t0;
  return WL_OK;
}

/* ---- the backend operations ---------------------------------------------- */

static void isph_free(void *ctx) {
  struct isph *c = ctx;
  if (!c) return;
  wl_particles_clear(&c->p);
  wl_particles_clear(&c->alt);
  free(c->begin);
  free(c->cursor);
  free(c->key_tmp);
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) free(c->ustar[a]);
  free(c->minv);
  free(c->pfix);
  free(c->press);
  free(c->divu);
  free(c->rhs);
  free(c->fmax2);
  free(c->derr);
  free(c->fixed);
  free(c->dry);
  free(c->gprev);
  free(c->wall_n);
  free(c->gradc);
  free(c->row_len);
  free(c->slot_col);
  free(c->rowptr);
  free(c->col);
  free(c->slot_val);
  free(c->val);
  for (int a = 0; a < 6; a++) free(c->kv[a]);
  free(c->chunk);
  if (c->A) gsl_spmatrix_free(c->A);
  if (c->gmres) gsl_splinalg_itersolve_free(c->gmres);
  free(c);
}

static enum wl_status isph_step(void *ctx, const struct wl_sph_step_in *in,
                                struct wl_sph_step_out *out, struct wl_error *err) {
  return project(ctx, in, in->dt, out, err);
}

/* backend.h wall_load: the cell lists of the current state, every
 * particle's pressure from its stored density (the ISPH pressure, see the
 * top of this file), then each fluid particle's share (sph/isph.h
 * wl_isph_wall_load) into divu and rhs, which hold nothing between steps,
 * summed in index order. */
static enum wl_status isph_wall_load(void *ctx, int body, double z_ref, double *force,
                                     double *moment, struct wl_error *err) {
  struct isph *c = ctx;
  struct wl_particles *p = &c->p;
  const struct wl_sph_const *k = &c->k;
  const int n = p->n, nb = p->n_bound, dim = p->dim;
  (void)err;
  rebuild(c);
  const struct wl_isph_view v = view(c);
  double *fx = c->divu, *my = c->rhs;
#pragma omp parallel num_threads(threads(c))
  {
#pragma omp for schedule(static)
    for (int i = 0; i < n; i++) c->press[i] = (double)wl_sph_eos_p(k, p->rho[i]);
#pragma omp for schedule(dynamic, 256)
    for (int i = nb; i < n; i++)
      wl_isph_wall_load(dim, k, &c->grid, &v, c->press, p->body, body, z_ref, i, &fx[i], &my[i]);
  }
  double sx = 0.0, sm = 0.0;
  for (int i = nb; i < n; i++) {
    sx += fx[i];
    sm += my[i];
  }
  *force = sx;
  *moment = sm;
  return WL_OK;
}

static void isph_describe(void *ctx, char *buf, size_t size) {
  const struct isph *c = ctx;
  snprintf(buf, size, "isph (OpenMP, %d threads, projection, PPE by %s, tol %.1e, %d cells of %.4g m)",
           threads(c), c->o.solver == WL_ISPH_SOLVER_GSL_GMRES ? "GSL GMRES" : "BiCGSTAB-Jacobi",
           c->o.tol, c->grid.n_cells, c->grid.cell);
}

static enum wl_status isph_download(void *ctx, struct wl_particles *host, struct wl_error *err) {
  struct isph *c = ctx;
  return wl_particles_copy_state(host, &c->p, err);
}

void wl_backend_isph_stats(const void *ctx, struct wl_isph_stats *out) {
  const struct isph *c = ctx;
  *out = c->stats;
}

/* An array of count elements of size bytes, labelled for the message. */
static enum wl_status grab(void **ptr, size_t count, size_t size, const char *label,
                           struct wl_error *err) {
  *ptr = calloc(count > 0 ? count : 1, size);
  if (!*ptr)
    return wl_error_set(err, WL_ENOMEM, "isph backend: cannot allocate %s (%zu x %zu B)", label,
                        count, size);
  return WL_OK;
}

static enum wl_status isph_init(void **ctx, const struct wl_sph_config *cfg,
                                const struct wl_sph_const *k, const struct wl_particles *host,
                                struct wl_sph_step_out *out, struct wl_error *err) {
  *ctx = NULL;
  const int dim = cfg->prm.dim;
  enum wl_status st = wl_sph_check_particles("isph", cfg, host, err);
  if (st) return st;
  if (dim != 2)
    return wl_error_set(err, WL_EUNSUPPORTED, "isph backend: 2D only for now (issue 22)");
  if (cfg->prm.mirror_lo || cfg->prm.mirror_hi)
    return wl_error_set(err, WL_EUNSUPPORTED, "isph backend: no mirror planes");
  struct isph *c = calloc(1, sizeof *c);
  if (!c) return wl_error_set(err, WL_ENOMEM, "isph backend: out of memory");
  c->cfg = *cfg;
  c->k = *k;
  c->o = cfg->isph;
  if (!(c->o.tol > 0)) c->o.tol = 1e-9;
  if (c->o.max_iter <= 0) c->o.max_iter = 2000;
  if (c->o.surface_offset == 0) c->o.surface_offset = 1;
  if (c->o.density_tau == 0) c->o.density_tau = 4.0 * sqrt(k->h_d / cfg->prm.g);
  c->wsum_ref = wl_isph_lattice_sum(dim, k);
  c->shift_a = c->o.shift_coef > 0 ? c->o.shift_coef : 0.0;
  /* 10 % of sqrt(g h): above the drift of a settling tank (docs/isph.md,
   * "walls"), below the speed of any flow that runs at a wall */
  c->u_wet = c->o.wet_speed > 0 ? c->o.wet_speed
            : c->o.wet_speed < 0 ? INFINITY : 0.1 * sqrt(cfg->prm.g * k->h_d);
  c->tfs = c->o.surface_tfs > 0 ? c->o.surface_tfs : dim == 2 ? 1.5 : 2.4;
  c->n_threads = cfg->n_threads > 0 ? cfg->n_threads : 1;
  c->row_max = dim == 2 ? WL_ISPH_ROW_MAX_2D : WL_ISPH_ROW_MAX_3D;
  st = wl_sph_grid_make(cfg, k, &c->grid, err);
  const size_t n = (size_t)host->n, nc = (size_t)c->grid.n_cells, rm = (size_t)c->row_max;
  if (st == WL_OK) st = wl_particles_alloc(&c->p, dim, host->n, 1, err);
  if (st == WL_OK) st = wl_particles_alloc(&c->alt, dim, host->n, 0, err);
  if (st == WL_OK) st = wl_particles_copy_state(&c->p, host, err);
  if (st == WL_OK) st = grab((void **)&c->begin, 2 * nc + 1, sizeof(int), "the cell index", err);
  if (st == WL_OK) st = grab((void **)&c->cursor, 2 * nc, sizeof(int), "the cell cursor", err);
  if (st == WL_OK) st = grab((void **)&c->key_tmp, n, sizeof(unsigned), "the sort keys", err);
  for (int a = 0; a < dim && st == WL_OK; a++)
    st = grab((void **)&c->ustar[a], n, sizeof(double), "u*", err);
  if (st == WL_OK) st = grab((void **)&c->minv, 6 * n, sizeof(double), "M^-1", err);
  if (st == WL_OK) st = grab((void **)&c->pfix, n, sizeof(double), "surface pressures", err);
  if (st == WL_OK) st = grab((void **)&c->press, n, sizeof(double), "pressures", err);
  if (st == WL_OK) st = grab((void **)&c->divu, n, sizeof(double), "div u*", err);
  if (st == WL_OK) st = grab((void **)&c->rhs, n, sizeof(double), "the PPE right-hand side", err);
  if (st == WL_OK) st = grab((void **)&c->fmax2, n, sizeof(double), "|f|^2", err);
  if (st == WL_OK) st = grab((void **)&c->derr, n, sizeof(double), "compressions", err);
  if (st == WL_OK) st = grab((void **)&c->fixed, n, 1, "surface flags", err);
  if (st == WL_OK) st = grab((void **)&c->dry, n, 1, "dry walls", err);
  if (st == WL_OK) st = grab((void **)&c->gprev, 3 * n, sizeof(double), "lagged grad p", err);
  if (st == WL_OK) st = grab((void **)&c->gradc, 4 * n, sizeof(double), "grad C", err);
  if (st == WL_OK)
    st = grab((void **)&c->wall_n, 3 * (size_t)host->n_bound, sizeof(double), "wall normals", err);
  if (st == WL_OK) st = grab((void **)&c->row_len, n, sizeof(int), "PPE row lengths", err);
  if (st == WL_OK) st = grab((void **)&c->slot_col, n * rm, sizeof(int), "PPE row slots", err);
  if (st == WL_OK) st = grab((void **)&c->slot_val, n * rm, sizeof(double), "PPE row slots", err);
  if (st == WL_OK) st = grab((void **)&c->rowptr, n + 1, sizeof(int), "PPE row pointers", err);
  if (st == WL_OK) st = grab((void **)&c->col, n * rm, sizeof(int), "PPE columns", err);
  if (st == WL_OK) st = grab((void **)&c->val, n * rm, sizeof(double), "PPE values", err);
  for (int a = 0; a < 6 && st == WL_OK; a++)
    st = grab((void **)&c->kv[a], n, sizeof(double), "solver vectors", err);
  if (st == WL_OK)
    st = grab((void **)&c->chunk, n / DOT_CHUNK + 1, sizeof(double), "dot chunks", err);
  if (st == WL_OK && c->o.solver == WL_ISPH_SOLVER_GSL_GMRES) {
    c->A = gsl_spmatrix_alloc_nzmax(n, n, n * rm, GSL_SPMATRIX_CSR);
    c->gmres = gsl_splinalg_itersolve_alloc(gsl_splinalg_itersolve_gmres, n, GMRES_M);
    if (!c->A || !c->gmres)
      st = wl_error_set(err, WL_ENOMEM, "isph backend: cannot allocate GSL's GMRES for %zu "
                        "unknowns", n);
  }
  if (st != WL_OK) {
    isph_free(c);
    return st;
  }
  /* the initial state's pressure (warm start of the first step) and dt:
   * a projection of length dt_probe = sqrt(h/g) moves nothing; the state
   * keeps its velocities */
  st = project(c, NULL, cfg->prm.cfl * sqrt(k->h_d / cfg->prm.g), out, err);
  if (st != WL_OK) {
    isph_free(c);
    return st;
  }
  c->stats.iterations_sum = 0;
  c->stats.solves = 0;
  c->stats.t_solve = c->stats.t_total = 0;
  *ctx = c;
  return WL_OK;
}

const struct wl_backend_ops wl_backend_isph_ops = {
    .name = "isph",
    .init = isph_init,
    .step = isph_step,
    .download = isph_download,
    .describe = isph_describe,
    .free = isph_free,
    .wall_load = isph_wall_load,
};
