/* schema.h: the scenario schema table (private to the scenario module). */
#ifndef WALLLOAD_SCENARIO_SCHEMA_H
#define WALLLOAD_SCENARIO_SCHEMA_H

#include <stddef.h>

#include "wallload/scenario.h"

enum wl_key_type {
  KT_QTY,         /* number with unit of `dim` */
  KT_QTY_OR_AUTO, /* same, or the word auto */
  KT_QTY_OR_SAME, /* same, or the word same-as-solitary */
  KT_INT,         /* integer */
  KT_INT_OR_AUTO, /* integer or auto */
  KT_STR,         /* text */
  KT_ENUM,        /* one of `choices` */
  KT_MAP,         /* a mapping with keys `sub` */
  KT_BED,         /* the bathymetry list */
  KT_GAUGES,      /* the gauges list */
  KT_LEVELS,      /* the convergence list of numbers */
  KT_SWEEP,       /* the sweep section: a mapping of parameters, each a list or a range */
};

struct wl_key {
  const char *name;
  enum wl_key_type type;
  enum wl_dim dim;
  size_t off;                  /* offset of the wl_scenario_value in its struct */
  const char *const *choices;  /* KT_ENUM: NULL-terminated */
  double lo, hi;               /* SI range; NAN: unbounded */
  int lo_open, hi_open;        /* 1: the bound is excluded */
  const char *def;             /* default text; NULL: no default */
  const struct wl_key *sub;    /* KT_MAP and lists: keys of the items */
  size_t present_off;          /* KT_MAP: offset of an int set when the map is given */
  int required;                /* missing is an error (when the parent is present) */
  const char *help;            /* what the key means, for messages and check */
};

/* A sweep parameter's range, {from, to, count, spacing} (scenario.c turns
 * it into values; from and to take the parameter's dimension and limits). */
struct wl_sweep_range {
  struct wl_scenario_value from, to, count, spacing;
};
enum wl_sweep_spacing { WL_SWEEP_LINEAR, WL_SWEEP_LOG };

extern const struct wl_key wl_schema_top[];
/* The sweep's parameters; `off` is the parameter (enum wl_sweep_param). */
extern const struct wl_key wl_schema_sweep_keys[];
/* A range's keys; offsets into struct wl_sweep_range. */
extern const struct wl_key wl_schema_sweep_range_keys[];
extern const struct wl_key wl_schema_bed_keys[];
extern const struct wl_key wl_schema_gauge_keys[];

#endif
