/* report.c: `wallload report RESULTS.h5 [-o FILE.pdf] [--template FILE]`:
 * re-render the design report from stored results alone. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "wallload/error.h"
#include "wallload/report.h"

#define REPORT_USAGE "usage: wallload report RESULTS.h5 [-o FILE.pdf] [--template FILE]"

/* Default output: report.pdf beside the results file. */
static void default_pdf(const char *results, char *out, size_t size) {
  const char *slash = strrchr(results, '/');
  if (slash)
    snprintf(out, size, "%.*s/report.pdf", (int)(slash - results), results);
  else
    snprintf(out, size, "report.pdf");
}

enum wl_status wl_cli_report(int argc, char **argv, struct wl_error *err) {
  const char *results = NULL, *pdf = NULL, *tpl = NULL;
  for (int i = 1; i < argc; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
      printf("%s\n\n"
             "Re-render the design report from RESULTS.h5 (and the particle snapshots beside it).\n"
             "  -o FILE.pdf        output (default: report.pdf beside RESULTS.h5)\n"
             "  --template FILE    report template (default: the scenario's report.template,\n"
             "                     or the design template shipped with wallload)\n",
             REPORT_USAGE);
      return WL_OK;
    } else if (!strcmp(a, "-o") || !strcmp(a, "--output")) {
      if (i + 1 >= argc)
        return wl_error_set(err, WL_EUSAGE, "%s needs a file; %s", a, REPORT_USAGE);
      pdf = argv[++i];
    } else if (!strcmp(a, "--template") || !strcmp(a, "-t")) {
      if (i + 1 >= argc)
        return wl_error_set(err, WL_EUSAGE, "%s needs a file; %s", a, REPORT_USAGE);
      tpl = argv[++i];
    } else if (a[0] == '-' && a[1]) {
      return wl_error_set(err, WL_EUSAGE, "report: unknown option '%s'; %s", a, REPORT_USAGE);
    } else if (!results) {
      results = a;
    } else {
      return wl_error_set(err, WL_EUSAGE, "report: found a second results file '%s'; %s", a,
                          REPORT_USAGE);
    }
  }
  if (!results)
    return wl_error_set(err, WL_EUSAGE, "report: no results file; %s", REPORT_USAGE);
  char out[1100];
  if (!pdf) {
    default_pdf(results, out, sizeof out);
    pdf = out;
  }
  enum wl_status st = wl_report_render(results, tpl, pdf, err);
  if (st == WL_OK)
    printf("report written to %s\n", pdf);
  return st;
}
