/* sph/particles.h: the particle state as a structure of arrays, one view of
 * raw pointers used by host and device code alike, and the field table that
 * drives allocation, sorting by cell, host/device copies and output.
 *
 * Order: boundary particles first (indices [0, n_bound)), then fluid
 * ([n_bound, n)); each group is sorted by cell at every rebuild, so memory
 * order follows space and the neighbours of a cell row are one contiguous
 * index range per group. Fixed and moving boundary particles share the
 * boundary group (their kind and body tell them apart). A new field is one
 * member here and one row in the table (src/sph/particles.c). */
#ifndef WALLLOAD_SPH_PARTICLES_H
#define WALLLOAD_SPH_PARTICLES_H

#include "wallload/sph/defs.h"

/* Particle kinds (the kind field). */
enum wl_particle_kind {
  WL_KIND_FLUID = 0,
  WL_KIND_FIXED = 1,  /* fixed boundary (bed, walls) */
  WL_KIND_MOVING = 2, /* moving boundary, prescribed motion of its body (paddle) */
};

/* The body number of a fluid particle taken out of the run (sph/guard.h
 * wl_sph_exclude): it left the domain box, and now rests where it left it;
 * the integrators and the guard leave it alone. */
#define WL_SPH_BODY_EXCLUDED 255

/* The body number of a fluid particle in a buffer band of a variable-
 * resolution run (include/wallload/vres.h): a fluid neighbour in every
 * pair, but its density and velocity are interpolated from the other
 * resolution's fluid after each step, so the integrators only move it with
 * its velocity (DualSPHysics 5.4's VRes buffers). */
#define WL_SPH_BODY_BUFFER 254

/* A particle's place in a zone (backend.h zone_download): 1 in it (its x in
 * [lo, hi]), 2 parked beyond it (a candidate for revival), 0 neither. */
static inline WL_HD int wl_sph_zone_flag(double x, unsigned char kind, unsigned char body,
                                         double lo, double hi) {
  if (x >= lo && x <= hi) return 1;
  return kind == WL_KIND_FLUID && body == WL_SPH_BODY_EXCLUDED ? 2 : 0;
}

struct wl_particles {
  int dim;      /* 2: components (x, z); 3: (x, y, z) */
  int n;        /* particles in use */
  int n_bound;  /* boundary particles, stored first */
  int capacity; /* particles allocated */
  /* state: sorted at rebuilds, written to output */
  double *pos[WL_SPH_DIM_MAX];  /* position [m] */
  wl_real *vel[WL_SPH_DIM_MAX]; /* velocity [m/s] */
  wl_real *rho;                 /* density [kg/m^3] */
  unsigned int *id;             /* particle number at creation, kept through sorting */
  unsigned char *kind;          /* enum wl_particle_kind */
  unsigned char *body;          /* moving body 1..WL_SPH_BODIES_MAX, 0 otherwise */
  /* work arrays of one step: not output, and not sorted (rewritten each step),
   * except vel_h and rho_h under Verlet, which hold the previous step */
  double *pos_h[WL_SPH_DIM_MAX];  /* half-step (predictor) position [m] */
  wl_real *vel_h[WL_SPH_DIM_MAX]; /* half-step velocity [m/s]; Verlet: the previous step's
                                     velocity, which the backend's sort carries along */
  wl_real *rho_h;                 /* half-step density [kg/m^3]; Verlet: the previous
                                     step's density (sorted along, as vel_h) */
  wl_real *press;                 /* pressure of the last force evaluation [Pa] */
  wl_real *ace[WL_SPH_DIM_MAX];   /* acceleration incl. gravity [m/s^2] */
  wl_real *ar;                    /* density rate d(rho)/dt [kg/m^3/s] */
  wl_real *visc;                  /* max_j h|v_ij.r_ij|/(r^2+eta^2) of particle i [m/s] */
  wl_real *shift[WL_SPH_DIM_MAX]; /* particle shifting of this step [m] (sph/shift.h) */
  unsigned int *key;              /* sort key: group * n_cells + cell */
  unsigned int *perm;             /* sorted position -> previous index */
};

/* Field element types. */
enum wl_field_type { WL_FIELD_F64 = 0, WL_FIELD_REAL = 1, WL_FIELD_U32 = 2, WL_FIELD_U8 = 3 };

/* Field flags. */
enum {
  WL_FIELD_VECTOR = 1, /* dim components (pos[0..dim-1]); else one array */
  WL_FIELD_SORT = 2,   /* permuted at cell rebuilds (state) */
  WL_FIELD_OUTPUT = 4, /* written to snapshots */
  WL_FIELD_WORK = 8,   /* per-step scratch */
};

/* One row of the field table. */
struct wl_field_desc {
  const char *name;        /* also the allocation label and the HDF5 dataset name */
  const char *unit;        /* SI unit, "1" for dimensionless, "" for codes */
  enum wl_field_type type;
  int flags;               /* WL_FIELD_* */
  unsigned long offset;    /* offsetof(struct wl_particles, member) of the pointer (array) */
  const char *description;
};

#endif
