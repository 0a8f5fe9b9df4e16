/* error.h: status codes and the caller-owned error object every fallible
 * function fills (GSL's single error function, SQLite's caller-owned text).
 *
 * A fallible function returns enum wl_status and takes `struct wl_error *err`
 * last. The first error set wins, so the innermost (most precise) message
 * survives; callers add context with wl_error_prefix. Library code never
 * prints; only the CLI's main() prints err->msg and picks the exit code. */
#ifndef WALLLOAD_ERROR_H
#define WALLLOAD_ERROR_H

#include <stddef.h>

enum wl_status {
  WL_OK = 0,
  WL_EINPUT,       /* bad input: scenario, option, out-of-range value (exit 2) */
  WL_EUSAGE,       /* bad command line (exit 2) */
  WL_EIO,          /* file could not be read or written (exit 1) */
  WL_ENOMEM,       /* allocation failed (exit 1) */
  WL_ENUMERIC,     /* a numerical method failed to converge (exit 1) */
  WL_EUNSTABLE,    /* the simulation went unstable; results so far kept (exit 1) */
  WL_EINTERRUPTED, /* the user interrupted a run; results so far kept (exit 1) */
  WL_EUNSUPPORTED, /* asked for something this build or stage does not have (exit 1) */
};

enum { WL_ERROR_MSG_MAX = 2048 };

struct wl_error {
  enum wl_status status;      /* WL_OK until the first error */
  char msg[WL_ERROR_MSG_MAX]; /* human-readable, no trailing newline */
};

/* Reset err to "no error". err may be NULL. */
void wl_error_clear(struct wl_error *err);

/* Record an error unless one is already recorded (first error wins).
 * Returns `status`, so callers can write `return wl_error_set(err, ...)`.
 * err may be NULL (the status is still returned). */
enum wl_status wl_error_set(struct wl_error *err, enum wl_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Put context in front of an already recorded message ("while reading X: ..."). */
void wl_error_prefix(struct wl_error *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Process exit code for a status: 0 ok, 2 bad input or usage, 1 otherwise. */
int wl_error_exit_code(enum wl_status status);

/* Short name of a status ("bad input", "unstable", ...). */
const char *wl_error_status_name(enum wl_status status);

/* "Did you mean" support for input errors. Levenshtein distance between
 * two names, ignoring case; names of 64 characters or more count as 99
 * (never suggested). */
int wl_error_edit_distance(const char *a, const char *b);

/* 1 when a name at edit distance d from what the user wrote is close enough
 * to suggest: at most 2 edits, or at most a third of the name. */
int wl_error_close_enough(int d, const char *name);

#endif
