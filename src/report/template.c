/* template.c: load a report template (a YAML file in report_templates/) with libyaml
 * into struct wl_report_template, checking it the way the scenario parser
 * checks scenarios: every key known, every value typed, each error
 * "file:line:col: key: found X; valid: ...". Which keys a section takes
 * depends on its type; the table below is that schema. */
#include "wallload/report.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "wallload/units.h"
#include "wallload/yaml_limits.h"

#define EXAGGERATION_MAX 100.0 /* beyond this a sketch stops being one */
#define DIGITS_MIN 2
#define DIGITS_MAX 6
#define DEFAULT_DIGITS 3
#define TEMPLATE_MAX_BYTES (1 << 20) /* a template is a page of text */

static const char *const TYPE_NAME[WL_REPORT_SECTION_COUNT] = {
    "title", "scene", "snapshots", "gauges", "loads",
    "peaks", "design_formulae", "convergence", "metadata"};

static const char *const DEFAULT_TITLE[WL_REPORT_SECTION_COUNT] = {
    "",
    "Flume, bathymetry and wall",
    "Free surface near the wall",
    "Free-surface elevation at the gauges",
    "Wall loads",
    "Peak loads",
    "Comparison with design formulae",
    "Resolution and numerical error",
    "Run record"};

static const char *const FIELD_NAMES[] = {"pressure", "velocity", "density", NULL};
static const char *const LOAD_NAMES[] = {"force", "impulse", "moment", "pressure", "runup", NULL};
static const char *const FORMULA_NAMES[] = {"hydrostatic", "goda-takahashi", "cross", "fema-p646",
                                            NULL};

/* Section keys; which types take which is TYPE_KEYS. */
enum skey {
  K_TYPE,
  K_TITLE,
  K_TEXT,
  K_PAGE_BREAK,
  K_TIMES,
  K_FIELD,
  K_X_RANGE,
  K_EXAGGERATION,
  K_GAUGES,
  K_QUANTITIES,
  K_FORMULAE,
  K_DIGITS,
  K_SCENARIO_TEXT,
  K_COUNT
};

static const char *const SKEY_NAME[K_COUNT] = {
    "type",   "title",      "text",     "page_break", "times",  "field",        "x_range",
    "exaggeration", "gauges", "quantities", "formulae", "digits", "scenario_text"};

#define BIT(k) (1u << (k))
#define COMMON (BIT(K_TYPE) | BIT(K_TITLE) | BIT(K_TEXT) | BIT(K_PAGE_BREAK))

static const unsigned TYPE_KEYS[WL_REPORT_SECTION_COUNT] = {
    COMMON,                                             /* title */
    COMMON | BIT(K_X_RANGE) | BIT(K_EXAGGERATION),      /* scene */
    COMMON | BIT(K_TIMES) | BIT(K_FIELD) | BIT(K_X_RANGE), /* snapshots */
    COMMON | BIT(K_GAUGES),                             /* gauges */
    COMMON | BIT(K_QUANTITIES),                         /* loads */
    COMMON | BIT(K_DIGITS),                             /* peaks */
    COMMON | BIT(K_FORMULAE) | BIT(K_DIGITS),           /* design_formulae */
    COMMON | BIT(K_DIGITS),                             /* convergence */
    COMMON | BIT(K_SCENARIO_TEXT),                      /* metadata */
};

static const char *const TOP_KEYS[] = {"company", "title", "subtitle", "title_block", "sections",
                                       NULL};
static const char *const BLOCK_KEYS[] = {"project",    "client",     "reference", "revision",
                                         "prepared_by", "checked_by", "date",      NULL};

struct ctx {
  const char *path;
  yaml_document_t *doc;
  struct wl_error *err;
};

static int line_of(const yaml_node_t *n) { return (int)n->start_mark.line + 1; }
static int col_of(const yaml_node_t *n) { return (int)n->start_mark.column + 1; }

static enum wl_status fail_at(struct ctx *c, const yaml_node_t *n, const char *key,
                              const char *msg) {
  return wl_error_set(c->err, WL_EINPUT, "%s:%d:%d: %s: %s", c->path, line_of(n), col_of(n), key,
                      msg);
}

static const char *node_kind(const yaml_node_t *n) {
  switch (n->type) {
  case YAML_SCALAR_NODE: return "a value";
  case YAML_SEQUENCE_NODE: return "a list";
  case YAML_MAPPING_NODE: return "a mapping";
  default: return "nothing";
  }
}

static const char *scalar(const yaml_node_t *n) { return (const char *)n->data.scalar.value; }


/* "a, b, c" of names[i] for the bits set in `mask` (all when mask is ~0). */
static void join_names(const char *const *names, int n, unsigned mask, char *buf, size_t size) {
  buf[0] = '\0';
  int first = 1;
  for (int i = 0; i < n && names[i]; i++) {
    if (!(mask & BIT(i))) continue;
    size_t used = strlen(buf);
    snprintf(buf + used, size - used, "%s%s", first ? "" : ", ", names[i]);
    first = 0;
  }
}

/* " (did you mean 'x'?)" when a name is close to `found`, else "". */
static void suggest(const char *found, const char *const *names, int n, unsigned mask, char *buf,
                    size_t size) {
  int best = -1, best_d = 99;
  for (int i = 0; i < n && names[i]; i++) {
    if (!(mask & BIT(i))) continue;
    int dd = wl_error_edit_distance(found, names[i]);
    if (dd < best_d) best_d = dd, best = i;
  }
  if (best >= 0 && wl_error_close_enough(best_d, names[best]))
    snprintf(buf, size, " (did you mean '%s'?)", names[best]);
  else
    buf[0] = '\0';
}

static int count_names(const char *const *names) {
  int n = 0;
  while (names[n]) n++;
  return n;
}

/* ---- typed values ------------------------------------------------------------ */

static enum wl_status want_scalar(struct ctx *c, const yaml_node_t *n, const char *key,
                                  const char *valid) {
  if (n->type == YAML_SCALAR_NODE) return WL_OK;
  char msg[512];
  snprintf(msg, sizeof msg, "found %s; valid: %s", node_kind(n), valid);
  return fail_at(c, n, key, msg);
}

static enum wl_status get_text(struct ctx *c, const yaml_node_t *n, const char *key, char *out,
                               size_t size) {
  enum wl_status st = want_scalar(c, n, key, "a text");
  if (st != WL_OK) return st;
  if (n->data.scalar.length >= size) {
    char msg[256];
    snprintf(msg, sizeof msg, "found a text of %zu bytes; valid: at most %zu bytes",
             n->data.scalar.length, size - 1);
    return fail_at(c, n, key, msg);
  }
  memcpy(out, scalar(n), n->data.scalar.length);
  out[n->data.scalar.length] = '\0';
  return WL_OK;
}

static enum wl_status get_bool(struct ctx *c, const yaml_node_t *n, const char *key, int *out) {
  static const char *const yes[] = {"true", "yes", "on"}, *const no[] = {"false", "no", "off"};
  enum wl_status st = want_scalar(c, n, key, "true or false");
  if (st != WL_OK) return st;
  for (int i = 0; i < 3; i++) {
    if (strcmp(scalar(n), yes[i]) == 0) return *out = 1, WL_OK;
    if (strcmp(scalar(n), no[i]) == 0) return *out = 0, WL_OK;
  }
  char msg[256];
  snprintf(msg, sizeof msg, "found '%.64s'; valid: true, false", scalar(n));
  return fail_at(c, n, key, msg);
}

static enum wl_status get_quantity(struct ctx *c, const yaml_node_t *n, const char *key,
                                   enum wl_dim dim, double *out) {
  char valid[256];
  snprintf(valid, sizeof valid, "a number with a unit (%s)", wl_units_valid(dim));
  enum wl_status st = want_scalar(c, n, key, valid);
  if (st != WL_OK) return st;
  struct wl_error uerr;
  struct wl_quantity q;
  wl_error_clear(&uerr);
  if (wl_units_parse(scalar(n), dim, &q, &uerr) != WL_OK) return fail_at(c, n, key, uerr.msg);
  *out = q.si;
  return WL_OK;
}

/* One of `names` -> its index. */
static enum wl_status get_choice(struct ctx *c, const yaml_node_t *n, const char *key,
                                 const char *const *names, int *out) {
  char valid[256], hint[96], msg[512];
  join_names(names, count_names(names), ~0u, valid, sizeof valid);
  enum wl_status st = want_scalar(c, n, key, valid);
  if (st != WL_OK) return st;
  for (int i = 0; names[i]; i++)
    if (strcmp(names[i], scalar(n)) == 0) return *out = i, WL_OK;
  suggest(scalar(n), names, count_names(names), ~0u, hint, sizeof hint);
  snprintf(msg, sizeof msg, "found '%.64s'%s; valid: %s", scalar(n), hint, valid);
  return fail_at(c, n, key, msg);
}

/* A list of `names` (or a single name) -> a bit set. */
static enum wl_status get_choice_set(struct ctx *c, yaml_node_t *n, const char *key,
                                     const char *const *names, unsigned *out) {
  if (n->type == YAML_SCALAR_NODE) {
    int i = 0;
    enum wl_status st = get_choice(c, n, key, names, &i);
    if (st == WL_OK) *out = BIT(i);
    return st;
  }
  if (n->type != YAML_SEQUENCE_NODE) {
    char valid[256], msg[512];
    join_names(names, count_names(names), ~0u, valid, sizeof valid);
    snprintf(msg, sizeof msg, "found %s; valid: a list of %s", node_kind(n), valid);
    return fail_at(c, n, key, msg);
  }
  unsigned set = 0;
  int k = 0;
  for (yaml_node_item_t *it = n->data.sequence.items.start; it < n->data.sequence.items.top;
       it++, k++) {
    yaml_node_t *item = yaml_document_get_node(c->doc, *it);
    char ikey[128];
    snprintf(ikey, sizeof ikey, "%s[%d]", key, k);
    int i = 0;
    enum wl_status st = get_choice(c, item, ikey, names, &i);
    if (st != WL_OK) return st;
    if (set & BIT(i)) return fail_at(c, item, ikey, "listed twice; valid: each name once");
    set |= BIT(i);
  }
  if (!set) return fail_at(c, n, key, "found an empty list; valid: at least one name");
  *out = set;
  return WL_OK;
}

/* ---- sections ----------------------------------------------------------------- */

static void section_defaults(struct wl_report_section *s, enum wl_report_section_type type) {
  memset(s, 0, sizeof *s);
  s->type = type;
  snprintf(s->title, sizeof s->title, "%s", DEFAULT_TITLE[type]);
  s->field = WL_REPORT_FIELD_PRESSURE;
  s->exaggeration = 1.0;
  s->loads = WL_REPORT_LOAD_FORCE | WL_REPORT_LOAD_IMPULSE | WL_REPORT_LOAD_MOMENT;
  s->formulae = WL_REPORT_FORMULA_HYDROSTATIC | WL_REPORT_FORMULA_GODA_TAKAHASHI |
                WL_REPORT_FORMULA_CROSS | WL_REPORT_FORMULA_FEMA_P646;
  s->digits = DEFAULT_DIGITS;
  s->scenario_text = 1;
}

static enum wl_status parse_times(struct ctx *c, yaml_node_t *n, const char *key,
                                  struct wl_report_section *s) {
  if (n->type == YAML_SCALAR_NODE && strcmp(scalar(n), "auto") == 0) {
    s->n_times = 0;
    return WL_OK;
  }
  if (n->type != YAML_SEQUENCE_NODE) {
    char msg[256];
    snprintf(msg, sizeof msg, "found %s%s%.64s%s; valid: auto, or a list of times (e.g. [2 s, 2.5 s])",
             node_kind(n), n->type == YAML_SCALAR_NODE ? " '" : "",
             n->type == YAML_SCALAR_NODE ? scalar(n) : "", n->type == YAML_SCALAR_NODE ? "'" : "");
    return fail_at(c, n, key, msg);
  }
  int k = 0;
  for (yaml_node_item_t *it = n->data.sequence.items.start; it < n->data.sequence.items.top;
       it++, k++) {
    yaml_node_t *item = yaml_document_get_node(c->doc, *it);
    char ikey[128], msg[256];
    snprintf(ikey, sizeof ikey, "%s[%d]", key, k);
    if (k >= WL_REPORT_MAX_TIMES) {
      snprintf(msg, sizeof msg, "found more than %d times; valid: at most %d per section",
               WL_REPORT_MAX_TIMES, WL_REPORT_MAX_TIMES);
      return fail_at(c, item, ikey, msg);
    }
    double t = 0;
    enum wl_status st = get_quantity(c, item, ikey, WL_DIM_TIME, &t);
    if (st != WL_OK) return st;
    if (t < 0 || (k > 0 && t <= s->times[k - 1])) {
      snprintf(msg, sizeof msg, "found %g s; valid: times from 0 s, each later than the one before",
               t);
      return fail_at(c, item, ikey, msg);
    }
    s->times[k] = t;
  }
  if (k == 0) return fail_at(c, n, key, "found an empty list; valid: auto, or at least one time");
  s->n_times = k;
  return WL_OK;
}

static enum wl_status parse_x_range(struct ctx *c, yaml_node_t *n, const char *key,
                                    struct wl_report_section *s) {
  const char *valid = "a list of two positions [from, to] with units, e.g. [16 m, 20 m]";
  char msg[512];
  if (n->type != YAML_SEQUENCE_NODE ||
      n->data.sequence.items.top - n->data.sequence.items.start != 2) {
    snprintf(msg, sizeof msg, "found %s%s; valid: %s", node_kind(n),
             n->type == YAML_SEQUENCE_NODE ? " of other than two entries" : "", valid);
    return fail_at(c, n, key, msg);
  }
  for (int k = 0; k < 2; k++) {
    yaml_node_t *item = yaml_document_get_node(c->doc, n->data.sequence.items.start[k]);
    char ikey[128];
    snprintf(ikey, sizeof ikey, "%s[%d]", key, k);
    enum wl_status st = get_quantity(c, item, ikey, WL_DIM_LENGTH, &s->x_range[k]);
    if (st != WL_OK) return st;
  }
  if (!(s->x_range[0] < s->x_range[1])) {
    snprintf(msg, sizeof msg, "found [%g m, %g m]; valid: from < to", s->x_range[0], s->x_range[1]);
    return fail_at(c, n, key, msg);
  }
  s->has_x_range = 1;
  return WL_OK;
}

static enum wl_status parse_gauges(struct ctx *c, yaml_node_t *n, const char *key,
                                   struct wl_report_section *s) {
  if (n->type == YAML_SCALAR_NODE && strcmp(scalar(n), "all") == 0) {
    s->n_gauges = 0;
    return WL_OK;
  }
  if (n->type != YAML_SEQUENCE_NODE) {
    char msg[256];
    snprintf(msg, sizeof msg, "found %s; valid: all, or a list of gauge names (e.g. [G1, G2])",
             node_kind(n));
    return fail_at(c, n, key, msg);
  }
  int k = 0;
  for (yaml_node_item_t *it = n->data.sequence.items.start; it < n->data.sequence.items.top;
       it++, k++) {
    yaml_node_t *item = yaml_document_get_node(c->doc, *it);
    char ikey[128];
    snprintf(ikey, sizeof ikey, "%s[%d]", key, k);
    if (k >= WL_REPORT_MAX_NAMES) {
      char msg[128];
      snprintf(msg, sizeof msg, "found more than %d gauges; valid: at most %d", WL_REPORT_MAX_NAMES,
               WL_REPORT_MAX_NAMES);
      return fail_at(c, item, ikey, msg);
    }
    enum wl_status st = get_text(c, item, ikey, s->gauges[k], WL_REPORT_NAME_MAX);
    if (st != WL_OK) return st;
    if (!s->gauges[k][0]) return fail_at(c, item, ikey, "found an empty name; valid: a gauge name");
  }
  if (k == 0) return fail_at(c, n, key, "found an empty list; valid: all, or at least one name");
  s->n_gauges = k;
  return WL_OK;
}

static enum wl_status parse_option(struct ctx *c, enum skey k, yaml_node_t *vn, const char *key,
                                   struct wl_report_section *s) {
  char msg[256];
  switch (k) {
  case K_TYPE: return WL_OK; /* read first, by parse_section */
  case K_TITLE: return get_text(c, vn, key, s->title, sizeof s->title);
  case K_TEXT: return get_text(c, vn, key, s->text, sizeof s->text);
  case K_PAGE_BREAK: return get_bool(c, vn, key, &s->page_break);
  case K_TIMES: return parse_times(c, vn, key, s);
  case K_FIELD: {
    int i = 0;
    enum wl_status st = get_choice(c, vn, key, FIELD_NAMES, &i);
    s->field = (enum wl_report_field_quantity)i;
    return st;
  }
  case K_X_RANGE: return parse_x_range(c, vn, key, s);
  case K_EXAGGERATION: {
    enum wl_status st = get_quantity(c, vn, key, WL_DIM_RATIO, &s->exaggeration);
    if (st == WL_OK && !(s->exaggeration >= 1.0 && s->exaggeration <= EXAGGERATION_MAX)) {
      snprintf(msg, sizeof msg, "found %g; valid: a number from 1 (true scale) to %g",
               s->exaggeration, EXAGGERATION_MAX);
      return fail_at(c, vn, key, msg);
    }
    return st;
  }
  case K_GAUGES: return parse_gauges(c, vn, key, s);
  case K_QUANTITIES: return get_choice_set(c, vn, key, LOAD_NAMES, &s->loads);
  case K_FORMULAE: return get_choice_set(c, vn, key, FORMULA_NAMES, &s->formulae);
  case K_DIGITS: {
    double v = 0;
    enum wl_status st = want_scalar(c, vn, key, "a whole number from 2 to 6");
    if (st != WL_OK) return st;
    char *end = NULL;
    v = strtod(scalar(vn), &end);
    if (end == scalar(vn) || *end || v != floor(v) || v < DIGITS_MIN || v > DIGITS_MAX) {
      snprintf(msg, sizeof msg, "found '%.64s'; valid: a whole number from %d to %d", scalar(vn),
               DIGITS_MIN, DIGITS_MAX);
      return fail_at(c, vn, key, msg);
    }
    s->digits = (int)v;
    return WL_OK;
  }
  case K_SCENARIO_TEXT: return get_bool(c, vn, key, &s->scenario_text);
  case K_COUNT: break;
  }
  return WL_OK;
}

/* The types that take key k, for "only X sections take it". */
static void types_taking(enum skey k, char *buf, size_t size) {
  buf[0] = '\0';
  int first = 1;
  for (int t = 0; t < WL_REPORT_SECTION_COUNT; t++) {
    if (!(TYPE_KEYS[t] & BIT(k))) continue;
    size_t used = strlen(buf);
    snprintf(buf + used, size - used, "%s%s", first ? "" : ", ", TYPE_NAME[t]);
    first = 0;
  }
}

static enum wl_status parse_section(struct ctx *c, yaml_node_t *item, int index,
                                    struct wl_report_section *s) {
  char key[96], msg[1024], valid[512], hint[96];
  snprintf(key, sizeof key, "sections[%d]", index);
  join_names(TYPE_NAME, WL_REPORT_SECTION_COUNT, ~0u, valid, sizeof valid);
  if (item->type != YAML_MAPPING_NODE) {
    snprintf(msg, sizeof msg, "found %s; valid: a mapping such as { type: loads, title: ... } "
                              "with type one of %s", node_kind(item), valid);
    return fail_at(c, item, key, msg);
  }
  /* The type decides which other keys are valid: read it first. */
  yaml_node_t *type_node = NULL;
  for (yaml_node_pair_t *p = item->data.mapping.pairs.start; p < item->data.mapping.pairs.top; p++) {
    yaml_node_t *kn = yaml_document_get_node(c->doc, p->key);
    if (kn->type == YAML_SCALAR_NODE && strcmp(scalar(kn), "type") == 0)
      type_node = yaml_document_get_node(c->doc, p->value);
  }
  if (!type_node) {
    snprintf(msg, sizeof msg, "found no 'type'; valid types: %s", valid);
    return fail_at(c, item, key, msg);
  }
  char tkey[128];
  snprintf(tkey, sizeof tkey, "%s.type", key);
  int type = 0;
  {
    enum wl_status st = want_scalar(c, type_node, tkey, valid);
    if (st != WL_OK) return st;
    int found = -1;
    for (int t = 0; t < WL_REPORT_SECTION_COUNT; t++)
      if (strcmp(TYPE_NAME[t], scalar(type_node)) == 0) found = t;
    if (found < 0) {
      suggest(scalar(type_node), TYPE_NAME, WL_REPORT_SECTION_COUNT, ~0u, hint, sizeof hint);
      snprintf(msg, sizeof msg, "found '%.64s'%s; valid: %s", scalar(type_node), hint, valid);
      return fail_at(c, type_node, tkey, msg);
    }
    type = found;
  }
  section_defaults(s, (enum wl_report_section_type)type);
  s->line = line_of(item);
  s->col = col_of(item);
  unsigned allowed = TYPE_KEYS[type], seen = 0;
  for (yaml_node_pair_t *p = item->data.mapping.pairs.start; p < item->data.mapping.pairs.top; p++) {
    yaml_node_t *kn = yaml_document_get_node(c->doc, p->key);
    yaml_node_t *vn = yaml_document_get_node(c->doc, p->value);
    if (kn->type != YAML_SCALAR_NODE) return fail_at(c, kn, key, "found a key that is not a word");
    const char *name = scalar(kn);
    char okey[160];
    snprintf(okey, sizeof okey, "%s.%.64s", key, name);
    int k = -1;
    for (int i = 0; i < K_COUNT; i++)
      if (strcmp(SKEY_NAME[i], name) == 0) k = i;
    join_names(SKEY_NAME, K_COUNT, allowed, valid, sizeof valid);
    if (k < 0) {
      suggest(name, SKEY_NAME, K_COUNT, allowed, hint, sizeof hint);
      snprintf(msg, sizeof msg, "found unknown key '%.64s'%s; valid for a %s section: %s", name,
               hint, TYPE_NAME[type], valid);
      return fail_at(c, kn, okey, msg);
    }
    if (!(allowed & BIT(k))) {
      char takers[256];
      types_taking((enum skey)k, takers, sizeof takers);
      snprintf(msg, sizeof msg,
               "found key '%s', which a %s section does not take (only %s sections do); valid "
               "for a %s section: %s",
               name, TYPE_NAME[type], takers, TYPE_NAME[type], valid);
      return fail_at(c, kn, okey, msg);
    }
    if (seen & BIT(k)) return fail_at(c, kn, okey, "found this key twice; valid: each key once");
    seen |= BIT(k);
    enum wl_status st = parse_option(c, (enum skey)k, vn, okey, s);
    if (st != WL_OK) return st;
  }
  return WL_OK;
}

static enum wl_status parse_sections(struct ctx *c, yaml_node_t *n, struct wl_report_template *t) {
  char valid[256], msg[512];
  join_names(TYPE_NAME, WL_REPORT_SECTION_COUNT, ~0u, valid, sizeof valid);
  if (n->type != YAML_SEQUENCE_NODE) {
    snprintf(msg, sizeof msg, "found %s; valid: a list of sections, each with a type (%s)",
             node_kind(n), valid);
    return fail_at(c, n, "sections", msg);
  }
  int count = (int)(n->data.sequence.items.top - n->data.sequence.items.start);
  if (count == 0) {
    snprintf(msg, sizeof msg, "found an empty list; valid: at least one section (%s)", valid);
    return fail_at(c, n, "sections", msg);
  }
  if (count > WL_REPORT_MAX_SECTIONS) {
    yaml_node_t *extra =
        yaml_document_get_node(c->doc, n->data.sequence.items.start[WL_REPORT_MAX_SECTIONS]);
    snprintf(msg, sizeof msg, "found %d sections; valid: at most %d", count,
             WL_REPORT_MAX_SECTIONS);
    char key[64];
    snprintf(key, sizeof key, "sections[%d]", WL_REPORT_MAX_SECTIONS);
    return fail_at(c, extra, key, msg);
  }
  t->sections = calloc((size_t)count, sizeof *t->sections);
  if (!t->sections)
    return wl_error_set(c->err, WL_ENOMEM, "%s: no memory for %d sections", c->path, count);
  for (int i = 0; i < count; i++) {
    yaml_node_t *item = yaml_document_get_node(c->doc, n->data.sequence.items.start[i]);
    enum wl_status st = parse_section(c, item, i, &t->sections[i]);
    if (st != WL_OK) return st;
    t->n_sections = i + 1;
  }
  return WL_OK;
}

static enum wl_status parse_block(struct ctx *c, yaml_node_t *n, struct wl_report_title_block *b) {
  char valid[256], msg[512], hint[96];
  int n_keys = count_names(BLOCK_KEYS);
  join_names(BLOCK_KEYS, n_keys, ~0u, valid, sizeof valid);
  if (n->type != YAML_MAPPING_NODE) {
    snprintf(msg, sizeof msg, "found %s; valid: a mapping with keys %s", node_kind(n), valid);
    return fail_at(c, n, "title_block", msg);
  }
  char *field[] = {b->project,    b->client,     b->reference, b->revision,
                   b->prepared_by, b->checked_by, b->date};
  unsigned seen = 0;
  for (yaml_node_pair_t *p = n->data.mapping.pairs.start; p < n->data.mapping.pairs.top; p++) {
    yaml_node_t *kn = yaml_document_get_node(c->doc, p->key);
    yaml_node_t *vn = yaml_document_get_node(c->doc, p->value);
    if (kn->type != YAML_SCALAR_NODE)
      return fail_at(c, kn, "title_block", "found a key that is not a word");
    char key[128];
    snprintf(key, sizeof key, "title_block.%.64s", scalar(kn));
    int k = -1;
    for (int i = 0; i < n_keys; i++)
      if (strcmp(BLOCK_KEYS[i], scalar(kn)) == 0) k = i;
    if (k < 0) {
      suggest(scalar(kn), BLOCK_KEYS, n_keys, ~0u, hint, sizeof hint);
      snprintf(msg, sizeof msg, "found unknown key '%.64s'%s; valid: %s", scalar(kn), hint, valid);
      return fail_at(c, kn, key, msg);
    }
    if (seen & BIT(k)) return fail_at(c, kn, key, "found this key twice; valid: each key once");
    seen |= BIT(k);
    enum wl_status st = get_text(c, vn, key, field[k], WL_REPORT_LINE_MAX);
    if (st != WL_OK) return st;
  }
  return WL_OK;
}

static enum wl_status parse_top(struct ctx *c, yaml_node_t *root, struct wl_report_template *t) {
  char valid[256], msg[512], hint[96];
  int n_keys = count_names(TOP_KEYS);
  join_names(TOP_KEYS, n_keys, ~0u, valid, sizeof valid);
  if (root->type != YAML_MAPPING_NODE) {
    snprintf(msg, sizeof msg, "found %s; valid: a mapping with keys %s", node_kind(root), valid);
    return fail_at(c, root, "template", msg);
  }
  unsigned seen = 0;
  for (yaml_node_pair_t *p = root->data.mapping.pairs.start; p < root->data.mapping.pairs.top;
       p++) {
    yaml_node_t *kn = yaml_document_get_node(c->doc, p->key);
    yaml_node_t *vn = yaml_document_get_node(c->doc, p->value);
    if (kn->type != YAML_SCALAR_NODE)
      return fail_at(c, kn, "template", "found a key that is not a word");
    const char *name = scalar(kn);
    char key[96];
    snprintf(key, sizeof key, "%.64s", name);
    int k = -1;
    for (int i = 0; i < n_keys; i++)
      if (strcmp(TOP_KEYS[i], name) == 0) k = i;
    if (k < 0) {
      suggest(name, TOP_KEYS, n_keys, ~0u, hint, sizeof hint);
      snprintf(msg, sizeof msg, "found unknown key '%.64s'%s; valid: %s", name, hint, valid);
      return fail_at(c, kn, key, msg);
    }
    if (seen & BIT(k)) return fail_at(c, kn, key, "found this key twice; valid: each key once");
    seen |= BIT(k);
    enum wl_status st = WL_OK;
    switch (k) {
    case 0: st = get_text(c, vn, key, t->company, sizeof t->company); break;
    case 1: st = get_text(c, vn, key, t->title, sizeof t->title); break;
    case 2: st = get_text(c, vn, key, t->subtitle, sizeof t->subtitle); break;
    case 3: st = parse_block(c, vn, &t->block); break;
    default: st = parse_sections(c, vn, t); break;
    }
    if (st != WL_OK) return st;
  }
  if (!(seen & BIT(4))) {
    join_names(TYPE_NAME, WL_REPORT_SECTION_COUNT, ~0u, valid, sizeof valid);
    snprintf(msg, sizeof msg, "found no 'sections'; valid: a list of sections, each with a type "
                              "(%s)", valid);
    return fail_at(c, root, "template", msg);
  }
  return WL_OK;
}

/* ---- public ------------------------------------------------------------------- */

void wl_report_template_init(struct wl_report_template *t) { memset(t, 0, sizeof *t); }

void wl_report_template_clear(struct wl_report_template *t) {
  if (!t) return;
  free(t->sections);
  memset(t, 0, sizeof *t);
}

const char *wl_report_section_type_name(enum wl_report_section_type type) {
  return (int)type >= 0 && type < WL_REPORT_SECTION_COUNT ? TYPE_NAME[type] : "?";
}

const char *wl_report_section_default_title(enum wl_report_section_type type) {
  return (int)type >= 0 && type < WL_REPORT_SECTION_COUNT ? DEFAULT_TITLE[type] : "";
}

enum wl_status wl_report_template_parse(const char *path, const char *text, size_t len,
                                        struct wl_report_template *t, struct wl_error *err) {
  wl_report_template_clear(t);
  snprintf(t->path, sizeof t->path, "%s", path);
  snprintf(t->title, sizeof t->title, "Wave loads on a wall");
  snprintf(t->block.date, sizeof t->block.date, "auto");
  /* depth 4: the root, its sections, a section, a section's list */
  enum wl_status lst = wl_yaml_check_limits(path, text, len, WL_YAML_MAX_DEPTH, WL_YAML_MAX_ANCHORS,
                                            "a report template needs at most 4", err);
  if (lst) return lst;
  yaml_parser_t parser;
  yaml_document_t doc;
  if (!yaml_parser_initialize(&parser))
    return wl_error_set(err, WL_ENOMEM, "%s: cannot initialise the YAML parser", path);
  yaml_parser_set_input_string(&parser, (const unsigned char *)text, len);
  if (!yaml_parser_load(&parser, &doc)) {
    char opened[128] = "";
    if (parser.context)
      snprintf(opened, sizeof opened, " (%s started at %d:%d)", parser.context,
               (int)parser.context_mark.line + 1, (int)parser.context_mark.column + 1);
    enum wl_status st = wl_error_set(
        err, WL_EINPUT, "%s:%d:%d: malformed YAML: %s%s", path, (int)parser.problem_mark.line + 1,
        (int)parser.problem_mark.column + 1, parser.problem ? parser.problem : "syntax error",
        opened);
    yaml_parser_delete(&parser);
    wl_report_template_clear(t);
    return st;
  }
  struct ctx c = {path, &doc, err};
  enum wl_status st = WL_OK;
  yaml_node_t *root = yaml_document_get_root_node(&doc);
  if (!root)
    st = wl_error_set(err, WL_EINPUT,
                      "%s:1:1: template: found an empty file; valid: a mapping with keys company, "
                      "title, subtitle, title_block, sections",
                      path);
  else
    st = parse_top(&c, root, t);
  if (st == WL_OK) {
    yaml_document_t extra;
    if (yaml_parser_load(&parser, &extra)) {
      yaml_node_t *r2 = yaml_document_get_root_node(&extra);
      if (r2)
        st = wl_error_set(err, WL_EINPUT,
                          "%s:%d:%d: template: found a second YAML document; valid: one per file",
                          path, (int)r2->start_mark.line + 1, (int)r2->start_mark.column + 1);
      yaml_document_delete(&extra);
    } else {
      st = wl_error_set(err, WL_EINPUT, "%s:%d:%d: malformed YAML after the template: %s", path,
                        (int)parser.problem_mark.line + 1, (int)parser.problem_mark.column + 1,
                        parser.problem ? parser.problem : "syntax error");
    }
  }
  yaml_document_delete(&doc);
  yaml_parser_delete(&parser);
  if (st != WL_OK) wl_report_template_clear(t);
  return st;
}

enum wl_status wl_report_template_load(const char *path, struct wl_report_template *t,
                                       struct wl_error *err) {
  wl_report_template_clear(t);
  FILE *f = fopen(path, "rb");
  if (!f) /* a file the user named */
    return wl_error_set(err, WL_EINPUT, "%s: cannot open the report template: %s", path,
                        strerror(errno));
  char *buf = malloc(TEMPLATE_MAX_BYTES + 1);
  if (!buf) {
    fclose(f);
    return wl_error_set(err, WL_ENOMEM, "%s: no memory to read the template", path);
  }
  size_t len = fread(buf, 1, TEMPLATE_MAX_BYTES + 1, f);
  int read_error = ferror(f);
  fclose(f);
  enum wl_status st;
  if (read_error)
    st = wl_error_set(err, WL_EIO, "%s: read error", path);
  else if (len > TEMPLATE_MAX_BYTES)
    st = wl_error_set(err, WL_EINPUT, "%s: larger than %d bytes; not a report template", path,
                      TEMPLATE_MAX_BYTES);
  else
    st = wl_report_template_parse(path, buf, len, t, err);
  free(buf);
  return st;
}
