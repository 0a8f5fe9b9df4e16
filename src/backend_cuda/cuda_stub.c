/* cuda_stub.c: wl_backend_cuda_ops in a build without CUDA, so that every
 * build links the same symbols; init answers WL_EUNSUPPORTED. */
#include <stdio.h>

#include "wallload/backend.h"
#include "wallload/config.h"

#if !WL_HAVE_CUDA
static enum wl_status stub_init(void **ctx, const struct wl_sph_config *cfg,
                                const struct wl_sph_const *k, const struct wl_particles *host,
                                struct wl_sph_step_out *out, struct wl_error *err) {
  (void)cfg;
  (void)k;
  (void)host;
  (void)out;
  *ctx = NULL;
  return wl_error_set(err, WL_EUNSUPPORTED,
                      "cuda backend: this wallload was built without CUDA (no nvcc found at "
                      "configure time; rebuild with nvcc on the PATH or -DWL_CUDA=ON)");
}

static enum wl_status stub_step(void *ctx, const struct wl_sph_step_in *in,
                                struct wl_sph_step_out *out, struct wl_error *err) {
  (void)ctx;
  (void)in;
  (void)out;
  return wl_error_set(err, WL_EUNSUPPORTED, "cuda backend: built without CUDA");
}

static enum wl_status stub_download(void *ctx, struct wl_particles *host, struct wl_error *err) {
  (void)ctx;
  (void)host;
  return wl_error_set(err, WL_EUNSUPPORTED, "cuda backend: built without CUDA");
}

static void stub_describe(void *ctx, char *buf, size_t size) {
  (void)ctx;
  snprintf(buf, size, "cuda (not built)");
}

static void stub_free(void *ctx) { (void)ctx; }

const struct wl_backend_ops wl_backend_cuda_ops = {
    .name = "cuda",
    .init = stub_init,
    .step = stub_step,
    .download = stub_download,
    .describe = stub_describe,
    .free = stub_free,
};
#endif
