/*
** css.h -- style sheets of <style> elements: a small CSS parser (rules,
** selectors, declarations of the reader's properties; CSS Syntax 3's
** error recovery) and a matcher over the open elements (the stream's
** frames), with the cascade's order (CSS Cascade 4 section 6; SVG 2
** section 6.3: presentation attributes below every rule, style="" above).
*/
#ifndef ARCLEN_SVGDOC_CSS_H
#define ARCLEN_SVGDOC_CSS_H

#include <stddef.h>

#include "svgdoc/internal.h"

/* Caps: a hostile sheet is cut, never slow. */
#define SVGDOC_MAX_CSS_BYTES (4u << 20)     /* sheet text per document */
#define SVGDOC_MAX_CSS_SELECTORS 65536      /* selectors (lists split) */
#define SVGDOC_MAX_CSS_DECLS 262144         /* declarations kept */
#define SVGDOC_MAX_CSS_COMPOUNDS 32         /* compounds per selector */
#define SVGDOC_MAX_CSS_SIMPLES 32           /* simple selectors per compound */
#define SVGDOC_MAX_CSS_NESTING 8            /* @media inside @media */
/* Compound tests per document: this many, and as many more per byte of
** the document read so far (a normal sheet costs a few tests a byte: the
** cap keeps a hostile one linear in the input, never a hang). */
#define SVGDOC_MAX_CSS_TESTS 200000000.0
#define SVGDOC_CSS_TESTS_PER_BYTE 200.0

/* What the matcher knows of an open element (the stream keeps one per
** frame, copied into the open element's pool). */
typedef struct svgdoc_css_node {
  const char *tag, *id, *cls;
  const char **atts;             /* name/value pairs, NULL-ended */
  int first_child;
  unsigned long children;        /* element children started so far */
} svgdoc_css_node;

/* The sheets' winning declarations of one element, per property: the
** normal and the !important one (NULL: none). */
typedef struct svgdoc_css_match {
  const char *normal[SVGDOC_NPROPS], *important[SVGDOC_NPROPS];
} svgdoc_css_match;

/* Parse the text of a <style> element (line, col: its place, for
** warnings) into the document's sheet; media: its media attribute. */
void svgdoc_css_add(svgdoc *D, const char *text, size_t n, const char *media,
                    unsigned long line, unsigned long col);
/* Does the document have a rule yet? */
int svgdoc_css_any(const svgdoc *D);
/* The rules matching the open element D->nodes[depth] (its ancestors
** D->nodes[0 .. depth-1]) into m. */
void svgdoc_css_match_node(svgdoc *D, size_t depth, unsigned long line,
                           unsigned long col, svgdoc_css_match *m);
/* m as extra attributes ("\1n:" or "\1i:" and the property's name) after
** the n attributes of a (room for 4 * SVGDOC_NPROPS + 1 more); the new
** count. */
size_t svgdoc_css_store(svgdoc *D, const svgdoc_css_match *m,
                        const char **a, size_t n);
/* The declarations an element kept for <use> was given where it was
** read (svgdoc_css_store), or, live, those matching it now. */
void svgdoc_css_for(svgdoc *D, const char **atts, int live, size_t depth,
                    unsigned long line, unsigned long col,
                    svgdoc_css_match *m);
/* The open element at depth (its local name, expat's attributes) as the
** matcher sees it, copied into the open element's pool. */
void svgdoc_css_open(svgdoc *D, size_t depth, const char *tag,
                     const char **atts);
/* The element at depth ends (every opened one must). */
void svgdoc_css_close(svgdoc *D, size_t depth);
/* A <style> element's start at depth, its text, its end. */
void svgdoc_css_style_start(svgdoc *D, const char **atts, size_t depth,
                            unsigned long line, unsigned long col);
void svgdoc_css_text(svgdoc *D, const char *s, size_t n);
void svgdoc_css_style_end(svgdoc *D, size_t depth);
void svgdoc_css_free(svgdoc *D);

#endif
