/*
** pathdata_message.c -- the words of a path-data error (pathdata.h), for
** the Lua binding and the document reader alike.
*/
#include <stdarg.h>
#include <stdio.h>

#include "arclen.h"
#include "svg/decimal.h"
#include "svg/pathdata.h"

typedef struct out {
  char *buf;
  size_t size, len;
} out;

/* Append as snprintf would, counting what does not fit. */
static void put(out *o, const char *fmt, ...) {
  va_list ap;
  int n;
  char *at = o->len < o->size ? o->buf + o->len : NULL;
  size_t room = o->len < o->size ? o->size - o->len : 0;
  va_start(ap, fmt);
  n = vsnprintf(at, room, fmt, ap);
  va_end(ap);
  if (n > 0) o->len += (size_t)n;
}

/* "'c'" for a byte (a NUL too, written as itself), or the end. */
static void put_byte(out *o, const arclen_pathdata_error *e) {
  if (e->at_end) {
    put(o, "the end of the data");
    return;
  }
  put(o, "'");
  if (o->len < o->size) o->buf[o->len] = (char)e->byte;
  o->len++;
  put(o, "'");
}

/* The inner message of arclen.svg_arc for the same failure (but the
** tolerance, which path data does not give, in terms of the arc's size). */
static void put_arc_reason(out *o, const arclen_pathdata_error *e) {
  static const char *const coord[] = {"x1", "y1", "x2", "y2"};
  switch (e->arc) {
  case ARCLEN_PD_ARC_X1: case ARCLEN_PD_ARC_Y1:
  case ARCLEN_PD_ARC_X2: case ARCLEN_PD_ARC_Y2:
    put(o, "%s must be finite", coord[e->arc - ARCLEN_PD_ARC_X1]);
    break;
  case ARCLEN_PD_ARC_TOL:      /* arc_tol times the arc's size: data's fault */
    put(o, "the arc's size is out of range (its radii or chord beyond the "
           "largest double, or too small for arc_tol)");
    break;
  case ARCLEN_PD_ARC_OVERFLOW:
    put(o, "the arc's radii, centre or control points lie beyond the "
           "largest double");
    break;
  case ARCLEN_PD_ARC_LEVEL: {  /* %.14g: Lua's own format of a number */
    char num[32];
    arclen_decimal_print(num, e->bound, 14);
    put(o, "tol not reached by level %d (bound %s)", ARCLEN_CONIC_MAXLEVEL,
        num);
    break;
  }
  case ARCLEN_PD_ARC_CUBICS:
    put(o, "a control point of the cubics lies beyond the largest double");
    break;
  case ARCLEN_PD_ARC_DEGENERATE:
    put(o, "the arc is degenerate in double precision (its control points "
           "coincide or are collinear)");
    break;
  default:
    put(o, "%s", arclen_strerror(e->code));
  }
}

size_t arclen_pathdata_message(const arclen_pathdata *pd, const char *d,
                               char *buf, size_t size) {
  const arclen_pathdata_error *e = &pd->err;
  out o;
  o.buf = buf, o.size = size, o.len = 0;
  switch (e->kind) {
  case ARCLEN_PD_EMPTY:
    put(&o, "path data is empty");
    break;
  case ARCLEN_PD_NO_MOVETO:
    put(&o, "path data must begin with a moveto (M or m), got ");
    put_byte(&o, e);
    break;
  case ARCLEN_PD_AFTER_Z:
    put(&o, "expected a command after Z, got ");
    put_byte(&o, e);
    break;
  case ARCLEN_PD_UNKNOWN:
    put(&o, "unknown command ");
    put_byte(&o, e);
    break;
  case ARCLEN_PD_CLOSE_FIRST:
    put(&o, "closepath before any moveto");
    break;
  case ARCLEN_PD_NUMBER:
    put(&o, "expected a number (%c %s), got ", e->cmd,
        arclen_pathdata_argname(e->cmd, e->arg));
    put_byte(&o, e);
    break;
  case ARCLEN_PD_EXPONENT:
    put(&o, "exponent without digits in a number");
    break;
  case ARCLEN_PD_RANGE:
    put(&o, "number out of range '%.*s'", (int)e->toklen, d + e->tok);
    break;
  case ARCLEN_PD_FLAG:
    put(&o, "expected %s (0 or 1)", arclen_pathdata_argname(e->cmd, e->arg));
    break;
  case ARCLEN_PD_COMMA:
    put(&o, "comma not followed by a number");
    break;
  case ARCLEN_PD_ARC:
    put(&o, "elliptical arc: ");
    put_arc_reason(&o, e);
    break;
  case ARCLEN_PD_TRANSFORM:
    put(&o, "the transform takes a coordinate out of range");
    break;
  default:
    put(&o, "not enough memory");
  }
  if (size > 0) buf[o.len < size ? o.len : size - 1] = '\0';
  return o.len;
}
