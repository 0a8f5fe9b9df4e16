/* scene.c: particle generation for flumes (scene.h): fluid blocks, fluid
 * under a free surface over a piecewise-linear bed, boundary polylines with
 * mitred layers, the piston paddle, hydrostatic densities. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/scene.h"
#include "internal.h"
#include "wallload/sph.h"

void wl_scene_init(struct wl_scene *sc, const struct wl_sph_const *k, double y0, double y1) {
  memset(sc, 0, sizeof *sc);
  sc->k = *k;
  sc->dim = k->dim;
  sc->dp = k->dp;
  sc->y0 = y0;
  sc->y1 = y1;
}

void wl_scene_clear(struct wl_scene *sc) {
  if (!sc) return;
  for (int g = 0; g < 2; g++) {
    free(sc->pos[g]);
    free(sc->vel[g]);
    free(sc->rho[g]);
    free(sc->kind[g]);
    free(sc->body[g]);
  }
  memset(sc, 0, sizeof *sc);
}

double wl_scene_rho_hydro(const struct wl_sph_const *k, double depth) {
  if (!(depth > 0)) return k->rho0;
  const double rho0 = k->rho0, B = k->B;
  const double g = -(double)k->gravity[k->dim - 1];
  return rho0 * pow(1.0 + rho0 * g * depth / B, 1.0 / 7.0);
}

/* Append one particle to group g (0 boundary, 1 fluid). */
enum wl_status wl_scene_push(struct wl_scene *sc, int g, const double *x, double rho, int kind,
                             int body, struct wl_error *err) {
  const int dim = sc->dim;
  if (sc->n[g] == sc->cap[g]) {
    const int cap = sc->cap[g] ? 2 * sc->cap[g] : 1024;
    if (cap <= sc->cap[g] || cap > 1 << 30)
      return wl_error_set(err, WL_ENOMEM, "scene: more than 2^30 particles");
    double *p = realloc(sc->pos[g], sizeof(double) * (size_t)dim * (size_t)cap);
    if (p) sc->pos[g] = p;
    double *v = p ? realloc(sc->vel[g], sizeof(double) * (size_t)dim * (size_t)cap) : NULL;
    if (v) sc->vel[g] = v;
    double *r = v ? realloc(sc->rho[g], sizeof(double) * (size_t)cap) : NULL;
    if (r) sc->rho[g] = r;
    unsigned char *kd = r ? realloc(sc->kind[g], (size_t)cap) : NULL;
    if (kd) sc->kind[g] = kd;
    unsigned char *bd = kd ? realloc(sc->body[g], (size_t)cap) : NULL;
    if (bd) sc->body[g] = bd;
    if (!bd)
      return wl_error_set(err, WL_ENOMEM, "scene: out of memory for %d %s particles (%.1f MiB)", cap,
                          g ? "fluid" : "boundary", (double)cap * (16.0 * dim + 10) / 1048576.0);
    sc->cap[g] = cap;
  }
  const int i = sc->n[g]++;
  for (int a = 0; a < dim; a++) {
    sc->pos[g][(size_t)i * dim + a] = x[a];
    sc->vel[g][(size_t)i * dim + a] = 0;
  }
  sc->rho[g][i] = rho;
  sc->kind[g][i] = (unsigned char)kind;
  sc->body[g][i] = (unsigned char)body;
  return WL_OK;
}

/* Lattice count of (i + 1/2) dp points in [a, b] and the first point. */
static int lattice(double a, double b, double dp, double *first) {
  const long n = (long)floor((b - a) / dp + WL_SCENE_LATTICE_TOL);
  *first = a + 0.5 * dp;
  return n > 0 ? (int)n : 0;
}

/* Hydrostatic column of n particles of width `width` [m] (dp on a lattice)
 * whose bottom face is z_base [m], with an overburden p_top [Pa] on its top
 * face: particle k (0 = lowest) carries the weight of the particles above
 * it, p_k = p_top + g w (n - k - 1/2) with w = rho0 dp^2 / width its mass
 * per unit area (2D: rho0 dp^2 per unit length on a width; 3D alike, the
 * other horizontal spacing dp), gets the Tait density of that pressure, and
 * the column is stacked with layer thicknesses w / rho_k, so that every
 * particle's volume m/rho equals the space it fills. A uniform lattice with
 * hydrostatic densities (GenCase's way) overstates the SPH pressure at the
 * bed by about the compression, 1 % at coefsound 10 (test_sph_tank); this
 * does not. Writes z[k], rho[k]; returns the column's height. */
static double hydro_column(const struct wl_sph_const *k, int n, double z_base, double p_top,
                           double width, double *z, double *rho) {
  const double dp = k->dp, rho0 = k->rho0, g = -(double)k->gravity[k->dim - 1];
  const double w = rho0 * dp * dp / width;
  double zf = z_base;
  for (int i = 0; i < n; i++) {
    const double p = p_top + g * w * (n - i - 0.5);
    rho[i] = wl_sph_eos_rho_of_p(rho0, k->B, p);
    const double t = w / rho[i];
    if (z) z[i] = zf + 0.5 * t;
    zf += t;
  }
  return zf - z_base;
}

/* The width [m] of a free-surface column of n particles whose height is n
 * dp (hydro_column; rho scratch of n): compressed water is denser at depth,
 * so the column is a little narrower than dp and holds the mass of n dp of
 * compressed water. Fixed point of width = width * height / (n dp). */
static double column_width(const struct wl_sph_const *k, int n, double *rho) {
  double width = k->dp;
  for (int it = 0; it < 4; it++)
    width *= hydro_column(k, n, 0.0, 0.0, width, NULL, rho) / (n * k->dp);
  return width;
}

enum wl_status wl_scene_fluid_block(struct wl_scene *sc, const double *lo, const double *hi,
                                    double eta, struct wl_error *err) {
  const struct wl_sph_const *k = &sc->k;
  const int dim = sc->dim;
  const double dp = sc->dp;
  int n[3] = {1, 1, 1};
  double x0[3] = {0, 0, 0};
  for (int a = 0; a < dim; a++) {
    if (!(hi[a] > lo[a]))
      return wl_error_set(err, WL_EINPUT, "scene fluid block: axis %d is [%g, %g] m; need lo < hi", a,
                          lo[a], hi[a]);
    n[a] = lattice(lo[a], hi[a], dp, &x0[a]);
    if (n[a] == 0)
      return wl_error_set(err, WL_EINPUT, "scene fluid block: axis %d is %g m long, less than dp = "
                          "%g m", a, hi[a] - lo[a], dp);
  }
  const int nz = n[dim - 1];
  double *zc = malloc(sizeof(double) * 2 * (size_t)nz);
  if (!zc) return wl_error_set(err, WL_ENOMEM, "scene fluid block: out of memory (%d layers)", nz);
  double *rc = zc + nz;
  const double g = -(double)k->gravity[dim - 1];
  const double over = eta > hi[dim - 1] ? k->rho0 * g * (eta - hi[dim - 1]) : 0;
  hydro_column(k, nz, lo[dim - 1], over, dp, zc, rc);
  double x[3];
  enum wl_status st = WL_OK;
  for (int iz = 0; iz < nz && st == WL_OK; iz++)
    for (int iy = 0; iy < (dim == 3 ? n[1] : 1) && st == WL_OK; iy++)
      for (int ix = 0; ix < n[0] && st == WL_OK; ix++) {
        x[0] = x0[0] + ix * dp;
        if (dim == 3) x[1] = x0[1] + iy * dp;
        x[dim - 1] = zc[iz];
        st = wl_scene_push(sc, 1, x, rc[iz], WL_KIND_FLUID, 0, err);
      }
  free(zc);
  return st;
}

/* Bed height at x by linear interpolation (held beyond the ends). */
static double bed_at(const double *bx, const double *bz, int n, double x) {
  if (x <= bx[0]) return bz[0];
  if (x >= bx[n - 1]) return bz[n - 1];
  int i = 0;
  while (i < n - 2 && x > bx[i + 1]) i++;
  const double s = (x - bx[i]) / (bx[i + 1] - bx[i]);
  return bz[i] + s * (bz[i + 1] - bz[i]);
}

double wl_scene_polyline_dist(const double *bx, const double *bz, int n, double x, double z) {
  double best = INFINITY;
  for (int i = 0; i + 1 < n; i++) {
    const double tx = bx[i + 1] - bx[i], tz = bz[i + 1] - bz[i];
    const double len2 = tx * tx + tz * tz;
    double s = len2 > 0 ? ((x - bx[i]) * tx + (z - bz[i]) * tz) / len2 : 0;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    const double dx = x - (bx[i] + s * tx), dz = z - (bz[i] + s * tz);
    const double d = sqrt(dx * dx + dz * dz);
    if (d < best) best = d;
  }
  return best;
}

/* A free-surface column: its centre x, width and bottom face [m] and the
 * particles still water at `level` gives it. */
struct column {
  double x, width, base;
  long count;
};

/* The bottom face of the column at x: its lowest particle dp/2 from the bed
 * (the polyline's distance: on a slope dp / (2 cos theta) above it).
 * Stacked on one lattice of rows instead, a column over a slope leaves a
 * void of up to a spacing between its lowest particle and the bed, a
 * sawtooth along the slope, and still water then ran up the slope along the
 * bed at 0.09-0.14 m/s (a 1:5.7 slope, dp = 0.01-0.02 m) and raised the
 * water at a seawall behind it by several mm for as long as it ran
 * (docs/history/2026-11-28-slope-current.md). */
static double column_base(double dp, const double *bed_x, const double *bed_z, int n_bed,
                          double x) {
  const double zb = bed_at(bed_x, bed_z, n_bed, x);
  double z_first = zb + 0.5 * dp;
  if (n_bed > 1) {
    double lo = zb, hi = zb + 2.0 * dp;
    while (wl_scene_polyline_dist(bed_x, bed_z, n_bed, x, hi) < 0.5 * dp && hi < zb + 64 * dp)
      lo = hi, hi += 2.0 * dp; /* a steep bed */
    for (int it = 0; it < 60; it++) {
      const double mid = 0.5 * (lo + hi);
      if (wl_scene_polyline_dist(bed_x, bed_z, n_bed, x, mid) < 0.5 * dp) lo = mid;
      else hi = mid;
    }
    z_first = hi;
  }
  return z_first - 0.5 * dp;
}

/* The particles a column holds up to a surface at z: the whole number
 * nearest the height from its bottom face. */
static long column_count(double dp, double base, double z) {
  return lround((z - base) / dp - WL_SCENE_LATTICE_TOL);
}

/* The particles, a real number, that a column stacked hydrostatically at its
 * width (hydro_column) needs for its top face to reach z: between two whole
 * counts n and n + 1 by the share of the (n + 1)th particle's layer below z;
 * 0 below the column's bottom face. rho: scratch, grown as needed. */
static double column_fill(const struct wl_sph_const *k, const struct column *c, double z,
                          double **rho, long *cap) {
  const double height = z - c->base;
  if (!(height > 0)) return 0;
  long n = (long)floor(height / k->dp);
  for (;;) {
    if (n + 1 > *cap) {
      const long want = 2 * (n + 1);
      double *t = realloc(*rho, sizeof *t * (size_t)want);
      if (!t) return NAN;
      *rho = t, *cap = want;
    }
    const double lo = n > 0 ? hydro_column(k, (int)n, 0.0, 0.0, c->width, NULL, *rho) : 0;
    const double hi = hydro_column(k, (int)(n + 1), 0.0, 0.0, c->width, NULL, *rho);
    if (lo > height && n > 0) n--;
    else if (hi <= height) n++;
    else return n + (height - lo) / (hi - lo);
  }
}

/* The still-water columns from x1 toward x0 (wl_scene_fluid_surface): as
 * many whole columns as fit, each as wide as holds its still water level
 * (column_width). *out malloc'ed (NULL and 0 when none fits); returns the
 * count, or -1 out of memory. */
static int lay_columns(const struct wl_sph_const *k, double x0, double x1, const double *bed_x,
                       const double *bed_z, int n_bed, double level, struct column **out) {
  const double dp = k->dp;
  struct column *col = NULL;
  int n = 0, cap = 0;
  double *rho = NULL;
  long rho_cap = 0;
  double edge = x1, width = dp;
  while (edge - x0 >= width * (1.0 - WL_SCENE_LATTICE_TOL)) {
    if (n == cap) {
      cap = cap ? 2 * cap : 256;
      struct column *t = realloc(col, sizeof *t * (size_t)cap);
      if (!t) goto oom;
      col = t;
    }
    struct column *c = &col[n];
    for (int pass = 0; pass < 2; pass++) { /* its centre, then its width there */
      c->x = edge - 0.5 * width;
      c->base = column_base(dp, bed_x, bed_z, n_bed, c->x);
      c->count = column_count(dp, c->base, level);
      if (c->count > rho_cap) {
        double *t = realloc(rho, sizeof *t * (size_t)c->count);
        if (!t) goto oom;
        rho = t, rho_cap = c->count;
      }
      /* Compressed water is denser at depth, so a column of count
       * particles a spacing wide stands g D^2/(2 c0^2) below the level it
       * was counted to (D its depth; 1.0 mm in 0.36 m at c0 = 25 m/s,
       * 0.03 mm in 0.06 m). Laid so, the deep flume of seawall.yaml stood
       * 1 mm lower than its platform, which drained into it after the
       * start, lowered the water at the wall by about 1 mm and set the
       * flume sloshing (the wall force 4 % of its value at rest off;
       * docs/history/2026-11-28-slope-current.md, "The level"). A column
       * narrower by that fraction holds compressed water to the level at
       * every depth, with no column a particle higher than the next. */
      width = c->count > 0 ? column_width(k, (int)c->count, rho) : dp;
    }
    c->width = width;
    edge -= width;
    n++;
  }
  free(rho);
  *out = col;
  return n;
oom:
  free(rho);
  free(col);
  *out = NULL;
  return -1;
}

double wl_scene_fluid_columns_edge(const struct wl_sph_const *k, double x0, double x1,
                                   const double *bed_x, const double *bed_z, int n_bed,
                                   double level) {
  struct column *col;
  const int n = lay_columns(k, x0, x1, bed_x, bed_z, n_bed, level, &col);
  double edge = x1;
  for (int i = 0; i < n; i++) edge -= col[i].width;
  free(col);
  return n < 0 ? NAN : edge;
}

enum wl_status wl_scene_fluid_surface(struct wl_scene *sc, double x0, double x1,
                                      const double *bed_x, const double *bed_z, int n_bed,
                                      double level, wl_scene_eta_fn eta, void *user,
                                      struct wl_error *err) {
  const struct wl_sph_const *k = &sc->k;
  const int dim = sc->dim;
  const double dp = sc->dp;
  if (n_bed < 1 || !bed_x || !bed_z || !eta)
    return wl_error_set(err, WL_EINPUT, "scene fluid surface: need a bed (>= 1 vertex) and eta(x)");
  for (int i = 1; i < n_bed; i++)
    if (!(bed_x[i] > bed_x[i - 1]))
      return wl_error_set(err, WL_EINPUT, "scene fluid surface: bed x not increasing at vertex %d "
                          "(%g after %g m)", i, bed_x[i], bed_x[i - 1]);
  if (!(x1 > x0))
    return wl_error_set(err, WL_EINPUT, "scene fluid surface: x range [%g, %g] m; need x0 < x1", x0, x1);
  double ys = 0;
  int ny = 1;
  if (dim == 3) ny = lattice(sc->y0, sc->y1, dp, &ys);
  struct column *col;
  const int n_col = lay_columns(k, x0, x1, bed_x, bed_z, n_bed, level, &col);
  if (n_col < 0) return wl_error_set(err, WL_ENOMEM, "scene fluid surface: out of memory (columns)");
  /* Each column: the particles that stack its top face to eta(x)
   * (column_fill), rounded with the remainder carried on to the next column
   * (error diffusion), so that a wave or a crater holds its volume to half a
   * particle. Rounding each column alone dropped every tail under dp/2: a
   * solitary wave started 2.4 % short of its volume at dp = H/9. Columns at
   * the still level keep the count they were laid with. */
  enum wl_status st = WL_OK;
  double *zc = NULL, *rc = NULL, x[3], *fill_rho = NULL, carry = 0;
  long cap = 0, fill_cap = 0;
  for (int i = n_col - 1; i >= 0 && st == WL_OK; i--) { /* seaward first, as the lattice did */
    const struct column *c = &col[i];
    const double z = eta(c->x, user);
    double want = (double)c->count;
    if (fabs(z - level) > WL_SCENE_LATTICE_TOL * dp) {
      want = column_fill(k, c, z, &fill_rho, &fill_cap);
      if (isnan(want)) {
        st = wl_error_set(err, WL_ENOMEM, "scene fluid surface: out of memory");
        break;
      }
    }
    long count = lround(want + carry);
    if (count < 0) count = 0;
    carry += want - (double)count;
    if (count <= 0) continue;
    if (count > cap) {
      double *t = realloc(zc, sizeof(double) * 2 * (size_t)count);
      if (!t) {
        st = wl_error_set(err, WL_ENOMEM, "scene fluid surface: out of memory");
        break;
      }
      zc = t, cap = count;
    }
    rc = zc + cap;
    hydro_column(k, (int)count, c->base, 0, c->width, zc, rc);
    for (long m = 0; m < count && st == WL_OK; m++)
      for (int iy = 0; iy < ny && st == WL_OK; iy++) {
        x[0] = c->x;
        if (dim == 3) x[1] = ys + iy * dp;
        x[dim - 1] = zc[m];
        st = wl_scene_push(sc, 1, x, rc[m], WL_KIND_FLUID, 0, err);
      }
  }
  free(col);
  free(zc);
  free(fill_rho);
  return st;
}

enum wl_status wl_scene_boundary_polyline(struct wl_scene *sc, const double *x, const double *z,
                                          int nv, int n_layers, int kind, int body,
                                          struct wl_sph_config *cfg, struct wl_error *err) {
  const int dim = sc->dim;
  const double dp = sc->dp;
  if (nv < 2 || !x || !z)
    return wl_error_set(err, WL_EINPUT, "scene boundary: a polyline needs >= 2 vertices (got %d)", nv);
  if (n_layers < 1 || n_layers > 16)
    return wl_error_set(err, WL_EINPUT, "scene boundary: %d layers; valid 1..16", n_layers);
  if (kind != WL_KIND_FIXED && kind != WL_KIND_MOVING)
    return wl_error_set(err, WL_EINPUT, "scene boundary: kind %d; valid %d (fixed) or %d (moving)",
                        kind, WL_KIND_FIXED, WL_KIND_MOVING);
  if (kind == WL_KIND_MOVING && (body < 1 || body > WL_SPH_BODIES_MAX))
    return wl_error_set(err, WL_EINPUT, "scene boundary: moving body %d; valid 1..%d", body,
                        WL_SPH_BODIES_MAX);
  if (kind == WL_KIND_FIXED) body = 0;
  /* unit directions and right-hand normals (away from the fluid) */
  double *nx = malloc(sizeof(double) * (size_t)(nv - 1) * 2);
  if (!nx) return wl_error_set(err, WL_ENOMEM, "scene boundary: out of memory");
  double *nz = nx + (nv - 1);
  for (int i = 0; i + 1 < nv; i++) {
    const double tx = x[i + 1] - x[i], tz = z[i + 1] - z[i], len = sqrt(tx * tx + tz * tz);
    if (!(len > 1e-12 * dp)) {
      free(nx);
      return wl_error_set(err, WL_EINPUT, "scene boundary: segment %d from (%g, %g) to (%g, %g) m "
                          "has zero length", i, x[i], z[i], x[i + 1], z[i + 1]);
    }
    nx[i] = tz / len; /* right of (tx, tz) is (tz, -tx) */
    nz[i] = -tx / len;
  }
  double ys = 0;
  int ny = 1;
  if (dim == 3) {
    const double w = sc->y1 - sc->y0;
    ny = (int)floor(w / dp + 0.5) + 1;
    if (ny < 1) ny = 1;
    ys = sc->y0;
  }
  const double dy = dim == 3 && ny > 1 ? (sc->y1 - sc->y0) / (ny - 1) : 0;
  enum wl_status st = WL_OK;
  for (int layer = 0; layer < n_layers && st == WL_OK; layer++) {
    const double off = (layer + 0.5) * dp;
    for (int i = 0; i + 1 < nv && st == WL_OK; i++) {
      /* offset end points with mitred joins */
      double p0[2], p1[2];
      for (int end = 0; end < 2; end++) {
        const int v = i + end;
        double mx, mz;
        if (v == 0 || v == nv - 1) {
          const int s = v == 0 ? 0 : nv - 2;
          mx = nx[s];
          mz = nz[s];
        } else {
          const double c = 1 + nx[v - 1] * nx[v] + nz[v - 1] * nz[v];
          mx = c > 1e-6 ? (nx[v - 1] + nx[v]) / c : nx[v];
          mz = c > 1e-6 ? (nz[v - 1] + nz[v]) / c : nz[v];
        }
        double *p = end ? p1 : p0;
        p[0] = x[v] + off * mx;
        p[1] = z[v] + off * mz;
      }
      const double len = sqrt((p1[0] - p0[0]) * (p1[0] - p0[0]) + (p1[1] - p0[1]) * (p1[1] - p0[1]));
      int m = (int)floor(len / dp + 0.5);
      if (m < 1) m = 1;
      const int last = i + 2 == nv; /* the last segment also places its end point */
      for (int j = 0; j < m + last && st == WL_OK; j++) {
        const double s = (double)j / m;
        double q[3];
        q[0] = p0[0] + s * (p1[0] - p0[0]);
        q[dim - 1] = p0[1] + s * (p1[1] - p0[1]);
        for (int iy = 0; iy < ny && st == WL_OK; iy++) {
          if (dim == 3) q[1] = ys + iy * dy;
          st = wl_scene_push(sc, 0, q, sc->k.rho0, kind, body, err);
        }
      }
    }
  }
  free(nx);
  if (st != WL_OK) return st;
  if (cfg && kind == WL_KIND_FIXED) st = wl_sph_config_add_faces(cfg, x, z, nv, n_layers * dp, err);
  return st;
}

enum wl_status wl_scene_piston(struct wl_scene *sc, double x_face, double z0, double z1,
                               int n_layers, int body, struct wl_error *err) {
  if (!(z1 > z0))
    return wl_error_set(err, WL_EINPUT, "scene piston: z range [%g, %g] m; need z0 < z1", z0, z1);
  /* walking down the face has the fluid (x > x_face) on its left */
  const double x[2] = {x_face, x_face}, z[2] = {z1, z0};
  return wl_scene_boundary_polyline(sc, x, z, 2, n_layers, WL_KIND_MOVING, body, NULL, err);
}

void wl_scene_hydrostatic_boundary(struct wl_scene *sc, double eta) {
  for (int i = 0; i < sc->n[0]; i++)
    sc->rho[0][i] = wl_scene_rho_hydro(&sc->k, eta - sc->pos[0][(size_t)i * sc->dim + sc->dim - 1]);
}

void wl_scene_fluid_velocity(struct wl_scene *sc, wl_scene_vel_fn fn, void *user) {
  for (int i = 0; i < sc->n[1]; i++)
    fn(&sc->pos[1][(size_t)i * sc->dim], &sc->vel[1][(size_t)i * sc->dim], user);
}

void wl_scene_fluid_add_pressure(struct wl_scene *sc, wl_scene_dp_fn fn, void *user) {
  const struct wl_sph_const *k = &sc->k;
  for (int i = 0; i < sc->n[1]; i++) {
    const double r = sc->rho[1][i] / (double)k->rho0, r2 = r * r;
    const double p = (double)k->B * (r2 * r2 * r2 * r - 1.0);
    sc->rho[1][i] = wl_sph_eos_rho_of_p(k->rho0, k->B, p + fn(&sc->pos[1][(size_t)i * sc->dim], user));
  }
}

enum wl_status wl_scene_build(const struct wl_scene *sc, struct wl_particles *out,
                              struct wl_error *err) {
  const int dim = sc->dim, n = sc->n[0] + sc->n[1];
  memset(out, 0, sizeof *out);
  if (sc->n[1] == 0) return wl_error_set(err, WL_EINPUT, "scene: no fluid particles");
  enum wl_status st = wl_particles_alloc(out, dim, n, 0, err);
  if (st != WL_OK) return st;
  int i = 0;
  for (int g = 0; g < 2; g++)
    for (int s = 0; s < sc->n[g]; s++, i++) {
      for (int a = 0; a < dim; a++) {
        out->pos[a][i] = sc->pos[g][(size_t)s * dim + a];
        out->vel[a][i] = (wl_real)sc->vel[g][(size_t)s * dim + a];
      }
      out->rho[i] = (wl_real)sc->rho[g][s];
      out->id[i] = (unsigned)i;
      out->kind[i] = sc->kind[g][s];
      out->body[i] = sc->body[g][s];
    }
  out->n = n;
  out->n_bound = sc->n[0];
  return WL_OK;
}
