/* error.c: the one place every wallload error passes through (set a
 * breakpoint on wl_error_set to catch any of them). */
#include "wallload/error.h"

#include <ctype.h>
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

int wl_error_edit_distance(const char *a, const char *b) {
  const size_t la = strlen(a), lb = strlen(b);
  if (la > 63 || lb > 63) return 99;
  int d[64][64];
  for (size_t i = 0; i <= la; i++) d[i][0] = (int)i;
  for (size_t j = 0; j <= lb; j++) d[0][j] = (int)j;
  for (size_t i = 1; i <= la; i++)
    for (size_t j = 1; j <= lb; j++) {
      const int cost = tolower((unsigned char)a[i - 1]) != tolower((unsigned char)b[j - 1]);
      int m = d[i - 1][j] + 1;
      if (d[i][j - 1] + 1 < m) m = d[i][j - 1] + 1;
      if (d[i - 1][j - 1] + cost < m) m = d[i - 1][j - 1] + cost;
      d[i][j] = m;
    }
  return d[la][lb];
}

int wl_error_close_enough(int d, const char *name) { return d <= 2 || d * 3 <= (int)strlen(name); }
