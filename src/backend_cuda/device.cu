/* device.cu: GPU discovery through the CUDA runtime, and the check of the
 * GPU's square root and reciprocal; every call checked. */
#include <cuda_runtime.h>
#include <string.h>

extern "C" {
#include "wallload/config.h"
#include "wallload/cuda_device.h"
#include "wallload/sph/defs.h"
}

/* wl_cuda_math_check's reference is nvcc's correctly rounded sqrtf and 1/x:
 * meaningless under fast-math, which the project never builds with. */
#if defined(__USE_FAST_MATH__)
#error "device.cu must not be built with --use_fast_math (wl_cuda_math_check's reference)"
#endif

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

/* Bit patterns [lo, hi] (as float): wl_sph_sqrt against sqrtf (what ==
 * 0) or wl_sph_rcp against 1/x (what == 1); mismatches into *bad. Both
 * sides are compiled here under nvcc's default correctly rounded division
 * and square root (no fast-math in the build). */
__global__ void k_math_check(unsigned int lo, unsigned int hi, int what,
                             unsigned long long *bad) {
  unsigned int n = 0;
  const unsigned int stride = gridDim.x * blockDim.x;
  for (unsigned int u = lo + blockIdx.x * blockDim.x + threadIdx.x; u <= hi && u >= lo;
       u += stride) {
    const float x = __uint_as_float(u);
    const float got = what ? wl_sph_rcp(x) : wl_sph_sqrt(x);
    const float want = what ? 1.0f / x : sqrtf(x);
    n += __float_as_uint(got) != __float_as_uint(want);
  }
  if (n) atomicAdd(bad, (unsigned long long)n);
}

extern "C" enum wl_status wl_cuda_math_check(unsigned long long *n_sqrt,
                                             unsigned long long *bad_sqrt,
                                             unsigned long long *n_rcp,
                                             unsigned long long *bad_rcp, struct wl_error *err) {
  /* float bit patterns: sqrt from 2^-100 (0x0d800000) to FLT_MAX; 1/x over
   * the normal floats below 2^126 (exponent fields 1..252), both signs */
  const unsigned int sq_lo = 0x0d800000u, sq_hi = 0x7f7fffffu;
  const unsigned int rc_lo = 0x00800000u, rc_hi = 0x7e7fffffu;
  *n_sqrt = *bad_sqrt = *n_rcp = *bad_rcp = 0;
  struct wl_cuda_device dev;
  enum wl_status st = wl_cuda_device_query(&dev, err);
  if (st != WL_OK) return st;
  unsigned long long *d = NULL, h[4] = {0, 0, 0, 0};
  cudaError_t e = cudaMalloc(&d, sizeof h);
  if (e == cudaSuccess) e = cudaMemset(d, 0, sizeof h);
  if (e == cudaSuccess) {
    const int blocks = 8 * dev.n_sm, threads = 256;
    k_math_check<<<blocks, threads>>>(sq_lo, sq_hi, 0, d);
    k_math_check<<<blocks, threads>>>(rc_lo, rc_hi, 1, d + 1);
    k_math_check<<<blocks, threads>>>(rc_lo | 0x80000000u, rc_hi | 0x80000000u, 1, d + 2);
    e = cudaGetLastError();
  }
  if (e == cudaSuccess) e = cudaMemcpy(h, d, sizeof h, cudaMemcpyDeviceToHost);
  if (d) cudaFree(d);
  if (e != cudaSuccess)
    return wl_error_set(err, WL_EUNSUPPORTED, "CUDA math check: %s", cudaGetErrorString(e));
  *n_sqrt = sq_hi - sq_lo + 1ull;
  *bad_sqrt = h[0];
  *n_rcp = 2ull * (rc_hi - rc_lo + 1ull);
  *bad_rcp = h[1] + h[2];
  return WL_OK;
}
