#define _POSIX_C_SOURCE 200809L /* mkdtemp */
/* test_store.c: results files are complete or absent (temp + rename), and
 * what is written reads back through the plain HDF5 API (an independent
 * reader) with its units. */
#include <hdf5.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "testutil.h"
#include "wallload/store.h"

static int exists(const char *p) {
  struct stat st;
  return stat(p, &st) == 0;
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
  remove(path);
  rmdir(dir);
  return TEST_RESULT();
}
