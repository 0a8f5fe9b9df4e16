/* output.c: the validation table and PDF: DIR/validation.json,
 * DIR/validation.csv and DIR/validation.pdf, each written to a temporary
 * name and renamed (wl_store_write_text; the report toolkit's .part file). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/draw.h"
#include "internal.h"
#include "wallload/config.h"
#include "wallload/store.h"

/* A growable text buffer. */
struct buf {
  char *s;
  size_t len, cap;
  int failed;
};

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void bprintf(struct buf *b, const char *fmt, ...) {
  if (b->failed) return;
  for (;;) {
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(b->s ? b->s + b->len : NULL, b->s ? b->cap - b->len : 0, fmt, ap);
    va_end(ap);
    if (n < 0) {
      b->failed = 1;
      return;
    }
    if (b->s && b->len + (size_t)n < b->cap) {
      b->len += (size_t)n;
      return;
    }
    size_t cap = b->cap ? 2 * b->cap : 4096;
    while (cap < b->len + (size_t)n + 1) cap *= 2;
    char *s = realloc(b->s, cap);
    if (!s) {
      b->failed = 1;
      return;
    }
    b->s = s;
    b->cap = cap;
  }
}

static const char *kind_name(enum wl_validate_kind k) {
  switch (k) {
  case WL_VALIDATE_REL: return "relative";
  case WL_VALIDATE_RMSE: return "rmse";
  case WL_VALIDATE_CORR: return "correlation";
  case WL_VALIDATE_RATIO: return "ratio";
  }
  return "?";
}

/* JSON number: null for NaN and infinities. */
static void jnum(struct buf *b, double v) {
  if (isfinite(v)) bprintf(b, "%.10g", v);
  else bprintf(b, "null");
}

static void jstr(struct buf *b, const char *s) {
  bprintf(b, "\"");
  for (; *s; s++) {
    if (*s == '"' || *s == '\\') bprintf(b, "\\%c", *s);
    else if ((unsigned char)*s < 0x20) bprintf(b, "\\u%04x", (unsigned char)*s);
    else bprintf(b, "%c", *s);
  }
  bprintf(b, "\"");
}

static void csv_str(struct buf *b, const char *s) {
  bprintf(b, "\"");
  for (; *s; s++) {
    if (*s == '"') bprintf(b, "\"\"");
    else if (*s == '\n') bprintf(b, " ");
    else bprintf(b, "%c", *s);
  }
  bprintf(b, "\"");
}

static void csv_num(struct buf *b, double v) {
  if (isfinite(v)) bprintf(b, "%.8g", v);
}

static enum wl_status write_json(const char *path, const struct wl_validate_result *r, int n,
                                 struct wl_error *err) {
  struct buf b = {0};
  int all = 1;
  for (int i = 0; i < n; i++) all = all && r[i].pass;
  bprintf(&b, "{\n  \"wallload\": \"%s\",\n  \"pass\": %s,\n  \"cases\": [", WL_VERSION,
          all ? "true" : "false");
  for (int i = 0; i < n; i++) {
    const struct wl_validate_result *c = &r[i];
    bprintf(&b, "%s\n    {\"name\": ", i ? "," : "");
    jstr(&b, c->name);
    bprintf(&b, ", \"title\": ");
    jstr(&b, c->title);
    bprintf(&b, ", \"pass\": %s, \"verdict\": ", c->pass ? "true" : "false");
    jstr(&b, c->verdict);
    bprintf(&b, ",\n     \"integrator\": ");
    jstr(&b, c->integrator);
    bprintf(&b, ",\n     \"residual_viscosity\": %g", c->residual);
    bprintf(&b, ", \"smagorinsky\": %g", c->smagorinsky);
    bprintf(&b, ", \"backend\": ");
    jstr(&b, c->backend[0] ? c->backend : "cpu");
    bprintf(&b, ", \"ratio\": ");
    jnum(&b, c->ratio);
    bprintf(&b, ", \"order\": ");
    jnum(&b, c->order);
    bprintf(&b, ", \"order_meaningful\": %s, \"extrapolated_error\": ", c->order_ok ? "true" : "false");
    jnum(&b, c->extrapolated);
    bprintf(&b, ",\n     \"levels\": [");
    for (int l = 0; l < c->n_levels; l++) {
      const struct wl_validate_level *lv = &c->lv[l];
      bprintf(&b, "%s\n      {\"dp\": {\"value\": ", l ? "," : "");
      jnum(&b, lv->dp);
      bprintf(&b, ", \"unit\": \"m\"}, \"particles\": %d, \"steps\": %ld, \"runtime\": {\"value\": ",
              lv->n_particles, lv->steps);
      jnum(&b, lv->runtime_s);
      bprintf(&b, ", \"unit\": \"s\"}, \"time_reached\": {\"value\": ");
      jnum(&b, lv->t_reached);
      bprintf(&b, ", \"unit\": \"s\"}, \"status\": ");
      jstr(&b, wl_error_status_name((enum wl_status)lv->status));
      bprintf(&b, ", \"message\": ");
      jstr(&b, lv->message);
      bprintf(&b, ",\n       \"metrics\": [");
      for (int j = 0; j < lv->n_metrics; j++) {
        const struct wl_validate_metric *m = &lv->m[j];
        bprintf(&b, "%s\n        {\"name\": ", j ? "," : "");
        jstr(&b, m->name);
        bprintf(&b, ", \"kind\": \"%s\", \"value\": ", kind_name(m->kind));
        jnum(&b, m->value);
        bprintf(&b, ", \"reference\": ");
        jnum(&b, m->reference);
        bprintf(&b, ", \"unit\": ");
        jstr(&b, m->unit);
        bprintf(&b, ", \"error\": ");
        jnum(&b, m->error);
        bprintf(&b, ", \"tolerance\": ");
        jnum(&b, m->tol);
        bprintf(&b, ", \"judged\": %s, \"pass\": %s}", isnan(m->tol) ? "false" : "true",
                m->pass ? "true" : "false");
      }
      bprintf(&b, "]}");
    }
    bprintf(&b, "]}");
  }
  bprintf(&b, "\n  ]\n}\n");
  enum wl_status st = b.failed ? wl_error_set(err, WL_ENOMEM, "%s: no memory for the JSON", path)
                               : wl_store_write_text(path, b.s, b.len, err);
  free(b.s);
  return st;
}

static enum wl_status write_csv(const char *path, const struct wl_validate_result *r, int n,
                                struct wl_error *err) {
  struct buf b = {0};
  bprintf(&b, "case,level,dp_m,particles,steps,runtime_s,status,metric,kind,value,reference,unit,"
              "error,tolerance,pass,case_pass,order,extrapolated_error\n");
  for (int i = 0; i < n; i++) {
    const struct wl_validate_result *c = &r[i];
    for (int l = 0; l < c->n_levels; l++) {
      const struct wl_validate_level *lv = &c->lv[l];
      for (int j = 0; j < lv->n_metrics; j++) {
        const struct wl_validate_metric *m = &lv->m[j];
        bprintf(&b, "%s,%d,%.6g,%d,%ld,%.4g,%s,", c->name, l + 1, lv->dp, lv->n_particles,
                lv->steps, lv->runtime_s, lv->status == WL_OK ? "ok" : "stopped");
        csv_str(&b, m->name);
        bprintf(&b, ",%s,", kind_name(m->kind));
        csv_num(&b, m->value);
        bprintf(&b, ",");
        csv_num(&b, m->reference);
        bprintf(&b, ",%s,", m->unit);
        csv_num(&b, m->error);
        bprintf(&b, ",");
        csv_num(&b, m->tol);
        bprintf(&b, ",%s,%d,", isnan(m->tol) ? "n/a" : (m->pass ? "1" : "0"), c->pass);
        if (j == 0 && l == c->n_levels - 1) {
          csv_num(&b, c->order);
          bprintf(&b, ",");
          csv_num(&b, c->order_ok ? c->extrapolated : NAN);
        } else {
          bprintf(&b, ",");
        }
        bprintf(&b, "\n");
      }
    }
  }
  enum wl_status st = b.failed ? wl_error_set(err, WL_ENOMEM, "%s: no memory for the CSV", path)
                               : wl_store_write_text(path, b.s, b.len, err);
  free(b.s);
  return st;
}

/* |primary error| in the plot: RMSE and ratios as they are, relative errors
 * as magnitudes, correlations as 1 - r. */
static double plot_error(const struct wl_validate_metric *m) {
  double e = m->kind == WL_VALIDATE_CORR ? 1 - m->error : fabs(m->error);
  return e > 0 && isfinite(e) ? e : NAN;
}

static enum wl_status write_pdf(const char *path, const struct wl_validate_result *r, int n,
                                struct wl_error *err) {
  struct wl_report_doc *d = NULL;
  struct wl_report_doc_info info = {"Validation: error against runtime", "wallload validate", NULL,
                                    NULL};
  enum wl_status st = wl_report_doc_open(path, &info, &d, err);
  if (st) return st;
  wl_report_add_title(d, "wallload validation",
                      "Reference cases (reference/): error of each case's primary metric against "
                      "runtime over the resolution ladder",
                      err);
  /* figure: one line per case */
  struct wl_report_series *ser = calloc((size_t)n + 1, sizeof *ser);
  double *xs = calloc((size_t)n * WL_VALIDATE_MAX_LEVELS + 1, sizeof(double));
  double *ys = calloc((size_t)n * WL_VALIDATE_MAX_LEVELS + 1, sizeof(double));
  char(*labels)[96] = calloc((size_t)n + 1, sizeof *labels);
  if (!ser || !xs || !ys || !labels) {
    st = wl_error_set(err, WL_ENOMEM, "validate: no memory for the plot");
  } else {
    for (int i = 0; i < n; i++) {
      double *x = xs + (size_t)i * WL_VALIDATE_MAX_LEVELS, *y = ys + (size_t)i * WL_VALIDATE_MAX_LEVELS;
      for (int l = 0; l < r[i].n_levels; l++) {
        x[l] = r[i].lv[l].runtime_s > 0 ? r[i].lv[l].runtime_s : NAN;
        y[l] = r[i].lv[l].n_metrics ? plot_error(&r[i].lv[l].m[0]) : NAN;
      }
      snprintf(labels[i], sizeof labels[i], "%s (%s)", r[i].name,
               r[i].n_levels && r[i].lv[0].n_metrics ? r[i].lv[0].m[0].name : "-");
      ser[i].label = labels[i];
      ser[i].x = x;
      ser[i].y = y;
      ser[i].n = (size_t)r[i].n_levels;
      ser[i].marker = WL_REPORT_MARKER_AUTO;
    }
    struct wl_report_plot p;
    memset(&p, 0, sizeof p);
    p.title = "Primary error against runtime (each point a ladder level, finer to the right)";
    p.x.label = "runtime";
    p.x.unit = "s";
    p.x.log = 1;
    p.y.label = "|error| of the primary metric";
    p.y.unit = "-";
    p.y.log = 1;
    p.series = ser;
    p.n_series = n;
    p.legend = WL_REPORT_LEGEND_BELOW;
    struct wl_report_rect area;
    if (!st) st = wl_report_begin_figure(d, 420, &area, err);
    if (!st) st = wl_report_draw_plot(d, &p, area, err);
    if (!st)
      st = wl_report_end_figure(d,
                                "Validation: the primary metric's error (relative error, RMSE "
                                "over its scale, or 1 - r) against wall-clock runtime, log-log.",
                                err);
  }
  /* summary table */
  if (!st) {
    static const struct wl_report_column cols[] = {
        {"case", NULL, WL_REPORT_ALIGN_LEFT, 0},  {"levels", NULL, WL_REPORT_ALIGN_AUTO, 0},
        {"finest dp", "m", WL_REPORT_ALIGN_AUTO, 3}, {"primary error", "-", WL_REPORT_ALIGN_AUTO, 3},
        {"tolerance", "-", WL_REPORT_ALIGN_AUTO, 3}, {"order p", NULL, WL_REPORT_ALIGN_AUTO, 3},
        {"extrapolated", "-", WL_REPORT_ALIGN_AUTO, 3}, {"result", NULL, WL_REPORT_ALIGN_LEFT, 0}};
    enum { NC = 8 };
    struct wl_report_cell *cells = calloc((size_t)n * NC + 1, sizeof *cells);
    char(*nl)[8] = calloc((size_t)n + 1, sizeof *nl);
    if (!cells || !nl) {
      st = wl_error_set(err, WL_ENOMEM, "validate: no memory for the table");
    } else {
      for (int i = 0; i < n; i++) {
        struct wl_report_cell *row = cells + (size_t)i * NC;
        const struct wl_validate_level *f = r[i].n_levels ? &r[i].lv[r[i].n_levels - 1] : NULL;
        row[0].text = r[i].name;
        snprintf(nl[i], sizeof nl[i], "%d", r[i].n_levels);
        row[1].text = nl[i];
        row[2].value = f ? f->dp : NAN;
        row[3].value = f && f->n_metrics ? f->m[0].error : NAN;
        row[4].value = f && f->n_metrics ? f->m[0].tol : NAN;
        row[5].value = r[i].order;
        row[6].value = r[i].order_ok ? r[i].extrapolated : NAN;
        row[7].text = r[i].pass ? "pass" : "FAIL";
      }
      struct wl_report_table t = {"Cases at the finest level (primary metric)", cols, NC, cells, n};
      st = wl_report_add_table(d, &t, err);
    }
    free(cells);
    free(nl);
  }
  /* per case: every level and metric */
  if (!st) st = wl_report_add_heading(d, 1, "Cases, level by level", err);
  for (int i = 0; i < n && !st; i++) {
    char h[256];
    snprintf(h, sizeof h, "%s: %s", r[i].name, r[i].title);
    wl_report_add_heading(d, 2, h, err);
    char para[700];
    if (r[i].n_levels < 3)
      snprintf(para, sizeof para, "Result: %s. Observed order: needs three levels.", r[i].verdict);
    else if (!isfinite(r[i].order))
      snprintf(para, sizeof para, "Result: %s. Observed order: undefined (equal errors).", r[i].verdict);
    else
      snprintf(para, sizeof para, "Result: %s. Observed order %.2f%s.", r[i].verdict, r[i].order,
               r[i].order_ok ? " (meaningful; Richardson estimate in the table above)"
                             : " (not meaningful: non-monotone or outside [0.5, 4])");
    st = wl_report_add_paragraph(d, para, err);
    static const struct wl_report_column mc[] = {
        {"level", NULL, WL_REPORT_ALIGN_AUTO, 0},   {"dp", "m", WL_REPORT_ALIGN_AUTO, 3},
        {"particles", NULL, WL_REPORT_ALIGN_AUTO, 6}, {"runtime", "s", WL_REPORT_ALIGN_AUTO, 3},
        {"metric", NULL, WL_REPORT_ALIGN_LEFT, 0},  {"value", NULL, WL_REPORT_ALIGN_AUTO, 4},
        {"reference", NULL, WL_REPORT_ALIGN_AUTO, 4}, {"error", "-", WL_REPORT_ALIGN_AUTO, 3},
        {"tolerance", "-", WL_REPORT_ALIGN_AUTO, 3}, {"pass", NULL, WL_REPORT_ALIGN_LEFT, 0}};
    enum { MC = 10 };
    int rows = 0;
    for (int l = 0; l < r[i].n_levels; l++) rows += r[i].lv[l].n_metrics;
    struct wl_report_cell *cells = calloc((size_t)rows * MC + 1, sizeof *cells);
    if (!cells) {
      st = wl_error_set(err, WL_ENOMEM, "validate: no memory for the table");
      break;
    }
    int k = 0;
    static const char *lvl[WL_VALIDATE_MAX_LEVELS] = {"1", "2", "3", "4", "5", "6"};
    char(*np)[16] = calloc((size_t)r[i].n_levels + 1, sizeof *np);
    if (!np) {
      free(cells);
      st = wl_error_set(err, WL_ENOMEM, "validate: no memory for the table");
      break;
    }
    for (int l = 0; l < r[i].n_levels; l++) {
      const struct wl_validate_level *lv = &r[i].lv[l];
      for (int j = 0; j < lv->n_metrics; j++, k++) {
        struct wl_report_cell *row = cells + (size_t)k * MC;
        const struct wl_validate_metric *m = &lv->m[j];
        row[0].text = lvl[l];
        row[1].value = lv->dp;
        snprintf(np[l], sizeof np[l], "%d", lv->n_particles);
        row[2].text = np[l];
        row[3].value = lv->runtime_s;
        row[4].text = m->name;
        row[5].value = m->value;
        row[6].value = m->reference;
        row[7].value = m->error;
        row[8].value = m->tol;
        row[9].text = isnan(m->tol) ? "n/a" : (m->pass ? "yes" : "NO");
      }
    }
    struct wl_report_table t = {NULL, mc, MC, cells, rows};
    if (!st) st = wl_report_add_table(d, &t, err);
    free(cells);
    free(np);
  }
  if (!st) st = wl_report_doc_finish(d, err);
  wl_report_doc_free(d);
  free(ser);
  free(xs);
  free(ys);
  free(labels);
  return st;
}

enum wl_status wl_validate_write(const char *dir, const struct wl_validate_result *r, int n,
                                 struct wl_error *err) {
  char path[1024];
  snprintf(path, sizeof path, "%s/validation.json", dir);
  enum wl_status st = write_json(path, r, n, err);
  if (!st) {
    snprintf(path, sizeof path, "%s/validation.csv", dir);
    st = write_csv(path, r, n, err);
  }
  if (!st) {
    snprintf(path, sizeof path, "%s/validation.pdf", dir);
    st = write_pdf(path, r, n, err);
  }
  return st;
}
