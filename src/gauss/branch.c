/*
** branch.c -- where the speed |z'(t)| stops being analytic.
**
** The speed is sqrt(Q(t)), Q = |z'|^2 a real polynomial of degree <= 4 that
** is >= 0 on the real line.  Its analytic continuation has branch points at
** the simple complex zeros of Q; they set the Bernstein ellipse in which
** Gauss-Legendre converges, so the quadrature reads its error bound off them.
*/
#include <math.h>

#include "arclen.h"
#include "curve/cplx.h"
#include "curve/cubic.h"
#include "roots/roots3d.h"

/* A computed imaginary part below this relative size is rounding noise:
** the root is real (a cusp).  In 2D the roots come from a quadratic formula
** accurate to ~1e-16; in 3D a double root of the quartic is only found to
** ~1e-8 (sqrt of eps), and treating a root with im < 1e-9 as real changes
** the integral by O(im^2) = 1e-18 relative. */
#define REAL_ROOT_RTOL2 1e-14
#define REAL_ROOT_RTOL3 1e-9

#define TWO_PI 6.283185307179586476925286766559

/* Store z and its conjugate (a real root: twice).  Inline: the 2D path
** runs on every default-method call. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void add_pair(arclen_branch *b, arclen_cx z, double rtol) {
  double re = z.re, im = fabs(z.im);
  /* x - x is 0 for finite x, NaN for inf and NaN: one test for both */
  if (b->n > 2 || !((re - re) + (im - im) == 0)) return;
  if (im <= rtol * (1 + fabs(re))) im = 0;
  b->re[b->n] = b->re[b->n + 1] = re;
  b->im[b->n] = b->im[b->n + 1] = im;
  b->n += 2;
}

static arclen_cx cdiv(arclen_cx p, arclen_cx q) {
  /* p / q by the textbook formula: the operands are scaled (hodo_scaled),
  ** so |q|^2 cannot overflow, and Smith's division (cplx.h) is slower. */
  double d = q.re * q.re + q.im * q.im;
  return arclen_cx_make((p.re * q.re + p.im * q.im) / d,
                        (p.im * q.re - p.re * q.im) / d);
}

/* 2D: z' = A2 t^2 + A1 t + A0 as a complex quadratic with roots s1, s2, so
** Q = |A2|^2 |t - s1|^2 |t - s2|^2 exactly and the branch points are s_k and
** their conjugates.  The root formula avoids cancellation: d is the square
** root of the discriminant D = A1^2 - 4 A2 A0 on the side of A1 (principal
** root in Kahan's formulation), q = -(A1 + d)/2, roots q/A2 and A0/q (see
** doc/papers.md, "Henkel").  In real arithmetic: this runs on every
** default-method call. */
static void branch2(const arclen_hodo *h, arclen_branch *b) {
  double x2 = h->a2[0], y2 = h->a2[1], x1 = h->a1[0], y1 = h->a1[1];
  double x0 = h->a0[0], y0 = h->a0[1];
  double n2 = x2 * x2 + y2 * y2, n1 = x1 * x1 + y1 * y1;
  if (n2 > 0) {
    double dr = (x1 * x1 - y1 * y1) - 4 * (x2 * x0 - y2 * y0);
    double di = 2 * x1 * y1 - 4 * (x2 * y0 + y2 * x0);
    double r = sqrt(dr * dr + di * di), w = (r + fabs(dr)) / 2, s = sqrt(w);
    double inv2 = 1 / n2, qr, qi, sr, si, qq, nq;
    b->lead2 = n2;
    if (s > 0) {                         /* d = sqrt(D), on the side of A1 */
      /* the other part di/(2s) = di s/(2w): 1/(2w) is taken beside s */
      double o = w > 0x1p-1000 ? di * s * (0.5 / w) : di / (2 * s);
      double ur = dr >= 0 ? s : fabs(o);
      double ui = dr >= 0 ? o : copysign(s, di);
      if (x1 * ur + y1 * ui < 0) { ur = -ur; ui = -ui; }
      qr = -(x1 + ur) / 2;
      qi = -(y1 + ui) / 2;
    } else {
      qr = -x1 / 2;
      qi = -y1 / 2;
    }
    if (qr == 0 && qi == 0) {            /* A1 = A0 = 0: double root at 0 */
      add_pair(b, arclen_cx_make(0, 0), REAL_ROOT_RTOL2);
      add_pair(b, arclen_cx_make(0, 0), REAL_ROOT_RTOL2);
      return;
    }
    qq = qr * qr + qi * qi;
    if (qq * 0x1p-700 > n2) {
      /* s1 = q / A2 is beyond 2^350 (1/|A2|^2 may overflow, |A2|^2 may be
      ** subnormal): on any piece |A2| |t - s1| = |A2 t - q| is |q| to
      ** within 2^-340, so Q = |q|^2 |t - s2|^2 with s1 dropped, and the
      ** lead is |q|^2, rounded up, not |A2|^2 (which would leave M short
      ** by |s1|^2: a false certificate for the inverse) */
      b->lead2 = qq * (1 + 0x1p-50);
    } else {
      /* q / A2 = q conj(A2) / |A2|^2 and A0 / q = A0 conj(q) / |q|^2 */
      sr = (qr * x2 + qi * y2) * inv2;
      si = (qi * x2 - qr * y2) * inv2;
      add_pair(b, arclen_cx_make(sr, si), REAL_ROOT_RTOL2);
    }
    nq = 1 / qq;
    sr = (x0 * qr + y0 * qi) * nq;
    si = (y0 * qr - x0 * qi) * nq;
    add_pair(b, arclen_cx_make(sr, si), REAL_ROOT_RTOL2);
  } else if (n1 > 0) {
    b->lead2 = n1;
    add_pair(b, arclen_cx_neg(cdiv(arclen_cx_make(h->a0[0], h->a0[1]),
                                   arclen_cx_make(h->a1[0], h->a1[1]))),
             REAL_ROOT_RTOL2);
  } else {
    b->lead2 = x0 * x0 + y0 * y0;
  }
}

/* 3D: Q = |a2|^2 t^4 + 2 a2.a1 t^3 + (|a1|^2 + 2 a2.a0) t^2 + 2 a1.a0 t + |a0|^2
** has no complex factorisation; its roots come from the quartic solver
** (roots.c: scaled, split on the Newton polygon, polished -- components of
** very different sizes put the roots in groups far apart).  They are
** matched into conjugate pairs by closeness of (re, |im|): each root is
** paired with the nearest unused root's conjugate. */
/* A root of Q near the real axis is a near-double root: from Q's
** coefficients its position is only good to ~sqrt(eps).  Read it off the
** hodograph instead: Newton on Q'/2 = h.h' finds the speed's minimum t*,
** and there Q(t) ~ Q(t*) + |h'|^2 (t - t*)^2, so the branch points sit at
** t* +- i |h(t*)| / |h'(t*)| (to first order, exact enough to tell a cusp
** from a near-cusp of 1e-9). */
static arclen_cx near_cusp(const arclen_hodo *h, arclen_cx z) {
  double t = z.re, hv[3], d1[3], d2[3], g, dg, half_width, dd;
  int it, k;
  if (!(fabs(z.im) < 1e-3 * (1 + fabs(t))) || !(fabs(t) < 1e6)) return z;
  for (it = 0; it < 20; it++) {
    g = dg = 0;
    for (k = 0; k < 3; k++) {
      hv[k] = (h->a2[k] * t + h->a1[k]) * t + h->a0[k];
      d1[k] = 2 * h->a2[k] * t + h->a1[k];
      d2[k] = 2 * h->a2[k];
      g += hv[k] * d1[k];
      dg += d1[k] * d1[k] + hv[k] * d2[k];
    }
    if (!(dg > 0)) return z;
    t -= g / dg;
    if (fabs(g / dg) <= 1e-16 * (1 + fabs(t))) break;
  }
  half_width = dd = 0;
  for (k = 0; k < 3; k++) {
    hv[k] = (h->a2[k] * t + h->a1[k]) * t + h->a0[k];
    d1[k] = 2 * h->a2[k] * t + h->a1[k];
    half_width += hv[k] * hv[k];
    dd += d1[k] * d1[k];
  }
  if (!(dd > 0) || !(fabs(t - z.re) < 1e-3 * (1 + fabs(t)))) return z;
  return arclen_cx_make(t, sqrt(half_width / dd));
}

/* Representatives of two roots of Q this close (relative) are a cluster:
** as in roots/roots3d.c (CLOSE_REL), where the roots are then recomputed. */
#define CLUSTER_REL 0.05

/* Not inlined: its frame and saved registers would be set up on the 2D
** path too. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static void branch3(const arclen_hodo *h, arclen_branch *b) {
  double q[5] = {0, 0, 0, 0, 0}, re[4], im[4];
  arclen_cx z[4], rep[4];
  int used[4] = {0, 0, 0, 0};
  int k, j, n, nr = 0, deg = 4;
  for (k = 0; k < 3; k++) {
    q[4] += h->a2[k] * h->a2[k];
    q[3] += 2 * h->a2[k] * h->a1[k];
    q[2] += h->a1[k] * h->a1[k] + 2 * h->a2[k] * h->a0[k];
    q[1] += 2 * h->a1[k] * h->a0[k];
    q[0] += h->a0[k] * h->a0[k];
  }
  /* Q's leading coefficient is |a2|^2, or |a1|^2 when a2 = 0: a sum of
  ** squares.  When |a2|^2 underflows (a2 below ~1e-154 of the largest
  ** coefficient), 2 a2.a1 is of the size of rounding beside |a1|^2 and may
  ** be negative: dropped with it, or the lead would be the root of a
  ** negative number (a NaN bound: 10^5 cuts on a near-line). */
  if (q[4] == 0) {
    q[3] = 0;
    if (!(q[2] > 0)) q[2] = q[1] = 0;
  }
  deg = q[4] > 0 ? 4 : q[2] > 0 ? 2 : 0;
  b->lead2 = q[deg];
  if (deg == 0) return;
  /* Q's coefficients are rounded sums: the refined roots of those digits
  ** buy the bound nothing, so the solver's plain form (roots3d.h) */
  n = arclen_quartic_plain(q[4], q[3], q[2], q[1], q[0], re, im);
  for (k = 0; k < n; k++) z[k] = arclen_cx_make(re[k], im[k]);
  for (k = 0; k < n; k++) {
    int best = -1;
    double bestd = HUGE_VAL;
    if (used[k]) continue;
    used[k] = 1;
    for (j = 0; j < n; j++) {
      double dist;
      if (used[j]) continue;
      dist = arclen_cx_abs(arclen_cx_sub(z[j], arclen_cx_conj(z[k])));
      if (dist < bestd) { bestd = dist; best = j; }
    }
    if (best >= 0) used[best] = 1;
    /* the pair's mean: (z + conj(partner)) / 2, in the upper half plane */
    rep[nr] = z[k];
    if (best >= 0)
      rep[nr] = arclen_cx_div_re(
          arclen_cx_add(z[k], arclen_cx_conj(z[best])), 2);
    rep[nr].im = fabs(rep[nr].im);
    nr++;
  }
  if (deg == 4 && nr == 2 &&
      arclen_cx_abs(arclen_cx_sub(rep[0], rep[1])) <=
          CLUSTER_REL * fmax(1, arclen_cx_abs(rep[0])) &&
      arclen_roots3d(h->a2, h->a1, h->a0, re, im) == ARCLEN_OK) {
    /* close roots (a stop: a quadruple root, found to eps^(1/4) from Q's
    ** coefficients; a near double pair): the elliptic method's, set in a
    ** frame about their cluster (roots/roots3d.c) */
    add_pair(b, arclen_cx_make(re[0], im[0]), REAL_ROOT_RTOL3);
    add_pair(b, arclen_cx_make(re[1], im[1]), REAL_ROOT_RTOL3);
    return;
  }
  for (k = 0; k < nr; k++) add_pair(b, near_cusp(h, rep[k]), REAL_ROOT_RTOL3);
}

void arclen_branch_points(const arclen_hodo *h, arclen_branch *b) {
  b->n = 0;                 /* re[k], im[k] are read for k < n only */
  b->lead2 = 0;
  if (h->zero) return;
  if (h->dim == 2) branch2(h, b);
  else branch3(h, b);
}
