/*
** line.c -- the straight segment P0 P1, t uniform: length |P1 - P0| (t1 -
** t0) without overflow, point, derivative, sub-range.
*/
#include <math.h>

#include "arclen.h"
#include "segment/segment.h"

double arclen_seg_norm(const double *v, int dim) {
  /* hypot scales, so no square overflows or underflows; in 3D two hypots
  ** (each within an ulp) rather than a sum of squares */
  return dim == 2 ? hypot(v[0], v[1]) : hypot(hypot(v[0], v[1]), v[2]);
}

/* P1 - P0 into d; 1 when that overflowed and d holds half of it. */
static int difference(const double *p, int dim, double *d) {
  int k, half = 0;
  for (k = 0; k < dim; k++) {
    d[k] = p[dim + k] - p[k];
    if (!isfinite(d[k])) half = 1;
  }
  if (half)                  /* points beyond +-DBL_MAX/2 on both sides */
    for (k = 0; k < dim; k++) d[k] = p[dim + k] / 2 - p[k] / 2;
  return half;
}

int arclen_line_length(const double *p, int dim, double t0, double t1,
                       double *len) {
  double d[3], L;
  int k, half = difference(p, dim, d);
  /* half of P1 - P0 may still have a norm beyond DBL_MAX (1.2e308 apart
  ** in x and y): a quarter has not, and the product by (t1 - t0) may be a
  ** double again */
  for (k = 0; half && k < dim; k++) d[k] /= 2;
  L = (t1 - t0) * arclen_seg_norm(d, dim);
  if (half) L *= 4;
  *len = L;
  return isfinite(L) ? ARCLEN_OK : ARCLEN_EOVERFLOW;
}

void arclen_line_point(const double *p, int dim, double t, double *out) {
  double d[3];
  int k, half = difference(p, dim, d);
  for (k = 0; k < dim; k++) {
    if (half) out[k] = (1 - t) * p[k] + t * p[dim + k];
    /* from the nearer end, so that t = 0 and t = 1 give P0 and P1 exactly */
    else out[k] = t <= 0.5 ? p[k] + t * d[k] : p[dim + k] - (1 - t) * d[k];
  }
}

void arclen_line_derivative(const double *p, int dim, double *out) {
  int k;
  for (k = 0; k < dim; k++) out[k] = p[dim + k] - p[k];
}

void arclen_line_sub(const double *p, int dim, double t0, double t1,
                     double *out) {
  arclen_line_point(p, dim, t0, out);
  arclen_line_point(p, dim, t1, out + dim);
}
