/* box3d.c: 3D boxes of dynamic boundary particles (scene.h): the floor and
 * four walls of a rectangular tank open at the top, and a solid box such as
 * a pillar standing on the floor. The 2D polylines of scene.c extrude along
 * y and cannot close a tank at y = y0 and y = y1; these can.
 *
 * Layout as scene.h's convention: the box faces are wall FACES. Along each
 * axis the points inside a face span sit at x0 + (i + 1/2) s, with s the
 * spacing closest to dp that divides the span (dp itself when the span is
 * a multiple of dp, so they coincide with the fluid lattice), and boundary
 * layer k (0 .. n_layers-1) lies (k + 1/2) dp behind the face. Edges and
 * corners are filled (the outer product of the axis coordinates), so no
 * fluid particle sees a gap. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/scene.h"
#include "internal.h"
#include "wallload/sph.h"

/* Coordinates along one axis: `before` layers below lo, the points inside
 * [lo, hi], `after` layers above hi (see the file header). c gets them
 * (room for before + after + the inside count), inside[] 1 for the inside
 * ones. Returns the count. */
static int axis_coords(double lo, double hi, double dp, int before, int after, double *c,
                       unsigned char *inside) {
  int m = (int)floor((hi - lo) / dp + 0.5);
  if (m < 1) m = 1;
  const double s = (hi - lo) / m;
  int n = 0;
  for (int k = before - 1; k >= 0; k--) {
    c[n] = lo - (k + 0.5) * dp;
    inside[n++] = 0;
  }
  for (int i = 0; i < m; i++) {
    c[n] = lo + (i + 0.5) * s;
    inside[n++] = 1;
  }
  for (int k = 0; k < after; k++) {
    c[n] = hi + (k + 0.5) * dp;
    inside[n++] = 0;
  }
  return n;
}

/* Shared checks of both boxes. */
static enum wl_status check_box(const struct wl_scene *sc, const char *what, const double *lo,
                                const double *hi, int n_layers, struct wl_error *err) {
  if (sc->dim != 3)
    return wl_error_set(err, WL_EINPUT, "scene %s: 3D only (the scene is %dD)", what, sc->dim);
  if (n_layers < 1 || n_layers > 16)
    return wl_error_set(err, WL_EINPUT, "scene %s: %d layers; valid 1..16", what, n_layers);
  for (int a = 0; a < 3; a++)
    if (!(hi[a] - lo[a] >= sc->dp) || !isfinite(hi[a] - lo[a]))
      return wl_error_set(err, WL_EINPUT, "scene %s: axis %d is [%g, %g] m; need hi - lo >= dp = %g m",
                          what, a, lo[a], hi[a], sc->dp);
  return WL_OK;
}

/* The points of the product of the axis coordinates outside the inside
 * span on at least one axis (the shell: faces, edges, corners). */
static enum wl_status emit_shell(struct wl_scene *sc, const double *c[3],
                                 const unsigned char *in[3], const int n[3], struct wl_error *err) {
  double q[3];
  enum wl_status st = WL_OK;
  for (int iz = 0; iz < n[2] && st == WL_OK; iz++)
    for (int iy = 0; iy < n[1] && st == WL_OK; iy++)
      for (int ix = 0; ix < n[0] && st == WL_OK; ix++) {
        if (in[0][ix] && in[1][iy] && in[2][iz]) continue;
        q[0] = c[0][ix];
        q[1] = c[1][iy];
        q[2] = c[2][iz];
        st = wl_scene_push(sc, 0, q, sc->k.rho0, WL_KIND_FIXED, 0, err);
      }
  return st;
}

enum wl_status wl_scene_box3d_tank(struct wl_scene *sc, const double *lo, const double *hi,
                                   int n_layers, struct wl_sph_config *cfg, struct wl_error *err) {
  enum wl_status st = check_box(sc, "tank", lo, hi, n_layers, err);
  if (st) return st;
  const double dp = sc->dp;
  int n[3];
  double *c[3] = {NULL, NULL, NULL};
  unsigned char *in[3] = {NULL, NULL, NULL};
  for (int a = 0; a < 3 && st == WL_OK; a++) {
    const int room = (int)floor((hi[a] - lo[a]) / dp + 0.5) + 2 * n_layers + 1;
    c[a] = malloc(sizeof(double) * (size_t)room);
    in[a] = malloc((size_t)room);
    if (!c[a] || !in[a]) st = wl_error_set(err, WL_ENOMEM, "scene tank: out of memory");
    else n[a] = axis_coords(lo[a], hi[a], dp, n_layers, a == 2 ? 0 : n_layers, c[a], in[a]);
  }
  if (st == WL_OK) {
    const double *cc[3] = {c[0], c[1], c[2]};
    const unsigned char *ii[3] = {in[0], in[1], in[2]};
    st = emit_shell(sc, cc, ii, n, err);
  }
  for (int a = 0; a < 3; a++) {
    free(c[a]);
    free(in[a]);
  }
  /* penetration guard: floor and the two end walls (extruded along y, as
   * sph/guard.h's walls are); the side walls y = lo, hi have no guard face */
  const double t = n_layers * dp;
  const double fx[4] = {lo[0], lo[0], hi[0], hi[0]}, fz[4] = {hi[2], lo[2], lo[2], hi[2]};
  if (st == WL_OK && cfg) st = wl_sph_config_add_faces(cfg, fx, fz, 4, t, err);
  return st;
}

enum wl_status wl_scene_box3d_solid(struct wl_scene *sc, const double *lo, const double *hi,
                                    int n_layers, int floor_below, struct wl_error *err) {
  enum wl_status st = check_box(sc, "solid box", lo, hi, n_layers, err);
  if (st) return st;
  const double dp = sc->dp;
  int n[3];
  double *c[3] = {NULL, NULL, NULL};
  unsigned char *in[3] = {NULL, NULL, NULL};
  for (int a = 0; a < 3 && st == WL_OK; a++) {
    const int room = (int)floor((hi[a] - lo[a]) / dp + 0.5) + 1;
    c[a] = malloc(sizeof(double) * (size_t)room);
    in[a] = malloc((size_t)room);
    if (!c[a] || !in[a]) {
      st = wl_error_set(err, WL_ENOMEM, "scene solid box: out of memory");
      break;
    }
    n[a] = axis_coords(lo[a], hi[a], dp, 0, 0, c[a], in[a]);
  }
  /* the layers: points within n_layers of a face (the bottom face counts
   * only when no floor is below), i.e. a hollow box n_layers thick */
  double q[3];
  for (int iz = 0; st == WL_OK && iz < n[2]; iz++)
    for (int iy = 0; iy < n[1] && st == WL_OK; iy++)
      for (int ix = 0; ix < n[0] && st == WL_OK; ix++) {
        const int dx = ix < n[0] - 1 - ix ? ix : n[0] - 1 - ix;
        const int dy = iy < n[1] - 1 - iy ? iy : n[1] - 1 - iy;
        const int dz = floor_below ? n[2] - 1 - iz : (iz < n[2] - 1 - iz ? iz : n[2] - 1 - iz);
        if (dx >= n_layers && dy >= n_layers && dz >= n_layers) continue;
        q[0] = c[0][ix];
        q[1] = c[1][iy];
        q[2] = c[2][iz];
        st = wl_scene_push(sc, 0, q, sc->k.rho0, WL_KIND_FIXED, 0, err);
      }
  for (int a = 0; a < 3; a++) {
    free(c[a]);
    free(in[a]);
  }
  return st;
}

enum wl_status wl_scene_box3d_sides(struct wl_scene *sc, const double *xz, int n, double y0,
                                    double y1, int sides, int n_layers, struct wl_error *err) {
  if (sc->dim != 3)
    return wl_error_set(err, WL_EINPUT, "scene side walls: 3D only (the scene is %dD)", sc->dim);
  if (n_layers < 1 || n_layers > 16)
    return wl_error_set(err, WL_EINPUT, "scene side walls: %d layers; valid 1..16", n_layers);
  if (!(y1 > y0))
    return wl_error_set(err, WL_EINPUT, "scene side walls: y range [%g, %g] m; need y0 < y1", y0,
                        y1);
  enum wl_status st = WL_OK;
  for (int side = 0; side < 2; side++) {
    if (!(sides & (1 << side))) continue;
    for (int k = 0; k < n_layers; k++)
      for (int i = 0; i < n && st == WL_OK; i++) {
        const double off = (k + 0.5) * sc->dp;
        const double q[3] = {xz[2 * i], side ? y1 + off : y0 - off, xz[2 * i + 1]};
        st = wl_scene_push(sc, 0, q, sc->k.rho0, WL_KIND_FIXED, 0, err);
      }
  }
  return st;
}
