/* numbers.c: the toolkit's pure functions: number formatting to significant
 * digits, "nice" axis ticks (linear 1-2-5 steps, logarithmic decades), the
 * viridis colour map, the series palette and min/max thinning of long
 * series. No cairo here, so all of it is unit-tested directly. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/draw.h"

#define REL_EPS 1e-9 /* relative slack when a value sits on a tick multiple */

/* ---- number formatting ---------------------------------------------------- */

void wl_report_format_superscript(int n, char *buf, size_t size) {
  static const char *const digit[10] = {"\xe2\x81\xb0", "\xc2\xb9",     "\xc2\xb2",
                                        "\xc2\xb3",     "\xe2\x81\xb4", "\xe2\x81\xb5",
                                        "\xe2\x81\xb6", "\xe2\x81\xb7", "\xe2\x81\xb8",
                                        "\xe2\x81\xb9"};
  static const char *const minus = "\xe2\x81\xbb";
  if (!buf || size == 0) return;
  char plain[16];
  snprintf(plain, sizeof plain, "%d", n);
  buf[0] = '\0';
  size_t used = 0;
  for (const char *p = plain; *p; p++) {
    const char *g = *p == '-' ? minus : digit[*p - '0'];
    size_t len = strlen(g);
    if (used + len + 1 > size) break;
    memcpy(buf + used, g, len + 1);
    used += len;
  }
}

void wl_report_format_sig(double v, int sig, char *buf, size_t size) {
  if (!buf || size == 0) return;
  if (sig < 1 || sig > 15) sig = 3;
  if (isnan(v)) {
    snprintf(buf, size, "n/a");
    return;
  }
  if (isinf(v)) {
    snprintf(buf, size, "%s", v > 0 ? "inf" : "-inf");
    return;
  }
  if (v == 0.0) {
    snprintf(buf, size, "0");
    return;
  }
  /* printf's %e does the rounding to `sig` digits, including 9.995 -> 1.00e+01. */
  char e[64];
  snprintf(e, sizeof e, "%.*e", sig - 1, v);
  char *pe = strchr(e, 'e');
  int ex = atoi(pe + 1);
  double rounded = strtod(e, NULL);
  if (ex >= -3 && ex <= 5) {
    int decimals = sig - 1 - ex;
    snprintf(buf, size, "%.*f", decimals > 0 ? decimals : 0, rounded);
  } else {
    *pe = '\0';
    char sup[32];
    wl_report_format_superscript(ex, sup, sizeof sup);
    snprintf(buf, size, "%s\xc3\x97" "10%s", e, sup);
  }
}

/* ---- ticks ------------------------------------------------------------------ */

static int decimals_for(double step) {
  int dec = (int)ceil(-log10(step) - REL_EPS);
  return dec > 0 ? dec : 0;
}

/* A 1-2-5 step: the smallest one not below `raw`. */
static double nice_step_at_least(double raw) {
  double base = pow(10.0, floor(log10(raw)));
  static const double mult[] = {1.0, 2.0, 5.0, 10.0};
  for (int i = 0; i < 4; i++)
    if (mult[i] * base >= raw * (1.0 - REL_EPS)) return mult[i] * base;
  return 10.0 * base;
}

static double next_nice(double step) {
  double base = pow(10.0, floor(log10(step) + REL_EPS));
  double m = step / base;
  if (m < 1.5) return 2.0 * base;
  if (m < 3.5) return 5.0 * base;
  return 10.0 * base;
}

void wl_report_ticks_linear(double lo, double hi, int max_intervals, int cover,
                            struct wl_report_ticks *t) {
  memset(t, 0, sizeof *t);
  if (max_intervals < 2 || max_intervals > 20) max_intervals = 6;
  if (!isfinite(lo) && !isfinite(hi)) {
    lo = 0.0;
    hi = 1.0;
  } else if (!isfinite(lo)) {
    lo = hi;
  } else if (!isfinite(hi)) {
    hi = lo;
  }
  if (lo > hi) {
    double s = lo;
    lo = hi;
    hi = s;
  }
  double mag = fmax(fabs(lo), fabs(hi));
  if (hi - lo <= 1e-12 * mag || hi - lo < 1e-300) {
    /* One value: show a range of one unit of its leading digit around it. */
    double m = mag > 0 ? pow(10.0, floor(log10(mag))) : 1.0;
    lo -= m;
    hi += m;
    cover = 1;
  }
  /* Lower bound of the step: a covering range has at least span/step
   * intervals, one kept inside [lo, hi] at least span/step - 2. */
  double step = nice_step_at_least((hi - lo) / (cover ? max_intervals : max_intervals + 2));
  double i0, i1;
  for (;;) {
    if (cover) {
      i0 = floor(lo / step + REL_EPS);
      i1 = ceil(hi / step - REL_EPS);
    } else {
      i0 = ceil(lo / step - REL_EPS);
      i1 = floor(hi / step + REL_EPS);
    }
    if (i1 - i0 <= max_intervals) break;
    step = next_nice(step);
  }
  t->step = step;
  if (cover) {
    t->lo = i0 * step;
    t->hi = i1 * step;
  } else {
    t->lo = lo;
    t->hi = hi;
  }
  double amax = fmax(fabs(t->lo), fabs(t->hi));
  if (amax >= 1e5 || amax < 1e-2) t->scale_exp = 3 * (int)floor(log10(amax) / 3.0);
  double scale = pow(10.0, t->scale_exp);
  int dec = decimals_for(step / scale);
  for (double i = i0; i <= i1 && t->n < WL_REPORT_TICKS_MAX; i += 1.0) {
    double v = i * step;
    if (fabs(v) < 1e-9 * step) v = 0.0;
    t->at[t->n] = v;
    double shown = v / scale;
    if (fabs(shown) < 1e-9 * step / scale) shown = 0.0;
    snprintf(t->label[t->n], WL_REPORT_TICK_LABEL, "%.*f", dec, shown);
    t->n++;
  }
}

static void log_label(double v, int decade, int plain, char *buf) {
  if (plain) {
    int dec = decade < 0 ? -decade : 0;
    snprintf(buf, WL_REPORT_TICK_LABEL, "%.*f", dec, v);
    return;
  }
  double m = v / pow(10.0, decade);
  char sup[32];
  wl_report_format_superscript(decade, sup, sizeof sup);
  if (fabs(m - 1.0) < 1e-6)
    snprintf(buf, WL_REPORT_TICK_LABEL, "10%s", sup);
  else
    snprintf(buf, WL_REPORT_TICK_LABEL, "%.0f\xc3\x97" "10%s", m, sup);
}

enum wl_status wl_report_ticks_log(double lo, double hi, int cover, struct wl_report_ticks *t,
                                   struct wl_error *err) {
  memset(t, 0, sizeof *t);
  if (!(lo > 0) || !(hi > 0) || !isfinite(lo) || !isfinite(hi))
    return wl_error_set(err, WL_EINPUT,
                        "log axis range [%g, %g]: found a bound that is not positive; valid: "
                        "positive finite bounds",
                        lo, hi);
  if (lo > hi) {
    double s = lo;
    lo = hi;
    hi = s;
  }
  int d0 = (int)floor(log10(lo) + REL_EPS), d1 = (int)ceil(log10(hi) - REL_EPS);
  if (d1 <= d0) d1 = d0 + 1;
  int step = 1;
  static const int steps[] = {1, 2, 5, 10, 20, 50, 100};
  for (int i = 0; i < 7; i++) {
    step = steps[i];
    if ((d1 - d0 + step - 1) / step <= 8) break;
  }
  if (cover) {
    d0 = (int)floor((double)d0 / step) * step;
    d1 = (int)ceil((double)d1 / step) * step;
    lo = pow(10.0, d0);
    hi = pow(10.0, d1);
  }
  t->lo = lo;
  t->hi = hi;
  t->step = step;
  double lo_in = lo * (1.0 - REL_EPS), hi_in = hi * (1.0 + REL_EPS);
  int with_25 = step == 1 && d1 - d0 <= 2;
  /* Majors first, in increasing order: decade multiples of `step`, and 2 and 5
   * times each decade for narrow ranges. */
  double maj_lo = INFINITY, maj_hi = 0;
  for (int e = d0 - 1; e <= d1; e++) {
    static const double mult[] = {1.0, 2.0, 5.0};
    for (int m = 0; m < (with_25 ? 3 : 1); m++) {
      if (m == 0 && ((e % step) + step) % step != 0) continue;
      double v = mult[m] * pow(10.0, e);
      if (v < lo_in || v > hi_in || t->n >= WL_REPORT_TICKS_MAX) continue;
      t->at[t->n++] = v;
      if (v < maj_lo) maj_lo = v;
      if (v > maj_hi) maj_hi = v;
    }
  }
  int plain = t->n > 0 && maj_lo >= 0.01 * (1.0 - REL_EPS) && maj_hi <= 1000.0 * (1.0 + REL_EPS);
  for (int i = 0; i < t->n; i++) {
    int decade = (int)floor(log10(t->at[i]) + REL_EPS);
    log_label(t->at[i], decade, plain, t->label[i]);
  }
  /* Minors: 2..9 per decade when decades are labelled one by one, else the
   * unlabelled decades. */
  for (int e = d0 - 1; e <= d1; e++) {
    for (int m = 1; m <= 9; m++) {
      if (step == 1 && m == 1) continue;
      if (step > 1 && (m != 1 || ((e % step) + step) % step == 0)) continue;
      if (with_25 && (m == 2 || m == 5)) continue;
      double v = m * pow(10.0, e);
      if (v < lo_in || v > hi_in || t->n_minor >= WL_REPORT_MINOR_MAX) continue;
      t->minor[t->n_minor++] = v;
    }
  }
  return WL_OK;
}

/* ---- colours ------------------------------------------------------------------ */

/* matplotlib's viridis (van der Walt & Smith 2015, _cm_listed.py) at entries
 * 0, 25.5, 51, ..., 255 of its 256: perceptually uniform and monotonic in
 * lightness, so it also reads in greyscale. */
static const double VIRIDIS[11][3] = {
    {0.267004, 0.004874, 0.329415}, {0.282623, 0.140926, 0.457517},
    {0.253935, 0.265254, 0.529983}, {0.206756, 0.371758, 0.553117},
    {0.163625, 0.471133, 0.558148}, {0.127568, 0.566949, 0.550556},
    {0.134692, 0.658636, 0.517649}, {0.266941, 0.748751, 0.440573},
    {0.477504, 0.821444, 0.318195}, {0.741388, 0.873449, 0.149561},
    {0.993248, 0.906157, 0.143936}};

void wl_report_colormap(double t, double rgb[3]) {
  if (isnan(t)) {
    rgb[0] = rgb[1] = rgb[2] = 0.75;
    return;
  }
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  double s = t * 10.0;
  int i = (int)floor(s);
  if (i >= 10) i = 9;
  double f = s - i;
  for (int c = 0; c < 3; c++) rgb[c] = (1.0 - f) * VIRIDIS[i][c] + f * VIRIDIS[i + 1][c];
}

void wl_report_palette(int k, double rgb[3]) {
  /* Okabe & Ito (2008) colour-blind-safe set, yellow left out (too light for
   * thin lines), ordered so that the first four differ in lightness
   * (relative luminance 0, 0.15, 0.42, 0.29); with the dash cycle they stay
   * apart in greyscale print. */
  static const double P[7][3] = {{0.0, 0.0, 0.0},       /* black */
                                 {0.0, 0.447, 0.698},   /* blue */
                                 {0.902, 0.624, 0.0},   /* orange */
                                 {0.800, 0.475, 0.655}, /* reddish purple */
                                 {0.835, 0.369, 0.0},   /* vermillion */
                                 {0.0, 0.620, 0.451},   /* bluish green */
                                 {0.337, 0.706, 0.914}}; /* sky blue */
  int i = k >= 1 ? (k - 1) % 7 : 0;
  for (int c = 0; c < 3; c++) rgb[c] = P[i][c];
}

/* ---- thinning ------------------------------------------------------------------- */

static size_t flush_bin(size_t first, size_t imin, size_t imax, size_t last, size_t *keep,
                        size_t out) {
  size_t v[4] = {first, imin, imax, last};
  for (int i = 1; i < 4; i++)
    for (int j = i; j > 0 && v[j] < v[j - 1]; j--) {
      size_t s = v[j];
      v[j] = v[j - 1];
      v[j - 1] = s;
    }
  for (int i = 0; i < 4; i++)
    if (i == 0 || v[i] != v[i - 1]) keep[out++] = v[i];
  return out;
}

size_t wl_report_thin(const double *x, const double *y, size_t n, double x0, double x1,
                      size_t n_bins, size_t *keep) {
  if (n_bins < 1 || !(x1 > x0) || !isfinite(x0) || !isfinite(x1)) {
    for (size_t i = 0; i < n; i++) keep[i] = i;
    return n;
  }
  size_t out = 0, first = 0, imin = 0, imax = 0, last = 0;
  int in_run = 0;
  long bin = -1;
  double per = (double)n_bins / (x1 - x0);
  for (size_t i = 0; i < n; i++) {
    if (!isfinite(x[i]) || !isfinite(y[i])) {
      if (in_run) {
        out = flush_bin(first, imin, imax, last, keep, out);
        keep[out++] = i;
        in_run = 0;
      }
      continue;
    }
    double fb = floor((x[i] - x0) * per);
    long b = fb < 0 ? -1 : fb > (double)n_bins ? (long)n_bins : (long)fb;
    if (!in_run || b != bin) {
      if (in_run) out = flush_bin(first, imin, imax, last, keep, out);
      first = imin = imax = last = i;
      bin = b;
      in_run = 1;
    } else {
      if (y[i] < y[imin]) imin = i;
      if (y[i] > y[imax]) imax = i;
      last = i;
    }
  }
  if (in_run) out = flush_bin(first, imin, imax, last, keep, out);
  return out;
}
