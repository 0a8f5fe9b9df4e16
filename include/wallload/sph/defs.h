/* sph/defs.h: what every shared physics header needs: the host+device
 * qualifier, the real type, and a few branch-free scalar helpers.
 *
 * Headers in include/wallload/sph/ are valid C11 and CUDA C++ and include no
 * library header: the CPU backend (src/backend_cpu, OpenMP) and the CUDA
 * backend compile the very same functions, so both compute the same thing and
 * a change is made in one place (STYLE.md "Physics written once").
 *
 * Precision. Positions are double: near x = 36 m the float spacing is about
 * 4 um, too coarse for v*dt at fine dp (a 1 m/s particle with dt = 1e-5 s
 * moves 10 um per step, which float would round away). Every other field is
 * wl_real (float by default): differences of positions are taken in double
 * and then narrowed to wl_real, where they are small and exact enough, as
 * DualSPHysics does. Build with -DWL_REAL_DOUBLE=1 to make wl_real double
 * (slower, for convergence checks). */
#ifndef WALLLOAD_SPH_DEFS_H
#define WALLLOAD_SPH_DEFS_H

#if defined(__CUDACC__)
#define WL_HD __host__ __device__
#else
#define WL_HD
#endif

/* Forced inlining for the neighbour-loop functions: they take the dimension
 * and model switches as arguments that are constants at the call site, and
 * only inlining turns those into compile-time constants (one specialised
 * loop per instantiation) and lets the loop vectorise. */
#if defined(__CUDACC__)
#define WL_INLINE __forceinline__
#elif defined(__GNUC__)
#define WL_INLINE inline __attribute__((always_inline))
#else
#define WL_INLINE inline
#endif

#ifndef WL_REAL_DOUBLE
#define WL_REAL_DOUBLE 0
#endif

#if WL_REAL_DOUBLE
typedef double wl_real;
#define WL_R(x) (x)
#else
typedef float wl_real;
#define WL_R(x) (x##f)
#endif

/* A load from an array that no thread writes during the kernel (the
 * neighbour loops' inputs): on the GPU through the read-only data cache
 * (__ldg), on the host a plain load. */
#if defined(__CUDA_ARCH__)
#define WL_LDG(ptr) __ldg(ptr)
#else
#define WL_LDG(ptr) (*(ptr))
#endif

/* Unrolling of the GPU's one-thread neighbour loop (sph/gather.h
 * wl_sph_gather_range with the cut): two candidates per trip, so that one's
 * loads overlap the other's pair. Left to itself nvcc unrolls some of the
 * loop's instances (fluid-fluid) and not others (fluid-wall), and the 2D
 * loop runs about 0.7 % slower on the H100 (BENCHMARKS.md). */
#ifndef WL_GPU_RANGE_UNROLL
#define WL_GPU_RANGE_UNROLL 2
#endif
#if defined(__CUDA_ARCH__) && WL_GPU_RANGE_UNROLL == 2
#define WL_GPU_UNROLL_RANGE _Pragma("unroll 2")
#else
#define WL_GPU_UNROLL_RANGE
#endif

/* Double product and sum each rounded once, never fused: nvcc contracts
 * a * b + c into one FMA by default, the CPU build (ISO C) never does, and
 * the time step's maxima (gather.h wl_sph_eval_dt_input) must be the same
 * on both. */
#if defined(__CUDA_ARCH__)
#define WL_DMUL(a, b) __dmul_rn((a), (b))
#define WL_DADD(a, b) __dadd_rn((a), (b))
#else
#define WL_DMUL(a, b) ((a) * (b))
#define WL_DADD(a, b) ((a) + (b))
#endif

/* Largest dimension and number of moving bodies (paddles) a run may have. */
#define WL_SPH_DIM_MAX 3
#define WL_SPH_BODIES_MAX 8
/* Damping zones along x (sph/params.h). */
#define WL_SPH_DAMP_ZONES 2

/* OpenMP SIMD hint for the neighbour loops. It permits the compiler to
 * reorder the listed sums (vector lanes), which changes rounding but not the
 * result's independence of the thread count: the order is fixed by the data
 * layout and the binary, never by the schedule. Ignored by nvcc. */
#if defined(_OPENMP) && !defined(__CUDA_ARCH__)
#define WL_PRAGMA_(x) _Pragma(#x)
#define WL_SIMD(...) WL_PRAGMA_(omp simd __VA_ARGS__)
#else
#define WL_SIMD(...)
#endif

/* Square root. On the host it is a Newton-Raphson iteration, not sqrtf:
 * under the project's strict IEEE flags (errno-setting math, trapping math)
 * GCC will not vectorise a loop that calls sqrtf, and the neighbour loop is
 * where the run time goes. Seed: the bit-level estimate of 1/sqrt(x) with
 * Lomont's constant (relative error < 3.5e-2), then three Newton steps
 * y <- y (3 - x y^2)/2, each squaring the relative error (3.5e-2 -> 1.8e-3
 * -> 4.7e-6 -> 3e-11), so only float rounding is left: within a few ulp of the
 * correctly rounded sqrt (test_sph_kernel checks 4 ulp over [1e-12, 1e4]).
 * x = 0 gives 0; x must be >= 0 and finite.
 *
 * On the GPU it is correctly rounded, the same bits as sqrtf, without
 * sqrtf's range check and branch (about 10 instructions; this is 6): for
 * a finite x >= 2^-101, nvcc's sqrtf is the hardware estimate y of
 * 1/sqrt(x), r = x y, and one FMA correction r + (x - r^2) y/2, and that
 * is what this does; below 2^-101 (zero and denormals) sqrtf takes a slow
 * path. Here x is raised to 2^-100 first, so x < 2^-100 gives 2^-50 (9e-16):
 * a distance of 1e-15 m or less is 0 to every term that uses it (q = r/h
 * rounds 1 - q/2 to 1). wl_cuda_math_check (cuda_device.h) compares it
 * with sqrtf on every float from 2^-100 up (test_cuda_backend). CPU and GPU
 * agree to a few ulp in r. */
WL_HD static WL_INLINE wl_real wl_sph_sqrt(wl_real x) {
#if defined(__CUDA_ARCH__) && !WL_REAL_DOUBLE
  const float xs = x < 0x1p-100f ? 0x1p-100f : x; /* a NaN stays NaN */
  float y;
  asm("rsqrt.approx.ftz.f32 %0, %1;" : "=f"(y) : "f"(xs));
  const float r = xs * y;
  return fmaf(fmaf(-r, r, xs), 0.5f * y, r);
#elif defined(__CUDACC__)
  return sqrt(x);
#elif WL_REAL_DOUBLE
  return __builtin_sqrt(x);
#else
  union {
    float f;
    unsigned int u;
  } b;
  b.f = x;
  b.u = 0x5f375a86u - (b.u >> 1);
  float y = b.f;
  const float hx = 0.5f * x;
  y = y * (1.5f - hx * y * y);
  y = y * (1.5f - hx * y * y);
  y = y * (1.5f - hx * y * y);
  return x * y;
#endif
}

/* 1/x, correctly rounded for a normal x with |x| < 2^126 (the same bits as
 * 1/x); the pair loops divide by rho ~ 1e3 and by (r^2 + eta^2)(rho_i +
 * rho_j) ~ 1e-5..1e5 in SI units, far inside that. On the host it is
 * the division. On the GPU, nvcc's correctly rounded 1/x is the hardware
 * estimate y and one FMA correction y - (x y - 1) y for such x, behind a
 * range check and a branch to a slow path for the rest (about 10
 * instructions; this is 3). Outside the range: 0 gives NaN (IEEE: inf),
 * |x| >= 2^126 gives 0 (IEEE: a denormal), a NaN stays NaN.
 * wl_cuda_math_check compares it with 1/x on every float in the range. */
WL_HD static WL_INLINE wl_real wl_sph_rcp(wl_real x) {
#if defined(__CUDA_ARCH__) && !WL_REAL_DOUBLE
  float y;
  asm("rcp.approx.ftz.f32 %0, %1;" : "=f"(y) : "f"(x));
  return fmaf(-fmaf(x, y, -1.0f), y, y);
#else
  return WL_R(1.0) / x;
#endif
}

/* |x| without a branch (on the GPU an operand modifier of the instruction
 * that uses it: wl_sph_pos and wl_sph_neg are then two instructions). */
WL_HD static WL_INLINE wl_real wl_sph_abs(wl_real x) {
#if defined(__CUDACC__) && WL_REAL_DOUBLE
  return fabs(x);
#elif defined(__CUDACC__)
  return fabsf(x);
#elif WL_REAL_DOUBLE
  return __builtin_fabs(x);
#else
  return __builtin_fabsf(x);
#endif
}

/* max(x, 0) and min(x, 0), exact and without a comparison (a comparison in
 * the neighbour loop stops GCC vectorising it under trapping math):
 * x + |x| is 2x or +0 exactly, and halving is exact. */
WL_HD static WL_INLINE wl_real wl_sph_pos(wl_real x) { return WL_R(0.5) * (x + wl_sph_abs(x)); }
WL_HD static WL_INLINE wl_real wl_sph_neg(wl_real x) { return WL_R(0.5) * (x - wl_sph_abs(x)); }

/* 1 if x > 0, 0 if x == +0 (x >= 0 finite), by integer arithmetic on the
 * bits: same reason as wl_sph_pos (no float comparison in the loop). */
WL_HD static WL_INLINE wl_real wl_sph_nonzero(wl_real x) {
#if defined(__CUDACC__) || WL_REAL_DOUBLE
  return x > 0 ? WL_R(1.0) : WL_R(0.0);
#else
  union {
    float f;
    unsigned int u;
  } b;
  b.f = x;
  return (wl_real)((b.u + 0x7fffffffu) >> 31);
#endif
}

/* max(a, b) of two non-negative finite values, exactly: for such floats
 * the IEEE bit patterns order like the values, so an integer max does it
 * (vectorises where a float comparison would not, see wl_sph_pos). */
WL_HD static WL_INLINE wl_real wl_sph_max_nonneg(wl_real a, wl_real b) {
#if defined(__CUDACC__) || WL_REAL_DOUBLE
  return a > b ? a : b;
#else
  union {
    float f;
    unsigned int u;
  } x, y;
  x.f = a;
  y.f = b;
  x.u = x.u > y.u ? x.u : y.u;
  return x.f;
#endif
}

WL_HD static inline double wl_sph_maxd(double a, double b) { return a > b ? a : b; }
WL_HD static inline double wl_sph_mind(double a, double b) { return a < b ? a : b; }
WL_HD static inline int wl_sph_maxi(int a, int b) { return a > b ? a : b; }
WL_HD static inline int wl_sph_mini(int a, int b) { return a < b ? a : b; }

#endif
