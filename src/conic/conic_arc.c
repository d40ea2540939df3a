/*
** conic_arc.c -- other descriptions of a conic arc, reduced to the standard
** form (p0, p1, p2; w) of Floater's eq. (1): three weights, an elliptic arc
** by centre and angles, and SVG's endpoint arc parameters.
*/
#include <float.h>
#include <math.h>

#include "arclen.h"
#include "curve/numeric.h"


/* A rational quadratic with weights (w0, w1, w2) is the standard form with
** w = w1 / sqrt(w0 w2) (Farin's reparametrisation t -> t/(t + c(1-t))).
** All three weights must have the same sign. */
int arclen_conic_normal_weight(double w0, double w1, double w2, double *w) {
  *w = NAN;
  if (!isfinite(w0) || !isfinite(w1) || !isfinite(w2)) return ARCLEN_EINVAL;
  if (w0 < 0 && w1 < 0 && w2 < 0) { w0 = -w0; w1 = -w1; w2 = -w2; }
  if (!(w0 > 0 && w1 > 0 && w2 > 0)) return ARCLEN_EDOMAIN;
  *w = w1 / (sqrt(w0) * sqrt(w2));   /* no overflow in w0 * w2 */
  return isfinite(*w) && *w > 0 ? ARCLEN_OK : ARCLEN_EDOMAIN;
}

/* The point of the ellipse at unit-frame coordinates (X, Y); where the
** terms overflow, the halves are summed and doubled (which overflows only
** when the point itself is beyond DBL_MAX).  Returns 0 or EOVERFLOW. */
static int ellipse_map(const double e[5], double X, double Y, double *x,
                       double *y) {
  double cp = cos(e[4]), sp = sin(e[4]);
  *x = e[0] + (e[2] * X) * cp - (e[3] * Y) * sp;
  *y = e[1] + (e[2] * X) * sp + (e[3] * Y) * cp;
  if (isfinite(*x) && isfinite(*y)) return ARCLEN_OK;
  *x = 2 * (e[0] / 2 + (e[2] / 2 * X) * cp - (e[3] / 2 * Y) * sp);
  *y = 2 * (e[1] / 2 + (e[2] / 2 * X) * sp + (e[3] / 2 * Y) * cp);
  return isfinite(*x) && isfinite(*y) ? ARCLEN_OK : ARCLEN_EOVERFLOW;
}

/* The control point of a piece of angle 2h about the unit-frame angle m
** whose ends p0 and p2 are given: the image of the tangents' intersection
** (cos m, sin m) / cos h is the chord's midpoint (cos m, sin m) cos h plus
** (cos m, sin m) sin h tan h, so p1 = (p0 + p2)/2 + M (cos m, sin m) sin h
** tan h with M the ellipse's linear part.  Written from the ends, not from
** the centre: a flat arc of a large ellipse has its centre ~R away, whose
** rounding (R eps) would move p1 far more than the arc's own sag; here
** the offset is of the sag's size and rounds with it. */
static int control_point(const double e[5], double m, double h,
                         const double *o, double *x, double *y) {
  double cp = cos(e[4]), sp = sin(e[4]), sh = sin(h), f = sh * (sh / cos(h));
  double X = e[2] * (cos(m) * f), Y = e[3] * (sin(m) * f);
  *x = (o[0] / 2 + o[4] / 2) + (X * cp - Y * sp);
  *y = (o[1] / 2 + o[5] / 2) + (X * sp + Y * cp);
  return isfinite(*x) && isfinite(*y) ? ARCLEN_OK : ARCLEN_EOVERFLOW;
}

/* The pieces of arclen_ellipse_conics, the first starting at ends[0..1]
** and the last ending at ends[2..3] where ends is given (SVG's own end
** points), else at the ellipse's points; each control point from its
** piece's ends (control_point). */
static int ellipse_pieces(const double e[5], double theta, double dtheta,
                          const double *ends, double out[28]) {
  int n, k;
  /* a few ulps of slack so that a full turn computed as 2 pi + rounding
  ** is still four quarters */
  if (fabs(dtheta) > 2 * ARCLEN_PI * (1 + 8 * DBL_EPSILON)) return ARCLEN_ERANGE;
  if (dtheta == 0) return 0;
  n = (int)ceil(fabs(dtheta) / (ARCLEN_PI / 2) * (1 - 8 * DBL_EPSILON));
  if (n < 1) n = 1;
  if (n > 4) n = 4;
  for (k = 0; k < n; k++) {
    /* neighbours compute their shared end from the same angle, so the
    ** pieces join exactly */
    double a = theta + dtheta * k / n;
    double b = k + 1 == n ? theta + dtheta : theta + dtheta * (k + 1) / n;
    /* the half angle from dtheta, not (b - a)/2: b - a near theta ~ pi
    ** keeps only eps pi of it, 4e-13 of a piece of 2e-3 */
    double h = dtheta / (2 * n), *o = out + 7 * k;
    if (ends && k == 0) { o[0] = ends[0]; o[1] = ends[1]; }
    else if (ellipse_map(e, cos(a), sin(a), &o[0], &o[1]) != ARCLEN_OK)
      return ARCLEN_EOVERFLOW;   /* a point beyond DBL_MAX */
    if (ends && k + 1 == n) { o[4] = ends[2]; o[5] = ends[3]; }
    else if (ellipse_map(e, cos(b), sin(b), &o[4], &o[5]) != ARCLEN_OK)
      return ARCLEN_EOVERFLOW;
    if (control_point(e, a + h, h, o, &o[2], &o[3]) != ARCLEN_OK)
      return ARCLEN_EOVERFLOW;
    o[6] = cos(h);
  }
  return n;
}

/* The arc of the ellipse centre (cx, cy), semi-axes rx, ry, rotated by phi
** (radians), from parametric angle theta to theta + dtheta (radians,
** |dtheta| <= 2 pi), in n equal pieces of at most 90 degrees.  Each piece
** of angle 2h is the image of a circular arc: w = cos h, and p1 the image
** of the tangents' intersection (control_point).  Writes n conics of 7
** numbers (p0, p1, p2, w) into out[28]; returns n (0 for dtheta = 0) or an
** error code (EOVERFLOW: a control point beyond DBL_MAX). */
int arclen_ellipse_conics(double cx, double cy, double rx, double ry,
                          double phi, double theta, double dtheta,
                          double out[28]) {
  double e[5];
  if (!isfinite(cx) || !isfinite(cy) || !isfinite(rx) || !isfinite(ry) ||
      !isfinite(phi) || !isfinite(theta) || !isfinite(dtheta))
    return ARCLEN_EINVAL;
  if (!(rx > 0) || !(ry > 0)) return ARCLEN_EDOMAIN;
  /* theta into [-pi, pi] (modulo the double 2 pi, which moves a start
  ** |theta|/2 pi turns away by 2.4e-16 radians a turn): far out, theta +
  ** dtheta k/n keeps only ulp(theta) of the sweep, and the pieces' ends
  ** would not be their half angles apart (found by fuzz/fuzz_conic:
  ** theta = -1e304 put both ends at one point) */
  if (fabs(theta) > ARCLEN_PI) theta = remainder(theta, 2 * ARCLEN_PI);
  e[0] = cx; e[1] = cy; e[2] = rx; e[3] = ry; e[4] = phi;
  return ellipse_pieces(e, theta, dtheta, NULL, out);
}

/* The angle from u to v, in (-pi, pi]. */
static double vec_angle(double ux, double uy, double vx, double vy) {
  return atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

/* SVG 1.1 Appendix F.6.5 (endpoint to centre parameterisation) with the
** out-of-range radius correction of F.6.6.  phi in degrees; large, sweep
** are the flags.  Returns ARCLEN_SVGARC_NONE (endpoints equal: the arc is
** omitted, F.6.2), ARCLEN_SVGARC_LINE (rx or ry is 0: a straight segment)
** or ARCLEN_SVGARC_ARC with c = cx cy rx ry phi(radians) theta1 dtheta;
** or a negative error code (non-finite input; ARCLEN_EOVERFLOW when the
** radii scaled up by F.6.6.3 exceed DBL_MAX). */
int arclen_svg_arc_center(double x1, double y1, double rx, double ry,
                          double phi_deg, int large, int sweep, double x2,
                          double y2, double c[7]) {
  double phi, cp, sp, dx, dy, x1p, y1p, lam, coef, cxp, cyp, ux, uy;
  double u, v, h, rest;
  double t1, dt;
  if (!isfinite(x1) || !isfinite(y1) || !isfinite(x2) || !isfinite(y2) ||
      !isfinite(rx) || !isfinite(ry) || !isfinite(phi_deg))
    return ARCLEN_EINVAL;
  if (x1 == x2 && y1 == y2) return ARCLEN_SVGARC_NONE;      /* F.6.2 */
  rx = fabs(rx); ry = fabs(ry);                              /* F.6.6 step 1 */
  if (rx == 0 || ry == 0) return ARCLEN_SVGARC_LINE;         /* F.6.2 */
  phi = fmod(phi_deg, 360.0) * (ARCLEN_PI / 180);
  cp = cos(phi); sp = sin(phi);
  dx = x1 / 2 - x2 / 2; dy = y1 / 2 - y2 / 2;    /* x1 - x2 may overflow */
  x1p = cp * dx + sp * dy;                                   /* F.6.5.1 */
  y1p = -sp * dx + cp * dy;
  /* F.6.6.2: Lambda = x1'^2/rx^2 + y1'^2/ry^2 = h^2 (as ratios and by
  ** hypot: endpoints a few subnormals apart would underflow the squares to
  ** 0 and make the centre 0 * inf = NaN; found by fuzz/fuzz_conic) */
  u = x1p / rx; v = y1p / ry;
  h = hypot(u, v);
  if (h == 0) return ARCLEN_SVGARC_LINE;     /* endpoints 1 subnormal apart */
  lam = h * h;
  if (lam > 1) {                                             /* F.6.6.3 */
    rx *= h; ry *= h;
    /* a radius ~1e-320 scaled up to reach the endpoints: beyond DBL_MAX */
    if (!isfinite(rx) || !isfinite(ry)) return ARCLEN_EOVERFLOW;
    u /= h; v /= h; h = 1;   /* the endpoints on the scaled ellipse */
    coef = rest = 0;
  } else {
    /* F.6.5.2's radicand, divided through by rx^2 ry^2: (1 - Lambda)/Lambda;
    ** its root times (rx y1'/ry, -ry x1'/rx) is sqrt(1 - Lambda) (rx v/h,
    ** -ry u/h) */
    rest = 1 - lam;
    coef = sqrt(rest);
    if (large == sweep) coef = -coef;
  }
  cxp = coef * (rx * (v / h));
  cyp = coef * -(ry * (u / h));
  /* F.6.5.3, halved: the terms may overflow where the centre does not */
  c[0] = 2 * ((cp * (cxp / 2) - sp * (cyp / 2)) + (x1 / 2 + x2 / 2) / 2);
  c[1] = 2 * ((sp * (cxp / 2) + cp * (cyp / 2)) + (y1 / 2 + y2 / 2) / 2);
  if (!isfinite(c[0]) || !isfinite(c[1])) return ARCLEN_EOVERFLOW;
  /* F.6.5.5-6 with cx'/rx = coef v/h, cy'/ry = -coef u/h (no overflow):
  ** the unit-frame ends are U = A + coef n and V = -A + coef n, A = (u, v)
  ** of length h, n the unit normal (-v, u)/h, so that U x V = 2 coef h and
  ** U . V = coef^2 - h^2 = 1 - 2 h^2.  Those, not the components' products,
  ** which cancel to a relative error of eps/h for a short arc (a flat arc,
  ** or a turn at the tip of a thin ellipse: 1e-13 of the length there). */
  ux = u - coef * (v / h); uy = v + coef * (u / h);
  t1 = vec_angle(1, 0, ux, uy);
  dt = atan2(2 * coef * h, rest - h * h);
  if (!sweep && dt > 0) dt -= 2 * ARCLEN_PI;
  else if (sweep && dt < 0) dt += 2 * ARCLEN_PI;
  c[2] = rx; c[3] = ry; c[4] = phi; c[5] = t1; c[6] = dt;
  return ARCLEN_SVGARC_ARC;
}

/* The SVG arc as at most four conics (7 numbers each) into c[28], the
** first starting at (x1, y1) and the last ending at (x2, y2) exactly (the
** centre form's rounding must not open a gap in the path).  Returns
** ARCLEN_SVGARC_NONE or ARCLEN_SVGARC_LINE (nothing in c, *n = 0),
** ARCLEN_SVGARC_ARC with *n conics, or a negative error code (EOVERFLOW:
** radii, centre or control points beyond DBL_MAX). */
int arclen_svg_arc_conics(double x1, double y1, double rx, double ry,
                          double phi_deg, int large, int sweep, double x2,
                          double y2, double c[28], int *n) {
  double e[7], ends[4];
  int kind = arclen_svg_arc_center(x1, y1, rx, ry, phi_deg, large, sweep, x2,
                                   y2, e), k;
  *n = 0;
  if (kind != ARCLEN_SVGARC_ARC) return kind;
  ends[0] = x1; ends[1] = y1; ends[2] = x2; ends[3] = y2;
  k = ellipse_pieces(e, e[5], e[6], ends, c);
  if (k <= 0) return k == 0 ? ARCLEN_EINVAL : k;
  *n = k;
  return ARCLEN_SVGARC_ARC;
}
