/* mpi.c: a sweep's cases shared among the ranks of `mpirun -np N wallload
 * sweep` (sweep.h, sweep_private.h; docs/sweep-mpi.md).
 *
 * Dynamic assignment: rank 0 (the lead) hands out one case index at a time
 * to whichever rank asks, in index order, and runs cases itself between
 * its answers (it answers from its own case's progress callback, every
 * half second). Dynamic rather than round-robin because a sweep's cases
 * differ in cost (a deeper flume has more particles; an unstable case ends
 * early; read-back cases cost nothing), and because a lost rank's other
 * cases are still handed to the ranks that remain.
 *
 * Every rank runs its case into DIR/cases/<id>/ itself (DIR is on a
 * filesystem all ranks see), writing the case's marker as a one-process
 * sweep does; its row then travels to the lead, which alone writes
 * sweep.csv, sweep.h5 and sweep.pdf. Resuming is therefore the
 * one-process sweep's: the lead reads back the markers before anything is
 * handed out.
 *
 * Nobody waits in a blocking MPI call: Open MPI's blocking calls spin on a
 * core, which on a machine of 2 cores would take one from the cases. Every
 * wait is MPI_Test or MPI_Iprobe with a 10 ms nap between.
 *
 * Messages are structs sent as bytes: every rank runs the same binary on
 * the same architecture (a sweep is one program's job). */
#define _POSIX_C_SOURCE 200809L /* nanosleep, gethostname, kill, setenv */
#include <dirent.h>
#include <errno.h>
#include <omp.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "sweep_private.h"
#include "wallload/config.h"

#if WL_HAVE_MPI
#include <mpi.h>
#endif

/* A lost rank is one silent this long, unless the command says otherwise. */
#define SILENCE_DEFAULT_S 600.0

int wl_sweep_mpi_built(void) { return WL_HAVE_MPI; }

/* The environment variable by which an MPI launcher announces a process
 * (NULL when none did), and its value. */
static const char *launcher_var(const char **value) {
  static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"};
  for (size_t k = 0; k < sizeof vars / sizeof vars[0]; k++) {
    const char *v = getenv(vars[k]);
    if (v && *v) {
      *value = v;
      return vars[k];
    }
  }
  return NULL;
}

static void one_process(struct wl_sweep_ranks *r) {
  memset(r, 0, sizeof *r);
  r->size = r->local_size = 1;
  r->silence_s = SILENCE_DEFAULT_S;
  if (gethostname(r->host, sizeof r->host) != 0) snprintf(r->host, sizeof r->host, "?");
  r->host[sizeof r->host - 1] = '\0';
}

#if WL_HAVE_MPI

static enum wl_status quiet(struct wl_error *err, enum wl_status st) {
  if (err) {
    err->status = st;
    err->msg[0] = '\0';
  }
  return st;
}

static double now_s(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

struct wl_sweep_comm {
  MPI_Comm comm;
  int finalize; /* MPI was initialised by wl_sweep_ranks_init */
};

enum { TAG_UP = 101, TAG_DOWN = 102 };
enum { UP_HELLO, UP_BEAT, UP_RESULT };  /* follower -> lead */
enum { DOWN_WORK, DOWN_STOP, DOWN_END }; /* lead -> follower */
#define BEAT_S 5.0  /* a running case's heartbeat [s] */
#define POLL_S 0.2  /* the lead's case answers the others at most this often [s] */

/* follower -> lead */
struct up {
  int kind;
  int case_index;       /* RESULT, BEAT: the case */
  int status;           /* HELLO: the follower cannot take part; RESULT: WL_EIO or WL_ENOMEM
                           when the case's files could not be written (the sweep stops) */
  int signal;           /* RESULT: the follower's stop signal, 0 if none */
  int threads;          /* HELLO */
  long pid;             /* HELLO */
  char host[64], gpu[64];
  char msg[1024];       /* why, for status */
  struct wl_sweep_row row; /* RESULT */
};

/* lead -> follower: WORK (value: the case), STOP (value: the signal), END
 * (value: the sweep's status, the follower's exit status; lost: a rank was
 * lost, so nobody finalises MPI) */
struct down {
  int kind, value, lost;
};
enum { DOWN_INTS = 3 };

/* the lead's start, broadcast: may the followers start, and where the lead is */
struct start {
  int status;
  long pid;
  char host[64];
};

static void nap(void) {
  const struct timespec ts = {0, 10000000L};
  nanosleep(&ts, NULL);
}

static enum wl_status mpi_failed(struct wl_error *err, int rc, const char *what) {
  char s[MPI_MAX_ERROR_STRING];
  int n = 0;
  if (MPI_Error_string(rc, s, &n) != MPI_SUCCESS) snprintf(s, sizeof s, "error %d", rc);
  return wl_error_set(err, WL_EIO, "MPI: %s: %s", what, s);
}

/* Wait for a non-blocking request without spinning on a core. */
static int wait_request(MPI_Request *q) {
  for (;;) {
    int done = 0;
    const int rc = MPI_Test(q, &done, MPI_STATUS_IGNORE);
    if (rc != MPI_SUCCESS || done) return rc;
    nap();
  }
}

/* 1 when process pid on this host is gone for certain. */
static int process_gone(long pid) { return pid > 0 && kill((pid_t)pid, 0) != 0 && errno == ESRCH; }

/* ---- the ranks ---------------------------------------------------------------------- */

/* This host's cores divided among its ranks, at most the cores this rank
 * may run on: mpirun binds each of 2 ranks to a core, but leaves
 * oversubscribed ranks (and those of --bind-to none) free on every core,
 * where each would otherwise start a thread per core. */
static int default_threads(int local_size) {
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  int t = cores > 0 ? (int)(cores / (local_size > 0 ? local_size : 1)) : 1;
  const int mine = omp_get_num_procs();
  if (mine > 0 && t > mine) t = mine;
  return t < 1 ? 1 : t;
}

/* One GPU per rank where a host has several, by local rank, through
 * CUDA_VISIBLE_DEVICES: set before the first CUDA call, the rank's CUDA
 * runtime sees its GPU alone, as device 0, which is the device the CUDA
 * backend takes (wl_cuda_device_query sets device 0: the backend is not
 * this module's to change). A list the scheduler set (several GPUs) gives
 * each rank one of its entries; an unset variable, one of the GPUs the
 * driver lists in /proc/driver/nvidia/gpus (counted without starting
 * CUDA). More ranks than GPUs share them round-robin. */
static void choose_gpu(struct wl_sweep_ranks *r) {
  if (!WL_HAVE_CUDA || r->local_size < 2) return;
  const char *vis = getenv("CUDA_VISIBLE_DEVICES");
  char pick[64] = "";
  if (vis && *vis) {
    int n = 1;
    for (const char *c = vis; *c; c++) n += *c == ',';
    if (n < 2) return;
    const char *c = vis;
    for (int k = r->local_rank % n; k > 0; k--) c = strchr(c, ',') + 1;
    const size_t len = strcspn(c, ",");
    if (len == 0 || len >= sizeof pick) return;
    memcpy(pick, c, len);
    pick[len] = '\0';
  } else {
    DIR *d = opendir("/proc/driver/nvidia/gpus");
    if (!d) return;
    int n = 0;
    for (struct dirent *e; (e = readdir(d));) n += e->d_name[0] != '.';
    closedir(d);
    if (n < 2) return;
    snprintf(pick, sizeof pick, "%d", r->local_rank % n);
  }
  if (setenv("CUDA_VISIBLE_DEVICES", pick, 1) == 0)
    snprintf(r->gpu, sizeof r->gpu, "CUDA_VISIBLE_DEVICES=%s", pick);
}

enum wl_status wl_sweep_ranks_init(struct wl_sweep_ranks *r, struct wl_error *err) {
  one_process(r);
  const char *value, *var = launcher_var(&value);
  if (!var) return WL_OK; /* no launcher: never start MPI (a singleton start is slow) */
  int inited = 0, provided = 0, rc;
  MPI_Initialized(&inited);
  /* FUNNELED: only the main thread calls MPI; the cases' OpenMP threads never do */
  if (!inited && (rc = MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided)))
    return mpi_failed(err, rc, "MPI_Init_thread");
  struct wl_sweep_comm *c = malloc(sizeof *c);
  if (!c) return wl_error_set(err, WL_ENOMEM, "no memory for MPI");
  c->finalize = !inited;
  /* a communicator of our own, whose errors come back as codes: a lost
   * rank must be a failed row, not the death of every rank */
  if ((rc = MPI_Comm_dup(MPI_COMM_WORLD, &c->comm))) {
    free(c);
    return mpi_failed(err, rc, "MPI_Comm_dup");
  }
  r->comm = c;
  MPI_Comm_set_errhandler(c->comm, MPI_ERRORS_RETURN);
  MPI_Comm_rank(c->comm, &r->rank);
  MPI_Comm_size(c->comm, &r->size);
  MPI_Comm local;
  if ((rc = MPI_Comm_split_type(c->comm, MPI_COMM_TYPE_SHARED, r->rank, MPI_INFO_NULL, &local)))
    return mpi_failed(err, rc, "MPI_Comm_split_type");
  MPI_Comm_rank(local, &r->local_rank);
  MPI_Comm_size(local, &r->local_size);
  MPI_Comm_free(&local);
  r->threads = default_threads(r->local_size);
  choose_gpu(r);
  return WL_OK;
}

void wl_sweep_ranks_finish(struct wl_sweep_ranks *r) {
  if (r->comm) {
    /* with a rank lost, Open MPI 4.1's MPI_Finalize can wait for it for
     * ever (seen under --enable-recovery): the process ends without it,
     * which mpirun accepts once the others end too */
    if (!r->lost) {
      MPI_Comm_free(&r->comm->comm);
      if (r->comm->finalize) MPI_Finalize();
    }
    free(r->comm);
  }
  one_process(r);
}

enum wl_status wl_sweep_ranks_agree(const struct wl_sweep_ranks *r, enum wl_status st,
                                    struct wl_error *err) {
  if (!r || !r->comm || r->size < 2) return st;
  int *all = malloc((size_t)r->size * sizeof *all);
  if (!all) return wl_error_set(err, WL_ENOMEM, "no memory for MPI");
  int mine = (int)st;
  MPI_Request q;
  int rc = MPI_Iallgather(&mine, 1, MPI_INT, all, 1, MPI_INT, r->comm->comm, &q);
  if (rc == MPI_SUCCESS) rc = wait_request(&q);
  if (rc != MPI_SUCCESS) {
    free(all);
    return st ? st : mpi_failed(err, rc, "the ranks' agreement");
  }
  enum wl_status out = (enum wl_status)all[0];
  if (out != WL_OK) {
    free(all);
    return r->rank == 0 ? out : quiet(err, out);
  }
  char which[256] = "";
  int n_bad = 0;
  for (int k = 1; k < r->size; k++) {
    if (all[k] == WL_OK) continue;
    if (!n_bad++) out = (enum wl_status)all[k];
    const size_t u = strlen(which);
    snprintf(which + u, sizeof which - u, "%s%d", u ? ", " : "", k);
  }
  free(all);
  if (out == WL_OK) return WL_OK;
  if (st != WL_OK) { /* this rank's own failure: its message, saying whose */
    wl_error_prefix(err, "rank %d (%s): ", r->rank, r->host);
    return st;
  }
  if (r->rank == 0)
    return wl_error_set(err, out, "rank%s %s failed (%s message%s above)", n_bad > 1 ? "s" : "",
                        which, n_bad > 1 ? "their" : "its", n_bad > 1 ? "s" : "");
  return quiet(err, out);
}

/* ---- the lead ------------------------------------------------------------------------ */

enum peer_state { PEER_STARTING, PEER_IDLE, PEER_BUSY, PEER_LOST, PEER_REFUSED };

struct peer {
  enum peer_state state;
  int case_index;   /* BUSY (and LOST, when lost while running one): its case */
  int stop_sent;
  double since;     /* BUSY: when its case was handed out [s] */
  double heard;     /* the last word from it, or its case's hand-out [s] */
  long pid;
  int same_host;    /* on the lead's host: its death is seen at once */
  char host[64];
};

struct sweep_lead {
  struct wl_sweep_ranks *r;
  MPI_Comm comm;
  struct peer *peer; /* [r->size]; [0] unused */
  /* while sweep_lead_cases runs */
  struct wl_sweep *sw;
  const char *dir;
  const struct wl_assess_opts *opts;
  const struct wl_sweep_events *ev;
  struct wl_error *err;
  int next;             /* the next case to hand out (index order) */
  int stop;             /* the stop signal, 0 until one */
  enum wl_status fatal; /* the sweep stops (err says why); cases running go on */
  double last_poll;
};

static void lead_fatal(struct sweep_lead *L, enum wl_status st, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void lead_fatal(struct sweep_lead *L, enum wl_status st, const char *fmt, ...) {
  if (L->fatal) return;
  L->fatal = st;
  char buf[WL_ERROR_MSG_MAX];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  wl_error_set(L->err, st, "%s", buf);
}

static void lead_tables(struct sweep_lead *L) {
  struct wl_error e;
  wl_error_clear(&e);
  const enum wl_status st = sweep_write_tables(L->sw, L->dir, &e);
  if (st) lead_fatal(L, st, "%s", e.msg);
}

static int lead_send(struct sweep_lead *L, int k, int kind, int value) {
  const struct down d = {kind, value, L->r->lost};
  return MPI_Send(&d, DOWN_INTS, MPI_INT, k, TAG_DOWN, L->comm);
}

/* Rank k is lost (why): its case, if it ran one, becomes a failed row. */
static void lead_lose(struct sweep_lead *L, int k, const char *why) {
  struct peer *p = &L->peer[k];
  const int was_busy = p->state == PEER_BUSY;
  p->state = PEER_LOST;
  L->r->lost = 1;
  if (!was_busy) return;
  const int i = p->case_index;
  struct wl_sweep_row *row = &L->sw->rows[i];
  memset(row, 0, sizeof *row);
  row->state = WL_SWEEP_RAN;
  row->status = WL_EIO;
  row->rank = k;
  row->runtime_s = now_s() - p->since;
  snprintf(row->message, sizeof row->message, "%s; running the sweep again runs this case again",
           why);
  if (L->ev && L->ev->case_end) L->ev->case_end(L->ev->user, L->sw, i);
  lead_tables(L);
}

static void lead_message(struct sweep_lead *L, int k, const struct up *m) {
  struct peer *p = &L->peer[k];
  if (m->kind == UP_HELLO) {
    p->pid = m->pid;
    snprintf(p->host, sizeof p->host, "%s", m->host);
    p->same_host = !strcmp(m->host, L->r->host);
    if (m->status != WL_OK) {
      p->state = PEER_REFUSED;
      lead_fatal(L, (enum wl_status)m->status, "rank %d (%s): %s", k, m->host, m->msg);
      return;
    }
    if (p->state == PEER_STARTING || p->state == PEER_LOST) p->state = PEER_IDLE;
    if (L->ev && L->ev->rank_ready) {
      struct wl_sweep_rank_info ri = {k, m->pid, m->threads, "", ""};
      snprintf(ri.host, sizeof ri.host, "%s", m->host);
      snprintf(ri.gpu, sizeof ri.gpu, "%s", m->gpu);
      L->ev->rank_ready(L->ev->user, &ri);
    }
  } else if (m->kind == UP_RESULT) {
    const int i = m->case_index;
    /* a result from a rank counted lost (silent too long, not dead) is
     * taken all the same: it replaces the failed row, and the rank works on */
    if ((p->state != PEER_BUSY && p->state != PEER_LOST) || p->case_index != i || i < 0 ||
        i >= L->sw->n_cases)
      return;
    L->sw->rows[i] = m->row;
    p->state = PEER_IDLE;
    p->case_index = -1;
    if (L->ev && L->ev->case_end) L->ev->case_end(L->ev->user, L->sw, i);
    lead_tables(L);
    if (m->status == WL_EIO || m->status == WL_ENOMEM)
      lead_fatal(L, (enum wl_status)m->status, "case %d (%s), on rank %d (%s): %s", i,
                 L->sw->cases[i].id, k, p->host, m->msg);
    /* a stop signal on one rank stops the sweep, as in one process */
    if (m->signal && !L->stop) L->stop = m->signal;
  }
}

/* The next case to hand out, or -1. */
static int lead_next(struct sweep_lead *L) {
  while (L->next < L->sw->n_cases && L->sw->rows[L->next].state != WL_SWEEP_PENDING) L->next++;
  return L->next < L->sw->n_cases ? L->next : -1;
}

/* Everything the lead owes the others: their messages read, lost ranks
 * found, a stop passed on, the idle given work. */
static void lead_poll(struct sweep_lead *L) {
  L->last_poll = now_s();
  for (;;) {
    int flag = 0;
    MPI_Status ms;
    int rc = MPI_Iprobe(MPI_ANY_SOURCE, TAG_UP, L->comm, &flag, &ms);
    if (rc != MPI_SUCCESS) {
      struct wl_error e;
      wl_error_clear(&e);
      mpi_failed(&e, rc, "MPI_Iprobe");
      lead_fatal(L, WL_EIO, "%s", e.msg);
      break;
    }
    if (!flag) break;
    struct up m;
    rc = MPI_Recv(&m, (int)sizeof m, MPI_BYTE, ms.MPI_SOURCE, TAG_UP, L->comm, MPI_STATUS_IGNORE);
    const int k = ms.MPI_SOURCE;
    if (k <= 0 || k >= L->r->size) continue;
    if (rc != MPI_SUCCESS) {
      lead_lose(L, k, "its message could not be received");
      continue;
    }
    L->peer[k].heard = now_s();
    lead_message(L, k, &m);
  }
  const double now = now_s();
  if (!L->stop && L->opts->interrupted && *L->opts->interrupted)
    L->stop = (int)*L->opts->interrupted;
  /* the lead's own running case stops with the others */
  if (L->stop && L->opts->interrupted && !*L->opts->interrupted)
    *L->opts->interrupted = (sig_atomic_t)L->stop;
  for (int k = 1; k < L->r->size; k++) {
    struct peer *p = &L->peer[k];
    if (p->state != PEER_STARTING && p->state != PEER_BUSY) continue;
    char why[300];
    if (p->same_host && process_gone(p->pid)) {
      snprintf(why, sizeof why, "rank %d (pid %ld on %s) died%s", k, p->pid, p->host,
               p->state == PEER_BUSY ? " while running this case" : "");
      lead_lose(L, k, why);
    } else if (now - p->heard > L->r->silence_s) {
      snprintf(why, sizeof why,
               "rank %d (%s) sent nothing for %.0f s (a running case's heartbeat is every %.0f "
               "s; wallload sweep --rank-timeout): counted as lost",
               k, p->host[0] ? p->host : "host unknown", now - p->heard, BEAT_S);
      lead_lose(L, k, why);
    } else if (p->state == PEER_BUSY && L->stop && !p->stop_sent) {
      p->stop_sent = 1;
      if (lead_send(L, k, DOWN_STOP, L->stop) != MPI_SUCCESS)
        lead_lose(L, k, "the stop could not be sent to it");
    }
  }
  for (int k = 1; k < L->r->size && !L->stop && !L->fatal; k++) {
    struct peer *p = &L->peer[k];
    const int i = p->state == PEER_IDLE ? lead_next(L) : -1;
    if (i < 0) continue;
    if (lead_send(L, k, DOWN_WORK, i) != MPI_SUCCESS) {
      lead_lose(L, k, "work could not be sent to it");
      continue; /* the case stays pending for another */
    }
    L->next = i + 1;
    p->state = PEER_BUSY;
    p->case_index = i;
    p->since = p->heard = now_s();
    L->sw->rows[i].rank = k;
    if (L->ev && L->ev->case_begin) L->ev->case_begin(L->ev->user, L->sw, i, 0);
  }
}

/* The lead's own case answers the others as it runs. */
static void lead_progress(void *user, const char *name, const struct wl_sph_progress *pr) {
  struct sweep_lead *L = user;
  if (now_s() - L->last_poll >= POLL_S) lead_poll(L);
  if (L->opts->progress) L->opts->progress(L->opts->user, name, pr);
}

enum wl_status sweep_lead_start(struct wl_sweep_ranks *r, const struct wl_sweep *sw,
                                enum wl_status st, struct sweep_lead **lead,
                                struct wl_error *err) {
  *lead = NULL;
  struct start s;
  memset(&s, 0, sizeof s);
  s.status = (int)st;
  s.pid = (long)getpid();
  snprintf(s.host, sizeof s.host, "%s", r->host);
  MPI_Request q;
  int rc = MPI_Ibcast(&s, (int)sizeof s, MPI_BYTE, 0, r->comm->comm, &q);
  if (rc == MPI_SUCCESS) rc = wait_request(&q);
  if (rc != MPI_SUCCESS) return mpi_failed(err, rc, "starting the other ranks");
  if (st != WL_OK) return st;
  struct sweep_lead *L = calloc(1, sizeof *L);
  struct peer *peer = calloc((size_t)r->size, sizeof *peer);
  if (!L || !peer) {
    free(L), free(peer);
    return wl_error_set(err, WL_ENOMEM, "%s: no memory for %d ranks", sw->path, r->size);
  }
  L->r = r;
  L->comm = r->comm->comm;
  L->peer = peer;
  const double now = now_s();
  for (int k = 0; k < r->size; k++) {
    peer[k].state = PEER_STARTING;
    peer[k].case_index = -1;
    peer[k].heard = now;
  }
  *lead = L;
  return WL_OK;
}

enum wl_status sweep_lead_cases(struct sweep_lead *L, struct wl_sweep *sw, const char *dir,
                                const struct wl_assess_opts *opts,
                                const struct wl_sweep_events *ev, char (*digest)[17], int threads,
                                int *stop, struct wl_error *err) {
  L->sw = sw;
  L->dir = dir;
  L->opts = opts;
  L->ev = ev;
  L->err = err;
  L->next = 0;
  if (ev && ev->rank_ready) {
    struct wl_sweep_rank_info me = {0, (long)getpid(), threads, "", ""};
    snprintf(me.host, sizeof me.host, "%s", L->r->host);
    snprintf(me.gpu, sizeof me.gpu, "%s", L->r->gpu);
    ev->rank_ready(ev->user, &me);
  }
  for (;;) {
    lead_poll(L);
    const int i = !L->stop && !L->fatal ? lead_next(L) : -1;
    if (i >= 0) { /* a case of the lead's own, answering the others as it runs */
      L->next = i + 1;
      sw->rows[i].rank = 0;
      if (ev && ev->case_begin) ev->case_begin(ev->user, sw, i, 0);
      struct wl_assess_opts o = *opts;
      o.progress = lead_progress;
      o.user = L;
      struct wl_error e;
      wl_error_clear(&e);
      const enum wl_status cst = sweep_run_case(sw, i, dir, digest[i], &o, &e);
      if (ev && ev->case_end) ev->case_end(ev->user, sw, i);
      lead_tables(L);
      if (cst == WL_EIO || cst == WL_ENOMEM)
        lead_fatal(L, cst, "case %d (%s): %s", i, sw->cases[i].id, e.msg);
      if (!L->stop && (cst == WL_EINTERRUPTED || (opts->interrupted && *opts->interrupted)))
        L->stop = opts->interrupted && *opts->interrupted ? (int)*opts->interrupted : SIGINT;
      continue;
    }
    int waiting = 0;
    for (int k = 1; k < L->r->size; k++)
      waiting += L->peer[k].state == PEER_STARTING || L->peer[k].state == PEER_BUSY;
    if (!waiting) break;
    nap();
  }
  *stop = L->stop;
  return L->fatal;
}

void sweep_lead_end(struct sweep_lead *L, enum wl_status st) {
  if (!L) return;
  /* every rank, the lost ones too: one counted lost for its silence may
   * be alive, and must not wait for work for ever; a send to a dead one
   * fails, which is ignored */
  for (int k = 1; k < L->r->size; k++) {
    const int silent_dead = L->peer[k].same_host && process_gone(L->peer[k].pid);
    if (!silent_dead) lead_send(L, k, DOWN_END, (int)st);
  }
  free(L->peer);
  free(L);
}

/* ---- a follower ----------------------------------------------------------------------- */

/* A follower's state; on the heap, with the buffers of its sends: a send
 * the lead never takes (it is gone) keeps its buffer for ever. */
struct follower {
  struct wl_sweep_ranks *r;
  MPI_Comm comm;
  const struct wl_assess_opts *opts;
  struct start lead;
  int lead_here;           /* the lead is on this host: its death is seen at once */
  int case_index;
  double last_beat;
  int ended;               /* END came (while a case ran: this rank was counted lost) */
  enum wl_status end_status;
  struct up beat, msg;     /* the heartbeat's buffer, and the hello's and results' */
  MPI_Request beat_req;    /* the last heartbeat, MPI_REQUEST_NULL once sent */
};

/* 1 when the lead is gone or silent beyond the limit (since t0); err says
 * which. */
static int follower_lead_lost(struct follower *f, double t0, struct wl_error *err) {
  if (f->lead_here && process_gone(f->lead.pid)) {
    wl_error_set(err, WL_EIO, "rank %d (%s): rank 0 (pid %ld) is gone; its cases in flight are "
                 "lost, the finished ones are kept: run the sweep again",
                 f->r->rank, f->r->host, f->lead.pid);
    return 1;
  }
  if (now_s() - t0 > f->r->silence_s) {
    wl_error_set(err, WL_EIO, "rank %d (%s): no word from rank 0 (%s) for %.0f s; giving up "
                 "(wallload sweep --rank-timeout)",
                 f->r->rank, f->r->host, f->lead.host, f->r->silence_s);
    return 1;
  }
  return 0;
}

/* f->msg to the lead, without waiting for ever: Open MPI's send to a rank
 * that died on the same host can block for good. */
static enum wl_status follower_send(struct follower *f, struct wl_error *err) {
  MPI_Request q;
  int rc = MPI_Isend(&f->msg, (int)sizeof f->msg, MPI_BYTE, 0, TAG_UP, f->comm, &q);
  const double t0 = now_s();
  for (int done = 0; rc == MPI_SUCCESS;) {
    rc = MPI_Test(&q, &done, MPI_STATUS_IGNORE);
    if (rc == MPI_SUCCESS && done) return WL_OK;
    if (follower_lead_lost(f, t0, err)) return WL_EIO;
    nap();
  }
  return mpi_failed(err, rc, "sending to rank 0");
}

/* A message from the lead, handled: STOP sets the stop flag the cases
 * read; END is remembered. */
static void follower_down(struct follower *f, const struct down *d) {
  if (d->kind == DOWN_STOP || d->kind == DOWN_END) {
    if (f->opts->interrupted && !*f->opts->interrupted)
      *f->opts->interrupted = (sig_atomic_t)(d->kind == DOWN_STOP ? d->value : SIGTERM);
  }
  if (d->kind == DOWN_END) {
    f->ended = 1;
    f->end_status = (enum wl_status)d->value;
    f->r->lost |= d->lost;
  }
}

/* A running case reads a stop from the lead, and beats: never blocking (a
 * beat still under way when the next is due is not repeated). */
static void follower_progress(void *user, const char *name, const struct wl_sph_progress *pr) {
  (void)name, (void)pr;
  struct follower *f = user;
  int flag = 0;
  MPI_Status ms;
  if (MPI_Iprobe(0, TAG_DOWN, f->comm, &flag, &ms) == MPI_SUCCESS && flag) {
    struct down d;
    if (MPI_Recv(&d, DOWN_INTS, MPI_INT, 0, TAG_DOWN, f->comm, MPI_STATUS_IGNORE) == MPI_SUCCESS)
      follower_down(f, &d);
  }
  const double now = now_s();
  if (now - f->last_beat < BEAT_S) return;
  if (f->beat_req != MPI_REQUEST_NULL) {
    int done = 0;
    if (MPI_Test(&f->beat_req, &done, MPI_STATUS_IGNORE) != MPI_SUCCESS || !done) return;
  }
  memset(&f->beat, 0, sizeof f->beat);
  f->beat.kind = UP_BEAT;
  f->beat.case_index = f->case_index;
  if (MPI_Isend(&f->beat, (int)sizeof f->beat, MPI_BYTE, 0, TAG_UP, f->comm, &f->beat_req) !=
      MPI_SUCCESS)
    f->beat_req = MPI_REQUEST_NULL;
  f->last_beat = now;
}

/* The lead's next word, or this rank's failure when the lead is lost. */
static enum wl_status follower_wait(struct follower *f, struct down *d, struct wl_error *err) {
  const double t0 = now_s();
  for (;;) {
    int flag = 0;
    MPI_Status ms;
    int rc = MPI_Iprobe(0, TAG_DOWN, f->comm, &flag, &ms);
    if (rc == MPI_SUCCESS && flag)
      rc = MPI_Recv(d, DOWN_INTS, MPI_INT, 0, TAG_DOWN, f->comm, MPI_STATUS_IGNORE);
    if (rc != MPI_SUCCESS) return mpi_failed(err, rc, "waiting for rank 0");
    if (flag) return WL_OK;
    if (follower_lead_lost(f, t0, err)) return WL_EIO;
    nap();
  }
}

enum wl_status sweep_follow(struct wl_sweep_ranks *r, struct wl_sweep *sw, const char *dir,
                            const struct wl_assess_opts *opts, struct wl_error *err) {
  struct start lead;
  MPI_Request q;
  int rc = MPI_Ibcast(&lead, (int)sizeof lead, MPI_BYTE, 0, r->comm->comm, &q);
  if (rc == MPI_SUCCESS) rc = wait_request(&q);
  if (rc != MPI_SUCCESS) return mpi_failed(err, rc, "waiting for rank 0 to start");
  if (lead.status != WL_OK) return quiet(err, (enum wl_status)lead.status); /* rank 0 says why */
  struct follower *f = calloc(1, sizeof *f);
  if (!f) return wl_error_set(err, WL_ENOMEM, "rank %d: no memory", r->rank);
  f->r = r;
  f->comm = r->comm->comm;
  f->opts = opts;
  f->lead = lead;
  f->lead_here = !strcmp(lead.host, r->host);
  f->case_index = -1;
  f->beat_req = MPI_REQUEST_NULL;
  /* hello: who this is, or why it cannot take part */
  struct up *m = &f->msg;
  m->kind = UP_HELLO;
  m->pid = (long)getpid();
  snprintf(m->host, sizeof m->host, "%s", r->host);
  snprintf(m->gpu, sizeof m->gpu, "%s", r->gpu);
  struct wl_error e;
  wl_error_clear(&e);
  char(*digest)[17] = NULL;
  enum wl_status st = sweep_digests(sw, opts, &digest, &m->threads, &e);
  char cases[1200];
  snprintf(cases, sizeof cases, "%s/cases", dir);
  struct stat sb;
  if (st == WL_OK && (stat(cases, &sb) != 0 || !S_ISDIR(sb.st_mode)))
    st = wl_error_set(&e, WL_EINPUT,
                      "%s: not found on this host (%s): the sweep's directory must be on a "
                      "filesystem every rank sees (rank 0 made it on %s)",
                      cases, r->host, lead.host);
  m->status = (int)st;
  snprintf(m->msg, sizeof m->msg, "%s", e.msg);
  /* the lead says why this rank cannot take part: this rank waits for END */
  enum wl_status out = follower_send(f, err);
  while (out == WL_OK && !f->ended) {
    struct down d;
    if ((out = follower_wait(f, &d, err))) break;
    follower_down(f, &d);
    if (d.kind != DOWN_WORK || d.value < 0 || d.value >= sw->n_cases || !digest) continue;
    const int i = d.value;
    memset(&sw->rows[i], 0, sizeof sw->rows[i]);
    sw->rows[i].rank = r->rank;
    struct wl_assess_opts o = *opts;
    o.progress = follower_progress;
    o.user = f;
    f->case_index = i;
    f->last_beat = now_s();
    wl_error_clear(&e);
    const enum wl_status cst = sweep_run_case(sw, i, dir, digest[i], &o, &e);
    if (f->ended) break; /* counted lost meanwhile: the lead has ended and takes no row */
    memset(m, 0, sizeof *m);
    m->kind = UP_RESULT;
    m->case_index = i;
    m->status = cst == WL_EIO || cst == WL_ENOMEM ? (int)cst : WL_OK;
    m->signal = opts->interrupted ? (int)*opts->interrupted : 0;
    snprintf(m->msg, sizeof m->msg, "%s", e.msg);
    m->row = sw->rows[i];
    out = follower_send(f, err);
  }
  free(digest);
  if (out != WL_OK) {
    /* the lead is lost: MPI_Finalize would wait for it, and a send still
     * under way reads f: both are left */
    r->lost = 1;
    return out;
  }
  int beat_done = 1;
  if (f->beat_req != MPI_REQUEST_NULL)
    MPI_Test(&f->beat_req, &beat_done, MPI_STATUS_IGNORE);
  const enum wl_status end = f->end_status;
  if (beat_done) free(f);
  else r->lost = 1; /* a beat the lead never took: f stays for it */
  return end ? quiet(err, end) : WL_OK;
}

#else /* !WL_HAVE_MPI: one process; several started by a launcher are refused */

enum wl_status wl_sweep_ranks_init(struct wl_sweep_ranks *r, struct wl_error *err) {
  one_process(r);
  const char *value, *var = launcher_var(&value);
  if (!var || (strcmp(var, "PMIX_RANK") && !strcmp(value, "1"))) return WL_OK;
  return wl_error_set(err, WL_EUNSUPPORTED,
                      "started by an MPI launcher (%s=%s), but this wallload was built without "
                      "MPI, so each process would run the whole sweep: build it with MPI "
                      "(Debian: libopenmpi-dev; scripts/setup.sh installs it), or run "
                      "`wallload sweep` without mpirun",
                      var, value);
}

void wl_sweep_ranks_finish(struct wl_sweep_ranks *r) { one_process(r); }

enum wl_status wl_sweep_ranks_agree(const struct wl_sweep_ranks *r, enum wl_status st,
                                    struct wl_error *err) {
  (void)r, (void)err;
  return st;
}

enum wl_status sweep_lead_start(struct wl_sweep_ranks *r, const struct wl_sweep *sw,
                                enum wl_status st, struct sweep_lead **lead,
                                struct wl_error *err) {
  (void)r;
  *lead = NULL;
  return st ? st : wl_error_set(err, WL_EUNSUPPORTED, "%s: built without MPI", sw->path);
}

enum wl_status sweep_lead_cases(struct sweep_lead *L, struct wl_sweep *sw, const char *dir,
                                const struct wl_assess_opts *opts,
                                const struct wl_sweep_events *ev, char (*digest)[17], int threads,
                                int *stop, struct wl_error *err) {
  (void)L, (void)dir, (void)opts, (void)ev, (void)digest, (void)threads, (void)stop;
  return wl_error_set(err, WL_EUNSUPPORTED, "%s: built without MPI", sw->path);
}

void sweep_lead_end(struct sweep_lead *L, enum wl_status st) { (void)L, (void)st; }

enum wl_status sweep_follow(struct wl_sweep_ranks *r, struct wl_sweep *sw, const char *dir,
                            const struct wl_assess_opts *opts, struct wl_error *err) {
  (void)r, (void)dir, (void)opts;
  return wl_error_set(err, WL_EUNSUPPORTED, "%s: built without MPI", sw->path);
}

#endif
