/* table.c: tables in the booktabs manner (top, middle and bottom rules, no
 * vertical lines): a header row, a units row, numbers formatted to
 * significant digits and lined up on their decimal points, page breaks that
 * repeat the header; key-value tables on the same machinery. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "doc.h"

#define CELL_PAD 5.0       /* left and right of every cell [pt] */
#define ROW_LEADING 1.45   /* row height / type size */
#define SIZE_MIN 6.5       /* smallest type a wide table shrinks to [pt] */
#define SIZE_STEP 0.5
#define RULE_HEAVY 0.8
#define RULE_LIGHT 0.45
#define CELL_BYTES 64      /* bytes of a formatted number */
#define DEFAULT_SIG 3
#define WRAP_MIN_W 60.0    /* narrowest text a too-wide table's words wrap into [pt] */

struct tcell {
  const char *text;     /* what is printed (points into buf or the caller's text) */
  char buf[CELL_BYTES];  /* formatted number */
  int numeric;
};

struct tcol {
  enum wl_report_align align;
  double width;          /* including padding [pt] */
  double int_w, frac_w;  /* decimal alignment: widest part left and right of the point */
};

/* Bytes before the decimal point (or the "×" of a power of ten, or the end). */
static size_t int_part(const char *s) {
  const char *dot = strchr(s, '.');
  if (dot) return (size_t)(dot - s);
  const char *times = strstr(s, "\xc3\x97");
  return times ? (size_t)(times - s) : strlen(s);
}

static double prefix_width(struct wl_report_doc *d, enum font font, double size, const char *s,
                           size_t len) {
  char buf[CELL_BYTES + 8];
  if (len >= sizeof buf) len = sizeof buf - 1;
  memcpy(buf, s, len);
  buf[len] = '\0';
  return wl_report_text_width(d, font, size, buf);
}

static int any_header(const struct wl_report_column *cols, int n) {
  for (int c = 0; c < n; c++)
    if (cols[c].header && cols[c].header[0]) return 1;
  return 0;
}

static int any_unit(const struct wl_report_column *cols, int n) {
  for (int c = 0; c < n; c++)
    if (cols[c].unit && cols[c].unit[0]) return 1;
  return 0;
}

static double measure(struct wl_report_doc *d, const struct wl_report_column *cols, int n_cols,
                      const struct tcell *cells, int n_rows, double size, struct tcol *tc) {
  double unit_size = size * SIZE_SMALL / SIZE_TABLE, total = 0;
  for (int c = 0; c < n_cols; c++) {
    double w = 0, iw = 0, fw = 0;
    int numeric = 0;
    if (cols[c].header) w = fmax(w, wl_report_text_width(d, FONT_BOLD, size, cols[c].header));
    if (cols[c].unit && cols[c].unit[0]) {
      char u[256];
      snprintf(u, sizeof u, "[%s]", cols[c].unit);
      w = fmax(w, wl_report_text_width(d, FONT_SANS, unit_size, u));
    }
    for (int r = 0; r < n_rows; r++) {
      const struct tcell *cell = &cells[(size_t)r * n_cols + c];
      if (cell->numeric) {
        numeric = 1;
        size_t k = int_part(cell->text);
        iw = fmax(iw, prefix_width(d, FONT_SANS, size, cell->text, k));
        fw = fmax(fw, wl_report_text_width(d, FONT_SANS, size, cell->text + k));
      } else {
        w = fmax(w, wl_report_text_width(d, FONT_SANS, size, cell->text));
      }
    }
    enum wl_report_align a = cols[c].align;
    if (a == WL_REPORT_ALIGN_AUTO) a = numeric ? WL_REPORT_ALIGN_DECIMAL : WL_REPORT_ALIGN_LEFT;
    if (a == WL_REPORT_ALIGN_DECIMAL) {
      w = fmax(w, iw + fw);
    } else {
      for (int r = 0; r < n_rows; r++) {
        const struct tcell *cell = &cells[(size_t)r * n_cols + c];
        if (cell->numeric) w = fmax(w, wl_report_text_width(d, FONT_SANS, size, cell->text));
      }
    }
    tc[c].align = a;
    tc[c].int_w = iw;
    tc[c].frac_w = fw;
    tc[c].width = w + 2.0 * CELL_PAD;
    total += tc[c].width;
  }
  return total;
}

enum cell_kind { CELL_TEXT, CELL_NUMBER, CELL_HEAD };

/* Text in a column box [x, x + w] by the column's alignment. In a decimal
 * column, numbers line up on the point, headings and units sit right (over
 * the numbers), words sit left (a key-value table's text values). */
static void put(struct wl_report_doc *d, enum font font, double size, const struct tcol *c,
                double x, double baseline, const char *s, enum cell_kind kind) {
  double left = x + CELL_PAD, right = x + c->width - CELL_PAD;
  switch (c->align) {
  case WL_REPORT_ALIGN_LEFT: wl_report_text_draw(d, font, size, left, baseline, s, 0.0, VALIGN_BASELINE); break;
  case WL_REPORT_ALIGN_CENTRE:
    wl_report_text_draw(d, font, size, 0.5 * (left + right), baseline, s, 0.5, VALIGN_BASELINE);
    break;
  case WL_REPORT_ALIGN_DECIMAL:
    if (kind == CELL_NUMBER) {
      /* The decimal point sits where the widest integer part ends. */
      double point = right - c->frac_w;
      size_t k = int_part(s);
      double iw = prefix_width(d, font, size, s, k);
      wl_report_text_draw(d, font, size, point - iw, baseline, s, 0.0, VALIGN_BASELINE);
      break;
    }
    if (kind == CELL_TEXT) {
      wl_report_text_draw(d, font, size, left, baseline, s, 0.0, VALIGN_BASELINE);
      break;
    }
    /* fall through */
  default: wl_report_text_draw(d, font, size, right, baseline, s, 1.0, VALIGN_BASELINE); break;
  }
}

static void rule(cairo_t *cr, double x, double w, double y, double width) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, width);
  cairo_move_to(cr, x, y);
  cairo_line_to(cr, x + w, y);
  cairo_stroke(cr);
}

/* Header and units rows with their rules, at the cursor. */
static void draw_head(struct wl_report_doc *d, const struct wl_report_column *cols,
                      const struct tcol *tc, int n_cols, double size, double table_w) {
  cairo_t *cr = d->cr;
  double x0 = MARGIN_X, unit_size = size * SIZE_SMALL / SIZE_TABLE;
  rule(cr, x0, table_w, d->y, RULE_HEAVY);
  d->y += 2.0;
  int has_h = any_header(cols, n_cols), has_u = any_unit(cols, n_cols);
  if (has_h) {
    double x = x0;
    for (int c = 0; c < n_cols; c++) {
      if (cols[c].header) put(d, FONT_BOLD, size, &tc[c], x, d->y + 0.75 * ROW_LEADING * size, cols[c].header, CELL_HEAD);
      x += tc[c].width;
    }
    d->y += ROW_LEADING * size;
  }
  if (has_u) {
    double x = x0;
    for (int c = 0; c < n_cols; c++) {
      if (cols[c].unit && cols[c].unit[0]) {
        char u[256];
        snprintf(u, sizeof u, "[%s]", cols[c].unit);
        put(d, FONT_SANS, unit_size, &tc[c], x, d->y + 0.8 * ROW_LEADING * unit_size, u, CELL_HEAD);
      }
      x += tc[c].width;
    }
    d->y += ROW_LEADING * unit_size;
  }
  if (has_h || has_u) {
    d->y += 1.0;
    rule(cr, x0, table_w, d->y, RULE_LIGHT);
    d->y += 2.0;
  }
}

static double head_height(const struct wl_report_column *cols, int n_cols, double size) {
  double h = 2.0;
  if (any_header(cols, n_cols)) h += ROW_LEADING * size;
  if (any_unit(cols, n_cols)) h += ROW_LEADING * size * SIZE_SMALL / SIZE_TABLE;
  if (any_header(cols, n_cols) || any_unit(cols, n_cols)) h += 3.0;
  return h;
}

static enum wl_status draw_table(struct wl_report_doc *d, const char *caption,
                                 const struct wl_report_column *cols, int n_cols,
                                 const struct tcell *cells, int n_rows, struct wl_error *err) {
  struct tcol tc[WL_REPORT_TABLE_MAX_COLS];
  enum wl_status st = wl_report_doc_ensure_page(d, err);
  if (st != WL_OK) return st;
  double size = SIZE_TABLE, total = measure(d, cols, n_cols, cells, n_rows, size, tc);
  while (total > CONTENT_W && size - SIZE_STEP >= SIZE_MIN - 1e-9) {
    size -= SIZE_STEP;
    total = measure(d, cols, n_cols, cells, n_rows, size, tc);
  }
  /* Still too wide at the smallest type: the widest left-aligned column
   * (words: a note, a reason) takes the width the others leave and its
   * cells wrap onto more lines. */
  int wrap_col = -1;
  if (total > CONTENT_W) {
    for (int c = 0; c < n_cols; c++)
      if (tc[c].align == WL_REPORT_ALIGN_LEFT && (wrap_col < 0 || tc[c].width > tc[wrap_col].width))
        wrap_col = c;
    const double avail = wrap_col < 0 ? 0 : CONTENT_W - (total - tc[wrap_col].width);
    if (avail < 2.0 * CELL_PAD + WRAP_MIN_W)
      return wl_report_doc_fail(d, err, WL_EINPUT,
                                "%s: table '%s': %d columns need %.0f mm at %.1f pt; the page has "
                                "%.0f mm",
                                d->path, caption ? caption : "", n_cols,
                                total / WL_REPORT_PT_PER_MM, size, CONTENT_W / WL_REPORT_PT_PER_MM);
    tc[wrap_col].width = avail;
    total = CONTENT_W;
  }
  double row_h = ROW_LEADING * size, head_h = head_height(cols, n_cols, size);
  int first_rows = n_rows < 3 ? n_rows : 3;
  /* Caption, header and the first rows stay together. */
  double cap_h = caption ? 2.0 * LEADING * SIZE_SMALL : 0.0;
  st = wl_report_doc_need(d, cap_h + head_h + first_rows * row_h + 4.0, err);
  if (st != WL_OK) return st;
  cairo_t *cr = d->cr;
  if (caption) {
    d->n_tables++;
    char text[1024];
    snprintf(text, sizeof text, "Table %d. %s", d->n_tables, caption);
    struct text_span *lines = NULL;
    size_t n = 0;
    st = wl_report_text_break(d, FONT_SANS, SIZE_SMALL, CONTENT_W, text, &lines, &n, err);
    if (st != WL_OK) {
      d->failed = st;
      return st;
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    for (size_t i = 0; i < n; i++) {
      wl_report_text_draw_span(d, FONT_SANS, SIZE_SMALL, MARGIN_X,
                               d->y + 0.75 * LEADING * SIZE_SMALL, text, lines[i]);
      d->y += LEADING * SIZE_SMALL;
    }
    free(lines);
    d->y += 2.0;
  }
  draw_head(d, cols, tc, n_cols, size, total);
  for (int r = 0; r < n_rows; r++) {
    struct text_span *wrapped = NULL;
    size_t n_wrapped = 1;
    if (wrap_col >= 0) {
      st = wl_report_text_break(d, FONT_SANS, size, tc[wrap_col].width - 2.0 * CELL_PAD,
                                cells[(size_t)r * n_cols + wrap_col].text, &wrapped, &n_wrapped,
                                err);
      if (st != WL_OK) {
        d->failed = st;
        return st;
      }
      if (n_wrapped < 1) n_wrapped = 1;
    }
    const double this_h = row_h * (double)n_wrapped;
    if (d->y + this_h + 2.0 > CONTENT_BOTTOM) {
      rule(cr, MARGIN_X, total, d->y + 1.0, RULE_LIGHT);
      st = wl_report_break_page(d, err);
      if (st == WL_OK) st = wl_report_doc_ensure_page(d, err);
      if (st != WL_OK) {
        free(wrapped);
        return st;
      }
      draw_head(d, cols, tc, n_cols, size, total);
    }
    double x = MARGIN_X, baseline = d->y + 0.75 * row_h;
    cairo_set_source_rgb(cr, 0, 0, 0);
    for (int c = 0; c < n_cols; c++) {
      const struct tcell *cell = &cells[(size_t)r * n_cols + c];
      if (c == wrap_col && wrapped)
        for (size_t k = 0; k < n_wrapped; k++)
          wl_report_text_draw_span(d, FONT_SANS, size, x + CELL_PAD, baseline + (double)k * row_h,
                                   cell->text, wrapped[k]);
      else
        put(d, FONT_SANS, size, &tc[c], x, baseline, cell->text,
            cell->numeric ? CELL_NUMBER : CELL_TEXT);
      x += tc[c].width;
    }
    free(wrapped);
    d->y += this_h;
  }
  d->y += 1.0;
  rule(cr, MARGIN_X, total, d->y, RULE_HEAVY);
  d->y += 1.5 * GAP_BLOCK;
  return WL_OK;
}

enum wl_status wl_report_add_table(struct wl_report_doc *d, const struct wl_report_table *t,
                                   struct wl_error *err) {
  enum wl_status st = wl_report_doc_usable(d, err);
  if (st != WL_OK) return st;
  if (!t) return wl_report_doc_fail(d, err, WL_EINPUT, "%s: table: none given (NULL)", d->path);
  const char *name = t->caption ? t->caption : "";
  if (t->n_cols < 1 || t->n_cols > WL_REPORT_TABLE_MAX_COLS || !t->cols)
    return wl_report_doc_fail(d, err, WL_EINPUT, "%s: table '%s': found %d columns; valid: 1 to %d",
                              d->path, name, t->n_cols, WL_REPORT_TABLE_MAX_COLS);
  if (t->n_rows < 0 || (t->n_rows > 0 && !t->cells))
    return wl_report_doc_fail(d, err, WL_EINPUT, "%s: table '%s': %d rows but no cells", d->path,
                              name, t->n_rows);
  size_t n = (size_t)t->n_rows * (size_t)t->n_cols;
  struct tcell *cells = calloc(n > 0 ? n : 1, sizeof *cells);
  if (!cells)
    return wl_report_doc_fail(d, err, WL_ENOMEM, "%s: table '%s': no memory for %zu cells",
                              d->path, name, n);
  for (size_t i = 0; i < n; i++) {
    const struct wl_report_cell *in = &t->cells[i];
    int c = (int)(i % (size_t)t->n_cols);
    if (in->text) {
      cells[i].text = in->text;
    } else {
      int sig = t->cols[c].sig > 0 ? t->cols[c].sig : DEFAULT_SIG;
      wl_report_format_sig(in->value, sig, cells[i].buf, sizeof cells[i].buf);
      cells[i].text = cells[i].buf;
      cells[i].numeric = 1;
    }
  }
  st = draw_table(d, t->caption, t->cols, t->n_cols, cells, t->n_rows, err);
  free(cells);
  return st;
}

enum wl_status wl_report_add_kv_table(struct wl_report_doc *d, const char *caption,
                                      const struct wl_report_kv *rows, int n_rows,
                                      struct wl_error *err) {
  enum wl_status st = wl_report_doc_usable(d, err);
  if (st != WL_OK) return st;
  if (n_rows < 0 || (n_rows > 0 && !rows))
    return wl_report_doc_fail(d, err, WL_EINPUT, "%s: key-value table '%s': %d rows but no data",
                              d->path, caption ? caption : "", n_rows);
  static const struct wl_report_column cols[3] = {
      {NULL, NULL, WL_REPORT_ALIGN_LEFT, 0},
      {NULL, NULL, WL_REPORT_ALIGN_DECIMAL, 0},
      {NULL, NULL, WL_REPORT_ALIGN_LEFT, 0}};
  struct tcell *cells = calloc((size_t)(n_rows > 0 ? n_rows : 1) * 3, sizeof *cells);
  if (!cells)
    return wl_report_doc_fail(d, err, WL_ENOMEM, "%s: key-value table: no memory", d->path);
  for (int r = 0; r < n_rows; r++) {
    struct tcell *c = &cells[3 * r];
    c[0].text = rows[r].key ? rows[r].key : "";
    if (rows[r].text) {
      c[1].text = rows[r].text;
    } else {
      wl_report_format_sig(rows[r].value, rows[r].sig > 0 ? rows[r].sig : DEFAULT_SIG, c[1].buf,
                           sizeof c[1].buf);
      c[1].text = c[1].buf;
      c[1].numeric = 1;
    }
    c[2].text = rows[r].unit ? rows[r].unit : "";
  }
  st = draw_table(d, caption, cols, 3, cells, n_rows, err);
  free(cells);
  return st;
}
