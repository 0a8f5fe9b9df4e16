#define _POSIX_C_SOURCE 200809L /* mkdtemp */
/* test_store.c: results files are complete or absent (temp + rename), and
 * what is written reads back through the plain HDF5 API (an independent
 * reader) with its units. Writes the system refuses (a file-size limit,
 * RLIMIT_FSIZE with SIGXFSZ ignored: EFBIG) are WL_EIO naming the file and
 * the reason, leave no temporary file and the previous file, and closing
 * such an HDF5 file cannot crash (issue 18: SIGSEGV in HDF5's exit handler
 * after a failed close); batches move all their files or none. */
#include <hdf5.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "testutil.h"
#include "wallload/scenario.h"
#include "wallload/store.h"

/* HDF5 1.10 loses its metadata accumulator's buffer (128 KiB, allocated in
 * H5F__accum_write) when writing it out fails at a flush: a leak of the
 * library's on that error path, once per refused file, not wallload's
 * (store.c closes the file all the same). LeakSanitizer is told to ignore
 * what is allocated around that refusal only. */
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#define HDF5_ERROR_PATH_BEGIN() __lsan_disable()
#define HDF5_ERROR_PATH_END() __lsan_enable()
#else
#define HDF5_ERROR_PATH_BEGIN() ((void)0)
#define HDF5_ERROR_PATH_END() ((void)0)
#endif

static int exists(const char *p) {
  struct stat st;
  return stat(p, &st) == 0;
}

static long file_size(const char *p) {
  struct stat st;
  return stat(p, &st) == 0 ? (long)st.st_size : -1;
}

/* Files over `bytes` are refused with EFBIG ("File too large"); 0 lifts it. */
static void limit_files(rlim_t bytes) {
  static struct rlimit saved;
  static int have = 0;
  if (!have) {
    getrlimit(RLIMIT_FSIZE, &saved);
    have = 1;
  }
  struct rlimit r = saved;
  if (bytes) r.rlim_cur = bytes;
  setrlimit(RLIMIT_FSIZE, &r);
}

/* A results file over the limit: every way the refusal can surface (the
 * write, the flush, the close) is WL_EIO with the reason, and the close
 * removes the temporary file and keeps the previous final one. */
static void refused(const char *dir, const char *path, const char *tmp) {
  signal(SIGXFSZ, SIG_IGN);
  const long before = file_size(path);
  enum { N = 100000 }; /* 800 kB */
  double *big = calloc(N, sizeof *big);
  struct wl_error err;
  struct wl_store *s;
  for (int way = 0; big && way < 3; way++) {
    wl_error_clear(&err);
    limit_files(way == 2 ? 8 * 1024 : 64 * 1024);
    CHECK_TRUE(wl_store_open(path, &s, &err) == WL_OK, "open under a file-size limit");
    enum wl_status st = WL_OK;
    /* ways: 0 many small datasets, 1 one large one (refused at a write), 2 metadata
     * within the limit until written out (refused at the close) */
    if (way == 0) {
      char name[64];
      for (int k = 0; k < 40 && !st; k++) {
        snprintf(name, sizeof name, "cases/a/v%02d", k);
        st = wl_store_write_vector(s, name, big, 4000, "1", "filler", &err);
      }
      if (!st) st = wl_store_flush(s, &err);
    } else if (way == 1) { /* one large dataset */
      st = wl_store_write_vector(s, "big", big, N, "1", "filler", &err);
    }
    if (way == 2) { /* metadata in HDF5's cache, over the limit only when written out */
      char name[64], text[200];
      memset(text, 'm', sizeof text - 1);
      text[sizeof text - 1] = '\0';
      st = wl_store_write_vector(s, "small", big, 100, "1", "filler", &err);
      for (int k = 0; k < 300 && !st; k++) {
        snprintf(name, sizeof name, "note%03d", k);
        st = wl_store_attr_text(s, "/", name, text, &err);
      }
    }
    if (way == 2) HDF5_ERROR_PATH_BEGIN();
    enum wl_status cs = wl_store_close(s, 1, way == 2 ? &err : &(struct wl_error){0});
    if (way == 2) HDF5_ERROR_PATH_END();
    limit_files(0);
    printf("  refused write, way %d: status %d, close %d: %s\n", way, st, cs, err.msg);
    if (way == 2 && st == WL_OK) st = cs;
    CHECK_TRUE(st == WL_EIO && cs == WL_EIO && strstr(err.msg, "File too large") &&
                   strstr(err.msg, path),
               "a refused write is WL_EIO naming the file and the system's reason");
    CHECK_TRUE(!exists(tmp) && file_size(path) == before,
               "no temporary file left; the previous file as it was");
  }
  free(big);
  /* text files */
  char txt[300], ttmp[310];
  snprintf(txt, sizeof txt, "%s/summary.json", dir);
  snprintf(ttmp, sizeof ttmp, "%s.tmp", txt);
  wl_error_clear(&err);
  CHECK_TRUE(wl_store_write_text(txt, "{}\n", 3, &err) == WL_OK, "a small text file");
  size_t n = 200000;
  char *text = malloc(n);
  if (text) {
    memset(text, 'x', n);
    limit_files(64 * 1024);
    enum wl_status st = wl_store_write_text(txt, text, n, &err);
    limit_files(0);
    CHECK_TRUE(st == WL_EIO && strstr(err.msg, "File too large") && strstr(err.msg, txt),
               "a refused text write is WL_EIO naming the file and the reason");
    CHECK_TRUE(!exists(ttmp) && file_size(txt) == 3, "the previous text file kept, no .tmp");
  }
  free(text);
  remove(txt);
  signal(SIGXFSZ, SIG_DFL);
}

/* Batches: every file moves, or none. */
static void batches(const char *dir) {
  char a[300], b[300], h[300], t[310];
  snprintf(a, sizeof a, "%s/a.csv", dir);
  snprintf(b, sizeof b, "%s/b.json", dir);
  snprintf(h, sizeof h, "%s/r.h5", dir);
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_store_batch batch;
  wl_store_batch_init(&batch);
  struct wl_store *s;
  double v[3] = {1, 2, 3};
  int ok = wl_store_open(h, &s, &err) == WL_OK &&
           wl_store_write_vector(s, "v", v, 3, "1", "v", &err) == WL_OK &&
           wl_store_close_batch(s, &batch, &err) == WL_OK &&
           wl_store_write_text_batch(a, "x\n1\n", 4, &batch, &err) == WL_OK &&
           wl_store_write_text_batch(b, "{}\n", 3, &batch, &err) == WL_OK;
  CHECK_TRUE(ok && !exists(a) && !exists(b) && !exists(h), "a batch: nothing in place before the commit");
  CHECK_TRUE(wl_store_batch_commit(&batch, &err) == WL_OK && exists(a) && exists(b) && exists(h),
             "a batch: all in place after it");
  snprintf(t, sizeof t, "%s.tmp", a);
  CHECK_TRUE(!exists(t), "a batch: no temporary file left");
  /* a second batch that fails half-way: the first one's files stay */
  wl_store_batch_init(&batch);
  ok = wl_store_write_text_batch(a, "y\n2\n3\n", 6, &batch, &err) == WL_OK;
  wl_store_batch_abort(&batch);
  CHECK_TRUE(ok && file_size(a) == 4 && !exists(t), "an aborted batch: the previous files, no .tmp");
  remove(a);
  remove(b);
  remove(h);
}

int main(void) {
  char dir[] = "/tmp/wl_store_XXXXXX";
  if (!mkdtemp(dir)) return 1;
  char path[256], tmp[300];
  snprintf(path, sizeof path, "%s/results.h5", dir);
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  struct wl_error err;
  wl_error_clear(&err);
  struct wl_store *s;
  CHECK_TRUE(wl_store_open(path, &s, &err) == WL_OK, "open");
  double t[5] = {0, 0.1, 0.2, 0.3, 0.4}, m[6] = {1, 2, 3, 4, 5, 6};
  CHECK_TRUE(wl_store_write_vector(s, "cases/a/wall/time", t, 5, "s", "sample times", &err) ==
                 WL_OK,
             "write vector in nested groups");
  CHECK_TRUE(wl_store_write_matrix(s, "cases/a/wall/pressure", m, 2, 3, "Pa", "p", &err) == WL_OK,
             "write matrix");
  CHECK_TRUE(wl_store_attr_text(s, "/", "version", "0.1.0", &err) == WL_OK, "root attribute");
  CHECK_TRUE(wl_store_attr_double(s, "cases/a", "dp", 0.01, "m", &err) == WL_OK, "double attr");
  CHECK_TRUE(wl_store_write_vector(s, "cases/a/wall/time", t, 5, "s", "again", &err) == WL_EIO,
             "writing the same dataset twice is an error, not a silent overwrite");
  CHECK_TRUE(exists(tmp) && !exists(path), "while writing, only the temporary file exists");
  wl_error_clear(&err);
  CHECK_TRUE(wl_store_close(s, 1, &err) == WL_OK, "close + commit");
  CHECK_TRUE(exists(path) && !exists(tmp), "after commit, only the final file exists");

  /* Read back independently. */
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  double back[6] = {0};
  hid_t d = H5Dopen2(f, "cases/a/wall/pressure", H5P_DEFAULT);
  H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, back);
  CHECK_ABS(back[5], 6.0, 0, "matrix element [1][2] reads back");
  hid_t a = H5Aopen(d, "unit", H5P_DEFAULT);
  hid_t ty = H5Aget_type(a);
  char unit[16] = {0};
  H5Aread(a, ty, unit);
  CHECK_TRUE(strcmp(unit, "Pa") == 0, "unit attribute reads back");
  H5Tclose(ty);
  H5Aclose(a);
  H5Dclose(d);
  H5Fclose(f);

  /* An abandoned file leaves nothing behind, and the old complete file stays. */
  CHECK_TRUE(wl_store_open(path, &s, &err) == WL_OK, "reopen");
  wl_store_close(s, 0, &err);
  CHECK_TRUE(exists(path) && !exists(tmp), "abandoning keeps the previous complete file");

  /* Bad directory: a clear I/O error. */
  wl_error_clear(&err);
  CHECK_TRUE(wl_store_open("/nonexistent/dir/x.h5", &s, &err) == WL_EIO &&
                 strstr(err.msg, "No such file") != NULL,
             "missing directory named in the message");

  char xmf[300];
  snprintf(xmf, sizeof xmf, "%s/particles.xmf", dir);
  struct wl_snapshot_ref refs[2] = {{0.0, 10, "snapshots/0000"}, {0.5, 10, "snapshots/0001"}};
  wl_error_clear(&err);
  CHECK_TRUE(wl_store_write_xdmf(xmf, "particles.h5", refs, 2, &err) == WL_OK, "xdmf written");
  FILE *x = fopen(xmf, "r");
  char buf[8192] = {0};
  size_t nread = x ? fread(buf, 1, sizeof buf - 1, x) : 0;
  if (x) fclose(x);
  CHECK_TRUE(nread > 0 && strstr(buf, "<Time Value=\"0.5\"/>") &&
                 strstr(buf, "particles.h5:snapshots/0001/position") && strstr(buf, "</Xdmf>"),
             "xdmf names both snapshots and is closed");
  remove(xmf);

  /* every stored setting is a scalar key of the scenario schema (the
   * names' owner): a typo in store's table would store "?" */
  struct wl_scenario sc;
  wl_scenario_init(&sc);
  int known = 0;
  for (int i = 0; i < wl_store_results_n_settings; i++)
    known += wl_scenario_value_of(&sc, wl_store_results_settings[i].key) != NULL;
  CHECK_TRUE(wl_store_results_n_settings > 0 && known == wl_store_results_n_settings,
             "store's settings are the scenario schema's keys (schema.c)");
  CHECK_TRUE(!wl_scenario_value_of(&sc, "numerics") && !wl_scenario_value_of(&sc, "numerics.x") &&
                 !wl_scenario_value_of(&sc, "gauges.x") &&
                 wl_scenario_value_of(&sc, "run.end_time") == &sc.run.end_time,
             "wl_scenario_value_of: scalars only, by their dotted schema name");
  wl_scenario_clear(&sc);

  refused(dir, path, tmp);
  batches(dir);
  remove(path);
  rmdir(dir);
  /* the exit itself (HDF5's library state after refused writes) must not crash */
  return TEST_RESULT();
}
