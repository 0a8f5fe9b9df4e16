/* sections.h: the section renderers of the design report (private to
 * src/report). wl_report_render (sections.c) reads the results, opens the
 * document and calls one renderer per template section; each renderer
 * draws through the toolkit (wallload/draw.h) from struct wl_results alone.
 *
 * Units on the page: forces kN/m, impulses kN s/m, moments kN m/m,
 * pressures kPa, lengths m, times s (the stored values are SI; the factor
 * is applied only when drawing). Every renderer says on the page what it
 * cannot show (a missing case, a short record, no snapshots) rather than
 * failing; a renderer fails only when the document does (cairo, memory). */
#ifndef WALLLOAD_REPORT_SECTIONS_H
#define WALLLOAD_REPORT_SECTIONS_H

#include <stddef.h>

#include "wallload/draw.h"
#include "digest.h"
#include "wallload/store.h"
#include "wallload/report.h"

#define KILO 1000.0 /* N -> kN, Pa -> kPa */

/* What every renderer gets. */
struct wl_report_ctx {
  struct wl_report_doc *doc;
  const struct wl_report_template *tpl;
  const struct wl_results *res;
  int digits;                /* significant digits of the peak values wherever they are printed
                                (the template's peaks section, else 3), so the summary, the peaks
                                table and the design comparison print the same strings */
  char template_source[600]; /* where the template came from, for the run record */
  char digest[65];           /* SHA-256 of the stored scenario text (digest.h) */
};

/* Why what the plan derived is not shown: results without /plan (written
 * before results.h5 held it), whose scenario the report no longer re-plans. */
#define WL_REPORT_NO_PLAN                                                                      \
  "the results hold no /plan (written by an older wallload); run wallload assess again to "   \
  "store it"

/* Owned temporary arrays of one renderer, freed together. */
enum { WL_REPORT_SCRATCH_MAX = 96 };
struct wl_report_scratch {
  void *p[WL_REPORT_SCRATCH_MAX];
  int n;
};

/* n doubles (uninitialised), or NULL when out of memory or slots. */
double *wl_report_scratch_alloc(struct wl_report_scratch *s, size_t n);

/* v[i] / divisor into a scratch array; NULL when v is NULL or out of memory. */
double *wl_report_scratch_scaled(struct wl_report_scratch *s, const double *v, size_t n,
                                 double divisor);

void wl_report_scratch_free(struct wl_report_scratch *s);

/* v to `sig` significant digits (wl_report_format_sig) into buf. */
const char *wl_report_fmt(double v, int sig, char *buf, size_t size);

/* "solitary wave", "explosion wave" for case index i. */
const char *wl_report_case_label(int i);

/* The section's heading (level 1; none for an empty title) and its text. */
enum wl_status wl_report_section_begin(struct wl_report_ctx *c, const struct wl_report_section *s,
                                       struct wl_error *err);

/* One paragraph printed from a format. */
enum wl_status wl_report_paragraphf(struct wl_report_doc *d, struct wl_error *err, const char *fmt,
                                    ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* The index of the case governing a quantity: the larger finite value of
 * a (solitary) and b (explosion); -1 when neither is finite. */
int wl_report_governs(double a, double b);

/* Renderers, one per section type. */
enum wl_status wl_report_render_title(struct wl_report_ctx *c, const struct wl_report_section *s,
                                      struct wl_error *err);
enum wl_status wl_report_render_scene(struct wl_report_ctx *c, const struct wl_report_section *s,
                                      struct wl_error *err);
enum wl_status wl_report_render_snapshots(struct wl_report_ctx *c,
                                          const struct wl_report_section *s, struct wl_error *err);
enum wl_status wl_report_render_gauges(struct wl_report_ctx *c, const struct wl_report_section *s,
                                       struct wl_error *err);
enum wl_status wl_report_render_loads(struct wl_report_ctx *c, const struct wl_report_section *s,
                                      struct wl_error *err);
enum wl_status wl_report_render_peaks(struct wl_report_ctx *c, const struct wl_report_section *s,
                                      struct wl_error *err);
enum wl_status wl_report_render_design(struct wl_report_ctx *c, const struct wl_report_section *s,
                                       struct wl_error *err);
enum wl_status wl_report_render_convergence(struct wl_report_ctx *c,
                                            const struct wl_report_section *s,
                                            struct wl_error *err);
enum wl_status wl_report_render_metadata(struct wl_report_ctx *c, const struct wl_report_section *s,
                                         struct wl_error *err);

/* The shipped report_templates/design.yaml, built in, for when no template
 * file is found (tests check that it equals the file). */
extern const char wl_report_builtin_design[];

/* The template of results r when the caller names none: the scenario's
 * report.template (default "design") as a file: a path (as given, beside
 * the scenario file, beside results.h5), or a name looked up as
 * NAME.yaml in $WALLLOAD_TEMPLATE_DIR, ./report_templates, and
 * report_templates beside or above the executable; "design" falls back to
 * the built-in copy. `source` gets where it came from. Returns what
 * wl_report_template_load / _parse return, or WL_EINPUT for a name with no
 * file. */
enum wl_status wl_report_template_resolve(const struct wl_results *r,
                                          struct wl_report_template *t, char *source, size_t size,
                                          struct wl_error *err);

/* ---- leading-wave measurement (sections_design.c; tested) ---------------------- */

/* The leading wave of an elevation record eta(t) (n samples): the crest is
 * the first local maximum at or above half the record's highest elevation;
 * the trough the lowest eta after it until eta next rises through zero (or
 * the record ends). Height = crest - trough (trough clamped to <= 0);
 * period = twice the time eta stays above 10 % of the crest around it
 * (WL_LOADS_THRESHOLD; for a sech^2 solitary wave the same measure gives
 * 4 acosh(sqrt 10) / (K c)). Returns 1 and fills the outputs, or 0 when the
 * record holds no crest above zero (*height, *period NAN); *period is NAN
 * when the crest does not fall back below the threshold within the record. */
int wl_report_leading_wave(const double *t, const double *eta, size_t n, double *height,
                           double *period, double *t_crest);

struct wl_design_scenario;
/* The design formulae's inputs for case ci of r (the wall as simulated,
 * the wave that reached it; sections_design.c says from where), with one
 * line each on where H and T came from. 0 when the case has no wall
 * geometry or record (ds then unset). */
int wl_report_design_inputs(const struct wl_results *r, int ci,
                            struct wl_design_scenario *ds, char *h_src, char *t_src,
                            size_t src_size);

#endif
