/* results.c: the report's reading of an assessment: results.h5 and the
 * particle snapshots beside it (HDF5, read only), the stored scenario
 * re-parsed and re-planned, peaks recomputed with loads.h, and the SHA-256
 * input digest (FIPS 180-4, "Secure Hash Standard", NIST 2015, sections
 * 4.1.2, 4.2.2, 5.1.1, 6.2). */
#define _POSIX_C_SOURCE 200809L /* strdup */

#include "results.h"

#include <errno.h>
#include <hdf5.h>
#include <stdio.h>
#include <sys/stat.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "wallload/loads.h"
#include "wallload/store.h"

const char *wl_report_case_name(int i) {
  return i == WL_REPORT_CASE_SOLITARY    ? "solitary"
         : i == WL_REPORT_CASE_EXPLOSION ? "explosion"
                                         : "?";
}

/* ---- SHA-256 ------------------------------------------------------------------ */

/* FIPS 180-4 section 4.2.2: the first 32 bits of the fractional parts of the
 * cube roots of the first 64 primes. */
static const uint32_t K256[64] = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

static uint32_t rotr(uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

/* One 64-byte block into the state (section 6.2.2). */
static void sha256_block(uint32_t hs[8], const uint8_t *p) {
  uint32_t w[64];
  for (int i = 0; i < 16; i++)
    w[i] = (uint32_t)p[4 * i] << 24 | (uint32_t)p[4 * i + 1] << 16 | (uint32_t)p[4 * i + 2] << 8 |
           (uint32_t)p[4 * i + 3];
  for (int i = 16; i < 64; i++) {
    uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
    uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
    w[i] = w[i - 16] + s0 + w[i - 7] + s1;
  }
  uint32_t a = hs[0], b = hs[1], c = hs[2], d = hs[3], e = hs[4], f = hs[5], g = hs[6], h = hs[7];
  for (int i = 0; i < 64; i++) {
    uint32_t t1 =
        h + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + K256[i] + w[i];
    uint32_t t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
    h = g, g = f, f = e, e = d + t1, d = c, c = b, b = a, a = t1 + t2;
  }
  hs[0] += a, hs[1] += b, hs[2] += c, hs[3] += d, hs[4] += e, hs[5] += f, hs[6] += g, hs[7] += h;
}

void wl_report_sha256(const void *data, size_t len, uint8_t out[32]) {
  /* section 5.3.3: initial hash value */
  uint32_t hs[8] = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                    0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  const uint8_t *p = data;
  size_t full = len / 64;
  for (size_t i = 0; i < full; i++)
    sha256_block(hs, p + 64 * i);
  /* section 5.1.1: a 1 bit, zeros, the 64-bit message length in bits */
  uint8_t tail[128] = {0};
  size_t rest = len - 64 * full;
  if (rest)
    memcpy(tail, p + 64 * full, rest);
  tail[rest] = 0x80;
  size_t tail_len = rest + 9 <= 64 ? 64 : 128;
  uint64_t bits = (uint64_t)len * 8u;
  for (int i = 0; i < 8; i++)
    tail[tail_len - 1 - i] = (uint8_t)(bits >> (8 * i));
  sha256_block(hs, tail);
  if (tail_len == 128)
    sha256_block(hs, tail + 64);
  for (int i = 0; i < 8; i++) {
    out[4 * i] = (uint8_t)(hs[i] >> 24), out[4 * i + 1] = (uint8_t)(hs[i] >> 16);
    out[4 * i + 2] = (uint8_t)(hs[i] >> 8), out[4 * i + 3] = (uint8_t)hs[i];
  }
}

void wl_report_sha256_hex(const void *data, size_t len, char hex[65]) {
  static const char digits[] = "0123456789abcdef";
  uint8_t md[32];
  wl_report_sha256(data, len, md);
  for (int i = 0; i < 32; i++)
    hex[2 * i] = digits[md[i] >> 4], hex[2 * i + 1] = digits[md[i] & 15];
  hex[64] = '\0';
}

/* ---- HDF5 helpers ----------------------------------------------------------------- */

/* 1 when every component of `path` (relative to loc) exists. */
static int exists(hid_t loc, const char *path) {
  char buf[512], *w = buf;
  size_t len = strlen(path);
  if (len >= sizeof buf)
    return 0;
  memcpy(buf, path, len + 1);
  for (char *s = buf; *s; s++) {
    if (*s != '/')
      continue;
    *s = '\0';
    if (*w && H5Lexists(loc, buf, H5P_DEFAULT) <= 0)
      return 0;
    *s = '/';
  }
  return H5Lexists(loc, buf, H5P_DEFAULT) > 0;
}

/* A string attribute of obj, malloc'ed; NULL when absent or not a string. */
static char *attr_text_alloc(hid_t obj, const char *name) {
  if (H5Aexists(obj, name) <= 0)
    return NULL;
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  if (a < 0)
    return NULL;
  char *out = NULL;
  hid_t ft = H5Aget_type(a);
  if (ft >= 0 && H5Tget_class(ft) == H5T_STRING) {
    hid_t mt = H5Tcopy(H5T_C_S1);
    if (H5Tis_variable_str(ft) > 0) {
      char *p = NULL;
      if (mt >= 0 && H5Tset_size(mt, H5T_VARIABLE) >= 0 && H5Aread(a, mt, &p) >= 0 && p) {
        out = strdup(p);
        H5free_memory(p);
      }
    } else {
      size_t size = H5Tget_size(ft);
      out = malloc(size + 1);
      if (out && (mt < 0 || H5Tset_size(mt, size) < 0 || H5Aread(a, mt, out) < 0)) {
        free(out);
        out = NULL;
      }
      if (out)
        out[size] = '\0';
    }
    if (mt >= 0)
      H5Tclose(mt);
  }
  if (ft >= 0)
    H5Tclose(ft);
  H5Aclose(a);
  return out;
}

static void attr_text(hid_t obj, const char *name, char *buf, size_t size) {
  char *s = attr_text_alloc(obj, name);
  snprintf(buf, size, "%s", s ? s : "");
  free(s);
}

static double attr_double(hid_t obj, const char *name) {
  double v = NAN;
  if (H5Aexists(obj, name) <= 0)
    return NAN;
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  if (a < 0)
    return NAN;
  if (H5Aread(a, H5T_NATIVE_DOUBLE, &v) < 0)
    v = NAN;
  H5Aclose(a);
  return v;
}

/* Read dataset `path` (rank 1 or 2) as mem_type into a malloc'ed array.
 * Returns WL_OK with *data NULL when it does not exist; WL_EINPUT when it
 * is not what wallload writes (a damaged results file: the user's input);
 * WL_EIO when it cannot be read; WL_ENOMEM. */
static enum wl_status read_dataset(hid_t file, const char *file_name, const char *path,
                                   hid_t mem_type, size_t elem, void **data, size_t *rows,
                                   size_t *cols, struct wl_error *err) {
  *data = NULL, *rows = 0, *cols = 1;
  if (!exists(file, path))
    return WL_OK;
  hid_t d = H5Dopen2(file, path, H5P_DEFAULT);
  if (d < 0)
    return wl_error_set(err, WL_EINPUT, "%s: %s: cannot open the dataset (a damaged results file)",
                        file_name, path);
  hid_t sp = H5Dget_space(d);
  hsize_t dims[2] = {0, 1};
  int rank = sp >= 0 ? H5Sget_simple_extent_ndims(sp) : -1;
  enum wl_status st = WL_OK;
  if (rank < 1 || rank > 2 || H5Sget_simple_extent_dims(sp, dims, NULL) < 0) {
    st = wl_error_set(err, WL_EINPUT, "%s: %s: found a dataset of rank %d; expected 1 or 2", file_name,
                      path, rank);
  } else {
    size_t count = (size_t)dims[0] * (size_t)(rank == 2 ? dims[1] : 1);
    void *buf = malloc((count ? count : 1) * elem);
    if (!buf) {
      st = wl_error_set(err, WL_ENOMEM, "%s: %s: no memory for %zu values", file_name, path, count);
    } else if (count && H5Dread(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf) < 0) {
      free(buf);
      st = wl_error_set(err, WL_EIO, "%s: %s: cannot read the dataset", file_name, path);
    } else {
      *data = buf;
      *rows = (size_t)dims[0];
      *cols = rank == 2 ? (size_t)dims[1] : 1;
    }
  }
  if (sp >= 0)
    H5Sclose(sp);
  H5Dclose(d);
  return st;
}

/* A vector of n doubles at `path`; NULL (no error) when absent or of another
 * length, so one damaged series does not hide the rest. */
static enum wl_status read_series(hid_t file, const char *file_name, const char *path, size_t n,
                                  double **out, struct wl_error *err) {
  void *data;
  size_t rows, cols;
  *out = NULL;
  enum wl_status st = read_dataset(file, file_name, path, H5T_NATIVE_DOUBLE, sizeof(double), &data,
                                   &rows, &cols, err);
  if (st)
    return st;
  if (data && (rows != n || cols != 1)) {
    free(data);
    return WL_OK;
  }
  *out = data;
  return WL_OK;
}

/* Names of the links in group `path`, at most max, into names[][size]. */
static int link_names(hid_t file, const char *path, char (*names)[64], int max) {
  if (!exists(file, path))
    return 0;
  hid_t g = H5Gopen2(file, path, H5P_DEFAULT);
  if (g < 0)
    return 0;
  H5G_info_t info;
  int n = 0;
  if (H5Gget_info(g, &info) >= 0)
    for (hsize_t i = 0; i < info.nlinks && n < max; i++)
      if (H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, names[n], 64, H5P_DEFAULT) > 0)
        n++;
  H5Gclose(g);
  return n;
}

/* ---- results.h5 ------------------------------------------------------------------ */

void wl_report_results_init(struct wl_report_results *r) {
  memset(r, 0, sizeof *r);
  wl_scenario_init(&r->scenario);
}

static void case_clear(struct wl_report_case *c) {
  double **arrays[] = {&c->t,       &c->force,     &c->force_f, &c->force_b,  &c->force_bf,
                       &c->impulse, &c->impulse_b, &c->moment,  &c->moment_f, &c->moment_b,
                       &c->kinetic, &c->potential, &c->probe_z, &c->pressure};
  for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) {
    free(*arrays[i]);
    *arrays[i] = NULL;
  }
  for (int g = 0; g < WL_REPORT_MAX_GAUGES; g++)
    free(c->gauges[g].eta);
  memset(c, 0, sizeof *c);
}

void wl_report_results_clear(struct wl_report_results *r) {
  if (!r)
    return;
  for (int i = 0; i < WL_REPORT_N_CASES; i++)
    case_clear(&r->cases[i]);
  free(r->scenario_text);
  if (r->have_scenario)
    wl_scenario_clear(&r->scenario);
  memset(r, 0, sizeof *r);
  wl_scenario_init(&r->scenario);
}

static int by_x(const void *a, const void *b) {
  const struct wl_report_gauge *ga = a, *gb = b;
  double xa = isfinite(ga->x) ? ga->x : INFINITY, xb = isfinite(gb->x) ? gb->x : INFINITY;
  return xa < xb ? -1 : xa > xb ? 1 : strcmp(ga->name, gb->name);
}

/* The peaks of one case from its stored series (loads.h definitions, the
 * same calls as the assessment's, so the numbers are summary.json's). */
static void case_derive(struct wl_report_case *c) {
  static const struct wl_peak none = {NAN, NAN, 0, NAN, NAN};
  c->force_peak = c->force_b_peak = c->moment_peak = none;
  c->impulse_total = c->impulse_b_total = c->runup = c->runup_time = NAN;
  c->impulse_peak = c->impulse_peak_from = c->impulse_peak_to = NAN;
  c->impulse_positive = c->impulse_positive_b = NAN;
  c->wall_gauge = -1;
  for (int g = 0; g < c->n_gauges; g++)
    if (!strcmp(c->gauges[g].name, "wall"))
      c->wall_gauge = g;
  /* the bases assess used: the model's force at rest where it measured it */
  const double fs0 = isfinite(c->static_force) ? c->static_force : 0.0;
  const double fs = isfinite(c->rest_force) ? c->rest_force : fs0;
  const double fbs = isfinite(c->rest_force_b) ? c->rest_force_b : fs0;
  /* from here on the bases themselves (results.h) */
  c->rest_force = fs, c->rest_force_b = fbs;
  size_t n = c->n;
  if (n == 0 || !c->t)
    return;
  const double ms = isfinite(c->rest_moment) ? c->rest_moment
                    : isfinite(c->static_moment) ? c->static_moment : 0.0;
  c->filtered = c->force_f != NULL;
  const double *f = c->force_f ? c->force_f : c->force;
  const double *fb = c->force_bf ? c->force_bf : c->force_b;
  const double *m = c->moment_f ? c->moment_f : c->moment;
  /* from peaks_from on, as the assessment searched them; indices made
   * absolute (sample numbers of the stored series) */
  size_t k0 = 0;
  while (isfinite(c->peaks_from) && k0 + 1 < n && c->t[k0] < c->peaks_from)
    k0++;
  if (f)
    wl_loads_peak(c->t + k0, f + k0, n - k0, fs, &c->force_peak), c->force_peak.index += k0;
  if (fb)
    wl_loads_peak(c->t + k0, fb + k0, n - k0, fbs, &c->force_b_peak), c->force_b_peak.index += k0;
  if (m)
    wl_loads_peak(c->t + k0, m + k0, n - k0, ms, &c->moment_peak), c->moment_peak.index += k0;
  if (c->impulse)
    c->impulse_total = c->impulse[n - 1];
  if (f && c->impulse)
    c->impulse_peak = wl_loads_positive_phase_impulse(c->t, f, c->impulse, n, fs,
                                                      c->force_peak.index, &c->impulse_peak_from,
                                                      &c->impulse_peak_to);
  if (f)
    c->impulse_positive = wl_loads_positive_impulse(c->t + k0, f + k0, n - k0, fs);
  if (fb)
    c->impulse_positive_b = wl_loads_positive_impulse(c->t + k0, fb + k0, n - k0, fbs);
  if (c->impulse_b)
    c->impulse_b_total = c->impulse_b[n - 1];
  if (c->wall_gauge >= 0 && c->gauges[c->wall_gauge].eta) {
    const double *e = c->gauges[c->wall_gauge].eta;
    for (size_t k = 0; k < n; k++)
      if (isfinite(e[k]) && !(e[k] <= c->runup))
        c->runup = e[k], c->runup_time = c->t[k];
  }
}

static enum wl_status read_case(hid_t file, const char *file_name, int index,
                                struct wl_report_case *c, struct wl_error *err) {
  char g[96], p[256];
  snprintf(c->name, sizeof c->name, "%s", wl_report_case_name(index));
  snprintf(g, sizeof g, "cases/%s", c->name);
  if (!exists(file, g))
    return WL_OK;
  c->present = 1;
  hid_t grp = H5Gopen2(file, g, H5P_DEFAULT);
  if (grp < 0)
    return wl_error_set(err, WL_EINPUT, "%s: /%s: cannot open the group (a damaged results file)",
                        file_name, g);
  struct {
    const char *name;
    double *v;
  } attrs[] = {
      {"dp", &c->dp},
      {"smoothing_length", &c->h},
      {"c0", &c->c0},
      {"particles", &c->particles},
      {"fluid_particles", &c->fluid_particles},
      {"steps", &c->steps},
      {"runtime", &c->runtime},
      {"end_time", &c->end_time},
      {"time_reached", &c->time_reached},
      {"filter_cutoff", &c->cutoff},
      {"peaks_from", &c->peaks_from},
      {"static_force", &c->static_force},
      {"static_moment", &c->static_moment},
      {"rest_force", &c->rest_force},
      {"rest_force_boundary", &c->rest_force_b},
      {"rest_moment", &c->rest_moment},
      {"rest_from", &c->rest_from},
      {"rest_to", &c->rest_to},
      {"wall_x", &c->wall_x},
      {"wall_toe_z", &c->wall_toe_z},
      {"wall_crest_z", &c->wall_crest_z},
      {"still_water_z", &c->still_water_z},
  };
  for (size_t i = 0; i < sizeof attrs / sizeof attrs[0]; i++)
    *attrs[i].v = attr_double(grp, attrs[i].name);
  attr_text(grp, "status", c->status, sizeof c->status);
  attr_text(grp, "stopped", c->stopped, sizeof c->stopped);
  attr_text(grp, "caution", c->caution, sizeof c->caution);
  H5Gclose(grp);

  void *data;
  size_t rows, cols;
  snprintf(p, sizeof p, "%s/time", g);
  enum wl_status st =
      read_dataset(file, file_name, p, H5T_NATIVE_DOUBLE, sizeof(double), &data, &rows, &cols, err);
  if (st)
    return st;
  c->t = data;
  c->n = data ? rows : 0;
  struct {
    const char *name;
    double **v;
  } series[] = {
      {"wall/force", &c->force},
      {"wall/force_filtered", &c->force_f},
      {"wall/force_boundary", &c->force_b},
      {"wall/force_boundary_filtered", &c->force_bf},
      {"wall/impulse", &c->impulse},
      {"wall/impulse_boundary", &c->impulse_b},
      {"wall/moment", &c->moment},
      {"wall/moment_filtered", &c->moment_f},
      {"wall/moment_boundary", &c->moment_b},
      {"energy/kinetic", &c->kinetic},
      {"energy/potential", &c->potential},
  };
  for (size_t i = 0; !st && c->n && i < sizeof series / sizeof series[0]; i++) {
    snprintf(p, sizeof p, "%s/%s", g, series[i].name);
    st = read_series(file, file_name, p, c->n, series[i].v, err);
  }
  if (!st) {
    snprintf(p, sizeof p, "%s/wall/probe_z", g);
    st = read_dataset(file, file_name, p, H5T_NATIVE_DOUBLE, sizeof(double), &data, &rows, &cols,
                      err);
    c->probe_z = data;
    c->n_probes = data ? rows : 0;
  }
  if (!st && c->n_probes) {
    snprintf(p, sizeof p, "%s/wall/pressure", g);
    st = read_dataset(file, file_name, p, H5T_NATIVE_DOUBLE, sizeof(double), &data, &rows, &cols,
                      err);
    if (!st && data && rows == c->n && cols == c->n_probes)
      c->pressure = data;
    else
      free(data);
  }
  if (!st) {
    char names[WL_REPORT_MAX_GAUGES][64];
    snprintf(p, sizeof p, "%s/gauges", g);
    int n_names = link_names(file, p, names, WL_REPORT_MAX_GAUGES);
    for (int k = 0; !st && k < n_names; k++) {
      struct wl_report_gauge *ga = &c->gauges[c->n_gauges];
      snprintf(ga->name, sizeof ga->name, "%s", names[k]);
      snprintf(p, sizeof p, "%s/gauges/%s", g, names[k]);
      ga->x = NAN;
      hid_t gg = H5Oopen(file, p, H5P_DEFAULT);
      if (gg >= 0) {
        ga->x = attr_double(gg, "x");
        H5Oclose(gg);
      }
      snprintf(p, sizeof p, "%s/gauges/%s/eta", g, names[k]);
      st = read_series(file, file_name, p, c->n, &ga->eta, err);
      if (!st && ga->eta)
        c->n_gauges++;
    }
    qsort(c->gauges, (size_t)c->n_gauges, sizeof c->gauges[0], by_x);
  }
  if (!st)
    case_derive(c);
  return st;
}

/* /convergence/<case>/ of case index i into *cv (left absent when the group
 * is not there). Returns WL_OK, WL_EIO (a dataset that cannot be read) or
 * WL_ENOMEM. */
static enum wl_status read_convergence(hid_t file, const char *file_name, int i,
                                       struct wl_report_convergence *cv, struct wl_error *err) {
  char g[64], p[160];
  snprintf(g, sizeof g, "convergence/%s", wl_report_case_name(i));
  memset(cv, 0, sizeof *cv);
  if (!exists(file, g))
    return WL_OK;
  hid_t grp = H5Gopen2(file, g, H5P_DEFAULT);
  if (grp < 0)
    return wl_error_set(err, WL_EINPUT, "%s: /%s: cannot open the group (a damaged results file)",
                        file_name, g);
  cv->present = 1;
  struct {
    const char *name;
    double *v;
  } attrs[] = {
      {"levels_planned", &cv->levels_planned},
      {"ratio", &cv->ratio},
      {"peak_force_order", &cv->force_order},
      {"peak_force_order_meaningful", &cv->force_order_ok},
      {"peak_force_extrapolated", &cv->force_extrapolated},
      {"peak_force_error_estimate", &cv->force_error},
      {"impulse_positive_order", &cv->pos_order},
      {"impulse_positive_order_meaningful", &cv->pos_order_ok},
      {"impulse_positive_extrapolated", &cv->pos_extrapolated},
      {"impulse_positive_error_estimate", &cv->pos_error},
      {"error_estimate", &cv->error_estimate},
      {"target", &cv->target},
      {"target_given", &cv->target_given},
      {"target_met", &cv->target_met},
      {"stopped_early", &cv->stopped_early},
  };
  for (size_t k = 0; k < sizeof attrs / sizeof attrs[0]; k++)
    *attrs[k].v = attr_double(grp, attrs[k].name);
  attr_text(grp, "peak_force_basis", cv->force_basis, sizeof cv->force_basis);
  attr_text(grp, "impulse_positive_basis", cv->pos_basis, sizeof cv->pos_basis);
  attr_text(grp, "note", cv->note, sizeof cv->note);
  H5Gclose(grp);
  struct {
    const char *name;
    double *v;
  } series[] = {
      {"factor", cv->factor},
      {"dp", cv->dp},
      {"particles", cv->particles},
      {"steps", cv->steps},
      {"runtime", cv->runtime},
      {"particle_steps_per_second", cv->rate},
      {"peak_force", cv->peak_force},
      {"peak_force_boundary", cv->peak_force_b},
      {"impulse", cv->impulse},
      {"impulse_positive_phase", cv->impulse_phase},
      {"impulse_positive", cv->impulse_pos},
      {"peak_moment", cv->peak_moment},
      {"max_runup", cv->runup},
      {"estimated_error", cv->error},
  };
  enum wl_status st = WL_OK;
  for (int l = 0; l < WL_REPORT_MAX_LEVELS; l++)
    for (size_t k = 0; k < sizeof series / sizeof series[0]; k++)
      series[k].v[l] = NAN;
  for (size_t k = 0; !st && k < sizeof series / sizeof series[0]; k++) {
    void *data;
    size_t rows, cols;
    snprintf(p, sizeof p, "%s/%s", g, series[k].name);
    st = read_dataset(file, file_name, p, H5T_NATIVE_DOUBLE, sizeof(double), &data, &rows, &cols,
                      err);
    if (st || !data)
      continue;
    if (rows > WL_REPORT_MAX_LEVELS)
      rows = WL_REPORT_MAX_LEVELS;
    memcpy(series[k].v, data, rows * sizeof(double));
    if (k == 0 || (int)rows < cv->n_levels)
      cv->n_levels = (int)rows; /* the levels every dataset has */
    free(data);
  }
  if (!st) {
    void *data;
    size_t rows, cols;
    snprintf(p, sizeof p, "%s/status", g);
    st = read_dataset(file, file_name, p, H5T_NATIVE_INT, sizeof(int), &data, &rows, &cols, err);
    for (size_t l = 0; !st && data && l < rows && l < WL_REPORT_MAX_LEVELS; l++)
      cv->status[l] = ((int *)data)[l];
    free(data);
  }
  return st;
}

/* Re-parse and re-plan the stored scenario; a failure is a note. */
static void replan(struct wl_report_results *r) {
  if (!r->scenario_text || !*r->scenario_text) {
    snprintf(r->scenario_note, sizeof r->scenario_note,
             "the results hold no scenario text, so the derived initial conditions and the "
             "bathymetry are not available");
    return;
  }
  struct wl_error e;
  wl_error_clear(&e);
  wl_scenario_init(&r->scenario);
  const char *name = r->scenario_file[0] ? r->scenario_file : "scenario_text";
  if (wl_scenario_parse(name, r->scenario_text, r->scenario_len, &r->scenario, &e) != WL_OK) {
    wl_scenario_clear(&r->scenario);
    snprintf(r->scenario_note, sizeof r->scenario_note,
             "the stored scenario could not be re-read by this wallload: %s", e.msg);
    return;
  }
  r->have_scenario = 1;
  wl_error_clear(&e);
  if (wl_plan_make(&r->scenario, &r->plan, &e) != WL_OK) {
    snprintf(r->scenario_note, sizeof r->scenario_note,
             "the stored scenario could not be re-planned by this wallload: %s", e.msg);
    return;
  }
  r->have_plan = 1;
}

enum wl_status wl_report_results_load(const char *path, struct wl_report_results *r,
                                      struct wl_error *err) {
  wl_report_results_init(r);
  wl_store_hdf5_init(); /* wallload reports its own errors (store.h) */
  if (!path || !*path)
    return wl_error_set(err, WL_EINPUT, "report: no results file given");
  if (strlen(path) >= sizeof r->path)
    return wl_error_set(err, WL_EINPUT, "%s: path longer than %zu bytes", path, sizeof r->path - 1);
  snprintf(r->path, sizeof r->path, "%s", path);
  snprintf(r->dir, sizeof r->dir, "%s", path);
  char *slash = strrchr(r->dir, '/');
  if (slash == r->dir)
    r->dir[1] = '\0';
  else if (slash)
    *slash = '\0';
  else
    snprintf(r->dir, sizeof r->dir, ".");
  struct stat sb;
  if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode))
    return wl_error_set(err, WL_EINPUT,
                        "%s: is a directory; expected the results.h5 that `wallload assess` writes",
                        path);
  FILE *probe = fopen(path, "rb");
  if (!probe) /* a path the user gave: missing or unreadable is their input */
    return wl_error_set(err, WL_EINPUT, "%s: cannot open the results file: %s", path,
                        strerror(errno));
  fclose(probe);
  if (H5Fis_hdf5(path) <= 0)
    return wl_error_set(err, WL_EINPUT,
                        "%s: found a file that is not HDF5; expected the "
                        "results.h5 that `wallload assess` writes",
                        path);
  hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0)
    return wl_error_set(err, WL_EINPUT,
                        "%s: an HDF5 file that cannot be opened (truncated or damaged); expected "
                        "the results.h5 that `wallload assess` writes",
                        path);
  enum wl_status st = WL_OK;
  hid_t root = H5Gopen2(file, "/", H5P_DEFAULT);
  int has_name = root >= 0 && H5Aexists(root, "scenario_name") > 0;
  if (!has_name && !exists(file, "cases")) {
    st = wl_error_set(err, WL_EINPUT,
                      "%s: found no scenario_name attribute and no /cases group; expected the "
                      "results.h5 that `wallload assess` writes",
                      path);
  } else if (root >= 0) {
    attr_text(root, "scenario_name", r->scenario_name, sizeof r->scenario_name);
    attr_text(root, "scenario_file", r->scenario_file, sizeof r->scenario_file);
    attr_text(root, "wallload_version", r->version, sizeof r->version);
    attr_text(root, "created", r->created, sizeof r->created);
    attr_text(root, "backend", r->backend, sizeof r->backend);
    r->scenario_text = attr_text_alloc(root, "scenario_text");
    if (!r->scenario_text)
      r->scenario_text = strdup("");
    if (!r->scenario_text)
      st = wl_error_set(err, WL_ENOMEM, "%s: no memory", path);
    r->threads = attr_double(root, "threads");
    r->dp = attr_double(root, "dp");
  }
  if (root >= 0)
    H5Gclose(root);
  if (!st) {
    r->scenario_len = strlen(r->scenario_text);
    wl_report_sha256_hex(r->scenario_text, r->scenario_len, r->digest);
    r->has_convergence = exists(file, "convergence");
  }
  for (int i = 0; !st && i < WL_REPORT_N_CASES; i++) {
    st = read_case(file, path, i, &r->cases[i], err);
    if (r->cases[i].present)
      r->n_cases++;
  }
  for (int i = 0; !st && r->has_convergence && i < WL_REPORT_N_CASES; i++)
    st = read_convergence(file, path, i, &r->conv[i], err);
  H5Fclose(file);
  if (st) {
    wl_report_results_clear(r);
    return st;
  }
  replan(r);
  return WL_OK;
}

/* ---- particle snapshots ---------------------------------------------------------- */

static int by_time(const void *a, const void *b) {
  const struct wl_report_snapshot_ref *ra = a, *rb = b;
  return ra->time < rb->time ? -1 : ra->time > rb->time ? 1 : strcmp(ra->group, rb->group);
}

enum wl_status wl_report_snapshot_list(const char *path, struct wl_report_snapshot_ref **refs,
                                       size_t *n, struct wl_error *err) {
  *refs = NULL, *n = 0;
  wl_store_hdf5_init();
  FILE *probe = fopen(path, "rb");
  if (!probe) /* named by the results file: a results set missing a file */
    return wl_error_set(err, WL_EINPUT, "%s: cannot open the particle snapshots: %s", path,
                        strerror(errno));
  fclose(probe);
  hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0)
    return wl_error_set(err, WL_EINPUT,
                        "%s: cannot open the particle snapshots (HDF5: truncated or damaged)", path);
  enum wl_status st = WL_OK;
  hid_t g = exists(file, "snapshots") ? H5Gopen2(file, "snapshots", H5P_DEFAULT) : -1;
  H5G_info_t info;
  if (g >= 0 && H5Gget_info(g, &info) >= 0 && info.nlinks > 0) {
    struct wl_report_snapshot_ref *out = malloc((size_t)info.nlinks * sizeof *out);
    if (!out)
      st = wl_error_set(err, WL_ENOMEM, "%s: no memory for the snapshot list", path);
    size_t k = 0;
    for (hsize_t i = 0; out && i < info.nlinks; i++) {
      char name[32];
      if (H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name,
                             H5P_DEFAULT) <= 0)
        continue;
      hid_t s = H5Gopen2(g, name, H5P_DEFAULT);
      if (s < 0)
        continue;
      double t = attr_double(s, "time");
      H5Gclose(s);
      if (!isfinite(t))
        continue;
      snprintf(out[k].group, sizeof out[k].group, "snapshots/%s", name);
      out[k++].time = t;
    }
    if (out) {
      qsort(out, k, sizeof *out, by_time);
      *refs = out, *n = k;
    }
  }
  if (g >= 0)
    H5Gclose(g);
  H5Fclose(file);
  return st;
}

enum wl_status wl_report_snapshot_read(const char *path, const char *group,
                                       enum wl_report_quantity q, double **x, double **z,
                                       double **value, int **kind, size_t *n,
                                       struct wl_error *err) {
  *x = *z = *value = NULL, *kind = NULL, *n = 0;
  wl_store_hdf5_init();
  hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0)
    return wl_error_set(err, WL_EINPUT,
                        "%s: cannot open the particle snapshots (HDF5: missing, truncated or damaged)",
                        path);
  char p[160];
  void *pos = NULL, *vq = NULL, *kd = NULL;
  size_t rows = 0, cols = 0, rq = 0, cq = 0, rk = 0, ck = 0;
  snprintf(p, sizeof p, "%s/position", group);
  enum wl_status st =
      read_dataset(file, path, p, H5T_NATIVE_DOUBLE, sizeof(double), &pos, &rows, &cols, err);
  const char *qname = q == WL_REPORT_Q_PRESSURE ? "p" : q == WL_REPORT_Q_SPEED ? "velocity" : "rho";
  if (!st) {
    snprintf(p, sizeof p, "%s/%s", group, qname);
    st = read_dataset(file, path, p, H5T_NATIVE_DOUBLE, sizeof(double), &vq, &rq, &cq, err);
  }
  if (!st) {
    snprintf(p, sizeof p, "%s/kind", group);
    st = read_dataset(file, path, p, H5T_NATIVE_INT, sizeof(int), &kd, &rk, &ck, err);
  }
  H5Fclose(file);
  if (!st && (!pos || cols < 2 || !vq || rq != rows || !kd || rk != rows))
    st = wl_error_set(err, WL_EINPUT,
                      "%s: %s: found incomplete particle data; expected position (n x 3), %s and "
                      "kind of equal length",
                      path, group, qname);
  double *ox = NULL, *oz = NULL, *ov = NULL;
  if (!st) {
    ox = malloc((rows ? rows : 1) * sizeof *ox);
    oz = malloc((rows ? rows : 1) * sizeof *oz);
    ov = malloc((rows ? rows : 1) * sizeof *ov);
    if (!ox || !oz || !ov)
      st = wl_error_set(err, WL_ENOMEM, "%s: no memory for %zu particles", path, rows);
  }
  if (!st) {
    const double *ps = pos, *vs = vq;
    for (size_t i = 0; i < rows; i++) {
      ox[i] = ps[i * cols];
      oz[i] = ps[i * cols + cols - 1];
      if (q == WL_REPORT_Q_SPEED) {
        double s2 = 0;
        for (size_t c = 0; c < cq; c++)
          s2 += vs[i * cq + c] * vs[i * cq + c];
        ov[i] = sqrt(s2);
      } else {
        ov[i] = vs[i * cq];
      }
    }
    *x = ox, *z = oz, *value = ov, *kind = kd, *n = rows;
    kd = NULL;
  } else {
    free(ox), free(oz), free(ov);
  }
  free(pos), free(vq), free(kd);
  return st;
}
