/* device.cu: GPU discovery through the CUDA runtime; every call checked. */
#include <cuda_runtime.h>
#include <string.h>

extern "C" {
#include "wallload/config.h"
#include "wallload/cuda_device.h"
}

extern "C" int wl_cuda_built(void) { return 1; }

extern "C" enum wl_status wl_cuda_device_query(struct wl_cuda_device *dev, struct wl_error *err) {
  int n = 0;
  cudaError_t e = cudaGetDeviceCount(&n);
  if (e != cudaSuccess || n == 0)
    return wl_error_set(err, WL_EUNSUPPORTED, "CUDA backend: no usable GPU (%s)",
                        e != cudaSuccess ? cudaGetErrorString(e) : "no devices");
  cudaDeviceProp prop;
  if ((e = cudaGetDeviceProperties(&prop, 0)) != cudaSuccess)
    return wl_error_set(err, WL_EUNSUPPORTED, "CUDA backend: cudaGetDeviceProperties: %s",
                        cudaGetErrorString(e));
  if ((e = cudaSetDevice(0)) != cudaSuccess)
    return wl_error_set(err, WL_EUNSUPPORTED, "CUDA backend: cudaSetDevice: %s",
                        cudaGetErrorString(e));
  size_t free_b = 0, total_b = 0;
  if ((e = cudaMemGetInfo(&free_b, &total_b)) != cudaSuccess)
    return wl_error_set(err, WL_EUNSUPPORTED, "CUDA backend: cudaMemGetInfo: %s",
                        cudaGetErrorString(e));
  memset(dev, 0, sizeof *dev);
  dev->index = 0;
  strncpy(dev->name, prop.name, sizeof dev->name - 1);
  dev->memory_total = total_b;
  dev->memory_free = free_b;
  dev->sm_major = prop.major;
  dev->sm_minor = prop.minor;
  dev->n_sm = prop.multiProcessorCount;
  return WL_OK;
}
