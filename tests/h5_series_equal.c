/* h5_series_equal: the sweep tests' bit-for-bit comparison of two results
 * files (a helper, not a test: tests/cli_sweep_run.sh runs it).
 *
 * usage: h5_series_equal A.h5 B.h5 DATASET...
 * Reads each DATASET (doubles) from both files and compares the bytes:
 * prints one PASS or FAIL line per dataset; exit 0 when all are equal, 1
 * when one differs or cannot be read.
 *
 * usage: h5_series_equal --print FILE.h5 DATASET
 * Prints the dataset's doubles one a line (%.17g) for a test script to
 * compare with another output; exit 1 when it cannot be read (absent). */
#include <hdf5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The dataset's doubles (malloc'ed) and their count; NULL when unreadable. */
static double *read_all(const char *file, const char *name, size_t *n) {
  double *v = NULL;
  *n = 0;
  hid_t f = H5Fopen(file, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return NULL;
  hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
  if (d >= 0) {
    hid_t sp = H5Dget_space(d);
    hssize_t m = H5Sget_simple_extent_npoints(sp);
    if (m > 0 && (v = malloc((size_t)m * sizeof *v)) != NULL) {
      if (H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0) {
        free(v);
        v = NULL;
      } else {
        *n = (size_t)m;
      }
    }
    H5Sclose(sp);
    H5Dclose(d);
  }
  H5Fclose(f);
  return v;
}

int main(int argc, char **argv) {
  if (argc < 4) {
    fprintf(stderr, "usage: h5_series_equal A.h5 B.h5 DATASET...\n"
                    "       h5_series_equal --print FILE.h5 DATASET\n");
    return 2;
  }
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  if (strcmp(argv[1], "--print") == 0) {
    size_t n;
    double *v = read_all(argv[2], argv[3], &n);
    if (!v) return 1;
    for (size_t i = 0; i < n; i++) printf("%.17g\n", v[i]);
    free(v);
    return 0;
  }
  int fail = 0;
  for (int k = 3; k < argc; k++) {
    size_t na, nb;
    double *a = read_all(argv[1], argv[k], &na), *b = read_all(argv[2], argv[k], &nb);
    if (!a || !b) {
      printf("FAIL %s: cannot read it from %s\n", argv[k], !a ? argv[1] : argv[2]);
      fail++;
    } else if (na != nb || memcmp(a, b, na * sizeof *a) != 0) {
      printf("FAIL %s: %zu and %zu values, not the same bits\n", argv[k], na, nb);
      fail++;
    } else {
      printf("PASS %s: %zu values, the same bits\n", argv[k], na);
    }
    free(a);
    free(b);
  }
  return fail ? 1 : 0;
}
