/* internal.h: what the waves module's files share and nobody else uses. */
#ifndef WALLLOAD_WAVES_INTERNAL_H
#define WALLLOAD_WAVES_INTERNAL_H

#include "wallload/waves.h"

/* Solve the exact wave of sw->eps (exact.c) and fill sw->exact and the
 * tabulated field (waves.h). Returns WL_OK, WL_ENOMEM or WL_ENUMERIC. */
enum wl_status wl_waves__exact_tabulate(struct wl_solitary *sw, struct wl_error *err);

#endif
