/* test_report_render.c: the design report rendered from a results.h5 alone
 * (wl_report_render), its SHA-256 input digest and its leading-wave
 * measurement.
 *
 * References from outside the code under test:
 *  - SHA-256: FIPS 180-4 / NIST CSRC example vectors ("abc", the 448-bit
 *    two-block message, one million 'a') and coreutils sha256sum on texts
 *    of every padding boundary length (55, 56, 63, 64, 65 bytes);
 *  - results: a synthetic results.h5 written with the store module from
 *    ANALYTIC series: Gaussian force pulses F(t) = F0 + A exp(-((t-t0)/s)^2)
 *    on top of the hydrostatic force F0 = rho g d^2/2, with the loads assess
 *    stores beside them in closed form: impulse A s sqrt(pi) (erf), moment
 *    with a fixed lever, 10 % rise time s sqrt(ln 10) and duration twice
 *    that, worked by hand below and printed to 3 significant digits (the
 *    shipped template's peaks `digits`);
 *  - leading wave: a sech^2 record (period measure 4 acosh(sqrt 10)/(K c)
 *    in closed form) and one sine period (crest a, trough -a);
 *  - PDFs read back with poppler (pdfinfo, pdftotext, pdftoppm), programs
 *    that did not write them. */
#define _POSIX_C_SOURCE 200809L /* popen, mkdtemp */

#include "wallload/report.h"

#include "../src/report/digest.h"
#include "../src/report/sections.h"
#include "testutil.h"
#include "wallload/assess.h"
#include "wallload/store.h"

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
#define WHITE_LEVEL 240 /* a grey pixel below this is ink */
#define INK_MIN 150     /* ink pixels a page's content box must have at 30 dpi */
#define MM_TOP 25.0     /* content box of the page model (src/report/doc.h) */
#define MM_BOTTOM 22.0

/* The synthetic wall: 0.2 m of water on a flat bed, wall at x = 3 m. */
#define RHO 1000.0
#define G 9.81
#define DEPTH 0.2
#define F_STATIC (RHO * G * DEPTH * DEPTH / 2)         /* 196.2 N/m */
#define M_STATIC (RHO * G * DEPTH * DEPTH * DEPTH / 6) /* 13.08 N m/m */
#define LEVER 0.1                                      /* pulse moment arm [m] */
#define DT 0.0002                                      /* sampling [s] */

static char tmpdir[256];

const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:libfontconfig.so\n"; }

static const char *const SCENARIO = "scenario: synthetic-wall\n"
                                    "water: {depth: 0.2 m}\n"
                                    "domain: {length: 4 m}\n"
                                    "wall: {x: 3 m, height: 0.4 m, probes: 10}\n"
                                    "gauges: [{name: G1, x: 2 m}]\n"
                                    "loads:\n"
                                    "  solitary: {height: 0.06 m, generation: initial, at: 1.6 m}\n"
                                    "  explosion: {energy: same-as-solitary, at: 1.5 m}\n"
                                    "resolution: {dp: 0.02 m}\n"
                                    "run: {output_interval: 0.02 s}\n";

/* ---- helpers ---------------------------------------------------------------------- */

static int have_tool(const char *name) {
  char cmd[256];
  snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", name);
  return system(cmd) == 0;
}

static char *run_capture(const char *cmd) {
  FILE *p = popen(cmd, "r");
  if (!p)
    return NULL;
  size_t cap = 1 << 16, len = 0, got;
  char *buf = malloc(cap);
  while (buf && (got = fread(buf + len, 1, cap - len - 1, p)) > 0) {
    len += got;
    if (len + 1 == cap) {
      char *b = realloc(buf, cap * 2);
      if (!b) {
        free(buf);
        buf = NULL;
        break;
      }
      buf = b, cap *= 2;
    }
  }
  int rc = pclose(p);
  if (!buf)
    return NULL;
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

/* Runs of white space to one space (pdftotext -layout pads columns). */
static void squeeze(char *s) {
  if (!s)
    return;
  char *w = s;
  for (const char *r = s; *r; r++) {
    char ch = (*r == '\n' || *r == '\t') ? ' ' : *r;
    if (!(ch == ' ' && w > s && w[-1] == ' '))
      *w++ = ch;
  }
  *w = '\0';
}

static int contains(const char *hay, const char *needle) { return hay && strstr(hay, needle); }

static void check_text(const char *text, const char *want, const char *ref) {
  int ok = contains(text, want);
  printf("%s pdftotext shows '%s' [%s]\n", ok ? "PASS" : "FAIL", want, ref);
  if (!ok)
    wl_test_failures++;
}

static void check_no_text(const char *text, const char *bad, const char *ref) {
  int ok = text && !contains(text, bad);
  printf("%s pdftotext does not show '%s' [%s]\n", ok ? "PASS" : "FAIL", bad, ref);
  if (!ok)
    wl_test_failures++;
}

/* Ink pixels inside the content box of page `page` at 30 dpi (greyscale). */
static long page_ink(const char *pdf, int page) {
  char prefix[512], cmd[1400], pgm[600];
  snprintf(prefix, sizeof prefix, "%s/ink%d", tmpdir, page);
  snprintf(cmd, sizeof cmd, "pdftoppm -r 30 -gray -f %d -l %d -singlefile '%s' '%s' 2>/dev/null",
           page, page, pdf, prefix);
  if (system(cmd) != 0)
    return -1;
  snprintf(pgm, sizeof pgm, "%s.pgm", prefix);
  FILE *f = fopen(pgm, "rb");
  if (!f)
    return -1;
  int w = 0, h = 0, maxval = 0;
  char magic[3] = {0};
  long ink = -1;
  if (fscanf(f, "%2s %d %d %d", magic, &w, &h, &maxval) == 4 && !strcmp(magic, "P5") &&
      maxval == 255 && w > 0 && h > 0) {
    fgetc(f);
    unsigned char *px = malloc((size_t)w * h);
    if (px && fread(px, 1, (size_t)w * h, f) == (size_t)w * h) {
      int y0 = (int)(MM_TOP / 25.4 * 30.0), y1 = h - (int)(MM_BOTTOM / 25.4 * 30.0);
      ink = 0;
      for (int y = y0; y < y1; y++)
        for (int x = 0; x < w; x++)
          if (px[(size_t)y * w + x] < WHITE_LEVEL)
            ink++;
    }
    free(px);
  }
  fclose(f);
  remove(pgm);
  return ink;
}

/* ---- SHA-256 ------------------------------------------------------------------------ */

static void check_sha(const void *data, size_t len, const char *want, const char *ref) {
  char hex[65];
  wl_report_sha256_hex(data, len, hex);
  int ok = !strcmp(hex, want);
  printf("%s sha256(%s) = %s [%s]\n", ok ? "PASS" : "FAIL", ref, hex, ref);
  if (!ok)
    wl_test_failures++;
}

static void test_sha256(void) {
  check_sha("", 0, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855",
            "empty message, NIST");
  check_sha("abc", 3, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad",
            "FIPS 180-4 example 'abc'");
  const char *two = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
  check_sha(two, strlen(two), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1",
            "FIPS 180-4 example, 448 bits (two blocks)");
  size_t n = 1000000;
  char *a = malloc(n);
  if (a) {
    memset(a, 'a', n);
    check_sha(a, n, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0",
              "one million 'a', NIST");
    free(a);
  }
  if (!have_tool("sha256sum")) {
    printf("SKIP sha256sum not installed: padding boundaries not cross-checked\n");
    return;
  }
  static const size_t lens[] = {1, 55, 56, 63, 64, 65, 119, 120, 128, 1000};
  for (size_t i = 0; i < sizeof lens / sizeof lens[0]; i++) {
    char path[400], cmd[600], buf[1000];
    for (size_t k = 0; k < lens[i]; k++)
      buf[k] = (char)('A' + (k * 7 + i) % 53);
    snprintf(path, sizeof path, "%s/sha%zu.bin", tmpdir, lens[i]);
    FILE *f = fopen(path, "wb");
    if (!f)
      continue;
    fwrite(buf, 1, lens[i], f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "sha256sum '%s'", path);
    char *out = run_capture(cmd);
    char hex[65];
    wl_report_sha256_hex(buf, lens[i], hex);
    int ok = out && !strncmp(out, hex, 64);
    printf("%s sha256 of %zu bytes = sha256sum's %.16s... [coreutils sha256sum]\n",
           ok ? "PASS" : "FAIL", lens[i], out ? out : "(none)");
    if (!ok)
      wl_test_failures++;
    free(out);
  }
}

/* ---- leading wave --------------------------------------------------------------------- */

static void test_leading_wave(void) {
  enum { N = 20001 };
  static double t[N], eta[N];
  /* sech^2 crest: eta = H sech^2(K c (t - tc)); above 10 % of H for
   * 2 acosh(sqrt 10)/(K c), the period measure is twice that. */
  double H = 0.05, K = 1.3, c = 1.9, tc = 5.0;
  for (int i = 0; i < N; i++) {
    t[i] = i * 0.0005;
    double s = 1.0 / cosh(K * c * (t[i] - tc));
    eta[i] = H * s * s;
  }
  double h, T, tcr;
  int ok = wl_report_leading_wave(t, eta, N, &h, &T, &tcr);
  CHECK_TRUE(ok, "sech^2 record has a crest");
  CHECK_REL(h, H, 1e-9, "sech^2: height = H (no trough)");
  CHECK_REL(T, 4.0 * acosh(sqrt(10.0)) / (K * c), 1e-5, "sech^2: 4 acosh(sqrt 10)/(K c)");
  CHECK_ABS(tcr, tc, 1e-12, "sech^2: crest time");
  /* one sine period from t = 1 s: crest a, trough -a; above 0.1 a for
   * T0/2 - T0 asin(0.1)/pi, the measure is twice that */
  double a = 0.03, T0 = 2.0;
  for (int i = 0; i < N; i++)
    eta[i] = (t[i] > 1.0 && t[i] < 1.0 + T0) ? a * sin(2 * PI * (t[i] - 1.0) / T0) : 0.0;
  wl_report_leading_wave(t, eta, N, &h, &T, &tcr);
  CHECK_REL(h, 2 * a, 1e-6, "sine: crest to trough 2a");
  CHECK_REL(T, 2.0 * (T0 / 2 - T0 * asin(0.1) / PI), 1e-5, "sine: closed-form time above 10 %");
  /* a crest that does not fall back within the record: no period */
  for (int i = 0; i < N; i++)
    eta[i] = 0.01 * t[i];
  wl_report_leading_wave(t, eta, N, &h, &T, &tcr);
  CHECK_TRUE(isnan(T) && h > 0, "rising record: height, no period");
  for (int i = 0; i < N; i++)
    eta[i] = -0.01;
  CHECK_TRUE(!wl_report_leading_wave(t, eta, N, &h, &T, &tcr) && isnan(h),
             "no crest above zero: none");
}

/* ---- synthetic results --------------------------------------------------------------- */

struct pulse {
  double A, t0, s; /* force pulse amplitude [N/m], time [s], width [s] */
  double t_end;    /* record length [s] */
  double runup;    /* peak water level at the wall [m] */
  double boundary; /* boundary-particle force = F0 + boundary * pulse */
  const char *status, *stopped;
};

#define STORE(call)                                                                                \
  do {                                                                                             \
    if (!st)                                                                                       \
      st = (call);                                                                                 \
  } while (0)

static enum wl_status write_case(struct wl_store *h5, const char *name, const struct pulse *p,
                                 struct wl_error *err) {
  size_t n = (size_t)llround(p->t_end / DT) + 1;
  enum { NP = 10 };
  double *v[16];
  for (int i = 0; i < 16; i++)
    v[i] = malloc(n * sizeof(double));
  double *pr = malloc(n * NP * sizeof(double));
  enum wl_status st = WL_OK;
  for (int i = 0; i < 16; i++)
    if (!v[i])
      st = WL_ENOMEM;
  if (!pr)
    st = WL_ENOMEM;
  if (st) {
    for (int i = 0; i < 16; i++)
      free(v[i]);
    free(pr);
    return wl_error_set(err, st, "test: no memory");
  }
  double *t = v[0], *f = v[1], *ff = v[2], *fb = v[3], *fbf = v[4], *imp = v[5], *impb = v[6],
         *m = v[7], *mf = v[8], *mb = v[9], *ke = v[10], *pe = v[11], *g1 = v[12], *wall = v[13];
  double pz[NP];
  for (int j = 0; j < NP; j++)
    pz[j] = 0.4 * (j + 0.5) / NP;
  for (size_t k = 0; k < n; k++) {
    t[k] = k * DT;
    double x = (t[k] - p->t0) / p->s, g = exp(-x * x);
    double ring = 0.03 * p->A * sin(2 * PI * 60.0 * t[k]); /* raw series only */
    ff[k] = F_STATIC + p->A * g;
    f[k] = ff[k] + ring;
    fbf[k] = F_STATIC + p->boundary * p->A * g;
    fb[k] = fbf[k] + ring;
    /* int_0^t A exp(-((t'-t0)/s)^2) dt' */
    imp[k] = p->A * p->s * sqrt(PI) / 2 * (erf(x) + erf(p->t0 / p->s));
    impb[k] = p->boundary * imp[k];
    mf[k] = M_STATIC + LEVER * p->A * g;
    m[k] = mf[k] + LEVER * ring;
    mb[k] = M_STATIC + LEVER * p->boundary * p->A * g;
    ke[k] = 5.0 * g, pe[k] = 10.0 - 5.0 * g;
    double sw = 1.0 / cosh(4.0 * (t[k] - (p->t0 - 0.2)));
    g1[k] = 0.05 * sw * sw;
    wall[k] = p->runup * g;
    for (int j = 0; j < NP; j++)
      pr[k * NP + j] = RHO * G * fmax(0.0, DEPTH - pz[j]) + p->A * g * 2.5 * (pz[j] < 0.25);
  }
  char b[128], q[200];
  snprintf(b, sizeof b, "cases/%s", name);
#define VEC(path, data, unit)                                                                      \
  snprintf(q, sizeof q, "%s/%s", b, path);                                                         \
  STORE(wl_store_write_vector(h5, q, data, n, unit, "synthetic", err))
  VEC("time", t, "s");
  VEC("wall/force", f, "N/m");
  VEC("wall/force_filtered", ff, "N/m");
  VEC("wall/force_boundary", fb, "N/m");
  VEC("wall/force_boundary_filtered", fbf, "N/m");
  VEC("wall/impulse", imp, "N s/m");
  VEC("wall/impulse_boundary", impb, "N s/m");
  VEC("wall/moment", m, "N m/m");
  VEC("wall/moment_filtered", mf, "N m/m");
  VEC("wall/moment_boundary", mb, "N m/m");
  VEC("energy/kinetic", ke, "J/m");
  VEC("energy/potential", pe, "J/m");
  VEC("gauges/G1/eta", g1, "m");
  VEC("gauges/wall/eta", wall, "m");
#undef VEC
  snprintf(q, sizeof q, "%s/wall/pressure", b);
  STORE(wl_store_write_matrix(h5, q, pr, n, NP, "Pa", "synthetic", err));
  snprintf(q, sizeof q, "%s/wall/probe_z", b);
  STORE(wl_store_write_vector(h5, q, pz, NP, "m", "synthetic", err));
  snprintf(q, sizeof q, "%s/gauges/G1", b);
  STORE(wl_store_attr_double(h5, q, "x", 2.0, "m", err));
  snprintf(q, sizeof q, "%s/gauges/wall", b);
  STORE(wl_store_attr_double(h5, q, "x", 2.99, "m", err));
  struct {
    const char *name;
    double v;
    const char *unit;
  } attrs[] = {{"dp", 0.02, "m"},
               {"smoothing_length", 0.028, "m"},
               {"c0", 16.0, "m/s"},
               {"particles", 2206, "1"},
               {"fluid_particles", 1459, "1"},
               {"steps", 870, "1"},
               {"runtime", 1.8, "s"},
               {"end_time", 2.0, "s"},
               {"time_reached", p->t_end, "s"},
               {"filter_cutoff", 10.0, "Hz"},
               {"static_force", F_STATIC, "N/m"},
               {"static_moment", M_STATIC, "N m/m"},
               {"wall_x", 3.0, "m"},
               {"wall_toe_z", 0.0, "m"},
               {"wall_crest_z", 0.4, "m"},
               {"still_water_z", DEPTH, "m"}};
  for (size_t i = 0; i < sizeof attrs / sizeof attrs[0]; i++)
    STORE(wl_store_attr_double(h5, b, attrs[i].name, attrs[i].v, attrs[i].unit, err));
  /* the loads assess stores with the series, in closed form: the crest at
   * the sample t0, impulses A s sqrt(pi) (the whole Gaussian, its positive
   * phase within +-8 s of t0), 10 % rise s sqrt(ln 10) and twice that
   * above 10 %; NaN where the record ends before the pulse (as assess
   * stores loads it could not measure) */
  const int whole = p->t0 + 8 * p->s <= p->t_end;
  const double I = p->A * p->s * sqrt(PI), rise = p->s * sqrt(log(10.0));
  const struct {
    const char *name;
    double v;
    const char *unit;
  } loads[] = {{"peak_force", F_STATIC + p->A, "N/m"},
               {"peak_force_time", p->t0, "s"},
               {"rise_time", rise, "s"},
               {"duration", 2 * rise, "s"},
               {"peak_force_boundary", F_STATIC + p->boundary * p->A, "N/m"},
               {"peak_force_boundary_time", p->t0, "s"},
               {"peak_moment", M_STATIC + LEVER * p->A, "N m/m"},
               {"peak_moment_time", p->t0, "s"},
               {"impulse", I, "N s/m"},
               {"impulse_boundary", p->boundary * I, "N s/m"},
               {"impulse_positive_phase", I, "N s/m"},
               {"impulse_positive_phase_from", p->t0 - 8 * p->s, "s"},
               {"impulse_positive_phase_to", p->t0 + 8 * p->s, "s"},
               {"impulse_positive", I, "N s/m"},
               {"impulse_positive_boundary", p->boundary * I, "N s/m"},
               {"max_runup", p->runup, "m"},
               {"max_runup_time", p->t0, "s"}};
  for (size_t i = 0; i < sizeof loads / sizeof loads[0]; i++)
    STORE(wl_store_attr_double(h5, b, loads[i].name, whole ? loads[i].v : NAN, loads[i].unit,
                               err));
  STORE(wl_store_attr_text(h5, b, "status", p->status, err));
  if (p->stopped)
    STORE(wl_store_attr_text(h5, b, "stopped", p->stopped, err));
  for (int i = 0; i < 16; i++)
    free(v[i]);
  free(pr);
  return st;
}

/* results.h5 in dir with the given cases (NULL: absent). */
static enum wl_status write_results(const char *dir, const char *scenario, const struct pulse *sol,
                                    const struct pulse *exp_case, struct wl_error *err) {
  char path[512];
  snprintf(path, sizeof path, "%s/results.h5", dir);
  struct wl_store *h5;
  enum wl_status st = wl_store_open(path, &h5, err);
  if (st)
    return st;
  /* the run's keys and, for a scenario this version reads, what assess
   * plans from it (/settings, /plan), as wallload assess stores them */
  struct wl_results *run = malloc(sizeof *run);
  struct wl_scenario sc;
  wl_scenario_init(&sc);
  struct wl_plan plan;
  struct wl_error e1;
  wl_error_clear(&e1);
  if (run && wl_scenario_parse("synthetic.yaml", scenario, strlen(scenario), &sc, &e1) == WL_OK &&
      wl_plan_make(&sc, &plan, &e1) == WL_OK)
    wl_assess_results_plan(&sc, &plan, run);
  else if (run)
    wl_store_results_init(run);
  if (run) {
    snprintf(run->scenario_name, sizeof run->scenario_name, "synthetic-wall");
    snprintf(run->scenario_file, sizeof run->scenario_file, "synthetic.yaml");
    run->scenario_text = (char *)scenario;
    snprintf(run->version, sizeof run->version, "0.1.0");
    snprintf(run->created, sizeof run->created, "2025-01-01T00:00:00Z");
    snprintf(run->backend, sizeof run->backend, "cpu");
    run->threads = 4, run->dp = 0.02;
    STORE(wl_store_results_write_run(h5, run, err));
  } else {
    st = wl_error_set(err, WL_ENOMEM, "test: no memory");
  }
  free(run);
  wl_scenario_clear(&sc);
  if (sol)
    STORE(write_case(h5, "solitary", sol, err));
  if (exp_case)
    STORE(write_case(h5, "explosion", exp_case, err));
  struct wl_error e2;
  wl_error_clear(&e2);
  enum wl_status st2 = wl_store_close(h5, st == WL_OK, &e2);
  return st ? st : st2;
}

/* particles_solitary.h5: two snapshots of a block of water against the wall. */
static enum wl_status write_particles(const char *dir, struct wl_error *err) {
  char path[512];
  snprintf(path, sizeof path, "%s/particles_solitary.h5", dir);
  enum { NX = 50, NZ = 10, NB = 80 };
  size_t n = NX * NZ + NB;
  double *pos = malloc(3 * n * sizeof *pos);
  float *vel = malloc(3 * n * sizeof *vel), *rho = malloc(n * sizeof *rho),
        *p = malloc(n * sizeof *p);
  int *kind = malloc(n * sizeof *kind);
  struct wl_store *h5 = NULL;
  enum wl_status st = pos && vel && rho && p && kind ? WL_OK : wl_error_set(err, WL_ENOMEM, "test");
  STORE(wl_store_open(path, &h5, err));
  for (int s = 0; !st && s < 2; s++) {
    size_t i = 0;
    for (int a = 0; a < NX; a++)
      for (int c = 0; c < NZ; c++, i++) {
        pos[3 * i] = 2.01 + 0.02 * a, pos[3 * i + 1] = 0, pos[3 * i + 2] = 0.01 + 0.02 * c;
        vel[3 * i] = (float)(0.1 * s + 0.01 * a), vel[3 * i + 1] = 0, vel[3 * i + 2] = 0;
        p[i] = (float)(RHO * G * (DEPTH - pos[3 * i + 2]));
        rho[i] = 1000.0f, kind[i] = 0;
      }
    for (int b = 0; b < NB; b++, i++) {
      int wall = b >= NX;
      pos[3 * i] = wall ? 3.01 : 2.01 + 0.02 * b, pos[3 * i + 1] = 0;
      pos[3 * i + 2] = wall ? 0.01 + 0.02 * (b - NX) : -0.01;
      vel[3 * i] = vel[3 * i + 1] = vel[3 * i + 2] = 0;
      p[i] = 0, rho[i] = 1000.0f, kind[i] = 1;
    }
    char g[64], q[128];
    snprintf(g, sizeof g, "snapshots/%04d", s);
    snprintf(q, sizeof q, "%s/position", g);
    STORE(wl_store_write_matrix(h5, q, pos, n, 3, "m", "position", err));
    snprintf(q, sizeof q, "%s/velocity", g);
    STORE(wl_store_write_matrix_f(h5, q, vel, n, 3, "m/s", "velocity", err));
    snprintf(q, sizeof q, "%s/rho", g);
    STORE(wl_store_write_vector_f(h5, q, rho, n, "kg/m^3", "density", err));
    snprintf(q, sizeof q, "%s/p", g);
    STORE(wl_store_write_vector_f(h5, q, p, n, "Pa", "pressure", err));
    snprintf(q, sizeof q, "%s/kind", g);
    STORE(wl_store_write_vector_i(h5, q, kind, n, "kind", err));
    STORE(wl_store_attr_double(h5, g, "time", s == 0 ? 0.9 : 1.0, "s", err));
  }
  struct wl_error e2;
  wl_error_clear(&e2);
  enum wl_status st2 = h5 ? wl_store_close(h5, st == WL_OK, &e2) : WL_OK;
  free(pos), free(vel), free(rho), free(p), free(kind);
  return st ? st : st2;
}

/* The solitary pulse: A = 1234.5 N/m at t0 = 1 s, s = 0.05 s, 2 s record.
 *   peak force  F0 + A = 196.2 + 1234.5 = 1430.7 N/m        -> 1.43 kN/m
 *   at          1.00 s
 *   impulse     A s sqrt(pi) (erf(20) + erf(20))/2 = 109.405 N s/m -> 0.109 kN s/m
 *   positive-phase impulse and positive impulse: the same (the pulse is
 *               positive throughout)
 *   moment      M0 + 0.1 A = 13.08 + 123.45 = 136.53 N m/m  -> 0.137 kN m/m
 *   run-up      0.0789 m
 *   rise time   s sqrt(ln 10) = 0.075871 s                   -> 0.0759 s
 *   duration    2 s sqrt(ln 10) = 0.151743 s                 -> 0.152 s
 *   boundary    F0 + 0.95 A = 1368.975 N/m -> 1.37; difference -61.725 N/m -> -0.0617,
 *               -61.725/1430.7 = -4.31 %                      -> -4.3
 * The explosion pulse (unstable, record to 0.6 s): A = 2345.6 N/m at 0.3 s,
 * s = 0.01 s:
 *   peak force  196.2 + 2345.6 = 2541.8 N/m -> 2.54 kN/m, at 0.300 s
 *   impulse     2345.6 * 0.01 * sqrt(pi) = 41.5746 N s/m -> 0.0416 kN s/m
 *   positive-phase impulse and positive impulse: the same
 *   moment      13.08 + 234.56 = 247.64 N m/m -> 0.248 kN m/m
 *   run-up      0.0456 m; rise 0.0151743 s -> 0.0152; duration 0.0303486 s -> 0.0303 */
static const struct pulse SOL = {1234.5, 1.0, 0.05, 2.0, 0.0789, 0.95, "complete", NULL};
static const struct pulse EXP = {
    2345.6, 0.3, 0.01, 0.6, 0.0456, 1.02, "unstable", "particle 77 left the domain at x = 3.2 m"};

static char *pdf_text(const char *pdf) {
  char cmd[700];
  snprintf(cmd, sizeof cmd, "pdftotext -layout '%s' -", pdf);
  char *text = run_capture(cmd);
  squeeze(text);
  return text;
}

static int pdf_pages(const char *pdf) {
  char cmd[700];
  snprintf(cmd, sizeof cmd, "pdfinfo '%s'", pdf);
  char *info = run_capture(cmd);
  const char *p = info ? strstr(info, "Pages:") : NULL;
  int n = p ? atoi(p + 6) : -1;
  free(info);
  return n;
}

static void check_pages(const char *pdf, const char *what, int min_pages) {
  if (!have_tool("pdfinfo") || !have_tool("pdftoppm")) {
    printf("SKIP poppler not installed: %s pages not checked\n", what);
    return;
  }
  int n = pdf_pages(pdf);
  printf("%s %s: pdfinfo counts %d pages (want >= %d) [poppler pdfinfo]\n",
         n >= min_pages ? "PASS" : "FAIL", what, n, min_pages);
  if (n < min_pages)
    wl_test_failures++;
  char *text = pdf_text(pdf);
  char last[32];
  snprintf(last, sizeof last, "page %d", n);
  CHECK_TRUE(contains(text, last), "the last footer's page number is pdfinfo's page count");
  free(text);
  int blank = 0;
  for (int pg = 1; pg <= n; pg++) {
    long ink = page_ink(pdf, pg);
    if (ink < INK_MIN) {
      printf("FAIL %s page %d: %ld ink pixels in the content box (want >= %d) [poppler pdftoppm]\n",
             what, pg, ink, INK_MIN);
      blank++;
    }
  }
  printf("%s %s: no blank page among %d [poppler pdftoppm, >= %d ink pixels at 30 dpi]\n",
         blank ? "FAIL" : "PASS", what, n, INK_MIN);
  if (blank)
    wl_test_failures++;
}

static void test_full_report(void) {
  char dir[400], pdf[500];
  snprintf(dir, sizeof dir, "%s/full", tmpdir);
  mkdir(dir, 0755);
  struct wl_error err;
  wl_error_clear(&err);
  enum wl_status st = write_results(dir, SCENARIO, &SOL, &EXP, &err);
  if (!st)
    st = write_particles(dir, &err);
  CHECK_TRUE(st == WL_OK, "synthetic results.h5 and particles written (store module)");
  if (st) {
    printf("  %s\n", err.msg);
    return;
  }
  /* the report module's reading of it, before any drawing */
  char res_path[500];
  snprintf(res_path, sizeof res_path, "%s/results.h5", dir);
  struct wl_results *r = malloc(sizeof *r);
  if (r && wl_store_results_read(res_path, r, &err) == WL_OK) {
    const struct wl_results_case *s = &r->cases[WL_RESULTS_CASE_SOLITARY],
                                *x = &r->cases[WL_RESULTS_CASE_EXPLOSION];
    CHECK_REL(s->force_peak.value, F_STATIC + SOL.A, 1e-12, "peak force = F0 + A (analytic pulse)");
    CHECK_ABS(s->force_peak.time, SOL.t0, 1e-12, "peak force at t0");
    CHECK_REL(s->impulse_total, SOL.A * SOL.s * sqrt(PI), 1e-9, "impulse = A s sqrt(pi)");
    /* the pulse is positive wherever it is not below rounding: its positive
     * phase is the whole pulse, and so is its impulse */
    CHECK_REL(s->impulse_peak, SOL.A * SOL.s * sqrt(PI), 1e-9,
              "positive-phase impulse = A s sqrt(pi) (the whole Gaussian)");
    CHECK_TRUE(s->impulse_peak_from < SOL.t0 - 5 * SOL.s && s->impulse_peak_to > SOL.t0 + 5 * SOL.s,
               "the positive phase spans the pulse");
    CHECK_REL(s->impulse_positive, SOL.A * SOL.s * sqrt(PI), 1e-6,
              "positive impulse = A s sqrt(pi) (the pulse lies wholly above the force at rest)");
    CHECK_REL(s->moment_peak.value, M_STATIC + LEVER * SOL.A, 1e-12, "peak moment = M0 + A lever");
    CHECK_REL(s->force_peak.rise_time, SOL.s * sqrt(log(10.0)), 1e-4,
              "rise time s sqrt(ln 10) (10 % of the Gaussian)");
    CHECK_REL(s->force_peak.duration, 2 * SOL.s * sqrt(log(10.0)), 1e-4,
              "duration 2 s sqrt(ln 10)");
    CHECK_REL(s->runup, SOL.runup, 1e-12, "run-up = max of the wall gauge");
    CHECK_REL(s->force_b_peak.value, F_STATIC + 0.95 * SOL.A, 1e-12, "boundary peak F0 + 0.95 A");
    CHECK_REL(x->force_peak.value, F_STATIC + EXP.A, 1e-12, "explosion peak force");
    CHECK_TRUE(!strcmp(x->status, "unstable") && strstr(x->stopped, "left the domain"),
               "explosion status and stop reason read back");
    CHECK_TRUE(r->plan.present && r->plan.solitary.present && r->plan.explosion.present &&
                   r->plan.solitary.n_surface > 0 && r->plan.explosion.n_surface > 0,
               "the plan assess stores (initial conditions, initial surfaces) read back");
    CHECK_TRUE(s->n_gauges == 2 && !strcmp(s->gauges[0].name, "G1") && s->wall_gauge == 1,
               "gauges read, ordered by x, the wall face last");
    CHECK_TRUE(!strcmp(r->scenario_text, SCENARIO), "scenario text read back byte for byte");
    wl_store_results_clear(r);
  } else {
    printf("FAIL results load: %s\n", err.msg);
    wl_test_failures++;
  }
  free(r);

  /* render with the scenario's template (none on disk here: the built-in design) */
  snprintf(pdf, sizeof pdf, "%s/report.pdf", dir);
  wl_error_clear(&err);
  st = wl_report_render(res_path, NULL, pdf, &err);
  printf("%s wl_report_render: %s [render]\n", st == WL_OK ? "PASS" : "FAIL",
         st == WL_OK ? "ok" : err.msg);
  if (st) {
    wl_test_failures++;
    return;
  }
  char part[600];
  snprintf(part, sizeof part, "%s.part", pdf);
  CHECK_TRUE(file_exists(pdf) && !file_exists(part), "PDF in place, no .part left");
  if (!have_tool("pdftotext")) {
    printf("SKIP pdftotext not installed: text not checked\n");
    return;
  }
  char *text = pdf_text(pdf);
  char digest[65];
  wl_report_sha256_hex(SCENARIO, strlen(SCENARIO), digest);
  check_text(text, "synthetic-wall", "scenario name");
  check_text(text, digest, "SHA-256 of the scenario text (checked above against NIST vectors)");
  /* peaks table rows as hand-computed above, 3 significant digits */
  check_text(text, "solitary 1.43 1.00 0.109 0.109 0.109 0.137 0.0789 0.0759 0.152",
             "peaks table, solitary row: analytic pulse");
  check_text(text, "explosion 2.54 0.300 0.0416 0.0416 0.0416 0.248 0.0456 0.0152 0.0303",
             "peaks table, explosion row: analytic pulse");
  check_text(text, "governs explosion solitary solitary solitary explosion solitary",
             "governs row: larger force, positive, positive-phase and net impulse, moment, "
             "run-up");
  check_text(text, "filtered series", "peaks say they come from the filtered series");
  check_text(text, "1.43 1.37 -4.3",
             "probe vs boundary: 1430.7 N/m, 1368.975 N/m (-61.725 N/m), -4.3 % of the probe's");
  check_text(text, "the explosion case has the larger peak force, 2.54 kN/m",
             "summary: force governed by the explosion");
  check_text(text, "the solitary case the larger positive impulse, 0.109 kN s/m",
             "summary: impulse governed by the solitary wave");
  check_text(text, "-4.3 % from the probe value", "summary: error indicator");
  check_text(text, "The explosion case did not complete (unstable",
             "summary: the unstable case is flagged");
  check_text(text, "particle 77 left the domain", "stop reason printed");
  check_text(text, "No particle snapshots of the explosion case", "missing snapshot file said");
  check_text(text, "solitary, t = 1.000 s (nearest the peak force)",
             "snapshot nearest the peak force (t0 = 1 s)");
  check_text(text, "Van Dorn R0 = 9.6 W^0.3; seed 001 eq 4", "initial conditions with sources");
  check_text(text, "No convergence ladder was run", "convergence: says no ladder, no plot");
  check_text(text, "resolution: { convergence: [1, 0.71, 0.5] }", "convergence: how to ask");
  check_text(text, "goda-takahashi", "design formulae evaluated");
  check_text(text, "Goda (2000)", "design citations printed");
  check_text(text, "scenario: synthetic-wall", "scenario text listed");
  check_text(text, "G1 at x = 2 m", "gauge plot");
  check_text(text, "Pressure on the wall face at the peak force", "pressure distribution");
  check_text(text, "design (built in;", "template source: built in");
  free(text);
  check_pages(pdf, "full report", 8);

  /* the shipped template file gives the same sections */
  char pdf2[500];
  snprintf(pdf2, sizeof pdf2, "%s/report-file-template.pdf", dir);
  wl_error_clear(&err);
  st = wl_report_render(res_path, WL_SOURCE_DIR "/report_templates/design.yaml", pdf2, &err);
  CHECK_TRUE(st == WL_OK, "renders with report_templates/design.yaml named explicitly");
  if (!st && have_tool("pdfinfo"))
    CHECK_TRUE(pdf_pages(pdf2) == pdf_pages(pdf), "same page count as the built-in template");

  /* every section option the template offers */
  char tpl[500], pdf3[500];
  snprintf(tpl, sizeof tpl, "%s/options.yaml", dir);
  FILE *f = fopen(tpl, "w");
  if (f) {
    fputs("title: Options\n"
          "company: Test Engineering Ltd\n"
          "sections:\n"
          "  - { type: scene, exaggeration: 5, x_range: [1 m, 3.5 m] }\n"
          "  - { type: snapshots, times: [930 ms], field: velocity }\n"
          "  - { type: gauges, gauges: [G1, nope] }\n"
          "  - { type: loads, quantities: [pressure, runup] }\n"
          "  - { type: peaks, digits: 4 }\n"
          "  - { type: design_formulae, formulae: [hydrostatic] }\n"
          "  - { type: metadata, scenario_text: false }\n",
          f);
    fclose(f);
  }
  snprintf(pdf3, sizeof pdf3, "%s/options.pdf", dir);
  wl_error_clear(&err);
  st = wl_report_render(res_path, tpl, pdf3, &err);
  printf("%s template with every option: %s [render]\n", st == WL_OK ? "PASS" : "FAIL",
         st == WL_OK ? "ok" : err.msg);
  if (st) {
    wl_test_failures++;
    return;
  }
  text = pdf_text(pdf3);
  check_text(text, "vertical exaggeration", "scene: exaggeration 5 printed");
  check_text(text, "0.930 s (nearest 0.900 s)", "snapshots: the requested 0.93 s -> nearest 0.9 s");
  check_text(text, "speed [m/s]", "snapshots: field velocity colours by speed");
  check_text(text, "not in the results: nope", "gauges: an unknown name is said");
  check_text(text, "Probe pressures, solitary case", "loads: pressure histories");
  check_text(text, "Water level at the wall face", "loads: run-up history");
  check_no_text(text, "Impulse on the wall", "loads: impulse not asked for");
  check_text(text, "solitary 1.431 1.000 0.1094 0.1094 0.1094 0.1365",
             "peaks with 4 digits: 1430.7, 109.405 (positive, positive phase, net), 136.53");
  check_no_text(text, "goda-takahashi", "design: only the hydrostatic rows");
  check_no_text(text, "Scenario file as run", "metadata: scenario_text false");
  check_text(text, "Test Engineering Ltd", "company in the footer");
  free(text);
}

static void test_one_case(void) {
  char dir[400], pdf[500], res[500];
  snprintf(dir, sizeof dir, "%s/one", tmpdir);
  mkdir(dir, 0755);
  struct wl_error err;
  wl_error_clear(&err);
  /* only the solitary case, and a scenario this version cannot re-read */
  enum wl_status st = write_results(dir, "scenario: x\nunknown_key: 1\n", &SOL, NULL, &err);
  CHECK_TRUE(st == WL_OK, "results with one case written");
  snprintf(res, sizeof res, "%s/results.h5", dir);
  snprintf(pdf, sizeof pdf, "%s/one.pdf", dir);
  wl_error_clear(&err);
  st = wl_report_render(res, NULL, pdf, &err);
  printf("%s one case, unreadable scenario: %s [graceful]\n", st == WL_OK ? "PASS" : "FAIL",
         st == WL_OK ? "rendered" : err.msg);
  if (st) {
    wl_test_failures++;
    return;
  }
  if (!have_tool("pdftotext"))
    return;
  char *text = pdf_text(pdf);
  check_text(text, "Only the solitary case is in the results", "summary: one case");
  check_text(text, "explosion not run", "peaks: the absent case's row");
  check_text(text, "No explosion case is in the results", "plots: captions say so");
  check_text(text, "hold no /plan", "scene: results without a plan said");
  check_text(text, "1.43", "peak force still printed");
  check_no_text(text, "governs explosion", "no comparison row with one case");
  free(text);
  check_pages(pdf, "one-case report", 5);
}

static void test_short_record(void) {
  char dir[400], pdf[500], res[500];
  snprintf(dir, sizeof dir, "%s/short", tmpdir);
  mkdir(dir, 0755);
  struct wl_error err;
  wl_error_clear(&err);
  /* an unstable case that stopped after 3 samples, before any load */
  struct pulse tiny = {500.0, 5.0, 0.05, 2 * DT, 0.0, 1.0, "unstable", "stopped at once"};
  enum wl_status st = write_results(dir, SCENARIO, NULL, &tiny, &err);
  snprintf(res, sizeof res, "%s/results.h5", dir);
  snprintf(pdf, sizeof pdf, "%s/short.pdf", dir);
  if (!st)
    st = wl_report_render(res, NULL, pdf, &err);
  printf("%s three-sample unstable case: %s [graceful]\n", st == WL_OK ? "PASS" : "FAIL",
         st == WL_OK ? "rendered" : err.msg);
  if (st)
    wl_test_failures++;
  if (!st && have_tool("pdftotext")) {
    char *text = pdf_text(pdf);
    check_text(text, "stopped at once", "stop reason of the short case");
    check_text(text, "did not complete", "the short case is flagged");
    free(text);
  }
}

static void test_errors(void) {
  struct wl_error err;
  char pdf[500], path[500];
  snprintf(pdf, sizeof pdf, "%s/err.pdf", tmpdir);
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_render(NULL, NULL, pdf, &err) == WL_EUSAGE, "no results path: WL_EUSAGE");
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_render("/nonexistent/results.h5", NULL, pdf, &err) == WL_EINPUT &&
                 contains(err.msg, "/nonexistent/results.h5"),
             "missing results: bad input naming the file");
  snprintf(path, sizeof path, "%s/not.h5", tmpdir);
  FILE *f = fopen(path, "w");
  if (f)
    fputs("this is not HDF5\n", f), fclose(f);
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_render(path, NULL, pdf, &err) == WL_EINPUT && contains(err.msg, "not HDF5"),
             "a text file: WL_EINPUT 'not HDF5'");
  /* an HDF5 file that is not wallload's */
  snprintf(path, sizeof path, "%s/other.h5", tmpdir);
  struct wl_store *h5;
  if (wl_store_open(path, &h5, &err) == WL_OK) {
    double v = 1;
    wl_store_write_vector(h5, "something", &v, 1, "1", "x", &err);
    wl_store_close(h5, 1, &err);
  }
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_render(path, NULL, pdf, &err) == WL_EINPUT &&
                 contains(err.msg, "no scenario_name"),
             "foreign HDF5: WL_EINPUT");
  /* a case without its required status (store's schema): bad input naming file and key */
  snprintf(path, sizeof path, "%s/nostatus.h5", tmpdir);
  if (wl_store_open(path, &h5, &err) == WL_OK) {
    double v = 1;
    wl_store_attr_text(h5, "/", "scenario_name", "x", &err);
    wl_store_write_vector(h5, "cases/solitary/time", &v, 1, "s", "x", &err);
    wl_store_close(h5, 1, &err);
  }
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_render(path, NULL, pdf, &err) == WL_EINPUT && contains(err.msg, path) &&
                 contains(err.msg, "/cases/solitary") && contains(err.msg, "'status'"),
             "a case without 'status': WL_EINPUT naming the file, the group and the key");
  /* a case without the loads assess stores (a file of an earlier wallload):
   * bad input naming the file and the key, saying to run assess again */
  snprintf(path, sizeof path, "%s/noloads.h5", tmpdir);
  if (wl_store_open(path, &h5, &err) == WL_OK) {
    double v = 1;
    wl_store_attr_text(h5, "/", "scenario_name", "x", &err);
    wl_store_write_vector(h5, "cases/solitary/time", &v, 1, "s", "x", &err);
    wl_store_attr_text(h5, "cases/solitary", "status", "complete", &err);
    wl_store_close(h5, 1, &err);
  }
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_render(path, NULL, pdf, &err) == WL_EINPUT && contains(err.msg, path) &&
                 contains(err.msg, "/cases/solitary") && contains(err.msg, "'peak_force'") &&
                 contains(err.msg, "run `wallload assess`"),
             "a case without its stored loads: WL_EINPUT naming the file and the key, and "
             "the remedy");
  CHECK_TRUE(!file_exists(pdf), "no PDF left after failures");
  /* a template with an unknown section type */
  char tpl[500], res[500];
  snprintf(tpl, sizeof tpl, "%s/bad.yaml", tmpdir);
  f = fopen(tpl, "w");
  if (f)
    fputs("sections:\n  - { type: title }\n  - { type: wibble }\n", f), fclose(f);
  snprintf(res, sizeof res, "%s/full/results.h5", tmpdir);
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_render(res, tpl, pdf, &err) == WL_EINPUT &&
                 contains(err.msg, "bad.yaml:3:") && contains(err.msg, "wibble"),
             "bad template: WL_EINPUT with its line");
  CHECK_TRUE(!file_exists(pdf), "no PDF after a bad template");
  wl_error_clear(&err);
  CHECK_TRUE(wl_report_render(res, NULL, "/nonexistent/dir/x.pdf", &err) == WL_EINPUT,
             "PDF in a missing directory: bad input");
}

static void test_builtin_template(void) {
  FILE *f = fopen(WL_SOURCE_DIR "/report_templates/design.yaml", "rb");
  char buf[16384];
  size_t n = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
  if (f)
    fclose(f);
  buf[n] = '\0';
  CHECK_TRUE(n > 0 && !strcmp(buf, wl_report_builtin_design),
             "built-in template = report_templates/design.yaml byte for byte");
}

int main(void) {
  snprintf(tmpdir, sizeof tmpdir, "%s/wl_render_XXXXXX",
           getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (!mkdtemp(tmpdir)) {
    printf("FAIL cannot create a temporary directory\n");
    return 1;
  }
  /* the built-in template must be what a missing file falls back to */
  unsetenv("WALLLOAD_TEMPLATE_DIR");
  if (chdir(tmpdir) != 0)
    printf("note: could not enter %s\n", tmpdir);
  test_sha256();
  test_leading_wave();
  test_builtin_template();
  test_full_report();
  test_one_case();
  test_short_record();
  test_errors();
  if (wl_test_failures == 0 && !getenv("WL_KEEP_TEST_FILES")) {
    char cmd[400];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    if (system(cmd) != 0)
      printf("note: could not remove %s\n", tmpdir);
  } else {
    printf("files kept in %s\n", tmpdir);
  }
  printf("%d failure(s)\n", wl_test_failures);
  return TEST_RESULT();
}
