/* draw.h: the report module's page, table and plot toolkit, public so that
 * the report's section renderers and `validate`'s PDF draw with one
 * toolkit. No cairo types appear here (library headers stay in src/), so a
 * caller needs no cairo include path; the report's renderers that need raw
 * cairo include src/report/doc.h.
 *
 * Model. A document (struct wl_report_doc, opaque) is an A4 portrait PDF
 * written with cairo's PDF surface (vector output, fonts subset and embedded
 * by cairo). Every page has margins, a running header (scenario name, report
 * title) and footer (wallload version, company, page number). Blocks flow
 * down a vertical cursor: headings, paragraphs, preformatted text, tables and
 * figure areas; a block that does not fit starts a new page (tables and
 * paragraphs continue across pages, tables repeat their header). A figure
 * area is a rectangle reserved on the page into which the plot functions
 * draw: x-y plots (wl_report_draw_plot), colour-mapped particle fields
 * (wl_report_draw_field) and scene sketches (wl_report_draw_scene). Several
 * plots can share one figure area (wl_report_rect_cell).
 *
 * Coordinates are PDF points (1/72 in) from the top-left page corner, y down.
 * Data come as double arrays; NaN or infinite values are gaps, empty series
 * are skipped, and a plot with no drawable data says "no data".
 *
 * Errors. Every fallible call returns enum wl_status and fills the caller's
 * struct wl_error. The first error also marks the document failed: later
 * calls return the same status without drawing, and wl_report_doc_finish
 * then removes the partial file, so a renderer may check once at the end.
 * Cairo's status is checked at every page end and at finish. Nothing prints. */
#ifndef WALLLOAD_DRAW_H
#define WALLLOAD_DRAW_H

#include <stddef.h>

#include "wallload/error.h"

#define WL_REPORT_PT_PER_MM (72.0 / 25.4) /* PDF points per millimetre */

struct wl_report_doc; /* opaque: one PDF being written */

/* A rectangle on the page [pt], y down from the page's top edge. */
struct wl_report_rect {
  double x, y, w, h;
};

/* ---- document ------------------------------------------------------------ */

struct wl_report_doc_info {
  const char *title;    /* report title: running header and PDF metadata; NULL: none */
  const char *scenario; /* scenario name: running header; NULL: none */
  const char *company;  /* running footer and PDF author; NULL or "": none */
  const char *version;  /* wallload version for the footer; NULL: this build's */
};

/* Create the PDF `path` (written as path.part, renamed by finish) and return
 * it in *out. info may be NULL. Returns WL_OK, WL_EIO (the file cannot be
 * created), WL_ENOMEM or WL_EINPUT (path too long). On failure *out is NULL
 * and no file is left. */
enum wl_status wl_report_doc_open(const char *path, const struct wl_report_doc_info *info,
                                  struct wl_report_doc **out, struct wl_error *err);

/* End the last page, write the PDF and move it to its final path. A document
 * with no content gets one page (header and footer only). Returns WL_OK,
 * WL_EIO (cairo could not write, or the rename failed; the partial file is
 * removed), or the status of an earlier failed call (partial file removed).
 * The document must still be freed. */
enum wl_status wl_report_doc_finish(struct wl_report_doc *d, struct wl_error *err);

/* Free the document; if it was not finished, its partial file is removed.
 * NULL is safe. */
void wl_report_doc_free(struct wl_report_doc *d);

/* Pages started so far (the page number of the current page). */
int wl_report_doc_pages(const struct wl_report_doc *d);

/* The content box of every page (inside margins, header and footer). */
struct wl_report_rect wl_report_doc_content(const struct wl_report_doc *d);

/* Vertical space left on the current page below the cursor [pt] (the whole
 * content height when no page is open yet), less what waiting headings take. */
double wl_report_doc_space_left(struct wl_report_doc *d);

/* ---- flowing blocks ------------------------------------------------------- */

/* End the current page; the next block starts a new one. No-op when the
 * current page is still empty. Returns WL_OK or a cairo failure (WL_EIO,
 * WL_ENOMEM). */
enum wl_status wl_report_break_page(struct wl_report_doc *d, struct wl_error *err);

/* Title page block: `title` large, `subtitle` (may be NULL) below. */
enum wl_status wl_report_add_title(struct wl_report_doc *d, const char *title,
                                   const char *subtitle, struct wl_error *err);

/* Heading of `level` 1 (numbered "3", a PDF bookmark), 2 (numbered "3.1",
 * bookmark) or 3 (unnumbered, bold). Kept with the next block: the heading
 * waits and is placed by the next block (paragraph, table, figure, reserve),
 * on the page that block starts on (or by finish). Returns WL_EINPUT for
 * another level. */
enum wl_status wl_report_add_heading(struct wl_report_doc *d, int level, const char *text,
                                     struct wl_error *err);

/* Paragraph of UTF-8 text wrapped to the content width; '\n' breaks a line.
 * Continues on the next page where needed. */
enum wl_status wl_report_add_paragraph(struct wl_report_doc *d, const char *text,
                                       struct wl_error *err);

/* Preformatted text (monospace, small): lines kept as given, long lines
 * wrapped; for listings such as the scenario file. */
enum wl_status wl_report_add_preformatted(struct wl_report_doc *d, const char *text,
                                          struct wl_error *err);

/* Reserve a `height` [pt] band of the content width at the cursor (new page
 * when it does not fit; clamped to a page), return it in *area and move the
 * cursor below it. Draw into it with the wl_report_draw_* functions. */
enum wl_status wl_report_reserve(struct wl_report_doc *d, double height,
                                 struct wl_report_rect *area, struct wl_error *err);

/* Figure: reserve `height` [pt] plus room for a caption (so the caption stays
 * on the figure's page); end_figure prints "Figure N. caption" below it.
 * Returns WL_EINPUT when end is called without begin or begin twice. */
enum wl_status wl_report_begin_figure(struct wl_report_doc *d, double height,
                                      struct wl_report_rect *area, struct wl_error *err);
enum wl_status wl_report_end_figure(struct wl_report_doc *d, const char *caption,
                                    struct wl_error *err);

/* Sub-rectangle `index` (row-major) of an n_cols x n_rows grid over r with
 * `gap` [pt] between cells. */
struct wl_report_rect wl_report_rect_cell(struct wl_report_rect r, int n_cols, int n_rows,
                                          int index, double gap);

/* ---- tables ---------------------------------------------------------------- */

enum wl_report_align {
  WL_REPORT_ALIGN_AUTO,    /* numbers: decimal point; text: left */
  WL_REPORT_ALIGN_LEFT,
  WL_REPORT_ALIGN_CENTRE,
  WL_REPORT_ALIGN_RIGHT,
  WL_REPORT_ALIGN_DECIMAL, /* numbers lined up on the decimal point */
};

struct wl_report_column {
  const char *header;         /* column heading; NULL: none */
  const char *unit;           /* units row, printed "[unit]"; NULL: none */
  enum wl_report_align align; /* AUTO by default */
  int sig;                    /* significant digits of numeric cells; 0: 3 */
};

/* One cell: text when `text` is not NULL, otherwise the number `value`
 * formatted to the column's significant digits (NaN prints "n/a"). */
struct wl_report_cell {
  const char *text;
  double value;
};

struct wl_report_table {
  const char *caption;                  /* "Table N. caption" above; NULL: no caption */
  const struct wl_report_column *cols;  /* n_cols column descriptions */
  int n_cols;                           /* 1..WL_REPORT_TABLE_MAX_COLS */
  const struct wl_report_cell *cells;   /* n_rows * n_cols cells, row-major */
  int n_rows;                           /* >= 0 */
};

enum { WL_REPORT_TABLE_MAX_COLS = 16 };

/* Table with header row, units row (when any column has a unit), rules,
 * aligned columns; breaks across pages repeating the header. Text shrinks
 * (down to 6.5 pt) when the natural width exceeds the page. Returns WL_OK or
 * WL_EINPUT (no columns, too many, cells NULL with rows, still too wide). */
enum wl_status wl_report_add_table(struct wl_report_doc *d, const struct wl_report_table *t,
                                   struct wl_error *err);

/* One key-value row: `text` when not NULL, else `value` to `sig` digits
 * (0: 3) followed by `unit` (may be NULL). */
struct wl_report_kv {
  const char *key;
  const char *text;
  double value;
  const char *unit;
  int sig;
};

/* Key-value table (key, value, unit), numbers on their decimal points. */
enum wl_status wl_report_add_kv_table(struct wl_report_doc *d, const char *caption,
                                      const struct wl_report_kv *rows, int n_rows,
                                      struct wl_error *err);

/* ---- x-y plots -------------------------------------------------------------- */

enum wl_report_line {
  WL_REPORT_LINE_AUTO,    /* by series order: solid, dashed, dotted, dash-dot */
  WL_REPORT_LINE_SOLID,
  WL_REPORT_LINE_DASHED,
  WL_REPORT_LINE_DOTTED,
  WL_REPORT_LINE_DASHDOT,
  WL_REPORT_LINE_NONE,    /* markers only (scatter) */
};

enum wl_report_marker {
  WL_REPORT_MARKER_NONE,
  WL_REPORT_MARKER_AUTO, /* by series order: circle, square, triangle, diamond, cross */
  WL_REPORT_MARKER_CIRCLE,
  WL_REPORT_MARKER_SQUARE,
  WL_REPORT_MARKER_TRIANGLE,
  WL_REPORT_MARKER_DIAMOND,
  WL_REPORT_MARKER_CROSS,
};

struct wl_report_series {
  const char *label;            /* legend text; NULL or "": not in the legend */
  const double *x, *y;          /* n values each (may be NULL when n is 0) */
  size_t n;
  enum wl_report_line line;     /* AUTO by default */
  enum wl_report_marker marker; /* NONE by default */
  int colour;                   /* 0: by series order; k >= 1: palette entry k */
};

struct wl_report_axis {
  const char *label; /* quantity ("wall force"); NULL: none */
  const char *unit;  /* printed "label [unit]"; NULL or "": none */
  int log;           /* 1: logarithmic (non-positive values are gaps) */
  int fixed;         /* 1: range is [min, max]; 0: nice range covering the data */
  double min, max;
};

/* A labelled reference line across the plot: horizontal at y = `at`
 * (default) or vertical at x = `at`. Its position is kept inside the range. */
struct wl_report_refline {
  double at;
  const char *label; /* may be NULL */
  int vertical;      /* 1: x = at */
};

enum wl_report_legend {
  WL_REPORT_LEGEND_AUTO,  /* inside, in a corner that hides no point; else below */
  WL_REPORT_LEGEND_NONE,
  WL_REPORT_LEGEND_BELOW, /* under the plot, in columns */
};

struct wl_report_plot {
  const char *title; /* above the plot; NULL: none */
  struct wl_report_axis x, y;
  const struct wl_report_series *series;
  int n_series;
  const struct wl_report_refline *refs;
  int n_refs;
  enum wl_report_legend legend;
};

/* Draw an x-y plot into r (axes, nice ticks, grid, series, reference lines,
 * legend). Long monotonic series are thinned to a min/max envelope per
 * 1/4 pt, which keeps every peak. Returns WL_OK, or WL_EINPUT for a series
 * with n > 0 and NULL data, or a fixed range with min >= max (or <= 0 on a
 * log axis). */
enum wl_status wl_report_draw_plot(struct wl_report_doc *d, const struct wl_report_plot *p,
                                   struct wl_report_rect r, struct wl_error *err);

/* ---- particle field ----------------------------------------------------------- */

/* Particles (x, z) coloured by `value` through a viridis map with a colour
 * bar, at true aspect ratio (1 m across = 1 m up). */
struct wl_report_field {
  const char *title;           /* NULL: none */
  const double *x, *z, *value; /* n each; NaN x or z: skipped; NaN value: grey */
  size_t n;
  double radius;               /* particle half-size [m] (dp/2); 0: from the density of points */
  struct wl_report_axis x_axis, z_axis; /* labels; `fixed` crops to a window; log ignored */
  const char *value_label, *value_unit; /* colour bar title */
  int fixed_range;             /* 1: colours span [vmin, vmax]; 0: the data's range */
  double vmin, vmax;
};

/* Draw a field into r (the drawing keeps true aspect and is placed at r's top
 * left). Returns WL_OK or WL_EINPUT (n > 0 with NULL arrays, bad fixed range).
 * Above WL_REPORT_FIELD_VECTOR_MAX particles the dots are rasterised at
 * WL_REPORT_FIELD_DPI (axes and text stay vector). */
enum wl_status wl_report_draw_field(struct wl_report_doc *d, const struct wl_report_field *f,
                                    struct wl_report_rect r, struct wl_error *err);

/* The height [pt] a field drawn `width` [pt] wide needs (true aspect). */
double wl_report_field_fit_height(const struct wl_report_field *f, double width);

enum { WL_REPORT_FIELD_VECTOR_MAX = 60000, WL_REPORT_FIELD_DPI = 300 };

/* ---- scene sketch --------------------------------------------------------------- */

enum wl_report_shape_kind {
  WL_REPORT_SHAPE_LINE,    /* open polyline (free surface, paddle path) */
  WL_REPORT_SHAPE_WATER,   /* closed polygon, water fill */
  WL_REPORT_SHAPE_BED,     /* closed polygon, sand fill */
  WL_REPORT_SHAPE_WALL,    /* closed polygon, concrete fill */
  WL_REPORT_SHAPE_OUTLINE, /* closed polygon, no fill */
};

struct wl_report_shape {
  enum wl_report_shape_kind kind;
  const double *x, *z; /* n vertices [m]; a NaN vertex breaks the outline */
  size_t n;
};

/* A labelled point (gauge, probe): a small triangle pointing down at (x, z). */
struct wl_report_mark {
  double x, z;
  const char *label;
};

struct wl_report_scene {
  const char *title; /* NULL: none */
  const struct wl_report_shape *shapes; /* drawn in order (painter's) */
  int n_shapes;
  const struct wl_report_mark *marks;
  int n_marks;
  struct wl_report_axis x_axis; /* `fixed`: horizontal window; `unit`: of the
                                   scale bar (NULL: "m"); label: axis title */
  int axes;                     /* 1: x axis with ticks under the drawing */
  double exaggeration;          /* vertical / horizontal scale; 0 or 1: true aspect */
};

/* Draw a scene into r, with a scale bar (and a vertical one when
 * exaggerated). Returns WL_OK or WL_EINPUT (NULL vertices with n > 0). */
enum wl_status wl_report_draw_scene(struct wl_report_doc *d, const struct wl_report_scene *s,
                                    struct wl_report_rect r, struct wl_error *err);

/* The height [pt] a scene drawn `width` [pt] wide needs. */
double wl_report_scene_fit_height(const struct wl_report_scene *s, double width);

/* ---- numbers, ticks, colours (pure functions) ------------------------------------ */

/* Format v to `sig` significant digits (1..15; others: 3): fixed notation for
 * 1e-3 <= |v| < 1e6 ("12300", "0.000123", "-0.500"), else "1.50×10⁻⁷" (UTF-8
 * superscripts); 0 prints "0", NaN "n/a", infinities "inf" / "-inf". */
void wl_report_format_sig(double v, int sig, char *buf, size_t size);

/* Superscript form of an integer ("⁻³") in UTF-8. */
void wl_report_format_superscript(int n, char *buf, size_t size);

enum { WL_REPORT_TICKS_MAX = 24, WL_REPORT_MINOR_MAX = 96, WL_REPORT_TICK_LABEL = 32 };

struct wl_report_ticks {
  double lo, hi;  /* axis range (covers the data when asked to) */
  double step;    /* linear: tick spacing; log: decades between major ticks */
  int n;          /* major ticks */
  double at[WL_REPORT_TICKS_MAX];
  char label[WL_REPORT_TICKS_MAX][WL_REPORT_TICK_LABEL]; /* UTF-8 */
  int n_minor;    /* unlabelled minor ticks (log axes) */
  double minor[WL_REPORT_MINOR_MAX];
  int scale_exp;  /* labels show value / 10^scale_exp; 0: none */
};

/* Linear ticks at 1-2-5 steps with at most `max_intervals` (2..20; others:
 * 6) intervals. cover = 1: the range grows to multiples of the step around
 * [lo, hi]; cover = 0: the range stays [lo, hi], ticks fall inside it.
 * Labels share one number of decimals; very large or small ranges are
 * labelled in units of 10^scale_exp (a multiple of 3). Degenerate input
 * (lo == hi, reversed, non-finite) gives a sensible range, never fails. */
void wl_report_ticks_linear(double lo, double hi, int max_intervals, int cover,
                            struct wl_report_ticks *t);

/* Log ticks at decades (every 1, 2, 5, ... decades for wide ranges; with 2
 * and 5 as well within two decades), minor ticks at 2..9. The range covers
 * [lo, hi] with whole decades when cover = 1, else stays [lo, hi]. Labels are
 * plain numbers between 0.01 and 1000, else powers "10⁵". Returns WL_OK or
 * WL_EINPUT when lo or hi is not positive and finite. */
enum wl_status wl_report_ticks_log(double lo, double hi, int cover, struct wl_report_ticks *t,
                                   struct wl_error *err);

/* Viridis colour map (matplotlib's, piecewise linear through 11 of its
 * entries): t in [0, 1] (clamped; NaN gives grey) to sRGB in [0, 1]. */
void wl_report_colormap(double t, double rgb[3]);

/* Series palette entry k >= 1 (Okabe-Ito colours, starting with black). */
void wl_report_palette(int k, double rgb[3]);

/* Thin a series for drawing: split [x0, x1] into n_bins bins and keep, per
 * bin and run of valid points, the indices of the first, smallest, largest
 * and last y, in index order; one invalid point (NaN x or y) is kept between
 * runs as the gap. x must be non-decreasing over the valid points. keep[]
 * needs room for n indices; returns how many were written (<= n, and at
 * most 4 per bin per run). */
size_t wl_report_thin(const double *x, const double *y, size_t n, double x0, double x1,
                      size_t n_bins, size_t *keep);

#endif
