/* device_stub.c: the answer of a build without CUDA. */
#include "wallload/config.h"
#include "wallload/cuda_device.h"

#if !WL_HAVE_CUDA
int wl_cuda_built(void) { return 0; }

enum wl_status wl_cuda_device_query(struct wl_cuda_device *dev, struct wl_error *err) {
  (void)dev;
  return wl_error_set(err, WL_EUNSUPPORTED,
                      "CUDA backend: this wallload was built without CUDA (no nvcc found at "
                      "configure time; rebuild with nvcc on the PATH or -DWL_CUDA=ON)");
}

enum wl_status wl_cuda_math_check(unsigned long long *n_sqrt, unsigned long long *bad_sqrt,
                                  unsigned long long *n_rcp, unsigned long long *bad_rcp,
                                  struct wl_error *err) {
  *n_sqrt = *bad_sqrt = *n_rcp = *bad_rcp = 0;
  return wl_error_set(err, WL_EUNSUPPORTED, "CUDA backend: this wallload was built without CUDA");
}
#endif
