#!/usr/bin/env bash
# gpu.sh: build wallload with the CUDA backend and run the GPU benchmark set
# in one go (made for one call on the device machine):
#   - the CPU-vs-GPU test (tests/test_cuda_backend.c);
#   - 3D dam break with pillar (DualSPHysics 01_DamBreak geometry) at about
#     1.04M and 8.1M particles, Wendland, h = 1.73 dp (coefh 1 in 3D);
#   - 2D dam break at about 0.89M particles, Wendland, h = 1.41 dp;
#   - the reference force loop (wl_sph_gather as is) at 1M in 3D and 0.9M
#     in 2D, and the CPU backend on the same host, for comparison;
#   - the memory-bandwidth ceiling (device-to-device copy) when PyTorch is
#     there.
# Results go to stdout (and to $OUT/gpu_bench.log when OUT is set); copy them
# into BENCHMARKS.md with the GPU and date.
#
#   usage: bench/gpu.sh [BUILD_DIR]      (default: build-gpu)
#   STEPS3D, STEPS8M, STEPS2D override the timed step counts.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-gpu}
log=${OUT:-/tmp}/gpu_bench.log
cmake -S "$root" -B "$build" -DWL_CUDA=ON -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" 2>&1 | grep -E "warning|error" || true
exe=$build/wallload
{
  echo "# $(date -u +%Y-%m-%dT%H:%M:%SZ) $(nvidia-smi --query-gpu=name,memory.total,driver_version,clocks.max.sm --format=csv,noheader 2>/dev/null || echo 'nvidia-smi unavailable')"
  echo "# host: $(lscpu | grep 'Model name' | sed 's/  */ /g'), $(nproc) cores"
  echo "## test_cuda_backend"
  "$build/tests/test_cuda_backend" 2>&1 | grep -E "^#|FAIL|SKIP" || true
  "$build/tests/test_cuda_backend" >/dev/null 2>&1 && echo "test_cuda_backend: PASS" || echo "test_cuda_backend: exit $?"
  echo "## fast loop (default)"
  "$exe" bench --case dambreak3d --backend cuda --particles 1.04e6 --steps "${STEPS3D:-200}"
  "$exe" bench --case dambreak3d --backend cuda --particles 8.1e6 --steps "${STEPS8M:-40}"
  "$exe" bench --case dambreak2d --backend cuda --particles 0.89e6 --steps "${STEPS2D:-500}"
  echo "## reference loop (wl_sph_gather)"
  WL_CUDA_GATHER=ref "$exe" bench --case dambreak3d --backend cuda --particles 1.04e6 --steps 20
  WL_CUDA_GATHER=ref "$exe" bench --case dambreak2d --backend cuda --particles 0.89e6 --steps 100
  echo "## CPU backend, same host, all cores"
  "$exe" bench --case dambreak3d --backend cpu --particles 1.04e6 --steps 3
  "$exe" bench --case dambreak2d --backend cpu --particles 0.89e6 --steps 10
  echo "## memory bandwidth ceiling"
  python3 - <<'PY' 2>&1 || echo "(no PyTorch: bandwidth not measured)"
import torch
x = torch.empty(1 << 30, dtype=torch.uint8, device="cuda")
y = torch.empty_like(x)
for _ in range(3): y.copy_(x)
s, e = torch.cuda.Event(enable_timing=True), torch.cuda.Event(enable_timing=True)
ts = []
for _ in range(20):
    s.record(); y.copy_(x); e.record(); torch.cuda.synchronize(); ts.append(s.elapsed_time(e))
ts.sort()
print("device-to-device copy of 1 GiB: median %.3f ms, %.2f TB/s (read + write)" % (ts[10], 2 * (1 << 30) / (ts[10] * 1e-3) / 1e12))
a = torch.randn(8192, 8192, device="cuda"); b = torch.randn(8192, 8192, device="cuda")
torch.backends.cuda.matmul.allow_tf32 = False
for _ in range(2): a @ b
ts = []
for _ in range(5):
    s.record(); a @ b; e.record(); torch.cuda.synchronize(); ts.append(s.elapsed_time(e))
ts.sort()
print("fp32 (no TF32) 8192^3 matrix product: median %.2f ms, %.1f TFLOP/s" % (ts[2], 2 * 8192**3 / (ts[2] * 1e-3) / 1e12))
PY
} 2>&1 | tee "$log"
