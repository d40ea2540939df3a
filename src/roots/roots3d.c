/*
** roots3d.c -- the branch points of a space cubic's speed: the roots of
** |z'(t)|^2 = |a2 t^2 + a1 t + a0|^2 (a real quartic) in the upper half
** plane, split into two quadratics by the quartic solver (roots.c) and
** polished by complex Newton on the hodograph's own form of the quartic.
** The elliptic method (elliptic3d.c) and the default method's branch points
** (gauss/branch.c) both take them from here.
**
** Roots close together are where Newton on Q fails: each of two roots a
** distance d apart is placed only to eps/d, and an error in their centre
** moves the length by as much.  The length is a function of the hodograph,
** |L(h + dh) - L(h)| <= int |dh|, so what is needed is roots that belong
** exactly to a hodograph within rounding of h: such roots are computed in
** a frame about the cluster, where h's Taylor coefficients (rounded once,
** a perturbation of h of relative size eps) set the local quartic to its
** own scale.
** - four roots near one real point (a stop, a near-collinear stop): the
**   real local quartic about that point, split by the quartic solver;
** - a pair well off the real axis (hodograph nearly in a plane through the
**   origin): the local quartic about the pair's centre m (complex) is
**   (u^2 + p u + q)(c4 u^2 + g1 u + g0); the small factor is read off by a
**   fixed-point iteration that contracts like (d / distance to the other
**   pair)^2.  Its roots -p/2 +- sqrt(p^2/4 - q) keep the centre exact and
**   the integral depends on their split only through its square.
*/
#include <math.h>

#include "arclen.h"
#include "curve/cplx.h"
#include "roots/roots3d.h"

#define POLISH_CAP 80   /* linear phase inside a close pair, then quadratic */
#define FACTOR_CAP 60   /* contraction <= 1/16 per step (PAIR_OFF below) */
/* Roots closer than this (relative to the frame's scale) are a cluster:
** beyond it Newton's eps/d leaves < 5e-15 (measured, tools/ref_close3d.py) */
#define CLOSE_REL 0.05
/* A close pair whose imaginary parts exceed PAIR_OFF times its split is
** far from its conjugates (the factor iteration contracts like
** (1/(2 PAIR_OFF))^2 = 1/16); nearer the axis all four roots are one
** cluster, taken in the real frame. */
#define PAIR_OFF 2

/* Q(s) and Q'(s) from the hodograph, s complex. */
static arclen_cx q_eval(const double a2[3], const double a1[3],
                        const double a0[3], arclen_cx s, arclen_cx *dq) {
  arclen_cx q = arclen_cx_make(0, 0), d = arclen_cx_make(0, 0);
  int k;
  for (k = 0; k < 3; k++) {
    /* v = (a2 s + a1) s + a0, Q += v^2, Q' += 2 v (2 a2 s + a1) */
    arclen_cx v = arclen_cx_add_re(
        arclen_cx_mul(arclen_cx_add_re(arclen_cx_scale(a2[k], s), a1[k]), s),
        a0[k]);
    arclen_cx dv = arclen_cx_add_re(arclen_cx_scale(2 * a2[k], s), a1[k]);
    q = arclen_cx_add(q, arclen_cx_mul(v, v));
    d = arclen_cx_add(d, arclen_cx_mul(arclen_cx_scale(2, v), dv));
  }
  *dq = d;
  return q;
}

/* Newton from s toward the root of Q in the upper half plane. */
static arclen_cx polish(const double a2[3], const double a1[3],
                        const double a0[3], arclen_cx s) {
  arclen_cx best = s, dq, q = q_eval(a2, a1, a0, s, &dq);
  double bestq = arclen_cx_abs(q);
  int i, stall = 0;
  for (i = 0; i < POLISH_CAP && bestq > 0 && !arclen_cx_is_zero(dq); i++) {
    arclen_cx next = arclen_cx_sub(s, arclen_cx_div(q, dq));
    next.im = fabs(next.im);
    q = q_eval(a2, a1, a0, next, &dq);
    /* at the rounding level Newton can cycle between neighbouring
    ** doubles, never taking a zero step: from roots already at the last
    ** bit (roots.c's double-double step) it ran the cap, 80 steps, and
    ** made the 3D methods 1.4x slower.  Two steps in a row without a
    ** smaller |Q| end it (the linear phase inside a close pair lowers
    ** |Q| at every step, so it is not cut short). */
    if (arclen_cx_abs(q) < bestq) {
      best = next;
      bestq = arclen_cx_abs(q);
      stall = 0;
    } else if (++stall >= 2) {
      break;
    }
    if (arclen_cx_abs(arclen_cx_sub(next, s)) <=
        0x1p-60 * (1 + arclen_cx_abs(next)))
      break;
    s = next;
  }
  return best;
}

static double dot3(const double *u, const double *v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

/* The two roots of Q = |a2 t^2 + a1 t + a0|^2 in the upper half plane
** that make Q = c4 |t - s1|^2 |t - s2|^2; unit: the frame's length scale
** (1 globally, the cluster's size in a local frame). */
static int roots(const double a2[3], const double a1[3], const double a0[3],
                 double unit, arclen_cx *s1, arclen_cx *s2) {
  /* Q = |A2|^2 t^4 + 2 A2.A1 t^3 + (|A1|^2 + 2 A2.A0) t^2 + 2 A1.A0 t
  **     + |A0|^2 */
  double q[4], re[4], im[4], t;
  int i, j, e = arclen_quartic_factor_plain(dot3(a2, a2), 2 * dot3(a2, a1),
                                            dot3(a1, a1) + 2 * dot3(a2, a0),
                                            2 * dot3(a1, a0), dot3(a0, a0), q);
  if (e != ARCLEN_OK) return e;
  /* Q >= 0, so its real roots are double; a factor with two distinct
  ** real roots (a near-collinear Q split the other way) is re-paired:
  ** the four roots sorted, neighbours together.  Newton starts off the
  ** real axis (on it, it would stay there). */
  arclen_quadratic(1, q[0], q[1], re, im);
  arclen_quadratic(1, q[2], q[3], re + 2, im + 2);
  if (im[0] != 0 && im[2] != 0) {
    *s1 = arclen_cx_make(re[0], fabs(im[0]));
    *s2 = arclen_cx_make(re[2], fabs(im[2]));
  } else {
    for (i = 1; i < 4; i++)          /* insertion sort by real part */
      for (j = i; j > 0 && re[j] < re[j - 1]; j--) {
        t = re[j]; re[j] = re[j - 1]; re[j - 1] = t;
        t = im[j]; im[j] = im[j - 1]; im[j - 1] = t;
      }
    *s1 = arclen_cx_make((re[0] + re[1]) / 2,
                         fmax(fabs(re[1] - re[0]) / 2, fabs(im[0])));
    *s2 = arclen_cx_make((re[2] + re[3]) / 2,
                         fmax(fabs(re[3] - re[2]) / 2, fabs(im[2])));
  }
  if (s1->im == 0) s1->im = 0x1p-30 * (unit + fabs(s1->re));
  if (s2->im == 0) s2->im = 0x1p-30 * (unit + fabs(s2->re));
  *s1 = polish(a2, a1, a0, *s1);
  *s2 = polish(a2, a1, a0, *s2);
  return ARCLEN_OK;
}

/* A close pair s1, s2 off the real axis, rebuilt from the local quartic
** about its centre m: Q(m + u) = sum_k (v_k + w_k u + a2_k u^2)^2 with
** v = h(m), w = h'(m) (each rounded once), e_j its coefficients; the
** factor u^2 + p u + q of the small roots by the fixed point
** q = e0/g0, p = (e1 - q g1)/g0, g1 = e3 - p e4, g0 = e2 - p g1 - q e4.
** Left as it was if the iteration does not settle. */
static void close_pair(const double a2[3], const double a1[3],
                       const double a0[3], arclen_cx *s1, arclen_cx *s2) {
  arclen_cx m = arclen_cx_div_re(arclen_cx_add(*s1, *s2), 2), e[5];
  arclen_cx p = arclen_cx_make(0, 0), q = p, g0, g1, r, mid;
  int k, i;
  for (k = 0; k < 5; k++) e[k] = arclen_cx_make(0, 0);
  for (k = 0; k < 3; k++) {
    /* v = h(m) = (a2 m + a1) m + a0, w = h'(m) = 2 a2 m + a1 */
    arclen_cx v = arclen_cx_add_re(
        arclen_cx_mul(arclen_cx_add_re(arclen_cx_scale(a2[k], m), a1[k]), m),
        a0[k]);
    arclen_cx w = arclen_cx_add_re(arclen_cx_scale(2 * a2[k], m), a1[k]);
    e[0] = arclen_cx_add(e[0], arclen_cx_mul(v, v));
    e[1] = arclen_cx_add(e[1], arclen_cx_mul(arclen_cx_scale(2, v), w));
    e[2] = arclen_cx_add(e[2], arclen_cx_add(arclen_cx_mul(w, w),
                                             arclen_cx_scale(2 * a2[k], v)));
    e[3] = arclen_cx_add(e[3], arclen_cx_scale(2 * a2[k], w));
    e[4] = arclen_cx_add_re(e[4], a2[k] * a2[k]);
  }
  for (i = 0; i < FACTOR_CAP; i++) {
    arclen_cx p0 = p, q0 = q;
    /* g1 = e3 - p e4, g0 = e2 - p g1 - q e4, q = e0/g0, p = (e1 - q g1)/g0 */
    g1 = arclen_cx_sub(e[3], arclen_cx_mul(p, e[4]));
    g0 = arclen_cx_sub(arclen_cx_sub(e[2], arclen_cx_mul(p, g1)),
                       arclen_cx_mul(q, e[4]));
    if (arclen_cx_is_zero(g0)) return;
    q = arclen_cx_div(e[0], g0);
    p = arclen_cx_div(arclen_cx_sub(e[1], arclen_cx_mul(q, g1)), g0);
    if (arclen_cx_eq(p, p0) && arclen_cx_eq(q, q0)) break;
  }
  if (i == FACTOR_CAP || !isfinite(p.re + p.im + q.re + q.im)) return;
  /* the roots of u^2 + p u + q about m: m - p/2 +- sqrt(p^2/4 - q) */
  r = arclen_cx_div_re(arclen_cx_mul(p, p), 4);
  r = arclen_cx_sqrt(arclen_cx_sub(r, q));
  mid = arclen_cx_sub(m, arclen_cx_div_re(p, 2));
  *s1 = arclen_cx_add(mid, r);
  *s2 = arclen_cx_sub(mid, r);
  s1->im = fabs(s1->im);
  s2->im = fabs(s2->im);
}

/* s1, s2 (frame scale unit) a pair for close_pair? */
static int is_pair(arclen_cx s1, arclen_cx s2, double unit) {
  double d = arclen_cx_abs(arclen_cx_sub(s1, s2));
  double big = fmax(arclen_cx_abs(s1), arclen_cx_abs(s2));
  return d <= CLOSE_REL * fmax(unit, big) &&
         fmin(s1.im, s2.im) > PAIR_OFF * d;
}

int arclen_roots3d(const double a2[3], const double a1[3],
                     const double a0[3], double re[2], double im[2]) {
  arclen_cx s1, s2;
  int e = roots(a2, a1, a0, 1, &s1, &s2);
  if (e != ARCLEN_OK) return e;
  if (fmax(arclen_cx_abs(arclen_cx_sub(s1, s2)), fmax(s1.im, s2.im)) <=
      CLOSE_REL * fmax(1, fabs(s1.re))) {
    /* four roots near one real point: about their mean c (Q''' = 0:
    ** c = -c3/(4 c4), from the hodograph to rounding, where the roots
    ** themselves are known to eps^(1/4) only), h(c + u) = a2 u^2 + b1 u
    ** + b0, whose roots are set to their own scale */
    double c = -dot3(a2, a1) / (2 * dot3(a2, a2)), b1[3], b0[3], unit;
    arclen_cx u1, u2;
    int k;
    for (k = 0; k < 3; k++) {
      b1[k] = 2 * a2[k] * c + a1[k];
      b0[k] = (a2[k] * c + a1[k]) * c + a0[k];
    }
    unit = fmax(hypot(s1.re - c, s1.im), hypot(s2.re - c, s2.im));
    if (roots(a2, b1, b0, unit, &u1, &u2) == ARCLEN_OK) {
      if (is_pair(u1, u2, 0)) close_pair(a2, b1, b0, &u1, &u2);
      s1 = arclen_cx_make(c + u1.re, u1.im);
      s2 = arclen_cx_make(c + u2.re, u2.im);
    }
  } else if (is_pair(s1, s2, 1)) {
    close_pair(a2, a1, a0, &s1, &s2);
  }
  re[0] = s1.re; im[0] = s1.im;
  re[1] = s2.re; im[1] = s2.im;
  return ARCLEN_OK;
}
