/* text.c: measuring, drawing and line-breaking UTF-8 text, through pango
 * (shaping, font fallback, proper line breaking) when the build has it and
 * through cairo's toy text API otherwise (WL_HAVE_PANGO in doc.h). Both
 * paths present the same primitives, so the rest of the toolkit does not
 * know which one it runs on. Hinted metrics are off: PDF is scaled freely. */
#include <stdlib.h>
#include <string.h>

#include "doc.h"

#if WL_HAVE_PANGO
static const char *const FAMILY[FONT_COUNT] = {"DejaVu Sans,sans-serif",
                                               "DejaVu Sans,sans-serif",
                                               "DejaVu Sans,sans-serif",
                                               "DejaVu Sans Mono,monospace"};
#else
static const char *const FAMILY[FONT_COUNT] = {"DejaVu Sans", "DejaVu Sans", "DejaVu Sans",
                                               "DejaVu Sans Mono"};
#endif

#if WL_HAVE_PANGO

enum wl_status wl_report_text_init(struct wl_report_doc *d, struct wl_error *err) {
  /* A font map of our own rather than pango's process-wide default: its
   * caches are freed with the document (leak checkers stay quiet, and a
   * long-running process does not grow). */
  d->fontmap = pango_cairo_font_map_new();
  PangoContext *ctx = d->fontmap ? pango_font_map_create_context(d->fontmap) : NULL;
  if (ctx) d->layout = pango_layout_new(ctx);
  if (!d->layout) {
    if (ctx) g_object_unref(ctx);
    return wl_error_set(err, WL_ENOMEM, "%s: cannot create a pango layout", d->path);
  }
  cairo_font_options_t *fo = cairo_font_options_create();
  cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
  pango_cairo_context_set_font_options(ctx, fo);
  cairo_font_options_destroy(fo);
  pango_cairo_update_context(d->cr, ctx);
  g_object_unref(ctx); /* the layout holds it */
  pango_layout_context_changed(d->layout);
  for (int f = 0; f < FONT_COUNT; f++) {
    d->fonts[f] = pango_font_description_from_string(FAMILY[f]);
    if (!d->fonts[f]) return wl_error_set(err, WL_ENOMEM, "%s: cannot create a font", d->path);
    if (f == FONT_BOLD) pango_font_description_set_weight(d->fonts[f], PANGO_WEIGHT_BOLD);
    if (f == FONT_ITALIC) pango_font_description_set_style(d->fonts[f], PANGO_STYLE_OBLIQUE);
  }
  return WL_OK;
}

void wl_report_text_free(struct wl_report_doc *d) {
  for (int f = 0; f < FONT_COUNT; f++) {
    if (d->fonts[f]) pango_font_description_free(d->fonts[f]);
    d->fonts[f] = NULL;
  }
  if (d->layout) g_object_unref(d->layout);
  d->layout = NULL;
  if (d->fontmap) g_object_unref(d->fontmap);
  d->fontmap = NULL;
}

static void use_font(struct wl_report_doc *d, enum font font, double size) {
  pango_font_description_set_absolute_size(d->fonts[font], size * PANGO_SCALE);
  pango_layout_set_font_description(d->layout, d->fonts[font]);
  pango_layout_set_width(d->layout, -1);
}

static void set_text(struct wl_report_doc *d, const char *s, int len) {
  pango_layout_set_text(d->layout, s, len);
}

double wl_report_text_width(struct wl_report_doc *d, enum font font, double size, const char *s) {
  if (!s || !*s) return 0.0;
  use_font(d, font, size);
  set_text(d, s, -1);
  PangoRectangle logical;
  pango_layout_get_extents(d->layout, NULL, &logical);
  return (double)logical.width / PANGO_SCALE;
}

static void show(struct wl_report_doc *d, enum font font, double size, double x, double y,
                 const char *s, int len, double halign, enum valign valign) {
  use_font(d, font, size);
  set_text(d, s, len);
  pango_cairo_update_layout(d->cr, d->layout);
  PangoRectangle logical;
  pango_layout_get_extents(d->layout, NULL, &logical);
  double w = (double)logical.width / PANGO_SCALE;
  double base = (double)pango_layout_get_baseline(d->layout) / PANGO_SCALE;
  double yb = y;
  if (valign == VALIGN_MIDDLE) yb = y + 0.5 * CAP_HEIGHT * size;
  if (valign == VALIGN_TOP) yb = y + CAP_HEIGHT * size;
  cairo_move_to(d->cr, x - halign * w, yb - base);
  pango_cairo_show_layout(d->cr, d->layout);
  cairo_new_path(d->cr);
}

enum wl_status wl_report_text_break(struct wl_report_doc *d, enum font font, double size,
                                    double width, const char *s, struct text_span **lines,
                                    size_t *n_lines, struct wl_error *err) {
  *lines = NULL;
  *n_lines = 0;
  use_font(d, font, size);
  pango_layout_set_width(d->layout, (int)(width * PANGO_SCALE));
  pango_layout_set_wrap(d->layout, PANGO_WRAP_WORD_CHAR);
  set_text(d, s, -1);
  int n = pango_layout_get_line_count(d->layout);
  struct text_span *out = malloc((size_t)(n > 0 ? n : 1) * sizeof *out);
  if (!out) {
    pango_layout_set_width(d->layout, -1);
    return wl_error_set(err, WL_ENOMEM, "%s: no memory to break a paragraph into lines", d->path);
  }
  for (int i = 0; i < n; i++) {
    PangoLayoutLine *l = pango_layout_get_line_readonly(d->layout, i);
    out[i].start = (size_t)l->start_index;
    out[i].len = (size_t)l->length;
  }
  pango_layout_set_width(d->layout, -1);
  *lines = out;
  *n_lines = (size_t)n;
  return WL_OK;
}

#else /* cairo's toy text API */

enum wl_status wl_report_text_init(struct wl_report_doc *d, struct wl_error *err) {
  (void)err;
  cairo_font_options_t *fo = cairo_font_options_create();
  cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
  cairo_set_font_options(d->cr, fo);
  cairo_font_options_destroy(fo);
  return WL_OK;
}

void wl_report_text_free(struct wl_report_doc *d) { (void)d; }

static void use_font(struct wl_report_doc *d, enum font font, double size) {
  cairo_select_font_face(d->cr, FAMILY[font],
                         font == FONT_ITALIC ? CAIRO_FONT_SLANT_OBLIQUE : CAIRO_FONT_SLANT_NORMAL,
                         font == FONT_BOLD ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(d->cr, size);
}

/* Width of bytes [0, len) of s in the current font. */
static double span_width(struct wl_report_doc *d, const char *s, size_t len) {
  char buf[1024];
  if (len >= sizeof buf) len = sizeof buf - 1;
  memcpy(buf, s, len);
  buf[len] = '\0';
  cairo_text_extents_t ext;
  cairo_text_extents(d->cr, buf, &ext);
  return ext.x_advance;
}

double wl_report_text_width(struct wl_report_doc *d, enum font font, double size, const char *s) {
  if (!s || !*s) return 0.0;
  use_font(d, font, size);
  return span_width(d, s, strlen(s));
}

static void show(struct wl_report_doc *d, enum font font, double size, double x, double y,
                 const char *s, int len, double halign, enum valign valign) {
  use_font(d, font, size);
  char buf[1024];
  size_t n = len < 0 ? strlen(s) : (size_t)len;
  if (n >= sizeof buf) n = sizeof buf - 1;
  memcpy(buf, s, n);
  buf[n] = '\0';
  cairo_text_extents_t ext;
  cairo_text_extents(d->cr, buf, &ext);
  double yb = y;
  if (valign == VALIGN_MIDDLE) yb = y + 0.5 * CAP_HEIGHT * size;
  if (valign == VALIGN_TOP) yb = y + CAP_HEIGHT * size;
  cairo_move_to(d->cr, x - halign * ext.x_advance, yb);
  cairo_show_text(d->cr, buf);
  cairo_new_path(d->cr);
}

static size_t next_char(const char *s, size_t i) {
  i++;
  while (((unsigned char)s[i] & 0xC0) == 0x80) i++;
  return i;
}

static enum wl_status push_line(struct text_span **lines, size_t *n, size_t *cap, size_t start,
                                size_t len) {
  if (*n == *cap) {
    size_t want = *cap ? 2 * *cap : 16;
    struct text_span *bigger = realloc(*lines, want * sizeof *bigger);
    if (!bigger) return WL_ENOMEM;
    *lines = bigger;
    *cap = want;
  }
  (*lines)[*n].start = start;
  (*lines)[*n].len = len;
  (*n)++;
  return WL_OK;
}

enum wl_status wl_report_text_break(struct wl_report_doc *d, enum font font, double size,
                                    double width, const char *s, struct text_span **lines,
                                    size_t *n_lines, struct wl_error *err) {
  *lines = NULL;
  *n_lines = 0;
  use_font(d, font, size);
  size_t cap = 0, n = 0, total = strlen(s), pos = 0;
  for (;;) {
    const char *nl = strchr(s + pos, '\n');
    size_t end = nl ? (size_t)(nl - s) : total;
    size_t start = pos;
    if (start == end && push_line(lines, &n, &cap, start, 0)) goto nomem;
    while (start < end) {
      size_t i = start, fit = start, brk = start;
      while (i < end) {
        size_t j = next_char(s, i);
        if (j > end) j = end;
        if (fit > start && span_width(d, s + start, j - start) > width) break;
        fit = j;
        if (s[i] == ' ') brk = j;
        i = j;
      }
      if (fit >= end) {
        if (push_line(lines, &n, &cap, start, end - start)) goto nomem;
        break;
      }
      size_t cut = brk > start ? brk : fit;
      if (push_line(lines, &n, &cap, start, cut - start)) goto nomem;
      start = cut;
      while (start < end && s[start] == ' ') start++;
    }
    if (!nl) break;
    pos = end + 1;
  }
  *n_lines = n;
  return WL_OK;
nomem:
  free(*lines);
  *lines = NULL;
  return wl_error_set(err, WL_ENOMEM, "%s: no memory to break a paragraph into lines", d->path);
}

#endif

void wl_report_text_draw(struct wl_report_doc *d, enum font font, double size, double x,
                         double y, const char *s, double halign, enum valign valign) {
  if (!s || !*s) return;
  show(d, font, size, x, y, s, -1, halign, valign);
}

void wl_report_text_draw_rotated(struct wl_report_doc *d, enum font font, double size, double x,
                                 double y, double angle, const char *s, double halign,
                                 enum valign valign) {
  if (!s || !*s) return;
  cairo_save(d->cr);
  cairo_translate(d->cr, x, y);
  cairo_rotate(d->cr, angle);
  show(d, font, size, 0.0, 0.0, s, -1, halign, valign);
  cairo_restore(d->cr);
}

void wl_report_text_draw_span(struct wl_report_doc *d, enum font font, double size, double x,
                              double y, const char *s, struct text_span span) {
  size_t len = span.len;
  while (len > 0 && (s[span.start + len - 1] == '\n' || s[span.start + len - 1] == '\r')) len--;
  if (len == 0) return;
  show(d, font, size, x, y, s + span.start, (int)len, 0.0, VALIGN_BASELINE);
}
