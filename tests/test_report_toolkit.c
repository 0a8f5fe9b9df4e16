/* test_report_toolkit.c: the report module's page, table and plot toolkit
 * and its template parser.
 *
 * References from outside the code under test:
 *  - ticks: Heckbert, "Nice numbers for graph labels", Graphics Gems (1990),
 *    loose labelling with 5 ticks, worked by hand for each range below;
 *  - number formatting: rounding to significant digits worked by hand;
 *  - colour map: matplotlib's viridis table (_cm_listed.py, first and last
 *    entries) and its monotonic lightness (relative luminance, ITU-R BT.709
 *    coefficients on linearised sRGB, IEC 61966-2-1);
 *  - PDFs: read back with poppler (pdfinfo, pdftotext, pdftoppm, pdffonts,
 *    pdfimages), a second program that did not write them;
 *  - templates: the shipped design.yaml, and bad templates whose error line
 *    and column are counted by hand in the strings below. */
#define _POSIX_C_SOURCE 200809L /* popen, mkdtemp, strtok_r */

#include "wallload/report.h"

#include "wallload/draw.h"
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef WL_SOURCE_DIR
#define WL_SOURCE_DIR "."
#endif

#define PI 3.14159265358979323846
#define WHITE_LEVEL 240       /* a grey pixel below this is ink */
#define INK_MIN 150           /* ink pixels a page's content box must have at 30 dpi */
#define MM_TOP 25.0           /* content box of the page model (doc.h) */
#define MM_BOTTOM 22.0
#define LONG_SERIES 1000000   /* points of the series that must be thinned */
#define THINNED_PDF_MAX (2 << 20) /* a plot of it stays under 2 MiB */

static char tmpdir[256];

/* LeakSanitizer hook (WL_SANITIZE builds): fontconfig keeps the configuration
 * it parsed for the life of the process, by design; that is not ours. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:libfontconfig.so\n"; }

/* ---- small helpers ---------------------------------------------------------------- */

static int have_tool(const char *name) {
  char cmd[256];
  snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", name);
  return system(cmd) == 0;
}

/* stdout of a shell command, malloc'ed (NULL on failure). */
static char *run_capture(const char *cmd) {
  FILE *p = popen(cmd, "r");
  if (!p) return NULL;
  size_t cap = 1 << 16, len = 0;
  char *buf = malloc(cap);
  size_t got;
  while (buf && (got = fread(buf + len, 1, cap - len - 1, p)) > 0) {
    len += got;
    if (len + 1 == cap) {
      char *bigger = realloc(buf, cap * 2);
      if (!bigger) {
        free(buf);
        buf = NULL;
        break;
      }
      buf = bigger;
      cap *= 2;
    }
  }
  int rc = pclose(p);
  if (!buf) return NULL;
  buf[len] = '\0';
  if (rc != 0) {
    free(buf);
    return NULL;
  }
  return buf;
}

static int file_exists(const char *path) {
  struct stat sb;
  return stat(path, &sb) == 0;
}

static long file_size(const char *path) {
  struct stat sb;
  return stat(path, &sb) == 0 ? (long)sb.st_size : -1;
}

/* Runs of spaces to one (pdftotext and pdfinfo pad with spaces). */
static void squeeze(char *s) {
  if (!s) return;
  char *w = s;
  for (const char *r = s; *r; r++)
    if (!(*r == ' ' && w > s && w[-1] == ' ')) *w++ = *r;
  *w = '\0';
}

static int contains(const char *hay, const char *needle) { return hay && strstr(hay, needle); }

static int count_of(const char *hay, const char *needle) {
  int n = 0;
  for (const char *p = hay; p && (p = strstr(p, needle)); p += strlen(needle)) n++;
  return n;
}

/* ---- pure functions ------------------------------------------------------------------ */

static void check_format(double v, int sig, const char *want, const char *ref) {
  char got[64];
  wl_report_format_sig(v, sig, got, sizeof got);
  int ok = strcmp(got, want) == 0;
  printf("%s format_sig(%.10g, %d) = '%s', want '%s' [%s]\n", ok ? "PASS" : "FAIL", v, sig, got,
         want, ref);
  if (!ok) wl_test_failures++;
}

static void test_format(void) {
  check_format(12345.6, 3, "12300", "3 s.f. of 12345.6");
  check_format(0.00123456, 3, "0.00123", "3 s.f., fixed down to 1e-3");
  check_format(0.000123456, 3, "1.23\xc3\x97" "10\xe2\x81\xbb\xe2\x81\xb4", "3 s.f., below 1e-3: power of ten");
  check_format(-0.5, 3, "-0.500", "3 s.f. keep trailing zeros");
  check_format(1.5e-7, 3, "1.50\xc3\x97" "10\xe2\x81\xbb\xe2\x81\xb7", "3 s.f., power of ten");
  check_format(999999.7, 3, "1.00\xc3\x97" "10\xe2\x81\xb6", "rounds up into the next decade");
  check_format(9.996, 3, "10.0", "rounds up into the next decade, fixed");
  check_format(9.994, 3, "9.99", "rounds down");
  check_format(0.0, 3, "0", "zero");
  check_format(NAN, 3, "n/a", "missing value");
  check_format(-INFINITY, 3, "-inf", "infinity");
  check_format(2.5e6, 2, "2.5\xc3\x97" "10\xe2\x81\xb6", "2 s.f., large");
  check_format(42.0, 0, "42.0", "sig 0 means 3");
  char sup[32];
  wl_report_format_superscript(-12, sup, sizeof sup);
  CHECK_TRUE(strcmp(sup, "\xe2\x81\xbb\xc2\xb9\xc2\xb2") == 0, "superscript -12 = U+207B U+00B9 U+00B2");
}

static void check_labels(const struct wl_report_ticks *t, const char *const *want, int n,
                         const char *ref) {
  int ok = t->n == n;
  for (int i = 0; ok && i < n; i++) ok = strcmp(t->label[i], want[i]) == 0;
  printf("%s tick labels:", ok ? "PASS" : "FAIL");
  for (int i = 0; i < t->n; i++) printf(" '%s'", t->label[i]);
  printf(" (want %d) [%s]\n", n, ref);
  if (!ok) wl_test_failures++;
}

static void test_ticks(void) {
  struct wl_report_ticks t;
  /* Heckbert: range nicenum(0.97) = 1, spacing nicenum(1/4, round) = 0.2,
   * graph [0, 1.0]; ticks 0, 0.2, ..., 1.0 with one decimal. */
  wl_report_ticks_linear(0.0, 0.97, 6, 1, &t);
  CHECK_ABS(t.step, 0.2, 1e-15, "Heckbert 1990: [0, 0.97] spacing 0.2");
  CHECK_ABS(t.lo, 0.0, 0.0, "Heckbert 1990: [0, 0.97] graph min 0");
  CHECK_ABS(t.hi, 1.0, 1e-15, "Heckbert 1990: [0, 0.97] graph max 1.0");
  static const char *const l1[] = {"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"};
  check_labels(&t, l1, 6, "Heckbert 1990: 6 ticks, nfrac = 1");
  CHECK_TRUE(t.scale_exp == 0, "no common factor for [0, 1]");

  /* Heckbert: range nicenum(1.42e-3) = 2e-3, spacing nicenum(5e-4, round) =
   * 5e-4, graph [-5e-4, 1.5e-3]: five ticks; labelled in units of 1e-3. */
  wl_report_ticks_linear(-3.2e-4, 1.1e-3, 6, 1, &t);
  CHECK_REL(t.step, 5e-4, 1e-12, "Heckbert 1990: [-3.2e-4, 1.1e-3] spacing 5e-4");
  CHECK_REL(t.lo, -5e-4, 1e-12, "Heckbert 1990: graph min -5e-4");
  CHECK_REL(t.hi, 1.5e-3, 1e-12, "Heckbert 1990: graph max 1.5e-3");
  static const char *const l2[] = {"-0.5", "0.0", "0.5", "1.0", "1.5"};
  check_labels(&t, l2, 5, "labels in units of 10^-3, zero exactly 0");
  CHECK_TRUE(t.scale_exp == -3, "common factor 10^-3 (engineering exponent)");
  CHECK_TRUE(t.lo <= -3.2e-4 && t.hi >= 1.1e-3, "range covers the data");

  /* cover = 0: range kept, ticks inside: [0.13, 0.87] by 0.1 (7 intervals
   * allowed) -> 0.2 .. 0.8. */
  wl_report_ticks_linear(0.13, 0.87, 7, 0, &t);
  CHECK_TRUE(t.lo == 0.13 && t.hi == 0.87, "cover = 0 keeps the range");
  CHECK_ABS(t.at[0], 0.2, 1e-15, "first tick inside [0.13, 0.87] at step 0.1");
  CHECK_ABS(t.at[t.n - 1], 0.8, 1e-15, "last tick inside");
  CHECK_TRUE(t.n == 7, "0.2..0.8 by 0.1 is 7 ticks");

  /* Heckbert on [0, 2.4e5]: spacing nicenum(6e4, round) = 5e4, graph
   * [0, 2.5e5]; labels in units of 10^3. */
  wl_report_ticks_linear(0.0, 2.4e5, 6, 1, &t);
  CHECK_REL(t.step, 5e4, 1e-12, "Heckbert 1990: [0, 2.4e5] spacing 5e4");
  CHECK_TRUE(t.scale_exp == 3 && strcmp(t.label[t.n - 1], "250") == 0,
             "2.5e5 labelled 250 in units of 10^3");

  /* Degenerate input never fails and brackets the value. */
  wl_report_ticks_linear(5.0, 5.0, 6, 1, &t);
  CHECK_TRUE(t.lo < 5.0 && t.hi > 5.0 && t.n >= 2, "single value 5 is bracketed");
  wl_report_ticks_linear(NAN, NAN, 6, 1, &t);
  CHECK_TRUE(t.lo == 0.0 && t.hi == 1.0, "no data: [0, 1]");
  wl_report_ticks_linear(3.0, -1.0, 6, 1, &t);
  CHECK_TRUE(t.lo <= -1.0 && t.hi >= 3.0, "reversed bounds are swapped");

  /* Log [1, 1e5]: decades 10^0..10^5, minor ticks 2..9 in each of 5 decades. */
  struct wl_error err;
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_ticks_log(1.0, 1e5, 1, &t, &err) == WL_OK, "log [1, 1e5] ok");
  CHECK_TRUE(t.n == 6 && t.at[0] == 1.0 && fabs(t.at[5] - 1e5) < 1e-9, "6 decade ticks 1..1e5");
  static const char *const l3[] = {
      "10\xe2\x81\xb0", "10\xc2\xb9", "10\xc2\xb2", "10\xc2\xb3", "10\xe2\x81\xb4",
      "10\xe2\x81\xb5"};
  check_labels(&t, l3, 6, "powers of ten beyond 1000");
  CHECK_TRUE(t.n_minor == 40, "8 minor ticks in each of 5 decades");

  /* Log within two decades: 1-2-5 labelled plainly. */
  wl_report_ticks_log(0.02, 0.7, 1, &t, &err);
  static const char *const l4[] = {"0.01", "0.02", "0.05", "0.1", "0.2", "0.5", "1"};
  check_labels(&t, l4, 7, "log [0.02, 0.7]: 1-2-5 in two decades, plain numbers");

  /* Log over 20 decades: every 5th decade. */
  wl_report_ticks_log(1e-10, 1e10, 1, &t, &err);
  CHECK_TRUE(t.n == 5 && t.step == 5, "log [1e-10, 1e10]: majors every 5 decades");
  CHECK_TRUE(t.n_minor == 16, "the other 16 decades are minor ticks");

  wl_error_clear(&err);
  CHECK_TRUE(wl_report_ticks_log(0.0, 10.0, 1, &t, &err) == WL_EINPUT &&
                 contains(err.msg, "not positive"),
             "log axis with a zero bound: WL_EINPUT");
}

static double linear_channel(double c) {
  return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static double luminance(const double rgb[3]) {
  return 0.2126 * linear_channel(rgb[0]) + 0.7152 * linear_channel(rgb[1]) +
         0.0722 * linear_channel(rgb[2]);
}

static void test_colours(void) {
  double rgb[3];
  wl_report_colormap(0.0, rgb);
  CHECK_ABS(rgb[0], 0.267004, 1e-6, "matplotlib viridis[0] red");
  CHECK_ABS(rgb[2], 0.329415, 1e-6, "matplotlib viridis[0] blue");
  wl_report_colormap(1.0, rgb);
  CHECK_ABS(rgb[1], 0.906157, 1e-6, "matplotlib viridis[255] green");
  int monotonic = 1;
  double prev = -1.0;
  for (int i = 0; i <= 200; i++) {
    wl_report_colormap(i / 200.0, rgb);
    double y = luminance(rgb);
    if (y <= prev) monotonic = 0;
    prev = y;
  }
  CHECK_TRUE(monotonic, "viridis: luminance (BT.709, linear sRGB) rises monotonically");
  wl_report_colormap(NAN, rgb);
  CHECK_TRUE(rgb[0] == rgb[1] && rgb[1] == rgb[2], "NaN value maps to grey");
  /* The first four series colours differ in luminance by at least 0.04
   * (with the dash cycle, what keeps them apart in greyscale). */
  double lum[4];
  for (int k = 0; k < 4; k++) {
    wl_report_palette(k + 1, rgb);
    lum[k] = luminance(rgb);
  }
  int apart = 1;
  for (int a = 0; a < 4; a++)
    for (int b = a + 1; b < 4; b++)
      if (fabs(lum[a] - lum[b]) < 0.04) apart = 0;
  CHECK_TRUE(apart, "palette 1-4 luminances at least 0.04 apart (BT.709)");
}

static void test_thin(void) {
  enum { N = 100000, BINS = 100 };
  double *x = malloc(N * sizeof *x), *y = malloc(N * sizeof *y);
  size_t *keep = malloc(N * sizeof *keep);
  if (!x || !y || !keep) {
    CHECK_TRUE(0, "memory for the thinning test");
    free(x), free(y), free(keep);
    return;
  }
  for (int i = 0; i < N; i++) {
    x[i] = i * 1e-3;
    y[i] = sin(2 * PI * x[i]);
  }
  y[31337] = 50.0;  /* spike */
  y[77777] = -40.0; /* dip */
  y[50000] = NAN;   /* gap */
  size_t n = wl_report_thin(x, y, N, x[0], x[N - 1], BINS, keep);
  int spike = 0, dip = 0, gap = 0, sorted = 1;
  for (size_t j = 0; j < n; j++) {
    if (keep[j] == 31337) spike = 1;
    if (keep[j] == 77777) dip = 1;
    if (keep[j] == 50000) gap = 1;
    if (j > 0 && keep[j] <= keep[j - 1]) sorted = 0;
  }
  CHECK_TRUE(spike && dip, "thinning keeps the global maximum and minimum (brute force: the spike)");
  CHECK_TRUE(gap, "thinning keeps the NaN gap");
  CHECK_TRUE(sorted, "kept indices in increasing order");
  CHECK_TRUE(n <= 4 * (BINS + 1) * 2 + 1, "at most 4 per bin per run");
  CHECK_TRUE(keep[0] == 0 && keep[n - 1] == N - 1, "first and last points kept");
  free(x), free(y), free(keep);
}

/* ---- templates ------------------------------------------------------------------- */

static void test_shipped_template(void) {
  struct wl_report_template t;
  struct wl_error err;
  wl_report_template_init(&t);
  wl_error_clear(&err);
  enum wl_status st =
      wl_report_template_load(WL_SOURCE_DIR "/report_templates/design.yaml", &t, &err);
  printf("%s design.yaml loads: %s [shipped template]\n", st == WL_OK ? "PASS" : "FAIL",
         st == WL_OK ? "ok" : err.msg);
  if (st != WL_OK) {
    wl_test_failures++;
    return;
  }
  static const enum wl_report_section_type order[] = {
      WL_REPORT_SECTION_TITLE,  WL_REPORT_SECTION_SCENE,           WL_REPORT_SECTION_SNAPSHOTS,
      WL_REPORT_SECTION_GAUGES, WL_REPORT_SECTION_LOADS,           WL_REPORT_SECTION_PEAKS,
      WL_REPORT_SECTION_DESIGN_FORMULAE, WL_REPORT_SECTION_CONVERGENCE,
      WL_REPORT_SECTION_METADATA};
  int same = t.n_sections == 9;
  for (int i = 0; same && i < 9; i++) same = t.sections[i].type == order[i];
  CHECK_TRUE(same, "design.yaml: the nine section types in the brief's order");
  CHECK_TRUE(strcmp(t.title, "Wave loads on a seawall") == 0, "design.yaml: title");
  CHECK_TRUE(t.n_sections >= 5 && strcmp(t.sections[4].title, "Wall loads") == 0 &&
                 t.sections[4].loads ==
                     (WL_REPORT_LOAD_FORCE | WL_REPORT_LOAD_IMPULSE | WL_REPORT_LOAD_MOMENT),
             "design.yaml: loads section title and quantities");
  CHECK_TRUE(t.n_sections >= 9 && t.sections[8].page_break == 1 && t.sections[8].scenario_text,
             "design.yaml: metadata on a new page, with the scenario text");
  CHECK_TRUE(t.n_sections >= 3 && t.sections[2].n_times == 0, "design.yaml: snapshot times auto");
  CHECK_TRUE(strcmp(t.block.date, "auto") == 0, "design.yaml: date auto");
  wl_report_template_clear(&t);
  CHECK_TRUE(t.sections == NULL && t.n_sections == 0, "clear leaves a zeroed template");
  wl_report_template_clear(&t); /* twice is safe */
}

static void test_good_template(void) {
  const char *text = "title: Retitled\n"
                     "sections:\n"
                     "  - { type: loads, title: Forces only, quantities: force }\n"
                     "  - type: snapshots\n"
                     "    times: [1.5 s, 2000 ms]\n"
                     "    x_range: [16 m, 20 m]\n"
                     "    field: velocity\n"
                     "  - { type: scene, exaggeration: 5, title: \"\" }\n"
                     "  - { type: gauges, gauges: [G2] }\n"
                     "  - { type: peaks, digits: 4 }\n";
  struct wl_report_template t;
  struct wl_error err;
  wl_report_template_init(&t);
  wl_error_clear(&err);
  enum wl_status st = wl_report_template_parse("edited.yaml", text, strlen(text), &t, &err);
  printf("%s edited template parses: %s [reordered, dropped, retitled]\n",
         st == WL_OK ? "PASS" : "FAIL", st == WL_OK ? "ok" : err.msg);
  if (st != WL_OK) {
    wl_test_failures++;
    return;
  }
  CHECK_TRUE(t.n_sections == 5 && t.sections[0].type == WL_REPORT_SECTION_LOADS,
             "order as written");
  CHECK_TRUE(strcmp(t.sections[0].title, "Forces only") == 0 &&
                 t.sections[0].loads == WL_REPORT_LOAD_FORCE,
             "retitled; a single quantity");
  CHECK_TRUE(t.sections[1].n_times == 2 && t.sections[1].times[0] == 1.5 &&
                 fabs(t.sections[1].times[1] - 2.0) < 1e-12,
             "times with units to seconds (2000 ms = 2 s)");
  CHECK_TRUE(t.sections[1].has_x_range && t.sections[1].x_range[0] == 16.0 &&
                 t.sections[1].x_range[1] == 20.0 && t.sections[1].field == WL_REPORT_FIELD_VELOCITY,
             "x_range and field");
  CHECK_TRUE(t.sections[2].exaggeration == 5.0 && t.sections[2].title[0] == '\0',
             "exaggeration; empty title means no heading");
  CHECK_TRUE(t.sections[3].n_gauges == 1 && strcmp(t.sections[3].gauges[0], "G2") == 0,
             "gauge list");
  CHECK_TRUE(t.sections[4].digits == 4 && strcmp(t.sections[4].title, "Peak loads") == 0,
             "digits; default title");
  CHECK_TRUE(t.sections[0].line == 3 && t.sections[0].col == 5, "section position 3:5");
  wl_report_template_clear(&t);
}

/* A bad template must fail with WL_EINPUT and a message holding each `want`. */
static void check_bad(const char *name, const char *text, const char *want1, const char *want2,
                      const char *want3) {
  struct wl_report_template t;
  struct wl_error err;
  wl_report_template_init(&t);
  wl_error_clear(&err);
  enum wl_status st = wl_report_template_parse("bad.yaml", text, strlen(text), &t, &err);
  int ok = st == WL_EINPUT && contains(err.msg, want1) && (!want2 || contains(err.msg, want2)) &&
           (!want3 || contains(err.msg, want3)) && t.sections == NULL && t.n_sections == 0;
  printf("%s bad template (%s): %s [want '%s'%s%s%s%s]\n", ok ? "PASS" : "FAIL", name, err.msg,
         want1, want2 ? ", '" : "", want2 ? want2 : "", want2 ? "'" : "", want3 ? " ..." : "");
  if (!ok) wl_test_failures++;
  wl_report_template_clear(&t);
}

static void test_bad_templates(void) {
  check_bad("unknown section type",
            "title: x\n"
            "sections:\n"
            "  - { type: title }\n"
            "  - { type: sceen, title: Flume }\n",
            "bad.yaml:4:13: sections[1].type: found 'sceen'", "did you mean 'scene'",
            "valid: title, scene, snapshots, gauges, loads, peaks, design_formulae, convergence, "
            "metadata");
  check_bad("unknown key",
            "sections:\n"
            "  - type: loads\n"
            "    title: Loads\n"
            "    colour: red\n",
            "bad.yaml:4:5: sections[0].colour: found unknown key 'colour'",
            "valid for a loads section: type, title, text, page_break, quantities", NULL);
  check_bad("key of another type",
            "sections:\n"
            "  - type: loads\n"
            "    times: [1 s]\n",
            "bad.yaml:3:5: sections[0].times: found key 'times'", "only snapshots sections",
            NULL);
  check_bad("malformed YAML",
            "title: x\n"
            "sections:\n"
            "  - { type: title\n"
            "  - { type: scene }\n",
            "bad.yaml:4:", "malformed YAML", NULL);
  check_bad("unknown top-level key",
            "titel: x\n"
            "sections: [ {type: title} ]\n",
            "bad.yaml:1:1: titel: found unknown key 'titel' (did you mean 'title'?)",
            "valid: company, title, subtitle, title_block, sections", NULL);
  check_bad("missing type",
            "sections:\n"
            "  - { title: Nothing }\n",
            "bad.yaml:2:5: sections[0]: found no 'type'", "valid types: title, scene", NULL);
  check_bad("time without unit",
            "sections:\n"
            "  - { type: snapshots, times: [2.5] }\n",
            /* col 32: the '2' after "  - { type: snapshots, times: [" (31 chars) */
            "bad.yaml:2:32: sections[0].times[0]:", "found '2.5' without a unit", NULL);
  check_bad("times not increasing",
            "sections:\n"
            "  - { type: snapshots, times: [3 s, 2 s] }\n",
            /* col 37: after "  - { type: snapshots, times: [3 s, " (36 chars) */
            "bad.yaml:2:37: sections[0].times[1]: found 2 s", "each later", NULL);
  check_bad("bad choice",
            "sections:\n"
            "  - { type: loads, quantities: [force, torque] }\n",
            /* col 40: after "  - { type: loads, quantities: [force, " (39 chars) */
            "bad.yaml:2:40: sections[0].quantities[1]: found 'torque'",
            "valid: force, impulse, moment, pressure, runup", NULL);
  check_bad("x_range reversed",
            "sections:\n"
            "  - { type: scene, x_range: [20 m, 16 m] }\n",
            /* col 29: the '[' after "  - { type: scene, x_range: " (28 chars) */
            "bad.yaml:2:29: sections[0].x_range: found [20 m, 16 m]", "from < to", NULL);
  check_bad("duplicate key",
            "sections:\n"
            "  - { type: peaks, digits: 3, digits: 4 }\n",
            /* col 31: the second key after "  - { type: peaks, digits: 3, " (30 chars) */
            "bad.yaml:2:31: sections[0].digits: found this key twice", NULL, NULL);
  check_bad("digits out of range",
            "sections:\n"
            "  - { type: peaks, digits: 9 }\n",
            "sections[0].digits: found '9'; valid: a whole number from 2 to 6", NULL, NULL);
  check_bad("no sections", "title: x\n", "bad.yaml:1:1: template: found no 'sections'", NULL,
            NULL);
  check_bad("empty sections", "sections: []\n", "bad.yaml:1:11: sections: found an empty list",
            NULL, NULL);
  check_bad("empty file", "", "bad.yaml:1:1: template: found an empty file", NULL, NULL);
  check_bad("bad boolean",
            "sections:\n"
            "  - { type: metadata, scenario_text: maybe }\n",
            "sections[0].scenario_text: found 'maybe'; valid: true, false", NULL, NULL);
  check_bad("title block key",
            "title_block: { projet: X }\n"
            "sections: [ {type: title} ]\n",
            "bad.yaml:1:16: title_block.projet: found unknown key 'projet' (did you mean "
            "'project'?)",
            NULL, NULL);
  check_bad("two documents",
            "sections: [ {type: title} ]\n"
            "---\n"
            "sections: [ {type: scene} ]\n",
            "bad.yaml:3:1: template: found a second YAML document", NULL, NULL);

  struct wl_report_template t;
  struct wl_error err;
  wl_report_template_init(&t);
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_template_load("/nonexistent/dir/t.yaml", &t, &err) == WL_EINPUT &&
                 contains(err.msg, "/nonexistent/dir/t.yaml") &&
                 contains(err.msg, "No such file or directory"),
             "missing template file: bad input naming it, with the system's reason");
  CHECK_TRUE(strcmp(wl_report_section_type_name(WL_REPORT_SECTION_DESIGN_FORMULAE),
                    "design_formulae") == 0 &&
                 strcmp(wl_report_section_type_name(WL_REPORT_SECTION_COUNT), "?") == 0,
             "type names");
}

/* ---- rendering -------------------------------------------------------------------- */

#define STEP(call)                                                                                \
  do {                                                                                            \
    enum wl_status st_ = (call);                                                                  \
    if (st_ != WL_OK) {                                                                           \
      printf("FAIL %s: %s (%s) [render]\n", #call, err.msg, wl_error_status_name(st_));         \
      wl_test_failures++;                                                                         \
      failed = 1;                                                                                 \
      goto out;                                                                                   \
    }                                                                                             \
  } while (0)

static const char *const LOREM =
    "The wall carries the hydrostatic load of the still water, and on top of it the dynamic load "
    "of the wave: a short impulsive peak when the front strikes, then a longer quasi-static "
    "load while the wave runs up and falls back. Both are shown below for each load case, per "
    "metre of wall. The numerical error of each peak is estimated from a ladder of three "
    "resolutions; the runtime of each level is given beside it, so the cost of a tighter answer "
    "can be read off directly. ";

static int render_full(const char *path, int *pages_out) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_report_doc *d = NULL;
  int failed = 0;
  double *lx = NULL, *ly = NULL, *px = NULL, *pz = NULL, *pv = NULL;
  struct wl_report_doc_info info = {"Toolkit test report", "synthetic-seawall",
                                    "Test Engineering Ltd", NULL};
  STEP(wl_report_doc_open(path, &info, &d, &err));

  /* Title page. */
  STEP(wl_report_add_title(d, "Wave loads on a seawall", "Synthetic data for the toolkit test",
                           &err));
  struct wl_report_kv block[] = {
      {"Project", "Harbour wall upgrade", 0, NULL, 0},
      {"Water depth", NULL, 0.36, "m", 3},
      {"Wave height", NULL, 0.05, "m", 2},
      {"Charge", NULL, 14.51495584, "kg", 4},
      {"Energy per width", NULL, 177000.0, "J/m", 3},
  };
  STEP(wl_report_add_kv_table(d, NULL, block, 5, &err));
  STEP(wl_report_add_paragraph(d, LOREM, &err));
  STEP(wl_report_break_page(d, &err));

  /* Tables. */
  STEP(wl_report_add_heading(d, 1, "Peak loads", &err));
  STEP(wl_report_add_paragraph(d, LOREM, &err));
  struct wl_report_column cols[] = {
      {"case", NULL, WL_REPORT_ALIGN_AUTO, 0},
      {"peak force", "kN/m", WL_REPORT_ALIGN_AUTO, 3},
      {"impulse", "kN s/m", WL_REPORT_ALIGN_AUTO, 3},
      {"rise time", "s", WL_REPORT_ALIGN_RIGHT, 2},
  };
  struct wl_report_cell cells[] = {
      {"solitary", 0}, {NULL, 12.345}, {NULL, 0.004567}, {NULL, 0.25},
      {"explosion", 0}, {NULL, 1234.5}, {NULL, 1.5e-7}, {NULL, NAN},
  };
  struct wl_report_table tab = {"Peak loads per metre of wall", cols, 4, cells, 2};
  STEP(wl_report_add_table(d, &tab, &err));

  /* A long table: breaks across a page and repeats its header. */
  enum { LONG_ROWS = 70 };
  struct wl_report_column lcols[] = {{"probe index", NULL, WL_REPORT_ALIGN_AUTO, 0},
                                     {"z", "m", WL_REPORT_ALIGN_AUTO, 3},
                                     {"peak pressure", "kPa", WL_REPORT_ALIGN_AUTO, 3}};
  static struct wl_report_cell lcells[LONG_ROWS * 3];
  static char names[LONG_ROWS][16];
  for (int r = 0; r < LONG_ROWS; r++) {
    snprintf(names[r], sizeof names[r], "P%02d", r);
    lcells[3 * r] = (struct wl_report_cell){names[r], 0};
    lcells[3 * r + 1] = (struct wl_report_cell){NULL, 0.005 * r};
    lcells[3 * r + 2] = (struct wl_report_cell){NULL, 10.0 * exp(-0.05 * r)};
  }
  struct wl_report_table ltab = {"Probe pressures", lcols, 3, lcells, LONG_ROWS};
  STEP(wl_report_add_table(d, &ltab, &err));

  /* A table too wide even at the smallest type: its words wrap (the
   * widest left-aligned column takes what the others leave). */
  struct wl_report_column wcols[] = {{"setting", NULL, WL_REPORT_ALIGN_AUTO, 0},
                                     {"value", NULL, WL_REPORT_ALIGN_AUTO, 3},
                                     {"reason", NULL, WL_REPORT_ALIGN_AUTO, 0}};
  struct wl_report_cell wcells[] = {
      {"dimensions", 0}, {NULL, 3.0},
      {"wrapfirst the crater is axisymmetric and narrower than the flume, so its wave spreads "
       "radially and a two-dimensional section of the flume cannot represent the decay of its "
       "height with distance from the charge, which the wall sees as a much smaller load than "
       "the plane wave of a section would give it; the plan therefore chooses three dimensions "
       "wraplast", 0},
      {"symmetry", 0}, {NULL, 1.0}, {"centreline", 0}};
  struct wl_report_table wtab = {"Wrapped reasons", wcols, 3, wcells, 2};
  STEP(wl_report_add_table(d, &wtab, &err));

  /* Plots. */
  STEP(wl_report_add_heading(d, 1, "Histories", &err));
  STEP(wl_report_add_heading(d, 2, "Free surface", &err));
  enum { NS = 400 };
  double t[NS], s1[NS], s2[NS], s3[NS];
  for (int i = 0; i < NS; i++) {
    t[i] = 10.0 * i / (NS - 1);
    s1[i] = 0.05 * sin(2 * PI * t[i] / 4.0);
    s2[i] = 0.03 * cos(2 * PI * t[i] / 3.0);
    s3[i] = (i % 100 < 30) ? NAN : 0.02 * sin(2 * PI * t[i]); /* gaps */
  }
  struct wl_report_series ser[] = {
      {"G1 (sine)", t, s1, NS, WL_REPORT_LINE_AUTO, WL_REPORT_MARKER_NONE, 0},
      {"G2 (cosine)", t, s2, NS, WL_REPORT_LINE_AUTO, WL_REPORT_MARKER_NONE, 0},
      {"G3 (with gaps)", t, s3, NS, WL_REPORT_LINE_AUTO, WL_REPORT_MARKER_NONE, 0},
      {"empty", NULL, NULL, 0, WL_REPORT_LINE_AUTO, WL_REPORT_MARKER_NONE, 0},
  };
  struct wl_report_refline ref = {0.045, "design level", 0};
  struct wl_report_plot plot = {"Free-surface elevation",
                                {"time", "s", 0, 0, 0, 0},
                                {"surface elevation", "m", 0, 0, 0, 0},
                                ser, 4, &ref, 1, WL_REPORT_LEGEND_AUTO};
  struct wl_report_rect area;
  STEP(wl_report_begin_figure(d, 220.0, &area, &err));
  STEP(wl_report_draw_plot(d, &plot, area, &err));
  STEP(wl_report_end_figure(d, "Surface elevation at three gauges (synthetic).", &err));

  /* Log-log error against runtime, with markers, and a scatter + no-data pair. */
  double runtime[] = {12.0, 48.0, 190.0, 760.0}, error_a[] = {0.08, 0.035, 0.016, 0.0072},
         error_b[] = {0.2, 0.06, 0.02, NAN};
  struct wl_report_series lser[] = {
      {"cpu", runtime, error_a, 4, WL_REPORT_LINE_SOLID, WL_REPORT_MARKER_AUTO, 0},
      {"cuda", runtime, error_b, 4, WL_REPORT_LINE_DASHED, WL_REPORT_MARKER_AUTO, 0},
  };
  struct wl_report_refline target = {0.05, "target error 5 %", 0};
  struct wl_report_plot lplot = {"Error against runtime",
                                 {"runtime", "s", 1, 0, 0, 0},
                                 {"relative error", NULL, 1, 0, 0, 0},
                                 lser, 2, &target, 1, WL_REPORT_LEGEND_BELOW};
  double sx[30], sy[30];
  for (int i = 0; i < 30; i++) {
    sx[i] = i * 0.1;
    sy[i] = sx[i] * sx[i] + 0.1 * sin(7.0 * i);
  }
  struct wl_report_series sser[] = {
      {"measured", sx, sy, 30, WL_REPORT_LINE_NONE, WL_REPORT_MARKER_CIRCLE, 0}};
  struct wl_report_refline vref = {1.5, "impact", 1};
  struct wl_report_plot splot = {"Scatter", {"distance", "m", 0, 0, 0, 0},
                                 {"run-up", "m", 0, 0, 0, 0}, sser, 1, &vref, 1,
                                 WL_REPORT_LEGEND_AUTO};
  double nan_x[3] = {NAN, NAN, NAN};
  struct wl_report_series nser[] = {{"nothing", nan_x, nan_x, 3, 0, 0, 0}};
  struct wl_report_plot nplot = {"All gaps", {"x", NULL, 0, 0, 0, 0}, {"y", NULL, 0, 0, 0, 0},
                                 nser, 1, NULL, 0, WL_REPORT_LEGEND_AUTO};
  STEP(wl_report_begin_figure(d, 400.0, &area, &err));
  struct wl_report_rect top = area, lower_l, lower_r;
  top.h = 230.0;
  struct wl_report_rect lower = {area.x, area.y + 240.0, area.w, area.h - 240.0};
  lower_l = wl_report_rect_cell(lower, 2, 1, 0, 12.0);
  lower_r = wl_report_rect_cell(lower, 2, 1, 1, 12.0);
  STEP(wl_report_draw_plot(d, &lplot, top, &err));
  STEP(wl_report_draw_plot(d, &splot, lower_l, &err));
  STEP(wl_report_draw_plot(d, &nplot, lower_r, &err));
  STEP(wl_report_end_figure(d, "Convergence, a scatter plot and a plot with only gaps.", &err));

  /* A long history (one million samples with a spike): thinned, peak kept. */
  lx = malloc(LONG_SERIES * sizeof *lx);
  ly = malloc(LONG_SERIES * sizeof *ly);
  if (!lx || !ly) {
    printf("FAIL memory for the long series [render]\n");
    wl_test_failures++;
    failed = 1;
    goto out;
  }
  for (int i = 0; i < LONG_SERIES; i++) {
    lx[i] = i * 1e-5;
    ly[i] = 2.0 + sin(lx[i]) + (i == 600000 ? 30.0 : 0.0);
  }
  struct wl_report_series hser[] = {
      {"force", lx, ly, LONG_SERIES, WL_REPORT_LINE_SOLID, WL_REPORT_MARKER_NONE, 0}};
  struct wl_report_plot hplot = {NULL, {"time", "s", 0, 0, 0, 0},
                                 {"wall force", "kN/m", 0, 0, 0, 0}, hser, 1, NULL, 0,
                                 WL_REPORT_LEGEND_NONE};
  STEP(wl_report_begin_figure(d, 160.0, &area, &err));
  STEP(wl_report_draw_plot(d, &hplot, area, &err));
  STEP(wl_report_end_figure(d, "A history of 10^6 samples.", &err));

  /* Particle snapshot with colour bar, true aspect. */
  STEP(wl_report_add_heading(d, 1, "Snapshots", &err));
  enum { NXP = 120, NZP = 30 };
  px = malloc(NXP * NZP * sizeof *px);
  pz = malloc(NXP * NZP * sizeof *pz);
  pv = malloc(NXP * NZP * sizeof *pv);
  if (!px || !pz || !pv) {
    printf("FAIL memory for the particles [render]\n");
    wl_test_failures++;
    failed = 1;
    goto out;
  }
  size_t np = 0;
  for (int i = 0; i < NXP; i++)
    for (int k = 0; k < NZP; k++) {
      double x = 16.0 + 0.025 * i, z = 0.0125 + 0.025 * k;
      double eta = 0.36 + 0.1 * exp(-pow((x - 17.0) / 0.4, 2));
      if (z > eta) continue;
      px[np] = x, pz[np] = z;
      pv[np] = 9.81 * (eta - z); /* kPa per 1000 kg/m^3 */
      if (i == 5 && k == 3) pv[np] = NAN;
      np++;
    }
  struct wl_report_field fld = {"t = 2.40 s", px, pz, pv, np, 0.0125,
                                {"x", "m", 0, 1, 16.4, 17.6}, {"z", "m", 0, 0, 0, 0},
                                "pressure", "kPa", 0, 0, 0};
  double fh = wl_report_field_fit_height(&fld, 482.0);
  STEP(wl_report_begin_figure(d, fh, &area, &err));
  STEP(wl_report_draw_field(d, &fld, area, &err));
  STEP(wl_report_end_figure(d, "Pressure near the wall (vertical colour bar).", &err));
  /* Long and low: the colour bar goes under the drawing. */
  struct wl_report_field strip = fld;
  strip.title = "whole window";
  strip.value_label = "hydrostatic head";
  strip.value_unit = "m";
  strip.x_axis.fixed = 1, strip.x_axis.min = 14.0, strip.x_axis.max = 20.0;
  fh = wl_report_field_fit_height(&strip, 482.0);
  STEP(wl_report_begin_figure(d, fh, &area, &err));
  STEP(wl_report_draw_field(d, &strip, area, &err));
  STEP(wl_report_end_figure(d, "A long, low window (horizontal colour bar).", &err));

  /* Scene sketch. */
  STEP(wl_report_add_heading(d, 1, "Scene", &err));
  double bx[] = {0, 16.33, 19.2, 19.2, 0}, bz[] = {0, 0, 0.5035, 0, 0};
  double wx[] = {0, 19.2, 19.2, 0}, wz[] = {0, 0, 0.36, 0.36};
  double wallx[] = {19.2, 19.5, 19.5, 19.2}, wallz[] = {0, 0, 0.96, 0.96};
  double fsx[] = {0, 4, 8, 12, 18.38}, fsz[] = {0.36, 0.36, 0.41, 0.36, 0.36};
  /* Water is the still-water rectangle, painted first; the bed over it. */
  struct wl_report_shape shapes[] = {
      {WL_REPORT_SHAPE_WATER, wx, wz, 4},
      {WL_REPORT_SHAPE_BED, bx, bz, 5},
      {WL_REPORT_SHAPE_WALL, wallx, wallz, 4},
      {WL_REPORT_SHAPE_LINE, fsx, fsz, 5},
      {WL_REPORT_SHAPE_OUTLINE, NULL, NULL, 0},
  };
  struct wl_report_mark marks[] = {{13.8, 0.36, "G1"}, {19.06, 0.36, "G2"}};
  struct wl_report_scene sc = {"Flume", shapes, 5, marks, 2, {"x", "m", 0, 0, 0, 0}, 1, 10.0};
  double sh = wl_report_scene_fit_height(&sc, 482.0);
  STEP(wl_report_begin_figure(d, sh, &area, &err));
  STEP(wl_report_draw_scene(d, &sc, area, &err));
  STEP(wl_report_end_figure(d, "The flume (vertical exaggeration 10).", &err));
  struct wl_report_scene close = sc;
  close.title = "Near the wall, true scale";
  close.exaggeration = 1.0;
  close.axes = 0;
  close.x_axis.fixed = 1, close.x_axis.min = 17.5, close.x_axis.max = 19.6;
  sh = wl_report_scene_fit_height(&close, 482.0);
  STEP(wl_report_begin_figure(d, sh, &area, &err));
  STEP(wl_report_draw_scene(d, &close, area, &err));
  STEP(wl_report_end_figure(d, "Close to the wall at true scale.", &err));

  /* Preformatted listing. */
  STEP(wl_report_add_heading(d, 1, "Run record", &err));
  STEP(wl_report_add_preformatted(d,
                                  "scenario: seawall\n"
                                  "water:     { depth: 0.36 m, density: 1000 kg/m^3 }\n"
                                  "domain:    { dimensions: 2, length: 36 m, width: 0.55 m }\n"
                                  "wall:      { x: 19.2 m, height: 0.05 m, probes: 20 }\n",
                                  &err));
  STEP(wl_report_add_heading(d, 3, "Unnumbered note", &err));
  STEP(wl_report_add_paragraph(d, "End of the test report.\nA second line after a break.", &err));
  *pages_out = wl_report_doc_pages(d);
  STEP(wl_report_doc_finish(d, &err));
out:
  wl_report_doc_free(d);
  free(lx), free(ly), free(px), free(pz), free(pv);
  return failed ? -1 : 0;
}

/* Ink pixels inside the content box of page `page` at 30 dpi (greyscale). */
static long page_ink(const char *pdf, int page) {
  char prefix[512], cmd[1200], pgm[600];
  snprintf(prefix, sizeof prefix, "%s/page%d", tmpdir, page);
  snprintf(cmd, sizeof cmd, "pdftoppm -r 30 -gray -f %d -l %d -singlefile '%s' '%s' 2>/dev/null",
           page, page, pdf, prefix);
  if (system(cmd) != 0) return -1;
  snprintf(pgm, sizeof pgm, "%s.pgm", prefix);
  FILE *f = fopen(pgm, "rb");
  if (!f) return -1;
  int w = 0, h = 0, maxval = 0;
  char magic[3] = {0};
  long ink = -1;
  if (fscanf(f, "%2s %d %d %d", magic, &w, &h, &maxval) == 4 && strcmp(magic, "P5") == 0 &&
      maxval == 255 && w > 0 && h > 0) {
    fgetc(f); /* the single whitespace after the header */
    unsigned char *px = malloc((size_t)w * h);
    if (px && fread(px, 1, (size_t)w * h, f) == (size_t)w * h) {
      int y0 = (int)(MM_TOP / 25.4 * 30.0), y1 = h - (int)(MM_BOTTOM / 25.4 * 30.0);
      ink = 0;
      for (int y = y0; y < y1; y++)
        for (int x = 0; x < w; x++)
          if (px[(size_t)y * w + x] < WHITE_LEVEL) ink++;
    }
    free(px);
  }
  fclose(f);
  remove(pgm);
  return ink;
}

static void inspect_full(const char *pdf, int pages) {
  char cmd[1024];
  if (!have_tool("pdfinfo")) {
    printf("SKIP pdfinfo not installed: page count not checked\n");
  } else {
    snprintf(cmd, sizeof cmd, "pdfinfo '%s'", pdf);
    char *info = run_capture(cmd);
    const char *p = info ? strstr(info, "Pages:") : NULL;
    int n = p ? atoi(p + 6) : -1;
    printf("%s pdfinfo: %d pages, the document counted %d [poppler pdfinfo]\n",
           n == pages && n >= 5 ? "PASS" : "FAIL", n, pages);
    if (!(n == pages && n >= 5)) wl_test_failures++;
    squeeze(info);
    CHECK_TRUE(contains(info, "Page size: 595.276 x 841.89 pts (A4)"),
               "pdfinfo: A4 portrait (ISO 216: 595.276 x 841.89 pt)");
    CHECK_TRUE(contains(info, "Title: Toolkit test report") &&
                   contains(info, "Author: Test Engineering Ltd"),
               "pdfinfo: title and author metadata");
    free(info);
  }
  if (!have_tool("pdftotext")) {
    printf("SKIP pdftotext not installed: text not checked\n");
  } else {
    snprintf(cmd, sizeof cmd, "pdftotext '%s' -", pdf);
    char *text = run_capture(cmd);
    squeeze(text);
    static const char *const want[] = {
        "12.3", "0.00457", "1230", "1.50\xc3\x97" "10\xe2\x81\xbb\xe2\x81\xb7", "n/a", "0.25",
        "[kN/m]", "[kN s/m]", "peak force", "Table 1. Peak loads per metre of wall",
        "0.360", "14.51", "177000", "J/m", "Harbour wall upgrade",
        "time [s]", "surface elevation [m]", "runtime [s]", "relative error", "design level",
        "target error 5 %", "G1 (sine)", "G2 (cosine)", "cpu", "cuda", "no data",
        "pressure [kPa]", "x [m]", "hydrostatic head [m]", "G1", "G2",
        "vertical exaggeration \xc3\x97" "10", "true scale", "depth: 0.36 m",
        "1 Peak loads", "2.1 Free surface", "Figure 7. Close to the wall at true scale.",
        "synthetic-seawall", "wallload ", "page 2", "Test Engineering Ltd",
        "P69", "wall force [kN/m]", "wrapfirst", "wraplast", "Wrapped reasons"};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
      int ok = contains(text, want[i]);
      printf("%s pdftotext shows '%s' [poppler pdftotext]\n", ok ? "PASS" : "FAIL", want[i]);
      if (!ok) wl_test_failures++;
    }
    CHECK_TRUE(count_of(text, "probe index") >= 2, "long table header repeated on the next page");
    free(text);
  }
  if (!have_tool("pdftoppm")) {
    printf("SKIP pdftoppm not installed: pages not rasterised\n");
  } else {
    for (int pg = 1; pg <= pages; pg++) {
      long ink = page_ink(pdf, pg);
      printf("%s page %d: %ld ink pixels in the content box at 30 dpi (want >= %d) [poppler "
             "pdftoppm]\n",
             ink >= INK_MIN ? "PASS" : "FAIL", pg, ink, INK_MIN);
      if (ink < INK_MIN) wl_test_failures++;
    }
  }
  if (!have_tool("pdffonts")) {
    printf("SKIP pdffonts not installed: font embedding not checked\n");
  } else {
    snprintf(cmd, sizeof cmd, "pdffonts '%s'", pdf);
    char *fonts = run_capture(cmd);
    /* Each font line ends "emb sub uni object ID": emb is the 5th token from the end. */
    int n_fonts = 0, all_embedded = fonts != NULL;
    char *save = NULL;
    for (char *line = fonts ? strtok_r(fonts, "\n", &save) : NULL; line;
         line = strtok_r(NULL, "\n", &save)) {
      if (strncmp(line, "name", 4) == 0 || strncmp(line, "----", 4) == 0) continue;
      char *tok[32];
      int nt = 0;
      char *s2 = NULL;
      for (char *w = strtok_r(line, " ", &s2); w && nt < 32; w = strtok_r(NULL, " ", &s2))
        tok[nt++] = w;
      if (nt < 6) continue;
      n_fonts++;
      if (strcmp(tok[nt - 5], "yes") != 0) all_embedded = 0;
    }
    CHECK_TRUE(n_fonts >= 2 && all_embedded, "pdffonts: every font embedded");
    free(fonts);
  }
  if (!have_tool("pdfimages")) {
    printf("SKIP pdfimages not installed: vector output not checked\n");
  } else {
    snprintf(cmd, sizeof cmd, "pdfimages -list '%s' | tail -n +3 | wc -l", pdf);
    char *n = run_capture(cmd);
    CHECK_TRUE(n && atoi(n) == 0, "pdfimages: no raster images (vector output)");
    free(n);
  }
}

static void test_render(void) {
  char pdf[512];
  snprintf(pdf, sizeof pdf, "%s/full.pdf", tmpdir);
  int pages = 0;
  int rc = render_full(pdf, &pages);
  CHECK_TRUE(rc == 0 && file_exists(pdf), "full report rendered");
  char part[600];
  snprintf(part, sizeof part, "%s.part", pdf);
  CHECK_TRUE(!file_exists(part), "no .part file left after finish");
  long size = file_size(pdf);
  printf("%s PDF size %ld bytes with a 10^6-sample series (want < %d) [thinning]\n",
         size > 0 && size < THINNED_PDF_MAX ? "PASS" : "FAIL", size, THINNED_PDF_MAX);
  if (!(size > 0 && size < THINNED_PDF_MAX)) wl_test_failures++;
  if (rc == 0) inspect_full(pdf, pages);
}

/* Many particles: rasterised dots, one image in the PDF. */
static void test_raster_field(void) {
  char pdf[512];
  snprintf(pdf, sizeof pdf, "%s/raster.pdf", tmpdir);
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_report_doc *d = NULL;
  enum { NX = 500, NZ = 160 };
  size_t n = (size_t)NX * NZ;
  double *x = malloc(n * sizeof *x), *z = malloc(n * sizeof *z), *v = malloc(n * sizeof *v);
  enum wl_status st = x && z && v ? WL_OK : WL_ENOMEM;
  for (size_t i = 0; st == WL_OK && i < n; i++) {
    x[i] = 0.01 * (double)(i % NX);
    z[i] = 0.01 * (double)(i / NX);
    v[i] = sin(x[i]) * z[i];
  }
  if (st == WL_OK) st = wl_report_doc_open(pdf, NULL, &d, &err);
  struct wl_report_field f = {NULL, x, z, v, n, 0.0, {"x", "m", 0, 0, 0, 0},
                              {"z", "m", 0, 0, 0, 0}, "v", NULL, 0, 0, 0};
  struct wl_report_rect area;
  if (st == WL_OK) st = wl_report_reserve(d, wl_report_field_fit_height(&f, 482.0), &area, &err);
  if (st == WL_OK) st = wl_report_draw_field(d, &f, area, &err);
  if (st == WL_OK) st = wl_report_doc_finish(d, &err);
  wl_report_doc_free(d);
  free(x), free(z), free(v);
  printf("%s %zu particles rendered: %s [raster path]\n", st == WL_OK ? "PASS" : "FAIL", n,
         st == WL_OK ? "ok" : err.msg);
  if (st != WL_OK) {
    wl_test_failures++;
    return;
  }
  if (!have_tool("pdfimages")) {
    printf("SKIP pdfimages not installed: raster image not checked\n");
    return;
  }
  char cmd[700];
  snprintf(cmd, sizeof cmd, "pdfimages -list '%s' | tail -n +3 | wc -l", pdf);
  char *out = run_capture(cmd);
  CHECK_TRUE(out && atoi(out) == 1, "pdfimages: the particles are one raster image");
  free(out);
}

/* ---- error paths ------------------------------------------------------------------- */

enum bad_call {
  BAD_SERIES_NULL,
  BAD_LOG_RANGE,
  BAD_TABLE_COLS,
  BAD_TABLE_WIDE,
  BAD_HEADING,
  BAD_END_FIGURE,
  BAD_FIELD_NULL,
  BAD_SCENE_NULL,
  BAD_PLOT_TINY,
};

static enum wl_status bad_call(struct wl_report_doc *d, enum bad_call which,
                               struct wl_error *err) {
  struct wl_report_rect r = {60, 80, 400, 200};
  switch (which) {
  case BAD_SERIES_NULL: {
    struct wl_report_series s = {"s", NULL, NULL, 5, 0, 0, 0};
    struct wl_report_plot p = {"p", {0}, {0}, &s, 1, NULL, 0, 0};
    return wl_report_draw_plot(d, &p, r, err);
  }
  case BAD_LOG_RANGE: {
    struct wl_report_plot p = {"p", {"x", NULL, 1, 1, 0.0, 10.0}, {0}, NULL, 0, NULL, 0, 0};
    return wl_report_draw_plot(d, &p, r, err);
  }
  case BAD_TABLE_COLS: {
    struct wl_report_table t = {"t", NULL, 0, NULL, 0};
    return wl_report_add_table(d, &t, err);
  }
  case BAD_TABLE_WIDE: {
    static struct wl_report_column cols[16];
    static struct wl_report_cell cells[16];
    for (int c = 0; c < 16; c++) {
      cols[c] = (struct wl_report_column){"a very long column heading", NULL, 0, 0};
      cells[c] = (struct wl_report_cell){"wide", 0};
    }
    struct wl_report_table t = {"wide", cols, 16, cells, 1};
    return wl_report_add_table(d, &t, err);
  }
  case BAD_HEADING: return wl_report_add_heading(d, 7, "h", err);
  case BAD_END_FIGURE: return wl_report_end_figure(d, "c", err);
  case BAD_FIELD_NULL: {
    struct wl_report_field f = {NULL, NULL, NULL, NULL, 10, 0, {0}, {0}, NULL, NULL, 0, 0, 0};
    return wl_report_draw_field(d, &f, r, err);
  }
  case BAD_SCENE_NULL: {
    struct wl_report_shape s = {WL_REPORT_SHAPE_BED, NULL, NULL, 4};
    struct wl_report_scene sc = {NULL, &s, 1, NULL, 0, {0}, 0, 1.0};
    return wl_report_draw_scene(d, &sc, r, err);
  }
  case BAD_PLOT_TINY: {
    struct wl_report_plot p = {NULL, {0}, {0}, NULL, 0, NULL, 0, 0};
    struct wl_report_rect tiny = {60, 80, 30, 20};
    return wl_report_draw_plot(d, &p, tiny, err);
  }
  }
  return WL_OK;
}

static void check_error_path(enum bad_call which, enum wl_status want, const char *needle,
                             const char *ref) {
  char pdf[512], part[600];
  snprintf(pdf, sizeof pdf, "%s/bad%d.pdf", tmpdir, (int)which);
  snprintf(part, sizeof part, "%s.part", pdf);
  struct wl_error err, err2, err3;
  wl_error_clear(&err), wl_error_clear(&err2), wl_error_clear(&err3);
  struct wl_report_doc *d = NULL;
  if (wl_report_doc_open(pdf, NULL, &d, &err) != WL_OK) {
    printf("FAIL open for %s: %s\n", ref, err.msg);
    wl_test_failures++;
    return;
  }
  wl_report_add_paragraph(d, "before the error", &err);
  enum wl_status st = bad_call(d, which, &err);
  enum wl_status later = wl_report_add_paragraph(d, "after the error", &err2);
  enum wl_status fin = wl_report_doc_finish(d, &err3);
  wl_report_doc_free(d);
  int ok = st == want && contains(err.msg, needle) && later == want && fin == want &&
           !file_exists(pdf) && !file_exists(part);
  printf("%s %s: %s; later call %s, finish %s, no file [error path]\n", ok ? "PASS" : "FAIL", ref,
         err.msg, wl_error_status_name(later), wl_error_status_name(fin));
  if (!ok) wl_test_failures++;
}

static void test_errors(void) {
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_report_doc *d = (struct wl_report_doc *)1;
  CHECK_TRUE(wl_report_doc_open("/nonexistent/dir/r.pdf", NULL, &d, &err) == WL_EINPUT &&
                 d == NULL && contains(err.msg, "/nonexistent/dir/r.pdf") &&
                 contains(err.msg, "No such file or directory"),
             "PDF in a missing directory: bad input naming the file and the reason");
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_doc_open("", NULL, &d, &err) == WL_EINPUT, "empty path: WL_EINPUT");
  check_error_path(BAD_SERIES_NULL, WL_EINPUT, "has 5 points but no data", "series without data");
  check_error_path(BAD_LOG_RANGE, WL_EINPUT, "min > 0 (log axis)", "log axis from 0");
  check_error_path(BAD_TABLE_COLS, WL_EINPUT, "found 0 columns; valid: 1 to 16", "no columns");
  check_error_path(BAD_TABLE_WIDE, WL_EINPUT, "the page has", "table wider than the page");
  check_error_path(BAD_HEADING, WL_EINPUT, "heading level 7; valid: 1, 2, 3", "heading level");
  check_error_path(BAD_END_FIGURE, WL_EINPUT, "end_figure without begin_figure",
                   "unbalanced figure");
  check_error_path(BAD_FIELD_NULL, WL_EINPUT, "10 particles but no data", "field without data");
  check_error_path(BAD_SCENE_NULL, WL_EINPUT, "shape 0 has 4 vertices but no data",
                   "scene without data");
  check_error_path(BAD_PLOT_TINY, WL_EINPUT, "too small", "plot area too small");

  /* Freed unfinished: the partial file goes. */
  char pdf[512], part[600];
  snprintf(pdf, sizeof pdf, "%s/abandoned.pdf", tmpdir);
  snprintf(part, sizeof part, "%s.part", pdf);
  wl_error_clear(&err);
  d = NULL;
  wl_report_doc_open(pdf, NULL, &d, &err);
  wl_report_add_paragraph(d, "never finished", &err);
  int had_part = file_exists(part);
  wl_report_doc_free(d);
  CHECK_TRUE(had_part && !file_exists(part) && !file_exists(pdf),
             "free without finish removes the partial file");
  wl_report_doc_free(NULL);

  /* An empty document still makes a valid one-page PDF. */
  snprintf(pdf, sizeof pdf, "%s/empty.pdf", tmpdir);
  d = NULL;
  wl_error_clear(&err);
  enum wl_status st = wl_report_doc_open(pdf, NULL, &d, &err);
  if (st == WL_OK) st = wl_report_doc_finish(d, &err);
  wl_report_doc_free(d);
  CHECK_TRUE(st == WL_OK && file_exists(pdf), "empty document: one page written");
}

int main(void) {
  snprintf(tmpdir, sizeof tmpdir, "%s/wl_report_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (!mkdtemp(tmpdir)) {
    printf("FAIL cannot create a temporary directory\n");
    return 1;
  }
  test_format();
  test_ticks();
  test_colours();
  test_thin();
  test_shipped_template();
  test_good_template();
  test_bad_templates();
  test_render();
  test_raster_field();
  test_errors();
  /* WL_KEEP_TEST_FILES=1 keeps the PDFs for a look. */
  if (wl_test_failures == 0 && !getenv("WL_KEEP_TEST_FILES")) {
    char cmd[400];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    if (system(cmd) != 0) printf("note: could not remove %s\n", tmpdir);
  } else {
    printf("files kept in %s\n", tmpdir);
  }
  printf("%d failure(s)\n", wl_test_failures);
  return TEST_RESULT();
}
