/* plot.c: x-y plots: axes with nice ticks (linear or log), grid, labelled
 * axis titles with units, series as lines (solid, dashed, dotted, dash-dot)
 * and/or markers in colours that stay apart in greyscale print, labelled
 * reference lines, and a legend placed where it hides the fewest points. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "doc.h"

#define SERIES_WIDTH 1.1   /* series line width [pt] */
#define GRID_GREY 0.86
#define MARKER_R 2.2       /* marker radius [pt] */
#define MARKERS_MAX 400    /* more points than this: markers on every k-th */
#define LEGEND_SAMPLE 22.0 /* legend line sample [pt] */
#define LEGEND_ROW 10.0
#define THIN_PER_PT 4.0    /* bins per point of width when thinning long series */
#define LEGEND_SAMPLES 2000 /* points per series tested for legend overlap */

void wl_report_set_rgb(cairo_t *cr, const double rgb[3]) {
  cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
}

void wl_report_axis_title(const struct wl_report_axis *a, int scale_exp, char *buf, size_t size) {
  const char *label = a->label ? a->label : "";
  const char *unit = a->unit && *a->unit ? a->unit : NULL;
  char scale[40] = "";
  if (scale_exp) {
    char sup[32];
    wl_report_format_superscript(scale_exp, sup, sizeof sup);
    snprintf(scale, sizeof scale, "10%s", sup);
  }
  if (unit && scale_exp)
    snprintf(buf, size, "%s [%s %s]", label, scale, unit);
  else if (unit)
    snprintf(buf, size, "%s [%s]", label, unit);
  else if (scale_exp)
    snprintf(buf, size, "%s [%s]", label, scale);
  else
    snprintf(buf, size, "%s", label);
}

/* ---- axis mapping ----------------------------------------------------------- */

static double to_page(const struct axis_map *m, double v) { return axis_to_page(m, v); }

static int usable(const struct wl_report_axis *a, double v) {
  return isfinite(v) && (!a->log || v > 0);
}

static int in_fixed(const struct wl_report_axis *a, double v) {
  return !a->fixed || (v >= a->min && v <= a->max);
}

/* Extent of the data the plot will show on x (which = 0) or y (which = 1). */
static int data_extent(const struct wl_report_plot *p, int which, double *lo, double *hi) {
  int any = 0;
  *lo = INFINITY;
  *hi = -INFINITY;
  for (int s = 0; s < p->n_series; s++) {
    const struct wl_report_series *se = &p->series[s];
    for (size_t i = 0; i < se->n; i++) {
      double x = se->x[i], y = se->y[i];
      if (!usable(&p->x, x) || !usable(&p->y, y)) continue;
      if (which == 1 && !in_fixed(&p->x, x)) continue;
      if (which == 0 && !in_fixed(&p->y, y)) continue;
      double v = which ? y : x;
      if (v < *lo) *lo = v;
      if (v > *hi) *hi = v;
      any = 1;
    }
  }
  for (int r = 0; r < p->n_refs; r++) {
    if (p->refs[r].vertical != (which == 0)) continue;
    double v = p->refs[r].at;
    if (!usable(which ? &p->y : &p->x, v)) continue;
    if (v < *lo) *lo = v;
    if (v > *hi) *hi = v;
    any = 1;
  }
  return any;
}

static int clamp_int(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

static void axis_ticks(const struct wl_report_axis *a, int has_data, double lo, double hi,
                       double length, double per_tick, struct wl_report_ticks *t) {
  if (a->log) {
    if (a->fixed)
      wl_report_ticks_log(a->min, a->max, 0, t, NULL);
    else if (has_data)
      wl_report_ticks_log(lo, hi, 1, t, NULL);
    else
      wl_report_ticks_log(1.0, 10.0, 1, t, NULL);
    return;
  }
  int n = clamp_int((int)(length / per_tick), 2, 8);
  if (a->fixed)
    wl_report_ticks_linear(a->min, a->max, n, 0, t);
  else if (has_data)
    wl_report_ticks_linear(lo, hi, n, 1, t);
  else
    wl_report_ticks_linear(0.0, 1.0, n, 1, t);
}

static enum wl_status check_axis(struct wl_report_doc *d, const struct wl_report_plot *p,
                                 const struct wl_report_axis *a, const char *name,
                                 struct wl_error *err) {
  if (!a->fixed) return WL_OK;
  if (!isfinite(a->min) || !isfinite(a->max) || !(a->min < a->max) || (a->log && !(a->min > 0)))
    return wl_report_doc_fail(d, err, WL_EINPUT,
                              "%s: plot '%s': %s axis range [%g, %g]: expected finite min < max%s",
                              d->path, p->title ? p->title : "", name, a->min, a->max,
                              a->log ? " with min > 0 (log axis)" : "");
  return WL_OK;
}

/* ---- styles ------------------------------------------------------------------- */

static enum wl_report_line series_line(const struct wl_report_series *s, int index) {
  static const enum wl_report_line cycle[4] = {WL_REPORT_LINE_SOLID, WL_REPORT_LINE_DASHED,
                                               WL_REPORT_LINE_DOTTED, WL_REPORT_LINE_DASHDOT};
  return s->line == WL_REPORT_LINE_AUTO ? cycle[index % 4] : s->line;
}

static enum wl_report_marker series_marker(const struct wl_report_series *s, int index) {
  static const enum wl_report_marker cycle[5] = {
      WL_REPORT_MARKER_CIRCLE, WL_REPORT_MARKER_SQUARE, WL_REPORT_MARKER_TRIANGLE,
      WL_REPORT_MARKER_DIAMOND, WL_REPORT_MARKER_CROSS};
  return s->marker == WL_REPORT_MARKER_AUTO ? cycle[index % 5] : s->marker;
}

static void series_rgb(const struct wl_report_series *s, int index, double rgb[3]) {
  wl_report_palette(s->colour >= 1 ? s->colour : index + 1, rgb);
}

static void set_line(cairo_t *cr, enum wl_report_line line, double width) {
  static const double dashed[] = {5.0, 2.5};
  static const double dotted[] = {0.01, 2.3};
  static const double dashdot[] = {5.0, 2.0, 0.01, 2.0};
  cairo_set_line_width(cr, width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  switch (line) {
  case WL_REPORT_LINE_DASHED: cairo_set_dash(cr, dashed, 2, 0); break;
  case WL_REPORT_LINE_DOTTED:
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_dash(cr, dotted, 2, 0);
    break;
  case WL_REPORT_LINE_DASHDOT:
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_dash(cr, dashdot, 4, 0);
    break;
  default: cairo_set_dash(cr, NULL, 0, 0); break;
  }
}

static void marker_path(cairo_t *cr, enum wl_report_marker m, double x, double y, double r) {
  switch (m) {
  case WL_REPORT_MARKER_CIRCLE:
    cairo_new_sub_path(cr);
    cairo_arc(cr, x, y, r, 0, 2 * WL_REPORT_PI);
    break;
  case WL_REPORT_MARKER_SQUARE: cairo_rectangle(cr, x - 0.9 * r, y - 0.9 * r, 1.8 * r, 1.8 * r); break;
  case WL_REPORT_MARKER_TRIANGLE:
    cairo_move_to(cr, x, y - 1.15 * r);
    cairo_line_to(cr, x + r, y + 0.7 * r);
    cairo_line_to(cr, x - r, y + 0.7 * r);
    cairo_close_path(cr);
    break;
  case WL_REPORT_MARKER_DIAMOND:
    cairo_move_to(cr, x, y - 1.2 * r);
    cairo_line_to(cr, x + r, y);
    cairo_line_to(cr, x, y + 1.2 * r);
    cairo_line_to(cr, x - r, y);
    cairo_close_path(cr);
    break;
  case WL_REPORT_MARKER_CROSS:
    cairo_move_to(cr, x - r, y - r);
    cairo_line_to(cr, x + r, y + r);
    cairo_move_to(cr, x - r, y + r);
    cairo_line_to(cr, x + r, y - r);
    break;
  default: break;
  }
}

/* Markers: filled, except the cross, which is stroked. */
static void draw_marker(cairo_t *cr, enum wl_report_marker m, double x, double y) {
  if (m == WL_REPORT_MARKER_NONE) return;
  marker_path(cr, m, x, y, MARKER_R);
  cairo_set_dash(cr, NULL, 0, 0);
  if (m == WL_REPORT_MARKER_CROSS) {
    cairo_set_line_width(cr, 0.9);
    cairo_stroke(cr);
  } else {
    cairo_fill(cr);
  }
}

/* ---- series ----------------------------------------------------------------------- */

static int monotonic_x(const struct wl_report_series *s) {
  double prev = -INFINITY;
  for (size_t i = 0; i < s->n; i++) {
    if (!isfinite(s->x[i]) || !isfinite(s->y[i])) continue;
    if (s->x[i] < prev) return 0;
    prev = s->x[i];
  }
  return 1;
}

static enum wl_status draw_series(struct wl_report_doc *d, const struct wl_report_plot *p, int k,
                                  const struct axis_map *mx, const struct axis_map *my,
                                  struct wl_error *err) {
  const struct wl_report_series *s = &p->series[k];
  if (s->n == 0) return WL_OK;
  cairo_t *cr = d->cr;
  enum wl_report_line line = series_line(s, k);
  enum wl_report_marker marker = series_marker(s, k);
  double rgb[3];
  series_rgb(s, k, rgb);
  wl_report_set_rgb(cr, rgb);

  size_t *keep = NULL, n_keep = s->n;
  double width_pt = fabs(mx->p1 - mx->p0);
  if (line != WL_REPORT_LINE_NONE && !p->x.log && (double)s->n > THIN_PER_PT * width_pt &&
      monotonic_x(s)) {
    keep = malloc(s->n * sizeof *keep);
    if (!keep)
      return wl_report_doc_fail(d, err, WL_ENOMEM, "%s: no memory to thin a series of %zu points",
                                d->path, s->n);
    n_keep = wl_report_thin(s->x, s->y, s->n, mx->lo, mx->hi, (size_t)(THIN_PER_PT * width_pt),
                            keep);
  }
  if (line != WL_REPORT_LINE_NONE) {
    set_line(cr, line, SERIES_WIDTH);
    int pen_up = 1;
    for (size_t j = 0; j < n_keep; j++) {
      size_t i = keep ? keep[j] : j;
      double x = s->x[i], y = s->y[i];
      if (!usable(&p->x, x) || !usable(&p->y, y)) {
        pen_up = 1;
        continue;
      }
      double px = to_page(mx, x), py = to_page(my, y);
      if (pen_up)
        cairo_move_to(cr, px, py);
      else
        cairo_line_to(cr, px, py);
      pen_up = 0;
    }
    cairo_stroke(cr);
  }
  free(keep);
  if (marker != WL_REPORT_MARKER_NONE) {
    size_t every = s->n > MARKERS_MAX ? (s->n + MARKERS_MAX - 1) / MARKERS_MAX : 1;
    for (size_t i = 0; i < s->n; i += every) {
      double x = s->x[i], y = s->y[i];
      if (!usable(&p->x, x) || !usable(&p->y, y)) continue;
      draw_marker(cr, marker, to_page(mx, x), to_page(my, y));
    }
  }
  return WL_OK;
}

/* ---- legend --------------------------------------------------------------------- */

/* A series is in the legend when it has a label and something drawn. */
static int in_legend(const struct wl_report_plot *p, int k) {
  const struct wl_report_series *s = &p->series[k];
  if (!s->label || !s->label[0]) return 0;
  for (size_t i = 0; i < s->n; i++)
    if (usable(&p->x, s->x[i]) && usable(&p->y, s->y[i]) && in_fixed(&p->x, s->x[i]) &&
        in_fixed(&p->y, s->y[i]))
      return 1;
  return 0;
}

static int legend_entries(const struct wl_report_plot *p) {
  int n = 0;
  for (int k = 0; k < p->n_series; k++) n += in_legend(p, k);
  return n;
}

static double legend_text_width(struct wl_report_doc *d, const struct wl_report_plot *p) {
  double w = 0;
  for (int k = 0; k < p->n_series; k++)
    if (in_legend(p, k)) {
      double tw = wl_report_text_width(d, FONT_SANS, SIZE_TICK, p->series[k].label);
      if (tw > w) w = tw;
    }
  return w;
}

static void legend_entry(struct wl_report_doc *d, const struct wl_report_plot *p, int k, double x,
                         double y) {
  cairo_t *cr = d->cr;
  const struct wl_report_series *s = &p->series[k];
  double rgb[3];
  series_rgb(s, k, rgb);
  wl_report_set_rgb(cr, rgb);
  enum wl_report_line line = series_line(s, k);
  if (line != WL_REPORT_LINE_NONE) {
    set_line(cr, line, SERIES_WIDTH);
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x + LEGEND_SAMPLE, y);
    cairo_stroke(cr);
  }
  draw_marker(cr, series_marker(s, k), x + 0.5 * LEGEND_SAMPLE, y);
  cairo_set_source_rgb(cr, 0, 0, 0);
  wl_report_text_draw(d, FONT_SANS, SIZE_TICK, x + LEGEND_SAMPLE + 4.0, y, s->label, 0.0,
                      VALIGN_MIDDLE);
}

/* Points of the plot inside box (page coordinates), sampled. */
static long points_inside(const struct wl_report_plot *p, const struct axis_map *mx,
                          const struct axis_map *my, struct wl_report_rect box) {
  long count = 0;
  for (int k = 0; k < p->n_series; k++) {
    const struct wl_report_series *s = &p->series[k];
    size_t every = s->n > LEGEND_SAMPLES ? s->n / LEGEND_SAMPLES : 1;
    for (size_t i = 0; i < s->n; i += every) {
      if (!usable(&p->x, s->x[i]) || !usable(&p->y, s->y[i])) continue;
      double px = to_page(mx, s->x[i]), py = to_page(my, s->y[i]);
      if (px >= box.x && px <= box.x + box.w && py >= box.y && py <= box.y + box.h) count++;
    }
  }
  return count;
}

static struct wl_report_rect legend_box(struct wl_report_doc *d, const struct wl_report_plot *p,
                                        struct wl_report_rect area, int corner) {
  double w = LEGEND_SAMPLE + 4.0 + legend_text_width(d, p) + 8.0;
  double h = legend_entries(p) * LEGEND_ROW + 4.0, inset = 4.0;
  int right = corner == 0 || corner == 2, bottom = corner >= 2;
  struct wl_report_rect b = {right ? area.x + area.w - inset - w : area.x + inset,
                             bottom ? area.y + area.h - inset - h : area.y + inset, w, h};
  return b;
}

/* The corner (0 top right, 1 top left, 2 bottom right, 3 bottom left) whose
 * legend box covers the fewest data points; *covered says how many. */
static int best_corner(struct wl_report_doc *d, const struct wl_report_plot *p,
                       struct wl_report_rect area, const struct axis_map *mx,
                       const struct axis_map *my, long *covered) {
  int best = 0;
  long best_count = -1;
  for (int c = 0; c < 4; c++) {
    long count = points_inside(p, mx, my, legend_box(d, p, area, c));
    if (best_count < 0 || count < best_count) best = c, best_count = count;
  }
  *covered = best_count;
  return best;
}

static void draw_legend_inside(struct wl_report_doc *d, const struct wl_report_plot *p,
                               struct wl_report_rect b) {
  cairo_t *cr = d->cr;
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_rectangle(cr, b.x, b.y, b.w, b.h);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
  cairo_set_line_width(cr, 0.4);
  cairo_set_dash(cr, NULL, 0, 0);
  cairo_stroke(cr);
  int row = 0;
  for (int k = 0; k < p->n_series; k++)
    if (in_legend(p, k)) legend_entry(d, p, k, b.x + 4.0, b.y + 2.0 + (row++ + 0.5) * LEGEND_ROW);
}

/* Legend under the plot: entries in as many columns as fit. */
static double legend_below_layout(struct wl_report_doc *d, const struct wl_report_plot *p,
                                  double width, int *n_cols) {
  int n = legend_entries(p);
  if (n == 0) return 0.0;
  double col_w = LEGEND_SAMPLE + 4.0 + legend_text_width(d, p) + 12.0;
  int cols = (int)(width / col_w);
  if (cols < 1) cols = 1;
  if (cols > n) cols = n;
  *n_cols = cols;
  return ((n + cols - 1) / cols) * LEGEND_ROW + 6.0;
}

/* ---- the plot ----------------------------------------------------------------------- */

static void draw_refs(struct wl_report_doc *d, const struct wl_report_plot *p,
                      struct wl_report_rect a, const struct axis_map *mx,
                      const struct axis_map *my) {
  static const double dash[] = {6.0, 3.0};
  cairo_t *cr = d->cr;
  for (int r = 0; r < p->n_refs; r++) {
    const struct wl_report_refline *ref = &p->refs[r];
    const struct wl_report_axis *ax = ref->vertical ? &p->x : &p->y;
    if (!usable(ax, ref->at) || !in_fixed(ax, ref->at)) continue;
    cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
    cairo_set_line_width(cr, 0.8);
    cairo_set_dash(cr, dash, 2, 0);
    if (ref->vertical) {
      double px = to_page(mx, ref->at);
      cairo_move_to(cr, px, a.y);
      cairo_line_to(cr, px, a.y + a.h);
      cairo_stroke(cr);
      if (ref->label)
        wl_report_text_draw_rotated(d, FONT_ITALIC, SIZE_TICK, px - 2.0, a.y + 3.0,
                                    -0.5 * WL_REPORT_PI, ref->label, 1.0, VALIGN_BASELINE);
    } else {
      double py = to_page(my, ref->at);
      cairo_move_to(cr, a.x, py);
      cairo_line_to(cr, a.x + a.w, py);
      cairo_stroke(cr);
      if (ref->label) {
        /* Above the line, or below it when it runs along the top. */
        int below = py - a.y < SIZE_TICK + 4.0;
        wl_report_text_draw(d, FONT_ITALIC, SIZE_TICK, a.x + a.w - 3.0,
                            below ? py + 2.5 : py - 2.5, ref->label, 1.0,
                            below ? VALIGN_TOP : VALIGN_BASELINE);
      }
    }
  }
  cairo_set_dash(cr, NULL, 0, 0);
}

void wl_report_draw_x_ticks(struct wl_report_doc *d, const struct wl_report_ticks *t,
                         const struct axis_map *mx, double y_axis, double y_top, int grid) {
  cairo_t *cr = d->cr;
  cairo_set_dash(cr, NULL, 0, 0);
  for (int i = 0; i < t->n; i++) {
    double px = to_page(mx, t->at[i]);
    if (grid) {
      cairo_set_source_rgb(cr, GRID_GREY, GRID_GREY, GRID_GREY);
      cairo_set_line_width(cr, 0.3);
      cairo_move_to(cr, px, y_top);
      cairo_line_to(cr, px, y_axis);
      cairo_stroke(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, FRAME_WIDTH);
    cairo_move_to(cr, px, y_axis);
    cairo_line_to(cr, px, y_axis + TICK_LEN);
    cairo_stroke(cr);
    wl_report_text_draw(d, FONT_SANS, SIZE_TICK, px, y_axis + TICK_LEN + LABEL_GAP, t->label[i],
                        0.5, VALIGN_TOP);
  }
  cairo_set_line_width(cr, 0.4);
  for (int i = 0; i < t->n_minor; i++) {
    double px = to_page(mx, t->minor[i]);
    cairo_move_to(cr, px, y_axis);
    cairo_line_to(cr, px, y_axis + MINOR_LEN);
  }
  cairo_stroke(cr);
}

void wl_report_draw_y_ticks(struct wl_report_doc *d, const struct wl_report_ticks *t,
                         const struct axis_map *my, double x_axis, double x_right, int grid) {
  cairo_t *cr = d->cr;
  cairo_set_dash(cr, NULL, 0, 0);
  for (int i = 0; i < t->n; i++) {
    double py = to_page(my, t->at[i]);
    if (grid) {
      cairo_set_source_rgb(cr, GRID_GREY, GRID_GREY, GRID_GREY);
      cairo_set_line_width(cr, 0.3);
      cairo_move_to(cr, x_axis, py);
      cairo_line_to(cr, x_right, py);
      cairo_stroke(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, FRAME_WIDTH);
    cairo_move_to(cr, x_axis - TICK_LEN, py);
    cairo_line_to(cr, x_axis, py);
    cairo_stroke(cr);
    wl_report_text_draw(d, FONT_SANS, SIZE_TICK, x_axis - TICK_LEN - LABEL_GAP, py, t->label[i],
                        1.0, VALIGN_MIDDLE);
  }
  cairo_set_line_width(cr, 0.4);
  for (int i = 0; i < t->n_minor; i++) {
    double py = to_page(my, t->minor[i]);
    cairo_move_to(cr, x_axis - MINOR_LEN, py);
    cairo_line_to(cr, x_axis, py);
  }
  cairo_stroke(cr);
}

double wl_report_ticks_width(struct wl_report_doc *d, const struct wl_report_ticks *t) {
  double w = 0;
  for (int i = 0; i < t->n; i++) {
    double tw = wl_report_text_width(d, FONT_SANS, SIZE_TICK, t->label[i]);
    if (tw > w) w = tw;
  }
  return w;
}

static enum wl_status check_plot(struct wl_report_doc *d, const struct wl_report_plot *p,
                                 struct wl_error *err) {
  if (!p) return wl_report_doc_fail(d, err, WL_EINPUT, "%s: plot: no plot given (NULL)", d->path);
  if (p->n_series < 0 || (p->n_series > 0 && !p->series) || p->n_refs < 0 ||
      (p->n_refs > 0 && !p->refs))
    return wl_report_doc_fail(d, err, WL_EINPUT,
                              "%s: plot '%s': %d series and %d reference lines, arrays missing",
                              d->path, p->title ? p->title : "", p->n_series, p->n_refs);
  for (int k = 0; k < p->n_series; k++) {
    const struct wl_report_series *s = &p->series[k];
    if (s->n > 0 && (!s->x || !s->y))
      return wl_report_doc_fail(d, err, WL_EINPUT,
                                "%s: plot '%s': series %d ('%s') has %zu points but no data",
                                d->path, p->title ? p->title : "", k, s->label ? s->label : "",
                                s->n);
  }
  enum wl_status st = check_axis(d, p, &p->x, "x", err);
  if (st == WL_OK) st = check_axis(d, p, &p->y, "y", err);
  return st;
}

struct plot_layout {
  struct wl_report_rect a; /* the frame */
  struct wl_report_ticks tx, ty;
  struct axis_map mx, my;
  double legend_h; /* below the plot [pt]; 0: none there */
  int legend_cols;
};

static void plot_layout(struct wl_report_doc *d, const struct wl_report_plot *p,
                        struct wl_report_rect r, int has_data, const double ext[4], int below,
                        struct plot_layout *L) {
  L->legend_cols = 1;
  L->legend_h = below ? legend_below_layout(d, p, r.w - 40.0, &L->legend_cols) : 0.0;
  double top = r.y + (p->title && *p->title ? SIZE_SMALL + 6.0 : 4.0);
  double bottom_band = TICK_LEN + LABEL_GAP + CAP_HEIGHT * SIZE_TICK + 6.0 + SIZE_SMALL + 3.0;
  struct wl_report_rect a;
  a.y = top;
  a.h = r.y + r.h - bottom_band - L->legend_h - top;
  axis_ticks(&p->y, has_data, ext[2], ext[3], a.h, 32.0, &L->ty);
  double left_band = SIZE_SMALL + 5.0 + wl_report_ticks_width(d, &L->ty) + LABEL_GAP + TICK_LEN;
  a.x = r.x + left_band;
  a.w = r.w - left_band - 10.0;
  axis_ticks(&p->x, has_data, ext[0], ext[1], a.w, 60.0, &L->tx);
  if (L->tx.n > 0) {
    /* Room for half of the last x label beyond the frame. */
    double half = 0.5 * wl_report_text_width(d, FONT_SANS, SIZE_TICK, L->tx.label[L->tx.n - 1]);
    if (half > 10.0) a.w = r.w - left_band - half;
  }
  L->a = a;
  struct axis_map mx = {L->tx.lo, L->tx.hi, p->x.log, a.x, a.x + a.w};
  struct axis_map my = {L->ty.lo, L->ty.hi, p->y.log, a.y + a.h, a.y};
  L->mx = mx;
  L->my = my;
}

enum wl_status wl_report_draw_plot(struct wl_report_doc *d, const struct wl_report_plot *p,
                                   struct wl_report_rect r, struct wl_error *err) {
  enum wl_status st = wl_report_doc_ensure_page(d, err);
  if (st == WL_OK) st = check_plot(d, p, err);
  if (st != WL_OK) return st;
  cairo_t *cr = d->cr;

  double ext[4];
  int has_x = data_extent(p, 0, &ext[0], &ext[1]), has_y = data_extent(p, 1, &ext[2], &ext[3]);
  int has_data = has_x && has_y;
  /* A reference line alone is not data: without points the plot says so. */
  int any_point = 0;
  for (int k = 0; k < p->n_series && !any_point; k++)
    for (size_t i = 0; i < p->series[k].n; i++)
      if (usable(&p->x, p->series[k].x[i]) && usable(&p->y, p->series[k].y[i]) &&
          in_fixed(&p->x, p->series[k].x[i]) && in_fixed(&p->y, p->series[k].y[i])) {
        any_point = 1;
        break;
      }

  int n_legend = any_point ? legend_entries(p) : 0;
  int below = p->legend == WL_REPORT_LEGEND_BELOW && n_legend > 0;
  struct plot_layout L;
  plot_layout(d, p, r, has_data, ext, below, &L);
  int corner = -1;
  if (p->legend == WL_REPORT_LEGEND_AUTO && n_legend > 0) {
    long covered = 0;
    corner = best_corner(d, p, L.a, &L.mx, &L.my, &covered);
    if (covered > 0) {
      /* Every corner hides data: put the legend under the plot instead. */
      below = 1;
      corner = -1;
      plot_layout(d, p, r, has_data, ext, below, &L);
    }
  }
  struct wl_report_rect a = L.a;
  struct wl_report_ticks tx = L.tx, ty = L.ty;
  struct axis_map mx = L.mx, my = L.my;
  int legend_cols = L.legend_cols;
  double legend_h = L.legend_h;
  if (a.w < 30.0 || a.h < 20.0)
    return wl_report_doc_fail(d, err, WL_EINPUT,
                              "%s: plot '%s': a %.0f x %.0f pt area is too small for a plot",
                              d->path, p->title ? p->title : "", r.w, r.h);

  cairo_save(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  if (p->title && *p->title)
    wl_report_text_draw(d, FONT_BOLD, SIZE_SMALL, a.x + 0.5 * a.w, r.y + 2.0, p->title, 0.5,
                        VALIGN_TOP);
  wl_report_draw_x_ticks(d, &tx, &mx, a.y + a.h, a.y, 1);
  wl_report_draw_y_ticks(d, &ty, &my, a.x, a.x + a.w, 1);

  char title[512];
  cairo_set_source_rgb(cr, 0, 0, 0);
  wl_report_axis_title(&p->x, tx.scale_exp, title, sizeof title);
  wl_report_text_draw(d, FONT_SANS, SIZE_SMALL, a.x + 0.5 * a.w,
                      a.y + a.h + TICK_LEN + LABEL_GAP + CAP_HEIGHT * SIZE_TICK + 5.0, title, 0.5,
                      VALIGN_TOP);
  wl_report_axis_title(&p->y, ty.scale_exp, title, sizeof title);
  wl_report_text_draw_rotated(d, FONT_SANS, SIZE_SMALL, r.x + 1.0, a.y + 0.5 * a.h,
                              -0.5 * WL_REPORT_PI, title, 0.5, VALIGN_TOP);

  cairo_save(cr);
  cairo_rectangle(cr, a.x, a.y, a.w, a.h);
  cairo_clip(cr);
  if (any_point) draw_refs(d, p, a, &mx, &my);
  for (int k = 0; k < p->n_series && st == WL_OK; k++) st = draw_series(d, p, k, &mx, &my, err);
  cairo_restore(cr);

  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, FRAME_WIDTH);
  cairo_set_dash(cr, NULL, 0, 0);
  cairo_rectangle(cr, a.x, a.y, a.w, a.h);
  cairo_stroke(cr);

  if (!any_point) {
    cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
    wl_report_text_draw(d, FONT_ITALIC, SIZE_SMALL, a.x + 0.5 * a.w, a.y + 0.5 * a.h, "no data",
                        0.5, VALIGN_MIDDLE);
  } else if (corner >= 0) {
    draw_legend_inside(d, p, legend_box(d, p, a, corner));
  } else if (below) {
    double col_w = a.w / legend_cols, y0 = r.y + r.h - legend_h + 3.0;
    int idx = 0;
    for (int k = 0; k < p->n_series; k++) {
      if (!in_legend(p, k)) continue;
      legend_entry(d, p, k, a.x + (idx % legend_cols) * col_w,
                   y0 + (idx / legend_cols + 0.5) * LEGEND_ROW);
      idx++;
    }
  }
  cairo_restore(cr);
  return st;
}
