/* vres.c: variable resolution by coupled subdomains (vres.h). Every level
 * is a wl_sph_sim of its own; between steps the driver edits a zone of each
 * on the host (wl_sph_sim_edit_zone / _commit_zone: the particles within
 * the coupling's reach of the interface, and as many parked ones as the
 * flux points can revive in a step): classification, the buffers' fit from
 * the other level, their shifting, removal and creation. Particles outside
 * the zone are the levels' own fluid deep in their ranges (or parked), which
 * the coupling neither reads nor changes, so the zone gives the bits that
 * the whole state would. */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/sph/kernel.h"
#include "wallload/sph/vres_fit.h"
#include "wallload/vres.h"

/* The donors of one level on a host cell grid of side 2h. */
struct donor_grid {
  double x0, z0, cell;
  int nx, nz;
  int *start; /* nx nz + 1 */
  int *idx;   /* particle indices, by cell */
  int n, cap_cells, cap_idx;
};

/* A buffer particle's fit from the other level (fit_at). */
struct fit_out {
  double val[3], wet;
  int r;
};

struct level {
  struct wl_sph_sim *sim;
  int threads;             /* the level's CPU threads, for the coupling's per-particle loops */
  struct fit_out *fits;    /* per particle, refill's first pass */
  double *across;          /* per particle, shift_buffers' displacement across the interface */
  int fits_cap;            /* of fits and across */
  const struct wl_sph_const *k;
  double lo, hi, w, dp, h, mass;
  double mass_lo, mass_hi; /* the part of its range its own mass counts (vres.h overlap) */
  double zone_lo, zone_hi; /* the x its grid covers: where either level's coupling asks (below) */
  double park_lo[2], park_hi[2];
  int park_nx, park_nz;
  long park_next;
  int n_points;
  double *pt_x, *pt_z, *pt_n, *acc; /* flux points: position, inward normal (+-1 in x), account */
  struct donor_grid grid;
  struct wl_vres_counts cnt;
};

struct wl_vres {
  int n;
  double t, z_bed, z_top, shift;
  int shift_across;
  struct level lv[WL_VRES_LEVELS_MAX];
};

static void grid_free(struct donor_grid *g) {
  free(g->start);
  free(g->idx);
  memset(g, 0, sizeof *g);
}

void wl_vres_free(struct wl_vres *v) {
  if (!v) return;
  for (int l = 0; l < v->n; l++) {
    struct level *L = &v->lv[l];
    wl_sph_sim_free(L->sim);
    free(L->pt_x);
    free(L->pt_z);
    free(L->pt_n);
    free(L->acc);
    free(L->fits);
    free(L->across);
    grid_free(&L->grid);
  }
  free(v);
}

static int owns(const struct level *L, double x) { return x >= L->lo && x <= L->hi; }

static int in_band(const struct level *L, double x) {
  return (x < L->lo && x >= L->lo - L->w) || (x > L->hi && x <= L->hi + L->w);
}

/* Park particle i of level L at rest in its next slot (vres.h). */
static void park(struct level *L, struct wl_particles *p, int i) {
  const long s = L->park_next++ % ((long)L->park_nx * L->park_nz);
  const double sx = (L->park_hi[0] - L->park_lo[0]) / L->park_nx;
  const double sz = (L->park_hi[1] - L->park_lo[1]) / L->park_nz;
  p->pos[0][i] = L->park_lo[0] + ((double)(s % L->park_nx) + 0.5) * sx;
  p->pos[1][i] = L->park_lo[1] + ((double)(s / L->park_nx) + 0.5) * sz;
  p->vel[0][i] = p->vel[1][i] = 0;
  p->rho[i] = L->k->rho0;
  p->body[i] = WL_SPH_BODY_EXCLUDED;
}

/* Whether particle i of level L is a donor: its fluid in its own range;
 * and its boundary and buffer particles, which count towards a point's
 * wetness only (the water beside a wall, and across the level's own
 * interface). */
static int donor(const struct level *L, const struct wl_particles *p, int i) {
  const double x = p->pos[0][i];
  return x >= L->zone_lo && x <= L->zone_hi &&
         (p->kind[i] != WL_KIND_FLUID || p->body[i] == WL_SPH_BODY_BUFFER ||
          (p->body[i] == 0 && owns(L, x)));
}

static int fit_donor(const struct level *L, const struct wl_particles *p, int j) {
  return p->kind[j] == WL_KIND_FLUID && p->body[j] == 0 && owns(L, p->pos[0][j]);
}

/* The donor grid of level L. */
static enum wl_status grid_build(struct level *L, const struct wl_particles *p, struct wl_error *err) {
  struct donor_grid *g = &L->grid;
  double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
  int n = 0;
  for (int i = 0; i < p->n; i++) {
    if (!donor(L, p, i)) continue;
    const double x = p->pos[0][i], z = p->pos[1][i]; /* comparisons, not fmin: no libm call */
    x0 = x < x0 ? x : x0, x1 = x > x1 ? x : x1;
    z0 = z < z0 ? z : z0, z1 = z > z1 ? z : z1;
    n++;
  }
  g->n = n;
  if (n == 0) return WL_OK;
  g->cell = 2.0 * L->h;
  g->x0 = x0, g->z0 = z0;
  g->nx = (int)((x1 - x0) / g->cell) + 1;
  g->nz = (int)((z1 - z0) / g->cell) + 1;
  const int nc = g->nx * g->nz;
  if (nc + 1 > g->cap_cells) {
    free(g->start);
    g->start = malloc(sizeof(int) * (size_t)(nc + 1));
    g->cap_cells = g->start ? nc + 1 : 0;
  }
  if (n > g->cap_idx) {
    free(g->idx);
    g->idx = malloc(sizeof(int) * (size_t)n);
    g->cap_idx = g->idx ? n : 0;
  }
  if (!g->start || !g->idx)
    return wl_error_set(err, WL_ENOMEM, "vres: out of memory for a donor grid of %d cells", nc);
  memset(g->start, 0, sizeof(int) * (size_t)(nc + 1));
  for (int i = 0; i < p->n; i++) {
    if (!donor(L, p, i)) continue;
    const int cx = (int)((p->pos[0][i] - x0) / g->cell), cz = (int)((p->pos[1][i] - z0) / g->cell);
    g->start[cz * g->nx + cx + 1]++;
  }
  for (int c = 0; c < nc; c++) g->start[c + 1] += g->start[c];
  for (int i = 0; i < p->n; i++) { /* fill, then shift back */
    if (!donor(L, p, i)) continue;
    const int cx = (int)((p->pos[0][i] - x0) / g->cell), cz = (int)((p->pos[1][i] - z0) / g->cell);
    g->idx[g->start[cz * g->nx + cx]++] = i;
  }
  for (int c = nc; c > 0; c--) g->start[c] = g->start[c - 1];
  g->start[0] = 0;
  return WL_OK;
}

/* A zone of at most this many fluid particles is coupled on one thread:
 * waking a team of sleeping threads costs more than these loops
 * (docs/history/2026-11-28-vres-gpu.md). */
#define WL_VRES_SERIAL_MAX 20000

/* Most particles of a level within 2h of a point (a lattice holds about 40;
 * the rest is room for crowding). */
#define WL_VRES_NEIGHBOURS_MAX 512

/* The particles of level L's grid within 2h of (x, z): indices into idx,
 * squared distances into r2; their number (at most WL_VRES_NEIGHBOURS_MAX,
 * the nearest cells first). */
static int neighbours(const struct level *L, const struct wl_particles *p, double x, double z,
                      int *idx, double *r2) {
  const struct donor_grid *g = &L->grid;
  if (g->n == 0) return 0;
  const int cx = (int)floor((x - g->x0) / g->cell), cz = (int)floor((z - g->z0) / g->cell);
  const double s2 = 4.0 * L->h * L->h;
  int n = 0;
  for (int jz = cz - 1; jz <= cz + 1; jz++) {
    if (jz < 0 || jz >= g->nz) continue;
    for (int jx = cx - 1; jx <= cx + 1; jx++) {
      if (jx < 0 || jx >= g->nx) continue;
      const int c = jz * g->nx + jx;
      for (int q = g->start[c]; q < g->start[c + 1] && n < WL_VRES_NEIGHBOURS_MAX; q++) {
        const int j = g->idx[q];
        const double dx = p->pos[0][j] - x, dz = p->pos[1][j] - z, d2 = dx * dx + dz * dz;
        if (d2 >= s2) continue;
        idx[n] = j;
        r2[n++] = d2;
      }
    }
  }
  return n;
}

/* The fit at (x, z) from donor level D (its host particles p); *wet: the
 * Shepard sum of its fluid, buffer and wall particles there (vres.h). */
static int fit_at(const struct level *D, const struct wl_particles *p, double x, double z,
                  double *out, double *wet) {
  int idx[WL_VRES_NEIGHBOURS_MAX];
  double r2[WL_VRES_NEIGHBOURS_MAX];
  const int n = neighbours(D, p, x, z, idx, r2);
  struct wl_vres_fit f;
  wl_vres_fit_init(&f, 2, D->h);
  double sum = 0;
  for (int q = 0; q < n; q++) {
    const int j = idx[q];
    const double w = (double)wl_sph_kernel_w(D->k, (wl_real)r2[q]);
    const double vol = D->mass / (double)p->rho[j];
    sum += vol * w;
    if (!fit_donor(D, p, j)) continue;
    const double d[2] = {p->pos[0][j] - x, p->pos[1][j] - z};
    const double val[3] = {p->rho[j], p->vel[0][j], p->vel[1][j]};
    wl_vres_fit_add(&f, d, w, (double)wl_sph_kernel_f(D->k, (wl_real)r2[q]), vol, val);
  }
  *wet = sum;
  return wl_vres_fit_solve(&f, out);
}

/* Particle shifting of level L's buffer particles (sph/shift.h's law,
 * delta r = -A h |v| dt grad C, each component capped at 0.1 dp), from the
 * level's own particles (its grid: fluid, buffer, walls), along the
 * interface: its normal component removed, as DualSPHysics'
 * BufferShiftingCpu does, so shifting moves no particle into or out of a
 * band. across: the normal component too, less its mean over the band
 * (spacing without a drift of the band's water through it, whose inflow is
 * the donor's alone), a particle that it would take out of its band keeping
 * its x. A band's particles move with the donor's velocity and nothing else
 * spaces them across; the symmetric pressure term pushes the fluid beside a
 * band away from where they crowd, with the whole hydrostatic pressure
 * behind it (docs/history/2026-11-29-vres-band-spacing.md: spaced across,
 * the pile-up went and the transmitted wave read about 1.5 % of H lower).
 * Not where the concentration is below 0.9 (a free surface). Serial: the
 * band means sum in particle order, the same bits on any thread count. */
static void shift_buffers(struct level *L, struct wl_particles *p, double dt, double A,
                          int across) {
  const double cap = 0.1 * L->dp;
  int idx[WL_VRES_NEIGHBOURS_MAX];
  double r2[WL_VRES_NEIGHBOURS_MAX];
  double sum[2] = {0, 0}; /* the across components' sums, by band: seaward of lo, beyond hi */
  long cnt[2] = {0, 0};
  for (int i = p->n_bound; i < p->n; i++) {
    if (across) L->across[i] = 0;
    if (p->body[i] != WL_SPH_BODY_BUFFER) continue;
    const double x = p->pos[0][i], z = p->pos[1][i];
    const int n = neighbours(L, p, x, z, idx, r2);
    double dcdx = 0, dcdz = 0, conc = 0;
    for (int q = 0; q < n; q++) {
      const int j = idx[q];
      const double vol = L->mass / (double)p->rho[j];
      conc += vol * (double)wl_sph_kernel_w(L->k, (wl_real)r2[q]);
      const double f = vol * (double)wl_sph_kernel_f(L->k, (wl_real)r2[q]);
      dcdx += f * (x - p->pos[0][j]); /* 0: j = i */
      dcdz += f * (z - p->pos[1][j]);
    }
    if (conc < 0.9) continue;
    const double s = -A * L->h * hypot((double)p->vel[0][i], (double)p->vel[1][i]) * dt;
    const double dz = s * dcdz, dx = s * dcdx;
    p->pos[1][i] += dz > cap ? cap : dz < -cap ? -cap : dz;
    if (!across) continue;
    const int e = x < L->lo ? 0 : 1;
    L->across[i] = dx > cap ? cap : dx < -cap ? -cap : dx;
    sum[e] += L->across[i];
    cnt[e]++;
  }
  if (!across || cnt[0] + cnt[1] == 0) return;
  for (int i = p->n_bound; i < p->n; i++) {
    if (p->body[i] != WL_SPH_BODY_BUFFER || L->across[i] == 0) continue;
    const double x = p->pos[0][i];
    const int e = x < L->lo ? 0 : 1;
    const double xn = x + L->across[i] - sum[e] / (double)cnt[e];
    if (in_band(L, xn)) p->pos[0][i] = xn;
  }
}

/* A parked particle of level L (index), or -1. */
static int take_parked(const struct wl_particles *p, int *cursor) {
  for (; *cursor < p->n; (*cursor)++)
    if (p->kind[*cursor] == WL_KIND_FLUID && p->body[*cursor] == WL_SPH_BODY_EXCLUDED) return (*cursor)++;
  return -1;
}

/* Level L's fluid by position (vres.h): its range, its bands, gone. The
 * classes side by side; the few that leave are parked after, in particle
 * order (parking counts its slots): the same bits on any thread count. */
static void classify(struct level *L, struct wl_particles *p) {
  const int n = p->n, n_bound = p->n_bound;
  long gone = 0;
#pragma omp parallel for reduction(+ : gone) num_threads(L->threads) \
    if (n - n_bound > WL_VRES_SERIAL_MAX)
  for (int i = n_bound; i < n; i++) {
    if (p->body[i] == WL_SPH_BODY_EXCLUDED) continue;
    const double x = p->pos[0][i];
    if (owns(L, x)) p->body[i] = 0;
    else if (in_band(L, x)) p->body[i] = WL_SPH_BODY_BUFFER;
    else gone++;
  }
  for (int i = n_bound; i < n && gone > 0; i++) {
    if (p->body[i] == WL_SPH_BODY_EXCLUDED) continue;
    const double x = p->pos[0][i];
    if (!owns(L, x) && !in_band(L, x)) {
      park(L, p, i);
      L->cnt.removed++;
      gone--;
    }
  }
}

/* Room for n particles' fits and displacements across in L. */
static enum wl_status fits_reserve(struct level *L, int n, struct wl_error *err) {
  if (n <= L->fits_cap) return WL_OK;
  free(L->fits);
  free(L->across);
  L->fits = malloc(sizeof *L->fits * (size_t)n);
  L->across = malloc(sizeof *L->across * (size_t)n);
  L->fits_cap = L->fits && L->across ? n : 0;
  if (!L->fits_cap) return wl_error_set(err, WL_ENOMEM, "vres: out of memory for %d fits", n);
  return WL_OK;
}

/* Level L's buffer particles from donor level D (vres.h), then the flux
 * points' creation. */
static enum wl_status refill(struct level *L, struct wl_particles *p, const struct level *D,
                             const struct wl_particles *pd, double dt, struct wl_error *err) {
  /* the fits first, side by side (each reads the donor level only), then
   * their use in particle order (parking counts its slots): the same bits
   * on any number of threads */
  enum wl_status st = fits_reserve(L, p->n, err);
  if (st) return st;
  struct fit_out *fits = L->fits;
  const int n = p->n, n_bound = p->n_bound;
#pragma omp parallel for schedule(dynamic, 64) num_threads(L->threads) \
    if (n - n_bound > WL_VRES_SERIAL_MAX)
  for (int i = n_bound; i < n; i++)
    if (p->body[i] == WL_SPH_BODY_BUFFER)
      fits[i].r = fit_at(D, pd, p->pos[0][i], p->pos[1][i], fits[i].val, &fits[i].wet);
  for (int i = n_bound; i < n; i++) {
    if (p->body[i] != WL_SPH_BODY_BUFFER) continue;
    const struct fit_out *f = &fits[i];
    if (f->r < 0 || f->wet < WL_VRES_DRY_MAX) {
      park(L, p, i);
      L->cnt.removed++;
      continue;
    }
    p->rho[i] = (wl_real)f->val[0];
    p->vel[0][i] = (wl_real)f->val[1];
    p->vel[1][i] = (wl_real)f->val[2];
    if (f->r == 1) L->cnt.fitted++;
    else L->cnt.shepard++;
  }
  double val[3], wet;
  int cursor = p->n_bound;
  int near[WL_VRES_NEIGHBOURS_MAX]; /* the level's particles near a new one's place */
  double near_r2[WL_VRES_NEIGHBOURS_MAX];
  for (int q = 0; q < L->n_points; q++) {
    const int r = fit_at(D, pd, L->pt_x[q], L->pt_z[q], val, &wet);
    if (r < 0 || wet < WL_VRES_WET_MIN) {
      L->acc[q] = 0;
      continue;
    }
    const double flux = val[0] * val[1] * L->pt_n[q] * L->dp * dt;
    L->acc[q] = fmax(0.0, L->acc[q] + flux);
    if (flux > 0) L->cnt.flux_in += flux;
    if (L->acc[q] < L->mass) continue;
    const double xn = L->pt_x[q] + 0.5 * L->dp * L->pt_n[q], zn = L->pt_z[q];
    int crowded = 0; /* a particle still there: wait for it to move on */
    const int m = neighbours(L, p, xn, zn, near, near_r2);
    for (int k = 0; k < m && !crowded; k++)
      crowded = p->kind[near[k]] == WL_KIND_FLUID && near_r2[k] < 0.25 * L->dp * L->dp;
    if (crowded) continue;
    const int i = take_parked(p, &cursor);
    if (i < 0)
      return wl_error_set(err, WL_ENOMEM, "vres: level of dp %g m has no parked particle left to "
                          "create at (%g, %g) m (raise its spare)", L->dp, xn, zn);
    p->pos[0][i] = xn;
    p->pos[1][i] = zn;
    p->rho[i] = (wl_real)val[0];
    p->vel[0][i] = (wl_real)val[1];
    p->vel[1][i] = (wl_real)val[2];
    p->body[i] = WL_SPH_BODY_BUFFER;
    L->acc[q] -= L->mass;
    L->cnt.created++;
  }
  return WL_OK;
}

/* The coupling after a step of dt (0: the initial state). */
static enum wl_status couple(struct wl_vres *v, double dt, struct wl_error *err) {
  struct wl_particles *p[WL_VRES_LEVELS_MAX];
  for (int l = 0; l < v->n; l++) {
    /* a particle moves less than a zone's margin (2h + dp beyond the
     * bands) in a step, so none leaves the class its place gives unseen;
     * each flux point revives at most one parked particle a step */
    const struct level *L = &v->lv[l];
    p[l] = wl_sph_sim_edit_zone(L->sim, L->zone_lo, L->zone_hi, L->n_points, err);
    if (!p[l]) return err->status;
  }
  for (int l = 0; l < v->n; l++) classify(&v->lv[l], p[l]);
  for (int l = 0; l < v->n; l++) {
    const enum wl_status st = grid_build(&v->lv[l], p[l], err);
    if (st) return st;
  }
  if (dt > 0 && v->shift > 0)
    for (int l = 0; l < v->n; l++) {
      const enum wl_status st = v->shift_across ? fits_reserve(&v->lv[l], p[l]->n, err) : WL_OK;
      if (st) return st;
      shift_buffers(&v->lv[l], p[l], dt, v->shift, v->shift_across);
    }
  for (int l = 0; l < v->n; l++) {
    const enum wl_status st = refill(&v->lv[l], p[l], &v->lv[1 - l], p[1 - l], dt, err);
    if (st) return st;
  }
  for (int l = 0; l < v->n; l++) {
    const enum wl_status st = wl_sph_sim_commit_zone(v->lv[l].sim, err);
    if (st) return st;
  }
  return WL_OK;
}

/* The initial particles of a level with `spare` parked ones appended. */
static enum wl_status with_spares(struct level *L, const struct wl_particles *in, int spare,
                                  struct wl_particles *out, struct wl_error *err) {
  enum wl_status st = wl_particles_alloc(out, in->dim, in->n + spare, 0, err);
  if (st) return st;
  st = wl_particles_copy_state(out, in, err);
  if (st) return st;
  for (int s = 0; s < spare; s++) {
    const int i = in->n + s;
    out->kind[i] = WL_KIND_FLUID;
    out->id[i] = (unsigned int)i;
    park(L, out, i);
  }
  out->n = in->n + spare;
  return WL_OK;
}

/* A band's width: whole rows of its level, at least buffer_h of its h. */
static double band_width(const struct wl_vres_opts *o, double h, double dp) {
  const double bh = o && o->buffer_h > 0 ? o->buffer_h : 2.0;
  return ceil(bh * h / dp - 1e-9) * dp;
}

static enum wl_status level_init(struct wl_vres *v, struct level *L, const struct wl_backend_ops *ops,
                                 const struct wl_vres_level_spec *s, const struct wl_vres_opts *o,
                                 struct wl_error *err) {
  const struct wl_sph_params *prm = &s->cfg->prm;
  if (prm->dim != 2)
    return wl_error_set(err, WL_EUNSUPPORTED, "vres: %dD; this stage couples 2D levels", prm->dim);
  if (!ops->zone_download || !ops->zone_upload)
    return wl_error_set(err, WL_EUNSUPPORTED, "vres: the %s backend cannot take edited particles "
                        "back (backend.h zone_upload)", ops->name);
  if (!(s->own_lo < s->own_hi))
    return wl_error_set(err, WL_EINPUT, "vres: a level owns x in [%g, %g] m; need lo < hi",
                        s->own_lo, s->own_hi);
  if (!(s->park_hi[0] > s->park_lo[0] && s->park_hi[1] > s->park_lo[1]))
    return wl_error_set(err, WL_EINPUT, "vres: empty parking rectangle");
  if (!(v->z_top > v->z_bed))
    return wl_error_set(err, WL_EINPUT, "vres: z_top %g m not above z_bed %g m", v->z_top, v->z_bed);
  struct wl_sph_const k;
  enum wl_status st = wl_sph_const_make(prm, &k, err);
  if (st) return st;
  L->lo = s->own_lo, L->hi = s->own_hi;
  L->dp = prm->dp, L->h = (double)k.h, L->mass = (double)k.mass;
  L->w = band_width(o, L->h, L->dp);
  L->threads = s->cfg->n_threads > 0 ? s->cfg->n_threads : omp_get_max_threads();
  memcpy(L->park_lo, s->park_lo, sizeof L->park_lo);
  memcpy(L->park_hi, s->park_hi, sizeof L->park_hi);
  const double slot = 2.2 * L->h; /* slots out of each other's reach */
  L->park_nx = (int)fmax(1.0, floor((L->park_hi[0] - L->park_lo[0]) / slot));
  L->park_nz = (int)fmax(1.0, floor((L->park_hi[1] - L->park_lo[1]) / slot));
  /* flux points: one a row on the far edge of each band */
  const int rows = (int)floor((v->z_top - v->z_bed) / L->dp + 1e-9);
  const int ends = isfinite(L->lo) + isfinite(L->hi);
  L->n_points = rows * ends;
  L->pt_x = calloc((size_t)L->n_points + 1, sizeof(double));
  L->pt_z = calloc((size_t)L->n_points + 1, sizeof(double));
  L->pt_n = calloc((size_t)L->n_points + 1, sizeof(double));
  L->acc = calloc((size_t)L->n_points + 1, sizeof(double));
  if (!L->pt_x || !L->pt_z || !L->pt_n || !L->acc)
    return wl_error_set(err, WL_ENOMEM, "vres: out of memory for %d flux points", L->n_points);
  int q = 0;
  for (int e = 0; e < 2; e++) {
    const double edge = e == 0 ? L->lo : L->hi;
    if (!isfinite(edge)) continue;
    const double n = e == 0 ? 1.0 : -1.0; /* into the level */
    for (int r = 0; r < rows; r++, q++) {
      L->pt_n[q] = n;
      L->pt_x[q] = edge - n * L->w;
      L->pt_z[q] = v->z_bed + (r + 0.5) * L->dp;
    }
  }
  L->k = &k; /* for park() below; replaced by the sim's own */
  struct wl_particles init = {0};
  st = with_spares(L, s->initial, s->spare > 0 ? s->spare : 0, &init, err);
  if (!st) st = wl_sph_sim_alloc(&L->sim, ops, s->cfg, &init, err);
  wl_particles_clear(&init);
  if (st) return st;
  L->k = wl_sph_sim_const(L->sim);
  return WL_OK;
}

void wl_vres_layout(double x_if, double dp_coarse, double dp_fine, double h_over_dp,
                    int fine_right, const struct wl_vres_opts *opts, struct wl_vres_layout *out) {
  const double dp[2] = {dp_coarse, dp_fine};
  for (int l = 0; l < 2; l++) out->band[l] = band_width(opts, h_over_dp * dp[l], dp[l]);
  const double ov = opts && opts->overlap < 0 ? 0.0 : (opts && opts->overlap > 0 ? opts->overlap : 1.0);
  out->overlap = ov * out->band[0];
  const int right = fine_right ? 1 : 0, left = 1 - right; /* the level on x > x_if, and the other */
  out->own_lo[left] = -INFINITY, out->own_hi[left] = x_if + out->overlap;
  out->own_lo[right] = x_if - out->overlap, out->own_hi[right] = INFINITY;
  out->water_lo[left] = -INFINITY, out->water_hi[left] = out->own_hi[left] + out->band[left];
  out->water_lo[right] = out->own_lo[right] - out->band[right], out->water_hi[right] = INFINITY;
}

enum wl_status wl_vres_alloc(struct wl_vres **out, const struct wl_backend_ops *ops, int n_levels,
                             const struct wl_vres_level_spec *levels,
                             const struct wl_vres_opts *opts, struct wl_error *err) {
  *out = NULL;
  if (n_levels != 2)
    return wl_error_set(err, WL_EUNSUPPORTED, "vres: %d levels; this stage couples 2", n_levels);
  struct wl_vres *v = calloc(1, sizeof *v);
  if (!v) return wl_error_set(err, WL_ENOMEM, "vres: out of memory");
  v->n = n_levels;
  v->z_bed = opts ? opts->z_bed : 0.0;
  v->z_top = opts ? opts->z_top : 0.0;
  v->shift = opts && opts->shift >= 0 ? opts->shift : 0.0;
  v->shift_across = opts && opts->shift_across;
  enum wl_status st = WL_OK;
  for (int l = 0; l < n_levels && !st; l++) {
    st = level_init(v, &v->lv[l], ops, &levels[l], opts, err);
    if (st) wl_error_prefix(err, "vres level %d: ", l);
  }
  if (!st) { /* side by side, touching or overlapping, neither range inside the other */
    const int a = levels[0].own_lo <= levels[1].own_lo ? 0 : 1, b = 1 - a;
    const struct wl_vres_level_spec *la = &levels[a], *lb = &levels[b];
    if (!(la->own_lo < lb->own_lo && la->own_hi < lb->own_hi && lb->own_lo <= la->own_hi))
      st = wl_error_set(err, WL_EINPUT, "vres: the levels' ranges [%g, %g] and [%g, %g] m must "
                        "touch or overlap, neither inside the other", la->own_lo, la->own_hi,
                        lb->own_lo, lb->own_hi);
    else if (lb->own_lo - v->lv[b].w < la->own_lo || la->own_hi + v->lv[a].w > lb->own_hi)
      st = wl_error_set(err, WL_EINPUT, "vres: a level's buffer band reaches beyond the other "
                        "level's range");
    else { /* own mass: each level counts the overlap up to its middle */
      /* each level's grid: the other level's bands and flux points (its
       * fits from this level), this level's own (shifting, crowding), and
       * the reach of the larger kernel beyond them */
      double lo = INFINITY, hi = -INFINITY, reach = 0;
      for (int l = 0; l < n_levels; l++) {
        const struct level *L = &v->lv[l];
        if (isfinite(L->lo)) lo = fmin(lo, L->lo - L->w), hi = fmax(hi, L->lo);
        if (isfinite(L->hi)) lo = fmin(lo, L->hi), hi = fmax(hi, L->hi + L->w);
        reach = fmax(reach, 2.0 * L->h + L->dp);
      }
      for (int l = 0; l < n_levels; l++)
        v->lv[l].zone_lo = lo - reach, v->lv[l].zone_hi = hi + reach;
      const double mid = 0.5 * (lb->own_lo + la->own_hi);
      v->lv[a].mass_lo = la->own_lo, v->lv[a].mass_hi = mid;
      v->lv[b].mass_lo = mid, v->lv[b].mass_hi = lb->own_hi;
    }
  }
  if (!st) st = couple(v, 0.0, err);
  if (st) {
    wl_vres_free(v);
    return st;
  }
  *out = v;
  return WL_OK;
}

enum wl_status wl_vres_step(struct wl_vres *v, double dt_max, struct wl_error *err) {
  double dt = dt_max > 0 ? dt_max : INFINITY;
  for (int l = 0; l < v->n; l++) dt = fmin(dt, wl_sph_sim_dt(v->lv[l].sim));
  for (int l = 0; l < v->n; l++) {
    const enum wl_status st = wl_sph_sim_step(v->lv[l].sim, dt, err);
    if (st) {
      wl_error_prefix(err, "vres level %d (dp %g m): ", l, v->lv[l].dp);
      return st;
    }
    v->lv[l].cnt.steps++;
  }
  v->t += dt;
  return couple(v, dt, err);
}

double wl_vres_time(const struct wl_vres *v) { return v->t; }

struct wl_sph_sim *wl_vres_level(struct wl_vres *v, int level) { return v->lv[level].sim; }

int wl_vres_owns(const struct wl_vres *v, int level, double x) { return owns(&v->lv[level], x); }

double wl_vres_own_mass(struct wl_vres *v, struct wl_error *err) {
  double m = 0;
  for (int l = 0; l < v->n; l++) {
    const struct wl_particles *p = wl_sph_sim_particles(v->lv[l].sim, err);
    if (!p) return NAN;
    long c = 0;
    const struct level *L = &v->lv[l];
    for (int i = p->n_bound; i < p->n; i++) {
      const double x = p->pos[0][i];
      c += p->body[i] == 0 && owns(L, x) && x >= L->mass_lo && x < L->mass_hi;
    }
    m += (double)c * v->lv[l].mass;
  }
  return m;
}

const struct wl_vres_counts *wl_vres_counts(const struct wl_vres *v, int level) {
  return &v->lv[level].cnt;
}
