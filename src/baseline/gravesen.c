/*
** gravesen.c -- Gravesen's adaptive subdivision (J. Gravesen, "Adaptive
** subdivision and the length and energy of Bezier curves", Computational
** Geometry 8 (1997) 13-31).  A Bezier curve of degree n is no shorter than
** its chord Lc and no longer than its control polygon Lp; the estimate
** E = (2 Lc + (n-1) Lp)/(n+1) -- (Lc + Lp)/2 for a cubic -- has an error
** that falls 16-fold with every de Casteljau halving (O(h^5) per piece).
**
** Pieces are kept as their three hodograph control vectors d0, d1, d2
** (d_i = P_{i+1} - P_i) at the velocity scale of the whole curve, and a
** level k: the piece's polygon is 2^-k (|d0| + |d1| + |d2|).  Halving is
** then exact in scale and free of the cancellation that absolute
** coordinates far from the origin would cause.
**
** Stopping rule for a relative tolerance rtol, per split piece with children
** sum S = E_left + E_right and own estimate E (node budget tol, below):
**   rigorous:   sum over children of (Lp - Lc)/2 <= tol, since each true
**               length lies in [Lc, Lp]; it is what ends the pieces at cusps;
**   asymptotic: on regular children (flat, Lp - Lc <= FLAT * Lp, and legs
**               within a factor SPREAD: no root of the speed near the
**               piece), one level more is taken and S2 (grandchildren)
**               accepted when |S - S2|/3 <= tol/2 (its error if it falls at
**               least 4-fold; asymptotically 16-fold) and the differences
**               are seen to fall: 4 |S - S2| <= |E - S| <= 256 |S - S2|
**               (a single |E - S| was fooled where E and S erred alike).
** The node budget is rtol/2 * max(S, Lref 2^-k), Lref = E_root/4 <= L: the
** budgets sum to at most rtol * L.  The Richardson variant extrapolates on
** three levels, R_j = S_j + (S_j - S_{j-1})/15, and takes R3 when
** |R3 - R2| is within budget and the extrapolations contract,
** 2 |R3 - R2| <= |R2 - R1| <= 256 |R3 - R2| (|R2 - R1| alone was 0.14 of
** R2's error on a piece where R1 and R2 erred alike).
*/
#include <float.h>
#include <math.h>
#include <stddef.h>

#include "arclen.h"
#include "curve/numeric.h"

#define MAX_LEVEL 60        /* pieces of width 2^-60: far below any budget */
#define MAX_SPLITS 20000000L  /* cap on subdivisions (rtol 1e-15 needs ~1e5) */
/* (Lp - Lc)/Lp of a piece trusted to be in the asymptotic regime: 0.02 let
** one of 1503 reference curves through at 2 rtol (rtol 1e-6); 0.005 none. */
#define FLAT 0.005
/* Error of S taken as |E - S|/(rho - 1) with rho = 4, not the asymptotic 16:
** measured on ~600 reference curves, 16 let pre-asymptotic pieces through
** (errors up to 2.3 rtol at rtol 1e-4), 4 keeps every error below 0.7 rtol. */
#define RHO_MINUS_1 3.0
/* Rounding level of a sum of estimates (relative): 64 eps. */
#define NOISE (64 * DBL_EPSILON)
/* Largest ratio |R2 - R1|/|R3 - R2| trusted: 32..64 when asymptotic
** (errors O(h^6), O(h^7) after one extrapolation), measured 64. */
#define MAX_RATIO 256.0
/* Largest leg ratio of a regular piece (see regular()). */
#define SPREAD 2.0

typedef struct piece {
  double d[9];              /* d0, d1, d2, stride 3 */
  int k;                    /* level: parameter width 2^-k */
  double e, lp, lc;         /* estimate, polygon and chord, times 2^-k */
  double lmin, lmax;        /* shortest and longest leg (unscaled) */
} piece;

static double norm(const double *v, int dim) {
  double s = 0.0;
  int i;
  for (i = 0; i < dim; i++) s += v[i] * v[i];
  return sqrt(s);
}

/* Fill e, lp, lc of p from its d and k. */
static void measure(piece *p, int dim) {
  double w = ldexp(1.0, -p->k), ch[3];
  double n0 = norm(p->d, dim), n1 = norm(p->d + 3, dim), n2 = norm(p->d + 6, dim);
  int i;
  for (i = 0; i < dim; i++) ch[i] = p->d[i] + p->d[3 + i] + p->d[6 + i];
  p->lmin = fmin(n0, fmin(n1, n2));
  p->lmax = fmax(n0, fmax(n1, n2));
  p->lp = w * (n0 + n1 + n2);
  p->lc = w * norm(ch, dim);
  p->e = (p->lc + p->lp) / 2.0;    /* (2 Lc + (3-1) Lp)/(3+1) */
}

/* de Casteljau halving of the hodograph's quadratic (velocity scale kept). */
static void halve(const piece *p, int dim, piece *l, piece *r) {
  int i;
  for (i = 0; i < dim; i++) {
    double d01 = (p->d[i] + p->d[3 + i]) / 2.0;
    double d12 = (p->d[3 + i] + p->d[6 + i]) / 2.0;
    double d02 = (d01 + d12) / 2.0;
    l->d[i] = p->d[i]; l->d[3 + i] = d01; l->d[6 + i] = d02;
    r->d[i] = d02; r->d[3 + i] = d12; r->d[6 + i] = p->d[6 + i];
  }
  l->k = r->k = p->k + 1;
  measure(l, dim);
  measure(r, dim);
}

/* A piece in the asymptotic regime: nearly straight, and its speed varies
** by at most SPREAD over it (legs within that factor).  Flatness alone let
** through a piece whose legs were 6e-6 and 4.3 (a turn at t ~ 1e-3, a root
** of the speed at 1e-3 of the piece's width): its error does not fall
** 16-fold on halving, and |E - S| was 5x below the true error (fuzz_length,
** 2.2 rtol; Richardson 5 rtol on such stops and collinear reversals). */
static int regular(const piece *p) {
  return p->lp - p->lc <= FLAT * p->lp && p->lmax <= SPREAD * p->lmin;
}

static int gravesen(const double *c, int dim, const arclen_opts *o,
                    int richardson, double *len, arclen_info *info) {
  piece stack[MAX_LEVEL + 2], root;
  double sub[12], quarter[12], lref, rtol = o ? o->rtol : 1e-12;
  double t0 = o ? o->t0 : 0.0, t1 = o ? o->t1 : 1.0, sign = 1.0;
  const double *q = c;
  arclen_sum total = {0.0, 0.0}, err = {0.0, 0.0};
  long splits = 0;
  double big = 0.0;
  int sp = 0, depth = 0, i, capped = 0, ex = 0, pre = 0;
  if (dim != 2 && dim != 3) { *len = NAN; return ARCLEN_EDIM; }
  if (t0 == t1) {          /* empty range: 0, as gauss (a cut-out point */
    *len = 0.0;            /* of a far curve has rounding-sized legs) */
    if (info) arclen_info_init(info);
    return ARCLEN_OK;
  }
  if (t0 > t1) { double w = t0; t0 = t1; t1 = w; sign = -1.0; }
  /* Coordinates beyond DBL_MAX/4 are quartered (exactly, 2 into ex) so
  ** that no leg overflows: legs of 1.2 DBL_MAX may bound a finite length. */
  for (i = 0; i < 4 * dim; i++)
    if (fabs(c[i]) > DBL_MAX / 4) pre = 2;
  if (pre) {
    for (i = 0; i < 4 * dim; i++) quarter[i] = c[i] * 0.25;
    q = c = quarter;
  }
  if (t0 != 0.0 || t1 != 1.0) {
    /* Cut the curve moved to P0 = 0: blossoming in absolute coordinates
    ** would cost |P0| eps of every control point (digits of a far curve). */
    double moved[12];
    for (i = 0; i < 4 * dim; i++) moved[i] = c[i] - c[i % dim];
    arclen_subcurve(moved, dim, t0, t1, sub);
    q = sub;
  }
  for (i = 0; i < 9; i++) root.d[i] = 0.0;
  for (i = 0; i < 3 * dim; i++) root.d[(i / dim) * 3 + i % dim] = q[i + dim] - q[i];
  /* Scale by a power of two (exact) so that the largest leg component is in
  ** [0.5, 1): squares neither overflow nor underflow at any coordinate size. */
  for (i = 0; i < 9; i++) big = fmax(big, fabs(root.d[i]));
  if (big > 0.0 && isfinite(big)) {
    frexp(big, &ex);
    for (i = 0; i < 9; i++) root.d[i] = ldexp(root.d[i], -ex);
  }
  root.k = 0;
  measure(&root, dim);
  lref = root.e / 4.0;
  stack[sp++] = root;
  while (sp > 0) {
    piece p = stack[--sp], l, r;
    double s, tol, rig;
    halve(&p, dim, &l, &r);
    splits++;
    if (l.k > depth) depth = l.k;
    s = l.e + r.e;
    tol = rtol / 2.0 * fmax(s, ldexp(lref, -p.k));
    rig = ((l.lp - l.lc) + (r.lp - r.lc)) / 2.0;
    if (rig <= tol) {                         /* guaranteed */
      arclen_sum_add(&total, s);
      arclen_sum_add(&err, rig);
      continue;
    }
    if (!richardson) {
      /* One level more to see the errors fall: |E - S| alone was 4.5e-10
      ** on a piece where both E and S were 7e-8 off (fuzz_length, 4.8 rtol).
      ** Tried where |S - S2| = |E - S|/16 (asymptotic) would pass. */
      if (regular(&l) && regular(&r) &&
          fabs(p.e - s) / RHO_MINUS_1 <= 16.0 * tol / 2.0) {
        piece g[4];
        double s2, d01 = fabs(p.e - s), d12;
        int ok = 1;
        halve(&l, dim, &g[0], &g[1]);
        halve(&r, dim, &g[2], &g[3]);
        for (i = 0; i < 4; i++) ok = ok && regular(&g[i]);
        splits += 2;
        if (g[0].k > depth) depth = g[0].k;
        s2 = (g[0].e + g[1].e) + (g[2].e + g[3].e);
        d12 = fabs(s - s2);
        if (ok && d12 / RHO_MINUS_1 <= tol / 2.0 && (d01 <= NOISE * s ||
            ((RHO_MINUS_1 + 1.0) * d12 <= d01 &&
             d01 <= MAX_RATIO * fmax(d12, NOISE * s)))) {
          arclen_sum_add(&total, s2);
          arclen_sum_add(&err, d12 / RHO_MINUS_1);
          continue;
        }
      }
    } else if (regular(&l) && regular(&r)) {
      /* Three levels below p: R1, R2, R3.  |R3 - R2| bounds R3's error only
      ** if the extrapolations contract; with two levels, |R2 - R1| was 0.14
      ** of R2's error on a piece where both were 3e-9 off (R3: 6e-11).
      ** A ratio d21/d32 beyond MAX_RATIO says R1 was not yet asymptotic
      ** (1.5e5 on a piece whose R3 was 1e-12 off, tol 5e-13); differences
      ** at rounding level (NOISE) say nothing either way. */
      piece g[4], h[8];
      double s2, s3, r1, r2, r3, d21, d32;
      int ok = 1;
      halve(&l, dim, &g[0], &g[1]);
      halve(&r, dim, &g[2], &g[3]);
      for (i = 0; i < 4; i++) {
        halve(&g[i], dim, &h[2 * i], &h[2 * i + 1]);
        ok = ok && regular(&g[i]) && regular(&h[2 * i]) && regular(&h[2 * i + 1]);
      }
      splits += 6;
      if (h[0].k > depth) depth = h[0].k;
      s2 = (g[0].e + g[1].e) + (g[2].e + g[3].e);
      s3 = ((h[0].e + h[1].e) + (h[2].e + h[3].e)) +
           ((h[4].e + h[5].e) + (h[6].e + h[7].e));
      r1 = s + (s - p.e) / 15.0;
      r2 = s2 + (s2 - s) / 15.0;
      r3 = s3 + (s3 - s2) / 15.0;
      d32 = fabs(r3 - r2);
      d21 = fabs(r2 - r1);
      if (ok && d32 <= tol && (d21 <= NOISE * s ||
          (2.0 * d32 <= d21 && d21 <= MAX_RATIO * fmax(d32, NOISE * s)))) {
        arclen_sum_add(&total, r3);
        arclen_sum_add(&err, fabs(r3 - r2));
        continue;
      }
    }
    if (l.k >= MAX_LEVEL || splits >= MAX_SPLITS) {   /* give up here */
      capped = 1;
      arclen_sum_add(&total, s);
      arclen_sum_add(&err, rig);
      continue;
    }
    stack[sp++] = r;
    stack[sp++] = l;
  }
  if (info) {
    info->evals = 0;
    info->pieces = splits;
    info->depth = depth;
    info->err = ldexp(err.s + err.c, ex + pre);
    info->branch = richardson ? "gravesen-richardson" : "gravesen";
    info->calls = 0;
  }
  if (capped) { *len = NAN; return ARCLEN_ENOCONV; }
  *len = sign * ldexp(total.s + total.c, ex + pre);
  return ARCLEN_OK;
}

int arclen_length_gravesen(const double *c, int dim, const arclen_opts *o,
                           double *len, arclen_info *info) {
  return gravesen(c, dim, o, 0, len, info);
}

int arclen_length_gravesen_richardson(const double *c, int dim,
                                      const arclen_opts *o, double *len,
                                      arclen_info *info) {
  return gravesen(c, dim, o, 1, len, info);
}
