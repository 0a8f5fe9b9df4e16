/* validate.c: the reference suite's driver: case selection, the resolution
 * ladder (dp0, dp0/sqrt2, dp0/2, ...), pass/fail at the finest level, and
 * the observed convergence order with a Richardson-extrapolated error.
 *
 * Order from three levels (Roache 1998, "Verification and Validation in
 * Computational Science and Engineering", the grid convergence index
 * method; wl_loads_convergence, shared with assess's ladder): with q1, q2,
 * q3 the primary metric from coarse to fine (signed relative error, or
 * RMSE) and a constant ratio r, p = ln((q1 - q2) / (q2 - q3)) / ln r,
 * meaningful when (q1 - q2) and (q2 - q3) have the same sign and p is in
 * [WL_LOADS_ORDER_MIN, WL_LOADS_ORDER_MAX]; then
 *   q_inf = q3 + (q3 - q2) / (r^p - 1)
 * is the error the method would keep at infinite resolution (model error:
 * physics, boundary treatment, the reference's own uncertainty). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "internal.h"
#include "wallload/config.h"
#include "wallload/cuda_device.h"
#include "wallload/loads.h"

#ifndef WL_VALIDATE_REFERENCE_DIR
#define WL_VALIDATE_REFERENCE_DIR "reference"
#endif

int wl_validate_n_cases(void) { return wl_val_n_cases; }

const char *wl_validate_case_name(int i) {
  return i >= 0 && i < wl_val_n_cases ? wl_val_cases[i].name : NULL;
}

const char *wl_validate_case_title(int i) {
  return i >= 0 && i < wl_val_n_cases ? wl_val_cases[i].title : NULL;
}

enum wl_status wl_validate_select(const char *name, int *sel, struct wl_error *err) {
  int found = 0;
  const size_t len = strlen(name);
  for (int i = 0; i < wl_val_n_cases; i++) {
    const char *cn = wl_val_cases[i].name;
    if (!strcmp(cn, name) || (len > 0 && !strncmp(cn, name, len) && cn[len] == '-')) {
      sel[i] = 1;
      found = 1;
    }
  }
  if (found) return WL_OK;
  char list[1024] = "";
  for (int i = 0; i < wl_val_n_cases; i++) {
    size_t u = strlen(list);
    snprintf(list + u, sizeof list - u, "%s%s", i ? ", " : "", wl_val_cases[i].name);
  }
  return wl_error_set(err, WL_EINPUT,
                      "validate: unknown case '%s'; valid: %s (or the group 'solitary')", name,
                      list);
}

static const char *kind_word(enum wl_validate_kind k) {
  switch (k) {
  case WL_VALIDATE_REL: return "error";
  case WL_VALIDATE_RMSE: return "RMSE";
  case WL_VALIDATE_CORR: return "r";
  case WL_VALIDATE_RATIO: return "ratio";
  }
  return "?";
}

/* Convergence order and extrapolation of the primary metric over the last
 * three levels. */
static void convergence(struct wl_validate_result *r) {
  r->order = NAN;
  r->extrapolated = NAN;
  r->order_ok = 0;
  if (r->n_levels < 3) return;
  const struct wl_validate_level *l1 = &r->lv[r->n_levels - 3], *l2 = l1 + 1, *l3 = l1 + 2;
  if (l1->n_metrics < 1 || l2->n_metrics < 1 || l3->n_metrics < 1) return;
  /* the same arithmetic as assess's convergence ladder (loads.h) */
  const double h[3] = {l1->dp, l2->dp, l3->dp};
  const double f[3] = {l1->m[0].error, l2->m[0].error, l3->m[0].error};
  struct wl_loads_convergence c;
  wl_loads_convergence(h, f, 3, &c);
  r->order = c.order;
  r->order_ok = c.order_ok;
  r->extrapolated = c.extrapolated;
}

static void verdict(struct wl_validate_result *r) {
  r->pass = 1;
  size_t u = 0;
  r->verdict[0] = '\0';
  for (int l = 0; l < r->n_levels; l++) {
    if (r->lv[l].status != WL_OK) {
      r->pass = 0;
      u += (size_t)snprintf(r->verdict + u, sizeof r->verdict - u,
                            "%slevel %d (dp = %g m) stopped: %.200s", u ? "; " : "", l + 1,
                            r->lv[l].dp, r->lv[l].message);
      if (u >= sizeof r->verdict) return;
    }
  }
  if (r->n_levels == 0) {
    r->pass = 0;
    snprintf(r->verdict, sizeof r->verdict, "no level ran");
    return;
  }
  const struct wl_validate_level *f = &r->lv[r->n_levels - 1];
  for (int j = 0; j < f->n_metrics; j++) {
    const struct wl_validate_metric *m = &f->m[j];
    if (m->pass) continue;
    r->pass = 0;
    if (u >= sizeof r->verdict) return;
    if (m->kind == WL_VALIDATE_CORR)
      u += (size_t)snprintf(r->verdict + u, sizeof r->verdict - u, "%s%s = %.3f below %.3f",
                            u ? "; " : "", m->name, m->error, m->tol);
    else if (m->kind == WL_VALIDATE_REL)
      u += (size_t)snprintf(r->verdict + u, sizeof r->verdict - u,
                            "%s%s off by %+.1f %% (tolerance %.1f %%)", u ? "; " : "", m->name,
                            100 * m->error, 100 * m->tol);
    else
      u += (size_t)snprintf(r->verdict + u, sizeof r->verdict - u, "%s%s %s = %.1f %% (tolerance %.1f %%)",
                            u ? "; " : "", m->name, kind_word(m->kind), 100 * m->error, 100 * m->tol);
  }
  if (r->pass) snprintf(r->verdict, sizeof r->verdict, "pass");
}

enum wl_status wl_validate_run(int i, const struct wl_validate_opts *opts,
                               struct wl_validate_result *r, struct wl_error *err) {
  memset(r, 0, sizeof *r);
  if (i < 0 || i >= wl_val_n_cases)
    return wl_error_set(err, WL_EINPUT, "validate: case index %d out of range", i);
  const struct wl_val_case *c = &wl_val_cases[i];
  snprintf(r->name, sizeof r->name, "%s", c->name);
  snprintf(r->title, sizeof r->title, "%s", c->title);
  r->ratio = sqrt(2.0);
  r->order = r->extrapolated = NAN;
  /* the quick ladder of a costly case (spheric2: one 3D level) is shorter,
   * the full ladder of a case that converges only at finer levels (the
   * solitary waves) longer, unless --ladder says otherwise */
  const int n_levels = opts->n_levels > 0                  ? opts->n_levels
                       : opts->quick && c->quick_levels > 0 ? c->quick_levels
                       : !opts->quick && c->levels > 0      ? c->levels
                                                            : 3;
  if (n_levels > WL_VALIDATE_MAX_LEVELS)
    return wl_error_set(err, WL_EINPUT, "validate: --ladder %d: at most %d levels", n_levels,
                        WL_VALIDATE_MAX_LEVELS);
  struct wl_val_ctx ctx = {opts->reference_dir ? opts->reference_dir : WL_VALIDATE_REFERENCE_DIR,
                           opts->threads, opts->quick, opts->verlet, opts->residual,
                           opts->smagorinsky, &wl_backend_cpu_ops, "cpu",
                           c->name, 0, opts->progress, opts->user};
  snprintf(r->integrator, sizeof r->integrator, "%s", opts->verlet ? "verlet" : "symplectic");
  r->residual = opts->residual;
  r->smagorinsky = opts->smagorinsky;
  /* the backend, as assess picks it (--backend cpu|cuda|auto) */
  const char *want = opts->backend ? opts->backend : "cpu";
  if (strcmp(want, "cpu") && strcmp(want, "cuda") && strcmp(want, "auto"))
    return wl_error_set(err, WL_EINPUT, "validate: backend '%s'; valid: cpu, cuda, auto", want);
  if (strcmp(want, "cpu")) {
    struct wl_cuda_device dev;
    struct wl_error qerr;
    wl_error_clear(&qerr);
    if (wl_cuda_device_query(&dev, &qerr) == WL_OK) {
      ctx.ops = &wl_backend_cuda_ops;
      ctx.backend = "cuda";
    } else if (!strcmp(want, "cuda")) {
      return wl_error_set(err, WL_EUNSUPPORTED, "validate: backend cuda: %s", qerr.msg);
    }
  }
  snprintf(r->backend, sizeof r->backend, "%s", ctx.backend);
  const double dp0 = opts->quick ? c->dp0_quick : c->dp0;
  for (int l = 0; l < n_levels; l++) {
    struct wl_validate_level *lv = &r->lv[l];
    memset(lv, 0, sizeof *lv);
    lv->dp = dp0 / pow(r->ratio, l);
    ctx.level = l;
    enum wl_status st = c->run(c, &ctx, lv->dp, lv, err);
    if (st) {
      wl_error_prefix(err, "validate %s, dp = %g m: ", c->name, lv->dp);
      verdict(r);
      return st;
    }
    r->n_levels = l + 1;
    if (opts->on_level) opts->on_level(opts->user, r, l);
  }
  convergence(r);
  verdict(r);
  return WL_OK;
}
