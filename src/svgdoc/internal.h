/*
** internal.h -- what the files of the svgdoc area share: the reader's
** state, located errors (a longjmp back to the expat callback that
** started the work, never across expat's own frames), the string pool,
** and the 2x3 matrices.
*/
#ifndef ARCLEN_SVGDOC_INTERNAL_H
#define ARCLEN_SVGDOC_INTERNAL_H

#include <setjmp.h>
#include <stddef.h>

#include "svgdoc/svgdoc.h"

/* SVG's matrix(a b c d e f) is {a, b, c, d, e, f}. */
typedef double svgdoc_matrix[6];

/* The viewport's size in the current user units (SVG 2 section 8.9), and
** the font sizes em and rem are relative to (CSS Values 3 section 6.1):
** what lengths are resolved against. */
typedef struct svgdoc_viewport {
  int has;
  double w, h;
  double em, rem;            /* the element's and the root's font-size */
} svgdoc_viewport;

/* The properties the reader uses, cascaded from the presentation
** attributes, style sheets and style="" (css.c), trimmed and lower-cased.
** The paint's (fill ... color) decide what shows (paint.c). */
enum { SVGDOC_DISPLAY, SVGDOC_VISIBILITY, SVGDOC_STROKE,
       SVGDOC_STROKE_WIDTH, SVGDOC_FILL, SVGDOC_FILL_OPACITY,
       SVGDOC_STROKE_OPACITY, SVGDOC_OPACITY, SVGDOC_COLOR, SVGDOC_FONT_SIZE,
       SVGDOC_MARKER_START, SVGDOC_MARKER_MID, SVGDOC_MARKER_END,
       SVGDOC_OVERFLOW, SVGDOC_NPROPS };
/* The marker properties keep their case (url(#Id): ids are case-sensitive);
** the shorthand `marker` sets all three in sheets and style="" only (it
** is no presentation attribute: SVG 2 section 11.6.3). */
#define SVGDOC_CASED_PROP(k) ((k) >= SVGDOC_MARKER_START && (k) <= SVGDOC_MARKER_END)

typedef struct svgdoc_buffer {
  char *s;
  size_t len, room;
} svgdoc_buffer;

/* Memory in blocks, handed out in order: the document's own (what <use>
** can still reference, warnings: freed with it), and the open elements'
** (layer names, shape data, messages: given back when the element that
** made them ends, so that what a stream keeps does not grow with it). */
typedef struct svgdoc_block svgdoc_block;
typedef struct svgdoc_arena {
  svgdoc_block *blocks;                  /* the newest first */
  char *at;
  size_t left;
} svgdoc_arena;
typedef svgdoc_arena svgdoc_mark;        /* a point to give back to */

typedef struct svgdoc_held svgdoc_held;  /* elements behind a forward use */
struct svgdoc_css;                       /* the style sheets (css.c) */
struct svgdoc_css_node;
struct svgdoc_css_match;
typedef struct svgdoc_event svgdoc_event;

/* ids -> the index of a kept event (or a set of ids: values unused). */
typedef struct svgdoc_idtable {
  const char **keys;
  size_t *vals, room, n;
} svgdoc_idtable;

struct svgdoc {
  svgdoc_options o;
  char *lang;                            /* o.lang copied (cond.c) */
  void *parser;                          /* XML_Parser */
  jmp_buf *on_error;                     /* where svgdoc_fail jumps */
  int failed, finished, scanned;
  unsigned long err_line, err_col;
  char *err_msg;
  svgdoc_arena keep, tmp;                /* the pools (memory.c) */
  svgdoc_arena *arena;                   /* where svgdoc_alloc takes from */
  svgdoc_block *spare;                   /* a tmp block given back */
  /* the streaming pass */
  struct svgdoc_frame *stack;            /* max_depth + 1 frames */
  struct svgdoc_frame *xstacks[SVGDOC_MAX_USE_DEPTH + 1];  /* for <use> */
  size_t depth;                          /* open elements */
  int root_seen, record, draining;
  size_t rec;                            /* depth inside kept subtrees */
  size_t *open_ev;                       /* the kept event of each */
  size_t bytes, nentities, ngroups, replayed, mreplayed;
  /* kept subtrees, for <use> */
  svgdoc_event *events;
  size_t nevents, events_room;
  svgdoc_idtable ids;                    /* id -> first event with it */
  /* the ids <use> refers to, from svgdoc_scan (refs_given: only those
  ** subtrees are kept) */
  svgdoc_idtable refs;
  int refs_given;
  /* every id of the document, when the scan read all of it (idbloom.c) */
  unsigned char *id_bloom;
  int ids_known, scan_lost;
  void *scanner;                         /* XML_Parser of svgdoc_scan */
  /* elements and uses waiting behind a <use> whose target is not read
  ** yet (a queue from held_head), and the id it waits for */
  svgdoc_held *held_q;
  size_t held_head, held_tail, held_room, held_elements;
  const char *waiting;
  size_t waiting_len;
  struct svgdoc_use *expanding_use;      /* taken from the queue (freed) */
  /* results: the elements of this feed (stream) or all (collect) */
  svgdoc_element **batch;
  size_t nbatch, batch_room, ndrawn;
  svgdoc_warning *warnings;
  size_t nwarnings;
  size_t skipped[SVGDOC_NSKIPPED];
  svgdoc_info info;
  svgdoc_buffer props[SVGDOC_NPROPS], scratch;
  svgdoc_buffer marker_buf;              /* a shape's vertices (marker.c) */
  /* style sheets (css.c): the rules, the open elements as selectors see
  ** them (max_depth + 2), the <style> being read (its depth + 1) */
  struct svgdoc_css *css;
  struct svgdoc_css_node *nodes;
  size_t style_depth, shapes_seen, shapes_before;
  unsigned long style_line, style_col;
  svgdoc_buffer style_text, style_media;
  int style_has_media;
  /* the segments of the element being drawn (reader.c, draw): copied into
  ** the element's block, the arrays kept for the next */
  arclen_pathdata draw_pd;
  /* input held back while expat has an unfinished token (reader.c) */
  svgdoc_buffer held;
  size_t held_need;
};

/* ---- memory and errors (memory.c) ---- */

/* The formats below use only C89's conversions (sizes as %lu of an
** unsigned long): MinGW checks them as msvcrt's printf, which has no %zu,
** and that is the printf that runs there. */

/* A located error: the message, then a jump to D->on_error. */
#if defined(__GNUC__)
__attribute__((noreturn, format(printf, 4, 5)))
#endif
void svgdoc_fail(svgdoc *D, unsigned long line, unsigned long col,
                 const char *fmt, ...);
void svgdoc_nomem(svgdoc *D);
/* The error without the jump (msg malloc'd; NULL: "not enough memory"). */
void svgdoc_set_error(svgdoc *D, unsigned long line, unsigned long col,
                      char *msg);
void svgdoc_free_pool(svgdoc *D);

/* Memory from D->arena (the open element's unless switched to D->keep);
** never NULL (fails). */
void *svgdoc_alloc(svgdoc *D, size_t n);
/* The tmp pool's point now, and everything taken from it since given back. */
void svgdoc_mark_get(const svgdoc *D, svgdoc_mark *m);
void svgdoc_release(svgdoc *D, const svgdoc_mark *m);
char *svgdoc_strdup(svgdoc *D, const char *s, size_t n);
/* A string formatted with malloc (NULL without memory), for the messages
** that outlive a failed document. */
char *svgdoc_message(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* A string formatted into the pool. */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
char *svgdoc_format(svgdoc *D, const char *fmt, ...);
/* b's room grown to n bytes (fails without memory). */
void svgdoc_reserve(svgdoc *D, svgdoc_buffer *b, size_t n);
void svgdoc_append(svgdoc *D, svgdoc_buffer *b, const char *s, size_t n);

/* ---- attributes (attrs.c) ---- */

/* The value of attribute name among expat's name/value pairs, or NULL. */
const char *svgdoc_attr(const char **atts, const char *name);

/* Is s empty or only whitespace?  (Whitespace is C's isspace in the C
** locale, as Lua's %s and the number scanner of svg/decimal.c take it.) */
int svgdoc_blank(const char *s);
/* Is c whitespace so?  (Inline: every area of the reader asks.) */
static inline int svgdoc_space(unsigned char c) {
  return c == ' ' || (c >= '\t' && c <= '\r');   /* \t \n \v \f \r */
}

/* %.17g of x in any locale (shapes and messages write numbers so). */
void svgdoc_num(char buf[32], double x);
/* v, or a located error "what must not be negative (v)". */
double svgdoc_nonneg(svgdoc *D, unsigned long line, unsigned long col,
                     double v, const char *what);
/* A negative length of an element (v < 0): invalid, so a renderer takes
** it as not given (SVG 2: a property's invalid value is ignored;
** web-platform-tests' circle-006, ellipse-006, rect-007) -- the warning
** "<tag>: name must not be negative (v); consequence", an error under
** o.strict.  1 when negative. */
int svgdoc_negative(svgdoc *D, unsigned long line, unsigned long col,
                    const char *tag, const char *name, double v,
                    const char *consequence);

/* A <length> (SVG 2 section 4.3) in user units; kind 'x', 'y' or 'o' for
** percentages of vp.  what: the attribute's name for messages. */
double svgdoc_length(svgdoc *D, unsigned long line, unsigned long col,
                     const char *s, int kind, const svgdoc_viewport *vp,
                     const char *what);
/* Attribute name as a length into *v; 0 (v untouched) when absent or
** blank. */
int svgdoc_len_attr(svgdoc *D, unsigned long line, unsigned long col,
                    const char **atts, const char *name, int kind,
                    const svgdoc_viewport *vp, double *v);

/* The transform attribute as one matrix (SVG 1.1 section 7.6). */
void svgdoc_transform(svgdoc *D, unsigned long line, unsigned long col,
                      const char *s, svgdoc_matrix T);
/* viewBox into vb; 0 when absent or blank. */
int svgdoc_viewbox(svgdoc *D, unsigned long line, unsigned long col,
                   const char *s, double vb[4]);
/* The viewBox vb onto the viewport (ex, ey, ew, eh) under
** preserveAspectRatio par (NULL: the default) (SVG 2 section 8.2). */
void svgdoc_viewbox_matrix(svgdoc *D, unsigned long line, unsigned long col,
                           const double vb[4], const char *par, double ex,
                           double ey, double ew, double eh, svgdoc_matrix M);
/* The reader's properties of an element, cascaded (SVG 2 section 6.3,
** CSS Cascade 4 section 6): style="" !important, the sheets' !important
** (sheet), style="", the sheets' normal ones, the presentation attribute;
** the strongest valid one, an invalid one warned of (at line, col) and
** passed over; out[k] NULL when none is given. */
void svgdoc_properties(svgdoc *D, unsigned long line, unsigned long col,
                       const char **atts, const struct svgdoc_css_match *sheet,
                       const char *out[]);
/* Is s (trimmed, lower-case) a valid value of property k?  CSS drops an
** invalid declaration (CSS Syntax 3 section 5), the cascade passes it over. */
int svgdoc_prop_valid(int k, const char *s);
/* The index of property name in the reader's list, or -1; its name. */
int svgdoc_prop_index(const char *name);
const char *svgdoc_prop_name(int k);
/* The computed font-size (px) of value s (NULL: inherited) under a parent
** whose font-size is em, the root's rem (CSS Fonts 4 section 2.5); s
** is valid (svgdoc_properties); one that overflows is warned of and
** inherited. */
double svgdoc_font_size(svgdoc *D, unsigned long line, unsigned long col,
                        const char *s, double em, double rem);
/* s as a length (as svgdoc_length) into *v; 0 when it is not one (no
** error: for properties, where CSS ignores an invalid value). */
int svgdoc_length_try(const char *s, int kind, const svgdoc_viewport *vp,
                      double *v);
/* A warning at a place, an error under o.strict (memory.c). */
void svgdoc_warn(svgdoc *D, unsigned long line, unsigned long col,
                 const char *msg);
/* What a renderer passes over: the warning "what; consequence", the error
** "what" under o.strict (memory.c). */
void svgdoc_lenient(svgdoc *D, unsigned long line, unsigned long col,
                    const char *what, const char *consequence);

/* ---- the ids of the scan (idbloom.c) ---- */

/* id s[0 .. n-1] into the filter (0, or -1 without memory); server: the
** id of a paint server (linearGradient, radialGradient, pattern). */
int svgdoc_bloom_add(svgdoc *D, const char *s, size_t n, int server);
/* Is it certain that no element (server: no paint server) has that id
** (the scan saw them all)? */
int svgdoc_bloom_absent(const svgdoc *D, const char *s, size_t n, int server);

/* ---- shapes (shapes.c) ---- */

/* The shape of a drawn element (tag, atts) in its own coordinates into
** *s (its numbers in the pool); 0 when it is not rendered (SVG 2 chapter
** 10: a zero width, radius, no points). */
int svgdoc_shape_get(svgdoc *D, unsigned long line, unsigned long col,
                     const char *tag, const char **atts,
                     const svgdoc_viewport *vp, svgdoc_shape *s);
/* s's path data (svgdoc_shape_d) into the pool; a path's d as it is. */
const char *svgdoc_shape_text(svgdoc *D, const svgdoc_shape *s);
/* The segments of s into pd (initialised) under T (NULL: the identity), as
** the document's arcs option says: a basic shape built from its numbers,
** the same records as its text would give (the text is parsed instead when
** a number is beyond the doubles, or the builder fails, so that the error
** is the text's); returns arclen_pathdata_parse's result, and on an error
** sets *d to the path data the error's position refers to. */
int svgdoc_shape_parse(svgdoc *D, arclen_pathdata *pd, const svgdoc_shape *s,
                       const double *T, const char **d);

/* ---- matrices ---- */

/* P Q (Q applied first): a child's CTM is its parent's times its own. */
static inline void svgdoc_mul(const svgdoc_matrix P, const svgdoc_matrix Q,
                              svgdoc_matrix R) {
  double r0 = P[0] * Q[0] + P[2] * Q[1], r1 = P[1] * Q[0] + P[3] * Q[1];
  double r2 = P[0] * Q[2] + P[2] * Q[3], r3 = P[1] * Q[2] + P[3] * Q[3];
  double r4 = P[0] * Q[4] + P[2] * Q[5] + P[4];
  double r5 = P[1] * Q[4] + P[3] * Q[5] + P[5];
  R[0] = r0, R[1] = r1, R[2] = r2, R[3] = r3, R[4] = r4, R[5] = r5;
}

static inline void svgdoc_translate(double tx, double ty, svgdoc_matrix R) {
  R[0] = 1, R[1] = 0, R[2] = 0, R[3] = 1, R[4] = tx, R[5] = ty;
}

#endif
