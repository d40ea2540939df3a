/*
** svgdoc.h -- SVG documents read as a renderer draws them: expat's
** events walked in C, every basic shape turned into segments (SVG 2
** chapter 10), nested transforms and viewports applied, <use> expanded,
** each drawn element's path data read into segments (svg/pathdata.c) in
** document coordinates, handed over as soon as it is complete (a stream:
** what is kept is the open elements' frames, the subtrees <use> can
** still reference, and the elements waiting behind a <use> of an element
** not read yet).  No Lua dependency; the binding is lua/svgdoc.c.
** doc/svg.md lists the semantic choices.
*/
#ifndef ARCLEN_SVGDOC_H
#define ARCLEN_SVGDOC_H

#include <stddef.h>

#include "svg/pathdata.h"

/* Caps: every loop and recursion has one. */
#define SVGDOC_MAX_DEPTH 1000          /* element nesting */
#define SVGDOC_MAX_USE_DEPTH 64        /* <use> inside used content */
#define SVGDOC_MAX_ELEMENTS 1000000    /* drawn elements collected (not stream) */
#define SVGDOC_MAX_HELD 1000000        /* drawn elements behind a forward use */
#define SVGDOC_MAX_REPLAYED 250000     /* events replayed by <use> */
#define SVGDOC_MAX_MARKER_REPLAYED 4000000L  /* events replayed by markers */
#define SVGDOC_MAX_ENTITIES 1000       /* entity declarations */
#define SVGDOC_MAX_ENTITY_LEN 65536    /* an entity's replacement text */
#define SVGDOC_MAX_WARNINGS 1000

typedef struct svgdoc_options {
  double arc_tol;       /* arcs' tolerance, relative to their size (cubics) */
  int arcs;             /* ARCLEN_PD_ARCS_CONICS (0): the segments' kinds as
                        ** drawn, circles, ellipses and rounded corners as
                        ** conics; ARCLEN_PD_ARCS_CUBICS: cubics only */
  double unit_px;       /* px per output unit; 0: the root's user units */
  int hidden;           /* draw display:none and visibility:hidden too */
  int stroked;          /* only shapes whose stroke paints (paint.c) */
  int painted;          /* only shapes whose stroke or fill paints (stroked
                        ** wins when both are set) */
  const char *lang;     /* user languages for systemLanguage, a comma-
                        ** separated list (NULL: "en"; copied) */
  int max_depth;        /* in [1, SVGDOC_MAX_DEPTH] */
  int uses;             /* the document may contain <use>: keep subtrees */
  int stream;           /* hand the elements over per feed, keep none */
  size_t max_held;      /* behind a forward use; 0: SVGDOC_MAX_HELD */
  int shape_text;       /* for the specs: basic shapes written as path data
                        ** and that parsed, the builder's reference */
  int strict;           /* warnings are errors (a missing reference, an
                        ** error in path data: doc/svg.md) */
} svgdoc_options;

/* What a drawn element is drawn of: a path's d as written, or a basic
** shape's own numbers (SVG 2 chapter 10, after its auto and clamping
** rules), which the reader builds into segments without a text between;
** svgdoc_shape_d writes them as path data when that is asked for. */
enum { SVGDOC_SHAPE_PATH, SVGDOC_SHAPE_RECT, SVGDOC_SHAPE_ELLIPSE,
       SVGDOC_SHAPE_LINE, SVGDOC_SHAPE_POLYLINE, SVGDOC_SHAPE_POLYGON };
typedef struct svgdoc_shape {
  int kind;             /* SVGDOC_SHAPE_* */
  const char *d;        /* PATH: the d attribute; otherwise NULL */
  size_t n;             /* the numbers: RECT x y width height rx ry (rx or
                        ** ry 0: square corners); ELLIPSE (circle too) cx cy
                        ** rx ry; LINE x1 y1 x2 y2; POLYLINE, POLYGON the
                        ** points' x y pairs */
  const double *v;
} svgdoc_shape;

/* The path data of s, as the reader has always written it (SVG 2 chapter
** 10's commands, numbers in 17 significant digits, any locale), handed to
** put(ctx, bytes, n) in pieces; a path's d as it is. */
void svgdoc_shape_d(const svgdoc_shape *s,
                    void (*put)(void *ctx, const char *bytes, size_t n),
                    void *ctx);

/* A drawn element.  Its strings live with it (NULL: none). */
typedef struct svgdoc_element {
  const char *id, *tag, *layer;
  const char *use;      /* the id a <use> instantiated this from */
  const char *marker;   /* the id of the <marker> whose content this is */
  svgdoc_shape shape;   /* what it is drawn of, in its own coordinates */
  unsigned long line, col;
  int stroked, filled;  /* its stroke, its fill paints something */
  double ctm[6];        /* onto the document's coordinates */
  arclen_pathdata pd;   /* the segments of shape mapped by ctm */
} svgdoc_element;

typedef struct svgdoc_warning {
  unsigned long line, col;
  const char *msg;
} svgdoc_warning;

/* The tags counted as rendered but not measured (text, image...). */
#define SVGDOC_NSKIPPED 8
extern const char *const svgdoc_skipped_tags[SVGDOC_NSKIPPED];

typedef struct svgdoc svgdoc;

/* A reader for one document (NULL without memory). */
svgdoc *svgdoc_new(const svgdoc_options *o);
void svgdoc_free(svgdoc *D);

/* Optional, before the first feed: the whole document once, in pieces,
** to learn the ids <use> elements refer to; then only the subtrees of
** those ids are kept (without a scan, every subtree with an id is, when
** o->uses).  Errors are left to the reading proper. */
void svgdoc_scan(svgdoc *D, const char *s, size_t n);

/* Feed the next n bytes; then svgdoc_finish once.  Both return 0, or -1
** with the error in svgdoc_error (later calls return -1 again). */
int svgdoc_feed(svgdoc *D, const char *s, size_t n);
int svgdoc_finish(svgdoc *D);
const char *svgdoc_error(const svgdoc *D, unsigned long *line,
                         unsigned long *col);

/* The drawn elements, uses expanded, in document order.  o->stream: those
** completed by the last feed or finish (valid until the next call);
** otherwise all of them, after a successful svgdoc_finish. */
size_t svgdoc_count(const svgdoc *D);
const svgdoc_element *svgdoc_get(const svgdoc *D, size_t i);
size_t svgdoc_drawn(const svgdoc *D);    /* all handed over so far */
int svgdoc_streaming(const svgdoc *D);   /* o->stream */
size_t svgdoc_nwarnings(const svgdoc *D);
const svgdoc_warning *svgdoc_warning_at(const svgdoc *D, size_t i);
const size_t *svgdoc_skipped(const svgdoc *D);      /* SVGDOC_NSKIPPED */
size_t svgdoc_kept(const svgdoc *D);  /* events kept for <use> */

/* The root's width and height (user units; has_* 0 when absent or a
** percentage) and viewBox (has_viewbox 0 when absent). */
typedef struct svgdoc_info {
  int has_width, has_height, has_viewbox;
  double width, height, viewbox[4];
} svgdoc_info;
const svgdoc_info *svgdoc_root_info(const svgdoc *D);

#endif
