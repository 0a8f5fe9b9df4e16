/* plot.c: the sweep's envelope PDF (stub while the report side is written). */
#include "sweep_private.h"

enum wl_status sweep_write_pdf(const struct wl_sweep *sw, const char *dir, struct wl_error *err) {
  (void)sw, (void)dir, (void)err;
  return WL_OK;
}
