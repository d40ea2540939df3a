/*
** conic_circle.c -- the length of a conic that is a circular arc, or all
** but one, in closed form: the fast branch of the conic segment's length
** (conic_seg.c), which a drawing of circles takes for every quarter.
**
** The conic (P0, P1, P2; w), w < 1, is the ellipse arc x(th) = C + U cos th
** + V sin th, th in [-al, al], al = acos w, with U = d w/(1-w^2), V =
** h/sqrt(1-w^2), d = P1 - (P0+P2)/2, h = (P2-P0)/2 (conic_length.c's
** form; U, V conjugate semi-diameters).  Its speed squared is
**   f = |U|^2 s^2 + |V|^2 c^2 - 2 U.V s c   (s = sin th, c = cos th),
** and with G = |U| s^2 + |V| c^2:  f = G^2 + s^2 c^2 (|U| - |V|)^2 - 2 U.V s c.
** A circular arc has |U| = |V| = r, U.V = 0: f = G^2 = r^2, L = 2 al r.
** Near one, sqrt f = G + (f - G^2)/(2G) + O(f - G^2)^2/G^3; the term in U.V
** is odd in th and integrates to 0 over [-al, al], so
**   L = int G = al (|U| + |V|) + w sqrt(1-w^2) (|V| - |U|)
** is the length to second order.  Bounds: s^2 c^2 <= sin^2 al = 1 - w^2,
** so with D = |(|U| - |V|)|/min(|U|, |V|) and Q = |U.V|/(|U| |V|) the first
** neglected term is at most (D^2 (1-w^2)/2) L and the square root's
** remainder (G^2 x^2/8 with |x| <= D^2 (1-w^2) + 2 Q sqrt(1-w^2)) at most
** ((D^2 (1-w^2) + 2 Q sqrt(1-w^2))^2/8) L.  Taken when D sqrt(1-w^2) and
** Q sqrt(1-w^2) are both at most tau = 2^-30 (and D <= 2^-10, an arc near
** a circle): the rest is then below tau^2 L = 2^-60 L.  The roundings of a
** circle's points pass (a radius of 0.2 at x = 1000: D ~ 3e-13; a short
** arc's rounded w: D ~ 1e-16/(1-w^2)); an ellipse of axes 1 and 1 + 1e-6
** does not.  Rounding: acos, the norms, sqrt and the quotients are each within
** an ulp or two, the legs one rounding of the points; |U|'s digits lost to d's
** cancellation on a short arc weigh (1-w^2)/3 in L; so the result is
** within a few ulps (spec/circle_spec.lua: against mpmath and against the
** general path, arclen_conic_length, which stays the one for every other
** conic).
*/
#include <math.h>

#include "arclen.h"
#include "segment/segment.h"

#define CIRCLE_TAU 0x1p-30      /* the gate: D and Q times sin(al) */
#define CIRCLE_NEAR 0x1p-10     /* and D itself: near a circle */

int arclen_rquad_circular(const double q[6], double w, double *len) {
  double ax = q[2] - q[0], ay = q[3] - q[1];     /* a = P1 - P0 */
  double kx = q[4] - q[0], ky = q[5] - q[1];     /* k = P2 - P0 */
  double mx, sc, hx, hy, dx, dy, onew, sq, ld, lh, nu, nv, dd, uv, al, L;
  int e;
  if (!(w > 0 && w < 1)) return 0;               /* parabolas, hyperbolas */
  mx = fmax(fmax(fabs(ax), fabs(ay)), fmax(fabs(kx), fabs(ky)));
  /* a point, or legs near the ends of the double range: the general path */
  if (!(mx >= 0x1p-1000 && mx <= 0x1p1000)) return 0;
  /* the legs scaled into [1/2, 1) so that no square under- or overflows,
  ** by a power of two (normal here: exact products, and cheaper than
  ** ldexp, which took a sixth of the time) */
  frexp(mx, &e);
  sc = ldexp(1, -e);
  ax *= sc, ay *= sc;
  hx = kx * (sc / 2), hy = ky * (sc / 2);
  dx = ax - hx, dy = ay - hy;
  onew = (1 - w) * (1 + w);                      /* 1 - w^2: 1 - w is exact */
  sq = sqrt(onew);
  /* norms as square roots of sums of squares, not hypot (a third of the
  ** time): the parts are below 1, and a |d| or |h| below 2^-500, whose
  ** squares could underflow, is left to the general path */
  ld = sqrt(dx * dx + dy * dy);
  lh = sqrt(hx * hx + hy * hy);
  if (!(ld > 0x1p-500 && lh > 0x1p-500)) return 0;
  nv = lh / sq;                                  /* |V| */
  nu = ld * (w / onew);                          /* |U| */
  if (!(nu > 0x1p-500 && nv > 0x1p-500 && nu < 0x1p500 && nv < 0x1p500))
    return 0;                                    /* extremes: the general path */
  dd = fabs(nu - nv) / fmin(nu, nv);                       /* D */
  if (!(dd <= CIRCLE_NEAR && dd * sq <= CIRCLE_TAU)) return 0;
  /* Q = U.V / (|U| |V|) = d.h / (|d| |h|) */
  uv = (dx * hx + dy * hy) / (ld * lh);
  if (!(fabs(uv) * sq <= CIRCLE_TAU)) return 0;
  al = acos(w);
  L = al * (nu + nv) + (w * sq) * (nv - nu);
  *len = ldexp(L, e);
  return 1;
}
