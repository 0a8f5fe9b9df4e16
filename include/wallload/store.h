/* store.h: results on disk, written so that nothing half-written is ever
 * left under the final name.
 *
 * Every file is written to "<path>.tmp" and renamed over <path> only when it
 * is complete (rename is atomic on POSIX file systems), so a crash, an
 * interruption or an unstable run leaves either the previous file or the new
 * complete one. Each file is synced to disk before the rename (and the
 * directory after it). A write the system refuses (a full disk, a file-size
 * limit, an I/O error) is WL_EIO with the final file's name and the
 * system's reason ("No space left on device"); the temporary file is then
 * removed and the previous file under the final name, if any, is kept.
 * Closing a file after a failed write cannot fail or crash (store.c says
 * how). HDF5 files hold datasets with a "unit" and a "description"
 * attribute each; particle snapshots come with an XDMF index that ParaView
 * opens (2D runs are written as (x, 0, z)). */
#ifndef WALLLOAD_STORE_H
#define WALLLOAD_STORE_H

#include <stddef.h>

#include "wallload/error.h"

struct wl_store; /* an HDF5 file being written; opaque */

/* HDF5 as wallload uses it: the library's own error printing off (every
 * status is checked and reported with the file), and no exit handler (a
 * file the library failed to close can then never crash the exit). Called
 * by wl_store_open; readers of HDF5 files call it before their first
 * HDF5 call. Idempotent. */
void wl_store_hdf5_init(void);

/* fsync the directory holding path, so that a rename in it reaches the
 * disk (best effort: the files themselves are synced before). */
void wl_store_sync_dir_of(const char *path);

/* Files written to their temporary names and moved into place together,
 * only when all of them were written: a failure on any one leaves every
 * previous file as it was. */
enum { WL_STORE_BATCH_MAX = 16 };
struct wl_store_batch {
  int n;
  char path[WL_STORE_BATCH_MAX][1024]; /* final names; each written as path.tmp */
};
void wl_store_batch_init(struct wl_store_batch *b);
/* Add path (its path.tmp written complete earlier, e.g. by a batch that
 * was not committed) to b. WL_EIO (and path.tmp removed) when b is full. */
enum wl_status wl_store_batch_add(struct wl_store_batch *b, const char *path,
                                  struct wl_error *err);
/* Rename every file of the batch into place (in the order added) and sync
 * the directory. WL_EIO when a rename fails (the files after it are
 * dropped). The batch is empty afterwards. */
enum wl_status wl_store_batch_commit(struct wl_store_batch *b, struct wl_error *err);
/* Remove every temporary file of the batch. */
void wl_store_batch_abort(struct wl_store_batch *b);

/* Create "<path>.tmp" for writing. Returns WL_OK and *out; WL_EIO (message
 * names the file and HDF5's reason). */
enum wl_status wl_store_open(const char *path, struct wl_store **out, struct wl_error *err);

/* Finish: close the file and, when `commit` is 1 and every write to it
 * succeeded, sync it and rename it to its final name; otherwise the
 * temporary file is removed (commit 0 returns WL_OK). Safe on NULL.
 * Returns WL_OK or WL_EIO. Always frees *store. */
enum wl_status wl_store_close(struct wl_store *store, int commit, struct wl_error *err);

/* Close a complete file into a batch (moved into place by
 * wl_store_batch_commit). On a failure (this close, or an earlier write)
 * the temporary file is removed and WL_EIO returned. Frees *store. */
enum wl_status wl_store_close_batch(struct wl_store *store, struct wl_store_batch *b,
                                    struct wl_error *err);

/* Push what is written so far to the file, so that a full disk is found
 * now rather than at the close (snapshots are flushed one by one). WL_EIO
 * names the file and the reason; the store is then failed (closing it
 * discards it). */
enum wl_status wl_store_flush(struct wl_store *store, struct wl_error *err);

/* Write a 1D double dataset `path` (groups created as needed, e.g.
 * "cases/solitary/gauges/G1/eta") with attributes unit and description. */
enum wl_status wl_store_write_vector(struct wl_store *store, const char *path, const double *data,
                                     size_t n, const char *unit, const char *description,
                                     struct wl_error *err);

/* Write a 2D row-major double dataset [rows x cols] (e.g. time x probe). */
enum wl_status wl_store_write_matrix(struct wl_store *store, const char *path, const double *data,
                                     size_t rows, size_t cols, const char *unit,
                                     const char *description, struct wl_error *err);

/* Write a 1D float dataset (particle fields). */
enum wl_status wl_store_write_vector_f(struct wl_store *store, const char *path, const float *data,
                                       size_t n, const char *unit, const char *description,
                                       struct wl_error *err);

/* Write a 2D row-major float dataset [rows x cols] (particle vectors). */
enum wl_status wl_store_write_matrix_f(struct wl_store *store, const char *path, const float *data,
                                       size_t rows, size_t cols, const char *unit,
                                       const char *description, struct wl_error *err);

/* Write a 1D int dataset (particle kinds, ids). */
enum wl_status wl_store_write_vector_i(struct wl_store *store, const char *path, const int *data,
                                       size_t n, const char *description, struct wl_error *err);

/* Attach a text attribute `name` to the object (group or dataset) at
 * `path`, creating the group if it does not exist ("" or "/" is the root). */
enum wl_status wl_store_attr_text(struct wl_store *store, const char *path, const char *name,
                                  const char *text, struct wl_error *err);

/* Attach a double attribute with a unit ("<name>" and "<name>_unit"). */
enum wl_status wl_store_attr_double(struct wl_store *store, const char *path, const char *name,
                                    double value, const char *unit, struct wl_error *err);

/* One particle snapshot for the XDMF index. */
struct wl_snapshot_ref {
  double time;   /* [s] */
  size_t n;      /* particles */
  char group[96];/* HDF5 group holding position (n x 3), velocity (n x 3), rho, p, kind */
};

/* Write the XDMF index `xmf_path` (atomically) that refers to the snapshot
 * groups in `h5_name` (a file name relative to the XDMF file). */
enum wl_status wl_store_write_xdmf(const char *xmf_path, const char *h5_name,
                                   const struct wl_snapshot_ref *snaps, size_t n_snaps,
                                   struct wl_error *err);

/* wl_store_write_xdmf into batch b (written to xmf_path.tmp, moved at the
 * batch's commit). */
enum wl_status wl_store_write_xdmf_batch(const char *xmf_path, const char *h5_name,
                                         const struct wl_snapshot_ref *snaps, size_t n_snaps,
                                         struct wl_store_batch *b, struct wl_error *err);

/* A growing text buffer for the text files written below (CSV, JSON):
 * wl_text_put appends printf-style; when an allocation fails, `failed` is
 * set and later puts do nothing (the writer then reports WL_ENOMEM).
 * Zero-initialise; the caller frees s. */
struct wl_text {
  char *s;
  size_t len, cap;
  int failed;
};
void wl_text_put(struct wl_text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Write `text` to `path` atomically (temp file + fsync + rename); for JSON
 * and CSV. */
enum wl_status wl_store_write_text(const char *path, const char *text, size_t len,
                                   struct wl_error *err);

/* Write `text` to path.tmp (synced) and add it to batch b. */
enum wl_status wl_store_write_text_batch(const char *path, const char *text, size_t len,
                                         struct wl_store_batch *b, struct wl_error *err);

#endif
