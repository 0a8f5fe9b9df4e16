/* sections_scene.c: the scene section (the flume to scale: the bed's
 * corners, the seawall and the land behind it, still water, gauges, the
 * initial solitary wave or crater, all as results.h5's /plan holds them;
 * and the table of derived initial conditions with each formula's source,
 * as `wallload check` prints them in wl_plan_write) and
 * the snapshots section (particles near the wall coloured by pressure,
 * speed or density at chosen times, read from particles_<case>.h5). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sections.h"
#include "wallload/units.h"
#include "wallload/waves.h"

#define SCENE_MIN_H 40.0     /* a flume drawn lower than this at true scale [pt] is exaggerated */
#define SCENE_TARGET_H 110.0 /* its height aimed at when exaggerating automatically [pt] */
#define CLOSE_DEPTHS 8.0     /* the close-up reaches this many depths seaward of the wall */
#define SNAP_DEPTHS 5.0      /* snapshot window: depths seaward of the wall */
#define SNAP_LAND 0.25       /* ... and this share of its width landward */
#define IC_ROWS 48

/* ---- flume geometry ------------------------------------------------------------------ */

struct geom {
  int from_plan;    /* 1: bed, gauges and initial surfaces from /plan */
  double x0, x_end; /* flume start and end of the land drawn [m] */
  double h;         /* still-water level above the floor [m] */
  double xw, toe, crest;
};

static int first_case(const struct wl_results *r) {
  for (int i = 0; i < WL_RESULTS_N_CASES; i++)
    if (r->cases[i].present)
      return i;
  return -1;
}

/* 0 when there is nothing to draw the flume from. */
static int geometry(const struct wl_results *r, struct geom *g) {
  int fc = first_case(r);
  const struct wl_results_case *k = fc >= 0 ? &r->cases[fc] : NULL;
  memset(g, 0, sizeof *g);
  if (r->plan.present) {
    const struct wl_results_plan *pl = &r->plan;
    g->from_plan = 1;
    g->x0 = 0.0;
    g->xw = pl->wall_x;
    g->h = pl->depth;
    g->toe = pl->wall_toe_z;
    g->crest = pl->wall_crest_z;
    if (k && isfinite(k->wall_crest_z))
      g->crest = k->wall_crest_z;
    g->x_end = g->xw + (pl->land_length > 0 ? pl->land_length : 0.1 * g->xw);
    return 1;
  }
  if (!k || !isfinite(k->wall_x) || !isfinite(k->still_water_z))
    return 0;
  g->xw = k->wall_x;
  g->h = k->still_water_z;
  g->toe = isfinite(k->wall_toe_z) ? k->wall_toe_z : 0.0;
  g->crest = isfinite(k->wall_crest_z) ? k->wall_crest_z : g->toe + g->h;
  g->x0 = g->xw - 10.0 * fmax(g->h, g->crest);
  g->x_end = g->xw + 2.0 * fmax(g->h, g->crest);
  return 1;
}

/* Polygons and lines of the flume. */
struct scene_parts {
  struct wl_report_shape shapes[8];
  int n_shapes;
  struct wl_report_mark marks[WL_RESULTS_MAX_GAUGES + 4];
  int n_marks;
  double bx[WL_RESULTS_MAX_BED + 2], bz[WL_RESULTS_MAX_BED + 2];
  double wx[4], wz[4], lx[4], lz[4];
  char notes[512];
};

static void add_shape(struct scene_parts *p, enum wl_report_shape_kind kind, const double *x,
                      const double *z, size_t n) {
  if (p->n_shapes < (int)(sizeof p->shapes / sizeof p->shapes[0]))
    p->shapes[p->n_shapes++] = (struct wl_report_shape){kind, x, z, n};
}

static void add_mark(struct scene_parts *p, double x, double z, const char *label) {
  if (p->n_marks < (int)(sizeof p->marks / sizeof p->marks[0]))
    p->marks[p->n_marks++] = (struct wl_report_mark){x, z, label};
}

static void build_scene(const struct wl_results *r, const struct geom *g,
                        struct scene_parts *p) {
  memset(p, 0, sizeof *p);
  /* still water first, the bed painted over it */
  p->wx[0] = g->x0, p->wz[0] = 0.0;
  p->wx[1] = g->xw, p->wz[1] = 0.0;
  p->wx[2] = g->xw, p->wz[2] = g->h;
  p->wx[3] = g->x0, p->wz[3] = g->h;
  add_shape(p, WL_REPORT_SHAPE_WATER, p->wx, p->wz, 4);
  const struct wl_results_plan *pl = &r->plan;
  int n = 0;
  if (g->from_plan) {
    for (size_t i = 0; i < pl->n_bed; i++)
      p->bx[n] = pl->bed_x[i], p->bz[n++] = pl->bed_z[i];
  } else { /* flat at the wall's toe */
    p->bx[n] = g->x0, p->bz[n++] = g->toe;
    p->bx[n] = g->xw, p->bz[n++] = g->toe;
  }
  p->bx[n] = g->xw, p->bz[n++] = 0.0;
  p->bx[n] = g->x0, p->bz[n++] = 0.0;
  add_shape(p, WL_REPORT_SHAPE_BED, p->bx, p->bz, (size_t)n);
  p->lx[0] = g->xw, p->lz[0] = 0.0;
  p->lx[1] = g->xw, p->lz[1] = g->crest;
  p->lx[2] = g->x_end, p->lz[2] = g->crest;
  p->lx[3] = g->x_end, p->lz[3] = 0.0;
  add_shape(p, WL_REPORT_SHAPE_WALL, p->lx, p->lz, 4);

  if (g->from_plan) {
    const struct wl_results_solitary *ps = &pl->solitary;
    const struct wl_results_explosion *px = &pl->explosion;
    if (ps->present && ps->n_surface) {
      add_shape(p, WL_REPORT_SHAPE_LINE, ps->surface_x, ps->surface_z, ps->n_surface);
      add_mark(p, ps->crest_x0, g->h + ps->H, "crest");
    }
    if (ps->present && ps->paddle)
      add_mark(p, 0.0, g->h, "paddle");
    if (px->present && px->n_surface) {
      add_shape(p, WL_REPORT_SHAPE_LINE, px->surface_x, px->surface_z, px->n_surface);
      add_mark(p, px->x_center, g->h, "crater");
    }
    for (int i = 0; i < pl->n_gauges; i++)
      add_mark(p, pl->gauge_x[i], g->h, pl->gauge_name[i]);
  }
  add_mark(p, g->xw, g->crest, "wall");
}

/* 1-2-5 number at or below v (>= 1). */
static double nice_down(double v) {
  if (!(v > 1.0))
    return 1.0;
  double p = pow(10.0, floor(log10(v))), m = v / p;
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p;
}

static enum wl_status draw_scene(struct wl_report_doc *d, struct wl_report_scene *sc,
                                 const char *caption, struct wl_error *err) {
  struct wl_report_rect cw = wl_report_doc_content(d), area;
  double h = wl_report_scene_fit_height(sc, cw.w);
  enum wl_status st = wl_report_begin_figure(d, h, &area, err);
  if (!st)
    st = wl_report_draw_scene(d, sc, area, err);
  if (!st)
    st = wl_report_end_figure(d, caption, err);
  return st;
}

/* ---- derived initial conditions ----------------------------------------------------- */

struct ic_table {
  struct wl_report_cell cells[IC_ROWS * 4];
  char text[IC_ROWS][3][160];
  int n;
};

static void ic_row(struct ic_table *t, const char *quantity, double value, const char *vtext,
                   const char *unit, const char *source) {
  if (t->n >= IC_ROWS)
    return;
  int i = t->n++;
  snprintf(t->text[i][0], sizeof t->text[i][0], "%s", quantity);
  snprintf(t->text[i][1], sizeof t->text[i][1], "%s", vtext ? vtext : "");
  snprintf(t->text[i][2], sizeof t->text[i][2], "%s", source ? source : "");
  struct wl_report_cell *c = &t->cells[4 * i];
  c[0] = (struct wl_report_cell){t->text[i][0], 0};
  c[1] = (struct wl_report_cell){vtext ? t->text[i][1] : NULL, value};
  c[2] = (struct wl_report_cell){unit ? unit : "", 0};
  c[3] = (struct wl_report_cell){t->text[i][2], 0};
}

/* The theory a solitary wave was stored with (its name,
 * wl_waves_solitary_theory_text); -1 when this version does not know it. */
static int solitary_theory(const char *name) {
  static const enum wl_solitary_theory all[] = {WL_SOLITARY_BOUSSINESQ, WL_SOLITARY_GRIMSHAW,
                                                WL_SOLITARY_EXACT};
  for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
    if (!strcmp(name, wl_waves_solitary_theory_text(all[i], 0)))
      return (int)all[i];
  return -1;
}

static enum wl_status initial_conditions(struct wl_report_ctx *c, struct wl_error *err) {
  const struct wl_results *r = c->res;
  struct wl_report_doc *d = c->doc;
  if (!r->plan.present)
    return wl_report_paragraphf(d, err, "The derived initial conditions are not shown: %s.",
                                WL_REPORT_NO_PLAN);
  const struct wl_results_plan *p = &r->plan;
  struct ic_table *t = calloc(1, sizeof *t);
  if (!t)
    return wl_error_set(err, WL_ENOMEM, "report: no memory for a table");
  char src[160];
  ic_row(t, "still-water depth h", p->depth, NULL, "m", "scenario water.depth");
  if (p->solitary.present) {
    const struct wl_results_solitary *ps = &p->solitary;
    const int theory = solitary_theory(ps->theory);
    ic_row(t, "solitary wave: theory", 0, ps->theory, NULL,
           theory < 0 ? "" : wl_waves_solitary_theory_text((enum wl_solitary_theory)theory, 1));
    ic_row(t, "  height H", ps->H, NULL, "m", "scenario loads.solitary.height");
    ic_row(t, "  H/h", ps->H / p->depth, NULL, "", "valid to 0.78 (3rd order to ~0.5)");
    ic_row(t, "  celerity c", ps->celerity, NULL, "m/s",
           theory == WL_SOLITARY_GRIMSHAW ? "seed 003 eq 23"
           : theory == WL_SOLITARY_EXACT  ? "exact: F sqrt(g h)"
                                          : "sqrt(g (h + H))");
    ic_row(t, "  energy (integrated)", ps->energy_integrated, NULL, "J/m",
           "quadrature of the wave's field");
    ic_row(t, "  energy, first order", ps->energy_first_order, NULL, "J/m", "KdV closed form");
    ic_row(t, "  energy 0.958 rho g h^3", ps->energy_seed001, NULL, "J/m",
           "highest wave on h; seed 001 eq 22");
    if (ps->paddle) {
      ic_row(t, "  paddle stroke", ps->paddle_stroke, NULL, "m", "Goring (1978) piston paddle");
      ic_row(t, "  paddle moves for", ps->paddle_duration, NULL, "s", "Goring (1978)");
    } else {
      ic_row(t, "  initial crest at x", ps->crest_x0, NULL, "m", "initial condition (plan)");
    }
    ic_row(t, "  crest at the wall", ps->arrival_time, NULL, "s", "plan estimate");
  }
  if (p->explosion.present) {
    const struct wl_results_explosion *px = &p->explosion;
    if (px->sized_to_solitary)
      snprintf(src, sizeof src, "%s basis: %.5g %s", px->basis, px->matched_energy,
               !strcmp(px->basis, "per-width") && p->dims == 2 ? "J/m" : "J");
    else
      snprintf(src, sizeof src, "scenario loads.explosion");
    ic_row(t, "explosion: from the", 0, px->source, NULL, src);
    ic_row(t, "  charge W", px->charge, NULL, "kg", "TNT; Van Dorn / Whalin chain");
    ic_row(t, "  charge W", px->charge / WL_LB_KG, NULL, "lb", "TNT (1 lb = 0.45359237 kg)");
    ic_row(t, "  crater radius R0", px->chain_r0, NULL, "m",
           "Van Dorn R0 = 9.6 W^0.3; seed 001 eq 4");
    snprintf(src, sizeof src, "Whalin / Le Mehaute, C = %g; seed 001 eq 6/7", px->whalin_coef);
    ic_row(t, "  Hmax r", px->hr, NULL, "m^2", src);
    ic_row(t, "  crater depth eta0", px->chain_eta0, NULL, "m",
           "eta0 R0 = 0.81 Hmax r; seed 001 eq 5");
    ic_row(t, "  crater energy, 3D", px->crater_energy, NULL, "J",
           "pi rho g eta0^2 R0^2/6; seed 001 eq 3");
    ic_row(t, "  chemical energy", px->chemical_energy, NULL, "J", "4.184 MJ/kg TNT");
    snprintf(src, sizeof src, "ceiling %.0f %%: seed 000 eq 9", 100.0 * px->wave_fraction);
    ic_row(t, "  crater / chemical energy", 100.0 * px->chain_wave_fraction, NULL, "%", src);
    ic_row(t, "  simulated shape", 0, px->shape, NULL, "seed 000 eqs 1-3, seed 001 eq 1");
    ic_row(t, "  simulated eta0", px->eta0, NULL, "m", "as simulated");
    ic_row(t, "  simulated R0", px->r0, NULL, "m", "as simulated");
    ic_row(t, "  crater centre x", px->x_center, NULL, "m", "scenario loads.explosion.at");
    snprintf(src, sizeof src, "closed form; quadrature of seed 000 eq 4: %.6g", px->energy_quad);
    ic_row(t, "  crater energy as simulated", px->energy, NULL, p->dims == 2 ? "J/m" : "J", src);
    snprintf(src, sizeof src, "net %+.4g %s", px->net_volume, p->dims == 2 ? "m^2/m" : "m^3");
    ic_row(t, "  conserves mass", 0, px->conserves_mass ? "yes" : "NO", NULL, src);
    if (px->sized_to_solitary && p->solitary.present) {
      ic_row(t, "  equal-energy solitary H", p->solitary.H, NULL, "m",
             "the solitary case, by construction");
    } else if (p->dims == 2) {
      double H = 0;
      struct wl_error e;
      wl_error_clear(&e);
      if (wl_waves_solitary_height_from_energy(px->energy, p->depth, p->g, p->rho, &H, &e) ==
          WL_OK)
        ic_row(t, "  equal-energy solitary H", H, NULL, "m", "Grimshaw wave of this energy per m");
      else
        ic_row(t, "  equal-energy solitary H", 0, "out of range", NULL,
               "no solitary wave holds this energy");
    }
    ic_row(t, "  leading wave at the wall", px->arrival_time, NULL, "s", "plan estimate");
  }
  static const struct wl_report_column cols[] = {
      {"quantity", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"value", NULL, WL_REPORT_ALIGN_AUTO, 4},
      {"unit", NULL, WL_REPORT_ALIGN_LEFT, 0},
      {"source", NULL, WL_REPORT_ALIGN_LEFT, 0},
  };
  struct wl_report_table tab = {"Derived initial conditions and their sources (as wallload check "
                                "prints them)",
                                cols, 4, t->cells, t->n};
  enum wl_status st = wl_report_add_table(d, &tab, err);
  free(t);
  return st;
}

enum wl_status wl_report_render_scene(struct wl_report_ctx *c, const struct wl_report_section *s,
                                      struct wl_error *err) {
  const struct wl_results *r = c->res;
  struct wl_report_doc *d = c->doc;
  enum wl_status st = wl_report_section_begin(c, s, err);
  struct geom g;
  if (!geometry(r, &g)) {
    if (!st)
      st = wl_report_paragraphf(d, err,
                                "The flume cannot be drawn: the results hold neither a plan "
                                "(%s) nor a load case with the wall's position.",
                                WL_REPORT_NO_PLAN);
    return st;
  }
  struct scene_parts *p = calloc(1, sizeof *p);
  if (!p)
    return wl_error_set(err, WL_ENOMEM, "report: no memory for the scene");
  build_scene(r, &g, p);
  char cap[1024], extra[600] = "";
  if (!g.from_plan)
    snprintf(extra, sizeof extra,
             " The bathymetry is not available (%s); the bed is drawn flat "
             "at the wall's toe.",
             WL_REPORT_NO_PLAN);
  else {
    size_t used = 0;
    for (int i = 0; i < WL_RESULTS_N_CASES; i++) {
      double xl = i == 0 ? r->plan.solitary.x_left : r->plan.explosion.x_left;
      int present = i == 0 ? r->plan.solitary.present : r->plan.explosion.present;
      if (present && xl > 0 && used < sizeof extra)
        used += (size_t)snprintf(extra + used, sizeof extra - used,
                                 " The %s case models the flume from x = %.4g m.",
                                 wl_store_results_case_name(i), xl);
    }
  }
  struct wl_report_scene scene = {NULL,     p->shapes,      p->n_shapes,
                                  p->marks, p->n_marks,     {"x", "m", 0, 0, 0, 0},
                                  1,        s->exaggeration};
  if (s->has_x_range) {
    scene.x_axis.fixed = 1;
    scene.x_axis.min = s->x_range[0];
    scene.x_axis.max = s->x_range[1];
  }
  struct wl_report_rect cw = wl_report_doc_content(d);
  double e = s->exaggeration > 0 ? s->exaggeration : 1.0;
  scene.exaggeration = e;
  /* the drawing's own height at true scale: what doubling the exaggeration adds */
  double h1 = wl_report_scene_fit_height(&scene, cw.w);
  scene.exaggeration = 2.0 * e;
  double dh = (wl_report_scene_fit_height(&scene, cw.w) - h1) / e;
  scene.exaggeration = e;
  int auto_exag = 0;
  if (e == 1.0 && dh > 0 && dh < SCENE_MIN_H) {
    scene.exaggeration = nice_down(SCENE_TARGET_H / dh);
    auto_exag = scene.exaggeration > 1.0;
  }
  if (auto_exag)
    snprintf(cap, sizeof cap,
             "The flume: bed, still water (%.4g m deep), seawall and land, gauges and the initial "
             "free surface of each load case, with vertical exaggeration %g (at true scale the "
             "flume would be %.1f mm high on the page).%s",
             g.h, scene.exaggeration, dh / WL_REPORT_PT_PER_MM, extra);
  else
    snprintf(cap, sizeof cap,
             "The flume: bed, still water (%.4g m deep), seawall and land, gauges and the initial "
             "free surface of each load case%s.%s",
             g.h, e == 1.0 ? ", to scale" : "", extra);
  if (!st)
    st = draw_scene(d, &scene, cap, err);
  if (!st && !s->has_x_range && (auto_exag || e != 1.0)) {
    struct wl_report_scene close = scene;
    close.exaggeration = 1.0;
    close.x_axis.fixed = 1;
    close.x_axis.min = fmax(g.x0, g.xw - CLOSE_DEPTHS * fmax(g.h, g.crest));
    close.x_axis.max = g.x_end;
    snprintf(cap, sizeof cap,
             "Near the wall, true scale: toe at z = %.4g m, crest at z = %.4g m (%.4g m above "
             "still water).",
             g.toe, g.crest, g.crest - g.h);
    st = draw_scene(d, &close, cap, err);
  }
  if (!st)
    st = initial_conditions(c, err);
  free(p);
  return st;
}

/* ---- snapshots ------------------------------------------------------------------------ */

/* Index of the snapshot nearest t. */
static size_t nearest(const struct wl_results_snapshot_ref *refs, size_t n, double t) {
  size_t best = 0;
  for (size_t i = 1; i < n; i++)
    if (fabs(refs[i].time - t) < fabs(refs[best].time - t))
      best = i;
  return best;
}

static int cmp_size(const void *a, const void *b) {
  size_t x = *(const size_t *)a, y = *(const size_t *)b;
  return x < y ? -1 : x > y;
}

static enum wl_status snapshots_case(struct wl_report_ctx *c, const struct wl_report_section *s,
                                     int ci, struct wl_error *err) {
  const struct wl_results *r = c->res;
  const struct wl_results_case *k = &r->cases[ci];
  struct wl_report_doc *d = c->doc;
  char path[1200];
  snprintf(path, sizeof path, "%s/particles_%s.h5", r->dir, k->name);
  struct wl_results_snapshot_ref *refs = NULL;
  size_t n_refs = 0;
  struct wl_error e;
  wl_error_clear(&e);
  enum wl_status st = wl_store_snapshot_list(path, &refs, &n_refs, &e);
  if (st == WL_ENOMEM)
    return wl_error_set(err, st, "%s", e.msg);
  if (st || n_refs == 0) {
    free(refs);
    return wl_report_paragraphf(d, err, "No particle snapshots of the %s case: %s.", k->name,
                                st ? e.msg : "the snapshot file holds none");
  }
  /* times: the template's, or around the peak force */
  double want[WL_REPORT_MAX_TIMES];
  int n_want = 0;
  if (s->n_times > 0) {
    for (int i = 0; i < s->n_times; i++)
      want[n_want++] = s->times[i];
  } else if (isfinite(k->force_peak.time)) {
    double tp = k->force_peak.time;
    if (isfinite(k->force_peak.rise_time) && k->force_peak.rise_time > 0)
      want[n_want++] = tp - k->force_peak.rise_time;
    want[n_want++] = tp;
    if (isfinite(k->force_peak.duration) && k->force_peak.duration > 0)
      want[n_want++] = tp + 0.5 * k->force_peak.duration;
  } else {
    double te = refs[n_refs - 1].time;
    want[n_want++] = te / 3, want[n_want++] = 2 * te / 3, want[n_want++] = te;
  }
  size_t pick[WL_REPORT_MAX_TIMES];
  int n_pick = 0;
  for (int i = 0; i < n_want; i++)
    pick[n_pick++] = nearest(refs, n_refs, want[i]);
  qsort(pick, (size_t)n_pick, sizeof pick[0], cmp_size);
  int m = 0;
  for (int i = 0; i < n_pick; i++)
    if (m == 0 || pick[i] != pick[m - 1])
      pick[m++] = pick[i];
  n_pick = m;
  size_t peak_snap =
      isfinite(k->force_peak.time) ? nearest(refs, n_refs, k->force_peak.time) : (size_t)-1;

  /* window near the wall */
  double depth = isfinite(k->still_water_z) ? k->still_water_z : 1.0;
  double xw = isfinite(k->wall_x) ? k->wall_x : 0.0;
  double x0 = xw - SNAP_DEPTHS * depth, x1 = xw + SNAP_LAND * SNAP_DEPTHS * depth;
  if (s->has_x_range)
    x0 = s->x_range[0], x1 = s->x_range[1];

  enum wl_results_quantity q = s->field == WL_REPORT_FIELD_VELOCITY  ? WL_RESULTS_Q_SPEED
                              : s->field == WL_REPORT_FIELD_DENSITY ? WL_RESULTS_Q_DENSITY
                                                                    : WL_RESULTS_Q_PRESSURE;
  double scale = q == WL_RESULTS_Q_PRESSURE ? KILO : 1.0;
  const char *qlabel = q == WL_RESULTS_Q_PRESSURE ? "pressure"
                       : q == WL_RESULTS_Q_SPEED  ? "speed"
                                                 : "density";
  const char *qunit = q == WL_RESULTS_Q_PRESSURE ? "kPa" : q == WL_RESULTS_Q_SPEED ? "m/s" : "kg/m^3";

  /* read the chosen snapshots; one colour range for the case */
  double *xs[WL_REPORT_MAX_TIMES] = {0}, *zs[WL_REPORT_MAX_TIMES] = {0},
         *vs[WL_REPORT_MAX_TIMES] = {0};
  int *kinds[WL_REPORT_MAX_TIMES] = {0};
  size_t ns[WL_REPORT_MAX_TIMES] = {0};
  double vmin = INFINITY, vmax = -INFINITY;
  char bad[WL_ERROR_MSG_MAX] = "";
  for (int i = 0; i < n_pick; i++) {
    wl_error_clear(&e);
    enum wl_status rs = wl_store_snapshot_read(path, refs[pick[i]].group, q, &xs[i], &zs[i],
                                                &vs[i], &kinds[i], &ns[i], &e);
    if (rs == WL_ENOMEM) {
      st = wl_error_set(err, rs, "%s", e.msg);
      break;
    }
    if (rs) {
      snprintf(bad, sizeof bad, "%s", e.msg);
      continue;
    }
    for (size_t j = 0; j < ns[i]; j++) {
      if (kinds[i][j] != 0) {
        vs[i][j] = NAN; /* walls, bed and paddle in grey */
        continue;
      }
      vs[i][j] /= scale;
      if (xs[i][j] < x0 || xs[i][j] > x1 || !isfinite(vs[i][j]))
        continue;
      vmin = fmin(vmin, vs[i][j]), vmax = fmax(vmax, vs[i][j]);
    }
  }
  for (int i = 0; !st && i < n_pick; i++) {
    if (!xs[i])
      continue;
    char title[160];
    snprintf(title, sizeof title, "%s, t = %.3f s%s", k->name, refs[pick[i]].time,
             pick[i] == peak_snap ? " (nearest the peak force)" : "");
    struct wl_report_field f = {title,
                                xs[i],
                                zs[i],
                                vs[i],
                                ns[i],
                                isfinite(k->dp) ? 0.5 * k->dp : 0.0,
                                {"x", "m", 0, 1, x0, x1},
                                {"z", "m", 0, 0, 0, 0},
                                qlabel,
                                qunit,
                                vmin < vmax,
                                vmin,
                                vmax};
    struct wl_report_rect cw = wl_report_doc_content(d), area;
    double h = wl_report_field_fit_height(&f, cw.w);
    char cap[512];
    snprintf(cap, sizeof cap,
             "The %s case at t = %.3f s (snapshot nearest %s): fluid particles coloured by %s, "
             "walls and bed grey; peak force at t = %.3f s.",
             k->name, refs[pick[i]].time, s->n_times ? "the requested time" : "the chosen time",
             qlabel, k->force_peak.time);
    st = wl_report_begin_figure(d, h, &area, err);
    if (!st)
      st = wl_report_draw_field(d, &f, area, err);
    if (!st)
      st = wl_report_end_figure(d, cap, err);
  }
  if (!st && s->n_times > 0) {
    char list[512] = "";
    size_t used = 0;
    for (int i = 0; i < s->n_times && used < sizeof list; i++)
      used += (size_t)snprintf(list + used, sizeof list - used, "%s%.3f s (nearest %.3f s)",
                               i ? ", " : "", s->times[i],
                               refs[nearest(refs, n_refs, s->times[i])].time);
    st = wl_report_paragraphf(d, err,
                              "Requested times and the %s snapshots nearest them (%zu stored, "
                              "%.3f s to %.3f s): %s.",
                              k->name, n_refs, refs[0].time, refs[n_refs - 1].time, list);
  }
  if (!st && bad[0])
    st = wl_report_paragraphf(d, err, "A snapshot of the %s case could not be read: %s.", k->name,
                              bad);
  for (int i = 0; i < n_pick; i++)
    free(xs[i]), free(zs[i]), free(vs[i]), free(kinds[i]);
  free(refs);
  return st;
}

enum wl_status wl_report_render_snapshots(struct wl_report_ctx *c,
                                          const struct wl_report_section *s, struct wl_error *err) {
  const struct wl_results *r = c->res;
  enum wl_status st = wl_report_section_begin(c, s, err);
  for (int i = 0; !st && i < WL_RESULTS_N_CASES; i++) {
    if (!r->cases[i].present) {
      st = wl_report_paragraphf(c->doc, err, "The %s case is not in the results: no snapshots.",
                                wl_store_results_case_name(i));
      continue;
    }
    st = wl_report_add_heading(c->doc, 2, wl_report_case_label(i), err);
    if (!st)
      st = snapshots_case(c, s, i, err);
  }
  return st;
}
