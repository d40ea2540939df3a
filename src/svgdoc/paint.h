/*
** paint.h -- what the reader needs to know of an element's paint: does
** its stroke, does its fill, show anything?  The inherited properties
** (fill, stroke, their opacities, stroke-width, color) and the group
** opacity, folded into a few flags per frame (paint.c).
*/
#ifndef ARCLEN_SVGDOC_PAINT_H
#define ARCLEN_SVGDOC_PAINT_H

/* A fill or stroke, as far as showing goes. */
enum { SVGDOC_PAINT_NONE,      /* none, or a colour of alpha 0 */
       SVGDOC_PAINT_SHOWN,     /* a colour of alpha > 0, a paint server */
       SVGDOC_PAINT_CURRENT }; /* currentColor: the element's color decides */

typedef struct svgdoc_paint {
  unsigned char fill, stroke;          /* SVGDOC_PAINT_* */
  unsigned char color_clear;           /* color has alpha 0 */
  unsigned char fill_clear, stroke_clear;   /* fill-/stroke-opacity 0 */
  unsigned char width_zero;            /* stroke-width 0 */
  unsigned char opacity_zero;          /* opacity 0 here or on an ancestor */
} svgdoc_paint;

/* The root's initial values (SVG 2 section 13: fill black, stroke none,
** stroke-width 1, opacities 1; color black). */
void svgdoc_paint_initial(svgdoc_paint *p);

/* p (a copy of the parent's) after the element's properties P (indexed
** by SVGDOC_FILL ..., NULL: not given).  context: the paint of the <use>
** whose content this is (context-fill, context-stroke), or NULL. */
void svgdoc_paint_apply(svgdoc_paint *p, const char *const *P,
                        const svgdoc_paint *context);

/* Does the stroke paint anything?  Does the fill (never for <line>, which
** has no interior: SVG 2 section 10.5)? */
int svgdoc_paint_stroked(const svgdoc_paint *p);
int svgdoc_paint_filled(const svgdoc_paint *p, const char *tag);

/* Is s (trimmed, lower-case, not a CSS-wide keyword) a valid value of
** paint property k (SVGDOC_FILL ... SVGDOC_COLOR)?  An invalid one is
** dropped by the cascade (CSS Syntax 3: an invalid declaration is
** ignored), so that a weaker origin's value applies.  1 for others. */
int svgdoc_paint_valid(int k, const char *s);

/* Fill or stroke value s (lower-case) after its paint server is looked
** for: a url(#id) that names no paint server of the document (when the
** scan saw all its ids) is its fallback, or none without one (SVG 2
** section 13.2); anything else is s. */
const char *svgdoc_paint_server(const struct svgdoc *D, const char *s);

/* A CSS colour (CSS Color 4: named, transparent, #rgb[a], #rrggbb[aa],
** rgb[a](), hsl[a](), hwb(), lab(), lch(), oklab(), oklch()), lower-case:
** 1 with *clear set when its alpha is 0; 0 when s is not a colour. */
int svgdoc_color(const char *s, int *clear);

#endif
