/* report.h: the design report's template (which sections, in which order,
 * with which titles and options) as typed, validated values.
 *
 * A template is a YAML file in report_templates/ (design.yaml ships with
 * wallload). A user copies it, reorders, drops or retitles sections and
 * points a scenario's `report.template` at the copy. Parsing follows the
 * scenario parser: an unknown section type, an unknown key, a wrong type or
 * an out-of-range option is an error "file:line:col: key: found X; valid:
 * a, b, c"; malformed YAML reports libyaml's line and column.
 *
 * The page, plot and table toolkit that renders sections is private to the
 * report module (src/report/draw.h); only the template is public here. */
#ifndef WALLLOAD_REPORT_H
#define WALLLOAD_REPORT_H

#include <stddef.h>

#include "wallload/error.h"

enum {
  WL_REPORT_MAX_SECTIONS = 32, /* sections in one template */
  WL_REPORT_MAX_TIMES = 12,    /* snapshot times in one section */
  WL_REPORT_MAX_NAMES = 32,    /* gauge names in one section */
  WL_REPORT_NAME_MAX = 32,     /* bytes of a gauge name, with the NUL */
  WL_REPORT_LINE_MAX = 256,    /* bytes of a one-line text (titles, title block), with the NUL */
  WL_REPORT_TEXT_MAX = 2048,   /* bytes of a paragraph (section `text`), with the NUL */
};

/* What a section shows; the order matches wl_report_section_type_name. */
enum wl_report_section_type {
  WL_REPORT_SECTION_TITLE,           /* title page: title, subtitle, title block */
  WL_REPORT_SECTION_SCENE,           /* flume, bathymetry, wall, gauges to scale */
  WL_REPORT_SECTION_SNAPSHOTS,       /* particle snapshots near the wall */
  WL_REPORT_SECTION_GAUGES,          /* free-surface elevation at the gauges */
  WL_REPORT_SECTION_LOADS,           /* force, impulse, moment, pressure histories */
  WL_REPORT_SECTION_PEAKS,           /* table of peak values per load case */
  WL_REPORT_SECTION_DESIGN_FORMULAE, /* comparison with design-code formulae */
  WL_REPORT_SECTION_CONVERGENCE,     /* resolution ladder: error against runtime */
  WL_REPORT_SECTION_METADATA,        /* version, backend, hardware, runtime, scenario */
  WL_REPORT_SECTION_COUNT
};

/* snapshots: which particle field colours the snapshot. */
enum wl_report_field_quantity {
  WL_REPORT_FIELD_PRESSURE, /* [Pa] */
  WL_REPORT_FIELD_VELOCITY, /* speed [m/s] */
  WL_REPORT_FIELD_DENSITY,  /* [kg/m^3] */
};

/* loads: histories to plot (bit set). */
enum wl_report_load_bits {
  WL_REPORT_LOAD_FORCE = 1 << 0,    /* horizontal force per width */
  WL_REPORT_LOAD_IMPULSE = 1 << 1,  /* impulse per width */
  WL_REPORT_LOAD_MOMENT = 1 << 2,   /* overturning moment per width */
  WL_REPORT_LOAD_PRESSURE = 1 << 3, /* probe pressures */
  WL_REPORT_LOAD_RUNUP = 1 << 4,    /* run-up on the wall */
};

/* design_formulae: formulae to compare with (bit set). */
enum wl_report_formula_bits {
  WL_REPORT_FORMULA_HYDROSTATIC = 1 << 0,    /* hydrostatic pressure of the crest level */
  WL_REPORT_FORMULA_GODA_TAKAHASHI = 1 << 1, /* Goda (2000) with Takahashi's impulsive term */
  WL_REPORT_FORMULA_CROSS = 1 << 2,          /* Cross (1967) surge force */
  WL_REPORT_FORMULA_FEMA_P646 = 1 << 3,      /* FEMA P-646 / ASCE 7 ch. 6 tsunami loads */
};

/* One section of the report, in template order. Options a section type does
 * not accept keep their defaults (the parser refuses them in the file). */
struct wl_report_section {
  enum wl_report_section_type type;
  int line, col;                  /* 1-based position of the entry in the template */
  char title[WL_REPORT_LINE_MAX]; /* heading; the type's default when not given;
                                     "" (given as "") means no heading */
  char text[WL_REPORT_TEXT_MAX];  /* introductory paragraph; "" for none */
  int page_break;                 /* 1: start the section on a new page (default 0) */

  /* snapshots */
  int n_times;                            /* 0: times chosen by the renderer ("auto") */
  double times[WL_REPORT_MAX_TIMES];      /* snapshot times [s], increasing */
  enum wl_report_field_quantity field;    /* colour quantity (default pressure) */

  /* scene, snapshots */
  int has_x_range;  /* 1: x_range given; 0: the renderer picks the window */
  double x_range[2]; /* horizontal window [m], x_range[0] < x_range[1] */

  /* scene */
  double exaggeration; /* vertical scale / horizontal scale [-]; 1 = true aspect (default) */

  /* gauges */
  int n_gauges;                                       /* 0: every gauge */
  char gauges[WL_REPORT_MAX_NAMES][WL_REPORT_NAME_MAX]; /* gauge names to plot */

  /* loads */
  unsigned loads; /* WL_REPORT_LOAD_* bits (default force, impulse, moment) */

  /* design_formulae */
  unsigned formulae; /* WL_REPORT_FORMULA_* bits (default all) */

  /* peaks, design_formulae, convergence */
  int digits; /* significant digits in tables, 2..6 (default 3) */

  /* metadata */
  int scenario_text; /* 1: list the scenario file (default 1) */
};

/* The title block printed on the title page (all optional, "" when absent). */
struct wl_report_title_block {
  char project[WL_REPORT_LINE_MAX];
  char client[WL_REPORT_LINE_MAX];
  char reference[WL_REPORT_LINE_MAX];
  char revision[WL_REPORT_LINE_MAX];
  char prepared_by[WL_REPORT_LINE_MAX];
  char checked_by[WL_REPORT_LINE_MAX];
  char date[WL_REPORT_LINE_MAX]; /* "auto": the date the report is rendered */
};

struct wl_report_template {
  char path[512];                        /* the file, as given */
  char company[WL_REPORT_LINE_MAX];      /* running footer, PDF author ("" for none) */
  char title[WL_REPORT_LINE_MAX];        /* report title (default "Wave loads on a wall") */
  char subtitle[WL_REPORT_LINE_MAX];     /* under the title ("" for none) */
  struct wl_report_title_block block;
  int n_sections;                        /* 1..WL_REPORT_MAX_SECTIONS once loaded */
  struct wl_report_section *sections;    /* n_sections entries; owned */
};

/* Zero a template (safe to _clear afterwards). */
void wl_report_template_init(struct wl_report_template *t);

/* Free what a template owns and zero it. Safe on a zeroed, half-built or
 * already cleared template; t may be NULL. */
void wl_report_template_clear(struct wl_report_template *t);

/* Parse template text `text` (len bytes, need not be NUL-terminated); `path`
 * names it in messages. Any previous content of *t is cleared first.
 * Returns WL_OK, WL_EINPUT (malformed YAML, unknown key or section type,
 * wrong type, bad value: "path:line:col: key: found ...; valid: ..."), or
 * WL_ENOMEM. On failure *t is left cleared. */
enum wl_status wl_report_template_parse(const char *path, const char *text, size_t len,
                                        struct wl_report_template *t, struct wl_error *err);

/* Read and parse the template file `path`. Returns what
 * wl_report_template_parse returns, or WL_EIO when the file cannot be read.
 * On failure *t is left cleared. */
enum wl_status wl_report_template_load(const char *path, struct wl_report_template *t,
                                       struct wl_error *err);

/* Find and load the report template `name` (a scenario's report.template):
 * a path (with '/' or a .yaml ending) as given, beside the scenario file
 * or in results_dir (either may be NULL); a name as NAME.yaml in
 * $WALLLOAD_TEMPLATE_DIR, ./report_templates, report_templates beside or
 * above the executable; "design" (or NULL/empty) falls back to the built-in
 * copy. source gets where it came from. `check` calls it so that a missing
 * or malformed template is refused before a run, not after it. Returns
 * what wl_report_template_load returns, or WL_EINPUT naming the places
 * looked in. */
enum wl_status wl_report_template_find(const char *name, const char *scenario_file,
                                       const char *results_dir, struct wl_report_template *t,
                                       char *source, size_t size, struct wl_error *err);

/* The YAML name of a section type ("title", "scene", ...); "?" out of range. */
const char *wl_report_section_type_name(enum wl_report_section_type type);

/* The heading a section of `type` gets when its template gives no title. */
const char *wl_report_section_default_title(enum wl_report_section_type type);

/* ---- rendering ------------------------------------------------------------------ */

/* Render the design report of an assessment to the PDF `pdf_path` from
 * `results_h5` alone (the results.h5 of `wallload assess`, with the particle
 * snapshots particles_<case>.h5 read from its directory when there) and a
 * template, read through the store's schema (wl_store_results_read): the
 * bathymetry, the derived initial conditions and the numerical settings
 * come from the /plan and /settings that assess stored (the scenario is not
 * re-planned); peaks are derived by the reader from the stored series with
 * the definitions of loads.h (so they equal summary.json's).
 *
 * template_path: a template file; NULL: the stored report_template (the
 * scenario's report.template, default "design"), looked up as a file (a path as given,
 * beside the scenario file or beside results.h5; a name as NAME.yaml in
 * $WALLLOAD_TEMPLATE_DIR, ./report_templates, report_templates beside or
 * above the executable); "design" falls back to a built-in copy of
 * report_templates/design.yaml.
 *
 * A missing load case, an unstable or short record, missing snapshots or
 * results without /plan (written before it was stored) are said on the
 * pages, not errors. Returns WL_OK; WL_EUSAGE (a NULL or empty path);
 * WL_EINPUT (a bad template, "file:line:col: key: ..."; a results file that
 * is not one, or lacks a key the schema requires: file, group and key);
 * WL_EIO (results or template unreadable, PDF not writable); WL_ENOMEM.
 * The PDF is written as pdf_path.part and renamed when complete; on failure
 * no file is left at pdf_path (an existing one is kept). Nothing prints. */
enum wl_status wl_report_render(const char *results_h5, const char *template_path,
                                const char *pdf_path, struct wl_error *err);

/* ---- the envelopes of a sweep (`wallload sweep`) ------------------------------- */

enum { WL_REPORT_SWEEP_MAX_PARAMS = 5 };

struct wl_report_sweep_param {
  const char *name;    /* "charge", "standoff", ... */
  const char *unit;    /* SI unit of the values ("kg", "m", "J") */
  const double *value; /* n_cases */
};

/* One load case's loads per sweep case (NaN: none). */
struct wl_report_sweep_load {
  int present;
  const double *peak_force, *peak_force_boundary; /* [N/m] */
  const double *impulse_positive;                 /* [N s/m] */
  const double *peak_moment;                      /* [N m/m] */
  const double *max_runup;                        /* [m] */
  const double *uncertainty;                      /* the ladder's, relative; NaN: none */
};

struct wl_report_sweep {
  const char *scenario;            /* name */
  const char *file;                /* the sweep's scenario file */
  int n_cases;
  int n_params;
  struct wl_report_sweep_param params[WL_REPORT_SWEEP_MAX_PARAMS];
  const char *const *case_id;      /* n_cases */
  const char *const *status;       /* n_cases: "complete", "unstable", "failed", ... */
  const char *const *results;      /* n_cases: the case's results.h5, NULL when it has none */
  struct wl_report_sweep_load load[2]; /* solitary, explosion */
};

/* Render the envelopes of a sweep to pdf_path: for each swept parameter,
 * the peak force, positive impulse, peak moment and run-up of every case
 * against it, with each load case's envelope (the largest over the other
 * parameters) and the explosion beside the solitary wave; the design
 * formulae's total forces (the design_formulae section's, evaluated on
 * each case's results.h5) beside the simulated peak force; and where the
 * governing load case changes along each parameter. Cases without results
 * are listed, not drawn. Returns WL_OK, WL_EIO (PDF not writable),
 * WL_ENOMEM; pdf_path is written as pdf_path.part and renamed when
 * complete. Nothing prints. */
enum wl_status wl_report_sweep_render(const struct wl_report_sweep *sw, const char *pdf_path,
                                      struct wl_error *err);

#endif
