/* ladder.c: the convergence ladder of a load case (resolution.convergence):
 * the case run at dp x factor for each level, coarse to fine, its scalar
 * loads kept per level, the observed order, Richardson value and uncertainty
 * of peak force and impulse after each level (wl_loads_convergence),
 * and the early stop at resolution.target_error. The explosion runs
 * plan->realisations times a level, its crater moved by a fraction of the
 * level's dp each time (plan.h wl_plan_realisation_x); the level's loads
 * are their mean. Definitions in assess.h. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "assess_private.h"

/* Progress of a level: the case name with the level, passed to the caller's
 * progress function. */
struct ladder_progress {
  const struct wl_assess_opts *opts;
  char label[96];
};

static void ladder_on_progress(void *user, const char *case_name,
                               const struct wl_sph_progress *pr) {
  struct ladder_progress *lp = user;
  if (case_name && strstr(case_name, ", still water")) { /* its reference run (plan.h) */
    char label[sizeof lp->label + 32];
    snprintf(label, sizeof label, "%s, still water", lp->label);
    lp->opts->progress(lp->opts->user, label, pr);
    return;
  }
  lp->opts->progress(lp->opts->user, lp->label, pr);
}

static double rel_change(double f, double ref) { return fabs(f - ref) / fabs(ref); }

/* A level's 95 % sampling uncertainty of a mean of r runs, absolute (NaN
 * for one run or where not defined: wl_loads_convergence_sampled reads it
 * as none) */
static double sampling_abs(double sd, int r, double mean) {
  return wl_loads_mean_uncertainty(sd, r, mean) * fabs(mean);
}

void ladder_estimate(struct wl_assess_convergence *cv) {
  double h[WL_ASSESS_MAX_LEVELS] = {0}, fo[WL_ASSESS_MAX_LEVELS] = {0};
  double im[WL_ASSESS_MAX_LEVELS] = {0};
  double fd[WL_ASSESS_MAX_LEVELS] = {0}; /* the peak force's part above the force at rest */
  /* each level's sampling uncertainty of those (absolute; NaN: one run) */
  double uo[WL_ASSESS_MAX_LEVELS] = {0}, ud[WL_ASSESS_MAX_LEVELS] = {0}, ui[WL_ASSESS_MAX_LEVELS] = {0};
  int idx[WL_ASSESS_MAX_LEVELS] = {0}, m = 0;
  /* only complete levels: a stopped run's peaks are not the event's */
  for (int k = 0; k < cv->n_levels; k++) {
    cv->lv[k].error = NAN;
    if (cv->lv[k].status != WL_OK) continue;
    h[m] = cv->lv[k].dp;
    fo[m] = cv->lv[k].peak_force;
    fd[m] = cv->lv[k].peak_force - cv->lv[k].rest_force;
    im[m] = cv->lv[k].impulse_positive;
    const int r = cv->lv[k].realisations;
    uo[m] = sampling_abs(cv->lv[k].peak_force_sd, r, fo[m]);
    ud[m] = sampling_abs(cv->lv[k].peak_force_dynamic_sd, r, fd[m]);
    ui[m] = sampling_abs(cv->lv[k].impulse_positive_sd, r, im[m]);
    idx[m++] = k;
  }
  wl_loads_convergence_sampled(h, fo, uo, m, &cv->force);
  wl_loads_convergence_sampled(h, fd, ud, m, &cv->force_dynamic);
  wl_loads_convergence_sampled(h, im, ui, m, &cv->impulse_pos);
  /* the finest level's means carry their own sampling uncertainty, added to
   * the bands the levels give (loads.h wl_loads_mean_uncertainty) */
  cv->force_sampling = cv->dynamic_sampling = cv->impulse_sampling = NAN;
  if (m > 0 && cv->lv[idx[m - 1]].realisations > 1) {
    cv->force_sampling = uo[m - 1] / fabs(fo[m - 1]);
    cv->dynamic_sampling = ud[m - 1] / fabs(fd[m - 1]);
    cv->impulse_sampling = ui[m - 1] / fabs(im[m - 1]);
    if (isfinite(cv->force_sampling)) cv->force.error += cv->force_sampling;
    if (isfinite(cv->dynamic_sampling)) cv->force_dynamic.error += cv->dynamic_sampling;
    if (isfinite(cv->impulse_sampling)) cv->impulse_pos.error += cv->impulse_sampling;
  }
  cv->error_estimate = (isnan(cv->force_dynamic.error) || isnan(cv->impulse_pos.error))
                           ? NAN
                           : fmax(cv->force_dynamic.error, cv->impulse_pos.error);
  cv->target_met = isfinite(cv->error_estimate) && cv->error_estimate <= cv->target;
  if (m < 2) return;
  /* each coarser level against the best value known: Richardson's when the
   * order is meaningful, else the finest complete level */
  double ref_f = cv->force_dynamic.order_ok ? cv->force_dynamic.extrapolated : fd[m - 1];
  double ref_i = cv->impulse_pos.order_ok ? cv->impulse_pos.extrapolated : im[m - 1];
  for (int j = 0; j + 1 < m; j++)
    cv->lv[idx[j]].error = fmax(rel_change(fd[j], ref_f), rel_change(im[j], ref_i));
  cv->lv[idx[m - 1]].error = cv->error_estimate;
}

/* What a level keeps of one realisation's run. */
struct run_loads {
  enum wl_status status;
  double peak_force, peak_force_bound, rest_force, impulse, impulse_phase, impulse_positive,
      impulse_positive_bound, peak_moment, runup, impulse_positive_uncorrected;
};

static struct run_loads run_loads_of(const struct wl_case_result *c) {
  const struct wl_case_loads *l = &c->loads;
  const int have = c->rec.n > 0 && l->force_filtered;
  return (struct run_loads){c->status,
                             have ? l->force_peak.value : NAN,
                             have ? l->force_bound_peak.value : NAN,
                             have ? l->rest_force : NAN,
                             have ? l->impulse_total : NAN,
                             have ? l->impulse_peak : NAN,
                             have ? l->impulse_positive : NAN,
                             have ? l->impulse_positive_bound : NAN,
                             have ? l->moment_peak.value : NAN,
                             have ? l->runup : NAN,
                             have ? l->impulse_positive_uncorrected : NAN};
}

/* Level lv from the run of its first realisation (c: particles, steps,
 * runtime, status) and the loads of all n (rl[0] is c's): each scalar the
 * mean over the complete ones, with the spread of the peak force and the
 * positive impulse. A realisation that did not complete makes the level's
 * status its own: the level then leaves the estimate (ladder_estimate),
 * as a stopped single run does. */
static void level_from_runs(struct wl_assess_level *lv, const struct wl_case_result *c,
                            const struct run_loads *rl, int n) {
  lv->status = c->status;
  lv->n_particles = c->n_particles;
  lv->steps = c->steps;
  lv->runtime_s = c->runtime_s;
  lv->rate = c->runtime_s > 0 ? (double)c->n_particles * (double)c->steps / c->runtime_s : NAN;
  lv->t_reached = c->t_reached;
  lv->error = NAN;
  struct run_loads sum = {WL_OK, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  double sq_f = 0.0, sq_i = 0.0, sq_d = 0.0, lo = INFINITY, hi = -INFINITY;
  int m = 0;
  for (int r = 0; r < n; r++) {
    if (rl[r].status != WL_OK) {
      if (lv->status == WL_OK) lv->status = rl[r].status;
      continue;
    }
    sum.peak_force += rl[r].peak_force, sum.peak_force_bound += rl[r].peak_force_bound;
    sum.rest_force += rl[r].rest_force, sum.impulse += rl[r].impulse;
    sum.impulse_phase += rl[r].impulse_phase, sum.impulse_positive += rl[r].impulse_positive;
    sum.impulse_positive_bound += rl[r].impulse_positive_bound;
    sum.peak_moment += rl[r].peak_moment, sum.runup += rl[r].runup;
    sum.impulse_positive_uncorrected += rl[r].impulse_positive_uncorrected;
    lo = fmin(lo, rl[r].peak_force), hi = fmax(hi, rl[r].peak_force);
    m++;
  }
  if (m == 0) { /* nothing complete: the first run's values, as a single run keeps them */
    sum = rl[0];
    m = 1;
    lo = hi = rl[0].peak_force;
  }
  lv->realisations = n == 1 ? 1 : m;
  lv->peak_force = sum.peak_force / m, lv->peak_force_bound = sum.peak_force_bound / m;
  lv->rest_force = sum.rest_force / m, lv->impulse = sum.impulse / m;
  lv->impulse_phase = sum.impulse_phase / m, lv->impulse_positive = sum.impulse_positive / m;
  lv->impulse_positive_bound = sum.impulse_positive_bound / m;
  lv->peak_moment = sum.peak_moment / m, lv->runup = sum.runup / m;
  lv->impulse_positive_uncorrected = sum.impulse_positive_uncorrected / m;
  lv->peak_force_min = lo, lv->peak_force_max = hi;
  for (int r = 0; r < n && m > 1; r++) {
    if (rl[r].status != WL_OK) continue;
    sq_f += (rl[r].peak_force - lv->peak_force) * (rl[r].peak_force - lv->peak_force);
    sq_i += (rl[r].impulse_positive - lv->impulse_positive) *
            (rl[r].impulse_positive - lv->impulse_positive);
    const double d = (rl[r].peak_force - rl[r].rest_force) - (lv->peak_force - lv->rest_force);
    sq_d += d * d;
  }
  lv->peak_force_sd = m > 1 ? sqrt(sq_f / (m - 1)) : NAN;
  lv->peak_force_dynamic_sd = m > 1 ? sqrt(sq_d / (m - 1)) : NAN;
  lv->impulse_positive_sd = m > 1 ? sqrt(sq_i / (m - 1)) : NAN;
}

/* With realisations, the case's scalar loads become the last level's means
 * (assess.h wl_case_loads.realisations): what the summary and the report
 * quote. The series, the peaks' times and the force at rest stay the first
 * realisation's. */
static void case_from_level(struct wl_case_result *c, const struct wl_assess_level *lv) {
  struct wl_case_loads *l = &c->loads;
  if (lv->realisations < 2 || !l->force_filtered) return;
  l->realisations = lv->realisations;
  l->force_peak.value = lv->peak_force;
  l->force_bound_peak.value = lv->peak_force_bound;
  l->impulse_total = lv->impulse;
  l->impulse_peak = lv->impulse_phase;
  l->impulse_positive = lv->impulse_positive;
  l->impulse_positive_bound = lv->impulse_positive_bound;
  l->impulse_positive_uncorrected = lv->impulse_positive_uncorrected;
  l->moment_peak.value = lv->peak_moment;
  l->runup = lv->runup;
}

static const char *pct(double v, char *buf, size_t size) {
  if (isfinite(v))
    snprintf(buf, size, "%.3g %%", 100.0 * v);
  else
    snprintf(buf, size, "not available");
  return buf;
}

static void ladder_note(struct wl_assess_convergence *cv, const char *stop_word) {
  char e[32], t[32];
  pct(cv->error_estimate, e, sizeof e);
  pct(cv->target, t, sizeof t);
  /* the basis of the larger of the two quantities' bands */
  const struct wl_loads_convergence *gov =
      !(cv->impulse_pos.error > cv->force_dynamic.error) ? &cv->force_dynamic : &cv->impulse_pos;
  const char *basis = wl_loads_estimate_name(gov->basis);
  const struct wl_assess_level *last = &cv->lv[cv->n_levels - 1];
  if (stop_word)
    snprintf(cv->note, sizeof cv->note,
             "level %d of %d (dp = %.4g m) %s, so the ladder stopped there; uncertainty %s "
             "(%s) from the complete levels",
             cv->n_levels, cv->n_planned, last->dp, stop_word, e, basis);
  else if (cv->stopped_early)
    snprintf(cv->note, sizeof cv->note,
             "stopped refining after level %d of %d (dp = %.4g m): the uncertainty %s (%s) "
             "is below the target %s",
             cv->n_levels, cv->n_planned, last->dp, e, basis, t);
  else if (cv->target_given)
    snprintf(cv->note, sizeof cv->note,
             "ran all %d levels; the uncertainty %s (%s) is %s the target %s%s", cv->n_levels, e,
             basis, cv->target_met ? "below" : "above", t,
             cv->target_met ? "" : ": a finer level is needed to meet it");
  else
    snprintf(cv->note, sizeof cv->note,
             "ran all %d levels (resolution.target_error not set, so no early stop); the "
             "uncertainty %s (%s) is %s the default target %s",
             cv->n_levels, e, basis, cv->target_met ? "below" : "above", t);
}

/* The progress of runs side by side (ladder_side_by_side): each run
 * reports its simulated time here, and the ladder reports the share of
 * all their planned work done (each run weighted by its planned
 * particle-steps), at most every half second, under one lock, so that
 * the caller's progress function is called from one thread at a time.
 * The finest level's first run, which reports alone otherwise, ends long
 * before its realisations and the levels beside it. */
struct ladder_share {
  pthread_mutex_t lock;
  const struct wl_assess_opts *opts;
  const char *label;
  int n;
  double *weight, *frac, total, wall, next;
};
struct ladder_share_hook {
  struct ladder_share *sh;
  int j;
};

static void ladder_share_progress(void *user, const char *case_name,
                                  const struct wl_sph_progress *pr) {
  const struct ladder_share_hook *hk = user;
  struct ladder_share *sh = hk->sh;
  pthread_mutex_lock(&sh->lock);
  (void)case_name;
  sh->frac[hk->j] = pr->t_end > 0 ? fmin(1.0, pr->t / pr->t_end) : 1.0;
  if (pr->wall_s > sh->wall) sh->wall = pr->wall_s;
  double done = 0.0;
  for (int j = 0; j < sh->n; j++) done += sh->weight[j] * sh->frac[j];
  done = sh->total > 0 ? done / sh->total : 1.0;
  if (sh->wall >= sh->next || done >= 1.0) {
    struct wl_sph_progress all = *pr;
    all.runs = sh->n;
    all.done = done;
    all.wall_s = sh->wall;
    all.eta_s = done > 0 ? sh->wall * (1.0 - done) / done : NAN;
    sh->opts->progress(sh->opts->user, sh->label, &all);
    sh->next = done >= 1.0 ? INFINITY : sh->wall + 0.5;
  }
  pthread_mutex_unlock(&sh->lock);
}

/* Levels side by side on one GPU: within WL_PLAN_GPU_SIDE_BY_SIDE_MEMORY
 * of its memory for all of them together (the plan's estimates), else one
 * after the other. */

/* A coarser level run beside the finest (ladder_side_by_side). */
struct level_job {
  int level, real;      /* ladder level (0-based) and realisation */
  int how;              /* assess_case's flags */
  struct wl_scenario s; /* shallow copy with the level's dp; never cleared */
  struct wl_plan p;
  enum wl_load_case load;
  struct wl_assess_opts opts; /* no progress: only the finest level reports */
  struct wl_case_result c;
  struct wl_error err;
  enum wl_status st;
};

static void *level_thread(void *arg) {
  struct level_job *j = arg;
  j->st = assess_case(&j->s, &j->p, j->load, &j->opts, NULL, j->how, &j->c, &j->err);
  return NULL;
}

/* Plan realisation r of n_real of level k of the ladder into *ls, *lp (the
 * scenario with the level's dp and, for r > 0, the crater moved by
 * wl_plan_realisation_x). */
static enum wl_status plan_level(const struct wl_scenario *s, const struct wl_assess_level *lv,
                                 int k, int n, int r, int n_real, struct wl_scenario *ls,
                                 struct wl_plan *lp, struct wl_error *err) {
  *ls = *s; /* shallow: the text stays the caller's; ls is never cleared */
  ls->resolution.dp.is_auto = 0;
  ls->resolution.dp.given = 1;
  ls->resolution.dp.q.si = lv->dp;
  ls->explosion.at.q.si = wl_plan_realisation_x(s->explosion.at.q.si, lv->dp, r, n_real);
  enum wl_status st = wl_plan_make(ls, lp, err);
  if (st) wl_error_prefix(err, "convergence level %d/%d (dp = %g m): ", k + 1, n, lv->dp);
  return st;
}

/* Every level of the ladder at once on the GPU: a small flume's step is
 * mostly fixed cost (launches, the per-step synchronisation), so levels in
 * their own threads, each with its own CUDA stream, fill the GPU that one
 * leaves idle (issue 21). The coarser levels run in threads without
 * progress or snapshots (HDF5 is not thread-safe); the finest in this
 * thread, as the sequential ladder's last level. A level's results are
 * those it gives alone: each run is deterministic on its own stream.
 * Returns 1 (with *st) when it ran the ladder, 0 when the levels do not
 * fit the GPU's memory together (or cannot be allocated) and the caller
 * runs them one after the other. */
static int ladder_side_by_side(const struct wl_scenario *s, enum wl_load_case load, int n_real,
                               const struct wl_assess_opts *opts, double gpu_bytes,
                               const char *snapshots, int urgent, struct wl_case_result *c,
                               struct wl_assess_convergence *cv, enum wl_status *st_out,
                               struct wl_error *err) {
  const int n = cv->n_planned, n_jobs = n * n_real;
  const int last = n_jobs - n_real; /* the finest level's first realisation: this thread's */
  struct level_job *jobs = calloc((size_t)n_jobs, sizeof *jobs);
  pthread_t *tid = calloc((size_t)n_jobs, sizeof *tid);
  int *started = calloc((size_t)n_jobs, sizeof *started);
  struct run_loads *rl = calloc((size_t)n_jobs, sizeof *rl);
  struct ladder_share_hook *hooks = calloc((size_t)n_jobs, sizeof *hooks);
  double *share = calloc(2 * (size_t)n_jobs, sizeof *share);
  if (!jobs || !tid || !started || !rl || !hooks || !share) {
    free(jobs), free(tid), free(started), free(rl), free(hooks), free(share);
    return 0;
  }
  double bytes = 0;
  enum wl_status st = WL_OK;
  for (int j = 0; j < n_jobs && !st; j++) {
    jobs[j].level = j / n_real, jobs[j].real = j % n_real;
    st = plan_level(s, &cv->lv[jobs[j].level], jobs[j].level, n, jobs[j].real, n_real, &jobs[j].s,
                    &jobs[j].p, err);
    bytes += jobs[j].p.gpu_memory_bytes;
  }
  if (st || !(bytes <= WL_PLAN_GPU_SIDE_BY_SIDE_MEMORY * gpu_bytes)) {
    free(jobs), free(tid), free(started), free(rl), free(hooks), free(share);
    return 0; /* the sequential ladder plans again and says why a level fails */
  }
  char label[128];
  if (n_real > 1)
    snprintf(label, sizeof label, "%s, levels 1-%d x %d realisations side by side",
             wl_flume_case_name(load), n, n_real);
  else
    snprintf(label, sizeof label, "%s, levels 1-%d side by side", wl_flume_case_name(load), n);
  struct ladder_share sh = {.opts = opts, .label = label, .n = n_jobs, .weight = share,
                            .frac = share + n_jobs};
  pthread_mutex_init(&sh.lock, NULL);
  /* a level's still-water reference (plan.h) runs with its first
   * realisation (beside it, in its own stream, without progress); the
   * others take it when all are done */
  for (int j = 0; j < n_jobs; j++) {
    const struct wl_plan *jp = &jobs[j].p;
    jobs[j].how = ASSESS_DEFER | (jobs[j].real > 0 ? ASSESS_NO_STILL : 0);
    sh.weight[j] = load == WL_CASE_EXPLOSION ? jp->explosion.particle_steps
                                             : jp->solitary.particle_steps;
    sh.total += sh.weight[j];
    hooks[j] = (struct ladder_share_hook){&sh, j};
  }
  for (int j = 0; j < n_jobs; j++) {
    if (j == last) continue;
    struct level_job *jb = &jobs[j];
    jb->load = load;
    jb->opts = *opts;
    jb->opts.progress = opts->progress ? ladder_share_progress : NULL;
    jb->opts.user = &hooks[j];
    wl_error_clear(&jb->err);
    started[j] = pthread_create(&tid[j], NULL, level_thread, jb) == 0;
  }
  struct wl_assess_opts lo = *opts;
  if (opts->progress) {
    lo.progress = ladder_share_progress;
    lo.user = &hooks[last];
  }
  st = assess_case(&jobs[last].s, &jobs[last].p, load, &lo, snapshots,
                   ASSESS_DEFER | (urgent ? ASSESS_URGENT : 0), c, err);
  for (int j = 0; j < n_jobs; j++) {
    if (j == last) {
      rl[j] = run_loads_of(c);
      continue;
    }
    if (started[j])
      pthread_join(tid[j], NULL);
    else
      level_thread(&jobs[j]); /* no thread to be had: here, after the finest */
    /* a later realisation takes its level's reference, from the level's
     * first run (joined before it; the finest level's is c) */
    struct wl_case_result *first =
        jobs[j].level == n - 1 ? c : &jobs[jobs[j].level * n_real].c;
    if (jobs[j].real > 0 && first->still) {
      struct wl_error aerr;
      wl_error_clear(&aerr);
      if (assess_attach_still(&jobs[j].c, first->still, &aerr) && jobs[j].st == WL_OK)
        jobs[j].st = WL_ENOMEM, jobs[j].err = aerr;
    }
    rl[j] = run_loads_of(&jobs[j].c);
    if (jobs[j].st != WL_OK && rl[j].status == WL_OK) rl[j].status = jobs[j].st;
  }
  for (int k = 0; k < n; k++) {
    const struct wl_case_result *first = k == n - 1 ? c : &jobs[k * n_real].c;
    level_from_runs(&cv->lv[k], first, rl + k * n_real, n_real);
  }
  for (int j = 0; j < n_jobs; j++)
    if (j != last) wl_assess_case_clear(&jobs[j].c);
  cv->n_levels = n;
  ladder_estimate(cv);
  case_from_level(c, &cv->lv[n - 1]);
  const char *stop_word = NULL;
  if (st && (c->rec.n > 0 || st == WL_EUNSTABLE || st == WL_EINTERRUPTED))
    stop_word = st == WL_EUNSTABLE      ? "went unstable"
                : st == WL_EINTERRUPTED ? "was interrupted"
                                        : "failed";
  ladder_note(cv, stop_word);
  pthread_mutex_destroy(&sh.lock);
  free(jobs), free(tid), free(started), free(rl), free(hooks), free(share);
  *st_out = st;
  return 1;
}

enum wl_status ladder_run(const struct wl_scenario *s, const struct wl_plan *plan,
                          enum wl_load_case load, const struct wl_assess_opts *opts,
                          const char *snapshots, int urgent, struct wl_case_result *c,
                          struct wl_assess_convergence *cv, struct wl_error *err) {
  memset(cv, 0, sizeof *cv);
  memset(c, 0, sizeof *c);
  int n = s->resolution.n_levels;
  if (n > WL_ASSESS_MAX_LEVELS) n = WL_ASSESS_MAX_LEVELS;
  const int n_real = load == WL_CASE_EXPLOSION && plan->realisations > 1 ? plan->realisations : 1;
  cv->n_planned = n;
  cv->target = s->resolution.target_error.q.si;
  cv->target_given = s->resolution.target_error.given;
  cv->error_estimate = NAN;
  for (int k = 0; k < n; k++) {
    cv->lv[k].factor = s->resolution.levels[k].q.si;
    cv->lv[k].dp = wl_plan_level_dp(s, plan, cv->lv[k].factor);
  }
  /* side by side on a GPU, unless refining stops at a target error (the
   * next level depends on the last) */
  const double gpu_bytes = cv->target_given || n < 2 ? 0.0 : assess_gpu_memory(s, opts);
  enum wl_status side_st;
  if (gpu_bytes > 0 && ladder_side_by_side(s, load, n_real, opts, gpu_bytes, snapshots, urgent, c,
                                           cv, &side_st, err))
    return side_st;
  /* each level is the scenario with dp set to the level's (plan.h
   * wl_plan_level_dp), planned again; its realisations one after the other,
   * the first into c (the finer level replaces the coarser one) */
  struct wl_scenario *sl = malloc(sizeof *sl);
  struct wl_plan *pl = malloc(sizeof *pl);
  struct wl_case_result *extra = malloc(sizeof *extra);
  if (!sl || !pl || !extra) {
    free(sl), free(pl), free(extra);
    return wl_error_set(err, WL_ENOMEM, "convergence ladder: no memory");
  }
  enum wl_status st = WL_OK;
  const char *stop_word = NULL;
  for (int k = 0; k < n; k++) {
    struct wl_assess_level *lv = &cv->lv[k];
    struct run_loads rl[WL_SCENARIO_MAX_REALISATIONS];
    int ran = 0, planned = 1;
    for (int r = 0; r < n_real; r++) {
      if ((st = plan_level(s, lv, k, n, r, n_real, sl, pl, err))) {
        planned = 0;
        break;
      }
      struct ladder_progress lp = {opts, ""};
      if (n_real > 1)
        snprintf(lp.label, sizeof lp.label, "%s, level %d/%d, dp = %.4g m, realisation %d/%d",
                 wl_flume_case_name(load), k + 1, n, lv->dp, r + 1, n_real);
      else
        snprintf(lp.label, sizeof lp.label, "%s, level %d/%d, dp = %.4g m",
                 wl_flume_case_name(load), k + 1, n, lv->dp);
      struct wl_assess_opts lo = *opts;
      if (opts->progress) {
        lo.progress = ladder_on_progress;
        lo.user = &lp;
      }
      struct wl_case_result *run = r == 0 ? c : extra;
      if (r == 0 && k > 0) wl_assess_case_clear(c); /* the finer level replaces the coarser */
      if (r > 0) memset(extra, 0, sizeof *extra);
      /* every level writes the snapshots file (its first realisation); the
       * last level run keeps it */
      /* the level's still-water reference (plan.h) runs with its first
       * realisation; the others take it */
      st = assess_case(sl, pl, load, &lo, r == 0 ? snapshots : NULL,
                       ASSESS_DEFER | (urgent && r == 0 ? ASSESS_URGENT : 0) |
                           (r > 0 ? ASSESS_NO_STILL : 0),
                       run, err);
      if (r > 0 && c->still && run->rec.n > 0) {
        enum wl_status ast = assess_attach_still(run, c->still, err);
        if (ast && st == WL_OK) st = ast;
      }
      const int no_run = st && run->rec.n == 0 && st != WL_EUNSTABLE && st != WL_EINTERRUPTED;
      rl[r] = run_loads_of(run);
      if (st != WL_OK && rl[r].status == WL_OK) rl[r].status = st;
      if (r > 0) wl_assess_case_clear(extra);
      if (no_run) {
        planned = 0;
        break;
      }
      ran = r + 1;
      if (st) break;
    }
    if (!planned && ran == 0) break; /* no run at this level */
    level_from_runs(lv, c, rl, ran);
    cv->n_levels = k + 1;
    ladder_estimate(cv);
    if (st) {
      stop_word = st == WL_EUNSTABLE      ? "went unstable"
                  : st == WL_EINTERRUPTED ? "was interrupted"
                                          : "failed";
      break;
    }
    if (cv->target_given && k + 1 < n && cv->target_met) {
      cv->stopped_early = 1;
      break;
    }
  }
  if (cv->n_levels) {
    case_from_level(c, &cv->lv[cv->n_levels - 1]);
    ladder_note(cv, stop_word);
  }
  free(sl), free(pl), free(extra);
  return st;
}
