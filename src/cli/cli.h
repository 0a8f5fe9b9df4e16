/* cli.h: the subcommands (each parses its own arguments; argv[0] is the
 * command name). They print results to stdout and return a status; main()
 * prints the error. */
#ifndef WALLLOAD_CLI_H
#define WALLLOAD_CLI_H

#include "wallload/error.h"

enum wl_status wl_cli_check(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_convert(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_assess(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_report(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_validate(int argc, char **argv, struct wl_error *err);
enum wl_status wl_cli_bench(int argc, char **argv, struct wl_error *err);

#endif
