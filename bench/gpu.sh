#!/usr/bin/env bash
# gpu.sh: build wallload's CUDA backend and run the GPU benchmark set in one
# go (made for one call on the device machine):
#   - the CPU-vs-GPU test (tests/test_cuda_backend.c);
#   - 3D dam break with pillar (DualSPHysics 01_DamBreak geometry) at about
#     1.04M and 8.1M particles, Wendland, h = 1.73 dp (coefh 1 in 3D);
#   - 2D dam break at about 0.89M particles, Wendland, h = 1.41 dp;
#   - the CPU backend on the same host, for comparison (the other force
#     loops are a test-only build of cuda.cu, tests/CMakeLists.txt, that
#     test_cuda_backend compares with the product's);
#   - the memory-bandwidth and fp32 ceilings through PyTorch, when it is there.
# Build: the full CMake build (-DWL_CUDA=ON) when its dependencies are there;
# otherwise (the device machine has no GSL, libyaml, cairo or HDF5) the
# modules the benchmark needs (error, sph, scene, backend_cpu, backend_cuda,
# cli/bench.c) straight with gcc and nvcc into BUILD_DIR/wl_bench and
# BUILD_DIR/test_cuda_backend.
# Results go to stdout and to $OUT/gpu_bench.log (or /tmp); copy them into
# BENCHMARKS.md with the GPU and the date.
#
#   usage: bench/gpu.sh [BUILD_DIR]      (default: build-gpu)
#   STEPS3D, STEPS8M, STEPS2D override the timed step counts;
#   WL_BENCH_DIRECT=1 skips the CMake attempt.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-gpu}
case $build in /*) ;; *) build=$PWD/$build ;; esac
log=${OUT:-/tmp}/gpu_bench.log
nvcc=$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)
cuda_lib=$(dirname "$(dirname "$nvcc")")/lib64
mkdir -p "$build"
if [ -z "${WL_BENCH_DIRECT:-}" ] &&
  cmake -S "$root" -B "$build" -DWL_CUDA=ON -DCMAKE_BUILD_TYPE=Release >"$build/configure.log" 2>&1; then
  cmake --build "$build" -j"$(nproc)" >"$build/build.log" 2>&1 || { tail -30 "$build/build.log"; exit 1; }
  bench=("$build/wallload" bench)
  test=$build/tests/test_cuda_backend
else
  echo "# full CMake build not used here ($(grep -s -m1 -o 'Could NOT find [A-Za-z0-9]*' "$build/configure.log" || echo 'skipped')); building the benchmark modules directly"
  mkdir -p "$build/include/wallload" "$build/obj"
  sed 's/@PROJECT_VERSION@/bench/; s/@WL_HAVE_CUDA@/1/' "$root/include/wallload/config.h.in" \
    >"$build/include/wallload/config.h"
  inc=(-I"$root/include" -I"$build/include" -I"$root/src/cli" -I"$root/tests")
  objs=()
  for f in "$root"/src/{error,sph,scene,backend_cpu,backend_cuda}/*.c "$root/src/cli/bench.c"; do
    o=$build/obj/$(basename "$(dirname "$f")")_$(basename "$f" .c).o
    gcc -std=c11 -O3 -DNDEBUG -fopenmp -Wall -Wextra -Wno-format-truncation "${inc[@]}" -c "$f" -o "$o" &
    objs+=("$o")
  done
  for f in "$root"/src/backend_cuda/*.cu; do
    o=$build/obj/cu_$(basename "$f" .cu).o
    "$nvcc" -O3 -DNDEBUG -arch=sm_90 "${inc[@]}" -c "$f" -o "$o" &
    objs+=("$o")
  done
  wait
  libs=(-L"$cuda_lib" -lcudart_static -lstdc++ -ldl -lpthread -lrt -lm -fopenmp)
  gcc -O3 "${inc[@]}" "$root/bench/gpu_main.c" "${objs[@]}" "${libs[@]}" -o "$build/wl_bench"
  gcc -std=c11 -O3 "${inc[@]}" "$root/tests/test_cuda_backend.c" "${objs[@]}" "${libs[@]}" \
    -o "$build/test_cuda_backend"
  bench=("$build/wl_bench")
  test=$build/test_cuda_backend
fi
b() { "${bench[@]}" "$@" | grep -v '^# \(warm-up\|GPU\)' || true; }
{
  echo "# $(date -u +%Y-%m-%dT%H:%M:%SZ) $(nvidia-smi --query-gpu=name,memory.total,driver_version,clocks.max.sm --format=csv,noheader 2>/dev/null || echo 'nvidia-smi unavailable')"
  echo "# host: $(lscpu | grep 'Model name' | sed 's/  */ /g'), $(nproc) cores"
  echo "## test_cuda_backend"
  rc=0
  "$test" >"$build/test_cuda_backend.log" 2>&1 || rc=$?
  grep -E "^#|FAIL|SKIP" "$build/test_cuda_backend.log" || true
  echo "test_cuda_backend: exit $rc ($(grep -c '^PASS' "$build/test_cuda_backend.log") PASS, $(grep -c '^FAIL' "$build/test_cuda_backend.log") FAIL)"
  echo "## default force loops (3D: split, 2D: fast)"
  b --case dambreak3d --backend cuda --particles 1.04e6 --steps "${STEPS3D:-200}"
  b --case dambreak3d --backend cuda --particles 8.1e6 --steps "${STEPS8M:-40}"
  b --case dambreak2d --backend cuda --particles 0.89e6 --steps "${STEPS2D:-500}"
  echo "## CPU backend, same host, all cores"
  b --case dambreak3d --backend cpu --particles 1.04e6 --steps 3 | grep '^dam'
  b --case dambreak2d --backend cpu --particles 0.89e6 --steps 10 | grep '^dam'
  echo "## ceilings (PyTorch)"
  python3 - <<'PY' 2>&1 || echo "(no PyTorch: ceilings not measured)"
import torch
s, e = torch.cuda.Event(enable_timing=True), torch.cuda.Event(enable_timing=True)
def med(f, n):
    ts = []
    for _ in range(n):
        s.record(); f(); e.record(); torch.cuda.synchronize(); ts.append(s.elapsed_time(e))
    return sorted(ts)[n // 2]
x = torch.empty(1 << 30, dtype=torch.uint8, device="cuda"); y = torch.empty_like(x)
for _ in range(3): y.copy_(x)
t = med(lambda: y.copy_(x), 21)
print("device-to-device copy of 1 GiB: median %.3f ms, %.2f TB/s (read + write)" % (t, 2 * (1 << 30) / (t * 1e-3) / 1e12))
torch.backends.cuda.matmul.allow_tf32 = False
a = torch.randn(8192, 8192, device="cuda"); c = torch.randn(8192, 8192, device="cuda")
for _ in range(2): a @ c
t = med(lambda: a @ c, 5)
print("fp32 (no TF32) 8192^3 matrix product: median %.2f ms, %.1f TFLOP/s" % (t, 2 * 8192**3 / (t * 1e-3) / 1e12))
PY
} 2>&1 | tee "$log"
