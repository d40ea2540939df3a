/*
** conic_seg.c -- the conic segment: the rational quadratic Bezier P0 P1 P2
** with weights (1, w, 1), w > 0 (Floater's eq. 1), in 2D and 3D.  The piece
** over [t0, t1] is again such a conic (the homogeneous blossom, weights
** renormalized to (1, w', 1)), so every partial length is the exact one of
** conic/conic_length.c.  A 3D arc lies in the plane of its points and is
** measured on its isometric image in 2D, built from |a|, a.c and |a x c|
** alone; a flat triangle (collinear points) is a segment run along a line,
** possibly turning back, measured as the variation of its coordinate.
*/
#include <float.h>
#include <math.h>

#include "arclen.h"
#include "segment/segment.h"

static double dot(const double *u, const double *v, int dim) {
  double s = u[0] * v[0] + u[1] * v[1];
  return dim == 3 ? s + u[2] * v[2] : s;
}

/* out (dim numbers) into the bounding box of the three points: a point
** of the conic (and of its blossom) is a convex combination of them
** (weights > 0), so only rounding can leave the box -- and beyond DBL_MAX
** it would (points at +-1.797e308). */
static void into_hull(const double *p, int dim, double *out) {
  int k;
  for (k = 0; k < dim; k++) {
    double lo = fmin(p[k], fmin(p[dim + k], p[2 * dim + k]));
    double hi = fmax(p[k], fmax(p[dim + k], p[2 * dim + k]));
    out[k] = fmin(fmax(out[k], lo), hi);
  }
}

/* The homogeneous blossom's weight W(u, v) and the point of B(u, v),
** formed relative to P0 (so far-away points keep the legs' digits). */
static double blossom(const double *p, int dim, double u, double v,
                      double *out) {
  double w = p[3 * dim];
  double b0 = (1 - u) * (1 - v), b1 = ((1 - u) * v + u * (1 - v)) * w;
  double b2 = u * v, W = b0 + b1 + b2;
  int k;
  /* the weights divided first: b1 (P1 - P0) alone may overflow (w = 1e5
  ** beside points at 1e304) where b1/W (P1 - P0) does not */
  for (k = 0; k < dim; k++) {
    double l1 = p[dim + k] - p[k], l2 = p[2 * dim + k] - p[k], x;
    if (isfinite(l1) && isfinite(l2)) {
      out[k] = p[k] + ((b1 / W) * l1 + (b2 / W) * l2);
    } else {            /* points on both sides of +-DBL_MAX/2: half legs */
      x = (b1 / W) * (p[dim + k] / 2 - p[k] / 2) + (b2 / W) * (p[2 * dim + k] / 2 - p[k] / 2);
      out[k] = (p[k] + x) + x;
    }
  }
  into_hull(p, dim, out);
  return W;
}

void arclen_rquad_sub(const double *p, int dim, double t0, double t1,
                      double *out) {
  double W0 = blossom(p, dim, t0, t0, out);
  double W1 = blossom(p, dim, t0, t1, out + dim);
  double W2 = blossom(p, dim, t1, t1, out + 2 * dim);
  int k;
  /* the ends exactly where the curve's ends are */
  if (t0 == 0 || t0 == 1)
    for (k = 0; k < dim; k++) out[k] = p[t0 == 0 ? k : 2 * dim + k];
  if (t1 == 0 || t1 == 1)
    for (k = 0; k < dim; k++) out[2 * dim + k] = p[t1 == 0 ? k : 2 * dim + k];
  /* weights (W0, W1, W2) -> (1, W1/sqrt(W0 W2), 1): the same curve
  ** (Farin, "NURBS", the standard form); square roots apart so that no
  ** product overflows */
  out[3 * dim] = W1 / (sqrt(W0) * sqrt(W2));
}

void arclen_rquad_point(const double *p, int dim, double t, double *out) {
  double w = p[3 * dim], s = 1 - t;
  double b0 = s * s, b1 = 2 * s * t * w, b2 = t * t, D = b0 + b1 + b2;
  int k;
  for (k = 0; k < dim; k++)
    if (!isfinite(p[2 * dim + k] - p[k]) || !isfinite(p[dim + k] - p[k]) ||
        !isfinite(p[dim + k] - p[2 * dim + k])) {
      blossom(p, dim, t, t, out);      /* legs beyond DBL_MAX: halved there */
      if (t == 1)
        for (k = 0; k < dim; k++) out[k] = p[2 * dim + k];
      return;
    }
  for (k = 0; k < dim; k++) {
    /* relative to the nearer end: P0 at t = 0 and P2 at t = 1 exactly */
    if (t <= 0.5)
      out[k] = p[k] + ((b1 / D) * (p[dim + k] - p[k]) + (b2 / D) * (p[2 * dim + k] - p[k]));
    else
      out[k] = p[2 * dim + k]
               + ((b0 / D) * (p[k] - p[2 * dim + k]) + (b1 / D) * (p[dim + k] - p[2 * dim + k]));
  }
  into_hull(p, dim, out);
}

/* C'(t) = 2 [w (1-t)^2 (P1 - P0) + t (1-t) (P2 - P0) + w t^2 (P2 - P1)] / D^2,
** D = (1-t)^2 + 2 w t (1-t) + t^2 (the quotient rule; the t^3 terms
** cancel). */
void arclen_rquad_derivative(const double *p, int dim, double t,
                             double *out) {
  /* 2 (w s^2 a + t s k + w t^2 c)/D^2 as 2 (W (s^2 a + t^2 c) + t s k/D)/D
  ** with W = w/D: D^2 overflows from w ~ 1e154 (the derivative was 0), D
  ** itself never (2 w t s as 2 (w t s): 2 w does from w ~ 9e307) */
  double w = p[3 * dim], s = 1 - t, D = s * s + 2 * (w * t * s) + t * t;
  double W = w / D;
  int k;
  for (k = 0; k < dim; k++)
    out[k] = 2 * (W * (s * s * (p[dim + k] - p[k])
                       + t * t * (p[2 * dim + k] - p[dim + k]))
                  + t * s * (p[2 * dim + k] - p[k]) / D) / D;
}

/* X(t) for the 1D conic (0, x1, x2; w). */
static double coord(double x1, double x2, double w, double t) {
  double s = 1 - t;
  if (t <= 0.5) return (2 * w * t * s * x1 + t * t * x2) / (s * s + 2 * w * t * s + t * t);
  return x2 + (s * s * (-x2) + 2 * w * t * s * (x1 - x2)) / (s * s + 2 * w * t * s + t * t);
}

/* The legs a = P1 - P0, c = P2 - P1, k = P2 - P0 (one rounding each; their
** halves where a difference overflows) scaled by 2^-e into [1/2, 1) at
** most, so that no square over- or underflows; returns e (0 and zero legs
** for a point). */
static int scaled_legs(const double *p, int dim, double leg[3][3]) {
  static const int to[3] = {1, 2, 2}, from[3] = {0, 1, 0};
  double mx = 0;
  int i, k, e, half = 0;
  for (i = 0; i < 3; i++)
    for (k = 0; k < dim; k++) {
      leg[i][k] = p[to[i] * dim + k] - p[from[i] * dim + k];
      if (!isfinite(leg[i][k])) half = 1;
    }
  for (i = 0; i < 3; i++)
    for (k = 0; k < dim; k++) {
      if (half) leg[i][k] = p[to[i] * dim + k] / 2 - p[from[i] * dim + k] / 2;
      if (fabs(leg[i][k]) > mx) mx = fabs(leg[i][k]);
    }
  if (mx == 0) return 0;
  frexp(mx, &e);
  for (i = 0; i < 3; i++)
    for (k = 0; k < dim; k++) leg[i][k] = ldexp(leg[i][k], -e);
  return e + half;
}

/* The length of a conic whose points lie on a line, from its scaled legs:
** the total variation of its coordinate along the line's direction (the
** longest leg's), split where X' = 0, i.e. at the roots of w x1 + (x2 - 2
** w x1) t + (w - 1) x2 t^2 (the numerator of C' above) in (0, 1). */
static double collinear_length(double leg[3][3], int dim, double w) {
  double len[3], e[3] = {0, 0, 0}, x1, x2, re[2], im[2], ts[4], L = 0;
  int i, k, best = 0, n, m = 0;
  for (i = 0; i < 3; i++) {
    len[i] = arclen_seg_norm(leg[i], dim);
    if (len[i] > len[best]) best = i;
  }
  if (!(len[best] > 0)) return 0;           /* a point */
  for (k = 0; k < dim; k++) e[k] = leg[best][k] / len[best];
  x1 = dot(leg[0], e, dim);
  x2 = dot(leg[2], e, dim);
  ts[m++] = 0;
  n = arclen_quadratic((w - 1) * x2, x2 - 2 * w * x1, w * x1, re, im);
  for (i = 0; i < n; i++)
    if (im[i] == 0 && re[i] > 0 && re[i] < 1) ts[m++] = re[i];
  if (m == 3 && ts[2] < ts[1]) { double r = ts[1]; ts[1] = ts[2]; ts[2] = r; }
  ts[m++] = 1;
  for (i = 0; i + 1 < m; i++)
    L += fabs(coord(x1, x2, w, ts[i + 1]) - coord(x1, x2, w, ts[i]));
  return L;
}

/* A circular arc's length in closed form (conic_circle.c); 0 for any
** other conic. */
static int circular(const double q[6], double w, double *L,
                    arclen_info *info) {
  if (!arclen_rquad_circular(q, w, L)) return 0;
  if (info) {
    arclen_info_init(info);
    info->branch = "circle";
  }
  return 1;
}

/* The whole arc's length. */
static int whole_length(const double *p, int dim, double *len,
                        arclen_info *info) {
  double leg[3][3], q[6], w = p[3 * dim], L;
  int e, flat, rc;
  if (dim == 3) {
    /* the isometric image in the plane, P1 at the origin: P0 -> (-|a|, 0),
    ** P2 -> |c| (cos, sin) of the angle between a and c, so both legs keep
    ** one rounding.  The angle from a and c each scaled by its own power
    ** of two: a leg 2^-1000 of the other would make the products of a
    ** common scale subnormal, and its direction a guess */
    double a[3], c[3], as[3], cs[3], x[3], la, lc, lx, ma = 0, mc = 0;
    int k, ea = 0, ec = 0, half = 0;
    for (k = 0; k < 3; k++) {
      a[k] = p[3 + k] - p[k];
      c[k] = p[6 + k] - p[3 + k];
      if (!isfinite(a[k]) || !isfinite(c[k])) half = 1;
    }
    /* a leg's norm is up to sqrt 3 times its largest part: quarters of
    ** the points where a part nears DBL_MAX (exact but for subnormals,
    ** nothing beside such legs) */
    for (k = 0; k < 3; k++)
      if (fabs(a[k]) > 0x1p1020 || fabs(c[k]) > 0x1p1020) half = 1;
    for (k = 0; k < 3; k++) {
      if (half) { a[k] = p[3 + k] / 4 - p[k] / 4; c[k] = p[6 + k] / 4 - p[3 + k] / 4; }
      ma = fmax(ma, fabs(a[k]));
      mc = fmax(mc, fabs(c[k]));
    }
    if (ma > 0) frexp(ma, &ea);
    if (mc > 0) frexp(mc, &ec);
    for (k = 0; k < 3; k++) { as[k] = ldexp(a[k], -ea); cs[k] = ldexp(c[k], -ec); }
    x[0] = as[1] * cs[2] - as[2] * cs[1];
    x[1] = as[2] * cs[0] - as[0] * cs[2];
    x[2] = as[0] * cs[1] - as[1] * cs[0];
    la = arclen_seg_norm(as, 3);
    lc = arclen_seg_norm(cs, 3);
    lx = arclen_seg_norm(x, 3);
    /* a flat triangle: the same test as arclen_conic_degenerate's */
    flat = !(la > 0) || !(lc > 0) || !(lx / la / lc > 16 * DBL_EPSILON);
    if (!flat) {
      q[0] = -ldexp(la, ea); q[1] = 0; q[2] = 0; q[3] = 0;
      q[4] = ldexp(dot(as, cs, 3) / la, ec);
      q[5] = ldexp(lx / la, ec);
      if (circular(q, w, &L, info)) rc = ARCLEN_OK;
      else rc = arclen_conic_length(q, w, &L, info);
      /* EDOMAIN: the image is flat after all (a leg at the bottom of the
      ** double range, 5e-324 beside 100, rounds its direction away) */
      if (rc != ARCLEN_EDOMAIN) {
        if (rc == ARCLEN_OK && half) L *= 4;
        *len = rc == ARCLEN_OK ? L : NAN;
        if (rc == ARCLEN_OK && !isfinite(L)) return ARCLEN_EOVERFLOW;
        return rc;
      }
      flat = 1;
    }
  } else {
    /* a leg's norm is up to sqrt 2 times its largest part: beyond 2^1020
    ** the conic at a quarter (exact but for subnormals), or its legs'
    ** norms overflow (and the flatness test with them) */
    int k, big = 0;
    for (k = 0; k < 4; k++)
      if (!(fabs(p[k + 2] - p[k]) <= 0x1p1020)) big = 1;
    for (k = 0; k < 6; k++) q[k] = big ? p[k] / 4 : p[k];
    /* a circular arc first: its triangle is not flat (its angle at P1 is
    ** pi minus the arc's), and the flatness test cost as much again */
    if (circular(q, w, &L, info)) rc = ARCLEN_OK, flat = 0;
    else if (!(flat = arclen_conic_degenerate(q)))
      rc = arclen_conic_length(q, w, &L, info);
    if (!flat) {
      if (rc == ARCLEN_OK && big) {
        L *= 4;
        if (!isfinite(L)) rc = ARCLEN_EOVERFLOW;
      }
      *len = rc == ARCLEN_OK ? L : NAN;
      return rc;
    }
  }
  /* flat: the points on a line (the scaled legs only here: a circle's
  ** quarter spent a third of its time on them) */
  if (info) info->branch = "collinear";
  e = scaled_legs(p, dim, leg);
  L = ldexp(collinear_length(leg, dim, w), e);
  *len = L;
  return isfinite(L) ? ARCLEN_OK : ARCLEN_EOVERFLOW;
}

/* w x / W for W >= w x / 2 or so, without forming w x where w is near
** DBL_MAX. */
static double wfrac(double w, double x, double W) {
  return w > 1 ? x / (W / w) : w * x / W;
}

/* The piece [t0, t1] of the conic with legs a = P1 - P0, c = P2 - P1, k =
** P2 - P0 (one rounding each), its own legs a', c', k' formed directly,
** not as differences of its control points rounded at the whole arc's
** scale (those moved a short piece's length by up to 3 eps |P|: 6.7e-14 of
** [0.9, 0.999] of a w = 18 conic, 8e-10 of [0.5, 0.5001] at w = 1000).
** With the homogeneous blossom's weights W00, W01, W11 (of (t0, t0), (t0,
** t1), (t1, t1)) and H(t) = w (1-t)^2 a + t (1-t) k + w t^2 c (D^2 C'(t) /
** 2):
**   a' = (t1 - t0) H(t0) / (W01 W00),  c' = (t1 - t0) H(t1) / (W01 W11),
**   k' = (t1 - t0) [2w (1-t0)(1-t1) a + ((1-t1) t0 + (1-t0) t1) k
**                   + 2w t0 t1 c] / (W00 W11),
**   w' = W01 / sqrt(W00 W11).
** (N, W the homogeneous blossom's point and weight: N(t0, v) and W(t0, v)
** are affine in v, so N(t0, t1) W00 - N00 W(t0, t1) = (t1 - t0)(N_v W -
** N W_v) at (t0, t0), half the numerator of C'(t0) = 2 H(t0)/W00^2;
** likewise at t1.  k' is the chord, N(t1) W(t0) - N(t0) W(t1) over W00 W11
** summed over pairs of control points.)  H(t) is taken as w (1 - 2t) a +
** t (w t + 1 - t) k for t <= 1/2 and w (2t - 1) c + (1 - t) (w (1 - t) +
** t) k above: positive terms, none of the size w |a| where the middle's
** tangent is k/(1 + w).  Every coefficient is positive and at most 1, the
** divisions ordered so that no intermediate exceeds 2w.
** The piece is returned as three points (and w') of which two legs are
** exactly a', c' or k' and the third, the longest, one rounding of their
** sum: on a flat triangle (thin hyperbolas) the longest is k', on a tall
** one (w = 1e-6, P1 1e6 away beside a chord of 1) a' or c', and k' = a' +
** c' lost 1e-11 there. */
static void piece_legs(const double *a, const double *c, const double *k,
                       int dim, double w, double t0, double t1,
                       double *out) {
  double W00 = (1 - t0) * (1 - t0) + 2 * w * t0 * (1 - t0) + t0 * t0;
  double W11 = (1 - t1) * (1 - t1) + 2 * w * t1 * (1 - t1) + t1 * t1;
  double W01 = (1 - t0) * (1 - t1) + w * ((1 - t0) * t1 + t0 * (1 - t1)) + t0 * t1;
  double h = t1 - t0, f0, g0, f1, g1, ea, ek, ec, la = 0, lc = 0, lk = 0;
  double ap[3], cp[3], kp[3];
  const double *v0 = t0 <= 0.5 ? a : c, *v1 = t1 <= 0.5 ? a : c;
  int i;
  if (t0 <= 0.5) { f0 = w * (1 - 2 * t0); g0 = t0 * (w * t0 + (1 - t0)); }
  else { f0 = w * (2 * t0 - 1); g0 = (1 - t0) * (w * (1 - t0) + t0); }
  if (t1 <= 0.5) { f1 = w * (1 - 2 * t1); g1 = t1 * (w * t1 + (1 - t1)); }
  else { f1 = w * (2 * t1 - 1); g1 = (1 - t1) * (w * (1 - t1) + t1); }
  f0 = h * (f0 / W00) / W01; g0 = h * (g0 / W00) / W01;
  f1 = h * (f1 / W11) / W01; g1 = h * (g1 / W11) / W01;
  ea = 2 * (h * (1 - t0) / W00) * wfrac(w, 1 - t1, W11);
  ek = (h / W00) * (((1 - t1) * t0 + (1 - t0) * t1) / W11);
  ec = 2 * (h * t1 / W11) * wfrac(w, t0, W00);
  for (i = 0; i < dim; i++) {
    ap[i] = f0 * v0[i] + g0 * k[i];
    cp[i] = f1 * v1[i] + g1 * k[i];
    kp[i] = ea * a[i] + ek * k[i] + ec * c[i];
    la = fmax(la, fabs(ap[i])); lc = fmax(lc, fabs(cp[i])); lk = fmax(lk, fabs(kp[i]));
  }
  for (i = 0; i < dim; i++) {
    if (lk >= la && lk >= lc) {          /* P1' = 0: a', c' exact */
      out[i] = -ap[i]; out[dim + i] = 0; out[2 * dim + i] = cp[i];
    } else if (la >= lc) {               /* P2' = 0: c', k' exact */
      out[i] = -kp[i]; out[dim + i] = -cp[i]; out[2 * dim + i] = 0;
    } else {                             /* P0' = 0: a', k' exact */
      out[i] = 0; out[dim + i] = ap[i]; out[2 * dim + i] = kp[i];
    }
  }
  out[3 * dim] = W01 / (sqrt(W00) * sqrt(W11));
}

int arclen_rquad_length(const double *p, int dim, double t0, double t1,
                        double *len, arclen_info *info) {
  double a[3], c[3], kk[3], sub[10], lo = t0 < t1 ? t0 : t1, hi = t0 < t1 ? t1 : t0;
  int rc, k, half = 0;
  *len = 0;
  if (lo == hi) return ARCLEN_OK;
  if (lo == 0 && hi == 1) {
    rc = whole_length(p, dim, len, info);
  } else {
    /* the legs, one rounding each (halved where they overflow) */
    for (k = 0; k < dim; k++) {
      a[k] = p[dim + k] - p[k];
      c[k] = p[2 * dim + k] - p[dim + k];
      kk[k] = p[2 * dim + k] - p[k];
      if (!isfinite(a[k]) || !isfinite(c[k]) || !isfinite(kk[k])) half = 1;
    }
    for (k = 0; k < dim && !half; k++)
      if (fabs(a[k]) > 0x1p1000 || fabs(c[k]) > 0x1p1000 || fabs(kk[k]) > 0x1p1000) half = 1;
    /* legs near DBL_MAX: the piece measured at 1/16 (exact), so that its
    ** polygon's sums stay finite, then scaled back */
    if (half)
      for (k = 0; k < dim; k++) {
        a[k] = p[dim + k] / 16 - p[k] / 16;
        c[k] = p[2 * dim + k] / 16 - p[dim + k] / 16;
        kk[k] = p[2 * dim + k] / 16 - p[k] / 16;
      }
    piece_legs(a, c, kk, dim, p[3 * dim], lo, hi, sub);
    rc = whole_length(sub, dim, len, info);
    if (rc == ARCLEN_OK && half) {
      *len *= 16;
      if (!isfinite(*len)) rc = ARCLEN_EOVERFLOW;
    }
  }
  if (rc == ARCLEN_OK && t1 < t0) *len = -*len;
  return rc;
}
