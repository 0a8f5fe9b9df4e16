/* sections_builtin.c: where the report's template comes from. A template
 * named in the call or in the scenario's report.template is looked up as a
 * file; the shipped design template is also built in, so `wallload report`
 * works wherever the binary is (tests/test_report_render.c checks that this
 * copy equals report_templates/design.yaml byte for byte). After editing
 * design.yaml, regenerate the string below with
 *   sed 's/\\/\\\\/g; s/"/\\"/g; s/^/    "/; s/$/\\n"/' report_templates/design.yaml */
#define _POSIX_C_SOURCE 200809L /* readlink */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sections.h"
#include "wallload/config.h"

/* report_templates/design.yaml, verbatim. */
const char wl_report_builtin_design[] =
    "# design.yaml: the layout of wallload's design report.\n"
    "#\n"
    "# This file is data, not code: copy it, then reorder, drop or retitle the\n"
    "# sections, and point your scenario at the copy:\n"
    "#\n"
    "#     report: { template: my-report.yaml }\n"
    "#\n"
    "# Top-level keys: company, title, subtitle, title_block, sections.\n"
    "# Every section has a `type` (title, scene, snapshots, gauges, loads, peaks,\n"
    "# design_formulae, convergence, metadata) and may have:\n"
    "#   title:      the heading (leave it out for the default; \"\" for none)\n"
    "#   text:       a paragraph printed under the heading\n"
    "#   page_break: true to start the section on a new page\n"
    "# Options by type:\n"
    "#   scene:           exaggeration (vertical / horizontal scale, 1 to 100),\n"
    "#                    x_range ([from, to] with units; default: the whole flume)\n"
    "#   snapshots:       times (auto, or a list such as [2.0 s, 2.4 s, 2.8 s]),\n"
    "#                    field (pressure, velocity, density), x_range\n"
    "#   gauges:          gauges (all, or a list of names such as [G1, G2])\n"
    "#   loads:           quantities (force, impulse, moment, pressure, runup)\n"
    "#   peaks:           digits (significant digits, 2 to 6)\n"
    "#   design_formulae: formulae (hydrostatic, goda-takahashi, cross, fema-p646), digits\n"
    "#   convergence:     digits\n"
    "#   metadata:        scenario_text (true: list the scenario file)\n"
    "# An unknown type or key is an error naming the line, so typos cannot hide.\n"
    "\n"
    "company: \"\"\n"
    "title: \"Wave loads on a seawall\"\n"
    "subtitle: \"SPH assessment: underwater explosion and equal-energy solitary wave\"\n"
    "\n"
    "title_block:\n"
    "  project: \"\"\n"
    "  client: \"\"\n"
    "  reference: \"\"\n"
    "  revision: \"A\"\n"
    "  prepared_by: \"\"\n"
    "  checked_by: \"\"\n"
    "  date: auto\n"
    "\n"
    "sections:\n"
    "  - type: title\n"
    "    text: >-\n"
    "      This report gives the horizontal force, impulse and overturning moment\n"
    "      that the waves of each load case put on the wall, computed with\n"
    "      weakly-compressible SPH, together with the numerical error of each\n"
    "      value and the runtime it took. Values are per metre of wall unless\n"
    "      stated otherwise.\n"
    "\n"
    "  - type: scene\n"
    "    title: \"Flume, bathymetry and wall\"\n"
    "    exaggeration: 1\n"
    "\n"
    "  - type: snapshots\n"
    "    title: \"Free surface near the wall\"\n"
    "    times: auto\n"
    "    field: pressure\n"
    "\n"
    "  - type: gauges\n"
    "    title: \"Free-surface elevation at the gauges\"\n"
    "    gauges: all\n"
    "\n"
    "  - type: loads\n"
    "    title: \"Wall loads\"\n"
    "    quantities: [force, impulse, moment]\n"
    "\n"
    "  - type: peaks\n"
    "    title: \"Peak loads\"\n"
    "    digits: 3\n"
    "\n"
    "  - type: design_formulae\n"
    "    title: \"Comparison with design formulae\"\n"
    "    formulae: [hydrostatic, goda-takahashi, cross, fema-p646]\n"
    "\n"
    "  - type: convergence\n"
    "    title: \"Resolution and numerical error\"\n"
    "\n"
    "  - type: metadata\n"
    "    title: \"Run record\"\n"
    "    page_break: true\n"
    "    scenario_text: true\n";

static int readable(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) return 0;
  fclose(f);
  return 1;
}

/* The directory part of path into dir ("." when none). */
static void dir_of(const char *path, char *dir, size_t size) {
  snprintf(dir, size, "%s", path);
  char *slash = strrchr(dir, '/');
  if (slash == dir)
    dir[1] = '\0';
  else if (slash)
    *slash = '\0';
  else
    snprintf(dir, size, ".");
}

static int ends_with(const char *s, const char *tail) {
  size_t a = strlen(s), b = strlen(tail);
  return a >= b && !strcmp(s + a - b, tail);
}

enum wl_status wl_report_template_find(const char *name, const char *scenario_file,
                                       const char *results_dir, struct wl_report_template *t,
                                       char *source, size_t size, struct wl_error *err) {
  if (!name || !name[0]) name = "design";
  char cand[8][1100];
  int n = 0;
  if (strchr(name, '/') || ends_with(name, ".yaml") || ends_with(name, ".yml")) {
    char dir[1024];
    snprintf(cand[n++], sizeof cand[0], "%s", name);
    if (name[0] != '/') {
      if (scenario_file && scenario_file[0]) {
        dir_of(scenario_file, dir, sizeof dir);
        snprintf(cand[n++], sizeof cand[0], "%s/%s", dir, name);
      }
      if (results_dir && results_dir[0]) snprintf(cand[n++], sizeof cand[0], "%s/%s", results_dir, name);
    }
  } else {
    const char *env = getenv("WALLLOAD_TEMPLATE_DIR");
    if (env && *env) snprintf(cand[n++], sizeof cand[0], "%s/%s.yaml", env, name);
    snprintf(cand[n++], sizeof cand[0], "report_templates/%s.yaml", name);
    char exe[1024];
    ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len > 0) {
      exe[len] = '\0';
      char dir[1024];
      dir_of(exe, dir, sizeof dir);
      snprintf(cand[n++], sizeof cand[0], "%s/report_templates/%s.yaml", dir, name);
      snprintf(cand[n++], sizeof cand[0], "%s/../report_templates/%s.yaml", dir, name);
      snprintf(cand[n++], sizeof cand[0], "%s/../share/wallload/report_templates/%s.yaml", dir,
               name);
    }
  }
  for (int i = 0; i < n; i++) {
    if (!readable(cand[i])) continue;
    snprintf(source, size, "%s", cand[i]);
    return wl_report_template_load(cand[i], t, err);
  }
  if (!strcmp(name, "design")) {
    snprintf(source, size, "design (built in; report_templates/design.yaml of wallload %s)",
             WL_VERSION);
    return wl_report_template_parse("design.yaml (built in)", wl_report_builtin_design,
                                    strlen(wl_report_builtin_design), t, err);
  }
  return wl_error_set(err, WL_EINPUT,
                      "%s: report.template: found '%s', but no such template file (looked in "
                      "%d places, first %s); valid: a template file, or 'design'",
                      scenario_file && scenario_file[0] ? scenario_file : "results", name, n,
                      cand[0]);
}

enum wl_status wl_report_template_resolve(const struct wl_results *r,
                                          struct wl_report_template *t, char *source,
                                          size_t size, struct wl_error *err) {
  const char *name = r->report_template[0] ? r->report_template : "design";
  return wl_report_template_find(name, r->scenario_file[0] ? r->scenario_file : r->path, r->dir,
                                 t, source, size, err);
}
