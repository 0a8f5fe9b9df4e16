/* page.c: the report document: an A4 PDF written with cairo, its pages with
 * running header and footer, and the vertical cursor that flowing blocks
 * (title, headings, paragraphs, preformatted text, reserved areas, figures)
 * move down. Cairo's status is checked at every page end and at finish; the
 * file is written as PATH.part and renamed only when complete. Cairo writes
 * through write_out to a descriptor of ours, so that a refused write is
 * reported with the system's reason (a full disk), and the file is synced
 * and its close checked before the rename. */
#define _POSIX_C_SOURCE 200809L /* fsync */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <unistd.h>

#include <cairo-pdf.h>

#include "doc.h"
#include "wallload/config.h"
#include "wallload/store.h"

#define CAPTION_ROOM (2.0 * LEADING * SIZE_SMALL + 6.0) /* room kept for a caption [pt] */
#define RULE_GREY 0.55
#define RUNNING_GREY 0.35

static double pending_height(struct wl_report_doc *d);

static void copy_text(char *dst, size_t size, const char *src) {
  snprintf(dst, size, "%s", src ? src : "");
}

cairo_t *wl_report_doc_cairo(struct wl_report_doc *d) { return d->cr; }

enum wl_status wl_report_doc_fail(struct wl_report_doc *d, struct wl_error *err,
                                  enum wl_status st, const char *fmt, ...) {
  char msg[WL_ERROR_MSG_MAX];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  if (d && d->failed == WL_OK) d->failed = st;
  return wl_error_set(err, st, "%s", msg);
}

enum wl_status wl_report_doc_usable(struct wl_report_doc *d, struct wl_error *err) {
  if (!d) return wl_error_set(err, WL_EINPUT, "report: no document (NULL)");
  if (d->finished)
    return wl_error_set(err, WL_EINPUT, "%s: the document is already finished", d->path);
  if (d->failed != WL_OK)
    return wl_error_set(err, d->failed, "%s: not drawn: an earlier report call failed (%s)",
                        d->path, wl_error_status_name(d->failed));
  return WL_OK;
}

/* Cairo keeps the first error in the context or surface; turn it into ours.
 * A write the system refused is named with its reason. */
static enum wl_status check_cairo(struct wl_report_doc *d, struct wl_error *err,
                                  const char *what) {
  cairo_status_t cs = d->cr ? cairo_status(d->cr) : CAIRO_STATUS_SUCCESS;
  if (cs == CAIRO_STATUS_SUCCESS) cs = cairo_surface_status(d->surface);
  if (cs == CAIRO_STATUS_SUCCESS) return WL_OK;
  if (d->io_errno)
    return wl_report_doc_fail(d, err, WL_EIO, "%s: cannot write %s (page %d, %s): %s", d->path,
                              d->tmp, d->page, what, strerror(d->io_errno));
  return wl_report_doc_fail(d, err, cs == CAIRO_STATUS_NO_MEMORY ? WL_ENOMEM : WL_EIO,
                            "%s: page %d: %s: cairo: %s", d->path, d->page, what,
                            cairo_status_to_string(cs));
}

/* ---- the file --------------------------------------------------------------- */

/* Cairo's output: every byte to the .part file, the first failure kept. */
static cairo_status_t write_out(void *closure, const unsigned char *data, unsigned int length) {
  struct wl_report_doc *d = closure;
  if (d->io_errno) return CAIRO_STATUS_WRITE_ERROR;
  if (d->fd < 0) {
    d->io_errno = EBADF;
    return CAIRO_STATUS_WRITE_ERROR;
  }
  size_t done = 0;
  while (done < length) {
    ssize_t w = write(d->fd, data + done, length - done);
    if (w > 0) {
      done += (size_t)w;
    } else if (w < 0 && errno == EINTR) {
      continue;
    } else {
      d->io_errno = w < 0 ? errno : EIO;
      return CAIRO_STATUS_WRITE_ERROR;
    }
  }
  return CAIRO_STATUS_SUCCESS;
}

/* Sync and close the .part file; the first failure goes to io_errno.
 * Returns 0 when the whole file is on disk. */
static int close_out(struct wl_report_doc *d) {
  if (d->fd < 0) return d->io_errno ? -1 : 0;
  if (!d->io_errno && fsync(d->fd) != 0 && errno != EINVAL && errno != EROFS)
    d->io_errno = errno;
  if (close(d->fd) != 0 && !d->io_errno && errno != EINTR) d->io_errno = errno;
  d->fd = -1;
  return d->io_errno ? -1 : 0;
}

/* Remove the .part file (closing it first where it is open). */
static void discard_out(struct wl_report_doc *d) {
  if (d->fd >= 0) close(d->fd);
  d->fd = -1;
  remove(d->tmp);
}

/* ---- open, finish, free --------------------------------------------------- */

static void set_metadata(struct wl_report_doc *d) {
#if CAIRO_VERSION >= CAIRO_VERSION_ENCODE(1, 16, 0)
  char creator[96];
  snprintf(creator, sizeof creator, "wallload %s", d->version);
  if (d->title[0]) cairo_pdf_surface_set_metadata(d->surface, CAIRO_PDF_METADATA_TITLE, d->title);
  if (d->company[0])
    cairo_pdf_surface_set_metadata(d->surface, CAIRO_PDF_METADATA_AUTHOR, d->company);
  if (d->scenario[0])
    cairo_pdf_surface_set_metadata(d->surface, CAIRO_PDF_METADATA_SUBJECT, d->scenario);
  cairo_pdf_surface_set_metadata(d->surface, CAIRO_PDF_METADATA_CREATOR, creator);
#else
  (void)d;
#endif
}

/* Tear down cairo and pango; the partial file stays (callers remove it:
 * discard_out). */
static void destroy_drawing(struct wl_report_doc *d) {
  wl_report_text_free(d);
  if (d->cr) cairo_destroy(d->cr);
  d->cr = NULL;
  if (d->surface) {
    cairo_surface_finish(d->surface);
    cairo_surface_destroy(d->surface);
  }
  d->surface = NULL;
}

enum wl_status wl_report_doc_open(const char *path, const struct wl_report_doc_info *info,
                                  struct wl_report_doc **out, struct wl_error *err) {
  *out = NULL;
  if (!path || !*path) return wl_error_set(err, WL_EINPUT, "report: no output file name given");
  struct wl_report_doc *d = calloc(1, sizeof *d);
  if (!d) return wl_error_set(err, WL_ENOMEM, "%s: no memory for the report document", path);
  if (strlen(path) >= sizeof d->path) {
    free(d);
    return wl_error_set(err, WL_EINPUT, "%s: output path longer than %zu bytes", path,
                        sizeof d->path - 1);
  }
  copy_text(d->path, sizeof d->path, path);
  snprintf(d->tmp, sizeof d->tmp, "%s.part", path);
  if (info) {
    copy_text(d->title, sizeof d->title, info->title);
    copy_text(d->scenario, sizeof d->scenario, info->scenario);
    copy_text(d->company, sizeof d->company, info->company);
  }
  copy_text(d->version, sizeof d->version, info && info->version ? info->version : WL_VERSION);

  d->fd = open(d->tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (d->fd < 0) {
    const int e = errno;
    free(d);
    /* a path the user chose that cannot hold a file is bad input; a full
     * or failing disk is not */
    return wl_error_set(err, e == ENOSPC || e == EIO || e == EDQUOT ? WL_EIO : WL_EINPUT,
                        "%s: cannot create %s.part: %s", path, path, strerror(e));
  }
  d->surface = cairo_pdf_surface_create_for_stream(write_out, d, PAGE_W, PAGE_H);
  cairo_status_t cs = cairo_surface_status(d->surface);
  if (cs != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(d->surface);
    discard_out(d);
    free(d);
    return wl_error_set(err, cs == CAIRO_STATUS_NO_MEMORY ? WL_ENOMEM : WL_EIO,
                        "%s: cannot create the PDF (cairo: %s)", path,
                        cairo_status_to_string(cs));
  }
  set_metadata(d);
  d->cr = cairo_create(d->surface);
  enum wl_status st = check_cairo(d, err, "creating the drawing context");
  if (st == WL_OK) st = wl_report_text_init(d, err);
  if (st != WL_OK) {
    destroy_drawing(d);
    discard_out(d);
    free(d);
    return st;
  }
  d->y = CONTENT_TOP;
  *out = d;
  return WL_OK;
}

enum wl_status wl_report_doc_finish(struct wl_report_doc *d, struct wl_error *err) {
  if (!d) return wl_error_set(err, WL_EINPUT, "report: no document (NULL)");
  if (d->finished) return WL_OK;
  enum wl_status st = d->failed;
  if (st != WL_OK) {
    wl_error_set(err, st, "%s: not written: an earlier report call failed (%s)", d->path,
                 wl_error_status_name(st));
  } else {
    if (d->page == 0 || d->n_pending) st = wl_report_doc_need(d, 0.0, err);
    if (st == WL_OK && d->page_open) {
      cairo_show_page(d->cr);
      d->page_open = 0;
      st = check_cairo(d, err, "ending the page");
    }
  }
  wl_report_text_free(d);
  cairo_destroy(d->cr);
  d->cr = NULL;
  cairo_surface_finish(d->surface);
  cairo_status_t cs = cairo_surface_status(d->surface);
  cairo_surface_destroy(d->surface);
  d->surface = NULL;
  d->finished = 1;
  if (st == WL_OK && cs != CAIRO_STATUS_SUCCESS) {
    if (d->io_errno)
      st = wl_report_doc_fail(d, err, WL_EIO, "%s: cannot write %s: %s", d->path, d->tmp,
                              strerror(d->io_errno));
    else
      st = wl_report_doc_fail(d, err, cs == CAIRO_STATUS_NO_MEMORY ? WL_ENOMEM : WL_EIO,
                              "%s: cannot write the PDF (cairo: %s)", d->path,
                              cairo_status_to_string(cs));
  }
  /* the whole file on disk (synced, closed without error) before the rename */
  if (st == WL_OK && close_out(d) != 0)
    st = wl_report_doc_fail(d, err, WL_EIO, "%s: cannot write %s: %s", d->path, d->tmp,
                            strerror(d->io_errno));
  if (st == WL_OK && rename(d->tmp, d->path) != 0)
    st = wl_report_doc_fail(d, err, WL_EIO, "%s: cannot move %s into place: %s", d->path, d->tmp,
                            strerror(errno));
  if (st == WL_OK) wl_store_sync_dir_of(d->path);
  if (st != WL_OK) {
    discard_out(d);
    if (d->failed == WL_OK) d->failed = st;
  }
  return st;
}

void wl_report_doc_free(struct wl_report_doc *d) {
  if (!d) return;
  if (!d->finished) {
    destroy_drawing(d);
    discard_out(d);
  }
  free(d);
}

int wl_report_doc_pages(const struct wl_report_doc *d) { return d ? d->page : 0; }

struct wl_report_rect wl_report_doc_content(const struct wl_report_doc *d) {
  (void)d;
  struct wl_report_rect r = {MARGIN_X, CONTENT_TOP, CONTENT_W, CONTENT_BOTTOM - CONTENT_TOP};
  return r;
}

double wl_report_doc_space_left(struct wl_report_doc *d) {
  if (!d) return 0.0;
  double waiting = d->n_pending ? pending_height(d) : 0.0;
  if (!d->page_open) return CONTENT_BOTTOM - CONTENT_TOP - waiting;
  double left = CONTENT_BOTTOM - d->y - waiting;
  return left > 0 ? left : 0;
}

/* ---- pages ------------------------------------------------------------------ */

static void draw_running(struct wl_report_doc *d) {
  cairo_t *cr = d->cr;
  cairo_save(cr);
  cairo_set_source_rgb(cr, RUNNING_GREY, RUNNING_GREY, RUNNING_GREY);
  double x0 = MARGIN_X, x1 = PAGE_W - MARGIN_X;
  wl_report_text_draw(d, FONT_BOLD, SIZE_SMALL, x0, HEADER_BASELINE, d->scenario, 0.0,
                      VALIGN_BASELINE);
  wl_report_text_draw(d, FONT_SANS, SIZE_SMALL, x1, HEADER_BASELINE, d->title, 1.0,
                      VALIGN_BASELINE);
  char left[96], right[32];
  snprintf(left, sizeof left, "wallload %s", d->version);
  snprintf(right, sizeof right, "page %d", d->page);
  wl_report_text_draw(d, FONT_SANS, SIZE_SMALL, x0, FOOTER_BASELINE, left, 0.0, VALIGN_BASELINE);
  wl_report_text_draw(d, FONT_SANS, SIZE_SMALL, 0.5 * (x0 + x1), FOOTER_BASELINE, d->company, 0.5,
                      VALIGN_BASELINE);
  wl_report_text_draw(d, FONT_SANS, SIZE_SMALL, x1, FOOTER_BASELINE, right, 1.0, VALIGN_BASELINE);
  cairo_set_source_rgb(cr, RULE_GREY, RULE_GREY, RULE_GREY);
  cairo_set_line_width(cr, 0.4);
  cairo_move_to(cr, x0, HEADER_BASELINE + 4.0);
  cairo_line_to(cr, x1, HEADER_BASELINE + 4.0);
  cairo_move_to(cr, x0, FOOTER_BASELINE - SIZE_SMALL - 3.0);
  cairo_line_to(cr, x1, FOOTER_BASELINE - SIZE_SMALL - 3.0);
  cairo_stroke(cr);
  cairo_restore(cr);
}

enum wl_status wl_report_doc_ensure_page(struct wl_report_doc *d, struct wl_error *err) {
  enum wl_status st = wl_report_doc_usable(d, err);
  if (st != WL_OK || d->page_open) return st;
  d->page++;
  d->page_open = 1;
  d->y = CONTENT_TOP;
  draw_running(d);
  return WL_OK;
}

enum wl_status wl_report_break_page(struct wl_report_doc *d, struct wl_error *err) {
  enum wl_status st = wl_report_doc_usable(d, err);
  if (st != WL_OK || !d->page_open) return st;
  if (d->in_figure)
    return wl_report_doc_fail(d, err, WL_EINPUT,
                              "%s: page %d: page break inside a figure (end_figure missing)",
                              d->path, d->page);
  cairo_show_page(d->cr);
  d->page_open = 0;
  return check_cairo(d, err, "ending the page");
}

static double heading_size(int level) {
  return level == 1 ? SIZE_H1 : level == 2 ? SIZE_H2 : SIZE_BODY;
}

static double heading_before(int level) { return level == 1 ? 14.0 : 9.0; }

/* Height of the waiting headings [pt] (with the space above each). */
static double pending_height(struct wl_report_doc *d) {
  double h = 0;
  for (int i = 0; i < d->n_pending; i++) {
    double size = heading_size(d->pending[i].level);
    double lines = ceil(wl_report_text_width(d, FONT_BOLD, size, d->pending[i].text) / CONTENT_W);
    h += heading_before(d->pending[i].level) + (lines > 1 ? lines : 1) * 1.3 * size + 4.0;
  }
  return h;
}

static void add_outline(struct wl_report_doc *d, int level, const char *text);

/* Draw lines of text from the cursor without page checks (space is known). */
static enum wl_status draw_lines(struct wl_report_doc *d, enum font font, double size,
                                 double leading, const char *text, struct wl_error *err) {
  struct text_span *lines = NULL;
  size_t n = 0;
  enum wl_status st = wl_report_text_break(d, font, size, CONTENT_W, text, &lines, &n, err);
  if (st != WL_OK) {
    d->failed = st;
    return st;
  }
  cairo_set_source_rgb(d->cr, 0, 0, 0);
  for (size_t i = 0; i < n; i++) {
    wl_report_text_draw_span(d, font, size, MARGIN_X, d->y + 0.75 * leading * size, text, lines[i]);
    d->y += leading * size;
  }
  free(lines);
  return WL_OK;
}

static enum wl_status place_pending(struct wl_report_doc *d, struct wl_error *err) {
  int n = d->n_pending;
  d->n_pending = 0;
  for (int i = 0; i < n; i++) {
    int level = d->pending[i].level;
    if (d->y > CONTENT_TOP) d->y += heading_before(level);
    if (level < 3) add_outline(d, level, d->pending[i].text);
    enum wl_status st = draw_lines(d, FONT_BOLD, heading_size(level), 1.3, d->pending[i].text, err);
    if (st != WL_OK) return st;
    d->y += 4.0;
  }
  return WL_OK;
}

enum wl_status wl_report_doc_need(struct wl_report_doc *d, double height, struct wl_error *err) {
  enum wl_status st = wl_report_doc_ensure_page(d, err);
  if (st != WL_OK) return st;
  double total = height + (d->n_pending ? pending_height(d) : 0.0);
  /* An empty page takes anything: what cannot fit there cannot fit anywhere. */
  if (d->y + total > CONTENT_BOTTOM && d->y > CONTENT_TOP) {
    st = wl_report_break_page(d, err);
    if (st == WL_OK) st = wl_report_doc_ensure_page(d, err);
    if (st != WL_OK) return st;
  }
  return d->n_pending ? place_pending(d, err) : WL_OK;
}

/* ---- running text -------------------------------------------------------------- */

/* Flow text in `font` at `size` from the cursor, indented by `indent` [pt],
 * line by line across pages. */
static enum wl_status flow(struct wl_report_doc *d, enum font font, double size, double leading,
                           double indent, const char *text, struct wl_error *err) {
  struct text_span *lines = NULL;
  size_t n = 0;
  enum wl_status st = wl_report_doc_ensure_page(d, err);
  if (st != WL_OK) return st;
  st = wl_report_text_break(d, font, size, CONTENT_W - indent, text, &lines, &n, err);
  if (st != WL_OK) {
    d->failed = st;
    return st;
  }
  double lh = leading * size;
  for (size_t i = 0; i < n && st == WL_OK; i++) {
    /* No single first line at a page's foot. */
    st = wl_report_doc_need(d, i == 0 && n > 1 ? 2.0 * lh : lh, err);
    if (st != WL_OK) break;
    cairo_set_source_rgb(d->cr, 0, 0, 0);
    wl_report_text_draw_span(d, font, size, MARGIN_X + indent, d->y + 0.75 * lh, text, lines[i]);
    d->y += lh;
  }
  free(lines);
  return st;
}

enum wl_status wl_report_add_title(struct wl_report_doc *d, const char *title,
                                   const char *subtitle, struct wl_error *err) {
  enum wl_status st = wl_report_doc_need(d, 120.0, err);
  if (st != WL_OK) return st;
  d->y += 60.0;
  st = flow(d, FONT_BOLD, SIZE_TITLE, 1.2, 0.0, title ? title : "", err);
  if (st == WL_OK && subtitle && *subtitle) {
    d->y += 6.0;
    st = flow(d, FONT_SANS, SIZE_SUBTITLE, 1.25, 0.0, subtitle, err);
  }
  if (st == WL_OK) {
    cairo_t *cr = d->cr;
    d->y += 10.0;
    cairo_save(cr);
    cairo_set_line_width(cr, 1.2);
    cairo_move_to(cr, MARGIN_X, d->y);
    cairo_line_to(cr, MARGIN_X + CONTENT_W, d->y);
    cairo_stroke(cr);
    cairo_restore(cr);
    d->y += 3.0 * GAP_BLOCK;
  }
  return st;
}

static void add_outline(struct wl_report_doc *d, int level, const char *text) {
#if CAIRO_VERSION >= CAIRO_VERSION_ENCODE(1, 16, 0)
  char link[96];
  snprintf(link, sizeof link, "page=%d pos=[%.1f %.1f]", d->page, MARGIN_X, d->y);
  int parent = level == 1 || d->outline_h1 == 0 ? CAIRO_PDF_OUTLINE_ROOT : d->outline_h1;
  int id = cairo_pdf_surface_add_outline(d->surface, parent, text, link, 0);
  if (level == 1) d->outline_h1 = id;
#else
  (void)d, (void)level, (void)text;
#endif
}

enum wl_status wl_report_add_heading(struct wl_report_doc *d, int level, const char *text,
                                     struct wl_error *err) {
  enum wl_status st = wl_report_doc_usable(d, err);
  if (st != WL_OK) return st;
  if (level < 1 || level > 3)
    return wl_report_doc_fail(d, err, WL_EINPUT, "%s: heading level %d; valid: 1, 2, 3", d->path,
                              level);
  if (d->n_pending == (int)(sizeof d->pending / sizeof d->pending[0])) {
    st = wl_report_doc_need(d, 0.0, err); /* places the waiting ones */
    if (st != WL_OK) return st;
  }
  char *full = d->pending[d->n_pending].text;
  size_t size = sizeof d->pending[0].text;
  if (level == 1) {
    d->h1++;
    d->h2 = 0;
    snprintf(full, size, "%d  %s", d->h1, text ? text : "");
  } else if (level == 2) {
    d->h2++;
    snprintf(full, size, "%d.%d  %s", d->h1, d->h2, text ? text : "");
  } else {
    snprintf(full, size, "%s", text ? text : "");
  }
  d->pending[d->n_pending++].level = level;
  return WL_OK;
}

enum wl_status wl_report_add_paragraph(struct wl_report_doc *d, const char *text,
                                       struct wl_error *err) {
  enum wl_status st = flow(d, FONT_SANS, SIZE_BODY, LEADING, 0.0, text ? text : "", err);
  if (st == WL_OK) d->y += 0.75 * GAP_BLOCK;
  return st;
}

enum wl_status wl_report_add_preformatted(struct wl_report_doc *d, const char *text,
                                          struct wl_error *err) {
  enum wl_status st = flow(d, FONT_MONO, SIZE_MONO, 1.2, 6.0, text ? text : "", err);
  if (st == WL_OK) d->y += 0.75 * GAP_BLOCK;
  return st;
}

/* ---- reserved areas and figures ---------------------------------------------------- */

enum wl_status wl_report_reserve(struct wl_report_doc *d, double height,
                                 struct wl_report_rect *area, struct wl_error *err) {
  double max_h = CONTENT_BOTTOM - CONTENT_TOP;
  if (!(height > 0)) height = 0.0;
  if (height > max_h) height = max_h;
  enum wl_status st = wl_report_doc_need(d, height, err);
  if (st != WL_OK) return st;
  struct wl_report_rect r = {MARGIN_X, d->y, CONTENT_W, height};
  *area = r;
  d->y += height;
  return WL_OK;
}

enum wl_status wl_report_begin_figure(struct wl_report_doc *d, double height,
                                      struct wl_report_rect *area, struct wl_error *err) {
  enum wl_status st = wl_report_doc_usable(d, err);
  if (st != WL_OK) return st;
  if (d->in_figure)
    return wl_report_doc_fail(d, err, WL_EINPUT,
                              "%s: begin_figure inside a figure (end_figure missing)", d->path);
  double max_h = CONTENT_BOTTOM - CONTENT_TOP - CAPTION_ROOM;
  if (!(height > 0)) height = 0.0;
  if (height > max_h) height = max_h;
  st = wl_report_doc_need(d, height + CAPTION_ROOM, err);
  if (st != WL_OK) return st;
  struct wl_report_rect r = {MARGIN_X, d->y, CONTENT_W, height};
  *area = r;
  d->y += height;
  d->in_figure = 1;
  return WL_OK;
}

enum wl_status wl_report_end_figure(struct wl_report_doc *d, const char *caption,
                                    struct wl_error *err) {
  enum wl_status st = wl_report_doc_usable(d, err);
  if (st != WL_OK) return st;
  if (!d->in_figure)
    return wl_report_doc_fail(d, err, WL_EINPUT, "%s: end_figure without begin_figure", d->path);
  d->in_figure = 0;
  d->n_figures++;
  char text[1024];
  snprintf(text, sizeof text, "Figure %d. %s", d->n_figures, caption ? caption : "");
  d->y += 4.0;
  st = flow(d, FONT_SANS, SIZE_SMALL, LEADING, 0.0, text, err);
  if (st == WL_OK) d->y += GAP_BLOCK;
  return st;
}

struct wl_report_rect wl_report_rect_cell(struct wl_report_rect r, int n_cols, int n_rows,
                                          int index, double gap) {
  if (n_cols < 1) n_cols = 1;
  if (n_rows < 1) n_rows = 1;
  if (index < 0) index = 0;
  double w = (r.w - (n_cols - 1) * gap) / n_cols, h = (r.h - (n_rows - 1) * gap) / n_rows;
  int row = index / n_cols, col = index % n_cols;
  struct wl_report_rect c = {r.x + col * (w + gap), r.y + row * (h + gap), w, h};
  return c;
}
