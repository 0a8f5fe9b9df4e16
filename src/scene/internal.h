/* internal.h: what the scene module's files share and nobody else uses. */
#ifndef WALLLOAD_SCENE_INTERNAL_H
#define WALLLOAD_SCENE_INTERNAL_H

#include "wallload/scene.h"

/* Append one particle at x[0..dim-1] [m], at rest, with density rho
 * [kg/m^3], kind and body, to group g (0 boundary, 1 fluid), growing the
 * lists by doubling. WL_ENOMEM (naming the group and the size) when they
 * cannot grow; the scene is unchanged then. */
enum wl_status wl_scene_push(struct wl_scene *sc, int g, const double *x, double rho, int kind,
                             int body, struct wl_error *err);

#endif
