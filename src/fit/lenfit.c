/*
** lenfit.c -- building length-versus-t fits of a cubic Bezier curve:
**   "paper":   Walter & Fournier (1996), one or two functional Bezier
**              spans through s at 1/3, 2/3 and 1 of each span (Eqns 4-5);
**   "hermite": piecewise cubic Hermite interpolation of s(t) with the
**              exact slope s'(t) = speed, knots at the speed's critical
**              points, optionally refined to a tolerance.
** Both store spans as functional cubic Beziers on s/s(1), so evaluation
** (lenfit_eval.c) does not care which built them.  The work is done on
** the curve translated to P0 = 0 and scaled by a power of 2 to unit size:
** s/s(1) is invariant under both, and huge or tiny coordinates keep their
** full accuracy.
*/
#include <math.h>
#include <string.h>

#include "arclen.h"

#define PAPER_N 10        /* Table 1 of the paper uses 10 points */
#define HERMITE_N 2       /* Gauss-Legendre points per Hermite piece */
#ifndef HERMITE_SPLIT
#define HERMITE_SPLIT 4   /* pieces between consecutive knots */
#endif
#define DEPTH_CAP 40      /* bisections of one piece (2^-40 in t) */
#define KNOT_MERGE 1e-12  /* critical points closer than this are one */
/* Initial pieces (at most 4 intervals * split) plus one pending sibling
** per bisection level. */
#define STACK_CAP (4 * HERMITE_SPLIT + DEPTH_CAP + 4)

void arclen_fit_opts_init(arclen_fit_opts *o) {
  o->method = ARCLEN_FIT_HERMITE;
  o->n = 0;
  o->tol = 0.0;
  o->monotone = 0;
}

double arclen_fit_speed(const arclen_fit *f, double t) {
  double sum = 0.0;
  int k;
  for (k = 0; k < f->dim; k++) {
    double v = (f->hod[k] * t + f->hod[3 + k]) * t + f->hod[6 + k];
    sum += v * v;
  }
  return sqrt(sum);
}

/* The length of cs over [a, b] by the n-point rule (x, w) on [0, 1]. */
static double gl_length(arclen_fit *f, double a, double b, const double *x,
                        const double *w, int n) {
  double h = b - a, sum = 0.0;
  int i;
  for (i = 0; i < n; i++) sum += w[i] * arclen_fit_speed(f, a + h * x[i]);
  f->evals += n;
  return h * sum;
}

/* Translate to P0 = 0 and scale by powers of 2 (exact) so that the
** largest coordinate difference lies in [0.5, 1). */
static int prepare(const double *c, int dim, arclen_fit *f) {
  double big = 0.0, a2[3] = {0, 0, 0}, a1[3] = {0, 0, 0}, a0[3] = {0, 0, 0};
  int i, k, e1 = 0, e2 = 0, np = 4 * dim;
  for (i = 0; i < np; i++) {
    if (!isfinite(c[i])) return ARCLEN_EINVAL;
    f->c[i] = c[i];
    if (fabs(c[i]) > big) big = fabs(c[i]);
  }
  if (big > 0.0) frexp(big, &e1);
  /* First bring everything to [-1, 1] so the differences cannot overflow. */
  for (i = 0; i < np; i++)
    f->cs[i] = ldexp(c[i], -e1) - ldexp(c[i % dim], -e1);
  big = 0.0;
  for (i = 0; i < np; i++)
    if (fabs(f->cs[i]) > big) big = fabs(f->cs[i]);
  if (big > 0.0) frexp(big, &e2);
  for (i = 0; i < np; i++) f->cs[i] = ldexp(f->cs[i], -e2);
  f->scale_exp = big > 0.0 ? e1 + e2 : 0;
  arclen_hodograph(f->cs, dim, a2, a1, a0);
  for (k = 0; k < 3; k++) {
    f->hod[k] = k < dim ? a2[k] : 0.0;
    f->hod[3 + k] = k < dim ? a1[k] : 0.0;
    f->hod[6 + k] = k < dim ? a0[k] : 0.0;
  }
  f->ncrit = arclen_critical_points(f->cs, dim, f->crit);
  return ARCLEN_OK;
}

/* A zero-length curve: s/s(1) is undefined; use s/s(1) = t, total 0. */
static void degenerate(arclen_fit *f) {
  arclen_fit_span *sp = &f->span[0];
  sp->t0 = 0.0;
  sp->t1 = 1.0;
  sp->y[0] = 0.0;
  sp->y[1] = 1.0 / 3.0;
  sp->y[2] = 2.0 / 3.0;
  sp->y[3] = 1.0;
  f->nspans = 1;
  f->total = 0.0;
}

/* ---- method "paper" ------------------------------------------------ */

/* Lengths from a to a + h/3, a + 2h/3 and b: one n-point rule each. */
static void paper_lengths(arclen_fit *f, double a, double b, const double *x,
                          const double *w, int n, double len[3]) {
  double h = b - a;
  len[0] = gl_length(f, a, a + h / 3.0, x, w, n);
  len[1] = gl_length(f, a, a + 2.0 * h / 3.0, x, w, n);
  len[2] = gl_length(f, a, b, x, w, n);
}

/* Span ordinates from y0, ya = y(a+h/3), yb = y(a+2h/3), y3: Eqns 4-5
** with y0, y3 free (the interpolation conditions at 1/3 and 2/3). */
static void paper_span(arclen_fit_span *sp, double a, double b, double y0,
                       double ya, double yb, double y3) {
  sp->t0 = a;
  sp->t1 = b;
  sp->y[0] = y0;
  sp->y[1] = (-5.0 * y0 + 18.0 * ya - 9.0 * yb + 2.0 * y3) / 6.0;
  sp->y[2] = (2.0 * y0 - 9.0 * ya + 18.0 * yb - 5.0 * y3) / 6.0;
  sp->y[3] = y3;
}

/* Squared distance from (p0, p2) to the monotone-boundary point at angle
** phi: with d0 = a^2, d2 = b^2 the boundary d0 + d2 - sqrt(d0 d2) = D is
** the ellipse a^2 - ab + b^2 = D; a = r cos(phi), b = r sin(phi). */
static double boundary_point(double D, double phi, double p0, double p2,
                             double *d0, double *d2) {
  double c = cos(phi), s = sin(phi), r2 = D / (1.0 - c * s);
  *d0 = r2 * c * c;
  *d2 = r2 * s * s;
  return (*d0 - p0) * (*d0 - p0) + (*d2 - p2) * (*d2 - p2);
}

#define PROJECT_SAMPLES 64   /* coarse scan of the boundary, then refine */
#define PROJECT_REFINE 60    /* golden-section steps (0.618^60 ~ 3e-13) */

/* The least-squares projection of a span's inner ordinates onto the set of
** non-decreasing functional cubics with the same ends: d0 = V1 - y0 >= 0,
** d2 = y3 - V2 >= 0, d1 = D - d0 - d2 >= -sqrt(d0 d2) (a Bernstein
** quadratic's non-negativity), a convex set in (d0, d2).  Clamping V1, V2
** instead costs much more accuracy (doc/papers.md, "Walter & Fournier"). */
static void project_monotone(arclen_fit_span *sp) {
  const double golden = 0.6180339887498949;   /* (sqrt(5) - 1) / 2 */
  const double half_pi = 1.5707963267948966;
  double D = sp->y[3] - sp->y[0], p0 = sp->y[1] - sp->y[0];
  double p2 = sp->y[3] - sp->y[2], best, b0, b2, d0, d2, lo, hi, dist;
  int i, ibest = 0;
  if (arclen_fit_span_monotone(sp)) return;
  if (!(D > 0.0)) { sp->y[1] = sp->y[0]; sp->y[2] = sp->y[3]; return; }
  /* The two axis edges: d0 = 0 or d2 = 0, the other in [0, D]. */
  b0 = 0.0;
  b2 = p2 < 0.0 ? 0.0 : (p2 > D ? D : p2);
  best = p0 * p0 + (b2 - p2) * (b2 - p2);
  d0 = p0 < 0.0 ? 0.0 : (p0 > D ? D : p0);
  dist = (d0 - p0) * (d0 - p0) + p2 * p2;
  if (dist < best) { best = dist; b0 = d0; b2 = 0.0; }
  /* The curved edge: scan, then golden-section search around the best. */
  for (i = 0; i <= PROJECT_SAMPLES; i++) {
    double di = boundary_point(D, half_pi * i / PROJECT_SAMPLES, p0, p2, &d0,
                               &d2);
    if (i == 0 || di < dist) { dist = di; ibest = i; }
  }
  lo = half_pi * (ibest > 0 ? ibest - 1 : 0) / PROJECT_SAMPLES;
  hi = half_pi * (ibest < PROJECT_SAMPLES ? ibest + 1 : PROJECT_SAMPLES) /
       PROJECT_SAMPLES;
  for (i = 0; i < PROJECT_REFINE; i++) {
    double m1 = hi - golden * (hi - lo), m2 = lo + golden * (hi - lo);
    if (boundary_point(D, m1, p0, p2, &d0, &d2) <
        boundary_point(D, m2, p0, p2, &d0, &d2))
      hi = m2;
    else
      lo = m1;
  }
  dist = boundary_point(D, 0.5 * (lo + hi), p0, p2, &d0, &d2);
  if (dist < best) { b0 = d0; b2 = d2; }
  /* Just inside, so rounding cannot put it back outside. */
  sp->y[1] = sp->y[0] + b0 * (1.0 - 1e-12);
  sp->y[2] = sp->y[3] - b2 * (1.0 - 1e-12);
}

static int build_paper(arclen_fit *f, int cap) {
  double x[ARCLEN_GL_MAXN], w[ARCLEN_GL_MAXN], l1[3], l2[3], tmid, s1;
  int n = f->n;
  if (arclen_gauss_legendre(n, x, w) != ARCLEN_OK) return ARCLEN_EDOMAIN;
  if (f->ncrit <= 1) {                 /* one span (Sec. 3.4 step 2) */
    paper_lengths(f, 0.0, 1.0, x, w, n, l1);
    if (!(l1[2] > 0.0)) { degenerate(f); return ARCLEN_OK; }
    paper_span(&f->span[0], 0.0, 1.0, 0.0, l1[0] / l1[2], l1[1] / l1[2],
               1.0);
    f->nspans = 1;
    f->total = l1[2];
    return ARCLEN_OK;
  }
  if (cap < 2) return ARCLEN_ENOCONV;
  /* Two spans, met at the mean of two roots or at the middle of three
  ** (Sec. 3.4 step 3). */
  tmid = f->ncrit == 2 ? 0.5 * (f->crit[0] + f->crit[1]) : f->crit[1];
  paper_lengths(f, 0.0, tmid, x, w, n, l1);
  paper_lengths(f, tmid, 1.0, x, w, n, l2);
  s1 = l1[2] + l2[2];
  if (!(s1 > 0.0)) { degenerate(f); return ARCLEN_OK; }
  paper_span(&f->span[0], 0.0, tmid, 0.0, l1[0] / s1, l1[1] / s1,
             l1[2] / s1);
  paper_span(&f->span[1], tmid, 1.0, l1[2] / s1, (l1[2] + l2[0]) / s1,
             (l1[2] + l2[1]) / s1, 1.0);
  f->nspans = 2;
  f->total = s1;
  return ARCLEN_OK;
}

static int build_paper_monotone(arclen_fit *f, int cap) {
  int i, status = build_paper(f, cap);
  for (i = 0; status == ARCLEN_OK && i < f->nspans; i++)
    project_monotone(&f->span[i]);
  return status;
}

/* ---- method "hermite" ---------------------------------------------- */

typedef struct piece {
  double a, b;     /* parameter range */
  double va, vb;   /* exact speeds at a and b: the Hermite slopes */
  double len;      /* length over [a, b] */
  int depth;
} piece;

/* The cubic Hermite interpolant of a piece is non-decreasing iff its
** Bezier ordinate differences d0 = va h/3, d1, d2 = vb h/3 (summing to
** len) satisfy d1 >= -sqrt(d0 d2), i.e. (va + vb - sqrt(va vb)) h <=
** 3 len.  Returns the factor (<= 1) to scale both slopes by to get there
** (Fritsch & Carlson's idea with the exact region, kept just inside). */
static double monotone_scale(const piece *p) {
  double h = p->b - p->a;
  double need = (p->va + p->vb - sqrt(p->va * p->vb)) * h;
  if (need <= 3.0 * p->len) return 1.0;
  return 3.0 * p->len / need * (1.0 - 1e-9);
}

/* Is the piece's Hermite interpolant good to abstol?  Bisects it into
** left and right (with their data) to find out. */
static int piece_ok(arclen_fit *f, const piece *p, double abstol,
                    const double *x, const double *w, int n, piece *left,
                    piece *right) {
  double a = p->a, b = p->b, h = b - a, m = 0.5 * (a + b);
  double vm = arclen_fit_speed(f, m), hm, dm, err;
  f->evals++;
  *left = *p;
  *right = *p;
  left->b = right->a = m;
  left->vb = right->va = vm;
  left->len = gl_length(f, a, m, x, w, n);
  right->len = gl_length(f, m, b, x, w, n);
  left->depth = right->depth = p->depth + 1;
  /* Hermite value and slope at the midpoint against the truth; the slope
  ** error is weighed by h/6, about the value error it implies nearby. */
  hm = 0.5 * p->len + (p->va - p->vb) * h / 8.0;
  dm = 1.5 * p->len / h - 0.25 * (p->va + p->vb);
  err = fabs(hm - left->len) + fabs(dm - vm) * h / 6.0;
  /* Half the budget to the interpolant, half (spread over [0,1] in
  ** proportion to h) to the quadrature, whose errors add up along t. */
  return err <= 0.5 * abstol &&
         fabs(left->len + right->len - p->len) <= 0.5 * abstol * h &&
         monotone_scale(p) == 1.0;
}

/* Accepted pieces are staged in the span array as raw spans (t0, t1,
** y = {va, vb, len, unused}); convert them in place into normalised
** Bezier ordinates, scaling the slopes where monotonicity needs it. */
static void stage(arclen_fit_span *sp, const piece *p) {
  sp->t0 = p->a;
  sp->t1 = p->b;
  sp->y[0] = p->va;
  sp->y[1] = p->vb;
  sp->y[2] = p->len;
  sp->y[3] = 0.0;
}

static void hermite_spans(arclen_fit *f, int np) {
  double total = 0.0, s = 0.0;
  int i;
  for (i = 0; i < np; i++) total += f->span[i].y[2];
  if (!(total > 0.0)) { degenerate(f); return; }
  for (i = 0; i < np; i++) {
    arclen_fit_span *sp = &f->span[i];
    piece p;
    double h, k;
    p.a = sp->t0;
    p.b = sp->t1;
    p.va = sp->y[0];
    p.vb = sp->y[1];
    p.len = sp->y[2];
    h = p.b - p.a;
    k = monotone_scale(&p);
    sp->y[0] = s / total;
    s += p.len;
    sp->y[3] = i == np - 1 ? 1.0 : s / total;
    sp->y[1] = sp->y[0] + k * p.va * h / (3.0 * total);
    sp->y[2] = sp->y[3] - k * p.vb * h / (3.0 * total);
  }
  f->nspans = np;
  f->total = total;
}

static int build_hermite(arclen_fit *f, int cap) {
  double x[ARCLEN_GL_MAXN], w[ARCLEN_GL_MAXN], knot[5], total = 0.0;
  double speed[5];
  piece stack[STACK_CAP];
  int n = f->n, nk = 0, i, j, top = 0, np = 0, status = ARCLEN_OK;
  if (arclen_gauss_legendre(n, x, w) != ARCLEN_OK) return ARCLEN_EDOMAIN;
  /* Knots: 0, the speed's critical points, 1. */
  knot[nk++] = 0.0;
  for (i = 0; i < f->ncrit; i++)
    if (f->crit[i] - knot[nk - 1] > KNOT_MERGE && 1.0 - f->crit[i] > KNOT_MERGE)
      knot[nk++] = f->crit[i];
  knot[nk++] = 1.0;
  for (i = 0; i < nk; i++) speed[i] = arclen_fit_speed(f, knot[i]);
  f->evals += nk;
  /* Initial pieces, pushed right to left so they pop left to right. */
  for (i = nk - 2; i >= 0; i--) {
    double a = knot[i], h = (knot[i + 1] - a) / HERMITE_SPLIT, vb = speed[i + 1];
    for (j = HERMITE_SPLIT - 1; j >= 0; j--) {
      piece *p = &stack[top++];
      p->a = a + j * h;
      p->b = j == HERMITE_SPLIT - 1 ? knot[i + 1] : a + (j + 1) * h;
      p->vb = vb;
      p->va = j == 0 ? speed[i] : arclen_fit_speed(f, p->a);
      if (j > 0) f->evals++;
      p->len = gl_length(f, p->a, p->b, x, w, n);
      p->depth = 0;
      total += p->len;
      vb = p->va;
    }
  }
  /* Depth-first refinement; accepted pieces are emitted in t order. */
  while (top > 0) {
    piece p = stack[--top], left, right;
    if (f->tol > 0.0 && total > 0.0) {
      if (!piece_ok(f, &p, f->tol * total, x, w, n, &left, &right)) {
        if (p.depth < DEPTH_CAP && top + 2 <= STACK_CAP) {
          stack[top++] = right;
          stack[top++] = left;
          continue;
        }
        status = ARCLEN_ENOCONV;
      }
      p.len = left.len + right.len;   /* the better length */
    }
    if (np == cap) return ARCLEN_ENOCONV;
    stage(&f->span[np++], &p);
  }
  hermite_spans(f, np);
  return status;
}

int arclen_fit_build(const double *c, int dim, const arclen_fit_opts *o,
                     arclen_fit *f, arclen_fit_span *spans, int cap) {
  int status;
  memset(f, 0, sizeof *f);
  f->span = spans;
  if (dim != 2 && dim != 3) return ARCLEN_EDIM;
  if (cap < 1) return ARCLEN_EDOMAIN;
  f->dim = dim;
  f->method = o->method;
  if (o->method != ARCLEN_FIT_HERMITE && o->method != ARCLEN_FIT_PAPER)
    return ARCLEN_EDOMAIN;
  f->n = o->n != 0 ? o->n : (o->method == ARCLEN_FIT_PAPER ? PAPER_N : HERMITE_N);
  if (f->n < 1 || f->n > ARCLEN_GL_MAXN) return ARCLEN_EDOMAIN;
  if (o->method == ARCLEN_FIT_HERMITE && o->tol != 0.0) {
    if (!(o->tol >= ARCLEN_FIT_TOL_MIN && o->tol <= ARCLEN_RTOL_MAX))
      return ARCLEN_ETOL;
    f->tol = o->tol;
  }
  status = prepare(c, dim, f);
  if (status != ARCLEN_OK) return status;
  if (o->method == ARCLEN_FIT_HERMITE) status = build_hermite(f, cap);
  else if (o->monotone) status = build_paper_monotone(f, cap);
  else status = build_paper(f, cap);
  f->itotal = f->total;
  if (f->nspans > 0) f->total = ldexp(f->total, f->scale_exp);
  return status;
}
