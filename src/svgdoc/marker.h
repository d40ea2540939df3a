/*
** marker.h -- markers (SVG 2 section 11.6): the marker properties'
** values, a shape's vertices and their directions (11.6.2 and the path
** directionality of section 9.5), and where each instance of a marker's
** content goes (orient, markerUnits, markerWidth/Height, viewBox,
** preserveAspectRatio, refX/refY, overflow).  The reader replays the
** marker's kept content under that placement (reader.c); clip.c cuts it
** to the marker's viewport.
*/
#ifndef ARCLEN_SVGDOC_MARKER_H
#define ARCLEN_SVGDOC_MARKER_H

#include "svgdoc/internal.h"
#include "svgdoc/paint.h"

enum { SVGDOC_MK_START, SVGDOC_MK_MID, SVGDOC_MK_END };

/* What a marker's content inherits: the marker element's own computed
** properties where it stands in the document, over its ancestors' (SVG 2
** 11.6.2: not the referencing shape's), and its overflow. */
typedef struct svgdoc_marker_def {
  svgdoc_paint paint;
  int visible, clip;               /* clip: overflow hidden or scroll */
  double em, sw;                   /* font-size, stroke-width */
} svgdoc_marker_def;

/* The instances of one marker property on one shape: its vertices in the
** shape's user space (x, y, the auto angle in radians), and, set for the
** instance being drawn, the map from the content's coordinates onto the
** document and the clip rectangle in the content's coordinates. */
typedef struct svgdoc_marker_set {
  int which;                       /* SVGDOC_MK_* */
  size_t n;
  double *v;                       /* 3 n numbers */
  double sw;                       /* the shape's stroke-width */
  svgdoc_matrix ctm;               /* the shape's CTM */
  svgdoc_viewport vp;              /* the shape's viewport */
  const char *tag;                 /* the shape's tag, for messages */
  /* the instance being drawn */
  svgdoc_matrix outer;
  int clip;
  double box[4];                   /* x0 y0 x1 y1 */
} svgdoc_marker_set;

/* A marker property's value (cascaded, NULL: not given) over the parent's
** (an id or NULL): "url(#id)" gives id (copied into the pool), "none" and
** "initial" NULL, anything else (inherit, unset, not a reference) the
** parent's. */
const char *svgdoc_marker_ref(svgdoc *D, const char *value,
                              const char *parent);

/* The computed stroke-width of value (NULL: inherited) over the parent's;
** an invalid or negative one is ignored (the parent's). */
double svgdoc_stroke_width(const char *value, double parent,
                           const svgdoc_viewport *vp);

/* The vertices of a path, line, polyline or polygon (in its own
** coordinates) into D->marker_buf: 3 numbers each (x, y, the auto angle);
** their count.  A path's data is read up to its first error. */
size_t svgdoc_marker_vertices(svgdoc *D, const svgdoc_shape *s,
                              double **v);

/* Instance i of ms for the marker element's attributes atts and what it
** inherits (def): ms->outer, ms->clip, ms->box, and the content's
** viewport into *vp; 0 when the marker draws nothing (a zero
** markerWidth, markerHeight, viewBox size or scale). */
int svgdoc_marker_place(svgdoc *D, svgdoc_marker_set *ms, size_t i,
                        const char **atts, const svgdoc_marker_def *def,
                        unsigned long line, unsigned long col,
                        svgdoc_viewport *vp);

/* ---- clip.c ---- */

/* pd's segments cut to the rectangle box (x0 y0 x1 y1; NULL: none), the
** parts inside kept as sub-ranges of their segments (a part that does not
** continue the one before starts a subpath), then every record mapped by
** M (NULL: none).  0, or -1 without memory (pd then freed). */
int svgdoc_clip_map(arclen_pathdata *pd, const double *box, const double *M);

#endif
