/* store.c: HDF5 results and text files, written atomically and durably.
 *
 * Failure policy (issue 18: a nearly full disk made HDF5 segfault in its
 * exit handler after a failed H5Fclose, losing stdout):
 *  - HDF5's automatic error printing is off; every status is checked here,
 *    and a failure is reported with the file and the innermost message of
 *    HDF5's error stack (for a failed system call, the system's reason:
 *    "No space left on device").
 *  - H5Fclose must not fail: a failed close leaves the file's id behind,
 *    half torn down, and the library's exit handler crashes on it. So the
 *    file is flushed first (H5Fflush reports what the disk refused while
 *    the file is intact), and once anything failed the file's descriptor
 *    is pointed at an in-memory sink (memfd) before the close, so that the
 *    close's own writes cannot fail; the temporary file is then removed.
 *    Files close with H5F_CLOSE_STRONG (no object id can keep one open), and
 *    H5dont_atexit keeps the exit handler away from anything that still
 *    went wrong.
 *  - Text files go through write(2) with every return checked, fsync and a
 *    checked close; HDF5 files are fsynced after the close; only then is the
 *    temporary file renamed over the final name (and the directory synced),
 *    so a power cut or a full disk leaves the previous file or the new one. */
#define _GNU_SOURCE /* memfd_create */
#include "wallload/store.h"

#include <stdarg.h>
#include <errno.h>
#include <fcntl.h>
#include <hdf5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

struct wl_store {
  hid_t file;
  int failed; /* a write failed: the file is discarded at close */
  char path[1024];
  char tmp[1040];
};

void wl_store_hdf5_init(void) {
  /* per thread: a thread-safe HDF5 keeps the error printing setting of
   * each thread's default error stack (cases run side by side, assess.c) */
  static _Thread_local int done = 0;
  if (done) return;
  done = 1;
  /* before any other HDF5 call (later it is refused, harmlessly) */
  H5dont_atexit();
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
}

int wl_store_thread_safe(void) {
  hbool_t safe = 0;
  return H5is_library_threadsafe(&safe) >= 0 && safe;
}

/* ---- reasons ------------------------------------------------------------------ */

struct h5_reason {
  char text[256];
  int found;
};

/* The innermost entry of HDF5's error stack (walked upward: n == 0 is the
 * most specific). A failed system call's entry reads "..., errno = 28,
 * error message = 'No space left on device', ...": that part is kept. */
static herr_t reason_walk(unsigned n, const H5E_error2_t *e, void *data) {
  struct h5_reason *r = data;
  if (n != 0 || r->found || !e->desc) return 0;
  const char *d = e->desc, *m = strstr(d, "error message = '");
  if (m) {
    m += strlen("error message = '");
    const char *q = strchr(m, '\'');
    int len = q ? (int)(q - m) : (int)strlen(m);
    snprintf(r->text, sizeof r->text, "%.*s", len, m);
  } else {
    snprintf(r->text, sizeof r->text, "%s", d);
  }
  r->found = r->text[0] != '\0';
  return 0;
}

/* Why the last HDF5 call failed: the system's reason where a system call
 * failed, else HDF5's own words. Call right after the failure (any later
 * HDF5 call clears the stack). */
static void h5_reason(char *buf, size_t size, int saved_errno) {
  struct h5_reason r = {{0}, 0};
  hid_t stack = H5Eget_current_stack();
  if (stack >= 0) {
    H5Ewalk2(stack, H5E_WALK_UPWARD, reason_walk, &r);
    H5Eclose_stack(stack);
  }
  if (r.found)
    snprintf(buf, size, "%s", r.text);
  else if (saved_errno)
    snprintf(buf, size, "%s", strerror(saved_errno));
  else
    snprintf(buf, size, "HDF5 error");
}

/* ---- the file's descriptor ------------------------------------------------------- */

/* Point the file's descriptor at an in-memory sink, so that whatever HDF5
 * still writes (at the close) succeeds and goes nowhere: the file is being
 * discarded. */
static void detach(struct wl_store *s) {
  void *handle = NULL;
  if (H5Fget_vfd_handle(s->file, H5P_DEFAULT, &handle) < 0 || !handle) return;
  const int fd = *(int *)handle;
  int sink = memfd_create("wallload-discarded", MFD_CLOEXEC);
  if (sink < 0) sink = open("/dev/null", O_RDWR | O_CLOEXEC);
  if (sink < 0) return;
  if (sink != fd) {
    dup2(sink, fd);
    close(sink);
  }
}

/* Record the first write failure: err names the final file, what failed
 * (msg) and why; the file is detached (see above). */
static enum wl_status store_fail_why(struct wl_store *s, struct wl_error *err, const char *msg,
                                     const char *why) {
  if (!s->failed) detach(s);
  s->failed = 1;
  return wl_error_set(err, WL_EIO, "%s: %s: %s", s->path, msg, why);
}

static enum wl_status store_fail(struct wl_store *s, struct wl_error *err, const char *msg,
                                 int saved_errno) {
  char why[256];
  h5_reason(why, sizeof why, saved_errno);
  return store_fail_why(s, err, msg, why);
}

/* store_fail for "cannot write <kind> <name> of <path>". */
static enum wl_status store_fail_obj(struct wl_store *s, struct wl_error *err, const char *kind,
                                     const char *name, const char *path, int saved_errno) {
  char msg[400];
  if (path)
    snprintf(msg, sizeof msg, "cannot write %s %s of %s", kind, name, path);
  else
    snprintf(msg, sizeof msg, "cannot write %s %s", kind, name);
  return store_fail(s, err, msg, saved_errno);
}

/* The error of a store that failed before: no HDF5 call is made on it. */
static enum wl_status store_failed(struct wl_store *s, struct wl_error *err) {
  return wl_error_set(err, WL_EIO, "%s: not written: an earlier write to it failed", s->path);
}

/* fsync a closed file by name (its data and size reach the disk). */
static int sync_path(const char *path) {
  const int fd = open(path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return -1;
  int rc = fsync(fd);
  if (rc != 0 && (errno == EINVAL || errno == EROFS)) rc = 0; /* cannot be synced: not an error */
  const int e = errno;
  close(fd);
  errno = e;
  return rc;
}

void wl_store_sync_dir_of(const char *path) {
  char dir[1040];
  snprintf(dir, sizeof dir, "%s", path);
  char *slash = strrchr(dir, '/');
  if (slash == dir)
    dir[1] = '\0';
  else if (slash)
    *slash = '\0';
  else
    snprintf(dir, sizeof dir, ".");
  const int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  fsync(fd); /* best effort: the files themselves are already synced */
  close(fd);
}

/* ---- batches ------------------------------------------------------------------------ */

void wl_store_batch_init(struct wl_store_batch *b) { memset(b, 0, sizeof *b); }

static enum wl_status batch_add(struct wl_store_batch *b, const char *path, const char *tmp,
                                struct wl_error *err) {
  if (b->n >= WL_STORE_BATCH_MAX) {
    remove(tmp);
    return wl_error_set(err, WL_EIO, "%s: more than %d files in one batch", path,
                        WL_STORE_BATCH_MAX);
  }
  snprintf(b->path[b->n++], sizeof b->path[0], "%s", path);
  return WL_OK;
}

enum wl_status wl_store_batch_add(struct wl_store_batch *b, const char *path,
                                  struct wl_error *err) {
  char tmp[1040];
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  return batch_add(b, path, tmp, err);
}

enum wl_status wl_store_batch_commit(struct wl_store_batch *b, struct wl_error *err) {
  enum wl_status st = WL_OK;
  int i = 0;
  for (; i < b->n; i++) {
    char tmp[1040];
    snprintf(tmp, sizeof tmp, "%s.tmp", b->path[i]);
    if (rename(tmp, b->path[i]) != 0) {
      st = wl_error_set(err, WL_EIO, "%s: cannot move %s into place: %s", b->path[i], tmp,
                        strerror(errno));
      break;
    }
  }
  if (i > 0) wl_store_sync_dir_of(b->path[0]);
  for (; i < b->n; i++) { /* after a failed rename: the rest is dropped */
    char tmp[1040];
    snprintf(tmp, sizeof tmp, "%s.tmp", b->path[i]);
    remove(tmp);
  }
  b->n = 0;
  return st;
}

void wl_store_batch_abort(struct wl_store_batch *b) {
  for (int i = 0; i < b->n; i++) {
    char tmp[1040];
    snprintf(tmp, sizeof tmp, "%s.tmp", b->path[i]);
    remove(tmp);
  }
  b->n = 0;
}

/* ---- HDF5 files ------------------------------------------------------------------------ */

enum wl_status wl_store_open(const char *path, struct wl_store **out, struct wl_error *err) {
  wl_store_hdf5_init();
  *out = NULL;
  struct wl_store *s = calloc(1, sizeof *s);
  if (!s) return wl_error_set(err, WL_ENOMEM, "%s: no memory for the results file", path);
  snprintf(s->path, sizeof s->path, "%s", path);
  snprintf(s->tmp, sizeof s->tmp, "%s.tmp", path);
  /* the POSIX driver (its descriptor can be detached, see above), and a
   * close that closes every object of the file */
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl >= 0 && (H5Pset_fapl_sec2(fapl) < 0 || H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) < 0)) {
    H5Pclose(fapl);
    fapl = -1;
  }
  errno = 0;
  s->file = fapl >= 0 ? H5Fcreate(s->tmp, H5F_ACC_TRUNC, H5P_DEFAULT, fapl) : -1;
  const int e = errno;
  if (s->file < 0) {
    char why[256];
    h5_reason(why, sizeof why, e);
    if (fapl >= 0) H5Pclose(fapl);
    remove(s->tmp);
    free(s);
    return wl_error_set(err, WL_EIO, "%s: cannot create %s.tmp: %s", path, path, why);
  }
  H5Pclose(fapl);
  *out = s;
  return WL_OK;
}

enum wl_status wl_store_flush(struct wl_store *s, struct wl_error *err) {
  if (!s) return WL_OK;
  if (s->failed) return store_failed(s, err);
  errno = 0;
  if (H5Fflush(s->file, H5F_SCOPE_LOCAL) < 0)
    return store_fail(s, err, "writing it out failed", errno);
  return WL_OK;
}

/* Close the file: flushed first (a refused write is reported while the
 * file is intact), detached when anything failed, then closed; on
 * success its temporary file is synced. Returns WL_OK when the temporary
 * file is complete on disk; otherwise it is removed. Frees s. */
static enum wl_status store_finish(struct wl_store *s, struct wl_error *err) {
  enum wl_status st = WL_OK;
  if (s->failed) {
    st = store_failed(s, err);
  } else {
    errno = 0;
    if (H5Fflush(s->file, H5F_SCOPE_LOCAL) < 0)
      st = store_fail(s, err, "writing it out failed", errno);
  }
  if (s->failed) detach(s);
  errno = 0;
  if (H5Fclose(s->file) < 0 && st == WL_OK) {
    /* not expected after a good flush; HDF5's exit handler is off
     * (wl_store_hdf5_init), so what is left of the file cannot crash it */
    char why[256];
    h5_reason(why, sizeof why, errno);
    st = wl_error_set(err, WL_EIO, "%s: closing %s failed: %s", s->path, s->tmp, why);
  }
  if (st == WL_OK && sync_path(s->tmp) != 0)
    st = wl_error_set(err, WL_EIO, "%s: cannot sync %s to disk: %s", s->path, s->tmp,
                      strerror(errno));
  if (st != WL_OK) remove(s->tmp);
  return st;
}

enum wl_status wl_store_close(struct wl_store *s, int commit, struct wl_error *err) {
  if (!s) return WL_OK;
  if (!commit && !s->failed) s->failed = 1; /* discarded: nothing needs to reach the disk */
  const int discard = !commit;
  struct wl_error e2;
  wl_error_clear(&e2);
  enum wl_status st = store_finish(s, discard ? &e2 : err);
  if (discard) {
    free(s);
    return WL_OK;
  }
  if (st == WL_OK) {
    if (rename(s->tmp, s->path) != 0) {
      st = wl_error_set(err, WL_EIO, "%s: cannot move %s into place: %s", s->path, s->tmp,
                        strerror(errno));
      remove(s->tmp);
    } else {
      wl_store_sync_dir_of(s->path);
    }
  }
  free(s);
  return st;
}

enum wl_status wl_store_close_batch(struct wl_store *s, struct wl_store_batch *b,
                                    struct wl_error *err) {
  if (!s) return WL_OK;
  enum wl_status st = store_finish(s, err);
  if (st == WL_OK) st = batch_add(b, s->path, s->tmp, err);
  free(s);
  return st;
}

/* Link-creation property list that creates missing parent groups. */
static hid_t make_lcpl(void) {
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  if (lcpl >= 0 && H5Pset_create_intermediate_group(lcpl, 1) < 0) {
    H5Pclose(lcpl);
    lcpl = -1;
  }
  return lcpl;
}

/* Each writer below stops at its first failed HDF5 call, takes the reason
 * there (store_fail), and then closes every id it opened. */

static herr_t set_text_attr(hid_t obj, const char *name, const char *text) {
  hid_t type = H5Tcopy(H5T_C_S1);
  if (type < 0) return -1;
  herr_t rc = H5Tset_size(type, strlen(text) + 1);
  if (rc >= 0) rc = H5Tset_strpad(type, H5T_STR_NULLTERM);
  hid_t space = rc >= 0 ? H5Screate(H5S_SCALAR) : -1;
  if (space < 0) rc = -1;
  if (rc >= 0 && H5Aexists(obj, name) > 0) rc = H5Adelete(obj, name);
  hid_t attr = rc >= 0 ? H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT) : -1;
  if (attr < 0) rc = -1;
  if (rc >= 0) rc = H5Awrite(attr, type, text);
  /* the reason is taken by the caller: close without touching the stack */
  if (rc < 0) {
    H5E_BEGIN_TRY {
      if (attr >= 0) H5Aclose(attr);
      if (space >= 0) H5Sclose(space);
      H5Tclose(type);
    } H5E_END_TRY;
    return -1;
  }
  rc = H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  return rc;
}

static enum wl_status write_dataset(struct wl_store *s, const char *path, hid_t mem_type,
                                    const void *data, int rank, const hsize_t *dims,
                                    const char *unit, const char *description,
                                    struct wl_error *err) {
  if (s->failed) return store_failed(s, err);
  errno = 0;
  hid_t lcpl = make_lcpl();
  hid_t space = lcpl >= 0 ? H5Screate_simple(rank, dims, NULL) : -1;
  hid_t dset = space >= 0
                   ? H5Dcreate2(s->file, path, mem_type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT)
                   : -1;
  int ok = dset >= 0 && H5Dwrite(dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0;
  if (ok && unit) ok = set_text_attr(dset, "unit", unit) >= 0;
  if (ok && description) ok = set_text_attr(dset, "description", description) >= 0;
  enum wl_status st = WL_OK;
  if (!ok) {
    char why[256], msg[300];
    h5_reason(why, sizeof why, errno);
    snprintf(msg, sizeof msg, "cannot write dataset %s", path);
    if (dset < 0 && H5Lexists(s->file, path, H5P_DEFAULT) > 0)
      st = wl_error_set(err, WL_EIO, "%s: dataset %s exists already", s->path, path);
    else
      st = store_fail_why(s, err, msg, why);
  }
  H5E_BEGIN_TRY {
    if (dset >= 0 && H5Dclose(dset) < 0 && st == WL_OK)
      st = store_fail_obj(s, err, "dataset", path, NULL, errno);
    if (space >= 0) H5Sclose(space);
    if (lcpl >= 0) H5Pclose(lcpl);
  } H5E_END_TRY;
  return st;
}

enum wl_status wl_store_write_vector(struct wl_store *s, const char *path, const double *data,
                                     size_t n, const char *unit, const char *description,
                                     struct wl_error *err) {
  hsize_t dims[1] = {n};
  return write_dataset(s, path, H5T_NATIVE_DOUBLE, data, 1, dims, unit, description, err);
}

enum wl_status wl_store_write_matrix(struct wl_store *s, const char *path, const double *data,
                                     size_t rows, size_t cols, const char *unit,
                                     const char *description, struct wl_error *err) {
  hsize_t dims[2] = {rows, cols};
  return write_dataset(s, path, H5T_NATIVE_DOUBLE, data, 2, dims, unit, description, err);
}

enum wl_status wl_store_write_vector_f(struct wl_store *s, const char *path, const float *data,
                                       size_t n, const char *unit, const char *description,
                                       struct wl_error *err) {
  hsize_t dims[1] = {n};
  return write_dataset(s, path, H5T_NATIVE_FLOAT, data, 1, dims, unit, description, err);
}

enum wl_status wl_store_write_matrix_f(struct wl_store *s, const char *path, const float *data,
                                       size_t rows, size_t cols, const char *unit,
                                       const char *description, struct wl_error *err) {
  hsize_t dims[2] = {rows, cols};
  return write_dataset(s, path, H5T_NATIVE_FLOAT, data, 2, dims, unit, description, err);
}

enum wl_status wl_store_write_vector_i(struct wl_store *s, const char *path, const int *data,
                                       size_t n, const char *description, struct wl_error *err) {
  hsize_t dims[1] = {n};
  return write_dataset(s, path, H5T_NATIVE_INT, data, 1, dims, NULL, description, err);
}

/* Open the object at path, creating a group there if nothing exists. */
static hid_t open_or_create(struct wl_store *s, const char *path) {
  if (!path[0] || !strcmp(path, "/")) return H5Oopen(s->file, "/", H5P_DEFAULT);
  if (H5Lexists(s->file, path, H5P_DEFAULT) > 0) return H5Oopen(s->file, path, H5P_DEFAULT);
  hid_t lcpl = make_lcpl();
  if (lcpl < 0) return -1;
  hid_t g = H5Gcreate2(s->file, path, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  if (g < 0) { /* keep the stack for the caller */
    H5E_BEGIN_TRY { H5Pclose(lcpl); } H5E_END_TRY;
    return -1;
  }
  H5Pclose(lcpl);
  return g;
}

/* Close an object a writer opened; a failure is the writer's failure. */
static enum wl_status close_obj(struct wl_store *s, hid_t obj, enum wl_status st,
                                const char *what, const char *path, struct wl_error *err) {
  if (obj < 0) return st;
  if (st != WL_OK) {
    H5E_BEGIN_TRY { H5Oclose(obj); } H5E_END_TRY;
    return st;
  }
  errno = 0;
  if (H5Oclose(obj) < 0) return store_fail_obj(s, err, "attribute", what, path, errno);
  return st;
}

enum wl_status wl_store_attr_text(struct wl_store *s, const char *path, const char *name,
                                  const char *text, struct wl_error *err) {
  if (s->failed) return store_failed(s, err);
  errno = 0;
  hid_t obj = open_or_create(s, path);
  enum wl_status st = WL_OK;
  if (obj < 0 || set_text_attr(obj, name, text) < 0) {
    st = store_fail_obj(s, err, "attribute", name, path, errno);
  }
  return close_obj(s, obj, st, name, path, err);
}

enum wl_status wl_store_attr_double(struct wl_store *s, const char *path, const char *name,
                                    double value, const char *unit, struct wl_error *err) {
  if (s->failed) return store_failed(s, err);
  errno = 0;
  hid_t obj = open_or_create(s, path);
  int ok = obj >= 0;
  if (ok) {
    hid_t space = H5Screate(H5S_SCALAR);
    ok = space >= 0;
    if (ok && H5Aexists(obj, name) > 0) ok = H5Adelete(obj, name) >= 0;
    hid_t attr = ok ? H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT)
                    : -1;
    ok = attr >= 0 && H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) >= 0;
    if (!ok) {
      H5E_BEGIN_TRY {
        if (attr >= 0) H5Aclose(attr);
        if (space >= 0) H5Sclose(space);
      } H5E_END_TRY;
    } else {
      ok = H5Aclose(attr) >= 0;
      H5Sclose(space);
    }
    if (ok && unit) {
      char uname[128];
      snprintf(uname, sizeof uname, "%s_unit", name);
      ok = set_text_attr(obj, uname, unit) >= 0;
    }
  }
  enum wl_status st = WL_OK;
  if (!ok) {
    st = store_fail_obj(s, err, "attribute", name, path, errno);
  }
  return close_obj(s, obj, st, name, path, err);
}

/* ---- text files ------------------------------------------------------------------------ */

/* Write text to tmp with every write, the fsync and the close checked.
 * Returns 0, or -1 with errno set (tmp removed). */
static int write_tmp(const char *tmp, const char *text, size_t len) {
  const int fd = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) return -1;
  int e = 0;
  for (size_t done = 0; done < len && !e;) {
    ssize_t w = write(fd, text + done, len - done);
    if (w > 0)
      done += (size_t)w;
    else if (w < 0 && errno == EINTR)
      continue;
    else
      e = w < 0 ? errno : EIO;
  }
  if (!e && fsync(fd) != 0 && errno != EINVAL && errno != EROFS) e = errno;
  if (close(fd) != 0 && !e && errno != EINTR) e = errno;
  if (e) {
    remove(tmp);
    errno = e;
    return -1;
  }
  return 0;
}

static enum wl_status write_text(const char *path, const char *text, size_t len,
                                 struct wl_store_batch *b, struct wl_error *err) {
  char tmp[1040];
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  if (write_tmp(tmp, text, len) != 0)
    return wl_error_set(err, WL_EIO, "%s: cannot write %s: %s", path, tmp, strerror(errno));
  if (b) return batch_add(b, path, tmp, err);
  if (rename(tmp, path) != 0) {
    const int e = errno;
    remove(tmp);
    return wl_error_set(err, WL_EIO, "%s: cannot move %s into place: %s", path, tmp, strerror(e));
  }
  wl_store_sync_dir_of(path);
  return WL_OK;
}

enum wl_status wl_store_write_text_batch(const char *path, const char *text, size_t len,
                                         struct wl_store_batch *b, struct wl_error *err) {
  return write_text(path, text, len, b, err);
}

enum wl_status wl_store_write_text(const char *path, const char *text, size_t len,
                                   struct wl_error *err) {
  return write_text(path, text, len, NULL, err);
}

enum wl_status wl_store_write_xdmf(const char *xmf_path, const char *h5_name,
                                   const struct wl_snapshot_ref *snaps, size_t n_snaps,
                                   struct wl_error *err) {
  return wl_store_write_xdmf_batch(xmf_path, h5_name, snaps, n_snaps, NULL, err);
}

enum wl_status wl_store_write_xdmf_batch(const char *xmf_path, const char *h5_name,
                                         const struct wl_snapshot_ref *snaps, size_t n_snaps,
                                         struct wl_store_batch *b, struct wl_error *err) {
  size_t cap = 1024 + n_snaps * (2048 + 6 * strlen(h5_name)), len = 0;
  char *buf = malloc(cap);
  if (!buf) return wl_error_set(err, WL_ENOMEM, "%s: no memory for the XDMF index", xmf_path);
#define PUT(...) len += (size_t)snprintf(buf + len, cap - len, __VA_ARGS__)
  PUT("<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n");
  for (size_t i = 0; i < n_snaps; i++) {
    const struct wl_snapshot_ref *r = &snaps[i];
    PUT("   <Grid Name=\"t%zu\" GridType=\"Uniform\">\n    <Time Value=\"%.9g\"/>\n", i, r->time);
    PUT("    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%zu\"/>\n", r->n);
    PUT("    <Geometry GeometryType=\"XYZ\"><DataItem Dimensions=\"%zu 3\" NumberType=\"Float\" "
        "Precision=\"8\" Format=\"HDF\">%s:%s/position</DataItem></Geometry>\n",
        r->n, h5_name, r->group);
    PUT("    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\"><DataItem "
        "Dimensions=\"%zu 3\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">%s:%s/velocity"
        "</DataItem></Attribute>\n",
        r->n, h5_name, r->group);
    static const char *const scalars[] = {"rho", "p", "dp"};
    for (int k = 0; k < 3; k++)
      PUT("    <Attribute Name=\"%s\" AttributeType=\"Scalar\" Center=\"Node\"><DataItem "
          "Dimensions=\"%zu\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">%s:%s/%s"
          "</DataItem></Attribute>\n",
          scalars[k], r->n, h5_name, r->group, scalars[k]);
    PUT("    <Attribute Name=\"kind\" AttributeType=\"Scalar\" Center=\"Node\"><DataItem "
        "Dimensions=\"%zu\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">%s:%s/kind"
        "</DataItem></Attribute>\n   </Grid>\n",
        r->n, h5_name, r->group);
  }
  PUT("  </Grid>\n </Domain>\n</Xdmf>\n");
#undef PUT
  enum wl_status st = write_text(xmf_path, buf, len, b, err);
  free(buf);
  return st;
}

void wl_text_put(struct wl_text *t, const char *fmt, ...) {
  if (t->failed) return;
  for (;;) {
    va_list ap;
    va_start(ap, fmt);
    const int n = vsnprintf(t->s ? t->s + t->len : NULL, t->s ? t->cap - t->len : 0, fmt, ap);
    va_end(ap);
    if (n < 0) {
      t->failed = 1;
      return;
    }
    if (t->s && t->len + (size_t)n < t->cap) {
      t->len += (size_t)n;
      return;
    }
    size_t cap = t->cap ? t->cap : 8192;
    while (cap <= t->len + (size_t)n) cap *= 2;
    char *b = realloc(t->s, cap);
    if (!b) {
      t->failed = 1;
      return;
    }
    t->s = b;
    t->cap = cap;
  }
}
