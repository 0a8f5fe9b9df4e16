/* doc.h: the document's insides and the text primitives the toolkit's
 * sources share (private to src/report). Section renderers that need raw
 * cairo drawing include this header and use wl_report_doc_cairo.
 *
 * Text goes through pango when its headers are on the include path (the
 * build links pangocairo when pkg-config finds it), else through cairo's toy
 * text API: WL_HAVE_PANGO is 1 or 0. Define WL_REPORT_NO_PANGO to force the
 * fallback (to test that it still builds and renders). */
#ifndef WALLLOAD_REPORT_DOC_H
#define WALLLOAD_REPORT_DOC_H

#include <cairo.h>
#include <math.h>

#include "wallload/draw.h"

#if defined(WL_REPORT_NO_PANGO)
#define WL_HAVE_PANGO 0
#elif defined(__has_include)
#if __has_include(<pango/pangocairo.h>)
#define WL_HAVE_PANGO 1
#else
#define WL_HAVE_PANGO 0
#endif
#else
#define WL_HAVE_PANGO 0
#endif

#if WL_HAVE_PANGO
#include <pango/pangocairo.h>
#endif

/* Page geometry [pt]: A4 portrait (ISO 216: 210 mm x 297 mm). */
#define PAGE_W (210.0 * WL_REPORT_PT_PER_MM)
#define PAGE_H (297.0 * WL_REPORT_PT_PER_MM)
#define MARGIN_X (20.0 * WL_REPORT_PT_PER_MM)      /* left and right */
#define MARGIN_TOP (25.0 * WL_REPORT_PT_PER_MM)    /* to the content box */
#define MARGIN_BOTTOM (22.0 * WL_REPORT_PT_PER_MM) /* to the content box */
#define HEADER_BASELINE (15.0 * WL_REPORT_PT_PER_MM)
#define FOOTER_BASELINE (PAGE_H - 12.0 * WL_REPORT_PT_PER_MM)
#define CONTENT_TOP MARGIN_TOP
#define CONTENT_BOTTOM (PAGE_H - MARGIN_BOTTOM)
#define CONTENT_W (PAGE_W - 2.0 * MARGIN_X)

/* Type sizes [pt] and spacing. */
#define SIZE_BODY 10.0
#define SIZE_SMALL 8.0  /* header, footer, captions, tables' units */
#define SIZE_TICK 7.5   /* tick labels, legends */
#define SIZE_TABLE 9.0
#define SIZE_MONO 7.5
#define SIZE_TITLE 22.0
#define SIZE_SUBTITLE 13.0
#define SIZE_H1 14.0
#define SIZE_H2 11.5
#define LEADING 1.3      /* line height / font size for running text */
#define GAP_BLOCK 8.0    /* space after a block [pt] */
#define CAP_HEIGHT 0.73  /* DejaVu Sans cap height / em, to centre labels vertically */
#define WL_REPORT_PI 3.14159265358979323846

enum font {
  FONT_SANS,
  FONT_BOLD,
  FONT_ITALIC,
  FONT_MONO,
  FONT_COUNT,
};

/* Where y is for text_draw. */
enum valign {
  VALIGN_BASELINE, /* y is the baseline */
  VALIGN_MIDDLE,   /* y is halfway up the capitals */
  VALIGN_TOP,      /* y is the top of the capitals */
};

struct wl_report_doc {
  cairo_surface_t *surface;
  cairo_t *cr;
#if WL_HAVE_PANGO
  PangoFontMap *fontmap; /* the document's own, so its font caches go with it */
  PangoLayout *layout;
  PangoFontDescription *fonts[FONT_COUNT];
#endif
  char path[1024];    /* final file */
  char tmp[1040];     /* path.part while writing */
  int fd;             /* tmp, open for writing (cairo writes through write_out); -1 when closed */
  int io_errno;       /* the system's reason for the first failed write, 0 while none */
  char title[256], scenario[256], company[256], version[64];
  int page;           /* pages started (current page number) */
  int page_open;      /* 1: header and footer of page `page` are drawn */
  double y;           /* cursor [pt from the top] */
  int n_figures, n_tables;
  int h1, h2;         /* heading counters */
  int outline_h1;     /* bookmark id of the last level-1 heading */
  int in_figure;      /* begin_figure seen, end_figure not yet */
  /* Headings wait here until the next block is placed, so that they land on
   * the same page as what follows them (keep-with-next). */
  int n_pending;
  struct {
    int level;
    char text[512]; /* numbered */
  } pending[4];
  int finished;
  enum wl_status failed; /* first error, WL_OK while all went well */
};

/* The document's cairo context (valid until finish), for custom drawing
 * inside a reserved rectangle: save and restore around it. */
cairo_t *wl_report_doc_cairo(struct wl_report_doc *d);

/* ---- internal helpers (page.c) ---- */

/* Return the stored failure (without drawing) when the document failed or
 * was finished; WL_OK otherwise. */
enum wl_status wl_report_doc_usable(struct wl_report_doc *d, struct wl_error *err);

/* Record `st` as the document's failure and in err; returns st. */
enum wl_status wl_report_doc_fail(struct wl_report_doc *d, struct wl_error *err, enum wl_status st,
                        const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Start a page if none is open (header and footer drawn). */
enum wl_status wl_report_doc_ensure_page(struct wl_report_doc *d, struct wl_error *err);

/* Make room for `height` at the cursor: a new page when it does not fit. */
enum wl_status wl_report_doc_need(struct wl_report_doc *d, double height, struct wl_error *err);


/* ---- text (text.c) ---- */

enum wl_status wl_report_text_init(struct wl_report_doc *d, struct wl_error *err);
void wl_report_text_free(struct wl_report_doc *d);

/* Advance width [pt] of s set in `font` at `size`. */
double wl_report_text_width(struct wl_report_doc *d, enum font font, double size, const char *s);

/* Draw s with its anchor at (x, y): halign 0 left, 0.5 centre, 1 right. */
void wl_report_text_draw(struct wl_report_doc *d, enum font font, double size, double x, double y,
               const char *s, double halign, enum valign valign);

/* Same, rotated by `angle` [rad] about the anchor (-pi/2: reads upwards). */
void wl_report_text_draw_rotated(struct wl_report_doc *d, enum font font, double size, double x,
                       double y, double angle, const char *s, double halign,
                       enum valign valign);

/* One line of broken text: bytes [start, start + len) of the input. */
struct text_span {
  size_t start, len;
};

/* Break s into lines at most `width` [pt] wide (words; characters where a
 * word is too long; '\n' always breaks). *lines is malloc'ed (free it).
 * Returns WL_OK or WL_ENOMEM. */
enum wl_status wl_report_text_break(struct wl_report_doc *d, enum font font, double size, double width,
                          const char *s, struct text_span **lines, size_t *n_lines,
                          struct wl_error *err);

/* Draw bytes [start, start + len) of s at baseline y. */
void wl_report_text_draw_span(struct wl_report_doc *d, enum font font, double size, double x, double y,
                    const char *s, struct text_span span);

/* ---- shared drawing helpers (plot.c) ---- */

#define TICK_LEN 3.0  /* major tick [pt] */
#define MINOR_LEN 1.8 /* minor tick [pt] */
#define LABEL_GAP 2.5 /* tick to its label [pt] */
#define FRAME_WIDTH 0.6

/* Data range [lo, hi] of an axis on the page: lo at p0, hi at p1. */
struct axis_map {
  double lo, hi;
  int log;
  double p0, p1;
};

static inline double axis_to_page(const struct axis_map *m, double v) {
  double a = m->log ? log10(m->lo) : m->lo, b = m->log ? log10(m->hi) : m->hi;
  double f = m->log ? log10(v) : v;
  return m->p0 + (f - a) / (b - a) * (m->p1 - m->p0);
}

/* Ticks and labels below a horizontal axis at y_axis (grid up to y_top), or
 * left of a vertical axis at x_axis (grid to x_right). */
void wl_report_draw_x_ticks(struct wl_report_doc *d, const struct wl_report_ticks *t,
                            const struct axis_map *mx, double y_axis, double y_top, int grid);
void wl_report_draw_y_ticks(struct wl_report_doc *d, const struct wl_report_ticks *t,
                            const struct axis_map *my, double x_axis, double x_right, int grid);

/* Widest tick label [pt]. */
double wl_report_ticks_width(struct wl_report_doc *d, const struct wl_report_ticks *t);

void wl_report_set_rgb(cairo_t *cr, const double rgb[3]);

/* "label [unit]", "label [10⁻³ unit]" with a tick scale, or "label". */
void wl_report_axis_title(const struct wl_report_axis *a, int scale_exp, char *buf, size_t size);

#endif
