/* yaml_limits.h: the reader limits of every YAML file wallload reads
 * (scenarios, report templates), checked before libyaml builds a document:
 * libyaml's loader has no nesting limit, and its cost grows with the square
 * of the nesting depth and of the number of anchors. */
#ifndef WALLLOAD_YAML_LIMITS_H
#define WALLLOAD_YAML_LIMITS_H

#include <stddef.h>

#include "wallload/error.h"

/* What a wallload YAML file may hold at most: collections nested this deep
 * (a scenario needs 3, a report template 4), anchors in one document. */
#define WL_YAML_MAX_DEPTH 64
#define WL_YAML_MAX_ANCHORS 256

/* WL_OK unless the YAML text nests collections (flow or block, in any of
 * its documents) deeper than max_depth, or one of its documents has more
 * than max_anchors anchors (&name): then WL_EINPUT, "PATH:LINE:COL: YAML
 * nested deeper than N levels; HINT" at the collection that goes one level
 * too deep, or "PATH:LINE:COL: YAML with more than N anchors ..." at the
 * anchor one too many. Malformed YAML is not judged here (WL_OK: the
 * loader reports it). One pass of libyaml's event parser, stopped at the
 * first excess, so its cost stays linear in the text; for any YAML read
 * with yaml_parser_load (report templates too). */
enum wl_status wl_yaml_check_limits(const char *path, const char *text, size_t len,
                                    int max_depth, int max_anchors, const char *hint,
                                    struct wl_error *err);

#endif
