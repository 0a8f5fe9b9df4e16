/* store.h: results on disk, written so that nothing half-written is ever
 * left under the final name.
 *
 * Every file is written to "<path>.tmp" and renamed over <path> only when it
 * is complete (rename is atomic on POSIX file systems), so a crash, an
 * interruption or an unstable run leaves either the previous file or the new
 * complete one. HDF5 files hold datasets with a "unit" and a "description"
 * attribute each; particle snapshots come with an XDMF index that ParaView
 * opens (2D runs are written as (x, 0, z)). */
#ifndef WALLLOAD_STORE_H
#define WALLLOAD_STORE_H

#include <stddef.h>

#include "wallload/error.h"

struct wl_store; /* an HDF5 file being written; opaque */

/* Create "<path>.tmp" for writing. Returns WL_OK and *out; WL_EIO (message
 * names the file and HDF5's reason). */
enum wl_status wl_store_open(const char *path, struct wl_store **out, struct wl_error *err);

/* Finish: close the file and, when `commit` is 1, rename it to its final
 * name; with commit 0 the temporary file is removed. Safe on NULL. Returns
 * WL_OK or WL_EIO. Always frees *store. */
enum wl_status wl_store_close(struct wl_store *store, int commit, struct wl_error *err);

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

/* Write `text` to `path` atomically (temp file + rename); for JSON and CSV. */
enum wl_status wl_store_write_text(const char *path, const char *text, size_t len,
                                   struct wl_error *err);

#endif
