/* sph/guard.h: the instability guard, checked for every particle after
 * every step (host and device). A run that fails it stops with
 * WL_EUNSTABLE and a message naming the particle, what, where and when.
 *
 * Faults, in the order checked:
 *  - non-finite position, velocity or density (any particle);
 *  - a particle outside the domain box (the cell grid); a fluid particle
 *    the update carried out of it is first taken out of the run
 *    (wl_sph_exclude, below), so this is a boundary particle's fault;
 *  - fluid density outside [rho_min, rho_max] (DualSPHysics RhopOutMin/Max,
 *    700 and 1300 kg/m^3 for water by default): compressibility has failed;
 *  - a fluid particle inside a wall: walls are segments of the wall FACE in
 *    the (x, z) plane (the line where the fluid ends and the boundary
 *    layers begin; scene.h puts the first layer dp/2 behind it), with the
 *    fluid on the left of a -> b, and caps across the layers at a
 *    polyline's ends (wl_sph_config_add_faces). A fluid particle's depth
 *    in a wall is, over the faces on which its projection falls (farther
 *    than `penetration` from their ends) and behind which it lies within
 *    the layers (thickness), the least of its distances to the face and to
 *    the back of the layers: the nearest way out. Deeper than `penetration`
 *    (default dp/2) is a crossed wall. So water that slides just under a
 *    convex corner's other face, passes over a wall's open top, or went
 *    over a wall and runs down its back is not a fault. In 3D the segments
 *    are extruded along y.
 * The dt collapse (dt < dt_collapse * initial dt) is checked by the driver. */
#ifndef WALLLOAD_SPH_GUARD_H
#define WALLLOAD_SPH_GUARD_H

#include "wallload/sph/particles.h"
#include "wallload/sph/params.h"

enum wl_sph_fault {
  WL_SPH_FAULT_NONE = 0,
  WL_SPH_FAULT_NONFINITE = 1,
  WL_SPH_FAULT_OUTSIDE = 2,
  WL_SPH_FAULT_DENSITY = 3,
  WL_SPH_FAULT_PENETRATION = 4,
  WL_SPH_FAULT_DT = 5, /* driver: dt collapsed */
};

/* A wall face segment for the penetration check. */
struct wl_sph_wall {
  double a[2];      /* start point (x, z) [m] */
  double t[2];      /* unit tangent a -> b; the fluid is on its left */
  double len;       /* |b - a| [m] */
  double thickness; /* depth of the boundary layers behind the face [m] */
};

/* The wall from a = (ax, az) to b = (bx, bz) [m], fluid on the left of
 * a -> b, boundary layers `thickness` [m] deep. a == b gives a wall that
 * never reports. */
WL_HD static inline struct wl_sph_wall wl_sph_wall_make(double ax, double az, double bx, double bz,
                                                        double thickness) {
  struct wl_sph_wall w;
  const double tx = bx - ax, tz = bz - az, len2 = tx * tx + tz * tz;
  double len = len2; /* sqrt by Newton: no libm in shared headers */
  if (len2 > 0) {
    len = len2 > 1 ? len2 : 1;
    for (int it = 0; it < 200; it++) len = 0.5 * (len + len2 / len);
  }
  w.a[0] = ax;
  w.a[1] = az;
  w.len = len;
  w.t[0] = len > 0 ? tx / len : 0;
  w.t[1] = len > 0 ? tz / len : 0;
  w.thickness = thickness;
  return w;
}

WL_HD static inline int wl_sph_finite(double x) { return x - x == 0.0; }

/* A fluid particle that the update carried out of the domain box (a splash
 * over a tank's wall, a jet over the box's top) is taken out of the run,
 * as DualSPHysics excludes such particles: put back just inside the face
 * it crossed, at rest, its body set to WL_SPH_BODY_EXCLUDED, after which
 * the integrators leave it where it is (sph/integrate.h). The runs count
 * them, and stop when more than a small fraction of the fluid is gone
 * (sph.c). Returns 1 when it excluded particle i now. */
WL_HD static inline int wl_sph_exclude(const int dim, const struct wl_particles *p,
                                       const double *lo, const double *hi, int i) {
  if (p->kind[i] != WL_KIND_FLUID || p->body[i] == WL_SPH_BODY_EXCLUDED) return 0;
  int out = 0;
  for (int a = 0; a < dim; a++) {
    const double x = p->pos[a][i], eps = 1e-9 * (hi[a] - lo[a]);
    if (!(x > lo[a] + eps)) p->pos[a][i] = lo[a] + eps, out = 1;
    if (!(x < hi[a] - eps)) p->pos[a][i] = hi[a] - eps, out = 1;
  }
  if (!out) return 0;
  for (int a = 0; a < dim; a++) {
    p->vel[a][i] = 0;
    p->vel_h[a][i] = 0;
  }
  p->body[i] = WL_SPH_BODY_EXCLUDED;
  return 1;
}

/* The wall limiter (params.h wall_limiter), after a fluid particle's
 * update: when it lies behind one or more wall faces, within their
 * boundary layers (the faces of the guard below), it is moved back onto
 * the face it is least deep behind (the nearest way out: at a convex
 * corner, the face it slid under, not the one it is far behind) and the
 * component of its velocity (and, for the Verlet step, of its previous
 * velocity) into that face is removed. Its momentum into the wall is lost:
 * a last resort against particles a thin, fast, pressure-free jet drives
 * into a wall, never active in a flow the wall condition holds (the runs
 * count the corrections). Returns 1 when it moved the particle. */
WL_HD static inline int wl_sph_wall_limit(const int dim, const struct wl_particles *p,
                                          const struct wl_sph_wall *walls, int n_walls,
                                          double end_margin, int i) {
  if (p->kind[i] != WL_KIND_FLUID || p->body[i] == WL_SPH_BODY_EXCLUDED) return 0;
  const int az = dim - 1;
  const double x = p->pos[0][i], z = p->pos[az][i];
  int best = -1;
  double depth = 0, way = 1.0;
  for (int w = 0; w < n_walls; w++) {
    const double tx = walls[w].t[0], tz = walls[w].t[1];
    const double rx = x - walls[w].a[0], rz = z - walls[w].a[1];
    const double s = rx * tx + rz * tz;
    /* not within end_margin of the face's ends: over a wall's open top a
     * particle passes above its layers, not through them */
    if (s < end_margin || s > walls[w].len - end_margin) continue;
    const double d = tx * rz - tz * rx; /* signed distance, > 0 on the fluid side */
    if (!(d < 0 && d > -walls[w].thickness)) continue;
    /* out through the face, or through the back of the layers (water
     * that went over the wall and runs down its outside), the nearer */
    const double front = -d, back = walls[w].thickness + d;
    if (best < 0 || (front < back ? front : back) < depth) {
      best = w;
      depth = front < back ? front : back;
      way = front < back ? 1.0 : -1.0;
    }
  }
  if (best < 0) return 0;
  /* unit normal out of the wall on the way taken */
  const double nx = -walls[best].t[1] * way, nz = walls[best].t[0] * way;
  p->pos[0][i] = x + depth * nx;
  p->pos[az][i] = z + depth * nz;
  const double vn = (double)p->vel[0][i] * nx + (double)p->vel[az][i] * nz;
  if (vn < 0) {
    p->vel[0][i] = (wl_real)((double)p->vel[0][i] - vn * nx);
    p->vel[az][i] = (wl_real)((double)p->vel[az][i] - vn * nz);
  }
  if (p->vel_h[0]) {
    const double vh = (double)p->vel_h[0][i] * nx + (double)p->vel_h[az][i] * nz;
    if (vh < 0) {
      p->vel_h[0][i] = (wl_real)((double)p->vel_h[0][i] - vh * nx);
      p->vel_h[az][i] = (wl_real)((double)p->vel_h[az][i] - vh * nz);
    }
  }
  return 1;
}

/* The axis-aligned box {x0, x1, z0, z1} around what lies behind face w
 * within its layers (a + s t - d n, n the fluid side's unit normal, s in
 * [0, len], d in [0, thickness]), widened by a micrometre against
 * rounding: a particle outside it is behind no part of w. */
WL_HD static inline void wl_sph_wall_box(const struct wl_sph_wall *w, double box[4]) {
  const double nx = -w->t[1], nz = w->t[0];
  const double cx[4] = {w->a[0], w->a[0] + w->len * w->t[0], w->a[0] - w->thickness * nx,
                        w->a[0] + w->len * w->t[0] - w->thickness * nx};
  const double cz[4] = {w->a[1], w->a[1] + w->len * w->t[1], w->a[1] - w->thickness * nz,
                        w->a[1] + w->len * w->t[1] - w->thickness * nz};
  box[0] = box[1] = cx[0];
  box[2] = box[3] = cz[0];
  for (int c = 1; c < 4; c++) {
    box[0] = cx[c] < box[0] ? cx[c] : box[0];
    box[1] = cx[c] > box[1] ? cx[c] : box[1];
    box[2] = cz[c] < box[2] ? cz[c] : box[2];
    box[3] = cz[c] > box[3] ? cz[c] : box[3];
  }
  box[0] -= 1e-6, box[1] += 1e-6, box[2] -= 1e-6, box[3] += 1e-6;
}

/* The faces of walls[0, n) whose boxes (wl_sph_wall_box) meet `box`
 * ({x0, x1, z0, z1}, the particles' own), copied in their order into out;
 * returns how many. For every particle inside `box` the limiter over them
 * decides as over all n (the faces left out cannot hold it, and the order
 * of those kept, which breaks ties, is the same). */
WL_HD static inline int wl_sph_walls_near(const struct wl_sph_wall *walls, int n,
                                          const double box[4], struct wl_sph_wall *out) {
  int m = 0;
  for (int w = 0; w < n; w++) {
    double b[4];
    wl_sph_wall_box(&walls[w], b);
    if (b[0] <= box[1] && b[1] >= box[0] && b[2] <= box[3] && b[3] >= box[2]) out[m++] = walls[w];
  }
  return m;
}

/* How many of the wall faces the guard must test for a particle after the
 * limiter: none when the limiter ran on it and left it where it was, all
 * of them otherwise. A particle the limiter left lies behind no face
 * (d < 0) within its layers and away from its ends, the same faces and
 * margins as the guard's test below, which therefore cannot fire (d = 0
 * is depth 0); one the limiter moved sits on a face and may be behind
 * another at a corner. The guard's verdicts are unchanged, and a step
 * loops over the faces once a particle instead of twice. */
WL_HD static inline int wl_sph_guard_faces(int limiter_ran, int limiter_moved, int n_walls) {
  return limiter_ran && !limiter_moved ? 0 : n_walls;
}

/* Fault of particle i (WL_SPH_FAULT_NONE if none); *wall gets the index of
 * the crossed wall for WL_SPH_FAULT_PENETRATION. lo, hi: domain box [m]. */
WL_HD static inline int wl_sph_guard(const int dim, const struct wl_sph_const *k,
                                     const struct wl_particles *p, const double *lo,
                                     const double *hi, const struct wl_sph_wall *walls,
                                     int n_walls, int i, int *wall) {
  int finite = wl_sph_finite((double)p->rho[i]);
  for (int a = 0; a < dim; a++)
    finite = finite && wl_sph_finite(p->pos[a][i]) && wl_sph_finite((double)p->vel[a][i]);
  if (!finite) return WL_SPH_FAULT_NONFINITE;
  if (p->kind[i] == WL_KIND_FLUID && p->body[i] == WL_SPH_BODY_EXCLUDED) return WL_SPH_FAULT_NONE;
  for (int a = 0; a < dim; a++)
    if (p->pos[a][i] < lo[a] || p->pos[a][i] > hi[a]) return WL_SPH_FAULT_OUTSIDE;
  if (p->kind[i] != WL_KIND_FLUID) return WL_SPH_FAULT_NONE;
  if (p->rho[i] < k->rho_min || p->rho[i] > k->rho_max) return WL_SPH_FAULT_DENSITY;
  const double x = p->pos[0][i], z = p->pos[dim - 1][i];
  /* its depth in the wall: the least over the faces it lies behind (at a
   * convex corner, a particle sliding just under the crest is not deep in
   * the wall although it is far behind the wall's vertical face) */
  int deepest = -1;
  double depth = 0;
  for (int w = 0; w < n_walls; w++) {
    const double tx = walls[w].t[0], tz = walls[w].t[1];
    const double rx = x - walls[w].a[0], rz = z - walls[w].a[1];
    const double s = rx * tx + rz * tz;
    /* a particle within `penetration` of a face's end is passing over the
     * wall's open top (or into the neighbouring face's region), not
     * through it */
    if (s < k->penetration || s > walls[w].len - k->penetration) continue;
    const double d = tx * rz - tz * rx; /* signed distance, > 0 on the fluid side */
    if (!(d <= 0 && d > -walls[w].thickness)) continue;
    /* depth from the face or from the back of the layers, the less: water
     * that went over a wall runs down its outside, against the back */
    const double front = -d, back = walls[w].thickness + d, dw = front < back ? front : back;
    if (deepest < 0 || dw < depth) {
      deepest = w;
      depth = dw;
    }
  }
  if (deepest >= 0 && depth > k->penetration) {
    *wall = deepest;
    return WL_SPH_FAULT_PENETRATION;
  }
  return WL_SPH_FAULT_NONE;
}

#endif
