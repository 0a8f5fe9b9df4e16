/* cuda_device.h: what GPU (if any) this build and this machine offer. The
 * CUDA backend's own step lives in src/backend_cuda/; this is the part every
 * build has, so `--backend auto` and GPU tests can ask "is there a GPU?"
 * whether or not wallload was built with CUDA. */
#ifndef WALLLOAD_CUDA_DEVICE_H
#define WALLLOAD_CUDA_DEVICE_H

#include <stddef.h>

#include "wallload/error.h"

struct wl_cuda_device {
  int index;             /* device number */
  char name[128];        /* e.g. "NVIDIA H100 80GB HBM3" */
  size_t memory_total;   /* [bytes] */
  size_t memory_free;    /* [bytes] at the time of the query */
  int sm_major, sm_minor;/* compute capability */
  int n_sm;              /* multiprocessors */
};

/* 1 if this binary was built with the CUDA backend, else 0. */
int wl_cuda_built(void);

/* Describe the first usable GPU. Returns WL_OK and fills *dev;
 * WL_EUNSUPPORTED when built without CUDA ("built without CUDA") or when no
 * GPU is present (the CUDA runtime's reason in the message). */
enum wl_status wl_cuda_device_query(struct wl_cuda_device *dev, struct wl_error *err);

/* The GPU's wl_sph_sqrt and wl_sph_rcp (sph/defs.h) against its correctly
 * rounded sqrtf and 1/x, on every float of their stated ranges (sqrt: from
 * 2^-100 to the largest finite float; reciprocal: every normal float of
 * magnitude below 2^126, both signs): *n_sqrt and *n_rcp get the numbers
 * of floats tried, *bad_sqrt and *bad_rcp those whose bits differ.
 * WL_EUNSUPPORTED without CUDA or a GPU. A few tenths of a second. */
enum wl_status wl_cuda_math_check(unsigned long long *n_sqrt, unsigned long long *bad_sqrt,
                                  unsigned long long *n_rcp, unsigned long long *bad_rcp,
                                  struct wl_error *err);

#endif
