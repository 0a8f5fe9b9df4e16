/* cases.c: the cases of a sweep, each the sweep's own scenario text with the
 * swept values written in place (sweep.h says why text, not parsed values:
 * the case is then exactly what `wallload assess` would run alone). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "sweep_private.h"

void wl_sweep_init(struct wl_sweep *sw) { memset(sw, 0, sizeof *sw); }

void wl_sweep_clear(struct wl_sweep *sw) {
  if (!sw) return;
  for (int i = 0; sw->cases && i < sw->n_cases; i++) free(sw->cases[i].text);
  free(sw->cases);
  free(sw->rows);
  memset(sw, 0, sizeof *sw);
}

/* ---- finding the keys to edit --------------------------------------------- */

/* Byte offset of character `index` of text: libyaml's marks count
 * characters, and a scenario may hold UTF-8 (a description). */
static size_t byte_of(const char *text, size_t len, size_t index) {
  size_t b = 0, ch = 0;
  while (b < len && ch < index) {
    b++;
    while (b < len && ((unsigned char)text[b] & 0xC0) == 0x80) b++; /* continuation bytes */
    ch++;
  }
  return b;
}

/* The value (and key) node of `name` in mapping node `map`; NULL if absent. */
static yaml_node_t *map_get(yaml_document_t *doc, yaml_node_t *map, const char *name,
                            yaml_node_t **key) {
  if (!map || map->type != YAML_MAPPING_NODE) return NULL;
  for (yaml_node_pair_t *p = map->data.mapping.pairs.start; p < map->data.mapping.pairs.top; p++) {
    yaml_node_t *k = yaml_document_get_node(doc, p->key);
    if (k && k->type == YAML_SCALAR_NODE && !strcmp((const char *)k->data.scalar.value, name)) {
      if (key) *key = k;
      return yaml_document_get_node(doc, p->value);
    }
  }
  return NULL;
}

/* Where each swept key's text is, as byte ranges of the sweep's text. */
struct span {
  size_t from, to; /* [from, to); from == to: absent */
};
struct places {
  struct span depth, solitary_height, at, source_key, source_value;
  const char *source; /* "charge" or "energy": the explosion's source key as written */
  int sweep_first_line, sweep_last_line; /* 0-based lines of the sweep section */
};

static struct span span_of(const char *text, size_t len, const yaml_node_t *n) {
  struct span s = {0, 0};
  if (n && n->type == YAML_SCALAR_NODE) {
    s.from = byte_of(text, len, n->start_mark.index);
    s.to = byte_of(text, len, n->end_mark.index);
  }
  return s;
}

static enum wl_status find_places(const struct wl_scenario *s, struct places *pl,
                                  struct wl_error *err) {
  memset(pl, 0, sizeof *pl);
  yaml_parser_t parser;
  yaml_document_t doc;
  if (!yaml_parser_initialize(&parser))
    return wl_error_set(err, WL_ENOMEM, "%s: cannot initialise the YAML parser", s->path);
  yaml_parser_set_input_string(&parser, (const unsigned char *)s->text, s->text_len);
  if (!yaml_parser_load(&parser, &doc)) { /* cannot be: wl_scenario_parse read it */
    yaml_parser_delete(&parser);
    return wl_error_set(err, WL_EINPUT, "%s: malformed YAML", s->path);
  }
  enum wl_status st = WL_OK;
  yaml_node_t *root = yaml_document_get_root_node(&doc);
  const char *t = s->text;
  const size_t n = s->text_len;
  if (!root || root->type != YAML_MAPPING_NODE ||
      root->data.mapping.style == YAML_FLOW_MAPPING_STYLE) {
    st = wl_error_set(err, WL_EINPUT,
                      "%s:%d:%d: sweep: the scenario is written as one flow mapping ({...}); "
                      "expected its top-level keys one per line (block style), so that each "
                      "case can be written as the same file with its values in place",
                      s->path, s->sweep.line, s->sweep.col);
    goto done;
  }
  yaml_node_t *loads = map_get(&doc, root, "loads", NULL);
  pl->depth = span_of(t, n, map_get(&doc, map_get(&doc, root, "water", NULL), "depth", NULL));
  pl->solitary_height =
      span_of(t, n, map_get(&doc, map_get(&doc, loads, "solitary", NULL), "height", NULL));
  yaml_node_t *ex = map_get(&doc, loads, "explosion", NULL);
  pl->at = span_of(t, n, map_get(&doc, ex, "at", NULL));
  static const char *const sources[] = {"charge", "energy"};
  for (int i = 0; i < 2; i++) {
    yaml_node_t *key = NULL, *v = map_get(&doc, ex, sources[i], &key);
    if (v) {
      pl->source = sources[i];
      pl->source_key = span_of(t, n, key);
      pl->source_value = span_of(t, n, v);
    }
  }
  yaml_node_t *sweep_key = NULL, *sweep = map_get(&doc, root, "sweep", &sweep_key);
  pl->sweep_first_line = (int)sweep_key->start_mark.line;
  /* a block collection ends where the next token starts (the next key, at
   * column 0); a flow one, or a scalar, just after its last character */
  pl->sweep_last_line = (int)sweep->end_mark.line - (sweep->end_mark.column == 0 ? 1 : 0);
  if (pl->sweep_last_line < pl->sweep_first_line) pl->sweep_last_line = pl->sweep_first_line;
done:
  yaml_document_delete(&doc);
  yaml_parser_delete(&parser);
  return st;
}

/* ---- writing a case ----------------------------------------------------------- */

struct edit {
  size_t from, to;
  char text[160];
};

static int edit_cmp(const void *a, const void *b) {
  const struct edit *x = a, *y = b;
  return x->from < y->from ? 1 : x->from > y->from ? -1 : 0; /* last first */
}

/* A value as YAML text: plain when it is plainly a number and a unit, else
 * double-quoted (a unit written "kg/m^3" or a value with '#' stays one
 * scalar). */
static void yaml_scalar(const char *v, char *out, size_t size) {
  int plain = v[0] != '\0';
  for (const char *q = v; plain && *q; q++)
    plain = strchr(":#,[]{}&*!|>'\"%@`", *q) == NULL;
  if (plain) {
    snprintf(out, size, "%s", v);
    return;
  }
  size_t o = 0;
  if (o + 1 < size) out[o++] = '"';
  for (const char *q = v; *q && o + 3 < size; q++) {
    if (*q == '"' || *q == '\\') out[o++] = '\\';
    out[o++] = *q;
  }
  if (o + 1 < size) out[o++] = '"';
  out[o < size ? o : size - 1] = '\0';
}


/* The text of a case: text_of[p] is parameter p's value text (NULL: keep
 * the scenario's). Returns a malloc'ed text (length in *len) or NULL. */
static char *case_text(const struct wl_scenario *s, const struct places *pl,
                       const char *const text_of[WL_SWEEP_N_PARAMS], size_t *len) {
  struct edit ed[8];
  int n = 0;
  if (text_of[WL_SWEEP_DEPTH]) {
    ed[n].from = pl->depth.from, ed[n].to = pl->depth.to;
    yaml_scalar(text_of[WL_SWEEP_DEPTH], ed[n++].text, sizeof ed[0].text);
  }
  if (text_of[WL_SWEEP_SOLITARY_HEIGHT]) {
    ed[n].from = pl->solitary_height.from, ed[n].to = pl->solitary_height.to;
    yaml_scalar(text_of[WL_SWEEP_SOLITARY_HEIGHT], ed[n++].text, sizeof ed[0].text);
  }
  if (text_of[WL_SWEEP_STANDOFF]) {
    /* the explosion's position from the paddle, in SI (its value is the
     * standoff's, subtracted from the wall's position as the scenario reads it) */
    struct wl_quantity q;
    struct wl_error e;
    wl_error_clear(&e);
    if (wl_units_parse(text_of[WL_SWEEP_STANDOFF], WL_DIM_LENGTH, &q, &e) != WL_OK) return NULL;
    char num[40];
    wl_scenario_number_text(s->wall.x.q.si - q.si, num, sizeof num);
    ed[n].from = pl->at.from, ed[n].to = pl->at.to;
    snprintf(ed[n++].text, sizeof ed[0].text, "%s m", num);
  }
  for (int p = WL_SWEEP_CHARGE; p <= WL_SWEEP_ENERGY; p++) {
    if (!text_of[p]) continue;
    const char *key = p == WL_SWEEP_CHARGE ? "charge" : "energy";
    if (strcmp(pl->source, key)) { /* energy: same-as-solitary swept by charge: the key too */
      ed[n].from = pl->source_key.from, ed[n].to = pl->source_key.to;
      snprintf(ed[n++].text, sizeof ed[0].text, "%s", key);
    }
    ed[n].from = pl->source_value.from, ed[n].to = pl->source_value.to;
    yaml_scalar(text_of[p], ed[n++].text, sizeof ed[0].text);
  }
  /* the sweep section, commented out line for line */
  const char *t = s->text;
  const size_t tl = s->text_len;
  int line = 0;
  size_t n_comment = 0;
  for (size_t b = 0; b <= tl; b++) {
    if (line >= pl->sweep_first_line && line <= pl->sweep_last_line &&
        (b == 0 || t[b - 1] == '\n') && b < tl)
      n_comment++;
    if (b < tl && t[b] == '\n') line++;
  }
  struct edit *all = malloc(((size_t)n + n_comment) * sizeof *all);
  if (!all) return NULL;
  memcpy(all, ed, (size_t)n * sizeof *ed);
  size_t m = (size_t)n;
  line = 0;
  for (size_t b = 0; b < tl; b++) {
    if ((b == 0 || t[b - 1] == '\n') && line >= pl->sweep_first_line &&
        line <= pl->sweep_last_line) {
      all[m].from = all[m].to = b;
      snprintf(all[m++].text, sizeof all[0].text, "# ");
    }
    if (t[b] == '\n') line++;
  }
  qsort(all, m, sizeof *all, edit_cmp);
  size_t cap = tl + 1;
  for (size_t i = 0; i < m; i++) cap += strlen(all[i].text);
  char *out = malloc(cap);
  if (!out) {
    free(all);
    return NULL;
  }
  /* the edits, last first, into the text copied from the end */
  size_t o = cap - 1, tail = tl;
  out[o] = '\0';
  for (size_t i = 0; i < m; i++) {
    size_t keep = tail - all[i].to;
    o -= keep;
    memcpy(out + o, t + all[i].to, keep);
    size_t el = strlen(all[i].text);
    o -= el;
    memcpy(out + o, all[i].text, el);
    tail = all[i].from;
  }
  o -= tail;
  memcpy(out + o, t, tail);
  free(all);
  if (o) memmove(out, out + o, cap - o);
  *len = cap - 1 - o;
  return out;
}

/* ---- the sweep ------------------------------------------------------------------ */

/* A directory-name-safe form of a value ("0.5 g" -> "0.5g", "1/5.7" -> "1per5.7"). */
static void id_part(const char *name, const char *value, char *out, size_t size) {
  size_t o = (size_t)snprintf(out, size, "_%s", name);
  for (const char *q = value; *q && o + 4 < size; q++) {
    const char ch = *q;
    if ((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
        ch == '.' || ch == '+' || ch == '-')
      out[o++] = ch;
    else if (ch == '/')
      o += (size_t)snprintf(out + o, size - o, "per");
  }
  out[o < size ? o : size - 1] = '\0';
}

void wl_sweep_case_label(const struct wl_sweep *sw, int i, char *buf, size_t size) {
  buf[0] = '\0';
  for (int k = 0; k < sw->n_params; k++) {
    const enum wl_sweep_param p = sw->order[k];
    size_t u = strlen(buf);
    snprintf(buf + u, size - u, "%s%s = %s", k ? ", " : "", wl_scenario_sweep_param_name(p),
             sw->cases[i].value_text[p]);
  }
}

enum wl_status wl_sweep_case_scenario(const struct wl_sweep *sw, int i, struct wl_scenario *cs,
                                      struct wl_error *err) {
  wl_scenario_init(cs);
  return wl_scenario_parse(sw->path, sw->cases[i].text, sw->cases[i].len, cs, err);
}

/* Parse a case's text: does it make a valid scenario? */
static enum wl_status try_case(const char *path, const char *text, size_t len,
                               struct wl_error *err) {
  struct wl_scenario *cs = malloc(sizeof *cs);
  if (!cs) return wl_error_set(err, WL_ENOMEM, "%s: no memory for a sweep case", path);
  wl_scenario_init(cs);
  enum wl_status st = wl_scenario_parse(path, text, len, cs, err);
  if (st == WL_OK && cs->sweep.present) /* cannot be: its sweep section is commented out */
    st = wl_error_set(err, WL_EINPUT, "%s: a sweep case still has a sweep section", path);
  wl_scenario_clear(cs);
  free(cs);
  return st;
}

enum wl_status wl_sweep_make(const struct wl_scenario *s, struct wl_sweep *sw,
                             struct wl_error *err) {
  wl_sweep_clear(sw);
  if (!s->sweep.present || s->sweep.n_cases < 1)
    return wl_error_set(err, WL_EINPUT,
                        "%s: sweep: the scenario has no sweep section; expected one, e.g. "
                        "sweep: { charge: [0.5 g, 1 g], standoff: [4 m, 8 m] }",
                        s->path);
  snprintf(sw->path, sizeof sw->path, "%s", s->path);
  snprintf(sw->name, sizeof sw->name, "%s", s->name.text);
  sw->n_params = s->sweep.n_params;
  memcpy(sw->order, s->sweep.order, sizeof sw->order);
  sw->has_load[0] = s->solitary.present;
  sw->has_load[1] = s->explosion.present;
  struct places pl;
  enum wl_status st = find_places(s, &pl, err);
  if (st) return st;
  const char *text_of[WL_SWEEP_N_PARAMS] = {0};
  /* each value alone first, so that an invalid one is named */
  for (int k = 0; k < sw->n_params; k++) {
    const enum wl_sweep_param p = sw->order[k];
    const struct wl_scenario_sweep_axis *a = &s->sweep.axis[p];
    for (int j = 0; j < a->n_values; j++) {
      text_of[p] = a->values[j].text;
      size_t len;
      char *t = case_text(s, &pl, text_of, &len);
      text_of[p] = NULL;
      if (!t) return wl_error_set(err, WL_ENOMEM, "%s: no memory for a sweep case", s->path);
      struct wl_error e;
      wl_error_clear(&e);
      st = try_case(s->path, t, len, &e);
      free(t);
      if (st == WL_EINPUT)
        return wl_error_set(err, st, "%s:%d:%d: sweep.%s[%d]: '%s' gives an invalid scenario: %s",
                            s->path, a->values[j].line, a->values[j].col,
                            wl_scenario_sweep_param_name(p), j, a->values[j].text, e.msg);
      if (st) return wl_error_set(err, st, "%s", e.msg);
    }
  }
  sw->cases = calloc((size_t)s->sweep.n_cases, sizeof *sw->cases);
  sw->rows = calloc((size_t)s->sweep.n_cases, sizeof *sw->rows);
  if (!sw->cases || !sw->rows)
    return wl_error_set(err, WL_ENOMEM, "%s: no memory for %d sweep cases", s->path,
                        s->sweep.n_cases);
  sw->n_cases = s->sweep.n_cases;
  for (int i = 0; i < sw->n_cases; i++) {
    struct wl_sweep_case *c = &sw->cases[i];
    for (int p = 0; p < WL_SWEEP_N_PARAMS; p++) c->value[p] = NAN;
    snprintf(c->id, sizeof c->id, "%03d", i);
    /* row-major: the first parameter written varies slowest */
    int rest = i;
    int idx[WL_SWEEP_N_PARAMS];
    for (int k = sw->n_params - 1; k >= 0; k--) {
      const int nv = s->sweep.axis[sw->order[k]].n_values;
      idx[k] = rest % nv;
      rest /= nv;
    }
    for (int k = 0; k < sw->n_params; k++) {
      const enum wl_sweep_param p = sw->order[k];
      const struct wl_scenario_value *v = &s->sweep.axis[p].values[idx[k]];
      snprintf(c->value_text[p], sizeof c->value_text[p], "%s", v->text);
      c->value[p] = v->q.si;
      text_of[p] = v->text;
      char part[64];
      id_part(wl_scenario_sweep_param_name(p), v->text, part, sizeof part);
      size_t u = strlen(c->id);
      snprintf(c->id + u, sizeof c->id - u, "%s", part);
    }
    c->text = case_text(s, &pl, text_of, &c->len);
    if (!c->text) return wl_error_set(err, WL_ENOMEM, "%s: no memory for a sweep case", s->path);
    struct wl_error e;
    wl_error_clear(&e);
    st = try_case(s->path, c->text, c->len, &e);
    if (st == WL_EINPUT) {
      char label[512];
      wl_sweep_case_label(sw, i, label, sizeof label);
      return wl_error_set(err, st,
                          "%s:%d:%d: sweep: case %d (%s) gives an invalid scenario, although each "
                          "of its values alone does not: %s",
                          s->path, s->sweep.line, s->sweep.col, i, label, e.msg);
    }
    if (st) return wl_error_set(err, st, "%s", e.msg);
  }
  return WL_OK;
}
