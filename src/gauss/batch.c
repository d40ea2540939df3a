/*
** batch.c -- the length of many cubics in one call: a loop over a flat
** array of control points with one method and one set of options, so that
** callers with large sets (fonts, plots, the Lua binding's
** arclen.lengths) pay the method lookup and option checks once.
*/
#include <math.h>
#include <stddef.h>

#include "arclen.h"

int arclen_lengths(const double *c, long n, int dim, const arclen_method *m,
                   const arclen_opts *o, double *out, long *failed) {
  long i;
  int stride = 4 * dim;
  /* the default method checks its own arguments (after its fast path):
  ** a second check a curve is a tenth of its cost */
  int checks_itself = m->length == arclen_length_gauss;
  if (failed) *failed = -1;
  if (dim != 2 && dim != 3) return ARCLEN_EDIM;
  if (n < 0) return ARCLEN_EDOMAIN;
  for (i = 0; i < n; i++) {
    const double *ci = c + i * stride;
    int rc = checks_itself ? ARCLEN_OK : arclen_check_curve(ci, dim);
    if (rc == ARCLEN_OK) rc = m->length(ci, dim, o, &out[i], NULL);
    if (rc != ARCLEN_OK) {
      long k;
      if (failed) *failed = i;
      /* the rest are NaN: a caller that ignores the code sees no length */
      for (k = i; k < n; k++) out[k] = NAN;
      return rc;
    }
  }
  return ARCLEN_OK;
}
