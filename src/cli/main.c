#include <stdio.h>
#include "wallload/scenario.h"
int main(int argc, char **argv) {
  struct wl_scenario s; struct wl_error err; wl_error_clear(&err); wl_scenario_init(&s);
  if (argc < 2) return 2;
  if (wl_scenario_load(argv[1], &s, &err)) { fprintf(stderr, "wallload: %s\n", err.msg); wl_scenario_clear(&s); return wl_error_exit_code(err.status); }
  wl_scenario_write_resolved(&s, stdout); wl_scenario_clear(&s); return 0;
}
