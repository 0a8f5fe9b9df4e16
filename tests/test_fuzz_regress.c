/* test_fuzz_regress.c: replay every input of tests/fuzz/regress/ (the fuzz
 * target's findings and the reader limits' edge cases) through the
 * parse-validate-plan path of `wallload check`, as the fuzz target drives
 * it (tests/fuzz/fuzz_drive.h), in every build: the sanitizer build of
 * scripts/test.sh then checks them for memory errors, leaks and undefined
 * behaviour without clang or libFuzzer. Each must finish with a clean
 * status: valid, or refused as bad input with a message naming the file.
 *
 *   test_fuzz_regress [FILE...]   replay these files instead */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fuzz/fuzz_drive.h"
#include "testutil.h"

#define REGRESS_DIR WL_SOURCE_DIR "/tests/fuzz/regress"

static int by_name(const void *a, const void *b) {
  return strcmp(*(char *const *)a, *(char *const *)b);
}

static void replay(const char *file, FILE *sink) {
  FILE *f = fopen(file, "rb");
  char *buf = NULL;
  size_t len = 0;
  if (f) {
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (buf) len = fread(buf, 1, (size_t)n, f);
    fclose(f);
  }
  CHECK_TRUE(buf != NULL, file);
  if (!buf) return;
  /* the name the messages must carry: the file's own */
  const char *name = strrchr(file, '/') ? strrchr(file, '/') + 1 : file;
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  struct wl_fuzz_result r = wl_fuzz_drive(name, buf, len, sink);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  double ms = 1e3 * (double)(t1.tv_sec - t0.tv_sec) + 1e-6 * (double)(t1.tv_nsec - t0.tv_nsec);
  printf("%s: %s (%zu bytes, %.1f ms)%s%s\n", name,
         r.status == WL_OK ? "valid" : r.msg, len, ms, r.violation[0] ? "\n  VIOLATION: " : "",
         r.violation);
  CHECK_TRUE(r.violation[0] == '\0', name);
  free(buf);
}

int main(int argc, char **argv) {
  FILE *sink = fopen("/dev/null", "w");
  if (!sink) return 77;
  if (argc > 1) {
    for (int i = 1; i < argc; i++) replay(argv[i], sink);
    fclose(sink);
    return TEST_RESULT();
  }
  DIR *d = opendir(REGRESS_DIR);
  CHECK_TRUE(d != NULL, REGRESS_DIR);
  if (!d) return TEST_RESULT();
  char **names = NULL;
  size_t n = 0;
  struct dirent *e;
  while ((e = readdir(d))) {
    if (e->d_name[0] == '.') continue;
    char **more = realloc(names, (n + 1) * sizeof *names);
    if (!more) break;
    names = more;
    size_t size = strlen(REGRESS_DIR) + strlen(e->d_name) + 2;
    names[n] = malloc(size);
    if (!names[n]) break;
    snprintf(names[n], size, "%s/%s", REGRESS_DIR, e->d_name);
    n++;
  }
  closedir(d);
  qsort(names, n, sizeof *names, by_name);
  CHECK_TRUE(n > 0, "tests/fuzz/regress/ holds the regression inputs");
  for (size_t i = 0; i < n; i++) {
    replay(names[i], sink);
    free(names[i]);
  }
  free(names);
  fclose(sink);
  return TEST_RESULT();
}
