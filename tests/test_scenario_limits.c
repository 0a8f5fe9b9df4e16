/* test_scenario_limits.c: the scenario reader's limits (issue 18): YAML
 * nested deeper than WL_SCENARIO_MAX_DEPTH collections and documents of
 * more than WL_SCENARIO_MAX_BYTES are refused as bad input, at their line
 * and column, before libyaml builds the document (whose cost grows with
 * the square of the flow nesting: 7 s for 50000 '[' in Release before the
 * limit). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "testutil.h"
#include "wallload/scenario.h"
#include "wallload/yaml_limits.h"

static double now_s(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Parse text; the status, the message in err. */
static enum wl_status parse(const char *text, size_t len, struct wl_error *err) {
  struct wl_scenario s;
  wl_scenario_init(&s);
  wl_error_clear(err);
  enum wl_status st = wl_scenario_parse("t.yaml", text, len, &s, err);
  wl_scenario_clear(&s);
  printf("  -> %s\n", st == WL_OK ? "valid" : err->msg);
  return st;
}

static int starts(const char *msg, const char *prefix) {
  return strncmp(msg, prefix, strlen(prefix)) == 0;
}

/* n times `unit`, then `tail`, in a new string. */
static char *repeat(const char *head, const char *unit, int n, const char *tail) {
  size_t a = strlen(head), u = strlen(unit), b = strlen(tail);
  char *t = malloc(a + u * (size_t)n + b + 1);
  if (!t) exit(1);
  memcpy(t, head, a);
  for (int i = 0; i < n; i++) memcpy(t + a + u * (size_t)i, unit, u);
  memcpy(t + a + u * (size_t)n, tail, b + 1);
  return t;
}

static const char *const minimal = "scenario: minimal\n"
                                   "water: { depth: 0.5 m }\n"
                                   "domain: { length: 20 m }\n"
                                   "wall: { x: 15 m, height: 1 m }\n"
                                   "loads:\n"
                                   "  solitary: { height: 0.1 m }\n";

int main(void) {
  struct wl_error err;
  char *t;

  /* 64 levels of flow sequences are read (and refused by the schema: the
   * top is not a mapping); the 65th '[' is refused by the limit, at it. */
  t = repeat("", "[", WL_SCENARIO_MAX_DEPTH, "");
  char *closed = repeat(t, "]", WL_SCENARIO_MAX_DEPTH, "\n");
  CHECK_TRUE(parse(closed, strlen(closed), &err) == WL_EINPUT &&
                 starts(err.msg, "t.yaml:1:1: scenario: found a list"),
             "64 levels are within the limit");
  free(closed);
  free(t);
  t = repeat("", "[", WL_SCENARIO_MAX_DEPTH + 1, "");
  CHECK_TRUE(parse(t, strlen(t), &err) == WL_EINPUT &&
                 starts(err.msg, "t.yaml:1:65: YAML nested deeper than 64 levels; a scenario "
                                 "needs at most 3"),
             "65 levels of '[': refused at the 65th");
  CHECK_TRUE(wl_error_exit_code(WL_EINPUT) == 2, "bad input exits 2");
  free(t);

  /* Flow mappings under a real key, on the second line. */
  t = repeat("scenario: x\nwater: ", "{a: ", 70, "1");
  CHECK_TRUE(parse(t, strlen(t), &err) == WL_EINPUT &&
                 starts(err.msg, "t.yaml:2:260: YAML nested deeper than 64 levels"),
             "flow mappings under water: refused at the 65th level (the root is the 1st)");
  free(t);

  /* Block sequences, compact on one line ("- - - x"): the same limit. */
  t = repeat("", "- ", 100, "x\n");
  CHECK_TRUE(parse(t, strlen(t), &err) == WL_EINPUT &&
                 starts(err.msg, "t.yaml:1:129: YAML nested deeper than 64 levels"),
             "65 levels of block sequences: refused at the 65th '-'");
  free(t);

  /* A second document is read too (the loader reads it to refuse it). */
  t = repeat("scenario: x\n---\n", "[", 1000, "");
  CHECK_TRUE(parse(t, strlen(t), &err) == WL_EINPUT &&
                 starts(err.msg, "t.yaml:3:65: YAML nested deeper than 64 levels"),
             "deep nesting in a second document: refused");
  free(t);

  /* Quoted scalars and comments hold no nesting. */
  t = repeat("scenario: minimal\ndescription: '", "[", 100, "'  # [[[[\n");
  char *full = malloc(strlen(t) + strlen(minimal) + 1);
  snprintf(full, strlen(t) + strlen(minimal) + 1, "%s%s", t, minimal + strlen("scenario: minimal\n"));
  CHECK_TRUE(parse(full, strlen(full), &err) == WL_OK, "brackets inside a quoted scalar or a comment");
  free(full);
  free(t);

  /* Malformed YAML is the loader's to report, with its own position. */
  CHECK_TRUE(parse("a: [1, 2\nb: 3\n", 14, &err) == WL_EINPUT &&
                 starts(err.msg, "t.yaml:") && strstr(err.msg, "malformed YAML") != NULL,
             "malformed YAML: reported by the loader, not the depth check");

  /* The cost stays linear: 200000 '[' (20 min in Release before the
   * limit, by the square of 50000's 7 s) are refused at once. */
  t = repeat("", "[", 200000, "");
  double t0 = now_s();
  enum wl_status st = parse(t, strlen(t), &err);
  double dt = now_s() - t0;
  printf("  200000 '[': %.3f s\n", dt);
  CHECK_TRUE(st == WL_EINPUT && starts(err.msg, "t.yaml:1:65: YAML nested deeper"),
             "200000 levels: refused at the 65th");
  CHECK_TRUE(dt < 2.0, "200000 levels: refused in well under 2 s (linear cost)");
  free(t);

  /* wl_yaml_check_limits itself, without a hint, on smaller limits. */
  wl_error_clear(&err);
  CHECK_TRUE(wl_yaml_check_limits("u.yaml", "[[[x]]]", 7, 3, 1, NULL, &err) == WL_OK,
             "3 levels within a limit of 3");
  CHECK_TRUE(wl_yaml_check_limits("u.yaml", "[[[[x]]]]", 9, 3, 1, NULL, &err) == WL_EINPUT &&
                 !strcmp(err.msg, "u.yaml:1:4: YAML nested deeper than 3 levels"),
             "4 levels: refused, no hint");
  wl_error_clear(&err);
  const char *two = "[&a x, &b y, *a]\n---\n[&a x, *a]\n", *three = "a: [&a x, &b y,\n  &c [z]]";
  CHECK_TRUE(wl_yaml_check_limits("u.yaml", two, strlen(two), 3, 2, NULL, &err) == WL_OK,
             "2 anchors a document within a limit of 2");
  CHECK_TRUE(wl_yaml_check_limits("u.yaml", three, strlen(three), 3, 2, NULL, &err) ==
                     WL_EINPUT &&
                 starts(err.msg, "u.yaml:2:3: YAML with more than 2 anchors (&name) in one "
                                 "document"),
             "3 anchors: refused at the third");

  /* Anchors: libyaml's loader compares each with all before it (95000 in
   * 0.9 MiB took 22 s in Release). */
  char *anchors = malloc(20 * 300 + 100);
  size_t at = (size_t)snprintf(anchors, 100, "scenario: x\ndescription: [");
  for (int i = 0; i < 300; i++) at += (size_t)sprintf(anchors + at, "&a%d x, ", i);
  snprintf(anchors + at, 10, "y]\n");
  CHECK_TRUE(parse(anchors, strlen(anchors), &err) == WL_EINPUT &&
                 starts(err.msg, "t.yaml:2:") &&
                 strstr(err.msg, ": YAML with more than 256 anchors (&name) in one document") != NULL,
             "300 anchors: refused at the 257th");
  free(anchors);

  /* Size: exactly WL_SCENARIO_MAX_BYTES is read; one byte more is refused
   * at the line and column of that byte. The filler is comment lines. */
  size_t big = (size_t)WL_SCENARIO_MAX_BYTES + 1;
  t = malloc(big + 1);
  size_t m = strlen(minimal);
  memcpy(t, minimal, m);
  for (size_t i = m; i < big; i++) t[i] = (i - m) % 4 == 0 ? '#' : (i - m) % 4 == 3 ? '\n' : ' ';
  t[big] = '\0';
  /* the minimal scenario has 6 lines; the filler "#  \n" ones after it */
  int line = 7 + (int)((WL_SCENARIO_MAX_BYTES - m) / 4);
  int col = 1 + (int)((WL_SCENARIO_MAX_BYTES - m) % 4);
  char want[160];
  snprintf(want, sizeof want, "t.yaml:%d:%d: YAML document larger than 1 MiB", line, col);
  CHECK_TRUE(parse(t, WL_SCENARIO_MAX_BYTES, &err) == WL_OK, "exactly 1 MiB: read");
  CHECK_TRUE(parse(t, big, &err) == WL_EINPUT && starts(err.msg, want),
             "1 MiB and a byte: refused at that byte");

  /* The same from a file (read no further than the limit and a byte). */
  char path[] = "/tmp/wl_limits_XXXXXX";
  int fd = mkstemp(path);
  CHECK_TRUE(fd >= 0, "a temporary file");
  if (fd >= 0) {
    FILE *f = fdopen(fd, "wb");
    fwrite(t, 1, big, f);
    fwrite(t, 1, big, f); /* 2 MiB and more */
    fclose(f);
    struct wl_scenario s;
    wl_scenario_init(&s);
    wl_error_clear(&err);
    st = wl_scenario_load(path, &s, &err);
    printf("  -> %s\n", err.msg);
    char wantf[600];
    snprintf(wantf, sizeof wantf, "%s:%d:%d: YAML document larger than 1 MiB", path, line, col);
    CHECK_TRUE(st == WL_EINPUT && starts(err.msg, wantf), "a file of 2 MiB: refused at 1 MiB + 1");
    wl_scenario_clear(&s);
    unlink(path);
  }
  free(t);

  /* A device that never ends: read to the limit, refused. */
  if (access("/dev/zero", R_OK) == 0) {
    struct wl_scenario s;
    wl_scenario_init(&s);
    wl_error_clear(&err);
    st = wl_scenario_load("/dev/zero", &s, &err);
    printf("  -> %s\n", err.msg);
    CHECK_TRUE(st == WL_EINPUT &&
                   starts(err.msg, "/dev/zero:1:1048577: YAML document larger than 1 MiB"),
               "/dev/zero: refused after 1 MiB");
    wl_scenario_clear(&s);
  }
  return TEST_RESULT();
}
