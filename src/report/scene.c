/* scene.c: a to-scale sketch of the flume: polygons for water, bed and wall,
 * polylines, labelled marks for gauges and probes, a scale bar, optionally
 * an x axis. True aspect unless a vertical exaggeration is asked for (and
 * then printed under the drawing). Fills differ in lightness, so they read
 * in greyscale print. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "doc.h"

#define SCENE_PAD 4.0       /* left and right [pt] */
#define MARK_ROOM 13.0      /* above the drawing, for mark labels [pt] */
#define MARK_SIZE 3.0       /* half-width of a mark's triangle [pt] */
#define AXES_BAND 26.0      /* x axis ticks, labels and title [pt] */
#define SCALE_BAND 28.0     /* scale bar and its labels [pt] */
#define SCALE_BAR_H 3.5     /* bar thickness [pt] */
#define SCALE_FRACTION 0.25 /* bar length at most this fraction of the width */

struct scene_layout {
  double x0, x1, z0, z1; /* data window [m] */
  double e;              /* vertical exaggeration */
  double scale;          /* page points per metre, horizontally */
  struct wl_report_rect data;
  double height;
};

static void scene_layout(const struct wl_report_scene *s, struct wl_report_rect r,
                         struct scene_layout *l) {
  double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
  for (int k = 0; s->shapes && k < s->n_shapes; k++) {
    const struct wl_report_shape *sh = &s->shapes[k];
    for (size_t i = 0; sh->x && sh->z && i < sh->n; i++) {
      if (!isfinite(sh->x[i]) || !isfinite(sh->z[i])) continue;
      x0 = fmin(x0, sh->x[i]), x1 = fmax(x1, sh->x[i]);
      z0 = fmin(z0, sh->z[i]), z1 = fmax(z1, sh->z[i]);
    }
  }
  for (int k = 0; s->marks && k < s->n_marks; k++) {
    if (!isfinite(s->marks[k].x) || !isfinite(s->marks[k].z)) continue;
    x0 = fmin(x0, s->marks[k].x), x1 = fmax(x1, s->marks[k].x);
    z0 = fmin(z0, s->marks[k].z), z1 = fmax(z1, s->marks[k].z);
  }
  if (!(x0 <= x1)) x0 = 0.0, x1 = 1.0, z0 = 0.0, z1 = 1.0;
  if (s->x_axis.fixed) x0 = s->x_axis.min, x1 = s->x_axis.max;
  if (!(x1 - x0 > 0)) x0 -= 0.5, x1 += 0.5;
  if (!(z1 - z0 > 0)) z0 -= 0.05 * (x1 - x0), z1 += 0.05 * (x1 - x0);
  l->x0 = x0, l->x1 = x1, l->z0 = z0, l->z1 = z1;
  l->e = s->exaggeration > 0 ? s->exaggeration : 1.0;
  double top = r.y + (s->title && *s->title ? SIZE_SMALL + 6.0 : 2.0) +
               (s->n_marks > 0 ? MARK_ROOM : 0.0);
  double bottom = SCALE_BAND + (s->axes ? AXES_BAND : 0.0);
  double avail_w = r.w - 2.0 * SCENE_PAD, avail_h = r.y + r.h - bottom - top;
  l->scale = fmin(avail_w / (x1 - x0), avail_h / ((z1 - z0) * l->e));
  struct wl_report_rect data = {r.x + SCENE_PAD, top, (x1 - x0) * l->scale,
                                (z1 - z0) * l->e * l->scale};
  l->data = data;
  l->height = top - r.y + data.h + bottom;
}

double wl_report_scene_fit_height(const struct wl_report_scene *s, double width) {
  struct wl_report_rect r = {0.0, 0.0, width, 1e6};
  struct scene_layout l;
  scene_layout(s, r, &l);
  return l.height;
}

static double px_of(const struct scene_layout *l, double x) {
  return l->data.x + (x - l->x0) * l->scale;
}
static double pz_of(const struct scene_layout *l, double z) {
  return l->data.y + l->data.h - (z - l->z0) * l->scale * l->e;
}

static void shape_style(enum wl_report_shape_kind kind, double fill[3], double line[3],
                        double *width, int *filled) {
  static const double water[3] = {0.80, 0.89, 0.97}, water_line[3] = {0.20, 0.42, 0.70};
  static const double bed[3] = {0.86, 0.76, 0.55}, bed_line[3] = {0.42, 0.32, 0.16};
  static const double wall[3] = {0.50, 0.50, 0.50}, wall_line[3] = {0.15, 0.15, 0.15};
  static const double black[3] = {0, 0, 0};
  const double *f = water, *ln = water_line;
  *filled = 1;
  *width = 0.6;
  switch (kind) {
  case WL_REPORT_SHAPE_WATER: break;
  case WL_REPORT_SHAPE_BED: f = bed, ln = bed_line; break;
  case WL_REPORT_SHAPE_WALL: f = wall, ln = wall_line; break;
  case WL_REPORT_SHAPE_OUTLINE: *filled = 0, ln = black; break;
  case WL_REPORT_SHAPE_LINE: *filled = 0, *width = 1.0; break;
  }
  memcpy(fill, f, 3 * sizeof *fill);
  memcpy(line, ln, 3 * sizeof *line);
}

static void shape_path(cairo_t *cr, const struct scene_layout *l, const struct wl_report_shape *sh,
                       int close) {
  int pen_up = 1;
  for (size_t i = 0; i < sh->n; i++) {
    if (!isfinite(sh->x[i]) || !isfinite(sh->z[i])) {
      if (!pen_up && close) cairo_close_path(cr);
      pen_up = 1;
      continue;
    }
    if (pen_up)
      cairo_move_to(cr, px_of(l, sh->x[i]), pz_of(l, sh->z[i]));
    else
      cairo_line_to(cr, px_of(l, sh->x[i]), pz_of(l, sh->z[i]));
    pen_up = 0;
  }
  if (!pen_up && close) cairo_close_path(cr);
}

/* Largest 1-2-5 length not above `most`. */
static double nice_below(double most) {
  double base = pow(10.0, floor(log10(most)));
  double m = most / base;
  return (m >= 5.0 ? 5.0 : m >= 2.0 ? 2.0 : 1.0) * base;
}

static void draw_scale_bar(struct wl_report_doc *d, const struct wl_report_scene *s,
                           const struct scene_layout *l, double y) {
  cairo_t *cr = d->cr;
  double len = nice_below(SCALE_FRACTION * (l->x1 - l->x0));
  double w = len * l->scale, x = l->data.x;
  cairo_set_line_width(cr, 0.5);
  for (int k = 0; k < 4; k++) {
    cairo_rectangle(cr, x + k * w / 4, y, w / 4, SCALE_BAR_H);
    if (k % 2 == 0)
      cairo_set_source_rgb(cr, 0, 0, 0);
    else
      cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_stroke(cr);
  }
  const char *unit = s->x_axis.unit && *s->x_axis.unit ? s->x_axis.unit : "m";
  char text[64];
  snprintf(text, sizeof text, "%g %s", len, unit);
  double ty = y + SCALE_BAR_H + 2.5;
  wl_report_text_draw(d, FONT_SANS, SIZE_TICK, x, ty, "0", 0.5, VALIGN_TOP);
  wl_report_text_draw(d, FONT_SANS, SIZE_TICK, x + w, ty, text, 0.5, VALIGN_TOP);
  if (fabs(l->e - 1.0) > 1e-9) {
    snprintf(text, sizeof text, "vertical exaggeration \xc3\x97%g", l->e);
    wl_report_text_draw(d, FONT_ITALIC, SIZE_TICK, l->data.x + l->data.w, y + 0.5 * SCALE_BAR_H,
                        text, 1.0, VALIGN_MIDDLE);
  } else {
    wl_report_text_draw(d, FONT_ITALIC, SIZE_TICK, l->data.x + l->data.w, y + 0.5 * SCALE_BAR_H,
                        "true scale", 1.0, VALIGN_MIDDLE);
  }
}

enum wl_status wl_report_draw_scene(struct wl_report_doc *d, const struct wl_report_scene *s,
                                    struct wl_report_rect r, struct wl_error *err) {
  enum wl_status st = wl_report_doc_ensure_page(d, err);
  if (st != WL_OK) return st;
  if (!s) return wl_report_doc_fail(d, err, WL_EINPUT, "%s: scene: none given (NULL)", d->path);
  if ((s->n_shapes > 0 && !s->shapes) || (s->n_marks > 0 && !s->marks) || s->n_shapes < 0 ||
      s->n_marks < 0)
    return wl_report_doc_fail(d, err, WL_EINPUT, "%s: scene: %d shapes and %d marks, arrays missing",
                              d->path, s->n_shapes, s->n_marks);
  for (int k = 0; k < s->n_shapes; k++)
    if (s->shapes[k].n > 0 && (!s->shapes[k].x || !s->shapes[k].z))
      return wl_report_doc_fail(d, err, WL_EINPUT, "%s: scene: shape %d has %zu vertices but no data",
                                d->path, k, s->shapes[k].n);
  if (s->x_axis.fixed && !(isfinite(s->x_axis.min) && isfinite(s->x_axis.max) &&
                           s->x_axis.min < s->x_axis.max))
    return wl_report_doc_fail(d, err, WL_EINPUT,
                              "%s: scene: window [%g, %g]; expected finite min < max", d->path,
                              s->x_axis.min, s->x_axis.max);
  struct scene_layout l;
  scene_layout(s, r, &l);
  if (!(l.scale > 0) || l.data.w < 10.0 || l.data.h < 1.0)
    return wl_report_doc_fail(d, err, WL_EINPUT,
                              "%s: scene: a %.0f x %.0f pt area is too small for the drawing",
                              d->path, r.w, r.h);
  cairo_t *cr = d->cr;
  cairo_save(cr);
  if (s->title && *s->title) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    wl_report_text_draw(d, FONT_BOLD, SIZE_SMALL, l.data.x + 0.5 * l.data.w, r.y + 2.0, s->title,
                        0.5, VALIGN_TOP);
  }
  cairo_save(cr);
  cairo_rectangle(cr, l.data.x, l.data.y - MARK_ROOM, l.data.w, l.data.h + MARK_ROOM);
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (int k = 0; k < s->n_shapes; k++) {
    const struct wl_report_shape *sh = &s->shapes[k];
    if (sh->n == 0) continue;
    double fill[3], line[3], width;
    int filled;
    shape_style(sh->kind, fill, line, &width, &filled);
    shape_path(cr, &l, sh, sh->kind != WL_REPORT_SHAPE_LINE);
    if (filled) {
      wl_report_set_rgb(cr, fill);
      cairo_fill_preserve(cr);
    }
    wl_report_set_rgb(cr, line);
    cairo_set_line_width(cr, width);
    cairo_stroke(cr);
  }
  cairo_restore(cr);

  cairo_set_source_rgb(cr, 0, 0, 0);
  for (int k = 0; k < s->n_marks; k++) {
    const struct wl_report_mark *m = &s->marks[k];
    if (!isfinite(m->x) || !isfinite(m->z) || m->x < l.x0 || m->x > l.x1) continue;
    double px = px_of(&l, m->x), pz = pz_of(&l, m->z);
    cairo_move_to(cr, px, pz);
    cairo_line_to(cr, px - MARK_SIZE, pz - 1.7 * MARK_SIZE);
    cairo_line_to(cr, px + MARK_SIZE, pz - 1.7 * MARK_SIZE);
    cairo_close_path(cr);
    cairo_fill(cr);
    if (m->label)
      wl_report_text_draw(d, FONT_SANS, SIZE_TICK, px, pz - 1.7 * MARK_SIZE - 2.0, m->label, 0.5,
                          VALIGN_BASELINE);
  }

  double y = l.data.y + l.data.h;
  if (s->axes) {
    struct wl_report_ticks t;
    int n = (int)(l.data.w / 60.0);
    wl_report_ticks_linear(l.x0, l.x1, n < 2 ? 2 : n > 8 ? 8 : n, 0, &t);
    struct axis_map mx = {l.x0, l.x1, 0, l.data.x, l.data.x + l.data.w};
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, FRAME_WIDTH);
    cairo_move_to(cr, l.data.x, y);
    cairo_line_to(cr, l.data.x + l.data.w, y);
    cairo_stroke(cr);
    wl_report_draw_x_ticks(d, &t, &mx, y, y, 0);
    char title[512];
    cairo_set_source_rgb(cr, 0, 0, 0);
    wl_report_axis_title(&s->x_axis, t.scale_exp, title, sizeof title);
    wl_report_text_draw(d, FONT_SANS, SIZE_SMALL, l.data.x + 0.5 * l.data.w,
                        y + TICK_LEN + LABEL_GAP + CAP_HEIGHT * SIZE_TICK + 5.0, title, 0.5,
                        VALIGN_TOP);
    y += AXES_BAND;
  }
  draw_scale_bar(d, s, &l, y + 8.0);
  cairo_restore(cr);
  return WL_OK;
}
