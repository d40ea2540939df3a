/*
** pathdata.h -- SVG path data (the `d` attribute, SVG 1.1 section 8.3 and
** SVG 2 section 9.3) read into segments of four kinds (lines, quadratic
** and cubic Bezier curves, conics), or into cubics only, optionally mapped
** by a 2x3 transform.  No Lua dependency: the binding (lua/svg.c) turns
** the result into tables and the error into its message.
*/
#ifndef ARCLEN_PATHDATA_H
#define ARCLEN_PATHDATA_H

#include <stddef.h>

/* A segment's record: ARCLEN_PD_STRIDE doubles, its kind's numbers first
** and the rest 0 -- a line P0 P1, a quadratic P0 P1 P2, a cubic P0 P1 P2
** P3, a conic P0 P1 P2 w (the rational quadratic with weights 1, w, 1,
** Floater's eq. 1) -- and its kind's letter, as arclen.lengths reads them. */
#define ARCLEN_PD_STRIDE 8
#define ARCLEN_PD_LINE 'L'
#define ARCLEN_PD_QUAD 'Q'
#define ARCLEN_PD_CUBIC 'C'
#define ARCLEN_PD_CONIC 'R'

/* What the reader makes of the data (arclen_pathdata.arcs). */
enum {
  ARCLEN_PD_ARCS_CONICS,    /* the kinds as written, arcs as conics (exact) */
  ARCLEN_PD_ARCS_CUBICS,    /* cubics only: lines and quadratics raised
                            ** exactly, arcs within arc_tol */
  ARCLEN_PD_ARCS_QUARTERS   /* as CONICS, but every arc is a quarter of an
                            ** axis-aligned ellipse given by its end points
                            ** (the basic shapes' own data, svgdoc/shapes.c):
                            ** the conic through the corner, w = sqrt(1/2) */
};

/* A subpath: its start point, whether Z closed it, and its segments
** first .. first + n - 1 of the result. */
typedef struct arclen_subpath {
  double x, y;
  size_t first, n;
  int closed;
} arclen_subpath;

/* The first error met, in the order a left-to-right reader meets them
** (the transform's overflow is found after the whole data is read). */
enum {
  ARCLEN_PD_OK,
  ARCLEN_PD_EMPTY,        /* only whitespace */
  ARCLEN_PD_NO_MOVETO,    /* the first command is not M/m (byte) */
  ARCLEN_PD_AFTER_Z,      /* arguments after Z (byte) */
  ARCLEN_PD_UNKNOWN,      /* a byte that is no command (byte) */
  ARCLEN_PD_CLOSE_FIRST,  /* Z with no subpath open (Z Z) */
  ARCLEN_PD_NUMBER,       /* argument arg of cmd missing (byte, or the end) */
  ARCLEN_PD_EXPONENT,     /* 'e' without digits */
  ARCLEN_PD_RANGE,        /* a number beyond the doubles (token) */
  ARCLEN_PD_FLAG,         /* an arc flag that is not 0 or 1 (cmd, arg) */
  ARCLEN_PD_COMMA,        /* a comma before a command or the end */
  ARCLEN_PD_ARC,          /* the arc conversion failed (arc, code, bound) */
  ARCLEN_PD_TRANSFORM,    /* a mapped coordinate overflows (no position) */
  ARCLEN_PD_NOMEM
};

/* Why an arc failed (ARCLEN_PD_ARC), in arclen.svg_arc's terms. */
enum {
  ARCLEN_PD_ARC_X1, ARCLEN_PD_ARC_Y1,   /* the start is not finite */
  ARCLEN_PD_ARC_X2, ARCLEN_PD_ARC_Y2,   /* the end is not finite */
  ARCLEN_PD_ARC_TOL,          /* the scaled tolerance is 0 or inf */
  ARCLEN_PD_ARC_OVERFLOW,     /* radii, centre or conics beyond DBL_MAX */
  ARCLEN_PD_ARC_CODE,         /* code: an arclen error code */
  ARCLEN_PD_ARC_LEVEL,        /* tol not reached by MAXLEVEL (bound) */
  ARCLEN_PD_ARC_CUBICS,       /* a cubic's control point beyond DBL_MAX */
  ARCLEN_PD_ARC_DEGENERATE    /* a conic rounding made degenerate */
};

typedef struct arclen_pathdata_error {
  int kind;
  size_t pos;           /* 1-based byte position; 0: none */
  int at_end;           /* NUMBER: the data ended where a number was due */
  unsigned char byte;   /* the offending byte */
  char cmd;             /* NUMBER, FLAG: the command (upper case) */
  int arg;              /* NUMBER, FLAG: its argument, from 1 */
  size_t tok, toklen;   /* RANGE: the number's text, d[tok .. tok+toklen-1] */
  int arc, code;        /* ARC: why (ARCLEN_PD_ARC_*), an error code */
  double bound;         /* ARC_LEVEL: the bound at the last level */
  size_t start;         /* 0-based offset of the command (or its implicit
                        ** repetition) that holds the error: the data before
                        ** it is correct, what SVG 2 section 9.5.4 renders */
} arclen_pathdata_error;

typedef struct arclen_pathdata {
  /* the segments' records (ARCLEN_PD_STRIDE numbers each) and kinds; the
  ** names are older than the kinds: every record is a cubic only under
  ** ARCLEN_PD_ARCS_CUBICS */
  double *cubics;
  unsigned char *kinds;
  size_t ncubics, cubics_room;
  int arcs;                           /* ARCLEN_PD_ARCS_*; init: CONICS */
  arclen_subpath *subpaths;
  size_t nsubpaths, subpaths_room;
  arclen_pathdata_error err;
} arclen_pathdata;

void arclen_pathdata_init(arclen_pathdata *pd);
void arclen_pathdata_free(arclen_pathdata *pd);

/* Read d[0 .. n-1] into pd (initialised, pd->arcs set; previous contents
** are dropped).  pd->arcs CONICS: L H V Z are lines, Q T quadratics, C S
** cubics, A at most four conics of at most 90 degrees (SVG 1.1 F.6.5),
** degenerate arcs per F.6.2 a line or nothing; a conic that rounding made
** flat is the line of its ends.  CUBICS: lines are cubics with control
** points at thirds, quadratics are degree-elevated, arcs become cubics
** within arc_tol times the arc's size (Floater's mid-point scheme; see
** doc/svg.md).  T (NULL: none) is {a, b, c, d, e, f} as SVG's matrix(a b
** c d e f): exact on every kind (the affine image of a Bezier curve or of
** a conic is the curve of its mapped control points, w unchanged).
** Returns the error kind (ARCLEN_PD_OK on success; then pd->err.kind is
** OK too). */
int arclen_pathdata_parse(arclen_pathdata *pd, const char *d, size_t n,
                          double arc_tol, const double *T);

/* A path built command by command (the basic shapes, svgdoc/shapes.c), with
** no text between: the records, kinds, subpaths, transform and errors that
** arclen_pathdata_parse gives the same commands written as text (numbers
** that read back to the same doubles), through the same functions; errors
** have no position (pd->err.pos 0).  The fields are the builder's own. */
typedef struct arclen_pathbuild {
  arclen_pathdata *pd;
  const char *d;            /* the text being parsed; NULL when building */
  size_t n;
  double arc_tol;
  const double *T;
  long sp;                  /* the open subpath, -1 when none */
  int overflow;             /* a mapped point beyond the doubles */
  size_t at;                /* where the command being read starts */
  int begun;                /* a first command seen */
  double cx, cy, sx, sy;    /* the current point, the subpath's start */
  double lcx, lcy, lqx, lqy;  /* the last cubic's and quadratic's control */
  int lastc, lastq;           /* points, valid after C/S and Q/T */
} arclen_pathbuild;

/* Start building into pd (initialised, pd->arcs set; previous contents
** dropped), arc_tol and T (kept, not copied) as arclen_pathdata_parse's. */
void arclen_pathbuild_start(arclen_pathbuild *b, arclen_pathdata *pd,
                            double arc_tol, const double *T);
/* One absolute command, cmd one of M L H V C S Q T A Z, with its arguments
** a[] in the text's order (A: rx ry rotation large-arc sweep x y; Z: none);
** the first must be M.  Returns the error kind; after an error the later
** calls return it again and add nothing. */
int arclen_pathbuild_add(arclen_pathbuild *b, char cmd, const double *a);
/* The end: T applied; returns the error kind (ARCLEN_PD_EMPTY: no command). */
int arclen_pathbuild_finish(arclen_pathbuild *b);

/* The name of argument k (from 1) of command cmd (upper case), as the
** specification calls it ("x1", "large-arc-flag"); "?" when none. */
const char *arclen_pathdata_argname(char cmd, int k);

/* The message of pd's error (without its position) into buf, as snprintf
** writes: the length it has, whatever fits. */
size_t arclen_pathdata_message(const arclen_pathdata *pd, const char *d,
                               char *buf, size_t size);

#endif
