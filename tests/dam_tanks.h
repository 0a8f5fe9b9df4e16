/* dam_tanks.h: the small dam breaks the backend tests run, built on a
 * configuration the caller has made (wl_sph_config_default with dp and the
 * tank's H, then its numerics and, for DAM_3D_MIRROR*, mirror planes at
 * y = 0 and y = DAM_W): the domain box is set here. The tank's left wall
 * (x < 0) is tagged body_wall. */
#ifndef WALLLOAD_TESTS_DAM_TANKS_H
#define WALLLOAD_TESTS_DAM_TANKS_H

#include "wallload/scene.h"
#include "wallload/sph.h"

enum dam_tank {
  DAM_2D,               /* L = 0.8 m, column 0.2 m wide */
  DAM_3D_MIRROR,        /* the x-z section extruded along y between mirror planes */
  DAM_3D_MIRROR_PILLAR, /* the same with a pillar */
  DAM_3D_BOX_PILLAR,    /* a closed box with a pillar */
};

#define DAM_W 0.2 /* 3D: tank width [m] */
#define DAM_LAYERS 2

/* The column's height H [m] of each tank (the caller's h_max). */
static inline double dam_tank_height(enum dam_tank t) { return t == DAM_2D ? 0.4 : 0.15; }

static inline enum wl_status dam_tank_build(enum dam_tank t, struct wl_sph_config *cfg,
                                            int body_wall, struct wl_particles *p,
                                            struct wl_error *err) {
  const double dp = cfg->prm.dp, H = dam_tank_height(t), W = DAM_W;
  struct wl_sph_const k;
  enum wl_status st = wl_sph_const_make(&cfg->prm, &k, err);
  if (st) return st;
  const double margin = (DAM_LAYERS + 2) * dp;
  const double plo[3] = {0.22, 0.08, 0}, phi[3] = {0.26, 0.12, 0.3}; /* the pillar */
  struct wl_scene sc;
  if (t == DAM_2D) {
    const double L = 0.8, A = 0.2;
    cfg->lo[0] = -margin;
    cfg->hi[0] = L + margin;
    cfg->lo[1] = -margin;
    cfg->hi[1] = 2 * H;
    wl_scene_init(&sc, &k, 0, 0);
    const double tx[4] = {0, 0, L, L}, tz[4] = {1.5 * H, 0, 0, 1.5 * H};
    const double lo[2] = {0, 0}, hi[2] = {A, H};
    st = wl_scene_boundary_polyline(&sc, tx, tz, 4, DAM_LAYERS, WL_KIND_FIXED, 0, cfg, err);
    if (!st) st = wl_scene_fluid_block(&sc, lo, hi, H, err);
  } else if (t != DAM_3D_BOX_PILLAR) {
    /* the x-z section's walls extruded along y; the planes y = 0 and W are
     * the box's faces */
    const double L = 0.4, T = 0.3;
    cfg->lo[0] = -margin;
    cfg->hi[0] = L + margin;
    cfg->lo[1] = 0.0;
    cfg->hi[1] = W;
    cfg->lo[2] = -margin;
    cfg->hi[2] = 0.6;
    wl_scene_init(&sc, &k, 0.5 * dp, W - 0.5 * dp);
    const double tx[4] = {0, 0, L, L}, tz[4] = {T, 0, 0, T};
    const double flo[3] = {0, 0, 0}, fhi[3] = {0.1, W, H};
    st = wl_scene_boundary_polyline(&sc, tx, tz, 4, DAM_LAYERS, WL_KIND_FIXED, 0, cfg, err);
    if (!st && t == DAM_3D_MIRROR_PILLAR) st = wl_scene_box3d_solid(&sc, plo, phi, DAM_LAYERS, 1, err);
    if (!st) st = wl_scene_fluid_block(&sc, flo, fhi, H, err);
  } else {
    const double tlo[3] = {0, 0, 0}, thi[3] = {0.4, W, 0.3};
    const double flo[3] = {0, 0, 0}, fhi[3] = {0.1, 0.2, H};
    for (int a = 0; a < 3; a++) {
      cfg->lo[a] = tlo[a] - margin;
      cfg->hi[a] = thi[a] + margin;
    }
    cfg->hi[2] = 0.6;
    wl_scene_init(&sc, &k, tlo[1], thi[1]);
    st = wl_scene_box3d_tank(&sc, tlo, thi, DAM_LAYERS, cfg, err);
    if (!st) st = wl_scene_box3d_solid(&sc, plo, phi, DAM_LAYERS, 1, err);
    if (!st) st = wl_scene_fluid_block(&sc, flo, fhi, H, err);
  }
  if (!st) st = wl_scene_build(&sc, p, err);
  wl_scene_clear(&sc);
  for (int j = 0; !st && j < p->n_bound; j++)
    if (p->kind[j] == WL_KIND_FIXED && p->pos[0][j] < 0.0) p->body[j] = (unsigned char)body_wall;
  return st;
}

#endif
