/* field.c: colour-mapped particle plots (x, z, value) at true aspect ratio
 * with a viridis colour bar, for free-surface snapshots. Particles are
 * squares of the particle size, grouped by colour (one fill per colour band)
 * so that the PDF stays small; beyond WL_REPORT_FIELD_VECTOR_MAX particles
 * the dots are rasterised while axes and text stay vector. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "doc.h"

#define FIELD_LEFT 40.0        /* z ticks, labels and title [pt] */
#define FIELD_BOTTOM 30.0      /* x ticks, labels and title [pt] */
#define BAR_GAP 8.0            /* data to colour bar [pt] */
#define BAR_THICK 9.0
#define BAR_RIGHT 64.0         /* room right of the data for a vertical bar [pt] */
#define BAR_BELOW 40.0         /* room below the axes for a horizontal bar [pt] */
#define BAR_LONG_MAX 200.0     /* length of a horizontal bar at most [pt] */
#define BAR_MIN_VERTICAL 100.0 /* a drawing lower than this gets a horizontal bar [pt] */
#define N_BANDS 64             /* colour bands (64 steps are below what print resolves) */
#define MIN_HALF_PT 0.3        /* smallest particle half-size on paper [pt] */
#define SEAM_PT 0.2            /* squares grow by this, so neighbours overlap: no white seams
                                  from anti-aliased edges [pt] */
#define RASTER_MAX_PX 8000     /* raster side at most [px] */

struct field_layout {
  double x0, x1, z0, z1;     /* data window [m] */
  double scale;              /* page points per metre */
  struct wl_report_rect data; /* the drawing */
  int bar_below;             /* 1: horizontal colour bar under the axes */
  double height;             /* of everything [pt] */
};

static int point_ok(const struct wl_report_field *f, size_t i) {
  double x = f->x[i], z = f->z[i];
  if (!isfinite(x) || !isfinite(z)) return 0;
  if (f->x_axis.fixed && (x < f->x_axis.min || x > f->x_axis.max)) return 0;
  if (f->z_axis.fixed && (z < f->z_axis.min || z > f->z_axis.max)) return 0;
  return 1;
}

/* Half-size of a particle [m]: given, or from the area per point. */
static double half_size(const struct wl_report_field *f, const struct field_layout *l,
                        size_t n_ok) {
  if (f->radius > 0) return f->radius;
  if (n_ok == 0) return 0.0;
  return 0.5 * sqrt((l->x1 - l->x0) * (l->z1 - l->z0) / (double)n_ok);
}

static void field_layout(const struct wl_report_field *f, struct wl_report_rect r,
                         struct field_layout *l, size_t *n_ok_out) {
  double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
  size_t n_ok = 0;
  for (size_t i = 0; f->x && f->z && i < f->n; i++) {
    if (!point_ok(f, i)) continue;
    n_ok++;
    if (f->x[i] < x0) x0 = f->x[i];
    if (f->x[i] > x1) x1 = f->x[i];
    if (f->z[i] < z0) z0 = f->z[i];
    if (f->z[i] > z1) z1 = f->z[i];
  }
  if (n_ok == 0) x0 = z0 = 0.0, x1 = z1 = 1.0;
  l->x0 = x0, l->x1 = x1, l->z0 = z0, l->z1 = z1;
  double pad = half_size(f, l, n_ok);
  l->x0 -= pad, l->x1 += pad, l->z0 -= pad, l->z1 += pad;
  if (f->x_axis.fixed) l->x0 = f->x_axis.min, l->x1 = f->x_axis.max;
  if (f->z_axis.fixed) l->z0 = f->z_axis.min, l->z1 = f->z_axis.max;
  if (!(l->x1 - l->x0 > 0)) l->x0 -= 0.5, l->x1 += 0.5;
  if (!(l->z1 - l->z0 > 0)) l->z0 -= 0.5, l->z1 += 0.5;
  double dx = l->x1 - l->x0, dz = l->z1 - l->z0;
  double top = r.y + (f->title && *f->title ? SIZE_SMALL + 6.0 : 2.0);
  for (int below = 0; below <= 1; below++) {
    double right = below ? 10.0 : BAR_RIGHT;
    double bottom = FIELD_BOTTOM + (below ? BAR_BELOW : 0.0);
    double avail_w = r.w - FIELD_LEFT - right, avail_h = r.y + r.h - bottom - top;
    l->scale = fmin(avail_w / dx, avail_h / dz);
    l->bar_below = below;
    l->height = top - r.y + dz * l->scale + bottom;
    if (dz * l->scale >= BAR_MIN_VERTICAL) break;
  }
  struct wl_report_rect data = {r.x + FIELD_LEFT, top, dx * l->scale, dz * l->scale};
  l->data = data;
  if (n_ok_out) *n_ok_out = n_ok;
}

double wl_report_field_fit_height(const struct wl_report_field *f, double width) {
  struct wl_report_rect r = {0.0, 0.0, width, 1e6};
  struct field_layout l;
  field_layout(f, r, &l, NULL);
  return l.height;
}

/* Squares of half-size h [pt] for the particles of each colour band. */
static void paint_particles(cairo_t *cr, const struct wl_report_field *f,
                            const struct field_layout *l, const size_t *order,
                            const size_t *band_start, double h) {
  for (int b = 0; b <= N_BANDS; b++) {
    if (band_start[b] == band_start[b + 1]) continue;
    double rgb[3];
    wl_report_colormap(b == N_BANDS ? NAN : (double)b / (N_BANDS - 1), rgb);
    wl_report_set_rgb(cr, rgb);
    for (size_t j = band_start[b]; j < band_start[b + 1]; j++) {
      size_t i = order[j];
      double px = l->data.x + (f->x[i] - l->x0) * l->scale;
      double py = l->data.y + l->data.h - (f->z[i] - l->z0) * l->scale;
      cairo_rectangle(cr, px - h, py - h, 2.0 * h, 2.0 * h);
    }
    cairo_fill(cr);
  }
}

static void gradient_stops(cairo_pattern_t *pat) {
  for (int k = 0; k <= 10; k++) {
    double rgb[3];
    wl_report_colormap(k / 10.0, rgb);
    cairo_pattern_add_color_stop_rgb(pat, k / 10.0, rgb[0], rgb[1], rgb[2]);
  }
}

static void draw_colour_bar(struct wl_report_doc *d, const struct wl_report_field *f,
                            const struct field_layout *l, double vmin, double vmax) {
  cairo_t *cr = d->cr;
  struct wl_report_axis va = {f->value_label, f->value_unit, 0, 0, 0, 0};
  struct wl_report_ticks t;
  char title[512];
  double bx, by, bw, bh;
  if (!l->bar_below) {
    bx = l->data.x + l->data.w + BAR_GAP, by = l->data.y, bw = BAR_THICK, bh = l->data.h;
  } else {
    bx = l->data.x, by = l->data.y + l->data.h + FIELD_BOTTOM + 4.0;
    bw = fmin(l->data.w, BAR_LONG_MAX), bh = 0.9 * BAR_THICK;
  }
  double length = l->bar_below ? bw : bh;
  int max_int = (int)(length / (l->bar_below ? 45.0 : 28.0));
  wl_report_ticks_linear(vmin, vmax, max_int < 2 ? 2 : max_int > 8 ? 8 : max_int, 0, &t);
  cairo_pattern_t *pat = l->bar_below ? cairo_pattern_create_linear(bx, 0, bx + bw, 0)
                                      : cairo_pattern_create_linear(0, by + bh, 0, by);
  gradient_stops(pat);
  cairo_set_source(cr, pat);
  cairo_rectangle(cr, bx, by, bw, bh);
  cairo_fill(cr);
  cairo_pattern_destroy(pat);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 0.5);
  cairo_rectangle(cr, bx, by, bw, bh);
  cairo_stroke(cr);
  wl_report_axis_title(&va, t.scale_exp, title, sizeof title);
  if (!l->bar_below) {
    struct axis_map m = {vmin, vmax, 0, by + bh, by};
    double lw = 0;
    for (int i = 0; i < t.n; i++) {
      double py = axis_to_page(&m, t.at[i]);
      cairo_move_to(cr, bx + bw, py);
      cairo_line_to(cr, bx + bw + TICK_LEN, py);
      cairo_stroke(cr);
      wl_report_text_draw(d, FONT_SANS, SIZE_TICK, bx + bw + TICK_LEN + LABEL_GAP, py,
                          t.label[i], 0.0, VALIGN_MIDDLE);
    }
    lw = wl_report_ticks_width(d, &t);
    wl_report_text_draw_rotated(d, FONT_SANS, SIZE_SMALL, bx + bw + TICK_LEN + LABEL_GAP + lw + 4.0,
                                by + 0.5 * bh, -0.5 * WL_REPORT_PI, title, 0.5, VALIGN_TOP);
  } else {
    struct axis_map m = {vmin, vmax, 0, bx, bx + bw};
    for (int i = 0; i < t.n; i++) {
      double px = axis_to_page(&m, t.at[i]);
      cairo_move_to(cr, px, by + bh);
      cairo_line_to(cr, px, by + bh + TICK_LEN);
      cairo_stroke(cr);
      wl_report_text_draw(d, FONT_SANS, SIZE_TICK, px, by + bh + TICK_LEN + LABEL_GAP, t.label[i],
                          0.5, VALIGN_TOP);
    }
    wl_report_text_draw(d, FONT_SANS, SIZE_SMALL, bx + bw + 10.0, by + 0.5 * bh, title, 0.0,
                        VALIGN_MIDDLE);
  }
}

static enum wl_status check_field(struct wl_report_doc *d, const struct wl_report_field *f,
                                  struct wl_error *err) {
  if (!f) return wl_report_doc_fail(d, err, WL_EINPUT, "%s: field: none given (NULL)", d->path);
  const char *name = f->title ? f->title : "";
  if (f->n > 0 && (!f->x || !f->z || !f->value))
    return wl_report_doc_fail(d, err, WL_EINPUT, "%s: field '%s': %zu particles but no data",
                              d->path, name, f->n);
  if (f->fixed_range && !(isfinite(f->vmin) && isfinite(f->vmax) && f->vmin < f->vmax))
    return wl_report_doc_fail(d, err, WL_EINPUT,
                              "%s: field '%s': colour range [%g, %g]; expected finite vmin < vmax",
                              d->path, name, f->vmin, f->vmax);
  const struct wl_report_axis *ax[2] = {&f->x_axis, &f->z_axis};
  for (int k = 0; k < 2; k++)
    if (ax[k]->fixed && !(isfinite(ax[k]->min) && isfinite(ax[k]->max) && ax[k]->min < ax[k]->max))
      return wl_report_doc_fail(d, err, WL_EINPUT,
                                "%s: field '%s': %s window [%g, %g]; expected finite min < max",
                                d->path, name, k ? "z" : "x", ax[k]->min, ax[k]->max);
  return WL_OK;
}

enum wl_status wl_report_draw_field(struct wl_report_doc *d, const struct wl_report_field *f,
                                    struct wl_report_rect r, struct wl_error *err) {
  enum wl_status st = wl_report_doc_ensure_page(d, err);
  if (st == WL_OK) st = check_field(d, f, err);
  if (st != WL_OK) return st;
  struct field_layout l;
  size_t n_ok = 0;
  field_layout(f, r, &l, &n_ok);
  if (!(l.scale > 0) || l.data.w < 10.0 || l.data.h < 2.0)
    return wl_report_doc_fail(d, err, WL_EINPUT,
                              "%s: field '%s': a %.0f x %.0f pt area is too small for the drawing",
                              d->path, f->title ? f->title : "", r.w, r.h);

  /* Colour range: given, or the values of the particles shown. */
  double vmin = INFINITY, vmax = -INFINITY;
  if (f->fixed_range) {
    vmin = f->vmin, vmax = f->vmax;
  } else {
    for (size_t i = 0; i < f->n; i++)
      if (point_ok(f, i) && isfinite(f->value[i])) {
        if (f->value[i] < vmin) vmin = f->value[i];
        if (f->value[i] > vmax) vmax = f->value[i];
      }
    if (!(vmin <= vmax)) vmin = 0.0, vmax = 1.0;
    if (vmax - vmin <= 1e-12 * fmax(fabs(vmin), fabs(vmax))) {
      double m = fabs(vmin) > 0 ? 0.05 * fabs(vmin) : 0.5;
      vmin -= m, vmax += m;
    }
  }

  /* Counting sort of the shown particles by colour band (band N_BANDS: NaN). */
  size_t *order = malloc((n_ok > 0 ? n_ok : 1) * sizeof *order);
  size_t band_start[N_BANDS + 2] = {0};
  if (!order)
    return wl_report_doc_fail(d, err, WL_ENOMEM, "%s: no memory to sort %zu particles", d->path,
                              n_ok);
  for (int pass = 0; pass < 2; pass++) {
    size_t fill[N_BANDS + 1];
    if (pass == 1) {
      for (int b = 0; b <= N_BANDS; b++) band_start[b + 1] += band_start[b];
      memcpy(fill, band_start, sizeof fill);
    }
    for (size_t i = 0; i < f->n; i++) {
      if (!point_ok(f, i)) continue;
      double v = f->value[i];
      int b = N_BANDS;
      if (isfinite(v)) {
        double t = (v - vmin) / (vmax - vmin);
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        b = (int)lround(t * (N_BANDS - 1));
      }
      if (pass == 0)
        band_start[b + 1]++;
      else
        order[fill[b]++] = i;
    }
  }

  cairo_t *cr = d->cr;
  cairo_save(cr);
  double h = half_size(f, &l, n_ok) * l.scale + SEAM_PT;
  if (h < MIN_HALF_PT) h = MIN_HALF_PT;
  cairo_save(cr);
  cairo_rectangle(cr, l.data.x, l.data.y, l.data.w, l.data.h);
  cairo_clip(cr);
  if (n_ok <= WL_REPORT_FIELD_VECTOR_MAX) {
    paint_particles(cr, f, &l, order, band_start, h);
  } else {
    double k = WL_REPORT_FIELD_DPI / 72.0;
    int wpx = (int)ceil(l.data.w * k), hpx = (int)ceil(l.data.h * k);
    if (wpx > RASTER_MAX_PX) wpx = RASTER_MAX_PX;
    if (hpx > RASTER_MAX_PX) hpx = RASTER_MAX_PX;
    /* Opaque (the page under it is white): one image, no soft mask. */
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, wpx, hpx);
    cairo_t *ic = cairo_create(img);
    cairo_set_source_rgb(ic, 1, 1, 1);
    cairo_paint(ic);
    cairo_scale(ic, wpx / l.data.w, hpx / l.data.h);
    cairo_translate(ic, -l.data.x, -l.data.y);
    paint_particles(ic, f, &l, order, band_start, h);
    cairo_status_t cs = cairo_status(ic);
    cairo_destroy(ic);
    if (cs == CAIRO_STATUS_SUCCESS) cs = cairo_surface_status(img);
    if (cs == CAIRO_STATUS_SUCCESS) {
      cairo_translate(cr, l.data.x, l.data.y);
      cairo_scale(cr, l.data.w / wpx, l.data.h / hpx);
      cairo_set_source_surface(cr, img, 0, 0);
      cairo_paint(cr);
    }
    cairo_surface_destroy(img);
    if (cs != CAIRO_STATUS_SUCCESS) {
      cairo_restore(cr);
      cairo_restore(cr);
      free(order);
      return wl_report_doc_fail(d, err, cs == CAIRO_STATUS_NO_MEMORY ? WL_ENOMEM : WL_EIO,
                                "%s: field '%s': rasterising %zu particles: cairo: %s", d->path,
                                f->title ? f->title : "", n_ok, cairo_status_to_string(cs));
    }
  }
  cairo_restore(cr);
  free(order);

  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, FRAME_WIDTH);
  cairo_rectangle(cr, l.data.x, l.data.y, l.data.w, l.data.h);
  cairo_stroke(cr);
  if (f->title && *f->title)
    wl_report_text_draw(d, FONT_BOLD, SIZE_SMALL, l.data.x + 0.5 * l.data.w, r.y + 2.0, f->title,
                        0.5, VALIGN_TOP);
  if (n_ok == 0) {
    cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
    wl_report_text_draw(d, FONT_ITALIC, SIZE_SMALL, l.data.x + 0.5 * l.data.w,
                        l.data.y + 0.5 * l.data.h, "no data", 0.5, VALIGN_MIDDLE);
    cairo_set_source_rgb(cr, 0, 0, 0);
  }

  struct wl_report_ticks tx, tz;
  int nx = (int)(l.data.w / 55.0), nz = (int)(l.data.h / 28.0);
  wl_report_ticks_linear(l.x0, l.x1, nx < 2 ? 2 : nx > 8 ? 8 : nx, 0, &tx);
  wl_report_ticks_linear(l.z0, l.z1, nz < 2 ? 2 : nz > 8 ? 8 : nz, 0, &tz);
  struct axis_map mx = {l.x0, l.x1, 0, l.data.x, l.data.x + l.data.w};
  struct axis_map mz = {l.z0, l.z1, 0, l.data.y + l.data.h, l.data.y};
  wl_report_draw_x_ticks(d, &tx, &mx, l.data.y + l.data.h, l.data.y, 0);
  wl_report_draw_y_ticks(d, &tz, &mz, l.data.x, l.data.x + l.data.w, 0);
  char title[512];
  cairo_set_source_rgb(cr, 0, 0, 0);
  wl_report_axis_title(&f->x_axis, tx.scale_exp, title, sizeof title);
  wl_report_text_draw(d, FONT_SANS, SIZE_SMALL, l.data.x + 0.5 * l.data.w,
                      l.data.y + l.data.h + TICK_LEN + LABEL_GAP + CAP_HEIGHT * SIZE_TICK + 5.0,
                      title, 0.5, VALIGN_TOP);
  wl_report_axis_title(&f->z_axis, tz.scale_exp, title, sizeof title);
  double zlw = wl_report_ticks_width(d, &tz);
  wl_report_text_draw_rotated(d, FONT_SANS, SIZE_SMALL,
                              l.data.x - TICK_LEN - LABEL_GAP - zlw - 4.0 - SIZE_SMALL,
                              l.data.y + 0.5 * l.data.h, -0.5 * WL_REPORT_PI, title, 0.5,
                              VALIGN_TOP);
  draw_colour_bar(d, f, &l, vmin, vmax);
  cairo_restore(cr);
  return WL_OK;
}
