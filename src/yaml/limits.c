/* limits.c: the YAML reader limits (yaml_limits.h). */
#include "wallload/yaml_limits.h"

#include <yaml.h>

enum wl_status wl_yaml_check_limits(const char *path, const char *text, size_t len,
                                    int max_depth, int max_anchors, const char *hint,
                                    struct wl_error *err) {
  /* Events, not a document: the scanner reads ahead of the parser only
   * while a simple key is possible (one line, 1024 characters), so
   * stopping at the first excess bounds the work however deep the text
   * goes on. (libyaml's loader checks each new anchor against all the
   * document's earlier ones, and looks each alias up the same way.) */
  yaml_parser_t parser;
  if (!yaml_parser_initialize(&parser))
    return wl_error_set(err, WL_ENOMEM, "%s: cannot initialise the YAML parser", path);
  yaml_parser_set_input_string(&parser, (const unsigned char *)text, len);
  enum wl_status st = WL_OK;
  int depth = 0, anchors = 0, done = 0;
  while (!done && st == WL_OK) {
    yaml_event_t ev;
    if (!yaml_parser_parse(&parser, &ev)) break; /* malformed: the loader says where */
    const int line = (int)ev.start_mark.line + 1, col = (int)ev.start_mark.column + 1;
    const yaml_char_t *anchor = NULL;
    switch (ev.type) {
    case YAML_DOCUMENT_START_EVENT: anchors = 0; break;
    case YAML_SEQUENCE_START_EVENT:
      anchor = ev.data.sequence_start.anchor;
      depth++;
      break;
    case YAML_MAPPING_START_EVENT:
      anchor = ev.data.mapping_start.anchor;
      depth++;
      break;
    case YAML_SCALAR_EVENT: anchor = ev.data.scalar.anchor; break;
    case YAML_SEQUENCE_END_EVENT:
    case YAML_MAPPING_END_EVENT: depth--; break;
    case YAML_STREAM_END_EVENT: done = 1; break;
    default: break;
    }
    if (anchor && ++anchors > max_anchors)
      st = wl_error_set(err, WL_EINPUT,
                        "%s:%d:%d: YAML with more than %d anchors (&name) in one document; the "
                        "reader's cost grows with their square",
                        path, line, col, max_anchors);
    else if (depth > max_depth)
      st = wl_error_set(err, WL_EINPUT, "%s:%d:%d: YAML nested deeper than %d levels%s%s", path,
                        line, col, max_depth, hint && hint[0] ? "; " : "", hint ? hint : "");
    yaml_event_delete(&ev);
  }
  yaml_parser_delete(&parser);
  return st;
}
