/* error.c: the one place every wallload error passes through (set a
 * breakpoint on wl_error_set to catch any of them). */
#include "wallload/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void wl_error_clear(struct wl_error *err) {
  if (!err) return;
  err->status = WL_OK;
  err->msg[0] = '\0';
}

enum wl_status wl_error_set(struct wl_error *err, enum wl_status status, const char *fmt, ...) {
  if (!err || err->status != WL_OK) return status;
  err->status = status;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(err->msg, sizeof err->msg, fmt, ap);
  va_end(ap);
  return status;
}

void wl_error_prefix(struct wl_error *err, const char *fmt, ...) {
  if (!err || err->status == WL_OK) return;
  char head[WL_ERROR_MSG_MAX];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(head, sizeof head, fmt, ap);
  va_end(ap);
  char joined[WL_ERROR_MSG_MAX];
  snprintf(joined, sizeof joined, "%s%s", head, err->msg);
  memcpy(err->msg, joined, sizeof err->msg);
}

int wl_error_exit_code(enum wl_status status) {
  switch (status) {
  case WL_OK: return 0;
  case WL_EINPUT:
  case WL_EUSAGE: return 2;
  default: return 1;
  }
}

const char *wl_error_status_name(enum wl_status status) {
  switch (status) {
  case WL_OK: return "ok";
  case WL_EINPUT: return "bad input";
  case WL_EUSAGE: return "usage";
  case WL_EIO: return "i/o error";
  case WL_ENOMEM: return "out of memory";
  case WL_ENUMERIC: return "numerical failure";
  case WL_EUNSTABLE: return "unstable";
  case WL_EINTERRUPTED: return "interrupted";
  case WL_EUNSUPPORTED: return "unsupported";
  }
  return "unknown";
}
