/* sph/integrate.h: the two time integrators of DualSPHysics, per particle,
 * for host and device (params.h wl_sph_integrator picks one).
 *
 * Symplectic position Verlet (Monaghan 2005, Rep. Prog. Phys. 68:1703;
 * Dominguez et al. 2022 eqs. 18-20), two force evaluations a step:
 * predictor (to t + dt/2, forces F^n at the step start):
 *   rho^{n+1/2} = rho^n + dt/2 drho^n/dt,  v^{n+1/2} = v^n + dt/2 a^n,
 *   r^{n+1/2} = r^n + dt/2 v^n
 * corrector (forces F^{n+1/2} at the half step):
 *   v^{n+1} = v^n + dt a^{n+1/2},  r^{n+1} = r^{n+1/2} + dt/2 v^{n+1},
 *   rho^{n+1} = rho^n (2 - eps)/(2 + eps),  eps = -(drho/dt)^{n+1/2} dt / rho^{n+1/2}
 *
 * Verlet (Verlet 1967 in DualSPHysics' form, Dominguez et al. 2022 eqs.
 * 15-17), one force evaluation a step (F^n at the step start):
 *   v^{n+1} = v^{n-1} + (dt' + dt) a^n,  rho^{n+1} = rho^{n-1} + (dt' + dt) drho^n/dt,
 *   r^{n+1} = r^n + dt v^n + dt^2/2 a^n,
 * dt' the previous step (2 dt in DualSPHysics, whose steps are not cut to
 * land on output times; here a step before an output can be much shorter
 * than the one after it, and 2 dt would then kick the velocity by a whole
 * step's acceleration too much or too little: exact for a constant
 * acceleration either way, test_sph_integrate);
 * every verlet_steps-th step, so that the two interleaved solutions of the
 * leapfrog (even and odd steps) cannot drift apart, v and rho take an Euler
 * step instead: v^{n+1} = v^n + dt a^n, rho^{n+1} = rho^n + dt drho^n/dt.
 * The previous step's v and rho live in vel_h and rho_h, which the cell
 * sort then carries with the state (the half-step arrays the symplectic
 * step needs are free in this scheme). Half the force evaluations of the
 * symplectic step at the same dt; what it costs in accuracy is measured in
 * BENCHMARKS.md and reference/RESULTS.md.
 *
 * Boundary particles (dynamic boundary condition) integrate density the same
 * way, clamped to rho >= rho0 as DualSPHysics does (a wall never sucks fluid
 * in); with the wall condition (sph/wall.h) their density rate is 0 and the
 * wall pass sets their density before each force evaluation. A fluid
 * particle's density is not integrated below k->rho_floor (params.h
 * tension_max), and one taken out of the run (guard.h wl_sph_exclude) is
 * left where it is. Fixed ones never move; moving ones (paddle) move with the velocity
 * of their body over the step, v_body = (X(t + dt) - X(t))/dt, which lands
 * them exactly on the prescribed trajectory X(t).
 *
 * Damping zone (DualSPHysics' Damping; Altomare et al. 2017, Coast. Eng.
 * 127:37): after the update, a fluid particle's velocity is multiplied by
 * max(0, 1 - dt rate w^2), w = clamp((x - x0)/(x1 - x0), 0, 1), so waves and
 * overtopping water entering the zone come to rest there instead of
 * reflecting.
 *
 * Particle shifting (sph/shift.h), when on: the update (the corrector, or
 * the Verlet step) adds the step's shift to a fluid particle's position.
 *
 * Mirror planes (sph/params.h): a fluid particle the update carries
 * across one is reflected back, its v_y reversed, as its mirror image
 * would have entered. */
#ifndef WALLLOAD_SPH_INTEGRATE_H
#define WALLLOAD_SPH_INTEGRATE_H

#include "wallload/sph/particles.h"
#include "wallload/sph/params.h"

/* The end of a fluid particle's update, on its new position x, velocity v
 * and previous velocity vh (the Verlet step reads it next), held in the
 * caller's registers: back across a mirror plane, then the damping zones.
 * The update functions below read a particle's values, compute, then
 * store: through the arrays themselves every store could alias the next
 * load, which kept the GPU's update waiting on memory. */
WL_HD static WL_INLINE void wl_sph_fluid_finish(const int dim, const struct wl_sph_const *k,
                                                double dt, double *x, wl_real *v, wl_real *vh) {
  if (dim == 3 && k->mirror) {
    const double y = x[1];
    if (((k->mirror & 1) && y < k->mirror_y[0]) || ((k->mirror & 2) && y > k->mirror_y[1])) {
      x[1] = 2.0 * k->mirror_y[y < k->mirror_y[0] ? 0 : 1] - y;
      v[1] = -v[1];
      vh[1] = -vh[1];
    }
  }
  for (int z = 0; z < WL_SPH_DAMP_ZONES; z++)
    if (k->damp_rate[z] > 0) {
      double w = (x[0] - k->damp_x0[z]) * k->damp_inv_len[z];
      w = w < 0 ? 0 : w > 1 ? 1 : w;
      double f = 1.0 - dt * k->damp_rate[z] * w * w;
      f = f < 0 ? 0 : f;
      for (int a = 0; a < dim; a++) v[a] = (wl_real)(f * (double)v[a]);
    }
}

/* Predictor for particle i: reads the state and the forces at the step start,
 * writes the half-step arrays. body_vel[b][a]: velocity of moving body b
 * [m/s] (row 0 unused); it is also stored as the particle's velocity. */
WL_HD static WL_INLINE void wl_sph_predict(const int dim, const struct wl_sph_const *k,
                                        const struct wl_particles *p, double dt,
                                        const double (*body_vel)[WL_SPH_DIM_MAX], int i) {
  const wl_real hdt = (wl_real)(0.5 * dt);
  const int kind = p->kind[i];
  if (kind == WL_KIND_FLUID && p->body[i] == WL_SPH_BODY_EXCLUDED) { /* at rest (guard.h) */
    p->rho_h[i] = p->rho[i];
    for (int a = 0; a < dim; a++) {
      p->vel_h[a][i] = 0;
      p->pos_h[a][i] = p->pos[a][i];
    }
    return;
  }
  if (kind == WL_KIND_FLUID && p->body[i] == WL_SPH_BODY_BUFFER) { /* particles.h */
    p->rho_h[i] = p->rho[i];
    for (int a = 0; a < dim; a++) {
      p->vel_h[a][i] = p->vel[a][i];
      p->pos_h[a][i] = p->pos[a][i] + 0.5 * dt * (double)p->vel[a][i];
    }
    return;
  }
  if (kind == WL_KIND_FLUID) {
    const wl_real rho = p->rho[i] + hdt * p->ar[i];
    p->rho_h[i] = rho > k->rho_floor ? rho : k->rho_floor; /* params.h tension_max */
    for (int a = 0; a < dim; a++) {
      p->vel_h[a][i] = p->vel[a][i] + hdt * p->ace[a][i];
      p->pos_h[a][i] = p->pos[a][i] + 0.5 * dt * (double)p->vel[a][i];
    }
  } else {
    const wl_real rho = p->rho[i] + hdt * p->ar[i];
    p->rho_h[i] = rho > k->rho0 ? rho : k->rho0;
    for (int a = 0; a < dim; a++) {
      const double v = kind == WL_KIND_MOVING ? body_vel[p->body[i]][a] : 0.0;
      p->vel[a][i] = (wl_real)v;
      p->vel_h[a][i] = (wl_real)v;
      p->pos_h[a][i] = p->pos[a][i] + 0.5 * dt * v;
    }
  }
}

/* Corrector for particle i: reads the step-start state, the half-step
 * arrays and the half-step forces; writes the new state. body_vel as in
 * wl_sph_predict (moving particles advance by exactly v_body dt in double). */
WL_HD static WL_INLINE void wl_sph_correct(const int dim, const struct wl_sph_const *k,
                                           const struct wl_particles *p, double dt,
                                           const double (*body_vel)[WL_SPH_DIM_MAX], int i) {
  if (p->kind[i] == WL_KIND_FLUID && p->body[i] == WL_SPH_BODY_EXCLUDED) return; /* guard.h */
  if (p->kind[i] == WL_KIND_FLUID && p->body[i] == WL_SPH_BODY_BUFFER) { /* particles.h */
    for (int a = 0; a < dim; a++) p->pos[a][i] = p->pos_h[a][i] + 0.5 * dt * (double)p->vel[a][i];
    return;
  }
  const wl_real eps = -(p->ar[i] / p->rho_h[i]) * (wl_real)dt;
  const wl_real rho = p->rho[i] * (WL_R(2.0) - eps) / (WL_R(2.0) + eps);
  if (p->kind[i] == WL_KIND_FLUID) {
    double x[WL_SPH_DIM_MAX];
    wl_real v[WL_SPH_DIM_MAX], vh[WL_SPH_DIM_MAX];
    for (int a = 0; a < dim; a++) {
      v[a] = p->vel[a][i] + (wl_real)dt * p->ace[a][i];
      vh[a] = p->vel_h[a][i];
      x[a] = p->pos_h[a][i] + 0.5 * dt * (double)v[a];
      if (k->shift_coef > 0) x[a] += (double)p->shift[a][i]; /* sph/shift.h */
    }
    wl_sph_fluid_finish(dim, k, dt, x, v, vh);
    p->rho[i] = rho > k->rho_floor ? rho : k->rho_floor;
    for (int a = 0; a < dim; a++) {
      p->vel[a][i] = v[a];
      p->vel_h[a][i] = vh[a];
      p->pos[a][i] = x[a];
    }
  } else {
    p->rho[i] = rho > k->rho0 ? rho : k->rho0;
    if (p->kind[i] == WL_KIND_MOVING)
      for (int a = 0; a < dim; a++) p->pos[a][i] = p->pos_h[a][i] + 0.5 * dt * body_vel[p->body[i]][a];
  }
}

/* Whether step number `step` (0 = the first) of a Verlet run is an Euler
 * step: the first, and every verlet_steps-th after it. */
WL_HD static WL_INLINE int wl_sph_verlet_euler(const struct wl_sph_const *k, long step) {
  return step % k->verlet_steps == 0;
}

/* Verlet step for particle i: reads the state, the previous step's v and
 * rho (vel_h, rho_h) and the forces at the step start; writes the new
 * state and keeps the current v and rho as the previous ones. dt_prev: the
 * previous step. euler != 0: the Euler step that re-couples the leapfrog's
 * even and odd steps. body_vel as in wl_sph_predict. */
WL_HD static WL_INLINE void wl_sph_verlet(const int dim, const struct wl_sph_const *k,
                                          const struct wl_particles *p, double dt, double dt_prev,
                                          const double (*body_vel)[WL_SPH_DIM_MAX], int euler,
                                          int i) {
  if (p->kind[i] == WL_KIND_FLUID && p->body[i] == WL_SPH_BODY_EXCLUDED) return; /* guard.h */
  if (p->kind[i] == WL_KIND_FLUID && p->body[i] == WL_SPH_BODY_BUFFER) { /* particles.h */
    /* moved with its (fitted) velocity; its v and rho are also the previous
     * ones, which the Verlet step reads once it joins the fluid */
    p->rho_h[i] = p->rho[i];
    for (int a = 0; a < dim; a++) {
      p->vel_h[a][i] = p->vel[a][i];
      p->pos[a][i] += dt * (double)p->vel[a][i];
    }
    return;
  }
  const wl_real span = (wl_real)(euler ? dt : dt_prev + dt);
  const wl_real rho_n = p->rho[i];
  const wl_real rho = (euler ? rho_n : p->rho_h[i]) + span * p->ar[i];
  if (p->kind[i] == WL_KIND_FLUID) {
    double x[WL_SPH_DIM_MAX];
    wl_real v[WL_SPH_DIM_MAX], vh[WL_SPH_DIM_MAX];
    for (int a = 0; a < dim; a++) {
      const wl_real v_n = p->vel[a][i], acc = p->ace[a][i];
      v[a] = (euler ? v_n : p->vel_h[a][i]) + span * acc;
      vh[a] = v_n;
      x[a] = p->pos[a][i] + (dt * (double)v_n + 0.5 * dt * dt * (double)acc);
      if (k->shift_coef > 0) x[a] += (double)p->shift[a][i]; /* sph/shift.h */
    }
    wl_sph_fluid_finish(dim, k, dt, x, v, vh);
    p->rho_h[i] = rho_n;
    p->rho[i] = rho > k->rho_floor ? rho : k->rho_floor;
    for (int a = 0; a < dim; a++) {
      p->vel[a][i] = v[a];
      p->vel_h[a][i] = vh[a];
      p->pos[a][i] = x[a];
    }
  } else {
    p->rho_h[i] = rho_n;
    p->rho[i] = rho > k->rho0 ? rho : k->rho0;
    for (int a = 0; a < dim; a++) {
      const double v = p->kind[i] == WL_KIND_MOVING ? body_vel[p->body[i]][a] : 0.0;
      p->pos[a][i] += dt * v;
      p->vel[a][i] = (wl_real)v;
      p->vel_h[a][i] = (wl_real)v;
    }
  }
}

#endif
