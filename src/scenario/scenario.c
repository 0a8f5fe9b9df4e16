/* scenario.c: load a scenario file with libyaml and check it against the
 * schema table (schema.c), then check the rules that span several keys. */
#include "wallload/scenario.h"
#include "wallload/yaml_limits.h"

#include <errno.h>
#include <sys/stat.h>

#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "schema.h"

/* Parsing context: the file name for messages and the YAML document. */
struct ctx {
  const char *path;
  yaml_document_t *doc;
  struct wl_error *err;
};

static struct wl_scenario_value *value_at(void *base, size_t off) {
  return (struct wl_scenario_value *)((char *)base + off);
}

static int line_of(const yaml_node_t *n) { return (int)n->start_mark.line + 1; }
static int col_of(const yaml_node_t *n) { return (int)n->start_mark.column + 1; }

static enum wl_status fail_at(struct ctx *c, const yaml_node_t *n, const char *key,
                              const char *fmt, const char *detail) {
  return wl_error_set(c->err, WL_EINPUT, "%s:%d:%d: %s: %s%s", c->path, line_of(n), col_of(n), key,
                      fmt, detail ? detail : "");
}

static const char *node_kind(const yaml_node_t *n) {
  switch (n->type) {
  case YAML_SCALAR_NODE: return "a value";
  case YAML_SEQUENCE_NODE: return "a list";
  case YAML_MAPPING_NODE: return "a mapping";
  default: return "nothing";
  }
}


static void list_keys(const struct wl_key *keys, char *buf, size_t size) {
  buf[0] = '\0';
  for (const struct wl_key *k = keys; k->name; k++) {
    size_t used = strlen(buf);
    snprintf(buf + used, size - used, "%s%s", k == keys ? "" : ", ", k->name);
  }
}

static void join_path(char *out, size_t size, const char *parent, const char *name) {
  if (parent && *parent)
    snprintf(out, size, "%s.%s", parent, name);
  else
    snprintf(out, size, "%s", name);
}

static void range_text(const struct wl_key *k, char *buf, size_t size) {
  char unit[24] = "";
  if (*wl_units_si_symbol(k->dim)) snprintf(unit, sizeof unit, " %s", wl_units_si_symbol(k->dim));
  if (!isnan(k->lo) && !isnan(k->hi))
    snprintf(buf, size, "a value %s %g and %s %g%s", k->lo_open ? "above" : "from", k->lo,
             k->hi_open ? "below" : "up to", k->hi, unit);
  else if (!isnan(k->lo))
    snprintf(buf, size, "a value %s %g%s", k->lo_open ? "above" : "of at least", k->lo, unit);
  else if (!isnan(k->hi))
    snprintf(buf, size, "a value %s %g%s", k->hi_open ? "below" : "of at most", k->hi, unit);
  else
    buf[0] = '\0';
}

static int out_of_range(const struct wl_key *k, double v) {
  if (!isnan(k->lo) && (k->lo_open ? v <= k->lo : v < k->lo)) return 1;
  if (!isnan(k->hi) && (k->hi_open ? v >= k->hi : v > k->hi)) return 1;
  return 0;
}

/* Parse one scalar `text` for key `k` into *v. `n` (may be NULL for
 * defaults) gives the position for messages. */
static enum wl_status set_scalar(struct ctx *c, const struct wl_key *k, const char *path,
                                 const yaml_node_t *n, const char *text,
                                 struct wl_scenario_value *v) {
  memset(v, 0, sizeof *v);
  char valid[256], msg[512];
  if (strlen(text) >= sizeof v->text) {
    /* kept whole or refused: a cut name or number would be another one */
    snprintf(msg, sizeof msg, "found a value of %zu characters; expected at most %zu (%s)",
             strlen(text), sizeof v->text - 1, k->help);
    if (n) return fail_at(c, n, path, msg, NULL);
  }
  snprintf(v->text, sizeof v->text, "%s", text);
  if (n) {
    v->given = 1;
    v->line = line_of(n);
    v->col = col_of(n);
  }
  switch (k->type) {
  case KT_STR:
    return WL_OK;
  case KT_ENUM: {
    for (int i = 0; k->choices[i]; i++)
      if (strcmp(k->choices[i], text) == 0) {
        v->choice = i;
        return WL_OK;
      }
    valid[0] = '\0';
    int best = -1, best_d = 99; /* a likely misspelling (centerline for centreline) */
    for (int i = 0; k->choices[i]; i++) {
      size_t u = strlen(valid);
      snprintf(valid + u, sizeof valid - u, "%s%s", i ? ", " : "", k->choices[i]);
      const int d = wl_error_edit_distance(text, k->choices[i]);
      if (d < best_d) best_d = d, best = i;
    }
    if (best >= 0 && wl_error_close_enough(best_d, k->choices[best]))
      snprintf(msg, sizeof msg, "found '%s'; did you mean '%s'? valid: %s", text, k->choices[best],
               valid);
    else
      snprintf(msg, sizeof msg, "found '%s'; valid: %s", text, valid);
    return n ? fail_at(c, n, path, msg, NULL)
             : wl_error_set(c->err, WL_EINPUT, "schema default for %s: %s", path, msg);
  }
  case KT_QTY_OR_AUTO:
  case KT_INT_OR_AUTO:
    if (strcmp(text, "auto") == 0) {
      v->is_auto = 1;
      return WL_OK;
    }
    break;
  case KT_QTY_OR_SAME:
    if (strcmp(text, "same-as-solitary") == 0) {
      v->is_auto = 1;
      return WL_OK;
    }
    break;
  default:
    break;
  }
  struct wl_error uerr;
  wl_error_clear(&uerr);
  enum wl_dim dim = (k->type == KT_INT || k->type == KT_INT_OR_AUTO) ? WL_DIM_NONE : k->dim;
  if (wl_units_parse(text, dim, &v->q, &uerr) != WL_OK) {
    const char *extra = k->type == KT_QTY_OR_AUTO || k->type == KT_INT_OR_AUTO
                            ? " (or auto)"
                            : k->type == KT_QTY_OR_SAME ? " (or same-as-solitary)" : "";
    snprintf(msg, sizeof msg, "%s%s", uerr.msg, extra);
    return n ? fail_at(c, n, path, msg, NULL)
             : wl_error_set(c->err, WL_EINPUT, "schema default for %s: %s", path, msg);
  }
  if ((k->type == KT_INT || k->type == KT_INT_OR_AUTO) && v->q.si != floor(v->q.si)) {
    snprintf(msg, sizeof msg, "found '%s'; expected a whole number", text);
    return fail_at(c, n, path, msg, NULL);
  }
  if (out_of_range(k, v->q.si)) {
    range_text(k, valid, sizeof valid);
    char si[64] = "";
    if (v->q.unit[0] || k->dim == WL_DIM_RATIO)
      snprintf(si, sizeof si, " (%g%s%s)", v->q.si, *wl_units_si_symbol(k->dim) ? " " : "",
               wl_units_si_symbol(k->dim));
    snprintf(msg, sizeof msg, "found '%s'%s; expected %s (%s)", text, si, valid, k->help);
    return n ? fail_at(c, n, path, msg, NULL)
             : wl_error_set(c->err, WL_EINPUT, "schema default for %s: %s", path, msg);
  }
  return WL_OK;
}

static enum wl_status parse_map(struct ctx *c, const struct wl_key *keys, void *base,
                                const char *parent, yaml_node_t *map, const yaml_node_t *owner);

/* Fill the defaults of every key of `keys` not given; `where` (may be NULL)
 * is the node of the enclosing map, for "missing key" messages. */
static enum wl_status fill_defaults(struct ctx *c, const struct wl_key *keys, void *base,
                                    const char *parent, const yaml_node_t *where,
                                    const unsigned char *seen) {
  for (int i = 0; keys[i].name; i++) {
    const struct wl_key *k = &keys[i];
    if (seen && seen[i]) continue;
    char path[256];
    join_path(path, sizeof path, parent, k->name);
    if (k->type == KT_MAP) {
      if (k->required && where) {
        char msg[512];
        snprintf(msg, sizeof msg, "missing required section '%s' (%s)", path, k->help);
        return fail_at(c, where, parent && *parent ? parent : "scenario", msg, NULL);
      }
      enum wl_status st = fill_defaults(c, k->sub, base, path, NULL, NULL);
      if (st) return st;
      continue;
    }
    if (k->type == KT_BED || k->type == KT_GAUGES || k->type == KT_LEVELS || k->type == KT_SWEEP)
      continue;
    if (k->required && where) {
      char msg[512];
      snprintf(msg, sizeof msg, "missing required key '%s' (%s)", k->name, k->help);
      return fail_at(c, where, parent && *parent ? parent : "scenario", msg, NULL);
    }
    if (k->def) {
      enum wl_status st = set_scalar(c, k, path, NULL, k->def, value_at(base, k->off));
      if (st) return st;
    }
  }
  return WL_OK;
}

/* One list entry: parse `item` (entry `index`, path `ipath`) into `out`. */
typedef enum wl_status (*item_parser)(struct ctx *c, const struct wl_key *k, const char *ipath,
                                      yaml_node_t *item, int index, void *out);

/* Walk a YAML list of at most max_items entries with `parse_item`. */
static enum wl_status parse_list(struct ctx *c, const struct wl_key *k, const char *path,
                                 yaml_node_t *seq, int max_items, item_parser parse_item,
                                 void *out, int *n_items) {
  if (seq->type != YAML_SEQUENCE_NODE) {
    char msg[512];
    snprintf(msg, sizeof msg, "found %s; expected a list (%s)", node_kind(seq), k->help);
    return fail_at(c, seq, path, msg, NULL);
  }
  int n = 0;
  for (yaml_node_item_t *it = seq->data.sequence.items.start; it < seq->data.sequence.items.top;
       it++, n++) {
    yaml_node_t *item = yaml_document_get_node(c->doc, *it);
    char ipath[256];
    snprintf(ipath, sizeof ipath, "%s[%d]", path, n);
    if (n >= max_items) {
      char msg[256];
      snprintf(msg, sizeof msg, "too many entries; at most %d are supported", max_items);
      return fail_at(c, item, ipath, msg, NULL);
    }
    enum wl_status st = parse_item(c, k, ipath, item, n, out);
    if (st) return st;
  }
  *n_items = n;
  return WL_OK;
}

/* A list of mappings (bathymetry, gauges) into an array of structs. */
struct map_array {
  void *items;
  size_t item_size;
};

static enum wl_status parse_map_item(struct ctx *c, const struct wl_key *k, const char *ipath,
                                     yaml_node_t *item, int index, void *out) {
  struct map_array *a = out;
  return parse_map(c, k->sub, (char *)a->items + (size_t)index * a->item_size, ipath, item, item);
}

/* The convergence ladder: factors of dp. */
static enum wl_status parse_level_item(struct ctx *c, const struct wl_key *k, const char *ipath,
                                       yaml_node_t *item, int index, void *out) {
  struct wl_scenario *s = out;
  if (item->type != YAML_SCALAR_NODE) {
    char msg[256];
    snprintf(msg, sizeof msg, "found %s; expected a number (a factor of dp)", node_kind(item));
    return fail_at(c, item, ipath, msg, NULL);
  }
  struct wl_key level = *k;
  level.type = KT_QTY;
  level.dim = WL_DIM_RATIO;
  return set_scalar(c, &level, ipath, item, (const char *)item->data.scalar.value,
                    &s->resolution.levels[index]);
}

/* "unknown key" at kn, with a suggestion when one of `keys` is close. */
static enum wl_status unknown_key(struct ctx *c, const struct wl_key *keys, const yaml_node_t *kn,
                                  const char *path, const char *name) {
  char msg[768], names[512];
  list_keys(keys, names, sizeof names);
  int best = -1, best_d = 99;
  for (int i = 0; keys[i].name; i++) {
    int d = wl_error_edit_distance(name, keys[i].name);
    if (d < best_d) best_d = d, best = i;
  }
  if (best >= 0 && wl_error_close_enough(best_d, keys[best].name))
    snprintf(msg, sizeof msg, "unknown key '%s'; did you mean '%s'? valid keys here: %s", name,
             keys[best].name, names);
  else
    snprintf(msg, sizeof msg, "unknown key '%s'; valid keys here: %s", name, names);
  return fail_at(c, kn, path, msg, NULL);
}

static enum wl_status parse_sweep(struct ctx *c, struct wl_scenario *s, const char *path,
                                  yaml_node_t *map, const yaml_node_t *kn);
static enum wl_status at_value(struct ctx *c, const struct wl_scenario_value *v, const char *key,
                               const char *msg);

/* `owner` is the node that names this map (its key), or the map itself at
 * the top: "missing key" messages point there. */
static enum wl_status parse_map(struct ctx *c, const struct wl_key *keys, void *base,
                                const char *parent, yaml_node_t *map, const yaml_node_t *owner) {
  if (map->type != YAML_MAPPING_NODE) {
    char msg[512], names[512];
    list_keys(keys, names, sizeof names);
    snprintf(msg, sizeof msg, "found %s; expected a mapping with keys: %s", node_kind(map), names);
    return fail_at(c, map, parent && *parent ? parent : "scenario", msg, NULL);
  }
  int n_keys = 0;
  while (keys[n_keys].name) n_keys++;
  unsigned char seen[64] = {0};
  for (yaml_node_pair_t *p = map->data.mapping.pairs.start; p < map->data.mapping.pairs.top; p++) {
    yaml_node_t *kn = yaml_document_get_node(c->doc, p->key);
    yaml_node_t *vn = yaml_document_get_node(c->doc, p->value);
    if (kn->type != YAML_SCALAR_NODE)
      return fail_at(c, kn, parent && *parent ? parent : "scenario",
                     "a key must be a plain word", NULL);
    const char *name = (const char *)kn->data.scalar.value;
    char path[256];
    join_path(path, sizeof path, parent, name);
    int idx = -1;
    for (int i = 0; i < n_keys; i++)
      if (strcmp(keys[i].name, name) == 0) idx = i;
    if (idx < 0) return unknown_key(c, keys, kn, path, name);
    if (seen[idx])
      return fail_at(c, kn, path, "this key appears twice in the same mapping", NULL);
    seen[idx] = 1;
    const struct wl_key *k = &keys[idx];
    enum wl_status st = WL_OK;
    switch (k->type) {
    case KT_MAP:
      if (k->present_off != (size_t)-1) *(int *)((char *)base + k->present_off) = 1;
      st = parse_map(c, k->sub, base, path, vn, kn);
      break;
    case KT_BED: {
      struct wl_scenario *s = base;
      struct map_array a = {s->bed, sizeof s->bed[0]};
      st = parse_list(c, k, path, vn, WL_SCENARIO_MAX_BED, parse_map_item, &a, &s->n_bed);
      s->bed_given = 1;
      break;
    }
    case KT_GAUGES: {
      struct wl_scenario *s = base;
      struct map_array a = {s->gauges, sizeof s->gauges[0]};
      st = parse_list(c, k, path, vn, WL_SCENARIO_MAX_GAUGES, parse_map_item, &a, &s->n_gauges);
      break;
    }
    case KT_LEVELS: {
      struct wl_scenario *s = base;
      st = parse_list(c, k, path, vn, WL_SCENARIO_MAX_LEVELS, parse_level_item, s,
                      &s->resolution.n_levels);
      s->resolution.levels_given = 1;
      break;
    }
    case KT_SWEEP:
      st = parse_sweep(c, base, path, vn, kn);
      break;
    default:
      if (vn->type != YAML_SCALAR_NODE) {
        char msg[512];
        snprintf(msg, sizeof msg, "found %s; expected a single value (%s)", node_kind(vn),
                 k->help);
        return fail_at(c, vn, path, msg, NULL);
      }
      if (vn->data.scalar.length == 0 && k->type != KT_STR) {
        char msg[512];
        snprintf(msg, sizeof msg, "the value is empty; expected %s",
                 k->type == KT_ENUM ? "one of the listed choices" : wl_units_valid(k->dim));
        return fail_at(c, vn, path, msg, NULL);
      }
      st = set_scalar(c, k, path, vn, (const char *)vn->data.scalar.value, value_at(base, k->off));
    }
    if (st) return st;
  }
  return fill_defaults(c, keys, base, parent, owner, seen);
}

/* ---- the sweep section ---------------------------------------------------- */

const char *wl_scenario_sweep_param_name(enum wl_sweep_param p) {
  for (const struct wl_key *k = wl_schema_sweep_keys; k->name; k++)
    if (k->off == (size_t)p) return k->name;
  return "?";
}

void wl_scenario_number_text(double v, char *buf, size_t size) {
  /* 12 significant digits: a generated value's last bits (19.999999999999996
   * from a log spacing, 12.000000000000002 from 19.2 - 7.2) are noise */
  char r[40];
  snprintf(r, sizeof r, "%.12g", v);
  v = strtod(r, NULL);
  for (int prec = 1; prec <= 17; prec++) {
    snprintf(buf, size, "%.*g", prec, v);
    if (strtod(buf, NULL) == v) break;
  }
  const double a = fabs(v);
  if (strchr(buf, 'e') && a >= 1e-4 && a < 1e15) { /* 1e+01: written out, 10 */
    const int decimals = (int)fmax(0.0, 16.0 - floor(log10(a)));
    for (int d = 0; d <= decimals; d++) {
      snprintf(buf, size, "%.*f", d, v);
      if (strtod(buf, NULL) == v) break;
    }
  }
}

static enum wl_status parse_sweep_item(struct ctx *c, const struct wl_key *k, const char *ipath,
                                       yaml_node_t *item, int index, void *out) {
  struct wl_scenario_sweep_axis *a = out;
  char msg[512];
  if (item->type != YAML_SCALAR_NODE) {
    snprintf(msg, sizeof msg, "found %s; expected one value (%s)", node_kind(item), k->help);
    return fail_at(c, item, ipath, msg, NULL);
  }
  if (item->data.scalar.length == 0) {
    snprintf(msg, sizeof msg, "the value is empty; expected %s", wl_units_valid(k->dim));
    return fail_at(c, item, ipath, msg, NULL);
  }
  return set_scalar(c, k, ipath, item, (const char *)item->data.scalar.value, &a->values[index]);
}

/* {from, to, count, spacing} into count values, each written as the text a
 * case's scenario gets: in from's unit when to has the same one, else SI. */
static enum wl_status parse_sweep_range(struct ctx *c, const struct wl_key *k, const char *path,
                                        yaml_node_t *map, const yaml_node_t *owner,
                                        struct wl_scenario_sweep_axis *a) {
  struct wl_key keys[5];
  memcpy(keys, wl_schema_sweep_range_keys, sizeof keys);
  for (int i = 0; i < 2; i++) { /* from and to: the parameter's dimension and limits */
    keys[i].dim = k->dim;
    keys[i].lo = k->lo, keys[i].hi = k->hi;
    keys[i].lo_open = k->lo_open, keys[i].hi_open = k->hi_open;
    keys[i].help = k->help;
  }
  struct wl_sweep_range r;
  memset(&r, 0, sizeof r);
  enum wl_status st = parse_map(c, keys, &r, path, map, owner);
  if (st) return st;
  const int n = (int)r.count.q.si;
  char key[300];
  if (n == 1 && r.from.q.si != r.to.q.si) {
    snprintf(key, sizeof key, "%s.count", path);
    return at_value(c, &r.count, key,
                    "found 1, which gives the one value `from` and never reaches `to`; expected a "
                    "count of at least 2, or the same value for from and to");
  }
  const int same_unit = strcmp(r.from.q.unit, r.to.q.unit) == 0;
  const double lo = same_unit ? r.from.q.value : r.from.q.si;
  const double hi = same_unit ? r.to.q.value : r.to.q.si;
  const char *unit = same_unit ? r.from.q.unit : wl_units_si_symbol(k->dim);
  const int log_spacing = r.spacing.choice == WL_SWEEP_LOG;
  for (int j = 0; j < n; j++) {
    const double t = n > 1 ? (double)j / (n - 1) : 0.0;
    double v = log_spacing ? lo * pow(hi / lo, t) : lo + (hi - lo) * t;
    if (j == 0) v = lo; /* the ends exactly as written */
    if (j == n - 1 && n > 1) v = hi;
    char num[40], text[64];
    wl_scenario_number_text(v, num, sizeof num);
    snprintf(text, sizeof text, "%s%s%s", num, *unit ? " " : "", unit);
    snprintf(key, sizeof key, "%s[%d]", path, j);
    if ((st = set_scalar(c, k, key, map, text, &a->values[j]))) return st;
  }
  a->n_values = n;
  a->is_range = 1;
  return WL_OK;
}

static enum wl_status parse_sweep(struct ctx *c, struct wl_scenario *s, const char *path,
                                  yaml_node_t *map, const yaml_node_t *kn) {
  char msg[768], names[256];
  list_keys(wl_schema_sweep_keys, names, sizeof names);
  s->sweep.present = 1;
  s->sweep.line = line_of(kn);
  s->sweep.col = col_of(kn);
  if (map->type != YAML_MAPPING_NODE || map->data.mapping.pairs.start == map->data.mapping.pairs.top) {
    snprintf(msg, sizeof msg,
             "found %s; expected a mapping of the parameters to vary (%s), each a list of values "
             "or a range {from, to, count}",
             map->type == YAML_MAPPING_NODE ? "an empty mapping" : node_kind(map), names);
    return fail_at(c, map, path, msg, NULL);
  }
  s->sweep.n_cases = 1;
  for (yaml_node_pair_t *p = map->data.mapping.pairs.start; p < map->data.mapping.pairs.top; p++) {
    yaml_node_t *pk = yaml_document_get_node(c->doc, p->key);
    yaml_node_t *pv = yaml_document_get_node(c->doc, p->value);
    if (pk->type != YAML_SCALAR_NODE) return fail_at(c, pk, path, "a key must be a plain word", NULL);
    const char *name = (const char *)pk->data.scalar.value;
    char ppath[256];
    join_path(ppath, sizeof ppath, path, name);
    const struct wl_key *k = NULL;
    for (const struct wl_key *q = wl_schema_sweep_keys; q->name; q++)
      if (!strcmp(q->name, name)) k = q;
    if (!k) return unknown_key(c, wl_schema_sweep_keys, pk, ppath, name);
    struct wl_scenario_sweep_axis *a = &s->sweep.axis[k->off];
    if (a->present) return fail_at(c, pk, ppath, "this key appears twice in the same mapping", NULL);
    a->present = 1;
    a->line = line_of(pk);
    a->col = col_of(pk);
    s->sweep.order[s->sweep.n_params++] = (enum wl_sweep_param)k->off;
    enum wl_status st;
    if (pv->type == YAML_SEQUENCE_NODE) {
      if (pv->data.sequence.items.start == pv->data.sequence.items.top) {
        snprintf(msg, sizeof msg, "the list is empty; expected at least one value (%s)", k->help);
        return fail_at(c, pv, ppath, msg, NULL);
      }
      st = parse_list(c, k, ppath, pv, WL_SCENARIO_MAX_SWEEP_VALUES, parse_sweep_item, a,
                      &a->n_values);
    } else if (pv->type == YAML_MAPPING_NODE) {
      st = parse_sweep_range(c, k, ppath, pv, pk, a);
    } else {
      const char *u = k->dim == WL_DIM_MASS ? "kg" : k->dim == WL_DIM_ENERGY ? "kJ" : "m";
      snprintf(msg, sizeof msg,
               "found %s; expected a list of values, e.g. [1 %s, 2 %s], or a range, e.g. "
               "{from: 1 %s, to: 4 %s, count: 4} (%s)",
               pv->type == YAML_SCALAR_NODE && pv->data.scalar.length == 0 ? "nothing"
                                                                            : node_kind(pv),
               u, u, u, u, k->help);
      return fail_at(c, pv, ppath, msg, NULL);
    }
    if (st) return st;
    for (int i = 1; i < a->n_values; i++)
      for (int j = 0; j < i; j++)
        if (a->values[i].q.si == a->values[j].q.si) {
          char key[300];
          snprintf(key, sizeof key, "%s[%d]", ppath, i);
          snprintf(msg, sizeof msg,
                   "found '%s', the same value as %s[%d]; expected each value once (each gives "
                   "one case)",
                   a->values[i].text, ppath, j);
          return at_value(c, &a->values[i], key, msg);
        }
    s->sweep.n_cases *= a->n_values;
    if (s->sweep.n_cases > WL_SCENARIO_MAX_SWEEP_CASES) {
      snprintf(msg, sizeof msg, "%d cases or more (the product of the values per parameter); "
               "expected at most %d", s->sweep.n_cases, WL_SCENARIO_MAX_SWEEP_CASES);
      return fail_at(c, pk, ppath, msg, NULL);
    }
  }
  return WL_OK;
}

/* The sweep's parameters against the scenario: each one must have its key
 * to vary (no charge without an explosion), and the explosion one source. */
static enum wl_status check_sweep(struct ctx *c, const struct wl_scenario *s) {
  const struct wl_scenario_sweep_axis *ax = s->sweep.axis;
  char msg[768], usable[256] = "";
  static const enum wl_sweep_param all[] = {WL_SWEEP_CHARGE, WL_SWEEP_ENERGY, WL_SWEEP_STANDOFF,
                                            WL_SWEEP_DEPTH, WL_SWEEP_SOLITARY_HEIGHT};
  for (int i = 0; i < WL_SWEEP_N_PARAMS; i++) {
    const enum wl_sweep_param p = all[i];
    const int ok = p == WL_SWEEP_DEPTH || (p == WL_SWEEP_SOLITARY_HEIGHT ? s->solitary.present
                                                                         : s->explosion.present);
    if (ok) {
      size_t u = strlen(usable);
      snprintf(usable + u, sizeof usable - u, "%s%s", u ? ", " : "", wl_scenario_sweep_param_name(p));
    }
  }
  for (int i = 0; i < s->sweep.n_params; i++) {
    const enum wl_sweep_param p = s->sweep.order[i];
    const struct wl_scenario_sweep_axis *a = &ax[p];
    const char *name = wl_scenario_sweep_param_name(p);
    const char *needs = NULL;
    if ((p == WL_SWEEP_CHARGE || p == WL_SWEEP_ENERGY || p == WL_SWEEP_STANDOFF) &&
        !s->explosion.present)
      needs = "loads.explosion";
    if (p == WL_SWEEP_SOLITARY_HEIGHT && !s->solitary.present) needs = "loads.solitary";
    if (needs) {
      snprintf(msg, sizeof msg, "the scenario has no %s for this parameter to vary; valid here: %s",
               needs, usable);
      return wl_error_set(c->err, WL_EINPUT, "%s:%d:%d: sweep.%s: %s", c->path, a->line, a->col,
                          name, msg);
    }
    if ((p == WL_SWEEP_CHARGE || p == WL_SWEEP_ENERGY) && s->explosion.eta0.given)
      return wl_error_set(c->err, WL_EINPUT,
                          "%s:%d:%d: sweep.%s: the explosion's source is a crater (eta0, r0), "
                          "which a %s cannot replace; expected loads.explosion to give a charge "
                          "or an energy",
                          c->path, a->line, a->col, name, name);
  }
  if (ax[WL_SWEEP_CHARGE].present && ax[WL_SWEEP_ENERGY].present) {
    const struct wl_scenario_sweep_axis *later =
        ax[WL_SWEEP_ENERGY].line > ax[WL_SWEEP_CHARGE].line ? &ax[WL_SWEEP_ENERGY]
                                                            : &ax[WL_SWEEP_CHARGE];
    return wl_error_set(c->err, WL_EINPUT,
                        "%s:%d:%d: sweep.%s: charge and energy both given; the explosion has one "
                        "source: sweep one of them",
                        c->path, later->line, later->col, later == &ax[WL_SWEEP_ENERGY] ? "energy" : "charge");
  }
  return WL_OK;
}

/* ---- rules that span several keys --------------------------------------- */

static enum wl_status at_value(struct ctx *c, const struct wl_scenario_value *v, const char *key,
                               const char *msg) {
  if (v->given)
    return wl_error_set(c->err, WL_EINPUT, "%s:%d:%d: %s: %s", c->path, v->line, v->col, key, msg);
  return wl_error_set(c->err, WL_EINPUT, "%s: %s (default value): %s", c->path, key, msg);
}

int wl_scenario_load_units(const struct wl_scenario *s, struct wl_load_units *u) {
  return wl_units_load_units(s->water.depth.q.unit, u);
}

double wl_scenario_bed_z(const struct wl_scenario *s, double x) {
  double z = 0.0;
  for (int i = 0; i < s->n_bed; i++) {
    double x0 = s->bed[i].from.q.si;
    if (x <= x0) break;
    double x1 = i + 1 < s->n_bed ? s->bed[i + 1].from.q.si : x;
    if (x1 > x) x1 = x;
    z += s->bed[i].slope.q.si * (x1 - x0);
  }
  return z;
}

static enum wl_status check_rules(struct ctx *c, struct wl_scenario *s) {
  char msg[768];
  double h = s->water.depth.q.si, len = s->domain.length.q.si, xw = s->wall.x.q.si;
  if (xw >= len) {
    snprintf(msg, sizeof msg,
             "found %g m, at or beyond the end of the flume; expected a position below "
             "domain.length = %g m",
             xw, len);
    return at_value(c, &s->wall.x, "wall.x", msg);
  }
  for (int i = 0; i < s->n_bed; i++) {
    char key[64];
    double x0 = s->bed[i].from.q.si;
    snprintf(key, sizeof key, "bathymetry[%d].from", i);
    if (i > 0 && x0 <= s->bed[i - 1].from.q.si) {
      snprintf(msg, sizeof msg,
               "found %g m; segments must be in increasing order of 'from' (previous: %g m)", x0,
               s->bed[i - 1].from.q.si);
      return at_value(c, &s->bed[i].from, key, msg);
    }
    if (x0 >= xw) {
      snprintf(msg, sizeof msg,
               "found %g m, at or behind the wall (wall.x = %g m): this segment never reaches "
               "the wall; expected a start before the wall",
               x0, xw);
      return at_value(c, &s->bed[i].from, key, msg);
    }
    double z_end = wl_scenario_bed_z(s, i + 1 < s->n_bed ? s->bed[i + 1].from.q.si : xw);
    snprintf(key, sizeof key, "bathymetry[%d].slope", i);
    if (z_end < -1e-12) {
      snprintf(msg, sizeof msg,
               "this slope takes the bed %g m below the flume floor; the floor is z = 0 and "
               "the bed may only rise from it",
               -z_end);
      return at_value(c, &s->bed[i].slope, key, msg);
    }
    if (z_end >= h) {
      double x_dry = x0 + (h - wl_scenario_bed_z(s, x0)) / s->bed[i].slope.q.si;
      snprintf(msg, sizeof msg,
               "the bed reaches the still-water level (depth %g m) at x = %.3f m, before the "
               "wall at %g m: this slope never reaches the wall under water; expected a "
               "gentler slope, a later start, or a flat segment before the shore",
               h, x_dry, xw);
      return at_value(c, &s->bed[i].slope, key, msg);
    }
  }
  if (s->domain.symmetry.choice == WL_SYMMETRY_CENTRELINE && !s->domain.dimensions.is_auto &&
      s->domain.dimensions.q.si != 3)
    return at_value(c, &s->domain.symmetry, "domain.symmetry",
                    "centreline needs domain.dimensions: 3 (a 2D flume section has no width "
                    "to halve); valid here: auto, none");
  double z_wall = wl_scenario_bed_z(s, xw);
  if (z_wall + s->wall.height.q.si <= h) {
    snprintf(msg, sizeof msg,
             "the wall's crest (%g m above the floor) is at or below the still-water level "
             "(%g m): a submerged wall is not a seawall; expected a height above %g m",
             z_wall + s->wall.height.q.si, h, h - z_wall);
    return at_value(c, &s->wall.height, "wall.height", msg);
  }
  {
    /* the name makes the default output directory NAME-results in the
     * working directory: no path separators, no leading dot, printable */
    const char *nm = s->name.text;
    int good = nm[0] != '\0' && nm[0] != '.' && strlen(nm) <= 64;
    for (const char *q = nm; good && *q; q++)
      good = isalnum((unsigned char)*q) || *q == '.' || *q == '_' || *q == '+' || *q == '-';
    if (!good) {
      char shown[65];
      size_t m = 0;
      for (; nm[m] && m + 1 < sizeof shown; m++)
        shown[m] = isprint((unsigned char)nm[m]) ? nm[m] : '?';
      shown[m] = '\0';
      snprintf(msg, sizeof msg,
               "'%s' is not a scenario name; expected 1 to 64 letters, digits, '.', '_', '+' or "
               "'-', not starting with '.' (it names the output directory NAME-results)",
               shown);
      return at_value(c, &s->name, "scenario", msg);
    }
  }
  for (int i = 0; i < s->n_gauges; i++) {
    char key[64];
    snprintf(key, sizeof key, "gauges[%d].x", i);
    double xg = s->gauges[i].x.q.si;
    if (xg <= 0 || xg >= xw) {
      snprintf(msg, sizeof msg,
               "found %g m; a gauge must be in the water between the paddle (0 m) and the "
               "wall (%g m)",
               xg, xw);
      return at_value(c, &s->gauges[i].x, key, msg);
    }
    /* a name becomes a results.h5 group, a CSV column and a report label:
     * letters, digits and . _ + - only; "wall" is the wall-face gauge's */
    const char *nm = s->gauges[i].name.text;
    int good = nm[0] != '\0' && strlen(nm) <= 31 && strcmp(nm, "wall") != 0;
    for (const char *q = nm; good && *q; q++)
      good = isalnum((unsigned char)*q) || *q == '.' || *q == '_' || *q == '+' || *q == '-';
    if (!good) {
      char shown[41]; /* the name as printable text: control bytes as '?' */
      size_t m = 0;
      for (; nm[m] && m + 1 < sizeof shown; m++)
        shown[m] = isprint((unsigned char)nm[m]) ? nm[m] : '?';
      shown[m] = '\0';
      snprintf(key, sizeof key, "gauges[%d].name", i);
      snprintf(msg, sizeof msg,
               "'%s' is not a gauge name; expected 1 to 31 letters, digits, '.', '_', '+' "
               "or '-', and not 'wall' (the wall face's own gauge)",
               shown);
      return at_value(c, &s->gauges[i].name, key, msg);
    }
    for (int j = 0; j < i; j++)
      if (strcmp(s->gauges[i].name.text, s->gauges[j].name.text) == 0) {
        snprintf(key, sizeof key, "gauges[%d].name", i);
        snprintf(msg, sizeof msg, "'%s' is already the name of gauges[%d]; names must be unique",
                 s->gauges[i].name.text, j);
        return at_value(c, &s->gauges[i].name, key, msg);
      }
  }
  if (!s->solitary.present && !s->explosion.present)
    return wl_error_set(c->err, WL_EINPUT,
                        "%s: loads: no load case; expected loads.solitary and/or loads.explosion",
                        c->path);
  if (s->solitary.present) {
    double H = s->solitary.height.q.si, eps = H / h;
    if (eps > WL_SCENARIO_MAX_EPS) {
      snprintf(msg, sizeof msg,
               "found %g m, H/h = %.3f in %g m of water; a solitary wave can be at most "
               "H/h = 0.833 high (Longuet-Higgins & Fenton 1974) and wallload's theories hold to "
               "H/h = %.2f: expected a height up to %.4g m",
               H, eps, h, WL_SCENARIO_MAX_EPS, WL_SCENARIO_MAX_EPS * h);
      return at_value(c, &s->solitary.height, "loads.solitary.height", msg);
    }
    if (!s->solitary.at.is_auto) {
      double xa = s->solitary.at.q.si;
      if (xa <= 0 || xa >= xw) {
        snprintf(msg, sizeof msg, "found %g m; expected a crest position between 0 and the wall (%g m)",
                 xa, xw);
        return at_value(c, &s->solitary.at, "loads.solitary.at", msg);
      }
    }
  }
  if (s->explosion.present) {
    int n_src = s->explosion.charge.given + s->explosion.energy.given +
                (s->explosion.eta0.given || s->explosion.r0.given);
    const char *one_source = "give exactly one of charge (e.g. 32 lb), energy (e.g. 177 kJ or "
                             "same-as-solitary) or a crater (eta0 and r0)";
    if (n_src == 0)
      return wl_error_set(c->err, WL_EINPUT, "%s: loads.explosion: no source given; %s", c->path,
                          one_source);
    if (n_src > 1) {
      /* Point at the source written last: the one that conflicts. */
      const struct wl_scenario_value *cand[] = {&s->explosion.charge, &s->explosion.energy,
                                                &s->explosion.eta0, &s->explosion.r0};
      const char *names[] = {"charge", "energy", "eta0", "r0"};
      int last = 0;
      for (int i = 1; i < 4; i++)
        if (cand[i]->given && (!cand[last]->given || cand[i]->line > cand[last]->line ||
                               (cand[i]->line == cand[last]->line && cand[i]->col > cand[last]->col)))
          last = i;
      char key[64];
      snprintf(key, sizeof key, "loads.explosion.%s", names[last]);
      snprintf(msg, sizeof msg, "more than one source given; %s", one_source);
      return at_value(c, cand[last], key, msg);
    }
    if (s->explosion.eta0.given != s->explosion.r0.given)
      return wl_error_set(c->err, WL_EINPUT,
                          "%s: loads.explosion: a crater needs both eta0 and r0 (only %s given)",
                          c->path, s->explosion.eta0.given ? "eta0" : "r0");
    if (s->explosion.energy.is_auto && !s->solitary.present)
      return at_value(c, &s->explosion.energy, "loads.explosion.energy",
                      "same-as-solitary needs a loads.solitary case to match");
    double xa = s->explosion.at.q.si;
    if (xa <= 0 || xa >= xw) {
      snprintf(msg, sizeof msg, "found %g m; expected a position between 0 and the wall (%g m)",
               xa, xw);
      return at_value(c, &s->explosion.at, "loads.explosion.at", msg);
    }
    int parts = (int)s->explosion.thrown_parts.q.si;
    if (parts != 1 && parts != 3 && parts != 5)
      return at_value(c, &s->explosion.thrown_parts, "loads.explosion.thrown_parts",
                      "expected 1, 3 or 5 (the partitions of seed 000)");
    if (s->explosion.shape.choice == WL_SHAPE_QUADRATIC && s->explosion.lip_form.given)
      return at_value(c, &s->explosion.lip_form, "loads.explosion.lip_form",
                      "a quadratic crater without lip has no lip form; remove lip_form or use "
                      "shape: quadratic-lip or quartic-lip");
  }
  if (s->numerics.verlet_steps.given && s->numerics.integrator.choice != WL_INTEGRATOR_VERLET)
    return at_value(c, &s->numerics.verlet_steps, "numerics.verlet_steps",
                    "applies to the Verlet integrator only; add integrator: verlet or remove "
                    "verlet_steps");
  for (int i = 0; i < s->resolution.n_levels; i++) {
    char key[64];
    snprintf(key, sizeof key, "resolution.convergence[%d]", i);
    double f = s->resolution.levels[i].q.si;
    if (!(f > 0 && f <= 1))
      return at_value(c, &s->resolution.levels[i], key,
                      "expected a factor of dp above 0 and up to 1 (e.g. 1, 0.71, 0.5)");
    if (i > 0 && f >= s->resolution.levels[i - 1].q.si)
      return at_value(c, &s->resolution.levels[i], key,
                      "levels must decrease (each one finer than the one before)");
  }
  if (s->resolution.refine.present && !s->resolution.refine.from.is_auto) {
    /* from: auto is placed, or declined with a note, by the plan */
    const struct wl_scenario_value *rf = &s->resolution.refine.from;
    const double xf = rf->q.si;
    if (!(xf > 0 && xf < xw)) {
      snprintf(msg, sizeof msg, "found %g m; expected a position between the paddle (0) and the "
               "wall (%g m): the fine level runs from it to the wall", xf, xw);
      return at_value(c, rf, "resolution.refine.from", msg);
    }
    if (s->domain.dimensions.given && !s->domain.dimensions.is_auto &&
        (int)s->domain.dimensions.q.si == 3)
      return at_value(c, rf, "resolution.refine.from",
                      "two resolutions run in 2D only (docs/variable-resolution.md); remove "
                      "resolution.refine or use domain.dimensions: 2");
    if (s->explosion.present && s->explosion.at.q.si >= xf)
      return at_value(c, rf, "resolution.refine.from",
                      "the explosion's crater lies in the fine level; expected `from` seaward of "
                      "loads.explosion.at (the crater collapses in the coarse level and its "
                      "waves cross into the fine one)");
  }
  if (s->sweep.present) return check_sweep(c, s);
  return WL_OK;
}

/* ---- loading ------------------------------------------------------------- */

void wl_scenario_init(struct wl_scenario *s) { memset(s, 0, sizeof *s); }

void wl_scenario_clear(struct wl_scenario *s) {
  if (!s) return;
  free(s->text);
  memset(s, 0, sizeof *s);
}

/* Line and column (1-based; the column in characters, not bytes) of byte
 * `offset` of text. */
static void text_position(const char *text, size_t len, size_t offset, int *line, int *col) {
  *line = 1, *col = 1;
  for (size_t b = 0; b < offset && b < len; b++) {
    if (text[b] == '\n') (*line)++, *col = 1;
    else if (((unsigned char)text[b] & 0xC0) != 0x80) (*col)++; /* not a continuation byte */
  }
}

enum wl_status wl_scenario_parse(const char *path, const char *text, size_t len,
                                 struct wl_scenario *s, struct wl_error *err) {
  wl_scenario_clear(s);
  snprintf(s->path, sizeof s->path, "%s", path);
  /* Reader limits, before libyaml builds anything (scenario.h). */
  if (len > WL_SCENARIO_MAX_BYTES) {
    int line, col;
    text_position(text, len, WL_SCENARIO_MAX_BYTES, &line, &col);
    return wl_error_set(err, WL_EINPUT,
                        "%s:%d:%d: YAML document larger than 1 MiB (it goes on past byte %d "
                        "here); a scenario needs a few kilobytes",
                        path, line, col, WL_SCENARIO_MAX_BYTES);
  }
  enum wl_status limits_st = wl_yaml_check_limits(
      path, text, len, WL_SCENARIO_MAX_DEPTH, WL_SCENARIO_MAX_ANCHORS,
      "a scenario needs at most 3 (a list of maps under bathymetry or gauges)", err);
  if (limits_st != WL_OK) return limits_st;
  s->text = malloc(len + 1);
  if (!s->text) return wl_error_set(err, WL_ENOMEM, "%s: no memory for the file's text", path);
  memcpy(s->text, text, len);
  s->text[len] = '\0';
  s->text_len = len;

  yaml_parser_t parser;
  yaml_document_t doc;
  if (!yaml_parser_initialize(&parser))
    return wl_error_set(err, WL_ENOMEM, "%s: cannot initialise the YAML parser", path);
  yaml_parser_set_input_string(&parser, (const unsigned char *)s->text, len);
  if (!yaml_parser_load(&parser, &doc)) {
    char opened[128] = "";
    if (parser.context)
      snprintf(opened, sizeof opened, " %s started at %d:%d", parser.context,
               (int)parser.context_mark.line + 1, (int)parser.context_mark.column + 1);
    int line = (int)parser.problem_mark.line + 1, col = (int)parser.problem_mark.column + 1;
    if (parser.error == YAML_READER_ERROR) {
      /* the reader (bad UTF-8, a NUL or control byte) gives a byte offset,
       * not a mark: its line and column from the text */
      text_position(s->text, len, parser.problem_offset, &line, &col);
    }
    enum wl_status st = wl_error_set(
        err, WL_EINPUT, "%s:%d:%d: malformed YAML: %s%s", path, line, col,
        parser.problem ? parser.problem : "syntax error", opened);
    yaml_parser_delete(&parser);
    return st;
  }
  struct ctx c = {path, &doc, err};
  enum wl_status st = WL_OK;
  yaml_node_t *root = yaml_document_get_root_node(&doc);
  if (!root)
    st = wl_error_set(err, WL_EINPUT, "%s:1:1: scenario: the file is empty; expected a mapping "
                      "with scenario, water, domain, wall and loads", path);
  else
    st = parse_map(&c, wl_schema_top, s, "", root, root);
  /* A second document in the same file would be silently ignored: refuse it. */
  if (st == WL_OK) {
    yaml_document_t extra;
    if (yaml_parser_load(&parser, &extra)) {
      yaml_node_t *r2 = yaml_document_get_root_node(&extra);
      if (r2)
        st = wl_error_set(err, WL_EINPUT,
                          "%s:%d:%d: a second YAML document; a scenario file holds one", path,
                          (int)r2->start_mark.line + 1, (int)r2->start_mark.column + 1);
      yaml_document_delete(&extra);
    }
  }
  if (st == WL_OK) st = check_rules(&c, s);
  yaml_document_delete(&doc);
  yaml_parser_delete(&parser);
  return st;
}

enum wl_status wl_scenario_load(const char *path, struct wl_scenario *s, struct wl_error *err) {
  struct stat sb;
  if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode))
    return wl_error_set(err, WL_EINPUT, "%s: is a directory; expected a scenario file (.yaml)", path);
  FILE *f = fopen(path, "rb");
  if (!f)
    return wl_error_set(err, WL_EINPUT, "%s: cannot open the scenario file: %s", path,
                        strerror(errno));
  size_t cap = 1 << 14, len = 0;
  char *buf = malloc(cap);
  if (!buf) {
    fclose(f);
    return wl_error_set(err, WL_ENOMEM, "%s: no memory to read the file", path);
  }
  /* At most one byte past WL_SCENARIO_MAX_BYTES is read (a device such as
   * /dev/zero never ends): wl_scenario_parse refuses the excess with its
   * position. */
  const size_t most = (size_t)WL_SCENARIO_MAX_BYTES + 1;
  size_t got;
  while (len < most && (got = fread(buf + len, 1, cap - len < most - len ? cap - len : most - len,
                                    f)) > 0) {
    len += got;
    if (len == cap && len < most) {
      char *bigger = realloc(buf, cap * 2);
      if (!bigger) {
        free(buf);
        fclose(f);
        return wl_error_set(err, WL_ENOMEM, "%s: no memory to read the file", path);
      }
      buf = bigger;
      cap *= 2;
    }
  }
  int read_error = ferror(f);
  fclose(f);
  if (read_error) {
    free(buf);
    return wl_error_set(err, WL_EIO, "%s: read error", path);
  }
  enum wl_status st = wl_scenario_parse(path, buf, len, s, err);
  free(buf);
  return st;
}

/* ---- listing ------------------------------------------------------------- */

static void write_value(FILE *out, const char *path, const struct wl_key *k,
                        const struct wl_scenario_value *v) {
  char left[160];
  if (v->is_auto && v->q.si > 0) /* resolved for the machine (wl_plan_choose) */
    snprintf(left, sizeof left, "%s: %.3g", v->text, v->q.si);
  else if (v->is_auto)
    snprintf(left, sizeof left, "%s", v->text);
  else if (k->type == KT_STR || k->type == KT_ENUM)
    snprintf(left, sizeof left, "%s", v->text);
  else if (k->type == KT_INT || k->type == KT_INT_OR_AUTO)
    snprintf(left, sizeof left, "%.0f", v->q.si);
  else if (k->dim == WL_DIM_RATIO && v->q.unit[0] == '\0' && strchr(v->text, '/'))
    snprintf(left, sizeof left, "%.6g", v->q.si);
  else if (*wl_units_si_symbol(k->dim))
    snprintf(left, sizeof left, "%.6g %s", v->q.si, wl_units_si_symbol(k->dim));
  else
    snprintf(left, sizeof left, "%.6g", v->q.si);
  char src[192];
  if (!v->given)
    snprintf(src, sizeof src, "default");
  else if (strcmp(left, v->text) == 0)
    snprintf(src, sizeof src, "line %d", v->line);
  else
    snprintf(src, sizeof src, "given as %s, line %d", v->text, v->line);
  fprintf(out, "  %-40s %-22s (%s)\n", path, left, src);
}

static void write_keys(FILE *out, const struct wl_key *keys, const void *base, const char *parent,
                       const struct wl_scenario *s) {
  for (const struct wl_key *k = keys; k->name; k++) {
    char path[256];
    join_path(path, sizeof path, parent, k->name);
    switch (k->type) {
    case KT_MAP:
      if (k->present_off != (size_t)-1 && !*(const int *)((const char *)base + k->present_off))
        continue;
      write_keys(out, k->sub, base, path, s);
      break;
    case KT_BED:
      if (s->n_bed == 0) fprintf(out, "  %-40s %-22s (default)\n", path, "flat");
      for (int i = 0; i < s->n_bed; i++) {
        char ip[256];
        snprintf(ip, sizeof ip, "%s[%d]", path, i);
        write_keys(out, k->sub, &s->bed[i], ip, s);
      }
      break;
    case KT_GAUGES:
      if (s->n_gauges == 0) fprintf(out, "  %-40s %-22s\n", path, "none");
      for (int i = 0; i < s->n_gauges; i++) {
        char ip[256];
        snprintf(ip, sizeof ip, "%s[%d]", path, i);
        write_keys(out, k->sub, &s->gauges[i], ip, s);
      }
      break;
    case KT_LEVELS:
      if (s->resolution.n_levels == 0) fprintf(out, "  %-40s %-22s (default)\n", path, "none");
      for (int i = 0; i < s->resolution.n_levels; i++) {
        char ip[256];
        snprintf(ip, sizeof ip, "%s[%d]", path, i);
        struct wl_key level = *k;
        level.type = KT_QTY;
        level.dim = WL_DIM_RATIO;
        write_value(out, ip, &level, &s->resolution.levels[i]);
      }
      break;
    case KT_SWEEP:
      for (int i = 0; s->sweep.present && i < s->sweep.n_params; i++) {
        const enum wl_sweep_param p = s->sweep.order[i];
        const struct wl_key *sk = &k->sub[p];
        for (int j = 0; j < s->sweep.axis[p].n_values; j++) {
          char ip[256];
          snprintf(ip, sizeof ip, "%s.%s[%d]", path, sk->name, j);
          write_value(out, ip, sk, &s->sweep.axis[p].values[j]);
        }
      }
      break;
    default: {
      const struct wl_scenario_value *v =
          (const struct wl_scenario_value *)((const char *)base + k->off);
      if (!v->given && !k->def) continue; /* optional and absent */
      write_value(out, path, k, v);
    }
    }
  }
}

const struct wl_scenario_value *wl_scenario_value_of(const struct wl_scenario *s,
                                                     const char *key) {
  const struct wl_key *keys = wl_schema_top;
  for (const char *name = key; keys && name && *name;) {
    const char *dot = strchr(name, '.');
    const size_t len = dot ? (size_t)(dot - name) : strlen(name);
    const struct wl_key *k = keys;
    while (k->name && (strlen(k->name) != len || strncmp(k->name, name, len))) k++;
    if (!k->name) return NULL;
    if (!dot) /* a scalar of the scenario itself, not a map or a list */
      return k->type == KT_MAP || k->type == KT_BED || k->type == KT_GAUGES ||
                     k->type == KT_LEVELS || k->type == KT_SWEEP
                 ? NULL
                 : (const struct wl_scenario_value *)((const char *)s + k->off);
    keys = k->type == KT_MAP ? k->sub : NULL;
    name = dot + 1;
  }
  return NULL;
}

void wl_scenario_write_resolved(const struct wl_scenario *s, FILE *out) {
  write_keys(out, wl_schema_top, s, "", s);
}
