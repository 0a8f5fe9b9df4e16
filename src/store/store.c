/* store.c: HDF5 results and text files, written atomically. */
#include "wallload/store.h"

#include <errno.h>
#include <hdf5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct wl_store {
  hid_t file;
  char path[1024];
  char tmp[1040];
};

/* HDF5 prints its error stack by default; wallload reports its own. */
static void quiet_hdf5(void) { H5Eset_auto2(H5E_DEFAULT, NULL, NULL); }

/* Why a file could not be created: HDF5 sets errno from the failing system
 * call, which names the real reason (no such directory, permission). */
static const char *io_reason(void) { return errno ? strerror(errno) : "HDF5 error"; }

enum wl_status wl_store_open(const char *path, struct wl_store **out, struct wl_error *err) {
  quiet_hdf5();
  *out = NULL;
  struct wl_store *s = calloc(1, sizeof *s);
  if (!s) return wl_error_set(err, WL_ENOMEM, "%s: no memory for the results file", path);
  snprintf(s->path, sizeof s->path, "%s", path);
  snprintf(s->tmp, sizeof s->tmp, "%s.tmp", path);
  errno = 0;
  s->file = H5Fcreate(s->tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (s->file < 0) {
    const char *why = io_reason();
    free(s);
    return wl_error_set(err, WL_EIO, "%s.tmp: cannot create the results file (%s)", path, why);
  }
  *out = s;
  return WL_OK;
}

enum wl_status wl_store_close(struct wl_store *s, int commit, struct wl_error *err) {
  if (!s) return WL_OK;
  enum wl_status st = WL_OK;
  if (H5Fclose(s->file) < 0) {
    st = wl_error_set(err, WL_EIO, "%s: closing the results file failed", s->tmp);
    commit = 0;
  }
  if (commit) {
    if (rename(s->tmp, s->path) != 0)
      st = wl_error_set(err, WL_EIO, "%s: cannot rename %s to it", s->path, s->tmp);
  } else {
    remove(s->tmp);
  }
  free(s);
  return st;
}

/* Link-creation property list that creates missing parent groups. */
static hid_t make_lcpl(void) {
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  if (lcpl >= 0) H5Pset_create_intermediate_group(lcpl, 1);
  return lcpl;
}

static herr_t set_text_attr(hid_t obj, const char *name, const char *text) {
  hid_t type = H5Tcopy(H5T_C_S1);
  if (type < 0) return -1;
  H5Tset_size(type, strlen(text) + 1);
  H5Tset_strpad(type, H5T_STR_NULLTERM);
  hid_t space = H5Screate(H5S_SCALAR);
  if (H5Aexists(obj, name) > 0) H5Adelete(obj, name);
  hid_t attr = H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  herr_t rc = attr >= 0 ? H5Awrite(attr, type, text) : -1;
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  return rc;
}

static enum wl_status write_dataset(struct wl_store *s, const char *path, hid_t mem_type,
                                    const void *data, int rank, const hsize_t *dims,
                                    const char *unit, const char *description,
                                    struct wl_error *err) {
  hid_t lcpl = make_lcpl();
  hid_t space = H5Screate_simple(rank, dims, NULL);
  hid_t dset = space >= 0 && lcpl >= 0
                   ? H5Dcreate2(s->file, path, mem_type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT)
                   : -1;
  int ok = dset >= 0 && H5Dwrite(dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0;
  if (ok && unit) ok = set_text_attr(dset, "unit", unit) >= 0;
  if (ok && description) ok = set_text_attr(dset, "description", description) >= 0;
  if (dset >= 0) H5Dclose(dset);
  if (space >= 0) H5Sclose(space);
  if (lcpl >= 0) H5Pclose(lcpl);
  if (!ok)
    return wl_error_set(err, WL_EIO, "%s: cannot write dataset %s (exists already, or disk full?)",
                        s->tmp, path);
  return WL_OK;
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
  hid_t g = H5Gcreate2(s->file, path, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  return g;
}

enum wl_status wl_store_attr_text(struct wl_store *s, const char *path, const char *name,
                                  const char *text, struct wl_error *err) {
  hid_t obj = open_or_create(s, path);
  int ok = obj >= 0 && set_text_attr(obj, name, text) >= 0;
  if (obj >= 0) H5Oclose(obj);
  return ok ? WL_OK
            : wl_error_set(err, WL_EIO, "%s: cannot write attribute %s of %s", s->tmp, name, path);
}

enum wl_status wl_store_attr_double(struct wl_store *s, const char *path, const char *name,
                                    double value, const char *unit, struct wl_error *err) {
  hid_t obj = open_or_create(s, path);
  int ok = obj >= 0;
  if (ok) {
    hid_t space = H5Screate(H5S_SCALAR);
    if (H5Aexists(obj, name) > 0) H5Adelete(obj, name);
    hid_t attr = H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
    ok = attr >= 0 && H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) >= 0;
    if (attr >= 0) H5Aclose(attr);
    H5Sclose(space);
    if (ok && unit) {
      char uname[128];
      snprintf(uname, sizeof uname, "%s_unit", name);
      ok = set_text_attr(obj, uname, unit) >= 0;
    }
    H5Oclose(obj);
  }
  return ok ? WL_OK
            : wl_error_set(err, WL_EIO, "%s: cannot write attribute %s of %s", s->tmp, name, path);
}

enum wl_status wl_store_write_text(const char *path, const char *text, size_t len,
                                   struct wl_error *err) {
  char tmp[1040];
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  FILE *f = fopen(tmp, "wb");
  if (!f) return wl_error_set(err, WL_EIO, "%s: cannot create the file", tmp);
  int ok = fwrite(text, 1, len, f) == len;
  ok = (fclose(f) == 0) && ok;
  if (!ok) {
    remove(tmp);
    return wl_error_set(err, WL_EIO, "%s: write failed (disk full?)", tmp);
  }
  if (rename(tmp, path) != 0) {
    remove(tmp);
    return wl_error_set(err, WL_EIO, "%s: cannot rename %s to it", path, tmp);
  }
  return WL_OK;
}

enum wl_status wl_store_write_xdmf(const char *xmf_path, const char *h5_name,
                                   const struct wl_snapshot_ref *snaps, size_t n_snaps,
                                   struct wl_error *err) {
  size_t cap = 1024 + n_snaps * 2048, len = 0;
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
    static const char *const scalars[] = {"rho", "p"};
    for (int k = 0; k < 2; k++)
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
  enum wl_status st = wl_store_write_text(xmf_path, buf, len, err);
  free(buf);
  return st;
}
