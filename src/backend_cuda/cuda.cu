/* cuda.cu: the CUDA backend (backend.h): particle arrays in device memory
 * (structure of arrays; positions double, every other field wl_real), one
 * symplectic step on the device with the shared physics of
 * include/wallload/sph/:
 *
 *   keys      key = group * n_cells + cell (sph/cells.h wl_sph_cell_of)
 *             and the particles per key, computed by the update that ends
 *             the step before (k_update; k_keys for the initial state)
 *   sort      counting sort by key in the stable order (a CUB scan that
 *             gives begin[key] = first sorted index of each key,
 *             k_scatter, k_cellsort), then the state fields gathered into
 *             sorted order (in a 2D step k_permute ranks each key's
 *             range itself, without k_cellsort)
 *   walls     with the wall condition (the default), k_wall: one thread per
 *             boundary particle samples the fluid (sph/wall.h); the force
 *             loops then start at the first fluid particle
 *   forces    the force loop of the dimension (below) at the step start;
 *             predictor (sph/integrate.h) and the forces again at the half
 *             step
 *   corrector and guard (sph/guard.h), the next step's keys and the end
 *             of the step in one kernel (k_update, whose last block ends
 *             the step); the first faulty particle (lowest sorted index)
 *             by an atomic min
 *   dt        each particle's time-step input (sph/gather.h
 *             wl_sph_eval_dt_input), then block reductions, one atomic max
 *             of the bit pattern per block (exact: the max of non-negative
 *             doubles does not depend on the order); the formula is
 *             backend.h wl_sph_step_dt, on the host
 *   wall load at an output (backend.h wall_load): sort, one thread per
 *             fluid particle (sph/gather.h wl_sph_gather_wall_load), one
 *             block's sum in a fixed order
 *
 * Steps. No input of a step is a kernel argument: the step's plan (dt,
 * the previous dt, the Euler flag, the bodies' motion) is in the device
 * record, so one step is captured once as a CUDA graph from each of the
 * two role sets of the arrays (a rebuild swaps them) and replayed. A step
 * of the driver (backend.h step) uploads its plan, replays and reads the
 * record back. A block (backend.h run) plans each step on the device by
 * the driver's rules (k_plan, k_update's end_step: backend.h wl_sph_dt_toward and
 * friends, the time step's wl_sph_step_dt, the guards), so the host
 * enqueues the block's steps and reads one record at its end; after a
 * fault, a collapse, the output time or the step count the plan stops
 * and the remaining replays return at once (plan.stop), so the record
 * names the first faulty step. A 2D flume of 20 000 particles steps in
 * tens of microseconds, of the order of a launch and a synchronisation.
 *
 * The host touches particle data only in download. Everything is
 * allocated in init (no allocation in step); init checks cudaMemGetInfo
 * first.
 *
 * The force loops run the shared loop bodies of sph/gather.h and differ
 * only in how they find each particle's candidates:
 *  - k_gather_lanes (2D, and 3D runs under WL_LANES_MAX_PARTICLES_3D):
 *    WL_GATHER_LANES threads per particle, each wl_sph_gather_range over
 *    its share of every row, their sums added;
 *  - k_gather (3D with double wl_real): wl_sph_gather_block itself, one
 *    thread per particle, with the cut-off skip (a candidate beyond 2h is
 *    not evaluated; the same bits as without it);
 *  - k_gather_split (larger 3D runs): the warp stages its particles'
 *    candidates in shared memory, marks those inside each particle's
 *    support, and splits the marked pairs evenly over its 32 lanes; each
 *    pair is wl_sph_pair_sum, the mirror planes' rows
 *    wl_sph_gather_mirrors, the end wl_sph_finish. The same terms in the same order per particle,
 *    summed in runs: equal to the reference loop to float rounding.
 * The reference loop (k_gather without the skip, wl_sph_gather) and the
 * loops of the other dimension are built only in the tests' build of this
 * file (WL_CUDA_TEST_LOOPS, tests/CMakeLists.txt), where test_cuda_backend
 * compares every loop with it and with the CPU. */
#include <cuda_runtime.h>
#include <stddef.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <utility>


extern "C" {
#include "wallload/backend.h"
#include "wallload/config.h"
#include "wallload/cuda_device.h"
#include "wallload/error.h"
#include "wallload/sph.h"
}
#include "wallload/sph/cells.h"
#include "wallload/sph/gather.h"
#include "wallload/sph/guard.h"
#include "wallload/sph/integrate.h"
#include "wallload/sph/wall.h"
#include "wallload/sph/shift.h"

/* Everything but the exported backend tables has internal linkage, so that
 * the tests' build of this file links beside the product's. */
namespace {

#define WL_STR_(x) #x
#define WL_STR(x) WL_STR_(x)

/* Threads per block of every particle kernel. */
enum { THREADS = 128 };

/* Force loops (see the file header): the reference loop (tests only),
 * the one-thread-per-particle loop with the cut-off skip, the split loop,
 * the loop with a few threads per particle. */
enum { MODE_REF = 0, MODE_FAST = 1, MODE_SPLIT = 2, MODE_LANES = 3 };

/* 1 in the tests' build of this file (tests/CMakeLists.txt), which has
 * every loop in both dimensions and exports one backend per loop. */
#ifndef WL_CUDA_TEST_LOOPS
#define WL_CUDA_TEST_LOOPS 0
#endif

/* 2D runs of fewer particles than this take the lanes loop, larger ones
 * the fast loop: with one thread per particle a run under about the GPU's
 * resident threads (132 SMs x 2048 on an H100) leaves the GPU waiting on
 * each thread's walk over its ~70 candidates, one after the other; above
 * it the fast loop's threads fill the GPU and the lanes' extra sums would
 * only cost. A fixed count, not the GPU's, so that a run takes the same
 * loop (and gives the same bits) on every GPU. */
#ifndef WL_LANES_MAX_PARTICLES
#define WL_LANES_MAX_PARTICLES 262144
#endif
/* The same in 3D, against the split loop, whose warps of 32 particles
 * leave a small flume's GPU as idle: lanes ran the 3D dam break at 2.06,
 * 1.50, 1.14 and 0.90 times split's force evaluations/s at 64 k, 110 k,
 * 156 k and 205 k particles (H100, 2026-11-27, BENCHMARKS.md "CUDA
 * backend: small 3D runs"); the crossing, about 180 k, is the bound. */
#ifndef WL_LANES_MAX_PARTICLES_3D
#define WL_LANES_MAX_PARTICLES_3D 180000
#endif

/* The product's loop of dimension dim for n particles: in 3D lanes for a
 * small run (WL_LANES_MAX_PARTICLES_3D), else split, where staging pays
 * (cells of ~30 particles); in 2D, where a cell holds ~8 and
 * the warp's rows are too short for split (split ran at half the rate of
 * fast there on the H100, docs/history/BENCHMARKS-history.md), lanes or
 * fast by size (WL_LANES_MAX_PARTICLES); fast in a 3D build with double
 * wl_real, which split's float staging would narrow. */
static constexpr int default_mode(int dim, int n) {
  return dim == 2 ? (n < WL_LANES_MAX_PARTICLES ? MODE_LANES : MODE_FAST)
                  : n < WL_LANES_MAX_PARTICLES_3D ? MODE_LANES
                  : !WL_REAL_DOUBLE              ? MODE_SPLIT
                                                 : MODE_FAST;
}

/* Whether this build has loop `mode` for dimension dim. The product has
 * its default loops (3D: lanes and split) and, in both dimensions, fast:
 * the one that runs the residual viscosity (its pair term and gradients
 * go through the shared wl_sph_gather_block, which the lanes and split
 * loops do not call). */
static constexpr bool loop_built(int mode, int dim) {
  return WL_CUDA_TEST_LOOPS ? mode != MODE_SPLIT || !WL_REAL_DOUBLE
         : dim == 2         ? mode == MODE_LANES || mode == MODE_FAST
                            : mode == MODE_LANES || mode == default_mode(dim, 1 << 30) ||
                                  mode == MODE_FAST;
}

/* Threads per particle of the lanes loop (a power of two, at most 32):
 * each takes a contiguous share of every row of candidates. */
#ifndef WL_GATHER_LANES
#define WL_GATHER_LANES 4
#endif
/* The same for the wall condition's boundary particles, by dimension: a
 * 2D flume's few thousand of them walk ~70 candidates each, and 16 lanes
 * took seawall.yaml's solitary step (dp = 0.012 m, 21 k particles) from
 * 42-44 to 39-40 us (8: 42 us); a 3D flume's tens of thousands fill the GPU
 * at 4 (16 was 3-5 % slower at 64-156 k particles; H100, 2026-11-27,
 * BENCHMARKS.md "CUDA backend: small 3D runs"). */
#ifndef WL_WALL_LANES_2D
#define WL_WALL_LANES_2D 16
#endif
#ifndef WL_WALL_LANES_3D
#define WL_WALL_LANES_3D 4
#endif

/* ---- error checking ----------------------------------------------------- */

/* Every CUDA call goes through CK: on failure the function returns the
 * error (first error wins) naming the call, the CUDA reason and the line. */
#define CK(call)                                                                                 \
  do {                                                                                           \
    const cudaError_t e_ = (call);                                                               \
    if (e_ != cudaSuccess)                                                                       \
      return wl_error_set(err, WL_EIO, "cuda backend: %s failed: %s (%s:%d)", #call,             \
                          cudaGetErrorString(e_), __FILE__, __LINE__);                           \
  } while (0)

/* After a kernel launch: the launch error (bad configuration) at once. */
#define CKL(what) CK(cudaPeekAtLastError())

/* ---- device state ------------------------------------------------------- */

/* The step under way, as its kernels read it (no step input is a kernel
 * argument: a captured step replays with the same arguments). Written by
 * the host before a step (cuda_step) or planned on the device in a block
 * (cuda_run, plan_next). */
struct dplan {
  double dt, dt_prev; /* the step and the previous one [s] */
  int euler;          /* Verlet: the Euler step (integrate.h wl_sph_verlet_euler) */
  int stop;           /* the block has stopped: every step kernel returns at once */
  int block;          /* 1: a block (end_step accounts and plans the next step), 0: one step */
  int pad;
  double body_vel[WL_SPH_BODIES_MAX + 1][WL_SPH_DIM_MAX]; /* backend.h wl_sph_step_in */
  double body_acc[WL_SPH_BODIES_MAX + 1][WL_SPH_DIM_MAX];
};

/* A block's driver state on the device (backend.h wl_sph_block_in/out). */
struct dblock {
  double t, t_out, dt_next, dt_last, dt_initial;
  long long step, max_steps, taken, n_excluded, n_fluid;
  unsigned long long limited, excluded; /* sums over the block */
  int why;                              /* enum wl_sph_block_stop */
  int lands;                            /* the planned step lands on t_out */
};

/* Reductions and fault of one step, and the step's plan (device record,
 * copied back once a step or block). */
struct dstats {
  unsigned long long ace2, vel2, visc; /* bit patterns of non-negative doubles */
  int first;                           /* lowest faulty index, INT_MAX if none */
  int fault, wall, kind;
  unsigned int id;
  int pad;
  double pos[WL_SPH_DIM_MAX], vel[WL_SPH_DIM_MAX], rho;
  unsigned long long limited; /* particles the wall limiter moved */
  unsigned long long excluded; /* particles that left the domain box (guard.h wl_sph_exclude) */
  double load[2];              /* wall_load: force [N or N/m], moment [N m or N m/m] */
  unsigned int ticket;         /* k_update's blocks done (its last block ends the step) */
  int pad2;
  struct dplan plan;           /* uploaded (with blk in a block) before the step */
  struct dblock blk;
};

/* The wall faces in a block's shared memory (k_update). */
struct wl_sph_walls_sh {
  struct wl_sph_wall w[WL_SPH_WALLS_MAX];
};

/* The velocity gradients' arrays, by value into k_vgrad. */
struct gvptr {
  wl_real *g[WL_SPH_DIM_MAX * WL_SPH_DIM_MAX];
};

/* Read-only configuration on the device (guard). */
struct dmeta {
  double lo[WL_SPH_DIM_MAX], hi[WL_SPH_DIM_MAX];
  int n_walls;
  struct wl_sph_wall walls[WL_SPH_WALLS_MAX];
};

/* The arrays whose roles a rebuild swaps (struct gpu), for the captured
 * steps: a rebuild from roles[0] gives roles[1] and back. */
struct roles {
  double *pos[WL_SPH_DIM_MAX], *pos_h[WL_SPH_DIM_MAX];
  wl_real *vel[WL_SPH_DIM_MAX], *vel_h[WL_SPH_DIM_MAX], *ace0, *rho, *rho_h, *ar;
  wl_real *vel_m1[WL_SPH_DIM_MAX], *vel_m1_alt[WL_SPH_DIM_MAX], *rho_m1, *rho_m1_alt;
  unsigned int *key, *id;
  unsigned char *kind, *kind_alt, *body, *body_alt;
};

struct gpu {
  struct wl_sph_config cfg;
  struct wl_sph_const k;
  struct wl_sph_grid grid;
  int dim, n, nb;
  int mode; /* force loop: MODE_FAST or MODE_SPLIT (MODE_REF in the tests' build) */
  /* device arrays (current roles; sorting swaps pos<->pos_h, vel<->vel_h,
   * rho<->rho_h, id<->ar, kind<->kind_alt, body<->body_alt) */
  double *pos[WL_SPH_DIM_MAX], *pos_h[WL_SPH_DIM_MAX];
  wl_real *vel[WL_SPH_DIM_MAX], *vel_h[WL_SPH_DIM_MAX], *ace[WL_SPH_DIM_MAX];
  wl_real *rho, *rho_h, *press, *ar, *visc;
  wl_real *shift[WL_SPH_DIM_MAX]; /* particle shifting (NULL when off) */
  /* the fluid's velocity gradients of the residual viscosity (sph/vgrad.h;
   * NULL when off): recomputed before each force evaluation, never sorted */
  wl_real *gv[WL_SPH_DIM_MAX * WL_SPH_DIM_MAX];
  /* Verlet (NULL with the symplectic integrator): the previous step's v and
   * rho (the view's vel_h and rho_h, sph/integrate.h) and their sort targets */
  wl_real *vel_m1[WL_SPH_DIM_MAX], *vel_m1_alt[WL_SPH_DIM_MAX], *rho_m1, *rho_m1_alt;
  unsigned int *key, *id;
  unsigned char *kind, *kind_alt, *body, *body_alt;
  int *begin; /* 2 n_cells + 1 */
  int *count; /* 2 n_cells + 1: particles per key (k_keys at init, then each update) */
  int *bsum;  /* the particles of each SCAN_THREADS keys (k_scan's blocks) */
  size_t bsum_bytes;
  struct dmeta *meta;
  struct dstats *stats;   /* device */
  struct dstats *h_stats; /* pinned host copy */
  struct dstats *h_up;    /* pinned host staging of the plan (and block) uploads */
  unsigned char *h_dl;    /* pinned host staging of download and snapshot (dl_bytes) */
  size_t dl_bytes;
  double *h_load;         /* pinned: force and moment of each wall load (2 WL_SPH_SNAPSHOT_LOADS) */
  cudaEvent_t snap_ev;    /* a snapshot's copies done (backend.h snapshot) */
  int snap_n;             /* its wall loads */
  int run_q0;             /* a started block's first role set (run_start, run_finish) */
  /* one step captured as a CUDA graph from each of the two role sets (a
   * step's kernels are a dozen launches of a few microseconds each at 20k
   * particles: replayed as a graph they follow each other without the
   * launch gaps) */
  cudaGraph_t graph[2];
  cudaGraphExec_t exec[2];
  /* two steps as one graph from each role set (back to it after them): a
   * block's steps in pairs, one graph launch's gap for two steps */
  cudaGraph_t graph2[2];
  cudaGraphExec_t exec2[2];
  struct roles roles[2];
  int graphs; /* exec[] captured */
  /* backend.h zone_download / zone_upload (allocated at the first): the
   * zone's places, each particle's flag (in the zone, parked beyond it,
   * neither), the zone's fields gathered, and the host's copies of the
   * flags and places */
  int *z_idx;
  unsigned char *z_flag, *z_buf;
  unsigned char *h_zflag; /* pinned */
  int *h_zidx;            /* pinned */
  void *allocs[64];       /* everything cudaMalloc'd, for free */
  int n_allocs;
  size_t bytes;           /* device bytes allocated */
  cudaStream_t stream;
  struct wl_cuda_device dev;
  /* programmatic dependent launch (compute capability 9.0 and later, CUDA
   * 12.3 and later; off with WL_CUDA_PDL=0): each kernel of a step may be
   * launched while the one before it finishes, and waits for it in
   * pdl_begin */
  int pdl;
};

/* Launch kernel kern (one whose first statement is pdl_begin) in stream s:
 * under c->pdl with programmatic stream serialisation, so that it may
 * start while the kernel before it in the stream finishes (pdl_begin waits
 * for that one); else as <<<grid, block, 0, s>>>. Errors as a launch's:
 * the caller's CKL reads them. Captured into a step's graph, the attribute
 * becomes a programmatic edge. */
template <typename... P, typename... A>
static void launch(const struct gpu *c, void (*kern)(P...), unsigned grid, unsigned block,
                   cudaStream_t s, A &&...args) {
#if CUDART_VERSION >= 12030 /* programmatic edges in captured graphs */
  if (!c->pdl) {
    kern<<<grid, block, 0, s>>>(std::forward<A>(args)...);
    return;
  }
  cudaLaunchAttribute attr[1];
  attr[0].id = cudaLaunchAttributeProgrammaticStreamSerialization;
  attr[0].val.programmaticStreamSerializationAllowed = 1;
  cudaLaunchConfig_t cfg;
  memset(&cfg, 0, sizeof cfg);
  cfg.gridDim = dim3(grid);
  cfg.blockDim = dim3(block);
  cfg.stream = s;
  cfg.attrs = attr;
  cfg.numAttrs = 1;
  (void)cudaLaunchKernelEx(&cfg, kern, std::forward<A>(args)...);
#else
  kern<<<grid, block, 0, s>>>(std::forward<A>(args)...);
#endif
}

/* ---- kernels ------------------------------------------------------------ */

static __device__ __forceinline__ int tid(void) { return blockIdx.x * blockDim.x + threadIdx.x; }

/* The first statement of every kernel of a step. Under programmatic
 * dependent launch (launch) a kernel's blocks may start before the kernel
 * before it in the stream has finished: griddepcontrol.wait holds them
 * until it has, its writes visible, so nothing of the kernel, not even the
 * stop flag, is read before. launch_dependents then lets the next kernel's
 * launch begin, so its launch latency overlaps this kernel's work instead
 * of following it. Without the launch attribute, or before sm_90, both are
 * no-ops and the stream orders the kernels as usual. */
static __device__ __forceinline__ void pdl_begin(void) {
#if defined(__CUDA_ARCH__) && __CUDA_ARCH__ >= 900
  asm volatile("griddepcontrol.wait;" ::: "memory");
  asm volatile("griddepcontrol.launch_dependents;" ::: "memory");
#endif
}

/* The sort (rebuild): a counting sort by key whose order inside a key is
 * the previous order, the order a stable sort gives. Each particle's key
 * and the particles per key (count) and per block of SCAN_THREADS keys
 * (bsum) come from the update that ended the step before (k_update; k_keys
 * for the initial state); their exclusive sum is begin (k_scan, one
 * kernel: each block starts from the sum of the block sums before it);
 * k_scatter: each particle into a free slot of its key's range (count
 * counted down to 0 as the fill counter: the order inside a range depends
 * on timing); k_cellsort: each range sorted by previous index, which makes
 * it the stable order again, the same permutation on every run (in a 2D
 * step k_permute takes each particle to its rank in its range instead,
 * the same permutation, one kernel fewer). A cell
 * holds ~8 particles in 2D and ~30 in 3D, so the ranges are short; this
 * takes a few short kernels where a radix sort of the keys takes two
 * passes of decoupled look-back that run nearly serially at a few ten
 * thousand particles.
 *
 * Every kernel of a step returns at once when the block has stopped
 * (plan.stop), and the counts stay those of the state. */

/* Keys per block of k_scan. */
enum { SCAN_THREADS = 1024 };
static int scan_blocks(int m) { return (m + SCAN_THREADS - 1) / SCAN_THREADS; }

/* Particle of key k counted: count[k] and its scan block's bsum (one
 * atomic per block index among the warp's active lanes: a warp's
 * particles are in sorted order, so mostly one). */
static __device__ __forceinline__ void count_key(unsigned k, int *count, int *bsum) {
  atomicAdd(&count[k], 1);
  const unsigned b = k / SCAN_THREADS;
  const unsigned peers = __match_any_sync(__activemask(), b);
  if ((int)(threadIdx.x & 31) == __ffs(peers) - 1) atomicAdd(&bsum[b], __popc(peers));
}

/* begin = the exclusive sum of count over m = n_keys + 1 keys: each block
 * scans its SCAN_THREADS keys (warp shuffles, then the warps' sums) from
 * the sum of the block sums before it. Integer sums: the same begin
 * whatever the order. */
__global__ void __launch_bounds__(SCAN_THREADS)
    k_scan(const int *__restrict__ count, const int *__restrict__ bsum, int *begin, int m,
           const struct dstats *st) {
  pdl_begin();
  if (st->plan.stop) return;
  __shared__ int wsum[SCAN_THREADS / 32];
  __shared__ int base;
  const int t = threadIdx.x, lane = t & 31, w = t >> 5, k = blockIdx.x * SCAN_THREADS + t;
  if (w == 0) {
    int b = 0;
    for (int q = lane; q < (int)blockIdx.x; q += 32) b += bsum[q];
    for (int o = 16; o > 0; o >>= 1) b += __shfl_xor_sync(0xffffffffu, b, o);
    if (lane == 0) base = b;
  }
  const int v = k < m ? count[k] : 0;
  int x = v;
  for (int o = 1; o < 32; o <<= 1) {
    const int y = __shfl_up_sync(0xffffffffu, x, o);
    if (lane >= o) x += y;
  }
  if (lane == 31) wsum[w] = x;
  __syncthreads();
  if (w == 0) {
    int y = wsum[lane];
    for (int o = 1; o < 32; o <<= 1) {
      const int z = __shfl_up_sync(0xffffffffu, y, o);
      if (lane >= o) y += z;
    }
    wsum[lane] = y;
  }
  __syncthreads();
  if (k < m) begin[k] = base + (w > 0 ? wsum[w - 1] : 0) + x - v;
}

/* Keys and particles per key, of the initial state (a step's come from
 * the update that ends the step before it, k_update). */
template <int DIM>
__global__ void k_keys(struct wl_sph_grid g, const double *__restrict__ x,
                       const double *__restrict__ y, const double *__restrict__ z,
                       const unsigned char *__restrict__ kind, unsigned int *key, int *count,
                       int *bsum, int n, struct dstats *st) {
  pdl_begin();
  if (st->plan.stop) return;
  const int i = tid();
  if (i >= n) return;
  double *pos[WL_SPH_DIM_MAX] = {(double *)x, (double *)y, (double *)z};
  if (DIM == 2) pos[1] = (double *)z;
  const unsigned group = kind[i] == WL_KIND_FLUID ? 1u : 0u;
  const unsigned k = group * (unsigned)g.n_cells + (unsigned)wl_sph_cell_of(DIM, &g, pos, i);
  key[i] = k;
  count_key(k, count, bsum);
}

/* Particle i into a free slot of its key's range of perm, counting its
 * count down (to 0 when all are placed); thread 0 resets the step
 * record. The first n_bsum block sums go to 0 for the step's update to
 * count anew, where no k_cellsort follows to do it (a 2D step: k_permute
 * ranks the ranges itself). */
__global__ void k_scatter(const unsigned int *__restrict__ key, const int *__restrict__ begin,
                          int *count, unsigned int *perm, int n, int *bsum, int n_bsum,
                          struct dstats *st) {
  pdl_begin();
  const int i = tid();
  if (st->plan.stop) return;
  for (int q = i; q < n_bsum; q += gridDim.x * blockDim.x) bsum[q] = 0;
  if (i >= n) return;
  if (i == 0) {
    st->ace2 = st->vel2 = st->visc = 0ull;
    st->first = 0x7fffffff;
    st->fault = 0;
    st->limited = 0ull;
    st->excluded = 0ull;
  }
  const unsigned k = key[i];
  perm[begin[k] + atomicSub(&count[k], 1) - 1] = (unsigned)i;
}

/* Range of key k of perm into ascending order: up to CELLSORT_REG entries
 * (a 2D cell holds ~8) by an unrolled odd-even transposition sort in
 * registers (an array indexed at run time lives in local memory, whose
 * round trips made this the step's slowest sort kernel); longer ranges
 * (3D cells hold ~30-40) are left to k_cellsort_warp when `by_warp`, else
 * (2D, where they are rare) sorted here, by insertion in a local array up
 * to CELLSORT_LOCAL and in place beyond. In a (3D) step the block sums go
 * to 0 for the step's update to count anew (k_update; the scatter left
 * count at 0); a 2D step has no k_cellsort (k_permute ranks the ranges,
 * k_scatter zeroes the block sums); a rebuild outside a step (wall_load: the next step sorts the same
 * state) gives count back. */
enum { CELLSORT_REG = 16, CELLSORT_LOCAL = 48, CELLSORT_WARP = 64 };
__global__ void k_cellsort(const int *__restrict__ begin, unsigned int *perm, int n_keys,
                           int *count, int *bsum, int step, int by_warp,
                           const struct dstats *st) {
  pdl_begin();
  const int k = tid();
  if (k >= n_keys || st->plan.stop) return;
  const int b = begin[k], m = begin[k + 1] - b;
  if (!step) count[k] = m;
  else if (k % SCAN_THREADS == 0) bsum[k / SCAN_THREADS] = 0;
  if (m < 2 || (by_warp && m > CELLSORT_REG)) return;
  unsigned int *p = perm + b;
  if (m <= CELLSORT_REG) {
    unsigned v[CELLSORT_REG];
#pragma unroll
    for (int a = 0; a < CELLSORT_REG; a++) v[a] = a < m ? p[a] : 0xffffffffu; /* pads sort last */
#pragma unroll
    for (int r = 0; r < CELLSORT_REG; r++) {
#pragma unroll
      for (int a = r & 1; a + 1 < CELLSORT_REG; a += 2) {
        const unsigned lo = min(v[a], v[a + 1]), hi = max(v[a], v[a + 1]);
        v[a] = lo;
        v[a + 1] = hi;
      }
    }
#pragma unroll
    for (int a = 0; a < CELLSORT_REG; a++)
      if (a < m) p[a] = v[a];
  } else if (m <= CELLSORT_LOCAL) {
    unsigned int v[CELLSORT_LOCAL];
    for (int a = 0; a < m; a++) {
      const unsigned x = p[a];
      int c = a;
      for (; c > 0 && v[c - 1] > x; c--) v[c] = v[c - 1];
      v[c] = x;
    }
    for (int a = 0; a < m; a++) p[a] = v[a];
  } else {
    for (int a = 1; a < m; a++) {
      const unsigned x = p[a];
      int c = a;
      for (; c > 0 && p[c - 1] > x; c--) p[c] = p[c - 1];
      p[c] = x;
    }
  }
}

/* The ranges longer than CELLSORT_REG, one warp each: every lane holds up
 * to two of the range's (distinct) indices and counts how many of the
 * range's are smaller, its index's place in ascending order; one thread
 * inserts beyond CELLSORT_WARP. The same order as k_cellsort's, in a
 * fraction of the time where most cells are long (one thread a 3D cell,
 * its insertion through local memory, was a tenth of the 3D step). */
__global__ void k_cellsort_warp(const int *__restrict__ begin, unsigned int *perm, int n_keys,
                                const struct dstats *st) {
  pdl_begin();
  const int k = (int)((blockIdx.x * blockDim.x + threadIdx.x) >> 5), lane = threadIdx.x & 31;
  if (k >= n_keys || st->plan.stop) return; /* the whole warp */
  const int b = begin[k], m = begin[k + 1] - b;
  if (m <= CELLSORT_REG) return;
  unsigned int *p = perm + b;
  if (m <= CELLSORT_WARP) {
    const unsigned v0 = lane < m ? p[lane] : 0xffffffffu; /* pads: larger than any index */
    const unsigned v1 = lane + 32 < m ? p[lane + 32] : 0xffffffffu;
    int r0 = 0, r1 = 0;
    for (int j = 0; j < 32; j++) {
      const unsigned a = __shfl_sync(0xffffffffu, v0, j), c = __shfl_sync(0xffffffffu, v1, j);
      r0 += (a < v0) + (c < v0);
      r1 += (a < v1) + (c < v1);
    }
    __syncwarp();
    if (lane < m) p[r0] = v0;
    if (lane + 32 < m) p[r1] = v1;
  } else if (lane == 0) {
    for (int a = 1; a < m; a++) {
      const unsigned x = p[a];
      int c = a;
      for (; c > 0 && p[c - 1] > x; c--) p[c] = p[c - 1];
      p[c] = x;
    }
  }
}

/* State fields into sorted order (dst[s] = src[perm[s]]) and the pressure
 * of the sorted density. */
struct permute_args {
  const unsigned int *perm;
  const unsigned int *key;
  unsigned int *key_d;
  const double *pos[WL_SPH_DIM_MAX];
  double *pos_d[WL_SPH_DIM_MAX];
  const wl_real *vel[WL_SPH_DIM_MAX];
  wl_real *vel_d[WL_SPH_DIM_MAX];
  const wl_real *rho;
  wl_real *rho_d, *press;
  const unsigned int *id;
  unsigned int *id_d;
  const unsigned char *kind, *body;
  unsigned char *kind_d, *body_d;
  /* Verlet only (rho_m1 NULL otherwise): the previous step's v and rho */
  const wl_real *vel_m1[WL_SPH_DIM_MAX], *rho_m1;
  wl_real *vel_m1_d[WL_SPH_DIM_MAX], *rho_m1_d;
};

/* RANK = 0: perm sorted (k_cellsort), sorted slot s takes particle
 * perm[s]. RANK = 1: perm as k_scatter left it, each key's range in the
 * order of the atomics; slot s's particle j goes to its place in the
 * stable order, the range's start plus the entries of the range smaller
 * than j (the indices are distinct): k_cellsort's permutation without its
 * kernel. A 2D range holds ~8 entries, so the count costs a few loads
 * that hit the lines the range's other threads load, against a whole
 * kernel's latencies in the step's chain: a Verlet step of the 2D flume of
 * 22 600 particles 41.0 to 39.5 us on the H100 (BENCHMARKS.md, "Ranks in
 * the permutation"). */
template <int DIM, int RANK>
__global__ void k_permute(struct permute_args a, struct wl_sph_const k, int n,
                          const int *__restrict__ begin, const struct dstats *st) {
  pdl_begin();
  const int t = tid();
  if (t >= n || st->plan.stop) return;
  const int j = (int)a.perm[t];
  /* every load before the first store: the arrays may alias for all the
   * compiler knows, and a store between two loads would keep them apart */
  const unsigned key = a.key[j], id = a.id[j];
  double pos[DIM];
  wl_real vel[DIM], vel_m1[DIM], rho_m1 = 0;
  for (int c = 0; c < DIM; c++) {
    pos[c] = a.pos[c][j];
    vel[c] = a.vel[c][j];
  }
  const wl_real rho = a.rho[j];
  const unsigned char kind = a.kind[j], body = a.body[j];
  if (a.rho_m1) {
    for (int c = 0; c < DIM; c++) vel_m1[c] = a.vel_m1[c][j];
    rho_m1 = a.rho_m1[j];
  }
  int s = t;
  if (RANK) {
    const int b = begin[key], e = begin[key + 1];
    int r = 0;
    for (int q = b; q < e; q++) r += a.perm[q] < (unsigned)j;
    s = b + r;
  }
  a.key_d[s] = key;
  for (int c = 0; c < DIM; c++) {
    a.pos_d[c][s] = pos[c];
    a.vel_d[c][s] = vel[c];
  }
  a.rho_d[s] = rho;
  a.press[s] = wl_sph_eos_p(&k, rho);
  a.id_d[s] = id;
  a.kind_d[s] = kind;
  a.body_d[s] = body;
  if (a.rho_m1) {
    for (int c = 0; c < DIM; c++) a.vel_m1_d[c][s] = vel_m1[c];
    a.rho_m1_d[s] = rho_m1;
  }
}

/* Block maxima of three non-negative doubles, one atomic max per block of
 * NT threads (a multiple of 32; one warp: no block barrier). */
template <int NT = THREADS>
static __device__ __forceinline__ void block_max3(double a, double b, double c, struct dstats *st) {
  for (int o = 16; o > 0; o >>= 1) {
    a = fmax(a, __shfl_xor_sync(0xffffffffu, a, o));
    b = fmax(b, __shfl_xor_sync(0xffffffffu, b, o));
    c = fmax(c, __shfl_xor_sync(0xffffffffu, c, o));
  }
  __shared__ double sh[3][NT / 32];
  const int w = threadIdx.x >> 5, l = threadIdx.x & 31;
  if (NT > 32 && l == 0) {
    sh[0][w] = a;
    sh[1][w] = b;
    sh[2][w] = c;
  }
  if (NT > 32) __syncthreads();
  if (threadIdx.x == 0) {
    for (int q = 1; q < NT / 32; q++) {
      a = fmax(a, sh[0][q]);
      b = fmax(b, sh[1][q]);
      c = fmax(c, sh[2][q]);
    }
    if (a > 0) atomicMax(&st->ace2, (unsigned long long)__double_as_longlong(a));
    if (b > 0) atomicMax(&st->vel2, (unsigned long long)__double_as_longlong(b));
    if (c > 0) atomicMax(&st->visc, (unsigned long long)__double_as_longlong(c));
  }
}

/* The one-thread-per-particle force loop: the shared wl_sph_gather_block
 * for one particle (lanes = 1). CUT = 1 (the product's loop in 2D, and in
 * 3D with double wl_real): candidates beyond the support are skipped
 * before their pair is evaluated, the same bits as CUT = 0, the reference
 * loop that only the tests build (WL_CUDA_TEST_LOOPS). In 3D a warp still
 * pays a pair evaluation for nearly every candidate, because one of its 32
 * particles nearly always has it inside the support: the split loop below
 * is the 3D one. */
/* Resident blocks per multiprocessor the 2D k_gather with the skip (the
 * product's 2D loop) is compiled for: 10 blocks of 128 threads cap it at
 * 48 registers without spills (ptxas), the occupancy of the earlier
 * hand-written copy of this loop; left to itself ptxas takes 56-64 and
 * fits 9 or 8 blocks. In 3D the cap would spill: none there. */
#ifndef WL_GATHER_MIN_BLOCKS
#define WL_GATHER_MIN_BLOCKS 10
#endif
template <int DIM, int LAM, int CUT>
__global__ void __launch_bounds__(THREADS, DIM == 2 && CUT ? WL_GATHER_MIN_BLOCKS : 1)
    k_gather(const struct wl_sph_const kp, const struct wl_sph_grid gp,
             const struct wl_sph_eval ep, int i0, int n, int nb, struct dstats *st) {
  pdl_begin();
  if (st->plan.stop) return;
  const struct wl_sph_const k = kp;
  const struct wl_sph_grid g = gp;
  const struct wl_sph_eval e = ep;
  const int i = i0 + tid();
  double a2 = 0, v2 = 0, vi = 0;
  if (i < n) {
    wl_sph_gather_block(DIM, LAM, 1, CUT, &k, &g, &e, nb, i, 1, 0);
    wl_sph_eval_dt_input(DIM, &e, i, nb, &a2, &v2, &vi);
  }
  block_max3(a2, v2, vi, st);
}

/* The sum of v over the R threads of a particle (consecutive lanes): a
 * butterfly, whose every step adds two partial sums commutatively, so all
 * R threads end with the same bits, whatever the timing. */
template <int R> static __device__ __forceinline__ wl_real lanes_sum(wl_real v) {
  for (int o = 1; o < R; o <<= 1) v += __shfl_xor_sync(0xffffffffu, v, o);
  return v;
}
template <int R> static __device__ __forceinline__ wl_real lanes_max(wl_real v) {
  for (int o = 1; o < R; o <<= 1) v = wl_sph_max_nonneg(v, __shfl_xor_sync(0xffffffffu, v, o));
  return v;
}
template <int R> static __device__ __forceinline__ void lanes_acc(struct wl_sph_acc *a) {
  for (int c = 0; c < 3; c++) a->a[c][0] = lanes_sum<R>(a->a[c][0]);
  a->cont[0] = lanes_sum<R>(a->cont[0]);
  a->ddt[0] = lanes_sum<R>(a->ddt[0]);
  a->wsum[0] = lanes_sum<R>(a->wsum[0]);
  a->visc[0] = lanes_max<R>(a->visc[0]);
}

/* Thread q of R's share [*c0, *c1) of the candidates [j0, j1). */
template <int R> static __device__ __forceinline__ void lanes_share(int j0, int j1, int q, int *c0,
                                                                     int *c1) {
  const int len = j1 - j0;
  *c0 = j0 + (len * q) / R;
  *c1 = j0 + (len * (q + 1)) / R;
}

/* wl_sph_gather_mirrors' rows (3D, the mirror planes' images) shared by
 * the R threads of a particle as its own rows are: one thread alone made
 * every warp beside a symmetry plane wait for it. */
template <int DIM, int LAM, int R>
static __device__ __forceinline__ void lanes_mirrors(const struct wl_sph_const *k,
                                                     const struct wl_sph_grid *g,
                                                     const struct wl_sph_eval *e,
                                                     const struct wl_sph_lanes *in, int fluid,
                                                     int cell, int q, struct wl_sph_acc *f,
                                                     struct wl_sph_acc *b) {
  if (DIM != 3 || !k->mirror) return;
  const int *const bf = e->begin + g->n_cells, *const bb = e->begin;
  int mf[2][6], ml[2][6], nm[2] = {0, 0}, c0, c1;
  wl_sph_cell_rows_mirrors(g, k->mirror, cell, 0, mf, ml, nm);
  for (int side = 0; side < 2; side++)
    for (int r = 0; r < nm[side]; r++) {
      lanes_share<R>(bf[mf[side][r]], bf[ml[side][r] + 1], q, &c0, &c1);
      if (fluid)
        wl_sph_gather_range(DIM, LAM, 1, 1, 1, 1, k, e, in, c0, c1, k->av_ff, k->lam_ff, side + 1,
                            f, 0);
      else
        wl_sph_gather_range(DIM, LAM, 0, 0, 1, 1, k, e, in, c0, c1, k->av_fb, k->lam_fb, side + 1,
                            f, 0);
    }
  if (fluid)
    for (int side = 0; side < 2; side++)
      for (int r = 0; r < nm[side]; r++) {
        lanes_share<R>(bb[mf[side][r]], bb[ml[side][r] + 1], q, &c0, &c1);
        wl_sph_gather_range(DIM, LAM, 1, 0, 1, 1, k, e, in, c0, c1, k->av_fb, k->lam_fb, side + 1,
                            b, 0);
      }
}

/* The lanes force loop (2D, and small 3D runs): R consecutive threads per
 * particle, each summing its share of every row (wl_sph_gather_range with
 * the cut-off skip, the rows in wl_sph_gather_block's order), then the R
 * partial sums added (lanes_sum) and the particle finished by its first
 * thread (wl_sph_finish); the mirror planes' rows (3D) shared the same way
 * (lanes_mirrors). The same terms as the reference loop, associated in R
 * runs: equal to it to float rounding, and the same bits on every run. */
template <int DIM, int LAM, int R>
__global__ void __launch_bounds__(THREADS)
    k_gather_lanes(const struct wl_sph_const kp, const struct wl_sph_grid gp,
                   const struct wl_sph_eval ep, int i0, int n, int nb, struct dstats *st) {
  pdl_begin();
  if (st->plan.stop) return;
  const struct wl_sph_const k = kp;
  const struct wl_sph_grid g = gp;
  const struct wl_sph_eval e = ep;
  const int t = tid(), q = t & (R - 1);
  const int i = i0 + t / R;
  const bool active = i < n;
  const int il = active ? i : n - 1; /* every thread takes part in the sums */
  const int nc = g.n_cells, fluid = il >= nb;
  const int cell = (int)e.key[il] - (fluid ? nc : 0);
  int first[9], last[9];
  const int nr = wl_sph_cell_rows(DIM, &g, cell, 0, first, last);
  const int *const bf = e.begin + nc, *const bb = e.begin;
  struct wl_sph_lanes in;
  for (int a = 0; a < DIM; a++) {
    in.x[a][0] = e.pos[a][il];
    in.v[a][0] = e.vel[a][il];
  }
  in.rho[0] = e.rho[il];
  in.inv_rho[0] = wl_sph_rcp(e.rho[il]);
  in.p[0] = e.press[il];
  struct wl_sph_acc f, b;
  for (int c = 0; c < 3; c++) f.a[c][0] = 0;
  f.cont[0] = f.ddt[0] = f.wsum[0] = f.visc[0] = 0;
  b = f;
  if (active) {
    int c0, c1;
    if (fluid) {
      for (int r = 0; r < nr; r++) {
        lanes_share<R>(bf[first[r]], bf[last[r] + 1], q, &c0, &c1);
        wl_sph_gather_range(DIM, LAM, 1, 1, 1, 1, &k, &e, &in, c0, c1, k.av_ff, k.lam_ff, 0, &f, 0);
      }
      for (int r = 0; r < nr; r++) {
        lanes_share<R>(bb[first[r]], bb[last[r] + 1], q, &c0, &c1);
        wl_sph_gather_range(DIM, LAM, 1, 0, 1, 1, &k, &e, &in, c0, c1, k.av_fb, k.lam_fb, 0, &b, 0);
      }
      lanes_mirrors<DIM, LAM, R>(&k, &g, &e, &in, 1, cell, q, &f, &b);
    } else {
      for (int r = 0; r < nr; r++) {
        lanes_share<R>(bf[first[r]], bf[last[r] + 1], q, &c0, &c1);
        wl_sph_gather_range(DIM, LAM, 0, 0, 1, 1, &k, &e, &in, c0, c1, k.av_fb, k.lam_fb, 0, &f, 0);
      }
      lanes_mirrors<DIM, LAM, R>(&k, &g, &e, &in, 0, cell, q, &f, &f);
    }
  }
  lanes_acc<R>(&f);
  lanes_acc<R>(&b);
  double a2 = 0, v2 = 0, vi = 0;
  if (active && q == 0) {
    if (fluid) wl_sph_finish(DIM, &k, &e, i, 1, in.rho[0], &f, &b, 0);
    else wl_sph_finish(DIM, &k, &e, i, 0, in.rho[0], &f, &f, 0);
    wl_sph_eval_dt_input(DIM, &e, i, nb, &a2, &v2, &vi);
  }
  block_max3(a2, v2, vi, st);
}

/* Candidates a warp stages in shared memory per batch (one 64-bit mask). */
enum { TILE = 64 };

/* The split force loop (3D runs of WL_LANES_MAX_PARTICLES_3D or more):
 * a warp's particles are split into segments of equal cell row (iy, iz)
 * and group; for each segment the warp walks the union of its particles'
 * neighbour rows (cells min ix - 1 .. max ix + 1 of each row), fluid rows
 * then boundary rows as wl_sph_gather_block does, 32 candidates at a time: each lane loads one, coalesced, and keeps
 * it if it lies within 2h of the segment's bounding box (a candidate
 * outside it is outside every segment particle's support: about 40 % of
 * a row's candidates go here). The kept ones are staged in shared memory,
 * in order, until a batch of 33-64 is full; then every lane of the segment
 * marks the staged candidates inside its support (r^2 < (2h)^2 (1 + 1e-4)
 * in float, a bit mask), and the batch's marked pairs are evaluated.
 *
 * Evaluation. Each lane evaluating its own marks (the loop this one
 * replaced, "tile") leaves most lanes idle: within one row the marks are
 * very uneven (the particles at the top of a cell have the row above in
 * reach, those at the bottom hardly any of it), and the warp runs as long
 * as its busiest lane (ncu: 10.5 of 32 lanes busy in the evaluations,
 * 3.6e8 evaluations/s on the H100, docs/history/BENCHMARKS-history.md).
 * Here the batch's marked
 * pairs, listed particle by particle in lane order (particle l's pairs at
 * positions excl_l .. excl_l + count_l - 1, ascending candidate), are split
 * into 32 equal blocks of consecutive positions, one per lane. A lane
 * evaluates its block in order, summing the pairs of each particle it meets
 * into a partial sum (a run), and writes each run to shared memory; then
 * each particle's owner adds its runs in list order. So every lane does the
 * same work, and every particle still adds its terms in ascending j,
 * grouped in runs of consecutive terms: the association differs from the
 * reference loop (by float rounding), not the terms. The result depends
 * only on the particle data and order, not on timing (no atomics).
 *
 * Positions enter the pair terms as float offsets from the segment's
 * origin (a particle of the segment), as DualSPHysics does relative to its
 * cells: float keeps ~6e-8 of the offset, and a segment with its rows
 * spans a few cells (~15 h), so dx is exact to ~1e-6 h, against ~1e-7 of
 * dx for the double difference of the other loops; float arithmetic in the
 * pair terms rounds at the same level. It halves the staged bytes, so more
 * warps fit an SM, which this latency-bound loop needs. Everything staged
 * is float: a build with double wl_real (WL_REAL_DOUBLE) uses the fast
 * loop instead. */
/* Threads per block of the split loop: one warp. A block's registers and
 * shared memory are freed only when all its warps are done, and a warp
 * done with its particles waited for its slowest sibling: with blocks of
 * four warps ncu sampled 15 % of the warps of the loop waiting at the exit
 * barrier, slots no new block could use. WL_SPLIT_THREADS = 128 builds the
 * four-warp blocks for comparison (docs/history/BENCHMARKS-history.md). */
#ifndef WL_SPLIT_THREADS
#define WL_SPLIT_THREADS 32
#endif
/* Resident threads per multiprocessor the split loop is compiled for: 1024
 * caps it at 64 registers (1024 x 64 = the register file) and needs 32
 * blocks of one warp (the most an SM holds) or 8 of four; 1024, 896 and
 * 768 threads ran at 4.8e8, 4.7e8 and 4.4e8 evaluations/s on the H100 (3D
 * 1M, before the staging filter): latency-bound, occupancy pays. 32 blocks
 * take 32 x (6 KB + 1 KB the hardware reserves a block) = 224 KB of shared
 * memory, within the H100's 228 KB when the carveout asks for the most
 * (cuda_init). */
#ifndef WL_SPLIT_MIN_BLOCKS
#define WL_SPLIT_MIN_BLOCKS (1024 / WL_SPLIT_THREADS)
#endif
/* Run slots: 0..31 a particle's first run in the batch, 32 + t the run
 * that starts at lane t's first position inside a particle's pairs. */
enum { SPLIT_RUNS = 64 };
struct split_warp {
  float4 cr[TILE]; /* candidates: offset c from the segment's origin, (|c|^2 - skip2)/2 */
  float4 cv[TILE]; /* velocity, pressure */
  float4 cj[TILE]; /* rho; wl_sph_pair_j: 1/rho, m/rho; unused */
  float4 sr[32];   /* the warp's own particles: offset from the segment's origin, rho */
  float4 sv[32];   /* velocity, pressure */
  wl_real sinv[32]; /* 1/rho */
  unsigned long long mask[32];
  int excl[32];
  /* a[3], cont, ddt, visc of each run; visc < 0: no pair of the run
   * inside the support (the DDT2 switch's "any boundary neighbour") */
  wl_real run[6][SPLIT_RUNS];
};

/* Marks of the 32 staged candidates cr[0..31] inside skip2 = (2h)^2 (1 +
 * 1e-4) of self (float offsets from the segment's origin), bit s for cr[s];
 * the caller masks off the slots beyond the batch. Unrolled and branch-free.
 *
 * |s - c|^2 < skip2 is tested as t = hs + hc - s.c < 0, with hs = |s|^2/2
 * (per lane) and hc = (|c|^2 - skip2)/2 (staged with the candidate): an add
 * and three FMAs, where the differences cost three adds, a multiply and
 * two FMAs. The expanded form cancels: offsets reach ~8h, so its terms are
 * up to ~32 h^2 and their float rounding ~1e-5 h^2, 40 times inside the
 * margin of 4e-4 h^2 in skip2. A pair marked beyond 2h adds exact zeros
 * (sph/kernel.h), so only a pair inside 2h left unmarked would be an
 * error, and the margin rules it out. The mark is t's sign bit, so t = -0
 * (exactly on the margin) counts as inside, which is as good. */
template <int DIM>
static __device__ __forceinline__ unsigned split_marks32(const float4 *cr, float4 self,
                                                         float hs) {
  unsigned m = 0;
#pragma unroll
  for (int s = 0; s < 32; s++) {
    const float4 c = cr[s];
    float t = hs + c.w;
    t = fmaf(-self.x, c.x, t);
    if (DIM == 3) t = fmaf(-self.y, c.y, t);
    t = fmaf(-self.z, c.z, t);
    /* t's sign bit shifted in at the bottom: one funnel shift, where
     * setting bit s costs a compare, a select and half an OR */
    m = __funnelshift_l(__float_as_uint(t), m, 1);
  }
  return __brev(m); /* candidate 0 went in first, so it is bit 31 */
}

/* Add pair (particle ri, vi, inv_rho_i; staged candidate s) to lane 0 of
 * acc: the shared pair body (sph/gather.h wl_sph_pair_sum) from float
 * offsets. */
template <int DIM, int LAM, int WANT_ACE, int WITH_DDT>
static __device__ __forceinline__ void split_pair(const struct wl_sph_const *k,
                                                  const struct split_warp *w, int s, float4 ri,
                                                  float4 vi, wl_real inv_rho_i, wl_real av,
                                                  wl_real lam, struct wl_sph_acc *acc) {
  const float4 rj = w->cr[s], vj = w->cv[s];
  const float4 pj = w->cj[s];
  wl_sph_pair_sum(DIM, LAM, WANT_ACE, WITH_DDT, k, ri.x - rj.x,
                  DIM == 3 ? ri.y - rj.y : WL_R(0.0), ri.z - rj.z, vi.x - vj.x,
                  DIM == 3 ? vi.y - vj.y : WL_R(0.0), vi.z - vj.z, ri.w, inv_rho_i, vi.w, pj.x,
                  pj.y, pj.z, vj.w, av, lam, acc, 0);
}

/* Lane 0 of acc to 0. */
static __device__ __forceinline__ void split_zero(struct wl_sph_acc *r) {
  for (int c = 0; c < 3; c++) r->a[c][0] = 0;
  r->cont[0] = r->ddt[0] = r->wsum[0] = r->visc[0] = 0;
}

static __device__ __forceinline__ void split_store(struct split_warp *w, int slot,
                                                   const struct wl_sph_acc *r) {
  for (int c = 0; c < 3; c++) w->run[c][slot] = r->a[c][0];
  w->run[3][slot] = r->cont[0];
  w->run[4][slot] = r->ddt[0];
  w->run[5][slot] = r->wsum[0] > 0 ? r->visc[0] : WL_R(-1.0);
}

static __device__ __forceinline__ void split_add(const struct split_warp *w, int slot,
                                                 struct wl_sph_acc *acc) {
  for (int c = 0; c < 3; c++) acc->a[c][0] += w->run[c][slot];
  acc->cont[0] += w->run[3][slot];
  acc->ddt[0] += w->run[4][slot];
  const wl_real v = w->run[5][slot];
  if (v >= 0) acc->wsum[0] = WL_R(1.0);
  acc->visc[0] = wl_sph_max_nonneg(acc->visc[0], v);
}

/* x less its k lowest set bits (0 <= k < popc(x), or k = 0): the position
 * of the k-th set bit by binary search on bit counts. */
static __device__ __forceinline__ unsigned split_drop_low(unsigned x, int k) {
  int pos = 0;
#pragma unroll
  for (int width = 16; width; width >>= 1) {
    const int c = __popc((x >> pos) & ((1u << width) - 1u));
    if (c <= k) {
      k -= c;
      pos += width;
    }
  }
  return x & (~0u << pos);
}

/* One batch: the marks m of each lane (count mc, list positions excl ..,
 * total for the warp) are evaluated in 32 equal blocks and the runs added
 * to each owner's acc. */
template <int DIM, int LAM, int WANT_ACE, int WITH_DDT>
static __device__ __forceinline__ void split_batch(const struct wl_sph_const *k,
                                                   struct split_warp *w, int lane,
                                                   unsigned long long m, int mc, int excl,
                                                   int total, wl_real av, wl_real lam,
                                                   struct wl_sph_acc *acc) {
  w->mask[lane] = m;
  w->excl[lane] = excl;
  const unsigned with_marks = __ballot_sync(0xffffffffu, mc > 0);
  __syncwarp();
  const int q0 = (lane * total) >> 5, q1 = ((lane + 1) * total) >> 5;
  if (q0 < q1) {
    /* the particle whose pairs hold position q0: the last lane l with
     * excl[l] <= q0 (a lane without marks shares its excl with the next) */
    int l = 0;
    for (int step = 16; step; step >>= 1)
      if (l + step < 32 && w->excl[l + step] <= q0) l += step;
    /* the particle's marks as two 32-bit halves (cheaper bit scans), less
     * the q0 - excl[l] before q0 (branch-free: a loop over them ran at a
     * third of the lanes): the half being scanned (cur, its bit s is
     * candidate base + s) and the upper half still to come (nxt) */
    unsigned long long mm = w->mask[l];
    unsigned cur, nxt;
    int base;
    {
      const unsigned mlo = (unsigned)mm, mhi = (unsigned)(mm >> 32);
      const int skip = q0 - w->excl[l], plo = __popc(mlo);
      const bool in_hi = skip >= plo;
      cur = split_drop_low(in_hi ? mhi : mlo, in_hi ? skip - plo : skip);
      nxt = in_hi ? 0u : mhi;
      base = in_hi ? 32 : 0;
    }
    int slot = q0 == w->excl[l] ? l : 32 + lane;
    float4 ri = w->sr[l], vi = w->sv[l];
    wl_real inv_rho_i = w->sinv[l];
    struct wl_sph_acc r;
    split_zero(&r);
    for (int left = q1 - q0; left > 0; left--) {
      if (!cur) { /* rare: one of these per particle and half */
        if (nxt) { /* on to the upper half */
          cur = nxt;
          nxt = 0u;
          base = 32;
        } else { /* this particle's pairs are done: the next one's */
          split_store(w, slot, &r);
          split_zero(&r);
          l = __ffs(with_marks & (0xfffffffeu << l)) - 1; /* next lane with marks */
          mm = w->mask[l];
          cur = (unsigned)mm;
          nxt = (unsigned)(mm >> 32);
          base = 0;
          if (!cur) {
            cur = nxt;
            nxt = 0u;
            base = 32;
          }
          slot = l;
          ri = w->sr[l];
          vi = w->sv[l];
          inv_rho_i = w->sinv[l];
        }
      }
      const int s = __ffs(cur) - 1 + base;
      cur &= cur - 1;
      split_pair<DIM, LAM, WANT_ACE, WITH_DDT>(k, w, s, ri, vi, inv_rho_i, av, lam, &r);
    }
    split_store(w, slot, &r);
  }
  __syncwarp();
  if (mc) {
    /* my runs in list order: my first, then those starting at the blocks
     * that begin inside my positions (a block's start q0 = t total / 32;
     * only a non-empty block wrote one) */
    split_add(w, lane, acc);
    const int incl = excl + mc;
    /* unsigned: a signed division costs about twice the instructions */
    for (int t = (int)((unsigned)(excl * 32) / (unsigned)total) + 1; t < 32; t++) {
      const int b = (t * total) >> 5;
      if (b >= incl) break;
      if (b > excl && ((t + 1) * total) >> 5 > b) split_add(w, 32 + t, acc);
    }
  }
}

/* One batch of `fill` staged candidates of group grp: the marks of the
 * segment's lanes, their list positions, and split_batch into f or b. */
template <int DIM, int LAM>
static __device__ __forceinline__ void split_group(const struct wl_sph_const *k,
                                                   struct split_warp *w, int lane, bool in_seg,
                                                   float4 self, int fill, int grp,
                                                   int seg_fluid, struct wl_sph_acc *f,
                                                   struct wl_sph_acc *b) {
  __syncwarp();
  unsigned long long m = 0;
  if (in_seg) {
    /* recomputed per batch: a register less across the walk */
    const float hs = 0.5f * (self.x * self.x + self.y * self.y + self.z * self.z);
    m = split_marks32<DIM>(w->cr, self, hs);
    if (fill > 32) m |= (unsigned long long)split_marks32<DIM>(w->cr + 32, self, hs) << 32;
    if (fill < 64) m &= (1ull << fill) - 1ull;
  }
  /* list positions: exclusive scan of the mark counts over lanes */
  const int mc = __popcll(m);
  int incl = mc;
  for (int o = 1; o < 32; o <<= 1) {
    const int v = __shfl_up_sync(0xffffffffu, incl, o);
    if (lane >= o) incl += v;
  }
  const int total = __shfl_sync(0xffffffffu, incl, 31);
  if (total) {
    if (grp == 1 && seg_fluid)
      split_batch<DIM, LAM, 1, 1>(k, w, lane, m, mc, incl - mc, total, k->av_ff, k->lam_ff, f);
    else if (grp == 1)
      split_batch<DIM, LAM, 0, 0>(k, w, lane, m, mc, incl - mc, total, k->av_fb, k->lam_fb, f);
    else
      split_batch<DIM, LAM, 1, 0>(k, w, lane, m, mc, incl - mc, total, k->av_fb, k->lam_fb, b);
  }
  __syncwarp(); /* the staging area is reused */
}

template <int DIM, int LAM>
__global__ void __launch_bounds__(WL_SPLIT_THREADS, WL_SPLIT_MIN_BLOCKS)
    k_gather_split(const struct wl_sph_const kp, const struct wl_sph_grid gp,
                   const struct wl_sph_eval ep, int i0, int n, int nb, float skip2,
                   struct dstats *st) {
  pdl_begin();
  __shared__ struct split_warp warps[WL_SPLIT_THREADS / 32];
  if (st->plan.stop) return;
  const struct wl_sph_const k = kp;
  const struct wl_sph_grid g = gp;
  const struct wl_sph_eval e = ep;
  const int i = i0 + tid(), lane = threadIdx.x & 31;
  struct split_warp *const w = warps + (threadIdx.x >> 5);
  const int nc = g.n_cells, nx = g.n[0], az = DIM - 1;
  const bool active = i < n;
  int fluid = 0, cx = 0, rest = 0;
  /* the particle's state stays in shared memory (sr, sv, sinv) during the
   * neighbour walk and is read again at the end: registers are what limits
   * the warps per SM */
  if (active) {
    fluid = i >= nb;
    const int cell = (int)e.key[i] - (fluid ? nc : 0);
    cx = cell % nx;
    rest = cell / nx;
    const wl_real rho = e.rho[i];
    w->sv[lane] = make_float4(e.vel[0][i], DIM == 3 ? e.vel[1][i] : WL_R(0.0), e.vel[az][i],
                              e.press[i]);
    w->sinv[lane] = wl_sph_rcp(rho);
    w->sr[lane].w = rho;
  } else {
    w->sv[lane] = make_float4(0.f, 0.f, 0.f, 0.f);
    w->sinv[lane] = WL_R(1.0);
    w->sr[lane].w = WL_R(1.0);
  }
  struct wl_sph_acc f, b;
  split_zero(&f);
  split_zero(&b);
  const unsigned seg_id = ((unsigned)fluid << 31) | (unsigned)rest;
  unsigned pending = __ballot_sync(0xffffffffu, active);
  while (pending) {
    const int leader = __ffs((int)pending) - 1;
    const unsigned lead_id = __shfl_sync(0xffffffffu, seg_id, leader);
    const bool in_seg = ((pending >> lane) & 1u) && seg_id == lead_id;
    pending &= ~__ballot_sync(0xffffffffu, in_seg);
    const int x0 = wl_sph_maxi(__reduce_min_sync(0xffffffffu, in_seg ? cx : 0x7fffffff) - 1, 0);
    const int x1 = wl_sph_mini(__reduce_max_sync(0xffffffffu, in_seg ? cx : -1) + 1, nx - 1);
    const int il = active ? i : n - 1;
    const double x = e.pos[0][il], y = DIM == 3 ? e.pos[1][il] : 0.0, z = e.pos[az][il];
    const double o0 = __shfl_sync(0xffffffffu, x, leader);
    const double o1 = __shfl_sync(0xffffffffu, y, leader);
    const double o2 = __shfl_sync(0xffffffffu, z, leader);
    /* every lane's offset from this segment's origin (lanes of other
     * segments are never paired in it) */
    const float4 self = make_float4((float)(x - o0), (float)(y - o1), (float)(z - o2),
                                    w->sr[lane].w);
    w->sr[lane] = self;
    const int seg_fluid = (int)(lead_id >> 31);
    const int seg_rest = (int)(lead_id & 0x7fffffffu);
    const int iy = DIM == 3 ? seg_rest % g.n[1] : 0, iz = DIM == 3 ? seg_rest / g.n[1] : seg_rest;
    const int nz = DIM == 3 ? g.n[2] : g.n[1];
    /* the segment's bounding box (float offsets), for the staging filter */
    float4 blo = in_seg ? self : make_float4(3e38f, 3e38f, 3e38f, 0.f);
    float4 bhi = in_seg ? self : make_float4(-3e38f, -3e38f, -3e38f, 0.f);
    for (int o = 16; o; o >>= 1) {
      blo.x = fminf(blo.x, __shfl_xor_sync(0xffffffffu, blo.x, o));
      blo.y = fminf(blo.y, __shfl_xor_sync(0xffffffffu, blo.y, o));
      blo.z = fminf(blo.z, __shfl_xor_sync(0xffffffffu, blo.z, o));
      bhi.x = fmaxf(bhi.x, __shfl_xor_sync(0xffffffffu, bhi.x, o));
      bhi.y = fmaxf(bhi.y, __shfl_xor_sync(0xffffffffu, bhi.y, o));
      bhi.z = fmaxf(bhi.z, __shfl_xor_sync(0xffffffffu, bhi.z, o));
    }
    for (int grp = 1; grp >= (seg_fluid ? 0 : 1); grp--) {
      const int *const bg = e.begin + (grp ? nc : 0);
      int fill = 0; /* candidates staged for the next batch */
      for (int row = 0; row < (DIM == 3 ? 9 : 3); row++) {
        const int dz = DIM == 3 ? row / 3 - 1 : row - 1, dy = DIM == 3 ? row % 3 - 1 : 0;
        const int jz = iz + dz, jy = iy + dy;
        const bool row_ok =
            jz >= 0 && jz < nz && (DIM != 3 || (jy >= 0 && jy < g.n[1]));
        const int base = DIM == 3 ? (jz * g.n[1] + jy) * nx : jz * nx;
        const int j0 = row_ok ? bg[base + x0] : 0, j1 = row_ok ? bg[base + x1 + 1] : 0;
        /* the row's candidates, 32 at a time: those within 2h of the
         * segment's box are staged in order (a candidate out of it is out
         * of every segment particle's support) */
        for (int c0 = j0; c0 < j1; c0 += 32) {
          const int j = c0 + lane;
          bool keep = false;
          float4 cr = make_float4(0.f, 0.f, 0.f, 0.f);
          /* the rest of the candidate's data is loaded with its position,
           * before the filter: one trip to memory instead of two for the
           * ~60 % kept (a third more bytes loaded, mostly from L2; fewer
           * spills, +0.9 % at 1M and 8M on the H100) */
          float4 cv = make_float4(0.f, 0.f, 0.f, 0.f);
          wl_real rho_j = WL_R(1.0);
          if (j < j1) {
            rho_j = e.rho[j];
            cv = make_float4(e.vel[0][j], DIM == 3 ? e.vel[1][j] : WL_R(0.0), e.vel[az][j],
                             e.press[j]);
            cr.x = (float)(e.pos[0][j] - o0);
            cr.y = DIM == 3 ? (float)(e.pos[1][j] - o1) : 0.f;
            cr.z = (float)(e.pos[az][j] - o2);
            const float ex = fmaxf(fmaxf(blo.x - cr.x, cr.x - bhi.x), 0.f);
            const float ey = DIM == 3 ? fmaxf(fmaxf(blo.y - cr.y, cr.y - bhi.y), 0.f) : 0.f;
            const float ez = fmaxf(fmaxf(blo.z - cr.z, cr.z - bhi.z), 0.f);
            keep = ex * ex + ey * ey + ez * ez < skip2;
          }
          const unsigned kept = __ballot_sync(0xffffffffu, keep);
          if (keep) {
            const int slot = fill + __popc(kept & ((1u << lane) - 1u));
            cr.w = 0.5f * (cr.x * cr.x + cr.y * cr.y + cr.z * cr.z - skip2);
            w->cr[slot] = cr;
            w->cv[slot] = cv;
            wl_real inv_rho_j, vol_j;
            wl_sph_pair_j_of(seg_fluid, grp, &k, rho_j, &inv_rho_j, &vol_j);
            w->cj[slot] = make_float4(rho_j, inv_rho_j, vol_j, 0.f);
          }
          fill += __popc(kept);
          if (fill > TILE - 32) { /* the next 32 might not fit: evaluate */
            split_group<DIM, LAM>(&k, w, lane, in_seg, self, fill, grp, seg_fluid, &f, &b);
            fill = 0;
          }
        }
      }
      if (fill)
        split_group<DIM, LAM>(&k, w, lane, in_seg, self, fill, grp, seg_fluid, &f, &b);
    }
  }
  double a2 = 0, v2 = 0, vmax = 0;
  if (active) {
    /* the mirror planes' rows, per thread (only the particles beside a
     * plane have any); the walk above did the ordinary rows of f and b */
    struct wl_sph_lanes in;
    const float4 sv = w->sv[lane];
    for (int a = 0; a < DIM; a++) in.x[a][0] = e.pos[a][i];
    in.v[0][0] = sv.x;
    if (DIM == 3) in.v[1][0] = sv.y;
    in.v[az][0] = sv.z;
    in.rho[0] = w->sr[lane].w;
    in.inv_rho[0] = w->sinv[lane];
    in.p[0] = sv.w;
    wl_sph_gather_mirrors(DIM, LAM, 1, 1, &k, &g, &e, &in, fluid, cx + nx * rest, 0, &f, &b);
    wl_sph_finish(DIM, &k, &e, i, fluid, in.rho[0], &f, &b, 0);
    wl_sph_eval_dt_input(DIM, &e, i, nb, &a2, &v2, &vmax);
  }
  block_max3<WL_SPLIT_THREADS>(a2, v2, vmax, st);
}

/* The wall condition's outputs (sph/wall.h: the boundary particles'
 * density and pressure from the fluid's, before the fluid's force loop
 * reads them) and what picks a moving body's acceleration [m/s^2] from
 * the plan. */
struct wallin {
  const unsigned char *kind, *body;
  wl_real *rho, *press;
};
/* The wall condition with R consecutive threads per boundary particle:
 * each sums its share of every fluid row, the mirror planes' rows too in
 * 3D (wl_sph_wall_range), the R sums are added (lanes_sum) and the first
 * thread stores the result (wl_sph_wall_store): wl_sph_wall_sample's
 * terms, associated in R runs. A wall particle walks ~70 candidates in
 * 2D and ~250 in 3D; one thread each leaves a flume's few thousand (3D:
 * tens of thousands) wall particles on a fraction of the GPU's threads,
 * each walking its candidates one after the other. */
template <int DIM, int R>
__global__ void __launch_bounds__(THREADS)
    k_wall_lanes(const struct wl_sph_const kp, const struct wl_sph_grid gp,
                 const struct wl_sph_eval ep, int nb, const struct wallin w,
                 const struct dstats *st) {
  pdl_begin();
  if (st->plan.stop) return;
  const struct wl_sph_const k = kp;
  const struct wl_sph_grid g = gp;
  const struct wl_sph_eval e = ep;
  const int t = tid(), q = t & (R - 1), i = t / R;
  const bool active = i < nb;
  const int il = active ? i : nb - 1;
  const int cell = (int)e.key[il];
  int first[9], last[9];
  const int nr = wl_sph_cell_rows(DIM, &g, cell, 0, first, last);
  const int *const bf = e.begin + g.n_cells;
  const double xi[3] = {e.pos[0][il], DIM == 3 ? e.pos[1][il] : 0.0, e.pos[DIM - 1][il]};
  wl_real ga[3];
  wl_sph_wall_ga(DIM, &k, w.kind[il] == WL_KIND_MOVING ? st->plan.body_acc[w.body[il]] : NULL, ga);
  struct wl_sph_wall_acc s = {0, 0};
  if (active) {
    int c0, c1;
    for (int r = 0; r < nr; r++) {
      lanes_share<R>(bf[first[r]], bf[last[r] + 1], q, &c0, &c1);
      wl_sph_wall_range(DIM, &k, &e, xi, ga, c0, c1, 0, &s);
    }
    if (DIM == 3 && k.mirror) {
      int mfirst[2][6], mlast[2][6], nm[2] = {0, 0};
      wl_sph_cell_rows_mirrors(&g, k.mirror, cell, 0, mfirst, mlast, nm);
      for (int side = 0; side < 2; side++)
        for (int r = 0; r < nm[side]; r++) {
          lanes_share<R>(bf[mfirst[side][r]], bf[mlast[side][r] + 1], q, &c0, &c1);
          wl_sph_wall_range(DIM, &k, &e, xi, ga, c0, c1, side + 1, &s);
        }
    }
  }
  s.sw = lanes_sum<R>(s.sw);
  s.spw = lanes_sum<R>(s.spw);
  if (active && q == 0) wl_sph_wall_store(DIM, &k, &e, &s, i, w.rho, w.press);
}

/* Predictor (sph/integrate.h) and the pressure of the half-step density. */
/* Particle shifting of the step (sph/shift.h), one thread per fluid
 * particle, from the sorted step-start state. */
struct shiftptr {
  wl_real *s[WL_SPH_DIM_MAX];
};
template <int DIM>
__global__ void __launch_bounds__(THREADS)
    k_shift(const struct wl_sph_const kp, const struct wl_sph_grid gp, const struct wl_sph_eval ep,
            int n, int nb, struct shiftptr sp, const struct dstats *st) {
  pdl_begin();
  const struct wl_sph_const k = kp;
  const struct wl_sph_grid g = gp;
  const struct wl_sph_eval e = ep;
  const int i = nb + tid();
  if (i < n && !st->plan.stop) wl_sph_shift(DIM, &k, &g, &e, nb, i, st->plan.dt, sp.s);
}

template <int DIM>
__global__ void k_predict(struct wl_sph_const kp, struct wl_particles p, int n,
                          const struct dstats *st) {
  pdl_begin();
  const int i = tid();
  if (i >= n || st->plan.stop) return;
  const struct wl_sph_const k = kp;
  wl_sph_predict(DIM, &k, &p, st->plan.dt, st->plan.body_vel, i);
  p.press[i] = wl_sph_eos_p(&k, p.rho_h[i]);
}

/* The fault record of faulty particle f, written by another block of
 * the kernel that calls it: its fields read past L1 (__ldcg), which may
 * hold the lines from before their update, into a one-particle view for
 * the shared guard. */
template <int DIM>
static __device__ void fault_record(const struct wl_sph_const *k, const struct wl_particles *pp,
                                    int f, const struct dmeta *m,
                                    const struct wl_sph_wall *walls, struct dstats *st) {
  double pos[WL_SPH_DIM_MAX] = {0, 0, 0};
  wl_real vel[WL_SPH_DIM_MAX] = {0, 0, 0}, rho = __ldcg(&pp->rho[f]);
  unsigned char kind = pp->kind[f], body = pp->body[f]; /* not written by the update */
  for (int a = 0; a < DIM; a++) {
    pos[a] = __ldcg(&pp->pos[a][f]);
    vel[a] = __ldcg(&pp->vel[a][f]);
  }
  if (kind == WL_KIND_FLUID) body = __ldcg((const unsigned char *)&pp->body[f]); /* excluded */
  struct wl_particles one;
  memset(&one, 0, sizeof one);
  one.dim = DIM;
  one.n = one.capacity = 1;
  for (int a = 0; a < DIM; a++) {
    one.pos[a] = &pos[a];
    one.vel[a] = &vel[a];
  }
  one.rho = &rho;
  one.kind = &kind;
  one.body = &body;
  int w = -1;
  st->fault = wl_sph_guard(DIM, k, &one, m->lo, m->hi, walls, m->n_walls, 0, &w);
  st->wall = w;
  st->id = __ldcg(&pp->id[f]);
  st->kind = kind;
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    st->pos[a] = a < DIM ? pos[a] : 0;
    st->vel[a] = a < DIM ? (double)vel[a] : 0;
  }
  st->rho = rho;
}

/* The plan of a block's next step on the device, as the host's loop
 * (src/sph/sim.c wl_sph_sim_run and wl_sph_sim_step) would choose it, by
 * the driver's rules of backend.h; or the block's stop. On the block's
 * state and the plan's fields in registers (the caller loads and stores
 * them). */
struct dnext {
  double dt, dt_prev;
  int euler, stop;
};
static __device__ void plan_next(const struct wl_sph_const *k, struct dblock *b, struct dnext *pl) {
  const double dt_cfl = b->dt_next, rest = b->t_out - b->t;
  int why = -1;
  if (b->taken >= b->max_steps) why = WL_SPH_BLOCK_COUNT;
  else if (!(rest > 0)) why = WL_SPH_BLOCK_REACHED;
  else if (wl_sph_dt_collapsed(k, dt_cfl, b->dt_initial)) why = WL_SPH_BLOCK_COLLAPSE;
  if (why >= 0) {
    b->why = why;
    pl->stop = 1;
    return;
  }
  int lands;
  pl->dt = wl_sph_dt_limit(wl_sph_dt_toward(rest, dt_cfl, &lands), dt_cfl);
  pl->dt_prev = b->dt_last;
  pl->euler = k->integrator == WL_SPH_VERLET && wl_sph_verlet_euler(k, (long)b->step);
  b->lands = lands;
}

/* The plan's fields that plan_next sets, stored. */
static __device__ void store_next(struct dplan *p, const struct dnext *pl) {
  p->dt = pl->dt;
  p->dt_prev = pl->dt_prev;
  p->euler = pl->euler;
  p->stop = pl->stop;
}

/* A block's first plan (one thread). */
__global__ void k_plan(struct wl_sph_const kp, struct dstats *st) {
  pdl_begin();
  const struct wl_sph_const k = kp;
  struct dblock b = st->blk;
  struct dnext pl = {st->plan.dt, st->plan.dt_prev, st->plan.euler, st->plan.stop};
  plan_next(&k, &b, &pl);
  st->blk = b;
  store_next(&st->plan, &pl);
}

/* The end of a step (one thread, after every particle's update): the fault
 * record of the first faulty particle; in a block, the step counted as
 * the host's loop counts it (time, step, the next CFL step, the guards in
 * its order) and the next one planned, or the block stopped after it. The
 * counters the update's blocks added to are read atomically (past L1).
 * One thread runs this with nothing to hide its latencies behind, so
 * every value it reads is loaded at once, before any is used, computed on
 * in registers and stored at the end: read as they are used, each load
 * waited for the branch before it (BENCHMARKS.md, "the cost of a step"). */
template <int DIM>
static __device__ void end_step(const struct wl_sph_const *k, const struct wl_particles *p, int n,
                                const struct dmeta *m, const struct wl_sph_walls_sh *ws,
                                struct dstats *st) {
  const int f = atomicAdd(&st->first, 0);
  const unsigned long long limited = atomicAdd(&st->limited, 0ull);
  const unsigned long long excluded = atomicAdd(&st->excluded, 0ull);
  const int is_block = st->plan.block;
  const double dt = st->plan.dt;
  struct dnext pl = {dt, st->plan.dt_prev, st->plan.euler, st->plan.stop};
  struct dblock b = st->blk;
  const unsigned long long bits[3] = {st->ace2, st->vel2, st->visc};
  if (f < n) fault_record<DIM>(k, p, f, m, ws->w, st);
  if (!is_block) return;
  b.t += dt;
  b.dt_last = dt;
  b.step++;
  b.taken++;
  double ace2, vel2, visc;
  memcpy(&ace2, &bits[0], sizeof ace2);
  memcpy(&vel2, &bits[1], sizeof vel2);
  memcpy(&visc, &bits[2], sizeof visc);
  struct wl_sph_step_out o;
  wl_sph_step_dt(k, ace2, vel2, visc, &o);
  b.dt_next = o.dt_next;
  b.limited += limited;
  b.excluded += excluded;
  b.n_excluded += (long long)excluded;
  int why = -1;
  if (f < n) why = WL_SPH_BLOCK_FAULT;
  else if (wl_sph_excluded_too_many((long)b.n_excluded, (long)b.n_fluid)) why = WL_SPH_BLOCK_EXCLUDED;
  else if (b.lands) {
    b.t = b.t_out; /* exact, against rounding of t + dt */
    why = WL_SPH_BLOCK_LANDED;
  }
  if (why >= 0) {
    b.why = why;
    pl.stop = 1;
  } else {
    plan_next(k, &b, &pl);
  }
  st->blk = b;
  store_next(&st->plan, &pl);
}

/* The update (when update != 0: the corrector, or the Verlet step with
 * its Euler flag, as planned) and guard, the lowest faulty index; then
 * each particle's key of its new position and the particles per key
 * (count, which the step's k_scatter left at 0, and the block sums, which
 * k_cellsort, or in 2D k_scatter, zeroed), for the next step's sort; and
 * the end of the step (end_step) by the block that finishes last, so that
 * a step needs no one-thread kernel of its own. The wall faces are read
 * from shared memory (the limiter tests every face; the guard only where
 * the limiter moved the particle, sph/guard.h wl_sph_guard_faces). */
template <int DIM>
__global__ void __launch_bounds__(THREADS)
    k_update(struct wl_sph_const kp, struct wl_sph_grid gp, struct wl_particles p, int n,
             int update, const struct dmeta *m, int *count, int *bsum, struct dstats *st) {
  pdl_begin();
  if (st->plan.stop) return; /* the same for every block: only the last one sets it */
  __shared__ struct wl_sph_walls_sh ws;
  __shared__ bool last;
  const int nw = m->n_walls;
  for (int w = threadIdx.x; w < nw; w += blockDim.x) ws.w[w] = m->walls[w];
  __syncthreads();
  const int i = tid();
  const struct wl_sph_const k = kp;
  if (i < n) {
    const struct dplan *pl = &st->plan;
    if (update && k.integrator == WL_SPH_VERLET)
      wl_sph_verlet(DIM, &k, &p, pl->dt, pl->dt_prev, pl->body_vel, pl->euler, i);
    else if (update)
      wl_sph_correct(DIM, &k, &p, pl->dt, pl->body_vel, i);
    const int limiter = update && k.wall_limiter;
    const int moved = limiter && wl_sph_wall_limit(DIM, &p, ws.w, nw, k.penetration, i);
    if (moved) atomicAdd(&st->limited, 1ull);
    if (update && wl_sph_exclude(DIM, &p, m->lo, m->hi, i)) atomicAdd(&st->excluded, 1ull);
    int w = -1;
    if (wl_sph_guard(DIM, &k, &p, m->lo, m->hi, ws.w, wl_sph_guard_faces(limiter, moved, nw), i,
                     &w))
      atomicMin(&st->first, i);
    const struct wl_sph_grid g = gp;
    const unsigned group = p.kind[i] == WL_KIND_FLUID ? 1u : 0u;
    const unsigned key = group * (unsigned)g.n_cells + (unsigned)wl_sph_cell_of(DIM, &g, p.pos, i);
    p.key[i] = key;
    count_key(key, count, bsum);
  }
  /* the last block to finish ends the step: the barrier orders the block's
   * writes before thread 0's fence, which orders them (fences are
   * cumulative) before its ticket, as cooperative groups' grid barrier
   * does; one fence a block instead of one a thread, which stalled every
   * warp of the update (BENCHMARKS.md, "the cost of a step") */
  __syncthreads();
  if (threadIdx.x == 0) {
    __threadfence();
    last = atomicAdd(&st->ticket, 1u) == gridDim.x - 1;
  }
  __syncthreads();
  if (!last || threadIdx.x != 0) return;
  __threadfence();
  st->ticket = 0;
  end_step<DIM>(&k, &p, n, m, &ws, st);
}

/* The wall load (backend.h wall_load): each fluid particle's share
 * (sph/gather.h wl_sph_gather_wall_load) into fx[i], my[i]. */
template <int DIM, int LAM>
__global__ void __launch_bounds__(THREADS)
    k_wall_load(const struct wl_sph_const kp, const struct wl_sph_grid gp,
                const struct wl_sph_eval ep, const unsigned char *__restrict__ body_of,
                int body, double z_ref, int nb, int n, double *fx, double *my) {
  const struct wl_sph_const k = kp;
  const struct wl_sph_grid g = gp;
  const struct wl_sph_eval e = ep;
  const int i = nb + tid();
  if (i < n) wl_sph_gather_wall_load(DIM, LAM, &k, &g, &e, body_of, body, z_ref, i, &fx[i], &my[i]);
}

/* Threads of k_load_sum's one block. */
enum { LOAD_THREADS = 1024 };

/* st->load = the sums of fx and my over [i0, n): thread t adds elements
 * i0 + t, i0 + t + LOAD_THREADS, ... in order, then a tree over the
 * threads; a fixed order, so the same bits on every run. */
__global__ void __launch_bounds__(LOAD_THREADS)
    k_load_sum(const double *__restrict__ fx, const double *__restrict__ my, int i0, int n,
               struct dstats *st) {
  __shared__ double sx[LOAD_THREADS], sm[LOAD_THREADS];
  const int t = threadIdx.x;
  double a = 0.0, b = 0.0;
  for (int i = i0 + t; i < n; i += LOAD_THREADS) {
    a += fx[i];
    b += my[i];
  }
  sx[t] = a;
  sm[t] = b;
  __syncthreads();
  for (int o = LOAD_THREADS / 2; o > 0; o >>= 1) {
    if (t < o) {
      sx[t] += sx[t + o];
      sm[t] += sm[t + o];
    }
    __syncthreads();
  }
  if (t == 0) {
    st->load[0] = sx[0];
    st->load[1] = sm[0];
  }
}

/* ---- host side ---------------------------------------------------------- */

static int blocks(int n) { return (n + THREADS - 1) / THREADS; }

template <class T> static void swap_ptr(T *&a, T *&b) {
  T *t = a;
  a = b;
  b = t;
}

/* The particle view of the current roles (for integrate.h and guard.h). */
static struct wl_particles view(const struct gpu *c) {
  struct wl_particles p;
  memset(&p, 0, sizeof p);
  p.dim = c->dim;
  p.n = p.capacity = c->n;
  p.n_bound = c->nb;
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    p.pos[a] = c->pos[a];
    p.vel[a] = c->vel[a];
    p.pos_h[a] = c->pos_h[a];
    p.vel_h[a] = c->vel_h[a];
    p.ace[a] = c->ace[a];
    p.shift[a] = c->shift[a];
  }
  p.rho = c->rho;
  p.rho_h = c->rho_h;
  if (c->rho_m1) { /* Verlet: vel_h and rho_h are the previous step's v and rho */
    for (int a = 0; a < c->dim; a++) p.vel_h[a] = c->vel_m1[a];
    p.rho_h = c->rho_m1;
  }
  p.press = c->press;
  p.ar = c->ar;
  p.visc = c->visc;
  p.id = c->id;
  p.kind = c->kind;
  p.body = c->body;
  p.key = c->key;
  return p;
}

/* Rebuild the cell lists: keys, sort (the counting sort above), begin,
 * state into sorted order, the pressure of the sorted density. The sort's
 * scratch lives in arrays that are free at this point of the step (ace);
 * key, pos_h, vel_h, rho_h receive the sorted keys and state and swap
 * roles with the unsorted ones (key with ace[0]), and so does ar with id
 * (both 4-byte arrays; ar is rewritten by the next force evaluation). */
/* The keys and counts come from the update that ended the last step
 * (k_update), or with REBUILD_KEYS from k_keys (the initial state); with
 * REBUILD_STEP they are left for the step's update to count anew, else
 * given back (wall_load: the next step sorts the same state). */
enum { REBUILD_KEYS = 1, REBUILD_STEP = 2 };
static enum wl_status rebuild(struct gpu *c, int how, struct wl_error *err) {
  const int n = c->n, dim = c->dim, n_keys = 2 * c->grid.n_cells;
  unsigned int *key_d = (unsigned int *)c->ace[0];
  unsigned int *perm = (unsigned int *)c->ace[1];
  const size_t count_bytes = sizeof(int) * (size_t)(n_keys + 1);
  if (how & REBUILD_KEYS) {
    CK(cudaMemsetAsync(c->count, 0, count_bytes, c->stream));
    CK(cudaMemsetAsync(c->bsum, 0, c->bsum_bytes, c->stream));
    if (dim == 3)
      launch(c, k_keys<3>, blocks(n), THREADS, c->stream, c->grid, c->pos[0], c->pos[1], c->pos[2],
             c->kind, c->key, c->count, c->bsum, n, c->stats);
    else
      launch(c, k_keys<2>, blocks(n), THREADS, c->stream, c->grid, c->pos[0], c->pos[1], c->pos[1],
             c->kind, c->key, c->count, c->bsum, n, c->stats);
    CKL("keys");
  }
  launch(c, k_scan, scan_blocks(n_keys + 1), SCAN_THREADS, c->stream, c->count, c->bsum, c->begin,
         n_keys + 1, c->stats);
  CKL("scan");
  /* a 2D step ranks each range in k_permute (its ranges are short); 3D
   * cells are long, and a rebuild outside a step gives the counts back:
   * k_cellsort there, and 3D's long ranges one warp each */
  const int rank = dim == 2 && (how & REBUILD_STEP);
  launch(c, k_scatter, blocks(n), THREADS, c->stream, c->key, c->begin, c->count, perm, n,
         c->bsum, rank ? scan_blocks(n_keys) : 0, c->stats);
  CKL("scatter");
  if (!rank) {
    launch(c, k_cellsort, blocks(n_keys), THREADS, c->stream, c->begin, perm, n_keys, c->count,
           c->bsum, (how & REBUILD_STEP) != 0, dim == 3, c->stats);
    CKL("cell sort");
  }
  if (dim == 3) {
    launch(c, k_cellsort_warp, (int)(((long)n_keys * 32 + THREADS - 1) / THREADS), THREADS,
           c->stream, c->begin, perm, n_keys, c->stats);
    CKL("cell sort, long ranges");
  }
  struct permute_args a;
  memset(&a, 0, sizeof a);
  a.perm = perm;
  a.key = c->key;
  a.key_d = key_d;
  for (int q = 0; q < dim; q++) {
    a.pos[q] = c->pos[q];
    a.pos_d[q] = c->pos_h[q];
    a.vel[q] = c->vel[q];
    a.vel_d[q] = c->vel_h[q];
  }
  a.rho = c->rho;
  a.rho_d = c->rho_h;
  a.press = c->press;
  a.id = c->id;
  a.id_d = (unsigned int *)c->ar;
  a.kind = c->kind;
  a.kind_d = c->kind_alt;
  a.body = c->body;
  a.body_d = c->body_alt;
  if (c->rho_m1) {
    for (int q = 0; q < dim; q++) {
      a.vel_m1[q] = c->vel_m1[q];
      a.vel_m1_d[q] = c->vel_m1_alt[q];
    }
    a.rho_m1 = c->rho_m1;
    a.rho_m1_d = c->rho_m1_alt;
  }
  if (dim == 3)
    launch(c, k_permute<3, 0>, blocks(n), THREADS, c->stream, a, c->k, n, c->begin, c->stats);
  else if (rank)
    launch(c, k_permute<2, 1>, blocks(n), THREADS, c->stream, a, c->k, n, c->begin, c->stats);
  else
    launch(c, k_permute<2, 0>, blocks(n), THREADS, c->stream, a, c->k, n, c->begin, c->stats);
  CKL("permute");
  {
    wl_real *t = (wl_real *)c->key;
    c->key = key_d;
    c->ace[0] = t;
  }
  for (int q = 0; q < dim; q++) {
    swap_ptr(c->pos[q], c->pos_h[q]);
    swap_ptr(c->vel[q], c->vel_h[q]);
  }
  swap_ptr(c->rho, c->rho_h);
  {
    wl_real *t = (wl_real *)c->id;
    c->id = (unsigned int *)c->ar;
    c->ar = t;
  }
  swap_ptr(c->kind, c->kind_alt);
  swap_ptr(c->body, c->body_alt);
  if (c->rho_m1) {
    for (int q = 0; q < dim; q++) swap_ptr(c->vel_m1[q], c->vel_m1_alt[q]);
    swap_ptr(c->rho_m1, c->rho_m1_alt);
  }
  return WL_OK;
}

/* The residual viscosity's velocity gradient of each fluid particle
 * (sph/vgrad.h), before the force loop reads them. */
template <int DIM>
__global__ void __launch_bounds__(THREADS)
    k_vgrad(const struct wl_sph_const kp, const struct wl_sph_grid gp, const struct wl_sph_eval ep,
            int nb, int n, struct gvptr gv, struct dstats *st) {
  pdl_begin();
  if (st->plan.stop) return;
  const int i = nb + tid();
  if (i >= n) return;
  wl_sph_vgrad(DIM, &kp, &gp, ep.pos, ep.vel, ep.rho, ep.key, ep.begin, i, gv.g);
}

/* The force loop of c->mode for particles i0 .. n - 1 (one of those this
 * build has, loop_built). */
template <int DIM, int LAM>
static void launch_gather(const struct gpu *c, const struct wl_sph_eval &e, int i0,
                          cudaStream_t s) {
  const int n = c->n, nb = c->nb;
  if constexpr (loop_built(MODE_SPLIT, DIM)) {
    if (c->mode == MODE_SPLIT) {
      /* the staging filter's and the marks' threshold: (2h)^2 with a
       * relative margin far above float rounding */
      const float skip2 = (float)(4.0 * c->k.h_d * c->k.h_d * 1.0001);
      const int nbs = (n - i0 + WL_SPLIT_THREADS - 1) / WL_SPLIT_THREADS;
      launch(c, k_gather_split<DIM, LAM>, nbs, WL_SPLIT_THREADS, s, c->k, c->grid, e, i0, n, nb,
             skip2, c->stats);
      return;
    }
  }
  if constexpr (loop_built(MODE_LANES, DIM)) {
    if (c->mode == MODE_LANES) {
      const int R = WL_GATHER_LANES;
      launch(c, k_gather_lanes<DIM, LAM, R>, blocks((n - i0) * R), THREADS, s, c->k, c->grid, e, i0,
             n, nb, c->stats);
      return;
    }
  }
  if constexpr (loop_built(MODE_FAST, DIM)) {
    if (c->mode == MODE_FAST) {
      launch(c, k_gather<DIM, LAM, 1>, blocks(n - i0), THREADS, s, c->k, c->grid, e, i0, n, nb,
             c->stats);
      return;
    }
  }
  if constexpr (loop_built(MODE_REF, DIM)) {
    if (c->mode == MODE_REF)
      launch(c, k_gather<DIM, LAM, 0>, blocks(n - i0), THREADS, s, c->k, c->grid, e, i0, n, nb,
             c->stats);
  }
}

/* One force evaluation at (pos, vel, rho) with press already filled; with
 * the wall condition, the boundary particles' rho and press are sampled
 * first (the moving bodies' accelerations from the plan) and the force
 * loop visits the fluid only. */
static enum wl_status evaluate(struct gpu *c, double *const *pos, wl_real *const *vel,
                               wl_real *rho, struct wl_error *err) {
  struct wl_sph_eval e;
  memset(&e, 0, sizeof e);
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    e.pos[a] = a < c->dim ? pos[a] : NULL;
    e.vel[a] = a < c->dim ? vel[a] : NULL;
    e.ace[a] = a < c->dim ? c->ace[a] : NULL;
  }
  e.rho = rho;
  e.press = c->press;
  e.key = c->key;
  e.begin = c->begin;
  e.ar = c->ar;
  e.visc = c->visc;
  const int n = c->n, nb = c->nb, lam = c->k.visc == WL_SPH_VISC_LAMINAR;
  cudaStream_t s = c->stream;
  const int wall_bc = c->k.boundary == WL_SPH_BOUND_ADAMI, i0 = wall_bc ? nb : 0;
  if (c->gv[0] && n > nb) {
    struct gvptr gv;
    memset(&gv, 0, sizeof gv);
    for (int q = 0; q < c->dim * c->dim; q++) e.gv[q] = gv.g[q] = c->gv[q];
    if (c->dim == 3)
      launch(c, k_vgrad<3>, blocks(n - nb), THREADS, s, c->k, c->grid, e, nb, n, gv, c->stats);
    else
      launch(c, k_vgrad<2>, blocks(n - nb), THREADS, s, c->k, c->grid, e, nb, n, gv, c->stats);
    CKL("velocity gradient");
  }
  if (wall_bc && nb > 0) {
    struct wallin w;
    memset(&w, 0, sizeof w);
    w.kind = c->kind;
    w.body = c->body;
    w.rho = rho;
    w.press = c->press;
    if (c->dim == 3)
      launch(c, k_wall_lanes<3, WL_WALL_LANES_3D>, blocks(nb * WL_WALL_LANES_3D), THREADS, s,
             c->k, c->grid, e, nb, w, c->stats);
    else
      launch(c, k_wall_lanes<2, WL_WALL_LANES_2D>, blocks(nb * WL_WALL_LANES_2D), THREADS, s,
             c->k, c->grid, e, nb, w, c->stats);
    CKL("wall");
  }
  if (n == i0) return WL_OK;
  if (c->dim == 3 && lam) launch_gather<3, 1>(c, e, i0, s);
  else if (c->dim == 3) launch_gather<3, 0>(c, e, i0, s);
  else if (lam) launch_gather<2, 1>(c, e, i0, s);
  else launch_gather<2, 0>(c, e, i0, s);
  CKL("gather");
  return WL_OK;
}

/* The update (update != 0; the plan says how), guard, the next sort's keys
 * and the end of the step (k_update). */
static enum wl_status enqueue_update(struct gpu *c, int update, struct wl_error *err) {
  const struct wl_particles p = view(c);
  const int n = c->n;
  if (c->dim == 3)
    launch(c, k_update<3>, blocks(n), THREADS, c->stream, c->k, c->grid, p, n, update, c->meta,
           c->count, c->bsum, c->stats);
  else
    launch(c, k_update<2>, blocks(n), THREADS, c->stream, c->k, c->grid, p, n, update, c->meta,
           c->count, c->bsum, c->stats);
  CKL("update");
  return WL_OK;
}

/* The step record back to the host (the one synchronisation of a step or
 * block). */
static enum wl_status fetch_record(struct gpu *c, struct wl_error *err) {
  CK(cudaMemcpyAsync(c->h_stats, c->stats, sizeof *c->stats, cudaMemcpyDeviceToHost, c->stream));
  CK(cudaStreamSynchronize(c->stream));
  return WL_OK;
}

/* The last step's out from the fetched record. */
static void step_out_of(const struct gpu *c, struct wl_sph_step_out *out) {
  const struct dstats *st = c->h_stats;
  double ace2, vel2, visc;
  memcpy(&ace2, &st->ace2, sizeof ace2);
  memcpy(&vel2, &st->vel2, sizeof vel2);
  memcpy(&visc, &st->visc, sizeof visc);
  memset(out, 0, sizeof *out);
  wl_sph_step_dt(&c->k, ace2, vel2, visc, out); /* the CPU backend's formula (backend.h) */
  out->fault = WL_SPH_FAULT_NONE;
  out->n_limited = (long)st->limited;
  out->n_excluded = (long)st->excluded;
  if (st->first < c->n) {
    out->fault = st->fault;
    out->fault_index = st->first;
    out->fault_id = st->id;
    out->fault_kind = st->kind;
    out->fault_wall = st->wall;
    for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
      out->fault_pos[a] = st->pos[a];
      out->fault_vel[a] = st->vel[a];
    }
    out->fault_rho = st->rho;
  }
}

static void cuda_free(void *ctx) {
  struct gpu *c = (struct gpu *)ctx;
  if (!c) return;
  for (int q = 0; q < 2; q++) {
    if (c->exec[q]) cudaGraphExecDestroy(c->exec[q]);
    if (c->graph[q]) cudaGraphDestroy(c->graph[q]);
    if (c->exec2[q]) cudaGraphExecDestroy(c->exec2[q]);
    if (c->graph2[q]) cudaGraphDestroy(c->graph2[q]);
  }
  for (int q = 0; q < c->n_allocs; q++) cudaFree(c->allocs[q]);
  if (c->h_stats) cudaFreeHost(c->h_stats);
  if (c->h_up) cudaFreeHost(c->h_up);
  if (c->h_dl) cudaFreeHost(c->h_dl);
  if (c->h_load) cudaFreeHost(c->h_load);
  if (c->h_zflag) cudaFreeHost(c->h_zflag);
  if (c->h_zidx) cudaFreeHost(c->h_zidx);
  if (c->snap_ev) cudaEventDestroy(c->snap_ev);
  if (c->stream) cudaStreamDestroy(c->stream);
  free(c);
}

/* The kernels of one step (the plan in the device record): rebuild,
 * shifting, forces, the symplectic predictor and half-step forces, update
 * and guard, end of step. Enqueued only; the roles of the arrays are those
 * after the step's rebuild. */
static enum wl_status enqueue_step(struct gpu *c, struct wl_error *err) {
  enum wl_status st = rebuild(c, REBUILD_STEP, err);
  if (st) return st;
  if (c->k.shift_coef > 0 && c->n > c->nb) {
    const struct wl_sph_eval e = wl_sph_eval_inputs(c->dim, c->pos, c->vel, c->rho, c->key, c->begin);
    struct shiftptr sp;
    memset(&sp, 0, sizeof sp);
    for (int a = 0; a < c->dim; a++) sp.s[a] = c->shift[a];
    const int nf = c->n - c->nb;
    if (c->dim == 3)
      launch(c, k_shift<3>, blocks(nf), THREADS, c->stream, c->k, c->grid, e, c->n, c->nb, sp,
             c->stats);
    else
      launch(c, k_shift<2>, blocks(nf), THREADS, c->stream, c->k, c->grid, e, c->n, c->nb, sp,
             c->stats);
    CKL("shift");
  }
  if ((st = evaluate(c, c->pos, c->vel, c->rho, err))) return st;
  if (c->k.integrator != WL_SPH_VERLET) {
    struct wl_particles p = view(c);
    if (c->dim == 3)
      launch(c, k_predict<3>, blocks(c->n), THREADS, c->stream, c->k, p, c->n, c->stats);
    else
      launch(c, k_predict<2>, blocks(c->n), THREADS, c->stream, c->k, p, c->n, c->stats);
    CKL("predict");
    if ((st = evaluate(c, c->pos_h, c->vel_h, c->rho_h, err))) return st;
  }
  return enqueue_update(c, 1, err);
}

static void save_roles(const struct gpu *c, struct roles *r) {
  memset(r, 0, sizeof *r);
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    r->pos[a] = c->pos[a];
    r->pos_h[a] = c->pos_h[a];
    r->vel[a] = c->vel[a];
    r->vel_h[a] = c->vel_h[a];
    r->vel_m1[a] = c->vel_m1[a];
    r->vel_m1_alt[a] = c->vel_m1_alt[a];
  }
  r->ace0 = c->ace[0];
  r->rho = c->rho;
  r->rho_h = c->rho_h;
  r->ar = c->ar;
  r->rho_m1 = c->rho_m1;
  r->rho_m1_alt = c->rho_m1_alt;
  r->key = c->key;
  r->id = c->id;
  r->kind = c->kind;
  r->kind_alt = c->kind_alt;
  r->body = c->body;
  r->body_alt = c->body_alt;
}

static void load_roles(struct gpu *c, const struct roles *r) {
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    c->pos[a] = r->pos[a];
    c->pos_h[a] = r->pos_h[a];
    c->vel[a] = r->vel[a];
    c->vel_h[a] = r->vel_h[a];
    c->vel_m1[a] = r->vel_m1[a];
    c->vel_m1_alt[a] = r->vel_m1_alt[a];
  }
  c->ace[0] = r->ace0;
  c->rho = r->rho;
  c->rho_h = r->rho_h;
  c->ar = r->ar;
  c->rho_m1 = r->rho_m1;
  c->rho_m1_alt = r->rho_m1_alt;
  c->key = r->key;
  c->id = r->id;
  c->kind = r->kind;
  c->kind_alt = r->kind_alt;
  c->body = r->body;
  c->body_alt = r->body_alt;
}

/* Which of the captured role sets the arrays are in now (a rebuild, in a
 * step or a wall load, flips it); -1: neither. */
static int role_set(const struct gpu *c) {
  struct roles r;
  save_roles(c, &r);
  for (int q = 0; q < 2; q++)
    if (!memcmp(&r, &c->roles[q], sizeof r)) return q;
  return -1;
}

/* One step captured as a graph from each role set (exec[0] from the
 * current roles, exec[1] from those after it); nothing runs. A rebuild
 * swaps every pair of arrays it uses, so two steps give the roles back:
 * checked. */
static enum wl_status capture_steps(struct gpu *c, struct wl_error *err) {
  save_roles(c, &c->roles[0]);
  for (int q = 0; q < 2; q++) {
    CK(cudaStreamBeginCapture(c->stream, cudaStreamCaptureModeThreadLocal));
    const enum wl_status st = enqueue_step(c, err);
    cudaGraph_t g = NULL;
    const cudaError_t e = cudaStreamEndCapture(c->stream, &g);
    if (st) {
      if (g) cudaGraphDestroy(g);
      return st;
    }
    CK(e);
    c->graph[q] = g;
    CK(cudaGraphInstantiate(&c->exec[q], g, 0));
    if (q == 0) save_roles(c, &c->roles[1]);
  }
  if (role_set(c) != 0)
    return wl_error_set(err, WL_EIO, "cuda backend: two captured steps do not give the arrays' "
                        "roles back");
  for (int q = 0; q < 2; q++) {
    load_roles(c, &c->roles[q]);
    CK(cudaStreamBeginCapture(c->stream, cudaStreamCaptureModeThreadLocal));
    enum wl_status st = enqueue_step(c, err);
    if (!st) st = enqueue_step(c, err);
    cudaGraph_t g = NULL;
    const cudaError_t e = cudaStreamEndCapture(c->stream, &g);
    if (st) {
      if (g) cudaGraphDestroy(g);
      return st;
    }
    CK(e);
    c->graph2[q] = g;
    CK(cudaGraphInstantiate(&c->exec2[q], g, 0));
    if (role_set(c) != q)
      return wl_error_set(err, WL_EIO, "cuda backend: two captured steps do not give the arrays' "
                          "roles back");
  }
  load_roles(c, &c->roles[0]);
  c->graphs = 1;
  return WL_OK;
}

/* Enqueue the next step: the captured graph of the current role set (the
 * kernels themselves before the capture). */
static enum wl_status launch_step(struct gpu *c, struct wl_error *err) {
  const int q = role_set(c);
  if (!c->graphs || q < 0) return enqueue_step(c, err);
  CK(cudaGraphLaunch(c->exec[q], c->stream));
  load_roles(c, &c->roles[q ^ 1]);
  return WL_OK;
}

static enum wl_status cuda_step(void *ctx, const struct wl_sph_step_in *in,
                                struct wl_sph_step_out *out, struct wl_error *err) {
  struct gpu *c = (struct gpu *)ctx;
  memset(out, 0, sizeof *out);
  struct dplan *pl = &c->h_up->plan;
  memset(pl, 0, sizeof *pl);
  pl->dt = in->dt;
  pl->dt_prev = in->dt_prev;
  pl->euler = c->k.integrator == WL_SPH_VERLET && wl_sph_verlet_euler(&c->k, in->step);
  memcpy(pl->body_vel, in->body_vel, sizeof pl->body_vel);
  memcpy(pl->body_acc, in->body_acc, sizeof pl->body_acc);
  CK(cudaMemcpyAsync(&c->stats->plan, pl, sizeof *pl, cudaMemcpyHostToDevice, c->stream));
  enum wl_status st = launch_step(c, err);
  if (!st) st = fetch_record(c, err);
  if (!st) step_out_of(c, out);
  return st;
}

/* backend.h run_start: the block's state and first plan uploaded, its
 * steps enqueued (each returns at once after the block stopped), the
 * record's copy back enqueued; nothing waited for. */
static enum wl_status cuda_run_start(void *ctx, const struct wl_sph_block_in *in,
                                     struct wl_error *err) {
  struct gpu *c = (struct gpu *)ctx;
  struct dstats *up = c->h_up;
  memset(&up->plan, 0, sizeof up->plan);
  memset(&up->blk, 0, sizeof up->blk);
  up->plan.block = 1;
  struct dblock *b = &up->blk;
  b->t = in->t;
  b->t_out = in->t_out;
  b->dt_next = in->dt_next;
  b->dt_last = in->dt_last;
  b->dt_initial = in->dt_initial;
  b->step = in->step;
  b->max_steps = in->max_steps;
  b->n_excluded = in->n_excluded;
  b->n_fluid = in->n_fluid;
  /* plan and blk are adjacent: one upload */
  const size_t off = offsetof(struct dstats, plan);
  const size_t len = offsetof(struct dstats, blk) + sizeof up->blk - off;
  CK(cudaMemcpyAsync((char *)c->stats + off, (const char *)up + off, len, cudaMemcpyHostToDevice,
                     c->stream));
  launch(c, k_plan, 1, 1, c->stream, c->k, c->stats);
  CKL("plan");
  const int q0 = role_set(c);
  if (!c->graphs || q0 < 0)
    return wl_error_set(err, WL_EIO, "cuda backend: a block of steps without its captured steps");
  for (long s = 0; s + 1 < in->max_steps; s += 2) CK(cudaGraphLaunch(c->exec2[q0], c->stream));
  if (in->max_steps & 1) CK(cudaGraphLaunch(c->exec[q0], c->stream));
  CK(cudaMemcpyAsync(c->h_stats, c->stats, sizeof *c->stats, cudaMemcpyDeviceToHost, c->stream));
  /* kernels after the block (wall_load's rebuild, the next step) run */
  CK(cudaMemsetAsync(&c->stats->plan.stop, 0, sizeof c->stats->plan.stop, c->stream));
  c->run_q0 = q0;
  return WL_OK;
}

/* backend.h run_finish: the started block waited for, its record read. */
static enum wl_status cuda_run_finish(void *ctx, struct wl_sph_block_out *out,
                                      struct wl_error *err) {
  struct gpu *c = (struct gpu *)ctx;
  memset(out, 0, sizeof *out);
  CK(cudaStreamSynchronize(c->stream));
  const struct dblock *hb = &c->h_stats->blk;
  /* the roles after the steps taken (the launches after the stop did
   * nothing) */
  load_roles(c, &c->roles[(c->run_q0 + hb->taken) & 1]);
  out->stop = hb->why;
  out->steps = (long)hb->taken;
  out->t = hb->t;
  out->dt_next = hb->dt_next;
  out->dt_last = hb->dt_last;
  out->n_limited = (long)hb->limited;
  out->n_excluded = (long)hb->excluded;
  if (hb->taken > 0) step_out_of(c, &out->last);
  return WL_OK;
}

/* backend.h run: run_start, then run_finish (one record back). */
static enum wl_status cuda_run(void *ctx, const struct wl_sph_block_in *in,
                               struct wl_sph_block_out *out, struct wl_error *err) {
  memset(out, 0, sizeof *out);
  const enum wl_status st = cuda_run_start(ctx, in, err);
  return st ? st : cuda_run_finish(ctx, out, err);
}

/* The wall load of body about z_ref on the cell lists rebuilt before
 * (wall_load, snapshot): each fluid particle's share into pos_h (free
 * between steps: rebuild left the old order's positions there), their
 * sums, and their copy into h_load[2 slot], enqueued. */
static enum wl_status enqueue_wall_load(struct gpu *c, int body, double z_ref, int slot,
                                        struct wl_error *err) {
  const int n = c->n, nb = c->nb, lam = c->k.visc == WL_SPH_VISC_LAMINAR;
  if (n <= nb) {
    c->h_load[2 * slot] = c->h_load[2 * slot + 1] = 0.0;
    return WL_OK;
  }
  struct wl_sph_eval e = wl_sph_eval_inputs(c->dim, c->pos, c->vel, c->rho, c->key, c->begin);
  e.press = c->press;
  double *fx = c->pos_h[0], *my = c->pos_h[1];
  const int nbk = blocks(n - nb);
  cudaStream_t s = c->stream;
  if (c->dim == 3 && lam) k_wall_load<3, 1><<<nbk, THREADS, 0, s>>>(c->k, c->grid, e, c->body, body, z_ref, nb, n, fx, my);
  else if (c->dim == 3) k_wall_load<3, 0><<<nbk, THREADS, 0, s>>>(c->k, c->grid, e, c->body, body, z_ref, nb, n, fx, my);
  else if (lam) k_wall_load<2, 1><<<nbk, THREADS, 0, s>>>(c->k, c->grid, e, c->body, body, z_ref, nb, n, fx, my);
  else k_wall_load<2, 0><<<nbk, THREADS, 0, s>>>(c->k, c->grid, e, c->body, body, z_ref, nb, n, fx, my);
  CKL("wall load");
  k_load_sum<<<1, LOAD_THREADS, 0, s>>>(fx, my, nb, n, c->stats);
  CKL("wall load sum");
  CK(cudaMemcpyAsync(c->h_load + 2 * slot, c->stats->load, sizeof c->stats->load,
                     cudaMemcpyDeviceToHost, s));
  return WL_OK;
}

/* backend.h wall_load: the cell lists of the current state (whose sort
 * also fills press with the EOS of every particle's density), the load
 * (enqueue_wall_load), back to the host. */
static enum wl_status cuda_wall_load(void *ctx, int body, double z_ref, double *force,
                                     double *moment, struct wl_error *err) {
  struct gpu *c = (struct gpu *)ctx;
  *force = *moment = 0.0;
  enum wl_status st = rebuild(c, 0, err);
  if (!st) st = enqueue_wall_load(c, body, z_ref, 0, err);
  if (st) return st;
  CK(cudaStreamSynchronize(c->stream));
  *force = c->h_load[0];
  *moment = c->h_load[1];
  return WL_OK;
}

static void cuda_describe(void *ctx, char *buf, size_t size) {
  const struct gpu *c = (const struct gpu *)ctx;
  snprintf(buf, size,
           "cuda (%s, sm_%d%d, %d SMs; %s force loop; %s; %d cells of %.4g m; "
           "%.1f MiB on the device, %.0f B/particle)",
           c->dev.name, c->dev.sm_major, c->dev.sm_minor, c->dev.n_sm,
           c->mode == MODE_SPLIT  ? "split (warp-shared candidates, pairs split evenly over the lanes)"
           : c->mode == MODE_LANES ? "lanes (" WL_STR(WL_GATHER_LANES) " threads per particle)"
           : c->mode == MODE_FAST ? "fast (cut-off skip, one thread per particle)"
                                  : "reference (wl_sph_gather, one thread per particle)",
           c->k.integrator == WL_SPH_VERLET ? "Verlet steps" : "symplectic steps", c->grid.n_cells,
           c->grid.cell, c->bytes / 1048576.0, (double)c->bytes / (c->n > 0 ? c->n : 1));
}

/* The fields download copies, in the order of its pinned staging buffer:
 * pos (dim doubles), vel (dim wl_real), rho, id, kind, body. */
static size_t download_bytes(int dim, size_t n) {
  return n * ((size_t)dim * (sizeof(double) + sizeof(wl_real)) + sizeof(wl_real) +
              sizeof(unsigned int) + 2);
}

/* The arrays download copies, in their order in the staging buffer (host:
 * the destinations, NULL for none). */
struct dl_part {
  void *host;
  const void *dev;
  size_t bytes;
};
static int dl_parts(const struct gpu *c, struct wl_particles *host,
                    struct dl_part parts[2 * WL_SPH_DIM_MAX + 4]) {
  const size_t n = (size_t)c->n;
  int np = 0;
  for (int a = 0; a < c->dim; a++)
    parts[np++] = {host ? host->pos[a] : NULL, c->pos[a], n * sizeof(double)};
  for (int a = 0; a < c->dim; a++)
    parts[np++] = {host ? host->vel[a] : NULL, c->vel[a], n * sizeof(wl_real)};
  parts[np++] = {host ? host->rho : NULL, c->rho, n * sizeof(wl_real)};
  parts[np++] = {host ? host->id : NULL, c->id, n * sizeof(unsigned int)};
  parts[np++] = {host ? host->kind : NULL, c->kind, n};
  parts[np++] = {host ? host->body : NULL, c->body, n};
  return np;
}

static enum wl_status check_host(const struct gpu *c, const struct wl_particles *host,
                                 struct wl_error *err) {
  if (host->dim != c->dim)
    return wl_error_set(err, WL_EINPUT, "cuda backend: download of %dD particles into %dD", c->dim,
                        host->dim);
  if (host->capacity < c->n)
    return wl_error_set(err, WL_EINPUT, "cuda backend: download of %d particles into room for %d",
                        c->n, host->capacity);
  return WL_OK;
}

/* The current arrays into the staging buffer, enqueued. */
static enum wl_status enqueue_dl(struct gpu *c, struct wl_error *err) {
  struct dl_part parts[2 * WL_SPH_DIM_MAX + 4];
  const int np = dl_parts(c, NULL, parts);
  size_t off = 0;
  for (int q = 0; q < np; q++) {
    CK(cudaMemcpyAsync(c->h_dl + off, parts[q].dev, parts[q].bytes, cudaMemcpyDeviceToHost,
                       c->stream));
    off += parts[q].bytes;
  }
  return WL_OK;
}

/* The staging buffer into the host's arrays. */
static void unstage(struct gpu *c, struct wl_particles *host) {
  struct dl_part parts[2 * WL_SPH_DIM_MAX + 4];
  const int np = dl_parts(c, host, parts);
  size_t off = 0;
  for (int q = 0; q < np; q++) {
    memcpy(parts[q].host, c->h_dl + off, parts[q].bytes);
    off += parts[q].bytes;
  }
  host->n = c->n;
  host->n_bound = c->nb;
}

/* The state into the host's arrays through the pinned staging buffer: the
 * copies from pageable memory each wait for the driver's own staging, at
 * an output every few dozen steps of a small flume. */
static enum wl_status cuda_download(void *ctx, struct wl_particles *host, struct wl_error *err) {
  struct gpu *c = (struct gpu *)ctx;
  enum wl_status st = check_host(c, host, err);
  if (!st) st = enqueue_dl(c, err);
  if (st) return st;
  CK(cudaStreamSynchronize(c->stream));
  unstage(c, host);
  return WL_OK;
}

/* backend.h snapshot: the fields download reads into the staging buffer,
 * then (with loads to compute) the cell lists rebuilt and each wall load
 * into h_load, as download then wall_load would do; all enqueued, an
 * event after them. */
static enum wl_status cuda_snapshot(void *ctx, int n, const int *body, const double *z_ref,
                                    struct wl_error *err) {
  struct gpu *c = (struct gpu *)ctx;
  if (n < 0 || n > WL_SPH_SNAPSHOT_LOADS)
    return wl_error_set(err, WL_EINPUT, "cuda backend: a snapshot of %d wall loads; at most %d", n,
                        (int)WL_SPH_SNAPSHOT_LOADS);
  enum wl_status st = enqueue_dl(c, err);
  if (!st && n > 0) st = rebuild(c, 0, err);
  for (int q = 0; q < n && !st; q++) st = enqueue_wall_load(c, body[q], z_ref[q], q, err);
  if (st) return st;
  CK(cudaEventRecord(c->snap_ev, c->stream));
  c->snap_n = n;
  return WL_OK;
}

/* backend.h snapshot_wait. */
static enum wl_status cuda_snapshot_wait(void *ctx, struct wl_particles *host, double *force,
                                         double *moment, struct wl_error *err) {
  struct gpu *c = (struct gpu *)ctx;
  enum wl_status st = check_host(c, host, err);
  if (st) return st;
  CK(cudaEventSynchronize(c->snap_ev));
  unstage(c, host);
  for (int q = 0; q < c->snap_n; q++) {
    force[q] = c->h_load[2 * q];
    moment[q] = c->h_load[2 * q + 1];
  }
  return WL_OK;
}

/* ---- zones (backend.h zone_download, zone_upload) ---------------------- */

/* The state arrays a zone reads and writes, by value into its kernels. */
struct zone_arrays {
  double *pos[WL_SPH_DIM_MAX];
  wl_real *vel[WL_SPH_DIM_MAX];
  wl_real *rho;
  unsigned int *id;
  unsigned char *kind, *body;
};

static struct zone_arrays zone_arrays_of(const struct gpu *c) {
  struct zone_arrays a;
  memset(&a, 0, sizeof a);
  for (int d = 0; d < c->dim; d++) a.pos[d] = c->pos[d], a.vel[d] = c->vel[d];
  a.rho = c->rho, a.id = c->id, a.kind = c->kind, a.body = c->body;
  return a;
}

/* Particle i's flag (sph/particles.h wl_sph_zone_flag). */
__global__ void k_zone_flag(const double *__restrict__ x, const unsigned char *__restrict__ kind,
                            const unsigned char *__restrict__ body, int n, double lo, double hi,
                            unsigned char *flag) {
  const int i = tid();
  if (i >= n) return;
  flag[i] = (unsigned char)wl_sph_zone_flag(x[i], kind[i], body[i], lo, hi);
}

/* The packed layout of m particles' fields (download's, dl_parts): x, y
 * (z), then velocities, density, id, kind, body, each a run of m. */
struct zone_layout {
  size_t pos, vel, rho, id, kind, body, bytes;
};

static __host__ __device__ struct zone_layout zone_layout_of(int dim, int m) {
  struct zone_layout l;
  l.pos = 0;
  l.vel = l.pos + (size_t)dim * m * sizeof(double);
  l.rho = l.vel + (size_t)dim * m * sizeof(wl_real);
  l.id = l.rho + (size_t)m * sizeof(wl_real);
  l.kind = l.id + (size_t)m * sizeof(unsigned int);
  l.body = l.kind + (size_t)m;
  l.bytes = l.body + (size_t)m;
  return l;
}

/* Zone particle k <-> its place idx[k] (to_buf: gather into buf; else
 * scatter from it). */
template <int DIM>
__global__ void k_zone_move(struct zone_arrays a, const int *__restrict__ idx, int m,
                            unsigned char *buf, int to_buf) {
  const int k = tid();
  if (k >= m) return;
  const int i = idx[k];
  const struct zone_layout l = zone_layout_of(DIM, m);
  double *pos = (double *)(buf + l.pos);
  wl_real *vel = (wl_real *)(buf + l.vel), *rho = (wl_real *)(buf + l.rho);
  unsigned int *id = (unsigned int *)(buf + l.id);
  unsigned char *kind = buf + l.kind, *body = buf + l.body;
  if (to_buf) {
    for (int d = 0; d < DIM; d++) pos[d * m + k] = a.pos[d][i], vel[d * m + k] = a.vel[d][i];
    rho[k] = a.rho[i], id[k] = a.id[i], kind[k] = a.kind[i], body[k] = a.body[i];
  } else {
    for (int d = 0; d < DIM; d++) a.pos[d][i] = pos[d * m + k], a.vel[d][i] = vel[d * m + k];
    a.rho[i] = rho[k], a.id[i] = id[k], a.kind[i] = kind[k], a.body[i] = body[k];
  }
}

/* k_zone_move of the m zone particles at c->z_idx, enqueued. */
static void zone_launch(const struct gpu *c, int m, int to_buf) {
  if (c->dim == 3)
    k_zone_move<3><<<blocks(m), THREADS, 0, c->stream>>>(zone_arrays_of(c), c->z_idx, m, c->z_buf,
                                                         to_buf);
  else
    k_zone_move<2><<<blocks(m), THREADS, 0, c->stream>>>(zone_arrays_of(c), c->z_idx, m, c->z_buf,
                                                         to_buf);
}

/* host <-> the packed layout in buf (to_buf: host into buf). */
static void zone_pack(int dim, struct wl_particles *host, unsigned char *buf, int m, int to_buf) {
  const struct zone_layout l = zone_layout_of(dim, m);
  struct {
    void *host;
    size_t off, bytes;
  } f[2 * WL_SPH_DIM_MAX + 4];
  int nf = 0;
  for (int d = 0; d < dim; d++) f[nf++] = {host->pos[d], l.pos + d * m * sizeof(double), m * sizeof(double)};
  for (int d = 0; d < dim; d++)
    f[nf++] = {host->vel[d], l.vel + d * m * sizeof(wl_real), m * sizeof(wl_real)};
  f[nf++] = {host->rho, l.rho, m * sizeof(wl_real)};
  f[nf++] = {host->id, l.id, m * sizeof(unsigned int)};
  f[nf++] = {host->kind, l.kind, (size_t)m};
  f[nf++] = {host->body, l.body, (size_t)m};
  for (int q = 0; q < nf; q++) {
    if (to_buf) memcpy(buf + f[q].off, f[q].host, f[q].bytes);
    else memcpy(f[q].host, buf + f[q].off, f[q].bytes);
  }
}

static enum wl_status dalloc(struct gpu *c, void **p, size_t bytes, const char *label,
                             struct wl_error *err);

static enum wl_status zone_alloc(struct gpu *c, struct wl_error *err) {
  if (c->z_idx) return WL_OK;
  const size_t n = (size_t)c->n;
  enum wl_status st = dalloc(c, (void **)&c->z_idx, n * sizeof(int), "zone places", err);
  if (!st) st = dalloc(c, (void **)&c->z_flag, n, "zone flags", err);
  if (!st) st = dalloc(c, (void **)&c->z_buf, download_bytes(c->dim, n), "zone fields", err);
  if (st) return st;
  CK(cudaMallocHost((void **)&c->h_zflag, n));
  CK(cudaMallocHost((void **)&c->h_zidx, n * sizeof(int)));
  return WL_OK;
}

/* backend.h zone_download: every particle flagged on the device, the flags
 * read here in the backend's order (the zone, and the first n_parked
 * parked particles beyond it), then the zone's fields gathered there and
 * copied across through the download's staging buffer. Two waits. */
static enum wl_status cuda_zone_download(void *ctx, double x_lo, double x_hi, int n_parked,
                                         struct wl_particles *host, int *idx,
                                         struct wl_error *err) {
  struct gpu *c = (struct gpu *)ctx;
  enum wl_status st = check_host(c, host, err);
  if (!st) st = zone_alloc(c, err);
  if (st) return st;
  k_zone_flag<<<blocks(c->n), THREADS, 0, c->stream>>>(c->pos[0], c->kind, c->body, c->n, x_lo,
                                                      x_hi, c->z_flag);
  CKL("zone flags");
  CK(cudaMemcpyAsync(c->h_zflag, c->z_flag, (size_t)c->n, cudaMemcpyDeviceToHost, c->stream));
  CK(cudaStreamSynchronize(c->stream));
  int m = 0, parked = 0, nb = 0;
  for (int i = 0; i < c->n; i++) {
    const unsigned char f = c->h_zflag[i];
    if (f == 1 || (f == 2 && parked < n_parked)) {
      parked += f == 2;
      nb += i < c->nb;
      c->h_zidx[m++] = i;
    }
  }
  memcpy(idx, c->h_zidx, sizeof(int) * (size_t)m);
  host->n = m, host->n_bound = nb;
  if (m == 0) return WL_OK;
  CK(cudaMemcpyAsync(c->z_idx, c->h_zidx, sizeof(int) * (size_t)m, cudaMemcpyHostToDevice,
                     c->stream));
  zone_launch(c, m, 1);
  CKL("zone gather");
  CK(cudaMemcpyAsync(c->h_dl, c->z_buf, zone_layout_of(c->dim, m).bytes, cudaMemcpyDeviceToHost,
                     c->stream));
  CK(cudaStreamSynchronize(c->stream));
  zone_pack(c->dim, host, c->h_dl, m, 0);
  return WL_OK;
}

/* backend.h zone_upload: host and its places packed into the pinned
 * staging buffers, copied across and scattered; enqueued only (the next
 * step follows in the stream, and the host next writes those buffers after
 * a download's wait). */
static enum wl_status cuda_zone_upload(void *ctx, const struct wl_particles *host, const int *idx,
                                       struct wl_error *err) {
  struct gpu *c = (struct gpu *)ctx;
  const int m = host->n;
  if (m == 0) return WL_OK;
  if (!c->z_idx || m > c->n)
    return wl_error_set(err, WL_EINPUT, "cuda backend: upload of a zone of %d particles without "
                        "its download", m);
  zone_pack(c->dim, (struct wl_particles *)host, c->h_dl, m, 1);
  memcpy(c->h_zidx, idx, sizeof(int) * (size_t)m);
  CK(cudaMemcpyAsync(c->z_buf, c->h_dl, zone_layout_of(c->dim, m).bytes, cudaMemcpyHostToDevice,
                     c->stream));
  CK(cudaMemcpyAsync(c->z_idx, c->h_zidx, sizeof(int) * (size_t)m, cudaMemcpyHostToDevice,
                     c->stream));
  zone_launch(c, m, 0);
  CKL("zone scatter");
  return WL_OK;
}

/* cudaMalloc of one labelled array, counted and remembered for free. */
static enum wl_status dalloc(struct gpu *c, void **p, size_t bytes, const char *label,
                             struct wl_error *err) {
  *p = NULL;
  if (c->n_allocs == (int)(sizeof c->allocs / sizeof c->allocs[0]))
    return wl_error_set(err, WL_ENOMEM, "cuda backend: more than %d device arrays ('%s')",
                        c->n_allocs, label);
  if (bytes == 0) bytes = 1;
  const cudaError_t e = cudaMalloc(p, bytes);
  if (e != cudaSuccess) {
    *p = NULL;
    return wl_error_set(err, WL_ENOMEM, "cuda backend: cannot allocate '%s' (%.1f MiB, %d particles): %s",
                        label, bytes / 1048576.0, c->n, cudaGetErrorString(e));
  }
  c->allocs[c->n_allocs++] = *p;
  c->bytes += bytes;
  return WL_OK;
}

/* Device bytes per particle of the arrays (dim components where vectors). */
static size_t bytes_per_particle(int dim, int shifting, int verlet, int residual) {
  return (size_t)dim * (2 * sizeof(double) + 3 * sizeof(wl_real)) /* pos, pos_h, vel, vel_h, ace */
         + 5 * sizeof(wl_real)                                      /* rho, rho_h, press, ar, visc */
         + 2 * sizeof(unsigned int)                                 /* key, id */
         + 4                                                        /* kind, body and their alts */
         + (shifting ? (size_t)dim * sizeof(wl_real) : 0)           /* shift (sph/shift.h) */
         + (verlet ? 2 * (size_t)(dim + 1) * sizeof(wl_real) : 0)   /* vel_m1, rho_m1, alts */
         + (residual ? (size_t)(dim * dim) * sizeof(wl_real) : 0);  /* gv (sph/vgrad.h) */
}

/* The split loop's kernels of dimension DIM asked for the most shared
 * memory (cudaSuccess where this build has none). */
template <int DIM> static cudaError_t split_carveout(void) {
  if constexpr (loop_built(MODE_SPLIT, DIM)) {
    const int most = cudaSharedmemCarveoutMaxShared;
    const cudaFuncAttribute carve = cudaFuncAttributePreferredSharedMemoryCarveout;
    cudaError_t e = cudaFuncSetAttribute(k_gather_split<DIM, 0>, carve, most);
    if (e == cudaSuccess) e = cudaFuncSetAttribute(k_gather_split<DIM, 1>, carve, most);
    return e;
  }
  return cudaSuccess;
}

/* backend.h init with force loop `mode` (-1: the product's for the
 * dimension); WL_EINPUT for a loop this build does not have. */
static enum wl_status init_mode(void **ctx, const struct wl_sph_config *cfg,
                                const struct wl_sph_const *k, const struct wl_particles *host,
                                struct wl_sph_step_out *out, int mode, struct wl_error *err) {
  *ctx = NULL;
  const int dim = cfg->prm.dim;
  enum wl_status st = wl_sph_check_particles("cuda", cfg, host, err);
  if (st) return st;
  struct wl_cuda_device dev;
  st = wl_cuda_device_query(&dev, err);
  if (st) return st;
  struct gpu *c = (struct gpu *)calloc(1, sizeof *c);
  if (!c) return wl_error_set(err, WL_ENOMEM, "cuda backend: out of host memory");
  c->cfg = *cfg;
  c->k = *k;
  c->dev = dev;
  c->dim = dim;
  c->n = host->n;
  c->nb = host->n_bound;
  {
    const char *pdl = getenv("WL_CUDA_PDL"); /* 0: off, to measure what it gains */
    c->pdl = dev.sm_major >= 9 && !(pdl && !strcmp(pdl, "0"));
  }
  /* the velocity gradients' terms (sph/vgrad.h): the residual and the eddy viscosity */
  const int residual = k->rav > 0 || k->nut_c > 0;
  c->mode = mode >= 0 ? mode : residual ? MODE_FAST : default_mode(dim, host->n);
  if (!(dim == 3 ? loop_built(c->mode, 3) : loop_built(c->mode, 2))) {
    cuda_free(c);
    return wl_error_set(err, WL_EINPUT, "cuda backend: force loop %d is not in this build for "
                        "%dD", mode, dim);
  }
  if (residual && c->mode != MODE_FAST && c->mode != MODE_REF) {
    cuda_free(c);
    return wl_error_set(err, WL_EINPUT, "cuda backend: the residual and the eddy viscosity run "
                        "in the fast or the reference force loop, not in loop %d", c->mode);
  }
  if ((st = wl_sph_grid_make(cfg, k, &c->grid, err))) {
    cuda_free(c);
    return st;
  }
  if (c->mode == MODE_SPLIT) {
    /* the most shared memory, so that 32 one-warp blocks fit an SM (see
     * WL_SPLIT_MIN_BLOCKS) */
    const cudaError_t e = dim == 3 ? split_carveout<3>() : split_carveout<2>();
    if (e != cudaSuccess) {
      cuda_free(c);
      return wl_error_set(err, WL_EIO, "cuda backend: cudaFuncSetAttribute (shared memory "
                          "carveout of the split loop) failed: %s", cudaGetErrorString(e));
    }
  }
  const int n = c->n, n_keys = 2 * c->grid.n_cells;

  /* what the run needs, against what the GPU has free */
  c->bsum_bytes = sizeof(int) * (size_t)scan_blocks(n_keys + 1);
  const int shifting = k->shift_coef > 0;
  const int verlet = k->integrator == WL_SPH_VERLET;
  const size_t per = bytes_per_particle(dim, shifting, verlet, residual);
  const size_t need = per * (size_t)n + 2 * sizeof(int) * (size_t)(n_keys + 1) + c->bsum_bytes +
                      sizeof(struct dmeta) + sizeof(struct dstats);
  size_t free_b = 0, total_b = 0;
  {
    const cudaError_t e = cudaMemGetInfo(&free_b, &total_b);
    if (e != cudaSuccess) {
      cuda_free(c);
      return wl_error_set(err, WL_EIO, "cuda backend: cudaMemGetInfo failed: %s",
                          cudaGetErrorString(e));
    }
  }
  /* leave a margin for the runtime and allocation granularity */
  const size_t margin = 64u << 20;
  if (need + margin > free_b) {
    const size_t tot = total_b;
    const double need_mib = need / 1048576.0, free_mib = free_b / 1048576.0,
                 sort_mib = c->bsum_bytes / 1048576.0;
    cuda_free(c);
    return wl_error_set(err, WL_ENOMEM,
                        "cuda backend: %d particles (%dD) need %.1f MiB of GPU memory (%zu B per "
                        "particle, %d cells, %.1f MiB sort scratch) plus a %.0f MiB margin; %s has "
                        "%.1f MiB free of %.1f MiB",
                        n, dim, need_mib, per, n_keys / 2, sort_mib, margin / 1048576.0,
                        dev.name, free_mib, tot / 1048576.0);
  }
  const size_t nd = (size_t)n * sizeof(double), nr = (size_t)n * sizeof(wl_real),
               nu = (size_t)n * sizeof(unsigned int), n8 = (size_t)n;
#define A(ptr, bytes, label)                                                                     \
  do {                                                                                           \
    if ((st = dalloc(c, (void **)&(ptr), (bytes), (label), err))) {                              \
      cuda_free(c);                                                                              \
      return st;                                                                                 \
    }                                                                                            \
  } while (0)
  for (int a = 0; a < dim; a++) {
    A(c->pos[a], nd, "pos");
    A(c->pos_h[a], nd, "pos_h");
    A(c->vel[a], nr, "vel");
    A(c->vel_h[a], nr, "vel_h");
    A(c->ace[a], nr, "ace");
    if (shifting) A(c->shift[a], nr, "shift");
    for (int b = 0; residual && b < dim; b++) A(c->gv[a * dim + b], nr, "velocity gradient");
    if (verlet) {
      A(c->vel_m1[a], nr, "previous velocity (Verlet)");
      A(c->vel_m1_alt[a], nr, "previous velocity (Verlet, sort copy)");
    }
  }
  if (verlet) {
    A(c->rho_m1, nr, "previous density (Verlet)");
    A(c->rho_m1_alt, nr, "previous density (Verlet, sort copy)");
  }
  A(c->rho, nr, "rho");
  A(c->rho_h, nr, "rho_h");
  A(c->press, nr, "press");
  A(c->ar, nr, "ar");
  A(c->visc, nr, "visc");
  A(c->key, nu, "key");
  A(c->id, nu, "id");
  A(c->kind, n8, "kind");
  A(c->kind_alt, n8, "kind (sort copy)");
  A(c->body, n8, "body");
  A(c->body_alt, n8, "body (sort copy)");
  A(c->begin, sizeof(int) * (size_t)(n_keys + 1), "cell index");
  A(c->count, sizeof(int) * (size_t)(n_keys + 1), "cell counts");
  A(c->bsum, c->bsum_bytes, "sort scratch");
  A(c->meta, sizeof(struct dmeta), "configuration");
  A(c->stats, sizeof(struct dstats), "step record");
#undef A
  c->dl_bytes = download_bytes(dim, (size_t)n);
  {
    cudaError_t e = cudaMallocHost((void **)&c->h_dl, c->dl_bytes);
    if (e == cudaSuccess)
      e = cudaMallocHost((void **)&c->h_load, 2 * WL_SPH_SNAPSHOT_LOADS * sizeof(double));
    if (e == cudaSuccess) e = cudaEventCreateWithFlags(&c->snap_ev, cudaEventDisableTiming);
    if (e != cudaSuccess) {
      const double mib = c->dl_bytes / 1048576.0;
      cuda_free(c);
      return wl_error_set(err, WL_ENOMEM, "cuda backend: the download staging (%.1f MiB pinned) "
                          "or its event: %s", mib, cudaGetErrorString(e));
    }
  }
  for (int q = 0; q < 2; q++) {
    struct dstats **h = q ? &c->h_up : &c->h_stats;
    const cudaError_t e = cudaMallocHost((void **)h, sizeof **h);
    if (e != cudaSuccess) {
      *h = NULL;
      cuda_free(c);
      return wl_error_set(err, WL_ENOMEM, "cuda backend: cudaMallocHost of the step record: %s",
                          cudaGetErrorString(e));
    }
  }
#define C(call)                                                                                  \
  do {                                                                                           \
    const cudaError_t e_ = (call);                                                               \
    if (e_ != cudaSuccess) {                                                                     \
      cuda_free(c);                                                                              \
      return wl_error_set(err, WL_EIO, "cuda backend: %s failed: %s (%s:%d)", #call,             \
                          cudaGetErrorString(e_), __FILE__, __LINE__);                           \
    }                                                                                            \
  } while (0)
  if (cfg->priority > 0) { /* backend.h: the run the others beside it wait for */
    int least = 0, greatest = 0;
    C(cudaDeviceGetStreamPriorityRange(&least, &greatest));
    C(cudaStreamCreateWithPriority(&c->stream, cudaStreamNonBlocking, greatest));
  } else {
    C(cudaStreamCreateWithFlags(&c->stream, cudaStreamNonBlocking));
  }
  struct dmeta m;
  memset(&m, 0, sizeof m);
  for (int a = 0; a < WL_SPH_DIM_MAX; a++) {
    m.lo[a] = cfg->lo[a];
    m.hi[a] = cfg->hi[a];
  }
  m.n_walls = cfg->n_walls;
  memcpy(m.walls, cfg->walls, sizeof m.walls);
  /* Every copy in the run's own stream. A plain cudaMemcpy goes to the
   * legacy stream, which a non-blocking stream does not wait for, and
   * returns before its DMA lands (from pageable memory, or device to
   * device): with other runs' copies ahead of it on a busy GPU, the first
   * sort read arrays not yet written (a 64-case sweep gave a case's wall
   * particles no body, its boundary force 0, on some runs and not others). */
  cudaStream_t s = c->stream;
  C(cudaMemcpyAsync(c->meta, &m, sizeof m, cudaMemcpyHostToDevice, s));
  for (int a = 0; a < dim; a++) {
    C(cudaMemcpyAsync(c->pos[a], host->pos[a], nd, cudaMemcpyHostToDevice, s));
    C(cudaMemcpyAsync(c->vel[a], host->vel[a], nr, cudaMemcpyHostToDevice, s));
  }
  C(cudaMemcpyAsync(c->rho, host->rho, nr, cudaMemcpyHostToDevice, s));
  C(cudaMemcpyAsync(c->id, host->id, nu, cudaMemcpyHostToDevice, s));
  C(cudaMemcpyAsync(c->kind, host->kind, n8, cudaMemcpyHostToDevice, s));
  C(cudaMemcpyAsync(c->body, host->body, n8, cudaMemcpyHostToDevice, s));
  if (verlet) { /* the previous step's v and rho start as the initial state */
    for (int a = 0; a < dim; a++)
      C(cudaMemcpyAsync(c->vel_m1[a], c->vel[a], nr, cudaMemcpyDeviceToDevice, s));
    C(cudaMemcpyAsync(c->rho_m1, c->rho, nr, cudaMemcpyDeviceToDevice, s));
  }
  /* m lives on this stack: its copy must land before the function returns */
  C(cudaStreamSynchronize(s));
  /* the plan at rest: no stop, no moving body in motion */
  C(cudaMemsetAsync(c->stats, 0, sizeof *c->stats, c->stream));
#undef C
  /* forces of the initial state give the first dt (as the CPU backend);
   * then the steps are captured */
  if ((st = rebuild(c, REBUILD_KEYS | REBUILD_STEP, err)) ||
      (st = evaluate(c, c->pos, c->vel, c->rho, err)) ||
      (st = enqueue_update(c, 0, err)) || (st = fetch_record(c, err)) ||
      (step_out_of(c, out), st = capture_steps(c, err))) {
    cuda_free(c);
    return st;
  }
  *ctx = c;
  return WL_OK;
}

}  // namespace

#if !WL_CUDA_TEST_LOOPS
static enum wl_status cuda_init(void **ctx, const struct wl_sph_config *cfg,
                                const struct wl_sph_const *k, const struct wl_particles *host,
                                struct wl_sph_step_out *out, struct wl_error *err) {
  return init_mode(ctx, cfg, k, host, out, -1, err);
}

extern "C" const struct wl_backend_ops wl_backend_cuda_ops = {
    "cuda", cuda_init, cuda_step, cuda_download, cuda_describe, cuda_free, cuda_wall_load,
    cuda_run, cuda_snapshot, cuda_snapshot_wait, cuda_run_start, cuda_run_finish,
    cuda_zone_download, cuda_zone_upload,
};
#else
/* The tests' build: one backend per force loop, for test_cuda_backend to
 * compare (the product's wl_backend_cuda_ops comes from the product's
 * build of this file). */
#define TEST_OPS(loop, MODE)                                                                     \
  static enum wl_status init_##loop(void **ctx, const struct wl_sph_config *cfg,                 \
                                    const struct wl_sph_const *k,                                \
                                    const struct wl_particles *host,                             \
                                    struct wl_sph_step_out *out, struct wl_error *err) {         \
    return init_mode(ctx, cfg, k, host, out, MODE, err);                                         \
  }                                                                                              \
  extern "C" const struct wl_backend_ops wl_backend_cuda_##loop##_ops = {                        \
      "cuda", init_##loop, cuda_step, cuda_download, cuda_describe, cuda_free, cuda_wall_load,   \
      cuda_run, cuda_snapshot, cuda_snapshot_wait, cuda_run_start, cuda_run_finish,              \
      cuda_zone_download, cuda_zone_upload,                                                      \
  };
TEST_OPS(ref, MODE_REF)
TEST_OPS(fast, MODE_FAST)
TEST_OPS(split, MODE_SPLIT)
#undef TEST_OPS
#endif
