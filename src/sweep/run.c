/* run.c: run the cases of a sweep through wl_assess_run, one after the
 * other or, on a GPU, several side by side, reading back the cases an
 * earlier sweep into the same directory finished (sweep.h: resuming). */
#define _POSIX_C_SOURCE 200809L /* mkdir, stat */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "sweep_private.h"
#include "wallload/config.h"
#include "wallload/plan.h"
#include "wallload/store.h"

#define MARKER "sweep-case.txt"

const struct sweep_field sweep_fields[] = {
#define F(m) offsetof(struct wl_sweep_loads, m)
    {"peak_force", "N_per_m", "N/m", "peak of the filtered pressure-probe force (quote this)",
     F(peak_force)},
    {"peak_force_boundary", "N_per_m", "N/m", "peak of the filtered boundary-particle force",
     F(peak_force_boundary)},
    {"impulse_positive", "Ns_per_m", "N s/m",
     "integral of max(0, filtered force - force at rest) dt, probes (quote this)",
     F(impulse_positive)},
    {"impulse_positive_boundary", "Ns_per_m", "N s/m", "the same from the boundary particles",
     F(impulse_positive_boundary)},
    {"impulse", "Ns_per_m", "N s/m", "net impulse of the whole record, probes", F(impulse)},
    {"impulse_positive_phase", "Ns_per_m", "N s/m", "impulse of the peak's positive phase, probes",
     F(impulse_positive_phase)},
    {"peak_moment", "Nm_per_m", "N m/m", "peak of the filtered overturning moment about the toe",
     F(peak_moment)},
    {"max_runup", "m", "m", "highest water level at the wall face above still water",
     F(max_runup)},
    {"uncertainty", "1", "1",
     "convergence ladder: the larger relative uncertainty of the two below (empty: no ladder)",
     F(uncertainty)},
    {"uncertainty_peak_force", "1", "1", "convergence ladder: relative uncertainty of peak_force",
     F(uncertainty_force)},
    {"uncertainty_impulse_positive", "1", "1",
     "convergence ladder: relative uncertainty of impulse_positive", F(uncertainty_impulse)},
#undef F
};
const int sweep_n_fields = (int)(sizeof sweep_fields / sizeof sweep_fields[0]);

const char *sweep_status_word(const struct wl_sweep_row *r, enum wl_status st) {
  if (r && r->state == WL_SWEEP_PENDING) return "pending";
  switch (st) {
  case WL_OK: return "complete";
  case WL_EUNSTABLE: return "unstable";
  case WL_EINTERRUPTED: return "interrupted";
  default: return "failed";
  }
}

const char *sweep_param_unit(enum wl_sweep_param p) {
  return p == WL_SWEEP_CHARGE ? "kg" : p == WL_SWEEP_ENERGY ? "J" : "m";
}

/* ---- the digest of a case's inputs ---------------------------------------------- */

/* FNV-1a, 64 bits: a change detector for the case's inputs (not a
 * security measure: the directory is the user's own). */
static uint64_t fnv1a(uint64_t h, const void *data, size_t n) {
  const unsigned char *p = data;
  for (size_t i = 0; i < n; i++) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

/* What decides a case's results: its scenario text, the backend (CPU and
 * GPU differ in the last bits), an --end-time override and the program's
 * version (raised whenever results.h5 gains keys that the sweep's tables
 * read, so a resumed sweep recomputes cases an earlier version wrote). Not
 * the thread count: the solver's results do not depend on it. */
static void case_digest(const struct wl_sweep_case *c, const char *backend, double end_time,
                        char hex[17]) {
  uint64_t h = 14695981039346656037ULL;
  h = fnv1a(h, c->text, c->len);
  char extra[256];
  const int n = snprintf(extra, sizeof extra, "\nbackend=%s\nend_time=%.17g\nversion=%s\n",
                         backend, end_time, WL_VERSION);
  h = fnv1a(h, extra, (size_t)n);
  snprintf(hex, 17, "%016llx", (unsigned long long)h);
}

/* ---- a case's marker: its digest and its row -------------------------------------- */

static const char *const load_key[WL_SWEEP_N_LOADS] = {"solitary", "explosion"};

static enum wl_status write_marker(const char *path, const char *digest,
                                   const struct wl_sweep_row *r, struct wl_error *err) {
  char buf[8192];
  size_t o = 0;
#define PUT(...) o += (size_t)snprintf(buf + o, o < sizeof buf ? sizeof buf - o : 0, __VA_ARGS__)
  PUT("# wallload sweep: this case's inputs (digest) and loads; delete it to run the case again\n");
  PUT("digest %s\nstatus %s\nruntime %.17g\n", digest, sweep_status_word(NULL, r->status),
      r->runtime_s);
  for (int l = 0; l < WL_SWEEP_N_LOADS; l++) {
    const struct wl_sweep_loads *ld = &r->load[l];
    if (!ld->present) continue;
    PUT("%s.status %s\n", load_key[l], sweep_status_word(NULL, ld->status));
    for (int f = 0; f < sweep_n_fields; f++)
      PUT("%s.%s %.17g\n", load_key[l], sweep_fields[f].name,
          *(const double *)(const void *)((const char *)ld + sweep_fields[f].off));
  }
  if (r->status != WL_OK) PUT("message %s\n", r->message);
#undef PUT
  if (o >= sizeof buf) return wl_error_set(err, WL_ENOMEM, "%s: the row is too long", path);
  return wl_store_write_text(path, buf, o, err);
}

static enum wl_status status_of_word(const char *w) {
  return !strcmp(w, "complete") ? WL_OK : !strcmp(w, "unstable") ? WL_EUNSTABLE : WL_EIO;
}

/* 1 with *r filled when `path` holds a finished case of digest `digest`
 * (complete or unstable: both are what the inputs give). */
static int read_marker(const char *path, const char *digest, struct wl_sweep_row *r) {
  FILE *f = fopen(path, "r");
  if (!f) return 0;
  struct wl_sweep_row row;
  memset(&row, 0, sizeof row);
  int have_digest = 0, have_status = 0;
  char line[2048];
  while (fgets(line, sizeof line, f)) {
    line[strcspn(line, "\n")] = '\0';
    char *sp = strchr(line, ' ');
    if (line[0] == '#' || !sp) continue;
    *sp = '\0';
    const char *key = line, *val = sp + 1;
    if (!strcmp(key, "digest")) have_digest = !strcmp(val, digest);
    else if (!strcmp(key, "status")) row.status = status_of_word(val), have_status = 1;
    else if (!strcmp(key, "runtime")) row.runtime_s = strtod(val, NULL);
    else if (!strcmp(key, "message")) snprintf(row.message, sizeof row.message, "%s", val);
    for (int l = 0; l < WL_SWEEP_N_LOADS; l++) {
      const size_t kl = strlen(load_key[l]);
      if (strncmp(key, load_key[l], kl) || key[kl] != '.') continue;
      struct wl_sweep_loads *ld = &row.load[l];
      ld->present = 1;
      if (!strcmp(key + kl + 1, "status")) ld->status = status_of_word(val);
      for (int k = 0; k < sweep_n_fields; k++)
        if (!strcmp(key + kl + 1, sweep_fields[k].name))
          *(double *)(void *)((char *)ld + sweep_fields[k].off) = strtod(val, NULL);
    }
  }
  fclose(f);
  if (!have_digest || !have_status || (row.status != WL_OK && row.status != WL_EUNSTABLE)) return 0;
  row.state = WL_SWEEP_REUSED;
  *r = row;
  return 1;
}

/* ---- running one case ----------------------------------------------------------------- */

static double now_s(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int file_exists(const char *path) {
  struct stat sb;
  return stat(path, &sb) == 0 && S_ISREG(sb.st_mode);
}

/* The row of an assessment: summary.json's values. */
static void row_from_result(const struct wl_assess_result *res, struct wl_sweep_row *r) {
  for (int l = 0; l < WL_SWEEP_N_LOADS; l++) r->load[l].present = 0;
  for (int k = 0; k < res->n_cases; k++) {
    const struct wl_case_result *c = &res->cases[k];
    const struct wl_case_loads *lo = &c->loads;
    struct wl_sweep_loads *ld = &r->load[c->load == WL_CASE_SOLITARY ? 0 : 1];
    ld->present = 1;
    ld->status = c->status;
    const int have = c->rec.n > 0;
    ld->peak_force = have ? lo->force_peak.value : NAN;
    ld->peak_force_boundary = have ? lo->force_bound_peak.value : NAN;
    ld->impulse_positive = have ? lo->impulse_positive : NAN;
    ld->impulse_positive_boundary = have ? lo->impulse_positive_bound : NAN;
    ld->impulse = have ? lo->impulse_total : NAN;
    ld->impulse_positive_phase = have ? lo->impulse_peak : NAN;
    ld->peak_moment = have ? lo->moment_peak.value : NAN;
    ld->max_runup = have ? lo->runup : NAN;
    const struct wl_assess_convergence *cv = &res->conv[k];
    ld->uncertainty = cv->n_levels ? cv->error_estimate : NAN;
    ld->uncertainty_force = cv->n_levels ? cv->force.error : NAN;
    ld->uncertainty_impulse = cv->n_levels ? cv->impulse_pos.error : NAN;
  }
}

enum wl_status sweep_run_case(struct wl_sweep *sw, int i, const char *dir, const char *digest,
                              const struct wl_assess_opts *opts, struct wl_error *err) {
  const struct wl_sweep_case *c = &sw->cases[i];
  struct wl_sweep_row *r = &sw->rows[i];
  char cdir[1200], path[1400];
  snprintf(cdir, sizeof cdir, "%s/cases/%s", dir, c->id);
  if (mkdir(cdir, 0777) != 0 && errno != EEXIST)
    return wl_error_set(err, WL_EIO, "%s: cannot create the case directory (%s)", cdir,
                        strerror(errno));
  snprintf(path, sizeof path, "%s/" MARKER, cdir);
  remove(path); /* another inputs' marker, or a result about to be replaced */
  char scen[1400];
  snprintf(scen, sizeof scen, "%s/scenario.yaml", cdir);
  enum wl_status st = wl_store_write_text(scen, c->text, c->len, err);
  if (st) return st;
  struct wl_scenario *cs = malloc(sizeof *cs);
  struct wl_plan *plan = malloc(sizeof *plan);
  struct wl_assess_result *res = calloc(1, sizeof *res);
  if (!cs || !plan || !res) {
    free(cs), free(plan), free(res);
    return wl_error_set(err, WL_ENOMEM, "%s: no memory for case %d", sw->path, i);
  }
  struct wl_error e;
  wl_error_clear(&e);
  const double t0 = now_s();
  st = wl_sweep_case_scenario(sw, i, cs, &e);
  if (st == WL_OK && cs->resolution.refine.present && cs->resolution.refine.from.is_auto) {
    struct wl_plan_machine m; /* from: auto, planned for the backend the case runs on */
    wl_assess_machine(cs, opts, &m);
    wl_plan_refine_machine(cs, &m);
  }
  if (st == WL_OK) st = wl_plan_make(cs, plan, &e);
  if (st == WL_OK) {
    struct wl_assess_opts o = *opts;
    o.out_dir = cdir;
    o.force = 1;
    o.no_snapshots = 1;
    o.no_report = 1;
    st = wl_assess_run(cs, plan, &o, res, &e);
    row_from_result(res, r);
  }
  r->runtime_s = now_s() - t0;
  r->state = WL_SWEEP_RAN;
  r->status = st;
  snprintf(r->message, sizeof r->message, "%s", st ? e.msg : "");
  enum wl_status out = st;
  if (st == WL_OK || st == WL_EUNSTABLE) { /* what these inputs give: kept for a later sweep */
    out = write_marker(path, digest, r, err);
    if (out == WL_OK) out = st;
  } else if (st == WL_EIO || st == WL_ENOMEM) {
    *err = e;
  }
  wl_assess_result_clear(res);
  wl_scenario_clear(cs);
  free(cs), free(plan), free(res);
  return out;
}

/* ---- the sweep ----------------------------------------------------------------------------- */

/* dir: created when missing; an existing one must be empty or an earlier
 * sweep's (its cases/ or sweep.csv), never an assessment's or the user's
 * other files. */
static enum wl_status prepare_dir(const char *dir, struct wl_error *err) {
  struct stat sb;
  if (stat(dir, &sb) != 0) {
    if (mkdir(dir, 0777) != 0)
      return wl_error_set(err, errno == ENOSPC || errno == EIO ? WL_EIO : WL_EINPUT,
                          "%s: cannot create the sweep's directory (%s)", dir, strerror(errno));
  } else if (!S_ISDIR(sb.st_mode)) {
    return wl_error_set(err, WL_EINPUT, "%s: exists and is not a directory; choose another with -o",
                        dir);
  } else {
    char p[1200];
    snprintf(p, sizeof p, "%s/cases", dir);
    int sweep_dir = stat(p, &sb) == 0 && S_ISDIR(sb.st_mode);
    snprintf(p, sizeof p, "%s/sweep.csv", dir);
    sweep_dir |= file_exists(p);
    int empty = 1;
    DIR *d = opendir(dir);
    if (d) {
      struct dirent *e;
      while (empty && (e = readdir(d)))
        empty = !strcmp(e->d_name, ".") || !strcmp(e->d_name, "..") ||
                !strcmp(e->d_name, ".wallload.lock");
      closedir(d);
    }
    if (!sweep_dir && !empty)
      return wl_error_set(err, WL_EINPUT,
                          "%s: exists and holds files that are not a sweep's (no cases/ or "
                          "sweep.csv); choose another directory with -o",
                          dir);
  }
  char cases[1200];
  snprintf(cases, sizeof cases, "%s/cases", dir);
  if (mkdir(cases, 0777) != 0 && errno != EEXIST)
    return wl_error_set(err, WL_EIO, "%s: cannot create it (%s)", cases, strerror(errno));
  return WL_OK;
}

/* A case done: run or read back, with a result its inputs give. */
static int is_done(const struct wl_sweep_row *r) {
  return r->state != WL_SWEEP_PENDING && (r->status == WL_OK || r->status == WL_EUNSTABLE);
}

/* The cases done, as "0-3, 5". */
static void list_done(const struct wl_sweep *sw, char *buf, size_t size) {
  buf[0] = '\0';
  for (int i = 0; i < sw->n_cases; i++) {
    if (!is_done(&sw->rows[i])) continue;
    int j = i;
    while (j + 1 < sw->n_cases && is_done(&sw->rows[j + 1])) j++;
    size_t u = strlen(buf);
    if (j > i) snprintf(buf + u, size - u, "%s%d-%d", u ? ", " : "", i, j);
    else snprintf(buf + u, size - u, "%s%d", u ? ", " : "", i);
    i = j;
  }
}

enum wl_status sweep_digests(const struct wl_sweep *sw, const struct wl_assess_opts *opts,
                             char (**digest)[17], int *threads, struct wl_error *err) {
  *digest = NULL;
  /* the backend the cases run on, for their digests */
  struct wl_scenario *cs = malloc(sizeof *cs);
  if (!cs) return wl_error_set(err, WL_ENOMEM, "%s: no memory", sw->path);
  enum wl_status st = wl_sweep_case_scenario(sw, 0, cs, err);
  struct wl_plan_machine m;
  if (st == WL_OK) wl_assess_machine(cs, opts, &m);
  wl_scenario_clear(cs);
  free(cs);
  if (st) return st;
  if (threads) *threads = m.threads;
  const char *backend = m.device_bytes > 0 ? "cuda" : "cpu";
  char(*d)[17] = malloc((size_t)sw->n_cases * sizeof *d);
  if (!d) return wl_error_set(err, WL_ENOMEM, "%s: no memory", sw->path);
  for (int i = 0; i < sw->n_cases; i++) case_digest(&sw->cases[i], backend, opts->end_time, d[i]);
  *digest = d;
  return WL_OK;
}

/* The pending cases one after the other in this process. *stop gets the
 * stop signal's number when one ends the sweep early. */
static enum wl_status run_serial(struct wl_sweep *sw, const char *dir,
                                 const struct wl_assess_opts *opts,
                                 const struct wl_sweep_events *ev, char (*digest)[17], int *stop,
                                 struct wl_error *err) {
  enum wl_status st = WL_OK;
  for (int i = 0; i < sw->n_cases; i++) {
    if (sw->rows[i].state != WL_SWEEP_PENDING) continue;
    if (opts->interrupted && *opts->interrupted) {
      *stop = (int)*opts->interrupted;
      break;
    }
    if (ev && ev->case_begin) ev->case_begin(ev->user, sw, i, 0);
    struct wl_error e;
    wl_error_clear(&e);
    const enum wl_status cst = sweep_run_case(sw, i, dir, digest[i], opts, &e);
    if (ev && ev->case_end) ev->case_end(ev->user, sw, i);
    st = sweep_write_tables(sw, dir, err);
    if (cst == WL_EIO || cst == WL_ENOMEM) {
      if (st == WL_OK) st = wl_error_set(err, cst, "case %d (%s): %s", i, sw->cases[i].id, e.msg);
      break;
    }
    if (st) break;
    if (cst == WL_EINTERRUPTED || (opts->interrupted && *opts->interrupted)) {
      *stop = opts->interrupted && *opts->interrupted ? (int)*opts->interrupted : SIGINT;
      break;
    }
  }
  return st;
}

/* Cases side by side on one GPU: a small flume's step is mostly fixed cost
 * (launches, the per-step synchronisation) and leaves the GPU idle, as the
 * ladder's levels do (src/assess/ladder.c); each case runs in its own
 * thread (and CUDA stream), its results those it gives alone. At most
 * WL_SWEEP_SIDE_BY_SIDE_MAX at once, and together within
 * WL_PLAN_GPU_SIDE_BY_SIDE_MEMORY of the GPU's memory (plan.h, which also
 * prices it). */

struct side_job {
  struct wl_sweep *sw;
  int i;
  const char *dir, *digest;
  struct wl_assess_opts opts;
  struct wl_error err;
  enum wl_status st;
  int done;              /* set under side->lock when the case has ended */
  struct side_state *side;
  pthread_t tid;
};

struct side_state {
  pthread_mutex_t lock;  /* guards the jobs' done flags */
  pthread_cond_t ended;  /* a job has ended */
  pthread_mutex_t write; /* HDF5: the cases' results and the sweep's tables */
};

static void *side_thread(void *arg) {
  struct side_job *j = arg;
  j->st = sweep_run_case(j->sw, j->i, j->dir, j->digest, &j->opts, &j->err);
  pthread_mutex_lock(&j->side->lock);
  j->done = 1;
  pthread_cond_signal(&j->side->ended);
  pthread_mutex_unlock(&j->side->lock);
  return NULL;
}

/* How many pending cases fit the GPU together: 0 when the sweep does not
 * run on a GPU (or a case cannot be planned: it then fails on its own). A
 * ladder's levels run side by side within each case, so a case counts its
 * levels' memory. */
static int side_by_side_width(const struct wl_sweep *sw, const struct wl_assess_opts *opts) {
  int n_pending = 0, first = -1;
  for (int i = 0; i < sw->n_cases; i++)
    if (sw->rows[i].state == WL_SWEEP_PENDING) {
      if (first < 0) first = i;
      n_pending++;
    }
  if (n_pending < 2) return 0;
  struct wl_scenario *cs = malloc(sizeof *cs);
  struct wl_plan *plan = malloc(sizeof *plan);
  if (!cs || !plan) {
    free(cs), free(plan);
    return 0;
  }
  double device = 0, bytes = 0;
  int ok = 1;
  for (int i = first; i < sw->n_cases && ok; i++) {
    if (sw->rows[i].state != WL_SWEEP_PENDING) continue;
    struct wl_error e;
    wl_error_clear(&e);
    wl_scenario_init(cs);
    ok = wl_sweep_case_scenario(sw, i, cs, &e) == WL_OK && wl_plan_make(cs, plan, &e) == WL_OK;
    if (ok && i == first) {
      struct wl_plan_machine m;
      wl_assess_machine(cs, opts, &m);
      device = m.device_bytes;
      ok = device > 0;
    }
    if (ok) {
      const int levels = cs->resolution.n_levels > 0 ? cs->resolution.n_levels : 1;
      bytes = fmax(bytes, levels * plan->gpu_memory_bytes);
    }
    wl_scenario_clear(cs);
  }
  free(cs), free(plan);
  if (!ok || !(bytes > 0)) return 0;
  const int k = wl_plan_gpu_side_by_side_width(bytes, device, WL_SWEEP_SIDE_BY_SIDE_MAX);
  return k < n_pending ? k : n_pending;
}

/* The pending cases, `width` at a time, each in its own thread; this thread
 * starts them in order, writes the tables as each ends and calls the
 * events (case_begin when a case starts, case_end when it has ended, in
 * the order they end). A stop signal lets the running cases stop at their
 * next output and starts no more. */
static enum wl_status run_side_by_side(struct wl_sweep *sw, const char *dir,
                                       const struct wl_assess_opts *opts,
                                       const struct wl_sweep_events *ev, char (*digest)[17],
                                       int width, int *stop, struct wl_error *err) {
  struct side_job *jobs = calloc((size_t)sw->n_cases, sizeof *jobs);
  struct side_state side;
  if (!jobs) return wl_error_set(err, WL_ENOMEM, "%s: no memory for %d cases", sw->path, sw->n_cases);
  pthread_mutex_init(&side.lock, NULL);
  pthread_cond_init(&side.ended, NULL);
  pthread_mutex_init(&side.write, NULL);
  /* the host's cores shared among the cases' host-side loops */
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  const int threads = opts->threads > 0 ? opts->threads : (int)(cores > 0 ? cores / width : 1);
  enum wl_status st = WL_OK;
  int running = 0, next = 0, ended_fatal = 0;
  for (;;) {
    /* start cases while there is room */
    while (running < width && !ended_fatal && st == WL_OK &&
           !(opts->interrupted && *opts->interrupted)) {
      while (next < sw->n_cases && sw->rows[next].state != WL_SWEEP_PENDING) next++;
      if (next >= sw->n_cases) break;
      struct side_job *j = &jobs[next];
      j->sw = sw, j->i = next, j->dir = dir, j->digest = digest[next], j->side = &side;
      j->opts = *opts;
      j->opts.progress = NULL; /* several cases at once: begin and end lines only */
      j->opts.threads = threads > 0 ? threads : 1;
      j->opts.write_lock = &side.write;
      wl_error_clear(&j->err);
      if (ev && ev->case_begin) ev->case_begin(ev->user, sw, next, 0);
      if (pthread_create(&j->tid, NULL, side_thread, j) != 0) {
        st = wl_error_set(err, WL_ENOMEM, "%s: cannot start a thread for case %d", sw->path, next);
        break;
      }
      running++;
      next++;
    }
    if (running == 0) break;
    /* wait for a case to end; handle every ended one */
    pthread_mutex_lock(&side.lock);
    int any = 0;
    for (;;) {
      for (int i = 0; i < sw->n_cases; i++)
        if (jobs[i].done == 1) any = 1;
      if (any) break;
      pthread_cond_wait(&side.ended, &side.lock);
    }
    pthread_mutex_unlock(&side.lock);
    for (int i = 0; i < sw->n_cases; i++) {
      struct side_job *j = &jobs[i];
      pthread_mutex_lock(&side.lock);
      const int ended = j->done == 1;
      if (ended) j->done = 2; /* handled */
      pthread_mutex_unlock(&side.lock);
      if (!ended) continue;
      pthread_join(j->tid, NULL);
      running--;
      if (ev && ev->case_end) ev->case_end(ev->user, sw, i);
      pthread_mutex_lock(&side.write);
      const enum wl_status wst = sweep_write_tables(sw, dir, err);
      pthread_mutex_unlock(&side.write);
      if (wst && st == WL_OK) st = wst;
      if ((j->st == WL_EIO || j->st == WL_ENOMEM) && !ended_fatal) {
        ended_fatal = 1;
        if (st == WL_OK) st = wl_error_set(err, j->st, "case %d (%s): %s", i, sw->cases[i].id, j->err.msg);
      }
      if (j->st == WL_EINTERRUPTED && !*stop) *stop = SIGINT;
    }
  }
  if (opts->interrupted && *opts->interrupted) *stop = (int)*opts->interrupted;
  pthread_mutex_destroy(&side.write);
  pthread_cond_destroy(&side.ended);
  pthread_mutex_destroy(&side.lock);
  free(jobs);
  return st;
}

/* The sweep in its locked directory: cases read back, the others run here
 * (lead NULL) or shared among MPI ranks (mpi.c), then the summary. */
static enum wl_status sweep_locked(struct wl_sweep *sw, const char *dir,
                                   const struct wl_assess_opts *opts,
                                   const struct wl_sweep_events *ev, struct sweep_lead *lead,
                                   struct wl_error *err) {
  char(*digest)[17];
  int threads = 0;
  enum wl_status st = sweep_digests(sw, opts, &digest, &threads, err);
  if (st) return st;
  for (int i = 0; i < sw->n_cases; i++) {
    memset(&sw->rows[i], 0, sizeof sw->rows[i]);
    char cdir[1200], p[1400];
    snprintf(cdir, sizeof cdir, "%s/cases/%s", dir, sw->cases[i].id);
    snprintf(p, sizeof p, "%s/results.h5", cdir);
    int results = file_exists(p);
    snprintf(p, sizeof p, "%s/summary.json", cdir);
    results = results && file_exists(p);
    snprintf(p, sizeof p, "%s/" MARKER, cdir);
    if (results && read_marker(p, digest[i], &sw->rows[i]) && ev && ev->case_begin)
      ev->case_begin(ev->user, sw, i, 1);
  }
  st = sweep_write_tables(sw, dir, err);
  int stop = 0, n_bad = 0;
  sw->side_by_side = lead ? 1 : side_by_side_width(sw, opts);
  if (sw->side_by_side < 2) sw->side_by_side = 1;
  if (st == WL_OK)
    st = lead                   ? sweep_lead_cases(lead, sw, dir, opts, ev, digest, threads, &stop, err)
         : sw->side_by_side > 1 ? run_side_by_side(sw, dir, opts, ev, digest, sw->side_by_side,
                                                   &stop, err)
                                : run_serial(sw, dir, opts, ev, digest, &stop, err);
  free(digest);
  if (st) return st;
  char done[1024];
  list_done(sw, done, sizeof done);
  int n_done = 0, n_reused = 0;
  for (int i = 0; i < sw->n_cases; i++) {
    const struct wl_sweep_row *r = &sw->rows[i];
    n_done += is_done(r);
    if (r->state == WL_SWEEP_REUSED) n_reused++;
    if (r->state != WL_SWEEP_PENDING && r->status != WL_OK) n_bad++;
  }
  if (stop)
    return wl_error_set(err, WL_EINTERRUPTED,
                        "interrupted by %s: %d of %d cases done (%s%s; %d of them read back from an "
                        "earlier run); %s/sweep.csv and sweep.h5 hold them; the same command "
                        "continues with the others",
                        wl_assess_stop_signal_name(stop), n_done, sw->n_cases,
                        n_done == 1 ? "case " : "cases ", n_done ? done : "none", n_reused, dir);
  st = sweep_write_pdf(sw, dir, err);
  if (st) return st;
  if (n_bad) {
    char bad[1024] = "";
    for (int i = 0; i < sw->n_cases; i++) {
      const struct wl_sweep_row *r = &sw->rows[i];
      if (r->status == WL_OK) continue;
      size_t u = strlen(bad);
      snprintf(bad + u, sizeof bad - u, "%s%d (%s)", u ? ", " : "", i,
               sweep_status_word(r, r->status));
    }
    return wl_error_set(err, WL_EUNSTABLE,
                        "%d of %d cases did not complete: %s; their rows in %s/sweep.csv say why",
                        n_bad, sw->n_cases, bad, dir);
  }
  return WL_OK;
}

enum wl_status wl_sweep_run(struct wl_sweep *sw, const char *dir,
                            const struct wl_assess_opts *opts, const struct wl_sweep_events *ev,
                            struct wl_error *err) {
  return wl_sweep_run_ranks(sw, dir, opts, ev, NULL, err);
}

enum wl_status wl_sweep_run_ranks(struct wl_sweep *sw, const char *dir,
                                  const struct wl_assess_opts *opts,
                                  const struct wl_sweep_events *ev,
                                  struct wl_sweep_ranks *ranks, struct wl_error *err) {
  const int shared = ranks && ranks->size > 1;
  if (shared && ranks->rank > 0) return sweep_follow(ranks, sw, dir, opts, err);
  /* the lead (or the only process): the directory and its lock are this
   * process's; the other ranks start once they are had, or learn why not */
  enum wl_status st = prepare_dir(dir, err);
  char lock[1200];
  if (st == WL_OK) st = wl_assess_lock_dir(dir, lock, sizeof lock, err);
  const int locked = st == WL_OK;
  struct sweep_lead *lead = NULL;
  if (shared) {
    enum wl_status lst = sweep_lead_start(ranks, sw, st, &lead, err);
    if (st == WL_OK) st = lst;
  }
  if (st == WL_OK) st = sweep_locked(sw, dir, opts, ev, lead, err);
  if (shared) sweep_lead_end(lead, st);
  if (locked) unlink(lock);
  return st;
}
