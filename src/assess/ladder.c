/* ladder.c: the convergence ladder of a load case (resolution.convergence):
 * the case run at dp x factor for each level, coarse to fine, its scalar
 * loads kept per level, the observed order, Richardson value and uncertainty
 * of peak force and impulse after each level (wl_loads_convergence),
 * and the early stop at resolution.target_error. Definitions in assess.h. */
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
  (void)case_name;
  lp->opts->progress(lp->opts->user, lp->label, pr);
}

static double rel_change(double f, double ref) { return fabs(f - ref) / fabs(ref); }

void ladder_estimate(struct wl_assess_convergence *cv) {
  double h[WL_ASSESS_MAX_LEVELS], fo[WL_ASSESS_MAX_LEVELS], im[WL_ASSESS_MAX_LEVELS];
  double fd[WL_ASSESS_MAX_LEVELS]; /* the peak force's part above the force at rest */
  int idx[WL_ASSESS_MAX_LEVELS], m = 0;
  /* only complete levels: a stopped run's peaks are not the event's */
  for (int k = 0; k < cv->n_levels; k++) {
    cv->lv[k].error = NAN;
    if (cv->lv[k].status != WL_OK) continue;
    h[m] = cv->lv[k].dp;
    fo[m] = cv->lv[k].peak_force;
    fd[m] = cv->lv[k].peak_force - cv->lv[k].rest_force;
    im[m] = cv->lv[k].impulse_positive;
    idx[m++] = k;
  }
  wl_loads_convergence(h, fo, m, &cv->force);
  wl_loads_convergence(h, fd, m, &cv->force_dynamic);
  wl_loads_convergence(h, im, m, &cv->impulse_pos);
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

static void level_from_case(struct wl_assess_level *lv, const struct wl_case_result *c) {
  const struct wl_case_loads *l = &c->loads;
  int have = c->rec.n > 0 && l->force_filtered;
  lv->status = c->status;
  lv->n_particles = c->n_particles;
  lv->steps = c->steps;
  lv->runtime_s = c->runtime_s;
  lv->rate = c->runtime_s > 0 ? (double)c->n_particles * (double)c->steps / c->runtime_s : NAN;
  lv->t_reached = c->t_reached;
  lv->peak_force = have ? l->force_peak.value : NAN;
  lv->peak_force_bound = have ? l->force_bound_peak.value : NAN;
  lv->rest_force = have ? l->rest_force : NAN;
  lv->impulse = have ? l->impulse_total : NAN;
  lv->impulse_phase = have ? l->impulse_peak : NAN;
  lv->impulse_positive = have ? l->impulse_positive : NAN;
  lv->peak_moment = have ? l->moment_peak.value : NAN;
  lv->runup = have ? l->runup : NAN;
  lv->error = NAN;
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

/* Levels side by side on one GPU: within WL_PLAN_GPU_SIDE_BY_SIDE_MEMORY
 * of its memory for all of them together (the plan's estimates), else one
 * after the other. */

/* A coarser level run beside the finest (ladder_side_by_side). */
struct level_job {
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
  j->st = assess_case(&j->s, &j->p, j->load, &j->opts, NULL, ASSESS_DEFER, &j->c, &j->err);
  return NULL;
}

/* Plan level k of the ladder into *ls, *lp (the scenario with the level's dp). */
static enum wl_status plan_level(const struct wl_scenario *s, const struct wl_assess_level *lv,
                                 int k, int n, struct wl_scenario *ls, struct wl_plan *lp,
                                 struct wl_error *err) {
  *ls = *s; /* shallow: the text stays the caller's; ls is never cleared */
  ls->resolution.dp.is_auto = 0;
  ls->resolution.dp.given = 1;
  ls->resolution.dp.q.si = lv->dp;
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
static int ladder_side_by_side(const struct wl_scenario *s, enum wl_load_case load,
                               const struct wl_assess_opts *opts, double gpu_bytes,
                               const char *snapshots, int urgent, struct wl_case_result *c,
                               struct wl_assess_convergence *cv, enum wl_status *st_out,
                               struct wl_error *err) {
  const int n = cv->n_planned;
  struct level_job *jobs = calloc((size_t)n, sizeof *jobs);
  if (!jobs) return 0;
  double bytes = 0;
  enum wl_status st = WL_OK;
  for (int k = 0; k < n && !st; k++) {
    st = plan_level(s, &cv->lv[k], k, n, &jobs[k].s, &jobs[k].p, err);
    bytes += jobs[k].p.gpu_memory_bytes;
  }
  if (st || !(bytes <= WL_PLAN_GPU_SIDE_BY_SIDE_MEMORY * gpu_bytes)) {
    free(jobs);
    return 0; /* the sequential ladder plans again and says why a level fails */
  }
  pthread_t tid[WL_ASSESS_MAX_LEVELS];
  int started[WL_ASSESS_MAX_LEVELS] = {0};
  for (int k = 0; k + 1 < n; k++) {
    struct level_job *j = &jobs[k];
    j->load = load;
    j->opts = *opts;
    j->opts.progress = NULL;
    wl_error_clear(&j->err);
    started[k] = pthread_create(&tid[k], NULL, level_thread, j) == 0;
  }
  struct ladder_progress lp = {opts, ""};
  snprintf(lp.label, sizeof lp.label, "%s, level %d/%d, dp = %.4g m (levels 1-%d beside it)",
           wl_flume_case_name(load), n, n, cv->lv[n - 1].dp, n - 1);
  struct wl_assess_opts lo = *opts;
  if (opts->progress) {
    lo.progress = ladder_on_progress;
    lo.user = &lp;
  }
  st = assess_case(&jobs[n - 1].s, &jobs[n - 1].p, load, &lo, snapshots,
                   ASSESS_DEFER | (urgent ? ASSESS_URGENT : 0), c, err);
  for (int k = 0; k + 1 < n; k++) {
    if (started[k])
      pthread_join(tid[k], NULL);
    else
      level_thread(&jobs[k]); /* no thread to be had: here, after the finest */
    level_from_case(&cv->lv[k], &jobs[k].c);
    if (jobs[k].st != WL_OK && cv->lv[k].status == WL_OK) cv->lv[k].status = jobs[k].st;
    wl_assess_case_clear(&jobs[k].c);
  }
  level_from_case(&cv->lv[n - 1], c);
  cv->n_levels = n;
  ladder_estimate(cv);
  const char *stop_word = NULL;
  if (st && (c->rec.n > 0 || st == WL_EUNSTABLE || st == WL_EINTERRUPTED))
    stop_word = st == WL_EUNSTABLE      ? "went unstable"
                : st == WL_EINTERRUPTED ? "was interrupted"
                                        : "failed";
  ladder_note(cv, stop_word);
  free(jobs);
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
  if (gpu_bytes > 0 &&
      ladder_side_by_side(s, load, opts, gpu_bytes, snapshots, urgent, c, cv, &side_st, err))
    return side_st;
  /* each level is the scenario with dp set to the level's (plan.h
   * wl_plan_level_dp), planned again */
  struct wl_scenario *sl = malloc(sizeof *sl);
  struct wl_plan *pl = malloc(sizeof *pl);
  if (!sl || !pl) {
    free(sl), free(pl);
    return wl_error_set(err, WL_ENOMEM, "convergence ladder: no memory");
  }
  enum wl_status st = WL_OK;
  const char *stop_word = NULL;
  for (int k = 0; k < n; k++) {
    struct wl_assess_level *lv = &cv->lv[k];
    if ((st = plan_level(s, lv, k, n, sl, pl, err))) break;
    struct ladder_progress lp = {opts, ""};
    snprintf(lp.label, sizeof lp.label, "%s, level %d/%d, dp = %.4g m", wl_flume_case_name(load),
             k + 1, n, lv->dp);
    struct wl_assess_opts lo = *opts;
    if (opts->progress) {
      lo.progress = ladder_on_progress;
      lo.user = &lp;
    }
    if (k > 0) wl_assess_case_clear(c); /* the finer level replaces the coarser one */
    /* every level writes the snapshots file; the last level run keeps it */
    st = assess_case(sl, pl, load, &lo, snapshots, ASSESS_DEFER | (urgent ? ASSESS_URGENT : 0), c,
                     err);
    level_from_case(lv, c);
    cv->n_levels = k + 1;
    ladder_estimate(cv);
    if (st) {
      if (c->rec.n == 0 && st != WL_EUNSTABLE && st != WL_EINTERRUPTED) break; /* no run */
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
  if (cv->n_levels) ladder_note(cv, stop_word);
  free(sl);
  free(pl);
  return st;
}
